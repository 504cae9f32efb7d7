//! Invariant factors from determinantal divisors over any gcd domain:
//! `d_k = gcd` of all k×k minors, `f_k = d_k / d_{k-1}`. This is the honest
//! mode over Q[s1..sn] with n ≥ 2, where no unimodular transforms need exist;
//! it is also the independent cross-check of the elimination in tests.
//! The minors come order by order from Laplace expansion
//! ([`MinorOrders`]), each order once for its gcd and its certificate.
//! Owns only this computation and its certificate.

use super::certify::{Certificate, Check};
use crate::algebra::matrix::{Matrix, MinorOrders};
use crate::algebra::ring::GcdDomain;

/// The determinantal divisors `d_1..d_r` (r = rank) and invariant factors.
#[derive(Clone, Debug)]
pub struct Divisors<E> {
    /// `d_k` for k = 1..=rank (normalised).
    pub determinantal: Vec<E>,
    /// `f_k = d_k / d_{k-1}` for k = 1..=rank.
    pub invariant: Vec<E>,
}

/// Error: the number of minors exceeds the caller's budget.
#[derive(Debug, thiserror::Error)]
#[error(
    "the determinantal-divisor mode would need {} minors of a {rows}×{cols} matrix (limit {limit}); name a principal symbol (`principal s` in the file or --principal s) to use the elimination over Q(others)[s] instead",
    fmt_count(*needed)
)]
pub struct TooManyMinors {
    /// Minors that would be computed.
    pub needed: u128,
    /// Matrix rows.
    pub rows: usize,
    /// Matrix columns.
    pub cols: usize,
    /// The limit.
    pub limit: u128,
}

fn fmt_count(n: u128) -> String {
    if n == u128::MAX {
        "more than 3.4e38".into()
    } else if n >= 10_000_000_000 {
        format!("{:.3e}", n as f64)
    } else {
        n.to_string()
    }
}

/// `C(n, k)`, saturating at `u128::MAX` instead of overflowing.
fn binom(n: usize, k: usize) -> u128 {
    let mut acc = 1u128;
    for i in 0..k as u128 {
        // acc·(n−i)/(i+1) is exact; divide first by the common factor
        // to keep the intermediate small, and saturate if it still
        // overflows.
        let (num, den) = ((n as u128) - i, i + 1);
        let g = gcd_u128(acc, den);
        let (a, d) = (acc / g, den / g);
        let Some(x) = a.checked_mul(num / d) else {
            return u128::MAX;
        };
        acc = x;
    }
    acc
}

fn gcd_u128(mut a: u128, mut b: u128) -> u128 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// The number of minors of all orders of an m×n matrix (saturating).
pub fn minor_count(m: usize, n: usize) -> u128 {
    (1..=m.min(n)).fold(0u128, |s, k| {
        s.saturating_add(binom(m, k).saturating_mul(binom(n, k)))
    })
}

/// Computes the determinantal divisors and invariant factors of `a`,
/// refusing inputs that would need more than `limit` minors in total.
pub fn determinantal_divisors<R: GcdDomain>(
    a: &Matrix<R>,
    limit: u128,
) -> Result<Divisors<R::Elem>, TooManyMinors> {
    divisors_pass(a, limit, false, None).map(|r| r.expect("no bulk limit").0)
}

/// [`determinantal_divisors`] with their certificate, taken from the same
/// minors: each `d_k` divides every k×k minor (by exact division),
/// `d_{k-1}·f_k = d_k` up to a unit, `f_k | f_{k+1}`, and every minor of
/// order rank + 1 vanishes.
pub fn certified_divisors<R: GcdDomain>(
    a: &Matrix<R>,
    limit: u128,
) -> Result<(Divisors<R::Elem>, Certificate), TooManyMinors> {
    certified_divisors_within(a, limit, None).map(|r| r.expect("no bulk limit"))
}

/// Divisors with their certificate.
pub type CertifiedDivisors<E> = (Divisors<E>, Certificate);

/// [`certified_divisors`] holding at most `max_bulk` terms of minors per
/// order (two orders at a time): `Ok(None)` when an order would hold more.
pub fn certified_divisors_within<R: GcdDomain>(
    a: &Matrix<R>,
    limit: u128,
    max_bulk: Option<usize>,
) -> Result<Option<CertifiedDivisors<R::Elem>>, TooManyMinors> {
    divisors_pass(a, limit, true, max_bulk)
        .map(|r| r.map(|(dv, cert)| (dv, cert.expect("certified"))))
}

/// The gcd of `minors`, smallest first, and for each minor whether an
/// exact division by the running gcd showed that the final gcd divides it
/// (the running gcd only loses factors). A minor the running gcd already
/// divides costs one exact division instead of a gcd; once the gcd is a
/// unit the rest are not looked at.
fn minors_gcd<R: GcdDomain>(r: &R, minors: &[R::Elem]) -> (R::Elem, Vec<bool>) {
    let mut order: Vec<usize> = (0..minors.len())
        .filter(|&i| !r.is_zero(&minors[i]))
        .collect();
    order.sort_by_key(|&i| r.bulk(&minors[i]));
    let mut divided = vec![false; minors.len()];
    let mut g = r.zero();
    for i in order {
        let x = &minors[i];
        if r.is_zero(&g) {
            g = r.normalize(x);
        } else if r.is_unit(&g) {
            break;
        } else if r.div_exact(x, &g).is_some() {
            divided[i] = true;
        } else {
            g = r.gcd(&g, x);
        }
    }
    (g, divided)
}

/// The minors order by order ([`MinorOrders`]): the gcd of each order,
/// and with `certify` the checks of [`certified_divisors`].
/// What one pass found: the divisors and, when asked, their certificate;
/// `None` at the bulk limit.
type Pass<E> = Option<(Divisors<E>, Option<Certificate>)>;

fn divisors_pass<R: GcdDomain>(
    a: &Matrix<R>,
    limit: u128,
    certify: bool,
    max_bulk: Option<usize>,
) -> Result<Pass<R::Elem>, TooManyMinors> {
    let (m, n) = (a.rows(), a.cols());
    let needed = minor_count(m, n);
    if needed > limit {
        return Err(TooManyMinors {
            needed,
            rows: m,
            cols: n,
            limit,
        });
    }
    let r = &a.ring;
    let mut det = Vec::new();
    let mut inv = Vec::new();
    let mut prev = r.one();
    let mut all_divide = true;
    let mut next_zero = true;
    let mut orders = MinorOrders::new(a);
    if let Some(m) = max_bulk {
        orders = orders.with_bulk_limit(m);
    }
    while orders.advance() {
        let minors = orders.minors();
        let (g, divided) = minors_gcd(r, minors);
        if r.is_zero(&g) {
            next_zero = minors.iter().all(|x| r.is_zero(x));
            break;
        }
        let g = r.normalize(&g);
        if certify && !r.is_unit(&g) {
            all_divide &= minors
                .iter()
                .zip(&divided)
                .all(|(x, &done)| done || r.div_exact(x, &g).is_some());
        }
        let f = r.div_exact(&g, &prev).expect("d_{k-1} divides d_k");
        inv.push(r.normalize(&f));
        prev = g.clone();
        det.push(g);
    }
    if orders.stopped_by_limit() {
        return Ok(None);
    }
    let cert = certify.then(|| {
        let rank = det.len();
        let chain = inv
            .windows(2)
            .all(|w| r.div_exact(&w[1], &w[0]).is_some());
        Certificate {
            checks: vec![
                Check {
                    property: "d_k divides every k×k minor".into(),
                    ok: all_divide,
                    detail: format!("checked by exact division for k = 1..{rank}"),
                },
                Check {
                    property: "rank".into(),
                    ok: next_zero,
                    detail: format!("rank {rank}: every minor of order {} vanishes", rank + 1),
                },
                Check {
                    property: "divisibility f1 | f2 | …".into(),
                    ok: chain,
                    detail: "each invariant factor divides the next".into(),
                },
            ],
        }
    });
    Ok(Some((
        Divisors {
            determinantal: det,
            invariant: inv,
        },
        cert,
    )))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn minor_counts_do_not_overflow() {
        assert_eq!(binom(10, 5), 252);
        assert_eq!(minor_count(2, 2), 5);
        // Σ C(10,k)² = C(20,10) − 1
        assert_eq!(minor_count(10, 10), 184_755);
        // Σ C(66,k)² = C(132,66) − 1 ≈ 3.8e38 > u128::MAX: saturates.
        assert_eq!(minor_count(66, 66), u128::MAX);
        assert!(minor_count(60, 60) < u128::MAX);
        let e = TooManyMinors {
            needed: u128::MAX,
            rows: 66,
            cols: 66,
            limit: 200_000,
        };
        assert!(e.to_string().contains("more than 3.4e38 minors of a 66×66"));
    }
}
