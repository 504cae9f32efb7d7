//! Q\[x\] specialised for speed: a polynomial is a vector of `BigInt`
//! numerators over one common positive denominator, kept coprime, so ring
//! operations are integer convolutions with one gcd per result instead of
//! one per coefficient. [`QxRing`] implements the same contracts as
//! `UPolyRing<Rationals>` (tests check that they agree) and prints the
//! same way. It knows nothing of matrices.

use super::intgcd::{gcd, lcm};
use super::rational::{Q, Rationals};
use super::ring::{EuclideanDomain, GcdDomain, Ring};
use super::upoly::{UPoly, UPolyRing};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// `Σ num[k] x^k / den`, `den > 0`, no trailing zeros, `gcd(den, num) = 1`.
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub struct QPoly {
    num: Vec<BigInt>,
    den: BigInt,
}

impl QPoly {
    /// `num / den` in canonical form (`den` nonzero).
    pub fn new(mut num: Vec<BigInt>, mut den: BigInt) -> Self {
        while num.last().is_some_and(|c| c.is_zero()) {
            num.pop();
        }
        if num.is_empty() {
            return QPoly {
                num,
                den: BigInt::one(),
            };
        }
        if den.is_negative() {
            den = -den;
            for c in num.iter_mut() {
                *c = -&*c;
            }
        }
        let mut g = den.clone();
        for c in &num {
            if g.is_one() {
                break;
            }
            g = gcd(&g, c);
        }
        if !g.is_one() {
            for c in num.iter_mut() {
                *c /= &g;
            }
            den /= &g;
        }
        QPoly { num, den }
    }

    /// The integer polynomial `Σ c[k] x^k`.
    pub fn from_ints(c: Vec<BigInt>) -> Self {
        Self::new(c, BigInt::one())
    }

    /// The constant `c`.
    pub fn constant(c: &Q) -> Self {
        Self::new(vec![c.numer().clone()], c.denom().clone())
    }

    /// The constant `c` given in lowest terms with a positive denominator
    /// (as every reduced `Q` is): no gcd is taken. The caller vouches for
    /// the form (checked in debug builds).
    pub(crate) fn constant_reduced(c: &Q) -> Self {
        debug_assert!(c.denom().is_positive() && gcd(c.numer(), c.denom()).is_one());
        if c.numer().is_zero() {
            return Self::new(Vec::new(), BigInt::one());
        }
        QPoly {
            num: vec![c.numer().clone()],
            den: c.denom().clone(),
        }
    }

    /// Numerators, low degree first.
    pub fn num(&self) -> &[BigInt] {
        &self.num
    }

    /// The common denominator.
    pub fn den(&self) -> &BigInt {
        &self.den
    }

    /// Degree (`None` for zero).
    pub fn degree(&self) -> Option<usize> {
        self.num.len().checked_sub(1)
    }

    /// Whether zero.
    pub fn is_zero(&self) -> bool {
        self.num.is_empty()
    }

    /// Coefficient `k` as a rational.
    pub fn coeff(&self, k: usize) -> Q {
        match self.num.get(k) {
            None => Q::zero(),
            Some(c) if self.den.is_one() => Q::from_integer(c.clone()),
            Some(c) => {
                let g = gcd(c, &self.den);
                Q::new_raw(c / &g, &self.den / &g)
            }
        }
    }

    /// As a dense polynomial with rational coefficients.
    pub fn to_upoly(&self) -> UPoly<Q> {
        UPoly((0..self.num.len()).map(|k| self.coeff(k)).collect())
    }

    /// From a dense polynomial with rational coefficients.
    pub fn from_upoly(p: &UPoly<Q>) -> Self {
        let l = p.0.iter().fold(BigInt::one(), |l, c| lcm(&l, c.denom()));
        Self::new(
            p.0.iter().map(|c| c.numer() * (&l / c.denom())).collect(),
            l,
        )
    }

    /// Multiplies by the rational `c`.
    pub fn scale(&self, c: &Q) -> Self {
        Self::new(
            self.num.iter().map(|x| x * c.numer()).collect(),
            &self.den * c.denom(),
        )
    }

    /// The leading coefficient.
    pub fn lc(&self) -> Q {
        self.degree().map(|d| self.coeff(d)).unwrap_or_else(Q::zero)
    }

    /// Positive integer content of the numerator (zero for zero).
    fn content(&self) -> BigInt {
        let mut g = BigInt::zero();
        for c in &self.num {
            g = gcd(&g, c);
            if g.is_one() {
                break;
            }
        }
        g
    }

}

/// Shorter factors use the schoolbook product.
pub(crate) const KRONECKER_MIN_LEN: usize = 24;

fn add_vec(
    a: &[BigInt],
    fa: Option<&BigInt>,
    b: &[BigInt],
    fb: Option<&BigInt>,
    sub: bool,
) -> Vec<BigInt> {
    let n = a.len().max(b.len());
    let mut out = Vec::with_capacity(n);
    for k in 0..n {
        let x = match (a.get(k), fa) {
            (Some(x), Some(f)) => x * f,
            (Some(x), None) => x.clone(),
            (None, _) => BigInt::zero(),
        };
        let y = match (b.get(k), fb) {
            (Some(y), Some(f)) => y * f,
            (Some(y), None) => y.clone(),
            (None, _) => BigInt::zero(),
        };
        out.push(if sub { x - y } else { x + y });
    }
    out
}

/// Whether the Kronecker product beats the schoolbook one: both factors
/// long, and not one with word-size coefficients against one with
/// coefficients of many words (packing would pad the small side to the
/// big side's width, and the schoolbook products are then one-word
/// scalings).
pub(crate) fn kronecker_pays(a: &[BigInt], b: &[BigInt]) -> bool {
    if a.len().min(b.len()) < KRONECKER_MIN_LEN {
        return false;
    }
    let bits = |v: &[BigInt]| v.iter().map(|c| c.bits()).max().unwrap_or(0);
    let (ba, bb) = (bits(a), bits(b));
    !(ba.min(bb) <= 64 && ba.max(bb) >= 64 * 16)
}

pub(crate) fn conv(a: &[BigInt], b: &[BigInt]) -> Vec<BigInt> {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    if kronecker_pays(a, b) {
        return super::kronecker::mul(a, b);
    }
    let mut c = vec![BigInt::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        if x.is_zero() {
            continue;
        }
        for (j, y) in b.iter().enumerate() {
            c[i + j] += x * y;
        }
    }
    c
}

/// The ring Q\[var\] with the fast representation.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct QxRing {
    /// The variable's name.
    pub var: String,
}

impl QxRing {
    /// Q\[var\].
    pub fn new(var: impl Into<String>) -> Self {
        QxRing { var: var.into() }
    }

    fn printer(&self) -> UPolyRing<Rationals> {
        UPolyRing::new(Rationals, self.var.clone())
    }

    fn combine(&self, a: &QPoly, b: &QPoly, sub: bool) -> QPoly {
        if a.den == b.den {
            return QPoly::new(add_vec(&a.num, None, &b.num, None, sub), a.den.clone());
        }
        let g = gcd(&a.den, &b.den);
        let fa = &b.den / &g;
        let fb = &a.den / &g;
        let den = &a.den * &fa;
        QPoly::new(add_vec(&a.num, Some(&fa), &b.num, Some(&fb), sub), den)
    }

    /// Extended Euclid: `(g, s)` with `s·a ≡ g (mod m)`, `g` monic gcd.
    pub fn ext_gcd_mod(&self, a: &QPoly, m: &QPoly) -> (QPoly, QPoly) {
        let (mut r0, mut r1) = (m.clone(), self.rem(a, m));
        let (mut s0, mut s1) = (self.zero(), self.one());
        while !r1.is_zero() {
            let (q, r) = self.div_rem(&r0, &r1);
            let s = self.sub(&s0, &self.mul(&q, &s1));
            // Scale the new remainder to coprime integers; scale s alike.
            let u = primitive_unit(&r);
            r0 = r1;
            s0 = s1;
            r1 = r.scale(&u);
            s1 = s.scale(&u);
        }
        let inv = r0.lc().recip();
        (r0.scale(&inv), self.rem(&s0.scale(&inv), m))
    }

    /// The inverse of `a` modulo `m` (`deg m ≥ 1`), if `gcd(a, m) = 1`:
    /// modular images and the Chinese remainder theorem
    /// ([`super::modgcd::qx_inverse`]) first, the exact extended Euclid
    /// over Q when that route declines.
    pub fn inverse_mod(&self, a: &QPoly, m: &QPoly) -> Option<QPoly> {
        let a = self.rem(a, m);
        if a.is_zero() {
            return None;
        }
        if let Some((s, r)) = super::modgcd::qx_inverse(&a.num, &m.num) {
            // a = A/da, so a⁻¹ = da·A⁻¹; m and its numerator generate the
            // same ideal.
            return Some(QPoly::new(s.into_iter().map(|c| c * &a.den).collect(), r));
        }
        let (g, s) = self.ext_gcd_mod(&a, m);
        self.is_unit(&g).then_some(s)
    }

    /// `a mod m`.
    pub fn rem(&self, a: &QPoly, m: &QPoly) -> QPoly {
        self.div_rem(a, m).1
    }
}

/// The positive rational `u` making `u·p` a primitive integer polynomial.
fn primitive_unit(p: &QPoly) -> Q {
    let c = p.content();
    if c.is_zero() {
        Q::one()
    } else {
        Q::new(p.den.clone(), c)
    }
}

impl Ring for QxRing {
    type Elem = QPoly;
    fn zero(&self) -> QPoly {
        QPoly::new(Vec::new(), BigInt::one())
    }
    fn one(&self) -> QPoly {
        QPoly::from_ints(vec![BigInt::one()])
    }
    fn add(&self, a: &QPoly, b: &QPoly) -> QPoly {
        self.combine(a, b, false)
    }
    fn sub(&self, a: &QPoly, b: &QPoly) -> QPoly {
        self.combine(a, b, true)
    }
    fn mul(&self, a: &QPoly, b: &QPoly) -> QPoly {
        QPoly::new(conv(&a.num, &b.num), &a.den * &b.den)
    }
    fn neg(&self, a: &QPoly) -> QPoly {
        QPoly {
            num: a.num.iter().map(|c| -c).collect(),
            den: a.den.clone(),
        }
    }
    fn is_zero(&self, a: &QPoly) -> bool {
        a.num.is_empty()
    }
    fn is_unit(&self, a: &QPoly) -> bool {
        a.num.len() == 1
    }
    fn is_one(&self, a: &QPoly) -> bool {
        a.num.len() == 1 && a.num[0].is_one() && a.den.is_one()
    }
    /// One running common denominator, one normalisation per sum.
    fn dot<'a>(&self, terms: &mut dyn Iterator<Item = (&'a QPoly, &'a QPoly)>) -> QPoly
    where
        QPoly: 'a,
    {
        let mut acc: Vec<BigInt> = Vec::new();
        let mut l = BigInt::one();
        for (a, b) in terms {
            if a.is_zero() || b.is_zero() {
                continue;
            }
            let num = conv(&a.num, &b.num);
            let den = &a.den * &b.den;
            let (fa, fn_) = if den == l {
                (None, None)
            } else {
                let g = gcd(&l, &den);
                let fa = &den / &g;
                let fn_ = &l / &g;
                l = &l * &fa;
                (Some(fa), Some(fn_))
            };
            acc = add_vec(&acc, fa.as_ref(), &num, fn_.as_ref(), false);
        }
        QPoly::new(acc, l)
    }
    fn node(&self, a: &QPoly) -> crate::algebra::print::Node {
        self.printer().node(&a.to_upoly())
    }
    /// The language form written directly (the same text as the print
    /// tree gives, tested: terms from the top degree, `c*x^k` with `c` in
    /// lowest terms, unit coefficients omitted), without building a tree
    /// per coefficient: a large U prints several times faster.
    fn lmx(&self, a: &QPoly) -> String {
        use num_traits::ToPrimitive;
        use std::fmt::Write;
        if a.is_zero() {
            return "0".to_string();
        }
        // Room for the digits (bits·log10 2 < bits·0.302) and the
        // separators, so the string grows once.
        let den_digits = (a.den.bits() as usize * 302).div_ceil(1000) + 1;
        let room: usize = a
            .num
            .iter()
            .map(|c| (c.bits() as usize * 302).div_ceil(1000) + den_digits + 8 + self.var.len())
            .sum();
        let mut out = String::with_capacity(room);
        let mut first = true;
        for k in (0..a.num.len()).rev() {
            let c = &a.num[k];
            if c.is_zero() {
                continue;
            }
            out.push_str(match (first, c.is_negative()) {
                (true, true) => "-",
                (true, false) => "",
                (false, true) => " - ",
                (false, false) => " + ",
            });
            first = false;
            let mag = c.magnitude();
            let (n, d) = if a.den.is_one() {
                (std::borrow::Cow::Borrowed(mag), None)
            } else if let Some(den) = a.den.to_u64() {
                // A word-size denominator: the gcd from one remainder.
                let r = (mag % den).to_u64().unwrap_or(0);
                let g = num_integer::Integer::gcd(&r, &den);
                let n = if g == 1 {
                    std::borrow::Cow::Borrowed(mag)
                } else {
                    std::borrow::Cow::Owned(mag / g)
                };
                (
                    n,
                    (den != g).then(|| std::borrow::Cow::Owned(num_bigint::BigUint::from(den / g))),
                )
            } else {
                let g = super::intgcd::gcd_nat(mag, a.den.magnitude());
                if g.is_one() {
                    (
                        std::borrow::Cow::Borrowed(mag),
                        Some(std::borrow::Cow::Borrowed(a.den.magnitude())),
                    )
                } else {
                    let d = a.den.magnitude() / &g;
                    let n = mag / &g;
                    if d.is_one() {
                        (std::borrow::Cow::Owned(n), None)
                    } else {
                        (std::borrow::Cow::Owned(n), Some(std::borrow::Cow::Owned(d)))
                    }
                }
            };
            let unit = n.is_one() && d.is_none();
            if k == 0 || !unit {
                super::decimal::write_nat(&mut out, &n);
                if let Some(d) = d {
                    out.push('/');
                    super::decimal::write_nat(&mut out, &d);
                }
                if k > 0 {
                    out.push('*');
                }
            }
            if k > 0 {
                out.push_str(&self.var);
                if k > 1 {
                    let _ = write!(out, "^{k}");
                }
            }
        }
        out
    }
    fn is_negative(&self, a: &QPoly) -> bool {
        a.num.last().is_some_and(|c| c.is_negative())
    }
    fn name(&self) -> String {
        format!("Q[{}]", self.var)
    }
}

impl GcdDomain for QxRing {
    fn div_exact(&self, a: &QPoly, b: &QPoly) -> Option<QPoly> {
        if b.is_zero() {
            return None;
        }
        let (q, r) = self.div_rem(a, b);
        r.is_zero().then_some(q)
    }
    fn gcd(&self, a: &QPoly, b: &QPoly) -> QPoly {
        let (mut x, mut y) = (a.clone(), b.clone());
        while !y.is_zero() {
            let r = self.rem(&x, &y);
            x = y;
            y = r.scale(&primitive_unit(&r));
        }
        self.normalize(&x)
    }
    fn normalize(&self, a: &QPoly) -> QPoly {
        if a.is_zero() {
            return a.clone();
        }
        let lc = a.num.last().expect("nonzero").clone();
        QPoly::new(a.num.clone(), lc)
    }
}

impl EuclideanDomain for QxRing {
    fn size(&self, a: &QPoly) -> Option<usize> {
        a.degree()
    }
    /// Integer pseudo-division `lb^k·A = Q·B + R`, then rescaled.
    fn div_rem(&self, a: &QPoly, b: &QPoly) -> (QPoly, QPoly) {
        let n = b.degree().expect("division by the zero polynomial");
        let Some(m) = a.degree().filter(|&m| m >= n) else {
            return (self.zero(), a.clone());
        };
        let bn = &b.num;
        let lb = bn[n].clone();
        let unit_lb = lb.is_one();
        let mut r = a.num.clone();
        let mut q = vec![BigInt::zero(); m - n + 1];
        let mut scale = BigInt::one();
        for i in (0..=m - n).rev() {
            let c = std::mem::take(&mut r[i + n]);
            if c.is_zero() {
                continue;
            }
            if !unit_lb {
                for x in q.iter_mut() {
                    *x *= &lb;
                }
                for x in r[..i + n].iter_mut() {
                    *x *= &lb;
                }
                scale *= &lb;
            }
            for j in 0..n {
                r[i + j] -= &c * &bn[j];
            }
            q[i] = c;
        }
        r.truncate(n);
        // a = A/ad, b = B/bd:  a = (Q·bd/(ad·s))·b + R/(ad·s).
        let qd = &a.den * &scale;
        let quot = QPoly::new(q.into_iter().map(|x| x * &b.den).collect(), qd.clone());
        (quot, QPoly::new(r, qd))
    }
    fn normal_unit(&self, a: &QPoly) -> QPoly {
        QPoly::constant(&a.lc().recip())
    }
    fn row_scale_unit(&self, row: &[&QPoly]) -> QPoly {
        let mut l = BigInt::one();
        for p in row {
            if !p.is_zero() {
                l = lcm(&l, &p.den);
            }
        }
        let mut g = BigInt::zero();
        for p in row {
            if p.is_zero() {
                continue;
            }
            let f = &l / &p.den;
            for c in &p.num {
                g = gcd(&g, &(c * &f));
                if g.is_one() {
                    break;
                }
            }
            if g.is_one() {
                break;
            }
        }
        if g.is_zero() {
            return self.one();
        }
        QPoly::constant(&Q::new(l, g))
    }
    fn unit_inverse(&self, u: &QPoly) -> QPoly {
        QPoly::constant(&u.lc().recip())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::print::{PrintOptions, print};
    use crate::algebra::rational::{q, qi};

    fn p(c: &[Q]) -> (QPoly, UPoly<Q>) {
        let u = UPoly(c.to_vec());
        (QPoly::from_upoly(&u), u)
    }

    #[test]
    fn agrees_with_the_generic_ring() {
        let fast = QxRing::new("x");
        let slow = UPolyRing::new(Rationals, "x");
        let (a, ua) = p(&[q(-3, 2), q(5, 7), qi(0), q(2, 3)]);
        let (b, ub) = p(&[q(1, 4), qi(-3)]);
        for (x, y) in [
            (fast.add(&a, &b), slow.add(&ua, &ub)),
            (fast.sub(&a, &b), slow.sub(&ua, &ub)),
            (fast.mul(&a, &b), slow.mul(&ua, &ub)),
            (fast.div_rem(&a, &b).0, slow.div_rem(&ua, &ub).0),
            (fast.div_rem(&a, &b).1, slow.div_rem(&ua, &ub).1),
            (fast.gcd(&a, &b), slow.gcd(&ua, &ub)),
        ] {
            assert_eq!(x.to_upoly(), y);
        }
        assert_eq!(fast.format(&a), slow.format(&ua));
    }

    #[test]
    fn direct_language_form_is_the_print_trees() {
        let r = QxRing::new("lam");
        let mut seed = 5u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 33) as i64
        };
        let mut checked = 0;
        for round in 0..300 {
            let len = (round % 6) as usize;
            let big = BigInt::from(10).pow((round % 4) as u32 * 9);
            let num: Vec<BigInt> = (0..len)
                .map(|_| match next() % 5 {
                    0 => BigInt::zero(),
                    1 => BigInt::from(1 - 2 * (next() % 2)),
                    _ => (BigInt::from(next() % 2001 - 1000)) * &big,
                })
                .collect();
            let den = match next() % 4 {
                0 => BigInt::one(),
                1 => BigInt::from(next() % 60 + 1) * &big * &big * &big,
                _ => BigInt::from(next() % 60 + 1) * &big,
            };
            let a = QPoly::new(num, den);
            let want = print(&r.node(&a), PrintOptions::LMX);
            assert_eq!(r.lmx(&a), want, "{a:?}");
            checked += 1;
        }
        assert_eq!(checked, 300);
    }

    #[test]
    fn modular_inverse() {
        let r = QxRing::new("x");
        let (m, _) = p(&[qi(1), qi(0), qi(0), qi(3)]);
        let (a, _) = p(&[q(1, 2), qi(2), qi(1)]);
        let (g, s) = r.ext_gcd_mod(&a, &m);
        assert_eq!(g, r.one());
        assert_eq!(r.rem(&r.mul(&s, &a), &m), r.one());
    }
}
