//! A solver for `examples/contact/flat_punch.lmx`, written by lambdamat 0.1.0 (`lambdamat codegen`).
//! Do not edit: regenerate with `lambdamat codegen examples/contact/flat_punch.lmx -o FILE.rs`.
//!
//! A split-domain (contact) problem. Kernels, right sides and output
//! weights are Rust functions of `x` (and `t`); interval ends, relation
//! factors, singular points, exponents and terms, condition values and
//! real parameters are Rust functions of the slot values `v` (the unknown
//! scalars, then the real parameters) and `x`. `input()` collects them and
//! `main()` solves through lambdamat's split-domain solver
//! (`lambdamat::standalone::split_solver_main`): the scalars' root solve,
//! refinement to the tolerance, and the error estimates. Parameters are
//! those of the regenerating command (`--set` there).
//!
//! Derived equations per subinterval (`lambdamat reduce`; a model where a
//! relation is substituted: the solver keeps the subintervals coupled):
//! - on [0, 1]:
//!   ordered elimination: `k1 p = g1`
//!   commutative eliminant: `k1 p = [1/3]`
//!
//! The problem (parameters substituted):
//!
//! ```text
//! param delta = 1/3
//! operator k1 = int(x..1) t/sqrt(t^2 - x^2) dt
//! unknown p on [0, 1]
//! equation k1 p = 1/3 on [0, 1]
//! inequality 0 <= p on [0, 1]
//! singular p at (1) ~ (1 - x)^(-1/2)
//! output P = 2*pi*int(0..1) x*p(x) dx
//! ```

// Literals are printed to read back bit for bit; some may look like
// named constants without being them.
#![allow(clippy::approx_constant)]

use std::sync::Arc;

use lambdamat::standalone::Limits::Upper;
use lambdamat::standalone::Singularity::AbelSqrt;
use lambdamat::standalone::{
    CompiledEquation, CompiledOutput, CompiledSystem, Operator, OutputTerm, PlanError, RealFn,
    SplitContact, SplitInequality, SplitInput, SplitInterval, SplitKind, SplitLinTerm,
    SplitSingular, words,
};

/// Operator `k1`, kernel `t/sqrt(t^2 - x^2)`: its smooth factor a(x, t) with kernel = a(x, t)/√|t² - x²|.
fn kernel_k1(_x: f64, t: f64) -> f64 {
    t
}

/// Right side of equation 1: `1/3`.
fn rhs_1(_x: f64) -> f64 {
    0.3333333333333333
}

/// Weight of output `P`: `x`.
fn weight_p(x: f64) -> f64 {
    x
}

/// The operator system, which `input()` completes.
pub fn system() -> Result<CompiledSystem, PlanError> {
    let mut op_k1 = Operator::zero();
    op_k1 = op_k1 + Operator::integral(Upper { b: 1.0 }, AbelSqrt, kernel_k1);
    let lhs_1 = vec![words(&[(&[0], "1")])?];
    let equation_1 = CompiledEquation {
        lhs: lhs_1,
        rhs: Arc::new(rhs_1),
        rhs_text: "1/3".into(),
    };
    let output_1_term_1 = OutputTerm::Integral {
        coeff: std::f64::consts::TAU,
        lower: 0.0,
        upper: 1.0,
        weight: Arc::new(weight_p),
        unknown: 0,
    };
    let output_1 = CompiledOutput {
        name: "P".into(),
        terms: vec![output_1_term_1],
    };
    let sys = CompiledSystem {
        symbols: vec!["k1".into()],
        operators: vec![Some(op_k1)],
        unknowns: vec!["p".into()],
        equations: vec![equation_1],
        outputs: vec![output_1],
        conditions: Vec::new(),
        target: 0,
        principal: None,
        derived_pivots: Some(Vec::new()),
        domain: (0.0, 1.0),
        interior: Vec::new(),
        features: Vec::new(),
    };
    sys.check()?;
    Ok(sys)
}

/// A constant: `0`.
fn const_0(_v: &[f64], _x: f64) -> f64 {
    0.0
}

/// A constant: `1`.
fn const_1(_v: &[f64], _x: f64) -> f64 {
    1.0
}

/// A constant: `-1/2`.
fn const_minus_1_2(_v: &[f64], _x: f64) -> f64 {
    -0.5
}

/// The split-domain problem, ready for `lambdamat::standalone::split_solver_main`.
pub fn input() -> Result<SplitInput, PlanError> {
    let contact = SplitContact {
        scalars: Vec::new(),
        reals: Vec::new(),
        unknown_domains: vec![Some(SplitInterval {
            lo: RealFn::new(const_0),
            hi: RealFn::new(const_1),
            lo_closed: true,
            hi_closed: true,
        })],
        equation_domains: vec![Some(SplitInterval {
            lo: RealFn::new(const_0),
            hi: RealFn::new(const_1),
            lo_closed: true,
            hi_closed: true,
        })],
        rhs: Vec::new(),
        relations: Vec::new(),
        inequalities: vec![SplitInequality {
            abs: false,
            lhs: vec![SplitLinTerm {
                coeff: RealFn::new(const_0),
                unknown: None,
            }],
            rhs: vec![SplitLinTerm {
                coeff: RealFn::new(const_1),
                unknown: Some(0),
            }],
            domain: SplitInterval {
                lo: RealFn::new(const_0),
                hi: RealFn::new(const_1),
                lo_closed: true,
                hi_closed: true,
            },
            text: "0 <= p".into(),
        }],
        singulars: vec![SplitSingular {
            unknown: 0,
            at: RealFn::new(const_1),
            side: 0,
            kind: SplitKind::Weight {
                exponent: RealFn::new(const_minus_1_2),
            },
        }],
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
