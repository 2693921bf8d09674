//! Scene-defined models: where the symbolic engine enters the library, and the one
//! interpreter of the programs it proves.
//!
//! A ship's 4.46 and a vehicle's six equations are known only when their scene is read, so
//! their builders (`ship::model`, `vehicle::model`) call `eom-codegen` at run time: to derive
//! the system from the table, prove its program and Jacobians, and name the table's terms.
//! Everything of the engine they use comes through [`engine`] here, so the library's use of it
//! has one seam, behind the feature `ship`; and what they build, they evaluate here.
//!
//! What runs is the proved straight-line program itself ([`Program`]): the arena of shared
//! nodes the emitter writes as Rust for a catalog model, with its functions (the right-hand
//! side, the Jacobians ∂f/∂x and ∂f/∂u, the kinetic energy), each folded back and proved
//! against the system and its exact derivative before it gets here. A call evaluates the nodes
//! its function needs, once each, in order; the hoisted coefficients are computed once per
//! table. It is generic over simba's `SimdRealField`, so it runs on f64, on SIMD lanes and on
//! dual numbers. Each of the program's variables is read where the model says ([`Source`]):
//! an entry of the state the call is given, its magnitude (a vehicle's |u|), or one of the
//! values the model sets beside the state (a ship's δ̇ and U, a vehicle's applied loads).
//! So a call copies nothing of the state: the compiled code reads it where it lies, and writes
//! the rates where the caller wants them.

use engine::{Expr, Function, Node, Program, System};

#[cfg(feature = "jit")]
mod compiled;
/// Without the feature `jit` no plan has machine code: the interpreter evaluates every one.
#[cfg(not(feature = "jit"))]
mod compiled {
    /// No machine code: this type has no values.
    #[derive(Debug, Clone, PartialEq)]
    pub(crate) enum Machine {}

    pub(super) fn compile(
        _: &super::Functions,
        _: &super::Interpreter,
    ) -> Option<super::Functions> {
        None
    }

    pub(super) fn run<T>(
        machine: &Machine,
        _: &[f64],
        _: super::Variables<T>,
        _: &mut [T],
    ) -> bool {
        match *machine {}
    }
}

/// What the builders of scene-defined models use of the symbolic engine, and the table
/// vocabularies the library re-exports from it (`ship::{Force, Term, Units, YawInertia}`,
/// `vehicle::{Convention, …}`).
pub(crate) mod engine {
    pub use eom_codegen::derivation::vehicle::LOADS as VEHICLE_LOADS;
    pub use eom_codegen::emit::program::{Function, Node, Program};
    pub use eom_codegen::emit::{EmitError, F64Formula, Operations, prove_with_jacobians};
    pub use eom_codegen::model::BuildError;
    pub use eom_codegen::model::aircraft::{
        QUATERNION_STATE as AIRCRAFT_QUATERNION_STATE, STATE as AIRCRAFT_STATE, aircraft_with,
    };
    pub use eom_codegen::model::earth as earth_model;
    pub use eom_codegen::model::ship::{
        ADDED_MASS, APPLIED_LOADS, CURRENT_INPUTS, Force, MMG_ADDED_MASS, MMG_SCALES, PRIME_SCALES,
        PROPULSION, ShipForm, ShipSpec, Term, Units, VARIABLES, YawInertia, ship,
    };
    /// A vehicle's table as the engine reads it (its error type among them).
    pub use eom_codegen::model::vehicle as vehicle_table;
    pub use eom_codegen::model::vehicle::{
        AddedMassCoriolis, Convention, FoldedComparison, InertiaAbout, NameError,
        PRIME_SCALES as VEHICLE_PRIME_SCALES, Propeller, VehicleSpec, folded_comparison,
        format_folded, vehicle,
    };
    pub use eom_codegen::model::{Kinematics, Symmetry, System};
    pub use eom_codegen::symbolic::Expr;
}
use simba::simd::SimdRealField;
use std::collections::BTreeMap;

/// Where the program reads one of its variables, as the model lays out a call.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Source {
    /// The entry of the state at this position.
    State(usize),
    /// The magnitude |x| of the state's entry at this position.
    Magnitude(usize),
    /// The value at this position among those the model sets beside the state.
    Computed(usize),
}

/// What a call reads its variables from: the state it is given, and what the model set
/// beside it (see [`Source`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Variables<'a, T> {
    pub(crate) state: &'a [T],
    pub(crate) computed: &'a [T],
}

/// One node of the program, with its operands resolved to positions.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Op {
    /// A variable: an entry of the state.
    State(usize),
    /// A variable: the magnitude of an entry of the state.
    Magnitude(usize),
    /// A variable: a value the model computed.
    Computed(usize),
    Value(f64),
    Sin(usize),
    Cos(usize),
    Recip(usize),
    Neg(usize),
    Add(usize, usize),
    Sub(usize, usize),
    Mul(usize, usize),
}

/// A proved program resolved to operations on numbers.
#[derive(Debug, Clone)]
pub(crate) struct Interpreter {
    ops: Vec<Op>,
    /// The `Value`s of `ops` in order: what the compiled plans read.
    values: Vec<f64>,
}

/// The functions of a proved program a scene-defined model evaluates, and where each
/// Jacobian entry sits.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Functions {
    pub(crate) rhs: Plan,
    pub(crate) kinetic_energy: Plan,
    pub(crate) state_jacobian: Plan,
    pub(crate) input_jacobian: Plan,
    /// (row, column) of each output of the state Jacobian.
    pub(crate) state_pattern: Vec<(usize, usize)>,
    /// (row, column) of each output of the input Jacobian.
    pub(crate) input_pattern: Vec<(usize, usize)>,
}

impl Functions {
    /// The functions of `program`, which must have been built with its Jacobians and have a
    /// kinetic energy; else the name of what it lacks.
    pub(crate) fn of(program: &Program) -> Result<Self, &'static str> {
        let jacobians = program.jacobians.as_ref().ok_or("Jacobians")?;
        let energy = program.kinetic_energy.as_ref().ok_or("kinetic energy")?;
        Ok(Functions {
            rhs: Plan::of(program, &program.rhs),
            kinetic_energy: Plan::of(program, energy),
            state_jacobian: Plan::of(program, &jacobians.state),
            input_jacobian: Plan::of(program, &jacobians.input),
            state_pattern: jacobians.state_pattern.clone(),
            input_pattern: jacobians.input_pattern.clone(),
        })
    }
}

impl Functions {
    /// These functions compiled to machine code for `interpreter`'s program where they can be
    /// (feature `jit`), else as they are; either way they serve any interpreter of the same
    /// program.
    pub(crate) fn compile(self, interpreter: &Interpreter) -> Functions {
        compiled::compile(&self, interpreter).unwrap_or(self)
    }

    /// These functions without machine code: the interpreter evaluates every one.
    pub(crate) fn interpreted(&self) -> Functions {
        let plain = |plan: &Plan| Plan {
            machine: None,
            ..plan.clone()
        };
        Functions {
            rhs: plain(&self.rhs),
            kinetic_energy: plain(&self.kinetic_energy),
            state_jacobian: plain(&self.state_jacobian),
            input_jacobian: plain(&self.input_jacobian),
            ..self.clone()
        }
    }

    /// Whether the right-hand side runs as machine code.
    pub(crate) fn is_compiled(&self) -> bool {
        self.rhs.machine.is_some()
    }
}

/// What one function of the program evaluates: the nodes its outputs need, in the arena's
/// order (every operand before its user), and its outputs.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Plan {
    needed: Vec<usize>,
    outputs: Vec<usize>,
    /// The plan as machine code, when it is compiled (`Functions::compile`).
    machine: Option<compiled::Machine>,
}

impl Plan {
    /// The nodes `function`'s outputs reach through their operands.
    pub(crate) fn of(program: &Program, function: &Function) -> Self {
        let mut needed = vec![false; program.nodes.len()];
        let mut pending: Vec<usize> = function.outputs.iter().map(|o| o.id.index()).collect();
        while let Some(index) = pending.pop() {
            if !std::mem::replace(&mut needed[index], true) {
                pending.extend(program.nodes[index].children().iter().map(|c| c.index()));
            }
        }
        Plan {
            needed: (0..needed.len()).filter(|&i| needed[i]).collect(),
            outputs: function.outputs.iter().map(|o| o.id.index()).collect(),
            machine: None,
        }
    }
}

impl Interpreter {
    /// The program's nodes with the hoisted `coefficients` put in and each variable read from
    /// where `variable` says; a variable it does not place is returned as the error.
    pub(crate) fn new(
        program: &Program,
        coefficients: &[f64],
        variable: impl Fn(&str) -> Option<Source>,
    ) -> Result<Self, String> {
        let mut ops = Vec::with_capacity(program.nodes.len());
        for node in &program.nodes {
            ops.push(match node {
                Node::Variable(name) => match variable(name).ok_or_else(|| name.clone())? {
                    Source::State(i) => Op::State(i),
                    Source::Magnitude(i) => Op::Magnitude(i),
                    Source::Computed(i) => Op::Computed(i),
                },
                Node::Coefficient(i) => Op::Value(coefficients[*i]),
                Node::Constant(c) => Op::Value(Expr::constant(c.clone()).eval(&|_| f64::NAN)),
                Node::Sin(a) => Op::Sin(a.index()),
                Node::Cos(a) => Op::Cos(a.index()),
                Node::Recip(a) => Op::Recip(a.index()),
                Node::Neg(a) => Op::Neg(a.index()),
                Node::Add(a, b) => Op::Add(a.index(), b.index()),
                Node::Sub(a, b) => Op::Sub(a.index(), b.index()),
                Node::Mul(a, b) => Op::Mul(a.index(), b.index()),
            });
        }
        Ok(Interpreter {
            values: (ops.iter())
                .filter_map(|op| match op {
                    Op::Value(x) => Some(*x),
                    _ => None,
                })
                .collect(),
            ops,
        })
    }

    /// The outputs of `plan` with its `variables`.
    pub(crate) fn evaluate<'a, T: SimdRealField + Copy>(
        &self,
        plan: &'a Plan,
        variables: Variables<T>,
    ) -> impl Iterator<Item = T> + use<'a, T> {
        let mut outputs = vec![T::zero(); plan.outputs.len()];
        self.evaluate_into(plan, variables, &mut outputs);
        outputs.into_iter()
    }

    /// The outputs of `plan` with its `variables`, into `outputs` (as many as the plan has): by
    /// the plan's machine code in f64 when it is compiled, else by the interpreter. Inlined,
    /// so that a compiled call costs its caller a few comparisons and the call, not the
    /// interpreter's frame.
    #[inline]
    pub(crate) fn evaluate_into<T: SimdRealField + Copy>(
        &self,
        plan: &Plan,
        variables: Variables<T>,
        outputs: &mut [T],
    ) {
        if let Some(machine) = &plan.machine
            && compiled::run(machine, &self.values, variables, outputs)
        {
            return;
        }
        self.interpret(plan, variables.state, variables.computed, outputs);
    }

    /// The outputs of `plan` by the interpreter: each node it needs once, in order. The
    /// variables come as slices, in registers, so that a compiled call does not lay them out in
    /// memory for a call it does not make.
    fn interpret<T: SimdRealField + Copy>(
        &self,
        plan: &Plan,
        state: &[T],
        computed: &[T],
        outputs: &mut [T],
    ) {
        let mut values: Vec<T> = vec![T::zero(); self.ops.len()];
        for &index in &plan.needed {
            values[index] = match self.ops[index] {
                Op::State(i) => state[i],
                Op::Magnitude(i) => state[i].simd_abs(),
                Op::Computed(i) => computed[i],
                Op::Value(x) => T::from_subset(&x),
                Op::Sin(a) => eom_kernel::sin_cos([values[a]])[0].0,
                Op::Cos(a) => eom_kernel::sin_cos([values[a]])[0].1,
                Op::Recip(a) => T::one() / values[a],
                Op::Neg(a) => -values[a],
                Op::Add(a, b) => values[a] + values[b],
                Op::Sub(a, b) => values[a] - values[b],
                Op::Mul(a, b) => values[a] * values[b],
            };
        }
        for (output, &index) in outputs.iter_mut().zip(&plan.outputs) {
            *output = values[index];
        }
    }
}

/// The hoisted coefficients of a proved program as formulas of its parameters, built once:
/// the reciprocals of parameter polynomials first (each a parameter of the ones after it),
/// then each coefficient. Each formula computes its value as the emitted `Coefficients::new`
/// computes it ([`engine::F64Formula`]), so the program has the bits of the same table
/// compiled by rustc from a user's `build.rs`; the symbolic work is not repeated for each set
/// of values (a Monte Carlo case).
#[derive(Debug, Clone)]
pub(crate) struct CoefficientFormulas {
    /// The parameters by index, the reciprocals' symbols after the given ones.
    symbols: Vec<String>,
    /// Each reciprocal: the index it fills, and the formula it is the reciprocal of.
    reciprocals: Vec<(usize, engine::F64Formula)>,
    coefficients: Vec<engine::F64Formula>,
}

impl CoefficientFormulas {
    pub(crate) fn new(system: &System, program: &Program) -> Self {
        let mut symbols: Vec<String> = Vec::new();
        let mut index = |symbol: &str| {
            (symbols.iter().position(|s| s == symbol)).unwrap_or_else(|| {
                symbols.push(symbol.to_owned());
                symbols.len() - 1
            })
        };
        let reciprocals = (system.reciprocals.iter())
            .map(|r| {
                let of = engine::F64Formula::new(&r.of, &mut index);
                (index(&r.symbol), of)
            })
            .collect();
        let coefficients = (program.coefficients.iter())
            .map(|c| engine::F64Formula::new(&c.value, &mut index))
            .collect();
        CoefficientFormulas {
            symbols,
            reciprocals,
            coefficients,
        }
    }

    /// The coefficients' values with the `parameters`' values; a parameter without a value
    /// makes NaN.
    pub(crate) fn values(&self, parameters: &BTreeMap<String, f64>) -> Vec<f64> {
        let known: Vec<f64> = (self.symbols.iter())
            .map(|s| parameters.get(s).copied().unwrap_or(f64::NAN))
            .collect();
        self.values_of(known)
    }

    /// The parameters the formulas read, by index: [`Self::values_of`] takes their values in
    /// this order.
    pub(crate) fn parameters(&self) -> &[String] {
        &self.symbols
    }

    /// The coefficients' values with each parameter's value at its index among
    /// [`Self::parameters`] (and a reciprocal's index after them, its value not read): what
    /// [`Self::values`] computes, for a caller that found each parameter's place once.
    pub(crate) fn values_of(&self, mut known: Vec<f64>) -> Vec<f64> {
        for (symbol, of) in &self.reciprocals {
            known[*symbol] = 1.0 / of.value(&known);
        }
        (self.coefficients.iter())
            .map(|c| c.value(&known))
            .collect()
    }
}

/// The hoisted coefficients' values, each computed once from the parameters: the formulas
/// of [`CoefficientFormulas`] built and used once.
pub(crate) fn coefficient_values(
    system: &System,
    program: &Program,
    parameters: &BTreeMap<String, f64>,
) -> Vec<f64> {
    CoefficientFormulas::new(system, program).values(parameters)
}

/// How many derivations a [`Derivations`] keeps: a sweep over tables of more term sets than
/// this derives each again once it falls out.
const DERIVATIONS_KEPT: usize = 16;

/// What a kind derived, proved and compiled from a table's terms (its spec), kept per process,
/// so that a table of the same terms (a sweep's case, a Monte Carlo's) takes its values into
/// it rather than being derived again: the last [`DERIVATIONS_KEPT`] specs, each once.
pub(crate) struct Derivations<Spec, Derived> {
    kept: std::sync::Mutex<Vec<(Spec, Derived)>>,
}

impl<Spec: PartialEq, Derived: Clone> Derivations<Spec, Derived> {
    /// None kept yet.
    pub(crate) const fn new() -> Self {
        Derivations {
            kept: std::sync::Mutex::new(Vec::new()),
        }
    }

    /// The derivation of `spec` kept earlier in this process, if there is one.
    pub(crate) fn get(&self, spec: &Spec) -> Option<Derived> {
        let kept = self.kept.lock().ok()?;
        (kept.iter().find(|(s, _)| s == spec)).map(|(_, derived)| derived.clone())
    }

    /// Keeps `derived` as `spec`'s and returns it, unless another thread kept one for `spec`
    /// meanwhile (the first cases of a Monte Carlo on every core): then that one, which every
    /// later table of the spec shares.
    pub(crate) fn keep(&self, spec: Spec, derived: Derived) -> Derived {
        let Ok(mut kept) = self.kept.lock() else {
            return derived;
        };
        if let Some((_, first)) = kept.iter().find(|(s, _)| *s == spec) {
            return first.clone();
        }
        if kept.len() == DERIVATIONS_KEPT {
            kept.remove(0);
        }
        kept.push((spec, derived.clone()));
        derived
    }
}

#[cfg(test)]
mod tests {
    use super::{DERIVATIONS_KEPT, Derivations};

    #[test]
    fn a_spec_is_kept_once_and_the_first_kept_is_the_one_shared() {
        let kept: Derivations<usize, &str> = Derivations::new();
        assert_eq!(kept.get(&0), None);
        assert_eq!(kept.keep(0, "first"), "first");
        // A second thread's derivation of the same spec: the first stays the one shared.
        assert_eq!(kept.keep(0, "second"), "first");
        assert_eq!(kept.get(&0), Some("first"));
        for spec in 1..DERIVATIONS_KEPT {
            kept.keep(spec, "other");
        }
        assert_eq!(kept.get(&0), Some("first"));
        kept.keep(DERIVATIONS_KEPT, "other");
        assert_eq!(kept.get(&0), None, "the oldest falls out");
        assert_eq!(kept.get(&DERIVATIONS_KEPT), Some("other"));
    }
}
