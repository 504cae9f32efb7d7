//! Dense solves that refuse to return meaningless numbers: LU with column
//! equilibration and a Hager–Higham estimate of the 1-norm condition number;
//! a singular or too ill-conditioned system is a [`NumericError`], never a
//! result. Also least squares for systems with more rows than unknowns
//! (equations plus side conditions), by SVD with the same conditioning
//! check, and block-matrix assembly helpers; and the rounding floor every
//! ladder's estimates keep ([`rounding_floor`]). This file owns linear
//! algebra only; it must not assemble operators.
use nalgebra::{DMatrix, DVector};

use super::error::NumericError;
use super::lu::DenseLu;

/// Default limit on the (equilibrated) condition number: beyond it a
/// double-precision solve cannot promise even a few correct digits.
pub const DEFAULT_MAX_COND: f64 = 1e13;

/// Above this (1-norm) condition estimate a square system's singular
/// values are computed to look for a null direction ([`null_direction`]).
const NULL_PROBE: f64 = 1e8;
/// Largest system whose full singular values the probe computes when the
/// iterations of [`extreme_singular_values`] do not settle (the SVD costs
/// several LU factorisations; beyond this the conditioning limit alone
/// acts).
const NULL_PROBE_SIZE: usize = 1500;
/// How many of the smallest singular values the probe iterates on (two are
/// needed; the others speed up the second one's convergence).
const PROBE_BLOCK: usize = 4;
/// Relative change of successive estimates at which the probe stops.
const PROBE_SETTLED: f64 = 1e-4;
/// Most iterations of each of the probe's two iterations.
const PROBE_ITERATIONS: usize = 80;
/// A smallest singular value below this fraction of the largest ...
pub(crate) const NULL_SMALLEST: f64 = 1e-10;
/// ... and below this fraction of the next one, ...
const NULL_GAP: f64 = 1e-3;
/// ... while the next one is above this fraction of the largest (the rest
/// of the spectrum is resolved), is a null direction.
pub(crate) const NULL_NEXT: f64 = 1e-6;

/// The two smallest singular values over the largest when the smallest is
/// isolated (below `NULL_GAP` of the next), tiny (below
/// `NULL_SMALLEST` of the largest) and the next is not (above
/// `NULL_NEXT`): a discrete null space. A well-posed problem's
/// ill-conditioning grows with the discretisation but spreads over many
/// singular values (a Hilbert matrix's fall steadily to rounding, where
/// the smallest ones are noise); a null direction is one value apart.
pub fn null_direction(singular_values: &[f64]) -> Option<(f64, f64)> {
    let mut sv: Vec<f64> = singular_values.to_vec();
    sv.sort_by(|a, b| b.total_cmp(a));
    let (&largest, rest) = sv.split_first()?;
    let [.., next, smallest] = rest else {
        return None;
    };
    (largest > 0.0
        && *smallest < NULL_SMALLEST * largest
        && *smallest < NULL_GAP * next
        && *next > NULL_NEXT * largest)
        .then(|| (smallest / largest, next / largest))
}

/// The largest and the [`PROBE_BLOCK`] smallest singular values of
/// `S = A·diag(scale)` from the factors of `S` at hand, for
/// [`null_direction`]: the largest by power iteration on `SᵀS`, the
/// smallest by subspace iteration with `(S Sᵀ)⁻¹` through the factors and
/// the singular values of `S⁻¹X` on the iterated orthonormal block `X`
/// (Ritz values: each estimate of a small singular value is at least the
/// true one, each approaches it as the block settles). Costs a few dozen
/// triangular solves with `PROBE_BLOCK` right sides, against the full SVD's
/// several factorisations. It stops as soon as the smallest value has
/// settled above twice the null threshold (no null direction, whatever the
/// next value is), else when the two smallest have settled. `None` for a
/// system of at most twice the block (its full SVD is as cheap), when an
/// estimate is not finite, or when the small ones did not settle within
/// [`PROBE_ITERATIONS`].
fn extreme_singular_values(a: &DMatrix<f64>, scale: &[f64], lu: &DenseLu) -> Option<Vec<f64>> {
    let n = scale.len();
    if n <= 2 * PROBE_BLOCK {
        return None;
    }
    let d = DVector::from_column_slice(scale);
    // Largest: ‖S x‖ for the power iterate x of SᵀS (from below).
    let mut x = DVector::from_fn(n, |i, _| 1.0 + (i % 7) as f64 / 7.0);
    x /= x.norm();
    let mut largest = 0.0;
    for _ in 0..PROBE_ITERATIONS {
        let y = a * x.component_mul(&d);
        let est = y.norm();
        let z = (a.tr_mul(&y)).component_mul(&d);
        let zn = z.norm();
        if !est.is_finite() || !zn.is_finite() || zn == 0.0 {
            return None;
        }
        x = z / zn;
        let settled = (est - largest).abs() <= PROBE_SETTLED * est;
        largest = est;
        if settled {
            break;
        }
    }
    // Smallest: subspace iteration with (S Sᵀ)⁻¹ = S⁻ᵀ S⁻¹.
    let mut word = crate::algebra::modular::lcg(0x5eed_u64 ^ n as u64);
    let start = DMatrix::from_fn(n, PROBE_BLOCK, |_, _| {
        (word() >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    });
    let mut q = start.qr().q();
    let mut prev: Vec<f64> = Vec::new();
    for _ in 0..PROBE_ITERATIONS {
        let mut y = q.clone();
        lu.solve_many(&mut y);
        let mut ritz: Vec<f64> = y.clone().singular_values().iter().map(|v| 1.0 / v).collect();
        ritz.sort_by(f64::total_cmp);
        if ritz.iter().any(|v| !v.is_finite()) {
            return None;
        }
        let close = |i: usize| prev.len() == ritz.len() && (ritz[i] - prev[i]).abs() <= PROBE_SETTLED * ritz[i];
        // A settled smallest value well above the null threshold decides
        // the test whatever the next one is.
        let decided = close(0) && ritz[0] > 2.0 * NULL_SMALLEST * largest;
        if decided || (close(0) && close(1)) {
            let mut sv = vec![largest];
            sv.extend(ritz);
            return Some(sv);
        }
        prev = ritz;
        let m = y.amax();
        if !(m.is_finite() && m > 0.0) {
            return None;
        }
        y /= m;
        lu.solve_transpose_many(&mut y);
        if y.iter().any(|v| !v.is_finite()) {
            return None;
        }
        q = y.qr().q();
    }
    None
}

/// An LU factorisation of `A·D` (`D` scales columns to unit max-norm) that
/// passed the singularity and conditioning checks.
pub struct CheckedLu {
    lu: DenseLu,
    scale: Vec<f64>,
    cond: f64,
}

impl CheckedLu {
    /// Factorises `a`; errors if it is singular, non-finite, or its
    /// estimated condition number exceeds `max_cond`.
    pub fn new(a: &DMatrix<f64>, max_cond: f64) -> Result<CheckedLu, NumericError> {
        let n = a.nrows();
        if n != a.ncols() {
            return Err(NumericError::Dimension(format!(
                "{}×{} system is not square",
                n,
                a.ncols()
            )));
        }
        if n == 0 {
            return Err(NumericError::Dimension("empty system".into()));
        }
        if a.iter().any(|v| !v.is_finite()) {
            return Err(NumericError::NonFinite("system matrix".into()));
        }
        let mut scale = vec![1.0; n];
        let mut s = a.clone();
        for (j, sc) in scale.iter_mut().enumerate() {
            let m = s.column(j).amax();
            if m == 0.0 {
                return Err(NumericError::Singular(n));
            }
            *sc = 1.0 / m;
            s.column_mut(j).scale_mut(1.0 / m);
        }
        let norm1 = (0..n).map(|j| s.column(j).lp_norm(1)).fold(0.0, f64::max);
        let lu = DenseLu::new(s)?;
        let mut me = CheckedLu {
            lu,
            scale,
            cond: f64::INFINITY,
        };
        let inv_norm = me.inverse_norm1_estimate();
        let cond = norm1 * inv_norm;
        if cond.is_nan() || cond > NULL_PROBE {
            let sv = match extreme_singular_values(a, &me.scale, &me.lu) {
                Some(sv) => sv,
                None if n <= NULL_PROBE_SIZE => {
                    let mut s = a.clone();
                    for (j, sc) in me.scale.iter().enumerate() {
                        s.column_mut(j).scale_mut(*sc);
                    }
                    s.singular_values().as_slice().to_vec()
                }
                None => Vec::new(),
            };
            if let Some((smallest, next)) = null_direction(&sv) {
                return Err(NumericError::NullSpace {
                    size: n,
                    smallest,
                    next,
                });
            }
        }
        if !cond.is_finite() || cond > max_cond {
            return Err(NumericError::IllConditioned {
                size: n,
                cond,
                limit: max_cond,
            });
        }
        me.cond = cond;
        Ok(me)
    }

    /// The estimated 1-norm condition number of the equilibrated matrix.
    pub fn cond(&self) -> f64 {
        self.cond
    }

    /// Solves `A x = b`.
    pub fn solve(&self, b: &DVector<f64>) -> Result<DVector<f64>, NumericError> {
        if b.len() != self.scale.len() {
            return Err(NumericError::Dimension(format!(
                "rhs {} for system {}",
                b.len(),
                self.scale.len()
            )));
        }
        let mut y = self.lu.solve(b);
        for (v, s) in y.iter_mut().zip(&self.scale) {
            *v *= s;
        }
        if y.iter().any(|v| !v.is_finite()) {
            return Err(NumericError::NonFinite("solution".into()));
        }
        Ok(y)
    }

    /// Solves `Aᵀ x = b` (`A = S·D⁻¹` with `S` the equilibrated matrix
    /// factorised, so `x = S⁻ᵀ·D·b`).
    pub fn solve_transpose(&self, b: &DVector<f64>) -> DVector<f64> {
        let db = DVector::from_iterator(b.len(), b.iter().zip(&self.scale).map(|(v, s)| v * s));
        self.lu.solve_transpose(&db)
    }

    /// Solves `Aᵀ X = B` in place for every column of `x`, each column
    /// exactly as [`CheckedLu::solve_transpose`] solves it.
    pub fn solve_transpose_many(&self, x: &mut DMatrix<f64>) {
        for mut col in x.column_iter_mut() {
            for (v, s) in col.iter_mut().zip(&self.scale) {
                *v *= s;
            }
        }
        self.lu.solve_transpose_many(x);
    }

    /// Solves `A X = B` column by column.
    pub fn solve_matrix(&self, b: &DMatrix<f64>) -> Result<DMatrix<f64>, NumericError> {
        let mut out = DMatrix::zeros(b.nrows(), b.ncols());
        for j in 0..b.ncols() {
            let x = self.solve(&b.column(j).into_owned())?;
            out.set_column(j, &x);
        }
        Ok(out)
    }

    /// Hager's estimate of `‖S⁻¹‖₁` for the equilibrated `S`.
    fn inverse_norm1_estimate(&self) -> f64 {
        let n = self.scale.len();
        let mut x = DVector::from_element(n, 1.0 / n as f64);
        let mut est: f64 = 0.0;
        for _ in 0..5 {
            let y = self.lu.solve(&x);
            est = y.lp_norm(1);
            let xi = y.map(|v| if v >= 0.0 { 1.0 } else { -1.0 });
            let z = self.lu.solve_transpose(&xi);
            let (jmax, zmax) = z.iter().enumerate().fold((0, 0.0), |acc, (j, v)| {
                if v.abs() > acc.1 { (j, v.abs()) } else { acc }
            });
            if zmax <= z.dot(&x) {
                break;
            }
            x = DVector::zeros(n);
            x[jmax] = 1.0;
        }
        if est.is_finite() { est } else { f64::INFINITY }
    }
}

/// Solves `A x = b` with the default conditioning limit.
#[cfg(feature = "internals")]
pub fn solve(a: &DMatrix<f64>, b: &DVector<f64>) -> Result<DVector<f64>, NumericError> {
    CheckedLu::new(a, DEFAULT_MAX_COND)?.solve(b)
}

/// Stacks blocks `rows[i][j]` into one matrix (all blocks of a block row
/// share their row count, all of a block column their column count).
pub fn block_matrix(rows: &[Vec<&DMatrix<f64>>]) -> Result<DMatrix<f64>, NumericError> {
    let Some(first) = rows.first() else {
        return Err(NumericError::Dimension("no block rows".into()));
    };
    let widths: Vec<usize> = first.iter().map(|b| b.ncols()).collect();
    let heights: Vec<usize> = rows
        .iter()
        .map(|r| r.first().map_or(0, |b| b.nrows()))
        .collect();
    let mut out = DMatrix::zeros(heights.iter().sum(), widths.iter().sum());
    let mut r0 = 0;
    for (i, row) in rows.iter().enumerate() {
        if row.len() != widths.len() {
            return Err(NumericError::Dimension(format!(
                "block row {i} has {} blocks",
                row.len()
            )));
        }
        let mut c0 = 0;
        for (j, b) in row.iter().enumerate() {
            if b.nrows() != heights[i] || b.ncols() != widths[j] {
                return Err(NumericError::Dimension(format!(
                    "block ({i},{j}) is {}×{}, expected {}×{}",
                    b.nrows(),
                    b.ncols(),
                    heights[i],
                    widths[j]
                )));
            }
            out.view_mut((r0, c0), (b.nrows(), b.ncols())).copy_from(b);
            c0 += widths[j];
        }
        r0 += heights[i];
    }
    Ok(out)
}

/// The factors of a least-squares solve (the SVD `a·D = U Σ Vᵀ` of the
/// column-scaled matrix), for adjoint rounding bounds of functionals of
/// its solution.
pub struct LeastSquares {
    u: DMatrix<f64>,
    sigma: DVector<f64>,
    v_t: DMatrix<f64>,
    scale: Vec<f64>,
}

impl LeastSquares {
    /// `Vᵀ·D·l`, the functional `l` in the right singular basis.
    fn right(&self, l: &DVector<f64>) -> DVector<f64> {
        let dl = DVector::from_iterator(l.len(), l.iter().zip(&self.scale).map(|(v, s)| v * s));
        &self.v_t * dl
    }

    /// `(a⁺)ᵀ·l = U Σ⁻¹ Vᵀ D l`: how the functional `lᵀx` of the solution
    /// moves with the right side (`δ(lᵀx) = ((a⁺)ᵀl)ᵀ·δb`).
    pub fn adjoint(&self, l: &DVector<f64>) -> DVector<f64> {
        let mut w = self.right(l);
        for (w, s) in w.iter_mut().zip(self.sigma.iter()) {
            *w /= s;
        }
        &self.u * w
    }

    /// `(aᵀa)⁻¹·l = D V Σ⁻² Vᵀ D l`: how `lᵀx` moves with the matrix
    /// through the residual (`δ(lᵀx) ∋ ((aᵀa)⁻¹l)ᵀ·δaᵀ·r`).
    pub fn normal_inverse(&self, l: &DVector<f64>) -> DVector<f64> {
        let mut w = self.right(l);
        for (w, s) in w.iter_mut().zip(self.sigma.iter()) {
            *w /= s * s;
        }
        let x = self.v_t.transpose() * w;
        DVector::from_iterator(x.len(), x.iter().zip(&self.scale).map(|(v, s)| v * s))
    }
}

/// A least-squares solution of `a·x ≈ b` (more rows than columns): the
/// solution, the 2-norm condition number of `a·D` (`D` scales columns to
/// unit max-norm), the relative residual `‖a·x - b‖∞ / ‖b‖∞` (zero when
/// `b = 0`), which is rounding-small exactly when the rows are consistent,
/// and the factors ([`LeastSquares`]). Errors if `a` is rank-deficient or
/// worse conditioned than `max_cond`.
pub fn least_squares(
    a: &DMatrix<f64>,
    b: &DVector<f64>,
    max_cond: f64,
) -> Result<(DVector<f64>, f64, f64, LeastSquares), NumericError> {
    let (m, n) = a.shape();
    if m < n || b.len() != m {
        return Err(NumericError::Dimension(format!(
            "least squares of a {m}×{n} system with {} right sides",
            b.len()
        )));
    }
    if a.iter().chain(b.iter()).any(|v| !v.is_finite()) {
        return Err(NumericError::NonFinite("least-squares system".into()));
    }
    let scale: Vec<f64> = (0..n)
        .map(|j| {
            let c = a.column(j).amax();
            if c > 0.0 { 1.0 / c } else { 1.0 }
        })
        .collect();
    let mut scaled = a.clone();
    for (j, s) in scale.iter().enumerate() {
        scaled.column_mut(j).scale_mut(*s);
    }
    let svd = scaled.svd(true, true);
    let sv = &svd.singular_values;
    let (smax, smin) = (sv.max(), sv.min());
    if let Some((smallest, next)) = null_direction(sv.as_slice()) {
        return Err(NumericError::NullSpace {
            size: n,
            smallest,
            next,
        });
    }
    if smin <= 0.0 {
        return Err(NumericError::Singular(n));
    }
    let cond = smax / smin;
    if cond.is_nan() || cond > max_cond {
        return Err(NumericError::IllConditioned {
            size: n,
            cond,
            limit: max_cond,
        });
    }
    let y = svd
        .solve(b, 0.0)
        .map_err(|e| NumericError::InvalidArgument(format!("least squares: {e}")))?;
    let x = DVector::from_iterator(n, y.iter().zip(&scale).map(|(v, s)| v * s));
    let bn = b.amax();
    let residual = if bn > 0.0 {
        (a * &x - b).amax() / bn
    } else {
        0.0
    };
    let (Some(u), Some(v_t)) = (svd.u, svd.v_t) else {
        return Err(NumericError::InvalidArgument(
            "least squares: the SVD has no singular vectors".into(),
        ));
    };
    let factors = LeastSquares {
        u,
        sigma: svd.singular_values,
        v_t,
        scale,
    };
    Ok((x, cond, residual, factors))
}

/// The smallest error estimate reported: below it, distances between
/// levels are rounding noise and say nothing about the error (measured:
/// true errors of 1.2e-14 beside distances of 1.1e-14).
pub const ROUNDING_FLOOR: f64 = 1e-13;

/// Rounding errors of a solve grow with the condition number `κ` of its
/// matrix: the estimate is at least `ROUNDING_GROWTH · ε · κ` (relative to
/// the solution's scale, like the distances between levels). Measured on
/// the kernel-class cases (`tests/kernel_classes.rs`): true errors between
/// 1·εκ and 7·εκ (the airfoil with a side condition: 4.7e-12 at
/// κ = 4.0e3, where levels 5 and 6 differed by only 1.7e-12), so the
/// factor leaves a margin of at least 4.
pub const ROUNDING_GROWTH: f64 = 32.0;

/// The rounding floor of an answer whose matrices have condition `cond`.
pub fn rounding_floor(cond: f64) -> f64 {
    let grown = ROUNDING_GROWTH * f64::EPSILON * cond;
    if grown.is_finite() {
        grown.max(ROUNDING_FLOOR)
    } else {
        ROUNDING_FLOOR
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_and_estimates_condition() {
        let a = DMatrix::from_row_slice(3, 3, &[4.0, 1.0, 0.0, 1.0, 3.0, 1.0, 0.0, 1.0, 2.0]);
        let b = DVector::from_vec(vec![1.0, 2.0, 3.0]);
        let lu = CheckedLu::new(&a, 1e12).unwrap();
        let x = lu.solve(&b).unwrap();
        assert!((&a * &x - &b).amax() < 1e-14);
        assert!(lu.cond() > 1.0 && lu.cond() < 10.0);
    }

    #[test]
    fn singular_and_ill_conditioned_are_errors() {
        let a = DMatrix::from_row_slice(2, 2, &[1.0, 2.0, 2.0, 4.0]);
        assert!(CheckedLu::new(&a, 1e12).is_err());
        let a = DMatrix::from_row_slice(2, 2, &[1.0, 1.0, 1.0, 1.0 + 1e-15]);
        assert!(matches!(
            CheckedLu::new(&a, 1e12),
            Err(NumericError::IllConditioned { .. }) | Err(NumericError::Singular(_))
        ));
        let z = DMatrix::<f64>::zeros(2, 2);
        assert_eq!(
            CheckedLu::new(&z, 1e12).err(),
            Some(NumericError::Singular(2))
        );
    }

    #[test]
    fn hilbert_condition_is_detected() {
        let n = 12;
        let h = DMatrix::from_fn(n, n, |i, j| 1.0 / (i + j + 1) as f64);
        assert!(matches!(
            CheckedLu::new(&h, 1e10),
            Err(NumericError::IllConditioned { .. })
        ));
    }

    #[test]
    fn an_isolated_tiny_singular_value_is_a_null_direction() {
        // f - 3x∫_0^1 t f dt annihilates f = x: on the monomials 1, x, x²
        // (collocation at 0, 1/2, 1) the system is singular up to rounding.
        let k = |i: usize, x: f64| {
            let moment = 1.0 / (i as f64 + 2.0);
            x.powi(i as i32) - 3.0 * x * moment
        };
        let pts = [0.0, 0.5, 1.0];
        let a = DMatrix::from_fn(3, 3, |r, c| k(c, pts[r]));
        assert!(matches!(
            CheckedLu::new(&a, 1e13),
            Err(NumericError::NullSpace { .. }) | Err(NumericError::Singular(_))
        ));
        // A spread of small singular values (Hilbert) is ill-conditioning,
        // not a null direction.
        for n in [8, 12, 14] {
            let h = DMatrix::from_fn(n, n, |i, j| 1.0 / (i + j + 1) as f64);
            assert_eq!(null_direction(h.singular_values().as_slice()), None);
        }
        assert!(null_direction(&[1.0, 0.5, 1e-13]).is_some());
        assert_eq!(null_direction(&[1.0, 1e-9, 1e-13]), None);
        assert_eq!(null_direction(&[1.0, 0.5, 1e-9]), None);
    }

    /// `U·diag(sv)·Vᵀ` with orthogonal `U`, `V` from seeded QRs.
    fn with_spectrum(sv: &[f64], seed: u64) -> DMatrix<f64> {
        let n = sv.len();
        let mut word = crate::algebra::modular::lcg(seed);
        let mut orth = || {
            let m = DMatrix::from_fn(n, n, |_, _| (word() >> 11) as f64 / (1u64 << 53) as f64 - 0.5);
            m.qr().q()
        };
        let (u, v) = (orth(), orth());
        u * DMatrix::from_diagonal(&DVector::from_column_slice(sv)) * v.transpose()
    }

    #[test]
    fn the_probe_matches_the_full_svd() {
        // Spectra: a planted null direction (isolated, tiny), a gap too
        // small to count, a steady fall to rounding, two tiny values, and
        // a well-conditioned one; plus Hilbert matrices (above twice the
        // block, where the probe iterates).
        let n = 60;
        let steady: Vec<f64> = (0..n).map(|i| 10f64.powf(-14.0 * i as f64 / (n - 1) as f64)).collect();
        let mut planted: Vec<f64> = (0..n).map(|i| 1.0 - 0.9 * i as f64 / n as f64).collect();
        planted[n - 1] = 1e-15;
        let mut small_gap = planted.clone();
        small_gap[n - 1] = 1e-2;
        let mut two = planted.clone();
        two[n - 2] = 3e-15;
        let flat: Vec<f64> = (0..n).map(|i| 2.0 - i as f64 / n as f64).collect();
        // The next value near its threshold (1e-6 of the largest), on
        // either side, above a smallest of 5e-12.
        let near = |next: f64| {
            let mut sv = planted.clone();
            sv[n - 3] = 3.0 * next;
            sv[n - 2] = next;
            sv[n - 1] = 5e-12;
            sv
        };
        let (above, below) = (near(3e-6), near(3e-7));
        let mut cases: Vec<(DMatrix<f64>, Option<bool>)> = [
            (&planted, Some(true)),
            (&small_gap, Some(false)),
            (&steady, Some(false)),
            (&two, Some(false)),
            (&flat, Some(false)),
            (&above, Some(true)),
            (&below, Some(false)),
        ]
            .into_iter()
            .enumerate()
            .map(|(k, (sv, want))| (with_spectrum(sv, 0x5eed + k as u64), want))
            .collect();
        for m in [10, 12, 14] {
            cases.push((DMatrix::from_fn(m, m, |i, j| 1.0 / (i + j + 1) as f64), Some(false)));
        }
        let mut compared = 0;
        for (k, (a, want)) in cases.iter().enumerate() {
            let m = a.nrows();
            let scale: Vec<f64> = (0..m).map(|j| 1.0 / a.column(j).amax()).collect();
            let mut s = a.clone();
            for (j, sc) in scale.iter().enumerate() {
                s.column_mut(j).scale_mut(*sc);
            }
            let lu = DenseLu::new(s.clone()).unwrap();
            let full = s.singular_values();
            let Some(probe) = extreme_singular_values(a, &scale, &lu) else {
                panic!("case {k}: the probe did not settle");
            };
            let decided = null_direction(&probe).is_some();
            assert_eq!(decided, null_direction(full.as_slice()).is_some(), "case {k}");
            if let Some(w) = want {
                assert_eq!(decided, *w, "case {k}");
            }
            let mut f: Vec<f64> = full.iter().copied().collect();
            f.sort_by(|x, y| y.total_cmp(x));
            // From below, within a few per cent: the test's thresholds are
            // orders of magnitude apart.
            assert!(probe[0] <= f[0] * (1.0 + 1e-12) && probe[0] >= 0.95 * f[0], "case {k}: largest {} against {}", probe[0], f[0]);
            // The smallest estimates are at or above the true values, and
            // close to them where they are resolved (above rounding).
            for (i, est) in probe[1..].iter().enumerate() {
                let t = f[m - 1 - i];
                assert!(*est >= t * (1.0 - 1e-6) || t < 1e-10 * f[0], "case {k}: σ {i} {est} below {t}");
                // The next value is iterated to the end only where the
                // smallest leaves the test open.
                let needed = i == 0 || probe[1] <= 2.0 * NULL_SMALLEST * probe[0];
                if t > 1e-10 * f[0] && i < 2 && needed {
                    assert!(*est <= t * (1.0 + 1e-2), "case {k}: σ {i} {est} against {t}");
                    compared += 1;
                }
            }
        }
        assert!(compared >= 5, "only {compared} resolved values compared");
    }

    #[test]
    fn blocks_stack() {
        let a = DMatrix::from_element(1, 2, 1.0);
        let b = DMatrix::from_element(1, 1, 2.0);
        let c = DMatrix::from_element(2, 2, 3.0);
        let d = DMatrix::from_element(2, 1, 4.0);
        let m = block_matrix(&[vec![&a, &b], vec![&c, &d]]).unwrap();
        assert_eq!(m.shape(), (3, 3));
        assert_eq!(m[(0, 2)], 2.0);
        assert_eq!(m[(2, 2)], 4.0);
        assert!(block_matrix(&[vec![&a, &b], vec![&c]]).is_err());
    }

    #[test]
    fn least_squares_of_consistent_and_inconsistent_rows() {
        // x + y = 3, x - y = 1, 2x = 4: consistent, x = 2, y = 1.
        let a = DMatrix::from_row_slice(3, 2, &[1.0, 1.0, 1.0, -1.0, 2.0, 0.0]);
        let b = DVector::from_vec(vec![3.0, 1.0, 4.0]);
        let (x, cond, res, _) = least_squares(&a, &b, 1e12).unwrap();
        assert!(
            (x[0] - 2.0).abs() < 1e-15 && (x[1] - 1.0).abs() < 1e-15,
            "{x}"
        );
        assert!((1.0..10.0).contains(&cond));
        assert!(res < 1e-15);
        // 2x = 5 instead: inconsistent, and the residual says so.
        let b = DVector::from_vec(vec![3.0, 1.0, 5.0]);
        let (_, _, res, _) = least_squares(&a, &b, 1e12).unwrap();
        assert!(res > 0.05, "{res}");
        // Rank-deficient and mis-shaped systems are errors.
        let a = DMatrix::from_row_slice(3, 2, &[1.0, 2.0, 2.0, 4.0, 3.0, 6.0]);
        assert!(least_squares(&a, &b, 1e12).is_err());
        assert!(least_squares(&DMatrix::zeros(1, 2), &DVector::zeros(1), 1e12).is_err());
    }

    #[test]
    fn least_squares_factors_give_the_pseudo_inverse() {
        // Columns of very different sizes, so the column scaling matters.
        let a = DMatrix::from_row_slice(
            4,
            3,
            &[
                1.0, 200.0, 0.5, 2.0, -100.0, 0.25, 0.0, 300.0, -1.0, 3.0, 0.0, 2.0,
            ],
        );
        let b = DVector::from_vec(vec![1.0, -2.0, 0.5, 3.0]);
        let (_, _, _, f) = least_squares(&a, &b, 1e12).unwrap();
        let ata = a.transpose() * &a;
        let ata_inv = ata.clone().try_inverse().unwrap();
        let pinv = &ata_inv * a.transpose();
        let l = DVector::from_vec(vec![0.3, -1.0, 2.0]);
        let adj = f.adjoint(&l);
        let want = pinv.transpose() * &l;
        assert!((&adj - &want).amax() <= 1e-12 * want.amax(), "{adj} {want}");
        let ni = f.normal_inverse(&l);
        let want = &ata_inv * &l;
        assert!((&ni - &want).amax() <= 1e-10 * want.amax(), "{ni} {want}");
    }
}
