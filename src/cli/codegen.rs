//! The `codegen` command: parses the file and writes the Rust solver that
//! [`crate::codegen`] generates, to a file or standard output. It owns the
//! command's arguments and messages only.
use std::io::Write;

use super::CodegenArgs;
use super::error::CliError;
use super::smith::load;
use crate::codegen::{Provenance, solver_source};

/// `lambdamat codegen FILE [--for u] [-o solver.rs]`.
pub fn codegen_command(a: &CodegenArgs, w: &mut dyn Write) -> Result<(), CliError> {
    let prog = load(&a.file)?;
    // The generated text depends on the source and `--for` only, not on
    // where it is written, so regenerating is reproducible.
    let mut command = format!("lambdamat codegen {}", a.file.display());
    if let Some(u) = &a.unknown {
        command.push_str(&format!(" --for {u}"));
    }
    command.push_str(" -o FILE.rs");
    let from = Provenance {
        source: a.file.display().to_string(),
        command,
    };
    let code = solver_source(&prog, a.unknown.as_deref(), &from)?;
    match &a.output {
        Some(path) => {
            std::fs::write(path, &code).map_err(CliError::Output)?;
            eprintln!(
                "wrote {} ({} lines): build it as a binary of a crate that depends on lambdamat, or include it as a module",
                path.display(),
                code.lines().count()
            );
        }
        None => w.write_all(code.as_bytes())?,
    }
    Ok(())
}
