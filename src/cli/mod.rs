//! The `lambdamat` command line (clap) and report formatting (text, LaTeX,
//! JSON). It owns exit codes (0 ok, 1 usage, 2 invalid input, 3 failed
//! computation) and never does algebra or parsing itself: it calls
//! [`crate::lang`] and [`crate::algebra`] and prints what they return.
//!
//! * [`error`]: the top-level error and its exit codes;
//! * [`render`]: matrices, certificates and reports as text and LaTeX;
//! * [`smith`]: the `smith` command and the Smith part of `run`;
//! * [`reduce`]: the `reduce` command and the `solve for` part of `run`;
//! * [`run`]: the `run` command (everything a file asks for).

pub mod error;
pub mod reduce;
pub mod render;
pub mod run;
pub mod smith;

use clap::{Args, Parser, Subcommand};
use error::CliError;
use std::io::Write;
use std::path::PathBuf;

/// lambdamat: systems of linear operator equations → exact λ-matrix algebra
/// (certified Smith forms) → numerical solvers.
#[derive(Parser, Debug)]
#[command(name = "lambdamat", version, about, long_about = None)]
#[command(
    after_help = "Exit codes: 0 ok, 1 usage error, 2 invalid input (with line:column), 3 a computation failed.\nThe language is documented in README.md; grammar/lambdamat.pest is its reference."
)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Do everything the file asks for (its `smith`, `check smith` and `solve for` directives, in order).
    Run(RunArgs),
    /// Certified Smith normal form (U, D, V) of the file's matrices.
    ///
    /// One symbol: over Q[x] with unimodular U, V and monic D. Several
    /// symbols with a principal one (`principal s` in the file or
    /// --principal s): over Q(others)[s], plus a denominator-free form.
    /// Several symbols and no principal one: invariant factors over Q[all]
    /// from determinantal divisors (no U, V claimed: Q[all] is not a PID).
    Smith(SmithArgs),
    /// One equation for one unknown of the file's operator system.
    ///
    /// Shows the λ-matrix and its invariant factors, the commutative
    /// eliminant det(A)·x = Σ adj(A)·g (common factor removed) in operator
    /// form and expanded into iterated integrals, the ordered
    /// (non-commutative) elimination with explicit inverses, and the symbol
    /// pairs the eliminant had to commute. A singular λ-matrix is an error
    /// (exit code 2).
    Reduce(ReduceArgs),
}

/// Output options shared by the commands.
#[derive(Args, Debug, Clone, Default)]
pub struct OutputArgs {
    /// Print one JSON object (an array if several matrices are shown) instead of text.
    #[arg(long)]
    pub json: bool,
    /// Print formulas as LaTeX.
    #[arg(long, conflicts_with = "json")]
    pub latex: bool,
}

#[derive(Args, Debug)]
struct RunArgs {
    /// A lambdamat source file (.lmx).
    file: PathBuf,
    #[command(flatten)]
    out: OutputArgs,
}

/// Arguments of `lambdamat smith`.
#[derive(Args, Debug)]
pub struct SmithArgs {
    /// A lambdamat source file (.lmx).
    pub file: PathBuf,
    /// The principal symbol λ (overrides a `principal` line in the file).
    #[arg(long, value_name = "SYM")]
    pub principal: Option<String>,
    /// Only this matrix (default: the file's `smith` directives, or every matrix if there are none).
    #[arg(long, value_name = "NAME")]
    pub matrix: Option<String>,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// Arguments of `lambdamat reduce`.
#[derive(Args, Debug)]
pub struct ReduceArgs {
    /// A lambdamat source file (.lmx) with an operator system.
    pub file: PathBuf,
    /// The unknown to solve for (default: the file's `solve for`, else the first unknown).
    #[arg(long = "for", value_name = "UNKNOWN")]
    pub unknown: Option<String>,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// Reads a source file, mapping I/O errors to invalid input.
pub fn read_source(path: &PathBuf) -> Result<(String, String), CliError> {
    let name = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| CliError::Io {
        path: name.clone(),
        source: e,
    })?;
    Ok((text, name))
}

/// Entry point used by the binary; returns the process exit code.
pub fn main() -> i32 {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            let code = if e.use_stderr() { 1 } else { 0 };
            let _ = e.print();
            return code;
        }
    };
    let mut stdout = std::io::stdout().lock();
    let result = match cli.command {
        Command::Run(a) => run::run(&a.file, &a.out, &mut stdout),
        Command::Smith(a) => smith::smith_command(&a, &mut stdout),
        Command::Reduce(a) => reduce::reduce_command(&a, &mut stdout),
    };
    let _ = stdout.flush();
    match result {
        Ok(()) => 0,
        Err(e) => {
            e.report();
            e.exit_code()
        }
    }
}
