//! Modular gcds over Q: Brown's dense modular algorithm for
//! multivariate polynomials ([`mpoly_gcd`]) and the small-prime modular
//! gcd for Q\[x\] ([`qx_gcd`]). Images are computed over Z_p (p < 2^62) —
//! multivariate ones by evaluation/interpolation of the least significant
//! variable, recursively, down to Euclid in Z_p\[x\] — combined by the
//! Chinese remainder theorem and accepted only after exact trial division
//! over Z, so a returned gcd is always exact; `None` asks the caller to use
//! its fallback (the primitive PRS of [`super::gcd`]). Owns the algorithms,
//! not the arithmetic of [`super::modular`] nor the representations.

use super::modular::{self as zp, Fp, Points, UP, crt, primes, symmetric};
use super::mpoly::{MPoly, Monomial};
use super::rational::Q;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::collections::BTreeMap;
use std::collections::btree_map::Entry;

/// Sparse polynomial over Z_p: terms in descending lexicographic order,
/// no zero coefficients (the layout of [`MPoly`]).
type SP = Vec<(Monomial, u64)>;

/// Recursive view: monomials in the leading variables (the last active
/// variable's exponent zeroed), each with a dense coefficient in Z_p[last].
type RP = Vec<(Monomial, UP)>;

/// Give up on a prime after this many unlucky evaluation points in a row.
const MAX_BAD_POINTS: usize = 64;

/// Give up (and let the caller fall back) after this many primes.
const MAX_PRIMES: usize = 400;

fn to_recursive(a: &SP, last: usize) -> RP {
    let mut map: BTreeMap<Monomial, UP> = BTreeMap::new();
    for (m, c) in a {
        let mut m2 = m.clone();
        let k = std::mem::replace(&mut m2[last], 0) as usize;
        let e = map.entry(m2).or_default();
        if e.len() <= k {
            e.resize(k + 1, 0);
        }
        e[k] = *c;
    }
    map.into_iter().rev().collect()
}

fn from_recursive(a: &RP, last: usize) -> SP {
    let mut out: SP = Vec::new();
    for (m, u) in a {
        for (k, &c) in u.iter().enumerate().rev() {
            if c != 0 {
                let mut m2 = m.clone();
                m2[last] = k as u32;
                out.push((m2, c));
            }
        }
    }
    // Within one leading monomial the exponents of `last` descend, and the
    // leading monomials descend, so the lex order holds already.
    out
}

fn monic_sp(f: Fp, a: SP) -> SP {
    match a.first() {
        None => a,
        Some((_, l)) => {
            let inv = f.inv(*l);
            a.into_iter().map(|(m, c)| (m, f.mul(c, inv))).collect()
        }
    }
}

/// Evaluates `last = x` in a recursive polynomial.
fn eval_rp(f: Fp, a: &RP, x: u64) -> SP {
    a.iter()
        .filter_map(|(m, u)| {
            let v = zp::eval(f, u, x);
            (v != 0).then(|| (m.clone(), v))
        })
        .collect()
}

/// Monic gcd over Z_p of `a` and `b` in the variables `vars` (ascending
/// indices, i.e. most significant first); `None` if no good evaluation
/// point was found.
fn gcd_zp(f: Fp, a: &SP, b: &SP, vars: &[usize], pts: &mut Points) -> Option<SP> {
    if a.is_empty() {
        return Some(monic_sp(f, b.clone()));
    }
    if b.is_empty() {
        return Some(monic_sp(f, a.clone()));
    }
    let nv = a[0].0.len();
    let Some((&last, rest)) = vars.split_last() else {
        return Some(vec![(vec![0; nv], 1)]);
    };
    let ra = to_recursive(a, last);
    let rb = to_recursive(b, last);
    // Contents in Z_p[last] and primitive parts.
    let content = |r: &RP| {
        r.iter().fold(
            Vec::new(),
            |g: UP, (_, u)| if g.len() == 1 { g } else { zp::gcd(f, &g, u) },
        )
    };
    let (ca, cb) = (content(&ra), content(&rb));
    let c = zp::gcd(f, &ca, &cb);
    let prim = |r: RP, c: &UP| -> RP {
        if c.len() == 1 {
            return r;
        }
        r.into_iter()
            .map(|(m, u)| (m, zp::div_rem(f, &u, c).0))
            .collect()
    };
    let (pa, pb) = (prim(ra, &ca), prim(rb, &cb));
    if rest.is_empty() || pa.len() == 1 && pa[0].0.iter().all(|&e| e == 0) {
        // Univariate in `last` (or one side constant in the leading
        // variables): the gcd is in Z_p[last].
        let g = if rest.is_empty() {
            let ua = pa.first().map(|x| x.1.clone()).unwrap_or_default();
            let ub = pb.first().map(|x| x.1.clone()).unwrap_or_default();
            zp::mul(f, &zp::gcd(f, &ua, &ub), &c)
        } else {
            c
        };
        return Some(monic_sp(f, from_recursive(&vec![(vec![0; nv], g)], last)));
    }
    if pb.len() == 1 && pb[0].0.iter().all(|&e| e == 0) {
        return Some(monic_sp(f, from_recursive(&vec![(vec![0; nv], c)], last)));
    }
    let (lca, lcb) = (&pa[0].1, &pb[0].1);
    let gam = zp::gcd(f, lca, lcb);
    let da = pa.iter().map(|(_, u)| u.len()).max().unwrap_or(1) - 1;
    let db = pb.iter().map(|(_, u)| u.len()).max().unwrap_or(1) - 1;
    let bound = da.min(db) + gam.len(); // deg γ + min deg + 1 points
    // Newton interpolation state.
    let mut interp: RP = Vec::new();
    let mut lm: Option<Monomial> = None;
    let mut q: UP = vec![1];
    let mut npts = 0;
    let mut bad = 0;
    while npts < bound {
        let x = pts.next(f);
        if zp::eval(f, lca, x) == 0 || zp::eval(f, lcb, x) == 0 || zp::eval(f, &q, x) == 0 {
            bad += 1;
            if bad > MAX_BAD_POINTS {
                return None;
            }
            continue;
        }
        let h = gcd_zp(f, &eval_rp(f, &pa, x), &eval_rp(f, &pb, x), rest, pts)?;
        let hm = h[0].0.clone();
        if hm.iter().all(|&e| e == 0) {
            // The primitive parts are coprime.
            return Some(monic_sp(f, from_recursive(&vec![(vec![0; nv], c)], last)));
        }
        match lm.as_ref().map(|l| hm.cmp(l)) {
            Some(std::cmp::Ordering::Greater) => {
                bad += 1;
                if bad > MAX_BAD_POINTS {
                    return None;
                }
                continue;
            }
            Some(std::cmp::Ordering::Less) | None => {
                interp.clear();
                q = vec![1];
                npts = 0;
                lm = Some(hm);
            }
            Some(std::cmp::Ordering::Equal) => {}
        }
        let gx = zp::eval(f, &gam, x);
        let h: SP = h.into_iter().map(|(m, v)| (m, f.mul(v, gx))).collect();
        interp = newton_step(f, &interp, &h, &q, x);
        q = zp::mul(f, &q, &[f.neg(x), 1]);
        npts += 1;
    }
    // Primitive part in the leading variables, times the content.
    let cont = content(&interp);
    let g: RP = interp
        .into_iter()
        .map(|(m, u)| (m, zp::mul(f, &zp::div_rem(f, &u, &cont).0, &c)))
        .collect();
    Some(monic_sp(f, from_recursive(&g, last)))
}

/// `C + q·(h − C(x))/q(x)`: the interpolant through one more point.
fn newton_step(f: Fp, c: &RP, h: &SP, q: &UP, x: u64) -> RP {
    let qinv = f.inv(zp::eval(f, q, x));
    let mut map: BTreeMap<Monomial, UP> = c.iter().cloned().collect();
    let hmap: BTreeMap<&Monomial, u64> = h.iter().map(|(m, v)| (m, *v)).collect();
    let keys: Vec<Monomial> = map
        .keys()
        .cloned()
        .chain(h.iter().map(|(m, _)| m.clone()))
        .collect();
    for k in keys {
        let old = map.get(&k).cloned().unwrap_or_default();
        let hv = hmap.get(&k).copied().unwrap_or(0);
        let d = f.mul(f.sub(hv, zp::eval(f, &old, x)), qinv);
        if d == 0 {
            continue;
        }
        let new = zp::add(f, &old, &zp::scale(f, q, d));
        if new.is_empty() {
            map.remove(&k);
        } else {
            map.insert(k, new);
        }
    }
    map.into_iter().rev().collect()
}

/// Integer coefficients of `u·a` and `u`, `u` making them coprime integers.
fn integer_terms(a: &MPoly) -> (Vec<(Monomial, BigInt)>, Q) {
    let u = a.integer_scale();
    let t = a
        .terms()
        .iter()
        .map(|(m, c)| (m.clone(), (c * &u).to_integer()))
        .collect();
    (t, u)
}

fn reduce_terms(f: Fp, a: &[(Monomial, BigInt)]) -> SP {
    a.iter()
        .filter_map(|(m, c)| {
            let r = f.reduce(c);
            (r != 0).then(|| (m.clone(), r))
        })
        .collect()
}

/// The gcd of two nonzero multivariate polynomials over Q by Brown's
/// modular algorithm, normalised like [`super::gcd::gcd`] (coprime integer
/// coefficients, positive leading coefficient). `None` if the algorithm
/// gave up; a returned value has passed exact trial division.
pub fn mpoly_gcd(a: &MPoly, b: &MPoly) -> Option<MPoly> {
    mpoly_gcd_cofactors(a, b).map(|(g, _, _)| g)
}

/// Like [`mpoly_gcd`], with the cofactors: `(g, a/g, b/g)`.
pub fn mpoly_gcd_cofactors(a: &MPoly, b: &MPoly) -> Option<(MPoly, MPoly, MPoly)> {
    let n = a.nvars();
    let (ia, ua) = integer_terms(a);
    let (ib, ub) = integer_terms(b);
    let (la, lb) = (&ia.first()?.1, &ib.first()?.1);
    let gamma = la.gcd(lb);
    let vars: Vec<usize> = (0..n)
        .filter(|&v| a.contains_var(v) || b.contains_var(v))
        .collect();
    let mut pts = Points::new(0x9E37_79B9_7F4A_7C15);
    let mut acc: Option<(Monomial, BTreeMap<Monomial, BigInt>, BigInt)> = None;
    let mut last_candidate: Option<Vec<(Monomial, BigInt)>> = None;
    for p in primes().take(MAX_PRIMES) {
        let f = Fp::new(p);
        if f.reduce(la) == 0 || f.reduce(lb) == 0 {
            continue;
        }
        let Some(g) = gcd_zp(
            f,
            &reduce_terms(f, &ia),
            &reduce_terms(f, &ib),
            &vars,
            &mut pts,
        ) else {
            continue;
        };
        let lm = g[0].0.clone();
        if lm.iter().all(|&e| e == 0) {
            return Some((MPoly::one(n), a.clone(), b.clone()));
        }
        let gp = f.reduce(&gamma);
        match &mut acc {
            Some((l, _, _)) if lm > *l => continue, // unlucky prime
            Some((l, map, m)) if lm == *l => {
                let minv = f.inv(f.reduce(m));
                let img: BTreeMap<&Monomial, u64> = g.iter().map(|(k, v)| (k, *v)).collect();
                let keys: Vec<Monomial> = map
                    .keys()
                    .cloned()
                    .chain(img.keys().map(|k| (*k).clone()))
                    .collect();
                let mut changed = false;
                for k in keys {
                    let old = map.get(&k).cloned().unwrap_or_default();
                    let r = f.mul(img.get(&k).copied().unwrap_or(0), gp);
                    let new = symmetric(&crt(&old, m, r, f, minv), &(&*m * p));
                    if new != old {
                        changed = true;
                    }
                    map.insert(k, new);
                }
                *m *= p;
                if changed {
                    last_candidate = None;
                    continue;
                }
            }
            _ => {
                let map = g
                    .iter()
                    .map(|(k, v)| {
                        (
                            k.clone(),
                            symmetric(&BigInt::from(f.mul(*v, gp)), &BigInt::from(p)),
                        )
                    })
                    .collect();
                acc = Some((lm, map, BigInt::from(p)));
                continue;
            }
        }
        // Stable under one more prime: try the candidate.
        let (_, map, _) = acc.as_ref()?;
        let cand = primitive_terms(map);
        if last_candidate.as_ref() == Some(&cand) {
            continue;
        }
        if let Some(qa) = int_div_terms(&ia, &cand)
            && let Some(qb) = int_div_terms(&ib, &cand)
        {
            let to_q = |t: &[(Monomial, BigInt)], u: &Q| {
                MPoly::from_sorted_terms(
                    n,
                    t.iter()
                        .map(|(m, c)| (m.clone(), Q::from_integer(c.clone()) / u))
                        .collect(),
                )
            };
            let one = Q::one();
            return Some((to_q(&cand, &one), to_q(&qa, &ua), to_q(&qb, &ub)));
        }
        last_candidate = Some(cand);
    }
    None
}

/// The primitive integer polynomial with positive leading coefficient of a
/// CRT image (descending terms, zeros dropped).
fn primitive_terms(map: &BTreeMap<Monomial, BigInt>) -> Vec<(Monomial, BigInt)> {
    let terms: Vec<(Monomial, BigInt)> = map
        .iter()
        .rev()
        .filter(|(_, c)| !c.is_zero())
        .map(|(m, c)| (m.clone(), c.clone()))
        .collect();
    let mut g = terms.iter().fold(BigInt::zero(), |g, (_, c)| g.gcd(c));
    if terms.first().is_some_and(|(_, c)| c.is_negative()) {
        g = -g;
    }
    terms.into_iter().map(|(m, c)| (m, c / &g)).collect()
}

/// Exact quotient of integer polynomials (descending lex terms), if `d`
/// divides `a` over Z: the remainder is kept in an ordered map, so each
/// quotient term costs `#d` updates instead of a full subtraction.
fn int_div_terms(
    a: &[(Monomial, BigInt)],
    d: &[(Monomial, BigInt)],
) -> Option<Vec<(Monomial, BigInt)>> {
    let (dm, dc) = d.first()?;
    let mut r: BTreeMap<Monomial, BigInt> = a.iter().cloned().collect();
    let mut q = Vec::new();
    while let Some((rm, rc)) = r.pop_last() {
        if !rm.iter().zip(dm).all(|(x, y)| x >= y) {
            return None;
        }
        let (c, rem) = rc.div_rem(dc);
        if !rem.is_zero() {
            return None;
        }
        let m: Monomial = rm.iter().zip(dm).map(|(x, y)| x - y).collect();
        for (tm, tc) in &d[1..] {
            let key: Monomial = m.iter().zip(tm).map(|(x, y)| x + y).collect();
            match r.entry(key) {
                Entry::Occupied(mut o) => {
                    *o.get_mut() -= &c * tc;
                    if o.get().is_zero() {
                        o.remove();
                    }
                }
                Entry::Vacant(v) => {
                    v.insert(-(&c * tc));
                }
            }
        }
        q.push((m, c));
    }
    Some(q)
}

/// Monic gcd over Q of two univariate integer polynomials (lowest
/// coefficient first, nonzero), by images mod word-size primes, CRT and
/// exact trial division; returns the primitive integer gcd with positive
/// leading coefficient. `None` if it gave up.
pub fn qx_gcd(a: &[BigInt], b: &[BigInt]) -> Option<Vec<BigInt>> {
    let (la, lb) = (a.last()?, b.last()?);
    let gamma = la.gcd(lb);
    let mut acc: Option<(usize, Vec<BigInt>, BigInt)> = None;
    let mut tried: Option<Vec<BigInt>> = None;
    for p in primes().take(MAX_PRIMES) {
        let f = Fp::new(p);
        if f.reduce(la) == 0 || f.reduce(lb) == 0 {
            continue;
        }
        let ap: UP = a.iter().map(|c| f.reduce(c)).collect();
        let bp: UP = b.iter().map(|c| f.reduce(c)).collect();
        let g = zp::gcd(f, &ap, &bp);
        let d = g.len() - 1;
        if d == 0 {
            return Some(vec![BigInt::one()]);
        }
        let gp = f.reduce(&gamma);
        let img: Vec<u64> = g.iter().map(|&c| f.mul(c, gp)).collect();
        match &mut acc {
            Some((dd, _, _)) if d > *dd => continue,
            Some((dd, cs, m)) if d == *dd => {
                let minv = f.inv(f.reduce(m));
                let mp = &*m * p;
                let mut changed = false;
                for (c, &r) in cs.iter_mut().zip(&img) {
                    let new = symmetric(&crt(c, m, r, f, minv), &mp);
                    if new != *c {
                        changed = true;
                        *c = new;
                    }
                }
                *m = mp;
                if changed {
                    continue;
                }
            }
            _ => {
                let pb = BigInt::from(p);
                acc = Some((
                    d,
                    img.iter()
                        .map(|&c| symmetric(&BigInt::from(c), &pb))
                        .collect(),
                    pb,
                ));
                continue;
            }
        }
        let (_, cs, _) = acc.as_ref()?;
        let cand = primitive_int(cs);
        if tried.as_ref() == Some(&cand) {
            continue;
        }
        if int_divides(&cand, a) && int_divides(&cand, b) {
            return Some(cand);
        }
        tried = Some(cand);
    }
    None
}

/// The inverse of `a` modulo `m` over Q for integer polynomials (lowest
/// coefficient first, `deg m ≥ 1`): `(S, R)` with integer `S` and
/// `R = Res(a, m) ≠ 0` such that `(S/R)·a ≡ 1 (mod m)`, `deg S < deg m`.
/// S and R are minors of the Sylvester matrix, so images modulo primes
/// whose product exceeds twice the Hadamard bound determine them exactly.
/// `None` if `a` looks non-invertible (the caller decides exactly).
pub fn qx_inverse(a: &[BigInt], m: &[BigInt]) -> Option<(Vec<BigInt>, BigInt)> {
    let (la, lm) = (a.last()?, m.last()?);
    let (da, dm) = (a.len() - 1, m.len() - 1);
    if dm == 0 {
        return None;
    }
    let norm = |v: &[BigInt]| -> f64 {
        // log2 of the Euclidean norm, from each coefficient's bit length.
        let mx = v.iter().map(|c| c.bits()).max().unwrap_or(0) as f64;
        mx + 0.5 * (v.len() as f64).log2() + 1.0
    };
    let bits = dm as f64 * norm(a) + da as f64 * norm(m) + 2.0;
    let mut s_acc: Vec<BigInt> = vec![BigInt::zero(); dm];
    let mut r_acc = BigInt::zero();
    let mut modulus = BigInt::one();
    let mut zeros = 0;
    for p in primes() {
        let f = Fp::new(p);
        if f.reduce(la) == 0 || f.reduce(lm) == 0 {
            continue;
        }
        let ap: UP = a.iter().map(|c| f.reduce(c)).collect();
        let mp: UP = m.iter().map(|c| f.reduce(c)).collect();
        let Some((s, r)) = zp::inverse_and_resultant(f, &ap, &mp) else {
            zeros += 1;
            if zeros > 8 {
                return None;
            }
            continue;
        };
        let minv = f.inv(f.reduce(&modulus));
        for (k, c) in s_acc.iter_mut().enumerate() {
            let v = f.mul(s.get(k).copied().unwrap_or(0), r);
            *c = crt(c, &modulus, v, f, minv);
        }
        r_acc = crt(&r_acc, &modulus, r, f, minv);
        modulus *= p;
        if modulus.bits() as f64 > bits {
            let mut sv: Vec<BigInt> = s_acc.iter().map(|c| symmetric(c, &modulus)).collect();
            while sv.last().is_some_and(|c| c.is_zero()) {
                sv.pop();
            }
            let r = symmetric(&r_acc, &modulus);
            return (!r.is_zero()).then_some((sv, r));
        }
    }
    None
}

/// Primitive part with positive leading coefficient.
fn primitive_int(c: &[BigInt]) -> Vec<BigInt> {
    let g = c.iter().fold(BigInt::zero(), |g, x| g.gcd(x));
    let s = if c.last().is_some_and(|x| x.is_negative()) {
        -g
    } else {
        g
    };
    c.iter().map(|x| x / &s).collect()
}

/// Whether the integer polynomial `d` (primitive) divides `a` over Z.
pub fn int_divides(d: &[BigInt], a: &[BigInt]) -> bool {
    int_div_exact(a, d).is_some()
}

/// Exact quotient `a / d` over Z, if `d` divides `a` with an integer
/// quotient (a quick check modulo a prime first).
pub fn int_div_exact(a: &[BigInt], d: &[BigInt]) -> Option<Vec<BigInt>> {
    let n = d.len().checked_sub(1)?;
    if a.is_empty() {
        return Some(Vec::new());
    }
    if a.len() < d.len() {
        return None;
    }
    // Fast rejection modulo a prime not dividing the leading coefficient.
    if let Some(p) = primes().take(8).find(|&p| Fp::new(p).reduce(&d[n]) != 0) {
        let f = Fp::new(p);
        let ap: UP = zp::trim(a.iter().map(|c| f.reduce(c)).collect());
        let dp: UP = d.iter().map(|c| f.reduce(c)).collect();
        if !zp::div_rem(f, &ap, &dp).1.is_empty() {
            return None;
        }
    }
    let mut r: Vec<BigInt> = a.to_vec();
    let mut q = vec![BigInt::zero(); a.len() - n];
    let ld = &d[n];
    for i in (0..q.len()).rev() {
        let (c, rem) = r[i + n].div_rem(ld);
        if !rem.is_zero() {
            return None;
        }
        if !c.is_zero() {
            for j in 0..n {
                r[i + j] -= &c * &d[j];
            }
        }
        q[i] = c;
    }
    r[..n].iter().all(|x| x.is_zero()).then_some(q)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::gcd::gcd;
    use crate::algebra::rational::{q, qi};

    fn vars(n: usize) -> Vec<MPoly> {
        (0..n).map(|i| MPoly::var(i, n)).collect()
    }

    #[test]
    fn brown_finds_the_common_factor() {
        let v = vars(3);
        let (x, y, z) = (&v[0], &v[1], &v[2]);
        let g = x * y - z.scale(&qi(3)) + MPoly::one(3).scale(&q(1, 2));
        let a = &g * &(x + y).pow(3) * (y * z + x.scale(&qi(7)));
        let b = &g * &(x * z - y).pow(2) * (y + z);
        assert_eq!(mpoly_gcd(&a, &b), Some(g.primitive_normal()));
        assert_eq!(gcd(&a, &b), g.primitive_normal());
    }

    #[test]
    fn brown_with_contents_and_big_coefficients() {
        let v = vars(2);
        let (x, y) = (&v[0], &v[1]);
        let big = MPoly::constant(Q::from_integer(BigInt::from(10).pow(40) + 7), 2);
        let g = &(y * y + big.clone()) * &(x - y.pow(3));
        let a = &g * &(x + &big);
        let b = &g * &(y - &MPoly::one(2)) * (x.pow(2) + MPoly::one(2));
        assert_eq!(mpoly_gcd(&a, &b), Some(g.primitive_normal()));
        let c = &(x + y) * &(x - y);
        assert_eq!(mpoly_gcd(&c, &(x.pow(3) + y)), Some(MPoly::one(2)));
    }

    #[test]
    fn modular_inverse_is_exact() {
        let bi = |v: &[i64]| v.iter().map(|&c| BigInt::from(c)).collect::<Vec<_>>();
        // a = 3x^2 − 7x + 11, m = 5x^3 + 2x − 9 (coprime)
        let (a, m) = (bi(&[11, -7, 3]), bi(&[-9, 2, 0, 5]));
        let (s, r) = qx_inverse(&a, &m).unwrap();
        // S·a − R ≡ 0 (mod m) over Q: check with the exact Q[x] ring.
        use crate::algebra::qx::{QPoly, QxRing};
        use crate::algebra::ring::Ring;
        let q = QxRing::new("x");
        let lhs = q.sub(
            &q.mul(&QPoly::from_ints(s), &QPoly::from_ints(a.clone())),
            &QPoly::from_ints(vec![r]),
        );
        assert!(q.rem(&lhs, &QPoly::from_ints(m.clone())).is_zero());
        // Not invertible: a common factor x − 1.
        assert!(qx_inverse(&bi(&[-1, 1]), &bi(&[-1, 0, 1])).is_none());
    }

    #[test]
    fn univariate_modular_gcd() {
        let bi = |v: &[i64]| v.iter().map(|&c| BigInt::from(c)).collect::<Vec<_>>();
        // (2x + 3)(x^2 + 1)  and  (2x + 3)(x - 5)^2 · 10^30
        let e = BigInt::from(10).pow(30);
        let a = bi(&[3, 2, 3, 2]);
        let b: Vec<BigInt> = bi(&[75, 20, -17, 2]).into_iter().map(|c| c * &e).collect();
        assert_eq!(qx_gcd(&a, &b), Some(bi(&[3, 2])));
        assert_eq!(qx_gcd(&bi(&[1, 1]), &bi(&[-1, 1])), Some(bi(&[1])));
    }
}
