//! The command line's top-level error: it wraps each layer's error enum and
//! decides the exit code and how the error is shown (miette for source
//! errors, one plain line otherwise). Nothing else in the CLI prints errors.

use crate::algebra::smith::modes::SmithError;
use crate::lang::LangErrors;
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
    /// Writing the output failed.
    #[error("cannot write output: {0}")]
    Output(#[from] std::io::Error),
}

impl CliError {
    /// The process exit code: 2 invalid input, 3 failed computation. A
    /// singular λ-matrix is invalid input (2): the system as written does
    /// not determine the unknown, and no computation failed.
    pub fn exit_code(&self) -> i32 {
        match self {
            CliError::Io { .. } | CliError::Lang(_) | CliError::Invalid(_) => 2,
            CliError::Smith(SmithError::TooManyMinors(_)) => 2,
            CliError::Reduce(_) => 2,
            CliError::Usage(_) => 1,
            CliError::Plan(e) if e.is_input_error() => 2,
            CliError::Smith(_) | CliError::Plan(_) | CliError::Numeric(_) | CliError::Output(_) => {
                3
            }
        }
    }

    /// Prints the error to standard error.
    pub fn report(&self) {
        match self {
            CliError::Lang(errs) => {
                let handler = if std::io::IsTerminal::is_terminal(&std::io::stderr()) {
                    miette::GraphicalReportHandler::new()
                } else {
                    miette::GraphicalReportHandler::new_themed(
                        miette::GraphicalTheme::unicode_nocolor(),
                    )
                };
                let mut out = String::new();
                if handler.render_report(&mut out, errs.as_ref()).is_ok() {
                    eprint!("{out}");
                } else {
                    eprint!("{}", errs.render());
                }
                eprintln!("{}", summary(errs.len()));
            }
            other => eprintln!("error: {other}"),
        }
    }
}

fn summary(n: usize) -> String {
    if n == 1 {
        "1 error: nothing was computed".to_string()
    } else {
        format!("{n} errors: nothing was computed")
    }
}
