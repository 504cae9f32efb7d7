//! A solver for `examples/hertz.lmx`, written by lambdamat 0.1.0 (`lambdamat codegen`).
//! Do not edit: regenerate with `lambdamat codegen examples/hertz.lmx -o FILE.rs`.
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
//! Slots: c, alpha.
//!
//! Derived equations per subinterval (`lambdamat reduce`; a model where a
//! relation is substituted: the solver keeps the subintervals coupled):
//! - on [0, c):
//!   ordered elimination: `(k1 - k2 k4^-1 k3) p = g1 - k2 k4^-1 g2`
//!   commutative eliminant: `(k1*k4 - k2*k3) p = k4[1] - k2[0]`
//! - on [c, 1] with q = 1801/10000*p substituted:
//!   ordered elimination: `(k1 + 1801/10000 k2) p = g1`
//!   commutative eliminant: `(k1 + 1801/10000*k2) p = [1]`
//!
//! The problem (parameters substituted):
//!
//! ```text
//! param nu = 1/4
//! param mu = 1801/10000
//! param gamma = 1/3
//! scalar c in (0, 1) ~ (4*((8/9)^(1 - (2*ln(2)))))*exp(ln(8/9)/(1801/30000))
//! param alpha = acot(1801/30000)/pi
//! operator k1 = int(x..1) t/sqrt(t^2 - x^2) dt
//! operator k2 = int(0..1) -1/3 dt + int(0..x) 1/3*(x/sqrt(x^2 - t^2)) dt
//! operator k3 = int(0..x) 1/3*(t/sqrt(x^2 - t^2)) dt
//! operator k4 = int(x..1) -(x/sqrt(t^2 - x^2)) dt
//! principal k4
//! unknown p, q on [0, 1]
//! equation k1 p + k2 q = 1 on [0, 1]
//! equation k3 p + k4 q = 0 on [0, c)
//! relation q = (1801/10000)*p on [c, 1]
//! inequality abs(q) <= (1801/10000)*p on [0, c)
//! singular p at (1) ~ (1 - x)^(-alpha)
//! singular q at (c)- ~ B*(x/sqrt(c^2 - (x^2)))
//! condition B = 0
//! output P = pi/2*int(0..1) x*p(x) dx
//! output P_shear = (1) + 1/3*int(0..1) x^2/(1 + sqrt(1 - x^2))*q(x) dx
//! solve for p
//! ```

// Literals are printed to read back bit for bit; some may look like
// named constants without being them.
#![allow(clippy::approx_constant)]

use std::sync::Arc;

use lambdamat::standalone::Limits::{Fixed, Lower, Upper};
use lambdamat::standalone::Singularity::{AbelSqrt, Smooth};
use lambdamat::standalone::{
    CompiledEquation, CompiledOutput, CompiledSystem, Operator, OutputTerm, PlanError, RFunc,
    RealFn, Scalar, SplitCondition, SplitContact, SplitInequality, SplitInput, SplitInterval,
    SplitKind, SplitLinTerm, SplitRelation, SplitSingular, real_pow, words,
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

/// Right side of equation 1: `1`.
fn rhs_1(_x: f64) -> f64 {
    1.0
}

/// Right side of equation 2: `0`.
fn rhs_2(_x: f64) -> f64 {
    0.0
}

/// Weight of output `P`: `x`.
fn weight_p(x: f64) -> f64 {
    x
}

/// Weight of output `P_shear`: `x^2/(1 + sqrt(1 - x^2))`.
fn weight_p_shear_2(x: f64) -> f64 {
    f64::powi(x, 2) / (1.0 + f64::sqrt(1.0 - f64::powi(x, 2)))
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
        rhs_text: "1".into(),
    };
    let lhs_2 = vec![words(&[(&[2], "1")])?, words(&[(&[3], "1")])?];
    let equation_2 = CompiledEquation {
        lhs: lhs_2,
        rhs: Arc::new(rhs_2),
        rhs_text: "0".into(),
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
    let output_2_term_1 = OutputTerm::Constant(1.0);
    let output_2_term_2 = OutputTerm::Integral {
        coeff: 0.3333333333333333,
        lower: 0.0,
        upper: 1.0,
        weight: Arc::new(weight_p_shear_2),
        unknown: 1,
    };
    let output_2 = CompiledOutput {
        name: "P_shear".into(),
        terms: vec![output_2_term_1, output_2_term_2],
    };
    let sys = CompiledSystem {
        symbols: vec!["k1".into(), "k2".into(), "k3".into(), "k4".into()],
        operators: vec![Some(op_k1), Some(op_k2), Some(op_k3), Some(op_k4)],
        unknowns: vec!["p".into(), "q".into()],
        equations: vec![equation_1, equation_2],
        outputs: vec![output_1, output_2],
        conditions: Vec::new(),
        target: 0,
        principal: Some(3),
        derived_pivots: Some(vec![(1, 1)]),
        domain: (0.0, 1.0),
        interior: Vec::new(),
        features: Vec::new(),
    };
    sys.check()?;
    Ok(sys)
}

/// Real parameter `alpha`: `acot(1801/30000)/pi`.
fn real_alpha(_v: &[f64], _x: f64) -> f64 {
    RFunc::Acot.apply(0.060033333333333334) / std::f64::consts::PI
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

/// A constant: `1801/10000`.
fn const_1801_10000(_v: &[f64], _x: f64) -> f64 {
    0.1801
}

/// Singular declaration 1, weight exponent: `-alpha`.
fn singular_1_exponent(v: &[f64], _x: f64) -> f64 {
    -v[1]
}

/// Singular declaration 2, singular term: `x/sqrt(c^2 - (x^2))`.
fn singular_2_term(v: &[f64], x: f64) -> f64 {
    x / RFunc::Sqrt.apply(real_pow(v[0], 2.0) - real_pow(x, 2.0))
}

/// Asymptotic estimate of the scalar `c`: `(4*((8/9)^(1 - (2*ln(2)))))*exp(ln(8/9)/(1801/30000))`.
fn estimate_c(_v: &[f64], _x: f64) -> f64 {
    let e0 = 4.0 * real_pow(0.8888888888888888, 1.0 - 2.0 * RFunc::Ln.apply(2.0));
    let e1 = RFunc::Exp.apply(RFunc::Ln.apply(0.8888888888888888) / 0.060033333333333334);
    e0 * e1
}

/// The split-domain problem, ready for `lambdamat::standalone::split_solver_main`.
pub fn input() -> Result<SplitInput, PlanError> {
    let contact = SplitContact {
        scalars: vec![Scalar {
            name: "c".into(),
            range: (0.0, 1.0),
        }],
        reals: vec![RealFn::new(real_alpha)],
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
            coeff: RealFn::new(const_1801_10000),
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
                coeff: RealFn::new(const_1801_10000),
                unknown: Some(0),
            }],
            domain: SplitInterval {
                lo: RealFn::new(const_0),
                hi: RealFn::new(slot_c),
                lo_closed: true,
                hi_closed: false,
            },
            text: "abs(q) <= (1801/10000)*p".into(),
        }],
        singulars: vec![
            SplitSingular {
                unknown: 0,
                at: RealFn::new(const_1),
                side: 0,
                kind: SplitKind::Weight {
                    exponent: RealFn::new(singular_1_exponent),
                },
            },
            SplitSingular {
                unknown: 1,
                at: RealFn::new(slot_c),
                side: -1,
                kind: SplitKind::Term {
                    coefficient: 0,
                    func: RealFn::new(singular_2_term),
                },
            },
        ],
        coefficients: vec!["B".into()],
        conditions: vec![SplitCondition {
            coefficient: 0,
            value: RealFn::new(const_0),
        }],
        estimates: vec![Some(RealFn::new(estimate_c))],
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
