//! Compiling the language's expression trees ([`Expr`]) once into closures,
//! and recognising the Abel factor `|t²-x²|^(-1/2)` in a kernel. Constant
//! subtrees are folded to one number at compile time, so the hot loops of
//! assembly call a small tree of closures and never walk the `Expr` again.
//! This file owns expression handling only; it must not know about
//! operators, limits or bases.
use std::sync::Arc;

use num_traits::ToPrimitive;

use crate::system::expr::{Expr, Func};

/// A compiled function of `(x, t)`.
pub type Fn2 = Arc<dyn Fn(f64, f64) -> f64 + Send + Sync>;

/// Compiles `e` into a closure of `(x, t)`.
///
/// ```
/// use lambdamat::plan::compile::compile;
/// use lambdamat::system::expr::Expr;
/// let f = compile(&Expr::Mul(Box::new(Expr::X), Box::new(Expr::T)));
/// assert_eq!(f(2.0, 3.0), 6.0);
/// ```
pub fn compile(e: &Expr) -> Fn2 {
    if !e.uses_x() && !e.uses_t() {
        let v = e.eval(0.0, 0.0);
        return Arc::new(move |_, _| v);
    }
    match e {
        Expr::X => Arc::new(|x, _| x),
        Expr::T => Arc::new(|_, t| t),
        Expr::Neg(a) => {
            let a = compile(a);
            Arc::new(move |x, t| -a(x, t))
        }
        Expr::Add(a, b) => bin(a, b, |u, v| u + v),
        Expr::Sub(a, b) => bin(a, b, |u, v| u - v),
        Expr::Mul(a, b) => bin(a, b, |u, v| u * v),
        Expr::Div(a, b) => bin(a, b, |u, v| u / v),
        Expr::Pow(a, b) => match const_exponent(b) {
            Some(p) => power(compile(a), p),
            None => bin(a, b, f64::powf),
        },
        Expr::Call(f, a) => {
            let a = compile(a);
            let f: Func = *f;
            Arc::new(move |x, t| f.apply(a(x, t)))
        }
        // Constants and π are folded above.
        Expr::Const(_) | Expr::Pi => {
            let v = e.eval(0.0, 0.0);
            Arc::new(move |_, _| v)
        }
    }
}

/// Compiles a function of `x` alone (right sides, multipliers, weights).
pub fn compile_x(e: &Expr) -> Arc<dyn Fn(f64) -> f64 + Send + Sync> {
    let f = compile(e);
    Arc::new(move |x| f(x, 0.0))
}

fn bin(a: &Expr, b: &Expr, op: fn(f64, f64) -> f64) -> Fn2 {
    let (a, b) = (compile(a), compile(b));
    Arc::new(move |x, t| op(a(x, t), b(x, t)))
}

/// The exponent of `a^b` if `b` is a finite constant.
pub fn const_exponent(b: &Expr) -> Option<f64> {
    if b.uses_x() || b.uses_t() {
        return None;
    }
    let v = b.eval(0.0, 0.0);
    v.is_finite().then_some(v)
}

/// `f^p` with the common exponents done without `powf`.
fn power(f: Fn2, p: f64) -> Fn2 {
    if p == 1.0 {
        f
    } else if p == 0.5 {
        Arc::new(move |x, t| f(x, t).sqrt())
    } else if p == -0.5 {
        Arc::new(move |x, t| 1.0 / f(x, t).sqrt())
    } else if p.fract() == 0.0 && p.abs() < 64.0 {
        let n = p as i32;
        Arc::new(move |x, t| f(x, t).powi(n))
    } else {
        Arc::new(move |x, t| f(x, t).powf(p))
    }
}

/// How the recognised Abel base was written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AbelBase {
    /// `c (t² - x²)` with `c > 0` (real for `t > x`).
    TMinusX,
    /// `c (x² - t²)` with `c > 0` (real for `t < x`).
    XMinusT,
    /// `|c (t² - x²)|` (real everywhere).
    Abs,
}

/// A kernel split as `a(x,t) · |t² - x²|^(-1/2)`.
#[cfg(any(test, feature = "internals"))]
pub struct AbelSplit {
    /// The smooth factor `a` (the base's constant is folded in).
    pub smooth: Fn2,
    /// How the base was written (decides where the kernel is real).
    pub base: AbelBase,
}

/// The same split as expressions: `a(x,t) = scale · Π factorᵢ^powerᵢ`,
/// multiplied left to right. [`split_abel`] compiles it to a closure and
/// the code generator ([`crate::codegen`]) prints it as Rust, so both
/// evaluate the same operations in the same order.
#[derive(Debug, Clone, PartialEq)]
pub struct AbelParts {
    /// Sign and the base's constant: `±1/√|c|`.
    pub scale: f64,
    /// The remaining factors with their real powers.
    pub factors: Vec<(Expr, f64)>,
    /// How the base was written.
    pub base: AbelBase,
}

/// Recognises a kernel of the form `a(x,t) · (c(t²-x²))^(-1/2)` (also
/// `(c(x²-t²))^(-1/2)`, `|c(t²-x²)|^(-1/2)`, `sqrt`, division, powers) and
/// returns the smooth factor `a`, or `None` if the kernel has no such
/// factor. The base is recognised by value (so `(t-x)*(t+x)` counts too);
/// the rest of the kernel is not checked for smoothness here.
///
/// ```
/// use lambdamat::plan::compile::{split_abel, AbelBase};
/// let p = lambdamat::lang::parse_program(
///     "operator k = int(x..1) 2*t/sqrt(t^2 - x^2) dt\nunknown p\nequation k p = 1",
///     "a.lmx").unwrap();
/// let lambdamat::system::Term::Integral { kernel, .. } = &p.operators[0].terms[0] else { panic!() };
/// let s = split_abel(kernel).unwrap();
/// assert_eq!(s.base, AbelBase::TMinusX);
/// assert!(((s.smooth)(0.3, 0.5) - 1.0).abs() < 1e-15);
/// ```
#[cfg(any(test, feature = "internals"))]
pub fn split_abel(e: &Expr) -> Option<AbelSplit> {
    let parts = abel_parts(e)?;
    Some(AbelSplit {
        smooth: smooth_factor(&parts),
        base: parts.base,
    })
}

/// The smooth factor `scale · Π factorᵢ^powerᵢ` as a closure.
///
/// The common shapes, constant factors followed by at most one plain `x`
/// or `t` (every kernel of the Hertz problem: `t/√(t² − x²)` is `t`,
/// `x/√(x² − t²)` is `x`), are closures of their own: no loop and no
/// inner closure per evaluation (the smooth factor is called once per
/// quadrature node in assembly; measured 7 % of a Hertz solve's CPU time
/// in the general form). They multiply the same numbers in the same order
/// as the general form, so the values are the same to the bit.
pub fn smooth_factor(parts: &AbelParts) -> Fn2 {
    let scale = parts.scale;
    let constants = parts
        .factors
        .iter()
        .take_while(|(f, _)| !f.uses_x() && !f.uses_t())
        .count();
    let rest = &parts.factors[constants..];
    let folded = || {
        parts.factors[..constants]
            .iter()
            .fold(scale, |v, (f, p)| v * pow_f(f.eval(0.0, 0.0), *p))
    };
    match rest {
        [] => {
            let v = folded();
            return Arc::new(move |_, _| v);
        }
        [(Expr::X, p)] if *p == 1.0 => {
            let v = folded();
            return Arc::new(move |x, _| v * x);
        }
        [(Expr::T, p)] if *p == 1.0 => {
            let v = folded();
            return Arc::new(move |_, t| v * t);
        }
        _ => {}
    }
    let factors: Vec<(Fn2, f64)> = parts
        .factors
        .iter()
        .map(|(f, p)| (compile(f), *p))
        .collect();
    Arc::new(move |x, t| {
        let mut v = scale;
        for (f, p) in &factors {
            v *= pow_f(f(x, t), *p);
        }
        v
    })
}

/// The symbolic form of [`split_abel`].
pub fn abel_parts(e: &Expr) -> Option<AbelParts> {
    let mut factors: Vec<(Expr, f64)> = Vec::new();
    let mut found: Option<(f64, AbelBase)> = None;
    let mut sign = 1.0;
    flatten(e, 1.0, &mut factors, &mut found, &mut sign);
    let (c, base) = found?;
    Some(AbelParts {
        scale: sign / c.abs().sqrt(),
        factors,
        base,
    })
}

/// `v^p` with the common exponents done without `powf` (the code
/// generator mirrors these cases exactly).
pub fn pow_f(v: f64, p: f64) -> f64 {
    if p == 1.0 {
        v
    } else if p == -1.0 {
        1.0 / v
    } else if p == 0.5 {
        v.sqrt()
    } else if p == -0.5 {
        1.0 / v.sqrt()
    } else if p.fract() == 0.0 && p.abs() < 64.0 {
        v.powi(p as i32)
    } else {
        v.powf(p)
    }
}

/// Splits `e^p` into factors; the first subexpression raised to `-1/2`
/// that equals `c(t²-x²)` by value becomes the Abel base.
fn flatten(
    e: &Expr,
    p: f64,
    out: &mut Vec<(Expr, f64)>,
    found: &mut Option<(f64, AbelBase)>,
    sign: &mut f64,
) {
    if found.is_none()
        && p == -0.5
        && let Some(b) = match_base(e)
    {
        *found = Some(b);
        return;
    }
    match e {
        Expr::Neg(a) => {
            if p.fract() == 0.0 && (p as i64) % 2 != 0 {
                *sign = -*sign;
                flatten(a, p, out, found, sign);
            } else if p.fract() == 0.0 {
                flatten(a, p, out, found, sign);
            } else {
                out.push((e.clone(), p));
            }
        }
        Expr::Mul(a, b) => {
            flatten(a, p, out, found, sign);
            flatten(b, p, out, found, sign);
        }
        Expr::Div(a, b) => {
            flatten(a, p, out, found, sign);
            flatten(b, -p, out, found, sign);
        }
        Expr::Pow(a, b) => match const_exponent(b) {
            Some(q) if q != 0.0 => flatten(a, p * q, out, found, sign),
            _ => out.push((e.clone(), p)),
        },
        Expr::Call(Func::Sqrt, a) => flatten(a, 0.5 * p, out, found, sign),
        _ => out.push((e.clone(), p)),
    }
}

const SAMPLES: [(f64, f64); 5] = [
    (0.3, 0.7),
    (0.61, 0.2),
    (0.15, 0.9),
    (0.8, 0.45),
    (0.05, 0.33),
];

/// `Some((c, kind))` if `e` equals `c(t²-x²)` (or `|c(t²-x²)|`) at sample
/// points, with `c` a nonzero constant.
fn match_base(e: &Expr) -> Option<(f64, AbelBase)> {
    if !e.uses_x() || !e.uses_t() {
        return None;
    }
    let (inner, abs) = match e {
        Expr::Call(Func::Abs, a) => (a.as_ref(), true),
        other => (other, false),
    };
    let f = compile(inner);
    let mut c: Option<f64> = None;
    for &(x, t) in &SAMPLES {
        let r = f(x, t) / (t * t - x * x);
        if !r.is_finite() || r == 0.0 {
            return None;
        }
        match c {
            None => c = Some(r),
            Some(c0) if (r - c0).abs() <= 1e-12 * c0.abs() => {}
            Some(_) => return None,
        }
    }
    let c = c?;
    let kind = if abs {
        AbelBase::Abs
    } else if c > 0.0 {
        AbelBase::TMinusX
    } else {
        AbelBase::XMinusT
    };
    Some((c, kind))
}

/// A diagonal singular factor recognised in a kernel (other than the
/// Hertz family `|t²-x²|^(-1/2)`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DiagonalClass {
    /// `|x - t|^(-β)`, `0 < β < 1`; `side` says where the base is real:
    /// `1` for `t < x` only (`(x-t)^(-β)`), `-1` for `t > x` only, `0`
    /// for both (`abs(x - t)^(-β)`).
    Power {
        /// The exponent `β`.
        beta: f64,
        /// Where the written base is real.
        side: i8,
    },
    /// `ln|c (x - t)| = ln|x - t| + ln|c|`: the constant `ln|c|` times
    /// the smooth factor is a smooth part of its own (0 when `|c| = 1`).
    Log {
        /// `ln|c|`.
        ln_c: f64,
    },
    /// `1/(t - x)`.
    Cauchy,
}

/// Recognises `a(x,t) · S(x,t)` with `S` one of [`DiagonalClass`],
/// however it is written (`1/sqrt(x - t)`, `(x - t)^(-1/3)`,
/// `1/sqrt(abs(x - t))`, `ln(abs(x - t))`, `1/(t - x)`, `-1/(x - t)`),
/// returning the class and the smooth factor `a` as [`AbelParts`] (its
/// `base` field is unused). The singular base is recognised by value: it
/// must equal `c (x - t)` (or `|c (x - t)|`) at sample points.
///
/// ```
/// use lambdamat::plan::compile::{diagonal_parts, DiagonalClass};
/// let p = lambdamat::lang::parse_program(
///     "operator k = int(0..x) 2/sqrt(x - t) dt\nunknown p\nequation k p = 1",
///     "a.lmx").unwrap();
/// let lambdamat::system::Term::Integral { kernel, .. } = &p.operators[0].terms[0] else { panic!() };
/// let (class, parts) = diagonal_parts(kernel).unwrap();
/// assert_eq!(class, DiagonalClass::Power { beta: 0.5, side: 1 });
/// let a = lambdamat::plan::compile::smooth_factor(&parts);
/// assert!((a(0.3, 0.1) - 2.0).abs() < 1e-15);
/// ```
pub fn diagonal_parts(e: &Expr) -> Option<(DiagonalClass, AbelParts)> {
    let mut factors: Vec<(Expr, f64)> = Vec::new();
    // A found base stops `flatten` from looking for the Hertz base.
    let mut found = Some((1.0, AbelBase::Abs));
    let mut sign = 1.0;
    flatten(e, 1.0, &mut factors, &mut found, &mut sign);
    let mut scale = sign;
    for (i, (f, p)) in factors.iter().enumerate() {
        let class = if let Expr::Call(Func::Ln, arg) = f {
            match match_linear(arg).or_else(|| match_abs_linear(arg)) {
                Some((c, true)) if *p == 1.0 => DiagonalClass::Log {
                    ln_c: if (c.abs() - 1.0).abs() < 1e-14 {
                        0.0
                    } else {
                        c.abs().ln()
                    },
                },
                _ => continue,
            }
        } else {
            let Some((c, abs)) = match_linear(f) else {
                continue;
            };
            if *p == -1.0 && !abs {
                // c (x - t) = -c (t - x).
                scale /= -c;
                DiagonalClass::Cauchy
            } else if *p > -1.0 && *p < 0.0 {
                scale *= c.abs().powf(*p);
                let side = if abs {
                    0
                } else if c > 0.0 {
                    1
                } else {
                    -1
                };
                DiagonalClass::Power { beta: -*p, side }
            } else {
                continue;
            }
        };
        let mut rest = factors.clone();
        rest.remove(i);
        return Some((
            class,
            AbelParts {
                scale,
                factors: rest,
                base: AbelBase::Abs,
            },
        ));
    }
    None
}

/// `Some((c, abs))` if `e` equals `c (x - t)` (or `|c (x - t)|`) at
/// sample points, with `c` a nonzero constant.
fn match_linear(e: &Expr) -> Option<(f64, bool)> {
    if !e.uses_x() || !e.uses_t() {
        return None;
    }
    let (inner, abs) = match e {
        Expr::Call(Func::Abs, a) => (a.as_ref(), true),
        other => (other, false),
    };
    let f = compile(inner);
    let mut c: Option<f64> = None;
    for &(x, t) in &SAMPLES {
        let r = f(x, t) / (x - t);
        if !r.is_finite() || r == 0.0 {
            return None;
        }
        match c {
            None => c = Some(r),
            Some(c0) if (r - c0).abs() <= 1e-12 * c0.abs() => {}
            Some(_) => return None,
        }
    }
    c.map(|c| (c, abs))
}

/// `Some((c, true))` if `e` equals `c |x - t|` with `c > 0` at sample
/// points on both sides of the diagonal, however the absolute value is
/// written (`abs(x - t)*3`, `sqrt((x - t)^2)`).
fn match_abs_linear(e: &Expr) -> Option<(f64, bool)> {
    if !e.uses_x() || !e.uses_t() {
        return None;
    }
    let f = compile(e);
    let mut c: Option<f64> = None;
    for &(x, t) in &SAMPLES {
        for (x, t) in [(x, t), (t, x)] {
            let r = f(x, t) / (x - t).abs();
            if !r.is_finite() || r <= 0.0 {
                return None;
            }
            match c {
                None => c = Some(r),
                Some(c0) if (r - c0).abs() <= 1e-12 * c0 => {}
                Some(_) => return None,
            }
        }
    }
    c.map(|c| (c, true))
}

/// The value of a constant expression (no `x`, `t`), if finite.
pub fn constant_value(e: &Expr) -> Option<f64> {
    if e.uses_x() || e.uses_t() {
        return None;
    }
    let v = e.eval(0.0, 0.0);
    v.is_finite().then_some(v)
}

/// A rational as `f64`.
pub fn rational(q: &num_rational::BigRational) -> f64 {
    q.to_f64().unwrap_or(f64::NAN)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kernel(src: &str) -> Expr {
        let text = format!("operator k = {src}\nunknown p\nequation k p = 1\n");
        let p = crate::lang::parse_program(&text, "t.lmx").expect("parses");
        match &p.operators[0].terms[0] {
            crate::system::Term::Integral { kernel, .. } => kernel.clone(),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn compiled_closures_match_eval() {
        let e = kernel("int(0..1) exp(x*t) + ln(1 + t)^2/(2 - x) - abs(x - t)^(3/2) dt");
        let f = compile(&e);
        for &(x, t) in &SAMPLES {
            assert!((f(x, t) - e.eval(x, t)).abs() < 1e-14);
        }
    }

    #[test]
    fn the_smooth_factors_common_shapes_are_the_general_products_to_the_bit() {
        // The general form: scale times every factor's power, in order.
        let general = |parts: &AbelParts, x: f64, t: f64| {
            let mut v = parts.scale;
            for (f, p) in &parts.factors {
                v *= pow_f(compile(f)(x, t), *p);
            }
            v
        };
        let cases = [
            // (kernel, whether it has one of the specialised shapes)
            ("int(x..1) t/sqrt(t^2 - x^2) dt", true),
            ("-int(x..1) x/sqrt(t^2 - x^2) dt", true),
            ("1/3*int(0..x) t/sqrt(x^2 - t^2) dt", true),
            ("int(0..1) 2*t/sqrt(abs(4*t^2 - 4*x^2)) dt", true),
            ("int(0..1) (1/7)*(2/3)*x/sqrt(abs(t^2 - x^2)) dt", true),
            ("int(0..1) 5/sqrt(abs(t^2 - x^2)) dt", true),
            ("int(x..1) t^2/sqrt(t^2 - x^2) dt", false),
            ("int(x..1) x*t/sqrt(t^2 - x^2) dt", false),
            ("int(x..1) exp(t)/sqrt(t^2 - x^2) dt", false),
        ];
        let mut special = 0;
        for (src, shaped) in cases {
            let parts = abel_parts(&kernel(src)).expect(src);
            let rest: Vec<_> = parts
                .factors
                .iter()
                .skip_while(|(f, _)| !f.uses_x() && !f.uses_t())
                .collect();
            let is_shaped = match rest.as_slice() {
                [] => true,
                [(Expr::X | Expr::T, p)] => *p == 1.0,
                _ => false,
            };
            assert_eq!(is_shaped, shaped, "{src}: {:?}", parts.factors);
            special += usize::from(is_shaped);
            let f = smooth_factor(&parts);
            for &(x, t) in &SAMPLES {
                let (a, b) = (f(x, t), general(&parts, x, t));
                assert_eq!(a.to_bits(), b.to_bits(), "{src} at ({x}, {t}): {a} vs {b}");
            }
        }
        assert_eq!(special, 6);
    }

    #[test]
    fn abel_factors_in_several_spellings() {
        let cases = [
            ("int(x..1) t/sqrt(t^2 - x^2) dt", AbelBase::TMinusX),
            ("-int(x..1) x/sqrt(t^2 - x^2) dt", AbelBase::TMinusX),
            ("1/3*int(0..x) t/sqrt(x^2 - t^2) dt", AbelBase::XMinusT),
            ("int(x..1) t*((t - x)*(t + x))^(-1/2) dt", AbelBase::TMinusX),
            ("int(0..1) 2*t/sqrt(abs(4*t^2 - 4*x^2)) dt", AbelBase::Abs),
        ];
        for (src, base) in cases {
            let e = kernel(src);
            let s = split_abel(&e).unwrap_or_else(|| panic!("{src}"));
            assert_eq!(s.base, base, "{src}");
            for &(x, t) in &SAMPLES {
                let want = e.eval(x, t) * (t * t - x * x).abs().sqrt();
                if want.is_finite() {
                    assert!(((s.smooth)(x, t) - want).abs() < 1e-13, "{src}");
                }
            }
        }
    }

    #[test]
    fn non_abel_kernels_are_not_split() {
        for src in [
            "int(x..1) t/(t^2 - x^2) dt",
            "int(0..1) x*t dt",
            "int(x..1) 1/sqrt(t - x) dt",
        ] {
            assert!(split_abel(&kernel(src)).is_none(), "{src}");
        }
    }
}
