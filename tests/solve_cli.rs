//! End-to-end tests of `lambdamat solve`: the manufactured coupled system
//! (coupled and ordered recover p = 1, q = x; the commutative model does
//! not, and its defect report says why), the frictionless punch, a
//! convergence sequence through the language path, CSV/SVG output and the
//! refusal of singular systems (exit 3) and unsupported kernels (exit 2).

mod common;

use common::cli::{json, lambdamat, lmx_file as file, stdout_with_code};
use serde_json::Value;
use std::f64::consts::{FRAC_PI_4, PI};

/// The JSON of `lambdamat solve ARGS --json`.
fn solve_json(args: &[&str]) -> Value {
    json(&[&["solve"], args].concat())
}

/// The JSON of a solve that finishes without converging (exit code 4),
/// as the commutative model does on the manufactured system.
fn unconverged_json(args: &[&str]) -> Value {
    let out = stdout_with_code(&[&["solve"], args, &["--json"]].concat(), 4);
    let v: Value = serde_json::from_str(&out).expect("valid JSON");
    assert_eq!(v["converged"], false);
    v
}

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

#[test]
fn mms_coupled_and_ordered_recover_the_exact_solution() {
    for method in ["coupled", "ordered"] {
        let v = solve_json(&["examples/mms.lmx", "--method", method]);
        assert_eq!(v["method"], method);
        let ep = max_error(&v, "p", |_| 1.0);
        let eq = max_error(&v, "q", |x| x);
        eprintln!("{method}: max error p {ep:.2e}, q {eq:.2e}");
        assert!(ep <= 1e-10, "{method}: p error {ep:e}");
        assert!(eq <= 1e-10, "{method}: q error {eq:e}");
        let pstar = v["outputs"]["P"].as_f64().expect("P");
        let qint = v["outputs"]["Q"].as_f64().expect("Q");
        assert!((pstar - FRAC_PI_4).abs() <= 1e-10, "P = {pstar}");
        assert!((qint - 0.5).abs() <= 1e-10, "Q = {qint}");
        // Absolute estimates, each within tol·max(1, |value|), each
        // bounding its true error.
        let est = |name: &str| v["error_estimates"][name].as_f64().expect("estimate");
        for (name, value) in [("P", pstar), ("Q", qint)] {
            assert!(
                est(name) <= 1e-10 * value.abs().max(1.0),
                "{name}: {}",
                est(name)
            );
        }
        assert!(
            (pstar - FRAC_PI_4).abs() <= est("P").max(1e-14),
            "P vs its estimate"
        );
        assert!(
            ep <= est("p") && eq <= est("q"),
            "fields vs their estimates"
        );
        assert_eq!(v["converged"], true);
        assert!(v["levels"].as_u64().expect("levels") >= 2);
    }
}

#[test]
fn mms_commutative_model_is_visibly_wrong_and_the_defect_says_why() {
    let v = unconverged_json(&["examples/mms.lmx", "--method", "commutative"]);
    assert_eq!(v["model"], true);
    let ep = max_error(&v, "p", |_| 1.0);
    eprintln!("commutative: max error of p {ep:.3}");
    assert!(ep > 0.1, "the model's p is not visibly wrong: {ep}");
    // The model solves its single equation for p; q follows from the
    // ordered elimination's pivot equation.
    assert!(v["unknowns"].get("q").is_some());
    let defects = v["commutator_defects"].as_array().expect("defects");
    let pairs: Vec<(String, String, f64)> = defects
        .iter()
        .map(|d| {
            (
                d["pair"][0].as_str().unwrap_or("").to_string(),
                d["pair"][1].as_str().unwrap_or("").to_string(),
                d["defect"].as_f64().unwrap_or(f64::NAN),
            )
        })
        .collect();
    eprintln!("defects: {pairs:?}");
    let k24 = pairs
        .iter()
        .find(|(a, b, _)| a == "k2" && b == "k4")
        .expect("k2, k4 were commuted");
    assert!(k24.2 > 0.1, "k2 k4 defect {}", k24.2);
    // The ordered method commutes nothing here: no defects to report.
    let o = solve_json(&["examples/mms.lmx", "--method", "ordered"]);
    assert_eq!(o["method"], "ordered");
    assert!(o.get("commutator_defects").is_none());
}

#[test]
fn commutative_warns_on_stderr() {
    let out = lambdamat()
        .args(["solve", "examples/mms.lmx", "--method", "commutative"])
        .output()
        .expect("runs");
    // The model's answer does not converge: printed, marked, exit 4.
    assert_eq!(out.status.code(), Some(4));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("k2 and k4 do not commute"), "{err}");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("MODEL"), "{text}");
}

#[test]
fn punch_edge_singularity_and_compliance() {
    let v = solve_json(&[
        "examples/punch.lmx",
        "--tol",
        "1e-12",
        "--field-tol",
        "1e-9",
    ]);
    let exact = |x: f64| 2.0 / PI / (1.0 - x * x).sqrt();
    let u = &v["unknowns"]["p"];
    assert_eq!(u["weight"], "(1 - x)^(-0.5)");
    let (x, y) = (floats(&u["x"]), floats(&u["values"]));
    let err = x
        .iter()
        .zip(&y)
        .map(|(x, y)| (y - exact(*x)).abs())
        .fold(0.0, f64::max);
    let pstar = v["outputs"]["P"].as_f64().expect("P");
    let est = u["error_estimate"].as_f64().expect("estimate");
    eprintln!(
        "punch: error of p {err:.2e} (estimate {est:.2e}), |P - 1| = {:.2e}",
        (pstar - 1.0).abs()
    );
    assert!(
        err <= est && est <= 1e-9,
        "p error {err:e}, estimate {est:e}"
    );
    assert!((pstar - 1.0).abs() <= 1e-12, "P = {pstar}");
}

#[test]
fn csv_and_svg_are_written() {
    let dir = tempfile::tempdir().expect("dir");
    let csv = dir.path().join("u.csv");
    let svg = dir.path().join("u.svg");
    lambdamat()
        .args(["solve", "examples/mms.lmx", "--method", "coupled", "--csv"])
        .arg(&csv)
        .arg("--plot")
        .arg(&svg)
        .assert()
        .success();
    let text = std::fs::read_to_string(&csv).expect("csv");
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("x,p,q"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|c| c.parse().expect("number")).collect())
        .collect();
    assert_eq!(rows.len(), 101);
    for r in &rows {
        assert!(
            (r[1] - 1.0).abs() < 1e-10 && (r[2] - r[0]).abs() < 1e-10,
            "{r:?}"
        );
    }
    let plot = std::fs::read_to_string(&svg).expect("svg");
    assert!(plot.contains("<svg") && plot.contains("polyline"));
}

const SINGULAR: &str = "operator k1 = int(x..1) t/sqrt(t^2 - x^2) dt\n\
unknown p, q\n\
equation k1 p + k1 q = 1\n\
equation k1 p + k1 q = 0\n";

#[test]
fn singular_system_is_exit_3_with_a_reason() {
    let f = file(SINGULAR);
    for method in ["coupled", "ordered", "commutative"] {
        let out = lambdamat()
            .arg("solve")
            .arg(f.path())
            .args(["--method", method, "--json"])
            .output()
            .expect("runs");
        // The commutative model needs det(A) ≠ 0: refused as input (2).
        let want = if method == "commutative" { 2 } else { 3 };
        assert_eq!(out.status.code(), Some(want), "{method}");
        assert!(out.stdout.is_empty(), "{method} printed a result");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains("singular") || err.contains("ill-conditioned"),
            "{method}: {err}"
        );
    }
}

#[test]
fn unsupported_kernel_is_exit_2_naming_the_operator() {
    let f = file("operator weird = int(0..1) 1/(t - x)^2 dt\nunknown p\nequation weird p = 1\n");
    let out = lambdamat()
        .arg("solve")
        .arg(f.path())
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("operator weird"), "{err}");
}

#[test]
fn run_performs_the_solve_directive() {
    let out = lambdamat()
        .args(["run", "examples/mms.lmx", "--json"])
        .output()
        .expect("runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let results = v["results"].as_array().expect("results");
    assert_eq!(results[0]["kind"], "reduce", "the reduction comes first");
    let r = results
        .iter()
        .find(|r| r["kind"] == "solve")
        .expect("a solve result");
    assert_eq!(r["result"]["method"], "coupled");
    assert!(max_error(&r["result"], "p", |_| 1.0) <= 1e-10);
}

#[test]
fn solve_for_picks_the_eliminated_unknown() {
    // The commutative model solves its single equation for the target.
    let v = unconverged_json(&["examples/mms.lmx", "--method", "commutative", "--for", "q"]);
    assert_eq!(v["target"], "q");
    let warnings = v["warnings"].as_array().expect("warnings");
    assert!(
        warnings
            .iter()
            .any(|w| w.as_str().is_some_and(|w| w.contains("equation for q"))),
        "{warnings:?}"
    );
    let out = lambdamat()
        .args(["solve", "examples/mms.lmx", "--for", "r"])
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("r is not an unknown"));
}
