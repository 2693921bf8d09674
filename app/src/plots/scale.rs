//! Which samples a plot draws and where its axes run: decimation to about one window of
//! samples per pixel (keeping each window's extremes), the clamp that keeps a range finite,
//! and axis ranges and tick labels with the digits their spacing needs.

/// The indices of the samples to draw out of `len`, in order: all of them if there are few,
/// else, in each of `windows` runs of consecutive samples, the first, the last and, for each
/// column of `extremes`, the smallest and the largest. Samples that `finite` rejects are
/// never kept. At most `(2 + 2·extremes.len())·windows` indices come back, in one pass.
pub(super) fn decimate(
    len: usize,
    windows: usize,
    finite: impl Fn(usize) -> bool,
    extremes: &[&[f64]],
) -> Vec<usize> {
    let windows = windows.max(1);
    let per_window = 2 + 2 * extremes.len();
    if len <= per_window * windows {
        return (0..len).filter(|&i| finite(i)).collect();
    }
    let mut kept = Vec::with_capacity(per_window * windows);
    let mut chosen = Vec::with_capacity(per_window);
    for w in 0..windows {
        let (start, end) = (w * len / windows, (w + 1) * len / windows);
        let Some(first) = (start..end).find(|&i| finite(i)) else {
            continue;
        };
        let last = (first..end).rev().find(|&i| finite(i)).unwrap_or(first);
        chosen.clear();
        chosen.extend([first, last]);
        for column in extremes {
            let (mut low, mut high) = (first, first);
            for i in first + 1..=last {
                if finite(i) {
                    if column[i] < column[low] {
                        low = i;
                    }
                    if column[i] > column[high] {
                        high = i;
                    }
                }
            }
            chosen.extend([low, high]);
        }
        chosen.sort_unstable();
        chosen.dedup();
        kept.extend_from_slice(&chosen);
    }
    kept
}

/// The largest magnitude drawn: beyond it a value is drawn at it, so that an axis range and
/// its width stay finite.
const HUGE: f64 = 1e300;

/// Clamps a finite value to ±[`HUGE`].
pub(super) fn bounded(v: f64) -> f64 {
    v.clamp(-HUGE, HUGE)
}

/// The smallest and largest of the values, if any.
pub(super) fn extent(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
    values.into_iter().fold(None, |range, v| match range {
        None => Some((v, v)),
        Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
    })
}

/// An axis range around `extent` with a margin of 5 % each side; a range narrower than
/// 10⁻⁸ of its magnitude (a constant, or round-off on a constant) is widened to that, so that
/// the tick labels tell their ticks apart in ten digits; no extent gives [−1, 1].
pub(super) fn axis_range(extent: Option<(f64, f64)>) -> (f64, f64) {
    let Some((lo, hi)) = extent else {
        return (-1.0, 1.0);
    };
    let magnitude = lo.abs().max(hi.abs());
    if magnitude == 0.0 {
        return (-1.0, 1.0);
    }
    let centre = lo / 2.0 + hi / 2.0;
    let half = (hi / 2.0 - lo / 2.0).max(magnitude * 0.5e-8);
    (centre - 1.05 * half, centre + 1.05 * half)
}

/// The tick label of `v` on an axis over `range` with about `ticks` ticks: fixed-point with
/// as many decimals as the tick spacing needs, or, on an axis reaching 10⁵ or staying below
/// 10⁻³, scientific with as many digits as the spacing needs at the value's own exponent.
pub(super) fn tick_label(v: f64, range: (f64, f64), ticks: usize) -> String {
    let step = (range.1 - range.0) / ticks.max(1) as f64;
    if v.abs() < step * 1e-6 {
        return "0".to_string();
    }
    let step_exponent = step.log10().floor() as i32;
    let magnitude = range.0.abs().max(range.1.abs());
    if !(1e-3..1e5).contains(&magnitude) {
        let digits = (v.abs().log10().floor() as i32 - step_exponent).clamp(0, 12) as usize;
        format!("{v:.digits$e}")
    } else {
        let decimals = (-step_exponent).clamp(0, 12) as usize;
        format!("{v:.decimals$}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimation_keeps_every_window_s_extremes() {
        // A flat series with one spike of one sample, up and one down.
        let mut y = vec![0.0; 1_000_000];
        y[123_457] = 5.0;
        y[765_433] = -3.0;
        let kept = decimate(y.len(), 500, |i| y[i].is_finite(), &[&y]);
        assert!(kept.len() <= 4 * 500);
        assert!(kept.contains(&123_457) && kept.contains(&765_433));
        assert_eq!((kept[0], kept[kept.len() - 1]), (0, 999_999));
        assert!(kept.windows(2).all(|w| w[0] < w[1]), "in order, once each");
        // Few samples are all kept, less the non-finite.
        let few = [1.0, f64::NAN, 3.0];
        assert_eq!(decimate(3, 500, |i| few[i].is_finite(), &[&few]), [0, 2]);
    }

    #[test]
    fn tick_labels_have_the_digits_their_spacing_needs() {
        assert_eq!(tick_label(0.4, (0.0, 1.0), 5), "0.4");
        assert_eq!(tick_label(0.05, (0.0, 0.2), 5), "0.05");
        assert_eq!(tick_label(120.0, (0.0, 1000.0), 5), "120");
        assert_eq!(tick_label(2e-5, (0.0, 1e-4), 5), "2e-5");
        assert_eq!(tick_label(1e-17, (-1.0, 1.0), 5), "0");
        assert_eq!(tick_label(1.2e-4, (0.0, 1e-4), 5), "1.2e-4");
        assert_eq!(tick_label(400_000.0, (0.0, 1e6), 5), "4e5");
        // Round-off on a constant: the range is widened to 10⁻¹⁰ of the value, and the
        // labels tell the ticks apart.
        let range = axis_range(Some((1.0, 1.0 + 1e-15)));
        assert!(range.1 - range.0 > 1e-8);
        assert_eq!(tick_label(1.0 + 2e-9, range, 5), "1.000000002");
    }
}
