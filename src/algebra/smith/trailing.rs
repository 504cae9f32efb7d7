//! Transforms for a nonsingular A over Q\[x\] with several non-trivial
//! invariant factors (e.g. B·diag(1, …, 1, x − 1, (x − 1)(x + 2))·C),
//! where the single-factor Hermite shortcut of [`super::nonsingular`]
//! declines.
//!
//! From `A·B = c·I` (`B = adj(Ã)·Δ`, `c = det Ã`, both exact) the row
//! lattice of A is `L = {r : r·B ≡ 0 mod c}`. With `f = c/lc(c)` split as
//! `f = c_loc·c_gen`, `c_loc` the part of f supported on the roots of a
//! multiple of the gcd of B's entries (there the rank of B drops by more
//! than one) and `c_gen` coprime to it:
//! - modulo `c_gen` the rows of B are proportional, so `e_i + h_i·e_n`
//!   with `h_i = −B_ij·B_nj⁻¹ mod c_gen` lies in L locally (as in the
//!   single-factor shortcut);
//! - modulo `c_loc` (small degree) the Hermite form of `L + c_loc·Q[x]ⁿ`
//!   is computed by elimination modulo `c_loc` (Cohen's HNF modulo D,
//!   Algorithm 2.4.8, in row form).
//!
//! The two are glued by the Chinese remainder theorem into
//! `H = [[I, h], [0, T]]` with T k×k upper triangular, `W = H·B/c`
//! (exact division, so W is polynomial and `W·A = H`), and the Smith form
//! of the small block T by the general elimination. Anything unexpected
//! returns `None` and the caller falls back; the result is certified by
//! the caller like any other decomposition. This module must not certify
//! or print.

use super::SmithDecomposition;
use super::small::SmallDecomposition;
use crate::algebra::intgcd;
use crate::algebra::matrix::Matrix;
use crate::algebra::qx::{QPoly, QxRing};
use crate::algebra::rational::Q;
use crate::algebra::ring::{EuclideanDomain, GcdDomain, Ring};
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// The trailing block is eliminated in full; beyond this size the route
/// declines.
pub const MAX_TRAILING: usize = 8;

/// `c_loc` of larger degree is not worth an elimination modulo it.
pub const MAX_LOCAL_DEGREE: usize = 64;

/// Monic gcd over Q: modular first, Euclid over Q when that declines.
fn gcd_q(r: &QxRing, a: &QPoly, b: &QPoly) -> QPoly {
    if a.is_zero() {
        return r.normalize(b);
    }
    if b.is_zero() {
        return r.normalize(a);
    }
    match crate::algebra::modgcd::qx_gcd(a.num(), b.num()) {
        Some(g) => r.normalize(&QPoly::from_ints(g)),
        None => r.gcd(a, b),
    }
}

/// `(u, v, g)` with `u·a + v·b = g`, g the monic gcd (a, b not both 0).
fn xgcd(r: &QxRing, a: &QPoly, b: &QPoly) -> Option<(QPoly, QPoly, QPoly)> {
    if b.is_zero() {
        let inv = QPoly::constant(&a.lc().recip());
        return Some((inv, r.zero(), r.normalize(a)));
    }
    if a.is_zero() {
        let inv = QPoly::constant(&b.lc().recip());
        return Some((r.zero(), inv, r.normalize(b)));
    }
    if b.degree() == Some(0) {
        return Some((r.zero(), QPoly::constant(&b.lc().recip()), r.one()));
    }
    let (g, u) = r.ext_gcd_mod(a, b);
    let v = r.div_exact(&r.sub(&g, &r.mul(&u, a)), b)?;
    Some((u, v, g))
}

fn reduce_row(r: &QxRing, row: &mut [QPoly], m: &QPoly) {
    for e in row.iter_mut() {
        if e.degree() >= m.degree() {
            *e = r.rem(e, m);
        }
    }
}

/// The Hermite basis (upper triangular, monic diagonal, each row reduced
/// modulo the modulus current at its step) of the row lattice
/// `rows + m·Q[x]ⁿ`, for a monic `m` that is a multiple of that lattice's
/// determinant (Cohen, Algorithm 2.4.8, transposed). The product of the
/// diagonal is then the determinant.
pub fn hnf_mod(r: &QxRing, rows: &[Vec<QPoly>], m: &QPoly) -> Option<Vec<Vec<QPoly>>> {
    let n = rows.len();
    let mut w: Vec<Vec<QPoly>> = rows.to_vec();
    let mut modulus = m.clone();
    for row in w.iter_mut() {
        reduce_row(r, row, &modulus);
    }
    let mut h = Vec::with_capacity(n);
    for j in 0..n {
        if modulus.degree() == Some(0) {
            // Everything left is the identity.
            let mut e = vec![r.zero(); n];
            e[j] = r.one();
            h.push(e);
            continue;
        }
        // A pivot invertible modulo the modulus: scale its row to a 1 there
        // (a polynomial multiple stays in the lattice, and the row is
        // recovered from it modulo the modulus) and clear the column below
        // by plain subtraction: no Bezout cofactors, whose heights compound.
        let unit = (j..n).find_map(|i| {
            (!w[i][j].is_zero())
                .then(|| r.inverse_mod(&w[i][j], &modulus))
                .flatten()
                .map(|s| (i, s))
        });
        if let Some((p, inv)) = unit {
            w.swap(j, p);
            let mut row: Vec<QPoly> = w[j].iter().map(|e| r.mul(e, &inv)).collect();
            reduce_row(r, &mut row, &modulus);
            for e in row.iter_mut().take(j) {
                *e = r.zero();
            }
            row[j] = r.one();
            for wi in w.iter_mut().skip(j + 1) {
                let q = wi[j].clone();
                if q.is_zero() {
                    continue;
                }
                for t in j..n {
                    wi[t] = r.sub(&wi[t], &r.mul(&q, &row[t]));
                }
                reduce_row(r, wi, &modulus);
                make_primitive(wi);
            }
            h.push(row);
            continue;
        }
        for i in j + 1..n {
            if w[i][j].is_zero() {
                continue;
            }
            if w[j][j].is_zero() {
                w.swap(i, j);
                continue;
            }
            let (u, v, g) = xgcd(r, &w[j][j], &w[i][j])?;
            let a = r.div_exact(&w[j][j], &g)?;
            let b = r.div_exact(&w[i][j], &g)?;
            let mut new_j = Vec::with_capacity(n);
            let mut new_i = Vec::with_capacity(n);
            for (x, y) in w[j].iter().zip(&w[i]) {
                new_j.push(r.add(&r.mul(&u, x), &r.mul(&v, y)));
                new_i.push(r.sub(&r.mul(&a, y), &r.mul(&b, x)));
            }
            reduce_row(r, &mut new_j, &modulus);
            reduce_row(r, &mut new_i, &modulus);
            // A constant factor is a unit of Q[x]: rows stay in the lattice,
            // and their heights stay small.
            make_primitive(&mut new_j);
            make_primitive(&mut new_i);
            w[j] = new_j;
            w[i] = new_i;
        }
        let (d, s) = r.ext_gcd_mod(&w[j][j], &modulus);
        let mut hj: Vec<QPoly> = w[j].iter().map(|e| r.mul(&s, e)).collect();
        reduce_row(r, &mut hj, &modulus);
        for e in hj.iter_mut().take(j) {
            *e = r.zero();
        }
        hj[j] = d.clone();
        h.push(hj);
        modulus = r.div_exact(&modulus, &d)?;
        for row in w.iter_mut().skip(j + 1) {
            reduce_row(r, row, &modulus);
        }
    }
    Some(h)
}

/// `f = c_loc·c_gen` (both monic, f monic): `c_loc` the part of f
/// supported on the roots of `g` (with f's multiplicities), `c_gen`
/// coprime to g.
pub fn repeated_part(r: &QxRing, f: &QPoly, g: &QPoly) -> Option<(QPoly, QPoly)> {
    let mut c_loc = r.one();
    let mut c_gen = f.clone();
    let mut u = gcd_q(r, &c_gen, g);
    while u.degree().is_some_and(|d| d > 0) {
        c_loc = r.mul(&c_loc, &u);
        c_gen = r.div_exact(&c_gen, &u)?;
        u = gcd_q(r, &c_gen, &u);
    }
    Some((r.normalize(&c_loc), r.normalize(&c_gen)))
}

/// The Hermite basis of the row lattice `L(A) + c_loc·Q[x]ⁿ` ([`hnf_mod`],
/// `c_loc` monic and a multiple of that lattice's determinant), reduced:
/// entries above a unit pivot cleared, entries above a trailing pivot
/// reduced modulo it, all modulo `c_loc`. Returns the rows and `first`,
/// the index of the first pivot that is not 1 (rows before it are
/// `e_i + (entries in columns ≥ first)`).
pub fn local_hermite(a: &Matrix<QxRing>, c_loc: &QPoly) -> Option<(Vec<Vec<QPoly>>, usize)> {
    let r = a.ring.clone();
    let n = a.rows();
    let rows: Vec<Vec<QPoly>> = (0..n).map(|i| a.row(i).to_vec()).collect();
    let mut h_loc = hnf_mod(&r, &rows, c_loc)?;
    let first = (0..n).find(|&i| h_loc[i][i].degree() != Some(0))?;
    // Pivot columns in increasing order, so later columns are reduced
    // after they change.
    for j in 0..n {
        let (top, rest) = h_loc.split_at_mut(j);
        let pivot = &rest[0];
        for row in top.iter_mut() {
            if row[j].is_zero() || row[j].degree() < pivot[j].degree() {
                continue;
            }
            let q = if j < first {
                row[j].clone()
            } else {
                r.div_rem(&row[j], &pivot[j]).0
            };
            for t in j..n {
                row[t] = r.sub(&row[t], &r.mul(&q, &pivot[t]));
            }
            reduce_row(&r, row, c_loc);
        }
    }
    Some((h_loc, first))
}

/// The decomposition described in the module documentation, or `None`.
/// `c = det Ã` and `B = adj(Ã)·Δ` with `A·B = c·I`.
///
/// When the local basis has a non-unit pivot before unit ones (sparse
/// inputs, whose column order puts a repeated root early), the route
/// works on `A·P` with the unit-pivot columns first (`P` a permutation;
/// `A·P·P⁻¹·B = c·I`), so the trailing block holds only the non-unit
/// pivots, and returns `V = P·V′` for A itself.
pub fn trailing_hermite(
    a: &Matrix<QxRing>,
    c: &QPoly,
    b: &Matrix<QxRing>,
) -> Option<SmallDecomposition> {
    let r = a.ring.clone();
    let n = a.rows();
    if n < 3 || a.cols() != n || c.is_zero() || c.degree() == Some(0) {
        return None;
    }
    let f = r.normalize(c);
    // gcd(B's entries), the last row and the first column first (they
    // usually settle it); its roots are those of f_1 ⋯ f_(n−1), so c_loc
    // carries no root of f_n alone (for a sparse A the gcd of one row and
    // column of B has many more roots, each a non-unit pivot of the local
    // basis in a column of its own).
    let mut g = r.zero();
    for e in b.row(n - 1).iter().chain((0..n).map(|i| b.get(i, 0))) {
        g = gcd_q(&r, &g, e);
        if g.degree() == Some(0) {
            return None;
        }
    }
    let mut g_int = crate::algebra::modgcd::qx_gcd(g.num(), g.num())?;
    for e in b.entries().iter().filter(|e| !e.is_zero()) {
        if crate::algebra::modgcd::int_div_exact(e.num(), &g_int).is_none() {
            g_int = crate::algebra::modgcd::qx_gcd(&g_int, e.num())?;
            if g_int.len() <= 1 {
                return None;
            }
        }
    }
    let g = QPoly::from_ints(g_int);
    let (c_loc, c_gen) = repeated_part(&r, &f, &g)?;
    if c_loc.degree()? > MAX_LOCAL_DEGREE {
        return None;
    }
    let rows: Vec<Vec<QPoly>> = (0..n).map(|i| a.row(i).to_vec()).collect();
    let modular = super::trailing_mod::local_hermite_modular(&rows, &c_loc);
    // The pivot pattern (unique: the diagonal of a Hermite basis) decides
    // the column order; without a modular basis, the elimination over Q.
    let (h0, first0) = match modular {
        Some(x) => x,
        None => local_hermite(a, &c_loc)?,
    };
    let unit = |i: usize| h0[i][i].degree() == Some(0);
    if !(first0..n).any(unit) {
        let k = n - first0;
        if !(2..=MAX_TRAILING).contains(&k) {
            return None;
        }
        return trailing_with(a, c, (&c_loc, &c_gen), b, Some((h0, first0)));
    }
    let perm: Vec<usize> = (0..n)
        .filter(|&i| unit(i))
        .chain((0..n).filter(|&i| !unit(i)))
        .collect();
    if n - perm.iter().filter(|&&i| unit(i)).count() > MAX_TRAILING {
        return None;
    }
    let ap = Matrix::new(
        r.clone(),
        n,
        n,
        (0..n)
            .flat_map(|i| perm.iter().map(move |&j| a.get(i, j).clone()))
            .collect(),
    );
    let bp = Matrix::new(
        r.clone(),
        n,
        n,
        perm.iter()
            .flat_map(|&s| b.row(s).iter().cloned())
            .collect(),
    );
    let prows: Vec<Vec<QPoly>> = (0..n).map(|i| ap.row(i).to_vec()).collect();
    let pm = super::trailing_mod::local_hermite_modular(&prows, &c_loc);
    let dec = trailing_with(&ap, c, (&c_loc, &c_gen), &bp, pm)?;
    // U·(A·P)·V′ = D, so U·A·(P·V′) = D and (P·V′)⁻¹ = V′⁻¹·P⁻¹.
    let mut v = Matrix::zeros(r.clone(), n, n);
    let mut v_inv = Matrix::zeros(r.clone(), n, n);
    for (s, &j) in perm.iter().enumerate() {
        for t in 0..n {
            v.set(j, t, dec.v.get(s, t).clone());
            v_inv.set(t, j, dec.v_inv.get(t, s).clone());
        }
    }
    Some(SmallDecomposition {
        d: dec.d,
        u: dec.u,
        v,
        v_inv,
    })
}

/// [`trailing_hermite`] for a given column order, with the local Hermite
/// basis from modular images ([`super::trailing_mod`]) when given, or by
/// elimination over Q.
fn trailing_with(
    a: &Matrix<QxRing>,
    c: &QPoly,
    (c_loc, c_gen): (&QPoly, &QPoly),
    b: &Matrix<QxRing>,
    modular: Option<(Vec<Vec<QPoly>>, usize)>,
) -> Option<SmallDecomposition> {
    let r = a.ring.clone();
    let n = a.rows();
    let c_loc = c_loc.clone();
    let c_gen = c_gen.clone();
    let (h_loc, first) = match modular {
        Some(x) => x,
        None => local_hermite(a, &c_loc)?,
    };
    let k = n - first;
    if !(2..=MAX_TRAILING).contains(&k) {
        return None;
    }
    // H = [[I, h], [0, T]]: row i (< n) is d_i·e_i plus h_loc's entries in
    // the trailing columns before the last; the last entry x is glued by
    // CRT: x ≡ h_loc[i][n] (c_loc), and modulo c_gen, where B's rows are
    // proportional (B_t ≡ β_t·w with β_t = B_tj/B_nj), x makes the row's
    // product with B vanish: x ≡ −(d_i·B_ij + Σ_t h_t·B_tj)·B_nj⁻¹.
    let gen_part = c_gen.degree()? > 0;
    let pivot_col = if gen_part {
        let last = b.row(n - 1);
        let mut order: Vec<usize> = (0..n).filter(|&j| !last[j].is_zero()).collect();
        order.sort_by_key(|&j| last[j].degree());
        Some(
            order
                .into_iter()
                .find_map(|j| r.inverse_mod(&last[j], &c_gen).map(|s| (j, s)))?,
        )
    } else {
        None
    };
    // The last entry by CRT modulo t_last = p_last·c_gen (p_last the local
    // pivot, coprime to c_gen): x = far + c_gen·y with
    // y ≡ (h_loc − far)·c_gen⁻¹ (mod p_last), deg y < deg p_last, so x is
    // already reduced modulo t_last.
    let p_last = &h_loc[n - 1][n - 1];
    let gen_inv = if gen_part && p_last.degree()? > 0 {
        Some(r.inverse_mod(&c_gen, p_last)?)
    } else {
        None
    };
    let t_last = r.mul(p_last, &c_gen);
    let mut h = Matrix::zeros(r.clone(), n, n);
    for (i, hl) in h_loc.iter().enumerate().take(n - 1) {
        let d = if i < first { r.one() } else { hl[i].clone() };
        let mid = first.max(i + 1)..n - 1;
        let far = match &pivot_col {
            Some((j, inv)) => {
                let mut acc = r.mul(&d, b.get(i, *j));
                for t in mid.clone() {
                    if !hl[t].is_zero() {
                        acc = r.add(&acc, &r.mul(&hl[t], b.get(t, *j)));
                    }
                }
                r.neg(&r.rem(&r.mul(&acc, inv), &c_gen))
            }
            None => r.zero(),
        };
        let x = match &gen_inv {
            Some(s) => {
                let diff = r.rem(&r.sub(&hl[n - 1], &far), p_last);
                let y = r.rem(&r.mul(&diff, s), p_last);
                r.add(&far, &r.mul(&c_gen, &y))
            }
            None if gen_part => far,
            None => r.rem(&hl[n - 1], &t_last),
        };
        h.set(i, n - 1, x);
        for t in mid {
            h.set(i, t, hl[t].clone());
        }
        h.set(i, i, d);
    }
    h.set(n - 1, n - 1, t_last);
    // Smith form of the trailing block T.
    let idx: Vec<usize> = (first..n).collect();
    let t = h.submatrix(&idx, &idx);
    let st = SmithDecomposition::new(&t);
    if st.d.diagonal().iter().any(|e| e.is_zero()) {
        return None;
    }
    // W = H·B/c exactly, over Z: row i is M_i/(L_i·cont c) with L_i the
    // lcm of the row's denominators and M_i = (Σ_t L_i·H_it·B_t)/pp(c),
    // an integer division by Gauss's lemma (B is integral).
    if !c.den().is_one() || b.entries().iter().any(|e| !e.den().is_one()) {
        return None;
    }
    let cont = c
        .num()
        .iter()
        .fold(BigInt::zero(), |g, x| intgcd::gcd(&g, x));
    let pp: Vec<BigInt> = c.num().iter().map(|x| x / &cont).collect();
    let mut rows: Vec<(Vec<QPoly>, Q)> = Vec::with_capacity(n);
    for i in 0..n {
        let support: Vec<usize> = std::iter::once(i)
            .chain(first.max(i + 1)..n)
            .filter(|&t| !h.get(i, t).is_zero())
            .collect();
        let l = support
            .iter()
            .fold(BigInt::one(), |l, &t| intgcd::lcm(&l, h.get(i, t).den()));
        let scaled: Vec<Vec<BigInt>> = support
            .iter()
            .map(|&t| {
                let e = h.get(i, t);
                let f = &l / e.den();
                e.num().iter().map(|x| x * &f).collect()
            })
            .collect();
        let mut m_row = Vec::with_capacity(n);
        for col in 0..n {
            let mut acc: Vec<BigInt> = Vec::new();
            for (x, &t) in scaled.iter().zip(&support) {
                add_product(&mut acc, x, b.get(t, col).num());
            }
            while acc.last().is_some_and(|x| x.is_zero()) {
                acc.pop();
            }
            m_row.push(crate::algebra::modgcd::int_div_exact(&acc, &pp)?);
        }
        // The row's content g > 0: U_i = M_i/g and λ_i = L_i·cont/g.
        let g = m_row
            .iter()
            .flatten()
            .fold(BigInt::zero(), |g, x| intgcd::gcd(&g, x));
        if g.is_zero() {
            return None;
        }
        let prim: Vec<QPoly> = m_row
            .into_iter()
            .map(|p| QPoly::from_ints(p.into_iter().map(|x| x / &g).collect()))
            .collect();
        rows.push((prim, Q::new(&l * &cont, g)));
    }
    // U = diag(I, U_T)·W: rows before `first` are W's, made primitive
    // (U_i = λ_i·W_i); the trailing rows are combined from W's rows
    // (W_i = U_i/λ_i) and made primitive by their own scale.
    let mut u_mat = Matrix::zeros(r.clone(), n, n);
    let mut lambda: Vec<Q> = Vec::with_capacity(n);
    for (i, (prim, lam)) in rows.iter().enumerate().take(first) {
        for (col, e) in prim.iter().enumerate() {
            u_mat.set(i, col, e.clone());
        }
        lambda.push(lam.clone());
    }
    let w_t: Vec<Vec<QPoly>> = rows[first..]
        .iter()
        .map(|(prim, lam)| {
            let inv = lam.recip();
            prim.iter().map(|e| e.scale(&inv)).collect()
        })
        .collect();
    for s in 0..k {
        let row: Vec<QPoly> = (0..n)
            .map(|col| r.dot(&mut (0..k).map(|q| (st.u.get(s, q), &w_t[q][col]))))
            .collect();
        let lam = primitive_scale(&row).unwrap_or_else(|| Q::from_integer(BigInt::one()));
        for (col, e) in row.iter().enumerate() {
            u_mat.set(first + s, col, e.scale(&lam));
        }
        lambda.push(lam);
    }
    // V = [[I, −h·V_T], [0, V_T]]·Λ⁻¹, V⁻¹ = Λ·[[I, h], [0, V_T⁻¹]].
    let mut v = Matrix::zeros(r.clone(), n, n);
    let mut v_inv = Matrix::zeros(r.clone(), n, n);
    for i in 0..n {
        let (lam, inv) = (&lambda[i], lambda[i].recip());
        if i < first {
            v.set(i, i, QPoly::constant(&inv));
            v_inv.set(i, i, QPoly::constant(lam));
        }
        for s in 0..k {
            let inv_s = lambda[first + s].recip();
            if i < first {
                let e = r.dot(&mut (0..k).map(|q| (h.get(i, first + q), st.v.get(q, s))));
                v.set(i, first + s, r.neg(&e).scale(&inv_s));
                v_inv.set(i, first + s, h.get(i, first + s).scale(lam));
            } else {
                let q = i - first;
                v.set(i, first + s, st.v.get(q, s).scale(&inv_s));
                v_inv.set(i, first + s, st.v_inv.get(q, s).scale(lam));
            }
        }
    }
    let mut d = Matrix::identity(r.clone(), n);
    for s in 0..k {
        d.set(first + s, first + s, st.d.get(s, s).clone());
    }
    Some(SmallDecomposition {
        d,
        u: u_mat,
        v,
        v_inv,
    })
}

/// `acc += x·y` over Z[x] (schoolbook, or Kronecker substitution where
/// [`crate::algebra::qx::kronecker_pays`]).
fn add_product(acc: &mut Vec<BigInt>, x: &[BigInt], y: &[BigInt]) {
    if x.is_empty() || y.is_empty() {
        return;
    }
    let len = x.len() + y.len() - 1;
    if acc.len() < len {
        acc.resize(len, BigInt::zero());
    }
    if crate::algebra::qx::kronecker_pays(x, y) {
        for (s, c) in acc.iter_mut().zip(crate::algebra::qx::conv(x, y)) {
            *s += c;
        }
        return;
    }
    for (i, p) in x.iter().enumerate() {
        if p.is_zero() {
            continue;
        }
        for (j, q) in y.iter().enumerate() {
            acc[i + j] += p * q;
        }
    }
}

/// Scales each row i of U by the constant λ_i that makes it a primitive
/// integer row, and column i of V (and of U⁻¹) by 1/λ_i, row i of V⁻¹ by
/// λ_i: `(ΛU)·A·(VΛ⁻¹) = Λ·D·Λ⁻¹ = D`. U's coefficients then print
/// without a rational normalisation each (the costly part of the report).
pub fn integral_rows(dec: &mut SmithDecomposition<QxRing>) {
    for i in 0..dec.u.rows() {
        let Some(lambda) = primitive_scale(dec.u.row(i)) else {
            continue;
        };
        let inv = QPoly::constant(&lambda.recip());
        let lam = QPoly::constant(&lambda);
        dec.u.scale_row(i, &lam);
        dec.v.scale_col(i, &inv);
        dec.u_inv.scale_col(i, &inv);
        dec.v_inv.scale_row(i, &lam);
    }
}

/// The positive constant λ making `λ·row` a primitive integer row, or
/// `None` when the row is zero or already primitive and integral.
fn primitive_scale(row: &[QPoly]) -> Option<Q> {
    let l = row
        .iter()
        .filter(|e| !e.is_zero())
        .fold(BigInt::one(), |l, e| intgcd::lcm(&l, e.den()));
    let mut g = BigInt::zero();
    for e in row.iter().filter(|e| !e.is_zero()) {
        let f = &l / e.den();
        for c in e.num() {
            if g.is_one() {
                break;
            }
            g = intgcd::gcd(&g, &(c * &f));
        }
    }
    if g.is_zero() || (l.is_one() && g.is_one()) {
        return None;
    }
    Some(Q::new(l, g))
}

fn make_primitive(row: &mut [QPoly]) {
    if let Some(lambda) = primitive_scale(row) {
        for e in row.iter_mut() {
            *e = e.scale(&lambda);
        }
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use num_bigint::BigInt;

    fn p(c: &[i64]) -> QPoly {
        QPoly::from_ints(c.iter().map(|&x| BigInt::from(x)).collect())
    }

    /// B·diag(1, …, 1, chain)·C with B, C small seeded integer matrices of
    /// degree 1 (shared with `hermite_cert`'s tests).
    pub(crate) fn planted(n: usize, chain: &[QPoly], seed: u64) -> Matrix<QxRing> {
        let r = QxRing::new("x");
        let mut s = seed;
        let mut next = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((s >> 33) % 19) as i64 - 9
        };
        let mut rand = |deg: usize| {
            let data: Vec<QPoly> = (0..n * n)
                .map(|_| p(&(0..=deg).map(|_| next()).collect::<Vec<_>>()))
                .collect();
            Matrix::new(r.clone(), n, n, data)
        };
        let bm = rand(1);
        let cm = rand(1);
        let mut dm = Matrix::identity(r.clone(), n);
        for (s, f) in chain.iter().enumerate() {
            let i = n - chain.len() + s;
            dm.set(i, i, f.clone());
        }
        bm.mul(&dm).and_then(|x| x.mul(&cm)).expect("shapes")
    }

    fn run(a: &Matrix<QxRing>) -> Option<SmallDecomposition> {
        match super::super::nonsingular::try_fast(a, u64::MAX)? {
            super::super::nonsingular::FastPath::NoHermite { c, b } => trailing_hermite(a, &c, &b),
            _ => None,
        }
    }

    #[test]
    fn hnf_mod_of_a_small_lattice() {
        // Rows (x, 1), (0, x²): det x³; the Hermite basis of the lattice is
        // [[1, x²·(−1)…]] — checked by its determinant and membership.
        let r = QxRing::new("x");
        let rows = vec![vec![p(&[0, 1]), p(&[1])], vec![p(&[0]), p(&[0, 0, 1])]];
        let m = p(&[0, 0, 0, 1]);
        let h = hnf_mod(&r, &rows, &m).expect("hnf");
        let det = r.mul(&h[0][0], &h[1][1]);
        assert_eq!(det, m);
        assert!(h[1][0].is_zero());
    }

    #[test]
    fn two_and_three_factor_chains_get_certified_transforms() {
        let r = QxRing::new("x");
        let chains = [
            vec![p(&[-1, 1]), p(&[-2, 1, 1])],
            vec![p(&[-1, 1]), p(&[-2, 1, 1]), p(&[0, -2, 1, 1])],
        ];
        for (seed, chain) in chains.iter().enumerate() {
            let a = planted(7, chain, 11 + seed as u64);
            let dec = run(&a).expect("the trailing route applies");
            let cert = super::super::trailing_cert::certify_transforms(&a, &dec);
            assert!(cert.verified(), "{:?}", cert.failures().collect::<Vec<_>>());
            // Independently: U⁻¹ = A·V·D⁻¹ is polynomial and the generic
            // certificate (U·A·V = D, U·U⁻¹ = I, V·V⁻¹ = I) holds.
            let av = a.mul(&dec.v).expect("shapes");
            let mut u_inv = av.clone();
            for j in 0..7 {
                for i in 0..7 {
                    let q = r
                        .div_exact(av.get(i, j), dec.d.get(j, j))
                        .expect("divisible");
                    u_inv.set(i, j, q);
                }
            }
            let full = SmithDecomposition {
                d: dec.d.clone(),
                u: dec.u.clone(),
                v: dec.v.clone(),
                u_inv,
                v_inv: dec.v_inv.clone(),
            };
            assert!(full.certify(&a).verified());
            let inv = full.invariant_factors();
            for (s, f) in chain.iter().take(chain.len() - 1).enumerate() {
                assert_eq!(inv[7 - chain.len() + s], r.normalize(f), "{inv:?}");
            }
            assert!(inv[..7 - chain.len()].iter().all(|e| r.is_one(e)));
        }
    }
}
