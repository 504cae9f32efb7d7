//! Chinese remaindering over many word primes by a product tree. With k
//! primes, Garner's mixed-radix form costs O(k²) word operations per value
//! (and O(k²) inverses once); here the value is the linear combination
//! `Σ vᵢ·(M/mᵢ)` with `vᵢ = rᵢ·(M/mᵢ)⁻¹ mod mᵢ`, summed up a balanced tree
//! of the primes' products, `val(N) = val(L)·M_R + val(R)·M_L`, so one value
//! costs a few big-integer multiplications per tree level (subquadratic in
//! num-bigint) and one final reduction modulo M. The constants
//! `(M/mᵢ)⁻¹ mod mᵢ` come from one remainder descent of the tree. This
//! module owns only that reconstruction; [`crate::algebra::smith::detadj`]'s
//! `Garner` uses it beyond a few dozen primes.

use super::modular::Fp;
use num_bigint::{BigInt, BigUint, Sign};
use num_traits::{One, Zero};

/// Primes per leaf: the leaf sums `Σ vᵢ·(M_leaf/mᵢ)` are formed on limbs.
const BLOCK: usize = 16;

/// The product tree of a fixed list of distinct word primes, with the
/// constants of the linear-combination CRT.
pub struct CrtTree {
    ps: Vec<Fp>,
    /// `(M/mᵢ)⁻¹ mod mᵢ`, prepared for [`Fp::mul_pre`].
    c: Vec<u64>,
    /// Per prime, the limbs of `M_leaf/mᵢ` (`BLOCK` limbs, zero-padded).
    cof: Vec<[u64; BLOCK]>,
    /// The products of a balanced binary tree over the leaves, in preorder
    /// (a subtree over b leaves has 2b − 1 nodes).
    nodes: Vec<BigUint>,
    leaves: usize,
    /// `M = Π mᵢ`.
    pub m: BigInt,
    half: BigUint,
}

impl CrtTree {
    /// The tree of the primes `ps` (distinct, at least one).
    pub fn new(ps: &[Fp]) -> Self {
        assert!(!ps.is_empty(), "CrtTree needs a prime");
        let leaves = ps.len().div_ceil(BLOCK);
        let mut cof = Vec::with_capacity(ps.len());
        for block in ps.chunks(BLOCK) {
            for i in 0..block.len() {
                let mut limbs = [0u64; BLOCK];
                limbs[0] = 1;
                let mut used = 1;
                for (j, f) in block.iter().enumerate() {
                    if j != i {
                        used = mul_word(&mut limbs, used, f.p);
                    }
                }
                cof.push(limbs);
            }
        }
        let mut nodes = vec![BigUint::zero(); 2 * leaves - 1];
        build(ps, &cof, &mut nodes, 0, 0, leaves);
        // (M/M_N) mod M_N down the tree; at a leaf, times M_leaf/mᵢ mod mᵢ.
        let mut c = vec![0u64; ps.len()];
        descend(ps, &nodes, &mut c, 0, 0, leaves, BigUint::one());
        let m = nodes[0].clone();
        CrtTree {
            ps: ps.to_vec(),
            c,
            cof,
            half: &m >> 1u32,
            m: BigInt::from_biguint(Sign::Plus, m),
            nodes,
            leaves,
        }
    }

    /// The integer in `(−M/2, M/2]` with the residues `res` (one per
    /// prime, each reduced).
    pub fn lift(&self, res: &[u64]) -> BigInt {
        debug_assert_eq!(res.len(), self.ps.len());
        let s = self.up(res, 0, 0, self.leaves);
        // s < k·M: one short division.
        let m = self.m.magnitude();
        let x = if &s >= m { s % m } else { s };
        if x > self.half {
            BigInt::from_biguint(Sign::Minus, m - x)
        } else {
            BigInt::from_biguint(Sign::Plus, x)
        }
    }

    /// `Σ vᵢ·(M_N/mᵢ)` over the leaves `lo..hi` of node `idx`.
    fn up(&self, res: &[u64], idx: usize, lo: usize, hi: usize) -> BigUint {
        if hi - lo == 1 {
            let start = lo * BLOCK;
            let end = (start + BLOCK).min(self.ps.len());
            let mut acc = [0u64; BLOCK + 1];
            let leaf = (&self.ps[start..end], &self.c[start..end], &self.cof[start..end]);
            for (((f, &c), cof), &r) in leaf.0.iter().zip(leaf.1).zip(leaf.2).zip(&res[start..end]) {
                let v = f.mul_pre(c, r);
                let mut carry = 0u128;
                for (a, &w) in acc.iter_mut().zip(cof.iter()) {
                    let t = *a as u128 + v as u128 * w as u128 + carry;
                    *a = t as u64;
                    carry = t >> 64;
                }
                acc[BLOCK] += carry as u64;
            }
            return super::smith::certify::biguint_from_limbs(&acc);
        }
        let mid = lo + (hi - lo) / 2;
        let (li, ri) = (idx + 1, idx + 2 * (mid - lo));
        let l = self.up(res, li, lo, mid);
        let r = self.up(res, ri, mid, hi);
        l * &self.nodes[ri] + r * &self.nodes[li]
    }
}

/// `limbs[..used] *= w` in place; the new used length.
fn mul_word(limbs: &mut [u64], used: usize, w: u64) -> usize {
    let mut carry = 0u128;
    for l in limbs[..used].iter_mut() {
        let t = *l as u128 * w as u128 + carry;
        *l = t as u64;
        carry = t >> 64;
    }
    if carry != 0 {
        limbs[used] = carry as u64;
        used + 1
    } else {
        used
    }
}

/// Fills the preorder products of the subtree `idx` over leaves `lo..hi`.
fn build(ps: &[Fp], cof: &[[u64; BLOCK]], nodes: &mut [BigUint], idx: usize, lo: usize, hi: usize) {
    if hi - lo == 1 {
        // M_leaf = (M_leaf/m₀)·m₀.
        let start = lo * BLOCK;
        let mut limbs = [0u64; BLOCK + 1];
        limbs[..BLOCK].copy_from_slice(&cof[start]);
        let used = limbs.iter().rposition(|&l| l != 0).map_or(0, |p| p + 1);
        mul_word(&mut limbs, used, ps[start].p);
        nodes[idx] = super::smith::certify::biguint_from_limbs(&limbs);
        return;
    }
    let mid = lo + (hi - lo) / 2;
    let (li, ri) = (idx + 1, idx + 2 * (mid - lo));
    build(ps, cof, nodes, li, lo, mid);
    build(ps, cof, nodes, ri, mid, hi);
    nodes[idx] = &nodes[li] * &nodes[ri];
}

/// With `r = (M/M_N) mod M_N` at node `idx`, sets `c[i] = (M/mᵢ)⁻¹ mod mᵢ`
/// (prepared) for the primes under it.
fn descend(
    ps: &[Fp],
    nodes: &[BigUint],
    c: &mut [u64],
    idx: usize,
    lo: usize,
    hi: usize,
    r: BigUint,
) {
    if hi - lo == 1 {
        let start = lo * BLOCK;
        let end = (start + BLOCK).min(ps.len());
        let r = BigInt::from_biguint(Sign::Plus, r);
        let leaf = &ps[start..end];
        for (i, f) in leaf.iter().enumerate() {
            // M_leaf/mᵢ mod mᵢ: the leaf's other primes.
            let own = leaf
                .iter()
                .enumerate()
                .filter(|&(j, _)| j != i)
                .fold(1u64, |acc, (_, g)| f.mul(acc, g.p % f.p));
            c[start + i] = f.prep(f.inv(f.mul(f.reduce(&r), own)));
        }
        return;
    }
    let mid = lo + (hi - lo) / 2;
    let (li, ri) = (idx + 1, idx + 2 * (mid - lo));
    let rl = (&r * &nodes[ri]) % &nodes[li];
    let rr = (r * &nodes[li]) % &nodes[ri];
    descend(ps, nodes, c, li, lo, mid, rl);
    descend(ps, nodes, c, ri, mid, hi, rr);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::modular::{long_primes, symmetric};

    /// The tree's lift is the symmetric CRT value, for prime counts on
    /// both sides of a leaf's size and of a power of two, values of every
    /// size up to the modulus, and the ends of the range.
    #[test]
    fn tree_lift_is_the_symmetric_crt_value() {
        let all: Vec<Fp> = long_primes().take(300).map(Fp::new).collect();
        let mut next = crate::algebra::modular::lcg(17);
        let mut checked = 0;
        for k in [1, 2, 15, 16, 17, 31, 32, 33, 64, 100, 255, 300] {
            let tree = CrtTree::new(&all[..k]);
            let m = all[..k].iter().fold(BigInt::one(), |a, f| a * f.p);
            assert_eq!(tree.m, m);
            for round in 0..20 {
                let bits = 1 + next() % (62 * k as u64);
                let mut x = BigInt::zero();
                for _ in 0..=k {
                    x = (x << 64u32) | BigInt::from(next());
                }
                x %= BigInt::one() << bits as usize;
                if round % 2 == 1 {
                    x = -x;
                }
                let x = symmetric(&x, &m);
                let res: Vec<u64> = all[..k].iter().map(|f| f.reduce(&x)).collect();
                assert_eq!(tree.lift(&res), x, "k = {k}");
                checked += 1;
            }
            let half = &m >> 1u32;
            for x in [half.clone(), -half, BigInt::zero(), BigInt::one()] {
                let res: Vec<u64> = all[..k].iter().map(|f| f.reduce(&x)).collect();
                assert_eq!(tree.lift(&res), x, "k = {k}");
            }
        }
        assert_eq!(checked, 12 * 20);
    }
}
