//! Helpers shared by the end-to-end CLI test files.

use assert_cmd::Command;
use serde_json::Value;
use std::io::Write;

/// The `lambdamat` binary under test.
pub fn lambdamat() -> Command {
    Command::cargo_bin("lambdamat").expect("binary builds")
}

/// Standard output of a successful run (panics with stderr otherwise).
pub fn stdout(args: &[&str]) -> String {
    let out = lambdamat().args(args).output().expect("runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("utf-8")
}

/// Standard output of a run that must end with exit code `code` (e.g. 4:
/// finished, printed, not converged).
pub fn stdout_with_code(args: &[&str], code: i32) -> String {
    let out = lambdamat().args(args).output().expect("runs");
    assert_eq!(
        out.status.code(),
        Some(code),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("utf-8")
}

/// The JSON printed by a successful run of `args` plus `--json`.
pub fn json(args: &[&str]) -> Value {
    serde_json::from_str(&stdout(&[args, &["--json"]].concat())).expect("valid JSON")
}

/// A temporary `.lmx` file holding `text`.
pub fn lmx_file(text: &str) -> tempfile::NamedTempFile {
    let mut f = tempfile::Builder::new()
        .suffix(".lmx")
        .tempfile()
        .expect("temp file");
    f.write_all(text.as_bytes()).expect("write");
    f
}
