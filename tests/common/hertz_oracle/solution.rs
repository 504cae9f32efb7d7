//! The result of a Hertz solve and everything computed from it: `p`, `q`,
//! `μp` and the slip `u` at any point, the stick and slip checks, and the
//! serialisable summary. Owns evaluation of a finished discretisation; it
//! must not iterate on `μ` or `c`.
use std::f64::consts::FRAC_2_PI;

use nalgebra::DVector;
use serde::Serialize;

use super::operators::{kappa1, kappa2, kappa3, kappa4};
use lambdamat::hertz::HertzError;
pub use lambdamat::hertz::front::{Sample, frictionless_pressure, profile_points};
use lambdamat::numeric::{Assembler, Mesh, Operator, PanelBasis};

/// The discrete fields of a solution (not serialised).
#[derive(Debug, Clone)]
pub struct Fields {
    /// Basis of `p` (weighted by `(1-t)^{-α}`).
    pub p_basis: PanelBasis,
    /// Coefficients of `p`.
    pub p: DVector<f64>,
    /// Basis of the stick shear on `[0,c]` (`None` without a stick zone).
    pub q_basis: Option<PanelBasis>,
    /// Coefficients of the stick shear.
    pub q: DVector<f64>,
    /// Coefficient `B` of the singular part `B·t/√(c²-t²)` of the stick
    /// shear (zero up to the root-finding tolerance in a solution).
    pub q_singular: f64,
    /// E2's residual `r = -(κ3 p + κ4 q)` on the slip zone, interpolated.
    pub r_basis: Option<PanelBasis>,
    /// Coefficients of `r`.
    pub r: DVector<f64>,
}

/// A solved Hertz problem with its checks and error estimate.
#[derive(Debug, Clone, Serialize)]
pub struct HertzSolution {
    /// Poisson's ratio.
    pub nu: f64,
    /// `γ = (1-2ν)/(2-2ν)`.
    pub gamma: f64,
    /// Friction coefficient.
    pub mu: f64,
    /// Stick radius (0: no stick zone; 1: full stick).
    pub c: f64,
    /// Edge exponent `α = arccot(γμ)/π` factored out of `p`.
    pub alpha: f64,
    /// `P* = (π/2) ∫ x p dx`.
    pub compliance: f64,
    /// `P* = 1 + γ ∫ q (1 - √(1-t²)) dt`.
    pub compliance_via_shear: f64,
    /// `compliance - compliance_via_shear`.
    pub compliance_difference: f64,
    /// Largest change of `μ` (or `c`), `P*` and `P*` via shear between the
    /// last two discretisations: a conservative estimate of the error.
    pub error_estimate: f64,
    /// Whether `error_estimate ≤ tol` was reached.
    pub converged: bool,
    /// The requested tolerance.
    pub tol: f64,
    /// `q < μp` on the sampled stick zone.
    pub stick_ok: bool,
    /// `u < 0` on the sampled slip zone.
    pub slip_ok: bool,
    /// `R(c)` of the final discretisation (bounded-shear condition).
    pub residual_c: f64,
    /// `q(c⁻) - μ p(c)`: continuity of the shear at the stick/slip point.
    pub shear_jump_at_c: f64,
    /// Number of unknowns of the final discretisation.
    pub unknowns: usize,
    /// Number of discretisation levels used.
    pub levels: usize,
    /// Condition estimate of the final block system.
    pub condition: f64,
    /// The discrete fields.
    #[serde(skip)]
    pub fields: Fields,
}

impl Fields {
    /// Builds the fields and interpolates E2's residual on the slip zone.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        gamma: f64,
        mu: f64,
        c: f64,
        p_basis: PanelBasis,
        p: DVector<f64>,
        q_basis: Option<PanelBasis>,
        q: DVector<f64>,
        q_singular: f64,
    ) -> Result<Fields, HertzError> {
        let mut f = Fields {
            p_basis,
            p,
            q_basis,
            q,
            q_singular,
            r_basis: None,
            r: DVector::zeros(0),
        };
        if c > 0.0 && c < 1.0 && mu > 0.0 {
            // Slip panels of the p mesh, unweighted.
            let panels: Vec<_> = f.p_basis.panels.iter().filter(|p| p.a >= c).collect();
            let mut breaks = vec![c];
            breaks.extend(panels.iter().map(|p| p.b));
            let counts: Vec<usize> = panels.iter().map(|p| p.nodes.len()).collect();
            let rb = PanelBasis::new(&Mesh::from_breaks(breaks)?, &counts, vec![])?;
            let xs = rb.nodes();
            let asm = Assembler::new(&f.p_basis)?;
            let a3 = asm.matrix(&kappa3(gamma), &xs)?;
            let a4 = asm.matrix_on(&kappa4(), &xs, (c, 1.0))?;
            // κ4 of the stick shear vanishes for x > c (support [0,c]).
            f.r = -(a3 * &f.p + a4 * &f.p * mu);
            f.r_basis = Some(rb);
        }
        Ok(f)
    }
}

impl HertzSolution {
    /// Normal stress `p(x)` (`x ∈ [0,1)`).
    pub fn p(&self, x: f64) -> f64 {
        self.fields.p_basis.eval(self.fields.p.as_slice(), x)
    }

    /// Shear stress `q(x)`: the stick solution on `[0,c)` (including its
    /// singular part, zero up to the root tolerance), `μp` on `[c,1)`.
    pub fn q(&self, x: f64) -> f64 {
        match &self.fields.q_basis {
            Some(b) if x < self.c => {
                let s = x / ((self.c - x) * (self.c + x)).sqrt();
                b.eval(self.fields.q.as_slice(), x) + self.fields.q_singular * s
            }
            _ if x >= self.c => self.mu * self.p(x),
            _ => 0.0,
        }
    }

    /// Slip `u(x) = (2/(πx)) ∫_c^x s r(s)/√(x²-s²) ds` on `(c,1]` with `r`
    /// the residual of E2; zero in the stick zone.
    pub fn u(&self, x: f64) -> Result<f64, HertzError> {
        let Some(rb) = &self.fields.r_basis else {
            return Ok(0.0);
        };
        if x <= self.c {
            return Ok(0.0);
        }
        let op = Operator::abel_lower(self.c, |_x, s| s);
        let asm = Assembler::new(rb)?;
        let mut row = vec![0.0; rb.dim()];
        asm.row_into(&op, x.min(1.0), rb.support(), &mut row)?;
        let v: f64 = row
            .iter()
            .zip(self.fields.r.iter())
            .map(|(a, b)| a * b)
            .sum();
        Ok(FRAC_2_PI / x * v)
    }

    /// A posteriori check: the largest absolute residuals of E1 on the
    /// points `xs ∩ (0,1)` and of E2 on `xs ∩ (0,c)`, evaluated with the
    /// product rules at points that are not collocation nodes.
    pub fn residuals(&self, xs: &[f64]) -> Result<(f64, f64), HertzError> {
        let (g, mu, c) = (self.gamma, self.mu, self.c);
        let f = &self.fields;
        let pa = Assembler::new(&f.p_basis)?;
        let qa = match &f.q_basis {
            Some(b) => Some((b, Assembler::new(b)?)),
            None => None,
        };
        let dot =
            |r: &[f64], v: &DVector<f64>| r.iter().zip(v.iter()).map(|(a, b)| a * b).sum::<f64>();
        let row = |asm: &Assembler,
                   op: &Operator,
                   x: f64,
                   w: (f64, f64)|
         -> Result<Vec<f64>, HertzError> {
            let mut r = vec![0.0; asm.basis().dim()];
            asm.row_into(op, x, w, &mut r)?;
            Ok(r)
        };
        let (k1, k2, k3, k4) = (kappa1(), kappa2(g), kappa3(g), kappa4());
        let slip = (c.max(0.0), 1.0);
        let (mut e1, mut e2) = (0.0f64, 0.0f64);
        for &x in xs.iter().filter(|x| **x > 0.0 && **x < 1.0) {
            let mut r = dot(&row(&pa, &k1, x, (0.0, 1.0))?, &f.p) - 1.0;
            if mu > 0.0 && c < 1.0 {
                r += mu * dot(&row(&pa, &k2, x, slip)?, &f.p);
            }
            if let Some((b, qasm)) = &qa {
                r += dot(&row(qasm, &k2, x, b.support())?, &f.q);
                r += f.q_singular * (-g * c + g * x * 0.5 * ((x + c) / (x - c).abs()).ln());
            }
            e1 = e1.max(r.abs());
            if x < c
                && let Some((b, qasm)) = &qa
            {
                let mut r = dot(&row(&pa, &k3, x, (0.0, 1.0))?, &f.p);
                r += mu * dot(&row(&pa, &k4, x, slip)?, &f.p);
                r += dot(&row(qasm, &k4, x, b.support())?, &f.q);
                r -= f.q_singular * std::f64::consts::FRAC_PI_2 * x;
                e2 = e2.max(r.abs());
            }
        }
        Ok((e1, e2))
    }

    /// `p, q, μp, u` at the points `xs` (each in `[0, 1)`).
    pub fn sample(&self, xs: &[f64]) -> Result<Vec<Sample>, HertzError> {
        let mut out = Vec::with_capacity(xs.len());
        let u_asm = match &self.fields.r_basis {
            Some(rb) => Some((rb, Assembler::new(rb)?)),
            None => None,
        };
        let op = Operator::abel_lower(self.c, |_x, s| s);
        for &x in xs {
            if !(0.0..1.0).contains(&x) {
                return Err(HertzError::InvalidParameter(format!(
                    "sample point {x} not in [0,1)"
                )));
            }
            let p = self.p(x);
            let u = match &u_asm {
                Some((rb, asm)) if x > self.c => {
                    let mut row = vec![0.0; rb.dim()];
                    asm.row_into(&op, x, rb.support(), &mut row)?;
                    FRAC_2_PI / x
                        * row
                            .iter()
                            .zip(self.fields.r.iter())
                            .map(|(a, b)| a * b)
                            .sum::<f64>()
                }
                _ => 0.0,
            };
            // The oracle has no pointwise estimate of its own.
            let none = f64::INFINITY;
            out.push(Sample {
                x,
                p,
                p_err: none,
                q: self.q(x),
                q_err: none,
                mu_p: self.mu * p,
                mu_p_err: none,
                u,
                u_err: none,
            });
        }
        Ok(out)
    }

    /// [`HertzSolution::sample`] on `n` equal steps of `[0,1)` plus points
    /// clustered toward `c` from both sides and toward 1, sorted.
    pub fn profile(&self, n: usize) -> Result<Vec<Sample>, HertzError> {
        self.sample(&profile_points(self.c, n))
    }
}
