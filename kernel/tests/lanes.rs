//! The kernel on SIMD lanes gives each lane, bit for bit, what the scalar kernel gives that
//! angle: f64×4 against `sin_cos_f64`, f32×8 against `sin_cos_f32`, over every path (inside
//! ±π/4, reduced, tiny, beyond the limit, NaN, ±∞, ±0) and lanes that mix them.
#![cfg(not(feature = "platform-trig"))]

use simba::simd::{WideF32x8, WideF64x4};

#[path = "support/uniform.rs"]
mod uniform;
use uniform::uniform;

/// Angles of every kind: uniform within ±1, ±10, ±1e3, ±1e5, and the special ones.
fn angles() -> Vec<f64> {
    let mut angles: Vec<f64> = uniform(40_000, 0x1A7E_5EED)
        .enumerate()
        .map(|(i, u)| (2.0 * u - 1.0) * [1.0, 10.0, 1e3, 1e5][i % 4])
        .collect();
    let special = [
        0.0,
        -0.0,
        1e-300,
        -3e-9,
        f64::MIN_POSITIVE,
        std::f64::consts::FRAC_PI_4,
        -std::f64::consts::FRAC_PI_4,
        823_549.0,
        823_550.0,
        1e10,
        -1e300,
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
    ];
    // Each special one lands in every lane position, beside ordinary angles.
    for (i, x) in special.into_iter().enumerate() {
        for lane in 0..8 {
            angles.splice(
                8 * (i * 8 + lane) + lane..8 * (i * 8 + lane) + lane + 1,
                [x],
            );
        }
    }
    angles
}

fn same_bits(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

#[test]
fn f64_lanes_are_the_scalar_kernel_lane_by_lane() {
    for chunk in angles().chunks_exact(4) {
        let lanes = WideF64x4::from([chunk[0], chunk[1], chunk[2], chunk[3]]);
        let [(s, c)] = eom_kernel::sin_cos([lanes]);
        let (s, c) = (s.0.to_array(), c.0.to_array());
        for (i, &x) in chunk.iter().enumerate() {
            let [(s0, c0)] = eom_kernel::sin_cos_f64([x]);
            assert!(
                same_bits(s[i], s0) && same_bits(c[i], c0),
                "x = {x:e} in lane {i}: ({}, {}) against ({s0}, {c0})",
                s[i],
                c[i]
            );
        }
    }
}

#[test]
fn f32_lanes_are_the_scalar_kernel_lane_by_lane() {
    let angles: Vec<f32> = angles().into_iter().map(|x| x as f32).collect();
    for chunk in angles.chunks_exact(8) {
        let lanes = WideF32x8::from(<[f32; 8]>::try_from(chunk).unwrap());
        let [(s, c)] = eom_kernel::sin_cos([lanes]);
        let (s, c) = (s.0.to_array(), c.0.to_array());
        for (i, &x) in chunk.iter().enumerate() {
            let [(s0, c0)] = eom_kernel::sin_cos_f32([x]);
            let same = |a: f32, b: f32| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan());
            assert!(
                same(s[i], s0) && same(c[i], c0),
                "x = {x:e} in lane {i}: ({}, {}) against ({s0}, {c0})",
                s[i],
                c[i]
            );
        }
    }
}

/// Three angles of lanes in one call, as an Euler-angle model makes it, give what each gives
/// alone.
#[test]
fn several_lane_angles_in_one_call() {
    let angles = angles();
    for chunk in angles.chunks_exact(12).take(2000) {
        let lane = |k: usize| WideF64x4::from([chunk[k], chunk[k + 3], chunk[k + 6], chunk[k + 9]]);
        let together = eom_kernel::sin_cos([lane(0), lane(1), lane(2)]);
        for (k, (s, c)) in together.into_iter().enumerate() {
            let [(s1, c1)] = eom_kernel::sin_cos([lane(k)]);
            assert_eq!(
                s.0.to_array().map(f64::to_bits),
                s1.0.to_array().map(f64::to_bits)
            );
            assert_eq!(
                c.0.to_array().map(f64::to_bits),
                c1.0.to_array().map(f64::to_bits)
            );
        }
    }
}
