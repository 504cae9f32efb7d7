//! The Hertz layer's error type; it wraps the numeric layer's refusals and
//! adds the problem's own (bad parameters, no free boundary found). It owns
//! the enum only.
use thiserror::Error;

use crate::numeric::NumericError;

/// Why a Hertz solve refused to return a result.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum HertzError {
    /// A parameter outside its physical range.
    #[error("invalid parameter: {0}")]
    InvalidParameter(String),
    /// The numeric layer refused (singular system, non-finite value, ...).
    #[error(transparent)]
    Numeric(#[from] NumericError),
    /// The free-boundary iteration or the refinement did not converge.
    #[error("no convergence: {0}")]
    #[cfg(feature = "internals")]
    NoConvergence(String),
}
