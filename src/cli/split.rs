//! The report of a split-domain (contact) problem for `lambdamat solve`:
//! scalars, outputs and singular coefficients, each with its error
//! estimate, as text or one JSON object (`"scalars": {"c": …}` beside
//! `"outputs"`). An answer that did not reach its tolerance is printed and
//! then refused with an error (non-zero exit). It does no numerics itself.
use std::io::Write;

use serde_json::{Map, Value, json};

use super::SolveFlags;
use super::error::CliError;
use crate::plan::split_solve::Estimate;
use crate::plan::{PlanError, SplitInput, SplitOptions, SplitReport, solve_split_input};
use crate::system::Program;

/// Solves `prog` and prints the report as `flags` ask.
pub fn solve_split_and_report(
    prog: &Program,
    flags: &SolveFlags,
    w: &mut dyn Write,
) -> Result<(), CliError> {
    check_method(flags)?;
    report(SplitInput::from_program(prog)?, flags, w)
}

fn check_method(flags: &SolveFlags) -> Result<(), CliError> {
    if flags.method == "commutative" {
        return Err(CliError::Invalid(
            "--method commutative: a split-domain file is solved as one collocation system on all its subintervals; the seed's single equations per subinterval are shown by `lambdamat reduce`".into(),
        ));
    }
    if let Some(flag) = [("--csv", &flags.csv), ("--plot", &flags.plot)]
        .into_iter()
        .find_map(|(name, path)| path.as_ref().map(|_| name))
    {
        return Err(CliError::Invalid(format!(
            "{flag}: a split-domain file's fields are not tabulated by `solve` (for the Hertz problem, `lambdamat hertz --csv FILE` or `--plot FILE.svg` writes them)"
        )));
    }
    Ok(())
}

/// Solves `input` and prints the report as `flags` ask.
fn report(input: SplitInput, flags: &SolveFlags, w: &mut dyn Write) -> Result<(), CliError> {
    let opts = SplitOptions {
        tol: flags.tol,
        max_level: flags.max_level,
    };
    let r = solve_split_input(input, &opts)?;
    if flags.json {
        super::output::write_json(w, &to_json(&r))?;
    } else {
        write_text(&r, w)?;
    }
    require_converged(&r)
}

/// The `main` of a solver `lambdamat codegen` wrote for a split-domain
/// file: parses the `solve` flags, builds the input, solves and prints the
/// report of `lambdamat solve`; returns the exit code.
pub fn split_solver_main(input: fn() -> Result<SplitInput, PlanError>) -> i32 {
    let cli = match super::parse_args::<super::solve::SolverCli>() {
        Ok(c) => c,
        Err(code) => return code,
    };
    let mut stdout = super::output::Stdout::new();
    let result = super::solve::check_flags(&cli.flags)
        .and_then(|()| check_method(&cli.flags))
        .and_then(|()| input().map_err(CliError::from))
        .and_then(|inp| report(inp, &cli.flags, &mut stdout));
    let _ = stdout.flush();
    super::exit_code(result)
}

/// An error unless `r` reached its tolerance (the report is printed first,
/// so a result that did not converge never exits 0).
pub fn require_converged(r: &SplitReport) -> Result<(), CliError> {
    if !r.converged {
        return Err(CliError::NotConverged(format!(
            "split-domain solve: the error estimate {:.2e} (level {}) is above the tolerance {:.1e}",
            r.error_estimate,
            r.levels.saturating_sub(1),
            r.tol
        )));
    }
    Ok(())
}

fn values(list: &[Estimate]) -> Map<String, Value> {
    list.iter()
        .map(|e| (e.name.clone(), json!(e.value)))
        .collect()
}

/// The JSON object: `scalars`, `outputs`, `coefficients` (name → value),
/// `error_estimates` (name → estimate) and diagnostics.
pub fn to_json(r: &SplitReport) -> Value {
    let errors: Map<String, Value> = r
        .scalars
        .iter()
        .chain(&r.outputs)
        .chain(&r.coefficients)
        .map(|e| (e.name.clone(), json!(e.error)))
        .collect();
    json!({
        "method": "split-domain collocation",
        "scalars": values(&r.scalars),
        "outputs": values(&r.outputs),
        "coefficients": values(&r.coefficients),
        "error_estimates": errors,
        "error_estimate": r.error_estimate,
        "converged": r.converged,
        "tol": r.tol,
        "levels": r.levels,
        "dim": r.dim,
        "cond": r.cond,
        "singular_exponents": r.singular_exponents,
        "end_answer": r.end_answer,
        "end_check": r.end_check,
    })
}

/// The line saying that the mesh was graded toward ends no `singular`
/// declaration names, and why.
pub fn end_grading_line(c: &crate::plan::split_ends::EndCheck) -> String {
    let ends = c
        .ends
        .iter()
        .map(|z| z.to_string())
        .collect::<Vec<_>>()
        .join(" and ");
    let why = match c.worst() {
        Some(w) => format!(
            ": on level {} grading it moved {} by {:.1e}, {} its estimate {:.1e} (an undeclared singular behaviour there; declaring it with `singular … at {}` says so in the file)",
            c.level,
            w.name,
            w.change,
            if c.share < 1.0 {
                format!("more than {} of", c.share)
            } else {
                "beyond".to_string()
            },
            w.estimate,
            c.ends.first().copied().unwrap_or(f64::NAN)
        ),
        None => String::new(),
    };
    let s = if c.ends.len() > 1 { "s" } else { "" };
    format!("mesh graded toward the end{s} {ends} of the interval automatically{why}")
}

/// The text report.
pub fn write_text(r: &SplitReport, w: &mut dyn Write) -> Result<(), CliError> {
    writeln!(w, "method: split-domain collocation")?;
    writeln!(
        w,
        "level {}: {} coefficients, condition ≈ {:.2e}",
        r.levels - 1,
        r.dim,
        r.cond
    )?;
    writeln!(
        w,
        "error estimate: {:.2e}{}",
        r.error_estimate,
        if r.converged { "" } else { " (not converged)" }
    )?;
    if let Some(e) = &r.end_answer {
        writeln!(
            w,
            "scalar {} is bounded, not resolved: the root of its condition lies within {:.1e} of the end {} (it is given as the middle of that gap); the outputs are those at {} = {:.6e}, each with its variation over the gap in its estimate",
            e.scalar, e.distance, e.end_value, e.scalar, e.at
        )?;
        if let Some(line) = estimate_line(e) {
            writeln!(w, "{line}")?;
        }
    }
    if let Some(c) = r.end_check.as_ref().filter(|c| c.graded) {
        writeln!(w, "{}", end_grading_line(c))?;
    }
    for (kind, list) in [
        ("scalar", &r.scalars),
        ("output", &r.outputs),
        ("coefficient", &r.coefficients),
    ] {
        for e in list {
            writeln!(w, "{kind} {} = {:.15} ± {:.1e}", e.name, e.value, e.error)?;
        }
    }
    for (u, at, beta) in &r.singular_exponents {
        writeln!(w, "singular term of {u} at {at}: measured exponent -{beta}")?;
    }
    Ok(())
}

/// What placed an end answer's root at its end, when the scalar has a
/// declared estimate there: the estimate alone (the condition's trend is
/// silent, and why), or both.
pub fn estimate_line(e: &crate::plan::split_end::EndAnswer) -> Option<String> {
    let v = e.by_estimate?;
    Some(match &e.trend_silent {
        Some(why) => format!(
            "the root is placed at this end by the declared estimate {} ~ {v:.3e} alone: the condition keeps one sign over the resolved range, but its trend does not show the root ({why})",
            e.scalar
        ),
        None => format!(
            "the declared estimate {} ~ {v:.3e} agrees: the condition's trend shows the root beyond this end too",
            e.scalar
        ),
    })
}
