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

#[path = "../tests/support/f32_ulps.rs"]
mod f32_ulps;
use f32_ulps::error_in_ulps;

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
