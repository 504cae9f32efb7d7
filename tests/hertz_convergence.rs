//! Self-convergence of the `hertz` front (the language files through the
//! split-domain solver): the free parameter and the compliance are stable
//! under refinement, the two compliance formulas agree, the successive
//! differences of a refinement sequence fall, and the equations hold
//! between the collocation nodes.
use lambdamat::hertz::front::{GIVEN_C, Given, HertzResult, program, solve};
use lambdamat::numeric::roots::{bracket, brent};
use lambdamat::plan::split::{SplitLevel, SplitProblem};
use lambdamat::plan::{PlanError, SplitOptions};

fn front(nu: f64, given: Given, tol: f64, max_level: usize) -> HertzResult {
    front_with(nu, given, tol, max_level, true)
}

/// The front with the unknowns kept out of convergence: the ladder stops
/// on the scalar's tolerance alone, so a coarse `tol` gives a coarse mesh
/// (the fields' default tolerance, 1e-6, would otherwise refine it too).
fn front_scalars_only(nu: f64, given: Given, tol: f64, max_level: usize) -> HertzResult {
    front_with(nu, given, tol, max_level, false)
}

fn front_with(
    nu: f64,
    given: Given,
    tol: f64,
    max_level: usize,
    fields_converge: bool,
) -> HertzResult {
    solve(
        nu,
        given,
        &SplitOptions {
            tol,
            max_level,
            fields_converge,
            ..SplitOptions::default()
        },
    )
    .expect("the front solves")
}

#[test]
fn given_c_is_stable_to_1e_10() {
    for (nu, c) in [(0.0, 0.5), (0.25, 0.3)] {
        let s = front(nu, Given::C(c), 1e-10, 7);
        assert!(
            s.converged && s.error_estimate <= 1e-10,
            "estimate {:e}",
            s.error_estimate
        );
        assert!(
            s.compliance_difference.abs() <= 1e-11,
            "P* formulas differ by {:e}",
            s.compliance_difference
        );
        assert!(s.stick_ok && s.slip_ok);
        // A finer, independent run agrees within the claimed estimate.
        let fine = solve(
            nu,
            Given::C(c),
            &SplitOptions {
                tol: 1e-12,
                max_level: 8,
                ..SplitOptions::default()
            },
        )
        .unwrap();
        assert!(fine.levels > s.levels);
        assert!(
            (fine.mu - s.mu).abs() <= 1e-10,
            "μ moved by {:e}",
            fine.mu - s.mu
        );
        assert!(
            (fine.compliance - s.compliance).abs() <= 1e-10,
            "P* moved by {:e}",
            fine.compliance - s.compliance
        );
    }
}

/// μ(c) on one fixed level of `examples/hertz_given_c.lmx` by Brent on
/// the free-boundary condition B = 0.
fn mu_on_level(nu: f64, c: f64, k: usize) -> Result<f64, PlanError> {
    let prog = program(GIVEN_C, &[("nu", nu), ("c", c)])?;
    let problem = SplitProblem::new(&prog)?;
    let lvl = SplitLevel::level(k);
    let mut f = |mu: f64| problem.discretise(&[mu], &lvl).map(|d| d.residuals[0]);
    let (a, fa, b, fb) = bracket(&mut f, 0.1, 0.4, 0.0, 10.0)?;
    brent(&mut f, a, fa, b, fb, 1e-15)
}

#[test]
fn refinement_sequence_converges() {
    let mus: Vec<f64> = (0..6).map(|k| mu_on_level(0.0, 0.5, k).unwrap()).collect();
    let diffs: Vec<f64> = mus.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
    eprintln!("μ by level {mus:?}, differences {diffs:?}");
    for w in diffs.windows(2) {
        assert!(w[1] < 0.5 * w[0], "differences do not fall: {diffs:?}");
    }
    assert!(diffs[diffs.len() - 1] < 1e-9, "{diffs:?}");
}

#[test]
fn given_mu_inverts_given_c() {
    let s = front(0.0, Given::C(0.6), 1e-10, 7);
    let t = front(0.0, Given::Mu(s.mu), 1e-10, 7);
    assert!((t.c - 0.6).abs() <= 1e-9, "c = {}", t.c);
    assert!((t.compliance - s.compliance).abs() <= 1e-9);
    assert!(t.stick_ok && t.slip_ok);
}

#[test]
fn shear_becomes_continuous_at_c() {
    // q(c⁻) - μp(c) → 0 under refinement (q - μp(c) ~ (c-t)^{1/2}, so the
    // value on the last panel converges like the square root of its size:
    // about 1/8 per level, three layers of ratio 1/4). Measured: 9.7e-6 on
    // 3 levels (tol 1e-6), 1.3e-6 on 4, 1.7e-7 on 5 (tol 1e-12).
    let coarse = front_scalars_only(0.25, Given::C(0.3), 1e-6, 8);
    let fine = front(0.25, Given::C(0.3), 1e-12, 8);
    assert!(fine.levels >= coarse.levels + 2);
    eprintln!(
        "shear jump {:.1e} → {:.1e}",
        coarse.shear_jump_at_c, fine.shear_jump_at_c
    );
    assert!(fine.shear_jump_at_c.abs() < 0.1 * coarse.shear_jump_at_c.abs());
    assert!(fine.shear_jump_at_c.abs() < 1e-4 * fine.mu);
}

#[test]
fn equations_hold_between_the_nodes() {
    // E1 and E2 evaluated at 199 points that are not collocation nodes
    // (split_fields' residuals); includes (ν=0.25, c=0.5), the entry that
    // differs from Spence by 1e-3.
    let xs: Vec<f64> = (1..200).map(|i| (i as f64 + 0.37) / 201.0).collect();
    for (nu, c) in [(0.0, 0.5), (0.25, 0.5)] {
        let coarse = front_scalars_only(nu, Given::C(c), 1e-6, 8);
        let fine = front(nu, Given::C(c), 1e-10, 7);
        let (c1, c2) = coarse.residuals(&xs).unwrap();
        let (f1, f2) = fine.residuals(&xs).unwrap();
        eprintln!("ν={nu} c={c}: residuals E1 {c1:.1e} → {f1:.1e}, E2 {c2:.1e} → {f2:.1e}");
        assert!(f1 < 0.1 * c1 && f2 < 0.1 * c2);
        assert!(f1 <= 1e-8 && f2 <= 1e-8);
    }
}
