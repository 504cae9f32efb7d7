//! A solver for `examples/mms.lmx`, written by lambdamat 0.1.0 (`lambdamat codegen`).
//! Do not edit: regenerate with `lambdamat codegen examples/mms.lmx -o FILE.rs`.
//!
//! Kernels, multipliers, right sides and output weights are the Rust
//! functions below; `system()` collects them, `input()` makes them a
//! problem without breakpoints, and `main()` solves it through
//! lambdamat's solver (`lambdamat::standalone::split_solver_main`):
//! assembly, refinement to the tolerance, and the error estimates.
//! Unknowns on [0, 1]; eliminations solve for `p`.
//!
//! Derived equations for `p` (`lambdamat reduce`):
//!
//! - ordered elimination, exact (`--method ordered`; gj is
//!   the right side of equation j):
//!   `(k1 - k2 k4^-1 k3) p = g1 - k2 k4^-1 g2`
//!   pivots: q from equation 2 (pivot k4)
//! - commutative eliminant, the seed's model (`--method commutative`):
//!   `(k1*k4 - k2*k3) p = k4[sqrt(1 - x^2) + 1/3*(x^2 - 1/2)] - k2[1/3*x - x*sqrt(1 - x^2)]`
//!   commuted pairs: (k2, k4)
//!
//! The system (parameters substituted):
//!
//! ```text
//! param gamma = 1/3
//! operator k1 = int(x..1) t/sqrt(t^2 - x^2) dt
//! operator k2 = int(0..1) -1/3 dt + int(0..x) 1/3*(x/sqrt(x^2 - t^2)) dt
//! operator k3 = int(0..x) 1/3*(t/sqrt(x^2 - t^2)) dt
//! operator k4 = int(x..1) -(x/sqrt(t^2 - x^2)) dt
//! unknown p, q
//! equation k1 p + k2 q = sqrt(1 - x^2) + 1/3*(x^2 - 1/2)
//! equation k3 p + k4 q = 1/3*x - x*sqrt(1 - x^2)
//! output P = pi/2*int(0..1) x*p(x) dx
//! output Q = int(0..1) q(x) dx
//! solve for p
//! ```

// Literals are printed to read back bit for bit; some may look like
// named constants without being them.
#![allow(clippy::approx_constant)]

use std::sync::Arc;

use lambdamat::standalone::Limits::{Fixed, Lower, Upper};
use lambdamat::standalone::Singularity::{AbelSqrt, Smooth};
use lambdamat::standalone::{
    CompiledEquation, CompiledOutput, CompiledSystem, Operator, OutputTerm, PlanError,
    SplitContact, SplitInput, words,
};

/// Operator `k1`, kernel `t/sqrt(t^2 - x^2)`: its smooth factor a(x, t) with kernel = a(x, t)/√|t² - x²|.
fn kernel_k1(_x: f64, t: f64) -> f64 {
    t
}

/// Operator `k2`, kernel `-1/3`: a smooth kernel.
fn kernel_k2_1(_x: f64, _t: f64) -> f64 {
    -0.3333333333333333
}

/// Operator `k2`, kernel `1/3*(x/sqrt(x^2 - t^2))`: its smooth factor a(x, t) with kernel = a(x, t)/√|t² - x²|.
fn kernel_k2_2(x: f64, _t: f64) -> f64 {
    0.3333333333333333 * x
}

/// Operator `k3`, kernel `1/3*(t/sqrt(x^2 - t^2))`: its smooth factor a(x, t) with kernel = a(x, t)/√|t² - x²|.
fn kernel_k3(_x: f64, t: f64) -> f64 {
    0.3333333333333333 * t
}

/// Operator `k4`, kernel `-(x/sqrt(t^2 - x^2))`: its smooth factor a(x, t) with kernel = a(x, t)/√|t² - x²|.
fn kernel_k4(x: f64, _t: f64) -> f64 {
    -x
}

/// Right side of equation 1: `sqrt(1 - x^2) + 1/3*(x^2 - 1/2)`.
fn rhs_1(x: f64) -> f64 {
    let v1 = 0.3333333333333333 * (f64::powi(x, 2) - 0.5);
    f64::sqrt(1.0 - f64::powi(x, 2)) + v1
}

/// Right side of equation 2: `1/3*x - x*sqrt(1 - x^2)`.
fn rhs_2(x: f64) -> f64 {
    0.3333333333333333 * x - x * f64::sqrt(1.0 - f64::powi(x, 2))
}

/// Weight of output `P`: `x`.
fn weight_p(x: f64) -> f64 {
    x
}

/// Weight of output `Q`: `1`.
fn weight_q(_x: f64) -> f64 {
    1.0
}

/// The operator system, which `input()` completes.
pub fn system() -> Result<CompiledSystem, PlanError> {
    let mut op_k1 = Operator::zero();
    op_k1 = op_k1 + Operator::integral(Upper { b: 1.0 }, AbelSqrt, kernel_k1);
    let mut op_k2 = Operator::zero();
    op_k2 = op_k2 + Operator::integral(Fixed { a: 0.0, b: 1.0 }, Smooth, kernel_k2_1);
    op_k2 = op_k2 + Operator::integral(Lower { a: 0.0 }, AbelSqrt, kernel_k2_2);
    let mut op_k3 = Operator::zero();
    op_k3 = op_k3 + Operator::integral(Lower { a: 0.0 }, AbelSqrt, kernel_k3);
    let mut op_k4 = Operator::zero();
    op_k4 = op_k4 + Operator::integral(Upper { b: 1.0 }, AbelSqrt, kernel_k4);
    let lhs_1 = vec![words(&[(&[0], "1")])?, words(&[(&[1], "1")])?];
    let equation_1 = CompiledEquation {
        lhs: lhs_1,
        rhs: Arc::new(rhs_1),
        rhs_text: "sqrt(1 - x^2) + 1/3*(x^2 - 1/2)".into(),
    };
    let lhs_2 = vec![words(&[(&[2], "1")])?, words(&[(&[3], "1")])?];
    let equation_2 = CompiledEquation {
        lhs: lhs_2,
        rhs: Arc::new(rhs_2),
        rhs_text: "1/3*x - x*sqrt(1 - x^2)".into(),
    };
    let output_1_term_1 = OutputTerm::Integral {
        coeff: std::f64::consts::FRAC_PI_2,
        lower: 0.0,
        upper: 1.0,
        weight: Arc::new(weight_p),
        unknown: 0,
    };
    let output_1 = CompiledOutput {
        name: "P".into(),
        terms: vec![output_1_term_1],
    };
    let output_2_term_1 = OutputTerm::Integral {
        coeff: 1.0,
        lower: 0.0,
        upper: 1.0,
        weight: Arc::new(weight_q),
        unknown: 1,
    };
    let output_2 = CompiledOutput {
        name: "Q".into(),
        terms: vec![output_2_term_1],
    };
    let sys = CompiledSystem {
        symbols: vec!["k1".into(), "k2".into(), "k3".into(), "k4".into()],
        operators: vec![Some(op_k1), Some(op_k2), Some(op_k3), Some(op_k4)],
        unknowns: vec!["p".into(), "q".into()],
        equations: vec![equation_1, equation_2],
        outputs: vec![output_1, output_2],
        conditions: Vec::new(),
        target: 0,
        principal: None,
        derived_pivots: Some(vec![(1, 1)]),
        domain: (0.0, 1.0),
        interior: Vec::new(),
        features: Vec::new(),
    };
    sys.check()?;
    Ok(sys)
}

/// The split-domain problem, ready for `lambdamat::standalone::split_solver_main`.
pub fn input() -> Result<SplitInput, PlanError> {
    let contact = SplitContact {
        scalars: Vec::new(),
        reals: Vec::new(),
        unknown_domains: vec![None, None],
        equation_domains: Vec::new(),
        rhs: Vec::new(),
        relations: Vec::new(),
        inequalities: Vec::new(),
        singulars: Vec::new(),
        coefficients: Vec::new(),
        conditions: Vec::new(),
        estimates: Vec::new(),
        ends: Vec::new(),
    };
    let sys = system()?;
    Ok(SplitInput { sys, contact })
}

/// Solves the problem and prints the report of `lambdamat solve`; takes
/// `[--method coupled|ordered|commutative] [--tol T] [--max-level N] [--json]`
/// `[--csv FILE]` (see `--help`). It needs lambdamat without its command line:
/// `lambdamat = { path = "…", default-features = false }`.
pub fn main() {
    std::process::exit(lambdamat::standalone::split_solver_main(input));
}
