//! A run evaluates a scene's loads through [`SceneLoads::prepared`], which decides once which
//! of them act. These tests hold it to the scene's own [`SceneLoads::inputs_at`] at random
//! states and times, for every family and for each kind of load alone, all together and
//! none, forces at points and loads given as time tables included.

use eom::kinds::body::{BodyScene, SceneLoads};
use eom::models::Loads;
use proptest::prelude::*;
use std::path::Path;

/// The scene file `scenes/{name}.toml` with its `[loads]` table replaced by `loads`.
fn with_loads(name: &str, loads: &str) -> BodyScene {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let text = std::fs::read_to_string(root.join(format!("{name}.toml"))).expect("the scene");
    let mut kept = String::new();
    let mut in_loads = false;
    for line in text.lines() {
        if line.starts_with('[') {
            in_loads = line.trim() == "[loads]";
        }
        if !in_loads {
            kept.push_str(line);
            kept.push('\n');
        }
    }
    let text = format!("{kept}\n[loads]\n{loads}\n");
    BodyScene::parse(&text, &format!("{name}.toml"), &root)
        .unwrap_or_else(|e| panic!("{name} with {loads:?}: {e}"))
}

/// Each family's scene, and its loads one kind at a time, all at once, and none.
fn scenes() -> Vec<(String, BodyScene)> {
    let families: [(&str, &[&str]); 5] = [
        (
            "pendulum",
            &[
                "moment = 0.3",
                "linear_damping = [0.2]",
                "quadratic_damping = [0.05]",
            ],
        ),
        (
            "heavy_top",
            &[
                "moment_body = [0.1, -0.2, 0.05]",
                "linear_damping = [0.1, 0.2, 0.3]",
                "quadratic_damping = [0.01, 0.02, 0.03]",
            ],
        ),
        (
            "planar_drift",
            &[
                "force_body = [2.0, -1.0]",
                "force_space = [0.5, 1.5]",
                "moment = -0.4",
                "linear_damping = [1.0, 2.0, 0.5]",
                "quadratic_damping = [0.1, 0.3, 0.2]",
            ],
        ),
        (
            "puck_in_wind",
            &[
                "force_body = [2.0, -1.0]",
                "force_space = [0.5, 1.5]",
                "moment = -0.4",
                "linear_damping = [1.0, 2.0, 0.5]",
            ],
        ),
        (
            "auv",
            &[
                "gravity = 9.81",
                "buoyancy = 500.0\nbuoyancy_centre = [0.0, 0.0, -0.05]",
                "force_body = [40.0, 0.0, 1.0]",
                "force_space = [1.0, -2.0, 3.0]",
                "moment_body = [0.1, 0.2, -0.3]",
                "moment_space = [-0.5, 0.4, 0.1]",
                "linear_damping = [10.0, 40.0, 40.0, 5.0, 20.0, 20.0]",
                "quadratic_damping = [20.0, 120.0, 120.0, 2.0, 30.0, 30.0]",
            ],
        ),
    ];
    let mut scenes = Vec::new();
    for (name, kinds) in families {
        scenes.push((format!("{name}, none"), with_loads(name, "")));
        for kind in kinds {
            scenes.push((format!("{name}, {kind}"), with_loads(name, kind)));
        }
        scenes.push((format!("{name}, all"), with_loads(name, &kinds.join("\n"))));
    }
    let quaternion = with_loads(
        "tennis_racket",
        "gravity = 9.81\nlinear_damping = [1, 1, 1, 1, 1, 1]",
    );
    scenes.push(("tennis_racket, gravity and damping".into(), quaternion));
    scenes.push((
        "tennis_racket, none".into(),
        with_loads("tennis_racket", ""),
    ));
    let step = |values: &str| {
        format!("{{ times = [0.5, 1.5], values = {values}, interpolation = \"step\" }}")
    };
    let ramp = |values: &str| {
        format!("{{ times = [0.0, 1.0, 2.5], values = {values}, interpolation = \"linear\" }}")
    };
    let timed = [
        (
            "auv",
            format!(
                "force_body = {}\nforce_body_at = [0.1, -0.2, 0.3]\nforce_space = {}\n\
                 force_space_at = [-0.4, 0.0, 0.2]\nmoment_body = {}\nmoment_space = {}\n\
                 gravity = 9.81",
                step("[[1.0, 2.0, 3.0], [-1.0, 0.5, 0.0]]"),
                ramp("[[0.0, 0.0, 0.0], [4.0, -2.0, 1.0], [1.0, 1.0, 1.0]]"),
                ramp("[[0.3, 0.0, 0.0], [0.0, 0.2, 0.0], [0.0, 0.0, -0.1]]"),
                step("[[0.5, 0.5, 0.0], [0.0, -0.5, 0.5]]"),
            ),
        ),
        (
            "planar_drift",
            format!(
                "force_body = {}\nforce_body_at = [0.5, -0.25]\nforce_space = {}\n\
                 force_space_at = [-1.0, 0.5]\nmoment = {}",
                step("[[2.0, 1.0], [0.0, -1.0]]"),
                ramp("[[0.0, 0.0], [1.0, 2.0], [3.0, 0.0]]"),
                ramp("[0.0, 1.0, -1.0]"),
            ),
        ),
        (
            "puck_in_wind",
            format!(
                "force_space = {}\nforce_space_at = [0.01, 0.0]",
                step("[[0.0, 0.05], [0.05, 0.0]]")
            ),
        ),
        ("pendulum", format!("moment = {}", step("[0.2, -0.3]"))),
        (
            "heavy_top",
            format!(
                "moment_body = {}",
                ramp("[[0.0, 0.0, 0.0], [0.1, 0.0, 0.0], [0.0, 0.0, 0.2]]")
            ),
        ),
    ];
    for (name, loads) in timed {
        scenes.push((
            format!("{name}, timed and at points"),
            with_loads(name, &loads),
        ));
    }
    scenes
}

/// The inputs both ways at time `t` and one state of `N` entries and `M` inputs.
fn both_at<const N: usize, const M: usize>(
    loads: &SceneLoads,
    t: f64,
    state: &[f64],
) -> [Vec<f64>; 2] {
    let state: [f64; N] = std::array::from_fn(|i| state[i]);
    let mut direct = [0.0; M];
    loads.inputs_at(t, &state, &mut direct);
    let prepared = Loads::<f64, N, M>::at(&loads.prepared(), t, &state);
    [direct.to_vec(), prepared.to_vec()]
}

/// The scene's inputs at `state`, directly and prepared, for each family's state and input
/// sizes (a planar body and a top with Euler angles both have 6 and 3).
fn both(loads: &SceneLoads, t: f64, state: &[f64]) -> [Vec<f64>; 2] {
    match state.len() {
        2 => both_at::<2, 1>(loads, t, state),
        6 => both_at::<6, 3>(loads, t, state),
        7 => both_at::<7, 3>(loads, t, state),
        12 => both_at::<12, 6>(loads, t, state),
        13 => both_at::<13, 6>(loads, t, state),
        n => panic!("a state of {n} entries"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Equal at every state. `==`, not bit for bit: the scene's own form adds every load,
    /// a damping of zero included, which can turn a zero input's sign (−0 for +0, the same
    /// force); every other input is the same operations in the same order.
    #[test]
    fn prepared_loads_are_the_scene_loads(
        state in prop::collection::vec(-3.0..3.0f64, 13),
        t in prop::sample::select(vec![0.0, 0.3, 0.5, 1.0, 1.2, 1.5, 2.5, 4.0]),
    ) {
        for (name, scene) in scenes() {
            let n = scene.initial.len();
            let mut state = state[..n].to_vec();
            if n == 13 {
                // A quaternion's attitude: normalised, as a run keeps it.
                let norm = state[9..].iter().map(|x| x * x).sum::<f64>().sqrt().max(1e-3);
                state[9..].iter_mut().for_each(|x| *x /= norm);
            }
            let loads = &scene.loads;
            let [direct, prepared] = both(loads, t, &state);
            prop_assert_eq!(&direct, &prepared, "{} at t = {}", name, t);
            if loads.is_free() {
                prop_assert!(prepared.iter().all(|x| *x == 0.0), "{name}: {prepared:?}");
            }
        }
    }
}

/// A load that acts is never dropped: each scene with loads gives some non-zero input at a
/// moving, tilted state (a test that `prepared` could not pass by returning zeros).
#[test]
fn every_acting_load_reaches_the_inputs() {
    for (name, scene) in scenes() {
        if scene.loads.is_free() {
            continue;
        }
        let n = scene.initial.len();
        let mut state = vec![0.7; n];
        if n == 13 {
            state[9..].copy_from_slice(&[0.5; 4]);
        }
        let [direct, prepared] = both(&scene.loads, 1.2, &state);
        assert!(prepared.iter().any(|x| *x != 0.0), "{name}: {prepared:?}");
        assert_eq!(direct, prepared, "{name}");
    }
}

/// The spatial loads written out by hand at one state: every force and moment, gravity and
/// buoyancy turned into body axes by the attitude's rotation (transposed), damping on the
/// body velocities. Agreement to 1e-12 of the largest term (the two sum the same terms in
/// another order).
#[test]
fn spatial_loads_by_hand() {
    use nalgebra::{Rotation3, Vector3};
    let loads = [
        "gravity = 9.81",
        "buoyancy = 500.0\nbuoyancy_centre = [0.01, -0.02, -0.05]",
        "force_body = [40.0, 0.0, 1.0]\nforce_space = [1.0, -2.0, 3.0]",
        "moment_body = [0.1, 0.2, -0.3]\nmoment_space = [-0.5, 0.4, 0.1]",
        "linear_damping = [10.0, 40.0, 40.0, 5.0, 20.0, 20.0]",
        "quadratic_damping = [20.0, 120.0, 120.0, 2.0, 30.0, 30.0]",
    ]
    .join("\n");
    let scene = with_loads("auv", &loads);
    let mass = 50.0;
    let state = [
        0.8, -0.3, 0.2, 0.4, -0.6, 0.25, 1.0, 2.0, 3.0, 0.3, -0.4, 2.0,
    ];
    let to_body = Rotation3::from_euler_angles(state[9], state[10], state[11]).inverse();
    let velocity = Vector3::new(state[0], state[1], state[2]);
    let rates = Vector3::new(state[3], state[4], state[5]);
    let damping = |x: Vector3<f64>, linear: [f64; 3], quadratic: [f64; 3]| {
        Vector3::from_fn(|i, _| -linear[i] * x[i] - quadratic[i] * x[i] * x[i].abs())
    };
    let buoyancy = to_body * Vector3::new(0.0, 0.0, -500.0);
    let force = Vector3::new(40.0, 0.0, 1.0)
        + to_body * Vector3::new(1.0, -2.0, 3.0)
        + to_body * Vector3::new(0.0, 0.0, mass * 9.81)
        + buoyancy
        + damping(velocity, [10.0, 40.0, 40.0], [20.0, 120.0, 120.0]);
    let moment = Vector3::new(0.1, 0.2, -0.3)
        + to_body * Vector3::new(-0.5, 0.4, 0.1)
        + Vector3::new(0.01, -0.02, -0.05).cross(&buoyancy)
        + damping(rates, [5.0, 20.0, 20.0], [2.0, 30.0, 30.0]);
    let [direct, prepared] = both(&scene.loads, 0.0, &state);
    let expected: Vec<f64> = force.iter().chain(moment.iter()).copied().collect();
    let scale = expected.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    for (i, ((d, p), e)) in direct.iter().zip(&prepared).zip(&expected).enumerate() {
        assert!((p - e).abs() <= 1e-12 * scale, "input {i}: {p} against {e}");
        assert_eq!(d.to_bits(), p.to_bits(), "input {i}");
    }
}
