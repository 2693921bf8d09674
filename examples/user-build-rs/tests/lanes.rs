//! Turning circles of the rustc-compiled Mariner in SIMD lanes step each case as the scalar
//! model does, bit for bit: four cases to a `Batch<WideF64x4, 7>` (each lane its own rudder
//! order and starting speed, the steering gear's clamp taken lane by lane) against each case
//! alone, in `Batch<f64, 7>` and in `eom`'s RK4. Seven cases, so that the last group of four
//! has an empty lane.

#[allow(dead_code)]
mod common;
#[path = "common/gear.rs"]
mod gear;

use common::{mariner_coefficients, mariner_table};
use eom::batch::Batch;
use eom::{Integrator, Model, Rk4};
use eom_example_user_build_rs::mariner;
use simba::simd::WideF64x4;

const H: f64 = 0.1;
const STEPS: usize = 3400;

/// `cases` straight approaches, rudder amidships, at speeds spread over ±5 % of U₀.
fn starts(cases: usize, design_speed: f64) -> Vec<[f64; 7]> {
    (0..cases)
        .map(|i| {
            let speed = design_speed * (0.95 + 0.1 * i as f64 / cases as f64);
            [speed, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
        })
        .collect()
}

#[test]
fn each_lane_turns_as_its_case_alone() {
    let table = mariner_table();
    let scalar = mariner_coefficients(&table);
    // `Coefficients::new` computes in f64 and splats: every lane the same table.
    let lanes = mariner::Coefficients::<WideF64x4>::new(&mariner::Parameters::from_symbols(|s| {
        common::symbols(&table).get(s).copied().unwrap_or(f64::NAN)
    }));
    let starts = starts(7, table.design_speed);
    let orders = gear::RUDDER_ORDERS_DEG.map(f64::to_radians);

    let mut batch = Batch::<WideF64x4, 7>::new(&starts);
    let loads = gear::steering_gear(WideF64x4::from(orders));
    for step in 0..STEPS {
        batch.step_rk4(&lanes, &loads, step as f64 * H, H);
    }

    // Each rudder order's cases alone, one at a time (`Batch<f64, 7>`, the bench's scalar
    // form), and each case in `eom`'s RK4 of the scalar model.
    for (lane, &order) in orders.iter().enumerate() {
        let cases: Vec<usize> = (lane..starts.len()).step_by(4).collect();
        let alone: Vec<[f64; 7]> = cases.iter().map(|&i| starts[i]).collect();
        let mut one_by_one = Batch::<f64, 7>::new(&alone);
        for step in 0..STEPS {
            one_by_one.step_rk4(&scalar, &gear::steering_gear(order), step as f64 * H, H);
        }
        for (k, &case) in cases.iter().enumerate() {
            let end = batch.state(case);
            let bits = |y: [f64; 7]| y.map(f64::to_bits);
            assert_eq!(bits(end), bits(one_by_one.state(k)), "case {case}");
            let driven = scalar.driven_by(gear::steering_gear(order));
            let rk4 = Rk4::new(H)
                .integrate(&driven, 0.0, starts[case].into(), STEPS as f64 * H)
                .unwrap();
            assert_eq!(bits(end), bits(rk4.data.0[0]), "case {case} in eom's RK4");
        }
    }

    // The turns are turns: every rudder is at its order and every heading has turned to port,
    // the harder rudders the further.
    let ends = batch.states();
    for (i, end) in ends.iter().enumerate() {
        assert!(
            (end[6] - orders[i % 4]).abs() < 1e-9,
            "case {i}: δ = {}",
            end[6]
        );
        assert!(end[5] < -1.0, "case {i}: ψ = {}", end[5]);
    }
    assert!(ends[3][5] < ends[0][5]);
}
