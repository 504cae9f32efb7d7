//! A solver for `examples/contact/sphere_load_range.lmx`, written by lambdamat 0.1.0 (`lambdamat codegen`).
//! Do not edit: regenerate with `lambdamat codegen examples/contact/sphere_load_range.lmx -o FILE.rs`.
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
//! Slots: a, delta.
//!
//! Derived equations per subinterval (`lambdamat reduce`; a model where a
//! relation is substituted: the solver keeps the subintervals coupled):
//! - on [0, a):
//!   ordered elimination: `k1 p = g1`
//!   commutative eliminant: `k1 p = [delta - (x^2)]`
//! - on [a, 2] with p = 0*p substituted:
//!   the file has no equations, so there is nothing to reduce
//!
//! The problem (parameters substituted):
//!
//! ```text
//! param P0 = 1
//! scalar a in (0, 2)
//! scalar delta in (0, 4)
//! operator k1 = int(x..a) t/sqrt(t^2 - x^2) dt
//! unknown p on [0, 2]
//! equation k1 p = 0 on [0, a)
//! relation p = 0 on [a, 2]
//! inequality 0 <= p on [0, a)
//! singular p at (a)- ~ B*(x/sqrt(a^2 - (x^2)))
//! condition B = 0
//! output P = int(0..a) 2*pi*x*p(x) dx
//! output P_half = int(0..a/2) 2*pi*x*p(x) dx
//! condition int(0..a) 2*pi*x*p(x) dx = 1
//! ```

// Literals are printed to read back bit for bit; some may look like
// named constants without being them.
#![allow(clippy::approx_constant)]

use std::sync::Arc;

use lambdamat::standalone::Limits::Upper;
use lambdamat::standalone::Singularity::AbelSqrt;
use lambdamat::standalone::{
    CompiledCondition, CompiledEquation, CompiledOutput, CompiledSystem, EndSite, Operator,
    OutputTerm, PlanError, RFunc, RealFn, Scalar, SplitCondition, SplitContact, SplitEnd,
    SplitInequality, SplitInput, SplitInterval, SplitKind, SplitLinTerm, SplitRelation,
    SplitSingular, real_pow, words,
};

/// Operator `k1`, kernel `t/sqrt(t^2 - x^2)`: its smooth factor a(x, t) with kernel = a(x, t)/√|t² - x²|.
fn kernel_k1(_x: f64, t: f64) -> f64 {
    t
}

/// Right side of equation 1: `delta - (x^2)`; it uses an unknown scalar, so the operator system holds 0 here and the split input evaluates it.
fn rhs_1(_x: f64) -> f64 {
    0.0
}

/// Weight of output `P`: `2*pi*x`.
fn weight_p(x: f64) -> f64 {
    std::f64::consts::TAU * x
}

/// Weight of output `P_half`: `2*pi*x`.
fn weight_p_half(x: f64) -> f64 {
    std::f64::consts::TAU * x
}

/// Weight of side condition 1: `2*pi*x`.
fn condition_weight_1(x: f64) -> f64 {
    std::f64::consts::TAU * x
}

/// The operator system, which `input()` completes.
pub fn system() -> Result<CompiledSystem, PlanError> {
    let mut op_k1 = Operator::zero();
    op_k1 = op_k1 + Operator::integral(Upper { b: 2.0 }, AbelSqrt, kernel_k1);
    let lhs_1 = vec![words(&[(&[0], "1")])?];
    let equation_1 = CompiledEquation {
        lhs: lhs_1,
        rhs: Arc::new(rhs_1),
        rhs_text: "delta - (x^2)".into(),
    };
    let output_1_term_1 = OutputTerm::Integral {
        coeff: 1.0,
        lower: 0.0,
        upper: 2.0,
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
        upper: 2.0,
        weight: Arc::new(weight_p_half),
        unknown: 0,
    };
    let output_2 = CompiledOutput {
        name: "P_half".into(),
        terms: vec![output_2_term_1],
    };
    let condition_1_term_1 = OutputTerm::Integral {
        coeff: 1.0,
        lower: 0.0,
        upper: 2.0,
        weight: Arc::new(condition_weight_1),
        unknown: 0,
    };
    let condition_1 = CompiledCondition {
        terms: vec![condition_1_term_1],
        value: 1.0,
        text: "side condition 1 (= 1)".into(),
    };
    let sys = CompiledSystem {
        symbols: vec!["k1".into()],
        operators: vec![Some(op_k1)],
        unknowns: vec!["p".into()],
        equations: vec![equation_1],
        outputs: vec![output_1, output_2],
        conditions: vec![condition_1],
        target: 0,
        principal: None,
        derived_pivots: Some(Vec::new()),
        domain: (0.0, 2.0),
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

/// A constant: `2`.
fn const_2(_v: &[f64], _x: f64) -> f64 {
    2.0
}

/// Slot value: `a`.
fn slot_a(v: &[f64], _x: f64) -> f64 {
    v[0]
}

/// Right side of equation 1 (it uses a scalar): `delta - (x^2)`: `delta - (x^2)`.
fn equation_1_rhs(v: &[f64], x: f64) -> f64 {
    v[1] - real_pow(x, 2.0)
}

/// A constant: `1`.
fn const_1(_v: &[f64], _x: f64) -> f64 {
    1.0
}

/// Singular declaration 1, singular term: `x/sqrt(a^2 - (x^2))`.
fn singular_1_term(v: &[f64], x: f64) -> f64 {
    x / RFunc::Sqrt.apply(real_pow(v[0], 2.0) - real_pow(x, 2.0))
}

/// Integration limit or point-value position 4 (it uses a scalar): `a/2`.
fn end_4(v: &[f64], _x: f64) -> f64 {
    v[0] / 2.0
}

/// The split-domain problem, ready for `lambdamat::standalone::split_solver_main`.
pub fn input() -> Result<SplitInput, PlanError> {
    let contact = SplitContact {
        scalars: vec![
            Scalar {
                name: "a".into(),
                range: (0.0, 2.0),
            },
            Scalar {
                name: "delta".into(),
                range: (0.0, 4.0),
            },
        ],
        reals: Vec::new(),
        unknown_domains: vec![Some(SplitInterval {
            lo: RealFn::new(const_0),
            hi: RealFn::new(const_2),
            lo_closed: true,
            hi_closed: true,
        })],
        equation_domains: vec![Some(SplitInterval {
            lo: RealFn::new(const_0),
            hi: RealFn::new(slot_a),
            lo_closed: true,
            hi_closed: false,
        })],
        rhs: vec![Some(RealFn::new(equation_1_rhs))],
        relations: vec![SplitRelation {
            unknown: 0,
            coeff: RealFn::new(const_0),
            other: 0,
            domain: SplitInterval {
                lo: RealFn::new(slot_a),
                hi: RealFn::new(const_2),
                lo_closed: true,
                hi_closed: true,
            },
        }],
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
                hi: RealFn::new(slot_a),
                lo_closed: true,
                hi_closed: false,
            },
            text: "0 <= p".into(),
        }],
        singulars: vec![SplitSingular {
            unknown: 0,
            at: RealFn::new(slot_a),
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
        estimates: vec![None, None],
        ends: vec![
            SplitEnd {
                site: EndSite::Operator { symbol: 0, term: 0 },
                upper: true,
                value: RealFn::new(slot_a),
            },
            SplitEnd {
                site: EndSite::Condition { condition: 0, term: 0 },
                upper: true,
                value: RealFn::new(slot_a),
            },
            SplitEnd {
                site: EndSite::Output { output: 0, term: 0 },
                upper: true,
                value: RealFn::new(slot_a),
            },
            SplitEnd {
                site: EndSite::Output { output: 1, term: 0 },
                upper: true,
                value: RealFn::new(end_4),
            },
        ],
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
