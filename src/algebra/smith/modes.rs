//! Chooses the honest Smith mode for a λ-matrix over Q[s1..sn], runs it,
//! certifies it and turns the result into a [`SmithReport`] of printable
//! strings: every formula in the language's syntax (which is also the text
//! form, and parses back with [`crate::lang::formula`]) and, on request,
//! LaTeX. Also checks user-supplied
//! decompositions ([`check_decomposition`]). Owns the conversions between
//! Q\[all\], Q\[λ\] and Q(others)\[λ\]; it must not print or know about files.

use super::SmithDecomposition;
use super::certify::{Certificate, Check, ProductCheck, Unimodular, certify};
use super::divisors::certified_divisors_within;
use super::nonsingular::{FastParts, FastPath};
use crate::algebra::gcd::{content_in, gcd, lcm};
use crate::algebra::matrix::Matrix;
use crate::algebra::mpoly::MPoly;
use crate::algebra::polyring::PolyRing;
use crate::algebra::qx::{QPoly, QxRing};
use crate::algebra::ratfunc::{RatFunc, RatFuncField};
use crate::algebra::rational::Rationals;
use crate::algebra::ring::{GcdDomain, Ring};
use crate::algebra::upoly::{UPoly, UPolyRing};
use serde::Serialize;

/// Rows of printed entries.
pub type Rows = Vec<Vec<String>>;

/// Which of the three honest modes produced a report.
#[derive(Clone, Copy, Debug, Serialize, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum Mode {
    /// One symbol: Q\[λ\] is a PID; unimodular U, V.
    OneSymbol,
    /// Principal symbol λ over K = Q(others).
    Principal,
    /// Invariant factors over Q\[all\] from determinantal divisors.
    DeterminantalDivisors,
}

/// LaTeX forms of a report's formulas.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct LatexForms {
    /// A.
    pub a: Rows,
    /// Invariant factors.
    pub invariant_factors: Vec<String>,
    /// D (if any).
    pub d: Option<Rows>,
    /// U (if any).
    pub u: Option<Rows>,
    /// V (if any).
    pub v: Option<Rows>,
}

/// The denominator-free form of a principal-mode decomposition:
/// `U′·A·V′ = C·D′` over Q\[all\], with U′, V′ polynomial, det U′ and det V′
/// nonzero elements of Q\[others\], D′ primitive and C diagonal over Q\[others\].
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct DenominatorFree {
    /// The ring the entries live in.
    pub ring: String,
    /// D′ (primitive invariant factors on the diagonal).
    #[serde(rename = "D")]
    pub d: Rows,
    /// U′.
    #[serde(rename = "U")]
    pub u: Rows,
    /// V′.
    #[serde(rename = "V")]
    pub v: Rows,
    /// The diagonal of C.
    #[serde(rename = "C")]
    pub c: Vec<String>,
    /// det U′.
    pub det_u: String,
    /// det V′.
    pub det_v: String,
    /// Whether every check passed.
    pub verified: bool,
    /// The checks.
    pub certificate: Vec<Check>,
}

/// Everything `lambdamat smith` shows for one matrix.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct SmithReport {
    /// Name of the matrix in the source file.
    pub matrix: String,
    /// The ring of the decomposition, e.g. `Q[x]` or `Q(k1, k2, k3)[k4]`.
    pub ring: String,
    /// The mode.
    pub mode: Mode,
    /// What the mode means, in one or two sentences.
    pub mode_note: String,
    /// Which algorithm produced the decomposition.
    pub algorithm: String,
    /// The input matrix.
    #[serde(rename = "A")]
    pub a: Rows,
    /// The nonzero invariant factors.
    pub invariant_factors: Vec<String>,
    /// The rank.
    pub rank: usize,
    /// D (the determinantal mode gives diag(invariant factors) without U, V).
    #[serde(rename = "D")]
    pub d: Rows,
    /// U (None in the determinantal mode).
    #[serde(rename = "U")]
    pub u: Option<Rows>,
    /// V (None in the determinantal mode).
    #[serde(rename = "V")]
    pub v: Option<Rows>,
    /// Whether every check of the certificate passed.
    pub verified: bool,
    /// The certificate.
    pub certificate: Vec<Check>,
    /// Principal mode only: each invariant factor as its coefficients in the
    /// principal symbol, constant term first, each a rational function of
    /// the other symbols in the language's syntax.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub invariant_factor_coefficients: Option<Vec<Vec<String>>>,
    /// The denominator-free form (principal mode only).
    pub denominator_free: Option<DenominatorFree>,
    /// LaTeX forms, when asked for.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub latex: Option<LatexForms>,
}

/// Errors of the Smith driver.
#[derive(Debug, thiserror::Error)]
pub enum SmithError {
    /// The determinantal mode would be too expensive.
    #[error(transparent)]
    TooManyMinors(#[from] super::divisors::TooManyMinors),
    /// The input is beyond every exact route of its mode; the message names
    /// the sizes each route would need.
    #[error("{0}")]
    TooLarge(String),
    /// A certificate failed: an internal error, never shown as a result.
    #[error(
        "internal error: the computed decomposition failed its certificate ({0}); please report this input"
    )]
    CertificateFailed(String),
}

/// Limit on the number of minors in the determinantal mode.
pub const MINOR_LIMIT: u128 = 200_000;

/// A callback told the name of each phase as it starts (the CLI shows it
/// on a terminal); the algebra never prints.
#[derive(Clone, Default)]
pub struct PhaseHook(pub Option<PhaseFn>);

/// The callback of a [`PhaseHook`].
pub type PhaseFn = std::sync::Arc<dyn Fn(&str) + Send + Sync>;

impl PhaseHook {
    /// Announces a phase.
    pub fn phase(&self, name: &str) {
        if let Some(f) = &self.0 {
            f(name);
        }
    }
}

impl std::fmt::Debug for PhaseHook {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(if self.0.is_some() {
            "PhaseHook(set)"
        } else {
            "PhaseHook(none)"
        })
    }
}

/// Options of the driver.
#[derive(Clone, Debug, Default)]
pub struct SmithOptions {
    /// Index of the principal symbol, if any.
    pub principal: Option<usize>,
    /// Also produce LaTeX forms.
    pub latex: bool,
    /// Phase announcements (progress display).
    pub progress: PhaseHook,
}

/// Computes, certifies and reports the Smith form of `a` (named `name`).
pub fn smith_report(
    name: &str,
    a: &Matrix<PolyRing>,
    opts: &SmithOptions,
) -> Result<SmithReport, SmithError> {
    let names = &a.ring.names;
    match (names.len(), opts.principal) {
        (0 | 1, _) => one_symbol(name, a, opts),
        (_, Some(p)) => principal(name, a, p, opts),
        (_, None) => divisors_mode(name, a, opts),
    }
}

fn rows_of<R: Ring>(m: &Matrix<R>, latex: bool) -> Rows {
    if latex { m.latex_rows() } else { m.lmx_rows() }
}

fn fail_if_unverified(c: &Certificate) -> Result<(), SmithError> {
    if c.verified() {
        Ok(())
    } else {
        let f: Vec<String> = c
            .failures()
            .map(|f| format!("{}: {}", f.property, f.detail))
            .collect();
        Err(SmithError::CertificateFailed(f.join("; ")))
    }
}

/// Q\[all\] with one (or no) variable → Q\[x\].
pub fn to_univariate(a: &Matrix<PolyRing>) -> Matrix<QxRing> {
    let var = a.ring.names.first().cloned().unwrap_or_else(|| "x".into());
    let ring = QxRing::new(var);
    let r2 = UPolyRing::new(Rationals, "x");
    a.map(ring, |p| {
        if p.nvars() <= 1 {
            return univariate_terms(p);
        }
        let cs = if p.nvars() == 0 {
            vec![p.as_constant().expect("no variables")]
        } else {
            p.coeffs_in(0)
                .into_iter()
                .map(|c| c.as_constant().expect("univariate"))
                .collect()
        };
        QPoly::from_upoly(&r2.trim(cs))
    })
}

/// A polynomial in at most one variable as a [`QPoly`], read from its
/// terms directly (distinct monomials, nonzero coefficients: MPoly's
/// canonical form): integer coefficients go straight to the numerators,
/// and only a polynomial with a fractional coefficient takes the common
/// denominator. The same value as the generic conversion through
/// `coeffs_in`.
fn univariate_terms(p: &MPoly) -> QPoly {
    let terms = p.terms();
    let len = terms
        .iter()
        .map(|(m, _)| m.first().copied().unwrap_or(0) as usize + 1)
        .max()
        .unwrap_or(0);
    let exp = |m: &[u32]| m.first().copied().unwrap_or(0) as usize;
    if terms.iter().all(|(_, c)| c.is_integer()) {
        let mut cs = vec![num_bigint::BigInt::from(0); len];
        for (m, c) in terms {
            cs[exp(m)] = c.numer().clone();
        }
        return QPoly::from_ints(cs);
    }
    let mut cs = vec![crate::algebra::rational::Q::from_integer(0.into()); len];
    for (m, c) in terms {
        cs[exp(m)] = c.clone();
    }
    QPoly::from_upoly(&UPoly(cs))
}

/// Decomposes over Q\[x\]: the nonsingular fast path when it applies, the
/// general elimination otherwise. Returns the algorithm's name too.
pub fn decompose_qx(a: &Matrix<QxRing>) -> (SmithDecomposition<QxRing>, &'static str) {
    match super::nonsingular::try_nonsingular(a) {
        Some(d) => (d, NONSINGULAR_ALGORITHM),
        None => (SmithDecomposition::new(a), ELIMINATION_ALGORITHM),
    }
}

const NONSINGULAR_ALGORITHM: &str = "nonsingular path: det and adj by images mod word primes and CRT, Hermite structure W·A = [[I, h], [0, f]] (U = I/det, V = adj when det is constant)";
const TRAILING_ALGORITHM: &str = "det and adj by images mod word primes (CRT above a proved bound); Hermite basis W·A = [[I, h], [0, T]] glued by CRT from the rank-one part (h = −adj_ij/adj_nj mod det) and an HNF modulo the repeated part of det; Smith form of the small trailing block T by elimination";
const ELIMINATION_ALGORITHM: &str =
    "elimination: least-degree pivot, division with remainder, content removal";

/// Above this estimated size of U (bits of coefficients; the estimate is
/// pessimistic, e.g. a 24×24 of degree 1 at 1e8 prints about 19 MB; a 4×4
/// of degree 200 at 2.2e8 took over 60 s to build its transforms) the
/// one-symbol mode certifies the invariant factors without transforms.
pub const TRANSFORM_LIMIT_BITS: u64 = 200_000_000;

/// Diagonal inputs from this size on get the invariant factors without
/// transforms (when the entries' products are coprime).
pub const DIAGONAL_FORM_ONLY: usize = 32;

/// From this size on, a nonsingular one-symbol input whose (n−1)-th
/// determinantal divisor is not 1 gets its invariant factors without
/// transforms when [`super::hermite_cert::certify_factors`] establishes
/// them (the general elimination with transforms grows fast: 8×8 of
/// B·diag(1, …, x − 1, (x − 1)(x + 2))·C in 0.5 s, 12×12 in 13.6 s).
pub const TWO_FACTOR_MIN: usize = 10;

/// Above this degree bound of det A (least of the sums of row and column
/// degrees), an input with several non-trivial invariant factors gets D
/// alone: the Hermite-basis transforms took 10.7 s on B·diag(…)·C 16×16 of
/// degree 7 (bound 112), 6.1 s at 20×20 of degree 5 (bound 100).
pub const NO_HERMITE_TRANSFORM_DEGREE: usize = 100;

/// The diagonal 1, …, 1, f.
fn last_only(a: &Matrix<QxRing>, f: QPoly) -> Vec<QPoly> {
    let mut v = vec![a.ring.one(); a.rows().saturating_sub(1)];
    v.push(f);
    v
}

/// The form-only report with two or more non-trivial invariant factors,
/// when [`super::hermite_cert::certify_factors`] establishes them.
#[allow(clippy::too_many_arguments)]
fn two_factor_report(
    name: &str,
    a_poly: &Matrix<PolyRing>,
    au: &Matrix<QxRing>,
    c: &QPoly,
    b: &Matrix<QxRing>,
    ring: &str,
    note: String,
    opts: &SmithOptions,
) -> Option<SmithReport> {
    opts.progress.phase(
        "certifying the invariant factors (A·B = c·I, gcd of B, deg det A, Hermite basis modulo the repeated part)",
    );
    let (cert, factors) = super::hermite_cert::certify_factors(au, c, b);
    if !cert.verified() || factors.len() != au.rows() {
        return None;
    }
    Some(form_only_report(
        name,
        a_poly,
        au,
        factors,
        cert,
        ring.to_string(),
        super::hermite_cert::ALGORITHM,
        note,
        opts,
    ))
}

/// The invariant factors 1, …, 1, f certified from `A·B = c·I`
/// (`certify_last_factor`), reported without transforms; `None` when the
/// certificate does not hold (the caller takes another route).
#[allow(clippy::too_many_arguments)]
fn last_factor_report(
    name: &str,
    a_poly: &Matrix<PolyRing>,
    a: &Matrix<QxRing>,
    (c, b): (&QPoly, &Matrix<QxRing>),
    ring: &str,
    algorithm: &str,
    note: String,
    opts: &SmithOptions,
) -> Option<SmithReport> {
    opts.progress
        .phase("certifying the invariant factors (A·B = c·I)");
    let (cert, f) = super::certify::certify_last_factor(a, c, b);
    cert.verified().then(|| {
        form_only_report(
            name,
            a_poly,
            a,
            last_only(a, f),
            cert,
            ring.to_string(),
            algorithm,
            note,
            opts,
        )
    })
}

/// A one-symbol report with D alone (`factors` its diagonal), certified by
/// [`super::certify::certify_last_factor`] or
/// [`super::hermite_cert::certify_factors`].
#[allow(clippy::too_many_arguments)]
fn form_only_report(
    name: &str,
    a_poly: &Matrix<PolyRing>,
    a: &Matrix<QxRing>,
    factors: Vec<QPoly>,
    cert: Certificate,
    ring: String,
    algorithm: &str,
    note: String,
    opts: &SmithOptions,
) -> SmithReport {
    let r = &a.ring;
    // Diagonal entries not given are 1 (the square routes give all n).
    let mut d = Matrix::zeros(r.clone(), a.rows(), a.cols());
    let mut factors = factors.into_iter();
    for i in 0..a.rows().min(a.cols()) {
        d.set(i, i, factors.next().unwrap_or_else(|| r.one()));
    }
    let inv: Vec<QPoly> = d.diagonal().into_iter().filter(|e| !e.is_zero()).collect();
    let latex = opts.latex.then(|| LatexForms {
        a: rows_of(a_poly, true),
        invariant_factors: inv.iter().map(|e| r.latex(e)).collect(),
        d: Some(rows_of(&d, true)),
        u: None,
        v: None,
    });
    SmithReport {
        matrix: name.to_string(),
        ring,
        mode: Mode::OneSymbol,
        mode_note: note,
        algorithm: algorithm.to_string(),
        a: rows_of(a_poly, false),
        invariant_factors: inv.iter().map(|e| r.lmx(e)).collect(),
        rank: inv.len(),
        d: rows_of(&d, false),
        u: None,
        v: None,
        verified: true,
        certificate: cert.checks,
        invariant_factor_coefficients: None,
        denominator_free: None,
        latex,
    }
}

/// The report of a certified decomposition with transforms `[D, U, V]`.
#[allow(clippy::too_many_arguments)]
fn transforms_report<R: crate::algebra::ring::EuclideanDomain>(
    name: &str,
    a_poly: &Matrix<PolyRing>,
    [d, u, v]: [&Matrix<R>; 3],
    cert: Certificate,
    algorithm: &str,
    mode: Mode,
    ring_name: String,
    note: String,
    opts: &SmithOptions,
) -> SmithReport {
    let r = &d.ring;
    let inv: Vec<R::Elem> = d.diagonal().into_iter().filter(|e| !r.is_zero(e)).collect();
    let latex = opts.latex.then(|| LatexForms {
        a: rows_of(a_poly, true),
        invariant_factors: inv.iter().map(|e| r.latex(e)).collect(),
        d: Some(rows_of(d, true)),
        u: Some(rows_of(u, true)),
        v: Some(rows_of(v, true)),
    });
    SmithReport {
        matrix: name.to_string(),
        ring: ring_name,
        mode,
        mode_note: note,
        algorithm: algorithm.to_string(),
        a: rows_of(a_poly, false),
        invariant_factors: inv.iter().map(|e| r.lmx(e)).collect(),
        rank: inv.len(),
        d: rows_of(d, false),
        u: Some(rows_of(u, false)),
        v: Some(rows_of(v, false)),
        verified: true,
        certificate: cert.checks,
        invariant_factor_coefficients: None,
        denominator_free: None,
        latex,
    }
}

/// The nonsingular path's decomposition (U with primitive integer rows)
/// certified by [`super::small::certify_small`] (det U constant from
/// degrees, so no `U·U⁻¹` product); `None` when that certificate does not
/// apply (the caller certifies the usual way).
fn degree_certified_report(
    name: &str,
    a_poly: &Matrix<PolyRing>,
    au: &Matrix<QxRing>,
    dec: &SmithDecomposition<QxRing>,
    ring: &str,
    note: &str,
    opts: &SmithOptions,
) -> Option<SmithReport> {
    let small = super::small::SmallDecomposition::from_decomposition(dec);
    small_certified_report(name, a_poly, au, &small, ring, note, opts)
}

/// [`degree_certified_report`] for the integer route's parts (U with
/// primitive integer rows already, no `U⁻¹`).
fn small_certified_report(
    name: &str,
    a_poly: &Matrix<PolyRing>,
    au: &Matrix<QxRing>,
    small: &super::small::SmallDecomposition,
    ring: &str,
    note: &str,
    opts: &SmithOptions,
) -> Option<SmithReport> {
    opts.progress
        .phase("certifying U·A·V = D, V·V⁻¹ = I, det U constant from degrees");
    let p = super::small::certificate_prime()?;
    let cert = super::small::certify_small(au, small, p);
    verified_small_report(
        name,
        a_poly,
        small,
        cert,
        NONSINGULAR_ALGORITHM,
        ring,
        note,
        opts,
    )
}

/// The report of a one-symbol decomposition whose transforms were
/// certified without `U⁻¹` (the dense and the trailing routes); `None`
/// when the certificate failed (the caller then falls back).
#[allow(clippy::too_many_arguments)]
fn verified_small_report(
    name: &str,
    a_poly: &Matrix<PolyRing>,
    small: &super::small::SmallDecomposition,
    cert: Certificate,
    algorithm: &str,
    ring: &str,
    note: &str,
    opts: &SmithOptions,
) -> Option<SmithReport> {
    if !cert.verified() {
        return None;
    }
    opts.progress.phase("formatting the report");
    Some(transforms_report(
        name,
        a_poly,
        [&small.d, &small.u, &small.v],
        cert,
        algorithm,
        Mode::OneSymbol,
        ring.to_string(),
        note.to_string(),
        opts,
    ))
}

/// The trailing (Hermite-basis) route's transforms
/// ([`super::trailing::trailing_hermite`]) certified by
/// [`super::trailing_cert::certify_transforms`] (no `U⁻¹`); `None` when
/// the route declines or its certificate fails (the caller falls back to
/// the elimination, certified the usual way).
#[allow(clippy::too_many_arguments)]
fn trailing_report(
    name: &str,
    a_poly: &Matrix<PolyRing>,
    au: &Matrix<QxRing>,
    c: &QPoly,
    b: &Matrix<QxRing>,
    ring: &str,
    note: &str,
    opts: &SmithOptions,
) -> Option<SmithReport> {
    opts.progress
        .phase("Hermite basis from A·B = c·I: rank-one part and HNF modulo the repeated part, Smith of the trailing block");
    let dec = super::trailing::trailing_hermite(au, c, b)?;
    opts.progress
        .phase("certifying U·A·V = D, V·V⁻¹ = I, det U constant from degrees");
    let cert = super::trailing_cert::certify_transforms(au, &dec);
    verified_small_report(
        name,
        a_poly,
        &dec,
        cert,
        TRAILING_ALGORITHM,
        ring,
        note,
        opts,
    )
}

#[allow(clippy::too_many_arguments)]
fn generic_report<R: crate::algebra::ring::EuclideanDomain>(
    name: &str,
    a_poly: &Matrix<PolyRing>,
    a: &Matrix<R>,
    dec: SmithDecomposition<R>,
    algorithm: &str,
    mode: Mode,
    ring_name: String,
    note: String,
    opts: &SmithOptions,
    check: &dyn ProductCheck<R>,
) -> Result<(SmithReport, SmithDecomposition<R>), SmithError> {
    opts.progress
        .phase("certifying U·A·V = D, U·U⁻¹ = I, V·V⁻¹ = I");
    let cert = dec.certify_with(a, check);
    fail_if_unverified(&cert)?;
    opts.progress.phase("formatting the report");
    let report = transforms_report(
        name,
        a_poly,
        [&dec.d, &dec.u, &dec.v],
        cert,
        algorithm,
        mode,
        ring_name,
        note,
        opts,
    );
    Ok((report, dec))
}

fn one_symbol(
    name: &str,
    a: &Matrix<PolyRing>,
    opts: &SmithOptions,
) -> Result<SmithReport, SmithError> {
    let au = to_univariate(a);
    let (ring, note) = if a.ring.names.is_empty() {
        (
            "Q".to_string(),
            "constant matrix: Smith form over the field Q (U, V invertible)".to_string(),
        )
    } else {
        (
            au.ring.name(),
            format!(
                "{} is a principal ideal domain: U and V are unimodular (constant nonzero determinant), D is monic with f1 | f2 | …",
                au.ring.name()
            ),
        )
    };
    opts.progress
        .phase(&format!("Smith form over {}", au.ring.name()));
    if let Some(report) = monomial_report(name, a, &au, &ring, &note, opts)? {
        return Ok(report);
    }
    if let Some(report) = unit_factors_report(name, a, &au, &ring, &note, opts) {
        return Ok(report);
    }
    let diag = (au.rows() >= DIAGONAL_FORM_ONLY)
        .then(|| super::nonsingular::diagonal_adjugate(&au))
        .flatten();
    if let Some((c, b)) = diag
        && let Some(report) = last_factor_report(
            name,
            a,
            &au,
            (&c, &b),
            &ring,
            "diagonal input: c = product of the diagonal, B = diag(product of the others); invariant factors from A·B = c·I, the gcd of B's entries and deg c (no elimination)",
            format!(
                "{note}; transforms omitted for a {n}×{n} diagonal input (they would be dense with Bezout coefficients of huge height): the invariant factors alone are certified",
                n = au.rows()
            ),
            opts,
        )
    {
        return Ok(report);
    }
    if let Some((cert, f)) = super::minors_cert::certify_generic(&au) {
        let n = au.rows();
        let why = format!(
            "{note}; transforms omitted for a {n}×{n} input of positive degree (U would be dense, with coefficients of the size of det's): the invariant factors alone are certified"
        );
        let (alg, f) = (super::minors_cert::ALGORITHM, last_only(&au, f));
        return Ok(form_only_report(
            name, a, &au, f, cert, ring, alg, why, opts,
        ));
    }
    if let Some(bits) = super::two_by_two::bezout_height_bits(&au)
        && bits > super::two_by_two::MAX_BEZOUT_BITS
    {
        // A·adj(A) = det(A)·I: D alone, as for the other oversized inputs.
        let r = &au.ring;
        let (p, q, s, t) = (au.get(0, 0), au.get(0, 1), au.get(1, 0), au.get(1, 1));
        let c = r.sub(&r.mul(p, t), &r.mul(q, s));
        let b = Matrix::new(
            r.clone(),
            2,
            2,
            vec![t.clone(), r.neg(q), r.neg(s), p.clone()],
        );
        if !c.is_zero()
            && let Some(report) = last_factor_report(
                name,
                a,
                &au,
                (&c, &b),
                &ring,
                "2×2: c = det A, B = adj A; invariant factors from A·B = c·I, the gcd of B's entries and deg c",
                format!(
                    "{note}; transforms omitted: the Bezout coefficients of the first row would have about {:.1e} digits each (beyond {:.1e}, the reach of the modular routes); the invariant factors alone are certified",
                    bits * std::f64::consts::LOG10_2,
                    super::two_by_two::MAX_BEZOUT_BITS * std::f64::consts::LOG10_2
                ),
                opts,
            )
        {
            return Ok(report);
        }
    }
    if let Some(d) = super::two_by_two::bezout_2x2(&au) {
        let alg = super::two_by_two::ALGORITHM;
        let check = super::two_by_two::RightFirst;
        let mode = Mode::OneSymbol;
        return Ok(generic_report(name, a, &au, d, alg, mode, ring, note, opts, &check)?.0);
    }
    let fast = match super::nonsingular::try_fast_parts(&au, TRANSFORM_LIMIT_BITS) {
        Some(FastParts::Small(s)) => {
            if let Some(report) =
                small_certified_report(name, a, &au, &s.parts.dec, &ring, &note, opts)
            {
                return Ok(report);
            }
            s.into_fast_path(&au)
        }
        Some(FastParts::Path(p)) => Some(p),
        None => None,
    };
    let (dec, alg) = match fast {
        Some(FastPath::Decomposition(mut d)) => {
            super::trailing::integral_rows(&mut d);
            if let Some(report) = degree_certified_report(name, a, &au, &d, &ring, &note, opts) {
                return Ok(report);
            }
            (d, NONSINGULAR_ALGORITHM)
        }
        Some(FastPath::FormOnly { c, b, bits, primes }) => {
            let digits = bits as f64 * std::f64::consts::LOG10_2;
            let omitted = match primes {
                None => format!(
                    "transforms omitted: U would hold about {digits:.1e} digits of coefficients (limit {:.1e})",
                    TRANSFORM_LIMIT_BITS as f64 * std::f64::consts::LOG10_2
                ),
                Some(k) => format!(
                    "transforms omitted: U's rows would need about {k} word primes to reconstruct (the modular route has {}), and the exact route stalls at that height",
                    crate::algebra::modular::NPRIMES_LONG
                ),
            };
            // Without coprime entries in B that certificate fails anyway,
            // after an expensive product check.
            if super::hermite_cert::entries_coprime(&b)
                && let Some(report) = last_factor_report(
                    name,
                    a,
                    &au,
                    (&c, &b),
                    &ring,
                    "det and adj by images mod word primes (CRT above a proved bound); invariant factors from A·B = c·I, the gcd of B's entries and deg c",
                    format!("{note}; {omitted}; the invariant factors alone are certified"),
                    opts,
                )
            {
                return Ok(report);
            }
            let why = format!(
                "{note}; {omitted}, and the (n−1)-th determinantal divisor is not 1; the invariant factors alone are certified"
            );
            if let Some(report) = two_factor_report(name, a, &au, &c, &b, &ring, why, opts) {
                return Ok(report);
            }
            // The form-only certificate declined (e.g. a trailing block
            // beyond its size): the Hermite-basis route with (large)
            // transforms, far cheaper than the elimination.
            if let Some(report) = trailing_report(name, a, &au, &c, &b, &ring, &note, opts) {
                return Ok(report);
            }
            (SmithDecomposition::new(&au), ELIMINATION_ALGORITHM)
        }
        Some(FastPath::NoHermite { c, b }) => {
            let big = super::hermite_cert::degree_bound(&au) > NO_HERMITE_TRANSFORM_DEGREE;
            if big
                && let Some(report) = two_factor_report(
                    name,
                    a,
                    &au,
                    &c,
                    &b,
                    &ring,
                    format!(
                        "{note}; transforms omitted: several non-trivial invariant factors and a degree bound of det above {NO_HERMITE_TRANSFORM_DEGREE} (the Hermite-basis transforms take over 10 s there); the invariant factors alone are certified"
                    ),
                    opts,
                )
            {
                return Ok(report);
            }
            if let Some(report) = trailing_report(name, a, &au, &c, &b, &ring, &note, opts) {
                return Ok(report);
            }
            if au.rows() >= TWO_FACTOR_MIN
                && let Some(report) = two_factor_report(
                    name,
                    a,
                    &au,
                    &c,
                    &b,
                    &ring,
                    format!(
                        "{note}; transforms omitted: the (n−1)-th determinantal divisor is not 1, so the Hermite shortcut does not apply and the general elimination with transforms is slow at this size; the invariant factors alone are certified"
                    ),
                    opts,
                )
            {
                return Ok(report);
            }
            (SmithDecomposition::new(&au), ELIMINATION_ALGORITHM)
        }
        None => (SmithDecomposition::new(&au), ELIMINATION_ALGORITHM),
    };
    Ok(generic_report(
        name,
        a,
        &au,
        dec,
        alg,
        Mode::OneSymbol,
        ring,
        note,
        opts,
        &super::certify::ClearedQx,
    )?
    .0)
}

/// Size policy for inputs that are not square and nonsingular: from this
/// estimate of the elimination's work on, `min(m, n)·N` with N the least
/// of the sums of row and column degrees of A's largest square block
/// (a bound on the degree of the r-minors, hence of the transforms'
/// entries), the invariant factors come alone when
/// [`super::rank_cert::certify_unit_factors`] establishes them (rank r,
/// all nonzero factors 1: the generic case). Below it the general
/// elimination gives U and V (e.g. 8×11 of degree 1, work 64: 0.05 s;
/// 13×10 of degree 2, work 200: 2.2 s with transforms).
pub const NONSQUARE_FORM_ONLY_WORK: usize = 100;

/// The size estimate of [`NONSQUARE_FORM_ONLY_WORK`].
fn nonsquare_work(a: &Matrix<QxRing>) -> usize {
    let k = a.rows().min(a.cols());
    let deg = |e: &QPoly| e.degree().unwrap_or(0);
    let mut rd: Vec<usize> = (0..a.rows())
        .map(|i| (0..a.cols()).map(|j| deg(a.get(i, j))).max().unwrap_or(0))
        .collect();
    let mut cd: Vec<usize> = (0..a.cols())
        .map(|j| (0..a.rows()).map(|i| deg(a.get(i, j))).max().unwrap_or(0))
        .collect();
    rd.sort_unstable_by(|x, y| y.cmp(x));
    cd.sort_unstable_by(|x, y| y.cmp(x));
    let n: usize = rd
        .iter()
        .take(k)
        .sum::<usize>()
        .min(cd.iter().take(k).sum());
    k * n
}

/// Non-square or singular inputs beyond [`NONSQUARE_FORM_ONLY_WORK`]
/// whose nonzero invariant factors are all 1: D alone, certified by
/// [`super::rank_cert::certify_unit_factors`]. `None` otherwise (square
/// nonsingular inputs, small ones, or a nontrivial factor).
fn unit_factors_report(
    name: &str,
    a_poly: &Matrix<PolyRing>,
    a: &Matrix<QxRing>,
    ring: &str,
    note: &str,
    opts: &SmithOptions,
) -> Option<SmithReport> {
    if nonsquare_work(a) < NONSQUARE_FORM_ONLY_WORK {
        return None;
    }
    opts.progress
        .phase("certifying rank and unit invariant factors (r-minors, kernel)");
    let (cert, r) = super::rank_cert::certify_unit_factors(a)?;
    if !cert.verified() {
        return None;
    }
    let (m, n) = (a.rows(), a.cols());
    let why = format!(
        "{note}; transforms omitted for a {m}×{n} input of rank {r} (size estimate min(m, n)·N = {} ≥ {NONSQUARE_FORM_ONLY_WORK}: the elimination with transforms grows fast there): the invariant factors alone are certified",
        nonsquare_work(a)
    );
    let factors = vec![a.ring.one(); r];
    let mut padded = factors;
    padded.resize(m.min(n), a.ring.zero());
    Some(form_only_report(
        name,
        a_poly,
        a,
        padded,
        cert,
        ring.to_string(),
        super::rank_cert::ALGORITHM,
        why,
        opts,
    ))
}

const MONOMIAL_ALGORITHM: &str = "monomial-shaped input (at most one nonzero entry per row and column): A = Pᵀ·[[Δ, 0], [0, 0]]·Qᵀ for permutations P, Q and the diagonal Δ of its entries; Δ's Smith form by the diagonal routes, lifted by P and Q";

/// Monomial-shaped inputs that are not square diagonal (permuted, or
/// padded with zero rows or columns): Δ's Smith form, lifted by the
/// permutations ([`super::monomial`]). From [`DIAGONAL_FORM_ONLY`] nonzero
/// entries on, D alone when `A·B = c·I` for Δ certifies it (as for square
/// diagonal inputs: the transforms would be dense with Bezout coefficients
/// of huge height); otherwise Δ's decomposition, lifted and certified
/// against A. `None` when A is not monomial-shaped, is square diagonal, or
/// is zero (the other routes take those).
fn monomial_report(
    name: &str,
    a_poly: &Matrix<PolyRing>,
    au: &Matrix<QxRing>,
    ring: &str,
    note: &str,
    opts: &SmithOptions,
) -> Result<Option<SmithReport>, SmithError> {
    let Some(shape) = super::monomial::MonomialShape::of(au) else {
        return Ok(None);
    };
    if shape.places.is_empty() || shape.is_square_diagonal(au) {
        return Ok(None);
    }
    let delta = shape.delta(au);
    let r = delta.rows();
    // Re-read A against Δ and the places: every entry is Δ's at its place
    // and zero elsewhere.
    let mut at = std::collections::HashMap::with_capacity(r);
    for (k, &ij) in shape.places.iter().enumerate() {
        at.insert(ij, k);
    }
    let ok = (0..au.rows()).all(|i| {
        (0..au.cols()).all(|j| match at.get(&(i, j)) {
            Some(&k) => au.get(i, j) == delta.get(k, k) && !delta.get(k, k).is_zero(),
            None => au.get(i, j).is_zero(),
        })
    });
    let structure = Check {
        property: "A is a row and column permutation of [[Δ, 0], [0, 0]]".into(),
        ok,
        detail: format!(
            "{r} nonzero entries, at most one in every row and column of the {}×{} input (checked entry by entry); Δ = their diagonal",
            au.rows(),
            au.cols()
        ),
    };
    if r >= DIAGONAL_FORM_ONLY
        && let Some((c, b)) = super::nonsingular::diagonal_adjugate(&delta)
    {
        opts.progress
            .phase("certifying the invariant factors of Δ (Δ·B = c·I)");
        let (mut cert, f) = super::certify::certify_last_factor(&delta, &c, &b);
        if cert.verified() && ok {
            cert.checks.insert(0, structure);
            let qr = &au.ring;
            let (m, n) = (au.rows(), au.cols());
            let mut d = Matrix::zeros(qr.clone(), m, n);
            for k in 0..r - 1 {
                d.set(k, k, qr.one());
            }
            d.set(r - 1, r - 1, f);
            let inv: Vec<QPoly> = d.diagonal().into_iter().filter(|e| !e.is_zero()).collect();
            let latex = opts.latex.then(|| LatexForms {
                a: rows_of(a_poly, true),
                invariant_factors: inv.iter().map(|e| qr.latex(e)).collect(),
                d: Some(rows_of(&d, true)),
                u: None,
                v: None,
            });
            return Ok(Some(SmithReport {
                matrix: name.to_string(),
                ring: ring.to_string(),
                mode: Mode::OneSymbol,
                mode_note: format!(
                    "{note}; transforms omitted for a {m}×{n} input with {r} nonzero entries, at most one per row and column (they would be dense with Bezout coefficients of huge height): the invariant factors alone are certified"
                ),
                algorithm: format!(
                    "{MONOMIAL_ALGORITHM}; c = product of Δ's diagonal, B = diag(product of the others); invariant factors from Δ·B = c·I, the gcd of B's entries and deg c"
                ),
                a: rows_of(a_poly, false),
                invariant_factors: inv.iter().map(|e| qr.lmx(e)).collect(),
                rank: r,
                d: rows_of(&d, false),
                u: None,
                v: None,
                verified: true,
                certificate: cert.checks,
                invariant_factor_coefficients: None,
                denominator_free: None,
                latex,
            }));
        }
    }
    opts.progress
        .phase("Smith form of Δ, lifted by the permutations");
    let (dec, _) = decompose_qx(&delta);
    let lifted = shape.lift(au, &dec);
    let (report, _) = generic_report(
        name,
        a_poly,
        au,
        lifted,
        MONOMIAL_ALGORITHM,
        Mode::OneSymbol,
        ring.to_string(),
        note.to_string(),
        opts,
        &super::certify::ClearedQx,
    )?;
    Ok(Some(report))
}

fn coefficient_field(a: &PolyRing, p: usize) -> RatFuncField {
    RatFuncField {
        names: a.names.clone(),
        shown: a
            .names
            .iter()
            .enumerate()
            .filter(|(i, _)| *i != p)
            .map(|(_, n)| n.clone())
            .collect(),
    }
}

/// Q\[all\] → Q(others)\[λ\]: the matrix principal mode works on, with `p`
/// the index of λ among the ring's symbols.
pub fn to_principal(a: &Matrix<PolyRing>, p: usize) -> Matrix<UPolyRing<RatFuncField>> {
    let k = coefficient_field(&a.ring, p);
    let ring = UPolyRing::new(k, a.ring.names[p].clone());
    let r2 = ring.clone();
    a.map(ring, |e| {
        r2.trim(e.coeffs_in(p).into_iter().map(RatFunc::from_poly).collect())
    })
}

fn principal(
    name: &str,
    a: &Matrix<PolyRing>,
    p: usize,
    opts: &SmithOptions,
) -> Result<SmithReport, SmithError> {
    let ap = to_principal(a, p);
    let ring_name = ap.ring.name();
    let note = format!(
        "principal symbol {}: Smith form over {ring_name}, a principal ideal domain; entries of U and V are rational functions of the other symbols",
        a.ring.names[p]
    );
    if let Some(r) = principal_form_only(name, a, &ap, p, &note, opts, None) {
        return Ok(r);
    }
    refuse_if_too_large(a, "the principal mode")?;
    let check = ClearedDenominators {
        p,
        nvars: a.ring.nvars(),
    };
    if let Some(r) = principal_fraction_free(name, a, &ap, p, &note, opts)? {
        return Ok(r);
    }
    opts.progress
        .phase(&format!("elimination over {ring_name}"));
    let dec = SmithDecomposition::new(&ap);
    let alg = "elimination over K[λ]: least-degree pivot, division with remainder";
    let (mut report, dec) = generic_report(
        name,
        a,
        &ap,
        dec,
        alg,
        Mode::Principal,
        ring_name,
        note,
        opts,
        &check,
    )?;
    report.invariant_factor_coefficients = Some(
        dec.invariant_factors()
            .iter()
            .map(|f| f.coeffs().iter().map(|c| ap.ring.k.lmx(c)).collect())
            .collect(),
    );
    opts.progress.phase("denominator-free form over Q[all]");
    report.denominator_free = Some(denominator_free(a, [&dec.u, &dec.d, &dec.v], p)?);
    Ok(report)
}

/// The principal mode for a square nonsingular input by the fraction-free
/// elimination over Q[others][λ] ([`super::fraction_free`]), certified
/// without inverse products
/// ([`super::certify_several::certify_principal_degrees`]); `Ok(None)`
/// when that route does not apply or does not certify (the caller takes
/// the elimination over K[λ]).
fn principal_fraction_free(
    name: &str,
    a: &Matrix<PolyRing>,
    ap: &Matrix<UPolyRing<RatFuncField>>,
    p: usize,
    note: &str,
    opts: &SmithOptions,
) -> Result<Option<SmithReport>, SmithError> {
    let kr = &ap.ring;
    opts.progress.phase(&format!(
        "fraction-free elimination over Q[{}][{}]",
        kr.k.shown.join(", "),
        a.ring.names[p]
    ));
    use super::fraction_free;
    let Some(ff) = fraction_free::eliminate_fraction_free(a, p) else {
        // Its entries swelled: the invariant factors alone, where the
        // det/adjugate (square) or coprime maximal minors (non-square)
        // certify them.
        let why = format!(
            "the fraction-free elimination over Q[others][λ] stopped at its safeguard against swelling entries (over {} bits of coefficients, or one round multiplying their size by over {} above {} bits, or by over {} above {} bits)",
            fraction_free::SIZE_LIMIT_BITS,
            fraction_free::JUMP_FACTOR,
            fraction_free::JUMP_FLOOR_BITS,
            fraction_free::SWELL_FACTOR,
            fraction_free::SWELL_FLOOR_BITS,
        );
        let form_only = super::principal_form::FormOnly {
            name,
            a,
            ap,
            p,
            note,
            why: &why,
            opts,
        };
        return Ok(principal_form_only(name, a, ap, p, note, opts, Some(&why))
            .or_else(|| form_only.maximal_minors())
            .or_else(|| form_only.determinantal_divisors()));
    };
    let Some([u, d, v]) = super::fraction_free::over_k(&ff, kr, p) else {
        return Ok(None);
    };
    opts.progress
        .phase("certifying U·A·V = D and deg det A (no inverse products)");
    let cert = super::certify_several::certify_principal_degrees(a, p, ap, [&u, &d, &v]);
    if !cert.verified() {
        return Ok(None);
    }
    let mut report = transforms_report(
        name,
        a,
        [&d, &u, &v],
        cert,
        "fraction-free elimination over Q[others][λ] (pseudo-division in λ, contents in Q[others] removed from each changed line), U = diag(1/lc)·U′, V = V′",
        Mode::Principal,
        kr.name(),
        note.to_string(),
        opts,
    );
    report.invariant_factor_coefficients = Some(
        d.diagonal()
            .iter()
            .map(|f| f.coeffs().iter().map(|c| kr.k.lmx(c)).collect())
            .collect(),
    );
    opts.progress.phase("denominator-free form over Q[all]");
    report.denominator_free = Some(denominator_free(a, [&u, &d, &v], p)?);
    Ok(Some(report))
}

/// From this size on, a square principal-mode input whose (n−1)-th
/// determinantal divisor over Q(others)\[λ\] is 1 gets its invariant factors
/// without transforms (certified from `A·B = c·I`,
/// [`super::certify_several`]); the elimination over Q(others)\[λ\] with
/// transforms grows fast (random 5×5 over Q[x, y] of degree 1: 0.4 s,
/// 6×6: 8.9 s CPU).
pub const PRINCIPAL_FORM_ONLY_MIN: usize = 6;

/// Below [`PRINCIPAL_FORM_ONLY_MIN`], the same happens when det A has more
/// than this many terms: on 96 seeded random 2×2–4×4 inputs in 2–3
/// symbols of degree ≤ 2 (`benches/multi_peers.py`), every elimination
/// whose det had at most 20 terms took ≤ 1.1 s CPU, and 16 of those with
/// 23 to 180 terms ran over 10 s (the transforms' coefficients are
/// rational functions of resultant size); the 4×4 in k1, k2, k3
/// (det of 21 terms) keeps its transforms (24 ms CPU by the fraction-free
/// route). With that route, 5 of 12 random 4×4 in three symbols of degree
/// 2 whose det has over 22 terms still took over 20 s with transforms, so
/// the threshold stays.
pub const PRINCIPAL_TRANSFORM_TERMS: usize = 22;

/// The principal-mode report with D alone, when the input is large
/// ([`PRINCIPAL_FORM_ONLY_MIN`], [`PRINCIPAL_TRANSFORM_TERMS`]; or
/// `forced`) and [`super::certify_several::certify_last_factor_several`]
/// establishes invariant factors 1, …, 1, det over Q(others)[λ]; when it
/// declines, for an input of at least [`PRINCIPAL_FORM_ONLY_MIN`] rows or
/// when `forced` (the fraction-free elimination's safeguard stopped it),
/// [`super::certify_several::certify_two_factors_several`] may establish
/// 1, …, 1, g, c/g instead (below that size and unforced the elimination
/// with transforms runs first, so its outputs are unchanged).
fn principal_form_only(
    name: &str,
    a: &Matrix<PolyRing>,
    ap: &Matrix<UPolyRing<RatFuncField>>,
    p: usize,
    note: &str,
    opts: &SmithOptions,
    forced: Option<&str>,
) -> Option<SmithReport> {
    opts.progress
        .phase("det and adj over Q[all] by Kronecker packing and images mod word primes");
    let (c, b) = super::several::det_adj_several(a)?;
    let n = a.rows();
    let why = if n >= PRINCIPAL_FORM_ONLY_MIN {
        format!(
            "a {n}×{n} input (the elimination with transforms is used below {PRINCIPAL_FORM_ONLY_MIN}×{PRINCIPAL_FORM_ONLY_MIN})"
        )
    } else if c.terms().len() > PRINCIPAL_TRANSFORM_TERMS {
        format!(
            "det A has {} terms (the elimination with transforms is used up to {PRINCIPAL_TRANSFORM_TERMS})",
            c.terms().len()
        )
    } else if let Some(why) = forced {
        why.to_string()
    } else {
        return None;
    };
    opts.progress
        .phase("certifying the invariant factors (A·B = c·I, gcd of adj over Q(others)[λ])");
    let cert = super::certify_several::certify_last_factor_several(a, &c, &b, &[p]);
    let kr = &ap.ring;
    let over_k = |e: &MPoly| {
        kr.normalize(&kr.trim(e.coeffs_in(p).into_iter().map(RatFunc::from_poly).collect()))
    };
    let pr = &a.ring;
    let mut d = Matrix::identity(kr.clone(), n);
    let (checks, last_note, algorithm) = if cert.verified() {
        d.set(n - 1, n - 1, over_k(&c));
        (
            cert.checks,
            format!("the last one, cleared of denominators, is {}", pr.format(&c.primitive_normal())),
            "det and adj over Q[all] by Kronecker substitution and images mod word primes (CRT above a proved bound); invariant factors from A·B = c·I, the gcd of adj's entries over Q(others)[λ] (images at a point mod p) and deg_λ c".to_string(),
        )
    } else if n < PRINCIPAL_FORM_ONLY_MIN && forced.is_none() {
        // Below that size the fraction-free elimination (with transforms)
        // runs first; this route is its fallback after the safeguard.
        return None;
    } else {
        // d_(n−1) ≠ 1 over Q(others)[λ] (or deg_λ c below the degree
        // bound): 1, …, 1, g, c/g by Jacobi's identity, or the elimination
        // below.
        opts.progress.phase(
            "certifying invariant factors 1, …, 1, g, c/g (gcd of adj, Jacobi, (n−2)-minors)",
        );
        let (cert2, g, last) = super::certify_several::certify_two_factors_several(a, &c, &b, p)?;
        if !cert2.verified() {
            return None;
        }
        d.set(n - 2, n - 2, over_k(&g));
        d.set(n - 1, n - 1, over_k(&last));
        (
            cert2.checks,
            if g.is_nonzero_constant() {
                format!(
                    "the last one, cleared of denominators, is {}",
                    pr.format(&last.primitive_normal())
                )
            } else {
                format!(
                    "the last two, cleared of denominators, are {} and {}",
                    pr.format(&g),
                    pr.format(&last.primitive_normal())
                )
            },
            "det and adj over Q[all] by Kronecker substitution and images mod word primes (CRT above a proved bound); invariant factors 1, …, 1, g, c/g from A·B = c·I: g = gcd of adj's entries over Q(others)[λ] (exact divisions, quotients coprime by images at a point mod p), c/det A free of λ by Jacobi's identity on a 2×2 minor, d_(n−2) = 1 from (n−2)×(n−2) minors".to_string(),
        )
    };
    let mode_note = format!(
        "{note}; transforms omitted because {why} (their coefficients are rational functions of resultant size): the invariant factors alone are certified; {last_note}"
    );
    Some(principal_d_only_report(
        name, a, d, n, mode_note, algorithm, checks, opts,
    ))
}

/// The principal mode's report of a certified D without transforms
/// (`rank` nonzero invariant factors): the form-only routes' common
/// assembly, shared by [`principal_form_only`] and
/// [`super::principal_form`].
#[allow(clippy::too_many_arguments)]
pub(super) fn principal_d_only_report(
    name: &str,
    a: &Matrix<PolyRing>,
    d: Matrix<UPolyRing<RatFuncField>>,
    rank: usize,
    mode_note: String,
    algorithm: String,
    certificate: Vec<Check>,
    opts: &SmithOptions,
) -> SmithReport {
    let kr = d.ring.clone();
    // The nonzero diagonal: a rank-deficient D lists only its rank's factors.
    let inv: Vec<_> = d.diagonal().into_iter().take(rank).collect();
    let latex = opts.latex.then(|| LatexForms {
        a: rows_of(a, true),
        invariant_factors: inv.iter().map(|e| kr.latex(e)).collect(),
        d: Some(rows_of(&d, true)),
        u: None,
        v: None,
    });
    SmithReport {
        matrix: name.to_string(),
        ring: kr.name(),
        mode: Mode::Principal,
        mode_note,
        algorithm,
        a: rows_of(a, false),
        invariant_factors: inv.iter().map(|e| kr.lmx(e)).collect(),
        rank,
        d: rows_of(&d, false),
        u: None,
        v: None,
        verified: true,
        certificate,
        invariant_factor_coefficients: Some(
            inv.iter()
                .map(|f| f.coeffs().iter().map(|c| kr.k.lmx(c)).collect())
                .collect(),
        ),
        denominator_free: None,
        latex,
    }
}

/// Evaluates identities over Q(others)[λ] by clearing denominators: with
/// `F̃ = δ_F·F` polynomial, `F1·…·Fk = R` ⇔ `δ_R·F̃1·…·F̃k = (Πδ_i)·R̃` over
/// Q[all]. The same statement, checked without rational-function gcds.
struct ClearedDenominators {
    p: usize,
    nvars: usize,
}

impl ClearedDenominators {
    fn clear(&self, m: &Matrix<UPolyRing<RatFuncField>>) -> (Matrix<PolyRing>, MPoly) {
        let mut dens: Vec<&MPoly> = Vec::new();
        for e in m.entries() {
            for c in &e.0 {
                if !dens.contains(&c.den()) {
                    dens.push(c.den());
                }
            }
        }
        let delta = dens.iter().fold(MPoly::one(self.nvars), |l, d| lcm(&l, d));
        let ring = PolyRing::new(m.ring.k.names.clone());
        let cleared = m.map(ring, |e| {
            let cs: Vec<MPoly> =
                e.0.iter()
                    .map(|c| c.num() * &delta.div_exact(c.den()).expect("lcm"))
                    .collect();
            MPoly::from_coeffs_in(self.p, &cs, self.nvars)
        });
        (cleared, delta)
    }
}

impl ProductCheck<UPolyRing<RatFuncField>> for ClearedDenominators {
    fn product_equals(
        &self,
        factors: &[&Matrix<UPolyRing<RatFuncField>>],
        rhs: &Matrix<UPolyRing<RatFuncField>>,
    ) -> bool {
        let mut scale = MPoly::one(self.nvars);
        let mut acc: Option<Matrix<PolyRing>> = None;
        for f in factors {
            let (c, d) = self.clear(f);
            scale = &scale * &d;
            acc = match acc {
                None => Some(c),
                Some(m) => match m.mul(&c) {
                    Some(x) => Some(x),
                    None => return false,
                },
            };
        }
        let Some(lhs) = acc else {
            return false;
        };
        let (r, dr) = self.clear(rhs);
        if lhs.rows() != r.rows() || lhs.cols() != r.cols() {
            return false;
        }
        lhs.entries()
            .iter()
            .zip(r.entries())
            .all(|(x, y)| &dr * x == &scale * y)
    }
}

/// A line of K\[λ\] entries with its denominators cleared
/// ([`super::certify_several::cleared_line`]) and its Q\[others\] content
/// removed: the entries come back over Q\[all\], λ the symbol `p`, with
/// no common factor free of λ.
fn cleared_content_free(line: &[&UPoly<RatFunc>], p: usize, n: usize) -> Vec<MPoly> {
    let cleared = super::certify_several::cleared_line(line, p, n);
    let mut g = MPoly::zero(n);
    for c in cleared.iter().flat_map(|e| e.coeffs_in(p)) {
        g = gcd(&g, &c);
        if g.is_nonzero_constant() {
            return cleared;
        }
    }
    if g.is_zero() {
        return cleared;
    }
    cleared
        .iter()
        .map(|e| e.div_exact(&g).expect("the content divides"))
        .collect()
}

fn denominator_free(
    a: &Matrix<PolyRing>,
    [du, dd, dv]: [&Matrix<UPolyRing<RatFuncField>>; 3],
    p: usize,
) -> Result<DenominatorFree, SmithError> {
    let n = a.ring.nvars();
    let kr = &du.ring;
    let pr = a.ring.clone();
    let scale_line = |line: Vec<&UPoly<RatFunc>>| cleared_content_free(&line, p, n);
    let m = du.rows();
    let mut u_rows = Vec::new();
    for i in 0..m {
        u_rows.extend(scale_line((0..m).map(|j| du.get(i, j)).collect()));
    }
    let u2 = Matrix::new(pr.clone(), m, m, u_rows);
    let nn = dv.cols();
    let mut v2 = Matrix::zeros(pr.clone(), nn, nn);
    for j in 0..nn {
        let col = scale_line((0..nn).map(|i| dv.get(i, j)).collect());
        for (i, e) in col.into_iter().enumerate() {
            v2.set(i, j, e);
        }
    }
    let prod = u2.mul(a).and_then(|x| x.mul(&v2)).expect("shapes");
    let diag = prod.diagonal();
    let mut c = Vec::new();
    let mut dprim = Matrix::zeros(pr.clone(), prod.rows(), prod.cols());
    for (i, e) in diag.iter().enumerate() {
        if e.is_zero() {
            c.push(MPoly::one(n));
            continue;
        }
        let ci = content_in(e, p);
        let pi = e.div_exact(&ci).expect("content divides");
        // Normalise D′ to primitive integer form; put the unit into C.
        let pn = pi.primitive_normal();
        let unit = pi.div_exact(&pn).expect("associates");
        c.push(&ci * &unit);
        dprim.set(i, i, pn);
    }
    let mut cd = dprim.clone();
    for (i, ci) in c.iter().enumerate().take(diag.len()) {
        let v = cd.get(i, i) * ci;
        cd.set(i, i, v);
    }
    let mut checks = Vec::new();
    let prod_ok = prod == cd;
    checks.push(Check {
        property: "U′·A·V′ = C·D′".into(),
        ok: prod_ok,
        detail: if prod_ok {
            "holds exactly over Q[all]".into()
        } else {
            "fails".into()
        },
    });
    let mut dets = Vec::new();
    for (nm, mat) in [("U′", &u2), ("V′", &v2)] {
        let d = super::certify_several::det_expanding_largest_row(mat).expect("square");
        let ok = !d.is_zero() && !d.contains_var(p);
        dets.push(pr.lmx(&d));
        checks.push(Check {
            property: format!("det {nm} ∈ Q[others] \\ {{0}}"),
            ok,
            detail: format!("det {nm} = {}", pr.format(&d)),
        });
    }
    let c_ok = c.iter().all(|x| !x.is_zero() && !x.contains_var(p));
    checks.push(Check {
        property: "C ∈ Q[others], nonzero".into(),
        ok: c_ok,
        detail: format!(
            "C = diag({})",
            c.iter()
                .map(|x| pr.format(x))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    });
    // D′ are associates over K of the certified invariant factors.
    let inv: Vec<UPoly<RatFunc>> = dd
        .diagonal()
        .into_iter()
        .filter(|e| !kr.is_zero(e))
        .collect();
    let assoc_ok = inv.iter().enumerate().all(|(i, f)| {
        let e = dprim.get(i, i);
        let as_k = kr.trim(e.coeffs_in(p).into_iter().map(RatFunc::from_poly).collect());
        kr.normalize(&as_k) == *f && content_in(e, p).is_nonzero_constant()
    });
    checks.push(Check {
        property: "D′ primitive, associate to D over K".into(),
        ok: assoc_ok,
        detail: "each D′ entry has content 1 in Q[others] and is D's entry times a unit of K"
            .into(),
    });
    let cert = Certificate { checks };
    fail_if_unverified(&cert)?;
    let kname = format!("Q[{}]", pr.names.join(", "));
    Ok(DenominatorFree {
        ring: kname,
        d: dprim.lmx_rows(),
        u: u2.lmx_rows(),
        v: v2.lmx_rows(),
        c: c.iter().map(|x| pr.lmx(x)).collect(),
        det_u: dets[0].clone(),
        det_v: dets[1].clone(),
        verified: true,
        certificate: cert.checks,
    })
}

/// Above this size the several-symbol modes refuse the elimination over
/// Q(others)\[s\] (rational-function coefficients; a random 6×6 over
/// Q[x, y] of degree 1 already takes 8.9 s CPU there) when the
/// det/adjugate route did not apply.
pub const SEVERAL_ELIMINATION_MAX: usize = 16;

/// Refuses an input that only the elimination over Q(others)[s] could
/// treat and that is too large for it, naming every route's size.
fn refuse_if_too_large(a: &Matrix<PolyRing>, mode: &str) -> Result<(), SmithError> {
    let (m, n) = (a.rows(), a.cols());
    if m.max(n) <= SEVERAL_ELIMINATION_MAX {
        return Ok(());
    }
    let minors = super::divisors::minor_count(m, n);
    let packed = super::several::packed_det_degree(a);
    let fmt = |x: u128| {
        if x == u128::MAX {
            "more than 3.4e38".to_string()
        } else if x >= 10_000_000_000 {
            format!("{:.2e}", x as f64)
        } else {
            x.to_string()
        }
    };
    Err(SmithError::TooLarge(format!(
        "{mode} cannot treat this {m}×{n} matrix over {ring}: the determinant route needs a square nonsingular matrix whose packed determinant has degree ≤ {maxp} (here {packed}) and first {k} invariant factors 1; the gcd of minors would need {minors} minors (limit {MINOR_LIMIT}); the elimination over Q(others)[s] is refused above {SEVERAL_ELIMINATION_MAX}×{SEVERAL_ELIMINATION_MAX}. A matrix in one symbol (substitute values for the others) is handled far beyond this size",
        ring = a.ring.name(),
        maxp = super::several::MAX_PACKED_DEGREE,
        packed = fmt(packed),
        k = m.min(n).saturating_sub(1),
        minors = fmt(minors),
    )))
}

/// Up to this many minors the determinantal mode enumerates them
/// ([`super::divisors::certified_divisors`]); above, a square input whose d_(n−1) is 1
/// takes det and adj by images, any other one certified Smith form per
/// symbol.
pub const MINOR_ROUTE_LIMIT: u128 = 20_000;

/// The primitive associate in Q[all] of an element of Q(others)[λ]
/// (denominators cleared, content in Q[others] removed).
fn cleared_primitive(e: &UPoly<RatFunc>, p: usize, n: usize) -> MPoly {
    let l = e.0.iter().fold(MPoly::one(n), |l, c| lcm(&l, c.den()));
    let cs: Vec<MPoly> =
        e.0.iter()
            .map(|c| c.num() * &l.div_exact(c.den()).expect("lcm"))
            .collect();
    let poly = MPoly::from_coeffs_in(p, &cs, n);
    let c = content_in(&poly, p);
    poly.div_exact(&c)
        .expect("content divides")
        .primitive_normal()
}

/// Determinantal divisors over Q[all] without minors. For each symbol s
/// occurring in A, the Smith form over Q(others)[s] is computed and
/// certified; the primitive part (in s) of its k-th determinantal divisor
/// is the product of the irreducible factors of d_k that involve s, with
/// their multiplicities. Every non-constant irreducible factor involves
/// some symbol, so d_k = lcm over s of these parts.
fn divisors_by_symbol(
    a: &Matrix<PolyRing>,
    progress: &PhaseHook,
) -> Result<(super::divisors::Divisors<MPoly>, Certificate), SmithError> {
    let n = a.ring.nvars();
    let mut checks = Vec::new();
    let mut per_symbol: Vec<Vec<MPoly>> = Vec::new();
    for p in (0..n).filter(|&p| a.entries().iter().any(|e| e.contains_var(p))) {
        let ap = to_principal(a, p);
        progress.phase(&format!("Smith form over {}", ap.ring.name()));
        let dec = SmithDecomposition::new(&ap);
        progress.phase(&format!(
            "certifying the Smith form over {}",
            ap.ring.name()
        ));
        let cert = dec.certify_with(&ap, &ClearedDenominators { p, nvars: n });
        fail_if_unverified(&cert)?;
        checks.push(Check {
            property: format!("Smith form over {} certified", ap.ring.name()),
            ok: true,
            detail: cert
                .checks
                .iter()
                .map(|c| c.property.clone())
                .collect::<Vec<_>>()
                .join("; "),
        });
        let mut acc = MPoly::one(n);
        per_symbol.push(
            dec.invariant_factors()
                .iter()
                .map(|f| {
                    acc = &acc * &cleared_primitive(f, p, n);
                    acc.primitive_normal()
                })
                .collect(),
        );
    }
    let rank = per_symbol.first().map_or(0, |d| d.len());
    if per_symbol.iter().any(|d| d.len() != rank) {
        return Err(SmithError::CertificateFailed(
            "the ranks over Q(others)[s] differ between symbols".into(),
        ));
    }
    let mut det: Vec<MPoly> = Vec::with_capacity(rank);
    let mut inv: Vec<MPoly> = Vec::with_capacity(rank);
    if per_symbol.is_empty() {
        // A constant matrix: its rank over Q, every divisor 1.
        let r = a.rank();
        det = vec![MPoly::one(n); r];
        inv = vec![MPoly::one(n); r];
    }
    for k in 0..rank {
        let dk = per_symbol.iter().fold(MPoly::one(n), |l, d| lcm(&l, &d[k]));
        let prev = if k == 0 {
            MPoly::one(n)
        } else {
            det[k - 1].clone()
        };
        let fk = dk
            .div_exact(&prev)
            .ok_or_else(|| SmithError::CertificateFailed("d_(k-1) does not divide d_k".into()))?;
        inv.push(fk.primitive_normal());
        det.push(dk);
    }
    let chain = inv.windows(2).all(|w| w[1].div_exact(&w[0]).is_some());
    checks.push(Check {
        property: "divisibility f1 | f2 | …".into(),
        ok: chain,
        detail: "each invariant factor divides the next (exact division over Q[all])".into(),
    });
    checks.push(Check {
        property: "d_k = lcm over symbols s of the primitive divisors over Q(others)[s]".into(),
        ok: true,
        detail: "every irreducible factor of d_k involves a symbol s and appears with its multiplicity in the certified Smith form over Q(others)[s]".into(),
    });
    Ok((
        super::divisors::Divisors {
            determinantal: det,
            invariant: inv,
        },
        Certificate { checks },
    ))
}

/// The determinantal mode for a square input with d_(n−1) = 1 over
/// Q[all] (the generic case): `A·B = c·I` from
/// [`super::several::det_adj_several`], certified over Q(others)[s] for
/// every symbol s ([`super::certify_several`]), gives d_1 = … = d_(n−1) = 1
/// and d_n ~ c without a single minor.
fn divisors_generic(name: &str, a: &Matrix<PolyRing>, opts: &SmithOptions) -> Option<SmithReport> {
    if a.rows() < 2 || a.rows() != a.cols() {
        return None;
    }
    opts.progress
        .phase("det and adj over Q[all] by Kronecker packing and images mod word primes");
    let (c, b) = super::several::det_adj_several(a)?;
    let symbols: Vec<usize> = (0..a.ring.nvars())
        .filter(|&v| a.entries().iter().any(|e| e.contains_var(v)))
        .collect();
    opts.progress
        .phase("certifying the divisors (A·B = c·I, gcd of adj over Q(others)[s] per symbol)");
    let cert = super::certify_several::certify_last_factor_several(a, &c, &b, &symbols);
    if !cert.verified() {
        return None;
    }
    let r = &a.ring;
    let n = a.rows();
    let mut inv = vec![MPoly::one(r.nvars()); n];
    inv[n - 1] = c.primitive_normal();
    let mut d = Matrix::zeros(r.clone(), n, n);
    for (i, f) in inv.iter().enumerate() {
        d.set(i, i, f.clone());
    }
    let latex = opts.latex.then(|| LatexForms {
        a: a.latex_rows(),
        invariant_factors: inv.iter().map(|e| r.latex(e)).collect(),
        d: Some(d.latex_rows()),
        u: None,
        v: None,
    });
    Some(SmithReport {
        matrix: name.to_string(),
        ring: r.name(),
        mode: Mode::DeterminantalDivisors,
        algorithm: "det and adj over Q[all] by Kronecker substitution and images mod word primes (CRT above a proved bound); d_(n−1) = 1 and d_n ~ det from A·B = c·I, the gcd of adj's entries over Q(others)[s] for every symbol s and deg_s c (no minors enumerated)".to_string(),
        mode_note: divisors_note(r),
        a: a.lmx_rows(),
        invariant_factors: inv.iter().map(|e| r.lmx(e)).collect(),
        rank: n,
        d: d.lmx_rows(),
        u: None,
        v: None,
        verified: true,
        certificate: cert.checks,
        invariant_factor_coefficients: None,
        denominator_free: None,
        latex,
    })
}

fn divisors_note(r: &PolyRing) -> String {
    format!(
        "invariant factors over {} from determinantal divisors (d_k = gcd of the k×k minors, f_k = d_k/d_(k-1)); this ring is not a principal ideal domain, so a unimodular U, V with U·A·V = D need not exist and none is claimed; name a principal symbol (`principal s` or --principal s) for transforms",
        r.name()
    )
}

/// Bytes one stored term of a minor takes (exponent vector, rational
/// coefficient and their allocations), for the minors route's memory
/// limit: peak resident memory over the terms of the two orders held then
/// was 121–125 bytes on 8×8 inputs in three symbols of degree 6 and 10
/// (6.6 and 18.2 million terms).
const MINOR_TERM_BYTES: u64 = 125;

fn divisors_mode(
    name: &str,
    a: &Matrix<PolyRing>,
    opts: &SmithOptions,
) -> Result<SmithReport, SmithError> {
    // Two orders of minors are held at once: each gets a quarter of the
    // process's memory budget.
    let max_terms = crate::numeric::budget::default_budget() / 4 / MINOR_TERM_BYTES;
    divisors_mode_within(name, a, opts, usize::try_from(max_terms).unwrap_or(usize::MAX))
}

/// [`divisors_mode`] with the minors route holding at most `max_terms`
/// terms per order; past that, the routes without minors.
fn divisors_mode_within(
    name: &str,
    a: &Matrix<PolyRing>,
    opts: &SmithOptions,
    max_terms: usize,
) -> Result<SmithReport, SmithError> {
    // Up to MINOR_ROUTE_LIMIT minors, all of them (by Laplace expansion)
    // are cheaper than det and adj by images: measured on seeded 4×4–8×8
    // in three symbols of degree 2–10, never slower and up to 60× faster.
    let mut by_minors = None;
    if super::divisors::minor_count(a.rows(), a.cols()) <= MINOR_ROUTE_LIMIT {
        opts.progress
            .phase("minors by Laplace expansion, their gcds and the certificate");
        by_minors = certified_divisors_within(a, MINOR_LIMIT, Some(max_terms))?;
    }
    let from_minors = by_minors.is_some();
    let (dv, cert) = match by_minors {
        Some(found) => found,
        None => {
            if let Some(r) = divisors_generic(name, a, opts) {
                return Ok(r);
            }
            refuse_if_too_large(a, "the determinantal-divisor mode")?;
            divisors_by_symbol(a, &opts.progress)?
        }
    };
    fail_if_unverified(&cert)?;
    let r = &a.ring;
    let mut d = Matrix::zeros(r.clone(), a.rows(), a.cols());
    for (i, f) in dv.invariant.iter().enumerate() {
        d.set(i, i, f.clone());
    }
    let latex = opts.latex.then(|| LatexForms {
        a: a.latex_rows(),
        invariant_factors: dv.invariant.iter().map(|e| r.latex(e)).collect(),
        d: Some(d.latex_rows()),
        u: None,
        v: None,
    });
    Ok(SmithReport {
        matrix: name.to_string(),
        ring: r.name(),
        mode: Mode::DeterminantalDivisors,
        algorithm: if from_minors {
            "gcd of k×k minors (Laplace expansion from the minors of order k−1, modular gcd)".to_string()
        } else {
            "lcm over each symbol s of the determinantal divisors of the certified Smith form over Q(others)[s] (no minors enumerated)".to_string()
        },
        mode_note: divisors_note(r),
        a: a.lmx_rows(),
        invariant_factors: dv.invariant.iter().map(|e| r.lmx(e)).collect(),
        rank: dv.invariant.len(),
        d: d.lmx_rows(),
        u: None,
        v: None,
        verified: true,
        certificate: cert.checks,
        invariant_factor_coefficients: None,
        denominator_free: None,
        latex,
    })
}

/// The result of checking a user-supplied decomposition.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct CheckReport {
    /// Names of A, U, D, V in the source.
    pub names: [String; 4],
    /// The ring the check was done over.
    pub ring: String,
    /// Whether `(U, D, V)` is a Smith decomposition of A.
    pub is_smith: bool,
    /// Every property with its outcome.
    pub certificate: Vec<Check>,
}

/// Checks whether `(u, d, v)` is a Smith decomposition of `a`, over Q\[x\]
/// (one symbol), Q(others)\[λ\] (principal λ) or Q\[all\] (otherwise), and
/// says which property fails.
pub fn check_decomposition(
    names: [String; 4],
    mats: [&Matrix<PolyRing>; 4],
    principal: Option<usize>,
) -> CheckReport {
    let [a, u, d, v] = mats;
    let (ring, cert) = match (a.ring.names.len(), principal) {
        (0 | 1, _) => {
            let m: Vec<_> = mats.iter().map(|m| to_univariate(m)).collect();
            (m[0].ring.name(), run_check(&m))
        }
        (_, Some(p)) => {
            let m: Vec<_> = mats.iter().map(|m| to_principal(m, p)).collect();
            (m[0].ring.name(), run_check(&m))
        }
        (_, None) => (
            a.ring.name(),
            certify(a, u, d, v, Unimodular::Determinant, Unimodular::Determinant),
        ),
    };
    CheckReport {
        names,
        ring,
        is_smith: cert.verified(),
        certificate: cert.checks,
    }
}

fn run_check<R: GcdDomain>(m: &[Matrix<R>]) -> Certificate {
    certify(
        &m[0],
        &m[1],
        &m[2],
        &m[3],
        Unimodular::Determinant,
        Unimodular::Determinant,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::smith::divisors::determinantal_divisors;

    fn seed() -> Matrix<PolyRing> {
        let names: Vec<String> = ["k1", "k2", "k3", "k4"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        let v: Vec<MPoly> = (0..4).map(|i| MPoly::var(i, 4)).collect();
        Matrix::new(PolyRing::new(names), 2, 2, v)
    }

    #[test]
    fn seed_matrix_in_the_determinantal_mode() {
        let r = smith_report("A", &seed(), &SmithOptions::default()).unwrap();
        assert_eq!(r.mode, Mode::DeterminantalDivisors);
        assert_eq!(r.invariant_factors, vec!["1", "k1*k4 - k2*k3"]);
        assert!(r.u.is_none() && r.verified);
    }

    #[test]
    fn determinantal_divisors_by_symbol_agree_with_minors() {
        // A = B·diag(1, x + y, (x + y)·x·(y + 1))·C with B, C invertible
        // over Q[x, y] (constant and unitriangular).
        let n = 2;
        let ring = PolyRing::new(vec!["x".into(), "y".into()]);
        let (x, y) = (MPoly::var(0, n), MPoly::var(1, n));
        let one = MPoly::one(n);
        let c = |v: i64| MPoly::constant(crate::algebra::rational::qi(v), n);
        let f2 = &x + &y;
        let f3 = &(&f2 * &x) * &(&y + &one);
        let zero = MPoly::zero(n);
        let d = Matrix::new(
            ring.clone(),
            3,
            3,
            vec![
                one.clone(),
                zero.clone(),
                zero.clone(),
                zero.clone(),
                f2,
                zero.clone(),
                zero.clone(),
                zero,
                f3,
            ],
        );
        let b = Matrix::new(
            ring.clone(),
            3,
            3,
            vec![c(1), c(2), c(0), c(-1), c(3), c(1), c(2), c(0), c(5)],
        );
        let cm = Matrix::new(
            ring.clone(),
            3,
            3,
            vec![
                one.clone(),
                y.clone(),
                x.clone(),
                c(0),
                one.clone(),
                &x * &y,
                c(0),
                c(0),
                one,
            ],
        );
        let a = b.mul(&d).unwrap().mul(&cm).unwrap();
        let by_minors = determinantal_divisors(&a, MINOR_LIMIT).unwrap();
        let (by_symbol, cert) = divisors_by_symbol(&a, &PhaseHook::default()).unwrap();
        assert!(cert.verified());
        assert_eq!(by_symbol.invariant, by_minors.invariant);
        assert_eq!(by_symbol.determinantal, by_minors.determinantal);
        let shown: Vec<String> = by_symbol.invariant.iter().map(|f| ring.format(f)).collect();
        assert_eq!(shown, vec!["1", "x + y", "x^2*y + x^2 + x*y^2 + x*y"]);
    }

    /// A seeded dense n×n over Q[x, y] with entries a + b·x + c·y + d·x·y.
    fn random_xy(n: usize, seed: u64) -> Matrix<PolyRing> {
        let mut s = seed;
        let mut next = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((s >> 33) % 19) as i64 - 9
        };
        let (x, y) = (MPoly::var(0, 2), MPoly::var(1, 2));
        let c = |v: i64| MPoly::constant(crate::algebra::rational::qi(v), 2);
        let data = (0..n * n)
            .map(|_| c(next()) + &x * &c(next()) + &y * &c(next()) + &(&x * &y) * &c(next()))
            .collect();
        Matrix::new(PolyRing::new(vec!["x".into(), "y".into()]), n, n, data)
    }

    #[test]
    fn principal_form_only_route_agrees_with_the_elimination() {
        let a = random_xy(3, 11);
        let ap = to_principal(&a, 1);
        let opts = SmithOptions::default();
        let fast = principal_form_only("A", &a, &ap, 1, "note", &opts, Some("asked"))
            .expect("generic input");
        let full = smith_report(
            "A",
            &a,
            &SmithOptions {
                principal: Some(1),
                ..SmithOptions::default()
            },
        )
        .expect("certified");
        assert!(full.u.is_some(), "a small det takes the elimination");
        assert_eq!(fast.invariant_factors, full.invariant_factors);
        assert_eq!(
            fast.invariant_factor_coefficients,
            full.invariant_factor_coefficients
        );
    }

    #[test]
    fn principal_divisors_route_agrees_with_the_elimination() {
        let square = random_xy(3, 11);
        // Rank 2: the third row is x·(first) + (second).
        let mut singular = random_xy(3, 5);
        for j in 0..3 {
            let e = &(&MPoly::var(0, 2) * singular.get(0, j)) + singular.get(1, j);
            singular.set(2, j, e);
        }
        let wide = random_xy(3, 7).submatrix(&[0, 1], &[0, 1, 2]);
        let tall = random_xy(3, 9).submatrix(&[0, 1, 2], &[0, 2]);
        let mut ranks = Vec::new();
        for a in [square, singular, wide, tall] {
            for p in [0, 1] {
                let ap = to_principal(&a, p);
                let opts = SmithOptions::default();
                let fast = super::super::principal_form::FormOnly {
                    name: "A",
                    a: &a,
                    ap: &ap,
                    p,
                    note: "note",
                    why: "asked",
                    opts: &opts,
                }
                .determinantal_divisors()
                .expect("few minors");
                let full = smith_report(
                    "A",
                    &a,
                    &SmithOptions {
                        principal: Some(p),
                        ..SmithOptions::default()
                    },
                )
                .expect("certified");
                assert!(full.u.is_some(), "a small input takes the elimination");
                assert!(fast.u.is_none());
                assert_eq!(fast.invariant_factors, full.invariant_factors, "symbol {p}");
                assert_eq!(fast.d, full.d);
                assert_eq!(fast.rank, full.rank);
                ranks.push(fast.rank);
            }
        }
        assert_eq!(ranks, [3, 3, 2, 2, 2, 2, 2, 2]);
    }

    /// A bulk limit below what the minors need sends the determinantal
    /// mode to the route without minors, with the same factors.
    #[test]
    fn the_minors_memory_limit_falls_back_to_the_routes_without_minors() {
        let opts = SmithOptions::default();
        for seed in [3, 4] {
            let a = random_xy(4, seed);
            let minors = divisors_mode_within("A", &a, &opts, usize::MAX).expect("certified");
            let limited = divisors_mode_within("A", &a, &opts, 10).expect("certified");
            assert!(minors.algorithm.starts_with("gcd of k×k minors"));
            assert!(limited.algorithm.starts_with("det and adj"), "{}", limited.algorithm);
            assert_eq!(minors.invariant_factors, limited.invariant_factors);
        }
    }

    #[test]
    fn determinantal_form_only_route_agrees_with_the_minors() {
        for seed in [3, 4] {
            let a = random_xy(4, seed);
            let fast = divisors_generic("A", &a, &SmithOptions::default()).expect("generic");
            let dv = determinantal_divisors(&a, MINOR_LIMIT).expect("few minors");
            let minors: Vec<String> = dv.invariant.iter().map(|f| a.ring.lmx(f)).collect();
            assert_eq!(fast.invariant_factors, minors);
        }
        // diag(x, x·y): d_1 = x, not generic; the route declines.
        let r = PolyRing::new(vec!["x".into(), "y".into()]);
        let (x, y) = (MPoly::var(0, 2), MPoly::var(1, 2));
        let z = MPoly::zero(2);
        let a = Matrix::new(r, 2, 2, vec![x.clone(), z.clone(), z, &x * &y]);
        assert!(divisors_generic("A", &a, &SmithOptions::default()).is_none());
    }

    fn qx_ring() -> PolyRing {
        PolyRing::new(vec!["x".into()])
    }

    /// x − c in Q[x] (as a one-symbol MPoly).
    fn x_minus(c: i64) -> MPoly {
        &MPoly::var(0, 1) - &MPoly::constant(crate::algebra::rational::qi(c), 1)
    }

    /// The invariant factors from the k×k minors, printed like a report's.
    fn from_minors(a: &Matrix<PolyRing>) -> Vec<String> {
        let au = to_univariate(a);
        let dv = determinantal_divisors(&au, MINOR_LIMIT).expect("few minors");
        dv.invariant.iter().map(|f| au.ring.lmx(f)).collect()
    }

    #[test]
    fn monomial_route_lifts_transforms_and_agrees_with_the_minors() {
        // 3×5 and 5×4, entries at scattered places, some factors shared.
        type Places = Vec<(usize, usize, MPoly)>;
        let shapes: [(usize, usize, Places); 2] = [
            (
                3,
                5,
                vec![
                    (0, 3, &x_minus(1) * &x_minus(2)),
                    (1, 0, x_minus(1)),
                    (2, 4, &x_minus(1) * &x_minus(1)),
                ],
            ),
            (
                5,
                4,
                vec![
                    (0, 2, x_minus(3)),
                    (2, 0, &x_minus(3) * &x_minus(0)),
                    (3, 1, x_minus(5)),
                    (4, 3, MPoly::constant(crate::algebra::rational::qi(7), 1)),
                ],
            ),
        ];
        for (m, n, places) in shapes {
            let mut a = Matrix::zeros(qx_ring(), m, n);
            for (i, j, e) in places {
                a.set(i, j, e);
            }
            let r = smith_report("A", &a, &SmithOptions::default()).expect("certified");
            assert!(r.verified);
            assert!(
                r.algorithm.starts_with("monomial-shaped"),
                "{}",
                r.algorithm
            );
            assert!(r.u.is_some() && r.v.is_some());
            assert_eq!(r.invariant_factors, from_minors(&a));
            assert_eq!(r.d.len(), m);
            assert_eq!(r.d[0].len(), n);
        }
    }

    #[test]
    fn large_non_square_diagonal_gets_its_factors_alone() {
        // diag(x − 1, …, x − 33) with a zero column, transposed too.
        let k = DIAGONAL_FORM_ONLY + 1;
        let mut f = MPoly::one(1);
        for i in 0..k {
            f = &f * &x_minus(i as i64 + 1);
        }
        for transpose in [false, true] {
            let mut a = Matrix::zeros(qx_ring(), k, k + 1);
            for i in 0..k {
                a.set(i, (i + 1) % (k + 1), x_minus(i as i64 + 1));
            }
            let a = if transpose { a.transpose() } else { a };
            let r = smith_report("A", &a, &SmithOptions::default()).expect("certified");
            assert!(r.verified && r.u.is_none());
            assert_eq!(r.rank, k);
            assert_eq!(r.invariant_factors.len(), k);
            let au = to_univariate(&a);
            let fu = to_univariate(&Matrix::new(qx_ring(), 1, 1, vec![f.clone()]));
            assert_eq!(r.invariant_factors[k - 1], au.ring.lmx(fu.get(0, 0)));
            assert!(r.invariant_factors[..k - 1].iter().all(|e| e == "1"));
            assert!(r.certificate.iter().all(|c| c.ok));
            assert_eq!(
                r.certificate[0].property,
                "A is a row and column permutation of [[Δ, 0], [0, 0]]"
            );
        }
    }

    #[test]
    fn two_by_two_with_a_huge_coefficient_gets_d_alone_agreeing_with_the_minors() {
        // Degree 40 with one 1 000-bit coefficient: Res(a, b) has about
        // 40 000 bits, beyond the modular routes.
        let big = num_bigint::BigInt::from(3u8).pow(631);
        let mut s = 7u64;
        let mut next = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((s >> 33) % 19) as i64 - 9
        };
        let x = MPoly::var(0, 1);
        let mut entries = Vec::new();
        for e in 0..4 {
            let mut p = MPoly::zero(1);
            let mut xk = MPoly::one(1);
            for k in 0..=40 {
                let c = if e == 0 && k == 20 {
                    crate::algebra::rational::Q::from(big.clone())
                } else {
                    crate::algebra::rational::qi(next())
                };
                p = &p + &(&xk * &MPoly::constant(c, 1));
                xk = &xk * &x;
            }
            entries.push(p);
        }
        let a = Matrix::new(qx_ring(), 2, 2, entries);
        let r = smith_report("A", &a, &SmithOptions::default()).expect("certified");
        assert!(r.verified && r.u.is_none(), "{}", r.algorithm);
        assert!(
            r.mode_note.contains("Bezout coefficients"),
            "{}",
            r.mode_note
        );
        assert_eq!(r.invariant_factors, from_minors(&a));
    }

    #[test]
    fn oversized_two_symbol_input_is_refused_with_every_route_named() {
        // 66×66 over Q[x, y]: Σ C(66,k)² minors overflow u128, the packed
        // det would have degree 66·67 = 4422 > 3000, the elimination is refused.
        let r = PolyRing::new(vec!["x".into(), "y".into()]);
        let e = &MPoly::var(0, 2) + &MPoly::var(1, 2);
        let a = Matrix::new(r, 66, 66, vec![e; 66 * 66]);
        for principal in [None, Some(1)] {
            let opts = SmithOptions {
                principal,
                ..SmithOptions::default()
            };
            let Err(SmithError::TooLarge(msg)) = smith_report("A", &a, &opts) else {
                panic!("expected a refusal");
            };
            assert!(msg.contains("66×66"), "{msg}");
            assert!(msg.contains("(here 4422)"), "{msg}");
            assert!(msg.contains("more than 3.4e38 minors"), "{msg}");
            assert!(msg.contains("one symbol"), "{msg}");
        }
    }

    #[test]
    fn seed_matrix_with_principal_k4() {
        let opts = SmithOptions {
            principal: Some(3),
            latex: true,
            ..SmithOptions::default()
        };
        let r = smith_report("A", &seed(), &opts).unwrap();
        assert_eq!(r.ring, "Q(k1, k2, k3)[k4]");
        assert_eq!(r.invariant_factors, vec!["1", "k4 - k2*k3/k1"]);
        let df = r.denominator_free.unwrap();
        assert_eq!(df.d[1][1], "k1*k4 - k2*k3");
        assert_eq!(df.d[0][0], "1");
        assert!(df.verified);
        eprintln!("{df:#?}\n{:#?}", r.u);
    }
}
