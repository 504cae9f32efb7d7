//! Expansion of operator words into iterated integrals with composed
//! kernels, from the operator table: `k4 k1 p` with `k4 = -∫_x^1 x/√(t²-x²)`
//! and `k1 = ∫_x^1 t/√(t²-x²)` becomes
//! `- ∫_x^1 (x/sqrt(t^2 - x^2)) ∫_t^1 (s/sqrt(s^2 - t^2)) p(s) ds dt`.
//! Each application of an integral operator introduces the next variable
//! (x, t, s, u, v, w, …); constant factors are pulled out of the kernels
//! into the term's coefficient. This module owns the expansion and its text
//! and LaTeX forms; it must not evaluate anything numerically and must not
//! do the elimination itself.

use crate::algebra::ncpoly::{Word, word_text};
use crate::algebra::rational::{Q, fmt_q, latex_q};
use crate::system::{Expr, Limit, Program, Term};
use num_traits::{One, Signed, Zero};

/// The most terms an expansion may produce before it is refused.
pub const MAX_TERMS: usize = 256;

/// The name of the variable at nesting depth `k` (0 is the output variable).
pub fn var_name(k: usize) -> String {
    const NAMES: [&str; 6] = ["x", "t", "s", "u", "v", "w"];
    NAMES
        .get(k)
        .map(|s| s.to_string())
        .unwrap_or_else(|| format!("t{k}"))
}

/// A limit of one integral: a number or an enclosing variable.
#[derive(Clone, Debug, PartialEq)]
pub enum Bound {
    /// A constant.
    Const(Q),
    /// The variable at this depth.
    Var(usize),
}

/// One layer of an iterated integral, outermost first.
#[derive(Clone, Debug, PartialEq)]
pub enum Layer {
    /// `∫_lower^upper kernel(outer, inner) … d inner`.
    Integral {
        /// Lower limit.
        lower: Bound,
        /// Upper limit.
        upper: Bound,
        /// The kernel without its constant factor (`None`: one).
        kernel: Option<Expr>,
        /// Depth of the variable the kernel's `x` stands for.
        outer: usize,
        /// Depth of the integration variable.
        inner: usize,
        /// A Cauchy principal value (`pv int`).
        pv: bool,
    },
    /// Multiplication by a function of the variable at depth `var`.
    Multiply {
        /// The function (its `x` is the variable at depth `var`).
        factor: Expr,
        /// Depth.
        var: usize,
    },
}

/// What the innermost layer acts on.
#[derive(Clone, Debug, PartialEq)]
pub enum Argument {
    /// The unknown function with this name.
    Unknown(String),
    /// A right side (a function of x; constants are folded into the
    /// coefficient and leave `None`).
    Value(Option<Expr>),
}

/// One term: `coeff · layers … argument(var)`.
#[derive(Clone, Debug, PartialEq)]
pub struct ExpandedTerm {
    /// The constant factor.
    pub coeff: Q,
    /// The layers, outermost first.
    pub layers: Vec<Layer>,
    /// The argument.
    pub argument: Argument,
    /// Depth of the argument's variable.
    pub depth: usize,
    /// The operator word this term comes from, as text (`k4 k1`).
    pub source: String,
}

/// Why a word could not be expanded.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ExpandError {
    /// A symbol has no operator definition (declared with `var`).
    #[error("`{0}` has no operator definition, so it cannot be written as an integral")]
    Undefined(String),
    /// The expansion would be too long to be useful.
    #[error("the expansion would have more than {MAX_TERMS} terms")]
    TooManyTerms,
    /// A right side uses an unknown scalar, which an iterated integral
    /// cannot show before `solve` fixes it.
    #[error("the right side `{0}` uses an unknown scalar; `solve` fixes it with the conditions")]
    ScalarRhs(String),
}

/// Splits an expression into a rational factor and the rest (`None` for 1):
/// `-x/sqrt(t^2 - x^2)` → `(-1, x/sqrt(t^2 - x^2))`, `1/3*t` → `(1/3, t)`.
pub fn peel(e: &Expr) -> (Q, Option<Expr>) {
    match e {
        Expr::Const(c) => (c.clone(), None),
        Expr::Neg(a) => {
            let (c, r) = peel(a);
            (-c, r)
        }
        Expr::Mul(a, b) => {
            let (ca, ra) = peel(a);
            let (cb, rb) = peel(b);
            let rest = match (ra, rb) {
                (None, r) | (r, None) => r,
                (Some(x), Some(y)) => Some(Expr::Mul(Box::new(x), Box::new(y))),
            };
            (ca * cb, rest)
        }
        Expr::Div(a, b) => {
            let (ca, ra) = peel(a);
            let (cb, rb) = peel(b);
            if cb.is_zero() {
                return (Q::one(), Some(e.clone()));
            }
            let rest = match (ra, rb) {
                (r, None) => r,
                (None, Some(y)) => Some(Expr::Div(Box::new(Expr::Const(Q::one())), Box::new(y))),
                (Some(x), Some(y)) => Some(Expr::Div(Box::new(x), Box::new(y))),
            };
            (ca / cb, rest)
        }
        _ => (Q::one(), Some(e.clone())),
    }
}

struct Partial {
    coeff: Q,
    layers: Vec<Layer>,
    depth: usize,
}

/// Expands `coeff · word` applied to `argument` (an unknown or a right
/// side given as a function of x). The word's first symbol is the
/// outermost operator.
pub fn expand_word(
    program: &Program,
    word: &Word,
    coeff: &Q,
    argument: &Argument,
) -> Result<Vec<ExpandedTerm>, ExpandError> {
    let mut partials = vec![Partial {
        coeff: coeff.clone(),
        layers: Vec::new(),
        depth: 0,
    }];
    for &s in word {
        let name = program
            .symbols
            .get(s)
            .cloned()
            .unwrap_or_else(|| format!("s{s}"));
        let def = program
            .operator(s)
            .ok_or_else(|| ExpandError::Undefined(name.clone()))?;
        let mut next = Vec::new();
        for p in &partials {
            for term in &def.terms {
                let mut q = Partial {
                    coeff: p.coeff.clone(),
                    layers: p.layers.clone(),
                    depth: p.depth,
                };
                match term {
                    Term::Integral {
                        lower,
                        upper,
                        kernel,
                        pv,
                    } => {
                        let (c, k) = peel(kernel);
                        let bound = |l: &Limit| match l {
                            Limit::X => Bound::Var(p.depth),
                            Limit::Const(c) => Bound::Const(c.clone()),
                        };
                        q.coeff *= c;
                        q.layers.push(Layer::Integral {
                            lower: bound(lower),
                            upper: bound(upper),
                            kernel: k,
                            outer: p.depth,
                            inner: p.depth + 1,
                            pv: *pv,
                        });
                        q.depth += 1;
                    }
                    Term::Multiply(m) => {
                        let (c, k) = peel(m);
                        q.coeff *= c;
                        if let Some(f) = k {
                            q.layers.push(Layer::Multiply {
                                factor: f,
                                var: p.depth,
                            });
                        }
                    }
                    Term::Identity => {}
                    Term::Scalar(c) => q.coeff *= c,
                }
                if !q.coeff.is_zero() {
                    next.push(q);
                }
                if next.len() > MAX_TERMS {
                    return Err(ExpandError::TooManyTerms);
                }
            }
        }
        partials = next;
    }
    let source = word_text(word, &program.symbols);
    Ok(partials
        .into_iter()
        .filter_map(|p| {
            let (coeff, argument) = match argument {
                Argument::Value(Some(v)) => {
                    let (c, r) = peel(v);
                    (p.coeff * c, Argument::Value(r))
                }
                a => (p.coeff, a.clone()),
            };
            (!coeff.is_zero()).then(|| ExpandedTerm {
                coeff,
                layers: p.layers,
                argument,
                depth: p.depth,
                source: source.clone(),
            })
        })
        .collect())
}

/// The notation a term is written in: the few primitives in which the
/// text and LaTeX forms differ.
struct Notation {
    integral: fn(&Bound, &Bound) -> String,
    pv: &'static str,
    group: fn(&Expr, &str, &str) -> String,
    differential: fn(&str) -> String,
    coeff: fn(&Q) -> String,
}

const TEXT: Notation = Notation {
    integral: |lo, hi| format!("∫_{}^{}", bound_text(lo), bound_text(hi)),
    pv: "PV ",
    group: group_text,
    differential: |v| format!(" d{v}"),
    coeff: fmt_q,
};

const LATEX: Notation = Notation {
    integral: |lo, hi| format!("\\int_{{{}}}^{{{}}}", bound_latex(lo), bound_latex(hi)),
    pv: "\\mathrm{PV}\\!",
    group: group_latex,
    differential: |v| format!("\\,d{v}"),
    coeff: latex_q,
};

impl ExpandedTerm {
    /// The term without its sign, e.g.
    /// `1/9 ∫_0^1 ∫_0^t (s/sqrt(t^2 - s^2)) p(s) ds dt`.
    pub fn body_text(&self) -> String {
        self.body(&TEXT)
    }

    /// The term without its sign in LaTeX.
    pub fn body_latex(&self) -> String {
        self.body(&LATEX)
    }

    fn body(&self, n: &Notation) -> String {
        let mut parts: Vec<String> = Vec::new();
        let a = self.coeff.abs();
        let mut diffs = Vec::new();
        for l in &self.layers {
            match l {
                Layer::Integral {
                    lower,
                    upper,
                    kernel,
                    outer,
                    inner,
                    pv,
                } => {
                    let pv = if *pv { n.pv } else { "" };
                    parts.push(format!("{pv}{}", (n.integral)(lower, upper)));
                    if let Some(k) = kernel {
                        parts.push((n.group)(k, &var_name(*outer), &var_name(*inner)));
                    }
                    diffs.push((n.differential)(&var_name(*inner)));
                }
                Layer::Multiply { factor, var } => {
                    parts.push((n.group)(factor, &var_name(*var), "?"));
                }
            }
        }
        let v = var_name(self.depth);
        match &self.argument {
            Argument::Unknown(u) => parts.push(format!("{u}({v})")),
            Argument::Value(Some(e)) => parts.push((n.group)(e, &v, "?")),
            Argument::Value(None) => {}
        }
        diffs.reverse();
        let mut body = parts.join(" ");
        body.push_str(&diffs.concat());
        match (body.is_empty(), a.is_one()) {
            (true, _) => (n.coeff)(&a),
            (false, true) => body,
            (false, false) => format!("{} {body}", (n.coeff)(&a)),
        }
    }
}

fn bound_text(b: &Bound) -> String {
    match b {
        Bound::Var(k) => var_name(*k),
        Bound::Const(c) => {
            let s = fmt_q(c);
            if s.len() > 1 { format!("({s})") } else { s }
        }
    }
}

fn bound_latex(b: &Bound) -> String {
    match b {
        Bound::Var(k) => var_name(*k),
        Bound::Const(c) => latex_q(c),
    }
}

fn group_text(e: &Expr, x: &str, t: &str) -> String {
    let s = e.renamed(x, t).to_string();
    if e.prec() >= 5 { s } else { format!("({s})") }
}

fn group_latex(e: &Expr, x: &str, t: &str) -> String {
    let s = e.to_latex_vars(x, t);
    if e.prec() >= 2 {
        s
    } else {
        format!("\\left({s}\\right)")
    }
}

/// A signed sum of terms as one line of text (`- a + 1/9 b - …`).
pub fn sum_text(terms: &[ExpandedTerm]) -> String {
    signed_join(terms, ExpandedTerm::body_text)
}

/// A signed sum of terms in LaTeX.
pub fn sum_latex(terms: &[ExpandedTerm]) -> String {
    signed_join(terms, ExpandedTerm::body_latex)
}

fn signed_join(terms: &[ExpandedTerm], body: fn(&ExpandedTerm) -> String) -> String {
    if terms.is_empty() {
        return "0".into();
    }
    let mut out = String::new();
    for (i, t) in terms.iter().enumerate() {
        out.push_str(match (i, t.coeff.is_negative()) {
            (0, true) => "-",
            (0, false) => "",
            (_, true) => " - ",
            (_, false) => " + ",
        });
        out.push_str(&body(t));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::rational::q;

    fn program(src: &str) -> Program {
        crate::lang::parse_program(src, "t.lmx").expect("valid")
    }

    const SEED: &str = "param gamma = 1/3\n\
        operator k1 = int(x..1) t/sqrt(t^2 - x^2) dt\n\
        operator k2 = -gamma*int(0..1) dt + gamma*int(0..x) x/sqrt(x^2 - t^2) dt\n\
        operator k3 = gamma*int(0..x) t/sqrt(x^2 - t^2) dt\n\
        operator k4 = -int(x..1) x/sqrt(t^2 - x^2) dt\n\
        unknown p, q\n\
        equation k1 p + k2 q = 1\n\
        equation k3 p + k4 q = 0\n";

    #[test]
    fn composed_kernels_of_the_seed() {
        let p = program(SEED);
        let u = Argument::Unknown("p".into());
        let t41 = expand_word(&p, &vec![3, 0], &Q::one(), &u).unwrap();
        assert_eq!(
            sum_text(&t41),
            "-∫_x^1 (x/sqrt(t^2 - x^2)) ∫_t^1 (s/sqrt(s^2 - t^2)) p(s) ds dt"
        );
        let t23 = expand_word(&p, &vec![1, 2], &-Q::one(), &u).unwrap();
        assert_eq!(
            sum_text(&t23),
            "1/9 ∫_0^1 ∫_0^t (s/sqrt(t^2 - s^2)) p(s) ds dt - 1/9 ∫_0^x (x/sqrt(x^2 - t^2)) ∫_0^t (s/sqrt(t^2 - s^2)) p(s) ds dt"
        );
        assert_eq!(
            sum_latex(&t41),
            "-\\int_{x}^{1} \\frac{x}{\\sqrt{t^{2} - x^{2}}} \\int_{t}^{1} \\frac{s}{\\sqrt{s^{2} - t^{2}}} p(s)\\,ds\\,dt"
        );
    }

    #[test]
    fn right_sides_fold_constants_and_drop_zero() {
        let p = program(SEED);
        let one = Argument::Value(Some(Expr::Const(Q::one())));
        let zero = Argument::Value(Some(Expr::Const(Q::zero())));
        let r = expand_word(&p, &vec![3], &Q::one(), &one).unwrap();
        assert_eq!(sum_text(&r), "-∫_x^1 (x/sqrt(t^2 - x^2)) dt");
        assert!(
            expand_word(&p, &vec![1], &-Q::one(), &zero)
                .unwrap()
                .is_empty()
        );
        let x2 = Argument::Value(Some(Expr::Mul(
            Box::new(Expr::Const(q(3, 2))),
            Box::new(Expr::X),
        )));
        let r = expand_word(&p, &vec![2], &Q::one(), &x2).unwrap();
        assert_eq!(sum_text(&r), "1/2 ∫_0^x (t/sqrt(x^2 - t^2)) t dt");
    }

    #[test]
    fn undefined_symbols_are_refused() {
        let p = program("var a\nunknown u\nequation a u = 1\n");
        let e = expand_word(&p, &vec![0], &Q::one(), &Argument::Unknown("u".into()));
        assert_eq!(e, Err(ExpandError::Undefined("a".into())));
    }

    #[test]
    fn peeling_constants() {
        let e = Expr::Div(
            Box::new(Expr::Neg(Box::new(Expr::Const(q(2, 1))))),
            Box::new(Expr::Mul(Box::new(Expr::Const(q(3, 1))), Box::new(Expr::X))),
        );
        let (c, r) = peel(&e);
        assert_eq!(c, q(-2, 3));
        assert_eq!(r.map(|r| r.to_string()), Some("1/x".to_string()));
    }
}
