//! The three ways to solve one discretised language system
//! `Σ_j A_ij(K) u_j = g_i`, every product in its written order: `coupled`
//! (one block system), `ordered` (exact block elimination toward the
//! target unknown in the pivot order of the system's
//! [`Derivation`], e.g. `(K11 - K12 K22⁻¹ K21) p = g1 - K12 K22⁻¹ g2`) and
//! `commutative` (the derivation's eliminant `D_i u_i = Σ_j c_j g_j`
//! evaluated with operator matrices: the seed's single equation, a
//! *model*, exact only if its commuted pairs commute). Also the pairs of
//! symbols a method commuted and their measured defects. With side
//! conditions (`condition int(-1..1) f(t) dt = 1`) every method but the
//! commutative model solves the equations and the conditions together as
//! one least-squares system (more rows than unknowns). This file owns
//! these recipes; it executes the derivation and never re-derives;
//! assembly is `discrete.rs`'s, refinement `refine.rs`'s.
use std::fmt;
use std::str::FromStr;

use nalgebra::{DMatrix, DVector};

use crate::algebra::derivation::{Derivation, MAX_ELIMINANT_TERMS};
use crate::numeric::Assembler;
use crate::numeric::NumericError;
use crate::numeric::elimination::{apply_to_values, commutator_defect_on, solve_blocks};
use crate::numeric::solve::{CheckedLu, block_matrix, least_squares};
use crate::system::NcPoly;

use super::compiled::{CompiledSystem, OutputTerm};
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
    /// Where the method departed from the derivation (a pivot replaced by
    /// a better-conditioned one), named.
    pub warnings: Vec<String>,
    /// The pivots the ordered elimination executed, as (equation,
    /// unknown), 0-based, in order (empty for the other methods).
    pub pivots: Vec<(usize, usize)>,
    /// With side conditions, the relative least-squares residual of the
    /// equations and conditions together (0 for square systems, solved
    /// exactly): not rounding-small when the conditions contradict the
    /// equations.
    pub residual: f64,
}

/// A functional on the discrete unknowns: a row per unknown (`None` where
/// it does not occur) and a constant.
pub type FunctionalRows = (Vec<Option<DVector<f64>>>, f64);

/// The row vectors of a linear functional on the unknowns' bases (one per
/// unknown, `None` where it does not occur) and its constant part.
pub fn functional_rows(
    d: &Discretisation,
    terms: &[OutputTerm],
    what: &str,
) -> Result<FunctionalRows, PlanError> {
    let mut rows: Vec<Option<DVector<f64>>> = vec![None; d.bases.len()];
    let mut constant = 0.0;
    for t in terms {
        let (u, row) = match t {
            OutputTerm::Constant(c) => {
                constant += c;
                continue;
            }
            OutputTerm::Integral {
                coeff,
                lower,
                upper,
                weight,
                unknown,
            } => {
                let basis = d.bases.get(*unknown).ok_or_else(|| {
                    PlanError::Invalid(format!("{what}: unknown #{unknown} has no basis"))
                })?;
                let asm = Assembler::new(basis).map_err(PlanError::numeric(what.to_string()))?;
                let w = weight.clone();
                let row = asm
                    .functional(move |x| w(x), *lower, *upper)
                    .map_err(PlanError::numeric(what.to_string()))?;
                (*unknown, DVector::from_vec(row) * *coeff)
            }
            OutputTerm::Point { coeff, at, unknown } => {
                let basis = d.bases.get(*unknown).ok_or_else(|| {
                    PlanError::Invalid(format!("{what}: unknown #{unknown} has no basis"))
                })?;
                let row = basis.point_row(*at);
                if row.iter().any(|v| !v.is_finite()) {
                    return Err(PlanError::Invalid(format!(
                        "{what}: the unknown is not finite at x = {at} (its weight {} is singular there); take the point value elsewhere",
                        if basis.weight_at(*at).is_finite() {
                            ""
                        } else {
                            "in the trial space"
                        }
                    )));
                }
                (*unknown, DVector::from_vec(row) * *coeff)
            }
        };
        match &mut rows[u] {
            Some(r) => *r += row,
            slot => *slot = Some(row),
        }
    }
    Ok((rows, constant))
}

/// The equations' blocks and right sides with the side conditions as
/// extra rows, solved together by least squares.
fn with_conditions(
    d: &Discretisation,
    prog: &CompiledSystem,
    blocks: &[Vec<DMatrix<f64>>],
    g: &[DVector<f64>],
    max_cond: f64,
) -> Result<LevelSolution, PlanError> {
    let refs: Vec<Vec<&DMatrix<f64>>> = blocks.iter().map(|r| r.iter().collect()).collect();
    let ctx = || PlanError::numeric("equations with side conditions (least squares)");
    let a = block_matrix(&refs).map_err(ctx())?;
    let dims: Vec<usize> = blocks
        .first()
        .map(|r| r.iter().map(DMatrix::ncols).collect())
        .unwrap_or_default();
    let (m, n) = a.shape();
    let k = prog.conditions.len();
    let mut big = DMatrix::zeros(m + k, n);
    big.rows_mut(0, m).copy_from(&a);
    let mut rhs = DVector::zeros(m + k);
    let mut r0 = 0;
    for gi in g {
        rhs.rows_mut(r0, gi.len()).copy_from(gi);
        r0 += gi.len();
    }
    for (i, c) in prog.conditions.iter().enumerate() {
        let (rows, constant) = functional_rows(d, &c.terms, &c.text)?;
        let mut c0 = 0;
        for (row, &dim) in rows.iter().zip(&dims) {
            if let Some(row) = row {
                big.view_mut((m + i, c0), (1, dim))
                    .copy_from(&row.transpose());
            }
            c0 += dim;
        }
        rhs[m + i] = c.value - constant;
    }
    let (x, cond, residual) = least_squares(&big, &rhs, max_cond).map_err(ctx())?;
    let mut coefs = Vec::with_capacity(dims.len());
    let mut c0 = 0;
    for dim in dims {
        coefs.push(Some(x.rows(c0, dim).into_owned()));
        c0 += dim;
    }
    Ok(LevelSolution {
        coefs,
        cond,
        warnings: Vec::new(),
        pivots: Vec::new(),
        residual,
    })
}

/// Solves the system on `d` by `method`, executing the derivation `der`
/// of the target unknown: `ordered` follows its pivot sequence, the
/// commutative model applies its eliminant (which it requires).
pub fn solve_level(
    d: &mut Discretisation,
    prog: &CompiledSystem,
    method: Method,
    der: Option<&Derivation>,
    max_cond: f64,
) -> Result<LevelSolution, PlanError> {
    let target = prog.target;
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
    if method == Method::Commutative && !prog.conditions.is_empty() {
        return Err(PlanError::Invalid(
            "the commutative model is one equation for one unknown and cannot take side conditions; use --method ordered or coupled".into(),
        ));
    }
    if method == Method::Commutative {
        let der = der.ok_or_else(|| {
            PlanError::Singular(
                "commutative model: the λ-matrix is singular (det(A) = 0 over Q[symbols]), so there is no single equation".into(),
            )
        })?;
        return commutative(d, prog, &g, der, max_cond);
    }
    let mut blocks = Vec::with_capacity(n);
    for eq in &prog.equations {
        let row = (0..n)
            .map(|j| d.poly(&eq.lhs[j], BasisId::Unknown(j)))
            .collect::<Result<Vec<_>, _>>()?;
        blocks.push(row);
    }
    if !prog.conditions.is_empty() {
        return with_conditions(d, prog, &blocks, &g, max_cond);
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
                warnings: Vec::new(),
                pivots: Vec::new(),
                residual: 0.0,
            })
        }
        _ => {
            let pivots = der.map(Derivation::pivot_order).unwrap_or_default();
            ordered(blocks, g, target, &pivots, &prog.unknowns, max_cond)
        }
    }
}

/// Block Gaussian elimination in the derivation's pivot order: `pivots`
/// lists (equation, unknown) as the ordered elimination used them; each
/// step factorises that equation's block for that unknown and, only if it
/// is singular or worse conditioned than `max_cond`, falls back to the
/// first remaining equation whose block is acceptable, with a warning that
/// names it. Without a derived order (the ordered form was too large), the
/// unknowns other than `target` are eliminated in order, each from its own
/// equation if possible. Then `target` is solved and the rest
/// back-substituted.
pub(super) fn ordered(
    mut b: Vec<Vec<DMatrix<f64>>>,
    mut g: Vec<DVector<f64>>,
    target: usize,
    pivots_in: &[(usize, usize)],
    names: &[String],
    max_cond: f64,
) -> Result<LevelSolution, PlanError> {
    let n = b.len();
    let derived = pivots_in.len() + 1 == n;
    let order: Vec<usize> = if derived {
        pivots_in.iter().map(|&(_, u)| u).chain([target]).collect()
    } else {
        (0..n).filter(|&j| j != target).chain([target]).collect()
    };
    let mut warnings = Vec::new();
    let mut left: Vec<usize> = (0..n).collect();
    let mut pivots: Vec<(usize, usize, CheckedLu)> = Vec::new();
    let mut cond: f64 = 0.0;
    for (step, &col) in order.iter().enumerate() {
        let want = if derived {
            pivots_in.get(step).map_or(col, |&(e, _)| e)
        } else {
            col
        };
        let mut cands = left.clone();
        cands.sort_by_key(|&r| r != want);
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
        if derived && r != want && left.contains(&want) {
            warnings.push(format!(
                "ordered elimination: the derivation solves equation {} for {}, but that block cannot be used ({}); used equation {} instead",
                want + 1,
                names[col],
                last.as_ref().map_or("unusable".into(), |e| e.to_string()),
                r + 1
            ));
        }
        cond = cond.max(lu.cond());
        left.retain(|&x| x != r);
        let later = &order[step + 1..];
        let ctx = || PlanError::numeric(format!("ordered elimination of {}", names[col]));
        // A zero block contributes nothing to the update, and in a sparse
        // system (a chain, say) most blocks are zero: skipping them keeps
        // the elimination from costing a solve and a dense product per pair
        // of blocks. `None` stands for a zero block of `y`.
        let y: Vec<Option<DMatrix<f64>>> = later
            .iter()
            .map(|&c| {
                if is_zero(&b[r][c]) {
                    return Ok(None);
                }
                let yc = lu.solve_matrix(&b[r][c])?;
                Ok(if is_zero(&yc) { None } else { Some(yc) })
            })
            .collect::<Result<_, NumericError>>()
            .map_err(ctx())?;
        let yg = lu.solve(&g[r]).map_err(ctx())?;
        for &i in &left {
            if is_zero(&b[i][col]) {
                continue;
            }
            let bic = b[i][col].clone();
            for (&c, yc) in later.iter().zip(&y) {
                if let Some(yc) = yc {
                    b[i][c] -= &bic * yc;
                }
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
    Ok(LevelSolution {
        coefs: u,
        cond,
        warnings,
        pivots: pivots.iter().map(|(col, r, _)| (*r, *col)).collect(),
        residual: 0.0,
    })
}

/// The commutative model for the target `i`, as derived: equation `j` is
/// multiplied on the left by the eliminant's `c_j` (monomials read in
/// symbol-table order) and the terms of the other unknowns are dropped, so
/// `D_i u_i = Σ_j c_j g_j` with `D_i = Σ_j c_j A_ji` applied in written
/// order (its commutative image is `det(A)/h`).
fn commutative(
    d: &mut Discretisation,
    prog: &CompiledSystem,
    g: &[DVector<f64>],
    der: &Derivation,
    max_cond: f64,
) -> Result<LevelSolution, PlanError> {
    let n = prog.unknowns.len();
    let i = der.target;
    let Some(e) = &der.eliminant else {
        return Err(PlanError::Invalid(format!(
            "commutative model: the eliminant was not derived: det(A) may have up to {:.3e} terms (limit {:.0}); use --method ordered or coupled",
            der.bound.terms, MAX_ELIMINANT_TERMS
        )));
    };
    let l = d.poly(&e.lhs_ordered, BasisId::Unknown(i))?;
    let dim = d.dim();
    let mut rhs = DVector::zeros(dim);
    let ctx = || PlanError::numeric("commutative model");
    for (c, gk) in e.multipliers.iter().zip(g).take(n) {
        if c.is_zero() {
            continue;
        }
        let cm = d.poly(&NcPoly::from_mpoly(c), BasisId::Mid)?;
        rhs += apply_to_values(&cm, &d.mid, gk).map_err(ctx())?;
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
        warnings: Vec::new(),
        pivots: Vec::new(),
        residual: 0.0,
    })
}

/// The symbol pairs a method commuted: none for `coupled` and `ordered`
/// (every product is applied as written); for the commutative model, the
/// derivation's commuted pairs ([`Derivation::commuted_pairs`]), the same
/// list `lambdamat reduce` prints.
pub fn commuted_pairs(method: Method, der: Option<&Derivation>) -> Vec<(usize, usize)> {
    match (method, der) {
        (Method::Commutative, Some(d)) => d.commuted_pairs().iter().map(|c| (c.a, c.b)).collect(),
        _ => Vec::new(),
    }
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

/// Whether every entry of `m` is zero.
fn is_zero(m: &DMatrix<f64>) -> bool {
    m.iter().all(|&v| v == 0.0)
}
