//! eom's proved point mass over the Earth (`eom::earth::point_mass`): its Jacobians against
//! differences of its rates, and NESC check case 1, the dropped sphere without drag over the
//! turning WGS-84 Earth with J2 gravitation, against the six tools of `data/nesc/cases.json`
//! at t = 5, 10, …, 30 s.

#![cfg(feature = "ship")]

use eom::earth::point_mass::PointMass;
use eom::earth::{Ecef, Geodetic, NESC};
use eom::{AdaptiveOptions, Constant, Dop853, Integrator, Model};
use eom_test_support::differences::central_jacobians;
use eom_test_support::nesc::{self, FOOT, case};
use nalgebra::SVector;
use serde_json::Value;

/// The tools' values of `column` at checkpoint `k`, those of `tools` that give it.
fn values(case: &Value, column: &str, k: usize, tools: &[&str]) -> Vec<f64> {
    (tools.iter())
        .filter_map(|tool| nesc::column(case, column, tool))
        .map(|v| v[k])
        .collect()
}

/// eom's rows at t = 0, 5, …, 30 s: the state (ECEF position and Earth-relative velocity).
fn fly(start: [f64; 6]) -> Vec<[f64; 6]> {
    let model = PointMass::nesc(&NESC).unwrap();
    let free = model.driven_by(Constant::zero());
    let mut method = Dop853::new(AdaptiveOptions::dop853(1e-13, 1e-13));
    let mut state = SVector::from(start);
    let mut rows = vec![start];
    for k in 0..6 {
        let t = 5.0 * k as f64;
        state = method.integrate(&free, t, state, t + 5.0).unwrap();
        rows.push(state.data.0[0]);
    }
    rows
}

/// The Earth-relative velocity in local north-east-down axes at `at`.
fn ned(at: &Geodetic, v: [f64; 3]) -> [f64; 3] {
    let (sin_lat, cos_lat) = at.latitude.sin_cos();
    let (sin_lon, cos_lon) = at.longitude.sin_cos();
    let along = cos_lon * v[0] + sin_lon * v[1];
    [
        -sin_lat * along + cos_lat * v[2],
        -sin_lon * v[0] + cos_lon * v[1],
        -cos_lat * along - sin_lat * v[2],
    ]
}

/// The median of `values`.
fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    let n = values.len();
    (values[(n - 1) / 2] + values[n / 2]) / 2.0
}

/// Case 1 from rest at 30 000 ft over the equator and the prime meridian: at every checkpoint
/// eom's altitude, eastward ECEF displacement (the Coriolis deflection, 21 ft by 30 s),
/// longitude and down and east velocities lie within the agreeing tools' own range of the
/// median of those tools, widened by a floor for the tools' printing (1e-6 ft or ft/s, 1e-12
/// deg; at 30 s the four agreeing tools' altitudes span 3.5e-6 ft). The agreeing
/// tools are SIM03–SIM06 for the altitude and the velocities, SIM01, SIM05 and SIM06 for the
/// eastward displacement and the longitude; held apart with the reason (`data/nesc`'s own
/// outlier rule and notes): SIM01's altitude (1.6e-3 ft high at 30 s: its atmosphere, the
/// data's note says) and SIM02 (prints 7 to 10 digits, and its east velocity is 7e-4 ft/s low);
/// SIM03's eastward displacement and longitude (3.6e-3 ft short at 30 s).
#[test]
fn case_1_the_dropped_sphere_falls_as_the_tools_say() {
    let case = case(1);
    let position = Geodetic {
        latitude: 0.0,
        longitude: 0.0,
        altitude: 30_000.0 * FOOT,
    }
    .ecef(&NESC.ellipsoid);
    let rows = fly([position.0[0], position.0[1], position.0[2], 0.0, 0.0, 0.0]);
    let vertical = ["SIM03", "SIM04", "SIM05", "SIM06"];
    let eastward = ["SIM01", "SIM05", "SIM06"];
    for (k, row) in rows.iter().enumerate() {
        let at = Ecef([row[0], row[1], row[2]]).geodetic(&NESC.ellipsoid);
        let velocity = ned(&at, [row[3], row[4], row[5]]);
        // Each value, the tools it is held to, and their printing's floor in its unit.
        let ours = [
            ("altitudeMsl_ft", at.altitude / FOOT, &vertical[..], 1e-6),
            ("feVelocity_ft_s_Z", velocity[2] / FOOT, &vertical[..], 1e-6),
            ("feVelocity_ft_s_Y", velocity[1] / FOOT, &vertical[..], 1e-6),
            ("gePosition_ft_Y", row[1] / FOOT, &eastward[..], 1e-6),
            (
                "longitude_deg",
                at.longitude.to_degrees(),
                &eastward[..],
                1e-12,
            ),
        ];
        for (column, value, tools, floor) in ours {
            let theirs = values(&case, column, k, tools);
            assert!(theirs.len() >= 3, "{column}: {theirs:?}");
            let range = theirs.iter().fold(f64::MIN, |m, v| m.max(*v))
                - theirs.iter().fold(f64::MAX, |m, v| m.min(*v));
            let off = (value - median(theirs.clone())).abs();
            assert!(
                off <= range + floor,
                "t = {} s, {column}: eom {value}, tools {theirs:?}",
                5 * k
            );
        }
    }
    // The Coriolis deflection is there: 21 ft east by 30 s.
    assert!(
        (rows[6][1] / FOOT - 21.0).abs() < 0.01,
        "{}",
        rows[6][1] / FOOT
    );
}

/// ∂f/∂x (with the chain rule through 1/r) and ∂f/∂f against central differences of the
/// rates at positions from the equator to the pole, on the ground and in orbit, to 1e-7 of
/// each row's largest entry (the differences at a step of 1e-6 of each value, 1 m for a
/// position, leave 1e-9 of it).
#[test]
fn the_jacobians_are_those_of_the_rates() {
    let model = PointMass::nesc(&NESC).unwrap();
    let states = [
        [6.4e6, 0.0, 0.0, 0.0, 0.0, -290.0],
        [3.1e6, -2.2e6, 5.0e6, 120.0, -40.0, 7.0],
        [1.0e3, 2.0e3, 6.36e6, 15.0, 0.0, 0.0],
        [-4.0e6, 5.3e6, -1.2e6, 5000.0, 6000.0, -200.0],
    ];
    let input = [0.3, -0.2, 9.0];
    for y in &states {
        let by_state = model.state_jacobian(y, &input);
        let by_input = model.input_jacobian(y, &input);
        let step = |v: f64| 1e-6 * v.abs().max(1.0);
        let rates = |x: &[f64; 6], u: &[f64; 3]| model.rhs(x, u);
        let (state_numeric, input_numeric) = central_jacobians(rates, (y, &input), step);
        for row in 0..6 {
            let size =
                (by_state[row].iter().chain(&by_input[row])).fold(1e-12f64, |m, d| m.max(d.abs()));
            let exact = by_state[row].iter().chain(&by_input[row]);
            let numeric = state_numeric[row].iter().chain(&input_numeric[row]);
            for (column, (a, b)) in exact.zip(numeric).enumerate() {
                assert!(
                    (a - b).abs() <= 1e-7 * size,
                    "∂f{row}/∂{column} at {y:?}: {a} against {b}"
                );
            }
        }
    }
}
