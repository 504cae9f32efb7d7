//! Files the commands write (CSV tables, SVG plots, generated solvers):
//! one function that refuses to overwrite an input file, writes the bytes,
//! and says `wrote FILE` on standard error. Every file a command writes goes
//! through [`write_file`], so the message, the refusal and the exit code of
//! an unwritable path (2) are the same everywhere. It knows nothing about
//! what the bytes mean. [`write_json`] is the one way `--json` documents
//! reach standard output. [`check_writable`] checks every output path
//! before any work; [`Stdout`] and [`note`] keep a closed standard output
//! or standard error from changing the exit code.

use std::path::Path;

use super::error::CliError;

/// Whether `a` and `b` name the same existing file (through any path:
/// relative, `..`, symbolic or hard links).
pub fn same_file(a: &Path, b: &Path) -> bool {
    let (Ok(ma), Ok(mb)) = (std::fs::metadata(a), std::fs::metadata(b)) else {
        return false;
    };
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        if ma.dev() == mb.dev() && ma.ino() == mb.ino() {
            return true;
        }
    }
    let _ = (ma, mb);
    match (std::fs::canonicalize(a), std::fs::canonicalize(b)) {
        (Ok(x), Ok(y)) => x == y,
        _ => false,
    }
}

/// Refuses `path` if it is one of `inputs` (the command's input files).
pub fn check_not_input(path: &Path, inputs: &[&Path]) -> Result<(), CliError> {
    if let Some(input) = inputs.iter().find(|i| same_file(path, i)) {
        return Err(CliError::Write {
            path: path.display().to_string(),
            reason: format!(
                "it is the input file {}; refusing to overwrite it",
                input.display()
            ),
        });
    }
    Ok(())
}

/// Checks, before any work, that `path` can be written: not one of
/// `inputs`, not a directory, and its directory exists and accepts the
/// file ([`crate::standalone::probe_writable`]: nothing is truncated and no
/// file is left behind).
pub fn check_writable(path: &Path, inputs: &[&Path]) -> Result<(), CliError> {
    check_not_input(path, inputs)?;
    crate::standalone::probe_writable(path).map_err(|reason| CliError::Write {
        path: path.display().to_string(),
        reason,
    })
}

pub use crate::standalone::{Stdout, note};

/// Writes `bytes` to `path` (never over one of `inputs`) and reports
/// `wrote PATH` (with `note`, if any) on standard error.
pub fn write_file(path: &Path, bytes: &[u8], inputs: &[&Path], note: &str) -> Result<(), CliError> {
    check_not_input(path, inputs)?;
    std::fs::write(path, bytes).map_err(|e| CliError::Write {
        path: path.display().to_string(),
        reason: e.to_string(),
    })?;
    if note.is_empty() {
        self::note(&format!("wrote {}", path.display()));
    } else {
        self::note(&format!("wrote {} {note}", path.display()));
    }
    Ok(())
}

/// Writes `v` as one pretty-printed JSON document and a newline: the
/// `--json` output of every command.
pub fn write_json(w: &mut dyn std::io::Write, v: &impl serde::Serialize) -> Result<(), CliError> {
    let text = serde_json::to_string_pretty(v).map_err(|e| CliError::Invalid(e.to_string()))?;
    writeln!(w, "{text}")?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_same_file_is_recognised_through_another_path() {
        let dir = tempfile::tempdir().expect("temp dir");
        let f = dir.path().join("a.lmx");
        std::fs::write(&f, "var x\n").expect("write");
        let other = dir.path().join(".").join("a.lmx");
        assert!(same_file(&f, &other));
        assert!(!same_file(&f, &dir.path().join("b.lmx")));
        let e = write_file(&other, b"x", &[&f], "").expect_err("refused");
        assert_eq!(e.exit_code(), 2);
        assert_eq!(std::fs::read_to_string(&f).expect("read"), "var x\n");
    }

    #[test]
    fn an_unwritable_path_is_invalid_input() {
        let e = write_file(Path::new("/nonexistent/dir/x.csv"), b"x", &[], "")
            .expect_err("cannot write");
        assert_eq!(e.exit_code(), 2);
        assert!(
            e.to_string()
                .starts_with("cannot write /nonexistent/dir/x.csv")
        );
    }

    #[test]
    fn writable_paths_are_checked_without_leaving_files() {
        let dir = tempfile::tempdir().expect("temp dir");
        let new = dir.path().join("new.csv");
        check_writable(&new, &[]).expect("creatable");
        assert!(!new.exists(), "the check leaves no file behind");
        std::fs::write(&new, "keep").expect("write");
        check_writable(&new, &[]).expect("writable");
        assert_eq!(std::fs::read_to_string(&new).expect("read"), "keep");
        assert_eq!(
            check_writable(&new, &[&new])
                .expect_err("input")
                .exit_code(),
            2
        );
        assert_eq!(
            check_writable(dir.path(), &[])
                .expect_err("dir")
                .exit_code(),
            2
        );
        let missing = dir.path().join("missing").join("x.csv");
        assert_eq!(
            check_writable(&missing, &[])
                .expect_err("no dir")
                .exit_code(),
            2
        );
    }
}
