//! Invariant factors from determinantal divisors over any gcd domain:
//! `d_k = gcd` of all k×k minors, `f_k = d_k / d_{k-1}`. This is the honest
//! mode over Q[s1..sn] with n ≥ 2, where no unimodular transforms need exist;
//! it is also the independent cross-check of the elimination in tests.
//! Owns only this computation and its certificate.

use super::certify::{Certificate, Check};
use crate::algebra::matrix::Matrix;
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
    "the determinantal-divisor mode would need {needed} minors of a {rows}×{cols} matrix (limit {limit}); name a principal symbol to use the elimination instead"
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

fn binom(n: usize, k: usize) -> u128 {
    (0..k).fold(1u128, |acc, i| acc * (n - i) as u128 / (i as u128 + 1))
}

/// Computes the determinantal divisors and invariant factors of `a`,
/// refusing inputs that would need more than `limit` minors in total.
pub fn determinantal_divisors<R: GcdDomain>(
    a: &Matrix<R>,
    limit: u128,
) -> Result<Divisors<R::Elem>, TooManyMinors> {
    let (m, n) = (a.rows(), a.cols());
    let needed: u128 = (1..=m.min(n)).map(|k| binom(m, k) * binom(n, k)).sum();
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
    for k in 1..=m.min(n) {
        let g = a
            .minors(k)
            .iter()
            .fold(r.zero(), |g, x| if r.is_zero(x) { g } else { r.gcd(&g, x) });
        if r.is_zero(&g) {
            break;
        }
        let g = r.normalize(&g);
        let f = r.div_exact(&g, &prev).expect("d_{k-1} divides d_k");
        inv.push(r.normalize(&f));
        prev = g.clone();
        det.push(g);
    }
    Ok(Divisors {
        determinantal: det,
        invariant: inv,
    })
}

/// Certifies divisors: each `d_k` divides every k×k minor, `d_{k-1}·f_k = d_k`
/// up to a unit, `f_k | f_{k+1}`, and all minors of order rank+1 vanish.
pub fn certify_divisors<R: GcdDomain>(a: &Matrix<R>, dv: &Divisors<R::Elem>) -> Certificate {
    let r = &a.ring;
    let mut checks = Vec::new();
    let mut all_divide = true;
    for (k, d) in dv.determinantal.iter().enumerate() {
        if a.minors(k + 1).iter().any(|x| r.div_exact(x, d).is_none()) {
            all_divide = false;
        }
    }
    checks.push(Check {
        property: "d_k divides every k×k minor".into(),
        ok: all_divide,
        detail: format!(
            "checked by exact division for k = 1..{}",
            dv.determinantal.len()
        ),
    });
    let rank = dv.determinantal.len();
    let next_zero =
        rank >= a.rows().min(a.cols()) || a.minors(rank + 1).iter().all(|x| r.is_zero(x));
    checks.push(Check {
        property: "rank".into(),
        ok: next_zero,
        detail: format!("rank {rank}: every minor of order {} vanishes", rank + 1),
    });
    let mut chain = true;
    for w in dv.invariant.windows(2) {
        if r.div_exact(&w[1], &w[0]).is_none() {
            chain = false;
        }
    }
    checks.push(Check {
        property: "divisibility f1 | f2 | …".into(),
        ok: chain,
        detail: "each invariant factor divides the next".into(),
    });
    Certificate { checks }
}
