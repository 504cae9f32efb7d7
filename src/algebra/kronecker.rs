//! Multiplication of integer polynomials by Kronecker substitution: both
//! factors are packed into one big integer each (coefficient `i` at bit
//! `k·i`, `k` large enough for every product coefficient), multiplied once
//! by num-bigint's subquadratic (Karatsuba/Toom-3) product and unpacked
//! with signed digits. Pays off for long, large-coefficient polynomials,
//! where the schoolbook convolution does `len(a)·len(b)` big products.
//! Owns only this product; [`super::qx`] decides when to use it.

use num_bigint::{BigInt, BigUint, Sign};
use num_traits::Zero;

/// Packs `Σ a_i 2^(k·i)` (signed coefficients, `|a_i| < 2^(k-1)`).
fn pack(a: &[BigInt], k: u64) -> BigInt {
    let words = ((a.len() as u64 * k) / 64 + 2) as usize;
    let mut pos = vec![0u64; words];
    let mut neg = vec![0u64; words];
    for (i, c) in a.iter().enumerate() {
        if c.is_zero() {
            continue;
        }
        let target = if c.sign() == Sign::Minus {
            &mut neg
        } else {
            &mut pos
        };
        let off = k * i as u64;
        let (w0, sh) = ((off / 64) as usize, (off % 64) as u32);
        for (j, d) in c.magnitude().iter_u64_digits().enumerate() {
            // The fields do not overlap, so adding is OR-ing.
            target[w0 + j] |= d << sh;
            if sh > 0 {
                target[w0 + j + 1] |= d >> (64 - sh);
            }
        }
    }
    BigInt::from_biguint(Sign::Plus, BigUint::from_slice(&to_u32(&pos)))
        - BigInt::from_biguint(Sign::Plus, BigUint::from_slice(&to_u32(&neg)))
}

fn to_u32(w: &[u64]) -> Vec<u32> {
    w.iter()
        .flat_map(|&x| [x as u32, (x >> 32) as u32])
        .collect()
}

/// The `k`-bit field at bit `off` of the little-endian words `w`.
fn field(w: &[u64], off: u64, k: u64) -> BigUint {
    let nw = k.div_ceil(64) as usize;
    let (w0, sh) = ((off / 64) as usize, (off % 64) as u32);
    let get = |i: usize| w.get(i).copied().unwrap_or(0);
    let mut out: Vec<u64> = (0..nw)
        .map(|j| {
            let lo = get(w0 + j) >> sh;
            let hi = if sh > 0 {
                get(w0 + j + 1) << (64 - sh)
            } else {
                0
            };
            lo | hi
        })
        .collect();
    let extra = (nw as u64 * 64 - k) as u32;
    if extra > 0 {
        let last = out.len() - 1;
        out[last] &= u64::MAX >> extra;
    }
    BigUint::from_slice(&to_u32(&out))
}

/// Unpacks `n` signed coefficients of width `k` from `c`.
fn unpack(c: &BigInt, k: u64, n: usize) -> Vec<BigInt> {
    let negate = c.sign() == Sign::Minus;
    let w: Vec<u64> = c.magnitude().iter_u64_digits().collect();
    let half = BigUint::from(1u8) << (k - 1);
    let full = BigInt::from(1u8) << k;
    let mut carry = false;
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let mut u = field(&w, k * i as u64, k);
        if carry {
            u += 1u8;
        }
        let v = if u >= half {
            carry = true;
            BigInt::from_biguint(Sign::Plus, u) - &full
        } else {
            carry = false;
            BigInt::from_biguint(Sign::Plus, u)
        };
        out.push(if negate { -v } else { v });
    }
    out
}

/// `a·b` for integer polynomials (lowest coefficient first, nonempty).
pub fn mul(a: &[BigInt], b: &[BigInt]) -> Vec<BigInt> {
    let bits = |v: &[BigInt]| v.iter().map(|c| c.bits()).max().unwrap_or(0);
    let n = a.len().min(b.len()) as u64;
    let k = bits(a) + bits(b) + (64 - n.leading_zeros()) as u64 + 2;
    let c = pack(a, k) * pack(b, k);
    unpack(&c, k, a.len() + b.len() - 1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn school(a: &[BigInt], b: &[BigInt]) -> Vec<BigInt> {
        let mut c = vec![BigInt::zero(); a.len() + b.len() - 1];
        for (i, x) in a.iter().enumerate() {
            for (j, y) in b.iter().enumerate() {
                c[i + j] += x * y;
            }
        }
        c
    }

    proptest! {
        #[test]
        fn agrees_with_the_schoolbook_product(
            a in prop::collection::vec(any::<i128>(), 1..40),
            b in prop::collection::vec(any::<i64>(), 1..40),
            big in 0u32..300,
        ) {
            let a: Vec<BigInt> = a.into_iter().map(|x| BigInt::from(x) << big).collect();
            let b: Vec<BigInt> = b.into_iter().map(BigInt::from).collect();
            prop_assert_eq!(mul(&a, &b), school(&a, &b));
        }
    }

    #[test]
    fn zeros_and_signs() {
        let v = |s: &[i64]| s.iter().map(|&x| BigInt::from(x)).collect::<Vec<_>>();
        assert_eq!(mul(&v(&[0, -1]), &v(&[0, 0, 1])), v(&[0, 0, 0, -1]));
        assert_eq!(mul(&v(&[-5]), &v(&[3, -4])), v(&[-15, 20]));
    }
}
