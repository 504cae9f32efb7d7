//! The hand-written Hertz solver, written before the language could state
//! the problem: an independent oracle for the tests (and the probes and
//! benches that compare with it), not part of the library. On top of
//! `lambdamat::numeric` only:
//!
//! * `operators`: κ1..κ4, `γ(ν)`, `α(γ, μ)`;
//! * `system`: one discretisation at fixed `(γ, μ, c)` and its `R(c)`;
//! * `roots`: bracketing, Brent and warm-started secant iterations;
//! * `solve`: the solvers and their refinement ladder;
//! * `solution`: the result, field evaluation, checks.
//!
//! Include it with `#[path = "common/hertz_oracle/mod.rs"] mod hertz_oracle;`.
#![allow(dead_code, unused_imports)]

pub mod operators;
pub mod roots;
pub mod solution;
pub mod solve;
pub mod system;

pub use solution::{HertzSolution, Sample};
pub use solve::{HertzOptions, solve_given_c, solve_given_mu};
