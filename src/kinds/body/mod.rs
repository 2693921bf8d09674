//! The catalog body as a kind of scene: a body of one of the catalog's families (the
//! pendulum, a planar body, a spatial body, the heavy top) under its loads, whose model is a
//! variant the build generated and proved ([`crate::scene`] reads and checks it, and selects
//! the variant). It runs once, from its initial state to its end time or its stop condition,
//! through the one runner ([`crate::run`]); its rows go to the caller's recorder, its summary
//! is [`crate::output::summary::Summary`] with a [`summary::BodySection`], and its drawing a [`RigidBody`].
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
//!
//! [`RigidBody`]: crate::output::drawing::RigidBody

mod kind;
mod run;
pub mod summary;

pub use run::BodyRun;
