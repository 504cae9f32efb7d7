//! Timings of `lambdamat solve` through the language path (parse excluded):
//! the manufactured coupled system at tol 1e-10 by each method, and the
//! punch at tol 1e-12. `cargo bench --bench solve` (about 15 s).
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};
use lambdamat::plan::{Method, SolveOptions, solve_program};

fn solve(c: &mut Criterion) {
    let mms = lambdamat::lang::parse_program(include_str!("../examples/mms.lmx"), "mms.lmx")
        .expect("example parses");
    let punch = lambdamat::lang::parse_program(include_str!("../examples/punch.lmx"), "punch.lmx")
        .expect("example parses");
    let mut g = c.benchmark_group("solve");
    g.sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    for method in [Method::Coupled, Method::Ordered, Method::Commutative] {
        let opts = SolveOptions {
            method,
            ..SolveOptions::default()
        };
        g.bench_function(format!("mms {method} tol=1e-10"), |b| {
            b.iter(|| solve_program(&mms, &opts))
        });
    }
    let opts = SolveOptions {
        tol: 1e-12,
        ..SolveOptions::default()
    };
    g.bench_function("punch ordered tol=1e-12", |b| {
        b.iter(|| solve_program(&punch, &opts))
    });
    g.finish();
}

criterion_group!(benches, solve);
criterion_main!(benches);
