//! End-to-end tests of `lambdamat smith` and `lambdamat run` on the seed
//! paper's λ-matrix (golden values from the issue), shapes, JSON output and
//! bad input (exit code 2 with line:column).

mod common;

use common::cli::{json, lambdamat, lmx_file as file};
use predicates::prelude::*;
use serde_json::Value;

fn strings(v: &Value) -> Vec<String> {
    v.as_array()
        .expect("array")
        .iter()
        .map(|s| s.as_str().expect("string").to_string())
        .collect()
}

#[test]
fn seed_matrix_over_all_symbols_has_invariant_factors_1_and_det() {
    let v = json(&["smith", "examples/seed_lambda.lmx", "--matrix", "A"]);
    assert_eq!(v["ring"], "Q[k1, k2, k3, k4]");
    assert_eq!(v["mode"], "determinantal-divisors");
    assert_eq!(strings(&v["invariant_factors"]), ["1", "k1*k4 - k2*k3"]);
    assert_eq!(v["verified"], true);
    assert!(
        v["U"].is_null() && v["V"].is_null(),
        "no transforms may be claimed over Q[all]"
    );
}

#[test]
fn seed_matrix_with_principal_k4() {
    let v = json(&[
        "smith",
        "examples/seed_lambda.lmx",
        "--matrix",
        "A",
        "--principal",
        "k4",
    ]);
    assert_eq!(v["ring"], "Q(k1, k2, k3)[k4]");
    assert_eq!(v["mode"], "principal");
    assert_eq!(strings(&v["invariant_factors"]), ["1", "k4 - k2*k3/k1"]);
    assert_eq!(v["D"][1][1], "k4 - k2*k3/k1");
    assert_eq!(v["verified"], true);
    let df = &v["denominator_free"];
    assert_eq!(df["D"][0][0], "1");
    assert_eq!(df["D"][1][1], "k1*k4 - k2*k3");
    assert_eq!(df["verified"], true);
    for key in ["U", "V"] {
        let rows = v[key].as_array().expect("rows");
        assert_eq!(rows.len(), 2);
    }
}

#[test]
fn the_seeds_own_decomposition_is_checked_and_rejected_with_reasons() {
    lambdamat()
        .args(["run", "examples/seed_lambda.lmx"])
        .assert()
        .success()
        .stdout(predicate::str::contains("✓ U·A·V = D: holds exactly"))
        .stdout(predicate::str::contains(
            "✗ U unimodular: det U = -k4 is not a unit",
        ))
        .stdout(predicate::str::contains(
            "✗ divisibility f1 | f2 | …: f1 = k4^2 does not divide f2 = k1*k4^2 - k2*k3*k4",
        ))
        .stdout(predicate::str::contains(
            "verdict: NOT a Smith decomposition",
        ));
    let v = json(&["run", "examples/seed_lambda.lmx"]);
    let check = &v["results"][1];
    assert_eq!(check["kind"], "check");
    assert_eq!(check["result"]["is_smith"], false);
}

#[test]
fn one_symbol_example_prints_expanded_polynomials() {
    let v = json(&["smith", "examples/matrix_qx.lmx"]);
    assert_eq!(v["ring"], "Q[x]");
    assert_eq!(v["mode"], "one-symbol");
    assert_eq!(v["A"][0][1], "x^2 - 1/3*x");
    assert_eq!(v["A"][1][1], "x^2 + 2*x + 1");
    // det A = (9x-5)(x+1)^2 - 3/4 (x^2 - x/3), made monic.
    assert_eq!(
        strings(&v["invariant_factors"]),
        ["1", "x^3 + 49/36*x^2 - 1/12*x - 5/9"]
    );
    for key in [
        "ring",
        "mode",
        "invariant_factors",
        "D",
        "U",
        "V",
        "verified",
    ] {
        assert!(v.get(key).is_some(), "JSON key {key} missing");
    }
}

#[test]
fn shapes_empty_row_column_zero_and_rank_deficient() {
    let src = "var x\nmatrix E = []\nmatrix R = [x, x^2, 1 + x]\nmatrix C = [x; x^2; x + 1]\n\
               matrix Z = [0, 0; 0, 0]\nmatrix S = [x, x^2; 2*x, 2*x^2]\n";
    let f = file(src);
    let p = f.path().to_str().expect("utf-8 path");
    let cases: [(&str, &[&str], usize); 5] = [
        ("E", &[], 0),
        ("R", &["1"], 1),
        ("C", &["1"], 1),
        ("Z", &[], 0),
        ("S", &["x"], 1),
    ];
    for (name, inv, rank) in cases {
        let v = json(&["smith", p, "--matrix", name]);
        assert_eq!(v["verified"], true, "{name}");
        assert_eq!(strings(&v["invariant_factors"]), inv, "{name}");
        assert_eq!(v["rank"], rank, "{name}");
    }
}

#[test]
fn several_matrices_give_a_json_array() {
    let f = file("var x\nmatrix A = [x]\nmatrix B = [x^2 - 1]\n");
    let v = json(&["smith", f.path().to_str().expect("utf-8")]);
    assert_eq!(v.as_array().map(|a| a.len()), Some(2));
}

#[test]
fn latex_output() {
    lambdamat()
        .args(["smith", "examples/matrix_qx.lmx", "--latex"])
        .assert()
        .success()
        .stdout(predicate::str::contains("\\begin{pmatrix}"))
        .stdout(predicate::str::contains("x^{3} + \\frac{49}{36} x^{2}"));
}

#[test]
fn bad_input_exits_2_with_line_and_column() {
    let cases = [
        ("var x\nmatrix A = [x, y]\n", "2:16"),
        ("var x\nmatrix A = [x/0]\n", "2:15"),
        ("var x\nmatrix A = [1/x]\n", "2:15"),
        ("var x\nmatrix A = [x, 1; 2]\n", "2:19"),
        ("var x\nmatrix A = [x +]\n", "2:16"),
        ("var x\nsmith B\n", "2:7"),
    ];
    for (src, pos) in cases {
        let f = file(src);
        let out = lambdamat()
            .arg("smith")
            .arg(f.path())
            .output()
            .expect("runs");
        assert_eq!(out.status.code(), Some(2), "{src}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(pos), "{src}: expected {pos} in\n{err}");
        assert!(!err.contains("panicked"), "{src}");
        assert!(
            out.stdout.is_empty(),
            "nothing may be printed as a result: {src}"
        );
    }
}

#[test]
fn usage_errors_exit_1_and_bad_flags_exit_2() {
    lambdamat().arg("smith").assert().code(1);
    lambdamat().arg("frobnicate").assert().code(1);
    lambdamat()
        .args(["smith", "no/such/file.lmx"])
        .assert()
        .code(2)
        .stderr(predicate::str::contains("cannot read"));
    lambdamat()
        .args(["smith", "examples/seed_lambda.lmx", "--principal", "k9"])
        .assert()
        .code(2)
        .stderr(predicate::str::contains("--principal k9: no such symbol"));
}
