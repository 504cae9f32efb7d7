//! The `codegen` command: parses the file and writes the Rust solver that
//! [`crate::codegen`] generates, to a file or standard output. It owns the
//! command's arguments and messages only.
use std::io::Write;

use super::CodegenArgs;
use super::error::CliError;
use super::output::{check_writable, write_file};
use super::smith::load_with_source;
use super::solve::located;
use crate::codegen::{Provenance, solver_source};
use crate::plan::split::SplitProblem;
use crate::plan::{CompiledSystem, SolveOptions, SplitInput, solve_system};

/// `lambdamat codegen FILE [--for u] [-o solver.rs]`.
///
/// The system must pass the checks `lambdamat solve` makes on its input
/// (kernels, right sides finite at the collocation points): a short solve on
/// the first levels runs them, and only its input errors refuse the file
/// (a numerical failure there is the generated solver's business).
pub fn codegen_command(a: &CodegenArgs, w: &mut dyn Write) -> Result<(), CliError> {
    if let Some(path) = &a.output {
        check_writable(path, &[a.file.as_path()])?;
    }
    let (prog, src) = load_with_source(&a.file)?;
    // The generated text depends on the source and `--for` only, not on
    // where it is written, so regenerating is reproducible.
    let mut command = format!("lambdamat codegen {}", a.file.display());
    if let Some(u) = &a.unknown {
        command.push_str(&format!(" --for {u}"));
    }
    for (name, value) in super::overrides() {
        command.push_str(&format!(" --set {name}={value}"));
    }
    command.push_str(" -o FILE.rs");
    let from = Provenance {
        source: a.file.display().to_string(),
        command,
    };
    let code = solver_source(&prog, a.unknown.as_deref(), &from).map_err(|e| located(e, &src))?;
    if prog.contact.is_split() {
        // The split solver's input checks (intervals, scalars against
        // conditions, operators) run when its problem is made.
        SplitProblem::from_input(SplitInput::from_program(&prog).map_err(|e| located(e, &src))?)
            .map_err(|e| located(e, &src))?;
        return write_code(a, &code, w);
    }
    let sys =
        CompiledSystem::from_program(&prog, a.unknown.as_deref()).map_err(|e| located(e, &src))?;
    let quick = SolveOptions {
        max_level: 2,
        tol: 1.0,
        ..SolveOptions::default()
    };
    if let Err(e) = solve_system(&sys, &quick)
        && e.is_input_error()
    {
        return Err(located(e, &src));
    }
    write_code(a, &code, w)
}

fn write_code(a: &CodegenArgs, code: &str, w: &mut dyn Write) -> Result<(), CliError> {
    match &a.output {
        Some(path) => {
            let note = format!(
                "({} lines): build it as a binary of a crate that depends on lambdamat (default-features = false is enough), or include it as a module",
                code.lines().count()
            );
            write_file(path, code.as_bytes(), &[a.file.as_path()], &note)?;
        }
        None => w.write_all(code.as_bytes())?,
    }
    Ok(())
}
