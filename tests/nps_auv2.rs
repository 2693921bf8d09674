//! The NPS AUV II at run time (`scenes/nps_auv2.toml`): Healey & Lienard's (1993) table in the
//! prime system as Fossen's MSS `npsauv.m` gives it, against a transcription of that file's
//! numbers (its tensor of inertia about O, its propeller law and terms in ε, its cross-flow
//! strips); the cruise against the propeller law's closed form, ε = 0 there; the Jacobian's
//! chain rule through ε against dual numbers; a small rudder step against the closed form of
//! the linear sway–yaw equations; the large turn converged and mirrored, and what the terms in
//! ε and the cross-flow drag change in it; and bad tables, laws and strips refused by key.

use eom::Model;
use eom::kinds::vehicle::manoeuvre::{self, VehicleManoeuvre, VehicleRun};
use eom::kinds::vehicle::summary::{CruiseSummary, StepFigures, largest_difference};
use eom::kinds::vehicle::trim::cruise;
use eom::kinds::vehicle::{InertiaAbout, VehicleModel, VehicleScene};
use eom::scene::AnyScene;
use num_dual::Dual64;
use std::path::Path;

const SCENE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/nps_auv2.toml");

/// npsauv.m's hydrodynamic derivatives, prime, as that file writes them (its names).
const SOURCE: [(&str, f64); 93] = [
    ("Xpp", 7.0e-3),
    ("Xqq", -1.5e-2),
    ("Xrr", 4.0e-3),
    ("Xpr", 7.5e-4),
    ("Xudot", -7.6e-3),
    ("Xwq", -2.0e-1),
    ("Xvp", -3.0e-3),
    ("Xvr", 2.0e-2),
    ("Xqds", 2.5e-2),
    ("Xqdb2", -1.3e-3),
    ("Xrdr", -1.0e-3),
    ("Xvv", 5.3e-2),
    ("Xww", 1.7e-1),
    ("Xvdr", 1.7e-3),
    ("Xwds", 4.6e-2),
    ("Xwdb2", 0.5e-2),
    ("Xdsds", -1.0e-2),
    ("Xdrdr", -1.0e-2),
    ("Xqdsn", 2.0e-3),
    ("Xwdsn", 3.5e-3),
    ("Xdsdsn", -1.6e-3),
    ("Ypdot", 1.2e-4),
    ("Yrdot", 1.2e-3),
    ("Ypq", 4.0e-3),
    ("Yqr", -6.5e-3),
    ("Yvdot", -5.5e-2),
    ("Yp", 3.0e-3),
    ("Yr", 3.0e-2),
    ("Yvq", 2.4e-2),
    ("Ywp", 2.3e-1),
    ("Ywr", -1.9e-2),
    ("Yv", -1.0e-1),
    ("Yvw", 6.8e-2),
    ("Ydr", 2.7e-2),
    ("Zqdot", -6.8e-3),
    ("Zpp", 1.3e-4),
    ("Zpr", 6.7e-3),
    ("Zrr", -7.4e-3),
    ("Zwdot", -2.4e-1),
    ("Zq", -1.4e-1),
    ("Zvp", -4.8e-2),
    ("Zvr", 4.5e-2),
    ("Zw", -3.0e-1),
    ("Zvv", -6.8e-2),
    ("Zds", -7.3e-2),
    ("Zdb2", -1.3e-2),
    ("Zqn", -2.9e-3),
    ("Zwn", -5.1e-3),
    ("Zdsn", -1.0e-2),
    ("Kpdot", -1.0e-3),
    ("Krdot", -3.4e-5),
    ("Kpq", -6.9e-5),
    ("Kqr", 1.7e-2),
    ("Kvdot", 1.2e-4),
    ("Kp", -1.1e-2),
    ("Kr", -8.4e-4),
    ("Kvq", -5.1e-3),
    ("Kwp", -1.3e-4),
    ("Kwr", 1.4e-2),
    ("Kv", 3.1e-3),
    ("Kvw", -1.9e-1),
    ("Kdb2", 0.0),
    ("Kpn", -5.7e-4),
    ("Kprop", 0.0),
    ("Mqdot", -1.7e-2),
    ("Mpp", 5.3e-5),
    ("Mpr", 5.0e-3),
    ("Mrr", 2.9e-3),
    ("Mwdot", -6.8e-3),
    ("Muq", -6.8e-2),
    ("Mvp", 1.2e-3),
    ("Mvr", 1.7e-2),
    ("Muw", 1.0e-1),
    ("Mvv", -2.6e-2),
    ("Mds", -4.1e-2),
    ("Mdb2", 3.5e-3),
    ("Mqn", -1.6e-3),
    ("Mwn", -2.9e-3),
    ("Mdsn", -5.2e-3),
    ("Npdot", -3.4e-5),
    ("Nrdot", -3.4e-3),
    ("Npq", -2.1e-2),
    ("Nqr", 2.7e-3),
    ("Nvdot", 1.2e-3),
    ("Np", -8.4e-4),
    ("Nr", -1.6e-2),
    ("Nvq", -1.0e-2),
    ("Nwp", -1.7e-2),
    ("Nwr", 7.4e-3),
    ("Nv", -7.4e-3),
    ("Nvw", -2.7e-2),
    ("Ndr", -1.3e-2),
    ("Nprop", 0.0),
];

/// The source's terms the scene leaves out, each said in its header: the bow planes' (held
/// at zero), its zero Kprop and Nprop.
const LEFT_OUT: [&str; 7] = ["Xqdb2", "Xwdb2", "Zdb2", "Kdb2", "Mdb2", "Kprop", "Nprop"];

/// The source's terms in ε, whose factor `n` the scene reads as the propeller law's ε.
const IN_EPSILON: [&str; 10] = [
    "Xqdsn", "Xwdsn", "Xdsdsn", "Zqn", "Zwn", "Zdsn", "Kpn", "Mqn", "Mwn", "Mdsn",
];

/// npsauv.m's scales, body and propeller law.
const RHO: f64 = 1025.0;
const LENGTH: f64 = 5.3;
const WEIGHT: f64 = 53400.0;
const G: f64 = 9.81;
const CD0: f64 = 0.00385;
/// npsauv.m's moments and products of inertia (Fossen's sign: Ixy = ∫xy dm), kg m².
const MOMENTS: [f64; 3] = [2038.0, 13587.0, 13587.0];
const PRODUCTS: [f64; 3] = [-13.58, -13.58, -13.58];
/// The setting: SIMnpsauv.m's n_d, rpm.
const RPM: f64 = 1300.0;
/// The law's prop = 0.012 n/u and C_t = 0.008 L² prop|prop|/2.
const ADVANCE: f64 = 0.012;
const CT: f64 = 0.008;

fn scene_text() -> String {
    std::fs::read_to_string(SCENE).unwrap()
}

fn parse(text: &str) -> Result<VehicleScene, String> {
    match AnyScene::parse(text, "nps_auv2.toml", Path::new(".")) {
        Ok(scene) => (scene.downcast::<VehicleScene>())
            .map(|scene| *scene)
            .ok_or_else(|| "not read as a vehicle".into()),
        Err(e) => Err(e.to_string()),
    }
}

fn nps() -> VehicleScene {
    parse(&scene_text()).unwrap()
}

/// The scene integrated by RK4 at 0.02 s (a fifth of the fins' lag, 0.3 % of the roll period),
/// where its figures move by less than 1e-6 at half the step: for the checks of the model
/// against closed forms, finer than the scene's own setting (DOPRI5 at 1e-5, what `eom
/// tradeoff` recommends for its figures' targets of 0.001° and 0.01 m).
fn nps_converged() -> VehicleScene {
    let text = scene_text();
    let (before, after) = text.split_once("[integrator]").unwrap();
    let (_, after) = after.split_once("[output]").unwrap();
    let text = format!("{before}[integrator]\nmethod = \"rk4\"\nstep = 0.02\n\n[output]{after}");
    parse(&text).unwrap()
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

/// The propeller's shaft speed at the setting, rad/s.
fn shaft_speed() -> f64 {
    RPM / 60.0 * 2.0 * std::f64::consts::PI
}

#[test]
fn the_nps_scene_holds_npsauv_m_s_numbers_bit_for_bit() {
    let scene = nps();
    let table = &scene.table;
    let text = scene_text();
    let mut held = 0;
    for (name, value) in SOURCE {
        if LEFT_OUT.contains(&name) {
            assert!(text.contains(name), "{name} left out but not said");
            assert!(!table.coefficients.contains_key(name), "{name}");
            continue;
        }
        let given = (table.added_mass.get(name))
            .or_else(|| table.coefficients.get(name))
            .unwrap_or_else(|| panic!("{name} missing"));
        assert_eq!(given.to_bits(), value.to_bits(), "{name}");
        held += 1;
    }
    // Every number of the table is the source's, but X_uu = −Cd0 of its propeller law.
    assert_eq!(table.added_mass.len() + table.coefficients.len(), held + 1);
    assert_eq!(table.coefficients["Xuu"].to_bits(), (-CD0).to_bits());
    let prime = table.prime.unwrap();
    assert_eq!((prime.density, prime.length), (RHO, LENGTH));
    assert_eq!((table.weight, table.buoyancy), (WEIGHT, WEIGHT));
    assert_eq!(table.mass.to_bits(), (WEIGHT / G).to_bits());
    assert_eq!(table.centre_of_gravity, [0.0, 0.0, 0.061]);
    assert_eq!(table.centre_of_buoyancy, [0.0; 3]);
    // npsauv.m's I_g = [Ix −Ixy −Ixz; −Ixy Iy −Iyz; −Ixz −Iyz Iz], in M_RB where the tensor
    // about O goes: eom's tensor about O, whose off-diagonal entries are the chapter's
    // products (−∫xy dm), so −(Fossen's Ixy) exactly.
    assert_eq!(table.inertia_about, InertiaAbout::Origin);
    let [ixy, iyz, ixz] = PRODUCTS.map(|p| -p);
    let tensor = [
        [MOMENTS[0], ixy, ixz],
        [ixy, MOMENTS[1], iyz],
        [ixz, iyz, MOMENTS[2]],
    ];
    for (given, source) in table.inertia.iter().flatten().zip(tensor.iter().flatten()) {
        assert_eq!(given.to_bits(), source.to_bits());
    }
    // The law as the scene writes it, and the thrust of X = ½ρL²Cd0(prop|prop| − 1)u²,
    // prop = 0.012n/u, at the setting.
    let propeller = table.propeller.unwrap();
    let law = propeller.law.unwrap();
    assert_eq!(
        (
            law.rpm,
            law.advance,
            law.drag_coefficient,
            law.thrust_coefficient
        ),
        (RPM, ADVANCE, CD0, CT)
    );
    assert_eq!((law.density, law.length), (RHO, LENGTH));
    let thrust = 0.5 * RHO * LENGTH.powi(2) * CD0 * (ADVANCE * shaft_speed()).powi(2);
    assert_eq!(propeller.thrust.to_bits(), thrust.to_bits());
    assert_eq!(propeller.torque, 0.0);
    for name in IN_EPSILON {
        assert!(table.coefficients.contains_key(name), "{name}");
    }
    // The cross-flow drag's strips as the scene writes them, the source's −L/2:L/10:L/2 to
    // rounding of the decimals, its 0.53 m, Cdy = 0.5, Cdz = 0.6, ρ the prime system's.
    let hull = table.cross_flow.as_ref().unwrap();
    let written = [
        -2.65, -2.12, -1.59, -1.06, -0.53, 0.0, 0.53, 1.06, 1.59, 2.12, 2.65,
    ];
    assert_eq!(hull.stations, written);
    for (k, x) in hull.stations.iter().enumerate() {
        let source = -LENGTH / 2.0 + k as f64 * LENGTH / 10.0;
        assert!((x - source).abs() <= 4.5e-16, "{x} against {source}");
    }
    assert_eq!(hull.lengths, [0.53; 11]);
    assert_eq!(hull.heights, [0.53; 11]);
    assert_eq!(hull.breadths, [0.53; 11]);
    assert_eq!((hull.sway_coefficient, hull.heave_coefficient), (0.5, 0.6));
    assert_eq!(hull.density, RHO);
}

/// At prop = 0.012n/u = 1 the thrust meets the resistance: u = 0.012n.
#[test]
fn the_cruise_is_the_propeller_law_s_speed_and_holds() {
    let scene = nps();
    let start = scene.start().unwrap();
    let cruise = CruiseSummary::new(&scene);
    println!("{cruise:#?}");
    let law = 0.012 * shaft_speed();
    let closed = cruise.speed_closed_form_m_s.unwrap();
    // The closed form from the scene's rounded thrust: rounding only.
    assert!((closed - law).abs() < 1e-14, "{closed} against {law}");
    // Newton stops when u̇ < 1e-13 m/s²; ∂u̇/∂u = −2·½ρL²Cd0·u/(M − ½ρL³X′_u̇) ≈ −0.03 /s, so
    // u is within 4e-12 m/s of the trim.
    assert!((cruise.speed_m_s - law).abs() < 1e-11, "{cruise:?}");
    // No propeller torque: no roll trim. On the straight course ω = 0, so the products of
    // inertia add no moment at the trim; but they couple ṗ to u̇ through the inverse mass
    // matrix, so Newton's steps in u (u̇ ≠ 0 until it has converged) move φ by rounding:
    // 1.7e-30° here, where the principal tensor left it at exactly zero.
    assert_eq!(cruise.roll_closed_form_deg, Some(0.0));
    assert!(cruise.roll_deg.abs() < 1e-20, "{cruise:?}");
    // The law's cruise: prop = 1, where ε is zero exactly, and at the trim to rounding.
    let propeller = scene.table.propeller_law().unwrap();
    assert_eq!(propeller.cruise_speed(), law);
    assert_eq!(propeller.epsilon(law).value, 0.0);
    let epsilon = propeller.epsilon(cruise.speed_m_s).value;
    println!("ε at the trim: {epsilon:e}");
    // |∂ε/∂u| ≈ 1.3 s/m here, and u is within 1e-11 m/s of the law's.
    assert!(epsilon.abs() < 2e-11, "{epsilon:e}");
    // Ten seconds of it (before the first step) leave it where it was.
    let run = run_with(&scene, &scene.model, &scene.manoeuvres[0], start);
    let before = run.ends[0];
    assert_eq!(before.t, 10.0);
    for (i, (a, b)) in before.state.iter().zip(&start).enumerate() {
        let moved = if i == 6 { a - b - law * 10.0 } else { a - b };
        assert!(moved.abs() < 1e-9, "state {i} moved by {moved:e}");
    }
}

/// The steady turn of the linear sway and yaw equations in the prime system (U = u, x_G = 0):
/// Y′_v v′ + (Y′_r − m′) r′ + Y′_δ δ = 0 and N′_v v′ + N′_r r′ + N′_δ δ = 0, so
/// r′ = δ (Y′_v N′_δ − Y′_δ N′_v)/(N′_v(Y′_r − m′) − Y′_v N′_r), r = r′u/L.
fn linear_yaw_rate(table: &eom::kinds::vehicle::VehicleTable, rudder: f64, u: f64) -> f64 {
    let c = |name: &str| table.coefficients[name];
    let m = table.mass / (0.5 * RHO * LENGTH.powi(3));
    let (yv, yr, yd) = (c("Yv"), c("Yr"), c("Ydr"));
    let (nv, nr, nd) = (c("Nv"), c("Nr"), c("Ndr"));
    let r_prime = rudder * (yv * nd - yd * nv) / (nv * (yr - m) - yv * nr);
    r_prime * u / LENGTH
}

/// The relative difference of the steady yaw rate after a rudder step of each of `degrees`
/// from the linear closed form, on `model`.
fn closed_form_errors(scene: &VehicleScene, model: &VehicleModel, degrees: [f64; 2]) -> [f64; 2] {
    let start = cruise(model).unwrap();
    degrees.map(|degrees| {
        let step = VehicleManoeuvre {
            steps: eom::kinds::vehicle::FinSteps::new(vec![10.0], vec![[f64::to_radians(degrees), 0.0]])
                .unwrap(),
            ..scene.manoeuvres[0].clone()
        };
        let run = run_with(scene, model, &step, start);
        let end = run.ends.last().unwrap().state;
        let closed = linear_yaw_rate(&scene.table, degrees.to_radians(), end[0]);
        let error = end[5] / closed - 1.0;
        println!(
            "δ_r = {degrees}°: r = {:.6} °/s at {:.4} m/s, closed form {:.6} °/s, relative {error:e}",
            end[5].to_degrees(),
            end[0],
            closed.to_degrees()
        );
        error
    })
}

#[test]
fn a_small_rudder_step_turns_at_the_linear_sway_yaw_closed_form() {
    let scene = nps_converged();
    // The table's own terms: the cross-flow drag is not in the linear equations.
    let mut table = scene.table.clone();
    table.cross_flow = None;
    let errors = closed_form_errors(&scene, &VehicleModel::new(&table).unwrap(), [0.5, 1.0]);
    // The couplings the closed form leaves out (roll, heave and pitch, the speed's own change)
    // are of second order in δ: the error is small and scales by about four from 0.5° to 1°.
    assert!(errors[1].abs() < 1e-3, "{errors:?}");
    let ratio = errors[1] / errors[0];
    assert!((3.0..5.0).contains(&ratio), "{errors:?}");
    // The cross-flow drag is a signed square of the cross flow, so its share of the sway and
    // yaw damping grows as δ itself: on the scene's model the turn is slower than the closed
    // form by a share that doubles from 0.5° to 1°.
    let errors = closed_form_errors(&scene, &scene.model, [0.5, 1.0]);
    assert!(errors[0] < 0.0 && errors[1] < 0.0, "{errors:?}");
    let ratio = errors[1] / errors[0];
    assert!((1.8..2.2).contains(&ratio), "{errors:?}");
}

#[test]
fn the_ten_degree_turn_converges_and_port_and_starboard_mirror() {
    let scene = nps_converged();
    let start = scene.start().unwrap();
    let turn = &scene.manoeuvres[1];
    let run = run_with(&scene, &scene.model, turn, start);
    let figures = StepFigures::of(&run);
    for f in &figures {
        println!("{f:?}");
    }
    let steady = figures[1];
    assert_eq!(
        (steady.from_s, steady.to_s, steady.rudder_deg),
        (10.0, 110.0, 10.0)
    );
    assert!(steady.yaw_rate_deg_s < -1.0, "{steady:?}");
    // Converged: half the step moves no figure by more than 1e-6 (RK4 at 0.02 s).
    let mut finer = scene.clone();
    finer.stepper = scene.stepper.refined(scene.every);
    let refined = StepFigures::of(&run_with(&finer, &scene.model, turn, start));
    let difference = largest_difference(&figures, &refined);
    println!("half-step difference {difference:e}");
    assert!(difference < 1e-6, "{difference:e}");
    // Without the products Ixy and Iyz (Ixz kept) the x–z plane is a plane of symmetry of the
    // body, and the table has no propeller torque: the port turn is the starboard one
    // reflected in the x–z plane (v, p, r, y, q1, q3 and the fins change sign).
    let symmetric = VehicleModel::new(&scene.table.without_lateral_products()).unwrap();
    let symmetric_start = cruise(&symmetric).unwrap();
    let worst = mirror_difference(&scene, &symmetric, turn, symmetric_start);
    println!("largest mirror difference, Ixy = Iyz = 0: {worst:e}");
    assert!(worst < 1e-9, "{worst:e}");
    // The source's products are not symmetric so: its port turn differs, a little.
    let asymmetric = mirror_difference(&scene, &scene.model, turn, start);
    println!("largest mirror difference with npsauv.m's products: {asymmetric:e}");
    assert!(asymmetric > 1e3 * worst, "{asymmetric:e}");
}

/// The largest difference between the turn `turn` and its mirror image to port, reflected.
fn mirror_difference(
    scene: &VehicleScene,
    model: &VehicleModel,
    turn: &VehicleManoeuvre,
    start: [f64; 15],
) -> f64 {
    let port = VehicleManoeuvre {
        steps: turn.steps.mirrored(),
        ..turn.clone()
    };
    let (starboard, mirrored) = (
        run_with(scene, model, turn, start),
        run_with(scene, model, &port, start),
    );
    let mut worst: f64 = 0.0;
    for (x, y) in starboard.ends.iter().zip(&mirrored.ends) {
        let reflected = manoeuvre::mirrored(&y.state);
        for (a, b) in x.state.iter().zip(reflected) {
            worst = worst.max((a - b).abs());
        }
    }
    worst
}

#[test]
fn the_folded_table_is_shown_in_prime_units() {
    let scene = nps();
    let xwq = (scene.model.folded().iter())
        .find(|r| r.name.as_deref() == Some("Xwq"))
        .unwrap();
    // Xwq = Z′_ẇ: −0.24 implied against −0.2 printed.
    assert_eq!((xwq.printed, xwq.implied), (Some(-0.2), -0.24));
}

/// The scene with `from` replaced by `to` (which must be there).
fn edited(from: &str, to: &str) -> String {
    let text = scene_text();
    assert!(text.contains(from), "{from}");
    text.replacen(from, to, 1)
}

#[test]
fn a_bad_prime_table_is_refused_naming_the_key() {
    let length = "length = 5.3                          # L, m\n";
    let density = "density = 1025.0                      # rho, kg/m³\n";
    let cases = [
        (length, "", "hydrodynamics.length"),
        (density, "", "hydrodynamics.density"),
        ("length = 5.3", "length = -5.3", "hydrodynamics.length"),
        (
            "units = \"prime\"",
            "units = \"metric\"",
            "hydrodynamics.units",
        ),
        (
            "units = \"prime\"",
            "units = \"dimensional\"",
            "hydrodynamics.density",
        ),
        (
            "Yv = -1.0e-1",
            "Yv = -1.0e-1\nYuvr = 1.0",
            "hydrodynamics.coefficients.Yuvr",
        ),
        (
            "Yv = -1.0e-1",
            "Yv = -1.0e-1\nYuv = 1.0",
            "hydrodynamics.coefficients.Yv",
        ),
    ];
    for (from, to, key) in cases {
        let error = parse(&edited(from, to))
            .err()
            .unwrap_or_else(|| panic!("{to} accepted"));
        println!("{error}");
        assert!(error.contains(&format!("`{key}`")), "{to}: {error}");
    }
    let missing = parse(&edited(length, "")).unwrap_err();
    assert!(missing.contains("the prime system needs L"), "{missing}");
    let three = parse(&edited("Yv = -1.0e-1", "Yv = -1.0e-1\nYuvr = 1.0")).unwrap_err();
    assert!(three.contains("prime system"), "{three}");
    let same = parse(&edited("Yv = -1.0e-1", "Yv = -1.0e-1\nYuv = 1.0")).unwrap_err();
    assert!(same.contains("`Yuv` and `Yv`"), "{same}");
}

/// The model's ∂f/∂x, whose column of u holds the chain rule through ε, against the dual
/// number's derivative of its rates (which carries ε's own through the law), at a state away
/// from the cruise (ε = 0.21) with every velocity and both fins moving.
#[test]
fn the_jacobian_holds_the_chain_rule_through_epsilon() {
    let scene = nps();
    let model = &scene.model;
    let mut x = [
        1.45, 0.12, -0.08, 0.03, -0.02, 0.05, 1.0, 2.0, 3.0, 0.9, 0.1, -0.2, 0.3, 0.1, -0.15,
    ];
    let norm = (9..13).map(|i| x[i] * x[i]).sum::<f64>().sqrt();
    for q in &mut x[9..13] {
        *q /= norm;
    }
    let epsilon = scene.table.propeller_law().unwrap().epsilon(x[0]).value;
    assert!(epsilon > 0.2, "{epsilon}");
    let input = [0.0, 0.0];
    let exact = Model::<f64, 15, 2>::state_jacobian(model, &x, &input);
    let mut worst: f64 = 0.0;
    for column in 0..15 {
        let mut seeded = x.map(Dual64::from);
        seeded[column].eps = 1.0;
        let rates = Model::<Dual64, 15, 2>::rhs(model, &seeded, &input.map(Dual64::from));
        for row in 0..15 {
            let scale = 1.0 + exact[row][column].abs();
            worst = worst.max((rates[row].eps - exact[row][column]).abs() / scale);
        }
    }
    println!("largest difference from the dual numbers' {worst:e}");
    // The same derivatives by two routes: rounding of entries of order one.
    assert!(worst < 1e-12, "{worst:e}");
    // The column of u is not the program's alone: the terms in ε add to it.
    let mut without = scene.table.clone();
    for name in IN_EPSILON {
        without.coefficients.remove(name);
    }
    let bare = VehicleModel::new(&without).unwrap();
    let bare_jacobian = Model::<f64, 15, 2>::state_jacobian(&bare, &x, &input);
    assert!((0..6).any(|row| (exact[row][0] - bare_jacobian[row][0]).abs() > 1e-6));
}

/// What the terms in ε change in the ten-degree turn: the same run without them.
#[test]
fn the_terms_in_epsilon_change_the_ten_degree_turn_a_little() {
    let scene = nps();
    let start = scene.start().unwrap();
    let turn = &scene.manoeuvres[1];
    let with = StepFigures::of(&run_with(&scene, &scene.model, turn, start))[1];
    let mut without = scene.table.clone();
    for name in IN_EPSILON {
        without.coefficients.remove(name);
    }
    let bare = VehicleModel::new(&without).unwrap();
    let start_bare = cruise(&bare).unwrap();
    assert_eq!(start_bare, start, "ε = 0 at the cruise: the same trim");
    let before = StepFigures::of(&run_with(&scene, &bare, turn, start))[1];
    println!("with the terms in ε:    {with:?}");
    println!("without the terms in ε: {before:?}");
    let law = scene.table.propeller_law().unwrap();
    println!(
        "ε at the turn's speed {}: {}",
        with.speed_m_s,
        law.epsilon(with.speed_m_s).value
    );
    let change = with.yaw_rate_deg_s / before.yaw_rate_deg_s - 1.0;
    println!("yaw rate changed by {change:e}");
    // With the stern planes at zero the terms multiply only the small w, p, q: under 1 %.
    assert!(change.abs() < 1e-2 && with.yaw_rate_deg_s != before.yaw_rate_deg_s);
}

#[test]
fn a_bad_propeller_law_is_refused_naming_the_key() {
    let cases = [
        ("rpm = 1300.0", "rpm = -1300.0", "propeller.rpm"),
        ("rpm = 1300.0", "rpm = nan", "propeller.rpm"),
        ("rpm = 1300.0", "", "propeller.rpm"),
        ("advance = 0.012", "advance = 0.0", "propeller.advance"),
        (
            "drag_coefficient = 0.00385",
            "drag_coefficient = -0.00385",
            "propeller.drag_coefficient",
        ),
        (
            "thrust_coefficient = 0.008",
            "thrust_coefficient = nan",
            "propeller.thrust_coefficient",
        ),
        (
            "law = \"healey_lienard\"",
            "law = \"wageningen\"",
            "propeller.law",
        ),
        (
            "law = \"healey_lienard\"",
            "law = \"healey_lienard\"\nthrust = 147.9",
            "propeller.thrust",
        ),
        (
            "law = \"healey_lienard\"",
            "law = \"constant\"",
            "propeller.rpm",
        ),
        ("torque = 0.0 ", "torque = nan ", "propeller.torque"),
    ];
    for (from, to, key) in cases {
        let error = parse(&edited(from, to))
            .err()
            .unwrap_or_else(|| panic!("{to} accepted"));
        println!("{error}");
        assert!(error.contains(&format!("`{key}`")), "{to}: {error}");
    }
    // Without the law, `n` is no factor of the table: the terms in ε are refused by name.
    let constant = edited(
        "law = \"healey_lienard\"\nrpm = 1300.0",
        "law = \"constant\"\nthrust = 147.9",
    );
    let constant = constant
        .replace("advance = 0.012", "")
        .replace("drag_coefficient = 0.00385", "")
        .replace("thrust_coefficient = 0.008", "");
    let error = parse(&constant).unwrap_err();
    assert!(error.contains("hydrodynamics.coefficients."), "{error}");
}

/// The steady turn's figures of the 10° rudder (its second stretch) and its steady diameter
/// 2U/r, m.
fn steady_turn(scene: &VehicleScene, model: &VehicleModel) -> (StepFigures, f64) {
    let start = cruise(model).unwrap();
    let figures = StepFigures::of(&run_with(scene, model, &scene.manoeuvres[1], start))[1];
    let diameter = 2.0 * figures.speed_m_s / figures.yaw_rate_deg_s.to_radians().abs();
    (figures, diameter)
}

/// What the cross-flow drag changes in the ten-degree turn: the same run without it. It
/// damps sway and yaw, so the turn is slower and wider; at the cruise there is no cross flow,
/// so the trim is the same.
#[test]
fn the_cross_flow_drag_slows_and_widens_the_ten_degree_turn() {
    let scene = nps();
    let (with, diameter) = steady_turn(&scene, &scene.model);
    let mut without = scene.table.clone();
    without.cross_flow = None;
    let bare = VehicleModel::new(&without).unwrap();
    assert_eq!(cruise(&bare).unwrap(), scene.start().unwrap());
    let (before, diameter_before) = steady_turn(&scene, &bare);
    println!(
        "with the cross-flow drag:    r = {:.6} °/s, U = {:.6} m/s, diameter {diameter:.3} m, {with:?}",
        with.yaw_rate_deg_s, with.speed_m_s
    );
    println!(
        "without the cross-flow drag: r = {:.6} °/s, U = {:.6} m/s, diameter {diameter_before:.3} m, {before:?}",
        before.yaw_rate_deg_s, before.speed_m_s
    );
    let slower = with.yaw_rate_deg_s / before.yaw_rate_deg_s - 1.0;
    println!(
        "yaw rate changed by {slower:e}, diameter by {:e}",
        diameter / diameter_before - 1.0
    );
    assert!(with.yaw_rate_deg_s.abs() < before.yaw_rate_deg_s.abs());
    assert!(diameter > diameter_before);
}

#[test]
fn a_bad_cross_flow_is_refused_naming_the_key() {
    let eleven = "[0.53, 0.53, 0.53, 0.53, 0.53, 0.53, 0.53, 0.53, 0.53, 0.53, 0.53]";
    let ten = "[0.53, 0.53, 0.53, 0.53, 0.53, 0.53, 0.53, 0.53, 0.53, 0.53]";
    let cases = [
        (
            format!("heights = {eleven}"),
            format!("heights = {ten}"),
            "hydrodynamics.cross_flow.heights",
        ),
        (
            format!("breadths = {eleven}"),
            format!("breadths = {}", eleven.replacen("0.53", "-0.53", 1)),
            "hydrodynamics.cross_flow.breadths[0]",
        ),
        (
            format!("lengths = {eleven}"),
            format!("lengths = {}", eleven.replacen("0.53", "nan", 1)),
            "hydrodynamics.cross_flow.lengths[0]",
        ),
        (
            "stations = [-2.65,".to_owned(),
            "stations = [nan,".to_owned(),
            "hydrodynamics.cross_flow.stations[0]",
        ),
        (
            "sway_coefficient = 0.5".to_owned(),
            "sway_coefficient = -0.5".to_owned(),
            "hydrodynamics.cross_flow.sway_coefficient",
        ),
        (
            "heave_coefficient = 0.6".to_owned(),
            "heave_coefficient = nan".to_owned(),
            "hydrodynamics.cross_flow.heave_coefficient",
        ),
        (
            "heave_coefficient = 0.6".to_owned(),
            "heave_coefficient = 0.6\ndensity = 0.0".to_owned(),
            "hydrodynamics.cross_flow.density",
        ),
        (
            "heave_coefficient = 0.6".to_owned(),
            "heave_coefficient = 0.6\nwidth = 0.53".to_owned(),
            "width",
        ),
    ];
    for (from, to, key) in cases {
        let error = parse(&edited(&from, &to))
            .err()
            .unwrap_or_else(|| panic!("{to} accepted"));
        println!("{error}");
        assert!(error.contains(key), "{to}: {error}");
    }
    let text = scene_text();
    let stations = text.lines().find(|l| l.starts_with("stations")).unwrap();
    let none = parse(&edited(stations, "stations = []")).unwrap_err();
    assert!(
        none.contains("`hydrodynamics.cross_flow.stations`"),
        "{none}"
    );
}
