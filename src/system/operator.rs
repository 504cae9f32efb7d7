//! The operator table: what each operator symbol of an operator system
//! means, as a sum of terms the numerics can discretise (integrals with
//! limits and a kernel, multiplication by a function of x, the identity, a
//! scalar multiple of the identity). Data only; built by `lang::lower`.

use num_rational::BigRational;

use super::expr::Expr;

/// An integration limit: a constant or the output variable `x`.
#[derive(Clone, Debug, PartialEq)]
pub enum Limit {
    /// A fixed number.
    Const(BigRational),
    /// The output variable `x`.
    X,
}

/// One term of an operator applied to a function `f`.
#[derive(Clone, Debug, PartialEq)]
pub enum Term {
    /// `∫_lower^upper kernel(x, t) f(t) dt`.
    Integral {
        /// Lower limit.
        lower: Limit,
        /// Upper limit.
        upper: Limit,
        /// The kernel in `x` and `t` (any outer factor is folded in).
        kernel: Expr,
        /// A Cauchy principal value (`pv int`).
        pv: bool,
    },
    /// `m(x) f(x)` for a function `m` that is not a rational constant
    /// (usually it depends on `x`; it may also be e.g. `pi`).
    Multiply(Expr),
    /// `f(x)`.
    Identity,
    /// `c f(x)` for a constant `c ≠ 1`.
    Scalar(BigRational),
}

/// The definition of one operator symbol.
#[derive(Clone, Debug, PartialEq)]
pub struct OperatorDef {
    /// Index into `Program::symbols`.
    pub symbol: usize,
    /// The terms whose sum is the operator.
    pub terms: Vec<Term>,
}
