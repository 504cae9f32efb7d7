//! Independent certification of a claimed Smith decomposition `U·A·V = D`
//! over any gcd domain. It recomputes everything it states from the
//! matrices alone (products, determinants or inverse products, exact
//! divisions) and never trusts the algorithm that produced them. The same
//! checker explains which property a user-supplied decomposition fails.

use crate::algebra::matrix::Matrix;
use crate::algebra::modular::{self, Fp};
use crate::algebra::qx::{QPoly, QxRing};
use crate::algebra::ring::GcdDomain;
#[cfg(any(test, feature = "internals"))]
use crate::algebra::ring::Ring;
use num_bigint::BigInt;
use num_traits::{One, Signed, ToPrimitive, Zero};
use serde::Serialize;
use std::borrow::Cow;

/// One checked property.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Check {
    /// Short name of the property, e.g. `U·A·V = D`.
    pub property: String,
    /// Whether it holds.
    pub ok: bool,
    /// What was computed, in words (e.g. `det U = -k4 is not a unit of …`).
    pub detail: String,
}

/// The result of checking a decomposition.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Certificate {
    /// Every property checked, in order.
    pub checks: Vec<Check>,
}

impl Certificate {
    /// Whether every property holds.
    pub fn verified(&self) -> bool {
        self.checks.iter().all(|c| c.ok)
    }
    /// The failing checks.
    pub fn failures(&self) -> impl Iterator<Item = &Check> {
        self.checks.iter().filter(|c| !c.ok)
    }
    /// Records one checked property.
    pub(crate) fn push(
        &mut self,
        property: impl Into<String>,
        ok: bool,
        detail: impl Into<String>,
    ) {
        self.checks.push(Check {
            property: property.into(),
            ok,
            detail: detail.into(),
        });
    }
}

/// Evidence that a transform is unimodular.
pub enum Unimodular<'a, R: GcdDomain> {
    /// A claimed inverse: `M·M⁻¹ = I` over the ring proves `det M` is a unit.
    Inverse(&'a Matrix<R>),
    /// Nothing: the determinant is computed (Bareiss) and tested.
    Determinant,
}

/// How a certificate evaluates matrix identities `F1·F2·…·Fk = R`. The
/// default evaluates them in the ring itself; a ring of fractions may clear
/// denominators first and compare over the polynomial ring, which is the
/// same statement and avoids gcds.
pub trait ProductCheck<R: GcdDomain> {
    /// Whether the product of `factors` equals `rhs`.
    fn product_equals(&self, factors: &[&Matrix<R>], rhs: &Matrix<R>) -> bool;
}

/// Evaluates identities directly in the ring.
pub struct Direct;

impl<R: GcdDomain> ProductCheck<R> for Direct {
    fn product_equals(&self, factors: &[&Matrix<R>], rhs: &Matrix<R>) -> bool {
        let mut it = factors.iter();
        let Some(first) = it.next() else {
            return false;
        };
        let mut acc = (*first).clone();
        for f in it {
            match acc.mul(f) {
                Some(m) => acc = m,
                None => return false,
            }
        }
        acc == *rhs
    }
}

/// Checks that `(u, d, v)` is a Smith decomposition of `a` over `a.ring`:
/// shapes, `U·A·V = D` exactly, `D` diagonal, `U` and `V` unimodular, the
/// nonzero diagonal entries normalised and each dividing the next, zeros
/// last.
pub fn certify<R: GcdDomain>(
    a: &Matrix<R>,
    u: &Matrix<R>,
    d: &Matrix<R>,
    v: &Matrix<R>,
    u_evidence: Unimodular<'_, R>,
    v_evidence: Unimodular<'_, R>,
) -> Certificate {
    certify_with(a, u, d, v, u_evidence, v_evidence, &Direct)
}

/// [`certify`] with a chosen way of evaluating the matrix identities.
pub fn certify_with<R: GcdDomain>(
    a: &Matrix<R>,
    u: &Matrix<R>,
    d: &Matrix<R>,
    v: &Matrix<R>,
    u_evidence: Unimodular<'_, R>,
    v_evidence: Unimodular<'_, R>,
    check: &dyn ProductCheck<R>,
) -> Certificate {
    let r = &a.ring;
    let mut c = Certificate { checks: Vec::new() };
    let (m, n) = (a.rows(), a.cols());
    let shapes_ok = u.rows() == m
        && u.cols() == m
        && v.rows() == n
        && v.cols() == n
        && d.rows() == m
        && d.cols() == n;
    c.push(
        "shapes",
        shapes_ok,
        format!(
            "A is {m}×{n}, U is {}×{}, D is {}×{}, V is {}×{}",
            u.rows(),
            u.cols(),
            d.rows(),
            d.cols(),
            v.rows(),
            v.cols()
        ),
    );
    if !shapes_ok {
        return c;
    }
    let prod_ok = check.product_equals(&[u, a, v], d);
    let detail = if prod_ok {
        "holds exactly".to_string()
    } else {
        let uav = u.mul(a).and_then(|ua| ua.mul(v)).expect("shapes checked");
        let (i, j) = first_difference(&uav, d);
        format!(
            "fails at ({}, {}): U·A·V has {} but D has {}",
            i + 1,
            j + 1,
            r.format(uav.get(i, j)),
            r.format(d.get(i, j))
        )
    };
    c.push("U·A·V = D", prod_ok, detail);
    let diag_ok = d.is_diagonal();
    c.push(
        "D diagonal",
        diag_ok,
        if diag_ok {
            "yes"
        } else {
            "D has a nonzero off-diagonal entry"
        },
    );
    for (name, mat, ev, left) in [("U", u, u_evidence, true), ("V", v, v_evidence, false)] {
        let (ok, detail) = unimodular(name, mat, ev, left, check);
        c.push(format!("{name} unimodular"), ok, detail);
    }
    if !diag_ok {
        return c;
    }
    let diag = d.diagonal();
    let first_zero = diag.iter().position(|e| r.is_zero(e)).unwrap_or(diag.len());
    let zeros_last = diag[first_zero..].iter().all(|e| r.is_zero(e));
    c.push(
        "zeros last",
        zeros_last,
        if zeros_last {
            format!("{first_zero} nonzero invariant factor(s), then zeros")
        } else {
            "a zero diagonal entry precedes a nonzero one".to_string()
        },
    );
    let mut norm_fail = Vec::new();
    for (i, e) in diag.iter().enumerate().take(first_zero) {
        if r.normalize(e) != *e {
            norm_fail.push(format!(
                "f{} = {} (normal form {})",
                i + 1,
                r.format(e),
                r.format(&r.normalize(e))
            ));
        }
    }
    c.push(
        "invariant factors normalised",
        norm_fail.is_empty(),
        if norm_fail.is_empty() {
            "each nonzero diagonal entry is in normal form (monic / primitive)".to_string()
        } else {
            norm_fail.join("; ")
        },
    );
    let mut div_fail = Vec::new();
    for i in 1..first_zero {
        if r.div_exact(&diag[i], &diag[i - 1]).is_none() {
            div_fail.push(format!(
                "f{} = {} does not divide f{} = {}",
                i,
                r.format(&diag[i - 1]),
                i + 1,
                r.format(&diag[i])
            ));
        }
    }
    c.push(
        "divisibility f1 | f2 | …",
        div_fail.is_empty(),
        if div_fail.is_empty() {
            "each invariant factor divides the next".to_string()
        } else {
            div_fail.join("; ")
        },
    );
    c
}

fn unimodular<R: GcdDomain>(
    name: &str,
    m: &Matrix<R>,
    ev: Unimodular<'_, R>,
    left: bool,
    check: &dyn ProductCheck<R>,
) -> (bool, String) {
    let r = &m.ring;
    match ev {
        Unimodular::Inverse(inv) => {
            let id = Matrix::identity(r.clone(), m.rows());
            let factors = if left { [m, inv] } else { [inv, m] };
            let square = m.rows() == m.cols() && inv.rows() == m.rows() && inv.cols() == m.cols();
            match square && check.product_equals(&factors, &id) {
                true => (
                    true,
                    format!(
                        "{name}·{name}⁻¹ = I for a polynomial {name}⁻¹, so det {name} is a unit"
                    ),
                ),
                false => (false, format!("{name} times the recorded inverse is not I")),
            }
        }
        Unimodular::Determinant => {
            let d = m.det().expect("square");
            let s = r.format(&d);
            if r.is_unit(&d) {
                (true, format!("det {name} = {s}, a unit of {}", r.name()))
            } else {
                (
                    false,
                    format!("det {name} = {s} is not a unit of {}", r.name()),
                )
            }
        }
    }
}

fn first_difference<R: GcdDomain>(x: &Matrix<R>, y: &Matrix<R>) -> (usize, usize) {
    for i in 0..x.rows() {
        for j in 0..x.cols() {
            if x.get(i, j) != y.get(i, j) {
                return (i, j);
            }
        }
    }
    (0, 0)
}

/// Evaluates identities over Q\[x\] with denominators cleared: each left
/// factor's rows and each right factor's columns are brought to one
/// common denominator, the product is taken over Z\[x\] (no rational
/// normalisation per term), and each entry of the result is put in
/// canonical form once. Exactly the same statement as [`Direct`], much
/// cheaper on large matrices with big rational entries.
pub struct ClearedQx;

/// `(integer numerators, common denominator)` of a line of `QPoly`s
/// (borrowed where the polynomial already has that denominator, as U's
/// integer rows do: no copy).
#[allow(clippy::type_complexity)]
fn clear_line<'a>(
    line: impl Iterator<Item = &'a QPoly> + Clone,
) -> (Vec<Cow<'a, [BigInt]>>, BigInt) {
    let mut l = BigInt::one();
    for p in line.clone() {
        if !p.is_zero() && p.den() != &l {
            l = crate::algebra::intgcd::lcm(&l, p.den());
        }
    }
    let nums = line
        .map(|p| {
            if p.den() == &l {
                Cow::Borrowed(p.num())
            } else {
                let s = &l / p.den();
                Cow::Owned(p.num().iter().map(|c| c * &s).collect())
            }
        })
        .collect();
    (nums, l)
}

/// The line's integer polynomials as `i64` coefficients, if all fit.
fn small_line<P: AsRef<[BigInt]>>(line: &[P]) -> Option<Vec<Vec<i64>>> {
    line.iter()
        .map(|p| {
            p.as_ref()
                .iter()
                .map(|c| c.to_i64())
                .collect::<Option<Vec<i64>>>()
        })
        .collect()
}

/// `Σ_t a_t·b_t` over Z[x] for integer polynomials `a_t` and `b_t` with
/// word-size coefficients, accumulated in fixed-width two's complement
/// words wide enough for every partial sum (no allocation per term; this
/// is the inner loop of `U·A` with a large U and a small A).
fn dot_small<P: AsRef<[BigInt]>>(xs: &[P], ys: &[Vec<i64>]) -> Vec<BigInt> {
    let (mut len, mut bits, mut terms) = (0usize, 0u64, 0u64);
    for (a, b) in xs.iter().zip(ys) {
        let a = a.as_ref();
        if a.is_empty() || b.is_empty() {
            continue;
        }
        len = len.max(a.len() + b.len() - 1);
        bits = bits.max(a.iter().map(|c| c.bits()).max().unwrap_or(0));
        terms += a.len().min(b.len()) as u64;
    }
    if len == 0 {
        return Vec::new();
    }
    // |a·b| < 2^(bits + 63); a sum of `terms` of them per coefficient, and
    // a sign bit.
    let w = ((bits + 63 + 64 - (terms + 1).leading_zeros() as u64 + 1) / 64 + 1) as usize;
    // Positive and negative terms go to separate unsigned accumulators
    // (no sign branch in the inner loop); their difference, in w words of
    // two's complement, is the sum.
    let mut acc = vec![0u64; len * w];
    let mut neg_acc = vec![0u64; len * w];
    let mut mag: Vec<u64> = Vec::with_capacity(w);
    for (a, b) in xs.iter().zip(ys) {
        for (i, c) in a.as_ref().iter().enumerate() {
            if c.is_zero() {
                continue;
            }
            mag.clear();
            mag.extend(c.magnitude().iter_u64_digits());
            let neg_c = c.is_negative();
            for (j, &q) in b.iter().enumerate() {
                if q == 0 {
                    continue;
                }
                let target = if neg_c ^ (q < 0) {
                    &mut neg_acc
                } else {
                    &mut acc
                };
                add_scaled(
                    &mut target[(i + j) * w..(i + j + 1) * w],
                    &mag,
                    q.unsigned_abs(),
                );
            }
        }
    }
    for (x, y) in acc.chunks_mut(w).zip(neg_acc.chunks(w)) {
        let mut borrow = false;
        for (l, &m) in x.iter_mut().zip(y) {
            let (d1, o1) = l.overflowing_sub(m);
            let (d2, o2) = d1.overflowing_sub(borrow as u64);
            *l = d2;
            borrow = o1 || o2;
        }
    }
    acc.chunks_mut(w)
        .map(|slot| {
            let negative = slot[w - 1] >> 63 == 1;
            twos_complement_to_bigint(slot, negative)
        })
        .collect()
}

/// A line of integer polynomials laid out for [`dot_flat`]: every
/// coefficient as `w` little-endian magnitude words, with a sign mask
/// (0 or −1) per word, the polynomials' coefficients contiguous.
struct FlatLine {
    /// Words per coefficient.
    w: usize,
    /// Per polynomial: (first word, number of coefficients).
    polys: Vec<(usize, usize)>,
    mags: Vec<u64>,
    masks: Vec<i128>,
}

impl FlatLine {
    fn new<P: AsRef<[BigInt]>>(line: &[P]) -> Self {
        let bits = line
            .iter()
            .flat_map(|p| p.as_ref())
            .map(|c| c.bits())
            .max()
            .unwrap_or(0);
        let w = bits.div_ceil(64).max(1) as usize;
        let total: usize = line.iter().map(|p| p.as_ref().len()).sum();
        let (mut mags, mut masks) = (Vec::with_capacity(total * w), Vec::with_capacity(total * w));
        let mut polys = Vec::with_capacity(line.len());
        for p in line {
            let p = p.as_ref();
            polys.push((mags.len(), p.len()));
            for c in p {
                let start = mags.len();
                mags.extend(c.magnitude().iter_u64_digits());
                mags.resize(start + w, 0);
                masks.resize(start + w, if c.is_negative() { -1 } else { 0 });
            }
        }
        FlatLine {
            w,
            polys,
            mags,
            masks,
        }
    }
}

/// [`dot_small`] for a [`FlatLine`] against factors whose coefficients
/// are below 2^32 in magnitude, each coefficient a sum of fewer than 2^30
/// products (the caller checks both): a limb of `|a|·|b|` is below 2^96,
/// so every product goes, signed, into one `i128` lane per word (below
/// 2^126 in magnitude: no overflow, no carry chain in the inner loop,
/// which is one contiguous multiply-add per factor coefficient); the lanes
/// are carried into words once per coefficient at the end.
fn dot_flat(xs: &FlatLine, ys: &[Vec<i64>]) -> Vec<BigInt> {
    let w = xs.w;
    let len = xs
        .polys
        .iter()
        .zip(ys)
        .filter(|((_, la), b)| *la > 0 && !b.is_empty())
        .map(|((_, la), b)| la + b.len() - 1)
        .max()
        .unwrap_or(0);
    if len == 0 {
        return Vec::new();
    }
    let mut lanes = vec![0i128; (len + 1) * w];
    for (&(start, la), b) in xs.polys.iter().zip(ys) {
        if la == 0 {
            // A zero entry: no products (and `t·w` may pass `lanes`).
            continue;
        }
        let (mags, masks) = (
            &xs.mags[start..start + la * w],
            &xs.masks[start..start + la * w],
        );
        for (t, &q) in b.iter().enumerate() {
            if q == 0 {
                continue;
            }
            let qa = u128::from(q.unsigned_abs());
            let qm: i128 = if q < 0 { -1 } else { 0 };
            for ((l, &m), &mk) in lanes[t * w..].iter_mut().zip(mags).zip(masks) {
                // ±m·|q|: conditional negation by the combined mask.
                let p = (u128::from(m) * qa) as i128;
                let mm = mk ^ qm;
                *l += (p ^ mm) - mm;
            }
        }
    }
    let mut words: Vec<u64> = Vec::with_capacity(w + 1);
    let mut out: Vec<BigInt> = Vec::new();
    let mut zeros = 0;
    for k in 0..len {
        words.clear();
        let mut carry = 0i128;
        for &l in &lanes[k * w..(k + 1) * w] {
            let t = l + carry;
            words.push(t as u64);
            carry = t >> 64;
        }
        // The value is Σ words·2^(64·i) + carry·2^(64·w), |carry| < 2^63.
        // Zero coefficients (most entries of U·A = D·V⁻¹ are zero) are
        // counted, not built, and trailing ones are never materialised.
        if carry == 0 && words.iter().all(|&x| x == 0) {
            zeros += 1;
            continue;
        }
        out.extend(std::iter::repeat_n(BigInt::zero(), zeros));
        zeros = 0;
        let negative = carry < 0;
        words.push(carry as u64);
        out.push(twos_complement_to_bigint(&mut words, negative));
    }
    out
}

/// Whether [`dot_flat`] applies to these factors (coefficients below
/// 2^32, fewer than 2^30 products per coefficient).
fn flat_applies(ys: &[Vec<i64>]) -> bool {
    let terms: usize = ys.iter().map(|b| b.len()).sum();
    terms < 1 << 30 && ys.iter().flatten().all(|q| q.unsigned_abs() < 1 << 32)
}

/// `slot += mag·q` on little-endian words (`slot` wide enough: the
/// caller's width bound).
#[inline]
fn add_scaled(slot: &mut [u64], mag: &[u64], q: u64) {
    let mut carry = 0u64;
    for (l, &m) in slot.iter_mut().zip(mag) {
        // m·q + l + carry ≤ (2^64 − 1)² + 2·(2^64 − 1) < 2^128.
        let t = m as u128 * q as u128 + *l as u128 + carry as u128;
        *l = t as u64;
        carry = (t >> 64) as u64;
    }
    for l in slot.iter_mut().skip(mag.len()) {
        if carry == 0 {
            break;
        }
        let (v, o) = l.overflowing_add(carry);
        *l = v;
        carry = o as u64;
    }
}

/// `X·Y` over Q\[x\] through an integer product.
pub fn mul_cleared(x: &Matrix<QxRing>, y: &Matrix<QxRing>) -> Option<Matrix<QxRing>> {
    if x.cols() != y.rows() {
        return None;
    }
    let (m, k, n) = (x.rows(), x.cols(), y.cols());
    let rows: Vec<(Vec<Cow<[BigInt]>>, BigInt)> = (0..m)
        .map(|i| clear_line((0..k).map(|t| x.get(i, t))))
        .collect();
    let cols: Vec<(Vec<Cow<[BigInt]>>, BigInt)> = (0..n)
        .map(|j| clear_line((0..k).map(|t| y.get(t, j))))
        .collect();
    let small_rows: Vec<Option<Vec<Vec<i64>>>> = rows.iter().map(|(l, _)| small_line(l)).collect();
    let small_cols: Vec<Option<Vec<Vec<i64>>>> = cols.iter().map(|(l, _)| small_line(l)).collect();
    // Rows laid out once for the columns with small coefficients.
    let flat_cols: Vec<bool> = small_cols
        .iter()
        .map(|c| c.as_ref().is_some_and(|ys| flat_applies(ys)))
        .collect();
    let flat_rows: Vec<Option<FlatLine>> = rows
        .iter()
        .map(|(l, _)| flat_cols.iter().any(|&f| f).then(|| FlatLine::new(l)))
        .collect();
    let mut data = Vec::with_capacity(m * n);
    for (((xr, dx), xs), xf) in rows.iter().zip(&small_rows).zip(&flat_rows) {
        for (((yc, dy), ys), &flat) in cols.iter().zip(&small_cols).zip(&flat_cols) {
            if let (Some(ys), Some(xf), true) = (ys, xf, flat) {
                data.push(QPoly::new(dot_flat(xf, ys), dx * dy));
                continue;
            }
            if let Some(ys) = ys {
                data.push(QPoly::new(dot_small(xr, ys), dx * dy));
                continue;
            }
            if let Some(xs) = xs {
                data.push(QPoly::new(dot_small(yc, xs), dx * dy));
                continue;
            }
            let mut acc: Vec<BigInt> = Vec::new();
            for (a, b) in xr.iter().zip(yc) {
                if a.is_empty() || b.is_empty() {
                    continue;
                }
                let len = a.len() + b.len() - 1;
                if acc.len() < len {
                    acc.resize(len, BigInt::zero());
                }
                if crate::algebra::qx::kronecker_pays(a, b) {
                    for (s, c) in acc.iter_mut().zip(crate::algebra::qx::conv(a, b)) {
                        *s += c;
                    }
                } else {
                    for (i, p) in a.iter().enumerate() {
                        if p.is_zero() {
                            continue;
                        }
                        for (j, q) in b.iter().enumerate() {
                            acc[i + j] += p * q;
                        }
                    }
                }
            }
            data.push(QPoly::new(acc, dx * dy));
        }
    }
    Some(Matrix::new(x.ring.clone(), m, n, data))
}

impl ProductCheck<QxRing> for ClearedQx {
    fn product_equals(&self, factors: &[&Matrix<QxRing>], rhs: &Matrix<QxRing>) -> bool {
        let mut it = factors.iter();
        let Some(first) = it.next() else {
            return false;
        };
        let mut acc = (*first).clone();
        for f in it {
            match mul_cleared(&acc, f) {
                Some(m) => acc = m,
                None => return false,
            }
        }
        acc == *rhs
    }
}

/// `Some((p, k))` when the gcd over Q of `entries` is proved to be 1: the
/// gcd of the images of the first k entries modulo p is 1, and p divides
/// no coefficient that matters: the image of the first entry keeps its
/// degree, so the primitive gcd g over Z (which divides the first entry's
/// numerator, by Gauss's lemma) keeps its degree mod p, and that degree is
/// at most the image gcd's. Tries the first three word primes.
pub(super) fn coprime_mod_p(entries: &[&QPoly]) -> Option<(u64, usize)> {
    let first = entries.first()?;
    for p in crate::algebra::modular::primes().take(3) {
        let f = Fp::new(p);
        let img = |e: &QPoly| modular::trim(e.num().iter().map(|c| f.reduce(c)).collect());
        let g0 = img(first);
        if modular::deg(&g0) != first.degree() {
            continue;
        }
        let mut g = g0;
        let mut used = 1;
        for e in &entries[1..] {
            if modular::deg(&g) == Some(0) {
                break;
            }
            g = modular::gcd(f, &g, &img(e));
            used += 1;
        }
        if modular::deg(&g) == Some(0) {
            return Some((p, used));
        }
    }
    None
}

/// Checks `A·B = c·I` exactly (integer products with cleared
/// denominators) when `shaped`, and records it in `cert`.
pub(super) fn push_product_check(
    cert: &mut Certificate,
    a: &Matrix<QxRing>,
    c: &QPoly,
    b: &Matrix<QxRing>,
    shaped: bool,
    failure: &str,
) -> bool {
    let n = a.rows();
    let mut ci = Matrix::zeros(a.ring.clone(), n, n);
    for i in 0..n {
        ci.set(i, i, c.clone());
    }
    let prod = shaped && ClearedQx.product_equals(&[a, b], &ci);
    cert.push(
        "A·B = c·I",
        prod,
        if prod {
            format!(
                "holds exactly for a polynomial B and c ≠ 0 of degree {}",
                c.degree().unwrap_or(0)
            )
        } else {
            failure.to_string()
        },
    );
    prod
}

/// Certifies that a square A over Q\[x\] has invariant factors 1, …, 1, f
/// with `f = c/lc(c)`, from `A·B = c·I` alone (no transforms), and returns
/// f. Three exact checks:
/// 1. `A·B = c·I` with `c ≠ 0` (an integer product, [`ClearedQx`]); then A
///    is invertible and `B = (c/det A)·adj A`;
/// 2. the entries of B have gcd 1: their gcd modulo a prime p that divides
///    no leading coefficient of the first entry is 1, and the degree of a
///    gcd over Q is at most that of its image; with 1 this gives
///    `c ~ det A/d_(n−1)` (d_k the k-th determinantal divisor);
/// 3. `deg c = N`, where N (the least of the sums of row and of column
///    degrees) bounds deg det A; so `deg d_(n−1) = 0`, hence
///    d_1 = … = d_(n−1) = 1 and `f_n = det A` up to a unit.
pub fn certify_last_factor(
    a: &Matrix<QxRing>,
    c: &QPoly,
    b: &Matrix<QxRing>,
) -> (Certificate, QPoly) {
    let r = &a.ring;
    let n = a.rows();
    let mut cert = Certificate { checks: Vec::new() };
    let square = n == a.cols() && b.rows() == n && b.cols() == n && !c.is_zero();
    let prod = push_product_check(&mut cert, a, c, b, square, "fails (or c = 0)");
    // Entries of B (nonzero), as integer numerators.
    let entries: Vec<&QPoly> = (0..b.rows())
        .flat_map(|i| (0..b.cols()).map(move |j| (i, j)))
        .map(|(i, j)| b.get(i, j))
        .filter(|e| !e.is_zero())
        .collect();
    let coprime = coprime_mod_p(&entries);
    cert.push(
        "gcd of the entries of B is 1",
        coprime.is_some(),
        match coprime {
            Some((p, k)) => format!(
                "the gcd of the first {k} nonzero entries of B is 1 modulo p = {p}, which does not divide the leading coefficient of the first, so their gcd over Q is 1"
            ),
            None => "no prime among the first three showed the entries coprime".to_string(),
        },
    );
    let deg = |p: &QPoly| p.degree().unwrap_or(0);
    let row_sum: usize = (0..n)
        .map(|i| (0..a.cols()).map(|j| deg(a.get(i, j))).max().unwrap_or(0))
        .sum();
    let col_sum: usize = (0..a.cols())
        .map(|j| (0..n).map(|i| deg(a.get(i, j))).max().unwrap_or(0))
        .sum();
    let bound = row_sum.min(col_sum);
    let deg_ok = c.degree() == Some(bound);
    cert.push(
        "deg c = degree bound of det A",
        deg_ok,
        format!(
            "deg c = {}; deg det A ≤ {bound} (least of the sums of row and of column degrees)",
            deg(c)
        ),
    );
    let ok = prod && coprime.is_some() && deg_ok;
    let f = r.normalize(c);
    cert.push(
        "invariant factors 1, …, 1, f",
        ok,
        if ok {
            "B = (c/det A)·adj A with coprime entries gives c ~ det A/d_(n−1); deg c ≥ deg det A gives d_(n−1) = 1, so f_1 = … = f_(n−1) = 1 and f_n = c/lc(c)".to_string()
        } else {
            "not established".to_string()
        },
    );
    (cert, f)
}

/// Whether `det Ã ≡ c` modulo the last (smallest) word prime p, as
/// polynomials, for `Ã = Δ·A` (Δ the rows' denominator lcms): both sides
/// have degree ≤ N (the least of the sums of row and of column degrees),
/// so agreement at the N+1 points 0, …, N of Z_p decides it. Returns p.
#[cfg(any(test, feature = "internals"))]
fn det_agrees_mod_p(a: &Matrix<QxRing>, c: &QPoly) -> Option<u64> {
    let n = a.rows();
    let p = modular::primes().last()?;
    let f = Fp::new(p);
    let cden = f.reduce(c.den());
    if cden == 0 {
        return None;
    }
    let cinv = f.inv(cden);
    let cimg: Vec<u64> = c.num().iter().map(|x| f.reduce(x)).collect();
    let mut rows: Vec<Vec<Vec<u64>>> = Vec::with_capacity(n);
    for i in 0..n {
        let l = a.row(i).iter().fold(BigInt::one(), |l, e| {
            crate::algebra::intgcd::lcm(&l, e.den())
        });
        rows.push(
            a.row(i)
                .iter()
                .map(|e| {
                    let s = &l / e.den();
                    e.num().iter().map(|x| f.reduce(&(x * &s))).collect()
                })
                .collect(),
        );
    }
    let deg = |e: &QPoly| e.degree().unwrap_or(0);
    let row_sum: usize = (0..n)
        .map(|i| (0..n).map(|j| deg(a.get(i, j))).max().unwrap_or(0))
        .sum();
    let col_sum: usize = (0..n)
        .map(|j| (0..n).map(|i| deg(a.get(i, j))).max().unwrap_or(0))
        .sum();
    let bound = row_sum.min(col_sum);
    // Agreement at N+1 points decides equality only up to degree N.
    if c.degree().is_none_or(|d| d > bound) {
        return None;
    }
    let bound = bound as u64;
    let mut m = vec![0u64; n * n];
    for x in 0..=bound {
        for (i, row) in rows.iter().enumerate() {
            for (j, e) in row.iter().enumerate() {
                m[i * n + j] = modular::eval(f, e, x);
            }
        }
        let d = super::detadj::det_adj_mod(f, &m, n).map_or(0, |(d, _)| d);
        if d != f.mul(modular::eval(f, &cimg, x), cinv) {
            return None;
        }
    }
    Some(p)
}

/// Certifies the invariant factors of a square A over Q\[x\] (n ≥ 3) as
/// 1, …, 1, g, c/g (normalised) from `A·B = c·I` and `c = κ·det A` for a
/// nonzero constant κ, without transforms, and returns all n of them.
/// The checks:
/// 1. `A·B = c·I` exactly ([`ClearedQx`]): `B = c·A⁻¹`;
/// 2. `c = det Ã` for `Ã = Δ·A` (Δ the rows' denominator lcms): c comes
///    from the exact computation by images beyond a proved coefficient
///    bound ([`super::detadj`]); here det Ã ≡ c is re-checked modulo a
///    further prime at N+1 points. With 1, `B = κ·adj A`;
/// 3. `g = gcd` of B's entries: computed by Euclid over Q, then every
///    entry is divided by g exactly and the quotients are shown coprime
///    modulo a prime that keeps the first quotient's degree. So
///    `d_(n−1)(A) ~ g` (the (n−1)-minors are adj's entries);
/// 4. `d_(n−2)(A) = 1`: by Jacobi's identity a 2×2 minor of adj A is
///    det A times the complementary (n−2)-minor of A (up to sign), so
///    `(B_ik·B_jl − B_il·B_jk)/c` is κ times an (n−2)-minor of A; a few of
///    them are divided by c exactly and shown coprime modulo a prime.
///
/// Then `f_(n−1) = d_(n−1)/d_(n−2) ~ g` and `f_n = det A/d_(n−1) ~ c/g`
/// (checked to be divisible by f_(n−1)). An empty vector means "not
/// established"; the certificate says which check failed.
#[cfg(any(test, feature = "internals"))]
pub fn certify_two_factors(
    a: &Matrix<QxRing>,
    c: &QPoly,
    b: &Matrix<QxRing>,
) -> (Certificate, Vec<QPoly>) {
    let r = &a.ring;
    let n = a.rows();
    let mut cert = Certificate { checks: Vec::new() };
    let square = n >= 3 && n == a.cols() && b.rows() == n && b.cols() == n && !c.is_zero();
    let prod = push_product_check(
        &mut cert,
        a,
        c,
        b,
        square,
        "fails (or c = 0, or A is not square and at least 3×3)",
    );
    if !prod {
        return (cert, Vec::new());
    }
    let det_p = det_agrees_mod_p(a, c);
    cert.push(
        "c = det Ã (Ã = Δ·A, Δ the rows' denominators)",
        det_p.is_some(),
        match det_p {
            Some(p) => format!(
                "c was computed exactly by images modulo word primes beyond a proved (Hadamard) coefficient bound; det Ã ≡ c modulo the further prime p = {p} at deg-bound + 1 points; so B = κ·adj A for a constant κ ≠ 0"
            ),
            None => "det Ã differs from c modulo the check prime".to_string(),
        },
    );
    // 3. The gcd of B's entries.
    let entries: Vec<&QPoly> = (0..n)
        .flat_map(|i| (0..n).map(move |j| (i, j)))
        .map(|(i, j)| b.get(i, j))
        .filter(|e| !e.is_zero())
        .collect();
    let mut g = r.zero();
    for e in &entries {
        if g.degree() == Some(0) {
            break;
        }
        g = r.gcd(&g, e);
    }
    let quotients: Option<Vec<QPoly>> = (!g.is_zero())
        .then(|| entries.iter().map(|e| r.div_exact(e, &g)).collect())
        .flatten();
    let gcd_proof = quotients.as_ref().and_then(|q| {
        let refs: Vec<&QPoly> = q.iter().collect();
        coprime_mod_p(&refs)
    });
    cert.push(
        "gcd of the entries of B is g",
        gcd_proof.is_some(),
        match gcd_proof {
            Some((p, k)) => format!(
                "g = {} (degree {}) divides every entry exactly, and the gcd of the first {k} quotients is 1 modulo p = {p}, which keeps the first one's degree; so d_(n−1)(A) ~ g",
                r.format(&g),
                g.degree().unwrap_or(0)
            ),
            None => "g does not divide every entry, or the quotients were not shown coprime"
                .to_string(),
        },
    );
    // 4. (n−2)-minors by Jacobi's identity.
    let mut minors = Vec::new();
    let mut jacobi_ok = true;
    for t in 0..(n - 1).min(8) {
        let (i, j) = (t, t + 1);
        let k = (n - 2 + t * 3) % (n - 1);
        let l = k + 1;
        let m2 = r.sub(
            &r.mul(b.get(i, k), b.get(j, l)),
            &r.mul(b.get(i, l), b.get(j, k)),
        );
        match r.div_exact(&m2, c) {
            Some(q) if !q.is_zero() => minors.push(q),
            Some(_) => {}
            None => jacobi_ok = false,
        }
    }
    let refs: Vec<&QPoly> = minors.iter().collect();
    let minors_proof = jacobi_ok.then(|| coprime_mod_p(&refs)).flatten();
    cert.push(
        "d_(n−2)(A) = 1",
        minors_proof.is_some(),
        match minors_proof {
            Some((p, k)) => format!(
                "{k} 2×2 minors of B, each divided exactly by c (Jacobi: κ times an (n−2)-minor of A), have gcd 1 modulo p = {p}, which keeps the first one's degree"
            ),
            None if !jacobi_ok => {
                "a 2×2 minor of B is not divisible by c, contradicting Jacobi's identity".to_string()
            }
            None => "the (n−2)-minors tried were not shown coprime".to_string(),
        },
    );
    let f_last = r.div_exact(c, &g).map(|q| r.normalize(&q));
    let f_prev = r.normalize(&g);
    let divides = f_last
        .as_ref()
        .is_some_and(|fl| r.div_exact(fl, &f_prev).is_some());
    let ok = det_p.is_some() && gcd_proof.is_some() && minors_proof.is_some() && divides;
    cert.push(
        "invariant factors 1, …, 1, g, c/g",
        ok,
        if ok {
            "f_1 = … = f_(n−2) = 1 (d_(n−2) = 1), f_(n−1) = d_(n−1)/d_(n−2) ~ g, f_n = det A/d_(n−1) ~ c/g, and f_(n−1) divides f_n".to_string()
        } else {
            "not established".to_string()
        },
    );
    if !ok {
        return (cert, Vec::new());
    }
    let mut factors = vec![r.one(); n - 2];
    factors.push(f_prev);
    factors.extend(f_last);
    (cert, factors)
}

/// The integer whose two's-complement little-endian 64-bit limbs are
/// `limbs` (negative when `negative`, i.e. its top bit is set); `limbs` is
/// negated in place on the way.
fn twos_complement_to_bigint(limbs: &mut [u64], negative: bool) -> BigInt {
    if negative {
        let mut carry = true;
        for l in limbs.iter_mut() {
            let (v, o) = (!*l).overflowing_add(u64::from(carry));
            *l = v;
            carry = o;
        }
    }
    let sign = if negative {
        num_bigint::Sign::Minus
    } else {
        num_bigint::Sign::Plus
    };
    BigInt::from_biguint(sign, biguint_from_limbs(limbs))
}

/// The natural with these little-endian 64-bit limbs, with one
/// allocation (none for a value below 2^64): num-bigint 0.4 builds from
/// 32-bit digits, which are packed here on the stack up to 32 limbs.
pub(crate) fn biguint_from_limbs(limbs: &[u64]) -> num_bigint::BigUint {
    let used = limbs.iter().rposition(|&l| l != 0).map_or(0, |i| i + 1);
    if used <= 1 {
        return num_bigint::BigUint::from(limbs.first().copied().unwrap_or(0));
    }
    let mut small = [0u32; 64];
    let mut big = Vec::new();
    let digits: &mut [u32] = if used <= 32 {
        &mut small[..2 * used]
    } else {
        big.resize(2 * used, 0);
        &mut big
    };
    for (d, &l) in digits.chunks_mut(2).zip(&limbs[..used]) {
        d[0] = l as u32;
        d[1] = (l >> 32) as u32;
    }
    num_bigint::BigUint::from_slice(digits)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::rational::Q;

    fn qp(num: &[i64], den: i64) -> QPoly {
        QPoly::new(
            num.iter().map(|&c| BigInt::from(c)).collect(),
            BigInt::from(den),
        )
    }

    /// Limbs → natural with one allocation: the same number as the
    /// shift-and-add form, for 0–40 limbs with zero runs and top zeros.
    #[test]
    fn naturals_from_limbs() {
        let mut seed = 3u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            seed
        };
        for round in 0..400 {
            let len = round % 41;
            let limbs: Vec<u64> = (0..len)
                .map(|i| if (i + round) % 5 == 0 { 0 } else { next() })
                .collect();
            let want = limbs
                .iter()
                .rev()
                .fold(num_bigint::BigUint::zero(), |acc, &l| {
                    (acc << 64u32) + num_bigint::BigUint::from(l)
                });
            assert_eq!(biguint_from_limbs(&limbs), want, "{limbs:?}");
        }
    }

    /// A flat dot product that cancels gives the empty (zero) polynomial,
    /// and interior zero coefficients stay in place.
    #[test]
    fn flat_dot_product_cancels_to_nothing() {
        let p: Vec<BigInt> = [5i64, -7, 11]
            .iter()
            .map(|&c| BigInt::from(c) << 130u32)
            .collect();
        let minus_p: Vec<BigInt> = p.iter().map(|c| -c).collect();
        let xs = vec![p.clone(), minus_p];
        let ys = vec![vec![3i64, 0, -2], vec![3, 0, -2]];
        assert!(flat_applies(&ys));
        assert!(dot_flat(&FlatLine::new(&xs), &ys).is_empty());
        // p·(1 + x²) has a zero coefficient at x¹ only if p does: use x^0
        // and x^2 terms of a sparse p.
        let sparse = vec![vec![
            BigInt::from(1) << 100u32,
            BigInt::zero(),
            BigInt::from(-1) << 100u32,
        ]];
        let got = dot_flat(&FlatLine::new(&sparse), &[vec![1, 0, 1]]);
        let b = BigInt::from(1) << 100u32;
        assert_eq!(
            got,
            vec![
                b.clone(),
                BigInt::zero(),
                BigInt::zero(),
                BigInt::zero(),
                -b
            ]
        );
    }

    #[test]
    fn word_size_dot_product_agrees_with_bigint_arithmetic() {
        let mut seed = 99u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            seed
        };
        let (mut checked, mut flat_checked) = (0, 0);
        // Rounds from 40 on have factors below 2^32 (the flat form).
        for round in 0..80 {
            let k = 1 + round % 5;
            let big = |x: u64, y: u64, z: u64| -> BigInt {
                let v = (BigInt::from(x) << 128) + (BigInt::from(y) << 64) + BigInt::from(z);
                let v: BigInt = v >> (x % 190) as usize;
                if y.is_multiple_of(2) { -v } else { v }
            };
            let xs: Vec<Vec<BigInt>> = (0..k)
                .map(|t| {
                    (0..(t + round) % 4)
                        .map(|_| big(next(), next(), next()))
                        .collect()
                })
                .collect();
            let ys: Vec<Vec<i64>> = (0..k)
                .map(|t| {
                    (0..(t + 2 * round) % 3 + 1)
                        .map(|s| match ((round + s) % 4, round >= 40) {
                            (0, false) => i64::MIN,
                            (1, false) => i64::MAX,
                            (0, true) => (1 << 32) - 1,
                            (1, true) => 1 - (1 << 32),
                            (_, false) => next() as i64 >> (next() % 60),
                            (_, true) => next() as i64 >> (32 + next() % 30),
                        })
                        .collect()
                })
                .collect();
            let mut want: Vec<BigInt> = Vec::new();
            for (a, b) in xs.iter().zip(&ys) {
                for (i, p) in a.iter().enumerate() {
                    for (j, q) in b.iter().enumerate() {
                        if want.len() <= i + j {
                            want.resize(i + j + 1, BigInt::zero());
                        }
                        want[i + j] += p * BigInt::from(*q);
                    }
                }
            }
            let got = dot_small(&xs, &ys);
            if flat_applies(&ys) {
                let flat = dot_flat(&FlatLine::new(&xs), &ys);
                let trim = |mut v: Vec<BigInt>| {
                    while v.last().is_some_and(|c| c.is_zero()) {
                        v.pop();
                    }
                    v
                };
                assert_eq!(trim(flat), trim(got.clone()), "round {round} (flat)");
                flat_checked += 1;
            }
            let trim = |mut v: Vec<BigInt>| {
                while v.last().is_some_and(|c| c.is_zero()) {
                    v.pop();
                }
                v
            };
            assert_eq!(trim(got), trim(want), "round {round}");
            checked += 1;
        }
        assert_eq!(checked, 80);
        assert!(flat_checked >= 40, "{flat_checked}");
    }

    #[test]
    fn cleared_product_agrees_with_the_ring_product() {
        let r = QxRing::new("x");
        let x = Matrix::new(
            r.clone(),
            2,
            3,
            vec![
                qp(&[1, 2], 3),
                qp(&[0, 0, 5], 7),
                qp(&[], 1),
                qp(&[-4], 9),
                qp(&[1, 1], 2),
                qp(&[3, 0, 1], 5),
            ],
        );
        let y = Matrix::new(
            r.clone(),
            3,
            2,
            vec![
                qp(&[2, -1], 5),
                qp(&[1], 1),
                qp(&[0, 3], 4),
                qp(&[7, 7, 7], 21),
                qp(&[-1, 0, 0, 2], 3),
                qp(&[5], 6),
            ],
        );
        let direct = x.mul(&y).expect("shapes");
        assert_eq!(mul_cleared(&x, &y).expect("shapes"), direct);
        assert!(ClearedQx.product_equals(&[&x, &y], &direct));
        let mut wrong = direct.clone();
        wrong.set(
            1,
            1,
            r.add(
                direct.get(1, 1),
                &QPoly::constant(&Q::from_integer(1.into())),
            ),
        );
        assert!(!ClearedQx.product_equals(&[&x, &y], &wrong));
    }

    fn diag3(d: [QPoly; 3]) -> Matrix<QxRing> {
        let r = QxRing::new("x");
        let mut m = Matrix::zeros(r, 3, 3);
        for (i, e) in d.into_iter().enumerate() {
            m.set(i, i, e);
        }
        m
    }

    #[test]
    fn last_factor_certificate_accepts_coprime_diagonals_only() {
        let r = QxRing::new("x");
        let (x, x1, x2) = (qp(&[0, 1], 1), qp(&[1, 1], 1), qp(&[2, 1], 1));
        let prod = |a: &QPoly, b: &QPoly| r.mul(a, b);
        // diag(x, x+1, x+2): coprime, f = x(x+1)(x+2).
        let a = diag3([x.clone(), x1.clone(), x2.clone()]);
        let c = prod(&prod(&x, &x1), &x2);
        let b = diag3([prod(&x1, &x2), prod(&x, &x2), prod(&x, &x1)]);
        let (cert, f) = certify_last_factor(&a, &c, &b);
        assert!(cert.verified(), "{cert:?}");
        assert_eq!(f, c);
        // A tampered B breaks A·B = c·I.
        let mut bad = b.clone();
        bad.set(0, 0, x.clone());
        assert!(!certify_last_factor(&a, &c, &bad).0.verified());
        // diag(x, x, x+1): A·B = c·I holds but the entries of B share x,
        // and indeed the invariant factors are 1, x, x(x+1).
        let a = diag3([x.clone(), x.clone(), x1.clone()]);
        let c = prod(&prod(&x, &x), &x1);
        let b = diag3([prod(&x, &x1), prod(&x, &x1), prod(&x, &x)]);
        let (cert, _) = certify_last_factor(&a, &c, &b);
        assert!(cert.checks[0].ok, "the product identity itself holds");
        assert!(!cert.verified());
        // c·B/x for the coprime diagonal: A·(B/x) = (c/x)·I fails the
        // degree check only when deg c < the degree bound.
        let a = diag3([x1.clone(), x2.clone(), qp(&[3, 1], 1)]);
        let c = prod(&prod(&x1, &x2), &qp(&[3, 1], 1));
        let b = diag3([
            prod(&x2, &qp(&[3, 1], 1)),
            prod(&x1, &qp(&[3, 1], 1)),
            prod(&x1, &x2),
        ]);
        assert!(certify_last_factor(&a, &c, &b).0.verified());
    }
    /// `P·diag(d)·Q` with P, Q unimodular over Q[x] (products of unit
    /// triangular matrices with polynomial entries).
    fn sandwich(d: &[QPoly]) -> Matrix<QxRing> {
        let r = QxRing::new("x");
        let n = d.len();
        let mut l = Matrix::identity(r.clone(), n);
        let mut u = Matrix::identity(r.clone(), n);
        let mut m = Matrix::zeros(r.clone(), n, n);
        for (i, di) in d.iter().enumerate() {
            m.set(i, i, di.clone());
            for j in 0..n {
                let s = ((3 * i + 5 * j) % 7) as i64 - 3;
                if i > j {
                    l.set(i, j, qp(&[s, ((i + j) % 2) as i64], 1));
                }
                if i < j {
                    u.set(i, j, qp(&[s + 1], 1));
                }
            }
        }
        let p = l.mul(&u).expect("shapes");
        let q = u.mul(&l).expect("shapes");
        p.mul(&m).and_then(|pm| pm.mul(&q)).expect("shapes")
    }

    #[test]
    fn two_factor_certificate_accepts_the_right_forms_only() {
        use crate::algebra::smith::nonsingular::{FastPath, try_fast};
        let r = QxRing::new("x");
        let (one, x, x1) = (qp(&[1], 1), qp(&[0, 1], 1), qp(&[1, 1], 1));
        let xx1 = r.mul(&x, &x1);
        let a = sandwich(&[one.clone(), one.clone(), x.clone(), xx1.clone()]);
        let Some(FastPath::NoHermite { c, b }) = try_fast(&a, u64::MAX) else {
            panic!("d_(n−1) = x: the Hermite shortcut must decline");
        };
        let (cert, f) = certify_two_factors(&a, &c, &b);
        assert!(cert.verified(), "{cert:?}");
        assert_eq!(f, vec![one.clone(), one.clone(), x.clone(), xx1.clone()]);
        // A tampered B breaks A·B = c·I.
        let mut bad = b.clone();
        bad.set(0, 1, r.add(b.get(0, 1), &one));
        let (cert, f) = certify_two_factors(&a, &c, &bad);
        assert!(!cert.checks[0].ok && !cert.verified() && f.is_empty());
        // c and B both times (x + 1): A·B = c·I still holds, but c is not
        // det Ã (it would claim f = 1, 1, x, x(x+1)²).
        let mut b2 = b.clone();
        for i in 0..4 {
            b2.scale_row(i, &x1);
        }
        let (cert, f) = certify_two_factors(&a, &r.mul(&c, &x1), &b2);
        assert!(cert.checks[0].ok, "the product identity itself holds");
        assert!(!cert.checks[1].ok && !cert.verified() && f.is_empty());
        // Three non-trivial factors 1, x, x, x²: d_(n−2) = x, rejected.
        let a3 = sandwich(&[one.clone(), x.clone(), x.clone(), r.mul(&x, &x)]);
        let Some(FastPath::NoHermite { c, b }) = try_fast(&a3, u64::MAX) else {
            panic!("d_(n−1) = x²: the Hermite shortcut must decline");
        };
        let (cert, f) = certify_two_factors(&a3, &c, &b);
        assert!(cert.checks[..3].iter().all(|c| c.ok), "{cert:?}");
        assert!(!cert.checks[3].ok && !cert.verified() && f.is_empty());
        // One non-trivial factor is the special case g = 1.
        let a1 = sandwich(&[one.clone(), one.clone(), one.clone(), xx1.clone()]);
        let c1 = a1.det().expect("square");
        let b1 = a1.adjugate().expect("square");
        let (cert, f) = certify_two_factors(&a1, &c1, &b1);
        assert!(cert.verified(), "{cert:?}");
        assert_eq!(f, vec![one.clone(), one.clone(), one, xx1]);
    }
}
