//! Underwater vehicles in six degrees of freedom about their table's origin, on their own
//! hydrodynamic tables.
//!
//! | step | where |
//! |---|---|
//! | the table as the scene gives it: body, hydrostatics, added mass, named terms, propeller | [`table`] |
//! | the six equations about O with exactly the table's terms, derived and proved by `eom-codegen`, evaluated | [`model`] |
//! | the propeller's law in its rate, and its ε computed beside the proved program | [`propeller`] |
//! | the cross-flow drag in strips, a force beside the proved program, read as its applied loads | [`cross_flow`] |
//! | the fins (rudder, stern planes): saturation, lag, rate limit; their step commands | [`fins`] |
//! | the autopilots: heading (PID on ψ), depth (depth to pitch to the planes), sampled | [`autopilot`] |
//! | the steady motion every manoeuvre starts from: the cruise, or the trim of the whole state | [`trim`] |
//! | linearised about a cruise: A, B, the modes (the Euler-angle twin of the table) | [`linear`] |
//! | a manoeuvre over the one driver (any method), its figures | [`manoeuvre`] |
//! | what a run reports, as data (`summary.json`'s types) | [`summary`] |
//! | the scene file | [`scene`] |
//!
//! The model is built when the scene is read, because the table is known only then: the
//! symbolic engine derives the six equations about O (4.1 and 4.2 with r = r_G + r′, the
//! added mass and, where the table does not fold them, Kirchhoff's terms), inverts the total
//! mass matrix once (refusing one that is not positive definite), and proves the straight-line
//! program and its Jacobians equal to the equations; [`model::VehicleModel`] then evaluates
//! that proved program as a [`Model`](crate::Model), so it runs on every integrator.

pub mod autopilot;
mod check;
pub mod cross_flow;
pub mod file;
pub mod fins;
pub mod keys;
pub mod kind;
pub mod linear;
pub mod manoeuvre;
pub mod model;
pub mod propeller;
pub mod run;
pub mod scene;
pub mod summary;
pub mod table;
pub mod trial;
pub mod trim;

/// The table's vocabulary, from the generator that builds the model: how names are read,
/// whether Kirchhoff's terms are folded, a folded coefficient against its added mass, the
/// point the inertia tensor is about.
pub use crate::defined::engine::{
    AddedMassCoriolis, Convention, FoldedComparison, InertiaAbout, format_folded,
};
pub use cross_flow::CrossFlow;
pub use fins::{FinSteps, Fins};
pub use kind::KIND;
pub use manoeuvre::{VehicleManoeuvre, VehicleRun};
pub use model::VehicleModel;
pub use propeller::PropellerLaw;
pub use scene::VehicleScene;
pub use table::{PrimeScales, PropellerSetting, VehicleTable};
pub use trim::{Trim, TrimError};

/// Why a vehicle cannot be built or run.
#[derive(Debug, thiserror::Error)]
pub enum VehicleError {
    /// A table value or key that cannot be used; `key` is its path in the scene.
    #[error("`{key}`: {reason}")]
    Invalid {
        /// The key's path, `hydrodynamics.coefficients.Yvv`.
        key: String,
        /// What is wrong.
        reason: String,
    },
    /// The table cannot make a model: a name not read, a mass matrix not positive definite.
    #[error("the vehicle's table: {0}")]
    Table(#[from] crate::defined::engine::vehicle_table::VehicleError),
    /// The symbolic engine could not prove the model.
    #[error("the vehicle model cannot be proved: {0}")]
    Prove(#[from] crate::defined::engine::EmitError),
    /// The linearisation could not be made (a trim that does not converge, a point beyond
    /// the model's reach).
    #[error("{0}")]
    Linear(#[from] crate::linear::LinearError),
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
        source: Box<VehicleError>,
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

impl VehicleError {
    /// The error said as of the manoeuvre it happened in (`manoeuvre turning_circle: …`).
    pub fn in_manoeuvre(self, manoeuvre: &str) -> Self {
        VehicleError::In {
            manoeuvre: manoeuvre.to_owned(),
            source: Box::new(self),
        }
    }

    /// The error itself, whichever manoeuvre it is said of.
    pub fn cause(&self) -> &VehicleError {
        match self {
            VehicleError::In { source, .. } => source.cause(),
            error => error,
        }
    }

    pub(crate) fn invalid(key: impl Into<String>, reason: impl Into<String>) -> Self {
        VehicleError::Invalid {
            key: key.into(),
            reason: reason.into(),
        }
    }

    /// The scene key a table's error is about: the coefficient or added-mass entry it names,
    /// else the table.
    pub fn key(&self) -> String {
        use crate::defined::engine::NameError;
        use crate::defined::engine::vehicle_table::VehicleError as Table;
        let entry = |name: &str| {
            let table = if name.ends_with("dot") {
                "added_mass"
            } else {
                "coefficients"
            };
            format!("hydrodynamics.{table}.{name}")
        };
        match self {
            VehicleError::Invalid { key, .. } => key.clone(),
            VehicleError::Table(table) => match table {
                Table::Name(
                    NameError::Ambiguous { name, .. } | NameError::Unknown { name, .. },
                )
                | Table::ListedTwice(name)
                | Table::SameTerm(_, name, _)
                | Table::Prime { name, .. } => entry(name),
                Table::AsymmetricAddedMass { name, .. } => entry(name),
                Table::NotPositiveDefinite { .. } => "hydrodynamics.added_mass".into(),
                _ => "hydrodynamics".into(),
            },
            _ => "hydrodynamics".into(),
        }
    }
}
