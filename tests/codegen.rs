//! `lambdamat codegen`: the generated solvers are checked in as golden
//! files (`examples/mms_solver.rs`, also built by `cargo test` as an
//! example program, and `tests/data/codegen_terms_solver.rs`, which uses
//! every kind of operator term). This file regenerates them and demands
//! identical text, compiles them as modules of this test, runs them, and
//! compares their reports with the in-process solve of the same `.lmx`
//! bit for bit for every method. It also checks the exact manufactured answer
//! and the command's errors.

mod common;

use common::cli::{lambdamat, lmx_file};
use lambdamat::lang::parse_program;
use lambdamat::plan::{CompiledSystem, Method, PlanError, SplitInput};
use lambdamat::report::{SolveSettings, solve, solve_split};
use lambdamat::system::Program;

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

fn program(source: &str) -> Program {
    let text = std::fs::read_to_string(source).expect("source");
    parse_program(&text, source).expect("parses")
}

fn in_process(source: &str) -> CompiledSystem {
    SplitInput::from_program(&program(source))
        .expect("compiles")
        .sys
}

/// The generated solver's solve and the in-process one for every method
/// print the same report, bit for bit (JSON numbers are printed to read
/// back exactly), or are refused with the same message.
fn compare(source: &str, generated: fn() -> Result<SplitInput, PlanError>) {
    let prog = program(source);
    let (g, here) = (generated().expect("consistent"), in_process(source));
    assert_eq!(g.sys.target, here.target);
    assert_eq!(g.sys.domain, here.domain);
    assert_eq!(g.sys.interior, here.interior);
    assert_eq!(g.sys.conditions.len(), here.conditions.len());
    let mut solved = 0;
    for method in [Method::Coupled, Method::Ordered, Method::Commutative] {
        let s = SolveSettings {
            method: Some(method),
            ..SolveSettings::default()
        };
        let a = solve_split(generated().expect("consistent"), &s);
        let b = solve(&prog, &s);
        match (a, b) {
            (Ok(a), Ok(b)) => {
                assert_eq!(
                    a.to_json().to_string(),
                    b.to_json().to_string(),
                    "{source} {method}: generated vs in-process"
                );
                solved += 1;
            }
            (Err(a), Err(b)) => {
                assert_eq!(a.to_string(), b.to_string(), "{source} {method}");
                // A method that cannot apply says why (exit 2).
                assert!(a.is_input_error(), "{source} {method}: {a}");
            }
            (a, b) => panic!(
                "{source} {method}: generated {:?} vs in-process {:?}",
                a.map(|r| r.converged),
                b.map(|r| r.converged)
            ),
        }
    }
    assert!(solved >= 1, "{source}: no method solved");
}

#[test]
fn generated_mms_solver_matches_the_in_process_solve() {
    compare("examples/mms.lmx", mms_solver::input);
    // And it solves the manufactured problem: p = 1, q = x.
    let r = solve_split(
        mms_solver::input().expect("consistent"),
        &SolveSettings::default(),
    )
    .expect("solves");
    assert!(r.converged);
    for (name, u) in &r.unknowns {
        let exact = |x: f64| if name == "p" { 1.0 } else { x };
        let err =
            u.x.iter()
                .zip(&u.values)
                .map(|(&x, v)| (v - exact(x)).abs())
                .fold(0.0, f64::max);
        assert!(err <= u.error_estimate, "{name}: max error {err:e}");
    }
}

#[test]
fn generated_solver_with_every_term_kind_matches() {
    compare("tests/data/codegen_terms.lmx", terms_solver::input);
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
    for (source, input) in [
        (
            "examples/mms.lmx",
            mms_solver::input as fn() -> Result<SplitInput, PlanError>,
        ),
        ("tests/data/codegen_terms.lmx", terms_solver::input),
    ] {
        let sys = input().expect("consistent").sys;
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
        // derives refuses to run the ordered elimination rather than run
        // something else.
        let mut stale = input().expect("consistent");
        stale.sys.derived_pivots = Some(vec![(0, 1 - sys.target)]);
        let s = SolveSettings {
            method: Some(Method::Ordered),
            ..SolveSettings::default()
        };
        let err = solve_split(stale, &s).expect_err("refused");
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
    compare("tests/data/codegen_functions.lmx", functions_solver::input);
}

#[test]
fn generated_solver_with_a_side_condition_matches() {
    compare("tests/data/codegen_condition.lmx", condition_solver::input);
    // f(1/2) = (1/2 + 2/π)/√(3/4).
    let r = solve_split(
        condition_solver::input().expect("consistent"),
        &SolveSettings::default(),
    )
    .expect("solves");
    let v = r.outputs["V"];
    let exact = (0.5 + 2.0 / std::f64::consts::PI) / 0.75f64.sqrt();
    assert!(r.converged, "V = {v}");
    assert!(
        (v - exact).abs() <= r.error_estimates["V"],
        "{v} vs {exact}: estimate {:e}",
        r.error_estimates["V"]
    );
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
