//! Product-integration rules for the diagonal kernel classes that are not
//! powers: `ln|t - x|`, the Cauchy principal value `1/(t - x)` and smooth
//! kernels sharply peaked at `t = x` (poles at `x ± iw`, e.g. Love's
//! `κ/(κ² + (x - t)²)`). Each rule returns nodes `t` and weights `w` with
//! `Σ w_q g(t_q) ≈ ∫_l^r g(t) W(t) S(x, t) dt` for smooth `g`, where `W` is
//! the basis weight (power factors at the interval's ends or outside it)
//! and `S` the kernel's singular factor:
//!
//! * **log**: the interval is split at `x`; the piece touching `x` is
//!   integrated exactly by `ln(h)`·Gauss–Legendre plus a Gauss rule for the
//!   weight `-ln u` on `[0, 1]` (built once per size by the Stieltjes
//!   procedure on an exact tensor discretisation `-ln u = ∫_u^1 dv/v`);
//! * **Cauchy**: the symmetric part `[x - δ, x + δ]` is folded,
//!   `∫_0^δ (F(x+s) - F(x-s))/s ds`, which is smooth; the rest is regular
//!   and graded toward `x`;
//! * **peaked**: pieces graded toward `x` down to the width `w`.
//!
//! Pieces near an outside weight point are graded as in
//! [`super::product::composite_rule`], whose power-singularity rules it
//! reuses. Owns these rules only; it must not know about bases or
//! operators.
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

use nalgebra::{DMatrix, SymmetricEigen};

use super::basis::Factor;
use super::basis::pow_fast;
use super::error::NumericError;
use super::gauss::gauss_legendre;
use super::product::{ETA, RuleCache};

/// The singular factor handled here.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DiagonalKind {
    /// `ln|t - x|`.
    Log,
    /// The principal value of `1/(t - x)`.
    Cauchy,
    /// A smooth factor (in the kernel) with complex poles at distance
    /// `width` from `t = x`; `S = 1`.
    Peaked {
        /// Distance of the nearest complex singularity from the real axis.
        width: f64,
    },
}

impl DiagonalKind {
    /// The value of `S(x, t)` away from `t = x` (`d = t - x`, accurate).
    fn value(&self, d: f64) -> f64 {
        match self {
            DiagonalKind::Log => d.abs().ln(),
            DiagonalKind::Cauchy => 1.0 / d,
            DiagonalKind::Peaked { .. } => 1.0,
        }
    }
}

/// A Gauss rule on `[0, 1]` for the weight `-ln u`: nodes and weights.
#[derive(Debug, Clone, PartialEq)]
pub struct LogRule {
    /// Nodes in `(0, 1)`, ascending.
    pub nodes: Vec<f64>,
    /// Positive weights summing to 1.
    pub weights: Vec<f64>,
}

/// The `m`-point Gauss rule for `∫_0^1 g(u) (-ln u) du` (exact for degree
/// `2m - 1`), cached.
///
/// ```
/// use lambdamat::numeric::kernels::log_rule;
/// let r = log_rule(6).unwrap();
/// // ∫_0^1 u^5 (-ln u) du = 1/36
/// let s: f64 = r.nodes.iter().zip(&r.weights).map(|(u, w)| w * u.powi(5)).sum();
/// assert!((s - 1.0 / 36.0).abs() < 1e-15);
/// ```
pub fn log_rule(m: usize) -> Result<Arc<LogRule>, NumericError> {
    static CACHE: OnceLock<Mutex<HashMap<usize, Arc<LogRule>>>> = OnceLock::new();
    let cache = CACHE.get_or_init(Default::default);
    if let Ok(c) = cache.lock()
        && let Some(r) = c.get(&m)
    {
        return Ok(r.clone());
    }
    let r = Arc::new(build_log_rule(m)?);
    if let Ok(mut c) = cache.lock() {
        c.insert(m, r.clone());
    }
    Ok(r)
}

fn build_log_rule(m: usize) -> Result<LogRule, NumericError> {
    if m == 0 {
        return Err(NumericError::InvalidRule("zero nodes".into()));
    }
    // Exact discretisation: ∫_0^1 g(u)(-ln u) du = ∫_0^1∫_0^1 g(vw) dw dv,
    // exact for polynomials of degree < 2M with M×M Gauss–Legendre points.
    let big = gauss_legendre((m + 2).max(24))?;
    let (v, wv) = big.mapped(0.0, 1.0);
    let mut u = Vec::with_capacity(v.len() * v.len());
    let mut w = Vec::with_capacity(v.len() * v.len());
    for (vi, wi) in v.iter().zip(&wv) {
        for (vj, wj) in v.iter().zip(&wv) {
            u.push(vi * vj);
            w.push(wi * wj);
        }
    }
    // Stieltjes procedure for the monic orthogonal polynomials.
    let mut alpha = vec![0.0; m];
    let mut beta = vec![0.0; m];
    let mut p_prev = vec![0.0; u.len()];
    let mut p = vec![1.0; u.len()];
    let mut norm_prev = 1.0;
    for k in 0..m {
        let norm: f64 = p.iter().zip(&w).map(|(p, w)| w * p * p).sum();
        let num: f64 = p
            .iter()
            .zip(&w)
            .zip(&u)
            .map(|((p, w), u)| w * u * p * p)
            .sum();
        alpha[k] = num / norm;
        beta[k] = if k == 0 { norm } else { norm / norm_prev };
        let next: Vec<f64> = (0..u.len())
            .map(|i| (u[i] - alpha[k]) * p[i] - beta[k] * p_prev[i])
            .collect();
        p_prev = std::mem::replace(&mut p, next);
        norm_prev = norm;
    }
    let mut jac = DMatrix::<f64>::zeros(m, m);
    for k in 0..m {
        jac[(k, k)] = alpha[k];
        if k + 1 < m {
            let b = beta[k + 1].sqrt();
            jac[(k, k + 1)] = b;
            jac[(k + 1, k)] = b;
        }
    }
    let eig = SymmetricEigen::try_new(jac, f64::EPSILON, 0).ok_or(NumericError::Eigen(m))?;
    let mut pairs: Vec<(f64, f64)> = (0..m)
        .map(|i| {
            let v0 = eig.eigenvectors[(0, i)];
            (eig.eigenvalues[i], beta[0] * v0 * v0)
        })
        .collect();
    pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
    if pairs
        .iter()
        .any(|(x, w)| !(x.is_finite() && w.is_finite() && *x > 0.0 && *x < 1.0))
    {
        return Err(NumericError::Eigen(m));
    }
    Ok(LogRule {
        nodes: pairs.iter().map(|p| p.0).collect(),
        weights: pairs.iter().map(|p| p.1).collect(),
    })
}

fn same_point(z: f64, e: f64) -> bool {
    (z - e).abs() <= 4.0 * f64::EPSILON * e.abs().max(z.abs())
}

/// `W(t)` at a point away from every factor.
fn weight_everywhere(factors: &[Factor], t: f64) -> f64 {
    factors
        .iter()
        .filter(|f| f.exponent != 0.0)
        .map(|f| pow_fast((t - f.at).abs(), f.exponent))
        .product()
}

/// `W(t)` on the piece `[a, b]` for the factors not sitting on its ends,
/// with distances taken through the nearer end (`s` is the reference
/// coordinate of `t`, so there is no cancellation near an end).
fn weight_off_ends(factors: &[Factor], a: f64, b: f64, t: f64) -> f64 {
    let mut v = 1.0;
    for f in factors.iter().filter(|f| f.exponent != 0.0) {
        if same_point(f.at, a) || same_point(f.at, b) {
            continue;
        }
        let dist = if f.at <= a {
            (a - f.at) + (t - a)
        } else if f.at >= b {
            (f.at - b) + (b - t)
        } else {
            (t - f.at).abs()
        };
        v *= pow_fast(dist, f.exponent);
    }
    v
}

/// Appends nodes and weights with `Σ w_q g(t_q) ≈ ∫_l^r g(t) W(t) S(x,t) dt`
/// (see the module text), using `m`-point rules on every piece; `weight`
/// holds the factors of `W`. Returns the number of pieces. A principal
/// value with `x` on an end of `[l, r]` diverges and is refused.
#[allow(clippy::too_many_arguments)]
pub fn diagonal_rule(
    l: f64,
    r: f64,
    x: f64,
    kind: DiagonalKind,
    weight: &[Factor],
    m: usize,
    cache: &RuleCache,
    t_out: &mut Vec<f64>,
    w_out: &mut Vec<f64>,
) -> Result<usize, NumericError> {
    if l > r || !l.is_finite() || !r.is_finite() || !x.is_finite() {
        return Err(NumericError::InvalidArgument(format!(
            "bad interval [{l}, {r}] or point {x}"
        )));
    }
    if l == r {
        return Ok(0);
    }
    let mut stack: Vec<(f64, f64)> = Vec::new();
    let inside = x > l && x < r && !same_point(x, l) && !same_point(x, r);
    match kind {
        DiagonalKind::Cauchy if inside => {
            // Symmetric fold on [x - δ, x + δ], away from the ends by 2δ.
            let delta = (x - l).min(r - x) / 3.0;
            let g = gauss_legendre(m)?;
            let (s, ws) = g.mapped(0.0, delta);
            for (s, w) in s.into_iter().zip(ws) {
                for sign in [1.0, -1.0] {
                    let t = x + sign * s;
                    t_out.push(t);
                    w_out.push(sign * w / s * weight_everywhere(weight, t));
                }
            }
            stack.push((x + delta, r));
            stack.push((l, x - delta));
        }
        DiagonalKind::Cauchy if same_point(x, l) || same_point(x, r) => {
            return Err(NumericError::NonFinite(format!(
                "principal value at the end x = {x} of [{l}, {r}]"
            )));
        }
        _ if inside => {
            stack.push((x, r));
            stack.push((l, x));
        }
        _ => stack.push((l, r)),
    }
    let width = match kind {
        DiagonalKind::Peaked { width } => width.abs(),
        _ => 0.0,
    };
    let mut pieces = 0;
    while let Some((a, b)) = stack.pop() {
        pieces += 1;
        if pieces > 4000 {
            return Err(NumericError::NoConvergence(
                "diagonal product rule needs too many pieces".into(),
            ));
        }
        let len = b - a;
        let x_at_a = same_point(x, a);
        let x_at_b = same_point(x, b);
        // Worst outside singular point: weight factors and the kernel's.
        let mut worst: Option<(f64, f64, f64)> = None; // (ratio, z, distance)
        let mut consider = |z: f64, d: f64| {
            let ratio = d / len;
            if ratio < ETA * (1.0 - 1e-9) && worst.is_none_or(|w| ratio < w.0) {
                worst = Some((ratio, z, d));
            }
        };
        for f in weight.iter().filter(|f| f.exponent != 0.0) {
            if same_point(f.at, a) || same_point(f.at, b) {
                continue;
            }
            consider(f.at, if f.at < a { a - f.at } else { f.at - b });
        }
        let kernel_d = if x_at_a || x_at_b {
            0.0
        } else if x < a {
            a - x
        } else {
            x - b
        };
        let kernel_d = match kind {
            DiagonalKind::Peaked { .. } => kernel_d.hypot(width),
            _ => kernel_d,
        };
        if !(x_at_a || x_at_b) || matches!(kind, DiagonalKind::Peaked { .. }) {
            consider(x, kernel_d);
        }
        if let Some((_, z, d)) = worst {
            let step = (d / ETA).clamp(len * 1e-300, 0.5 * len);
            let toward_a = if same_point(z, a) {
                true
            } else if same_point(z, b) {
                false
            } else {
                z <= a
            };
            if toward_a {
                stack.push((a + step, b));
                stack.push((a, a + step));
            } else {
                stack.push((a, b - step));
                stack.push((b - step, b));
            }
            continue;
        }
        // End exponents of the weight.
        let (mut ea, mut eb) = (0.0, 0.0);
        for f in weight.iter().filter(|f| f.exponent != 0.0) {
            if same_point(f.at, b) {
                ea += f.exponent;
            } else if same_point(f.at, a) {
                eb += f.exponent;
            }
        }
        let log_end = kind == DiagonalKind::Log && (x_at_a || x_at_b);
        if log_end {
            let (other, own) = if x_at_a { (ea, eb) } else { (eb, ea) };
            if own != 0.0 {
                return Err(NumericError::InvalidArgument(format!(
                    "log kernel at a weighted end x = {x}"
                )));
            }
            if other != 0.0 {
                let mid = 0.5 * (a + b);
                stack.push((mid, b));
                stack.push((a, mid));
                continue;
            }
            // ∫_a^b g ln|t-x| dt = len [ln(len) ∫_0^1 g du + ∫_0^1 g ln u du],
            // u measured from x.
            let at = |u: f64| if x_at_a { a + len * u } else { b - len * u };
            let g = gauss_legendre(m)?;
            let lnh = len.ln();
            for (s, w) in g.nodes.iter().zip(&g.weights) {
                let u = 0.5 * (1.0 + s);
                let t = at(u);
                t_out.push(t);
                w_out.push(len * 0.5 * w * lnh * weight_off_ends(weight, a, b, t));
            }
            let lr = log_rule(m)?;
            for (u, w) in lr.nodes.iter().zip(&lr.weights) {
                let t = at(*u);
                t_out.push(t);
                w_out.push(-len * w * weight_off_ends(weight, a, b, t));
            }
            continue;
        }
        let rule = cache.get(m, ea, eb)?;
        let (ts, ws) = rule.mapped(a, b);
        let half = 0.5 * len;
        for ((t, w), s) in ts.into_iter().zip(ws).zip(&rule.nodes) {
            // t - x through the nearer end.
            let d = if x_at_a {
                half * (1.0 + s)
            } else if x_at_b {
                -half * (1.0 - s)
            } else if x <= a {
                (a - x) + half * (1.0 + s)
            } else {
                -((x - b) + half * (1.0 - s))
            };
            t_out.push(t);
            w_out.push(w * kind.value(d) * weight_off_ends(weight, a, b, t));
        }
    }
    Ok(pieces)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn integrate(
        l: f64,
        r: f64,
        x: f64,
        k: DiagonalKind,
        wf: &[Factor],
        g: impl Fn(f64) -> f64,
    ) -> f64 {
        let cache = RuleCache::new();
        let (mut t, mut w) = (vec![], vec![]);
        diagonal_rule(l, r, x, k, wf, 14, &cache, &mut t, &mut w).unwrap();
        t.iter().zip(&w).map(|(t, w)| w * g(*t)).sum()
    }

    #[test]
    fn log_rule_moments() {
        for m in [1, 5, 20, 30] {
            let r = log_rule(m).unwrap();
            for k in 0..2 * m {
                let s: f64 = r
                    .nodes
                    .iter()
                    .zip(&r.weights)
                    .map(|(u, w)| w * u.powi(k as i32))
                    .sum();
                let exact = 1.0 / ((k + 1) as f64).powi(2);
                assert!(
                    (s - exact).abs() < 1e-15 * 4.0,
                    "m={m} k={k}: {s} vs {exact}"
                );
            }
        }
    }

    #[test]
    fn log_kernel_inside_and_outside() {
        // ∫_{-1}^{1} ln|t - x| dt = (1-x)ln(1-x) + (1+x)ln(1+x) - 2.
        let f = |x: f64| {
            let p = |y: f64| if y == 0.0 { 0.0 } else { y * y.abs().ln() };
            p(1.0 - x) + p(1.0 + x) - 2.0
        };
        for &x in &[-0.999, -0.3, 0.0, 0.77, 1.0, 1.0 + 1e-9, 1.5] {
            let got = integrate(-1.0, 1.0, x, DiagonalKind::Log, &[], |_| 1.0);
            assert!((got - f(x)).abs() < 1e-14, "x={x}: {got} vs {}", f(x));
        }
    }

    #[test]
    fn carleman_identity_with_edge_weight() {
        // ∫_{-1}^{1} ln|x - t| / √(1-t²) dt = -π ln 2 for |x| < 1.
        let wf = [
            Factor {
                at: 1.0,
                exponent: -0.5,
            },
            Factor {
                at: -1.0,
                exponent: -0.5,
            },
        ];
        for &x in &[-0.9999, -0.5, 0.1, 0.95] {
            // Pieces [-1, 0] and [0, 1] as a basis would have them.
            let got = integrate(-1.0, 0.0, x, DiagonalKind::Log, &wf, |_| 1.0)
                + integrate(0.0, 1.0, x, DiagonalKind::Log, &wf, |_| 1.0);
            let exact = -std::f64::consts::PI * std::f64::consts::LN_2;
            assert!((got - exact).abs() < 1e-13, "x={x}: {got} vs {exact}");
        }
    }

    #[test]
    fn cauchy_principal_values() {
        // PV ∫_{-1}^{1} √(1-t²)/(t - x) dt = -π x.
        let wf = [
            Factor {
                at: 1.0,
                exponent: 0.5,
            },
            Factor {
                at: -1.0,
                exponent: 0.5,
            },
        ];
        for &x in &[-0.999, -0.4, 0.0, 0.3, 0.9999] {
            let got = integrate(-1.0, 1.0, x, DiagonalKind::Cauchy, &wf, |_| 1.0);
            let exact = -std::f64::consts::PI * x;
            assert!((got - exact).abs() < 1e-13, "x={x}: {got} vs {exact}");
        }
        // PV ∫_0^1 t²/(t - x) dt = x + 1/2 + x² ln((1-x)/x); also x outside.
        for &x in &[0.01, 0.5, 0.93] {
            let got = integrate(0.0, 1.0, x, DiagonalKind::Cauchy, &[], |t| t * t);
            let exact = x + 0.5 + x * x * ((1.0 - x) / x).ln();
            assert!((got - exact).abs() < 1e-13, "x={x}: {got} vs {exact}");
        }
        let x = 1.0 + 1e-6;
        let got = integrate(0.0, 1.0, x, DiagonalKind::Cauchy, &[], |_| 1.0);
        let exact = ((x - 1.0) / x).ln(); // x - 1 is exact

        assert!(
            (got - exact).abs() < 1e-12 * exact.abs(),
            "{got} vs {exact}"
        );
        let cache = RuleCache::new();
        let (mut t, mut w) = (vec![], vec![]);
        assert!(
            diagonal_rule(
                0.0,
                1.0,
                1.0,
                DiagonalKind::Cauchy,
                &[],
                8,
                &cache,
                &mut t,
                &mut w
            )
            .is_err()
        );
    }

    #[test]
    fn peaked_kernel_is_resolved() {
        // ∫_{-1}^{1} κ/(κ² + (x-t)²) dt = atan((1-x)/κ) + atan((1+x)/κ).
        for &kappa in &[0.1, 1e-3] {
            for &x in &[-1.0, -0.999, 0.0, 0.42] {
                let got = integrate(
                    -1.0,
                    1.0,
                    x,
                    DiagonalKind::Peaked { width: kappa },
                    &[],
                    |t| kappa / (kappa * kappa + (x - t) * (x - t)),
                );
                let exact = ((1.0 - x) / kappa).atan() + ((1.0 + x) / kappa).atan();
                assert!(
                    (got - exact).abs() < 1e-13,
                    "κ={kappa} x={x}: {got} vs {exact}"
                );
            }
        }
    }
}
