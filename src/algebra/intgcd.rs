//! Fast gcd of big integers by Lehmer's method (Knuth, TAOCP vol. 2,
//! Algorithm 4.5.2L): Euclid's quotients are simulated on the leading 62
//! bits, and the accumulated 2×2 cofactor matrix is applied to the full
//! numbers once per word, instead of num-bigint's bit-by-bit binary gcd.
//! Profiling showed gcd dominating Q[x] arithmetic (≈80% of a 10×10 Smith
//! decomposition); this module owns only that routine.

use num_bigint::{BigInt, BigUint, Sign};
use num_integer::Integer;
use num_traits::Zero;

/// gcd of two naturals.
///
/// The numbers are kept as little-endian 64-bit limbs and each Lehmer step
/// applies its cofactor matrix in one pass over the limbs, without
/// allocating; only the rare single large quotient takes a num-bigint
/// division.
pub fn gcd_nat(a: &BigUint, b: &BigUint) -> BigUint {
    let (mut a, mut b) = if a >= b {
        (a.to_u64_digits(), b.to_u64_digits())
    } else {
        (b.to_u64_digits(), a.to_u64_digits())
    };
    while bits(&b) > 64 {
        if less(&a, &b) {
            std::mem::swap(&mut a, &mut b);
        }
        let shift = bits(&a) - 62;
        let x = window(&a, shift);
        let y = window(&b, shift);
        // Cofactors: a' = A·a + B·b, b' = C·a + D·b.
        let (mut ca, mut cb, mut cc, mut cd) = (1i128, 0i128, 0i128, 1i128);
        let (mut x, mut y) = (x as i128, y as i128);
        while y + cc != 0 && y + cd != 0 {
            let q = quot(x + ca, y + cc);
            let q2 = quot(x + cb, y + cd);
            if q != q2 {
                break;
            }
            let t = ca - q * cc;
            ca = cc;
            cc = t;
            let t = cb - q * cd;
            cb = cd;
            cd = t;
            let t = x - q * y;
            x = y;
            y = t;
        }
        let combined = if cb == 0 {
            None
        } else {
            combine(&a, &b, ca, cb).zip(combine(&a, &b, cc, cd))
        };
        match combined {
            Some((na, nb)) => {
                a = na;
                b = nb;
            }
            None if cb == 0 => {
                let r = (nat(&a) % nat(&b)).to_u64_digits();
                a = std::mem::replace(&mut b, r);
            }
            None => {
                // Cofactors too large for the one-pass form (not expected
                // from 62-bit leading parts): the same step in BigInt.
                let (ai, bi) = (
                    BigInt::from_biguint(Sign::Plus, nat(&a)),
                    BigInt::from_biguint(Sign::Plus, nat(&b)),
                );
                let na = &ai * ca + &bi * cb;
                let nb = &ai * cc + &bi * cd;
                a = na.magnitude().to_u64_digits();
                b = nb.magnitude().to_u64_digits();
            }
        }
    }
    let Some(&y) = b.first() else {
        return nat(&a);
    };
    // b fits a word now: a mod b by one pass of word divisions.
    let r = a
        .iter()
        .rev()
        .fold(0u128, |r, &l| ((r << 64) | u128::from(l)) % u128::from(y)) as u64;
    BigUint::from(y.gcd(&r))
}

/// The number with these little-endian limbs.
fn nat(limbs: &[u64]) -> BigUint {
    let mut v = Vec::with_capacity(2 * limbs.len());
    for &l in limbs {
        v.push(l as u32);
        v.push((l >> 32) as u32);
    }
    BigUint::new(v)
}

/// The bit length of a normalised limb vector (no leading zero limbs).
fn bits(l: &[u64]) -> u64 {
    l.last().map_or(0, |&top| {
        64 * l.len() as u64 - u64::from(top.leading_zeros())
    })
}

/// Whether `a < b` (both normalised).
fn less(a: &[u64], b: &[u64]) -> bool {
    a.len() < b.len() || (a.len() == b.len() && a.iter().rev().lt(b.iter().rev()))
}

/// `⌊l / 2^shift⌋ mod 2^64` (the caller makes it fit 62 bits).
fn window(l: &[u64], shift: u64) -> u64 {
    let (w, o) = ((shift / 64) as usize, (shift % 64) as u32);
    let lo = l.get(w).copied().unwrap_or(0);
    let hi = l.get(w + 1).copied().unwrap_or(0);
    if o == 0 {
        lo
    } else {
        (lo >> o) | (hi << (64 - o))
    }
}

/// `p·a + q·b` for cofactors of at most 62 bits, when it is non-negative,
/// in one pass over the limbs; `None` otherwise.
fn combine(a: &[u64], b: &[u64], p: i128, q: i128) -> Option<Vec<u64>> {
    const LIMIT: i128 = 1 << 62;
    if p.abs() > LIMIT || q.abs() > LIMIT {
        return None;
    }
    let mut out = Vec::with_capacity(a.len());
    let mut carry = 0i128;
    for i in 0..a.len().max(b.len()) {
        let x = i128::from(a.get(i).copied().unwrap_or(0));
        let y = i128::from(b.get(i).copied().unwrap_or(0));
        // |p·x + q·y| < 2^127 - 2^64 since |p|, |q| ≤ 2^62 and x, y < 2^64.
        let t = p * x + q * y + carry;
        out.push(t as u64);
        carry = t >> 64;
    }
    if carry != 0 {
        return None;
    }
    while out.last() == Some(&0) {
        out.pop();
    }
    Some(out)
}

/// `a / b` (truncated, like `i128` division), in one word division when
/// both fit 64 bits (they do in the Lehmer steps above: 62-bit leading
/// parts plus cofactors), which is several times faster than `i128`'s.
#[inline]
fn quot(a: i128, b: i128) -> i128 {
    match (i64::try_from(a), i64::try_from(b)) {
        (Ok(a), Ok(b)) => a
            .checked_div(b)
            .map_or_else(|| a as i128 / b as i128, i128::from),
        _ => a / b,
    }
}

/// gcd of two integers (non-negative).
pub fn gcd(a: &BigInt, b: &BigInt) -> BigInt {
    BigInt::from_biguint(Sign::Plus, gcd_nat(a.magnitude(), b.magnitude()))
}

/// lcm of two integers (non-negative; zero if either is zero).
pub fn lcm(a: &BigInt, b: &BigInt) -> BigInt {
    if a.is_zero() || b.is_zero() {
        return BigInt::zero();
    }
    let g = gcd(a, b);
    (a / g * b).magnitude().clone().into()
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn big(words: &[u64]) -> BigUint {
        words
            .iter()
            .fold(BigUint::zero(), |acc, &w| (acc << 64u32) + BigUint::from(w))
    }

    proptest! {
        #[test]
        fn agrees_with_binary_gcd(a in proptest::collection::vec(any::<u64>(), 0..12),
                                  b in proptest::collection::vec(any::<u64>(), 0..12),
                                  c in proptest::collection::vec(any::<u64>(), 0..6)) {
            let (a, b, c) = (big(&a), big(&b), big(&c));
            // A planted common factor makes nontrivial gcds likely.
            let (x, y) = (&a * &c, &b * &c);
            prop_assert_eq!(gcd_nat(&x, &y), x.gcd(&y));
            prop_assert_eq!(gcd_nat(&a, &b), a.gcd(&b));
        }
    }

    #[test]
    fn word_quotients_are_i128_quotients() {
        let vals: [i128; 10] = [
            0,
            1,
            -1,
            7,
            -7,
            i64::MAX as i128,
            i64::MIN as i128,
            i64::MAX as i128 + 1,
            i64::MIN as i128 - 1,
            1 << 62,
        ];
        for &a in &vals {
            for &b in vals.iter().filter(|&&b| b != 0) {
                assert_eq!(quot(a, b), a / b, "{a} / {b}");
            }
        }
    }

    #[test]
    fn edge_cases() {
        let z = BigUint::zero();
        let five = BigUint::from(5u32);
        assert_eq!(gcd_nat(&z, &z), z);
        assert_eq!(gcd_nat(&z, &five), five);
        assert_eq!(gcd(&BigInt::from(-12), &BigInt::from(18)), BigInt::from(6));
        assert_eq!(lcm(&BigInt::from(4), &BigInt::from(6)), BigInt::from(12));
    }
}
