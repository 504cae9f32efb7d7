//! The numeric layer's error type. It owns nothing but the enum: every
//! fallible routine in `crate::numeric` returns [`NumericError`] instead of a
//! doubtful number, and it must not format anything for the command line.
use thiserror::Error;

/// Why a numerical routine refused to return a result.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum NumericError {
    /// A quadrature rule was requested with impossible parameters.
    #[error("invalid quadrature rule: {0}")]
    InvalidRule(String),
    /// The symmetric eigensolver behind Golub–Welsch did not deliver.
    #[error("Golub–Welsch eigen-decomposition failed for {0} nodes")]
    Eigen(usize),
    /// A mesh or basis description is inconsistent (unsorted, empty, ...).
    #[error("invalid mesh: {0}")]
    InvalidMesh(String),
    /// An argument outside the documented domain.
    #[error("invalid argument: {0}")]
    InvalidArgument(String),
    /// A kernel, weight or right-hand side produced NaN or infinity.
    #[error("non-finite value in {0}")]
    NonFinite(String),
    /// Dimensions of blocks, vectors or matrices do not match.
    #[error("dimension mismatch: {0}")]
    Dimension(String),
    /// The discretised system is exactly singular (zero pivot).
    #[error("discretised system of size {0} is singular")]
    Singular(usize),
    /// The discretised system is too ill-conditioned for its result to mean
    /// anything: `cond` is the estimated 1-norm condition number.
    #[error(
        "discretised system of size {size} is ill-conditioned (cond ≈ {cond:.3e} > {limit:.1e})"
    )]
    IllConditioned {
        /// Size of the system.
        size: usize,
        /// Estimated 1-norm condition number.
        cond: f64,
        /// The limit that was exceeded.
        limit: f64,
    },
    /// The discretised system has an isolated singular value at the level
    /// of rounding or discretisation error: the operator has (or nearly
    /// has) a null space, so the problem has more than one solution or
    /// none. `smallest` and `next` are the two smallest singular values
    /// relative to the largest (columns scaled to unit max-norm). The
    /// right side is not examined, so the message names both cases.
    #[error(
        "the problem has more than one solution or none: the discretised system of size {size} has a null direction (its smallest singular value is {smallest:.1e} of the largest, the next {next:.1e}), so the operator is not invertible; if the right side lies in its range, any multiple of the null function can be added to a solution and a side condition (`condition …`) can select one; if not, there is no solution and the right side must be changed (this check does not tell which)"
    )]
    NullSpace {
        /// Size of the system.
        size: usize,
        /// The smallest singular value over the largest.
        smallest: f64,
        /// The second smallest over the largest.
        next: f64,
    },
    /// An iteration (root finding, refinement) did not converge.
    #[error("no convergence: {0}")]
    NoConvergence(String),
}
