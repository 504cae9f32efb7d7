//! The seed paper's literal algorithm, for comparison only (the `hertz
//! table` column "seed"): `p` on `[0,1]` is collocated with the paper's
//! (2.4) (E1 with `q = μp` everywhere) at the nodes in `[c,1]` and with its
//! single equation (3.3), `(κ4κ1 - κ2κ3) p = κ4[1]`, at the nodes in
//! `[0,c)`; operator products go through one intermediate basis. Both
//! equations are approximations (hertz.md, "Where the seed's reduction is
//! an approximation"), so this module reports what they give level by
//! level and whether that sequence settles; it never feeds the exact
//! solver. Owns this comparison and its own small discretisation over
//! [`crate::numeric`] (a mesh graded geometrically toward `c` on both sides
//! and toward the edge `1`, degrees rising away from them, `p` with the
//! edge weight `(1-t)^(-α)`); it shares no code with the language's
//! solver or with the hand-written oracle of the tests.
use std::f64::consts::FRAC_PI_2;

use nalgebra::{DMatrix, DVector};
use serde::Serialize;

use super::error::HertzError;
use crate::numeric::elimination::product;
use crate::numeric::solve::{CheckedLu, DEFAULT_MAX_COND};
use crate::numeric::{Assembler, Factor, Grading, Mesh, Operator, PanelBasis, Side};

/// `γ = (1-2ν)/(2-2ν)`.
pub fn gamma_of_nu(nu: f64) -> f64 {
    (1.0 - 2.0 * nu) / (2.0 - 2.0 * nu)
}

/// The edge exponent `α = arccot(γμ)/π ∈ (0, 1/2]`.
pub fn edge_exponent(gamma: f64, mu: f64) -> f64 {
    let gm = gamma * mu;
    if gm <= 0.0 {
        0.5
    } else {
        (1.0 / gm).atan() / std::f64::consts::PI
    }
}

/// `κ1 f(x) = ∫_x^1 t f(t)/√(t²-x²) dt`.
fn kappa1() -> Operator {
    Operator::abel_upper(1.0, |_x, t| t)
}

/// `κ2 f(x) = -γ ∫_0^1 f(t) dt + γ ∫_0^x x f(t)/√(x²-t²) dt`.
fn kappa2(gamma: f64) -> Operator {
    Operator::smooth(0.0, 1.0, |_, _| 1.0).scaled(-gamma)
        + Operator::abel_lower(0.0, |x, _t| x).scaled(gamma)
}

/// `κ3 f(x) = γ ∫_0^x t f(t)/√(x²-t²) dt`.
fn kappa3(gamma: f64) -> Operator {
    Operator::abel_lower(0.0, |_x, t| t).scaled(gamma)
}

/// `κ4 f(x) = -∫_x^1 x f(t)/√(t²-x²) dt`.
fn kappa4() -> Operator {
    Operator::abel_upper(1.0, |x, _t| x).scaled(-1.0)
}

/// Mesh and degree parameters of level `k` of the seed's ladder.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeedResolution {
    /// Geometric layers toward `c` (each side) and toward `1`.
    pub layers: usize,
    /// Grading ratio `σ` (panel sizes shrink by `σ` per layer).
    pub sigma: f64,
    /// Nodes on the panels touching a graded point.
    pub n_min: usize,
    /// Extra nodes per layer away from the graded point.
    pub slope: f64,
    /// Maximum nodes per panel.
    pub n_max: usize,
}

impl SeedResolution {
    /// Level `k`: two more layers (at most 20) and one more node allowed
    /// per level.
    pub fn level(k: usize) -> SeedResolution {
        SeedResolution {
            layers: (6 + 2 * k).min(20),
            sigma: 0.25,
            n_min: 3,
            slope: 0.75,
            n_max: 7 + k,
        }
    }
}

/// One level's mesh of `[0, 1]` and its node counts per panel.
struct SeedMesh {
    mesh: Mesh,
    nodes: Vec<usize>,
}

impl SeedMesh {
    fn new(c: f64, res: &SeedResolution) -> Result<SeedMesh, HertzError> {
        let gr = [
            Grading {
                at: c,
                side: Side::Both,
                layers: res.layers,
            },
            Grading {
                at: 1.0,
                side: Side::Left,
                layers: res.layers,
            },
        ];
        let mesh = Mesh::graded(0.0, 1.0, &gr, res.sigma)?;
        let nodes = mesh
            .levels
            .iter()
            .map(|&l| {
                ((res.n_min as f64 + res.slope * l as f64).round() as usize).clamp(1, res.n_max)
            })
            .collect();
        Ok(SeedMesh { mesh, nodes })
    }

    /// The basis of `p` with the edge weight `(1-t)^(-α)`.
    fn basis(&self, alpha: f64) -> Result<PanelBasis, HertzError> {
        Ok(PanelBasis::new(
            &self.mesh,
            &self.nodes,
            vec![Factor {
                at: 1.0,
                exponent: -alpha,
            }],
        )?)
    }

    /// The collocation points (the nodes of the unweighted basis).
    fn points(&self) -> Result<Vec<f64>, HertzError> {
        Ok(PanelBasis::new(&self.mesh, &self.nodes, vec![])?.nodes())
    }
}

/// One discretisation level of the literal algorithm.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SeedLevel {
    /// Level of [`SeedResolution::level`].
    pub level: usize,
    /// Number of unknowns.
    pub unknowns: usize,
    /// `P*` from the computed `p`, or `None` if the system was refused.
    pub compliance: Option<f64>,
    /// Why the system was refused (singular, ill-conditioned, ...).
    pub refused: Option<String>,
}

/// The literal algorithm on a ladder of levels.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SeedResult {
    /// Poisson's ratio.
    pub nu: f64,
    /// Friction coefficient used.
    pub mu: f64,
    /// Stick radius used.
    pub c: f64,
    /// Every level tried.
    pub levels: Vec<SeedLevel>,
    /// Last computed `P*`.
    pub compliance: Option<f64>,
    /// `|P*_k - P*_{k-1}|` of the last two computed levels.
    pub last_change: Option<f64>,
    /// Whether the last change is at most the requested tolerance.
    pub converged: bool,
}

/// Runs the literal algorithm at `(ν, μ, c)` on levels `0..=max_level`
/// and reports the compliance per level.
pub fn seed_literal(
    nu: f64,
    mu: f64,
    c: f64,
    max_level: usize,
    tol: f64,
) -> Result<SeedResult, HertzError> {
    let valid = (0.0..0.5).contains(&nu) && mu > 0.0 && mu.is_finite() && c > 0.0 && c < 1.0;
    if !valid {
        return Err(HertzError::InvalidParameter(format!(
            "need 0 ≤ ν < 1/2, μ > 0, 0 < c < 1; got ν={nu}, μ={mu}, c={c}"
        )));
    }
    let gamma = gamma_of_nu(nu);
    let alpha = edge_exponent(gamma, mu);
    let mut levels = Vec::new();
    for k in 0..=max_level {
        let m = SeedMesh::new(c, &SeedResolution::level(k))?;
        let basis = m.basis(alpha)?;
        let mid = m.basis(0.0)?;
        let x = m.points()?;
        let n = basis.dim();
        match one_level(gamma, mu, c, &x, &basis, &mid) {
            Ok(pstar) => levels.push(SeedLevel {
                level: k,
                unknowns: n,
                compliance: Some(pstar),
                refused: None,
            }),
            Err(e) => levels.push(SeedLevel {
                level: k,
                unknowns: n,
                compliance: None,
                refused: Some(e.to_string()),
            }),
        }
    }
    let computed: Vec<f64> = levels.iter().filter_map(|l| l.compliance).collect();
    let last_change = match computed.len() {
        0 | 1 => None,
        m => Some((computed[m - 1] - computed[m - 2]).abs()),
    };
    Ok(SeedResult {
        nu,
        mu,
        c,
        compliance: computed.last().copied(),
        converged: last_change.is_some_and(|d| d <= tol),
        last_change,
        levels,
    })
}

fn one_level(
    gamma: f64,
    mu: f64,
    c: f64,
    x: &[f64],
    basis: &PanelBasis,
    mid: &PanelBasis,
) -> Result<f64, HertzError> {
    let asm = Assembler::new(basis)?;
    let mid_asm = Assembler::new(mid)?;
    let (stick, slip): (Vec<usize>, Vec<usize>) = (0..x.len()).partition(|&i| x[i] < c);
    let xs: Vec<f64> = stick.iter().map(|&i| x[i]).collect();
    let xl: Vec<f64> = slip.iter().map(|&i| x[i]).collect();
    // (2.4) on [c,1]: (κ1 + μκ2) p = 1.
    let a_slip = asm.matrix(&kappa1(), &xl)? + asm.matrix(&kappa2(gamma), &xl)? * mu;
    // (3.3) on [0,c): (κ4κ1 - κ2κ3) p = κ4[1].
    let k1 = asm.matrix(&kappa1(), x)?;
    let k3 = asm.matrix(&kappa3(gamma), x)?;
    let k4 = mid_asm.matrix(&kappa4(), &xs)?;
    let k2 = mid_asm.matrix(&kappa2(gamma), &xs)?;
    let a_stick = product(&k4, mid, &k1)? - product(&k2, mid, &k3)?;
    let n = x.len();
    let mut a = DMatrix::zeros(n, basis.dim());
    let mut rhs = DVector::zeros(n);
    for (r, &i) in stick.iter().enumerate() {
        a.set_row(i, &a_stick.row(r));
        let xi = x[i];
        rhs[i] = xi * xi.ln() - xi * (1.0 + (1.0 - xi * xi).sqrt()).ln();
    }
    for (r, &i) in slip.iter().enumerate() {
        a.set_row(i, &a_slip.row(r));
        rhs[i] = 1.0;
    }
    let p = CheckedLu::new(&a, DEFAULT_MAX_COND)?.solve(&rhs)?;
    Ok(FRAC_PI_2 * DVector::from_vec(asm.functional(|t| t, 0.0, 1.0)?).dot(&p))
}
