//! The one printer of every formula lambdamat shows: a small print tree
//! ([`Node`]) that each ring builds from its elements, and one function
//! ([`print()`]) that writes the tree as plain text, LaTeX or the language's
//! own syntax ([`Format`]). Parentheses and signs are decided here, on the
//! tree, from binding strengths that follow the language's Pratt parser
//! (`^` tightest and right-associative, then unary minus, then `*` `/`,
//! then `+` `-`), never by looking at printed strings; so a printed formula
//! reads back as the value it stands for. This module owns the tree and the
//! layout rules only; it must not know rings, names tables or the parser.
//!
//! ```
//! use lambdamat::algebra::print::{Node, PrintOptions, print};
//! use lambdamat::algebra::rational::qi;
//! // k4^3 - (k1 + 1): the negated constant coefficient keeps its parentheses
//! let k1_plus_1 = Node::Terms(vec![(false, Node::sym("k1")), (false, Node::Num(qi(1)))]);
//! let f = Node::Terms(vec![
//!     (false, Node::Pow(Box::new(Node::sym("k4")), Box::new(Node::Num(qi(3))))),
//!     (true, k1_plus_1),
//! ]);
//! assert_eq!(print(&f, PrintOptions::TEXT), "k4^3 - (k1 + 1)");
//! assert_eq!(print(&f, PrintOptions::LATEX), "k_{4}^{3} - \\left(k_{1} + 1\\right)");
//! ```

use super::rational::Q;
use num_traits::{One, Signed};

/// The notation a tree is written in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Format {
    /// Plain text for people: operator words by juxtaposition (`k4 k1`),
    /// inverses as `k4^-1`; commutative formulas as in the language.
    #[default]
    Text,
    /// LaTeX (`\frac`, `k_{1}`, `\left( … \right)`).
    Latex,
    /// The language's own syntax (`grammar/lambdamat.pest`): every product
    /// written with `*`, negative exponents parenthesised, so the text
    /// parses back with lambdamat's parser to the same value.
    Lmx,
}

/// How to print (the format; room for more switches).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct PrintOptions {
    /// The notation.
    pub format: Format,
}

impl PrintOptions {
    /// Plain text.
    pub const TEXT: PrintOptions = PrintOptions {
        format: Format::Text,
    };
    /// LaTeX.
    pub const LATEX: PrintOptions = PrintOptions {
        format: Format::Latex,
    };
    /// The language's syntax.
    pub const LMX: PrintOptions = PrintOptions {
        format: Format::Lmx,
    };
}

/// A formula as a tree. Ring printers build it; [`print()`] lays it out.
#[derive(Clone, Debug, PartialEq)]
pub enum Node {
    /// An exact rational (any sign).
    Num(Q),
    /// A name (a symbol, an unknown, `x`, `pi`); LaTeX renders it with
    /// [`latex_name`].
    Sym(String),
    /// Unary minus.
    Neg(Box<Node>),
    /// A signed sum `± t1 ± t2 …`: each term is `(negative, magnitude)`;
    /// empty is `0`. Ring elements print through this node.
    Terms(Vec<(bool, Node)>),
    /// Binary `a + b` (kernel expressions keep their own tree).
    Add(Box<Node>, Box<Node>),
    /// Binary `a - b`.
    Sub(Box<Node>, Box<Node>),
    /// A commutative product: `a*b` (text, language), `a b` (LaTeX).
    Mul(Vec<Node>),
    /// An ordered product of operators: `k4 k1` (text, LaTeX), `k4*k1`
    /// (language).
    Word(Vec<Node>),
    /// `a/b`, `\frac{a}{b}`.
    Div(Box<Node>, Box<Node>),
    /// `a^b`.
    Pow(Box<Node>, Box<Node>),
    /// `f(a)` for a named function (`sqrt`, `ln`, `abs`, `exp`, …).
    Call(String, Box<Node>),
    /// An operator applied to what follows it: `(k1 - k2) p`.
    Apply(Box<Node>, Box<Node>),
    /// `a = b`.
    Equation(Box<Node>, Box<Node>),
    /// Parentheses chosen by the tree's builder for readability
    /// (`(1/k1)*k4^2`); LaTeX leaves a `\frac` bare.
    Group(Box<Node>),
}

// Binding strengths: higher binds tighter.
const EQ: u8 = 0;
const SUM: u8 = 1;
const PRODUCT: u8 = 2;
const UNARY: u8 = 3;
const POWER: u8 = 4;
const ATOM: u8 = 5;

impl Node {
    /// A name.
    pub fn sym(name: impl Into<String>) -> Node {
        Node::Sym(name.into())
    }

    /// `base^e` for a machine integer exponent (`base` itself for 1).
    pub fn pow_i(base: Node, e: i64) -> Node {
        if e == 1 {
            base
        } else {
            Node::Pow(
                Box::new(base),
                Box::new(Node::Num(Q::from_integer(e.into()))),
            )
        }
    }

    /// A product of factors, flattening nested products and dropping
    /// factors equal to one; a single factor is returned as it is.
    pub fn product(factors: Vec<Node>) -> Node {
        let mut out = Vec::new();
        for f in factors {
            match f {
                Node::Mul(fs) => out.extend(fs),
                Node::Num(q) if q.is_one() => {}
                other => out.push(other),
            }
        }
        match out.len() {
            0 => Node::Num(Q::one()),
            1 => out.pop().unwrap_or(Node::Num(Q::one())),
            _ => Node::Mul(out),
        }
    }

    /// Splits off a leading minus: `(true, m)` when the node equals `-m`
    /// and `m` prints without a leading minus; otherwise `(false, self)`.
    /// A sum whose first term is negative is negated as a whole, so
    /// `-k1 - 1` becomes `-(k1 + 1)`.
    pub fn split_sign(self) -> (bool, Node) {
        match self {
            Node::Num(q) if q.is_negative() => (true, Node::Num(-q)),
            Node::Neg(a) => (true, *a),
            Node::Terms(ts) if ts.first().is_some_and(|t| t.0) => (
                true,
                Node::Terms(ts.into_iter().map(|(n, m)| (!n, m)).collect()),
            ),
            Node::Mul(mut fs) if fs.first().is_some_and(Node::starts_with_minus) => {
                let first = fs.remove(0);
                let (_, m) = first.split_sign();
                fs.insert(0, m);
                (true, Node::product(fs))
            }
            Node::Div(a, b) if a.starts_with_minus() => {
                let (_, m) = a.split_sign();
                (true, Node::Div(Box::new(m), b))
            }
            other => (false, other),
        }
    }

    /// Whether the printed form begins with a minus sign.
    pub fn starts_with_minus(&self) -> bool {
        match self {
            Node::Num(q) => q.is_negative(),
            Node::Neg(_) => true,
            Node::Terms(ts) => ts.first().is_some_and(|t| t.0 || t.1.starts_with_minus()),
            // A first factor that binds looser than a product is printed in
            // parentheses, so its minus is not in front.
            Node::Mul(fs) | Node::Word(fs) => fs
                .first()
                .is_some_and(|a| a.prec(Format::Text) >= PRODUCT && a.starts_with_minus()),
            Node::Div(a, _) | Node::Apply(a, _) => {
                a.prec(Format::Text) >= PRODUCT && a.starts_with_minus()
            }
            Node::Add(a, _) | Node::Sub(a, _) => a.starts_with_minus(),
            _ => false,
        }
    }

    fn prec(&self, f: Format) -> u8 {
        match self {
            Node::Num(q) if q.is_negative() => PRODUCT,
            Node::Num(q) if !q.is_integer() && f != Format::Latex => PRODUCT,
            Node::Num(_) | Node::Sym(_) | Node::Call(..) | Node::Group(_) => ATOM,
            Node::Neg(_) => UNARY,
            Node::Terms(ts) => match ts.as_slice() {
                [] => ATOM,
                [(true, _)] => UNARY,
                [(false, m)] => m.prec(f),
                _ => SUM,
            },
            Node::Add(..) | Node::Sub(..) => SUM,
            Node::Mul(fs) | Node::Word(fs) => match fs.as_slice() {
                [one] => one.prec(f),
                _ => PRODUCT,
            },
            Node::Div(..) if f == Format::Latex => ATOM,
            Node::Div(..) | Node::Apply(..) => PRODUCT,
            Node::Pow(..) => POWER,
            Node::Equation(..) => EQ,
        }
    }
}

/// Writes `node` in the notation of `opts`.
pub fn print(node: &Node, opts: PrintOptions) -> String {
    let mut p = Printer {
        out: String::new(),
        f: opts.format,
    };
    p.node(node);
    p.out
}

struct Printer {
    out: String,
    f: Format,
}

impl Printer {
    fn open(&mut self) {
        self.out.push_str(if self.f == Format::Latex {
            "\\left("
        } else {
            "("
        });
    }

    fn close(&mut self) {
        self.out.push_str(if self.f == Format::Latex {
            "\\right)"
        } else {
            ")"
        });
    }

    /// `n`, in parentheses when it binds looser than `min` (or, with
    /// `no_minus`, when it starts with a minus sign).
    fn child(&mut self, n: &Node, min: u8, no_minus: bool) {
        if n.prec(self.f) < min || (no_minus && n.starts_with_minus()) {
            self.open();
            self.node(n);
            self.close();
        } else {
            self.node(n);
        }
    }

    fn num(&mut self, q: &Q) {
        let a = q.abs();
        if q.is_negative() {
            self.out.push('-');
        }
        if a.is_integer() {
            self.out.push_str(&a.numer().to_string());
        } else if self.f == Format::Latex {
            self.out
                .push_str(&format!("\\frac{{{}}}{{{}}}", a.numer(), a.denom()));
        } else {
            self.out.push_str(&format!("{}/{}", a.numer(), a.denom()));
        }
    }

    fn factors(&mut self, fs: &[Node], sep: &str) {
        for (i, x) in fs.iter().enumerate() {
            if i == 0 {
                self.child(x, PRODUCT, false);
                continue;
            }
            if self.f == Format::Latex && matches!(x, Node::Num(_)) {
                self.out.push_str(" \\cdot ");
            } else {
                self.out.push_str(sep);
            }
            // A right operand of `*` must bind tighter than `*`; an operator
            // word inside a product is a product of the same kind.
            let min = if matches!(x, Node::Word(_)) {
                PRODUCT
            } else {
                UNARY
            };
            self.child(x, min, true);
        }
    }

    fn node(&mut self, n: &Node) {
        let f = self.f;
        let latex = f == Format::Latex;
        match n {
            Node::Num(q) => self.num(q),
            Node::Sym(s) => {
                if latex {
                    self.out.push_str(&latex_name(s));
                } else {
                    self.out.push_str(s);
                }
            }
            Node::Neg(a) => {
                self.out.push('-');
                self.child(a, if latex { PRODUCT } else { POWER }, true);
            }
            Node::Terms(ts) => {
                if ts.is_empty() {
                    self.out.push('0');
                }
                for (i, (neg, m)) in ts.iter().enumerate() {
                    self.out.push_str(match (i, neg) {
                        (0, true) => "-",
                        (0, false) => "",
                        (_, true) => " - ",
                        (_, false) => " + ",
                    });
                    let min = if i == 0 && !neg { SUM } else { PRODUCT };
                    self.child(m, min, i > 0 || *neg);
                }
            }
            Node::Add(a, b) | Node::Sub(a, b) => {
                self.child(a, SUM, false);
                self.out.push_str(if matches!(n, Node::Add(..)) {
                    " + "
                } else {
                    " - "
                });
                self.child(b, PRODUCT, false);
            }
            Node::Mul(fs) => self.factors(fs, if latex { " " } else { "*" }),
            Node::Word(fs) => self.factors(fs, if f == Format::Lmx { "*" } else { " " }),
            Node::Div(a, b) => {
                if latex {
                    self.out.push_str("\\frac{");
                    self.node(a);
                    self.out.push_str("}{");
                    self.node(b);
                    self.out.push('}');
                } else {
                    self.child(a, PRODUCT, false);
                    self.out.push('/');
                    self.child(b, POWER, true);
                }
            }
            Node::Pow(a, b) => {
                let fraction = match &**a {
                    Node::Div(..) => true,
                    Node::Num(q) => !q.is_integer(),
                    _ => false,
                };
                let bare_base = a.prec(f) >= ATOM && !(latex && fraction);
                if bare_base && !a.starts_with_minus() {
                    self.node(a);
                } else {
                    self.open();
                    self.node(a);
                    self.close();
                }
                if latex {
                    self.out.push_str("^{");
                    self.node(b);
                    self.out.push('}');
                } else {
                    self.out.push('^');
                    let short = f == Format::Text
                        && matches!(&**b, Node::Num(q) if q.is_integer() && q.is_negative());
                    if short {
                        self.node(b);
                    } else {
                        self.child(b, ATOM, true);
                    }
                }
            }
            Node::Call(name, a) => match (latex, name.as_str()) {
                (true, "sqrt") => {
                    self.out.push_str("\\sqrt{");
                    self.node(a);
                    self.out.push('}');
                }
                (true, "abs") => {
                    self.out.push_str("\\left|");
                    self.node(a);
                    self.out.push_str("\\right|");
                }
                (true, "exp") => {
                    self.out.push_str("e^{");
                    self.node(a);
                    self.out.push('}');
                }
                (true, other) => {
                    self.out.push_str(&format!("\\{other}"));
                    self.open();
                    self.node(a);
                    self.close();
                }
                (false, other) => {
                    self.out.push_str(other);
                    self.out.push('(');
                    self.node(a);
                    self.out.push(')');
                }
            },
            Node::Apply(op, arg) => {
                self.child(op, PRODUCT, false);
                self.out.push(' ');
                self.child(arg, ATOM, true);
            }
            Node::Equation(a, b) => {
                self.node(a);
                self.out.push_str(" = ");
                self.node(b);
            }
            Node::Group(a) => {
                if latex && matches!(**a, Node::Div(..)) {
                    self.node(a);
                } else {
                    self.open();
                    self.node(a);
                    self.close();
                }
            }
        }
    }
}

/// LaTeX name of a symbol: `k1` → `k_{1}`, `lambda` → `\lambda`.
pub fn latex_name(name: &str) -> String {
    const GREEK: [&str; 13] = [
        "alpha", "beta", "gamma", "delta", "kappa", "lambda", "mu", "nu", "sigma", "tau", "phi",
        "omega", "pi",
    ];
    let split = name
        .find(|c: char| c.is_ascii_digit())
        .unwrap_or(name.len());
    let (head, digits) = name.split_at(split);
    let head = if GREEK.contains(&head) {
        format!("\\{head}")
    } else {
        head.to_string()
    };
    if digits.is_empty() {
        head
    } else if digits.chars().all(|c| c.is_ascii_digit()) {
        format!("{head}_{{{digits}}}")
    } else {
        format!("\\mathit{{{name}}}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::rational::{q, qi};

    fn s(n: &str) -> Node {
        Node::sym(n)
    }

    fn text(n: &Node) -> String {
        print(n, PrintOptions::TEXT)
    }

    #[test]
    fn sums_fold_signs_and_group_negated_sums() {
        let inner = Node::Terms(vec![(false, s("k1")), (false, Node::Num(qi(1)))]);
        let f = Node::Terms(vec![
            (false, Node::pow_i(s("k4"), 3)),
            (
                false,
                Node::Mul(vec![
                    Node::Group(Box::new(Node::Div(
                        Box::new(Node::Num(qi(1))),
                        Box::new(s("k1")),
                    ))),
                    Node::pow_i(s("k4"), 2),
                ]),
            ),
            (true, inner),
        ]);
        assert_eq!(text(&f), "k4^3 + (1/k1)*k4^2 - (k1 + 1)");
        assert_eq!(
            print(&f, PrintOptions::LATEX),
            "k_{4}^{3} + \\frac{1}{k_{1}} k_{4}^{2} - \\left(k_{1} + 1\\right)"
        );
        assert_eq!(text(&Node::Terms(vec![])), "0");
    }

    #[test]
    fn products_and_quotients_parenthesise_on_the_tree() {
        let sum = Node::Terms(vec![(false, s("a")), (false, s("b"))]);
        let d = Node::Div(
            Box::new(Node::Num(qi(1))),
            Box::new(Node::Mul(vec![s("a"), s("b")])),
        );
        assert_eq!(text(&d), "1/(a*b)");
        let m = Node::Mul(vec![sum.clone(), Node::Num(q(-1, 2))]);
        assert_eq!(text(&m), "(a + b)*(-1/2)");
        let inv = Node::pow_i(sum.clone(), -1);
        assert_eq!(text(&inv), "(a + b)^-1");
        assert_eq!(print(&inv, PrintOptions::LMX), "(a + b)^(-1)");
        let w = Node::Word(vec![Node::Num(qi(2)), s("k2"), Node::pow_i(s("k4"), -1)]);
        assert_eq!(text(&w), "2 k2 k4^-1");
        assert_eq!(print(&w, PrintOptions::LMX), "2*k2*k4^(-1)");
        let (neg, m) = Node::Terms(vec![(true, s("a")), (false, s("b"))]).split_sign();
        assert!(neg);
        assert_eq!(text(&m), "a - b");
    }
}
