//! The emitted source of every model, byte for byte, against the files in `tests/golden/`.
//!
//! A change to the engine, the derivations or the emitter that changes generated code shows
//! up here as a diff to review. After reviewing, regenerate the files with
//! `EOM_BLESS=1 cargo test -p eom-codegen --test golden`.

use eom_codegen::emit::generate;
use eom_codegen::model::Model;
use std::path::PathBuf;

fn golden_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/golden")
        .join(format!("{name}.rs"))
}

#[test]
fn emitted_source_matches_the_golden_files() {
    let bless = std::env::var_os("EOM_BLESS").is_some();
    let mut stale = Vec::new();
    for model in Model::all() {
        let generated = generate(model).unwrap_or_else(|e| panic!("{e}"));
        let path = golden_path(&generated.name);
        if bless {
            std::fs::write(&path, &generated.source).unwrap();
        } else if std::fs::read_to_string(&path).ok().as_deref() != Some(generated.source.as_str())
        {
            stale.push(generated.name);
        }
    }
    assert!(
        stale.is_empty(),
        "generated code differs from tests/golden for {stale:?}; review, then run \
         `EOM_BLESS=1 cargo test -p eom-codegen --test golden`"
    );
}

#[test]
fn generating_twice_gives_the_same_bytes() {
    for model in Model::all() {
        assert_eq!(
            generate(model).unwrap().source,
            generate(model).unwrap().source
        );
    }
}

#[test]
fn models_with_angles_are_exactly_those_with_trigonometry() {
    for model in Model::all() {
        let trig = generate(model).unwrap().operations.trig;
        assert_eq!(model.has_angles(), trig > 0, "{}", model.name());
    }
}

#[test]
fn euler_variants_call_sin_cos_once_per_angle_and_never_tan() {
    for model in Model::all() {
        let generated = generate(model).unwrap();
        if generated.name.ends_with("_euler") {
            // One kernel call for the angles, each angle's pair bound once. A spatial model
            // reads all three; the top's weight and rates do not depend on its heading ψ.
            let source = &generated.source;
            let start = source.find("pub fn rhs").unwrap();
            let end = source.find("pub const STATE_JACOBIAN").unwrap();
            let rhs = &source[start..end];
            assert_eq!(
                rhs.matches("= eom_kernel::sin_cos([").count(),
                1,
                "{}",
                generated.name
            );
            let angles: &[&str] = match model {
                Model::Top { .. } => &["phi", "theta"],
                _ => &["phi", "theta", "psi"],
            };
            for angle in angles {
                let pair = format!("(sin_{angle}, cos_{angle})");
                assert_eq!(rhs.matches(&pair).count(), 1, "{pair}");
            }
            assert!(!source.contains("tan("), "{}", generated.name);
            assert_eq!(generated.operations.trig as usize, angles.len());
        }
    }
}

#[test]
fn pruning_removes_operations() {
    let cost = |name: &str| {
        let model = Model::all().into_iter().find(|m| m.name() == name).unwrap();
        let ops = generate(model).unwrap().operations;
        ops.add + ops.mul + ops.div
    };
    for kinematics in ["euler", "quaternion"] {
        let full = cost(&format!("spatial_full_{kinematics}"));
        let xz = cost(&format!("spatial_xz_{kinematics}"));
        let principal = cost(&format!("spatial_principal_{kinematics}"));
        assert!(
            principal < xz && xz < full,
            "{kinematics}: {principal} {xz} {full}"
        );
    }
}
