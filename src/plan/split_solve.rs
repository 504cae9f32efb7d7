//! Solving a split-domain problem: the ends no declaration names first get
//! their automatic weights (`split_weights.rs`); the unknown scalar (e.g. the stick
//! radius `c`) is found from its condition by a safeguarded root solve in
//! the variable `s = ln((x - lo)/(hi - x))` of its declared range (so a
//! root near an end is resolved to a relative accuracy in its distance to
//! that end). On the first level: a scan (a grid in `s`, then toward the
//! lower end, then toward the upper end, with doubling steps, to at most
//! `1e-10` of an end), Brent's method on each bracket from the lowest,
//! and the first root that is not a pole and whose solution keeps every
//! declared inequality (`inequality abs(q) <= mu*p on [0, c)`: the
//! Coulomb stick inequality) is taken; without a scalar, an answer that
//! breaks one is refused. On every further level: a secant iteration
//! warm-started from the previous root with a Newton step on the previous
//! slope, never shorter than a few ulps of the scalar (near `c → 1` the
//! root moves by less than one between levels; the step then brackets it
//! and the level costs two discretisations), and a local bracket and
//! Brent if it misbehaves. Every root
//! iteration stops at the tolerance in `s` that keeps the absolute root
//! tolerance in `x`, capped at a relative `1e-6` of the distance to the
//! nearer end and no finer than a few ulps of `x`. The levels of
//! [`SplitLevel`] are climbed until every scalar's, output's and singular
//! coefficient's estimate from the differences of successive levels
//! (`level_estimate`: the last difference while they shrink fast, more
//! when they do not, never less than the previous rate predicts, none
//! before three levels or on a level that adds no unknowns) is within the
//! tolerance. Each is reported with its own such estimate, and so is
//! every unknown's largest pointwise estimate on the output grid
//! ([`UnknownEstimate`], at least the rounding floor `32·ε·κ` of
//! [`rounding_floor`]), which drives the ladder too when
//! [`SplitOptions::fields_converge`] is set: each must then be within
//! `tol·max(1, size)` (`estimate`). Owns this
//! control logic;
//! the discretisation is `split.rs`'s.
use serde::Serialize;

use super::error::{EndReason, PlanError, RangeEnd, RootAtEnd};
use super::method::Method;
use super::split::{Discrete, SplitLevel, SplitProblem};
use super::split_fields::{LeftOut, LevelFields};
use super::split_input::SplitInput;
use crate::numeric::NumericError;
use crate::numeric::roots::{brent, secant};
use crate::numeric::solve::rounding_floor;
#[cfg(any(test, feature = "internals"))]
use crate::system::Program;

/// Accuracy controls.
#[derive(Debug, Clone, Copy)]
pub struct SplitOptions {
    /// Stop when every scalar's, output's and coefficient's estimate is
    /// within `tol·max(1, |value|)` (and, with
    /// [`SplitOptions::fields_converge`], every unknown's largest pointwise
    /// estimate within [`SplitOptions::field_tol`]`·max(1, size)`, its
    /// size being its largest `|u/weight|` on the output grid).
    pub tol: f64,
    /// Whether the unknowns' pointwise estimates enter convergence
    /// (`estimate`), each within [`SplitOptions::field_tol`]. On by
    /// default. (At a field tolerance of `1e-10` the sphere indentation's
    /// pressure at `x = 0` does not converge within the level cap,
    /// estimate 1.2e-10 on level 8 against a true error of 3e-11, and
    /// `32·ε·κ` floors every field of the contact gallery at about `1e-10`
    /// once `κ > 1.4e4`: hence the separate, coarser field tolerance.)
    pub fields_converge: bool,
    /// The unknowns' tolerance: with [`SplitOptions::fields_converge`],
    /// every unknown's largest pointwise estimate on the output grid must
    /// be within `field_tol·max(1, size)` (its size being its largest
    /// `|u/weight|` there), while the scalars, outputs and coefficients
    /// meet [`SplitOptions::tol`]. Apart from `tol` because a field
    /// converges pointwise more slowly than the integrals that make the
    /// outputs (see [`DEFAULT_FIELD_TOL`]).
    pub field_tol: f64,
    /// Highest level tried.
    pub max_level: usize,
    /// Points of the output grid the unknowns are estimated on.
    pub grid: usize,
    /// The method: `coupled` (the full collocation system) on every
    /// file; `ordered` and `commutative` where `split_methods.rs` can run
    /// them.
    pub method: Method,
}

impl Default for SplitOptions {
    fn default() -> SplitOptions {
        SplitOptions {
            tol: 1e-10,
            max_level: 8,
            grid: 101,
            method: Method::Coupled,
            fields_converge: true,
            field_tol: DEFAULT_FIELD_TOL,
        }
    }
}

/// The default of [`SplitOptions::field_tol`] (and of `--field-tol`).
///
/// Measured (`probes/unknowns_ladder.rs`, `/usr/bin/time -f %U+%S`, CPU
/// seconds with the fields out of convergence → at `1e-6` → at `1e-8`):
/// `examples/hertz.lmx` 0.33 → 0.33 (4 levels, `p` ± 6.9e-7, `q` ±
/// 8.6e-7) → 0.58 (5 levels, ± 5.7e-9); the sphere indentation 0.03 →
/// 0.07 → 0.08 (4 → 5 → 6 levels; `p` ± 7.4e-8 with true error 8.4e-9 at
/// `1e-6`); the sphere under load 0.17 → 0.19 → 0.21; JKR 0.02 → 0.03 →
/// 0.06; Cattaneo–Mindlin, the cone, the power law and the flat punch
/// unchanged (their ladders already climb for the scalars). So `1e-6`
/// keeps every file's cost; `--field-tol 1e-8` costs Hertz 1.8×. With the
/// fields on by default, `lambdamat hertz --nu 0.3 --mu 0.5` climbs 5
/// levels instead of 4 (`p` ± 1.1e-5 on level 4), CPU 0.50 → 0.92 s;
/// the sphere indentation, the sphere under load and its range climb one
/// or two levels more (CPU 0.03 → 0.06, 0.19 → 0.20, 0.72 → 0.93 s).
pub const DEFAULT_FIELD_TOL: f64 = 1e-6;

/// The unknowns' tolerance when none is given at tolerance `tol`: the
/// larger of `tol` and [`DEFAULT_FIELD_TOL`], so that the fields are never
/// asked for more than the scalars and outputs (`--tol 0.5` asks for
/// every number to 0.5, the fields too).
pub fn default_field_tol(tol: f64) -> f64 {
    tol.max(DEFAULT_FIELD_TOL)
}

/// What [`estimate`] multiplies each unknown's relative estimate by, so
/// that the one estimate compared with `tol` compares every field's with
/// `field_tol`: `tol/field_tol`; `None` when the fields do not enter
/// convergence.
fn field_scale(opts: &SplitOptions) -> Option<f64> {
    opts.fields_converge.then(|| opts.tol / opts.field_tol)
}

/// A number with its error estimate.
#[derive(Debug, Clone, Serialize)]
pub struct Estimate {
    /// Its name.
    pub name: String,
    /// Its value on the last level.
    pub value: f64,
    /// Distance to the previous level (plus the root tolerance for
    /// scalars); infinite after one level.
    pub error: f64,
}

/// The estimate of an unknown on the output grid: at each point, the
/// largest difference of the last two levels over a window around it
/// ([`super::split_fields::LevelFields`]) times `factor`, and at least
/// `floor`; `error` is the largest of these on the grid.
#[derive(Debug, Clone, Serialize)]
pub struct UnknownEstimate {
    /// The unknown.
    pub name: String,
    /// Its size, the largest `|u/weight|` on the grid.
    pub size: f64,
    /// Its largest pointwise estimate on the grid.
    pub error: f64,
    /// The safety factor on the level difference: 1 while the differences
    /// shrink at least twofold per level, `ρ/(1 − ρ)` at a slower ratio
    /// `ρ` (the geometric tail beyond the last level); infinite (no
    /// estimate) with a single difference.
    pub factor: f64,
    /// The rounding floor `32·ε·κ·max(1, size)` ([`rounding_floor`]), or
    /// where that would decide the estimate and the level was solved by
    /// one square factorisation, the largest adjoint bound of the grid
    /// values ([`adjoint_floors`]).
    pub floor: f64,
    /// The grid points left out of its values and estimates, each with
    /// why ([`LevelFields::on_grid`]): a singular term's own point, an end
    /// the end check graded (e.g. the cone's centre, where the pressure is
    /// infinite), a point within the scalars' estimate of an end that
    /// moves with them. The estimate holds on the points kept.
    pub left_out: Vec<LeftOut>,
}

/// A solved split-domain problem.
#[derive(Debug, Clone, Serialize)]
pub struct SplitReport {
    /// The unknown scalars.
    pub scalars: Vec<Estimate>,
    /// The outputs.
    pub outputs: Vec<Estimate>,
    /// The coefficients of the exact singular terms.
    pub coefficients: Vec<Estimate>,
    /// The unknowns' estimates on the output grid.
    pub unknowns: Vec<UnknownEstimate>,
    /// The method used.
    pub method: String,
    /// Largest estimate of a scalar, output or coefficient, each relative
    /// to `max(1, |value|)`, and with [`SplitOptions::fields_converge`] of
    /// an unknown, relative to `max(1, size)`: what convergence compares
    /// with the tolerance.
    pub error_estimate: f64,
    /// Whether it is within the tolerance.
    pub converged: bool,
    /// The unknowns' tolerance ([`SplitOptions::field_tol`]) when their
    /// pointwise estimates entered convergence
    /// ([`SplitOptions::fields_converge`]); `None` when they did not.
    pub field_tol: Option<f64>,
    /// The tolerance.
    pub tol: f64,
    /// Levels climbed.
    pub levels: usize,
    /// Coefficients on the last level.
    pub dim: usize,
    /// Condition estimate on the last level.
    pub cond: f64,
    /// The exponents measured for the singular terms, `(unknown, point, β)`.
    pub singular_exponents: Vec<(String, f64, f64)>,
    /// Set when the scalar was not resolved but bounded: its root lies
    /// within the resolved distance of an end of its range, and every
    /// value above is the answer there with that bound included
    /// (`split_end.rs`).
    pub end_answer: Option<super::split_end::EndAnswer>,
    /// The end check (`split_ends.rs`): whether grading the ends of the
    /// unknowns' interval that no `singular` declaration names moved an
    /// answer beyond its estimate (then the mesh was graded there), when
    /// the check was made.
    pub end_check: Option<super::split_ends::EndCheck>,
    /// Why the ladder stopped before the tolerance was reached, when it
    /// was the memory budget.
    pub stopped: Option<String>,
    /// Set when the equation has more than one solution and the answer is
    /// the one the solver's weight selects: the warning saying so
    /// (`uniqueness.rs`).
    pub uniqueness: Option<String>,
}

pub(super) struct Level {
    /// Unknowns of the level's discretisation ([`refines`]).
    pub(super) dim: usize,
    pub(super) scalars: Vec<f64>,
    pub(super) slope: f64,
    pub(super) outputs: Vec<f64>,
    pub(super) coefficients: Vec<f64>,
    /// Per unknown, its moments over the unknowns' interval: what the end
    /// check compares (`split_ends::integrals_of`), functionals of the
    /// solution the equations define whatever outputs are requested.
    pub(super) integrals: Vec<f64>,
    /// The condition estimate of the level's system.
    pub(super) cond: f64,
    /// Per unknown, the largest level difference to the level before on
    /// the output grid (empty when not measured).
    pub(super) unknowns: Vec<f64>,
    /// Per unknown, its size ([`UnknownEstimate::size`]; empty when not
    /// measured).
    pub(super) sizes: Vec<f64>,
    /// Per unknown, the grid points left out ([`UnknownEstimate::left_out`];
    /// empty when not measured).
    pub(super) left_out: Vec<Vec<LeftOut>>,
    /// Per unknown, its rounding floor when the adjoint bound replaced
    /// `32·ε·κ·max(1, size)` ([`adjoint_floors`]; empty otherwise).
    pub(super) floors: Vec<Option<f64>>,
    /// Per output, the adjoint rounding bound of its functional
    /// ([`SplitProblem::output_rounding`]; `None` where the level's
    /// factors were not kept).
    pub(super) output_floors: Vec<Option<f64>>,
    /// Per singular-term coefficient, its adjoint rounding bound
    /// ([`SplitProblem::coefficient_rounding`]; `None` where the level's
    /// factors were not kept): a coefficient is one entry of the solution,
    /// read like a point value, not summed like an integral.
    pub(super) coefficient_floors: Vec<Option<f64>>,
}

/// Tolerance of the root iterations: a twentieth of the requested
/// accuracy, added to the estimate.
pub(super) fn root_tolerance(tol: f64) -> f64 {
    (0.005 * tol).clamp(1e-15, 1e-9)
}

/// A solved split-domain problem with its last discretisation, for
/// sampling the fields (`split_fields.rs`).
pub struct SplitSolution {
    /// The report.
    pub report: SplitReport,
    /// The compiled problem.
    pub problem: SplitProblem,
    /// The discrete solution on the last level, at the scalars reported.
    pub discrete: Discrete,
    /// The discrete solution on the level before (at that level's
    /// scalars), when more than one level was climbed: the fields of the
    /// two levels at the same points give the fields' own error estimate
    /// (`split_fields::LevelFields`), as the two levels' scalars and
    /// outputs give theirs.
    pub previous: Option<Discrete>,
    /// The last level discretised at the unknown scalar moved by its
    /// estimate (toward the inside of its range), when there is a scalar
    /// with a finite estimate: at each point, the change of a field from
    /// [`SplitSolution::discrete`] to this is what the scalar's own
    /// uncertainty makes uncertain there
    /// ([`super::split_fields::LevelFields::windowed`]).
    pub shifted: Option<Discrete>,
}

/// Solves `prog` (a file with split-domain declarations).
#[cfg(feature = "internals")]
pub fn solve_split(prog: &Program, opts: &SplitOptions) -> Result<SplitReport, PlanError> {
    solve_split_fields(prog, opts).map(|s| s.report)
}

/// [`solve_split`], keeping the compiled problem and the last
/// discretisation.
#[cfg(any(test, feature = "internals"))]
pub fn solve_split_fields(prog: &Program, opts: &SplitOptions) -> Result<SplitSolution, PlanError> {
    check_tolerance(opts)?;
    solve_split_input_fields(SplitInput::from_program(prog)?, opts)
}

pub(super) fn check_tolerance(opts: &SplitOptions) -> Result<(), PlanError> {
    if !(opts.tol > 0.0 && opts.tol.is_finite()) {
        return Err(PlanError::Invalid(format!(
            "tolerance {} must be positive",
            opts.tol
        )));
    }
    if !(opts.field_tol > 0.0 && opts.field_tol.is_finite()) {
        return Err(PlanError::Invalid(format!(
            "field tolerance {} must be positive",
            opts.field_tol
        )));
    }
    Ok(())
}

/// Solves the problem `input` describes, however it was built (from a
/// program by [`solve_split`], or by a solver `lambdamat codegen` wrote).
#[cfg(feature = "internals")]
pub fn solve_split_input(input: SplitInput, opts: &SplitOptions) -> Result<SplitReport, PlanError> {
    solve_split_input_fields(input, opts).map(|s| s.report)
}

/// [`solve_split_input`], keeping the compiled problem and the last
/// discretisation.
#[cfg(any(test, feature = "internals"))]
pub fn solve_split_input_fields(
    input: SplitInput,
    opts: &SplitOptions,
) -> Result<SplitSolution, PlanError> {
    solve_split_within(input, opts, None)
}

/// [`solve_split_input_fields`] within a memory budget of `max_memory`
/// bytes (`None`: the default of [`crate::numeric::budget`]): a level over
/// it is not built, and the last level that fitted is reported, marked.
pub fn solve_split_within(
    input: SplitInput,
    opts: &SplitOptions,
    max_memory: Option<u64>,
) -> Result<SplitSolution, PlanError> {
    let choice = super::uniqueness::check_split(&input)?;
    let mut sol = solve_split_ladder(input, opts, max_memory)?;
    if let super::uniqueness::Uniqueness::Chosen(w) = choice {
        sol.report.uniqueness = Some(w);
    }
    Ok(sol)
}

/// The numeric input checks of a solve (right sides and kernels finite at
/// the nodes, …) without the ladder, for a file without unknown scalars:
/// level 0 assembled with the declared ends (no automatic end weights, whose
/// trials solve the whole system some ten times over) and solved once.
/// `Ok(false)` when the file has unknown scalars (their root solve is the
/// ladder's, so the caller runs a short solve instead); any error of the
/// level is returned, the caller keeps its input errors.
pub fn check_inputs(input: SplitInput) -> Result<bool, PlanError> {
    let problem = SplitProblem::from_input(input)?;
    if !problem.contact.scalars.is_empty() {
        return Ok(false);
    }
    problem.discretise(&[], &SplitLevel::level(0))?;
    Ok(true)
}

/// [`solve_split_within`] without the uniqueness check.
fn solve_split_ladder(
    input: SplitInput,
    opts: &SplitOptions,
    max_memory: Option<u64>,
) -> Result<SplitSolution, PlanError> {
    check_tolerance(opts)?;
    let mut problem = SplitProblem::from_input(input)?;
    problem.set_method(opts.method)?;
    if let Some(b) = max_memory {
        problem.budget = b;
    }
    let ns = problem.contact.scalars.len();
    super::split_weights::choose(&mut problem)?;
    let mut levels: Vec<Level> = Vec::new();
    let mut previous: Option<Discrete> = None;
    for k in 0..=opts.max_level {
        let lvl = SplitLevel::level(k);
        let attempt = if ns == 0 {
            problem.discretise(&[], &lvl).map(|d| (d, vec![], 0.0))
        } else if ns > 1 {
            let last = levels.last().map(|l| l.scalars.as_slice());
            super::split_scalars::find_scalars(&problem, &lvl, last, opts.tol)
                .map(|(x, d)| (d, x, 0.0))
        } else {
            find_scalar(&problem, &lvl, &levels, opts.tol).map(|(x, slope, d)| (d, vec![x], slope))
        };
        let (mut d, scalars, slope) = match attempt {
            Ok(a) => a,
            // On the first level a root beyond the resolved distance
            // from an end may still give an answer to the tolerance.
            Err(PlanError::RootAtEnd(r)) if levels.is_empty() => {
                return super::split_end::answer_at_end(problem, r, opts);
            }
            // Over the memory budget, or too ill-conditioned to solve: the
            // last level solved, marked (not converged).
            Err(e)
                if previous.is_some()
                    && !levels.is_empty()
                    && (matches!(e, PlanError::OverBudget(_)) || is_ill_conditioned(&e)) =>
            {
                let why = match &e {
                    PlanError::OverBudget(_) => "the last within the memory budget",
                    _ => "the last whose system was well-conditioned",
                };
                let this = levels.pop().expect("checked");
                let d = previous.take().expect("checked");
                let rt = if ns > 0 {
                    2.0 * root_tolerance(opts.tol)
                } else {
                    0.0
                };
                let est = if levels.is_empty() {
                    f64::INFINITY
                } else {
                    (estimate(&problem, &levels, &this, field_scale(opts)) + rt)
                        .max(d.consistency)
                };
                let mut report = report(&problem, &d, &levels, &this, est, false, opts, k, rt);
                report.stopped = Some(format!("stopped after {k} levels, {why}: {e}"));
                if let Some(e) = without_a_digit(&mut problem, &report) {
                    return Err(e);
                }
                return Ok(SplitSolution {
                    report,
                    problem,
                    discrete: d,
                    previous: None,
                    shifted: None,
                });
            }
            Err(e) if is_null_direction(&e) => {
                return Err(match &problem.weight_text {
                    Some(w) => super::split_weights::in_class(e, w, ""),
                    None => e,
                });
            }
            Err(e) => return Err(e),
        };
        let outputs = (0..problem.sys.outputs.len())
            .map(|o| problem.output(&d, o))
            .collect::<Result<Vec<f64>, PlanError>>()?;
        let coefficients = (0..problem.contact.coefficients.len())
            .map(|c| problem.coefficient(&d, c).unwrap_or(f64::NAN))
            .collect();
        let output_floors = (0..problem.sys.outputs.len())
            .map(|o| problem.output_rounding(&d, o))
            .collect();
        let coefficient_floors = (0..problem.contact.coefficients.len())
            .map(|c| problem.coefficient_rounding(&d, c))
            .collect();
        let mut this = Level {
            dim: SplitProblem::size(&d),
            scalars,
            slope,
            outputs,
            coefficients,
            integrals: super::split_ends::integrals_of(&problem, &d)?,
            cond: d.cond,
            unknowns: Vec::new(),
            sizes: Vec::new(),
            left_out: Vec::new(),
            floors: Vec::new(),
            output_floors,
            coefficient_floors,
        };
        let rt = if ns > 0 {
            2.0 * root_tolerance(opts.tol)
        } else {
            0.0
        };
        let mut shifted = None;
        if let Some(p) = &previous {
            let scalar_error = (0..ns)
                .map(|i| estimate_of(&levels, &this, &|l| &l.scalars, i) + rt)
                .fold(0.0, f64::max);
            shifted = shifted_level(&problem, &this.scalars, scalar_error, &lvl);
            let kept;
            (this.unknowns, this.sizes, this.left_out, kept) =
                unknown_distances(&problem, &d, p, shifted.as_ref(), scalar_error, opts.grid)?;
            this.floors = adjoint_floors(&d, &levels, &this, &kept, opts);
        }
        // The factors are needed no longer.
        d.rounding = None;
        if let Some(s) = shifted.as_mut() {
            s.rounding = None;
        }
        let mut est = (!levels.is_empty()).then(|| {
            (estimate(&problem, &levels, &this, field_scale(opts)) + rt).max(d.consistency)
        });
        let mut converged = est.is_some_and(|e| e <= opts.tol);
        // Would grading the undeclared ends move the answer?
        use super::split_ends::{APPROACH_LEVEL, Mode, Verdict, check};
        let mode = if converged {
            Some(Mode::Accept)
        } else if (APPROACH_LEVEL..opts.max_level).contains(&k) {
            Some(Mode::Approach)
        } else {
            None
        };
        if let Some(mode) = mode {
            match check(&mut problem, &lvl, k, &levels, &this, opts, mode, false)? {
                Verdict::Accept => {}
                Verdict::Climb { level, discrete } => {
                    levels = vec![*level];
                    previous = Some(*discrete);
                    continue;
                }
                Verdict::Refuse { worst } => {
                    converged = false;
                    est = est.map(|e| e.max(worst));
                }
            }
        }
        if converged || k == opts.max_level {
            // Without a scalar no root was chosen by the inequalities, so
            // the answer itself is checked. (With one, the root chosen on
            // the first level kept them; later levels are not checked
            // again: near a stick radius below 1e-9 the condition's
            // rounding noise breaks the Coulomb inequality beside `c` by
            // a few tens of per cent while the answer is right, see
            // `S_LIMIT_LO`.)
            if ns == 0
                && let Some((text, x, l, r)) = problem.inequality_violation(&d)
            {
                return Err(PlanError::Inequality(format!(
                    "the solution violates the inequality `{text}`: at x = {x:.6e} the smaller side is {l:.6e}, above {r:.6e} by {:.3e}",
                    l - r
                )));
            }
            let est = est.unwrap_or(f64::INFINITY);
            let report = report(
                &problem,
                &d,
                &levels,
                &this,
                est,
                converged,
                opts,
                k + 1,
                rt,
            );
            if let Some(e) = without_a_digit(&mut problem, &report) {
                return Err(e);
            }
            return Ok(SplitSolution {
                report,
                problem,
                discrete: d,
                previous,
                shifted,
            });
        }
        levels.push(this);
        previous = Some(d);
    }
    Err(PlanError::Invalid("empty level ladder".into()))
}

/// The refusal of an answer that did not reach its tolerance in a trial
/// space chosen beside one with a null direction
/// ([`SplitProblem::null_refusal`]), when no output, scalar or
/// coefficient it reports has three significant digits (an estimate below
/// a thousandth of its value's size; or there is none of them at all):
/// the chosen space then only drifts toward what the other represents
/// (`tests/data/traps/null_log_system_none.lmx`: no solution,
/// `int f = -1.1e8 ± 1.1e8`). An answer with digits
/// (`null_log_system.lmx`: `-6.2831856 ± 1.6e-5`) is kept, marked.
fn without_a_digit(problem: &mut SplitProblem, r: &SplitReport) -> Option<PlanError> {
    if r.converged || problem.null_refusal.is_none() {
        return None;
    }
    let mut all = r.scalars.iter().chain(&r.outputs).chain(&r.coefficients).peekable();
    let none = all.peek().is_none();
    let digitless = none || all.any(|q| !q.value.is_finite() || q.error.is_nan() || q.error >= 1e-3 * q.value.abs());
    if digitless {
        problem.null_refusal.take()
    } else {
        None
    }
}

/// Whether `e` is the solver's discrete null-direction refusal.
pub(super) fn is_null_direction(e: &PlanError) -> bool {
    matches!(
        e,
        PlanError::Numeric {
            source: crate::numeric::NumericError::NullSpace { .. },
            ..
        }
    )
}

/// Whether `e` is the solver's refusal of an ill-conditioned level.
fn is_ill_conditioned(e: &PlanError) -> bool {
    matches!(
        e,
        PlanError::Numeric {
            source: crate::numeric::NumericError::IllConditioned { .. },
            ..
        }
    )
}

/// The error estimate of one quantity on the newest level, from its
/// values on every level climbed (`history`, oldest first, newest last).
///
/// With `Δₖ` the difference of levels `k − 1` and `k`, and `ρ` the larger
/// of the last ratio `Δₖ/Δₖ₋₁` and the one before it, `Δₖ₋₁/Δₖ₋₂`:
/// - while they shrink at least twofold per level (`ρ ≤ 1/2`) the
///   remaining error, `Σ_(j>k) Δⱼ`, is at most the last difference;
/// - when they shrink more slowly (`ρ ∈ (1/2, 0.9)`) the geometric tail
///   `Δₖ·ρ/(1 − ρ)` is used;
/// - when they do not shrink from one level to the next (`ρ ≥ 0.9`: some
///   quantities improve only every other level) the larger of the last two
///   differences is the estimate. Measured on `examples/punch_torsion.lmx`
///   at w = 1.01 on the ladder of the time: the torque's error fell
///   2.9e-10, 2.7e-11, 1.6e-11, 1.7e-12 over four levels, so the last
///   difference alone (1.1e-11) was below the true error (1.6e-11).
///
/// **The stall guard.** Two levels can agree by coincidence while both
/// are still far off: the difference of a quantity whose error changes
/// sign, or barely moves, between two levels says nothing about its size.
/// Measured on the torque of `examples/punch_torsion.lmx` at w = 3/2
/// (`tests/contact_torsion.rs`): errors 4.2e-10, 8.3e-13, 7.5e-13, 4.2e-14
/// over the first four levels, so the difference of levels 1 and 2
/// (8.1e-14) was a tenth of their error. So the last difference is taken
/// no smaller than the previous ratio predicts, `Δₖ₋₁·(Δₖ₋₁/Δₖ₋₂)`: a
/// sudden acceleration is not believed until a further level confirms it.
/// With only two differences there is no previous ratio, and the last one
/// is taken no smaller than `Δₖ₋₁·FASTEST_UNCONFIRMED`. With fewer than
/// three levels there is no estimate (infinite): one difference cannot
/// tell a converged value from a stalled one.
///
/// **The sign guard.** When the last two differences have opposite signs
/// the ladder is not in its asymptotic regime (it wobbles about a floor
/// the levels do not refine, or overshoots), and the last difference says
/// nothing about the distance to the limit: the estimate is then at least
/// the previous difference. Measured on `tests/data/traps/contact_spike_8.lmx`
/// (a kernel spike of width 1e-8): `a` was off by 9.5e-9, 3.9e-10, 5.1e-11,
/// 2.2e-11, 2.2e-11 on levels 0–4, the last two differences 2.95e-11 and
/// −2.0e-13, so the stall guard alone gave 3.5e-12; `P` was off by
/// 1.2e-10, 4.5e-11, 6.7e-11 on levels 2–4 while its differences fell
/// 7.9e-11, −2.2e-11. Point values go without it
/// ([`level_estimate_guarded`]).
///
/// It is never below 32 ulps of the value (the rounding of the sums that
/// form an output over hundreds of panels: `examples/punch_torsion.lmx`'s
/// load P = 1 came out 1.0e-15 off while two levels agreed to 6.7e-16).
pub(super) fn level_estimate(history: &[f64]) -> f64 {
    level_estimate_guarded(history, true)
}

/// [`level_estimate`], with the sign guard only when `sign_guard`. Point
/// values go without it ([`output_estimate`]): beside the plain end of
/// `examples/contact/flat_punch.lmx`, `p(1e-9)` wobbles about a floor of
/// 1e-10 to 3e-10 from level 5 on (off by 3.3e-11, 2.9e-10, 1.7e-10,
/// 1.2e-10 on levels 5–8), so the guard drove the ladder from level 3
/// (off by 2.3e-11 against 5.4e-11) into that floor, where the last
/// differences (+2.6e-10, −1.2e-10, −5.1e-11) again understate it.
fn level_estimate_guarded(history: &[f64], sign_guard: bool) -> f64 {
    let n = history.len();
    if n < 3 {
        return f64::INFINITY;
    }
    let diff = |k: usize| (history[k] - history[k - 1]).abs();
    // A ratio of differences; a zero difference after a non-zero one is
    // ratio 0, any difference after a zero one is ratio ∞.
    let ratio = |a: f64, b: f64| if a == 0.0 { 0.0 } else { a / b };
    let floor = 32.0 * f64::EPSILON * history[n - 1].abs();
    let (last, prev) = (diff(n - 1), diff(n - 2));
    let before = if n >= 4 {
        ratio(prev, diff(n - 3))
    } else {
        FASTEST_UNCONFIRMED
    };
    let rho = ratio(last, prev).max(before);
    // The stall guard: the last difference, no smaller than predicted.
    let guarded = last.max(prev * before);
    let est = if rho <= 0.5 {
        guarded
    } else if rho < 0.9 {
        guarded * rho / (1.0 - rho)
    } else {
        // Also when a ratio is undefined (two equal levels).
        last.max(prev)
    };
    // The sign guard: the last two differences point opposite ways.
    let d = |k: usize| history[k] - history[k - 1];
    let est = if sign_guard && d(n - 1) * d(n - 2) < 0.0 {
        est.max(prev)
    } else {
        est
    };
    est.max(floor)
}

/// The fastest contraction per level [`level_estimate`] believes before a
/// second ratio confirms it. On the ladder of [`SplitLevel::level`] the
/// differences of the Hertz problem's `c`, `P` and `P_shear` (twelve
/// `(ν, μ)` of issue 13's sweep) and of the torsion punch's outputs fell
/// 1/16 to 1/70 from the first difference to the second, 1/1000 only for
/// `c` at `(0, 100)` (already within 1e-12); the stalled torque above fell
/// 1/5000.
pub(super) const FASTEST_UNCONFIRMED: f64 = 1.0 / 64.0;

/// Whether `this` level refines the last one climbed: its discretisation
/// has more unknowns. A level that does not (identical meshes and
/// degrees, as a ladder whose parameters have all reached their caps
/// would give) says nothing about the error, and the estimates on it are
/// infinite whatever its values.
pub(super) fn refines(levels: &[Level], this: &Level) -> bool {
    levels.last().is_some_and(|l| this.dim > l.dim)
}

/// [`level_estimate`] of quantity `i` of `of` on `this` level, infinite
/// when `this` does not refine the last level ([`refines`]).
pub(super) fn estimate_of(
    levels: &[Level],
    this: &Level,
    of: &dyn Fn(&Level) -> &[f64],
    i: usize,
) -> f64 {
    estimate_of_guarded(levels, this, of, i, true)
}

/// [`estimate_of`] with the sign guard only when `sign_guard`
/// ([`level_estimate_guarded`]).
fn estimate_of_guarded(
    levels: &[Level],
    this: &Level,
    of: &dyn Fn(&Level) -> &[f64],
    i: usize,
    sign_guard: bool,
) -> f64 {
    if refines(levels, this) {
        // Not floored at `32·ε·κ` ([`rounding_floor`](crate::numeric::solve::rounding_floor);
        // point outputs are, [`point_rounding`]): κ reaches 1.4e4
        // by level 7 on the contact gallery (floor 1.0e-10), where the
        // radii are right to 1e-13 (the cone's `a`), so no example would
        // reach the default tolerance.
        level_estimate_guarded(&history(levels, this, of, i), sign_guard)
    } else {
        f64::INFINITY
    }
}

/// The rounding term of output `o` on `this` level: for an output that
/// reads point values `Σ cᵢ·u(xᵢ)`, [`rounding_floor`]`(κ)` (`32·ε·κ`)
/// times `max(Σ|cᵢ|, |value|)`; 0 for an output of integrals and
/// constants only. Its estimate is at least this.
///
/// **Why point values.** The coefficients of a solve with condition `κ`
/// carry relative errors up to about `ε·κ` (the rounding of the
/// right-hand side and of the factorisation, amplified), the same bound
/// the fields' estimates are floored at ([`UnknownEstimate::floor`]). A
/// point value reads the few coefficients of one panel, so it carries that
/// error in full, and the level differences need not show it: the noise
/// of successive levels is not a geometric sequence. Measured on
/// `examples/hertz_split_mms.lmx` with point outputs appended
/// (`tests/off_grid_points.rs`): `p(0.2503…)` off by 8.3e-14 against a
/// level estimate of 1.1e-14 at `κ = 3.7e3` (`ε·κ = 8.2e-13`), and
/// `p(c − 1e-9)`, on the innermost panel graded toward the free boundary
/// `c = 1/2`, off by 4.2e-11 against a level estimate of 2.3e-11 at
/// `κ = 1.4e4` (`ε·κ = 3.1e-12`; its error grew from 7.5e-12 to 4.2e-11
/// over levels 2 to 5, the noise of panels of `1e-12` beside `c`): 13.5
/// times `ε·κ`, within the factor 32. An integral sums the coefficients of
/// hundreds of panels, whose rounding errors largely cancel: the contact
/// gallery's loads are right to 1e-13 at `κ = 1.4e4` (`32·ε·κ = 1e-10`,
/// see [`estimate_of`]), so integral outputs, scalars and coefficients get
/// no such term (only the 32 ulps of [`level_estimate`]), and the
/// gallery's estimates (all integrals) are unchanged.
pub(super) fn point_rounding(problem: &SplitProblem, this: &Level, o: usize) -> f64 {
    let adjoint = this.output_floors.get(o).copied().flatten();
    let weight = point_weight(problem, o);
    if weight == 0.0 {
        // An integral sums many panels' rounding, which largely cancels
        // (see above), unless the system is close to singular: beyond
        // `INTEGRAL_ROUNDING_COND` the adjoint bound is its floor. Below
        // it the bound overstates: on `tests/data/traps/contact_spike_8.lmx`
        // (κ ≈ 1.9e7) it held `P` at 9.4e-10, whose error is 6.7e-11, and
        // the ladder never converged. Above it the level differences can
        // miss the rounding: on `null_near_miss.lmx` (κ ≈ 5e8) `I` is off
        // by 1.9e-4 while they say 1.8e-4, and on `null_log_system.lmx`
        // (κ ≈ 2.2e12, a near null direction) `int f` is off by 3.09e-7
        // while they say 3.08e-7; with the adjoint bound the estimates are
        // 7.6e-3 and 1.6e-5.
        return if this.cond > INTEGRAL_ROUNDING_COND {
            adjoint.unwrap_or(0.0)
        } else {
            0.0
        };
    }
    let normwise = rounding_floor(this.cond) * weight.max(this.outputs[o].abs());
    // The sharper of the two bounds of a point value's rounding: the
    // adjoint one overstates it beside an end where the operator weighs
    // the unknown by a vanishing factor (measured on the flat punch:
    // 9.9e-9 at `p(1e-9)`, whose error is 1.2e-10).
    adjoint.map_or(normwise, |a| a.min(normwise))
}

/// The condition number beyond which an integral output's estimate is
/// floored at its adjoint rounding bound ([`point_rounding`]): where
/// `32·ε·κ` passes 1e-6 (κ ≈ 1.4e8), between the two measured cases
/// there.
const INTEGRAL_ROUNDING_COND: f64 = 1e-6 / (32.0 * f64::EPSILON);

/// The sum of `|coeff|` over output `o`'s point values `coeff·u(c)`
/// (0 for an output of integrals and constants only).
fn point_weight(problem: &SplitProblem, o: usize) -> f64 {
    problem.sys.outputs[o]
        .terms
        .iter()
        .map(|t| match t {
            super::compiled::OutputTerm::Point { coeff, .. } => coeff.abs(),
            _ => 0.0,
        })
        .sum()
}

/// [`estimate_of`] of output `o`, at least its [`point_rounding`]; an
/// output with a point value goes without the sign guard
/// ([`level_estimate_guarded`]).
pub(super) fn output_estimate(
    problem: &SplitProblem,
    levels: &[Level],
    this: &Level,
    o: usize,
) -> f64 {
    let guarded = point_weight(problem, o) == 0.0;
    estimate_of_guarded(levels, this, &|l| &l.outputs, o, guarded).max(point_rounding(problem, this, o))
}

/// [`estimate_of`] of singular-term coefficient `i`, at least its
/// adjoint rounding bound (`Level::coefficient_floors`): the level
/// differences miss rounding that every level repeats alike, such as an
/// extra collocation row's (the second term of an unknown at a point)
/// cancellation beside the point.
pub(super) fn coefficient_estimate(levels: &[Level], this: &Level, i: usize) -> f64 {
    let floor = this.coefficient_floors.get(i).copied().flatten();
    estimate_of(levels, this, &|l| &l.coefficients, i).max(floor.unwrap_or(0.0))
}

/// One quantity's values on every level climbed, then on `this`.
pub(super) fn history(
    levels: &[Level],
    this: &Level,
    of: &dyn Fn(&Level) -> &[f64],
    i: usize,
) -> Vec<f64> {
    levels
        .iter()
        .chain(std::iter::once(this))
        .map(|l| of(l)[i])
        .collect()
}

/// Per unknown, the largest level difference of discretisation `d` to
/// `previous` on the output grid of `grid` points
/// ([`LevelFields::on_grid`], with the scalars' estimate `scalar_error`
/// for the ends that move with them), and its size.
fn unknown_distances(
    problem: &SplitProblem,
    d: &Discrete,
    previous: &Discrete,
    shifted: Option<&Discrete>,
    scalar_error: f64,
    grid: usize,
) -> Result<UnknownDistances, PlanError> {
    let lf = LevelFields::pair(problem, d, Some(previous), scalar_error)?
        .with_shifted(problem, shifted)?;
    let (mut dist, mut sizes, mut left_out, mut kept) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for u in 0..problem.sys.unknowns.len() {
        let g = lf.on_grid(u, grid, true)?;
        dist.push(g.errors.iter().fold(0.0, |m: f64, &e| m.max(e)));
        sizes.push(g.size);
        left_out.push(g.left_out);
        kept.push(g.x);
    }
    Ok((dist, sizes, left_out, kept))
}

/// Per unknown: its largest level difference on the grid, its size, the
/// grid points left out and those kept ([`unknown_distances`]).
type UnknownDistances = (Vec<f64>, Vec<f64>, Vec<Vec<LeftOut>>, Vec<Vec<f64>>);

/// Per unknown of `this` level, the adjoint rounding bound of its values
/// on the grid points `kept` (per unknown), where the floor
/// `32·ε·κ·max(1, size)` would decide its estimate (above its factor times
/// its level difference) and keep it from the field tolerance (with
/// [`SplitOptions::fields_converge`]), and the level's factors are at hand
/// ([`Discrete`]'s square solve): the largest over the points of
/// `|A⁻ᵀl|ᵀ·(|r| + 32·ε·(|A||y| + |b|))`, `l` the row that reads the
/// unknown at the point from the coefficients `y` of `A y = b` (its
/// weight, its relations and its singular terms included), `r` the
/// computed residual. `κ` is a normwise condition of the column-scaled
/// matrix: grading toward a stick radius of `6e-7`
/// (`examples/punch_torsion.lmx` at `w = 10`) makes it `5e10` and that
/// floor `3.5e-4`, while the point values move by far less under the
/// rounding of the rows they depend on. `None` where the floor is kept.
fn adjoint_floors(
    d: &Discrete,
    levels: &[Level],
    this: &Level,
    kept: &[Vec<f64>],
    opts: &SplitOptions,
) -> Vec<Option<f64>> {
    let Some(rounding) = d.rounding.as_deref().filter(|_| opts.fields_converge) else {
        return Vec::new();
    };
    let layout = d.layout();
    unknown_estimates(levels, this)
        .into_iter()
        .enumerate()
        .map(|(u, (_, factor, floor))| {
            // Only where the floor would keep the unknown from its
            // tolerance: elsewhere the transposed solves (one per grid
            // point) are not worth their cost.
            let fails = floor > opts.field_tol * this.sizes[u].max(1.0);
            if !(factor.is_finite() && floor > factor * this.unknowns[u] && fails) {
                return None;
            }
            let rows = kept[u]
                .iter()
                .map(|&x| {
                    let term = super::compiled::OutputTerm::Point {
                        coeff: 1.0,
                        at: x,
                        unknown: u,
                    };
                    layout.functional(&[term]).ok().map(|(row, _)| row)
                })
                .collect::<Option<Vec<_>>>()?;
            rounding.worst_bound(&rows)
        })
        .collect()
}

/// Level `lvl` discretised at the one unknown scalar of `scalars` moved by
/// its estimate `delta` toward the inside of its declared range (by
/// `-delta` when `+delta` leaves it); `None` without a scalar, with an
/// infinite estimate, or when that discretisation fails (then the fields
/// fall back to the power-law model of
/// [`LevelFields::shift_term`]).
fn shifted_level(
    problem: &SplitProblem,
    scalars: &[f64],
    delta: f64,
    lvl: &SplitLevel,
) -> Option<Discrete> {
    let (&x, s) = (scalars.first()?, problem.contact.scalars.first()?);
    if !(delta.is_finite() && delta > 0.0) {
        return None;
    }
    let (lo, hi) = s.range;
    let up = x + delta;
    let moved = if up < hi { up } else { x - delta };
    if !(moved > lo && moved < hi) {
        return None;
    }
    problem.discretise(&[moved], lvl).ok()
}

/// The safety factor on an unknown's last level difference given the
/// history of its differences `h` (oldest first, the last one `this`
/// level's), with a stall guard: the differences falling geometrically
/// with ratio `ρ`, the remaining error
/// is about `d·ρ/(1 − ρ)`. `ρ` is the larger of the last two ratios, so a
/// ratio that is not clearly contracting is not trusted on one sighting.
/// While at most [`UNCONFIRMED_DIFFERENCES`] differences exist the factor
/// is at least [`UNCONFIRMED_FACTOR`]: the grid's largest difference
/// contracts faster than the slowest point (measured: the flat punch's
/// and `examples/mms.lmx`'s `p(0)` were off by 1.007 and 1.012 times
/// their level difference on the third level, their grids' ratios small).
/// When the differences do not shrink (`ρ ≥ 1`) there is no geometric
/// tail; the factor is then `1 + dₙ₋₁/dₙ`, at least
/// [`UNCONFIRMED_FACTOR`]: this level's error is at most its difference
/// plus the last level's error, and that is taken as the last level's own
/// difference. (It was 1, the bare last difference: measured on the flat
/// punch at level cap 4 with [`SplitOptions::fields_converge`], when its
/// plain end was graded like a singular point, `p(0)` was off by 2.08e-5
/// against the estimate 2.05e-5 while the differences grew.)
/// Infinite without two finite differences (one difference cannot tell a
/// converged field from a stalled one).
fn safety_factor(h: &[f64]) -> f64 {
    let n = h.len();
    if n < 2 || !h[n - 1].is_finite() || !h[n - 2].is_finite() {
        return f64::INFINITY;
    }
    let ratio = |a: f64, b: f64| {
        if a == 0.0 {
            0.0
        } else if b > 0.0 {
            a / b
        } else {
            f64::INFINITY
        }
    };
    let mut r = ratio(h[n - 1], h[n - 2]);
    if n >= 3 && h[n - 3].is_finite() {
        r = r.max(ratio(h[n - 2], h[n - 3]));
    }
    let tail = if r < 1.0 {
        (r / (1.0 - r)).max(1.0)
    } else {
        // Not shrinking: no tail to sum, so the error of this level is
        // bounded by its difference plus the last level's error, taken as
        // that level's own difference.
        (1.0 + h[n - 2] / h[n - 1]).max(UNCONFIRMED_FACTOR)
    };
    if n <= UNCONFIRMED_DIFFERENCES {
        tail.max(UNCONFIRMED_FACTOR)
    } else {
        tail
    }
}

/// Up to this many level differences of an unknown, its safety factor is
/// at least [`UNCONFIRMED_FACTOR`] ([`safety_factor`]).
const UNCONFIRMED_DIFFERENCES: usize = 3;

/// The smallest safety factor on an unknown's level difference while its
/// contraction is unconfirmed ([`safety_factor`]).
const UNCONFIRMED_FACTOR: f64 = 2.0;

/// Per unknown of `this` level, `(estimate, factor, floor)` of
/// [`UnknownEstimate`]; none when `this` carries no level differences.
fn unknown_estimates(levels: &[Level], this: &Level) -> Vec<(f64, f64, f64)> {
    this.unknowns
        .iter()
        .enumerate()
        .map(|(u, &d)| {
            let floor = this
                .floors
                .get(u)
                .copied()
                .flatten()
                .unwrap_or_else(|| rounding_floor(this.cond) * this.sizes[u].max(1.0));
            let factor = if refines(levels, this) {
                let mut h: Vec<f64> = levels
                    .iter()
                    .filter_map(|l| l.unknowns.get(u).copied())
                    .collect();
                h.push(d);
                safety_factor(&h)
            } else {
                f64::INFINITY
            };
            let est = if factor.is_finite() {
                (factor * d).max(floor)
            } else {
                f64::INFINITY
            };
            (est, factor, floor)
        })
        .collect()
}

/// The estimate that decides convergence: the largest of every scalar's,
/// output's and free coefficient's [`level_estimate`] (a coefficient a
/// condition fixes is excluded), each divided by `max(1, |value|)`, and
/// with `fields` (`Some(tol/field_tol)`, [`field_scale`]) of every
/// unknown's largest pointwise estimate on the output grid
/// ([`unknown_estimates`]) divided by `max(1, size)` (its size being its
/// largest `|u/weight|` there) and multiplied by `tol/field_tol`:
/// converged (this at most `tol`) means every scalar's, output's and
/// coefficient's absolute estimate is within `tol·max(1, |value|)` (the
/// rule of [`crate::report`]) and every unknown's within
/// `field_tol·max(1, size)` at every point of the grid kept
/// ([`LevelFields::on_grid`] leaves out a singular term's own point, the
/// ends the end check graded and points within the scalars' estimate of
/// an end that moves with them). Measured with the unknowns in
/// (`probes/unknowns_ladder.rs`): the flat punch's `p(0)`
/// (`examples/contact/flat_punch.lmx`, an end where the operator weighs
/// `p` by `t`) was off by 2.1e-5, 4.2e-4 and 1.7e-3 on levels 5, 7 and 9
/// while that end was graded like a singular point; graded with few
/// layers ([`super::split::PLAIN_END_LAYERS`]) it converges after six
/// levels. A field tolerance below `32·ε·κ` (1e-10 at `κ = 1.4e4`, the
/// contact gallery's last levels) is not reached: the fields' estimates
/// are floored there ([`unknown_estimates`]).
fn estimate(
    problem: &SplitProblem,
    levels: &[Level],
    this: &Level,
    fields: Option<f64>,
) -> f64 {
    let rel = |e: f64, v: f64| e / v.abs().max(1.0);
    let scalars = (0..this.scalars.len()).map(|i| {
        rel(
            estimate_of(levels, this, &|l| &l.scalars, i),
            this.scalars[i],
        )
    });
    let outputs = (0..this.outputs.len())
        .map(|i| rel(output_estimate(problem, levels, this, i), this.outputs[i]));
    // A coefficient a condition fixes (`condition B = 0`) is that value at
    // the root by definition; its computed value differs from it by the
    // root solve's residual, which the scalars' estimates already carry.
    let fixed = |i: usize| {
        problem
            .contact
            .conditions
            .iter()
            .any(|c| c.coefficient == i)
    };
    let coefficients = (0..this.coefficients.len())
        .filter(|&i| !fixed(i))
        .map(|i| {
            rel(
                coefficient_estimate(levels, this, i),
                this.coefficients[i],
            )
        });
    // Each unknown's largest pointwise estimate on the output grid,
    // relative to `max(1, size)` (its largest `|u/weight|` there): a
    // field's absolute error is within `tol` where it is of order one or
    // below, and within `tol` of its own size where it is larger, as a
    // scalar's is within `tol·max(1, |value|)`.
    let unknowns = unknown_estimates(levels, this)
        .into_iter()
        .zip(&this.sizes)
        .filter_map(|((e, _, _), &size)| fields.map(|scale| scale * rel(e, size)));
    scalars
        .chain(outputs)
        .chain(coefficients)
        .chain(unknowns)
        .fold(0.0, f64::max)
}

#[allow(clippy::too_many_arguments)]
pub(super) fn report(
    problem: &SplitProblem,
    d: &Discrete,
    climbed: &[Level],
    this: &Level,
    est: f64,
    converged: bool,
    opts: &SplitOptions,
    levels: usize,
    rt: f64,
) -> SplitReport {
    let tol = opts.tol;
    let err = |f: &dyn Fn(&Level) -> &[f64], i: usize, extra: f64| {
        estimate_of(climbed, this, f, i) + extra
    };
    let c = &problem.contact;
    let mut rep = SplitReport {
        scalars: c
            .scalars
            .iter()
            .enumerate()
            .map(|(i, s)| Estimate {
                name: s.name.clone(),
                value: this.scalars[i],
                error: err(&|l| &l.scalars, i, rt),
            })
            .collect(),
        outputs: problem
            .sys
            .outputs
            .iter()
            .enumerate()
            .map(|(i, o)| Estimate {
                name: o.name.clone(),
                value: this.outputs[i],
                error: output_estimate(problem, climbed, this, i),
            })
            .collect(),
        coefficients: c
            .coefficients
            .iter()
            .enumerate()
            .map(|(i, n)| Estimate {
                name: n.clone(),
                value: this.coefficients[i],
                error: coefficient_estimate(climbed, this, i),
            })
            .collect(),
        unknowns: if this.unknowns.is_empty() {
            Vec::new()
        } else {
            unknown_estimates(climbed, this)
                .into_iter()
                .enumerate()
                .map(|(u, (error, factor, floor))| UnknownEstimate {
                    name: problem.sys.unknowns[u].clone(),
                    size: this.sizes[u],
                    error,
                    factor,
                    floor,
                    left_out: this.left_out.get(u).cloned().unwrap_or_default(),
                })
                .collect()
        },
        method: problem.method().name().to_string(),
        error_estimate: est,
        converged,
        tol,
        field_tol: opts.fields_converge.then_some(opts.field_tol),
        levels,
        dim: SplitProblem::size(d),
        cond: d.cond,
        singular_exponents: d
            .terms
            .iter()
            .map(|t| (problem.sys.unknowns[t.unknown].clone(), t.at, t.beta))
            .collect(),
        end_answer: None,
        end_check: problem.end_check().cloned(),
        stopped: None,
        uniqueness: problem.weight_note.clone(),
    };
    // A coefficient a condition fixes to a value that depends on the
    // scalars (JKR: `B = -C/sqrt(a)`) moves with them: its estimate adds
    // the change of that value when each scalar moves by its estimate.
    // Measured on `examples/contact/jkr_indentation.lmx`: B off by 2.69e-13
    // against a level estimate of 2.67e-13.
    for cond in &c.conditions {
        let base = cond.value.eval(&d.vars, 0.0);
        let mut moved = 0.0f64;
        for (i, s) in rep.scalars.iter().enumerate() {
            if i < d.vars.len() {
                let mut vars = d.vars.clone();
                vars[i] += s.error;
                moved = moved.max((cond.value.eval(&vars, 0.0) - base).abs());
            }
        }
        if let Some(e) = rep.coefficients.get_mut(cond.coefficient) {
            e.error += if moved.is_nan() { f64::INFINITY } else { moved };
        }
    }
    // Side conditions that contradict the equations leave a least-squares
    // residual: no answer is more accurate than it (relative, as it is).
    if d.consistency > 0.0 {
        for e in rep
            .scalars
            .iter_mut()
            .chain(rep.outputs.iter_mut())
            .chain(rep.coefficients.iter_mut())
        {
            e.error = e.error.max(d.consistency * e.value.abs().max(1.0));
        }
        rep.error_estimate = rep.error_estimate.max(d.consistency);
        rep.converged = rep.converged && rep.error_estimate <= tol;
    }
    // An answer on the level where grading the ends moved it (the last
    // level allowed): each estimate is at least its change.
    if let Some(c) = problem
        .end_check()
        .filter(|c| c.graded && c.level + 1 == levels)
    {
        for e in rep.scalars.iter_mut().chain(rep.outputs.iter_mut()) {
            if let Some(ch) = c
                .changes
                .iter()
                .chain(&c.outputs)
                .find(|ch| ch.name == e.name)
            {
                e.error = e.error.max(ch.change);
            }
        }
    }
    rep
}

/// The map between a scalar `x` in its declared range `(lo, hi)` and the
/// variable `s ∈ ℝ` the root is solved in: `s = ln((x - lo)/(hi - x))` on
/// a finite range, `s = ln(x - lo)` on `(lo, ∞)`, `s = -ln(hi - x)` on
/// `(-∞, hi)`, `s = asinh(x)` on the whole line. A root close to an end
/// (a stick radius `c → 0` or `c → 1`) is then as easy to bracket and to
/// resolve to a *relative* accuracy in its distance to the end as one in
/// the middle.
#[derive(Debug, Clone, Copy)]
pub(super) struct ScalarMap {
    pub(super) lo: f64,
    pub(super) hi: f64,
}

impl ScalarMap {
    pub(super) fn x(&self, s: f64) -> f64 {
        let (lo, hi) = (self.lo, self.hi);
        match (lo.is_finite(), hi.is_finite()) {
            (true, true) => {
                if s < 0.0 {
                    let e = s.exp();
                    lo + (hi - lo) * e / (1.0 + e)
                } else {
                    hi - (hi - lo) / (1.0 + s.exp())
                }
            }
            (true, false) => lo + s.exp(),
            (false, true) => hi - (-s).exp(),
            (false, false) => s.sinh(),
        }
    }

    pub(super) fn s(&self, x: f64) -> f64 {
        let (lo, hi) = (self.lo, self.hi);
        match (lo.is_finite(), hi.is_finite()) {
            (true, true) => ((x - lo) / (hi - x)).ln(),
            (true, false) => (x - lo).ln(),
            (false, true) => -(hi - x).ln(),
            (false, false) => x.asinh(),
        }
    }

    /// `dx/ds` at `s`: `(x - lo)(hi - x)/(hi - lo)` on a finite range.
    fn dx_ds(&self, s: f64) -> f64 {
        let (lo, hi) = (self.lo, self.hi);
        let x = self.x(s);
        match (lo.is_finite(), hi.is_finite()) {
            (true, true) => (x - lo) * (hi - x) / (hi - lo),
            (true, false) => x - lo,
            (false, true) => hi - x,
            (false, false) => s.cosh(),
        }
    }

    /// The tolerance in `s` for a root near `s` that is to be within the
    /// absolute tolerance `xtol` in `x`: `xtol/(4 dx/ds)` (a quarter of
    /// it, so that in the middle of a unit range it is `xtol` in `s` as
    /// before), but at most
    /// [`S_REL_TOL`] (so a root near an end still has its distance to the
    /// end to that relative accuracy) and at least a few ulps of `x`
    /// (closer than that the iterations only step between neighbouring
    /// floating-point numbers: measured at `1 - c = 4.3e-7`, where one ulp
    /// of `c` is `2.6e-10` in `s`).
    fn s_tolerance(&self, s: f64, xtol: f64) -> f64 {
        let dxds = self.dx_ds(s);
        if !(dxds > 0.0 && dxds.is_finite()) {
            return xtol;
        }
        let ulps = self.s_ulps(s);
        // `dx/ds ≤ (hi - lo)/4`: in the middle of the range this is
        // `xtol` in `s`, the tolerance the solver always had there.
        (0.25 * xtol / dxds).min(S_REL_TOL).max(ulps).max(xtol)
    }

    /// Four ulps of `x(s)` in the map's variable, `4ε|x|/(dx/ds)`: a
    /// step in `s` shorter than about this may leave `x` unchanged (within
    /// `1e-10` of the upper end of a unit range it is more than `1e-6`);
    /// 0 (no floor) where `dx/ds` is not a positive number.
    pub(super) fn s_ulps(&self, s: f64) -> f64 {
        let dxds = self.dx_ds(s);
        if !(dxds > 0.0 && dxds.is_finite()) {
            return 0.0;
        }
        4.0 * f64::EPSILON * self.x(s).abs() / dxds
    }

    /// Whether `x(s)` is within `1e-8` (relative) of an end.
    fn near_end(&self, s: f64) -> bool {
        self.lo.is_finite() && self.hi.is_finite() && s.abs() > 8.0 * 10f64.ln()
    }

    /// Whether `x(s)` is strictly inside the range (and so a distinct
    /// number from both ends in floating point).
    fn inside(&self, s: f64) -> bool {
        let x = self.x(s);
        x.is_finite() && x > self.lo && x < self.hi
    }
}

/// How far the root is sought toward the upper end in the variable `s`:
/// `s ≤ 27.7`, a root at least `e^(−27.7) ≈ 9.3e-13` (relative) from the
/// upper end of a finite range (on `(lo, ∞)`: up to `e^27.7 ≈ 1e12`). For
/// the Hertz problem `1 − c ≥ 9.3e-13`, about four times the mesh floor of
/// `Mesh::graded_to_scale` there (`1e3·ε`). Measured at ν = 0.4, where the
/// slip annulus is that thin for μ ≳ 4.6: the roots `1 − c = 2.9e-11,
/// 4.9e-12, 2.4e-12, 1.6e-12` at μ = 4.64, 10, 21.5, 100 converge over
/// the levels (estimates 2–7e-11), continuing the trend toward `c∞` of
/// the resolved μ ≤ 2.15; closer, the outputs vary with `1 − c` like
/// `(1 − c)^0.4` (`P*` by 2e-8 between `1e-10` and `5e-12`), so no answer
/// at that end (`split_end.rs`) reaches a tolerance of 1e-10. The fields
/// beside such a `c` are not resolved (the shear jump there is up to 13 %
/// of `μp(c)`).
pub(super) const S_LIMIT: f64 = 27.7;

/// How far the root is sought toward the lower end: `s ≥ -23`, a root at
/// least `1e-10` (relative) from the lower end. Measured on the Hertz
/// problem: below a stick radius of about `1e-9` the discrete condition
/// `B(c)` carries rounding noise of about `4e-16/c` (the stick zone's `p`
/// is fixed by `O(c)` variations of `O(1)` rows of E1; see
/// docs/hertz_asymptotics.md). Its slope is `c·dB/dc ≈ 0.012` there, so
/// the noise moves the root by only about `3e-14` absolute, and
/// [`check_not_pole`] widens its probe to see past it. Further down (tried
/// to `s = -28`, `c ≈ 6.9e-13`) the roots are found where the asymptotics
/// put them, but the same noise, magnified about 100-fold in the stick
/// shear at the nodes nearest `c` (about `1e-14/c` to `5e-14/c`), breaks
/// the Coulomb inequality there: they would be refused anyway.
pub(super) const S_LIMIT_LO: f64 = 23.0;

/// The largest tolerance of the root in `s`: the distance of a root to the
/// nearer end of a finite range is resolved to this relative accuracy even
/// where the absolute tolerance in `x` asks for less. Below it the discrete
/// condition's own noise (see [`S_LIMIT_LO`]) is reached near the ends:
/// measured on the Hertz problem at `c = 2.06e-8` (μ = 0.03) the root moves
/// by about `1e-6` in `s` between neighbouring evaluations, and a tighter
/// tolerance only makes the iterations chase that noise.
const S_REL_TOL: f64 = 1e-6;

/// The slope of the condition (in the map's variable) expected on the
/// next level from the slopes on the levels so far: the last one times
/// the last ratio of successive slopes when that ratio is steady enough to
/// trust (same sign, between 1/16 and 16), else the last one. Measured on
/// the Hertz problem the ratio is nearly constant along the ladder
/// (1.054 per level at ν = 0.25, μ = 0.1801; 3.93 at ν = 0, μ = 100,
/// where the grading toward `1 - c ≈ 1e-3` sharpens the condition), so the
/// first Newton step of a level lands within about 1 % of its root and the
/// secant iteration usually stops after two evaluations instead of three.
/// Only the starting step depends on it; the root is the secant's.
fn predicted_slope(levels: &[Level]) -> f64 {
    match levels {
        [.., a, b] => {
            let r = b.slope / a.slope;
            if r.is_finite() && (1.0 / 16.0..=16.0).contains(&r) {
                b.slope * r
            } else {
                b.slope
            }
        }
        [b] => b.slope,
        [] => 0.0,
    }
}

/// The scalar on level `lvl`, the slope of its condition there (with
/// respect to the map's variable `s`) and the discrete solution at it.
/// `levels` are the levels solved so far (the root is warm-started from
/// the last one).
pub(super) fn find_scalar(
    problem: &SplitProblem,
    lvl: &SplitLevel,
    levels: &[Level],
    tol: f64,
) -> Result<(f64, f64, Discrete), PlanError> {
    let (lo, hi) = problem.contact.scalars[0].range;
    let name = problem.contact.scalars[0].name.as_str();
    let map = ScalarMap { lo, hi };
    // Every discretisation of this level, by the scalar's value: the
    // condition at a value already seen (the pole check and the slope
    // re-evaluate the root Brent just evaluated) is not recomputed, and
    // the discretisation at the root is reused for the bound check and
    // returned.
    let evals: std::cell::RefCell<Vec<(f64, Discrete)>> = Default::default();
    let seen = |x: f64| {
        evals
            .borrow()
            .iter()
            .rev()
            .find(|e| e.0.to_bits() == x.to_bits())
            .map(|e| e.1.residuals[0])
    };
    let mut f = |s: f64| -> Result<f64, PlanError> {
        let x = map.x(s);
        if let Some(r) = seen(x) {
            return Ok(r);
        }
        let d = problem.discretise(&[x], lvl)?;
        let r = d.residuals[0];
        evals.borrow_mut().push((x, d));
        Ok(r)
    };
    // In `s`, a step `δs` moves x by about `δs·(x - lo)(hi - x)/(hi - lo)`:
    // an absolute tolerance in `s` is a relative one in the distance to the
    // nearer end.
    let xtol = root_tolerance(tol).max(1e-15);
    let (s, slope) = match levels.last() {
        Some(l) => {
            let s0 = map.s(l.scalars[0]);
            let stol = map.s_tolerance(s0, xtol);
            let f0 = f(s0)?;
            let predicted = predicted_slope(levels);
            let mut step = if predicted != 0.0 && predicted.is_finite() {
                -f0 / predicted
            } else {
                1e-6
            };
            if step == 0.0 {
                step = 1e-12;
            }
            // A first step within a few ulps of `x` would land on `x(s0)`
            // itself (near `c → 1`, where one ulp of `c` is more than the
            // root moves from level to level), and the secant would stop
            // without a slope and fall back to a bracket and Brent (4–7
            // discretisations instead of 2). So it is at least the
            // tolerance there, which the map's ulps set: then the step
            // brackets the root and the secant stops after that one
            // evaluation. Elsewhere the step is as predicted (lengthening
            // it to the tolerance near `c → 0`, where the condition is
            // noisy on that scale, made the secant chase the noise).
            let step = step.clamp(-0.5, 0.5);
            let ulps = map.s_ulps(s0);
            let step = if step.abs() < ulps {
                stol.max(ulps).copysign(step)
            } else {
                step
            };
            match secant(&mut f, s0, f0, step, stol, 12, (-S_LIMIT_LO, S_LIMIT))? {
                Some(r) => r,
                None => {
                    let (a, fa, b, fb) = local_bracket(&mut f, s0, f0, &map)?;
                    let s = brent(&mut f, a, fa, b, fb, stol)?;
                    if let Err(e) = check_not_pole(&mut f, s, fa, fb, &map) {
                        return Err(at_end(e, name, &evals.borrow()));
                    }
                    (s, l.slope)
                }
            }
        }
        None => {
            let scanned = match scan(&mut f, &map) {
                Ok(b) => b,
                Err(e) => return Err(at_end(e, name, &evals.borrow())),
            };
            let mut rejected: Vec<(f64, String)> = Vec::new();
            // Every admissible root the brackets hold: one is the answer,
            // several are refused (the answer would be a choice).
            let mut admissible: Vec<(f64, f64)> = Vec::new();
            for &(a, fa, b, fb) in &scanned.brackets {
                let stol = map.s_tolerance(a, xtol).min(map.s_tolerance(b, xtol));
                let s = brent(&mut f, a, fa, b, fb, stol)?;
                if let Err(e) = check_not_pole(&mut f, s, fa, fb, &map) {
                    rejected.push((map.x(s), e.to_string()));
                    continue;
                }
                let x = map.x(s);
                let fresh;
                let list = evals.borrow();
                let d = match list.iter().rev().find(|e| e.0.to_bits() == x.to_bits()) {
                    Some(e) => &e.1,
                    None => {
                        fresh = problem.discretise(&[x], lvl)?;
                        &fresh
                    }
                };
                if let Some((text, x, l, r)) = problem.inequality_violation(d) {
                    rejected.push((
                        map.x(s),
                        format!(
                            "the root {:.6e} violates the inequality `{text}`: at x = {x:.4e} the smaller side is {l:.3e}, above {r:.3e} by {:.3e}",
                            map.x(s),
                            l - r
                        ),
                    ));
                    continue;
                }
                admissible.push((s, x));
            }
            if admissible.len() > 1 {
                return Err(several_roots(name, &map, &admissible));
            }
            let Some(&(s, _)) = admissible.first() else {
                // The admissible root, if any, is beyond the resolved range
                // at the end where the condition is smaller in size.
                let (left, right) = (scanned.left, scanned.right);
                let toward_hi = right.1.abs() < left.1.abs();
                let (end, end_value, reached, resolved) = if toward_hi {
                    (RangeEnd::Upper, hi, map.x(right.0), (-S_LIMIT).exp())
                } else {
                    (RangeEnd::Lower, lo, map.x(left.0), (-S_LIMIT_LO).exp())
                };
                let message = format!(
                    "no admissible root of the condition in ({lo}, {hi}) between {:.3e} and {:.3e}: {}; an admissible root, if any, lies closer than {:.1e} (relative) to the end {lo} or {:.1e} to the end {hi}, which the solver does not resolve",
                    map.x(-S_LIMIT_LO),
                    map.x(S_LIMIT),
                    rejected
                        .iter()
                        .map(|r| r.1.as_str())
                        .collect::<Vec<_>>()
                        .join("; "),
                    (-S_LIMIT_LO).exp(),
                    (-S_LIMIT).exp()
                );
                let e = PlanError::RootAtEnd(Box::new(RootAtEnd {
                    scalar: String::new(),
                    end,
                    end_value,
                    resolved,
                    reached,
                    trend: Vec::new(),
                    reason: EndReason::NoneAdmissible { rejected },
                    message,
                }));
                return Err(at_end(e, name, &evals.borrow()));
            };
            // A step the map's variable resolves: within `1e-10` of an end
            // of a unit range one ulp of `x` is more than `1e-6` in `s`,
            // and `x(s + 1e-6)` would be `x(s)` itself (slope 0).
            let h = map.s_ulps(s).max(1e-6);
            let slope = (f(s + h)? - f(s)?) / h;
            (s, slope)
        }
    };
    let x = map.x(s);
    let d = match evals.into_inner().into_iter().rev().find(|e| e.0 == x) {
        Some(e) => e.1,
        None => problem.discretise(&[x], lvl)?,
    };
    Ok((x, slope, d))
}

/// The brackets of sign changes of the condition `f(s)` in the map's
/// variable, lowest first: a grid of seven points `s = -6, -4, …, 6`
/// (`x` from about `2.5e-3` to `1 - 2.5e-3` of a finite range) and points
/// toward the lower end with steps 2, 4, 8, … in `s` (to `s = -S_LIMIT_LO`,
/// or to the last `s` where the discretisation works) until the sign
/// changes; only if neither shows a sign change, the same toward the upper
/// end. The caller solves every bracket and refuses several admissible
/// roots: a contact condition may have further roots accumulating at the
/// upper end (`c → 1`), which the Coulomb inequality rejects. Two roots
/// between neighbouring points of the grid are not seen. No sign change
/// at all is refused, naming the end toward which the condition kept its
/// sign.
#[allow(clippy::type_complexity)]
fn scan<F>(f: &mut F, map: &ScalarMap) -> Result<Scan, PlanError>
where
    F: FnMut(f64) -> Result<f64, PlanError>,
{
    let (lo, hi) = (map.lo, map.hi);
    let spacing = if lo.is_finite() && hi.is_finite() {
        2.0
    } else {
        4f64.ln()
    };
    let grid: Vec<f64> = (-3..4).map(|i| spacing * f64::from(i)).collect();
    let mut pts: Vec<(f64, f64)> = Vec::new();
    let mut first_err: Option<PlanError> = None;
    for &s in &grid {
        match f(s) {
            Ok(v) if v.is_finite() => pts.push((s, v)),
            Ok(_) => {}
            // A fault of the input fails everywhere: report it at once.
            Err(e) if e.is_input_error() => return Err(e),
            Err(e) => {
                first_err.get_or_insert(e);
            }
        }
    }
    let (Some(&first), Some(&last)) = (pts.first(), pts.last()) else {
        if let Some(e) = first_err {
            return Err(e);
        }
        return Err(PlanError::Numeric {
            context: "scalar root".into(),
            source: NumericError::NoConvergence(
                "the condition could not be evaluated in the declared range".into(),
            ),
        });
    };
    let mut out = Vec::new();
    // Toward one end from `start`, steps 2, 4, 8, … in s (`dir` = ±1).
    let extend = |f: &mut F,
                  start: (f64, f64),
                  dir: f64|
     -> ((f64, f64), Option<(f64, f64, f64, f64)>, Option<PlanError>) {
        let mut at = start;
        let mut step = 2.0;
        loop {
            let s = at.0 + dir * step;
            let s = s.clamp(-S_LIMIT_LO, S_LIMIT);
            if s == at.0 || !map.inside(s) {
                return (at, None, None);
            }
            match f(s) {
                Ok(v) if v.is_finite() => {
                    if v.signum() != at.1.signum() || v == 0.0 {
                        let b = if dir < 0.0 {
                            (s, v, at.0, at.1)
                        } else {
                            (at.0, at.1, s, v)
                        };
                        return (at, Some(b), None);
                    }
                    at = (s, v);
                }
                Ok(_) => return (at, None, None),
                Err(e) => return (at, None, Some(e)),
            }
            step *= 2.0;
        }
    };
    let (left, lb, l_err) = extend(f, first, -1.0);
    out.extend(lb);
    for i in 1..pts.len() {
        if pts[i - 1].1.signum() != pts[i].1.signum() || pts[i].1 == 0.0 {
            out.push((pts[i - 1].0, pts[i - 1].1, pts[i].0, pts[i].1));
        }
    }
    if !out.is_empty() {
        return Ok(Scan {
            brackets: out,
            left,
            right: last,
        });
    }
    let (right, rb, r_err) = extend(f, last, 1.0);
    out.extend(rb);
    if !out.is_empty() {
        return Ok(Scan {
            brackets: out,
            left,
            right,
        });
    }
    // It keeps one sign; the root, if any, lies beyond the end where |f|
    // is smaller.
    let toward_hi = right.1.abs() < left.1.abs();
    let (end, reached, err) = if toward_hi {
        (hi, map.x(right.0), r_err)
    } else {
        (lo, map.x(left.0), l_err)
    };
    let why = match &err {
        Some(e) => format!(" (beyond it the discretisation fails: {e})"),
        None => String::new(),
    };
    Err(PlanError::RootAtEnd(Box::new(RootAtEnd {
        scalar: String::new(),
        end: if toward_hi {
            RangeEnd::Upper
        } else {
            RangeEnd::Lower
        },
        end_value: end,
        resolved: (-if toward_hi { S_LIMIT } else { S_LIMIT_LO }).exp(),
        reached,
        trend: Vec::new(),
        reason: EndReason::NoSignChange {
            failed_beyond: err.map(|e| e.to_string()),
        },
        message: format!(
            "no sign change of the condition in ({lo}, {hi}): it keeps one sign from {:.6e} to {:.6e} and is smallest in size toward {end} (reached {reached:.6e}, {:.3e} from it){why}; the root, if any, lies closer to the end {end} than the solver resolves ({:.1e} relative)",
            map.x(left.0),
            map.x(right.0),
            (end - reached).abs(),
            (-if toward_hi { S_LIMIT } else { S_LIMIT_LO }).exp(),
        ),
    })))
}

/// The refusal of a condition with several admissible roots `(s, x)`,
/// naming each and how to select one.
fn several_roots(name: &str, map: &ScalarMap, roots: &[(f64, f64)]) -> PlanError {
    PlanError::Numeric {
        context: "scalar root".into(),
        source: NumericError::NoConvergence(format!(
            "the condition for {name} has {} admissible roots in ({}, {}): {}; state an inequality that tells them apart, or narrow the range in `scalar {name} in (lo, hi)` to one of them (its ends may be parameters, set with --set)",
            roots.len(),
            map.lo,
            map.hi,
            roots
                .iter()
                .map(|(_, x)| format!("{name} = {x:.12e}"))
                .collect::<Vec<_>>()
                .join(", ")
        )),
    }
}

/// What [`scan`] found: the brackets of sign changes, lowest first, and
/// the points `(s, condition)` it reached toward the lower and the upper
/// end.
struct Scan {
    brackets: Vec<(f64, f64, f64, f64)>,
    left: (f64, f64),
    right: (f64, f64),
}

/// `e` with the scalar's name and the condition's measured trend (every
/// evaluation of the level, ascending in the scalar) filled in, if it is a
/// [`PlanError::RootAtEnd`].
fn at_end(e: PlanError, scalar: &str, evals: &[(f64, Discrete)]) -> PlanError {
    match e {
        PlanError::RootAtEnd(mut r) => {
            r.scalar = scalar.to_string();
            let mut trend: Vec<(f64, f64)> = evals
                .iter()
                .filter_map(|(x, d)| d.residuals.first().map(|&v| (*x, v)))
                .collect();
            trend.sort_by(|a, b| a.0.total_cmp(&b.0));
            trend.dedup_by(|a, b| a.0 == b.0);
            r.trend = trend;
            PlanError::RootAtEnd(r)
        }
        e => e,
    }
}

/// A bracket around `s0` (the map's variable) by steps growing outward on
/// both sides.
fn local_bracket<F>(
    f: &mut F,
    s0: f64,
    f0: f64,
    map: &ScalarMap,
) -> Result<(f64, f64, f64, f64), PlanError>
where
    F: FnMut(f64) -> Result<f64, PlanError>,
{
    let mut h = 1e-6;
    for _ in 0..40 {
        for s in [s0 - h, s0 + h] {
            if (-S_LIMIT_LO..=S_LIMIT).contains(&s) && map.inside(s) {
                let v = f(s)?;
                if v.signum() != f0.signum() || v == 0.0 {
                    return Ok(if s < s0 {
                        (s, v, s0, f0)
                    } else {
                        (s0, f0, s, v)
                    });
                }
            }
        }
        h *= 2.0;
    }
    Err(PlanError::Numeric {
        context: "scalar root".into(),
        source: NumericError::NoConvergence(format!(
            "no sign change of the condition near {}",
            map.x(s0)
        )),
    })
}

/// Refuses a "root" `s` (at `x`) that is a sign change across a pole: at
/// a root `|f|` grows away from `s` (to about `|f'|·δ` at `s ± δ`, with
/// opposite signs); at a pole it falls (`|f(s)| ≫ |f(s ± δ)|` for every
/// `δ` wider than the distance to the pole, which is within the root
/// tolerance). The first probe, `δ = 1e-3`, accepts a root when `|f(s)|`
/// is below 1% of both values beside it. If it does not, and the values
/// beside `s` are not both smaller than `|f(s)|` (a pole's shape), the
/// probe widens by 4 up to [`POLE_PROBE_MAX`] and accepts once the values
/// have opposite signs and `|f(s)|` is below 10% of both: near `c → 0` the
/// Hertz condition carries rounding noise of about `4e-16/c` (the stick
/// zone's `p` is fixed by `O(c)` variations of `O(1)` rows of E1;
/// docs/hertz_asymptotics.md), and at `c = 1e-12` the values beside a
/// root stand out of it only at `δ ≈ 0.3`. A pole is refused at every `δ`
/// (there `|f(s)|/|f(s ± δ)| ≈ δ/|s − pole| ≫ 10`). The condition's own
/// scale does not enter (it is tiny when the scalar is: `B ∝ c` for a
/// stick radius `c → 0`), only its local shape.
///
/// Near an end of the range a refusal is a [`PlanError::RootAtEnd`] (the
/// root may be one the solver cannot place).
fn check_not_pole<F>(f: &mut F, s: f64, fa: f64, fb: f64, map: &ScalarMap) -> Result<(), PlanError>
where
    F: FnMut(f64) -> Result<f64, PlanError>,
{
    let x = map.x(s);
    let fx = f(s)?;
    if fx == 0.0 || fx.abs() <= 1e-9 * (fa.abs() + fb.abs()) {
        return Ok(());
    }
    let mut delta = 1e-3;
    let (mut fl, mut fr) = (f(s - delta)?, f(s + delta)?);
    let mut ratio = 1e-2;
    loop {
        if fl.signum() != fr.signum() && fx.abs() <= ratio * fl.abs().min(fr.abs()) {
            return Ok(());
        }
        if fl.abs().max(fr.abs()) < fx.abs() || 4.0 * delta > POLE_PROBE_MAX {
            break;
        }
        delta *= 4.0;
        ratio = 0.1;
        (fl, fr) = (f(s - delta)?, f(s + delta)?);
    }
    let base = format!(
        "the condition changes sign across a pole near {x:.6e} (value {fx:.3e}, {fl:.3e} and {fr:.3e} at s ∓ {delta}), not a root"
    );
    if !map.near_end(s) {
        return Err(PlanError::Numeric {
            context: "scalar root".into(),
            source: NumericError::NoConvergence(base),
        });
    }
    let (end, end_value, resolved) = if s < 0.0 {
        (RangeEnd::Lower, map.lo, (-S_LIMIT_LO).exp())
    } else {
        (RangeEnd::Upper, map.hi, (-S_LIMIT).exp())
    };
    Err(PlanError::RootAtEnd(Box::new(RootAtEnd {
        scalar: String::new(),
        end,
        end_value,
        resolved,
        reached: x,
        trend: Vec::new(),
        reason: EndReason::Noisy {
            at: x,
            values: (fl, fx, fr),
        },
        message: format!(
            "{base}; this close to an end of the range the discrete condition is noisy (measured on the Hertz problem: about 4e-16/c at a stick radius c), so this may be a root the solver cannot place"
        ),
    })))
}

/// The widest probe of [`check_not_pole`] in the map's variable `s`.
const POLE_PROBE_MAX: f64 = 1.1;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_level_estimate_bounds_errors_that_fall_only_every_other_level() {
        // The torque of examples/punch_torsion.lmx at w = 1.01, levels 4–8
        // (true value 0.428532699810415594): errors 5.06e-10, 2.90e-10,
        // 2.74e-11, 1.63e-11, 1.68e-12 (measured with --max-level).
        let exact = 0.428_532_699_810_415_6;
        let h = [5.06e-10, 2.90e-10, 2.74e-11, 1.63e-11, 1.68e-12].map(|e| exact + e);
        for n in 3..=h.len() {
            let est = level_estimate(&h[..n]);
            let err = (h[n - 1] - exact).abs();
            assert!(
                est >= err,
                "level {n}: estimate {est:.1e} < error {err:.1e}"
            );
        }
        // The last difference alone would not bound level 7's error.
        assert!((h[3] - h[2]).abs() < (h[3] - exact).abs());
        // Fast geometric convergence keeps the last difference.
        let g: [f64; 4] = [1.0, 1.0 + 1e-3, 1.0 + 1e-3 + 1e-5, 1.0 + 1e-3 + 1e-5 + 1e-7];
        let last = (g[3] - g[2]).abs();
        assert!((level_estimate(&g) - last).abs() <= 1e-6 * last);
        // Slow geometric convergence (ratio 0.8): the geometric tail.
        let s: Vec<f64> = (0..5).map(|k| 0.8_f64.powi(k)).collect();
        let last = (s[4] - s[3]).abs();
        assert!((level_estimate(&s) - last * 4.0).abs() <= 1e-12);
        // Never below 32 ulps; fewer than three levels have no estimate.
        assert_eq!(level_estimate(&[2.0, 2.0, 2.0]), 64.0 * f64::EPSILON);
        assert!(level_estimate(&[1.0, 1.0 + 1e-20]).is_infinite());
        assert!(level_estimate(&[1.0]).is_infinite());
    }

    /// `level_estimate` bounds the true error on every prefix of `h` from
    /// three levels on; returns the prefixes on which the last difference
    /// alone did not (the stalls).
    fn bounds_every_level(h: &[f64], exact: f64) -> Vec<usize> {
        let mut stalls = Vec::new();
        for n in 3..=h.len() {
            let (est, err) = (level_estimate(&h[..n]), (h[n - 1] - exact).abs());
            assert!(
                est >= err,
                "{n} levels: estimate {est:.1e} < error {err:.1e}"
            );
            if (h[n - 1] - h[n - 2]).abs() < err {
                stalls.push(n);
            }
        }
        stalls
    }

    #[test]
    fn the_level_estimate_does_not_trust_a_stalled_difference() {
        // The torque of examples/punch_torsion.lmx at w = 3/2, μ = 1 on
        // levels 0–4 of the ladder (exact 0.4945019862481885040 from the
        // closed form, tests/contact_torsion.rs): errors 4.2e-10, 8.3e-13,
        // 7.5e-13, 4.2e-14, 2.4e-15. Levels 1 and 2 differ by 8.1e-14, a
        // tenth of their error; the estimate without the stall guard was
        // that difference, 8.1e-14, on level 2.
        let torque = [
            0.494_501_986_664_462_66,
            0.494_501_986_249_014_5,
            0.494_501_986_248_933_66,
            0.494_501_986_248_230_33,
            0.494_501_986_248_190_86,
        ];
        let exact = 0.494_501_986_248_188_53;
        assert_eq!(bounds_every_level(&torque, exact), vec![3]);
        // P of the Hertz problem at (ν, μ) = (−0.6, 100), levels 0–4 (the
        // reference from levels 7–10 of the same ladder): errors 7.2e-8,
        // 1.1e-9, 2.4e-12, 2.9e-12, 3.2e-13. Levels 2 and 3 differ by
        // 4.8e-13 only: the stall is on level 3, after two honest ratios.
        let p = [
            1.212_338_544_252_097_3,
            1.212_338_474_304_729_9,
            1.212_338_472_710_854_4,
            1.212_338_472_710_377_6,
            1.212_338_472_712_915,
        ];
        assert_eq!(bounds_every_level(&p, 1.212_338_472_713_235), vec![4]);
        // Levels that agree exactly after converging ones: the estimate is
        // what the previous ratio predicts, not the rounding floor.
        let h = [1.0, 1.0 + 1e-4, 1.0 + 1e-4 + 1e-6, 1.0 + 1e-4 + 1e-6];
        let est = level_estimate(&h);
        assert!(est >= 0.9e-8, "{est:e}");
        // Two differences only: the second is believed to fall at most
        // FASTEST_UNCONFIRMED of the first.
        let est = level_estimate(&[1.0, 1.0 + 1e-4, 1.0 + 1e-4]);
        assert!(est >= 0.99e-4 * FASTEST_UNCONFIRMED, "{est:e}");
    }

    #[test]
    fn the_level_estimate_does_not_trust_a_difference_that_turns_back() {
        // tests/data/traps/contact_spike_8.lmx at the default tolerance,
        // levels 0–4 (exact a = √(1/2), P = (8/3)a³).
        let a = [
            0.707_106_771_258_991,
            0.707_106_780_792_587,
            0.707_106_781_135_340_1,
            0.707_106_781_164_821_3,
            0.707_106_781_164_621_6,
        ];
        let exact_a = std::f64::consts::FRAC_1_SQRT_2;
        assert_eq!(bounds_every_level(&a, exact_a), vec![5]);
        let p = [
            0.942_809_013_869_512_2,
            0.942_809_040_605_730_8,
            0.942_809_041_458_665_3,
            0.942_809_041_537_230_7,
            0.942_809_041_514_966_4,
        ];
        let exact_p = 0.942_809_041_582_063_4;
        assert_eq!(bounds_every_level(&p, exact_p), vec![5]);
        // Without the turn the stall guard alone decides: a monotone
        // history with the same magnitudes gets the smaller estimate.
        let mut mono = a;
        mono[4] = a[3] + (a[4] - a[3]).abs();
        assert!(level_estimate(&mono) < level_estimate(&a));
        // Without the guard the last level's estimate is below its error.
        let unguarded = level_estimate_guarded(&a, false);
        assert!(unguarded < (a[4] - exact_a).abs(), "{unguarded:e}");
    }

    #[test]
    fn the_scalar_map_is_invertible_and_resolves_both_ends() {
        let m = ScalarMap { lo: 0.0, hi: 1.0 };
        for x in [1e-12, 1e-3, 0.25, 0.5, 0.9, 1.0 - 1e-9] {
            let back = m.x(m.s(x));
            assert!((back - x).abs() <= 1e-15 * x.max(1e-3), "{x} {back}");
        }
        // Near 1 the distance 1 - x is carried to a relative accuracy.
        let s = m.s(1.0 - 1e-9);
        assert!(((1.0 - m.x(s)) / 1e-9 - 1.0).abs() < 1e-6);
        assert!(m.inside(S_LIMIT) && m.inside(-S_LIMIT_LO) && !m.inside(40.0));
        let half = ScalarMap {
            lo: 0.0,
            hi: f64::INFINITY,
        };
        assert!((half.x(half.s(0.3)) - 0.3).abs() < 1e-15);
    }

    #[test]
    fn a_step_of_the_maps_ulps_moves_x_where_a_millionth_does_not() {
        // Near full stick (ν = 0.4, μ = 4.64: 1 − c = 2.9e-11; the
        // resolved limit s = S_LIMIT) a step of 1e-6 in s leaves c where
        // it is, so a slope from it is 0 and a secant from it stops: the
        // level-0 slope and the warm start's first step use at least
        // `s_ulps`, which moves c by a few ulps and no more.
        let m = ScalarMap { lo: 0.0, hi: 1.0 };
        let mut stuck = 0;
        for s in [m.s(1.0 - 2.9e-11), m.s(1.0 - 1.6e-12), S_LIMIT] {
            let x = m.x(s);
            stuck += usize::from(m.x(s + 1e-6) == x);
            let h = m.s_ulps(s).max(1e-6);
            for step in [h, -h] {
                let moved = (m.x(s + step) - x).abs() / (f64::EPSILON / 2.0);
                assert!((1.0..=16.0).contains(&moved), "s = {s}: {moved} ulps");
            }
            // And it is the tolerance there: the iterations stop at it.
            assert_eq!(m.s_tolerance(s, 5e-13), m.s_ulps(s));
        }
        assert!(stuck >= 2, "the case the floor is for did not occur");
        // Elsewhere it is far below the steps the solver takes (1e-6), so
        // the warm start's predicted step is left as it is.
        for x in [1e-10, 2e-8, 0.5, 1.0 - 4.3e-7] {
            assert!(m.s_ulps(m.s(x)) < 1e-8, "{x}");
        }
        // At an end (dx/ds = 0) there is no floor.
        assert_eq!(m.s_ulps(800.0), 0.0);
    }

    #[test]
    fn the_tolerance_in_s_keeps_the_absolute_one_and_stops_at_the_ulps() {
        let m = ScalarMap { lo: 0.0, hi: 1.0 };
        let xtol = 5e-12;
        // Mid-range: the absolute tolerance itself (dx/ds = 1/4).
        let s = m.s(0.5);
        let t = m.s_tolerance(s, xtol);
        assert!((t - xtol).abs() < 1e-20, "{t}");
        // Near 0: capped by the relative accuracy of the distance to 0,
        // and still within the absolute tolerance in x.
        let s = m.s(2e-8);
        let t = m.s_tolerance(s, xtol);
        assert_eq!(t, S_REL_TOL);
        assert!((m.x(s + t) - m.x(s)).abs() <= xtol);
        // Near 1: no finer than a few ulps of x, which is coarser there
        // than the requested tolerance.
        let s = m.s(1.0 - 4.3e-7);
        let t = m.s_tolerance(s, 1e-18);
        assert!(m.x(s + t) != m.x(s) && t < 1e-8, "{t}");
        // Never tighter than the absolute tolerance itself.
        assert!(m.s_tolerance(0.0, xtol) >= xtol);
    }
}
