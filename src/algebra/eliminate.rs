//! The commutative eliminant of one unknown of a square system `A·X = G`
//! over Q\[symbols\]: `det(A)·x_i = Σ_j adj(A)_ij·g_j`, divided by the common
//! factor of the whole relation, cross-checked against the determinantal
//! divisors (Smith data over Q\[all\]), together with the symbol pairs whose
//! commutation the derivation assumed. The right sides `g_j` are opaque
//! here: the relation keeps every term, also those whose `g_j` is zero, so
//! no factor is cancelled on the strength of a zero right side. This module owns that computation; it must not know about
//! files, kernels, f64 or printing beyond names borrowed for display. The
//! ordered (non-commutative) elimination lives in [`super::ordered`].

use super::gcd::gcd;
use super::matrix::Matrix;
use super::mpoly::MPoly;
use super::ncpoly::NcPoly;
use super::polyring::PolyRing;
use super::smith::certify::Check;
use super::smith::divisors::{determinantal_divisors, minor_count};
use super::smith::modes::MINOR_LIMIT;

/// Why no eliminant exists.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum EliminateError {
    /// The system is not square.
    #[error("the λ-matrix is {rows}×{cols}; an eliminant needs a square system")]
    NotSquare {
        /// Rows (equations).
        rows: usize,
        /// Columns (unknowns).
        cols: usize,
    },
    /// The unknown index is out of range.
    #[error("unknown number {0} does not exist")]
    NoSuchUnknown(usize),
    /// `det(A) = 0`: the equations are dependent over Q(symbols), so no
    /// single equation for the unknown follows from them.
    #[error(
        "the λ-matrix is singular: det(A) = 0 (rank {rank} < {n}), so the equations do not determine the unknown and no eliminant exists"
    )]
    Singular {
        /// The rank over Q(symbols).
        rank: usize,
        /// The size of the system.
        n: usize,
    },
}

/// A pair of symbols the derivation had to commute, and where.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CommutedPair {
    /// The smaller symbol index.
    pub a: usize,
    /// The larger symbol index.
    pub b: usize,
    /// The unknowns (0-based) whose coefficient cancels only if `a`, `b`
    /// commute.
    pub on_unknowns: Vec<usize>,
}

/// The cross-check of the eliminant against the Smith data over Q\[all\].
#[derive(Clone, Debug, PartialEq)]
pub struct SmithCrossCheck {
    /// The invariant factors f_1 | … | f_n (determinantal divisors).
    pub invariant_factors: Vec<MPoly>,
    /// The checks, all of which must pass.
    pub checks: Vec<Check>,
}

/// `lhs · x_unknown = Σ_j multipliers[j] · g_j`: the eliminant.
#[derive(Clone, Debug, PartialEq)]
pub struct Eliminant {
    /// The unknown (0-based).
    pub unknown: usize,
    /// `det(A)`.
    pub det: MPoly,
    /// The common factor `h` removed from the relation (normalised; one if
    /// none): the gcd of `adj(A)_ij` over all j, which also divides det.
    pub removed_factor: MPoly,
    /// `det(A) / h`.
    pub lhs: MPoly,
    /// `c_j = adj(A)_ij / h`: equation j is multiplied by `c_j` on the left.
    pub multipliers: Vec<MPoly>,
    /// `Σ_j c_j·A_ji` with every product kept in its order (each `c_j`
    /// written in symbol-table order): the operator the derivation really
    /// applies to the unknown. Its commutative image is `lhs`.
    pub lhs_ordered: NcPoly,
    /// For every other unknown k with a nonzero ordered coefficient
    /// `Σ_j c_j·A_jk` (whose commutative image is zero): that coefficient.
    /// The eliminant drops these terms, which is exact only if they vanish.
    pub dropped: Vec<(usize, NcPoly)>,
    /// The pairs whose commutation makes every dropped term vanish.
    pub commuted_pairs: Vec<CommutedPair>,
    /// Smith cross-check (`None` if the minors would be too many).
    pub smith: Option<SmithCrossCheck>,
}

/// The eliminant of unknown `unknown` (0-based) of `A·X = G`.
///
/// ```
/// use lambdamat::algebra::{eliminate::eliminate, matrix::Matrix, mpoly::MPoly, polyring::PolyRing};
/// let names = ["k1", "k2", "k3", "k4"].map(String::from).to_vec();
/// let a = Matrix::new(PolyRing::new(names.clone()), 2, 2,
///     (0..4).map(|i| MPoly::var(i, 4)).collect());
/// let e = eliminate(&a, 0).unwrap();
/// assert_eq!(e.lhs.to_string_with(&names), "k1*k4 - k2*k3");
/// assert_eq!(e.lhs_ordered.to_string_with(&names), "k4 k1 - k2 k3");
/// assert_eq!((e.commuted_pairs[0].a, e.commuted_pairs[0].b), (1, 3)); // k2, k4
/// ```
#[cfg(any(test, feature = "internals"))]
pub fn eliminate(a: &Matrix<PolyRing>, unknown: usize) -> Result<Eliminant, EliminateError> {
    let words: Vec<Vec<NcPoly>> = (0..a.rows())
        .map(|i| {
            (0..a.cols())
                .map(|j| NcPoly::from_mpoly(a.get(i, j)))
                .collect()
        })
        .collect();
    eliminate_ordered(a, &words, unknown)
}

/// The eliminant of unknown `unknown` of the system whose ordered
/// operators are `words` (row `i`, column `j`; products in the order
/// written) and whose λ-matrix `a` is their commutative image: the
/// multipliers come from `a`, the ordered coefficients (the operator really
/// applied, the dropped terms and so the commuted pairs) from `words`.
pub fn eliminate_ordered(
    a: &Matrix<PolyRing>,
    words: &[Vec<NcPoly>],
    unknown: usize,
) -> Result<Eliminant, EliminateError> {
    let n = a.rows();
    if a.cols() != n {
        return Err(EliminateError::NotSquare {
            rows: n,
            cols: a.cols(),
        });
    }
    if unknown >= n {
        return Err(EliminateError::NoSuchUnknown(unknown));
    }
    let nvars = a.ring.nvars();
    // Only det(A) and row `unknown` of adj(A) are needed: one elimination.
    let (det, row) = a
        .det_adjugate_row(unknown)
        .ok_or(EliminateError::NotSquare {
            rows: n,
            cols: a.cols(),
        })?;
    let Some(row) = row.filter(|_| !det.is_zero()) else {
        return Err(EliminateError::Singular { rank: a.rank(), n });
    };
    // det = Σ_j adj_ij A_ji lies in the ideal of the adj_ij, so the gcd of
    // the whole relation (det and every adj_ij) is the gcd of the adj_ij.
    let h = row
        .iter()
        .fold(det.clone(), |g, c| if c.is_zero() { g } else { gcd(&g, c) })
        .primitive_normal();
    let h = if h.is_zero() { MPoly::one(nvars) } else { h };
    let divide = |p: &MPoly| p.div_exact(&h).unwrap_or_else(|| p.clone());
    let lhs = divide(&det);
    let multipliers: Vec<MPoly> = row.iter().map(divide).collect();
    let ordered_coeff = |k: usize| {
        let mut acc = NcPoly::zero();
        for (j, c) in multipliers.iter().enumerate() {
            let a_jk = words
                .get(j)
                .and_then(|r| r.get(k))
                .cloned()
                .unwrap_or_else(|| NcPoly::from_mpoly(a.get(j, k)));
            acc = &acc + &(&NcPoly::from_mpoly(c) * &a_jk);
        }
        acc
    };
    let lhs_ordered = ordered_coeff(unknown);
    let dropped: Vec<(usize, NcPoly)> = (0..n)
        .filter(|&k| k != unknown)
        .map(|k| (k, ordered_coeff(k)))
        .filter(|(_, p)| !p.is_zero())
        .collect();
    let commuted_pairs = commuted_pairs(&dropped);
    let smith = smith_cross_check(a, &det, &h, unknown);
    Ok(Eliminant {
        unknown,
        det,
        removed_factor: h,
        lhs,
        multipliers,
        lhs_ordered,
        dropped,
        commuted_pairs,
        smith,
    })
}

/// The pairs each dropped coefficient needs; if the necessary pairs of
/// one coefficient are not sufficient (possible for long words), every
/// pair of distinct symbols in it is listed instead.
fn commuted_pairs(dropped: &[(usize, NcPoly)]) -> Vec<CommutedPair> {
    let mut out: Vec<CommutedPair> = Vec::new();
    for (k, p) in dropped {
        let mut pairs = p.needed_commutations();
        if !p.vanishes_if_commuting(&pairs) {
            let syms: Vec<usize> = p.symbols().into_iter().collect();
            pairs = syms
                .iter()
                .enumerate()
                .flat_map(|(i, &x)| syms[i + 1..].iter().map(move |&y| (x, y)))
                .collect();
        }
        for (a, b) in pairs {
            match out.iter_mut().find(|c| c.a == a && c.b == b) {
                Some(c) => c.on_unknowns.push(*k),
                None => out.push(CommutedPair {
                    a,
                    b,
                    on_unknowns: vec![*k],
                }),
            }
        }
    }
    out.sort_by_key(|c| (c.a, c.b));
    out
}

/// Above this many minors the cross-check takes the adjugate row's gcd
/// when it settles the question: all k×k minors of a 9×9 (48 619) or 10×10
/// (184 755) took longer than the whole reduction of a 20×20 chain.
const CROSS_CHECK_MINORS: u128 = 20_000;

fn smith_cross_check(
    a: &Matrix<PolyRing>,
    det: &MPoly,
    h: &MPoly,
    unknown: usize,
) -> Option<SmithCrossCheck> {
    let n = a.rows();
    let nvars = a.ring.nvars();
    if minor_count(n, n) > CROSS_CHECK_MINORS && h.is_nonzero_constant() {
        // h is the gcd of row `unknown` of adj(A) (see eliminate_ordered);
        // those entries are (n−1)-minors, so d_(n−1) divides h: it is 1,
        // and the invariant factors are 1, …, 1, det(A).
        let mut inv = vec![MPoly::one(nvars); n.saturating_sub(1)];
        inv.push(det.primitive_normal());
        return Some(SmithCrossCheck {
            invariant_factors: inv,
            checks: vec![Check {
                property: "d_(n-1) = 1".into(),
                ok: true,
                detail: format!(
                    "the (n-1)-minors in row {} of adj(A) have gcd 1 (computed above), so f1 = … = f(n-1) = 1 and fn = det(A) up to a unit (the minors themselves are not enumerated beyond {CROSS_CHECK_MINORS})",
                    unknown + 1
                ),
            }],
        });
    }
    let dv = determinantal_divisors(a, MINOR_LIMIT).ok()?;
    let prod = dv
        .invariant
        .iter()
        .fold(MPoly::one(nvars), |acc, f| &acc * f);
    let mut checks = Vec::new();
    checks.push(Check {
        property: "det(A) = f1·…·fn up to a unit".into(),
        ok: dv.invariant.len() == n && prod.primitive_normal() == det.primitive_normal(),
        detail: format!(
            "{} invariant factors over Q[all]; their product is an associate of det(A)",
            dv.invariant.len()
        ),
    });
    // d_{n-1} (gcd of all (n-1)-minors) divides every adj_ij, hence h; so
    // the eliminant's operator det/h divides f_n = det/d_{n-1}.
    let d_prev = if n >= 2 {
        dv.determinantal.get(n - 2).cloned()
    } else {
        Some(MPoly::one(nvars))
    };
    let divides = d_prev.as_ref().is_some_and(|d| h.div_exact(d).is_some());
    checks.push(Check {
        property: "d_(n-1) divides the removed factor".into(),
        ok: divides,
        detail: "so the eliminant's operator det(A)/h divides the last invariant factor f_n".into(),
    });
    let f_n = dv
        .invariant
        .last()
        .cloned()
        .unwrap_or_else(|| MPoly::one(nvars));
    let lhs = det.div_exact(h);
    checks.push(Check {
        property: "det(A)/h divides f_n".into(),
        ok: lhs.is_some_and(|l| f_n.div_exact(&l).is_some()),
        detail: "checked by exact division".into(),
    });
    Some(SmithCrossCheck {
        invariant_factors: dv.invariant,
        checks,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(v: &[&str]) -> Vec<String> {
        v.iter().map(|s| s.to_string()).collect()
    }

    fn seed() -> (Vec<String>, Matrix<PolyRing>) {
        let n = names(&["k1", "k2", "k3", "k4"]);
        let a = Matrix::new(
            PolyRing::new(n.clone()),
            2,
            2,
            (0..4).map(|i| MPoly::var(i, 4)).collect(),
        );
        (n, a)
    }

    #[test]
    fn seed_eliminant_for_p() {
        let (n, a) = seed();
        let e = eliminate(&a, 0).unwrap();
        assert_eq!(e.lhs.to_string_with(&n), "k1*k4 - k2*k3");
        let m: Vec<String> = e.multipliers.iter().map(|c| c.to_string_with(&n)).collect();
        assert_eq!(m, ["k4", "-k2"]);
        assert!(e.removed_factor.is_nonzero_constant());
        assert_eq!(e.lhs_ordered.to_string_with(&n), "k4 k1 - k2 k3");
        assert_eq!(e.dropped.len(), 1);
        assert_eq!(e.dropped[0].0, 1);
        assert_eq!(e.dropped[0].1.to_string_with(&n), "-k2 k4 + k4 k2");
        assert_eq!(
            e.commuted_pairs,
            vec![CommutedPair {
                a: 1,
                b: 3,
                on_unknowns: vec![1]
            }]
        );
        let s = e.smith.unwrap();
        assert!(s.checks.iter().all(|c| c.ok), "{:?}", s.checks);
        let f: Vec<String> = s
            .invariant_factors
            .iter()
            .map(|f| f.to_string_with(&n))
            .collect();
        assert_eq!(f, ["1", "k1*k4 - k2*k3"]);
    }

    #[test]
    fn seed_eliminant_for_q() {
        let (n, a) = seed();
        let e = eliminate(&a, 1).unwrap();
        let m: Vec<String> = e.multipliers.iter().map(|c| c.to_string_with(&n)).collect();
        assert_eq!(m, ["-k3", "k1"]);
        assert_eq!(e.lhs_ordered.to_string_with(&n), "k1 k4 - k3 k2");
        // The p-coefficient -k3 k1 + k1 k3 needs (k1, k3).
        assert_eq!((e.commuted_pairs[0].a, e.commuted_pairs[0].b), (0, 2));
    }

    #[test]
    fn common_factor_of_the_whole_relation_is_removed() {
        // A = x·I: det x^2, adj row 1 = (x, 0), h = x.
        let n = names(&["x"]);
        let x = MPoly::var(0, 1);
        let z = MPoly::zero(1);
        let a = Matrix::new(
            PolyRing::new(n.clone()),
            2,
            2,
            vec![x.clone(), z.clone(), z, x],
        );
        let e = eliminate(&a, 0).unwrap();
        assert_eq!(e.removed_factor.to_string_with(&n), "x");
        assert_eq!(e.lhs.to_string_with(&n), "x");
        assert_eq!(e.multipliers[0].to_string_with(&n), "1");
        assert!(e.dropped.is_empty() && e.commuted_pairs.is_empty());
        assert!(e.smith.unwrap().checks.iter().all(|c| c.ok));
    }

    #[test]
    fn singular_matrices_give_no_equation() {
        let n = names(&["k1", "k2"]);
        let (k1, k2) = (MPoly::var(0, 2), MPoly::var(1, 2));
        // Second row = k2 × first row (commutatively).
        let a = Matrix::new(
            PolyRing::new(n),
            2,
            2,
            vec![k1.clone(), k2.clone(), &k1 * &k2, &k2 * &k2],
        );
        assert_eq!(
            eliminate(&a, 0),
            Err(EliminateError::Singular { rank: 1, n: 2 })
        );
        let e = EliminateError::Singular { rank: 1, n: 2 }.to_string();
        assert!(e.contains("singular") && e.contains("det(A) = 0"));
    }

    #[test]
    fn generic_3x3_is_det_and_adjugate() {
        let n: Vec<String> = (1..=9).map(|i| format!("k{i}")).collect();
        let a = Matrix::new(
            PolyRing::new(n.clone()),
            3,
            3,
            (0..9).map(|i| MPoly::var(i, 9)).collect(),
        );
        let adj = a.adjugate().unwrap();
        for u in 0..3 {
            let e = eliminate(&a, u).unwrap();
            assert_eq!(e.lhs, a.det().unwrap());
            for j in 0..3 {
                assert_eq!(&e.multipliers[j], adj.get(u, j));
            }
            assert_eq!(e.lhs_ordered.commutative_image(9), e.lhs);
            assert_eq!(e.dropped.len(), 2);
            assert!(!e.commuted_pairs.is_empty());
            for (_, p) in &e.dropped {
                assert!(p.commutative_image(9).is_zero());
                let pairs: Vec<(usize, usize)> =
                    e.commuted_pairs.iter().map(|c| (c.a, c.b)).collect();
                assert!(p.vanishes_if_commuting(&pairs));
            }
            assert!(e.smith.unwrap().checks.iter().all(|c| c.ok));
        }
    }
}
