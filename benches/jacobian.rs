//! The emitted Jacobians against the dual-number route, per evaluation of both ∂f/∂x and
//! ∂f/∂u, for every model of the catalog: the two proved straight-line programs, against
//! N + M calls of `rhs` over dual numbers (num-dual, one seeded entry each).
//!
//! ```sh
//! cargo bench --bench jacobian
//! ```
//!
//! docs/linear.md gathers the medians with the operation counts.

use criterion::{Criterion, criterion_group, criterion_main};
use eom::models::Model;
use eom_test_support::jacobian::{Sink, by_dual_numbers, each_model, emitted, point};
use num_dual::Dual64;
use std::hint::black_box;

struct Bench<'a>(&'a mut Criterion);

impl Sink for Bench<'_> {
    fn model<Mo, Md, const N: usize, const M: usize>(&mut self, name: &str, model: &Mo, dual: &Md)
    where
        Mo: Model<f64, N, M>,
        Md: Model<Dual64, N, M>,
    {
        let (state, input) = point::<N, M>();
        let mut group = self.0.benchmark_group(format!("jacobian/{name}"));
        group.bench_function("emitted", |b| {
            b.iter(|| emitted(model, black_box(&state), black_box(&input)))
        });
        group.bench_function("dual_numbers", |b| {
            b.iter(|| by_dual_numbers(dual, black_box(&state), black_box(&input)))
        });
        group.finish();
    }
}

fn jacobians(c: &mut Criterion) {
    each_model(&mut Bench(c));
}

criterion_group!(benches, jacobians);
criterion_main!(benches);
