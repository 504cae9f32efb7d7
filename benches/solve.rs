//! Timings of `lambdamat solve` through the language path (parse excluded):
//! the manufactured coupled system at tol 1e-10 by each method, and the
//! punch at tol 1e-12, all through `report::solve` (the one solver); and
//! the problems written by `lambdamat codegen` (kernels as Rust functions)
//! against the same files compiled to closures in process; `reduce` and `codegen` on a 20-unknown system.
//! `cargo bench --bench solve` (about 40 s).
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};
use lambdamat::plan::{Method, SplitInput};
use lambdamat::report::{SolveSettings, solve as solve_file, solve_split};

#[allow(dead_code)]
#[path = "../examples/mms_solver.rs"]
mod mms_solver;

#[allow(dead_code)]
#[path = "../tests/data/codegen_terms_solver.rs"]
mod terms_solver;

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
        let settings = SolveSettings {
            method: Some(method),
            ..SolveSettings::default()
        };
        g.bench_function(format!("mms {method} tol=1e-10"), |b| {
            b.iter(|| solve_file(&mms, &settings))
        });
    }
    let settings = SolveSettings {
        tol: 1e-12,
        ..SolveSettings::default()
    };
    g.bench_function("punch coupled tol=1e-12", |b| {
        b.iter(|| solve_file(&punch, &settings))
    });
    g.finish();
}

/// Generated kernels (Rust functions) vs closures compiled in process, on
/// the same refinement ladder (the answers are bit for bit equal; see
/// `tests/codegen.rs`).
fn generated(c: &mut Criterion) {
    let parsed = |src: &str, name: &str| lambdamat::lang::parse_program(src, name).expect("parses");
    type Input = fn() -> Result<SplitInput, lambdamat::plan::PlanError>;
    let cases: [(&str, _, Input); 2] = [
        (
            "mms",
            parsed(include_str!("../examples/mms.lmx"), "mms.lmx"),
            mms_solver::input,
        ),
        (
            "codegen_terms",
            parsed(
                include_str!("../tests/data/codegen_terms.lmx"),
                "codegen_terms.lmx",
            ),
            terms_solver::input,
        ),
    ];
    let mut g = c.benchmark_group("codegen");
    g.sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    let settings = SolveSettings::default();
    for (name, closures, generated) in &cases {
        g.bench_function(format!("{name} closures"), |b| {
            b.iter(|| solve_file(closures, &settings))
        });
        g.bench_function(format!("{name} generated"), |b| {
            b.iter(|| solve_split(generated().expect("generated"), &settings))
        });
    }
    g.finish();
}

/// `reduce` and `codegen` on the 20-unknown system of issue 9: the
/// derivation bounds the eliminant before expanding it (goal: well under
/// a second each).
fn twenty_unknowns(c: &mut Criterion) {
    let src = include_str!("../tests/data/twenty_unknowns.lmx");
    let prog = lambdamat::lang::parse_program(src, "twenty.lmx").expect("parses");
    let from = lambdamat::codegen::Provenance {
        source: "twenty.lmx".into(),
        command: "lambdamat codegen twenty.lmx".into(),
    };
    let mut g = c.benchmark_group("twenty unknowns");
    g.sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    g.bench_function("derivation (bound + ordered steps)", |b| {
        b.iter(|| lambdamat::reduce::derive(&prog, 0))
    });
    g.bench_function("reduce", |b| b.iter(|| lambdamat::reduce::reduce(&prog, 0)));
    g.bench_function("reduce + text with the steps", |b| {
        b.iter(|| {
            let r = lambdamat::reduce::reduce(&prog, 0).expect("reduces");
            lambdamat::report::reduction::text(&r)
        })
    });
    g.bench_function("codegen", |b| {
        b.iter(|| lambdamat::codegen::solver_source(&prog, None, &from))
    });
    g.finish();
}

criterion_group!(benches, solve, generated, twenty_unknowns);
criterion_main!(benches);
