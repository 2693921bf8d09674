//! A point mass over the Earth: the proved program of `eom_codegen::model::earth` (ECEF
//! position and Earth-relative velocity under J2 gravitation, the Coriolis and centripetal
//! terms of a turning Earth), derived, proved with its Jacobians and resolved when it is
//! built, evaluated here as a [`Model`] any integrator runs.
//!
//! The program reads 1/r beside the state (its expressions are polynomials): this model
//! computes it from the position, and its ∂f/∂x adds the chain rule ∂(1/r)/∂r = −r/r³ to the
//! program's entries. The inputs are the applied force per unit mass in ECEF axes.

use super::{EarthConstants, Gravity};
use crate::defined::engine::{EmitError, earth_model, prove_with_jacobians};
use crate::defined::{CoefficientFormulas, Functions, Interpreter, Source, Variables};
use crate::models::Model;
use simba::simd::SimdRealField;
use std::collections::BTreeMap;

/// The state: x, y, z (m, ECEF) and the velocity relative to the Earth (m/s, ECEF axes).
pub const STATE: [&str; 6] = earth_model::STATE;

/// The inputs: the applied force per unit mass, m/s², ECEF axes.
pub const INPUTS: [&str; 3] = ["f_x", "f_y", "f_z"];

/// Why a point mass cannot be built.
#[derive(Debug, thiserror::Error)]
pub enum PointMassError {
    /// A constant field has no centre: it is the flat Earth's.
    #[error("a constant gravity is the flat Earth's; over the Earth give GM/r² or J2")]
    ConstantGravity,
    /// The symbolic engine could not build or prove the program.
    #[error("the point mass cannot be built: {0}")]
    Build(#[from] EmitError),
    /// A value the program needs is not a finite number.
    #[error("`{0}` is not a finite number")]
    NotFinite(&'static str),
}

/// A point mass over the Earth, its program proved.
#[derive(Debug, Clone)]
pub struct PointMass {
    program: Interpreter,
    functions: Functions,
}

impl PointMass {
    /// The point mass in `gravity` (GM/r² or J2) over an Earth turning at `rotation_rate`
    /// (rad/s; zero for one that does not).
    pub fn new(gravity: &Gravity, rotation_rate: f64) -> Result<Self, PointMassError> {
        let (gm, j2, radius) = match *gravity {
            Gravity::Constant(_) => return Err(PointMassError::ConstantGravity),
            Gravity::InverseSquare { gm } => (gm, 0.0, 1.0),
            Gravity::J2 {
                gm,
                j2,
                equatorial_radius,
            } => (gm, j2, equatorial_radius),
        };
        let values = [
            ("GM", gm),
            ("J2", j2),
            ("a_e", radius),
            ("omega_e", rotation_rate),
        ];
        if let Some((name, _)) = values.iter().find(|(_, v)| !v.is_finite()) {
            return Err(PointMassError::NotFinite(name));
        }
        let system = earth_model::point_mass("point_mass")
            .map_err(|e| PointMassError::Build(EmitError::Model(e)))?;
        let program = prove_with_jacobians(&system)?;
        let parameters: BTreeMap<String, f64> =
            values.iter().map(|(n, v)| (n.to_string(), *v)).collect();
        let coefficients = CoefficientFormulas::new(&system, &program).values(&parameters);
        let functions =
            Functions::of(&program).map_err(|_| PointMassError::NotFinite("program"))?;
        let position = |name: &str| {
            let index = |names: &[&str]| names.iter().position(|s| *s == name);
            (index(&STATE).map(Source::State))
                .or_else(|| index(&earth_model::INPUTS).map(Source::Computed))
        };
        let program = Interpreter::new(&program, &coefficients, position)
            .map_err(|_| PointMassError::NotFinite("program"))?;
        Ok(PointMass {
            functions: functions.compile(&program),
            program,
        })
    }

    /// The point mass over the NESC cases' Earth: J2 on WGS-84, turning.
    pub fn nesc(constants: &EarthConstants) -> Result<Self, PointMassError> {
        let gravity = Gravity::J2 {
            gm: constants.gm,
            j2: constants.j2,
            equatorial_radius: constants.ellipsoid.equatorial_radius,
        };
        PointMass::new(&gravity, constants.rotation_rate)
    }

    /// (1/r, f_x, f_y, f_z): what the program reads beside the state.
    fn computed<T: SimdRealField + Copy>(state: &[T; 6], input: &[T; 3]) -> [T; 4] {
        let r2 = state[0] * state[0] + state[1] * state[1] + state[2] * state[2];
        [T::one() / r2.simd_sqrt(), input[0], input[1], input[2]]
    }

    fn evaluate<'a, T: SimdRealField + Copy>(
        &'a self,
        plan: &'a crate::defined::Plan,
        state: &'a [T; 6],
        computed: &'a [T; 4],
    ) -> impl Iterator<Item = T> + 'a {
        let variables = Variables { state, computed };
        self.program.evaluate(plan, variables)
    }
}

impl<T: SimdRealField + Copy> Model<T, 6, 3> for PointMass {
    const NAME: &'static str = "point_mass_over_earth";
    const STATE: [&'static str; 6] = STATE;
    const INPUTS: [&'static str; 3] = INPUTS;
    #[rustfmt::skip]
    const STATE_JACOBIAN: &'static [(usize, usize)] = &[
        (0, 3), (1, 4), (2, 5),
        (3, 0), (3, 1), (3, 2), (3, 4),
        (4, 0), (4, 1), (4, 2), (4, 3),
        (5, 0), (5, 1), (5, 2),
    ];
    const INPUT_JACOBIAN: &'static [(usize, usize)] = &[(3, 0), (4, 1), (5, 2)];

    /// The proved program's rates.
    fn rhs(&self, state: &[T; 6], input: &[T; 3]) -> [T; 6] {
        let computed = Self::computed(state, input);
        let variables = Variables {
            state,
            computed: &computed,
        };
        let mut rates = [T::zero(); 6];
        (self.program).evaluate_into(&self.functions.rhs, variables, &mut rates);
        rates
    }

    /// ½|v|², J/kg: the kinetic energy per unit mass relative to the Earth.
    fn kinetic_energy(&self, state: &[T; 6]) -> T {
        let computed = Self::computed(state, &[T::zero(); 3]);
        let plan = &self.functions.kinetic_energy;
        self.evaluate(plan, state, &computed)
            .next()
            .unwrap_or_else(T::zero)
    }

    /// ∂f/∂x: the proved Jacobian program, with the chain rule through 1/r.
    fn state_jacobian(&self, state: &[T; 6], input: &[T; 3]) -> [[T; 6]; 6] {
        let computed = Self::computed(state, input);
        let mut by_state = [[T::zero(); 6]; 6];
        let entries = self.evaluate(&self.functions.state_jacobian, state, &computed);
        for (&(row, column), value) in self.functions.state_pattern.iter().zip(entries) {
            by_state[row][column] = value;
        }
        let inv_r = computed[0];
        let inv_r3 = inv_r * inv_r * inv_r;
        let entries = self.evaluate(&self.functions.input_jacobian, state, &computed);
        for (&(row, column), value) in self.functions.input_pattern.iter().zip(entries) {
            if column == 0 {
                for k in 0..3 {
                    by_state[row][k] -= value * state[k] * inv_r3;
                }
            }
        }
        by_state
    }

    /// ∂f/∂f: the proved Jacobian program's columns of the applied force.
    fn input_jacobian(&self, state: &[T; 6], input: &[T; 3]) -> [[T; 3]; 6] {
        let computed = Self::computed(state, input);
        let mut by_input = [[T::zero(); 3]; 6];
        let entries = self.evaluate(&self.functions.input_jacobian, state, &computed);
        for (&(row, column), value) in self.functions.input_pattern.iter().zip(entries) {
            if column > 0 {
                by_input[row][column - 1] = value;
            }
        }
        by_input
    }
}
