//! Operator definitions of the language ([`OperatorDef`]) as numeric
//! [`Operator`]s: limits become [`Limits`], Abel kernels
//! `a(x,t)|t²-x²|^(-1/2)` become [`Singularity::AbelSqrt`] terms with the
//! smooth factor `a`, other kernels become smooth terms after a check that
//! they are regular on their range, and `id`, scalars and multipliers
//! become multiplications. Anything else is refused with the operator's
//! name. The decisions are kept as [`TermPlan`]s, which `lambdamat
//! codegen` prints as Rust. This file owns that mapping only; it must not
//! assemble matrices.
use crate::numeric::{Limits, Operator, Singularity};
use crate::system::{Expr, Limit, OperatorDef, Term};

use super::compile::{
    AbelBase, AbelParts, DiagonalClass, Fn2, abel_parts, compile, compile_x, diagonal_parts,
    rational, smooth_factor,
};
use super::error::PlanError;

/// One term of an operator, decided but not yet compiled: what
/// [`build_operator`] compiles to closures and `lambdamat codegen` prints
/// as Rust, so both build the same operator.
#[derive(Debug, Clone, PartialEq)]
pub enum TermPlan {
    /// The identity.
    Identity,
    /// A constant multiple of the identity.
    Scalar(f64),
    /// Multiplication by a function of `x`.
    Multiply(Expr),
    /// `sign · ∫ kernel`.
    Integral {
        /// The integration range.
        limits: Limits,
        /// `-1` when the written limits were reversed, else `1`.
        sign: f64,
        /// The kernel.
        kernel: KernelPlan,
        /// The kernel as written (for messages and comments).
        written: Expr,
    },
}

/// A kernel as the numerics take it.
#[derive(Debug, Clone, PartialEq)]
pub enum KernelPlan {
    /// `a(x,t)·|t²-x²|^(-1/2)`: the smooth factor `a`.
    Abel(AbelParts),
    /// A smooth kernel.
    Smooth(Expr),
    /// `a(x,t)·S(x,t)` with a diagonal singular factor `S` (power, log,
    /// Cauchy): the numeric class and the smooth factor `a`.
    Diagonal(Singularity, AbelParts),
    /// A smooth kernel sharply peaked at `t = x` (the numeric class
    /// carries the estimated width).
    Peaked(Singularity, Expr),
}

impl KernelPlan {
    /// Its singularity class.
    pub fn singularity(&self) -> Singularity {
        match self {
            KernelPlan::Abel(_) => Singularity::AbelSqrt,
            KernelPlan::Smooth(_) => Singularity::Smooth,
            KernelPlan::Diagonal(s, _) | KernelPlan::Peaked(s, _) => *s,
        }
    }

    /// The compiled smooth part.
    pub fn compile(&self) -> Fn2 {
        match self {
            KernelPlan::Abel(parts) => smooth_factor(parts),
            KernelPlan::Smooth(e) | KernelPlan::Peaked(_, e) => compile(e),
            KernelPlan::Diagonal(_, parts) => smooth_factor(parts),
        }
    }
}

/// The numeric operator of `def` (named `name`) for unknowns on `domain`.
pub fn build_operator(
    def: &OperatorDef,
    name: &str,
    domain: (f64, f64),
) -> Result<Operator, PlanError> {
    let mut op = Operator::zero();
    for term in plan_operator(def, name, domain)? {
        let piece = match term {
            TermPlan::Identity => Operator::identity(),
            TermPlan::Scalar(c) => Operator::identity().scaled(c),
            TermPlan::Multiply(m) => {
                let f = compile_x(&m);
                Operator::multiply(move |x| f(x))
            }
            TermPlan::Integral {
                limits,
                sign,
                kernel,
                ..
            } => Operator::integral_shared(limits, kernel.singularity(), kernel.compile())
                .scaled(sign),
        };
        op = op + piece;
    }
    Ok(op)
}

/// The terms of `def` (named `name`) for unknowns on `domain`, checked:
/// limits mapped, Abel factors split off, kernels regular on their range.
pub fn plan_operator(
    def: &OperatorDef,
    name: &str,
    domain: (f64, f64),
) -> Result<Vec<TermPlan>, PlanError> {
    let unsupported = |reason: String| PlanError::Unsupported {
        operator: name.to_string(),
        reason,
    };
    let mut out = Vec::new();
    for term in &def.terms {
        // A second term split off the first (the `ln|c|` part of a log
        // kernel).
        let mut extra = None;
        let piece = match term {
            Term::Identity => TermPlan::Identity,
            Term::Scalar(c) => TermPlan::Scalar(rational(c)),
            Term::Multiply(m) => {
                if m.uses_t() {
                    return Err(unsupported(format!("multiplier {m} depends on t")));
                }
                TermPlan::Multiply(m.clone())
            }
            Term::Integral {
                lower,
                upper,
                kernel,
                pv,
            } => {
                let (limits, sign) = match (lower, upper) {
                    (Limit::X, Limit::X) => continue,
                    (Limit::Const(a), Limit::X) => (Limits::Lower { a: rational(a) }, 1.0),
                    (Limit::X, Limit::Const(b)) => (Limits::Upper { b: rational(b) }, 1.0),
                    (Limit::Const(a), Limit::Const(b)) => {
                        let (a, b) = (rational(a), rational(b));
                        if a == b {
                            continue;
                        } else if a < b {
                            (Limits::Fixed { a, b }, 1.0)
                        } else {
                            (Limits::Fixed { a: b, b: a }, -1.0)
                        }
                    }
                };
                let reversed = reversed_side(limits, domain);
                let plan = match abel_parts(kernel) {
                    Some(parts) => {
                        let real = matches!(
                            (limits, parts.base),
                            (_, AbelBase::Abs)
                                | (Limits::Upper { .. }, AbelBase::TMinusX)
                                | (Limits::Lower { .. }, AbelBase::XMinusT)
                        ) && (parts.base == AbelBase::Abs || reversed.is_none());
                        if !real {
                            let range = reversed.as_deref().unwrap_or("on all of its range");
                            return Err(unsupported(format!(
                                "kernel {kernel} is not real {range} (write abs(t^2 - x^2))"
                            )));
                        }
                        if *pv {
                            return Err(unsupported(format!(
                                "pv int: kernel {kernel} has no factor 1/(t - x)"
                            )));
                        }
                        if domain.0 < 0.0 {
                            return Err(unsupported(format!(
                                "Abel kernel {kernel} needs unknowns on x ≥ 0, not on [{}, {}]",
                                domain.0, domain.1
                            )));
                        }
                        KernelPlan::Abel(parts)
                    }
                    None => match diagonal_parts(kernel) {
                        Some((class, parts)) => {
                            if let DiagonalClass::Log { ln_c } = class
                                && ln_c != 0.0
                            {
                                // ln|c (x - t)| = ln|x - t| + ln|c|: the
                                // constant part is a smooth term of its own.
                                let mut smooth = parts.clone();
                                smooth.scale *= ln_c;
                                extra = Some(TermPlan::Integral {
                                    limits,
                                    sign,
                                    kernel: KernelPlan::Diagonal(Singularity::Smooth, smooth),
                                    written: kernel.clone(),
                                });
                            }
                            if let (DiagonalClass::Power { side, .. }, Some(why)) =
                                (class, &reversed)
                                && side != 0
                            {
                                let fix = if side == 1 { "x - t" } else { "t - x" };
                                return Err(unsupported(format!(
                                    "kernel {kernel} is not real {why} (write abs({fix}))"
                                )));
                            }
                            diagonal_plan(class, parts, limits, *pv, kernel).map_err(unsupported)?
                        }
                        None if *pv => {
                            return Err(unsupported(format!(
                                "pv int: kernel {kernel} has no factor 1/(t - x) whose principal value could be taken"
                            )));
                        }
                        None => match peak_width(&compile(kernel), limits, domain) {
                            Some(w) => {
                                KernelPlan::Peaked(Singularity::Peaked { width: w }, kernel.clone())
                            }
                            None => KernelPlan::Smooth(kernel.clone()),
                        },
                    },
                };
                let range = match limits {
                    Limits::Fixed { a, b } => (a, b),
                    Limits::Lower { a } => (a.min(domain.0), a.max(domain.1)),
                    Limits::Upper { b } => (b.min(domain.0), b.max(domain.1)),
                };
                if let Some((p, why)) = super::features::interior_singularity(kernel, range, domain)
                {
                    return Err(unsupported(format!(
                        "kernel {kernel} is not finite at t = {p}, inside its range ({why}); kernels infinite at an interior point are not supported: split the interval there, or move the point to an end"
                    )));
                }
                check_regular(&plan.compile(), limits, domain).map_err(|why| {
                    unsupported(format!(
                        "kernel {kernel}: {why}; supported kernels are a smooth factor times 1, |t^2 - x^2|^(-1/2), |x - t|^(-b) (0 < b < 1), ln(abs(x - t)) or (in a pv integral) 1/(t - x)"
                    ))
                })?;
                TermPlan::Integral {
                    limits,
                    sign,
                    kernel: plan,
                    written: kernel.clone(),
                }
            }
        };
        out.push(piece);
        out.extend(extra);
    }
    Ok(out)
}

/// Where an `int(a..x)` (`int(x..b)`) range is reversed on `domain`: for
/// `x < a` (`x > b`) the integral is `-∫_x^a` (`-∫_b^x`), over which a
/// one-sided base such as `x - t` is negative. `None` if `x` never passes
/// the constant limit.
fn reversed_side(limits: Limits, domain: (f64, f64)) -> Option<String> {
    match limits {
        Limits::Lower { a } if domain.0 < a => Some(format!(
            "for x < {a}, where int({a}..x) is -int(x..{a}) and t > x"
        )),
        Limits::Upper { b } if domain.1 > b => Some(format!(
            "for x > {b}, where int(x..{b}) is -int({b}..x) and t < x"
        )),
        _ => None,
    }
}

/// The plan of a kernel with a recognised diagonal factor: the base must
/// be real on the range, and a Cauchy factor needs a principal value.
fn diagonal_plan(
    class: DiagonalClass,
    parts: AbelParts,
    limits: Limits,
    pv: bool,
    kernel: &Expr,
) -> Result<KernelPlan, String> {
    let sing = match class {
        DiagonalClass::Power { beta, side } => {
            let real = matches!(
                (side, limits),
                (0, _) | (1, Limits::Lower { .. }) | (-1, Limits::Upper { .. })
            );
            if !real {
                let fix = if side == 1 { "x - t" } else { "t - x" };
                return Err(format!(
                    "kernel {kernel} (class |x - t|^(-{beta})) is not real on all of its range (write abs({fix}))"
                ));
            }
            Singularity::Power { beta }
        }
        DiagonalClass::Log { .. } => Singularity::Log,
        DiagonalClass::Cauchy => {
            if !pv {
                return Err(format!(
                    "kernel {kernel} (class Cauchy 1/(t - x)) is not integrable: mark the integral as a principal value, `pv int(a..b) ... dt`"
                ));
            }
            if !matches!(limits, Limits::Fixed { .. }) {
                return Err(format!(
                    "kernel {kernel} (class Cauchy 1/(t - x)): a principal value needs constant limits"
                ));
            }
            Singularity::Cauchy
        }
    };
    if pv && sing != Singularity::Cauchy {
        return Err(format!(
            "pv int: kernel {kernel} has no factor 1/(t - x) whose principal value could be taken"
        ));
    }
    Ok(KernelPlan::Diagonal(sing, parts))
}

/// Kernels whose diagonal curvature scale `√|k/∂²ₜk|` is below this
/// fraction of the interval are integrated as peaked.
const PEAK_FRACTION: f64 = 0.125;

/// The width of a smooth kernel sharply peaked at `t = x` (estimated from
/// `√|k(x,x) / ∂²ₜk(x,x)|` at sample points by finite differences), or
/// `None` if it is not peaked on the scale of the interval.
fn peak_width(k: &Fn2, limits: Limits, domain: (f64, f64)) -> Option<f64> {
    let (lo, hi) = domain;
    let len = hi - lo;
    let mut width = f64::INFINITY;
    for fx in [0.1, 0.37, 0.5, 0.71, 0.9] {
        let x = lo + fx * len;
        let (l, h, _) = limits.range_at(x);
        if !(x > l && x < h) {
            continue;
        }
        let mut step = 1e-2 * len;
        let mut w = f64::INFINITY;
        for _ in 0..6 {
            let (a, b, c) = (k(x, x - step), k(x, x), k(x, x + step));
            let d2 = (a - 2.0 * b + c) / (step * step);
            if !(d2.is_finite() && b.is_finite()) || d2 == 0.0 || b == 0.0 {
                break;
            }
            let d1 = (c - a) / (2.0 * step);
            let scale = (b / d2).abs().sqrt();
            if (d1 * scale).abs() > 0.5 * b.abs() {
                // The diagonal is on a flank, not at a peak (the tail of
                // a feature at a fixed t, which `features` finds).
                w = f64::INFINITY;
                break;
            }
            w = scale;
            if step <= 0.05 * w {
                break;
            }
            step = 0.05 * w;
        }
        width = width.min(w);
    }
    (width < PEAK_FRACTION * len).then_some(width)
}

/// Checks that `k` is finite on its range at sample points and does not
/// blow up or oscillate next to the diagonal `t = x`.
///
/// The jump test is relative to the kernel's own size on its range (the
/// largest sampled `|k|`), so a smooth kernel with a large constant factor
/// is not mistaken for a singular one.
fn check_regular(k: &Fn2, limits: Limits, domain: (f64, f64)) -> Result<(), String> {
    let (lo, hi) = domain;
    let xs = [0.0, 0.05, 0.3, 0.55, 0.8, 0.97, 1.0];
    let ts = [0.0, 0.2, 0.5, 0.8, 1.0];
    let mut scale = 0.0f64;
    for fx in xs {
        let x = lo + fx * (hi - lo);
        let (l, h, _) = limits.range_at(x);
        let (l, h) = (l.max(lo), h.min(hi));
        for ft in ts {
            let v = k(x, l + ft * (h - l));
            if v.is_finite() {
                scale = scale.max(v.abs());
            }
        }
    }
    for fx in xs {
        let x = lo + fx * (hi - lo);
        let (l, h, _) = limits.range_at(x);
        let (l, h) = (l.max(lo), h.min(hi));
        if l >= h {
            continue;
        }
        for ft in ts {
            let t = l + ft * (h - l);
            let v = k(x, t);
            if !v.is_finite() {
                return Err(format!("not finite at x = {x}, t = {t}"));
            }
        }
        // A jump between 1e-4 and 1e-9 from the diagonal that goes on
        // between 1e-9 and 1e-12 is a singularity; one that stops is a
        // narrow peak (Love's kernel at κ = 1e-4), not refused here.
        let jump = |a: f64, b: f64| (a - b).abs() > 0.1 * (1.0 + scale.max(a.abs()));
        for s in [1.0, -1.0] {
            let (t1, t2, t3) = (x + s * 1e-4, x + s * 1e-9, x + s * 1e-12);
            if t1 < l || t1 > h || t3 < l || t3 > h {
                continue;
            }
            let (v1, v2, v3) = (k(x, t1), k(x, t2), k(x, t3));
            if !(v2.is_finite() && v3.is_finite()) || (jump(v1, v2) && jump(v2, v3)) {
                return Err(format!("singular on the diagonal t = x near x = {x}"));
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn op(src: &str) -> Result<Operator, PlanError> {
        let text = format!("operator k = {src}\nunknown p\nequation k p = 1\n");
        let p = crate::lang::parse_program(&text, "t.lmx").expect("parses");
        build_operator(&p.operators[0], "k", (0.0, 1.0))
    }

    #[test]
    fn hertz_operators_are_supported() {
        for src in [
            "int(x..1) t/sqrt(t^2 - x^2) dt",
            "-1/3*int(0..1) dt + 1/3*int(0..x) x/sqrt(x^2 - t^2) dt",
            "2*id + x*id - int(0..1) exp(x*t) dt",
            "int(1..0) t dt",
            "int(0..1) 100000000000000000000*(x + t) dt",
        ] {
            assert!(op(src).is_ok(), "{src}");
        }
        assert_eq!(op("int(0..1) x*t dt + 3*id").unwrap().terms.len(), 2);
    }

    #[test]
    fn unsupported_kernels_name_the_operator() {
        for src in [
            "int(x..1) 1/sqrt(x - t) dt",
            "int(0..1) 1/(t - x)^2 dt",
            "int(0..1) ln(t - x) dt",
            "int(0..1) t/sqrt(t^2 - x^2) dt",
            "int(x..1) t/sqrt(x^2 - t^2) dt",
            "int(0..1) 1/(t - x) dt",
            "int(0..1) 1000000*x*t + ln(abs(t - x)) dt",
        ] {
            let e = op(src).err().unwrap_or_else(|| panic!("accepted {src}"));
            assert!(e.is_input_error());
            assert!(e.to_string().starts_with("operator k:"), "{e}");
        }
    }
}
