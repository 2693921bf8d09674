//! What the bench and the tests of this crate share: the tables `eom` reads for the ships this
//! crate compiles with rustc (the ten-term ship of `build.rs`, the Mariner of
//! `scenes/mariner.toml`), each parameter by its generated symbol, and random ship states.

use eom::Model;
use eom::kinds::ship::table::{GivenTable, ShipBody, ShipTable};
use eom::kinds::ship::{RigidBodyTerms, ShipScene, Units, YawInertia};
use eom::kinds::vehicle::VehicleScene;
use eom::kinds::vehicle::model::{parameter_values, spec};
use eom::scene::AnyScene;
use eom_codegen::model::Kinematics;
use eom_codegen::model::ship::{ADDED_MASS, PRIME_SCALES, ShipForm, ShipSpec};
use eom_example_user_build_rs::{example_ship, mariner, remus};
use std::collections::BTreeMap;
use std::path::Path;
use std::sync::OnceLock;

/// The same numbers as `example_ship`, as a table `eom` reads.
pub fn table() -> ShipTable {
    let p = example_ship();
    let coefficients = [
        ("Xudot", p.x_udot),
        ("Yvdot", p.y_vdot),
        ("Yrdot", p.y_rdot),
        ("Nvdot", p.n_vdot),
        ("Nrdot", p.n_rdot),
        ("Xu", p.x_u),
        ("Xvv", p.x_vv),
        ("Yv", p.y_v),
        ("Yr", p.y_r),
        ("Yvvv", p.y_vvv),
        ("Yd", p.y_d),
        ("Nv", p.n_v),
        ("Nr", p.n_r),
        ("Nvvr", p.n_vvr),
        ("Nd", p.n_d),
    ];
    let given = GivenTable {
        units: Units::Dimensional,
        body: ShipBody {
            mass: p.mass,
            yaw_inertia: p.izz,
            yaw_inertia_about: YawInertia::AboutG,
            x_g: p.x_g,
        },
        density: None,
        length: None,
        design_speed: 6.0,
        rigid_body_terms: RigidBodyTerms::Separate,
        coefficients: coefficients
            .iter()
            .map(|(k, v)| ((*k).into(), *v))
            .collect(),
        propulsion: None,
    };
    ShipTable::new(&given).expect("a valid table")
}

/// A scene of the workspace's `scenes/`.
pub fn scene_path(file: &str) -> String {
    format!("{}/../../scenes/{file}", env!("CARGO_MANIFEST_DIR"))
}

/// The Mariner's table as `eom` reads its scene.
pub fn mariner_table() -> ShipTable {
    ShipScene::load(Path::new(&scene_path("mariner.toml")))
        .expect("the Mariner's scene reads")
        .table
}

/// Every parameter of `table` by its symbol, as `eom`'s ship model fills them.
pub fn symbols(table: &ShipTable) -> BTreeMap<String, f64> {
    let spec = ShipSpec {
        units: table.units,
        yaw_inertia: table.body.yaw_inertia_about,
        terms: table.terms.keys().copied().collect(),
        propulsion: false,
        form: ShipForm::Polynomial,
        current: false,
        applied: false,
    };
    let body = [table.body.mass, table.body.yaw_inertia, table.body.x_g];
    let scales = [
        table.density.unwrap_or(f64::NAN),
        table.length.unwrap_or(f64::NAN),
        table.design_speed,
    ];
    (spec.body_symbols().into_iter().zip(body))
        .chain(ADDED_MASS.into_iter().zip(table.added_mass))
        .chain(PRIME_SCALES.into_iter().zip(scales))
        .map(|(symbol, value)| (symbol.to_owned(), value))
        .chain(table.terms.iter().map(|(t, v)| (t.symbol(), *v)))
        .collect()
}

/// A splitmix64 draw in [−bound, bound).
pub fn draw(seed: &mut u64, bound: f64) -> f64 {
    *seed = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *seed;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^= z >> 31;
    bound * (2.0 * ((z >> 11) as f64 / (1u64 << 53) as f64) - 1.0)
}

/// Outputs of `a` and `b` whose bits differ, over 10⁵ random ship states.
pub fn differing_bits(
    a: impl Fn(&[f64; 7], f64) -> [f64; 7],
    b: impl Fn(&[f64; 7], f64) -> [f64; 7],
) -> usize {
    let mut seed = 1;
    let bounds = [12.0, 4.0, 0.1, 5000.0, 5000.0, 20.0, 0.8];
    (0..100_000)
        .map(|_| {
            let state = bounds.map(|b| draw(&mut seed, b));
            let rate = draw(&mut seed, 0.1);
            let (x, y) = (a(&state, rate), b(&state, rate));
            x.iter()
                .zip(&y)
                .filter(|(x, y)| x.to_bits() != y.to_bits())
                .count()
        })
        .sum()
}

/// The Mariner's coefficients as this crate's rustc-compiled `mariner` module computes them
/// from `table`'s values.
pub fn mariner_coefficients(table: &ShipTable) -> mariner::Coefficients<f64> {
    let values = symbols(table);
    mariner::Coefficients::new(&mariner::Parameters::from_symbols(|s| {
        values.get(s).copied().unwrap_or(f64::NAN)
    }))
}

/// The rustc-compiled Mariner's rates with the rudder moving at `rate`: the prime system's
/// forces scale with U, an input of the generated program that `eom`'s model computes from
/// the state, so here.
pub fn mariner_rates(m: &mariner::Coefficients<f64>, s: &[f64; 7], rate: f64) -> [f64; 7] {
    m.rhs(s, &[rate, (s[0] * s[0] + s[1] * s[1]).sqrt()])
}

/// REMUS 100's scene as `eom` reads it.
pub fn remus_scene() -> VehicleScene {
    let text = std::fs::read_to_string(scene_path("remus100.toml")).expect("REMUS's scene");
    let scene = AnyScene::parse(&text, "remus100.toml", Path::new(".")).ok();
    match scene.and_then(AnyScene::downcast::<VehicleScene>) {
        Some(scene) => *scene,
        None => panic!("remus100.toml is read as a vehicle"),
    }
}

/// REMUS's coefficients as this crate's rustc-compiled `remus` module computes them from the
/// scene's table, its parameters filled as `eom`'s model fills them.
pub fn remus_coefficients(scene: &VehicleScene) -> remus::Coefficients<f64> {
    let spec = spec(&scene.table, Kinematics::Quaternion);
    let values = parameter_values(&spec, &scene.table).expect("REMUS's parameters");
    remus::Coefficients::new(&remus::Parameters::from_symbols(|s| {
        values.get(s).copied().unwrap_or(f64::NAN)
    }))
}

/// Where the rustc-compiled REMUS reads each of its inputs in `eom`'s fifteen-entry state (the
/// fins' angles last), as `eom`'s model sets it: the entry, and whether its magnitude |x|.
/// Found by name once, so that a call costs what the generated code costs.
fn remus_inputs() -> &'static [(usize, bool); remus::INPUTS.len()] {
    static INPUTS: OnceLock<[(usize, bool); remus::INPUTS.len()]> = OnceLock::new();
    INPUTS.get_or_init(|| {
        remus::INPUTS.map(|name| match name {
            "dr" => (13, false),
            "ds" => (14, false),
            _ => {
                let of = name.strip_prefix("abs_").expect("an input |x|");
                let index = (remus::STATE.iter().position(|s| *s == of)).expect("a state");
                (index, true)
            }
        })
    })
}

/// The rustc-compiled REMUS's rates of its thirteen states at `eom`'s fifteen-entry state (the
/// fins' angles last), each input set as `eom`'s model sets it: a fin's angle, or |x|.
pub fn remus_rates(k: &remus::Coefficients<f64>, state: &[f64; 15]) -> [f64; 13] {
    let mut inputs = [0.0; remus::INPUTS.len()];
    for (input, &(index, magnitude)) in inputs.iter_mut().zip(remus_inputs()) {
        *input = if magnitude {
            state[index].abs()
        } else {
            state[index]
        };
    }
    let body: [f64; 13] = std::array::from_fn(|i| state[i]);
    k.rhs(&body, &inputs)
}

/// Outputs of `a` and `b` whose bits differ, over 10⁵ random REMUS states (velocities and
/// rates of either sign, a quaternion not of unit length, the fins beyond their stops).
pub fn differing_vehicle_bits(
    a: impl Fn(&[f64; 15]) -> [f64; 13],
    b: impl Fn(&[f64; 15]) -> [f64; 13],
) -> usize {
    let mut seed = 2;
    let bounds = [
        3.0, 1.0, 1.0, 1.5, 1.5, 1.5, 100.0, 100.0, 100.0, 1.2, 1.2, 1.2, 1.2, 0.6, 0.6,
    ];
    (0..100_000)
        .map(|_| {
            let state = bounds.map(|b| draw(&mut seed, b));
            let (x, y) = (a(&state), b(&state));
            x.iter()
                .zip(&y)
                .filter(|(x, y)| x.to_bits() != y.to_bits())
                .count()
        })
        .sum()
}
