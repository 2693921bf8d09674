//! The generic forms under the model contract ([`Model`]), in f64: so a test integrates a
//! generic form and a generated model through the same trait, the same `driven_by` and the same
//! integrator, and compares trajectories, not only rates.
//!
//! Each form names its state and inputs as the generated model of the same equations does
//! (`tests/generic_forms.rs` holds the two to one another). A generic form carries the full
//! tensor, so its name is the full variant's. Its Jacobians are not emitted: they are the
//! derivatives of the form's own `rhs` by forward-mode dual numbers (one evaluation per
//! column, exact to rounding), which makes them an independent check on the emitted ones;
//! since the form does not know which entries vanish, its patterns list every entry.
//!
//! The top has no generic form, so none is here.

use super::{Pendulum, PlanarBody, PlanarMidship, PlanarSpaceFixed, RigidBody};
use super::{rates, velocity};
use crate::energy::{pendulum_kinetic_energy, pendulum_potential_energy};
use crate::models::Model;
use nalgebra::{RealField, SVector, Vector3};
use num_dual::Dual64;

/// Every (row, column) of an `R × C` matrix, row by row: the pattern of a Jacobian whose form
/// does not say which entries vanish.
const fn every_entry<const K: usize>(rows: usize, columns: usize) -> [(usize, usize); K] {
    let mut entries = [(0, 0); K];
    let mut k = 0;
    while k < K {
        entries[k] = (k / columns, k % columns);
        k += 1;
    }
    assert!(K == rows * columns, "K is rows × columns");
    entries
}

/// ∂f/∂x of `rates` at `(state, input)`: column `j` from one evaluation with ε on `state[j]`.
fn by_state<const N: usize, const M: usize>(
    rates: impl Fn(&[Dual64; N], &[Dual64; M]) -> [Dual64; N],
    state: &[f64; N],
    input: &[f64; M],
) -> [[f64; N]; N] {
    let mut jacobian = [[0.0; N]; N];
    let input = input.map(Dual64::from);
    for column in 0..N {
        let mut seeded = state.map(Dual64::from);
        seeded[column] = seeded[column].derivative();
        for (row, rate) in rates(&seeded, &input).iter().enumerate() {
            jacobian[row][column] = rate.eps;
        }
    }
    jacobian
}

/// ∂f/∂u of `rates` at `(state, input)`: column `j` from one evaluation with ε on `input[j]`.
fn by_input<const N: usize, const M: usize>(
    rates: impl Fn(&[Dual64; N], &[Dual64; M]) -> [Dual64; N],
    state: &[f64; N],
    input: &[f64; M],
) -> [[f64; M]; N] {
    let mut jacobian = [[0.0; M]; N];
    let state = state.map(Dual64::from);
    for column in 0..M {
        let mut seeded = input.map(Dual64::from);
        seeded[column] = seeded[column].derivative();
        for (row, rate) in rates(&state, &seeded).iter().enumerate() {
            jacobian[row][column] = rate.eps;
        }
    }
    jacobian
}

/// The three entries of `v` starting at `at`.
fn three<T: RealField + Copy, const M: usize>(v: &[T; M], at: usize) -> Vector3<T> {
    Vector3::new(v[at], v[at + 1], v[at + 2])
}

/// The contract items every form writes the same way: the Jacobians by dual numbers through
/// `$rates`, a function of the form over `Dual64` and the state and input arrays.
macro_rules! dual_jacobians {
    ($n:literal, $m:literal, $rates:expr) => {
        const STATE_JACOBIAN: &'static [(usize, usize)] = &every_entry::<{ $n * $n }>($n, $n);
        const INPUT_JACOBIAN: &'static [(usize, usize)] = &every_entry::<{ $n * $m }>($n, $m);

        fn state_jacobian(&self, state: &[f64; $n], input: &[f64; $m]) -> [[f64; $n]; $n] {
            let form = self.cast::<Dual64>();
            by_state(|x, u| $rates(&form, x, u), state, input)
        }

        fn input_jacobian(&self, state: &[f64; $n], input: &[f64; $m]) -> [[f64; $m]; $n] {
            let form = self.cast::<Dual64>();
            by_input(|x, u| $rates(&form, x, u), state, input)
        }
    };
}

/// 4.24 as the generic pendulum writes it, on arrays.
fn pendulum<T: RealField + Copy>(form: &Pendulum<T>, state: &[T; 2], input: &[T; 1]) -> [T; 2] {
    form.rhs(&SVector::from(*state), input[0]).into()
}

impl Model<f64, 2, 1> for Pendulum<f64> {
    const NAME: &'static str = "pendulum";
    const STATE: [&'static str; 2] = ["theta", "theta_dot"];
    const INPUTS: [&'static str; 1] = ["M_O"];

    fn rhs(&self, state: &[f64; 2], input: &[f64; 1]) -> [f64; 2] {
        pendulum(self, state, input)
    }

    fn kinetic_energy(&self, state: &[f64; 2]) -> f64 {
        pendulum_kinetic_energy(self.i0(), state[1])
    }

    /// V = −Mgh cos θ (4.35): 4.34's U = Mgh(1 − cos θ), less Mgh.
    fn potential_energy(&self, state: &[f64; 2]) -> Option<f64> {
        let (mass, g, h) = (self.mass(), self.g(), self.h());
        Some(pendulum_potential_energy(mass, g, h, state[0]) - mass * g * h)
    }

    dual_jacobians!(2, 1, pendulum);
}

/// 4.43 + 4.44 as the generic planar body writes it, on arrays.
fn planar_at_g<T: RealField + Copy>(form: &PlanarBody<T>, x: &[T; 6], u: &[T; 3]) -> [T; 6] {
    form.rhs_body_at_g(&SVector::from(*x), &three(u, 0)).into()
}

/// ½M(a² + b²) + ½I_zz c².
fn planar_energy(mass: f64, izz: f64, a: f64, b: f64, c: f64) -> f64 {
    0.5 * (mass * (a * a + b * b) + izz * c * c)
}

impl Model<f64, 6, 3> for PlanarBody<f64> {
    const NAME: &'static str = "planar_at_g";
    const STATE: [&'static str; 6] = ["u", "v", "r", "X", "Y", "psi"];
    const INPUTS: [&'static str; 3] = ["F_x", "F_y", "M_z"];

    fn rhs(&self, state: &[f64; 6], input: &[f64; 3]) -> [f64; 6] {
        planar_at_g(self, state, input)
    }

    fn kinetic_energy(&self, [u, v, r, ..]: &[f64; 6]) -> f64 {
        planar_energy(self.mass(), self.izz(), *u, *v, *r)
    }

    dual_jacobians!(6, 3, planar_at_g);
}

/// 4.39 as the generic planar body writes it, on arrays.
fn planar_space_fixed<T: RealField + Copy>(form: &PlanarBody<T>, x: &[T; 6], u: &[T; 3]) -> [T; 6] {
    form.rhs_space_fixed(&SVector::from(*x), &three(u, 0))
        .into()
}

impl PlanarSpaceFixed<f64> {
    fn cast<S: RealField + Copy>(&self) -> PlanarBody<S> {
        self.0.cast()
    }
}

impl Model<f64, 6, 3> for PlanarSpaceFixed<f64> {
    const NAME: &'static str = "planar_space_fixed";
    const STATE: [&'static str; 6] = ["X", "Y", "psi", "X_dot", "Y_dot", "psi_dot"];
    const INPUTS: [&'static str; 3] = ["F_X", "F_Y", "M_z"];

    fn rhs(&self, state: &[f64; 6], input: &[f64; 3]) -> [f64; 6] {
        planar_space_fixed(&self.0, state, input)
    }

    fn kinetic_energy(&self, [.., x_dot, y_dot, psi_dot]: &[f64; 6]) -> f64 {
        planar_energy(self.0.mass(), self.0.izz(), *x_dot, *y_dot, *psi_dot)
    }

    dual_jacobians!(6, 3, planar_space_fixed);
}

/// 4.46 + 4.44 as the generic midship form writes it, on arrays.
fn planar_midship<T: RealField + Copy>(form: &PlanarMidship<T>, x: &[T; 6], u: &[T; 3]) -> [T; 6] {
    form.rhs_body_at_midship(&SVector::from(*x), &three(u, 0))
        .into()
}

impl Model<f64, 6, 3> for PlanarMidship<f64> {
    const NAME: &'static str = "planar_midship";
    const STATE: [&'static str; 6] = ["u", "v", "r", "X", "Y", "psi"];
    const INPUTS: [&'static str; 3] = ["F_x", "F_y", "M_z"];

    /// G moves at (u, v + x_G r): ½M(u² + (v + x_G r)²) + ½I_zz r².
    fn kinetic_energy(&self, [u, v, r, ..]: &[f64; 6]) -> f64 {
        planar_energy(self.mass(), self.izz(), *u, v + self.x_g() * r, *r)
    }

    fn rhs(&self, state: &[f64; 6], input: &[f64; 3]) -> [f64; 6] {
        planar_midship(self, state, input)
    }

    dual_jacobians!(6, 3, planar_midship);
}

/// 4.49 + 4.51 + 4.57 + 4.60 as the generic rigid body writes them, on arrays.
fn spatial_euler<T: RealField + Copy>(form: &RigidBody<T>, x: &[T; 12], u: &[T; 6]) -> [T; 12] {
    form.rhs_euler(&SVector::from(*x), &three(u, 0), &three(u, 3))
        .into()
}

/// 4.49 + 4.51 and the quaternion's rate as the generic rigid body writes them, on arrays.
fn spatial_quaternion<T: RealField + Copy>(
    form: &RigidBody<T>,
    x: &[T; 13],
    u: &[T; 6],
) -> [T; 13] {
    form.rhs_quaternion(&SVector::from(*x), &three(u, 0), &three(u, 3))
        .into()
}

/// ½M v·v + ½ωᵀ[I]ω (4.32) of a spatial state, either kinematics.
fn spatial_energy<const N: usize>(form: &RigidBody<f64>, state: &[f64; N]) -> f64 {
    let state = SVector::from(*state);
    form.kinetic_energy(&velocity(&state), &rates(&state))
}

const SPATIAL_INPUTS: [&str; 6] = ["F_x", "F_y", "F_z", "M_x", "M_y", "M_z"];

impl Model<f64, 12, 6> for RigidBody<f64> {
    const NAME: &'static str = "spatial_full_euler";
    const STATE: [&'static str; 12] = [
        "u", "v", "w", "p", "q", "r", "x", "y", "z", "phi", "theta", "psi",
    ];
    const INPUTS: [&'static str; 6] = SPATIAL_INPUTS;

    fn rhs(&self, state: &[f64; 12], input: &[f64; 6]) -> [f64; 12] {
        spatial_euler(self, state, input)
    }

    fn kinetic_energy(&self, state: &[f64; 12]) -> f64 {
        spatial_energy(self, state)
    }

    dual_jacobians!(12, 6, spatial_euler);
}

impl Model<f64, 13, 6> for RigidBody<f64> {
    const NAME: &'static str = "spatial_full_quaternion";
    const STATE: [&'static str; 13] = [
        "u", "v", "w", "p", "q", "r", "x", "y", "z", "q0", "q1", "q2", "q3",
    ];
    const INPUTS: [&'static str; 6] = SPATIAL_INPUTS;

    fn rhs(&self, state: &[f64; 13], input: &[f64; 6]) -> [f64; 13] {
        spatial_quaternion(self, state, input)
    }

    fn kinetic_energy(&self, state: &[f64; 13]) -> f64 {
        spatial_energy(self, state)
    }

    dual_jacobians!(13, 6, spatial_quaternion);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_entry_lists_the_matrix_row_by_row() {
        assert_eq!(
            every_entry::<6>(2, 3),
            [(0, 0), (0, 1), (0, 2), (1, 0), (1, 1), (1, 2)]
        );
    }
}
