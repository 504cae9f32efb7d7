//! Criterion benchmarks of the Smith engine: the peer matrices of
//! `../shared/bench/smith_peers.py` (random over Q[x], transforms and
//! certificate included) and the seed λ-matrix in its two multivariate
//! modes. Ratios against PARI/GP and SymPy are measured by `benches/peers.sh`.

use criterion::{Criterion, criterion_group, criterion_main};
use lambdamat::algebra::matrix::Matrix;
use lambdamat::algebra::polyring::PolyRing;
use lambdamat::algebra::smith::modes::{SmithOptions, smith_report};
use lambdamat::lang::parse_program;
use std::hint::black_box;

fn first_matrix(path: &str) -> Matrix<PolyRing> {
    let src = std::fs::read_to_string(path).expect("bench data");
    let p = parse_program(&src, path).expect("valid bench data");
    let m = &p.matrices[0];
    Matrix::new(
        PolyRing::new(p.symbols.clone()),
        m.rows,
        m.cols,
        m.entries.clone(),
    )
}

fn peers(c: &mut Criterion) {
    let mut g = c.benchmark_group("smith_qx");
    g.sample_size(10);
    for case in ["10_2_1", "8_4_1", "12_3_1"] {
        let a = first_matrix(&format!("benches/data/peers_{case}.lmx"));
        g.bench_function(case, |b| {
            b.iter(|| {
                smith_report("A", black_box(&a), &SmithOptions::default()).expect("certified")
            })
        });
    }
    g.finish();
}

fn seed(c: &mut Criterion) {
    let a = first_matrix("examples/seed_lambda.lmx");
    let mut g = c.benchmark_group("smith_seed");
    g.bench_function("determinantal_divisors", |b| {
        b.iter(|| smith_report("A", black_box(&a), &SmithOptions::default()).expect("certified"))
    });
    let opts = SmithOptions {
        principal: Some(3),
        latex: false,
    };
    g.bench_function("principal_k4", |b| {
        b.iter(|| smith_report("A", black_box(&a), &opts).expect("certified"))
    });
    g.finish();
}

criterion_group!(benches, peers, seed);
criterion_main!(benches);
