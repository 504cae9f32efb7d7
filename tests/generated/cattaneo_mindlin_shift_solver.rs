//! A solver for `examples/contact/cattaneo_mindlin_shift.lmx`, written by lambdamat 0.1.0 (`lambdamat codegen`).
//! Do not edit: regenerate with `lambdamat codegen examples/contact/cattaneo_mindlin_shift.lmx -o FILE.rs`.
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
//! Slots: c.
//!
//! Derived equations per subinterval (`lambdamat reduce`; a model where a
//! relation is substituted: the solver keeps the subintervals coupled):
//! - on [0, c):
//!   ordered elimination: `k1 p = g1`
//!   commutative eliminant: `k1 p = [1 - x^2]`
//! - on [c, 1] with q = 1/2*p substituted:
//!   ordered elimination: `k1 p = g1`
//!   commutative eliminant: `k1 p = [1 - x^2]`
//!
//! The problem (parameters substituted):
//!
//! ```text
//! param mu = 1/2
//! param S = 1/4
//! scalar c in (0, 1)
//! operator k1 = int(x..1) t/sqrt(t^2 - x^2) dt
//! unknown p, q on [0, 1]
//! equation k1 p = 1 - x^2 on [0, 1]
//! equation k1 q = 1/4 on [0, c)
//! relation q = (1/2)*p on [c, 1]
//! inequality abs(q) <= (1/2)*p on [0, c)
//! singular q at (c)- ~ B*(x/sqrt(c^2 - (x^2)))
//! condition B = 0
//! output Q = 2*pi*int(0..1) x*q(x) dx
//! output P = 2*pi*int(0..1) x*p(x) dx
//! ```

// Literals are printed to read back bit for bit; some may look like
// named constants without being them.
#![allow(clippy::approx_constant)]

use std::sync::Arc;

use lambdamat::standalone::Limits::Upper;
use lambdamat::standalone::Singularity::AbelSqrt;
use lambdamat::standalone::{
    CompiledEquation, CompiledOutput, CompiledSystem, Operator, OutputTerm, PlanError, RFunc,
    RealFn, Scalar, SplitCondition, SplitContact, SplitInequality, SplitInput, SplitInterval,
    SplitKind, SplitLinTerm, SplitRelation, SplitSingular, real_pow, words,
};

/// Operator `k1`, kernel `t/sqrt(t^2 - x^2)`: its smooth factor a(x, t) with kernel = a(x, t)/√|t² - x²|.
fn kernel_k1(_x: f64, t: f64) -> f64 {
    t
}

/// Right side of equation 1: `1 - x^2`.
fn rhs_1(x: f64) -> f64 {
    1.0 - f64::powi(x, 2)
}

/// Right side of equation 2: `1/4`.
fn rhs_2(_x: f64) -> f64 {
    0.25
}

/// Weight of output `Q`: `x`.
fn weight_q(x: f64) -> f64 {
    x
}

/// Weight of output `P`: `x`.
fn weight_p(x: f64) -> f64 {
    x
}

/// The operator system, which `input()` completes.
pub fn system() -> Result<CompiledSystem, PlanError> {
    let mut op_k1 = Operator::zero();
    op_k1 = op_k1 + Operator::integral(Upper { b: 1.0 }, AbelSqrt, kernel_k1);
    let lhs_1 = vec![words(&[(&[0], "1")])?, words(&[])?];
    let equation_1 = CompiledEquation {
        lhs: lhs_1,
        rhs: Arc::new(rhs_1),
        rhs_text: "1 - x^2".into(),
    };
    let lhs_2 = vec![words(&[])?, words(&[(&[0], "1")])?];
    let equation_2 = CompiledEquation {
        lhs: lhs_2,
        rhs: Arc::new(rhs_2),
        rhs_text: "1/4".into(),
    };
    let output_1_term_1 = OutputTerm::Integral {
        coeff: std::f64::consts::TAU,
        lower: 0.0,
        upper: 1.0,
        weight: Arc::new(weight_q),
        unknown: 1,
    };
    let output_1 = CompiledOutput {
        name: "Q".into(),
        terms: vec![output_1_term_1],
    };
    let output_2_term_1 = OutputTerm::Integral {
        coeff: std::f64::consts::TAU,
        lower: 0.0,
        upper: 1.0,
        weight: Arc::new(weight_p),
        unknown: 0,
    };
    let output_2 = CompiledOutput {
        name: "P".into(),
        terms: vec![output_2_term_1],
    };
    let sys = CompiledSystem {
        symbols: vec!["k1".into()],
        operators: vec![Some(op_k1)],
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

/// A constant: `0`.
fn const_0(_v: &[f64], _x: f64) -> f64 {
    0.0
}

/// A constant: `1`.
fn const_1(_v: &[f64], _x: f64) -> f64 {
    1.0
}

/// Slot value: `c`.
fn slot_c(v: &[f64], _x: f64) -> f64 {
    v[0]
}

/// A constant: `1/2`.
fn const_1_2(_v: &[f64], _x: f64) -> f64 {
    0.5
}

/// Singular declaration 1, singular term: `x/sqrt(c^2 - (x^2))`.
fn singular_1_term(v: &[f64], x: f64) -> f64 {
    x / RFunc::Sqrt.apply(real_pow(v[0], 2.0) - real_pow(x, 2.0))
}

/// The split-domain problem, ready for `lambdamat::standalone::split_solver_main`.
pub fn input() -> Result<SplitInput, PlanError> {
    let contact = SplitContact {
        scalars: vec![Scalar {
            name: "c".into(),
            range: (0.0, 1.0),
        }],
        reals: Vec::new(),
        unknown_domains: vec![
            Some(SplitInterval {
                lo: RealFn::new(const_0),
                hi: RealFn::new(const_1),
                lo_closed: true,
                hi_closed: true,
            }),
            Some(SplitInterval {
                lo: RealFn::new(const_0),
                hi: RealFn::new(const_1),
                lo_closed: true,
                hi_closed: true,
            }),
        ],
        equation_domains: vec![
            Some(SplitInterval {
                lo: RealFn::new(const_0),
                hi: RealFn::new(const_1),
                lo_closed: true,
                hi_closed: true,
            }),
            Some(SplitInterval {
                lo: RealFn::new(const_0),
                hi: RealFn::new(slot_c),
                lo_closed: true,
                hi_closed: false,
            }),
        ],
        rhs: Vec::new(),
        relations: vec![SplitRelation {
            unknown: 1,
            coeff: RealFn::new(const_1_2),
            other: 0,
            domain: SplitInterval {
                lo: RealFn::new(slot_c),
                hi: RealFn::new(const_1),
                lo_closed: true,
                hi_closed: true,
            },
        }],
        inequalities: vec![SplitInequality {
            abs: true,
            lhs: vec![SplitLinTerm {
                coeff: RealFn::new(const_1),
                unknown: Some(1),
            }],
            rhs: vec![SplitLinTerm {
                coeff: RealFn::new(const_1_2),
                unknown: Some(0),
            }],
            domain: SplitInterval {
                lo: RealFn::new(const_0),
                hi: RealFn::new(slot_c),
                lo_closed: true,
                hi_closed: false,
            },
            text: "abs(q) <= (1/2)*p".into(),
        }],
        singulars: vec![SplitSingular {
            unknown: 1,
            at: RealFn::new(slot_c),
            side: -1,
            kind: SplitKind::Term {
                coefficient: 0,
                func: RealFn::new(singular_1_term),
            },
        }],
        coefficients: vec!["B".into()],
        conditions: vec![SplitCondition {
            coefficient: 0,
            value: RealFn::new(const_0),
        }],
        estimates: vec![None],
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
