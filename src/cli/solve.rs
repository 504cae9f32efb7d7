//! The `solve` command: parses the file, asks [`crate::plan`] to solve its
//! system and prints the answer as text or one JSON object, optionally
//! with a CSV table and an SVG plot (plotters) of the unknowns. The same
//! report ([`crate::standalone::report`]) is printed by the solvers
//! `lambdamat codegen` writes. It does no numerics itself.
use std::io::Write;
use std::path::Path;

use plotters::prelude::*;

use super::error::CliError;
use super::output::{check_writable, write_file};
use super::smith::{Source, load_with_source};
use super::{SolveArgs, SolveFlags};
use crate::plan::{CompiledSystem, Method, PlanError, SolveOptions, SolveReport, solve_system};

/// `lambdamat solve FILE …`.
pub fn solve_command(a: &SolveArgs, w: &mut dyn Write) -> Result<(), CliError> {
    check_flags(&a.flags)?;
    let (prog, src) = load_with_source(&a.file)?;
    if prog.contact.is_split() {
        return super::split::solve_split_and_report(&prog, &a.flags, w);
    }
    let inputs = [a.file.as_path()];
    let sys =
        CompiledSystem::from_program(&prog, a.unknown.as_deref()).map_err(|e| located(e, &src))?;
    solve_and_report(&sys, &a.flags, &inputs, w).map_err(|e| match e {
        CliError::Plan(p) => located(p, &src),
        other => other,
    })
}

pub use crate::standalone::MAX_LEVEL;
pub use crate::standalone::report::{csv, solve_json as to_json, solve_text as write_text};

/// Checks the flags before any work: a finite positive tolerance, a
/// refinement level the numerics support.
pub fn check_flags(flags: &SolveFlags) -> Result<(), CliError> {
    if !(flags.tol > 0.0 && flags.tol.is_finite()) {
        return Err(CliError::Invalid(format!(
            "--tol {}: the tolerance must be a finite number > 0, e.g. 1e-10",
            flags.tol
        )));
    }
    if flags.max_level == 0 || flags.max_level > MAX_LEVEL {
        return Err(CliError::Invalid(format!(
            "--max-level {}: must be between 1 and {MAX_LEVEL}",
            flags.max_level
        )));
    }
    Ok(())
}

/// Solves `sys` as `flags` ask and prints the report (text or JSON, CSV,
/// plot, warnings on standard error).
///
/// A result that did not reach its tolerance is printed, marked, and ends
/// in [`CliError::NotConverged`] (exit 4). `inputs` are the files the
/// system was read from, which `--csv` and `--plot` must not overwrite.
pub fn solve_and_report(
    sys: &CompiledSystem,
    flags: &SolveFlags,
    inputs: &[&Path],
    w: &mut dyn Write,
) -> Result<(), CliError> {
    check_flags(flags)?;
    for path in [&flags.csv, &flags.plot].into_iter().flatten() {
        check_writable(path, inputs)?;
    }
    let method: Method = flags.method.parse().map_err(CliError::Invalid)?;
    let opts = SolveOptions {
        method,
        tol: flags.tol,
        max_level: flags.max_level,
        ..SolveOptions::default()
    };
    let r = solve_system(sys, &opts)?;
    if let Some(path) = &flags.csv {
        write_file(path, csv(&r).as_bytes(), inputs, "")?;
    }
    if let Some(path) = &flags.plot {
        write_file(path, svg(&r, path)?.as_bytes(), inputs, "")?;
    }
    if flags.json {
        super::output::write_json(w, &to_json(&r))?;
    } else {
        write_text(&r, w)?;
    }
    for warning in &r.warnings {
        super::output::note(&format!("warning: {warning}"));
    }
    converged(&r)
}

/// `Ok` if `r` reached its tolerance, else [`CliError::NotConverged`].
pub fn converged(r: &SolveReport) -> Result<(), CliError> {
    if r.converged {
        Ok(())
    } else {
        Err(CliError::NotConverged(format!(
            "the error estimate {:.1e} (level {}) is above the tolerance; the result above is marked \"not converged\"",
            r.error_estimate, r.level
        )))
    }
}

/// A plan error pointed at its place in `src` (a kernel, a right side),
/// when it has one.
pub fn located(e: PlanError, src: &Source) -> CliError {
    match super::locate::locate_plan_error(&e, &src.text, &src.name) {
        Some(errs) => CliError::Lang(Box::new(errs)),
        None => CliError::Plan(e),
    }
}

/// The unknowns as an SVG plot (written by the caller to `path`).
fn svg(r: &SolveReport, path: &Path) -> Result<String, CliError> {
    let err = |e: String| CliError::Write {
        path: path.display().to_string(),
        reason: format!("cannot plot: {e}"),
    };
    let mut out = String::new();
    let finite = |v: &f64| v.is_finite();
    let ys: Vec<f64> = r
        .unknowns
        .iter()
        .flat_map(|u| u.values.iter().copied().filter(finite))
        .collect();
    let (mut y0, mut y1) = ys
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    if !(y0.is_finite() && y1.is_finite()) {
        return Err(err("no finite values".into()));
    }
    if y1 - y0 < 1e-12 {
        y0 -= 0.5;
        y1 += 0.5;
    }
    let pad = 0.05 * (y1 - y0);
    {
        let root = SVGBackend::with_string(&mut out, (800, 500)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(e.to_string()))?;
        let mut chart = ChartBuilder::on(&root)
            .caption(
                format!("lambdamat solve ({})", r.method),
                ("sans-serif", 20),
            )
            .margin(10)
            .x_label_area_size(30)
            .y_label_area_size(50)
            .build_cartesian_2d(r.domain.0..r.domain.1, (y0 - pad)..(y1 + pad))
            .map_err(|e| err(e.to_string()))?;
        chart
            .configure_mesh()
            .x_desc("x")
            .draw()
            .map_err(|e| err(e.to_string()))?;
        for (k, u) in r.unknowns.iter().enumerate() {
            let color = Palette99::pick(k).to_rgba();
            let pts: Vec<(f64, f64)> =
                u.x.iter()
                    .copied()
                    .zip(u.values.iter().copied())
                    .filter(|(_, v)| v.is_finite())
                    .collect();
            chart
                .draw_series(LineSeries::new(pts, color))
                .map_err(|e| err(e.to_string()))?
                .label(u.name.clone())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color));
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()
            .map_err(|e| err(e.to_string()))?;
        root.present().map_err(|e| err(e.to_string()))?;
    }
    Ok(out)
}
