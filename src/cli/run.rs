//! The `run` command: performs every directive of a file in order (Smith
//! forms, checks of claimed decompositions, and for each `solve for` the
//! one derivation of that unknown, printed (eliminant, ordered elimination,
//! or the single equations per subinterval of a split-domain file) and then
//! executed by the numerical solve for that unknown with the defaults of
//! `lambdamat solve`, through [`crate::api::Problem::solve`]) and prints
//! the results as text, LaTeX or one JSON object.

use super::OutputArgs;
use super::error::CliError;
use super::reduce::print_reduction;
use crate::report::reduction::to_json;
use crate::report::smith as render;
use super::smith::{check, load_problem, principal, print_report, report};
use super::solve;
use crate::lang::Directive;
use crate::reduce::{derive, reduce_with};
use serde_json::json;
use std::io::Write;
use std::path::Path;

/// `lambdamat run FILE`.
pub fn run(
    file: &Path,
    out: &OutputArgs,
    max_memory: Option<u64>,
    w: &mut dyn Write,
) -> Result<(), CliError> {
    let problem = load_problem(file)?;
    let p = problem.program();
    let principal = principal(p, None)?;
    let mut results = Vec::new();
    let mut not_converged: Option<CliError> = None;
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
                let r = report(p, *matrix, principal, out.latex)?;
                if out.json {
                    results.push(json!({"kind": "smith", "result": r}));
                } else {
                    sep(w, &mut first)?;
                    print_report(&r, out, w)?;
                }
            }
            Directive::CheckSmith { matrix, u, d, v } => {
                let c = check(p, [*matrix, *u, *d, *v], principal);
                if out.json {
                    results.push(json!({"kind": "check", "result": c}));
                } else {
                    sep(w, &mut first)?;
                    write!(w, "{}", render::check_text(&c))?;
                }
            }
            Directive::Solve { unknown } => {
                // One derivation per target: printed here, executed by the
                // solve below.
                sep(w, &mut first)?;
                if p.contact.is_split() {
                    let list = crate::report::reduction::split_reductions(p, *unknown)?;
                    if out.json {
                        results.push(
                            json!({"kind": "reduce", "result": crate::report::reduction::split_json(&list)}),
                        );
                    } else {
                        write!(w, "{}", crate::report::reduction::split_text(&list, out.latex))?;
                    }
                } else {
                    let red = reduce_with(p, &derive(p, *unknown)?)?;
                    if out.json {
                        results.push(json!({"kind": "reduce", "result": to_json(&red)}));
                    } else {
                        print_reduction(&red, out, w)?;
                    }
                }
                // Symbols declared with `var` are abstract: no kernels, no numerics.
                let abstract_symbols: Vec<&str> = (0..p.symbols.len())
                    .filter(|&i| p.operator(i).is_none())
                    .map(|i| p.symbols[i].as_str())
                    .collect();
                if !p.contact.is_split() && !abstract_symbols.is_empty() {
                    let note = format!(
                        "numerical solve skipped: {} ha{} no operator definition (declared with `var`)",
                        abstract_symbols.join(", "),
                        if abstract_symbols.len() == 1 {
                            "s"
                        } else {
                            "ve"
                        }
                    );
                    if out.json {
                        results.push(json!({"kind": "solve", "skipped": note}));
                    } else {
                        writeln!(w, "\nnote: {note}")?;
                    }
                    continue;
                }
                let opts = crate::api::SolveOptions {
                    unknown: Some(p.unknowns[*unknown].clone()),
                    max_memory,
                    ..crate::api::SolveOptions::default()
                };
                let r = problem
                    .solve(&opts)
                    .map_err(crate::api::Error::into_cli)?;
                if out.json {
                    results.push(json!({"kind": "solve", "result": r.to_json()}));
                } else {
                    sep(w, &mut first)?;
                    r.write_text(w)?;
                }
                for warning in &r.warnings {
                    super::output::note(&format!("warning: {warning}"));
                }
                if let Err(e) = solve::converged(&r) {
                    not_converged.get_or_insert(e);
                }
            }
        }
    }
    if out.json {
        let v = json!({"file": file.display().to_string(), "results": results});
        super::output::write_json(w, &v)?;
    } else if first {
        writeln!(
            w,
            "{}: no directives (add `smith A`, `check smith A with U, D, V`, …)",
            file.display()
        )?;
    }
    not_converged.map_or(Ok(()), Err)
}
