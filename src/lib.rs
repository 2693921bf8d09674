//! # eom — rigid-body equations of motion, derived, proved and emitted
//!
//! The equations of a rigid body (ships, underwater vehicles, aircraft, pendulums) are derived
//! from their vector definitions by the symbolic engine in `eom-codegen`, proved equal to the
//! textbook's own forms when this crate is built, emitted as specialised Rust, and proved
//! again, program against equations, before a file is written. This crate holds what runs,
//! in the order data flows through it:
//!
//! | stage | where |
//! |---|---|
//! | the physical inputs, validated once, and the one set of value checks | [`InertiaTensor`], [`PendulumParameters`], [`ParameterError`], [`validate`], [`mass`] (mass properties of a body) |
//! | the generated models, one type per catalog entry, and any model through one object-safe trait | [`models`]: [`Model`], [`Loads`], [`Constant`], [`AnyModel`], `DynModel` |
//! | the independent nalgebra forms they are checked against | [`generic`] |
//! | many bodies of one model in SIMD lanes, stepped together | [`batch`] |
//! | integrators: one trait, tableaux over one adaptive driver, and the one driver of a run's stretches (any method, events located where they first hold) | [`integrate`]: [`Integrator`], [`OdeSystem`], [`Dop853`], [`Dopri5`], [`Rk4`], `Stepper`, `Problem`, … |
//! | scenes as data: one entry for a scene of any kind, one checker, sweeps, shards and Monte Carlo laws | [`scene`]: `AnyScene` |
//! | what every kind of scene is, and what its run gives | [`kind`]: `Kind`, `Finished`, `KindError` |
//! | the kinds, each in its folder, and the registry that lists them: a catalog body, a ship on its hydrodynamic table (4.46), an underwater vehicle and an aircraft on theirs (the last three with feature `ship`) | [`kinds`]: `REGISTRY`, one folder a kind |
//! | what a ship's and a vehicle's manoeuvres share: the steering gear, the course | [`manoeuvring`] |
//! | the Earth around a body that moves through space: its constants, shapes, geodesy and gravity | [`earth`] |
//! | a scene's runs: the one runner of every kind's runs, rows to a recorder, the trade-off of its integrators, a Monte Carlo | [`run`]: `run::scene`, `run::record`, `run::tradeoff`, `run::uncertainty` |
//! | linearisation of any model: the operating point, A and B from the proved Jacobians, the modes | [`linear`] |
//! | exact solutions and invariants for judging runs | [`reference`](mod@reference), [`energy`], [`elliptic`] |
//! | the swing test: radius of gyration from a pendulum's period | [`swing`] |
//! | where the symbolic engine enters for the scene-defined models, and the one interpreter of their proved programs (feature `ship`) | `defined` (private) |
//! | what a run writes: its output folder, the trajectory (CSV), the summary (JSON), the drawings said in shapes | [`output`] |
//!
//! The `eom` command is a crate of its own (`eom-cli`): its plots, its 3-D view and its
//! terminal output bring crates (clap, plotters, indicatif) that a program using this library
//! does not build.
//!
//! A generated model under its loads is an ODE system, so integrating one takes no adapter:
//!
//! ```
//! use eom::{AdaptiveOptions, Constant, Dop853, InertiaTensor, Integrator, Model};
//! use eom::models::SpatialPrincipalQuaternion;
//! use nalgebra::SVector;
//!
//! // The tennis-racket flip: a free body spinning about its middle axis.
//! let inertia = InertiaTensor::new(2.0, 3.0, 4.5, 0.0, 0.0, 0.0)?;
//! let racket = SpatialPrincipalQuaternion::<f64>::new(1.0, &inertia)?;
//! let mut start = [0.0; 13];
//! start[3..6].copy_from_slice(&[0.001, 6.0, 0.002]); // p, q, r
//! start[9] = 1.0; // q0: the identity attitude
//! let mut dop853 = Dop853::new(AdaptiveOptions::dop853(1e-10, 1e-10));
//! let end = dop853.integrate(&racket.driven_by(Constant::zero()), 0.0, start.into(), 5.0)?;
//! // By t = 5 s the racket has flipped: q has reversed, as Dzhanibekov's nut does.
//! assert!(end[4] < -5.0);
//! // and its kinetic energy (4.32, emitted from the proved form) is kept to the tolerance.
//! let energy = |y: &SVector<f64, 13>| racket.kinetic_energy(&y.data.0[0]);
//! assert!((energy(&end) / energy(&start.into()) - 1.0).abs() < 1e-8);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
#![deny(missing_docs)]

pub mod batch;
#[cfg(feature = "ship")]
mod defined;
pub mod earth;
pub mod elliptic;
pub mod energy;
pub mod generic;
mod inertia;
pub mod integrate;
pub mod kind;
pub mod kinds;
pub mod linear;
pub mod manoeuvring;
pub mod mass;
pub mod models;
pub mod output;
mod pendulum;
pub mod reference;
pub mod run;
pub mod scene;
mod short;
pub mod swing;
pub mod validate;

/// The nalgebra that eom's models, states and integrators are written in, so that a user's
/// vectors are of the same version without choosing it by hand.
pub use nalgebra;

pub use inertia::{InertiaError, InertiaTensor};
pub use integrate::{AdaptiveOptions, Dop853, Dopri5, Integrator, OdeSystem, Rk4, Statistics};
pub use models::{AnyModel, Constant, Loads, Model};
pub use pendulum::PendulumParameters;
pub use short::{Short, counted, fixed};
pub use validate::ParameterError;
