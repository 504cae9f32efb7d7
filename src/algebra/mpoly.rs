//! Sparse multivariate polynomials over Q in commuting symbols with a fixed
//! variable order (index 0 is the most significant in the lexicographic
//! term order). This module owns the representation and the ring
//! operations (add, mul, pow, exact division, content, substitution,
//! degrees, printing); gcd lives in [`super::gcd`], and names are only
//! borrowed for printing.

use super::print::{Node, PrintOptions, print};
use super::rational::{Q, primitive_scale};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;
use std::collections::BTreeMap;
use std::ops::{Add, Mul, Neg, Sub};

/// Exponent vector of a monomial (one entry per variable).
pub type Monomial = Vec<u32>;

/// A polynomial in `nvars` commuting variables with rational coefficients.
///
/// Terms are kept sorted by descending lexicographic order of their exponent
/// vectors, with no zero coefficients, so equal polynomials are equal as
/// data.
///
/// ```
/// use lambdamat::algebra::mpoly::MPoly;
/// let x = MPoly::var(0, 2);
/// let y = MPoly::var(1, 2);
/// let p = (&x + &y).pow(2) - &x * &y;
/// assert_eq!(p.to_string_with(&["x", "y"]), "x^2 + x*y + y^2");
/// ```
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub struct MPoly {
    nvars: usize,
    terms: Vec<(Monomial, Q)>,
}

impl MPoly {
    /// The zero polynomial.
    pub fn zero(nvars: usize) -> Self {
        MPoly {
            nvars,
            terms: Vec::new(),
        }
    }

    /// The constant one.
    pub fn one(nvars: usize) -> Self {
        Self::constant(Q::one(), nvars)
    }

    /// The constant `c`.
    pub fn constant(c: Q, nvars: usize) -> Self {
        if c.is_zero() {
            return Self::zero(nvars);
        }
        MPoly {
            nvars,
            terms: vec![(vec![0; nvars], c)],
        }
    }

    /// The variable with index `i`.
    pub fn var(i: usize, nvars: usize) -> Self {
        assert!(i < nvars, "variable index out of range");
        let mut m = vec![0; nvars];
        m[i] = 1;
        MPoly {
            nvars,
            terms: vec![(m, Q::one())],
        }
    }

    /// `c * x^m` for one monomial.
    pub fn monomial(m: Monomial, c: Q) -> Self {
        let nvars = m.len();
        if c.is_zero() {
            return Self::zero(nvars);
        }
        MPoly {
            nvars,
            terms: vec![(m, c)],
        }
    }

    /// Builds a polynomial from arbitrary terms (merged and sorted).
    pub fn from_terms(nvars: usize, terms: impl IntoIterator<Item = (Monomial, Q)>) -> Self {
        let mut map: BTreeMap<Monomial, Q> = BTreeMap::new();
        for (m, c) in terms {
            debug_assert_eq!(m.len(), nvars);
            *map.entry(m).or_insert_with(Q::zero) += c;
        }
        MPoly {
            nvars,
            terms: map
                .into_iter()
                .rev()
                .filter(|(_, c)| !c.is_zero())
                .collect(),
        }
    }

    /// Builds a polynomial from terms already in descending lexicographic
    /// order with distinct monomials and nonzero coefficients.
    pub fn from_sorted_terms(nvars: usize, terms: Vec<(Monomial, Q)>) -> Self {
        debug_assert!(terms.windows(2).all(|w| w[0].0 > w[1].0));
        debug_assert!(terms.iter().all(|(_, c)| !c.is_zero()));
        MPoly { nvars, terms }
    }

    /// Number of variables of the ambient ring.
    pub fn nvars(&self) -> usize {
        self.nvars
    }

    /// The terms, in descending lexicographic order.
    pub fn terms(&self) -> &[(Monomial, Q)] {
        &self.terms
    }

    /// Whether this is the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// The value if the polynomial is constant (zero included).
    pub fn as_constant(&self) -> Option<Q> {
        match self.terms.as_slice() {
            [] => Some(Q::zero()),
            [(m, c)] if m.iter().all(|&e| e == 0) => Some(c.clone()),
            _ => None,
        }
    }

    /// Whether the polynomial is a nonzero constant.
    pub fn is_nonzero_constant(&self) -> bool {
        matches!(self.as_constant(), Some(c) if !c.is_zero())
    }

    /// Leading term (largest in lex order).
    pub fn leading(&self) -> Option<&(Monomial, Q)> {
        self.terms.first()
    }

    /// Multiplies every coefficient by `c`.
    pub fn scale(&self, c: &Q) -> Self {
        if c.is_zero() {
            return Self::zero(self.nvars);
        }
        MPoly {
            nvars: self.nvars,
            terms: self.terms.iter().map(|(m, a)| (m.clone(), a * c)).collect(),
        }
    }

    /// `self^e` by repeated squaring.
    pub fn pow(&self, mut e: u32) -> Self {
        let mut base = self.clone();
        let mut acc = Self::one(self.nvars);
        while e > 0 {
            if e & 1 == 1 {
                acc = &acc * &base;
            }
            e >>= 1;
            if e > 0 {
                base = &base * &base;
            }
        }
        acc
    }

    /// Degree in variable `v` (`None` for zero).
    pub fn degree_in(&self, v: usize) -> Option<u32> {
        self.terms.iter().map(|(m, _)| m[v]).max()
    }

    /// Total degree (`None` for zero).
    pub fn total_degree(&self) -> Option<u32> {
        self.terms.iter().map(|(m, _)| m.iter().sum()).max()
    }

    /// Whether variable `v` occurs.
    pub fn contains_var(&self, v: usize) -> bool {
        self.terms.iter().any(|(m, _)| m[v] > 0)
    }

    /// The most significant variable that occurs, if any.
    pub fn main_var(&self) -> Option<usize> {
        (0..self.nvars).find(|&v| self.contains_var(v))
    }

    /// Coefficients with respect to `v`: `self = Σ_k c_k v^k`; each `c_k`
    /// is free of `v`. Index `k` of the result is `c_k`.
    pub fn coeffs_in(&self, v: usize) -> Vec<MPoly> {
        let Some(d) = self.degree_in(v) else {
            return Vec::new();
        };
        let mut buckets: Vec<Vec<(Monomial, Q)>> = vec![Vec::new(); d as usize + 1];
        for (m, c) in &self.terms {
            let mut m2 = m.clone();
            let k = std::mem::replace(&mut m2[v], 0);
            buckets[k as usize].push((m2, c.clone()));
        }
        buckets
            .into_iter()
            .map(|ts| {
                // Removing one variable's exponent keeps lex order among the
                // terms of one bucket only when `v` is the first variable, so
                // re-sort in general.
                let mut p = MPoly {
                    nvars: self.nvars,
                    terms: ts,
                };
                p.terms.sort_by(|a, b| b.0.cmp(&a.0));
                p
            })
            .collect()
    }

    /// The leading coefficient with respect to `v` (free of `v`).
    pub fn lc_in(&self, v: usize) -> MPoly {
        self.coeffs_in(v)
            .pop()
            .unwrap_or_else(|| Self::zero(self.nvars))
    }

    /// `Σ_k c_k v^k` from coefficients free of `v`.
    pub fn from_coeffs_in(v: usize, coeffs: &[MPoly], nvars: usize) -> Self {
        let mut terms = Vec::new();
        for (k, c) in coeffs.iter().enumerate() {
            for (m, a) in &c.terms {
                let mut m2 = m.clone();
                m2[v] += k as u32;
                terms.push((m2, a.clone()));
            }
        }
        Self::from_terms(nvars, terms)
    }

    /// Multiplies by `v^k`.
    pub fn shift(&self, v: usize, k: u32) -> Self {
        MPoly {
            nvars: self.nvars,
            terms: self
                .terms
                .iter()
                .map(|(m, c)| {
                    let mut m2 = m.clone();
                    m2[v] += k;
                    (m2, c.clone())
                })
                .collect(),
        }
    }

    /// Substitutes the value `val` for variable `v`.
    pub fn eval_var(&self, v: usize, val: &Q) -> Self {
        let coeffs = self.coeffs_in(v);
        let mut acc = Self::zero(self.nvars);
        for c in coeffs.iter().rev() {
            acc = acc.scale(val) + c;
        }
        acc
    }

    /// Substitutes the polynomial `p` for variable `v`.
    pub fn substitute(&self, v: usize, p: &MPoly) -> Self {
        let coeffs = self.coeffs_in(v);
        let mut acc = Self::zero(self.nvars);
        for c in coeffs.iter().rev() {
            acc = &(&acc * p) + c;
        }
        acc
    }

    /// The positive rational `u` such that `u * self` has coprime integer
    /// coefficients (one for zero).
    pub fn integer_scale(&self) -> Q {
        primitive_scale(self.terms.iter().map(|(_, c)| c))
    }

    /// The associate with coprime integer coefficients and positive leading
    /// coefficient: the normal form used for gcds and printing.
    pub fn primitive_normal(&self) -> Self {
        if self.is_zero() {
            return self.clone();
        }
        let mut u = self.integer_scale();
        if self.terms[0].1.is_negative() {
            u = -u;
        }
        self.scale(&u)
    }

    /// Exact division: `Some(q)` with `q * d == self`, or `None` if `d` does
    /// not divide `self` (or `d` is zero).
    pub fn div_exact(&self, d: &MPoly) -> Option<MPoly> {
        let (dm, _) = d.terms.first()?;
        if let Some(c) = d.as_constant() {
            return Some(self.scale(&c.recip()));
        }
        if self.is_zero() {
            return Some(self.clone());
        }
        if let [(dm, dc)] = d.terms.as_slice() {
            // A monomial divides term by term (the order is kept).
            let inv = dc.recip();
            let mut terms = Vec::with_capacity(self.terms.len());
            for (m, c) in &self.terms {
                if !m.iter().zip(dm).all(|(a, b)| a >= b) {
                    return None;
                }
                let q = m.iter().zip(dm).map(|(a, b)| a - b).collect();
                terms.push((q, if inv.is_one() { c.clone() } else { c * &inv }));
            }
            return Some(MPoly::from_sorted_terms(self.nvars, terms));
        }
        // Over the integers: with `a = sa·self` and `e = sd·d` of coprime
        // integer coefficients, d | self over Q iff e | a over Q, and then
        // (Gauss's lemma, e primitive) the quotient a/e has integer
        // coefficients, so every step's leading coefficient divides exactly
        // and a failed integer division means no division over Q either.
        // self/d = (a/e)·sd/sa. Integer steps need no gcd per coefficient,
        // which rational steps take for every term of every remainder.
        let (sa, sd) = (self.integer_scale(), d.integer_scale());
        let int_terms = |p: &MPoly, s: &Q| -> Vec<(Monomial, BigInt)> {
            p.terms
                .iter()
                .map(|(m, c)| (m.clone(), (c * s).to_integer()))
                .collect()
        };
        let e = int_terms(d, &sd);
        let lc = &e[0].1;
        // The remainder in an ordered map: a step touches the divisor's
        // terms only (|d|·log|r|), where rebuilding the remainder's sorted
        // list cost |r| per quotient term (quadratic when d is small and
        // the quotient long).
        let mut r: BTreeMap<Monomial, BigInt> = int_terms(self, &sa).into_iter().collect();
        let mut quot: Vec<(Monomial, BigInt)> = Vec::new();
        let mut key: Monomial = vec![0; self.nvars];
        while let Some((rm, rc)) = r.pop_last() {
            if !rm.iter().zip(dm).all(|(a, b)| a >= b) {
                return None;
            }
            let (c, rem) = rc.div_rem(lc);
            if !rem.is_zero() {
                return None;
            }
            let m: Monomial = rm.iter().zip(dm).map(|(a, b)| a - b).collect();
            // The leading term cancels exactly; subtract c·x^m·(d − lt d).
            for (em, ec) in &e[1..] {
                for ((k, a), b) in key.iter_mut().zip(em).zip(&m) {
                    *k = a + b;
                }
                let t = ec * &c;
                match r.get_mut(key.as_slice()) {
                    Some(v) => {
                        *v -= t;
                        if v.is_zero() {
                            r.remove(key.as_slice());
                        }
                    }
                    None => {
                        r.insert(key.clone(), -t);
                    }
                }
            }
            quot.push((m, c));
        }
        let back = &sd / &sa;
        Some(MPoly {
            nvars: self.nvars,
            terms: quot
                .into_iter()
                .map(|(m, c)| (m, Q::from_integer(c) * &back))
                .collect(),
        })
    }

    /// The print tree: a signed sum of `coefficient*monomial` terms,
    /// highest first (see [`super::print`]).
    pub fn to_node<S: AsRef<str>>(&self, names: &[S]) -> Node {
        Node::Terms(
            self.terms
                .iter()
                .map(|(m, c)| {
                    let mut fs = vec![Node::Num(c.abs())];
                    fs.extend(monomial_factors(m, names));
                    (c.is_negative(), Node::product(fs))
                })
                .collect(),
        )
    }

    /// Prints with the given variable names, e.g. `k1*k4 - k2*k3` or
    /// `x^2 + 1/2*x - 3` (highest term first); this is also the language's
    /// syntax.
    pub fn to_string_with<S: AsRef<str>>(&self, names: &[S]) -> String {
        print(&self.to_node(names), PrintOptions::TEXT)
    }

    /// LaTeX form with the given variable names, e.g. `k_{1} k_{4} - k_{2} k_{3}`.
    pub fn to_latex_with<S: AsRef<str>>(&self, names: &[S]) -> String {
        print(&self.to_node(names), PrintOptions::LATEX)
    }
}

/// The factors `name^e` of a monomial, in variable order.
pub fn monomial_factors<S: AsRef<str>>(m: &[u32], names: &[S]) -> Vec<Node> {
    m.iter()
        .enumerate()
        .filter(|(_, e)| **e > 0)
        .map(|(v, &e)| {
            let name = names
                .get(v)
                .map(|s| s.as_ref().to_string())
                .unwrap_or_else(|| format!("s{v}"));
            Node::pow_i(Node::Sym(name), i64::from(e))
        })
        .collect()
}

fn merge(a: &MPoly, b: &MPoly, negate_b: bool) -> MPoly {
    debug_assert_eq!(a.nvars, b.nvars);
    let mut terms = Vec::with_capacity(a.terms.len() + b.terms.len());
    let (mut i, mut j) = (0, 0);
    while i < a.terms.len() || j < b.terms.len() {
        let ord = match (a.terms.get(i), b.terms.get(j)) {
            (Some(x), Some(y)) => y.0.cmp(&x.0),
            (Some(_), None) => Ordering::Less,
            _ => Ordering::Greater,
        };
        match ord {
            Ordering::Less => {
                terms.push(a.terms[i].clone());
                i += 1;
            }
            Ordering::Greater => {
                let (m, c) = &b.terms[j];
                terms.push((m.clone(), if negate_b { -c } else { c.clone() }));
                j += 1;
            }
            Ordering::Equal => {
                let c = if negate_b {
                    &a.terms[i].1 - &b.terms[j].1
                } else {
                    &a.terms[i].1 + &b.terms[j].1
                };
                if !c.is_zero() {
                    terms.push((a.terms[i].0.clone(), c));
                }
                i += 1;
                j += 1;
            }
        }
    }
    MPoly {
        nvars: a.nvars,
        terms,
    }
}

/// The integer numerators of `p` and the positive rational `u` with
/// `p = numerators / u` (`u = 1` when the coefficients are integers).
fn integer_form(p: &MPoly) -> (Vec<BigInt>, Option<Q>) {
    if p.terms.iter().all(|(_, c)| c.is_integer()) {
        return (
            p.terms.iter().map(|(_, c)| c.numer().clone()).collect(),
            None,
        );
    }
    let u = p.integer_scale();
    let v = p.terms.iter().map(|(_, c)| (c * &u).to_integer()).collect();
    (v, Some(u))
}

/// Exponent vectors packed into one `u64`, symbol 0 in the highest bits,
/// so that the integer order is the lexicographic term order and adding
/// keys adds monomials: usable for a product when every symbol's exponents
/// in the two factors sum below `2^bits`.
struct Packing {
    nvars: usize,
    bits: u32,
}

impl Packing {
    fn for_product(a: &MPoly, b: &MPoly) -> Option<Packing> {
        Packing::for_products(a.nvars, &[(a, b)])
    }

    /// One packing for every product `a·b` of `pairs`.
    fn for_products(nvars: usize, pairs: &[(&MPoly, &MPoly)]) -> Option<Packing> {
        if nvars == 0 || nvars > 64 {
            return None;
        }
        let bits = (64 / nvars as u32).min(32);
        let top = |p: &MPoly, v: usize| p.terms.iter().map(|(m, _)| u64::from(m[v])).max();
        let fits = pairs.iter().all(|(a, b)| {
            (0..nvars).all(|v| top(a, v).unwrap_or(0) + top(b, v).unwrap_or(0) < 1u64 << bits)
        });
        fits.then_some(Packing { nvars, bits })
    }

    fn pack(&self, m: &[u32]) -> u64 {
        m.iter().fold(0, |k, &e| (k << self.bits) | u64::from(e))
    }

    fn unpack(&self, mut k: u64) -> Monomial {
        let mask = (1u64 << self.bits) - 1;
        let mut m = vec![0u32; self.nvars];
        for e in m.iter_mut().rev() {
            *e = (k & mask) as u32;
            k >>= self.bits;
        }
        m
    }
}

/// The product, accumulated over the integers (one rational normalisation
/// per result term instead of one per pair of terms), on packed monomials
/// where they fit.
fn product(a: &MPoly, b: &MPoly) -> MPoly {
    debug_assert_eq!(a.nvars, b.nvars);
    if a.is_zero() || b.is_zero() {
        return MPoly::zero(a.nvars);
    }
    let (ia, ua) = integer_form(a);
    let (ib, ub) = integer_form(b);
    let map: Vec<(Monomial, BigInt)> = match Packing::for_product(a, b) {
        Some(pk) => {
            let kb: Vec<u64> = b.terms.iter().map(|(m, _)| pk.pack(m)).collect();
            let mut map: BTreeMap<u64, BigInt> = BTreeMap::new();
            for ((ma, _), ca) in a.terms.iter().zip(&ia) {
                let ka = pk.pack(ma);
                for (kb, cb) in kb.iter().zip(&ib) {
                    *map.entry(ka + kb).or_default() += ca * cb;
                }
            }
            map.into_iter()
                .rev()
                .filter(|(_, c)| !c.is_zero())
                .map(|(k, c)| (pk.unpack(k), c))
                .collect()
        }
        None => {
            let mut map: BTreeMap<Monomial, BigInt> = BTreeMap::new();
            // One exponent buffer for the lookups; a monomial is allocated
            // only when it is new.
            let mut key: Monomial = vec![0; a.nvars];
            for ((ma, _), ca) in a.terms.iter().zip(&ia) {
                for ((mb, _), cb) in b.terms.iter().zip(&ib) {
                    for ((k, x), y) in key.iter_mut().zip(ma).zip(mb) {
                        *k = x + y;
                    }
                    let c = ca * cb;
                    match map.get_mut(key.as_slice()) {
                        Some(v) => *v += c,
                        None => {
                            map.insert(key.clone(), c);
                        }
                    }
                }
            }
            map.into_iter()
                .rev()
                .filter(|(_, c)| !c.is_zero())
                .collect()
        }
    };
    let scale = match (ua, ub) {
        (None, None) => None,
        (Some(x), None) | (None, Some(x)) => Some(x.recip()),
        (Some(x), Some(y)) => Some((x * y).recip()),
    };
    MPoly {
        nvars: a.nvars,
        terms: map
            .into_iter()
            .map(|(m, c)| {
                let q = Q::from_integer(c);
                (m, if let Some(s) = &scale { q * s } else { q })
            })
            .collect(),
    }
}

/// `Σ ±a_k·b_k` over `(a_k, b_k, subtract)`. When every coefficient is an
/// integer and the exponents of every pair fit one packing, all products
/// are summed in one map of packed monomials over the integers (no
/// rational normalisation, no intermediate sums); otherwise product by
/// product.
pub fn sum_of_products(nvars: usize, terms: &[(&MPoly, &MPoly, bool)]) -> MPoly {
    let integral = |p: &MPoly| p.terms.iter().all(|(_, c)| c.is_integer());
    let pairs: Vec<(&MPoly, &MPoly)> = terms.iter().map(|(a, b, _)| (*a, *b)).collect();
    let packing = pairs
        .iter()
        .all(|(a, b)| integral(a) && integral(b))
        .then(|| Packing::for_products(nvars, &pairs))
        .flatten();
    let Some(pk) = packing else {
        let mut acc = MPoly::zero(nvars);
        for (a, b, minus) in terms {
            let p = product(a, b);
            acc = merge(&acc, &p, *minus);
        }
        return acc;
    };
    let mut map: BTreeMap<u64, BigInt> = BTreeMap::new();
    for (a, b, minus) in terms {
        let kb: Vec<u64> = b.terms.iter().map(|(m, _)| pk.pack(m)).collect();
        for (ma, ca) in &a.terms {
            let ka = pk.pack(ma);
            let ca = if *minus { -ca.numer() } else { ca.numer().clone() };
            for (kb, (_, cb)) in kb.iter().zip(&b.terms) {
                *map.entry(ka + kb).or_default() += &ca * cb.numer();
            }
        }
    }
    MPoly {
        nvars,
        terms: map
            .into_iter()
            .rev()
            .filter(|(_, c)| !c.is_zero())
            .map(|(k, c)| (pk.unpack(k), Q::from_integer(c)))
            .collect(),
    }
}

macro_rules! forward_binop {
    ($tr:ident, $method:ident, $body:expr) => {
        impl $tr<&MPoly> for &MPoly {
            type Output = MPoly;
            fn $method(self, rhs: &MPoly) -> MPoly {
                $body(self, rhs)
            }
        }
        impl $tr<MPoly> for MPoly {
            type Output = MPoly;
            fn $method(self, rhs: MPoly) -> MPoly {
                $body(&self, &rhs)
            }
        }
        impl $tr<&MPoly> for MPoly {
            type Output = MPoly;
            fn $method(self, rhs: &MPoly) -> MPoly {
                $body(&self, rhs)
            }
        }
        impl $tr<MPoly> for &MPoly {
            type Output = MPoly;
            fn $method(self, rhs: MPoly) -> MPoly {
                $body(self, &rhs)
            }
        }
    };
}

forward_binop!(Add, add, |a, b| merge(a, b, false));
forward_binop!(Sub, sub, |a, b| merge(a, b, true));
forward_binop!(Mul, mul, product);

impl Neg for &MPoly {
    type Output = MPoly;
    fn neg(self) -> MPoly {
        MPoly {
            nvars: self.nvars,
            terms: self.terms.iter().map(|(m, c)| (m.clone(), -c)).collect(),
        }
    }
}

impl Neg for MPoly {
    type Output = MPoly;
    fn neg(self) -> MPoly {
        -&self
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::rational::{q, qi};

    fn xy() -> (MPoly, MPoly) {
        (MPoly::var(0, 2), MPoly::var(1, 2))
    }

    /// The product as a sum of one-term products (`Add` only): the
    /// reference the packed and unpacked products are checked against.
    fn sum_of_term_products(a: &MPoly, b: &MPoly) -> MPoly {
        let mut s = MPoly::zero(a.nvars);
        for (ma, ca) in &a.terms {
            for (mb, cb) in &b.terms {
                let m: Monomial = ma.iter().zip(mb).map(|(x, y)| x + y).collect();
                s = &s + &MPoly::monomial(m, ca * cb);
            }
        }
        s
    }

    #[test]
    fn division_by_a_monomial_is_term_by_term() {
        let (x, y) = (MPoly::var(0, 2), MPoly::var(1, 2));
        let p = &(&x.pow(3) * &y).scale(&Q::new(3.into(), 2.into())) - &(&x * &y.pow(2));
        let m = (&x * &y).scale(&Q::new((-3).into(), 4.into()));
        let q = p.div_exact(&m).expect("x*y divides p");
        assert_eq!(&q * &m, p);
        assert_eq!(q.to_string_with(&["x", "y"]), "-2*x^2 + 4/3*y");
        assert!(p.div_exact(&x.pow(2)).is_none());
        assert!(p.div_exact(&y.pow(2)).is_none());
    }

    #[test]
    fn products_agree_packed_and_unpacked() {
        let mut seed = 7u64;
        let mut next = |k: u64| {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 33) % k
        };
        let mut packed = 0;
        let mut unpacked = 0;
        for nvars in 1..=4usize {
            let bits = (64 / nvars as u32).min(32);
            for case in 0..40 {
                // Exponents near half the packing range, so that some sums
                // reach 2^bits (the unpacked path) and some stay below it.
                let half = 1u64 << (bits - 1);
                let mut poly = |big: bool| {
                    let terms: Vec<(Monomial, Q)> = (0..1 + next(6))
                        .map(|_| {
                            let m = (0..nvars)
                                .map(|_| {
                                    let e = if big { half - 3 + next(6) } else { next(4) };
                                    e as u32
                                })
                                .collect();
                            let c = Q::new(
                                BigInt::from(next(19) as i64 - 9),
                                BigInt::from(1 + next(4) as i64),
                            );
                            (m, c)
                        })
                        .collect();
                    MPoly::from_terms(nvars, terms)
                };
                let (a, b) = (poly(case % 2 == 0), poly(case % 4 == 0));
                match Packing::for_product(&a, &b) {
                    Some(_) => packed += 1,
                    None => unpacked += 1,
                }
                assert_eq!(&a * &b, sum_of_term_products(&a, &b), "{a:?} * {b:?}");
            }
        }
        assert!(packed >= 40 && unpacked >= 10, "packed {packed}, unpacked {unpacked}");
    }

    #[test]
    fn prints_highest_first_with_rationals() {
        let x = MPoly::var(0, 1);
        let p = x.pow(2) + x.scale(&q(1, 2)) - MPoly::constant(qi(3), 1);
        assert_eq!(p.to_string_with(&["x"]), "x^2 + 1/2*x - 3");
        assert_eq!((-&x).to_string_with(&["x"]), "-x");
        assert_eq!(MPoly::zero(1).to_string_with(&["x"]), "0");
    }

    #[test]
    fn exact_division_and_its_failure() {
        let (x, y) = xy();
        let a = &x + &y;
        let b = &x - &y;
        let p = &a * &b;
        assert_eq!(p.div_exact(&a), Some(b.clone()));
        assert_eq!(p.div_exact(&(&x + MPoly::one(2))), None);
        assert_eq!(p.div_exact(&MPoly::zero(2)), None);
    }

    /// The integer-step division against the quotient it must return, on
    /// seeded products of polynomials in three symbols with rational
    /// coefficients (large ones included), and its refusals: a remainder
    /// whose leading monomial is not a multiple, a leading coefficient the
    /// divisor's does not divide over Z after clearing (no division over Q
    /// either), and a zero dividend.
    #[test]
    fn integer_step_division_is_exact_on_rational_products() {
        let mut seed = 11u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            seed >> 33
        };
        let mut random = |terms: usize, big: bool| {
            let mut p = MPoly::zero(3);
            for _ in 0..terms {
                let m: Monomial = (0..3).map(|_| (next() % 3) as u32).collect();
                let n = BigInt::from(next() % 19) - 9;
                let d = BigInt::from(1 + next() % 7);
                let n = if big {
                    n * BigInt::from(next()).pow(4)
                } else {
                    n
                };
                p = p + MPoly::monomial(m, Q::new(n, d));
            }
            p
        };
        let mut checked = 0;
        for round in 0..200 {
            let (a, b) = (
                random(1 + round % 5, round % 3 == 0),
                random(1 + round % 4, round % 2 == 0),
            );
            if a.is_zero() || b.is_zero() {
                continue;
            }
            let p = &a * &b;
            assert_eq!(p.div_exact(&b), Some(a.clone()), "{round}");
            assert_eq!(p.div_exact(&a), Some(b.clone()), "{round}");
            if b.as_constant().is_none() {
                let off = &p + &MPoly::one(3);
                assert_eq!(off.div_exact(&b).map(|q| &q * &b), None, "{round}");
            }
            checked += 1;
        }
        assert!(checked >= 150, "only {checked} products checked");
        let (x, y) = xy();
        let two = MPoly::constant(qi(2), 2);
        // x + 1/2 divides x^2 + x/2, and 2x + 1 too: the scales of both
        // sides are undone exactly.
        let p = &(&x * &x) + &x.scale(&q(1, 2));
        let d = &x + &MPoly::constant(q(1, 2), 2);
        assert_eq!(p.div_exact(&d), Some(x.clone()));
        assert_eq!(p.div_exact(&(&two * &d)), Some(x.scale(&q(1, 2))));
        // 3x + 1 ∤ 2x^2 + x: integer leading coefficients 2 and 3.
        let p = &(&x * &x).scale(&qi(2)) + &x;
        let d = &x.scale(&qi(3)) + &MPoly::one(2);
        assert_eq!(p.div_exact(&d), None);
        assert_eq!(p.div_exact(&(&y + &x)), None);
        assert_eq!(MPoly::zero(2).div_exact(&d), Some(MPoly::zero(2)));
    }

    #[test]
    fn coefficients_round_trip() {
        let (x, y) = xy();
        let p = (&x * &y + &y).pow(3) - &x;
        for v in 0..2 {
            let cs = p.coeffs_in(v);
            assert_eq!(MPoly::from_coeffs_in(v, &cs, 2), p);
            assert!(cs.iter().all(|c| !c.contains_var(v)));
        }
    }

    #[test]
    fn substitution_and_evaluation() {
        let (x, y) = xy();
        let p = &x * &x - &y;
        assert_eq!(p.substitute(1, &(&x * &x)), MPoly::zero(2));
        assert_eq!(p.eval_var(0, &qi(2)), MPoly::constant(qi(4), 2) - &y);
    }

    #[test]
    fn primitive_normal_is_integer_positive() {
        let (x, y) = xy();
        let p = (x.scale(&q(-2, 3)) + y.scale(&q(4, 9))).primitive_normal();
        assert_eq!(p.to_string_with(&["x", "y"]), "3*x - 2*y");
    }
}
