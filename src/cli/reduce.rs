//! The `reduce` command and the reduction part of `run`: prints what
//! [`crate::api::Problem::reduce`] returns, through the printer in
//! [`crate::report::reduction`].

use super::error::CliError;
use super::{OutputArgs, ReduceArgs};
use crate::reduce::Reduction;
use crate::report::reduction::{latex, text, to_json};
use std::io::Write;

/// `lambdamat reduce FILE [--for u] [--json] [--latex]`: prints what
/// [`crate::api::Problem::reduce`] returns.
pub fn reduce_command(a: &ReduceArgs, w: &mut dyn Write) -> Result<(), CliError> {
    let (text, name) = crate::cli::read_source(&a.file)?;
    let r = crate::api::Problem::with_sets(text, name, crate::cli::overrides().to_vec())
        .and_then(|p| p.reduce(a.unknown.as_deref()))
        .map_err(crate::api::Error::into_cli)?;
    if a.out.json {
        writeln!(w, "{}", r.to_json())?;
    } else if a.out.latex {
        write!(w, "{}", r.latex())?;
    } else {
        write!(w, "{}", r.text())?;
    }
    Ok(())
}

/// Prints a reduction in the requested form.
pub fn print_reduction(r: &Reduction, out: &OutputArgs, w: &mut dyn Write) -> Result<(), CliError> {
    if out.json {
        let v = to_json(r);
        crate::cli::output::write_json(w, &v)?;
    } else if out.latex {
        write!(w, "{}", latex(r))?;
    } else {
        write!(w, "{}", text(r))?;
    }
    Ok(())
}

