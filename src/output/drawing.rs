//! What a run's plots and 3-D view draw, said by the kind of scene and drawn by the command.
//!
//! A kind says *which* drawings a run of it has, from a small vocabulary of shapes (a
//! manoeuvre in the plane, a manoeuvre in space, curves in a plane); the command (`eom-cli`,
//! which has plotters and the view's page) draws each from the run's rows. A drawing names the
//! columns it reads, so a new kind whose rows carry them is drawn without a line of the
//! command changed, and the command names no kind.

use crate::models::{Family, Kinematics};

/// A point to mark on a track: a turning circle's execute, its 90° and 180° points.
#[derive(Debug, Clone, PartialEq)]
pub struct Mark {
    /// What it is (`advance`, `tactical diameter`).
    pub label: String,
    /// Where: x (north) and y (east) in space axes, m.
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

/// The waterline drawn along a track in the plane and moving in the view.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hull {
    /// L, m.
    pub length: f64,
    /// B, m.
    pub beam: f64,
    /// Whether B is assumed (the scene gives none): the captions and the view say so.
    pub beam_assumed: bool,
}

impl Hull {
    /// L/B of a hull whose scene gives no beam: a cargo ship's.
    pub const ASSUMED_LENGTH_OVER_BEAM: f64 = 7.0;

    /// A hull of `length` whose beam is assumed, L/[`Self::ASSUMED_LENGTH_OVER_BEAM`].
    pub fn of_length(length: f64) -> Self {
        Hull {
            length,
            beam: length / Self::ASSUMED_LENGTH_OVER_BEAM,
            beam_assumed: true,
        }
    }
}

/// A rigid body as the view draws it: its mass and its inertia tensor about G, in body axes,
/// kg m² (the view finds the solid of revolution with the same principal moments).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Solid {
    /// M, kg.
    pub mass: f64,
    /// The inertia tensor about G, kg m².
    pub inertia_about_g: [[f64; 3]; 3],
}

/// A manoeuvre in the horizontal plane. Its rows carry `x`, `y` (north and east of the
/// reference point, m), `psi` (rad), `delta` and `command` (the rudder and its command after
/// saturation, rad). Drawn: the track in plan with the hull along it and the marks, the
/// heading change since the execute, the rudder with its command; and the view of the hull
/// on the water, its readout the columns named in `readout`.
#[derive(Debug, Clone, PartialEq)]
pub struct PlaneManoeuvre {
    /// The captions' title: the scene's and the run's.
    pub title: String,
    /// When the rudder is put over, s: the heading change is counted from there.
    pub execute_s: f64,
    /// Points to mark on the track.
    pub marks: Vec<Mark>,
    /// The hull.
    pub hull: Hull,
    /// The columns the view's readout shows, in order.
    pub readout: Vec<String>,
}

/// A manoeuvre in space. Its rows carry `x`, `y`, `z` (north, east, down, m), `phi`, `theta`,
/// `psi` (rad), `q0`…`q3` (the attitude's quaternion), `dr`, `ds`, `dr_command`,
/// `ds_command` (the fins and their commands, rad). Drawn: the track in plan with the marks,
/// the profile, the attitude, the fins with their commands; and the view of the solid moving
/// through the water, every column in its readout.
#[derive(Debug, Clone, PartialEq)]
pub struct SpaceManoeuvre {
    /// The captions' title: the scene's and the run's.
    pub title: String,
    /// Points to mark on the track.
    pub marks: Vec<Mark>,
    /// The body the view draws.
    pub solid: Solid,
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

/// A flight in space. Its rows carry `north`, `east`, `altitude` (in the scene's length
/// unit, altitude up) and `phi`, `theta`, `psi` (rad), each column labelled with its unit
/// (`north[ft]`). Drawn: the view of the aircraft moving over the ground, its fuselage, wings
/// and tail from the scene's geometry, every column in its readout.
#[derive(Debug, Clone, PartialEq)]
pub struct Flight {
    /// The captions' title: the scene's and the run's.
    pub title: String,
    /// The wing's span, in the scene's length unit.
    pub span: f64,
    /// Its chord.
    pub chord: f64,
    /// The fuselage's length, where the scene gives it.
    pub length: Option<f64>,
    /// The length unit of the rows and of the solid (`ft`, `m`).
    pub length_unit: &'static str,
}

/// One drawing of a run.
#[derive(Debug, Clone, PartialEq)]
pub enum Drawing {
    /// A rigid body of the catalog's families.
    RigidBody(RigidBody),
    /// A manoeuvre in the horizontal plane.
    PlaneManoeuvre(PlaneManoeuvre),
    /// A manoeuvre in space.
    SpaceManoeuvre(SpaceManoeuvre),
    /// Curves in a plane.
    Curves(Curves),
    /// A flight in space.
    Flight(Flight),
}

/// A run's drawings, under its path in the output (`turning_circle_35/port`).
#[derive(Debug, Clone, PartialEq)]
pub struct RunDrawings {
    /// The run's path, as the recorder was told it.
    pub path: String,
    /// What is drawn of it.
    pub drawings: Vec<Drawing>,
}
