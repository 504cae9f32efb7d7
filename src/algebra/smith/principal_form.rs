//! The principal mode's report without transforms for a non-square input
//! (issue 15): when the fraction-free elimination gives up on the size of
//! its entries ([`super::fraction_free::SIZE_LIMIT_BITS`]), the invariant
//! factors over Q(others)\[λ\] are still certified from its maximal minors
//! ([`super::certify_several::certify_maximal_minors`]): D = diag(1, …, 1,
//! d) padded with zeros, rank min(m, n), d the gcd of the minors. This
//! module only assembles the report; it must not compute or certify (the
//! square inputs take `modes`' det/adjugate route instead).

use super::certify_several::certify_maximal_minors;
use super::modes::{SmithOptions, SmithReport, principal_d_only_report};
use crate::algebra::matrix::Matrix;
use crate::algebra::polyring::PolyRing;
use crate::algebra::ratfunc::{RatFunc, RatFuncField};
use crate::algebra::ring::{GcdDomain, Ring};
use crate::algebra::upoly::UPolyRing;

/// The report of a non-square `a` of full rank over Q(others)\[λ\] (λ =
/// symbol `p`, `ap` = A over that ring) from its maximal minors,
/// transforms omitted because of `why`; `None` when the invariant factors
/// are not established that way.
pub fn maximal_minors_report(
    name: &str,
    a: &Matrix<PolyRing>,
    ap: &Matrix<UPolyRing<RatFuncField>>,
    p: usize,
    note: &str,
    why: &str,
    opts: &SmithOptions,
) -> Option<SmithReport> {
    let (m, n) = (a.rows(), a.cols());
    if m == n {
        return None;
    }
    let r = m.min(n);
    opts.progress.phase(&format!(
        "invariant factors from the {r}×{r} minors over Q(others)[{}]",
        a.ring.names[p]
    ));
    let (cert, last) = certify_maximal_minors(a, p)?;
    if !cert.verified() {
        return None;
    }
    let kr = &ap.ring;
    let mut d = Matrix::zeros(kr.clone(), m, n);
    for i in 0..r - 1 {
        d.set(i, i, kr.one());
    }
    let f = kr.normalize(
        &kr.trim(
            last.coeffs_in(p)
                .into_iter()
                .map(RatFunc::from_poly)
                .collect(),
        ),
    );
    d.set(r - 1, r - 1, f);
    let algorithm = if last.is_nonzero_constant() {
        format!(
            "{r}×{r} minors over Q[all] by expansion; their gcd over Q(others)[λ] is 1 (images at a point mod p), so every invariant factor is 1"
        )
    } else {
        format!(
            "{r}×{r} minors over Q[all] by expansion; d_{r} = their gcd over Q(others)[λ] (the gcd over Q[all]; the quotients' gcd 1 from images at a point mod p), d_{} = 1 from smaller minors the same way; invariant factors 1, …, 1, d_{r}",
            r - 1
        )
    };
    let mode_note = format!(
        "{note}; transforms omitted because {why}: the invariant factors alone are certified"
    );
    Some(principal_d_only_report(
        name,
        a,
        d,
        r,
        mode_note,
        algorithm,
        cert.checks,
        opts,
    ))
}
