//! The `lambdamat` command line (clap) and report formatting (text, LaTeX,
//! JSON). It owns exit codes (0 ok, 1 usage, 2 invalid input, 3 failed
//! computation, 4 not converged: see [`error`]) and never does algebra or
//! parsing itself: it calls [`crate::lang`] and [`crate::algebra`] and
//! prints what they return.
//!
//! * [`error`]: the top-level error and its exit codes;
//! * [`output`]: the files commands write (`wrote FILE`, never over an input);
//! * [`hertz`]: the flagship Hertz problem (solve, table, sweep);
//! * [`plot`]: SVG plots;
//! * [`smith`]: the `smith` command and the Smith part of `run`;
//! * [`reduce`]: the `reduce` command and the `solve for` part of `run` (the
//!   printers are `report::reduction`'s);
//! * [`run`]: the `run` command (everything a file asks for);
//! * [`solve`]: the `solve` command (numerical solution of the file's system);
//! * [`codegen`]: the `codegen` command (a Rust solver for the file's system).

pub mod codegen;
pub(crate) use crate::error;
pub mod hertz;
pub mod output;
pub mod plot;
pub mod reduce;
pub mod run;
pub mod smith;
pub mod solve;

use clap::{Args, Parser, Subcommand};
use error::CliError;
use std::io::Write;
use std::path::PathBuf;

/// lambdamat: systems of linear operator equations → exact λ-matrix algebra
/// (certified Smith forms) → numerical solvers.
#[derive(Parser, Debug)]
#[command(name = "lambdamat", version, about, long_about = None)]
#[command(after_help = AFTER_HELP)]
pub struct Cli {
    /// Override a parameter of the file for this command: `--set nu=0.25`
    /// (integers, exact decimals and fractions `a/b`; repeatable).
    #[arg(long = "set", global = true, value_name = "NAME=VALUE")]
    set: Vec<String>,
    #[command(subcommand)]
    command: Command,
}

/// The `--set` overrides of this process, fixed once by [`main`] before any
/// command runs (every command loads its file through `smith::load`).
static OVERRIDES: std::sync::OnceLock<Vec<(String, num_rational::BigRational)>> =
    std::sync::OnceLock::new();

/// The `--set` overrides (empty when none were given or outside [`main`]).
pub fn overrides() -> &'static [(String, num_rational::BigRational)] {
    OVERRIDES.get().map_or(&[], Vec::as_slice)
}

/// Parses `NAME=VALUE` pairs.
fn parse_sets(sets: &[String]) -> Result<Vec<(String, num_rational::BigRational)>, CliError> {
    sets.iter()
        .map(|s| {
            let (n, v) = s.split_once('=').ok_or_else(|| {
                CliError::Invalid(format!("--set {s}: expected NAME=VALUE, e.g. --set nu=0.25"))
            })?;
            let value = crate::lang::parser::parse_exact(v).ok_or_else(|| {
                CliError::Invalid(format!(
                    "--set {s}: `{v}` is not an exact number (write an integer, a decimal such as 0.1801, or a fraction such as 1/4)"
                ))
            })?;
            Ok((n.trim().to_string(), value))
        })
        .collect()
}

/// The text after every `--help` (the exit codes and where the documents
/// are), followed by the command's examples: `help_with_examples!("…")`.
macro_rules! help_with_examples {
    ($examples:literal) => {
        concat!(
            "Exit codes: 0 success (every result reached its tolerance); 1 usage error; ",
            "2 invalid input (file, parameter or path; with line:column where there is one; nothing computed); ",
            "3 a computation failed (tables and sweeps: at least one row failed, the count is on stderr); ",
            "4 finished but not converged (results printed and marked). ",
            "A closed standard output or standard error does not change the exit code.\n",
            "The language: docs/language.md (grammar/lambdamat.pest is its reference); ",
            "the Hertz problem: docs/hertz.md.\n\n",
            "Examples:\n",
            $examples
        )
    };
}
pub(crate) use help_with_examples;

/// The text after the top-level `--help`.
pub const AFTER_HELP: &str = help_with_examples!(
    "  lambdamat solve examples/mms.lmx\n  lambdamat hertz --nu 0.25 --mu 0.1801"
);

#[derive(Subcommand, Debug)]
enum Command {
    /// Do everything the file asks for (its directives, in order).
    #[command(after_help = help_with_examples!("  lambdamat run examples/seed_lambda.lmx\n  lambdamat run examples/written_order.lmx --json"))]
    Run(RunArgs),
    /// Certified Smith normal form (U, D, V) of the file's matrices.
    ///
    /// One symbol: over Q[x] with unimodular U, V and monic D. Several
    /// symbols with a principal one (`principal s` in the file or
    /// --principal s): over Q(others)[s], plus a denominator-free form.
    /// Several symbols and no principal one: invariant factors over Q[all]
    /// from determinantal divisors (no U, V claimed: Q[all] is not a PID).
    #[command(after_help = help_with_examples!("  lambdamat smith examples/matrix_qx.lmx\n  lambdamat smith examples/seed_lambda.lmx --principal k1 --latex"))]
    Smith(SmithArgs),
    /// One equation for one unknown of the file's operator system.
    ///
    /// Shows the λ-matrix and its invariant factors, the commutative
    /// eliminant det(A)·x = Σ adj(A)·g (common factor removed) in operator
    /// form and expanded into iterated integrals, the ordered
    /// (non-commutative) elimination with explicit inverses, and the symbol
    /// pairs the eliminant had to commute. A singular λ-matrix is an error
    /// (exit code 2).
    #[command(after_help = help_with_examples!("  lambdamat reduce examples/hertz.lmx\n  lambdamat reduce examples/hertz_stick.lmx --for q"))]
    Reduce(ReduceArgs),
    /// The Hertz contact problem with finite friction, solved exactly (docs/hertz.md).
    ///
    /// `hertz --nu 0.25 --mu 0.1801` finds the stick radius c; `--c 0.5`
    /// finds μ instead. `hertz table` reproduces the seed paper's tables
    /// beside our values; `hertz sweep` solves a ν × μ grid in parallel.
    #[command(after_help = help_with_examples!("  lambdamat hertz --nu 0.25 --mu 0.1801\n  lambdamat hertz --nu 0 --c 0.5 --json"))]
    Hertz(hertz::HertzArgs),
    /// Solve the file's operator system numerically: unknowns on a grid,
    /// outputs, an error estimate and the commutator defects of the pairs
    /// an elimination commuted.
    #[command(after_help = help_with_examples!("  lambdamat solve examples/mms.lmx --method coupled --csv /tmp/mms.csv\n  lambdamat solve examples/hertz.lmx --set nu=0.25 --set mu=0.1801"))]
    Solve(SolveArgs),
    /// Write a standalone Rust solver for the file's operator system.
    ///
    /// Kernels, multipliers, right sides and output weights become Rust
    /// functions; the module's `system()` collects them and its `main()`
    /// solves through lambdamat's numeric layer, printing what `lambdamat
    /// solve` prints (same flags). Use it as an example or binary target of
    /// a crate that depends on lambdamat, or include it as a module.
    #[command(after_help = help_with_examples!("  lambdamat codegen examples/mms.lmx -o /tmp/mms_solver.rs"))]
    Codegen(CodegenArgs),
}

/// Arguments of `lambdamat solve`.
#[derive(Args, Debug)]
pub struct SolveArgs {
    /// A lambdamat source file (.lmx).
    pub file: PathBuf,
    /// The unknown the eliminations solve for (default: the file's `solve for`, else the first unknown).
    #[arg(long = "for", value_name = "UNKNOWN")]
    pub unknown: Option<String>,
    #[command(flatten)]
    pub flags: SolveFlags,
}

/// How to solve and what to print: shared by `lambdamat solve` and the
/// solvers `lambdamat codegen` writes.
#[derive(Args, Debug, Clone)]
pub struct SolveFlags {
    /// coupled (one collocation system of every equation; the default), ordered (exact block elimination in the pivot order `lambdamat reduce` prints) or commutative (the seed's single equation, a model). A method that cannot apply to the file (side conditions for ordered and commutative; relations, exact singular terms or det(A) = 0 for commutative) is refused with the reason (exit 2).
    #[arg(long, value_parser = ["coupled", "ordered", "commutative"])]
    pub method: Option<String>,
    /// Refine until every error estimate (absolute, from successive levels) is within tol·max(1, |value|): absolute tolerance tol for values up to 1, relative above (finite, > 0).
    #[arg(long, default_value = "1e-10", allow_hyphen_values = true)]
    pub tol: f64,
    /// Refine also until every unknown's largest pointwise estimate on the output grid is within field-tol·max(1, size), its size being its largest |u/weight| there (> 0; default: the larger of --tol and 1e-6). `--field-tol inf`: the unknowns are reported with their estimates but do not decide convergence. Points where the behaviour is not resolved pointwise (ends graded by the end check, points a `singular` declaration grades toward, pieces narrower than 1e-4 of the interval) are left out of the grid, each with its reason.
    #[arg(long, allow_hyphen_values = true)]
    pub field_tol: Option<f64>,
    /// Highest refinement level tried (levels are numbered from 0; at most 14).
    #[arg(long, default_value_t = 8, allow_hyphen_values = true)]
    pub max_level: usize,
    /// Memory budget, e.g. 2G or 500M (default: half the free memory, and of `ulimit -v`). A level that would not fit is not built: the result of the last level that did is printed and marked (exit 4), or, if none fits, the size needed is reported (exit 3).
    #[arg(long, value_name = "SIZE", value_parser = crate::numeric::budget::parse_size)]
    pub max_memory: Option<u64>,
    /// Print one JSON object instead of text.
    #[arg(long)]
    pub json: bool,
    /// Write the unknowns on the output grid as CSV (one column per unknown).
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,
    /// Plot the unknowns as SVG.
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,
}

/// Arguments of `lambdamat codegen`.
#[derive(Args, Debug)]
pub struct CodegenArgs {
    /// A lambdamat source file (.lmx) with an operator system.
    pub file: PathBuf,
    /// The unknown the eliminations solve for (default: the file's `solve for`, else the first unknown).
    #[arg(long = "for", value_name = "UNKNOWN")]
    pub unknown: Option<String>,
    /// Write the Rust module here (default: standard output).
    #[arg(short, long, value_name = "FILE.rs")]
    pub output: Option<PathBuf>,
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
    /// Memory budget of each solve, e.g. 2G or 500M (default: half the free memory, and of `ulimit -v`).
    #[arg(long, value_name = "SIZE", value_parser = crate::numeric::budget::parse_size)]
    max_memory: Option<u64>,
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

pub use crate::api::locate::read_source;

/// The command line parsed as `T`, or the exit code after clap printed
/// help (0) or a usage error (1).
pub fn parse_args<T: Parser>() -> Result<T, i32> {
    T::try_parse().map_err(|e| {
        let code = if e.use_stderr() { 1 } else { 0 };
        let _ = e.print();
        code
    })
}

/// The exit code of a command's result, reporting an error on stderr.
pub fn exit_code(result: Result<(), CliError>) -> i32 {
    match result {
        Ok(()) => 0,
        Err(e) => {
            e.report();
            e.exit_code()
        }
    }
}

/// Entry point used by the binary; returns the process exit code.
pub fn main() -> i32 {
    let cli = match parse_args::<Cli>() {
        Ok(c) => c,
        Err(code) => return code,
    };
    match parse_sets(&cli.set) {
        Ok(sets) => {
            let _ = OVERRIDES.set(sets);
        }
        Err(e) => return exit_code(Err(e)),
    }
    let mut stdout = output::Stdout::new();
    let result = match cli.command {
        Command::Run(a) => run::run(&a.file, &a.out, a.max_memory, &mut stdout),
        Command::Smith(a) => smith::smith_command(&a, &mut stdout),
        Command::Reduce(a) => reduce::reduce_command(&a, &mut stdout),
        Command::Solve(a) => solve::solve_command(&a, &mut stdout),
        Command::Codegen(a) => codegen::codegen_command(&a, &mut stdout),
        Command::Hertz(a) => hertz::hertz_command(&a, &mut stdout),
    };
    let _ = stdout.flush();
    exit_code(result)
}
