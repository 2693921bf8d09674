//! The vehicle model: the six equations about the table's origin O with its table's terms,
//! built and proved by `eom-codegen` when the scene is read, and evaluated by the one
//! interpreter of proved programs (`crate::defined`).
//!
//! The state is the generator's (ν = u, v, w, p, q, r in body axes at O; the position x, y, z
//! of O in space axes, Z down; the quaternion q0 … q3) followed by the fins' angles δ_r, δ_s,
//! whose rates are the model's inputs (the steering gear sets them, [`super::fins`]), as the
//! ship's rudder is a state of the ship. The program reads δ_r and δ_s as its controls, and
//! |x| of each velocity whose signed square x|x| the table holds as an input `abs_x`: this
//! model computes those from the state, and its ∂f/∂x adds the chain rule
//! ∂f/∂abs_x · sign(x) to the column of x (and the program's ∂f/∂δ to the fins' columns).

use super::VehicleError;
use super::table::{CONTROLS, VehicleTable};
use crate::defined::engine::{
    FoldedComparison, InertiaAbout, Kinematics, Operations, Propeller, Symmetry, Units,
    VehicleSpec, folded_comparison, prove_with_jacobians, vehicle,
};
use crate::defined::{Functions, Interpreter, coefficient_values};
use crate::models::Model;
use simba::simd::SimdRealField;
use std::collections::BTreeMap;

/// The state: the generator's thirteen, then the rudder's and the stern planes' angles (rad).
pub const STATE: [&str; 15] = [
    "u", "v", "w", "p", "q", "r", "x", "y", "z", "q0", "q1", "q2", "q3", "dr", "ds",
];

/// The inputs: the fins' rates (rad/s), which the steering gear sets.
pub const INPUTS: [&str; 2] = ["dr_rate", "ds_rate"];

/// The number of the generator's state entries (before the fins').
const BODY: usize = 13;

/// Where the rates can depend on the state, for any table: ν̇ on ν, the attitude (the
/// restoring loads) and the fins; the position's rates on ν and the attitude; the attitude's
/// on ω and itself; the fins' on nothing (their rates are inputs).
const STATE_JACOBIAN: [(usize, usize); 6 * 12 + 3 * 7 + 4 * 7] = pattern();

const fn pattern() -> [(usize, usize); 121] {
    let mut entries = [(0, 0); 121];
    let mut k = 0;
    let mut row = 0;
    while row < BODY {
        let mut column = 0;
        while column < STATE.len() {
            let velocity = column < 6;
            let attitude = column >= 9 && column < BODY;
            let fin = column >= BODY;
            let depends = if row < 6 {
                velocity || attitude || fin
            } else if row < 9 {
                column < 3 || attitude
            } else {
                (column >= 3 && column < 6) || attitude
            };
            if depends {
                entries[k] = (row, column);
                k += 1;
            }
            column += 1;
        }
        row += 1;
    }
    entries
}

/// δ̇_r and δ̇_s are the fins' rates themselves.
const INPUT_JACOBIAN: [(usize, usize); 2] = [(13, 0), (14, 1)];

/// A vehicle's proved program, ready to evaluate.
#[derive(Debug, Clone)]
pub struct VehicleModel {
    program: Interpreter,
    functions: Functions,
    /// For each program input, what it is.
    inputs: Vec<Variable>,
    operations: Operations,
    terms: usize,
    folded: Vec<FoldedComparison>,
}

/// A program input, by what the model sets it from.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Variable {
    /// A fin's angle: the state entry.
    Fin(usize),
    /// |x| of the state entry.
    Absolute(usize),
}

/// The spec of a table: quaternion kinematics, inertia about G in principal axes, the fins as
/// controls, the propeller constant.
pub fn spec(table: &VehicleTable) -> VehicleSpec {
    VehicleSpec {
        units: Units::Dimensional,
        kinematics: Kinematics::Quaternion,
        inertia: InertiaAbout::Gravity,
        symmetry: Symmetry::Principal,
        convention: table.convention,
        controls: CONTROLS.map(String::from).to_vec(),
        added_mass: table.added_mass.keys().cloned().collect(),
        added_mass_coriolis: table.added_mass_coriolis,
        terms: table.coefficients.keys().cloned().collect(),
        propeller: if table.propeller.is_some() {
            Propeller::Constant
        } else {
            Propeller::None
        },
        hydrostatics: true,
        applied_loads: false,
    }
}

/// Every parameter's value by its symbol, as the spec names them, without the inverse mass
/// matrix.
fn table_values(
    spec: &VehicleSpec,
    table: &VehicleTable,
) -> Result<BTreeMap<String, f64>, VehicleError> {
    let mut values = BTreeMap::new();
    values.insert("M".to_owned(), table.mass);
    for (axis, value) in ["Ixx_G", "Iyy_G", "Izz_G"].into_iter().zip(table.inertia) {
        values.insert(axis.to_owned(), value);
    }
    for (i, axis) in ["x", "y", "z"].into_iter().enumerate() {
        values.insert(format!("{axis}_G"), table.centre_of_gravity[i]);
        values.insert(format!("{axis}_B"), table.centre_of_buoyancy[i]);
    }
    values.insert("weight".to_owned(), table.weight);
    values.insert("buoyancy".to_owned(), table.buoyancy);
    values.extend(table.added_mass.iter().map(|(k, v)| (k.clone(), *v)));
    if let Some(propeller) = table.propeller {
        values.insert("X_prop".to_owned(), propeller.thrust);
        values.insert("K_prop".to_owned(), propeller.torque);
    }
    for term in spec.force_terms()? {
        let value = table
            .coefficients
            .get(&term.name)
            .copied()
            .unwrap_or(f64::NAN);
        values.insert(term.symbol(), value);
    }
    Ok(values)
}

impl VehicleModel {
    /// Derives and proves the six equations with the table's terms, inverts the mass matrix
    /// (refusing one that is not positive definite), then resolves the program.
    pub fn new(table: &VehicleTable) -> Result<Self, VehicleError> {
        let spec = spec(table);
        let system = vehicle("vehicle", &spec)?;
        let program = prove_with_jacobians(&system)?;
        let mut values = table_values(&spec, table)?;
        let folded = folded_comparison(&spec, &values)?;
        values.extend(spec.inverse_mass_matrix(&values)?);
        let coefficients = coefficient_values(&system, &program, &values);
        if let Some(c) = program
            .coefficients
            .iter()
            .zip(&coefficients)
            .find(|(_, v)| !v.is_finite())
        {
            return Err(VehicleError::invalid(
                "hydrodynamics",
                format!("the coefficient `{}` is not finite", c.0.value),
            ));
        }
        let inputs = (system.inputs.iter())
            .map(|name| input_variable(name))
            .collect::<Result<Vec<_>, _>>()?;
        // The variables in `variables`'s order: the generator's state, then its inputs.
        let position =
            |name: &str| (system.state.iter().chain(&system.inputs)).position(|s| *s == name);
        let interpreter = Interpreter::new(&program, &coefficients, position).map_err(|name| {
            VehicleError::invalid("hydrodynamics", format!("the program reads `{name}`"))
        })?;
        let functions = Functions::of(&program)
            .map_err(|what| VehicleError::invalid("hydrodynamics", format!("no {what}")))?
            .compile(&interpreter);
        Ok(VehicleModel {
            functions,
            inputs,
            operations: program.operations(&program.rhs),
            terms: spec.terms.len(),
            folded,
            program: interpreter,
        })
    }

    /// The program's variables at `state`: the generator's state, then its inputs.
    fn variables<T: SimdRealField + Copy>(&self, state: &[T; 15]) -> Vec<T> {
        let mut variables = state[..BODY].to_vec();
        variables.extend(self.inputs.iter().map(|input| input.value(state)));
        variables
    }

    /// ∂f/∂x and ∂f/∂δ̇ of the model, dense: the proved Jacobian programs scattered by their
    /// patterns, the fins' columns and the chain rule through |x| added.
    fn jacobians<T: SimdRealField + Copy>(&self, state: &[T; 15]) -> ([[T; 15]; 15], [[T; 2]; 15]) {
        let variables = self.variables(state);
        let mut by_state = [[T::zero(); 15]; 15];
        let entries = self
            .program
            .evaluate(&self.functions.state_jacobian, &variables);
        for (&(row, column), value) in self.functions.state_pattern.iter().zip(entries) {
            by_state[row][column] = value;
        }
        let entries = self
            .program
            .evaluate(&self.functions.input_jacobian, &variables);
        for (&(row, column), value) in self.functions.input_pattern.iter().zip(entries) {
            match self.inputs[column] {
                Variable::Fin(i) => by_state[row][i] += value,
                Variable::Absolute(i) => by_state[row][i] += value * state[i].simd_signum(),
            }
        }
        let mut by_input = [[T::zero(); 2]; 15];
        by_input[13][0] = T::one();
        by_input[14][1] = T::one();
        (by_state, by_input)
    }

    /// What one call costs, as the emitter counts it.
    pub fn operations(&self) -> Operations {
        self.operations
    }

    /// How many named force terms the model carries.
    pub fn terms(&self) -> usize {
        self.terms
    }

    /// The folded table against its added mass, per cross term (empty for a derived one).
    pub fn folded(&self) -> &[FoldedComparison] {
        &self.folded
    }

    /// Whether the proved program runs as machine code compiled when the model was built
    /// (in f64, with the feature `jit`), rather than by the interpreter.
    pub fn is_compiled(&self) -> bool {
        self.functions.is_compiled()
    }

    /// The same model evaluated by the interpreter of its proved program: the reference the
    /// compiled code is checked against, bit for bit.
    pub fn interpreted(&self) -> VehicleModel {
        VehicleModel {
            functions: self.functions.interpreted(),
            ..self.clone()
        }
    }

    /// The same model with its proved program compiled to machine code (the interpreter's
    /// when the program cannot be compiled): what [`VehicleModel::new`] builds.
    pub fn compiled(&self) -> VehicleModel {
        VehicleModel {
            functions: self.functions.clone().compile(&self.program),
            ..self.clone()
        }
    }
}

impl Variable {
    /// Its value at `state`.
    fn value<T: SimdRealField + Copy>(self, state: &[T; 15]) -> T {
        match self {
            Variable::Fin(i) => state[i],
            Variable::Absolute(i) => state[i].simd_abs(),
        }
    }
}

fn input_variable(name: &str) -> Result<Variable, VehicleError> {
    let state = |x: &str| STATE.iter().position(|s| *s == x);
    let found = match name.strip_prefix("abs_") {
        Some(x) => state(x).filter(|&i| i < 6).map(Variable::Absolute),
        None => state(name).filter(|&i| i >= BODY).map(Variable::Fin),
    };
    found.ok_or_else(|| {
        VehicleError::invalid(
            "hydrodynamics",
            format!("the program's input `{name}` is not set"),
        )
    })
}

/// The vehicle as a model like the catalog's: its state and input, the proved program as
/// `rhs`, its proved Jacobians, and the kinetic energy of the body and the fluid.
impl<T: SimdRealField + Copy> Model<T, 15, 2> for VehicleModel {
    const NAME: &'static str = "vehicle";
    const STATE: [&'static str; 15] = STATE;
    const INPUTS: [&'static str; 2] = INPUTS;
    const STATE_JACOBIAN: &'static [(usize, usize)] = &STATE_JACOBIAN;
    const INPUT_JACOBIAN: &'static [(usize, usize)] = &INPUT_JACOBIAN;

    /// The rates of the state with the fins moving at `input`: the proved program, and the
    /// fins' rates.
    fn rhs(&self, state: &[T; 15], input: &[T; 2]) -> [T; 15] {
        // The variables on the stack when they fit (the generator's state and up to eight
        // inputs), as the rates are: a call allocates nothing.
        let mut variables = [T::zero(); BODY + 8];
        let count = BODY + self.inputs.len();
        let mut rates = [T::zero(); 15];
        if count <= variables.len() {
            variables[..BODY].copy_from_slice(&state[..BODY]);
            for (variable, input) in variables[BODY..].iter_mut().zip(&self.inputs) {
                *variable = input.value(state);
            }
            (self.program).evaluate_into(
                &self.functions.rhs,
                &variables[..count],
                &mut rates[..BODY],
            );
        } else {
            let variables = self.variables(state);
            (self.program).evaluate_into(&self.functions.rhs, &variables, &mut rates[..BODY]);
        }
        rates[13] = input[0];
        rates[14] = input[1];
        rates
    }

    /// T = ½M|v + ω × r_G|² + ½ωᵀ I_G ω + ½νᵀM_Aν, the body's and the fluid's, in J: the
    /// program's proved form.
    fn kinetic_energy(&self, state: &[T; 15]) -> T {
        let variables = self.variables(state);
        (self
            .program
            .evaluate(&self.functions.kinetic_energy, &variables)
            .next())
        .unwrap_or_else(T::zero)
    }

    /// ∂f/∂x: the proved Jacobian program (see the module docs for |x| and the fins).
    fn state_jacobian(&self, state: &[T; 15], _input: &[T; 2]) -> [[T; 15]; 15] {
        self.jacobians(state).0
    }

    /// ∂f/∂δ̇: the fins' rates are the inputs.
    fn input_jacobian(&self, state: &[T; 15], _input: &[T; 2]) -> [[T; 2]; 15] {
        self.jacobians(state).1
    }
}
