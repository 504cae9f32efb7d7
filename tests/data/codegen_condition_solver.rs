//! A solver for `tests/data/codegen_condition.lmx`, written by lambdamat 0.1.0 (`lambdamat codegen`).
//! Do not edit: regenerate with `lambdamat codegen tests/data/codegen_condition.lmx -o FILE.rs`.
//!
//! Kernels, multipliers, right sides and output weights are the Rust
//! functions below; `system()` collects them, `input()` makes them a
//! problem without breakpoints, and `main()` solves it through
//! lambdamat's solver (`lambdamat::standalone::split_solver_main`):
//! assembly, refinement to the tolerance, and the error estimates.
//! Unknowns on [-1, 1]; eliminations solve for `f`.
//!
//! Derived equations for `f` (`lambdamat reduce`):
//!
//! - ordered elimination, exact (`--method ordered`; gj is
//!   the right side of equation j):
//!   `h f = g1`
//!   pivots: none (one equation)
//! - commutative eliminant, the seed's model (`--method commutative`):
//!   `h f = [1]`
//!   commuted pairs: none
//! - with its 1 side condition(s) the system is solved as one least-squares
//!   system of equations and conditions (`--method coupled`; the eliminations
//!   refuse them).
//!
//! The system (parameters substituted):
//!
//! ```text
//! operator h = pv int(-1..1) 1/pi*(1/(t - x)) dt
//! unknown f on [-1, 1]
//! equation h f = 1
//! output V = f(1/2)
//! condition int(-1..1) f(x) dx + -1*f(0) + f(0) = 2
//! ```

// Literals are printed to read back bit for bit; some may look like
// named constants without being them.
#![allow(clippy::approx_constant)]

use std::sync::Arc;

use lambdamat::standalone::Limits::Fixed;
use lambdamat::standalone::{
    CompiledCondition, CompiledEquation, CompiledOutput, CompiledSystem, Operator, OutputTerm,
    PlanError, RealFn, SplitContact, SplitInput, SplitInterval, words,
};

/// Operator `h`, kernel `1/pi*(1/(t - x))`: its smooth factor a(x, t) with kernel = a(x, t)/(t - x).
fn kernel_h(_x: f64, _t: f64) -> f64 {
    1.0 * (1.0 / std::f64::consts::PI) * 1.0
}

/// Right side of equation 1: `1`.
fn rhs_1(_x: f64) -> f64 {
    1.0
}

/// Weight of side condition 1: `1`.
fn condition_weight_1_1(_x: f64) -> f64 {
    1.0
}

/// The operator system, which `input()` completes.
pub fn system() -> Result<CompiledSystem, PlanError> {
    let mut op_h = Operator::zero();
    let limits = Fixed { a: -1.0, b: 1.0 };
    let term = Operator::integral(limits, lambdamat::standalone::Singularity::Cauchy, kernel_h);
    op_h = op_h + term;
    let lhs_1 = vec![words(&[(&[0], "1")])?];
    let equation_1 = CompiledEquation {
        lhs: lhs_1,
        rhs: Arc::new(rhs_1),
        rhs_text: "1".into(),
    };
    let output_1_term_1 = OutputTerm::Point {
        coeff: 1.0,
        at: 0.5,
        unknown: 0,
    };
    let output_1 = CompiledOutput {
        name: "V".into(),
        terms: vec![output_1_term_1],
    };
    let condition_1_term_1 = OutputTerm::Integral {
        coeff: 1.0,
        lower: -1.0,
        upper: 1.0,
        weight: Arc::new(condition_weight_1_1),
        unknown: 0,
    };
    let condition_1_term_2 = OutputTerm::Point {
        coeff: -1.0,
        at: 0.0,
        unknown: 0,
    };
    let condition_1_term_3 = OutputTerm::Point {
        coeff: 1.0,
        at: 0.0,
        unknown: 0,
    };
    let condition_1 = CompiledCondition {
        terms: vec![condition_1_term_1, condition_1_term_2, condition_1_term_3],
        value: 2.0,
        text: "side condition 1 (= 2)".into(),
    };
    let sys = CompiledSystem {
        symbols: vec!["h".into()],
        operators: vec![Some(op_h)],
        unknowns: vec!["f".into()],
        equations: vec![equation_1],
        outputs: vec![output_1],
        conditions: vec![condition_1],
        target: 0,
        principal: None,
        derived_pivots: Some(Vec::new()),
        domain: (-1.0, 1.0),
        interior: Vec::new(),
        features: Vec::new(),
    };
    sys.check()?;
    Ok(sys)
}

/// A constant: `-1`.
fn const_minus_1(_v: &[f64], _x: f64) -> f64 {
    -1.0
}

/// A constant: `1`.
fn const_1(_v: &[f64], _x: f64) -> f64 {
    1.0
}

/// The split-domain problem, ready for `lambdamat::standalone::split_solver_main`.
pub fn input() -> Result<SplitInput, PlanError> {
    let contact = SplitContact {
        scalars: Vec::new(),
        reals: Vec::new(),
        unknown_domains: vec![Some(SplitInterval {
            lo: RealFn::new(const_minus_1),
            hi: RealFn::new(const_1),
            lo_closed: true,
            hi_closed: true,
        })],
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
