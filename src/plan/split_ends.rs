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
//! the moved root). Every scalar and every unknown's integral over the
//! unknowns' interval is compared with its own estimate: quantities the
//! equations define, so that the mesh (like the end weights,
//! `split_weights.rs`) never depends on the outputs requested (issue 27:
//! a point value requested beside an end moved when that end was graded,
//! which graded it, while the solution was right without grading). If no
//! change exceeds its estimate (and 64 ulps; of the largest integral for
//! an integral, as the unknowns are solved together), the answer
//! stands and the cost was one or two solves on level `k`. If one does,
//! the end behaviour was not resolved: the mesh is graded toward those
//! ends from then on, the graded level `k` becomes the first level of a
//! new history and the ladder climbs on; on the last level allowed the
//! answer is instead marked not converged, each estimate at least its
//! change (the outputs' changes are recorded for that, not compared).
//! The report says which ends were graded and by how much the answers
//! moved. A graded end costs panels on every level, so ends are
//! graded only when the check shows they matter.
use serde::Serialize;

use super::compiled::OutputTerm;
use super::error::PlanError;
use super::split::{Discrete, SplitLevel, SplitProblem};
use super::split_scalars::find_scalars;
use super::split_solve::{Level, ScalarMap, SplitOptions, find_scalar, history, level_estimate};

/// One quantity's change under the end check.
#[derive(Debug, Clone, Serialize)]
pub struct EndChange {
    /// The scalar's name, or the unknown's integral (`int(0..1) p(x) dx`),
    /// or the output's name.
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
    /// The share of its estimate a change could reach without grading:
    /// 1 before accepting a level, less ahead of it.
    pub share: f64,
    /// Every scalar's and unknown integral's change, and its estimate
    /// then: what decided `graded`.
    pub changes: Vec<EndChange>,
    /// Every output's change and estimate: not part of the decision, but
    /// the least estimate of an answer refused on the last level.
    #[serde(skip)]
    pub outputs: Vec<EndChange>,
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
    /// Nothing to check, or the check passed: go on as without it
    /// (accept the level, or climb on).
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

/// When the ladder asks for the end check.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Mode {
    /// The level's estimate is within the tolerance: check before
    /// accepting it; grade when a change exceeds its estimate.
    Accept,
    /// A level from [`APPROACH_LEVEL`] on that does not converge cleanly
    /// (once per solve): grade when a change is more than
    /// [`APPROACH_SHARE`] of its estimate, so that an end which limits the
    /// convergence is graded before the ladder spends its remaining levels
    /// on it.
    Approach,
}

/// The first level of [`Mode::Approach`] (five levels: the first at which
/// the pair rule of `converges_cleanly` applies, so that the Hertz
/// problem's levels in pairs at `c → 1` count as clean). On the
/// full-slip Hertz problem at the default tolerance 1e-10 the ungraded
/// ladder never got below 1.6e-9 in nine levels; on level 4 (estimate
/// 1.0e-8) grading the centre moves `P` by 8.9e-9. On level 3 the check
/// was tried and graded 17 of the 195 points of the Hertz sweep
/// needlessly (their level-3 estimates do not yet bound the changes, up
/// to 8.6 times; on acceptance they all do).
pub(super) const APPROACH_LEVEL: usize = 4;

/// The share of its estimate a change may reach in [`Mode::Approach`].
const APPROACH_SHARE: f64 = 0.5;

/// The end check on level `k` (`lvl`), whose values are `this`, after the
/// levels `climbed` (oldest first). `fixed`: the scalars are held fixed
/// (an answer at an end of the scalar's range, `split_end.rs`) rather than
/// found as a root. It accepts at once when every end is graded, when
/// every scalar and unknown's integral converges cleanly
/// (`converges_cleanly`), and
/// in [`Mode::Approach`] when a check was made before.
#[allow(clippy::too_many_arguments)]
pub(super) fn check(
    problem: &mut SplitProblem,
    lvl: &SplitLevel,
    k: usize,
    climbed: &[Level],
    this: &Level,
    opts: &SplitOptions,
    mode: Mode,
    fixed: bool,
) -> Result<Verdict, PlanError> {
    if mode == Mode::Approach && problem.end_check().is_some() {
        return Ok(Verdict::Accept);
    }
    let ends = problem.ungraded_ends(&this.scalars);
    if ends.is_empty() {
        return Ok(Verdict::Accept);
    }
    let share = match mode {
        Mode::Accept => 1.0,
        Mode::Approach => APPROACH_SHARE,
    };
    let histories = (0..this.scalars.len())
        .map(|i| history(climbed, this, &|l| &l.scalars, i))
        .chain((0..this.integrals.len()).map(|i| history(climbed, this, &|l| &l.integrals, i)));
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
    problem.set_probe(Some((ends.clone(), PROBE_LAYERS)));
    let probed = probe(problem, lvl, this, opts.tol);
    problem.set_probe(None);
    let (scalars, outputs, integrals) = probed?;
    // Every scalar's and integral's change against its own estimate.
    let mut changes = Vec::new();
    let mut exceeded = false;
    let names = |list: &mut dyn Iterator<Item = String>| list.collect::<Vec<_>>();
    let scalar_names = names(&mut problem.contact.scalars.iter().map(|s| s.name.clone()));
    let integral_names = names(&mut problem.sys.unknowns.iter().flat_map(|u| {
        let (a, b) = problem.domain;
        (0..MOMENTS).map(move |k| match k {
            0 => format!("int({a}..{b}) {u}(x) dx"),
            _ => format!("int({a}..{b}) t^{k}*{u}(x) dx (t = (x - {a})/({b} - {a}))"),
        })
    }));
    // `scale`: the size the quantity's rounding is relative to.
    let mut compare = |name: &str, a: f64, b: f64, estimate: f64, scale: f64| {
        let change = (b - a).abs();
        let slack = 64.0 * f64::EPSILON * a.abs().max(b.abs()).max(scale);
        // A change that is not a number (the probe's Newton step had no
        // finite slope or residual: seen at 1 − c ≈ 2e-12 on the Hertz
        // problem) is no evidence either way; the integrals, compared at
        // the same scalar, still are.
        let over = change > share * estimate + slack;
        if over {
            exceeded = true;
        }
        changes.push(EndChange {
            name: name.to_string(),
            change,
            estimate,
        });
    };
    // Held fixed, the scalars have nothing to compare.
    for (i, name) in scalar_names.iter().enumerate().filter(|_| !fixed) {
        let h = history(climbed, this, &|l| &l.scalars, i);
        compare(
            name,
            this.scalars[i],
            scalars[i],
            level_estimate(&h) + rt,
            0.0,
        );
    }
    // The unknowns are solved together, so each one's values carry the
    // rounding of the whole solution: an integral's slack is relative to
    // the largest one, not to its own size. The Hertz problem at μ = 1e-9
    // and c = 1e-10: `∫q ≈ 1e-9` moved by 1.9e-16 (rounding, ε·|∫p|)
    // against its level estimate 1.2e-16 and 64 ulps of itself (1e-23),
    // which graded the end 0 for nothing.
    let solution_scale = this
        .integrals
        .iter()
        .chain(&integrals)
        .fold(0.0f64, |m, v| m.max(v.abs()));
    for (i, name) in integral_names.iter().enumerate() {
        let h = history(climbed, this, &|l| &l.integrals, i);
        compare(
            name,
            this.integrals[i],
            integrals[i],
            level_estimate(&h),
            solution_scale,
        );
    }
    let output_changes: Vec<EndChange> = problem
        .sys
        .outputs
        .iter()
        .enumerate()
        .map(|(i, o)| EndChange {
            name: o.name.clone(),
            change: (outputs[i] - this.outputs[i]).abs(),
            estimate: level_estimate(&history(climbed, this, &|l| &l.outputs, i)),
        })
        .collect();
    let worst = changes
        .iter()
        .chain(&output_changes)
        .fold(0.0f64, |m, c| m.max(c.change));
    problem.set_end_check(EndCheck {
        ends: ends.clone(),
        level: k,
        graded: exceeded,
        share,
        changes,
        outputs: output_changes,
    });
    if !exceeded {
        return Ok(Verdict::Accept);
    }
    if k >= opts.max_level {
        // (Only on acceptance.) The answer stays the ungraded one,
        // marked not converged.
        return Ok(Verdict::Refuse { worst });
    }
    // From now on the ends are graded like declared singular points; the
    // graded level `k` is the first of a new history.
    let mut graded = problem.graded_ends().to_vec();
    graded.extend(&ends);
    problem.set_graded_ends(graded);
    let (scalars, slope, d) = if this.scalars.len() > 1 && !fixed {
        let (x, d) = find_scalars(problem, lvl, Some(&this.scalars), opts.tol)?;
        (x, 0.0, d)
    } else if this.scalars.is_empty() || fixed {
        (
            this.scalars.clone(),
            this.slope,
            problem.discretise(&this.scalars, lvl)?,
        )
    } else {
        let warm = [Level {
            dim: this.dim,
            scalars: this.scalars.clone(),
            slope: this.slope,
            outputs: this.outputs.clone(),
            coefficients: this.coefficients.clone(),
            integrals: this.integrals.clone(),
            cond: this.cond,
            unknowns: Vec::new(),
            sizes: Vec::new(),
            left_out: Vec::new(),
            floors: Vec::new(),
            output_floors: Vec::new(),
            coefficient_floors: Vec::new(),
        }];
        let (x, slope, d) = find_scalar(problem, lvl, &warm, opts.tol)?;
        (vec![x], slope, d)
    };
    let level = Level {
        dim: SplitProblem::size(&d),
        scalars,
        slope,
        outputs: outputs_of(problem, &d)?,
        coefficients: coefficients_of(problem, &d),
        integrals: integrals_of(problem, &d)?,
        cond: d.cond,
        unknowns: Vec::new(),
        sizes: Vec::new(),
        left_out: Vec::new(),
        floors: Vec::new(),
        output_floors: Vec::new(),
        coefficient_floors: Vec::new(),
    };
    Ok(Verdict::Climb {
        level: Box::new(level),
        discrete: Box::new(d),
    })
}

/// The most layers the probe grades an end with. Enough to tell an
/// unresolved end apart from a resolved one on any level: an end
/// behaviour `x^α` (α > −1) on the ungraded end panel `[0, h]` of degree
/// `n ≤ 20` is approximated to about `h^(1+α)·n^(−2(1+α))`; the probe's
/// innermost panel `h·σ^(L−1)` (σ = 1/4, degree 3) to about
/// `(h·σ^(L−1))^(1+α)`, at least ten times better when
/// `(L − 1)·ln 4 ≥ 2 ln 20 + ln 10/(1 + α)`, i.e. `L ≥ 8` for α ≥ −0.3
/// (`L ≥ 10` down to α = −0.6). Fewer layers than the ladder's (up to 20)
/// keep the probe cheap on the highest levels.
const PROBE_LAYERS: usize = 10;

/// What [`probe`] measures: scalars, outputs, unknowns' moments.
type Probed = (Vec<f64>, Vec<f64>, Vec<f64>);

/// The probed problem's scalars, outputs and unknowns' integrals on
/// level `lvl`: the outputs and integrals at the scalars of `this`, and
/// the scalar moved by a Newton step on the level's slope of the
/// condition (the root of the probed condition, to first order). Outputs
/// and integrals are compared at the same scalar, so that only the
/// discretisations differ.
fn probe(
    problem: &SplitProblem,
    lvl: &SplitLevel,
    this: &Level,
    tol: f64,
) -> Result<Probed, PlanError> {
    let d = problem.discretise(&this.scalars, lvl)?;
    let outputs = outputs_of(problem, &d)?;
    let integrals = integrals_of(problem, &d)?;
    // Several scalars: their joint root on the probed level.
    if this.scalars.len() > 1 {
        let (x, _) = find_scalars(problem, lvl, Some(&this.scalars), tol)?;
        return Ok((x, outputs, integrals));
    }
    let Some(&x0) = this.scalars.first() else {
        return Ok((Vec::new(), outputs, integrals));
    };
    let (lo, hi) = problem.contact.scalars[0].range;
    let map = ScalarMap { lo, hi };
    let r = d.residuals.first().copied().unwrap_or(f64::NAN);
    let x1 = if this.slope.is_finite() && this.slope != 0.0 {
        map.x(map.s(x0) - r / this.slope)
    } else {
        f64::NAN
    };
    Ok((vec![x1], outputs, integrals))
}

/// Whether the values of one quantity over the levels (`h`, oldest
/// first) converge cleanly, so that it needs no end check. With the
/// differences `Dⱼ = |hⱼ − hⱼ₋₁|` and the sums of two successive ones
/// `Sⱼ = Dⱼ + Dⱼ₋₁` (the ladder refines the mesh and the degree in turn,
/// and some quantities improve only every other level): from five
/// levels on, over the last two levels the sum fell at least eightfold,
/// `Sₙ ≤ Sₙ₋₂/8`, as also `Sₙ₋₁ ≤ Sₙ₋₃/8` when there are six levels or
/// more; on four levels, each of the last two differences is at most a
/// quarter of the one before (pairs show there as a rise); on fewer, no
/// convergence is clean. A difference or sum below `tol/10` (the
/// outputs' rounding noise: `P` of `examples/hertz.lmx` moved 3.7e-13,
/// then 2.2e-12 on levels 3 and 4) passes.
///
/// An undeclared end singularity on a panel of full degree `n` (7 + the
/// level) converges only algebraically, like `n^(−r)`: over two levels
/// by a factor `((n + 2)/n)^(r+1)`, below 8 for `r ≤ 7` from level 0 on
/// (on the full-slip Hertz problem the sums fell by 0.30, 0.39 and 0.46
/// per two levels). The Hertz problem's fall about a hundredfold per two
/// levels (`c` at ν = 1/4, μ = 0.1801: 1.7e-8, 1.1e-9, 8.7e-11 per level;
/// `P` at ν = 0.3, μ = 2.154, in pairs: 1.5e-9, 1.1e-10, 1.1e-10,
/// 1.2e-11, 8.2e-12).
fn converges_cleanly(h: &[f64], tol: f64) -> bool {
    let n = h.len();
    if n < 4 {
        return false;
    }
    let d = |k: usize| (h[k] - h[k - 1]).abs();
    // Two equal levels are no sign of convergence: nothing was refined
    // that the quantity sees (one ungraded panel keeps its degree).
    if (n - 3..n).any(|k| d(k) == 0.0) {
        return false;
    }
    let floor = 0.1 * tol;
    if n == 4 {
        return (2..4).all(|k| d(k) <= floor || d(k) <= d(k - 1) / 4.0);
    }
    let pair = |k: usize| d(k) + d(k - 1);
    [n - 1, n - 2]
        .into_iter()
        .filter(|&k| k >= 4)
        .all(|k| pair(k) <= floor || pair(k) <= pair(k - 2) / 8.0)
}

fn outputs_of(problem: &SplitProblem, d: &Discrete) -> Result<Vec<f64>, PlanError> {
    (0..problem.sys.outputs.len())
        .map(|o| problem.output(d, o))
        .collect()
}

/// Moments per unknown the end check compares ([`integrals_of`]).
const MOMENTS: usize = 3;

/// Per unknown of `problem`, its moments `∫ tᵏ u(x) dx` over the unknowns'
/// interval `[a, b]`, `t = (x − a)/(b − a)`, `k < MOMENTS`, in the
/// discrete solution `d` (every part of `u`: free basis, related pieces,
/// exact singular terms): the quantities the end check compares. An
/// undeclared end behaviour left on an ungraded panel moves them as it
/// moves any integral output (the full-slip Hertz problem's `P` is
/// `π/2·∫x p`). One moment is not enough: an Abel operator
/// `∫_x^1 t p(t)/√(t² − x²) dt = f` pins `∫p = f(0)` whatever the
/// discretisation does at 1 (`examples/contact/cattaneo_mindlin_shift.lmx`:
/// `∫p` converged cleanly while `P = 2π∫x p`, whose end at 1 is `√(1 − x)`,
/// moved by 6e-8 on level 9 and never reached 1e-10 ungraded).
pub(super) fn integrals_of(problem: &SplitProblem, d: &Discrete) -> Result<Vec<f64>, PlanError> {
    let (a, b) = problem.domain;
    let mut out = Vec::new();
    for u in 0..problem.sys.unknowns.len() {
        for k in 0..MOMENTS {
            let term = OutputTerm::Integral {
                coeff: 1.0,
                lower: a,
                upper: b,
                weight: std::sync::Arc::new(move |x| ((x - a) / (b - a)).powi(k as i32)),
                unknown: u,
            };
            let (row, constant) = d.layout().functional(std::slice::from_ref(&term))?;
            out.push(constant + row.dot(&d.solution));
        }
    }
    Ok(out)
}

fn coefficients_of(problem: &SplitProblem, d: &Discrete) -> Vec<f64> {
    (0..problem.contact.coefficients.len())
        .map(|c| problem.coefficient(d, c).unwrap_or(f64::NAN))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::converges_cleanly;

    fn from_differences(d: &[f64]) -> Vec<f64> {
        let mut h = vec![1.0];
        for (i, x) in d.iter().enumerate() {
            // Alternating signs, as levels often come.
            let s = if i % 2 == 0 { 1.0 } else { -1.0 };
            h.push(h[i] + s * x);
        }
        h
    }

    #[test]
    fn clean_convergence_is_told_from_an_unresolved_end() {
        let tol = 1e-10;
        // The Hertz problem's c at ν = 1/4, μ = 0.1801 (first difference
        // assumed 15 times the second): clean on four and five levels.
        let c = [2.5e-7, 1.7e-8, 1.1e-9, 8.7e-11];
        assert!(converges_cleanly(&from_differences(&c[..3]), tol));
        assert!(converges_cleanly(&from_differences(&c), tol));
        // P at ν = 0.3, μ = 2.154: in pairs, falling about tenfold per two.
        let p = [
            2.3e-8, 7.1e-10, 1.45e-9, 1.1e-10, 1.06e-10, 1.2e-11, 8.2e-12,
        ];
        assert!(converges_cleanly(&from_differences(&p), tol));
        // The full-slip problem's P without grading at the centre: never.
        let slip = [3.6e-8, 2.9e-10, 1.02e-8, 8.1e-10, 3.77e-9, 5.4e-10, 1.64e-9];
        for n in 2..=slip.len() {
            assert!(
                !converges_cleanly(&from_differences(&slip[..n]), tol),
                "{n}"
            );
        }
        // Algebraic convergence n^(-4) in the degree n = 7 + level.
        let alg: Vec<f64> = (0..8)
            .map(|k| (7.0 + k as f64).powi(-4) - (8.0 + k as f64).powi(-4))
            .collect();
        assert!(!converges_cleanly(&from_differences(&alg), tol));
        // Two equal levels, and fewer than four levels, are not clean.
        assert!(!converges_cleanly(
            &[1.0, 1.0 + 1e-3, 1.0 + 1e-3, 1.0 + 1e-3],
            tol
        ));
        assert!(!converges_cleanly(&[1.0, 1.1, 1.1001], tol));
        // Differences at the outputs' rounding noise pass.
        let noise = [3.7e-11, 3.7e-13, 2.2e-12, 1.0e-13];
        assert!(converges_cleanly(&from_differences(&noise), tol));
    }
}
