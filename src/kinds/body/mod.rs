//! The catalog body as a kind of scene: a body of one of the catalog's families (the
//! pendulum, a planar body, a spatial body, the heavy top) under its loads, whose model is a
//! variant the build generated and proved.
//!
//! Its folder holds the whole path: its tables ([`file`](mod@file)) read by the one reader and checked
//! here ([`BodyScene::from_file`]: the family's keys, the body, the variant it selects
//! ([`select_spatial`]), the loads as the model's inputs ([`SceneLoads`], with their time
//! tables, [`table`]), the initial state, the integrator); its run ([`run`]: from its initial
//! state to its end time or its stop condition, a problem solved by the one loop, every step
//! watched by the [`guard`]); its linear plant ([`linear`]); its integrators compared on its
//! end state ([`tradeoff`]); its keys for the scene reference ([`EVERY_KEY`]). Its rows go to the
//! caller's recorder, its summary is [`crate::output::summary::Summary`] with a
//! [`summary::BodySection`], and its drawings said in the shapes that name no kind
//! ([`drawing`](mod@drawing): its state, attitude, track, energy drift, polhode, profile and
//! view, in the columns of its family's layout).
//!
//! A body's run that fails (gimbal lock, a step too long, a value that is not finite) keeps
//! what it ran: its rows, its drawings and a summary that gives the error; the failure is
//! then [`Finished::failure`](super::Finished::failure), not an error of the run itself.
//!
//! Any scene runs as a kind; here the pendulum, its rows dropped, to its summary:
//!
//! ```
//! use eom::run::record::Discard;
//! use eom::scene::AnyScene;
//!
//! let pendulum = AnyScene::load("scenes/pendulum.toml".as_ref())?.into_kind();
//! assert_eq!(pendulum.kind(), "body");
//! let finished = pendulum.run("pendulum.toml", &mut Discard)?;
//! assert!(finished.failure().is_none());
//! let summary = finished.summary();
//! assert_eq!(summary.section["variant"], "pendulum");
//! // The period measured from its rows, as summary.json gives it, and as every kind's runs
//! // give their figures.
//! assert!(summary.section["period_s"].as_f64().unwrap() > 0.0);
//! assert_eq!(summary.figure("", "period_s"), summary.section["period_s"].as_f64());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod check;
mod drawing;
pub mod file;
pub mod guard;
mod keys;
mod kind;
pub mod linear;
mod loads;
mod run;
mod scene;
mod select;
mod solve;
pub mod summary;
pub mod table;
pub mod tradeoff;

pub use keys::EVERY_KEY;
pub use kind::{KIND, NAME};
pub use linear::Plant;
pub use loads::{PendulumLoads, PlanarLoads, PreparedLoads, SceneLoads, SpatialLoads, TopLoads};
pub use run::{BodyOutcome, BodyRun};
pub use scene::{Body, BodyScene, IntegratorSpec, LOOSE_TOLERANCE, read};
pub use select::{Selection, select_spatial};
pub use solve::{Ended, Report, RunError, run, run_reporting};
