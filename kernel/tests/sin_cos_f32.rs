//! The f32 kernel against the correctly rounded sine and cosine: the f64 platform functions
//! rounded to f32 (their error, under an f64 ulp, can flip a rounding only where the exact
//! value lies within 2⁻²⁹ ulp of a tie between two f32, which the 2-ulp bound absorbs).
#![cfg(not(feature = "platform-trig"))]

use std::f32::consts::{FRAC_PI_2, FRAC_PI_4};

/// The largest argument the f32 kernel reduces itself (its `LIMIT`, the f64 kernel's).
const LIMIT: f32 = 823_549.0;

#[path = "support/f32_ulps.rs"]
mod f32_ulps;
#[path = "support/uniform.rs"]
mod uniform;
use f32_ulps::{error_in_ulps, sin_cos};
use uniform::uniform;

/// The worst error over `points` and where it is.
fn worst(points: impl Iterator<Item = f32>) -> (u32, f32) {
    points
        .map(|x| (error_in_ulps(x), x))
        .fold((0, f32::NAN), |a, b| if b.0 > a.0 { b } else { a })
}

/// Every 499th f32 of either sign up to 2π (two quadrants each way, 4.4 million angles), from
/// the subnormals up: all magnitudes, and both the path within ±π/4 and the reduction. Every
/// f32 there, 2.2 billion angles, is `cargo run --release -p eom-kernel --example
/// f32_exhaustive` (about 20 s).
#[test]
fn within_one_ulp_of_the_correctly_rounded_pair_up_to_two_pi() {
    let top = (8.0 * FRAC_PI_4).to_bits();
    let points = (0..=top)
        .step_by(499)
        .flat_map(|bits| [f32::from_bits(bits), -f32::from_bits(bits)]);
    let (error, x) = worst(points);
    println!("|x| ≤ 2π, every 499th f32: {error} ulp at most (at x = {x:e})");
    assert!(error <= 1, "{error} ulp at x = {x:e}");
}

/// Uniform angles up to the limit: the reduction's error grows with k, the bound holds.
#[test]
fn within_two_ulp_up_to_the_limit() {
    for range in [10.0, 1e3, 1e5, f64::from(LIMIT)] {
        let points = uniform(200_000, 0x9E37_79B9).map(|u| ((2.0 * u - 1.0) * range) as f32);
        let (error, x) = worst(points);
        println!("|x| < {range:e}: {error} ulp at most (at x = {x:e})");
        assert!(error <= 2, "{error} ulp at x = {x:e} (|x| < {range})");
    }
}

/// Next to the multiples of π/2 one of the pair is tiny and all its digits come from the
/// reduction: the f32 nearest each multiple up to the limit, and its neighbours.
#[test]
fn keeps_relative_accuracy_next_to_multiples_of_a_right_angle() {
    let k_max = (f64::from(LIMIT) / std::f64::consts::FRAC_PI_2) as i32;
    let mut worst_error = 0;
    for k in (-k_max..=k_max).filter(|&k| k != 0) {
        let x = (f64::from(k) * std::f64::consts::FRAC_PI_2) as f32;
        let step = |n: i32| f32::from_bits(x.to_bits().wrapping_add_signed(n));
        for neighbour in [step(-1), x, step(1)] {
            let error = error_in_ulps(neighbour);
            worst_error = worst_error.max(error);
            assert!(error <= 2, "{error} ulp at x = {neighbour:e} (k = {k})");
        }
    }
    println!("next to k·π/2 up to the limit: {worst_error} ulp at most");
    assert!(error_in_ulps(FRAC_PI_2) <= 1);
}

#[test]
fn zeros_tiny_and_non_finite_arguments() {
    let (s, c) = sin_cos(-0.0);
    assert!(s == 0.0 && s.is_sign_negative() && c == 1.0);
    let (s, c) = sin_cos(0.0);
    assert!(s == 0.0 && s.is_sign_positive() && c == 1.0);
    for tiny in [
        f32::from_bits(1),
        -f32::MIN_POSITIVE / 3.0,
        1e-30,
        -3e-12,
        2.4e-4,
    ] {
        assert_eq!(error_in_ulps(tiny), 0, "x = {tiny:e}");
    }
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        let (s, c) = sin_cos(bad);
        assert!(s.is_nan() && c.is_nan(), "x = {bad}");
    }
}

/// Past the limit the angle goes through the f64 kernel, which hands it to the platform's f64
/// functions: their pair rounded.
#[test]
fn beyond_the_limit_gives_the_f64_platform_result_rounded() {
    for x in [LIMIT * 1.0001, -2e6, 1e10, f32::MAX] {
        let (s, c) = f64::from(x).sin_cos();
        assert_eq!(sin_cos(x), (s as f32, c as f32), "x = {x:e}");
    }
}

/// Several angles in one call give what each gives alone, bit for bit, also when some take
/// the cold path (huge, NaN) and the others do not, and when some are within ±π/4 and some not.
#[test]
fn angles_together_equal_angles_alone() {
    assert_eq!(eom_kernel::sin_cos::<f32, 0>([]), []);
    let same = |a: (f32, f32), b: (f32, f32)| {
        a.0.to_bits() == b.0.to_bits() && a.1.to_bits() == b.1.to_bits()
    };
    let mixed = [0.3, -2.5, 1e7, f32::NAN, -1e-12, 700.0, -0.0];
    for (x, pair) in mixed.into_iter().zip(eom_kernel::sin_cos(mixed)) {
        assert!(same(pair, sin_cos(x)), "x = {x:e}");
    }
    let angles: Vec<f32> = uniform(3000, 0x51ED_2701)
        .enumerate()
        .map(|(i, u)| ((2.0 * u - 1.0) * if i < 1500 { 1.5 } else { 50.0 }) as f32)
        .collect();
    for three in angles.chunks_exact(3) {
        let together = eom_kernel::sin_cos([three[0], three[1], three[2]]);
        for (&x, pair) in three.iter().zip(together) {
            assert!(same(pair, sin_cos(x)), "x = {x:e}");
        }
    }
    for two in angles.chunks_exact(2) {
        let together = eom_kernel::sin_cos([two[0], two[1]]);
        for (&x, pair) in two.iter().zip(together) {
            assert!(same(pair, sin_cos(x)), "x = {x:e}");
        }
    }
}

/// `sin_cos` on f32 is the f32 kernel, `sin_cos_f32`.
#[test]
fn sin_cos_on_f32_is_the_f32_kernel() {
    for x in uniform(10_000, 0xC0FF_EE11).map(|u| ((2.0 * u - 1.0) * 1e3) as f32) {
        assert_eq!(sin_cos(x), eom_kernel::sin_cos_f32([x])[0], "x = {x:e}");
    }
}
