//! The scene keys that say more than where a body starts and what constant load acts at G:
//! an initial velocity in space axes, a force at a point of the body, and uniform gravity
//! under the geometric integrator. Each is held to its closed form: v = Rᵀ V for the
//! velocity, r_P × F for the moment, torque-free rotation and ½ g t² for the fall.

use eom::run::{Row, Sink, run};
use eom::scene::{Scene, SceneError};
use nalgebra::{Rotation3, UnitQuaternion, Vector3};
use std::path::Path;

/// A scene from its text, read as `eom run` reads a file.
fn parse(text: &str) -> Result<Scene, SceneError> {
    Scene::parse(text, "scene.toml", Path::new("."))
}

/// The error a scene gives, as `eom run` prints it.
fn error_of(text: &str) -> String {
    match parse(text) {
        Ok(_) => panic!("accepted: {text}"),
        Err(e) => e.to_string(),
    }
}

/// A spatial body's scene with the given `[initial]`, `[loads]` and `[integrator]` lines.
fn spatial(initial: &str, loads: &str, integrator: &str) -> String {
    format!(
        "title = \"t\"\n[body]\nmass = 2.0\n\
         inertia = [[2.0, 0.0, 0.0], [0.0, 3.0, 0.0], [0.0, 0.0, 4.5]]\n\
         [model]\nfamily = \"spatial\"\n[initial]\n{initial}\n[loads]\n{loads}\n\
         [integrator]\n{integrator}\nend_time = 2.0\n[output]\nevery = 0.01\n"
    )
}

/// A planar body's scene of `family` with the given `[initial]` and `[loads]` lines.
fn planar(family: &str, initial: &str, loads: &str) -> String {
    let x_g = if family == "planar-midship" {
        "x_g = 0.1"
    } else {
        ""
    };
    format!(
        "title = \"t\"\n[body]\nmass = 2.0\nizz = 0.5\n{x_g}\n[model]\nfamily = \"{family}\"\n\
         [initial]\n{initial}\n[loads]\n{loads}\n\
         [integrator]\nmethod = \"rk4\"\nstep = 0.01\nend_time = 1.0\n"
    )
}

const ADAPTIVE: &str = "method = \"dop853\"\nrtol = 1e-10\natol = 1e-10";

/// Every row of a run.
#[derive(Default)]
struct Rows(Vec<(f64, Vec<f64>)>);

impl Sink for Rows {
    fn row(&mut self, row: &Row) -> bool {
        self.0.push((row.t, row.state.to_vec()));
        true
    }
}

fn rows_of(scene: &Scene) -> Vec<(f64, Vec<f64>)> {
    let mut rows = Rows::default();
    run(scene, &mut rows).unwrap();
    rows.0
}

#[test]
fn a_velocity_in_space_axes_starts_the_body_at_r_transposed_v() {
    let v_space = Vector3::new(3.0, -1.5, 0.75);
    for kinematics in ["quaternion", "euler"] {
        let text = spatial(
            "velocity_space = [3.0, -1.5, 0.75]\nattitude_deg = [20.0, -35.0, 110.0]",
            "",
            ADAPTIVE,
        )
        .replace(
            "family = \"spatial\"",
            &format!("family = \"spatial\"\nkinematics = \"{kinematics}\""),
        );
        let scene = parse(&text).unwrap();
        let r = Rotation3::from_euler_angles(
            20f64.to_radians(),
            (-35f64).to_radians(),
            110f64.to_radians(),
        );
        let expected = r.transpose() * v_space;
        let started = Vector3::from_column_slice(&scene.initial[..3]);
        assert!(
            (started - expected).norm() <= 1e-15 * v_space.norm(),
            "{kinematics}: {started} against {expected}"
        );
        // The body-axis velocity turned back by the state's own attitude is the one given.
        if kinematics == "quaternion" {
            let a = &scene.initial[9..13];
            let q = UnitQuaternion::from_quaternion([a[1], a[2], a[3], a[0]].into());
            assert!((q * started - v_space).norm() < 1e-14);
        }
    }
}

#[test]
fn a_planar_velocity_in_space_axes_is_turned_by_the_heading() {
    let (x_dot, y_dot, psi) = (1.2_f64, -0.4_f64, 30f64.to_radians());
    let initial = "x_dot = 1.2\ny_dot = -0.4\npsi_deg = 30.0";
    let (s, c) = psi.sin_cos();
    let body = [c * x_dot + s * y_dot, -s * x_dot + c * y_dot];
    for family in ["planar-g", "planar-midship"] {
        let scene = parse(&planar(family, initial, "")).unwrap();
        assert_eq!(scene.initial[..2], body, "{family}");
    }
    // The space-fixed state holds Ẋ and Ẏ themselves.
    let scene = parse(&planar("planar-space", initial, "")).unwrap();
    assert_eq!(scene.initial[3..5], [x_dot, y_dot]);
    // And u, v given in body axes reach the same state.
    let same = format!("u = {}\nv = {}\npsi_deg = 30.0", body[0], body[1]);
    let by_body = parse(&planar("planar-space", &same, "")).unwrap();
    for (a, b) in by_body.initial[3..5].iter().zip(&scene.initial[3..5]) {
        assert!((a - b).abs() < 1e-15, "{a} against {b}");
    }
}

#[test]
fn a_velocity_given_in_both_axes_is_refused_naming_both_keys() {
    let both = spatial(
        "velocity = [1.0, 0.0, 0.0]\nvelocity_space = [1.0, 0.0, 0.0]",
        "",
        ADAPTIVE,
    );
    let message = error_of(&both);
    assert!(message.contains("`initial.velocity_space`"), "{message}");
    assert!(message.contains("initial.velocity)"), "{message}");
    let message = error_of(&planar("planar-g", "v = 1.0\nx_dot = 2.0", ""));
    assert!(
        message.contains("`initial.x_dot`") && message.contains("initial.v is given"),
        "{message}"
    );
    // Not a key of the other families.
    let top = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/heavy_top.toml"),
    )
    .unwrap()
    .replacen(
        "[initial]",
        "[initial]\nvelocity_space = [1.0, 0.0, 0.0]",
        1,
    );
    assert!(error_of(&top).contains("initial.velocity_space"));
    let message = error_of(&spatial("velocity_space = [1.0, nan, 0.0]", "", ADAPTIVE));
    assert!(message.contains("initial.velocity_space[1]"), "{message}");
}

/// The scene's inputs (forces, then moments) at `state`.
fn inputs(scene: &Scene, state: &[f64]) -> Vec<f64> {
    let mut out = vec![0.0; 6];
    scene.loads.inputs(state, &mut out);
    out
}

/// A spatial state at rest, tilted by roll, pitch and yaw, as a quaternion state.
fn tilted(roll: f64, pitch: f64, yaw: f64) -> (Vec<f64>, Rotation3<f64>) {
    let q = UnitQuaternion::from_euler_angles(roll, pitch, yaw);
    let mut state = vec![0.0; 13];
    state[9..].copy_from_slice(&[q.w, q.i, q.j, q.k]);
    (state, q.to_rotation_matrix())
}

#[test]
fn a_force_at_a_point_adds_the_moment_r_cross_f() {
    let r = Vector3::new(0.3, -0.2, 0.5);
    let (state, to_space) = tilted(0.4, -0.3, 1.1);
    // In body axes: the moment is r × F, the force unchanged.
    let scene = parse(&spatial(
        "",
        "force_body = [4.0, -1.0, 2.5]\nforce_body_at = [0.3, -0.2, 0.5]",
        ADAPTIVE,
    ))
    .unwrap();
    let f = Vector3::new(4.0, -1.0, 2.5);
    let loads = inputs(&scene, &state);
    assert_eq!(loads[..3], [4.0, -1.0, 2.5]);
    assert_eq!(loads[3..], *r.cross(&f).as_slice());
    // In space axes: the force as the body sees it, F_b = Rᵀ F, and the moment r × F_b.
    let scene = parse(&spatial(
        "",
        "force_space = [4.0, -1.0, 2.5]\nforce_space_at = [0.3, -0.2, 0.5]",
        ADAPTIVE,
    ))
    .unwrap();
    let f_body = to_space.transpose() * f;
    let loads = inputs(&scene, &state);
    let moment = r.cross(&f_body);
    for i in 0..3 {
        assert!((loads[i] - f_body[i]).abs() < 1e-15, "force {i}");
        assert!((loads[3 + i] - moment[i]).abs() < 1e-15, "moment {i}");
    }
    // Planar: the vertical component x F_y − y F_x.
    let scene = parse(&planar(
        "planar-g",
        "",
        "force_body = [3.0, 1.0]\nforce_body_at = [-0.5, 0.25]",
    ))
    .unwrap();
    let mut out = [0.0; 3];
    scene.loads.inputs(&[0.0; 6], &mut out);
    assert_eq!(out, [3.0, 1.0, -0.5 * 1.0 - 0.25 * 3.0]);
}

#[test]
fn a_force_through_g_gives_no_moment() {
    let (state, _) = tilted(0.4, -0.3, 1.1);
    // At G, and at a point on the force's line through G (r = F/2, exact in binary).
    for at in [
        "",
        "force_body_at = [2.0, -0.5, 1.25]",
        "force_body_at = [0.0, 0.0, 0.0]",
    ] {
        let scene = parse(&spatial(
            "",
            &format!("force_body = [4.0, -1.0, 2.5]\n{at}"),
            ADAPTIVE,
        ))
        .unwrap();
        assert_eq!(inputs(&scene, &state)[3..], [0.0; 3], "{at}");
    }
    let scene = parse(&planar(
        "planar-space",
        "",
        "force_space = [3.0, 1.0]\nforce_space_at = [1.5, 0.5]",
    ))
    .unwrap();
    let mut out = [0.0; 3];
    scene.loads.inputs(&[0.0; 6], &mut out);
    assert_eq!(out[2], 0.0);
}

#[test]
fn a_space_force_at_a_point_keeps_the_energy_of_its_potential() {
    // A constant space force off G swings the body like a pendulum about G: conservative,
    // with potential −F·r_P; DOP853 at 1e-10 keeps T + V to 1e-9 of the scale.
    let scene = parse(&spatial(
        "rates = [0.3, 0.1, 0.2]",
        "force_space = [0.0, 0.0, -20.0]\nforce_space_at = [0.0, 0.0, 0.4]",
        ADAPTIVE,
    ))
    .unwrap();
    assert!(scene.loads.has_potential());
    let mut rows = Rows::default();
    let report = run(&scene, &mut rows).unwrap();
    let drift = report.energy_drift.unwrap();
    assert!(drift < 1e-9, "energy drift {drift}");
    // It does swing: the pitch rate changes by more than a tenth.
    let q: Vec<f64> = rows.0.iter().map(|(_, s)| s[4]).collect();
    assert!(q.iter().any(|x| (x - q[0]).abs() > 0.1));
}

#[test]
fn a_point_without_its_force_or_of_the_wrong_length_is_refused() {
    let message = error_of(&spatial("", "force_space_at = [0.0, 0.0, 1.0]", ADAPTIVE));
    assert!(message.contains("`loads.force_space_at`: is given without loads.force_space"));
    let message = error_of(&spatial(
        "",
        "force_body = [1.0, 0.0, 0.0]\nforce_body_at = [0.0, 1.0]",
        ADAPTIVE,
    ));
    assert!(
        message.contains("`loads.force_body_at`: must have 3 entries"),
        "{message}"
    );
    let message = error_of(&planar(
        "planar-g",
        "",
        "force_body = [1.0, 0.0]\nforce_body_at = [0.0, inf]",
    ));
    assert!(message.contains("loads.force_body_at[1]"), "{message}");
}

#[test]
fn lie_midpoint_under_uniform_gravity_turns_free_and_falls_as_half_g_t_squared() {
    let lie = "method = \"lie-midpoint\"\nstep = 0.001";
    let initial = "velocity = [1.0, -0.5, -2.0]\nrates = [0.001, 6.0, 0.002]\n\
                   attitude_deg = [10.0, 20.0, 30.0]";
    let falling = parse(&spatial(initial, "gravity = 9.81", lie)).unwrap();
    let free = parse(&spatial(initial, "", lie)).unwrap();
    let (falling, free) = (rows_of(&falling), rows_of(&free));
    assert_eq!(falling.len(), 201);
    let (attitude, _) = tilted(10f64.to_radians(), 20f64.to_radians(), 30f64.to_radians());
    let q = UnitQuaternion::from_quaternion(
        [attitude[10], attitude[11], attitude[12], attitude[9]].into(),
    );
    let v0 = q * Vector3::new(1.0, -0.5, -2.0);
    let g = 9.81;
    for ((t, fall), (_, turn)) in falling.iter().zip(&free) {
        // The rotation: p, q, r and the quaternion bit for bit the torque-free run's.
        assert_eq!(fall[3..6], turn[3..6], "rates at t = {t}");
        assert_eq!(fall[9..], turn[9..], "attitude at t = {t}");
        // The fall: x₀ + V₀ t + ½ g t² Z.
        let expected = v0 * *t + Vector3::new(0.0, 0.0, 0.5 * g * t * t);
        let position = Vector3::from_column_slice(&fall[6..9]);
        assert!(
            (position - expected).norm() <= 1e-12 * expected.norm().max(1.0),
            "t = {t}: {position} against {expected}"
        );
        // The body velocity is Rᵀ(V₀ + g t Z).
        let a = &fall[9..];
        let q_t = UnitQuaternion::from_quaternion([a[1], a[2], a[3], a[0]].into());
        let v_space = q_t * Vector3::from_column_slice(&fall[..3]);
        let expected = v0 + Vector3::new(0.0, 0.0, g * t);
        assert!((v_space - expected).norm() <= 1e-12 * expected.norm());
    }
    // Any other load still refuses the method, naming it.
    let message = error_of(&spatial(initial, "gravity = 9.81\nbuoyancy = 1.0", lie));
    assert!(message.contains("integrator.method"), "{message}");
}
