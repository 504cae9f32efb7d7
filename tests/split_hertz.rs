//! The Hertz problem through the language (`examples/hertz.lmx`,
//! `examples/hertz_given_c.lmx`, solved by `plan::split`) against the
//! hand-written solver in `lambdamat::hertz` (kept as an independent
//! oracle), on every row of Spence's table in the seed (both directions),
//! and through the CLI with `--set`.
mod common;

use common::cli::{json, lambdamat};
use lambdamat::hertz::{HertzOptions, solve_given_c, solve_given_mu};
use lambdamat::lang::parse_program_with;
use lambdamat::lang::parser::parse_exact;
use lambdamat::plan::{SplitOptions, SplitReport, solve_split};

/// Spence's (ν, μ, c) rows (seed Table 1, column c1).
const SPENCE: [(&str, &str, &str); 7] = [
    ("0", "0.2063", "0.24"),
    ("0", "0.2986", "0.50"),
    ("0", "0.4013", "0.70"),
    ("0", "0.4862", "0.80"),
    ("0.25", "0.1387", "0.30"),
    ("0.25", "0.1801", "0.50"),
    ("0.25", "0.2843", "0.80"),
];

fn solve_file(path: &str, sets: &[(&str, &str)]) -> SplitReport {
    let src = std::fs::read_to_string(path).expect("example exists");
    let sets: Vec<_> = sets
        .iter()
        .map(|(n, v)| (n.to_string(), parse_exact(v).expect("exact")))
        .collect();
    let prog = parse_program_with(&src, path, &sets).expect("valid");
    solve_split(&prog, &SplitOptions::default()).expect("solves")
}

fn get(list: &[lambdamat::plan::split_solve::Estimate], name: &str) -> (f64, f64) {
    let e = list.iter().find(|e| e.name == name).expect("present");
    (e.value, e.error)
}

#[test]
fn given_mu_agrees_with_the_builtin_on_spence_rows() {
    for (nu, mu, _) in SPENCE {
        let r = solve_file("examples/hertz.lmx", &[("nu", nu), ("mu", mu)]);
        let s = solve_given_mu(
            nu.parse().unwrap(),
            mu.parse().unwrap(),
            &HertzOptions::default(),
        )
        .expect("built-in solves");
        let (c, ce) = get(&r.scalars, "c");
        let (p, pe) = get(&r.outputs, "P");
        let (ps, _) = get(&r.outputs, "P_shear");
        eprintln!(
            "ν={nu} μ={mu}: c = {c:.15} ± {ce:.1e} (built-in {:.15}, Δ {:.1e}); P = {p:.15} ± {pe:.1e} (Δ {:.1e})",
            s.c,
            c - s.c,
            p - s.compliance
        );
        assert!(r.converged && ce <= 1e-10 && pe <= 1e-10);
        assert!((c - s.c).abs() <= 1e-10, "c: {c} vs {}", s.c);
        assert!((p - s.compliance).abs() <= 1e-10);
        assert!((ps - s.compliance_via_shear).abs() <= 1e-10);
        assert!((p - ps).abs() <= 1e-10, "the two compliance formulas");
        // The free-boundary coefficient is zero at the solution.
        assert!(get(&r.coefficients, "B").0.abs() <= 1e-10);
    }
}

#[test]
fn given_c_agrees_with_the_builtin_on_spence_rows() {
    for (nu, _, c) in SPENCE {
        let r = solve_file("examples/hertz_given_c.lmx", &[("nu", nu), ("c", c)]);
        let s = solve_given_c(
            nu.parse().unwrap(),
            c.parse().unwrap(),
            &HertzOptions::default(),
        )
        .expect("built-in solves");
        let (mu, me) = get(&r.scalars, "mu");
        let (p, _) = get(&r.outputs, "P");
        eprintln!(
            "ν={nu} c={c}: μ = {mu:.15} ± {me:.1e} (built-in {:.15}, Δ {:.1e}); P Δ {:.1e}",
            s.mu,
            mu - s.mu,
            p - s.compliance
        );
        assert!(r.converged && me <= 1e-10);
        assert!((mu - s.mu).abs() <= 1e-10);
        assert!((p - s.compliance).abs() <= 1e-10);
    }
}

#[test]
fn cli_solve_with_set_matches_cli_hertz() {
    let ours = json(&[
        "solve",
        "examples/hertz.lmx",
        "--set",
        "nu=0.25",
        "--set",
        "mu=0.1801",
    ]);
    let theirs = json(&["hertz", "--nu", "0.25", "--mu", "0.1801"]);
    let c = ours["scalars"]["c"].as_f64().expect("c");
    let p = ours["outputs"]["P"].as_f64().expect("P");
    assert!((c - theirs["c"].as_f64().expect("c")).abs() <= 1e-10);
    assert!((p - theirs["compliance"].as_f64().expect("P")).abs() <= 1e-10);
    assert!(ours["error_estimates"]["c"].as_f64().expect("estimate") <= 1e-10);
    assert_eq!(ours["converged"], true);
    let inv = json(&[
        "solve",
        "examples/hertz_given_c.lmx",
        "--set",
        "nu=0",
        "--set",
        "c=1/2",
    ]);
    let theirs = json(&["hertz", "--nu", "0", "--c", "0.5"]);
    let mu = inv["scalars"]["mu"].as_f64().expect("mu");
    assert!((mu - theirs["mu"].as_f64().expect("mu")).abs() <= 1e-10);
}

#[test]
fn set_errors_are_invalid_input() {
    for args in [["--set", "nx=1"], ["--set", "nu=1e-3"], ["--set", "nu"]] {
        let out = lambdamat()
            .args(["solve", "examples/hertz.lmx"])
            .args(args)
            .output()
            .expect("runs");
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(String::from_utf8_lossy(&out.stderr).contains("--set"));
    }
}

#[test]
fn too_few_levels_is_not_success() {
    let out = lambdamat()
        .args(["solve", "examples/hertz.lmx", "--max-level", "1"])
        .output()
        .expect("runs");
    // Two levels cannot agree to 1e-10: printed, marked, exit 4.
    assert_eq!(out.status.code(), Some(4));
    assert!(String::from_utf8_lossy(&out.stdout).contains("not converged"));
}
