//! The Hertz contact problem with finite friction (docs/hertz.md).
//!
//! * [`front`]: what `lambdamat hertz` runs: the language files
//!   `examples/hertz*.lmx` through the general split-domain solver, and
//!   the fields, slip and checks read off their solution. This is the one
//!   numerical implementation behind the command line.
//!
//! Everything else here is the hand-written solver written before the
//! language could state the problem. It is kept as an independent oracle
//! for tests (tests/split_hertz.rs and the hertz_* tests compare the front
//! with it on Spence's rows) and no command-line path calls its solvers;
//! [`seed`] (the seed paper's literal algorithm, a different model) uses its
//! discretisation for the `hertz table` comparison column. On top of
//! [`crate::numeric`] (no second copy of quadrature):
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
pub mod front;
pub mod operators;
pub mod roots;
pub mod seed;
pub mod solution;
pub mod solve;
pub mod system;

pub use error::HertzError;
pub use solution::{HertzSolution, Sample};
pub use solve::{HertzOptions, solve_given_c, solve_given_mu};
