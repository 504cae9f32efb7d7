//! The error catalogue: one input per kind of error (and per exit code),
//! each with its whole standard error and exit code pinned in
//! `tests/data/errors/NAME.expected` (first line `exit N`, then stderr).
//! A change of wording shows up here as a diff to review; regenerate with
//! `LAMBDAMAT_BLESS=1 cargo test --release --test error_catalogue` and read
//! the diff before committing it.

mod common;

use common::cli::lambdamat;
use std::path::Path;

/// (name of the expected file, input in tests/data/errors, command line;
/// `{}` stands for the input file).
const CASES: &[(&str, &str, &[&str])] = &[
    ("first_token", "first_token", &["run", "{}"]),
    ("bom_accepted", "bom_accepted", &["run", "{}"]),
    ("not_utf8", "not_utf8", &["run", "{}"]),
    ("syntax", "syntax", &["run", "{}"]),
    ("keyword_as_name", "keyword_as_name", &["run", "{}"]),
    ("undeclared", "undeclared", &["run", "{}"]),
    ("duplicate", "duplicate", &["run", "{}"]),
    ("division_by_zero", "division_by_zero", &["run", "{}"]),
    ("non_polynomial", "non_polynomial", &["run", "{}"]),
    ("bad_exponent", "bad_exponent", &["run", "{}"]),
    ("ragged_rows", "ragged_rows", &["run", "{}"]),
    ("unknown_matrix", "unknown_matrix", &["run", "{}"]),
    ("shape", "shape", &["run", "{}"]),
    ("bad_principal", "bad_principal", &["run", "{}"]),
    ("wrong_sort", "wrong_sort", &["run", "{}"]),
    ("too_deep", "too_deep", &["run", "{}"]),
    ("long_literal", "long_literal", &["run", "{}"]),
    ("bad_variable", "bad_variable", &["solve", "{}"]),
    ("non_linear", "non_linear", &["solve", "{}"]),
    ("not_square", "not_square", &["solve", "{}"]),
    ("unsupported_kernel", "unsupported_kernel", &["solve", "{}"]),
    ("missing_pv", "missing_pv", &["solve", "{}"]),
    (
        "point_value_not_constant",
        "point_value_not_constant",
        &["solve", "{}"],
    ),
    (
        "side_condition_value",
        "side_condition_value",
        &["solve", "{}"],
    ),
    (
        "side_condition_split",
        "side_condition_split",
        &["solve", "{}"],
    ),
    ("singular_twice", "singular_twice", &["solve", "{}"]),
    (
        "condition_not_a_functional",
        "condition_not_a_functional",
        &["solve", "{}"],
    ),
    (
        "right_side_not_finite",
        "right_side_not_finite",
        &["solve", "{}"],
    ),
    (
        "right_side_not_finite_codegen",
        "right_side_not_finite",
        &["codegen", "{}"],
    ),
    ("no_system", "no_system", &["solve", "{}"]),
    (
        "singular_lambda_matrix",
        "singular_lambda_matrix",
        &["reduce", "{}"],
    ),
    (
        "not_converged",
        "not_converged",
        &["solve", "{}", "--max-level", "3"],
    ),
    ("codegen_over_input", "good", &["codegen", "{}", "-o", "{}"]),
    (
        "codegen_over_input_other_path",
        "good",
        &["codegen", "{}", "-o", "./../errors/good.lmx"],
    ),
    ("tol_negative", "good", &["solve", "{}", "--tol", "-1"]),
    ("tol_nan", "good", &["solve", "{}", "--tol", "nan"]),
    (
        "max_level_too_high",
        "good",
        &["solve", "{}", "--max-level", "99"],
    ),
    ("missing_file", "good", &["solve", "missing.lmx"]),
    (
        "plot_unwritable",
        "good",
        &["solve", "{}", "--plot", "no/such/dir/p.svg"],
    ),
    (
        "usage_bad_method",
        "good",
        &["solve", "{}", "--method", "nope"],
    ),
    (
        "hertz_nu_out_of_range",
        "good",
        &["hertz", "--nu", "0.7", "--mu", "0.2"],
    ),
    (
        "hertz_table_tol_zero",
        "good",
        &["hertz", "table", "--tol", "0"],
    ),
    (
        "hertz_sweep_too_many_points",
        "good",
        &["hertz", "sweep", "--nu=0:0.45:100000000000", "--mu=0.1:1:3"],
    ),
    (
        "hertz_sweep_out_of_domain",
        "good",
        &["hertz", "sweep", "--nu=-1:0.45:3", "--mu=0.1:1:3"],
    ),
];

#[test]
fn every_error_kind_has_its_message_and_exit_code_pinned() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/errors");
    let bless = std::env::var_os("LAMBDAMAT_BLESS").is_some();
    let mut failures = Vec::new();
    for (expected, name, args) in CASES {
        let file = format!("{name}.lmx");
        let argv: Vec<&str> = args
            .iter()
            .map(|a| if *a == "{}" { file.as_str() } else { a })
            .collect();
        let before = std::fs::read(dir.join(&file)).expect("input exists");
        let out = lambdamat()
            .current_dir(&dir)
            .args(&argv)
            .output()
            .expect("runs");
        // No command may change its input.
        assert_eq!(
            std::fs::read(dir.join(&file)).expect("input still there"),
            before,
            "{argv:?} changed its input"
        );
        let code = out.status.code().expect("exited (no signal)");
        let got = format!("exit {code}\n{}", String::from_utf8_lossy(&out.stderr));
        let path = dir.join(format!("{expected}.expected"));
        if bless {
            std::fs::write(&path, &got).expect("write expected");
            continue;
        }
        let want = std::fs::read_to_string(&path).unwrap_or_default();
        if got != want {
            failures.push(format!(
                "lambdamat {}\n--- expected ({})\n{want}\n--- got\n{got}",
                argv.join(" "),
                path.display()
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

#[test]
fn every_catalogue_input_is_used() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/errors");
    for entry in std::fs::read_dir(&dir).expect("dir") {
        let p = entry.expect("entry").path();
        if p.extension().is_some_and(|e| e == "lmx") {
            let stem = p.file_stem().and_then(|s| s.to_str()).unwrap_or("");
            assert!(
                CASES.iter().any(|(_, n, _)| *n == stem),
                "{} is not in CASES",
                p.display()
            );
        }
    }
}
