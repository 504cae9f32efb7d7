//! det and adjugate of a square matrix of integer polynomials, by images.
//! For word primes p ([`crate::algebra::modular::primes`]) and enough
//! points x of Z_p, Gauss–Jordan mod p gives det A(x) and adj A(x) =
//! det A(x)·A(x)⁻¹; Newton interpolation mod p turns the values into
//! polynomials mod p, and Garner's mixed-radix Chinese remaindering lifts
//! them to Z once the product of the primes exceeds twice a proved bound on
//! every coefficient. The bound: a coefficient of a polynomial is at most
//! its largest modulus on the unit circle (Cauchy), and there
//! `|a_ij(x)| ≤ ‖a_ij‖₁`, so Hadamard's inequality with the row norms
//! `r_i = (Σ_j ‖a_ij‖₁²)^½` bounds every coefficient of det A and of every
//! (n−1)-minor by `Π r_i` (each `r_i ≥ 1`). The result is therefore exact,
//! not probabilistic. A prime is skipped when det A vanishes mod p as a
//! polynomial; three such primes in a row mean "probably singular" and give
//! `None` (callers then take another, slower, exact route). This module
//! owns no Smith logic and must not certify: callers' results are checked.

use crate::algebra::modular::{Fp, primes};
use num_bigint::BigInt;
use num_traits::{Signed, Zero};

/// An integer polynomial (coefficients, low degree first).
pub type IntPoly = Vec<BigInt>;

/// The degree of a row of integer polynomials (its largest entry's
/// degree; 0 for a row of zeros). The sum over the rows bounds deg det.
pub fn row_degree(row: &[IntPoly]) -> usize {
    row.iter()
        .map(|p| p.len().saturating_sub(1))
        .max()
        .unwrap_or(0)
}

/// Upper bound, in bits, of every coefficient of det A and of every
/// (n−1)-minor; `None` when a row is zero (A is singular).
pub fn coefficient_bound_bits(m: &[Vec<IntPoly>]) -> Option<u64> {
    let mut total = 0u64;
    for row in m {
        let mut s = BigInt::zero();
        for p in row {
            let n1: BigInt = p.iter().map(|c| c.abs()).sum();
            s += &n1 * &n1;
        }
        if s.is_zero() {
            return None;
        }
        // √s < 2^⌈bits(s)/2⌉.
        total += s.bits().div_ceil(2);
    }
    Some(total)
}

/// Gauss–Jordan inversion in place mod p: `(det M, adj M)` (row-major),
/// or `None` when M is singular mod p. Each pivot step stores the
/// inverse's column where A's was (n³ products instead of the 1.5·n³ of
/// eliminating on `[M | I]`); row interchanges make it `(P·M)⁻¹ = M⁻¹·P⁻¹`,
/// undone by the same interchanges of columns in reverse order.
pub fn det_adj_mod(f: Fp, m: &[u64], n: usize) -> Option<(u64, Vec<u64>)> {
    let mut a = m[..n * n].to_vec();
    let mut swaps: Vec<(usize, usize)> = Vec::new();
    let mut det = 1u64;
    for k in 0..n {
        let p = (k..n).find(|&i| a[i * n + k] != 0)?;
        if p != k {
            for j in 0..n {
                a.swap(p * n + j, k * n + j);
            }
            det = f.neg(det);
            swaps.push((k, p));
        }
        let piv = a[k * n + k];
        det = f.mul(det, piv);
        let inv = f.prep(f.inv(piv));
        a[k * n + k] = 1;
        for j in 0..n {
            a[k * n + j] = f.mul_pre(inv, a[k * n + j]);
        }
        let (before, rest) = a.split_at_mut(k * n);
        let (prow, after) = rest.split_at_mut(n);
        for row in before.chunks_mut(n).chain(after.chunks_mut(n)) {
            let c = row[k];
            if c == 0 {
                continue;
            }
            row[k] = 0;
            let cm = f.prep(c);
            for (x, &y) in row.iter_mut().zip(prow.iter()) {
                *x = f.sub(*x, f.mul_pre(cm, y));
            }
        }
    }
    for &(k, p) in swaps.iter().rev() {
        for i in 0..n {
            a.swap(i * n + k, i * n + p);
        }
    }
    let dm = f.prep(det);
    for v in a.iter_mut() {
        *v = f.mul_pre(dm, *v);
    }
    Some((det, a))
}

/// The Lagrange basis of the distinct points `xs` mod p, row-major:
/// entry `i·n + c` is the coefficient of `x^c` in `L_i = Π_{j≠i} (x −
/// x_j)/(x_i − x_j)` (n = `xs.len()`), from `P = Π (x − x_j)` by one
/// synthetic division per point and one inversion per point.
fn lagrange_basis(f: Fp, xs: &[u64]) -> Vec<u64> {
    let n = xs.len();
    // P, monic of degree n.
    let mut p = vec![0u64; n + 1];
    p[0] = 1;
    for (len, &xj) in xs.iter().enumerate() {
        let xm = f.prep(xj);
        for k in (0..=len + 1).rev() {
            let hi = if k > 0 { p[k - 1] } else { 0 };
            p[k] = f.sub(hi, f.mul_pre(xm, p[k]));
        }
    }
    let mut out = vec![0u64; n * n];
    let mut q = vec![0u64; n];
    for (i, &xi) in xs.iter().enumerate() {
        // q = P/(x − x_i), then L_i = q/q(x_i).
        let xm = f.prep(xi);
        q[n - 1] = p[n];
        for k in (1..n).rev() {
            q[k - 1] = f.add(p[k], f.mul_pre(xm, q[k]));
        }
        let w = q
            .iter()
            .rev()
            .fold(0u64, |acc, &c| f.add(f.mul_pre(xm, acc), c));
        let wm = f.prep(f.inv(w));
        for (o, &c) in out[i * n..(i + 1) * n].iter_mut().zip(&q) {
            *o = f.mul_pre(wm, c);
        }
    }
    out
}

/// Newton interpolation mod p through `(xs[k], ys[k])`, in monomial form
/// (length `xs.len()`, not trimmed). `inv[k][i]` = `(xs[i] − xs[i−k])⁻¹`.
/// The former route, now the reference for [`lagrange_basis`].
#[cfg(test)]
fn interpolate_mod(f: Fp, xs: &[u64], ys: &[u64], inv: &[Vec<u64>]) -> Vec<u64> {
    let n = xs.len();
    let mut c = ys.to_vec();
    for (k, inv_k) in inv.iter().enumerate().take(n).skip(1) {
        for i in (k..n).rev() {
            c[i] = f.mul_pre(inv_k[i], f.sub(c[i], c[i - 1]));
        }
    }
    let mut p = vec![0u64; n];
    // p ← p·(x − xs[k]) + c[k], from the top.
    let mut len = 0usize;
    for k in (0..n).rev() {
        let xk = xs[k];
        // multiply p (length len) by (x − xk)
        let mut carry = 0u64;
        for coef in p.iter_mut().take(len) {
            let cur = *coef;
            *coef = f.sub(carry, f.mul(cur, xk));
            carry = cur;
        }
        if len < n {
            p[len] = carry;
        }
        len = (len + 1).min(n);
        p[0] = f.add(p[0], c[k]);
    }
    p
}

/// One prime's image: det and adj as polynomials mod p of degree ≤ `deg`
/// (coefficient vectors of length `deg + 1`), or `None` if det A ≡ 0 mod p.
#[allow(clippy::type_complexity)]
fn image(f: Fp, m: &[Vec<IntPoly>], deg: usize) -> Option<(Vec<u64>, Vec<Vec<u64>>)> {
    let n = m.len();
    let mp: Vec<Vec<u64>> = m
        .iter()
        .flat_map(|row| row.iter().map(|p| p.iter().map(|c| f.reduce(c)).collect()))
        .collect();
    let mut xs = Vec::with_capacity(deg + 1);
    let mut dets = Vec::with_capacity(deg + 1);
    let mut adjs: Vec<Vec<u64>> = Vec::with_capacity(deg + 1);
    let mut x = 0u64;
    let mut failures = 0usize;
    let mut vals = vec![0u64; n * n];
    while xs.len() <= deg {
        for (v, p) in vals.iter_mut().zip(&mp) {
            *v = p.iter().rev().fold(0u64, |acc, &c| f.add(f.mul(acc, x), c));
        }
        match det_adj_mod(f, &vals, n) {
            Some((d, adj)) => {
                xs.push(x);
                dets.push(d);
                adjs.push(adj);
            }
            None => {
                failures += 1;
                // A nonzero det of degree ≤ deg has at most deg roots.
                if failures > deg {
                    return None;
                }
            }
        }
        x += 1;
    }
    let npts = xs.len();
    // One Lagrange basis for all n² + 1 interpolations: each is then a
    // matrix–vector product with lazy sums.
    let basis = lagrange_basis(f, &xs);
    let interpolate = |ys: &[u64]| -> Vec<u64> {
        (0..npts)
            .map(|c| {
                let acc = ys.iter().enumerate().fold(0u128, |acc, (i, &y)| {
                    f.mul_add_wide(acc, y, basis[i * npts + c])
                });
                f.reduce_wide(acc)
            })
            .collect()
    };
    let det = interpolate(&dets);
    let mut ys = vec![0u64; npts];
    let adj = (0..n * n)
        .map(|e| {
            for (y, a) in ys.iter_mut().zip(&adjs) {
                *y = a[e];
            }
            interpolate(&ys)
        })
        .collect();
    Some((det, adj))
}

/// Garner's mixed-radix reconstruction for a fixed list of primes: the
/// residues `res[k] mod ps[k]` give the integer in the symmetric range of
/// `m = Π ps` (the inverses and the products are computed once).
pub struct Garner {
    /// The primes (empty when `tree` holds them).
    ps: Vec<Fp>,
    /// From [`TREE_MIN`] primes on, the product-tree reconstruction
    /// (`ps`, `inv` and the limbs are then empty).
    tree: Option<crate::algebra::crt::CrtTree>,
    /// `inv[i][j] = ps[j]⁻¹ mod ps[i]` (prepared), `j < i`.
    inv: Vec<Vec<u64>>,
    /// `m = Π ps`.
    pub m: BigInt,
    /// m and ⌊m/2⌋ as little-endian limbs.
    m_limbs: Vec<u64>,
    half_limbs: Vec<u64>,
}

/// From this many primes on, [`Garner`] reconstructs by the product tree
/// of [`crate::algebra::crt`] (O(k²) mixed-radix digits give way to a few
/// subquadratic products per level). Measured per value: Garner 6–10 %
/// faster at 16–24 primes, the tree 1.4× faster at 32, 2.4× at 128, 5.4×
/// at 1 500 (and 10× faster to set up there).
pub const TREE_MIN: usize = 32;

impl Garner {
    /// The basis of the primes `ps` (distinct).
    pub fn new(ps: &[Fp]) -> Self {
        if ps.len() >= TREE_MIN {
            let tree = crate::algebra::crt::CrtTree::new(ps);
            return Garner {
                ps: Vec::new(),
                inv: Vec::new(),
                m: tree.m.clone(),
                m_limbs: Vec::new(),
                half_limbs: Vec::new(),
                tree: Some(tree),
            };
        }
        let inv = (0..ps.len())
            .map(|i| {
                (0..i)
                    .map(|j| ps[i].prep(ps[i].inv(ps[j].p % ps[i].p)))
                    .collect()
            })
            .collect();
        let m = ps.iter().fold(BigInt::from(1), |acc, f| acc * f.p);
        let half = &m >> 1u32;
        Garner {
            ps: ps.to_vec(),
            tree: None,
            inv,
            m_limbs: m.magnitude().to_u64_digits(),
            half_limbs: half.magnitude().to_u64_digits(),
            m,
        }
    }

    /// The integer in `(−m/2, m/2]` with the residues `res` (one per prime).
    pub fn lift(&self, res: &[u64]) -> BigInt {
        if let Some(tree) = &self.tree {
            return tree.lift(res);
        }
        let k = res.len();
        debug_assert_eq!(k, self.ps.len());
        let mut v = [0u64; 32];
        let mut v_big = Vec::new();
        let v: &mut [u64] = if k <= 32 {
            &mut v[..k]
        } else {
            v_big.resize(k, 0);
            &mut v_big
        };
        for i in 0..k {
            let f = self.ps[i];
            let mut t = res[i];
            for (&inv, &vj) in self.inv[i].iter().zip(v.iter()) {
                // vj < p_j; the word primes lie within a factor 2 of each
                // other, so the division is almost never needed.
                let vj = if vj >= f.p { vj % f.p } else { vj };
                t = f.mul_pre(inv, f.sub(t, vj));
            }
            v[i] = t;
        }
        // Up to two primes (m < 2^128) the value fits an i128: no BigInt
        // digits to pack.
        if k <= 2 {
            let m: u128 = self.ps.iter().map(|f| u128::from(f.p)).product();
            let acc = if k == 2 {
                u128::from(v[1]) * u128::from(self.ps[0].p) + u128::from(v[0])
            } else {
                v.first().map_or(0, |&x| u128::from(x))
            };
            return if acc > m >> 1 {
                BigInt::from(acc as i128 - m as i128)
            } else {
                BigInt::from(acc)
            };
        }
        // Horner on 64-bit limbs: acc = v[k−1]; acc = acc·p + v[i]. The
        // value has at most k limbs (each p < 2^64); on the stack up to 32.
        let mut limbs_small = [0u64; 32];
        let mut limbs_big = Vec::new();
        let limbs: &mut [u64] = if k <= 32 {
            &mut limbs_small[..k]
        } else {
            limbs_big.resize(k, 0);
            &mut limbs_big
        };
        let mut used = 0usize;
        for i in (0..k).rev() {
            let p = self.ps[i].p as u128;
            let mut carry = v[i] as u128;
            for l in limbs[..used].iter_mut() {
                let t = *l as u128 * p + carry;
                *l = t as u64;
                carry = t >> 64;
            }
            if carry != 0 {
                limbs[used] = carry as u64;
                used += 1;
            }
        }
        // The symmetric representative, built once (one allocation): acc
        // above ⌊m/2⌋ is acc − m = −(m − acc), taken in limbs.
        let acc = &mut limbs[..used];
        let above = used > self.half_limbs.len()
            || (used == self.half_limbs.len() && acc.iter().rev().gt(self.half_limbs.iter().rev()));
        if !above {
            return BigInt::from_biguint(
                num_bigint::Sign::Plus,
                super::certify::biguint_from_limbs(acc),
            );
        }
        let mut diff_small = [0u64; 32];
        let mut diff_big = Vec::new();
        let diff: &mut [u64] = if k <= 32 {
            &mut diff_small[..self.m_limbs.len()]
        } else {
            diff_big.resize(self.m_limbs.len(), 0);
            &mut diff_big
        };
        let mut borrow = false;
        for (i, (d, &mw)) in diff.iter_mut().zip(&self.m_limbs).enumerate() {
            let a = acc.get(i).copied().unwrap_or(0);
            let (v1, o1) = mw.overflowing_sub(a);
            let (v2, o2) = v1.overflowing_sub(u64::from(borrow));
            *d = v2;
            borrow = o1 || o2;
        }
        debug_assert!(!borrow);
        BigInt::from_biguint(
            num_bigint::Sign::Minus,
            super::certify::biguint_from_limbs(diff),
        )
    }
}

fn trim(mut p: IntPoly) -> IntPoly {
    while p.last().is_some_and(|c| c.is_zero()) {
        p.pop();
    }
    p
}

/// det A and adj A for a square matrix of integer polynomials whose det
/// has degree ≤ `deg`; `None` when A looks singular (det ≡ 0 modulo three
/// primes in a row) or the prime supply runs out.
#[allow(clippy::type_complexity)]
pub fn det_adj(m: &[Vec<IntPoly>], deg: usize) -> Option<(IntPoly, Vec<Vec<IntPoly>>)> {
    let n = m.len();
    let need = coefficient_bound_bits(m)? + 2;
    let mut fps: Vec<Fp> = Vec::new();
    let mut images: Vec<(Vec<u64>, Vec<Vec<u64>>)> = Vec::new();
    let mut bits = 0u64;
    let mut bad_in_a_row = 0;
    for p in primes() {
        if bits >= need {
            break;
        }
        let f = Fp::new(p);
        match image(f, m, deg) {
            Some(img) => {
                bad_in_a_row = 0;
                fps.push(f);
                images.push(img);
                // p > 2^61.
                bits += 61;
            }
            None => {
                bad_in_a_row += 1;
                if bad_in_a_row >= 3 {
                    return None;
                }
            }
        }
    }
    if bits < need {
        return None;
    }
    let basis = Garner::new(&fps);
    let mut res = vec![0u64; fps.len()];
    let mut lift = |get: &dyn Fn(&(Vec<u64>, Vec<Vec<u64>>)) -> u64| -> BigInt {
        for (r, img) in res.iter_mut().zip(&images) {
            *r = get(img);
        }
        basis.lift(&res)
    };
    let det = trim((0..=deg).map(|c| lift(&|img| img.0[c])).collect());
    let adj = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| {
                    trim(
                        (0..=deg)
                            .map(|c| lift(&|img| img.1[i * n + j][c]))
                            .collect(),
                    )
                })
                .collect()
        })
        .collect();
    Some((det, adj))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::smith::nonsingular::{det_adj_int, interpolate_int};

    fn bi(v: &[i64]) -> IntPoly {
        v.iter().map(|&x| BigInt::from(x)).collect()
    }

    /// The former form, Gauss–Jordan on `[M | I]` mod p (the reference): `(det M, adj M)` (row-major), or
    /// `None` when M is singular mod p.
    fn det_adj_mod_augmented(f: Fp, m: &[u64], n: usize) -> Option<(u64, Vec<u64>)> {
        let w = 2 * n;
        let mut a = vec![0u64; n * w];
        for i in 0..n {
            a[i * w..i * w + n].copy_from_slice(&m[i * n..(i + 1) * n]);
            a[i * w + n + i] = 1;
        }
        let mut det = 1u64;
        for k in 0..n {
            let p = (k..n).find(|&i| a[i * w + k] != 0)?;
            if p != k {
                for j in 0..w {
                    a.swap(p * w + j, k * w + j);
                }
                det = f.neg(det);
            }
            let piv = a[k * w + k];
            det = f.mul(det, piv);
            let inv = f.prep(f.inv(piv));
            for j in k..w {
                a[k * w + j] = f.mul_pre(inv, a[k * w + j]);
            }
            let (before, rest) = a.split_at_mut(k * w);
            let (prow, after) = rest.split_at_mut(w);
            for row in before.chunks_mut(w).chain(after.chunks_mut(w)) {
                let c = row[k];
                if c == 0 {
                    continue;
                }
                let cm = f.prep(c);
                for j in k..w {
                    row[j] = f.sub(row[j], f.mul_pre(cm, prow[j]));
                }
            }
        }
        let dm = f.prep(det);
        let adj = (0..n)
            .flat_map(|i| (0..n).map(move |j| (i, j)))
            .map(|(i, j)| f.mul_pre(dm, a[i * w + n + j]))
            .collect();
        Some((det, adj))
    }

    /// Garner's lift is the symmetric representative of the Chinese
    /// remainder, for one to five primes (the i128 form up to two).
    #[test]
    fn garner_lift_is_the_symmetric_crt_value() {
        let ps: Vec<Fp> = primes().take(5).map(Fp::new).collect();
        let mut next = crate::algebra::modular::lcg(9);
        let mut checked = 0;
        for k in 1..=5 {
            let basis = Garner::new(&ps[..k]);
            for round in 0..50 {
                let bits = 1 + next() % (62 * k as u64 - 1);
                let mut x = BigInt::from(next()) << 64u32 | BigInt::from(next());
                x = (x << (62 * k)) | BigInt::from(next());
                x %= BigInt::from(1) << bits as usize;
                if round % 2 == 1 {
                    x = -x;
                }
                let x = crate::algebra::modular::symmetric(&x, &basis.m);
                let res: Vec<u64> = ps[..k].iter().map(|f| f.reduce(&x)).collect();
                assert_eq!(basis.lift(&res), x, "k = {k}");
                checked += 1;
            }
            // The ends of the range.
            let half = &basis.m >> 1u32;
            for x in [half.clone(), -half.clone()] {
                let res: Vec<u64> = ps[..k].iter().map(|f| f.reduce(&x)).collect();
                assert_eq!(basis.lift(&res), x, "k = {k}");
            }
        }
        assert_eq!(checked, 250);
    }

    /// Interpolating with the Lagrange basis equals Newton's form, on
    /// consecutive points (as `image` takes them, some skipped) and random
    /// ones.
    #[test]
    fn lagrange_basis_interpolates_like_newton() {
        let f = Fp::new(primes().next().expect("a prime"));
        let mut seed = 21u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            seed >> 3
        };
        let mut checked = 0;
        for round in 0..120 {
            let npts = 1 + round % 14;
            let mut xs: Vec<u64> = Vec::new();
            let mut x = 0u64;
            while xs.len() < npts {
                let skip = round % 2 == 1 && next() % 4 == 0;
                if !skip {
                    xs.push(if round % 3 == 2 { next() % f.p } else { x });
                }
                x += 1;
            }
            xs.sort_unstable();
            xs.dedup();
            let npts = xs.len();
            let ys: Vec<u64> = (0..npts).map(|_| next() % f.p).collect();
            let inv: Vec<Vec<u64>> = (0..npts)
                .map(|k| {
                    (0..npts)
                        .map(|i| {
                            if k == 0 || i < k {
                                0
                            } else {
                                f.prep(f.inv(f.sub(xs[i], xs[i - k])))
                            }
                        })
                        .collect()
                })
                .collect();
            let want = interpolate_mod(f, &xs, &ys, &inv);
            let basis = lagrange_basis(f, &xs);
            let got: Vec<u64> = (0..npts)
                .map(|c| {
                    (0..npts).fold(0u64, |acc, i| f.add(acc, f.mul(ys[i], basis[i * npts + c])))
                })
                .collect();
            assert_eq!(got, want, "round {round}");
            checked += 1;
        }
        assert_eq!(checked, 120);
    }

    #[test]
    fn in_place_inversion_equals_elimination_on_m_and_i() {
        let f = Fp::new(primes().next().expect("a prime"));
        let mut seed = 5u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            seed >> 3
        };
        let (mut inverted, mut singular) = (0, 0);
        for round in 0..400 {
            let n = 1 + round % 9;
            // Small entries and many zeros force row interchanges and
            // singular cases.
            let m: Vec<u64> = (0..n * n)
                .map(|_| match next() % 4 {
                    0 => 0,
                    1 => next() % 3,
                    _ => next() % f.p,
                })
                .collect();
            let got = det_adj_mod(f, &m, n);
            assert_eq!(got, det_adj_mod_augmented(f, &m, n), "round {round}");
            match got {
                Some(_) => inverted += 1,
                None => singular += 1,
            }
        }
        assert!(inverted > 250 && singular > 10, "{inverted} {singular}");
    }

    #[test]
    fn modular_det_adj_matches_fraction_free_elimination() {
        // A 3×3 of integer polynomials of degree ≤ 2.
        let m = vec![
            vec![bi(&[1, 2]), bi(&[0, 0, 3]), bi(&[-4])],
            vec![bi(&[5, -1, 1]), bi(&[2]), bi(&[0, 7])],
            vec![bi(&[-3]), bi(&[1, 1]), bi(&[9, 0, -2])],
        ];
        let deg = 6;
        let (det, adj) = det_adj(&m, deg).expect("nonsingular");
        // Reference: exact integer elimination at 7 points, interpolated.
        let mut dets = Vec::new();
        let mut adjs = Vec::new();
        for x in -3i64..=3 {
            let mx: Vec<Vec<BigInt>> = m
                .iter()
                .map(|row| {
                    row.iter()
                        .map(|p| {
                            p.iter()
                                .rev()
                                .fold(BigInt::zero(), |a, c| a * BigInt::from(x) + c)
                        })
                        .collect()
                })
                .collect();
            let (d, a) = det_adj_int(&mx).expect("nonsingular at the point");
            dets.push(d);
            adjs.push(a);
        }
        assert_eq!(det, interpolate_int(&dets, -3));
        for i in 0..3 {
            for j in 0..3 {
                let vals: Vec<BigInt> = adjs.iter().map(|a| a[i][j].clone()).collect();
                assert_eq!(adj[i][j], interpolate_int(&vals, -3), "adj[{i}][{j}]");
            }
        }
    }

    #[test]
    fn large_constant_entries_need_several_primes() {
        // det of [[a, b], [c, d]] with 40-digit entries spans many primes.
        let big = |s: &str| vec![s.parse::<BigInt>().expect("integer")];
        let m = vec![
            vec![
                big("1234567890123456789012345678901234567891"),
                big("-987654321098765432109876543210987654321"),
            ],
            vec![
                big("555555555555555555555555555555555555555"),
                big("777777777777777777777777777777777777777"),
            ],
        ];
        let (det, adj) = det_adj(&m, 0).expect("nonsingular");
        let want = &m[0][0][0] * &m[1][1][0] - &m[0][1][0] * &m[1][0][0];
        assert_eq!(det, vec![want]);
        assert_eq!(adj[0][0], m[1][1]);
        assert_eq!(adj[0][1], vec![-&m[0][1][0]]);
    }

    #[test]
    fn singular_input_gives_none() {
        let m = vec![vec![bi(&[1, 1]), bi(&[2, 2])], vec![bi(&[3]), bi(&[6])]];
        assert!(det_adj(&m, 1).is_none());
    }
}
