//! The proved program compiled to machine code when the scene is read (feature `jit`).
//!
//! The interpreter of [`super`] walks the program's nodes on every call: it is the reference,
//! and it runs on any `SimdRealField` (SIMD lanes, dual numbers, f32). In f64 the same nodes
//! are compiled here, with Cranelift, to one function per plan (the right-hand side, the
//! kinetic energy, the two Jacobians), so a scene-defined model runs at the speed of the code
//! rustc writes for a catalog model, with no toolchain on the user's machine.
//!
//! The compiled code is the interpreter's operations one for one: each node is one IEEE
//! operation of the same operands in the same order (no fused multiply–add, no reassociation:
//! Cranelift contracts nothing it is not asked to), and 1/x is a division of one by x. Sine and
//! cosine are the kernel the interpreter calls (`eom_kernel::sin_cos`), once per angle for
//! both, written out operation for operation from its constants (`eom_kernel::recipe`). An
//! angle beyond the kernel's reduction (|x| > 2¹⁹·π/2, NaN, infinite), where the kernel calls
//! the platform's sine and cosine, makes the compiled function return before it writes
//! anything, and the interpreter evaluates that call: so the code calls nothing, and needs no
//! frame of its own. So its results are the
//! interpreter's bit for bit, which the tests check on random states and on the angles where
//! the kernel changes path. With the feature `platform-trig` (the platform's sine and cosine,
//! which no written-out kernel reproduces) a program with an angle is not compiled.
//!
//! A call is given pointers to the caller's state, to the few values the model sets beside it,
//! to the interpreter's values and to the caller's outputs: the state is read where it lies
//! (a vehicle's |u| is taken in the code, as `f64::abs` takes it), nothing is copied into a
//! buffer of variables first, and the outputs are written in place. What it reads and writes
//! is checked against the slices at each call, a few comparisons.
//!
//! The values of the program's constants and hoisted coefficients are not in the code: the
//! compiled function reads them from the interpreter's table at each call, so one compiled
//! program serves every interpreter of the same program (a table re-parameterised, as a Monte
//! Carlo over the coefficients does, is not compiled again). A program with an operation this
//! compiler does not know, a host Cranelift does not support, or a failure of code generation
//! leaves the plans uncompiled, and the interpreter evaluates them.

use super::{Functions, Interpreter, Op, Plan, Variables};
use cranelift_codegen::ir::condcodes::IntCC;
use cranelift_codegen::ir::{AbiParam, Block, BlockArg, InstBuilder, MemFlags, Value, types};
use cranelift_codegen::isa::OwnedTargetIsa;
use cranelift_codegen::settings::{self, Configurable};
use cranelift_frontend::{FunctionBuilder, FunctionBuilderContext};
use cranelift_jit::{JITBuilder, JITModule};
use cranelift_module::{FuncId, Module, default_libcall_names};
use eom_kernel::recipe;
use std::any::TypeId;
use std::sync::{Arc, OnceLock};

/// Why a program was not compiled; the interpreter evaluates it then.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub(crate) enum CompileError {
    /// Cranelift cannot generate code for this machine.
    #[error("the compiler does not support this machine: {0}")]
    Host(String),
    /// The program has an operation this compiler does not know.
    #[error("node {0} of the program is an operation the compiler does not know")]
    Operation(usize),
    /// Cranelift refused the function or could not place its code.
    #[error("code generation failed: {0}")]
    Generation(String),
}

/// A compiled function: the state, the values the model set beside it, the interpreter's
/// values, the outputs, each a pointer to f64s; returns 1 when it wrote the outputs, 0 when an
/// angle was beyond the kernel's reduction (nothing written).
type Entry = unsafe extern "C" fn(*const f64, *const f64, *const f64, *mut f64) -> u8;

/// One plan compiled: its entry point and what it reads and writes.
#[derive(Clone)]
pub(crate) struct Machine {
    entry: Entry,
    /// How many entries of the state and of the computed values it reads (one past the
    /// largest position of each).
    reads: [usize; 2],
    /// How many of the interpreter's values it reads.
    values: usize,
    /// How many outputs it writes.
    outputs: usize,
    /// The code the entry point is in, freed when the last plan that calls it goes.
    code: Arc<Code>,
}

impl std::fmt::Debug for Machine {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Machine")
            .field("reads", &self.reads)
            .field("values", &self.values)
            .field("outputs", &self.outputs)
            .finish_non_exhaustive()
    }
}

/// Two plans compiled into the same code with the same shape are the same function.
impl PartialEq for Machine {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.code, &other.code)
            && (self.reads, self.values, self.outputs) == (other.reads, other.values, other.outputs)
    }
}

/// The compiled functions' memory, owned by the Cranelift module that placed them.
struct Code {
    module: Option<JITModule>,
}

// SAFETY: after `finalize_definitions` the module is only touched by `drop`, which has the
// only reference; the code it placed is read-only and executable, and calling it from any
// thread only reads the arguments and the machine's stack.
unsafe impl Send for Code {}
// SAFETY: as for `Send`: no method of `Code` reads or writes the module through `&self`.
unsafe impl Sync for Code {}

impl Drop for Code {
    fn drop(&mut self) {
        if let Some(module) = self.module.take() {
            // SAFETY: the last `Machine` holding this code is being dropped, so no entry point
            // into it remains, and none is running (a call borrows its `Machine`).
            unsafe { module.free_memory() };
        }
    }
}

impl Functions {
    /// These functions compiled for `interpreter`'s program: each plan with its machine code,
    /// which serves any interpreter of the same program (the values are read at each call).
    pub(crate) fn compiled(&self, interpreter: &Interpreter) -> Result<Functions, CompileError> {
        let mut compiler = Compiler::new()?;
        let plans = [
            &self.rhs,
            &self.kinetic_energy,
            &self.state_jacobian,
            &self.input_jacobian,
        ];
        let ids = plans
            .iter()
            .map(|plan| compiler.define(&interpreter.ops, plan))
            .collect::<Result<Vec<_>, _>>()?;
        let (code, entries) = compiler.finish(&ids)?;
        let machine = |plan: &Plan, entry: Entry| {
            let reads = variables_read(&interpreter.ops, plan);
            Plan {
                machine: Some(Machine {
                    entry,
                    reads,
                    values: interpreter.values.len(),
                    outputs: plan.outputs.len(),
                    code: code.clone(),
                }),
                ..plan.clone()
            }
        };
        Ok(Functions {
            rhs: machine(&self.rhs, entries[0]),
            kinetic_energy: machine(&self.kinetic_energy, entries[1]),
            state_jacobian: machine(&self.state_jacobian, entries[2]),
            input_jacobian: machine(&self.input_jacobian, entries[3]),
            ..self.clone()
        })
    }
}

/// `functions` compiled for `interpreter`'s program, or none if they cannot be.
pub(super) fn compile(functions: &Functions, interpreter: &Interpreter) -> Option<Functions> {
    functions.compiled(interpreter).ok()
}

/// One past the largest position of the state, and of the computed values, that `plan` reads.
fn variables_read(ops: &[Op], plan: &Plan) -> [usize; 2] {
    let mut reads = [0; 2];
    for &i in &plan.needed {
        let (which, position) = match ops[i] {
            Op::State(position) | Op::Magnitude(position) => (STATE, position),
            Op::Computed(position) => (COMPUTED, position),
            _ => continue,
        };
        reads[which] = reads[which].max(position + 1);
    }
    reads
}

/// Runs `machine` when `T` is f64 and the slices have the lengths it was compiled for;
/// returns whether it wrote the outputs (else the caller interprets).
#[inline]
pub(super) fn run<T: 'static>(
    machine: &Machine,
    values: &[f64],
    variables: Variables<T>,
    out: &mut [T],
) -> bool {
    let Variables { state, computed } = variables;
    let [state_read, computed_read] = machine.reads;
    let fits = state.len() >= state_read
        && computed.len() >= computed_read
        && values.len() >= machine.values
        && out.len() == machine.outputs;
    if TypeId::of::<T>() != TypeId::of::<f64>() || !fits {
        return false;
    }
    // SAFETY: `T` is f64 (same type id), so the slices hold f64s; the compiled function reads
    // `machine.reads` entries of the state and the computed values and
    // `machine.values` values and writes `machine.outputs` outputs, each within the slice just
    // checked; it was compiled with this signature in the platform's C calling convention, and
    // its code lives as long as `machine.code`.
    let wrote = unsafe {
        (machine.entry)(
            state.as_ptr().cast(),
            computed.as_ptr().cast(),
            values.as_ptr(),
            out.as_mut_ptr().cast(),
        )
    };
    wrote != 0
}

/// The target this machine is, set up once: Cranelift's settings for speed, the host's
/// features (SSE levels, AVX); fused multiply–add is never emitted unless asked for.
fn host() -> Result<OwnedTargetIsa, CompileError> {
    static HOST: OnceLock<Result<OwnedTargetIsa, CompileError>> = OnceLock::new();
    HOST.get_or_init(|| {
        let mut flags = settings::builder();
        for (name, value) in [
            ("opt_level", "speed"),
            ("use_colocated_libcalls", "false"),
            ("is_pic", "false"),
        ] {
            (flags.set(name, value)).map_err(|e| CompileError::Host(e.to_string()))?;
        }
        let builder = cranelift_native::builder().map_err(|e| CompileError::Host(e.into()))?;
        let isa = (builder.finish(settings::Flags::new(flags)))
            .map_err(|e| CompileError::Host(e.to_string()))?;
        Ok(isa)
    })
    .clone()
}

/// A Cranelift module being filled with the plans of one program.
struct Compiler {
    module: JITModule,
    context: FunctionBuilderContext,
}

fn generation(error: impl std::fmt::Display) -> CompileError {
    CompileError::Generation(error.to_string())
}

impl Compiler {
    fn new() -> Result<Self, CompileError> {
        let builder = JITBuilder::with_isa(host()?, default_libcall_names());
        Ok(Compiler {
            module: JITModule::new(builder),
            context: FunctionBuilderContext::new(),
        })
    }

    /// Declares and defines the function of `plan` over `ops`.
    fn define(&mut self, ops: &[Op], plan: &Plan) -> Result<FuncId, CompileError> {
        let pointer = self.module.target_config().pointer_type();
        let mut signature = self.module.make_signature();
        signature.params = vec![AbiParam::new(pointer); ARGUMENTS];
        signature.returns = vec![AbiParam::new(types::I8)];
        let id = (self.module.declare_anonymous_function(&signature)).map_err(generation)?;
        let mut context = self.module.make_context();
        context.func.signature = signature;
        let mut builder = FunctionBuilder::new(&mut context.func, &mut self.context);
        let block = builder.create_block();
        builder.append_block_params_for_function_params(block);
        builder.switch_to_block(block);
        builder.seal_block(block);
        let params = builder.block_params(block).to_vec();
        let arguments: [Value; ARGUMENTS] = std::array::from_fn(|i| params[i]);
        Body::new(&mut builder, arguments, ops).emit(plan)?;
        builder.finalize();
        (self.module.define_function(id, &mut context)).map_err(generation)?;
        Ok(id)
    }

    /// Places the code and returns it with the entry point of each of `ids`.
    fn finish(mut self, ids: &[FuncId]) -> Result<(Arc<Code>, Vec<Entry>), CompileError> {
        (self.module.finalize_definitions()).map_err(generation)?;
        let entries = ids
            .iter()
            .map(|&id| {
                let address = self.module.get_finalized_function(id);
                // SAFETY: `id` was defined by `define` with four pointer parameters and a
                // byte returned, in the platform's default (C) calling convention: `Entry`.
                unsafe { std::mem::transmute::<*const u8, Entry>(address) }
            })
            .collect();
        Ok((
            Arc::new(Code {
                module: Some(self.module),
            }),
            entries,
        ))
    }
}

/// The arguments of a compiled function, by position ([`Entry`]).
const STATE: usize = 0;
const COMPUTED: usize = 1;
const VALUES: usize = 2;
const OUTPUTS: usize = 3;
const ARGUMENTS: usize = 4;

/// The body of one function being written: the nodes' values so far.
struct Body<'a, 'b, 'o> {
    builder: &'a mut FunctionBuilder<'b>,
    /// The state, the computed values, the interpreter's values, the outputs.
    arguments: [Value; ARGUMENTS],
    ops: &'o [Op],
    /// Each `Value` node's position among the interpreter's values.
    slots: Vec<usize>,
    /// Each node's value, once emitted (not the loads: see [`Body::operand`]).
    nodes: Vec<Option<Value>>,
    /// Each angle's sine and cosine, once computed.
    trig: Vec<Option<(Value, Value)>>,
    /// The block that returns 0 (an angle beyond the kernel's reduction), once made.
    outside: Option<Block>,
}

impl<'a, 'b, 'o> Body<'a, 'b, 'o> {
    fn new(
        builder: &'a mut FunctionBuilder<'b>,
        arguments: [Value; ARGUMENTS],
        ops: &'o [Op],
    ) -> Self {
        Body {
            builder,
            arguments,
            ops,
            slots: value_slots(ops),
            nodes: vec![None; ops.len()],
            trig: vec![None; ops.len()],
            outside: None,
        }
    }

    /// The plan's nodes, each one operation, then its outputs stored and 1 returned; then the
    /// block that returns 0, if an angle branches there. The sines and cosines and what their
    /// angles need come first, so that an angle beyond the kernel's reduction returns before any
    /// other work.
    fn emit(&mut self, plan: &Plan) -> Result<(), CompileError> {
        let early = trig_first(self.ops, plan);
        let order = (plan.needed.iter()).filter(|&&i| early[i]);
        let rest = (plan.needed.iter()).filter(|&&i| !early[i]);
        for &index in order.chain(rest) {
            let value = match self.ops[index] {
                // Read where they are used, as a memory operand where one fits: read once
                // into a register at the start, they would be held, or spilled and read
                // back, across the whole function.
                Op::State(_) | Op::Magnitude(_) | Op::Computed(_) | Op::Value(_) => continue,
                Op::Sin(a) => self.sin_cos(a)?.0,
                Op::Cos(a) => self.sin_cos(a)?.1,
                Op::Recip(a) => {
                    let one = self.builder.ins().f64const(1.0);
                    let x = self.operand(a)?;
                    self.builder.ins().fdiv(one, x)
                }
                Op::Neg(a) => {
                    let x = self.operand(a)?;
                    self.builder.ins().fneg(x)
                }
                Op::Add(a, b) => {
                    let (x, y) = (self.operand(a)?, self.operand(b)?);
                    self.builder.ins().fadd(x, y)
                }
                Op::Sub(a, b) => {
                    let (x, y) = (self.operand(a)?, self.operand(b)?);
                    self.builder.ins().fsub(x, y)
                }
                Op::Mul(a, b) => {
                    let (x, y) = (self.operand(a)?, self.operand(b)?);
                    self.builder.ins().fmul(x, y)
                }
                // An operation added to the interpreter after this compiler was written is
                // not guessed at: the interpreter evaluates the program.
                #[allow(unreachable_patterns)]
                _ => return Err(CompileError::Operation(index)),
            };
            self.nodes[index] = Some(value);
        }
        // In pairs, one 16-byte store each: the caller reads its array of rates back in
        // 16-byte moves, which a pair of 8-byte stores would make wait for both to retire.
        for (pair, outputs) in plan.outputs.chunks(2).enumerate() {
            let mut value = self.operand(outputs[0])?;
            if let Some(&second) = outputs.get(1) {
                let second = self.operand(second)?;
                // The first in both lanes, the second over the upper: two instructions on
                // x86-64 (pshufd, movlhps), where scalar_to_vector's zeroed upper lane takes three.
                let lanes = self.builder.ins().splat(types::F64X2, value);
                value = self.builder.ins().insertlane(lanes, second, 1);
            }
            let offset = offset(2 * pair)?;
            (self.builder.ins()).store(MemFlags::trusted(), value, self.arguments[OUTPUTS], offset);
        }
        let wrote = self.builder.ins().iconst(types::I8, 1);
        self.builder.ins().return_(&[wrote]);
        if let Some(outside) = self.outside {
            let b = &mut *self.builder;
            b.switch_to_block(outside);
            b.set_cold_block(outside);
            b.seal_block(outside);
            let none = b.ins().iconst(types::I8, 0);
            b.ins().return_(&[none]);
        }
        Ok(())
    }

    /// The value of node `index` for one use: a variable or a value read here, another node
    /// as emitted before (the arena's order).
    fn operand(&mut self, index: usize) -> Result<Value, CompileError> {
        match self.ops.get(index) {
            Some(&Op::State(i)) => self.load(STATE, i),
            Some(&Op::Magnitude(i)) => {
                let x = self.load(STATE, i)?;
                Ok(self.builder.ins().fabs(x))
            }
            Some(&Op::Computed(i)) => self.load(COMPUTED, i),
            Some(Op::Value(_)) => self.load(VALUES, self.slots[index]),
            _ => (self.nodes.get(index).copied().flatten()).ok_or(CompileError::Operation(index)),
        }
    }

    /// Entry `i` of the argument `which` ([`STATE`], [`COMPUTED`] or [`VALUES`]).
    fn load(&mut self, which: usize, i: usize) -> Result<Value, CompileError> {
        let offset = offset(i)?;
        let base = self.arguments[which];
        // Nothing the function writes is read (the outputs are apart), so a read can move to
        // where it is used, and two of the same place are one.
        let flags = MemFlags::trusted().with_readonly().with_can_move();
        Ok((self.builder.ins()).load(types::F64, flags, base, offset))
    }

    /// `(sin, cos)` of node `angle`: the kernel written out, for each angle once.
    fn sin_cos(&mut self, angle: usize) -> Result<(Value, Value), CompileError> {
        if let Some(pair) = self.trig[angle] {
            return Ok(pair);
        }
        if !recipe::IS_THE_KERNEL {
            return Err(CompileError::Operation(angle));
        }
        let x = self.operand(angle)?;
        let outside = self.outside_block();
        let pair = kernel(self.builder, x, outside);
        self.trig[angle] = Some(pair);
        Ok(pair)
    }

    /// The block an angle beyond the kernel's reduction branches to, filled when the function
    /// ends: it returns 0, and the interpreter evaluates the call.
    fn outside_block(&mut self) -> Block {
        *self
            .outside
            .get_or_insert_with(|| self.builder.create_block())
    }
}

/// The kernel of `eom_kernel::sin_cos_f64` for one angle, operation for operation as
/// `kernel.rs` writes it (so its bits). One unsigned comparison of |x|'s bits, as the kernel's
/// own range check, sends both ends to a cold block: a tiny angle's pair `(x, 1)`, as the
/// kernel's cold path gives it (`one_at_a_time`), so that a heading held at exactly zero stays
/// in the compiled code; an angle beyond the reduction's limit (NaN and the infinities, whose
/// bits order above it) to `outside`, where the kernel calls the platform. In between, an
/// angle within ±π/4 (|x|'s bits at most π/4's) takes both polynomials as it is, any other is
/// reduced, evaluated and put in its quadrant (`in_range`, `place`): two copies of the
/// polynomials, so that the one path does not pay for the other's quadrant. The code after the
/// call continues in the block the three paths join.
fn kernel(b: &mut FunctionBuilder<'_>, x: Value, outside: Block) -> (Value, Value) {
    let [cold, warm, near, reduce, join] = std::array::from_fn(|_| b.create_block());
    let bits = b.ins().bitcast(types::I64, MemFlags::new(), x);
    let magnitude = b.ins().band_imm(bits, !recipe::SIGN_BIT as i64);
    let (tiny, limit) = (recipe::TINY.to_bits(), recipe::LIMIT.to_bits());
    let shifted = b.ins().iadd_imm(magnitude, tiny.wrapping_neg() as i64);
    let span = (limit - tiny) as i64;
    let unusual = (b.ins()).icmp_imm(IntCC::UnsignedGreaterThan, shifted, span);
    b.ins().brif(unusual, cold, &[], warm, &[]);

    b.switch_to_block(cold);
    b.set_cold_block(cold);
    b.seal_block(cold);
    let below = (b.ins()).icmp_imm(IntCC::UnsignedLessThan, magnitude, tiny as i64);
    let one = b.ins().f64const(1.0);
    let as_tiny = [BlockArg::Value(x), BlockArg::Value(one)];
    b.ins().brif(below, join, &as_tiny, outside, &[]);

    b.switch_to_block(warm);
    b.seal_block(warm);
    let quarter = std::f64::consts::FRAC_PI_4.to_bits() as i64;
    let small = (b.ins()).icmp_imm(IntCC::UnsignedLessThanOrEqual, magnitude, quarter);
    b.ins().brif(small, near, &[], reduce, &[]);

    b.switch_to_block(near);
    b.seal_block(near);
    let (sin, cos) = (sin_reduced(b, x), cos_reduced(b, x));
    b.ins()
        .jump(join, &[BlockArg::Value(sin), BlockArg::Value(cos)]);

    b.switch_to_block(reduce);
    b.seal_block(reduce);
    let (r, quadrant) = reduced(b, x);
    let (sin, cos) = (sin_reduced(b, r), cos_reduced(b, r));
    let (sin, cos) = placed(b, quadrant, sin, cos);
    b.ins()
        .jump(join, &[BlockArg::Value(sin), BlockArg::Value(cos)]);

    let sin = b.append_block_param(join, types::F64);
    let cos = b.append_block_param(join, types::F64);
    b.switch_to_block(join);
    b.seal_block(join);
    (sin, cos)
}

/// `r = x − k·π/2` in three steps, `k = round(2x/π)`, and the bits of the rounding sum, whose
/// low bits are k's (two's complement): `quadrant` and `reduce` of the kernel.
fn reduced(b: &mut FunctionBuilder<'_>, x: Value) -> (Value, Value) {
    let rounder = b.ins().f64const(recipe::ROUNDER);
    let scaled = mul_by(b, x, std::f64::consts::FRAC_2_PI);
    let shifted = b.ins().fadd(scaled, rounder);
    let k = b.ins().fsub(shifted, rounder);
    let mut r = x;
    for part in [recipe::PIO2_1, recipe::PIO2_2, recipe::PIO2_2T] {
        let product = mul_by(b, k, part);
        r = b.ins().fsub(r, product);
    }
    (r, b.ins().bitcast(types::I64, MemFlags::new(), shifted))
}

/// The reduced pair put in quadrant `k mod 4`: swapped for odd k, the sine negated for
/// k ≡ 2, 3 and the cosine for k ≡ 1, 2 (`place` of the kernel).
fn placed(b: &mut FunctionBuilder<'_>, quadrant: Value, sin: Value, cos: Value) -> (Value, Value) {
    let odd = b.ins().band_imm(quadrant, 1);
    let swapped_sin = b.ins().select(odd, cos, sin);
    let swapped_cos = b.ins().select(odd, sin, cos);
    let next = b.ins().iadd_imm(quadrant, 1);
    (
        with_sign_of(b, swapped_sin, quadrant),
        with_sign_of(b, swapped_cos, next),
    )
}

/// `value` with its sign bit flipped where bit 1 of `quadrant` is set.
fn with_sign_of(b: &mut FunctionBuilder<'_>, value: Value, quadrant: Value) -> Value {
    let shifted = b.ins().ishl_imm(quadrant, 62);
    let sign = b.ins().band_imm(shifted, recipe::SIGN_BIT as i64);
    let bits = b.ins().bitcast(types::I64, MemFlags::new(), value);
    let flipped = b.ins().bxor(bits, sign);
    b.ins().bitcast(types::F64, MemFlags::new(), flipped)
}

/// `x·c`.
fn mul_by(b: &mut FunctionBuilder<'_>, x: Value, c: f64) -> Value {
    let c = b.ins().f64const(c);
    b.ins().fmul(x, c)
}

/// `c0 + x·c1`.
fn linear(b: &mut FunctionBuilder<'_>, c0: f64, x: Value, c1: f64) -> Value {
    let product = mul_by(b, x, c1);
    let c0 = b.ins().f64const(c0);
    // The sum's bits do not depend on the order (c0 is never NaN), and with the constant
    // second it is read from memory by the addition itself, not moved through a register.
    b.ins().fadd(product, c0)
}

/// The degree-5 polynomial in z = r² of the sine's and the cosine's kernels, in pairs
/// (Estrin's scheme, as `kernel.rs` groups it): `(a + z b) + w ((c + z d) + w (e + z f))`.
fn estrin(b: &mut FunctionBuilder<'_>, z: Value, w: Value, c: [f64; 6]) -> Value {
    let low = linear(b, c[0], z, c[1]);
    let middle = linear(b, c[2], z, c[3]);
    let high = linear(b, c[4], z, c[5]);
    let upper = b.ins().fmul(w, high);
    let upper = b.ins().fadd(middle, upper);
    let upper = b.ins().fmul(w, upper);
    b.ins().fadd(low, upper)
}

/// sin r for |r| ≤ π/4: `r + r³ P(r²)`, as `sin_reduced` of `kernel.rs`.
fn sin_reduced(b: &mut FunctionBuilder<'_>, r: Value) -> Value {
    use recipe::{S1, S2, S3, S4, S5, S6};
    let z = b.ins().fmul(r, r);
    let w = b.ins().fmul(z, z);
    let p = estrin(b, z, w, [S1, S2, S3, S4, S5, S6]);
    let cube = b.ins().fmul(z, r);
    let tail = b.ins().fmul(cube, p);
    b.ins().fadd(r, tail)
}

/// cos r for |r| ≤ π/4: `1 − r²/2 + r⁴ Q(r²)` with the rounding error of `1 − r²/2` added
/// back, as `cos_reduced` of `kernel.rs`.
fn cos_reduced(b: &mut FunctionBuilder<'_>, r: Value) -> Value {
    use recipe::{C1, C2, C3, C4, C5, C6};
    let z = b.ins().fmul(r, r);
    let w = b.ins().fmul(z, z);
    let q = estrin(b, z, w, [C1, C2, C3, C4, C5, C6]);
    let half_z = mul_by(b, z, 0.5);
    let one = b.ins().f64const(1.0);
    let head = b.ins().fsub(one, half_z);
    let lost = b.ins().fsub(one, head);
    let lost = b.ins().fsub(lost, half_z);
    let w_q = b.ins().fmul(w, q);
    let tail = b.ins().fadd(lost, w_q);
    b.ins().fadd(head, tail)
}

/// Which of `plan`'s nodes are sines, cosines, or what their angles are computed from.
fn trig_first(ops: &[Op], plan: &Plan) -> Vec<bool> {
    let mut early = vec![false; ops.len()];
    for &index in plan.needed.iter().rev() {
        let trig = matches!(ops[index], Op::Sin(_) | Op::Cos(_));
        if trig || early[index] {
            early[index] = true;
            let children = match ops[index] {
                Op::Sin(a) | Op::Cos(a) | Op::Recip(a) | Op::Neg(a) => vec![a],
                Op::Add(a, b) | Op::Sub(a, b) | Op::Mul(a, b) => vec![a, b],
                _ => vec![],
            };
            for child in children {
                early[child] = true;
            }
        }
    }
    early
}

/// The byte offset of f64 number `i`.
fn offset(i: usize) -> Result<i32, CompileError> {
    (i.checked_mul(8).and_then(|o| i32::try_from(o).ok()))
        .ok_or_else(|| CompileError::Generation(format!("offset of entry {i}")))
}

/// For each node, its position among the values (`Interpreter::values`, the `Value` nodes in
/// order).
fn value_slots(ops: &[Op]) -> Vec<usize> {
    let mut next = 0;
    ops.iter()
        .map(|op| {
            let slot = next;
            if matches!(op, Op::Value(_)) {
                next += 1;
            }
            slot
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::super::{Functions, Interpreter, Source, Variables};
    use eom_codegen::emit::program::{Function, Id, Jacobians, Named, Node, Program};

    /// Numbers at the edges of f64: both zeros, subnormals, the largest magnitudes, the
    /// infinities, NaN of either sign and with a payload.
    const EDGES: [f64; 11] = [
        0.0,
        -0.0,
        5e-324,
        -2.2e-308,
        1e300,
        -f64::MAX,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
        -f64::NAN,
        f64::from_bits(0xFFF0_0000_0000_0001),
    ];

    /// A program of three variables, x, |x| and c, that outputs each of them and three
    /// operations of them: each source a compiled call reads, seen in its outputs' bits.
    fn program() -> Program {
        let node = |i: u32| Id(i);
        let function = |ids: &[u32]| Function {
            stages: vec![],
            outputs: (ids.iter())
                .map(|&i| Named {
                    name: format!("out{i}"),
                    id: node(i),
                })
                .collect(),
        };
        Program {
            nodes: vec![
                Node::Variable("x".into()),
                Node::Variable("abs_x".into()),
                Node::Variable("c".into()),
                Node::Mul(node(0), node(1)),
                Node::Add(node(1), node(2)),
                Node::Neg(node(1)),
            ],
            coefficients: vec![],
            rhs: function(&[1, 0, 2, 3, 4, 5]),
            kinetic_energy: Some(function(&[3])),
            potential_energy: None,
            jacobians: Some(Jacobians {
                state: function(&[1]),
                input: function(&[2]),
                state_pattern: vec![(0, 0)],
                input_pattern: vec![(0, 0)],
            }),
        }
    }

    /// The compiled call reads x from the state where it lies (the second entry: the first
    /// is not read), takes |x| of it as `f64::abs` does (a cleared sign bit, for −0 and a
    /// negative NaN too), reads c from what the model sets, and writes its outputs in place:
    /// at every pair of edges of f64 its outputs are the interpreter's bit for bit, and its
    /// first output is `x.abs()`.
    #[test]
    fn each_variable_is_read_where_it_lies_at_the_edges_of_f64() {
        let program = program();
        let source = |name: &str| match name {
            "x" => Some(Source::State(1)),
            "abs_x" => Some(Source::Magnitude(1)),
            "c" => Some(Source::Computed(0)),
            _ => None,
        };
        let interpreter = Interpreter::new(&program, &[], source).unwrap();
        let functions = Functions::of(&program).unwrap();
        let compiled = functions.compiled(&interpreter).unwrap();
        assert!(compiled.is_compiled());
        let interpreted = functions.interpreted();
        for x in EDGES {
            for c in EDGES {
                let (state, computed) = ([f64::NAN, x], [c]);
                let variables = Variables {
                    state: &state,
                    computed: &computed,
                };
                let (mut fast, mut reference) = ([0.0; 6], [0.0; 6]);
                interpreter.evaluate_into(&compiled.rhs, variables, &mut fast);
                interpreter.evaluate_into(&interpreted.rhs, variables, &mut reference);
                assert_eq!(
                    fast.map(f64::to_bits),
                    reference.map(f64::to_bits),
                    "x = {x:e}, c = {c:e}"
                );
                assert_eq!(fast[0].to_bits(), x.abs().to_bits(), "|{x:e}|");
            }
        }
    }
}
