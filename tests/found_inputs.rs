//! Inputs that `app/tests/fuzz_inputs.rs` found, each once a panic, an abort or an untyped
//! failure, kept as they were found.

use eom::kinds::body::BodyScene;
use eom::scene::{Problem, SceneError, sweep};
use std::path::PathBuf;

fn scenes() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenes")
}

fn parse_scene(text: &str) -> Result<BodyScene, SceneError> {
    BodyScene::parse(text, "found.toml", &scenes())
}

/// A tensor of 1e-303 kg m² is a valid tensor, but its determinant underflows: the scene was
/// accepted and `Scene::model` panicked on its `expect`.
#[test]
fn a_tensor_whose_determinant_underflows_is_refused_when_the_scene_is_read() {
    let text = r#"title = "Free precession of a spinning plate"
[body]
inertia = [[1e-303, 0.0, 0.0], [0.0, 1e-303, 0.0], [0.0, 0.0, 2e-303]]
mass = 2e-301
[model]
family = "spatial"
[integrator]
method = "dop853"
end_time = 2.0
"#;
    let error = parse_scene(text).unwrap_err();
    assert_eq!(error.key, "body.inertia");
    assert!(matches!(error.problem, Problem::Invalid(_)), "{error}");
    assert!(error.to_string().contains("cannot be inverted"), "{error}");
}

const PENDULUM: &str = r#"title = "t"
[body]
i0 = 2.0
mass = 1.0
g = 9.81
h = 0.5
[model]
family = "pendulum"
[integrator]
method = "rk4"
step = 0.01
end_time = 1.0
[sweep]
"#;

/// `count = 9223372036854775807` panicked ("capacity overflow") making the range's values,
/// and `count = 1000000000000` aborted the process (an allocation of 32 TB failed).
#[test]
fn a_range_of_more_values_than_a_sweep_may_have_is_refused() {
    for count in ["9223372036854775807", "1000000000000", "100001"] {
        let text =
            format!("{PENDULUM}\"body.mass\" = {{ from = 1.0, to = 2.0, count = {count} }}\n");
        let error = sweep::cases(&text, "found.toml").unwrap_err();
        assert_eq!(error.key, "sweep.body.mass");
        assert!(matches!(error.problem, Problem::Invalid(_)), "{error}");
    }
    let most = format!(
        "{PENDULUM}\"body.mass\" = {{ from = 1.0, to = 2.0, count = {} }}\n",
        sweep::MAX_CASES
    );
    assert_eq!(
        sweep::cases(&most, "found.toml").unwrap().len(),
        sweep::MAX_CASES
    );
}

/// Sixty-four keys of two values each: the count of cases overflowed, a panic in a debug
/// build and, wrapped to 0, a sweep of no cases at all in a release build.
#[test]
fn a_sweep_whose_combinations_overflow_is_refused() {
    let mut text = PENDULUM.to_owned();
    for i in 0..64 {
        text += &format!("\"initial.theta_deg{i:02}\" = [1.0, 2.0]\n");
    }
    let error = sweep::cases(&text, "found.toml").unwrap_err();
    assert!(matches!(error.problem, Problem::Invalid(_)), "{error}");
    // 2¹⁷ > 100 000: the key that crosses the limit is named.
    assert_eq!(error.key, "sweep.initial.theta_deg16");
}

/// `end_time = 5e-324` and no `output.every`: the default spacing of rows, end_time / 500,
/// was 0, and the scene was accepted with rows 0 s apart, which a run never gets past.
#[test]
fn an_end_time_too_short_to_divide_into_rows_is_refused() {
    let text = r#"title = "swept pendulum"
[body]
g = 9.81
h = 0.5
i0 = 2.0
mass = 1.0
[integrator]
end_time = 5e-324
method = "rk4"
step = 0.01
[model]
family = "pendulum"
"#;
    let error = parse_scene(text).unwrap_err();
    assert_eq!(error.key, "integrator.end_time");
    assert!(matches!(error.problem, Problem::Invalid(_)), "{error}");
    // With rows of its own, the same end time is a run of one row.
    let scene = parse_scene(&text.replace("[model]", "[output]\nevery = 5e-324\n[model]")).unwrap();
    assert_eq!(scene.every, 5e-324);
}

/// Rows 1e-300 s apart over 1 s would make the fixed-step driver list 10³⁰⁰ stop times: the
/// scene is refused, naming output.every.
#[test]
fn a_trajectory_of_more_rows_than_the_limit_is_refused() {
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/looping.toml"),
    )
    .unwrap()
    .replace("every = 0.01", "every = 1e-300");
    let error =
        BodyScene::parse(&text, "looping.toml", std::path::Path::new("scenes")).unwrap_err();
    assert_eq!(error.key, "output.every", "{error}");
}
