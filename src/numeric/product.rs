//! Product-integration rules for integrands `g(t) Π_k |t - z_k|^{e_k}` with
//! `g` smooth: the interval is split at interior singular points, pieces
//! near an outside singular point are graded geometrically toward it (each
//! piece at least `η` times its length away), and a singular point sitting
//! on a piece's end is integrated exactly by Gauss–Jacobi. This is how the
//! `|t²-x²|^{-1/2} = |t-x|^{-1/2}|t+x|^{-1/2}` diagonal singularity, its
//! near-diagonal neighbours and the factored edge weights are all handled.
//! Owns the rule cache and the splitting; it must not know about bases,
//! kernels or operators.
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

use super::basis::{Factor, pow_fast};
use super::error::NumericError;
use super::gauss::{GaussRule, gauss_jacobi};

/// Distance/length ratio below which an outside singular point forces a
/// split (the Bernstein-ellipse parameter of the remaining factor is then
/// at least `3 + 2√2`).
pub const ETA: f64 = 1.0;

/// A thread-safe cache of Gauss–Jacobi rules keyed by `(n, a, b)`.
#[derive(Debug, Default)]
pub struct RuleCache {
    map: Mutex<HashMap<(usize, u64, u64), Arc<GaussRule>>>,
}

impl RuleCache {
    /// An empty cache.
    pub fn new() -> RuleCache {
        RuleCache::default()
    }

    /// The process-wide cache every [`crate::numeric::Assembler`] uses: a
    /// rule depends only on `(n, a, b)`, and one solve builds dozens of
    /// assemblers (one per basis per discretisation, several
    /// discretisations per root iteration) that need the same few rules.
    /// Cleared when it holds more than `SHARED_RULES` rules (a long sweep
    /// meets new edge exponents at every point).
    pub fn shared() -> &'static RuleCache {
        static SHARED: OnceLock<RuleCache> = OnceLock::new();
        SHARED.get_or_init(RuleCache::new)
    }

    /// The `n`-point rule for `(1-s)^a (1+s)^b`, computed once.
    pub fn get(&self, n: usize, a: f64, b: f64) -> Result<Arc<GaussRule>, NumericError> {
        type Local = std::cell::RefCell<HashMap<(usize, u64, u64), Arc<GaussRule>>>;
        thread_local! {
            // A rule is a function of `(n, a, b)` alone, so one memo per
            // thread serves every cache without taking its lock (the
            // assembly asks for a rule once per quadrature piece, from
            // several threads).
            static LOCAL: Local = Default::default();
        }
        let key = (n, a.to_bits(), b.to_bits());
        let remember = |r: &Arc<GaussRule>| {
            LOCAL.with(|l| {
                let mut l = l.borrow_mut();
                if l.len() >= SHARED_RULES {
                    l.clear();
                }
                l.insert(key, r.clone());
            })
        };
        if let Some(r) = LOCAL.with(|l| l.borrow().get(&key).cloned()) {
            return Ok(r);
        }
        if let Ok(m) = self.map.lock()
            && let Some(r) = m.get(&key)
        {
            remember(r);
            return Ok(r.clone());
        }
        let r = Arc::new(gauss_jacobi(n, a, b)?);
        remember(&r);
        if let Ok(mut m) = self.map.lock() {
            if m.len() >= SHARED_RULES {
                m.clear();
            }
            m.insert(key, r.clone());
        }
        Ok(r)
    }
}

/// Most rules a [`RuleCache`] keeps (a few hundred kilobytes).
const SHARED_RULES: usize = 4096;

fn same_point(z: f64, e: f64) -> bool {
    (z - e).abs() <= 4.0 * f64::EPSILON * e.abs().max(z.abs())
}

/// Appends nodes `t` and weights `w` such that
/// `Σ w_q g(t_q) ≈ ∫_l^r g(t) Π_k |t - z_k|^{e_k} dt` for smooth `g`,
/// using `m`-point rules on every piece. Factors with exponent 0 are
/// ignored. Returns the number of pieces used.
#[cfg(any(test, feature = "internals"))]
pub fn composite_rule(
    l: f64,
    r: f64,
    factors: &[Factor],
    m: usize,
    cache: &RuleCache,
    t_out: &mut Vec<f64>,
    w_out: &mut Vec<f64>,
) -> Result<usize, NumericError> {
    composite_each(l, r, factors, m, cache, |t, w, _, _| {
        t_out.push(t);
        w_out.push(w);
    })
}

/// A product rule with every node's distance from both ends of its
/// interval: see [`composite_rule_offsets`].
#[derive(Debug, Clone, Default)]
pub struct OffsetRule {
    /// Nodes.
    pub t: Vec<f64>,
    /// Weights (the factors included).
    pub w: Vec<f64>,
    /// `t - l`, to relative rounding.
    pub from_l: Vec<f64>,
    /// `r - t`, to relative rounding.
    pub from_r: Vec<f64>,
}

impl OffsetRule {
    /// Empties the rule, keeping its storage.
    pub fn clear(&mut self) {
        self.t.clear();
        self.w.clear();
        self.from_l.clear();
        self.from_r.clear();
    }
}

/// As [`composite_rule`] (the same nodes and weights), appending to `out`
/// also each node's distances `t - l` and `r - t`, accurate to relative
/// rounding. On a panel much shorter than its distance from 0 the node `t`
/// itself is only known to `ulp(t)`, which is a large part of the panel
/// (1e-16 of 0.8 is 3e-4 of a panel of length 4e-13 next to a
/// breakpoint): a factor `|t - z|^e` of a point `z` outside the interval
/// evaluated from `t` then carries that relative error, while
/// `(l - z) + (t - l)` does not; so does the reference coordinate of `t` in
/// the interval, which Lagrange evaluation needs.
pub fn composite_rule_offsets(
    l: f64,
    r: f64,
    factors: &[Factor],
    m: usize,
    cache: &RuleCache,
    out: &mut OffsetRule,
) -> Result<usize, NumericError> {
    composite_each(l, r, factors, m, cache, |t, w, from_l, from_r| {
        out.t.push(t);
        out.w.push(w);
        out.from_l.push(from_l);
        out.from_r.push(from_r);
    })
}

/// The rule of [`composite_rule`], node by node: `emit(t, w, t - l, r - t)`.
fn composite_each(
    l: f64,
    r: f64,
    factors: &[Factor],
    m: usize,
    cache: &RuleCache,
    mut emit: impl FnMut(f64, f64, f64, f64),
) -> Result<usize, NumericError> {
    if l > r || !l.is_finite() || !r.is_finite() {
        return Err(NumericError::InvalidArgument(format!(
            "bad interval [{l}, {r}]"
        )));
    }
    if l == r {
        return Ok(0);
    }
    // Split at interior singular points first.
    let mut cuts: Vec<f64> = factors
        .iter()
        .filter(|f| {
            f.exponent != 0.0
                && f.at > l
                && f.at < r
                && !same_point(f.at, l)
                && !same_point(f.at, r)
        })
        .map(|f| f.at)
        .collect();
    cuts.sort_by(|a, b| a.total_cmp(b));
    cuts.dedup();
    let mut stack: Vec<(f64, f64)> = Vec::new();
    let mut prev = l;
    for c in cuts.into_iter().chain(std::iter::once(r)) {
        stack.push((prev, c));
        prev = c;
    }
    let mut pieces = 0;
    while let Some((a, b)) = stack.pop() {
        pieces += 1;
        if pieces > 2000 {
            return Err(NumericError::NoConvergence(
                "product rule needs too many pieces".into(),
            ));
        }
        let len = b - a;
        // Worst outside singular point (not on an end).
        let mut worst: Option<(f64, f64)> = None; // (ratio, z)
        for f in factors.iter().filter(|f| f.exponent != 0.0) {
            if same_point(f.at, a) || same_point(f.at, b) {
                continue;
            }
            let d = if f.at < a { a - f.at } else { f.at - b };
            let ratio = d / len;
            if ratio < ETA * (1.0 - 1e-9) && worst.is_none_or(|w| ratio < w.0) {
                worst = Some((ratio, f.at));
            }
        }
        if let Some((_, z)) = worst {
            // Cut so that the piece next to z has length = distance / η.
            let d = if z < a { a - z } else { z - b };
            let step = (d / ETA).clamp(len * 1e-300, 0.5 * len);
            if z < a {
                stack.push((a + step, b));
                stack.push((a, a + step));
            } else {
                stack.push((a, b - step));
                stack.push((b - step, b));
            }
            continue;
        }
        // Endpoint exponents: `ea` at the right end (1-s)^ea, `eb` at the left.
        let (mut ea, mut eb) = (0.0, 0.0);
        for f in factors.iter().filter(|f| f.exponent != 0.0) {
            if same_point(f.at, b) {
                ea += f.exponent;
            } else if same_point(f.at, a) {
                eb += f.exponent;
            }
        }
        let rule = cache.get(m, ea, eb)?;
        // `rule.mapped(a, b)` without its two vectors (the same numbers).
        let half = 0.5 * (b - a);
        let scale = half.powf(1.0 + rule.a + rule.b);
        for (s, w) in rule.nodes.iter().zip(&rule.weights) {
            let t = a + half * (1.0 + s);
            let mut v = w * scale;
            for f in factors.iter().filter(|f| f.exponent != 0.0) {
                if same_point(f.at, a) || same_point(f.at, b) {
                    continue;
                }
                // Distance through the nearer end: a sum of two positive,
                // accurately known numbers (no cancellation near `z`).
                let dist = if f.at < a {
                    (a - f.at) + half * (1.0 + s)
                } else {
                    (f.at - b) + half * (1.0 - s)
                };
                v *= pow_fast(dist, f.exponent);
            }
            // Both sums of two positive numbers, each accurate (`a - l`
            // and `r - b` are differences of nearby breakpoints).
            emit(t, v, (a - l) + half * (1.0 + s), (r - b) + half * (1.0 - s));
        }
    }
    Ok(pieces)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn integrate(l: f64, r: f64, f: &[Factor], g: impl Fn(f64) -> f64) -> f64 {
        let cache = RuleCache::new();
        let (mut t, mut w) = (vec![], vec![]);
        composite_rule(l, r, f, 12, &cache, &mut t, &mut w).unwrap();
        t.iter().zip(&w).map(|(t, w)| w * g(*t)).sum()
    }

    #[test]
    fn abel_diagonal_inside_and_at_ends() {
        // ∫_0^1 |t² - x²|^{-1/2} t dt = √(1-x²) + x  (both sides of x).
        for &x in &[0.0001, 0.01, 0.3, 0.5, 0.999, 1.0] {
            let f = [
                Factor {
                    at: x,
                    exponent: -0.5,
                },
                Factor {
                    at: -x,
                    exponent: -0.5,
                },
            ];
            let got = integrate(0.0, 1.0, &f, |t| t);
            let exact = (1.0f64 - x * x).sqrt() + x;
            assert!((got - exact).abs() < 1e-14, "x={x}: {got} vs {exact}");
        }
    }

    #[test]
    fn near_singular_outside_point() {
        // ∫_a^1 (t - z)^{-1/2} dt = 2(√(1-z) - √(a-z)) with z just below a.
        for &gap in &[1e-1, 1e-4, 1e-9, 1e-13] {
            let a = 0.5;
            let z = a - gap;
            let f = [Factor {
                at: z,
                exponent: -0.5,
            }];
            let got = integrate(a, 1.0, &f, |_| 1.0);
            let d = a - z; // the gap actually represented (z is rounded)
            let exact = 2.0 * ((1.0 - z).sqrt() - d.sqrt());
            assert!((got - exact).abs() < 1e-14, "gap={gap}: {got} vs {exact}");
        }
    }

    #[test]
    fn two_endpoint_exponents() {
        // ∫_0^1 (1-t)^{-0.3} t^{-0.5} dt = B(0.5, 0.7).
        let f = [
            Factor {
                at: 1.0,
                exponent: -0.3,
            },
            Factor {
                at: 0.0,
                exponent: -0.5,
            },
        ];
        let got = integrate(0.0, 1.0, &f, |_| 1.0);
        let lg = super::super::gamma::ln_gamma;
        let exact = (lg(0.5) + lg(0.7) - lg(1.2)).exp();
        assert!((got - exact).abs() < 1e-14);
    }
}
