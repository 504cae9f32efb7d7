//! Printed formulas read back: one expression in the language's syntax
//! (what [`crate::algebra::print`] writes in its `Lmx` format, e.g. an entry
//! of a `--json` report) turned into the exact value it stands for, in the
//! ring it belongs to: a polynomial ([`parse_poly`]), a rational function of
//! the symbols ([`parse_ratfunc`], for principal-mode entries such as
//! `k4^3 + (1/k1)*k4^2 - (k1 + 1)`), or a non-commutative rational operator
//! expression ([`parse_ncexpr`], for ordered eliminations such as
//! `k1 - k2*k4^(-1)*k3`). Errors carry spans and render with line:column
//! like any other language error. This module owns only that evaluation; it
//! must not print, and the syntax itself is the grammar's.

use super::ast::{BinOp, Expr, ExprKind, Span};
use super::diagnostics::LangErrors;
use super::error::{ErrorKind, LangError};
use super::parser::parse_formula;
use super::validate::MAX_EXPONENT;
use crate::algebra::mpoly::MPoly;
#[cfg(any(test, feature = "internals"))]
use crate::algebra::ordered::NcExpr;
use crate::algebra::ratfunc::{RatFunc, RatFuncField};
use crate::algebra::rational::Q;
use crate::algebra::ring::{Field, Ring};
use num_traits::{One, Signed, ToPrimitive};

/// The file name shown in a formula's errors.
const SOURCE: &str = "<formula>";

/// The arithmetic a formula is evaluated in.
trait Target {
    type V: Clone;
    fn num(&self, q: &Q) -> Self::V;
    fn sym(&self, i: usize) -> Self::V;
    fn add(&self, a: &Self::V, b: &Self::V) -> Self::V;
    fn sub(&self, a: &Self::V, b: &Self::V) -> Self::V;
    fn mul(&self, a: &Self::V, b: &Self::V) -> Self::V;
    fn neg(&self, a: &Self::V) -> Self::V;
    /// `a / b`: `Err(kind)` when `b` is zero or the quotient is not allowed.
    fn div(&self, a: &Self::V, b: &Self::V) -> Result<Self::V, ErrorKind>;
    fn inv(&self, a: &Self::V) -> Option<Self::V>;
    fn as_const(&self, a: &Self::V) -> Option<Q>;
}

struct Commutative(RatFuncField);

impl Target for Commutative {
    type V = RatFunc;
    fn num(&self, q: &Q) -> RatFunc {
        RatFunc::from_poly(MPoly::constant(q.clone(), self.0.names.len()))
    }
    fn sym(&self, i: usize) -> RatFunc {
        RatFunc::from_poly(MPoly::var(i, self.0.names.len()))
    }
    fn add(&self, a: &RatFunc, b: &RatFunc) -> RatFunc {
        self.0.add(a, b)
    }
    fn sub(&self, a: &RatFunc, b: &RatFunc) -> RatFunc {
        self.0.sub(a, b)
    }
    fn mul(&self, a: &RatFunc, b: &RatFunc) -> RatFunc {
        self.0.mul(a, b)
    }
    fn neg(&self, a: &RatFunc) -> RatFunc {
        self.0.neg(a)
    }
    fn div(&self, a: &RatFunc, b: &RatFunc) -> Result<RatFunc, ErrorKind> {
        let bi = self.0.inv(b).ok_or(ErrorKind::DivisionByZero)?;
        Ok(self.0.mul(a, &bi))
    }
    fn inv(&self, a: &RatFunc) -> Option<RatFunc> {
        self.0.inv(a)
    }
    fn as_const(&self, a: &RatFunc) -> Option<Q> {
        if a.is_polynomial() {
            a.num().as_constant()
        } else {
            None
        }
    }
}

#[cfg(any(test, feature = "internals"))]
struct Ordered;

#[cfg(any(test, feature = "internals"))]
impl Target for Ordered {
    type V = NcExpr;
    fn num(&self, q: &Q) -> NcExpr {
        NcExpr::constant(q.clone())
    }
    fn sym(&self, i: usize) -> NcExpr {
        NcExpr::sym(i)
    }
    fn add(&self, a: &NcExpr, b: &NcExpr) -> NcExpr {
        a.add(b)
    }
    fn sub(&self, a: &NcExpr, b: &NcExpr) -> NcExpr {
        a.sub(b)
    }
    fn mul(&self, a: &NcExpr, b: &NcExpr) -> NcExpr {
        a.mul(b)
    }
    fn neg(&self, a: &NcExpr) -> NcExpr {
        a.neg()
    }
    fn div(&self, a: &NcExpr, b: &NcExpr) -> Result<NcExpr, ErrorKind> {
        // `a/b` does not say on which side b^-1 stands: only constants.
        match b.as_constant() {
            Some(c) if num_traits::Zero::is_zero(&c) => Err(ErrorKind::DivisionByZero),
            Some(c) => Ok(a.mul(&NcExpr::constant(c.recip()))),
            None => Err(ErrorKind::NonPolynomial),
        }
    }
    fn inv(&self, a: &NcExpr) -> Option<NcExpr> {
        a.inv()
    }
    fn as_const(&self, a: &NcExpr) -> Option<Q> {
        a.as_constant()
    }
}

fn err(kind: ErrorKind, message: impl Into<String>, span: Span, label: &str) -> LangError {
    LangError::new(kind, message, span, label)
}

fn eval<T: Target>(t: &T, e: &Expr, symbols: &[String]) -> Result<T::V, LangError> {
    match &e.kind {
        ExprKind::Number(q) => Ok(t.num(q)),
        ExprKind::Name(id) => match symbols.iter().position(|s| *s == id.name) {
            Some(i) => Ok(t.sym(i)),
            None => Err(err(
                ErrorKind::Undeclared,
                format!("undeclared symbol `{}`", id.name),
                id.span,
                "not one of the formula's symbols",
            )
            .with_help(format!("symbols: {}", symbols.join(", ")))),
        },
        ExprKind::Neg(a) => Ok(t.neg(&eval(t, a, symbols)?)),
        ExprKind::Binary(op, a, b) => {
            let x = eval(t, a, symbols)?;
            if *op == BinOp::Pow {
                return power(t, &x, b, symbols);
            }
            let y = eval(t, b, symbols)?;
            match op {
                BinOp::Add => Ok(t.add(&x, &y)),
                BinOp::Sub => Ok(t.sub(&x, &y)),
                BinOp::Mul => Ok(t.mul(&x, &y)),
                _ => t.div(&x, &y).map_err(|kind| {
                    let msg = if kind == ErrorKind::DivisionByZero {
                        "division by zero"
                    } else {
                        "division by an operator that is not a constant"
                    };
                    err(kind, msg, b.span, "this divisor")
                        .with_help("write the inverse on its side, e.g. `a*b^(-1)`")
                }),
            }
        }
        _ => Err(err(
            ErrorKind::WrongSort,
            "only numbers, symbols, `+ - * / ^` and parentheses may appear in a formula",
            e.span,
            "not allowed here",
        )),
    }
}

fn power<T: Target>(t: &T, base: &T::V, exp: &Expr, symbols: &[String]) -> Result<T::V, LangError> {
    let bad = |msg: String| err(ErrorKind::BadExponent, msg, exp.span, "this exponent");
    let e = eval(t, exp, symbols)?;
    let q = t
        .as_const(&e)
        .ok_or_else(|| bad("the exponent must be an integer constant".into()))?;
    if !q.is_integer() {
        return Err(bad(format!(
            "the exponent must be an integer, not {}",
            crate::algebra::rational::fmt_q(&q)
        )));
    }
    let n = q
        .to_integer()
        .abs()
        .to_u32()
        .filter(|n| *n <= MAX_EXPONENT)
        .ok_or_else(|| bad(format!("exponent too large (the limit is {MAX_EXPONENT})")))?;
    let b = if q.is_negative() {
        t.inv(base).ok_or_else(|| {
            err(
                ErrorKind::DivisionByZero,
                "a negative power of zero",
                exp.span,
                "this exponent",
            )
        })?
    } else {
        base.clone()
    };
    let mut acc = t.num(&Q::one());
    for _ in 0..n {
        acc = t.mul(&acc, &b);
    }
    Ok(acc)
}

fn run<T: Target>(t: &T, src: &str, symbols: &[String]) -> Result<T::V, LangErrors> {
    let wrap = |e: LangError| LangErrors::new(SOURCE, src, vec![e]);
    let e = parse_formula(src).map_err(wrap)?;
    eval(t, &e, symbols).map_err(wrap)
}

/// Reads a rational function of `symbols` (the field Q(symbols)).
///
/// ```
/// use lambdamat::lang::formula::parse_ratfunc;
/// let names = ["k1".to_string(), "k4".to_string()];
/// let f = parse_ratfunc("k4^3 + (1/k1)*k4^2 - (k1 + 1)", &names).expect("valid");
/// assert_eq!(f.den().to_string_with(&names), "k1");
/// let e = parse_ratfunc("k1/(k4 - k4)", &names).unwrap_err();
/// assert!(e.render().contains("<formula>:1:4"));
/// ```
pub fn parse_ratfunc(src: &str, symbols: &[String]) -> Result<RatFunc, LangErrors> {
    let k = RatFuncField {
        names: symbols.to_vec(),
        shown: symbols.to_vec(),
    };
    run(&Commutative(k), src, symbols)
}

/// Reads a polynomial in `symbols`; a non-constant denominator is an error.
#[cfg(any(test, feature = "internals"))]
pub fn parse_poly(src: &str, symbols: &[String]) -> Result<MPoly, LangErrors> {
    let f = parse_ratfunc(src, symbols)?;
    if f.is_polynomial() {
        return Ok(f.num().clone());
    }
    let span = Span::new(0, src.len());
    Err(LangErrors::new(
        SOURCE,
        src,
        vec![err(
            ErrorKind::NonPolynomial,
            "this formula is a fraction, not a polynomial",
            span,
            "has a non-constant denominator",
        )],
    ))
}

/// Reads a non-commutative rational expression in `symbols` (products keep
/// their order, `s^(-1)` is an inverse).
#[cfg(any(test, feature = "internals"))]
pub fn parse_ncexpr(src: &str, symbols: &[String]) -> Result<NcExpr, LangErrors> {
    run(&Ordered, src, symbols)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(v: &[&str]) -> Vec<String> {
        v.iter().map(|s| s.to_string()).collect()
    }

    #[test]
    fn the_issue_factor_reads_back_to_its_value() {
        let n = names(&["k1", "k4"]);
        let f = parse_ratfunc("k4^3 + (1/k1)*k4^2 - (k1 + 1)", &n).expect("valid");
        // times k1: k1*k4^3 + k4^2 - k1^2 - k1
        let g = parse_poly("k1*k4^3 + k4^2 - k1^2 - k1", &n).expect("valid");
        assert_eq!(f.num(), &g);
        let wrong = parse_ratfunc("k4^3 + 1/k1*k4^2 - k1 + 1", &n).expect("valid");
        assert_ne!(wrong, f);
    }

    #[test]
    fn errors_point_at_the_place() {
        let n = names(&["a", "b"]);
        let e = parse_ratfunc("a + c", &n).unwrap_err();
        assert!(e.render().contains("1:5"), "{}", e.render());
        assert!(parse_ratfunc("a^b", &n).is_err());
        assert!(parse_ratfunc("a^(1/2)", &n).is_err());
        assert!(parse_ratfunc("sqrt(a)", &n).is_err());
        assert!(parse_ratfunc("a +", &n).is_err());
        assert!(parse_poly("1/a", &n).is_err());
        assert!(parse_ncexpr("a/b", &n).is_err());
        assert!(parse_ncexpr("(a - a)^(-1)", &n).is_err());
    }

    #[test]
    fn ordered_products_keep_their_order() {
        let n = names(&["a", "b"]);
        let x = parse_ncexpr("a*b^(-1) - 2*(a + b)^(-1)", &n).expect("valid");
        assert_eq!(x.to_string_with(&n), "a b^-1 - 2 (a + b)^-1");
        assert_ne!(parse_ncexpr("a*b", &n).ok(), parse_ncexpr("b*a", &n).ok());
    }
}
