//! The joint root solve of several unknown scalars (a contact radius and
//! an indentation fixed by a bounded edge and a given load, a stick radius
//! and a shift fixed by a bounded edge and a given tangential force): as
//! many conditions (coefficient conditions and, with scalars, side
//! conditions) as scalars, `F(x) = 0`. Each scalar is solved in the
//! variable `s` of its declared range (`split_solve::ScalarMap`). The
//! iteration is Newton's with a forward-difference Jacobian, damped by
//! backtracking on the scaled residual norm; where it stalls from a
//! starting point, a Newton homotopy `F(s) − (1 − t)·F(s₀)` is continued
//! from `t = 0` to `t = 1`. On the first level it is started from every
//! point of a grid (`s ∈ {−2, 0, 2}` per scalar: a quarter, a half and
//! three quarters… of the range in `x`), and the distinct roots that keep
//! every declared inequality are collected: none, or more than one, is
//! refused naming them. On every further level it is warm-started from
//! the last level's root. The single-scalar solve (`split_solve.rs`) is
//! not routed here. Owns this iteration only; the discretisation is
//! `split.rs`'s, the ladder `split_solve.rs`'s.
use nalgebra::{DMatrix, DVector};

use super::error::PlanError;
use super::split::{Discrete, SplitLevel, SplitProblem};
use super::split_solve::{S_LIMIT, S_LIMIT_LO, ScalarMap, root_tolerance};
use crate::numeric::NumericError;

/// The starting values of the grid on the first level, in `s`.
const GRID: [f64; 3] = [-2.0, 0.0, 2.0];

/// Newton iterations per start.
const MAX_NEWTON: usize = 20;

/// Halvings of a Newton step before the start is given up.
const MAX_HALVINGS: usize = 10;

/// Two roots closer than this in every `s` are one.
const SAME_ROOT: f64 = 1e-6;

fn failure(msg: String) -> PlanError {
    PlanError::Numeric {
        context: "scalar root".into(),
        source: NumericError::NoConvergence(msg),
    }
}

/// The conditions as a function of the scalars' map variables, with the
/// discretisation at the last point evaluated kept.
struct System<'a> {
    problem: &'a SplitProblem,
    lvl: &'a SplitLevel,
    maps: Vec<ScalarMap>,
    /// Every point evaluated, `(x, discretisation)`, newest last.
    evals: Vec<(Vec<f64>, Discrete)>,
    /// The Jacobian in `s` Newton last computed, reused while its steps
    /// keep reducing the residuals ([`newton`]).
    jac: Option<DMatrix<f64>>,
}

impl System<'_> {
    fn xs(&self, s: &[f64]) -> Vec<f64> {
        s.iter().zip(&self.maps).map(|(&s, m)| m.x(s)).collect()
    }

    /// The residuals at `s`: `Ok(None)` where the discretisation fails
    /// numerically (a value of the scalars it cannot take), an error at
    /// once for a fault of the input.
    fn eval(&mut self, s: &[f64]) -> Result<Option<Vec<f64>>, PlanError> {
        if s.iter().any(|&v| !(-S_LIMIT_LO..=S_LIMIT).contains(&v)) {
            return Ok(None);
        }
        let x = self.xs(s);
        if let Some(e) = self.evals.iter().rev().find(|e| same_bits(&e.0, &x)) {
            return Ok(Some(e.1.residuals.clone()));
        }
        match self.problem.discretise(&x, self.lvl) {
            Ok(d) => {
                let r = d.residuals.clone();
                if r.iter().any(|v| !v.is_finite()) {
                    return Ok(None);
                }
                self.evals.push((x, d));
                if self.evals.len() > 64 {
                    self.evals.remove(0);
                }
                Ok(Some(r))
            }
            Err(e) if e.is_input_error() => Err(e),
            Err(_) => Ok(None),
        }
    }

    /// The discretisation at `s` (re-evaluated if it is not kept).
    fn discrete(&mut self, s: &[f64]) -> Result<Discrete, PlanError> {
        let x = self.xs(s);
        match self.evals.iter().position(|e| same_bits(&e.0, &x)) {
            Some(i) => Ok(self.evals.swap_remove(i).1),
            None => self.problem.discretise(&x, self.lvl),
        }
    }

    /// The forward-difference Jacobian in `s` at `s` (residuals `f0`).
    fn jacobian(&mut self, s: &[f64], f0: &[f64]) -> Result<Option<DMatrix<f64>>, PlanError> {
        let n = s.len();
        let mut j = DMatrix::zeros(n, n);
        for k in 0..n {
            let h = self.maps[k].s_ulps(s[k]).max(1e-6);
            let mut sh = s.to_vec();
            // Step inward when the forward point is out of the range.
            let h = if s[k] + h > S_LIMIT { -h } else { h };
            sh[k] += h;
            let Some(fh) = self.eval(&sh)? else {
                return Ok(None);
            };
            for i in 0..n {
                j[(i, k)] = (fh[i] - f0[i]) / h;
            }
        }
        Ok(Some(j))
    }
}

fn same_bits(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())
}

/// The scaled norm of residuals `f` (each divided by `scale`).
fn norm(f: &[f64], scale: &[f64]) -> f64 {
    f.iter()
        .zip(scale)
        .map(|(v, s)| (v / s).powi(2))
        .sum::<f64>()
        .sqrt()
}

/// Damped Newton on `g(s) = F(s) − shift` from `s`; the root, or `None`
/// where it stalls. The merit is the norm of the residuals each divided
/// by `scale` (empty: by its Jacobian row's largest entry at the start). Stops once a full step moves every scalar by less
/// than `xtol` (in `x`). The Jacobian (one discretisation per scalar) is
/// kept in `sys.jac` and reused (a chord step: one discretisation) while
/// full steps with it at least halve the merit; a step with a reused
/// Jacobian that backtracking cannot accept, or that reduces the merit
/// less, is taken again with a fresh one. On a level warm-started from the
/// last level's root with the last level's Jacobian, the root is then
/// reached in two or three discretisations instead of about seven.
fn newton(
    sys: &mut System,
    start: &[f64],
    shift: &[f64],
    scale: &[f64],
    xtol: f64,
) -> Result<Option<Vec<f64>>, PlanError> {
    let n = start.len();
    let mut s = start.to_vec();
    let g = |f: Vec<f64>| -> Vec<f64> { f.iter().zip(shift).map(|(a, b)| a - b).collect() };
    let Some(f) = sys.eval(&s)? else {
        return Ok(None);
    };
    let mut gs = g(f);
    let mut scale = scale.to_vec();
    for _ in 0..MAX_NEWTON {
        if gs.iter().all(|&v| v == 0.0) {
            return Ok(Some(s));
        }
        let reused = sys.jac.is_some();
        let jac = match sys.jac.take() {
            Some(j) => j,
            None => {
                let f_here: Vec<f64> = gs.iter().zip(shift).map(|(a, b)| a + b).collect();
                let Some(j) = sys.jacobian(&s, &f_here)? else {
                    return Ok(None);
                };
                j
            }
        };
        // Without a scale given: each residual's change per unit of `s`
        // at the start (a residual near zero there is no scale).
        if scale.is_empty() {
            scale = (0..n)
                .map(|i| {
                    let r = jac.row(i).iter().fold(0.0f64, |m, v| m.max(v.abs()));
                    if r > 0.0 && r.is_finite() { r } else { 1.0 }
                })
                .collect();
        }
        let scale = scale.as_slice();
        let rhs = DVector::from_iterator(n, gs.iter().map(|v| -v));
        let step = jac.clone().lu().solve(&rhs);
        let Some(step) = step.filter(|d| d.iter().all(|v| v.is_finite())) else {
            if reused {
                continue;
            }
            return Ok(None);
        };
        // At most 2 in any `s` per step (a factor of about e² in `x`
        // near an end).
        let big = step.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let cap = if big > 2.0 { 2.0 / big } else { 1.0 };
        let here = norm(&gs, scale);
        let mut lambda = cap;
        let mut accepted = None;
        for _ in 0..MAX_HALVINGS {
            let trial: Vec<f64> = s
                .iter()
                .zip(step.iter())
                .map(|(a, d)| a + lambda * d)
                .collect();
            if let Some(f) = sys.eval(&trial)? {
                let gt = g(f);
                if norm(&gt, scale) <= (1.0 - 1e-4 * lambda) * here || here == 0.0 {
                    accepted = Some((trial, gt));
                    break;
                }
            }
            lambda *= 0.5;
        }
        // The full step's size in `x`, scalar by scalar.
        let small = (0..n).all(|k| {
            let m = sys.maps[k];
            (m.x(s[k] + step[k]) - m.x(s[k])).abs() <= xtol || step[k].abs() <= m.s_ulps(s[k])
        });
        match accepted {
            Some((t, gt)) => {
                // Keep the Jacobian while its full steps converge fast.
                if lambda == 1.0 && norm(&gt, scale) <= 0.5 * here {
                    sys.jac = Some(jac);
                }
                s = t;
                gs = gt;
                // (a reused Jacobian must also have converged fast)
                if small && lambda == 1.0 && (!reused || sys.jac.is_some()) {
                    return Ok(Some(s));
                }
            }
            // A reused Jacobian: try again with a fresh one.
            None if reused => {}
            // Backtracking found no decrease: at a root within rounding
            // if the step is below the tolerance, else stalled.
            None => return Ok(small.then_some(s)),
        }
    }
    Ok(None)
}

/// Newton from `start`, and where it stalls the Newton homotopy
/// `F(s) − (1 − t)·F(start)` continued from `t = 0` to 1 (steps halved
/// where a corrector fails, at most 64 of them).
fn solve_from(
    sys: &mut System,
    start: &[f64],
    scale: &[f64],
    xtol: f64,
) -> Result<Option<Vec<f64>>, PlanError> {
    let zero = vec![0.0; start.len()];
    if let Some(r) = newton(sys, start, &zero, scale, xtol)? {
        return Ok(Some(r));
    }
    let Some(f0) = sys.eval(start)? else {
        return Ok(None);
    };
    let (mut t, mut dt, mut s) = (0.0f64, 0.25f64, start.to_vec());
    for _ in 0..64 {
        let next = (t + dt).min(1.0);
        let shift: Vec<f64> = f0.iter().map(|v| (1.0 - next) * v).collect();
        // Intermediate points need not be resolved finely.
        let tol = if next < 1.0 { 1e3 * xtol } else { xtol };
        match newton(sys, &s, &shift, scale, tol)? {
            Some(r) => {
                s = r;
                t = next;
                if t >= 1.0 {
                    return Ok(Some(s));
                }
                dt = (2.0 * dt).min(0.5);
            }
            None => {
                dt *= 0.5;
                if dt < 1e-4 {
                    return Ok(None);
                }
            }
        }
    }
    Ok(None)
}

/// Remembers the Jacobian `sys` ended with for the next level's warm
/// start.
fn keep_jacobian(problem: &SplitProblem, sys: &System) {
    if let (Some(j), Ok(mut slot)) = (&sys.jac, problem.scalar_jacobian.lock()) {
        *slot = Some(j.clone());
    }
}

/// The scalars on level `lvl` and the discrete solution at them: from the
/// last level's root when there is one, else from every point of the grid
/// (refusing none or several admissible roots).
pub(super) fn find_scalars(
    problem: &SplitProblem,
    lvl: &SplitLevel,
    previous: Option<&[f64]>,
    tol: f64,
) -> Result<(Vec<f64>, Discrete), PlanError> {
    let scalars = &problem.contact.scalars;
    let maps: Vec<ScalarMap> = scalars
        .iter()
        .map(|s| ScalarMap {
            lo: s.range.0,
            hi: s.range.1,
        })
        .collect();
    let names: Vec<&str> = scalars.iter().map(|s| s.name.as_str()).collect();
    let mut sys = System {
        problem,
        lvl,
        maps: maps.clone(),
        evals: Vec::new(),
        // The last level's Jacobian, for the warm start from its root.
        jac: previous.and_then(|_| problem.scalar_jacobian.lock().ok()?.clone()),
    };
    let xtol = root_tolerance(tol).max(1e-15);
    let n = scalars.len();
    let show = |x: &[f64]| -> String {
        names
            .iter()
            .zip(x)
            .map(|(n, v)| format!("{n} = {v:.12e}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    if let Some(prev) = previous {
        let s0: Vec<f64> = prev.iter().zip(&maps).map(|(&x, m)| m.s(x)).collect();
        let root = solve_from(&mut sys, &s0, &[], xtol)?.ok_or_else(|| {
            failure(format!(
                "the conditions have no root near the last level's ({}) on the next level",
                show(prev)
            ))
        })?;
        let x = sys.xs(&root);
        let d = sys.discrete(&root)?;
        keep_jacobian(problem, &sys);
        return Ok((x, d));
    }
    // Every grid point, and the residual scale from them.
    let starts: Vec<Vec<f64>> = (0..GRID.len().pow(n as u32))
        .map(|mut k| {
            (0..n)
                .map(|_| {
                    let v = GRID[k % GRID.len()];
                    k /= GRID.len();
                    v
                })
                .collect()
        })
        .collect();
    let mut values = Vec::new();
    for s in &starts {
        if let Some(f) = sys.eval(s)? {
            values.push((s.clone(), f));
        }
    }
    if values.is_empty() {
        return Err(failure(format!(
            "the conditions could not be evaluated at any starting point in the declared ranges of {}",
            names.join(", ")
        )));
    }
    let scale: Vec<f64> = (0..n)
        .map(|i| {
            let m = values.iter().fold(0.0f64, |m, (_, f)| m.max(f[i].abs()));
            if m > 0.0 { m } else { 1.0 }
        })
        .collect();
    // Nearest the root first.
    values.sort_by(|a, b| norm(&a.1, &scale).total_cmp(&norm(&b.1, &scale)));
    // Newton from every start; only if none converges, the homotopy
    // from each.
    let zero = vec![0.0; n];
    let mut roots: Vec<Vec<f64>> = Vec::new();
    for homotopy in [false, true] {
        for (s, _) in &values {
            // Each start computes its own Jacobian.
            sys.jac = None;
            let r = if homotopy {
                solve_from(&mut sys, s, &scale, xtol)?
            } else {
                newton(&mut sys, s, &zero, &scale, xtol)?
            };
            if let Some(r) = r
                && !roots
                    .iter()
                    .any(|q| q.iter().zip(&r).all(|(a, b)| (a - b).abs() <= SAME_ROOT))
            {
                roots.push(r);
            }
        }
        if !roots.is_empty() {
            break;
        }
    }
    let mut admissible = Vec::new();
    let mut rejected = Vec::new();
    for r in roots {
        let x = sys.xs(&r);
        let d = sys.discrete(&r)?;
        match problem.inequality_violation(&d) {
            Some((text, at, l, rr)) => rejected.push(format!(
                "the root {} violates the inequality `{text}`: at x = {at:.4e} the smaller side is {l:.3e}, above {rr:.3e} by {:.3e}",
                show(&x),
                l - rr
            )),
            None => admissible.push((x, d)),
        }
    }
    match admissible.len() {
        1 => Ok(admissible.pop().expect("one")),
        0 => Err(failure(format!(
            "no admissible root of the {n} conditions for {} found from {} starting points in their declared ranges{}",
            names.join(", "),
            values.len(),
            if rejected.is_empty() {
                String::new()
            } else {
                format!(": {}", rejected.join("; "))
            }
        ))),
        k => Err(failure(format!(
            "the {n} conditions for {} have {k} admissible roots: {}; state an inequality that tells them apart, or narrow the scalars' ranges",
            names.join(", "),
            admissible
                .iter()
                .map(|(x, _)| format!("({})", show(x)))
                .collect::<Vec<_>>()
                .join(", ")
        ))),
    }
}
