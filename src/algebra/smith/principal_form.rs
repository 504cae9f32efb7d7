//! The principal mode's reports without transforms, for inputs on which
//! the fraction-free elimination gives up on the size of its entries
//! ([`super::fraction_free::SIZE_LIMIT_BITS`]) and no det/adjugate
//! certificate applies: from the maximal minors of a non-square input
//! ([`super::certify_several::certify_maximal_minors`]: D = diag(1, …, 1,
//! d) padded with zeros, rank min(m, n), d the gcd of the minors), or, for
//! any shape and rank, from the determinantal divisors over Q\[all\]
//! ([`super::divisors`]), whose primitive parts in λ are those over
//! Q(others)\[λ\]. This module only assembles the reports; the minors,
//! gcds and checks belong to the modules it calls.

use super::certify::Check;
use super::certify_several::certify_maximal_minors;
use super::divisors::{certified_divisors, minor_count};
use super::modes::{SmithOptions, SmithReport, principal_d_only_report};
use crate::algebra::gcd::content_in;
use crate::algebra::matrix::Matrix;
use crate::algebra::mpoly::MPoly;
use crate::algebra::polyring::PolyRing;
use crate::algebra::ratfunc::{RatFunc, RatFuncField};
use crate::algebra::ring::{GcdDomain, Ring};
use crate::algebra::upoly::UPolyRing;

/// At most this many minors (of all orders) for
/// [`FormOnly::determinantal_divisors`]: a 4×5 has 125, a 6×6 923, a 7×7
/// 3 431 (the determinantal mode's own route switch is at 20 000).
pub const DIVISOR_ROUTE_MINORS: u128 = 5_000;

/// What a report without transforms is for: the matrix `a` (named
/// `name`) over Q\[all\], the same matrix `ap` over Q(others)\[λ\] with λ
/// the symbol `p`, the mode's `note`, and `why` the transforms are omitted.
pub struct FormOnly<'a> {
    /// The matrix's name in the report.
    pub name: &'a str,
    /// A over Q\[all\].
    pub a: &'a Matrix<PolyRing>,
    /// A over Q(others)\[λ\].
    pub ap: &'a Matrix<UPolyRing<RatFuncField>>,
    /// The index of λ among the ring's symbols.
    pub p: usize,
    /// The principal mode's note.
    pub note: &'a str,
    /// Why the transforms are omitted.
    pub why: &'a str,
    /// The driver's options (progress, LaTeX).
    pub opts: &'a SmithOptions,
}

impl FormOnly<'_> {
    /// The report of a non-square `a` of full rank from its maximal
    /// minors; `None` when the invariant factors are not established that
    /// way.
    pub fn maximal_minors(&self) -> Option<SmithReport> {
        let (a, ap, p) = (self.a, self.ap, self.p);
        let (m, n) = (a.rows(), a.cols());
        if m == n {
            return None;
        }
        let r = m.min(n);
        self.opts.progress.phase(&format!(
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
        Some(self.report(d, r, algorithm, cert.checks))
    }

    /// The report of any `a` from its determinantal divisors over Q\[all\]:
    /// d_k = gcd of the k×k minors (certified to divide every one of them, and
    /// every minor of order rank + 1 to vanish), and over K\[λ\] the k-th
    /// divisor is the primitive part of d_k in λ (a content in Q\[others\] is a
    /// unit of K; by Gauss's lemma the gcd of the minors over K\[λ\] is the
    /// primitive part of their gcd over Q\[all\]); `None` above [`DIVISOR_ROUTE_MINORS`] minors or when the
    /// certificate fails.
    pub fn determinantal_divisors(&self) -> Option<SmithReport> {
        let (a, ap, p) = (self.a, self.ap, self.p);
        let (m, n) = (a.rows(), a.cols());
        if minor_count(m, n) > DIVISOR_ROUTE_MINORS {
            return None;
        }
        self.opts.progress.phase(&format!(
            "determinantal divisors over Q[all] ({} minors), their primitive parts in {}",
            minor_count(m, n),
            a.ring.names[p]
        ));
        let (dv, cert) = certified_divisors(a, DIVISOR_ROUTE_MINORS).ok()?;
        if !cert.verified() {
            return None;
        }
        let primitive = |d: &MPoly| -> Option<MPoly> { d.div_exact(&content_in(d, p)) };
        let kr = &ap.ring;
        let to_k = |e: &MPoly| {
            kr.normalize(&kr.trim(e.coeffs_in(p).into_iter().map(RatFunc::from_poly).collect()))
        };
        let r = dv.determinantal.len();
        let mut d = Matrix::zeros(kr.clone(), m, n);
        let mut prev = MPoly::one(a.ring.nvars());
        let mut chain = true;
        for (k, dk) in dv.determinantal.iter().enumerate() {
            let pk = primitive(dk)?;
            let f = pk.div_exact(&prev);
            chain &= f.is_some();
            d.set(k, k, to_k(&f?));
            prev = pk;
        }
        let mut checks = cert.checks;
        checks.push(Check {
            property: "f_k = pp(d_k)/pp(d_(k-1)) over Q(others)[λ]".into(),
            ok: chain,
            detail: "the primitive part in λ of each divisor divides the next's (exact division over Q[all])".into(),
        });
        if !chain {
            return None;
        }
        let algorithm = format!(
            "determinantal divisors over Q[all] (d_k = gcd of the k×k minors by Laplace expansion, modular gcd), their primitive parts in {} are those over Q(others)[{}]; f_k = d_k/d_(k-1)",
            a.ring.names[p], a.ring.names[p]
        );
        Some(self.report(d, r, algorithm, checks))
    }

    /// The report of the invariant factors on the diagonal of `d` (rank
    /// `r`), found by `algorithm` and certified by `checks`.
    fn report(
        &self,
        d: Matrix<UPolyRing<RatFuncField>>,
        r: usize,
        algorithm: String,
        checks: Vec<Check>,
    ) -> SmithReport {
        let mode_note = format!(
            "{}; transforms omitted because {}: the invariant factors alone are certified",
            self.note, self.why
        );
        principal_d_only_report(
            self.name, self.a, d, r, mode_note, algorithm, checks, self.opts,
        )
    }
}
