//! A model whose sizes are known at run time: one object-safe trait over every
//! [`Model<f64, N, M>`](Model), for callers that hold a scene's model without knowing its type
//! (a binding to another language, a tool that takes any scene).
//!
//! [`DynModel`] evaluates the same `rhs` and proved Jacobians as the typed model, into slices
//! the caller owns: no allocation per call, and nothing but a size check between the caller
//! and the generated code. [`Erased`] gives any typed model the trait; [`AnyModel`] has it by
//! visiting the model it holds.

use super::{AnyModel, Model, Visitor};
use thiserror::Error;

/// A slice of the wrong length handed to a [`DynModel`].
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("{what} has {got} entries; the model {model} takes {expected}")]
pub struct SizeError {
    /// What was handed over (`state`, `input`, `rates`, `state Jacobian`).
    pub what: &'static str,
    /// Its length.
    pub got: usize,
    /// The length the model takes.
    pub expected: usize,
    /// The model's name.
    pub model: &'static str,
}

/// A model of sizes known at run time: its names, its rates and its proved Jacobians.
pub trait DynModel: Send + Sync + std::fmt::Debug {
    /// The model's name (`ship`, `spatial_principal_quaternion`).
    fn name(&self) -> &'static str;
    /// Every state entry's name, in the model's layout (n of them).
    fn state_names(&self) -> Vec<&'static str>;
    /// Every input's name (m of them).
    fn input_names(&self) -> Vec<&'static str>;
    /// The rates f(x, u) into `rates` (n entries).
    fn rhs(&self, state: &[f64], input: &[f64], rates: &mut [f64]) -> Result<(), SizeError>;
    /// ∂f/∂x into `out`, n × n, row-major (row i the derivative of the rate of state i).
    fn state_jacobian(
        &self,
        state: &[f64],
        input: &[f64],
        out: &mut [f64],
    ) -> Result<(), SizeError>;
    /// ∂f/∂u into `out`, n × m, row-major.
    fn input_jacobian(
        &self,
        state: &[f64],
        input: &[f64],
        out: &mut [f64],
    ) -> Result<(), SizeError>;
    /// The kinetic energy of `state` (4.32).
    fn kinetic_energy(&self, state: &[f64]) -> Result<f64, SizeError>;
}

/// A typed model as a [`DynModel`].
#[derive(Debug, Clone)]
pub struct Erased<Mo, const N: usize, const M: usize>(pub Mo);

/// `slice` as an array of `K`, or the error naming it.
fn sized<'a, const K: usize>(
    slice: &'a [f64],
    what: &'static str,
    model: &'static str,
) -> Result<&'a [f64; K], SizeError> {
    slice.try_into().map_err(|_| SizeError {
        what,
        got: slice.len(),
        expected: K,
        model,
    })
}

/// `out` checked to hold `expected` entries.
fn room(
    out: &[f64],
    expected: usize,
    what: &'static str,
    model: &'static str,
) -> Result<(), SizeError> {
    match out.len() == expected {
        true => Ok(()),
        false => Err(SizeError {
            what,
            got: out.len(),
            expected,
            model,
        }),
    }
}

/// `state`, `input` as the model's arrays, `out` checked to hold `width` entries per state
/// entry (1 for the rates, N for ∂f/∂x, M for ∂f/∂u).
fn arguments<'a, Mo: Model<f64, N, M>, const N: usize, const M: usize>(
    (state, input, out): (&'a [f64], &'a [f64], &[f64]),
    width: usize,
    what: &'static str,
) -> Result<(&'a [f64; N], &'a [f64; M]), SizeError> {
    let x = sized::<N>(state, "state", Mo::NAME)?;
    let u = sized::<M>(input, "input", Mo::NAME)?;
    room(out, N * width, what, Mo::NAME)?;
    Ok((x, u))
}

/// `rows` written one after another into `out` (row-major).
fn write_rows<const W: usize>(out: &mut [f64], rows: impl IntoIterator<Item = [f64; W]>) {
    if W > 0 {
        for (row, values) in out.chunks_exact_mut(W).zip(rows) {
            row.copy_from_slice(&values);
        }
    }
}

/// One call of a [`DynModel`] method, with its arguments.
enum Call<'a> {
    Rhs(&'a [f64], &'a [f64], &'a mut [f64]),
    StateJacobian(&'a [f64], &'a [f64], &'a mut [f64]),
    InputJacobian(&'a [f64], &'a [f64], &'a mut [f64]),
    KineticEnergy(&'a [f64]),
    Names,
}

/// What a [`Call`] gives: the kinetic energy (0 for the calls that write into a slice), or
/// the names.
enum Given {
    Done(Result<f64, SizeError>),
    Names(&'static str, Vec<&'static str>, Vec<&'static str>),
}

impl Call<'_> {
    /// The call on a typed model: every length checked, then the typed call.
    fn on<Mo: Model<f64, N, M>, const N: usize, const M: usize>(self, model: &Mo) -> Given {
        let done = |result: Result<(), SizeError>| Given::Done(result.map(|()| 0.0));
        match self {
            Call::Rhs(state, input, out) => done(
                arguments::<Mo, N, M>((state, input, out), 1, "rates")
                    .map(|(x, u)| out.copy_from_slice(&model.rhs(x, u))),
            ),
            Call::StateJacobian(state, input, out) => done(
                arguments::<Mo, N, M>((state, input, out), N, "state Jacobian")
                    .map(|(x, u)| write_rows(out, model.state_jacobian(x, u))),
            ),
            Call::InputJacobian(state, input, out) => done(
                arguments::<Mo, N, M>((state, input, out), M, "input Jacobian")
                    .map(|(x, u)| write_rows(out, model.input_jacobian(x, u))),
            ),
            Call::KineticEnergy(state) => {
                Given::Done(sized::<N>(state, "state", Mo::NAME).map(|x| model.kinetic_energy(x)))
            }
            Call::Names => Given::Names(Mo::NAME, Mo::STATE.to_vec(), Mo::INPUTS.to_vec()),
        }
    }
}

impl Visitor for Call<'_> {
    type Output = Given;

    fn visit<Mo: Model<f64, N, M>, const N: usize, const M: usize>(self, model: &Mo) -> Given {
        self.on(model)
    }
}

/// What answers a [`Call`]: a typed model directly, an [`AnyModel`] by visiting the model it
/// holds. Every such type is a [`DynModel`].
trait Answers {
    fn answer(&self, call: Call) -> Given;
}

impl<Mo: Model<f64, N, M>, const N: usize, const M: usize> Answers for Erased<Mo, N, M> {
    fn answer(&self, call: Call) -> Given {
        call.on(&self.0)
    }
}

/// A catalog model, whichever it is, visited at each call (a match, then the typed call).
impl Answers for AnyModel {
    fn answer(&self, call: Call) -> Given {
        self.visit(call)
    }
}

/// The kinetic energy, or 0 for a call that wrote into its slice.
fn done(given: Given) -> Result<f64, SizeError> {
    match given {
        Given::Done(result) => result,
        Given::Names(..) => Ok(0.0),
    }
}

fn names(given: Given) -> (&'static str, Vec<&'static str>, Vec<&'static str>) {
    match given {
        Given::Names(name, state, inputs) => (name, state, inputs),
        Given::Done(_) => ("", Vec::new(), Vec::new()),
    }
}

impl<T: Answers + Send + Sync + std::fmt::Debug> DynModel for T {
    fn name(&self) -> &'static str {
        names(self.answer(Call::Names)).0
    }

    fn state_names(&self) -> Vec<&'static str> {
        names(self.answer(Call::Names)).1
    }

    fn input_names(&self) -> Vec<&'static str> {
        names(self.answer(Call::Names)).2
    }

    fn rhs(&self, state: &[f64], input: &[f64], rates: &mut [f64]) -> Result<(), SizeError> {
        done(self.answer(Call::Rhs(state, input, rates))).map(drop)
    }

    fn state_jacobian(
        &self,
        state: &[f64],
        input: &[f64],
        out: &mut [f64],
    ) -> Result<(), SizeError> {
        done(self.answer(Call::StateJacobian(state, input, out))).map(drop)
    }

    fn input_jacobian(
        &self,
        state: &[f64],
        input: &[f64],
        out: &mut [f64],
    ) -> Result<(), SizeError> {
        done(self.answer(Call::InputJacobian(state, input, out))).map(drop)
    }

    fn kinetic_energy(&self, state: &[f64]) -> Result<f64, SizeError> {
        done(self.answer(Call::KineticEnergy(state)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::{Pendulum, PlanarAtG};

    /// The erased call gives the typed call's bits, and a slice of the wrong length is an
    /// error that names it, not a panic.
    #[test]
    fn an_erased_model_gives_the_typed_models_bits_and_refuses_wrong_sizes() {
        let typed = PlanarAtG::new(2.0, 3.0).unwrap();
        let state = [1.0, 0.5, 0.25, 3.0, -2.0, 0.7];
        let input = [0.3, -0.2, 0.1];
        for model in [
            &Erased::<_, 6, 3>(typed) as &dyn DynModel,
            &AnyModel::from(typed) as &dyn DynModel,
        ] {
            let mut rates = [0.0; 6];
            model.rhs(&state, &input, &mut rates).unwrap();
            assert_eq!(rates, typed.rhs(&state, &input));
            let mut a = [0.0; 36];
            model.state_jacobian(&state, &input, &mut a).unwrap();
            assert_eq!(a[6..12], typed.state_jacobian(&state, &input)[1]);
            let mut b = [0.0; 18];
            model.input_jacobian(&state, &input, &mut b).unwrap();
            assert_eq!(b[3..6], typed.input_jacobian(&state, &input)[1]);
            assert_eq!(model.state_names(), PlanarAtG::<f64>::STATE.to_vec());
            assert_eq!(model.input_names().len(), 3);
            let error = model.rhs(&state[..5], &input, &mut rates).unwrap_err();
            assert_eq!((error.what, error.got, error.expected), ("state", 5, 6));
            let error = model.state_jacobian(&state, &input, &mut b).unwrap_err();
            assert_eq!(
                (error.what, error.got, error.expected),
                ("state Jacobian", 18, 36)
            );
        }
        let pendulum = AnyModel::from(Pendulum::new(
            &crate::PendulumParameters::new(2.0, 3.0, 9.81, 0.5).unwrap(),
        ));
        assert_eq!(pendulum.name(), "pendulum");
    }
}
