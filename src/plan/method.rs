//! The solution methods a user chooses (`--method`): [`Method`], and the
//! one recipe they share with no discretisation in it, [`ordered`]: exact
//! block Gaussian elimination in the pivot order of the system's
//! derivation (`(K11 - K12 K22⁻¹ K21) p = g1 - K12 K22⁻¹ g2`), every
//! product in its written order. `split_methods.rs` executes it, and the
//! commutative model, on the split discretisation's blocks.
use std::fmt;
use std::str::FromStr;

use nalgebra::{DMatrix, DVector};

use crate::numeric::NumericError;
use crate::numeric::solve::CheckedLu;

use super::error::PlanError;

/// A solution method.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// The block system, solved at once; the default.
    Coupled,
    /// Exact (non-commutative) elimination in the derivation's pivot order.
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

/// What the ordered elimination computed: every unknown's coefficients
/// (`None` where it was not reached) and the largest condition estimate
/// met.
pub struct Eliminated {
    /// Coefficients per unknown.
    pub coefs: Vec<Option<DVector<f64>>>,
    /// Largest estimated condition number of a factorised matrix.
    pub cond: f64,
    /// Where the method departed from the derivation (a pivot replaced by
    /// a better-conditioned one), named.
    pub warnings: Vec<String>,
    /// The pivots executed, as (equation, unknown), 0-based, in order.
    pub pivots: Vec<(usize, usize)>,
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
pub fn ordered(
    mut b: Vec<Vec<DMatrix<f64>>>,
    mut g: Vec<DVector<f64>>,
    target: usize,
    pivots_in: &[(usize, usize)],
    names: &[String],
    max_cond: f64,
) -> Result<Eliminated, PlanError> {
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
    Ok(Eliminated {
        coefs: u,
        cond,
        warnings,
        pivots: pivots.iter().map(|(col, r, _)| (*r, *col)).collect(),
    })
}

/// Whether every entry of `m` is zero.
fn is_zero(m: &DMatrix<f64>) -> bool {
    m.iter().all(|&v| v == 0.0)
}
