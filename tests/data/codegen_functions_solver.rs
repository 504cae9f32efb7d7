//! A solver for `tests/data/codegen_functions.lmx`, written by lambdamat 0.1.0 (`lambdamat codegen`).
//! Do not edit: regenerate with `lambdamat codegen tests/data/codegen_functions.lmx -o FILE.rs`.
//!
//! Kernels, multipliers, right sides and output weights are the Rust
//! functions below; `system()` collects them, `input()` makes them a
//! problem without breakpoints, and `main()` solves it through
//! lambdamat's solver (`lambdamat::standalone::split_solver_main`):
//! assembly, refinement to the tolerance, and the error estimates.
//! Unknowns on [0, 1]; eliminations solve for `u`.
//!
//! Derived equations for `u` (`lambdamat reduce`):
//!
//! - ordered elimination, exact (`--method ordered`; gj is
//!   the right side of equation j):
//!   `(k - m l) u = g1 - m g2`
//!   pivots: v from equation 2 (pivot 1)
//! - commutative eliminant, the seed's model (`--method commutative`):
//!   `(k - m*l) u = [exp(x) + sinh(x)/2 - atan(x)] - m[cos(x) + tanh(x)*acot(x + 1)]`
//!   commuted pairs: none
//!
//! The system (parameters substituted):
//!
//! ```text
//! operator k = id + int(0..1) -1/10*(sin(x*t) + cos(t) + tan(t/2) + asin(t/2) + acos(t/2)) dt
//! operator m = int(0..1) 1/10*(atan(t) + acot(t + 1) + sinh(x*t) + cosh(t) + tanh(t)) dt
//! operator l = int(0..1) 1/10*ln(abs(3*x - 3*t)) dt
//! unknown u, v
//! equation k u + m v = exp(x) + sinh(x)/2 - atan(x)
//! equation l u + 1 v = cos(x) + tanh(x)*acot(x + 1)
//! output P = u(1/2) + -2*v(1/4) + int(0..1) u(x) dx
//! ```

// Literals are printed to read back bit for bit; some may look like
// named constants without being them.
#![allow(clippy::approx_constant)]

use std::sync::Arc;

use lambdamat::standalone::Limits::Fixed;
use lambdamat::standalone::Singularity::Smooth;
use lambdamat::standalone::{
    CompiledEquation, CompiledOutput, CompiledSystem, Operator, OutputTerm, PlanError,
    SplitContact, SplitInput, words,
};

/// Operator `k`, kernel `-1/10*(sin(x*t) + cos(t) + tan(t/2) + asin(t/2) + acos(t/2))`: a smooth kernel.
fn kernel_k_2(x: f64, t: f64) -> f64 {
    let v1 = f64::sin(x * t) + f64::cos(t) + f64::tan(t / 2.0) + f64::asin(t / 2.0);
    -0.1 * (v1 + f64::acos(t / 2.0))
}

/// Operator `m`, kernel `1/10*(atan(t) + acot(t + 1) + sinh(x*t) + cosh(t) + tanh(t))`: a smooth kernel.
fn kernel_m(x: f64, t: f64) -> f64 {
    let v1 = f64::atan(t) + lambdamat::standalone::acot(t + 1.0) + f64::sinh(x * t);
    0.1 * (v1 + f64::cosh(t) + f64::tanh(t))
}

/// Operator `l`, kernel `1/10*ln(abs(3*x - 3*t))`: its smooth factor a(x, t) with kernel = a(x, t) ln|x - t|.
fn kernel_l_1(_x: f64, _t: f64) -> f64 {
    0.1
}

/// Operator `l`, kernel `1/10*ln(abs(3*x - 3*t))`: its smooth part a(x, t) ln|c| with kernel = a(x, t) ln|c (x - t)|.
fn kernel_l_2(_x: f64, _t: f64) -> f64 {
    1.0986122886681096 * 0.1
}

/// Right side of equation 1: `exp(x) + sinh(x)/2 - atan(x)`.
fn rhs_1(x: f64) -> f64 {
    f64::exp(x) + f64::sinh(x) / 2.0 - f64::atan(x)
}

/// Right side of equation 2: `cos(x) + tanh(x)*acot(x + 1)`.
fn rhs_2(x: f64) -> f64 {
    f64::cos(x) + f64::tanh(x) * lambdamat::standalone::acot(x + 1.0)
}

/// Weight of output `P`: `1`.
fn weight_p_3(_x: f64) -> f64 {
    1.0
}

/// The operator system, which `input()` completes.
pub fn system() -> Result<CompiledSystem, PlanError> {
    let mut op_k = Operator::zero();
    op_k = op_k + Operator::identity();
    op_k = op_k + Operator::integral(Fixed { a: 0.0, b: 1.0 }, Smooth, kernel_k_2);
    let mut op_m = Operator::zero();
    op_m = op_m + Operator::integral(Fixed { a: 0.0, b: 1.0 }, Smooth, kernel_m);
    let mut op_l = Operator::zero();
    let limits = Fixed { a: 0.0, b: 1.0 };
    let term = Operator::integral(limits, lambdamat::standalone::Singularity::Log, kernel_l_1);
    op_l = op_l + term;
    let limits = Fixed { a: 0.0, b: 1.0 };
    let term = Operator::integral(
        limits,
        lambdamat::standalone::Singularity::Smooth,
        kernel_l_2,
    );
    op_l = op_l + term;
    let lhs_1 = vec![words(&[(&[0], "1")])?, words(&[(&[1], "1")])?];
    let equation_1 = CompiledEquation {
        lhs: lhs_1,
        rhs: Arc::new(rhs_1),
        rhs_text: "exp(x) + sinh(x)/2 - atan(x)".into(),
    };
    let lhs_2 = vec![words(&[(&[2], "1")])?, words(&[(&[], "1")])?];
    let equation_2 = CompiledEquation {
        lhs: lhs_2,
        rhs: Arc::new(rhs_2),
        rhs_text: "cos(x) + tanh(x)*acot(x + 1)".into(),
    };
    let output_1_term_1 = OutputTerm::Point {
        coeff: 1.0,
        at: 0.5,
        unknown: 0,
    };
    let output_1_term_2 = OutputTerm::Point {
        coeff: -2.0,
        at: 0.25,
        unknown: 1,
    };
    let output_1_term_3 = OutputTerm::Integral {
        coeff: 1.0,
        lower: 0.0,
        upper: 1.0,
        weight: Arc::new(weight_p_3),
        unknown: 0,
    };
    let output_1 = CompiledOutput {
        name: "P".into(),
        terms: vec![output_1_term_1, output_1_term_2, output_1_term_3],
    };
    let sys = CompiledSystem {
        symbols: vec!["k".into(), "m".into(), "l".into()],
        operators: vec![Some(op_k), Some(op_m), Some(op_l)],
        unknowns: vec!["u".into(), "v".into()],
        equations: vec![equation_1, equation_2],
        outputs: vec![output_1],
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
