//! Piecewise-polynomial trial spaces with a factored weight: a function is
//! `f(t) = W(t) φ(t)` with `W(t) = Π_k |t - z_k|^{e_k}` (for example the edge
//! factor `(1-t)^(-α)`) and `φ` a polynomial of degree `n_k - 1` on panel `k`,
//! stored by its values at the panel's Gauss–Legendre nodes (discontinuous
//! across breakpoints). This file owns nodes, Lagrange/barycentric
//! evaluation and interpolation; it must not know about kernels or
//! operators.
use super::error::NumericError;
use super::gauss::gauss_legendre;
use super::mesh::Mesh;

/// A factor `|t - at|^exponent` of a weight or of a kernel singularity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Factor {
    /// The singular point.
    pub at: f64,
    /// The exponent (> -1 for integrability).
    pub exponent: f64,
}

impl Factor {
    /// Value `|t - at|^exponent`.
    pub fn eval(&self, t: f64) -> f64 {
        pow_fast((t - self.at).abs(), self.exponent)
    }
}

/// One panel of a [`PanelBasis`].
#[derive(Debug, Clone, PartialEq)]
pub struct Panel {
    /// Left end.
    pub a: f64,
    /// Right end.
    pub b: f64,
    /// Interpolation (and collocation) nodes, Gauss–Legendre, ascending.
    pub nodes: Vec<f64>,
    /// The same nodes mapped to the reference panel `[-1, 1]`.
    pub ref_nodes: Vec<f64>,
    /// Barycentric weights of `ref_nodes`.
    pub bary: Vec<f64>,
    /// Index of the first coefficient of this panel.
    pub offset: usize,
}

impl Panel {
    /// Values of all Lagrange basis polynomials of the panel at `t`
    /// (`out.len() == nodes.len()`). Works for any real `t` (first-kind
    /// barycentric formula in the reference coordinate `s ∈ [-1, 1]`, which
    /// is backward stable and safe from under/overflow on tiny panels).
    pub fn lagrange(&self, t: f64, out: &mut [f64]) {
        self.lagrange_ref((2.0 * t - self.a - self.b) / (self.b - self.a), out);
    }

    /// As [`Panel::lagrange`] at the reference coordinate `s` (`-1` and
    /// `1` are the panel's ends). A quadrature node's `s` is known more
    /// accurately than its `t` on a panel that is short beside `|t|`.
    pub fn lagrange_ref(&self, s: f64, out: &mut [f64]) {
        let mut ell = 1.0;
        for (j, &x) in self.ref_nodes.iter().enumerate() {
            let d = s - x;
            if d == 0.0 {
                out.iter_mut().for_each(|o| *o = 0.0);
                out[j] = 1.0;
                return;
            }
            ell *= d;
            out[j] = self.bary[j] / d;
        }
        out.iter_mut().for_each(|o| *o *= ell);
    }
}

/// A weighted, discontinuous piecewise-polynomial trial space.
#[derive(Debug, Clone, PartialEq)]
pub struct PanelBasis {
    /// Panels in increasing order.
    pub panels: Vec<Panel>,
    /// Factors of the weight `W`; their points must be breakpoints or
    /// outside the support.
    pub weight: Vec<Factor>,
    dim: usize,
}

impl PanelBasis {
    /// A basis on `mesh` with `nodes_per_panel[k]` Gauss–Legendre nodes on
    /// panel `k` and weight factors `weight`.
    pub fn new(
        mesh: &Mesh,
        nodes_per_panel: &[usize],
        weight: Vec<Factor>,
    ) -> Result<PanelBasis, NumericError> {
        if nodes_per_panel.len() != mesh.panels() {
            return Err(NumericError::Dimension(format!(
                "{} node counts for {} panels",
                nodes_per_panel.len(),
                mesh.panels()
            )));
        }
        let (lo, hi) = (mesh.breaks[0], mesh.breaks[mesh.panels()]);
        for f in &weight {
            let inside = f.at > lo && f.at < hi;
            if f.exponent <= -1.0 || (inside && !mesh.breaks.contains(&f.at)) {
                return Err(NumericError::InvalidArgument(format!(
                    "weight factor |t-{}|^{} must be integrable and sit on a breakpoint",
                    f.at, f.exponent
                )));
            }
        }
        let mut panels = Vec::with_capacity(mesh.panels());
        let mut offset = 0;
        for (k, &n) in nodes_per_panel.iter().enumerate() {
            let (a, b) = mesh.panel(k);
            let rule = gauss_legendre(n)?;
            let (nodes, _) = rule.mapped(a, b);
            let bary = barycentric_weights(&rule.nodes);
            panels.push(Panel {
                a,
                b,
                nodes,
                ref_nodes: rule.nodes,
                bary,
                offset,
            });
            offset += n;
        }
        Ok(PanelBasis {
            panels,
            weight,
            dim: offset,
        })
    }

    /// Number of coefficients.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// `(lo, hi)` of the support.
    pub fn support(&self) -> (f64, f64) {
        (self.panels[0].a, self.panels[self.panels.len() - 1].b)
    }

    /// All nodes in coefficient order (the natural collocation points).
    pub fn nodes(&self) -> Vec<f64> {
        self.panels
            .iter()
            .flat_map(|p| p.nodes.iter().copied())
            .collect()
    }

    /// The weight `W(t)`.
    pub fn weight_at(&self, t: f64) -> f64 {
        self.weight.iter().map(|f| f.eval(t)).product()
    }

    /// Index of the panel containing `t` (left-closed; the last panel is
    /// closed), or `None` outside the support.
    pub fn panel_of(&self, t: f64) -> Option<usize> {
        let (lo, hi) = self.support();
        if !(t >= lo && t <= hi) {
            return None;
        }
        let k = self.panels.partition_point(|p| p.b <= t);
        Some(k.min(self.panels.len() - 1))
    }

    /// Coefficients interpolating `f` (values of `f/W` at the nodes).
    pub fn interpolate(&self, f: impl Fn(f64) -> f64) -> Vec<f64> {
        self.nodes()
            .into_iter()
            .map(|t| f(t) / self.weight_at(t))
            .collect()
    }

    /// Row vector of the point evaluation `f ↦ f(t) = W(t) φ(t)` (zero
    /// outside the support; not finite where the weight is not).
    pub fn point_row(&self, t: f64) -> Vec<f64> {
        let mut row = vec![0.0; self.dim];
        if let Some(k) = self.panel_of(t) {
            let p = &self.panels[k];
            let mut l = vec![0.0; p.nodes.len()];
            p.lagrange(t, &mut l);
            let w = self.weight_at(t);
            for (i, v) in l.iter().enumerate() {
                row[p.offset + i] = v * w;
            }
        }
        row
    }

    /// `f(t) = W(t) φ(t)` for coefficients `coef` (zero outside the support).
    pub fn eval(&self, coef: &[f64], t: f64) -> f64 {
        let Some(k) = self.panel_of(t) else {
            return 0.0;
        };
        let p = &self.panels[k];
        let mut l = vec![0.0; p.nodes.len()];
        p.lagrange(t, &mut l);
        let phi: f64 = l
            .iter()
            .zip(&coef[p.offset..p.offset + l.len()])
            .map(|(a, b)| a * b)
            .sum();
        phi * self.weight_at(t)
    }
}

/// Barycentric weights `1 / Π_{k≠j} (x_j - x_k)` of nodes in `[-1, 1]`.
fn barycentric_weights(x: &[f64]) -> Vec<f64> {
    (0..x.len())
        .map(|j| {
            let mut p = 1.0;
            for (k, xk) in x.iter().enumerate() {
                if k != j {
                    p *= x[j] - xk;
                }
            }
            1.0 / p
        })
        .collect()
}

/// `d^e` with the square-root exponents of Abel kernels done by `sqrt`
/// (used by the weights here and by the product rules of
/// [`super::product`], which depend on this module, not the reverse).
#[inline]
pub fn pow_fast(d: f64, e: f64) -> f64 {
    if e == -0.5 {
        1.0 / d.sqrt()
    } else if e == 0.5 {
        d.sqrt()
    } else {
        d.powf(e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolation_reproduces_weighted_polynomials() {
        let mesh = Mesh::from_breaks(vec![0.0, 0.3, 0.7, 1.0]).unwrap();
        let w = vec![Factor {
            at: 1.0,
            exponent: -0.3,
        }];
        let basis = PanelBasis::new(&mesh, &[4, 5, 6], w).unwrap();
        let f = |t: f64| (1.0 - t).powf(-0.3) * (1.0 + t - 2.0 * t * t * t);
        let c = basis.interpolate(f);
        for i in 0..50 {
            let t = i as f64 / 50.0;
            assert!(
                (basis.eval(&c, t) - f(t)).abs() < 1e-13 * f(t).abs().max(1.0),
                "t={t}"
            );
        }
        assert_eq!(basis.dim(), 15);
        assert_eq!(basis.panel_of(0.3), Some(1));
        assert_eq!(basis.panel_of(1.0), Some(2));
        assert_eq!(basis.panel_of(1.5), None);
    }

    #[test]
    fn lagrange_extrapolates_exactly() {
        let mesh = Mesh::from_breaks(vec![0.0, 1.0]).unwrap();
        let basis = PanelBasis::new(&mesh, &[3], vec![]).unwrap();
        let c = basis.interpolate(|t| t * t);
        let mut l = [0.0; 3];
        basis.panels[0].lagrange(-0.5, &mut l);
        let v: f64 = l.iter().zip(&c).map(|(a, b)| a * b).sum();
        assert!((v - 0.25).abs() < 1e-14);
    }

    #[test]
    fn weight_off_breakpoint_is_rejected() {
        let mesh = Mesh::from_breaks(vec![0.0, 1.0]).unwrap();
        assert!(
            PanelBasis::new(
                &mesh,
                &[3],
                vec![Factor {
                    at: 0.5,
                    exponent: -0.5
                }]
            )
            .is_err()
        );
    }
}
