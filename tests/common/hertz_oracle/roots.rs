//! The root finders of the free boundary now live in
//! [`lambdamat::numeric::roots`] (shared with the language's split-domain
//! solver); this module re-exports them for the Hertz solver.
pub use lambdamat::numeric::roots::{bracket, brent, directed_bracket, secant};
