//! Fast gcd of big integers by Lehmer's method (Knuth, TAOCP vol. 2,
//! Algorithm 4.5.2L): Euclid's quotients are simulated on the leading 62
//! bits, and the accumulated 2×2 cofactor matrix is applied to the full
//! numbers once per word, instead of num-bigint's bit-by-bit binary gcd.
//! Profiling showed gcd dominating Q\[x\] arithmetic (≈80% of a 10×10 Smith
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
    let (a, b) = if a.bits() >= b.bits() { (a, b) } else { (b, a) };
    if b.bits() <= 64 {
        // A word: a mod b by one pass of word divisions.
        let Some(y) = b.iter_u64_digits().next() else {
            return a.clone();
        };
        let r = a
            .iter_u64_digits()
            .rev()
            .fold(0u128, |r, l| ((r << 64) | u128::from(l)) % u128::from(y)) as u64;
        return BigUint::from(y.gcd(&r));
    }
    // The binary route takes about two steps per bit of the larger number
    // where Euclid's first quotient would take them all at once: very
    // unequal sizes start with one division.
    let g = if a.bits() > b.bits() + 64 {
        gcd_binary(b, &(a % b))
    } else {
        gcd_binary(a, b)
    };
    g.unwrap_or_else(|| gcd_lehmer(a, b))
}

/// [`gcd_nat`] by Lehmer's method (the route above [`BIN_LIMBS`] limbs).
fn gcd_lehmer(a: &BigUint, b: &BigUint) -> BigUint {
    let (mut a, mut b) = if a >= b {
        (a.to_u64_digits(), b.to_u64_digits())
    } else {
        (b.to_u64_digits(), a.to_u64_digits())
    };
    let (mut na, mut nb) = (Vec::new(), Vec::new());
    while bits(&b) > 64 {
        if less(&a, &b) {
            std::mem::swap(&mut a, &mut b);
        }
        let shift = bits(&a) - 62;
        let (ca, cb, cc, cd) = lehmer_step(window(&a, shift), window(&b, shift), 0);
        if cb == 0 {
            // Not even the first quotient is certain: one full division.
            let r = (nat(&a) % nat(&b)).to_u64_digits();
            a = std::mem::replace(&mut b, r);
            continue;
        }
        // The cofactors keep both results non-negative (lehmer_step's
        // condition), so the one-pass combination cannot fail; the
        // num-bigint form remains for safety.
        if combine(&a, &b, ca, cb, &mut na) && combine(&a, &b, cc, cd, &mut nb) {
            std::mem::swap(&mut a, &mut na);
            std::mem::swap(&mut b, &mut nb);
        } else {
            let (ai, bi) = (
                BigInt::from_biguint(Sign::Plus, nat(&a)),
                BigInt::from_biguint(Sign::Plus, nat(&b)),
            );
            let x = &ai * ca + &bi * cb;
            let y = &ai * cc + &bi * cd;
            a = x.magnitude().to_u64_digits();
            b = y.magnitude().to_u64_digits();
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

/// The largest inputs (in 64-bit limbs) [`gcd_binary`] takes.
const BIN_LIMBS: usize = 16;

/// gcd of two naturals of at most [`BIN_LIMBS`] limbs by the binary
/// algorithm with 31 steps per pass on two-word approximations (Pornin,
/// "Optimized binary GCD for modular inversion", 2020, Alg. 2), on the
/// stack; `None` for larger inputs (or, as a safeguard, when it has not
/// converged within its bound), then Lehmer's route runs.
///
/// After the common power of two is set aside both numbers are odd, and
/// `b` stays odd: a pass repeats "if a is odd: if a < b swap; a ← a − b;
/// then a ← a/2" 31 times on `ã = (a mod 2^31) + 2^31·⌊a/2^(ℓ−33)⌋`
/// and the same `b̃` (ℓ the larger bit length), recording the factors
/// with `2^31·(a', b') = (f0·a + g0·b, f1·a + g1·b)`. The low 31 bits are
/// exact, so every parity decision is the true one and the division by
/// 2^31 is exact; a comparison on the approximations may be wrong, which
/// can only make a value negative (then it is negated). Each operation
/// (swap, subtract, halve an even number while the other is odd, negate)
/// keeps the gcd, and no value ever exceeds the larger input.
fn gcd_binary(a: &BigUint, b: &BigUint) -> Option<BigUint> {
    if a.is_zero() {
        return Some(b.clone());
    }
    if b.is_zero() {
        return Some(a.clone());
    }
    let la = a.bits().div_ceil(64) as usize;
    let lb = b.bits().div_ceil(64) as usize;
    if la > BIN_LIMBS || lb > BIN_LIMBS {
        return None;
    }
    let mut x = [0u64; BIN_LIMBS];
    let mut y = [0u64; BIN_LIMBS];
    for (d, w) in x.iter_mut().zip(a.iter_u64_digits()) {
        *d = w;
    }
    for (d, w) in y.iter_mut().zip(b.iter_u64_digits()) {
        *d = w;
    }
    let mut n = la.max(lb);
    let (ta, tb) = (shr_odd(&mut x[..n]), shr_odd(&mut y[..n]));
    let k = ta.min(tb);
    // Each pass takes at least 31 bits off the total length (Pornin,
    // Thm. 1, for two-word approximations); twice that is the safeguard.
    let mut passes_left = 2 * (128 * n).div_ceil(31) + 4;
    let (mut nx, mut ny) = ([0u64; BIN_LIMBS], [0u64; BIN_LIMBS]);
    loop {
        while n > 0 && x[n - 1] == 0 && y[n - 1] == 0 {
            n -= 1;
        }
        if x[..n].iter().all(|&w| w == 0) {
            return Some(nat(&y[..n]) << k);
        }
        if n <= 1 {
            return Some(BigUint::from(x[0].gcd(&y[0])) << k);
        }
        if passes_left == 0 {
            return None;
        }
        passes_left -= 1;
        let len = 64 * n as u64 - u64::from(x[n - 1].leading_zeros().min(y[n - 1].leading_zeros()));
        const LOW: u64 = (1 << 31) - 1;
        let mut xa = (x[0] & LOW) | (window(&x[..n], len - 33) << 31);
        let mut ya = (y[0] & LOW) | (window(&y[..n], len - 33) << 31);
        let (mut f0, mut g0, mut f1, mut g1) = (1i64, 0i64, 0i64, 1i64);
        for _ in 0..31 {
            // Branch-free: masks of all ones for "a odd" and "swap".
            let odd = 0u64.wrapping_sub(xa & 1);
            let swap = odd & 0u64.wrapping_sub(u64::from(xa < ya));
            let t = (xa ^ ya) & swap;
            xa ^= t;
            ya ^= t;
            let sw = swap as i64;
            let t = (f0 ^ f1) & sw;
            f0 ^= t;
            f1 ^= t;
            let t = (g0 ^ g1) & sw;
            g0 ^= t;
            g1 ^= t;
            let o = odd as i64;
            xa -= ya & odd;
            f0 -= f1 & o;
            g0 -= g1 & o;
            xa >>= 1;
            f1 <<= 1;
            g1 <<= 1;
        }
        if !comb_shift(&x[..n], &y[..n], f0, g0, &mut nx[..n])
            || !comb_shift(&x[..n], &y[..n], f1, g1, &mut ny[..n])
        {
            return None;
        }
        x[..n].copy_from_slice(&nx[..n]);
        y[..n].copy_from_slice(&ny[..n]);
        if y[0] & 1 == 0 {
            return None;
        }
    }
}

/// Shifts `l` right by its number of trailing zero bits (`l` nonzero) and
/// returns that number.
fn shr_odd(l: &mut [u64]) -> u64 {
    let w = l.iter().position(|&d| d != 0).unwrap_or(0);
    let b = l[w].trailing_zeros();
    let n = l.len();
    for i in 0..n {
        let lo = l.get(i + w).copied().unwrap_or(0);
        let hi = l.get(i + w + 1).copied().unwrap_or(0);
        l[i] = if b == 0 {
            lo
        } else {
            (lo >> b) | (hi << (64 - b))
        };
    }
    64 * w as u64 + u64::from(b)
}

/// `out = |f·x + g·y| / 2^31` (`|f|, |g| ≤ 2^31`; the division is exact),
/// `false` if it does not fit `x.len()` limbs.
fn comb_shift(x: &[u64], y: &[u64], f: i64, g: i64, out: &mut [u64]) -> bool {
    let n = x.len();
    let mut t = [0u64; BIN_LIMBS + 1];
    let mut carry = 0i128;
    for i in 0..n {
        // |f·x_i + g·y_i| < 2^96, so no overflow.
        let v = i128::from(f) * i128::from(x[i]) + i128::from(g) * i128::from(y[i]) + carry;
        t[i] = v as u64;
        carry = v >> 64;
    }
    t[n] = carry as u64;
    if carry < 0 {
        // Two's complement negation of the n + 1 limbs.
        let mut c = true;
        for w in t[..=n].iter_mut() {
            let (v, o) = (!*w).overflowing_add(u64::from(c));
            *w = v;
            c = o;
        }
    }
    // Exact by the proof; checked anyway, since a wrong gcd would print a
    // wrong fraction (`false` sends the caller to Lehmer's method).
    if t[0] & ((1 << 31) - 1) != 0 || t[n] >> 31 != 0 {
        return false;
    }
    for i in 0..n {
        out[i] = (t[i] >> 31) | (t[i + 1] << 33);
    }
    true
}

/// Euclid on the leading parts `x ≥ y` (`x < 2^62`) of numbers `a ≥ b`
/// (`x = ⌊a/2^s⌋`, `y = ⌊b/2^s⌋`) as far as its quotients are provably
/// those of `a` and `b`: the cofactors `(A, B, C, D)` with
/// `a' = A·a + B·b`, `b' = C·a + D·b` the remainders after the accepted
/// steps (`B = 0`: none accepted).
///
/// With `r_j = u_j·x + v_j·y` and the true `R_j = u_j·a + v_j·b =
/// 2^s·r_j + u_j·e_a + v_j·e_b` (`0 ≤ e_a, e_b < 2^s`), a step's quotient
/// is right when `0 ≤ R_{j+1} < R_j`. The cofactors alternate in sign, so
/// that holds when `r_{j+1} ≥ max(|u_{j+1}|, |v_{j+1}|)` and `r_j −
/// r_{j+1} ≥ max(|u_j| + |u_{j+1}|, |v_j| + |v_{j+1}|)` (a sufficient
/// form of Jebelean's condition); one word division per step, none for
/// quotient 1. All magnitudes stay below 2^62.
///
/// With `floor > 0` a step is also refused unless `r_{j+1} −
/// max(|u_{j+1}|, |v_{j+1}|) ≥ floor`: since the error term `u·e_a + v·e_b`
/// (opposite signs) is below `max(|u|, |v|)·2^s` in magnitude, the true
/// remainder then exceeds `2^s·floor` ([`euclid_below`] stops Euclid at a
/// bound this way without passing it).
fn lehmer_step(x: u64, y: u64, floor: u64) -> (i128, i128, i128, i128) {
    // (r0, u0, v0) the current pair's first, (r1, u1, v1) its second;
    // signs by parity (u0 ≥ 0 ≥ v0 on even steps, the reverse on odd).
    let (mut r0, mut r1) = (x, y);
    let (mut u0, mut v0, mut u1, mut v1) = (1u64, 0u64, 0u64, 1u64);
    let mut steps = 0u32;
    while r1 != 0 {
        // Small quotients (about three in four) by subtraction.
        let (mut q, mut r2) = (1, r0 - r1);
        while r2 >= r1 && q < 4 {
            r2 -= r1;
            q += 1;
        }
        if r2 >= r1 {
            q = r0 / r1;
            r2 = r0 - q * r1;
        }
        let u2 = u0 + q * u1;
        let v2 = v0 + q * v1;
        if r2 < u2.max(v2).saturating_add(floor) || r1 - r2 < (u1 + u2).max(v1 + v2) {
            break;
        }
        (r0, r1) = (r1, r2);
        (u0, v0, u1, v1) = (u1, v1, u2, v2);
        steps += 1;
    }
    // After an even number of steps the first pair is (u0, −v0) and the
    // second (−u1, v1); after an odd number, the reverse.
    let (u0, v0, u1, v1) = (
        i128::from(u0),
        i128::from(v0),
        i128::from(u1),
        i128::from(v1),
    );
    if steps.is_multiple_of(2) {
        (u0, -v0, -u1, v1)
    } else {
        (-u0, v0, u1, -v1)
    }
}

/// Euclid's remainder sequence `r_0 = a`, `r_1 = b`, `r_{j+1} = r_{j−1} −
/// q_j·r_j` (`a > b`) with the cofactors `t_0 = 0`, `t_1 = 1`, `t_{j+1} =
/// t_{j−1} − q_j·t_j` (so `r_j ≡ t_j·b mod a`), stopped at the first
/// `j ≥ 1` with `r_j ≤ bound`: returns `(r_j, t_j)`. This is the loop of
/// rational reconstruction (Wang), run by Lehmer steps
/// (`lehmer_step` with a floor, so that no accepted step passes the
/// bound) and single divisions where Lehmer's quotients are not certain.
pub fn euclid_below(a: &BigUint, b: &BigUint, bound: &BigUint) -> (BigUint, BigInt) {
    debug_assert!(a > b);
    let (mut a, mut b) = (a.to_u64_digits(), b.to_u64_digits());
    let bl = bound.to_u64_digits();
    let (mut t0, mut t1) = (BigInt::zero(), BigInt::from(1));
    let (mut na, mut nb) = (Vec::new(), Vec::new());
    while less(&bl, &b) {
        let shift = bits(&a).saturating_sub(62);
        // The remainders must stay above bound: r − max(|u|, |v|) ≥
        // ⌊bound/2^s⌋ + 1 makes the true one exceed bound.
        let floor = if bits(&bl) > shift + 62 {
            u64::MAX
        } else {
            window(&bl, shift) + 1
        };
        let (ca, cb, cc, cd) = lehmer_step(window(&a, shift), window(&b, shift), floor);
        if cb != 0 && combine(&a, &b, ca, cb, &mut na) && combine(&a, &b, cc, cd, &mut nb) {
            std::mem::swap(&mut a, &mut na);
            std::mem::swap(&mut b, &mut nb);
            let t = &t0 * BigInt::from(ca) + &t1 * BigInt::from(cb);
            t1 = &t0 * BigInt::from(cc) + &t1 * BigInt::from(cd);
            t0 = t;
            continue;
        }
        // One step of Euclid by a full division.
        let (q, r) = nat(&a).div_rem(&nat(&b));
        a = std::mem::replace(&mut b, r.to_u64_digits());
        let t = &t0 - BigInt::from_biguint(Sign::Plus, q) * &t1;
        t0 = std::mem::replace(&mut t1, t);
    }
    (nat(&b), t1)
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

/// `out = p·a + q·b` for cofactors of at most 62 bits, when it is
/// non-negative, in one pass over the limbs; `false` otherwise.
fn combine(a: &[u64], b: &[u64], p: i128, q: i128, out: &mut Vec<u64>) -> bool {
    const LIMIT: i128 = 1 << 62;
    if p.abs() > LIMIT || q.abs() > LIMIT {
        return false;
    }
    // Lehmer's cofactors have opposite signs: a difference of two
    // word-by-number products, one unsigned multiplication each per limb.
    match (p >= 0, q >= 0) {
        (true, false) => return sub_mul(a, p as u64, b, (-q) as u64, out),
        (false, true) => return sub_mul(b, q as u64, a, (-p) as u64, out),
        _ => {}
    }
    out.clear();
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
        return false;
    }
    while out.last() == Some(&0) {
        out.pop();
    }
    true
}

/// `out = cx·x − cy·y` (cofactors below 2^63) when it is non-negative, in
/// one pass over the limbs; `false` otherwise.
fn sub_mul(x: &[u64], cx: u64, y: &[u64], cy: u64, out: &mut Vec<u64>) -> bool {
    out.clear();
    let (mut cp, mut cn, mut borrow) = (0u64, 0u64, false);
    for i in 0..x.len().max(y.len()) {
        let xi = x.get(i).copied().unwrap_or(0);
        let yi = y.get(i).copied().unwrap_or(0);
        // < 2^63·2^64 + 2^64: no overflow.
        let tp = u128::from(cx) * u128::from(xi) + u128::from(cp);
        let tn = u128::from(cy) * u128::from(yi) + u128::from(cn);
        cp = (tp >> 64) as u64;
        cn = (tn >> 64) as u64;
        let (d1, o1) = (tp as u64).overflowing_sub(tn as u64);
        let (d2, o2) = d1.overflowing_sub(u64::from(borrow));
        out.push(d2);
        borrow = o1 || o2;
    }
    let top = i128::from(cp) - i128::from(cn) - i128::from(borrow);
    if top < 0 {
        return false;
    }
    if top > 0 {
        out.push(top as u64);
    }
    while out.last() == Some(&0) {
        out.pop();
    }
    true
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
            // Both routes, whatever the size.
            prop_assert_eq!(gcd_lehmer(&x, &y), x.gcd(&y));
            if let Some(g) = gcd_binary(&x, &y) {
                prop_assert_eq!(g, x.gcd(&y));
            }
        }
    }

    /// The binary route converges (no fallback) and agrees with
    /// num-integer's gcd on random inputs of 1–16 limbs with planted
    /// common factors and powers of two, on equal, nearly equal and very
    /// unequal sizes, and on consecutive Fibonacci numbers; above 16 limbs
    /// it declines.
    #[test]
    fn binary_gcd_converges_and_agrees() {
        let mut seed = 5u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            seed
        };
        let mut cases: Vec<(BigUint, BigUint)> = Vec::new();
        for round in 0..3000u64 {
            let la = 1 + (round % 16) as usize;
            let a = big(&(0..la).map(|_| next()).collect::<Vec<_>>());
            let lb = 1 + (next() % la as u64) as usize;
            let b = match round % 6 {
                0 => a.clone(),
                1 => &a + BigUint::from(next() % 7),
                2 => big(&(0..lb).map(|_| next()).collect::<Vec<_>>()),
                3 => BigUint::from(next() | 1),
                _ => big(&(0..la).map(|_| next()).collect::<Vec<_>>()),
            };
            let c = big(&(0..(next() % 3) as usize)
                .map(|_| next())
                .collect::<Vec<_>>());
            let c = if c.is_zero() { BigUint::from(1u32) } else { c };
            let (a, b) = if a.bits() + c.bits() <= 64 * 16 && b.bits() + c.bits() <= 64 * 16 {
                (&a * &c, &b * &c)
            } else {
                (a, b)
            };
            let sh = (next() % 100) as u32;
            let (a, b) = if a.bits() + 100 <= 64 * 16 && b.bits() + 100 <= 64 * 16 {
                (a << sh, b << (sh / 2 + (round % 3) as u32))
            } else {
                (a, b)
            };
            cases.push((a, b));
        }
        let (mut f0, mut f1) = (BigUint::from(1u32), BigUint::from(1u32));
        for _ in 0..1400 {
            let f2 = &f0 + &f1;
            f0 = std::mem::replace(&mut f1, f2);
            if f1.bits() <= 64 * 16 {
                cases.push((f1.clone(), f0.clone()));
            }
        }
        for (a, b) in &cases {
            let g = gcd_binary(a, b).expect("converges within its bound");
            assert_eq!(g, a.gcd(b), "{a} {b}");
            assert_eq!(gcd_binary(b, a), Some(g));
        }
        let huge = BigUint::from(3u32) << (64 * 16u32);
        assert_eq!(gcd_binary(&huge, &BigUint::from(6u32)), None);
        assert_eq!(gcd_nat(&huge, &BigUint::from(6u32)), BigUint::from(6u32));
        let one = BigUint::from(1u32);
        assert_eq!(
            gcd_binary(
                &(BigUint::from(1u32) << 900u32),
                &(BigUint::from(1u32) << 700u32)
            ),
            Some(one << 700u32)
        );
    }

    /// Every accepted Lehmer step is a step of Euclid on the full
    /// numbers: `(a', b')` is a consecutive pair of their remainder
    /// sequence, on random inputs, equal and nearly equal ones, and
    /// consecutive Fibonacci numbers (all quotients 1).
    #[test]
    fn lehmer_steps_are_euclid_steps() {
        let mut seed = 11u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            seed
        };
        let mut cases: Vec<(BigUint, BigUint)> = Vec::new();
        for round in 0..400 {
            let la = 2 + round % 5;
            let a = big(&(0..la).map(|_| next()).collect::<Vec<_>>());
            let b = match round % 4 {
                0 => a.clone(),
                1 => &a - BigUint::from(next() % 1000 + 1),
                2 => &a >> (next() % 70),
                _ => big(&(0..la).map(|_| next()).collect::<Vec<_>>()),
            };
            cases.push(if a >= b { (a, b) } else { (b, a) });
        }
        let (mut f0, mut f1) = (BigUint::from(1u32), BigUint::from(1u32));
        for _ in 0..400 {
            let f2 = &f0 + &f1;
            f0 = std::mem::replace(&mut f1, f2);
            if f1.bits() > 65 {
                cases.push((f1.clone(), f0.clone()));
            }
        }
        let mut accepted = 0;
        for (a, b) in cases {
            if b.bits() <= 64 {
                continue;
            }
            let (al, bl) = (a.to_u64_digits(), b.to_u64_digits());
            let shift = bits(&al) - 62;
            let (ca, cb, cc, cd) = lehmer_step(window(&al, shift), window(&bl, shift), 0);
            if cb == 0 {
                continue;
            }
            accepted += 1;
            let (ai, bi) = (BigInt::from(a.clone()), BigInt::from(b.clone()));
            let x = &ai * ca + &bi * cb;
            let y = &ai * cc + &bi * cd;
            let mut out = Vec::new();
            assert!(combine(&al, &bl, ca, cb, &mut out) && nat(&out) == *x.magnitude());
            assert!(combine(&al, &bl, cc, cd, &mut out) && nat(&out) == *y.magnitude());
            // The negated combinations are negative (unless zero): refused.
            if !y.is_zero() {
                assert!(!combine(&al, &bl, -cc, -cd, &mut out));
            }
            let (mut r0, mut r1) = (ai, bi);
            while !(r0 == x && r1 == y) {
                assert!(!r1.is_zero(), "not a Euclid pair: {a} {b}");
                let r = &r0 % &r1;
                r0 = std::mem::replace(&mut r1, r);
            }
        }
        assert!(accepted > 300, "only {accepted} cases took a Lehmer step");
    }

    /// Euclid stopped at a bound, plainly: the reference for
    /// [`euclid_below`].
    fn euclid_below_plain(a: &BigUint, b: &BigUint, bound: &BigUint) -> (BigUint, BigInt) {
        let (mut r0, mut r1) = (BigInt::from(a.clone()), BigInt::from(b.clone()));
        let (mut t0, mut t1) = (BigInt::zero(), BigInt::from(1));
        while r1 > BigInt::from(bound.clone()) {
            let (q, r) = r0.div_rem(&r1);
            r0 = std::mem::replace(&mut r1, r);
            let t = &t0 - &q * &t1;
            t0 = std::mem::replace(&mut t1, t);
        }
        (r1.magnitude().clone(), t1)
    }

    /// Lehmer's Euclid stops at the same remainder and cofactor as the
    /// plain loop: random sizes, bounds at, around and far from √a,
    /// bounds equal to a remainder of the sequence, Fibonacci pairs (all
    /// quotients 1) and single large quotients.
    #[test]
    fn euclid_below_is_plain_euclid_stopped_at_the_bound() {
        let mut seed = 29u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            seed
        };
        let mut lehmer_used = 0;
        for round in 0..1500 {
            let la = 1 + round % 9;
            let a = big(&(0..la).map(|_| next()).collect::<Vec<_>>()) + BigUint::from(2u32);
            let b = match round % 5 {
                0 => &a >> (next() % 90 + 1),
                1 => &a - BigUint::from(next() % 1000 + 1),
                _ => big(&(0..la).map(|_| next()).collect::<Vec<_>>()) % &a,
            };
            let bound = match round % 6 {
                0 => a.sqrt(),
                1 => (&a >> 1u32).sqrt() + BigUint::from(next() % 3),
                2 => &a >> (next() % (64 * la as u64) + 1),
                3 => BigUint::from(next() % 100),
                4 => {
                    // A remainder of the sequence itself.
                    let (mut r0, mut r1) = (a.clone(), b.clone());
                    for _ in 0..next() % 40 {
                        if r1.is_zero() {
                            break;
                        }
                        let r = &r0 % &r1;
                        r0 = std::mem::replace(&mut r1, r);
                    }
                    r1
                }
                _ => BigUint::from(next()),
            };
            let got = euclid_below(&a, &b, &bound);
            assert_eq!(got, euclid_below_plain(&a, &b, &bound), "{a} {b} {bound}");
            if b.bits() > 128 && bound.bits() + 64 < b.bits() {
                lehmer_used += 1;
            }
        }
        let (mut f0, mut f1) = (BigUint::from(1u32), BigUint::from(2u32));
        for i in 0..500 {
            let f2 = &f0 + &f1;
            f0 = std::mem::replace(&mut f1, f2);
            if i % 37 == 0 {
                let bound = f0.sqrt();
                assert_eq!(
                    euclid_below(&f1, &f0, &bound),
                    euclid_below_plain(&f1, &f0, &bound)
                );
            }
        }
        let a = BigUint::from(1u32) << 300u32;
        let b = BigUint::from(3u32);
        assert_eq!(
            euclid_below(&a, &b, &BigUint::from(1u32)),
            euclid_below_plain(&a, &b, &BigUint::from(1u32))
        );
        assert!(lehmer_used > 300, "only {lehmer_used} cases long enough");
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
