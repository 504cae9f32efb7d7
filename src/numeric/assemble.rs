//! Discretisation of [`Operator`]s on a [`PanelBasis`] by collocation: entry
//! `(i, j)` of the matrix is the operator applied to basis function `j`,
//! evaluated at point `x_i`. Every integral is a product integral computed
//! by \[`composite_rule`\]: the smooth factor `a(x,t)` times the Lagrange
//! polynomial is integrated against the exact singular weight
//! (`|t-x|^{-1/2}|t+x|^{-1/2}` and the basis weight), so the diagonal
//! singularity and the factored edge exponent cost no accuracy. Panels far
//! from `x` use a per-panel rule prepared once.
//!
//! Why collocation: the equations are of the first kind with Abel kernels;
//! collocation at the basis' own Gauss nodes gives square systems without
//! an outer quadrature (a Galerkin method would need a second, singular,
//! integration in `x`), products of operators become matrix products on
//! one intermediate basis (values at nodes are coefficients), and on
//! geometrically graded meshes with degrees rising away from the singular
//! points it converges exponentially in the number of unknowns, which the
//! convergence tests measure. This file owns assembly only; it must not
//! solve systems or know about any particular problem.
use nalgebra::DMatrix;
use rayon::prelude::*;

use super::basis::{Factor, PanelBasis};
use super::error::NumericError;
use super::kernels::{DiagonalKind, diagonal_rule};
use super::operator::{Limits, Operator, Singularity, Term};
use super::product::{ETA, OffsetRule, RuleCache, composite_rule_offsets};

/// Extra quadrature nodes per panel beyond its interpolation nodes.
pub const DEFAULT_EXTRA_NODES: usize = 10;

/// Distance (in panel lengths) from a diagonal singular point beyond which
/// a panel that counts as near (closer than [`ETA`] lengths) is still
/// integrated by a rule prepared once per panel, with
/// [`MID_EXTRA_NODES`] more nodes than the far rule, instead of a product
/// rule split toward the point. At a distance `δ·h` the integrand is
/// analytic inside the Bernstein ellipse of parameter
/// `ρ = 1 + 2δ + 2√(δ² + δ) ≥ 2.62` (δ = 1/4), so the prepared rule's
/// error falls like `ρ^(-2·extra)`: `2.62^(-40) ≈ 2e-17` with
/// `extra = 20` (the far rule: `ρ ≥ 5.83`, `5.83^(-20) ≈ 5e-16`; the
/// unit test finds the two equally accurate for 3 to 15 nodes, and the
/// test fails with 2 extra nodes instead of 10). On the
/// geometric meshes of the split solver most near panels are of this kind
/// (every panel of a grading but the two next to the collocation point's
/// own), and the split rule cost a Lagrange evaluation and a power per
/// node (measured: about half of the assembly time).
pub const MID_DISTANCE: f64 = 0.25;

/// Extra nodes of the prepared rule for panels between [`MID_DISTANCE`]
/// and [`ETA`] lengths from the singular point, beyond the far rule's.
pub const MID_EXTRA_NODES: usize = 10;

struct FarRule {
    t: Vec<f64>,
    w: Vec<f64>,
    /// `t_q - a` and `b - t_q` (the panel's ends), to relative rounding.
    from_a: Vec<f64>,
    from_b: Vec<f64>,
    /// Lagrange values, row-major: `lag[q * n + j] = ℓ_j(t_q)`.
    lag: Vec<f64>,
}

/// The reference coordinate in `[-1, 1]` of a node `from_a` from a
/// panel's left end and `from_b` from its right end (`h = b - a`), from
/// the nearer end.
fn ref_coord(from_a: f64, from_b: f64, h: f64) -> f64 {
    if from_a <= from_b {
        -1.0 + 2.0 * (from_a / h)
    } else {
        1.0 - 2.0 * (from_b / h)
    }
}

/// `t - z` for a node `t` of the panel `[a, b]` with the distances
/// `from_a = t - a`, `from_b = b - t`: through the nearer end when `z` is
/// outside the panel (a sum of two positive, accurately known numbers,
/// where `t - z` would carry the rounding of `t`).
fn node_minus(z: f64, a: f64, b: f64, t: f64, from_a: f64, from_b: f64) -> f64 {
    if z <= a {
        (a - z) + from_a
    } else if z >= b {
        -((z - b) + from_b)
    } else {
        t - z
    }
}

/// Assembles operator matrices for one trial basis.
pub struct Assembler<'b> {
    basis: &'b PanelBasis,
    far: Vec<FarRule>,
    /// Per panel, the rule for panels [`MID_DISTANCE`] to [`ETA`] lengths
    /// from the singular point.
    mid: Vec<FarRule>,
    cache: &'static RuleCache,
    extra: usize,
}

impl<'b> Assembler<'b> {
    /// Prepares per-panel rules for `basis` with the default quadrature.
    pub fn new(basis: &'b PanelBasis) -> Result<Assembler<'b>, NumericError> {
        Assembler::with_extra_nodes(basis, DEFAULT_EXTRA_NODES)
    }

    /// As [`Assembler::new`] with `extra` quadrature nodes beyond the
    /// interpolation nodes on every piece.
    pub fn with_extra_nodes(
        basis: &'b PanelBasis,
        extra: usize,
    ) -> Result<Assembler<'b>, NumericError> {
        let cache = RuleCache::shared();
        let mut far = Vec::with_capacity(basis.panels.len());
        let mut mid = Vec::with_capacity(basis.panels.len());
        for p in &basis.panels {
            let n = p.nodes.len();
            let h = p.b - p.a;
            for (rules, m) in [
                (&mut far, n.div_ceil(2) + extra),
                (&mut mid, n.div_ceil(2) + extra + MID_EXTRA_NODES),
            ] {
                let mut r = OffsetRule::default();
                composite_rule_offsets(p.a, p.b, &basis.weight, m, cache, &mut r)?;
                let mut lag = vec![0.0; r.t.len() * n];
                for (q, (&fa, &fb)) in r.from_l.iter().zip(&r.from_r).enumerate() {
                    p.lagrange_ref(ref_coord(fa, fb, h), &mut lag[q * n..(q + 1) * n]);
                }
                rules.push(FarRule {
                    t: r.t,
                    w: r.w,
                    from_a: r.from_l,
                    from_b: r.from_r,
                    lag,
                });
            }
        }
        Ok(Assembler {
            basis,
            far,
            mid,
            cache,
            extra,
        })
    }

    /// The trial basis.
    pub fn basis(&self) -> &PanelBasis {
        self.basis
    }

    /// The collocation matrix `(op φ_j)(x_i)`, `points.len() × dim`.
    pub fn matrix(&self, op: &Operator, points: &[f64]) -> Result<DMatrix<f64>, NumericError> {
        let (lo, hi) = self.basis.support();
        self.matrix_on(op, points, (lo, hi))
    }

    /// As [`Assembler::matrix`] for the trial functions restricted to the
    /// window `[w0, w1]` (functions are set to zero outside it; the window
    /// ends should be breakpoints).
    pub fn matrix_on(
        &self,
        op: &Operator,
        points: &[f64],
        window: (f64, f64),
    ) -> Result<DMatrix<f64>, NumericError> {
        let dim = self.basis.dim();
        let rows: Vec<Vec<f64>> = points
            .par_iter()
            .map(|&x| {
                let mut row = vec![0.0; dim];
                self.row_into(op, x, window, &mut row)?;
                Ok(row)
            })
            .collect::<Result<_, NumericError>>()?;
        Ok(DMatrix::from_fn(points.len(), dim, |i, j| rows[i][j]))
    }

    /// Adds the row of `op` at `x` (trial functions restricted to `window`)
    /// into `row` (length `dim`).
    pub fn row_into(
        &self,
        op: &Operator,
        x: f64,
        window: (f64, f64),
        row: &mut [f64],
    ) -> Result<(), NumericError> {
        if row.len() != self.basis.dim() {
            return Err(NumericError::Dimension(format!(
                "row of {} for dim {}",
                row.len(),
                self.basis.dim()
            )));
        }
        if !x.is_finite() {
            return Err(NumericError::NonFinite(format!("collocation point {x}")));
        }
        for (c, term) in &op.terms {
            match term {
                Term::Multiply(m) => self.add_multiply(*c, m.as_ref(), x, window, row),
                Term::Integral {
                    limits,
                    singularity,
                    kernel,
                } => {
                    self.add_integral(*c, *limits, *singularity, kernel.as_ref(), x, window, row)?
                }
            }
        }
        if let Some(v) = row.iter().find(|v| !v.is_finite()) {
            return Err(NumericError::NonFinite(format!(
                "operator row at x = {x} (entry {v})"
            )));
        }
        Ok(())
    }

    fn add_multiply(
        &self,
        c: f64,
        m: &(dyn Fn(f64) -> f64 + Send + Sync),
        x: f64,
        window: (f64, f64),
        row: &mut [f64],
    ) {
        if !(x >= window.0 && x <= window.1) {
            return;
        }
        let Some(k) = self.basis.panel_of(x) else {
            return;
        };
        let p = &self.basis.panels[k];
        let n = p.nodes.len();
        let mut l = vec![0.0; n];
        p.lagrange(x, &mut l);
        let s = c * m(x) * self.basis.weight_at(x);
        for (r, v) in row[p.offset..p.offset + n].iter_mut().zip(&l) {
            *r += s * v;
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn add_integral(
        &self,
        c: f64,
        limits: Limits,
        sing: Singularity,
        a: &(dyn Fn(f64, f64) -> f64 + Send + Sync),
        x: f64,
        window: (f64, f64),
        row: &mut [f64],
    ) -> Result<(), NumericError> {
        let (l0, h0, sign) = limits.range_at(x);
        let c = sign * c;
        let lo = l0.max(window.0);
        let hi = h0.min(window.1);
        if lo.partial_cmp(&hi) != Some(std::cmp::Ordering::Less) {
            return Ok(());
        }
        let mut factors: Vec<Factor> = self.basis.weight.clone();
        let diagonal = match sing {
            Singularity::AbelSqrt => {
                factors.push(Factor {
                    at: x,
                    exponent: -0.5,
                });
                factors.push(Factor {
                    at: -x,
                    exponent: -0.5,
                });
                None
            }
            Singularity::Power { beta } => {
                factors.push(Factor {
                    at: x,
                    exponent: -beta,
                });
                None
            }
            Singularity::Smooth => None,
            Singularity::Log => Some(DiagonalKind::Log),
            Singularity::Cauchy => Some(DiagonalKind::Cauchy),
            Singularity::Peaked { width } => Some(DiagonalKind::Peaked { width }),
        };
        let mut ts = Vec::new();
        let mut ws = Vec::new();
        let mut rule = OffsetRule::default();
        let mut lag = Vec::new();
        for (k, p) in self.basis.panels.iter().enumerate() {
            if p.b <= lo || p.a >= hi {
                continue;
            }
            let n = p.nodes.len();
            let seg = (p.a.max(lo), p.b.min(hi));
            let h = p.b - p.a;
            let dist = |z: f64| {
                if z < p.a {
                    p.a - z
                } else if z > p.b {
                    z - p.b
                } else {
                    0.0
                }
            };
            let near = match sing {
                Singularity::Smooth => false,
                Singularity::AbelSqrt => {
                    let near_x = |z: f64| z > p.a - ETA * h && z < p.b + ETA * h;
                    near_x(x) || near_x(-x)
                }
                Singularity::Peaked { width } => dist(x).hypot(width) < ETA * h,
                _ => dist(x) < ETA * h,
            };
            let clipped = seg.0 > p.a || seg.1 < p.b;
            let out = &mut row[p.offset..p.offset + n];
            let prepared = if clipped {
                None
            } else if !near {
                Some(&self.far[k])
            } else {
                let apart = |z: f64| dist(z) >= MID_DISTANCE * h;
                match sing {
                    Singularity::AbelSqrt if apart(x) && apart(-x) => Some(&self.mid[k]),
                    Singularity::Power { .. } if apart(x) => Some(&self.mid[k]),
                    _ => None,
                }
            };
            if let Some(f) = prepared {
                for q in 0..f.t.len() {
                    let t = f.t[q];
                    let mut v = c * f.w[q] * a(x, t);
                    let minus = |z: f64| node_minus(z, p.a, p.b, t, f.from_a[q], f.from_b[q]);
                    match sing {
                        Singularity::Smooth | Singularity::Peaked { .. } => {}
                        Singularity::AbelSqrt => v /= (minus(x).abs() * minus(-x).abs()).sqrt(),
                        s => v *= s.value_from(minus(x), t + x),
                    }
                    for (o, lj) in out.iter_mut().zip(&f.lag[q * n..(q + 1) * n]) {
                        *o += v * lj;
                    }
                }
            } else {
                let m = n.div_ceil(2) + self.extra;
                lag.resize(n, 0.0);
                match diagonal {
                    Some(kind) => {
                        ts.clear();
                        ws.clear();
                        diagonal_rule(
                            seg.0,
                            seg.1,
                            x,
                            kind,
                            &self.basis.weight,
                            m,
                            self.cache,
                            &mut ts,
                            &mut ws,
                        )?;
                        for (&t, &w) in ts.iter().zip(&ws) {
                            p.lagrange(t, &mut lag);
                            let v = c * w * a(x, t);
                            for (o, lj) in out.iter_mut().zip(&lag) {
                                *o += v * lj;
                            }
                        }
                    }
                    None => {
                        rule.clear();
                        composite_rule_offsets(seg.0, seg.1, &factors, m, self.cache, &mut rule)?;
                        // The nodes' distances from the panel's ends.
                        let (da, db) = (seg.0 - p.a, p.b - seg.1);
                        for q in 0..rule.t.len() {
                            let s = ref_coord(da + rule.from_l[q], db + rule.from_r[q], h);
                            p.lagrange_ref(s, &mut lag);
                            let v = c * rule.w[q] * a(x, rule.t[q]);
                            for (o, lj) in out.iter_mut().zip(&lag) {
                                *o += v * lj;
                            }
                        }
                    }
                }
            }
        }
        Ok(())
    }

    /// Row vector of the functional `f ↦ ∫_lo^hi g(t) f(t) dt` (smooth `g`),
    /// restricted to the basis support.
    pub fn functional(
        &self,
        g: impl Fn(f64) -> f64 + Send + Sync + 'static,
        lo: f64,
        hi: f64,
    ) -> Result<Vec<f64>, NumericError> {
        let op = Operator::smooth(lo, hi, move |_x, t| g(t));
        let mut row = vec![0.0; self.basis.dim()];
        let (l, h) = self.basis.support();
        self.row_into(&op, 0.0, (l, h), &mut row)?;
        Ok(row)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::Mesh;
    use crate::numeric::product::composite_rule;

    /// The largest difference, relative to the largest entry, between the
    /// row of `∫_0.5^1 (t + x²) φ_j(t) (1-t)^(-0.3) / √|t² - x²| dt` at
    /// `x = 0.5 - δ·h` as assembled and by the product rule split toward
    /// `±x` with 40 nodes per piece.
    fn row_error(n: usize, delta: f64) -> f64 {
        let weight = vec![Factor {
            at: 1.0,
            exponent: -0.3,
        }];
        let mesh = Mesh::from_breaks(vec![0.5, 1.0]).unwrap();
        let basis = PanelBasis::new(&mesh, &[n], weight.clone()).unwrap();
        let asm = Assembler::new(&basis).unwrap();
        let p = &basis.panels[0];
        let x = p.a - delta * (p.b - p.a);
        let op = Operator::abel_fixed(0.5, 1.0, |x, t| t + x * x);
        let mut row = vec![0.0; n];
        asm.row_into(&op, x, (0.5, 1.0), &mut row).unwrap();
        let mut factors = weight;
        factors.push(Factor {
            at: x,
            exponent: -0.5,
        });
        factors.push(Factor {
            at: -x,
            exponent: -0.5,
        });
        let (mut ts, mut ws) = (Vec::new(), Vec::new());
        let cache = RuleCache::new();
        composite_rule(p.a, p.b, &factors, 40, &cache, &mut ts, &mut ws).unwrap();
        let mut exact = vec![0.0; n];
        let mut lag = vec![0.0; n];
        for (&t, &w) in ts.iter().zip(&ws) {
            p.lagrange(t, &mut lag);
            for (e, l) in exact.iter_mut().zip(&lag) {
                *e += w * (t + x * x) * l;
            }
        }
        let scale = exact.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        row.iter()
            .zip(&exact)
            .map(|(a, b)| (a - b).abs() / scale)
            .fold(0.0, f64::max)
    }

    /// Panels between [`MID_DISTANCE`] and [`ETA`] lengths from the
    /// collocation point (the prepared mid rule) are as accurate as far
    /// panels (the prepared far rule, whose difference from the reference
    /// is the rules' own rounding, a few 1e-14 at 15 nodes), for every node
    /// count the split solver uses, with an edge weight like the Hertz
    /// pressure's.
    #[test]
    fn the_prepared_near_rule_is_as_accurate_as_the_far_rule() {
        for n in 3..=15 {
            let far = [1.5, 3.0].map(|d| row_error(n, d));
            let far = far[0].max(far[1]);
            let mid = [MID_DISTANCE, 0.3, 0.5, 0.75, 0.99].map(|d| row_error(n, d));
            let mid = mid.iter().fold(0.0f64, |m, v| m.max(*v));
            assert!(
                mid <= (2.0 * far).max(1e-14) && mid < 1e-13,
                "{n} nodes: near {mid:e}, far {far:e}"
            );
        }
    }

    /// The row of `∫ t φ_j(t) W(t) / √|t² - x²| dt` over the one panel
    /// `[a, a + h]` at the point `x = z + off` (`z` the left end if `left`,
    /// else the right end), as assembled and as computed in the panel's own
    /// coordinate `u = (t - a)/h`, where every distance is an `O(1)` number
    /// (`|t - x| = h·|u - u₀|`, `W` from the exact `u`): the largest
    /// difference relative to the largest entry. `W` is `(1-t)^(-0.47)`
    /// and, if `end_weight`, also `|t - z_w|^(-1/2)` at the panel's right end
    /// (the stick shear's weight at c).
    fn tiny_row_error(n: usize, a: f64, h: f64, x_from_a: f64, end_weight: bool) -> f64 {
        let b = a + h;
        let h = b - a; // the panel actually represented
        let mut weight = vec![Factor {
            at: 1.0,
            exponent: -0.47,
        }];
        if end_weight {
            weight.push(Factor {
                at: b,
                exponent: -0.5,
            });
        }
        let mesh = Mesh::from_breaks(vec![a, b]).unwrap();
        let basis = PanelBasis::new(&mesh, &[n], weight).unwrap();
        let asm = Assembler::new(&basis).unwrap();
        let x = a + x_from_a;
        // `x - a` exactly, as a double (Sterbenz: x and a are close).
        let xa = x - a;
        let op = Operator::abel_fixed(0.0, 1.0, |_x, t| t);
        let mut row = vec![0.0; n];
        asm.row_into(&op, x, (a, b), &mut row).unwrap();
        // The reference in u ∈ [0, 1].
        let u0 = xa / h;
        let mut factors = vec![Factor {
            at: u0,
            exponent: -0.5,
        }];
        if end_weight {
            factors.push(Factor {
                at: 1.0,
                exponent: -0.5,
            });
        }
        let (mut us, mut ws) = (Vec::new(), Vec::new());
        let cache = RuleCache::new();
        composite_rule(0.0, 1.0, &factors, 40, &cache, &mut us, &mut ws).unwrap();
        let hpow = if end_weight { 0.0 } else { 0.5 };
        let p = &basis.panels[0];
        let mut exact = vec![0.0; n];
        let mut lag = vec![0.0; n];
        for (&u, &w) in us.iter().zip(&ws) {
            let t = a + h * u;
            // h·du, |t - x|^(-1/2) = h^(-1/2)|u - u₀|^(-1/2) (in the rule),
            // and h^(-1/2) of the end weight when present.
            let v = w
                * h.powf(hpow)
                * t
                * ((a + x) + h * u).powf(-0.5)
                * ((1.0 - a) - h * u).powf(-0.47);
            p.lagrange_ref(2.0 * u - 1.0, &mut lag);
            for (e, l) in exact.iter_mut().zip(&lag) {
                *e += v * l;
            }
        }
        let scale = exact.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        row.iter()
            .zip(&exact)
            .map(|(r, e)| (r - e).abs() / scale)
            .fold(0.0, f64::max)
    }

    /// Panels of length 1e-12 beside a breakpoint at 0.8 (where the split
    /// solver's meshes grade toward the stick radius c): each node `t` is
    /// known only to `ulp(0.8) ≈ 1e-16`, 1e-4 of the panel, yet the rows
    /// must be as accurate as on a panel of length 1, for the collocation
    /// point on either side and inside, at every distance (the split rule
    /// below [`MID_DISTANCE`], the prepared near rule up to [`ETA`], the far
    /// rule beyond). Evaluating `|t - x|` from `t` (the prepared rules
    /// before this test) was off by up to 5e-4 here, which moved the
    /// pressure at c by 1.5e-5 at ν = 0.25, c = 0.8.
    #[test]
    fn rows_on_tiny_panels_beside_a_breakpoint_are_accurate() {
        let (a, h) = (0.8, 1e-12);
        let mut worst = 0.0f64;
        for n in [3, 4, 7, 11, 15] {
            for end_weight in [false, true] {
                for d in [0.1, MID_DISTANCE, 0.3, 0.6, 0.99, 1.0, 1.5, 3.0] {
                    let before = tiny_row_error(n, a, h, -d * h, end_weight);
                    let inside = tiny_row_error(n, a, h, (d / 3.0).min(0.9) * h, end_weight);
                    worst = worst.max(before).max(inside);
                    if !end_weight {
                        worst = worst.max(tiny_row_error(n, a, h, (1.0 + d) * h, end_weight));
                    }
                }
            }
        }
        assert!(worst < 1e-13, "relative row error {worst:e}");
    }
}
