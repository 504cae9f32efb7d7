//! `Matrix<R>`: a dense matrix that stores its ring object beside its
//! entries, so one type serves Q, Q\[x\], Q[s1..sn] and Q(others)\[λ\]. Owns
//! shape handling, products, the fraction-free (Bareiss) determinant,
//! adjugate, rank and k×k minors; the Smith normal form lives in
//! [`super::smith`].

use super::ring::{GcdDomain, Ring};

/// `det(A)` and, when it is nonzero, one row of `adj(A)`
/// ([`Matrix::det_adjugate_row`]).
pub type DetAdjRow<E> = (E, Option<Vec<E>>);

/// A `rows × cols` matrix over the ring object `ring`, row-major.
/// Equality compares shapes and entries.
#[derive(Clone, Debug)]
pub struct Matrix<R: Ring> {
    /// The ring the entries live in.
    pub ring: R,
    rows: usize,
    cols: usize,
    data: Vec<R::Elem>,
}

impl<R: Ring> PartialEq for Matrix<R> {
    fn eq(&self, other: &Self) -> bool {
        self.rows == other.rows && self.cols == other.cols && self.data == other.data
    }
}

impl<R: Ring> Matrix<R> {
    /// A matrix from row-major entries (`data.len() == rows * cols`).
    pub fn new(ring: R, rows: usize, cols: usize, data: Vec<R::Elem>) -> Self {
        assert_eq!(data.len(), rows * cols, "matrix data has the wrong length");
        Matrix {
            ring,
            rows,
            cols,
            data,
        }
    }

    /// The zero matrix.
    pub fn zeros(ring: R, rows: usize, cols: usize) -> Self {
        let z = ring.zero();
        Matrix::new(ring, rows, cols, vec![z; rows * cols])
    }

    /// The identity matrix.
    pub fn identity(ring: R, n: usize) -> Self {
        let mut m = Self::zeros(ring, n, n);
        for i in 0..n {
            m.data[i * n + i] = m.ring.one();
        }
        m
    }

    /// Number of rows.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Number of columns.
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// Entry `(i, j)`.
    pub fn get(&self, i: usize, j: usize) -> &R::Elem {
        &self.data[i * self.cols + j]
    }

    /// Mutable entry `(i, j)`.
    pub fn get_mut(&mut self, i: usize, j: usize) -> &mut R::Elem {
        &mut self.data[i * self.cols + j]
    }

    /// Sets entry `(i, j)`.
    pub fn set(&mut self, i: usize, j: usize, v: R::Elem) {
        self.data[i * self.cols + j] = v;
    }

    /// Row `i` as a slice.
    pub fn row(&self, i: usize) -> &[R::Elem] {
        &self.data[i * self.cols..(i + 1) * self.cols]
    }

    /// The entries, row-major.
    pub fn entries(&self) -> &[R::Elem] {
        &self.data
    }

    /// The same matrix with every entry mapped into another ring.
    pub fn map<S: Ring>(&self, ring: S, f: impl Fn(&R::Elem) -> S::Elem) -> Matrix<S> {
        Matrix::new(
            ring,
            self.rows,
            self.cols,
            self.data.iter().map(f).collect(),
        )
    }

    /// The matrix product `self * other`, or `None` if the shapes do not fit.
    pub fn mul(&self, other: &Matrix<R>) -> Option<Matrix<R>> {
        if self.cols != other.rows {
            return None;
        }
        let r = &self.ring;
        let mut data = Vec::with_capacity(self.rows * other.cols);
        for i in 0..self.rows {
            for j in 0..other.cols {
                let mut terms = (0..self.cols).map(|k| (self.get(i, k), other.get(k, j)));
                data.push(r.dot(&mut terms));
            }
        }
        Some(Matrix::new(r.clone(), self.rows, other.cols, data))
    }

    /// The transpose.
    pub fn transpose(&self) -> Matrix<R> {
        let mut data = Vec::with_capacity(self.data.len());
        for j in 0..self.cols {
            for i in 0..self.rows {
                data.push(self.get(i, j).clone());
            }
        }
        Matrix::new(self.ring.clone(), self.cols, self.rows, data)
    }

    /// Whether every off-diagonal entry is zero.
    pub fn is_diagonal(&self) -> bool {
        (0..self.rows).all(|i| (0..self.cols).all(|j| i == j || self.ring.is_zero(self.get(i, j))))
    }

    /// Whether this is the identity matrix.
    pub fn is_identity(&self) -> bool {
        self.rows == self.cols
            && self.is_diagonal()
            && (0..self.rows).all(|i| self.ring.is_one(self.get(i, i)))
    }

    /// The diagonal entries.
    pub fn diagonal(&self) -> Vec<R::Elem> {
        (0..self.rows.min(self.cols))
            .map(|i| self.get(i, i).clone())
            .collect()
    }

    /// Swaps rows `a` and `b`.
    pub fn swap_rows(&mut self, a: usize, b: usize) {
        if a == b {
            return;
        }
        for j in 0..self.cols {
            self.data.swap(a * self.cols + j, b * self.cols + j);
        }
    }

    /// Swaps columns `a` and `b`.
    pub fn swap_cols(&mut self, a: usize, b: usize) {
        if a == b {
            return;
        }
        for i in 0..self.rows {
            self.data.swap(i * self.cols + a, i * self.cols + b);
        }
    }

    /// `row[dst] += c * row[src]`.
    pub fn add_row_multiple(&mut self, dst: usize, src: usize, c: &R::Elem) {
        if self.ring.is_zero(c) {
            return;
        }
        for j in 0..self.cols {
            let s = self.get(src, j);
            if self.ring.is_zero(s) {
                continue;
            }
            let t = self.ring.mul(c, s);
            let d = self.get(dst, j);
            let v = self.ring.add(d, &t);
            self.set(dst, j, v);
        }
    }

    /// `col[dst] += c * col[src]`.
    pub fn add_col_multiple(&mut self, dst: usize, src: usize, c: &R::Elem) {
        if self.ring.is_zero(c) {
            return;
        }
        for i in 0..self.rows {
            let s = self.get(i, src);
            if self.ring.is_zero(s) {
                continue;
            }
            let t = self.ring.mul(c, s);
            let d = self.get(i, dst);
            let v = self.ring.add(d, &t);
            self.set(i, dst, v);
        }
    }

    /// `row[i] *= c`.
    pub fn scale_row(&mut self, i: usize, c: &R::Elem) {
        for j in 0..self.cols {
            let v = self.ring.mul(self.get(i, j), c);
            self.set(i, j, v);
        }
    }

    /// `col[j] *= c`.
    pub fn scale_col(&mut self, j: usize, c: &R::Elem) {
        for i in 0..self.rows {
            let v = self.ring.mul(self.get(i, j), c);
            self.set(i, j, v);
        }
    }

    /// The submatrix on the given rows and columns.
    pub fn submatrix(&self, rows: &[usize], cols: &[usize]) -> Matrix<R> {
        let mut data = Vec::with_capacity(rows.len() * cols.len());
        for &i in rows {
            for &j in cols {
                data.push(self.get(i, j).clone());
            }
        }
        Matrix::new(self.ring.clone(), rows.len(), cols.len(), data)
    }

    /// Rows of formatted entries (for reports).
    pub fn format_rows(&self) -> Vec<Vec<String>> {
        (0..self.rows)
            .map(|i| {
                (0..self.cols)
                    .map(|j| self.ring.format(self.get(i, j)))
                    .collect()
            })
            .collect()
    }

    /// Rows of entries in the language's syntax (for machine-read reports:
    /// each entry parses back to its value).
    pub fn lmx_rows(&self) -> Vec<Vec<String>> {
        (0..self.rows)
            .map(|i| {
                (0..self.cols)
                    .map(|j| self.ring.lmx(self.get(i, j)))
                    .collect()
            })
            .collect()
    }

    /// Rows of LaTeX entries (for reports).
    pub fn latex_rows(&self) -> Vec<Vec<String>> {
        (0..self.rows)
            .map(|i| {
                (0..self.cols)
                    .map(|j| self.ring.latex(self.get(i, j)))
                    .collect()
            })
            .collect()
    }
}

impl<R: GcdDomain> Matrix<R> {
    /// Determinant by fraction-free Gaussian elimination (Bareiss), with
    /// exact divisions only; `None` for a non-square matrix.
    pub fn det(&self) -> Option<R::Elem> {
        if self.rows != self.cols {
            return None;
        }
        let r = &self.ring;
        let n = self.rows;
        if n == 0 {
            return Some(r.one());
        }
        let mut m = self.clone();
        let mut sign_negative = false;
        let mut prev = r.one();
        for k in 0..n - 1 {
            let Some(p) = (k..n).find(|&i| !r.is_zero(m.get(i, k))) else {
                return Some(r.zero());
            };
            if p != k {
                m.swap_rows(p, k);
                sign_negative = !sign_negative;
            }
            for i in k + 1..n {
                for j in k + 1..n {
                    let t = r.sub(
                        &r.mul(m.get(k, k), m.get(i, j)),
                        &r.mul(m.get(i, k), m.get(k, j)),
                    );
                    let v = r.div_exact(&t, &prev).expect("Bareiss division is exact");
                    m.set(i, j, v);
                }
            }
            prev = m.get(k, k).clone();
        }
        let d = m.get(n - 1, n - 1).clone();
        Some(if sign_negative { r.neg(&d) } else { d })
    }

    /// `det(A)` and row `i` of `adj(A)` from one fraction-free elimination:
    /// Bareiss on `[Aᵀ | e_i]` gives `det(A)` as its last pivot, and the
    /// fraction-free back substitution `y_k = (det·b_k − Σ_{j>k} u_kj y_j)
    /// / u_kk` (exact divisions) gives `y = det(A)·A⁻ᵀ·e_i`, which is row
    /// `i` of `adj(A)`. `O(n³)` ring operations instead of the `n²`
    /// determinants of [`Matrix::adjugate`]; rows whose entry in the pivot
    /// column is zero are only rescaled (and not at all when consecutive
    /// pivots are equal, e.g. unit pivots of a sparse system). The row is
    /// `None` when `det(A) = 0`; `None` overall for a non-square matrix or
    /// `i` out of range.
    pub fn det_adjugate_row(&self, i: usize) -> Option<DetAdjRow<R::Elem>> {
        if self.rows != self.cols || i >= self.rows {
            return None;
        }
        let r = &self.ring;
        let n = self.rows;
        if n == 1 {
            return Some((self.get(0, 0).clone(), Some(vec![r.one()])));
        }
        // Augmented Aᵀ with the column e_i, n × (n + 1).
        let w = n + 1;
        let mut m: Vec<R::Elem> = Vec::with_capacity(n * w);
        for row in 0..n {
            for col in 0..n {
                m.push(self.get(col, row).clone());
            }
            m.push(if row == i { r.one() } else { r.zero() });
        }
        let mut negative = false;
        let mut prev = r.one();
        for k in 0..n {
            let Some(p) = (k..n).find(|&row| !r.is_zero(&m[row * w + k])) else {
                return Some((r.zero(), None));
            };
            if p != k {
                for col in 0..w {
                    m.swap(p * w + col, k * w + col);
                }
                negative = !negative;
            }
            if k + 1 == n {
                break;
            }
            let pivot = m[k * w + k].clone();
            let same = pivot == prev;
            for row in k + 1..n {
                let factor = m[row * w + k].clone();
                if r.is_zero(&factor) {
                    if !same {
                        for col in k + 1..w {
                            let e = &m[row * w + col];
                            if !r.is_zero(e) {
                                let t = r.mul(&pivot, e);
                                m[row * w + col] =
                                    r.div_exact(&t, &prev).expect("Bareiss division is exact");
                            }
                        }
                    }
                    continue;
                }
                for col in k + 1..w {
                    let (a_kc, a_rc) = (&m[k * w + col], &m[row * w + col]);
                    let t = match (r.is_zero(a_kc), r.is_zero(a_rc)) {
                        (true, true) => continue,
                        (true, false) => r.mul(&pivot, a_rc),
                        (false, true) => r.neg(&r.mul(&factor, a_kc)),
                        (false, false) => r.sub(&r.mul(&pivot, a_rc), &r.mul(&factor, a_kc)),
                    };
                    m[row * w + col] = if r.is_one(&prev) {
                        t
                    } else {
                        r.div_exact(&t, &prev).expect("Bareiss division is exact")
                    };
                }
                m[row * w + k] = r.zero();
            }
            prev = pivot;
        }
        let last = m[(n - 1) * w + (n - 1)].clone();
        if r.is_zero(&last) {
            return Some((r.zero(), None));
        }
        let det = if negative { r.neg(&last) } else { last };
        let mut y: Vec<R::Elem> = vec![r.zero(); n];
        for k in (0..n).rev() {
            let b = &m[k * w + n];
            let mut acc = if r.is_zero(b) {
                r.zero()
            } else {
                r.mul(&det, b)
            };
            for (j, yj) in y.iter().enumerate().skip(k + 1) {
                let u = &m[k * w + j];
                if !r.is_zero(u) && !r.is_zero(yj) {
                    acc = r.sub(&acc, &r.mul(u, yj));
                }
            }
            y[k] = if r.is_zero(&acc) {
                acc
            } else {
                r.div_exact(&acc, &m[k * w + k])
                    .expect("Cramer's numerators are divisible by the pivots")
            };
        }
        Some((det, Some(y)))
    }

    /// The adjugate (transposed cofactor matrix): `A·adj(A) = det(A)·I`.
    pub fn adjugate(&self) -> Option<Matrix<R>> {
        if self.rows != self.cols {
            return None;
        }
        let n = self.rows;
        let r = &self.ring;
        let mut out = Matrix::zeros(r.clone(), n, n);
        if n == 1 {
            out.set(0, 0, r.one());
            return Some(out);
        }
        for i in 0..n {
            for j in 0..n {
                let rows: Vec<usize> = (0..n).filter(|&k| k != i).collect();
                let cols: Vec<usize> = (0..n).filter(|&k| k != j).collect();
                let c = self.submatrix(&rows, &cols).det()?;
                let c = if (i + j) % 2 == 1 { r.neg(&c) } else { c };
                out.set(j, i, c);
            }
        }
        Some(out)
    }

    /// Rank over the fraction field (fraction-free elimination).
    pub fn rank(&self) -> usize {
        let r = &self.ring;
        let mut m = self.clone();
        let mut rank = 0;
        let mut prev = r.one();
        for col in 0..self.cols {
            if rank == self.rows {
                break;
            }
            let Some(p) = (rank..self.rows).find(|&i| !r.is_zero(m.get(i, col))) else {
                continue;
            };
            m.swap_rows(p, rank);
            for i in rank + 1..self.rows {
                for j in col + 1..self.cols {
                    let t = r.sub(
                        &r.mul(m.get(rank, col), m.get(i, j)),
                        &r.mul(m.get(i, col), m.get(rank, j)),
                    );
                    let v = r.div_exact(&t, &prev).expect("Bareiss division is exact");
                    m.set(i, j, v);
                }
                m.set(i, col, r.zero());
            }
            prev = m.get(rank, col).clone();
            rank += 1;
        }
        rank
    }

    /// All k×k minors (in lexicographic order of row and column subsets),
    /// by [`MinorOrders`].
    pub fn minors(&self, k: usize) -> Vec<R::Elem> {
        let mut orders = MinorOrders::new(self);
        while orders.order() < k {
            if !orders.advance() {
                return Vec::new();
            }
        }
        orders.minors().to_vec()
    }
}

/// Every minor of a matrix, one order at a time, lowest first. Order
/// k + 1 comes from order k by Laplace expansion along the line (a row or
/// a column of the minor) with the fewest non-zero entries, so a minor
/// costs at most k + 1 products of an entry with a minor of the order
/// before, and no division; an order's minors are listed in
/// lexicographic order of their row subsets, then of their column
/// subsets. Holds one order at a time.
pub struct MinorOrders<'a, R: Ring> {
    a: &'a Matrix<R>,
    order: usize,
    minors: Vec<R::Elem>,
    /// Most [`GcdDomain::bulk`] (terms) one order may hold, if limited.
    max_bulk: Option<usize>,
    /// An advance stopped at `max_bulk`.
    stopped: bool,
}

impl<'a, R: GcdDomain> MinorOrders<'a, R> {
    /// Starts at order 0 (the single empty minor, 1).
    pub fn new(a: &'a Matrix<R>) -> Self {
        MinorOrders {
            a,
            order: 0,
            minors: vec![a.ring.one()],
            max_bulk: None,
            stopped: false,
        }
    }

    /// Stops an advance, and keeps the order before, as soon as the order
    /// being built would hold more than `terms` terms in all (so at most
    /// two orders within the limit are held at once).
    pub fn with_bulk_limit(mut self, terms: usize) -> Self {
        self.max_bulk = Some(terms);
        self
    }

    /// Whether the last [`Self::advance`] stopped at the bulk limit.
    pub fn stopped_by_limit(&self) -> bool {
        self.stopped
    }

    /// The order of the minors [`Self::minors`] lists.
    pub fn order(&self) -> usize {
        self.order
    }

    /// The minors of the current order.
    pub fn minors(&self) -> &[R::Elem] {
        &self.minors
    }

    /// Steps to the next order; `false` (and no change) past
    /// `min(rows, cols)` or at the bulk limit.
    pub fn advance(&mut self) -> bool {
        let (a, r, k) = (self.a, &self.a.ring, self.order + 1);
        if k > a.rows.min(a.cols) {
            return false;
        }
        // For every k-subset, the index among the (k−1)-subsets of the
        // subset without its p-th element.
        let drops = |n: usize| -> (Vec<Vec<usize>>, Vec<Vec<usize>>) {
            let prev: std::collections::HashMap<Vec<usize>, usize> = subsets(n, k - 1)
                .into_iter()
                .enumerate()
                .map(|(i, s)| (s, i))
                .collect();
            let subs = subsets(n, k);
            let drop = subs
                .iter()
                .map(|s| {
                    (0..k)
                        .map(|p| {
                            let rest: Vec<usize> = [&s[..p], &s[p + 1..]].concat();
                            prev[&rest]
                        })
                        .collect()
                })
                .collect();
            (subs, drop)
        };
        let (rsubs, rdrop) = drops(a.rows);
        let (csubs, cdrop) = drops(a.cols);
        let prev_cols = binomial_len(a.cols, k - 1);
        let mut out = Vec::with_capacity(rsubs.len() * csubs.len());
        let mut bulk = 0usize;
        for (rs, rd) in rsubs.iter().zip(&rdrop) {
            for (cs, cd) in csubs.iter().zip(&cdrop) {
                let nz = |i: usize, j: usize| !r.is_zero(a.get(rs[i], cs[j]));
                // (non-zeros, along a row?, position)
                let mut line = (usize::MAX, true, 0);
                for p in 0..k {
                    let row = (0..k).filter(|&j| nz(p, j)).count();
                    if row < line.0 {
                        line = (row, true, p);
                    }
                    let col = (0..k).filter(|&i| nz(i, p)).count();
                    if col < line.0 {
                        line = (col, false, p);
                    }
                }
                if line.0 == 0 {
                    out.push(r.zero());
                    continue;
                }
                let (_, along_row, p) = line;
                // The q-th term: its entry's (row, column) positions.
                let at = |q: usize| if along_row { (p, q) } else { (q, p) };
                let term = |q: usize| {
                    let (i, j) = at(q);
                    (a.get(rs[i], cs[j]), &self.minors[rd[i] * prev_cols + cd[j]])
                };
                let mut terms = (0..k).filter(|&q| nz(at(q).0, at(q).1)).map(|q| {
                    let (e, m) = term(q);
                    (e, m, (p + q) % 2 == 1)
                });
                let minor = r.signed_dot(&mut terms);
                bulk += r.bulk(&minor);
                if self.max_bulk.is_some_and(|m| bulk > m) {
                    self.stopped = true;
                    return false;
                }
                out.push(minor);
            }
        }
        self.minors = out;
        self.order = k;
        true
    }
}

/// The number of `k`-subsets of `0..n`.
fn binomial_len(n: usize, k: usize) -> usize {
    (0..k).fold(1usize, |acc, i| acc * (n - i) / (i + 1))
}

/// All `k`-subsets of `0..n` in lexicographic order.
pub fn subsets(n: usize, k: usize) -> Vec<Vec<usize>> {
    fn go(start: usize, n: usize, k: usize, cur: &mut Vec<usize>, out: &mut Vec<Vec<usize>>) {
        if cur.len() == k {
            out.push(cur.clone());
            return;
        }
        for i in start..n {
            if n - i < k - cur.len() {
                break;
            }
            cur.push(i);
            go(i + 1, n, k, cur, out);
            cur.pop();
        }
    }
    let mut out = Vec::new();
    if k <= n {
        go(0, n, k, &mut Vec::new(), &mut out);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::mpoly::MPoly;
    use crate::algebra::polyring::PolyRing;
    use crate::algebra::rational::Q;

    fn seed() -> Matrix<PolyRing> {
        let names: Vec<String> = ["k1", "k2", "k3", "k4"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        let ring = PolyRing::new(names);
        let v: Vec<MPoly> = (0..4).map(|i| MPoly::var(i, 4)).collect();
        Matrix::new(ring, 2, 2, v)
    }

    /// Seeded rectangular matrices over Q[x, y] with many zero entries (so
    /// the expansion line changes from minor to minor, rows and columns
    /// both) and some halves among integer coefficients (both summation
    /// paths): every minor of every order equals the Bareiss determinant
    /// of its submatrix.
    #[test]
    fn laplace_minors_equal_bareiss_determinants() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = move |m: u64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state % m
        };
        let ring = PolyRing::new(vec!["x".to_string(), "y".to_string()]);
        // Minors checked, those a column expands (sparser than any row),
        // and those of integer entries only (summed on packed monomials).
        let (mut checked, mut by_column, mut integral_minors) = (0, 0, 0);
        for (rows, cols) in [(4, 4), (3, 5), (5, 4), (5, 5)] {
            let data: Vec<MPoly> = (0..rows * cols)
                .map(|_| {
                    if next(5) < 2 {
                        return MPoly::zero(2);
                    }
                    MPoly::from_terms(
                        2,
                        (0..1 + next(3)).map(|_| {
                            let c = next(19) as i64 - 9;
                            let den = if next(6) == 0 { 2 } else { 1 };
                            (vec![next(3) as u32, next(3) as u32], Q::new(c.into(), den.into()))
                        }),
                    )
                })
                .collect();
            let a = Matrix::new(ring.clone(), rows, cols, data);
            let mut orders = MinorOrders::new(&a);
            while orders.advance() {
                let k = orders.order();
                let mut it = orders.minors().iter();
                for rs in subsets(rows, k) {
                    for cs in subsets(cols, k) {
                        let sub = a.submatrix(&rs, &cs);
                        let nz = |i: usize, j: usize| !sub.get(i, j).is_zero();
                        let row = (0..k).map(|i| (0..k).filter(|&j| nz(i, j)).count()).min();
                        let col = (0..k).map(|j| (0..k).filter(|&i| nz(i, j)).count()).min();
                        by_column += usize::from(col < row);
                        let integral = (0..k)
                            .all(|i| (0..k).all(|j| sub.get(i, j).terms().iter().all(|(_, c)| c.is_integer())));
                        integral_minors += usize::from(integral);
                        assert_eq!(it.next(), sub.det().as_ref(), "rows {rs:?} cols {cs:?}");
                        checked += 1;
                    }
                }
                assert!(it.next().is_none());
            }
            assert_eq!(orders.order(), rows.min(cols));
        }
        assert!(
            checked == 500 && by_column > 20 && (100..400).contains(&integral_minors),
            "{checked} minors, {by_column} by a column, {integral_minors} integral"
        );
    }

    #[test]
    fn a_bulk_limit_stops_an_order_and_keeps_the_one_before() {
        let ring = PolyRing::new(vec!["x".to_string()]);
        let x = MPoly::var(0, 1);
        // A 3×4 of entries x + i²: 12 entries and 18 two-by-two minors,
        // two terms each.
        let data = (0..12)
            .map(|i: i64| &x + &MPoly::constant(Q::from_integer((i * i).into()), 1))
            .collect();
        let a = Matrix::new(ring, 3, 4, data);
        let bulk = |o: &MinorOrders<PolyRing>| o.minors().iter().map(|m| m.terms().len()).sum();
        let mut free = MinorOrders::new(&a);
        assert!(free.advance());
        let first: usize = bulk(&free);
        assert!(free.advance());
        assert!(bulk(&free) > first, "the second order is larger");
        let mut orders = MinorOrders::new(&a).with_bulk_limit(first);
        assert!(orders.advance());
        assert!(!orders.advance());
        assert!(orders.stopped_by_limit());
        assert_eq!((orders.order(), orders.minors().len()), (1, 12));
        while free.advance() {}
        assert!(!free.stopped_by_limit() && free.order() == 3);
    }

    #[test]
    fn det_and_adjugate_of_the_seed_matrix() {
        let a = seed();
        let d = a.det().unwrap();
        assert_eq!(a.ring.format(&d), "k1*k4 - k2*k3");
        let adj = a.adjugate().unwrap();
        let prod = a.mul(&adj).unwrap();
        let expect = Matrix::new(
            a.ring.clone(),
            2,
            2,
            vec![d.clone(), MPoly::zero(4), MPoly::zero(4), d],
        );
        assert_eq!(prod, expect);
        assert_eq!(a.rank(), 2);
    }

    /// A seeded n×n over Q[k1, k2] with entries c0 + c1·k1 + c2·k2·k1, a
    /// third of them zero (so pivots need row swaps).
    fn sparse_xy(n: usize, seed: u64) -> Matrix<PolyRing> {
        let mut s = seed;
        let mut next = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((s >> 33) % 7) as i64 - 3
        };
        let (x, y) = (MPoly::var(0, 2), MPoly::var(1, 2));
        let c = |v: i64| MPoly::constant(crate::algebra::rational::qi(v), 2);
        let data = (0..n * n)
            .map(|_| {
                if next() < -1 {
                    MPoly::zero(2)
                } else {
                    c(next()) + &x * &c(next()) + &(&x * &y) * &c(next())
                }
            })
            .collect();
        Matrix::new(PolyRing::new(vec!["k1".into(), "k2".into()]), n, n, data)
    }

    #[test]
    fn adjugate_row_from_one_elimination_is_the_adjugates_row() {
        let mut nonsingular = 0;
        for seed in 0..12u64 {
            let n = 2 + (seed % 4) as usize;
            let a = sparse_xy(n, seed);
            let det = a.det().unwrap();
            let adj = a.adjugate().unwrap();
            for i in 0..n {
                let (d, row) = a.det_adjugate_row(i).unwrap();
                assert_eq!(d, det, "seed {seed} row {i}");
                match row {
                    Some(row) => {
                        assert!(!det.is_zero());
                        assert_eq!(row, adj.row(i).to_vec(), "seed {seed} row {i}");
                        nonsingular += 1;
                    }
                    None => assert!(det.is_zero()),
                }
            }
        }
        assert!(
            nonsingular >= 20,
            "only {nonsingular} nonsingular rows checked"
        );
        // A permutation-like matrix needs a swap at the first pivot.
        let r = seed().ring;
        let k = |i| MPoly::var(i, 4);
        let z = || MPoly::zero(4);
        let m = Matrix::new(r, 2, 2, vec![z(), k(0), k(1), z()]);
        let (d, row) = m.det_adjugate_row(1).unwrap();
        assert_eq!(d, -(&k(0) * &k(1)));
        assert_eq!(row.unwrap(), vec![-k(1), z()]);
    }

    #[test]
    fn rank_deficient_and_empty() {
        let a = seed();
        let r = a.ring.clone();
        let row: Vec<MPoly> = a.row(0).to_vec();
        let twice: Vec<MPoly> = row.iter().map(|p| p + p).collect();
        let m = Matrix::new(r.clone(), 2, 2, [row, twice].concat());
        assert_eq!(m.rank(), 1);
        assert!(r.is_zero(&m.det().unwrap()));
        let e = Matrix::zeros(r.clone(), 0, 0);
        assert_eq!(e.det(), Some(r.one()));
        assert_eq!(e.rank(), 0);
        assert_eq!(subsets(4, 2).len(), 6);
        assert!(subsets(2, 3).is_empty());
    }
}
