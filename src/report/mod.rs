//! The one report of a numerical solve, and the one entry that produces it
//! for every file: [`solve`] takes a program (with or without breakpoints,
//! scalars, relations or singular declarations) and returns a [`Report`];
//! [`Report::to_json`], [`Report::write_text`], [`Report::csv`] and
//! [`Report::svg`] are the only places a solve's answer is formatted
//! (`lambdamat solve`, `run`, `hertz` and the solvers `lambdamat codegen`
//! writes all print through them). It owns the conversion of the solver's
//! own report ([`crate::plan::SplitReport`]) into this shape and the sampling of a split-domain solution's unknowns
//! on the output grid; it does no discretisation itself.
//!
//! **Estimates are absolute.** Every quantity (output, scalar, singular
//! coefficient, and each unknown at each grid point) carries an estimate
//! of `|computed − exact|` in its own units; an unknown's
//! `error_estimate` is its largest pointwise estimate on the grid.
//!
//! **The tolerance rule** (`--tol`): a solve has converged
//! when every estimate that drives refinement is within `tol·max(1,
//! |value|)`, i.e. absolute tolerance `tol` for quantities of size up to 1
//! and relative tolerance `tol` above (SciPy's `atol = rtol = tol`): the
//! scalars, outputs and singular coefficients, and each unknown's
//! pointwise estimates to the field tolerance (`--field-tol`).
//!
//! * [`text`]: the text report;
//! * [`svg`]: the plot of the unknowns.
//!
//! The printers of the exact results live here too: `smith` (matrices,
//! certificates, Smith and check reports as text and LaTeX) and
//! `reduction` (a reduction as text, LaTeX and JSON).

pub mod reduction;
pub mod smith;
#[cfg(feature = "cli")]
pub mod svg;
pub mod text;

use std::collections::BTreeMap;

use serde::Serialize;
use serde_json::{Map, Value, json};

use crate::plan::split_fields::LevelFields;
use crate::plan::{Method, PlanError, SplitInput, SplitOptions, SplitSolution};
use crate::system::Program;

/// Points of the output grid on which unknowns are reported.
pub const GRID_POINTS: usize = 101;

/// An unknown on the output grid.
///
/// ```
/// let p = lambdamat::Problem::from_source(
///     "unknown f on [0, 1]\noperator k = int(0..x) dt\nequation f + k f = 1\noutput F = int(0..1) f(x) dx",
///     "ex.lmx",
/// )?;
/// let s = p.solve(&lambdamat::SolveOptions::default())?;
/// let f = &s.unknowns["f"];
/// assert_eq!(f.x.len(), f.values.len());
/// // f = exp(-x)
/// assert!((f.values[0] - 1.0).abs() <= f.error_estimate + 1e-12);
/// # Ok::<(), lambdamat::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Field {
    /// Grid points (points where the unknown is unbounded are left out).
    pub x: Vec<f64>,
    /// Its values there.
    pub values: Vec<f64>,
    /// The behaviour its trial space was given: the weight the smooth part
    /// is multiplied by (`1` for none) and any exact singular terms.
    pub weight: String,
    /// Its largest absolute pointwise error estimate on the grid.
    pub error_estimate: f64,
}

/// What a numerical solve found, in one shape for every file.
///
/// ```
/// let p = lambdamat::Problem::from_source(
///     "unknown f on [0, 1]\noperator k = int(0..x) dt\nequation f + k f = 1\noutput F = int(0..1) f(x) dx",
///     "ex.lmx",
/// )?;
/// let s = p.solve(&lambdamat::SolveOptions::default())?;
/// assert!(s.converged);
/// assert!(s.error_estimates["F"] <= 1e-10);
/// assert!(s.warnings.is_empty());
/// # Ok::<(), lambdamat::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// `ordered`, `coupled`, `commutative`, or the split solver's method.
    pub method: String,
    /// Whether every estimate that drives refinement met the tolerance
    /// rule of this module.
    pub converged: bool,
    /// Refinement levels solved.
    pub levels: usize,
    /// The tolerance.
    pub tol: f64,
    /// The unknowns on the output grid.
    pub unknowns: BTreeMap<String, Field>,
    /// The outputs.
    pub outputs: BTreeMap<String, f64>,
    /// The unknown scalars (e.g. a stick radius `c`).
    pub scalars: BTreeMap<String, f64>,
    /// The coefficients of exact singular terms.
    pub coefficients: BTreeMap<String, f64>,
    /// Absolute estimates: one per output, scalar, coefficient and unknown
    /// (its largest pointwise estimate).
    pub error_estimates: BTreeMap<String, f64>,
    /// Warnings (printed on standard error by the CLI).
    pub warnings: Vec<String>,
    /// The solver's diagnostics: `dim`, `cond`, `target`, `unique`,
    /// `singular_exponents`, `end_answer`, `end_check`, `notes` (lines
    /// the text report shows after the numbers, e.g. that the scalar is
    /// bounded at an end of its range); with `--method ordered` or
    /// `commutative` also `pivots`, and for the commutative model `model`
    /// and `commutator_defects`.
    pub extra: Map<String, Value>,
}

/// How to solve.
#[derive(Debug, Clone)]
pub struct SolveSettings {
    /// The unknown the eliminations solve for (default: the file's `solve
    /// for`, else the first unknown).
    pub unknown: Option<String>,
    /// The tolerance (see the module's rule).
    pub tol: f64,
    /// The highest refinement level tried (levels are numbered from 0).
    pub max_level: usize,
    /// The method; `None` is `coupled`.
    pub method: Option<Method>,
    /// Points of the output grid.
    pub grid: usize,
    /// Memory budget in bytes (`--max-memory`; `None`: the default of
    /// [`crate::numeric::budget`]).
    pub max_memory: Option<u64>,
    /// The unknowns' tolerance on a split domain (`--field-tol`,
    /// [`crate::plan::SplitOptions::field_tol`]); `None`: the larger of
    /// `tol` and `1e-6` ([`crate::plan::split_solve::default_field_tol`]);
    /// infinite: the unknowns do not enter convergence.
    pub field_tol: Option<f64>,
}

impl Default for SolveSettings {
    fn default() -> SolveSettings {
        SolveSettings {
            unknown: None,
            tol: 1e-10,
            max_level: 8,
            method: None,
            grid: GRID_POINTS,
            max_memory: None,
            field_tol: None,
        }
    }
}

/// The highest refinement level the numerics support.
pub const MAX_LEVEL: usize = 14;

impl SolveSettings {
    /// A finite positive tolerance, a level the numerics support.
    pub fn check(&self) -> Result<(), PlanError> {
        if !(self.tol > 0.0 && self.tol.is_finite()) {
            return Err(PlanError::Invalid(format!(
                "--tol {}: the tolerance must be a finite number > 0, e.g. 1e-10",
                self.tol
            )));
        }
        if let Some(ft) = self.field_tol
            && (ft.is_nan() || ft <= 0.0)
        {
            return Err(PlanError::Invalid(format!(
                "--field-tol {ft}: the tolerance must be a number > 0, e.g. 1e-6 (inf: the unknowns do not decide convergence)"
            )));
        }
        if self.max_level == 0 || self.max_level > MAX_LEVEL {
            return Err(PlanError::Invalid(format!(
                "--max-level {}: must be between 1 and {MAX_LEVEL}",
                self.max_level
            )));
        }
        Ok(())
    }
}

/// Solves `prog` as `s` asks: the one entry for every file.
pub fn solve(prog: &Program, s: &SolveSettings) -> Result<Report, PlanError> {
    s.check()?;
    solve_split(SplitInput::for_target(prog, s.unknown.as_deref())?, s)
}

/// Solves a split-domain problem (built from a program, or by a solver
/// `lambdamat codegen` wrote).
pub fn solve_split(input: SplitInput, s: &SolveSettings) -> Result<Report, PlanError> {
    Ok(solve_split_solution(input, s)?.0)
}

/// [`solve_split`], keeping the solution for further sampling (the
/// `hertz` front reads its fields).
pub fn solve_split_solution(
    input: SplitInput,
    s: &SolveSettings,
) -> Result<(Report, SplitSolution), PlanError> {
    s.check()?;
    let field_tol = s
        .field_tol
        .unwrap_or_else(|| crate::plan::split_solve::default_field_tol(s.tol));
    let opts = SplitOptions {
        tol: s.tol,
        max_level: s.max_level,
        // The unknowns' estimates that decide convergence are taken on at
        // least the default grid, so that a coarser report (the `hertz`
        // front's two points) converges as the default one does.
        grid: s.grid.max(GRID_POINTS),
        method: s.method.unwrap_or(Method::Coupled),
        fields_converge: field_tol.is_finite(),
        field_tol: if field_tol.is_finite() {
            field_tol
        } else {
            crate::plan::split_solve::DEFAULT_FIELD_TOL
        },
    };
    let sol = crate::plan::split_solve::solve_split_within(input, &opts, s.max_memory)?;
    let r = from_split(&sol, s.grid)?;
    Ok((r, sol))
}

/// A JSON number, or null when not finite.
fn finite(v: f64) -> Value {
    if v.is_finite() { json!(v) } else { Value::Null }
}

/// The report of a split-domain solve: its scalars, outputs and
/// coefficients with their estimates, and its unknowns sampled on the
/// output grid with their pointwise estimates ([`LevelFields`]).
pub fn from_split(sol: &SplitSolution, grid: usize) -> Result<Report, PlanError> {
    let r = &sol.report;
    let mut error_estimates = BTreeMap::new();
    let mut take = |list: &[crate::plan::split_solve::Estimate]| {
        list.iter()
            .map(|e| {
                error_estimates.insert(e.name.clone(), e.error);
                (e.name.clone(), e.value)
            })
            .collect::<BTreeMap<String, f64>>()
    };
    let scalars = take(&r.scalars);
    let outputs = take(&r.outputs);
    let coefficients = take(&r.coefficients);
    let unknowns = split_fields(sol, grid)?;
    for (name, f) in &unknowns {
        error_estimates.insert(name.clone(), f.error_estimate);
    }
    let mut warnings: Vec<String> = r.stopped.iter().chain(&r.uniqueness).cloned().collect();
    let mut extra = Map::new();
    if let Some(m) = sol.problem.method_record() {
        warnings.extend(m.warnings);
        if r.method == Method::Commutative.name() {
            for c in &m.commuted {
                let [a, b] = &c.pair;
                if let Some(v) = c.defect
                    && v > crate::plan::split_methods::DEFECT_WARNING
                {
                    warnings.push(format!(
                        "{a} and {b} do not commute: ‖{a}{b} f - {b}{a} f‖/‖{a}{b} f‖ = {v:.3e} for f = 1 + x; an elimination that commutes them is a model, not the system"
                    ));
                }
            }
            extra.insert("model".into(), json!(true));
            extra.insert(
                "commutator_defects".into(),
                m.commuted
                    .iter()
                    .map(|c| {
                        json!({"pair": c.pair, "defect": c.defect, "defect_on_solution": c.on_solution})
                    })
                    .collect(),
            );
            warnings.push(format!(
                "the commutative method solves the seed's single equation for {} (the eliminant of `lambdamat reduce`), a model that treats the operators as commuting symbols; the other unknowns follow from the ordered elimination's pivot equations; compare with --method ordered",
                sol.problem.sys.unknowns[sol.problem.sys.target]
            ));
        }
        extra.insert(
            "pivots".into(),
            m.pivots
                .iter()
                .map(|&(e, u)| {
                    let name = u.checked_sub(1).and_then(|u| sol.problem.sys.unknowns.get(u));
                    json!({"equation": e, "unknown": name})
                })
                .collect(),
        );
    }
    extra.insert(
        "target".into(),
        json!(sol.problem.sys.unknowns.get(sol.problem.sys.target)),
    );
    extra.insert("unique".into(), json!(r.uniqueness.is_none()));
    let mut notes = text::split_notes(r);
    notes.extend(text::log_end_notes(sol));
    extra.insert("notes".into(), json!(notes));
    extra.insert("dim".into(), json!(r.dim));
    extra.insert("cond".into(), finite(r.cond));
    extra.insert("singular_exponents".into(), json!(r.singular_exponents));
    extra.insert("end_answer".into(), json!(r.end_answer));
    extra.insert("end_check".into(), json!(r.end_check));
    Ok(Report {
        method: r.method.clone(),
        converged: r.converged,
        levels: r.levels,
        tol: r.tol,
        unknowns,
        outputs,
        scalars,
        coefficients,
        error_estimates,
        warnings,
        extra,
    })
}

/// Each unknown of a split-domain solution on `grid` points of its
/// interval (its declared one, else the whole), with the pointwise
/// estimates of [`LevelFields::value`]; points where the value or its
/// estimate is not finite (a singular term's own point) are left out.
fn split_fields(sol: &SplitSolution, grid: usize) -> Result<BTreeMap<String, Field>, PlanError> {
    let lf = LevelFields::new(sol)?;
    let mut out = BTreeMap::new();
    for (u, name) in sol.problem.sys.unknowns.iter().enumerate() {
        let g = lf.on_grid(u, grid, sol.report.converged)?;
        out.insert(
            name.clone(),
            Field {
                error_estimate: g.errors.iter().fold(0.0, |m: f64, &e| m.max(e)),
                x: g.x,
                values: g.values,
                weight: split_weight(sol, u),
            },
        );
    }
    Ok(out)
}

/// The behaviour of unknown `u` in a split-domain discretisation: its
/// basis weight and its exact singular terms.
fn split_weight(sol: &SplitSolution, u: usize) -> String {
    use crate::plan::{WeightSide, weight_factor_text};
    let d = &sol.discrete;
    let mut parts = Vec::new();
    let w = d.bases.get(u).and_then(Option::as_ref).map_or_else(
        || "1".to_string(),
        |b| {
            if b.weight.is_empty() {
                "1".to_string()
            } else {
                // A factor at an end of the unknown's support is printed
                // one-sided (`x^(0.5)`, `(1 - x)^(-0.5)`), one inside it
                // with an absolute value.
                let lo = b.panels.first().map_or(f64::NEG_INFINITY, |p| p.a);
                let hi = b.panels.last().map_or(f64::INFINITY, |p| p.b);
                b.weight
                    .iter()
                    .map(|f| {
                        let side = if f.at >= hi {
                            WeightSide::Below
                        } else if f.at <= lo {
                            WeightSide::Above
                        } else {
                            WeightSide::Both
                        };
                        weight_factor_text(f.at, f.exponent, side)
                    })
                    .collect::<Vec<_>>()
                    .join("*")
            }
        },
    );
    parts.push(w);
    for t in d.terms.iter().filter(|t| t.unknown == u) {
        parts.push(format!(
            "singular term {} at {}",
            weight_factor_text(t.at, -t.beta, WeightSide::Both),
            t.at
        ));
    }
    parts.join(" + ")
}

impl Report {
    /// The JSON object: `method`, `converged`, `levels`, `tol`,
    /// `unknowns` (per unknown `x`, `values`, `weight`,
    /// `error_estimate`), `outputs`, `scalars`, `coefficients`,
    /// `error_estimates` (absolute), `warnings`, then the track-specific
    /// keys of [`Report::extra`]. Non-finite numbers are written as null
    /// (they occur only in a report that did not converge).
    ///
    /// ```
    /// let p = lambdamat::Problem::from_source(
    ///     "unknown f on [0, 1]\noperator k = int(0..x) dt\nequation f + k f = 1\noutput F = int(0..1) f(x) dx",
    ///     "ex.lmx",
    /// )?;
    /// let s = p.solve(&lambdamat::SolveOptions::default())?;
    /// let v = s.to_json();
    /// assert_eq!(v["converged"], true);
    /// assert!(v["unknowns"]["f"]["values"].is_array());
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn to_json(&self) -> Value {
        let nums = |m: &BTreeMap<String, f64>| -> Map<String, Value> {
            m.iter().map(|(k, v)| (k.clone(), finite(*v))).collect()
        };
        let unknowns: Map<String, Value> = self
            .unknowns
            .iter()
            .map(|(k, f)| {
                (
                    k.clone(),
                    json!({
                        "x": f.x,
                        "values": f.values.iter().map(|v| finite(*v)).collect::<Vec<_>>(),
                        "weight": f.weight,
                        "error_estimate": finite(f.error_estimate),
                    }),
                )
            })
            .collect();
        let mut o = Map::new();
        o.insert("method".into(), json!(self.method));
        o.insert("converged".into(), json!(self.converged));
        o.insert("levels".into(), json!(self.levels));
        o.insert("tol".into(), json!(self.tol));
        o.insert("unknowns".into(), Value::Object(unknowns));
        o.insert("outputs".into(), Value::Object(nums(&self.outputs)));
        o.insert("scalars".into(), Value::Object(nums(&self.scalars)));
        o.insert(
            "coefficients".into(),
            Value::Object(nums(&self.coefficients)),
        );
        o.insert(
            "error_estimates".into(),
            Value::Object(nums(&self.error_estimates)),
        );
        o.insert("warnings".into(), json!(self.warnings));
        for (k, v) in &self.extra {
            o.entry(k.clone()).or_insert_with(|| v.clone());
        }
        Value::Object(o)
    }

    /// The unknowns as CSV: `x` and one column per unknown, on the union
    /// of the unknowns' grids (a cell is empty where an unknown has no
    /// value).
    ///
    /// ```
    /// let p = lambdamat::Problem::from_source(
    ///     "unknown f on [0, 1]\noperator k = int(0..x) dt\nequation f + k f = 1\noutput F = int(0..1) f(x) dx",
    ///     "ex.lmx",
    /// )?;
    /// let s = p.solve(&lambdamat::SolveOptions::default())?;
    /// assert!(s.csv().starts_with("x,f\n"));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn csv(&self) -> String {
        let mut s = String::from("x");
        for name in self.unknowns.keys() {
            s.push(',');
            s.push_str(name);
        }
        s.push('\n');
        let mut xs: Vec<f64> = self.unknowns.values().flat_map(|u| u.x.clone()).collect();
        xs.sort_by(f64::total_cmp);
        xs.dedup();
        for x in xs {
            s.push_str(&format!("{x}"));
            for u in self.unknowns.values() {
                s.push(',');
                if let Some(i) = u.x.iter().position(|&y| y == x) {
                    s.push_str(&format!("{:e}", u.values[i]));
                }
            }
            s.push('\n');
        }
        s
    }

    /// The message of a result that did not reach its tolerance (exit 4),
    /// the same for `lambdamat solve` and generated solvers.
    ///
    /// ```
    /// let p = lambdamat::Problem::from_source(
    ///     "unknown f on [0, 1]\noperator k = int(0..x) dt\nequation f + k f = 1\noutput F = int(0..1) f(x) dx",
    ///     "ex.lmx",
    /// )?;
    /// let s = p.solve(&lambdamat::SolveOptions::default())?;
    /// let mut r = s.clone();
    /// r.converged = false;
    /// assert!(!r.not_converged_message().is_empty());
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn not_converged_message(&self) -> String {
        format!(
            "after {} levels an error estimate (largest {:.1e}) is above tol·max(1, |value|) with tol {:.1e}; the result above is marked \"not converged\"",
            self.levels,
            self.largest_estimate(),
            self.tol
        )
    }

    /// The largest estimate of every reported quantity (0 with none).
    ///
    /// ```
    /// let p = lambdamat::Problem::from_source(
    ///     "unknown f on [0, 1]\noperator k = int(0..x) dt\nequation f + k f = 1\noutput F = int(0..1) f(x) dx",
    ///     "ex.lmx",
    /// )?;
    /// let s = p.solve(&lambdamat::SolveOptions::default())?;
    /// assert!(s.largest_estimate() >= s.error_estimates["F"]);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn largest_estimate(&self) -> f64 {
        self.error_estimates.values().fold(0.0, |m, &e| m.max(e))
    }

    /// The estimate of a named quantity.
    ///
    /// ```
    /// let p = lambdamat::Problem::from_source(
    ///     "unknown f on [0, 1]\noperator k = int(0..x) dt\nequation f + k f = 1\noutput F = int(0..1) f(x) dx",
    ///     "ex.lmx",
    /// )?;
    /// let s = p.solve(&lambdamat::SolveOptions::default())?;
    /// assert_eq!(s.estimate("F"), Some(s.error_estimates["F"]));
    /// assert_eq!(s.estimate("G"), None);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn estimate(&self, name: &str) -> Option<f64> {
        self.error_estimates.get(name).copied()
    }
}
