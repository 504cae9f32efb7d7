//! Operator products and side conditions in a split-domain file
//! (`tests/data/split_products_mms.lmx`: products in both orders inside
//! equations that hold on different subintervals, a relation that makes
//! `q` jump at 1/2, and an integral side condition that fixes the
//! homogeneous solution `(p, q) = (1, 2)`), recovered to 1e-10 through the
//! language, the CLI and the field sampler.
mod common;

use common::cli::{json, lambdamat, lmx_file};
use lambdamat::plan::split_fields::{Approach, Fields};
use lambdamat::plan::{SplitOptions, solve_split_fields};

const FILE: &str = "tests/data/split_products_mms.lmx";

fn exact() -> [(&'static str, f64); 3] {
    let (s1, c1) = (1f64.sin(), 1f64.cos());
    [
        ("P", c1 + s1 - 1.0),
        ("Q", 0.5f64.exp() - 1.0 + 2.0 * s1 - 2.0 * 0.5f64.sin()),
        ("p_at", 0.75f64.cos()),
    ]
}

#[test]
fn outputs_are_recovered_with_honest_estimates() {
    let r = json(&["solve", FILE]);
    assert_eq!(r["converged"], true);
    for (name, want) in exact() {
        let got = r["outputs"][name].as_f64().expect("output");
        let est = r["error_estimates"][name].as_f64().expect("estimate");
        let err = (got - want).abs();
        eprintln!("{name}: error {err:.2e}, estimate {est:.2e}");
        assert!(err <= 1e-10, "{name}: error {err:.2e}");
        assert!(
            est >= err,
            "{name}: estimate {est:.2e} below error {err:.2e}"
        );
        assert!(est <= 1e-10, "{name}: estimate {est:.2e}");
    }
}

#[test]
fn fields_and_residuals_with_products() {
    let text = std::fs::read_to_string(FILE).expect("reads");
    let prog = lambdamat::lang::parse_program(&text, FILE).expect("parses");
    let sol = solve_split_fields(&prog, &SplitOptions::default()).expect("solves");
    let f = Fields::new(&sol.problem, &sol.discrete).expect("fields");
    let mut compared = 0;
    for k in 0..=20 {
        let x = f64::from(k) / 20.0;
        let p = f.value(0, x, Approach::Above).expect("p");
        assert!(
            (p - x.cos()).abs() <= 1e-10,
            "p({x}) off by {:.2e}",
            p - x.cos()
        );
        let side = if x == 1.0 {
            Approach::Below
        } else {
            Approach::Above
        };
        let q = f.value(1, x, side).expect("q");
        let want = if x < 0.5 { x.exp() } else { 2.0 * x.cos() };
        assert!((q - want).abs() <= 1e-10, "q({x}) off by {:.2e}", q - want);
        compared += 1;
    }
    assert_eq!(compared, 21);
    // The residuals apply the products too: small where each equation
    // is imposed.
    let xs = [0.05, 0.3, 0.45];
    for e in 0..2 {
        for r in f.residuals(e, &xs).expect("residuals") {
            assert!(r.abs() <= 1e-10, "equation {}: residual {r:.2e}", e + 1);
        }
    }
    let r = f.residuals(0, &[0.7, 0.95]).expect("residuals");
    assert!(r.iter().all(|r| r.abs() <= 1e-10), "{r:?}");
}

#[test]
fn the_side_condition_is_what_fixes_the_solution() {
    let text = std::fs::read_to_string(FILE).expect("reads");
    let without = text.replace("condition int(0..1) p(x) dx = sin(1)", "");
    let f = lmx_file(&without);
    let out = lambdamat()
        .args(["solve", f.path().to_str().expect("utf-8")])
        .output()
        .expect("runs");
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "{err}");
    assert!(
        err.contains("singular") || err.contains("condition"),
        "{err}"
    );
}

#[test]
fn products_are_applied_in_written_order() {
    // The same file with A*B q written B*A q: A and B do not commute, so
    // the answer moves far beyond the estimates.
    let text = std::fs::read_to_string(FILE).expect("reads");
    let swapped = text.replace("+ A*B q", "+ B*A q");
    assert_ne!(swapped, text);
    // (The swapped system does not have the file's homogeneous solution,
    // so its side condition contradicts it: a few levels say enough.)
    let f = lmx_file(&swapped);
    let out = lambdamat()
        .args(["solve", f.path().to_str().expect("utf-8")])
        .args(["--json", "--max-level", "3"])
        .output()
        .expect("runs");
    assert_ne!(out.status.code(), Some(0));
    let r: serde_json::Value = serde_json::from_slice(&out.stdout).expect("a JSON report");
    let p = r["outputs"]["P"].as_f64().expect("P");
    assert!((p - exact()[0].1).abs() > 1e-3, "P = {p}");
}
