//! The limits of the `hertz` front without shear stress
//! (`examples/hertz_frictionless.lmx`): `μ = 0` gives the punch pressure
//! `(2/π)/√(1-x²)` and `P* = 1`; `ν = 1/2` decouples the stresses (full
//! stick). Also the serialised keys and the refusal of bad parameters.
use lambdamat::hertz::front::{Given, Limit, frictionless_pressure, solve, solve_with_limit};
use lambdamat::plan::{PlanError, SplitOptions};

#[test]
fn zero_friction_is_the_punch() {
    let opts = SplitOptions {
        tol: 1e-12,
        max_level: 7,
        ..SplitOptions::default()
    };
    // ν < 0 (auxetic solids, -1 < ν ≤ 1/2) is accepted like ν ≥ 0.
    for nu in [-0.5, 0.0, 0.25, 0.5] {
        let s = solve(nu, Given::Mu(0.0), &opts).unwrap();
        assert!(s.converged);
        assert!(
            (s.compliance - 1.0).abs() <= 1e-12,
            "P* - 1 = {:e}",
            s.compliance - 1.0
        );
        assert_eq!(s.alpha, 0.5);
        assert_eq!(s.c, 0.0);
        assert_eq!(s.compliance_via_shear, 1.0);
        let worst = (0..1000)
            .map(|i| {
                let x = i as f64 / 1000.0;
                let p = s.p(x).unwrap();
                ((p - frictionless_pressure(x)) / frictionless_pressure(x)).abs()
            })
            .fold(0.0, f64::max);
        eprintln!("ν={nu}: relative error of p {worst:.1e}");
        // Measured 1.1e-8 at ν = 0: the split ladder's estimate (and so
        // --tol) covers the scalars and outputs (P to 1e-12 here), not p
        // pointwise, which its largest panels limit.
        assert!(worst <= 1e-7, "relative error of p: {worst:e}");
        assert_eq!(s.q(0.5).unwrap(), 0.0);
        assert!(s.stick_ok && s.slip_ok);
    }
}

#[test]
fn decoupled_material_sticks_everywhere() {
    // ν = 1/2: γ = 0, p is the punch pressure whatever μ, q = 0, c = 1.
    let s = solve(0.5, Given::Mu(0.3), &SplitOptions::default()).unwrap();
    assert_eq!(s.c, 1.0);
    assert_eq!(s.gamma, 0.0);
    assert!((s.compliance - 1.0).abs() <= 1e-10);
    assert!(s.stick_ok && s.slip_ok);
}

#[test]
fn solution_serialises_with_the_documented_keys() {
    let s = solve(0.0, Given::Mu(0.0), &SplitOptions::default()).unwrap();
    let v: serde_json::Value = serde_json::to_value(&s).unwrap();
    for k in [
        "nu",
        "gamma",
        "mu",
        "c",
        "alpha",
        "compliance",
        "compliance_via_shear",
        "compliance_difference",
        "error_estimate",
        "converged",
        "tol",
        "stick_ok",
        "slip_ok",
        "residual_c",
        "shear_jump_at_c",
        "unknowns",
        "levels",
        "condition",
        "file",
        "command",
    ] {
        assert!(v.get(k).is_some(), "missing key {k}");
    }
    assert!(v.get("solution").is_none());
}

#[test]
fn bad_parameters_are_errors_not_results() {
    let o = SplitOptions::default();
    let input = |r: Result<_, PlanError>| matches!(r, Err(e) if e.is_input_error());
    assert!(input(solve(0.0, Given::C(1.0), &o)));
    assert!(input(solve(0.0, Given::C(-0.1), &o)));
    assert!(input(solve(0.7, Given::C(0.5), &o)));
    // A stable isotropic solid has -1 < ν ≤ 1/2.
    assert!(input(solve(-1.0, Given::Mu(0.3), &o)));
    assert!(input(solve(-1.5, Given::C(0.5), &o)));
    assert!(input(solve(0.5, Given::C(0.5), &o)));
    assert!(input(solve(0.0, Given::Mu(-1.0), &o)));
    assert!(input(solve(0.0, Given::Mu(f64::NAN), &o)));
    assert!(input(solve(
        0.0,
        Given::Mu(0.3),
        &SplitOptions { tol: 0.0, ..o }
    )));
    // Stick zones below the resolved range (c < 1e-10; ν = 0, μ = 0.01
    // gives c ≈ 1e-25 by docs/hertz_asymptotics.md) are answered at the
    // end (c bounded, tests/end_answers.rs), with the limit's asymptotic
    // values beside the answer.
    let r = solve_with_limit(0.0, Given::Mu(0.01), &o).expect("an end answer");
    assert!(r.end_answer.is_some());
    let Some(Limit::SmallFriction {
        exponent,
        c_asymptotic: (lo, hi),
        compliance_asymptotic,
        ..
    }) = r.limit
    else {
        panic!("not the small-friction limit: {:?}", r.limit);
    };
    // a = −ln(1−γ²)/γ with γ = 1/2 is 2 ln(4/3);
    // P* = 1 + μ(1−2/π)/2 + Jμ²/4 (J derived, docs/hertz_asymptotics.md).
    assert!((exponent - 2.0 * (4.0f64 / 3.0).ln()).abs() < 1e-15);
    assert!(lo < hi && hi < 1e-24 && lo > 1e-26, "{lo:e} {hi:e}");
    let j = lambdamat::hertz::front::SMALL_FRICTION_COMPLIANCE_J;
    let p = 1.0 + 0.005 * (1.0 - 2.0 / std::f64::consts::PI) + 0.25 * j * 1e-4;
    assert!((compliance_asymptotic - p).abs() < 1e-15);
    // Where the end gives no answer (ν = −0.9 at the tolerance 1e-11: half
    // the resolved gap is above it) the refusal is a failed computation,
    // not bad input, and names the limit.
    let tight = SplitOptions {
        tol: 1e-11,
        ..SplitOptions::default()
    };
    let r = solve_with_limit(-0.9, Given::Mu(0.01), &tight)
        .err()
        .expect("refused");
    let text = r.error.to_string();
    assert!(text.contains("small-friction limit"), "{text}");
    assert!(!r.error.is_input_error());
}
