//! The `main` of the solvers `lambdamat codegen` writes, built without the
//! command line (the crate's `cli` feature off: no clap, miette's fancy
//! output, plotters or indicatif). It parses the flags of `lambdamat solve`
//! that need no plotting (`--method`, `--tol`, `--max-level`, `--json`,
//! `--csv FILE`, `--help`) by hand, solves, prints the report of
//! `lambdamat solve` (`crate::report`) and returns the exit code of the
//! project's contract: 0 converged, 1 usage, 2 invalid input, 3 failed
//! computation, 4 printed but not converged. A closed standard output or
//! standard error does not change the exit code ([`Stdout`], [`note`]).
//!
//! It also re-exports every name a generated solver uses, and no other: a
//! generated file names `lambdamat::standalone` only, so that it builds
//! against the crate's public surface.

use std::io::Write;
use std::path::{Path, PathBuf};

use crate::plan::Method;
use crate::report::{Report, SolveSettings};

pub use crate::numeric::{Limits, Operator, Singularity};
pub use crate::plan::PlanError;
pub use crate::plan::compiled::{
    CompiledCondition, CompiledEquation, CompiledOutput, CompiledSystem, OutputTerm, words,
};
pub use crate::plan::split_input::{
    RealFn, SplitCondition, SplitContact, SplitEnd, SplitInequality, SplitInput, SplitInterval,
    SplitKind, SplitLinTerm, SplitRelation, SplitSingular,
};
pub use crate::system::contact::{EndSite, RFunc, Scalar, real_pow};
pub use crate::system::expr::{acot, erf, gamma};

/// The highest refinement level `--max-level` accepts (levels are numbered
/// from 0): beyond it the geometric grading makes panels too small for the
/// quadrature rules.
///
/// ```
/// use lambdamat::standalone::{Flags, MAX_LEVEL};
/// assert_eq!(MAX_LEVEL, 14);
/// assert!(Flags::default().max_level <= MAX_LEVEL);
/// ```
pub const MAX_LEVEL: usize = crate::report::MAX_LEVEL;

/// The flags of a generated solver.
///
/// ```
/// let f = lambdamat::standalone::Flags::default();
/// assert_eq!((f.tol, f.max_level, f.json), (1e-10, 8, false));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Flags {
    /// `--method`: coupled (default), ordered or commutative.
    pub method: Option<String>,
    /// `--tol` (default 1e-10).
    pub tol: f64,
    /// `--max-level` (default 8).
    pub max_level: usize,
    /// `--json`.
    pub json: bool,
    /// `--csv FILE`.
    pub csv: Option<PathBuf>,
}

impl Default for Flags {
    fn default() -> Self {
        Flags {
            method: None,
            tol: 1e-10,
            max_level: 8,
            json: false,
            csv: None,
        }
    }
}

/// The text of `--help`.
///
/// ```
/// assert!(lambdamat::standalone::USAGE.contains("--tol T"));
/// ```
pub const USAGE: &str = "A solver written by `lambdamat codegen`: solves its system and prints the report of `lambdamat solve`.

Usage: SOLVER [--method coupled|ordered|commutative] [--tol T] [--max-level N] [--json] [--csv FILE]

Options:
      --method M       coupled (one collocation system, default), ordered (exact elimination) or commutative (a model)
      --tol T          refine until the error estimate is below T (finite, > 0) [default: 1e-10]
      --max-level N    highest refinement level tried, numbered from 0 (1 to 14) [default: 8]
      --json           print one JSON object instead of text
      --csv FILE       write the unknowns on the output grid as CSV
  -h, --help           print this help

Exit codes: 0 success; 1 usage error; 2 invalid input; 3 a computation failed; 4 finished but not converged (results printed and marked).";

/// What the flags ask for: a solve with these flags, or help (exit 0).
///
/// ```
/// use lambdamat::standalone::{Parsed, parse_flags};
/// assert_eq!(parse_flags(["--help".to_string()]), Ok(Parsed::Help));
/// ```
#[derive(Debug, PartialEq)]
pub enum Parsed {
    /// The flags.
    Flags(Flags),
    /// `--help` was asked for.
    Help,
}

/// Parses the flags (without the program name). Values may be negative
/// numbers in any notation (`--tol -1e-3` is a value, refused later as
/// invalid input). A usage error (exit 1) is its message.
///
/// ```
/// use lambdamat::standalone::{Parsed, parse_flags};
/// let args = ["--tol", "1e-8", "--json"].map(String::from);
/// let Ok(Parsed::Flags(f)) = parse_flags(args) else { panic!() };
/// assert_eq!((f.tol, f.json), (1e-8, true));
/// assert!(parse_flags(["--frobnicate".to_string()]).is_err());
/// ```
pub fn parse_flags(args: impl IntoIterator<Item = String>) -> Result<Parsed, String> {
    let mut f = Flags::default();
    let mut it = args.into_iter();
    while let Some(arg) = it.next() {
        let (name, inline) = match arg.split_once('=') {
            Some((n, v)) if n.starts_with("--") => (n.to_string(), Some(v.to_string())),
            _ => (arg.clone(), None),
        };
        let mut value = |what: &str| {
            inline
                .clone()
                .or_else(|| it.next())
                .ok_or_else(|| format!("{name} needs a value ({what})"))
        };
        match name.as_str() {
            "-h" | "--help" => return Ok(Parsed::Help),
            "--json" => f.json = true,
            "--method" => {
                let m = value("coupled, ordered or commutative")?;
                if !["coupled", "ordered", "commutative"].contains(&m.as_str()) {
                    return Err(format!(
                        "--method {m}: expected coupled, ordered or commutative"
                    ));
                }
                f.method = Some(m);
            }
            "--tol" => {
                let v = value("a number such as 1e-10")?;
                f.tol = v.parse().map_err(|_| format!("--tol {v}: not a number"))?;
            }
            "--max-level" => {
                let v = value("a level such as 8")?;
                f.max_level = v
                    .parse()
                    .map_err(|_| format!("--max-level {v}: not a level (0, 1, 2, …)"))?;
            }
            "--csv" => f.csv = Some(PathBuf::from(value("a file")?)),
            "--plot" => {
                return Err(
                    "--plot: a generated solver draws no plots (run `lambdamat solve FILE --plot FILE.svg`)"
                        .into(),
                );
            }
            other => return Err(format!("unexpected argument `{other}`")),
        }
    }
    Ok(Parsed::Flags(f))
}

/// A failure and its exit code.
struct Failure {
    code: i32,
    message: String,
}

impl Failure {
    fn invalid(message: String) -> Self {
        Failure { code: 2, message }
    }
    fn plan(e: PlanError) -> Self {
        Failure {
            code: if e.is_input_error() { 2 } else { 3 },
            message: e.to_string(),
        }
    }
    fn output(e: std::io::Error) -> Self {
        Failure {
            code: 3,
            message: format!("cannot write output: {e}"),
        }
    }
}

/// Whether `path` can be written, tried without truncating it or leaving a
/// file behind (an existing file is opened for appending; a new one is
/// created and removed). The reason otherwise.
///
/// ```
/// let dir = std::env::temp_dir();
/// assert_eq!(lambdamat::standalone::probe_writable(&dir).unwrap_err(), "it is a directory");
/// ```
pub fn probe_writable(path: &Path) -> Result<(), String> {
    if path.is_dir() {
        return Err("it is a directory".into());
    }
    if path.exists() {
        std::fs::OpenOptions::new()
            .append(true)
            .open(path)
            .map_err(|e| e.to_string())?;
        return Ok(());
    }
    std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(path)
        .map_err(|e| e.to_string())?;
    let _ = std::fs::remove_file(path);
    Ok(())
}

/// Prints one line on standard error; a closed or failing standard error
/// is ignored (a message must never turn an exit code into a panic).
///
/// ```
/// lambdamat::standalone::note("solving at level 3");
/// ```
pub fn note(line: &str) {
    let _ = writeln!(std::io::stderr(), "{line}");
}

/// Standard output for a report. Once the reader has gone away (a broken
/// pipe: `… | head -1`) further bytes are dropped and the program runs on,
/// so its exit code is that of its result.
pub struct Stdout {
    inner: std::io::StdoutLock<'static>,
    closed: bool,
}

impl Stdout {
    /// The locked standard output.
    pub fn new() -> Self {
        Stdout {
            inner: std::io::stdout().lock(),
            closed: false,
        }
    }

    fn guard<T>(&mut self, r: std::io::Result<T>, dropped: T) -> std::io::Result<T> {
        match r {
            Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => {
                self.closed = true;
                Ok(dropped)
            }
            other => other,
        }
    }
}

impl Default for Stdout {
    fn default() -> Self {
        Self::new()
    }
}

impl Write for Stdout {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        if self.closed {
            return Ok(buf.len());
        }
        let r = self.inner.write(buf);
        self.guard(r, buf.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        if self.closed {
            return Ok(());
        }
        let r = self.inner.flush();
        self.guard(r, ())
    }
}

/// Parses the process's flags and runs `body`; returns the exit code.
fn run_main(body: impl FnOnce(&Flags, &mut Stdout) -> Result<(), Failure>) -> i32 {
    let flags = match parse_flags(std::env::args().skip(1)) {
        Ok(Parsed::Flags(f)) => f,
        Ok(Parsed::Help) => {
            let _ = writeln!(Stdout::new(), "{USAGE}");
            return 0;
        }
        Err(e) => {
            note(&format!("error: {e}\n\n{USAGE}"));
            return 1;
        }
    };
    let mut out = Stdout::new();
    let result = body(&flags, &mut out);
    let _ = out.flush();
    match result {
        Ok(()) => 0,
        Err(f) => {
            note(&format!("error: {}", f.message));
            f.code
        }
    }
}

/// Solves with `solve` as `flags` ask and prints the [`Report`] (text or
/// JSON, and the CSV table): the body of a generated main.
fn solve_and_print(
    flags: &Flags,
    out: &mut Stdout,
    solve: impl FnOnce(&SolveSettings) -> Result<Report, PlanError>,
) -> Result<(), Failure> {
    if let Some(path) = &flags.csv {
        probe_writable(path)
            .map_err(|why| Failure::invalid(format!("cannot write {}: {why}", path.display())))?;
    }
    let method = flags
        .method
        .as_deref()
        .map(str::parse::<Method>)
        .transpose()
        .map_err(Failure::invalid)?;
    let s = SolveSettings {
        tol: flags.tol,
        max_level: flags.max_level,
        method,
        ..SolveSettings::default()
    };
    s.check().map_err(Failure::plan)?;
    let r = solve(&s).map_err(Failure::plan)?;
    if let Some(path) = &flags.csv {
        std::fs::write(path, r.csv())
            .map_err(|e| Failure::invalid(format!("cannot write {}: {e}", path.display())))?;
        note(&format!("wrote {}", path.display()));
    }
    if flags.json {
        let text =
            serde_json::to_string_pretty(&r.to_json()).map_err(|e| Failure::output(e.into()))?;
        writeln!(out, "{text}").map_err(Failure::output)?;
    } else {
        r.write_text(out).map_err(Failure::output)?;
    }
    for warning in &r.warnings {
        note(&format!("warning: {warning}"));
    }
    if r.converged {
        Ok(())
    } else {
        Err(Failure {
            code: 4,
            message: r.not_converged_message(),
        })
    }
}

/// The `main` of a solver `lambdamat codegen` wrote (for any file: one on
/// one interval is a split problem with no breakpoints and no scalars):
/// returns the exit code. A generated solver's whole `main`:
///
/// ```no_run
/// use lambdamat::standalone::{PlanError, SplitInput, split_solver_main};
/// fn input() -> Result<SplitInput, PlanError> {
///     todo!("written by `lambdamat codegen`")
/// }
/// std::process::exit(split_solver_main(input));
/// ```
pub fn split_solver_main(input: fn() -> Result<SplitInput, PlanError>) -> i32 {
    run_main(|flags, out| solve_and_print(flags, out, |s| crate::report::solve_split(input()?, s)))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(args: &[&str]) -> Result<Parsed, String> {
        parse_flags(args.iter().map(|s| s.to_string()))
    }

    #[test]
    fn flags_parse_like_lambdamat_solve() {
        let Ok(Parsed::Flags(f)) = parse(&[
            "--method",
            "coupled",
            "--tol=-2e-1",
            "--max-level",
            "5",
            "--json",
            "--csv",
            "x.csv",
        ]) else {
            panic!("parses")
        };
        assert_eq!(f.method.as_deref(), Some("coupled"));
        assert_eq!(f.tol, -0.2);
        assert_eq!(f.max_level, 5);
        assert!(f.json);
        assert_eq!(f.csv, Some(PathBuf::from("x.csv")));
        assert_eq!(
            parse(&["--tol", "-1E-3"]).map(|p| p != Parsed::Help),
            Ok(true)
        );
        assert_eq!(parse(&["--help"]), Ok(Parsed::Help));
        for bad in [
            &["--bogus"][..],
            &["--tol"],
            &["--method", "x"],
            &["--plot", "a.svg"],
        ] {
            assert!(parse(bad).is_err(), "{bad:?}");
        }
    }
}
