//! The generated right-hand sides run on dual numbers (num-dual through simba's
//! `SimdRealField`), so their exact derivatives come for free: checked here against central
//! differences of the f64 functions.

use eom::InertiaTensor;
use eom::models::{Model, SpatialFullEuler, SpatialXzQuaternion};
use num_dual::Dual64;

/// Force `[F_x, F_y, F_z]` and moment `[M_x, M_y, M_z]` about G, body axes.
const INPUT: [f64; 6] = [1.0, -2.0, 0.5, 0.1, 0.3, -0.2];

fn tensor() -> InertiaTensor {
    InertiaTensor::new(2.0, 3.0, 4.0, 0.1, -0.05, 0.2).unwrap()
}

/// Central differences with step 1e-6 on values of order one: truncation ~1e-12, round-off
/// ~1e-10, so 1e-8 relative to the size of the derivative is a safe bound.
fn assert_close(dual: f64, difference: f64, what: &str) {
    assert!(
        (dual - difference).abs() <= 1e-8 * (1.0 + difference.abs()),
        "{what}: dual {dual} vs difference {difference}"
    );
}

#[test]
fn euler_rates_differentiate_exactly_with_respect_to_pitch() {
    let state = [
        1.0, 0.2, -0.1, 0.3, -0.2, 0.5, 0.0, 0.0, 0.0, 0.4, 1.1, -0.7,
    ];
    let model = SpatialFullEuler::<f64>::new(5.0, &tensor()).unwrap();
    let dual_model = SpatialFullEuler::<Dual64>::new(5.0, &tensor()).unwrap();
    let mut dual_state = state.map(Dual64::from);
    dual_state[10] = Dual64::from(state[10]).derivative();
    let derivative = dual_model.rhs(&dual_state, &INPUT.map(Dual64::from));
    let h = 1e-6;
    let shifted = |dx: f64| {
        let mut s = state;
        s[10] += dx;
        model.rhs(&s, &INPUT)
    };
    let (plus, minus) = (shifted(h), shifted(-h));
    for i in 0..12 {
        assert_close(
            derivative[i].eps,
            (plus[i] - minus[i]) / (2.0 * h),
            &format!("d rate[{i}] / dθ"),
        );
        assert_same_value(derivative[i].re, model.rhs(&state, &INPUT)[i], i);
    }
}

/// A dual number's real part is the f64 model's value: bit for bit in a build without FMA.
/// With FMA the f64 model fuses each `mul_add` (one rounding) and num-dual's `mul_add` does
/// not (a product and a sum, two), so the two may differ by the extra roundings of a few
/// multiply–adds: within 16 ε of the value (the Euler rates' longest chain has about six).
fn assert_same_value(dual: f64, model: f64, i: usize) {
    if cfg!(target_feature = "fma") {
        let bound = 16.0 * f64::EPSILON * model.abs().max(f64::MIN_POSITIVE);
        assert!(
            (dual - model).abs() <= bound,
            "rate[{i}]: {dual} vs {model}"
        );
    } else {
        assert_eq!(dual, model, "rate[{i}]");
    }
}

#[test]
fn quaternion_model_differentiates_with_respect_to_the_roll_rate() {
    let q = nalgebra::UnitQuaternion::from_euler_angles(0.2, -0.4, 1.0);
    let state = [
        1.0, 0.2, -0.1, 0.3, -0.2, 0.5, 0.0, 0.0, 0.0, q.w, q.i, q.j, q.k,
    ];
    let tensor = InertiaTensor::new(2.0, 3.0, 4.0, 0.0, 0.0, 0.2).unwrap();
    let model = SpatialXzQuaternion::<f64>::new(5.0, &tensor).unwrap();
    let dual_model = SpatialXzQuaternion::<Dual64>::new(5.0, &tensor).unwrap();
    let mut dual_state = state.map(Dual64::from);
    dual_state[3] = Dual64::from(state[3]).derivative();
    let derivative = dual_model.rhs(&dual_state, &INPUT.map(Dual64::from));
    let h = 1e-6;
    let shifted = |dx: f64| {
        let mut s = state;
        s[3] += dx;
        model.rhs(&s, &INPUT)
    };
    let (plus, minus) = (shifted(h), shifted(-h));
    for i in 0..13 {
        assert_close(
            derivative[i].eps,
            (plus[i] - minus[i]) / (2.0 * h),
            &format!("d rate[{i}] / dp"),
        );
    }
}
