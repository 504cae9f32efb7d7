//! The `run` command: performs every directive of a file in order (Smith
//! forms, checks of claimed decompositions, and the reduction for each
//! `solve for`) and prints the results as
//! text, LaTeX or one JSON object.

use super::OutputArgs;
use super::error::CliError;
use super::reduce::{print_reduction, to_json};
use super::render;
use super::smith::{check, load, principal, print_report, report};
use crate::lang::Directive;
use crate::reduce::reduce;
use serde_json::json;
use std::io::Write;
use std::path::PathBuf;

/// What `run` says about `solve for` beyond the algebra.
pub const NUMERICS_NOTE: &str = "the numerical solve of language files is not wired into `run` yet; only the algebraic reduction is shown";

/// `lambdamat run FILE`.
pub fn run(file: &PathBuf, out: &OutputArgs, w: &mut dyn Write) -> Result<(), CliError> {
    let p = load(file)?;
    let principal = principal(&p, None)?;
    let mut results = Vec::new();
    let mut first = true;
    for d in &p.directives {
        let sep = |w: &mut dyn Write, first: &mut bool| -> Result<(), CliError> {
            if !*first && !out.json {
                writeln!(w, "\n{}\n", "─".repeat(60))?;
            }
            *first = false;
            Ok(())
        };
        match d {
            Directive::Smith { matrix } => {
                let r = report(&p, *matrix, principal, out.latex)?;
                if out.json {
                    results.push(json!({"kind": "smith", "result": r}));
                } else {
                    sep(w, &mut first)?;
                    print_report(&r, out, w)?;
                }
            }
            Directive::CheckSmith { matrix, u, d, v } => {
                let c = check(&p, [*matrix, *u, *d, *v], principal);
                if out.json {
                    results.push(json!({"kind": "check", "result": c}));
                } else {
                    sep(w, &mut first)?;
                    write!(w, "{}", render::check_text(&c))?;
                }
            }
            Directive::Solve { unknown } => {
                let r = reduce(&p, *unknown)?;
                if out.json {
                    results.push(json!({
                        "kind": "reduce",
                        "result": to_json(&r),
                        "numerics": NUMERICS_NOTE,
                    }));
                } else {
                    sep(w, &mut first)?;
                    print_reduction(&r, out, w)?;
                    if out.latex {
                        writeln!(w, "% {NUMERICS_NOTE}")?;
                    } else {
                        writeln!(w, "\nnote: {NUMERICS_NOTE}")?;
                    }
                }
            }
        }
    }
    if out.json {
        let v = json!({"file": file.display().to_string(), "results": results});
        writeln!(
            w,
            "{}",
            serde_json::to_string_pretty(&v).map_err(|e| CliError::Invalid(e.to_string()))?
        )?;
    } else if first {
        writeln!(
            w,
            "{}: no directives (add `smith A`, `check smith A with U, D, V`, …)",
            file.display()
        )?;
    }
    Ok(())
}
