//! Prices the kernels against the platform: ns per call of `eom_kernel::sin_cos_f64`, of
//! `f64::sin_cos`, of the f32 kernel `eom_kernel::sin_cos_f32` and of f32 through the f64
//! kernel (widened, rounded once: what `sin_cos` did for f32 before it had a kernel of its
//! own), on one angle and on three, for angles within ±π/4 (no reduction) and beyond it. The
//! calls take turns, round after round, so that what a shared machine does meanwhile falls on
//! all of them alike; the median round is printed.
//!
//! ```sh
//! cargo run --release -p eom-kernel --example sin_cos_timing
//! ```

use std::hint::black_box;
use std::ops::Add;
use std::time::Instant;

const ANGLES: usize = 3 * 1024;
const PASSES: usize = 50;
const ROUNDS: usize = 31;

/// Nanoseconds per call of `f` on each of `angles`, in groups of `N`; the results are summed
/// in their own type, so that f32 pays for no conversion the models would not make.
fn time<T: Copy + Default + Add<Output = T>, const N: usize>(
    angles: &[T],
    f: impl Fn([T; N]) -> [(T, T); N],
) -> f64 {
    let start = Instant::now();
    let mut sum = T::default();
    for _ in 0..PASSES {
        for group in angles.chunks_exact(N) {
            let pairs = f(black_box(group.try_into().expect("a group of N")));
            sum = pairs.iter().fold(sum, |sum, &(s, c)| sum + (s + c));
        }
    }
    black_box(sum);
    start.elapsed().as_secs_f64() * 1e9 / (PASSES * angles.len() / N) as f64
}

/// f32 angles through the f64 kernel, rounded once.
#[inline(always)]
fn f32_via_f64<const N: usize>(x: [f32; N]) -> [(f32, f32); N] {
    eom_kernel::sin_cos_f64(x.map(f64::from)).map(|(s, c)| (s as f32, c as f32))
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
        let angles32: Vec<f32> = angles.iter().map(|&x| x as f32).collect();
        let mut rows = [const { Vec::new() }; 8];
        for _ in 0..ROUNDS {
            rows[0].push(time::<_, 1>(&angles, eom_kernel::sin_cos_f64));
            rows[1].push(time::<_, 1>(&angles, |x| x.map(platform)));
            rows[2].push(time::<_, 1>(&angles32, eom_kernel::sin_cos_f32));
            rows[3].push(time::<_, 1>(&angles32, f32_via_f64));
            rows[4].push(time::<_, 3>(&angles, eom_kernel::sin_cos_f64));
            rows[5].push(time::<_, 3>(&angles, |x| x.map(platform)));
            rows[6].push(time::<_, 3>(&angles32, eom_kernel::sin_cos_f32));
            rows[7].push(time::<_, 3>(&angles32, f32_via_f64));
        }
        let [k1, p1, n1, w1, k3, p3, n3, w3] = rows.map(median);
        println!(
            "{range}: 1 angle {k1:.2} ns f64 kernel, {p1:.2} ns f64 platform, \
             {n1:.2} ns f32 kernel, {w1:.2} ns f32 via f64 kernel; \
             3 angles {k3:.2} ns f64 kernel, {p3:.2} ns f64 platform, \
             {n3:.2} ns f32 kernel, {w3:.2} ns f32 via f64 kernel"
        );
    }
}
