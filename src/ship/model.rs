//! The ship model: 4.46 with a table's terms, built and proved by `eom-codegen` when the
//! scene is read, and evaluated here.
//!
//! What runs is the proved straight-line program itself, through the one interpreter of
//! scene-defined models (`crate::defined`): the right-hand side, its Jacobians ∂f/∂x and
//! ∂f/∂u, the kinetic energy, each folded back and proved against the system and its exact
//! derivative when the scene is read, as the catalog's are when eom is built.
//!
//! In the prime system the forces scale with the speed U = √(u² + v²), which the program takes
//! as an input beside δ̇: this model computes U from the state, and its ∂f/∂x adds the chain
//! rule through U (∂f/∂U · u/U and · v/U) to the program's ∂f/∂u and ∂f/∂v.

use super::ShipError;
use super::table::ShipTable;
use crate::defined::engine::{
    ADDED_MASS, EmitError, Operations, PRIME_SCALES, Program, ShipSpec, System, Units,
    prove_with_jacobians, ship,
};
use crate::defined::{Functions, Interpreter, Plan, coefficient_values};
use crate::models::Model;
use simba::simd::SimdRealField;
use std::collections::BTreeMap;
use std::sync::Arc;

/// The state: u, v, r (m/s, m/s, rad/s, body axes at midship), X, Y (m, midship in space
/// axes), ψ (rad), δ (rad, the rudder angle).
pub const STATE: [&str; 7] = ["u", "v", "r", "X", "Y", "psi", "delta"];

/// The input: the rudder's rate δ̇ (rad/s), which the steering gear sets
/// ([`super::rudder`]).
pub const INPUTS: [&str; 1] = ["delta_rate"];

/// Where the rates can depend on the state, for any table: u̇, v̇, ṙ on u, v, r and δ (the
/// terms in U of a prime table are in u and v); Ẋ, Ẏ on u, v, ψ (4.44); ψ̇ on r; δ̇ on none.
/// A table without a term in some entry makes that entry's derivative zero at every state.
#[rustfmt::skip]
const STATE_JACOBIAN: [(usize, usize); 19] = [
    (0, 0), (0, 1), (0, 2), (0, 6),
    (1, 0), (1, 1), (1, 2), (1, 6),
    (2, 0), (2, 1), (2, 2), (2, 6),
    (3, 0), (3, 1), (3, 5),
    (4, 0), (4, 1), (4, 5),
    (5, 2),
];

/// δ̇ is the rudder's rate itself.
const INPUT_JACOBIAN: [(usize, usize); 1] = [(6, 0)];

/// A ship's proved program, ready to evaluate.
#[derive(Debug, Clone)]
pub struct ShipModel {
    program: Interpreter,
    functions: Functions,
    /// What the table's values do not change, shared by the models of other values.
    proved: Arc<Proved>,
    /// The column of U among the program's inputs (prime tables), after δ̇'s.
    speed_input: Option<usize>,
    operations: Operations,
    terms: usize,
}

/// The table's terms, 4.46 with them and its proved program: the same for every value of the
/// coefficients.
#[derive(Debug)]
struct Proved {
    spec: ShipSpec,
    system: System,
    program: Program,
}

/// The terms of `table`, its units and where its yaw inertia is taken.
fn spec_of(table: &ShipTable) -> ShipSpec {
    ShipSpec {
        units: table.units,
        yaw_inertia: table.body.yaw_inertia_about,
        terms: table.terms.keys().copied().collect(),
    }
}

impl ShipModel {
    /// Derives, solves and proves 4.46 with the table's terms, then resolves the program.
    pub fn new(table: &ShipTable) -> Result<Self, ShipError> {
        let spec = spec_of(table);
        let system = ship("ship", &spec).map_err(|e| ShipError::Build(EmitError::Model(e)))?;
        let program = prove_with_jacobians(&system)?;
        let functions = Functions::of(&program)
            .map_err(|what| ShipError::invalid("hydrodynamics", format!("no {what}")))?;
        let proved = Proved {
            spec,
            system,
            program,
        };
        let interpreter = interpreter(&proved, &coefficients(&proved, table))?;
        Ok(ShipModel {
            functions: functions.compile(&interpreter),
            speed_input: proved.system.inputs.iter().position(|i| *i == "U"),
            operations: proved.program.operations(&proved.program.rhs),
            terms: proved.spec.terms.len(),
            program: interpreter,
            proved: Arc::new(proved),
        })
    }

    /// The model of `table`, a table of the same terms, units and yaw-inertia convention as
    /// this model's, with other values (a Monte Carlo case, a coefficient being fitted): the
    /// program is the one derived, proved and compiled for this model, only its coefficients
    /// are computed again, in microseconds where [`ShipModel::new`] takes tens of
    /// milliseconds. A table of other terms is refused: derive and prove its own model.
    pub fn with_table(&self, table: &ShipTable) -> Result<Self, ShipError> {
        if spec_of(table) != self.proved.spec {
            return Err(ShipError::invalid(
                "hydrodynamics",
                "the table's terms, units or yaw inertia are not the model's: build its own \
                 model (ShipModel::new)",
            ));
        }
        let coefficients = coefficients(&self.proved, table);
        // A table that did not come through `ShipTable::new` may have a singular mass matrix.
        let program = &self.proved.program;
        if let Some((c, _)) = (program.coefficients.iter())
            .zip(&coefficients)
            .find(|(_, v)| !v.is_finite())
        {
            return Err(ShipError::invalid(
                "hydrodynamics",
                format!("the coefficient `{}` is not finite", c.value),
            ));
        }
        Ok(ShipModel {
            program: interpreter(&self.proved, &coefficients)?,
            ..self.clone()
        })
    }
    /// The program's variables at `state` with the rudder moving at `delta_rate`: the state,
    /// δ̇, U (zero where the program does not read it: a table in SI).
    fn variables<T: SimdRealField + Copy>(&self, state: &[T; 7], delta_rate: T) -> [T; 9] {
        let mut variables = [T::zero(); 9];
        variables[..7].copy_from_slice(state);
        variables[7] = delta_rate;
        if self.speed_input.is_some() {
            variables[8] = (state[0] * state[0] + state[1] * state[1]).simd_sqrt();
        }
        variables
    }

    /// The outputs of `plan` at `state` with the rudder moving at `delta_rate`.
    fn evaluate<'a, T: SimdRealField + Copy>(
        &self,
        plan: &'a Plan,
        state: &[T; 7],
        delta_rate: T,
    ) -> impl Iterator<Item = T> + use<'a, T> {
        (self.program).evaluate(plan, &self.variables(state, delta_rate))
    }

    /// ∂f/∂x and ∂f/∂δ̇ of the model, dense: the proved Jacobian programs scattered by their
    /// patterns, and in the prime system the chain rule through U added.
    fn jacobians<T: SimdRealField + Copy>(
        &self,
        state: &[T; 7],
        delta_rate: T,
    ) -> ([[T; 7]; 7], [[T; 1]; 7]) {
        let mut by_state = [[T::zero(); 7]; 7];
        let entries = self.evaluate(&self.functions.state_jacobian, state, delta_rate);
        for (&(row, column), value) in self.functions.state_pattern.iter().zip(entries) {
            by_state[row][column] = value;
        }
        let mut by_input = [[T::zero(); 1]; 7];
        let speed = (state[0] * state[0] + state[1] * state[1]).simd_sqrt();
        let entries = self.evaluate(&self.functions.input_jacobian, state, delta_rate);
        for (&(row, column), value) in self.functions.input_pattern.iter().zip(entries) {
            if Some(column) == self.speed_input {
                // ∂U/∂u = u/U, ∂U/∂v = v/U.
                by_state[row][0] += value * (state[0] / speed);
                by_state[row][1] += value * (state[1] / speed);
            } else {
                by_input[row][column] = value;
            }
        }
        (by_state, by_input)
    }

    /// What one call costs, as the emitter counts it.
    pub fn operations(&self) -> Operations {
        self.operations
    }

    /// How many terms of the polynomial the model carries.
    pub fn terms(&self) -> usize {
        self.terms
    }

    /// Whether the proved program runs as machine code compiled when the model was built
    /// (in f64, with the feature `jit`), rather than by the interpreter.
    pub fn is_compiled(&self) -> bool {
        self.functions.is_compiled()
    }

    /// The same model evaluated by the interpreter of its proved program: the reference the
    /// compiled code is checked against, bit for bit.
    pub fn interpreted(&self) -> ShipModel {
        ShipModel {
            functions: self.functions.interpreted(),
            ..self.clone()
        }
    }

    /// The same model with its proved program compiled to machine code (the interpreter's
    /// when the program cannot be compiled): what [`ShipModel::new`] builds.
    pub fn compiled(&self) -> ShipModel {
        ShipModel {
            functions: self.functions.clone().compile(&self.program),
            ..self.clone()
        }
    }
}

/// The hoisted coefficients of the proved program with `table`'s values.
fn coefficients(proved: &Proved, table: &ShipTable) -> Vec<f64> {
    let values = parameter_values(&proved.spec, table);
    coefficient_values(&proved.system, &proved.program, &values)
}

/// The proved program resolved with the `coefficients`' values.
fn interpreter(proved: &Proved, coefficients: &[f64]) -> Result<Interpreter, ShipError> {
    // The variables in `evaluate`'s order: the state, δ̇, U.
    let position = |name: &str| match name {
        "delta_rate" => Some(7),
        "U" => Some(8),
        _ => STATE.iter().position(|s| *s == name),
    };
    Interpreter::new(&proved.program, coefficients, position)
        .map_err(|name| ShipError::invalid("hydrodynamics", format!("the program reads `{name}`")))
}

/// Every parameter's value by its symbol, as the table gives it; the symbols are the spec's.
fn parameter_values(spec: &ShipSpec, table: &ShipTable) -> BTreeMap<String, f64> {
    let body = [table.body.mass, table.body.yaw_inertia, table.body.x_g];
    let mut values: BTreeMap<String, f64> = spec
        .body_symbols()
        .into_iter()
        .zip(body)
        .chain(ADDED_MASS.into_iter().zip(table.added_mass))
        .map(|(symbol, value)| (symbol.to_owned(), value))
        .collect();
    if table.units == Units::Prime {
        let scales = [
            table.density.unwrap_or(f64::NAN),
            table.length.unwrap_or(f64::NAN),
            table.design_speed,
        ];
        for (symbol, value) in PRIME_SCALES.into_iter().zip(scales) {
            values.insert(symbol.to_owned(), value);
        }
    }
    for (term, value) in &table.terms {
        values.insert(term.symbol(), *value);
    }
    values
}

/// The ship as a model like the catalog's: its state and input, the proved program as `rhs`,
/// its proved Jacobians, and the rigid body's kinetic energy.
impl<T: SimdRealField + Copy> Model<T, 7, 1> for ShipModel {
    const NAME: &'static str = "ship";
    const STATE: [&'static str; 7] = STATE;
    const INPUTS: [&'static str; 1] = INPUTS;
    const STATE_JACOBIAN: &'static [(usize, usize)] = &STATE_JACOBIAN;
    const INPUT_JACOBIAN: &'static [(usize, usize)] = &INPUT_JACOBIAN;

    /// The rates of the state with the rudder moving at `input[0]`: the proved program.
    fn rhs(&self, state: &[T; 7], input: &[T; 1]) -> [T; 7] {
        let variables = self.variables(state, input[0]);
        let mut rates = [T::zero(); 7];
        (self.program).evaluate_into(&self.functions.rhs, &variables, &mut rates);
        rates
    }

    /// The rigid body's kinetic energy ½M(u² + (v + x_G r)²) + ½I_z r² (4.32 about G, with
    /// I_z about G), in J (a prime table's body scaled to SI), the program's proved form; the
    /// fluid's share (the added mass) is not in it.
    fn kinetic_energy(&self, state: &[T; 7]) -> T {
        (self
            .evaluate(&self.functions.kinetic_energy, state, T::zero())
            .next())
        .unwrap_or_else(T::zero)
    }

    /// ∂f/∂x: the proved Jacobian program (see the module docs for U).
    fn state_jacobian(&self, state: &[T; 7], input: &[T; 1]) -> [[T; 7]; 7] {
        self.jacobians(state, input[0]).0
    }

    /// ∂f/∂δ̇: the proved Jacobian program.
    fn input_jacobian(&self, state: &[T; 7], input: &[T; 1]) -> [[T; 1]; 7] {
        self.jacobians(state, input[0]).1
    }
}
