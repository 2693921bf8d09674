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
//! Where the scene names the propeller's law, the program reads its ε as a control `n`
//! too, computed from u beside it ([`super::propeller`]), and ∂f/∂x adds ∂f/∂ε · ∂ε/∂u to
//! the column of u. Where the scene gives a cross-flow drag, the program reads its loads as
//! the generator's applied loads `F_x` … `M_z`, computed beside it ([`super::cross_flow`]),
//! and ∂f/∂x adds ∂f/∂F · ∂F/∂ν to the velocities' columns.

use super::VehicleError;
use super::cross_flow::{CrossFlow, CrossFlowLoads};
use super::propeller::PropellerLaw;
use super::table::{CONTROLS, EPSILON, VehicleTable};
use crate::defined::engine::{
    FoldedComparison, InertiaAbout, Kinematics, Operations, Program, Propeller, System, Units,
    VEHICLE_LOADS as LOADS, VEHICLE_PRIME_SCALES as PRIME_SCALES, VehicleSpec, folded_comparison,
    prove_with_jacobians, vehicle,
};
use crate::defined::{Derivations, Functions, Interpreter, Source, Variables, coefficient_values};
use crate::models::Model;
use simba::simd::SimdRealField;
use std::collections::BTreeMap;
use std::sync::Arc;

/// The state: the generator's thirteen, then the rudder's and the stern planes' angles (rad).
pub const STATE: [&str; 15] = [
    "u", "v", "w", "p", "q", "r", "x", "y", "z", "q0", "q1", "q2", "q3", "dr", "ds",
];

/// The inputs: the fins' rates (rad/s), which the steering gear sets.
pub const INPUTS: [&str; 2] = ["dr_rate", "ds_rate"];

/// The number of the generator's state entries (before the fins').
const BODY: usize = 13;

/// The most program inputs a model computes beside the state: the propeller law's ε and the
/// six applied loads.
const COMPUTED: usize = 1 + 6;

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

/// The state of the Euler-angle twin (the table derived with Euler-angle kinematics): ν, the
/// position, the roll, pitch and heading angles of 4.57–4.60, then the fins' angles.
pub const EULER_STATE: [&str; 14] = [
    "u", "v", "w", "p", "q", "r", "x", "y", "z", "phi", "theta", "psi", "dr", "ds",
];

/// A vehicle's proved program, ready to evaluate.
#[derive(Debug, Clone)]
pub struct VehicleModel {
    proved: Proved,
    terms: usize,
    folded: Vec<FoldedComparison>,
}

/// A table's proved program in one kinematics, evaluated on a state laid out as the
/// generator's (ν, the position, the attitude) followed by the fins' angles: the quaternion
/// model runs, and the Euler-angle twin is what the linearisation reads (`super::linear`).
#[derive(Debug, Clone)]
pub(crate) struct Proved {
    program: Interpreter,
    functions: Functions,
    /// For each program input, what it is.
    inputs: Vec<Variable>,
    /// The program inputs computed beside the state at each call (ε, the applied loads), in
    /// the order the program reads them: the others are read from the state where they lie.
    computed: Vec<Variable>,
    /// The cross-flow drag, whose loads the program reads as its applied loads.
    cross_flow: Option<CrossFlow>,
    /// The number of the generator's state entries (before the fins').
    body: usize,
    operations: Operations,
}

/// A program input, by what the model sets it from.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Variable {
    /// A fin's angle: the state entry.
    Fin(usize),
    /// |x| of the state entry.
    Absolute(usize),
    /// The propeller law's ε at the surge speed u (the state's first entry).
    Epsilon(PropellerLaw),
    /// An applied load about O (`F_x` … `M_z`, by its index): the cross-flow drag's.
    Load(usize),
}

/// The spec of a table: `kinematics`, the inertia about the table's point with the products
/// it gives (the zero ones pruned), the fins as controls, the propeller constant, the table's
/// units.
pub fn spec(table: &VehicleTable, kinematics: Kinematics) -> VehicleSpec {
    VehicleSpec {
        units: if table.prime.is_some() {
            Units::Prime
        } else {
            Units::Dimensional
        },
        kinematics,
        inertia: table.inertia_about,
        symmetry: table.symmetry(),
        convention: table.convention,
        controls: controls(table),
        added_mass: table.added_mass.keys().cloned().collect(),
        added_mass_coriolis: table.added_mass_coriolis,
        terms: table.coefficients.keys().cloned().collect(),
        propeller: if table.propeller.is_some() {
            Propeller::Constant
        } else {
            Propeller::None
        },
        hydrostatics: true,
        applied_loads: table.cross_flow.is_some(),
    }
}

/// The controls the table's terms may hold: the fins, and ε where the scene names the
/// propeller's law.
fn controls(table: &VehicleTable) -> Vec<String> {
    let mut controls = CONTROLS.map(String::from).to_vec();
    if table.propeller_law().is_some() {
        controls.push(EPSILON.to_owned());
    }
    controls
}

/// Every parameter of `spec`'s proved program by its symbol, as the model fills them from
/// `table`: the body, the added mass, the propeller, the table's terms, and the inverse of the
/// total mass matrix (`minv_*`). What a program emitted from the same spec for a user's
/// `build.rs` needs (its `Parameters::from_symbols`) to compute what the model computes.
pub fn parameter_values(
    spec: &VehicleSpec,
    table: &VehicleTable,
) -> Result<BTreeMap<String, f64>, VehicleError> {
    let mut values = table_values(spec, table)?;
    values.extend(spec.inverse_mass_matrix(&values)?);
    Ok(values)
}

/// Every parameter's value by its symbol, as the spec names them, without the inverse mass
/// matrix.
fn table_values(
    spec: &VehicleSpec,
    table: &VehicleTable,
) -> Result<BTreeMap<String, f64>, VehicleError> {
    let mut values = BTreeMap::new();
    values.insert("M".to_owned(), table.mass);
    values.extend(inertia_values(spec, table));
    for (i, axis) in ["x", "y", "z"].into_iter().enumerate() {
        values.insert(format!("{axis}_G"), table.centre_of_gravity[i]);
        values.insert(format!("{axis}_B"), table.centre_of_buoyancy[i]);
    }
    values.insert("weight".to_owned(), table.weight);
    values.insert("buoyancy".to_owned(), table.buoyancy);
    if let Some(prime) = table.prime {
        let [density, length] = PRIME_SCALES;
        values.insert(density.to_owned(), prime.density);
        values.insert(length.to_owned(), prime.length);
    }
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

/// The tensor's entries by the spec's symbols (`Ixx_G` … about G, `Ixx` … about O), the
/// products its symmetry prunes left out.
fn inertia_values(spec: &VehicleSpec, table: &VehicleTable) -> Vec<(String, f64)> {
    let suffix = match spec.inertia {
        InertiaAbout::Gravity => "_G",
        InertiaAbout::Origin => "",
    };
    let entries = [
        ("Ixx", 0, 0),
        ("Iyy", 1, 1),
        ("Izz", 2, 2),
        ("Ixy", 0, 1),
        ("Iyz", 1, 2),
        ("Ixz", 0, 2),
    ];
    (entries.into_iter())
        .filter(|(entry, _, _)| !spec.symmetry.pruned().contains(entry))
        .map(|(entry, r, c)| (format!("{entry}{suffix}"), table.inertia[r][c]))
        .collect()
}

/// What a table's values give a derived program: the program's inputs and where each is read,
/// the cross-flow drag, and the folded table against its added mass.
struct Resolved {
    inputs: Vec<Variable>,
    computed: Vec<Variable>,
    cross_flow: Option<CrossFlow>,
    body: usize,
    folded: Vec<FoldedComparison>,
}

impl Resolved {
    /// The proved model: `program` resolved into `interpreter`, run by `functions`.
    fn with(
        self,
        interpreter: Interpreter,
        functions: Functions,
        program: &Program,
    ) -> (Proved, Vec<FoldedComparison>) {
        let proved = Proved {
            functions,
            inputs: self.inputs,
            computed: self.computed,
            cross_flow: self.cross_flow,
            body: self.body,
            operations: program.operations(&program.rhs),
            program: interpreter,
        };
        (proved, self.folded)
    }
}

/// `program` (of `system`, derived from `spec`) resolved with `table`'s values: the mass matrix inverted (refusing
/// one that is not positive definite), the coefficients computed (refusing one that is not
/// finite), each input placed.
fn resolve(
    (spec, system, program): (&VehicleSpec, &System, &Program),
    table: &VehicleTable,
) -> Result<(Interpreter, Resolved), VehicleError> {
    let mut values = table_values(spec, table)?;
    let folded = folded_comparison(spec, &values)?;
    values.extend(spec.inverse_mass_matrix(&values)?);
    let coefficients = coefficient_values(system, program, &values);
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
    let body = system.state.len();
    let state: Vec<&str> = (system.state.iter().map(|s| s.as_ref()))
        .chain(["dr", "ds"])
        .collect();
    let law = table.propeller_law();
    let inputs = (system.inputs.iter())
        .map(|name| input_variable(name, &state, body, law))
        .collect::<Result<Vec<_>, _>>()?;
    let computed: Vec<Variable> = (inputs.iter().copied())
        .filter(|input| matches!(input, Variable::Epsilon(_) | Variable::Load(_)))
        .collect();
    if computed.len() > COMPUTED {
        return Err(VehicleError::invalid(
            "hydrodynamics",
            format!("the program reads {} computed inputs", computed.len()),
        ));
    }
    // The state's variables where they lie (a fin's angle too, and |x| of an entry), the
    // computed ones as `Proved::computed_values` lays them out.
    let position = |name: &str| {
        if let Some(i) = system.state.iter().position(|s| *s == name) {
            return Some(Source::State(i));
        }
        let input = inputs[system.inputs.iter().position(|s| *s == name)?];
        Some(match input {
            Variable::Fin(i) => Source::State(i),
            Variable::Absolute(i) => Source::Magnitude(i),
            Variable::Epsilon(_) | Variable::Load(_) => {
                Source::Computed(computed.iter().position(|c| *c == input)?)
            }
        })
    };
    let interpreter = Interpreter::new(program, &coefficients, position).map_err(|name| {
        VehicleError::invalid("hydrodynamics", format!("the program reads `{name}`"))
    })?;
    let resolved = Resolved {
        inputs,
        computed,
        cross_flow: table.cross_flow.clone(),
        body,
        folded,
    };
    Ok((interpreter, resolved))
}

/// A spec's six equations derived and proved, with the program compiled: what a table's values
/// do not change, kept per process ([`DERIVED`]) so that a table of the same terms (a Monte
/// Carlo's case, a sweep's) takes its values into it rather than being derived again.
struct Derived {
    spec: VehicleSpec,
    system: System,
    program: Program,
    /// Compiled once (the compiled code reads the coefficients at each call).
    functions: Functions,
}

/// The specs derived in this process.
static DERIVED: Derivations<VehicleSpec, Arc<Derived>> = Derivations::new();

impl Proved {
    /// The six equations with the table's terms in `kinematics`, derived and proved once per
    /// process for each spec (terms, units, inertia, symmetry, controls, propeller), the mass
    /// matrix inverted (refusing one that is not positive definite) and the program resolved
    /// with the table's values; with the folded table against its added mass.
    pub(crate) fn new(
        table: &VehicleTable,
        kinematics: Kinematics,
    ) -> Result<(Self, Vec<FoldedComparison>), VehicleError> {
        let spec = spec(table, kinematics);
        if let Some(derived) = DERIVED.get(&spec) {
            let derivation = (&derived.spec, &derived.system, &derived.program);
            let (interpreter, resolved) = resolve(derivation, table)?;
            return Ok(resolved.with(interpreter, derived.functions.clone(), &derived.program));
        }
        let (proved, derived) = Self::derive(table, kinematics)?;
        DERIVED.keep(spec, Arc::new(derived));
        Ok(proved)
    }

    /// The six equations with the table's terms derived, proved and compiled anew, whatever
    /// was derived before (see [`Proved::new`]), with what the derivation keeps for others.
    fn derive(
        table: &VehicleTable,
        kinematics: Kinematics,
    ) -> Result<((Self, Vec<FoldedComparison>), Derived), VehicleError> {
        let spec = spec(table, kinematics);
        let system = vehicle("vehicle", &spec)?;
        let program = prove_with_jacobians(&system)?;
        let (interpreter, resolved) = resolve((&spec, &system, &program), table)?;
        let functions = Functions::of(&program)
            .map_err(|what| VehicleError::invalid("hydrodynamics", format!("no {what}")))?
            .compile(&interpreter);
        let proved = resolved.with(interpreter, functions.clone(), &program);
        let derived = Derived {
            spec,
            system,
            program,
            functions,
        };
        Ok((proved, derived))
    }

    /// The number of the generator's state entries (before the fins').
    pub(crate) fn body(&self) -> usize {
        self.body
    }

    /// The cross-flow drag's loads at `state` (zero without it), with their derivatives.
    fn applied<T: SimdRealField + Copy>(&self, state: &[T]) -> CrossFlowLoads<T> {
        match &self.cross_flow {
            Some(hull) => hull.loads(&state[..6]),
            None => CrossFlowLoads {
                loads: [T::zero(); 6],
                by: [[T::zero(); 6]; 6],
            },
        }
    }

    /// The program inputs computed beside `state`, in the order of [`Proved::computed`]
    /// (none for a table without a propeller law or a cross-flow drag).
    fn computed_values<T: SimdRealField + Copy>(&self, state: &[T]) -> [T; COMPUTED] {
        let mut values = [T::zero(); COMPUTED];
        if !self.computed.is_empty() {
            let loads = match &self.cross_flow {
                Some(hull) => hull.forces(&state[..6]),
                None => [T::zero(); 6],
            };
            for (value, input) in values.iter_mut().zip(&self.computed) {
                *value = input.value(state, &loads);
            }
        }
        values
    }

    /// The rates of the generator's state entries into `rates`: the program reads `state`
    /// where it lies and writes `rates` in place, and a call allocates nothing.
    #[inline]
    fn rates_into<T: SimdRealField + Copy>(&self, state: &[T], rates: &mut [T]) {
        if self.computed.is_empty() {
            (self.program).evaluate_into(&self.functions.rhs, variables(state, &[]), rates);
        } else {
            self.rates_with_computed(state, rates);
        }
    }

    /// [`Proved::rates_into`] for a table whose program reads values computed beside the
    /// state (a propeller law, a cross-flow drag): out of line, so that the call of one that
    /// reads none (REMUS) stays small enough to be inlined into its caller.
    #[inline(never)]
    fn rates_with_computed<T: SimdRealField + Copy>(&self, state: &[T], rates: &mut [T]) {
        let computed = self.computed_values(state);
        (self.program).evaluate_into(&self.functions.rhs, variables(state, &computed), rates);
    }

    /// The rates of the generator's state entries.
    pub(crate) fn rates<T: SimdRealField + Copy>(
        &self,
        state: &[T],
    ) -> impl Iterator<Item = T> + use<'_, T> {
        let computed = self.computed_values(state);
        (self.program).evaluate(&self.functions.rhs, variables(state, &computed))
    }

    /// The kinetic energy of the body and the fluid.
    fn kinetic_energy<T: SimdRealField + Copy>(&self, state: &[T]) -> T {
        let computed = self.computed_values(state);
        let plan = &self.functions.kinetic_energy;
        (self
            .program
            .evaluate(plan, variables(state, &computed))
            .next())
        .unwrap_or_else(T::zero)
    }

    /// ∂(rates)/∂(state), each entry that is not identically zero handed to `set` as (row,
    /// column, value), where a column may come more than once (its values add): the proved
    /// Jacobian programs scattered by their patterns, the program's ∂f/∂δ put in the fins'
    /// columns and the chain rule through |x| added.
    pub(crate) fn state_jacobian<T: SimdRealField + Copy>(
        &self,
        state: &[T],
        mut set: impl FnMut(usize, usize, T),
    ) {
        let applied = self.applied(state);
        let computed = self.computed_values(state);
        let entries = self
            .program
            .evaluate(&self.functions.state_jacobian, variables(state, &computed));
        for (&(row, column), value) in self.functions.state_pattern.iter().zip(entries) {
            set(row, column, value);
        }
        let entries = self
            .program
            .evaluate(&self.functions.input_jacobian, variables(state, &computed));
        for (&(row, column), value) in self.functions.input_pattern.iter().zip(entries) {
            match self.inputs[column] {
                Variable::Fin(i) => set(row, i, value),
                Variable::Absolute(i) => set(row, i, value * state[i].simd_signum()),
                Variable::Epsilon(law) => set(row, 0, value * law.epsilon(state[0]).by_u),
                Variable::Load(load) => {
                    for (velocity, by) in applied.by[load].iter().enumerate() {
                        set(row, velocity, value * *by);
                    }
                }
            }
        }
    }

    /// Where [`Self::state_jacobian`] can be non-zero, as (row, column).
    pub(crate) fn state_pattern(&self) -> Vec<(usize, usize)> {
        let through_inputs = (self.functions.input_pattern.iter()).flat_map(|&(row, column)| {
            let columns = match self.inputs[column] {
                Variable::Fin(i) | Variable::Absolute(i) => i..i + 1,
                Variable::Epsilon(_) => 0..1,
                Variable::Load(_) => 0..6,
            };
            columns.map(move |i| (row, i))
        });
        let mut pattern: Vec<(usize, usize)> = (self.functions.state_pattern.iter().copied())
            .chain(through_inputs)
            .collect();
        pattern.sort_unstable();
        pattern.dedup();
        pattern
    }
}

impl VehicleModel {
    /// The six equations with the table's terms, derived and proved once per process for each
    /// set of terms (a Monte Carlo's cases take their values into it), the mass matrix inverted
    /// (refusing one that is not positive definite), the program resolved.
    pub fn new(table: &VehicleTable) -> Result<Self, VehicleError> {
        let (proved, folded) = Proved::new(table, Kinematics::Quaternion)?;
        Ok(VehicleModel {
            proved,
            terms: table.coefficients.len(),
            folded,
        })
    }

    /// The same model derived, proved and compiled anew, whatever this process derived before
    /// ([`VehicleModel::new`] derives each set of terms once and takes another table's values
    /// into it): the reference that reuse is checked against.
    pub fn derive(table: &VehicleTable) -> Result<Self, VehicleError> {
        let ((proved, folded), _) = Proved::derive(table, Kinematics::Quaternion)?;
        Ok(VehicleModel {
            proved,
            terms: table.coefficients.len(),
            folded,
        })
    }

    /// ∂f/∂x and ∂f/∂δ̇ of the model, dense (see [`Proved::state_jacobian`]); the fins'
    /// rates are the inputs.
    fn jacobians<T: SimdRealField + Copy>(&self, state: &[T; 15]) -> ([[T; 15]; 15], [[T; 2]; 15]) {
        let mut by_state = [[T::zero(); 15]; 15];
        self.proved
            .state_jacobian(state, |row, column, value| by_state[row][column] += value);
        let mut by_input = [[T::zero(); 2]; 15];
        by_input[13][0] = T::one();
        by_input[14][1] = T::one();
        (by_state, by_input)
    }

    /// What one call costs, as the emitter counts it.
    pub fn operations(&self) -> Operations {
        self.proved.operations
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
        self.proved.functions.is_compiled()
    }

    /// The same model evaluated by the interpreter of its proved program: the reference the
    /// compiled code is checked against, bit for bit.
    pub fn interpreted(&self) -> VehicleModel {
        let mut model = self.clone();
        model.proved.functions = self.proved.functions.interpreted();
        model
    }

    /// The same model with its proved program compiled to machine code (the interpreter's
    /// when the program cannot be compiled): what [`VehicleModel::new`] builds.
    pub fn compiled(&self) -> VehicleModel {
        let mut model = self.clone();
        model.proved.functions = (self.proved.functions.clone()).compile(&self.proved.program);
        model
    }
}

/// What the program reads: `state`, and the inputs `computed` beside it.
fn variables<'a, T>(state: &'a [T], computed: &'a [T]) -> Variables<'a, T> {
    Variables { state, computed }
}

impl Variable {
    /// Its value at `state`, where the applied loads are `loads`.
    fn value<T: SimdRealField + Copy>(self, state: &[T], loads: &[T; 6]) -> T {
        match self {
            Variable::Fin(i) => state[i],
            Variable::Absolute(i) => state[i].simd_abs(),
            Variable::Epsilon(law) => law.epsilon(state[0]).value,
            Variable::Load(load) => loads[load],
        }
    }
}

/// What the program's input `name` is set from, in a state named `state` whose first `body`
/// entries are the generator's (u first), with the propeller's `law` if the scene names one.
fn input_variable(
    name: &str,
    state: &[&str],
    body: usize,
    law: Option<PropellerLaw>,
) -> Result<Variable, VehicleError> {
    let index = |x: &str| state.iter().position(|s| *s == x);
    let found = match name.strip_prefix("abs_") {
        Some(x) => index(x).filter(|&i| i < 6).map(Variable::Absolute),
        None if name == EPSILON => law.filter(|_| state[0] == "u").map(Variable::Epsilon),
        None if LOADS.contains(&name) => LOADS.iter().position(|l| *l == name).map(Variable::Load),
        None => index(name).filter(|&i| i >= body).map(Variable::Fin),
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
    #[inline]
    fn rhs(&self, state: &[T; 15], input: &[T; 2]) -> [T; 15] {
        let mut rates = [T::zero(); 15];
        self.proved.rates_into(state, &mut rates[..BODY]);
        rates[13] = input[0];
        rates[14] = input[1];
        rates
    }

    /// T = ½M|v + ω × r_G|² + ½ωᵀ I_G ω + ½νᵀM_Aν, the body's and the fluid's, in J: the
    /// program's proved form.
    fn kinetic_energy(&self, state: &[T; 15]) -> T {
        self.proved.kinetic_energy(state)
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
