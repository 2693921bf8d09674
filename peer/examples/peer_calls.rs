//! Calls one right-hand side of the peer bench many times, for counting the instructions of one
//! call with callgrind, which repeats exactly where wall time on a shared machine does not:
//!
//! ```sh
//! cargo build --release -p eom-peer --example peer_calls
//! valgrind --tool=callgrind --toggle-collect='*measured*' --callgrind-out-file=/dev/null \
//!     target/release/examples/peer_calls eom spatial_full_quaternion 1000
//! ```
//!
//! `side` is `eom`, `op` (SymPy-C op by op), `fma` (SymPy-C with FMA contraction), or
//! `op-unit` / `fma-unit` (SymPy's unit-quaternion form); `variant` one of the six spatial
//! variants. Each call goes through one `#[inline(never)]` function, `measured`, which calls
//! the right-hand side through a `fn` pointer as the bench does: collecting only inside it
//! counts the call (and the sines and cosines it calls) and nothing of the loop. The
//! difference between N = 2000 and N = 1000, over 1000, is one call. The states are the
//! bench's draws, taken in turn.

use eom_peer::{CModel, CRhs, EomModel, MASS, SEED, body, draw, eom_model, fma, op_by_op};
use std::hint::black_box;

/// The one function whose instructions are counted: it calls `f` once.
#[inline(never)]
fn measured<R>(f: impl FnOnce() -> R) -> R {
    f()
}

/// `calls` calls of eom's model over the draws; returns the sum of every output.
fn eom<K, const N: usize>(
    model: EomModel<K, N>,
    states: &[[f64; N]],
    inputs: &[[f64; 6]],
    calls: usize,
) -> f64 {
    let f = black_box(model.rhs);
    let mut sum = 0.0;
    for i in 0..calls {
        let j = i % states.len();
        let (x, u) = (black_box(&states[j]), black_box(&inputs[j]));
        sum += measured(|| f(&model.k, x, u)).iter().sum::<f64>();
    }
    sum
}

/// `calls` calls of a C model over the draws; returns the sum of every output.
fn c<const N: usize>(
    model: &CModel,
    unit: bool,
    states: &[[f64; N]],
    inputs: &[[f64; 6]],
    calls: usize,
) -> f64 {
    assert_eq!(model.state_len, N);
    let k = model.coefficients(&eom_peer::parameters(MASS, &body(model.name)));
    let f: CRhs = black_box(if unit {
        model.unit_fn.expect("a quaternion variant")
    } else {
        model.rhs_fn
    });
    let mut sum = 0.0;
    let mut out = [0.0; N];
    for i in 0..calls {
        let j = i % states.len();
        let (x, u) = (black_box(&states[j]), black_box(&inputs[j]));
        // SAFETY: `k` and `N` are the lengths the C reads and writes (asserted above).
        measured(|| unsafe { f(k.as_ptr(), x.as_ptr(), u.as_ptr(), out.as_mut_ptr()) });
        sum += out.iter().sum::<f64>();
    }
    sum
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let side = args.get(1).map_or("eom", String::as_str);
    let variant = args
        .get(2)
        .map_or("spatial_full_quaternion", String::as_str);
    let calls: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(1000);
    let draws = draw(1024, SEED);
    let euler: Vec<[f64; 12]> = draws.iter().map(|d| d.euler).collect();
    let quaternion: Vec<[f64; 13]> = draws.iter().map(|d| d.quaternion).collect();
    let inputs: Vec<[f64; 6]> = draws.iter().map(|d| d.input).collect();
    let (e, q, i) = (&euler[..], &quaternion[..], &inputs[..]);
    let b = body;
    let sum = match side {
        "eom" => match variant {
            "spatial_full_euler" => Some(eom(
                eom_model::spatial_full_euler(MASS, &b(variant)),
                e,
                i,
                calls,
            )),
            "spatial_full_quaternion" => Some(eom(
                eom_model::spatial_full_quaternion(MASS, &b(variant)),
                q,
                i,
                calls,
            )),
            "spatial_xz_euler" => Some(eom(
                eom_model::spatial_xz_euler(MASS, &b(variant)),
                e,
                i,
                calls,
            )),
            "spatial_xz_quaternion" => Some(eom(
                eom_model::spatial_xz_quaternion(MASS, &b(variant)),
                q,
                i,
                calls,
            )),
            "spatial_principal_euler" => Some(eom(
                eom_model::spatial_principal_euler(MASS, &b(variant)),
                e,
                i,
                calls,
            )),
            "spatial_principal_quaternion" => Some(eom(
                eom_model::spatial_principal_quaternion(MASS, &b(variant)),
                q,
                i,
                calls,
            )),
            _ => None,
        },
        "op" | "fma" | "op-unit" | "fma-unit" => {
            let models = if side.starts_with("op") {
                &op_by_op::MODELS
            } else {
                &fma::MODELS
            };
            let unit = side.ends_with("unit");
            models
                .iter()
                .find(|m| m.name == variant)
                .and_then(|m| match m.state_len {
                    12 if !unit => Some(c(m, false, e, i, calls)),
                    13 => Some(c(m, unit, q, i, calls)),
                    _ => None,
                })
        }
        _ => None,
    };
    match sum {
        Some(sum) => println!("{side} {variant}: {calls} calls (checksum {sum:.6})"),
        None => {
            eprintln!(
                "usage: peer_calls eom|op|fma|op-unit|fma-unit VARIANT [CALLS]; see the source"
            );
            std::process::exit(2);
        }
    }
}
