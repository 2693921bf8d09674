//! Every catalog model over f64 and over dual numbers, handed to a [`Sink`]: shared by the
//! Jacobian bench and `examples/jacobian_table.rs`, so that both price the same calls.

use crate::bodies::tensor;
use eom::PendulumParameters;
use eom::models::{Model, Symmetry};
use num_dual::Dual64;

/// What is done with each model.
pub trait Sink {
    /// One model, `name` its module, over f64 and over dual numbers.
    fn model<Mo, Md, const N: usize, const M: usize>(&mut self, name: &str, model: &Mo, dual: &Md)
    where
        Mo: Model<f64, N, M>,
        Md: Model<Dual64, N, M>;
}

macro_rules! each_model {
    ($($module:ident => $type:ident {
        family: $family:ident $(($($option:ident),+))?,
        state: $n:literal, inputs: $m:literal, title: $title:literal,
        parameters: [$($parameter:ident),*], potential_energy: $potential:tt
    },)*) => {
        /// Hands every model of the catalog to `sink`, in the catalog's order.
        pub fn each_model(sink: &mut impl Sink) {
            $({
                let (model, dual) = each_model!(@new $type, $family $(($($option),+))?);
                sink.model::<_, _, $n, $m>(stringify!($module), &model, &dual);
            })*
        }
    };
    (@new $type:ident, Pendulum) => {{
        let parameters = PendulumParameters::new(2.0, 3.0, 9.81, 0.5).expect("valid");
        (eom::models::$type::<f64>::new(&parameters), eom::models::$type::<Dual64>::new(&parameters))
    }};
    (@new $type:ident, PlanarMidship) => {(
        eom::models::$type::<f64>::new(1000.0, 2.0e5, 3.0).expect("valid"),
        eom::models::$type::<Dual64>::new(1000.0, 2.0e5, 3.0).expect("valid"),
    )};
    (@new $type:ident, Top($kinematics:ident)) => {(
        eom::models::$type::<f64>::new(2.0, &tensor(Symmetry::Principal), 0.4, 9.81).expect("valid"),
        eom::models::$type::<Dual64>::new(2.0, &tensor(Symmetry::Principal), 0.4, 9.81).expect("valid"),
    )};
    (@new $type:ident, Spatial($symmetry:ident, $kinematics:ident)) => {(
        eom::models::$type::<f64>::new(5.0, &tensor(Symmetry::$symmetry)).expect("valid"),
        eom::models::$type::<Dual64>::new(5.0, &tensor(Symmetry::$symmetry)).expect("valid"),
    )};
    (@new $type:ident, $planar:ident) => {(
        eom::models::$type::<f64>::new(1000.0, 2.0e5).expect("valid"),
        eom::models::$type::<Dual64>::new(1000.0, 2.0e5).expect("valid"),
    )};
}

eom::for_each_model!(each_model);

/// A state of `N` entries away from every singularity (angles of 0.1–0.4 rad, a quaternion
/// of about unit length), and inputs of `M`.
pub fn point<const N: usize, const M: usize>() -> ([f64; N], [f64; M]) {
    (
        std::array::from_fn(|i| 0.1 + 0.3 * ((i * 7 % 11) as f64) / 11.0),
        std::array::from_fn(|i| 0.5 - 0.1 * i as f64),
    )
}

/// Both Jacobians the emitted way: the two programs, scattered into dense matrices.
pub fn emitted<Mo: Model<f64, N, M>, const N: usize, const M: usize>(
    model: &Mo,
    state: &[f64; N],
    input: &[f64; M],
) -> ([[f64; N]; N], [[f64; M]; N]) {
    (
        model.state_jacobian(state, input),
        model.input_jacobian(state, input),
    )
}

/// Both Jacobians by dual numbers: `rhs` once per column, the column's entry seeded.
pub fn by_dual_numbers<Md: Model<Dual64, N, M>, const N: usize, const M: usize>(
    dual: &Md,
    state: &[f64; N],
    input: &[f64; M],
) -> ([[f64; N]; N], [[f64; M]; N]) {
    let (x, u) = (state.map(Dual64::from), input.map(Dual64::from));
    let mut a = [[0.0; N]; N];
    let mut b = [[0.0; M]; N];
    for j in 0..N {
        let mut seeded = x;
        seeded[j] = seeded[j].derivative();
        for (i, rate) in dual.rhs(&seeded, &u).iter().enumerate() {
            a[i][j] = rate.eps;
        }
    }
    for j in 0..M {
        let mut seeded = u;
        seeded[j] = seeded[j].derivative();
        for (i, rate) in dual.rhs(&x, &seeded).iter().enumerate() {
            b[i][j] = rate.eps;
        }
    }
    (a, b)
}
