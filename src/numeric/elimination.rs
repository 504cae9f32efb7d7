//! Linear-algebra building blocks for discretised operator systems whose
//! blocks are collocation matrices on one basis per unknown (rows at the
//! nodes of the unknown's basis): the coupled block solve of an `n × n`
//! system, products of operators as matrix products through one
//! intermediate basis (`values at nodes → coefficients`), and the
//! commutator defect `‖KaKb f - KbKa f‖/‖KaKb f‖`. The methods that use
//! them (coupled, ordered, commutative) are `plan::methods`'s. Owns these
//! recipes only; it must not assemble operators or choose a method.
use nalgebra::{DMatrix, DVector};

use super::basis::PanelBasis;
use super::error::NumericError;
use super::solve::{CheckedLu, block_matrix};

/// The coupled solve of an `n × n` block system `Σ_j K_ij u_j = g_i`
/// (block `(i, j)` maps unknown `j` to the collocation rows of equation
/// `i`); returns the coefficient vector of each
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
