//! Real-valued expression trees in the output variable `x` and the
//! integration variable `t`: kernels, multipliers, right sides and output
//! weights. Parameters are already replaced by their exact values and every
//! rational subexpression is folded into one [`Expr::Const`]. This module owns
//! the tree, its evaluation at a point and its print tree (laid out by [`crate::algebra::print`]) in source syntax; it
//! must not parse, and compiling trees to closures is the numerics' job.

use std::fmt;

use crate::algebra::print::{Node, PrintOptions, print};

use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive};

/// A built-in function of one argument.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Func {
    /// Square root.
    Sqrt,
    /// Natural logarithm.
    Ln,
    /// Absolute value.
    Abs,
    /// Exponential.
    Exp,
    /// Sine.
    Sin,
    /// Cosine.
    Cos,
    /// Tangent.
    Tan,
    /// Arcsine, values in [-π/2, π/2].
    Asin,
    /// Arccosine, values in [0, π].
    Acos,
    /// Arctangent, values in (-π/2, π/2).
    Atan,
    /// Arccotangent, values in (0, π) (`acot(0) = π/2`).
    Acot,
    /// Hyperbolic sine.
    Sinh,
    /// Hyperbolic cosine.
    Cosh,
    /// Hyperbolic tangent.
    Tanh,
    /// Euler's Gamma function Γ (poles at 0, −1, −2, …).
    Gamma,
    /// The error function erf.
    Erf,
}

/// Every function, in the order the documentation lists them.
pub const FUNCS: [Func; 16] = [
    Func::Sqrt,
    Func::Ln,
    Func::Abs,
    Func::Exp,
    Func::Sin,
    Func::Cos,
    Func::Tan,
    Func::Asin,
    Func::Acos,
    Func::Atan,
    Func::Acot,
    Func::Sinh,
    Func::Cosh,
    Func::Tanh,
    Func::Gamma,
    Func::Erf,
];

/// Euler's Gamma function (libm's `tgamma`; NaN at the poles 0, −1, −2, …,
/// as for any value outside a function's domain). Generated solvers call it
/// too, so that they compute what `solve` computes.
pub fn gamma(v: f64) -> f64 {
    if v <= 0.0 && v.fract() == 0.0 {
        return f64::NAN;
    }
    libm::tgamma(v)
}

/// The error function (libm's `erf`; generated solvers call it too).
pub fn erf(v: f64) -> f64 {
    libm::erf(v)
}

/// arccot with values in (0, π): `acot(0) = π/2`, `acot(v) = atan(1/v)`
/// for `v > 0` and `π + atan(1/v)` for `v < 0` (the branch that is
/// continuous through 0; used by generated solvers too).
pub fn acot(v: f64) -> f64 {
    if v == 0.0 {
        std::f64::consts::FRAC_PI_2
    } else if v > 0.0 {
        (1.0 / v).atan()
    } else {
        std::f64::consts::PI + (1.0 / v).atan()
    }
}

impl Func {
    /// The function's name in source (and, but for `acot`, `gamma` and
    /// `erf`, the name of the `f64` method that computes it).
    pub fn name(self) -> &'static str {
        match self {
            Func::Sqrt => "sqrt",
            Func::Ln => "ln",
            Func::Abs => "abs",
            Func::Exp => "exp",
            Func::Sin => "sin",
            Func::Cos => "cos",
            Func::Tan => "tan",
            Func::Asin => "asin",
            Func::Acos => "acos",
            Func::Atan => "atan",
            Func::Acot => "acot",
            Func::Sinh => "sinh",
            Func::Cosh => "cosh",
            Func::Tanh => "tanh",
            Func::Gamma => "gamma",
            Func::Erf => "erf",
        }
    }

    /// The function with this source name.
    pub fn from_name(name: &str) -> Option<Func> {
        FUNCS.into_iter().find(|f| f.name() == name)
    }

    /// Whether `f64` has a method of this name that computes it (else
    /// generated code calls the function of this module of that name).
    pub fn is_f64_method(self) -> bool {
        !matches!(self, Func::Acot | Func::Gamma | Func::Erf)
    }

    /// Its value at `v` (IEEE semantics: NaN outside the domain).
    pub fn apply(self, v: f64) -> f64 {
        match self {
            Func::Sqrt => v.sqrt(),
            Func::Ln => v.ln(),
            Func::Abs => v.abs(),
            Func::Exp => v.exp(),
            Func::Sin => v.sin(),
            Func::Cos => v.cos(),
            Func::Tan => v.tan(),
            Func::Asin => v.asin(),
            Func::Acos => v.acos(),
            Func::Atan => v.atan(),
            Func::Acot => acot(v),
            Func::Sinh => v.sinh(),
            Func::Cosh => v.cosh(),
            Func::Tanh => v.tanh(),
            Func::Gamma => gamma(v),
            Func::Erf => erf(v),
        }
    }
}

/// A real expression in `x` and `t`.
#[derive(Clone, Debug, PartialEq)]
pub enum Expr {
    /// An exact rational constant.
    Const(BigRational),
    /// The output variable `x`.
    X,
    /// The integration variable `t`.
    T,
    /// π.
    Pi,
    /// `-a`
    Neg(Box<Expr>),
    /// `a + b`
    Add(Box<Expr>, Box<Expr>),
    /// `a - b`
    Sub(Box<Expr>, Box<Expr>),
    /// `a * b`
    Mul(Box<Expr>, Box<Expr>),
    /// `a / b`
    Div(Box<Expr>, Box<Expr>),
    /// `a ^ b` (real power)
    Pow(Box<Expr>, Box<Expr>),
    /// `f(a)`
    Call(Func, Box<Expr>),
}

impl Expr {
    /// The value at `x`, `t` (IEEE semantics: may be NaN or infinite where
    /// the expression is undefined).
    ///
    /// ```
    /// use lambdamat::system::expr::{Expr, Func};
    /// use num_rational::BigRational;
    /// // t / sqrt(t^2 - x^2)
    /// let two = || Box::new(Expr::Const(BigRational::from_integer(2.into())));
    /// let t2 = Expr::Pow(Box::new(Expr::T), two());
    /// let x2 = Expr::Pow(Box::new(Expr::X), two());
    /// let root = Expr::Call(Func::Sqrt, Box::new(Expr::Sub(Box::new(t2), Box::new(x2))));
    /// let k = Expr::Div(Box::new(Expr::T), Box::new(root));
    /// assert!((k.eval(0.6, 1.0) - 1.25).abs() < 1e-15);
    /// assert_eq!(k.to_string(), "t/sqrt(t^2 - x^2)");
    /// ```
    pub fn eval(&self, x: f64, t: f64) -> f64 {
        match self {
            Expr::Const(q) => q.to_f64().unwrap_or(f64::NAN),
            Expr::X => x,
            Expr::T => t,
            Expr::Pi => std::f64::consts::PI,
            Expr::Neg(a) => -a.eval(x, t),
            Expr::Add(a, b) => a.eval(x, t) + b.eval(x, t),
            Expr::Sub(a, b) => a.eval(x, t) - b.eval(x, t),
            Expr::Mul(a, b) => a.eval(x, t) * b.eval(x, t),
            Expr::Div(a, b) => a.eval(x, t) / b.eval(x, t),
            Expr::Pow(a, b) => pow(a.eval(x, t), b),
            Expr::Call(f, a) => f.apply(a.eval(x, t)),
        }
    }

    /// Whether `x` occurs.
    pub fn uses_x(&self) -> bool {
        self.any(&|e| matches!(e, Expr::X))
    }

    /// Whether `t` occurs.
    pub fn uses_t(&self) -> bool {
        self.any(&|e| matches!(e, Expr::T))
    }

    /// The exact value, if this is a rational constant.
    pub fn as_const(&self) -> Option<&BigRational> {
        match self {
            Expr::Const(q) => Some(q),
            _ => None,
        }
    }

    fn any(&self, p: &dyn Fn(&Expr) -> bool) -> bool {
        if p(self) {
            return true;
        }
        match self {
            Expr::Const(_) | Expr::X | Expr::T | Expr::Pi => false,
            Expr::Neg(a) | Expr::Call(_, a) => a.any(p),
            Expr::Add(a, b)
            | Expr::Sub(a, b)
            | Expr::Mul(a, b)
            | Expr::Div(a, b)
            | Expr::Pow(a, b) => a.any(p) || b.any(p),
        }
    }

    /// Binding strength when printed: higher binds tighter (1 for `+ -`,
    /// 2 for `* /` and fractions, 3 for unary minus, 4 for `^`, 5 for atoms).
    pub fn prec(&self) -> u8 {
        match self {
            Expr::Add(..) | Expr::Sub(..) => 1,
            Expr::Mul(..) | Expr::Div(..) => 2,
            Expr::Neg(..) => 3,
            Expr::Pow(..) => 4,
            Expr::Const(q) if !q.is_integer() || q.is_negative() => 2,
            _ => 5,
        }
    }
}

/// Real power, with integer exponents done exactly by `powi`.
fn pow(base: f64, exp: &Expr) -> f64 {
    if let Expr::Const(q) = exp {
        if q.is_integer()
            && let Some(n) = q.to_integer().to_i32()
        {
            return base.powi(n);
        }
        if let Some(e) = q.to_f64() {
            return base.powf(e);
        }
    }
    base.powf(exp.eval(f64::NAN, f64::NAN))
}

/// `e` printed in source syntax with other names for `x` and `t` (for
/// composed kernels, where the variables are renamed level by level).
pub struct Renamed<'a> {
    e: &'a Expr,
    x: &'a str,
    t: &'a str,
}

impl Expr {
    /// Source-syntax form with `x` printed as `x_name` and `t` as `t_name`.
    ///
    /// ```
    /// use lambdamat::system::expr::Expr;
    /// let e = Expr::Mul(Box::new(Expr::X), Box::new(Expr::T));
    /// assert_eq!(e.renamed("t", "s").to_string(), "t*s");
    /// ```
    pub fn renamed<'a>(&'a self, x_name: &'a str, t_name: &'a str) -> Renamed<'a> {
        Renamed {
            e: self,
            x: x_name,
            t: t_name,
        }
    }

    /// LaTeX form with the given names for `x` and `t`, e.g.
    /// `\frac{x}{\sqrt{t^{2} - x^{2}}}`.
    pub fn to_latex_vars(&self, x: &str, t: &str) -> String {
        print(&self.to_node_vars(x, t), PrintOptions::LATEX)
    }

    /// The print tree, node for node (so the language form parses back to
    /// the same tree), with the given names for `x` and `t`.
    pub fn to_node_vars(&self, x: &str, t: &str) -> Node {
        let b = |e: &Expr| Box::new(e.to_node_vars(x, t));
        match self {
            Expr::Const(q) => Node::Num(q.clone()),
            Expr::X => Node::sym(x),
            Expr::T => Node::sym(t),
            Expr::Pi => Node::sym("pi"),
            Expr::Neg(a) => Node::Neg(b(a)),
            Expr::Add(a0, a1) => Node::Add(b(a0), b(a1)),
            Expr::Sub(a0, a1) => Node::Sub(b(a0), b(a1)),
            Expr::Mul(a0, a1) => Node::Mul(vec![*b(a0), *b(a1)]),
            Expr::Div(a0, a1) => Node::Div(b(a0), b(a1)),
            Expr::Pow(a0, a1) => Node::Pow(b(a0), b(a1)),
            Expr::Call(func, a) => Node::Call(func.name().to_string(), b(a)),
        }
    }
}

/// Prints in source syntax, so that parsing the text gives the same tree:
/// `t/sqrt(t^2 - x^2)`, `-1/2*x`, `(1 - x)^(-1/2)`.
impl fmt::Display for Expr {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&print(&self.to_node_vars("x", "t"), PrintOptions::LMX))
    }
}

impl fmt::Display for Renamed<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&print(
            &self.e.to_node_vars(self.x, self.t),
            PrintOptions::LMX,
        ))
    }
}

#[cfg(test)]
mod rename_tests {
    use super::*;

    fn c(n: i64, d: i64) -> Box<Expr> {
        Box::new(Expr::Const(BigRational::new(n.into(), d.into())))
    }

    #[test]
    fn renamed_and_latex_forms() {
        // -x/sqrt(t^2 - x^2)
        let root = Expr::Call(
            Func::Sqrt,
            Box::new(Expr::Sub(
                Box::new(Expr::Pow(Box::new(Expr::T), c(2, 1))),
                Box::new(Expr::Pow(Box::new(Expr::X), c(2, 1))),
            )),
        );
        let k = Expr::Neg(Box::new(Expr::Div(Box::new(Expr::X), Box::new(root))));
        assert_eq!(k.to_string(), "-(x/sqrt(t^2 - x^2))");
        assert_eq!(k.renamed("t", "s").to_string(), "-(t/sqrt(s^2 - t^2))");
        assert_eq!(
            k.to_latex_vars("x", "t"),
            "-\\frac{x}{\\sqrt{t^{2} - x^{2}}}"
        );
        let half = Expr::Mul(c(1, 2), Box::new(Expr::Call(Func::Ln, Box::new(Expr::X))));
        assert_eq!(
            half.to_latex_vars("t", "s"),
            "\\frac{1}{2} \\ln\\left(t\\right)"
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigInt;

    fn c(n: i64, d: i64) -> Expr {
        Expr::Const(BigRational::new(BigInt::from(n), BigInt::from(d)))
    }

    fn b(e: Expr) -> Box<Expr> {
        Box::new(e)
    }

    #[test]
    fn eval_follows_the_tree() {
        // (1 - x)^(-1/2) * ln(t) + abs(-x) / exp(0)
        let e = Expr::Add(
            b(Expr::Mul(
                b(Expr::Pow(b(Expr::Sub(b(c(1, 1)), b(Expr::X))), b(c(-1, 2)))),
                b(Expr::Call(Func::Ln, b(Expr::T))),
            )),
            b(Expr::Div(
                b(Expr::Call(Func::Abs, b(Expr::Neg(b(Expr::X))))),
                b(Expr::Call(Func::Exp, b(c(0, 1)))),
            )),
        );
        let (x, t) = (0.75f64, 2.0f64);
        let want = (1.0 - x).powf(-0.5) * t.ln() + x;
        assert!((e.eval(x, t) - want).abs() < 1e-14);
        assert!(e.uses_x() && e.uses_t());
        assert!(!c(3, 1).uses_x());
        assert!(Expr::Pi.eval(0.0, 0.0) == std::f64::consts::PI);
    }

    #[test]
    fn display_parenthesises_only_where_needed() {
        let sum = Expr::Add(b(Expr::X), b(Expr::T));
        assert_eq!(
            Expr::Mul(b(sum.clone()), b(Expr::X)).to_string(),
            "(x + t)*x"
        );
        assert_eq!(
            Expr::Sub(b(Expr::X), b(sum.clone())).to_string(),
            "x - (x + t)"
        );
        assert_eq!(Expr::Pow(b(Expr::X), b(c(-1, 2))).to_string(), "x^(-1/2)");
        assert_eq!(Expr::Pow(b(c(-2, 1)), b(Expr::X)).to_string(), "(-2)^x");
        assert_eq!(Expr::Mul(b(c(-1, 2)), b(Expr::X)).to_string(), "-1/2*x");
        assert_eq!(Expr::Mul(b(Expr::X), b(c(1, 2))).to_string(), "x*(1/2)");
        assert_eq!(
            Expr::Neg(b(Expr::Mul(b(Expr::X), b(Expr::T)))).to_string(),
            "-(x*t)"
        );
        assert_eq!(
            Expr::Neg(b(Expr::Pow(b(Expr::X), b(c(2, 1))))).to_string(),
            "-x^2"
        );
        assert_eq!(Expr::Div(b(Expr::Pi), b(c(2, 1))).to_string(), "pi/2");
    }

    #[test]
    fn every_function_by_name_and_value() {
        use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};
        let cases: [(&str, f64, f64); 16] = [
            ("sqrt", 0.25, 0.5),
            ("ln", 1.0, 0.0),
            ("abs", -2.0, 2.0),
            ("exp", 0.0, 1.0),
            ("sin", FRAC_PI_2, 1.0),
            ("cos", PI, -1.0),
            ("tan", FRAC_PI_4, 1.0),
            ("asin", 1.0, FRAC_PI_2),
            ("acos", -1.0, PI),
            ("atan", 1.0, FRAC_PI_4),
            ("acot", -1.0, 0.75 * PI),
            ("sinh", 0.0, 0.0),
            ("cosh", 0.0, 1.0),
            ("tanh", 0.0, 0.0),
            ("gamma", 0.5, 1.772_453_850_905_516),
            ("erf", 1.0, 0.842_700_792_949_714_9),
        ];
        for (name, at, want) in cases {
            let f = Func::from_name(name).expect(name);
            assert_eq!(f.name(), name);
            let got = f.apply(at);
            assert!(
                (got - want).abs() <= 1e-15,
                "{name}({at}) = {got}, not {want}"
            );
            let e = Expr::Call(f, b(Expr::X));
            assert_eq!(e.to_string(), format!("{name}(x)"));
            assert_eq!(e.eval(at, 0.0), got);
        }
        assert_eq!(FUNCS.len(), cases.len());
        assert_eq!(acot(0.0), FRAC_PI_2);
        assert!(Func::Asin.apply(2.0).is_nan());
        assert_eq!(Func::from_name("sec"), None);
        assert!(Func::Gamma.apply(-2.0).is_nan() && Func::Gamma.apply(0.0).is_nan());
        assert!((Func::Gamma.apply(5.0) - 24.0).abs() < 1e-13);
        assert!((Func::Gamma.apply(-0.5) + 2.0 * PI.sqrt()).abs() < 1e-14);
    }
}
