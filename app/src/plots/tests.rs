//! The plots' tests: each plot written for the shapes a run draws, and what is left out and why.

use super::shapes::{
    TrackPlot, energy_drift, leaves_the_plane, track_not_drawn, write_attitude, write_energy_drift,
    write_panels, write_polhode as write_polhode_plot, write_profile, write_track,
};
use super::*;
use std::f64::consts::TAU;
use std::time::Instant;

/// A fresh, empty folder for one test, removed with everything in it when dropped.
struct Folder(PathBuf);

impl Folder {
    fn new(test: &str) -> Self {
        let path = std::env::temp_dir().join(format!("eom-plots-{test}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&path);
        fs::create_dir_all(&path).unwrap();
        Folder(path)
    }

    /// The names of the files in the folder, sorted.
    fn names(&self) -> Vec<String> {
        let mut names: Vec<String> = fs::read_dir(&self.0)
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .collect();
        names.sort();
        names
    }
}

impl Drop for Folder {
    fn drop(&mut self) {
        let _ = fs::remove_dir_all(&self.0);
    }
}

/// The names of a spatial quaternion state, as trajectory.csv names them without their units.
const SPATIAL: [&str; 13] = [
    "u", "v", "w", "p", "q", "r", "x", "y", "z", "q0", "q1", "q2", "q3",
];

/// Owned columns of a synthetic run, sampled every 1 ms.
struct Run {
    time: Vec<f64>,
    state: Vec<(&'static str, Vec<f64>)>,
    attitude: [Vec<f64>; 3],
    x: Vec<f64>,
    y: Vec<f64>,
    drift: Vec<f64>,
}

impl Run {
    /// A quaternion-like 13-state of `n` samples: a body turning steadily about z while
    /// it rolls like a pendulum, on a circle of radius 50 m; its energy drifts linearly
    /// to 10⁻³ with round-off of ±10⁻¹⁴ on top.
    fn spatial(n: usize) -> Run {
        let time: Vec<f64> = (0..n).map(|i| i as f64 * 1e-3).collect();
        let turn = |t: f64| TAU * t / 20.0;
        let roll = |t: f64| 0.3 * (TAU * t / 2.0).sin();
        let column = |f: &dyn Fn(f64) -> f64| time.iter().map(|&t| f(t)).collect::<Vec<_>>();
        let state = SPATIAL
            .iter()
            .map(|&name| {
                let values = match name {
                    "u" => column(&|_| 5.0 * TAU / 20.0 * 10.0),
                    "v" | "w" | "z" => column(&|_| 0.0),
                    "p" => column(&|t| 0.3 * TAU / 2.0 * (TAU * t / 2.0).cos()),
                    "q" => column(&|t| 1e-3 * (t * 7.0).sin()),
                    "r" => column(&|_| TAU / 20.0),
                    "x" => column(&|t| 50.0 * turn(t).cos()),
                    "y" => column(&|t| 50.0 * turn(t).sin()),
                    "q0" => column(&|t| (roll(t) / 2.0).cos() * (turn(t) / 2.0).cos()),
                    "q1" => column(&|t| (roll(t) / 2.0).sin() * (turn(t) / 2.0).cos()),
                    "q2" => column(&|t| -(roll(t) / 2.0).sin() * (turn(t) / 2.0).sin()),
                    _ => column(&|t| (roll(t) / 2.0).cos() * (turn(t) / 2.0).sin()),
                };
                (name, values)
            })
            .collect();
        let end = time.last().copied().unwrap_or(1.0).max(1e-3);
        Run {
            attitude: [
                column(&|t| roll(t).to_degrees()),
                column(&|t| 2.0 * (t * 0.5).sin()),
                column(&|t| (turn(t).to_degrees() + 180.0).rem_euclid(360.0) - 180.0),
            ],
            x: column(&|t| 50.0 * turn(t).cos()),
            y: column(&|t| 50.0 * turn(t).sin()),
            drift: column(&|t| 1e-3 * t / end + 1e-14 * (t * 1e3).sin()),
            state,
            time,
        }
    }

    /// A pendulum: two states, θ a sine of 20° amplitude and its rate; its energy kept
    /// to round-off (drifts of 10⁻¹⁵ to 10⁻¹⁴ of either sign).
    fn pendulum(n: usize) -> Run {
        let time: Vec<f64> = (0..n).map(|i| i as f64 * 1e-3).collect();
        let w = TAU / 2.0;
        let theta = time.iter().map(|t| 0.35 * (w * t).sin()).collect();
        let rate = time.iter().map(|t| 0.35 * w * (w * t).cos()).collect();
        let drift = time.iter().map(|t| 1e-14 * (3.0 * t).sin()).collect();
        Run {
            state: vec![("theta", theta), ("theta_dot", rate)],
            attitude: [vec![], vec![], vec![]],
            x: vec![],
            y: vec![],
            drift,
            time,
        }
    }

    /// Writes the plots of the run into `dir` as the recorder draws a body's, in its order:
    /// the state, and for a spatial run the attitude and the track (where it is more than a
    /// point), then the energy drift.
    fn write(&self, dir: &Path, title: &str, spatial: bool) -> Result<Vec<PathBuf>, PlotError> {
        let state: Vec<(&str, &[f64])> = (self.state.iter())
            .map(|(n, v)| (*n, v.as_slice()))
            .collect();
        let mut written = vec![write_panels(dir, title, &self.time, &state)?];
        if spatial {
            let [roll, pitch, yaw] = [0, 1, 2].map(|k| self.attitude[k].as_slice());
            written.push(write_attitude(dir, title, &self.time, [roll, pitch, yaw])?);
            if track_not_drawn(&self.x, &self.y).is_none() {
                let caption = format!("{title}: track in space axes");
                written.push(write_track(dir, &self.track(&caption))?);
            }
        }
        written.push(write_energy_drift(dir, title, &self.time, &self.drift)?);
        Ok(written)
    }

    /// The track under `caption`, as the recorder draws a body's.
    fn track<'a>(&'a self, caption: &'a str) -> TrackPlot<'a> {
        TrackPlot {
            caption,
            axes: ("x [m]", "y [m]"),
            across: &self.x,
            up: &self.y,
            marks: &[],
            outline: None,
        }
    }
}

/// A written SVG, parsed.
struct Svg {
    text: String,
}

impl Svg {
    fn read(path: &Path) -> Svg {
        let text = fs::read_to_string(path).unwrap();
        roxmltree::Document::parse(&text)
            .unwrap_or_else(|e| panic!("{} is not XML: {e}", path.display()));
        Svg { text }
    }

    /// The elements named `tag`, mapped by `f`.
    fn elements<T>(&self, tag: &str, f: impl Fn(roxmltree::Node) -> T) -> Vec<T> {
        let doc = roxmltree::Document::parse(&self.text).unwrap();
        doc.descendants()
            .filter(|n| n.tag_name().name() == tag)
            .map(f)
            .collect()
    }

    /// The polylines of the data: plotters draws axes, ticks and grid lines as polylines
    /// of two points, and every line series as one polyline of more.
    fn series(&self) -> Vec<Vec<(f64, f64)>> {
        self.elements("polyline", |n| {
            n.attribute("points")
                .unwrap()
                .split_whitespace()
                .map(|p| {
                    let (x, y) = p.split_once(',').unwrap();
                    (x.parse().unwrap(), y.parse().unwrap())
                })
                .collect::<Vec<_>>()
        })
        .into_iter()
        .filter(|p| p.len() > 2)
        .collect()
    }

    /// Every text, trimmed.
    fn texts(&self) -> Vec<String> {
        self.elements("text", |n| n.text().unwrap_or("").trim().to_string())
    }
}

#[test]
fn a_long_title_is_fitted_to_the_plot_not_cut_off_at_its_edge() {
    let folder = Folder::new("long-title");
    let run = Run::spatial(1_000);
    let title = "A REMUS 100 with 6.5 kg of payload forward of its centre of buoyancy, \
                 trimmed nose-down at 1.5 m/s, on Prestero's table with the fins at 15°";
    let written = run.write(&folder.0, title, true).unwrap();
    assert_eq!(written.len(), 4);
    for file in written {
        let svg = Svg::read(&file);
        let captions = svg.elements("text", |n| {
            let size: f64 = n.attribute("font-size").unwrap_or("0").parse().unwrap();
            (n.text().unwrap_or("").trim().to_string(), size)
        });
        let (caption, size) = captions
            .iter()
            .find(|(text, _)| text.starts_with("A REMUS 100"))
            .unwrap_or_else(|| panic!("{}: no caption in {captions:?}", file.display()));
        // Drawn within the width at 0.6 em a character, the estimate `fitted_caption`
        // makes (sans-serif's average character is narrower).
        let drawn = caption.chars().count() as f64 * 0.6 * size;
        assert!(
            drawn <= f64::from(WIDTH) - 24.0,
            "{}: {caption:?} at {size} px is {drawn:.0} px wide",
            file.display()
        );
        // Shortened in the title, so that what the plot is stays legible.
        assert!(caption.contains('…'), "{caption}");
        let what = file.file_stem().unwrap().to_str().unwrap();
        let what = if what == "track" {
            "track in space axes"
        } else {
            what
        };
        assert!(caption.contains(what), "{}: {caption}", file.display());
    }
}

#[test]
fn a_caption_that_fits_is_kept_whole_at_the_largest_size_it_fits() {
    assert_eq!(
        fitted_caption("tennis racket: state", TITLE_FONT, WIDTH),
        ("tennis racket: state".to_string(), TITLE_FONT)
    );
    let long = "x".repeat(90);
    assert_eq!(
        fitted_caption(&long, TITLE_FONT, WIDTH),
        (long.clone(), PANEL_FONT)
    );
    assert_eq!(fitted_caption(&long, PANEL_FONT, WIDTH).1, PANEL_FONT);
    let longer = format!("{}: attitude", "y".repeat(300));
    let (shortened, size) = fitted_caption(&longer, TITLE_FONT, WIDTH);
    assert_eq!(size, LABEL_FONT);
    assert!(shortened.ends_with("…: attitude"), "{shortened}");
    assert!(shortened.starts_with("yyy"), "{shortened}");
}

#[test]
fn writes_the_four_plots_with_their_series_and_titles() {
    let folder = Folder::new("four");
    let run = Run::spatial(100_000);
    let written = run.write(&folder.0, "tennis racket", true).unwrap();
    let names = ["attitude.svg", "energy.svg", "state.svg", "track.svg"];
    assert_eq!(
        written,
        ["state.svg", "attitude.svg", "track.svg", "energy.svg"].map(|n| folder.0.join(n))
    );
    // Only the plots are left: no temporary file.
    assert_eq!(folder.names(), names);

    // v, w and z are zero throughout: named in the caption, not drawn.
    let state = Svg::read(&folder.0.join("state.svg"));
    assert_eq!(state.series().len(), 10);
    let texts = state.texts();
    assert!(
        texts.contains(&"tennis racket: state (v, w, z zero throughout, not drawn)".to_string()),
        "{texts:?}"
    );
    for name in SPATIAL {
        let panel = texts.contains(&name.to_string());
        assert_eq!(panel, !["v", "w", "z"].contains(&name), "panel {name}");
    }
    // Every value axis carries its unit.
    for label in ["u [m/s]", "p [rad/s]", "x [m]", "q0 [-]"] {
        assert!(texts.contains(&label.to_string()), "no axis {label}");
    }

    let attitude = Svg::read(&folder.0.join("attitude.svg"));
    assert_eq!(attitude.series().len(), 3);
    let texts = attitude.texts();
    for text in [
        "tennis racket: attitude (Euler angles, continuous, no wraps)",
        "roll φ",
        "pitch θ",
        "yaw ψ",
    ] {
        assert!(texts.contains(&text.to_string()), "no {text} in {texts:?}");
    }

    let track = Svg::read(&folder.0.join("track.svg"));
    assert_eq!(track.series().len(), 1);
    // The start and the end, each on the plot and in the legend.
    assert_eq!(track.elements("circle", |_| ()).len(), 4);
    let texts = track.texts();
    for text in [
        "tennis racket: track in space axes",
        "track",
        "start",
        "end",
    ] {
        assert!(texts.contains(&text.to_string()), "no {text} in {texts:?}");
    }

    let energy = Svg::read(&folder.0.join("energy.svg"));
    assert_eq!(energy.series().len(), 1);
    let texts = energy.texts();
    assert!(
        texts
            .iter()
            .any(|t| t.starts_with("tennis racket: relative energy drift")),
        "{texts:?}"
    );
    // The symmetric log axis: zero, a decade of round-off and the drift's decade.
    for tick in ["0", "1e-14", "1e-3"] {
        assert!(
            texts.contains(&tick.to_string()),
            "no tick {tick} in {texts:?}"
        );
    }
}

#[test]
fn a_circle_track_is_drawn_round() {
    let folder = Folder::new("round");
    let run = Run::spatial(20_001);
    run.write(&folder.0, "circle", true).unwrap();
    let track = &Svg::read(&folder.0.join("track.svg")).series()[0];
    let (xs, ys): (Vec<f64>, Vec<f64>) = track.iter().copied().unzip();
    let spread = |v: &[f64]| {
        v.iter().copied().fold(f64::MIN, f64::max) - v.iter().copied().fold(f64::MAX, f64::min)
    };
    let (width, height) = (spread(&xs), spread(&ys));
    assert!(width > 500.0, "the circle fills the plot: {width} px");
    assert!((width - height).abs() <= 1.0, "{width} × {height} px");
    // Drawn at sub-pixel precision: most points fall between whole pixels.
    let fractional = track.iter().filter(|(x, _)| x.fract() != 0.0).count();
    assert!(
        fractional * 2 > track.len(),
        "{fractional} of {}",
        track.len()
    );
}

#[test]
fn a_pendulum_is_stacked_in_one_column() {
    let folder = Folder::new("pendulum");
    let run = Run::pendulum(10_000);
    let written = run.write(&folder.0, "pendulum", false).unwrap();
    assert_eq!(
        written,
        [folder.0.join("state.svg"), folder.0.join("energy.svg")]
    );
    let state = Svg::read(&folder.0.join("state.svg"));
    let series = state.series();
    assert_eq!(series.len(), 2);
    // One above the other, over the same time axis.
    let (top, bottom) = (&series[0], &series[1]);
    assert_eq!(top[0].0, bottom[0].0);
    let lowest_of_top = top.iter().map(|p| p.1).fold(f64::MIN, f64::max);
    let highest_of_bottom = bottom.iter().map(|p| p.1).fold(f64::MAX, f64::min);
    assert!(lowest_of_top < highest_of_bottom);
    // Drifts of 10⁻¹⁴ either side of zero show.
    let texts = Svg::read(&folder.0.join("energy.svg")).texts();
    for tick in ["1e-14", "-1e-14"] {
        assert!(
            texts.contains(&tick.to_string()),
            "no tick {tick} in {texts:?}"
        );
    }
}

#[test]
fn a_million_samples_make_small_files_quickly() {
    let folder = Folder::new("million");
    let run = Run::spatial(1_000_000);
    let start = Instant::now();
    let written = run.write(&folder.0, "a long run", true).unwrap();
    let seconds = start.elapsed().as_secs_f64();
    for (path, lines) in written.iter().zip([10, 3, 1, 1]) {
        let bytes = fs::metadata(path).unwrap().len();
        println!("{}: {bytes} bytes", path.display());
        assert!(bytes < 1_000_000, "{}: {bytes} bytes", path.display());
        // Still every series, each decimated to a few thousand points.
        let series = Svg::read(path).series();
        assert_eq!(series.len(), lines, "{}", path.display());
        assert!(
            series.iter().all(|s| s.len() <= 6_000),
            "{}",
            path.display()
        );
    }
    println!("drawing 4 plots of 1e6 samples: {seconds:.3} s");
    assert_eq!(written.len(), 4);
}

#[test]
fn non_finite_values_are_skipped() {
    let folder = Folder::new("nan");
    let mut run = Run::spatial(5_000);
    run.time[10] = f64::NAN;
    run.state[0].1[100] = f64::NAN;
    run.state[1].1[200] = f64::INFINITY;
    run.state[2].1.fill(f64::NAN);
    run.state[3].1[300] = f64::MAX;
    run.attitude[0][0] = f64::NEG_INFINITY;
    run.x[4_999] = f64::NAN;
    run.drift.fill(f64::NAN);
    let written = run.write(&folder.0, "broken", true).unwrap();
    assert_eq!(written.len(), 4);
    for path in &written {
        let svg = Svg::read(path);
        assert!(!svg.text.contains("NaN") && !svg.text.contains("inf"));
    }
    // A state of nothing but NaN (w) draws an empty panel, and v with an infinity is not
    // zero throughout: 11 lines for 12 panels, z alone left out.
    assert_eq!(Svg::read(&written[0]).series().len(), 11);

    // No samples at all: each plot drawn empty (a track of none is not one point).
    let empty = Folder::new("nan-empty");
    let none: &[f64] = &[];
    assert!(track_not_drawn(none, none).is_none());
    let plot = TrackPlot {
        caption: "empty: track in space axes",
        axes: ("x [m]", "y [m]"),
        across: none,
        up: none,
        marks: &[],
        outline: None,
    };
    let polhode = Polhode {
        moments: [1.0, 2.0, 3.0],
        omega: [none, none, none],
    };
    write_panels(&empty.0, "empty", none, &[("u", none)]).unwrap();
    write_attitude(&empty.0, "empty", none, [none, none, none]).unwrap();
    write_track(&empty.0, &plot).unwrap();
    write_energy_drift(&empty.0, "empty", none, none).unwrap();
    write_polhode_plot(&empty.0, "empty", &polhode).unwrap();
    assert!(!leaves_the_plane(none, none, none));
    assert_eq!(empty.names().len(), 5);
}

#[test]
fn the_same_input_gives_the_same_bytes() {
    let (a, b) = (Folder::new("same-a"), Folder::new("same-b"));
    let run = Run::spatial(30_000);
    let first = run.write(&a.0, "again", true).unwrap();
    let second = run.write(&b.0, "again", true).unwrap();
    for (p, q) in first.iter().zip(&second) {
        assert_eq!(
            fs::read(p).unwrap(),
            fs::read(q).unwrap(),
            "{}",
            p.display()
        );
    }
}

#[test]
fn a_column_of_the_wrong_length_writes_nothing() {
    let folder = Folder::new("length");
    let mut run = Run::spatial(1_000);
    run.y.pop();
    let error = write_track(&folder.0, &run.track("short: track")).unwrap_err();
    assert!(
        matches!(&error, PlotError::Length { column, len: 999, times: 1000, .. } if column == "up")
    );
    assert!(error.to_string().contains("track.svg"), "{error}");
    run.drift.pop();
    let error = write_energy_drift(&folder.0, "short", &run.time, &run.drift).unwrap_err();
    assert!(
        matches!(&error, PlotError::Length { column, len: 999, times: 1000, .. } if column == "energy drift")
    );
    assert!(folder.names().is_empty());
}

#[test]
fn a_tumbling_body_s_attitude_has_no_jumps() {
    // A spin about body y at 1 rad/s: the principal values fold pitch back at ±90° and
    // jump roll and yaw by 180°; the continuous angles run pitch on and hold the others.
    let (mut roll, mut pitch, mut yaw) = (vec![], vec![], vec![]);
    for i in 0..2_000 {
        let rotation = nalgebra::Rotation3::from_euler_angles(0.0, i as f64 * 0.01, 0.0)
            * nalgebra::Rotation3::from_euler_angles(0.0, 0.0, 0.0);
        let (r, p, y) = rotation.euler_angles();
        roll.push(r.to_degrees());
        pitch.push(p.to_degrees());
        yaw.push(y.to_degrees());
    }
    assert!(
        roll.windows(2).any(|w| (w[1] - w[0]).abs() > 170.0),
        "principal values jump"
    );
    let [r, p, y] = series::continuous_euler_deg([&roll, &pitch, &yaw]);
    let largest_step = |v: &[f64]| {
        v.windows(2)
            .map(|w| (w[1] - w[0]).abs())
            .fold(0.0, f64::max)
    };
    for column in [&r, &p, &y] {
        assert!(largest_step(column) < 1.0, "{}", largest_step(column));
    }
    assert!(
        (p[1_999] - 19.99f64.to_degrees()).abs() < 1e-6,
        "{}",
        p[1_999]
    );
}

/// A spinning plate's ω, I₁ = I₂ = 1, I₃ = 2: (3 cos t, 3 sin t, 4) over `n` samples.
fn plate(n: usize) -> [Vec<f64>; 3] {
    let t = (0..n).map(|i| i as f64 * 1e-2);
    [
        t.clone().map(|t| 3.0 * t.cos()).collect(),
        t.clone().map(|t| 3.0 * t.sin()).collect(),
        t.map(|_| 4.0).collect(),
    ]
}

/// Writes the polhode of a plate, with `omega` as its ω.
fn write_polhode(folder: &Folder, omega: &[Vec<f64>; 3]) -> PathBuf {
    let polhode = Polhode {
        moments: [1.0, 1.0, 2.0],
        omega: [&omega[0], &omega[1], &omega[2]],
    };
    write_polhode_plot(&folder.0, "plate", &polhode).unwrap()
}

#[test]
fn the_polhode_draws_the_run_and_the_dashed_curve_in_three_projections() {
    let folder = Folder::new("polhode");
    let written = write_polhode(&folder, &plate(700));
    assert_eq!(written, folder.0.join("polhode.svg"));
    let svg = Svg::read(&folder.0.join("polhode.svg"));
    let dashed = svg.elements("polyline", |n| n.attribute("stroke-dasharray").is_some());
    // Per projection: the run, the polhode (dashed) and the ellipsoid's outline, clipped
    // to the window; one dashed sample in the legend.
    assert_eq!(dashed.iter().filter(|d| **d).count(), 3 + 1);
    assert!(svg.series().len() >= 3 * 3, "{}", svg.series().len());
    let texts = svg.texts();
    for text in ["ω₁–ω₂", "ω₂–ω₃", "ω₃–ω₁", "the run's ω", "T = 20.5 J"] {
        assert!(texts.contains(&text.to_string()), "no {text} in {texts:?}");
    }
    assert!(
        texts.contains(&"the loop goes round ω₃".to_string()),
        "{texts:?}"
    );

    // One row, nothing, a row of NaN first: a plot, and no panic.
    let mut broken = plate(10);
    broken[1][0] = f64::NAN;
    for omega in [plate(1), plate(0), broken] {
        write_polhode(&folder, &omega);
        let text = fs::read_to_string(folder.0.join("polhode.svg")).unwrap();
        assert!(!text.contains("NaN"));
    }
}

#[test]
fn a_track_in_place_is_said_to_be_one_and_a_climb_gets_a_profile() {
    let folder = Folder::new("profile");
    let mut run = Run::spatial(2_000);
    // Turning in place: the track is a point, not drawn as an empty frame, and said so; its
    // profile is not drawn.
    run.x = vec![0.0; 2_000];
    run.y = vec![0.0; 2_000];
    let written = run.write(&folder.0, "in place", true).unwrap();
    assert!(!written.contains(&folder.0.join("track.svg")));
    assert!(!folder.0.join("track.svg").exists());
    assert_eq!(
        track_not_drawn(&run.x, &run.y).as_deref(),
        Some("track.svg not drawn: the body does not translate, it stays at (0, 0) m")
    );
    assert!(!leaves_the_plane(&run.x, &run.y, &run.x));
    assert!(track_not_drawn(&Run::spatial(2_000).x, &Run::spatial(2_000).y).is_none());

    // Climbing 30 m on the 50 m circle (3 % of its 100 m span): a profile, the height
    // against the distance run, which ends at 1/10 of the circumference.
    run.x = (0..2_000)
        .map(|i| 50.0 * (i as f64 * TAU / 20_000.0).cos())
        .collect();
    run.y = (0..2_000)
        .map(|i| 50.0 * (i as f64 * TAU / 20_000.0).sin())
        .collect();
    let climb: Vec<f64> = (0..2_000).map(|i| -0.015 * i as f64).collect();
    assert!(leaves_the_plane(&run.x, &run.y, &climb));
    let level = vec![0.0; 2_000];
    assert!(!leaves_the_plane(&run.x, &run.y, &level));
    write_profile(&folder.0, "climb", (&run.x, &run.y, &climb)).unwrap();
    let profile = Svg::read(&folder.0.join("profile.svg"));
    let line = &profile.series()[0];
    // Up to the right: the height grows as the distance does.
    assert!(line[0].0 < line[line.len() - 1].0 && line[0].1 > line[line.len() - 1].1);
    let texts = profile.texts();
    for text in ["horizontal distance run [m]", "height −z [m]", "30"] {
        assert!(texts.contains(&text.to_string()), "no {text} in {texts:?}");
    }
    // A z column of the wrong length is refused before anything is drawn.
    let error = write_profile(&folder.0, "climb", (&run.x, &run.y, &climb[1..])).unwrap_err();
    assert!(error.to_string().contains("profile.svg"), "{error}");
}

/// The drift is relative to the larger of |E₀| and the largest kinetic energy, so that a
/// potential whose zero makes E₀ nought still gives a drift; no energy, or none to scale it
/// by, gives none.
#[test]
fn the_energy_drift_is_relative_to_the_larger_of_e0_and_the_largest_kinetic_energy() {
    // |E₀| = 2 is the larger: the drift of 1 is a half.
    assert_eq!(
        energy_drift(&[2.0, 3.0, 1.0], &[1.0, 1.5, 0.5]),
        Some(vec![0.0, 0.5, -0.5])
    );
    // E₀ = 0 (a potential's zero at the start), |T| up to 4: the drift of 1 is a quarter.
    assert_eq!(
        energy_drift(&[0.0, 1.0], &[4.0, -4.0]),
        Some(vec![0.0, 0.25])
    );
    // Nothing to scale by, and no energy.
    assert_eq!(energy_drift(&[0.0, 1.0], &[0.0, 0.0]), None);
    assert_eq!(energy_drift(&[f64::NAN], &[0.0]), None);
    assert_eq!(energy_drift(&[], &[]), None);
}

#[test]
fn a_missing_folder_names_the_file() {
    let folder = Folder::new("missing");
    let run = Run::pendulum(100);
    let missing = folder.0.join("no such folder");
    let error = run.write(&missing, "pendulum", false).unwrap_err();
    assert!(matches!(error, PlotError::Write { .. }));
    assert!(error.to_string().contains("state.svg"), "{error}");
}

/// The pole plot names each mode with its eigenvalue, and where slow modes crowd the origin
/// beside a fast one (a phugoid and a spiral at a hundredth of a short period's reach) draws
/// them again in a panel at their own scale; where none do, one panel.
#[test]
fn the_pole_plot_names_its_modes_and_spreads_the_slow_ones() {
    use super::poles::{PlottedMode, write_pole_plot};
    let mode = |name: &str, eigenvalue| PlottedMode {
        name: name.into(),
        eigenvalue,
    };
    let folder = Folder::new("poles");
    let modes = [
        mode("short period", (-2.5, 2.6)),
        mode("phugoid", (-0.0167, 0.0216)),
        mode("spiral", (-0.0084, 0.0)),
        mode("height", (0.0, 0.0)),
    ];
    let file = write_pole_plot(&folder.0, "a flight", &modes, 1e-9).unwrap();
    let svg = fs::read_to_string(file).unwrap();
    for said in [
        "short period: -2.5 ± 2.6i",
        "phugoid: -0.0167 ± 0.0216i",
        "spiral: -0.0084",
    ] {
        assert!(svg.contains(said), "{said}");
    }
    assert!(svg.contains("the slow modes, near the origin"));
    let fast = [mode("short period", (-2.5, 2.6)), mode("roll", (-8.4, 0.0))];
    let file = write_pole_plot(&folder.0, "a flight", &fast, 1e-9).unwrap();
    assert!(!fs::read_to_string(file).unwrap().contains("the slow modes"));
}
