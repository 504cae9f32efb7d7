//! Transforms for a nonsingular 2×2 `A = [[a, b], [c, d]]` over Q\[x\]
//! whose first row is coprime, from one Bezout identity `s·a + t·b = 1`:
//! `V = [[s, −b], [t, a]]` (det 1) gives `A·V = [[1, 0], [e, δ]]` with
//! `e = c·s + d·t` and `δ = det A`, and `U = [[1, 0], [−e/κ, 1/κ]]`
//! (κ = lc δ) clears e, so `U·A·V = diag(1, δ/κ)`.
//!
//! s and t have degree below deg b and deg a and coefficients of the size
//! of Res(a, b), where the general nonsingular path's `h = −adj_12·adj_22⁻¹
//! mod det` lives modulo a polynomial of twice the degree (a 2×2 of degree
//! 500: 6.7 s there). s comes from the modular inverse of a modulo b
//! ([`crate::algebra::modgcd::qx_inverse`] through
//! [`QxRing::inverse_mod`]), t by exact division. Anything unexpected
//! returns `None`; the caller certifies the result like any other. This
//! module must not certify or print.

use super::SmithDecomposition;
use super::certify::{ProductCheck, mul_cleared};
use crate::algebra::matrix::Matrix;
use crate::algebra::qx::{QPoly, QxRing};
use crate::algebra::rational::Q;
use crate::algebra::ring::{GcdDomain, Ring};
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// The algorithm's description in reports.
pub const ALGORITHM: &str = "2×2 with a coprime first row: Bezout s·a + t·b = 1 (modular inverse of a mod b, CRT), V = [[s, −b], [t, a]], U clears the (2, 1) entry";

/// Inputs whose entries have at least this degree take this route (below
/// it the general nonsingular path is as fast).
pub const MIN_DEGREE: usize = 32;

/// Above this estimated height of the Bezout coefficients s, t (bits of
/// Res(a, b), from Hadamard's bound on the first row's integer numerators)
/// the modular routes cannot reach them: their images stop at
/// [`crate::algebra::modular::NPRIMES`] word primes (about 31 000 bits),
/// and the exact extended Euclid over Q that remains took 17 s on a 2×2 of
/// degree 50 with one 2 322-bit coefficient, for transforms of millions of
/// digits. `modes.rs` then certifies D alone from `A·adj(A) = det(A)·I`.
pub const MAX_BEZOUT_BITS: f64 = (crate::algebra::modular::NPRIMES * 61) as f64;

/// The estimated height (bits) of the Bezout coefficients of the first
/// row of a 2×2 `A` that [`bezout_2x2`] would take (`None` when it would
/// not): `deg b·log₂‖a‖ + deg a·log₂‖b‖` for the rows' integer numerators.
pub fn bezout_height_bits(a: &Matrix<QxRing>) -> Option<f64> {
    if a.rows() != 2 || a.cols() != 2 {
        return None;
    }
    let max_deg = a.entries().iter().filter_map(|e| e.degree()).max()?;
    if max_deg < MIN_DEGREE {
        return None;
    }
    let (pa, pb) = (a.get(0, 0), a.get(0, 1));
    let (da, db) = (pa.degree()?, pb.degree()?);
    let norm = |p: &QPoly| -> f64 {
        let mx = p.num().iter().map(|c| c.bits()).max().unwrap_or(0) as f64;
        mx + 0.5 * (p.num().len() as f64).log2() + 1.0
    };
    Some(db as f64 * norm(pa) + da as f64 * norm(pb))
}

/// The decomposition described in the module documentation, or `None`
/// (A not 2×2, singular, of low degree, or with a non-coprime first row).
pub fn bezout_2x2(a: &Matrix<QxRing>) -> Option<SmithDecomposition<QxRing>> {
    if a.rows() != 2 || a.cols() != 2 {
        return None;
    }
    let r = a.ring.clone();
    let max_deg = a.entries().iter().filter_map(|e| e.degree()).max()?;
    if max_deg < MIN_DEGREE {
        return None;
    }
    let (pa, pb, pc, pd) = (a.get(0, 0), a.get(0, 1), a.get(1, 0), a.get(1, 1));
    if pa.is_zero() || pb.is_zero() {
        return None;
    }
    // s·a + t·b = 1.
    let (s, t) = if pb.degree() == Some(0) {
        (r.zero(), QPoly::constant(&pb.lc().recip()))
    } else if pa.degree() == Some(0) {
        (QPoly::constant(&pa.lc().recip()), r.zero())
    } else {
        // Coprimality shown modulo a prime first: inverse_mod's exact
        // fallback would be slow at high degree.
        super::certify::coprime_mod_p(&[pa, pb])?;
        bezout_early(&r, pa, pb).or_else(|| {
            let s = r.inverse_mod(pa, pb)?;
            let t = exact_quotient(&r, &r.sub(&r.one(), &r.mul(&s, pa)), pb)?;
            Some((s, t))
        })?
    };
    let delta = r.sub(&r.mul(pa, pd), &r.mul(pb, pc));
    if delta.is_zero() {
        return None;
    }
    let kappa = delta.lc();
    let k_inv = QPoly::constant(&kappa.recip());
    let k_poly = QPoly::constant(&kappa);
    let e = r.add(&r.mul(pc, &s), &r.mul(pd, &t));
    let f = r.normalize(&delta);
    let mat = |v: [QPoly; 4]| Matrix::new(r.clone(), 2, 2, v.to_vec());
    let mut dec = SmithDecomposition {
        d: mat([r.one(), r.zero(), r.zero(), f]),
        u: mat([r.one(), r.zero(), r.neg(&r.mul(&e, &k_inv)), k_inv]),
        v: mat([s.clone(), r.neg(pb), t.clone(), pa.clone()]),
        u_inv: mat([r.one(), r.zero(), e, k_poly]),
        v_inv: mat([pa.clone(), pb.clone(), r.neg(&t), s]),
    };
    super::trailing::integral_rows(&mut dec);
    // D_11 = 1: the scale of V's first column (s, t, denominator
    // Res(a, b)) can move to U's first row, so V prints with integers.
    if let Some(lambda) = primitive_scale(&[dec.v.get(0, 0), dec.v.get(1, 0)]) {
        let lam = QPoly::constant(&lambda);
        let inv = QPoly::constant(&lambda.recip());
        dec.v.scale_col(0, &lam);
        dec.u.scale_row(0, &inv);
        dec.u_inv.scale_col(0, &lam);
        dec.v_inv.scale_row(0, &inv);
    }
    Some(dec)
}

/// `(s, t)` with `s·a + t·b = 1` by images: `s = S/R`, `R = Res(a, b)`,
/// from `S mod p` and `R mod p` ([`modular::inverse_and_resultant`]),
/// Chinese remaindering until R and S stop changing (early termination;
/// the proved bound of [`crate::algebra::modgcd::qx_inverse`] is often a
/// quarter too high), then `t = (1 − s·a)/b` by exact division, which
/// proves the identity. `None` when the images run out or look
/// non-coprime (the caller then takes the bounded route).
fn bezout_early(r: &QxRing, a: &QPoly, b: &QPoly) -> Option<(QPoly, QPoly)> {
    use crate::algebra::modular::{self, Fp, crt, symmetric};
    let (an, bn) = (a.num(), b.num());
    let (la, lb) = (an.last()?, bn.last()?);
    let db = bn.len() - 1;
    let mut s_acc: Vec<BigInt> = vec![BigInt::zero(); db];
    let mut r_acc = BigInt::zero();
    let mut modulus = BigInt::one();
    let mut stable = 0;
    for p in modular::primes().take(modular::NPRIMES / 2) {
        let f = Fp::new(p);
        if f.reduce(la) == 0 || f.reduce(lb) == 0 {
            continue;
        }
        let ap: Vec<u64> = an.iter().map(|c| f.reduce(c)).collect();
        let bp: Vec<u64> = bn.iter().map(|c| f.reduce(c)).collect();
        let (sp, rp) = modular::inverse_and_resultant(f, &ap, &bp)?;
        let minv = f.inv(f.reduce(&modulus));
        let mp = &modulus * p;
        let mut changed = false;
        for (k, c) in s_acc.iter_mut().enumerate() {
            let v = f.mul(sp.get(k).copied().unwrap_or(0), rp);
            let new = symmetric(&crt(c, &modulus, v, f, minv), &mp);
            changed |= new != *c;
            *c = new;
        }
        let new_r = symmetric(&crt(&r_acc, &modulus, rp, f, minv), &mp);
        changed |= new_r != r_acc;
        r_acc = new_r;
        modulus = mp;
        stable = if changed { 0 } else { stable + 1 };
        if stable < 2 || r_acc.is_zero() {
            continue;
        }
        let s = QPoly::new(s_acc.clone(), r_acc.clone());
        let num = r.sub(&r.one(), &r.mul(&s, a));
        if let Some(t) = exact_quotient(r, &num, b) {
            return Some((s, t));
        }
        stable = 0;
    }
    None
}

/// The positive constant making `λ·(p, q)` primitive integer polynomials.
fn primitive_scale(line: &[&QPoly]) -> Option<Q> {
    let l = line.iter().fold(BigInt::one(), |l, e| {
        crate::algebra::intgcd::lcm(&l, e.den())
    });
    let mut g = BigInt::zero();
    for e in line {
        let f = &l / e.den();
        for c in e.num() {
            if g.is_one() {
                break;
            }
            g = crate::algebra::intgcd::gcd(&g, &(c * &f));
        }
    }
    (!g.is_zero()).then(|| Q::new(l, g))
}

/// `x / y` when exact: integer division of the numerators (no
/// pseudo-division, whose scaling by powers of lc(y) would blow up the
/// coefficients), the ring's division when that declines.
pub(super) fn exact_quotient(r: &QxRing, x: &QPoly, y: &QPoly) -> Option<QPoly> {
    if let Some(q) = crate::algebra::modgcd::int_div_exact(x.num(), y.num()) {
        // x = X/dx, y = Y/dy: x/y = (X/Y)·dy/dx.
        return Some(QPoly::new(
            q.into_iter().map(|c| c * y.den()).collect(),
            x.den().clone(),
        ));
    }
    r.div_exact(x, y)
}

/// `X·Y = I` for 2×2 matrices over Q[x], decided as `δ·X = adj Y` with
/// `δ = det Y ≠ 0` (then `X·Y = adj(Y)·Y/δ = I`): one determinant of Y
/// instead of the products `X·Y`, which for `X = V⁻¹`, `Y = V` would
/// multiply s by t.
fn inverse_by_adjugate(x: &Matrix<QxRing>, y: &Matrix<QxRing>) -> bool {
    let r = &y.ring;
    if x.rows() != 2 || x.cols() != 2 {
        return false;
    }
    let (a, b, c, d) = (y.get(0, 0), y.get(0, 1), y.get(1, 0), y.get(1, 1));
    let delta = r.sub(&r.mul(a, d), &r.mul(b, c));
    if delta.is_zero() {
        return false;
    }
    let adj = [d.clone(), r.neg(b), r.neg(c), a.clone()];
    (0..4).all(|k| r.mul(&delta, x.get(k / 2, k % 2)) == adj[k])
}

/// Evaluates `F1·F2·…·Fk` from the right, each product over Z\[x\] as in
/// [`super::certify::ClearedQx`]. For this route `A·V = [[1, 0], [e, δ]]`
/// is small, where `U·A` has entries of degree deg e + deg A whose product
/// with V would multiply two huge polynomials.
pub struct RightFirst;

impl ProductCheck<QxRing> for RightFirst {
    fn product_equals(&self, factors: &[&Matrix<QxRing>], rhs: &Matrix<QxRing>) -> bool {
        if let [x, y] = factors
            && y.rows() == 2
            && y.cols() == 2
            && rhs.is_identity()
        {
            return inverse_by_adjugate(x, y);
        }
        let mut it = factors.iter().rev();
        let Some(last) = it.next() else {
            return false;
        };
        let mut acc = (*last).clone();
        for f in it {
            match mul_cleared(f, &acc) {
                Some(m) => acc = m,
                None => return false,
            }
        }
        acc == *rhs
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn seeded(deg: usize, seed: u64) -> QPoly {
        let mut s = seed;
        QPoly::from_ints(
            (0..=deg)
                .map(|_| {
                    s = s
                        .wrapping_mul(6364136223846793005)
                        .wrapping_add(1442695040888963407);
                    BigInt::from(((s >> 33) % 19) as i64 - 9)
                })
                .collect(),
        )
    }

    #[test]
    fn random_two_by_two_gets_a_certified_decomposition() {
        let r = QxRing::new("x");
        let a = Matrix::new(r.clone(), 2, 2, (0..4).map(|i| seeded(40, 3 + i)).collect());
        let dec = bezout_2x2(&a).expect("coprime first row");
        assert!(dec.certify(&a).verified());
        let det = a.det().expect("square");
        assert_eq!(dec.d.get(1, 1), &r.normalize(&det));
    }

    #[test]
    fn declines_small_degrees_and_a_shared_factor() {
        let r = QxRing::new("x");
        let small = Matrix::new(r.clone(), 2, 2, (0..4).map(|i| seeded(3, i)).collect());
        assert!(bezout_2x2(&small).is_none());
        // First row (x − 1)·p, (x − 1)·q.
        let x1 = QPoly::from_ints(vec![BigInt::from(-1), BigInt::from(1)]);
        let a = Matrix::new(
            r.clone(),
            2,
            2,
            vec![
                r.mul(&x1, &seeded(40, 1)),
                r.mul(&x1, &seeded(40, 2)),
                seeded(40, 3),
                seeded(40, 4),
            ],
        );
        assert!(bezout_2x2(&a).is_none());
    }
}
