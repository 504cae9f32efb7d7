//! One discretisation of the closed Hertz problem for fixed `(γ, μ, c)`:
//! `p = (1-t)^{-α} φ_p` on `[0,1]` (the edge exponent factored out) and
//! the stick shear `q = q_b + B·t/√(c²-t²)` on `[0,c)` with `q_b` bounded;
//! `φ_p`, `q_b` are piecewise polynomials on meshes graded geometrically
//! toward `c` (both sides, with extra layers when `c` or `1-c` is small)
//! and toward `1`, degrees rising away from those points; `q = μp` on
//! `[c,1]`. E1 is collocated at the nodes of `p`, E2 at the nodes of `q_b`
//! and, as the extra equation for `B`, at `x → c⁻`. The free boundary is
//! where `B = (2/π) R(c)` vanishes; `B` is a smooth function of `μ` and `c`
//! because the singular part is represented exactly for every parameter.
//! Owns this discretisation; it must not do root finding or refinement
//! control (see `solve.rs`).
use nalgebra::{DMatrix, DVector};

use super::operators::{edge_exponent, kappa1, kappa2, kappa3, kappa4};
use lambdamat::hertz::HertzError;
use lambdamat::numeric::solve::{CheckedLu, DEFAULT_MAX_COND};
use lambdamat::numeric::{Assembler, Factor, Grading, Mesh, PanelBasis, Side};

/// Mesh and degree parameters of one discretisation level.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Resolution {
    /// Geometric layers toward `c` on each side.
    pub layers_c: usize,
    /// Geometric layers toward `1`.
    pub layers_1: usize,
    /// Grading ratio `σ` (panel sizes shrink by `σ` per layer).
    pub sigma: f64,
    /// Nodes on the panels touching a graded point.
    pub n_min: usize,
    /// Extra nodes per layer away from the graded point.
    pub slope: f64,
    /// Maximum nodes per panel.
    pub n_max: usize,
}

impl Resolution {
    /// Level `k` of the default refinement ladder (more layers and higher
    /// degrees as `k` grows).
    /// Measured (see tests/hertz_convergence.rs): the error of `μ(c)`
    /// falls by a factor of about 15 per level and is dominated by the
    /// grading toward `c`; the agreement of the two compliance formulas is
    /// dominated by the grading toward the edge. Both gain two layers per
    /// level (at most 20: the smallest panel stays above ~1e-12·c).
    pub fn level(k: usize) -> Resolution {
        let layers = (6 + 2 * k).min(20);
        Resolution {
            layers_c: layers,
            layers_1: layers,
            sigma: 0.25,
            n_min: 3,
            slope: 0.75,
            n_max: 7 + k,
        }
    }
}

/// The μ-independent part of a discretisation at fixed `(γ, c)`: bases,
/// collocation points and the blocks acting on the stick shear.
pub struct Frame {
    /// `γ`.
    pub gamma: f64,
    /// Stick radius.
    pub c: f64,
    /// Mesh of `p` on `[0,1]`.
    pub p_mesh: Mesh,
    /// Basis of the stick shear on `[0,c]`.
    pub q_basis: PanelBasis,
    /// Collocation points of E1 (nodes of `p`).
    pub xp: Vec<f64>,
    /// Collocation points of E2 (nodes of `q`).
    pub xq: Vec<f64>,
    node_counts: Vec<usize>,
    k2q: DMatrix<f64>,
    k4q: DMatrix<f64>,
}

impl Frame {
    /// Builds meshes, bases and the `q` blocks.
    pub fn new(gamma: f64, c: f64, res: &Resolution) -> Result<Frame, HertzError> {
        if !(c > 0.0 && c < 1.0) {
            return Err(HertzError::InvalidParameter(format!(
                "stick radius c = {c} not in (0,1)"
            )));
        }
        let gr = [
            Grading {
                at: c,
                side: Side::Both,
                layers: res.layers_c,
            },
            Grading {
                at: 1.0,
                side: Side::Left,
                layers: res.layers_1,
            },
        ];
        let p_mesh = Mesh::graded(0.0, 1.0, &gr, res.sigma)?;
        let node_counts: Vec<usize> = p_mesh
            .levels
            .iter()
            .map(|&l| {
                ((res.n_min as f64 + res.slope * l as f64).round() as usize).clamp(1, res.n_max)
            })
            .collect();
        // The stick mesh is the part of the p mesh left of c.
        let kc = p_mesh.breaks.iter().position(|&b| b == c).ok_or_else(|| {
            HertzError::InvalidParameter("c is not a breakpoint of the mesh".into())
        })?;
        let q_mesh = Mesh {
            breaks: p_mesh.breaks[..=kc].to_vec(),
            levels: p_mesh.levels[..kc].to_vec(),
        };
        let q_basis = PanelBasis::new(&q_mesh, &node_counts[..kc], vec![])?;
        let p_plain = PanelBasis::new(&p_mesh, &node_counts, vec![])?;
        let xp = p_plain.nodes();
        let xq = q_basis.nodes();
        let asm = Assembler::new(&q_basis)?;
        let k2q = asm.matrix(&kappa2(gamma), &xp)?;
        let k4q = asm.matrix(&kappa4(), &xq)?;
        Ok(Frame {
            gamma,
            c,
            p_mesh,
            q_basis,
            xp,
            xq,
            node_counts,
            k2q,
            k4q,
        })
    }

    /// The basis of `p` with the edge weight `(1-t)^{-α}`.
    pub fn p_basis(&self, alpha: f64) -> Result<PanelBasis, HertzError> {
        Ok(PanelBasis::new(
            &self.p_mesh,
            &self.node_counts,
            vec![Factor {
                at: 1.0,
                exponent: -alpha,
            }],
        )?)
    }

    /// Number of unknowns.
    pub fn size(&self) -> usize {
        self.xp.len() + self.xq.len()
    }

    /// Solves the closed problem for friction `mu`.
    pub fn solve(&self, mu: f64) -> Result<Discrete, HertzError> {
        if !(mu >= 0.0 && mu.is_finite()) {
            return Err(HertzError::InvalidParameter(format!(
                "friction μ = {mu} must be ≥ 0"
            )));
        }
        let (g, c) = (self.gamma, self.c);
        let alpha = edge_exponent(g, mu);
        let p_basis = self.p_basis(alpha)?;
        let asm = Assembler::new(&p_basis)?;
        let slip = (c, 1.0);
        let a11 =
            asm.matrix(&kappa1(), &self.xp)? + asm.matrix_on(&kappa2(g), &self.xp, slip)? * mu;
        let a21 =
            asm.matrix(&kappa3(g), &self.xq)? + asm.matrix_on(&kappa4(), &self.xq, slip)? * mu;
        // The shear may carry a singular part B·t/√(c²-t²) on the stick
        // zone; it is one extra unknown, with images in closed form:
        // κ2[s](x) = -γc + γx·½ln((x+c)/|x-c|), κ4[s](x) = -πx/2 (x < c).
        // The extra equation is E2 at x → c⁻, where κ4 of the bounded part
        // vanishes: c·R(c) - B·πc/2 = 0 with c·R(c) = κ3 p(c) + μκ4[p|slip](c).
        let np = self.xp.len();
        let nq = self.xq.len();
        let n = np + nq + 1;
        let mut r3 = vec![0.0; p_basis.dim()];
        asm.row_into(&kappa3(g), c, (0.0, 1.0), &mut r3)?;
        let mut r4 = vec![0.0; p_basis.dim()];
        asm.row_into(&kappa4(), c, slip, &mut r4)?;
        let mut a = DMatrix::zeros(n, n);
        a.view_mut((0, 0), (np, np)).copy_from(&a11);
        a.view_mut((0, np), (np, nq)).copy_from(&self.k2q);
        a.view_mut((np, 0), (nq, np)).copy_from(&a21);
        a.view_mut((np, np), (nq, nq)).copy_from(&self.k4q);
        for (i, &x) in self.xp.iter().enumerate() {
            a[(i, n - 1)] = -g * c + g * x * 0.5 * ((x + c) / (x - c).abs()).ln();
        }
        for (i, &x) in self.xq.iter().enumerate() {
            a[(np + i, n - 1)] = -std::f64::consts::FRAC_PI_2 * x;
        }
        for j in 0..np {
            a[(n - 1, j)] = r3[j] + mu * r4[j];
        }
        a[(n - 1, n - 1)] = -std::f64::consts::FRAC_PI_2 * c;
        let mut rhs = DVector::zeros(n);
        rhs.rows_mut(0, np).fill(1.0);
        let lu = CheckedLu::new(&a, DEFAULT_MAX_COND)?;
        let sol = lu.solve(&rhs)?;
        let p = sol.rows(0, np).into_owned();
        let q = sol.rows(np, nq).into_owned();
        let e2c: f64 = r3
            .iter()
            .zip(&r4)
            .zip(p.iter())
            .map(|((a, b), p)| (a + mu * b) * p)
            .sum();
        let singular = sol[n - 1];
        Ok(Discrete {
            mu,
            alpha,
            p_basis,
            p,
            q,
            residual_c: e2c / c,
            singular,
            cond: lu.cond(),
        })
    }
}

/// The discrete solution at fixed `(γ, μ, c)`.
pub struct Discrete {
    /// Friction coefficient.
    pub mu: f64,
    /// Edge exponent used in the weight.
    pub alpha: f64,
    /// Basis of `p` (weighted).
    pub p_basis: PanelBasis,
    /// Coefficients of `p`.
    pub p: DVector<f64>,
    /// Coefficients of the stick shear on `[0,c]`.
    pub q: DVector<f64>,
    /// `R(c)`: zero exactly when the shear is bounded at `c`.
    pub residual_c: f64,
    /// Coefficient `B` of the singular part `B·t/√(c²-t²)` of the stick
    /// shear (`B = (2/π) R(c)` in the continuous problem).
    pub singular: f64,
    /// Condition estimate of the block system.
    pub cond: f64,
}
