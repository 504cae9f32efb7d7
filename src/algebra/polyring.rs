//! The ring object Q[s1..sn]: multivariate polynomials ([`MPoly`]) with the
//! user's symbol names, implementing [`GcdDomain`]. It only adapts
//! [`super::mpoly`] and [`super::gcd`] to the ring traits.

use super::gcd::gcd;
use super::mpoly::MPoly;
use super::print::Node;
use super::ring::{GcdDomain, Ring};

/// Q[names...] with a fixed variable order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PolyRing {
    /// Variable names, most significant first.
    pub names: Vec<String>,
}

impl PolyRing {
    /// The ring `Q[names]`.
    pub fn new(names: Vec<String>) -> Self {
        PolyRing { names }
    }
    /// Number of variables.
    pub fn nvars(&self) -> usize {
        self.names.len()
    }
}

impl Ring for PolyRing {
    type Elem = MPoly;
    fn zero(&self) -> MPoly {
        MPoly::zero(self.nvars())
    }
    fn one(&self) -> MPoly {
        MPoly::one(self.nvars())
    }
    fn add(&self, a: &MPoly, b: &MPoly) -> MPoly {
        a + b
    }
    fn sub(&self, a: &MPoly, b: &MPoly) -> MPoly {
        a - b
    }
    fn signed_dot<'a>(
        &self,
        terms: &mut dyn Iterator<Item = (&'a MPoly, &'a MPoly, bool)>,
    ) -> MPoly
    where
        MPoly: 'a,
    {
        let terms: Vec<_> = terms.collect();
        crate::algebra::mpoly::sum_of_products(self.nvars(), &terms)
    }
    fn mul(&self, a: &MPoly, b: &MPoly) -> MPoly {
        a * b
    }
    fn neg(&self, a: &MPoly) -> MPoly {
        -a
    }
    fn is_zero(&self, a: &MPoly) -> bool {
        a.is_zero()
    }
    fn is_unit(&self, a: &MPoly) -> bool {
        a.is_nonzero_constant()
    }
    fn node(&self, a: &MPoly) -> Node {
        a.to_node(&self.names)
    }
    fn is_negative(&self, a: &MPoly) -> bool {
        a.leading()
            .is_some_and(|(_, c)| c < &num_traits::Zero::zero())
    }
    fn name(&self) -> String {
        format!("Q[{}]", self.names.join(", "))
    }
}

impl GcdDomain for PolyRing {
    fn bulk(&self, a: &MPoly) -> usize {
        a.terms().len()
    }
    fn div_exact(&self, a: &MPoly, b: &MPoly) -> Option<MPoly> {
        a.div_exact(b)
    }
    fn gcd(&self, a: &MPoly, b: &MPoly) -> MPoly {
        gcd(a, b)
    }
    fn normalize(&self, a: &MPoly) -> MPoly {
        a.primitive_normal()
    }
}
