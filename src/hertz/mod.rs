//! The Hertz contact problem with finite friction (docs/hertz.md), solved
//! on top of [`crate::numeric`] (no second copy of quadrature):
//!
//! * [`operators`]: κ1..κ4, `γ(ν)`, `α(γ, μ)`;
//! * [`system`]: one discretisation at fixed `(γ, μ, c)` and its `R(c)`;
//! * [`roots`]: bracketing, Brent and warm-started secant iterations;
//! * [`solve`]: the public solvers and their refinement ladder;
//! * [`solution`]: the result, field evaluation, checks;
//! * [`seed`]: the seed paper's literal algorithm, for comparison only;
//! * [`error`]: the layer's error enum.
//!
//! ```no_run
//! use lambdamat::hertz::{solve_given_mu, HertzOptions};
//! let s = solve_given_mu(0.25, 0.1801, &HertzOptions::default()).unwrap();
//! println!("c = {} ± {}", s.c, s.error_estimate);
//! ```
pub mod error;
pub mod operators;
pub mod roots;
pub mod seed;
pub mod solution;
pub mod solve;
pub mod system;

pub use error::HertzError;
pub use solution::{HertzSolution, Sample};
pub use solve::{HertzOptions, solve_given_c, solve_given_mu};
