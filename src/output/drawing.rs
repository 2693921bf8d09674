//! What a run's plots and 3-D view draw, said by the kind of scene and drawn by the command.
//!
//! A kind says *which* drawings a run of it has, from a small vocabulary of shapes that name
//! no kind: a track in a plane ([`Track`]), columns against time ([`Series`]), an attitude's
//! angles ([`Attitude`]), a track in space seen from the side ([`Profile`]), a body moving in
//! 3-D ([`View`]), curves in a plane ([`Curves`]), and a rigid body of the catalog's families
//! ([`RigidBody`], whose plots read the catalog's state layout). The command (`eom-cli`, which
//! has plotters and the view's page) draws each from the run's rows. A drawing names the
//! columns it reads, so a new kind whose rows carry them is drawn without a line of the
//! command changed, and the command names no kind.

use crate::models::{Family, Kinematics};

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
}

/// Roll, pitch and yaw against time, made continuous (a tumbling body's angles do not wrap),
/// into `attitude.svg`.
#[derive(Debug, Clone, PartialEq)]
pub struct Attitude {
    /// The captions' title.
    pub title: String,
    /// The columns of φ, θ, ψ (rad).
    pub angles: [String; 3],
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

/// How a [`View`]'s attitude is read from the rows.
#[derive(Debug, Clone, PartialEq)]
pub enum Orientation {
    /// Turned about z (down) by a heading column (rad): a motion in the plane.
    Heading(String),
    /// The quaternion's four columns (q0 the scalar), taken to unit length row by row.
    Quaternion([String; 4]),
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
    /// along the principal axis nearest body x.
    Cylinder(Solid),
    /// A fuselage along body x with wings, a tailplane and a fin.
    Aircraft(Airframe),
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

/// A body moving in 3-D, Z down, about the rows' reference point, with the rows' columns in
/// a readout beside it, into `view.html`.
#[derive(Debug, Clone, PartialEq)]
pub struct View {
    /// The page's title.
    pub title: String,
    /// What is drawn.
    pub shape: Shape,
    /// North, east and down of the reference point.
    pub position: [Coordinate; 3],
    /// The attitude.
    pub orientation: Orientation,
    /// The columns the readout shows, in order; `None` for every column.
    pub readout: Option<Vec<String>>,
    /// The point the trail follows (`midship`).
    pub trail: String,
    /// Whether the body is on or in water (the surface drawn at z = 0) rather than over a
    /// floor.
    pub water: bool,
    /// What the page says of how the shape was made (and what it assumed).
    pub notes: Vec<String>,
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

/// The shape of a rigid body of the catalog's families, as its plots and its view need it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BodyShape {
    /// A spatial body: M and the inertia tensor about G, body axes, kg m².
    Spatial {
        /// M, kg.
        mass: f64,
        /// The tensor about G.
        inertia: [[f64; 3]; 3],
        /// Whether water acts on it (buoyancy, damping): the view draws it as a cylinder on
        /// the water rather than a box over a floor.
        in_water: bool,
        /// Whether it turns free of moments about G (no loads, or uniform gravity at G alone):
        /// its polhode is drawn.
        free_of_moments: bool,
    },
    /// The heavy top: M, its tensor about G in principal axes, G at h along body z.
    Top {
        /// M, kg.
        mass: f64,
        /// The tensor about G.
        inertia: [[f64; 3]; 3],
        /// Pivot to G, m.
        h: f64,
    },
    /// The compound pendulum: pivot to G, the moment of inertia about the pivot, M.
    Pendulum {
        /// Pivot to G, m.
        h: f64,
        /// I about the pivot, kg m².
        i0: f64,
        /// M, kg.
        mass: f64,
    },
    /// A planar body: M and I_zz about G.
    Planar {
        /// M, kg.
        mass: f64,
        /// I_zz about G, kg m².
        izz: f64,
    },
}

/// A rigid body of the catalog's families. Its rows carry the model's state in its own layout
/// (the family's and the attitude's: `family` and `kinematics` say which) and, where its loads
/// have a potential, the potential and total energy. Drawn: the state against time, the
/// attitude, the track (and a spatial body's profile), the energy drift, a free body's
/// polhode; and the view of its shape moving, every column in its readout.
#[derive(Debug, Clone, PartialEq)]
pub struct RigidBody {
    /// The captions' title.
    pub title: String,
    /// The model's family.
    pub family: Family,
    /// How its attitude is written, where it has one.
    pub kinematics: Option<Kinematics>,
    /// Its shape.
    pub shape: BodyShape,
    /// The state it started from (the view trails the tip of the axis it spins most about).
    pub initial: Vec<f64>,
    /// Whether its energy is conserved, so that the drift of the total energy is drawn.
    pub conserves_energy: bool,
}

/// One drawing of a run.
#[derive(Debug, Clone, PartialEq)]
pub enum Drawing {
    /// A rigid body of the catalog's families.
    RigidBody(RigidBody),
    /// A track in a plane.
    Track(Track),
    /// Columns against time.
    Series(Series),
    /// An attitude's angles against time.
    Attitude(Attitude),
    /// A track in space seen from the side.
    Profile(Profile),
    /// A body moving in 3-D.
    View(View),
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
