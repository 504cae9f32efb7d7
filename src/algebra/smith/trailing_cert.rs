//! The exact certificate of the trailing (Hermite-basis) route's
//! transforms ([`super::trailing::trailing_hermite`]): U, D, V and V⁻¹
//! over Q\[x\], without `U⁻¹`. It recomputes everything it states from
//! A and the four matrices and trusts nothing from the route:
//!
//! 1. `V·V⁻¹ = I` exactly with V⁻¹ polynomial: det V is a nonzero
//!    constant, and (square matrices over the field Q(x)) `V⁻¹·V = I`.
//! 2. `U·A = D·V⁻¹` exactly (integer products with cleared
//!    denominators); with 1 this is `U·A·V = D`, without multiplying by
//!    V's large columns.
//! 3. D diagonal with monic nonzero entries, each dividing the next.
//! 4. `deg(det A mod p) = Σ deg D_ii` for a word prime p dividing no
//!    denominator of A (`hermite_cert::det_degree_mod`): reduction
//!    mod p cannot raise a degree, so `deg det A ≥ Σ deg D_ii`. From 1 and
//!    2, `det U·det A·det V = det D ≠ 0` with det U a polynomial and det V
//!    a nonzero constant, so `deg det U = Σ deg D_ii − deg det A ≤ 0`:
//!    det U is a nonzero constant and U is unimodular.
//!
//! This module must not compute decompositions, choose modes or print.

use super::certify::{Certificate, Check, mul_cleared};
use super::small::SmallDecomposition;
use crate::algebra::matrix::Matrix;
use crate::algebra::modular;
use crate::algebra::qx::QxRing;
use crate::algebra::ring::{GcdDomain, Ring};

fn push(cert: &mut Certificate, property: &str, ok: bool, detail: String) {
    cert.checks.push(Check {
        property: property.to_string(),
        ok,
        detail,
    });
}

/// `V·V⁻¹ = I`, summing only products of nonzero entries after clearing
/// denominators per line ([`mul_cleared`] on the nonzero pattern).
fn is_inverse(v: &Matrix<QxRing>, v_inv: &Matrix<QxRing>) -> bool {
    let n = v.rows();
    match mul_cleared(v, v_inv) {
        Some(p) => p == Matrix::identity(v.ring.clone(), n),
        None => false,
    }
}

/// `D·V⁻¹` for a diagonal D (row i of V⁻¹ times `D_ii`).
fn diag_times(d: &Matrix<QxRing>, m: &Matrix<QxRing>) -> Matrix<QxRing> {
    let r = &m.ring;
    let mut out = m.clone();
    for i in 0..m.rows() {
        let di = d.get(i, i);
        if r.is_one(di) {
            continue;
        }
        for j in 0..m.cols() {
            let e = m.get(i, j);
            if !e.is_zero() {
                out.set(i, j, r.mul(di, e));
            }
        }
    }
    out
}

/// Certifies `s` as a Smith decomposition of the square `a` over Q\[x\] as
/// described in the module documentation.
pub fn certify_transforms(a: &Matrix<QxRing>, s: &SmallDecomposition) -> Certificate {
    let r = &a.ring;
    let n = a.rows();
    let mut cert = Certificate { checks: Vec::new() };
    let shapes = a.cols() == n
        && [&s.u, &s.v, &s.v_inv, &s.d]
            .iter()
            .all(|m| m.rows() == n && m.cols() == n);
    push(
        &mut cert,
        "shapes",
        shapes,
        format!("A, U, D, V and V⁻¹ are {n}×{n} (square)"),
    );
    if !shapes {
        return cert;
    }
    let diag = s.d.diagonal();
    let diag_ok = s.d.is_diagonal() && diag.iter().all(|e| !e.is_zero());
    let vinv = is_inverse(&s.v, &s.v_inv);
    let prod =
        vinv && diag_ok && mul_cleared(&s.u, a).is_some_and(|ua| ua == diag_times(&s.d, &s.v_inv));
    push(
        &mut cert,
        "U·A·V = D",
        prod,
        if prod {
            "holds exactly (checked as U·A = D·V⁻¹ with V·V⁻¹ = I)".to_string()
        } else {
            "not established (U·A differs from D·V⁻¹, or V·V⁻¹ is not I)".to_string()
        },
    );
    push(
        &mut cert,
        "D diagonal",
        diag_ok,
        if diag_ok {
            "yes, with a nonzero diagonal".to_string()
        } else {
            "D has a nonzero off-diagonal entry or a zero on its diagonal".to_string()
        },
    );
    push(
        &mut cert,
        "V unimodular",
        vinv,
        if vinv {
            "V·V⁻¹ = I for a polynomial V⁻¹, so det V is a unit".to_string()
        } else {
            "V times the recorded inverse is not I".to_string()
        },
    );
    let total: usize = diag.iter().map(|e| e.degree().unwrap_or(0)).sum();
    let found = modular::primes()
        .take(3)
        .find_map(|p| super::hermite_cert::det_degree_mod(a, p).map(|d| (d, p)));
    let u_ok = prod && found.is_some_and(|(d, _)| d == total);
    push(
        &mut cert,
        "U unimodular",
        u_ok,
        match found {
            Some((d, p)) if u_ok => format!(
                "det U·det A·det V = det D with det V a nonzero constant; deg(det A mod p) = {d} for p = {p} (values at the points 0, …, N), so deg det A ≥ {d} = deg det D and det U is a nonzero constant"
            ),
            Some((d, p)) => format!(
                "not established: deg(det A mod {p}) = {d}, Σ deg D_ii = {total}, or U·A·V = D not established"
            ),
            None => "not established: no prime gave det A mod p".to_string(),
        },
    );
    push(
        &mut cert,
        "zeros last",
        diag_ok,
        format!("{n} nonzero invariant factor(s)"),
    );
    let normal = diag_ok && diag.iter().all(|e| r.normalize(e) == *e);
    push(
        &mut cert,
        "invariant factors normalised",
        normal,
        if normal {
            "each nonzero diagonal entry is in normal form (monic / primitive)".to_string()
        } else {
            "a diagonal entry is not monic".to_string()
        },
    );
    let divides = diag_ok && diag.windows(2).all(|w| r.div_exact(&w[1], &w[0]).is_some());
    push(
        &mut cert,
        "divisibility f1 | f2 | …",
        divides,
        if divides {
            "each invariant factor divides the next".to_string()
        } else {
            "an invariant factor does not divide the next".to_string()
        },
    );
    cert
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::qx::QPoly;
    use crate::algebra::smith::nonsingular::{FastPath, try_fast};
    use crate::algebra::smith::trailing::{tests::planted, trailing_hermite};
    use num_bigint::BigInt;

    fn p(c: &[i64]) -> QPoly {
        QPoly::from_ints(c.iter().map(|&x| BigInt::from(x)).collect())
    }

    fn decomposition(n: usize) -> (Matrix<QxRing>, SmallDecomposition) {
        let a = planted(n, &[p(&[-1, 1]), p(&[-2, 1, 1])], 5);
        let Some(FastPath::NoHermite { c, b }) = try_fast(&a, u64::MAX) else {
            panic!("two non-trivial factors");
        };
        let dec = trailing_hermite(&a, &c, &b).expect("the trailing route applies");
        (a, dec)
    }

    fn failing(cert: &Certificate) -> Vec<String> {
        cert.failures().map(|c| c.property.clone()).collect()
    }

    #[test]
    fn the_route_is_certified_and_tampering_is_caught() {
        let (a, dec) = decomposition(6);
        let r = a.ring.clone();
        assert!(certify_transforms(&a, &dec).verified());
        // A changed entry of U breaks U·A·V = D.
        let mut bad = dec.clone_parts();
        let e = r.add(bad.u.get(0, 0), &r.one());
        bad.u.set(0, 0, e);
        assert!(failing(&certify_transforms(&a, &bad)).contains(&"U·A·V = D".to_string()));
        // A V⁻¹ that is not V's inverse.
        let mut bad = dec.clone_parts();
        let e = r.add(bad.v_inv.get(0, 1), &r.one());
        bad.v_inv.set(0, 1, e);
        assert!(failing(&certify_transforms(&a, &bad)).contains(&"V unimodular".to_string()));
        // x·U with x·D: U·A·V = D still holds and D is still a chain, so
        // only the degree argument rejects it (det U = x^n).
        let mut bad = dec.clone_parts();
        let x = p(&[0, 1]);
        for i in 0..6 {
            for j in 0..6 {
                let e = r.mul(bad.u.get(i, j), &x);
                bad.u.set(i, j, e);
            }
            let e = r.mul(bad.d.get(i, i), &x);
            bad.d.set(i, i, e);
        }
        let cert = certify_transforms(&a, &bad);
        assert_eq!(failing(&cert), vec!["U unimodular".to_string()]);
    }

    impl SmallDecomposition {
        fn clone_parts(&self) -> SmallDecomposition {
            SmallDecomposition {
                d: self.d.clone(),
                u: self.u.clone(),
                v: self.v.clone(),
                v_inv: self.v_inv.clone(),
            }
        }
    }
}
