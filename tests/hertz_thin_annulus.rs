//! The Hertz problem at ν = 0.4 and large μ (`lambdamat hertz`, the front
//! over `examples/hertz.lmx`): the slip annulus `1 − c` tends to the
//! derived `1 − c∞ = δ₀(1 − δ₀/2)`, `δ₀ = 8·exp(−π²/ln(3−4ν)) ≈ 1.46e-12`
//! (docs/hertz_asymptotics.md), only a few mesh-floor panels wide. The
//! values at c whose continuum value is 0 (the shear jump q(c⁻) − μp(c)
//! and E2's residual at c) must lie within their estimates: where the
//! panels beside c did not change between the last two levels (the
//! grading toward c at the mesh floor) there is no estimate, and the front
//! must say so (`unrefined_at_c`, infinite estimates) instead of reporting
//! the two levels' agreement as one. Before that, (0.4, 4.64) reported the
//! jump as −2.2e3 ± 3.9e-4, and (0.4, 46.4) was refused as a spurious free
//! boundary on the strength of such an estimate.
use lambdamat::hertz::front::{Given, HertzResult, large_friction_asymptotics, solve};
use lambdamat::plan::SplitOptions;

fn gamma(nu: f64) -> f64 {
    (1.0 - 2.0 * nu) / (2.0 - 2.0 * nu)
}

/// The values at c are 0 in the continuum: each must be within its
/// estimate, and an estimate is infinite exactly when the front reports
/// the fields at c as not refined.
fn fields_at_c_within_estimates(s: &HertzResult) {
    for (name, v) in [
        ("shear_jump_at_c", s.shear_jump_at_c),
        ("residual_c", s.residual_c),
    ] {
        let e = s.field_error_estimates[name];
        assert!(
            v.abs() <= e,
            "μ = {}: {name} = {v:e} ± {e:e}: the continuum value 0 is outside",
            s.mu
        );
        assert_eq!(
            e.is_infinite(),
            s.unrefined_at_c.is_some(),
            "μ = {}: {name} ± {e:e}",
            s.mu
        );
    }
}

#[test]
fn nu_0_4_at_large_mu_is_answered_with_honest_fields_at_c() {
    let nu = 0.4;
    let g = gamma(nu);
    let (one_minus_c_inf, eps0) = large_friction_asymptotics(g);
    let full_stick = g.atanh() / g;
    for mu in [1.0, 4.64, 46.4] {
        let s = solve(nu, Given::Mu(mu), &SplitOptions::default())
            .unwrap_or_else(|e| panic!("(0.4, {mu}) is answered: {e}"));
        assert!(s.converged && s.error_estimate <= 1e-10, "μ = {mu}");
        assert!(s.stick_ok && s.slip_ok, "μ = {mu}");
        fields_at_c_within_estimates(&s);
        // At these points the grading toward c reaches the mesh floor: the
        // panels beside c are the floor's (1e3 ulps ≈ 2.2e-13).
        let u = s.unrefined_at_c.expect("the fields at c are not refined");
        assert!(u.panel_below < 1e-12 && u.panel_above < 1e-12, "{u:?}");
        assert!((u.one_minus_c - (1.0 - s.c)).abs() <= 1e-15);
        // c grows toward c∞ (derived): 1 − c ≥ 1 − c∞ within c's estimate.
        let c_err = s.error_estimates["c"];
        assert!(
            1.0 - s.c + c_err >= one_minus_c_inf,
            "μ = {mu}: c = {}",
            s.c
        );
        // P* < P*ₛ = artanh(γ)/γ, and within P's estimate of its limit
        // P*ₛ(1 − δ₀/2) plus the O(1 − c) the annulus still moves it by.
        let p_err = s.error_estimates["P"];
        assert!(s.compliance <= full_stick + p_err);
        assert!(
            (s.compliance - full_stick * (1.0 - one_minus_c_inf / 2.0)).abs()
                <= p_err + full_stick * (1.0 - s.c),
            "μ = {mu}: P* = {}",
            s.compliance
        );
    }
    // 1 − c against δ₀(1 − δ₀/2)·exp(1/(2ε₀μ)) (derived to first order in
    // 1/μ) at μ = 46.4, where the next term, about Φ₂/(ε₀μ²) with the
    // measured Φ₂ ≈ 0.25/γ, is 1.3 %: within c's estimate plus twice that
    // term. Measured: 1.816e-12 against 1.784e-12; a root on the next
    // branch (δ₁ = δ₀·exp(−π/ε₀) ≈ 4e-38) or one missed by 1e-12 fails.
    let mu = 46.4;
    let s = solve(nu, Given::Mu(mu), &SplitOptions::default()).expect("answered");
    let predicted = one_minus_c_inf * (1.0 / (2.0 * eps0 * mu)).exp();
    let next = 2.0 * (0.25 / g) / (eps0 * mu * mu);
    let c_err = s.error_estimates["c"];
    assert!(
        (1.0 - s.c - predicted).abs() <= c_err + next * predicted,
        "1 − c = {:e} against {predicted:e} (± {c_err:e} + {:e})",
        1.0 - s.c,
        next * predicted
    );
    // The derived limit itself: δ₀(1 − δ₀/2) with δ₀ = 8·exp(−π²/ln(3−4ν)).
    let d0 = 8.0 * (-std::f64::consts::PI.powi(2) / (3.0 - 4.0 * nu).ln()).exp();
    assert!((one_minus_c_inf / (d0 * (1.0 - d0 / 2.0)) - 1.0).abs() < 1e-12);
}

#[test]
fn refined_fields_at_c_keep_their_level_estimates() {
    // Mid range the panels beside c shrink from level to level: the
    // estimates are finite and hold the continuum value 0.
    let s = solve(0.25, Given::Mu(0.1801), &SplitOptions::default()).expect("solves");
    assert!(s.unrefined_at_c.is_none());
    fields_at_c_within_estimates(&s);
}
