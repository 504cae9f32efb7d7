//! The end check of the split-domain ladder: before an answer is accepted,
//! is it the same with the mesh graded toward the ends of the unknowns'
//! interval that no `singular` declaration names? Owns that check, the
//! decision to grade those ends from then on, and its record in the
//! report ([`EndCheck`]); it must not change the level ladder itself
//! (`split_solve.rs` calls it from one place, where the ladder would
//! accept) nor the discretisation (`split.rs` grades the ends it is told
//! to, exactly as for a declared `singular u at end ~ 1`).
//!
//! **Why.** The mesh is graded toward every breakpoint and every declared
//! singular point; an end of the interval that is neither lies in a panel
//! of full degree. An unknown that behaves like `x^α` there (α not a
//! non-negative integer, or a `ln x` term) is then approximated only
//! algebraically in the degree, and the differences of successive levels
//! need not bound the error: measured on the full-slip Hertz problem
//! (`examples/hertz_frictionless.lmx` with `q = μp` on all of [0, 1], at
//! ν = 0, μ = 0.01, where `p ~ x^(−μγ)`-like at the centre), levels 1 and
//! 2 agreed to 2.9e-10 while `P` was 2.0e-8 off, and levels 10 and 11 to
//! 7e-15 while it was 1.6e-9 off. The exponent depends on the operators'
//! Mellin symbols at the end (docs/hertz.md), which the solver does not
//! derive for a general file; the check measures the effect instead.
//!
//! **The check.** Once, when the ladder's estimate first meets the
//! tolerance on level `k`, the problem is solved once more on level `k`
//! with the mesh also graded toward those ends (the layers of a declared
//! singular point). With an unknown scalar, the graded discretisation is
//! evaluated at the accepted root, and the root's move is the Newton step
//! on the level's slope (a second evaluation and a secant step when that
//! move exceeds the root tolerance; the outputs are then interpolated to
//! the moved root). Every scalar and output is compared with its own
//! estimate. If no change exceeds its estimate (and 64 ulps), the answer
//! stands and the cost was one or two solves on level `k`. If one does,
//! the end behaviour was not resolved: the mesh is graded toward those
//! ends from then on, the graded level `k` becomes the first level of a
//! new history and the ladder climbs on; on the last level allowed the
//! answer is instead marked not converged, each estimate at least its
//! change. The report says which ends were graded and by how much the
//! answers moved. A graded end costs panels on every level, so ends are
//! graded only when the check shows they matter.
use serde::Serialize;

use super::error::PlanError;
use super::split::{Discrete, SplitLevel, SplitProblem};
use super::split_solve::{Level, ScalarMap, SplitOptions, find_scalar, history, level_estimate};

/// One quantity's change under the end check.
#[derive(Debug, Clone, Serialize)]
pub struct EndChange {
    /// The scalar's or output's name.
    pub name: String,
    /// How far it moved when the ends were graded (same level).
    pub change: f64,
    /// Its estimate from the ungraded levels.
    pub estimate: f64,
}

/// The record of the end check.
#[derive(Debug, Clone, Serialize)]
pub struct EndCheck {
    /// The ends of the unknowns' interval that were not graded (no
    /// `singular` declaration names them).
    pub ends: Vec<f64>,
    /// The level (index in the ladder) on which the check was made.
    pub level: usize,
    /// Whether a change exceeded its estimate, so that the mesh is graded
    /// toward those ends from then on.
    pub graded: bool,
    /// Every scalar's and output's change, and its estimate then.
    pub changes: Vec<EndChange>,
}

impl EndCheck {
    /// The change that exceeded its estimate by the largest factor (or the
    /// largest change relative to its estimate when none did).
    pub fn worst(&self) -> Option<&EndChange> {
        self.changes.iter().max_by(|a, b| {
            let r = |c: &EndChange| c.change / c.estimate.max(f64::MIN_POSITIVE);
            r(a).total_cmp(&r(b))
        })
    }
}

/// What the ladder does after the end check.
pub(super) enum Verdict {
    /// Nothing to check, or the check passed: accept the level.
    Accept,
    /// The ends are graded from now on: continue the ladder from this
    /// level (the graded solution on the level just checked) as the first
    /// of a new history.
    Climb {
        /// The graded level.
        level: Box<Level>,
        /// Its discretisation.
        discrete: Box<Discrete>,
    },
    /// The ends needed grading but no level is left: not converged; the
    /// estimate is at least `worst`.
    Refuse {
        /// The largest change.
        worst: f64,
    },
}

/// The end check on level `k` (`lvl`), whose values are `this`, after the
/// levels `climbed` (oldest first). `fixed`: the scalars are held fixed
/// (an answer at an end of the scalar's range, `split_end.rs`) rather than
/// found as a root. Made once per solve: when `problem` already holds a
/// check, or every end is graded, it accepts at once.
pub(super) fn check(
    problem: &mut SplitProblem,
    lvl: &SplitLevel,
    k: usize,
    climbed: &[Level],
    this: &Level,
    opts: &SplitOptions,
    fixed: bool,
) -> Result<Verdict, PlanError> {
    if problem.end_check().is_some() {
        return Ok(Verdict::Accept);
    }
    let ends = problem.ungraded_ends(&this.scalars);
    if ends.is_empty() {
        return Ok(Verdict::Accept);
    }
    let histories = (0..this.scalars.len())
        .map(|i| history(climbed, this, &|l| &l.scalars, i))
        .chain((0..this.outputs.len()).map(|i| history(climbed, this, &|l| &l.outputs, i)));
    if histories
        .into_iter()
        .all(|h| converges_cleanly(&h, opts.tol))
    {
        return Ok(Verdict::Accept);
    }
    let rt = if this.scalars.is_empty() || fixed {
        0.0
    } else {
        2.0 * super::split_solve::root_tolerance(opts.tol)
    };
    let before = problem.graded_ends().to_vec();
    let mut graded = before.clone();
    graded.extend(&ends);
    problem.set_graded_ends(graded);
    let probe = probe(problem, lvl, this, opts, fixed);
    let (scalars, outputs, first) = match probe {
        Ok(p) => p,
        Err(e) => {
            problem.set_graded_ends(before);
            return Err(e);
        }
    };
    // Every scalar's and output's change against its own estimate.
    let mut changes = Vec::new();
    let mut exceeded = false;
    let quantities = problem
        .contact
        .scalars
        .iter()
        .map(|s| s.name.clone())
        .zip(this.scalars.iter().zip(&scalars))
        .enumerate()
        .map(|(i, (n, (a, b)))| (n, *a, *b, level_estimate(&history(climbed, this, &|l| &l.scalars, i)) + rt))
        .collect::<Vec<_>>();
    let outs = problem
        .sys
        .outputs
        .iter()
        .map(|o| o.name.clone())
        .zip(this.outputs.iter().zip(&outputs))
        .enumerate()
        .map(|(i, (n, (a, b)))| (n, *a, *b, level_estimate(&history(climbed, this, &|l| &l.outputs, i))));
    for (name, a, b, estimate) in quantities.into_iter().chain(outs) {
        let change = (b - a).abs();
        let slack = 64.0 * f64::EPSILON * a.abs().max(b.abs());
        // A change that is not a number (the graded solve failed to give
        // one) counts as exceeding.
        if !(change <= estimate + slack) {
            exceeded = true;
        }
        changes.push(EndChange {
            name,
            change,
            estimate,
        });
    }
    problem.set_end_check(EndCheck {
        ends: ends.clone(),
        level: k,
        graded: exceeded,
        changes,
    });
    if !exceeded {
        problem.set_graded_ends(before);
        return Ok(Verdict::Accept);
    }
    let worst = problem
        .end_check()
        .map(|c| c.changes.iter().fold(0.0f64, |m, c| m.max(c.change)))
        .unwrap_or(f64::INFINITY);
    if k >= opts.max_level {
        // Keep the ungraded discretisation the answer was computed on.
        problem.set_graded_ends(before);
        return Ok(Verdict::Refuse { worst });
    }
    // The graded level `k` as the first of a new history.
    let (level, discrete) = match first {
        Some(ld) => ld,
        None => {
            let mut warm: Vec<Level> = Vec::new();
            warm.push(Level {
                scalars: this.scalars.clone(),
                slope: this.slope,
                outputs: this.outputs.clone(),
                coefficients: this.coefficients.clone(),
            });
            let (x, slope, d) = find_scalar(problem, lvl, &warm, opts.tol)?;
            let outputs = outputs_of(problem, &d)?;
            let coefficients = coefficients_of(problem, &d);
            (
                Level {
                    scalars: vec![x],
                    slope,
                    outputs,
                    coefficients,
                },
                d,
            )
        }
    };
    Ok(Verdict::Climb {
        level: Box::new(level),
        discrete: Box::new(discrete),
    })
}

/// The graded problem's scalars and outputs on level `lvl`, and the
/// graded level itself when it was computed exactly (no scalar, or the
/// scalar held fixed).
#[allow(clippy::type_complexity)]
fn probe(
    problem: &SplitProblem,
    lvl: &SplitLevel,
    this: &Level,
    opts: &SplitOptions,
    fixed: bool,
) -> Result<(Vec<f64>, Vec<f64>, Option<(Level, Discrete)>), PlanError> {
    let d0 = problem.discretise(&this.scalars, lvl)?;
    let o0 = outputs_of(problem, &d0)?;
    if this.scalars.is_empty() || fixed {
        let level = Level {
            scalars: this.scalars.clone(),
            slope: this.slope,
            outputs: o0.clone(),
            coefficients: coefficients_of(problem, &d0),
        };
        return Ok((this.scalars.clone(), o0, Some((level, d0))));
    }
    // One scalar: where the graded condition's root moved, by a Newton
    // step on the level's slope; the outputs are compared at the accepted
    // root (the same scalar on both meshes).
    let (lo, hi) = problem.contact.scalars[0].range;
    let map = ScalarMap { lo, hi };
    let x0 = this.scalars[0];
    let r0 = d0.residuals[0];
    if !(this.slope.is_finite() && this.slope != 0.0 && r0.is_finite()) {
        return Ok((vec![f64::NAN], o0, None));
    }
    let x1 = map.x(map.s(x0) - r0 / this.slope);
    Ok((vec![x1], o0, None))
}

/// Whether the values of one quantity over the levels (`h`, oldest
/// first) converge cleanly: at least five levels, and each of the last
/// three differences at most a quarter of the one before or below
/// `tol/10` (the outputs' rounding noise: `P` of `examples/hertz.lmx`
/// moved 3.7e-13, then 2.2e-12 on levels 3 and 4). An unknown's undeclared end singularity on a panel of full
/// degree converges only algebraically in the degree, which shows as
/// differences that fall slowly or in pairs (on the full-slip Hertz
/// problem they fell 3.6e-8, 2.9e-10, 1.0e-8, 8.1e-10, 3.8e-9, …); the
/// Hertz problem's fall about fifteenfold per level (`c` at ν = 1/4,
/// μ = 0.1801: 1.7e-8, 1.1e-9, 8.7e-11). A quantity that converges
/// cleanly needs no end check; a singular part hidden under such
/// differences would have to stay below them on three levels while it
/// falls at most about 0.7-fold per level.
fn converges_cleanly(h: &[f64], tol: f64) -> bool {
    let n = h.len();
    if n < 5 {
        return false;
    }
    let d = |k: usize| (h[k] - h[k - 1]).abs();
    let floor = 0.1 * tol;
    (n - 3..n).all(|k| d(k) <= floor || d(k) <= 0.25 * d(k - 1))
}

fn outputs_of(problem: &SplitProblem, d: &Discrete) -> Result<Vec<f64>, PlanError> {
    (0..problem.sys.outputs.len())
        .map(|o| problem.output(d, o))
        .collect()
}

fn coefficients_of(problem: &SplitProblem, d: &Discrete) -> Vec<f64> {
    (0..problem.contact.coefficients.len())
        .map(|c| problem.coefficient(d, c).unwrap_or(f64::NAN))
        .collect()
}
