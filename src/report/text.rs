//! The text report of a [`Report`]: method, levels, convergence, every
//! number with its absolute estimate (`name = value ± estimate`), the
//! track-specific lines (commutator defects, notes, singular exponents)
//! and the unknowns on every tenth grid point.
use std::io::Write;

use serde_json::Value;

use super::Report;
use crate::plan::SplitReport;

impl Report {
    /// Writes the text report (what `lambdamat solve` prints).
    ///
    /// ```
    /// let p = lambdamat::Problem::from_source(
    ///     "unknown f on [0, 1]\noperator k = int(0..x) dt\nequation f + k f = 1\noutput F = int(0..1) f(x) dx",
    ///     "ex.lmx",
    /// )?;
    /// let s = p.solve(&lambdamat::SolveOptions::default())?;
    /// let mut out = Vec::new();
    /// s.write_text(&mut out).unwrap();
    /// assert!(String::from_utf8(out).unwrap().contains("F"));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn write_text(&self, w: &mut dyn Write) -> std::io::Result<()> {
        let model = self.extra.get("model").and_then(Value::as_bool) == Some(true);
        let label = if model {
            " (a MODEL: operators treated as commuting)"
        } else {
            ""
        };
        writeln!(w, "method: {}{label}", self.method)?;
        let dim = self.extra.get("dim").and_then(Value::as_u64).unwrap_or(0);
        let cond = self
            .extra
            .get("cond")
            .and_then(Value::as_f64)
            .unwrap_or(f64::NAN);
        let size = match self.extra.get("domain").and_then(Value::as_array) {
            Some(d) if d.len() == 2 => format!(
                "{dim} coefficients per unknown on [{}, {}]",
                d[0].as_f64().unwrap_or(f64::NAN),
                d[1].as_f64().unwrap_or(f64::NAN)
            ),
            _ => format!("{dim} coefficients"),
        };
        writeln!(w, "levels: {}, {size}, condition ≈ {cond:.2e}", self.levels)?;
        writeln!(
            w,
            "tolerance {:.1e}·max(1, |value|) (estimates ± are absolute): {}",
            self.tol,
            if self.converged {
                "reached"
            } else {
                "NOT reached (not converged)"
            }
        )?;
        for (kind, map) in [
            ("scalar", &self.scalars),
            ("output", &self.outputs),
            ("coefficient", &self.coefficients),
        ] {
            for (name, v) in map {
                writeln!(w, "{kind} {name} = {v:.15} ± {}", self.shown(name))?;
            }
        }
        for line in self
            .extra
            .get("notes")
            .and_then(Value::as_array)
            .into_iter()
            .flatten()
            .filter_map(Value::as_str)
        {
            writeln!(w, "{line}")?;
        }
        self.write_defects(w)?;
        if let Some(list) = self
            .extra
            .get("singular_exponents")
            .and_then(Value::as_array)
        {
            for t in list {
                if let Some([u, at, beta]) = t.as_array().map(Vec::as_slice) {
                    let u = u.as_str().unwrap_or("?");
                    writeln!(w, "singular term of {u} at {at}: measured exponent -{beta}")?;
                }
            }
        }
        for (name, u) in &self.unknowns {
            writeln!(
                w,
                "{name} (weight {}), error estimate ≤ {}:",
                u.weight,
                show_estimate(u.error_estimate)
            )?;
            let step = (u.x.len() / 10).max(1);
            for (x, v) in u.x.iter().zip(&u.values).step_by(step) {
                writeln!(w, "  x = {x:<6} {v:.12}")?;
            }
        }
        Ok(())
    }

    /// A quantity's estimate as printed.
    fn shown(&self, name: &str) -> String {
        self.estimate(name).map_or("?".to_string(), show_estimate)
    }

    /// The commutator defects of the commutative model, on `1 + x` and on
    /// its solution.
    fn write_defects(&self, w: &mut dyn Write) -> std::io::Result<()> {
        let Some(list) = self
            .extra
            .get("commutator_defects")
            .and_then(Value::as_array)
            .filter(|l| !l.is_empty())
        else {
            return Ok(());
        };
        let target = self
            .extra
            .get("target")
            .and_then(Value::as_str)
            .unwrap_or("target");
        writeln!(
            w,
            "commutator defects ‖KaKb f - KbKa f‖/‖KaKb f‖ (f = 1 + x; f = the model's {target}):"
        )?;
        let show = |v: Option<&Value>| {
            v.and_then(Value::as_f64)
                .map_or("undefined".to_string(), |v| format!("{v:.3e}"))
        };
        for d in list {
            let pair = d.get("pair").and_then(Value::as_array);
            let name = |i: usize| {
                pair.and_then(|p| p.get(i))
                    .and_then(Value::as_str)
                    .unwrap_or("?")
                    .to_string()
            };
            writeln!(
                w,
                "  {} {}: {}; {}",
                name(0),
                name(1),
                show(d.get("defect")),
                show(d.get("defect_on_solution"))
            )?;
        }
        Ok(())
    }
}

/// An estimate as printed: `1.2e-11`, or `∞ (one level)`.
fn show_estimate(e: f64) -> String {
    if e.is_finite() {
        format!("{e:.1e}")
    } else {
        "∞ (no estimate)".to_string()
    }
}

/// The lines a split-domain solve adds after its numbers: that its scalar
/// was bounded at an end of its range rather than resolved, and that the
/// mesh was graded toward ends no declaration names.
pub fn split_notes(r: &SplitReport) -> Vec<String> {
    let mut out = Vec::new();
    if let Some(e) = &r.end_answer {
        out.push(format!(
            "scalar {} is bounded, not resolved: the root of its condition lies within {:.1e} of the end {} (it is given as the middle of that gap); the outputs are those at {} = {:.6e}, each with its variation over the gap in its estimate",
            e.scalar, e.distance, e.end_value, e.scalar, e.at
        ));
        if let Some(line) = estimate_line(e) {
            out.push(line);
        }
    }
    if let Some(c) = r.end_check.as_ref().filter(|c| c.graded) {
        out.push(end_grading_line(c));
    }
    out
}

/// The lines saying what each logarithmic declaration
/// (`singular p at 0 ~ ln(x)`) makes of its point.
pub fn log_end_notes(sol: &crate::plan::SplitSolution) -> Vec<String> {
    let p = &sol.problem;
    p.contact
        .singulars
        .iter()
        .filter(|s| matches!(s.kind, crate::plan::split_input::SplitKind::Log))
        .map(|s| {
            let u = &p.sys.unknowns[s.unknown];
            let z = s.at.eval(&sol.discrete.vars, 0.0);
            format!(
                "{u} is declared logarithmic at {z}: the mesh is graded toward it as toward any declared point, no weight is factored out, and {u}({z}) (infinite) is left out of the values and their estimate"
            )
        })
        .collect()
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
    let z = c.ends.first().copied().unwrap_or(f64::NAN);
    let why = match c.worst() {
        Some(w) => format!(
            ": on level {} grading it moved {} by {:.1e}, {} its estimate {:.1e} (an undeclared singular behaviour there: a power `|x - {z}|^e` can be declared with `singular … at {z}`, a logarithmic one, such as the cone's pressure at its tip, with `singular … at {z} ~ ln(abs(x - {z}))`)",
            c.level,
            w.name,
            w.change,
            if c.share < 1.0 {
                format!("more than {} of", c.share)
            } else {
                "beyond".to_string()
            },
            w.estimate,
        ),
        None => String::new(),
    };
    let s = if c.ends.len() > 1 { "s" } else { "" };
    format!("mesh graded toward the end{s} {ends} of the interval automatically{why}")
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
