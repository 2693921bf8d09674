//! The polhode plot of a body turning free of moments about G.
//!
//! Free of moments, a body keeps its kinetic energy T (4.32) and the magnitude of its angular
//! momentum H, so its angular velocity ω, seen in principal axes, stays on two surfaces at
//! once: the energy ellipsoid I₁ω₁² + I₂ω₂² + I₃ω₃² = 2T and the momentum ellipsoid
//! I₁²ω₁² + I₂²ω₂² + I₃²ω₃² = H². Their intersection, the polhode, is all that ω can do: a
//! loop about the axis of the largest or of the smallest moment, never about the middle one,
//! which is why the tennis racket turns over. The plot draws the run's ω in three orthographic
//! projections (ω₁–ω₂, ω₂–ω₃, ω₃–ω₁) with the outline of the energy ellipsoid and, dashed
//! over the run, the polhode computed from the first row's T and H² alone: where the run
//! leaves the dashed curve, the integrator has let T or H drift.
//!
//! The curve is sampled analytically. The loop goes round axis k (the largest moment's when
//! H² ≥ 2T·I_middle, else the smallest's); with a and b the other two, given ω_a the two
//! surfaces are a linear system in ω_b² and ω_k², and ω_b² is affine in ω_a², zero where
//! |ω_a| is largest. So ω_a = A sin φ gives ω_b = B cos φ, and ω_k has the sign it starts
//! with: evenly spaced φ give points evenly spread round the loop, ends included.

use super::precise::{Overlay, PixelFrame};
use super::scale::{bounded, decimate, extent, tick_label};
use super::{
    Area, COLOURS, DrawError, FONT, LABEL_FONT, PANEL_FONT, TITLE_FONT, WIDTH, fitted_caption,
    render,
};
use eom::InertiaTensor;
use eom::Short;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::f64::consts::TAU;

/// A free body's angular velocity in principal axes, for the polhode plot.
#[derive(Clone, Copy)]
pub struct Polhode<'a> {
    /// The principal moments I₁, I₂, I₃, kg m², in the order of the columns.
    pub moments: [f64; 3],
    /// ω₁, ω₂, ω₃ in principal axes, rad/s, one value per sample time each.
    pub omega: [&'a [f64]; 3],
}

/// The principal moments of `tensor` and the body rates `rates` (p, q, r) turned into its
/// principal axes. A tensor without products (the `principal` symmetry class) keeps the body
/// axes in their order, so ω₁, ω₂, ω₃ are p, q, r; any other is turned onto its
/// eigenvectors, moments ascending.
pub fn in_principal_axes(tensor: &InertiaTensor, rates: [&[f64]; 3]) -> ([f64; 3], [Vec<f64>; 3]) {
    if tensor.ixy() == 0.0 && tensor.iyz() == 0.0 && tensor.izx() == 0.0 {
        let moments = [tensor.ixx(), tensor.iyy(), tensor.izz()];
        return (moments, rates.map(<[f64]>::to_vec));
    }
    let (moments, axes) = tensor.principal();
    let len = rates.iter().map(|c| c.len()).min().unwrap_or(0);
    let turned = [0, 1, 2].map(|k| {
        (0..len)
            .map(|row| (0..3).map(|j| axes[(j, k)] * rates[j][row]).sum())
            .collect()
    });
    ([moments[0], moments[1], moments[2]], turned)
}

/// 2T = Σ Iᵢωᵢ² and H² = Σ Iᵢ²ωᵢ² of `omega` in principal axes.
pub(super) fn invariants(moments: [f64; 3], omega: [f64; 3]) -> (f64, f64) {
    (0..3).fold((0.0, 0.0), |(two_t, h2), k| {
        let (i, w2) = (moments[k], omega[k] * omega[k]);
        (two_t + i * w2, h2 + i * i * w2)
    })
}

/// The squares of ω_other and ω_k where ω_given = `value`, from the two surfaces; `None` when
/// the system is singular (I_other = I_k).
fn squares(
    moments: [f64; 3],
    (two_t, h2): (f64, f64),
    (given, other, k): (usize, usize, usize),
    value: f64,
) -> Option<(f64, f64)> {
    let (ig, io, ik) = (moments[given], moments[other], moments[k]);
    let (e, m) = (two_t - ig * value * value, h2 - ig * ig * value * value);
    // io·x_o + ik·x_k = e and io²·x_o + ik²·x_k = m, by Cramer's rule.
    let det = io * ik * (ik - io);
    if det.abs() <= 1e-12 * io * ik * io.max(ik) || !det.is_finite() {
        return None;
    }
    Some(((e * ik * ik - ik * m) / det, (io * m - io * io * e) / det))
}

/// `samples + 1` points round the polhode through `start` (the first and last the same), or
/// `None` where there is no loop: ω zero or not finite, or a permanent rotation about an axis
/// whose moment another shares.
pub(super) fn polhode_curve(
    moments: [f64; 3],
    start: [f64; 3],
    samples: usize,
) -> Option<Vec<[f64; 3]>> {
    let invariants = invariants(moments, start);
    let (two_t, h2) = invariants;
    if !(two_t > 0.0 && h2 > 0.0 && two_t.is_finite() && h2.is_finite()) {
        return None;
    }
    let mut order = [0, 1, 2];
    order.sort_by(|&a, &b| moments[a].total_cmp(&moments[b]));
    let k = if h2 >= two_t * moments[order[1]] {
        order[2]
    } else {
        order[0]
    };
    let (a, b) = ((k + 1) % 3, (k + 2) % 3);
    let (a_squared, _) = squares(moments, invariants, (b, a, k), 0.0)?;
    let amplitude = a_squared.max(0.0).sqrt();
    let sign = if start[k] < 0.0 { -1.0 } else { 1.0 };
    (0..=samples.max(1))
        .map(|n| {
            let phi = TAU * n as f64 / samples.max(1) as f64;
            let wa = amplitude * phi.sin();
            let (b_squared, k_squared) = squares(moments, invariants, (a, b, k), wa)?;
            let mut point = [0.0; 3];
            point[a] = wa;
            point[b] = phi.cos().signum() * b_squared.max(0.0).sqrt();
            point[k] = sign * k_squared.max(0.0).sqrt();
            Some(point)
        })
        .collect()
}

/// The three projections: (horizontal, vertical) component indices.
const PROJECTIONS: [(usize, usize); 3] = [(0, 1), (1, 2), (2, 0)];
/// The components' names.
const NAMES: [&str; 3] = ["ω₁", "ω₂", "ω₃"];
/// The colour of the energy ellipsoid's outline.
const GREY: RGBColor = RGBColor(150, 150, 150);

/// What the polhode plot draws, worked out before drawing.
struct Figure {
    /// The run's ω, decimated, finite.
    run: Vec<[f64; 3]>,
    /// The theoretical polhode, if there is a loop.
    curve: Option<Vec<[f64; 3]>>,
    /// The energy ellipsoid's semi-axes √(2T/Iᵢ), where T > 0.
    semi_axes: Option<[f64; 3]>,
    /// The caption.
    caption: String,
    /// The figures under the legend: T, |H| and the axis the loop goes round.
    figures: Vec<String>,
}

impl Figure {
    fn new(title: &str, polhode: &Polhode) -> Figure {
        let [w1, w2, w3] = polhode.omega;
        let len = w1.len().min(w2.len()).min(w3.len());
        let finite = |i: usize| w1[i].is_finite() && w2[i].is_finite() && w3[i].is_finite();
        let run: Vec<[f64; 3]> = decimate(len, 600, finite, &[w1, w2, w3])
            .into_iter()
            .map(|i| [bounded(w1[i]), bounded(w2[i]), bounded(w3[i])])
            .collect();
        let moments = polhode.moments;
        let start = run.first().copied();
        let curve = start.and_then(|s| polhode_curve(moments, s, 720));
        let two_t = start.map(|s| invariants(moments, s).0);
        let semi_axes = two_t
            .filter(|t| *t > 0.0 && t.is_finite() && moments.iter().all(|i| *i > 0.0))
            .map(|t| moments.map(|i| (t / i).sqrt()));
        let [i1, i2, i3] = moments.map(Short);
        let mut caption =
            format!("{title}: polhode, ω in principal axes (I = {i1}, {i2}, {i3} kg m²)");
        match (start, two_t, &curve) {
            (None, _, _) => caption.push_str(", no finite ω"),
            (_, Some(0.0), None) => caption.push_str(", ω = 0"),
            (_, _, None) => caption.push_str(", a permanent rotation"),
            _ => {}
        }
        let figures = start.map_or_else(Vec::new, |s| figures(moments, s, curve.is_some()));
        Figure {
            run,
            curve,
            semi_axes,
            caption,
            figures,
        }
    }

    /// A projection's square window, as its centre and half-width: round the run and the
    /// polhode, so that a small loop on a large ellipsoid (a spinning plate's wobble) fills it,
    /// and at least a twentieth of the ellipsoid's reach, so that a loop shrunk to a point (a
    /// permanent rotation) shows the run's round-off no larger than it is.
    fn window(&self, (h, v): (usize, usize)) -> ((f64, f64), f64) {
        let curve = self.curve.iter().flatten();
        let points: Vec<&[f64; 3]> = self.run.iter().chain(curve).collect();
        let outline = self.semi_axes.map_or(0.0, |s| s[h].max(s[v]));
        let (Some(x), Some(y)) = (
            extent(points.iter().map(|w| w[h])),
            extent(points.iter().map(|w| w[v])),
        ) else {
            return ((0.0, 0.0), if outline > 0.0 { 1.08 * outline } else { 1.0 });
        };
        let centre = (x.0 / 2.0 + x.1 / 2.0, y.0 / 2.0 + y.1 / 2.0);
        let half = (0.55 * (x.1 - x.0).max(y.1 - y.0)).max(0.05 * outline);
        let half = if half > 0.0 && half.is_finite() {
            half
        } else {
            1.0
        };
        (centre, half)
    }
}

/// The runs of consecutive `points` inside `window` (x and y ranges), each a line to draw.
fn inside(points: &[(f64, f64)], (x, y): ((f64, f64), (f64, f64))) -> Vec<Vec<(f64, f64)>> {
    let within = |p: &(f64, f64)| (x.0..=x.1).contains(&p.0) && (y.0..=y.1).contains(&p.1);
    let mut runs: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut previous = false;
    for point in points {
        let now = within(point);
        match (now, previous) {
            (true, true) => runs.last_mut().into_iter().for_each(|r| r.push(*point)),
            (true, false) => runs.push(vec![*point]),
            _ => {}
        }
        previous = now;
    }
    runs.retain(|r| r.len() > 1);
    runs
}

/// The lines of figures under the legend: T and |H| from the first row, and the axis the loop
/// goes round (the largest moment's or the smallest's).
fn figures(moments: [f64; 3], start: [f64; 3], looped: bool) -> Vec<String> {
    let (two_t, h2) = invariants(moments, start);
    let mut lines = vec![
        format!("T = {} J", Short(two_t / 2.0)),
        format!("|H| = {} kg m²/s", Short(h2.sqrt())),
    ];
    if let (true, Some(curve)) = (looped, polhode_curve(moments, start, 4)) {
        // The axis along which ω keeps its sign all round the loop.
        let k = (0..3)
            .find(|&k| {
                curve
                    .iter()
                    .all(|p| p[k] != 0.0 && p[k].signum() == curve[0][k].signum())
            })
            .unwrap_or(2);
        lines.push(format!("the loop goes round {}", NAMES[k]));
    }
    lines
}

/// The polhode plot: the three projections and the legend, two by two, one scale on both axes
/// of each projection.
pub(super) fn draw_polhode(
    svg: &mut String,
    title: &str,
    polhode: &Polhode,
) -> Result<(), DrawError> {
    let figure = Figure::new(title, polhode);
    render(svg, (WIDTH, WIDTH), |root, overlay| {
        let (caption, size) = fitted_caption(&figure.caption, TITLE_FONT, WIDTH);
        let body = root.titled(&caption, (FONT, size))?;
        let cells = body.split_evenly((2, 2));
        for (area, projection) in cells.iter().zip(PROJECTIONS) {
            draw_projection(area, overlay, &figure, projection)?;
        }
        draw_legend(&cells[3], overlay, &figure.figures)
    })
}

/// The legend: the run, the polhode, the outline and the start, each with its mark, then the
/// figures.
fn draw_legend(area: &Area, overlay: &mut Overlay, figures: &[String]) -> Result<(), DrawError> {
    // The overlay draws in the whole SVG's pixels, the texts in the area's.
    let (left, top) = area.get_base_pixel();
    let (x, step) = (30, 28);
    let row = |k: i32| 60 + k * step;
    let sample = |k: i32| {
        let (x, y) = (f64::from(left + x), f64::from(top + row(k)));
        [(x, y), (x + 36.0, y)]
    };
    overlay.line(area, sample(0), COLOURS[0], 3)?;
    overlay.dashed(area, sample(1), (COLOURS[1], 2), 6)?;
    overlay.line(area, sample(3), GREY, 1)?;
    area.draw(&Circle::new(
        (x + 18, row(4)),
        6,
        COLOURS[2].stroke_width(2),
    ))?;
    let style =
        TextStyle::from((FONT, LABEL_FONT).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
    let entries = [
        (0, "the run's ω"),
        (1, "the polhode from row 1: the energy"),
        (2, "ellipsoid ∩ the momentum ellipsoid"),
        (3, "the energy ellipsoid's outline"),
        (4, "the start"),
    ];
    for (k, text) in entries {
        area.draw(&Text::new(text, (x + 48, row(k)), style.clone()))?;
    }
    for (k, text) in (6..).zip(figures) {
        area.draw(&Text::new(text.as_str(), (x, row(k)), style.clone()))?;
    }
    Ok(())
}

/// The chart builder of a projection, the same for the layout pass and the drawing.
fn projection_builder<'a, 'b>(
    area: &'a Area<'b>,
    caption: &str,
) -> ChartBuilder<'a, 'b, SVGBackend<'b>> {
    let (caption, size) = fitted_caption(caption, PANEL_FONT, area.dim_in_pixel().0);
    let mut builder = ChartBuilder::on(area);
    builder
        .caption(caption, (FONT, size))
        .margin(8)
        .x_label_area_size(52)
        .y_label_area_size(76);
    builder
}

/// One projection: the outline, the run, the dashed polhode and the start.
fn draw_projection(
    area: &Area,
    overlay: &mut Overlay,
    figure: &Figure,
    (h, v): (usize, usize),
) -> Result<(), DrawError> {
    let caption = format!("{}–{}", NAMES[h], NAMES[v]);
    let (width, height) = {
        let mut scratch = String::new();
        let scratch_root =
            SVGBackend::with_string(&mut scratch, area.dim_in_pixel()).into_drawing_area();
        let chart =
            projection_builder(&scratch_root, &caption).build_cartesian_2d(0.0..1.0, 0.0..1.0)?;
        let (w, h) = chart.plotting_area().dim_in_pixel();
        (f64::from(w.max(1)), f64::from(h.max(1)))
    };
    let ((cx, cy), half) = figure.window((h, v));
    let per_pixel = (2.0 * half / width).max(2.0 * half / height);
    let x_range = (cx - per_pixel * width / 2.0, cx + per_pixel * width / 2.0);
    let y_range = (cy - per_pixel * height / 2.0, cy + per_pixel * height / 2.0);
    let ticks = 5;
    let x_label = |x: &f64| tick_label(*x, x_range, ticks);
    let y_label = |y: &f64| tick_label(*y, y_range, ticks);
    let mut chart = projection_builder(area, &caption)
        .build_cartesian_2d(x_range.0..x_range.1, y_range.0..y_range.1)?;
    chart
        .configure_mesh()
        .x_labels(ticks)
        .y_labels(ticks)
        .x_label_formatter(&x_label)
        .y_label_formatter(&y_label)
        .light_line_style(TRANSPARENT)
        .label_style((FONT, LABEL_FONT))
        .axis_desc_style((FONT, LABEL_FONT))
        .x_desc(format!("{} [rad/s]", NAMES[h]))
        .y_desc(format!("{} [rad/s]", NAMES[v]))
        .draw()?;
    let frame = PixelFrame::new(chart.plotting_area().get_pixel_range(), x_range, y_range);
    let project = |w: &[f64; 3]| frame.at((w[h], w[v]));
    if let Some(s) = figure.semi_axes {
        let outline: Vec<(f64, f64)> = (0..=720)
            .map(|n| {
                let t = TAU * f64::from(n) / 720.0;
                (s[h] * t.cos(), s[v] * t.sin())
            })
            .collect();
        for part in inside(&outline, (x_range, y_range)) {
            overlay.line(area, part.into_iter().map(|p| frame.at(p)), GREY, 1)?;
        }
    }
    overlay.line(area, figure.run.iter().map(project), COLOURS[0], 3)?;
    if let Some(curve) = &figure.curve {
        overlay.dashed(area, curve.iter().map(project), (COLOURS[1], 2), 6)?;
    }
    if let Some(start) = figure.run.first() {
        let ring = Circle::new((start[h], start[v]), 6, COLOURS[2].stroke_width(2));
        chart.draw_series([ring])?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use eom::output::drawing::{Drawing, RunDrawings};
    use eom::run::Row;
    use eom::run::record::{RecordError, Recorder, RunStart};
    use eom::scene::AnyScene;

    /// Keeps p, q and r of every row, and the body's tensor from its drawing.
    #[derive(Default)]
    struct Rates {
        rates: [Vec<f64>; 3],
        inertia: Option<[[f64; 3]; 3]>,
    }

    impl Recorder for Rates {
        fn begin(&mut self, _: RunStart) -> Result<(), RecordError> {
            Ok(())
        }
        fn row(&mut self, row: &Row) -> bool {
            for (column, value) in self.rates.iter_mut().zip(&row.state[3..6]) {
                column.push(*value);
            }
            true
        }
        fn end(&mut self) -> Result<(), RecordError> {
            Ok(())
        }
        fn drawn(&mut self, drawn: RunDrawings) -> Result<(), RecordError> {
            for drawing in drawn.drawings {
                if let Drawing::Polhode(polhode) = drawing {
                    self.inertia = Some(polhode.spin.inertia_about_g);
                }
            }
            Ok(())
        }
        fn stop_asked(&self) -> bool {
            false
        }
    }

    /// The tennis racket's moments and its ω in principal axes, row by row.
    fn tennis_racket() -> ([f64; 3], [Vec<f64>; 3]) {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../scenes/tennis_racket.toml");
        let scene = AnyScene::load(std::path::Path::new(path)).unwrap();
        let mut rates = Rates::default();
        scene
            .into_kind()
            .run("tennis_racket.toml", &mut rates)
            .unwrap();
        let inertia = rates.inertia.expect("the tennis racket's polhode is drawn");
        let [p, q, r] = &rates.rates;
        let tensor = nalgebra::Matrix3::from_fn(|r, c| inertia[r][c]);
        in_principal_axes(&InertiaTensor::from_matrix(tensor).unwrap(), [p, q, r])
    }

    #[test]
    fn the_tennis_racket_s_omega_stays_on_both_ellipsoids() {
        let (moments, [w1, w2, w3]) = tennis_racket();
        assert_eq!(moments, [2.0, 3.0, 4.5]);
        assert_eq!(w1.len(), 2001);
        let (two_t, h2) = invariants(moments, [w1[0], w2[0], w3[0]]);
        // DOP853 at rtol 1e-10 over 20 s keeps T and |H| to 1e-8 relative.
        let mut largest = (0.0f64, 0.0f64);
        for row in 0..w1.len() {
            let (t, h) = invariants(moments, [w1[row], w2[row], w3[row]]);
            largest.0 = largest.0.max((t / two_t - 1.0).abs());
            largest.1 = largest.1.max((h / h2 - 1.0).abs());
        }
        assert!(largest.0 < 1e-8 && largest.1 < 1e-8, "{largest:?}");
        // It flips: ω₂ takes both signs, ω₃ keeps its own (a loop round the largest axis).
        assert!(w2.iter().any(|w| *w < -5.0) && w2.iter().any(|w| *w > 5.0));
        assert!(w3.iter().all(|w| *w > 0.0));
    }

    #[test]
    fn the_polhode_lies_on_both_ellipsoids_through_the_start() {
        let (moments, [w1, w2, w3]) = tennis_racket();
        let start = [w1[0], w2[0], w3[0]];
        let (two_t, h2) = invariants(moments, start);
        let curve = polhode_curve(moments, start, 720).unwrap();
        assert_eq!(curve.len(), 721);
        // Closed: the last point is the first, to round-off in sin 2π.
        assert!((0..3).all(|k| (curve[0][k] - curve[720][k]).abs() < 1e-12));
        for point in &curve {
            let (t, h) = invariants(moments, *point);
            assert!((t / two_t - 1.0).abs() < 1e-12, "{point:?}");
            assert!((h / h2 - 1.0).abs() < 1e-12, "{point:?}");
        }
        // Every row of the run lies near the loop: within its spacing of a sampled point.
        let distance =
            |a: [f64; 3], b: [f64; 3]| (0..3).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>().sqrt();
        for row in (0..w1.len()).step_by(7) {
            let w = [w1[row], w2[row], w3[row]];
            let nearest = curve
                .iter()
                .map(|c| distance(*c, w))
                .fold(f64::MAX, f64::min);
            assert!(nearest < 0.05, "row {row}: {nearest}");
        }
    }

    #[test]
    fn an_axisymmetric_body_s_polhode_is_a_circle_about_its_axis() {
        // The free plate: I₁ = I₂ < I₃, so ω turns about axis 3 at constant ω₃.
        let moments = [0.001, 0.001, 0.002];
        let curve = polhode_curve(moments, [3.0, 0.0, 40.0], 360).unwrap();
        for point in curve {
            assert!((point[0].hypot(point[1]) - 3.0).abs() < 1e-9, "{point:?}");
            assert!((point[2] - 40.0).abs() < 1e-9, "{point:?}");
        }
        // Spun about the smallest axis, the loop goes round it, with its sign.
        let low = polhode_curve([2.0, 3.0, 4.5], [-6.0, 0.1, 0.1], 90).unwrap();
        assert!(low.iter().all(|p| p[0] < -5.0), "{low:?}");
    }

    #[test]
    fn no_loop_is_drawn_where_there_is_none() {
        assert!(polhode_curve([1.0, 2.0, 3.0], [0.0; 3], 10).is_none());
        assert!(polhode_curve([1.0, 2.0, 3.0], [f64::NAN, 0.0, 1.0], 10).is_none());
        // A sphere: every axis is principal, ω stays put.
        assert!(polhode_curve([2.0; 3], [1.0, 2.0, 3.0], 10).is_none());
    }

    #[test]
    fn a_tensor_with_products_is_turned_onto_its_eigenvectors() {
        // Without products the body axes keep their order, unsorted.
        let tensor = InertiaTensor::new(2.0, 1.0, 3.0, 0.0, 0.0, 0.0).unwrap();
        let (moments, _) = in_principal_axes(&tensor, [&[1.0], &[2.0], &[3.0]]);
        assert_eq!(moments, [2.0, 1.0, 3.0]);
        let tensor = InertiaTensor::new(1.5, 1.5, 3.0, 0.5, 0.0, 0.0).unwrap();
        let (moments, [w1, w2, w3]) = in_principal_axes(&tensor, [&[1.0], &[1.0], &[0.0]]);
        for (m, expected) in moments.iter().zip([1.0, 2.0, 3.0]) {
            assert!((m - expected).abs() < 1e-12, "{moments:?}");
        }
        // (1, 1, 0) lies along the eigenvector of I = 2: ω' = (0, ±√2, 0), and 2T = ωᵀ[I]ω = 4
        // and H² = |[I]ω|² = 8 either way.
        assert!(w1[0].abs() < 1e-12 && w3[0].abs() < 1e-12, "{w1:?} {w3:?}");
        let (two_t, h2) = invariants(moments, [w1[0], w2[0], w3[0]]);
        assert!(
            (two_t - 4.0).abs() < 1e-12 && (h2 - 8.0).abs() < 1e-12,
            "{two_t} {h2}"
        );
    }
}
