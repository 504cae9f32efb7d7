//! Invariant factors of a nonsingular A over Q\[x\] with any number of
//! non-trivial factors, certified without transforms of A: from
//! `A·B = c·I` (B and c exact, from [`super::detadj`]) and a Hermite basis
//! of the row lattice modulo the repeated part of c
//! ([`super::trailing::hnf_mod`]), whose small trailing block alone goes
//! through the general elimination.
//!
//! Notation: `L(M)` is the row lattice `Q[x]ⁿ·M`; `f_1 | … | f_n` are the
//! invariant factors of A (monic); at an irreducible p they have
//! exponents `e_1 ≤ … ≤ e_n`. The certificate ([`certify_factors`]):
//!
//! 1. `A·B = c·I` exactly, `c ≠ 0`: A is nonsingular and `B = c·A⁻¹`.
//! 2. `g` divides every entry of B exactly and some quotients have gcd 1
//!    (modulo a prime keeping the first one's degree), so `g = gcd(B)`.
//!    Locally at p, `A = P·diag(p^e_i)·Q` with P, Q invertible, and the
//!    least valuation of the entries of a matrix does not change under
//!    invertible factors, so `min v_p(B_ij) = v_p(c) − e_n`: hence
//!    `f_n ~ c/g`, whatever the relation of c to det A.
//! 3. `deg det A = D`: the determinant of A modulo a prime p dividing no
//!    denominator of A, B, c nor the leading coefficient of c, by values at
//!    `N + 1` points (N the row/column degree bound). Reduction mod p is a
//!    ring map, so `det A_p · det B_p = c_pⁿ`, whose degree is `n·deg c`;
//!    reduction cannot raise a degree and over Q also
//!    `deg det A + deg det B = n·deg c`, so `deg det A = deg det A_p`.
//! 4. `H = [[I, h], [0, T]]` (T k×k) and a Smith decomposition
//!    `U_T·T·V_T = D_T` of T, certified from scratch ([`mod@super::certify`]):
//!    then the invariant factors of H are `t = (1, …, 1, diag D_T)`.
//! 5. `L(A) ⊆ L(H)`: `A·H⁻¹ = [A_1, (A_2 − A_1·h)·T⁻¹]` and
//!    `T⁻¹ = V_T·D_T⁻¹·U_T`, so it suffices that every column s of
//!    `(A_2 − A_1·h)·V_T` is divisible by `(D_T)_ss`. Then
//!    `Q[x]ⁿ/L(H)` is a quotient of `Q[x]ⁿ/L(A)`, and for each p the
//!    dimension of `p^j·M/p^(j+1)·M` (the number of exponents above j)
//!    can only drop in a quotient M, so `t_i | f_i` for every i (both
//!    sorted by divisibility; Newman, *Integral Matrices*, Thm II.15).
//! 6. `Σ_(i<n) deg t_i + deg(c/g) = D = Σ_i deg f_i`: with 2 and
//!    `t_i | f_i` this forces `f_i = t_i` for every `i < n`.
//!
//! Nothing is trusted from the algorithms that produced B, c, H or the
//! Smith form of T; only completeness depends on them (c_loc must carry
//! every prime of `f_(n−1)`, as it does when `c ~ det A`). This module
//! must not print or choose modes.

use super::SmithDecomposition;
use super::certify::{Certificate, coprime_mod_p, push_product_check};
use crate::algebra::matrix::Matrix;
use crate::algebra::modgcd::{int_div_exact, qx_gcd};
use crate::algebra::modular::{self, Fp};
use crate::algebra::qx::{QPoly, QxRing};
use crate::algebra::ring::{GcdDomain, Ring};
use num_bigint::BigInt;

/// The algorithm's description in reports.
pub const ALGORITHM: &str = "det and adj by images mod word primes (CRT above a proved bound); invariant factors from A·B = c·I without transforms: f_n = c/gcd(B) (modular gcd, exact division, quotients coprime mod p), deg det A from one prime, the others from the Smith form of the trailing block T of a Hermite basis H = [[I, h], [0, T]] modulo the repeated part of c, with L(A) ⊆ L(H) checked and the degrees adding up to deg det A";

/// Trailing blocks up to this size are eliminated (with transforms) to
/// certify their Smith form; beyond it the route declines.
pub const MAX_BLOCK: usize = 16;

/// Whether B's nonzero entries are shown coprime modulo a prime (the
/// test [`super::certify::certify_last_factor`] makes): when not, that
/// certificate would fail and the caller skips it.
pub fn entries_coprime(b: &Matrix<QxRing>) -> bool {
    let entries: Vec<&QPoly> = b.entries().iter().filter(|e| !e.is_zero()).collect();
    coprime_mod_p(&entries).is_some()
}

/// The primitive integer gcd g of B's nonzero entries (as numerators) and
/// the quotients of all of them by g (all: the entries of one row of B can
/// share a factor the other rows lack, as a sparse A's nearly diagonal
/// adjugate does; the coprimality proof stops at the first quotients whose
/// images have gcd 1), or `None` when an entry is not divisible by the
/// final g (never, unless the modular gcd gave up).
fn entry_gcd(b: &Matrix<QxRing>) -> Option<(Vec<BigInt>, Vec<QPoly>)> {
    let entries: Vec<&QPoly> = b.entries().iter().filter(|e| !e.is_zero()).collect();
    let mut g: Vec<BigInt> = entries.first()?.num().to_vec();
    // Primitive with a positive leading coefficient.
    g = qx_gcd(&g, &g)?;
    for e in &entries[1..] {
        if g.len() == 1 {
            break;
        }
        if int_div_exact(e.num(), &g).is_none() {
            g = qx_gcd(&g, e.num())?;
        }
    }
    // g now divides the entries it was built from; every entry is divided
    // again here (the proof does not rely on the loop above).
    let mut quotients = Vec::with_capacity(entries.len());
    for e in &entries {
        let q = int_div_exact(e.num(), &g)?;
        quotients.push(QPoly::from_ints(q));
    }
    Some((g, quotients))
}

/// N: the least of the sums of row and of column degrees of A, a bound on
/// `deg det A`.
pub fn degree_bound(a: &Matrix<QxRing>) -> usize {
    let n = a.rows();
    let deg = |p: &QPoly| p.degree().unwrap_or(0);
    let row_sum: usize = (0..n)
        .map(|i| (0..a.cols()).map(|j| deg(a.get(i, j))).max().unwrap_or(0))
        .sum();
    let col_sum: usize = (0..a.cols())
        .map(|j| (0..n).map(|i| deg(a.get(i, j))).max().unwrap_or(0))
        .sum();
    row_sum.min(col_sum)
}

/// The degree of the polynomial of degree ≤ N taking `values[i]` at
/// `i = 0, …, N` over Z_p (Newton's divided differences; `None` for zero).
fn degree_from_values(f: Fp, values: &[u64]) -> Option<usize> {
    let mut d = values.to_vec();
    let mut top = None;
    for k in 0..d.len() {
        if d[k] != 0 {
            top = Some(k);
        }
        for i in (k + 1..d.len()).rev() {
            // d[i] ← (d[i] − d[i−1]) / (x_i − x_(i−k−1)) with x_i = i.
            let num = f.sub(d[i], d[i - 1]);
            d[i] = f.mul(num, f.inv((k + 1) as u64));
        }
    }
    // d[k] is now the k-th divided difference f[x_0..x_k]: the coefficient
    // of the Newton basis polynomial of degree k.
    top
}

/// Step 3: `(deg det A, p)`.
fn det_degree(a: &Matrix<QxRing>, b: &Matrix<QxRing>, c: &QPoly) -> Option<(usize, u64)> {
    let lc = c.num().last()?;
    let p = modular::primes().find(|&p| {
        let f = Fp::new(p);
        f.reduce(lc) != 0
            && f.reduce(c.den()) != 0
            && a.entries()
                .iter()
                .chain(b.entries())
                .all(|e| f.reduce(e.den()) != 0)
    })?;
    Some((det_degree_mod(a, p)?, p))
}

/// The degree of `det A mod p` (`None` when it is zero, or when p divides
/// a denominator of A or is too small for the values at `0, …, N`, N
/// [`degree_bound`]): a lower bound on `deg det A`, since reduction mod p
/// is a ring map and cannot raise a degree.
pub(super) fn det_degree_mod(a: &Matrix<QxRing>, p: u64) -> Option<usize> {
    let n = a.rows();
    let bound = degree_bound(a);
    if bound as u64 + 1 >= p || a.cols() != n {
        return None;
    }
    let f = Fp::new(p);
    if a.entries().iter().any(|e| f.reduce(e.den()) == 0) {
        return None;
    }
    let img: Vec<Vec<u64>> = a
        .entries()
        .iter()
        .map(|e| {
            let dinv = f.inv(f.reduce(e.den()));
            e.num().iter().map(|x| f.mul(f.reduce(x), dinv)).collect()
        })
        .collect();
    let mut values = Vec::with_capacity(bound + 1);
    let mut m = vec![0u64; n * n];
    for x in 0..=bound as u64 {
        for (s, e) in m.iter_mut().zip(&img) {
            *s = modular::eval(f, e, x);
        }
        values.push(super::minors_cert::det_mod(f, &mut m, n));
    }
    degree_from_values(f, &values)
}

/// Certifies the invariant factors of a square nonsingular A over Q\[x\]
/// from `A·B = c·I` as described in the module documentation, and returns
/// all n of them (monic). An empty vector means "not established"; the
/// certificate says which step failed.
pub fn certify_factors(
    a: &Matrix<QxRing>,
    c: &QPoly,
    b: &Matrix<QxRing>,
) -> (Certificate, Vec<QPoly>) {
    let r = &a.ring;
    let n = a.rows();
    let mut cert = Certificate { checks: Vec::new() };
    let square = n >= 2 && n == a.cols() && b.rows() == n && b.cols() == n && !c.is_zero();
    if !push_product_check(
        &mut cert,
        a,
        c,
        b,
        square,
        "fails (or c = 0, or A is not square)",
    ) {
        return (cert, Vec::new());
    }
    // 2. gcd(B) = g, so f_n ~ c/g.
    let gcd = entry_gcd(b);
    let proof = gcd.as_ref().and_then(|(_, q)| {
        let refs: Vec<&QPoly> = q.iter().collect();
        coprime_mod_p(&refs)
    });
    let g = gcd.map(|(g, _)| QPoly::from_ints(g));
    let f_last = g
        .as_ref()
        .and_then(|g| r.div_exact(c, g))
        .map(|q| r.normalize(&q));
    let ok2 = proof.is_some() && f_last.is_some();
    cert.push(
        "f_n = c/gcd(B)",
        ok2,
        match (&g, proof) {
            (Some(g), Some((p, k))) if ok2 => format!(
                "g = {} (degree {}) divides every entry of B exactly and the gcd of the first {k} quotients is 1 modulo p = {p}, which keeps the first one's degree; so gcd(B) ~ g, and as min v_p(B_ij) = v_p(c) − v_p(f_n) for B = c·A⁻¹, f_n ~ c/g",
                r.format(g),
                g.degree().unwrap_or(0)
            ),
            _ => "the gcd of B's entries was not established".to_string(),
        },
    );
    let (Some(g), Some(f_last), true) = (g, f_last, ok2) else {
        return (cert, Vec::new());
    };
    // 3. deg det A.
    let dd = det_degree(a, b, c);
    cert.push(
        "deg det A = D",
        dd.is_some(),
        match dd {
            Some((d, p)) => format!(
                "D = {d}: det A mod p = {p} (p divides no denominator of A, B, c nor lc(c)) from its values at 0, …, {}; det A_p·det B_p = c_pⁿ has degree n·deg c, so no degree dropped mod p",
                degree_bound(a)
            ),
            None => "no suitable prime".to_string(),
        },
    );
    let Some((big_d, _)) = dd else {
        return (cert, Vec::new());
    };
    if g.degree() == Some(0) {
        // One non-trivial factor: f_n has the whole degree or the claim fails.
        let ok = f_last.degree() == Some(big_d);
        cert.push(
            "invariant factors 1, …, 1, f_n",
            ok,
            format!(
                "gcd(B) = 1 and deg(c/g) = {} against deg det A = {big_d}",
                f_last.degree().unwrap_or(0)
            ),
        );
        if !ok {
            return (cert, Vec::new());
        }
        let mut f = vec![r.one(); n - 1];
        f.push(f_last);
        return (cert, f);
    }
    // 4. H from the local Hermite basis modulo the repeated part of c.
    let block = local_block(a, c, &g);
    let Some((first, h, t, perm)) = block else {
        cert.push(
            "Hermite basis modulo the repeated part of c",
            false,
            format!(
                "declined (the repeated part has degree above {} or the trailing block is larger than {MAX_BLOCK}×{MAX_BLOCK})",
                super::trailing::MAX_LOCAL_DEGREE
            ),
        );
        return (cert, Vec::new());
    };
    let k = n - first;
    let st = SmithDecomposition::new(&t);
    let tcert = st.certify(&t);
    let t_ok = tcert.verified() && st.d.diagonal().iter().all(|e| !e.is_zero());
    cert.push(
        "Smith form of the trailing block T",
        t_ok,
        if t_ok {
            format!(
                "U_T·T·V_T = D_T, U_T·U_T⁻¹ = I, V_T·V_T⁻¹ = I and the divisibility chain of D_T checked exactly for the {k}×{k} block T of H = [[I, h], [0, T]]"
            )
        } else {
            "the elimination's decomposition of T failed its certificate".to_string()
        },
    );
    if !t_ok {
        return (cert, Vec::new());
    }
    // 5. L(A·P) ⊆ L(H), P the column permutation of step 4 (A·P has A's
    // invariant factors).
    let moved = perm.iter().enumerate().any(|(s, &j)| s != j);
    let ap = if moved {
        permute_columns(a, &perm)
    } else {
        a.clone()
    };
    let contained = contained_in(&ap, first, &h, &st);
    cert.push(
        "L(A) ⊆ L(H)",
        contained,
        if contained {
            format!(
                "every column s of (A_2 − A_1·h)·V_T is divisible by (D_T)_ss, so A·H⁻¹ is polynomial{}; hence each invariant factor t_i of H divides f_i",
                if moved {
                    " (A with its columns permuted so that the unit pivots of the local Hermite basis come first: same invariant factors)"
                } else {
                    ""
                }
            )
        } else {
            "A·H⁻¹ is not polynomial".to_string()
        },
    );
    if !contained {
        return (cert, Vec::new());
    }
    // 6. Degrees.
    let dt = st.d.diagonal();
    let sum: usize = dt[..k - 1].iter().map(|e| e.degree().unwrap_or(0)).sum();
    let total = sum + f_last.degree().unwrap_or(0);
    let t_prev = if k >= 2 { dt[k - 2].clone() } else { r.one() };
    let chain = r.div_exact(&f_last, &t_prev).is_some();
    let ok = total == big_d && chain;
    cert.push(
        "invariant factors 1, …, 1, t_(n−k+1), …, t_(n−1), c/g",
        ok,
        format!(
            "Σ_(i<n) deg t_i + deg(c/g) = {sum} + {} = {total} against deg det A = {big_d}{}",
            f_last.degree().unwrap_or(0),
            if ok {
                ": with t_i | f_i this gives f_i = t_i for i < n"
            } else if !chain {
                "; t_(n−1) does not divide c/g"
            } else {
                ""
            }
        ),
    );
    if !ok {
        return (cert, Vec::new());
    }
    let mut f = vec![r.one(); first];
    f.extend(dt[..k - 1].iter().cloned());
    f.push(f_last);
    (cert, f)
}

/// `(first, h, T)`: `H = [[I, h], [0, T]]` from the Hermite basis
/// `[[U_1, h′], [0, T]]` of `L(A) + c_loc·Q[x]ⁿ` ([`super::trailing::hnf_mod`];
/// c_loc the part of c supported on g's roots, U_1 unit upper triangular)
/// with `h = U_1⁻¹·h′` by back substitution modulo c_loc (only the k
/// trailing columns: the leading block is never reduced). How h is
/// obtained does not matter to the certificate, which checks this H.
#[allow(clippy::type_complexity)]
fn local_block(
    a: &Matrix<QxRing>,
    c: &QPoly,
    g: &QPoly,
) -> Option<(usize, Matrix<QxRing>, Matrix<QxRing>, Vec<usize>)> {
    let r = &a.ring;
    let n = a.rows();
    let (c_loc, _) = super::trailing::repeated_part(r, &r.normalize(c), &r.normalize(g))?;
    if c_loc.degree()? > super::trailing::MAX_LOCAL_DEGREE {
        return None;
    }
    let mut rows: Vec<Vec<QPoly>> = (0..n).map(|i| a.row(i).to_vec()).collect();
    let mut hl = super::trailing::hnf_mod(r, &rows, &c_loc)?;
    let unit = |hl: &[Vec<QPoly>], i: usize| hl[i][i].degree() == Some(0);
    let mut perm: Vec<usize> = (0..n).collect();
    let first0 = (0..n).find(|&i| !unit(&hl, i))?;
    if (first0..n).any(|i| unit(&hl, i)) {
        // A non-unit pivot before unit ones (sparse inputs): the unit-pivot
        // columns S have full rank modulo every prime of c_loc (H[S, S] is
        // unit triangular and H = W·A with W invertible there), so with S
        // first the non-unit pivots come last and T is as small as it can
        // be for this lattice.
        perm = (0..n)
            .filter(|&i| unit(&hl, i))
            .chain((0..n).filter(|&i| !unit(&hl, i)))
            .collect();
        rows = rows
            .iter()
            .map(|row| perm.iter().map(|&j| row[j].clone()).collect())
            .collect();
        hl = super::trailing::hnf_mod(r, &rows, &c_loc)?;
    }
    let first = (0..n).find(|&i| hl[i][i].degree() != Some(0))?;
    let k = n - first;
    if !(1..=MAX_BLOCK).contains(&k) || (0..first).any(|i| !r.is_one(&hl[i][i])) {
        return None;
    }
    // Back substitution, last row first: h_i = h′_i − Σ_(i<j<first) U_ij·h_j.
    let mut h: Vec<Vec<QPoly>> = vec![Vec::new(); first];
    for i in (0..first).rev() {
        let row: Vec<QPoly> = (0..k)
            .map(|s| {
                let acc = r.dot(
                    &mut (i + 1..first)
                        .filter(|&j| !hl[i][j].is_zero())
                        .map(|j| (&hl[i][j], &h[j][s])),
                );
                let e = r.sub(&hl[i][first + s], &acc);
                if e.degree() >= c_loc.degree() {
                    r.rem(&e, &c_loc)
                } else {
                    e
                }
            })
            .collect();
        h[i] = row;
    }
    let mut hm = Matrix::zeros(r.clone(), first, k);
    for (i, row) in h.into_iter().enumerate() {
        for (s, e) in row.into_iter().enumerate() {
            hm.set(i, s, e);
        }
    }
    let mut t = Matrix::zeros(r.clone(), k, k);
    for q in 0..k {
        for s in 0..k {
            t.set(q, s, hl[first + q][first + s].clone());
        }
    }
    Some((first, hm, t, perm))
}

/// A with its columns in the order `perm` (column s is A's column perm[s]).
fn permute_columns(a: &Matrix<QxRing>, perm: &[usize]) -> Matrix<QxRing> {
    let data = (0..a.rows())
        .flat_map(|i| perm.iter().map(move |&j| a.get(i, j).clone()))
        .collect();
    Matrix::new(a.ring.clone(), a.rows(), perm.len(), data)
}

/// Step 5: every column s of `(A_2 − A_1·h)·V_T` divisible by `(D_T)_ss`.
fn contained_in(
    a: &Matrix<QxRing>,
    first: usize,
    h: &Matrix<QxRing>,
    st: &SmithDecomposition<QxRing>,
) -> bool {
    let r = &a.ring;
    let n = a.rows();
    let k = n - first;
    for i in 0..n {
        let m: Vec<QPoly> = (0..k)
            .map(|s| {
                let ah = r.dot(&mut (0..first).map(|t| (a.get(i, t), h.get(t, s))));
                r.sub(a.get(i, first + s), &ah)
            })
            .collect();
        for s in 0..k {
            let x = r.dot(&mut (0..k).map(|q| (&m[q], st.v.get(q, s))));
            let d = st.d.get(s, s);
            if d.is_zero() || !r.rem(&x, d).is_zero() {
                return false;
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::smith::nonsingular::{FastPath, try_fast};

    fn p(c: &[i64]) -> QPoly {
        QPoly::from_ints(c.iter().map(|&x| BigInt::from(x)).collect())
    }

    use crate::algebra::smith::trailing::tests::planted;

    fn cb(a: &Matrix<QxRing>) -> (QPoly, Matrix<QxRing>) {
        match try_fast(a, 0) {
            Some(FastPath::FormOnly { c, b, .. }) => (c, b),
            _ => panic!("nonsingular input with a non-constant det"),
        }
    }

    #[test]
    fn degree_from_values_finds_the_degree() {
        let f = Fp::new(modular::primes().next().expect("a prime"));
        // 3x² − x + 5 at 0..=5.
        let vals: Vec<u64> = (0..6u64)
            .map(|x| f.add(f.sub(f.mul(3, f.mul(x, x)), x), 5))
            .collect();
        assert_eq!(degree_from_values(f, &vals), Some(2));
        assert_eq!(degree_from_values(f, &[0, 0, 0]), None);
        assert_eq!(degree_from_values(f, &[7, 7, 7]), Some(0));
    }

    #[test]
    fn chains_of_two_three_and_four_factors_are_certified() {
        let r = QxRing::new("x");
        let chains = [
            vec![p(&[-1, 1]), p(&[-2, 1, 1])],
            vec![p(&[-1, 1]), p(&[-2, 1, 1]), p(&[0, -2, 1, 1])],
            vec![p(&[1, 1]), p(&[1, 1]), p(&[1, 2, 1]), p(&[0, 1, 2, 1])],
        ];
        for (seed, chain) in chains.iter().enumerate() {
            let n = 8;
            let a = planted(n, chain, 5 + seed as u64);
            let (c, b) = cb(&a);
            let (cert, f) = certify_factors(&a, &c, &b);
            assert!(cert.verified(), "{cert:#?}");
            assert_eq!(f.len(), n);
            // The elimination agrees on every factor.
            let full = SmithDecomposition::new(&a).invariant_factors();
            assert_eq!(f, full);
            for (s, fac) in chain.iter().take(chain.len() - 1).enumerate() {
                assert_eq!(f[n - chain.len() + s], r.normalize(fac));
            }
        }
    }

    #[test]
    fn tampered_inputs_are_rejected() {
        let r = QxRing::new("x");
        let chain = [p(&[-1, 1]), p(&[-2, 1, 1]), p(&[0, -2, 1, 1])];
        let a = planted(7, &chain, 3);
        let (c, b) = cb(&a);
        assert!(certify_factors(&a, &c, &b).0.verified());
        // A tampered B breaks A·B = c·I.
        let mut bad = b.clone();
        bad.set(0, 1, r.add(b.get(0, 1), &r.one()));
        let (cert, f) = certify_factors(&a, &c, &bad);
        assert!(!cert.checks[0].ok && f.is_empty());
        // c and B both times (x + 5): A·B = c·I holds and gcd(B) grows by
        // the same factor, so f_n is unchanged; the claim stays right.
        let x5 = p(&[5, 1]);
        let mut b5 = b.clone();
        for i in 0..7 {
            b5.scale_row(i, &x5);
        }
        let (cert, f5) = certify_factors(&a, &r.mul(&c, &x5), &b5);
        assert!(cert.verified(), "{cert:#?}");
        assert_eq!(f5, certify_factors(&a, &c, &b).1);
    }

    #[test]
    fn a_superlattice_with_too_small_factors_is_caught_by_the_degrees() {
        // diag(1, x, x, x²): a lattice H = diag(1, 1, x, x²) contains L(A)
        // but has t_3 = 1 < f_3 = x; only the degree count can tell.
        let r = QxRing::new("x");
        let x = p(&[0, 1]);
        let x2 = p(&[0, 0, 1]);
        let mut a = Matrix::identity(r.clone(), 4);
        a.set(1, 1, x.clone());
        a.set(2, 2, x.clone());
        a.set(3, 3, x2.clone());
        let h = Matrix::zeros(r.clone(), 2, 2);
        let mut t = Matrix::identity(r.clone(), 2);
        t.set(1, 1, x2.clone());
        let st = SmithDecomposition::new(&t);
        assert!(contained_in(&a, 2, &h, &st), "L(A) ⊆ L(H) holds");
        let t_deg: usize = st.d.diagonal()[..1]
            .iter()
            .map(|e| e.degree().unwrap_or(0))
            .sum();
        // deg det A = 4, deg f_4 = 2: 0 + 2 ≠ 4.
        assert_ne!(t_deg + 2, 4);
        // And the whole certificate gets the true factors 1, x, x, x².
        let c = r.mul(&r.mul(&x, &x), &x2);
        let b = a.adjugate().expect("square");
        let (cert, f) = certify_factors(&a, &c, &b);
        assert!(cert.verified(), "{cert:#?}");
        assert_eq!(f, vec![r.one(), x.clone(), x, x2]);
    }
}
