//! The principal mode's elimination without rational-function arithmetic:
//! a Smith elimination over R\[λ\], R = Q\[others\], for any A over Q\[all\]
//! (any shape and rank). Every operation is `row_i ← m·row_i − q·row_k` (and the
//! same on columns) with `m ∈ R \ {0}` (a unit of K = Q(others)) and
//! `q ∈ R[λ]` from a pseudo-division in λ, so U′ and V′ stay polynomial
//! and `U′·A·V′ = diag(e_1, …, e_r, 0, …)` over Q\[all\], with det U′ and det V′
//! nonzero elements of R and e_i | e_(i+1) over K\[λ\]. The content in R of
//! each changed row (column), taken over the working matrix and U′ (V′)
//! together, is divided out, which keeps the entries near the size of the
//! minors. Nothing here is trusted: [`super::certify_several::
//! certify_principal_degrees`] checks the result from scratch. This module
//! must not certify, choose a mode or print.

use crate::algebra::gcd::{gcd, gcd_cofactors, primitive_part_in};
use crate::algebra::matrix::Matrix;
use crate::algebra::mpoly::{MPoly, sum_of_products};
use crate::algebra::polyring::PolyRing;
use crate::algebra::ratfunc::{RatFunc, RatFuncField};
use crate::algebra::rational::primitive_scale;
use crate::algebra::upoly::UPolyRing;

/// `U′·A·V′ = diag(e)` over Q\[all\] (not yet certified).
#[derive(Clone, Debug)]
pub struct FractionFree {
    /// Row transform, polynomial.
    pub u: Matrix<PolyRing>,
    /// Column transform, polynomial.
    pub v: Matrix<PolyRing>,
    /// The nonzero diagonal (length the rank), each entry dividing the
    /// next over K\[λ\]; the rest of `U′·A·V′` is zero.
    pub e: Vec<MPoly>,
}

/// Gives up after this many pivot rounds (a safeguard; a round lowers the
/// pivot's degree in λ or finishes a column, so honest inputs need few).
const MAX_ROUNDS: usize = 10_000;

/// Gives up when the working matrix and the transforms together hold more
/// than this many bits of coefficients (numerators and denominators). The
/// contents removed from each line keep the entries near minor size only
/// when the transforms' lines have content too; when they do not, a
/// remainder sequence in λ swells exponentially (a 2×3 in three symbols of
/// degree ≤ 3 with 60-digit rational coefficients, found by timing the
/// property strategies: 0.4 Mbit after 5 rounds, 7 Mbit after 6, and the
/// 7th round's gcds ran for minutes). The caller then certifies the
/// invariant factors without transforms where it can.
pub const SIZE_LIMIT_BITS: u64 = 2_000_000;

/// Also gives up when a round multiplies the bits held by more than
/// [`SWELL_FACTOR`] and ends above this size: the next round then costs
/// far more than all before it (the 2×3 above: ×11 to 0.9 Mbit, the next
/// round alone 7 s CPU; a 3×2 of the same kind: ×7.7 to 0.27 Mbit, the
/// next round 6 s). On 64 seeded random 2×2–5×5 inputs in 2–3 symbols
/// (`benches/multi_peers.py`, degrees 1–2, 4 seeds) that finish, no round
/// above this floor grew the size more than ×3.1 (×5.9 below it), and the
/// largest size reached was 0.7 Mbit (4.2 s CPU).
pub const SWELL_FLOOR_BITS: u64 = 256_000;

/// See [`SWELL_FLOOR_BITS`].
pub const SWELL_FACTOR: u64 = 6;

/// Also gives up when one round multiplies the bits held by more than
/// [`JUMP_FACTOR`] and ends above this size. On seeded 4×5 inputs in three
/// symbols of degree 6 (`benches/principal_grid.py --ns 4 --nvs 3 --degs 6
/// --extra-cols 1`, seeds 1–6), none of which finishes under the size
/// limit, five jumped ×9.4–×49 to 54–204 kbit, and the next round took up
/// to 3.8 s by itself before the limit stopped it. Over the 192 seeded
/// 2×2–5×6 inputs of degree 1–3 in 2–3 symbols of the same script, the
/// 27 that finish and take over 0.3 s grew at most ×7.6 in a round ending
/// above this floor (×5.2 but for one).
pub const JUMP_FLOOR_BITS: u64 = 32_000;

/// See [`JUMP_FLOOR_BITS`].
pub const JUMP_FACTOR: u64 = 8;

struct Work {
    m: Vec<Vec<MPoly>>,
    u: Vec<Vec<MPoly>>,
    v: Vec<Vec<MPoly>>,
    rows: usize,
    cols: usize,
    p: usize,
}

fn deg(e: &MPoly, p: usize) -> Option<u32> {
    e.degree_in(p)
}

/// `(m, q)` with `m·b − q·a` of λ-degree below that of `a`, m ∈ R \ {0}.
fn pseudo_quotient(b: &MPoly, a: &MPoly, p: usize) -> (MPoly, MPoly) {
    let nv = a.nvars();
    let da = deg(a, p).unwrap_or(0);
    let la = a.lc_in(p);
    let la_const = la.as_constant();
    let mut m = MPoly::one(nv);
    let mut q = MPoly::zero(nv);
    let mut r = b.clone();
    while let Some(dr) = deg(&r, p) {
        if dr < da {
            break;
        }
        let lr = r.lc_in(p);
        let (ma, mr) = match &la_const {
            Some(c) => (MPoly::one(nv), lr.scale(&c.recip())),
            None => {
                let g = gcd(&la, &lr);
                (
                    la.div_exact(&g).unwrap_or_else(|| la.clone()),
                    lr.div_exact(&g).unwrap_or(lr.clone()),
                )
            }
        };
        let t = mr.shift(p, dr - da);
        r = &(&ma * &r) - &(&t * a);
        q = &(&ma * &q) + &t;
        m = &ma * &m;
    }
    (m, q)
}

/// A test of whether `pivot` (nonzero) divides an entry over K\[λ\],
/// K = Q(others). Its primitive part P in R\[λ\] (R = Q\[others\]) is
/// taken once; by Gauss's lemma P divides `f` over K\[λ\] exactly when it
/// divides `f` over R\[λ\], which is one exact division over Q\[all\]. A
/// pseudo-remainder would instead multiply `f` by a power of the pivot's
/// leading coefficient, and its coefficients swell.
fn divides_over_k(pivot: &MPoly, p: usize) -> impl Fn(&MPoly) -> bool + use<> {
    let d = deg(pivot, p).unwrap_or(0);
    let prim = (d > 0).then(|| primitive_part_in(pivot, p));
    move |f: &MPoly| match &prim {
        _ if f.is_zero() => true,
        None => true,
        Some(_) if deg(f, p).unwrap_or(0) < d => false,
        Some(q) => f.div_exact(q).is_some(),
    }
}

/// Divides the nonzero entries of `line` by their gcd in Q[all] and scales
/// them to coprime integer coefficients.
///
/// The entries go smallest first: the running gcd is then small early, and
/// every later step has one small argument. An entry the running gcd `g`
/// divides costs one exact division, whose quotient is kept; otherwise
/// [`gcd_cofactors`] gives the smaller gcd `g′` with the entry's quotient.
/// A quotient by an earlier `g` becomes one by the final gcd through a
/// product with `g / g_final` (small), so no entry is divided twice.
fn reduce_line(line: &mut [&mut MPoly]) {
    let mut order: Vec<usize> = (0..line.len()).filter(|&i| !line[i].is_zero()).collect();
    order.sort_by_key(|&i| line[i].terms().len());
    // Every gcd taken, and per entry its quotient by one of them.
    let mut gs: Vec<MPoly> = Vec::new();
    let mut quotients: Vec<(usize, usize, MPoly)> = Vec::new();
    for &i in &order {
        let e = &*line[i];
        let Some(g) = gs.last() else {
            let g = e.primitive_normal();
            if g.is_nonzero_constant() {
                break;
            }
            let c = e.leading().expect("nonzero").1.clone() / &g.leading().expect("nonzero").1;
            quotients.push((i, 0, MPoly::constant(c, e.nvars())));
            gs.push(g);
            continue;
        };
        if let Some(q) = e.div_exact(g) {
            quotients.push((i, gs.len() - 1, q));
            continue;
        }
        let (g2, _, q) = gcd_cofactors(g, e);
        if g2.is_nonzero_constant() {
            gs.clear();
            break;
        }
        quotients.push((i, gs.len(), q));
        gs.push(g2);
    }
    // A constant gcd is never kept: `gs` is empty then.
    if let Some(last) = gs.last() {
        // g_k / g_final for every gcd taken (each divides the one before).
        let ratios: Vec<MPoly> = gs
            .iter()
            .map(|g| g.div_exact(last).expect("the final gcd divides every earlier one"))
            .collect();
        for (i, k, q) in quotients {
            *line[i] = if k + 1 == ratios.len() { q } else { &q * &ratios[k] };
        }
    }
    let s = primitive_scale(line.iter().flat_map(|e| e.terms().iter().map(|(_, c)| c)));
    if !num_traits::Zero::is_zero(&s) && !num_traits::One::is_one(&s) {
        for e in line.iter_mut() {
            **e = e.scale(&s);
        }
    }
}

/// `m·x − q·y`, summed once ([`sum_of_products`]).
fn m_minus_q(m: &MPoly, x: &MPoly, q: &MPoly, y: &MPoly) -> MPoly {
    sum_of_products(m.nvars(), &[(m, x, false), (q, y, true)])
}

impl Work {
    /// Bits of coefficients held by the working matrix and the transforms.
    fn size_bits(&self) -> u64 {
        self.m
            .iter()
            .chain(&self.u)
            .chain(&self.v)
            .flatten()
            .flat_map(|e| e.terms().iter())
            .map(|(_, c)| c.numer().bits() + c.denom().bits())
            .sum()
    }

    fn row_op(&mut self, i: usize, k: usize, m: &MPoly, q: &MPoly) {
        for j in 0..self.cols {
            let a = m_minus_q(m, &self.m[i][j], q, &self.m[k][j]);
            self.m[i][j] = a;
        }
        for j in 0..self.rows {
            let b = m_minus_q(m, &self.u[i][j], q, &self.u[k][j]);
            self.u[i][j] = b;
        }
        let (mi, ui) = (&mut self.m[i], &mut self.u[i]);
        let mut line: Vec<&mut MPoly> = mi.iter_mut().chain(ui.iter_mut()).collect();
        reduce_line(&mut line);
    }

    fn col_op(&mut self, j: usize, k: usize, m: &MPoly, q: &MPoly) {
        for i in 0..self.rows {
            let a = m_minus_q(m, &self.m[i][j], q, &self.m[i][k]);
            self.m[i][j] = a;
        }
        for i in 0..self.cols {
            let b = m_minus_q(m, &self.v[i][j], q, &self.v[i][k]);
            self.v[i][j] = b;
        }
        let mut line: Vec<&mut MPoly> = self
            .m
            .iter_mut()
            .map(|r| &mut r[j])
            .chain(self.v.iter_mut().map(|r| &mut r[j]))
            .collect();
        reduce_line(&mut line);
    }

    /// The nonzero entry of least λ-degree (then fewest terms) in the
    /// active block.
    fn pivot(&self, k: usize) -> Option<(usize, usize)> {
        let mut best: Option<((u32, usize), (usize, usize))> = None;
        for i in k..self.rows {
            for j in k..self.cols {
                let e = &self.m[i][j];
                if let Some(d) = deg(e, self.p) {
                    let key = (d, e.terms().len());
                    if best.as_ref().is_none_or(|(b, _)| key < *b) {
                        best = Some((key, (i, j)));
                    }
                }
            }
        }
        best.map(|(_, ij)| ij)
    }
}

/// The fraction-free Smith elimination of `a` over `Q[others][λ]`, λ the
/// symbol with index `p` (any shape and rank); `None` only if a safeguard
/// stops it: the number of rounds, the size of the entries
/// ([`SIZE_LIMIT_BITS`]), or their growth in one round
/// ([`SWELL_FACTOR`], [`JUMP_FACTOR`]).
pub fn eliminate_fraction_free(a: &Matrix<PolyRing>, p: usize) -> Option<FractionFree> {
    eliminate_fraction_free_within(a, p, SIZE_LIMIT_BITS)
}

/// [`eliminate_fraction_free`] with a given limit on the bits held.
pub fn eliminate_fraction_free_within(
    a: &Matrix<PolyRing>,
    p: usize,
    limit_bits: u64,
) -> Option<FractionFree> {
    let (rows, cols) = (a.rows(), a.cols());
    let nv = a.ring.nvars();
    let id = |n: usize| -> Vec<Vec<MPoly>> {
        (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| {
                        if i == j {
                            MPoly::one(nv)
                        } else {
                            MPoly::zero(nv)
                        }
                    })
                    .collect()
            })
            .collect()
    };
    let mut w = Work {
        m: (0..rows).map(|i| a.row(i).to_vec()).collect(),
        u: id(rows),
        v: id(cols),
        rows,
        cols,
        p,
    };
    let mut rounds = 0usize;
    let mut rank = 0usize;
    let mut last_size = u64::MAX;
    for k in 0..rows.min(cols) {
        loop {
            rounds += 1;
            if rounds > MAX_ROUNDS {
                return None;
            }
            let size = w.size_bits();
            let grew = |floor: u64, factor: u64| {
                size > floor && size > factor.saturating_mul(last_size)
            };
            if size > limit_bits
                || grew(SWELL_FLOOR_BITS, SWELL_FACTOR)
                || grew(JUMP_FLOOR_BITS, JUMP_FACTOR)
            {
                return None;
            }
            last_size = size;
            let Some((pi, pj)) = w.pivot(k) else {
                break;
            };
            w.m.swap(k, pi);
            w.u.swap(k, pi);
            for row in w.m.iter_mut() {
                row.swap(k, pj);
            }
            for row in w.v.iter_mut() {
                row.swap(k, pj);
            }
            let pivot = w.m[k][k].clone();
            let mut dirty = false;
            for i in k + 1..rows {
                if w.m[i][k].is_zero() {
                    continue;
                }
                let (m, q) = pseudo_quotient(&w.m[i][k], &pivot, p);
                w.row_op(i, k, &m, &q);
                if w.size_bits() > limit_bits {
                    return None;
                }
                dirty |= !w.m[i][k].is_zero();
            }
            if dirty {
                continue;
            }
            let pivot = w.m[k][k].clone();
            for j in k + 1..cols {
                if w.m[k][j].is_zero() {
                    continue;
                }
                let (m, q) = pseudo_quotient(&w.m[k][j], &pivot, p);
                w.col_op(j, k, &m, &q);
                if w.size_bits() > limit_bits {
                    return None;
                }
                dirty |= !w.m[k][j].is_zero();
            }
            if dirty {
                continue;
            }
            // The pivot must divide every remaining entry over K[λ].
            let divides = divides_over_k(&w.m[k][k], p);
            let bad = (k + 1..rows).find(|&i| (k + 1..cols).any(|j| !divides(&w.m[i][j])));
            match bad {
                Some(i) => {
                    let one = MPoly::one(nv);
                    let minus_one = -&one;
                    // row_k ← row_k + row_i.
                    w.row_op(k, i, &one, &minus_one);
                }
                None => {
                    rank = k + 1;
                    break;
                }
            }
        }
        if rank != k + 1 {
            break;
        }
    }
    let e: Vec<MPoly> = (0..rank).map(|i| w.m[i][i].clone()).collect();
    let flat = |m: Vec<Vec<MPoly>>| m.into_iter().flatten().collect::<Vec<_>>();
    Some(FractionFree {
        u: Matrix::new(a.ring.clone(), rows, rows, flat(w.u)),
        v: Matrix::new(a.ring.clone(), cols, cols, flat(w.v)),
        e,
    })
}

/// `(U, D, V)` over K\[λ\] from a fraction-free result: `D = diag(e_i /
/// lc_λ(e_i))` (monic), `U = diag(1/lc_λ(e_i))·U′`, `V = V′`; so `U·A·V =
/// D` whenever `U′·A·V′ = diag(e)`.
pub fn over_k(
    ff: &FractionFree,
    kr: &UPolyRing<RatFuncField>,
    p: usize,
) -> Option<[Matrix<UPolyRing<RatFuncField>>; 3]> {
    let (rows, cols) = (ff.u.rows(), ff.v.rows());
    let nv = ff.u.ring.nvars();
    let to_k = |e: &MPoly| kr.trim(e.coeffs_in(p).into_iter().map(RatFunc::from_poly).collect());
    let mut d = Matrix::zeros(kr.clone(), rows, cols);
    let mut u = ff.u.map(kr.clone(), to_k);
    for (i, e) in ff.e.iter().enumerate() {
        let s = RatFunc::new(MPoly::one(nv), e.lc_in(p))?;
        d.set(i, i, kr.scale(&to_k(e), &s));
        for j in 0..rows {
            let x = kr.scale(u.get(i, j), &s);
            u.set(i, j, x);
        }
    }
    let v = ff.v.map(kr.clone(), to_k);
    Some([u, d, v])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::rational::qi;

    #[test]
    fn fraction_free_product_is_the_diagonal() {
        let ring = PolyRing::new(vec!["x".into(), "y".into()]);
        let (x, y) = (MPoly::var(0, 2), MPoly::var(1, 2));
        let one = MPoly::one(2);
        let a = Matrix::new(
            ring,
            3,
            3,
            vec![
                &x * &y + &one,
                y.clone(),
                &x - &y,
                y.pow(2),
                &x + &y.scale(&qi(3)),
                one.clone(),
                &x * &y,
                MPoly::zero(2),
                &y * &y - &one,
            ],
        );
        let ff = eliminate_fraction_free(&a, 1).expect("nonsingular");
        let prod = ff.u.mul(&a).and_then(|m| m.mul(&ff.v)).expect("shapes");
        for i in 0..3 {
            for j in 0..3 {
                let want = if i == j {
                    ff.e[i].clone()
                } else {
                    MPoly::zero(2)
                };
                assert_eq!(prod.get(i, j), &want, "entry {i},{j}");
            }
        }
    }

    #[test]
    fn divisibility_over_k_agrees_with_the_pseudo_remainder() {
        use crate::algebra::gcd::prem;
        let (x, y, z) = (MPoly::var(0, 3), MPoly::var(1, 3), MPoly::var(2, 3));
        let one = MPoly::one(3);
        // Pivots over Q[x, y][z] (λ = z), with a content free of z, none,
        // or of degree 0 in z (a unit over K).
        let pivots = [
            &(&x + &one) * &(&z - &y),
            &(&x * &z) + &y,
            &z * &z - &(&x * &y),
            &x * &y + &one,
        ];
        let fs = [
            &(&z - &y) * &z,
            &(&(&x * &z) + &y) * &(&y * &z + &x),
            &(&z * &z - &(&x * &y)) * &(&x + &y),
            &z * &z + &x,
            &y * &z - &(&x * &y),
            x.clone(),
            MPoly::zero(3),
        ];
        let mut divisible = 0;
        for pivot in &pivots {
            let divides = divides_over_k(pivot, 2);
            for f in &fs {
                let want = prem(f, pivot, 2).is_zero();
                assert_eq!(divides(f), want, "{f:?} by {pivot:?}");
                divisible += usize::from(want);
            }
        }
        // Both answers occur, so the comparison means something.
        assert!((8..28).contains(&divisible), "{divisible} divisible");
    }

    #[test]
    fn singular_input_has_its_rank() {
        let ring = PolyRing::new(vec!["x".into(), "y".into()]);
        let (x, y) = (MPoly::var(0, 2), MPoly::var(1, 2));
        let a = Matrix::new(ring, 2, 2, vec![x.clone(), y.clone(), &x * &y, &y * &y]);
        let ff = eliminate_fraction_free(&a, 1).expect("finishes");
        assert_eq!(ff.e.len(), 1);
        let prod = ff.u.mul(&a).and_then(|m| m.mul(&ff.v)).expect("shapes");
        assert_eq!(prod.get(0, 0), &ff.e[0]);
        for (i, j) in [(0, 1), (1, 0), (1, 1)] {
            assert!(prod.get(i, j).is_zero());
        }
    }
}
