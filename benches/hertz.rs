//! Timings of the Hertz solvers and of operator assembly. Short runs:
//! `cargo bench --bench hertz` (about 20 s in all).
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};
use lambdamat::hertz::operators::kappa1;
use lambdamat::hertz::{HertzOptions, solve_given_c, solve_given_mu};
use lambdamat::numeric::{Assembler, Factor, Mesh, PanelBasis};

fn hertz(c: &mut Criterion) {
    let opts = HertzOptions::default();
    let mut g = c.benchmark_group("hertz");
    g.sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(5));
    g.bench_function("given_c nu=0 c=0.5 tol=1e-10", |b| {
        b.iter(|| solve_given_c(0.0, 0.5, &opts))
    });
    g.bench_function("given_c nu=0.25 c=0.3 tol=1e-10", |b| {
        b.iter(|| solve_given_c(0.25, 0.3, &opts))
    });
    g.bench_function("given_mu nu=0.25 mu=0.1801 tol=1e-10", |b| {
        b.iter(|| solve_given_mu(0.25, 0.1801, &opts))
    });
    g.finish();
}

fn assembly(c: &mut Criterion) {
    // One κ1 matrix on a graded, weighted basis: 400 × 400 entries.
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
    let op = kappa1();
    let mut g = c.benchmark_group("assembly");
    g.sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    g.bench_function("kappa1 400x400", |b| b.iter(|| asm.matrix(&op, &x)));
    g.finish();
}

criterion_group!(benches, hertz, assembly);
criterion_main!(benches);
