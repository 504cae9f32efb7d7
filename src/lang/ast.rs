//! The spanned abstract syntax tree: what the parser builds and the validator
//! checks. Every node carries the byte [`Span`] of the text it came from so
//! that diagnostics can point at it. This module only defines data; it must
//! not resolve names, do arithmetic or format positions (that is
//! `validate.rs`, `lower.rs` and `diagnostics.rs`).

use num_rational::BigRational;

/// A byte range `start..end` in the source text.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub struct Span {
    /// Byte offset of the first character.
    pub start: usize,
    /// Byte offset one past the last character.
    pub end: usize,
}

impl Span {
    /// The span `start..end`.
    pub fn new(start: usize, end: usize) -> Span {
        Span { start, end }
    }

    /// The smallest span covering both `self` and `other`.
    pub fn to(self, other: Span) -> Span {
        Span::new(self.start.min(other.start), self.end.max(other.end))
    }
}

/// A name as written, with its position.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Ident {
    /// The name.
    pub name: String,
    /// Where it was written.
    pub span: Span,
}

/// A binary arithmetic operator.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinOp {
    /// `+`
    Add,
    /// `-`
    Sub,
    /// `*`
    Mul,
    /// `/`
    Div,
    /// `^`
    Pow,
}

impl BinOp {
    /// The operator as written in source.
    #[cfg(any(test, feature = "internals"))]
    pub fn symbol(self) -> &'static str {
        match self {
            BinOp::Add => "+",
            BinOp::Sub => "-",
            BinOp::Mul => "*",
            BinOp::Div => "/",
            BinOp::Pow => "^",
        }
    }
}

/// The variable an integral runs over, named by its differential.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IntVar {
    /// `dx`
    X,
    /// `dt`
    T,
}

/// The shape of an expression node.
#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    /// A numeric literal, already exact (`0.25` is 1/4).
    Number(BigRational),
    /// A name: a symbol, parameter, unknown, operator, or `x`/`t`.
    Name(Ident),
    /// `pi`
    Pi,
    /// `id`, the identity operator.
    Identity,
    /// Unary minus.
    Neg(Box<Expr>),
    /// A binary operation.
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// `f(arg)`: a built-in function or an unknown evaluated at a point.
    Call(Ident, Box<Expr>),
    /// `int(lower..upper) integrand dvar`; a missing integrand means 1.
    Integral {
        /// Lower limit.
        lower: Box<Expr>,
        /// Upper limit.
        upper: Box<Expr>,
        /// The integrand, `None` for `int(a..b) dt`.
        integrand: Option<Box<Expr>>,
        /// The integration variable.
        var: IntVar,
        /// Where the differential (`dt`/`dx`) was written.
        var_span: Span,
        /// Written `pv int`: a Cauchy principal value.
        pv: bool,
    },
}

/// An expression with its span.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    /// What it is.
    pub kind: ExprKind,
    /// Where it was written (parentheses included).
    pub span: Span,
}

/// The sign in front of a term of an equation's left side.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sign {
    /// `+` (or no sign).
    Plus,
    /// `-`
    Minus,
}

/// One term of an equation's left side: `sign operator-product unknown`.
#[derive(Clone, Debug, PartialEq)]
pub struct LhsTerm {
    /// The sign in front of it.
    pub sign: Sign,
    /// The operator product (or, when `unknown` is `None`, a product whose
    /// last factor must be the unknown, as in `k1*p` or just `p`).
    pub product: Expr,
    /// The unknown written after the product by juxtaposition (`k1 p`).
    pub unknown: Option<Ident>,
    /// The whole term.
    pub span: Span,
}

/// One statement of a file.
#[derive(Clone, Debug, PartialEq)]
pub enum Stmt {
    /// `var a, b`
    Var(Vec<Ident>),
    /// `principal k4`
    Principal(Ident),
    /// `matrix A = [...]`
    Matrix {
        /// The matrix name.
        name: Ident,
        /// Rows of entries.
        rows: Vec<MatrixRow>,
        /// The bracketed literal.
        lit_span: Span,
    },
    /// `smith A`
    Smith(Ident),
    /// `check smith A with U, D, V`
    CheckSmith {
        /// The matrix.
        a: Ident,
        /// The left transform.
        u: Ident,
        /// The claimed diagonal form.
        d: Ident,
        /// The right transform.
        v: Ident,
    },
    /// `param nu = 1/4`
    Param {
        /// The parameter's name.
        name: Ident,
        /// Its value.
        value: Expr,
    },
    /// `unknown p, q` (optionally `on [a, b]`)
    Unknown(Vec<Ident>, Option<Interval>),
    /// `operator k1 = ...`
    Operator {
        /// The operator symbol.
        name: Ident,
        /// Its definition.
        body: Expr,
    },
    /// `equation lhs = rhs`
    Equation {
        /// Signed terms of the left side.
        lhs: Vec<LhsTerm>,
        /// The right side, a function of x.
        rhs: Expr,
        /// `on [a, b)`: where it holds (everywhere when `None`).
        domain: Option<Interval>,
    },
    /// `relation q = mu*p on [c, 1]`
    Relation {
        /// The unknown that is expressed.
        unknown: Ident,
        /// The right side: a constant times another unknown.
        value: Expr,
        /// Where it holds.
        domain: Interval,
    },
    /// `inequality abs(q) <= mu*p on [0, c)`
    Inequality {
        /// The left side.
        lhs: Expr,
        /// `>=` (true) or `<=`.
        ge: bool,
        /// The right side.
        rhs: Expr,
        /// Where it must hold.
        domain: Interval,
    },
    /// `scalar c in (0, 1)` or `scalar c in (0, 1) ~ estimate`
    Scalar {
        /// The scalar's name.
        name: Ident,
        /// The range searched for it.
        range: Interval,
        /// A derived asymptotic estimate of its value (a real expression
        /// of the parameters).
        estimate: Option<Expr>,
    },
    /// `singular p at 1 ~ (1 - x)^(-alpha)` or `singular q at c- ~ B*g(x)`
    Singular {
        /// The unknown.
        unknown: Ident,
        /// The point.
        at: Expr,
        /// `-1` for `at c-`, `1` for `at c+`, `0` when no side is written.
        side: i8,
        /// The behaviour.
        body: Expr,
    },
    /// `condition lhs = rhs`
    Condition {
        /// The left side.
        lhs: Expr,
        /// The right side.
        rhs: Expr,
    },
    /// `solve for p`
    Solve(Ident),
    /// `output P = ...`
    Output {
        /// The output's name.
        name: Ident,
        /// Its definition.
        body: Expr,
    },
}

/// An interval `[a, b)` with open or closed ends.
#[derive(Clone, Debug, PartialEq)]
pub struct Interval {
    /// Left end.
    pub lo: Expr,
    /// Right end.
    pub hi: Expr,
    /// Whether the left end belongs to it (`[`).
    pub lo_closed: bool,
    /// Whether the right end belongs to it (`]`).
    pub hi_closed: bool,
    /// The bracketed text.
    pub span: Span,
}

/// One row of a matrix literal.
#[derive(Clone, Debug, PartialEq)]
pub struct MatrixRow {
    /// The entries.
    pub entries: Vec<Expr>,
    /// The row's text.
    pub span: Span,
}

/// A statement with its span.
#[derive(Clone, Debug, PartialEq)]
pub struct Statement {
    /// What it says.
    pub kind: Stmt,
    /// Where it was written.
    pub span: Span,
}

/// A parsed file.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct File {
    /// The statements in source order.
    pub statements: Vec<Statement>,
}
