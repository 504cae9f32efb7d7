//! Decimal text of big naturals, appended to a `String` without the
//! intermediate buffers of num-bigint's `Display` (which builds a digit
//! vector and a string per number): the limbs are divided by 10^19 with a
//! precomputed reciprocal (Möller–Granlund, "Improved division by
//! invariant integers", 2011, Algorithm 4), and each 19-digit chunk is
//! written two digits at a time. The text is exactly `Display`'s (tested).
//! Printing the large coefficients of Smith transforms spends most of its
//! time here. This module owns only that conversion; it knows nothing of
//! polynomials or signs.

use num_bigint::BigUint;
use num_integer::Integer;

/// 10^19, the largest power of ten below 2^64; its top bit is set, so it
/// is already normalised for the reciprocal division.
const BASE: u64 = 10_000_000_000_000_000_000;

/// `⌊(2^128 − 1)/BASE⌋ − 2^64`.
const RECIP: u64 = (u128::MAX / BASE as u128 - (1u128 << 64)) as u64;

/// `(⌊(hi·2^64 + lo)/BASE⌋, remainder)` for `hi < BASE`.
#[inline]
fn div_base(hi: u64, lo: u64) -> (u64, u64) {
    // Modulo 2^128, as the algorithm specifies (no carry out for hi < BASE).
    let p =
        (u128::from(RECIP) * u128::from(hi)).wrapping_add((u128::from(hi) << 64) | u128::from(lo));
    let (mut q1, q0) = (((p >> 64) as u64).wrapping_add(1), p as u64);
    let mut r = lo.wrapping_sub(q1.wrapping_mul(BASE));
    if r > q0 {
        q1 = q1.wrapping_sub(1);
        r = r.wrapping_add(BASE);
    }
    if r >= BASE {
        q1 += 1;
        r -= BASE;
    }
    (q1, r)
}

const PAIRS: &[u8; 200] = b"\
0001020304050607080910111213141516171819\
2021222324252627282930313233343536373839\
4041424344454647484950515253545556575859\
6061626364656667686970717273747576777879\
8081828384858687888990919293949596979899";

/// The 19 decimal digits of `c < BASE`, zero-padded, into `buf` (19
/// bytes).
#[inline]
fn chunk_digits(mut c: u64, buf: &mut [u8]) {
    debug_assert_eq!(buf.len(), 19);
    let mut i = 19;
    while i > 1 {
        let d = (c % 100) as usize;
        c /= 100;
        buf[i - 2..i].copy_from_slice(&PAIRS[2 * d..2 * d + 2]);
        i -= 2;
    }
    buf[0] = b'0' + c as u8;
}

/// Above this many limbs, [`write_nat`] splits the number by powers
/// `10^(19·2^j)` (num-bigint's subquadratic division) instead of dividing
/// every limb by 10^19 once per chunk, which is quadratic.
const SPLIT_LIMBS: usize = 40;

/// Widths (in 19-digit chunks) up to this are written by the chunk loop.
const SPLIT_BASE_CHUNKS: usize = 32;

thread_local! {
    /// `10^(19·2^j)` for j = 0, 1, …, as far as printing has needed.
    static POWERS: std::cell::RefCell<Vec<BigUint>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// Appends the decimal text of `n` (as `n.to_string()` gives it).
pub fn write_nat(out: &mut String, n: &BigUint) {
    if n.iter_u64_digits().len() > SPLIT_LIMBS {
        POWERS.with(|cache| {
            let mut powers = cache.borrow_mut();
            if powers.is_empty() {
                powers.push(BigUint::from(BASE));
            }
            // Up to the first power above n.
            while powers.last().is_some_and(|p| p <= n) {
                let sq = powers.last().map(|p| p * p).unwrap_or_default();
                powers.push(sq);
            }
            write_split(out, n, &powers);
        });
        return;
    }
    write_small(out, n);
}

/// `n > 0` (with `n < powers.last()`): the digits above the largest power
/// `P_j ≤ n` unpadded, those below it padded to its width.
fn write_split(out: &mut String, n: &BigUint, powers: &[BigUint]) {
    if n.iter_u64_digits().len() <= SPLIT_LIMBS {
        write_small(out, n);
        return;
    }
    let j = powers.iter().rposition(|p| p <= n).unwrap_or(0);
    let (q, r) = n.div_rem(&powers[j]);
    write_split(out, &q, powers);
    write_padded(out, &r, j, powers);
}

/// `v < 10^(19·2^j)` as exactly 19·2^j digits.
fn write_padded(out: &mut String, v: &BigUint, j: usize, powers: &[BigUint]) {
    let width = 19usize << j;
    if (1usize << j) <= SPLIT_BASE_CHUNKS {
        let start = out.len();
        write_small(out, v);
        let written = out.len() - start;
        if written < width {
            out.insert_str(start, &"0".repeat(width - written));
        }
        return;
    }
    let (hi, lo) = v.div_rem(&powers[j - 1]);
    write_padded(out, &hi, j - 1, powers);
    write_padded(out, &lo, j - 1, powers);
}

/// [`write_nat`] by one division of all limbs per 19-digit chunk.
fn write_small(out: &mut String, n: &BigUint) {
    const STACK: usize = 16;
    let len = n.iter_u64_digits().len();
    if len <= 1 {
        use std::fmt::Write;
        let _ = write!(out, "{}", n.iter_u64_digits().next().unwrap_or(0));
        return;
    }
    // Up to 1024 bits on the stack.
    let (mut l_stack, mut c_stack) = ([0u64; STACK], [0u64; STACK + 2]);
    let (mut l_heap, mut c_heap) = (Vec::new(), Vec::new());
    let (limbs, chunks): (&mut [u64], &mut [u64]) = if len <= STACK {
        (&mut l_stack[..len], &mut c_stack[..])
    } else {
        l_heap.resize(len, 0);
        c_heap.resize(len + len / 63 + 2, 0);
        (&mut l_heap[..], &mut c_heap[..])
    };
    for (l, d) in limbs.iter_mut().zip(n.iter_u64_digits()) {
        *l = d;
    }
    write_limbs(out, limbs, chunks);
}

/// [`write_nat`] on little-endian limbs without leading zeros (consumed),
/// `chunks` room for the base-10^19 digits (`len·64/63 + 1` suffice).
fn write_limbs(out: &mut String, limbs: &mut [u64], chunks: &mut [u64]) {
    let mut top = limbs.len();
    let mut count = 0;
    while top > 0 {
        let mut rem = 0u64;
        for l in limbs[..top].iter_mut().rev() {
            let (q, r) = div_base(rem, *l);
            *l = q;
            rem = r;
        }
        chunks[count] = rem;
        count += 1;
        while top > 0 && limbs[top - 1] == 0 {
            top -= 1;
        }
    }
    // All the digits into one buffer (on the stack up to 18 chunks), then
    // one UTF-8 check over the whole, which takes its word-wide ASCII path
    // (checking each 19-byte chunk separately took 2 % of a Smith report).
    const STACK_DIGITS: usize = 19 * 18;
    let mut d_stack = [0u8; STACK_DIGITS];
    let mut d_heap = Vec::new();
    let digits: &mut [u8] = if 19 * count <= STACK_DIGITS {
        &mut d_stack[..19 * count]
    } else {
        d_heap.resize(19 * count, 0);
        &mut d_heap
    };
    for (slot, &c) in digits.chunks_mut(19).zip(chunks[..count].iter().rev()) {
        chunk_digits(c, slot);
    }
    let lead = digits[..18].iter().position(|&b| b != b'0').unwrap_or(18);
    // The digits are ASCII, so this conversion cannot fail.
    out.push_str(std::str::from_utf8(&digits[lead..]).unwrap_or_default());
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn text(n: &BigUint) -> String {
        let mut s = String::new();
        write_nat(&mut s, n);
        s
    }

    #[test]
    fn reciprocal_division_is_division() {
        for (hi, lo) in [
            (0, 0),
            (0, u64::MAX),
            (BASE - 1, u64::MAX),
            (BASE - 1, 0),
            (1, 0),
            (123_456_789, 987_654_321),
        ] {
            let x = (u128::from(hi) << 64) | u128::from(lo);
            let b = u128::from(BASE);
            assert_eq!(div_base(hi, lo), ((x / b) as u64, (x % b) as u64));
        }
    }

    #[test]
    fn edges_print_as_display() {
        let ten = BigUint::from(10u32);
        let mut cases = vec![BigUint::from(0u32), BigUint::from(u64::MAX)];
        for k in [18u32, 19, 20, 37, 38, 39, 57, 76, 100] {
            let p = ten.pow(k);
            cases.push(&p - 1u32);
            cases.push(p.clone());
            cases.push(&p + 1u32);
        }
        for k in [63u32, 64, 65, 127, 128, 129, 640] {
            let p = BigUint::from(1u32) << k;
            cases.push(&p - 1u32);
            cases.push(p);
        }
        for n in &cases {
            assert_eq!(text(n), n.to_string());
        }
        let mut s = String::from("x = ");
        write_nat(&mut s, &ten.pow(25));
        assert_eq!(s, format!("x = {}", ten.pow(25)));
    }

    /// Numbers long enough to be split by powers of 10^19, with runs of
    /// zero digits at the split points and below them.
    #[test]
    fn long_naturals_print_as_display() {
        let ten = BigUint::from(10u32);
        let mut checked = 0;
        for k in [19 * 42, 850, 19 * 64, 19 * 128, 19 * 129 + 7, 5_000, 19 * 512, 20_000] {
            let p = ten.pow(k);
            let q = ten.pow(k / 2 + 3);
            for n in [&p - 1u32, p.clone(), &p + 1u32, &p + &q, &p * 7u32 + 3u32, &p * &q - 1u32] {
                assert!(n.iter_u64_digits().len() > SPLIT_LIMBS);
                assert_eq!(text(&n), n.to_string(), "10^{k}");
                checked += 1;
            }
        }
        assert_eq!(checked, 48);
    }

    proptest! {
        #[test]
        fn random_long_naturals_print_as_display(limbs in proptest::collection::vec(any::<u64>(), 41..700),
                                                 zeros in 0usize..300) {
            let mut l = limbs;
            for i in 0..zeros.min(l.len() - 1) {
                l[i] = 0;
            }
            let n = l.iter().rev().fold(BigUint::from(0u32), |acc, &w| (acc << 64u32) + BigUint::from(w));
            prop_assert_eq!(text(&n), n.to_string());
        }

        #[test]
        fn random_naturals_print_as_display(limbs in proptest::collection::vec(any::<u64>(), 0..14),
                                            zeros in 0usize..4) {
            // Runs of zero limbs exercise zero-padded chunks.
            let mut l = limbs;
            for i in 0..zeros.min(l.len()) {
                l[i] = 0;
            }
            let n = l.iter().rev().fold(BigUint::from(0u32), |acc, &w| (acc << 64u32) + BigUint::from(w));
            prop_assert_eq!(text(&n), n.to_string());
        }
    }
}
