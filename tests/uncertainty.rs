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
fn states(count: usize) -> Vec<([f64; 7], [f64; 2])> {
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
            (state, [x(-0.09, 0.09), 0.0])
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
