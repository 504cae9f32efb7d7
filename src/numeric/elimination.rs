//! Solvers for a discretised 2×2 operator system
//! `K11 p + K12 q = g1, K21 p + K22 q = g2` whose blocks are collocation
//! matrices on one basis per unknown (rows at the nodes of the unknown's
//! basis): the coupled block solve, the ordered (non-commutative) block
//! elimination `(K11 - K12 K22⁻¹ K21) p = g1 - K12 K22⁻¹ g2`, and the
//! commutative single-equation *model* `(K22K11 - K12K21) p = K22 g1 - K12 g2`
//! with the commutator defect that shows how far it is from the system.
//! Products of operators are matrix products through one intermediate
//! basis (`values at nodes → coefficients`). Owns these linear-algebra
//! recipes only; it must not assemble operators.
use nalgebra::{DMatrix, DVector};

use super::basis::PanelBasis;
use super::error::NumericError;
use super::solve::{CheckedLu, block_matrix};

/// The blocks and right sides of a 2×2 system.
pub struct System2<'a> {
    /// `K11` (p → row 1).
    pub k11: &'a DMatrix<f64>,
    /// `K12` (q → row 1).
    pub k12: &'a DMatrix<f64>,
    /// `K21` (p → row 2).
    pub k21: &'a DMatrix<f64>,
    /// `K22` (q → row 2).
    pub k22: &'a DMatrix<f64>,
    /// Right side of row 1 (values at its collocation points).
    pub g1: &'a DVector<f64>,
    /// Right side of row 2.
    pub g2: &'a DVector<f64>,
}

/// A solved 2×2 system: coefficients of `p` and `q` and the estimated
/// condition number of the matrix that was factorised.
#[derive(Debug, Clone)]
pub struct Solution2 {
    /// Coefficients of `p`.
    pub p: DVector<f64>,
    /// Coefficients of `q` (empty for the commutative model).
    pub q: DVector<f64>,
    /// Condition estimate of the factorised matrix.
    pub cond: f64,
}

/// The coupled block solve.
pub fn solve_coupled(s: &System2, max_cond: f64) -> Result<Solution2, NumericError> {
    let a = block_matrix(&[vec![s.k11, s.k12], vec![s.k21, s.k22]])?;
    let mut g = DVector::zeros(s.g1.len() + s.g2.len());
    g.rows_mut(0, s.g1.len()).copy_from(s.g1);
    g.rows_mut(s.g1.len(), s.g2.len()).copy_from(s.g2);
    let lu = CheckedLu::new(&a, max_cond)?;
    let x = lu.solve(&g)?;
    let np = s.k11.ncols();
    Ok(Solution2 {
        p: x.rows(0, np).into_owned(),
        q: x.rows(np, x.len() - np).into_owned(),
        cond: lu.cond(),
    })
}

/// The coupled solve of an `n × n` block system `Σ_j K_ij u_j = g_i`
/// (blocks as in [`System2`]); returns the coefficient vector of each
/// unknown and the condition estimate.
pub fn solve_blocks(
    blocks: &[Vec<&DMatrix<f64>>],
    rhs: &[&DVector<f64>],
    max_cond: f64,
) -> Result<(Vec<DVector<f64>>, f64), NumericError> {
    if blocks.len() != rhs.len() {
        return Err(NumericError::Dimension(format!(
            "{} block rows, {} right sides",
            blocks.len(),
            rhs.len()
        )));
    }
    let a = block_matrix(blocks)?;
    let mut g = DVector::zeros(a.nrows());
    let mut r0 = 0;
    for r in rhs {
        if r0 + r.len() > g.len() {
            return Err(NumericError::Dimension(
                "right sides longer than the system".into(),
            ));
        }
        g.rows_mut(r0, r.len()).copy_from(r);
        r0 += r.len();
    }
    if r0 != g.len() {
        return Err(NumericError::Dimension(
            "right sides shorter than the system".into(),
        ));
    }
    let lu = CheckedLu::new(&a, max_cond)?;
    let x = lu.solve(&g)?;
    let mut out = Vec::new();
    let mut c0 = 0;
    for b in &blocks[0] {
        out.push(x.rows(c0, b.ncols()).into_owned());
        c0 += b.ncols();
    }
    Ok((out, lu.cond()))
}

/// The ordered elimination (exact for non-commuting operators):
/// `(K11 - K12 K22⁻¹ K21) p = g1 - K12 K22⁻¹ g2`, then
/// `q = K22⁻¹ (g2 - K21 p)`.
pub fn solve_ordered(s: &System2, max_cond: f64) -> Result<Solution2, NumericError> {
    let l22 = CheckedLu::new(s.k22, max_cond)?;
    let y = l22.solve_matrix(s.k21)?;
    let schur = s.k11 - s.k12 * y;
    let rhs = s.g1 - s.k12 * l22.solve(s.g2)?;
    let ls = CheckedLu::new(&schur, max_cond)?;
    let p = ls.solve(&rhs)?;
    let q = l22.solve(&(s.g2 - s.k21 * &p))?;
    Ok(Solution2 {
        p,
        q,
        cond: ls.cond().max(l22.cond()),
    })
}

/// The matrix of the operator product `A·B` where `B` maps into values at
/// the nodes of `mid` and `A` acts on coefficients of `mid`.
pub fn product(
    a: &DMatrix<f64>,
    mid: &PanelBasis,
    b: &DMatrix<f64>,
) -> Result<DMatrix<f64>, NumericError> {
    let to_coef = values_to_coefficients(mid);
    if a.ncols() != to_coef.len() || b.nrows() != to_coef.len() {
        return Err(NumericError::Dimension(
            "operator product through a basis of another size".into(),
        ));
    }
    let mut scaled = b.clone();
    for (i, s) in to_coef.iter().enumerate() {
        scaled.row_mut(i).scale_mut(*s);
    }
    Ok(a * scaled)
}

/// Applies `A` to a vector of values at the nodes of `mid`.
pub fn apply_to_values(
    a: &DMatrix<f64>,
    mid: &PanelBasis,
    v: &DVector<f64>,
) -> Result<DVector<f64>, NumericError> {
    let to_coef = values_to_coefficients(mid);
    if a.ncols() != v.len() || v.len() != to_coef.len() {
        return Err(NumericError::Dimension("vector of another size".into()));
    }
    Ok(a * v.component_mul(&DVector::from_vec(to_coef)))
}

fn values_to_coefficients(b: &PanelBasis) -> Vec<f64> {
    b.nodes().iter().map(|&t| 1.0 / b.weight_at(t)).collect()
}

/// The commutative single-equation model of the seed paper,
/// `(K22K11 - K12K21) p = K22 g1 - K12 g2`, with all products through the
/// one basis `mid` (all four blocks square on it). A *model*: compare it
/// with [`solve_ordered`] and look at [`commutator_defect`].
pub fn solve_commutative(
    s: &System2,
    mid: &PanelBasis,
    max_cond: f64,
) -> Result<Solution2, NumericError> {
    let lhs = product(s.k22, mid, s.k11)? - product(s.k12, mid, s.k21)?;
    let rhs = apply_to_values(s.k22, mid, s.g1)? - apply_to_values(s.k12, mid, s.g2)?;
    let lu = CheckedLu::new(&lhs, max_cond)?;
    let p = lu.solve(&rhs)?;
    Ok(Solution2 {
        p,
        q: DVector::zeros(0),
        cond: lu.cond(),
    })
}

/// The measured defect `‖KaKb f - KbKa f‖ / ‖KaKb f‖` (max norms over the
/// nodes of `mid`) for coefficients `f` on `mid`.
pub fn commutator_defect(
    ka: &DMatrix<f64>,
    kb: &DMatrix<f64>,
    mid: &PanelBasis,
    f: &DVector<f64>,
) -> Result<f64, NumericError> {
    commutator_defect_on(ka, kb, ka, kb, mid, f)
}

/// The same defect for coefficients `f` on another basis of the same
/// nodes: `ka_f`, `kb_f` act on that basis, `ka`, `kb` on `mid`, and both
/// products are formed through `mid`.
pub fn commutator_defect_on(
    ka: &DMatrix<f64>,
    kb: &DMatrix<f64>,
    ka_f: &DMatrix<f64>,
    kb_f: &DMatrix<f64>,
    mid: &PanelBasis,
    f: &DVector<f64>,
) -> Result<f64, NumericError> {
    let ab = product(ka, mid, kb_f)? * f;
    let ba = product(kb, mid, ka_f)? * f;
    let n = ab.amax();
    if n == 0.0 || !n.is_finite() {
        return Err(NumericError::InvalidArgument(
            "KaKb f vanishes or is not finite; defect undefined".into(),
        ));
    }
    Ok((ab - ba).amax() / n)
}
