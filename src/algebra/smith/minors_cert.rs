//! Invariant factors 1, …, 1, det A/lc of a large square A over Q\[x\]
//! (the generic case), certified without the adjugate: det A exactly by
//! images and two (n−1)-minors shown coprime modulo one prime. For an
//! n×n of degree 1 this skips the n² adjugate entries (100×100: 30 s by
//! the adjugate route). The checks ([`certify_generic`]):
//!
//! 1. `c = det Ã` (`Ã = Δ·A`, Δ the rows' denominator lcms): values of
//!    det Ã at N + 1 points modulo word primes (N the row/column degree
//!    bound), interpolated and lifted by Chinese remaindering once the
//!    primes' product exceeds twice Hadamard's bound on every coefficient
//!    ([`super::detadj::coefficient_bound_bits`]); then re-checked modulo a
//!    further prime at N + 1 points.
//! 2. `d_(n−1) = 1`: the minors `M1 = det A[1..n−1; 1..n−1]` and
//!    `M2 = det A[1..n−1; 1..n−2, n]` of Ã (row scales are units) are
//!    computed modulo a prime p from their values; `deg (M1 mod p)` equals
//!    M1's own degree bound, so p keeps M1's degree and divides no leading
//!    coefficient of their primitive gcd g over Z, and `gcd(M1 mod p,
//!    M2 mod p) = 1` then forces `deg g = 0`.
//!
//! So `f_1 = … = f_(n−1) = 1` and `f_n = det A/lc`. Anything unexpected
//! returns `None` and the caller takes the adjugate route. This module
//! must not print or choose modes.

use super::certify::Certificate;
use crate::algebra::matrix::Matrix;
use crate::algebra::modular::{self, Fp, crt, symmetric};
use crate::algebra::qx::{QPoly, QxRing};
use crate::algebra::ring::GcdDomain;
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// From this size on (and degree ≥ 1) the route is tried first.
pub const MIN_SIZE: usize = 48;

/// The algorithm's description in reports.
pub const ALGORITHM: &str = "det by images mod word primes at N + 1 points (CRT above Hadamard's bound, re-checked mod a further prime); d_(n−1) = 1 from two (n−1)-minors coprime modulo a prime that keeps the first one's degree (no adjugate)";

/// Integer rows `Ã = Δ·A` as coefficient vectors.
pub(super) fn integer_rows(a: &Matrix<QxRing>) -> Vec<Vec<Vec<BigInt>>> {
    (0..a.rows())
        .map(|i| {
            let l = a.row(i).iter().fold(BigInt::one(), |l, p| {
                crate::algebra::intgcd::lcm(&l, p.den())
            });
            a.row(i)
                .iter()
                .map(|p| p.num().iter().map(|c| c * (&l / p.den())).collect())
                .collect()
        })
        .collect()
}

/// Least of the sums of row and of column degrees of the submatrix.
pub(super) fn bound(m: &[Vec<Vec<BigInt>>], rows: &[usize], cols: &[usize]) -> usize {
    let deg = |p: &Vec<BigInt>| p.len().saturating_sub(1);
    let r: usize = rows
        .iter()
        .map(|&i| cols.iter().map(|&j| deg(&m[i][j])).max().unwrap_or(0))
        .sum();
    let c: usize = cols
        .iter()
        .map(|&j| rows.iter().map(|&i| deg(&m[i][j])).max().unwrap_or(0))
        .sum();
    r.min(c)
}

/// Determinant mod p of an n×n matrix (row-major, overwritten), by
/// elimination with prepared multipliers.
pub(super) fn det_mod(f: Fp, m: &mut [u64], n: usize) -> u64 {
    let mut det = 1u64;
    for k in 0..n {
        let Some(p) = (k..n).find(|&i| m[i * n + k] != 0) else {
            return 0;
        };
        if p != k {
            for j in 0..n {
                m.swap(p * n + j, k * n + j);
            }
            det = f.neg(det);
        }
        let pk = m[k * n + k];
        det = f.mul(det, pk);
        let inv = f.inv(pk);
        for i in k + 1..n {
            let q = m[i * n + k];
            if q == 0 {
                continue;
            }
            let q = f.prep(f.mul(q, inv));
            for j in k + 1..n {
                let t = f.mul_pre(q, m[k * n + j]);
                m[i * n + j] = f.sub(m[i * n + j], t);
            }
        }
    }
    det
}

/// The polynomial mod p of degree ≤ `deg` equal to det of the submatrix
/// at `x = 0, …, deg` (Newton interpolation).
pub(super) fn minor_mod(
    f: Fp,
    img: &[Vec<Vec<u64>>],
    rows: &[usize],
    cols: &[usize],
    deg: usize,
) -> Vec<u64> {
    let k = rows.len();
    let mut m = vec![0u64; k * k];
    let mut vals = Vec::with_capacity(deg + 1);
    for x in 0..=deg as u64 {
        for (a, &i) in rows.iter().enumerate() {
            for (b, &j) in cols.iter().enumerate() {
                m[a * k + b] = modular::eval(f, &img[i][j], x);
            }
        }
        vals.push(det_mod(f, &mut m, k));
    }
    // Divided differences, then the Newton form expanded.
    let mut d = vals;
    for s in 1..d.len() {
        let inv = f.inv(s as u64);
        for i in (s..d.len()).rev() {
            d[i] = f.mul(f.sub(d[i], d[i - 1]), inv);
        }
    }
    let mut p: Vec<u64> = Vec::with_capacity(d.len());
    for s in (0..d.len()).rev() {
        // p ← p·(x − s) + d[s]
        p.insert(0, 0);
        let xs = s as u64 % f.p;
        for i in 0..p.len() - 1 {
            let t = f.mul(p[i + 1], xs);
            p[i] = f.sub(p[i], t);
        }
        p[0] = f.add(p[0], d[s]);
    }
    modular::trim(p)
}

pub(super) fn reduce_all(f: Fp, m: &[Vec<Vec<BigInt>>]) -> Vec<Vec<Vec<u64>>> {
    m.iter()
        .map(|row| {
            row.iter()
                .map(|p| p.iter().map(|c| f.reduce(c)).collect())
                .collect()
        })
        .collect()
}

/// The certificate of the module documentation and f_n = det A/lc, or
/// `None` (not square, too small, constant, singular, or d_(n−1) not shown
/// to be 1).
pub fn certify_generic(a: &Matrix<QxRing>) -> Option<(Certificate, QPoly)> {
    let n = a.rows();
    if n < MIN_SIZE || a.cols() != n {
        return None;
    }
    if a.entries().iter().all(|e| e.degree().unwrap_or(0) == 0) {
        return None;
    }
    let at = integer_rows(a);
    let all: Vec<usize> = (0..n).collect();
    let big_n = bound(&at, &all, &all);
    let need = super::detadj::coefficient_bound_bits(&at)? + 2;
    let mut primes = modular::primes();
    // 2. Two (n−1)-minors, first (cheap, and decides whether to go on).
    let rows: Vec<usize> = (0..n - 1).collect();
    let cols1: Vec<usize> = (0..n - 1).collect();
    let cols2: Vec<usize> = (0..n - 2).chain(std::iter::once(n - 1)).collect();
    let n1 = bound(&at, &rows, &cols1);
    let n2 = bound(&at, &rows, &cols2);
    let p0 = primes.next()?;
    let f0 = Fp::new(p0);
    let img0 = reduce_all(f0, &at);
    let m1 = minor_mod(f0, &img0, &rows, &cols1, n1);
    if modular::deg(&m1) != Some(n1) {
        return None;
    }
    let m2 = minor_mod(f0, &img0, &rows, &cols2, n2);
    if m2.is_empty() || modular::deg(&modular::gcd(f0, &m1, &m2)) != Some(0) {
        return None;
    }
    // 1. det Ã by images and CRT.
    let mut acc: Vec<BigInt> = vec![BigInt::zero(); big_n + 1];
    let mut modulus = BigInt::one();
    let mut used = 0usize;
    while modulus.bits() < need {
        let p = primes.next()?;
        let f = Fp::new(p);
        let img = reduce_all(f, &at);
        let d = minor_mod(f, &img, &all, &all, big_n);
        let minv = f.inv(f.reduce(&modulus));
        let mp = &modulus * p;
        for (k, c) in acc.iter_mut().enumerate() {
            let v = d.get(k).copied().unwrap_or(0);
            *c = symmetric(&crt(c, &modulus, v, f, minv), &mp);
        }
        modulus = mp;
        used += 1;
    }
    let det = QPoly::from_ints(acc);
    if det.degree().is_none_or(|d| d == 0) {
        return None;
    }
    // Re-check modulo a further prime.
    let pc = primes.next()?;
    let fc = Fp::new(pc);
    let dc = minor_mod(fc, &reduce_all(fc, &at), &all, &all, big_n);
    let det_img: Vec<u64> = modular::trim(det.num().iter().map(|c| fc.reduce(c)).collect());
    let recheck = dc == det_img;
    let mut cert = Certificate { checks: Vec::new() };
    cert.push(
        "c = det Ã (Ã = Δ·A, Δ the rows' denominators)",
        recheck,
        format!(
            "det Ã from its values at 0, …, {big_n} modulo {used} word primes, lifted by CRT beyond Hadamard's bound 2^{need} on its coefficients; re-checked modulo p = {pc} at the same points"
        ),
    );
    cert.push(
        "d_(n−1)(A) = 1",
        true,
        format!(
            "the (n−1)-minors on rows 1..{} with columns 1..{} and with columns 1..{}, {n} have gcd 1 modulo p = {p0}, and the first keeps its degree bound {n1} modulo p, so their gcd over Q is 1",
            n - 1,
            n - 1,
            n - 2
        ),
    );
    cert.push(
        "invariant factors 1, …, 1, f",
        recheck,
        "d_(n−1) = 1 gives f_1 = … = f_(n−1) = 1, and f_n = d_n/d_(n−1) = det A up to its leading coefficient".to_string(),
    );
    recheck.then(|| (cert, a.ring.normalize(&det)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::smith::nonsingular::{FastPath, try_fast};

    fn seeded(n: usize, seed: u64) -> Matrix<QxRing> {
        let mut s = seed;
        let mut next = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            BigInt::from(((s >> 33) % 19) as i64 - 9)
        };
        let data: Vec<QPoly> = (0..n * n)
            .map(|_| QPoly::from_ints(vec![next(), next()]))
            .collect();
        Matrix::new(QxRing::new("x"), n, n, data)
    }

    #[test]
    fn agrees_with_the_adjugate_route() {
        let a = seeded(MIN_SIZE, 9);
        let (cert, f) = certify_generic(&a).expect("generic input");
        assert!(cert.verified(), "{cert:#?}");
        let Some(FastPath::FormOnly { c, .. }) = try_fast(&a, 0) else {
            panic!("nonsingular");
        };
        assert_eq!(f, a.ring.normalize(&c));
    }

    #[test]
    fn a_common_factor_of_the_minors_declines() {
        // Rows 1 and 2 times (x + 3): every (n−1)-minor has the factor.
        let mut a = seeded(MIN_SIZE, 4);
        let x3 = QPoly::from_ints(vec![BigInt::from(3), BigInt::from(1)]);
        a.scale_row(0, &x3);
        a.scale_row(1, &x3);
        assert!(certify_generic(&a).is_none());
    }
}
