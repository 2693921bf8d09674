//! Inputs that `tests/fuzz_inputs.rs` found, each once a panic, an abort or an untyped
//! failure, kept as they were found.

use eom::scene::{Problem, Scene, SceneError};
use std::path::PathBuf;

fn scenes() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenes")
}

fn parse_scene(text: &str) -> Result<Scene, SceneError> {
    Scene::parse(text, "found.toml", &scenes())
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
