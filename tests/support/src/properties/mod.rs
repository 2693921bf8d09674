//! What the property tests share: the runner that checks a gap against its tolerance, the
//! typed spatial models behind one trait, random cases (`cases`) and the size of the terms of
//! each output that tolerances are relative to (`scale`).
//!
//! Why "the size of the terms": two floating-point evaluations of one formula differ by a few
//! rounding errors of the terms they add, not of the sum. An output that cancels (a rate near
//! zero made of large opposite terms) can legitimately differ by far more than a few ulps of
//! itself. So every output gets a scale: the same formula evaluated with the absolute value of
//! every factor, which bounds the rounding error of any evaluation order to first order
//! (|fl(Σ aᵢ) − Σ aᵢ| ≤ n·u·Σ|aᵢ|, u = ε/2, and likewise through products).

use eom::InertiaTensor;
use eom::generic::{EulerState, ModelError, QuaternionState, RigidBody};
use eom::models::Model;
use nalgebra::SimdRealField;
use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use std::cell::Cell;

mod cases;
mod scale;

pub use cases::*;
pub use scale::*;

/// Random cases per property: enough to meet the extremes each strategy mixes in (one case
/// in eight is a thin rod, one in four has every rate at 10³ rad/s) while every property runs
/// in a few tens of milliseconds in debug.
pub const CASES: u32 = 128;

/// Runs `gap` on [`CASES`] random cases and panics with the property's name and the (shrunk)
/// case if one exceeds `tolerance`. Prints the largest gap seen (`--nocapture` shows it).
pub fn check<S: Strategy>(name: &str, strategy: S, gap: impl Fn(&S::Value) -> f64, tolerance: f64) {
    // The test crate's name is the same for every property: `module::property` is enough.
    let name = name.split_once("::").map_or(name, |(_, rest)| rest);
    let worst = Cell::new(0.0f64);
    let config = Config {
        cases: CASES,
        // The runner is built by hand, so there is no source file to record failures in; a
        // failure prints its case instead.
        failure_persistence: None,
        ..Config::default()
    };
    let outcome = TestRunner::new(config).run(&strategy, |case| {
        let g = gap(&case);
        worst.set(worst.get().max(g));
        prop_assert!(g <= tolerance, "gap {g:e} exceeds {tolerance:e}");
        Ok(())
    });
    if let Err(error) = outcome {
        panic!("{name}: {error}");
    }
    println!(
        "{name:<78} largest gap {:9.2e}, tolerance {tolerance:9.2e}",
        worst.get()
    );
}

/// One test per property, each `name: strategy, gap function, tolerance;`, run by [`check`].
#[macro_export]
macro_rules! properties {
    ($($name:ident: $strategy:expr, $gap:expr, $tolerance:expr;)*) => {
        $(
            #[test]
            fn $name() {
                $crate::properties::check(concat!(module_path!(), "::", stringify!($name)), $strategy, $gap, $tolerance);
            }
        )*
    };
}

/// The typed spatial models behind one interface, with slices for states of either length.
pub trait Spatial<T>: Sized {
    /// The variant's name, for messages.
    const NAME: &'static str;
    /// The attitude it carries.
    const KINEMATICS: Kinematics;
    /// `Self::new`.
    fn build(mass: f64, tensor: &InertiaTensor) -> Result<Self, ModelError>;
    /// `Self::rhs` on a slice of the state's length.
    fn eval(&self, state: &[T], force: &[T; 3], moment: &[T; 3]) -> Vec<T>;
    /// `Self::kinetic_energy` on a slice of the state's length.
    fn kinetic(&self, state: &[T]) -> T;
}

/// [`Spatial`] for every spatial model of the catalog.
macro_rules! spatial {
    ($($module:ident => $type:ident {
        family: $family:ident $(($($option:ident),+))?,
        state: $n:literal, inputs: $m:literal, title: $title:literal,
        parameters: [$($parameter:ident),*], potential_energy: $potential:tt
    },)*) => {
        $(spatial!(@item $module $type $family $(($($option),+))?);)*
    };
    (@item $module:ident $type:ident Spatial($symmetry:ident, $kinematics:ident)) => {
        impl<T: SimdRealField + Copy> Spatial<T> for eom::models::$type<T> {
            const NAME: &'static str = stringify!($module);
            const KINEMATICS: Kinematics = Kinematics::$kinematics;
            fn build(mass: f64, tensor: &InertiaTensor) -> Result<Self, ModelError> {
                Self::new(mass, tensor)
            }
            fn eval(&self, state: &[T], force: &[T; 3], moment: &[T; 3]) -> Vec<T> {
                let state = state.try_into().expect("state of the variant's length");
                let input = [force[0], force[1], force[2], moment[0], moment[1], moment[2]];
                self.rhs(state, &input).to_vec()
            }
            fn kinetic(&self, state: &[T]) -> T {
                self.kinetic_energy(state.try_into().expect("state of the variant's length"))
            }
        }
        // Every spatial variant has a symmetry class.
        const _: eom::models::Symmetry = eom::models::Symmetry::$symmetry;
    };
    (@item $($other:tt)*) => {};
}

eom::for_each_model!(spatial);

/// The generated model of type `S` evaluated in f64 at the case.
pub fn generated<S: Spatial<f64>>(case: &SpatialCase) -> Vec<f64> {
    let model = S::build(case.mass, &case.tensor).expect("a valid body of the model's class");
    let state = case.state(S::KINEMATICS);
    model.eval(&state, &case.force.into(), &case.moment.into())
}

/// The generic nalgebra form evaluated at the case.
pub fn generic(case: &SpatialCase, kinematics: Kinematics) -> Vec<f64> {
    let body = RigidBody::<f64>::new(case.mass, &case.tensor).expect("a valid body");
    let state = case.state(kinematics);
    match kinematics {
        Kinematics::Euler => {
            let state = EulerState::from_column_slice(&state);
            body.rhs_euler(&state, &case.force, &case.moment)
                .as_slice()
                .to_vec()
        }
        Kinematics::Quaternion => {
            let state = QuaternionState::from_column_slice(&state);
            body.rhs_quaternion(&state, &case.force, &case.moment)
                .as_slice()
                .to_vec()
        }
    }
}
