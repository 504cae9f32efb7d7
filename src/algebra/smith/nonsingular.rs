//! The fast path for a square nonsingular A over Q\[x\] whose first n-1
//! invariant factors are 1 (the generic case, e.g. random matrices).
//!
//! det A and adj A are computed exactly by images mod word primes at N+1
//! points (N a degree bound) and Chinese remaindering up to a proved
//! coefficient bound ([`super::detadj`]); the fraction-free integer
//! Gauss–Jordan kept here is the reference the tests compare against. With f = det/lc(det) and `a` the
//! last row of adj A, if some `a_j` is invertible mod f then
//! `h_i = -adj_ij · a_j⁻¹ mod f` gives the Hermite structure
//! `W·A = H = [[I, h], [0, f]]` with `W = H·adj(A)/det(A)` (checked by exact
//! division), so `U = W`, `V = [[I, -h], [0, 1]]`, `D = diag(1, …, 1, f)`,
//! and deg U ≤ deg adj A. Anything unexpected returns `None` and the caller
//! falls back to the general elimination; the result is certified by the
//! caller like any other. This module must not certify or print.

use super::SmithDecomposition;
use crate::algebra::matrix::Matrix;
use crate::algebra::qx::{QPoly, QxRing};
use crate::algebra::rational::Q;
use crate::algebra::ring::{GcdDomain, Ring};
use num_bigint::BigInt;
use num_traits::One;
#[cfg(any(test, feature = "internals"))]
use num_traits::Zero;

#[cfg(test)]
fn eval_int(p: &[BigInt], x: &BigInt) -> BigInt {
    let mut acc = BigInt::zero();
    for c in p.iter().rev() {
        acc = acc * x + c;
    }
    acc
}

/// Fraction-free Gauss–Jordan on `[M | I]`: returns `(det M, adj M)`, or
/// `None` when M is singular.
#[cfg(any(test, feature = "internals"))]
pub fn det_adj_int(m: &[Vec<BigInt>]) -> Option<(BigInt, Vec<Vec<BigInt>>)> {
    let n = m.len();
    let mut w: Vec<Vec<BigInt>> = m
        .iter()
        .enumerate()
        .map(|(i, row)| {
            let mut r = row.clone();
            r.extend((0..n).map(|j| {
                if i == j {
                    BigInt::one()
                } else {
                    BigInt::zero()
                }
            }));
            r
        })
        .collect();
    let mut prev = BigInt::one();
    let mut negative = false;
    for k in 0..n {
        let p = (k..n).find(|&i| !w[i][k].is_zero())?;
        if p != k {
            w.swap(p, k);
            negative = !negative;
        }
        let pivot_row = w[k].clone();
        let pk = pivot_row[k].clone();
        for (i, row) in w.iter_mut().enumerate() {
            if i == k {
                continue;
            }
            let f = row[k].clone();
            for j in 0..2 * n {
                if j == k {
                    continue;
                }
                let t = &pk * &row[j] - &f * &pivot_row[j];
                row[j] = t / &prev;
            }
            row[k] = BigInt::zero();
        }
        // Every earlier diagonal entry is now pk as well (Bareiss–Jordan).
        prev = pk;
    }
    // Now w = [det'·I | X] with X = det'·M⁻¹ (det' = ±det).
    let d = w[0][0].clone();
    let sign = if negative {
        -BigInt::one()
    } else {
        BigInt::one()
    };
    let adj = w
        .iter()
        .map(|row| row[n..].iter().map(|x| x * &sign).collect())
        .collect();
    Some((d * sign, adj))
}

/// The integer polynomial of degree ≤ `values.len()-1` taking `values[k]` at
/// `s + k`, by forward differences (exact: Δ^k f(s) is divisible by k!).
#[cfg(any(test, feature = "internals"))]
pub fn interpolate_int(values: &[BigInt], s: i64) -> Vec<BigInt> {
    let n = values.len();
    let mut diff = values.to_vec();
    let mut newton = Vec::with_capacity(n);
    let mut fact = BigInt::one();
    for k in 0..n {
        if k > 0 {
            fact *= BigInt::from(k);
        }
        newton.push(&diff[0] / &fact);
        for i in 0..n - 1 - k {
            diff[i] = &diff[i + 1] - &diff[i];
        }
    }
    // f(x) = Σ c_k (x-s)(x-s-1)…(x-s-k+1): Horner from the top.
    let mut p: Vec<BigInt> = Vec::new();
    for k in (0..n).rev() {
        // p ← p·(x - (s+k)) + c_k
        let root = BigInt::from(s + k as i64);
        let mut q = vec![BigInt::zero(); p.len() + 1];
        for (i, c) in p.iter().enumerate() {
            q[i + 1] += c;
            q[i] -= c * &root;
        }
        if q.is_empty() {
            q.push(BigInt::zero());
        }
        q[0] += &newton[k];
        p = q;
    }
    while p.last().is_some_and(|c| c.is_zero()) {
        p.pop();
    }
    p
}

/// Tries the fast path; `None` means "use the general elimination".
pub fn try_nonsingular(a: &Matrix<QxRing>) -> Option<SmithDecomposition<QxRing>> {
    match try_fast(a, u64::MAX)? {
        FastPath::Decomposition(d) => Some(d),
        FastPath::FormOnly { .. } | FastPath::NoHermite { .. } => None,
    }
}

/// What the fast path produced.
pub enum FastPath {
    /// A full decomposition (not yet certified).
    Decomposition(SmithDecomposition<QxRing>),
    /// The transforms would have about `bits` bits of coefficients, over the
    /// caller's limit: instead `A·B = c·I` with `B = adj(Ã)·Δ` polynomial
    /// and `c = det Ã ≠ 0`, from which the caller certifies the invariant
    /// factors 1, …, 1, c/lc(c) (see `certify::certify_last_factor`).
    FormOnly {
        /// `c`.
        c: QPoly,
        /// `B`.
        b: Matrix<QxRing>,
        /// Estimated size of U in bits.
        bits: u64,
        /// When the size is within the limit but the modular route would
        /// need this many word primes to reconstruct U's rows, beyond its
        /// supply ([`crate::algebra::modular::NPRIMES_LONG`]).
        primes: Option<usize>,
    },
    /// No entry of adj's last row is invertible modulo det (so
    /// `d_(n−1) ≠ 1`, or an unlucky last row): `A·B = c·I` as in
    /// [`FastPath::FormOnly`], for a certificate with more than one
    /// non-trivial invariant factor (`certify::certify_two_factors`).
    NoHermite {
        /// `c = det Ã`.
        c: QPoly,
        /// `B = adj(Ã)·Δ`.
        b: Matrix<QxRing>,
    },
}

/// `B = adj(Ã)·Δ` as a matrix over Q[x] (integer coefficients).
fn scaled_adjugate(r: &QxRing, adj_t: &[Vec<Vec<BigInt>>], delta: &[BigInt]) -> Matrix<QxRing> {
    let n = adj_t.len();
    let mut b = Matrix::zeros(r.clone(), n, n);
    for (i, row) in adj_t.iter().enumerate() {
        for (k, (e, d)) in row.iter().zip(delta).enumerate() {
            b.set(i, k, QPoly::from_ints(e.iter().map(|x| x * d).collect()));
        }
    }
    b
}

/// Size estimate of the Hermite transforms, in bits: `h_i` is
/// `-adj_ij·adj_nj⁻¹ mod f`, whose coefficients are about as large as the
/// resultant of `adj_nj` and f (Hadamard on the Sylvester matrix), and U
/// has `n(n−1)` such entries of degree ≤ deg adj.
fn transform_bits(det: &[BigInt], adj: &[Vec<Vec<BigInt>>]) -> u64 {
    let n = adj.len();
    let hb = |p: &[BigInt]| p.iter().map(|c| c.bits()).max().unwrap_or(0);
    let last = &adj[n - 1];
    let (hx, dx) = last
        .iter()
        .map(|p| (hb(p), p.len().saturating_sub(1) as u64))
        .fold((0, 0), |(h, d), (h2, d2)| (h.max(h2), d.max(d2)));
    let df = det.len().saturating_sub(1) as u64;
    let per_coeff = df
        .saturating_mul(hx)
        .saturating_add(dx.saturating_mul(hb(det)));
    (n as u64 * (n as u64 - 1))
        .saturating_mul(dx + 1)
        .saturating_mul(per_coeff)
}

/// The fast path with a limit (in bits) on the size of the transforms.
pub fn try_fast(a: &Matrix<QxRing>, limit_bits: u64) -> Option<FastPath> {
    match try_fast_parts(a, limit_bits)? {
        FastParts::Path(p) => Some(p),
        FastParts::Small(s) => s.into_fast_path(a),
    }
}

/// [`try_fast`]'s result with the generic decomposition not yet
/// completed: its `U⁻¹` is only built on request, since the degree
/// certificate ([`super::small::certify_small`]) does not need it.
pub enum FastParts {
    /// Any other outcome, as [`try_fast`] gives it.
    Path(FastPath),
    /// The integer route's decomposition without `U⁻¹`.
    Small(SmallFast),
}

/// [`FastParts::Small`]: the decomposition's parts and the exact det and
/// adj of `Ã = Δ·A` they came from.
pub struct SmallFast {
    /// D, U, V, V⁻¹ and what `U⁻¹` is built from.
    pub parts: super::small::SmallParts,
    at: Vec<Vec<Vec<BigInt>>>,
    delta: Vec<BigInt>,
    det: Vec<BigInt>,
    adj: Vec<Vec<Vec<BigInt>>>,
}

impl SmallFast {
    /// The full decomposition (with `U⁻¹`), or, when building `U⁻¹`
    /// fails, what the exact Q\[x\] route gives: [`try_fast`]'s result.
    pub fn into_fast_path(self, a: &Matrix<QxRing>) -> Option<FastPath> {
        let SmallFast {
            parts,
            at,
            delta,
            det,
            adj,
        } = self;
        if let Some(d) = parts.into_decomposition(&at, &delta) {
            return Some(FastPath::Decomposition(d));
        }
        hermite_or_no_column(a, det, &adj, &delta)
    }
}

fn hermite_or_no_column(
    a: &Matrix<QxRing>,
    det: Vec<BigInt>,
    adj_t: &[Vec<Vec<BigInt>>],
    delta: &[BigInt],
) -> Option<FastPath> {
    match exact_hermite(a, &det, adj_t, delta)? {
        Hermite::Decomposition(d) => Some(FastPath::Decomposition(*d)),
        Hermite::NoColumn => {
            let b = scaled_adjugate(&a.ring, adj_t, delta);
            Some(FastPath::NoHermite {
                c: QPoly::from_ints(det),
                b,
            })
        }
    }
}

/// [`try_fast`] with the generic decomposition's `U⁻¹` left to the caller
/// (see [`FastParts`]).
pub fn try_fast_parts(a: &Matrix<QxRing>, limit_bits: u64) -> Option<FastParts> {
    let n = a.rows();
    if n < 2 || a.cols() != n {
        return None;
    }
    let r = a.ring.clone();
    // Ã = diag(δ)·A with integer coefficients.
    let mut delta = Vec::with_capacity(n);
    let mut at: Vec<Vec<Vec<BigInt>>> = Vec::with_capacity(n);
    let mut bound = 0usize;
    for i in 0..n {
        // Integer rows (the usual input) skip the lcm and the scaling.
        let l = a.row(i).iter().fold(BigInt::one(), |l, p| {
            if p.den() == &l {
                l
            } else {
                crate::algebra::intgcd::lcm(&l, p.den())
            }
        });
        let row: Vec<Vec<BigInt>> = a
            .row(i)
            .iter()
            .map(|p| {
                if p.den() == &l {
                    p.num().to_vec()
                } else {
                    let s = &l / p.den();
                    p.num().iter().map(|c| c * &s).collect()
                }
            })
            .collect();
        bound += super::detadj::row_degree(&row);
        delta.push(l);
        at.push(row);
    }
    let (det_t, adj_t) = super::detadj::det_adj(&at, bound)?;
    let det_q = QPoly::from_ints(det_t);
    if det_q.is_zero() {
        return None;
    }
    if det_q.degree() == Some(0) {
        return Some(FastParts::Path(FastPath::Decomposition(unimodular(
            a, &det_q, &adj_t, &delta,
        ))));
    }
    let bits = transform_bits(det_q.num(), &adj_t);
    // Beyond the prime supply the integer route cannot finish, and the
    // exact one (extended Euclid over Q[x] on coefficients of that height)
    // stalls: bigq_6_d2, 6×6 of degree 2 with 60-digit rationals, needs
    // about 6 900 primes and ran over 60 s.
    let primes = super::small::h_primes_estimate(det_q.num());
    if bits > limit_bits || primes > crate::algebra::modular::NPRIMES_LONG {
        let b = scaled_adjugate(&r, &adj_t, &delta);
        let primes = (bits <= limit_bits).then_some(primes);
        return Some(FastParts::Path(FastPath::FormOnly {
            c: det_q,
            b,
            bits,
            primes,
        }));
    }
    if let Some(parts) = super::small::small_parts(a, det_q.num(), &adj_t, &delta) {
        return Some(FastParts::Small(SmallFast {
            parts,
            at,
            delta,
            det: det_q.num().to_vec(),
            adj: adj_t,
        }));
    }
    hermite_or_no_column(a, det_q.num().to_vec(), &adj_t, &delta).map(FastParts::Path)
}

/// What [`exact_hermite`] found.
pub enum Hermite {
    /// The decomposition (not yet certified).
    Decomposition(Box<SmithDecomposition<QxRing>>),
    /// No entry of adj's last row is invertible modulo det.
    NoColumn,
}

/// The Hermite structure over Q\[x\] (the reference route, and the fallback
/// when [`super::small::hermite_from_adjugate`] declines): `det` and `adj`
/// of `Ã = diag(δ)·A` exactly, `δ` the row scales; `None` when an exact
/// division fails.
pub fn exact_hermite(
    a: &Matrix<QxRing>,
    det: &[BigInt],
    adj_t: &[Vec<Vec<BigInt>>],
    delta: &[BigInt],
) -> Option<Hermite> {
    let n = a.rows();
    let r = a.ring.clone();
    let det_q = QPoly::from_ints(det.to_vec());
    let f = r.normalize(&det_q);
    let last: Vec<QPoly> = adj_t[n - 1]
        .iter()
        .map(|p| QPoly::from_ints(p.clone()))
        .collect();
    // Pick the column of least degree whose entry is invertible mod f.
    let mut order: Vec<usize> = (0..n).filter(|&j| !last[j].is_zero()).collect();
    order.sort_by_key(|&j| last[j].degree());
    let Some((j, inv)) = order
        .into_iter()
        .filter(|&j| may_be_coprime(&last[j], &det_q))
        .find_map(|j| r.inverse_mod(&last[j], &f).map(|s| (j, s)))
    else {
        return Some(Hermite::NoColumn);
    };
    let mut h = Vec::with_capacity(n - 1);
    let mut w = Matrix::zeros(r.clone(), n, n);
    for (i, adj_row) in adj_t.iter().enumerate().take(n - 1) {
        let bij = QPoly::from_ints(adj_row[j].clone());
        let hi = r.neg(&r.rem(&r.mul(&bij, &inv), &f));
        for (k, (bk, lk)) in adj_row.iter().zip(&last).enumerate() {
            let b = QPoly::from_ints(bk.clone());
            let num = r.add(&b, &r.mul(&hi, lk));
            w.set(i, k, super::two_by_two::exact_quotient(&r, &num, &det_q)?);
        }
        h.push(hi);
    }
    let lc_inv = det_q.lc().recip();
    for (k, lk) in last.iter().enumerate() {
        w.set(n - 1, k, lk.scale(&lc_inv));
    }
    // U = W·diag(δ).
    let mut u = w;
    for (k, d) in delta.iter().enumerate() {
        u.scale_col(k, &QPoly::constant(&Q::from_integer(d.clone())));
    }
    let mut v = Matrix::identity(r.clone(), n);
    let mut v_inv = Matrix::identity(r.clone(), n);
    for (i, hi) in h.iter().enumerate() {
        v.set(i, n - 1, r.neg(hi));
        v_inv.set(i, n - 1, hi.clone());
    }
    let mut d = Matrix::identity(r.clone(), n);
    d.set(n - 1, n - 1, f.clone());
    // U⁻¹ = A·V·D⁻¹: A's first n-1 columns, then (A·v_n)/f.
    let mut u_inv = a.clone();
    for i in 0..n {
        let mut acc = a.get(i, n - 1).clone();
        for (k, hk) in h.iter().enumerate() {
            acc = r.sub(&acc, &r.mul(a.get(i, k), hk));
        }
        u_inv.set(i, n - 1, super::two_by_two::exact_quotient(&r, &acc, &f)?);
    }
    Some(Hermite::Decomposition(Box::new(SmithDecomposition {
        d,
        u,
        v,
        u_inv,
        v_inv,
    })))
}

/// False when the images of `a` and `m` modulo a prime that keeps m's
/// degree share a factor. That is always so when a and m share one over
/// Q (a primitive gcd g divides both numerators and keeps its degree mod
/// p, its leading coefficient dividing m's), and only rarely otherwise
/// (an unlucky prime, which merely costs the Hermite shortcut). Skips the
/// costly exact extended Euclid of `inverse_mod` on entries that cannot be
/// inverted.
fn may_be_coprime(a: &QPoly, m: &QPoly) -> bool {
    use crate::algebra::modular::{self, Fp};
    let Some(p) = modular::primes().next() else {
        return true;
    };
    let f = Fp::new(p);
    let img = |e: &QPoly| modular::trim(e.num().iter().map(|c| f.reduce(c)).collect());
    let mi = img(m);
    let ai = img(a);
    if modular::deg(&mi) != m.degree() || ai.is_empty() {
        return true;
    }
    modular::deg(&modular::gcd(f, &ai, &mi)) == Some(0)
}

/// A with a constant nonzero determinant (always so for a nonsingular
/// constant matrix): `A·adj(Ã)·Δ = det Ã·I` for `Ã = Δ·A` integral, so
/// `U = I/det Ã`, `V = adj(Ã)·Δ`, `D = I`, with `U⁻¹ = det Ã·I` and
/// `V⁻¹ = A/det Ã`. Nothing is inverted over Q and V has integer
/// coefficients up to the row scales δ.
fn unimodular(
    a: &Matrix<QxRing>,
    det: &QPoly,
    adj: &[Vec<Vec<BigInt>>],
    delta: &[BigInt],
) -> SmithDecomposition<QxRing> {
    let r = a.ring.clone();
    let n = a.rows();
    let c = det.lc();
    let mut u = Matrix::identity(r.clone(), n);
    let mut u_inv = Matrix::identity(r.clone(), n);
    let c_inv = QPoly::constant(&c.recip());
    let c_poly = QPoly::constant(&c);
    for i in 0..n {
        u.set(i, i, c_inv.clone());
        u_inv.set(i, i, c_poly.clone());
    }
    let mut v = Matrix::zeros(r.clone(), n, n);
    for (i, row) in adj.iter().enumerate() {
        for (k, (e, d)) in row.iter().zip(delta).enumerate() {
            v.set(i, k, QPoly::from_ints(e.iter().map(|x| x * d).collect()));
        }
    }
    let mut v_inv = a.clone();
    for i in 0..n {
        v_inv.scale_row(i, &c_inv);
    }
    SmithDecomposition {
        d: Matrix::identity(r, n),
        u,
        v,
        u_inv,
        v_inv,
    }
}

/// A diagonal A with nonzero entries a_i: `c = Π a_i` and
/// `B = diag(Π_(j≠i) a_j)`, so `A·B = c·I` (prefix and suffix products).
/// `None` unless A is square, diagonal, at least 3×3 and has no zero on
/// its diagonal.
pub fn diagonal_adjugate(a: &Matrix<QxRing>) -> Option<(QPoly, Matrix<QxRing>)> {
    let n = a.rows();
    if n < 3 || a.cols() != n || !a.is_diagonal() {
        return None;
    }
    let r = a.ring.clone();
    let diag = a.diagonal();
    if diag.iter().any(|e| e.is_zero()) {
        return None;
    }
    let mut prefix = Vec::with_capacity(n + 1);
    prefix.push(r.one());
    for e in &diag {
        let next = r.mul(prefix.last().expect("nonempty"), e);
        prefix.push(next);
    }
    let mut suffix = vec![r.one(); n + 1];
    for i in (0..n).rev() {
        suffix[i] = r.mul(&suffix[i + 1], &diag[i]);
    }
    let mut b = Matrix::zeros(r.clone(), n, n);
    for i in 0..n {
        b.set(i, i, r.mul(&prefix[i], &suffix[i + 1]));
    }
    Some((prefix[n].clone(), b))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bi(v: &[i64]) -> Vec<BigInt> {
        v.iter().map(|&x| BigInt::from(x)).collect()
    }

    #[test]
    fn gauss_jordan_gives_det_and_adjugate() {
        let m = vec![bi(&[0, 2, 1]), bi(&[3, -1, 4]), bi(&[5, 2, -2])];
        let (d, adj) = det_adj_int(&m).unwrap();
        // det by cofactor expansion
        // det by cofactor expansion along the first row (its first entry is 0).
        let det = -2 * (3 * -2 - 4 * 5) + (3 * 2 + 5);
        assert_eq!(d, BigInt::from(det));
        for (i, row) in m.iter().enumerate() {
            for j in 0..3 {
                let s: BigInt = row.iter().zip(&adj).map(|(x, a)| x * &a[j]).sum();
                assert_eq!(s, if i == j { d.clone() } else { BigInt::zero() });
            }
        }
        assert!(det_adj_int(&[bi(&[1, 2]), bi(&[2, 4])]).is_none());
    }

    #[test]
    fn interpolation_recovers_integer_polynomials() {
        let p = bi(&[7, -3, 0, 2, 5]);
        for s in [-3i64, 0, 4] {
            let vals: Vec<BigInt> = (0..7).map(|k| eval_int(&p, &BigInt::from(s + k))).collect();
            assert_eq!(interpolate_int(&vals, s), p);
        }
    }

    #[test]
    fn form_only_route_agrees_with_the_transforms() {
        use crate::algebra::smith::certify::certify_last_factor;
        // A 6×6 of degree 1 with small integer coefficients.
        let r = QxRing::new("x");
        let mut seed = 7u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 33) % 19) as i64 - 9
        };
        let n = 6;
        let data: Vec<QPoly> = (0..n * n)
            .map(|_| QPoly::from_ints(bi(&[next(), next()])))
            .collect();
        let a = Matrix::new(r.clone(), n, n, data);
        let Some(FastPath::Decomposition(full)) = try_fast(&a, u64::MAX) else {
            panic!("the fast path applies to this matrix");
        };
        assert!(full.certify(&a).verified());
        let Some(FastPath::FormOnly { c, b, .. }) = try_fast(&a, 0) else {
            panic!("a zero limit gives the form-only route");
        };
        let (cert, f) = certify_last_factor(&a, &c, &b);
        assert!(cert.verified(), "{cert:?}");
        assert_eq!(&f, full.d.get(n - 1, n - 1));
    }

    #[test]
    fn diagonal_adjugate_is_the_adjugate() {
        let r = QxRing::new("x");
        let n = 4;
        let mut a = Matrix::zeros(r.clone(), n, n);
        for i in 0..n {
            a.set(i, i, QPoly::from_ints(bi(&[-(i as i64) - 1, 1])));
        }
        let (c, b) = diagonal_adjugate(&a).expect("diagonal");
        let mut ci = Matrix::zeros(r.clone(), n, n);
        for i in 0..n {
            ci.set(i, i, c.clone());
        }
        assert_eq!(a.mul(&b).expect("shapes"), ci);
        assert!(diagonal_adjugate(&Matrix::identity(r, 2)).is_none());
    }
}
