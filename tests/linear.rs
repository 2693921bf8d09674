//! `eom::linear` on every family against the closed forms: the pendulum's √(Mgh/I₀) about its
//! lowest point (and its trimmed and inverted points), a free body spinning about each
//! principal axis (λ² from Euler's equations: the intermediate axis unstable, the others
//! not), the heavy top sleeping upright (its four roots, and the spin threshold
//! C²Ω² = 4 A_O M g h bracketed 1 % either side), and a planar body's set-aside track.
//!
//! Tolerance: 1e-9 relative to the eigenvalue's size. A is made of the emitted Jacobians,
//! exact to rounding; the Schur form's eigenvalues of these 2–6 state matrices, whose
//! eigenvalues are simple, carry an error of a few ε times ‖A‖/|λ|, some 10⁻¹⁵ here, so the
//! bound leaves six digits of room and still tells a wrong term (a relative change of order
//! one) from a right one.

use eom::kinds::body::BodyScene;
use eom::kinds::body::linear::linearise_scene;
use eom::linear::{Linearisation, Stability};
use eom::nalgebra::Complex;

fn linearise(text: &str) -> Linearisation {
    let scene = BodyScene::parse(text, "test.toml", std::path::Path::new(".")).unwrap();
    linearise_scene(&scene).unwrap()
}

fn assert_relative(found: f64, wanted: f64, what: &str) {
    let error = (found - wanted).abs() / wanted.abs().max(f64::MIN_POSITIVE);
    println!("{what}: {found:.15e} against {wanted:.15e}, relative error {error:.1e}");
    assert!(error <= 1e-9, "{what}: {found} against {wanted}");
}

const INTEGRATOR: &str = "[integrator]\nmethod = \"dop853\"\nend_time = 1.0\n";

fn pendulum(extra: &str) -> String {
    format!(
        "title = \"p\"\n[body]\ni0 = 2.0\nmass = 3.0\ng = 9.81\nh = 0.5\n[model]\nfamily = \
         \"pendulum\"\n{extra}\n{INTEGRATOR}"
    )
}

#[test]
fn the_pendulum_swings_at_the_root_of_mgh_over_i0_about_its_lowest_point() {
    let linear = linearise(&pendulum(""));
    assert!(linear.equilibrium && linear.set_aside.is_empty());
    let omega = (3.0f64 * 9.81 * 0.5 / 2.0).sqrt();
    assert_eq!(linear.eigenvalues.len(), 2);
    for l in &linear.eigenvalues {
        assert!(l.re.abs() <= 1e-12 * omega, "{l}");
        assert_relative(l.im.abs(), omega, "pendulum ω");
    }
    let mode = &linear.modes[0];
    assert_eq!(mode.name, Some("the pendulum's swing"));
    assert_relative(
        mode.period_s.unwrap(),
        2.0 * std::f64::consts::PI / omega,
        "period 4.27",
    );
    assert_eq!(linear.stability, Some(Stability::Marginal));
}

#[test]
fn the_pendulum_upside_down_falls_at_the_same_rate() {
    let linear = linearise(&pendulum("[initial]\ntheta_deg = 180.0\n"));
    let rate = (3.0f64 * 9.81 * 0.5 / 2.0).sqrt();
    assert_relative(linear.eigenvalues[0].re, rate, "inverted pendulum's growth");
    assert_relative(-linear.eigenvalues[1].re, rate, "inverted pendulum's decay");
    assert_eq!(linear.stability, Some(Stability::Unstable));
}

#[test]
fn a_pendulum_held_at_thirty_degrees_is_trimmed_by_its_moment() {
    let theta = 30f64.to_radians();
    let linear = linearise(&pendulum(&format!(
        "[linear]\nat = {{ theta = {theta} }}\ntrim = [\"M_O\"]\n"
    )));
    let (values, _) = linear.trimmed.as_ref().unwrap();
    assert_relative(
        values[0].1,
        3.0 * 9.81 * 0.5 * theta.sin(),
        "M_O = Mgh sin θ",
    );
    assert!(linear.equilibrium);
    let omega = (3.0 * 9.81 * 0.5 * theta.cos() / 2.0).sqrt();
    assert_relative(linear.eigenvalues[0].im.abs(), omega, "ω² = Mgh cos θ / I₀");
}

#[test]
fn a_trim_that_cannot_hold_the_point_says_it_did_not_converge() {
    // θ cannot make θ̇ = 1 rad/s an equilibrium: θ's own rate is θ̇.
    let scene = BodyScene::parse(
        &pendulum("[initial]\ntheta_dot = 1.0\n[linear]\ntrim = [\"theta\"]\n"),
        "t.toml",
        std::path::Path::new("."),
    )
    .unwrap();
    let error = linearise_scene(&scene).unwrap_err().to_string();
    assert!(
        error.contains("did not converge") && error.contains("theta"),
        "{error}"
    );
}

/// λ² of a free body spinning at Ω about axis `a` (Euler's equations 4.52 linearised).
fn euler_lambda_squared(inertia: [f64; 3], axis: usize, omega: f64) -> f64 {
    let (b, c) = ((axis + 1) % 3, (axis + 2) % 3);
    omega * omega * (inertia[axis] - inertia[b]) * (inertia[c] - inertia[axis])
        / (inertia[b] * inertia[c])
}

fn spinning_body(axis: usize, omega: f64, kinematics: &str) -> String {
    let mut rates = [0.0; 3];
    rates[axis] = omega;
    format!(
        "title = \"s\"\n[body]\nmass = 1.0\ninertia = [[2.0, 0.0, 0.0], [0.0, 3.0, 0.0], \
         [0.0, 0.0, 4.5]]\n[model]\nfamily = \"spatial\"\nkinematics = \"{kinematics}\"\n\
         [initial]\nrates = {rates:?}\n{INTEGRATOR}"
    )
}

#[test]
fn a_free_body_spins_stably_about_its_largest_and_smallest_axes_only() {
    let inertia = [2.0, 3.0, 4.5];
    for kinematics in ["euler", "quaternion"] {
        for axis in 0..3 {
            let omega = 6.0;
            let linear = linearise(&spinning_body(axis, omega, kinematics));
            // The attitude about the spin axis grows and is set aside; spinning about z, that
            // is the heading ψ alone, and roll and pitch stay (a quaternion scene is
            // linearised in the Euler angles of the same body).
            let mut reduced = vec!["u", "v", "w", "p", "q", "r"];
            if axis == 2 {
                reduced.extend(["phi", "theta"]);
            }
            assert_eq!(linear.reduced_names(), reduced, "{kinematics}");
            let squared = euler_lambda_squared(inertia, axis, omega);
            let named: Vec<Complex<f64>> = linear
                .modes
                .iter()
                .filter(|m| matches!(m.name, Some("nutation" | "the spin's instability")))
                .map(|m| m.eigenvalue)
                .collect();
            let what = format!("{kinematics}, spin about axis {axis}");
            if squared > 0.0 {
                assert_eq!(linear.stability, Some(Stability::Unstable), "{what}");
                assert_relative(named[0].re, squared.sqrt(), &format!("{what}: λ"));
            } else {
                assert_eq!(linear.stability, Some(Stability::Marginal), "{what}");
                assert_relative(named[0].im, (-squared).sqrt(), &format!("{what}: ω"));
            }
        }
    }
}

/// A sleeping top: G at h above the pivot, spinning at Ω about its axis.
fn top(omega: f64, kinematics: &str) -> String {
    format!(
        "title = \"t\"\n[body]\nmass = 1.0\ninertia = [[0.25, 0.0, 0.0], [0.0, 0.25, 0.0], \
         [0.0, 0.0, 0.2]]\nh = 0.5\ng = 9.81\n[model]\nfamily = \"top\"\nkinematics = \
         \"{kinematics}\"\n[initial]\nrates = [0.0, 0.0, {omega}]\n{INTEGRATOR}"
    )
}

#[test]
fn the_sleeping_top_is_stable_exactly_above_its_spin_threshold() {
    let (a_o, c, mgh): (f64, f64, f64) = (0.25 + 0.5 * 0.5, 0.2, 9.81 * 0.5);
    let threshold = 2.0 * (a_o * mgh).sqrt() / c;
    for kinematics in ["euler", "quaternion"] {
        let slow = linearise(&top(0.99 * threshold, kinematics));
        let fast = linearise(&top(1.01 * threshold, kinematics));
        assert_eq!(slow.stability, Some(Stability::Unstable), "{kinematics}");
        assert_eq!(fast.stability, Some(Stability::Marginal), "{kinematics}");
        assert_eq!(fast.set_aside_names(), ["psi"]);
        for spin in [1.01 * threshold, 3.0 * threshold] {
            let linear = linearise(&top(spin, kinematics));
            // A_O s² − iCΩ s − Mgh = 0: s = i(CΩ ± √(C²Ω² − 4A_O Mgh))/(2A_O).
            let root = (c * c * spin * spin - 4.0 * a_o * mgh).sqrt();
            let nutation = (c * spin + root) / (2.0 * a_o);
            let precession = (c * spin - root) / (2.0 * a_o);
            // The roll and pitch of the Euler-angle top are measured in axes turned by the
            // heading, at Ω: the modes are compared as seen in space.
            let by_name = |name: &str| {
                let mode = linear.modes.iter().find(|m| m.name == Some(name)).unwrap();
                mode.frequency_in_space.unwrap()
            };
            assert_relative(
                by_name("nutation"),
                nutation,
                &format!("{kinematics}: nutation"),
            );
            assert_relative(
                by_name("precession"),
                precession,
                &format!("{kinematics}: precession"),
            );
            // The periods are those seen in space, the turning axes' beside them.
            for (name, frequency) in [("nutation", nutation), ("precession", precession)] {
                let mode = linear.modes.iter().find(|m| m.name == Some(name)).unwrap();
                let what = format!("{kinematics}: {name}'s period in space");
                assert_relative(
                    mode.period_s.unwrap(),
                    std::f64::consts::TAU / frequency,
                    &what,
                );
                let turning = mode.period_in_turning_axes_s.unwrap();
                let in_turning_axes = std::f64::consts::TAU / mode.eigenvalue.im;
                assert_relative(turning, in_turning_axes, &format!("{what}, turning axes"));
            }
        }
    }
}

#[test]
fn a_planar_body_at_speed_sets_aside_its_track_and_heading() {
    let text = format!(
        "title = \"b\"\n[body]\nmass = 1000.0\nizz = 2.0e5\n[model]\nfamily = \"planar-g\"\n\
         [initial]\nu = 2.0\n[loads]\nforce_body = [200.0, 0.0]\nlinear_damping = [100.0, 400.0, 8.0e4]\n\
         {INTEGRATOR}"
    );
    let linear = linearise(&text);
    assert_eq!(linear.set_aside_names(), ["X", "Y", "psi"]);
    assert_eq!(linear.reduced_names(), ["u", "v", "r"]);
    // Pushed against its damping at 2 m/s, u̇ = (F − d_u u)/M + v r = 0, and a disturbance of
    // the surge decays at d_u/M.
    assert!(linear.equilibrium);
    let surge = linear
        .modes
        .iter()
        .find(|m| m.name == Some("surge"))
        .unwrap();
    assert_relative(-surge.eigenvalue.re, 100.0 / 1000.0, "surge decay d_u/M");
    assert_eq!(linear.stability, Some(Stability::Asymptotic));
}

/// A free body at rest under no load: A is nilpotent (an angle reads a rate), every eigenvalue
/// is zero and the solver gives ±10⁻¹⁶. The verdict is marginal, not unstable, and no mode has
/// a doubling time; the quaternion scene is linearised in Euler angles, so no component of a
/// quaternion is in the reduced state.
#[test]
fn a_free_body_at_rest_is_marginal_not_unstable() {
    let scene = BodyScene::load(std::path::Path::new("scenes/thruster_burn.toml")).unwrap();
    let linear = linearise_scene(&scene).unwrap();
    assert!(linear.equilibrium);
    assert_eq!(linear.stability, Some(Stability::Marginal));
    assert!(linear.modes.iter().all(|m| m.time_to_double_s.is_none()));
    assert!(linear.modes.iter().all(|m| m.period_s.is_none()));
    let reduced = linear.reduced_names();
    assert!(
        !reduced.iter().any(|n| n.starts_with('q') && n.len() == 2),
        "{reduced:?}"
    );
    assert!(
        reduced.contains(&"phi") && reduced.contains(&"theta"),
        "{reduced:?}"
    );
}

/// The verdict's tolerance is scaled to ‖A‖, not to the eigenvalues: a nilpotent A turned by an
/// orthogonal matrix has computed eigenvalues of about √(ε‖A‖) ≈ 10⁻⁸·‖A‖, a spectral radius
/// of round-off, and is still marginal; a growth of 10⁻⁴‖A‖ is still seen.
#[test]
fn round_off_in_the_eigenvalues_is_no_growth() {
    use eom::linear::{Naming, modes};
    use eom::models::Family;
    use eom::nalgebra::DMatrix;
    let n = 4;
    let q = DMatrix::from_fn(n, n, |i, j| ((3 * i + 5 * j + 1) as f64).cos())
        .qr()
        .q();
    let names: Vec<String> = (0..n).map(|i| format!("x{i}")).collect();
    let verdict = |growth: f64| {
        // x₀ reads x₁ and x₂ reads x₃ (two Jordan blocks of size 2), with `growth` on x₁.
        let mut a = DMatrix::zeros(n, n);
        a[(0, 1)] = 3.0;
        a[(2, 3)] = 5.0;
        a[(1, 1)] = growth;
        let turned = &q * a * q.transpose();
        let (eigenvalues, _, stability) =
            modes(&turned, (&names, &[]), Naming::Family(Family::Spatial), 0.0);
        (eigenvalues, stability)
    };
    let (eigenvalues, stability) = verdict(0.0);
    let largest = eigenvalues.iter().fold(0.0f64, |m, l| m.max(l.re));
    println!("round-off growth {largest:e}");
    assert!(
        largest > 0.0,
        "the test needs round-off that looks like growth"
    );
    assert_eq!(stability, Stability::Marginal);
    assert_eq!(verdict(5e-4).1, Stability::Unstable);
    assert_eq!(
        verdict(-5e-4).1,
        Stability::Marginal,
        "the other block stays neutral"
    );
}

/// At a point that is not an equilibrium (a pendulum released at 150°) there is no verdict
/// and no mode is named: A there describes no motion that stays near the point.
#[test]
fn a_point_that_is_not_an_equilibrium_gets_no_verdict() {
    let linear = linearise(&pendulum("[initial]\ntheta_deg = 150.0\n"));
    assert!(!linear.equilibrium);
    assert_eq!(linear.stability, None);
    assert!(linear.modes.iter().all(|m| m.name.is_none()));
}
