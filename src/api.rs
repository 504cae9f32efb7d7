//! The library's small entry point: a [`Problem`] is one parsed, validated
//! source file, and everything the command line does with a file is a
//! method on it — [`Problem::smith`], [`Problem::reduce`],
//! [`Problem::codegen`], [`Problem::solve`] — returning values
//! ([`SmithForm`], [`Reduction`], [`Solution`]) that print through the
//! crate's one printer, and one [`Error`] whose kind mirrors the command
//! line's exit codes. The CLI's `smith`, `reduce` and `codegen` commands
//! and the Python package (`python/`) are clients of this module. It owns
//! the choices a command makes before the work (which matrix, which
//! unknown, which parameters are set) and delegates the work itself.
//!
//! ```
//! use lambdamat::{Problem, SolveOptions};
//! let p = Problem::from_source(
//!     "unknown f on [0, 1]\noperator k = int(0..x) dt\nequation f + k f = 1\noutput F = int(0..1) f(x) dx",
//!     "ex.lmx",
//! )?;
//! let s = p.solve(&SolveOptions::default())?;
//! assert!(s.converged);
//! // f = exp(-x), so F = 1 - 1/e
//! assert!((s.outputs["F"] - (1.0 - (-1.0f64).exp())).abs() <= s.error_estimates["F"] + 1e-12);
//! # Ok::<(), lambdamat::Error>(())
//! ```

use std::path::Path;

use num_rational::BigRational;

use crate::algebra::matrix::Matrix;
use crate::algebra::polyring::PolyRing;
use crate::algebra::smith::modes::{self, SmithReport};
use crate::error::CliError;
pub use crate::hertz::front::Given;
use crate::lang::Directive;
pub use crate::plan::Method;
use crate::plan::{PlanError, SplitInput};
use crate::system::Program;

mod exact;
mod hertz;
pub(crate) mod locate;
pub use self::exact::{RationalFunction, Terms};
pub(crate) use self::hertz::check_tol;
pub use self::hertz::{
    Hertz, HertzOptions, HertzRefusal, HertzSweep, HertzTable, MAX_SWEEP_POINTS, Tally, hertz,
    hertz_report, hertz_sweep, hertz_table,
};

/// What kind of failure an [`Error`] is; each kind maps to one of the
/// command line's exit codes ([`Error::exit_code`]). New kinds may be
/// added, so a `match` on it needs a wildcard arm.
///
/// ```
/// use lambdamat::{ErrorKind, Problem};
/// let e = Problem::from_file("no/such/file.lmx").unwrap_err();
/// assert_eq!(e.kind(), ErrorKind::Io);
/// assert_eq!(e.exit_code(), 2);
/// let e = Problem::from_source("var x\nmatrix A = [y]", "a.lmx").unwrap_err();
/// assert_eq!(e.kind(), ErrorKind::InvalidInput);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum ErrorKind {
    /// Invalid input: the text, a parameter or an option (exit 2); nothing
    /// was computed.
    InvalidInput,
    /// A file could not be read or written (exit 2, as invalid input: the
    /// path given is wrong); nothing was computed.
    Io,
    /// A computation refused or failed, naming the cause (exit 3).
    ComputationFailed,
}

/// A place in a source file an [`Error`] points at (1-based); see
/// [`Error::locations`].
///
/// ```
/// let e = lambdamat::Problem::from_source("var x\n\nmatrix A = [x, z]", "a.lmx").unwrap_err();
/// let lambdamat::Location { file, line, column } = e.locations()[0].clone();
/// assert_eq!(format!("{file}:{line}:{column}"), "a.lmx:3:16");
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Location {
    /// The file name as given to [`Problem::from_source`] or
    /// [`Problem::from_file`].
    pub file: String,
    /// Line, from 1.
    pub line: usize,
    /// Column in characters, from 1.
    pub column: usize,
}

/// Why a [`Problem`] method failed. Its `Display` is the message the
/// command line prints on standard error for the same failure (plain
/// text, with `file:line:column` and a caret for source errors).
///
/// ```
/// use lambdamat::{ErrorKind, Problem};
/// let e = Problem::from_source("var x\nmatrix A = [y]", "a.lmx").unwrap_err();
/// assert_eq!(e.kind(), ErrorKind::InvalidInput);
/// assert_eq!(e.exit_code(), 2);
/// assert_eq!((e.locations()[0].line, e.locations()[0].column), (2, 13));
/// assert!(e.to_string().contains("a.lmx:2:13"));
/// ```
#[derive(Debug)]
pub struct Error(CliError);

impl Error {
    /// The kind: invalid input, a file that cannot be read or written, or
    /// a failed computation.
    ///
    /// ```
    /// use lambdamat::{ErrorKind, Problem, SolveOptions};
    /// // A file with a matrix and no system parses, but has nothing to solve.
    /// let p = Problem::from_source("var x\nmatrix A = [x, 1]", "a.lmx")?;
    /// let e = p.solve(&SolveOptions::default()).unwrap_err();
    /// assert_eq!(e.kind(), ErrorKind::InvalidInput);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn kind(&self) -> ErrorKind {
        match &self.0 {
            CliError::Io { .. } | CliError::Write { .. } => ErrorKind::Io,
            _ if self.exit_code() == crate::error::EXIT_FAILED => ErrorKind::ComputationFailed,
            _ => ErrorKind::InvalidInput,
        }
    }

    /// The exit code `lambdamat` ends with for this error: 2 or 3.
    ///
    /// ```
    /// let e = lambdamat::Problem::from_source("unknown f on [0, 1", "a.lmx").unwrap_err();
    /// assert_eq!(e.exit_code(), 2);
    /// ```
    pub fn exit_code(&self) -> i32 {
        match self.0.exit_code() {
            crate::error::EXIT_FAILED => crate::error::EXIT_FAILED,
            _ => crate::error::EXIT_INVALID,
        }
    }

    /// The source places the error points at (empty when it names none).
    ///
    /// ```
    /// let e = lambdamat::Problem::from_source("var x\nmatrix A = [x, z]", "a.lmx").unwrap_err();
    /// let at = &e.locations()[0];
    /// assert_eq!((at.file.as_str(), at.line, at.column), ("a.lmx", 2, 16));
    /// ```
    pub fn locations(&self) -> Vec<Location> {
        match &self.0 {
            CliError::Lang(errs) => errs
                .errors()
                .iter()
                .map(|e| {
                    let (line, column) = errs.line_col(e.span);
                    Location {
                        file: errs.filename().to_string(),
                        line,
                        column,
                    }
                })
                .collect(),
            _ => Vec::new(),
        }
    }

    /// The command line's error, for the CLI's own reporting.
    pub(crate) fn into_cli(self) -> CliError {
        self.0
    }
}

impl From<CliError> for Error {
    fn from(e: CliError) -> Error {
        Error(e)
    }
}

impl From<PlanError> for Error {
    fn from(e: PlanError) -> Error {
        Error(CliError::Plan(e))
    }
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.0.plain_message().trim_end())
    }
}

impl std::error::Error for Error {}

fn invalid(msg: String) -> Error {
    Error(CliError::Invalid(msg))
}

/// Reads `NAME=VALUE` settings as `--set` does: the value is an integer, a
/// decimal (`0.1801`, read as the exact rational 1801/10000) or a
/// fraction (`1/4`).
///
/// ```
/// let s = lambdamat::api::parse_sets(&[("nu".into(), "0.25".into())])?;
/// assert_eq!(s[0].1.to_string(), "1/4");
/// # Ok::<(), lambdamat::Error>(())
/// ```
pub fn parse_sets(set: &[(String, String)]) -> Result<Vec<(String, BigRational)>, Error> {
    set.iter()
        .map(|(n, v)| {
            let value = crate::lang::parser::parse_exact(v.trim()).ok_or_else(|| {
                invalid(format!(
                    "--set {n}={v}: `{v}` is not an exact number (write an integer, a decimal such as 0.1801, or a fraction such as 1/4)"
                ))
            })?;
            Ok((n.trim().to_string(), value))
        })
        .collect()
}

/// One source file, parsed and validated (with its parameters set).
///
/// ```
/// use lambdamat::Problem;
/// let p = Problem::from_source("param a = 1/2\nvar x\nmatrix A = [x, a; 0, x]", "m.lmx")?;
/// assert_eq!(p.params(), vec![("a".to_string(), "1/2".to_string())]);
/// # Ok::<(), lambdamat::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct Problem {
    program: Program,
    text: String,
    name: String,
    sets: Vec<(String, BigRational)>,
}

impl Problem {
    /// Parses and validates `text`, shown as `name` in messages. Invalid
    /// text is an [`Error`] naming `name`, line and column.
    ///
    /// ```
    /// let p = lambdamat::Problem::from_source("var x\nmatrix A = [x, 1; 0, x]", "m.lmx")?;
    /// assert_eq!(p.name(), "m.lmx");
    /// let e = lambdamat::Problem::from_source("var x\nmatrix A = [x, 1; 0]", "m.lmx").unwrap_err();
    /// assert_eq!(e.locations()[0].file, "m.lmx");
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn from_source(text: &str, name: &str) -> Result<Problem, Error> {
        Problem::with_sets(text.to_string(), name.to_string(), Vec::new())
    }

    /// Reads, parses and validates the file at `path`.
    ///
    /// ```
    /// let p = lambdamat::Problem::from_file("examples/hertz.lmx")?;
    /// assert_eq!(p.params()[0], ("nu".to_string(), "1/4".to_string()));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn from_file(path: impl AsRef<Path>) -> Result<Problem, Error> {
        let (text, name) = locate::read_source(path.as_ref())?;
        Problem::with_sets(text, name, Vec::new())
    }

    /// The same source with parameters set (each replaces the parameter's
    /// definition before validation, as `--set` does). A name that is
    /// not a parameter of the file is invalid input.
    ///
    /// ```
    /// let p = lambdamat::Problem::from_source("param a = 1\nvar x\nmatrix A = [a*x]", "m.lmx")?;
    /// let q = p.with_set(&[("a".into(), "3/2".into())])?;
    /// assert_eq!(q.params()[0].1, "3/2");
    /// assert!(p.with_set(&[("b".into(), "1".into())]).is_err());
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn with_set(&self, set: &[(String, String)]) -> Result<Problem, Error> {
        let mut sets = self.sets.clone();
        sets.extend(parse_sets(set)?);
        Problem::with_sets(self.text.clone(), self.name.clone(), sets)
    }

    /// `text` with the exact settings `sets` (names checked against the
    /// file's parameters).
    pub(crate) fn with_sets(
        text: String,
        name: String,
        sets: Vec<(String, BigRational)>,
    ) -> Result<Problem, Error> {
        let lang = |e| Error(CliError::Lang(Box::new(e)));
        if !sets.is_empty() {
            let ast = crate::lang::parse_ast(&text, &name).map_err(lang)?;
            let names = crate::lang::param_names(&ast);
            for (n, _) in &sets {
                if !names.contains(n) {
                    return Err(invalid(format!(
                        "--set {n}: {name} defines no parameter `{n}` (parameters: {})",
                        if names.is_empty() {
                            "none".to_string()
                        } else {
                            names.join(", ")
                        }
                    )));
                }
            }
        }
        let program = crate::lang::parse_program_with(&text, &name, &sets).map_err(lang)?;
        Ok(Problem {
            program,
            text,
            name,
            sets,
        })
    }

    /// The lowered program (for the command line).
    pub(crate) fn program(&self) -> &Program {
        &self.program
    }

    /// The name the source is shown under.
    ///
    /// ```
    /// let p = lambdamat::Problem::from_source("var x\nmatrix A = [x]", "mine.lmx")?;
    /// assert_eq!(p.name(), "mine.lmx");
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The source text (without the settings of [`Problem::with_set`]).
    ///
    /// ```
    /// let p = lambdamat::Problem::from_source("param a = 1\nvar x\nmatrix A = [a*x]", "m.lmx")?;
    /// let q = p.with_set(&[("a".into(), "2".into())])?;
    /// assert_eq!(q.source(), p.source());
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn source(&self) -> &str {
        &self.text
    }

    /// The parameters in definition order: each name and its value as
    /// written in the file (or as set by [`Problem::with_set`], printed
    /// exactly).
    ///
    /// ```
    /// let p = lambdamat::Problem::from_file("examples/hertz.lmx")?;
    /// for (name, value) in p.params() {
    ///     println!("{name} = {value}");
    /// }
    /// assert_eq!(p.params()[0].0, "nu");
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn params(&self) -> Vec<(String, String)> {
        let text = crate::lang::strip_bom(&self.text);
        let Ok(ast) = crate::lang::parse_ast(text, &self.name) else {
            return Vec::new();
        };
        ast.statements
            .iter()
            .filter_map(|s| match &s.kind {
                crate::lang::ast::Stmt::Param { name, value } => {
                    let set = self.sets.iter().rev().find(|(n, _)| *n == name.name);
                    let shown = match set {
                        Some((_, v)) => v.to_string(),
                        None => text
                            .get(value.span.start..value.span.end)
                            .unwrap_or_default()
                            .to_string(),
                    };
                    Some((name.name.clone(), shown))
                }
                _ => None,
            })
            .collect()
    }

    /// The matrices [`Problem::smith`] decomposes: `(name, matrix)` for
    /// the matrix `opts.matrix`, else the file's `smith` directives, else
    /// every matrix, else the λ-matrix of the operator system (named `A`).
    pub(crate) fn smith_targets(
        &self,
        opts: &SmithOptions,
    ) -> Result<Vec<(String, Matrix<PolyRing>)>, Error> {
        let p = &self.program;
        let as_matrix = |m: &crate::lang::MatrixDef| {
            Matrix::new(
                PolyRing::new(p.symbols.clone()),
                m.rows,
                m.cols,
                m.entries.clone(),
            )
        };
        if let Some(name) = &opts.matrix {
            let m = p.matrices.iter().find(|m| &m.name == name).ok_or_else(|| {
                invalid(format!(
                    "--matrix {name}: no such matrix in the file (defined: {})",
                    if p.matrices.is_empty() {
                        "none".to_string()
                    } else {
                        p.matrices
                            .iter()
                            .map(|m| m.name.as_str())
                            .collect::<Vec<_>>()
                            .join(", ")
                    }
                ))
            })?;
            return Ok(vec![(m.name.clone(), as_matrix(m))]);
        }
        let from_directives: Vec<usize> = p
            .directives
            .iter()
            .filter_map(|d| match d {
                Directive::Smith { matrix } => Some(*matrix),
                _ => None,
            })
            .collect();
        let chosen: Vec<usize> = if from_directives.is_empty() {
            (0..p.matrices.len()).collect()
        } else {
            from_directives
        };
        if !chosen.is_empty() {
            return Ok(chosen
                .into_iter()
                .map(|i| (p.matrices[i].name.clone(), as_matrix(&p.matrices[i])))
                .collect());
        }
        if p.equations.is_empty() {
            return Err(invalid(format!(
                "{}: the file defines no matrix and no operator system",
                self.name
            )));
        }
        let a = p.lambda_matrix();
        Ok(vec![(a.name.clone(), as_matrix(&a))])
    }

    /// The principal symbol's index: `opts.principal`, else the file's
    /// `principal` line.
    pub(crate) fn principal(&self, opts: &SmithOptions) -> Result<Option<usize>, Error> {
        principal_of(&self.program, opts.principal.as_deref())
    }

    /// The certified Smith form of the file's matrix (the one named by
    /// `opts.matrix`, else the first the file asks for with `smith`, else
    /// its first matrix) or, when it defines none, of the λ-matrix of its
    /// operator system. The decomposition is certified before it is
    /// returned; a failed certificate is an error, never a result.
    ///
    /// ```
    /// use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_source("var x\nmatrix A = [x, 1; 0, x]", "m.lmx")?;
    /// let s = p.smith(&SmithOptions::default())?;
    /// assert_eq!(s.invariant_factors(), &["1".to_string(), "x^2".to_string()]);
    /// assert!(s.verified());
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn smith(&self, opts: &SmithOptions) -> Result<SmithForm, Error> {
        let mut all = self.smith_targets(opts)?;
        let principal = self.principal(opts)?;
        let (name, m) = all.swap_remove(0);
        SmithForm::compute(&name, &m, principal, &modes::PhaseHook::default())
    }

    /// The reduction of the operator system for `target` (an unknown's
    /// name; default the file's `solve for`, else the first unknown): the
    /// commutative eliminant, the ordered form and the commuted pairs.
    ///
    /// ```
    /// let p = lambdamat::Problem::from_file("examples/generic3.lmx")?;
    /// let r = p.reduce(None)?;
    /// assert!(!r.eliminant().lmx.is_empty());
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn reduce(&self, target: Option<&str>) -> Result<Reduction, Error> {
        let p = &self.program;
        let u = crate::reduce::choose_unknown(p, target).map_err(|e| Error(e.into()))?;
        if p.contact.is_split() {
            let pieces = crate::report::reduction::split_reductions(p, u)?;
            return Ok(Reduction {
                pieces: pieces
                    .into_iter()
                    .map(|(piece, r)| (Some(piece), r))
                    .collect(),
            });
        }
        let r = crate::reduce::reduce(p, u).map_err(|e| Error(e.into()))?;
        Ok(Reduction {
            pieces: vec![(None, r)],
        })
    }

    /// The Rust source of a standalone solver for the system, solving for
    /// `target` (default as in [`Problem::reduce`]): what `lambdamat
    /// codegen` writes. The system must pass the input checks `solve`
    /// makes (the first level, assembled and solved once, runs them; with
    /// unknown scalars a short solve on the first levels; only their input
    /// errors refuse it).
    ///
    /// ```
    /// let p = lambdamat::Problem::from_file("examples/mms.lmx")?;
    /// let code = p.codegen(None)?;
    /// assert!(code.contains("fn main"));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn codegen(&self, target: Option<&str>) -> Result<String, Error> {
        let mut command = format!("lambdamat codegen {}", self.name);
        if let Some(u) = target {
            command.push_str(&format!(" --for {u}"));
        }
        for (name, value) in &self.sets {
            command.push_str(&format!(" --set {name}={value}"));
        }
        command.push_str(" -o FILE.rs");
        let from = crate::codegen::Provenance {
            source: self.name.clone(),
            command,
        };
        let prog = &self.program;
        let code =
            crate::codegen::solver_source(prog, target, &from).map_err(|e| self.located(e))?;
        // The solver's input checks (intervals, scalars against
        // conditions, operators) run when its problem is made; those of the
        // numerics (right sides finite at the nodes, …) on the first level,
        // or with unknown scalars on a short solve.
        let input = SplitInput::for_target(prog, target).map_err(|e| self.located(e))?;
        match crate::plan::split_solve::check_inputs(input) {
            Ok(true) => return Ok(code),
            Err(e) if e.is_input_error() => return Err(self.located(e)),
            Err(_) => return Ok(code),
            Ok(false) => {}
        }
        let quick = crate::report::SolveSettings {
            tol: 1.0,
            max_level: 1,
            unknown: target.map(str::to_string),
            ..crate::report::SolveSettings::default()
        };
        if let Err(e) = crate::report::solve(prog, &quick)
            && e.is_input_error()
        {
            return Err(self.located(e));
        }
        Ok(code)
    }

    /// Solves the file's system (a split-domain file with the split-domain
    /// solver) after setting `opts.set`, refining until the error
    /// estimate is below `opts.tol` or the levels run out. A result that
    /// did not reach the tolerance is `Ok` with `converged == false`.
    ///
    /// ```
    /// use lambdamat::{Problem, SolveOptions};
    /// let p = Problem::from_file("examples/mms.lmx")?;
    /// let s = p.solve(&SolveOptions { tol: 1e-8, ..SolveOptions::default() })?;
    /// assert!(s.converged);
    /// assert_eq!(s.unknowns.len(), 2);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn solve(&self, opts: &SolveOptions) -> Result<Solution, Error> {
        let settings = opts.settings()?;
        let problem;
        let me = if opts.set.is_empty() {
            self
        } else {
            problem = self.with_set(&opts.set)?;
            &problem
        };
        crate::report::solve(&me.program, &settings).map_err(|e| me.located(e))
    }

    /// A plan error pointed at its place in the source, when it has one.
    fn located(&self, e: PlanError) -> Error {
        Error(locate::located(e, &self.text, &self.name))
    }
}

/// A float as `--set` reads it: its shortest decimal (`0.1801`, not the
/// binary double's exact expansion).
///
/// ```
/// assert_eq!(lambdamat::api::float_text(0.1801), "0.1801");
/// let s = lambdamat::api::parse_sets(&[("mu".into(), lambdamat::api::float_text(0.3))])?;
/// assert_eq!(s[0].1.to_string(), "3/10");
/// # Ok::<(), lambdamat::Error>(())
/// ```
pub fn float_text(x: f64) -> String {
    format!("{x}")
}

/// The index of the principal symbol: `flag`, else the program's
/// `principal` line; a flag naming no symbol is invalid input.
pub(crate) fn principal_of(p: &Program, flag: Option<&str>) -> Result<Option<usize>, Error> {
    match flag {
        None => Ok(p.principal),
        Some(s) => p
            .symbols
            .iter()
            .position(|n| n == s)
            .map(Some)
            .ok_or_else(|| {
                invalid(format!(
                    "--principal {s}: no such symbol in the file (declared: {})",
                    if p.symbols.is_empty() {
                        "none".to_string()
                    } else {
                        p.symbols.join(", ")
                    }
                ))
            }),
    }
}

/// The highest refinement level a solve tries by default (the command
/// line's `--max-level` default).
///
/// ```
/// assert_eq!(lambdamat::SolveOptions::default().max_level, None); // means this
/// assert_eq!(lambdamat::api::DEFAULT_MAX_LEVEL, 8);
/// ```
pub const DEFAULT_MAX_LEVEL: usize = 8;

/// Options of [`Problem::solve`].
///
/// ```
/// use lambdamat::{Method, SolveOptions};
/// let o = SolveOptions {
///     set: vec![("nu".into(), "0.3".into())],
///     method: Some(Method::Coupled),
///     ..SolveOptions::default()
/// };
/// assert_eq!(o.tol, 1e-10);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct SolveOptions {
    /// Parameter settings `(name, value)`, read exactly as `--set` reads
    /// them (see [`parse_sets`]).
    pub set: Vec<(String, String)>,
    /// Refine until the error estimate is below this (finite, > 0).
    pub tol: f64,
    /// The method (default: `ordered` on one interval; split-domain files
    /// use their own collocation and refuse the others).
    pub method: Option<Method>,
    /// The highest refinement level (default [`DEFAULT_MAX_LEVEL`], at
    /// most 14).
    pub max_level: Option<usize>,
    /// The memory budget in bytes (default: the rule of
    /// `crate::numeric::budget`, half the free memory). A refinement
    /// level that would not fit is not built: the solve stops at the last
    /// level that did (not converged, with a warning) or fails with the
    /// size it would have needed.
    pub max_memory: Option<u64>,
    /// The unknown the eliminations solve for (default: the file's `solve
    /// for`, else the first unknown).
    pub unknown: Option<String>,
    /// On a split domain, the unknowns' tolerance: convergence also needs
    /// each unknown's largest pointwise estimate on the output grid
    /// within `field_tol·max(1, size)` (`--field-tol`). `None` (the
    /// default): the larger of `tol` and `1e-6`;
    /// `Some(f64::INFINITY)` (`--field-tol inf`): the unknowns are
    /// reported with their estimates but do not enter convergence.
    pub field_tol: Option<f64>,
}

impl SolveOptions {
    /// Checks the options before any work, as the command line checks its
    /// flags: a finite tolerance > 0, a level the numerics support (at
    /// most 14), a field tolerance > 0. A failure is invalid input.
    ///
    /// ```
    /// use lambdamat::SolveOptions;
    /// assert!(SolveOptions::default().check().is_ok());
    /// let bad = SolveOptions { tol: f64::NAN, ..SolveOptions::default() };
    /// assert_eq!(bad.check().unwrap_err().exit_code(), 2);
    /// ```
    pub fn check(&self) -> Result<(), Error> {
        self.settings().map(|_| ())
    }

    /// The report's settings for these options, checked.
    fn settings(&self) -> Result<crate::report::SolveSettings, Error> {
        let settings = crate::report::SolveSettings {
            unknown: self.unknown.clone(),
            tol: self.tol,
            max_level: self.max_level.unwrap_or(DEFAULT_MAX_LEVEL),
            method: self.method,
            max_memory: self.max_memory,
            field_tol: self.field_tol,
            ..crate::report::SolveSettings::default()
        };
        settings.check()?;
        Ok(settings)
    }
}

impl Default for SolveOptions {
    fn default() -> SolveOptions {
        SolveOptions {
            set: Vec::new(),
            tol: 1e-10,
            method: None,
            max_level: None,
            max_memory: None,
            unknown: None,
            field_tol: None,
        }
    }
}

pub use crate::report::Field;
/// A solved problem: the one report of a solve, whose
/// [`to_json`](Solution::to_json) is what `lambdamat solve --json` prints.
/// `converged`, `scalars`, `outputs`, `error_estimates` (absolute),
/// `unknowns` (name → [`Field`]) and `warnings` are its fields.
pub use crate::report::Report as Solution;

// Values the methods of `SmithForm` and `Reduction` return: one check of
// a Smith form's certificate, a formula in three notations and the ordered
// elimination's form.
pub use crate::algebra::smith::certify::Check;
pub use crate::reduce::{OrderedForm, Printed};

/// Options of [`Problem::smith`].
///
/// ```
/// use lambdamat::{Problem, SmithOptions};
/// let p = Problem::from_source("var x, y\nmatrix A = [x, y; 0, x]\nmatrix B = [y]", "m.lmx")?;
/// let s = p.smith(&SmithOptions { matrix: Some("B".into()), principal: Some("y".into()) })?;
/// assert_eq!(s.name(), "B");
/// # Ok::<(), lambdamat::Error>(())
/// ```
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SmithOptions {
    /// The principal symbol λ (overrides the file's `principal` line).
    pub principal: Option<String>,
    /// The matrix to decompose (default: the first the file asks for).
    pub matrix: Option<String>,
}

/// A certified Smith decomposition `U·A·V = D`. Entries are exact: each is
/// the one printer's output in the language's syntax (it parses back with
/// `crate::lang::formula`), with LaTeX beside it.
///
/// ```
/// use lambdamat::{Problem, SmithOptions};
/// let p = Problem::from_source("var x\nmatrix A = [x, 1; 0, x]", "m.lmx")?;
/// let s = p.smith(&SmithOptions::default())?;
/// assert_eq!(s.d()[1][1], "x^2");
/// assert!(s.latex().contains("\\begin{pmatrix}"));
/// assert!(s.text().contains("verified: yes"));
/// # Ok::<(), lambdamat::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct SmithForm {
    report: SmithReport,
    symbols: Vec<String>,
}

impl SmithForm {
    pub(crate) fn compute(
        name: &str,
        a: &Matrix<PolyRing>,
        principal: Option<usize>,
        progress: &modes::PhaseHook,
    ) -> Result<SmithForm, Error> {
        let opts = modes::SmithOptions {
            principal,
            latex: true,
            progress: progress.clone(),
        };
        let report = modes::smith_report(name, a, &opts).map_err(|e| Error(e.into()))?;
        Ok(SmithForm {
            report,
            symbols: a.ring.names.clone(),
        })
    }

    /// `rows` read back as exact values.
    fn exact(&self, rows: &[Vec<String>]) -> Result<Vec<Vec<RationalFunction>>, Error> {
        rows.iter()
            .map(|r| r.iter().map(|e| self.read(e)).collect())
            .collect()
    }

    /// One printed entry read back as an exact value.
    fn read(&self, text: &str) -> Result<RationalFunction, Error> {
        RationalFunction::read(text, &self.symbols).ok_or_else(|| {
            Error(CliError::Numeric(format!(
                "the printed entry `{text}` of {} does not read back as a rational function of {}",
                self.report.matrix,
                self.symbols.join(", ")
            )))
        })
    }

    /// The invariant factors as exact values (the same facts as
    /// [`SmithForm::invariant_factors`], read back from them).
    ///
    /// ```
    /// use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_file("examples/hertz.lmx")?;
    /// let s = p.smith(&SmithOptions::default())?;
    /// let f = s.exact_invariant_factors()?;
    /// assert_eq!(f.len(), s.invariant_factors().len());
    /// assert_eq!(f[0].to_string(), s.invariant_factors()[0]);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn exact_invariant_factors(&self) -> Result<Vec<RationalFunction>, Error> {
        self.report
            .invariant_factors
            .iter()
            .map(|e| self.read(e))
            .collect()
    }

    /// D as exact values.
    ///
    /// ```
    /// use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_source("var x\nmatrix A = [x, 1; 0, x]", "m.lmx")?;
    /// let d = p.smith(&SmithOptions::default())?.exact_d()?;
    /// assert!(d[0][1].numerator().is_empty()); // zero has no terms
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn exact_d(&self) -> Result<Vec<Vec<RationalFunction>>, Error> {
        self.exact(&self.report.d)
    }

    /// U and V as exact values (`None` in the determinantal-divisor mode).
    /// With [`SmithForm::exact_a`] and [`SmithForm::exact_d`] they let a
    /// caller check `U·A·V = D` in its own arithmetic.
    ///
    /// ```
    /// use lambdamat::{Problem, SmithOptions};
    /// use num_rational::BigRational as Q;
    /// let p = Problem::from_source("var x\nmatrix A = [x, 1; 0, x]", "m.lmx")?;
    /// let s = p.smith(&SmithOptions::default())?;
    /// let (u, v) = s.exact_uv()?.expect("U and V are computed");
    /// let (a, d) = (s.exact_a()?, s.exact_d()?);
    /// // U·A·V = D at x = 5, entry by entry.
    /// let at = |f: &lambdamat::RationalFunction| f.eval(&[Q::from_integer(5.into())]).unwrap();
    /// for i in 0..2 {
    ///     for j in 0..2 {
    ///         let mut uav = Q::from_integer(0.into());
    ///         for k in 0..2 {
    ///             for l in 0..2 {
    ///                 uav += at(&u[i][k]) * at(&a[k][l]) * at(&v[l][j]);
    ///             }
    ///         }
    ///         assert_eq!(uav, at(&d[i][j]));
    ///     }
    /// }
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    #[allow(clippy::type_complexity)]
    pub fn exact_uv(
        &self,
    ) -> Result<Option<(Vec<Vec<RationalFunction>>, Vec<Vec<RationalFunction>>)>, Error> {
        match (&self.report.u, &self.report.v) {
            (Some(u), Some(v)) => Ok(Some((self.exact(u)?, self.exact(v)?))),
            _ => Ok(None),
        }
    }

    /// The input matrix A as exact values.
    ///
    /// ```
    /// use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_source("var x\nmatrix A = [x/2]", "m.lmx")?;
    /// let a = p.smith(&SmithOptions::default())?.exact_a()?;
    /// assert_eq!(a[0][0].numerator()[0].1, num_rational::BigRational::new(1.into(), 2.into()));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn exact_a(&self) -> Result<Vec<Vec<RationalFunction>>, Error> {
        self.exact(&self.report.a)
    }

    /// The matrix's name (`A` for an operator system's λ-matrix).
    ///
    /// ```
    /// use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_source("var x\nmatrix A = [x, 1; 0, x]", "m.lmx")?;
    /// let s = p.smith(&SmithOptions::default())?;
    /// assert_eq!(s.name(), "A");
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn name(&self) -> &str {
        &self.report.matrix
    }

    /// The ring, e.g. `Q[x]` or `Q(k1, k2, k3)[k4]`.
    ///
    /// ```
    /// use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_source("var x\nmatrix A = [x, 1; 0, x]", "m.lmx")?;
    /// let s = p.smith(&SmithOptions::default())?;
    /// assert_eq!(s.ring(), "Q[x]");
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn ring(&self) -> &str {
        &self.report.ring
    }

    /// The input matrix A.
    ///
    /// ```
    /// use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_source("var x\nmatrix A = [x, 1; 0, x]", "m.lmx")?;
    /// let s = p.smith(&SmithOptions::default())?;
    /// assert_eq!(s.a()[0], ["x", "1"]);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn a(&self) -> &[Vec<String>] {
        &self.report.a
    }

    /// The nonzero invariant factors, each monic, each dividing the next.
    ///
    /// ```
    /// use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_source("var x\nmatrix A = [x, 1; 0, x]", "m.lmx")?;
    /// let s = p.smith(&SmithOptions::default())?;
    /// assert_eq!(s.invariant_factors(), ["1", "x^2"]);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn invariant_factors(&self) -> &[String] {
        &self.report.invariant_factors
    }

    /// D, the diagonal matrix of invariant factors.
    ///
    /// ```
    /// use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_source("var x\nmatrix A = [x, 1; 0, x]", "m.lmx")?;
    /// let s = p.smith(&SmithOptions::default())?;
    /// assert_eq!(s.d(), [["1", "0"], ["0", "x^2"]]);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn d(&self) -> &[Vec<String>] {
        &self.report.d
    }

    /// U (None in the determinantal-divisor mode, which gives D only).
    ///
    /// ```
    /// use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_source("var x\nmatrix A = [x, 1; 0, x]", "m.lmx")?;
    /// let s = p.smith(&SmithOptions::default())?;
    /// let u = s.u().expect("U is computed");
    /// assert_eq!((u.len(), u[0].len()), (2, 2));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn u(&self) -> Option<&[Vec<String>]> {
        self.report.u.as_deref()
    }

    /// V (None in the determinantal-divisor mode).
    ///
    /// ```
    /// use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_source("var x\nmatrix A = [x, 1; 0, x]", "m.lmx")?;
    /// let s = p.smith(&SmithOptions::default())?;
    /// let v = s.v().expect("V is computed");
    /// assert_eq!((v.len(), v[0].len()), (2, 2));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn v(&self) -> Option<&[Vec<String>]> {
        self.report.v.as_deref()
    }

    /// Whether every check of the certificate passed (always true for a
    /// returned form: a failure is an [`Error`]).
    ///
    /// ```
    /// use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_source("var x\nmatrix A = [x, 1; 0, x]", "m.lmx")?;
    /// let s = p.smith(&SmithOptions::default())?;
    /// assert!(s.verified());
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn verified(&self) -> bool {
        self.report.verified
    }

    /// The certificate: each property checked, recomputed from A, U, D, V.
    ///
    /// ```
    /// use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_source("var x\nmatrix A = [x, 1; 0, x]", "m.lmx")?;
    /// let s = p.smith(&SmithOptions::default())?;
    /// assert!(!s.certificate().is_empty());
    /// assert!(s.certificate().iter().all(|c| c.ok));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn certificate(&self) -> &[Check] {
        &self.report.certificate
    }

    /// The text `lambdamat smith` prints.
    ///
    /// ```
    /// use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_source("var x\nmatrix A = [x, 1; 0, x]", "m.lmx")?;
    /// let s = p.smith(&SmithOptions::default())?;
    /// assert!(s.text().contains("x^2"));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn text(&self) -> String {
        crate::report::smith::smith_text(&self.report)
    }

    /// The LaTeX `lambdamat smith --latex` prints.
    ///
    /// ```
    /// use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_source("var x\nmatrix A = [x, 1; 0, x]", "m.lmx")?;
    /// let s = p.smith(&SmithOptions::default())?;
    /// assert!(s.latex().contains("x^{2}"));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn latex(&self) -> String {
        crate::report::smith::smith_latex(&self.report)
    }

    /// The JSON `lambdamat smith --json` prints.
    ///
    /// ```
    /// use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_source("var x\nmatrix A = [x, 1; 0, x]", "m.lmx")?;
    /// let s = p.smith(&SmithOptions::default())?;
    /// let v: serde_json::Value = serde_json::from_str(&s.to_json()).unwrap();
    /// assert_eq!(v["invariant_factors"][1], "x^2");
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(&self.report).unwrap_or_default()
    }
}

/// The reduction of an operator system for one unknown: for a
/// split-domain file one per subinterval ([`Reduction::pieces`]).
///
/// ```
/// let p = lambdamat::Problem::from_file("examples/generic3.lmx")?;
/// let r = p.reduce(None)?;
/// assert!(r.text().contains(&r.eliminant().text));
/// # Ok::<(), lambdamat::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct Reduction {
    pieces: Vec<(
        Option<crate::reduce::split::Piece>,
        crate::reduce::Reduction,
    )>,
}

impl Reduction {
    /// The reduction (of the first subinterval, for a split-domain file).
    pub(crate) fn value(&self) -> &crate::reduce::Reduction {
        &self.pieces[0].1
    }

    /// Each subinterval's label and reduction (one unlabelled piece for a
    /// file on one interval).
    ///
    /// ```
    /// let r = lambdamat::Problem::from_file("examples/generic3.lmx")?.reduce(None)?;
    /// let pieces = r.pieces();
    /// assert_eq!(pieces.len(), 1);
    /// assert_eq!(pieces[0].0, None);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn pieces(&self) -> Vec<(Option<&str>, Reduction)> {
        self.pieces
            .iter()
            .map(|(p, r)| {
                let one = Reduction {
                    pieces: vec![(None, r.clone())],
                };
                (p.as_ref().map(|p| p.label.as_str()), one)
            })
            .collect()
    }

    /// The unknown solved for.
    ///
    /// ```
    /// let r = lambdamat::Problem::from_file("examples/generic3.lmx")?.reduce(None)?;
    /// assert_eq!(r.unknown(), "u1");
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn unknown(&self) -> &str {
        &self.value().unknown
    }

    /// The commutative eliminant's operator on the unknown, printed.
    ///
    /// ```
    /// let r = lambdamat::Problem::from_file("examples/generic3.lmx")?.reduce(None)?;
    /// // The determinant of the 3×3 λ-matrix acts on u1.
    /// assert!(r.eliminant().lmx.contains("k1*k5*k9"));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn eliminant(&self) -> Printed {
        crate::reduce::Printed::of(&self.value().lhs_node)
    }

    /// The ordered elimination's form, or why there is none.
    ///
    /// ```
    /// let r = lambdamat::Problem::from_file("examples/generic3.lmx")?.reduce(None)?;
    /// assert!(r.ordered().is_ok());
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn ordered(&self) -> Result<&OrderedForm, &str> {
        self.value().ordered.as_ref().map_err(String::as_str)
    }

    /// The pairs of operators the commutative eliminant treats as
    /// commuting.
    ///
    /// ```
    /// let r = lambdamat::Problem::from_file("examples/generic3.lmx")?.reduce(None)?;
    /// // Cramer's rule on three unknowns multiplies operators of different
    /// // rows and columns, e.g. k2·k5, as if they commuted.
    /// let pairs = r.commuted_pairs();
    /// assert_eq!(pairs.len(), 12);
    /// assert!(pairs.contains(&["k2".to_string(), "k5".to_string()]));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn commuted_pairs(&self) -> Vec<[String; 2]> {
        self.value()
            .commuted_pairs
            .iter()
            .map(|p| p.pair.clone())
            .collect()
    }

    /// The text `lambdamat reduce` prints.
    ///
    /// ```
    /// let r = lambdamat::Problem::from_file("examples/generic3.lmx")?.reduce(None)?;
    /// assert!(r.text().contains("u1"));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn text(&self) -> String {
        self.print(false)
    }

    /// The LaTeX `lambdamat reduce --latex` prints.
    ///
    /// ```
    /// let r = lambdamat::Problem::from_file("examples/generic3.lmx")?.reduce(None)?;
    /// assert!(r.latex().contains("u_{1}") || r.latex().contains("u1"));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn latex(&self) -> String {
        self.print(true)
    }

    fn print(&self, latex: bool) -> String {
        match self.split_list() {
            Some(list) => crate::report::reduction::split_text(&list, latex),
            None if latex => crate::report::reduction::latex(self.value()),
            None => crate::report::reduction::text(self.value()),
        }
    }

    fn split_list(&self) -> Option<Vec<(crate::reduce::split::Piece, crate::reduce::Reduction)>> {
        self.pieces
            .iter()
            .map(|(p, r)| p.clone().map(|p| (p, r.clone())))
            .collect()
    }

    /// The JSON `lambdamat reduce --json` prints.
    ///
    /// ```
    /// let r = lambdamat::Problem::from_file("examples/generic3.lmx")?.reduce(None)?;
    /// let v: serde_json::Value = serde_json::from_str(&r.to_json()).unwrap();
    /// assert_eq!(v["unknown"], "u1");
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn to_json(&self) -> String {
        let v = match self.split_list() {
            Some(list) => crate::report::reduction::split_json(&list),
            None => crate::report::reduction::to_json(self.value()),
        };
        serde_json::to_string_pretty(&v).unwrap_or_default()
    }
}
