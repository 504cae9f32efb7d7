//! The capability ladder of the exact algebra: [`Ring`] → [`GcdDomain`] →
//! [`EuclideanDomain`], and [`Field`]. Rings are *objects* (they may carry
//! variable names or a coefficient field) stored beside the data, so one
//! `Matrix<R>` type serves Q, Q\[x\], Q[s1..sn] and Q(others)\[λ\]. This module
//! only states the contracts; implementations live with their element types.

use super::print::{Node, PrintOptions, print};
use std::fmt::Debug;

/// A commutative ring with one, given as an object that knows how to operate
/// on its elements.
pub trait Ring: Clone + Debug {
    /// The element type.
    type Elem: Clone + PartialEq + Debug;
    /// The additive identity.
    fn zero(&self) -> Self::Elem;
    /// The multiplicative identity.
    fn one(&self) -> Self::Elem;
    /// `a + b`.
    fn add(&self, a: &Self::Elem, b: &Self::Elem) -> Self::Elem;
    /// `a - b`.
    fn sub(&self, a: &Self::Elem, b: &Self::Elem) -> Self::Elem;
    /// `a * b`.
    fn mul(&self, a: &Self::Elem, b: &Self::Elem) -> Self::Elem;
    /// `-a`.
    fn neg(&self, a: &Self::Elem) -> Self::Elem;
    /// Whether `a == 0`.
    fn is_zero(&self, a: &Self::Elem) -> bool;
    /// Whether `a == 1`.
    fn is_one(&self, a: &Self::Elem) -> bool {
        self.is_zero(&self.sub(a, &self.one()))
    }
    /// `Σ a_k·b_k`; rings may override it to normalise once per sum.
    fn dot<'a>(
        &self,
        terms: &mut dyn Iterator<Item = (&'a Self::Elem, &'a Self::Elem)>,
    ) -> Self::Elem
    where
        Self::Elem: 'a,
    {
        let mut acc = self.zero();
        for (a, b) in terms {
            if !self.is_zero(a) && !self.is_zero(b) {
                acc = self.add(&acc, &self.mul(a, b));
            }
        }
        acc
    }
    /// `Σ ±a_k·b_k` (the flag: subtract); rings may override it to sum
    /// once.
    fn signed_dot<'a>(
        &self,
        terms: &mut dyn Iterator<Item = (&'a Self::Elem, &'a Self::Elem, bool)>,
    ) -> Self::Elem
    where
        Self::Elem: 'a,
    {
        let mut acc = self.zero();
        for (a, b, minus) in terms {
            if !self.is_zero(a) && !self.is_zero(b) {
                let p = self.mul(a, b);
                acc = if minus {
                    self.sub(&acc, &p)
                } else {
                    self.add(&acc, &p)
                };
            }
        }
        acc
    }
    /// Whether `a` is invertible in this ring.
    fn is_unit(&self, a: &Self::Elem) -> bool;
    /// The print tree of an element (expanded, highest degree first): the
    /// one source of [`Ring::format`], [`Ring::latex`] and [`Ring::lmx`].
    fn node(&self, a: &Self::Elem) -> Node;
    /// Human-readable form of an element.
    fn format(&self, a: &Self::Elem) -> String {
        print(&self.node(a), PrintOptions::TEXT)
    }
    /// LaTeX form of an element.
    fn latex(&self, a: &Self::Elem) -> String {
        print(&self.node(a), PrintOptions::LATEX)
    }
    /// The element in the language's syntax (parses back to it).
    fn lmx(&self, a: &Self::Elem) -> String {
        print(&self.node(a), PrintOptions::LMX)
    }
    /// Whether the printed form of `a` starts with a minus sign (used to
    /// print sums as `a - b` rather than `a + -b`).
    fn is_negative(&self, _a: &Self::Elem) -> bool {
        false
    }
    /// A short name of the ring, e.g. `Q[x]` or `Q(k1, k2, k3)[k4]`.
    fn name(&self) -> String;
}

/// An integral domain with exact division and greatest common divisors.
pub trait GcdDomain: Ring {
    /// `a / b` when `b` divides `a`, otherwise `None` (also for `b = 0`).
    fn div_exact(&self, a: &Self::Elem, b: &Self::Elem) -> Option<Self::Elem>;
    /// A greatest common divisor, normalised so that it is unique.
    fn gcd(&self, a: &Self::Elem, b: &Self::Elem) -> Self::Elem;
    /// The normalised associate of `a` (e.g. monic, or primitive with a
    /// positive leading coefficient); `0` stays `0`.
    fn normalize(&self, a: &Self::Elem) -> Self::Elem;
    /// A rough size of `a` (its number of terms, for polynomials), by
    /// which gcd folds take small elements first; 0 where not measured.
    fn bulk(&self, _a: &Self::Elem) -> usize {
        0
    }
}

/// A Euclidean domain: division with remainder decreasing a size function.
pub trait EuclideanDomain: GcdDomain {
    /// The Euclidean size (degree for polynomials); `None` for zero.
    fn size(&self, a: &Self::Elem) -> Option<usize>;
    /// `(q, r)` with `a = q*b + r` and `size(r) < size(b)`; `b` must be nonzero.
    fn div_rem(&self, a: &Self::Elem, b: &Self::Elem) -> (Self::Elem, Self::Elem);
    /// The unit `u` with `u * a == normalize(a)` (`a` nonzero).
    fn normal_unit(&self, a: &Self::Elem) -> Self::Elem;
    /// A unit by which a row (or column) of a matrix may be scaled to keep its
    /// coefficients small, e.g. clearing denominators and integer content in
    /// Q\[x\]. The default is one (no scaling).
    fn row_scale_unit(&self, _row: &[&Self::Elem]) -> Self::Elem {
        self.one()
    }
    /// The inverse of a unit.
    fn unit_inverse(&self, u: &Self::Elem) -> Self::Elem;
}

/// A field.
pub trait Field: Ring {
    /// `1/a`, or `None` for `a = 0`.
    fn inv(&self, a: &Self::Elem) -> Option<Self::Elem>;
    /// A nonzero scalar by which a list of coefficients may be multiplied to
    /// keep them small (for Q: clear denominators and integer content).
    /// Default: one.
    fn small_scale(&self, _coeffs: &[&Self::Elem]) -> Self::Elem {
        self.one()
    }
}
