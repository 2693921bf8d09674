//! The emitted Jacobians ∂f/∂x and ∂f/∂u of every catalog model equal the derivative of the
//! emitted `rhs` taken by dual numbers, at random states and at extreme ones (rates of
//! 10³ rad/s, angles near ±π, a pitch of 86°, a quaternion of length 10⁻³ and 10³); and an
//! entry outside a Jacobian's pattern is exactly zero by dual numbers too, so the pattern
//! leaves out only what vanishes identically.
//!
//! Both routes are exact derivatives evaluated in floating point in different orders, so they
//! differ by rounding only: a few ε of the largest term of the row. The bound, 1e-11 of the
//! row's largest entry (or of one), is some 10⁴ ε: room for rows of a few dozen terms and
//! their cancellation, far below any wrong term (which changes an entry by its own size).

use eom::PendulumParameters;
use eom::models::{Model, Symmetry};
use eom_test_support::bodies::tensor;
use num_dual::Dual64;

/// A repeatable value in [−1, 1) for each (case, index).
fn pseudo_random(case: u64, index: usize) -> f64 {
    let mut h = case.wrapping_mul(0x9e37_79b9_7f4a_7c15)
        ^ (index as u64).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    h = (h ^ (h >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    h = (h ^ (h >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    h ^= h >> 31;
    2.0 * ((h >> 11) as f64 / (1u64 << 53) as f64) - 1.0
}

/// The states a model is checked at: random ones of several sizes, then the extremes.
fn states<const N: usize>(quaternion: bool) -> Vec<[f64; N]> {
    let mut all = Vec::new();
    for case in 0..24u64 {
        let size = [1.0, 10.0, 1e3][case as usize % 3];
        all.push(std::array::from_fn(|i| size * pseudo_random(case, i)));
    }
    for extreme in [3.1, -3.1, 1.5] {
        all.push(std::array::from_fn(|i| {
            if i % 2 == 0 {
                extreme
            } else {
                1e3 * pseudo_random(99, i)
            }
        }));
    }
    if quaternion {
        for length in [1e-3, 1e3] {
            let mut state: [f64; N] = std::array::from_fn(|i| pseudo_random(7, i));
            for q in &mut state[N - 4..] {
                *q *= length;
            }
            all.push(state);
        }
    }
    all
}

/// Checks one model: every column of both Jacobians against a dual-number derivative.
fn check<Mo: Model<f64, N, M>, Md: Model<Dual64, N, M>, const N: usize, const M: usize>(
    model: &Mo,
    dual: &Md,
    quaternion: bool,
) -> usize {
    let mut compared = 0;
    for state in states::<N>(quaternion) {
        let input: [f64; M] = std::array::from_fn(|i| pseudo_random(5, i));
        let a = model.state_jacobian(&state, &input);
        let b = model.input_jacobian(&state, &input);
        for column in 0..N {
            let mut x = state.map(Dual64::from);
            x[column] = x[column].derivative();
            let d = dual.rhs(&x, &input.map(Dual64::from)).map(|v| v.eps);
            compared += compare(Mo::NAME, "∂f/∂x", &a, &d, column, Mo::STATE_JACOBIAN);
        }
        for column in 0..M {
            let mut u = input.map(Dual64::from);
            u[column] = u[column].derivative();
            let d = dual.rhs(&state.map(Dual64::from), &u).map(|v| v.eps);
            compared += compare(Mo::NAME, "∂f/∂u", &b, &d, column, Mo::INPUT_JACOBIAN);
        }
    }
    compared
}

fn compare<const N: usize, const C: usize>(
    name: &str,
    what: &str,
    emitted: &[[f64; C]; N],
    dual: &[f64; N],
    column: usize,
    pattern: &[(usize, usize)],
) -> usize {
    for row in 0..N {
        let (e, d) = (emitted[row][column], dual[row]);
        if !pattern.contains(&(row, column)) {
            assert_eq!(
                d, 0.0,
                "{name} {what}[{row}][{column}] is outside the pattern"
            );
            continue;
        }
        let scale = emitted[row].iter().fold(1.0f64, |m, v| m.max(v.abs()));
        assert!(
            (e - d).abs() <= 1e-11 * scale.max(d.abs()),
            "{name} {what}[{row}][{column}]: emitted {e:e}, dual numbers {d:e}"
        );
    }
    N
}

macro_rules! jacobian_tests {
    ($($module:ident => $type:ident {
        family: $family:ident $(($($option:ident),+))?,
        state: $n:literal, inputs: $m:literal, title: $title:literal,
        parameters: [$($parameter:ident),*], potential_energy: $potential:tt
    },)*) => {$(
        #[test]
        fn $module() {
            let (model, dual) = jacobian_tests!(@new $type, $family $(($($option),+))?);
            let quaternion = stringify!($module).ends_with("quaternion");
            let compared = check::<_, _, $n, $m>(&model, &dual, quaternion);
            println!("{}: {compared} entries compared", stringify!($module));
        }
    )*};
    (@new $type:ident, Pendulum) => {{
        let parameters = PendulumParameters::new(2.0, 3.0, 9.81, 0.5).unwrap();
        (eom::models::$type::<f64>::new(&parameters), eom::models::$type::<Dual64>::new(&parameters))
    }};
    (@new $type:ident, PlanarMidship) => {(
        eom::models::$type::<f64>::new(1000.0, 2.0e5, 3.0).unwrap(),
        eom::models::$type::<Dual64>::new(1000.0, 2.0e5, 3.0).unwrap(),
    )};
    (@new $type:ident, Top($kinematics:ident)) => {(
        eom::models::$type::<f64>::new(2.0, &tensor(Symmetry::Principal), 0.4, 9.81).unwrap(),
        eom::models::$type::<Dual64>::new(2.0, &tensor(Symmetry::Principal), 0.4, 9.81).unwrap(),
    )};
    (@new $type:ident, Spatial($symmetry:ident, $kinematics:ident)) => {(
        eom::models::$type::<f64>::new(5.0, &tensor(Symmetry::$symmetry)).unwrap(),
        eom::models::$type::<Dual64>::new(5.0, &tensor(Symmetry::$symmetry)).unwrap(),
    )};
    (@new $type:ident, $planar:ident) => {(
        eom::models::$type::<f64>::new(1000.0, 2.0e5).unwrap(),
        eom::models::$type::<Dual64>::new(1000.0, 2.0e5).unwrap(),
    )};
}

mod emitted_jacobians_equal_dual_numbers_through_rhs {
    use super::*;
    eom::for_each_model!(jacobian_tests);
}
