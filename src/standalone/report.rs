//! The reports of a numerical solve as text, JSON and CSV: the one printer
//! of [`SolveReport`] and [`SplitReport`], shared by `lambdamat solve`,
//! `lambdamat run` and the solvers `lambdamat codegen` writes (which build
//! without the command line: this module needs neither clap nor plotters).
use std::io::Write;

use serde_json::{Map, Value, json};

use crate::plan::split_solve::Estimate;
use crate::plan::{SolveReport, SplitReport};

/// The JSON object: `method`, `unknowns`, `outputs`, `error_estimate`,
/// `commutator_defects` and a few diagnostics.
pub fn solve_json(r: &SolveReport) -> Value {
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
pub fn solve_text(r: &SolveReport, w: &mut dyn Write) -> std::io::Result<()> {
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
pub fn csv(r: &SolveReport) -> String {
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

fn values(list: &[Estimate]) -> Map<String, Value> {
    list.iter()
        .map(|e| (e.name.clone(), json!(e.value)))
        .collect()
}

/// The JSON object: `scalars`, `outputs`, `coefficients` (name → value),
/// `error_estimates` (name → estimate) and diagnostics.
pub fn split_json(r: &SplitReport) -> Value {
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
pub fn split_text(r: &SplitReport, w: &mut dyn Write) -> std::io::Result<()> {
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
