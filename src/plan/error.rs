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
    /// The root of an unknown scalar's condition lies closer to an end of
    /// the scalar's declared range than the solver resolves (or was not
    /// found elsewhere): a numerical refusal, carrying what a caller needs
    /// to name the physical limit without reading the message.
    #[error("scalar root: no convergence: {}", .0.message)]
    RootAtEnd(Box<RootAtEnd>),
    /// The next level does not fit the memory budget (and no level before
    /// it was solved).
    #[error("{0}")]
    OverBudget(crate::numeric::budget::OverBudget),
    /// The answer breaks a declared inequality (where, and by how much,
    /// in the message): a refusal of the computed result, not of the input.
    #[error("{0}")]
    Inequality(String),
    /// The numerics refused (singular, ill-conditioned, non-finite, ...).
    #[error("{context}: {source}")]
    Numeric {
        /// What was being computed.
        context: String,
        /// The numeric layer's reason.
        source: NumericError,
    },
}

/// Which end of a scalar's declared range.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RangeEnd {
    /// The lower end (`lo` of `(lo, hi)`).
    Lower,
    /// The upper end (`hi`; possibly `inf`).
    Upper,
}

/// Why the root is placed at an end.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum EndReason {
    /// The condition keeps one sign over the whole resolved range; its
    /// size is smallest toward the end named.
    NoSignChange {
        /// Why the scan stopped short of the resolved distance, if it did
        /// (the discretisation failed beyond the last point reached).
        failed_beyond: Option<String>,
    },
    /// Sign changes were found, but every one was rejected (a pole, the
    /// discrete condition's noise near an end, or a root whose solution
    /// violates a relation's bound): `(scalar value, why)` for each.
    NoneAdmissible {
        /// The rejected candidates.
        rejected: Vec<(f64, String)>,
    },
    /// On a refined level the root moved this close to the end, where
    /// the sign change is not a clean root (a pole, or noise).
    Noisy {
        /// Where the sign change was.
        at: f64,
        /// The condition there and at the two neighbouring points.
        values: (f64, f64, f64),
    },
}

/// A root of an unknown scalar's condition that lies (or may lie) closer
/// to an end of its declared range than the solver resolves.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct RootAtEnd {
    /// The scalar's name (e.g. `c`).
    pub scalar: String,
    /// Toward which end.
    pub end: RangeEnd,
    /// The value of that end (e.g. `0`, `1`, `inf`).
    pub end_value: f64,
    /// The relative distance to an end the solver resolves (`1e-10` of a
    /// finite range; in `ln x` for a half-line).
    pub resolved: f64,
    /// The scalar's value nearest that end at which the condition was
    /// evaluated.
    pub reached: f64,
    /// The measured trend of the condition: `(scalar value, condition)`
    /// at the points of the scan, ascending in the scalar.
    pub trend: Vec<(f64, f64)>,
    /// Why.
    pub reason: EndReason,
    /// The solver's words (the error's text).
    pub message: String,
}

impl RootAtEnd {
    /// The condition's values toward `end`, outermost first.
    fn toward(&self, end: RangeEnd) -> Vec<f64> {
        match end {
            RangeEnd::Lower => self.trend.iter().map(|t| t.1).collect(),
            RangeEnd::Upper => self.trend.iter().rev().map(|t| t.1).collect(),
        }
    }

    /// Whether the condition's size falls strictly over the `n` scanned
    /// points nearest `end`, toward it (a root beyond the end, or the
    /// condition vanishing there).
    pub fn shrinks_toward(&self, end: RangeEnd, n: usize) -> bool {
        let v = self.toward(end);
        v.len() >= n && v[..n].windows(2).all(|w| w[0].abs() < w[1].abs())
    }

    /// Whether the condition levels off at a non-zero value toward `end`:
    /// its two outermost values differ by at most `rel` of their size (no
    /// root beyond that end).
    pub fn levels_off(&self, end: RangeEnd, rel: f64) -> bool {
        let v = self.toward(end);
        v.len() >= 2 && v[0] != 0.0 && (v[0] - v[1]).abs() <= rel * v[0].abs()
    }
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
        !matches!(
            self,
            PlanError::Numeric { .. }
                | PlanError::Singular(_)
                | PlanError::RootAtEnd(_)
                | PlanError::OverBudget(_)
                | PlanError::Inequality(_)
        )
    }
}
