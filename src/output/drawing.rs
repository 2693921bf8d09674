//! What a run's plots and 3-D view draw, said by the kind of scene and drawn by the command.
//!
//! A kind says *which* drawings a run of it has, from a small vocabulary of shapes that name
//! no kind: a track in a plane ([`Track`]), columns against time on one panel ([`Series`]) or
//! a panel each ([`Panels`]), an attitude's angles ([`Attitude`]), a track in space seen from
//! the side ([`Profile`]), the drift of the total energy ([`EnergyDrift`]), a free body's
//! polhode ([`Polhode`]), a body moving in 3-D ([`View`]) and curves in a plane ([`Curves`]).
//! The command (`eom-cli`, which has plotters and the view's page) draws each from the run's
//! rows. A drawing names the columns it reads, so a new kind whose rows carry them is drawn
//! without a line of the command changed, and the command names no kind.

/// A point to mark on a track: a turning circle's execute, its 90° and 180° points.
#[derive(Debug, Clone, PartialEq)]
pub struct Mark {
    /// What it is (`advance`, `tactical diameter`).
    pub label: String,
    /// Where: up and across in the track's plane (x north and y east in space axes), m.
    pub at: [f64; 2],
}

impl Mark {
    /// The marks a run's figures give as (what, [x, y]).
    pub fn all(marks: &[(String, [f64; 2])]) -> Vec<Mark> {
        (marks.iter())
            .map(|(label, at)| Mark {
                label: label.clone(),
                at: *at,
            })
            .collect()
    }
}

/// How a drawing reads a column of the rows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Reading {
    /// As it is.
    AsIs,
    /// An angle in radians, drawn in degrees.
    Degrees,
    /// An angle in radians, drawn in degrees less its value at the first row at or after
    /// `from_s` (a heading's change since the rudder was put over); as it is where no row
    /// is that late.
    DegreesSince {
        /// When the change is counted from, s.
        from_s: f64,
    },
}

/// One line of a [`Series`]: a column as read, under its label in the legend.
#[derive(Debug, Clone, PartialEq)]
pub struct Line {
    /// The legend's label (`rudder δ`).
    pub label: String,
    /// The column it reads (`delta`).
    pub column: String,
    /// How it reads it.
    pub reading: Reading,
}

impl Line {
    /// A line of `column`, read as `reading`, labelled `label`.
    pub fn new(label: &str, column: &str, reading: Reading) -> Self {
        Line {
            label: label.to_owned(),
            column: column.to_owned(),
            reading,
        }
    }
}

/// Columns against time on one panel with a legend, into a file of their own.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// The file, in the run's folder (`heading.svg`).
    pub file: String,
    /// The captions' title: the scene's and the run's.
    pub title: String,
    /// What the caption says after the title (`heading and rudder`).
    pub what: String,
    /// The value axis's description, with its unit (`[deg]`).
    pub y_desc: String,
    /// The lines, in the legend's order (at most four: the palette's).
    pub lines: Vec<Line>,
}

/// An outline drawn along a track at the start and every `1/times` of the distance run, at
/// the track's point and turned by a heading column: a hull's waterline (a pointed bow over
/// the fore fifth, parallel sides, a rounded stern), of length L and beam B.
#[derive(Debug, Clone, PartialEq)]
pub struct Outline {
    /// L, in the track's unit.
    pub length: f64,
    /// B.
    pub beam: f64,
    /// The column of the heading ψ (rad, from north towards east) it is turned by.
    pub heading: String,
    /// How many times it is drawn besides the start.
    pub times: usize,
    /// Its legend entry (`hull`).
    pub label: String,
}

/// A track in a plane: one column across, one up, at one scale, the start a ring and the end a
/// dot, with marks and an outline along it, into `track.svg`.
#[derive(Debug, Clone, PartialEq)]
pub struct Track {
    /// The captions' title: the scene's and the run's.
    pub title: String,
    /// What the caption says after the title (`track in plan`).
    pub what: String,
    /// The column across (`y`) and its axis's description (`east Y [m]`).
    pub across: (String, String),
    /// The column up (`x`) and its axis's description (`north X [m]`).
    pub up: (String, String),
    /// Points to mark, in the track's plane.
    pub marks: Vec<Mark>,
    /// What is drawn along it, if anything.
    pub outline: Option<Outline>,
}

/// A track in space seen from the side: the height against the distance run, and seen from the
/// east, into `profile.svg`.
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    /// The captions' title.
    pub title: String,
    /// The columns of north, east and down (m).
    pub position: [String; 3],
    /// Whether it is drawn where the motion stays level (z varies by no more than 1 % of the
    /// larger of the north and east spans): a run whose depth or height is its point has its
    /// profile whatever it shows; a body that may stay level has one where it leaves the
    /// plane.
    pub when_level: bool,
}

/// Every column named against time, one small panel each titled with its name, its value
/// axis with its unit (stacked up to four, else two to a row), a column zero throughout named
/// in the caption instead, into `state.svg`.
#[derive(Debug, Clone, PartialEq)]
pub struct Panels {
    /// The captions' title.
    pub title: String,
    /// The columns, in the panels' order.
    pub columns: Vec<String>,
}

/// Roll, pitch and yaw against time, made continuous (a tumbling body's angles do not wrap),
/// into `attitude.svg`.
#[derive(Debug, Clone, PartialEq)]
pub struct Attitude {
    /// The captions' title.
    pub title: String,
    /// How the angles are read from the rows: a quaternion's turned into roll, pitch and yaw
    /// (z–y–x), a heading's or a pitch's with the other two angles zero.
    pub orientation: Orientation,
}

/// The drift of the rows' total energy from its first value, relative to the larger of |E₀|
/// and the largest kinetic energy (a potential's zero is a convention, so E₀ alone may be 0),
/// as the summary's `energy_drift` measures it, on a symmetric logarithmic axis, into
/// `energy.svg`. Said only of a run whose energy is conserved; not drawn where the rows carry
/// no energy, or the scale is 0.
#[derive(Debug, Clone, PartialEq)]
pub struct EnergyDrift {
    /// The captions' title.
    pub title: String,
}

/// A body's angular velocity and its inertia tensor about G, as a polhode and a view's arrows
/// of ω and H = I ω read them.
#[derive(Debug, Clone, PartialEq)]
pub struct Spin {
    /// The columns of p, q, r (rad/s, body axes).
    pub omega: [String; 3],
    /// The inertia tensor about G, body axes, kg m².
    pub inertia_about_g: [[f64; 3]; 3],
}

/// The angular velocity of a body turning free of moments about G, in its principal axes, on
/// the energy and momentum ellipsoids, with the polhode of its first row, into `polhode.svg`.
#[derive(Debug, Clone, PartialEq)]
pub struct Polhode {
    /// The captions' title.
    pub title: String,
    /// Its rates and its tensor (drawn in the tensor's principal axes; not drawn where the
    /// tensor is not a body's).
    pub spin: Spin,
}

/// One coordinate of a [`View`]'s position: a column, a column negated (an altitude as z
/// down), or zero (a motion in the plane).
#[derive(Debug, Clone, PartialEq)]
pub enum Coordinate {
    /// The column as it is.
    Column(String),
    /// The column negated.
    Negated(String),
    /// Zero at every row.
    Zero,
}

/// How an attitude is read from the rows, by a [`View`] and an [`Attitude`].
#[derive(Debug, Clone, PartialEq)]
pub enum Orientation {
    /// Turned about z (down) by a heading column (rad): a motion in the plane.
    Heading(String),
    /// Turned about y by a pitch column (rad): a swing in the x–z plane.
    Pitch(String),
    /// The quaternion's four columns (q0 the scalar), taken to unit length row by row.
    Quaternion([String; 4]),
    /// The quaternion's four columns (q0 the scalar) as the rows give them, near unit length:
    /// a view's page takes each to unit length as it draws it, so the two draw the same, and
    /// the page's data keeps the run's own values.
    QuaternionAsIs([String; 4]),
    /// Roll, pitch and yaw columns (rad), z–y–x.
    EulerAngles([String; 3]),
}

/// What a [`View`] draws moving: its shape, in the rows' length unit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// A hull's waterline of length L and beam B, on the water.
    Waterline {
        /// L.
        length: f64,
        /// B.
        beam: f64,
    },
    /// The solid cylinder with a body's mass and principal moments about G (kg, kg m²),
    /// along the principal axis nearest body x; where no cylinder has them (the moment across
    /// less than half the moment along), the [`Box`](Shape::Box).
    Cylinder(Solid),
    /// The uniform box with a body's mass and principal moments about G, its sides along the
    /// principal axes, so that it turns as the body does.
    Box(Solid),
    /// A fuselage along body x with wings, a tailplane and a fin.
    Aircraft(Airframe),
    /// A cone from a pivot at the reference point to a disc at G, `h` along body z, the disc's
    /// radius R from I₃ = M R²/2 (within 0.2 h and 1.5 h).
    Top {
        /// M, kg.
        mass: f64,
        /// I₃, the moment about body z through G, kg m².
        axial: f64,
        /// Pivot to G.
        h: f64,
    },
    /// A rod from a pivot at the reference point to a bob at G, `h` along body z, the bob the
    /// sphere with the moment about G that I₀ − M h² leaves (within h/20 and h/3 in radius).
    Pendulum {
        /// Pivot to G.
        h: f64,
        /// I₀, the moment about the pivot, kg m².
        i0: f64,
        /// M, kg.
        mass: f64,
    },
    /// A plate in body x–y, its sides 2 : 1 (assumed), with a body's mass and I_zz about G.
    Plate {
        /// M, kg.
        mass: f64,
        /// I_zz about G, kg m².
        izz: f64,
    },
}

/// An aircraft as a view draws it: a fuselage along body x, wings of its span and chord
/// through G, a tailplane and a fin, in the rows' length unit (the view's page reads these
/// fields as they are serialised).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Airframe {
    /// The fuselage's length.
    pub length: f64,
    /// Its diameter.
    pub diameter: f64,
    /// The wing's span.
    pub span: f64,
    /// Its chord.
    pub chord: f64,
    /// The length unit (`ft`, `m`).
    pub unit: &'static str,
}

impl Shape {
    /// L/B of a hull whose scene gives no beam: a cargo ship's.
    pub const ASSUMED_LENGTH_OVER_BEAM: f64 = 7.0;
}

/// A rigid body's mass and inertia tensor about G, in body axes, kg m².
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Solid {
    /// M, kg.
    pub mass: f64,
    /// The inertia tensor about G, kg m².
    pub inertia_about_g: [[f64; 3]; 3],
}

/// The point a [`View`]'s trail follows.
#[derive(Debug, Clone, PartialEq)]
pub enum Trail {
    /// A point fixed in the body, in body axes from the reference point and in the rows'
    /// length unit, and what it is (`midship`, `G`).
    Point([f64; 3], String),
    /// The tip of body axis `axis` (0 x, 1 y, 2 z), three quarters of the shape's size out,
    /// where the reference point moves less than half the shape's size over the run (a free
    /// spin, its G staying put: the tip shows the turning); else the reference point, named
    /// `reference`.
    TipWhereStill {
        /// The axis.
        axis: usize,
        /// What the reference point is (`G`).
        reference: String,
    },
}

/// What a [`View`] draws its body over.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Ground {
    /// The water's surface at z = 0, drawn blue: the body is on or in water.
    Water,
    /// A floor at this z, in space axes and the rows' length unit.
    Floor(f64),
    /// A floor under the deepest point of the reference point's path by 0.8 of the shape's
    /// size (z down): a body in flight over no floor of its own.
    BelowPath,
}

/// A body moving in 3-D about the rows' reference point, with the rows' columns in a readout
/// beside it, into `view.html`.
#[derive(Debug, Clone, PartialEq)]
pub struct View {
    /// The page's title.
    pub title: String,
    /// What is drawn.
    pub shape: Shape,
    /// The reference point's position along the space axes x, y and z (north, east and down;
    /// z up where `z_up`).
    pub position: [Coordinate; 3],
    /// The attitude.
    pub orientation: Orientation,
    /// The columns the readout shows, in order; `None` for every column.
    pub readout: Option<Vec<String>>,
    /// The point the trail follows.
    pub trail: Trail,
    /// What the body is over.
    pub ground: Ground,
    /// Whether the space axes have z up (gravity along −z, as a top's) rather than down.
    pub z_up: bool,
    /// The point the camera looks at, in space axes; `None` where it follows the reference
    /// point.
    pub camera: Option<[f64; 3]>,
    /// The body's rates and tensor, where ω and H = I ω are drawn as arrows from G (read from
    /// the readout, which must show the rates).
    pub spin: Option<Spin>,
    /// What the page says of how the shape was made (and what it assumed).
    pub notes: Vec<String>,
}

impl View {
    /// A view of `shape` moved by `position` and `orientation`: every column in its readout,
    /// its trail following the reference point (named `G`), over the floor z = 0 (z down),
    /// the camera following it, no arrows and no notes; a kind sets what differs.
    pub fn moving(
        title: String,
        shape: Shape,
        position: [Coordinate; 3],
        orientation: Orientation,
    ) -> Self {
        View {
            title,
            shape,
            position,
            orientation,
            readout: None,
            trail: Trail::Point([0.0; 3], "G".into()),
            ground: Ground::Floor(0.0),
            z_up: false,
            camera: None,
            spin: None,
            notes: Vec::new(),
        }
    }
}

/// Named curves in one plane, into a file of their own (a spiral's r against δ).
#[derive(Debug, Clone, PartialEq)]
pub struct Curves {
    /// The file, in the run's folder (`spiral.svg`).
    pub file: String,
    /// The caption.
    pub caption: String,
    /// The x axis's description, with its unit.
    pub x_desc: String,
    /// The y axis's description, with its unit.
    pub y_desc: String,
    /// Each curve: its name and its points.
    pub curves: Vec<(String, Vec<(f64, f64)>)>,
}

/// One drawing of a run.
#[derive(Debug, Clone, PartialEq)]
pub enum Drawing {
    /// A track in a plane.
    Track(Track),
    /// Columns against time on one panel.
    Series(Series),
    /// Columns against time, a panel each.
    Panels(Panels),
    /// An attitude's angles against time.
    Attitude(Attitude),
    /// A track in space seen from the side.
    Profile(Profile),
    /// The drift of the total energy.
    EnergyDrift(EnergyDrift),
    /// A free body's angular velocity on its ellipsoids.
    Polhode(Polhode),
    /// A body moving in 3-D (boxed: the largest shape by far).
    View(Box<View>),
    /// Curves in a plane.
    Curves(Curves),
}

/// A run's drawings, under its path in the output (`turning_circle_35/port`).
#[derive(Debug, Clone, PartialEq)]
pub struct RunDrawings {
    /// The run's path, as the recorder was told it.
    pub path: String,
    /// What is drawn of it.
    pub drawings: Vec<Drawing>,
}
