//! Every classical kernel class through the language path (`parse_program`
//! → `lambdamat::report::solve`, the one solver, at tol 1e-10 for the
//! outputs and the fields): Abel kernels of order 1/2 in
//! three spellings and of order 2/3, Carleman's logarithmic equation, the
//! airfoil equation (principal value), Love's equation (peaked kernel)
//! against a Nyström reference computed here, solutions with endpoint
//! behaviour, and a coupled 3×3 system mixing kernel classes. Every case
//! checks the true error against an exact (or independently computed)
//! solution, and that the reported estimate is not below it.
use lambdamat::report::{Report, SolveSettings};
use nalgebra::{DMatrix, DVector};
use std::f64::consts::PI;

/// A solve in the shape these checks read: unknowns and outputs in the
/// order declared, and the largest absolute estimate of them all (the
/// errors below are measured relative to `max(1, |exact|)`, never above
/// the absolute error).
struct Solved {
    unknowns: Vec<Field>,
    outputs: Vec<(String, Option<f64>)>,
    error_estimate: f64,
    converged: bool,
    level: usize,
    dim: f64,
    cond: f64,
}

struct Field {
    x: Vec<f64>,
    values: Vec<f64>,
    weight: String,
}

fn solved(prog: &lambdamat::system::Program, r: Report) -> Solved {
    let mut est = 0.0f64;
    let unknowns = prog
        .unknowns
        .iter()
        .map(|n| {
            let u = &r.unknowns[n];
            est = est.max(u.error_estimate);
            Field {
                x: u.x.clone(),
                values: u.values.clone(),
                weight: u.weight.clone(),
            }
        })
        .collect();
    let outputs = prog
        .outputs
        .iter()
        .map(|o| {
            let v = r.outputs.get(&o.name).copied();
            if let Some(e) = r.error_estimates.get(&o.name) {
                est = est.max(*e);
            }
            (o.name.clone(), v)
        })
        .collect();
    let num = |k: &str| r.extra.get(k).and_then(|v| v.as_f64()).unwrap_or(f64::NAN);
    Solved {
        unknowns,
        outputs,
        error_estimate: est,
        converged: r.converged,
        level: r.levels,
        dim: num("dim"),
        cond: num("cond"),
    }
}

/// The fields are checked to the tolerance too (`--field-tol`).
fn settings(tol: f64) -> SolveSettings {
    SolveSettings {
        tol,
        field_tol: Some(tol),
        ..SolveSettings::default()
    }
}

fn solve_with(src: &str, s: &SolveSettings) -> Result<Solved, lambdamat::plan::PlanError> {
    let prog = lambdamat::lang::parse_program(src, "k.lmx").expect("parses");
    lambdamat::report::solve(&prog, s).map(|r| solved(&prog, r))
}

fn solve(src: &str) -> Solved {
    solve_with(src, &settings(1e-10)).expect("solves")
}

/// Largest relative (to max(1, |exact|)) error of unknown `j` on the grid.
fn grid_error(r: &Solved, j: usize, exact: impl Fn(f64) -> f64) -> f64 {
    let u = &r.unknowns[j];
    u.x.iter()
        .zip(&u.values)
        .filter(|(x, _)| exact(**x).is_finite())
        .map(|(x, v)| (v - exact(*x)).abs() / exact(*x).abs().max(1.0))
        .fold(0.0, f64::max)
}

/// Converged, accurate to `tol`, and the estimate bounds the error.
fn check(name: &str, r: &Solved, err: f64, tol: f64) {
    eprintln!(
        "{name}: error {err:.2e}, estimate {:.2e}, level {}, dim {}, cond {:.1e}",
        r.error_estimate, r.level, r.dim, r.cond
    );
    assert!(r.converged, "{name}: not converged");
    assert!(err < tol, "{name}: error {err:.2e} ≥ {tol:.0e}");
    assert!(
        r.error_estimate >= err,
        "{name}: estimate {:.2e} below the error {err:.2e}",
        r.error_estimate
    );
}

#[test]
fn abel_half_in_three_spellings() {
    for k in ["1/sqrt(x - t)", "(x - t)^(-1/2)", "1/sqrt(abs(x - t))"] {
        let src = format!(
            "operator k = int(0..x) {k} dt\nunknown f\nequation k f = 2*sqrt(x) + 4/3*x^(3/2)\noutput I = int(0..1) f(x) dx\n"
        );
        let r = solve(&src);
        check(k, &r, grid_error(&r, 0, |t| 1.0 + t), 1e-12);
    }
}

#[test]
fn abel_on_an_interval_reaching_negative_x() {
    // ∫_{-1}^x (1+t)/√(x-t) dt = (4/3)(x+1)^{3/2}.
    let src = "operator k = int(-1..x) 1/sqrt(x - t) dt\nunknown f\nequation k f = 4/3*(x + 1)^(3/2)\noutput I = int(-1..1) f(x) dx\n";
    let r = solve(src);
    check("abel on [-1, 1]", &r, grid_error(&r, 0, |t| 1.0 + t), 1e-12);
}

#[test]
fn abel_order_one_third_and_upper_limit() {
    // ∫_0^x (1+t)(x-t)^(-1/3) dt = (3/2)x^{2/3} + (9/10)x^{5/3}.
    let src = "operator k = int(0..x) (x - t)^(-1/3) dt\nunknown f\nequation k f = 3/2*x^(2/3) + 9/10*x^(5/3)\noutput I = int(0..1) f(x) dx\n";
    let r = solve(src);
    check("order 1/3", &r, grid_error(&r, 0, |t| 1.0 + t), 1e-11);
    // ∫_x^1 t (t-x)^(-1/3) dt = x·(3/2)(1-x)^{2/3} + (3/5)(1-x)^{5/3}.
    let src = "operator k = int(x..1) (t - x)^(-1/3) dt\nunknown f\nequation k f = 3/2*x*(1 - x)^(2/3) + 3/5*(1 - x)^(5/3)\noutput I = int(0..1) f(x) dx\n";
    let r = solve(src);
    check("order 1/3 upper", &r, grid_error(&r, 0, |t| t), 1e-11);
}

#[test]
fn carleman_logarithmic_equation() {
    let src = "operator k = int(-1..1) ln(abs(x - t)) dt\nunknown f\nequation k f = 1\n";
    let r = solve(src);
    let c = -1.0 / (PI * std::f64::consts::LN_2);
    // The weighted solution f √(1-x²) against the constant c.
    let u = &r.unknowns[0];
    let err =
        u.x.iter()
            .zip(&u.values)
            .map(|(x, v)| (v * (1.0 - x * x).sqrt() - c).abs())
            .fold(0.0, f64::max);
    assert!(u.x.len() > 90);
    check("carleman", &r, err, 1e-10);
}

#[test]
fn airfoil_equation_bounded_solution() {
    // (1/π) PV∫ √(1-t²) U_{n-1}(t)/(t-x) dt = -T_n(x): f = √(1-t²)(1 + 2t).
    let src =
        "operator h = 1/pi*pv int(-1..1) 1/(t - x) dt\nunknown f\nequation h f = 1 - x - 2*x^2\n";
    let r = solve(src);
    let err = grid_error(&r, 0, |t| (1.0 - t * t).sqrt() * (1.0 + 2.0 * t));
    check("airfoil", &r, err, 1e-10);
}

/// Largest error of the weighted unknown `f·√(1-x²)` against `phi`.
fn weighted_error(r: &Solved, phi: impl Fn(f64) -> f64) -> f64 {
    let u = &r.unknowns[0];
    assert!(u.x.len() > 90, "grid points left out");
    u.x.iter()
        .zip(&u.values)
        .map(|(x, v)| (v * (1.0 - x * x).sqrt() - phi(*x)).abs() / phi(*x).abs().max(1.0))
        .fold(0.0, f64::max)
}

#[test]
fn airfoil_equation_with_side_condition_unbounded_class() {
    // (1/π) PV∫ T_n(t)/(√(1-t²)(t-x)) dt = U_{n-1}(x) and 0 for n = 0:
    // g = 1 has the solutions f = (t + c)/√(1-t²), and ∫_{-1}^1 f dt = cπ
    // selects one. With ∫ f = 2: c = 2/π, so f(1/2) = (1/2 + 2/π)/√(3/4).
    let src = "operator h = 1/pi*pv int(-1..1) 1/(t - x) dt\nunknown f\nequation h f = 1\n\
               condition int(-1..1) f(t) dt = 2\noutput V = f(1/2)\noutput W = int(-1..1) f(x) dx + 3*f(0)\n";
    let r = solve(src);
    assert!(
        r.unknowns[0].weight.contains("-0.5"),
        "{}",
        r.unknowns[0].weight
    );
    let c = 2.0 / PI;
    let err = weighted_error(&r, |x| x + c);
    let v = r.outputs[0].1.expect("V");
    let w = r.outputs[1].1.expect("W");
    let err = err
        .max((v - (0.5 + c) / 0.75f64.sqrt()).abs())
        .max((w - (2.0 + 3.0 * c)).abs() / (2.0 + 3.0 * c));
    check("airfoil, side condition, g = 1", &r, err, 1e-10);

    // A solution that is not a polynomial times the weight: with a = 2,
    // (1/π) ∫ 1/((a-t)√(1-t²)) dt = 1/√(a²-1) and the principal value of
    // 1/(√(1-t²)(t-x)) vanishes, so φ = 1/(a - t) + c solves
    // g = 1/((a - x)√(a²-1)) for every c, and ∫ f = π/√(a²-1) + cπ.
    // With ∫ f = 1: c = 1/π - 1/√3.
    let src = "operator h = 1/pi*pv int(-1..1) 1/(t - x) dt\nunknown f\n\
               equation h f = 1/((2 - x)*sqrt(3))\ncondition int(-1..1) f(t) dt = 1\n";
    // With a side condition the system is solved by least squares. Its
    // condition grows with the grading toward ±1 (1e5 on level 4, 1e7 on
    // level 9) faster than the discretisation error falls, so the fields
    // stop near 1e-8, short of 1e-10 (measured: f/weight off by 6.1e-11,
    // 2.5e-10, 3.8e-9 and 1.0e-8 on levels 4, 5, 6 and 9); the answer is
    // marked (not converged) with an estimate that still bounds its
    // error.
    let r = solve(src);
    let c = 1.0 / PI - 1.0 / 3f64.sqrt();
    let err = weighted_error(&r, |x| 1.0 / (2.0 - x) + c);
    eprintln!(
        "airfoil, side condition, g = 1/((2-x)√3): error {err:.2e}, estimate {:.2e}, converged {}",
        r.error_estimate, r.converged
    );
    assert!(err < 1e-7, "error {err:.2e}");
    assert!(
        r.error_estimate >= err,
        "estimate {:.2e} below {err:.2e}",
        r.error_estimate
    );
}

#[test]
fn contradicting_side_condition_is_not_converged() {
    // f - ∫_0^1 x t f dt = 1 - x/2 has the one solution f = 1, so ∫ f = 2
    // cannot hold: the least-squares residual stays and the answer is
    // marked unconverged.
    let src = "operator k = id - int(0..1) x*t dt\nunknown f\nequation k f = 1 - x/2\n\
               condition int(0..1) f(x) dx = 2\n";
    let r = solve(src);
    assert!(!r.converged, "estimate {:.2e}", r.error_estimate);
    assert!(r.error_estimate > 1e-3, "estimate {:.2e}", r.error_estimate);
    // The consistent condition ∫ f = 1 converges to f = 1.
    let r = solve(&src.replace("dx = 2", "dx = 1"));
    check(
        "consistent side condition",
        &r,
        grid_error(&r, 0, |_| 1.0),
        1e-10,
    );
}

#[test]
fn point_values_in_outputs_carry_the_estimate() {
    // Volterra f + ∫_0^x f dt = 1 on [0, 2] (declared: no output needed
    // to fix the interval): f = exp(-x).
    let src = "operator k = id + int(0..x) dt\nunknown f on [0, 2]\nequation k f = 1\n\
               output P = f(1/2) - 2*f(3/2) + int(0..1) f(x) dx\n";
    let r = solve(src);
    assert_eq!(r.unknowns[0].x.last(), Some(&2.0));
    let exact = (-0.5f64).exp() - 2.0 * (-1.5f64).exp() + 1.0 - (-1.0f64).exp();
    let p = r.outputs[0].1.expect("P");
    let err = (p - exact).abs().max(grid_error(&r, 0, |x| (-x).exp()));
    check("point values", &r, err, 1e-10);
}

#[test]
fn log_kernel_with_a_constant_inside() {
    // ln|3(x - t)| = ln|x - t| + ln 3 and ∫ ln|x-t|/√(1-t²) dt = -π ln 2,
    // so f = 1/(π ln(3/2) √(1-t²)) solves ∫ ln|3(x-t)| f dt = 1.
    for k in [
        "ln(abs(3*x - 3*t))",
        "ln(abs(x - t)*3)",
        "2*ln(abs(3*(t - x)))/2",
    ] {
        let src = format!("operator k = int(-1..1) {k} dt\nunknown f\nequation k f = 1\n");
        let r = solve(&src);
        let c = 1.0 / (PI * 1.5f64.ln());
        check(k, &r, weighted_error(&r, |_| c), 1e-10);
    }
}

#[test]
fn every_function_in_kernels_and_right_sides() {
    // f - ∫_0^1 x F(t) f(t) dt = 1 - x ∫_0^1 F has the solution f = 1;
    // the integral is written with the functions themselves.
    let cases = [
        ("sin(t)", "1 - cos(1)"),
        ("cos(t)", "sin(1)"),
        ("tan(t)", "-ln(cos(1))"),
        ("asin(t/2)", "pi/6 + sqrt(3) - 2"),
        ("acos(t/2)", "pi/3 - sqrt(3) + 2"),
        ("atan(t)", "pi/4 - ln(2)/2"),
        ("acot(t)", "pi/4 + ln(2)/2"),
        ("sinh(t)", "cosh(1) - 1"),
        ("cosh(t)", "sinh(1)"),
        ("tanh(t)", "ln(cosh(1))"),
    ];
    for (f, integral) in cases {
        let src = format!(
            "operator k = id - int(0..1) x*{f} dt\nunknown u\nequation k u = 1 - x*({integral})\noutput I = int(0..1) u(x) dx\n"
        );
        let r = solve(&src);
        let err = grid_error(&r, 0, |_| 1.0).max((r.outputs[0].1.expect("I") - 1.0).abs());
        check(f, &r, err, 1e-12);
    }
}

#[test]
fn cauchy_kernel_without_pv_is_refused() {
    let src = "operator h = int(-1..1) 1/(t - x) dt\nunknown f\nequation h f = 1\n";
    let prog = lambdamat::lang::parse_program(src, "k.lmx").expect("parses");
    let e = lambdamat::report::solve(&prog, &SolveSettings::default()).expect_err("refused");
    assert!(e.is_input_error());
    assert!(e.to_string().contains("principal value"), "{e}");
}

/// Nyström reference for f ∓ (1/π)∫_{-1}^1 κ/(κ²+(x-t)²) f dt = 1: ∫ f.
fn love_reference(kappa: f64, sign: f64) -> f64 {
    let panels = 100;
    let g = lambdamat::numeric::gauss::gauss_legendre(16).expect("rule");
    let (mut t, mut w) = (Vec::new(), Vec::new());
    for p in 0..panels {
        let a = -1.0 + 2.0 * p as f64 / panels as f64;
        let (tp, wp) = g.mapped(a, a + 2.0 / panels as f64);
        t.extend(tp);
        w.extend(wp);
    }
    let n = t.len();
    let k = |x: f64, s: f64| kappa / (kappa * kappa + (x - s) * (x - s)) / PI;
    let a = DMatrix::from_fn(n, n, |i, j| {
        (i == j) as u8 as f64 - sign * w[j] * k(t[i], t[j])
    });
    let f = a
        .lu()
        .solve(&DVector::from_element(n, 1.0))
        .expect("solves");
    f.iter().zip(&w).map(|(f, w)| f * w).sum()
}

#[test]
fn love_equation_both_signs_two_widths() {
    for (kappa, ktext) in [(1.0, "1"), (0.1, "1/10")] {
        for (sign, stext) in [(1.0, "-"), (-1.0, "+")] {
            let src = format!(
                "operator k = id {stext} 1/pi*int(-1..1) ({ktext})/(({ktext})^2 + (x - t)^2) dt\nunknown f\nequation k f = 1\noutput I = int(-1..1) f(x) dx\n"
            );
            let r = solve(&src);
            let i = r.outputs[0].1.expect("I");
            let exact = love_reference(kappa, sign);
            let err = (i - exact).abs() / exact.abs().max(1.0);
            check(&format!("love κ={kappa} {stext}"), &r, err, 1e-10);
        }
    }
}

#[test]
fn endpoint_behaviour_sqrt_and_inverse_sqrt() {
    let r =
        solve("operator k = id + int(0..1) x*t dt\nunknown f\nequation k f = sqrt(x) + 2/5*x\n");
    check("√t", &r, grid_error(&r, 0, f64::sqrt), 1e-10);
    let r =
        solve("operator k = id + int(0..1) x*t dt\nunknown f\nequation k f = 1/sqrt(x) + 2/3*x\n");
    check("1/√t", &r, grid_error(&r, 0, |t| 1.0 / t.sqrt()), 1e-10);
    // Both ends: f = √(t(1-t)) (∫_0^1 t f dt = π/16).
    let r = solve(
        "operator k = id + int(0..1) x*t dt\nunknown f\nequation k f = sqrt(x*(1 - x)) + pi/16*x\n",
    );
    check(
        "√(t(1-t))",
        &r,
        grid_error(&r, 0, |t| (t * (1.0 - t)).sqrt()),
        1e-10,
    );
}

#[test]
fn coupled_log_abel_smooth_system() {
    let src = "operator L = int(0..1) ln(abs(x - t)) dt
operator A = int(0..x) 1/sqrt(x - t) dt
operator S = int(0..1) x*t dt
unknown f, g, h
equation L f + g = x*ln(x) + (1 - x)*ln(1 - x) - 1 + x
equation A g + h = 4/3*x^(3/2) + 1 + x
equation f + S h = 1 + 5/6*x
";
    let r = solve(src);
    let err = grid_error(&r, 0, |_| 1.0)
        .max(grid_error(&r, 1, |x| x))
        .max(grid_error(&r, 2, |x| 1.0 + x));
    check("3×3", &r, err, 1e-10);
}

#[test]
fn end_weights_do_not_depend_on_the_outputs() {
    // Issue 27: the two-sided Abel equation (exact f ~ (1 - t²)^(-1/4))
    // with and without an output near its singular end: the trial space is
    // chosen from the equations and the unknowns only.
    let base = "operator k = int(-1..1) 1/sqrt(abs(x - t)) dt\nunknown f\nequation k f = 1\noutput I = int(-1..1) f(x) dx\n";
    let more = format!("{base}output Fa = f(999/1000)\n");
    let other = "operator k = id + int(0..1) x*t dt\nunknown f\nequation k f = 1/sqrt(x) + 2/3*x\n";
    let other_more = format!("{other}output F = f(1/1000)\noutput G = int(0..1) f(x) dx\n");
    for tol in [1e-6, 1e-8] {
        let opts = settings(tol);
        for (a, b) in [(base, more.as_str()), (other, other_more.as_str())] {
            let solve = |src: &str| solve_with(src, &opts).expect("solves");
            let (ra, rb) = (solve(a), solve(b));
            assert_eq!(
                ra.unknowns[0].weight, rb.unknowns[0].weight,
                "tol {tol:e}: the weight changed with the outputs"
            );
            assert_ne!(
                ra.unknowns[0].weight, "1",
                "tol {tol:e}: no end weight chosen"
            );
        }
    }
}
