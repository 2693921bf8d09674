//! `view.html`: a run seen in 3-D, in one file that opens from the file system with no
//! network: the page, its script and the trajectory are all inside it.
//!
//! Why a page of its own and not a plot: the flip of a tennis racket, the nutation of a top
//! or a ship's turn are understood by watching the body move, which no time series shows. The
//! page draws the body as what it is ([`Shape`]), its body axes, for spinning bodies the
//! angular velocity ω and the momentum H about G, a trail of a point, and a grid (or the
//! water); it plays, pauses, changes speed, moves to any time on a slider, and turns its
//! camera with the mouse; it shows the time and the state at the frame shown.
//!
//! Why it is drawn by a small canvas renderer of its own (in `view.html`) and not a 3-D
//! library: the bodies are a few dozen flat faces and lines, painted far to near, which a
//! 2-D canvas does in a few hundred lines with nothing to vendor or keep up to date.
//!
//! Why float32 in base64: the trajectory is embedded as little-endian `f32` columns (t, the
//! position, the attitude quaternion, then each state component), 5⅓ bytes per number, so
//! that a run of 10⁴ rows and 13 states is about 1.1 MB. A longer run is thinned to at most
//! [`MAX_FRAMES`] evenly spaced rows (the page says so). `f32` keeps seven digits, more
//! than a picture needs; `trajectory.csv` holds every digit.
//!
//! The page exposes what it drew at the frame shown (`window.eomProbe()`, and in
//! `<pre id="probe">` when the address ends in `#…&probe`): the box's corners in space axes,
//! each visible face's screen outline and colour, and the camera, so that a test in a real
//! browser can check the drawing against the trajectory.

use eom::output::drawing::Airframe;
use serde::Serialize;
use std::borrow::Cow;
use std::path::{Path, PathBuf};
use thiserror::Error;

/// The file a run writes its view into.
pub const VIEW_FILE: &str = "view.html";

/// The most rows embedded: a longer run is thinned evenly to this many.
pub const MAX_FRAMES: usize = 20_000;

/// The page, with `/*EOM-DATA*/` where the run's JSON goes.
const TEMPLATE: &str = include_str!("view.html");

/// How the space axes stand.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum SpaceAxes {
    /// z down (north, east, down), as the spatial, planar and ship scenes have them.
    #[serde(rename = "z-down")]
    ZDown,
    /// Z up, as the heavy top has them (gravity along −Z).
    #[serde(rename = "z-up")]
    ZUp,
}

/// What the body is drawn as, in body axes.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum Shape {
    /// A uniform box, centred at G, its sides along `axes`' columns.
    Box {
        /// The sides along each axis, m.
        sides: [f64; 3],
        /// The axes as columns, in body axes (rows are body x, y, z).
        axes: [[f64; 3]; 3],
    },
    /// A solid cylinder centred at G along `axes`' first column.
    Cylinder {
        /// Its length, m.
        length: f64,
        /// Its diameter, m.
        diameter: f64,
        /// The axes as columns, in body axes.
        axes: [[f64; 3]; 3],
    },
    /// A top: a cone from the pivot (the body origin) to a disc at G, `h` along body z.
    Top {
        /// Pivot to G, m.
        h: f64,
        /// The disc's radius, m.
        radius: f64,
    },
    /// A hull's waterline from its length and beam, midship at the body origin (the page
    /// knows it as `hull`).
    #[serde(rename = "hull")]
    Waterline {
        /// L, m.
        length: f64,
        /// B, m.
        beam: f64,
    },
    /// An aircraft: a fuselage along body x, wings through G, a tailplane and a fin.
    Aircraft(Airframe),
    /// A pendulum: a rod from the pivot (the body origin) to a bob at G, `length` along body z.
    Pendulum {
        /// Pivot to G, m.
        length: f64,
        /// The bob's radius, m.
        bob: f64,
    },
}

/// Where the camera looks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CameraTarget {
    /// At the body's origin as it moves.
    Follow,
    /// At a fixed point, space axes.
    Fixed([f64; 3]),
}

/// The angular velocity and the momentum about G, drawn as arrows from G.
#[derive(Debug, Clone, PartialEq)]
pub struct Vectors {
    /// The readout columns holding p, q, r (body axes).
    pub omega: [usize; 3],
    /// The inertia tensor about G, body axes: H = I ω.
    pub inertia: [[f64; 3]; 3],
}

/// Everything the page needs: the body, the frames, what the panel shows.
#[derive(Debug, Clone)]
pub struct ViewInput<'a> {
    /// The scene's title.
    pub title: &'a str,
    /// The body's shape.
    pub shape: Shape,
    /// How the space axes stand.
    pub axes: SpaceAxes,
    /// The sample times, s.
    pub time: &'a [f64],
    /// The body origin's position in space axes, m, one column per axis.
    pub position: [Vec<f64>; 3],
    /// The attitude as a unit quaternion (q0 scalar), body to space axes, one column each.
    pub attitude: [Vec<f64>; 4],
    /// The state shown in the panel: each name with its unit, and its values. An angle labelled
    /// `[rad]` is shown in degrees, a heading wrapped as a compass reads (see `shown`).
    pub readout: Vec<(String, &'a [f64])>,
    /// ω and H, for a body that spins freely or on a pivot.
    pub vectors: Option<Vectors>,
    /// The point whose path the trail shows, in body axes, and what it is.
    pub trail: ([f64; 3], String),
    /// Where the camera looks.
    pub camera: CameraTarget,
    /// The height of the grid (or the water) along the space z-axis, m.
    pub floor: f64,
    /// Whether the grid is the water's surface, drawn blue.
    pub water: bool,
    /// How the shape was made from the scene (shown in the panel).
    pub notes: Vec<String>,
}

/// Why the view could not be written.
#[derive(Debug, Error)]
pub enum ViewError {
    /// A column's length differs from the number of sample times.
    #[error("{}: column {column} has {len} values, but there are {times} sample times", .file.display())]
    Length {
        /// The view's file.
        file: PathBuf,
        /// The column.
        column: String,
        /// Its length.
        len: usize,
        /// The number of sample times.
        times: usize,
    },
    /// The run has no rows to show.
    #[error("{}: no rows to show", .file.display())]
    Empty {
        /// The view's file.
        file: PathBuf,
    },
    /// The page could not be written.
    #[error("{}: could not write the view: {source}", .file.display())]
    Write {
        /// The view's file.
        file: PathBuf,
        /// The failed file operation.
        #[source]
        source: std::io::Error,
    },
}

/// The JSON the page reads.
#[derive(Serialize)]
struct Data<'a> {
    title: &'a str,
    shape: &'a Shape,
    axes: SpaceAxes,
    rows: usize,
    readout: Vec<&'a str>,
    data: String,
    vectors: Option<VectorsJson>,
    trail: [f64; 3],
    trail_name: &'a str,
    camera: &'static str,
    camera_target: [f64; 3],
    elevation_deg: f64,
    floor: f64,
    water: bool,
    notes: Vec<String>,
    /// The unit of every length the page shows (the grid's step).
    length_unit: &'static str,
}

#[derive(Serialize)]
struct VectorsJson {
    omega: [usize; 3],
    inertia: [[f64; 3]; 3],
}

/// Writes `dir/view.html` atomically and returns its path.
pub fn write_view(dir: &Path, input: &ViewInput) -> Result<PathBuf, ViewError> {
    let file = dir.join(VIEW_FILE);
    let html = render_view(input).map_err(|e| e.at(&file))?;
    crate::plots::write_atomically(dir, VIEW_FILE, html.as_bytes()).map_err(|source| {
        ViewError::Write {
            file: file.clone(),
            source,
        }
    })?;
    Ok(file)
}

/// A problem found before the file is named.
enum Problem {
    Length(String, usize, usize),
    Empty,
}

impl Problem {
    fn at(self, file: &Path) -> ViewError {
        let file = file.to_owned();
        match self {
            Problem::Length(column, len, times) => ViewError::Length {
                file,
                column,
                len,
                times,
            },
            Problem::Empty => ViewError::Empty { file },
        }
    }
}

/// The page for `input`, as text.
fn render_view(input: &ViewInput) -> Result<String, Problem> {
    let columns = all_columns(input);
    let times = input.time.len();
    if let Some((name, column)) = columns.iter().find(|(_, c)| c.len() != times) {
        return Err(Problem::Length(name.clone(), column.len(), times));
    }
    if times == 0 {
        return Err(Problem::Empty);
    }
    let rows = frame_rows(times);
    let mut notes = input.notes.clone();
    if rows.len() < times {
        notes.push(format!(
            "{times} rows thinned to {} evenly spaced for the view; trajectory.csv has them all",
            rows.len()
        ));
    }
    let (camera, camera_target) = match input.camera {
        CameraTarget::Follow => ("follow", [0.0; 3]),
        CameraTarget::Fixed(p) => ("fixed", p),
    };
    let data = Data {
        title: input.title,
        shape: &input.shape,
        axes: input.axes,
        rows: rows.len(),
        readout: columns[POSED..].iter().map(|(n, _)| n.as_str()).collect(),
        data: base64(&pack(&columns, &rows)),
        vectors: input.vectors.as_ref().map(|v| VectorsJson {
            omega: v.omega,
            inertia: v.inertia,
        }),
        length_unit: match input.shape {
            Shape::Aircraft(airframe) => airframe.unit,
            _ => "m",
        },
        trail: input.trail.0,
        trail_name: &input.trail.1,
        camera,
        camera_target,
        // A top is best seen from near its pivot's level, the rest from a little above.
        elevation_deg: match input.shape {
            Shape::Top { .. } => 8.0,
            _ => 22.0,
        },
        // The page draws in axes with z up.
        floor: match input.axes {
            SpaceAxes::ZDown => -input.floor,
            SpaceAxes::ZUp => input.floor,
        },
        water: input.water,
        notes,
    };
    // serde_json writes finite numbers; a non-finite constant (none is expected) is null.
    let json = serde_json::to_string(&data).unwrap_or_else(|_| "{}".into());
    // Inside <script>, "</" could close the element: JSON allows "<\/" for it.
    let json = json.replace("</", "<\\/");
    Ok(TEMPLATE.replace("/*EOM-DATA*/", &json))
}

/// The columns every frame is posed from, before the readout: t, the position (x, y, z) and
/// the attitude (q0…q3).
const POSED: usize = 1 + 3 + 4;

/// Every column in the order the page reads them: t, position, quaternion, then the readout
/// as the panel shows it ([`shown`]).
fn all_columns<'a>(input: &'a ViewInput) -> Vec<(String, Cow<'a, [f64]>)> {
    let mut columns = Vec::with_capacity(POSED + input.readout.len());
    columns.push(("t".to_string(), Cow::Borrowed(input.time)));
    for (name, column) in ["x", "y", "z"].iter().zip(&input.position) {
        columns.push((format!("position {name}"), Cow::Borrowed(column.as_slice())));
    }
    for (name, column) in ["q0", "q1", "q2", "q3"].iter().zip(&input.attitude) {
        columns.push((format!("attitude {name}"), Cow::Borrowed(column.as_slice())));
    }
    for (name, column) in &input.readout {
        columns.push(shown(name, column));
    }
    columns
}

/// A readout column as a person reads it: an angle (a name labelled `[rad]`) in degrees, and
/// a heading or yaw (ψ, `psi`) wrapped into [−180°, 180°) as a compass reads; any other column
/// as it is. The rates stay in rad/s: the page draws ω from them.
fn shown<'a>(label: &str, values: &'a [f64]) -> (String, Cow<'a, [f64]>) {
    let Some(name) = label.strip_suffix("[rad]") else {
        return (label.to_string(), Cow::Borrowed(values));
    };
    let heading = matches!(name.trim(), "psi" | "ψ" | "yaw");
    let degrees = values.iter().map(|&angle| {
        let deg = angle.to_degrees();
        if heading {
            (deg + 180.0).rem_euclid(360.0) - 180.0
        } else {
            deg
        }
    });
    (format!("{name}[deg]"), Cow::Owned(degrees.collect()))
}

/// The rows embedded out of `len`: all of them up to [`MAX_FRAMES`], else that many evenly
/// spaced, the first and the last always among them.
pub fn frame_rows(len: usize) -> Vec<usize> {
    if len <= MAX_FRAMES {
        return (0..len).collect();
    }
    let last = len - 1;
    (0..MAX_FRAMES)
        .map(|k| (k * last + (MAX_FRAMES - 1) / 2) / (MAX_FRAMES - 1))
        .collect()
}

/// The chosen rows of every column as little-endian f32, column after column.
fn pack(columns: &[(String, Cow<[f64]>)], rows: &[usize]) -> Vec<u8> {
    let mut bytes = Vec::with_capacity(columns.len() * rows.len() * 4);
    for (_, column) in columns {
        for &row in rows {
            bytes.extend_from_slice(&(column[row] as f32).to_le_bytes());
        }
    }
    bytes
}

/// Standard base64 with padding (RFC 4648), as the page's `atob` reads it.
fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            chunk.get(1).copied().unwrap_or(0),
            chunk.get(2).copied().unwrap_or(0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(ALPHABET[(n >> (18 - 6 * k)) as usize & 63] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// The sides of the uniform box with mass `mass` and principal moments `moments`
/// (4.20–4.21 turned round): I₁ = M(b² + c²)/12 and its cycles give
/// a² = 6(I₂ + I₃ − I₁)/M. A side that comes out zero or negative (a flat body, I₁ + I₂ =
/// I₃, or moments no box has) is drawn 2 % of the longest, so the box stays a solid.
pub fn box_sides(mass: f64, moments: [f64; 3]) -> [f64; 3] {
    let [i1, i2, i3] = moments;
    let squared = [i2 + i3 - i1, i1 + i3 - i2, i1 + i2 - i3].map(|s| 6.0 * s / mass);
    let longest = squared.iter().fold(0.0f64, |m, s| m.max(*s)).sqrt();
    squared.map(|s| {
        let side = s.max(0.0).sqrt();
        side.max(0.02 * longest)
    })
}

/// The length and diameter of the uniform solid cylinder with mass `mass`, moment `axial`
/// about its axis and `transverse` about a diameter through G: I_axial = M R²/2 and
/// I_transverse = M(3R² + L²)/12, so R² = 2 I_axial/M and L² = 12 I_transverse/M − 3R².
/// `None` where no cylinder has these moments (L² ≤ 0).
pub fn cylinder_size(mass: f64, axial: f64, transverse: f64) -> Option<(f64, f64)> {
    let r2 = 2.0 * axial / mass;
    let l2 = 12.0 * transverse / mass - 3.0 * r2;
    (r2 > 0.0 && l2 > 0.0).then(|| (l2.sqrt(), 2.0 * r2.sqrt()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_matches_the_rfc_vectors() {
        for (text, code) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(text.as_bytes()), code, "{text}");
        }
    }

    #[test]
    fn a_box_has_the_moments_it_was_made_from() {
        let (mass, moments) = (1.5, [2.0, 3.0, 4.5]);
        let [a, b, c] = box_sides(mass, moments);
        let back = [
            mass * (b * b + c * c) / 12.0,
            mass * (a * a + c * c) / 12.0,
            mass * (a * a + b * b) / 12.0,
        ];
        for (m, n) in moments.iter().zip(back) {
            assert!((m - n).abs() < 1e-12, "{moments:?} vs {back:?}");
        }
        // A flat plate keeps a thickness.
        let plate = box_sides(0.2, [0.001, 0.001, 0.002]);
        assert!(plate[2] > 0.0 && plate[2] < 0.05 * plate[0], "{plate:?}");
        let (length, diameter) = cylinder_size(50.0, 2.0, 12.0).unwrap();
        let r = diameter / 2.0;
        assert!((50.0 * r * r / 2.0 - 2.0).abs() < 1e-12);
        assert!((50.0 * (3.0 * r * r + length * length) / 12.0 - 12.0).abs() < 1e-12);
        assert!(cylinder_size(1.0, 10.0, 1.0).is_none());
    }

    #[test]
    fn the_panel_reads_angles_in_degrees_and_a_heading_as_a_compass() {
        // A ship's heading after one and a quarter turns to starboard, and a vehicle's.
        let turned = [0.0, 1.25 * std::f64::consts::TAU, -4.0];
        for label in ["psi[rad]", "psi [rad]"] {
            let (name, values) = shown(label, &turned);
            assert_eq!(name, label.replace("rad", "deg"));
            let expected = [0.0, 90.0, 360.0 - 4f64.to_degrees()];
            for (v, e) in values.iter().zip(expected) {
                assert!((v - e).abs() < 1e-9, "{values:?}");
            }
        }
        // Pitch and the rudder in degrees, not wrapped; a rate and a length as they are.
        let (name, values) = shown("delta[rad]", &[-0.6108652381980153, 7.0]);
        assert_eq!(name, "delta[deg]");
        assert!((values[0] + 35.0).abs() < 1e-12 && (values[1] - 7f64.to_degrees()).abs() < 1e-9);
        for label in ["r[rad/s]", "x [m]", "q0 [-]"] {
            let (name, values) = shown(label, &turned);
            assert_eq!((name.as_str(), &values[..]), (label, &turned[..]));
        }
    }

    #[test]
    fn long_runs_are_thinned_to_their_ends() {
        assert_eq!(frame_rows(3), [0, 1, 2]);
        let rows = frame_rows(1_000_001);
        assert_eq!(rows.len(), MAX_FRAMES);
        assert_eq!((rows[0], rows[rows.len() - 1]), (0, 1_000_000));
        assert!(rows.windows(2).all(|w| w[1] > w[0]));
    }

    fn input<'a>(time: &'a [f64], title: &'a str) -> ViewInput<'a> {
        let n = time.len();
        ViewInput {
            title,
            shape: Shape::Box {
                sides: [1.0, 2.0, 3.0],
                axes: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            },
            axes: SpaceAxes::ZDown,
            time,
            position: [vec![0.0; n], vec![0.0; n], vec![0.0; n]],
            attitude: [vec![1.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]],
            readout: vec![("p [rad/s]".into(), time)],
            vectors: None,
            trail: ([1.0, 0.0, 0.0], "body x tip".into()),
            camera: CameraTarget::Follow,
            floor: 2.0,
            water: false,
            notes: vec![],
        }
    }

    #[test]
    fn the_page_embeds_its_data_and_no_address() {
        let time: Vec<f64> = (0..10_000).map(|i| i as f64 * 1e-3).collect();
        let html = render_view(&input(&time, "a </script> title"))
            .ok()
            .unwrap();
        assert!(!html.contains("/*EOM-DATA*/"));
        // The title cannot close the data element early.
        assert_eq!(html.matches("</script>").count(), 2);
        // Nothing is fetched: no address a browser would load.
        for fetch in ["http:", "https:", "src=", "import "] {
            assert!(!html.contains(fetch), "{fetch}");
        }
        // 10⁴ rows of 9 columns: 4 bytes each, and a third more for base64.
        let data = 10_000.0 * 9.0 * 4.0 * 4.0 / 3.0;
        assert!((html.len() as f64) < data + 40_000.0, "{}", html.len());
    }

    #[test]
    fn a_short_column_names_itself() {
        let time = [0.0, 1.0];
        let mut bad = input(&time, "short");
        bad.position[1].pop();
        let dir = std::env::temp_dir();
        let error = write_view(&dir, &bad).unwrap_err();
        assert!(
            matches!(&error, ViewError::Length { column, len: 1, times: 2, .. } if column == "position y"),
            "{error}"
        );
    }
}
