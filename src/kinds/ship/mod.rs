//! Ship manoeuvring: a hydrodynamic table on 4.46, a rudder, the standard manoeuvres and the
//! IMO criteria they are judged by.
//!
//! The chapter writes the planar equations at midship (4.46) "with the fluid forces measured
//! in model tests about midship". A ship scene gives those forces as a table of derivatives
//! (the Mariner's planar-motion-mechanism table, say); the flow is
//!
//! | step | where |
//! |---|---|
//! | the table as written: names, units, the rigid-body convention, folded tables converted | [`table`] |
//! | 4.46 with exactly the table's terms, derived, solved and proved by `eom-codegen`, evaluated | [`model`] |
//! | the rudder: saturation, first-order lag, rate limit; its commands (the steering gear every craft shares) | [`crate::manoeuvring::steering`] |
//! | the propeller: the thrust law, the rudder's inflow speed, the engine's rate command | [`propulsion`] |
//! | the manoeuvres as schedules and events over the one driver (any method), their figures | [`manoeuvre`] |
//! | the two sides of a turn or zig-zag, and which is the worse | [`side`] |
//! | the spiral tests (direct and reverse), the r–δ curve and its loop | [`spiral`] |
//! | the steady turns at fixed rudder by continuation, and the folds that end the loop | [`steady`] |
//! | what a run reports, as data (`summary.json`'s types) | [`summary`] |
//! | the current, the wind and the windage as a run reports them, and what the figures are over | [`environment`] |
//! | what the figures assume (ahead, not stopped, one way, settled), checked on the run (shared with the vehicle's turning circle) | [`crate::manoeuvring::course`] |
//! | the IMO MSC.137(76) criteria | [`imo`] |
//! | the linear model about the straight course: Nomoto, course stability, pivot point | [`linear`] |
//! | the MMG standard method: its forces (hull, propeller, rudder) at a state, every quantity kept; the propeller's and rudder's loads the proved program reads, with their derivatives; the rate that balances the approach | [`mmg`] |
//! | the wind: a ship's coefficients over the relative wind's angle (a table, or Isherwood's regression), its loads and their derivatives; gusts from a spectrum with a seed | [`wind`] |
//! | the scene file | [`scene`] |
//!
//! The model is built when the scene is read, because the table is known only then: the
//! symbolic engine derives 4.46 with the table's terms, solves it with the constant mass
//! matrix inverted once, and proves the straight-line program equal to the equations, as it
//! does for every catalog model at build time; [`model::ShipModel`] then evaluates that proved
//! program, and is a [`Model`](crate::Model) like the catalog's (state, input, `rhs`, proved
//! Jacobians, kinetic energy), so it runs on every integrator. The engine is reached through
//! one seam, `crate::defined`. A user who wants the same model compiled calls the generator's
//! `emit::system_source` (crate `eom-codegen`) from a `build.rs`.

mod check;
pub mod environment;
pub mod file;
pub mod imo;
pub mod keys;
pub mod kind;
pub mod linear;
pub mod manoeuvre;
pub mod mmg;
pub mod model;
pub mod propulsion;
pub mod run;

pub mod scene;
pub mod side;
pub mod spiral;
pub mod steady;
pub mod summary;
pub mod table;
pub mod wind;

/// The added-mass derivatives' symbols and the motion variables' letters, in the generator's
/// order (the table reads its names by them).
pub(crate) use crate::defined::engine::{ADDED_MASS, VARIABLES};
/// The table's vocabulary, from the generator that builds the model: a term, its load, the
/// units, and about which point the yaw inertia is given.
pub use crate::defined::engine::{Force, ShipForm, Term, Units, YawInertia};
pub use crate::manoeuvring::{Rudder, Series};
pub use kind::KIND;
pub use linear::{LinearModel, Nomoto};
pub use manoeuvre::{Manoeuvre, ManoeuvreKind, ManoeuvreRun};
pub use model::ShipModel;
pub use propulsion::Propulsion;
pub use scene::ShipScene;
pub use side::Side;
pub use table::{RigidBodyTerms, ShipTable};

/// Why a ship cannot be built or run.
#[derive(Debug, thiserror::Error)]
pub enum ShipError {
    /// A table value or key that cannot be used; `key` is its path in the scene.
    #[error("`{key}`: {reason}")]
    Invalid {
        /// The key's path, `hydrodynamics.coefficients.Yvv`.
        key: String,
        /// What is wrong.
        reason: String,
    },
    /// The symbolic engine could not build or prove the model.
    #[error("the ship model cannot be built: {0}")]
    Build(#[from] crate::defined::engine::EmitError),
    /// A run that cannot go on, with the time and the reason.
    #[error("the run stopped at t = {} s: {reason}", crate::Short(*time))]
    Run {
        /// When.
        time: f64,
        /// Why.
        reason: String,
    },
    /// An error of one manoeuvre's run.
    #[error("manoeuvre {manoeuvre}")]
    In {
        /// The manoeuvre's name.
        manoeuvre: String,
        /// What went wrong.
        source: Box<ShipError>,
    },
    /// The rows of a run could not be kept by the caller's recorder (a trajectory file that
    /// could not be written).
    #[error("keeping what {run} gave")]
    Record {
        /// The run's path under the output (`turning_circle_35/port`).
        run: String,
        /// Why.
        source: crate::run::record::RecordError,
    },
}

impl ShipError {
    /// The error said as of the manoeuvre it happened in (`manoeuvre turning_circle_35: …`).
    pub fn in_manoeuvre(self, manoeuvre: &str) -> Self {
        ShipError::In {
            manoeuvre: manoeuvre.to_owned(),
            source: Box::new(self),
        }
    }

    /// The error itself, whichever manoeuvre it is said of.
    pub fn cause(&self) -> &ShipError {
        match self {
            ShipError::In { source, .. } => source.cause(),
            error => error,
        }
    }

    pub(crate) fn invalid(key: impl Into<String>, reason: impl Into<String>) -> Self {
        ShipError::Invalid {
            key: key.into(),
            reason: reason.into(),
        }
    }
}
