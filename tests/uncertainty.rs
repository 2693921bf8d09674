//! The Mariner's Monte Carlo scene (`scenes/mariner_uncertainty.toml`): its table is
//! `scenes/mariner.toml`'s with the rigid-body terms taken out, so that its nominal model is
//! the published scene's, bit for bit; and its cases take their values into the model derived
//! and proved once, giving what a model derived and proved for each case's table gives.

use eom::Model;
use eom::kinds::ship::{ShipModel, ShipScene};
use eom::scene::AnyScene;
use eom::scene::uncertainty::Uncertainty;
use eom_test_support::random::Random;
use std::path::Path;

const SCENE: &str = "scenes/mariner_uncertainty.toml";

/// The ship scene of a case's (or the nominal scene's) tables.
fn ship(table: toml::Table) -> ShipScene {
    let scene = AnyScene::from_table(table, SCENE, Path::new("scenes")).unwrap();
    *scene.downcast::<ShipScene>().expect("a ship scene")
}

/// States about the approach and well into a hard turn, with the rudder moving.
fn states(count: usize) -> Vec<([f64; 7], [f64; 3])> {
    let mut random = Random(17);
    (0..count)
        .map(|_| {
            let mut x = |lo: f64, hi: f64| lo + (hi - lo) * random.unit();
            let state = [
                x(3.0, 8.0),
                x(-1.5, 1.5),
                x(-0.02, 0.02),
                x(-2e3, 2e3),
                x(-2e3, 2e3),
                x(-7.0, 7.0),
                x(-0.7, 0.7),
            ];
            (state, [x(-0.09, 0.09), 0.0, 0.0])
        })
        .collect()
}

#[test]
fn the_nominal_scene_runs_the_published_mariners_model_bit_for_bit() {
    let text = std::fs::read_to_string(SCENE).unwrap();
    let uncertainty = Uncertainty::parse(&text, SCENE).unwrap();
    let nominal = ShipModel::new(&ship(uncertainty.nominal().clone()).table).unwrap();
    let published = ShipScene::load(Path::new("scenes/mariner.toml")).unwrap();
    let published = ShipModel::new(&published.table).unwrap();
    for (state, input) in states(1000) {
        let (a, b): ([f64; 7], [f64; 7]) =
            (nominal.rhs(&state, &input), published.rhs(&state, &input));
        assert_eq!(a.map(f64::to_bits), b.map(f64::to_bits), "{state:?}");
    }
}

#[test]
fn a_case_takes_its_values_into_the_model_proved_once() {
    let text = std::fs::read_to_string(SCENE).unwrap();
    let uncertainty = Uncertainty::parse(&text, SCENE).unwrap();
    // 45 numbers: the 39 terms of the polynomial, X_vr among them at zero, and the 5 added masses.
    assert_eq!(uncertainty.varied.len(), 45);
    let nominal = ShipModel::new(&ship(uncertainty.nominal().clone()).table).unwrap();
    for index in [0, 1, 9999] {
        let case = ship(uncertainty.case(index).table).table;
        let shared = ShipModel::new(&case).unwrap();
        assert!(
            shared.shares_proof_with(&nominal),
            "case {index} derived anew"
        );
        let derived = ShipModel::derive(&case).unwrap();
        assert!(!derived.shares_proof_with(&nominal));
        for (state, input) in states(200) {
            let (a, b): ([f64; 7], [f64; 7]) =
                (shared.rhs(&state, &input), derived.rhs(&state, &input));
            assert_eq!(a.map(f64::to_bits), b.map(f64::to_bits), "case {index}");
            let bits = |j: [[f64; 7]; 7]| j.map(|row| row.map(f64::to_bits));
            let (ja, jb) = (
                shared.state_jacobian(&state, &input),
                derived.state_jacobian(&state, &input),
            );
            assert_eq!(bits(ja), bits(jb), "case {index}");
        }
    }
}

/// REMUS 100 with its yaw moment's terms varied by 20 %: a case's vehicle model takes its
/// values into the equations derived for the scene and gives what a model derived for the
/// case's table alone gives, bit for bit.
#[test]
fn a_vehicle_case_takes_its_values_into_the_model_derived_once() {
    use eom::kinds::vehicle::{VehicleModel, VehicleScene};
    let text = std::fs::read_to_string("scenes/remus100.toml").unwrap()
        + "\n[uncertainty]\ncases = 4\nseed = 3\n[uncertainty.vary]\n\
           \"hydrodynamics.coefficients.N*\" = { distribution = \"uniform\", relative = 0.2 }\n";
    let uncertainty = Uncertainty::parse(&text, "remus100.toml").unwrap();
    assert!(uncertainty.varied.len() > 3, "{:?}", uncertainty.varied);
    for index in 0..4 {
        let case =
            AnyScene::from_table(uncertainty.case(index).table, "remus", Path::new("scenes"));
        let case = *case.unwrap().downcast::<VehicleScene>().unwrap();
        let derived = VehicleModel::derive(&case.table).unwrap();
        let mut random = Random(index as u64 + 1);
        let start = case.start().unwrap();
        for _ in 0..100 {
            let state: [f64; 15] = std::array::from_fn(|i| start[i] + 0.1 * (random.unit() - 0.5));
            let input = [0.01, -0.02];
            let (a, b): ([f64; 15], [f64; 15]) =
                (case.model.rhs(&state, &input), derived.rhs(&state, &input));
            assert_eq!(a.map(f64::to_bits), b.map(f64::to_bits), "case {index}");
        }
    }
}

/// Counts the rows it is given, keeping them as `eom run` keeps a scene's.
#[derive(Default)]
struct Counted(usize);

impl eom::run::record::Recorder for Counted {
    fn begin(
        &mut self,
        _: eom::run::record::RunStart,
    ) -> Result<(), eom::run::record::RecordError> {
        Ok(())
    }
    fn row(&mut self, _: &eom::run::Row) -> bool {
        self.0 += 1;
        true
    }
    fn end(&mut self) -> Result<(), eom::run::record::RecordError> {
        Ok(())
    }
    fn drawn(
        &mut self,
        _: eom::output::drawing::RunDrawings,
    ) -> Result<(), eom::run::record::RecordError> {
        Ok(())
    }
    fn stop_asked(&self) -> bool {
        false
    }
}

/// A case builds no rows and is not run again refined, and reads the same figures, bit for
/// bit, as its scene run whole with its rows kept: the rows and the refined run are not what
/// the figures are read from.
#[test]
fn a_case_reads_the_figures_its_scene_gives_when_run_whole() {
    use eom::run::uncertainty::run_case;
    let remus = std::fs::read_to_string("scenes/remus100.toml").unwrap()
        + "\n[uncertainty]\ncases = 2\nseed = 3\n[uncertainty.vary]\n\
           \"hydrodynamics.coefficients.N*\" = { distribution = \"uniform\", relative = 0.2 }\n";
    let mariner = std::fs::read_to_string(SCENE).unwrap();
    for (text, name) in [(mariner, SCENE), (remus, "remus100.toml")] {
        let uncertainty = Uncertainty::parse(&text, name).unwrap();
        for index in [0, 1] {
            let case = run_case(&uncertainty, index, (name, Path::new("scenes")), &|| false);
            assert_eq!(case.error, None, "{name} case {index}");
            let table = uncertainty.case(index).table;
            let scene = AnyScene::from_table(table, name, Path::new("scenes")).unwrap();
            let mut rows = Counted::default();
            let whole = scene.as_kind().run(name, &mut rows).unwrap().summary();
            assert!(rows.0 > 100, "{name}: {} rows", rows.0);
            let figures: Vec<(String, Option<u64>)> = (whole.runs.iter())
                .flat_map(|run| {
                    (run.figures.iter()).map(move |figure| match run.run.is_empty() {
                        true => (figure.key.clone(), figure.value.map(f64::to_bits)),
                        false => (
                            format!("{}/{}", run.run, figure.key),
                            figure.value.map(f64::to_bits),
                        ),
                    })
                })
                .collect();
            let read: Vec<(String, Option<u64>)> = (case.figures.iter())
                .map(|(key, value)| (key.clone(), value.map(f64::to_bits)))
                .collect();
            assert!(read.len() > 10, "{name}: {read:?}");
            assert_eq!(read, figures, "{name} case {index}");
        }
    }
}

/// A case's values set into the scene as read (a ship's coefficients into its file,
/// `Kind::with_numbers`) give the case its scene read again from its tables gives, bit for
/// bit: every figure, verdict and value, for the Mariner's Monte Carlo; and a key a kind does
/// not take so (REMUS's coefficients: the vehicle reads its tables again) gives the same too.
#[test]
fn a_case_set_into_the_scene_as_read_is_the_case_read_again() {
    use eom::run::uncertainty::{run_case, run_cases};
    let remus = std::fs::read_to_string("scenes/remus100.toml").unwrap()
        + "\n[uncertainty]\ncases = 3\nseed = 3\n[uncertainty.vary]\n\
           \"hydrodynamics.coefficients.N*\" = { distribution = \"uniform\", relative = 0.2 }\n";
    let mariner = std::fs::read_to_string(SCENE).unwrap();
    for (text, name) in [(mariner, SCENE), (remus, "remus100.toml")] {
        let uncertainty = Uncertainty::parse(&text, name).unwrap();
        let scene = (name, Path::new("scenes"));
        let nominal = AnyScene::from_table(uncertainty.nominal().clone(), name, scene.1).unwrap();
        let numbers: Vec<(&str, f64)> = (uncertainty.varied.iter())
            .map(|number| (number.key.as_str(), number.nominal))
            .collect();
        let taken = nominal.as_kind().with_numbers(name, &numbers).is_some();
        assert_eq!(
            taken,
            name == SCENE,
            "{name}: whether the kind takes numbers"
        );
        let indices = [0, 1, 2];
        let fast = run_cases(&uncertainty, &indices, scene, &|| false);
        for (index, fast) in indices.iter().zip(&fast) {
            let again = run_case(&uncertainty, *index, scene, &|| false);
            assert_eq!(fast.error, None, "{name} case {index}");
            let bits = |figures: &[(String, Option<f64>)]| -> Vec<(String, Option<u64>)> {
                (figures.iter())
                    .map(|(key, value)| (key.clone(), value.map(f64::to_bits)))
                    .collect()
            };
            assert_eq!(
                bits(&fast.figures),
                bits(&again.figures),
                "{name} case {index}"
            );
            assert!(!fast.figures.is_empty(), "{name} case {index}");
            assert_eq!(fast.verdicts, again.verdicts, "{name} case {index}");
            let values = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(values(&fast.values), values(&again.values), "{name}");
        }
    }
}

/// A value that the scene's checks refuse is refused for the case as when its tables are read
/// again: the Mariner's mass matrix made singular by its added mass, through the scene as read.
#[test]
fn a_case_set_into_the_scene_as_read_is_checked_as_the_scene_is() {
    let uncertainty = Uncertainty::parse(&std::fs::read_to_string(SCENE).unwrap(), SCENE).unwrap();
    let nominal = AnyScene::from_table(uncertainty.nominal().clone(), SCENE, ".".as_ref()).unwrap();
    let ship: &ShipScene = nominal.as_kind().as_any().downcast_ref().unwrap();
    let key = "hydrodynamics.coefficients.Yv";
    let refused = ship.with_coefficients(SCENE, &[(key, f64::NAN)]).unwrap();
    let error = refused
        .expect_err("a NaN coefficient is refused")
        .to_string();
    assert!(error.contains("Yv"), "{error}");
    let unknown = ship.with_coefficients(SCENE, &[("hydrodynamics.coefficients.Yzz", 1.0)]);
    assert!(unknown.is_none(), "a coefficient the table does not have");
    let other = ship.with_coefficients(SCENE, &[("body.mass", 1.0)]);
    assert!(other.is_none(), "a key that is not a coefficient");
}
