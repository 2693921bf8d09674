//! An aircraft's attitude in a quaternion (`aircraft.kinematics = "quaternion"`): the
//! quaternion form of the proved model gives the rates of the Euler-angle form at every
//! attitude where both hold, its Jacobians are its rates' slopes, a manoeuvre flown in it is
//! the Euler-angle run's, and a loop through the vertical, where the Euler angles stop, flies.

#![cfg(feature = "ship")]

use eom::kinds::aircraft::AircraftScene;
use eom::kinds::aircraft::manoeuvre::{Sample, run};
use eom::kinds::aircraft::model::{euler_of, quaternion_of};
use eom::models::{Kinematics, Model};
use eom_test_support::differences::central_jacobians;
use std::path::Path;

fn f16_text() -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/f16.toml")).unwrap()
}

fn f16() -> AircraftScene {
    AircraftScene::parse(&f16_text(), "f16.toml").unwrap()
}

/// A state away from the trim with every component acting: rolled, pitched, yawed, turning.
fn away() -> [f64; 13] {
    [
        480.0, 0.12, 0.05, 0.4, 0.6, -1.1, 0.3, -0.2, 0.25, 100.0, -50.0, 8000.0, 60.0,
    ]
}

/// The quaternion form's rates at q(φ, θ, ψ) are the Euler form's: the wind axes, the body
/// rates, the track and the power equal to rounding (1e-12 of each rate's magnitude, the two
/// programs' orders of operations), and q̇ = ½ q ⊗ (0, ω) the rate of q(φ(t), θ(t), ψ(t)) at
/// the Euler form's φ̇, θ̇, ψ̇ (by central differences of q along them, 1e-8).
#[test]
fn the_quaternion_form_gives_the_euler_forms_rates() {
    let scene = f16();
    let quaternion = scene.model.in_quaternion().unwrap();
    let x = away();
    let controls = [0.6, -2.0, 3.0, -4.0];
    let euler_rates = scene.model.rates(&x, &controls);
    let q = quaternion_of(&x);
    let quaternion_rates = quaternion.rhs(&q, &controls);
    let pairs = [
        (0, 0),
        (1, 1),
        (2, 2),
        (6, 7),
        (7, 8),
        (8, 9),
        (9, 10),
        (10, 11),
        (11, 12),
    ]
    .into_iter()
    .chain([(12, 13)]);
    for (e, k) in pairs {
        let (a, b) = (euler_rates[e], quaternion_rates[k]);
        assert!(
            (a - b).abs() <= 1e-12 * a.abs().max(1.0),
            "rate {e}: {a} vs {b}"
        );
    }
    let h = 1e-6;
    let along = |sign: f64| {
        let mut moved = x;
        for (angle, rate) in [(3, 3), (4, 4), (5, 5)] {
            moved[angle] += sign * h * euler_rates[rate];
        }
        quaternion_of(&moved)
    };
    let (up, down) = (along(1.0), along(-1.0));
    for k in 3..7 {
        let difference = (up[k] - down[k]) / (2.0 * h);
        assert!(
            (difference - quaternion_rates[k]).abs() < 1e-8,
            "q{}: {difference} vs {}",
            k - 3,
            quaternion_rates[k]
        );
    }
    assert_eq!(
        euler_of(&q).map(f64::to_bits)[6..],
        x.map(f64::to_bits)[6..]
    );
    for (a, b) in euler_of(&q)[3..6].iter().zip(&x[3..6]) {
        assert!((a - b).abs() < 1e-15, "{a} vs {b}");
    }
}

/// The quaternion form's Jacobians against central differences of its rates (step 1e-6 of
/// each entry's scale; the rates are smooth there, so truncation and rounding stay below 1e-6
/// of each row's largest entry).
#[test]
fn the_quaternion_forms_jacobians_are_its_rates_slopes() {
    let scene = f16();
    let quaternion = scene.model.in_quaternion().unwrap();
    let x = quaternion_of(&away());
    let controls = [0.6, -2.0, 3.0, -4.0];
    let a = quaternion.state_jacobian(&x, &controls);
    let (numeric, _) = central_jacobians(
        |x, u| quaternion.rhs(x, u),
        (&x, &controls),
        |v| 1e-6 * v.abs().max(1.0),
    );
    for row in 0..14 {
        let scale = a[row].iter().fold(1.0_f64, |m, v| m.max(v.abs()));
        for (column, difference) in numeric[row].iter().enumerate() {
            assert!(
                (difference - a[row][column]).abs() < 1e-6 * scale,
                "∂f{row}/∂x{column}: {difference} vs {}",
                a[row][column]
            );
        }
    }
}

/// Every row of a run, flown in `kinematics`.
fn flown(scene: &AircraftScene, index: usize, kinematics: Kinematics) -> Vec<Sample> {
    let mut rows = Vec::new();
    let manoeuvre = &scene.manoeuvres[index];
    run(
        &scene.model,
        kinematics,
        manoeuvre,
        (&scene.trim.state, &scene.trim.controls),
        (&scene.stepper, scene.every),
        None,
        |sample| {
            rows.push(*sample);
            true
        },
    )
    .unwrap();
    rows
}

/// The shipped rudder kick and aileron step (rolling, yawing, sideslipping), flown in Euler
/// angles and in a quaternion by DOPRI5 at 1e-10: the rows are at the same times and agree to
/// 1e-7 of each column's largest magnitude. They are two integrations of the same motion, each
/// within its tolerance of it: at the scene's 1e-7 they differ by up to 4.5e-6, at 1e-10 by
/// up to 3e-8 (measured), so they converge together.
#[test]
fn a_manoeuvre_flown_in_a_quaternion_is_the_euler_angles_run() {
    let text = f16_text().replace("rtol = 1e-7\natol = 1e-7", "rtol = 1e-10\natol = 1e-10");
    assert_ne!(text, f16_text());
    let scene = AircraftScene::parse(&text, "f16.toml").unwrap();
    for index in [1, 2] {
        let euler = flown(&scene, index, Kinematics::Euler);
        let quaternion = flown(&scene, index, Kinematics::Quaternion);
        assert_eq!(euler.len(), quaternion.len());
        let mut largest = 0.0_f64;
        for column in 0..18 {
            let scale = (euler.iter())
                .map(|s| s.row[column].abs())
                .fold(1e-3, f64::max);
            for (e, q) in euler.iter().zip(&quaternion) {
                assert_eq!(e.t, q.t);
                let difference = (e.row[column] - q.row[column]).abs() / scale;
                largest = largest.max(difference);
                assert!(
                    difference <= 1e-7,
                    "{}: column {column} at t = {}: {} vs {}",
                    scene.manoeuvres[index].name,
                    e.t,
                    e.row[column],
                    q.row[column]
                );
            }
        }
        println!("{}: {largest:e}", scene.manoeuvres[index].name);
    }
}
