//! The public Hertz solvers: given `(ν, c)` find `μ`, given `(ν, μ)` find
//! `c`, and the frictionless case. Each runs a ladder of discretisations
//! ([`Resolution::level`]); on the first it brackets the singular
//! coefficient `B` of the stick shear (using its known monotonicity: `B`
//! falls with `μ` and rises with `c`) and applies Brent's method, on each
//! further level it starts a secant iteration from the previous root with
//! a Newton step on the previous slope, and it stops when two successive
//! levels agree to `tol` in the free parameter and in both compliance
//! formulas. A root whose shear is not continuous at `c`, or a sign change
//! across a pole of `B`, is refused with an error.
//!
//! Measured range (tol 1e-8): given `c ∈ [1e-3, 0.99]` works for ν = 0,
//! 0.25, 0.45; given `μ` works while the resulting `c` lies in about
//! `[1e-3, 0.9996]`. Below `c ≈ 4e-4` (ν = 0) the bounded-shear condition
//! degenerates (∂B/∂μ changes sign near `c ≈ 3.5e-4`) and the solvers
//! return errors. Owns this control logic; the discretisation is in
//! `system.rs`, evaluation and checks in `solution.rs`.
use std::f64::consts::FRAC_PI_2;

use nalgebra::DVector;
use serde::Serialize;

use super::operators::{edge_exponent, gamma_of_nu, kappa1};
use super::roots::{brent, directed_bracket, secant};
use super::solution::{Fields, HertzSolution, profile_points};
use super::system::{Discrete, Frame, Resolution};
use lambdamat::hertz::HertzError;
use lambdamat::numeric::solve::{CheckedLu, DEFAULT_MAX_COND};
use lambdamat::numeric::{Assembler, Factor, Mesh, PanelBasis};

/// Accuracy controls.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct HertzOptions {
    /// Stop when successive levels agree to `tol` (absolute).
    pub tol: f64,
    /// Highest level of [`Resolution::level`] tried.
    pub max_level: usize,
}

impl Default for HertzOptions {
    fn default() -> HertzOptions {
        HertzOptions {
            tol: 1e-10,
            max_level: 8,
        }
    }
}

struct Level {
    param: f64,
    slope: f64,
    pstar: f64,
    pstar_shear: f64,
}

impl Level {
    fn distance(&self, other: &Level) -> f64 {
        (self.param - other.param)
            .abs()
            .max((self.pstar - other.pstar).abs())
            .max((self.pstar_shear - other.pstar_shear).abs())
    }
}

fn check_nu(nu: f64) -> Result<f64, HertzError> {
    if !(0.0..=0.5).contains(&nu) {
        return Err(HertzError::InvalidParameter(format!(
            "Poisson's ratio ν = {nu} not in [0, 1/2]"
        )));
    }
    Ok(gamma_of_nu(nu))
}

fn check_opts(o: &HertzOptions) -> Result<(), HertzError> {
    if !(o.tol > 0.0 && o.tol.is_finite()) {
        return Err(HertzError::InvalidParameter(format!(
            "tolerance {} must be positive",
            o.tol
        )));
    }
    Ok(())
}

/// `1 - √(1-t²)` without cancellation.
fn shear_weight(t: f64) -> f64 {
    t * t / (1.0 + (1.0 - t * t).max(0.0).sqrt())
}

/// Both compliance formulas for a discrete solution.
fn compliances(
    gamma: f64,
    mu: f64,
    c: f64,
    frame: &Frame,
    d: &Discrete,
) -> Result<(f64, f64), HertzError> {
    let asm = Assembler::new(&d.p_basis)?;
    let pstar = FRAC_PI_2 * DVector::from_vec(asm.functional(|t| t, 0.0, 1.0)?).dot(&d.p);
    let slip = DVector::from_vec(asm.functional(shear_weight, c, 1.0)?).dot(&d.p) * mu;
    let qa = Assembler::new(&frame.q_basis)?;
    let stick = DVector::from_vec(qa.functional(shear_weight, 0.0, c)?).dot(&d.q);
    Ok((pstar, 1.0 + gamma * (stick + slip)))
}

/// Solves for the friction coefficient `μ` that makes `c` the stick radius
/// at Poisson's ratio `ν`, then `p`, `q`, `u`, `P*` and the checks.
///
/// ```no_run
/// use lambdamat::hertz::{solve_given_c, HertzOptions};
/// let s = solve_given_c(0.0, 0.5, &HertzOptions::default()).unwrap();
/// assert!((s.mu - 0.2986).abs() < 1e-3);
/// ```
pub fn solve_given_c(nu: f64, c: f64, opts: &HertzOptions) -> Result<HertzSolution, HertzError> {
    let gamma = check_nu(nu)?;
    check_opts(opts)?;
    if !(c > 0.0 && c < 1.0) {
        return Err(HertzError::InvalidParameter(format!(
            "stick radius c = {c} not in (0,1)"
        )));
    }
    if gamma == 0.0 {
        return Err(HertzError::InvalidParameter(
            "ν = 1/2 decouples normal and shear stress: the stick zone is the whole contact (c = 1) for every μ".into(),
        ));
    }
    let mut levels: Vec<Level> = Vec::new();
    for k in 0..=opts.max_level {
        let frame = Frame::new(gamma, c, &Resolution::level(k))?;
        let mut evals: Vec<(f64, Discrete)> = Vec::new();
        let mut f = |mu: f64| -> Result<f64, HertzError> {
            let d = frame.solve(mu)?;
            let r = d.singular;
            evals.push((mu, d));
            Ok(r)
        };
        // B decreases with μ; start from the small-c balance μ ≈ γ/ln(2/c).
        let search = Search {
            start: gamma / (2.0 / c).ln().max(0.5),
            increasing: false,
            range: (0.0, f64::INFINITY),
            relative: false,
        };
        let (mu, slope) = find_root(&mut f, &levels, &search, opts.tol)?;
        let d = match evals.into_iter().rev().find(|e| e.0 == mu) {
            Some(e) => e.1,
            None => frame.solve(mu)?,
        };
        let (pstar, pstar_shear) = compliances(gamma, mu, c, &frame, &d)?;
        let this = Level {
            param: mu,
            slope,
            pstar,
            pstar_shear,
        };
        if let Some(done) = close_level(&mut levels, this, k, opts, (nu, gamma, c), &frame, d) {
            return done;
        }
    }
    Err(HertzError::NoConvergence("empty level ladder".into()))
}

/// Solves for the stick radius `c` at friction `μ` and Poisson's ratio `ν`,
/// then `p`, `q`, `u`, `P*` and the checks. `μ = 0` is the frictionless
/// punch (no stick zone, `c = 0`); `ν = 1/2` decouples the stresses (full
/// stick, `c = 1`, `q = 0`).
pub fn solve_given_mu(nu: f64, mu: f64, opts: &HertzOptions) -> Result<HertzSolution, HertzError> {
    let gamma = check_nu(nu)?;
    check_opts(opts)?;
    if !(mu >= 0.0 && mu.is_finite()) {
        return Err(HertzError::InvalidParameter(format!(
            "friction μ = {mu} must be finite and ≥ 0"
        )));
    }
    if mu == 0.0 {
        return solve_frictionless(nu, mu, 0.0, opts);
    }
    if gamma == 0.0 {
        return solve_frictionless(nu, mu, 1.0, opts);
    }
    let mut levels: Vec<Level> = Vec::new();
    for k in 0..=opts.max_level {
        let res = Resolution::level(k);
        let mut evals: Vec<(f64, Frame, Discrete)> = Vec::new();
        let mut f = |c: f64| -> Result<f64, HertzError> {
            let frame = Frame::new(gamma, c, &res)?;
            let d = frame.solve(mu)?;
            let r = d.singular;
            evals.push((c, frame, d));
            Ok(r)
        };
        // Start near c ≈ 2 exp(-γ/μ) (the small-c balance of the two terms
        // of R(c)); R also vanishes on a spurious branch near c ≈ 3.5e-4
        // (ν = 0) where ∂R/∂μ changes sign, so the start matters.
        // B increases with c.
        let search = Search {
            start: (2.0 * (-gamma / mu).exp()).clamp(2e-3, 0.9),
            increasing: true,
            // Stick zones below 1e-7 are far outside the reliable range.
            range: (1e-7, 1.0),
            relative: true,
        };
        let (c, slope) = find_root(&mut f, &levels, &search, opts.tol)?;
        let (frame, d) = match evals.into_iter().rev().find(|e| e.0 == c) {
            Some(e) => (e.1, e.2),
            None => {
                let fr = Frame::new(gamma, c, &res)?;
                let d = fr.solve(mu)?;
                (fr, d)
            }
        };
        let (pstar, pstar_shear) = compliances(gamma, mu, c, &frame, &d)?;
        let this = Level {
            param: c,
            slope,
            pstar,
            pstar_shear,
        };
        if let Some(done) = close_level(&mut levels, this, k, opts, (nu, gamma, c), &frame, d) {
            return done;
        }
    }
    Err(HertzError::NoConvergence("empty level ladder".into()))
}

/// Tolerance of the root iterations: a twentieth of the requested accuracy
/// (so the last secant step is usually skipped); it is added to the error
/// estimate.
fn root_tolerance(tol: f64) -> f64 {
    (0.05 * tol).clamp(1e-15, 1e-9)
}

/// How the first level looks for a sign change of the singular
/// coefficient `B`.
struct Search {
    /// Starting point.
    start: f64,
    /// `B` increases with the argument.
    increasing: bool,
    /// Admissible open range of the argument.
    range: (f64, f64),
    /// Scale the root tolerance by the distance to the range's ends (for
    /// `c`, whose neighbourhood shrinks as `c → 0` or `c → 1`).
    relative: bool,
}

/// Root of `f` on this level and the slope of `f` there: on the first level
/// a directed bracket search from `search.start` and Brent; afterwards a
/// secant iteration started from the previous level's root with a Newton
/// step on the previous slope (a new bracket and Brent if that fails).
fn find_root<F>(
    f: &mut F,
    levels: &[Level],
    search: &Search,
    tol: f64,
) -> Result<(f64, f64), HertzError>
where
    F: FnMut(f64) -> Result<f64, HertzError>,
{
    let (lo, hi) = search.range;
    let near = levels.last().map_or(search.start, |l| l.param);
    let scale = if search.relative {
        (near - lo).min(hi - near).min(1.0)
    } else {
        1.0
    };
    let xtol = (root_tolerance(tol) * scale).max(1e-15);
    let room = |x: f64| 0.25 * (hi - x).min(x - lo);
    let up = |x: f64| {
        if hi.is_finite() {
            x + 0.5 * (hi - x)
        } else {
            1.5 * x
        }
    };
    let down = |x: f64| lo + 0.5 * (x - lo);
    if let Some(last) = levels.last() {
        let x0 = last.param;
        let f0 = f(x0)?;
        let mut step = if last.slope != 0.0 && last.slope.is_finite() {
            -f0 / last.slope
        } else {
            1e-6
        };
        if step == 0.0 {
            step = 1e-12;
        }
        let step = step.clamp(-room(x0), room(x0));
        if let Some(r) = secant(f, x0, f0, step, xtol, 12, search.range)? {
            return Ok(r);
        }
        let (a, fa, b, fb) = directed_bracket(f, x0, search.increasing, up, down, 80)?;
        let x = brent(f, a, fa, b, fb, xtol)?;
        check_not_pole(f, x, fa, fb)?;
        return Ok((x, last.slope));
    }
    let (a, fa, b, fb) = directed_bracket(f, search.start, search.increasing, up, down, 80)?;
    let x = brent(f, a, fa, b, fb, xtol)?;
    check_not_pole(f, x, fa, fb)?;
    // Slope at the root by one extra evaluation (cheap on the first level).
    let h = 1e-6 * room(x).min(x.abs()).max(1e-12);
    let slope = (f(x + h)? - f(x)?) / h;
    Ok((x, slope))
}

/// `B` is a ratio of determinants in the parameter and can change sign
/// across a pole; Brent then converges to the pole. Refuse that.
fn check_not_pole<F>(f: &mut F, x: f64, fa: f64, fb: f64) -> Result<(), HertzError>
where
    F: FnMut(f64) -> Result<f64, HertzError>,
{
    let fx = f(x)?;
    if fx.abs() <= 1e-6 * (fa.abs() + fb.abs()) {
        Ok(())
    } else {
        Err(HertzError::NoConvergence(format!(
            "the free-boundary residual changes sign across a pole near {x:.6e} (value {fx:.3e}), not a root"
        )))
    }
}

/// Records one refinement level; once successive levels agree to the
/// tolerance (or the ladder ends) returns the finished solution.
fn close_level(
    levels: &mut Vec<Level>,
    this: Level,
    k: usize,
    opts: &HertzOptions,
    (nu, gamma, c): (f64, f64, f64),
    frame: &Frame,
    d: Discrete,
) -> Option<Result<HertzSolution, HertzError>> {
    let est = levels
        .last()
        .map(|l| this.distance(l) + 2.0 * root_tolerance(opts.tol));
    levels.push(this);
    let converged = est.is_some_and(|e| e <= opts.tol);
    (converged || k == opts.max_level).then(|| {
        finish(
            nu,
            gamma,
            c,
            frame,
            d,
            levels,
            est.unwrap_or(f64::INFINITY),
            converged,
            opts.tol,
        )
    })
}

#[allow(clippy::too_many_arguments)]
fn finish(
    nu: f64,
    gamma: f64,
    c: f64,
    frame: &Frame,
    d: Discrete,
    levels: &[Level],
    est: f64,
    converged: bool,
    tol: f64,
) -> Result<HertzSolution, HertzError> {
    let last = levels
        .last()
        .ok_or_else(|| HertzError::NoConvergence("no level".into()))?;
    let (mu, alpha, cond, residual_c) = (d.mu, d.alpha, d.cond, d.residual_c);
    let unknowns = frame.size();
    let fields = Fields::new(
        gamma,
        mu,
        c,
        d.p_basis,
        d.p,
        Some(frame.q_basis.clone()),
        d.q,
        d.singular,
    )?;
    let mut s = HertzSolution {
        nu,
        gamma,
        mu,
        c,
        alpha,
        compliance: last.pstar,
        compliance_via_shear: last.pstar_shear,
        compliance_difference: last.pstar - last.pstar_shear,
        error_estimate: est,
        converged,
        tol,
        stick_ok: false,
        slip_ok: false,
        residual_c,
        shear_jump_at_c: 0.0,
        unknowns,
        levels: levels.len(),
        condition: cond,
        fields,
    };
    // Bounded, continuous shear: q(c⁻) = μ p(c) (the stick shear's last
    // panel is closed at c; p's panel to the right of c starts there).
    if let Some(qb) = &s.fields.q_basis {
        s.shear_jump_at_c = qb.eval(s.fields.q.as_slice(), c) - s.mu * s.p(c);
        // A root of the bounded-shear condition whose shear still jumps at c
        // is not the physical free boundary. This happens at very small
        // stick zones (measured at ν = 0: c ≲ 4e-4, μ ≲ 0.065), where the
        // condition degenerates (∂B/∂μ changes sign); refuse it.
        let mup = (s.mu * s.p(c)).abs();
        if s.shear_jump_at_c.is_nan() || s.shear_jump_at_c.abs() > 0.1 * mup {
            return Err(HertzError::NoConvergence(format!(
                "spurious free boundary at c = {c:.4e}, μ = {:.4e}: q(c⁻) - μp(c) = {:.3e} (μp(c) = {mup:.3e}); \
                 c this close to 0 or 1 is outside the solver's reliable range",
                s.mu, s.shear_jump_at_c
            )));
        }
    }
    let samples = s.sample(&profile_points(c, 200))?;
    s.stick_ok = samples.iter().filter(|v| v.x < c).all(|v| v.q < v.mu_p);
    s.slip_ok = samples.iter().filter(|v| v.x > c).all(|v| v.u < 0.0);
    Ok(s)
}

/// The frictionless (or decoupled) problem `κ1 p = 1`, `q = 0`, on a mesh
/// graded toward 1 with the weight `(1-t)^{-1/2}`; `c` is recorded as
/// given (0: no stick zone, 1: full stick).
fn solve_frictionless(
    nu: f64,
    mu: f64,
    c: f64,
    opts: &HertzOptions,
) -> Result<HertzSolution, HertzError> {
    let gamma = gamma_of_nu(nu);
    // The weight (1-t)^{-1/2} is the whole singularity (φ is analytic), so
    // uniform panels with rising degree suffice; the estimate compares P*
    // and p itself (relative, on a grid) between successive levels.
    let grid: Vec<f64> = (0..200).map(|i| i as f64 / 200.0).collect();
    let mut prev: Option<(f64, Vec<f64>)> = None;
    for k in 0..=opts.max_level {
        let mesh = Mesh::uniform(0.0, 1.0, 2 + k / 3)?;
        let n = 6 + 2 * k;
        let basis = PanelBasis::new(
            &mesh,
            &vec![n; mesh.panels()],
            vec![Factor {
                at: 1.0,
                exponent: -0.5,
            }],
        )?;
        let asm = Assembler::new(&basis)?;
        let xs = basis.nodes();
        let a = asm.matrix(&kappa1(), &xs)?;
        let lu = CheckedLu::new(&a, DEFAULT_MAX_COND)?;
        let p = lu.solve(&DVector::from_element(xs.len(), 1.0))?;
        let pstar = FRAC_PI_2 * DVector::from_vec(asm.functional(|t| t, 0.0, 1.0)?).dot(&p);
        let values: Vec<f64> = grid.iter().map(|&x| basis.eval(p.as_slice(), x)).collect();
        let est = prev.as_ref().map(|(q, v)| {
            let dp = values
                .iter()
                .zip(v)
                .map(|(a, b)| ((a - b) / a).abs())
                .fold(0.0, f64::max);
            (pstar - q).abs().max(dp)
        });
        let converged = est.is_some_and(|e| e <= opts.tol);
        if converged || k == opts.max_level {
            let fields = Fields::new(gamma, 0.0, c, basis, p, None, DVector::zeros(0), 0.0)?;
            let s = HertzSolution {
                nu,
                gamma,
                mu,
                c,
                alpha: edge_exponent(gamma, 0.0),
                compliance: pstar,
                compliance_via_shear: 1.0,
                compliance_difference: pstar - 1.0,
                error_estimate: est.unwrap_or(f64::INFINITY),
                converged,
                tol: opts.tol,
                // q = 0: no slip anywhere, and 0 < μp wherever there is stick.
                stick_ok: true,
                slip_ok: true,
                residual_c: 0.0,
                shear_jump_at_c: 0.0,
                unknowns: xs.len(),
                levels: k + 1,
                condition: lu.cond(),
                fields,
            };
            return Ok(s);
        }
        prev = Some((pstar, values));
    }
    Err(HertzError::NoConvergence("empty level ladder".into()))
}
