//! The vehicle at run time: REMUS on Prestero's table (`scenes/remus100.toml`) against the
//! published data (`data/remus100_prestero.json`), its cruise against the closed forms, the turn of the thesis's Chapter 8 test,
//! the mirror of port and starboard turns, the proved Jacobian with the chain rule through
//! |x|, the folded table against its added mass, and bad tables each refused by key.

use eom::Model;
use eom::kinds::vehicle::manoeuvre::{self, VehicleManoeuvre, VehicleRun};
use eom::kinds::vehicle::summary::{CruiseSummary, StepFigures, largest_difference};
use eom::kinds::vehicle::trim::cruise;
use eom::kinds::vehicle::{VehicleModel, VehicleScene, format_folded};
use eom::scene::AnyScene;
use eom_test_support::differences::central_jacobians;
use std::path::Path;

const SCENE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/remus100.toml");

fn scene_text() -> String {
    std::fs::read_to_string(SCENE).unwrap()
}

fn parse(text: &str) -> Result<VehicleScene, String> {
    match AnyScene::parse(text, "remus100.toml", Path::new(".")) {
        Ok(scene) => (scene.downcast::<VehicleScene>())
            .map(|scene| *scene)
            .ok_or_else(|| "not read as a vehicle".into()),
        Err(e) => Err(e.to_string()),
    }
}

fn remus() -> VehicleScene {
    parse(&scene_text()).unwrap()
}

/// Scene text stepped by RK4 at 0.01 s, a tenth of a percent of the roll period, where the
/// figures move by less than 1e-6 at half the step: for the checks of convergence, finer than
/// the scene's 0.05 s (what `eom tradeoff` recommends for targets of 0.01 m and 0.001°).
fn at_fine_step(text: &str) -> String {
    assert!(text.contains("\nstep = 0.05\n"), "the scene's step");
    text.replacen("\nstep = 0.05\n", "\nstep = 0.01\n", 1)
}

fn data() -> serde_json::Value {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/data/remus100_prestero.json");
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn run_with(
    scene: &VehicleScene,
    model: &VehicleModel,
    m: &VehicleManoeuvre,
    start: [f64; 15],
) -> VehicleRun {
    let stepping = (&scene.stepper, scene.every);
    manoeuvre::run(model, &scene.fins, m, start, stepping, |_| true).unwrap()
}

#[test]
fn the_remus_scene_holds_the_published_data_bit_for_bit() {
    let scene = remus();
    let data = data();
    let number = |v: &serde_json::Value| v.as_f64().unwrap();
    let coefficients = data["coefficients"].as_object().unwrap();
    let table = &scene.table;
    assert_eq!(
        table.added_mass.len() + table.coefficients.len(),
        coefficients.len()
    );
    for (name, value) in coefficients {
        let given = table
            .added_mass
            .get(name)
            .or_else(|| table.coefficients.get(name))
            .unwrap_or_else(|| panic!("{name} missing"));
        assert_eq!(given.to_bits(), number(value).to_bits(), "{name}");
    }
    let body = &data["mass_properties"];
    assert_eq!(table.mass.to_bits(), number(&body["mass_kg"]).to_bits());
    assert_eq!(table.weight.to_bits(), number(&body["weight_N"]).to_bits());
    // The one number the scene changes, and says so: neutral buoyancy, as the data's note
    // says the thesis's turning runs are.
    assert_eq!(table.buoyancy.to_bits(), table.weight.to_bits());
    assert!(
        body["buoyancy_note"]
            .as_str()
            .unwrap()
            .contains("buoyancy = weight")
    );
    // Prestero's moments are about the origin O (the centre of buoyancy), and the scene reads
    // them there: carried from G by Steiner they would add M z_G² to I_xx and I_yy.
    for (i, axis) in ["Ixx", "Iyy", "Izz"].iter().enumerate() {
        let value = number(&body["inertia_about_O_kg_m2"][axis]);
        assert_eq!(table.inertia[i][i].to_bits(), value.to_bits(), "{axis}");
    }
    assert_eq!(
        table.inertia_about,
        eom::kinds::vehicle::InertiaAbout::Origin
    );
    for i in 0..3 {
        let g = number(&body["centre_of_gravity_m"][i]);
        let b = number(&body["centre_of_buoyancy_m"][i]);
        assert_eq!(table.centre_of_gravity[i].to_bits(), g.to_bits());
        assert_eq!(table.centre_of_buoyancy[i].to_bits(), b.to_bits());
    }
    let propeller = table.propeller.unwrap();
    let setting = &data["propeller_at_1500_rpm"];
    assert_eq!(
        propeller.thrust.to_bits(),
        number(&setting["X_prop_N"]).to_bits()
    );
    assert_eq!(
        propeller.torque.to_bits(),
        number(&setting["K_prop_N_m"]).to_bits()
    );
    // Every reading that differs between the transcriptions is listed in the scene.
    let text = scene_text();
    for reading in data["readings_that_differ"].as_array().unwrap() {
        let name = reading.as_str().unwrap().split(':').next().unwrap();
        assert!(text.contains(&format!("# - {name}:")), "{name} not listed");
    }
}

#[test]
fn the_cruise_is_the_closed_form_speed_and_roll_trim_and_holds() {
    let scene = remus();
    let start = scene.start().unwrap();
    let cruise = CruiseSummary::new(&scene);
    println!("{cruise:#?}");
    // Newton stops when u̇ and ṗ are below 1e-13 (m/s², rad/s²); ∂u̇/∂u ≈ 0.16 /s and
    // ∂ṗ/∂φ ≈ 24 /s², so u and φ are within 1e-12 of the trim.
    let speed = cruise.speed_closed_form_m_s.unwrap();
    assert!((cruise.speed_m_s - speed).abs() < 1e-11, "{cruise:?}");
    assert!((speed - 1.5436).abs() < 1e-4, "the data's note: 1.5436 m/s");
    let roll = cruise.roll_closed_form_deg.unwrap();
    assert!((cruise.roll_deg - roll).abs() < 1e-9, "{cruise:?}");
    // The propeller's torque rolls REMUS to port by about 5.3°.
    assert!((roll + 5.3164).abs() < 1e-4, "{roll}");
    // The cruise is a trim of the whole model: ten seconds of it leave it where it was, to
    // the rounding of 1000 RK4 steps.
    let run = run_with(&scene, &scene.model, &scene.manoeuvres[0], start);
    let before = run.ends[0];
    assert_eq!(before.t, 10.0);
    for (i, (a, b)) in before.state.iter().zip(&start).enumerate() {
        let moved = if i == 6 { a - b - speed * 10.0 } else { a - b };
        assert!(moved.abs() < 1e-9, "state {i} moved by {moved:e}");
    }
}

#[test]
fn remus_turns_at_the_thesis_s_rate_under_four_degrees_of_rudder() {
    let scene = parse(&at_fine_step(&scene_text())).unwrap();
    let start = scene.start().unwrap();
    let figures = StepFigures::of(&run_with(&scene, &scene.model, &scene.manoeuvres[0], start));
    for f in &figures {
        println!("{f:?}");
    }
    let turn = figures[1];
    assert_eq!((turn.from_s, turn.to_s, turn.rudder_deg), (10.0, 40.0, 4.0));
    // The thesis's figure reads about −9.0 °/s; a reading of a plot, so 0.5 °/s.
    assert!((turn.yaw_rate_deg_s + 9.0).abs() < 0.5, "{turn:?}");
    let back = figures[2];
    assert!((back.yaw_rate_deg_s - 9.0).abs() < 0.5, "{back:?}");
    // Converged: half the step moves no figure by more than 1e-6 (RK4's error at 0.01 s is
    // of order h⁴ = 1e-8 times the motion's fourth derivative).
    let mut finer = scene.clone();
    finer.stepper = scene.stepper.refined(scene.every);
    let refined = StepFigures::of(&run_with(&finer, &scene.model, &scene.manoeuvres[0], start));
    let difference = largest_difference(&figures, &refined);
    println!("half-step difference {difference:e}");
    assert!(difference < 1e-6, "{difference:e}");
}

#[test]
fn port_and_starboard_turns_mirror_each_other_without_propeller_torque() {
    let scene = remus();
    let table = scene.table.without_propeller_torque();
    let model = VehicleModel::new(&table).unwrap();
    let start = cruise(&model).unwrap();
    assert_eq!(start[10], 0.0, "no torque, no roll trim");
    let starboard = &scene.manoeuvres[0];
    let port = VehicleManoeuvre {
        steps: starboard.steps.mirrored(),
        ..starboard.clone()
    };
    let (a, b) = (
        run_with(&scene, &model, starboard, start),
        run_with(&scene, &model, &port, start),
    );
    // Reflected in the x–z plane (manoeuvre::mirrored).
    let mut worst: f64 = 0.0;
    for (x, y) in a.ends.iter().zip(&b.ends) {
        let reflected = manoeuvre::mirrored(&y.state);
        for (a, b) in x.state.iter().zip(reflected) {
            worst = worst.max((a - b).abs());
        }
    }
    println!("largest mirror difference {worst:e}");
    assert!(worst < 1e-9, "{worst:e}");
    assert!(a.ends[1].state[5].abs() > 0.1, "the vehicle turned");
}

#[test]
fn the_model_s_jacobian_is_the_derivative_of_its_rates_with_the_sign_chain_rule() {
    let scene = remus();
    let model = &scene.model;
    // A state with every entry moving, some velocities negative (|x| then −x).
    let mut x = [
        1.2, -0.2, 0.15, -0.3, 0.25, -0.4, 1.0, 2.0, 3.0, 0.9, 0.1, -0.2, 0.3, 0.05, -0.04,
    ];
    let norm = (9..13).map(|i| x[i] * x[i]).sum::<f64>().sqrt();
    for q in &mut x[9..13] {
        *q /= norm;
    }
    let input = [0.01, -0.02];
    let exact = Model::<f64, 15, 2>::state_jacobian(model, &x, &input);
    let (numeric, _) = central_jacobians(
        |x, u| Model::<f64, 15, 2>::rhs(model, x, u),
        (&x, &input),
        |_| 1e-6,
    );
    let mut worst: f64 = 0.0;
    for (numeric_row, exact_row) in numeric.iter().zip(&exact) {
        for (numeric, exact) in numeric_row.iter().zip(exact_row) {
            worst = worst.max((numeric - exact).abs() / (1.0 + exact.abs()));
        }
    }
    // Central differences at h = 1e-6: truncation h² ~ 1e-12 times the third derivative,
    // rounding 1e-16/h ~ 1e-10 times the rates (of order 100 here).
    assert!(worst < 1e-6, "{worst:e}");
    for (row, column) in <VehicleModel as Model<f64, 15, 2>>::STATE_JACOBIAN
        .iter()
        .copied()
    {
        assert!(row < 15 && column < 15);
    }
}

#[test]
fn the_folded_table_is_shown_against_its_added_mass() {
    let scene = remus();
    let rows = scene.model.folded();
    println!("{}", format_folded(rows));
    let printed: Vec<_> = rows.iter().filter(|r| r.printed.is_some()).collect();
    let exact = printed.iter().filter(|r| r.difference == Some(0.0)).count();
    assert_eq!((printed.len(), exact), (18, 10));
    let mrp = rows
        .iter()
        .find(|r| r.name.as_deref() == Some("Mrp"))
        .unwrap();
    // Mrp = K_ṗ − N_ṙ: −0.0704 + 4.88 = 4.8096 against 4.86 printed.
    assert!(
        (mrp.implied - 4.8096).abs() < 1e-12 && (mrp.difference.unwrap() - 0.0504).abs() < 1e-12
    );
    let muw = rows
        .iter()
        .find(|r| r.name.as_deref() == Some("Muw"))
        .unwrap();
    assert!(
        (muw.implied - 34.57).abs() < 1e-9,
        "the Munk moment {}",
        muw.implied
    );
}

/// The scene with `from` replaced by `to` (which must be there).
fn edited(from: &str, to: &str) -> String {
    let text = scene_text();
    assert!(text.contains(from), "{from}");
    text.replacen(from, to, 1)
}

#[test]
fn bad_tables_are_refused_naming_the_key() {
    let cases = [
        (
            "Yvv = -1310.0",
            "Yfoo = -1310.0",
            "hydrodynamics.coefficients.Yfoo",
        ),
        (
            "Yvv = -1310.0",
            "Yvvr = -1310.0",
            "hydrodynamics.coefficients.Yvvr",
        ),
        (
            "Yuv = -28.6",
            "Yuv = -28.6\nYvu = -28.6",
            "hydrodynamics.coefficients.Yvu",
        ),
        (
            "Nvdot = 1.93",
            "Nvdot = 2.0",
            "hydrodynamics.added_mass.Nvdot",
        ),
        ("Xudot = -0.93", "Xudot = 40.0", "hydrodynamics.added_mass"),
        (
            "Xuu = -1.62",
            "Xuu = -1.62\nXudot = -0.93",
            "hydrodynamics.coefficients.Xudot",
        ),
        (
            "[rudder]\nmax_deg = 15.0",
            "[rudder]\nmax_deg = 15.0\nmax_rate_deg_s = 20.0",
            "rudder.max_rate_deg_s",
        ),
        (
            "convention = \"prestero\"",
            "convention = \"abkowitz\"",
            "hydrodynamics.convention",
        ),
        ("inertia = [0.177", "inertia = [-0.177", "body.inertia[0]"),
        ("inertia = [0.177", "inertia = [nan", "body.inertia[0]"),
        (
            "inertia = [0.177, 3.45, 3.45]",
            "inertia = [0.177, 3.45, 3.7]",
            "body.inertia",
        ),
        (
            "inertia = [0.177, 3.45, 3.45]",
            "inertia = [0.177, 3.45, 3.45]\nproducts_of_inertia = [0.0, 0.0]",
            "body.products_of_inertia",
        ),
        (
            "inertia = [0.177, 3.45, 3.45]",
            "inertia = [0.177, 3.45, 3.45]\nproducts_of_inertia = [0.0, nan, 0.0]",
            "body.products_of_inertia[1]",
        ),
        (
            "inertia = [0.177, 3.45, 3.45]",
            "inertia = [0.177, 3.45, 3.45]\nproducts_of_inertia = [0.8, 0.0, 0.0]",
            "body.inertia",
        ),
        (
            "inertia_about = \"origin\"",
            "inertia_about = \"B\"",
            "body.inertia_about",
        ),
        // About O, I_xx = 0.005 is less than M z_G² = 0.0117: no tensor about G gives it.
        ("inertia = [0.177", "inertia = [0.005", "body.inertia"),
        (
            "kind = \"fin_steps\"",
            "kind = \"crash_back\"",
            "manoeuvre[0].kind",
        ),
        (
            "thrust = 3.86                         # X_prop, N\n",
            "law = \"healey_lienard\"\nrpm = 1500.0\nadvance = 0.001\ndrag_coefficient = 0.1\n\
             thrust_coefficient = 0.01\n",
            "propeller.law",
        ),
        (
            "thrust = 3.86",
            "thrust = 3.86\nrpm = 1500.0",
            "propeller.rpm",
        ),
        ("torque = -0.543", "", "propeller.torque"),
    ];
    for (from, to, key) in cases {
        let error = parse(&edited(from, to))
            .err()
            .unwrap_or_else(|| panic!("{to} accepted"));
        println!("{error}");
        assert!(error.contains(&format!("`{key}`")), "{to}: {error}");
    }
    // What each refusal says of the table.
    let not_definite = parse(&edited("Xudot = -0.93", "Xudot = 40.0")).unwrap_err();
    assert!(not_definite.contains("not positive definite") && not_definite.contains("Xudot"));
    let ambiguous = parse(&edited("Yvv = -1310.0", "Yvvr = -1310.0")).unwrap_err();
    assert!(ambiguous.contains("ambiguous"), "{ambiguous}");
    let inertia = |to: &str| parse(&edited("inertia = [0.177, 3.45, 3.45]", to)).unwrap_err();
    let triangle = inertia("inertia = [0.177, 3.45, 3.7]");
    assert!(triangle.contains("triangle inequality"), "{triangle}");
    let indefinite =
        inertia("inertia = [0.177, 3.45, 3.45]\nproducts_of_inertia = [0.8, 0.0, 0.0]");
    assert!(indefinite.contains("not positive definite"), "{indefinite}");
    let about_g = parse(&edited("inertia = [0.177", "inertia = [0.005")).unwrap_err();
    assert!(about_g.contains("about G"), "{about_g}");
    let dimensional = parse(&edited(
        "thrust = 3.86                         # X_prop, N\n",
        "law = \"healey_lienard\"\nrpm = 1500.0\nadvance = 0.001\ndrag_coefficient = 0.1\n\
         thrust_coefficient = 0.01\n",
    ))
    .unwrap_err();
    assert!(dimensional.contains("prime system"), "{dimensional}");
    let shape = inertia("inertia = [0.177, 3.45, 3.45]\nproducts_of_inertia = [0.0, 0.0]");
    assert!(shape.contains("three products"), "{shape}");
}

/// REMUS with its products of inertia written, zero: the products are pruned, so the model
/// is the same program, operation for operation and bit for bit.
#[test]
fn a_tensor_with_zero_products_builds_the_principal_model() {
    let scene = remus();
    let tensor = parse(&edited(
        "inertia = [0.177, 3.45, 3.45]",
        "inertia = [0.177, 3.45, 3.45]\nproducts_of_inertia = [0.0, 0.0, 0.0]",
    ))
    .unwrap();
    assert_eq!(
        tensor.table.inertia,
        [[0.177, 0.0, 0.0], [0.0, 3.45, 0.0], [0.0, 0.0, 3.45]]
    );
    assert_eq!(tensor.model.operations(), scene.model.operations());
    let start = scene.start().unwrap();
    assert_eq!(tensor.start().unwrap(), start);
    let mut state = start;
    state[1..6].copy_from_slice(&[0.1, -0.05, 0.2, -0.3, 0.4]);
    state[13] = 0.1;
    let input = [0.01, -0.02];
    let a = Model::<f64, 15, 2>::rhs(&scene.model, &state, &input);
    let b = Model::<f64, 15, 2>::rhs(&tensor.model, &state, &input);
    assert_eq!(a, b);
    // REMUS's manoeuvres run the same.
    let m = &scene.manoeuvres[0];
    let (x, y) = (
        run_with(&scene, &scene.model, m, start),
        run_with(&tensor, &tensor.model, m, start),
    );
    for (x, y) in x.ends.iter().zip(&y.ends) {
        assert_eq!(x.state, y.state);
    }
}

/// REMUS's tensor about O and the tensor about G that Steiner (4.23) carries to it describe
/// one body: the scene written either way gives the same rates, to rounding. Prestero's
/// numbers written about G (as their transcription first labelled them) are another, heavier
/// body in roll and pitch, whose rates differ.
#[test]
fn the_tensor_about_o_is_the_tensor_about_g_carried_by_steiner() {
    let scene = remus();
    let table = &scene.table;
    assert_eq!(
        table.inertia_about,
        eom::kinds::vehicle::InertiaAbout::Origin
    );
    let ([x, y, z], m, i) = (table.centre_of_gravity, table.mass, table.inertia);
    // x_G = y_G = 0: the products about G are zero too.
    assert_eq!((x, y), (0.0, 0.0));
    let about_g = [
        i[0][0] - m * (y * y + z * z),
        i[1][1] - m * (z * z + x * x),
        i[2][2] - m * (x * x + y * y),
    ];
    let written_about_g = |moments: [f64; 3]| {
        let text = edited(
            "inertia = [0.177, 3.45, 3.45]",
            &format!(
                "inertia = [{:?}, {:?}, {:?}]",
                moments[0], moments[1], moments[2]
            ),
        )
        .replacen("inertia_about = \"origin\"", "inertia_about = \"G\"", 1);
        parse(&text).unwrap()
    };
    let steiner = written_about_g(about_g);
    let mislabelled = written_about_g([i[0][0], i[1][1], i[2][2]]);
    // Rolling, pitching and yawing, with the fins turned.
    let mut state = scene.start().unwrap();
    state[1..6].copy_from_slice(&[0.1, -0.05, 0.4, -0.3, 0.2]);
    state[13] = 0.05;
    let input = [0.01, -0.02];
    let rates = |scene: &VehicleScene| Model::<f64, 15, 2>::rhs(&scene.model, &state, &input);
    let (given, carried, other) = (rates(&scene), rates(&steiner), rates(&mislabelled));
    let largest = |a: &[f64; 15], b: &[f64; 15]| {
        (a.iter().zip(b))
            .map(|(a, b)| (a - b).abs() / (1.0 + a.abs()))
            .fold(0.0, f64::max)
    };
    // The hoisted I_O = I_G + M z_G² rounds differently from the given I_O: a few ulps of the
    // rates (of order 10 here).
    let same = largest(&given, &carried);
    assert!(same < 1e-12, "{same:e}");
    // M z_G² = 0.0117 against I_xx − K_ṗ = 0.247: the roll acceleration moves by a few
    // percent (3.7 % at this state).
    let differs = (given[3] - other[3]).abs() / given[3].abs();
    println!(
        "ṗ about O {} against {} about G: {differs:.3}",
        given[3], other[3]
    );
    assert!(differs > 0.01, "{differs:e}");
}

/// `eom new vehicle` writes REMUS's body as its scene reads it: Prestero's moments, about O.
#[test]
fn the_template_s_remus_reads_its_moments_about_o_as_the_scene_does() {
    use eom::scene::reference::{SceneFamily, template};
    let scene = remus();
    let text = template(SceneFamily::Kind("vehicle"));
    let written = parse(&text).unwrap();
    assert_eq!(written.table.inertia, scene.table.inertia);
    assert_eq!(written.table.inertia_about, scene.table.inertia_about);
    assert_eq!(
        written.table.centre_of_gravity,
        scene.table.centre_of_gravity
    );
    assert_eq!(written.table.mass, scene.table.mass);
}

/// The quaternion of roll φ, pitch θ, heading ψ (4.57's rotation Rz(ψ)Ry(θ)Rx(φ)).
fn quaternion<
    T: Copy + std::ops::Mul<Output = T> + std::ops::Add<Output = T> + std::ops::Sub<Output = T>,
>(
    (c, s): ([T; 3], [T; 3]),
) -> [T; 4] {
    let ([cf, ct, cp], [sf, st, sp]) = (c, s);
    [
        cf * ct * cp + sf * st * sp,
        sf * ct * cp - cf * st * sp,
        cf * st * cp + sf * ct * sp,
        cf * ct * sp - sf * st * cp,
    ]
}

#[test]
fn the_linearised_vehicle_is_the_running_model_in_euler_angles() {
    use eom::kinds::vehicle::linear::VehiclePlant;
    use eom::linear::LinearPlant;
    use num_dual::{Dual64, DualNum};
    let scene = remus();
    let plant = VehiclePlant::new(&scene.table).unwrap();
    // Every velocity moving (some negative, for |x|), an attitude far from level, the fins
    // turned.
    let nu = [1.3, -0.15, 0.1, -0.2, 0.12, 0.25];
    let angles = [0.2, -0.3, 0.7];
    let fins = [0.05, -0.03];
    let mut state: Vec<f64> = nu.to_vec();
    state.extend([1.0, -2.0, 3.0]);
    state.extend(angles);
    let twin = plant.evaluate(&state, &fins).unwrap();
    // The running model at the same point, over dual numbers in each angle in turn: its rates
    // and their exact derivatives by φ, θ, ψ through the quaternion.
    for (column, _) in angles.iter().enumerate() {
        let half: [Dual64; 3] = std::array::from_fn(|i| {
            let a = Dual64::from(angles[i] / 2.0);
            if i == column {
                Dual64::new(a.re, 0.5)
            } else {
                a
            }
        });
        let q = quaternion((half.map(|a| a.cos()), half.map(|a| a.sin())));
        let mut x = [Dual64::from(0.0); 15];
        for i in 0..9 {
            x[i] = Dual64::from(state[i]);
        }
        x[9..13].copy_from_slice(&q);
        x[13] = Dual64::from(fins[0]);
        x[14] = Dual64::from(fins[1]);
        let rates = Model::<Dual64, 15, 2>::rhs(&scene.model, &x, &[Dual64::from(0.0); 2]);
        // ν̇ and the position's rates, and their derivatives by the angle: the same equations
        // in two attitudes' coordinates, to rounding (rates of order 10, 1e-12 relative).
        for (row, rate) in rates.iter().enumerate().take(9) {
            let (value, slope) = (rate.re, rate.eps);
            let scale = 1.0 + value.abs().max(slope.abs());
            assert!(
                (twin.rates[row] - value).abs() < 1e-12 * scale,
                "rate {row}: {} against {value}",
                twin.rates[row]
            );
            let derivative = twin.a[(row, 9 + column)];
            assert!(
                (derivative - slope).abs() < 1e-12 * scale,
                "∂(rate {row})/∂(angle {column}): {derivative} against {slope}"
            );
        }
    }
    // The velocity and fin columns are the running model's.
    let mut x = [0.0; 15];
    x[..9].copy_from_slice(&state[..9]);
    let half = angles.map(|a| a / 2.0);
    x[9..13].copy_from_slice(&quaternion((half.map(f64::cos), half.map(f64::sin))));
    x[13..].copy_from_slice(&fins);
    let model = Model::<f64, 15, 2>::state_jacobian(&scene.model, &x, &[0.0; 2]);
    for row in 0..9 {
        for column in 0..6 {
            let (twin, model) = (twin.a[(row, column)], model[row][column]);
            assert!(
                (twin - model).abs() < 1e-12 * (1.0 + model.abs()),
                "A[{row}][{column}]"
            );
        }
        for fin in 0..2 {
            let (twin, model) = (twin.b[(row, fin)], model[row][13 + fin]);
            assert!(
                (twin - model).abs() < 1e-12 * (1.0 + model.abs()),
                "B[{row}][{fin}]"
            );
        }
    }
}

fn with_linear(table: &str) -> VehicleScene {
    parse(&format!("{}\n[linear]\n{table}\n", scene_text())).unwrap()
}

#[test]
fn remus_at_cruise_is_unstable_open_loop_in_yaw_and_in_pitch() {
    use eom::kinds::vehicle::linear::linearise_vehicle;
    use eom::linear::Stability;
    let scene = remus();
    let linear = linearise_vehicle(&scene).unwrap();
    for m in &linear.modes {
        println!("{:?} {:?} {:?}", m.eigenvalue, m.dominant, m.name);
    }
    assert!(linear.equilibrium, "{:?}", linear.residual);
    assert_eq!(linear.set_aside_names(), ["x", "y", "z", "psi"]);
    assert_eq!(
        linear.reduced_names(),
        ["u", "v", "w", "p", "q", "r", "phi", "theta"]
    );
    assert_eq!(linear.input_names, ["dr", "ds"]);
    assert_eq!(linear.stability, Some(Stability::Unstable));
    let growing: Vec<Option<&str>> = (linear.modes.iter())
        .filter(|m| m.time_to_double_s.is_some())
        .map(|m| m.name)
        .collect();
    assert_eq!(growing, [Some("sway and yaw"), Some("heave and pitch")]);
    // Roll is the pendulum of z_G W − z_B B about O under the roll inertia about O and the
    // added mass, lightly damped (Prestero's roll damping Kpp p|p| has no linear part): a
    // period near 2π √((I_xx − K_ṗ)/(z_G W − z_B B)), with I_xx the scene's tensor about O.
    // The coupling to sway and yaw moves it by about 1 %, so 2 %; reading the tensor about G
    // instead would add M z_G² to I_xx and lengthen the period by 2.3 %.
    let roll = (linear.modes.iter())
        .find(|m| m.name == Some("roll"))
        .expect("a roll mode");
    let table = &scene.table;
    assert_eq!(
        table.inertia_about,
        eom::kinds::vehicle::InertiaAbout::Origin
    );
    let inertia = table.inertia[0][0] - table.added_mass["Kpdot"];
    let restoring =
        table.centre_of_gravity[2] * table.weight - table.centre_of_buoyancy[2] * table.buoyancy;
    let pendulum = std::f64::consts::TAU * (inertia / restoring).sqrt();
    let period = roll.period_s.unwrap();
    println!("roll period {period} s against the pendulum's {pendulum} s");
    assert!(
        (period / pendulum - 1.0).abs() < 0.02,
        "{period} against {pendulum}"
    );
    assert!(roll.damping_ratio.unwrap().abs() < 0.01);
    // The fins act where they should: the rudder on sway, roll and yaw, the stern planes on
    // surge, heave and pitch.
    let acts = |row: usize, fin: usize| linear.b[(row, fin)] != 0.0;
    assert!([1, 3, 5].iter().all(|&i| acts(i, 0)) && [0, 2, 4].iter().all(|&i| !acts(i, 0)));
    assert!([0, 2, 4].iter().all(|&i| acts(i, 1)) && [1, 3, 5].iter().all(|&i| !acts(i, 1)));
}

/// Every mode of REMUS at its cruise is named by the plane of motion it moves, its eigenvector
/// read in comparable units (docs/linear.md): in the roll oscillation φ̇ = p, so p read by the
/// mode's own time, p/|λ|, is φ's swing, and both are dominant (read raw, p in rad/s
/// outweighed φ by |λ| = 4.9/s, and φ was not among them); the heave-and-pitch root at
/// −2.19/s moves w as well as q and θ (w/U is the angle of attack it changes).
#[test]
fn remus_modes_are_named_by_the_planes_they_move() {
    use eom::kinds::vehicle::linear::linearise_vehicle;
    let linear = linearise_vehicle(&remus()).unwrap();
    let plane = |name: &str| -> &[&str] {
        match name {
            "surge" => &["u"],
            "sway and yaw" => &["v", "r"],
            "heave and pitch" => &["w", "q", "theta"],
            "roll" => &["p", "phi"],
            _ => &[],
        }
    };
    for m in &linear.modes {
        println!("{:?} {:?} {:?}", m.eigenvalue, m.dominant, m.name);
        let name = m.name.expect("every mode is named");
        for state in &m.dominant {
            assert!(plane(name).contains(&state.as_str()), "{name}: {state}");
        }
    }
    let roll = (linear.modes.iter())
        .find(|m| m.name == Some("roll"))
        .expect("a roll mode");
    assert_eq!(roll.dominant, ["p", "phi"]);
}

#[test]
fn a_vehicle_is_trimmed_for_the_variables_its_linear_table_names() {
    use eom::kinds::vehicle::linear::linearise_vehicle;
    let scene = remus();
    let start = scene.start().unwrap();
    let cruise_roll =
        eom::models::euler_angles(eom::models::Kinematics::Quaternion, &start[9..13])[0];
    // From 1 m/s level, the speed and roll the propeller holds: the cruise again.
    let trimmed = linearise_vehicle(&with_linear(
        "at = { u = 1.0, phi = 0.0 }\ntrim = [\"u\", \"phi\"]",
    ))
    .unwrap();
    let (values, steps) = trimmed.trimmed.clone().unwrap();
    println!("{values:?} in {steps}");
    assert!(trimmed.equilibrium);
    // Newton stops at rates below 1e-9 (1 + max|x|); ∂u̇/∂u ≈ 0.16 /s and ∂ṗ/∂φ ≈ 24 /s², so
    // u is within 2e-8 of the cruise and φ within 1e-10.
    assert!((values[0].1 - start[0]).abs() < 2e-8, "{values:?}");
    assert!((values[1].1 - cruise_roll).abs() < 1e-10, "{values:?}");
    // Pitched up 3° with the planes at 2°, the pitch and the planes that hold it level again,
    // by the fins' other name.
    let trimmed = linearise_vehicle(&with_linear(
        "at = { theta = 0.05, ds = 0.035 }\ntrim = [\"theta\", \"stern_planes\"]",
    ))
    .unwrap();
    let (values, _) = trimmed.trimmed.clone().unwrap();
    assert!(trimmed.equilibrium);
    assert!(
        values[0].1.abs() < 1e-9 && values[1].1.abs() < 1e-9,
        "{values:?}"
    );
    // The speed cannot be held by the planes alone.
    let error = linearise_vehicle(&with_linear("at = { u = 1.0 }\ntrim = [\"stern_planes\"]"))
        .unwrap_err()
        .to_string();
    assert!(
        error.contains("did not converge") && error.contains("stern_planes"),
        "{error}"
    );
    // A name the vehicle does not have is refused when the scene is read, naming the key.
    let error = parse(&format!("{}\n[linear]\ntrim = [\"delta\"]\n", scene_text())).unwrap_err();
    assert!(
        error.contains("linear.trim[0]") && error.contains("stern_planes"),
        "{error}"
    );
}

/// REMUS's scene with `autopilot` and `manoeuvres` in place of its own.
fn autopiloted(autopilot: &str, manoeuvres: &str) -> String {
    let text = scene_text();
    let own_autopilot = text.find("[autopilot]").unwrap();
    let integrator = text.find("[integrator]").unwrap();
    let own_manoeuvres = text.find("[[manoeuvre]]").unwrap();
    format!(
        "{}{autopilot}\n{}{manoeuvres}",
        &text[..own_autopilot],
        &text[integrator..own_manoeuvres]
    )
}

const AUTOPILOTS: &str = "[autopilot]\nsample_s = 0.1\n\n\
    [autopilot.heading]\nkp = 1.0\nki = 0.02\nkd = 1.0\n\n\
    [autopilot.depth]\nkp = 0.2\nmax_pitch_deg = 20.0\nkp_pitch = 2.0\nkd_pitch = 1.0\n";

const TURN_AND_DIVE: &str = "[[manoeuvre]]\nname = \"turn_and_dive\"\nkind = \"autopilot\"\n\
    times_s = [5.0]\nheading_deg = [30.0]\ndepth_m = [5.0]\nduration_s = 120.0\n";

#[test]
fn the_autopilots_take_remus_to_a_new_heading_and_depth_and_hold_them() {
    use eom::kinds::vehicle::summary::{
        SETTLING_BAND, SetpointFigures, largest_setpoint_difference,
    };
    let scene = parse(&at_fine_step(&autopiloted(AUTOPILOTS, TURN_AND_DIVE))).unwrap();
    let start = scene.start().unwrap();
    let m = &scene.manoeuvres[0];
    let run = run_with(&scene, &scene.model, m, start);
    let figures = SetpointFigures::of(&run);
    println!("{figures:#?}");
    assert_eq!(figures.len(), 2);
    let (heading, depth) = (figures[0], figures[1]);
    assert_eq!(
        (heading.what, heading.from, heading.to),
        ("heading", 0.0, 30.0)
    );
    assert_eq!((depth.what, depth.from, depth.to), ("depth", 0.0, 5.0));
    // Both settle within 2 % of the change and stay there to the end, 115 s later.
    for f in [heading, depth] {
        let settled = f.settling_time_s.expect("settles");
        assert!(settled > 0.0 && settled < 60.0, "{f:?}");
        assert!(
            f.steady_error.abs() <= SETTLING_BAND * (f.to - f.from).abs(),
            "{f:?}"
        );
        assert_eq!(f.at_s, 5.0);
        assert_eq!(f.until_s, 120.0);
    }
    // The last sample is the run's end: the heading and depth there are the state's.
    let last = run.tracked.last().unwrap();
    let end = run.ends.last().unwrap();
    assert_eq!(last.t, 120.0);
    assert_eq!(last.value.1, end.state[8]);
    // The samples are at k·T_s: 1200 of them and the end, each with its setpoints.
    assert_eq!(run.tracked.len(), 1201);
    assert!((run.tracked[1].t - 0.1).abs() < 1e-15);
    assert_eq!(run.tracked[49].setpoint, (Some(0.0), Some(0.0)));
    assert_eq!(run.tracked[50].setpoint, (Some(30.0), Some(5.0)));
    // Half the step, the same control law: the figures move by the integrator's error only
    // (RK4 at 0.01 s against 0.005 s over 120 s: below 1e-5 in degrees, m and s). A settling
    // time is a sample instant, so it either stays or moves by a sample (0.1 s).
    let refined = manoeuvre::run(
        &scene.model,
        &scene.fins,
        m,
        start,
        (&scene.stepper.refined(scene.every), scene.every),
        |_| true,
    )
    .unwrap();
    let difference = largest_setpoint_difference(&figures, &SetpointFigures::of(&refined));
    assert!(difference < 1e-5, "{difference:e}");
}

#[test]
fn the_autopilot_reads_the_rudder_s_sense_from_the_table() {
    // The same vehicle with its rudder's sign reversed (Yuudr, Nuudr negated: a positive
    // rudder now turns it to starboard) turns the same way under the same gains: the rudder's
    // commands are negated, and since negation is exact, the motion is the same to the bit.
    let text = autopiloted(AUTOPILOTS, TURN_AND_DIVE);
    let reversed = text
        .replace("Yuudr = 9.64", "Yuudr = -9.64")
        .replace("Nuudr = -6.15", "Nuudr = 6.15");
    assert_ne!(text, reversed);
    let runs: Vec<VehicleRun> = [text, reversed]
        .iter()
        .map(|text| {
            let scene = parse(text).unwrap();
            let start = scene.start().unwrap();
            run_with(&scene, &scene.model, &scene.manoeuvres[0], start)
        })
        .collect();
    let (a, b) = (runs[0].ends.last().unwrap(), runs[1].ends.last().unwrap());
    assert_eq!(a.state[..13], b.state[..13]);
    assert_eq!(a.state[13], -b.state[13], "the rudder's angle, negated");
    assert_eq!(runs[0].tracked, runs[1].tracked);
}

#[test]
fn bad_autopilots_are_refused_naming_the_key() {
    let error =
        |autopilot: &str, manoeuvre: &str| parse(&autopiloted(autopilot, manoeuvre)).unwrap_err();
    let cases = [
        (
            AUTOPILOTS.replace("kp = 1.0", "kp = -1.0"),
            TURN_AND_DIVE.to_owned(),
            "autopilot.heading.kp",
        ),
        (
            AUTOPILOTS.replace("sample_s = 0.1", "sample_s = 0.0"),
            TURN_AND_DIVE.to_owned(),
            "autopilot.sample_s",
        ),
        (
            AUTOPILOTS.replace("max_pitch_deg = 20.0", "max_pitch_deg = 95.0"),
            TURN_AND_DIVE.to_owned(),
            "autopilot.depth.max_pitch_deg",
        ),
        (
            AUTOPILOTS.replace("kd = 1.0", "kd = nan"),
            TURN_AND_DIVE.to_owned(),
            "autopilot.heading.kd",
        ),
        // A heading to hold without a heading autopilot.
        (
            AUTOPILOTS[..AUTOPILOTS.find("[autopilot.heading]").unwrap()].to_owned(),
            TURN_AND_DIVE.to_owned(),
            "manoeuvre[0].heading_deg",
        ),
        // The rudder commanded while the heading autopilot holds it; setpoints in fin steps.
        (
            AUTOPILOTS.to_owned(),
            TURN_AND_DIVE.replace("depth_m = [5.0]", "rudder_deg = [5.0]"),
            "manoeuvre[0].rudder_deg",
        ),
        (
            AUTOPILOTS.to_owned(),
            TURN_AND_DIVE.replace("kind = \"autopilot\"", "kind = \"fin_steps\""),
            "manoeuvre[0].heading_deg",
        ),
        (
            AUTOPILOTS.to_owned(),
            TURN_AND_DIVE.replace("depth_m = [5.0]", "depth_m = [5.0, 6.0]"),
            "manoeuvre[0].depth_m",
        ),
    ];
    for (autopilot, manoeuvre, key) in cases {
        let message = error(&autopilot, &manoeuvre);
        assert!(message.contains(key), "{key}: {message}");
    }
    // A rudder the table does not act with cannot steer: its autopilot is refused.
    let text = autopiloted(AUTOPILOTS, TURN_AND_DIVE)
        .replace("Yuudr = 9.64\n", "")
        .replace("Nuudr = -6.15\n", "");
    let message = parse(&text).unwrap_err();
    assert!(
        message.contains("autopilot.heading") && message.contains("∂ṙ/∂δ_r"),
        "{message}"
    );
}

const TRIALS: &str = "[[manoeuvre]]\nname = \"turning_circle\"\nkind = \"turning_circle\"\n\
    times_s = [5.0]\nrudder_deg = [10.0]\ndepth_m = [0.0]\nduration_s = 150.0\n\n\
    [[manoeuvre]]\nname = \"zigzag\"\nkind = \"zigzag\"\nplane = \"horizontal\"\nfin_deg = 10.0\n\
    switch_deg = 10.0\ntimes_s = [5.0]\ndepth_m = [0.0]\nduration_s = 30.0\n\n\
    [[manoeuvre]]\nname = \"zigzag_vertical\"\nkind = \"zigzag\"\nplane = \"vertical\"\n\
    fin_deg = 10.0\nswitch_deg = 10.0\ntimes_s = [5.0]\nheading_deg = [0.0]\nduration_s = 30.0\n";

#[test]
fn a_turning_circle_s_figures_are_read_at_its_events_and_once_it_has_settled() {
    use eom::kinds::vehicle::summary::trial_figures;
    use eom::kinds::vehicle::trial::{TrialFigures, Watch, largest_trial_difference};
    let scene = parse(&autopiloted(AUTOPILOTS, TRIALS)).unwrap();
    let start = scene.start().unwrap();
    let m = &scene.manoeuvres[0];
    let run = run_with(&scene, &scene.model, m, start);
    let progress = run.trial.as_ref().unwrap();
    // The events are where the heading has changed by 90° and 180° (REMUS turns to port under
    // a positive rudder), located to the rounding of the heading (1e-12 rad).
    let heading = |state: &[f64; 15]| manoeuvre::euler_angles(state)[2];
    let turned: Vec<f64> = (progress.events.iter())
        .map(|e| {
            assert!(matches!(e.watch, Watch::Turned(_)), "{:?}", e.watch);
            heading(&e.state).to_degrees()
        })
        .collect();
    assert_eq!(turned.len(), 2, "{turned:?}");
    assert!((turned[0] + 90.0).abs() < 1e-10, "{turned:?}");
    assert!((turned[1].abs() - 180.0).abs() < 1e-10, "{turned:?}");
    let Some(TrialFigures::TurningCircle(figures)) = trial_figures(&run, m) else {
        panic!("a turning circle's figures");
    };
    println!("{figures:#?}");
    // Settled under the depth autopilot: the steady diameter is 2 V_h/|ψ̇| at the end.
    let steady = figures.steady_diameter_m.expect("settled");
    let end = run.ends.last().unwrap().state;
    let (psi_dot, _) = eom::kinds::vehicle::trial::heading_and_pitch_rates(&end);
    let v_h = eom::kinds::vehicle::trial::horizontal_speed(&end);
    assert_eq!(steady, 2.0 * v_h / psi_dot.abs());
    // The tactical diameter, read at 180°, is near the steady one (a small vehicle settles
    // within the first half turn), and the advance at 90° is more than half of it.
    let tactical = figures.tactical_diameter_m.unwrap();
    assert!(
        (tactical / steady - 1.0).abs() < 0.05,
        "{tactical} against {steady}"
    );
    assert!(figures.advance_m.unwrap() > 0.5 * tactical);
    assert!(
        figures.depth_change_m.is_some_and(|z| z.abs() < 0.1),
        "the depth is held"
    );
    // Half the step: the figures move by the integrator's error, within the targets `eom
    // tradeoff` chose the scene's RK4 at 0.05 s for (0.01 m, 0.001°): 5.9e-5 measured.
    let refined = manoeuvre::run(
        &scene.model,
        &scene.fins,
        m,
        start,
        (&scene.stepper.refined(scene.every), scene.every),
        |_| true,
    )
    .unwrap();
    let a = trial_figures(&run, m).unwrap();
    let b = trial_figures(&refined, m).unwrap();
    let difference = largest_trial_difference(&a, &b);
    assert!(difference < 1e-3, "{difference:e}");
    // Without the depth autopilot REMUS's pitch does not settle in the turn (its heave and
    // pitch are unstable at the cruise): no steady figures, and the reason.
    let free = parse(&autopiloted(
        AUTOPILOTS,
        &TRIALS.replacen("depth_m = [0.0]\n", "", 1),
    ))
    .unwrap();
    let m = &free.manoeuvres[0];
    let run = run_with(&free, &free.model, m, start);
    let Some(TrialFigures::TurningCircle(figures)) = trial_figures(&run, m) else {
        panic!("a turning circle's figures");
    };
    assert_eq!(figures.steady_diameter_m, None);
    let why = figures.not_steady_because.unwrap();
    assert!(why.contains("has not settled"), "{why}");
}

#[test]
fn a_zigzag_switches_at_its_angle_and_reads_each_overshoot_where_the_rate_is_zero() {
    use eom::kinds::vehicle::summary::trial_figures;
    use eom::kinds::vehicle::trial::{TrialFigures, Watch, heading_and_pitch_rates};
    let scene = parse(&autopiloted(AUTOPILOTS, TRIALS)).unwrap();
    let start = scene.start().unwrap();
    for (m, vertical) in [(&scene.manoeuvres[1], false), (&scene.manoeuvres[2], true)] {
        let run = run_with(&scene, &scene.model, m, start);
        let progress = run.trial.as_ref().unwrap();
        let angle = |state: &[f64; 15]| {
            let [_, theta, psi] = manoeuvre::euler_angles(state);
            if vertical { theta } else { psi }
        };
        let (mut switches, mut zeros) = (0, 0);
        for event in &progress.events {
            match event.watch {
                Watch::Switch(at) => {
                    switches += 1;
                    assert!((angle(&event.state) - at).abs() < 1e-12, "{event:?}");
                    assert_eq!(at.abs(), 10f64.to_radians());
                }
                Watch::RateZero => {
                    zeros += 1;
                    let (psi_dot, theta_dot) = heading_and_pitch_rates(&event.state);
                    let rate = if vertical { theta_dot } else { psi_dot };
                    assert!(rate.abs() < 1e-12, "{rate:e}");
                }
                Watch::Turned(_) => panic!("a zig-zag watches no turn"),
            }
        }
        assert!(
            switches >= 4 && zeros >= 3,
            "{switches} switches, {zeros} zeros"
        );
        let Some(TrialFigures::ZigZag(figures)) = trial_figures(&run, m) else {
            panic!("a zig-zag's figures");
        };
        println!("{figures:?}");
        // Each overshoot is past the switch angle, and the fin switched sides each time.
        assert!(figures.overshoots_deg.iter().all(|&o| o > 0.0 && o < 20.0));
        assert_eq!(figures.switches_s.len(), switches);
    }
}

#[test]
fn bad_trials_are_refused_naming_the_key() {
    let zigzag = "[[manoeuvre]]\nkind = \"zigzag\"\nplane = \"horizontal\"\nfin_deg = 10.0\n\
        switch_deg = 10.0\ntimes_s = [5.0]\nduration_s = 30.0\n";
    let circle = "[[manoeuvre]]\nkind = \"turning_circle\"\ntimes_s = [5.0]\n\
        rudder_deg = [10.0]\nduration_s = 30.0\n";
    let cases = [
        (
            zigzag.replace("fin_deg = 10.0\n", ""),
            "manoeuvre[0].fin_deg",
        ),
        (
            zigzag.replace("switch_deg = 10.0", "switch_deg = -1.0"),
            "manoeuvre[0].switch_deg",
        ),
        (
            zigzag.replace("horizontal", "diagonal"),
            "manoeuvre[0].plane",
        ),
        (
            zigzag.replace("times_s = [5.0]", "times_s = [5.0, 6.0]"),
            "manoeuvre[0].times_s",
        ),
        (
            zigzag.replace("times_s = [5.0]", "times_s = [5.0]\nheading_deg = [0.0]"),
            "manoeuvre[0].heading_deg",
        ),
        (
            zigzag.replace("times_s = [5.0]", "times_s = [5.0]\nrudder_deg = [1.0]"),
            "manoeuvre[0].rudder_deg",
        ),
        (
            circle.replace("rudder_deg = [10.0]", "rudder_deg = [10.0, 0.0]"),
            "manoeuvre[0].rudder_deg",
        ),
        (
            circle.replace("times_s = [5.0]", "times_s = [5.0]\nheading_deg = [0.0]"),
            "manoeuvre[0].heading_deg",
        ),
        (
            circle.replace("times_s = [5.0]", "times_s = [5.0]\nfin_deg = 3.0"),
            "manoeuvre[0].fin_deg",
        ),
    ];
    for (manoeuvre, key) in cases {
        let message = parse(&autopiloted(AUTOPILOTS, &manoeuvre)).unwrap_err();
        assert!(message.contains(key), "{key}: {message}");
    }
}

#[test]
fn a_fin_s_rate_limit_is_an_event_of_the_run() {
    // The rudder with a lag of 0.1 s and a rate limit of 5°/s: each step of its command starts
    // at the limit and leaves it where (δ_c − δ)/τ falls to 5°/s, a kink in δ̇. Located as an
    // event, RK4 keeps its order across it: the figures' change from h = 0.02 to 0.01 s is
    // more than 8 times that from 0.01 to 0.005 s (a kink stepped across would leave a
    // first-order error, a ratio near 2).
    let text = scene_text().replace(
        "[rudder]\nmax_deg = 15.0",
        "[rudder]\nmax_deg = 15.0\nmax_rate_deg_s = 5.0\ntime_constant_s = 0.1",
    );
    let scene = parse(&text).unwrap();
    let start = scene.start().unwrap();
    let figures = |step: f64| {
        let mut stepper = scene.stepper.clone();
        stepper.step = Some(step);
        let run = manoeuvre::run(
            &scene.model,
            &scene.fins,
            &scene.manoeuvres[0],
            start,
            (&stepper, scene.every),
            |_| true,
        )
        .unwrap();
        StepFigures::of(&run)
    };
    let (coarse, middle, fine) = (figures(0.02), figures(0.01), figures(0.005));
    let (d1, d2) = (
        largest_difference(&coarse, &middle),
        largest_difference(&middle, &fine),
    );
    println!("{d1:e} {d2:e} ratio {}", d1 / d2);
    assert!(d1 / d2 > 8.0, "{d1:e} / {d2:e}");
    assert!(d2 < 1e-6, "{d2:e}");
}

#[test]
fn a_count_in_a_message_takes_its_noun_s_number() {
    let one = parse(&edited(
        "rudder_deg = [4.0, -4.0, 0.0]",
        "rudder_deg = [4.0]",
    ))
    .unwrap_err();
    assert!(one.contains("1 value for 3 times"), "{one}");
}

/// REMUS with `payload` kg more mass and weight (W = M · 9.81 N, to 0.1 N), G at `x_g` m.
fn with_payload(payload: f64, x_g: f64) -> String {
    let mass = 30.48 + payload;
    let weight = (mass * 9.81 * 10.0).round() / 10.0;
    edited("mass = 30.48 ", &format!("mass = {mass} "))
        .replacen("weight = 299.0 ", &format!("weight = {weight} "), 1)
        .replacen(
            "centre_of_gravity = [0.0, 0.0, 0.0196]",
            &format!("centre_of_gravity = [{x_g}, 0.0, 0.0196]"),
            1,
        )
}

#[test]
fn a_fin_command_beyond_its_stop_is_refused_naming_both_keys() {
    // REMUS's fins stop at 15°: a command beyond would run at 15° under a 30° label.
    let cases = [
        (
            "rudder_deg = [4.0, -4.0, 0.0]",
            "rudder_deg = [4.0, -30.0, 0.0]",
            "manoeuvre[0].rudder_deg[1]",
            "rudder.max_deg",
        ),
        (
            "stern_planes_deg = [4.0, -4.0, 0.0]",
            "stern_planes_deg = [16.0, -4.0, 0.0]",
            "manoeuvre[1].stern_planes_deg[0]",
            "stern_planes.max_deg",
        ),
        (
            "rudder_deg = [10.0]",
            "rudder_deg = [30.0]",
            "manoeuvre[3].rudder_deg[0]",
            "rudder.max_deg",
        ),
        (
            "plane = \"vertical\"\nfin_deg = 10.0",
            "plane = \"vertical\"\nfin_deg = 30.0",
            "manoeuvre[5].fin_deg",
            "stern_planes.max_deg",
        ),
    ];
    for (from, to, command, stop) in cases {
        let error = parse(&edited(from, to)).unwrap_err();
        println!("{error}");
        assert!(error.contains(&format!("`{command}`")), "{to}: {error}");
        assert!(error.contains(&format!("`{stop}` = 15°")), "{to}: {error}");
    }
    // At the stop itself, the command runs as labelled.
    assert!(parse(&edited("rudder_deg = [10.0]", "rudder_deg = [15.0]")).is_ok());
}

#[test]
fn a_thrust_not_ahead_and_a_mass_against_its_weight_are_refused_by_key() {
    let astern = parse(&edited("thrust = 3.86", "thrust = -3.86")).unwrap_err();
    assert!(
        astern.contains("`propeller.thrust`") && astern.contains("astern"),
        "{astern}"
    );
    let none = parse(&edited("thrust = 3.86", "thrust = 0.0")).unwrap_err();
    assert!(
        none.contains("`propeller.thrust`") && none.contains("zero thrust"),
        "{none}"
    );
    let start = scene_text().find("[propeller]").unwrap();
    let end = scene_text().find("# The fins' stops").unwrap();
    let mut without = scene_text();
    without.replace_range(start..end, "");
    let missing = parse(&without).unwrap_err();
    assert!(missing.contains("`propeller`"), "{missing}");
    // 6.5 kg of payload in the weight and not in the mass: W/M = 11.9 m/s².
    let heavier = parse(&edited("weight = 299.0 ", "weight = 362.8 ")).unwrap_err();
    println!("{heavier}");
    assert!(
        heavier.contains("`body.mass`") && heavier.contains("`body.weight` = 362.8 N"),
        "{heavier}"
    );
    // Both in: W/M = 9.81 m/s² (REMUS's own 299 N and 30.48 kg give 9.8097, to the rounding
    // of the numbers as written; so do the standard 9.80665 and a mass of three digits).
    let both = parse(&with_payload(6.5, 0.0)).err();
    assert!(both.is_none_or(|e| !e.contains("body.mass")));
    for (mass, weight) in [("30.49", "299.0"), ("30.5", "299.0"), ("31", "299.0")] {
        let text = edited("mass = 30.48 ", &format!("mass = {mass} ")).replacen(
            "weight = 299.0 ",
            &format!("weight = {weight} "),
            1,
        );
        assert!(parse(&text).is_ok(), "{mass} kg, {weight} N");
    }
}

#[test]
fn a_trim_that_newton_does_not_find_names_the_state_whose_rate_is_left() {
    // 1 kg of payload at O: W − B = 9.81 N, and Newton from the cruise does not converge in
    // its steps. The message names the rate left, not only its size.
    let error = parse(&with_payload(1.0, 0.0)).unwrap_err();
    println!("{error}");
    assert!(error.contains("no trim: "), "{error}");
    assert!(
        error.contains("the largest rate left is d") && error.contains("/dt = "),
        "{error}"
    );
    assert_eq!(error.matches("no trim").count(), 1, "said once: {error}");
}

#[test]
fn a_heavy_remus_has_no_trim_ahead_and_is_refused_by_its_body() {
    // 6.5 kg of payload aft: the only steady motion Newton finds from the cruise backs down
    // as it sinks (u = −0.28 m/s), outside a table identified ahead.
    let error = parse(&with_payload(6.5, -0.01)).unwrap_err();
    println!("{error}");
    assert!(
        error.contains("`body`") && error.contains("no trim ahead"),
        "{error}"
    );
    assert!(
        error.contains("body.weight − body.buoyancy = 63.8 N"),
        "{error}"
    );
}

#[test]
fn a_vehicle_out_of_trim_starts_each_manoeuvre_steady_from_its_trim() {
    use eom::kinds::vehicle::linear::VehiclePlant;
    use eom::linear::{EQUILIBRIUM_TOLERANCE, LinearPlant};
    // 0.5 kg of payload 1 cm aft of the centre of buoyancy: level, REMUS would pitch up by
    // tens of degrees before its first command.
    let scene = parse(&with_payload(0.5, -0.01)).unwrap();
    let trim = scene.trim;
    println!("{trim:?}");
    assert!(trim.whole_state_steps.is_some());
    let [_, pitch, _] = manoeuvre::euler_angles(&trim.state);
    assert!(pitch.to_degrees() > 30.0, "{}°", pitch.to_degrees());
    let plant = VehiclePlant::new(&scene.table).unwrap();
    let twin = |state: &[f64; 15]| {
        let mut x = state[..9].to_vec();
        x.extend(manoeuvre::euler_angles(state));
        x
    };
    for m in &scene.manoeuvres {
        let held = m.held();
        // The rates the trim holds at zero: ν̇, φ̇, θ̇ (the helix's ψ̇ and ż are steady), and
        // ψ̇ or ż where an autopilot holds the heading or the depth; each to the trim's
        // tolerance, 1e-9 (1 + max |x|).
        let rates = plant
            .evaluate(&twin(&m.trim.state), &m.trim.state[13..])
            .unwrap()
            .rates;
        let mut held_rates = vec![0, 1, 2, 3, 4, 5, 9, 10];
        held_rates.extend(held.heading.then_some(11));
        held_rates.extend(held.depth.then_some(8));
        let scale = 1.0 + m.trim.state.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        for i in held_rates {
            assert!(
                rates[i].abs() <= EQUILIBRIUM_TOLERANCE * scale,
                "{}: rate {i} = {:e}",
                m.name,
                rates[i]
            );
        }
        // Until its first command, the run stays in the trim: velocities, rates, roll and
        // pitch within 1e-9 of it, and the depth on the trim's ż, however far it sinks or
        // turns meanwhile (Newton's last step leaves rates far below its 1e-9 tolerance:
        // measured, 2e-12 moved in 10 s, and 1e-12 m).
        let run = run_with(&scene, &scene.model, m, m.trim.state);
        let before = run.ends[0];
        let angles = |s: &[f64; 15]| manoeuvre::euler_angles(s);
        let velocities = (0..6).map(|i| before.state[i] - m.trim.state[i]);
        let tilt = (0..2).map(|i| angles(&before.state)[i] - angles(&m.trim.state)[i]);
        let moved = velocities.chain(tilt).fold(0.0f64, |a, x| a.max(x.abs()));
        let sunk = before.state[8] - m.trim.depth_rate() * before.t;
        println!(
            "{}: in {} s, ν, φ, θ moved by {moved:e}, z by {sunk:e} m from the trim's",
            m.name, before.t
        );
        assert!(moved < 1e-9, "{}: {moved:e}", m.name);
        assert!(sunk.abs() < 1e-9, "{}: {sunk:e} m off the trim's ż", m.name);
    }
    // The autopilots hold the heading (and the depth) of the manoeuvre that asks them to
    // from the start, the fin each works trimmed: no turn, and no depth change.
    let turn_and_dive = &scene.manoeuvres[2];
    assert!(turn_and_dive.held().heading && turn_and_dive.held().depth);
    let trim = &turn_and_dive.trim;
    assert!(trim.state[13] != 0.0 && trim.state[14] != 0.0, "{trim:?}");
    assert_eq!(
        trim.trimmed(),
        ["u", "v", "w", "p", "q", "r", "phi", "theta", "dr", "ds"]
    );
}

#[test]
fn a_vertical_zigzag_switches_about_the_trim_s_pitch() {
    use eom::kinds::vehicle::trial::Watch;
    // G 1 cm aft: REMUS trims 26.9° nose up with its heading held, and zig-zags about that.
    let scene = parse(&with_payload(0.0, -0.01)).unwrap();
    let m = &scene.manoeuvres[5];
    let trim_pitch = manoeuvre::euler_angles(&m.trim.state)[1];
    assert!(trim_pitch.to_degrees() > 20.0);
    let run = run_with(&scene, &scene.model, m, m.trim.state);
    let progress = run.trial.as_ref().unwrap();
    let mut switches = 0;
    for event in &progress.events {
        if let Watch::Switch(at) = event.watch {
            switches += 1;
            let pitch = manoeuvre::euler_angles(&event.state)[1];
            assert!((pitch - trim_pitch - at).abs() < 1e-12, "{event:?}");
        }
    }
    assert!(switches >= 4, "{switches}");
}

/// REMUS with its turning circle alone (10° of rudder from 5 s, its depth held), its rows every
/// 0.01 s, and `integrator.stop_when = stop` where it is given.
fn remus_turn(stop: Option<&str>) -> Result<VehicleScene, String> {
    let text = scene_text();
    let mut text =
        text[..text.find("[[manoeuvre]]").unwrap()].replace("every = 0.1", "every = 0.01");
    if let Some(stop) = stop {
        text = text.replace(
            "[integrator]\n",
            &format!("[integrator]\nstop_when = \"{stop}\"\n"),
        );
    }
    text.push_str(
        "[[manoeuvre]]\nname = \"turn\"\nkind = \"turning_circle\"\ntimes_s = [5.0]\n\
         rudder_deg = [10.0]\ndepth_m = [0.0]\nduration_s = 150.0\n",
    );
    parse(&text)
}

/// Runs a scene's one manoeuvre to its end or to the scene's stop condition: its rows (t, then
/// the trajectory's columns) and the run.
fn run_rows(scene: &VehicleScene) -> (Vec<(f64, [f64; 20])>, VehicleRun) {
    let m = &scene.manoeuvres[0];
    let mut rows = Vec::new();
    let done = manoeuvre::run_until(
        &scene.model,
        &scene.fins,
        m,
        (m.trim.state, scene.stop.as_ref()),
        (&scene.stepper, scene.every),
        |s| {
            rows.push((s.t, s.row()));
            true
        },
    )
    .unwrap();
    (rows, done)
}

/// `integrator.stop_when` on the heading ends REMUS's turning circle where ψ first passes 2.5
/// rad (143°, after the 90° event and before the 180° one): the rows are the whole run's up to
/// there, the last where the condition first holds; the advance and transfer, read at 90°, and
/// the step before the execute are the whole run's; the tactical diameter and every figure
/// read at the end are not given, the step the stop cut short neither, and a note says so.
#[test]
fn a_stop_condition_ends_a_vehicles_turn_where_it_first_holds() {
    use eom::kinds::vehicle::summary::trial_figures;
    use eom::kinds::vehicle::trial::TrialFigures;
    let whole = remus_turn(None).unwrap();
    let (all_rows, all) = run_rows(&whole);
    // ψ is column 19 of a row after t; the turn's side decides the condition's sign.
    let sign = all_rows.iter().map(|(_, r)| r[19]).sum::<f64>().signum();
    let stop = if sign > 0.0 {
        "psi > 2.5"
    } else {
        "psi < -2.5"
    };
    let holds = |psi: f64| sign * psi > 2.5;
    let stopped = remus_turn(Some(stop)).unwrap();
    let (rows, cut) = run_rows(&stopped);
    let (last, before) = (&rows[rows.len() - 1], &rows[rows.len() - 2]);
    assert_eq!((all.stopped_at, cut.stopped_at), (None, Some(last.0)));
    assert!(holds(last.1[19]) && !holds(before.1[19]), "{stop}");
    assert_eq!(rows[..rows.len() - 1], all_rows[..rows.len() - 1]);
    // The crossing interpolated between the whole run's rows 0.01 s apart: ψ̈h²/8 over ψ̇ (ψ̈
    // below 1e-2 rad/s², ψ̇ near 0.2 rad/s at ψ = ±2.5 in this turn) is below 1e-6 s; the
    // located time is on the same RK4 solution.
    let first = all_rows.iter().position(|(_, r)| holds(r[19])).unwrap();
    let ((ta, a), (tb, b)) = (&all_rows[first - 1], &all_rows[first]);
    let crossing = ta + (sign * 2.5 - a[19]) / (b[19] - a[19]) * (tb - ta);
    assert!(
        (last.0 - crossing).abs() < 1e-6,
        "stopped at {} against {crossing}",
        last.0
    );
    // The step before the execute ended at 5 s, before the stop: the whole run's exactly; the
    // turn's step did not end.
    let (steps, all_steps) = (StepFigures::of(&cut), StepFigures::of(&all));
    assert_eq!((steps.len(), all_steps.len()), (1, 2));
    assert_eq!(largest_difference(&steps, &all_steps[..1]), 0.0);
    let m = &whole.manoeuvres[0];
    let (Some(TrialFigures::TurningCircle(f)), Some(TrialFigures::TurningCircle(g))) =
        (trial_figures(&cut, m), trial_figures(&all, m))
    else {
        panic!("a turning circle's figures");
    };
    assert!(f.advance_m.is_some() && f.transfer_m.is_some());
    assert_eq!((f.advance_m, f.transfer_m), (g.advance_m, g.transfer_m));
    let at_end = [
        f.tactical_diameter_m,
        f.steady_diameter_m,
        f.speed_m_s,
        f.heading_rate_deg_s,
        f.roll_deg,
        f.pitch_deg,
        f.depth_change_m,
    ];
    assert_eq!(at_end, [None; 7]);
    assert!(g.tactical_diameter_m.is_some() && g.speed_m_s.is_some());
    let why = f.not_steady_because.unwrap();
    assert!(why.contains("integrator.stop_when"), "{why}");
}

/// The scene's run says the condition and where the manoeuvre stopped, every digit, and its
/// note (in summary.json and in the shared figures) names what the stop left out.
#[test]
fn a_vehicles_summary_says_where_the_stop_condition_ended_a_manoeuvre() {
    use eom::run::record::Discard;
    use eom::run::scene::run as run_scene;
    let scene = remus_turn(Some("t > 60")).unwrap();
    let finished = run_scene(&scene, "turn", &mut Discard).unwrap();
    let summary = &finished.summary;
    let turn = &summary.section.manoeuvre["turn"];
    // The first time above 60 s, located to adjacent doubles or at an autopilot's sample
    // k·T_s, whose product rounds a few ulps of 60 away from it.
    let at = turn.stopped_at.flatten().unwrap();
    assert!(at > 60.0 && at - 60.0 < 1e-12, "{at}");
    let json = serde_json::to_value(summary).unwrap();
    assert_eq!(json["stop_when"], "t > 60");
    assert_eq!(json["manoeuvre"]["turn"]["stopped_at"], at);
    let note = &turn.notes[0];
    for expected in [
        "stopped at t = 60.0 s where `t > 60` first held",
        "before: the step of the commands from 5 s ended",
        "the turning circle gave steady_diameter_m, speed_m_s",
    ] {
        assert!(note.contains(expected), "{expected}: {note}");
    }
    // The tactical diameter was read at 180°, before the stop.
    assert!(!note.contains("tactical_diameter_m"), "{note}");
    assert!(json["manoeuvre"]["turn"]["trial"]["tactical_diameter_m"].is_number());
    assert_eq!(summary.runs[0].notes, turn.notes);
    assert!(json["manoeuvre"]["turn"]["trial"]["speed_m_s"].is_null());
}

/// A stop condition is read against a vehicle's row, and refused naming the key where it names
/// something else, holds where a manoeuvre starts or is not a comparison.
#[test]
fn a_vehicles_bad_stop_condition_is_refused_naming_the_key() {
    let cases = [
        (
            "depth > 1",
            "unknown name `depth`; one of t, u, v, w, p, q, r, x, y, z, q0",
        ),
        (
            "t >= 0",
            "`t >= 0` holds at the start of manoeuvre `turn` (0), so the run would end before \
             it begins",
        ),
        ("z >", "`` is not one number"),
    ];
    for (stop, expected) in cases {
        let error = remus_turn(Some(stop)).unwrap_err();
        assert!(error.contains("integrator.stop_when"), "{stop}: {error}");
        assert!(error.contains(expected), "{stop}: {error}");
    }
}
