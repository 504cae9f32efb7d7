//! Multivariate gcd over Q. The main route is Brown's modular algorithm
//! ([`super::modgcd::mpoly_gcd`], exact by trial division); the fallback,
//! used only if it gives up, is the recursive primitive polynomial remainder
//! sequence: a polynomial is viewed in its most significant variable with
//! coefficients in Q[remaining variables]; contents are gcds of those
//! coefficients (recursively), primitive parts go through pseudo-remainders.
//! This module owns gcd, content and pseudo-remainder, nothing else.

use super::mpoly::MPoly;
use super::rational::Q;
use num_traits::One;

/// Pseudo-remainder of `a` by `b` with respect to variable `v`: a multiple
/// `c * a` (with `c` a power-product of leading coefficients of `b`, free of
/// `v`) minus a multiple of `b`, of degree in `v` below that of `b`.
pub fn prem(a: &MPoly, b: &MPoly, v: usize) -> MPoly {
    let Some(db) = b.degree_in(v) else {
        return a.clone();
    };
    let lb = b.lc_in(v);
    let mut r = a.clone();
    while let Some(dr) = r.degree_in(v) {
        if dr < db || r.is_zero() {
            break;
        }
        let lr = r.lc_in(v);
        r = &lb * &r - (&lr * b).shift(v, dr - db);
        // Keep rational coefficients small: scaling by a nonzero constant
        // does not change what the remainder sequence computes.
        let u = r.integer_scale();
        r = r.scale(&u);
    }
    r
}

/// Gcd of the coefficients of `a` with respect to `v` (normalised).
pub fn content_in(a: &MPoly, v: usize) -> MPoly {
    let mut g = MPoly::zero(a.nvars());
    for c in a.coeffs_in(v) {
        if c.is_zero() {
            continue;
        }
        g = gcd(&g, &c);
        if g.is_nonzero_constant() {
            return g;
        }
    }
    g
}

/// Primitive part of `a` with respect to `v` (`a / content_in(a, v)`).
pub fn primitive_part_in(a: &MPoly, v: usize) -> MPoly {
    if a.is_zero() {
        return a.clone();
    }
    let c = content_in(a, v);
    a.div_exact(&c)
        .expect("content divides the polynomial")
        .primitive_normal()
}

/// The largest monomial dividing `p` (nonzero): each variable's smallest
/// exponent over the terms.
fn monomial_content(p: &MPoly) -> Vec<u32> {
    let mut e = p.terms()[0].0.clone();
    for (t, _) in &p.terms()[1..] {
        for (x, y) in e.iter_mut().zip(t) {
            *x = (*x).min(*y);
        }
    }
    e
}

/// `p / x^m` for a monomial `x^m` dividing `p`.
fn div_monomial(p: &MPoly, m: &[u32]) -> MPoly {
    let terms = p
        .terms()
        .iter()
        .map(|(t, c)| (t.iter().zip(m).map(|(x, y)| x - y).collect(), c.clone()))
        .collect();
    MPoly::from_sorted_terms(p.nvars(), terms)
}

/// The greatest common divisor of `a` and `b`, normalised to coprime integer
/// coefficients with a positive leading coefficient (so `gcd(0, 0) = 0` and
/// the gcd of nonzero constants is `1`).
///
/// ```
/// use lambdamat::algebra::{gcd::gcd, mpoly::MPoly};
/// let (x, y) = (MPoly::var(0, 2), MPoly::var(1, 2));
/// let g = gcd(&((&x - &y) * (&x + &y)), &((&x - &y).pow(2)));
/// assert_eq!(g.to_string_with(&["x", "y"]), "x - y");
/// ```
pub fn gcd(a: &MPoly, b: &MPoly) -> MPoly {
    if a.is_zero() {
        return b.primitive_normal();
    }
    if b.is_zero() {
        return a.primitive_normal();
    }
    // Associates (a line of one denominator, an lcm that already holds
    // the next factor) need no gcd.
    let same_monomials = a.terms().len() == b.terms().len()
        && a.terms().iter().zip(b.terms()).all(|((x, _), (y, _))| x == y);
    if same_monomials {
        let pa = a.primitive_normal();
        if pa == b.primitive_normal() {
            return pa;
        }
    }
    // Monomial factors apart: gcd(x^α·a', x^β·b') = x^min(α,β)·gcd(a', b')
    // when no variable divides a' or b' (the variables are primes). The
    // images of a' and b' then have no common monomial either, so a
    // coprime pair is seen as such at once.
    let (ma, mb) = (monomial_content(a), monomial_content(b));
    if ma.iter().chain(&mb).any(|&e| e > 0) {
        let m: Vec<u32> = ma.iter().zip(&mb).map(|(x, y)| *x.min(y)).collect();
        let g = gcd(&div_monomial(a, &ma), &div_monomial(b, &mb));
        return &g * &MPoly::monomial(m, Q::one());
    }
    let n = a.nvars();
    let v = match (a.main_var(), b.main_var()) {
        (None, _) | (_, None) => return MPoly::one(n),
        (Some(x), Some(y)) => x.min(y),
    };
    if let Some(g) = super::modgcd::mpoly_gcd(a, b) {
        return g;
    }
    if !a.contains_var(v) {
        return gcd(a, &content_in(b, v));
    }
    if !b.contains_var(v) {
        return gcd(&content_in(a, v), b);
    }
    let ca = content_in(a, v);
    let cb = content_in(b, v);
    let c = gcd(&ca, &cb);
    let pa = a.div_exact(&ca).expect("content divides");
    let pb = b.div_exact(&cb).expect("content divides");
    let g = primitive_prs(pa, pb, v);
    (&c * &g).primitive_normal()
}

/// Gcd of two polynomials primitive in `v` by the primitive PRS.
fn primitive_prs(a: MPoly, b: MPoly, v: usize) -> MPoly {
    let (mut r0, mut r1) = if a.degree_in(v) >= b.degree_in(v) {
        (a, b)
    } else {
        (b, a)
    };
    loop {
        if r1.degree_in(v) == Some(0) {
            return MPoly::one(r0.nvars());
        }
        let r = prem(&r0, &r1, v);
        if r.is_zero() {
            return primitive_part_in(&r1, v);
        }
        r0 = r1;
        r1 = primitive_part_in(&r, v);
    }
}

/// `(g, a/g, b/g)` with `g = gcd(a, b)` normalised as in [`gcd`]; the
/// modular route returns the cofactors from its trial division, so callers
/// that reduce fractions divide only once.
pub fn gcd_cofactors(a: &MPoly, b: &MPoly) -> (MPoly, MPoly, MPoly) {
    if !a.is_zero()
        && !b.is_zero()
        && a.main_var().is_some()
        && b.main_var().is_some()
        && let Some(r) = super::modgcd::mpoly_gcd_cofactors(a, b)
    {
        return r;
    }
    let g = gcd(a, b);
    if g.is_zero() {
        return (g, a.clone(), b.clone());
    }
    let qa = a.div_exact(&g).expect("gcd divides");
    let qb = b.div_exact(&g).expect("gcd divides");
    (g, qa, qb)
}

/// Least common multiple (normalised); zero if either is zero.
pub fn lcm(a: &MPoly, b: &MPoly) -> MPoly {
    if a.is_zero() || b.is_zero() {
        return MPoly::zero(a.nvars());
    }
    // A running lcm usually holds the next factor already (a line's
    // denominators divide one product): one exact division decides it.
    if a.div_exact(b).is_some() {
        return a.primitive_normal();
    }
    let g = gcd(a, b);
    (a * &b.div_exact(&g).expect("gcd divides")).primitive_normal()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::rational::{q, qi};

    fn vars(n: usize) -> Vec<MPoly> {
        (0..n).map(|i| MPoly::var(i, n)).collect()
    }

    #[test]
    fn gcd_of_products_shares_the_common_factor() {
        let v = vars(3);
        let (x, y, z) = (&v[0], &v[1], &v[2]);
        let f = x * y - z.scale(&qi(3)) + MPoly::one(3);
        let a = &f * &(x + y).pow(2);
        let b = &f * &(x * z - y);
        assert_eq!(gcd(&a, &b), f.primitive_normal());
    }

    #[test]
    fn coprime_and_constant_cases() {
        let v = vars(2);
        let (x, y) = (&v[0], &v[1]);
        assert_eq!(gcd(&(x + y), &(x - y)), MPoly::one(2));
        assert_eq!(gcd(&MPoly::constant(q(3, 4), 2), &x.clone()), MPoly::one(2));
        assert_eq!(gcd(&MPoly::zero(2), &x.scale(&qi(-2))), x.clone());
        assert!(gcd(&MPoly::zero(2), &MPoly::zero(2)).is_zero());
    }

    #[test]
    fn a_monomial_gcd_takes_the_smallest_exponents() {
        let v = vars(3);
        let (x, y, z) = (&v[0], &v[1], &v[2]);
        let m = (x.pow(2) * y.clone()).scale(&q(-5, 3));
        // Every term has x and y²; one lacks z.
        let p = &(&(x.pow(3) * y.pow(2)) * z) - &(x * &y.pow(4)).scale(&qi(7));
        assert_eq!(gcd(&m, &p), x * y);
        assert_eq!(gcd(&p, &m), x * y);
        assert_eq!(gcd(&m, &(z + &MPoly::one(3))), MPoly::one(3));
        assert_eq!(gcd(&m, &m.scale(&qi(4))), (x.pow(2) * y.clone()));
        assert_eq!(gcd(&MPoly::zero(3), &m), (x.pow(2) * y.clone()));
    }

    #[test]
    fn content_is_found_in_lower_variables() {
        let v = vars(2);
        let (x, y) = (&v[0], &v[1]);
        // (y^2 - 1) x^2 + (y - 1) x  has content y - 1 in x.
        let p = &(y * y - MPoly::one(2)) * &(x * x) + &(y - &MPoly::one(2)) * x;
        assert_eq!(content_in(&p, 0), (y - &MPoly::one(2)));
        let g = gcd(&p, &(y * y - MPoly::one(2)));
        assert_eq!(g, y - &MPoly::one(2));
    }

    #[test]
    fn gcd_with_rational_coefficients_is_normalised() {
        let v = vars(1);
        let x = &v[0];
        let a = (x - &MPoly::constant(q(1, 2), 1)) * (x + &MPoly::one(1));
        let b = (x - &MPoly::constant(q(1, 2), 1)).scale(&q(7, 3));
        assert_eq!(gcd(&a, &b).to_string_with(&["x"]), "2*x - 1");
    }
}
