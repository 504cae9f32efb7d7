//! The split solver's pointwise estimates of the unknowns bound their true
//! errors at every point of the output grid, on every file whose unknowns
//! have a closed form: the manufactured split problem
//! (`examples/hertz_split_mms.lmx`: p = x, q = 4x³ on [0, 1/2) and
//! q = μp = x on [1/2, 1]), the flat punch (p = (2δ/π)/√(1 − x²)), the
//! sphere indentation (p = (4/π)√(a² − x²) on [0, a), a = √δ) and the
//! one-interval manufactured system `examples/mms.lmx` (p = 1, q = x);
//! and the ends the end check graded are left out of the grid, named in
//! the report: the cone (`p = arccosh(a/x)`, infinite at its centre) and
//! Cattaneo–Mindlin (`p = (4/π)√(1 − x²)`, `q` from the closed form).
//! (`--method` on the split solver is `tests/split_methods.rs`'s.)
use lambdamat::lang::parse_program;
use lambdamat::plan::split_fields::{LeftOutReason, LevelFields};
use lambdamat::plan::{SplitOptions, solve_split_fields};
use std::f64::consts::PI;

const GRID: usize = 101;

/// Solves `path` with each level cap of `caps` and compares every
/// unknown's grid values with `exact(name, x)`: the estimate at each point
/// bounds the error there, the report's estimate is the grid's largest,
/// and at most `skipped_max` grid points per unknown and cap are left out
/// (the singular point, points within the scalar's estimate of a moving
/// end). Returns the number of finite estimates compared.
fn check(
    path: &str,
    caps: &[usize],
    skipped_max: usize,
    exact: &dyn Fn(&str, f64) -> f64,
) -> usize {
    let text = std::fs::read_to_string(path).expect("example");
    let prog = parse_program(&text, path).expect("parses");
    let mut compared = 0;
    for &max_level in caps {
        let opts = SplitOptions {
            max_level,
            ..SplitOptions::default()
        };
        let s = solve_split_fields(&prog, &opts).expect("solves");
        let lf = LevelFields::new(&s).expect("fields");
        for (u, name) in s.problem.sys.unknowns.iter().enumerate() {
            let g = lf.on_grid(u, GRID, true).expect("grid");
            let skipped = GRID - g.x.len();
            assert!(
                skipped <= skipped_max,
                "{path}, cap {max_level}, {name}: {skipped} grid points left out"
            );
            let worst = g.errors.iter().fold(0.0f64, |m, &e| m.max(e));
            let est = s.report.unknowns.iter().find(|e| &e.name == name);
            assert!(
                est.is_some_and(|e| e.error == worst),
                "{name}: the report's estimate is the grid's largest"
            );
            let (mut max_err, mut ratio) = (0.0f64, 0.0f64);
            for ((x, v), e) in g.x.iter().zip(&g.values).zip(&g.errors) {
                let err = (v - exact(name, *x)).abs();
                max_err = max_err.max(err);
                ratio = ratio.max(err / e);
                assert!(
                    err <= *e,
                    "{path}, level cap {max_level}, {name}({x}): error {err:.3e} > estimate {e:.3e}"
                );
                compared += usize::from(e.is_finite());
            }
            eprintln!(
                "{path} cap {max_level} levels {} {name}: max error {max_err:.3e}, estimate {worst:.3e}, largest error/estimate {ratio:.3}, factor {:.3}, skipped {skipped}",
                s.report.levels,
                est.map_or(f64::NAN, |e| e.factor)
            );
        }
    }
    compared
}

#[test]
fn pointwise_estimates_bound_the_errors_of_the_manufactured_fields() {
    let compared = check(
        "examples/hertz_split_mms.lmx",
        &[3, 4, 6, 8],
        2,
        &|u, x| match u {
            "p" => x,
            _ if x < 0.5 => 4.0 * x * x * x,
            _ => x,
        },
    );
    // Finite estimates only count: an infinite one bounds anything.
    assert!(compared >= 600, "only {compared} finite estimates compared");
}

#[test]
fn pointwise_estimates_bound_the_flat_punch_pressure() {
    let delta = 1.0 / 3.0;
    // The edge x = 1 (the singular term's point) is the one point left out.
    let compared = check(
        "examples/contact/flat_punch.lmx",
        &[3, 4, 6, 8],
        1,
        &|_, x| 2.0 * delta / PI / (1.0 - x * x).sqrt(),
    );
    assert!(compared >= 300, "only {compared} finite estimates compared");
}

#[test]
fn pointwise_estimates_bound_the_sphere_indentation_pressure() {
    let a = 0.5f64.sqrt();
    let compared = check(
        "examples/contact/sphere_indentation.lmx",
        &[3, 4, 6, 8],
        2,
        &|_, x| {
            if x < a {
                4.0 / PI * (a * a - x * x).sqrt()
            } else {
                0.0
            }
        },
    );
    assert!(compared >= 300, "only {compared} finite estimates compared");
}

#[test]
fn pointwise_estimates_bound_the_one_interval_manufactured_fields() {
    let compared = check("examples/mms.lmx", &[3, 4, 6, 8], 0, &|u, x| match u {
        "p" => 1.0,
        _ => x,
    });
    assert!(compared >= 600, "only {compared} finite estimates compared");
}
/// With the unknowns driving the ladder ([`SplitOptions::fields_converge`])
/// at the default tolerance, the manufactured split problem converges and
/// its pointwise estimates bound the true errors (`check` with that
/// option), each within `tol·max(1, size)`.
#[test]
fn with_the_fields_driving_the_ladder_the_manufactured_fields_converge() {
    let opts = SplitOptions {
        fields_converge: true,
        ..SplitOptions::default()
    };
    let path = "examples/hertz_split_mms.lmx";
    let text = std::fs::read_to_string(path).expect("example");
    let prog = parse_program(&text, path).expect("parses");
    let s = solve_split_fields(&prog, &opts).expect("solves");
    assert!(s.report.converged, "{:?}", s.report.unknowns);
    let lf = LevelFields::new(&s).expect("fields");
    let mut compared = 0;
    for (u, name) in s.problem.sys.unknowns.iter().enumerate() {
        let est = &s.report.unknowns[u];
        assert!(
            est.error <= s.report.tol * est.size.max(1.0),
            "{name} ± {:.3e}",
            est.error
        );
        let g = lf.on_grid(u, GRID, true).expect("grid");
        for ((x, v), e) in g.x.iter().zip(&g.values).zip(&g.errors) {
            let exact = match name.as_str() {
                "p" => *x,
                _ if *x < 0.5 => 4.0 * x * x * x,
                _ => *x,
            };
            let err = (v - exact).abs();
            assert!(err <= *e, "{name}({x}): error {err:.3e} > estimate {e:.3e}");
            compared += usize::from(e.is_finite());
        }
    }
    assert!(compared >= 190, "only {compared} finite estimates compared");
}

/// A field the ladder cannot resolve is not converged, whatever its
/// outputs do: `p + ∫p = 1/x` (`tests/data/errors/not_converged.lmx`,
/// the one-interval solver's exit 4) on the split solver with the unknowns
/// driving the ladder.
#[test]
fn an_unresolved_field_is_not_converged() {
    let path = "tests/data/errors/not_converged.lmx";
    let text = std::fs::read_to_string(path).expect("input");
    let prog = parse_program(&text, path).expect("parses");
    let opts = SplitOptions {
        fields_converge: true,
        ..SplitOptions::default()
    };
    let s = solve_split_fields(&prog, &opts).expect("solves");
    assert!(!s.report.converged, "{:?}", s.report.unknowns);
    let p = &s.report.unknowns[0];
    assert!(p.error > s.report.tol * p.size.max(1.0), "{p:?}");
}

/// The cone's pressure `p = arccosh(a/x)` (a = 2/π) is infinite at its
/// centre: the end check grades `x = 0` (and `x = 2`), so both leave the
/// output grid, the report names them with the reason, and on the points
/// kept every estimate bounds the true error, also with the fields
/// driving the ladder.
#[test]
fn the_cone_pressure_is_estimated_without_its_infinite_centre() {
    let a = 2.0 / PI;
    let exact = move |_: &str, x: f64| if x < a { (a / x).acosh() } else { 0.0 };
    let path = "examples/contact/cone.lmx";
    let compared = check(path, &[8], 2, &exact);
    assert!(compared >= 90, "only {compared} finite estimates compared");
    let text = std::fs::read_to_string(path).expect("example");
    let prog = parse_program(&text, path).expect("parses");
    for fields_converge in [false, true] {
        let opts = SplitOptions {
            fields_converge,
            field_tol: 1e-8,
            ..SplitOptions::default()
        };
        let s = solve_split_fields(&prog, &opts).expect("solves");
        assert!(s.report.converged, "{:?}", s.report.unknowns);
        assert_eq!(s.report.field_tol, fields_converge.then_some(1e-8));
        let p = &s.report.unknowns[0];
        let graded: Vec<f64> = p
            .left_out
            .iter()
            .filter(|l| l.reason == LeftOutReason::GradedEnd)
            .map(|l| l.x)
            .collect();
        assert_eq!(graded, vec![0.0, 2.0], "{:?}", p.left_out);
        // Everything else of the grid is kept, and the size is finite.
        assert_eq!(p.left_out.len(), 2, "{:?}", p.left_out);
        assert!(p.size.is_finite() && p.error <= 1e-8 * p.size.max(1.0));
    }
}

/// Cattaneo–Mindlin (`examples/contact/cattaneo_mindlin_shift.lmx`):
/// `p = (4/π)√(1 − x²)` and `q = (p − (4/π)√(c² − x²))/2` on the stick
/// zone, `p/2` beyond, c = √(1/2). The end check grades `x = 0` and
/// `x = 1`, where the pressure's end value is off by O(1) (the innermost
/// panel under the Abel operator is seen only through its width); the
/// open interval's points are estimated, and bounded.
#[test]
fn cattaneo_mindlin_fields_are_bounded_on_the_open_interval() {
    let c = 0.5f64.sqrt();
    let compared = check(
        "examples/contact/cattaneo_mindlin_shift.lmx",
        &[8],
        3,
        &|u, x| {
            let p = 4.0 / PI * (1.0 - x * x).max(0.0).sqrt();
            if u == "p" {
                p
            } else if x < c {
                0.5 * (p - 4.0 / PI * (c * c - x * x).sqrt())
            } else {
                0.5 * p
            }
        },
    );
    assert!(compared >= 190, "only {compared} finite estimates compared");
}

/// The unknowns' estimates that decide convergence are taken on the
/// default grid whatever grid the report asks for: the `hertz` front
/// (two report points) and the library's `api::hertz_report` (101) climb
/// the same levels to the same answer.
#[test]
fn the_report_grid_does_not_decide_convergence() {
    use lambdamat::api::{Given, HertzOptions, hertz_report};
    for (nu, mu) in [(0.3, 0.5), (0.25, 0.1801)] {
        let front = lambdamat::hertz::front::solve(nu, Given::Mu(mu), &SplitOptions::default())
            .expect("solves");
        for grid in [2, 101] {
            let api = hertz_report(
                nu,
                Given::Mu(mu),
                &HertzOptions {
                    grid,
                    ..HertzOptions::default()
                },
            )
            .expect("solves");
            let j: serde_json::Value = serde_json::from_str(&api.to_json()).expect("json");
            assert_eq!(
                j["levels"].as_u64(),
                Some(front.levels as u64),
                "ν {nu}, μ {mu}, grid {grid}"
            );
            assert_eq!(j["converged"], true);
            assert_eq!(api.c(), front.c, "ν {nu}, μ {mu}, grid {grid}");
        }
    }
}

/// Where `32·ε·κ` would decide a field's estimate, the adjoint rounding
/// bound replaces it and still bounds the true error: the torsion punch
/// at w = 10 (`c = 6.0e-7`, κ about `1e10` from the grading toward `c`),
/// whose pressure is the flat punch's, `p = (2/π)/√(1 − x²)`; the thin
/// stick zone `[0, c)` leaves the grid.
#[test]
fn the_adjoint_rounding_bound_bounds_the_pressure_beside_a_thin_stick_zone() {
    let path = "examples/punch_torsion.lmx";
    let src = std::fs::read_to_string(path)
        .expect("example")
        .replace("param w  = 2 ", "param w  = 10 ");
    assert!(src.contains("param w  = 10 "));
    let prog = parse_program(&src, path).expect("parses");
    let s = solve_split_fields(&prog, &SplitOptions::default()).expect("solves");
    let r = &s.report;
    assert!(r.converged, "estimate {:.1e}", r.error_estimate);
    assert!(r.cond > 1e9, "κ {:.1e}", r.cond);
    let lf = LevelFields::new(&s).expect("fields");
    let p = s
        .problem
        .sys
        .unknowns
        .iter()
        .position(|u| u == "p")
        .expect("p");
    let e = &r.unknowns[p];
    // The adjoint bound ran: the floor is far below 32·ε·κ·max(1, size).
    assert!(
        e.floor < 1e-3 * 32.0 * f64::EPSILON * r.cond * e.size.max(1.0),
        "floor {:.1e}, κ {:.1e}",
        e.floor,
        r.cond
    );
    let g = lf.on_grid(p, 101, true).expect("grid");
    assert!(
        g.left_out
            .iter()
            .any(|l| l.reason == LeftOutReason::ThinPiece && l.x == 0.0)
    );
    assert!(g.x.len() >= 99);
    for ((x, v), err) in g.x.iter().zip(&g.values).zip(&g.errors) {
        let exact = 2.0 / PI / (1.0 - x * x).sqrt();
        assert!(
            (v - exact).abs() <= *err,
            "p({x}) = {v} ± {err:.1e}, exact {exact}"
        );
    }
}
