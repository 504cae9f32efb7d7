//! Narrow features of a system's formulas, found from the expression
//! trees (not from a mesh): where a kernel varies fast in `t` at a fixed
//! point, or a right side in `x`. Three shapes are recognised wherever
//! they occur in a formula:
//!
//! - a Gaussian `exp(A)` whose exponent has a maximum at `c` with
//!   curvature `A''(c) < 0`: width `√(2/|A''(c)|)` (`exp(-((t-c)/ε)²)`
//!   has width `ε`);
//! - a denominator (or a base raised to a negative power) with a positive
//!   minimum of `|D|` at `c`, a pole beside the real line: width
//!   `√(2·D(c)/D''(c))` (`(x-c)² + w²` has width `w`);
//! - the kink of `abs(B)` at a zero `c` of `B` (width 0: a breakpoint).
//!
//! A zero of a denominator, of a base raised to a negative power or of a
//! logarithm's argument inside the range is an interior singularity
//! ([`interior_singularity`]); for kernels it is refused (docs/language.md)
//! unless it moves with `x` (the diagonal classes of `operators.rs`).
//! Each feature is located on the formula's own parts by Newton steps
//! (exact in one step for the quadratic and linear shapes above), at
//! several values of the other variable; a feature of a kernel that moves
//! with `x` is the diagonal peak `operators.rs` classifies, not one of
//! these. The ladder grades its mesh toward every feature deeply enough
//! that the first level's panels there are no wider than the feature
//! (`split.rs`).
use crate::system::expr::{Expr, Func};

/// Features narrower than this fraction of the interval are graded
/// toward.
pub const NARROW: f64 = 0.05;

/// A narrow feature: its point and width (0 for a kink).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Feature {
    /// Where it is.
    pub at: f64,
    /// Its width (0: a kink, graded like a breakpoint).
    pub width: f64,
}

/// Which variable a formula is examined in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Var {
    /// `t` (kernels), at several values of `x`.
    T,
    /// `x` (right sides).
    X,
}

fn at(e: &Expr, var: Var, v: f64, other: f64) -> f64 {
    match var {
        Var::T => e.eval(other, v),
        Var::X => e.eval(v, other),
    }
}

fn uses(e: &Expr, var: Var) -> bool {
    match var {
        Var::T => e.uses_t(),
        Var::X => e.uses_x(),
    }
}

/// A stationary point of `f` near `[lo, hi]` by Newton steps on central
/// differences: `(c, f(c), f''(c))`.
fn stationary(f: &dyn Fn(f64) -> f64, lo: f64, hi: f64) -> Option<(f64, f64, f64)> {
    let len = hi - lo;
    let mut v = 0.5 * (lo + hi);
    let mut h = 1e-3 * len;
    for _ in 0..40 {
        let (a, b, c) = (f(v - h), f(v), f(v + h));
        let d1 = (c - a) / (2.0 * h);
        let d2 = (a - 2.0 * b + c) / (h * h);
        if !(d1.is_finite() && d2.is_finite()) || d2 == 0.0 {
            return None;
        }
        let step = d1 / d2;
        v -= step;
        if !v.is_finite() || (v - 0.5 * (lo + hi)).abs() > 10.0 * len {
            return None;
        }
        // Refine the difference step toward the feature's own scale.
        let scale = (b / d2).abs().sqrt();
        if scale.is_finite() && scale > 0.0 {
            h = h.min(0.05 * scale).max(1e-12 * len.max(v.abs()));
        }
        if step.abs() <= 1e-13 * len.max(v.abs()) {
            let (a, b, c) = (f(v - h), f(v), f(v + h));
            return Some((v, b, (a - 2.0 * b + c) / (h * h)));
        }
    }
    None
}

/// A zero of `f` near `[lo, hi]` by secant steps from the middle (exact in
/// one step for a linear `f`).
fn zero(f: &dyn Fn(f64) -> f64, lo: f64, hi: f64) -> Option<f64> {
    let len = hi - lo;
    let (mut a, mut b) = (0.5 * (lo + hi), 0.5 * (lo + hi) + 0.1 * len);
    let (mut fa, mut fb) = (f(a), f(b));
    for _ in 0..60 {
        if fb == 0.0 {
            return Some(b);
        }
        if !(fa.is_finite() && fb.is_finite()) || fa == fb {
            return None;
        }
        let c = b - fb * (b - a) / (fb - fa);
        if !c.is_finite() || (c - 0.5 * (lo + hi)).abs() > 10.0 * len {
            return None;
        }
        (a, fa, b) = (b, fb, c);
        fb = f(b);
        if (b - a).abs() <= 1e-15 * len.max(b.abs()) {
            return Some(b);
        }
    }
    None
}

/// `e` with `abs`, negation and constant factors peeled off.
fn core(e: &Expr) -> &Expr {
    match e {
        Expr::Call(Func::Abs, a) | Expr::Neg(a) => core(a),
        Expr::Mul(a, b) if !a.uses_x() && !a.uses_t() => core(b),
        Expr::Mul(a, b) if !b.uses_x() && !b.uses_t() => core(a),
        _ => e,
    }
}

/// The same point at every value of the other variable (within `tol`),
/// or `None`.
fn fixed(points: &[Option<f64>], tol: f64) -> Option<f64> {
    let first = (*points.first()?)?;
    points
        .iter()
        .all(|p| p.is_some_and(|p| (p - first).abs() <= tol))
        .then_some(first)
}

const OTHERS: [f64; 3] = [0.137, 0.5, 0.861];

fn others(var: Var, domain: (f64, f64)) -> Vec<f64> {
    match var {
        Var::T => OTHERS
            .iter()
            .map(|f| domain.0 + f * (domain.1 - domain.0))
            .collect(),
        Var::X => vec![0.0],
    }
}

/// The narrow features of `e` in `var` on `domain` (the kink of `abs` of
/// any width; peaks narrower than [`NARROW`] of the interval).
pub fn features(e: &Expr, var: Var, domain: (f64, f64)) -> Vec<Feature> {
    let mut out = Vec::new();
    visit(e, &mut |s| {
        if let Some(f) = feature_of(s, var, domain) {
            out.push(f);
        }
    });
    out
}

fn visit(e: &Expr, f: &mut dyn FnMut(&Expr)) {
    f(e);
    match e {
        Expr::Neg(a) | Expr::Call(_, a) => visit(a, f),
        Expr::Add(a, b) | Expr::Sub(a, b) | Expr::Mul(a, b) | Expr::Div(a, b) | Expr::Pow(a, b) => {
            visit(a, f);
            visit(b, f);
        }
        _ => {}
    }
}

fn feature_of(s: &Expr, var: Var, domain: (f64, f64)) -> Option<Feature> {
    let (lo, hi) = domain;
    let len = hi - lo;
    let inside = |c: f64, w: f64| c >= lo - 3.0 * w && c <= hi + 3.0 * w;
    let clamp = |c: f64| c.clamp(lo, hi);
    let os = others(var, domain);
    match s {
        Expr::Call(Func::Exp, a) if uses(a, var) => {
            let found: Vec<Option<(f64, f64)>> = os
                .iter()
                .map(|&o| {
                    let (c, _, d2) = stationary(&|v| at(a, var, v, o), lo, hi)?;
                    (d2 < 0.0).then(|| (c, (2.0 / -d2).sqrt()))
                })
                .collect();
            let w = found.iter().flatten().map(|p| p.1).fold(0.0, f64::max);
            let c = fixed(
                &found.iter().map(|p| p.map(|p| p.0)).collect::<Vec<_>>(),
                0.1 * w,
            )?;
            (w < NARROW * len && inside(c, w)).then(|| Feature {
                at: clamp(c),
                width: w,
            })
        }
        Expr::Div(_, d) if uses(d, var) => near_pole(core(d), var, domain, &os),
        Expr::Pow(b, p) if uses(b, var) && !p.uses_x() && !p.uses_t() && p.eval(0.0, 0.0) < 0.0 => {
            near_pole(core(b), var, domain, &os)
        }
        Expr::Call(Func::Abs, a) if uses(a, var) => {
            let zs: Vec<Option<f64>> = os
                .iter()
                .map(|&o| zero(&|v| at(a, var, v, o), lo, hi))
                .collect();
            let c = fixed(&zs, 1e-12 * len)?;
            (c > lo && c < hi).then_some(Feature { at: c, width: 0.0 })
        }
        _ => None,
    }
}

/// A positive minimum of `|d|` near the interval: a pole beside it.
fn near_pole(d: &Expr, var: Var, domain: (f64, f64), os: &[f64]) -> Option<Feature> {
    let (lo, hi) = domain;
    let len = hi - lo;
    let found: Vec<Option<(f64, f64)>> = os
        .iter()
        .map(|&o| {
            let (c, v, d2) = stationary(&|t| at(d, var, t, o), lo, hi)?;
            let r = 2.0 * v / d2;
            (r > 0.0).then(|| (c, r.sqrt()))
        })
        .collect();
    let w = found.iter().flatten().map(|p| p.1).fold(0.0, f64::max);
    let c = fixed(
        &found.iter().map(|p| p.map(|p| p.0)).collect::<Vec<_>>(),
        0.1 * w,
    )?;
    (w < NARROW * len && c >= lo - 3.0 * w && c <= hi + 3.0 * w).then(|| Feature {
        at: c.clamp(lo, hi),
        width: w,
    })
}

/// An interior point of `range` where the kernel `e` is infinite at every
/// `x` (a zero of a denominator, of a base raised to a negative power, or
/// of a logarithm's argument), with what vanishes there.
pub fn interior_singularity(
    e: &Expr,
    range: (f64, f64),
    domain: (f64, f64),
) -> Option<(f64, String)> {
    let (lo, hi) = range;
    let len = hi - lo;
    let os = others(Var::T, domain);
    let mut found = None;
    visit(e, &mut |s| {
        if found.is_some() {
            return;
        }
        let (base, what) = match s {
            Expr::Div(_, d) if d.uses_t() => (core(d), "a denominator"),
            Expr::Pow(b, p)
                if b.uses_t() && !p.uses_x() && !p.uses_t() && p.eval(0.0, 0.0) < 0.0 =>
            {
                (core(b), "a base raised to a negative power")
            }
            Expr::Call(Func::Ln, a) if a.uses_t() => (core(a), "the argument of ln"),
            _ => return,
        };
        let zs: Vec<Option<f64>> = os
            .iter()
            .map(|&o| {
                let z = zero(&|t| base.eval(o, t), lo, hi)?;
                let scale = base
                    .eval(o, lo)
                    .abs()
                    .max(base.eval(o, hi).abs())
                    .max(1e-300);
                (base.eval(o, z).abs() <= 1e-9 * scale).then_some(z)
            })
            .collect();
        if let Some(z) = fixed(&zs, 1e-12 * len.max(1.0))
            && z > lo
            && z < hi
        {
            found = Some((z, format!("{what}, {base}, is zero there")));
        }
    });
    found
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kernel(src: &str) -> Expr {
        let text = format!("operator k = int(0..1) {src} dt\nunknown p\nequation k p = 1\n");
        let p = crate::lang::parse_program(&text, "t.lmx").expect("parses");
        match &p.operators[0].terms[0] {
            crate::system::Term::Integral { kernel, .. } => kernel.clone(),
            _ => unreachable!(),
        }
    }

    #[test]
    fn gaussian_spikes_and_near_poles_are_found_at_their_width() {
        for e in [2, 3, 6] {
            let eps = 10f64.powi(-e);
            let k = kernel(&format!("x*exp(-((t - 1/pi)*10^{e})^2)*10^{e}/sqrt(pi)"));
            let f = features(&k, Var::T, (0.0, 1.0));
            assert_eq!(f.len(), 1, "{f:?}");
            assert!(
                (f[0].at - 1.0 / std::f64::consts::PI).abs() < 1e-3 * eps,
                "{f:?}"
            );
            assert!((f[0].width / eps - 1.0).abs() < 1e-3, "{f:?}");
        }
        let k = kernel("1/((t - 0.123456789)^2 + 1/10^14)");
        let f = features(&k, Var::T, (0.0, 1.0));
        assert!(
            (f[0].at - 0.123456789).abs() < 1e-9 && (f[0].width / 1e-7 - 1.0).abs() < 1e-3,
            "{f:?}"
        );
        // Love's kernel peaks on the diagonal: not a fixed feature.
        assert!(features(&kernel("1/(1/10^6 + (x - t)^2)"), Var::T, (0.0, 1.0)).is_empty());
        assert!(features(&kernel("exp(x*t)"), Var::T, (0.0, 1.0)).is_empty());
        // Wider than NARROW of the interval: not a feature.
        assert!(features(&kernel("exp(-((t - 1/pi)*10)^2)"), Var::T, (0.0, 1.0)).is_empty());
        let f = features(&kernel("abs(t - 1/3)"), Var::T, (0.0, 1.0));
        assert!(
            (f[0].at - 1.0 / 3.0).abs() < 1e-14 && f[0].width == 0.0,
            "{f:?}"
        );
    }

    #[test]
    fn interior_singularities_are_found_at_their_point() {
        let d = (0.0, 1.0);
        for (src, p) in [
            ("abs(t - 1/pi)^(-9/10)", 1.0 / std::f64::consts::PI),
            ("1/(t - 1/3)", 1.0 / 3.0),
            ("x*ln(abs(t - 0.7))", 0.7),
        ] {
            let (z, _) =
                interior_singularity(&kernel(src), d, d).unwrap_or_else(|| panic!("{src}"));
            assert!((z - p).abs() < 1e-12, "{src}: {z}");
        }
        for src in [
            "ln(abs(x - t))",
            "1/(t - x)",
            "1/(t + 2)",
            "exp(x*t)",
            "1/(1 + t^2)",
        ] {
            assert!(interior_singularity(&kernel(src), d, d).is_none(), "{src}");
        }
    }
}
