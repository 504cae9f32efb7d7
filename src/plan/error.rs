//! The error of the language-to-numerics bridge. It owns only the enum and
//! the split between input the bridge cannot handle (an unsupported kernel,
//! a non-square system: the user must change the file) and numerics that
//! refused to give a result (singular or ill-conditioned discretisations).
use crate::numeric::NumericError;

/// Why a system from the language could not be solved.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PlanError {
    /// An operator's definition is outside what the numerics support.
    #[error("operator {operator}: {reason}")]
    Unsupported {
        /// The operator symbol's name.
        operator: String,
        /// What is not supported.
        reason: String,
    },
    /// The file's system cannot be solved as written (shape, missing parts).
    #[error("{0}")]
    Invalid(String),
    /// The right side of an equation cannot be used (e.g. not finite at a
    /// collocation point).
    #[error("{reason}")]
    RightSide {
        /// The equation's index (0-based, source order).
        equation: usize,
        /// What is wrong, in words (names the equation 1-based).
        reason: String,
    },
    /// The system is singular before any discretisation (exact algebra).
    #[error("{0}")]
    Singular(String),
    /// The numerics refused (singular, ill-conditioned, non-finite, ...).
    #[error("{context}: {source}")]
    Numeric {
        /// What was being computed.
        context: String,
        /// The numeric layer's reason.
        source: NumericError,
    },
}

impl From<NumericError> for PlanError {
    fn from(source: NumericError) -> PlanError {
        PlanError::Numeric {
            context: "root finding".into(),
            source,
        }
    }
}

impl PlanError {
    /// Wraps a numeric error with what was being computed.
    pub fn numeric(context: impl Into<String>) -> impl FnOnce(NumericError) -> PlanError {
        let context = context.into();
        move |source| PlanError::Numeric { context, source }
    }

    /// Whether the input (not the numerics) is at fault.
    pub fn is_input_error(&self) -> bool {
        !matches!(self, PlanError::Numeric { .. } | PlanError::Singular(_))
    }
}
