//! A solver for `tests/data/codegen_terms.lmx`, written by lambdamat 0.1.0 (`lambdamat codegen`).
//! Do not edit: regenerate with `lambdamat codegen tests/data/codegen_terms.lmx -o FILE.rs`.
//!
//! Kernels, multipliers, right sides and output weights are the Rust
//! functions below; `system()` collects them, `input()` makes them a
//! problem without breakpoints, and `main()` solves it through
//! lambdamat's solver (`lambdamat::standalone::split_solver_main`):
//! assembly, refinement to the tolerance, and the error estimates.
//! Unknowns on [0, 1]; eliminations solve for `v`.
//!
//! Derived equations for `v` (`lambdamat reduce`):
//!
//! - ordered elimination, exact (`--method ordered`; gj is
//!   the right side of equation j):
//!   `(h - m g^-1 h - m g^-1 - k g^-1 h - k g^-1) v = g1 + (-m g^-1 - k g^-1) g2`
//!   pivots: u from equation 2 (pivot g)
//! - commutative eliminant, the seed's model (`--method commutative`):
//!   `(m*h + m + k*h + k - h*g) v = -g[1 + x] + (m + k)[x^2 - pi/8]`
//!   commuted pairs: (m, g), (k, g)
//!
//! The system (parameters substituted):
//!
//! ```text
//! param a = 1/2
//! operator m = 3*id + id + x*id
//! operator k = int(1..0) exp(x*t)/4 dt
//! operator h = int(0..1/2) x*t dt
//! operator g = int(0..x) -1/5*(t/sqrt(x^2 - t^2)) dt
//! unknown u, v
//! equation (m + k) u + h v = 1 + x
//! equation g u + (h + 1) v = x^2 - pi/8
//! output U = (1) + int(0..1) u(x) dx
//! output V = pi*int(0..1/2) x^2*v(x) dx
//! solve for v
//! ```

// Literals are printed to read back bit for bit; some may look like
// named constants without being them.
#![allow(clippy::approx_constant)]

use std::sync::Arc;

use lambdamat::standalone::Limits::{Fixed, Lower};
use lambdamat::standalone::Singularity::{AbelSqrt, Smooth};
use lambdamat::standalone::{
    CompiledEquation, CompiledOutput, CompiledSystem, Operator, OutputTerm, PlanError,
    SplitContact, SplitInput, words,
};

/// Multiplier of operator `m`: `x`.
fn multiplier_m_3(x: f64) -> f64 {
    x
}

/// Operator `k`, kernel `exp(x*t)/4`: a smooth kernel.
fn kernel_k(x: f64, t: f64) -> f64 {
    f64::exp(x * t) / 4.0
}

/// Operator `h`, kernel `x*t`: a smooth kernel.
fn kernel_h(x: f64, t: f64) -> f64 {
    x * t
}

/// Operator `g`, kernel `-1/5*(t/sqrt(x^2 - t^2))`: its smooth factor a(x, t) with kernel = a(x, t)/√|t² - x²|.
fn kernel_g(_x: f64, t: f64) -> f64 {
    -0.2 * t
}

/// Right side of equation 1: `1 + x`.
fn rhs_1(x: f64) -> f64 {
    1.0 + x
}

/// Right side of equation 2: `x^2 - pi/8`.
fn rhs_2(x: f64) -> f64 {
    f64::powi(x, 2) - std::f64::consts::FRAC_PI_8
}

/// Weight of output `U`: `1`.
fn weight_u_2(_x: f64) -> f64 {
    1.0
}

/// Weight of output `V`: `x^2`.
fn weight_v(x: f64) -> f64 {
    f64::powi(x, 2)
}

/// The operator system, which `input()` completes.
pub fn system() -> Result<CompiledSystem, PlanError> {
    let mut op_m = Operator::zero();
    op_m = op_m + Operator::identity().scaled(3.0);
    op_m = op_m + Operator::identity();
    op_m = op_m + Operator::multiply(multiplier_m_3);
    let mut op_k = Operator::zero();
    let limits = Fixed { a: 0.0, b: 1.0 };
    let term = Operator::integral(limits, Smooth, kernel_k);
    op_k = op_k + term.scaled(-1.0);
    let mut op_h = Operator::zero();
    op_h = op_h + Operator::integral(Fixed { a: 0.0, b: 0.5 }, Smooth, kernel_h);
    let mut op_g = Operator::zero();
    op_g = op_g + Operator::integral(Lower { a: 0.0 }, AbelSqrt, kernel_g);
    let lhs_1 = vec![words(&[(&[0], "1"), (&[1], "1")])?, words(&[(&[2], "1")])?];
    let equation_1 = CompiledEquation {
        lhs: lhs_1,
        rhs: Arc::new(rhs_1),
        rhs_text: "1 + x".into(),
    };
    let lhs_2 = vec![words(&[(&[3], "1")])?, words(&[(&[2], "1"), (&[], "1")])?];
    let equation_2 = CompiledEquation {
        lhs: lhs_2,
        rhs: Arc::new(rhs_2),
        rhs_text: "x^2 - pi/8".into(),
    };
    let output_1_term_1 = OutputTerm::Constant(1.0);
    let output_1_term_2 = OutputTerm::Integral {
        coeff: 1.0,
        lower: 0.0,
        upper: 1.0,
        weight: Arc::new(weight_u_2),
        unknown: 0,
    };
    let output_1 = CompiledOutput {
        name: "U".into(),
        terms: vec![output_1_term_1, output_1_term_2],
    };
    let output_2_term_1 = OutputTerm::Integral {
        coeff: std::f64::consts::PI,
        lower: 0.0,
        upper: 0.5,
        weight: Arc::new(weight_v),
        unknown: 1,
    };
    let output_2 = CompiledOutput {
        name: "V".into(),
        terms: vec![output_2_term_1],
    };
    let sys = CompiledSystem {
        symbols: vec!["m".into(), "k".into(), "h".into(), "g".into()],
        operators: vec![Some(op_m), Some(op_k), Some(op_h), Some(op_g)],
        unknowns: vec!["u".into(), "v".into()],
        equations: vec![equation_1, equation_2],
        outputs: vec![output_1, output_2],
        conditions: Vec::new(),
        target: 1,
        principal: None,
        derived_pivots: Some(vec![(1, 0)]),
        domain: (0.0, 1.0),
        interior: vec![0.5],
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
