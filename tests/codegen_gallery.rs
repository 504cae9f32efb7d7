//! `lambdamat codegen` for every contact gallery file (examples/contact/):
//! the generated solvers are checked in under tests/generated/ (this test
//! demands they match a fresh `codegen` exactly), compiled as modules of
//! this test (one build for all nine), and each one's solve is compared
//! with the in-process `solve` of its file at the default tolerance bit for
//! bit: every scalar, output, coefficient, estimate and diagnostic, or the
//! same refusal.

mod common;

use common::cli::lambdamat;
use lambdamat::lang::parse_program;
use lambdamat::plan::split_solve::Estimate;
use lambdamat::plan::{SplitInput, SplitOptions, SplitReport, solve_split, solve_split_input};

#[allow(dead_code)]
#[rustfmt::skip]
#[path = "generated/cattaneo_mindlin_force_solver.rs"]
mod cattaneo_mindlin_force_solver;

#[allow(dead_code)]
#[rustfmt::skip]
#[path = "generated/cattaneo_mindlin_shift_solver.rs"]
mod cattaneo_mindlin_shift_solver;

#[allow(dead_code)]
#[rustfmt::skip]
#[path = "generated/cone_solver.rs"]
mod cone_solver;

#[allow(dead_code)]
#[rustfmt::skip]
#[path = "generated/flat_punch_solver.rs"]
mod flat_punch_solver;

#[allow(dead_code)]
#[rustfmt::skip]
#[path = "generated/jkr_indentation_solver.rs"]
mod jkr_indentation_solver;

#[allow(dead_code)]
#[rustfmt::skip]
#[path = "generated/power_law_solver.rs"]
mod power_law_solver;

#[allow(dead_code)]
#[rustfmt::skip]
#[path = "generated/sphere_indentation_solver.rs"]
mod sphere_indentation_solver;

#[allow(dead_code)]
#[rustfmt::skip]
#[path = "generated/sphere_load_solver.rs"]
mod sphere_load_solver;
#[allow(dead_code)]
#[rustfmt::skip]
#[path = "generated/sphere_load_range_solver.rs"]
mod sphere_load_range_solver;
#[allow(dead_code)]
#[rustfmt::skip]
#[path = "data/codegen_log_end_solver.rs"]
mod codegen_log_end_solver;
#[allow(dead_code)]
#[rustfmt::skip]
#[path = "data/codegen_two_terms_solver.rs"]
mod codegen_two_terms_solver;

fn same_bits(what: &str, a: &[Estimate], b: &[Estimate]) {
    assert_eq!(a.len(), b.len(), "{what}");
    for (x, y) in a.iter().zip(b) {
        assert_eq!(x.name, y.name, "{what}");
        assert_eq!(
            x.value.to_bits(),
            y.value.to_bits(),
            "{what} {}: {} vs {}",
            x.name,
            x.value,
            y.value
        );
        assert_eq!(
            x.error.to_bits(),
            y.error.to_bits(),
            "{what} {} estimate: {} vs {}",
            x.name,
            x.error,
            y.error
        );
    }
}

fn assert_identical(a: &SplitReport, b: &SplitReport) {
    same_bits("scalar", &a.scalars, &b.scalars);
    same_bits("output", &a.outputs, &b.outputs);
    same_bits("coefficient", &a.coefficients, &b.coefficients);
    assert_eq!(a.error_estimate.to_bits(), b.error_estimate.to_bits());
    assert_eq!(a.converged, b.converged);
    assert_eq!((a.levels, a.dim), (b.levels, b.dim));
    assert_eq!(a.cond.to_bits(), b.cond.to_bits());
    assert_eq!(a.singular_exponents.len(), b.singular_exponents.len());
    for (x, y) in a.singular_exponents.iter().zip(&b.singular_exponents) {
        assert_eq!(x.0, y.0);
        assert_eq!(
            (x.1.to_bits(), x.2.to_bits()),
            (y.1.to_bits(), y.2.to_bits())
        );
    }
}

/// The generated solver for `name` is up to date and solves bit for bit
/// as `solve` does (or refuses with the same message).
fn check(name: &str, input: SplitInput) -> bool {
    check_file(
        &format!("examples/contact/{name}.lmx"),
        &format!("tests/generated/{name}_solver.rs"),
        input,
    )
}

/// [`check`] for the source `file` and its checked-in solver `solver`.
fn check_file(file: &str, solver: &str, input: SplitInput) -> bool {
    let name = file;
    let out = lambdamat().args(["codegen", file]).output().expect("runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let golden = std::fs::read_to_string(solver).expect("golden");
    assert_eq!(
        String::from_utf8(out.stdout).expect("utf-8"),
        golden,
        "{solver} is stale: regenerate it with `lambdamat codegen {file} -o {solver}`"
    );
    let text = std::fs::read_to_string(file).expect("source");
    let prog = parse_program(&text, file).expect("parses");
    let opts = SplitOptions::default();
    match (solve_split_input(input, &opts), solve_split(&prog, &opts)) {
        (Ok(g), Ok(h)) => {
            assert_identical(&g, &h);
            true
        }
        (Err(g), Err(h)) => {
            assert_eq!(g.to_string(), h.to_string(), "{name}");
            false
        }
        (g, h) => panic!(
            "{name}: generated {:?} vs in-process {:?}",
            g.map(|r| r.converged),
            h.map(|r| r.converged)
        ),
    }
}

#[test]
fn every_gallery_file_generates_a_solver_identical_to_solve() {
    let reports = [
        check(
            "cattaneo_mindlin_force",
            cattaneo_mindlin_force_solver::input().expect("generated input is consistent"),
        ),
        check(
            "cattaneo_mindlin_shift",
            cattaneo_mindlin_shift_solver::input().expect("generated input is consistent"),
        ),
        check(
            "cone",
            cone_solver::input().expect("generated input is consistent"),
        ),
        check(
            "flat_punch",
            flat_punch_solver::input().expect("generated input is consistent"),
        ),
        check(
            "jkr_indentation",
            jkr_indentation_solver::input().expect("generated input is consistent"),
        ),
        check(
            "power_law",
            power_law_solver::input().expect("generated input is consistent"),
        ),
        check(
            "sphere_indentation",
            sphere_indentation_solver::input().expect("generated input is consistent"),
        ),
        check(
            "sphere_load",
            sphere_load_solver::input().expect("generated input is consistent"),
        ),
        check(
            "sphere_load_range",
            sphere_load_range_solver::input().expect("generated input is consistent"),
        ),
    ];
    // Every file gives a report (converged or not), so every comparison
    // is of reports, not of refusals.
    assert_eq!(reports.iter().filter(|&&r| r).count(), 9);
}

/// A logarithmic end (`singular p at 0 ~ ln(x)`, the cone's tip) is
/// generated, compiled and solves bit for bit as `solve` does.
#[test]
fn a_logarithmic_end_generates_a_solver_identical_to_solve() {
    let input = codegen_log_end_solver::input().expect("generated input is consistent");
    assert!(
        input
            .contact
            .singulars
            .iter()
            .any(|s| matches!(s.kind, lambdamat::plan::split_input::SplitKind::Log)),
        "the generated input declares the logarithmic end"
    );
    assert!(check_file(
        "tests/data/codegen_log_end.lmx",
        "tests/data/codegen_log_end_solver.rs",
        input,
    ));
}

/// Two exact terms of one unknown at one point (`examples/two_terms.lmx`,
/// one declaration `A*g(x) + B*h(x)`) are generated as two terms, and the
/// solver compiled from them solves bit for bit as `solve` does.
#[test]
fn several_singular_terms_generate_a_solver_identical_to_solve() {
    let input = codegen_two_terms_solver::input().expect("generated input is consistent");
    let terms = input
        .contact
        .singulars
        .iter()
        .filter(|s| matches!(s.kind, lambdamat::plan::split_input::SplitKind::Term { .. }))
        .count();
    assert_eq!(terms, 2, "the generated input declares both terms");
    assert!(check_file(
        "examples/two_terms.lmx",
        "tests/data/codegen_two_terms_solver.rs",
        input,
    ));
}

/// Every checked-in generated solver names lambdamat only through
/// `lambdamat::standalone` (outside comments), the module that re-exports
/// what generated code needs: the rest of the crate is not public.
#[test]
fn generated_solvers_name_only_the_standalone_module() {
    let mut files = Vec::new();
    for dir in ["tests/generated", "tests/data", "examples"] {
        for entry in std::fs::read_dir(dir).expect("dir") {
            let path = entry.expect("entry").path();
            let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
            if name.ends_with("_solver.rs") {
                files.push(path);
            }
        }
    }
    assert!(files.len() >= 14, "{files:?}");
    let mut paths = 0;
    for path in &files {
        let text = std::fs::read_to_string(path).expect("read");
        for (i, line) in text.lines().enumerate() {
            if line.trim_start().starts_with("//") {
                continue;
            }
            for (at, _) in line.match_indices("lambdamat::") {
                paths += 1;
                assert!(
                    line[at..].starts_with("lambdamat::standalone"),
                    "{}:{}: {line}",
                    path.display(),
                    i + 1
                );
            }
        }
    }
    assert!(paths >= 3 * files.len(), "{paths} paths");
}
