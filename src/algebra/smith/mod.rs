//! Smith normal form, in three honest modes:
//!
//! 1. one symbol: over Q\[λ\] with unimodular U, V and monic D (for inputs
//!    whose transforms would be enormous, D alone, certified from
//!    `A·B = c·I`, see [`certify::certify_last_factor`]);
//! 2. a principal symbol among several: over K\[λ\], K = Q(others), plus a
//!    denominator-free form over Q\[all\];
//! 3. several symbols, no principal one: invariant factors over Q\[all\] from
//!    determinantal divisors, with no transforms claimed.
//!
//! [`elimination`] computes, [`mod@certify`] and [`divisors`] check
//! independently, [`modes`] chooses the mode and produces reports. Every
//! decomposition handed out of this module has been certified.

pub mod certify;
pub mod certify_several;
pub mod detadj;
pub mod divisors;
pub mod elimination;
pub mod fraction_free;
pub mod hermite_cert;
pub mod minors_cert;
pub mod modes;
pub mod monomial;
pub mod nonsingular;
pub mod principal_form;
pub mod rank_cert;
pub mod several;
pub mod small;
pub mod trailing;
pub mod trailing_cert;
pub mod trailing_mod;
pub mod two_by_two;

use crate::algebra::matrix::Matrix;
use crate::algebra::ring::EuclideanDomain;
use certify::{Certificate, ProductCheck, Unimodular, certify, certify_with};
#[cfg(feature = "internals")]
use elimination::NoTransforms;
use elimination::{Recorder, eliminate};

/// A Smith decomposition `U·A·V = D` with the inverses of U and V.
#[derive(Clone, Debug)]
pub struct SmithDecomposition<R: EuclideanDomain> {
    /// The diagonal form.
    pub d: Matrix<R>,
    /// Row transform.
    pub u: Matrix<R>,
    /// Column transform.
    pub v: Matrix<R>,
    /// `U⁻¹` (polynomial: the unimodularity certificate).
    pub u_inv: Matrix<R>,
    /// `V⁻¹`.
    pub v_inv: Matrix<R>,
}

impl<R: EuclideanDomain> SmithDecomposition<R> {
    /// Computes the decomposition of `a` (not yet certified).
    ///
    /// ```
    /// use lambdamat::algebra::{matrix::Matrix, rational::{Rationals, qi}, upoly::{UPoly, UPolyRing}};
    /// use lambdamat::algebra::smith::SmithDecomposition;
    /// let r = UPolyRing::new(Rationals, "x");
    /// let x = UPoly(vec![qi(0), qi(1)]);
    /// let a = Matrix::new(r.clone(), 2, 2, vec![x.clone(), UPoly(vec![]), UPoly(vec![]), x]);
    /// let s = SmithDecomposition::new(&a);
    /// assert!(s.certify(&a).verified());
    /// ```
    pub fn new(a: &Matrix<R>) -> Self {
        let mut rec = Recorder::new(&a.ring, a.rows(), a.cols());
        let d = eliminate(a, &mut rec);
        SmithDecomposition {
            d,
            u: rec.u,
            v: rec.v,
            u_inv: rec.u_inv,
            v_inv: rec.v_inv,
        }
    }

    /// Checks this decomposition against `a` from scratch.
    pub fn certify(&self, a: &Matrix<R>) -> Certificate {
        certify(
            a,
            &self.u,
            &self.d,
            &self.v,
            Unimodular::Inverse(&self.u_inv),
            Unimodular::Inverse(&self.v_inv),
        )
    }

    /// Like [`Self::certify`], evaluating the identities with `check`.
    pub fn certify_with(&self, a: &Matrix<R>, check: &dyn ProductCheck<R>) -> Certificate {
        certify_with(
            a,
            &self.u,
            &self.d,
            &self.v,
            Unimodular::Inverse(&self.u_inv),
            Unimodular::Inverse(&self.v_inv),
            check,
        )
    }

    /// The nonzero diagonal entries (the invariant factors).
    pub fn invariant_factors(&self) -> Vec<R::Elem> {
        let r = &self.d.ring;
        self.d
            .diagonal()
            .into_iter()
            .filter(|e| !r.is_zero(e))
            .collect()
    }
}

/// The Smith form D alone (no transforms are built).
#[cfg(feature = "internals")]
pub fn smith_form<R: EuclideanDomain>(a: &Matrix<R>) -> Matrix<R> {
    eliminate(a, &mut NoTransforms)
}
