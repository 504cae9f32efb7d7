//! `gamma`, `beta` and `erf` as functions of the language, and real
//! parameters (values that are not exact rationals) in right sides and
//! outputs. The flat-punch equation `k1 p = g` has the load
//! `P = (π/2)∫ x p = g`, so a right side built from these functions and a
//! real parameter must give back the value computed here independently.

mod common;

use common::cli::{json, lambdamat, lmx_file};
use std::f64::consts::PI;

/// `acot(v)/π` with acot in (0, π), computed here.
fn acot_over_pi(v: f64) -> f64 {
    (PI / 2.0 - v.atan()) / PI
}

#[test]
fn functions_and_a_real_parameter_in_a_right_side() {
    // beta(1/2, 3/2) = π/2 and gamma(1/2)² = π, so the right side is
    // g + erf(x)·0 + 0 = g, and P = g; the output Q = g directly.
    let f = lmx_file(
        "param nu = 1/4\nparam mu = 0.1801\nparam g = acot(nu*mu)/pi\n\
         operator k1 = int(x..1) t/sqrt(t^2 - x^2) dt\nunknown p on [0, 1]\n\
         equation k1 p = g*beta(1/2, 3/2)*2/pi + 0*erf(x) + gamma(1/2)^2/pi - 1\n\
         output P = pi/2 * int(0..1) x*p(x) dx\noutput Q = g\n",
    );
    let j = json(&["solve", f.path().to_str().expect("utf-8")]);
    let g = acot_over_pi(0.25 * 0.1801);
    for name in ["P", "Q"] {
        let v = j["outputs"][name].as_f64().expect("number");
        let e = j["error_estimates"][name].as_f64().expect("number");
        assert!(
            (v - g).abs() <= e.max(1e-14),
            "{name} = {v} ± {e}, want {g}"
        );
        assert!((v - g).abs() <= 1e-9, "{name} = {v}, want {g}");
    }
}

#[test]
fn erf_varies_with_x_and_gamma_is_still_a_parameter_name() {
    // For `k1 p = f` the load is P = (π/2)∫x p = ∫_0^1 f (exchange the
    // integrals: ∫_0^t dx/√(t² − x²) = π/2). With f = x·erf(x) + 1/3
    // (even and smooth): P = erf(1)/4 + 1/(2e√π) + 1/3,
    // erf(1) = 0.8427007929497149.
    let f = lmx_file(
        "param gamma = 1/3\noperator k1 = int(x..1) t/sqrt(t^2 - x^2) dt\n\
         unknown p on [0, 1]\nequation k1 p = x*erf(x) + gamma\n\
         output P = pi/2 * int(0..1) x*p(x) dx\n",
    );
    let j = json(&["solve", f.path().to_str().expect("utf-8")]);
    let want = 0.842_700_792_949_714_9 / 4.0 + 0.5 / (1.0f64.exp() * PI.sqrt()) + 1.0 / 3.0;
    let p = j["outputs"]["P"].as_f64().expect("number");
    let e = j["error_estimates"]["P"].as_f64().expect("number");
    assert!(
        (p - want).abs() <= e.max(1e-14),
        "P = {p} ± {e}, want {want}"
    );
    assert!((p - want).abs() <= 1e-9, "P = {p}, want {want}");
}

#[test]
fn a_wrong_number_of_arguments_is_an_input_error() {
    for (call, want) in [
        ("beta(1/2)", "`beta` takes two arguments, not 1"),
        ("gamma(1, 2)", "`gamma` takes one argument, not 2"),
    ] {
        let f = lmx_file(&format!(
            "operator k1 = int(x..1) t/sqrt(t^2 - x^2) dt\nunknown p on [0, 1]\n\
             equation k1 p = {call}\n"
        ));
        let out = lambdamat()
            .args(["solve", f.path().to_str().expect("utf-8")])
            .output()
            .expect("runs");
        assert_eq!(out.status.code(), Some(2));
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(want), "{err}");
        assert!(err.contains(":3:"), "{err}");
    }
}

#[test]
fn a_real_parameter_stays_out_of_kernels() {
    let f = lmx_file(
        "param a = sqrt(2)\noperator k1 = int(x..1) a*t/sqrt(t^2 - x^2) dt\n\
         unknown p on [0, 1]\nequation k1 p = 1\n",
    );
    let out = lambdamat()
        .args(["solve", f.path().to_str().expect("utf-8")])
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("real (not exactly rational) parameter"),
        "{err}"
    );
}
