//! The `codegen` command: writes the Rust solver that
//! [`crate::api::Problem::codegen`] generates, to a file or standard output. It owns the
//! command's arguments and messages only.
use std::io::Write;

use super::CodegenArgs;
use super::error::CliError;
use super::output::{check_writable, write_file};
use super::read_source;
use crate::api::Problem;

/// `lambdamat codegen FILE [--for u] [-o solver.rs]`: writes what
/// [`crate::api::Problem::codegen`] returns.
pub fn codegen_command(a: &CodegenArgs, w: &mut dyn Write) -> Result<(), CliError> {
    if let Some(path) = &a.output {
        check_writable(path, &[a.file.as_path()])?;
    }
    let (text, name) = read_source(&a.file)?;
    let code = Problem::with_sets(text, name, super::overrides().to_vec())
        .and_then(|p| p.codegen(a.unknown.as_deref()))
        .map_err(crate::api::Error::into_cli)?;
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
