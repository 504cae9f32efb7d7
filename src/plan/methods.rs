//! The three ways to solve one discretised language system
//! `Σ_j A_ij(K) u_j = g_i`: `coupled` (one block system), `ordered` (exact
//! block elimination toward the target unknown, with block pivoting:
//! `(K11 - K12 K22⁻¹ K21) p = g1 - K12 K22⁻¹ g2` for two unknowns) and
//! `commutative` (the seed's single equation
//! `det(A) u_i = Σ_j adj(A)_ij g_j` with `det` and `adj` computed exactly
//! by the algebra over Q[symbols] and then evaluated with operator
//! matrices: a *model*, exact only if the operators commute). Also the
//! pairs of symbols a method commuted and their measured defects. This file
//! owns these recipes; assembly is `discrete.rs`'s, refinement `refine.rs`'s.
use std::collections::BTreeSet;
use std::fmt;
use std::str::FromStr;

use nalgebra::{DMatrix, DVector};

use crate::algebra::matrix::Matrix;
use crate::algebra::polyring::PolyRing;
use crate::numeric::NumericError;
use crate::numeric::elimination::{apply_to_values, commutator_defect_on, product, solve_blocks};
use crate::numeric::solve::CheckedLu;
use crate::system::{MPoly, NcPoly};

use super::compiled::CompiledSystem;
use super::discrete::{BasisId, Discretisation};
use super::error::PlanError;

/// A solution method.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// The block system, solved at once.
    Coupled,
    /// Exact (non-commutative) elimination; the default.
    Ordered,
    /// The commutative single-equation model.
    Commutative,
}

impl Method {
    /// Its name on the command line and in reports.
    pub fn name(self) -> &'static str {
        match self {
            Method::Coupled => "coupled",
            Method::Ordered => "ordered",
            Method::Commutative => "commutative",
        }
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Method {
    type Err = String;
    fn from_str(s: &str) -> Result<Method, String> {
        match s {
            "coupled" => Ok(Method::Coupled),
            "ordered" => Ok(Method::Ordered),
            "commutative" => Ok(Method::Commutative),
            other => Err(format!(
                "unknown method {other} (coupled, ordered, commutative)"
            )),
        }
    }
}

/// Coefficients of the unknowns on one level (`None` where the method does
/// not compute an unknown) and the largest condition estimate met.
pub struct LevelSolution {
    /// Coefficients per unknown.
    pub coefs: Vec<Option<DVector<f64>>>,
    /// Largest estimated condition number of a factorised matrix.
    pub cond: f64,
}

/// Solves the system on `d` by `method`; `target` is the unknown the
/// ordered and commutative eliminations solve for.
pub fn solve_level(
    d: &mut Discretisation,
    prog: &CompiledSystem,
    method: Method,
    target: usize,
    max_cond: f64,
) -> Result<LevelSolution, PlanError> {
    let n = prog.unknowns.len();
    let mut g = Vec::with_capacity(n);
    for (i, eq) in prog.equations.iter().enumerate() {
        g.push(
            d.values(
                &eq.rhs,
                &format!("right side of equation {} = {}", i + 1, eq.rhs_text),
            )
            .map_err(|e| match e {
                PlanError::Invalid(reason) => PlanError::RightSide {
                    equation: i,
                    reason,
                },
                other => other,
            })?,
        );
    }
    if method == Method::Commutative {
        return commutative(d, prog, &g, target, max_cond);
    }
    let mut blocks = Vec::with_capacity(n);
    for eq in &prog.equations {
        let row = (0..n)
            .map(|j| d.poly(&eq.lhs[j], BasisId::Unknown(j)))
            .collect::<Result<Vec<_>, _>>()?;
        blocks.push(row);
    }
    match method {
        Method::Coupled => {
            let refs: Vec<Vec<&DMatrix<f64>>> = blocks.iter().map(|r| r.iter().collect()).collect();
            let grefs: Vec<&DVector<f64>> = g.iter().collect();
            let (u, cond) = solve_blocks(&refs, &grefs, max_cond)
                .map_err(PlanError::numeric("coupled block system"))?;
            Ok(LevelSolution {
                coefs: u.into_iter().map(Some).collect(),
                cond,
            })
        }
        _ => ordered(blocks, g, target, &prog.unknowns, max_cond),
    }
}

/// Block Gaussian elimination: the unknowns other than `target` are
/// eliminated in order (pivot block: the unknown's own equation if its
/// block is well conditioned, else the first remaining equation whose
/// block is), then `target` is solved and the rest back-substituted.
fn ordered(
    mut b: Vec<Vec<DMatrix<f64>>>,
    mut g: Vec<DVector<f64>>,
    target: usize,
    names: &[String],
    max_cond: f64,
) -> Result<LevelSolution, PlanError> {
    let n = b.len();
    let order: Vec<usize> = (0..n).filter(|&j| j != target).chain([target]).collect();
    let mut left: Vec<usize> = (0..n).collect();
    let mut pivots: Vec<(usize, usize, CheckedLu)> = Vec::new();
    let mut cond: f64 = 0.0;
    for (step, &col) in order.iter().enumerate() {
        let mut cands = left.clone();
        cands.sort_by_key(|&r| r != col);
        let mut chosen = None;
        let mut last: Option<NumericError> = None;
        for r in cands {
            match CheckedLu::new(&b[r][col], max_cond) {
                Ok(lu) => {
                    chosen = Some((r, lu));
                    break;
                }
                Err(e) => last = Some(e),
            }
        }
        let Some((r, lu)) = chosen else {
            return Err(PlanError::Numeric {
                context: format!(
                    "ordered elimination: no remaining equation can be solved for {}",
                    names[col]
                ),
                source: last.unwrap_or(NumericError::Singular(0)),
            });
        };
        cond = cond.max(lu.cond());
        left.retain(|&x| x != r);
        let later = &order[step + 1..];
        let ctx = || PlanError::numeric(format!("ordered elimination of {}", names[col]));
        let y: Vec<DMatrix<f64>> = later
            .iter()
            .map(|&c| lu.solve_matrix(&b[r][c]))
            .collect::<Result<_, _>>()
            .map_err(ctx())?;
        let yg = lu.solve(&g[r]).map_err(ctx())?;
        for &i in &left {
            let bic = b[i][col].clone();
            for (&c, yc) in later.iter().zip(&y) {
                b[i][c] -= &bic * yc;
            }
            g[i] -= &bic * &yg;
        }
        pivots.push((col, r, lu));
    }
    let mut u: Vec<Option<DVector<f64>>> = vec![None; n];
    for (step, (col, r, lu)) in pivots.iter().enumerate().rev() {
        let mut rhs = g[*r].clone();
        for &c in &order[step + 1..] {
            if let Some(uc) = &u[c] {
                rhs -= &b[*r][c] * uc;
            }
        }
        u[*col] = Some(
            lu.solve(&rhs)
                .map_err(PlanError::numeric("ordered back substitution"))?,
        );
    }
    Ok(LevelSolution { coefs: u, cond })
}

/// The λ-matrix over Q[symbols], its determinant and adjugate.
fn algebra(
    prog: &CompiledSystem,
) -> Result<(Matrix<PolyRing>, MPoly, Matrix<PolyRing>), PlanError> {
    let n = prog.unknowns.len();
    let ring = PolyRing::new(prog.symbols.clone());
    let nvars = prog.symbols.len();
    let entries = prog
        .equations
        .iter()
        .flat_map(|e| e.lhs.iter().map(|w| w.commutative_image(nvars)))
        .collect();
    let a = Matrix::new(ring, n, n, entries);
    let det = a
        .det()
        .ok_or_else(|| PlanError::Invalid("the system is not square".into()))?;
    let adj = a
        .adjugate()
        .ok_or_else(|| PlanError::Invalid("the system is not square".into()))?;
    Ok((a, det, adj))
}

/// The commutative model for unknown `i`: `L u_i = Σ_j adj_ij g_j` with
/// `L = Σ_k adj_ik A_ki` (adj's operators applied after A's, the order in
/// which the seed multiplies the system by a row of adj), which equals
/// `det(A)` as a commutative polynomial (checked).
fn commutative(
    d: &mut Discretisation,
    prog: &CompiledSystem,
    g: &[DVector<f64>],
    i: usize,
    max_cond: f64,
) -> Result<LevelSolution, PlanError> {
    let n = prog.unknowns.len();
    let (a, det, adj) = algebra(prog)?;
    let mut expanded = MPoly::zero(prog.symbols.len());
    for k in 0..n {
        expanded = expanded + adj.get(i, k) * a.get(k, i);
    }
    if expanded != det {
        return Err(PlanError::Invalid(
            "internal: adj(A)·A differs from det(A)".into(),
        ));
    }
    if det.is_zero() {
        return Err(PlanError::Singular(
            "commutative model: det(A) = 0 over Q[symbols], so the single equation is singular"
                .into(),
        ));
    }
    let dim = d.dim();
    let mut l = DMatrix::zeros(dim, dim);
    let mut rhs = DVector::zeros(dim);
    let ctx = || PlanError::numeric("commutative model");
    for (k, gk) in g.iter().enumerate().take(n) {
        let adj_ik = d.poly(&NcPoly::from_mpoly(adj.get(i, k)), BasisId::Mid)?;
        let a_ki = d.poly(&prog.equations[k].lhs[i], BasisId::Unknown(i))?;
        l += product(&adj_ik, &d.mid, &a_ki).map_err(ctx())?;
        rhs += apply_to_values(&adj_ik, &d.mid, gk).map_err(ctx())?;
    }
    let lu = CheckedLu::new(&l, max_cond).map_err(PlanError::numeric(format!(
        "commutative model det(A) {} = …",
        prog.unknowns[i]
    )))?;
    let u = lu.solve(&rhs).map_err(ctx())?;
    let mut coefs = vec![None; n];
    coefs[i] = Some(u);
    Ok(LevelSolution {
        coefs,
        cond: lu.cond(),
    })
}

/// The symbol pairs whose order the method fixed without knowing that
/// they commute: none for `coupled` and `ordered` (every product is applied
/// as written); for the commutative model, every symbol of `adj_ik` with
/// every symbol of `A_kj` (the terms `j ≠ i` are the ones the model
/// drops). Sorted, each once.
pub fn commuted_pairs(prog: &CompiledSystem, method: Method, target: usize) -> Vec<(usize, usize)> {
    let mut pairs = BTreeSet::new();
    let vars = |p: &MPoly| -> BTreeSet<usize> {
        (0..prog.symbols.len())
            .filter(|&v| p.contains_var(v))
            .collect()
    };
    let mut add = |a: usize, b: usize| {
        if a != b {
            pairs.insert((a.min(b), a.max(b)));
        }
    };
    if method == Method::Commutative
        && let Ok((_, _, adj)) = algebra(prog)
    {
        let n = prog.unknowns.len();
        for k in 0..n {
            for j in 0..n {
                for x in vars(adj.get(target, k)) {
                    for y in prog.equations[k].lhs[j].symbols() {
                        add(x, y);
                    }
                }
            }
        }
    }
    pairs.into_iter().collect()
}

/// The measured defect `‖KaKb f - KbKa f‖/‖KaKb f‖` (max norm at the
/// nodes) for `f = 1 + x` on the intermediate basis; `None` if `KaKb f`
/// vanishes.
pub fn defect(d: &mut Discretisation, a: usize, b: usize) -> Result<Option<f64>, PlanError> {
    let f = DVector::from_vec(d.mid.interpolate(|x| 1.0 + x));
    defect_on(d, a, b, BasisId::Mid, &f)
}

/// The same defect for the function with coefficients `f` on basis `id`
/// (a computed unknown): both products are formed through `mid`.
pub fn defect_on(
    d: &mut Discretisation,
    a: usize,
    b: usize,
    id: BasisId,
    f: &DVector<f64>,
) -> Result<Option<f64>, PlanError> {
    let (ka, kb) = (d.symbol(a, BasisId::Mid)?, d.symbol(b, BasisId::Mid)?);
    let (ka_f, kb_f) = (d.symbol(a, id)?, d.symbol(b, id)?);
    match commutator_defect_on(&ka, &kb, &ka_f, &kb_f, &d.mid, f) {
        Ok(v) => Ok(Some(v)),
        Err(NumericError::InvalidArgument(_)) => Ok(None),
        Err(e) => Err(PlanError::numeric("commutator defect")(e)),
    }
}
