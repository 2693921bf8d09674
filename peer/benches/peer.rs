//! eom's generated models against SymPy's C, in one process: `cargo bench -p eom-peer`.
//!
//! For each of the six spatial variants (and SymPy's unit-quaternion form of the three
//! quaternion ones), four contenders evaluate the right-hand side at the same 1024 drawn
//! states and inputs (`eom_peer::draw`, fixed seed) on the same body:
//!
//! - **eom**: `generated::<variant>::rhs`, wrapped in a function that is never inlined and
//!   called through a `fn` pointer the optimiser cannot see through;
//! - **SymPy-C op-by-op**: `sympy/c/<variant>.c` built `-O3 -march=native -ffp-contract=off`;
//! - **SymPy-C FMA**: the same source built `-O3 -march=native -ffp-contract=fast`;
//!
//! both C builds called through an `extern "C" fn` pointer; and a fourth column, eom called the
//! way a user's crate calls it (`fn call(k, s, u, out) { *out = rhs(k, s, u) }`, never inlined,
//! a function of this bench's crate rather than of `eom-peer`, called directly), so that the
//! two ways of calling eom are timed in the same rounds. Every entry of every output is
//! read with its own volatile load and added into the checksum, so nothing is left for the
//! optimiser to drop, and no entry is read by a load wider than the store that wrote it (such
//! a load waits for the stores to reach the cache instead of taking their data directly; how
//! wide the compiler made the loads of a plain accumulation depended on the target features,
//! and slowed the C calls by up to 40 % in a build for `-C target-cpu=native`). The sum over
//! one pass is the contender's checksum. Before timing, the
//! bench checks every output of the three against each other (to 1e-12 of the output's
//! largest entry), then that the checksums agree to 1e-12 of the sum of the outputs' sizes.
//!
//! Timing: one timing is enough passes over the states to last at least 10 ms; 11 rounds,
//! each timing every contender of every variant once, the contenders' order turned each
//! round, so that a change of load falls on all four alike. A contender's time is the
//! median of its 11; the ratio is SymPy-C's median over eom's (above 1: eom is faster), with
//! the range of the 11 per-round ratios beside it.

use eom::models::generated;
use eom_peer::{CRhs, EomModel, MASS, SEED, body, draw, eom_model, fma, op_by_op};
use std::hint::black_box;
use std::rc::Rc;
use std::time::{Duration, Instant};

/// The drawn states and inputs.
const STATES: usize = 1024;
/// Timing rounds; each contender's time is the median of its rounds.
const ROUNDS: usize = 11;
/// The least time of one timing.
const MIN_TIMING: Duration = Duration::from_millis(10);
/// Agreement asked of each output entry (of the output's largest entry), and of the
/// checksums (of the sum of the outputs' absolute values).
const TOLERANCE: f64 = 1e-12;

type EomFn<K, const N: usize> = fn(&K, &[f64; N], &[f64; 6]) -> [f64; N];

/// `passes` passes of eom's `f` over the states; returns the sum of every output entry.
#[inline(never)]
fn eom_passes<K, const N: usize>(
    f: EomFn<K, N>,
    k: &K,
    states: &[[f64; N]],
    inputs: &[[f64; 6]],
    passes: usize,
) -> f64 {
    // The optimiser must not see which function it calls, nor inline it.
    let f = black_box(f);
    let mut sum = 0.0;
    for _ in 0..passes {
        for (x, u) in states.iter().zip(inputs) {
            sum += total(&f(k, x, u));
        }
    }
    sum
}

/// `passes` passes of SymPy's C `f` over the states; returns the sum of every output entry.
///
/// `k` must hold as many coefficients as `f` reads and `N` be its state length (checked by
/// [`Row::new`] before any call).
#[inline(never)]
fn c_passes<const N: usize>(
    f: CRhs,
    k: &[f64],
    states: &[[f64; N]],
    inputs: &[[f64; 6]],
    passes: usize,
) -> f64 {
    let f = black_box(f);
    let mut sum = 0.0;
    let mut out = [0.0; N];
    for _ in 0..passes {
        for (x, u) in states.iter().zip(inputs) {
            // SAFETY: the lengths are those the C reads and writes (see above).
            unsafe { f(k.as_ptr(), x.as_ptr(), u.as_ptr(), out.as_mut_ptr()) };
            sum += total(&out);
        }
    }
    sum
}

/// The sum of one output's entries, each read with a volatile load of its own: the compiler
/// may neither skip an entry nor read two with one wider load. Four partial sums keep the
/// chain of dependent additions short.
#[inline(always)]
fn total<const N: usize>(out: &[f64; N]) -> f64 {
    let mut partial = [0.0; 4];
    for (i, x) in out.iter().enumerate() {
        // SAFETY: `x` is a valid, aligned reference to an initialised f64.
        partial[i % 4] += unsafe { std::ptr::read_volatile(x) };
    }
    (partial[0] + partial[1]) + (partial[2] + partial[3])
}

/// eom's `rhs` as a user's crate calls it: its own never-inlined function of this crate (not
/// of `eom-peer`), writing the rates through `out`, called directly in the loop.
trait UserCall<const N: usize> {
    fn call(&self, state: &[f64; N], input: &[f64; 6], out: &mut [f64; N]);
}

macro_rules! user_calls {
    ($($variant:ident: $n:literal),* $(,)?) => {
        $(
            impl UserCall<$n> for generated::$variant::Coefficients<f64> {
                #[inline(never)]
                fn call(&self, state: &[f64; $n], input: &[f64; 6], out: &mut [f64; $n]) {
                    *out = generated::$variant::rhs(self, state, input);
                }
            }
        )*
    };
}

user_calls! {
    spatial_full_euler: 12,
    spatial_full_quaternion: 13,
    spatial_xz_euler: 12,
    spatial_xz_quaternion: 13,
    spatial_principal_euler: 12,
    spatial_principal_quaternion: 13,
}

/// `passes` passes of `k.call` over the states, a user's loop; returns the sum of every output.
#[inline(never)]
fn user_passes<K: UserCall<N>, const N: usize>(
    k: &K,
    states: &[[f64; N]],
    inputs: &[[f64; 6]],
    passes: usize,
) -> f64 {
    let mut sum = 0.0;
    let mut out = [0.0; N];
    for _ in 0..passes {
        for (x, u) in states.iter().zip(inputs) {
            k.call(x, u, &mut out);
            sum += total(&out);
        }
    }
    sum
}

/// The harness alone: a never-inlined function that returns its state unchanged, called and
/// consumed as eom's models are.
#[inline(never)]
fn copy_state<const N: usize>(_: &(), state: &[f64; N], _: &[f64; 6]) -> [f64; N] {
    *state
}

/// The contenders, in the table's order.
const CONTENDERS: [&str; 4] = [
    "eom",
    "SymPy-C op-by-op",
    "SymPy-C FMA",
    "eom, a user's call",
];

/// A contender: runs the given number of passes, returns its checksum.
type Passes = Box<dyn Fn(usize) -> f64>;

/// One line of the table: a variant, its four contenders and their timings.
struct Row {
    label: String,
    contenders: [Passes; 4],
    checksums: [f64; 4],
    /// The sum of the absolute values of eom's outputs over one pass.
    magnitude: f64,
    passes: usize,
    seconds: [Vec<f64>; 4],
}

impl Row {
    /// eom's model against both C builds of the same variant (`unit`: SymPy's unit-quaternion
    /// form), after checking that all three compute the same outputs.
    fn new<K: UserCall<N> + Clone + 'static, const N: usize>(
        eom: EomModel<K, N>,
        unit: bool,
        states: Rc<[[f64; N]]>,
        inputs: Rc<[[f64; 6]]>,
    ) -> Row {
        let name = eom.name;
        let parameters = eom_peer::parameters(MASS, &body(name));
        let [op, fma] = [&op_by_op::MODELS, &fma::MODELS].map(|models| {
            let c = *models.iter().find(|m| m.name == name).expect("a C model");
            assert_eq!(c.state_len, N, "{name}");
            let f = if unit {
                c.unit_fn.expect("a unit form")
            } else {
                c.rhs_fn
            };
            (c, f, Rc::<[f64]>::from(c.coefficients(&parameters)))
        });

        let mut magnitude = 0.0;
        for (i, (x, u)) in states.iter().zip(inputs.iter()).enumerate() {
            let expected = (eom.rhs)(&eom.k, x, u);
            magnitude += expected.iter().map(|e| e.abs()).sum::<f64>();
            for (c, _, k) in [&op, &fma] {
                let got = if unit {
                    c.rhs_unit(k, x, u).expect("a unit form")
                } else {
                    c.rhs(k, x, u)
                };
                if let Err((entry, a, b)) = eom_peer::agree(&expected, &got, TOLERANCE) {
                    panic!("{name} state {i}, entry {entry}: eom {a:e}, SymPy-C {b:e}");
                }
            }
        }

        let user_k = eom.k.clone();
        let eom_run: Passes = {
            let states = Rc::clone(&states);
            let inputs = Rc::clone(&inputs);
            Box::new(move |passes| eom_passes(eom.rhs, &eom.k, &states, &inputs, passes))
        };
        let c_run = |(_, f, k): (eom_peer::CModel, CRhs, Rc<[f64]>)| -> Passes {
            let states = Rc::clone(&states);
            let inputs = Rc::clone(&inputs);
            Box::new(move |passes| c_passes(f, &k, &states, &inputs, passes))
        };
        let user_run: Passes = {
            let (k, states, inputs) = (user_k, Rc::clone(&states), Rc::clone(&inputs));
            Box::new(move |passes| user_passes(&k, &states, &inputs, passes))
        };
        let contenders = [eom_run, c_run(op), c_run(fma), user_run];
        let checksums = [0, 1, 2, 3].map(|i| contenders[i](1));
        for (i, checksum) in checksums.iter().enumerate().skip(1) {
            assert!(
                (checksum - checksums[0]).abs() <= TOLERANCE * magnitude,
                "{name}: checksum of {} {checksum:e} against eom's {:e}",
                CONTENDERS[i],
                checksums[0]
            );
        }

        // Enough passes for one timing of eom to last MIN_TIMING.
        let start = Instant::now();
        black_box(contenders[0](1));
        let pass = start.elapsed().max(Duration::from_micros(1));
        let passes = (MIN_TIMING.as_secs_f64() / pass.as_secs_f64()).ceil() as usize;

        let label = if unit {
            format!("{name}, SymPy unit-q")
        } else {
            name.to_owned()
        };
        Row {
            label,
            contenders,
            checksums,
            magnitude,
            passes: passes.max(1),
            seconds: Default::default(),
        }
    }

    /// Times each contender once, starting with contender `first`.
    fn time(&mut self, first: usize) {
        for j in 0..4 {
            let c = (first + j) % 4;
            let start = Instant::now();
            black_box(self.contenders[c](self.passes));
            self.seconds[c].push(start.elapsed().as_secs_f64());
        }
    }

    /// The median time of one call of contender `c`, in ns.
    fn ns_per_call(&self, c: usize) -> f64 {
        median(&self.seconds[c]) / (self.passes * STATES) as f64 * 1e9
    }

    /// Contender `c`'s time over eom's: the ratio of the medians, and the least and largest
    /// ratio of one round.
    fn ratio(&self, c: usize) -> (f64, f64, f64) {
        let rounds: Vec<f64> = self.seconds[c]
            .iter()
            .zip(&self.seconds[0])
            .map(|(c, e)| c / e)
            .collect();
        let low = rounds.iter().copied().fold(f64::INFINITY, f64::min);
        let high = rounds.iter().copied().fold(0.0, f64::max);
        (self.ns_per_call(c) / self.ns_per_call(0), low, high)
    }
}

fn median(xs: &[f64]) -> f64 {
    let mut xs = xs.to_vec();
    xs.sort_by(f64::total_cmp);
    xs[xs.len() / 2]
}

/// A line of `/proc/cpuinfo` or `/proc/loadavg`, for the record of where the bench ran.
fn proc_field(file: &str, key: &str) -> String {
    let text = std::fs::read_to_string(file).unwrap_or_default();
    if key.is_empty() {
        return text
            .split_whitespace()
            .take(3)
            .collect::<Vec<_>>()
            .join(" ");
    }
    text.lines()
        .find(|l| l.split(':').next().is_some_and(|k| k.trim() == key))
        .and_then(|l| l.split_once(':'))
        .map_or_else(|| "unknown".to_owned(), |(_, v)| v.trim().to_owned())
}

fn main() {
    let draws = draw(STATES, SEED);
    let euler: Rc<[[f64; 12]]> = draws.iter().map(|d| d.euler).collect();
    let quaternion: Rc<[[f64; 13]]> = draws.iter().map(|d| d.quaternion).collect();
    let inputs: Rc<[[f64; 6]]> = draws.iter().map(|d| d.input).collect();

    let full_e = eom_model::spatial_full_euler(MASS, &body("spatial_full_euler"));
    let full_q = eom_model::spatial_full_quaternion(MASS, &body("spatial_full_quaternion"));
    let xz_e = eom_model::spatial_xz_euler(MASS, &body("spatial_xz_euler"));
    let xz_q = eom_model::spatial_xz_quaternion(MASS, &body("spatial_xz_quaternion"));
    let principal_e = eom_model::spatial_principal_euler(MASS, &body("spatial_principal_euler"));
    let principal_q =
        eom_model::spatial_principal_quaternion(MASS, &body("spatial_principal_quaternion"));
    let (e, q, i) = (&euler, &quaternion, &inputs);
    let mut rows = vec![
        Row::new(full_e, false, e.clone(), i.clone()),
        Row::new(full_q, false, q.clone(), i.clone()),
        Row::new(xz_e, false, e.clone(), i.clone()),
        Row::new(xz_q, false, q.clone(), i.clone()),
        Row::new(principal_e, false, e.clone(), i.clone()),
        Row::new(principal_q, false, q.clone(), i.clone()),
        Row::new(full_q, true, q.clone(), i.clone()),
        Row::new(xz_q, true, q.clone(), i.clone()),
        Row::new(principal_q, true, q.clone(), i.clone()),
    ];

    // The harness alone, timed in every round beside the rows.
    let floor_passes = rows[1].passes;
    let floor = || {
        let start = Instant::now();
        black_box(eom_passes(copy_state::<13>, &(), q, i, floor_passes));
        start.elapsed().as_secs_f64()
    };
    let mut floor_seconds = Vec::new();

    let load_before = proc_field("/proc/loadavg", "");
    for row in &mut rows {
        // Warm-up, not kept.
        row.time(0);
        row.seconds = Default::default();
    }
    for round in 0..ROUNDS {
        floor_seconds.push(floor());
        for row in &mut rows {
            row.time(round % 4);
        }
    }
    let load_after = proc_field("/proc/loadavg", "");

    println!("# eom against SymPy's C: ns per call, median of {ROUNDS} interleaved rounds\n");
    println!(
        "- CPU: {} (family {}, model {}), {} logical CPUs; load average {load_before} before, \
         {load_after} after",
        proc_field("/proc/cpuinfo", "model name"),
        proc_field("/proc/cpuinfo", "cpu family"),
        proc_field("/proc/cpuinfo", "model"),
        std::thread::available_parallelism().map_or(0, |n| n.get()),
    );
    println!(
        "- C: {}, `{}`",
        env!("EOM_PEER_CC"),
        env!("EOM_PEER_CFLAGS").replace(" | ", "` and `")
    );
    println!(
        "- Rust: {}, target features avx2 {}, fma {} (eom's generated `mul_add` is one fused \
         multiply–add with fma, a product and a sum without; rustc contracts nothing else)",
        env!("EOM_PEER_RUSTC"),
        cfg!(target_feature = "avx2"),
        cfg!(target_feature = "fma"),
    );
    println!(
        "- {STATES} states and inputs (seed {SEED:#x}), mass {MASS} kg, the models bench's body of \
         each symmetry class; ratio = SymPy-C / eom (above 1: eom faster), per-round range in \
         brackets; checksum: eom's, and each C build's difference from it over the sum of |out|"
    );
    println!(
        "- the harness alone (a never-inlined function returning its 13-entry state, called and \
         summed as the models are): {:.1} ns per call, included in every time below\n",
        median(&floor_seconds) / (floor_passes * STATES) as f64 * 1e9
    );
    println!(
        "| variant | ns/call eom | ns/call SymPy-C op-by-op | ns/call SymPy-C FMA | ratio vs \
         op-by-op | ratio vs FMA | ns/call eom, a user's call | checksums (eom; op-by-op, FMA \
         rel. diff.) |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---|");
    for row in &rows {
        let ratio = |c| {
            let (r, low, high) = row.ratio(c);
            format!("**{r:.2}** ({low:.2}–{high:.2})")
        };
        let diff = |c: usize| (row.checksums[c] - row.checksums[0]) / row.magnitude;
        println!(
            "| {} | {:.1} | {:.1} | {:.1} | {} | {} | {:.1} | {:.15e}; {:.0e}, {:.0e} |",
            row.label,
            row.ns_per_call(0),
            row.ns_per_call(1),
            row.ns_per_call(2),
            ratio(1),
            ratio(2),
            row.ns_per_call(3),
            row.checksums[0],
            diff(1),
            diff(2),
        );
    }
}
