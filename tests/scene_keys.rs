//! The scene keys that say more than where a body starts and what constant load acts at G:
//! an initial velocity in space axes, a force at a point of the body, and uniform gravity
//! under the geometric integrator. Each is held to its closed form: v = Rᵀ V for the
//! velocity, r_P × F for the moment, torque-free rotation and ½ g t² for the fall.

use eom::kinds::body::{BodyScene, run};
use eom::run::{Row, Sink};
use eom::scene::SceneError;
use nalgebra::{Rotation3, UnitQuaternion, Vector3};
use std::path::Path;

/// A scene from its text, read as `eom run` reads a file.
fn parse(text: &str) -> Result<BodyScene, SceneError> {
    BodyScene::parse(text, "scene.toml", Path::new("."))
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

fn rows_of(scene: &BodyScene) -> Vec<(f64, Vec<f64>)> {
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
fn inputs(scene: &BodyScene, state: &[f64]) -> Vec<f64> {
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

/// The report and the rows of a run.
fn run_rows(scene: &BodyScene) -> (eom::kinds::body::Report, Vec<(f64, Vec<f64>)>) {
    let mut rows = Rows::default();
    let report = run(scene, &mut rows).unwrap();
    (report, rows.0)
}

#[test]
fn a_dropped_body_stops_where_it_has_fallen_ten_metres() {
    // z = ½ g t² passes 10 m at √(2·10/g). The methods below are exact for a quadratic in t
    // (DOP853 and DOPRI5 with their dense output, RK4, lie-midpoint's exact translation), so
    // the time found is the exact one to rounding: 1e-12 s.
    let g: f64 = 9.81;
    let exact = (2.0 * 10.0 / g).sqrt();
    let methods = [
        ADAPTIVE.to_owned(),
        "method = \"dopri5\"\nrtol = 1e-10\natol = 1e-10".to_owned(),
        "method = \"rk4\"\nstep = 0.01".to_owned(),
        "method = \"lie-midpoint\"\nstep = 0.01".to_owned(),
    ];
    for method in methods {
        let text = spatial(
            "",
            "gravity = 9.81",
            &format!("{method}\nstop_when = \"z > 10\""),
        );
        let scene = parse(&text).unwrap();
        let (report, rows) = run_rows(&scene);
        let t = report
            .stopped_at
            .unwrap_or_else(|| panic!("{method}: did not stop"));
        assert!(
            (t - exact).abs() < 1e-12,
            "{method}: {t} against {exact}, {:e}",
            t - exact
        );
        assert_eq!(report.final_time, t);
        let (last_t, last) = rows.last().unwrap();
        assert_eq!(*last_t, t);
        // The last row is just past the crossing, and every row before it on the grid.
        assert!(
            last[8] > 10.0 && last[8] - 10.0 < 1e-10,
            "{method}: z = {}",
            last[8]
        );
        assert_eq!(rows.len(), 144, "{method}");
        for (k, (time, state)) in rows[..rows.len() - 1].iter().enumerate() {
            assert_eq!(*time, k as f64 * 0.01);
            assert!(state[8] <= 10.0);
        }
    }
}

#[test]
fn a_condition_on_time_stops_there_and_one_that_never_holds_runs_to_the_end() {
    let text = spatial(
        "rates = [0.001, 6.0, 0.002]",
        "",
        &format!("{ADAPTIVE}\nstop_when = \"t >= 1.5\""),
    );
    let (report, rows) = run_rows(&parse(&text).unwrap());
    assert_eq!(report.stopped_at, Some(1.5));
    assert_eq!(rows.len(), 151);
    let text = spatial("", "", &format!("{ADAPTIVE}\nstop_when = \"z > 10\""));
    let (report, rows) = run_rows(&parse(&text).unwrap());
    assert_eq!(
        (report.stopped_at, report.final_time, rows.len()),
        (None, 2.0, 201)
    );
}

#[test]
fn a_bad_stop_condition_is_refused_naming_the_key() {
    let with = |condition: &str| {
        error_of(&spatial(
            "position = [0.0, 0.0, 12.0]",
            "",
            &format!("{ADAPTIVE}\nstop_when = \"{condition}\""),
        ))
    };
    let message = with("height > 10");
    assert!(message.contains("`integrator.stop_when`: unknown name `height`; one of t, u, v, w, p, q, r, x, y, z, q0, q1, q2, q3"), "{message}");
    let message = with("z > 10");
    assert!(message.contains("holds at the start (12)"), "{message}");
    let message = with("z = 10");
    assert!(
        message.contains("`integrator.stop_when`: no comparison"),
        "{message}"
    );
}

/// A spinning body's scene under `moment_body` given as `table`, with `integrator` lines,
/// rows every 0.3 s (so that t = 1 is not a row time).
fn torqued(table: &str, integrator: &str, end: f64) -> BodyScene {
    let text = format!(
        "title = \"t\"\n[body]\nmass = 2.0\n\
         inertia = [[2.0, 0.0, 0.0], [0.0, 3.0, 0.0], [0.0, 0.0, 4.5]]\n\
         [model]\nfamily = \"spatial\"\n[loads]\nmoment_body = {table}\n\
         [integrator]\n{integrator}\nend_time = {end}\n[output]\nevery = 0.3\n"
    );
    parse(&text).unwrap()
}

const SWITCHED_ON: &str = "{ times = [0.0, 1.0], values = [[0.0, 0.0, 0.0], [0.0, 0.0, 0.9]], \
                           interpolation = \"step\" }";

#[test]
fn a_torque_switched_on_at_one_second_gives_the_exact_rate_at_two() {
    // About a principal axis, ṙ = N/I_zz from t = 1 on: r(2) = 0.9·1/4.5 = 0.2 rad/s.
    let exact = 0.9 * (2.0 - 1.0) / 4.5;
    let methods = [
        ("dop853", ADAPTIVE.to_owned()),
        (
            "dopri5",
            "method = \"dopri5\"\nrtol = 1e-10\natol = 1e-10".to_owned(),
        ),
        ("rk4", "method = \"rk4\"\nstep = 0.07".to_owned()),
        ("euler", "method = \"euler\"\nstep = 0.07".to_owned()),
    ];
    for (name, integrator) in methods {
        let scene = torqued(SWITCHED_ON, &integrator, 2.0);
        assert!(!scene.loads.has_potential());
        let (report, rows) = run_rows(&scene);
        let r = report.final_state[5];
        assert!(
            (r - exact).abs() < 1e-12,
            "{name}: r(2) = {r}, {:e} off",
            r - exact
        );
        // Before the switch nothing turns; after it r grows linearly.
        for (t, state) in &rows {
            let expected = 0.9 * (t - 1.0).max(0.0) / 4.5;
            assert!(
                (state[5] - expected).abs() < 1e-12,
                "{name} at t = {t}: {}",
                state[5]
            );
        }
    }
}

#[test]
fn a_step_integrated_across_without_the_cut_errs_where_the_cut_run_does_not() {
    // The same torque integrated by DOP853 through t = 1 (the loads read at each time, no
    // cut): the error estimate meets the jump and the step control must shrink across it.
    use eom::integrate::{AdaptiveOptions, Dop853, Integrator, Statistics};
    use eom::models::Model;
    let scene = torqued(SWITCHED_ON, ADAPTIVE, 2.0);
    let (cut, _) = run_rows(&scene);
    let mut uncut = None;
    scene.model().visit(Uncut {
        loads: &scene.loads,
        initial: &scene.initial,
        out: &mut uncut,
    });
    let (r, steps) = uncut.unwrap();
    let exact = 0.2;
    println!(
        "r(2): cut {:e} off in {} steps, uncut {:e} off in {steps} steps",
        cut.final_state[5] - exact,
        cut.steps,
        r - exact
    );
    assert!((cut.final_state[5] - exact).abs() < 1e-12);
    // Measured: 8e-17 off in 12 steps with the cut, 4.0e-9 in 31 without it.
    assert!(
        (r - exact).abs() > 1e-10,
        "the uncut run erred by only {:e}",
        r - exact
    );

    struct Uncut<'a> {
        loads: &'a eom::kinds::body::SceneLoads,
        initial: &'a [f64],
        out: &'a mut Option<(f64, usize)>,
    }
    impl eom::models::Visitor for Uncut<'_> {
        type Output = ();
        fn visit<Mo: Model<f64, N, M>, const N: usize, const M: usize>(self, model: &Mo) {
            let system = model.driven_by(self.loads.clone());
            let mut method = Dop853::new(AdaptiveOptions::dop853(1e-10, 1e-10));
            let y0 = nalgebra::SVector::<f64, N>::from_column_slice(self.initial);
            let y = method.integrate(&system, 0.0, y0, 2.0).unwrap();
            *self.out = Some((y[5], method.stats().steps));
        }
    }
}

#[test]
fn a_ramp_is_followed_and_its_last_value_held() {
    // N(t) = 0.9 t/2 up to t = 2, then 0.9: r = 0.9 t²/(4·4.5) to t = 2, then 0.2 + 0.9(t − 2)/4.5.
    let ramp = "{ times = [0.0, 2.0], values = [[0.0, 0.0, 0.0], [0.0, 0.0, 0.9]], \
                interpolation = \"linear\" }";
    let scene = torqued(ramp, ADAPTIVE, 3.0);
    let (_, rows) = run_rows(&scene);
    for (t, state) in &rows {
        let expected = if *t <= 2.0 {
            0.9 * t * t / (4.0 * 4.5)
        } else {
            0.2 + 0.9 * (t - 2.0) / 4.5
        };
        assert!(
            (state[5] - expected).abs() < 1e-12,
            "t = {t}: {} against {expected}",
            state[5]
        );
    }
    // Before a table's first time its first value holds: a table starting at t = 1 with
    // 0.9 acts from t = 0.
    let late = "{ times = [1.0, 5.0], values = [[0.0, 0.0, 0.9], [0.0, 0.0, 0.9]], \
                interpolation = \"linear\" }";
    let (report, _) = run_rows(&torqued(late, ADAPTIVE, 2.0));
    assert!((report.final_state[5] - 0.4).abs() < 1e-12);
}

#[test]
fn a_planar_force_table_pushes_from_its_switch() {
    // u̇ = F/m from t = 0.5: u(1) = 4·0.5/2 = 1 m/s.
    let scene = parse(&planar(
        "planar-g",
        "",
        "force_body = { times = [0.0, 0.5], values = [[0.0, 0.0], [4.0, 0.0]], interpolation = \"step\" }",
    ))
    .unwrap();
    let (report, _) = run_rows(&scene);
    assert!(
        (report.final_state[0] - 1.0).abs() < 1e-12,
        "{}",
        report.final_state[0]
    );
}

#[test]
fn a_bad_time_table_is_refused_naming_its_entry() {
    let cases = [
        (
            "{ times = [0.0, 1.0, 1.0], values = [[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, 2.0]], interpolation = \"step\" }",
            "`loads.moment_body.times[2]`: must be after the time before it",
        ),
        (
            "{ times = [0.0], values = [[0.0, 0.0]], interpolation = \"step\" }",
            "`loads.moment_body.values[0]`: must have 3 entries, got 2",
        ),
        (
            "{ times = [0.0], values = [[0.0, 0.0, 0.0]], interpolation = \"cubic\" }",
            "`loads.moment_body.interpolation`: unknown value `cubic`; one of linear, step",
        ),
        (
            "{ times = [0.0], values = [[0.0, 0.0, 0.0]] }",
            "`loads.moment_body.interpolation`: missing",
        ),
        (
            "{ times = [0.0], value = [[0.0, 0.0, 0.0]], interpolation = \"step\" }",
            "`loads.moment_body.value`: unknown field",
        ),
        (
            "\"strong\"",
            "`loads.moment_body`: invalid type: string \"strong\", expected a constant, or a time table",
        ),
        (
            "[1.0, 2.0]",
            "`loads.moment_body`: must have 3 entries, got 2",
        ),
    ];
    for (table, expected) in cases {
        let text = spatial("", &format!("moment_body = {table}"), ADAPTIVE);
        let message = error_of(&text);
        assert!(message.contains(expected), "{table}: {message}");
    }
}

/// An unknown key is told with the keys the scene's own family takes in that table, not every
/// family's (serde's list is the table's whole union: a planar body was offered `i0`).
#[test]
fn an_unknown_key_lists_only_its_familys_keys() {
    let text = "title = \"x\"\n[body]\nmass = 1.0\nizz = 2.0\nfoo = 1\n[model]\nfamily = \
                \"planar-g\"\n[integrator]\nmethod = \"rk4\"\nstep = 0.1\nend_time = 1.0\n";
    let error = BodyScene::parse(text, "x.toml", std::path::Path::new("."))
        .unwrap_err()
        .to_string();
    assert!(
        error.contains("`body.foo`") && error.contains("planar-g scene's [body] takes mass, izz"),
        "{error}"
    );
    assert!(!error.contains("i0"), "{error}");
    // Through the reader of any kind (a sweep's case) the same.
    let table: toml::Table = text.parse().unwrap();
    let error = eom::scene::AnyScene::from_table(table, "x.toml", std::path::Path::new("."))
        .err()
        .unwrap()
        .to_string();
    assert!(
        error.contains("takes mass, izz") && !error.contains("i0"),
        "{error}"
    );
}
