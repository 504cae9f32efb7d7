//! The ordered (non-commutative) elimination of one unknown from a square
//! system `A·X = G` of operator equations: block Gaussian elimination by
//! successive Schur complements, with explicit inverses of the pivots, e.g.
//! `(k1 - k2 k4^-1 k3) p = g1 - k2 k4^-1 g2`. No symbol is ever moved past
//! another, so the result is exact for non-commuting operators provided the
//! listed inverses exist. This module owns the non-commutative rational
//! expressions ([`NcExpr`]) and the elimination; it must not know about
//! files, kernels or printing beyond names borrowed for display.

use super::matrix::Matrix;
use super::mpoly::MPoly;
use super::ncpoly::NcPoly;
use super::polyring::PolyRing;
use super::print::{Node, PrintOptions, print};
use super::ratfunc::{RatFunc, RatFuncField};
use super::rational::Q;
use super::ring::{Field, Ring};
use num_traits::{One, Signed, Zero};

/// One factor of a product: a symbol or the inverse of an expression.
#[derive(Clone, Debug, PartialEq)]
pub enum Factor {
    /// The symbol with this index.
    Sym(usize),
    /// The inverse of an expression that is not a single product.
    Inv(Box<NcExpr>),
}

/// A non-commutative rational expression: a sum of `coefficient · product
/// of factors`, where a factor is a symbol or an inverse.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct NcExpr {
    terms: Vec<(Q, Vec<Factor>)>,
}

impl NcExpr {
    /// Zero.
    pub fn zero() -> Self {
        NcExpr::default()
    }

    /// The constant `c`.
    pub fn constant(c: Q) -> Self {
        NcExpr::zero().plus_term(c, Vec::new())
    }

    /// The symbol `i`.
    pub fn sym(i: usize) -> Self {
        NcExpr::zero().plus_term(Q::one(), vec![Factor::Sym(i)])
    }

    /// A commutative polynomial with its monomials read as products in
    /// symbol-table order.
    pub fn from_mpoly(p: &MPoly) -> Self {
        let mut out = NcExpr::zero();
        for (m, c) in p.terms() {
            let fs: Vec<Factor> = m
                .iter()
                .enumerate()
                .flat_map(|(v, &e)| std::iter::repeat_n(Factor::Sym(v), e as usize))
                .collect();
            out = out.plus_term(c.clone(), fs);
        }
        out
    }

    /// An ordered polynomial, word by word.
    pub fn from_ncpoly(p: &NcPoly) -> Self {
        let mut out = NcExpr::zero();
        for (w, c) in p.terms() {
            out = out.plus_term(c.clone(), w.iter().map(|&s| Factor::Sym(s)).collect());
        }
        out
    }

    fn plus_term(mut self, c: Q, fs: Vec<Factor>) -> Self {
        if c.is_zero() {
            return self;
        }
        let fs = cancel_inverses(fs);
        if let Some(k) = self.terms.iter().position(|(_, f)| *f == fs) {
            let s = &self.terms[k].0 + &c;
            if s.is_zero() {
                self.terms.remove(k);
            } else {
                self.terms[k].0 = s;
            }
        } else {
            self.terms.push((c, fs));
        }
        self
    }

    /// Whether this is zero as written (no terms).
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// The value if this is a constant (no factors).
    pub fn as_constant(&self) -> Option<Q> {
        match self.terms.as_slice() {
            [] => Some(Q::zero()),
            [(c, fs)] if fs.is_empty() => Some(c.clone()),
            _ => None,
        }
    }

    /// The symbol if this is exactly one symbol times a nonzero constant.
    pub fn as_scaled_symbol(&self) -> Option<(Q, usize)> {
        match self.terms.as_slice() {
            [(c, fs)] => match fs.as_slice() {
                [Factor::Sym(i)] => Some((c.clone(), *i)),
                _ => None,
            },
            _ => None,
        }
    }

    /// Whether one term is a nonzero constant (no factors).
    pub fn has_constant_term(&self) -> bool {
        self.terms.iter().any(|(_, fs)| fs.is_empty())
    }

    /// Number of terms of the sum.
    pub fn len(&self) -> usize {
        self.terms.len()
    }

    /// Whether the sum has no terms (same as [`NcExpr::is_zero`]).
    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }

    /// `self + other`.
    pub fn add(&self, other: &NcExpr) -> NcExpr {
        let mut out = self.clone();
        for (c, fs) in &other.terms {
            out = out.plus_term(c.clone(), fs.clone());
        }
        out
    }

    /// `-self`.
    pub fn neg(&self) -> NcExpr {
        NcExpr {
            terms: self.terms.iter().map(|(c, f)| (-c, f.clone())).collect(),
        }
    }

    /// `self - other`.
    pub fn sub(&self, other: &NcExpr) -> NcExpr {
        self.add(&other.neg())
    }

    /// `self · other` (in this order).
    pub fn mul(&self, other: &NcExpr) -> NcExpr {
        let mut out = NcExpr::zero();
        for (ca, fa) in &self.terms {
            for (cb, fb) in &other.terms {
                let mut fs = fa.clone();
                fs.extend(fb.iter().cloned());
                out = out.plus_term(ca * cb, fs);
            }
        }
        out
    }

    /// The inverse, or `None` for zero. A single product `c·f1…fm` inverts
    /// factor by factor in reverse order; a sum becomes one [`Factor::Inv`].
    pub fn inv(&self) -> Option<NcExpr> {
        match self.terms.as_slice() {
            [] => None,
            [(c, fs)] => {
                let mut out = NcExpr::constant(c.recip());
                for f in fs.iter().rev() {
                    let fi = match f {
                        Factor::Sym(_) => NcExpr::zero().plus_term(
                            Q::one(),
                            vec![Factor::Inv(Box::new(NcExpr {
                                terms: vec![(Q::one(), vec![f.clone()])],
                            }))],
                        ),
                        Factor::Inv(e) => (**e).clone(),
                    };
                    out = out.mul(&fi);
                }
                Some(out)
            }
            _ => {
                Some(NcExpr::zero().plus_term(Q::one(), vec![Factor::Inv(Box::new(self.clone()))]))
            }
        }
    }

    /// Every inverse that occurs (outermost first, without repeats).
    pub fn inverses(&self) -> Vec<NcExpr> {
        let mut out: Vec<NcExpr> = Vec::new();
        for (_, fs) in &self.terms {
            for f in fs {
                if let Factor::Inv(e) = f {
                    if !out.contains(e) {
                        out.push((**e).clone());
                    }
                    for x in e.inverses() {
                        if !out.contains(&x) {
                            out.push(x);
                        }
                    }
                }
            }
        }
        out
    }

    /// The image in the field Q(s_0..s_{nvars-1}) when every symbol commutes;
    /// `None` if an inverse of something whose image is zero occurs.
    pub fn commutative_image(&self, k: &RatFuncField) -> Option<RatFunc> {
        let n = k.names.len();
        let mut acc = k.zero();
        for (c, fs) in &self.terms {
            let mut t = RatFunc::from_poly(MPoly::constant(c.clone(), n));
            for f in fs {
                let v = match f {
                    Factor::Sym(i) => RatFunc::from_poly(MPoly::var(*i, n)),
                    Factor::Inv(e) => k.inv(&e.commutative_image(k)?)?,
                };
                t = k.mul(&t, &v);
            }
            acc = k.add(&acc, &t);
        }
        Some(acc)
    }

    /// The print tree: a signed sum of ordered products
    /// `coefficient factor…`, a run of one symbol as a power, the inverse
    /// of a symbol as `k4^-1` and of a sum as `(…)^-1`.
    pub fn to_node<S: AsRef<str>>(&self, names: &[S]) -> Node {
        Node::Terms(
            self.terms
                .iter()
                .map(|(c, fs)| {
                    let mut word = Vec::new();
                    if !c.abs().is_one() || fs.is_empty() {
                        word.push(Node::Num(c.abs()));
                    }
                    word.extend(factor_nodes(fs, names));
                    let node = if word.len() == 1 {
                        word.remove(0)
                    } else {
                        Node::Word(word)
                    };
                    (c.is_negative(), node)
                })
                .collect(),
        )
    }

    /// Text form: products by juxtaposition, `k4^-1` for the inverse of a
    /// symbol, `(…)^-1` otherwise: `k1 - k2 k4^-1 k3`.
    pub fn to_string_with<S: AsRef<str>>(&self, names: &[S]) -> String {
        print(&self.to_node(names), PrintOptions::TEXT)
    }

    /// LaTeX form: `k_{1} - k_{2} k_{4}^{-1} k_{3}`.
    pub fn to_latex_with<S: AsRef<str>>(&self, names: &[S]) -> String {
        print(&self.to_node(names), PrintOptions::LATEX)
    }

    /// The language's syntax: `k1 - k2*k4^(-1)*k3`.
    pub fn to_lmx_with<S: AsRef<str>>(&self, names: &[S]) -> String {
        print(&self.to_node(names), PrintOptions::LMX)
    }
}

/// Removes adjacent `s s^-1` and `s^-1 s` pairs of one symbol.
fn cancel_inverses(fs: Vec<Factor>) -> Vec<Factor> {
    let mut out: Vec<Factor> = Vec::with_capacity(fs.len());
    for f in fs {
        let cancels = match (out.last(), &f) {
            (Some(Factor::Sym(a)), Factor::Inv(e)) | (Some(Factor::Inv(e)), Factor::Sym(a)) => e
                .as_scaled_symbol()
                .is_some_and(|(c, b)| b == *a && c.is_one()),
            _ => false,
        };
        if cancels {
            out.pop();
        } else {
            out.push(f);
        }
    }
    out
}

fn factor_nodes<S: AsRef<str>>(fs: &[Factor], names: &[S]) -> Vec<Node> {
    let name = |i: usize| {
        Node::Sym(
            names
                .get(i)
                .map(|s| s.as_ref().to_string())
                .unwrap_or_else(|| format!("s{i}")),
        )
    };
    let mut parts: Vec<Node> = Vec::new();
    let mut k = 0;
    while k < fs.len() {
        match &fs[k] {
            Factor::Sym(i) => {
                let mut run = 1;
                while fs.get(k + run) == Some(&Factor::Sym(*i)) {
                    run += 1;
                }
                parts.push(Node::pow_i(name(*i), run as i64));
                k += run;
            }
            Factor::Inv(e) => {
                let inner = match e.as_scaled_symbol() {
                    Some((c, i)) if c.is_one() => name(i),
                    _ => e.to_node(names),
                };
                parts.push(Node::pow_i(inner, -1));
                k += 1;
            }
        }
    }
    parts
}

/// One pivot of the elimination: unknown `unknown` was solved from
/// equation `equation` (both 0-based, in the original numbering) with this
/// pivot entry, whose inverse the result uses.
#[derive(Clone, Debug, PartialEq)]
pub struct Pivot {
    /// The original equation.
    pub equation: usize,
    /// The eliminated unknown.
    pub unknown: usize,
    /// The pivot (an entry of the current Schur complement).
    pub entry: NcExpr,
}

/// `lhs · x_unknown = Σ_j rhs[j] · g_j`, derived without commuting symbols.
#[derive(Clone, Debug, PartialEq)]
pub struct OrderedElimination {
    /// The unknown (0-based).
    pub unknown: usize,
    /// The equation that is left over (0-based, original numbering).
    pub equation: usize,
    /// The operator applied to the unknown (a Schur complement).
    pub lhs: NcExpr,
    /// The operator applied to each right side `g_j` (zero if unused).
    pub rhs: Vec<NcExpr>,
    /// The pivots in the order they were used.
    pub pivots: Vec<Pivot>,
}

/// Why an ordered elimination could not be carried out.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum OrderedError {
    /// The matrix is not square.
    #[error("the ordered elimination needs a square system ({rows}×{cols} given)")]
    NotSquare {
        /// Rows.
        rows: usize,
        /// Columns.
        cols: usize,
    },
    /// The unknown index is out of range.
    #[error("unknown number {0} does not exist")]
    NoSuchUnknown(usize),
    /// An unknown occurs in none of the remaining equations.
    #[error("unknown number {unknown} drops out of the remaining equations: no pivot")]
    NoPivot {
        /// The unknown (0-based).
        unknown: usize,
    },
    /// The remaining equation does not contain the unknown.
    #[error("the unknown drops out of the last equation: its operator is zero")]
    ZeroLhs,
    /// An entry of a Schur complement would exceed [`MAX_ENTRY_TERMS`] terms.
    #[error(
        "the ordered elimination is too large to write out: an entry of a Schur complement would have more than {MAX_ENTRY_TERMS} terms"
    )]
    TooLarge,
}

/// The most terms one entry of a Schur complement (or one product formed
/// on the way) may have; past it the elimination stops with
/// [`OrderedError::TooLarge`] instead of filling memory (products of sums
/// grow geometrically with the number of eliminated unknowns).
pub const MAX_ENTRY_TERMS: usize = 256;

/// Sort key of a candidate pivot: (class, off the diagonal, unknown, equation).
type PivotKey = (u8, bool, usize, usize);

/// Pivot preference: lower is better. After constants and the principal
/// symbol come entries of the second kind, `c + K` with a nonzero
/// constant `c` (identity plus operators: invertible in the cases that
/// matter and well conditioned), then single symbols (first kind), single
/// products, anything else.
fn pivot_class(e: &NcExpr, principal: Option<usize>) -> u8 {
    if e.as_constant().is_some() {
        0
    } else if let Some((_, s)) = e.as_scaled_symbol() {
        if Some(s) == principal { 1 } else { 3 }
    } else if e.has_constant_term() {
        2
    } else if e.len() == 1 {
        4
    } else {
        5
    }
}

/// Eliminates every unknown but `unknown` by Schur complements, choosing
/// as pivot a constant if possible, else the principal symbol, else an
/// entry of the second kind (`c + K`), else a single symbol, else a single
/// product, else any nonzero entry (ties: the diagonal, then the first
/// unknown, then the first equation).
///
/// ```
/// use lambdamat::algebra::{matrix::Matrix, mpoly::MPoly, polyring::PolyRing};
/// use lambdamat::algebra::ordered::ordered_elimination;
/// let names = ["k1", "k2", "k3", "k4"].map(String::from).to_vec();
/// let a = Matrix::new(PolyRing::new(names.clone()), 2, 2,
///     (0..4).map(|i| MPoly::var(i, 4)).collect());
/// let o = ordered_elimination(&a, 0, Some(3)).unwrap();
/// assert_eq!(o.to_string_with(&names, "p"), "(k1 - k2 k4^-1 k3) p = g1 - k2 k4^-1 g2");
/// ```
#[cfg(any(test, feature = "internals"))]
pub fn ordered_elimination(
    a: &Matrix<PolyRing>,
    unknown: usize,
    principal: Option<usize>,
) -> Result<OrderedElimination, OrderedError> {
    let words: Vec<Vec<NcPoly>> = (0..a.rows())
        .map(|i| {
            (0..a.cols())
                .map(|j| NcPoly::from_mpoly(a.get(i, j)))
                .collect()
        })
        .collect();
    ordered_elimination_of(a, &words, unknown, principal)
}

/// [`ordered_elimination`] of the system whose ordered operators are
/// `words` (row `i`, column `j`, products in the order written) and whose
/// commutative image is `a`: the Schur form of [`eliminate_in_steps`], or
/// why it cannot be written out.
#[cfg(any(test, feature = "internals"))]
pub fn ordered_elimination_of(
    a: &Matrix<PolyRing>,
    words: &[Vec<NcPoly>],
    unknown: usize,
    principal: Option<usize>,
) -> Result<OrderedElimination, OrderedError> {
    eliminate_in_steps(a, words, unknown, principal)?.1
}

/// One entry of the system being eliminated: symbolically (an entry as
/// written, a named intermediate, or zero) and, while it stays small,
/// expanded over the operator symbols.
#[derive(Clone)]
struct Entry {
    sym: NcExpr,
    full: Option<NcExpr>,
}

impl Entry {
    fn is_zero(&self) -> bool {
        match &self.full {
            Some(e) => e.is_zero(),
            None => self.sym.is_zero(),
        }
    }
}

/// The ordered elimination of unknown `unknown`, carried out once: the
/// pivots are chosen as documented at [`ordered_elimination`] (an entry
/// that was not expanded because it grew past [`MAX_ENTRY_TERMS`] ranks
/// last), every update of a remaining equation is recorded as a named
/// intermediate ([`EliminationSteps`], never expanded), and the Schur form
/// ([`OrderedElimination`]) is returned beside it when every entry stayed
/// within [`MAX_ENTRY_TERMS`] terms (else [`OrderedError::TooLarge`]). Both
/// have the same pivot sequence. The outer error is for a system with no
/// ordered elimination at all.
#[allow(clippy::type_complexity)]
pub fn eliminate_in_steps(
    a: &Matrix<PolyRing>,
    words: &[Vec<NcPoly>],
    unknown: usize,
    principal: Option<usize>,
) -> Result<(EliminationSteps, Result<OrderedElimination, OrderedError>), OrderedError> {
    let n = a.rows();
    if a.cols() != n {
        return Err(OrderedError::NotSquare {
            rows: n,
            cols: a.cols(),
        });
    }
    if unknown >= n {
        return Err(OrderedError::NoSuchUnknown(unknown));
    }
    let nsym = a.ring.nvars();
    // Symbols of the steps form: the operators, then g1..gn (the right
    // sides), then the intermediates in the order they are named.
    let g_sym = |r: usize| nsym + r;
    let inter_sym = |k: usize| nsym + n + k;
    // m[r][c]: column c < n is unknown c, column n is the right side.
    let mut m: Vec<Vec<Entry>> = (0..n)
        .map(|i| {
            let mut row: Vec<Entry> = (0..n)
                .map(|j| {
                    let e = match words.get(i).and_then(|r| r.get(j)) {
                        Some(w) => NcExpr::from_ncpoly(w),
                        None => NcExpr::from_mpoly(a.get(i, j)),
                    };
                    Entry {
                        sym: e.clone(),
                        full: Some(e),
                    }
                })
                .collect();
            row.push(Entry {
                sym: NcExpr::sym(g_sym(i)),
                full: None,
            });
            row
        })
        .collect();
    // The expanded right sides: rhs[r][j] is the coefficient of g_j.
    let mut rhs: Vec<Option<Vec<NcExpr>>> = (0..n)
        .map(|i| {
            Some(
                (0..n)
                    .map(|j| {
                        if i == j {
                            NcExpr::constant(Q::one())
                        } else {
                            NcExpr::zero()
                        }
                    })
                    .collect(),
            )
        })
        .collect();
    let mut expanding = true;
    let mut rows: Vec<usize> = (0..n).collect();
    let mut cols: Vec<usize> = (0..n).filter(|&j| j != unknown).collect();
    let mut pivots = Vec::new();
    let mut steps = Vec::new();
    let mut inters: Vec<Intermediate> = Vec::new();
    let too_large =
        |a: &NcExpr, b: &NcExpr, c: &NcExpr| a.len() * b.len() + c.len() > MAX_ENTRY_TERMS;
    while !cols.is_empty() {
        let mut best: Option<(PivotKey, usize, usize)> = None;
        for &j in &cols {
            for &r in &rows {
                let e = &m[r][j];
                if e.is_zero() {
                    continue;
                }
                let class = e.full.as_ref().map_or(6, |f| pivot_class(f, principal));
                let key = (class, r != j, j, r);
                if best.as_ref().is_none_or(|(k, _, _)| key < *k) {
                    best = Some((key, r, j));
                }
            }
        }
        let Some((_, r, j)) = best else {
            return Err(OrderedError::NoPivot { unknown: cols[0] });
        };
        let piv = m[r][j].clone();
        let Some(inv) = piv.sym.inv() else {
            return Err(OrderedError::NoPivot { unknown: j });
        };
        let full_inv = piv.full.as_ref().and_then(NcExpr::inv);
        rows.retain(|&x| x != r);
        cols.retain(|&x| x != j);
        let mut updates = Vec::new();
        for &s in &rows {
            if m[s][j].is_zero() {
                continue;
            }
            let f_sym = m[s][j].sym.mul(&inv);
            let mut f_full = None;
            if expanding {
                match (&m[s][j].full, &full_inv) {
                    (Some(x), Some(y)) if !too_large(x, y, &NcExpr::zero()) => {
                        f_full = Some(x.mul(y));
                    }
                    _ => expanding = false,
                }
            }
            for &c in cols.iter().chain([&unknown, &n]) {
                if c < n && m[r][c].is_zero() {
                    continue;
                }
                let mut full = None;
                if expanding && c < n {
                    match (&f_full, &m[r][c].full, &m[s][c].full) {
                        (Some(f), Some(x), Some(old)) if !too_large(f, x, old) => {
                            full = Some(old.sub(&f.mul(x)));
                        }
                        _ => expanding = false,
                    }
                }
                if c == n && expanding {
                    match (&f_full, &rhs[r], &rhs[s]) {
                        (Some(f), Some(pr), Some(sr)) => {
                            let mut out = Vec::with_capacity(n);
                            for (x, y) in sr.iter().zip(pr) {
                                if y.is_zero() {
                                    out.push(x.clone());
                                } else if too_large(f, y, x) {
                                    expanding = false;
                                    break;
                                } else {
                                    out.push(x.sub(&f.mul(y)));
                                }
                            }
                            rhs[s] = expanding.then_some(out);
                        }
                        _ => expanding = false,
                    }
                }
                if !expanding {
                    rhs[s] = None;
                }
                let value = m[s][c].sym.sub(&f_sym.mul(&m[r][c].sym));
                let vanishes = full.as_ref().is_some_and(NcExpr::is_zero);
                let k = inters.len();
                inters.push(Intermediate {
                    equation: s,
                    column: (c < n).then_some(c),
                    value,
                    vanishes,
                });
                updates.push(k);
                m[s][c] = if vanishes {
                    Entry {
                        sym: NcExpr::zero(),
                        full,
                    }
                } else {
                    Entry {
                        sym: NcExpr::sym(inter_sym(k)),
                        full,
                    }
                };
            }
            m[s][j] = Entry {
                sym: NcExpr::zero(),
                full: Some(NcExpr::zero()),
            };
        }
        steps.push(Step {
            equation: r,
            unknown: j,
            pivot: piv.sym.clone(),
            inverse: inv,
            updates,
        });
        pivots.push(Pivot {
            equation: r,
            unknown: j,
            entry: piv.full.unwrap_or_else(|| piv.sym.clone()),
        });
    }
    let last = rows[0];
    if m[last][unknown].is_zero() {
        return Err(OrderedError::ZeroLhs);
    }
    let steps = EliminationSteps {
        unknown,
        equation: last,
        symbols: nsym,
        equations: n,
        steps,
        intermediates: inters,
        lhs: m[last][unknown].sym.clone(),
        rhs: m[last][n].sym.clone(),
    };
    let full = match (expanding, &m[last][unknown].full, &rhs[last]) {
        (true, Some(lhs), Some(r)) => Ok(OrderedElimination {
            unknown,
            equation: last,
            lhs: lhs.clone(),
            rhs: r.clone(),
            pivots,
        }),
        _ => Err(OrderedError::TooLarge),
    };
    Ok((steps, full))
}

/// One named intermediate of [`EliminationSteps`]: the new coefficient of
/// one unknown (or the new right side) of one remaining equation after a
/// pivot, `old - (entry of the pivot's column) · pivot^-1 · (entry of the
/// pivot equation)`, in the steps form's symbols.
#[derive(Clone, Debug, PartialEq)]
pub struct Intermediate {
    /// The equation updated (0-based, original numbering).
    pub equation: usize,
    /// The unknown whose coefficient this is (0-based), `None` for the
    /// right side.
    pub column: Option<usize>,
    /// Its definition, over the steps form's symbols.
    pub value: NcExpr,
    /// The definition expands to zero (so the entry is zero afterwards).
    pub vanishes: bool,
}

/// One pivot of [`EliminationSteps`] and the updates it makes.
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    /// The pivot equation (0-based, original numbering).
    pub equation: usize,
    /// The unknown it is solved for (0-based).
    pub unknown: usize,
    /// The pivot, over the steps form's symbols.
    pub pivot: NcExpr,
    /// The inverse it needs (a constant for a constant pivot).
    pub inverse: NcExpr,
    /// The intermediates it defines (indices into
    /// [`EliminationSteps::intermediates`]).
    pub updates: Vec<usize>,
}

/// The ordered elimination as a sequence of steps, with every updated
/// entry named instead of expanded, so it can be written out at any size:
/// its symbols are the operators (`0..symbols`), then `g1..gn` (the right
/// sides), then the intermediates (`Sk` for coefficients, `Rk` for right
/// sides, numbered separately from 1; see [`EliminationSteps::names`]).
/// The result is `lhs · x_unknown = rhs` in equation `equation`.
#[derive(Clone, Debug, PartialEq)]
pub struct EliminationSteps {
    /// The unknown solved for (0-based).
    pub unknown: usize,
    /// The equation left over (0-based, original numbering).
    pub equation: usize,
    /// Number of operator symbols.
    pub symbols: usize,
    /// Number of equations (and of right sides `g_j`).
    pub equations: usize,
    /// The pivots in the order they are used.
    pub steps: Vec<Step>,
    /// The named intermediates, in the order they are defined.
    pub intermediates: Vec<Intermediate>,
    /// The operator left on the unknown.
    pub lhs: NcExpr,
    /// The right side left over.
    pub rhs: NcExpr,
}

impl EliminationSteps {
    /// The pivots as (equation, unknown), in order.
    pub fn pivot_order(&self) -> Vec<(usize, usize)> {
        self.steps.iter().map(|s| (s.equation, s.unknown)).collect()
    }

    /// The names of the steps form's symbols: the operator names `ops`,
    /// `g1..gn`, then the intermediates, `S1, S2, …` for coefficients and
    /// `R1, R2, …` for right sides (another letter when an operator is
    /// already called so, e.g. `T1` if an operator is named `S1`).
    pub fn names<S: AsRef<str>>(&self, ops: &[S]) -> Vec<String> {
        let taken = |p: &str| {
            ops.iter().any(|o| {
                o.as_ref()
                    .strip_prefix(p)
                    .is_some_and(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()))
            })
        };
        let pick = |cands: &[&'static str]| {
            cands
                .iter()
                .copied()
                .find(|p| !taken(p))
                .unwrap_or(cands[cands.len() - 1])
        };
        let (s, r) = (pick(&["S", "T", "W", "S_"]), pick(&["R", "H", "V", "R_"]));
        let mut out: Vec<String> = ops.iter().map(|o| o.as_ref().to_string()).collect();
        out.extend((1..=self.equations).map(|j| format!("g{j}")));
        let (mut ns, mut nr) = (0, 0);
        for i in &self.intermediates {
            if i.column.is_some() {
                ns += 1;
                out.push(format!("{s}{ns}"));
            } else {
                nr += 1;
                out.push(format!("{r}{nr}"));
            }
        }
        out
    }

    /// The print tree of the result `lhs u = rhs`.
    pub fn result_node<S: AsRef<str>>(&self, names: &[S], unknown: &str) -> Node {
        let u = Node::sym(unknown);
        let lhs = match self.lhs.as_constant() {
            Some(c) if c.is_one() => u,
            _ => Node::Apply(Box::new(self.lhs.to_node(names)), Box::new(u)),
        };
        Node::Equation(Box::new(lhs), Box::new(self.rhs.to_node(names)))
    }

    /// The print tree of intermediate `k`'s definition `Sk = …`.
    pub fn definition_node<S: AsRef<str>>(&self, names: &[S], k: usize) -> Node {
        let name = names
            .get(self.symbols + self.equations + k)
            .map_or_else(|| format!("#{k}"), |s| s.as_ref().to_string());
        Node::Equation(
            Box::new(Node::Sym(name)),
            Box::new(self.intermediates[k].value.to_node(names)),
        )
    }

    /// Every distinct inverse the steps need, in order of use.
    pub fn inverses(&self) -> Vec<NcExpr> {
        let mut out: Vec<NcExpr> = Vec::new();
        for s in &self.steps {
            for x in s.inverse.inverses() {
                if !out.contains(&x) {
                    out.push(x);
                }
            }
        }
        out
    }
}

impl OrderedElimination {
    /// `(k1 - k2 k4^-1 k3) p = g1 - k2 k4^-1 g2` (`g_j` is the right side
    /// of equation j, numbered from 1).
    pub fn to_string_with<S: AsRef<str>>(&self, names: &[S], unknown: &str) -> String {
        self.render(names, unknown, false)
    }

    /// LaTeX form of [`OrderedElimination::to_string_with`].
    pub fn to_latex_with<S: AsRef<str>>(&self, names: &[S], unknown: &str) -> String {
        self.render(names, unknown, true)
    }

    /// The print tree of the equation `lhs u = Σ rhs_j g_j`.
    pub fn to_node<S: AsRef<str>>(&self, names: &[S], unknown: &str) -> Node {
        let u = Node::sym(unknown);
        let lhs = match self.lhs.as_constant() {
            Some(c) if c.is_one() => u,
            _ => Node::Apply(Box::new(self.lhs.to_node(names)), Box::new(u)),
        };
        let mut terms = Vec::new();
        for (j, r) in self.rhs.iter().enumerate() {
            if r.is_zero() {
                continue;
            }
            let g = Node::Sym(format!("g{}", j + 1));
            let (neg, body) = match r.to_node(names) {
                Node::Terms(mut ts) if ts.len() == 1 => ts.remove(0),
                sum => (false, sum),
            };
            let term = match body {
                Node::Num(c) if c.is_one() => g,
                Node::Word(mut fs) => {
                    fs.push(g);
                    Node::Word(fs)
                }
                other => Node::Word(vec![other, g]),
            };
            terms.push((neg, term));
        }
        Node::Equation(Box::new(lhs), Box::new(Node::Terms(terms)))
    }

    fn render<S: AsRef<str>>(&self, names: &[S], unknown: &str, latex: bool) -> String {
        let opts = if latex {
            PrintOptions::LATEX
        } else {
            PrintOptions::TEXT
        };
        print(&self.to_node(names, unknown), opts)
    }

    /// The equation in the language's syntax:
    /// `(k1 - k2*k4^(-1)*k3) p = g1 - k2*k4^(-1)*g2`.
    pub fn to_lmx_with<S: AsRef<str>>(&self, names: &[S], unknown: &str) -> String {
        print(&self.to_node(names, unknown), PrintOptions::LMX)
    }

    /// The distinct inverses the result uses, as text (`k4^-1`).
    pub fn required_inverses<S: AsRef<str>>(&self, names: &[S]) -> Vec<String> {
        self.inverse_nodes(names)
            .iter()
            .map(|n| print(n, PrintOptions::TEXT))
            .collect()
    }

    /// The distinct inverses in the language's syntax (`k4^(-1)`).
    pub fn required_inverses_lmx<S: AsRef<str>>(&self, names: &[S]) -> Vec<String> {
        self.inverse_nodes(names)
            .iter()
            .map(|n| print(n, PrintOptions::LMX))
            .collect()
    }

    fn inverse_nodes<S: AsRef<str>>(&self, names: &[S]) -> Vec<Node> {
        let mut all = self.lhs.inverses();
        for r in &self.rhs {
            for x in r.inverses() {
                if !all.contains(&x) {
                    all.push(x);
                }
            }
        }
        all.iter()
            .map(|e| Node::pow_i(e.to_node(names), -1))
            .collect()
    }

    /// Checks the result against Cramer's rule in the commutative image:
    /// `rhs_j / lhs = adj(A)_{i j} / det(A)` for every j. True when every
    /// symbol commuting makes the ordered and the commutative eliminations
    /// agree (they must).
    pub fn agrees_with_cramer(&self, a: &Matrix<PolyRing>) -> bool {
        let k = RatFuncField {
            names: a.ring.names.clone(),
            shown: a.ring.names.clone(),
        };
        let Some((det, Some(adj_row))) = a.det_adjugate_row(self.unknown) else {
            return false;
        };
        if det.is_zero() {
            return false;
        }
        let Some(l) = self.lhs.commutative_image(&k) else {
            return false;
        };
        let Some(linv) = k.inv(&l) else {
            return false;
        };
        let d = RatFunc::from_poly(det);
        (0..a.cols()).all(|j| {
            let Some(r) = self.rhs[j].commutative_image(&k) else {
                return false;
            };
            let lhs = k.mul(&r, &linv);
            let want = k.mul(
                &RatFunc::from_poly(adj_row[j].clone()),
                &k.inv(&d).unwrap_or_else(|| k.zero()),
            );
            lhs == want
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn generic(n: usize) -> (Vec<String>, Matrix<PolyRing>) {
        let names: Vec<String> = (1..=n * n).map(|i| format!("a{i}")).collect();
        let v = (0..n * n).map(|i| MPoly::var(i, n * n)).collect();
        (names.clone(), Matrix::new(PolyRing::new(names), n, n, v))
    }

    #[test]
    fn seed_ordered_elimination_for_p_and_q() {
        let names: Vec<String> = ["k1", "k2", "k3", "k4"].map(String::from).to_vec();
        let a = Matrix::new(
            PolyRing::new(names.clone()),
            2,
            2,
            (0..4).map(|i| MPoly::var(i, 4)).collect(),
        );
        let o = ordered_elimination(&a, 0, Some(3)).unwrap();
        assert_eq!(
            o.to_string_with(&names, "p"),
            "(k1 - k2 k4^-1 k3) p = g1 - k2 k4^-1 g2"
        );
        assert_eq!(o.required_inverses(&names), vec!["k4^-1"]);
        assert!(o.agrees_with_cramer(&a));
        assert_eq!(
            o.to_latex_with(&names, "p"),
            "\\left(k_{1} - k_{2} k_{4}^{-1} k_{3}\\right) p = g_{1} - k_{2} k_{4}^{-1} g_{2}"
        );
        // For q the principal symbol k4 is not eliminable; k1 is the first
        // single-symbol pivot on the diagonal.
        let o = ordered_elimination(&a, 1, Some(3)).unwrap();
        assert_eq!(
            o.to_string_with(&names, "q"),
            "(k4 - k3 k1^-1 k2) q = -k3 k1^-1 g1 + g2"
        );
        assert!(o.agrees_with_cramer(&a));
    }

    #[test]
    fn generic_3x3_agrees_with_cramer() {
        for n in [3] {
            let (names, a) = generic(n);
            for u in 0..n {
                let o = ordered_elimination(&a, u, None).unwrap();
                assert!(o.agrees_with_cramer(&a), "n = {n}, unknown {u}");
                assert_eq!(o.pivots.len(), n - 1);
                assert!(!o.required_inverses(&names).is_empty());
            }
        }
    }

    #[test]
    fn constant_pivots_need_no_inverse() {
        // [[k1, 1], [k2, k3]]: q from equation 1 with pivot 1.
        let names: Vec<String> = ["k1", "k2", "k3"].map(String::from).to_vec();
        let r = PolyRing::new(names.clone());
        let v = |i| MPoly::var(i, 3);
        let a = Matrix::new(r, 2, 2, vec![v(0), MPoly::one(3), v(1), v(2)]);
        let o = ordered_elimination(&a, 0, None).unwrap();
        assert_eq!(
            o.to_string_with(&names, "p"),
            "(k2 - k3 k1) p = -k3 g1 + g2"
        );
        assert!(o.required_inverses(&names).is_empty());
        assert!(o.agrees_with_cramer(&a));
    }

    #[test]
    fn a_zero_column_has_no_pivot() {
        let names: Vec<String> = ["k1"].map(String::from).to_vec();
        let r = PolyRing::new(names);
        let a = Matrix::new(
            r,
            2,
            2,
            vec![
                MPoly::var(0, 1),
                MPoly::zero(1),
                MPoly::one(1),
                MPoly::zero(1),
            ],
        );
        assert_eq!(
            ordered_elimination(&a, 0, None),
            Err(OrderedError::NoPivot { unknown: 1 })
        );
    }

    /// The value of a steps-form expression over the operator symbols and
    /// `g_j` (kept as symbols `nsym + j`): every intermediate substituted.
    fn substitute(e: &NcExpr, st: &EliminationSteps, vals: &[NcExpr]) -> NcExpr {
        let base = st.symbols + st.equations;
        let mut out = NcExpr::zero();
        for (c, fs) in &e.terms {
            let mut t = NcExpr::constant(c.clone());
            for f in fs {
                let v = match f {
                    Factor::Sym(i) if *i >= base => vals[*i - base].clone(),
                    Factor::Sym(i) => NcExpr::sym(*i),
                    Factor::Inv(x) => substitute(x, st, vals).inv().expect("nonzero"),
                };
                t = t.mul(&v);
            }
            out = out.add(&t);
        }
        out
    }

    #[test]
    fn steps_expand_to_the_schur_form_with_the_same_pivots() {
        for n in [2, 3] {
            let (names, a) = generic(n);
            let words: Vec<Vec<NcPoly>> = (0..n)
                .map(|i| (0..n).map(|j| NcPoly::from_mpoly(a.get(i, j))).collect())
                .collect();
            for u in 0..n {
                let (st, full) = eliminate_in_steps(&a, &words, u, None).unwrap();
                let o = full.unwrap();
                assert_eq!(
                    st.pivot_order(),
                    o.pivots
                        .iter()
                        .map(|p| (p.equation, p.unknown))
                        .collect::<Vec<_>>()
                );
                assert_eq!(st.equation, o.equation);
                let mut vals: Vec<NcExpr> = Vec::new();
                for i in &st.intermediates {
                    let v = substitute(&i.value, &st, &vals);
                    vals.push(v);
                }
                let lhs = substitute(&st.lhs, &st, &vals);
                assert!(lhs.sub(&o.lhs).is_zero(), "n = {n}, unknown {u}");
                // The right side: Σ_j rhs_j g_j with g_j the symbol nsym + j.
                let mut want = NcExpr::zero();
                for (j, r) in o.rhs.iter().enumerate() {
                    want = want.add(&r.mul(&NcExpr::sym(st.symbols + j)));
                }
                let got = substitute(&st.rhs, &st, &vals);
                assert!(got.sub(&want).is_zero(), "n = {n}, unknown {u}");
                let all = st.names(&names);
                assert_eq!(
                    all.len(),
                    st.symbols + st.equations + st.intermediates.len()
                );
            }
        }
    }

    #[test]
    fn intermediate_names_avoid_operator_names() {
        let names: Vec<String> = ["S1", "k2", "k3", "k4"].map(String::from).to_vec();
        let a = Matrix::new(
            PolyRing::new(names.clone()),
            2,
            2,
            (0..4).map(|i| MPoly::var(i, 4)).collect(),
        );
        let words: Vec<Vec<NcPoly>> = (0..2)
            .map(|i| (0..2).map(|j| NcPoly::from_mpoly(a.get(i, j))).collect())
            .collect();
        let (st, _) = eliminate_in_steps(&a, &words, 0, Some(3)).unwrap();
        let all = st.names(&names);
        assert_eq!(&all[4..6], ["g1", "g2"]);
        assert!(
            all[6..]
                .iter()
                .all(|x| x.starts_with('T') || x.starts_with('R')),
            "{all:?}"
        );
        let def = print(&st.definition_node(&all, 0), PrintOptions::TEXT);
        assert_eq!(def, "T1 = S1 - k2 k4^-1 k3");
    }

    #[test]
    fn inverses_of_products_reverse_and_cancel() {
        let e = NcExpr::sym(0).mul(&NcExpr::sym(1));
        let inv = e.inv().unwrap();
        assert_eq!(inv.to_string_with(&["a", "b"]), "b^-1 a^-1");
        assert_eq!(e.mul(&inv).as_constant(), Some(Q::one()));
        let s = NcExpr::sym(0).add(&NcExpr::sym(1));
        assert_eq!(s.inv().unwrap().to_string_with(&["a", "b"]), "(a + b)^-1");
        assert_eq!(NcExpr::zero().inv(), None);
    }
}
