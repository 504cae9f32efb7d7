//! `lambdamat codegen`: the generated solvers are checked in as golden
//! files (`examples/mms_solver.rs`, also built by `cargo test` as an
//! example program, and `tests/data/codegen_terms_solver.rs`, which uses
//! every kind of operator term). This file regenerates them and demands
//! identical text, compiles them as modules of this test, runs them, and
//! compares their answers with the in-process solve of the same `.lmx` to
//! 1e-12 for every method. It also checks the exact manufactured answer
//! and the command's errors.

mod common;

use common::cli::{lambdamat, lmx_file};
use lambdamat::lang::parse_program;
use lambdamat::plan::{CompiledSystem, Method, SolveOptions, SolveReport, solve_system};

#[allow(dead_code)]
#[path = "../examples/mms_solver.rs"]
mod mms_solver;

#[allow(dead_code)]
#[path = "data/codegen_terms_solver.rs"]
mod terms_solver;

#[allow(dead_code)]
#[path = "data/codegen_functions_solver.rs"]
mod functions_solver;

#[allow(dead_code)]
#[path = "data/codegen_condition_solver.rs"]
mod condition_solver;

/// `lambdamat codegen SOURCE -o tmp` must give exactly the checked-in file.
fn assert_regenerates(source: &str, golden: &str) {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("solver.rs");
    lambdamat()
        .args(["codegen", source, "-o"])
        .arg(&out)
        .assert()
        .success();
    let fresh = std::fs::read_to_string(&out).expect("written");
    let checked_in = std::fs::read_to_string(golden).expect("golden file");
    assert!(
        fresh == checked_in,
        "{golden} is stale: regenerate it with `lambdamat codegen {source} -o {golden}`"
    );
    // Standard output carries the same text.
    let out = lambdamat()
        .args(["codegen", source])
        .output()
        .expect("runs");
    assert!(out.status.success());
    assert_eq!(String::from_utf8(out.stdout).expect("utf-8"), checked_in);
}

#[test]
fn generated_solvers_are_up_to_date() {
    assert_regenerates("examples/mms.lmx", "examples/mms_solver.rs");
    assert_regenerates(
        "tests/data/codegen_terms.lmx",
        "tests/data/codegen_terms_solver.rs",
    );
    assert_regenerates(
        "tests/data/codegen_functions.lmx",
        "tests/data/codegen_functions_solver.rs",
    );
    assert_regenerates(
        "tests/data/codegen_condition.lmx",
        "tests/data/codegen_condition_solver.rs",
    );
}

fn in_process(source: &str) -> CompiledSystem {
    let text = std::fs::read_to_string(source).expect("source");
    let prog = parse_program(&text, source).expect("parses");
    CompiledSystem::from_program(&prog, None).expect("compiles")
}

/// Largest difference between two reports, relative to the size of each
/// compared quantity (at least 1).
fn distance(a: &SolveReport, b: &SolveReport) -> f64 {
    assert_eq!(a.level, b.level, "same refinement level");
    assert_eq!(a.unknowns.len(), b.unknowns.len());
    let mut d: f64 = 0.0;
    for (ua, ub) in a.unknowns.iter().zip(&b.unknowns) {
        assert_eq!((&ua.name, &ua.x, &ua.weight), (&ub.name, &ub.x, &ub.weight));
        for (x, y) in ua.values.iter().zip(&ub.values) {
            d = d.max((x - y).abs() / y.abs().max(1.0));
        }
    }
    for ((na, va), (nb, vb)) in a.outputs.iter().zip(&b.outputs) {
        assert_eq!(na, nb);
        assert_eq!(va.is_some(), vb.is_some(), "output {na}");
        if let (Some(x), Some(y)) = (va, vb) {
            d = d.max((x - y).abs() / y.abs().max(1.0));
        }
    }
    let (ea, eb) = (a.error_estimate, b.error_estimate);
    d = d.max((ea - eb).abs() / eb.abs().max(1.0));
    for (da, db) in a.commutator_defects.iter().zip(&b.commutator_defects) {
        assert_eq!(da.pair, db.pair);
        for (x, y) in [
            (da.defect, db.defect),
            (da.defect_on_solution, db.defect_on_solution),
        ] {
            assert_eq!(x.is_some(), y.is_some());
            if let (Some(x), Some(y)) = (x, y) {
                d = d.max((x - y).abs() / y.abs().max(1.0));
            }
        }
    }
    d
}

fn compare(source: &str, generated: &CompiledSystem) {
    let here = in_process(source);
    assert_eq!(generated.target, here.target);
    assert_eq!(generated.domain, here.domain);
    assert_eq!(generated.interior, here.interior);
    assert_eq!(generated.conditions.len(), here.conditions.len());
    for method in [Method::Coupled, Method::Ordered, Method::Commutative] {
        if method == Method::Commutative && !here.conditions.is_empty() {
            // The single-equation model takes no side conditions.
            assert!(
                solve_system(
                    generated,
                    &SolveOptions {
                        method,
                        ..SolveOptions::default()
                    }
                )
                .is_err()
            );
            continue;
        }
        let opts = SolveOptions {
            method,
            ..SolveOptions::default()
        };
        let a = solve_system(generated, &opts).expect("generated solver solves");
        let b = solve_system(&here, &opts).expect("in-process solve");
        let d = distance(&a, &b);
        println!("{source} {method}: generated vs in-process {d:e}");
        assert!(
            d <= 1e-12,
            "{source} {method}: generated vs in-process {d:e}"
        );
    }
}

#[test]
fn generated_mms_solver_matches_the_in_process_solve() {
    let sys = mms_solver::system().expect("generated system is consistent");
    compare("examples/mms.lmx", &sys);
    // And it solves the manufactured problem: p = 1, q = x.
    let r = solve_system(&sys, &SolveOptions::default()).expect("solves");
    assert!(r.converged);
    for u in &r.unknowns {
        let exact = |x: f64| if u.name == "p" { 1.0 } else { x };
        let err =
            u.x.iter()
                .zip(&u.values)
                .map(|(&x, v)| (v - exact(x)).abs())
                .fold(0.0, f64::max);
        assert!(err <= 1e-10, "{}: max error {err:e}", u.name);
    }
}

#[test]
fn generated_solver_with_every_term_kind_matches() {
    let sys = terms_solver::system().expect("generated system is consistent");
    compare("tests/data/codegen_terms.lmx", &sys);
}

/// The pivots (equation, unknown), 0-based, of `reduce --json`'s steps.
fn reduce_pivots(source: &str, unknowns: &[String]) -> Vec<(usize, usize)> {
    let v = common::cli::json(&["reduce", source]);
    v["ordered_steps"]["steps"]
        .as_array()
        .expect("steps")
        .iter()
        .map(|s| {
            let e = s["equation"].as_u64().expect("equation") as usize - 1;
            let u = s["unknown"].as_str().expect("unknown");
            (e, unknowns.iter().position(|x| x == u).expect("declared"))
        })
        .collect()
}

#[test]
fn generated_solvers_embed_the_derivation_reduce_prints() {
    for (source, sys) in [
        (
            "examples/mms.lmx",
            mms_solver::system().expect("consistent"),
        ),
        (
            "tests/data/codegen_terms.lmx",
            terms_solver::system().expect("consistent"),
        ),
    ] {
        let here = in_process(source);
        assert_eq!(
            here.derived_pivots, None,
            "compiled in process: nothing embedded"
        );
        let embedded = sys.derived_pivots.clone().expect("embedded pivots");
        let derived = here.derivation().expect("derivation").pivot_order();
        assert_eq!(embedded, derived, "{source}");
        assert_eq!(embedded, reduce_pivots(source, &sys.unknowns), "{source}");
        // A solver whose embedded derivation is not the one this lambdamat
        // derives refuses to run rather than run something else.
        let mut stale = sys.clone();
        stale.derived_pivots = Some(vec![(0, 1 - sys.target)]);
        let opts = SolveOptions::default();
        let err = solve_system(&stale, &opts).expect_err("refused");
        assert!(err.to_string().contains("regenerate it"), "{err}");
    }
    // The 20-unknown system: the generated text embeds the steps' pivots.
    let source = "tests/data/twenty_unknowns.lmx";
    let code = common::cli::stdout(&["codegen", source]);
    let list = code
        .split("derived_pivots: Some(vec![")
        .nth(1)
        .and_then(|rest| rest.split("])").next())
        .expect("derived_pivots in the generated code");
    let embedded: Vec<(usize, usize)> = list
        .split(['(', ')', ','])
        .map(str::trim)
        .filter(|t| !t.is_empty())
        .map(|t| t.parse::<usize>().expect("index"))
        .collect::<Vec<_>>()
        .chunks(2)
        .map(|c| (c[0], c[1]))
        .collect();
    let here = in_process(source);
    assert_eq!(embedded.len(), 19);
    assert_eq!(embedded, reduce_pivots(source, &here.unknowns));
    assert!(code.contains("//!   pivots: u2 from equation 2; u3 from equation 3;"));
}

#[test]
fn generated_solver_with_every_function_matches() {
    let sys = functions_solver::system().expect("generated system is consistent");
    compare("tests/data/codegen_functions.lmx", &sys);
}

#[test]
fn generated_solver_with_a_side_condition_matches() {
    let sys = condition_solver::system().expect("generated system is consistent");
    compare("tests/data/codegen_condition.lmx", &sys);
    // f(1/2) = (1/2 + 2/π)/√(3/4).
    let r = solve_system(&sys, &SolveOptions::default()).expect("solves");
    let v = r.outputs[0].1.expect("V");
    let exact = (0.5 + 2.0 / std::f64::consts::PI) / 0.75f64.sqrt();
    assert!(r.converged && (v - exact).abs() < 1e-10, "{v} vs {exact}");
}

#[test]
fn codegen_for_picks_the_target_and_errors_are_clear() {
    let src = "examples/mms.lmx";
    let out = lambdamat()
        .args(["codegen", src, "--for", "q"])
        .output()
        .expect("runs");
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).expect("utf-8");
    assert!(text.contains("        target: 1,"), "target q");
    assert!(text.contains("--for q -o FILE.rs"), "header names --for");

    // Not an unknown: invalid input.
    refused(&["codegen", src, "--for", "r"], "r is not an unknown");
    // Abstract symbols have no kernels to generate.
    let var = lmx_file("var k\nunknown p\nequation k p = x\n");
    // Unsupported kernels are refused as `solve` refuses them.
    let singular = lmx_file("operator k = int(0..1) 1/(t - x)^2 dt\nunknown p\nequation k p = 1\n");
    // Syntax errors carry line and column.
    let syntax = lmx_file("unknown p\nequation p = (x\n");
    for (f, needle) in [
        (&var, "`var`"),
        (&singular, "operator k:"),
        (&syntax, ".lmx:3:1"),
    ] {
        let path = f.path().to_str().expect("utf-8 path");
        refused(&["codegen", path], needle);
    }
}

/// `lambdamat ARGS` exits 2 with `needle` on standard error and nothing on
/// standard output.
fn refused(args: &[&str], needle: &str) {
    let out = lambdamat().args(args).output().expect("runs");
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(err.contains(needle), "{args:?}: {err}");
    assert!(out.stdout.is_empty(), "{args:?}");
}
