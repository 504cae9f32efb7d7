//! Word-size modular arithmetic for the modular algorithms: the prime field
//! Z_p with p < 2^62 ([`Fp`]), a deterministic supply of such primes
//! ([`primes`]), dense univariate polynomials over Z_p (Euclid, evaluation)
//! and the Chinese remainder step on big integers. Owns nothing else: the
//! algorithms that use these pieces live in [`super::modgcd`].

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// The prime field Z_p, `p < 2^62` odd, elements in `0..p` (products by
/// Montgomery reduction: two REDC steps instead of a 128-bit division).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Fp {
    /// The modulus.
    pub p: u64,
    /// `-p⁻¹ mod 2^64`.
    pinv: u64,
    /// `2^128 mod p`.
    r2: u64,
}

impl Fp {
    /// Z_p for an odd `p < 2^62`.
    pub fn new(p: u64) -> Self {
        debug_assert!(p % 2 == 1 && p < 1 << 62);
        // Newton iteration for p⁻¹ mod 2^64.
        let mut inv: u64 = 1;
        for _ in 0..6 {
            inv = inv.wrapping_mul(2u64.wrapping_sub(p.wrapping_mul(inv)));
        }
        let r = ((1u128 << 64) % p as u128) as u64;
        let r2 = ((r as u128 * r as u128) % p as u128) as u64;
        Fp {
            p,
            pinv: inv.wrapping_neg(),
            r2,
        }
    }
    #[inline]
    fn redc(self, t: u128) -> u64 {
        let m = (t as u64).wrapping_mul(self.pinv);
        let u = ((t + m as u128 * self.p as u128) >> 64) as u64;
        if u >= self.p { u - self.p } else { u }
    }
    /// `a + b`.
    #[inline]
    pub fn add(self, a: u64, b: u64) -> u64 {
        let s = a + b;
        if s >= self.p { s - self.p } else { s }
    }
    /// `a - b`.
    #[inline]
    pub fn sub(self, a: u64, b: u64) -> u64 {
        if a >= b { a - b } else { a + self.p - b }
    }
    /// `-a`.
    #[inline]
    pub fn neg(self, a: u64) -> u64 {
        if a == 0 { 0 } else { self.p - a }
    }
    /// `a·b`.
    #[inline]
    pub fn mul(self, a: u64, b: u64) -> u64 {
        self.redc(self.redc(a as u128 * b as u128) as u128 * self.r2 as u128)
    }
    /// `c` prepared for repeated products [`Fp::mul_pre`] (Montgomery form).
    #[inline]
    pub fn prep(self, c: u64) -> u64 {
        self.redc(c as u128 * self.r2 as u128)
    }
    /// `c·b` for `cm = prep(c)`: one reduction instead of two.
    #[inline]
    pub fn mul_pre(self, cm: u64, b: u64) -> u64 {
        self.redc(cm as u128 * b as u128)
    }
    /// `t mod p` for `t < p·2^64` (a lazily reduced sum of products),
    /// by two Montgomery reductions instead of a 128-bit division:
    /// `redc(t) = t·2^−64` and `mul_pre(r2, ·)` multiplies by 2^64 again.
    #[inline]
    pub fn reduce_wide(self, t: u128) -> u64 {
        debug_assert!(t < (self.p as u128) << 64);
        self.mul_pre(self.r2, self.redc(t))
    }
    /// `acc + a·b`, kept below `p·2^64` by one conditional subtraction
    /// (`acc < p·2^64` and `a, b < p`); finish with [`Fp::reduce_wide`].
    #[inline]
    pub fn mul_add_wide(self, acc: u128, a: u64, b: u64) -> u128 {
        let top = (self.p as u128) << 64;
        let v = acc + a as u128 * b as u128;
        if v >= top { v - top } else { v }
    }
    /// `a^e`.
    pub fn pow(self, mut a: u64, mut e: u64) -> u64 {
        let mut r = 1 % self.p;
        while e > 0 {
            if e & 1 == 1 {
                r = self.mul(r, a);
            }
            a = self.mul(a, a);
            e >>= 1;
        }
        r
    }
    /// `a⁻¹` (`a` nonzero), by the extended Euclidean algorithm (several
    /// times faster than `a^(p−2)`).
    pub fn inv(self, a: u64) -> u64 {
        debug_assert!(!a.is_multiple_of(self.p));
        // |t| ≤ p < 2^62 throughout, so i64 suffices.
        let (mut r0, mut r1) = (self.p as i64, (a % self.p) as i64);
        let (mut t0, mut t1) = (0i64, 1i64);
        while r1 != 0 {
            let q = r0 / r1;
            (r0, r1) = (r1, r0 - q * r1);
            (t0, t1) = (t1, t0 - q * t1);
        }
        debug_assert_eq!(r0, 1);
        t0.rem_euclid(self.p as i64) as u64
    }
    /// The residue of a big integer.
    pub fn reduce(self, a: &BigInt) -> u64 {
        // Horner on the 64-bit digits from the top: acc·2^64 is
        // `mul_pre(r2, acc)` (r2 = 2^128 mod p is 2^64 in Montgomery form),
        // so no allocation and no 128-bit division.
        let r = a.magnitude().iter_u64_digits().rev().fold(0u64, |acc, d| {
            self.add(self.mul_pre(self.r2, acc), d % self.p)
        });
        if a.is_negative() { self.neg(r) } else { r }
    }
}

/// Deterministic Miller–Rabin for `u64` (these bases are exact below 2^64).
pub fn is_prime(n: u64) -> bool {
    if n < 2 {
        return false;
    }
    for q in [2u64, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37] {
        if n.is_multiple_of(q) {
            return n == q;
        }
    }
    let f = Fp::new(n);
    let (mut d, mut s) = (n - 1, 0);
    while d % 2 == 0 {
        d /= 2;
        s += 1;
    }
    'bases: for a in [2u64, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37] {
        let mut x = f.pow(a, d);
        if x == 1 || x == n - 1 {
            continue;
        }
        for _ in 1..s {
            x = f.mul(x, x);
            if x == n - 1 {
                continue 'bases;
            }
        }
        return false;
    }
    true
}

/// How many primes [`primes`] offers.
pub const NPRIMES: usize = 512;

/// The largest [`NPRIMES`] primes below 2^62, descending. They are found
/// lazily, as far as some caller has asked, and kept for the process (a
/// small input needs two or three of them; finding all 512 costs a few
/// milliseconds, which used to be most of a small `smith` run).
pub fn primes() -> impl Iterator<Item = u64> {
    Primes(0, NPRIMES)
}

/// How many primes [`long_primes`] offers (about 250 000 bits).
pub const NPRIMES_LONG: usize = 4096;

/// A seeded 64-bit linear congruential generator (Knuth's MMIX
/// constants): reproducible random words for the tests and for the
/// null-direction probe's start block (`numeric::solve`).
pub(crate) fn lcg(mut seed: u64) -> impl FnMut() -> u64 {
    move || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        seed
    }
}

/// [`primes`] continued to [`NPRIMES_LONG`] primes, for the routes whose
/// size estimate is known before the first image (the generic Hermite
/// route's h and U rows, `smith::small`): a row-scaled matrix of
/// 45-digit rationals needs about 1 500 of them. The routes that stop only
/// when the primes run out keep [`primes`].
pub fn long_primes() -> impl Iterator<Item = u64> {
    Primes(0, NPRIMES_LONG)
}

/// The k-th of [`primes`] (0-based), `None` beyond [`NPRIMES`].
#[cfg(test)]
pub fn prime(k: usize) -> Option<u64> {
    if k >= NPRIMES {
        return None;
    }
    nth_prime(k)
}

/// The k-th of [`long_primes`], found lazily and kept.
fn nth_prime(k: usize) -> Option<u64> {
    if k >= NPRIMES_LONG {
        return None;
    }
    static FOUND: std::sync::Mutex<Vec<u64>> = std::sync::Mutex::new(Vec::new());
    let mut found = FOUND.lock().unwrap_or_else(|e| e.into_inner());
    while found.len() <= k {
        let mut n = found.last().map_or((1 << 62) - 1, |&p| p - 2);
        while !is_prime(n) {
            n -= 2;
        }
        found.push(n);
    }
    Some(found[k])
}

/// The iterator behind [`primes`] and [`long_primes`] (next index, end).
struct Primes(usize, usize);

impl Iterator for Primes {
    type Item = u64;
    fn next(&mut self) -> Option<u64> {
        if self.0 >= self.1 {
            return None;
        }
        let p = nth_prime(self.0)?;
        self.0 += 1;
        Some(p)
    }
    fn size_hint(&self) -> (usize, Option<usize>) {
        let left = self.1.saturating_sub(self.0);
        (left, Some(left))
    }
}

/// A small deterministic generator of evaluation points.
#[derive(Clone, Debug)]
pub struct Points(u64);

impl Points {
    /// A generator with a fixed seed.
    pub fn new(seed: u64) -> Self {
        Points(seed | 1)
    }
    /// The next point in `1..p`.
    pub fn next(&mut self, f: Fp) -> u64 {
        // xorshift64*
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let r = self.0.wrapping_mul(0x2545_F491_4F6C_DD1D);
        1 + r % (f.p - 1)
    }
}

/// Dense univariate polynomial over Z_p, lowest coefficient first, no
/// trailing zeros (the zero polynomial is empty).
pub type UP = Vec<u64>;

/// Removes trailing zeros.
pub fn trim(mut a: UP) -> UP {
    while a.last() == Some(&0) {
        a.pop();
    }
    a
}

/// Degree (`None` for zero).
pub fn deg(a: &[u64]) -> Option<usize> {
    a.len().checked_sub(1)
}

/// `a(x)` by Horner.
pub fn eval(f: Fp, a: &[u64], x: u64) -> u64 {
    a.iter().rev().fold(0, |acc, &c| f.add(f.mul(acc, x), c))
}

/// `c·a`.
pub fn scale(f: Fp, a: &[u64], c: u64) -> UP {
    if c == 0 {
        return Vec::new();
    }
    let cm = f.prep(c);
    a.iter().map(|&x| f.mul_pre(cm, x)).collect()
}

/// `a·b` (schoolbook).
pub fn mul(f: Fp, a: &[u64], b: &[u64]) -> UP {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    // Accumulate in u128 and reduce rarely: p < 2^62 so 2^4 products fit.
    let mut acc = vec![0u128; a.len() + b.len() - 1];
    for (i, &x) in a.iter().enumerate() {
        if x == 0 {
            continue;
        }
        for (j, &y) in b.iter().enumerate() {
            acc[i + j] = f.mul_add_wide(acc[i + j], x, y);
        }
    }
    trim(acc.into_iter().map(|s| f.reduce_wide(s)).collect())
}

/// `a + b`.
pub fn add(f: Fp, a: &[u64], b: &[u64]) -> UP {
    let n = a.len().max(b.len());
    let v = (0..n)
        .map(|i| {
            f.add(
                a.get(i).copied().unwrap_or(0),
                b.get(i).copied().unwrap_or(0),
            )
        })
        .collect();
    trim(v)
}

/// `a - b`.
pub fn sub(f: Fp, a: &[u64], b: &[u64]) -> UP {
    let n = a.len().max(b.len());
    let v = (0..n)
        .map(|i| {
            f.sub(
                a.get(i).copied().unwrap_or(0),
                b.get(i).copied().unwrap_or(0),
            )
        })
        .collect();
    trim(v)
}

/// Quotient and remainder of `a` by nonzero `b`.
pub fn div_rem(f: Fp, a: &[u64], b: &[u64]) -> (UP, UP) {
    let n = b.len() - 1;
    if a.len() < b.len() {
        return (Vec::new(), a.to_vec());
    }
    let inv = f.inv(b[n]);
    let mut r = a.to_vec();
    let mut q = vec![0u64; a.len() - n];
    for i in (0..q.len()).rev() {
        let c = f.mul(r[i + n], inv);
        q[i] = c;
        if c == 0 {
            continue;
        }
        let cm = f.prep(c);
        for j in 0..=n {
            r[i + j] = f.sub(r[i + j], f.mul_pre(cm, b[j]));
        }
    }
    r.truncate(n);
    (trim(q), trim(r))
}

/// Monic associate (zero stays zero).
pub fn monic(f: Fp, a: &[u64]) -> UP {
    match a.last() {
        None => Vec::new(),
        Some(&l) => scale(f, a, f.inv(l)),
    }
}

/// Monic gcd by Euclid.
pub fn gcd(f: Fp, a: &[u64], b: &[u64]) -> UP {
    let (mut x, mut y) = (a.to_vec(), b.to_vec());
    while !y.is_empty() {
        let r = div_rem(f, &x, &y).1;
        x = y;
        y = r;
    }
    monic(f, &x)
}

/// `(s, Res(a, m))` with `s·a ≡ 1 (mod m)`, `deg s < deg m`, for `a` and
/// `m` with `deg m ≥ 1`; `None` when `gcd(a, m) ≠ 1` (the resultant is 0).
pub fn inverse_and_resultant(f: Fp, a: &[u64], m: &[u64]) -> Option<(UP, u64)> {
    let (da, dm) = (deg(a)?, deg(m)?);
    // Euclid on (m, a), tracking t with t·a ≡ y (mod m) and Res(m, a).
    let (mut x, mut y) = (m.to_vec(), a.to_vec());
    let (mut t0, mut t1): (UP, UP) = (Vec::new(), vec![1]);
    let mut res = 1u64;
    loop {
        let (dx, dy) = (deg(&x)?, deg(&y)?);
        if dy == 0 {
            res = f.mul(res, f.pow(y[0], dx as u64));
            let c = f.inv(y[0]);
            let s = div_rem(f, &scale(f, &t1, c), m).1;
            // Res(a, m) = (−1)^(deg a·deg m) Res(m, a).
            let sign = if (da * dm) % 2 == 1 { f.neg(res) } else { res };
            return Some((s, sign));
        }
        let (q, r) = div_rem(f, &x, &y);
        let dr = deg(&r)?; // r = 0: a common factor
        if (dx * dy) % 2 == 1 {
            res = f.neg(res);
        }
        res = f.mul(res, f.pow(y[dy], (dx - dr) as u64));
        let t = sub(f, &t0, &mul(f, &q, &t1));
        t0 = std::mem::replace(&mut t1, t);
        x = std::mem::replace(&mut y, r);
    }
}

/// `s` with `s·a ≡ 1 (mod m)`, `deg s < deg m` (`deg m ≥ 1`), or `None`
/// when `gcd(a, m) ≠ 1`: [`inverse_and_resultant`]'s `s` without the
/// resultant, by Euclid with pseudo-remainders (each elimination `x ←
/// lc(y)·x − lc(x)·x^k·y` instead of a division by `lc(y)`), so that one
/// inversion is taken at the end instead of one per step.
pub fn inverse_mod(f: Fp, a: &[u64], m: &[u64]) -> Option<UP> {
    let dm = deg(m)?;
    if dm == 0 {
        return None;
    }
    let a = trim(a.to_vec());
    let a = if a.len() > dm { div_rem(f, &a, m).1 } else { a };
    // t0·a ≡ x and t1·a ≡ y (mod m) throughout.
    let (mut x, mut y) = (m.to_vec(), a);
    let (mut t0, mut t1): (UP, UP) = (Vec::new(), vec![1]);
    loop {
        let dy = deg(&y)?;
        if dy == 0 {
            let c = f.prep(f.inv(y[0]));
            let s: UP = t1.iter().map(|&v| f.mul_pre(c, v)).collect();
            let s = trim(s);
            return Some(if s.len() > dm { div_rem(f, &s, m).1 } else { s });
        }
        let c = f.prep(y[dy]);
        while x.len() > dy {
            let k = x.len() - 1 - dy;
            let l = f.prep(x[x.len() - 1]);
            // x ← c·x − l·x^k·y, t0 ← c·t0 − l·x^k·t1.
            for v in x.iter_mut() {
                *v = f.mul_pre(c, *v);
            }
            for (i, &v) in y.iter().enumerate() {
                x[i + k] = f.sub(x[i + k], f.mul_pre(l, v));
            }
            for v in t0.iter_mut() {
                *v = f.mul_pre(c, *v);
            }
            if t0.len() < t1.len() + k {
                t0.resize(t1.len() + k, 0);
            }
            for (i, &v) in t1.iter().enumerate() {
                t0[i + k] = f.sub(t0[i + k], f.mul_pre(l, v));
            }
            x = trim(x);
            t0 = trim(t0);
        }
        if x.is_empty() {
            // y (of degree ≥ 1) divides m and a.
            return None;
        }
        std::mem::swap(&mut x, &mut y);
        std::mem::swap(&mut t0, &mut t1);
    }
}

/// Chinese remainder: the residue `c mod m` (with `c` in `0..m` or the
/// symmetric range) is combined with `r mod p` into a residue mod `m·p`,
/// returned in `0..m·p`. `minv` is `m⁻¹ mod p`.
pub fn crt(c: &BigInt, m: &BigInt, r: u64, f: Fp, minv: u64) -> BigInt {
    let cm = f.reduce(c);
    let t = f.mul(f.sub(r, cm), minv);
    let mut out = c + m * BigInt::from(t);
    if out.is_negative() {
        out += m * BigInt::from(f.p);
    }
    out
}

/// The representative of `c mod m` in `(-m/2, m/2]`.
pub fn symmetric(c: &BigInt, m: &BigInt) -> BigInt {
    let c = c.mod_floor(m);
    if (&c << 1u32) > *m { c - m } else { c }
}

/// Rational reconstruction (Wang): `n/d ≡ c (mod m)` with `|n|, d ≤
/// √(m/2)`, if it exists.
#[cfg(any(test, feature = "internals"))]
pub fn rational_reconstruct(c: &BigInt, m: &BigInt) -> Option<(BigInt, BigInt)> {
    reconstruct_below(c, m, &(m >> 1u32).sqrt())
}

/// [`rational_reconstruct`] with the bound `√(m/2)` given.
fn reconstruct_below(c: &BigInt, m: &BigInt, bound: &BigInt) -> Option<(BigInt, BigInt)> {
    // Euclid on (m, c mod m) until the remainder is at most the bound, by
    // Lehmer steps.
    let c = c.mod_floor(m);
    let (r1, t1) = super::intgcd::euclid_below(m.magnitude(), c.magnitude(), bound.magnitude());
    let r1 = BigInt::from_biguint(num_bigint::Sign::Plus, r1);
    if t1.is_zero() || t1.abs() > *bound {
        return None;
    }
    let (n, d) = if t1.is_negative() {
        (-r1, -t1)
    } else {
        (r1, t1)
    };
    if !super::intgcd::gcd(&n, &d).is_one() {
        return None;
    }
    Some((n, d))
}

/// Rational reconstruction of a vector with one common denominator,
/// starting from the candidate denominator `l` (1 when none is known):
/// `(numerators, denominator)` with every |numerator| and the denominator
/// at most √(m/2), or `None`.
pub fn rational_reconstruct_vec(
    c: &[BigInt],
    m: &BigInt,
    l: &BigInt,
) -> Option<(Vec<BigInt>, BigInt)> {
    rational_reconstruct_vec_below(c, m, &reconstruction_bound(m), l)
}

/// The bound `⌊√(m/2)⌋` of rational reconstruction modulo `m` (for
/// callers that reconstruct many vectors modulo one `m`).
pub fn reconstruction_bound(m: &BigInt) -> BigInt {
    (m >> 1u32).sqrt()
}

/// [`rational_reconstruct_vec`] with `bound` =
/// [`reconstruction_bound`]`(m)` given.
pub fn rational_reconstruct_vec_below(
    c: &[BigInt],
    m: &BigInt,
    bound: &BigInt,
    l: &BigInt,
) -> Option<(Vec<BigInt>, BigInt)> {
    let mut l = l.clone();
    let mut nums: Vec<BigInt> = Vec::with_capacity(c.len());
    let half = m >> 1u32;
    for x in c {
        let xl = x * &l;
        // symmetric(xl, m) without a shifted copy per coefficient.
        let r = xl.mod_floor(m);
        let t = if r > half { r - m } else { r };
        if t.magnitude() <= bound.magnitude() {
            nums.push(t);
            continue;
        }
        let (nn, dd) = reconstruct_below(&xl, m, bound)?;
        // x ≡ nn/(dd·l): scale what came before by dd.
        for v in nums.iter_mut() {
            *v *= &dd;
        }
        l *= dd;
        if l > *bound {
            return None;
        }
        nums.push(nn);
    }
    Some((nums, l))
}

/// Whether the rational vector `nums/den` reduces to `r` modulo `f` (a
/// denominator divisible by p never agrees).
pub fn agrees(f: Fp, nums: &[BigInt], den: &BigInt, r: &[u64]) -> bool {
    let d = f.reduce(den);
    if d == 0 {
        return false;
    }
    let dm = f.prep(d);
    nums.iter()
        .zip(r)
        .all(|(x, &y)| f.reduce(x) == f.mul_pre(dm, y))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn primes_are_prime_and_descending() {
        let ps: Vec<u64> = primes().take(5).collect();
        assert!(ps.windows(2).all(|w| w[0] > w[1]));
        assert!(ps.iter().all(|&p| is_prime(p) && p < 1 << 62));
        // Lazily found, yet the same sequence: the first five are the five
        // largest primes below 2^62 (no prime is skipped between them).
        let mut n = (1u64 << 62) - 1;
        for &p in &ps {
            while !is_prime(n) {
                n -= 2;
            }
            assert_eq!(p, n);
            n -= 2;
        }
        assert_eq!(primes().count(), NPRIMES);
        assert_eq!(prime(NPRIMES - 1), primes().last());
        assert_eq!(prime(NPRIMES), None);
        assert!(!is_prime(3_215_031_751)); // strong pseudoprime to 2, 3, 5, 7
        assert!(is_prime(1_000_000_007));
    }

    #[test]
    fn euclid_mod_p() {
        let f = Fp::new(1_000_000_007);
        // (x + 1)(x + 2) and (x + 1)(x + 3)
        let a = mul(f, &[1, 1], &[2, 1]);
        let b = mul(f, &[1, 1], &[3, 1]);
        assert_eq!(gcd(f, &a, &b), vec![1, 1]);
        let (q, r) = div_rem(f, &a, &[1, 1]);
        assert_eq!((q, r), (vec![2, 1], vec![]));
    }

    #[test]
    fn inverses_by_euclid() {
        for p in primes().take(3).chain([3, 1_000_000_007]) {
            let f = Fp::new(p);
            for a in [1, 2, 3, p - 1, p / 2, p / 3 + 7, 123_456_789 % p] {
                if a % p == 0 {
                    continue;
                }
                assert_eq!(f.mul(a % p, f.inv(a)), 1, "p = {p}, a = {a}");
                assert_eq!(f.inv(a), f.pow(a % p, p - 2));
            }
        }
    }

    #[test]
    fn wide_sums_reduce_like_division() {
        let mut checked = 0;
        for p in primes().take(2).chain([3, 1_000_000_007]) {
            let f = Fp::new(p);
            let vals = [0, 1, 2, p / 2, p - 2, p - 1, 0x0123_4567_89ab_cdef % p];
            let mut acc = 0u128;
            let mut want = 0u128;
            for &a in &vals {
                for &b in &vals {
                    acc = f.mul_add_wide(acc, a, b);
                    want = (want + a as u128 * b as u128) % p as u128;
                    assert_eq!(f.reduce_wide(acc) as u128, want, "p = {p}");
                    checked += 1;
                }
            }
        }
        assert_eq!(checked, 4 * 49);
    }

    #[test]
    fn residues_of_big_integers_agree_with_division() {
        use num_integer::Integer;
        use num_traits::ToPrimitive;
        let mut checked = 0;
        for p in primes().take(3).chain([3, 5, 1_000_000_007]) {
            let f = Fp::new(p);
            let mut x = BigInt::from(0x1234_5678_9abc_def1u64);
            for k in 0..40 {
                for a in [x.clone(), -x.clone(), x.clone() + 1, BigInt::from(k)] {
                    let want = a.mod_floor(&BigInt::from(p)).to_u64().expect("< p");
                    assert_eq!(f.reduce(&a), want, "p = {p}, a = {a}");
                    checked += 1;
                }
                // Grow by about 61 bits, with all-ones and zero digits.
                x = x * BigInt::from(0x1fff_ffff_ffff_fffbu64) + BigInt::from(u64::MAX) * k;
            }
        }
        assert_eq!(checked, 6 * 40 * 4);
    }

    #[test]
    fn pseudo_remainder_inverse_is_the_inverse() {
        let f = Fp::new(prime(0).expect("a prime"));
        let mut word = lcg(17);
        let mut next = || word() >> 2;
        let (mut inverted, mut refused) = (0, 0);
        for round in 0..300 {
            let dm = 1 + round % 9;
            let mut m: UP = (0..=dm).map(|_| next() % f.p).collect();
            if m[dm] == 0 {
                m[dm] = 1;
            }
            let mut a: UP = (0..(round % 12)).map(|_| next() % f.p).collect();
            if round % 5 == 0 && dm >= 2 {
                // A common factor (x − 3).
                m = mul(f, &monic(f, &m[..dm]), &[f.neg(3), 1]);
                a = mul(f, &a, &[f.neg(3), 1]);
            }
            let want = inverse_and_resultant(f, &a, &m).map(|(s, _)| s);
            let got = inverse_mod(f, &a, &m);
            assert_eq!(got, want, "round {round}");
            match got {
                Some(_) => inverted += 1,
                None => refused += 1,
            }
        }
        assert!(inverted > 200 && refused > 20, "{inverted} {refused}");
    }

    #[test]
    fn inverse_and_resultant_mod_p() {
        let f = Fp::new(1_000_000_007);
        // a = x + 2, m = x^2 + 1: Res(a, m) = m(−2) = 5, a⁻¹ = (2 − x)/5.
        let (s, r) = inverse_and_resultant(f, &[2, 1], &[1, 0, 1]).unwrap();
        assert_eq!(r, 5);
        let i5 = f.inv(5);
        assert_eq!(s, vec![f.mul(2, i5), f.mul(f.neg(1), i5)]);
        assert!(inverse_and_resultant(f, &[1, 1], &[f.neg(1), 0, 1]).is_none());
    }

    #[test]
    fn crt_and_reconstruction() {
        let ps: Vec<u64> = primes().take(3).collect();
        let x = BigInt::from(-123_456_789_012_345_678_901_234_567i128);
        let (mut c, mut m) = (BigInt::zero(), BigInt::one());
        for &p in &ps {
            let f = Fp::new(p);
            let minv = f.inv(f.reduce(&m));
            c = crt(&c, &m, f.reduce(&x), f, minv);
            m *= p;
        }
        assert_eq!(symmetric(&c, &m), x);
        // 22/7 mod m
        let f = BigInt::from(7).modinv(&m).unwrap() * 22;
        let (n, d) = rational_reconstruct(&f, &m).unwrap();
        assert_eq!((n, d), (BigInt::from(22), BigInt::from(7)));
    }
}
