//! Monomial-shaped inputs: matrices with at most one nonzero entry in every
//! row and every column (diagonal, permuted diagonal, and either padded
//! with zero rows or columns). Such an A is `Pᵀ·[[Δ, 0], [0, 0]]·Qᵀ` for
//! permutations P, Q and the diagonal Δ of its nonzero entries, so its
//! Smith form is Δ's padded with zeros and its transforms are Δ's bordered
//! by identities and composed with P and Q. This module owns only that
//! detection and the lifting; Δ's Smith form comes from the other routes
//! (`modes.rs` chooses), and the lifted decomposition is certified against
//! A itself.

use super::SmithDecomposition;
use crate::algebra::matrix::Matrix;
use crate::algebra::ring::EuclideanDomain;

/// Where the nonzero entries of a monomial-shaped matrix sit.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MonomialShape {
    /// `(row, column)` of each nonzero entry, in row order.
    pub places: Vec<(usize, usize)>,
}

impl MonomialShape {
    /// The shape of `a` when every row and every column holds at most one
    /// nonzero entry; `None` otherwise (one pass over the entries).
    pub fn of<R: EuclideanDomain>(a: &Matrix<R>) -> Option<MonomialShape> {
        let r = &a.ring;
        let mut col_used = vec![false; a.cols()];
        let mut places = Vec::new();
        for i in 0..a.rows() {
            let mut found = None;
            for (j, used) in col_used.iter_mut().enumerate() {
                if !r.is_zero(a.get(i, j)) {
                    if found.is_some() || *used {
                        return None;
                    }
                    found = Some(j);
                    *used = true;
                }
            }
            if let Some(j) = found {
                places.push((i, j));
            }
        }
        Some(MonomialShape { places })
    }

    /// Whether A is square and already diagonal (the other routes take
    /// those directly).
    pub fn is_square_diagonal<R: EuclideanDomain>(&self, a: &Matrix<R>) -> bool {
        a.rows() == a.cols() && self.places.iter().all(|&(i, j)| i == j)
    }

    /// Δ: the r×r diagonal of the nonzero entries, in row order.
    pub fn delta<R: EuclideanDomain>(&self, a: &Matrix<R>) -> Matrix<R> {
        let r = self.places.len();
        let mut d = Matrix::zeros(a.ring.clone(), r, r);
        for (k, &(i, j)) in self.places.iter().enumerate() {
            d.set(k, k, a.get(i, j).clone());
        }
        d
    }

    /// The row order `p` (row `p[k]` of A goes to row k of P·A) and the
    /// column order `q` (column `q[k]` of A goes to column k of A·Q) that
    /// bring the nonzero entries to the leading diagonal.
    fn orders(&self, m: usize, n: usize) -> (Vec<usize>, Vec<usize>) {
        let mut p: Vec<usize> = self.places.iter().map(|&(i, _)| i).collect();
        let mut q: Vec<usize> = self.places.iter().map(|&(_, j)| j).collect();
        let mut row_used = vec![false; m];
        let mut col_used = vec![false; n];
        for &(i, j) in &self.places {
            row_used[i] = true;
            col_used[j] = true;
        }
        p.extend((0..m).filter(|&i| !row_used[i]));
        q.extend((0..n).filter(|&j| !col_used[j]));
        (p, q)
    }

    /// Lifts a decomposition `U′·Δ·V′ = D′` of Δ to A (m×n):
    /// `U = diag(U′, I)·P`, `V = Q·diag(V′, I)`, `D = [[D′, 0], [0, 0]]`,
    /// and the inverses likewise (`U⁻¹ = Pᵀ·diag(U′⁻¹, I)`). Not certified
    /// here: the caller certifies the result against A.
    pub fn lift<R: EuclideanDomain>(
        &self,
        a: &Matrix<R>,
        dec: &SmithDecomposition<R>,
    ) -> SmithDecomposition<R> {
        let ring = &a.ring;
        let (m, n) = (a.rows(), a.cols());
        let r = self.places.len();
        let (p, q) = self.orders(m, n);
        let border = |inner: &Matrix<R>, size: usize| {
            let mut out = Matrix::identity(ring.clone(), size);
            for i in 0..r {
                for j in 0..r {
                    out.set(i, j, inner.get(i, j).clone());
                }
            }
            out
        };
        let (bu, bui) = (border(&dec.u, m), border(&dec.u_inv, m));
        let (bv, bvi) = (border(&dec.v, n), border(&dec.v_inv, n));
        // U = B_u·P: column p[k] of U is column k of B_u.
        let mut u = Matrix::zeros(ring.clone(), m, m);
        let mut u_inv = Matrix::zeros(ring.clone(), m, m);
        for (k, &pk) in p.iter().enumerate() {
            for i in 0..m {
                u.set(i, pk, bu.get(i, k).clone());
                // Pᵀ·B: row p[k] of U⁻¹ is row k of B_u⁻¹.
                u_inv.set(pk, i, bui.get(k, i).clone());
            }
        }
        // V = Q·B_v: row q[k] of V is row k of B_v.
        let mut v = Matrix::zeros(ring.clone(), n, n);
        let mut v_inv = Matrix::zeros(ring.clone(), n, n);
        for (k, &qk) in q.iter().enumerate() {
            for j in 0..n {
                v.set(qk, j, bv.get(k, j).clone());
                // B⁻¹·Qᵀ: column q[k] of V⁻¹ is column k of B_v⁻¹.
                v_inv.set(j, qk, bvi.get(j, k).clone());
            }
        }
        let mut d = Matrix::zeros(ring.clone(), m, n);
        for k in 0..r {
            d.set(k, k, dec.d.get(k, k).clone());
        }
        SmithDecomposition {
            d,
            u,
            v,
            u_inv,
            v_inv,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::qx::{QPoly, QxRing};
    use crate::algebra::ring::Ring;

    fn lin(c: i64) -> QPoly {
        // x − c
        QPoly::from_upoly(&crate::algebra::upoly::UPoly(vec![
            crate::algebra::rational::qi(-c),
            crate::algebra::rational::qi(1),
        ]))
    }

    #[test]
    fn shape_rejects_two_entries_in_a_column_or_row() {
        let r = QxRing::new("x");
        let mut a = Matrix::zeros(r.clone(), 3, 4);
        a.set(0, 2, lin(1));
        a.set(2, 0, lin(2));
        assert!(MonomialShape::of(&a).is_some());
        a.set(1, 2, lin(3));
        assert!(MonomialShape::of(&a).is_none());
        a.set(1, 2, r.zero());
        a.set(2, 3, lin(3));
        assert!(MonomialShape::of(&a).is_none());
    }

    #[test]
    fn lifted_decomposition_of_a_permuted_padded_diagonal_certifies() {
        let r = QxRing::new("x");
        // 4×6: entries x−1, x−1, (x−1)(x−2) at scattered places.
        let mut a = Matrix::zeros(r.clone(), 4, 6);
        a.set(0, 4, lin(1));
        a.set(2, 1, r.mul(&lin(1), &lin(2)));
        a.set(3, 5, lin(1));
        let shape = MonomialShape::of(&a).expect("monomial");
        assert!(!shape.is_square_diagonal(&a));
        let delta = shape.delta(&a);
        let dec = SmithDecomposition::new(&delta);
        assert!(dec.certify(&delta).verified());
        let lifted = shape.lift(&a, &dec);
        let cert = lifted.certify(&a);
        assert!(cert.verified(), "{:?}", cert.checks);
        let diag = lifted.d.diagonal();
        assert_eq!(diag[0], lin(1));
        assert_eq!(diag[1], lin(1));
        assert_eq!(diag[2], r.mul(&lin(1), &lin(2)));
        assert!(r.is_zero(&diag[3]));
    }
}
