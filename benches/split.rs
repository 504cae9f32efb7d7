//! The Hertz problem through the language (`examples/hertz.lmx`,
//! `examples/hertz_given_c.lmx`, the split-domain solver) beside the
//! hand-written solver, in the same run, at tol 1e-10, and the `hertz`
//! front (the same files plus field sampling and the stick/slip checks,
//! what `lambdamat hertz` runs). Short runs:
//! `cargo bench --bench split -- --warm-up-time 1 --measurement-time 3`.
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};
use lambdamat::hertz::front::{Given, solve};
#[path = "../tests/common/hertz_oracle/mod.rs"]
mod hertz_oracle;
use hertz_oracle::{HertzOptions, solve_given_c, solve_given_mu};
use lambdamat::lang::parse_program_with;
use lambdamat::lang::parser::parse_exact;
use lambdamat::plan::{SplitOptions, solve_split};

fn program(path: &str, sets: &[(&str, &str)]) -> lambdamat::lang::Program {
    let src = std::fs::read_to_string(path).expect("example");
    let sets: Vec<_> = sets
        .iter()
        .map(|(n, v)| (n.to_string(), parse_exact(v).expect("exact")))
        .collect();
    parse_program_with(&src, path, &sets).expect("valid")
}

fn split(c: &mut Criterion) {
    let opts = SplitOptions::default();
    let hopts = HertzOptions::default();
    let given_mu = program("examples/hertz.lmx", &[("nu", "0.25"), ("mu", "0.1801")]);
    let given_c = program("examples/hertz_given_c.lmx", &[("nu", "0"), ("c", "0.5")]);
    let mut g = c.benchmark_group("split");
    g.sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    g.bench_function("language (nu,mu)=(0.25,0.1801)", |b| {
        b.iter(|| solve_split(&given_mu, &opts))
    });
    g.bench_function("front (nu,mu)=(0.25,0.1801)", |b| {
        b.iter(|| solve(0.25, Given::Mu(0.1801), &opts))
    });
    g.bench_function("built-in (nu,mu)=(0.25,0.1801)", |b| {
        b.iter(|| solve_given_mu(0.25, 0.1801, &hopts))
    });
    g.bench_function("language (nu,c)=(0,0.5)", |b| {
        b.iter(|| solve_split(&given_c, &opts))
    });
    g.bench_function("front (nu,c)=(0,0.5)", |b| {
        b.iter(|| solve(0.0, Given::C(0.5), &opts))
    });
    g.bench_function("built-in (nu,c)=(0,0.5)", |b| {
        b.iter(|| solve_given_c(0.0, 0.5, &hopts))
    });
    // The ends of the physical range (issue 13): a stick zone of 2e-8,
    // a slip annulus of 4.3e-7 (the slowest point of the sweep), ν < 0.
    for (nu, mu) in [("0", "0.03"), ("0.3", "100"), ("-0.9", "100")] {
        let prog = program("examples/hertz.lmx", &[("nu", nu), ("mu", mu)]);
        g.bench_function(format!("language (nu,mu)=({nu},{mu})"), |b| {
            b.iter(|| solve_split(&prog, &opts))
        });
    }
    g.finish();
}

/// The points of the issue-13 sweep (−0.9 ≤ ν ≤ 0.5, 0.01 ≤ μ ≤ 100) that
/// were slowest (c near 1) beside Spence's and Kalker's mid-range cases and
/// the smallest stick zone, through the `hertz` front (what `lambdamat
/// hertz` and `hertz sweep` run per point), at tol 1e-10. The goal is at
/// most 0.5 s CPU per point. The last seven are the near-full-stick points
/// (1 − c from 4.6e-5 down to 1.6e-12, where one ulp of c is more than the
/// root moves between levels) that took 0.5–0.7 s before the warm start
/// learned to step by at least the map's ulps. Run alone:
/// `cargo bench --bench split -- sweep_points --warm-up-time 1 --measurement-time 3`;
/// the CPU time of every point of the sweep: `benches/sweep_times.py`.
fn sweep_points(c: &mut Criterion) {
    let opts = SplitOptions::default();
    let mut g = c.benchmark_group("sweep_points");
    g.sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    for (nu, mu) in [
        (0.3, 100.0),
        (0.0, 100.0),
        (-0.9, 10.0),
        (0.3, 2.154),
        (-0.6, 100.0),
        (0.1, 1.0),
        (0.25, 0.1801),
        (0.0, 0.2986),
        (0.0, 0.03),
        (0.4, 4.641588833612779),
        (0.4, 10.0),
        (0.4, 21.54434690031882),
        (0.4, 46.41588833612773),
        (0.4, 100.0),
        (-0.4, 21.54434690031882),
        (0.2, 10.0),
    ] {
        g.bench_function(format!("front (nu,mu)=({nu},{mu})"), |b| {
            b.iter(|| solve(nu, Given::Mu(mu), &opts))
        });
    }
    g.finish();
}

criterion_group!(benches, split, sweep_points);
criterion_main!(benches);
