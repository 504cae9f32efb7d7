//! The `solve` command: reads the file as a [`crate::api::Problem`],
//! solves it with [`crate::api::Problem::solve`] (the one entry
//! [`crate::report::solve`]) and prints the returned [`Report`] as text or
//! one JSON object, optionally with a CSV table and an SVG plot of the
//! unknowns.
//! Solvers written by `lambdamat codegen` print the same report through
//! [`crate::standalone`]. It does no numerics and no formatting of its
//! own.
use std::io::Write;
use std::path::Path;

use super::error::CliError;
use super::output::{check_writable, write_file};
use super::smith::load_problem;
use super::{SolveArgs, SolveFlags};
use crate::api::SolveOptions;
use crate::plan::Method;
use crate::report::Report;

/// `lambdamat solve FILE …`.
pub fn solve_command(a: &SolveArgs, w: &mut dyn Write) -> Result<(), CliError> {
    let opts = options(&a.flags, a.unknown.clone())?;
    let problem = load_problem(&a.file)?;
    check_outputs(&a.flags, &[a.file.as_path()])?;
    let r = problem
        .solve(&opts)
        .map_err(crate::api::Error::into_cli)?;
    print(&r, &a.flags, &[a.file.as_path()], w)
}

/// The library's options for the flags, checked before any work
/// ([`SolveOptions::check`]: a finite positive tolerance, a refinement
/// level the numerics support) and the method's name read.
pub fn options(flags: &SolveFlags, unknown: Option<String>) -> Result<SolveOptions, CliError> {
    let method = flags
        .method
        .as_deref()
        .map(str::parse::<Method>)
        .transpose()
        .map_err(CliError::Invalid)?;
    let opts = SolveOptions {
        tol: flags.tol,
        max_level: Some(flags.max_level),
        method,
        max_memory: flags.max_memory,
        unknown,
        field_tol: flags.field_tol,
        ..SolveOptions::default()
    };
    opts.check().map_err(crate::api::Error::into_cli)?;
    Ok(opts)
}

/// `--csv` and `--plot` must not overwrite an input.
fn check_outputs(flags: &SolveFlags, inputs: &[&Path]) -> Result<(), CliError> {
    for path in [&flags.csv, &flags.plot].into_iter().flatten() {
        check_writable(path, inputs)?;
    }
    Ok(())
}

/// Prints `r` as `flags` ask (text or JSON, CSV, plot, warnings on
/// standard error). A result that did not reach its tolerance is printed,
/// marked, and ends in [`CliError::NotConverged`] (exit 4).
pub fn print(
    r: &Report,
    flags: &SolveFlags,
    inputs: &[&Path],
    w: &mut dyn Write,
) -> Result<(), CliError> {
    if let Some(path) = &flags.csv {
        write_file(path, r.csv().as_bytes(), inputs, "")?;
    }
    if let Some(path) = &flags.plot {
        let svg = r.svg().map_err(|reason| CliError::Write {
            path: path.display().to_string(),
            reason,
        })?;
        write_file(path, svg.as_bytes(), inputs, "")?;
    }
    if flags.json {
        super::output::write_json(w, &r.to_json())?;
    } else {
        r.write_text(w)?;
    }
    for warning in &r.warnings {
        super::output::note(&format!("warning: {warning}"));
    }
    converged(r)
}

/// `Ok` if `r` reached its tolerance, else [`CliError::NotConverged`].
pub fn converged(r: &Report) -> Result<(), CliError> {
    if r.converged {
        Ok(())
    } else {
        Err(CliError::NotConverged(r.not_converged_message()))
    }
}
