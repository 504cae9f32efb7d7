//! The command line's flags, end to end: `--set` is honoured or refused on
//! every command, the exit code survives a closed standard output or
//! standard error, negative numbers in any notation are option values,
//! output paths are checked before any work, refinement levels are counted
//! one way (the number of levels solved, `levels: N`), and
//! every subcommand's `--help` ends with examples.

mod common;

use common::cli::lambdamat;
use predicates::prelude::*;
use std::os::fd::{FromRawFd, OwnedFd};
use std::process::{Command, Stdio};

fn code(args: &[&str]) -> i32 {
    lambdamat()
        .args(args)
        .output()
        .expect("runs")
        .status
        .code()
        .expect("exit code")
}

/// The write end of a pipe whose read end is already closed: every write
/// to it fails with a broken pipe.
fn closed_pipe() -> Stdio {
    let mut fds = [0; 2];
    // SAFETY: `pipe` fills two new descriptors, which we own from here on.
    assert_eq!(unsafe { libc::pipe(fds.as_mut_ptr()) }, 0, "pipe");
    // SAFETY: both descriptors were just created and are owned by nobody else.
    let (read, write) = unsafe { (OwnedFd::from_raw_fd(fds[0]), OwnedFd::from_raw_fd(fds[1])) };
    drop(read);
    Stdio::from(write)
}

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_lambdamat"))
}

#[test]
fn set_is_refused_by_hertz_and_its_subcommands_naming_the_parameter() {
    for args in [
        &[
            "hertz", "--set", "bogus=1", "--nu", "0.25", "--mu", "0.1801",
        ][..],
        &["hertz", "--set", "mu=0.5", "--nu", "0.25", "--mu", "0.1801"],
        &["hertz", "table", "--set", "nu=0"],
        &[
            "hertz", "sweep", "--nu", "0:0.5:2", "--mu", "0.1:1:2", "--set", "bogus=2",
        ],
    ] {
        let name = args
            .iter()
            .skip_while(|a| **a != "--set")
            .nth(1)
            .and_then(|s| s.split('=').next())
            .expect("a --set");
        lambdamat()
            .args(args)
            .assert()
            .code(2)
            .stdout("")
            .stderr(predicate::str::contains(format!("--set {name}:")));
    }
    // The commands that read a file honour a parameter it defines and
    // refuse one it does not.
    for cmd in ["solve", "codegen", "reduce", "run"] {
        lambdamat()
            .args([cmd, "examples/mms.lmx", "--set", "bogus=1"])
            .assert()
            .code(2)
            .stderr(predicate::str::contains("--set bogus"));
    }
    assert_eq!(
        code(&["solve", "examples/mms.lmx", "--set", "gamma=1/2"]),
        0
    );
}

#[test]
fn a_closed_standard_output_keeps_the_exit_code_of_the_result() {
    // Not converged (4): the report is lost, the status and message are not.
    let out = bin()
        .args(["solve", "examples/mms.lmx", "--max-level", "1"])
        .stdout(closed_pipe())
        .stderr(Stdio::piped())
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(4));
    assert!(String::from_utf8_lossy(&out.stderr).contains("not converged"));
    // Converged (0).
    let out = bin()
        .args(["solve", "examples/mms.lmx"])
        .stdout(closed_pipe())
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(0));
    // Invalid input (2).
    let out = bin()
        .args(["hertz", "--nu", "0.7", "--mu", "0.1"])
        .stdout(closed_pipe())
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn a_closed_standard_error_never_turns_an_exit_code_into_a_panic() {
    for (args, want) in [
        (&["solve", "no/such/file.lmx"][..], 2),
        (&["solve", "examples/mms.lmx", "--max-level", "1"], 4),
        (
            &[
                "hertz",
                "--nu",
                "0.25",
                "--mu",
                "0.1801",
                "--csv",
                "/nonexistent/x.csv",
            ],
            2,
        ),
        (&["smith", "--bogus"], 1),
    ] {
        let out = bin()
            .args(args)
            .stdout(Stdio::null())
            .stderr(closed_pipe())
            .output()
            .expect("runs");
        assert_eq!(out.status.code(), Some(want), "{args:?}");
    }
}

#[test]
fn negative_numbers_in_any_notation_are_option_values() {
    for nu in ["-0.2", "-2e-1", "-2E-1", "-.2e0", "-20e-2"] {
        lambdamat()
            .args(["hertz", "--nu", nu, "--mu", "0.1"])
            .assert()
            .code(0)
            .stdout(predicate::str::contains("ν = -0.2,"));
    }
    // A negative tolerance is a value, refused as invalid input (2), not a
    // usage error (1).
    for tol in ["-1e-3", "-1E-3", "-0.001"] {
        assert_eq!(
            code(&["solve", "examples/mms.lmx", "--tol", tol]),
            2,
            "{tol}"
        );
        assert_eq!(code(&["hertz", "table", "--tol", tol]), 2, "{tol}");
    }
}

#[test]
fn output_paths_are_checked_before_any_work() {
    let dir = tempfile::tempdir().expect("temp dir");
    let missing = dir.path().join("missing-dir").join("x.csv");
    let missing = missing.to_str().expect("utf-8");
    let cases: Vec<Vec<&str>> = vec![
        // A 50-point sweep takes seconds; refused at once, nothing printed.
        vec![
            "hertz", "sweep", "--nu", "0:0.5:5", "--mu", "0.1:1:10", "-o", missing,
        ],
        vec!["hertz", "--nu", "0.25", "--mu", "0.1801", "--csv", missing],
        vec!["hertz", "--nu", "0.25", "--mu", "0.1801", "--plot", missing],
        vec!["solve", "examples/mms.lmx", "--csv", missing],
        vec!["solve", "examples/mms.lmx", "--plot", missing],
        vec!["codegen", "examples/mms.lmx", "-o", missing],
        vec!["solve", "examples/mms.lmx", "--csv", "examples/mms.lmx"],
        vec!["codegen", "examples/mms.lmx", "-o", "examples/mms.lmx"],
    ];
    for args in &cases {
        lambdamat()
            .args(args)
            .assert()
            .code(2)
            .stdout("")
            .stderr(predicate::str::starts_with("error: cannot write"));
    }
    assert!(!dir.path().join("missing-dir").exists());
    // A split-domain file's unknowns are tabulated like any other file's.
    let csv = dir.path().join("hertz.csv");
    lambdamat()
        .args(["solve", "examples/hertz.lmx", "--csv"])
        .arg(&csv)
        .assert()
        .code(0);
    let table = std::fs::read_to_string(&csv).expect("the CSV was written");
    assert!(table.lines().count() > 100, "{table}");
}

/// The number of levels solved, after `prefix`, in `text`.
fn level_after(text: &str, prefix: &str) -> usize {
    let at = text
        .find(prefix)
        .unwrap_or_else(|| panic!("{prefix:?} in {text}"));
    text[at + prefix.len()..]
        .chars()
        .take_while(char::is_ascii_digit)
        .collect::<String>()
        .parse()
        .expect("a level")
}

#[test]
fn hertz_and_solve_count_levels_the_same_way() {
    let hertz = common::cli::stdout(&["hertz", "--nu", "0.25", "--mu", "0.1801"]);
    let solve = common::cli::stdout(&[
        "solve",
        "examples/hertz.lmx",
        "--set",
        "nu=0.25",
        "--set",
        "mu=0.1801",
    ]);
    let h = level_after(&hertz, "refinement levels: ");
    let s = level_after(&solve, "levels: ");
    assert_eq!(h, s, "{hertz}\n{solve}");
    let json = common::cli::stdout(&["hertz", "--nu", "0.25", "--mu", "0.1801", "--json"]);
    assert!(json.contains(&format!("\"levels\": {h}")), "{json}");
}

#[test]
fn every_help_ends_with_examples() {
    let commands: [&[&str]; 9] = [
        &[],
        &["run"],
        &["smith"],
        &["reduce"],
        &["solve"],
        &["codegen"],
        &["hertz"],
        &["hertz", "table"],
        &["hertz", "sweep"],
    ];
    for cmd in commands {
        let out = lambdamat().args(cmd).arg("--help").output().expect("runs");
        assert_eq!(out.status.code(), Some(0), "{cmd:?}");
        let text = String::from_utf8(out.stdout).expect("utf-8");
        let (_, examples) = text
            .rsplit_once("Examples:\n")
            .unwrap_or_else(|| panic!("{cmd:?} --help has no examples:\n{text}"));
        let lines: Vec<&str> = examples.lines().collect();
        assert!((1..=2).contains(&lines.len()), "{cmd:?}: {lines:?}");
        for line in lines {
            let want = format!("  lambdamat {}", cmd.join(" "));
            assert!(line.starts_with(want.trim_end()), "{cmd:?}: {line}");
        }
    }
}

#[test]
fn help_examples_run() {
    // Each example shown by a --help that writes no file runs with exit 0
    // (examples that write under /tmp and the slow tables are skipped).
    let mut ran = 0;
    for cmd in [
        &["run"][..],
        &["smith"],
        &["reduce"],
        &["solve"],
        &["hertz"],
        &["hertz", "table"],
    ] {
        let out = lambdamat().args(cmd).arg("--help").output().expect("runs");
        let text = String::from_utf8(out.stdout).expect("utf-8");
        let (_, examples) = text.rsplit_once("Examples:\n").expect("examples");
        for line in examples.lines() {
            let args: Vec<&str> = line.split_whitespace().skip(1).collect();
            if args.iter().any(|a| a.starts_with("/tmp/") || *a == "table") {
                continue;
            }
            assert_eq!(code(&args), 0, "{line}");
            ran += 1;
        }
    }
    assert!(ran >= 7, "only {ran} examples ran");
}
