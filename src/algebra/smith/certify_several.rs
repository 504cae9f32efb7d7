//! Certifies invariant factors 1, …, 1, det over Q[s1..sn] (several
//! symbols) from `A·B = c·I` alone, with no transforms and no minors, for
//! a set S of symbols: over Q(others)\[s\] for each s ∈ S (the principal
//! mode takes S = {λ}; the determinantal mode takes every symbol of A, and
//! then the statement holds over Q\[all\]). It recomputes what it states
//! from A, B and c and never trusts the algorithm that produced them
//! ([`super::several`]); it must not compute B or choose a mode.
//!
//! The argument, for one symbol s and K = Q(others):
//! 1. `A·B = c·I` exactly over Q\[all\] with `c ≠ 0`; so A is invertible and
//!    `B = (c/δ)·adj A` (δ = det A); write `c/δ = u/v` in lowest terms;
//! 2. the entries of B have gcd 1 over K\[s\]: their images in Z_p\[s\] at a
//!    point of the other symbols where the first entry keeps its leading
//!    coefficient in s have gcd 1 (by Gauss's lemma a common factor g
//!    primitive over Z\[others\] keeps its degree in s there and divides
//!    every image). From `u·adj A = v·B`, u divides every entry of B, so
//!    u ∈ K (free of s);
//! 3. `deg_s c = N_s`, the least of the sums of row and of column degrees
//!    in s of A, which bounds `deg_s δ`; since `δ = c·v/u`, v is free of s.
//!
//! Hence over K\[s\] c and det A are associates and adj A = (v/u)·B has
//! unit content, so `d_(n−1) = 1` and the invariant factors are
//! 1, …, 1, c (made monic in s). When every symbol of A is in S, u and v
//! are constants and the same holds over Q\[all\]: d_(n−1) = 1 and
//! d_n ~ c.
//!
//! For a non-square A, [`certify_maximal_minors`] states invariant factors
//! 1, …, 1, d over Q(others)\[s\] from its maximal minors computed exactly
//! (d their gcd) and step 2's argument applied to them. For a square A
//! with `d_(n−1) ≠ 1`, [`certify_two_factors_several`] states 1, …, 1, g,
//! c/g over Q(others)\[s\] from the same `A·B = c·I`: g the gcd of B's
//! entries (step 2's argument on the quotients), `c/det A` free of s by
//! Jacobi's identity, `d_(n−2) = 1` from (n−2)×(n−2) minors of A.

use super::certify::{Certificate, Check};
use super::several::degree_bound;
use crate::algebra::gcd::lcm;
use crate::algebra::matrix::Matrix;
use crate::algebra::modular::{self, Fp, Points, UP};
use crate::algebra::mpoly::{MPoly, Monomial};
use crate::algebra::polyring::PolyRing;
use crate::algebra::ratfunc::{RatFunc, RatFuncField};
use crate::algebra::ring::{GcdDomain, Ring};
use crate::algebra::upoly::{UPoly, UPolyRing};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Zero};
use std::collections::BTreeMap;

/// The image of `e` in Z_p[s] with the other symbols set to `point`
/// (indexed by symbol; `point[s]` unused). `None` if a denominator
/// vanishes mod p.
fn image_in(f: Fp, e: &MPoly, s: usize, point: &[u64]) -> Option<UP> {
    let mut out: UP = vec![0; e.degree_in(s).unwrap_or(0) as usize + 1];
    for (m, c) in e.terms() {
        let den = f.reduce(c.denom());
        if den == 0 {
            return None;
        }
        let mut v = f.mul(f.reduce(c.numer()), f.inv(den));
        for (k, &ek) in m.iter().enumerate() {
            if k != s && ek > 0 {
                v = f.mul(v, f.pow(point[k], u64::from(ek)));
            }
        }
        let slot = &mut out[m[s] as usize];
        *slot = f.add(*slot, v);
    }
    Some(modular::trim(out))
}

/// Whether the nonzero `entries` have gcd 1 over Q(others)[s], proved by
/// images at points mod p (see the module text); returns `(p, used)`.
fn coprime_in(entries: &[&MPoly], s: usize) -> Option<(u64, usize)> {
    let first = entries.first()?;
    let nv = first.nvars();
    let d0 = first.degree_in(s).unwrap_or(0) as usize;
    let mut pts = Points::new(0x5eed_5eed_0f00_0015);
    for p in modular::primes().take(3) {
        let f = Fp::new(p);
        for _ in 0..3 {
            let point: Vec<u64> = (0..nv).map(|_| pts.next(f)).collect();
            let Some(g0) = image_in(f, first, s, &point) else {
                break;
            };
            if modular::deg(&g0) != Some(d0) {
                continue;
            }
            let mut g = g0;
            let mut used = 1;
            for e in &entries[1..] {
                if modular::deg(&g) == Some(0) {
                    break;
                }
                let Some(img) = image_in(f, e, s, &point) else {
                    break;
                };
                g = modular::gcd(f, &g, &img);
                used += 1;
            }
            if modular::deg(&g) == Some(0) {
                return Some((p, used));
            }
        }
    }
    None
}

/// Integer terms `(m, k·coefficient)` of `p` for an integer `k` that
/// clears its denominators, or `None` if `k` does not.
fn scaled_terms<'p>(p: &'p MPoly, k: &BigInt) -> Option<Vec<(&'p Monomial, BigInt)>> {
    p.terms()
        .iter()
        .map(|(m, c)| {
            let (q, r) = (c.numer() * k).div_rem(c.denom());
            r.is_zero().then_some((m, q))
        })
        .collect()
}

/// Whether `A·B = c·I` exactly: row i of A and c are scaled by the lcm of
/// the denominators in row i of A, in c and in B, and every entry of the
/// product is accumulated over Z in one ordered map (the same identity,
/// without a rational normalisation per term).
fn product_is_c_identity(a: &Matrix<PolyRing>, c: &MPoly, b: &Matrix<PolyRing>) -> bool {
    let n = a.rows();
    let den_lcm = |ps: &[MPoly]| {
        ps.iter()
            .flat_map(|p| p.terms().iter())
            .fold(BigInt::one(), |l, (_, q)| {
                crate::algebra::intgcd::lcm(&l, q.denom())
            })
    };
    let kb = den_lcm(b.entries());
    let Some(bt): Option<Vec<Vec<(&Monomial, BigInt)>>> =
        b.entries().iter().map(|e| scaled_terms(e, &kb)).collect()
    else {
        return false;
    };
    for i in 0..n {
        let ka = den_lcm(a.row(i));
        let kc = crate::algebra::intgcd::lcm(&ka, &den_lcm(std::slice::from_ref(c)));
        let Some(at): Option<Vec<Vec<(&Monomial, BigInt)>>> =
            a.row(i).iter().map(|e| scaled_terms(e, &kc)).collect()
        else {
            return false;
        };
        for j in 0..n {
            let mut acc: BTreeMap<Monomial, BigInt> = BTreeMap::new();
            for (k, ak) in at.iter().enumerate() {
                for (ma, ca) in ak {
                    for (mb, cb) in &bt[k * n + j] {
                        let m: Monomial = ma.iter().zip(mb.iter()).map(|(x, y)| x + y).collect();
                        *acc.entry(m).or_insert_with(BigInt::zero) += ca * cb;
                    }
                }
            }
            acc.retain(|_, v| !v.is_zero());
            // Expected: kc·kb·c on the diagonal, 0 elsewhere.
            if i != j {
                if !acc.is_empty() {
                    return false;
                }
                continue;
            }
            let kk = &kc * &kb;
            let Some(want) = scaled_terms(c, &kk) else {
                return false;
            };
            if want.len() != acc.len() || !want.iter().all(|(m, v)| acc.get(*m) == Some(v)) {
                return false;
            }
        }
    }
    true
}

/// Certifies, for every symbol s in `symbols`, that over Q(others)\[s\] the
/// invariant factors of the square A are 1, …, 1, c (up to a unit), given
/// `A·B = c·I`; see the module text. With every symbol of A in `symbols`
/// this proves `d_(n−1) = 1` and `d_n ~ c` over Q\[all\].
pub fn certify_last_factor_several(
    a: &Matrix<PolyRing>,
    c: &MPoly,
    b: &Matrix<PolyRing>,
    symbols: &[usize],
) -> Certificate {
    let n = a.rows();
    let names = &a.ring.names;
    let mut checks = Vec::new();
    let shaped = n == a.cols() && b.rows() == n && b.cols() == n && !c.is_zero();
    let prod = shaped && product_is_c_identity(a, c, b);
    checks.push(Check {
        property: "A·B = c·I".into(),
        ok: prod,
        detail: if prod {
            format!(
                "holds exactly over {} for a polynomial B and c ≠ 0 ({} terms)",
                a.ring.name(),
                c.terms().len()
            )
        } else {
            "fails (or c = 0, or the shapes differ)".into()
        },
    });
    let entries: Vec<&MPoly> = b.entries().iter().filter(|e| !e.is_zero()).collect();
    let mut all = prod;
    for &s in symbols {
        let bound = degree_bound(a, s);
        let dc = c.degree_in(s).unwrap_or(0) as usize;
        let deg_ok = dc == bound;
        checks.push(Check {
            property: format!("deg_{} c = degree bound of det A", names[s]),
            ok: deg_ok,
            detail: format!(
                "deg_{0} c = {dc}; deg_{0} det A ≤ {bound} (least of the sums of row and of column degrees in {0})",
                names[s]
            ),
        });
        let coprime = if entries.iter().any(|e| e.contains_var(s)) {
            coprime_in(&entries, s)
        } else {
            // Entries free of s are units of Q(others)[s].
            Some((0, 1))
        };
        checks.push(Check {
            property: format!("gcd of B's entries over Q(others)[{}] is 1", names[s]),
            ok: coprime.is_some(),
            detail: match coprime {
                Some((0, _)) => format!("an entry of B is free of {}, a unit", names[s]),
                Some((p, k)) => format!(
                    "the first {k} nonzero entries of B have gcd 1 in Z_p[{0}], p = {p}, at a point of the other symbols where the first keeps its leading coefficient in {0}",
                    names[s]
                ),
                None => "not shown (no prime and point among those tried)".into(),
            },
        });
        all = all && deg_ok && coprime.is_some();
    }
    checks.push(Check {
        property: "invariant factors 1, …, 1, c".into(),
        ok: all,
        detail: if all {
            "B = (c/det A)·adj A with entries of unit content and deg c ≥ deg det A in each symbol: c ~ det A and d_(n−1) = 1".into()
        } else {
            "not established".into()
        },
    });
    Certificate { checks }
}

/// At most this many r×r minors (r-subsets of the longer side) are
/// computed by [`certify_maximal_minors`], and at most this many
/// (r−1)×(r−1) minors tried for `d_(r−1) = 1`.
pub const MAXIMAL_MINORS_LIMIT: usize = 64;

/// Certifies the invariant factors of a non-square `a` (m×n, r = min(m, n))
/// over Q(others)\[s\] from A alone, without transforms: every r×r minor
/// (r-subsets of the longer side, at most [`MAXIMAL_MINORS_LIMIT`]) is
/// computed exactly over Q\[all\]; `d` = the primitive part in s of their
/// gcd over Q\[all\] divides each of them exactly and the quotients have gcd
/// 1 over Q(others)\[s\] (their images in Z_p\[s\] at a point where the first
/// keeps its degree in s, the argument of the module text, step 2), so
/// `d_r ~ d`; and some (r−1)×(r−1) minors have gcd 1 there, so `d_(r−1) =
/// 1` and `d_k = 1` for k < r (d_k divides d_(k+1)). The invariant factors
/// are then 1, …, 1, d (rank r). When the first minors tried are already
/// coprime, `d = 1` and neither the other minors nor the (r−1)×(r−1) ones
/// are needed. Returns the certificate and `d`; `None` for a square or
/// rank-deficient input, or when the statement is not established.
pub fn certify_maximal_minors(a: &Matrix<PolyRing>, s: usize) -> Option<(Certificate, MPoly)> {
    let (m, n) = (a.rows(), a.cols());
    if m == n || m == 0 || n == 0 {
        return None;
    }
    let r = m.min(n);
    let long = m.max(n);
    let nv = a.ring.nvars();
    let name = &a.ring.names[s];
    let side = if m < n { "columns" } else { "rows" };
    let sets = |used: &[Vec<usize>]| -> String {
        used.iter()
            .map(|c| {
                let c: Vec<String> = c.iter().map(|i| (i + 1).to_string()).collect();
                format!("{{{}}}", c.join(", "))
            })
            .collect::<Vec<_>>()
            .join(", ")
    };
    let minor_of =
        |rows: &[usize], cols: &[usize]| det_expanding_largest_row(&a.submatrix(rows, cols));
    let all: Vec<usize> = (0..r).collect();
    // The r×r minors, stopping early once those so far are coprime.
    let mut subset: Vec<usize> = (0..r).collect();
    let mut minors: Vec<MPoly> = Vec::new();
    let mut used: Vec<Vec<usize>> = Vec::new();
    let mut complete = false;
    loop {
        let minor = if m < n {
            minor_of(&all, &subset)?
        } else {
            minor_of(&subset, &all)?
        };
        if !minor.is_zero() {
            minors.push(minor);
            used.push(subset.clone());
            if let Some((p, k)) = coprime_or_unit(&minors.iter().collect::<Vec<_>>(), s) {
                let gcd_detail = if p == 0 {
                    format!("minor {} is free of {name}, a unit", sets(&used[k - 1..k]))
                } else {
                    format!(
                        "the first {k} have gcd 1 in Z_p[{name}], p = {p}, at a point of the other symbols where the first keeps its degree in {name}"
                    )
                };
                let checks = vec![
                    Check {
                        property: format!("{r}×{r} minors computed"),
                        ok: true,
                        detail: format!(
                            "{k} nonzero {r}×{r} minor(s) of A over {} ({side} {}), each by expansion",
                            a.ring.name(),
                            sets(&used[..k])
                        ),
                    },
                    Check {
                        property: format!("gcd of {r}×{r} minors over Q(others)[{name}] is 1"),
                        ok: true,
                        detail: gcd_detail,
                    },
                    Check {
                        property: "invariant factors 1, …, 1".into(),
                        ok: true,
                        detail: format!(
                            "d_{r} = 1, so d_k = 1 for every k ≤ {r} (d_k divides d_(k+1)): rank {r}, every invariant factor 1"
                        ),
                    },
                ];
                return Some((Certificate { checks }, MPoly::one(nv)));
            }
        }
        if used.len() + 1 > MAXIMAL_MINORS_LIMIT {
            break;
        }
        if !next_subset(&mut subset, long) {
            complete = true;
            break;
        }
    }
    if !complete || minors.is_empty() {
        return None;
    }
    // d = primitive part in s of the gcd of all r×r minors.
    let g = minors
        .iter()
        .fold(MPoly::zero(nv), |g, e| crate::algebra::gcd::gcd(&g, e));
    if g.degree_in(s).unwrap_or(0) == 0 {
        return None;
    }
    let d = crate::algebra::gcd::primitive_part_in(&g, s).primitive_normal();
    let quotients: Vec<MPoly> = minors
        .iter()
        .map(|e| e.div_exact(&d))
        .collect::<Option<_>>()?;
    let (p, k) = coprime_or_unit(&quotients.iter().collect::<Vec<_>>(), s)?;
    // d_(r−1) = 1 from some (r−1)×(r−1) minors (r = 1: d_0 = 1).
    let low = if r == 1 {
        None
    } else {
        let mut rows: Vec<usize> = (0..r - 1).collect();
        let mut small: Vec<MPoly> = Vec::new();
        let mut found = None;
        'outer: loop {
            let mut cols: Vec<usize> = (0..r - 1).collect();
            loop {
                let (rr, cc) = if m < n {
                    (&rows, &cols)
                } else {
                    (&cols, &rows)
                };
                let e = minor_of(rr, cc)?;
                if !e.is_zero() {
                    small.push(e);
                    if let Some(pk) = coprime_or_unit(&small.iter().collect::<Vec<_>>(), s) {
                        found = Some(pk);
                        break 'outer;
                    }
                    if small.len() >= MAXIMAL_MINORS_LIMIT {
                        break 'outer;
                    }
                }
                if !next_subset(&mut cols, long) {
                    break;
                }
            }
            if !next_subset(&mut rows, r) {
                break;
            }
        }
        Some(found?)
    };
    let pr = &a.ring;
    let checks = vec![
        Check {
            property: format!("{r}×{r} minors computed"),
            ok: true,
            detail: format!(
                "all {} nonzero {r}×{r} minor(s) of A over {} ({side} {}), each by expansion",
                minors.len(),
                pr.name(),
                sets(&used)
            ),
        },
        Check {
            property: format!("d_{r} over Q(others)[{name}]"),
            ok: true,
            detail: format!(
                "d = {} (primitive part in {name} of their gcd over {}) divides each exactly; the first {k} quotients have gcd 1 in Z_p[{name}], p = {p}, at a point of the other symbols where the first keeps its degree in {name}",
                pr.format(&d),
                pr.name()
            ),
        },
        Check {
            property: format!("d_{} = 1", r - 1),
            ok: true,
            detail: match low {
                None => "d_0 = 1".to_string(),
                Some((0, _)) => format!("a nonzero {0}×{0} minor is free of {name}, a unit", r - 1),
                Some((p, k)) => format!(
                    "{k} nonzero {0}×{0} minors have gcd 1 in Z_p[{name}], p = {p}, at a point where the first keeps its degree in {name}",
                    r - 1
                ),
            },
        },
        Check {
            property: "invariant factors 1, …, 1, d".into(),
            ok: true,
            detail: format!("d_k = 1 for k < {r} and d_{r} ~ d: rank {r}"),
        },
    ];
    Some((Certificate { checks }, d))
}

/// At most this many (n−2)×(n−2) minors of A are tried by
/// [`certify_two_factors_several`] for `d_(n−2) = 1`.
pub const TWO_FACTOR_MINORS_LIMIT: usize = 64;

/// Certifies, for a square A with `A·B = c·I` over Q\[all\], that over
/// Q(others)\[s\] the invariant factors of A are 1, …, 1, g, c/g, where g is
/// the primitive part in s of the gcd of B's entries: the case
/// `d_(n−1) ≠ 1` that [`certify_last_factor_several`] declines (the
/// several-symbol analogue of `hermite_cert::certify_two_factors`, by
/// Jacobi's identity). With K = Q(others):
/// 1. `A·B = c·I` exactly with `c ≠ 0`: `B = c·A⁻¹`;
/// 2. g (primitive in s; 1 when the gcd is free of s) divides every entry
///    of B exactly over Q\[all\], and the quotients have gcd 1 over K\[s\] (images
///    in Z_p\[s\] at a point where the first keeps its degree in s, the
///    module text's step 2): the gcd of B's entries over K\[s\] is g;
/// 3. `c/det A ∈ K`: by Jacobi's identity a 2×2 minor of `A⁻¹` on rows I,
///    columns J is `±det A[J′, I′]/det A` (J′, I′ the complements), so the
///    2×2 minor m_B of B there is `±(c/det A)·c·M` with `M = det A[J′, I′]`
///    computed directly from A; `m_B·lc_s(c·M) = c·M·lc_s(m_B)` exactly over
///    Q\[all\] shows the ratio free of s. Hence over K\[s\] `c ~ det A` and
///    `B ~ adj A`, so `d_n ~ c` and `d_(n−1)` (the gcd of adj A's entries)
///    `~ g`;
/// 4. `d_(n−2) = 1`: some (n−2)×(n−2) minors of A (computed exactly, the
///    first one M of step 3) have gcd 1 over K\[s\] by the same image
///    argument (n = 2: `d_0 = 1`; not needed when g = 1);
/// 5. `c/g` and `(c/g)/g` are exact divisions over Q\[all\] (g is primitive
///    in s, so by Gauss's lemma divisibility over K\[s\] is exact division
///    here): `f_(n−1) = d_(n−1)/d_(n−2) ~ g` divides `f_n = d_n/d_(n−1) ~
///    c/g`, a consistency check on 1–4.
///
/// With g = 1 this certifies 1, …, 1, c where [`certify_last_factor_several`]
/// declines only because `deg_s c` is below the row/column degree bound
/// (step 3 above replaces its degree argument). Returns the certificate,
/// g and c/g; `None` whenever a step is not established (three or more
/// non-trivial factors, a B or c
/// that does not satisfy 1, a ratio c/det A depending on s).
pub fn certify_two_factors_several(
    a: &Matrix<PolyRing>,
    c: &MPoly,
    b: &Matrix<PolyRing>,
    s: usize,
) -> Option<(Certificate, MPoly, MPoly)> {
    let n = a.rows();
    if n < 2 || a.cols() != n || b.rows() != n || b.cols() != n || c.is_zero() {
        return None;
    }
    let nv = a.ring.nvars();
    let name = &a.ring.names[s];
    let pr = &a.ring;
    // 1.
    if !product_is_c_identity(a, c, b) {
        return None;
    }
    // 2.
    let entries: Vec<&MPoly> = b.entries().iter().filter(|e| !e.is_zero()).collect();
    let g0 = entries
        .iter()
        .fold(MPoly::zero(nv), |g, e| crate::algebra::gcd::gcd(&g, e));
    let g = if g0.degree_in(s).unwrap_or(0) == 0 {
        MPoly::one(nv)
    } else {
        crate::algebra::gcd::primitive_part_in(&g0, s).primitive_normal()
    };
    let unit_g = g.is_nonzero_constant();
    let quotients: Vec<MPoly> = entries
        .iter()
        .map(|e| e.div_exact(&g))
        .collect::<Option<_>>()?;
    let (p2, k2) = coprime_or_unit(&quotients.iter().collect::<Vec<_>>(), s)?;
    // 3 and 4: (n−2)×(n−2) minors M = det A[J′, I′] beside the 2×2 minors
    // of B on rows I, columns J.
    let lc = |e: &MPoly| e.coeffs_in(s).pop().unwrap_or_else(|| MPoly::zero(nv));
    let mut rows_b: Vec<usize> = vec![0, 1];
    let mut small: Vec<MPoly> = Vec::new();
    let mut jacobi: Option<(Vec<usize>, Vec<usize>)> = None;
    let mut low: Option<(u64, usize)> = None;
    'outer: loop {
        let mut cols_b: Vec<usize> = vec![0, 1];
        loop {
            let rows_a: Vec<usize> = (0..n).filter(|i| !cols_b.contains(i)).collect();
            let cols_a: Vec<usize> = (0..n).filter(|j| !rows_b.contains(j)).collect();
            let m = if n == 2 {
                MPoly::one(nv)
            } else {
                det_expanding_largest_row(&a.submatrix(&rows_a, &cols_a))?
            };
            if !m.is_zero() {
                if jacobi.is_none() {
                    let (b00, b01) = (b.get(rows_b[0], cols_b[0]), b.get(rows_b[0], cols_b[1]));
                    let (b10, b11) = (b.get(rows_b[1], cols_b[0]), b.get(rows_b[1], cols_b[1]));
                    let mb = &(b00 * b11) - &(b01 * b10);
                    let cm = c * &m;
                    if mb.is_zero() || &mb * &lc(&cm) != &cm * &lc(&mb) {
                        return None;
                    }
                    jacobi = Some((rows_b.clone(), cols_b.clone()));
                }
                small.push(m);
                if n == 2 || unit_g {
                    // d_(n−1) = 1 already: no (n−2)×(n−2) minors needed.
                    break 'outer;
                }
                if let Some(pk) = coprime_or_unit(&small.iter().collect::<Vec<_>>(), s) {
                    low = Some(pk);
                    break 'outer;
                }
                if small.len() >= TWO_FACTOR_MINORS_LIMIT {
                    return None;
                }
            }
            if !next_subset(&mut cols_b, n) {
                break;
            }
        }
        if !next_subset(&mut rows_b, n) {
            return None;
        }
    }
    let (ib, jb) = jacobi?;
    if n > 2 && !unit_g && low.is_none() {
        return None;
    }
    // 5.
    let last = c.div_exact(&g)?;
    last.div_exact(&g)?;
    let one_based = |v: &[usize]| {
        v.iter()
            .map(|i| (i + 1).to_string())
            .collect::<Vec<_>>()
            .join(", ")
    };
    let checks = vec![
        Check {
            property: "A·B = c·I".into(),
            ok: true,
            detail: format!(
                "holds exactly over {} for a polynomial B and c ≠ 0 ({} terms)",
                pr.name(),
                c.terms().len()
            ),
        },
        Check {
            property: format!("gcd of B's entries over Q(others)[{name}] is g"),
            ok: true,
            detail: format!(
                "g = {} (primitive part in {name} of their gcd over {}) divides each exactly; {}",
                pr.format(&g),
                pr.name(),
                if p2 == 0 {
                    format!("quotient {k2} is free of {name}, a unit")
                } else {
                    format!(
                        "the first {k2} quotients have gcd 1 in Z_p[{name}], p = {p2}, at a point of the other symbols where the first keeps its degree in {name}"
                    )
                }
            ),
        },
        Check {
            property: format!("c/det A is free of {name} (Jacobi)"),
            ok: true,
            detail: format!(
                "the 2×2 minor of B on rows {{{}}}, columns {{{}}} is ±(c/det A)·c·M with M the complementary minor of A (rows {{{}}}, columns {{{}}}), and it equals c·M times an element of Q(others) exactly over {}: c ~ det A and B ~ adj A over Q(others)[{name}]",
                one_based(&ib),
                one_based(&jb),
                one_based(&(0..n).filter(|i| !jb.contains(i)).collect::<Vec<_>>()),
                one_based(&(0..n).filter(|j| !ib.contains(j)).collect::<Vec<_>>()),
                pr.name()
            ),
        },
        Check {
            property: format!("d_{} = 1", n - 2),
            ok: true,
            detail: match low {
                None if unit_g => format!("d_{} = 1 already", n - 1),
                None => "d_0 = 1".to_string(),
                Some((0, _)) => format!(
                    "a nonzero {0}×{0} minor of A is free of {name}, a unit",
                    n - 2
                ),
                Some((p, k)) => format!(
                    "{k} nonzero {0}×{0} minors of A (by expansion) have gcd 1 in Z_p[{name}], p = {p}, at a point where the first keeps its degree in {name}",
                    n - 2
                ),
            },
        },
        if unit_g {
            Check {
                property: "invariant factors 1, …, 1, c".into(),
                ok: true,
                detail: format!("d_{} = 1 and d_{n} ~ c", n - 1),
            }
        } else {
            Check {
                property: "invariant factors 1, …, 1, g, c/g".into(),
                ok: true,
                detail: format!(
                    "d_{} = 1, d_{} ~ g, d_{n} ~ c; c/g and (c/g)/g are exact divisions over {}, so g divides c/g",
                    n - 2,
                    n - 1,
                    pr.name()
                ),
            }
        },
    ];
    Some((Certificate { checks }, g, last))
}

/// `coprime_in`, or `(0, i + 1)` when entry i is free of `s` (a unit).
fn coprime_or_unit(entries: &[&MPoly], s: usize) -> Option<(u64, usize)> {
    match entries.iter().position(|e| !e.contains_var(s)) {
        Some(i) => Some((0, i + 1)),
        None => coprime_in(entries, s),
    }
}

/// The next r-subset of 0..n in lexicographic order (false after the last).
fn next_subset(sub: &mut [usize], n: usize) -> bool {
    let r = sub.len();
    for i in (0..r).rev() {
        if sub[i] < n - r + i {
            sub[i] += 1;
            for j in i + 1..r {
                sub[j] = sub[j - 1] + 1;
            }
            return true;
        }
    }
    false
}

/// A lower bound on `deg_λ det A` (λ = symbol `s`): the degree of the
/// image of det A in Z_p\[λ\] at a point of the other symbols, det taken at
/// `N + 1` values of λ (N = [`degree_bound`]) and interpolated. Reduction
/// and evaluation form a ring map, which can lower degrees, never raise
/// them. The largest degree over a few primes and points; stops as soon as
/// it reaches `target`. Returns `(degree, p)`.
pub fn det_degree_lower_bound(
    a: &Matrix<PolyRing>,
    s: usize,
    target: usize,
) -> Option<(usize, u64)> {
    let n = a.rows();
    if n != a.cols() {
        return None;
    }
    let bound = degree_bound(a, s);
    let nv = a.ring.nvars();
    let mut pts = Points::new(0x5eed_0de9_0f00_0015);
    let mut best: Option<(usize, u64)> = None;
    for p in modular::primes().take(3) {
        if (bound as u64) + 1 >= p {
            return best;
        }
        let f = Fp::new(p);
        for _ in 0..2 {
            let point: Vec<u64> = (0..nv).map(|_| pts.next(f)).collect();
            let Some(img): Option<Vec<UP>> = a
                .entries()
                .iter()
                .map(|e| image_in(f, e, s, &point))
                .collect()
            else {
                break;
            };
            let xs: Vec<u64> = (0..=bound as u64).collect();
            let ys: Vec<u64> = xs
                .iter()
                .map(|&x| {
                    let m: Vec<u64> = img.iter().map(|e| modular::eval(f, e, x)).collect();
                    det_mod(f, m, n)
                })
                .collect();
            let d = modular::deg(&interpolate(f, &xs, &ys));
            if let Some(d) = d
                && best.is_none_or(|(b, _)| d > b)
            {
                best = Some((d, p));
            }
            if best.is_some_and(|(b, _)| b >= target) {
                return best;
            }
        }
    }
    best
}

/// det of the row-major n×n matrix `m` over Z_p (Gaussian elimination).
fn det_mod(f: Fp, mut m: Vec<u64>, n: usize) -> u64 {
    let mut det = 1u64;
    for k in 0..n {
        let Some(piv) = (k..n).find(|&i| m[i * n + k] != 0) else {
            return 0;
        };
        if piv != k {
            for j in 0..n {
                m.swap(piv * n + j, k * n + j);
            }
            det = f.neg(det);
        }
        let pk = m[k * n + k];
        det = f.mul(det, pk);
        let inv = f.inv(pk);
        for i in k + 1..n {
            let c = f.mul(m[i * n + k], inv);
            if c == 0 {
                continue;
            }
            for j in k..n {
                let t = f.mul(c, m[k * n + j]);
                m[i * n + j] = f.sub(m[i * n + j], t);
            }
        }
    }
    det
}

/// The polynomial of degree ≤ len − 1 through `(xs[i], ys[i])` over Z_p
/// (Newton's divided differences), lowest coefficient first, trimmed.
fn interpolate(f: Fp, xs: &[u64], ys: &[u64]) -> UP {
    let k = xs.len();
    let mut c = ys.to_vec();
    for j in 1..k {
        for i in (j..k).rev() {
            let num = f.sub(c[i], c[i - 1]);
            let den = f.sub(xs[i], xs[i - j]);
            c[i] = f.mul(num, f.inv(den));
        }
    }
    // Horner on the Newton form: p = c0 + (x − x0)(c1 + (x − x1)(…)).
    let mut out: UP = Vec::with_capacity(k);
    for i in (0..k).rev() {
        // out ← out·(x − x_i) + c_i
        let mut next = vec![0u64; out.len() + 1];
        for (t, &o) in out.iter().enumerate() {
            next[t + 1] = f.add(next[t + 1], o);
            next[t] = f.sub(next[t], f.mul(o, xs[i]));
        }
        next[0] = f.add(next[0], c[i]);
        out = next;
    }
    modular::trim(out)
}

/// The entries of `line` (over K[λ]) times the lcm of their
/// denominators, as polynomials over Q[all] (λ = symbol `s`).
pub(super) fn cleared_line(line: &[&UPoly<RatFunc>], s: usize, nv: usize) -> Vec<MPoly> {
    scaled_line(line, s, nv).1
}

/// `(l, l·line)`: the lcm `l` of the denominators of `line` and the
/// entries of [`cleared_line`].
fn scaled_line(line: &[&UPoly<RatFunc>], s: usize, nv: usize) -> (MPoly, Vec<MPoly>) {
    let mut l = MPoly::one(nv);
    for c in line.iter().flat_map(|e| e.0.iter()) {
        // A line's entries often share one denominator: no lcm for it.
        if !c.is_polynomial() && c.den() != &l {
            l = lcm(&l, c.den());
        }
    }
    let cleared = line
        .iter()
        .map(|e| {
            let cs: Vec<MPoly> =
                e.0.iter()
                    .map(|c| c.num() * &l.div_exact(c.den()).expect("the lcm of the denominators"))
                    .collect();
            MPoly::from_coeffs_in(s, &cs, nv)
        })
        .collect();
    (l, cleared)
}

/// det of a square matrix over Q\[all\] by expansion along its row with the
/// most terms, the minors by fraction-free elimination: a transform whose
/// rows differ greatly in size (the row of a Bezout step) never enters an
/// exact division. `None` if not square.
pub fn det_expanding_largest_row(m: &Matrix<PolyRing>) -> Option<MPoly> {
    let n = m.rows();
    if m.cols() != n {
        return None;
    }
    if n <= 2 {
        return m.det();
    }
    let size = |i: usize| m.row(i).iter().map(|e| e.terms().len()).sum::<usize>();
    let r = (0..n).max_by_key(|&i| size(i))?;
    let rows: Vec<usize> = (0..n).filter(|&i| i != r).collect();
    let mut acc = MPoly::zero(m.ring.nvars());
    for j in 0..n {
        let e = m.get(r, j);
        if e.is_zero() {
            continue;
        }
        let cols: Vec<usize> = (0..n).filter(|&c| c != j).collect();
        let minor = m.submatrix(&rows, &cols).det()?;
        let t = e * &minor;
        acc = if (r + j) % 2 == 0 {
            &acc + &t
        } else {
            &acc - &t
        };
    }
    Some(acc)
}

/// Whether `U·A·V = D` over K\[λ\] (λ = symbol `s`), evaluated over Q\[all\]
/// with each row i of U cleared by δ_i, each column j of V by ε_j and
/// each entry of D by γ_ij (all in Q\[others\]): `U′ = diag(δ)·U`, `V′ =
/// V·diag(ε)`, and `U·A·V = D` ⇔ `γ_ij·(U′·A·V′)_ij = δ_i·ε_j·D̃_ij` for
/// all i, j. The same statement as clearing whole matrices, with far
/// smaller scales.
pub fn product_by_lines(
    a: &Matrix<PolyRing>,
    s: usize,
    [u, d, v]: [&Matrix<UPolyRing<RatFuncField>>; 3],
) -> bool {
    let (m, n) = (a.rows(), a.cols());
    let nv = a.ring.nvars();
    if u.rows() != m || u.cols() != m || v.rows() != n || v.cols() != n {
        return false;
    }
    if d.rows() != m || d.cols() != n {
        return false;
    }
    let rows: Vec<(MPoly, Vec<MPoly>)> = (0..m)
        .map(|i| {
            let line: Vec<&UPoly<RatFunc>> = (0..m).map(|j| u.get(i, j)).collect();
            scaled_line(&line, s, nv)
        })
        .collect();
    let cols: Vec<(MPoly, Vec<MPoly>)> = (0..n)
        .map(|j| {
            let line: Vec<&UPoly<RatFunc>> = (0..n).map(|i| v.get(i, j)).collect();
            scaled_line(&line, s, nv)
        })
        .collect();
    // U′·A, row by row.
    let ua: Vec<Vec<MPoly>> = rows
        .iter()
        .map(|(_, r)| {
            (0..n)
                .map(|j| {
                    r.iter()
                        .enumerate()
                        .filter(|(k, x)| !x.is_zero() && !a.get(*k, j).is_zero())
                        .fold(MPoly::zero(nv), |acc, (k, x)| &acc + &(x * a.get(k, j)))
                })
                .collect()
        })
        .collect();
    for (i, (di, _)) in rows.iter().enumerate() {
        for (j, (ej, c)) in cols.iter().enumerate() {
            let x = ua[i]
                .iter()
                .zip(c)
                .filter(|(p, q)| !p.is_zero() && !q.is_zero())
                .fold(MPoly::zero(nv), |acc, (p, q)| &acc + &(p * q));
            let dij = d.get(i, j);
            if dij.0.is_empty() {
                if !x.is_zero() {
                    return false;
                }
                continue;
            }
            let (g, mut dt) = scaled_line(&[dij], s, nv);
            let dt = dt.remove(0);
            if &g * &x != &(di * ej) * &dt {
                return false;
            }
        }
    }
    true
}

/// Certifies a Smith decomposition `U·A·V = D` over K\[λ\], K = Q(others), λ
/// the symbol with index `s`, without inverse products (`a` over Q\[all\],
/// `ap` the same matrix over K\[λ\]; the product is evaluated by
/// [`product_by_lines`]):
/// 1. `U·A·V = D` exactly, D diagonal with monic entries, zeros last, each
///    nonzero entry dividing the next (pseudo-remainder in λ over Q\[all\]
///    of the cleared entries, zero exactly when the division holds over
///    K\[λ\]);
/// 2. for a square A with no zero on D's diagonal: `deg_λ det A ≥ Σ deg_λ
///    D_ii` from the image of det A at a point mod p (a ring map cannot
///    raise the degree). Then `det U·det A·det V = det D ≠ 0` in the domain
///    K\[λ\], so `deg det U + deg det V ≤ 0`: both determinants are nonzero
///    elements of K, units of K\[λ\];
/// 3. otherwise: U with each row and V with each column cleared of
///    denominators (by an element of Q\[others\]) have determinants (fraction
///    -free elimination over Q\[all\]) that are nonzero and free of λ.
pub fn certify_principal_degrees(
    a: &Matrix<PolyRing>,
    s: usize,
    ap: &Matrix<UPolyRing<RatFuncField>>,
    [u, d, v]: [&Matrix<UPolyRing<RatFuncField>>; 3],
) -> Certificate {
    let (m, n) = (a.rows(), a.cols());
    let nv = a.ring.nvars();
    let kr = &ap.ring;
    let mut checks = Vec::new();
    let mut push = |property: &str, ok: bool, detail: String| {
        checks.push(Check {
            property: property.to_string(),
            ok,
            detail,
        })
    };
    let shapes = ap.rows() == m
        && ap.cols() == n
        && (u.rows(), u.cols()) == (m, m)
        && (d.rows(), d.cols()) == (m, n)
        && (v.rows(), v.cols()) == (n, n);
    push(
        "shapes",
        shapes,
        format!("A and D are {m}×{n}, U is {m}×{m}, V is {n}×{n}"),
    );
    if !shapes {
        return Certificate { checks };
    }
    let diag = d.diagonal();
    let rank = diag.iter().take_while(|e| !kr.is_zero(e)).count();
    let diag_ok = d.is_diagonal();
    let zeros_last = diag[rank..].iter().all(|e| kr.is_zero(e));
    let normalised = diag[..rank].iter().all(|e| kr.normalize(e) == *e);
    let total: usize = diag.iter().map(|e| e.degree().unwrap_or(0)).sum();
    let full = m == n && rank == n;
    // Degrees first: the product is evaluated only if they can conclude.
    let lower = if full && diag_ok {
        det_degree_lower_bound(a, s, total)
    } else {
        None
    };
    let degrees = lower.is_some_and(|(l, _)| l >= total);
    let structure = diag_ok && zeros_last && normalised;
    let prod = (degrees || !full) && structure && product_by_lines(a, s, [u, d, v]);
    push(
        "U·A·V = D",
        prod,
        if prod {
            "holds exactly (denominators cleared, compared over Q[all])"
        } else {
            "not established"
        }
        .to_string(),
    );
    push(
        "D diagonal",
        diag_ok,
        if diag_ok {
            "yes"
        } else {
            "D has a nonzero off-diagonal entry"
        }
        .to_string(),
    );
    let name = &a.ring.names[s];
    if full {
        let unimod = prod && degrees;
        let why = match lower {
            Some((l, p)) => format!(
                "det U·det A·det V = det D ≠ 0 in {}, and deg_{name} det A ≥ {l} (its image at a point of the other symbols mod p = {p}) ≥ Σ deg_{name} D_ii = {total}: so deg det U + deg det V ≤ 0",
                kr.name()
            ),
            None => "no degree bound for det A".to_string(),
        };
        for nm in ["U", "V"] {
            push(
                &format!("{nm} unimodular"),
                unimod,
                if unimod {
                    format!(
                        "{why}; det {nm} is a nonzero element of {}, a unit",
                        kr.k.name()
                    )
                } else {
                    format!("not established ({why})")
                },
            );
        }
    } else {
        let ring = a.ring.clone();
        let u2 = Matrix::new(
            ring.clone(),
            m,
            m,
            (0..m)
                .flat_map(|i| cleared_line(&(0..m).map(|j| u.get(i, j)).collect::<Vec<_>>(), s, nv))
                .collect(),
        );
        let mut v2 = Matrix::zeros(ring, n, n);
        for j in 0..n {
            let col = cleared_line(&(0..n).map(|i| v.get(i, j)).collect::<Vec<_>>(), s, nv);
            for (i, e) in col.into_iter().enumerate() {
                v2.set(i, j, e);
            }
        }
        for (nm, mat) in [("U", &u2), ("V", &v2)] {
            let det = if prod {
                det_expanding_largest_row(mat)
            } else {
                None
            };
            let ok = det
                .as_ref()
                .is_some_and(|x| !x.is_zero() && !x.contains_var(s));
            push(
                &format!("{nm} unimodular"),
                ok,
                match det {
                    Some(x) => format!(
                        "{nm}′ ({nm} with each {} cleared of denominators in Q[others]) has det {} over Q[all]{}",
                        if nm == "U" { "row" } else { "column" },
                        a.ring.format(&x),
                        if ok {
                            format!(
                                ", a nonzero element of Q[others]: det {nm} is a unit of {}",
                                kr.name()
                            )
                        } else {
                            ", not a nonzero element of Q[others]".to_string()
                        }
                    ),
                    None => "not established".to_string(),
                },
            );
        }
    }
    push(
        "zeros last",
        zeros_last,
        format!("{rank} nonzero invariant factor(s), then zeros"),
    );
    push(
        "invariant factors normalised",
        normalised,
        "each nonzero diagonal entry is monic in the principal symbol".to_string(),
    );
    let cleared: Vec<MPoly> = diag[..rank]
        .iter()
        .map(|e| cleared_line(&[e], s, nv).remove(0))
        .collect();
    let div_ok = cleared
        .windows(2)
        .all(|w| crate::algebra::gcd::prem(&w[1], &w[0], s).is_zero());
    push(
        "divisibility f1 | f2 | …",
        div_ok,
        if div_ok {
            format!(
                "each invariant factor divides the next (pseudo-remainder in {name} zero over Q[all])"
            )
        } else {
            "not established".to_string()
        },
    );
    Certificate { checks }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::rational::qi;
    use crate::algebra::smith::several::det_adj_several;

    fn ring2() -> PolyRing {
        PolyRing::new(vec!["x".into(), "y".into()])
    }

    /// `L·diag(diag)·R` with L unit lower and R unit upper triangular
    /// (polynomial entries): unimodular over Q[x, y].
    fn planted(diag: &[MPoly]) -> Matrix<PolyRing> {
        let n = diag.len();
        let (x, y) = (MPoly::var(0, 2), MPoly::var(1, 2));
        let one = MPoly::one(2);
        let entry = |i: usize, j: usize| match (i + 2 * j) % 4 {
            0 => &x + &one,
            1 => y.clone(),
            2 => &(&x * &y) - &one,
            _ => one.scale(&qi(2)),
        };
        let mut l = Matrix::identity(ring2(), n);
        let mut r = Matrix::identity(ring2(), n);
        for i in 0..n {
            for j in 0..i {
                l.set(i, j, entry(i, j));
                r.set(j, i, entry(j, i + 1));
            }
        }
        let mut d = Matrix::zeros(ring2(), n, n);
        for (i, e) in diag.iter().enumerate() {
            d.set(i, i, e.clone());
        }
        l.mul(&d).and_then(|ld| ld.mul(&r)).expect("square")
    }

    /// Whether `p` and `q` are associates over Q(others)[s] (same primitive
    /// part in s up to a rational constant).
    fn associates_in(p: &MPoly, q: &MPoly, s: usize) -> bool {
        use crate::algebra::gcd::primitive_part_in;
        let (pp, qq) = (primitive_part_in(p, s), primitive_part_in(q, s));
        pp.div_exact(&qq).is_some_and(|u| u.is_nonzero_constant())
    }

    #[test]
    fn two_factors_of_planted_inputs_agree_with_the_determinantal_divisors() {
        use crate::algebra::smith::divisors::determinantal_divisors;
        let (x, y) = (MPoly::var(0, 2), MPoly::var(1, 2));
        let one = MPoly::one(2);
        let (xm, xp) = (&x - &y, &x + &y);
        for n in [2, 3, 4] {
            let mut diag = vec![one.clone(); n - 2];
            diag.push(xm.clone());
            diag.push(&xm * &xp);
            let a = planted(&diag);
            let (c, b) = det_adj_several(&a).expect("nonsingular");
            // d_(n−1) = x − y ≠ 1: the one-factor certificate declines.
            assert!(!certify_last_factor_several(&a, &c, &b, &[0]).verified());
            let dv = determinantal_divisors(&a, 1 << 20).expect("few minors");
            for s in [0, 1] {
                let (cert, g, last) =
                    certify_two_factors_several(&a, &c, &b, s).expect("two factors");
                assert!(cert.verified(), "n = {n}, s = {s}");
                // Against the minors over Q[x, y] (their primitive parts in s
                // are the divisors over Q(others)[s], Gauss's lemma).
                assert!(associates_in(&g, &dv.invariant[n - 2], s), "n = {n}");
                assert!(associates_in(&last, &dv.invariant[n - 1], s), "n = {n}");
                assert!(associates_in(&g, &xm, s) && associates_in(&last, &(&xm * &xp), s));
                for f in &dv.invariant[..n - 2] {
                    assert!(f.is_nonzero_constant());
                }
            }
            // Tampering: a changed entry of B or a changed c fails A·B = c·I.
            let mut bad = b.clone();
            bad.set(0, 0, b.get(0, 0) + &one);
            assert!(certify_two_factors_several(&a, &c, &bad, 0).is_none());
            assert!(certify_two_factors_several(&a, &(&c * &xp), &b, 0).is_none());
            // B and c both times (x + 2): A·B = c·I still holds and the gcd of
            // B gains x + 2, but c/det A depends on x: Jacobi's check refuses
            // (over Q(x)[y] the factor is a unit and the statement stands).
            let k = &x + &one.scale(&qi(2));
            let bk = b.map(ring2(), |e| e * &k);
            let ck = &c * &k;
            assert!(certify_two_factors_several(&a, &ck, &bk, 0).is_none());
            let (cert, g, _) = certify_two_factors_several(&a, &ck, &bk, 1).expect("unit");
            assert!(cert.verified() && associates_in(&g, &xm, 1));
        }
        // Three non-trivial factors: d_(n−2) = x − y, declined.
        let a = planted(&[one.clone(), xm.clone(), xm.clone(), &xm * &xp]);
        let (c, b) = det_adj_several(&a).expect("nonsingular");
        for s in [0, 1] {
            assert!(certify_two_factors_several(&a, &c, &b, s).is_none());
        }
    }

    #[test]
    fn two_factor_route_covers_a_det_below_the_degree_bound() {
        // [[x, x + 1], [x, x + 2]]: det x, degree bound 2 in x, so the
        // one-factor certificate declines; gcd(adj) = 1, factors 1, x.
        let x = MPoly::var(0, 2);
        let one = MPoly::one(2);
        let a = Matrix::new(
            ring2(),
            2,
            2,
            vec![x.clone(), &x + &one, x.clone(), &x + &one.scale(&qi(2))],
        );
        let (c, b) = det_adj_several(&a).expect("nonsingular");
        assert!(!certify_last_factor_several(&a, &c, &b, &[0]).verified());
        let (cert, g, last) = certify_two_factors_several(&a, &c, &b, 0).expect("1, x");
        assert!(cert.verified());
        assert!(g.is_nonzero_constant());
        assert!(associates_in(&last, &x, 0));
    }

    #[test]
    fn maximal_minors_give_the_last_factor_of_non_square_inputs() {
        let (x, y) = (MPoly::var(0, 2), MPoly::var(1, 2));
        let one = MPoly::one(2);
        // [[x, y, 1], [y, x, x]]: minors x² − y², x² − y, xy − x; coprime
        // over Q(y)[x]: invariant factors 1, 1.
        let a = Matrix::new(
            ring2(),
            2,
            3,
            vec![
                x.clone(),
                y.clone(),
                one.clone(),
                y.clone(),
                x.clone(),
                x.clone(),
            ],
        );
        let (cert, d) = certify_maximal_minors(&a, 0).expect("coprime minors");
        assert!(cert.verified() && d.is_nonzero_constant());
        // The transpose: the same over rows.
        let t = Matrix::new(
            ring2(),
            3,
            2,
            vec![
                x.clone(),
                y.clone(),
                y.clone(),
                x.clone(),
                one.clone(),
                x.clone(),
            ],
        );
        let (_, d) = certify_maximal_minors(&t, 0).expect("coprime minors");
        assert!(d.is_nonzero_constant());
        // Both rows times (x − y) in the second column's and third's minors:
        // [[x, y(x − y), x − y], [1, x(x − y), 0]] has minors divisible by
        // x − y and entries with gcd 1: invariant factors 1, x − y over
        // Q(y)[x]; over Q(x)[y] the same (y − x up to a unit).
        let xy = &x - &y;
        let b = Matrix::new(
            ring2(),
            2,
            3,
            vec![
                x.clone(),
                &y * &xy,
                xy.clone(),
                one.clone(),
                &x * &xy,
                MPoly::zero(2),
            ],
        );
        let (cert, d) = certify_maximal_minors(&b, 0).expect("established");
        assert!(cert.verified());
        assert_eq!(d.degree_in(0), Some(1));
        assert!(d.div_exact(&xy).is_some_and(|q| q.is_nonzero_constant()));
        let (_, d) = certify_maximal_minors(&b, 1).expect("established");
        assert!(d.div_exact(&xy).is_some_and(|q| q.is_nonzero_constant()));
        // Square or rank-deficient inputs are not treated.
        let sq = Matrix::new(
            ring2(),
            2,
            2,
            vec![x.clone(), y.clone(), y.clone(), x.clone()],
        );
        assert!(certify_maximal_minors(&sq, 0).is_none());
        let low = Matrix::new(
            ring2(),
            2,
            3,
            vec![
                x.clone(),
                y.clone(),
                one.clone(),
                x.clone(),
                y.clone(),
                one.clone(),
            ],
        );
        assert!(certify_maximal_minors(&low, 0).is_none());
    }

    #[test]
    fn generic_matrix_is_certified_and_tampering_is_caught() {
        let (x, y) = (MPoly::var(0, 2), MPoly::var(1, 2));
        let one = MPoly::one(2);
        let a = Matrix::new(
            ring2(),
            2,
            2,
            vec![&x + &y, one.clone(), &x * &y - &one, &y + &x.scale(&qi(2))],
        );
        let (c, b) = det_adj_several(&a).expect("nonsingular");
        assert!(certify_last_factor_several(&a, &c, &b, &[0, 1]).verified());
        assert!(certify_last_factor_several(&a, &c, &b, &[1]).verified());
        // c and B multiplied by a common factor keep A·B = c·I but lose the
        // coprimality of B's entries.
        let t = &x + &one;
        let bt = b.map(ring2(), |e| e * &t);
        let ct = &c * &t;
        let cert = certify_last_factor_several(&a, &ct, &bt, &[0, 1]);
        assert!(!cert.verified());
        // [[x + y, 1], [x·y − 1, y]] has det y² + 1: the invariant factors
        // over Q(y)[x] are 1, 1, but deg_x c = 0 < 2 leaves it unproved.
        let a2 = Matrix::new(
            ring2(),
            2,
            2,
            vec![&x + &y, one.clone(), &x * &y - &one, y.clone()],
        );
        let (c2, b2) = det_adj_several(&a2).expect("nonsingular");
        assert!(!certify_last_factor_several(&a2, &c2, &b2, &[0]).verified());
        assert!(certify_last_factor_several(&a2, &c2, &b2, &[1]).verified());
        // A wrong c fails the product.
        assert!(!certify_last_factor_several(&a, &(&c + &one), &b, &[0]).verified());
    }

    #[test]
    fn diag_x_x_is_rejected_by_the_degree_check() {
        // A = diag(x, x): B = I, c = x satisfy A·B = c·I with coprime B,
        // but d_1 = x; only deg_x c = 1 < 2 exposes it.
        let x = MPoly::var(0, 2);
        let z = MPoly::zero(2);
        let one = MPoly::one(2);
        let a = Matrix::new(
            ring2(),
            2,
            2,
            vec![x.clone(), z.clone(), z.clone(), x.clone()],
        );
        let b = Matrix::new(ring2(), 2, 2, vec![one.clone(), z.clone(), z, one]);
        let cert = certify_last_factor_several(&a, &x, &b, &[0, 1]);
        assert!(!cert.verified());
        assert!(cert.failures().any(|f| f.property.starts_with("deg_x")));
        assert!(!certify_last_factor_several(&a, &x, &b, &[0]).verified());
    }

    use crate::algebra::smith::modes::to_principal as principal;

    #[test]
    fn principal_degrees_certify_the_fraction_free_route_and_catch_a_non_unit() {
        let (x, y) = (MPoly::var(0, 2), MPoly::var(1, 2));
        let one = MPoly::one(2);
        let a = Matrix::new(
            ring2(),
            2,
            2,
            vec![&x * &y + &one, &x - &y, y.pow(2), &x * &y.scale(&qi(3))],
        );
        let ap = principal(&a, 1);
        let ff =
            crate::algebra::smith::fraction_free::eliminate_fraction_free(&a, 1).expect("finishes");
        let [u, d, v] =
            crate::algebra::smith::fraction_free::over_k(&ff, &ap.ring, 1).expect("units");
        assert!(certify_principal_degrees(&a, 1, &ap, [&u, &d, &v]).verified());
        // A changed entry of U breaks the product.
        let mut u2 = u.clone();
        let e = ap.ring.add(u2.get(0, 0), &ap.ring.one());
        u2.set(0, 0, e);
        let cert = certify_principal_degrees(&a, 1, &ap, [&u2, &d, &v]);
        assert!(cert.failures().any(|c| c.property == "U·A·V = D"));
        // A = I, U = diag(y, y), V = I, D = diag(y, y): the product, the
        // normal form and the divisibility hold, but det U = y² is not a
        // unit; only deg_y det A = 0 < 2 exposes it.
        let z = MPoly::zero(2);
        let i2 = Matrix::new(
            ring2(),
            2,
            2,
            vec![one.clone(), z.clone(), z.clone(), one.clone()],
        );
        let yy = Matrix::new(ring2(), 2, 2, vec![y.clone(), z.clone(), z, y.clone()]);
        let (ip, yp) = (principal(&i2, 1), principal(&yy, 1));
        let cert = certify_principal_degrees(&i2, 1, &ip, [&yp, &yp, &ip]);
        assert!(!cert.verified());
        assert!(cert.failures().any(|c| c.property == "U unimodular"));
        // The singular route: [[x, y], [x·y, y²]] has rank 1 over Q(x)[y].
        let s = Matrix::new(ring2(), 2, 2, vec![x.clone(), y.clone(), &x * &y, y.pow(2)]);
        let sp = principal(&s, 1);
        let ff =
            crate::algebra::smith::fraction_free::eliminate_fraction_free(&s, 1).expect("finishes");
        let [u, d, v] =
            crate::algebra::smith::fraction_free::over_k(&ff, &sp.ring, 1).expect("units");
        let cert = certify_principal_degrees(&s, 1, &sp, [&u, &d, &v]);
        assert!(cert.verified(), "{:?}", cert.failures().collect::<Vec<_>>());
        assert!(
            cert.checks
                .iter()
                .any(|c| c.detail.contains("cleared of denominators"))
        );
    }
}
