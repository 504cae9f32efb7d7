//! End-to-end tests of issue 9: operator products are applied in the
//! order written. `examples/written_order.lmx` (products `k2*k1`, `A*k2`,
//! `k2*A`) and `examples/both_orders.lmx` (`k2*k1` and `k1*k2` in one
//! equation) have the exact solution p = 1 + x, q = x²: `coupled` and
//! `ordered` recover it to 1e-10; the commutative model does not, and
//! says which pairs it commuted.

mod common;

use common::cli::json;
use serde_json::Value;

fn floats(v: &Value) -> Vec<f64> {
    v.as_array()
        .expect("array")
        .iter()
        .map(|x| x.as_f64().expect("number"))
        .collect()
}

/// Max |u(x) - exact(x)| over the unknown's grid.
fn max_error(v: &Value, name: &str, exact: impl Fn(f64) -> f64) -> f64 {
    let u = &v["unknowns"][name];
    let (x, y) = (floats(&u["x"]), floats(&u["values"]));
    assert!(x.len() > 50 && x.len() == y.len(), "grid of {name}");
    x.iter()
        .zip(&y)
        .map(|(x, y)| (y - exact(*x)).abs())
        .fold(0.0, f64::max)
}

const FILES: [&str; 2] = ["examples/written_order.lmx", "examples/both_orders.lmx"];

#[test]
fn coupled_and_ordered_recover_the_exact_solution_in_written_order() {
    for file in FILES {
        for method in ["coupled", "ordered"] {
            let v = json(&["solve", file, "--method", method]);
            let ep = max_error(&v, "p", |x| 1.0 + x);
            let eq = max_error(&v, "q", |x| x * x);
            assert!(ep <= 1e-10, "{file} {method}: p error {ep:e}");
            assert!(eq <= 1e-10, "{file} {method}: q error {eq:e}");
            let p = v["outputs"]["P"].as_f64().expect("P");
            let q = v["outputs"]["Q"].as_f64().expect("Q");
            assert!((p - 1.5).abs() <= 1e-10, "{file} {method}: P = {p}");
            assert!((q - 1.0 / 3.0).abs() <= 1e-10, "{file} {method}: Q = {q}");
            assert_eq!(v["converged"], true);
        }
    }
}

#[test]
fn the_commutative_model_reports_the_pairs_it_commuted() {
    for file in FILES {
        let v = json(&["solve", file, "--method", "commutative"]);
        assert_eq!(v["model"], true);
        let pairs: Vec<String> = v["commutator_defects"]
            .as_array()
            .expect("defects")
            .iter()
            .map(|d| format!("{} {}", d["pair"][0], d["pair"][1]).replace('"', ""))
            .collect();
        assert!(pairs.contains(&"k1 k2".to_string()), "{file}: {pairs:?}");
        // The model is visibly not the system: p is off by far more than
        // the tolerance.
        let ep = max_error(&v, "p", |x| 1.0 + x);
        assert!(ep > 1e-3, "{file}: the model happens to be exact ({ep:e})");
    }
}

#[test]
fn run_solves_every_solve_for_target() {
    let f = common::cli::lmx_file(
        "operator k1 = int(0..x) dt\noperator k2 = int(0..1) x*t dt\nunknown p, q\n\
         equation p + k1 q = x\nequation q + k2 p = 1\nsolve for p\nsolve for q\n",
    );
    let path = f.path().to_str().expect("utf-8 path");
    let v = json(&["run", path]);
    let targets: Vec<&Value> = v["results"]
        .as_array()
        .expect("results")
        .iter()
        .filter(|r| r["kind"] == "solve")
        .map(|r| &r["result"]["target"])
        .collect();
    assert_eq!(targets, [&Value::from("p"), &Value::from("q")]);
    let text = common::cli::stdout(&["run", path]);
    let reductions: Vec<&str> = text
        .lines()
        .filter(|l| l.starts_with("Reduction for"))
        .collect();
    assert_eq!(reductions, ["Reduction for p", "Reduction for q"]);
    // Each solve reports its own target's derivation: the text report of
    // the second solve follows the second reduction.
    let second = text.split("Reduction for q").nth(1).expect("second part");
    assert!(second.contains("method: coupled"), "{second}");
}

#[test]
fn reduce_and_the_commutative_solve_list_the_same_commuted_pairs() {
    let mut checked = 0;
    for entry in std::fs::read_dir("examples").expect("examples") {
        let path = entry.expect("entry").path();
        if path.extension().is_none_or(|e| e != "lmx") {
            continue;
        }
        let f = path.to_str().expect("utf-8");
        let out = common::cli::lambdamat()
            .args(["solve", f, "--method", "commutative", "--json"])
            .output()
            .expect("runs");
        // Exit 4 (not converged) still prints the report and its defects.
        if !matches!(out.status.code(), Some(0 | 4)) {
            // No numerics for this file (abstract `var` symbols, only
            // matrices, singular, or a split-domain file, which has no
            // commutative method): nothing to compare.
            continue;
        }
        let solve: Value = serde_json::from_slice(&out.stdout).expect("JSON");
        let from_solve: Vec<Value> = solve["commutator_defects"]
            .as_array()
            .expect("defects")
            .iter()
            .map(|d| d["pair"].clone())
            .collect();
        let reduce = json(&["reduce", f]);
        let from_reduce = reduce["commuted_pairs"].as_array().expect("pairs").clone();
        assert_eq!(from_reduce, from_solve, "{f}");
        checked += 1;
    }
    assert!(checked >= 6, "only {checked} examples compared");
}

#[test]
fn a_twenty_unknown_system_is_reduced_and_generated_without_the_eliminant() {
    let f = "tests/data/twenty_unknowns.lmx";
    let text = common::cli::stdout(&["reduce", f]);
    assert!(
        text.contains("not expanded: det(A) may have up to 3.487e9 terms of degree up to 40"),
        "{text}"
    );
    assert!(text.contains("Commuted pairs: not computed"), "{text}");
    let code = common::cli::stdout(&["codegen", f]);
    assert!(code.contains("//! - commutative eliminant: not expanded"));
    assert!(code.contains("pub fn system()"));
    // The numerics do not need it either.
    let v = json(&["solve", f]);
    assert_eq!(v["converged"], true);
}

/// The (equation, unknown) pivots of `reduce --json`'s steps, then the
/// equation left over with the target: the sequence `ordered` must run.
fn reduce_pivots(reduce: &Value) -> Vec<(u64, String)> {
    let st = &reduce["ordered_steps"];
    let mut out: Vec<(u64, String)> = st["steps"]
        .as_array()
        .expect("steps")
        .iter()
        .map(|s| {
            (
                s["equation"].as_u64().expect("equation"),
                s["unknown"].as_str().expect("unknown").to_string(),
            )
        })
        .collect();
    out.push((
        st["result"]["equation"].as_u64().expect("result equation"),
        reduce["unknown"].as_str().expect("unknown").to_string(),
    ));
    out
}

fn solve_pivots(solve: &Value) -> Vec<(u64, String)> {
    solve["pivots"]
        .as_array()
        .expect("pivots")
        .iter()
        .map(|p| {
            (
                p["equation"].as_u64().expect("equation"),
                p["unknown"].as_str().expect("unknown").to_string(),
            )
        })
        .collect()
}

#[test]
fn ordered_solve_executes_the_pivots_that_reduce_prints() {
    let files = [
        "tests/data/twenty_unknowns.lmx",
        "tests/data/codegen_terms.lmx",
        "examples/written_order.lmx",
        "examples/both_orders.lmx",
        "examples/mms.lmx",
        "examples/hertz_manufactured.lmx",
    ];
    for f in files {
        let reduce = json(&["reduce", f]);
        let solve = json(&["solve", f, "--method", "ordered"]);
        let warnings = solve["warnings"].as_array().expect("warnings");
        assert!(
            !warnings.iter().any(|w| w
                .as_str()
                .is_some_and(|w| w.contains("ordered elimination"))),
            "{f}: {warnings:?}"
        );
        let (r, s) = (reduce_pivots(&reduce), solve_pivots(&solve));
        assert!(s.len() >= 2, "{f}: {s:?}");
        assert_eq!(r, s, "{f}: reduce's pivots vs the ones solve ran");
        // The Schur form, where it is written out, has the same pivots.
        if let Some(list) = reduce["ordered_pivots"].as_array()
            && reduce["ordered"].is_string()
        {
            let want: Vec<String> = r[..r.len() - 1]
                .iter()
                .map(|(e, u)| format!("{u} from equation {e} "))
                .collect();
            assert_eq!(list.len(), want.len(), "{f}");
            for (l, w) in list.iter().zip(&want) {
                assert!(
                    l.as_str().expect("pivot").starts_with(w.as_str()),
                    "{f}: {l} vs {w}"
                );
            }
        }
    }
}

#[test]
fn reduce_prints_the_twenty_unknown_elimination_as_steps() {
    use lambdamat::lang::formula::parse_ncexpr;
    let f = "tests/data/twenty_unknowns.lmx";
    let v = json(&["reduce", f]);
    assert!(v["ordered"].is_null(), "the Schur form is too large");
    let st = &v["ordered_steps"];
    let symbols: Vec<String> = st["symbols"]
        .as_array()
        .expect("symbols")
        .iter()
        .map(|s| s.as_str().expect("name").to_string())
        .collect();
    // Operators, then g1..g20, then the intermediates.
    assert_eq!(symbols[19], "k20");
    assert_eq!(symbols[20], "g1");
    assert_eq!(symbols[39], "g20");
    let steps = st["steps"].as_array().expect("steps");
    assert_eq!(steps.len(), 19, "every unknown but u1 is eliminated");
    // Every formula parses back over the names defined so far: each
    // intermediate is defined before it is used, nothing is left implicit.
    let mut known: Vec<String> = symbols[..40].to_vec();
    let mut defined = 0;
    let read = |s: &Value, known: &[String]| {
        let s = s.as_str().expect("formula");
        parse_ncexpr(s, known).unwrap_or_else(|e| panic!("`{s}`: {}", e.render()))
    };
    for step in steps {
        read(&step["pivot"], &known);
        read(&step["inverse"], &known);
        for u in step["updates"].as_array().expect("updates") {
            read(&u["value"], &known);
            let name = u["name"].as_str().expect("name").to_string();
            assert_eq!(name, symbols[40 + defined], "names in order of definition");
            known.push(name);
            defined += 1;
        }
    }
    assert_eq!(known.len(), symbols.len());
    read(&st["result"]["lhs"], &known);
    read(&st["result"]["rhs"], &known);
    assert!(defined > 19, "only {defined} intermediates");
    // The first step solves equation 2 for u2 with the pivot 1 (no
    // operator inverse); equation 1's coefficient of u3 becomes -k1 k2.
    assert_eq!(steps[0]["unknown"], "u2");
    assert_eq!(steps[0]["pivot"], "1");
    assert_eq!(steps[0]["updates"][0]["value"], "-k1*k2");
    assert_eq!(steps[0]["updates"][0]["unknown"], "u3");

    // The text and LaTeX forms print the same steps.
    let text = common::cli::stdout(&["reduce", f]);
    assert!(text.contains("Schur form not available"), "{text}");
    assert!(
        text.contains("step 1: u2 from equation 2, pivot 1"),
        "{text}"
    );
    assert!(
        text.contains("S1 = -k1 k2    [equation 1, coefficient of u3]"),
        "{text}"
    );
    assert!(text.contains("step 19: "), "{text}");
    let result = format!(
        "result, equation {}: ",
        st["result"]["equation"].as_u64().expect("equation")
    );
    assert!(text.contains(&result), "{text}");
    let latex = common::cli::stdout(&["reduce", f, "--latex"]);
    assert!(latex.contains("\\begin{align*}"), "{latex}");
    assert!(latex.contains("S_{1} &= -k_{1} k_{2}"), "{latex}");
}

#[test]
fn ordered_falls_back_to_a_better_pivot_only_with_a_warning_naming_it() {
    let f = "tests/data/pivot_fallback.lmx";
    // The derivation solves equation 2 for q (pivot 1 - k3)…
    let reduce = json(&["reduce", f]);
    assert_eq!(reduce_pivots(&reduce), [(2, "q".into()), (1, "p".into())]);
    // …but that block is numerically singular, so `ordered` uses
    // equation 1 and says so.
    let v = json(&["solve", f, "--method", "ordered"]);
    let warnings: Vec<&str> = v["warnings"]
        .as_array()
        .expect("warnings")
        .iter()
        .filter_map(Value::as_str)
        .collect();
    assert!(
        warnings.iter().any(|w| w.starts_with(
            "ordered elimination: the derivation solves equation 2 for q, but that block cannot be used ("
        ) && w.ends_with("); used equation 1 instead")),
        "{warnings:?}"
    );
    assert_eq!(solve_pivots(&v), [(1, "q".into()), (2, "p".into())]);
    // The answer is still the system's.
    assert_eq!(v["converged"], true);
    let ep = max_error(&v, "p", |x| 1.0 + x);
    let eq = max_error(&v, "q", |x| x);
    assert!(ep <= 1e-10 && eq <= 1e-10, "errors {ep:e}, {eq:e}");
    let p = v["outputs"]["P"].as_f64().expect("P");
    assert!((p - 1.5).abs() <= 1e-10, "P = {p}");
    // The text report shows the warning too (on standard error).
    let out = common::cli::lambdamat()
        .args(["solve", f, "--method", "ordered"])
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(0));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("warning: ordered elimination: the derivation solves equation 2 for q"),
        "{err}"
    );
}
