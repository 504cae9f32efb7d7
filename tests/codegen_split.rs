//! `lambdamat codegen` for split-domain (contact) files: the generated
//! Hertz solver is checked in as `examples/hertz_solver.rs` (built by
//! `cargo test` as an example program). This file regenerates it and
//! demands identical text, compiles it as a module of this test, and
//! compares its solve with the in-process `solve` of `examples/hertz.lmx`
//! bit for bit (every scalar, output, coefficient, estimate and
//! diagnostic), at tol 1e-10. It also checks that `--set` reaches the
//! generated text.

mod common;

use common::cli::lambdamat;
use lambdamat::lang::parse_program;
use lambdamat::plan::split_solve::Estimate;
use lambdamat::plan::{SplitOptions, SplitReport, solve_split, solve_split_input};

#[allow(dead_code)]
#[path = "../examples/hertz_solver.rs"]
mod hertz_solver;

#[allow(dead_code)]
#[path = "../examples/punch_torsion_solver.rs"]
mod punch_torsion_solver;

#[test]
fn generated_hertz_solver_is_up_to_date() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("solver.rs");
    lambdamat()
        .args(["codegen", "examples/hertz.lmx", "-o"])
        .arg(&out)
        .assert()
        .success();
    let fresh = std::fs::read_to_string(&out).expect("written");
    let golden = std::fs::read_to_string("examples/hertz_solver.rs").expect("golden");
    assert!(
        fresh == golden,
        "examples/hertz_solver.rs is stale: regenerate it with \
         `lambdamat codegen examples/hertz.lmx -o examples/hertz_solver.rs`"
    );
}

fn same_bits(what: &str, a: &[Estimate], b: &[Estimate]) {
    assert_eq!(a.len(), b.len(), "{what}");
    for (x, y) in a.iter().zip(b) {
        assert_eq!(x.name, y.name, "{what}");
        assert_eq!(
            x.value.to_bits(),
            y.value.to_bits(),
            "{what} {}: generated {} vs in-process {}",
            x.name,
            x.value,
            y.value
        );
        assert_eq!(
            x.error.to_bits(),
            y.error.to_bits(),
            "{what} {} estimate: generated {} vs in-process {}",
            x.name,
            x.error,
            y.error
        );
    }
}

fn assert_identical(a: &SplitReport, b: &SplitReport) {
    same_bits("scalar", &a.scalars, &b.scalars);
    same_bits("output", &a.outputs, &b.outputs);
    same_bits("coefficient", &a.coefficients, &b.coefficients);
    assert_eq!(a.error_estimate.to_bits(), b.error_estimate.to_bits());
    assert_eq!(a.converged, b.converged);
    assert_eq!((a.levels, a.dim), (b.levels, b.dim));
    assert_eq!(a.cond.to_bits(), b.cond.to_bits());
    assert_eq!(a.singular_exponents.len(), b.singular_exponents.len());
    for (x, y) in a.singular_exponents.iter().zip(&b.singular_exponents) {
        assert_eq!(x.0, y.0);
        assert_eq!(
            (x.1.to_bits(), x.2.to_bits()),
            (y.1.to_bits(), y.2.to_bits())
        );
    }
}

#[test]
fn generated_hertz_solver_matches_the_in_process_solve_bit_for_bit() {
    let text = std::fs::read_to_string("examples/hertz.lmx").expect("source");
    let prog = parse_program(&text, "examples/hertz.lmx").expect("parses");
    let opts = SplitOptions {
        tol: 1e-10,
        ..SplitOptions::default()
    };
    let here = solve_split(&prog, &opts).expect("in-process solve");
    let input = hertz_solver::input().expect("generated input is consistent");
    let generated = solve_split_input(input, &opts).expect("generated solver solves");
    assert!(generated.converged, "tol 1e-10 reached");
    assert_identical(&generated, &here);
    // The answer is the Hertz problem's (ν = 1/4, μ = 0.1801; the
    // hand-written solver gives c = 0.495646720757209): a bounded shear
    // (B = 0) and the two compliance formulas agree.
    let c = generated.scalars[0].value;
    assert!((c - 0.495646720757209).abs() <= 1e-9, "c = {c}");
    let (p, ps) = (generated.outputs[0].value, generated.outputs[1].value);
    assert!((p - ps).abs() <= 1e-10, "P = {p}, P_shear = {ps}");
    assert!(generated.coefficients[0].value.abs() <= 1e-10);
}

#[test]
fn generated_torsion_solver_matches_the_in_process_solve_bit_for_bit() {
    // The second contact problem (tests/contact_torsion.rs checks its
    // closed form): a different operator, right side and relation.
    let text = std::fs::read_to_string("examples/punch_torsion.lmx").expect("source");
    let prog = parse_program(&text, "examples/punch_torsion.lmx").expect("parses");
    let opts = SplitOptions {
        tol: 1e-10,
        ..SplitOptions::default()
    };
    let here = solve_split(&prog, &opts).expect("in-process solve");
    let input = punch_torsion_solver::input().expect("generated input is consistent");
    let generated = solve_split_input(input, &opts).expect("generated solver solves");
    assert!(generated.converged, "tol 1e-10 reached");
    assert_identical(&generated, &here);
}

#[test]
fn set_overrides_reach_the_generated_solver() {
    let out = lambdamat()
        .args(["codegen", "examples/hertz.lmx", "--set", "mu=1/5"])
        .output()
        .expect("runs");
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).expect("utf-8");
    assert!(
        text.contains("regenerate with `lambdamat codegen examples/hertz.lmx --set mu=1/5 -o"),
        "header names the override"
    );
    assert!(text.contains("fn const_1_5(_v: &[f64], _x: f64) -> f64 {\n    0.2\n}"));
    assert!(text.contains("coeff: RealFn::new(const_1_5),"));
    // What solve refuses about the split declarations, codegen refuses.
    let bad = common::cli::lmx_file(
        "unknown p on [0, 1]\nscalar c in (0, 1)\noperator k = int(x..1) dt\n\
         equation k p = 1 on [0, c)\n",
    );
    let path = bad.path().to_str().expect("utf-8 path");
    let solve = lambdamat().args(["solve", path]).output().expect("runs");
    let gen_ = lambdamat().args(["codegen", path]).output().expect("runs");
    assert_eq!(solve.status.code(), Some(2));
    assert_eq!(gen_.status.code(), Some(2));
    assert!(gen_.stdout.is_empty());
}
