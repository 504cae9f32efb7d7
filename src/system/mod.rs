//! The span-free lowered form of a lambdamat file: the interface between the
//! front end ([`crate::lang`]) and both the algebra and the numerics. It holds
//! names only as a symbol table (indices everywhere else), exact rationals
//! and polynomials for the algebra, and plain expression trees for the
//! numerics. Nothing here knows about source text, spans or parsing, and
//! nothing here does algebra beyond storing [`MPoly`](crate::algebra::mpoly::MPoly) and [`NcPoly`] values.
//!
//! * [`program`]: [`Program`], [`MatrixDef`], [`Directive`], equations,
//!   parameters and outputs;
//! * [`operator`]: the operator table (integral terms, multipliers, identity);
//! * [`contact`]: split domains, relations, scalars, singular behaviour;
//! * [`expr`]: expression trees in `x` and `t` with `eval`.

pub mod contact;
pub mod expr;
pub mod operator;
pub mod program;

pub use crate::algebra::ncpoly::NcPoly;
pub use expr::{Expr, Func};
pub use operator::{Limit, OperatorDef, Term};
pub use program::{
    Directive, Equation, FunctionalTerm, MatrixDef, Output, Param, Program, SideCondition,
};
