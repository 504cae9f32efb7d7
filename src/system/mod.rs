//! The span-free lowered form of a lambdamat file: the interface between the
//! front end ([`crate::lang`]) and both the algebra and the numerics. It holds
//! names only as a symbol table (indices everywhere else), exact rationals
//! and polynomials for the algebra, and plain expression trees for the
//! numerics. Nothing here knows about source text, spans or parsing, and
//! nothing here does algebra beyond storing [`MPoly`] values.
//!
//! * [`program`]: [`Program`], [`MatrixDef`], [`Directive`].

pub mod program;

pub use crate::algebra::mpoly::MPoly;
pub use program::{Directive, MatrixDef, Program};
