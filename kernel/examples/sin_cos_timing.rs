//! Prices the kernel against the platform: ns per call of `eom_kernel::sin_cos_f64` and of
//! `f64::sin_cos`, on one angle and on three, for angles within ±π/4 (no reduction) and
//! beyond it. The four calls take turns, round after round, so that what a shared machine
//! does meanwhile falls on all of them alike; the median round is printed.
//!
//! ```sh
//! cargo run --release -p eom-kernel --example sin_cos_timing
//! ```

use std::hint::black_box;
use std::time::Instant;

const ANGLES: usize = 3 * 1024;
const PASSES: usize = 50;
const ROUNDS: usize = 31;

/// Nanoseconds per call of `f` on each of `angles`, in groups of `N`.
fn time<const N: usize>(angles: &[f64], f: impl Fn([f64; N]) -> [(f64, f64); N]) -> f64 {
    let start = Instant::now();
    let mut sum = 0.0;
    for _ in 0..PASSES {
        for group in angles.chunks_exact(N) {
            let pairs = f(black_box(group.try_into().expect("a group of N")));
            sum += pairs.iter().map(|(s, c)| s + c).sum::<f64>();
        }
    }
    black_box(sum);
    start.elapsed().as_secs_f64() * 1e9 / (PASSES * angles.len() / N) as f64
}

fn median(mut times: Vec<f64>) -> f64 {
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

fn main() {
    let platform = |x: f64| x.sin_cos();
    for (range, low, high) in [("|x| < π/4", 0.0, 0.78), ("π/4 < |x| < π", 0.8, 3.1)] {
        // A fixed spread of magnitudes and signs over the range.
        let angles: Vec<f64> = (0..ANGLES)
            .map(|i| {
                let u = (i as f64 * 0.618_033_988_75).fract();
                let sign = if i % 2 == 0 { 1.0 } else { -1.0 };
                sign * (low + u * (high - low))
            })
            .collect();
        let mut rows = [const { Vec::new() }; 4];
        for _ in 0..ROUNDS {
            rows[0].push(time::<1>(&angles, eom_kernel::sin_cos_f64));
            rows[1].push(time::<1>(&angles, |x| x.map(platform)));
            rows[2].push(time::<3>(&angles, eom_kernel::sin_cos_f64));
            rows[3].push(time::<3>(&angles, |x| x.map(platform)));
        }
        let [kernel_1, platform_1, kernel_3, platform_3] = rows.map(median);
        println!(
            "{range}: 1 angle {kernel_1:.2} ns kernel, {platform_1:.2} ns platform; \
             3 angles {kernel_3:.2} ns kernel, {platform_3:.2} ns platform"
        );
    }
}
