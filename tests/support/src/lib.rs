//! What eom's tests, benches and examples share, so that each is written once:
//!
//! | what | where |
//! |---|---|
//! | the `eom` binary, the example scenes, a fresh folder per test | [`cli`] (and [`child`]: a run in the background; [`eval`]: `eom eval` on standard input) |
//! | the property tests' runner, random cases and the size of the terms | [`properties`] |
//! | bodies several tests, benches and examples are built on | [`bodies`] |
//! | every catalog model over f64 and dual numbers, for the Jacobian bench and its table | [`jacobian`] |
//! | the bodies, runs and measures of the tests at the extremes | [`extremes`], [`double_double`] |
//! | a fixed stream of random draws | [`random`] |
//! | a model's Jacobians by central differences | [`differences`] |
//! | the keys a serde schema accepts | [`schema`] |
//! | the Mariner in a wind, built from the shipped scene | [`ships`] |
//! | NASA's NESC check cases of `data/nesc/` | [`nesc`] |

pub mod bodies;
pub mod child;
pub mod cli;
pub mod differences;
pub mod double_double;
pub mod eval;
pub mod extremes;
pub mod jacobian;
pub mod nesc;
pub mod properties;
pub mod random;
pub mod schema;
pub mod ships;
