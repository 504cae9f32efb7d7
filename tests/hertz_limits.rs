//! The Hertz problem with friction (`examples/hertz.lmx`, split-domain
//! solver) in its limits, against the asymptotics of
//! `docs/hertz_asymptotics.md`: convergence-style checks (the error of the
//! leading term must fall at its stated order), the large-μ limit
//! (a slip annulus remains: c → c∞ < 1, at rate O(1/μ)), the bound by the
//! full-stick compliance artanh(γ)/γ, ν < 0, and the refusals at the ends
//! (the spurious roots accumulating at c → 1 are not returned).
use lambdamat::lang::parse_program_with;
use lambdamat::lang::parser::parse_exact;
use lambdamat::plan::error::{EndReason, RangeEnd, RootAtEnd};
use lambdamat::plan::{PlanError, SplitOptions, solve_split};

/// `(c, P*)` at tol 1e-10, or the refusal.
fn solve(nu: &str, mu: &str) -> Result<(f64, f64), String> {
    let path = "examples/hertz.lmx";
    let src = std::fs::read_to_string(path).expect("example exists");
    let sets = vec![
        ("nu".to_string(), parse_exact(nu).expect("exact")),
        ("mu".to_string(), parse_exact(mu).expect("exact")),
    ];
    let prog = parse_program_with(&src, path, &sets).expect("valid");
    let r = solve_split(&prog, &SplitOptions::default()).map_err(|e| e.to_string())?;
    assert!(r.converged, "ν={nu} μ={mu}: not converged");
    let c = r.scalars.iter().find(|e| e.name == "c").expect("c");
    let p = r.outputs.iter().find(|e| e.name == "P").expect("P");
    assert!(c.error <= 1e-10 && p.error <= 1e-10);
    Ok((c.value, p.value))
}

fn gamma(nu: f64) -> f64 {
    (1.0 - 2.0 * nu) / (2.0 - 2.0 * nu)
}

#[test]
fn small_mu_compliance_is_one_plus_gamma_mu_times_one_minus_two_over_pi() {
    // P* = 1 + γμ(1 - 2/π) + O(μ²): halving μ divides the error by ~4.
    let g = gamma(0.0);
    let err = |mu: f64, p: f64| p - 1.0 - g * mu * (1.0 - 2.0 / std::f64::consts::PI);
    let (_, p1) = solve("0", "0.1").expect("solves");
    let (_, p2) = solve("0", "0.05").expect("solves");
    let (e1, e2) = (err(0.1, p1), err(0.05, p2));
    eprintln!(
        "P* errors: μ=0.1 {e1:.3e}, μ=0.05 {e2:.3e}, ratio {:.3}",
        e2 / e1
    );
    assert!(e1.abs() < 1e-3 && e2.abs() < e1.abs());
    let ratio = e2 / e1;
    assert!(
        (0.18..=0.3).contains(&ratio),
        "order 2 expected, ratio {ratio}"
    );
}

#[test]
fn small_mu_stick_radius_decays_like_exp_of_minus_a_over_mu() {
    // ln c = -a/μ + O(ln μ) with a = γ/√(1-γ²) (measured; see the doc):
    // the local exponent -Δln c/Δ(1/μ) approaches a, its gap shrinking
    // with μ.
    let g = gamma(0.0);
    let a = g / (1.0 - g * g).sqrt();
    let pts: Vec<(f64, f64)> = ["0.05", "0.04", "0.03"]
        .iter()
        .map(|mu| {
            let (c, _) = solve("0", mu).expect("solves");
            (mu.parse::<f64>().expect("number"), c)
        })
        .collect();
    let slope = |i: usize| {
        let ((m1, c1), (m2, c2)) = (pts[i], pts[i + 1]);
        (c1.ln() - c2.ln()) / (1.0 / m2 - 1.0 / m1)
    };
    let (s1, s2) = (slope(0), slope(1));
    eprintln!("local exponents {s1:.6}, {s2:.6}; a = {a:.6}");
    assert!((s1 - a).abs() < 0.01 * a && (s2 - a).abs() < 0.01 * a);
    assert!((s2 - a).abs() < (s1 - a).abs());
    assert!(pts[2].1 < 1e-7 && pts[2].1 > 1e-9);
}

#[test]
fn large_mu_leaves_a_slip_annulus_and_approaches_it_at_rate_one_over_mu() {
    let g = gamma(0.0);
    let full_stick = g.atanh() / g;
    let d: Vec<(f64, f64)> = ["10", "100", "1000"]
        .iter()
        .map(|mu| {
            let (c, p) = solve("0", mu).expect("solves");
            (1.0 - c, p)
        })
        .collect();
    eprintln!("1 - c: {:?}; full-stick P* {full_stick}", d);
    // 1 - c decreases to a positive limit (≈ 1.00e-3 at ν = 0).
    assert!(d[0].0 > d[1].0 && d[1].0 > d[2].0 && d[2].0 > 5e-4);
    let ratio = (d[0].0 - d[1].0) / (d[1].0 - d[2].0);
    assert!(
        (7.0..=15.0).contains(&ratio),
        "O(1/μ) expected, ratio {ratio}"
    );
    // P* increases toward its limit, below the full-stick value.
    assert!(d[0].1 < d[1].1 && d[1].1 < d[2].1 && d[2].1 < full_stick);
    assert!(full_stick - d[2].1 < 1e-3);
}

#[test]
fn negative_poisson_ratio_solves() {
    let (c, p) = solve("-1/2", "3/10").expect("solves");
    assert!(c > 0.2 && c < 0.3 && p > 1.0);
}

#[test]
fn the_ends_are_refused_with_their_limit() {
    // ν = 0, μ = 0.02: the stick zone (c ≈ 1e-12) is below the resolved
    // range; the roots near c → 1 violate the Coulomb bound and are not
    // returned.
    let e = solve("0", "0.02").expect_err("refused");
    assert!(
        e.contains("violates the bound") && e.contains("closer than"),
        "{e}"
    );
    // ν = 1/2 (γ = 0): no coupling; the stick zone fills the contact.
    let e = solve("1/2", "0.3").expect_err("refused");
    assert!(e.contains("closer to the end 1"), "{e}");
}

/// The split solver's refusal at an end as data: `(nu, mu)` through
/// `examples/hertz.lmx`.
fn root_at_end(nu: &str, mu: &str) -> RootAtEnd {
    let path = "examples/hertz.lmx";
    let src = std::fs::read_to_string(path).expect("example exists");
    let sets = vec![
        ("nu".to_string(), parse_exact(nu).expect("exact")),
        ("mu".to_string(), parse_exact(mu).expect("exact")),
    ];
    let prog = parse_program_with(&src, path, &sets).expect("valid");
    match solve_split(&prog, &SplitOptions::default()) {
        Err(PlanError::RootAtEnd(r)) => *r,
        other => panic!("ν={nu} μ={mu}: not a root at an end: {other:?}"),
    }
}

#[test]
fn the_ends_are_structured_refusals_naming_the_scalar_the_end_and_the_trend() {
    // ν = 1/2: no sign change; the condition falls toward c = 1 and keeps
    // its sign (levels off at ≈ −0.19).
    let r = root_at_end("1/2", "0.3");
    assert_eq!(
        (r.scalar.as_str(), r.end, r.end_value),
        ("c", RangeEnd::Upper, 1.0)
    );
    assert!(matches!(r.reason, EndReason::NoSignChange { .. }));
    assert!(r.resolved > 0.0 && r.resolved < 1e-9);
    assert!(1.0 - r.reached <= 2.0 * r.resolved, "{}", r.reached);
    assert!(r.trend.len() >= 7 && r.trend.windows(2).all(|w| w[0].0 < w[1].0));
    assert!(r.trend.iter().all(|t| t.1 < 0.0));
    // ν = 0.4, μ = 10: thin slip, |condition| falls steadily toward c = 1.
    let r = root_at_end("2/5", "10");
    assert_eq!((r.end, r.end_value), (RangeEnd::Upper, 1.0));
    assert!(r.shrinks_toward(RangeEnd::Upper, 4));
    // ν = 0, μ = 0.02: the only sign change is a root near c = 1 that
    // violates the Coulomb bound; the condition shrinks toward c = 0
    // (B ∝ c), the end where the physical root lies (c ≈ 1e-12).
    let r = root_at_end("0", "0.02");
    assert_eq!((r.end, r.end_value), (RangeEnd::Lower, 0.0));
    assert!(r.shrinks_toward(RangeEnd::Lower, 2));
    let EndReason::NoneAdmissible { rejected } = &r.reason else {
        panic!("{:?}", r.reason);
    };
    assert!(
        rejected
            .iter()
            .any(|(x, why)| *x > 0.99 && why.contains("violates the bound"))
    );
    // The message is the user's text, unchanged.
    let text = PlanError::RootAtEnd(Box::new(r)).to_string();
    assert!(text.starts_with("scalar root: no convergence: no admissible root"));
}

#[test]
fn the_front_names_every_physical_limit_from_the_structured_refusal() {
    use lambdamat::hertz::front::{Given, Limit, solve_with_limit};
    let o = SplitOptions::default();
    let limit = |nu: f64, given: Given| {
        let r = solve_with_limit(nu, given, &o).err().expect("refused");
        assert!(!r.error.is_input_error());
        (r.limit, r.error.to_string())
    };
    // Small friction (c ≈ 1e-12 at ν = 0, μ = 0.02).
    let (l, text) = limit(0.0, Given::Mu(0.02));
    assert!(matches!(l, Some(Limit::SmallFriction { .. })), "{l:?}");
    assert!(text.contains("small-friction limit"), "{text}");
    // Thin slip: ν = 0.4, μ = 10 (1 − c below 1e-10).
    let (l, text) = limit(0.4, Given::Mu(10.0));
    assert!(matches!(l, Some(Limit::ThinSlip { .. })), "{l:?}");
    assert!(text.contains("1 − c is below 1e-10"), "{text}");
    // A given c beyond c∞(ν): at ν = 0 the condition in μ levels off toward
    // μ → ∞; at ν = −0.9 (c∞ ≈ 0.957) and ν = 0.3 (1 − c∞ ≈ 4e-7) it
    // levels off at both ends and is smaller toward μ → 0, which the text
    // of the message could not tell apart from a root at μ → 0.
    for (nu, c) in [(0.0, 0.999), (-0.9, 0.99), (0.3, 0.99999999)] {
        let (l, text) = limit(nu, Given::C(c));
        assert!(
            matches!(l, Some(Limit::BeyondLargeFriction { .. })),
            "ν = {nu}, c = {c}: {l:?} {text}"
        );
        assert!(text.contains("beyond c∞(ν)"), "{text}");
    }
}
