//! The scene-defined models compiled to machine code when the scene is read, against the
//! interpreter of the same proved program: every output bit for bit on random states, for the
//! Mariner's 39-term table and REMUS's six degrees of freedom; and a ship re-parameterised
//! without deriving, proving or compiling again, against the ship built from its values.

use eom::Model;
use eom::kinds::ship::{ShipModel, ShipScene};
use eom::kinds::vehicle::VehicleModel;
use eom::scene::AnyScene;
use eom_test_support::random::Random;
use std::path::Path;

/// Whether a program with an angle is compiled: not with the feature `platform-trig`, whose
/// platform sine and cosine the compiled code does not reproduce (REMUS, in quaternions, has
/// no angle and is compiled either way).
const ANGLES_COMPILE: bool = eom_kernel::recipe::IS_THE_KERNEL;

/// States drawn for each model's right-hand side.
const STATES: usize = 100_000;
/// States drawn for the Jacobians and the kinetic energy, which cost more to interpret.
const JACOBIAN_STATES: usize = 10_000;

/// The model of the ship scene `file` of `scenes/`.
fn ship(file: &str) -> ShipModel {
    let path = format!("{}/scenes/{file}", env!("CARGO_MANIFEST_DIR"));
    ShipModel::new(&ShipScene::load(Path::new(&path)).unwrap().table).unwrap()
}

fn mariner() -> ShipModel {
    ship("mariner.toml")
}

fn remus() -> VehicleModel {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/remus100.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let scene = AnyScene::parse(&text, "remus100.toml", Path::new(".")).ok();
    match scene.and_then(AnyScene::downcast::<eom::kinds::vehicle::VehicleScene>) {
        Some(scene) => scene.model,
        None => panic!("remus100.toml is read as a vehicle"),
    }
}

/// Uniform in [−bound, bound).
fn within(random: &mut Random, bound: f64) -> f64 {
    bound * (2.0 * random.unit() - 1.0)
}

/// A Mariner state far around its manoeuvres: u of either sign (a ship going astern), every
/// heading within ±20 rad (the kernel's reduction), the rudder beyond its stops; and δ̇.
fn ship_state(random: &mut Random) -> ([f64; 7], [f64; 3]) {
    let state = [
        within(random, 12.0),
        within(random, 4.0),
        within(random, 0.1),
        within(random, 5000.0),
        within(random, 5000.0),
        within(random, 20.0),
        within(random, 0.8),
    ];
    // δ̇, the propeller rate n of either sign (ahead and astern), rev/s, and a gust, m/s.
    let input = [
        within(random, 0.1),
        within(random, 2.0),
        within(random, 3.0),
    ];
    (state, input)
}

/// A REMUS state: velocities and rates of either sign (the |x| inputs), any position, a
/// quaternion not of unit length, the fins beyond their stops; and the fins' rates.
fn vehicle_state(random: &mut Random) -> ([f64; 15], [f64; 2]) {
    let mut state = [0.0; 15];
    for (i, x) in state.iter_mut().enumerate() {
        let bound = match i {
            0 => 3.0,
            1 | 2 => 1.0,
            3..6 => 1.5,
            6..9 => 100.0,
            9..13 => 1.2,
            _ => 0.6,
        };
        *x = within(random, bound);
    }
    (state, [within(random, 0.3), within(random, 0.3)])
}

/// How many of `a`'s and `b`'s entries differ in their bits.
fn differing(a: impl IntoIterator<Item = f64>, b: impl IntoIterator<Item = f64>) -> usize {
    a.into_iter()
        .zip(b)
        .filter(|(x, y)| x.to_bits() != y.to_bits())
        .count()
}

/// `model` against `reference` on `STATES` draws of `draw`: rhs on every one, the Jacobians
/// and the kinetic energy on the first `JACOBIAN_STATES`; the count of differing bits.
fn compare<M, R, const N: usize, const I: usize>(
    model: &M,
    reference: &R,
    mut draw: impl FnMut() -> ([f64; N], [f64; I]),
) -> (usize, usize)
where
    M: Model<f64, N, I>,
    R: Model<f64, N, I>,
{
    let (mut rates, mut rest) = (0, 0);
    for k in 0..STATES {
        let (state, input) = draw();
        rates += differing(model.rhs(&state, &input), reference.rhs(&state, &input));
        if k < JACOBIAN_STATES {
            let by_state = |m: &dyn Fn() -> [[f64; N]; N]| m().into_iter().flatten();
            rest += differing(
                by_state(&|| model.state_jacobian(&state, &input)),
                by_state(&|| reference.state_jacobian(&state, &input)),
            );
            rest += differing(
                model.input_jacobian(&state, &input).into_iter().flatten(),
                reference
                    .input_jacobian(&state, &input)
                    .into_iter()
                    .flatten(),
            );
            rest += differing(
                [model.kinetic_energy(&state)],
                [reference.kinetic_energy(&state)],
            );
        }
    }
    (rates, rest)
}

#[test]
fn the_compiled_mariner_is_the_interpreted_one_bit_for_bit() {
    let model = mariner();
    assert_eq!(model.terms(), 39);
    assert_eq!(
        model.is_compiled(),
        ANGLES_COMPILE,
        "the Mariner's program compiles"
    );
    let reference = model.interpreted();
    assert!(!reference.is_compiled());
    let mut random = Random(0x5EED_0001);
    let (rates, rest) = compare(&model, &reference, || ship_state(&mut random));
    assert_eq!(
        (rates, rest),
        (0, 0),
        "differing outputs: rhs, Jacobians and energy"
    );
}

#[test]
fn the_compiled_remus_is_the_interpreted_one_bit_for_bit() {
    let model = remus();
    assert!(model.is_compiled(), "REMUS's program compiles");
    let reference = model.interpreted();
    let mut random = Random(0x5EED_0002);
    let (rates, rest) = compare(&model, &reference, || vehicle_state(&mut random));
    assert_eq!(
        (rates, rest),
        (0, 0),
        "differing outputs: rhs, Jacobians and energy"
    );
}

#[test]
fn the_compiled_esso_osaka_is_the_interpreted_one_bit_for_bit() {
    // The published table: the program reads the propeller's n, |n|, u_A and c beside U.
    let model = ship("esso_osaka.toml");
    assert!(model.propulsion().is_some());
    assert_eq!(model.is_compiled(), ANGLES_COMPILE);
    let reference = model.interpreted();
    let mut random = Random(0x5EED_0004);
    let (rates, rest) = compare(&model, &reference, || ship_state(&mut random));
    assert_eq!(
        (rates, rest),
        (0, 0),
        "differing outputs: rhs, Jacobians and energy"
    );
}

/// The compiled code writes the sine and cosine kernel out: at the angles where the kernel
/// changes path (±π/4, the quadrants' edges and far beyond, tiny angles, its reduction's limit
/// 2¹⁹·π/2, NaN, the infinities) and their neighbours, the heading's sine and cosine are the
/// interpreter's, bit for bit.
#[test]
fn the_written_out_kernel_is_the_kernel_at_every_edge() {
    let model = mariner();
    let reference = model.interpreted();
    let limit = f64::from_bits(0x4129_21FA_0000_0000);
    let mut headings = vec![0.0, -0.0, 1e-300, 2f64.powi(-27), 1e-9, limit, 1e7, 1e300];
    headings.extend([f64::NAN, f64::INFINITY, f64::MIN_POSITIVE, f64::MAX]);
    for k in -8..=8 {
        let edge = f64::from(k) * std::f64::consts::FRAC_PI_4;
        headings.push(edge);
        headings.push(f64::from(k) * std::f64::consts::FRAC_PI_2 + 1e-12);
    }
    let mut all = Vec::new();
    for heading in headings {
        for x in [heading, -heading] {
            let ulp = |x: f64, by: i64| f64::from_bits(x.to_bits().wrapping_add_signed(by));
            all.extend((-2..=2).map(|by| ulp(x, by)));
        }
    }
    let mut state = [7.7, 0.3, -0.01, 10.0, -4.0, 0.0, 0.1];
    for heading in all {
        state[5] = heading;
        let (a, b) = (
            model.rhs(&state, &[0.0; 3]),
            reference.rhs(&state, &[0.0; 3]),
        );
        // x' = u cos ψ − v sin ψ and y' = u sin ψ + v cos ψ read the heading's pair.
        assert_eq!(
            a.map(f64::to_bits),
            b.map(f64::to_bits),
            "heading {heading:e}"
        );
    }
}

/// The interpreted model compiled again gives the bits of the model as built.
#[test]
fn compiling_again_gives_the_same_bits() {
    let model = mariner();
    let again = model.interpreted().compiled();
    assert_eq!(again.is_compiled(), ANGLES_COMPILE);
    let mut random = Random(0x5EED_0003);
    for _ in 0..1000 {
        let (state, input) = ship_state(&mut random);
        assert_eq!(
            differing(model.rhs(&state, &input), again.rhs(&state, &input)),
            0
        );
    }
}

/// Types other than f64 are the interpreter's: an f32 call through the compiled model gives
/// the interpreted model's f32 bits.
#[test]
fn other_number_types_are_interpreted() {
    let model = mariner();
    let reference = model.interpreted();
    let state = [7.5f32, 0.3, -0.01, 10.0, -4.0, 0.4, 0.2];
    let (a, b) = (
        model.rhs(&state, &[0.01, 0.0, 0.0]),
        reference.rhs(&state, &[0.01, 0.0, 0.0]),
    );
    assert_eq!(a.map(f32::to_bits), b.map(f32::to_bits));
    assert!(a.iter().all(|x| x.is_finite()));
}

/// The Mariner's table with every term and added mass scaled by its own factor.
fn perturbed(
    table: &eom::kinds::ship::table::ShipTable,
    seed: u64,
) -> eom::kinds::ship::table::ShipTable {
    let mut random = Random(seed);
    let mut table = table.clone();
    for value in table.terms.values_mut().chain(table.added_mass.iter_mut()) {
        *value *= 1.0 + within(&mut random, 0.2);
    }
    table
}

/// A model re-parameterised with another table's values (the program proved and compiled
/// once, its values read at each call) is the model built from that table, bit for bit.
#[test]
fn a_model_with_other_values_is_the_model_of_those_values() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/mariner.toml");
    let table = ShipScene::load(Path::new(path)).unwrap().table;
    let base = ShipModel::new(&table).unwrap();
    let other = perturbed(&table, 0x5EED_0004);
    let (reused, built) = (
        base.with_table(&other).unwrap(),
        ShipModel::new(&other).unwrap(),
    );
    assert_eq!(reused.is_compiled(), ANGLES_COMPILE);
    let mut random = Random(0x5EED_0005);
    let mut changed = 0;
    for _ in 0..1000 {
        let (state, input) = ship_state(&mut random);
        let rates = reused.rhs(&state, &input);
        assert_eq!(differing(rates, built.rhs(&state, &input)), 0);
        changed += differing(rates, base.rhs(&state, &input));
    }
    assert!(changed > 1000, "the values changed the rates: {changed}");
    // A table of other terms is another program.
    let mut fewer = table.clone();
    let first = *fewer.terms.keys().next().unwrap();
    fewer.terms.remove(&first);
    assert!(base.with_table(&fewer).is_err());
}

/// Numbers at the edges of f64: both zeros, subnormals, the largest magnitudes, the
/// infinities, and NaN of either sign.
const EXTREMES: [f64; 10] = [
    0.0,
    -0.0,
    5e-324,
    -2.2e-308,
    1e300,
    -f64::MAX,
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::NAN,
    -f64::NAN,
];

/// The entries whose bits differ between `model`'s and `reference`'s rates at `state` under
/// `input`, each named with the state and input.
fn rates_differing<M: Model<f64, N, I>, const N: usize, const I: usize>(
    model: &M,
    reference: &M,
    state: &[f64; N],
    input: &[f64; I],
) -> Vec<String> {
    let (a, b) = (model.rhs(state, input), reference.rhs(state, input));
    (0..N)
        .filter(|&k| a[k].to_bits() != b[k].to_bits())
        .map(|k| format!("rate {k}: {:e} ≠ {:e} at {state:?}, {input:?}", a[k], b[k]))
        .collect()
}

/// `model`'s rates against its interpreter's at `draw`'s states with each entry of the state
/// and the input set in turn to each of [`EXTREMES`], and at states and inputs whose every
/// entry is drawn from them or from `draw`: the differing entries.
fn extremes_differing<M: Model<f64, N, I>, const N: usize, const I: usize>(
    model: &M,
    reference: &M,
    mut draw: impl FnMut() -> ([f64; N], [f64; I]),
    random: &mut Random,
) -> Vec<String> {
    let mut differing = Vec::new();
    for position in 0..N + I {
        for extreme in EXTREMES {
            let (mut state, mut input) = draw();
            match position.checked_sub(N) {
                None => state[position] = extreme,
                Some(k) => input[k] = extreme,
            }
            differing.extend(rates_differing(model, reference, &state, &input));
        }
    }
    for _ in 0..2000 {
        let (mut state, mut input) = draw();
        for x in state.iter_mut().chain(input.iter_mut()) {
            if random.unit() < 0.5 {
                *x = EXTREMES[(random.unit() * EXTREMES.len() as f64) as usize];
            }
        }
        differing.extend(rates_differing(model, reference, &state, &input));
    }
    differing
}

/// The compiled call reads each of the program's variables where the model puts it (an entry
/// of the state where it lies, the magnitude |x| of one, what the model sets beside the state:
/// a ship's δ̇, U, n, |n|, u_A and c, a vehicle's propeller ε and cross-flow loads) and writes
/// the rates in place: at the edges of f64 (signed zeros, subnormals, the largest magnitudes,
/// the infinities, NaN of either sign) in any entry of the state or the input, its rates are
/// the interpreter's bit for bit, for ships with and without propulsion and for vehicles with
/// and without computed inputs.
#[test]
fn the_compiled_call_is_the_interpreter_s_at_the_edges_of_f64() {
    let nps = {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/nps_auv2.toml");
        let text = std::fs::read_to_string(path).unwrap();
        let scene = AnyScene::parse(&text, "nps_auv2.toml", Path::new(".")).ok();
        match scene.and_then(AnyScene::downcast::<eom::kinds::vehicle::VehicleScene>) {
            Some(scene) => scene.model,
            None => panic!("nps_auv2.toml is read as a vehicle"),
        }
    };
    let mut random = Random(0x5EED_0006);
    let mut differing = Vec::new();
    for ship in [mariner(), ship("esso_osaka.toml")] {
        assert_eq!(ship.is_compiled(), ANGLES_COMPILE);
        let reference = ship.interpreted();
        let mut draws = Random(0x5EED_0007);
        let draw = || ship_state(&mut draws);
        differing.extend(extremes_differing(&ship, &reference, draw, &mut random));
    }
    for vehicle in [remus(), nps] {
        assert!(vehicle.is_compiled());
        let reference = vehicle.interpreted();
        let mut draws = Random(0x5EED_0008);
        let draw = || vehicle_state(&mut draws);
        differing.extend(extremes_differing(&vehicle, &reference, draw, &mut random));
    }
    assert!(
        differing.is_empty(),
        "{} differing rates, the first: {:#?}",
        differing.len(),
        &differing[..differing.len().min(5)]
    );
}
