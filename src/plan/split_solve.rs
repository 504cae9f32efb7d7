//! Solving a split-domain problem: the unknown scalar (e.g. the stick
//! radius `c`) is found from its condition by a safeguarded root solve —
//! on the first level a scan of the declared range for a sign change
//! (refined geometrically toward the ends) and Brent's method, on every
//! further level a secant iteration warm-started from the previous root
//! with a Newton step on the previous slope (a local bracket and Brent if
//! it misbehaves) — and the levels of [`SplitLevel`] are climbed until two
//! successive levels agree to the tolerance in every scalar and output.
//! Every scalar, output and singular coefficient is reported with that
//! estimate. Owns this control logic; the discretisation is `split.rs`'s.
use serde::Serialize;

use super::error::PlanError;
use super::split::{Discrete, SplitLevel, SplitProblem};
use super::split_input::SplitInput;
use crate::numeric::NumericError;
use crate::numeric::roots::{brent, secant};
use crate::system::Program;

/// Accuracy controls.
#[derive(Debug, Clone, Copy)]
pub struct SplitOptions {
    /// Stop when two successive levels agree to this (absolute).
    pub tol: f64,
    /// Highest level tried.
    pub max_level: usize,
}

impl Default for SplitOptions {
    fn default() -> SplitOptions {
        SplitOptions {
            tol: 1e-10,
            max_level: 8,
        }
    }
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

/// A solved split-domain problem.
#[derive(Debug, Clone, Serialize)]
pub struct SplitReport {
    /// The unknown scalars.
    pub scalars: Vec<Estimate>,
    /// The outputs.
    pub outputs: Vec<Estimate>,
    /// The coefficients of the exact singular terms.
    pub coefficients: Vec<Estimate>,
    /// Largest estimate.
    pub error_estimate: f64,
    /// Whether it is within the tolerance.
    pub converged: bool,
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
}

struct Level {
    scalars: Vec<f64>,
    slope: f64,
    outputs: Vec<f64>,
    coefficients: Vec<f64>,
}

/// Tolerance of the root iterations: a twentieth of the requested
/// accuracy, added to the estimate.
fn root_tolerance(tol: f64) -> f64 {
    (0.05 * tol).clamp(1e-15, 1e-9)
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
}

/// Solves `prog` (a file with split-domain declarations).
pub fn solve_split(prog: &Program, opts: &SplitOptions) -> Result<SplitReport, PlanError> {
    solve_split_fields(prog, opts).map(|s| s.report)
}

/// [`solve_split`], keeping the compiled problem and the last
/// discretisation.
pub fn solve_split_fields(prog: &Program, opts: &SplitOptions) -> Result<SplitSolution, PlanError> {
    check_tolerance(opts)?;
    solve_split_input_fields(SplitInput::from_program(prog)?, opts)
}

fn check_tolerance(opts: &SplitOptions) -> Result<(), PlanError> {
    if !(opts.tol > 0.0 && opts.tol.is_finite()) {
        return Err(PlanError::Invalid(format!(
            "tolerance {} must be positive",
            opts.tol
        )));
    }
    Ok(())
}

/// Solves the problem `input` describes, however it was built (from a
/// program by [`solve_split`], or by a solver `lambdamat codegen` wrote).
pub fn solve_split_input(input: SplitInput, opts: &SplitOptions) -> Result<SplitReport, PlanError> {
    solve_split_input_fields(input, opts).map(|s| s.report)
}

/// [`solve_split_input`], keeping the compiled problem and the last
/// discretisation.
pub fn solve_split_input_fields(
    input: SplitInput,
    opts: &SplitOptions,
) -> Result<SplitSolution, PlanError> {
    check_tolerance(opts)?;
    let problem = SplitProblem::from_input(input)?;
    let ns = problem.contact.scalars.len();
    if ns > 1 {
        return Err(PlanError::Invalid(format!(
            "{ns} unknown scalars: the split-domain solver handles at most one so far"
        )));
    }
    let mut levels: Vec<Level> = Vec::new();
    for k in 0..=opts.max_level {
        let lvl = SplitLevel::level(k);
        let (d, scalars, slope) = if ns == 0 {
            (problem.discretise(&[], &lvl)?, vec![], 0.0)
        } else {
            let (x, slope, d) = find_scalar(&problem, &lvl, levels.last(), opts.tol)?;
            (d, vec![x], slope)
        };
        let outputs = (0..problem.sys.outputs.len())
            .map(|o| problem.output(&d, o))
            .collect::<Result<Vec<f64>, PlanError>>()?;
        let coefficients = (0..problem.contact.coefficients.len())
            .map(|c| problem.coefficient(&d, c).unwrap_or(f64::NAN))
            .collect();
        let this = Level {
            scalars,
            slope,
            outputs,
            coefficients,
        };
        let rt = if ns > 0 {
            2.0 * root_tolerance(opts.tol)
        } else {
            0.0
        };
        let est = levels.last().map(|l| distance(l, &this) + rt);
        let converged = est.is_some_and(|e| e <= opts.tol);
        if converged || k == opts.max_level {
            let est = est.unwrap_or(f64::INFINITY);
            let report = report(
                &problem,
                &d,
                levels.last(),
                &this,
                est,
                converged,
                opts.tol,
                k + 1,
                rt,
            );
            return Ok(SplitSolution {
                report,
                problem,
                discrete: d,
            });
        }
        levels.push(this);
    }
    Err(PlanError::Invalid("empty level ladder".into()))
}

fn distance(a: &Level, b: &Level) -> f64 {
    let d = |x: &[f64], y: &[f64]| {
        x.iter()
            .zip(y)
            .map(|(p, q)| (p - q).abs())
            .fold(0.0, f64::max)
    };
    d(&a.scalars, &b.scalars).max(d(&a.outputs, &b.outputs))
}

#[allow(clippy::too_many_arguments)]
fn report(
    problem: &SplitProblem,
    d: &Discrete,
    prev: Option<&Level>,
    this: &Level,
    est: f64,
    converged: bool,
    tol: f64,
    levels: usize,
    rt: f64,
) -> SplitReport {
    let err = |f: &dyn Fn(&Level) -> &[f64], i: usize, extra: f64| {
        prev.map_or(f64::INFINITY, |p| (f(p)[i] - f(this)[i]).abs() + extra)
    };
    let c = &problem.contact;
    SplitReport {
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
                error: err(&|l| &l.outputs, i, 0.0),
            })
            .collect(),
        coefficients: c
            .coefficients
            .iter()
            .enumerate()
            .map(|(i, n)| Estimate {
                name: n.clone(),
                value: this.coefficients[i],
                error: err(&|l| &l.coefficients, i, 0.0),
            })
            .collect(),
        error_estimate: est,
        converged,
        tol,
        levels,
        dim: SplitProblem::size(d),
        cond: d.cond,
        singular_exponents: d
            .terms
            .iter()
            .map(|t| (problem.sys.unknowns[t.unknown].clone(), t.at, t.beta))
            .collect(),
    }
}

/// The scalar on level `lvl`, the slope of its condition there and the
/// discrete solution at it.
fn find_scalar(
    problem: &SplitProblem,
    lvl: &SplitLevel,
    last: Option<&Level>,
    tol: f64,
) -> Result<(f64, f64, Discrete), PlanError> {
    let (lo, hi) = problem.contact.scalars[0].range;
    let mut evals: Vec<(f64, Discrete)> = Vec::new();
    let mut f = |x: f64| -> Result<f64, PlanError> {
        let d = problem.discretise(&[x], lvl)?;
        let r = d.residuals[0];
        evals.push((x, d));
        Ok(r)
    };
    let scale = |x: f64| {
        if hi.is_finite() {
            (x - lo).min(hi - x).min(1.0)
        } else {
            1.0
        }
    };
    let room = |x: f64| {
        let r = if hi.is_finite() {
            (hi - x).min(x - lo)
        } else {
            x - lo
        };
        0.25 * r
    };
    let (x, slope) = match last {
        Some(l) => {
            let x0 = l.scalars[0];
            let xtol = (root_tolerance(tol) * scale(x0)).max(1e-15);
            let f0 = f(x0)?;
            let mut step = if l.slope != 0.0 && l.slope.is_finite() {
                -f0 / l.slope
            } else {
                1e-6
            };
            if step == 0.0 {
                step = 1e-12;
            }
            let step = step.clamp(-room(x0), room(x0));
            match secant(&mut f, x0, f0, step, xtol, 12, (lo, hi))? {
                Some(r) => r,
                None => {
                    let (a, fa, b, fb) = local_bracket(&mut f, x0, f0, lo, hi)?;
                    let x = brent(&mut f, a, fa, b, fb, xtol)?;
                    check_not_pole(&mut f, x, fa, fb)?;
                    (x, l.slope)
                }
            }
        }
        None => {
            let (a, fa, b, fb) = scan(&mut f, lo, hi)?;
            let xtol = (root_tolerance(tol) * scale(0.5 * (a + b))).max(1e-15);
            let x = brent(&mut f, a, fa, b, fb, xtol)?;
            check_not_pole(&mut f, x, fa, fb)?;
            let h = 1e-6 * room(x).min(x.abs()).max(1e-12);
            let slope = (f(x + h)? - f(x)?) / h;
            (x, slope)
        }
    };
    let d = match evals.into_iter().rev().find(|e| e.0 == x) {
        Some(e) => e.1,
        None => problem.discretise(&[x], lvl)?,
    };
    Ok((x, slope, d))
}

/// A sign change of `f` in `(lo, hi)`: a grid of seven interior points
/// (geometric when `hi` is infinite), then points approaching the ends
/// geometrically. Two or more sign changes on the grid are refused: the
/// condition has several roots in the declared range.
fn scan<F>(f: &mut F, lo: f64, hi: f64) -> Result<(f64, f64, f64, f64), PlanError>
where
    F: FnMut(f64) -> Result<f64, PlanError>,
{
    let grid: Vec<f64> = if hi.is_finite() {
        (1..8)
            .map(|i| lo + (hi - lo) * f64::from(i) / 8.0)
            .collect()
    } else {
        (-3..4).map(|i| lo + 2f64.powi(i)).collect()
    };
    let mut pts: Vec<(f64, f64)> = Vec::new();
    let mut first_err: Option<PlanError> = None;
    for &x in &grid {
        match f(x) {
            Ok(v) if v.is_finite() => pts.push((x, v)),
            Ok(_) => {}
            // A fault of the input fails everywhere: report it at once.
            Err(e) if e.is_input_error() => return Err(e),
            Err(e) => {
                first_err.get_or_insert(e);
            }
        }
    }
    let changes: Vec<usize> = (1..pts.len())
        .filter(|&i| pts[i - 1].1.signum() != pts[i].1.signum() || pts[i].1 == 0.0)
        .collect();
    if changes.len() > 1 {
        let at: Vec<String> = changes
            .iter()
            .map(|&i| format!("({:.4}, {:.4})", pts[i - 1].0, pts[i].0))
            .collect();
        return Err(PlanError::Numeric {
            context: "scalar root".into(),
            source: NumericError::NoConvergence(format!(
                "the condition changes sign more than once in the declared range: in {}; narrow the scalar's range",
                at.join(", ")
            )),
        });
    }
    if let Some(&i) = changes.first() {
        let ((a, fa), (b, fb)) = (pts[i - 1], pts[i]);
        return Ok((a, fa, b, fb));
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
    // Toward the ends.
    let (mut left, mut right) = (first, last);
    for _ in 0..14 {
        let x = lo + 0.25 * (left.0 - lo);
        if let Ok(v) = f(x)
            && v.is_finite()
        {
            if v.signum() != left.1.signum() || v == 0.0 {
                return Ok((x, v, left.0, left.1));
            }
            left = (x, v);
        }
        let x = if hi.is_finite() {
            hi - 0.25 * (hi - right.0)
        } else {
            4.0 * right.0
        };
        if let Ok(v) = f(x)
            && v.is_finite()
        {
            if v.signum() != right.1.signum() || v == 0.0 {
                return Ok((right.0, right.1, x, v));
            }
            right = (x, v);
        }
    }
    Err(PlanError::Numeric {
        context: "scalar root".into(),
        source: NumericError::NoConvergence(format!(
            "no sign change of the condition found in ({lo}, {hi})"
        )),
    })
}

/// A bracket around `x0` by steps growing outward on both sides.
fn local_bracket<F>(
    f: &mut F,
    x0: f64,
    f0: f64,
    lo: f64,
    hi: f64,
) -> Result<(f64, f64, f64, f64), PlanError>
where
    F: FnMut(f64) -> Result<f64, PlanError>,
{
    let mut h = 1e-6 * x0.abs().max(1e-3);
    for _ in 0..40 {
        for x in [x0 - h, x0 + h] {
            if x > lo && x < hi {
                let v = f(x)?;
                if v.signum() != f0.signum() || v == 0.0 {
                    return Ok(if x < x0 {
                        (x, v, x0, f0)
                    } else {
                        (x0, f0, x, v)
                    });
                }
            }
        }
        h *= 2.0;
    }
    Err(PlanError::Numeric {
        context: "scalar root".into(),
        source: NumericError::NoConvergence(format!("no sign change of the condition near {x0}")),
    })
}

/// Refuses a "root" that is a sign change across a pole.
fn check_not_pole<F>(f: &mut F, x: f64, fa: f64, fb: f64) -> Result<(), PlanError>
where
    F: FnMut(f64) -> Result<f64, PlanError>,
{
    let fx = f(x)?;
    if fx.abs() <= 1e-6 * (fa.abs() + fb.abs()) {
        Ok(())
    } else {
        Err(PlanError::Numeric {
            context: "scalar root".into(),
            source: NumericError::NoConvergence(format!(
                "the condition changes sign across a pole near {x:.6e} (value {fx:.3e}), not a root"
            )),
        })
    }
}
