//! The `solve` command: parses the file, asks [`crate::plan`] to solve its
//! system and prints the answer as text or one JSON object, optionally
//! with a CSV table and an SVG plot (plotters) of the unknowns. The same
//! report is the `main` of solvers written by `lambdamat codegen`
//! ([`solver_main`]). It does no numerics itself.
use std::io::Write;
use std::path::Path;

use plotters::prelude::*;
use serde_json::{Map, Value, json};

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

/// The highest refinement level `--max-level` accepts: beyond it the
/// geometric grading makes panels too small for the quadrature rules.
pub const MAX_LEVEL: usize = 14;

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

/// The flags of a generated solver (the `solve` flags without a file).
#[derive(clap::Parser, Debug)]
#[command(about = "A solver written by `lambdamat codegen`: solves its system and prints the report of `lambdamat solve`.", long_about = None)]
#[command(after_help = super::AFTER_HELP)]
pub(super) struct SolverCli {
    #[command(flatten)]
    pub(super) flags: SolveFlags,
}

/// The `main` of a solver written by `lambdamat codegen`: parses the
/// `solve` flags, builds the system, solves and prints; returns the exit
/// code (0 ok, 1 usage, 2 invalid system, 3 failed computation).
pub fn solver_main(system: fn() -> Result<CompiledSystem, PlanError>) -> i32 {
    let cli = match super::parse_args::<SolverCli>() {
        Ok(c) => c,
        Err(code) => return code,
    };
    let mut stdout = super::output::Stdout::new();
    let result = system()
        .map_err(CliError::from)
        .and_then(|sys| solve_and_report(&sys, &cli.flags, &[], &mut stdout));
    let _ = stdout.flush();
    super::exit_code(result)
}

/// The JSON object: `method`, `unknowns`, `outputs`, `error_estimate`,
/// `commutator_defects` and a few diagnostics.
pub fn to_json(r: &SolveReport) -> Value {
    let mut unknowns = Map::new();
    for u in &r.unknowns {
        unknowns.insert(
            u.name.clone(),
            json!({"x": u.x, "values": u.values, "weight": u.weight}),
        );
    }
    let mut outputs = Map::new();
    for (name, v) in &r.outputs {
        outputs.insert(name.clone(), json!(v));
    }
    json!({
        "method": r.method,
        "model": r.model,
        "target": r.target,
        "unknowns": unknowns,
        "outputs": outputs,
        "error_estimate": r.error_estimate,
        "converged": r.converged,
        "level": r.level,
        "dim": r.dim,
        "cond": r.cond,
        "commutator_defects": r.commutator_defects,
        "warnings": r.warnings,
        "pivots": r.pivots.iter().map(|(e, u)| json!({"equation": e, "unknown": u})).collect::<Vec<_>>(),
    })
}

/// The text report.
pub fn write_text(r: &SolveReport, w: &mut dyn Write) -> Result<(), CliError> {
    let label = if r.model {
        " (a MODEL: operators treated as commuting)"
    } else {
        ""
    };
    writeln!(w, "method: {}{label}", r.method)?;
    writeln!(
        w,
        "level {}: {} coefficients per unknown on [{}, {}], condition ≈ {:.2e}",
        r.level, r.dim, r.domain.0, r.domain.1, r.cond
    )?;
    writeln!(
        w,
        "error estimate: {:.2e}{}",
        r.error_estimate,
        if r.converged { "" } else { " (not converged)" }
    )?;
    for (name, v) in &r.outputs {
        match v {
            Some(v) => writeln!(w, "output {name} = {v:.15}")?,
            None => writeln!(
                w,
                "output {name}: needs an unknown this method does not compute"
            )?,
        }
    }
    if !r.commutator_defects.is_empty() {
        writeln!(
            w,
            "commutator defects ‖KaKb f - KbKa f‖/‖KaKb f‖ (f = 1 + x; f = the system's {}):",
            r.target
        )?;
        let show = |v: Option<f64>| v.map_or("undefined".to_string(), |v| format!("{v:.3e}"));
        for d in &r.commutator_defects {
            writeln!(
                w,
                "  {} {}: {}; {}",
                d.pair[0],
                d.pair[1],
                show(d.defect),
                show(d.defect_on_solution)
            )?;
        }
    }
    for u in &r.unknowns {
        writeln!(w, "{} (weight {}):", u.name, u.weight)?;
        let step = (u.x.len() / 10).max(1);
        for (x, v) in u.x.iter().zip(&u.values).step_by(step) {
            writeln!(w, "  x = {x:<6} {v:.12}")?;
        }
    }
    Ok(())
}

/// The unknowns as CSV: `x` and one column per unknown.
fn csv(r: &SolveReport) -> String {
    let mut s = String::from("x");
    for u in &r.unknowns {
        s.push(',');
        s.push_str(&u.name);
    }
    s.push('\n');
    // The union of the unknowns' grids (weighted unknowns skip a singular end).
    let mut xs: Vec<f64> = r.unknowns.iter().flat_map(|u| u.x.clone()).collect();
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    for x in xs {
        s.push_str(&format!("{x}"));
        for u in &r.unknowns {
            s.push(',');
            if let Some(i) = u.x.iter().position(|&y| y == x) {
                s.push_str(&format!("{:e}", u.values[i]));
            }
        }
        s.push('\n');
    }
    s
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
