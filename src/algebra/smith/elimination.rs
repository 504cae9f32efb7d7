//! The one Smith elimination over any Euclidean domain. It reports every
//! elementary row and column operation to a [`Sink`]: [`NoTransforms`]
//! yields D alone, [`Recorder`] builds U, V and their inverses (the inverses
//! are the unimodularity certificate). There is no second code path.
//!
//! Coefficient growth is kept down three ways: the pivot is always an entry
//! of least degree, rows are reduced by division with remainder before they
//! are eliminated (degree grows linearly, not geometrically), and every
//! modified row is rescaled by a unit of the ring (for Q\[x\]: cleared
//! denominators, coprime integer coefficients). This module must not check
//! its own result; [`mod@super::certify`] does that independently.

use crate::algebra::matrix::Matrix;
use crate::algebra::ring::EuclideanDomain;

/// One elementary operation (on rows or on columns, as the sink is told).
#[derive(Clone, Debug)]
pub enum Op<E> {
    /// Exchange lines `a` and `b`.
    Swap(usize, usize),
    /// `line[dst] += c * line[src]`.
    AddMultiple { dst: usize, src: usize, c: E },
    /// `line[i] *= u` for a unit `u`.
    Scale { i: usize, u: E },
}

/// Receives the elementary operations of an elimination.
pub trait Sink<R: EuclideanDomain> {
    /// A row operation was applied to the working matrix.
    fn row(&mut self, ring: &R, op: &Op<R::Elem>);
    /// A column operation was applied to the working matrix.
    fn col(&mut self, ring: &R, op: &Op<R::Elem>);
}

/// Discards the operations: only D is computed.
#[cfg(feature = "internals")]
pub struct NoTransforms;

#[cfg(feature = "internals")]
impl<R: EuclideanDomain> Sink<R> for NoTransforms {
    fn row(&mut self, _: &R, _: &Op<R::Elem>) {}
    fn col(&mut self, _: &R, _: &Op<R::Elem>) {}
}

/// Records U, V (with `U·A·V = D`) and their inverses.
pub struct Recorder<R: EuclideanDomain> {
    /// Row transform.
    pub u: Matrix<R>,
    /// Inverse of `u`, kept as the unimodularity certificate.
    pub u_inv: Matrix<R>,
    /// Column transform.
    pub v: Matrix<R>,
    /// Inverse of `v`.
    pub v_inv: Matrix<R>,
}

impl<R: EuclideanDomain> Recorder<R> {
    /// Identity transforms for an `m × n` input.
    pub fn new(ring: &R, m: usize, n: usize) -> Self {
        Recorder {
            u: Matrix::identity(ring.clone(), m),
            u_inv: Matrix::identity(ring.clone(), m),
            v: Matrix::identity(ring.clone(), n),
            v_inv: Matrix::identity(ring.clone(), n),
        }
    }
}

impl<R: EuclideanDomain> Sink<R> for Recorder<R> {
    // U ← E·U and U⁻¹ ← U⁻¹·E⁻¹ (a column operation on U⁻¹).
    fn row(&mut self, ring: &R, op: &Op<R::Elem>) {
        match op {
            Op::Swap(a, b) => {
                self.u.swap_rows(*a, *b);
                self.u_inv.swap_cols(*a, *b);
            }
            Op::AddMultiple { dst, src, c } => {
                self.u.add_row_multiple(*dst, *src, c);
                self.u_inv.add_col_multiple(*src, *dst, &ring.neg(c));
            }
            Op::Scale { i, u } => {
                self.u.scale_row(*i, u);
                self.u_inv.scale_col(*i, &ring.unit_inverse(u));
            }
        }
    }
    // V ← V·F and V⁻¹ ← F⁻¹·V⁻¹ (a row operation on V⁻¹).
    fn col(&mut self, ring: &R, op: &Op<R::Elem>) {
        match op {
            Op::Swap(a, b) => {
                self.v.swap_cols(*a, *b);
                self.v_inv.swap_rows(*a, *b);
            }
            Op::AddMultiple { dst, src, c } => {
                self.v.add_col_multiple(*dst, *src, c);
                self.v_inv.add_row_multiple(*src, *dst, &ring.neg(c));
            }
            Op::Scale { i, u } => {
                self.v.scale_col(*i, u);
                self.v_inv.scale_row(*i, &ring.unit_inverse(u));
            }
        }
    }
}

struct Work<'s, R: EuclideanDomain, S: Sink<R>> {
    d: Matrix<R>,
    sink: &'s mut S,
}

impl<R: EuclideanDomain, S: Sink<R>> Work<'_, R, S> {
    fn ring(&self) -> R {
        self.d.ring.clone()
    }
    fn row_op(&mut self, op: Op<R::Elem>) {
        match &op {
            Op::Swap(a, b) => self.d.swap_rows(*a, *b),
            Op::AddMultiple { dst, src, c } => self.d.add_row_multiple(*dst, *src, c),
            Op::Scale { i, u } => self.d.scale_row(*i, u),
        }
        let r = self.ring();
        self.sink.row(&r, &op);
    }
    fn col_op(&mut self, op: Op<R::Elem>) {
        match &op {
            Op::Swap(a, b) => self.d.swap_cols(*a, *b),
            Op::AddMultiple { dst, src, c } => self.d.add_col_multiple(*dst, *src, c),
            Op::Scale { i, u } => self.d.scale_col(*i, u),
        }
        let r = self.ring();
        self.sink.col(&r, &op);
    }
    fn size(&self, i: usize, j: usize) -> Option<usize> {
        self.d.ring.size(self.d.get(i, j))
    }
    /// Rescales row `i` (from column `t` on) by a unit that keeps it small.
    fn tidy_row(&mut self, i: usize, t: usize) {
        let r = self.ring();
        let row: Vec<&R::Elem> = (t..self.d.cols()).map(|j| self.d.get(i, j)).collect();
        let u = r.row_scale_unit(&row);
        if r.is_zero(&r.sub(&u, &r.one())) {
            return;
        }
        self.row_op(Op::Scale { i, u });
    }
    fn tidy_col(&mut self, j: usize, t: usize) {
        let r = self.ring();
        let col: Vec<&R::Elem> = (t..self.d.rows()).map(|i| self.d.get(i, j)).collect();
        let u = r.row_scale_unit(&col);
        if r.is_zero(&r.sub(&u, &r.one())) {
            return;
        }
        self.col_op(Op::Scale { i: j, u });
    }
    /// Position of a least-size nonzero entry among `cells`.
    fn least(&self, cells: impl Iterator<Item = (usize, usize)>) -> Option<(usize, usize)> {
        cells
            .filter_map(|(i, j)| self.size(i, j).map(|s| (s, i, j)))
            .min_by_key(|&(s, i, j)| (s, i, j))
            .map(|(_, i, j)| (i, j))
    }

    fn run(&mut self) {
        let (m, n) = (self.d.rows(), self.d.cols());
        for t in 0..m.min(n) {
            let cells = (t..m).flat_map(|i| (t..n).map(move |j| (i, j)));
            let Some((pi, pj)) = self.least(cells) else {
                break;
            };
            if pi != t {
                self.row_op(Op::Swap(t, pi));
            }
            if pj != t {
                self.col_op(Op::Swap(t, pj));
            }
            self.settle_pivot(t);
            let r = self.ring();
            let u = r.normal_unit(self.d.get(t, t));
            if !r.is_zero(&r.sub(&u, &r.one())) {
                self.row_op(Op::Scale { i: t, u });
            }
        }
    }

    /// Makes `(t,t)` divide everything in its row, column and the trailing
    /// block, and clears its row and column.
    fn settle_pivot(&mut self, t: usize) {
        let (m, n) = (self.d.rows(), self.d.cols());
        let r = self.ring();
        loop {
            for i in t + 1..m {
                if r.is_zero(self.d.get(i, t)) {
                    continue;
                }
                let (q, _) = r.div_rem(self.d.get(i, t), self.d.get(t, t));
                self.row_op(Op::AddMultiple {
                    dst: i,
                    src: t,
                    c: r.neg(&q),
                });
                self.tidy_row(i, t);
            }
            if let Some((i, _)) = self.least((t + 1..m).map(|i| (i, t))) {
                self.row_op(Op::Swap(t, i));
                continue;
            }
            for j in t + 1..n {
                if r.is_zero(self.d.get(t, j)) {
                    continue;
                }
                let (q, _) = r.div_rem(self.d.get(t, j), self.d.get(t, t));
                self.col_op(Op::AddMultiple {
                    dst: j,
                    src: t,
                    c: r.neg(&q),
                });
                self.tidy_col(j, t);
            }
            if let Some((_, j)) = self.least((t + 1..n).map(|j| (t, j))) {
                self.col_op(Op::Swap(t, j));
                continue;
            }
            // Row and column are clear; the pivot must divide the block
            // (trivially so when it is a unit).
            if self.size(t, t) == Some(0) {
                return;
            }
            let p = self.d.get(t, t).clone();
            let bad = (t + 1..m).find(|&i| {
                (t + 1..n).any(|j| {
                    let e = self.d.get(i, j);
                    !r.is_zero(e) && !r.is_zero(&r.div_rem(e, &p).1)
                })
            });
            match bad {
                Some(i) => self.row_op(Op::AddMultiple {
                    dst: t,
                    src: i,
                    c: r.one(),
                }),
                None => return,
            }
        }
    }
}

/// Runs the elimination on `a`, reporting operations to `sink`; returns D.
pub fn eliminate<R: EuclideanDomain, S: Sink<R>>(a: &Matrix<R>, sink: &mut S) -> Matrix<R> {
    let mut w = Work { d: a.clone(), sink };
    w.run();
    w.d
}
