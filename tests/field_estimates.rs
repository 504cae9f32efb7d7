//! Convergence test of the pointwise error estimates of the Hertz fields
//! (`hertz::front::HertzResult::sample`, built on
//! `plan::split_fields::LevelFields`): at several (ν, μ) and (ν, c), the
//! fields p, q, μp and u at the default tolerance, on the profile grid the
//! CSV and the plot use (from x = 0 to 1 − 1e-5, clustered toward c), are
//! compared with a much finer solve of the same file (tolerance 1e-13, up
//! to level 11), and at one point with the hand-written oracle
//! (`src/hertz/`, tolerance 1e-12). Every true error must be within its
//! estimate; and the estimates must not be vacuous (the largest ratio
//! true/estimate stays above 1/20, and away from the edge the estimates
//! stay below 1e-4). Measured ratios: at most 0.49 (probes/field_errors.rs).
use lambdamat::hertz::front::{Given, HertzResult, Sample, profile_points, solve};
#[path = "common/hertz_oracle/mod.rs"]
mod hertz_oracle;
use hertz_oracle::{HertzOptions, solve_given_mu};
use lambdamat::plan::SplitOptions;

fn fields(s: &Sample) -> [(f64, f64); 4] {
    [
        (s.p, s.p_err),
        (s.q, s.q_err),
        (s.mu_p, s.mu_p_err),
        (s.u, s.u_err),
    ]
}

/// The default solve and the fine reference at `(nu, given)`; asserts
/// the estimates bound the true errors; returns the default solve.
fn check(nu: f64, given: Given) -> HertzResult {
    let s = solve(nu, given, &SplitOptions::default()).expect("solves");
    let fine = SplitOptions {
        tol: 1e-13,
        max_level: 11,
        ..SplitOptions::default()
    };
    let r = solve(nu, given, &fine).expect("reference solves");
    let xs = profile_points(s.c, 200);
    let ours = s.sample(&xs).expect("samples");
    let refs = r.sample(&xs).expect("reference samples");
    let mut worst_ratio = 0.0f64;
    for (a, b) in ours.iter().zip(&refs) {
        for (k, ((v, e), (t, _))) in fields(a).into_iter().zip(fields(b)).enumerate() {
            let err = (v - t).abs();
            assert!(
                err <= e,
                "ν = {nu}, {given:?}: field {k} at x = {}: true error {err:e} > estimate {e:e}",
                a.x
            );
            if err > 0.0 {
                worst_ratio = worst_ratio.max(err / e);
            }
            if a.x <= 0.9 {
                assert!(
                    e < 1e-4,
                    "ν = {nu}, {given:?}: estimate {e:e} at x = {}",
                    a.x
                );
            }
        }
    }
    eprintln!("ν = {nu}, {given:?}: largest true/estimate {worst_ratio:.3}");
    assert!(worst_ratio > 0.05, "estimates vacuous: {worst_ratio}");
    // The values at c, each level at its own c.
    for (name, v, t) in [
        ("shear_jump_at_c", s.shear_jump_at_c, r.shear_jump_at_c),
        ("residual_c", s.residual_c, r.residual_c),
    ] {
        let e = s.field_error_estimates[name];
        assert!((v - t).abs() <= e, "{name}: {v:e} vs {t:e} ± {e:e}");
    }
    s
}

#[test]
fn field_estimates_bound_the_true_errors_mid_range_and_against_the_oracle() {
    let s = check(0.25, Given::Mu(0.1801));
    let o = HertzOptions {
        tol: 1e-12,
        max_level: 10,
    };
    let oracle = solve_given_mu(0.25, 0.1801, &o).expect("oracle solves");
    let xs: Vec<f64> = profile_points(s.c, 200)
        .into_iter()
        .filter(|&x| x <= 0.99)
        .collect();
    let ours = s.sample(&xs).expect("samples");
    let theirs = oracle.sample(&xs).expect("oracle samples");
    for (a, b) in ours.iter().zip(&theirs) {
        for ((v, e), (t, _)) in fields(a).into_iter().zip(fields(b)) {
            assert!((v - t).abs() <= e, "x = {}: {v} vs oracle {t} ± {e:e}", a.x);
        }
    }
}

#[test]
fn field_estimates_bound_the_true_errors_given_c() {
    check(0.25, Given::C(0.8));
}

#[test]
fn field_estimates_bound_the_true_errors_at_negative_nu() {
    check(-0.5, Given::Mu(0.3));
}

#[test]
fn field_estimates_bound_the_true_errors_near_full_stick() {
    // 1 − c ≈ 8.8e-5: the fields near c vary on that scale, and c's own
    // uncertainty is what bounds them there.
    check(0.45, Given::Mu(0.3));
}
