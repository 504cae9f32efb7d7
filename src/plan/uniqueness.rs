//! Equations with more than one solution, recognised from their operators
//! before any discretisation (issue 27). One equation for one unknown,
//! without a side condition, whose operator is a first-kind integral over
//! the unknown's whole interval `[a, b]` with constant kernel factors:
//!
//! * `α ∫_a^b ln|x - t| f(t) dt + β ∫_a^b f(t) dt` maps the equilibrium
//!   density `1/√((t - a)(b - t))` to `π (α ln((b - a)/4) + β)`, a
//!   constant; when it vanishes (the logarithmic capacity `(b - a)/4` is
//!   1 for `β = 0`) the operator has a null space, so the equation has
//!   infinitely many solutions or none. It is refused
//!   ([`PlanError::Singular`]), asking for a side condition.
//! * `γ PV∫_a^b f(t)/(t - x) dt` (the airfoil equation) annihilates the
//!   same density: the solutions unbounded at both ends form a
//!   one-parameter family, and the two classes bounded at one end have
//!   one solution each. The solver's weight selects one; the answer
//!   says so in a warning (containing "unique") naming how to select
//!   another.
//!
//! Anything else (several unknowns, an identity term, a kernel factor that
//! is not constant, a side condition) is left to the numerics.
use super::compiled::CompiledSystem;
use super::error::PlanError;
use super::split_input::SplitInput;
use crate::numeric::operator::{Limits, Singularity, Term};

/// What the operators say about uniqueness.
#[derive(Debug, Clone, PartialEq)]
pub enum Uniqueness {
    /// Nothing is known against it.
    Unknown,
    /// More than one solution; the solver's choice is described by the
    /// warning.
    Chosen(String),
}

/// The relative size below which two kernel values, or a capacity
/// defect, are equal.
const EQUAL: f64 = 1e-12;

/// Checks `sys` (see the module documentation): an error for a singular
/// logarithmic equation, [`Uniqueness::Chosen`] for a Cauchy equation
/// without a side condition.
pub fn check(sys: &CompiledSystem) -> Result<Uniqueness, PlanError> {
    if sys.unknowns.len() != 1 || sys.equations.len() != 1 || !sys.conditions.is_empty() {
        return Ok(Uniqueness::Unknown);
    }
    let (a, b) = sys.domain;
    let Some(poly) = sys.equations[0].lhs.first() else {
        return Ok(Uniqueness::Unknown);
    };
    let (mut log, mut smooth, mut cauchy) = (0.0, 0.0, 0.0);
    for (word, coeff) in poly.terms() {
        let [symbol] = word.as_slice() else {
            return Ok(Uniqueness::Unknown);
        };
        let Some(Some(op)) = sys.operators.get(*symbol) else {
            return Ok(Uniqueness::Unknown);
        };
        let c: f64 = num_traits::ToPrimitive::to_f64(coeff).unwrap_or(f64::NAN);
        for (k, term) in &op.terms {
            let Term::Integral {
                limits: Limits::Fixed { a: lo, b: hi },
                singularity,
                kernel,
            } = term
            else {
                return Ok(Uniqueness::Unknown);
            };
            if (*lo, *hi) != (a, b) {
                return Ok(Uniqueness::Unknown);
            }
            let Some(value) = constant(kernel.as_ref(), a, b) else {
                return Ok(Uniqueness::Unknown);
            };
            let v = c * k * value;
            match singularity {
                Singularity::Log => log += v,
                Singularity::Smooth => smooth += v,
                Singularity::Cauchy => cauchy += v,
                _ => return Ok(Uniqueness::Unknown),
            }
        }
    }
    let name = &sys.unknowns[0];
    let minus = |v: f64| {
        if v < 0.0 {
            format!("x + {}", -v)
        } else {
            format!("x - {v}")
        }
    };
    let density = format!("1/sqrt(({})*({b} - x))", minus(a));
    let cond = format!("condition int({a}..{b}) {name}(t) dt = C");
    if cauchy != 0.0 && log == 0.0 && smooth == 0.0 {
        return Ok(Uniqueness::Chosen(format!(
            "the solution is not unique: the Cauchy (airfoil) equation for {name} on [{a}, {b}] without a side condition has a one-parameter family of solutions unbounded at both ends (any multiple of {density} can be added) and one solution in each class bounded at one end; the answer is the one in the class of {name}'s weight shown; to select one of the family add a side condition such as `{cond}`"
        )));
    }
    if log != 0.0 && cauchy == 0.0 {
        let cap = (b - a) / 4.0;
        let mean = log * cap.ln() + smooth;
        let scale = log.abs() * (1.0 + cap.ln().abs()) + smooth.abs();
        if mean.abs() <= EQUAL * scale {
            let why = if smooth == 0.0 {
                format!("[{a}, {b}] has logarithmic capacity (b - a)/4 = 1")
            } else {
                format!(
                    "the kernel's constant part cancels ln((b - a)/4) = {} of [{a}, {b}]",
                    cap.ln()
                )
            };
            return Err(PlanError::Singular(format!(
                "the problem has more than one solution (or none): the logarithmic kernel's operator maps {density} to 0, because {why}, so any multiple of it can be added to a solution; add a side condition such as `{cond}`"
            )));
        }
    }
    Ok(Uniqueness::Unknown)
}

/// [`check`] for the split-domain solver's input: only a file without
/// split-domain declarations is one equation on one interval.
pub fn check_split(input: &SplitInput) -> Result<Uniqueness, PlanError> {
    let c = &input.contact;
    let plain = c.scalars.is_empty()
        && c.relations.is_empty()
        && c.inequalities.is_empty()
        && c.singulars.is_empty()
        && c.coefficients.is_empty()
        && c.conditions.is_empty()
        && c.equation_domains.iter().all(Option::is_none);
    if plain {
        check(&input.sys)
    } else {
        Ok(Uniqueness::Unknown)
    }
}

/// The kernel factor's value if it is the same (relative to its size) at
/// sample points of `[a, b]²`.
fn constant(kernel: &(dyn Fn(f64, f64) -> f64 + Send + Sync), a: f64, b: f64) -> Option<f64> {
    let at = |s: f64| a + (b - a) * s;
    let first = kernel(at(0.5), at(0.5));
    let same = [0.13, 0.5, 0.91].iter().all(|&s| {
        [0.07, 0.62, 0.95].iter().all(|&r| {
            let v = kernel(at(s), at(r));
            (v - first).abs() <= EQUAL * first.abs()
        })
    });
    (first.is_finite() && same).then_some(first)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check_src(src: &str) -> Result<Uniqueness, PlanError> {
        let prog = crate::lang::parse_program(src, "u.lmx").expect("parses");
        check(&CompiledSystem::from_program(&prog, None).expect("compiles"))
    }

    #[test]
    fn capacity_one_log_equations_are_refused() {
        for src in [
            "operator k = 1/pi*int(0..4) ln(abs(x - t)) dt\nunknown f on [0, 4]\nequation k f = x - 2\n",
            "operator k = int(-1..1) ln(abs(2*x - 2*t)) dt\nunknown f on [-1, 1]\nequation k f = 1\n",
            "operator k = int(-1..1) ln(abs(x - t)) dt + ln(2)*int(-1..1) dt\nunknown f on [-1, 1]\nequation k f = 1\n",
        ] {
            let e = check_src(src).expect_err(src);
            assert!(!e.is_input_error(), "{e}");
            assert!(e.to_string().contains("more than one solution"), "{e}");
            assert!(e.to_string().contains("condition int("), "{e}");
        }
    }

    #[test]
    fn other_log_equations_and_side_conditions_pass() {
        for src in [
            "operator k = int(-1..1) ln(abs(x - t)) dt\nunknown f\nequation k f = 1\n",
            "operator k = int(0..4) ln(abs(x - t)) dt\nunknown f on [0, 4]\nequation k f = x - 2\ncondition int(0..4) f(t) dt = 1\n",
            "operator k = int(0..4) x*ln(abs(x - t)) dt\nunknown f on [0, 4]\nequation k f = x - 2\n",
            "operator k = id + int(0..4) ln(abs(x - t)) dt\nunknown f on [0, 4]\nequation k f = x - 2\n",
        ] {
            assert_eq!(check_src(src).expect(src), Uniqueness::Unknown, "{src}");
        }
    }

    #[test]
    fn cauchy_equations_without_a_side_condition_state_the_choice() {
        let src =
            "operator h = 1/pi*pv int(-1..1) 1/(t - x) dt\nunknown f\nequation h f = exp(x)\n";
        let Uniqueness::Chosen(w) = check_src(src).expect("checks") else {
            panic!("not flagged");
        };
        assert!(w.contains("not unique") && w.contains("condition int(-1..1) f(t) dt"));
        let with = format!("{src}condition int(-1..1) f(t) dt = 1\n");
        assert_eq!(check_src(&with).expect("checks"), Uniqueness::Unknown);
    }
}
