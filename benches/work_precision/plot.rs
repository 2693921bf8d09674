//! The log–log plots of error against wall time: one panel per problem with every method on
//! the base model and the peer, and one plot of the tennis racket's model variants (DOP853).

use std::path::Path;

use plotters::prelude::*;

use super::names;
use super::report::BASE;
use super::sweep::Row;

/// Errors below this are drawn at it (an exact end state has error zero, which a log axis
/// cannot show).
const FLOOR: f64 = 1e-17;

/// The points (time, error) of the runs `keep` selects, sorted by time.
fn points<'a>(rows: &'a [Row], keep: impl Fn(&Row) -> bool + 'a) -> Vec<(f64, f64)> {
    let mut p: Vec<(f64, f64)> = rows
        .iter()
        .filter(|r| keep(r) && r.error.is_finite())
        .map(|r| (r.seconds, r.error.max(FLOOR)))
        .collect();
    p.sort_by(|a, b| a.0.total_cmp(&b.0));
    p
}

/// The axis ranges that hold every point, widened to whole decades.
fn ranges(series: &[(String, Vec<(f64, f64)>)]) -> ((f64, f64), (f64, f64)) {
    let all = series.iter().flat_map(|(_, p)| p.iter());
    let (mut x, mut y) = ((f64::MAX, f64::MIN), (f64::MAX, f64::MIN));
    for &(t, e) in all {
        x = (x.0.min(t), x.1.max(t));
        y = (y.0.min(e), y.1.max(e));
    }
    let decade = |(lo, hi): (f64, f64)| {
        (
            10f64.powf(lo.log10().floor()),
            10f64.powf(hi.log10().ceil()),
        )
    };
    (decade(x), decade(y))
}

/// Every method, in a fixed order: its index picks its colour, the same in every panel.
const METHODS: [&str; 8] = [
    "Euler",
    "symplectic Euler",
    "RK4",
    "DOPRI5",
    "DOP853",
    "Lie midpoint",
    "ode_solvers Dopri5",
    "ode_solvers Dop853",
];

/// The colour of a series: by its method's place in [`METHODS`] when it names one, else by
/// its place in the plot.
fn colour(name: &str, index: usize) -> RGBAColor {
    let slot = METHODS.iter().position(|m| *m == name).unwrap_or(index);
    Palette99::pick(slot).to_rgba()
}

/// Draws one panel of series onto `area`.
fn panel(
    area: &DrawingArea<SVGBackend, plotters::coord::Shift>,
    title: &str,
    series: &[(String, Vec<(f64, f64)>)],
) -> Result<(), Box<dyn std::error::Error>> {
    let ((x0, x1), (y0, y1)) = ranges(series);
    let mut chart = ChartBuilder::on(area)
        .caption(title, ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(36)
        .y_label_area_size(60)
        .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())?;
    chart
        .configure_mesh()
        .x_desc("wall time per run [s]")
        .y_desc("error")
        .x_label_formatter(&|v| format!("{v:.0e}"))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()?;
    for (i, (name, p)) in series.iter().enumerate() {
        let color = colour(name, i);
        chart
            .draw_series(LineSeries::new(p.iter().copied(), color.stroke_width(2)).point_size(3))?
            .label(name.as_str())
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 16, y)], color.stroke_width(2))
            });
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerLeft)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 12))
        .draw()?;
    Ok(())
}

/// The methods present for a problem, in the order they were run.
fn methods(rows: &[Row], problem: &str) -> Vec<&'static str> {
    let mut names: Vec<&'static str> = Vec::new();
    for r in rows
        .iter()
        .filter(|r| r.problem == problem && r.model == BASE)
    {
        if !names.contains(&r.method) {
            names.push(r.method);
        }
    }
    names
}

/// The 2×2 plot of the four problems.
pub fn problems(
    rows: &[Row],
    problems: &[&str],
    path: &Path,
) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (1400, 1100)).into_drawing_area();
    root.fill(&WHITE)?;
    for (area, &problem) in root.split_evenly((2, 2)).iter().zip(problems) {
        let series: Vec<(String, Vec<(f64, f64)>)> = methods(rows, problem)
            .into_iter()
            .map(|m| {
                (
                    m.to_string(),
                    points(rows, move |r| {
                        r.problem == problem && r.model == BASE && r.method == m
                    }),
                )
            })
            .collect();
        panel(area, problem, &series)?;
    }
    root.present()?;
    Ok(())
}

/// The models of a panel of the variant plot: (panel title, models).
const PANELS: [(&str, &[&str]); 2] = [
    (
        "tennis racket, DOP853: form of the right-hand side",
        &[
            BASE,
            "f64, full tensor 4.51",
            names::GENERATED,
            names::GENERIC,
            names::GENERATED_FULL_ZERO,
            names::TURNED_GENERATED,
            names::TURNED_GENERIC,
        ],
    ),
    (
        "tennis racket, DOP853: precision and kinematics",
        &[
            BASE,
            "f32",
            names::GENERATED_F32,
            names::GENERIC_F32,
            "f64, Euler angles 4.60",
            names::GENERATED_EULER,
            names::GENERIC_EULER,
        ],
    ),
];

/// The plot of the tennis racket's variants with DOP853, in two panels.
pub fn variants(rows: &[Row], path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (1400, 650)).into_drawing_area();
    root.fill(&WHITE)?;
    for (area, (title, models)) in root.split_evenly((1, 2)).iter().zip(PANELS) {
        let series: Vec<(String, Vec<(f64, f64)>)> = models
            .iter()
            .map(|&model| {
                let p = points(rows, |r| {
                    r.problem == "tennis racket" && r.model == model && r.method == "DOP853"
                });
                (model.to_string(), p)
            })
            .collect();
        panel(area, title, &series)?;
    }
    root.present()?;
    Ok(())
}
