//! Answers at an end of a free-boundary scalar's range
//! (`src/plan/split_end.rs`): a stick radius whose root lies below the
//! resolved `1e-10` is bounded, not resolved, and the outputs are given to
//! the tolerance with their variation over the gap. Checked against the
//! derived small-μ asymptotics (docs/hertz_asymptotics.md), against an
//! independent computation (the full-slip problem, c = 0 exactly, a file
//! without a free boundary), and through the CLI; and a trend that does not
//! show a root beyond the end still refuses.
mod common;

use common::cli::lambdamat;
use lambdamat::hertz::front::{Given, solve};
use lambdamat::lang::parse_program_with;
use lambdamat::lang::parser::parse_exact;
use lambdamat::plan::error::RangeEnd;
use lambdamat::plan::{PlanError, SplitOptions, solve_split};
use std::f64::consts::PI;

fn gamma(nu: f64) -> f64 {
    (1.0 - 2.0 * nu) / (2.0 - 2.0 * nu)
}

/// `P*` of the full-slip problem (`q = μp` on all of [0, 1]: the stick
/// radius is 0 exactly), from `examples/hertz_frictionless.lmx` with its
/// relation `q = 0·p` replaced by `q = μp`: no scalar, no condition.
fn full_slip_compliance(nu: &str, mu: &str) -> (f64, f64) {
    let path = "examples/hertz_frictionless.lmx";
    let src = std::fs::read_to_string(path).expect("example exists");
    assert!(src.contains("relation q = 0*p on [0, 1]"));
    assert!(src.contains("param alpha = 1/2"));
    let src = src
        .replace("relation q = 0*p on [0, 1]", "relation q = mu*p on [0, 1]")
        .replace(
            "param alpha = 1/2",
            "param mu = 1\nparam alpha = acot(gamma*mu)/pi",
        )
        // The mesh graded toward the centre, where p ~ x^(−μγ): without it
        // the levels agree to 2.9e-10 while P* is 2.0e-8 off (measured at
        // ν = 0, μ = 0.01).
        .replace(
            "singular p at 1 ~ (1 - x)^(-alpha)",
            "singular p at 1 ~ (1 - x)^(-alpha)\nsingular p at 0 ~ (x - 0)^(0)",
        );
    let sets = vec![
        ("nu".to_string(), parse_exact(nu).expect("exact")),
        ("mu".to_string(), parse_exact(mu).expect("exact")),
    ];
    let prog = parse_program_with(&src, path, &sets).expect("valid");
    // Without a stick zone the pressure goes like x^(−μγ) at the centre:
    // the ladder reaches about 2e-9 there (P itself ± 8.6e-11), so 1e-8.
    let o = SplitOptions {
        tol: 1e-8,
        ..SplitOptions::default()
    };
    let r = solve_split(&prog, &o).expect("solves");
    assert!(
        r.converged && r.scalars.is_empty(),
        "full slip: converged {}, estimate {:.1e}, levels {}",
        r.converged,
        r.error_estimate,
        r.levels
    );
    let p = r.outputs.iter().find(|e| e.name == "P").expect("P");
    (p.value, p.error)
}

#[test]
fn a_stick_radius_below_the_resolved_range_is_bounded_and_p_star_is_answered() {
    let o = SplitOptions::default();
    // ν = −0.9 (c ≈ 4e-46) was refused until the mesh's inner layers were
    // anchored at c: the condition B(c) over 1e-10 … 1e-3 was a staircase
    // (0.26–0.38) following the mesh's phase relative to c, and is now
    // monotone (0.37–0.42), so its trend shows the root beyond the end.
    for (nu, mu) in [(0.0, 0.01), (0.3, 0.01), (-0.9, 0.01)] {
        let s = solve(nu, Given::Mu(mu), &o).expect("an end answer");
        let e = s.end_answer.as_ref().expect("bounded, not resolved");
        let g = gamma(nu);
        println!(
            "ν = {nu}, μ = {mu}: c = {:.3e} ± {:.1e}, P* = {:.15} ± {:.1e}",
            s.c, s.error_estimates["c"], s.compliance, s.error_estimates["P"]
        );
        assert!(s.converged && s.error_estimate <= o.tol);
        assert_eq!(e.end, RangeEnd::Lower);
        assert!(e.distance <= 1.1e-10 && e.at == e.distance);
        // c is the middle of (0, δ), within half of it.
        assert!((s.c - e.distance / 2.0).abs() <= 1e-25);
        assert!((s.error_estimates["c"] - e.distance / 2.0).abs() <= 1e-25);
        // The derived c = C₀·exp(−a/μ) lies in that gap (far below it).
        let (a, c0) = (
            -(1.0 - g * g).ln() / g,
            4.0 * (1.0 - g * g).powf(1.0 - 2.0 * 2f64.ln()),
        );
        let c_asym = c0 * (-a / mu).exp();
        assert!(c_asym < 1e-12 && (s.c - c_asym).abs() <= s.error_estimates["c"]);
        // P* = 1 + γμ(1 − 2/π) + O(μ²) (derived): the remainder is O(μ²).
        let p_asym = 1.0 + g * mu * (1.0 - 2.0 / PI);
        assert!(
            (s.compliance - p_asym).abs() <= g * mu * mu,
            "{}",
            s.compliance - p_asym
        );
        // To second order (derived, J = −0.0243953…): the remainder is
        // O(μ³), measured at about −0.08γ³μ³ (a few 1e-8 at ν = −0.9).
        let j = lambdamat::hertz::front::SMALL_FRICTION_COMPLIANCE_J;
        let p2 = p_asym + g * g * j * mu * mu;
        assert!(
            (s.compliance - p2).abs() <= 0.3 * (g * mu).powi(3),
            "{}",
            s.compliance - p2
        );
        // An independent computation: the full-slip problem (c = 0
        // exactly), which the root's problem differs from by O(c²).
        let (p_fs, e_fs) = full_slip_compliance(&nu.to_string(), &mu.to_string());
        let d = (s.compliance - p_fs).abs();
        println!("  full slip: P* = {p_fs:.15} ± {e_fs:.1e}, difference {d:.1e}");
        assert!(d <= s.error_estimates["P"] + e_fs, "{d:e}");
        // The two formulas for P* agree.
        assert!((s.compliance - s.compliance_via_shear).abs() <= 2.0 * o.tol);
        // Each output's variation over the gap is part of its estimate.
        for v in e.variations.iter().filter(|v| v.name.starts_with('P')) {
            assert!(v.bound > 0.0 && v.bound <= s.error_estimates[&v.name]);
        }
        assert!(s.stick_ok && s.slip_ok);
        // The limit's asymptotic values come along as information.
        assert!(s.limit.is_some_and(|l| l.kind() == "small_friction"));
    }
}

#[test]
fn a_trend_that_does_not_show_a_root_beyond_the_end_still_refuses() {
    // A given c = 0.99 beyond c∞(−0.9) ≈ 0.957: the condition in μ levels
    // off toward μ → ∞ (no root there), so no end answer either. The
    // `hertz` front refuses such a c before solving; the general solver,
    // run on the same file, must reach the same refusal from its trend.
    match solve(-0.9, Given::C(0.99), &SplitOptions::default()) {
        Err(e) => {
            assert!(!e.is_input_error());
            assert!(e.to_string().contains("beyond c∞"), "{e}");
        }
        Ok(s) => panic!("answered: c = {}", s.c),
    }
    let out = lambdamat()
        .args([
            "solve",
            "examples/hertz_given_c.lmx",
            "--set",
            "nu=-9/10",
            "--set",
            "c=99/100",
        ])
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(3));
    let text = String::from_utf8_lossy(&out.stderr);
    assert!(text.contains("no answer at the end either"), "{text}");
    assert!(text.contains("levels off"), "{text}");
}

#[test]
fn the_cli_says_the_stick_radius_is_bounded_and_exits_0() {
    let out = lambdamat()
        .args(["hertz", "--nu", "0", "--mu", "0.01"])
        .output()
        .expect("runs");
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{text}");
    assert!(
        text.contains("c < 1.0262e-10, bounded, not resolved"),
        "{text}"
    );
    assert!(text.contains("small-friction limit (information"), "{text}");
    assert!(text.contains("at c: not checked"), "{text}");
    let out = lambdamat()
        .args(["hertz", "--nu", "0", "--mu", "0.01", "--json"])
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    assert_eq!(v["end_answer"]["end"], "lower");
    assert_eq!(v["limit"]["kind"], "small_friction");
    // `solve` on the language file says the same.
    let out = lambdamat()
        .args([
            "solve",
            "examples/hertz.lmx",
            "--set",
            "nu=0",
            "--set",
            "mu=0.01",
        ])
        .output()
        .expect("runs");
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{text}");
    assert!(text.contains("scalar c is bounded, not resolved"), "{text}");
}

#[test]
fn plan_errors_at_an_end_stay_numerical() {
    // A tolerance tighter than the resolved gap (δ/2 ≈ 5e-11 > 1e-11)
    // cannot be met at the end: a refusal, not an answer.
    let o = SplitOptions {
        tol: 1e-11,
        ..SplitOptions::default()
    };
    match solve(0.0, Given::Mu(0.01), &o) {
        Err(e) => {
            assert!(!matches!(e, PlanError::Invalid(_)) && !e.is_input_error());
            assert!(e.to_string().contains("resolved distance"), "{e}");
        }
        Ok(s) => panic!("answered: c = {}", s.c),
    }
}
