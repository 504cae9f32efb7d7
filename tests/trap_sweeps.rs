//! Tolerance sweeps (issue 27): a split-domain solve that succeeds at one
//! tolerance succeeds at every looser one, and every answer it gives,
//! exit 0 or 4, bounds its true error. On the manufactured Hertz-type
//! file (`examples/hertz_split_mms.lmx`: exact c = 1/2, P = π/6) every
//! tolerance from 1e-4 to 1e-12 is answered, exit 0, within its estimate.
mod common;

use common::cli::lambdamat;
use serde_json::Value;

#[test]
fn the_manufactured_split_file_is_answered_at_every_tolerance() {
    let exact = [("c", 0.5), ("P", std::f64::consts::PI / 6.0)];
    for tol in ["1e-4", "1e-6", "1e-8", "1e-10", "1e-12"] {
        let out = lambdamat()
            .args([
                "solve",
                "examples/hertz_split_mms.lmx",
                "--json",
                "--tol",
                tol,
            ])
            .output()
            .expect("runs");
        assert_eq!(out.status.code(), Some(0), "--tol {tol}");
        let j: Value = serde_json::from_slice(&out.stdout).expect("json");
        for (name, value) in exact {
            let v = ["outputs", "scalars"]
                .iter()
                .find_map(|k| j[k][name].as_f64())
                .expect("value");
            let e = j["error_estimates"][name].as_f64().expect("estimate");
            let t: f64 = tol.parse().expect("number");
            assert!(
                (v - value).abs() <= e && e <= t * value.abs().max(1.0),
                "--tol {tol}: {name} = {v} ± {e:.1e}, true error {:.1e}",
                (v - value).abs()
            );
        }
    }
}
