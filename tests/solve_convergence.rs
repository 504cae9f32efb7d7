//! Convergence through the language path: the frictionless punch solved by
//! `plan::solve_program` on refinement levels 2..4 (forced by an
//! unreachable tolerance). The error against the exact solution must fall
//! from level to level, and the error estimate carried by each answer (the
//! distance to the previous level) must not understate the error.
use lambdamat::plan::{Method, SolveOptions, solve_program};
use std::f64::consts::PI;

#[test]
fn punch_errors_fall_with_the_level_and_estimates_bound_them() {
    let src = include_str!("../examples/punch.lmx");
    let prog = lambdamat::lang::parse_program(src, "punch.lmx").expect("parses");
    let exact = |x: f64| 2.0 / PI / (1.0 - x * x).sqrt();
    let mut rows = Vec::new();
    for level in 2..=4 {
        let opts = SolveOptions {
            method: Method::Ordered,
            tol: 1e-300,
            max_level: level,
            ..SolveOptions::default()
        };
        let r = solve_program(&prog, &opts).expect("solves");
        assert_eq!(r.level, level);
        assert!(!r.converged);
        let p = &r.unknowns[0];
        let err =
            p.x.iter()
                .zip(&p.values)
                .map(|(x, v)| ((v - exact(*x)) / exact(*x)).abs())
                .fold(0.0, f64::max);
        let pstar = r.outputs[0].1.expect("P");
        rows.push((level, r.dim, err, (pstar - 1.0).abs(), r.error_estimate));
    }
    eprintln!("(level, dim, p error, |P-1|, estimate): {rows:?}");
    for w in rows.windows(2) {
        assert!(w[1].2 < 0.5 * w[0].2, "p errors do not fall: {rows:?}");
    }
    for r in &rows {
        assert!(
            r.4 >= r.2.max(1e-15),
            "estimate understates the error: {r:?}"
        );
    }
}
