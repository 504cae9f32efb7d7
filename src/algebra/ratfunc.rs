//! The field Q(s1..sn) of rational functions, always kept reduced:
//! numerator and denominator coprime, denominator with coprime integer
//! coefficients and a positive leading coefficient, so equal functions are
//! equal as data. Used as the coefficient field K of the principal-variable
//! Smith mode, K\[λ\]. Owns only the fraction arithmetic; gcds come from
//! [`super::gcd`].

use super::gcd::gcd_cofactors;
use super::mpoly::MPoly;
use super::print::Node;
use super::rational::Q;
use super::ring::{Field, Ring};
use num_traits::One;

/// A reduced fraction `num / den` of polynomials.
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub struct RatFunc {
    num: MPoly,
    den: MPoly,
}

impl RatFunc {
    /// `num / den`, reduced; `None` if `den` is zero.
    pub fn new(num: MPoly, den: MPoly) -> Option<Self> {
        if den.is_zero() {
            return None;
        }
        if num.is_zero() {
            let n = num.nvars();
            return Some(RatFunc {
                num,
                den: MPoly::one(n),
            });
        }
        let (num, den) = if let Some(c) = den.as_constant() {
            (num.scale(&c.recip()), MPoly::one(den.nvars()))
        } else {
            let (g, n, d) = gcd_cofactors(&num, &den);
            let (n, d) = if g.is_nonzero_constant() {
                (num, den)
            } else {
                (n, d)
            };
            let dn = d.primitive_normal();
            // d = u * dn  with u the leading coefficient ratio.
            let u: Q = d.leading().expect("nonzero").1.clone() / &dn.leading().expect("nonzero").1;
            (n.scale(&u.recip()), dn)
        };
        Some(RatFunc { num, den })
    }

    /// The polynomial `p` as a fraction.
    pub fn from_poly(p: MPoly) -> Self {
        let n = p.nvars();
        RatFunc {
            num: p,
            den: MPoly::one(n),
        }
    }

    /// Numerator.
    pub fn num(&self) -> &MPoly {
        &self.num
    }

    /// Denominator (normalised).
    pub fn den(&self) -> &MPoly {
        &self.den
    }

    /// Whether the denominator is one.
    pub fn is_polynomial(&self) -> bool {
        self.den.as_constant().is_some_and(|c| c.is_one())
    }
}

/// The field Q(names...).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RatFuncField {
    /// Variable names (the ambient polynomial ring's; some may never occur).
    pub names: Vec<String>,
    /// Names shown in [`Ring::name`] (the variables the field is over).
    pub shown: Vec<String>,
}

impl RatFuncField {
    fn n(&self) -> usize {
        self.names.len()
    }
    /// Formats `p` with the field's names.
    pub fn format_poly(&self, p: &MPoly) -> String {
        p.to_string_with(&self.names)
    }
}

impl Ring for RatFuncField {
    type Elem = RatFunc;
    fn zero(&self) -> RatFunc {
        RatFunc::from_poly(MPoly::zero(self.n()))
    }
    fn one(&self) -> RatFunc {
        RatFunc::from_poly(MPoly::one(self.n()))
    }
    fn add(&self, a: &RatFunc, b: &RatFunc) -> RatFunc {
        if a.den == b.den {
            return RatFunc::new(&a.num + &b.num, a.den.clone()).expect("nonzero den");
        }
        RatFunc::new(&a.num * &b.den + &b.num * &a.den, &a.den * &b.den).expect("nonzero den")
    }
    fn sub(&self, a: &RatFunc, b: &RatFunc) -> RatFunc {
        self.add(a, &self.neg(b))
    }
    fn mul(&self, a: &RatFunc, b: &RatFunc) -> RatFunc {
        if a.is_polynomial() && b.is_polynomial() {
            return RatFunc::from_poly(&a.num * &b.num);
        }
        RatFunc::new(&a.num * &b.num, &a.den * &b.den).expect("nonzero den")
    }
    fn neg(&self, a: &RatFunc) -> RatFunc {
        RatFunc {
            num: -&a.num,
            den: a.den.clone(),
        }
    }
    fn is_zero(&self, a: &RatFunc) -> bool {
        a.num.is_zero()
    }
    fn is_unit(&self, a: &RatFunc) -> bool {
        !a.num.is_zero()
    }
    /// `num` or `num/den`, a leading minus of the numerator in front of
    /// the whole fraction: `-(k1 + 1)/k1`.
    fn node(&self, a: &RatFunc) -> Node {
        let num = a.num.to_node(&self.names);
        if a.is_polynomial() {
            return num;
        }
        let (neg, n) = num.split_sign();
        let q = Node::Div(Box::new(n), Box::new(a.den.to_node(&self.names)));
        if neg { Node::Terms(vec![(true, q)]) } else { q }
    }
    fn is_negative(&self, a: &RatFunc) -> bool {
        a.num
            .leading()
            .is_some_and(|(_, c)| c < &num_traits::Zero::zero())
    }
    fn name(&self) -> String {
        format!("Q({})", self.shown.join(", "))
    }
}

impl Field for RatFuncField {
    fn inv(&self, a: &RatFunc) -> Option<RatFunc> {
        RatFunc::new(a.den.clone(), a.num.clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::rational::qi;

    fn field() -> RatFuncField {
        RatFuncField {
            names: vec!["a".into(), "b".into()],
            shown: vec!["a".into(), "b".into()],
        }
    }

    #[test]
    fn fractions_are_reduced_and_canonical() {
        let (a, b) = (MPoly::var(0, 2), MPoly::var(1, 2));
        let f = RatFunc::new(&a * &a - &b * &b, (&a + &b).scale(&qi(-2))).unwrap();
        let g = RatFunc::new((&b - &a).scale(&qi(1)), MPoly::constant(qi(2), 2)).unwrap();
        assert_eq!(f, g);
        assert!(f.is_polynomial());
    }

    #[test]
    fn field_operations_invert() {
        let k = field();
        let (a, b) = (MPoly::var(0, 2), MPoly::var(1, 2));
        let f = RatFunc::new(a.clone(), &b + &MPoly::one(2)).unwrap();
        let fi = k.inv(&f).unwrap();
        assert_eq!(k.mul(&f, &fi), k.one());
        let s = k.add(&f, &k.neg(&f));
        assert!(k.is_zero(&s));
        assert_eq!(k.format(&f), "a/(b + 1)");
        assert!(k.inv(&k.zero()).is_none());
    }
}
