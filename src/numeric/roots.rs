//! Scalar root finding for free boundaries and other scalar unknowns:
//! Brent's method on a bracket (for a first, coarse discretisation) and a
//! warm-started secant iteration (for refinements, whose root moves very
//! little), falling back to Brent when the secant misbehaves. The
//! functions may fail with the caller's error type `E` (any error that a
//! [`NumericError`] converts into). Owns the iterations only; it must not
//! know what the function computes.
use super::error::NumericError;

/// Finds a sign change of `f` by stepping outward from `[a, b]` inside
/// `[lo, hi]` and returns the bracket and its values.
#[cfg(any(test, feature = "internals"))]
pub fn bracket<E, F>(
    f: &mut F,
    mut a: f64,
    mut b: f64,
    lo: f64,
    hi: f64,
) -> Result<(f64, f64, f64, f64), E>
where
    F: FnMut(f64) -> Result<f64, E>,
    E: From<NumericError>,
{
    let mut fa = f(a)?;
    let mut fb = f(b)?;
    for _ in 0..60 {
        if fa == 0.0 || fb == 0.0 || fa.signum() != fb.signum() {
            return Ok((a, fa, b, fb));
        }
        // Step toward the side where |f| is smaller.
        if fa.abs() < fb.abs() {
            let na = (a - 1.6 * (b - a)).max(lo + 0.5 * (a - lo));
            b = a;
            fb = fa;
            a = na;
            fa = f(a)?;
        } else {
            let nb = (b + 1.6 * (b - a)).min(hi - 0.5 * (hi - b));
            a = b;
            fa = fb;
            b = nb;
            fb = f(b)?;
        }
    }
    Err(
        NumericError::NoConvergence("no sign change of the free-boundary residual found".into())
            .into(),
    )
}

/// Brackets a root of a function known to be increasing (`increasing`) or
/// decreasing in its argument: from `x0` it steps with `up` or `down`
/// (chosen by the sign of `f(x0)`) until the sign changes. Returns the
/// bracket and its values.
#[cfg(any(test, feature = "internals"))]
pub fn directed_bracket<E, F>(
    f: &mut F,
    x0: f64,
    increasing: bool,
    up: impl Fn(f64) -> f64,
    down: impl Fn(f64) -> f64,
    max_steps: usize,
) -> Result<(f64, f64, f64, f64), E>
where
    F: FnMut(f64) -> Result<f64, E>,
    E: From<NumericError>,
{
    let f0 = f(x0)?;
    if f0 == 0.0 {
        return Ok((x0, f0, x0, f0));
    }
    // Root above x0 when f(x0) has the sign of the function's low end.
    let go_up = (f0 < 0.0) == increasing;
    let (mut a, mut fa) = (x0, f0);
    for _ in 0..max_steps {
        let b = if go_up { up(a) } else { down(a) };
        let fb = f(b)?;
        if fb == 0.0 || fb.signum() != fa.signum() {
            return Ok(if a < b {
                (a, fa, b, fb)
            } else {
                (b, fb, a, fa)
            });
        }
        a = b;
        fa = fb;
    }
    Err(NumericError::NoConvergence(format!(
        "no sign change of the free-boundary residual found (searched from {x0} to {a})"
    ))
    .into())
}

/// Brent's method on a bracket `[a, b]` with `f(a) f(b) ≤ 0`, to absolute
/// tolerance `xtol` in the argument.
pub fn brent<E, F>(f: &mut F, a: f64, fa: f64, b: f64, fb: f64, xtol: f64) -> Result<f64, E>
where
    F: FnMut(f64) -> Result<f64, E>,
    E: From<NumericError>,
{
    let (mut a, mut fa, mut b, mut fb) = (a, fa, b, fb);
    if fa == 0.0 {
        return Ok(a);
    }
    if fb == 0.0 {
        return Ok(b);
    }
    if fa.signum() == fb.signum() {
        return Err(NumericError::NoConvergence("Brent called without a bracket".into()).into());
    }
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for _ in 0..200 {
        if fb.signum() == fc.signum() {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol = 2.0 * f64::EPSILON * b.abs() + 0.5 * xtol;
        let m = 0.5 * (c - b);
        if m.abs() <= tol || fb == 0.0 {
            return Ok(b);
        }
        if e.abs() >= tol && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * m * s;
                q = 1.0 - s;
            } else {
                let qq = fa / fc;
                let r = fb / fc;
                p = s * (2.0 * m * qq * (qq - r) - (b - a) * (r - 1.0));
                q = (qq - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (tol * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol { d } else { tol.copysign(m) };
        fb = f(b)?;
    }
    Err(NumericError::NoConvergence("Brent iteration limit".into()).into())
}

/// Secant iteration from `x0` (where `f(x0) = f0` is already known) with
/// first step `step`, stopping when the next update is below `xtol`;
/// returns the last *evaluated* iterate (its distance to the root is about
/// that last update) and the last secant slope, or `None` when it does not
/// settle within `max_iter` steps (the caller then brackets).
pub fn secant<E, F>(
    f: &mut F,
    x0: f64,
    f0: f64,
    step: f64,
    xtol: f64,
    max_iter: usize,
    range: (f64, f64),
) -> Result<Option<(f64, f64)>, E>
where
    F: FnMut(f64) -> Result<f64, E>,
    E: From<NumericError>,
{
    let (mut a, mut fa) = (x0, f0);
    let mut b = x0 + step;
    let mut fb = f(b)?;
    for _ in 0..max_iter {
        if fb == fa {
            return Ok(if fb == 0.0 { Some((b, 0.0)) } else { None });
        }
        let slope = (fb - fa) / (b - a);
        let nb = b - fb / slope;
        if !nb.is_finite() || nb <= range.0 || nb >= range.1 {
            return Ok(None);
        }
        if (nb - b).abs() <= xtol {
            return Ok(Some((b, slope)));
        }
        a = b;
        fa = fb;
        b = nb;
        fb = f(b)?;
    }
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn brent_and_secant_find_roots() {
        let mut f = |x: f64| -> Result<f64, NumericError> { Ok(x.cos() - x) };
        let (a, fa, b, fb) = bracket(&mut f, 0.0, 0.1, -10.0, 10.0).unwrap();
        let r = brent(&mut f, a, fa, b, fb, 1e-15).unwrap();
        assert!((r - 0.739_085_133_215_160_6).abs() < 1e-14);
        let f0 = f(0.7).unwrap();
        let (s, slope) = secant(&mut f, 0.7, f0, 1e-3, 1e-15, 20, (0.0, 1.0))
            .unwrap()
            .unwrap();
        let (a, fa, b, fb) =
            directed_bracket(&mut f, 0.1, false, |x| 2.0 * x, |x| 0.5 * x, 20).unwrap();
        assert!(a < r && r < b && fa > 0.0 && fb < 0.0);
        assert!((s - r).abs() < 1e-13);
        assert!((slope + 1.0 + r.sin()).abs() < 1e-6);
        let mut g = |x: f64| -> Result<f64, NumericError> { Ok(x * x + 1.0) };
        assert!(bracket(&mut g, 0.0, 1.0, -5.0, 5.0).is_err());
    }
}
