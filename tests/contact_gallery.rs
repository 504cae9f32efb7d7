//! The contact gallery `examples/contact/`: each file states a textbook
//! contact problem through the Abel reduction of axisymmetric contact
//! (docs/contact_problems.md) and carries its closed form in a comment.
//! Each is solved at the default tolerance, must exit 0, and must agree
//! with the closed form computed here to 1e-9 (and lie within its own
//! error estimate of it, up to a few ulps).

mod common;

use common::cli::json;
use std::f64::consts::PI;

/// The value and estimate of `name` among the outputs, scalars or
/// singular coefficients.
fn get(j: &serde_json::Value, name: &str) -> (f64, f64) {
    let v = j["outputs"][name]
        .as_f64()
        .or_else(|| j["scalars"][name].as_f64())
        .or_else(|| j["coefficients"][name].as_f64())
        .unwrap_or_else(|| panic!("no {name} in {j}"));
    let e = j["error_estimates"][name]
        .as_f64()
        .unwrap_or_else(|| panic!("no estimate of {name}"));
    (v, e)
}

/// Solves `file` at the default tolerance and checks each `(name, exact)`.
fn check(file: &str, want: &[(&str, f64)]) {
    check_with(file, &[], want);
}

/// As [`check`], with extra arguments (`--set …`).
fn check_with(file: &str, args: &[&str], want: &[(&str, f64)]) {
    let mut all = vec!["solve", file];
    all.extend_from_slice(args);
    let j = json(&all);
    assert_eq!(j["converged"], true, "{file}");
    for &(name, exact) in want {
        let (v, e) = get(&j, name);
        let err = (v - exact).abs();
        assert!(err <= 1e-9, "{file}: {name} = {v}, closed form {exact}");
        assert!(
            err <= e + 8.0 * f64::EPSILON * exact.abs(),
            "{file}: {name} = {v} ± {e}, closed form {exact} (error {err:.2e})"
        );
    }
}

#[test]
fn flat_punch_load_is_sneddons() {
    // P = 4·delta (E* = 2, radius 1), delta = 1/3.
    check("examples/contact/flat_punch.lmx", &[("P", 4.0 / 3.0)]);
}

#[test]
fn sphere_at_given_indentation_is_hertz() {
    // a = sqrt(delta), P = (8/3) a^3, delta = 1/2.
    let a = 0.5f64.sqrt();
    check(
        "examples/contact/sphere_indentation.lmx",
        &[("a", a), ("P", 8.0 / 3.0 * a.powi(3))],
    );
}

#[test]
fn cone_contact_radius_and_load_are_sneddons() {
    // a = 2 delta/pi, P = pi a^2, delta = 1.
    let a = 2.0 / PI;
    check("examples/contact/cone.lmx", &[("a", a), ("P", PI * a * a)]);
}

#[test]
fn power_law_punch_follows_its_beta_function_law() {
    // f = r^3: K = (n + 1)/2·B(5/2, 1/2) = 3π/4, a = (delta/K)^(1/3),
    // P = 4·a·delta·n/(n + 1) = 3a, delta = 1.
    let a = (4.0 / (3.0 * PI)).cbrt();
    check(
        "examples/contact/power_law.lmx",
        &[("a", a), ("P", 3.0 * a)],
    );
}

#[test]
fn cattaneo_mindlin_at_given_shift() {
    // c = sqrt(1 - S/mu), Q = mu P (1 - c^3), P = 8/3; mu = 1/2, S = 1/4.
    let (mu, s, p) = (0.5f64, 0.25f64, 8.0 / 3.0);
    let c = (1.0 - s / mu).sqrt();
    check(
        "examples/contact/cattaneo_mindlin_shift.lmx",
        &[("c", c), ("P", p), ("Q", mu * p * (1.0 - c.powi(3)))],
    );
}

#[test]
fn sphere_at_given_load_is_hertz() {
    // Scalars a and delta, fixed by B = 0 and the load P0 = 1:
    // a^3 = 3 P0 R/(4 E*) = 3/8, delta = a^2 (R = 1, E* = 2).
    let a = (3.0f64 / 8.0).cbrt();
    check(
        "examples/contact/sphere_load.lmx",
        &[("a", a), ("delta", a * a), ("P", 1.0)],
    );
}

#[test]
fn sphere_at_given_load_over_the_contact_itself_is_hertz() {
    // The same problem with the Abel operator and the load integrated to
    // the unknown radius (`int(x..a)`, `int(0..a)`): a^3 = 3/8, delta =
    // a^2, and the load inside a/2 is 1 - (3/4)^(3/2).
    let a = (3.0f64 / 8.0).cbrt();
    check(
        "examples/contact/sphere_load_range.lmx",
        &[
            ("a", a),
            ("delta", a * a),
            ("P", 1.0),
            ("P_half", 1.0 - 0.75f64.powf(1.5)),
        ],
    );
}

#[test]
fn cattaneo_mindlin_at_given_tangential_force() {
    // Scalars c and S, fixed by B = 0 and the force Q0 = 7/6:
    // c = (1 - Q0/(mu P))^(1/3) = 1/2, S = mu (1 - c^2) = 3/8; mu = 1/2.
    let (mu, q0, p) = (0.5f64, 7.0 / 6.0, 8.0 / 3.0);
    let c = (1.0 - q0 / (mu * p)).cbrt();
    check(
        "examples/contact/cattaneo_mindlin_force.lmx",
        &[("c", c), ("S", mu * (1.0 - c * c)), ("P", p)],
    );
}

/// JKR's closed form at work of adhesion `c` and depth 1/2: the contact
/// radius (the root of delta = a^2 - (pi/2) c sqrt(a), by bisection to the
/// last bit), the load and the edge coefficient B = -c/sqrt(a).
fn jkr_closed_form(c: f64) -> [(&'static str, f64); 3] {
    let delta = 0.5f64;
    let f = |a: f64| a * a - PI / 2.0 * c * a.sqrt() - delta;
    let (mut lo, mut hi) = (0.25f64, 2.0f64);
    assert!(f(lo) < 0.0 && f(hi) > 0.0);
    for _ in 0..200 {
        let m = 0.5 * (lo + hi);
        if f(m) > 0.0 { hi = m } else { lo = m }
    }
    let a = lo;
    [
        ("a", a),
        ("P", 8.0 / 3.0 * a.powi(3) - 2.0 * PI * c * a.powf(1.5)),
        ("B", -c / a.sqrt()),
    ]
}

#[test]
fn jkr_adhesion_at_given_indentation() {
    // The file's C = 1/4; then weaker and stronger adhesion.
    let file = "examples/contact/jkr_indentation.lmx";
    check(file, &jkr_closed_form(0.25));
    for (set, c) in [("C=1/8", 0.125), ("C=1", 1.0)] {
        check_with(file, &["--set", set], &jkr_closed_form(c));
    }
}
