//! How long the build-time step takes: derive every equation and prove it against the book.

use criterion::{Criterion, criterion_group, criterion_main};

fn derive_and_check(c: &mut Criterion) {
    c.bench_function("derive_and_check_all_equations", |b| {
        b.iter(|| eom_codegen::check::check_all().expect("every equation proves"))
    });
}

criterion_group!(benches, derive_and_check);
criterion_main!(benches);
