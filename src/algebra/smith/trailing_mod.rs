//! The reduced Hermite basis of `L(A) + c_loc·Q[x]ⁿ` (the output of
//! [`super::trailing::local_hermite`]) from images modulo word primes:
//! the same elimination over Z_p\[x\] for each prime, then rational
//! reconstruction of each row with one common denominator, accepted when
//! one further prime agrees. The reduced basis (monic pivots, entries
//! above a unit pivot zero, entries above a trailing pivot of lower
//! degree, all modulo `c_loc`) is unique, so a good prime gives its exact
//! image; a prime whose pivot degrees differ from the first prime's makes
//! the route decline. The result is a candidate only: the trailing route
//! checks every row of H by an exact division, and the certificate
//! decides. This module must not certify, choose modes or print.

use crate::algebra::modular::{self, Fp, UP};
use crate::algebra::qx::QPoly;
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// Primes tried before the route declines.
const MAX_PRIMES: usize = 64;

fn rem(f: Fp, a: &[u64], m: &[u64]) -> UP {
    if a.len() < m.len() {
        return a.to_vec();
    }
    modular::div_rem(f, a, m).1
}

fn reduce_row(f: Fp, row: &mut [UP], m: &[u64]) {
    for e in row.iter_mut() {
        if e.len() >= m.len() {
            *e = rem(f, e, m);
        }
    }
}

/// `(g, s, t)` with `s·a + t·b = g`, g the monic gcd (a, b not both 0).
fn xgcd(f: Fp, a: &[u64], b: &[u64]) -> (UP, UP, UP) {
    let (mut r0, mut r1) = (a.to_vec(), b.to_vec());
    let (mut s0, mut s1): (UP, UP) = (vec![1], Vec::new());
    let (mut t0, mut t1): (UP, UP) = (Vec::new(), vec![1]);
    while !r1.is_empty() {
        let (q, r) = modular::div_rem(f, &r0, &r1);
        let s = modular::sub(f, &s0, &modular::mul(f, &q, &s1));
        let t = modular::sub(f, &t0, &modular::mul(f, &q, &t1));
        r0 = std::mem::replace(&mut r1, r);
        s0 = std::mem::replace(&mut s1, s);
        t0 = std::mem::replace(&mut t1, t);
    }
    let inv = f.inv(*r0.last().unwrap_or(&1));
    (
        modular::scale(f, &r0, inv),
        modular::scale(f, &s0, inv),
        modular::scale(f, &t0, inv),
    )
}

/// [`super::trailing::hnf_mod`] over Z_p[x] (`m` monic of degree ≥ 1).
fn hnf_mod_p(f: Fp, mut w: Vec<Vec<UP>>, m: &[u64]) -> Option<Vec<Vec<UP>>> {
    let n = w.len();
    let mut modulus = m.to_vec();
    for row in w.iter_mut() {
        reduce_row(f, row, &modulus);
    }
    let mut h = Vec::with_capacity(n);
    for j in 0..n {
        if modulus.len() <= 1 {
            let mut e = vec![Vec::new(); n];
            e[j] = vec![1];
            h.push(e);
            continue;
        }
        let unit = (j..n).find_map(|i| {
            (!w[i][j].is_empty())
                .then(|| modular::inverse_and_resultant(f, &w[i][j], &modulus))
                .flatten()
                .map(|(s, _)| (i, s))
        });
        if let Some((p, inv)) = unit {
            w.swap(j, p);
            let mut row: Vec<UP> = w[j].iter().map(|e| modular::mul(f, e, &inv)).collect();
            reduce_row(f, &mut row, &modulus);
            for e in row.iter_mut().take(j) {
                e.clear();
            }
            row[j] = vec![1];
            for wi in w.iter_mut().skip(j + 1) {
                let q = std::mem::take(&mut wi[j]);
                if q.is_empty() {
                    continue;
                }
                for t in j + 1..n {
                    wi[t] = modular::sub(f, &wi[t], &modular::mul(f, &q, &row[t]));
                }
                reduce_row(f, wi, &modulus);
            }
            h.push(row);
            continue;
        }
        for i in j + 1..n {
            if w[i][j].is_empty() {
                continue;
            }
            if w[j][j].is_empty() {
                w.swap(i, j);
                continue;
            }
            let (g, u, v) = xgcd(f, &w[j][j], &w[i][j]);
            let (a, ra) = modular::div_rem(f, &w[j][j], &g);
            let (b, rb) = modular::div_rem(f, &w[i][j], &g);
            if !ra.is_empty() || !rb.is_empty() {
                return None;
            }
            let mut new_j = Vec::with_capacity(n);
            let mut new_i = Vec::with_capacity(n);
            for (x, y) in w[j].iter().zip(&w[i]) {
                new_j.push(modular::add(
                    f,
                    &modular::mul(f, &u, x),
                    &modular::mul(f, &v, y),
                ));
                new_i.push(modular::sub(
                    f,
                    &modular::mul(f, &a, y),
                    &modular::mul(f, &b, x),
                ));
            }
            reduce_row(f, &mut new_j, &modulus);
            reduce_row(f, &mut new_i, &modulus);
            w[j] = new_j;
            w[i] = new_i;
        }
        // (d, s) with s·w_jj ≡ d = gcd(w_jj, modulus) (mod modulus).
        let (d, s) = if w[j][j].is_empty() {
            (modulus.clone(), Vec::new())
        } else {
            let (g, s, _) = xgcd(f, &w[j][j], &modulus);
            (g, rem(f, &s, &modulus))
        };
        let mut hj: Vec<UP> = w[j].iter().map(|e| modular::mul(f, &s, e)).collect();
        reduce_row(f, &mut hj, &modulus);
        for e in hj.iter_mut().take(j) {
            e.clear();
        }
        hj[j] = d.clone();
        h.push(hj);
        let (q, r) = modular::div_rem(f, &modulus, &d);
        if !r.is_empty() {
            return None;
        }
        modulus = q;
        for row in w.iter_mut().skip(j + 1) {
            reduce_row(f, row, &modulus);
        }
    }
    Some(h)
}

/// The reduced basis modulo p ([`super::trailing::local_hermite`]'s loop)
/// and its `first` (the first pivot that is not 1).
fn local_p(f: Fp, rows: Vec<Vec<UP>>, m: &[u64]) -> Option<(Vec<Vec<UP>>, usize)> {
    let n = rows.len();
    let mut h = hnf_mod_p(f, rows, m)?;
    let first = (0..n).find(|&i| h[i][i].len() != 1)?;
    for j in 0..n {
        let (top, rest) = h.split_at_mut(j);
        let pivot = &rest[0];
        for row in top.iter_mut() {
            if row[j].is_empty() || row[j].len() < pivot[j].len() {
                continue;
            }
            let q = if j < first {
                row[j].clone()
            } else {
                modular::div_rem(f, &row[j], &pivot[j]).0
            };
            for t in j..n {
                row[t] = modular::sub(f, &row[t], &modular::mul(f, &q, &pivot[t]));
            }
            reduce_row(f, row, m);
        }
    }
    Some((h, first))
}

/// `a mod p` for a rational polynomial (`None` when p divides its
/// denominator).
fn image(f: Fp, e: &QPoly) -> Option<UP> {
    let d = f.reduce(e.den());
    if d == 0 {
        return None;
    }
    let di = f.prep(f.inv(d));
    Some(modular::trim(
        e.num().iter().map(|c| f.mul_pre(di, f.reduce(c))).collect(),
    ))
}

/// The positions `(i, t, len)` of the unknown coefficients: entries
/// above the diagonal in the trailing columns (degree below the pivot's),
/// and the trailing pivots without their leading 1.
fn layout(n: usize, first: usize, pivot_deg: &[usize]) -> Vec<Vec<(usize, usize)>> {
    (0..n)
        .map(|i| {
            let from = if i < first { first } else { i };
            (from..n).map(|t| (t, pivot_deg[t - first])).collect()
        })
        .collect()
}

/// One row's residues mod the running modulus, with its reconstruction.
struct RowState {
    residues: Vec<BigInt>,
    candidate: Option<(Vec<BigInt>, BigInt)>,
    done: bool,
}

/// The reduced Hermite basis of `L(A) + c_loc·Q[x]ⁿ` and its `first`,
/// from images modulo word primes (see the module documentation); `None`
/// when a prime's pivot degrees differ from the first's, or no
/// reconstruction is confirmed within `MAX_PRIMES` primes.
#[allow(clippy::type_complexity)]
pub fn local_hermite_modular(a: &[Vec<QPoly>], c_loc: &QPoly) -> Option<(Vec<Vec<QPoly>>, usize)> {
    let n = a.len();
    let mut shape: Option<(usize, Vec<usize>)> = None;
    let mut states: Vec<RowState> = Vec::new();
    let mut layout_rows: Vec<Vec<(usize, usize)>> = Vec::new();
    let mut m = BigInt::one();
    for (count, p) in modular::primes().take(MAX_PRIMES).enumerate() {
        let f = Fp::new(p);
        let Some(mp) = image(f, c_loc) else {
            continue;
        };
        if mp.len() != c_loc.num().len() {
            continue;
        }
        let Some(rows) = a
            .iter()
            .map(|row| row.iter().map(|e| image(f, e)).collect::<Option<Vec<UP>>>())
            .collect::<Option<Vec<_>>>()
        else {
            continue;
        };
        let (h, first) = local_p(f, rows, &mp)?;
        let pivot_deg: Vec<usize> = (first..n).map(|t| h[t][t].len() - 1).collect();
        match &shape {
            None => {
                layout_rows = layout(n, first, &pivot_deg);
                states = layout_rows
                    .iter()
                    .map(|row| RowState {
                        residues: vec![BigInt::zero(); row.iter().map(|(_, l)| l).sum()],
                        candidate: None,
                        done: false,
                    })
                    .collect();
                shape = Some((first, pivot_deg));
            }
            Some((f0, d0)) if *f0 != first || *d0 != pivot_deg => return None,
            Some(_) => {}
        }
        let minv = f.inv(f.reduce(&m));
        let mut all_done = true;
        for ((i, st), lay) in states.iter_mut().enumerate().zip(&layout_rows) {
            if st.done {
                continue;
            }
            let img: Vec<u64> = lay
                .iter()
                .flat_map(|&(t, len)| (0..len).map(move |k| (t, k)))
                .map(|(t, k)| h[i][t].get(k).copied().unwrap_or(0))
                .collect();
            if let Some((nums, den)) = &st.candidate
                && modular::agrees(f, nums, den, &img)
            {
                st.done = true;
                continue;
            }
            for (c, &r) in st.residues.iter_mut().zip(&img) {
                *c = modular::crt(c, &m, r, f, minv);
            }
            all_done = false;
        }
        if all_done {
            break;
        }
        m *= BigInt::from(p);
        if count >= 1 {
            for st in states.iter_mut().filter(|s| !s.done) {
                st.candidate = modular::rational_reconstruct_vec(&st.residues, &m, &BigInt::one());
            }
        }
    }
    let (first, pivot_deg) = shape?;
    if states.iter().any(|s| !s.done) {
        return None;
    }
    let mut out = vec![vec![QPoly::from_ints(Vec::new()); n]; n];
    for (i, (st, lay)) in states.iter().zip(&layout_rows).enumerate() {
        let (nums, den) = st.candidate.as_ref()?;
        let mut k = 0;
        for &(t, len) in lay {
            let mut coeffs: Vec<BigInt> = nums[k..k + len].to_vec();
            k += len;
            if t == i {
                coeffs.push(den.clone());
            }
            out[i][t] = QPoly::new(coeffs, den.clone());
        }
        if i < first {
            out[i][i] = QPoly::from_ints(vec![BigInt::one()]);
        }
    }
    debug_assert!(pivot_deg.iter().all(|&d| d > 0));
    Some((out, first))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::ring::{GcdDomain, Ring};
    use crate::algebra::smith::nonsingular::{FastPath, try_fast};
    use crate::algebra::smith::trailing::{local_hermite, repeated_part, tests::planted};

    fn p(c: &[i64]) -> QPoly {
        QPoly::from_ints(c.iter().map(|&x| BigInt::from(x)).collect())
    }

    #[test]
    fn modular_local_basis_equals_the_elimination_over_q() {
        let chains = [
            vec![p(&[-1, 1]), p(&[-2, 1, 1])],
            vec![p(&[-1, 1]), p(&[-2, 1, 1]), p(&[0, -2, 1, 1])],
            vec![p(&[1, 0, 1]), p(&[1, 0, 2, 0, 1])],
        ];
        let mut checked = 0;
        for (seed, chain) in chains.iter().enumerate() {
            for n in [5, 8] {
                let a = planted(n, chain, 3 + seed as u64);
                let r = a.ring.clone();
                let Some(FastPath::NoHermite { c, b }) = try_fast(&a, u64::MAX) else {
                    panic!("planted chains have several non-trivial factors");
                };
                // c_loc as the trailing route computes it.
                let g = (0..n).fold(r.zero(), |g, j| r.gcd(&g, b.get(n - 1, j)));
                let f = r.normalize(&c);
                let (c_loc, _) = repeated_part(&r, &f, &g).expect("split");
                let rows: Vec<Vec<QPoly>> = (0..n).map(|i| a.row(i).to_vec()).collect();
                let exact = local_hermite(&a, &c_loc).expect("exact");
                let modular = local_hermite_modular(&rows, &c_loc).expect("modular");
                assert_eq!(exact, modular, "n = {n}, chain {seed}");
                checked += 1;
            }
        }
        assert_eq!(checked, 6);
    }
}
