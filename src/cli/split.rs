//! The report of a split-domain (contact) problem for `lambdamat solve`:
//! scalars, outputs and singular coefficients, each with its error
//! estimate, as text or one JSON object (`"scalars": {"c": …}` beside
//! `"outputs"`). An answer that did not reach its tolerance is printed and
//! then refused with an error (non-zero exit). It does no numerics itself.
use std::io::Write;

use super::SolveFlags;
use super::error::CliError;
use crate::plan::{SplitInput, SplitOptions, SplitReport, solve_split_input};
pub use crate::standalone::report::{
    end_grading_line, estimate_line, split_json as to_json, split_text as write_text,
};
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
