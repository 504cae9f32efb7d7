//! Spence's published (μ, c) pairs (seed Table 1, column c1) through the
//! `hertz` front (the language files and the split-domain solver), the
//! physical checks along a small sweep, and monotonicity of c(μ).
mod common;

use common::SPENCE;
use lambdamat::hertz::front::{Given, HertzResult, solve};
use lambdamat::plan::SplitOptions;

fn front(nu: f64, given: Given, tol: f64) -> HertzResult {
    solve(
        nu,
        given,
        &SplitOptions {
            tol,
            max_level: 7,
            ..SplitOptions::default()
        },
    )
    .expect("the front solves")
}

/// Every entry agrees to 1e-3 in μ except (ν = 0.25, c = 0.5), where we
/// get μ = 0.181118 against Spence's 0.1801 (difference 1.02e-3). That
/// value is converged (estimate ≤ 1e-9, checked here, and the inverse
/// solve from μ = 0.1801 gives c = 0.4956, not 0.5), so the test pins the
/// difference to [1.0e-3, 1.05e-3] instead of hiding it: if the solver
/// changes, this entry must be looked at again.
#[test]
fn spence_pairs_to_about_1e_3() {
    for (nu, mu, c) in SPENCE {
        let s = front(nu, Given::C(c), 1e-9);
        eprintln!(
            "ν={nu} c={c}: μ = {:.6} (Spence {mu}, difference {:+.2e}), P* = {:.10} ± {:.1e}",
            s.mu,
            s.mu - mu,
            s.compliance,
            s.error_estimate
        );
        assert!(s.converged && s.error_estimate <= 1e-9);
        if nu == 0.25 && c == 0.5 {
            let d = s.mu - mu;
            assert!(
                (1.0e-3..=1.05e-3).contains(&d),
                "ν=0.25 c=0.5: difference {d:e}"
            );
        } else {
            assert!(
                (s.mu - mu).abs() <= 1e-3,
                "ν={nu} c={c}: μ = {} vs {mu}",
                s.mu
            );
        }
        assert!(s.stick_ok && s.slip_ok);
        // Pointwise at the singular point c itself: limited by the smallest panel.
        assert!(
            s.shear_jump_at_c.abs() <= 1e-3 * s.mu,
            "q(c-) - μp(c) = {:e}",
            s.shear_jump_at_c
        );
        assert!(s.compliance > 1.0);
    }
}

#[test]
fn sweep_checks_and_monotone_c() {
    for (nu, mus) in [(0.0, [0.1, 0.2, 0.5, 1.0]), (0.3, [0.1, 0.2, 0.3, 0.5])] {
        let mut prev = 0.0;
        for mu in mus {
            let s = front(nu, Given::Mu(mu), 1e-8);
            assert!(
                s.c > prev && s.c < 1.0,
                "ν={nu} μ={mu}: c = {} after {prev}",
                s.c
            );
            assert!(s.stick_ok, "stick inequality fails at ν={nu} μ={mu}");
            assert!(s.slip_ok, "u < 0 fails at ν={nu} μ={mu}");
            assert!(s.compliance_difference.abs() < 1e-9);
            prev = s.c;
        }
    }
}
