//! Dense univariate polynomials over any field object `K`: the Euclidean
//! domain K\[λ\] on which the Smith normal form is computed (K = Q for one
//! symbol, K = Q(others) for a principal symbol). Owns the coefficient
//! vectors, long division and printing; knows nothing of matrices.

use super::print::Node;
use super::ring::{EuclideanDomain, Field, GcdDomain, Ring};

/// A polynomial `Σ c[k] λ^k`, coefficients low degree first, no trailing
/// zeros (so the zero polynomial is the empty vector).
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub struct UPoly<E>(pub Vec<E>);

impl<E> UPoly<E> {
    /// Degree (`None` for zero).
    pub fn degree(&self) -> Option<usize> {
        self.0.len().checked_sub(1)
    }
    /// Coefficients, low degree first.
    pub fn coeffs(&self) -> &[E] {
        &self.0
    }
}

/// The ring K\[var\].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UPolyRing<K: Field> {
    /// The coefficient field.
    pub k: K,
    /// The variable's name.
    pub var: String,
}

impl<K: Field> UPolyRing<K> {
    /// K\[var\].
    pub fn new(k: K, var: impl Into<String>) -> Self {
        UPolyRing { k, var: var.into() }
    }

    /// Removes trailing zeros.
    pub fn trim(&self, mut c: Vec<K::Elem>) -> UPoly<K::Elem> {
        while c.last().is_some_and(|x| self.k.is_zero(x)) {
            c.pop();
        }
        UPoly(c)
    }

    /// The zero polynomial (a convenience for doc examples).
    #[cfg(any(test, feature = "internals"))]
    pub fn zero_of(&self) -> UPoly<K::Elem> {
        UPoly(Vec::new())
    }

    /// Multiplies by a scalar.
    pub fn scale(&self, a: &UPoly<K::Elem>, c: &K::Elem) -> UPoly<K::Elem> {
        if self.k.is_zero(c) {
            return UPoly(Vec::new());
        }
        UPoly(a.0.iter().map(|x| self.k.mul(x, c)).collect())
    }

    /// Leading coefficient (zero for zero).
    pub fn lc(&self, a: &UPoly<K::Elem>) -> K::Elem {
        a.0.last().cloned().unwrap_or_else(|| self.k.zero())
    }

    /// The term `c·var^k` as `(negative, magnitude)`: a sign of the
    /// coefficient is taken out, a sum keeps its parentheses through the
    /// printer (`(k1 + 1)*k4`), a fraction is grouped (`(1/k1)*k4^2`).
    fn term_node(&self, c: &K::Elem, k: usize) -> (bool, Node) {
        let (neg, mag) = self.k.node(c).split_sign();
        if k == 0 {
            return (neg, mag);
        }
        let power = Node::pow_i(Node::Sym(self.var.clone()), k as i64);
        let coeff = match mag {
            Node::Terms(mut ts) if ts.len() == 1 && !ts[0].0 => ts.remove(0).1,
            other => other,
        };
        let coeff = match coeff {
            Node::Div(..) => Node::Group(Box::new(coeff)),
            other => other,
        };
        (neg, Node::product(vec![coeff, power]))
    }
}

impl<K: Field> Ring for UPolyRing<K> {
    type Elem = UPoly<K::Elem>;
    fn zero(&self) -> Self::Elem {
        UPoly(Vec::new())
    }
    fn one(&self) -> Self::Elem {
        UPoly(vec![self.k.one()])
    }
    fn add(&self, a: &Self::Elem, b: &Self::Elem) -> Self::Elem {
        let n = a.0.len().max(b.0.len());
        let z = self.k.zero();
        let c = (0..n)
            .map(|i| {
                self.k
                    .add(a.0.get(i).unwrap_or(&z), b.0.get(i).unwrap_or(&z))
            })
            .collect();
        self.trim(c)
    }
    fn sub(&self, a: &Self::Elem, b: &Self::Elem) -> Self::Elem {
        let n = a.0.len().max(b.0.len());
        let z = self.k.zero();
        let c = (0..n)
            .map(|i| {
                self.k
                    .sub(a.0.get(i).unwrap_or(&z), b.0.get(i).unwrap_or(&z))
            })
            .collect();
        self.trim(c)
    }
    fn mul(&self, a: &Self::Elem, b: &Self::Elem) -> Self::Elem {
        if a.0.is_empty() || b.0.is_empty() {
            return self.zero();
        }
        let mut c = vec![self.k.zero(); a.0.len() + b.0.len() - 1];
        for (i, x) in a.0.iter().enumerate() {
            if self.k.is_zero(x) {
                continue;
            }
            for (j, y) in b.0.iter().enumerate() {
                c[i + j] = self.k.add(&c[i + j], &self.k.mul(x, y));
            }
        }
        self.trim(c)
    }
    fn neg(&self, a: &Self::Elem) -> Self::Elem {
        UPoly(a.0.iter().map(|x| self.k.neg(x)).collect())
    }
    fn is_zero(&self, a: &Self::Elem) -> bool {
        a.0.is_empty()
    }
    fn is_unit(&self, a: &Self::Elem) -> bool {
        a.0.len() == 1
    }
    fn node(&self, a: &Self::Elem) -> Node {
        Node::Terms(
            a.0.iter()
                .enumerate()
                .rev()
                .filter(|(_, c)| !self.k.is_zero(c))
                .map(|(k, c)| self.term_node(c, k))
                .collect(),
        )
    }
    fn is_negative(&self, a: &Self::Elem) -> bool {
        a.0.last().is_some_and(|c| self.k.is_negative(c))
    }
    fn name(&self) -> String {
        let k = self.k.name();
        format!("{k}[{}]", self.var)
    }
}

impl<K: Field> GcdDomain for UPolyRing<K> {
    fn div_exact(&self, a: &Self::Elem, b: &Self::Elem) -> Option<Self::Elem> {
        if b.0.is_empty() {
            return None;
        }
        let (q, r) = self.div_rem(a, b);
        r.0.is_empty().then_some(q)
    }
    fn gcd(&self, a: &Self::Elem, b: &Self::Elem) -> Self::Elem {
        let (mut x, mut y) = (a.clone(), b.clone());
        while !y.0.is_empty() {
            let (_, r) = self.div_rem(&x, &y);
            x = y;
            y = r;
        }
        self.normalize(&x)
    }
    fn normalize(&self, a: &Self::Elem) -> Self::Elem {
        if a.0.is_empty() {
            return a.clone();
        }
        self.scale(a, &self.normal_unit_scalar(a))
    }
}

impl<K: Field> UPolyRing<K> {
    fn normal_unit_scalar(&self, a: &UPoly<K::Elem>) -> K::Elem {
        self.k
            .inv(&self.lc(a))
            .expect("nonzero leading coefficient")
    }
}

impl<K: Field> EuclideanDomain for UPolyRing<K> {
    fn size(&self, a: &Self::Elem) -> Option<usize> {
        a.degree()
    }
    fn div_rem(&self, a: &Self::Elem, b: &Self::Elem) -> (Self::Elem, Self::Elem) {
        let db = b.degree().expect("division by zero polynomial");
        let inv = self
            .k
            .inv(&self.lc(b))
            .expect("nonzero leading coefficient");
        let mut r = a.0.clone();
        let Some(da) = a.degree().filter(|&d| d >= db) else {
            return (self.zero(), a.clone());
        };
        let mut q = vec![self.k.zero(); da - db + 1];
        for k in (db..=da).rev() {
            if self.k.is_zero(&r[k]) {
                continue;
            }
            let c = self.k.mul(&r[k], &inv);
            for (j, bj) in b.0.iter().enumerate() {
                let t = self.k.mul(&c, bj);
                r[k - db + j] = self.k.sub(&r[k - db + j], &t);
            }
            q[k - db] = c;
        }
        r.truncate(db);
        (self.trim(q), self.trim(r))
    }
    fn normal_unit(&self, a: &Self::Elem) -> Self::Elem {
        UPoly(vec![self.normal_unit_scalar(a)])
    }
    fn row_scale_unit(&self, row: &[&Self::Elem]) -> Self::Elem {
        let coeffs: Vec<&K::Elem> = row.iter().flat_map(|p| p.0.iter()).collect();
        UPoly(vec![self.k.small_scale(&coeffs)])
    }
    fn unit_inverse(&self, u: &Self::Elem) -> Self::Elem {
        UPoly(vec![self.k.inv(&u.0[0]).expect("a unit")])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::rational::{Rationals, q, qi};

    fn ring() -> UPolyRing<Rationals> {
        UPolyRing::new(Rationals, "x")
    }

    #[test]
    fn division_with_remainder_reconstructs() {
        let r = ring();
        let a = UPoly(vec![qi(-3), q(1, 2), qi(0), qi(2)]);
        let b = UPoly(vec![qi(1), qi(3)]);
        let (qq, rr) = r.div_rem(&a, &b);
        assert_eq!(r.add(&r.mul(&qq, &b), &rr), a);
        assert!(rr.degree().unwrap_or(0) < 1);
    }

    #[test]
    fn gcd_is_monic() {
        let r = ring();
        let f = UPoly(vec![qi(-1), qi(2)]); // 2x - 1
        let a = r.mul(&f, &UPoly(vec![qi(1), qi(1)]));
        let b = r.mul(&f, &UPoly(vec![qi(5), qi(0), qi(1)]));
        assert_eq!(r.format(&r.gcd(&a, &b)), "x - 1/2");
    }

    #[test]
    fn prints_like_the_issue_says() {
        let r = ring();
        let p = UPoly(vec![qi(-3), q(1, 2), qi(1)]);
        assert_eq!(r.format(&p), "x^2 + 1/2*x - 3");
        assert_eq!(r.latex(&p), "x^{2} + \\frac{1}{2} x - 3");
        assert_eq!(r.format(&r.zero()), "0");
    }
}
