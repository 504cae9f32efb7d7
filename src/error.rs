//! The library's and the command line's one error: it wraps each layer's error enum and
//! decides the exit code and how the error is shown (miette for source
//! errors, one plain line otherwise). Nothing else in the CLI prints errors.
//!
//! The exit-code contract (documented in `--help` and README.md):
//!
//! | code | meaning |
//! |---|---|
//! | 0 | success: every result printed reached its tolerance |
//! | 1 | usage: the command line cannot be parsed or is contradictory |
//! | 2 | invalid input: the file, a parameter or a path given (nothing computed) |
//! | 3 | a computation failed (for tables and sweeps: at least one row failed) |
//! | 4 | finished but not converged: results printed and marked, tolerance not reached |
//!
//! A closed standard output (`lambdamat … | head`) or standard error does
//! not change the exit code (see the CLI's `output::Stdout`); messages to a
//! closed standard error are dropped.

use crate::algebra::smith::modes::SmithError;
use crate::lang::LangErrors;
use crate::lang::diagnostics::elide_long_numbers;
use crate::plan::PlanError;
use crate::reduce::ReduceError;

/// Everything that can stop a command.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    /// The file could not be read.
    #[error("cannot read {path}: {source}")]
    Io {
        /// The path as given.
        path: String,
        /// The I/O error.
        source: std::io::Error,
    },
    /// The source text is invalid (syntax or meaning), with positions.
    #[error(transparent)]
    Lang(#[from] Box<LangErrors>),
    /// A command-line value does not fit the file (e.g. an unknown symbol)
    /// or a parameter is outside its range.
    #[error("{0}")]
    Invalid(String),
    /// The command line is incomplete or contradictory.
    #[error("{0}")]
    Usage(String),
    /// A numerical computation refused or failed (singular, no convergence).
    #[error("numerical failure: {0}")]
    Numeric(String),
    /// The Smith computation refused or failed.
    #[error(transparent)]
    Smith(#[from] SmithError),
    /// Solving a system: unsupported input (exit 2) or failed numerics
    /// (singular, ill-conditioned: exit 3).
    #[error(transparent)]
    Plan(#[from] PlanError),
    /// No reduction exists (no system, no such unknown, singular λ-matrix).
    #[error(transparent)]
    Reduce(#[from] ReduceError),
    /// Writing to standard output failed (a closed pipe is not an error:
    /// [`super::output::Stdout`] drops the bytes).
    #[error("cannot write output: {0}")]
    Output(#[from] std::io::Error),
    /// A file named on the command line cannot be written (or would
    /// overwrite the input).
    #[error("cannot write {path}: {reason}")]
    Write {
        /// The path as given.
        path: String,
        /// Why.
        reason: String,
    },
    /// Every result was printed, but at least one did not reach its
    /// tolerance (exit 4).
    #[error("not converged: {0}")]
    NotConverged(String),
    /// Some rows of a table or sweep failed; the others were printed (exit 3).
    #[error("{failed} of {total} {what} failed")]
    RowsFailed {
        /// How many rows failed.
        failed: usize,
        /// How many rows there were.
        total: usize,
        /// What a row is ("rows", "solves").
        what: &'static str,
    },
}

/// Exit code: the command line cannot be parsed or is contradictory.
pub const EXIT_USAGE: i32 = 1;
/// Exit code: invalid input (file, parameter, path); nothing computed.
pub const EXIT_INVALID: i32 = 2;
/// Exit code: a computation failed (or some rows of a table or sweep).
pub const EXIT_FAILED: i32 = 3;
/// Exit code: finished, results printed and marked, tolerance not reached.
pub const EXIT_NOT_CONVERGED: i32 = 4;

impl CliError {
    /// The process exit code: 2 invalid input, 3 failed computation. A
    /// singular λ-matrix is invalid input (2): the system as written does
    /// not determine the unknown, and no computation failed.
    pub fn exit_code(&self) -> i32 {
        match self {
            CliError::Io { .. }
            | CliError::Lang(_)
            | CliError::Invalid(_)
            | CliError::Write { .. } => EXIT_INVALID,
            CliError::Smith(SmithError::TooManyMinors(_) | SmithError::TooLarge(_)) => EXIT_INVALID,
            CliError::Reduce(_) => EXIT_INVALID,
            CliError::Usage(_) => EXIT_USAGE,
            CliError::Plan(e) if e.is_input_error() => EXIT_INVALID,
            CliError::NotConverged(_) => EXIT_NOT_CONVERGED,
            CliError::Smith(_)
            | CliError::Plan(_)
            | CliError::Numeric(_)
            | CliError::Output(_)
            | CliError::RowsFailed { .. } => EXIT_FAILED,
        }
    }

    /// What [`CliError::report`] prints when standard error is not a
    /// terminal (no colours), as one string. The library's [`crate::api::Error`] displays this.
    pub fn plain_message(&self) -> String {
        self.message(false)
    }

    /// The message, with colours for a terminal or without.
    fn message(&self, colours: bool) -> String {
        match self {
            CliError::Lang(errs) => {
                let handler = if colours {
                    miette::GraphicalReportHandler::new()
                } else {
                    miette::GraphicalReportHandler::new_themed(
                        miette::GraphicalTheme::unicode_nocolor(),
                    )
                };
                let mut text = String::new();
                for (i, one) in errs.split().iter().enumerate() {
                    if i > 0 {
                        text.push('\n');
                    }
                    let mut out = String::new();
                    if !one.has_long_lines() && handler.render_report(&mut out, one).is_ok() {
                        text.push_str(&elide_long_numbers(&out));
                    } else {
                        text.push_str(&one.render());
                    }
                }
                text.push_str(&summary(errs.len()));
                text.push('\n');
                text
            }
            other => format!("error: {}\n", elide_long_numbers(&other.to_string())),
        }
    }

    /// Prints the error to standard error.
    pub fn report(&self) {
        use std::io::Write as _;
        let text = self.message(std::io::IsTerminal::is_terminal(&std::io::stderr()));
        // A closed standard error must not turn the exit code into a panic.
        let _ = std::io::stderr().lock().write_all(text.as_bytes());
    }
}

fn summary(n: usize) -> String {
    if n == 1 {
        "1 error: nothing was computed".to_string()
    } else {
        format!("{n} errors: nothing was computed")
    }
}

impl From<crate::api::Error> for CliError {
    fn from(e: crate::api::Error) -> CliError {
        e.into_cli()
    }
}
