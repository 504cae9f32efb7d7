//! The field Q of exact rationals (`num_rational::BigRational`) as a ring
//! object, plus the small helpers every other algebra module uses to build
//! and print rationals. Nothing here knows about polynomials.

use super::print::{Node, PrintOptions, print};
use super::ring::{Field, Ring};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// Exact rational number.
pub type Q = BigRational;

/// The rational `n/d` from machine integers (`d` nonzero).
#[cfg(any(test, feature = "internals"))]
pub fn q(n: i64, d: i64) -> Q {
    Q::new(BigInt::from(n), BigInt::from(d))
}

/// The rational `n`.
#[cfg(any(test, feature = "internals"))]
pub fn qi(n: i64) -> Q {
    Q::from_integer(BigInt::from(n))
}

/// Prints `a` as `n` or `n/d`.
pub fn fmt_q(a: &Q) -> String {
    print(&Node::Num(a.clone()), PrintOptions::TEXT)
}

/// LaTeX form of `a`: `n` or `\frac{n}{d}` (with the sign in front).
pub fn latex_q(a: &Q) -> String {
    print(&Node::Num(a.clone()), PrintOptions::LATEX)
}

/// The unit `u > 0` such that `u * c` are coprime integers for all `c` in
/// `coeffs` (lcm of denominators over gcd of numerators); one for an empty
/// or all-zero list.
pub fn primitive_scale<'a>(coeffs: impl IntoIterator<Item = &'a Q>) -> Q {
    let mut l = BigInt::one();
    let mut g = BigInt::zero();
    for c in coeffs {
        if c.is_zero() {
            continue;
        }
        // Lehmer's gcd (num's binary gcd is quadratic in bits, with a
        // large constant, on the big coefficients of eliminations).
        if !c.denom().is_one() {
            l = super::intgcd::lcm(&l, c.denom());
        }
        if !g.is_one() {
            g = super::intgcd::gcd(&g, c.numer());
        }
    }
    if g.is_zero() {
        Q::one()
    } else {
        // Already in lowest terms: a prime dividing g divides every
        // numerator, so no denominator (each coefficient is reduced).
        Q::new_raw(l, g)
    }
}

/// The field of rationals.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Rationals;

impl Ring for Rationals {
    type Elem = Q;
    fn zero(&self) -> Q {
        Q::zero()
    }
    fn one(&self) -> Q {
        Q::one()
    }
    fn add(&self, a: &Q, b: &Q) -> Q {
        a + b
    }
    fn sub(&self, a: &Q, b: &Q) -> Q {
        a - b
    }
    fn mul(&self, a: &Q, b: &Q) -> Q {
        a * b
    }
    fn neg(&self, a: &Q) -> Q {
        -a
    }
    fn is_zero(&self, a: &Q) -> bool {
        a.is_zero()
    }
    fn is_unit(&self, a: &Q) -> bool {
        !a.is_zero()
    }
    fn is_one(&self, a: &Q) -> bool {
        a.is_one()
    }
    fn node(&self, a: &Q) -> Node {
        Node::Num(a.clone())
    }
    fn is_negative(&self, a: &Q) -> bool {
        a.is_negative()
    }
    fn name(&self) -> String {
        "Q".into()
    }
}

impl Field for Rationals {
    fn inv(&self, a: &Q) -> Option<Q> {
        (!a.is_zero()).then(|| a.recip())
    }
    fn small_scale(&self, coeffs: &[&Q]) -> Q {
        primitive_scale(coeffs.iter().copied())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn primitive_scale_clears_denominators_and_content() {
        let cs = [q(2, 3), q(-4, 9), qi(0)];
        let u = primitive_scale(cs.iter());
        let scaled: Vec<Q> = cs.iter().map(|c| c * &u).collect();
        assert_eq!(scaled, vec![qi(3), qi(-2), qi(0)]);
    }

    #[test]
    fn formats_integers_and_fractions() {
        assert_eq!(fmt_q(&q(-6, 4)), "-3/2");
        assert_eq!(fmt_q(&qi(7)), "7");
    }
}
