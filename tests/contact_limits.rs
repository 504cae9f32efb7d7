//! The closed-form ends of the punch problem that `examples/hertz.lmx`
//! states (the seed's (2.1) is the flat-ended punch with partial adhesion,
//! docs/hertz.md), checked through the language:
//!
//! * full adhesion (`μ = ∞`, the stick zone is the whole contact:
//!   `examples/hertz_stick.lmx`, E1 and E2 on all of [0, 1]) is
//!   Mossakovskii's bonded flat punch, whose compliance factor is
//!   `P* = (1 - ν) ln(3 - 4ν)/(1 - 2ν) = artanh(γ)/γ` with
//!   `γ = (1 - 2ν)/(2 - 2ν)` (the two forms are equal because
//!   `(3 - 4ν) = (1 + γ)/(1 - γ)` and `(1 - 2ν)/(1 - ν) = 2γ`);
//! * `ν = 1/2` (`γ = 0`) decouples p from q: `p = (2/π)/√(1 - x²)`, the
//!   frictionless punch, and `P* = 1`.
//!
//! The bonded punch's normal stress oscillates at the edge
//! (`(1 - x)^(-1/2 ± iε)`, `ε = ln(3 - 4ν)/(2π)`), which the solver's
//! weights do not capture, so it may stop short of the tolerance by its
//! own estimate; the check is that the exact value lies within that
//! estimate, and within 1e-8.

use lambdamat::lang::parse_program_with;
use lambdamat::report::{Report, SolveSettings, solve};
use num_rational::BigRational;

fn solve_stick(nu: (i64, i64)) -> Report {
    let text = std::fs::read_to_string("examples/hertz_stick.lmx").expect("example");
    let sets = [("nu".to_string(), BigRational::new(nu.0.into(), nu.1.into()))];
    let prog = parse_program_with(&text, "examples/hertz_stick.lmx", &sets).expect("parses");
    solve(&prog, &SolveSettings::default()).expect("solves")
}

fn output(r: &Report, name: &str) -> f64 {
    r.outputs[name]
}

fn estimate(r: &Report, name: &str) -> f64 {
    r.error_estimates[name]
}

#[test]
fn full_adhesion_is_mossakovskiis_bonded_punch() {
    for nu in [(2, 5), (1, 4), (0, 1), (-1, 2)] {
        let v = nu.0 as f64 / nu.1 as f64;
        let gamma = (1.0 - 2.0 * v) / (2.0 - 2.0 * v);
        let exact = gamma.atanh() / gamma;
        let classical = (1.0 - v) * (3.0 - 4.0 * v).ln() / (1.0 - 2.0 * v);
        assert!((exact - classical).abs() <= 1e-14, "the two closed forms");
        let r = solve_stick(nu);
        let p = output(&r, "P");
        let err = (p - exact).abs();
        println!(
            "ν = {v}: P* = {p:.15}, exact {exact:.15}, error {err:.1e}, estimate {:.1e}",
            estimate(&r, "P")
        );
        assert!(
            err <= estimate(&r, "P") && err <= 1e-8,
            "ν = {v}: P* = {p}, exact {exact}, estimate {:.1e}",
            estimate(&r, "P")
        );
    }
}

#[test]
fn incompressible_punch_is_frictionless() {
    let r = solve_stick((1, 2));
    assert!(r.converged, "estimates {:?}", r.error_estimates);
    assert!((output(&r, "P") - 1.0).abs() <= 1e-10);
    let p = &r.unknowns["p"];
    let q = &r.unknowns["q"];
    let mut checked = 0;
    for (&x, &v) in p.x.iter().zip(&p.values) {
        let exact = 2.0 / std::f64::consts::PI / (1.0 - x * x).sqrt();
        // The grid leaves the singular end out; compare relative to size.
        assert!(
            (v - exact).abs() <= 1e-9 * exact,
            "p({x}) = {v}, exact {exact}"
        );
        checked += 1;
    }
    assert!(checked >= 10, "only {checked} grid points");
    assert!(q.values.iter().all(|v| v.abs() <= 1e-9), "q = 0 when γ = 0");
}
