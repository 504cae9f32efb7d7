//! Invariant factors of a non-square or singular A over Q\[x\] (m×n, rank r)
//! in the generic case, all r nonzero factors equal to 1, certified
//! without transforms and without any elimination over Q\[x\]. This is the
//! D-alone route of the size policy for inputs that are not square and
//! nonsingular (random rectangular matrices, rank-deficient products
//! B·C). The checks ([`certify_unit_factors`]), on `Ã = Δ·A` (Δ the rows'
//! denominator lcms, a unit of Q: rank and determinantal divisors are
//! those of A):
//!
//! 1. Pivots: Gaussian elimination of `Ã(x₀)` modulo a word prime p gives
//!    rows I and columns J (r of each) with `Ã(x₀)[I, J]` nonsingular mod p.
//!    This only chooses; nothing below trusts it.
//! 2. `rank A ≥ r` and `d_r(A) = 1`: the r-minor `M₁ = det Ã[I, J]` is
//!    computed modulo p from its values at `N₁ + 1` points (N₁ its row/column
//!    degree bound) and has degree exactly N₁ modulo p, so `M₁ ≠ 0` and p
//!    divides no leading coefficient of the primitive gcd g over Z of the
//!    r-minors (g divides M₁, Gauss's lemma). A few further r-minors
//!    (one column or row of (I, J) exchanged) are computed the same way; when
//!    the gcd of all of them modulo p is a constant, `deg g = 0`, so
//!    `d_r(A) = 1` and `f_1 = … = f_r = 1` (each `f_i` divides `d_r`).
//! 3. `rank A ≤ r` (only when `r < min(m, n)`): `det Ã[I, J]` and
//!    `adj Ã[I, J]` exactly ([`super::detadj::det_adj`], images and CRT
//!    beyond Hadamard's bound); for each column j ∉ J the vector k_j with
//!    `k_j[J] = −adj·Ã[I, j]`, `k_j[j] = det`, zero elsewhere. `A·K = 0` is
//!    checked exactly over Z\[x\], and K's rows outside J are `det·I` with
//!    `det ≠ 0` (step 2), so K has rank `n − r` and A's nullity is at least
//!    that.
//!
//! So `D = [[I_r, 0], [0, 0]]` (m×n). Anything else (a nonconstant gcd of
//! the minors tried, a degree lost modulo p, a failed product) returns
//! `None` and the caller takes another route. This module must not print
//! or choose modes.

use super::certify::{Certificate, mul_cleared};
use super::minors_cert::{bound, integer_rows, minor_mod, reduce_all};
use crate::algebra::matrix::Matrix;
use crate::algebra::modular::{self, Fp};
use crate::algebra::qx::{QPoly, QxRing};
use crate::algebra::ring::Ring;
use num_bigint::BigInt;

/// The algorithm's description in reports.
pub const ALGORITHM: &str = "rank and pivots of A(x₀) modulo a word prime; d_r = 1 from r-minors coprime modulo a prime that keeps the first one's degree; rank ≤ r from an exact kernel A·K = 0 (K from det and adj of the pivot block, by images and CRT); no elimination over Q[x]";

/// How many further r-minors are tried before giving up on `d_r = 1`.
const EXTRA_MINORS: usize = 8;

/// Rows and columns of a nonsingular maximal block of the m×n matrix `v`
/// (row-major) mod p, by elimination with row search per column.
fn pivots(f: Fp, mut v: Vec<u64>, m: usize, n: usize) -> (Vec<usize>, Vec<usize>) {
    let mut rows_used = vec![false; m];
    let (mut ri, mut cj) = (Vec::new(), Vec::new());
    for j in 0..n {
        let Some(p) = (0..m).find(|&i| !rows_used[i] && v[i * n + j] != 0) else {
            continue;
        };
        rows_used[p] = true;
        ri.push(p);
        cj.push(j);
        let inv = f.inv(v[p * n + j]);
        for i in 0..m {
            if rows_used[i] || v[i * n + j] == 0 {
                continue;
            }
            let q = f.mul(v[i * n + j], inv);
            for k in j..n {
                let t = f.mul(q, v[p * n + k]);
                v[i * n + k] = f.sub(v[i * n + k], t);
            }
        }
    }
    let mut order: Vec<usize> = (0..ri.len()).collect();
    order.sort_by_key(|&k| ri[k]);
    // Rows sorted, columns kept in the pairing (the minor is the same up to sign).
    let rows = order.iter().map(|&k| ri[k]).collect();
    (rows, cj)
}

/// The certificate of the module documentation and the rank r, or `None`
/// (square and nonsingular, zero, constant, or a check that does not hold).
pub fn certify_unit_factors(a: &Matrix<QxRing>) -> Option<(Certificate, usize)> {
    let (m, n) = (a.rows(), a.cols());
    if m == 0 || n == 0 || a.entries().iter().all(|e| e.degree().unwrap_or(0) == 0) {
        return None;
    }
    let at = integer_rows(a);
    let p0 = modular::primes().next()?;
    let f0 = Fp::new(p0);
    let img = reduce_all(f0, &at);
    // 1. Pivots at a point away from small integers.
    let x0 = 1_000_003 % p0;
    let vals: Vec<u64> = img
        .iter()
        .flat_map(|row| row.iter().map(|p| modular::eval(f0, p, x0)))
        .collect();
    let (rows, cols) = pivots(f0, vals, m, n);
    let r = rows.len();
    if r == 0 || (r == m && r == n) {
        return None;
    }
    // 2. d_r = 1 from M₁ and a few exchanged minors.
    let n1 = bound(&at, &rows, &cols);
    let m1 = minor_mod(f0, &img, &rows, &cols, n1);
    if modular::deg(&m1) != Some(n1) {
        return None;
    }
    let mut g = m1;
    let mut tried = Vec::new();
    let other_cols: Vec<usize> = (0..n).filter(|j| !cols.contains(j)).collect();
    let other_rows: Vec<usize> = (0..m).filter(|i| !rows.contains(i)).collect();
    let mut candidates: Vec<(Vec<usize>, Vec<usize>)> = Vec::new();
    for t in 0..EXTRA_MINORS {
        if !other_cols.is_empty() {
            let mut c = cols.clone();
            c[r - 1 - (t / other_cols.len()) % r] = other_cols[t % other_cols.len()];
            candidates.push((rows.clone(), c));
        }
        if !other_rows.is_empty() {
            let mut rr = rows.clone();
            rr[r - 1 - (t / other_rows.len()) % r] = other_rows[t % other_rows.len()];
            candidates.push((rr, cols.clone()));
        }
    }
    for (ri, cj) in candidates {
        if modular::deg(&g) == Some(0) {
            break;
        }
        let nb = bound(&at, &ri, &cj);
        let mk = minor_mod(f0, &img, &ri, &cj, nb);
        if !mk.is_empty() {
            g = modular::gcd(f0, &g, &mk);
            tried.push((ri, cj));
        }
    }
    if modular::deg(&g) != Some(0) {
        return None;
    }
    let mut cert = Certificate { checks: Vec::new() };
    let one_based = |v: &[usize]| {
        v.iter()
            .map(|i| (i + 1).to_string())
            .collect::<Vec<_>>()
            .join(",")
    };
    cert.push(
        "rank A ≥ r and d_r(A) = 1",
        true,
        format!(
            "r = {r}: the r-minor on rows {} and columns {} has degree {n1} (its degree bound) modulo p = {p0}, so it is nonzero and p keeps the degree of the gcd of the r-minors; with {} further r-minors its gcd modulo p is 1, so d_r(A) = 1",
            one_based(&rows),
            one_based(&cols),
            tried.len()
        ),
    );
    // 3. rank ≤ r from an exact kernel.
    if r < m.min(n) {
        let sub: Vec<Vec<Vec<BigInt>>> = rows
            .iter()
            .map(|&i| cols.iter().map(|&j| at[i][j].clone()).collect())
            .collect();
        let (det, adj) = super::detadj::det_adj(&sub, n1)?;
        let ring = &a.ring;
        let q = |c: &Vec<BigInt>| QPoly::from_ints(c.clone());
        let det_q = q(&det);
        if det_q.is_zero() {
            return None;
        }
        let mut k = Matrix::zeros(ring.clone(), n, other_cols.len());
        for (t, &j) in other_cols.iter().enumerate() {
            for (b, &cb) in cols.iter().enumerate() {
                let terms: Vec<(QPoly, QPoly)> = rows
                    .iter()
                    .enumerate()
                    .map(|(ai, &i)| (q(&adj[b][ai]), q(&at[i][j])))
                    .collect();
                let s = ring.dot(&mut terms.iter().map(|(x, y)| (x, y)));
                k.set(cb, t, ring.neg(&s));
            }
            k.set(j, t, det_q.clone());
        }
        let prod = mul_cleared(a, &k).or_else(|| a.mul(&k))?;
        let zero = prod.entries().iter().all(|e| e.is_zero());
        cert.push(
            "rank A ≤ r",
            zero,
            format!(
                "A·K = 0 exactly for the {n}×{} kernel K built from det and adj of the pivot block (det of degree {}); K's rows outside the pivot columns are det·I, so K has rank {}",
                n - r,
                det_q.degree().unwrap_or(0),
                n - r
            ),
        );
        if !zero {
            return None;
        }
    }
    cert.push(
        "invariant factors",
        true,
        format!("rank {r} and d_r = 1: f_1 = … = f_{r} = 1, the other diagonal entries of D zero"),
    );
    Some((cert, r))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::smith::SmithDecomposition;

    fn seeded(m: usize, n: usize, d: usize, seed: u64) -> Matrix<QxRing> {
        let mut s = seed;
        let mut next = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            BigInt::from(((s >> 33) % 19) as i64 - 9)
        };
        let data: Vec<QPoly> = (0..m * n)
            .map(|_| QPoly::from_ints((0..=d).map(|_| next()).collect()))
            .collect();
        Matrix::new(QxRing::new("x"), m, n, data)
    }

    fn elimination_rank_and_units(a: &Matrix<QxRing>) -> (usize, bool) {
        let f = SmithDecomposition::new(a).invariant_factors();
        let r = &a.ring;
        (f.len(), f.iter().all(|e| r.is_one(e)))
    }

    #[test]
    fn rectangular_inputs_agree_with_the_elimination() {
        let mut seen = 0;
        for (m, n, seed) in [(4, 7, 1), (7, 4, 2), (5, 6, 3), (6, 5, 4)] {
            let a = seeded(m, n, 1, seed);
            let (cert, r) = certify_unit_factors(&a).expect("generic rectangular input");
            assert!(cert.verified(), "{cert:#?}");
            assert_eq!((r, true), elimination_rank_and_units(&a));
            seen += 1;
        }
        assert_eq!(seen, 4);
    }

    #[test]
    fn rank_deficient_products_agree_with_the_elimination() {
        for (n, k, seed) in [(6, 4, 1), (7, 5, 2), (5, 2, 3)] {
            let b = seeded(n, k, 1, seed);
            let c = seeded(k, n, 1, seed + 100);
            let a = b.mul(&c).unwrap();
            let (cert, r) = certify_unit_factors(&a).expect("generic product");
            assert!(cert.verified(), "{cert:#?}");
            assert_eq!(r, k);
            assert_eq!((r, true), elimination_rank_and_units(&a));
        }
    }

    #[test]
    fn a_common_factor_or_a_square_nonsingular_input_declines() {
        // Every row times (x + 3): d_r has that factor.
        let mut a = seeded(4, 6, 1, 5);
        let x3 = QPoly::from_ints(vec![BigInt::from(3), BigInt::from(1)]);
        for i in 0..4 {
            a.scale_row(i, &x3);
        }
        assert!(certify_unit_factors(&a).is_none());
        assert!(certify_unit_factors(&seeded(5, 5, 1, 6)).is_none());
    }

    #[test]
    fn a_wrong_rank_is_refused_by_the_kernel_check() {
        // Full-rank square input but forced through step 3 with a smaller
        // pivot block: the product A·K is nonzero.
        let a = seeded(5, 6, 1, 7);
        let at = integer_rows(&a);
        let sub: Vec<Vec<Vec<BigInt>>> = (0..3)
            .map(|i| (0..3).map(|j| at[i][j].clone()).collect())
            .collect();
        let nb = bound(&at, &[0, 1, 2], &[0, 1, 2]);
        let (det, adj) = super::super::detadj::det_adj(&sub, nb).unwrap();
        let r = &a.ring;
        let mut k = Matrix::zeros(r.clone(), 6, 1);
        for (b, adj_b) in adj.iter().enumerate() {
            let mut s = r.zero();
            for (ai, e) in adj_b.iter().enumerate() {
                let t = r.mul(
                    &QPoly::from_ints(e.clone()),
                    &QPoly::from_ints(at[ai][3].clone()),
                );
                s = r.add(&s, &t);
            }
            k.set(b, 0, r.neg(&s));
        }
        k.set(3, 0, QPoly::from_ints(det));
        let p = a.mul(&k).unwrap();
        // Rows 0..3 vanish (the construction), the others do not.
        assert!((0..3).all(|i| p.get(i, 0).is_zero()));
        assert!((3..5).any(|i| !p.get(i, 0).is_zero()));
    }
}
