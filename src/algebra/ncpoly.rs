//! Non-commutative polynomials over Q: linear combinations of words in the
//! symbols (a word is a product in a fixed order, `k4 k1` ≠ `k1 k4`), their
//! commutative image as an [`MPoly`], and the trace normal form used to ask
//! which symbol pairs must commute for a relation to hold. This module owns
//! only that arithmetic; it must not know about files, operators' kernels or
//! the elimination that uses it ([`super::eliminate`]).

use super::mpoly::MPoly;
use super::print::{Node, PrintOptions, print};
use super::rational::Q;
use num_traits::{One, Signed, Zero};
use std::collections::{BTreeMap, BTreeSet};

/// A product of symbols in order (indices into the symbol table).
pub type Word = Vec<usize>;

/// A polynomial in non-commuting symbols with rational coefficients.
///
/// ```
/// use lambdamat::algebra::ncpoly::NcPoly;
/// let (k1, k4) = (NcPoly::var(0), NcPoly::var(3));
/// let c = &(&k4 * &k1) - &(&k1 * &k4);
/// assert!(!c.is_zero());
/// assert!(c.commutative_image(4).is_zero());
/// assert_eq!(c.to_string_with(&["k1", "k2", "k3", "k4"]), "-k1 k4 + k4 k1");
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct NcPoly {
    terms: BTreeMap<Word, Q>,
}

impl NcPoly {
    /// Zero.
    pub fn zero() -> Self {
        NcPoly::default()
    }

    /// The constant `c`.
    pub fn constant(c: Q) -> Self {
        let mut p = NcPoly::zero();
        p.add_term(Vec::new(), c);
        p
    }

    /// The symbol `i`.
    pub fn var(i: usize) -> Self {
        let mut p = NcPoly::zero();
        p.add_term(vec![i], Q::one());
        p
    }

    /// The commutative polynomial `p` read as words with the symbols in
    /// table order (`k1*k4` → `k1 k4`): the order a commutative algebra
    /// fixes for its monomials.
    pub fn from_mpoly(p: &MPoly) -> Self {
        let mut out = NcPoly::zero();
        for (m, c) in p.terms() {
            let w: Word = m
                .iter()
                .enumerate()
                .flat_map(|(v, &e)| std::iter::repeat_n(v, e as usize))
                .collect();
            out.add_term(w, c.clone());
        }
        out
    }

    fn add_term(&mut self, w: Word, c: Q) {
        if c.is_zero() {
            return;
        }
        let cancelled = {
            let e = self.terms.entry(w.clone()).or_insert_with(Q::zero);
            *e += c;
            e.is_zero()
        };
        if cancelled {
            self.terms.remove(&w);
        }
    }

    /// Whether this is zero as a non-commutative polynomial.
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// The value if this is a constant (the empty word only, or zero).
    pub fn as_constant(&self) -> Option<Q> {
        match self.terms.iter().next() {
            None => Some(Q::zero()),
            Some((w, c)) if w.is_empty() && self.terms.len() == 1 => Some(c.clone()),
            _ => None,
        }
    }

    /// Whether symbol `s` occurs in some word.
    pub fn contains_var(&self, s: usize) -> bool {
        self.terms.keys().any(|w| w.contains(&s))
    }

    /// Number of terms (distinct words with a nonzero coefficient).
    pub fn len(&self) -> usize {
        self.terms.len()
    }

    /// Whether there are no terms (same as [`NcPoly::is_zero`]).
    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }

    /// The longest word's length (0 for constants and zero).
    pub fn degree(&self) -> usize {
        self.terms.keys().map(Vec::len).max().unwrap_or(0)
    }

    /// The sum of `c · w` over the given (word, coefficient) pairs.
    pub fn from_terms(terms: impl IntoIterator<Item = (Word, Q)>) -> Self {
        let mut out = NcPoly::zero();
        for (w, c) in terms {
            out.add_term(w, c);
        }
        out
    }

    /// `c · self`.
    pub fn scale(&self, c: &Q) -> Self {
        NcPoly::from_terms(self.terms.iter().map(|(w, k)| (w.clone(), k * c)))
    }

    /// `self^k` (`k` factors of `self` in a row; `self^0 = 1`).
    pub fn pow(&self, k: u32) -> Self {
        let mut out = NcPoly::constant(Q::one());
        for _ in 0..k {
            out = &out * self;
        }
        out
    }

    /// Whether every word lists its symbols in table order; exactly then
    /// the polynomial equals [`NcPoly::from_mpoly`] of its commutative
    /// image (distinct sorted words have distinct images).
    pub fn is_table_ordered(&self) -> bool {
        self.terms
            .keys()
            .all(|w| w.windows(2).all(|p| p[0] <= p[1]))
    }

    /// The terms (word, coefficient), in the printing order: by the
    /// commutative monomial (as [`MPoly`] orders it), then by word.
    pub fn terms(&self) -> Vec<(&Word, &Q)> {
        let mut v: Vec<(&Word, &Q)> = self.terms.iter().collect();
        v.sort_by(|a, b| cmp_exponents(b.0, a.0).then(a.0.cmp(b.0)));
        v
    }

    /// The symbols that occur.
    pub fn symbols(&self) -> BTreeSet<usize> {
        self.terms.keys().flatten().copied().collect()
    }

    /// The image in the commutative ring Q[s_0..s_{nvars-1}].
    pub fn commutative_image(&self, nvars: usize) -> MPoly {
        MPoly::from_terms(
            nvars,
            self.terms.iter().map(|(w, c)| {
                let mut m = vec![0u32; nvars];
                for &s in w {
                    if let Some(e) = m.get_mut(s) {
                        *e += 1;
                    }
                }
                (m, c.clone())
            }),
        )
    }

    /// The unordered pairs `{a, b}` (a < b) of distinct symbols whose
    /// commutation this polynomial needs in order to vanish: the pairs on
    /// which its projection (delete every other symbol from every word) is
    /// not zero. Each listed pair is necessary: if `a` and `b` did not
    /// commute the polynomial could not vanish, whatever the other symbols
    /// do. [`NcPoly::vanishes_if_commuting`] checks sufficiency.
    pub fn needed_commutations(&self) -> Vec<(usize, usize)> {
        let syms: Vec<usize> = self.symbols().into_iter().collect();
        let mut out = Vec::new();
        for (i, &a) in syms.iter().enumerate() {
            for &b in &syms[i + 1..] {
                let mut proj = NcPoly::zero();
                for (w, c) in &self.terms {
                    let pw: Word = w.iter().copied().filter(|&s| s == a || s == b).collect();
                    proj.add_term(pw, c.clone());
                }
                if !proj.is_zero() {
                    out.push((a, b));
                }
            }
        }
        out
    }

    /// Whether the polynomial is zero when exactly the given pairs of
    /// symbols commute (and no others): words are compared in the
    /// lexicographic normal form of the trace monoid.
    pub fn vanishes_if_commuting(&self, pairs: &[(usize, usize)]) -> bool {
        let commute = |a: usize, b: usize| a == b || pairs.contains(&(a.min(b), a.max(b)));
        let mut acc = NcPoly::zero();
        for (w, c) in &self.terms {
            acc.add_term(trace_normal_form(w, &commute), c.clone());
        }
        acc.is_zero()
    }

    /// The print tree: a signed sum of `coefficient*word` terms in the
    /// order of [`NcPoly::terms`].
    pub fn to_node<S: AsRef<str>>(&self, names: &[S]) -> Node {
        Node::Terms(
            self.terms()
                .into_iter()
                .map(|(w, c)| {
                    let word = word_node(w, names);
                    (
                        c.is_negative(),
                        Node::product(vec![Node::Num(c.abs()), word]),
                    )
                })
                .collect(),
        )
    }

    /// Prints words with spaces between the factors, e.g. `k4 k1 - k2 k3`,
    /// runs of one symbol as powers (`k4^2`).
    pub fn to_string_with<S: AsRef<str>>(&self, names: &[S]) -> String {
        print(&self.to_node(names), PrintOptions::TEXT)
    }

    /// LaTeX form, e.g. `k_{4} k_{1} - k_{2} k_{3}`.
    pub fn to_latex_with<S: AsRef<str>>(&self, names: &[S]) -> String {
        print(&self.to_node(names), PrintOptions::LATEX)
    }

    /// The language's syntax, e.g. `k4*k1 - k2*k3` (parses back).
    pub fn to_lmx_with<S: AsRef<str>>(&self, names: &[S]) -> String {
        print(&self.to_node(names), PrintOptions::LMX)
    }
}

/// Compares words by their exponent vectors as [`MPoly`] orders monomials
/// (lexicographic, symbol 0 most significant).
fn cmp_exponents(a: &Word, b: &Word) -> std::cmp::Ordering {
    let n = a.iter().chain(b).max().map_or(0, |m| m + 1);
    let count = |w: &Word| {
        let mut e = vec![0u32; n];
        for &s in w {
            e[s] += 1;
        }
        e
    };
    count(a).cmp(&count(b))
}

fn runs(w: &Word) -> Vec<(usize, usize)> {
    let mut out: Vec<(usize, usize)> = Vec::new();
    for &s in w {
        match out.last_mut() {
            Some((t, k)) if *t == s => *k += 1,
            _ => out.push((s, 1)),
        }
    }
    out
}

fn name_of<S: AsRef<str>>(names: &[S], s: usize) -> String {
    names
        .get(s)
        .map(|n| n.as_ref().to_string())
        .unwrap_or_else(|| format!("s{s}"))
}

/// The print tree of a word: runs of one symbol as powers (`k4^2 k3`).
pub fn word_node<S: AsRef<str>>(w: &Word, names: &[S]) -> Node {
    let mut fs: Vec<Node> = runs(w)
        .into_iter()
        .map(|(s, k)| Node::pow_i(Node::Sym(name_of(names, s)), k as i64))
        .collect();
    match fs.len() {
        0 => Node::Num(Q::one()),
        1 => fs.remove(0),
        _ => Node::Word(fs),
    }
}

/// A word as text: `k4 k1`, `k4^2 k3`.
pub fn word_text<S: AsRef<str>>(w: &Word, names: &[S]) -> String {
    if w.is_empty() {
        return String::new();
    }
    print(&word_node(w, names), PrintOptions::TEXT)
}

/// The lexicographically least word equivalent to `w` when the pairs for
/// which `commute` holds may be swapped (Anisimov–Knuth normal form): take
/// repeatedly the least letter that can be moved to the front.
pub fn trace_normal_form(w: &Word, commute: &dyn Fn(usize, usize) -> bool) -> Word {
    let mut rest = w.clone();
    let mut out = Vec::with_capacity(w.len());
    while !rest.is_empty() {
        // A position can move to the front if its letter commutes with
        // every letter before it (and differs from them: equal letters
        // keep their order, which changes nothing).
        let mut best: Option<usize> = None;
        for (i, &s) in rest.iter().enumerate() {
            if rest[..i].iter().all(|&p| p != s && commute(p, s))
                && best.is_none_or(|b| s < rest[b])
            {
                best = Some(i);
            }
        }
        let i = best.unwrap_or(0);
        out.push(rest.remove(i));
    }
    out
}

impl std::ops::Add for &NcPoly {
    type Output = NcPoly;
    fn add(self, rhs: &NcPoly) -> NcPoly {
        let mut out = self.clone();
        for (w, c) in &rhs.terms {
            out.add_term(w.clone(), c.clone());
        }
        out
    }
}

impl std::ops::Sub for &NcPoly {
    type Output = NcPoly;
    fn sub(self, rhs: &NcPoly) -> NcPoly {
        let mut out = self.clone();
        for (w, c) in &rhs.terms {
            out.add_term(w.clone(), -c);
        }
        out
    }
}

impl std::ops::Mul for &NcPoly {
    type Output = NcPoly;
    fn mul(self, rhs: &NcPoly) -> NcPoly {
        let mut out = NcPoly::zero();
        for (wa, ca) in &self.terms {
            for (wb, cb) in &rhs.terms {
                let mut w = wa.clone();
                w.extend_from_slice(wb);
                out.add_term(w, ca * cb);
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::rational::qi;

    const N: [&str; 4] = ["k1", "k2", "k3", "k4"];

    fn k(i: usize) -> NcPoly {
        NcPoly::var(i - 1)
    }

    #[test]
    fn products_keep_their_order() {
        let a = &k(4) * &k(1);
        let b = &k(1) * &k(4);
        assert_ne!(a, b);
        assert_eq!(a.commutative_image(4), b.commutative_image(4));
        assert_eq!(a.to_string_with(&N), "k4 k1");
        let sq = &(&k(4) * &k(4)) * &k(3);
        assert_eq!(sq.to_string_with(&N), "k4^2 k3");
        assert_eq!(sq.to_latex_with(&N), "k_{4}^{2} k_{3}");
    }

    #[test]
    fn from_mpoly_uses_table_order_and_prints_like_mpoly() {
        let m = MPoly::var(0, 4) * MPoly::var(3, 4) - MPoly::var(1, 4) * MPoly::var(2, 4);
        let p = NcPoly::from_mpoly(&m);
        assert_eq!(p.to_string_with(&N), "k1 k4 - k2 k3");
        assert_eq!(p.commutative_image(4), m);
        let two = NcPoly::constant(qi(2));
        assert_eq!((&two * &k(2)).to_string_with(&N), "2*k2");
        assert_eq!(NcPoly::zero().to_string_with(&N), "0");
    }

    #[test]
    fn the_seed_commutator_needs_exactly_k2_k4() {
        // k4 k2 - k2 k4: the q-coefficient after multiplying by (k4, -k2).
        let r = &(&k(4) * &k(2)) - &(&k(2) * &k(4));
        assert_eq!(r.needed_commutations(), vec![(1, 3)]);
        assert!(r.vanishes_if_commuting(&[(1, 3)]));
        assert!(!r.vanishes_if_commuting(&[(0, 3)]));
    }

    #[test]
    fn commuting_pairs_are_found_in_longer_words() {
        // a b c - a c b needs (b, c) only; c a b - a b c needs (a, c) and (b, c).
        let (a, b, c) = (k(1), k(2), k(3));
        let r = &(&(&a * &b) * &c) - &(&(&a * &c) * &b);
        assert_eq!(r.needed_commutations(), vec![(1, 2)]);
        assert!(r.vanishes_if_commuting(&[(1, 2)]));
        let s = &(&(&c * &a) * &b) - &(&(&a * &b) * &c);
        assert_eq!(s.needed_commutations(), vec![(0, 2), (1, 2)]);
        assert!(s.vanishes_if_commuting(&[(0, 2), (1, 2)]));
        assert!(!s.vanishes_if_commuting(&[(0, 2)]));
    }

    #[test]
    fn trace_normal_form_moves_letters_past_commuting_blocks() {
        // b c a with a commuting with b and c: normal form a b c.
        let comm = |x: usize, y: usize| x == 0 || y == 0;
        assert_eq!(trace_normal_form(&vec![1, 2, 0], &comm), vec![0, 1, 2]);
        // Nothing commutes: unchanged.
        let none = |_: usize, _: usize| false;
        assert_eq!(trace_normal_form(&vec![2, 1, 0], &none), vec![2, 1, 0]);
    }
}
