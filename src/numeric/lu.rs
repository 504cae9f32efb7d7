//! A blocked, right-looking LU factorisation with partial pivoting
//! (`P A = L U`, LAPACK `getrf` order of operations): narrow panels are
//! factorised column by column and the trailing matrix is updated with one
//! matrix product per panel, which nalgebra hands to `matrixmultiply`. It
//! also solves with `Aᵀ`, which the condition estimate needs. Owns the
//! factorisation only; conditioning policy lives in `solve.rs`.
use nalgebra::{DMatrix, DVector};

use super::error::NumericError;

/// Panel width of the blocked factorisation.
const NB: usize = 48;

/// `Σ aᵢbᵢ` over the common length, in four interleaved partial sums (the
/// transposed solves' inner products; one dependency chain would leave the
/// floating-point units idle).
fn dot(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    let mut acc = [0.0f64; 4];
    let (ca, cb) = (a.chunks_exact(4), b.chunks_exact(4));
    let (ra, rb) = (ca.remainder(), cb.remainder());
    for (x, y) in ca.zip(cb) {
        for i in 0..4 {
            acc[i] += x[i] * y[i];
        }
    }
    let mut tail = 0.0;
    for (x, y) in ra.iter().zip(rb) {
        tail += x * y;
    }
    (acc[0] + acc[1]) + (acc[2] + acc[3]) + tail
}

/// `P A = L U` with unit lower `L` and upper `U` stored in one matrix.
#[derive(Debug, Clone)]
pub struct DenseLu {
    a: DMatrix<f64>,
    /// At step `k`, rows `k` and `piv[k]` were swapped.
    piv: Vec<usize>,
}

impl DenseLu {
    /// Factorises a square matrix; a zero pivot is [`NumericError::Singular`].
    pub fn new(mut a: DMatrix<f64>) -> Result<DenseLu, NumericError> {
        let n = a.nrows();
        if n != a.ncols() {
            return Err(NumericError::Dimension(format!(
                "{}×{} matrix is not square",
                n,
                a.ncols()
            )));
        }
        let mut piv = vec![0usize; n];
        let mut k0 = 0;
        while k0 < n {
            let k1 = (k0 + NB).min(n);
            for k in k0..k1 {
                let col = &a.as_slice()[k * n..(k + 1) * n];
                let (mut p, mut maxv) = (k, col[k].abs());
                for (i, v) in col.iter().enumerate().skip(k + 1) {
                    if v.abs() > maxv {
                        maxv = v.abs();
                        p = i;
                    }
                }
                if maxv == 0.0 || !maxv.is_finite() {
                    return Err(NumericError::Singular(n));
                }
                piv[k] = p;
                if p != k {
                    a.swap_rows(k, p);
                }
                let s = a.as_mut_slice();
                let inv = 1.0 / s[k * n + k];
                for v in &mut s[k * n + k + 1..(k + 1) * n] {
                    *v *= inv;
                }
                for j in k + 1..k1 {
                    let akj = s[j * n + k];
                    if akj != 0.0 {
                        let (lcol, rest) = s.split_at_mut(j * n);
                        let lk = &lcol[k * n..(k + 1) * n];
                        for i in k + 1..n {
                            rest[i] -= lk[i] * akj;
                        }
                    }
                }
            }
            if k1 < n {
                // U12 = L11⁻¹ A12 (unit lower forward substitution).
                let s = a.as_mut_slice();
                for j in k1..n {
                    let (left, right) = s.split_at_mut(j * n);
                    let cj = &mut right[..n];
                    for k in k0..k1 {
                        let v = cj[k];
                        if v != 0.0 {
                            let lk = &left[k * n..(k + 1) * n];
                            for i in k + 1..k1 {
                                cj[i] -= lk[i] * v;
                            }
                        }
                    }
                }
                // A22 -= L21 U12.
                let l21 = a.view((k1, k0), (n - k1, k1 - k0)).into_owned();
                let u12 = a.view((k0, k1), (k1 - k0, n - k1)).into_owned();
                a.view_mut((k1, k1), (n - k1, n - k1))
                    .gemm(-1.0, &l21, &u12, 1.0);
            }
            k0 = k1;
        }
        Ok(DenseLu { a, piv })
    }

    /// Order of the matrix.
    pub fn size(&self) -> usize {
        self.piv.len()
    }

    /// Solves `A x = b` ([`DenseLu::solve_many`] with one column).
    pub fn solve(&self, b: &DVector<f64>) -> DVector<f64> {
        let mut x = DMatrix::from_column_slice(b.len(), 1, b.as_slice());
        self.solve_many(&mut x);
        DVector::from_column_slice(x.as_slice())
    }

    /// Solves `A X = B` in place for every column of `x`; each column of
    /// the factors is read once for all right sides.
    pub fn solve_many(&self, x: &mut DMatrix<f64>) {
        let n = self.size();
        let s = self.a.as_slice();
        for (k, &p) in self.piv.iter().enumerate() {
            x.swap_rows(k, p);
        }
        let xs = x.as_mut_slice();
        for k in 0..n {
            let col = &s[k * n + k + 1..(k + 1) * n];
            for xj in xs.chunks_exact_mut(n) {
                let v = xj[k];
                if v != 0.0 {
                    for (xi, l) in xj[k + 1..].iter_mut().zip(col) {
                        *xi -= l * v;
                    }
                }
            }
        }
        for k in (0..n).rev() {
            let col = &s[k * n..k * n + k];
            let d = s[k * n + k];
            for xj in xs.chunks_exact_mut(n) {
                xj[k] /= d;
                let v = xj[k];
                if v != 0.0 {
                    for (xi, u) in xj[..k].iter_mut().zip(col) {
                        *xi -= u * v;
                    }
                }
            }
        }
    }

    /// Solves `Aᵀ X = B` in place for every column of `x`.
    pub fn solve_transpose_many(&self, x: &mut DMatrix<f64>) {
        let n = self.size();
        let s = self.a.as_slice();
        {
            let xs = x.as_mut_slice();
            for k in 0..n {
                let col = &s[k * n..k * n + k];
                let d = s[k * n + k];
                for xj in xs.chunks_exact_mut(n) {
                    xj[k] = (xj[k] - dot(col, &xj[..k])) / d;
                }
            }
            for k in (0..n).rev() {
                let col = &s[k * n + k + 1..(k + 1) * n];
                for xj in xs.chunks_exact_mut(n) {
                    xj[k] -= dot(col, &xj[k + 1..]);
                }
            }
        }
        for (k, &p) in self.piv.iter().enumerate().rev() {
            x.swap_rows(k, p);
        }
    }

    /// Solves `Aᵀ x = b` ([`DenseLu::solve_transpose_many`] with one
    /// column).
    pub fn solve_transpose(&self, b: &DVector<f64>) -> DVector<f64> {
        let mut x = DMatrix::from_column_slice(b.len(), 1, b.as_slice());
        self.solve_transpose_many(&mut x);
        DVector::from_column_slice(x.as_slice())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn test_matrix(n: usize) -> DMatrix<f64> {
        DMatrix::from_fn(n, n, |i, j| {
            let x = ((i * 7 + j * 13) % 17) as f64 / 17.0 - 0.5;
            if i == j {
                x + 0.1
            } else {
                x / (1.0 + (i as f64 - j as f64).abs())
            }
        })
    }

    #[test]
    fn solves_with_a_and_its_transpose() {
        for n in [1, 5, 47, 48, 49, 130] {
            let a = test_matrix(n);
            let lu = DenseLu::new(a.clone()).unwrap();
            let b = DVector::from_fn(n, |i, _| (i as f64).sin());
            let x = lu.solve(&b);
            assert!((&a * &x - &b).amax() < 1e-10 * x.amax().max(1.0), "n={n}");
            let y = lu.solve_transpose(&b);
            assert!(
                (a.transpose() * &y - &b).amax() < 1e-10 * y.amax().max(1.0),
                "n={n}"
            );
            let reference = a.clone().lu().solve(&b).unwrap();
            assert!((x - reference).amax() < 1e-9);
        }
    }

    #[test]
    fn many_right_sides_are_solved_bit_for_bit_as_one() {
        for n in [1, 5, 49, 130] {
            let lu = DenseLu::new(test_matrix(n)).unwrap();
            let b = DMatrix::from_fn(n, 3, |i, j| ((i * 3 + j) as f64).cos());
            let (mut x, mut y) = (b.clone(), b.clone());
            lu.solve_many(&mut x);
            lu.solve_transpose_many(&mut y);
            for j in 0..3 {
                let bj = b.column(j).into_owned();
                assert_eq!(x.column(j), lu.solve(&bj), "n={n} column {j}");
                assert_eq!(y.column(j), lu.solve_transpose(&bj), "n={n} column {j}");
            }
        }
    }

    #[test]
    fn singular_is_detected() {
        let mut a = test_matrix(60);
        for i in 0..60 {
            a[(i, 59)] = 2.0 * a[(i, 3)];
        }
        // Exact rank deficiency may survive rounding as a tiny pivot; the
        // condition estimate in solve.rs catches that case.
        let z = DMatrix::<f64>::zeros(3, 3);
        assert_eq!(DenseLu::new(z).err(), Some(NumericError::Singular(3)));
    }
}
