//! The energy plot: the relative drift on a symmetric logarithmic axis, linear through zero
//! within round-off and a decade per unit above it.

use super::precise::PixelFrame;
use super::scale::{bounded, decimate, extent, tick_label};
use super::series::time_range;
use super::{COLOURS, DrawError, FONT, LABEL_FONT, TITLE_FONT, WIDTH, fitted_caption, render};
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, KeyPointWeight};
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;

/// Below this magnitude the energy axis is linear, above it logarithmic: a few units of
/// double-precision round-off, under which a relative drift means nothing.
pub(super) const LINEAR_BELOW: f64 = 1e-16;

/// The symmetric logarithm of a drift: `sign(d)·log₁₀(1 + |d|/c)` with `c` =
/// [`LINEAR_BELOW`]. Linear through zero, a decade per unit above `c`: drifts of 10⁻¹⁴ and of
/// 10⁻³ are both told apart from zero and from each other, with either sign.
pub(super) fn symlog(d: f64) -> f64 {
    d.signum() * (d.abs() / LINEAR_BELOW).ln_1p() / std::f64::consts::LN_10
}

/// The inverse of [`symlog`].
pub(super) fn symexp(s: f64) -> f64 {
    s.signum() * LINEAR_BELOW * (s.abs() * std::f64::consts::LN_10).exp_m1()
}

/// The energy axis: drifts placed by their [`symlog`] between `low` and `high` (in symlog
/// units), ticked at zero and at the decades ±10ᵏ inside it.
#[derive(Clone)]
struct SymlogAxis {
    /// The bottom of the axis, in symlog units.
    low: f64,
    /// The top of the axis, in symlog units.
    high: f64,
}

impl Ranged for SymlogAxis {
    // The labels come from the chart's formatter ([`decade_label`]).
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, drift: &f64, limit: (i32, i32)) -> i32 {
        RangedCoordf64::from(self.low..self.high).map(&symlog(*drift), limit)
    }

    /// Zero and the decades ±10ᵏ inside the axis from 10⁻¹⁵ up, every second or third decade
    /// when there would be more than sixteen; no light points (no minor grid). ±10⁻¹⁶, the
    /// edge of the linear part, lies 0.3 decade from zero, where its label would overwrite
    /// zero's; the axis's description names it instead.
    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if let KeyPointWeight::Any = hint.weight() {
            return Vec::new();
        }
        let top = symexp(self.low.abs().max(self.high.abs()));
        // Up to 10³⁰⁸, the largest finite decade (a drift past it is drawn at the top).
        let lowest = LINEAR_BELOW.log10().round() as i32 + 1;
        let highest = (top.log10().floor().min(308.0) as i32).max(lowest);
        let inside = |d: &f64| (self.low..=self.high).contains(&symlog(*d));
        let decades: Vec<(i32, f64)> = (lowest..=highest)
            .flat_map(|k| [(k, -10f64.powi(k)), (k, 10f64.powi(k))])
            .filter(|(_, d)| inside(d))
            .collect();
        // At most sixteen decades in all (of either sign), counted down from the top one.
        let stride = decades.len().saturating_sub(1) as i32 / 16 + 1;
        let mut ticks = vec![0.0];
        ticks.extend(
            decades
                .into_iter()
                .filter(|(k, _)| (highest - k) % stride == 0)
                .map(|(_, d)| d),
        );
        ticks.sort_by(f64::total_cmp);
        ticks
    }

    fn range(&self) -> std::ops::Range<f64> {
        symexp(self.low)..symexp(self.high)
    }
}

/// The label of an energy-axis tick: the decade, to one significant digit.
pub(super) fn decade_label(d: f64) -> String {
    if d == 0.0 {
        "0".to_string()
    } else {
        format!("{d:.0e}")
    }
}

/// The energy plot: the relative drift on a symmetric logarithmic axis ([`symlog`]).
pub(super) fn draw_energy(
    svg: &mut String,
    title: &str,
    time: &[f64],
    drift: &[f64],
) -> Result<(), DrawError> {
    let size = (WIDTH, 460);
    let time_range = time_range(time);
    let largest = drift
        .iter()
        .filter(|d| d.is_finite())
        .fold(0.0f64, |m, d| m.max(d.abs()));
    let (caption, caption_size) = fitted_caption(
        &format!("{title}: relative energy drift, largest |ΔE/E₀| = {largest:.1e}"),
        TITLE_FONT,
        WIDTH,
    );
    render(svg, size, |root, overlay| {
        let windows = size.0 as usize;
        let finite = |i: usize| time[i].is_finite() && drift[i].is_finite();
        let points: Vec<(f64, f64)> = decimate(time.len(), windows, finite, &[drift])
            .into_iter()
            .map(|i| (bounded(time[i]), drift[i]))
            .collect();
        // The range holds zero, so that the sign of a drift reads at a glance.
        let range = extent(points.iter().map(|p| symlog(p.1)).chain([0.0]));
        let range = match range {
            Some((lo, hi)) if hi - lo > 0.0 => {
                let pad = 0.05 * (hi - lo);
                (lo - pad, hi + pad)
            }
            _ => (-1.0, 1.0),
        };
        let time_ticks = 8;
        let x_label = |v: &f64| tick_label(*v, time_range, time_ticks);
        let y_label = |d: &f64| decade_label(*d);
        let mut chart = ChartBuilder::on(root)
            .caption(&caption, (FONT, caption_size))
            .margin(12)
            .x_label_area_size(52)
            .y_label_area_size(96)
            .build_cartesian_2d(
                time_range.0..time_range.1,
                SymlogAxis {
                    low: range.0,
                    high: range.1,
                },
            )?;
        chart
            .configure_mesh()
            .x_labels(time_ticks)
            .x_label_formatter(&x_label)
            .y_label_formatter(&y_label)
            .light_line_style(TRANSPARENT)
            .label_style((FONT, LABEL_FONT))
            .axis_desc_style((FONT, LABEL_FONT))
            .x_desc("t [s]")
            .y_desc("(E − E₀)/|E₀|, symmetric log, linear below 1e-16")
            .draw()?;
        let frame = PixelFrame::new(chart.plotting_area().get_pixel_range(), time_range, range);
        let pixels = points.iter().map(|&(t, d)| frame.at((t, symlog(d))));
        overlay.line(root, pixels, COLOURS[0], 1)?;
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_energy_axis_tells_round_off_from_drift() {
        assert_eq!(symlog(0.0), 0.0);
        for d in [1e-16, 1e-14, -1e-14, 1e-3, -0.5] {
            assert!((symexp(symlog(d)) / d - 1.0).abs() < 1e-12, "{d}");
        }
        // A decade per unit above round-off.
        assert!((symlog(1e-3) - symlog(1e-4) - 1.0).abs() < 1e-9);
        let ticks = |low: f64, high: f64| {
            let axis = SymlogAxis {
                low: symlog(low) * 1.05,
                high: symlog(high) * 1.05,
            };
            axis.key_points(plotters::coord::ranged1d::BoldPoints(10))
        };
        // A drift from zero to 10⁻³: every decade from round-off up, but for the edge of the
        // linear part, whose label would sit on zero's.
        let drift = ticks(0.0, 1e-3);
        for d in [0.0, 1e-15, 1e-14, 1e-3] {
            assert!(drift.contains(&d), "{d:e} not in {drift:?}");
        }
        assert!(!drift.contains(&1e-16), "{drift:?}");
        // Of either sign: every second decade, the top one kept.
        let both = ticks(-1e-3, 1e-3);
        for d in [-1e-3, -1e-15, 0.0, 1e-15, 1e-3] {
            assert!(both.contains(&d), "{d:e} not in {both:?}");
        }
        assert!(both.len() <= 17, "{both:?}");
        assert_eq!(decade_label(1e-14), "1e-14");
        assert_eq!(decade_label(-1e-3), "-1e-3");
    }
}
