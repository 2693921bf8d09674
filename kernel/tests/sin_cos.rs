//! The kernel against the platform's `sin` and `cos`: [`eom_kernel::sin_cos`] as the generated
//! models call it, on f64, dual numbers and SIMD lanes (f32 in `tests/sin_cos_f32.rs`).
//!
//! With the feature `platform-trig`, `sin_cos` calls the platform's functions instead, so these
//! checks would not be of the kernel; `tests/platform_trig.rs` checks that switch.
#![cfg(not(feature = "platform-trig"))]

use num_dual::Dual64;
use simba::simd::{SimdComplexField, WideF64x4};
use std::f64::consts::FRAC_PI_2;

#[path = "support/uniform.rs"]
mod uniform;
use uniform::uniform;

/// The kernel on one angle.
fn sin_cos<T: simba::simd::SimdRealField + Copy>(x: T) -> (T, T) {
    let [pair] = eom_kernel::sin_cos([x]);
    pair
}

/// The largest argument the kernel reduces itself (its `LIMIT`); beyond it the platform's.
const LIMIT: f64 = 823_549.0;

/// One unit in the last place of `reference` (of its magnitude; the smallest normal's for 0).
fn ulp(reference: f64) -> f64 {
    let magnitude = reference.abs().max(f64::MIN_POSITIVE);
    f64::from_bits(magnitude.to_bits() + 1) - magnitude
}

/// The larger of the two errors of `sin_cos(x)` against the platform, in its ulps.
fn error_in_ulps(x: f64) -> f64 {
    let (s, c) = sin_cos(x);
    let (s0, c0) = x.sin_cos();
    ((s - s0).abs() / ulp(s0)).max((c - c0).abs() / ulp(c0))
}

fn worst(points: impl Iterator<Item = f64>) -> (f64, f64) {
    points
        .map(|x| (error_in_ulps(x), x))
        .fold((0.0, f64::NAN), |a, b| if b.0 > a.0 { b } else { a })
}

/// fdlibm's polynomials are good to 2⁻⁵⁸ on |r| ≤ π/4, so what is left is the rounding of the
/// reduction and of the polynomial evaluation: the platform's own functions are within one
/// ulp of the exact value, and ours within one more.
#[test]
fn within_two_ulp_of_the_platform_up_to_the_limit() {
    for range in [1.0, 10.0, 1e3, 1e5, LIMIT] {
        let (error, x) = worst(uniform(100_000, 0x9E37_79B9).map(|u| (2.0 * u - 1.0) * range));
        assert!(error <= 2.0, "{error} ulp at x = {x:e} (|x| < {range})");
    }
}

/// Up to |x| = 1000 (heading after some 160 turns) the reduction's rounding stays below half
/// an ulp and the pair is within one ulp of the platform.
#[test]
fn within_one_ulp_of_the_platform_for_everyday_angles() {
    let (error, x) = worst(uniform(200_000, 0x2545_F491).map(|u| (2.0 * u - 1.0) * 1e3));
    assert!(error <= 1.0, "{error} ulp at x = {x:e}");
}

/// Next to the multiples of π/2 one of the pair is tiny and all its digits come from the
/// reduction, so the split of π/2 must carry enough bits: here the exact products matter.
#[test]
fn keeps_relative_accuracy_next_to_multiples_of_a_right_angle() {
    // k = 0 is the zero and tiny arguments, tested below.
    for k in (-3000..=3000).filter(|&k| k != 0) {
        let x = f64::from(k) * FRAC_PI_2;
        // x and its neighbouring doubles: two towards zero, one away from it.
        let step = |n: i64| f64::from_bits(x.to_bits().wrapping_add_signed(n));
        for neighbour in [step(-2), step(-1), x, step(1)] {
            let error = error_in_ulps(neighbour);
            assert!(error <= 2.0, "{error} ulp at x = {neighbour:e} (k = {k})");
        }
    }
}

#[test]
fn zeros_tiny_and_non_finite_arguments_behave_as_the_platform_does() {
    let (s, c) = sin_cos(-0.0_f64);
    assert!(s == 0.0 && s.is_sign_negative() && c == 1.0);
    let (s, c) = sin_cos(0.0_f64);
    assert!(s == 0.0 && s.is_sign_positive() && c == 1.0);
    for tiny in [1e-300, -3e-12, f64::MIN_POSITIVE / 4.0, 7.4e-9] {
        assert_eq!(sin_cos(tiny), tiny.sin_cos(), "x = {tiny:e}");
    }
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let (s, c) = sin_cos(bad);
        assert!(s.is_nan() && c.is_nan(), "x = {bad}");
    }
}

/// Past the limit the kernel hands the argument to the platform: the same bits.
#[test]
fn beyond_the_limit_gives_the_platform_result_exactly() {
    for x in [LIMIT * 1.0001, -2e6, 1e10, 1e300] {
        assert_eq!(sin_cos(x), x.sin_cos(), "x = {x:e}");
    }
}

/// Dual numbers keep their own sine and cosine, so the derivative survives; SIMD lanes get
/// the kernel, lane by lane (tests/lanes.rs).
#[test]
fn dual_numbers_use_their_own_functions_and_lanes_the_kernel() {
    let x = Dual64::new(0.7, 1.0);
    let (s, c) = sin_cos(x);
    assert_eq!((s, c), x.simd_sin_cos());
    assert_eq!(s.eps, 0.7f64.cos());
    let lanes = WideF64x4::from([0.1, -2.0, 40.0, 1e3]);
    let (s, c) = sin_cos(lanes);
    for (i, x) in [0.1, -2.0, 40.0, 1e3].into_iter().enumerate() {
        assert_eq!(
            (s.0.to_array()[i], c.0.to_array()[i]),
            sin_cos(x),
            "x = {x}"
        );
    }
}

/// Several angles in one call give what each gives alone, also when some of them take the cold
/// path (tiny, huge, NaN) and the others do not.
#[test]
fn angles_together_equal_angles_alone() {
    assert_eq!(eom_kernel::sin_cos::<f64, 0>([]), []);
    let mixed = [0.3, -2.5, 1e7, f64::NAN, -1e-12, 700.0];
    let together = eom_kernel::sin_cos(mixed);
    for (x, pair) in mixed.into_iter().zip(together) {
        let alone = sin_cos(x);
        assert!(
            pair.0.to_bits() == alone.0.to_bits() && pair.1.to_bits() == alone.1.to_bits(),
            "x = {x:e}: {pair:?} together, {alone:?} alone"
        );
    }
    // Within ±1.5 about half the angles are inside ±π/4, where the kernel skips the reduction,
    // so most triples mix the two paths; within ±50 nearly all are reduced.
    let three: Vec<f64> = uniform(600, 0x51ED_2701)
        .enumerate()
        .map(|(i, u)| (2.0 * u - 1.0) * if i < 300 { 1.5 } else { 50.0 })
        .collect();
    for angles in three.chunks_exact(3) {
        let together = eom_kernel::sin_cos([angles[0], angles[1], angles[2]]);
        for (x, pair) in angles.iter().zip(together) {
            assert_eq!(pair, sin_cos(*x), "x = {x:e}");
        }
    }
}
