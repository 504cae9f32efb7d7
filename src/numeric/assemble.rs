//! Discretisation of [`Operator`]s on a [`PanelBasis`] by collocation: entry
//! `(i, j)` of the matrix is the operator applied to basis function `j`,
//! evaluated at point `x_i`. Every integral is a product integral computed
//! by [`composite_rule`]: the smooth factor `a(x,t)` times the Lagrange
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
use super::product::{ETA, RuleCache, composite_rule};

/// Extra quadrature nodes per panel beyond its interpolation nodes.
pub const DEFAULT_EXTRA_NODES: usize = 10;

struct FarRule {
    t: Vec<f64>,
    w: Vec<f64>,
    /// Lagrange values, row-major: `lag[q * n + j] = ℓ_j(t_q)`.
    lag: Vec<f64>,
}

/// Assembles operator matrices for one trial basis.
pub struct Assembler<'b> {
    basis: &'b PanelBasis,
    far: Vec<FarRule>,
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
        for p in &basis.panels {
            let n = p.nodes.len();
            let (mut t, mut w) = (Vec::new(), Vec::new());
            composite_rule(
                p.a,
                p.b,
                &basis.weight,
                n.div_ceil(2) + extra,
                cache,
                &mut t,
                &mut w,
            )?;
            let mut lag = vec![0.0; t.len() * n];
            for (q, &tq) in t.iter().enumerate() {
                p.lagrange(tq, &mut lag[q * n..(q + 1) * n]);
            }
            far.push(FarRule { t, w, lag });
        }
        Ok(Assembler {
            basis,
            far,
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
        let (l0, h0) = limits.at(x);
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
            if !clipped && !near {
                let f = &self.far[k];
                for (q, (&t, &w)) in f.t.iter().zip(&f.w).enumerate() {
                    let mut v = c * w * a(x, t);
                    match sing {
                        Singularity::AbelSqrt => v /= ((t - x).abs() * (t + x).abs()).sqrt(),
                        Singularity::Smooth => {}
                        s => v *= s.value(x, t),
                    }
                    for (o, lj) in out.iter_mut().zip(&f.lag[q * n..(q + 1) * n]) {
                        *o += v * lj;
                    }
                }
            } else {
                ts.clear();
                ws.clear();
                let m = n.div_ceil(2) + self.extra;
                match diagonal {
                    Some(kind) => diagonal_rule(
                        seg.0,
                        seg.1,
                        x,
                        kind,
                        &self.basis.weight,
                        m,
                        self.cache,
                        &mut ts,
                        &mut ws,
                    )?,
                    None => {
                        composite_rule(seg.0, seg.1, &factors, m, self.cache, &mut ts, &mut ws)?
                    }
                };
                lag.resize(n, 0.0);
                for (&t, &w) in ts.iter().zip(&ws) {
                    p.lagrange(t, &mut lag);
                    let v = c * w * a(x, t);
                    for (o, lj) in out.iter_mut().zip(&lag) {
                        *o += v * lj;
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
