//! det and adjugate of a square matrix over Q[s1..sn] (several symbols)
//! without elimination over Q(others): the rows are scaled to integer
//! coefficients, the symbols are packed into one by Kronecker substitution
//! (s_i → t^(w_i), w_(i+1) = w_i·(N_i + 1), N_i a proved bound on the
//! degree in s_i of det A and of every (n−1)-minor: the least of the sums
//! of row and of column degrees), and [`super::detadj::det_adj`] computes
//! the univariate det and adjugate exactly by images mod word primes above
//! a proved coefficient bound. Unpacking is exact because no result has a
//! degree in s_i above N_i. The result `A·B = c·I` is what
//! [`super::certify_several`] certifies; this module must not certify,
//! choose a mode or print.

use super::detadj::{IntPoly, det_adj};
use crate::algebra::matrix::Matrix;
use crate::algebra::mpoly::{MPoly, Monomial};
use crate::algebra::polyring::PolyRing;
use crate::algebra::rational::Q;
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// Refuse packings whose univariate degree exceeds this (the images cost
/// about n²·deg² word operations per prime).
pub const MAX_PACKED_DEGREE: usize = 3_000;

/// The least of the sums of row and of column degrees in variable `v`: a
/// bound on `deg_v det A` and on the degree in v of every (n−1)-minor.
pub fn degree_bound(a: &Matrix<PolyRing>, v: usize) -> usize {
    let deg = |e: &MPoly| e.degree_in(v).unwrap_or(0) as usize;
    let (m, n) = (a.rows(), a.cols());
    let rows: usize = (0..m)
        .map(|i| (0..n).map(|j| deg(a.get(i, j))).max().unwrap_or(0))
        .sum();
    let cols: usize = (0..n)
        .map(|j| (0..m).map(|i| deg(a.get(i, j))).max().unwrap_or(0))
        .sum();
    rows.min(cols)
}

/// The degree bound of the packed (univariate) det A: the sum over rows of
/// the largest packed degree of an entry, saturating instead of
/// overflowing (so a refusal can name it for any size).
pub fn packed_det_degree(a: &Matrix<PolyRing>) -> u128 {
    let nv = a.ring.nvars();
    let mut weights = vec![0u128; nv];
    let mut w = 1u128;
    for (v, wv) in weights.iter_mut().enumerate() {
        if a.entries().iter().any(|e| e.contains_var(v)) {
            *wv = w;
            w = w.saturating_mul(degree_bound(a, v) as u128 + 1);
        }
    }
    (0..a.rows())
        .map(|i| {
            a.row(i)
                .iter()
                .flat_map(|p| p.terms().iter())
                .map(|(m, _)| {
                    m.iter().zip(&weights).fold(0u128, |acc, (&e, &wv)| {
                        acc.saturating_add(wv.saturating_mul(u128::from(e)))
                    })
                })
                .max()
                .unwrap_or(0)
        })
        .fold(0u128, |acc, d| acc.saturating_add(d))
}

/// `(c, B)` with `A·B = c·I`, `c = det(Δ·A)` and `B = adj(Δ·A)·Δ` for the
/// diagonal Δ of the rows' denominator lcms (so B has integer
/// coefficients). `None` when A is not square, looks singular, or the
/// packing would be too large; callers then take another exact route.
pub fn det_adj_several(a: &Matrix<PolyRing>) -> Option<(MPoly, Matrix<PolyRing>)> {
    let n = a.rows();
    if n < 2 || a.cols() != n {
        return None;
    }
    if packed_det_degree(a) > MAX_PACKED_DEGREE as u128 {
        return None;
    }
    let nv = a.ring.nvars();
    let vars: Vec<usize> = (0..nv)
        .filter(|&v| a.entries().iter().any(|e| e.contains_var(v)))
        .collect();
    // Weights of the packing and the radices D_i = N_i + 1.
    let mut weights = vec![0usize; nv];
    let mut radix = vec![1usize; nv];
    let mut w = 1usize;
    for &v in &vars {
        weights[v] = w;
        radix[v] = degree_bound(a, v) + 1;
        w = w.checked_mul(radix[v])?;
    }
    let packed_degree =
        |m: &Monomial| -> usize { vars.iter().map(|&v| m[v] as usize * weights[v]).sum() };
    let mut delta: Vec<BigInt> = Vec::with_capacity(n);
    let mut rows: Vec<Vec<IntPoly>> = Vec::with_capacity(n);
    let mut row_deg = 0usize;
    for i in 0..n {
        let l = a.row(i).iter().fold(BigInt::one(), |l, p| {
            p.terms()
                .iter()
                .fold(l, |l, (_, c)| crate::algebra::intgcd::lcm(&l, c.denom()))
        });
        let mut row = Vec::with_capacity(n);
        let mut md = 0usize;
        for p in a.row(i) {
            let d = p
                .terms()
                .iter()
                .map(|(m, _)| packed_degree(m))
                .max()
                .unwrap_or(0);
            md = md.max(d);
            let mut dense = vec![BigInt::zero(); if p.is_zero() { 0 } else { d + 1 }];
            for (m, c) in p.terms() {
                dense[packed_degree(m)] = c.numer() * (&l / c.denom());
            }
            row.push(dense);
        }
        row_deg += md;
        delta.push(l);
        rows.push(row);
    }
    if row_deg > MAX_PACKED_DEGREE {
        return None;
    }
    let (det, adj) = det_adj(&rows, row_deg)?;
    let unpack = |p: &IntPoly, scale: &BigInt| -> MPoly {
        let terms = p
            .iter()
            .enumerate()
            .filter(|(_, c)| !c.is_zero())
            .map(|(k, c)| {
                let mut m = vec![0u32; nv];
                for &v in &vars {
                    m[v] = ((k / weights[v]) % radix[v]) as u32;
                }
                (m, Q::from_integer(c * scale))
            });
        MPoly::from_terms(nv, terms)
    };
    let one = BigInt::one();
    let c = unpack(&det, &one);
    if c.is_zero() {
        return None;
    }
    let mut b = Matrix::zeros(a.ring.clone(), n, n);
    for (i, row) in adj.iter().enumerate() {
        for (k, (e, d)) in row.iter().zip(&delta).enumerate() {
            b.set(i, k, unpack(e, d));
        }
    }
    Some((c, b))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::rational::{q, qi};
    use crate::algebra::ring::Ring;

    #[test]
    fn packed_det_and_adjugate_satisfy_a_b_equals_c_i() {
        let ring = PolyRing::new(vec!["x".into(), "y".into(), "z".into()]);
        let v: Vec<MPoly> = (0..3).map(|i| MPoly::var(i, 3)).collect();
        let one = MPoly::one(3);
        let (x, y, z) = (&v[0], &v[1], &v[2]);
        let data = vec![
            x * y + one.clone(),
            z.scale(&q(1, 2)),
            x - y,
            y * y,
            x + &z.scale(&qi(3)),
            one.clone(),
            x * z,
            MPoly::zero(3),
            y.pow(2) * z - one.clone(),
        ];
        let a = Matrix::new(ring.clone(), 3, 3, data);
        let (c, b) = det_adj_several(&a).expect("nonsingular");
        let ab = a.mul(&b).expect("shapes");
        for i in 0..3 {
            for j in 0..3 {
                let want = if i == j { c.clone() } else { ring.zero() };
                assert_eq!(ab.get(i, j), &want, "entry {i},{j}");
            }
        }
        // c is det(Δ·A) with Δ = diag(2, 1, 1).
        let det = a.det().expect("square");
        assert_eq!(c, det.scale(&qi(2)));
    }

    #[test]
    fn singular_input_gives_none() {
        let ring = PolyRing::new(vec!["x".into(), "y".into()]);
        let (x, y) = (MPoly::var(0, 2), MPoly::var(1, 2));
        let a = Matrix::new(ring, 2, 2, vec![x.clone(), y.clone(), &x * &y, &y * &y]);
        assert!(det_adj_several(&a).is_none());
    }
}
