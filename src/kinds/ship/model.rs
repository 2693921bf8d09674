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
//! rule through U (∂f/∂U · u/U and · v/U) to the program's ∂f/∂u and ∂f/∂v. A ship with a
//! propulsion model has the propeller rate n as its second input, and the program reads beside
//! U what this model computes from u and n ([`super::propulsion`]): |n|, the induced velocity
//! u_A and the rudder's inflow speed c; the Jacobians add the chain rule through them, into
//! ∂f/∂u and ∂f/∂n. A ship without one reads n nowhere.
//!
//! An MMG ship (the MMG form of `eom_codegen::model::ship`) reads beside U the propeller's and
//! the rudder's loads X_a, Y_a, N_a, which [`super::mmg::MmgShip`] computes from (u, v, r, δ,
//! n) in f64, lane by lane for a SIMD scalar; its Jacobians add ∂f/∂(X_a, Y_a, N_a) times
//! their dual-number derivatives, into ∂f/∂(u, v, r, δ) and ∂f/∂n. Outside the paper's model
//! (a ship going astern, the propeller stopped) the loads are NaN, and the run says why
//! ([`crate::integrate::IntegrateError::OutsideModel`]).
//!
//! A ship with a [`super::wind::Windage`] reads the wind's loads the same way, added to an MMG
//! ship's or alone ([`super::wind::ShipWind::loads`]): they are of u, v and the heading ψ (the
//! wind is fixed in space) and of the gust g, the model's third input, so its ∂f/∂x gains
//! entries in ψ's column and its ∂f/∂g a column.

use super::ShipError;
use super::mmg::MmgShip;
use super::propulsion::Propulsion;
use super::table::ShipTable;
use super::wind::ShipWind;
use crate::defined::engine::{
    ADDED_MASS, APPLIED_LOADS, CURRENT_INPUTS, EmitError, MMG_ADDED_MASS, MMG_SCALES, Operations,
    PRIME_SCALES, PROPULSION, Program, ShipSpec, Units, prove_with_jacobians, ship,
};
use crate::defined::{
    CoefficientFormulas, Derivations, Functions, Interpreter, Plan, Source, Variables,
};
use crate::models::Model;
use simba::simd::SimdRealField;

use std::sync::Arc;

/// The state: u, v, r (m/s, m/s, rad/s, body axes at midship), X, Y (m, midship in space
/// axes), ψ (rad), δ (rad, the rudder angle).
pub const STATE: [&str; 7] = ["u", "v", "r", "X", "Y", "psi", "delta"];

/// The inputs: the rudder's rate δ̇ (rad/s), which the steering gear sets
/// ([`crate::manoeuvring::steering`]); the propeller rate n (rev/s), which the engine's command
/// sets ([`super::propulsion`]; read only by a ship with a propulsion model or an MMG ship's);
/// the gust g (m/s), the wind's speed less its mean ([`super::wind::gust`]; read only by a ship
/// with a windage, zero where the wind does not gust).
pub const INPUTS: [&str; 3] = ["delta_rate", "n", "wind_gust"];

/// The program's variables this model sets beside the state, in the order of
/// [`ShipModel::computed`]: δ̇, U, then what propulsion reads, then an MMG ship's applied
/// loads (or the wind's, or both's sum). The state's are read where they lie.
const COMPUTED: [&str; 11] = [
    "delta_rate",
    "U",
    "n",
    "n_abs",
    "u_A",
    "c",
    APPLIED_LOADS[0],
    APPLIED_LOADS[1],
    APPLIED_LOADS[2],
    CURRENT_INPUTS[0],
    CURRENT_INPUTS[1],
];

/// Where a current's components lie in [`COMPUTED`].
const CURRENT: usize = 9;

/// Where the applied loads (an MMG ship's propeller and rudder, the wind) lie in [`COMPUTED`].
const APPLIED: usize = 6;

/// Where the rates can depend on the state, for any table: u̇, v̇, ṙ on u, v, r and δ (the
/// terms in U of a prime table are in u and v) and, in a wind, on ψ; Ẋ, Ẏ on u, v, ψ (4.44);
/// ψ̇ on r; δ̇ on none. A table without a term in some entry makes that entry's derivative zero
/// at every state.
#[rustfmt::skip]
const STATE_JACOBIAN: [(usize, usize); 22] = [
    (0, 0), (0, 1), (0, 2), (0, 5), (0, 6),
    (1, 0), (1, 1), (1, 2), (1, 5), (1, 6),
    (2, 0), (2, 1), (2, 2), (2, 5), (2, 6),
    (3, 0), (3, 1), (3, 5),
    (4, 0), (4, 1), (4, 5),
    (5, 2),
];

/// δ̇ is the rudder's rate itself; u̇, v̇, ṙ depend on n through the thrust law and c, and on
/// the gust through the wind's loads.
#[rustfmt::skip]
const INPUT_JACOBIAN: [(usize, usize); 7] =
    [(0, 1), (0, 2), (1, 1), (1, 2), (2, 1), (2, 2), (6, 0)];

/// A ship's proved program, ready to evaluate.
#[derive(Debug, Clone)]
pub struct ShipModel {
    program: Interpreter,
    functions: Functions,
    /// What each of the program's inputs is, by its column.
    inputs: Vec<ProgramInput>,
    /// Whether the program reads U (a prime table): asked at every call, so kept apart.
    reads_speed: bool,
    propulsion: Option<Propulsion>,
    /// An MMG ship's propeller and rudder, whose loads the program reads.
    mmg: Option<MmgShip>,
    /// The current's north and east components, m/s, for a ship in one.
    current: Option<[f64; 2]>,
    /// The air on a ship with a windage: its coefficients, the wind, the current it drifts in.
    wind: Option<Arc<ShipWind>>,
    /// What the table's values do not change, shared by the models of other values.
    proved: Arc<Proved>,
    operations: Operations,
    terms: usize,
}

/// One input of the proved program, and how the model's Jacobians take it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum ProgramInput {
    /// δ̇, the model's first input.
    RudderRate,
    /// U = √(u² + v²).
    Speed,
    /// n, the model's second input.
    Rate,
    /// |n|.
    RateMagnitude,
    /// u_A(u, n).
    Induced,
    /// c(u, n).
    Inflow,
    /// An applied load X, Y or N (by its index): an MMG ship's, of (u, v, r, δ, n), and the
    /// wind's, of (u, v, ψ, g).
    Applied(usize),
    /// A current's north or east component: a constant.
    Current,
}

/// The table's terms, 4.46 with them and its proved program: the same for every value of the
/// coefficients.
#[derive(Debug)]
struct Proved {
    spec: ShipSpec,
    program: Program,
    /// The program's coefficients as formulas of the table's values.
    formulas: CoefficientFormulas,
    /// Where each of the formulas' parameters is among a table's values as [`parameters`]
    /// lists them for this spec (the last entry of its symbol), or `None` for one a table of
    /// the spec does not give (NaN): found once, so that another table's values are taken in
    /// by position.
    places: Vec<Option<usize>>,
}

/// The terms of `table`, its units, where its yaw inertia is taken and whether it has a
/// propulsion model.
fn spec_of(table: &ShipTable) -> ShipSpec {
    ShipSpec {
        units: table.units,
        yaw_inertia: table.body.yaw_inertia_about,
        terms: table.terms.keys().copied().collect(),
        propulsion: table.propulsion.is_some(),
        form: table.form(),
        current: table.current.is_some(),
        applied: table.windage.is_some(),
    }
}

/// The models derived in this process, one per set of terms, units, yaw-inertia convention
/// and propulsion: what [`ShipModel::new`] takes another table's values into.
static PROVED_MODELS: Derivations<ShipSpec, ShipModel> = Derivations::new();

impl ShipModel {
    /// The model of the table: 4.46 with its terms derived, solved and proved (with its
    /// Jacobians) and compiled once per process for each set of terms, units, yaw-inertia
    /// convention and propulsion, the table's values then taken in as
    /// [`ShipModel::with_table`] takes them. A scene read again with other values (each case
    /// of a sweep or of a Monte Carlo) reuses the proof; [`ShipModel::derive`] derives anew.
    pub fn new(table: &ShipTable) -> Result<Self, ShipError> {
        let spec = spec_of(table);
        if let Some(model) = PROVED_MODELS.get(&spec) {
            return model.with_table(table);
        }
        let model = Self::derive(table)?;
        let kept = PROVED_MODELS.keep(spec, model.clone());
        match kept.shares_proof_with(&model) {
            true => Ok(model),
            // Another thread derived the same terms meanwhile: its proof is the one shared.
            false => kept.with_table(table),
        }
    }

    /// Derives, solves and proves 4.46 with the table's terms, then resolves the program,
    /// whatever was derived before (see [`ShipModel::new`]).
    pub fn derive(table: &ShipTable) -> Result<Self, ShipError> {
        let spec = spec_of(table);
        let system = ship("ship", &spec).map_err(|e| ShipError::Build(EmitError::Model(e)))?;
        let program = prove_with_jacobians(&system)?;
        let functions = Functions::of(&program)
            .map_err(|what| ShipError::invalid("hydrodynamics", format!("no {what}")))?;
        let inputs: Vec<ProgramInput> = system
            .inputs
            .iter()
            .map(|name| match *name {
                "delta_rate" => Ok(ProgramInput::RudderRate),
                "U" => Ok(ProgramInput::Speed),
                "n" => Ok(ProgramInput::Rate),
                "n_abs" => Ok(ProgramInput::RateMagnitude),
                "u_A" => Ok(ProgramInput::Induced),
                "c" => Ok(ProgramInput::Inflow),
                other if CURRENT_INPUTS.contains(&other) => Ok(ProgramInput::Current),
                other if APPLIED_LOADS.contains(&other) => Ok(ProgramInput::Applied(
                    APPLIED_LOADS.iter().position(|l| *l == other).unwrap_or(0),
                )),
                other => Err(ShipError::invalid(
                    "hydrodynamics",
                    format!("the program has an input `{other}` no ship computes"),
                )),
            })
            .collect::<Result<_, _>>()?;
        let formulas = CoefficientFormulas::new(&system, &program);
        let (names, _) = parameters(&spec, table, true);
        let places = (formulas.parameters().iter())
            .map(|symbol| names.iter().rposition(|name| name == symbol))
            .collect();
        let proved = Proved {
            formulas,
            places,
            spec,
            program,
        };
        let interpreter = interpreter(&proved, &coefficients(&proved, table))?;
        Ok(ShipModel {
            functions: functions.compile(&interpreter),
            reads_speed: inputs.contains(&ProgramInput::Speed),
            inputs,
            propulsion: table.propulsion,
            mmg: table.mmg,
            current: table.current.map(|c| c.components()),
            wind: table.ship_wind().map(Arc::new),
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
            propulsion: table.propulsion,
            mmg: table.mmg,
            current: table.current.map(|c| c.components()),
            wind: table.ship_wind().map(Arc::new),
            ..self.clone()
        })
    }

    /// The program's variables set beside `state` under `input` (δ̇, n), in [`COMPUTED`]'s
    /// order: δ̇, U (zero where the program does not read it: a table in SI), and what a
    /// propulsion model computes (zero without one).
    #[inline]
    fn computed<T: SimdRealField + Copy>(&self, state: &[T; 7], input: &[T; 3]) -> [T; 11] {
        let mut computed = [T::zero(); 11];
        self.compute(state, input, &mut computed);
        computed
    }

    /// [`ShipModel::computed`] into `computed`, which holds zeros: a call of `rhs` sets its
    /// values where the compiled code reads them, not in a temporary moved there.
    #[inline]
    fn compute<T: SimdRealField + Copy>(
        &self,
        state: &[T; 7],
        input: &[T; 3],
        computed: &mut [T; 11],
    ) {
        computed[0] = input[0];
        if self.reads_speed {
            computed[1] = (state[0] * state[0] + state[1] * state[1]).simd_sqrt();
        }
        if let Some(propulsion) = &self.propulsion {
            propelled(propulsion, state, input, computed);
        }
        if let Some(mmg) = &self.mmg {
            mmg_applied(mmg, state, input, computed);
        }
        if let Some(wind) = &self.wind {
            wind_applied(wind, state, input, computed);
        }
        if let Some([north, east]) = self.current {
            computed[CURRENT] = T::from_subset(&north);
            computed[CURRENT + 1] = T::from_subset(&east);
        }
    }

    /// The outputs of `plan` at `state` under `input` (δ̇, n).
    fn evaluate<'a, T: SimdRealField + Copy>(
        &self,
        plan: &'a Plan,
        state: &[T; 7],
        input: &[T; 3],
    ) -> impl Iterator<Item = T> + use<'a, T> {
        let computed = self.computed(state, input);
        let variables = Variables {
            state,
            computed: &computed,
        };
        (self.program).evaluate(plan, variables)
    }

    /// ∂f/∂x and ∂f/∂(δ̇, n) of the model, dense: the proved Jacobian programs scattered by
    /// their patterns, with the chain rule through what the model computes (U, |n|, u_A, c).
    fn jacobians<T: SimdRealField + Copy>(
        &self,
        state: &[T; 7],
        input: &[T; 3],
    ) -> ([[T; 7]; 7], [[T; 3]; 7]) {
        let mut by_state = [[T::zero(); 7]; 7];
        let entries = self.evaluate(&self.functions.state_jacobian, state, input);
        for (&(row, column), value) in self.functions.state_pattern.iter().zip(entries) {
            by_state[row][column] = value;
        }
        let mut by_input = [[T::zero(); 3]; 7];
        let speed = (state[0] * state[0] + state[1] * state[1]).simd_sqrt();
        let inflow = self.propulsion.map(|p| p.inflow(state[0], input[1]));
        let applied_by = self.mmg.map(|mmg| mmg_applied_by(&mmg, state, input));
        let wind_by = (self.wind.as_deref()).map(|wind| wind_applied_by(wind, state, input));
        let entries = self.evaluate(&self.functions.input_jacobian, state, input);
        for (&(row, column), value) in self.functions.input_pattern.iter().zip(entries) {
            // (∂/∂u, ∂/∂n) of the input, where it is one the model computes.
            let through = |by: [T; 2], by_state: &mut [[T; 7]; 7], by_input: &mut [[T; 3]; 7]| {
                by_state[row][0] += value * by[0];
                by_input[row][1] += value * by[1];
            };
            match (self.inputs[column], inflow) {
                (ProgramInput::RudderRate, _) => by_input[row][0] = value,
                (ProgramInput::Speed, _) => {
                    // ∂U/∂u = u/U, ∂U/∂v = v/U.
                    by_state[row][0] += value * (state[0] / speed);
                    by_state[row][1] += value * (state[1] / speed);
                }
                (ProgramInput::Rate, _) => by_input[row][1] += value,
                (ProgramInput::RateMagnitude, _) => {
                    by_input[row][1] += value * input[1].simd_signum();
                }
                (ProgramInput::Induced, Some(inflow)) => {
                    through(inflow.induced_by, &mut by_state, &mut by_input);
                }
                (ProgramInput::Inflow, Some(inflow)) => {
                    through(inflow.speed_by, &mut by_state, &mut by_input);
                }
                (ProgramInput::Induced | ProgramInput::Inflow, None) => {}
                // A constant: no derivative.
                (ProgramInput::Current, _) => {}
                (ProgramInput::Applied(load), _) => {
                    // ∂/∂(u, v, r, δ) into the state's columns, ∂/∂n into the rate's.
                    if let Some(by) = &applied_by {
                        for (variable, column) in [0, 1, 2, 6].into_iter().enumerate() {
                            by_state[row][column] += value * by[load][variable];
                        }
                        by_input[row][1] += value * by[load][4];
                    }
                    // ∂/∂(u, v, ψ) into the state's columns, ∂/∂g into the gust's.
                    if let Some(by) = &wind_by {
                        for (variable, column) in [0, 1, 5].into_iter().enumerate() {
                            by_state[row][column] += value * by[load][variable];
                        }
                        by_input[row][2] += value * by[load][3];
                    }
                }
            }
        }
        (by_state, by_input)
    }

    /// Whether this model runs the very program `other` runs, derived and proved once for
    /// both ([`ShipModel::new`] of tables of the same terms, [`ShipModel::with_table`]).
    pub fn shares_proof_with(&self, other: &ShipModel) -> bool {
        Arc::ptr_eq(&self.proved, &other.proved)
    }

    /// The propulsion model, for a ship that has one.
    pub fn propulsion(&self) -> Option<&Propulsion> {
        self.propulsion.as_ref()
    }

    /// The propeller rate at the approach, n₀ (rev/s): the model's second input on the
    /// straight course at U₀; zero for a ship without a propulsion model.
    pub fn approach_rate(&self) -> f64 {
        match (&self.propulsion, &self.mmg) {
            (Some(p), _) => p.approach_rate,
            (None, Some(mmg)) => mmg.approach_rate,
            (None, None) => 0.0,
        }
    }

    /// An MMG ship's propeller and rudder, for a ship of that form.
    pub fn mmg(&self) -> Option<&MmgShip> {
        self.mmg.as_ref()
    }

    /// The current's north and east components, m/s, for a ship in one.
    pub fn current(&self) -> Option<[f64; 2]> {
        self.current
    }

    /// The air on a ship with a windage: its coefficients, the wind, the current.
    pub fn wind(&self) -> Option<&ShipWind> {
        self.wind.as_deref()
    }

    /// The same ship in calm air: the wind's loads left out (an MMG ship's propeller and
    /// rudder kept), what the linear model about the straight course is of.
    pub fn calm(&self) -> ShipModel {
        ShipModel {
            wind: None,
            ..self.clone()
        }
    }

    /// Whether the track drifts: the ship is in a current, or feels a wind.
    pub fn drifts(&self) -> bool {
        self.current.is_some() || self.wind.as_ref().is_some_and(|w| w.wind.speed > 0.0)
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

/// What `propulsion` sets beside the state (n, |n|, u_A, c, after δ̇ and U): out of line, so
/// that the call of a ship without one stays small enough to be inlined into its caller.
#[inline(never)]
fn propelled<T: SimdRealField + Copy>(
    propulsion: &Propulsion,
    state: &[T; 7],
    input: &[T; 3],
    computed: &mut [T; 11],
) {
    let inflow = propulsion.inflow(state[0], input[1]);
    computed[2] = input[1];
    computed[3] = input[1].simd_abs();
    computed[4] = inflow.induced;
    computed[5] = inflow.speed;
}

/// Lane `lane` of `value`, in f64.
fn lane_of<T: SimdRealField + Copy>(value: T, lane: usize) -> f64 {
    T::splat(value.extract(lane)).to_subset_unchecked()
}

/// `value` into lane `lane` of `into`.
fn set_lane<T: SimdRealField + Copy>(into: &mut T, lane: usize, value: f64) {
    into.replace(lane, T::from_subset(&value).extract(0));
}

/// (u, v, r, δ, n) of lane `lane`: what an MMG ship's applied loads are of.
fn mmg_variables<T: SimdRealField + Copy>(state: &[T; 7], input: &[T; 3], lane: usize) -> [f64; 5] {
    [state[0], state[1], state[2], state[6], input[1]].map(|x| lane_of(x, lane))
}

/// An MMG ship's applied loads (X_P + X_R, Y_R, N_R) into `computed`, lane by lane in f64;
/// NaN outside the paper's model (a ship going astern, the propeller stopped), which the run
/// reports with the reason ([`super::mmg::MmgShip::loads`]).
#[inline(never)]
fn mmg_applied<T: SimdRealField + Copy>(
    mmg: &MmgShip,
    state: &[T; 7],
    input: &[T; 3],
    computed: &mut [T; 11],
) {
    for lane in 0..T::LANES {
        let loads = mmg.loads(mmg_variables(state, input, lane));
        for (k, load) in loads.unwrap_or([f64::NAN; 3]).into_iter().enumerate() {
            set_lane(&mut computed[APPLIED + k], lane, load);
        }
    }
}

/// The derivatives of an MMG ship's applied loads by (u, v, r, δ, n), lane by lane.
fn mmg_applied_by<T: SimdRealField + Copy>(
    mmg: &MmgShip,
    state: &[T; 7],
    input: &[T; 3],
) -> [[T; 5]; 3] {
    by_lanes(|lane| {
        let applied = mmg.loads_with_derivatives(mmg_variables(state, input, lane));
        applied.map_or([[f64::NAN; 5]; 3], |a| a.by)
    })
}

/// Derivatives of the three applied loads computed lane by lane in f64 (`of_lane`), gathered
/// into the SIMD scalar's lanes.
fn by_lanes<T: SimdRealField + Copy, const N: usize>(
    of_lane: impl Fn(usize) -> [[f64; N]; 3],
) -> [[T; N]; 3] {
    let mut by = [[T::zero(); N]; 3];
    for lane in 0..T::LANES {
        for (row, values) in by.iter_mut().zip(of_lane(lane)) {
            for (entry, value) in row.iter_mut().zip(values) {
                set_lane(entry, lane, value);
            }
        }
    }
    by
}

/// (u, v, ψ) and g of lane `lane`: what the wind's loads are of.
fn wind_variables<T: SimdRealField + Copy>(
    state: &[T; 7],
    input: &[T; 3],
    lane: usize,
) -> ([f64; 3], f64) {
    let of = |x| lane_of(x, lane);
    ([of(state[0]), of(state[1]), of(state[5])], of(input[2]))
}

/// The wind's loads added into `computed`'s applied loads, lane by lane in f64.
#[inline(never)]
fn wind_applied<T: SimdRealField + Copy>(
    wind: &ShipWind,
    state: &[T; 7],
    input: &[T; 3],
    computed: &mut [T; 11],
) {
    for lane in 0..T::LANES {
        let (velocity, gust) = wind_variables(state, input, lane);
        let loads = wind.loads(velocity, gust).loads;
        for (k, load) in loads.into_iter().enumerate() {
            let sum = lane_of(computed[APPLIED + k], lane) + load;
            set_lane(&mut computed[APPLIED + k], lane, sum);
        }
    }
}

/// The derivatives of the wind's loads by (u, v, ψ, g), lane by lane.
fn wind_applied_by<T: SimdRealField + Copy>(
    wind: &ShipWind,
    state: &[T; 7],
    input: &[T; 3],
) -> [[T; 4]; 3] {
    by_lanes(|lane| {
        let (velocity, gust) = wind_variables(state, input, lane);
        wind.loads(velocity, gust).by
    })
}

/// The hoisted coefficients of the proved program with `table`'s values.
fn coefficients(proved: &Proved, table: &ShipTable) -> Vec<f64> {
    let (_, values) = parameters(&proved.spec, table, false);
    let known = (proved.places.iter())
        .map(|place| place.map_or(f64::NAN, |at| values[at]))
        .collect();
    proved.formulas.values_of(known)
}

/// The proved program resolved with the `coefficients`' values.
fn interpreter(proved: &Proved, coefficients: &[f64]) -> Result<Interpreter, ShipError> {
    // The state's variables where they lie, the others as `ShipModel::computed` lays them out.
    let position = |name: &str| {
        let index = |names: &[&str]| names.iter().position(|s| *s == name);
        (index(&STATE).map(Source::State)).or_else(|| index(&COMPUTED).map(Source::Computed))
    };
    Interpreter::new(&proved.program, coefficients, position)
        .map_err(|name| ShipError::invalid("hydrodynamics", format!("the program reads `{name}`")))
}

/// Every parameter's value by its symbol, as the table gives it; the symbols are the spec's:
/// what [`coefficients`] takes by position, kept as the reference its test holds it to.
#[cfg(test)]
fn parameter_values(spec: &ShipSpec, table: &ShipTable) -> std::collections::BTreeMap<String, f64> {
    let (names, values) = parameters(spec, table, true);
    // A symbol given twice takes its last value.
    names.into_iter().zip(values).collect()
}

/// Every parameter's value as the table gives it, in an order that depends on the spec
/// alone: the body's, the added mass, the prime system's scales, the propulsion's, then each
/// term's; with their symbols where `named` (building them costs more than the values).
fn parameters(spec: &ShipSpec, table: &ShipTable, named: bool) -> (Vec<String>, Vec<f64>) {
    let mut names: Vec<String> = Vec::new();
    let mut values: Vec<f64> = Vec::new();
    let mut give = |symbol: &dyn Fn() -> String, value: f64| {
        if named {
            names.push(symbol());
        }
        values.push(value);
    };
    let body = [table.body.mass, table.body.yaw_inertia, table.body.x_g];
    for (symbol, value) in spec.body_symbols().into_iter().zip(body) {
        give(&|| symbol.to_owned(), value);
    }
    if let Some(mmg) = &table.mmg {
        let p = &mmg.parameters;
        let added = [p.added_mass.surge, p.added_mass.sway, p.added_mass.yaw];
        let ship = &p.particulars;
        let scales = [ship.density, ship.length, ship.draft];
        let given = MMG_ADDED_MASS.into_iter().zip(added);
        for (symbol, value) in given.chain(MMG_SCALES.into_iter().zip(scales)) {
            give(&|| symbol.to_owned(), value);
        }
        for (term, value) in &table.terms {
            give(&|| term.symbol(), *value);
        }
        return (names, values);
    }
    for (symbol, value) in ADDED_MASS.into_iter().zip(table.added_mass) {
        give(&|| symbol.to_owned(), value);
    }
    if table.units == Units::Prime {
        let scales = [
            table.density.unwrap_or(f64::NAN),
            table.length.unwrap_or(f64::NAN),
            table.design_speed,
        ];
        for (symbol, value) in PRIME_SCALES.into_iter().zip(scales) {
            give(&|| symbol.to_owned(), value);
        }
    }
    if let Some(p) = &table.propulsion {
        let length = table.length.unwrap_or(f64::NAN);
        let [t_uu, t_un, t_nn] = p.thrust;
        let given = [
            p.rudder_position,
            p.approach_inflow,
            t_uu,
            t_un,
            t_nn,
            p.resistance_prime(length),
        ];
        for (symbol, value) in PROPULSION.into_iter().zip(given) {
            give(&|| symbol.to_owned(), value);
        }
    }
    for (term, value) in &table.terms {
        give(&|| term.symbol(), *value);
    }
    (names, values)
}

/// The ship as a model like the catalog's: its state and inputs, the proved program as `rhs`,
/// its proved Jacobians, and the rigid body's kinetic energy.
impl<T: SimdRealField + Copy> Model<T, 7, 3> for ShipModel {
    const NAME: &'static str = "ship";
    const STATE: [&'static str; 7] = STATE;
    const INPUTS: [&'static str; 3] = INPUTS;
    const STATE_JACOBIAN: &'static [(usize, usize)] = &STATE_JACOBIAN;
    const INPUT_JACOBIAN: &'static [(usize, usize)] = &INPUT_JACOBIAN;

    /// The rates of the state with the rudder moving at `input[0]` and the propeller turning
    /// at `input[1]`: the proved program.
    #[inline]
    fn rhs(&self, state: &[T; 7], input: &[T; 3]) -> [T; 7] {
        let mut computed = [T::zero(); 11];
        self.compute(state, input, &mut computed);
        let variables = Variables {
            state,
            computed: &computed,
        };
        let mut rates = [T::zero(); 7];
        (self.program).evaluate_into(&self.functions.rhs, variables, &mut rates);
        rates
    }

    /// The rigid body's kinetic energy ½M(u² + (v + x_G r)²) + ½I_z r² (4.32 about G, with
    /// I_z about G), in J (a prime table's body scaled to SI), the program's proved form; the
    /// fluid's share (the added mass) is not in it.
    fn kinetic_energy(&self, state: &[T; 7]) -> T {
        (self
            .evaluate(&self.functions.kinetic_energy, state, &[T::zero(); 3])
            .next())
        .unwrap_or_else(T::zero)
    }

    /// ∂f/∂x: the proved Jacobian program (see the module docs for U, u_A and c).
    fn state_jacobian(&self, state: &[T; 7], input: &[T; 3]) -> [[T; 7]; 7] {
        self.jacobians(state, input).0
    }

    /// ∂f/∂(δ̇, n): the proved Jacobian program.
    fn input_jacobian(&self, state: &[T; 7], input: &[T; 3]) -> [[T; 3]; 7] {
        self.jacobians(state, input).1
    }
}

#[cfg(test)]
mod tests {
    use super::STATE;
    use crate::models::state_unit;

    /// A table's values taken in by the places found once give every coefficient, bit for
    /// bit, that they give looked up by symbol, for every ship scene shipped (prime and SI,
    /// with and without propulsion, rigid-body terms folded and separate).
    #[test]
    fn coefficients_by_place_are_coefficients_by_symbol() {
        let scenes = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
        for file in [
            "mariner.toml",
            "esso_osaka.toml",
            "s175.toml",
            "mariner_uncertainty.toml",
        ] {
            let text = std::fs::read_to_string(scenes.join(file)).unwrap();
            let scene = super::super::ShipScene::parse(&text, file).unwrap();
            let model = super::ShipModel::new(&scene.table).unwrap();
            let proved = &model.proved;
            let by_symbol =
                (proved.formulas).values(&super::parameter_values(&proved.spec, &scene.table));
            let by_place = super::coefficients(proved, &scene.table);
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&by_place), bits(&by_symbol), "{file}");
            assert!(by_place.iter().all(|c| c.is_finite()), "{file}");
        }
    }

    #[test]
    fn every_ship_state_entry_has_a_unit() {
        for name in STATE {
            assert!(state_unit(name).is_some(), "{name}");
        }
    }
}
