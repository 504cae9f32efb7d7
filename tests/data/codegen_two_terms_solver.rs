//! A solver for `examples/two_terms.lmx`, written by lambdamat 0.1.0 (`lambdamat codegen`).
//! Do not edit: regenerate with `lambdamat codegen examples/two_terms.lmx -o FILE.rs`.
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
//! - on [0, 1):
//!   ordered elimination: `k p = g1`
//!   commutative eliminant: `k p = [2*sqrt(1 - x) + 1/2*pi + 1/3*(gamma(3/4)*gamma(1/2)/gamma(5/4))*(1 - x)^(1/4)]`
//!
//! The problem (parameters substituted):
//!
//! ```text
//! param A0 = 1/2
//! param B0 = 1/3
//! operator k = int(x..1) 1/sqrt(t - x) dt
//! unknown p on [0, 1]
//! equation k p = 2*sqrt(1 - x) + 1/2*pi + 1/3*(gamma(3/4)*gamma(1/2)/gamma(5/4))*(1 - x)^(1/4) on [0, 1)
//! singular p at (1)- ~ A*(1/sqrt(1 - x))
//! singular p at (1)- ~ B*((1 - x)^(-1/4))
//! output P = int(0..1) p(x) dx
//! solve for p
//! ```

// Literals are printed to read back bit for bit; some may look like
// named constants without being them.
#![allow(clippy::approx_constant)]

use std::sync::Arc;

use lambdamat::standalone::Limits::Upper;
use lambdamat::standalone::{
    CompiledEquation, CompiledOutput, CompiledSystem, Operator, OutputTerm, PlanError, RFunc,
    RealFn, SplitContact, SplitInput, SplitInterval, SplitKind, SplitSingular, real_pow, words,
};

/// Operator `k`, kernel `1/sqrt(t - x)`: its smooth factor a(x, t) with kernel = a(x, t) |x - t|^(-β).
fn kernel_k(_x: f64, _t: f64) -> f64 {
    1.0
}

/// Right side of equation 1: `2*sqrt(1 - x) + 1/2*pi + 1/3*(gamma(3/4)*gamma(1/2)/gamma(5/4))*(1 - x)^(1/4)`.
fn rhs_1(x: f64) -> f64 {
    let v1 = 2.0 * f64::sqrt(1.0 - x) + std::f64::consts::FRAC_PI_2;
    v1 + 0.7987601564903943 * f64::powf(1.0 - x, 0.25)
}

/// Weight of output `P`: `1`.
fn weight_p(_x: f64) -> f64 {
    1.0
}

/// The operator system, which `input()` completes.
pub fn system() -> Result<CompiledSystem, PlanError> {
    let mut op_k = Operator::zero();
    let limits = Upper { b: 1.0 };
    let term = Operator::integral(
        limits,
        lambdamat::standalone::Singularity::Power { beta: 0.5 },
        kernel_k,
    );
    op_k = op_k + term;
    let lhs_1 = vec![words(&[(&[0], "1")])?];
    let equation_1 = CompiledEquation {
        lhs: lhs_1,
        rhs: Arc::new(rhs_1),
        rhs_text: "2*sqrt(1 - x) + 1/2*pi + 1/3*(gamma(3/4)*gamma(1/2)/gamma(5/4))*(1 - x)^(1/4)".into(),
    };
    let output_1_term_1 = OutputTerm::Integral {
        coeff: 1.0,
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
        symbols: vec!["k".into()],
        operators: vec![Some(op_k)],
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

/// Singular declaration 1, singular term: `1/sqrt(1 - x)`.
fn singular_1_term(_v: &[f64], x: f64) -> f64 {
    1.0 / RFunc::Sqrt.apply(1.0 - x)
}

/// Singular declaration 2, singular term: `(1 - x)^(-1/4)`.
fn singular_2_term(_v: &[f64], x: f64) -> f64 {
    real_pow(1.0 - x, -0.25)
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
            hi_closed: false,
        })],
        rhs: Vec::new(),
        relations: Vec::new(),
        inequalities: Vec::new(),
        singulars: vec![
            SplitSingular {
                unknown: 0,
                at: RealFn::new(const_1),
                side: -1,
                kind: SplitKind::Term {
                    coefficient: 0,
                    func: RealFn::new(singular_1_term),
                },
            },
            SplitSingular {
                unknown: 0,
                at: RealFn::new(const_1),
                side: -1,
                kind: SplitKind::Term {
                    coefficient: 1,
                    func: RealFn::new(singular_2_term),
                },
            },
        ],
        coefficients: vec!["A".into(), "B".into()],
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
