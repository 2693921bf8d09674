//! What every fuzz target checks: no panic (libFuzzer reports one with its input), every
//! refusal the crate's error with a message, and an accepted scene builds its model and runs.

use eom_cli::eval::evaluate;
use eom::mass::{BodyFile, Mesh, MeshMass};
use eom::models::{Family, Kinematics, Symmetry};
use eom::run::{Row, Sink};
use eom::kinds::aircraft::AircraftScene;
use eom::kinds::aircraft::manoeuvre::AircraftManoeuvre;
use eom::kinds::body::BodyScene;
use eom::scene::{AnyScene, Problem, SceneError, sweep};
use eom::kinds::ship::ShipScene;
use eom::kinds::vehicle::VehicleScene;
use eom::kinds::vehicle::manoeuvre::VehicleManoeuvre;
use nalgebra::Vector3;
use std::io::Cursor;
use std::path::{Path, PathBuf};

/// The example scenes' folder: a scene's `body.file` and a body's mesh `path` are found
/// relative to it.
pub fn scenes() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes")
}

/// Text that names a device or a kernel file: reading `/dev/zero` as a body file never ends,
/// which says nothing about the parsers.
pub fn names_a_device(text: &str) -> bool {
    ["/dev", "/proc", "/sys"].iter().any(|d| text.contains(d))
}

fn scene_error(error: &SceneError) {
    let message = match &error.problem {
        Problem::Read(e) => e.to_string(),
        Problem::Syntax(m) | Problem::Schema(m) | Problem::Missing(m) | Problem::Invalid(m) => {
            m.clone()
        }
        Problem::BodyFile(e) => e.to_string(),
    };
    assert!(!message.trim().is_empty(), "an empty message: {error:?}");
    if matches!(error.problem, Problem::Invalid(_) | Problem::BodyFile(_)) {
        assert!(
            !error.key.is_empty(),
            "a value refused without its key: {error}"
        );
    }
}

struct Rows(usize);

impl Sink for Rows {
    fn row(&mut self, row: &Row) -> bool {
        assert!(row.t.is_finite(), "a row at t = {}", row.t);
        self.0 += 1;
        true
    }
}

fn accepted(scene: &BodyScene) {
    let spec = &scene.integrator;
    assert!(scene.initial.iter().all(|x| x.is_finite()), "{scene:?}");
    assert!(
        scene.every > 0.0 && scene.every <= spec.end_time,
        "{scene:?}"
    );
    let _ = scene.model();
    // At most 0.01 s, 10 rows and 200 steps.
    let mut short = scene.clone();
    let spec = &mut short.integrator;
    spec.end_time = spec.end_time.min(0.01);
    spec.max_steps = spec.max_steps.min(200);
    if let Some(options) = &mut spec.adaptive {
        options.max_steps = options.max_steps.min(200);
    }
    if let Some(step) = &mut spec.step {
        *step = step.max(spec.end_time / 200.0);
    }
    short.every = short.every.clamp(spec.end_time / 10.0, spec.end_time);
    let mut rows = Rows(0);
    match eom::kinds::body::run(&short, &mut rows) {
        Ok(report) => assert_eq!(report.final_state.len(), scene.initial.len()),
        Err(error) => assert!(!error.to_string().trim().is_empty()),
    }
}

/// A vehicle scene read: its model was built and proved; the cruise found and 0.05 s of its
/// first manoeuvre run, at most 200 steps.
fn vehicle_accepted(scene: &VehicleScene) {
    let first = &scene.manoeuvres[0];
    let short = VehicleManoeuvre {
        duration: first.duration.min(0.05),
        ..first.clone()
    };
    let mut stepper = scene.stepper.clone();
    stepper.step = stepper.step.map(|step| step.max(short.duration / 200.0));
    let every = scene.every.max(short.duration / 10.0);
    let result = scene.start().and_then(|start| {
        eom::kinds::vehicle::manoeuvre::run(
            &scene.model,
            &scene.fins,
            &short,
            start,
            (&stepper, every),
            |sample| sample.t.is_finite(),
        )
    });
    if let Err(error) = result {
        assert!(!error.to_string().trim().is_empty());
    }
}

/// An aircraft scene read: trimmed to finite numbers, and 0.05 s of its first manoeuvre run
/// from the trim, at most 200 steps.
fn aircraft_accepted(scene: &AircraftScene) {
    let trim = (&scene.trim.state, &scene.trim.controls);
    assert!(
        trim.0.iter().chain(trim.1).all(|x| x.is_finite()),
        "a trim that is not finite: {:?}",
        scene.trim
    );
    let first = &scene.manoeuvres[0];
    let short = AircraftManoeuvre {
        duration: first.duration.min(0.05),
        ..first.clone()
    };
    let mut stepper = scene.stepper.clone();
    stepper.step = stepper.step.map(|step| step.max(short.duration / 200.0));
    let every = scene.every.max(short.duration / 10.0);
    let result = eom::kinds::aircraft::manoeuvre::run(
        &scene.model,
        scene.kinematics,
        &short,
        trim,
        (&stepper, every),
        None,
        |_| true,
    );
    if let Err(error) = result {
        assert!(!error.to_string().trim().is_empty());
    }
}

/// A ship scene read: its model was built and proved.
fn ship_accepted(scene: &ShipScene) {
    if let Err(error) = eom::kinds::ship::ShipModel::new(&scene.table) {
        assert!(!error.to_string().trim().is_empty());
    }
}

/// A scene's text through the one reader of every scene: read, checked, its sweep's cases
/// made, and what is accepted run briefly.
pub fn scene_text(text: &str) {
    if names_a_device(text) {
        return;
    }
    let base = scenes();
    match AnyScene::parse(text, "fuzz.toml", &base) {
        Ok(scene) => {
            let scene = scene.as_kind();
            if let Some(body) = scene.as_any().downcast_ref() {
                accepted(body);
            }
            if let Some(ship) = scene.as_any().downcast_ref() {
                ship_accepted(ship);
            }
            if let Some(vehicle) = scene.as_any().downcast_ref() {
                vehicle_accepted(vehicle);
            }
            if let Some(aircraft) = scene.as_any().downcast_ref() {
                aircraft_accepted(aircraft);
            }
        }
        Err(error) => scene_error(&error),
    }
    match sweep::cases(text, "fuzz.toml") {
        Ok(cases) => {
            for case in cases.iter().take(4) {
                match BodyScene::from_table(case.table.clone(), "fuzz.toml", &base) {
                    Ok(scene) => accepted(&scene),
                    Err(error) => scene_error(&error),
                }
            }
        }
        Err(error) => scene_error(&error),
    }
}

/// `eom eval`'s input, for every family and every spatial variant.
pub fn eval_json(text: &str) {
    let mut models = vec![
        (Family::Pendulum, Symmetry::Full, Kinematics::Euler),
        (Family::PlanarAtG, Symmetry::Full, Kinematics::Euler),
        (Family::PlanarMidship, Symmetry::Full, Kinematics::Euler),
        (Family::PlanarSpaceFixed, Symmetry::Full, Kinematics::Euler),
        (Family::Top, Symmetry::Full, Kinematics::Quaternion),
    ];
    for symmetry in Symmetry::ALL {
        for kinematics in Kinematics::ALL {
            models.push((Family::Spatial, symmetry, kinematics));
        }
    }
    for (family, symmetry, kinematics) in models {
        match evaluate(text, family, symmetry, kinematics) {
            Ok(evaluation) => {
                assert!(!evaluation.generated.is_empty());
                let values = evaluation.generated.iter().chain(&evaluation.generic);
                assert!(
                    values.into_iter().all(|(_, x)| x.is_finite()),
                    "{evaluation:?}"
                );
            }
            Err(error) => assert!(
                error.chain().all(|c| !c.to_string().trim().is_empty()),
                "{error:#}"
            ),
        }
    }
}

/// A body file, with meshes found in `scenes/bodies/`, and what `eom mass` prints of it.
pub fn body_file(text: &str) {
    if names_a_device(text) {
        return;
    }
    let body = match BodyFile::parse(text, &scenes().join("bodies")) {
        Ok(body) => body,
        Err(error) => return assert!(!error.to_string().trim().is_empty(), "{error:?}"),
    };
    match body.mass_properties() {
        Ok(properties) => {
            let principal = properties.principal();
            assert!(
                principal.moments.iter().all(|x| x.is_finite()),
                "{properties:?}"
            );
            assert!(properties.radii_of_gyration().iter().all(|x| x.is_finite()));
            if let Err(error) = properties.inertia_about(&Vector3::new(1.0, -2.0, 3.0)) {
                assert!(!error.to_string().trim().is_empty());
            }
        }
        Err(error) => assert!(!error.to_string().trim().is_empty(), "{error:?}"),
    }
}

/// An STL file, ASCII or binary: read, its mass properties, and written back unchanged.
pub fn stl_mesh(bytes: &[u8]) {
    let mesh = match Mesh::read_stl(&mut Cursor::new(bytes)) {
        Ok(mesh) => mesh,
        Err(error) => return assert!(!error.to_string().trim().is_empty(), "{error:?}"),
    };
    for mass in [MeshMass::Density(1000.0), MeshMass::Total(1.0)] {
        match mesh.mass_properties(mass) {
            Ok(p) => assert!(p.mass() > 0.0 && p.centre_of_gravity().iter().all(|x| x.is_finite())),
            Err(error) => assert!(!error.to_string().trim().is_empty(), "{error:?}"),
        }
    }
    let mut written = Vec::new();
    mesh.write_stl(&mut written).expect("writing into memory");
    let again = Mesh::read_stl(&mut Cursor::new(&written)).expect("a written mesh reads back");
    assert_eq!(again, mesh);
}
