//! One derivation per (system, target unknown, principal symbol): the
//! single value that `reduce` prints, `solve`/`run` execute, `codegen`
//! writes into its header and generated solvers run. It is built once from
//! the ordered system (operator words in the order written, row `i` =
//! equation `i`, column `j` = unknown `j`) and its commutative image (the
//! λ-matrix), and holds:
//!
//! * the size bound of the commutative eliminant, computed before anything
//!   is expanded, and the eliminant itself
//!   ([`super::eliminate::Eliminant`]: `det(A)/h · x_i = Σ_j c_j g_j` with
//!   the common factor `h` removed) when the bound allows it;
//! * the ordered elimination ([`super::ordered::OrderedElimination`]:
//!   Schur complements, pivot sequence, inverses required), which commutes
//!   nothing;
//! * the **commuted pairs** (see [`Derivation::commuted_pairs`]).
//!
//! This module owns only that assembly and the size bound; the
//! eliminations are [`super::eliminate`]'s and [`super::ordered`]'s. It
//! must not know about files, kernels, f64 or printing.

use super::eliminate::{CommutedPair, Eliminant, EliminateError, eliminate_ordered};
use super::matrix::Matrix;
use super::ncpoly::NcPoly;
use super::ordered::{EliminationSteps, OrderedElimination, OrderedError, eliminate_in_steps};
use super::polyring::PolyRing;

/// The largest bound on the number of terms of `det(A)` for which the
/// commutative eliminant is expanded. Past it, `det` and `adj` (Bareiss
/// over Q\[symbols\]) may take minutes: the eliminant of a sparse 20×20
/// system with three terms per row has a bound of 3^20 ≈ 3.5e9.
pub const MAX_ELIMINANT_TERMS: f64 = 20_000.0;

/// An upper bound on the size of `det(A)` (and so of the eliminant),
/// computed from the entries without expanding anything.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SizeBound {
    /// At most this many terms: the smaller of the products of the row
    /// sums and of the column sums of the entries' term counts (each term
    /// of `det` comes from one product of one term per row and column),
    /// and of the number of monomials of degree at most `degree`.
    pub terms: f64,
    /// At most this total degree: the smaller of `Σ_i max_j deg A_ij` and
    /// `Σ_j max_i deg A_ij`.
    pub degree: u32,
}

impl SizeBound {
    /// The bound for the square λ-matrix `a`.
    pub fn of(a: &Matrix<PolyRing>) -> SizeBound {
        let (r, c) = (a.rows(), a.cols());
        let count = |i: usize, j: usize| a.get(i, j).terms().len() as f64;
        let deg = |i: usize, j: usize| a.get(i, j).total_degree().unwrap_or(0);
        let row_terms: f64 = (0..r)
            .map(|i| (0..c).map(|j| count(i, j)).sum::<f64>())
            .product();
        let col_terms: f64 = (0..c)
            .map(|j| (0..r).map(|i| count(i, j)).sum::<f64>())
            .product();
        let row_deg: u32 = (0..r)
            .map(|i| (0..c).map(|j| deg(i, j)).max().unwrap_or(0))
            .sum();
        let col_deg: u32 = (0..c)
            .map(|j| (0..r).map(|i| deg(i, j)).max().unwrap_or(0))
            .sum();
        let degree = row_deg.min(col_deg);
        // Monomials of degree ≤ D in m variables: C(m + D, D).
        let m = a.ring.nvars() as f64;
        let monomials = (1..=degree).fold(1.0, |acc: f64, k| acc * (m + k as f64) / k as f64);
        SizeBound {
            terms: row_terms.min(col_terms).min(monomials),
            degree,
        }
    }

    /// Whether the eliminant may be expanded.
    pub fn allows_expansion(&self) -> bool {
        self.terms <= MAX_ELIMINANT_TERMS
    }
}

/// The derivation of one unknown of one system.
#[derive(Clone, Debug, PartialEq)]
pub struct Derivation {
    /// The unknown solved for (0-based).
    pub target: usize,
    /// The principal symbol the ordered elimination prefers as pivot.
    pub principal: Option<usize>,
    /// The size bound of the commutative eliminant.
    pub bound: SizeBound,
    /// The commutative eliminant; `None` when [`Derivation::bound`] is past
    /// [`MAX_ELIMINANT_TERMS`] (it was not expanded).
    pub eliminant: Option<Eliminant>,
    /// The ordered elimination written out (Schur form), or why it is not
    /// ([`OrderedError::TooLarge`] when its entries fill in).
    pub ordered: Result<OrderedElimination, OrderedError>,
    /// The same elimination as steps with named intermediates (never
    /// expanded, so it exists at any size), or why there is none. Its
    /// pivots are those of [`Derivation::ordered`] when that exists; they
    /// are what `solve --method ordered` executes
    /// ([`Derivation::pivot_order`]).
    pub steps: Result<EliminationSteps, OrderedError>,
}

impl Derivation {
    /// Derives unknown `target` of the system whose ordered operators are
    /// `words` (row `i`, column `j`) and whose λ-matrix is `image`. Fails
    /// only for a system that has no single equation at all (not square,
    /// no such unknown, `det(A) = 0` when the eliminant is expanded).
    pub fn new(
        image: &Matrix<PolyRing>,
        words: &[Vec<NcPoly>],
        target: usize,
        principal: Option<usize>,
    ) -> Result<Derivation, EliminateError> {
        let n = image.rows();
        if image.cols() != n {
            return Err(EliminateError::NotSquare {
                rows: n,
                cols: image.cols(),
            });
        }
        if target >= n {
            return Err(EliminateError::NoSuchUnknown(target));
        }
        let bound = SizeBound::of(image);
        let eliminant = if bound.allows_expansion() {
            Some(eliminate_ordered(image, words, target)?)
        } else {
            None
        };
        let (steps, ordered) = match eliminate_in_steps(image, words, target, principal) {
            Ok((steps, ordered)) => (Ok(steps), ordered),
            Err(e) => (Err(e.clone()), Err(e)),
        };
        Ok(Derivation {
            target,
            principal,
            bound,
            eliminant,
            ordered,
            steps,
        })
    }

    /// The commuted pairs: the pairs of distinct symbols `{a, b}` whose
    /// commutation the commutative eliminant relies on. The eliminant is
    /// obtained by multiplying equation `j` on the left by `c_j =
    /// adj(A)_{ij}/h` (its monomials read in symbol-table order) and
    /// summing; with every product kept in its written order this gives,
    /// exactly, `Σ_k D_k x_k = Σ_j c_j g_j` with `D_k = Σ_j c_j A_jk`. The
    /// eliminant keeps `D_i` (executed as this ordered operator; its image
    /// is `det(A)/h`) and drops every `D_k`, `k ≠ i`, whose commutative
    /// image is zero. A pair is listed when some dropped `D_k` does not
    /// vanish on that pair alone (delete every other symbol from its
    /// words): then `D_k ≠ 0` whenever `a` and `b` do not commute, so each
    /// listed pair is necessary. When the necessary pairs do not suffice
    /// for some `D_k` (checked in the trace monoid), every pair of its
    /// symbols is listed instead. Empty when nothing is dropped (the
    /// eliminant is then exact) or when the eliminant was not expanded.
    pub fn commuted_pairs(&self) -> &[CommutedPair] {
        self.eliminant
            .as_ref()
            .map_or(&[], |e| e.commuted_pairs.as_slice())
    }

    /// The pivots of the ordered elimination as (equation, unknown), in the
    /// order they are used: those of [`Derivation::steps`], which are also
    /// those of the Schur form when it is written out (empty if there is no
    /// ordered elimination).
    pub fn pivot_order(&self) -> Vec<(usize, usize)> {
        match &self.steps {
            Ok(s) => s.pivot_order(),
            Err(_) => Vec::new(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn system(words: Vec<Vec<NcPoly>>, nvars: usize) -> Matrix<PolyRing> {
        let names: Vec<String> = (1..=nvars).map(|i| format!("k{i}")).collect();
        let n = words.len();
        let entries = words
            .iter()
            .flat_map(|r| r.iter().map(|w| w.commutative_image(nvars)))
            .collect();
        Matrix::new(PolyRing::new(names), n, n, entries)
    }

    fn k(i: usize) -> NcPoly {
        NcPoly::var(i)
    }

    #[test]
    fn seed_system_commutes_k2_k4_and_pivots_on_k4() {
        let words = vec![vec![k(0), k(1)], vec![k(2), k(3)]];
        let a = system(words.clone(), 4);
        let d = Derivation::new(&a, &words, 0, Some(3)).unwrap();
        let pairs: Vec<(usize, usize)> = d.commuted_pairs().iter().map(|c| (c.a, c.b)).collect();
        assert_eq!(pairs, [(1, 3)]);
        assert_eq!(d.pivot_order(), [(1, 1)]);
        assert!(d.bound.allows_expansion());
        assert_eq!(d.bound.degree, 2);
    }

    #[test]
    fn commuted_pairs_come_from_the_written_words() {
        // [[k1, k2], [k3, k4 k2 + 1]]: the multipliers for p are
        // (k2 k4 + 1, -k2), and the q-coefficient they leave is
        // (k2 k4 + 1) k2 - k2 (k4 k2 + 1) = 0 as written, so nothing is
        // commuted; read in table order (k2 k4 + 1) it would need (k2, k4).
        let one = NcPoly::constant(crate::algebra::rational::qi(1));
        let written = vec![vec![k(0), k(1)], vec![k(2), &(&k(3) * &k(1)) + &one]];
        let sorted = vec![vec![k(0), k(1)], vec![k(2), &(&k(1) * &k(3)) + &one]];
        let a = system(written.clone(), 4);
        let d = Derivation::new(&a, &written, 0, None).unwrap();
        let e = Derivation::new(&a, &sorted, 0, None).unwrap();
        let (de, ee) = (d.eliminant.as_ref().unwrap(), e.eliminant.as_ref().unwrap());
        assert_eq!(de.lhs, ee.lhs);
        assert!(de.dropped.is_empty() && d.commuted_pairs().is_empty());
        let pairs: Vec<(usize, usize)> = e.commuted_pairs().iter().map(|c| (c.a, c.b)).collect();
        assert_eq!(pairs, [(1, 3)]);
    }

    #[test]
    fn a_large_system_is_bounded_not_expanded() {
        // 20 unknowns, three terms per row: bound 3^20 terms.
        let n = 20;
        let one = NcPoly::constant(crate::algebra::rational::qi(1));
        let words: Vec<Vec<NcPoly>> = (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| {
                        if j == i {
                            one.clone()
                        } else if j == (i + 1) % n {
                            k(i)
                        } else if j == (i + 7) % n {
                            &k((i + 1) % n) * &k(i)
                        } else {
                            NcPoly::zero()
                        }
                    })
                    .collect()
            })
            .collect();
        let a = system(words.clone(), n);
        let d = Derivation::new(&a, &words, 0, None).unwrap();
        assert!(!d.bound.allows_expansion());
        assert!(d.bound.terms >= 3f64.powi(20) - 1.0, "{:?}", d.bound);
        assert!(d.eliminant.is_none() && d.commuted_pairs().is_empty());
        // Its Schur complements fill in geometrically: not written out, but
        // the steps (named intermediates, nothing expanded) exist and
        // eliminate all 19 other unknowns.
        assert_eq!(d.ordered, Err(OrderedError::TooLarge));
        let steps = d.steps.as_ref().expect("steps at any size");
        assert_eq!(d.pivot_order().len(), n - 1);
        assert_eq!(steps.equation, 0);
        assert!(!d.pivot_order().iter().any(|&(_, u)| u == 0));
    }
}
