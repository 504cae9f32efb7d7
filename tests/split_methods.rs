//! `--method` on the split-domain solver: `ordered` (exact block
//! elimination in the derivation's pivot order on the split system's
//! (equation, unknown) blocks) agrees with `coupled` within the estimates
//! on split files (the manufactured split problem, the Hertz problem for
//! its stick radius and at a given one) and on one-interval files fed to
//! the split solver, and the report says which method ran; the
//! `commutative` model agrees with `coupled` where its commuted operators
//! commute and differs (defect near 1) where they do not;
//! every file or method it cannot take is refused with exit 2 and the
//! reason.
use std::io::Write;
use std::process::Command;

use lambdamat::lang::parse_program;
use lambdamat::plan::split_fields::LevelFields;
use lambdamat::plan::split_methods::Commuted;
use lambdamat::plan::{Method, PlanError, SplitOptions, SplitSolution, solve_split_fields};

fn solve(path: &str, method: Method) -> SplitSolution {
    let text = std::fs::read_to_string(path).expect("file");
    let prog = parse_program(&text, path).expect("parses");
    let opts = SplitOptions {
        method,
        ..SplitOptions::default()
    };
    solve_split_fields(&prog, &opts).unwrap_or_else(|e| panic!("{path} {method}: {e}"))
}

/// Solves `path` by `coupled` and `ordered` and checks that every scalar,
/// output and coefficient, and every unknown on the output grid, agree
/// within the two estimates together (each bounds its own error). Returns the number of values
/// compared.
fn agree(path: &str) -> usize {
    let c = solve(path, Method::Coupled);
    let o = solve(path, Method::Ordered);
    assert_eq!(c.report.method, "coupled");
    assert_eq!(o.report.method, "ordered");
    assert!(c.report.converged && o.report.converged, "{path}");
    let mut compared = 0;
    let lists = |s: &SplitSolution| {
        let r = &s.report;
        r.scalars
            .iter()
            .chain(&r.outputs)
            .chain(&r.coefficients)
            .cloned()
            .collect::<Vec<_>>()
    };
    for (a, b) in lists(&c).iter().zip(lists(&o)) {
        assert_eq!(a.name, b.name);
        let diff = (a.value - b.value).abs();
        let est = a.error + b.error;
        eprintln!(
            "{path} {}: |ordered - coupled| = {diff:.2e}, estimate {est:.2e}",
            a.name
        );
        assert!(diff <= est, "{path} {}: {diff:e} > {est:e}", a.name);
        compared += 1;
    }
    let (fc, fo) = (
        LevelFields::new(&c).expect("fields"),
        LevelFields::new(&o).expect("fields"),
    );
    for (u, name) in c.problem.sys.unknowns.iter().enumerate() {
        let (gc, go) = (
            fc.on_grid(u, 101, true).expect("grid"),
            fo.on_grid(u, 101, true).expect("grid"),
        );
        let mut worst = 0.0f64;
        for (i, x) in gc.x.iter().enumerate() {
            let Some(j) = go.x.iter().position(|y| y == x) else {
                continue;
            };
            let diff = (gc.values[i] - go.values[j]).abs();
            let est = gc.errors[i] + go.errors[j];
            worst = worst.max(diff);
            assert!(diff <= est, "{path} {name}({x}): {diff:e} > {est:e}");
            compared += 1;
        }
        eprintln!("{path} {name}: largest |ordered - coupled| on the grid {worst:.2e}");
    }
    // The ordered elimination executed the derivation's pivots.
    let record = o.problem.method_record().expect("a record");
    assert_eq!(record.pivots.len(), c.problem.sys.unknowns.len(), "{path}");
    assert!(c.problem.method_record().is_none());
    compared
}

#[test]
fn ordered_agrees_with_coupled_on_the_manufactured_split_problem() {
    assert!(agree("examples/hertz_split_mms.lmx") >= 150);
}

#[test]
fn ordered_agrees_with_coupled_on_the_hertz_problem() {
    let o = solve("examples/hertz.lmx", Method::Ordered);
    // Eliminate q from the stick equation E2 (the principal k4), then p.
    assert_eq!(
        o.problem.method_record().expect("record").pivots,
        vec![(2, 2), (1, 1)]
    );
    assert!(agree("examples/hertz.lmx") >= 150);
}

#[test]
fn ordered_agrees_with_coupled_on_the_hertz_problem_at_a_given_c() {
    assert!(agree("examples/hertz_given_c.lmx") >= 150);
}

#[test]
fn ordered_agrees_with_coupled_on_one_interval_files_through_the_split_solver() {
    assert!(agree("examples/mms.lmx") >= 150);
    assert!(agree("tests/data/codegen_terms.lmx") >= 150);
}

fn lambdamat(args: &[&str]) -> (Option<i32>, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_lambdamat"))
        .args(args)
        .output()
        .expect("runs");
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn the_cli_runs_ordered_on_a_split_file_and_says_so() {
    for (method, text) in [("ordered", true), ("coupled", true), ("ordered", false)] {
        let mut args = vec!["solve", "examples/hertz_split_mms.lmx", "--method", method];
        if !text {
            args.push("--json");
        }
        let (code, out, err) = lambdamat(&args);
        assert_eq!(code, Some(0), "{method}: {err}");
        if text {
            assert!(out.starts_with(&format!("method: {method}\n")), "{out}");
        } else {
            let v: serde_json::Value = serde_json::from_str(&out).expect("json");
            assert_eq!(v["method"], method);
            assert_eq!(
                v["pivots"],
                serde_json::json!([{"equation": 2, "unknown": "q"}, {"equation": 1, "unknown": "p"}])
            );
        }
    }
}

fn file(text: &str) -> tempfile::NamedTempFile {
    let mut f = tempfile::Builder::new()
        .suffix(".lmx")
        .tempfile()
        .expect("temp file");
    f.write_all(text.as_bytes()).expect("write");
    f
}

#[test]
fn methods_the_split_solver_cannot_run_are_refused_with_the_reason() {
    // q is collocated with the stick equation on (0, 1/2) and with the
    // first equation where the relation substitutes p.
    let swap = file(
        "operator k = int(0..1) x*t dt\n\
         unknown p, q on [0, 1]\n\
         equation p + k q = 1 on [0, 1]\n\
         equation q + k p = x on [0, 1/2)\n\
         relation p = q on [1/2, 1]\n\
         output P = int(0..1) p(x) dx\n",
    );
    let swap = swap.path().to_str().expect("path").to_string();
    let (code, _, err) = lambdamat(&["solve", &swap, "--method", "coupled"]);
    assert_eq!(code, Some(0), "coupled solves it: {err}");
    let cases: [(&str, &str, &[&str]); 4] = [
        (
            swap.as_str(),
            "ordered",
            &["q is collocated with equation 2 on (0, 0.5) but with equation 1 on (0.5, 1)"],
        ),
        (
            "examples/hertz_frictionless.lmx",
            "ordered",
            &["q is nowhere free"],
        ),
        (
            "tests/data/split_products_mms.lmx",
            "ordered",
            &["side conditions add rows outside every (equation, unknown) block"],
        ),
        (
            "examples/hertz_split_mms.lmx",
            "commutative",
            &[
                "relations substitute an unknown on a subinterval",
                "does not hold",
            ],
        ),
    ];
    for (path, method, reasons) in cases {
        let (code, out, err) = lambdamat(&["solve", path, "--method", method]);
        assert_eq!(code, Some(2), "{path} {method}: {err}");
        assert!(out.is_empty(), "{path} {method} printed {out}");
        assert!(err.contains(&format!("--method {method}:")), "{err}");
        assert!(err.contains("use --method coupled"), "{err}");
        for r in reasons {
            assert!(err.contains(r), "{path} {method}: {err}");
        }
    }
    // The library refuses the same way.
    let text = std::fs::read_to_string("examples/hertz_frictionless.lmx").expect("file");
    let prog = parse_program(&text, "hertz_frictionless.lmx").expect("parses");
    let opts = SplitOptions {
        method: Method::Ordered,
        ..SplitOptions::default()
    };
    assert!(matches!(
        solve_split_fields(&prog, &opts).map(|s| s.report),
        Err(PlanError::Invalid(m)) if m.contains("nowhere free")
    ));
}

/// Solves `path` by `coupled` and `commutative` through the split solver:
/// the largest difference of an output or of an unknown on the grid
/// relative to the estimates, and the commuted pairs with their defects.
fn commutative_vs_coupled(path: &str) -> (f64, f64, Vec<Commuted>) {
    let c = solve(path, Method::Coupled);
    let m = solve(path, Method::Commutative);
    assert_eq!(m.report.method, "commutative");
    let mut worst_diff = 0.0f64;
    let mut worst_est = 0.0f64;
    for (a, b) in c.report.outputs.iter().zip(&m.report.outputs) {
        let diff = (a.value - b.value).abs();
        eprintln!(
            "{path} {}: |commutative - coupled| = {diff:.2e}, estimates {:.2e} + {:.2e}",
            a.name, a.error, b.error
        );
        worst_diff = worst_diff.max(diff);
        worst_est = worst_est.max(a.error + b.error);
    }
    let (fc, fm) = (
        LevelFields::new(&c).expect("fields"),
        LevelFields::new(&m).expect("fields"),
    );
    for u in 0..c.problem.sys.unknowns.len() {
        let (gc, gm) = (
            fc.on_grid(u, 101, true).expect("grid"),
            fm.on_grid(u, 101, true).expect("grid"),
        );
        assert_eq!(gc.x, gm.x);
        for i in 0..gc.x.len() {
            worst_diff = worst_diff.max((gc.values[i] - gm.values[i]).abs());
            worst_est = worst_est.max(gc.errors[i] + gm.errors[i]);
        }
    }
    let record = m.problem.method_record().expect("record");
    eprintln!("{path}: commuted {:?}", record.commuted);
    (worst_diff, worst_est, record.commuted)
}

#[test]
fn the_commutative_model_agrees_with_coupled_where_its_operators_commute() {
    // a and b = id + a commute (as operators, not as symbols): the model
    // is exact, its one commuted pair's defect at rounding level.
    let f = file(
        "operator a = int(0..1) x*t dt\n\
         operator b = id + int(0..1) x*t dt\n\
         operator k = int(0..x) t dt\n\
         unknown p, q\n\
         equation p + a q = 1\n\
         equation k p + b q = x\n\
         solve for p\n\
         output P = int(0..1) p(x) dx\n\
         output Q = int(0..1) q(x) dx\n",
    );
    let (diff, est, commuted) = commutative_vs_coupled(f.path().to_str().expect("path"));
    assert_eq!(commuted.len(), 1, "{commuted:?}");
    assert!(
        commuted[0].defect.is_some_and(|d| d < 1e-12)
            && commuted[0].on_solution.is_some_and(|d| d < 1e-12),
        "{commuted:?}"
    );
    assert!(diff <= est, "{diff:e} > {est:e}");
    // A split file with one unknown (a singular weight, a breakpoint-free
    // punch): the eliminant is the equation itself.
    let (diff, est, commuted) = commutative_vs_coupled("examples/contact/flat_punch.lmx");
    assert!(commuted.is_empty());
    assert!(diff <= est, "{diff:e} > {est:e}");
}

#[test]
fn the_commutative_model_differs_from_coupled_where_its_operators_do_not() {
    // examples/mms.lmx: k2 and k4 do not commute; the model's P is off by
    // more than the estimates, and the defect says why.
    let c = solve("examples/mms.lmx", Method::Coupled);
    let m = solve("examples/mms.lmx", Method::Commutative);
    assert_eq!(m.report.method, "commutative");
    // The model's P = π/2 ∫ x p (exact π/4) is off by more than both
    // estimates together.
    let (a, b) = (&c.report.outputs[0], &m.report.outputs[0]);
    assert_eq!(a.name, "P");
    let diff = (a.value - b.value).abs();
    eprintln!(
        "P: coupled {} ± {:.1e}, commutative {} ± {:.1e}",
        a.value, a.error, b.value, b.error
    );
    assert!(diff > a.error + b.error, "{diff:e}");
    let commuted = m.problem.method_record().expect("record").commuted;
    eprintln!("commuted {commuted:?}");
    assert!(!commuted.is_empty());
    assert!(
        commuted
            .iter()
            .all(|c| c.defect.is_some_and(|d| d > 1e-3) && c.on_solution.is_some_and(|d| d > 1e-3)),
        "{commuted:?}"
    );
}
