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
