//! Every f32 in [−2π, 2π], 2.2 billion angles, through `eom_kernel::sin_cos` against f64
//! `sin` and `cos` rounded to f32: the largest error in ulps. About 20 s in a release build:
//!
//! ```sh
//! cargo run --release -p eom-kernel --example f32_exhaustive
//! ```
//!
//! The test suite checks every 499th of these angles (`tests/sin_cos_f32.rs`); this is the
//! whole range, for a change to the kernel.

use std::f32::consts::FRAC_PI_4;

/// The kernel on one angle.
fn sin_cos(x: f32) -> (f32, f32) {
    let [pair] = eom_kernel::sin_cos([x]);
    pair
}

/// How many f32 lie between `a` and `b` (0 if equal, ±0 counted as one, NaN as equal to NaN).
fn ulps_apart(a: f32, b: f32) -> u32 {
    if a.is_nan() && b.is_nan() {
        return 0;
    }
    let ordered = |v: f32| {
        let bits = v.to_bits() as i32;
        i64::from(if bits < 0 { i32::MIN - bits } else { bits })
    };
    (ordered(a) - ordered(b)).unsigned_abs() as u32
}

/// The larger of the two errors of the kernel at `x`, in f32 ulps of the correctly rounded
/// pair.
fn error_in_ulps(x: f32) -> u32 {
    let (s, c) = sin_cos(x);
    let (s0, c0) = f64::from(x).sin_cos();
    ulps_apart(s, s0 as f32).max(ulps_apart(c, c0 as f32))
}

fn main() {
    let top = (8.0 * FRAC_PI_4).to_bits();
    let (mut worst, mut at) = (0, 0.0f32);
    for bits in 0..=top {
        for x in [f32::from_bits(bits), -f32::from_bits(bits)] {
            let error = error_in_ulps(x);
            if error > worst {
                (worst, at) = (error, x);
            }
        }
    }
    println!("every f32 with |x| ≤ 2π: {worst} ulp at most (at x = {at:e})");
}
