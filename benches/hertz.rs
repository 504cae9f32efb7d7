//! Timings of what `lambdamat hertz` runs (the front: the embedded
//! language files through the general solver and the report) and of
//! operator assembly. Short runs: `cargo bench --bench hertz`.
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};
use lambdamat::hertz::front::{Given, solve};
use lambdamat::numeric::{Assembler, Factor, Mesh, Operator, PanelBasis};
use lambdamat::plan::SplitOptions;

fn hertz(c: &mut Criterion) {
    let opts = SplitOptions::default();
    let mut g = c.benchmark_group("hertz");
    g.sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(5));
    g.bench_function("front given_c nu=0 c=0.5 tol=1e-10", |b| {
        b.iter(|| solve(0.0, Given::C(0.5), &opts))
    });
    g.bench_function("front given_c nu=0.25 c=0.3 tol=1e-10", |b| {
        b.iter(|| solve(0.25, Given::C(0.3), &opts))
    });
    g.bench_function("front given_mu nu=0.25 mu=0.1801 tol=1e-10", |b| {
        b.iter(|| solve(0.25, Given::Mu(0.1801), &opts))
    });
    g.finish();
}

fn assembly(c: &mut Criterion) {
    // One κ1 matrix (`∫_x^1 t f(t)/√(t²-x²) dt`) on a graded, weighted
    // basis: 400 × 400 entries.
    let mesh = Mesh::uniform(0.0, 1.0, 40).unwrap();
    let basis = PanelBasis::new(
        &mesh,
        &[10; 40],
        vec![Factor {
            at: 1.0,
            exponent: -0.4,
        }],
    )
    .unwrap();
    let asm = Assembler::new(&basis).unwrap();
    let x = basis.nodes();
    let op = Operator::abel_upper(1.0, |_x, t| t);
    let mut g = c.benchmark_group("assembly");
    g.sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    g.bench_function("kappa1 400x400", |b| b.iter(|| asm.matrix(&op, &x)));
    g.finish();
}

criterion_group!(benches, hertz, assembly);
criterion_main!(benches);
