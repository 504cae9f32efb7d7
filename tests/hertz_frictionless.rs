//! The frictionless limit of the Hertz solver: `μ = 0` gives the punch
//! pressure `(2/π)/√(1-x²)` and `P* = 1`.
use lambdamat::hertz::solution::frictionless_pressure;
use lambdamat::hertz::{HertzOptions, solve_given_mu};

#[test]
fn zero_friction_is_the_punch() {
    let opts = HertzOptions {
        tol: 1e-12,
        ..HertzOptions::default()
    };
    for nu in [0.0, 0.25, 0.5] {
        let s = solve_given_mu(nu, 0.0, &opts).unwrap();
        assert!(s.converged);
        assert!(
            (s.compliance - 1.0).abs() <= 1e-12,
            "P* - 1 = {:e}",
            s.compliance - 1.0
        );
        assert_eq!(s.alpha, 0.5);
        let worst = (0..1000)
            .map(|i| {
                let x = i as f64 / 1000.0;
                ((s.p(x) - frictionless_pressure(x)) / frictionless_pressure(x)).abs()
            })
            .fold(0.0, f64::max);
        assert!(worst <= 1e-12, "relative error of p: {worst:e}");
        assert_eq!(s.q(0.5), 0.0);
    }
}

#[test]
fn decoupled_material_sticks_everywhere() {
    // ν = 1/2: γ = 0, p is the punch pressure whatever μ, q = 0, c = 1.
    let s = solve_given_mu(0.5, 0.3, &HertzOptions::default()).unwrap();
    assert_eq!(s.c, 1.0);
    assert!((s.compliance - 1.0).abs() <= 1e-10);
    assert!(s.stick_ok && s.slip_ok);
}

#[test]
fn solution_serialises_with_the_documented_keys() {
    let s = solve_given_mu(0.0, 0.0, &HertzOptions::default()).unwrap();
    let v: serde_json::Value = serde_json::to_value(&s).unwrap();
    for k in [
        "nu",
        "gamma",
        "mu",
        "c",
        "alpha",
        "compliance",
        "compliance_via_shear",
        "error_estimate",
        "stick_ok",
        "slip_ok",
    ] {
        assert!(v.get(k).is_some(), "missing key {k}");
    }
    assert!(v.get("fields").is_none());
}

#[test]
fn bad_parameters_are_errors_not_results() {
    use lambdamat::hertz::solve_given_c;
    let o = HertzOptions::default();
    assert!(solve_given_c(0.0, 1.0, &o).is_err());
    assert!(solve_given_c(0.0, -0.1, &o).is_err());
    assert!(solve_given_c(0.7, 0.5, &o).is_err());
    assert!(solve_given_c(0.5, 0.5, &o).is_err());
    assert!(solve_given_mu(0.0, -1.0, &o).is_err());
    assert!(solve_given_mu(0.0, f64::NAN, &o).is_err());
    assert!(solve_given_mu(0.0, 0.3, &HertzOptions { tol: 0.0, ..o }).is_err());
    // Stick zones below the reliable range are refused, not returned.
    assert!(solve_given_mu(0.0, 0.03, &o).is_err());
}
