//! The fields of a solved split-domain problem at any point: each unknown
//! (free, substituted by a relation, plus its exact singular terms) from
//! either side of a subinterval end, and the residual `lhs − rhs` of each
//! equation at any point of the unknowns' interval, whether or not the
//! equation is imposed there; the residual of an equation on a
//! subinterval where it is not imposed is the quantity it leaves free
//! there (for the Hertz problem, E2's residual on the slip zone defines the
//! slip, docs/hertz.md). Owns evaluation of a finished [`Discrete`] only: it
//! must not discretise, solve or iterate on scalars (that is `split.rs` and
//! `split_solve.rs`), and it reads the discretisation through their public
//! accessors, never their internals. [`LevelFields`] pairs the last
//! level's fields with the previous level's, so that every field value
//! carries an error estimate: the distance between the two levels at the
//! same point, as the solver's estimate of a scalar or an output is the
//! distance between the two levels' values.
use nalgebra::{DMatrix, DVector};

use super::error::PlanError;
use super::split::{Discrete, SplitProblem};
use super::split_input::SplitKind;
use super::split_solve::SplitSolution;
use crate::numeric::{Assembler, Mesh, Operator, PanelBasis};

/// From which side a point is approached (it matters only at subinterval
/// ends and panel ends, where the discrete fields may jump).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Approach {
    /// The limit from below (`x⁻`).
    Below,
    /// The limit from above (`x⁺`).
    Above,
}

/// An equation's residual interpolated on the level's mesh panels that
/// tile an interval (an unweighted panel basis, values at its nodes).
#[derive(Debug, Clone)]
pub struct ResidualField {
    /// The unweighted basis on the panels of the interval.
    pub basis: PanelBasis,
    /// The residual at the basis nodes (its coefficients).
    pub values: Vec<f64>,
}

impl ResidualField {
    /// The interpolated residual at `x` (zero outside the interval).
    #[cfg(any(test, feature = "internals"))]
    pub fn eval(&self, x: f64) -> f64 {
        self.basis.eval(&self.values, x)
    }
}

/// Evaluation of the unknowns and residuals of one discrete solution.
///
/// ```no_run
/// use lambdamat::plan::split_fields::{Approach, Fields};
/// # fn f(s: &lambdamat::plan::SplitSolution) -> Result<(), lambdamat::plan::PlanError> {
/// let f = Fields::new(&s.problem, &s.discrete)?;
/// let q = f.unknown_index("q").expect("q");
/// println!("q(0.3) = {}", f.value(q, 0.3, Approach::Above)?);
/// println!("E2 residual at 0.9: {}", f.residual(1, 0.9)?);
/// # Ok(()) }
/// ```
pub struct Fields<'a> {
    problem: &'a SplitProblem,
    d: &'a Discrete,
    asms: Vec<Option<Assembler<'a>>>,
    term_asms: Vec<Assembler<'a>>,
    /// The intermediate basis of operator products, if any.
    mid: Option<Assembler<'a>>,
}

fn invalid(s: String) -> PlanError {
    PlanError::Invalid(s)
}

/// `W(x)·φ(x)` on the panel of `basis` that `x` is approached from.
fn eval_side(basis: &PanelBasis, coef: &[f64], x: f64, side: Approach) -> f64 {
    let (lo, hi) = basis.support();
    if !(x >= lo && x <= hi) || basis.panels.is_empty() {
        return 0.0;
    }
    let k = match side {
        Approach::Below => basis.panels.partition_point(|p| p.b < x),
        Approach::Above => basis.panels.partition_point(|p| p.b <= x),
    }
    .min(basis.panels.len() - 1);
    let p = &basis.panels[k];
    let mut l = vec![0.0; p.nodes.len()];
    p.lagrange(x, &mut l);
    let phi: f64 = l
        .iter()
        .zip(&coef[p.offset..p.offset + l.len()])
        .map(|(a, b)| a * b)
        .sum();
    phi * basis.weight_at(x)
}

/// A field value with its error estimate.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Valued {
    /// The value on the last level.
    pub value: f64,
    /// `|last − previous|`, the two levels' values of the same quantity
    /// (infinite when only one level was climbed, or when the previous
    /// level's value is not finite).
    pub error: f64,
}

impl Valued {
    /// An exact zero.
    pub const ZERO: Valued = Valued {
        value: 0.0,
        error: 0.0,
    };

    /// `a·self` (the estimate scales with `|a|`).
    #[cfg(feature = "internals")]
    pub fn scale(self, a: f64) -> Valued {
        Valued {
            value: a * self.value,
            error: a.abs() * self.error,
        }
    }
}

/// Points per window of [`LevelFields::window`] besides the point itself.
const WINDOW_POINTS: usize = 9;

/// The fields of the last two levels of a solve: each quantity evaluated on
/// both, its estimate the largest distance between them over a window
/// around the point (the ladder's estimate, [`crate::plan::split_solve`],
/// applied pointwise), plus what the scalars' own uncertainty makes
/// uncertain at a fixed point near an end that moves with them
/// ([`LevelFields::shift_term`]).
///
/// Why a window: the error of a collocation field oscillates within each
/// panel, and the difference of two levels crosses zero at points where
/// the last level's own error need not (measured on the Hertz problem at
/// (ν, c) = (0.25, 0.8): the plain difference at the point fell to 1/50 of
/// the true error at isolated points). The window is the previous level's
/// panel around the point (its error's natural scale), clipped to the
/// subinterval the point lies on in both levels, sampled at its Chebyshev
/// points. Measured (`probes/field_errors.rs`, notes of issue 10/13):
/// with the window the estimate bounds the true error at every sampled
/// point of the Hertz problem.
///
/// At a point closer to a scalar-dependent end (e.g. `c`) than the
/// scalar's own estimate, the two levels may lie on different sides of it,
/// and the estimate is then as large as the jump there: honest, since the
/// point's side is not known to that accuracy.
pub struct LevelFields<'a> {
    /// The last level (the values reported).
    pub last: Fields<'a>,
    /// The previous level, if there is one.
    pub previous: Option<Fields<'a>>,
    /// The largest error estimate of the unknown scalars (0 without).
    pub scalar_error: f64,
    /// The last level's subinterval ends that depend on an unknown scalar.
    moving: Vec<f64>,
    /// The last level discretised at the scalars moved by their estimate
    /// ([`SplitSolution::shifted`]), when there is one: what the scalars'
    /// uncertainty makes uncertain at a point is its change there
    /// ([`LevelFields::windowed`]).
    shifted: Option<Fields<'a>>,
    /// Per unknown, what turns its level difference into its estimate
    /// (the ladder's, [`crate::plan::split_solve::UnknownEstimate`]):
    /// `(factor, floor)`, the estimate at a point being
    /// `max(factor·difference, floor)`. `(1, 0)` (the plain difference)
    /// for an unknown the ladder did not estimate.
    bounds: Vec<(f64, f64)>,
}

/// One unknown sampled on the output grid ([`LevelFields::on_grid`]).
#[derive(Debug, Clone, Default)]
pub struct GridField {
    /// The points kept.
    pub x: Vec<f64>,
    /// The unknown there (last level).
    pub values: Vec<f64>,
    /// The estimate there ([`LevelFields::value`]).
    pub errors: Vec<f64>,
    /// The unknown's size: its largest `|u/weight|` on the points kept
    /// (the weight of its basis; 1 where it has none).
    pub size: f64,
    /// The grid points left out, each with why ([`LevelFields::on_grid`]).
    pub left_out: Vec<LeftOut>,
}

/// A point of the output grid left out of an unknown's values and
/// estimates ([`LevelFields::on_grid`]).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct LeftOut {
    /// The point.
    pub x: f64,
    /// Why.
    pub reason: LeftOutReason,
}

/// Why a grid point is left out ([`LevelFields::on_grid`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LeftOutReason {
    /// A singular term's own point: the fields there are one-sided limits
    /// of singular behaviours.
    SingularPoint,
    /// An end of the unknowns' interval the end check graded: the
    /// behaviour there is not resolved pointwise (it may be infinite, as
    /// the cone's pressure at its centre).
    GradedEnd,
    /// Within the scalars' estimate of an end that moves with them: the
    /// point's side is not known.
    MovingEnd,
    /// The value is not finite.
    NotFinite,
    /// The estimate is not finite (a level that has none).
    NoEstimate,
}

impl<'a> LevelFields<'a> {
    /// The fields of `s`'s last two levels, each unknown's estimate
    /// bounded as the ladder bounded it (`s.report.unknowns`).
    pub fn new(s: &'a SplitSolution) -> Result<LevelFields<'a>, PlanError> {
        let mut lf = LevelFields::pair(
            &s.problem,
            &s.discrete,
            s.previous.as_ref(),
            s.report.scalars.iter().map(|e| e.error).fold(0.0, f64::max),
        )?;
        lf.shifted = s
            .shifted
            .as_ref()
            .map(|d| Fields::new(&s.problem, d))
            .transpose()?;
        for e in &s.report.unknowns {
            if let Some(u) = lf.last.unknown_index(&e.name) {
                lf.bounds[u] = (e.factor, e.floor);
            }
        }
        Ok(lf)
    }

    /// The fields of discretisation `last` beside `previous` (the level
    /// before), with the scalars' estimate `scalar_error`; each unknown's
    /// estimate is the plain level difference (factor 1, no floor).
    pub fn pair(
        problem: &'a SplitProblem,
        last: &'a Discrete,
        previous: Option<&'a Discrete>,
        scalar_error: f64,
    ) -> Result<LevelFields<'a>, PlanError> {
        let last = Fields::new(problem, last)?;
        Ok(LevelFields {
            moving: last.scalar_ends(),
            last,
            previous: previous.map(|d| Fields::new(problem, d)).transpose()?,
            scalar_error,
            bounds: vec![(1.0, 0.0); problem.sys.unknowns.len()],
            shifted: None,
        })
    }

    /// These fields with `shifted`, the last level discretised at the
    /// scalars moved by their estimate, as the measure of what the
    /// scalars' uncertainty makes uncertain ([`LevelFields::windowed`]).
    pub fn with_shifted(
        mut self,
        problem: &'a SplitProblem,
        shifted: Option<&'a Discrete>,
    ) -> Result<LevelFields<'a>, PlanError> {
        self.shifted = shifted.map(|d| Fields::new(problem, d)).transpose()?;
        Ok(self)
    }

    /// Unknown `u` on `n` equally spaced points of its interval (its
    /// declared one, else the whole; the last point approached from below,
    /// the others from above) with the estimates of [`LevelFields::value`]:
    /// the output grid of every report. Left out are the points where the
    /// value is not finite, the points at a singular term's own point (of
    /// any unknown: the fields there are one-sided limits of singular
    /// behaviours, which the level differences do not estimate) and those
    /// within the scalars' estimate of an end that moves with them (their
    /// side is not known); and, when `skip_unestimated`, points whose
    /// estimate is not finite.
    ///
    /// **Graded ends.** Also left out are the ends of the unknowns'
    /// interval that the end check graded (`split_ends.rs`,
    /// [`SplitProblem::graded_ends`]): grading them moved an answer, so the
    /// unknowns' behaviour there is not a polynomial's, and the value at
    /// the end is a limit the collocation does not resolve. The cone's
    /// pressure is logarithmically infinite at its centre
    /// (`examples/contact/cone.lmx`), and under an Abel operator
    /// `∫_x t u(t)/√(t² − x²) dt` the innermost panel `[0, h]` is seen only
    /// through `O(h)`, so even a finite end value (the Cattaneo–Mindlin
    /// pressure at `x = 0`) is off by `O(1)` there while the points of the
    /// open interval converge. The estimates then hold on the half-open or
    /// open interval, and [`GridField::left_out`] (the report's
    /// `left_out` of each unknown) names every point left out and why.
    /// A plain end the automatic weights chose (few layers,
    /// [`super::split::PLAIN_END_LAYERS`]) stays on the grid: the flat
    /// punch's `p(0)` converges.
    pub fn on_grid(
        &self,
        u: usize,
        n: usize,
        skip_unestimated: bool,
    ) -> Result<GridField, PlanError> {
        let p = self.last.problem;
        let d = self.last.d;
        let (lo, hi) = (d.breaks[0], d.breaks[d.breaks.len() - 1]);
        let (a, b) = match p.contact.unknown_domains.get(u).and_then(Option::as_ref) {
            Some(dom) => {
                let (a, b) = dom.eval(&d.vars);
                (a.max(lo), b.min(hi))
            }
            None => (lo, hi),
        };
        let n = n.max(2);
        let ulps = |z: f64| 4.0 * f64::EPSILON * z.abs().max(1.0);
        let mut avoid: Vec<(f64, f64, LeftOutReason)> = d
            .terms
            .iter()
            .map(|t| (t.at, ulps(t.at), LeftOutReason::SingularPoint))
            .collect();
        avoid.extend(
            p.contact
                .singulars
                .iter()
                .filter(|s| s.unknown == u && matches!(s.kind, SplitKind::Log))
                .map(|s| s.at.eval(&d.vars, 0.0))
                .map(|z| (z, ulps(z), LeftOutReason::SingularPoint)),
        );
        avoid.extend(
            p.graded_ends()
                .iter()
                .map(|&e| (e, ulps(e), LeftOutReason::GradedEnd)),
        );
        if self.scalar_error.is_finite() {
            avoid.extend(
                self.moving
                    .iter()
                    .map(|&e| (e, self.scalar_error, LeftOutReason::MovingEnd)),
            );
        }
        let mut g = GridField::default();
        for k in 0..n {
            let t = a + (b - a) * k as f64 / (n - 1) as f64;
            if let Some(&(_, _, reason)) = avoid.iter().find(|&&(e, r, _)| (t - e).abs() <= r) {
                g.left_out.push(LeftOut { x: t, reason });
                continue;
            }
            let side = if k + 1 == n {
                Approach::Below
            } else {
                Approach::Above
            };
            let v = self.value(u, t, side)?;
            if !v.value.is_finite() || (skip_unestimated && !v.error.is_finite()) {
                let reason = if v.value.is_finite() {
                    LeftOutReason::NoEstimate
                } else {
                    LeftOutReason::NotFinite
                };
                g.left_out.push(LeftOut { x: t, reason });
                continue;
            }
            let w = self.last.weight_at(u, t);
            if w.is_finite() && w != 0.0 {
                g.size = g
                    .size
                    .max(self.last.regular_value(u, t, side)?.abs() / w.abs());
            }
            g.x.push(t);
            g.values.push(v.value);
            g.errors.push(v.error);
        }
        Ok(g)
    }

    /// The end of the subinterval of `x` (from `side`) nearest to `x` that
    /// depends on an unknown scalar (e.g. `c`), with the scalars'
    /// uncertainty `δ`: `(end, δ)`. `None` when neither end depends on one,
    /// or with one level only.
    pub fn moving_end(&self, x: f64, side: Approach) -> Option<(f64, f64)> {
        self.previous.as_ref()?;
        let (lo, hi) = self.last.piece_ends(x, side)?;
        [lo, hi]
            .into_iter()
            .filter(|e| self.moving.contains(e))
            .min_by(|a, b| (a - x).abs().total_cmp(&(b - x).abs()))
            .map(|b| (b, self.scalar_error))
    }

    /// What the uncertainty `δ` of a moving end `b` makes uncertain at `x`
    /// for a field whose values are `fx` at `x` and `fb` next to `b` (on
    /// `x`'s side): near a free boundary a field varies as a power
    /// `(x − b)^β` (β ≤ 3/2 for the Hertz fields), so a shift of the
    /// whole profile by `δ` changes it by about `β·|fx − fb|·δ/|x − b|`;
    /// `2·|fx − fb|·δ / max(|x − b|, δ)`. Needed because the two levels'
    /// roots may agree far better than the root's own estimate (which
    /// holds the root tolerance): measured on the Hertz problem at
    /// (ν, μ) = (0.45, 0.3), 1 − c = 8.8e-5, the slip a few 1e-10 from c
    /// was off by 50 times its level difference, entirely from c.
    pub fn shift_term(x: f64, (b, delta): (f64, f64), fx: f64, fb: f64) -> f64 {
        finite_or_inf(2.0 * (fx - fb).abs() * delta / (x - b).abs().max(delta))
    }

    /// A quantity `q` computed from each level's fields: its value on the
    /// last level, its estimate the distance to the previous level's. `q`
    /// may read the level's own scalars ([`Fields::slot`]): a quantity at
    /// `c` (a one-sided limit there) is compared at each level's own `c`,
    /// as the scalars and outputs are.
    pub fn estimate<F>(&self, q: F) -> Result<Valued, PlanError>
    where
        F: Fn(&Fields<'a>) -> Result<f64, PlanError>,
    {
        let value = q(&self.last)?;
        let error = match &self.previous {
            Some(p) => finite_or_inf((q(p)? - value).abs()),
            None => f64::INFINITY,
        };
        Ok(Valued { value, error })
    }

    /// The points whose level differences estimate the error at `x`
    /// (approached from `side`): `x` itself first, then the Chebyshev
    /// points of the previous level's panel around `x`, clipped to the
    /// subinterval `x` lies on in both levels (interior points, so the
    /// side matters only for `x` itself).
    pub fn window(&self, x: f64, side: Approach) -> Vec<(f64, Approach)> {
        let mut out = vec![(x, side)];
        let Some(prev) = &self.previous else {
            return out;
        };
        let Some((mut a, mut b)) = prev.panel(x, side).or_else(|| self.last.panel(x, side)) else {
            return out;
        };
        for f in [&self.last, prev] {
            if let Some((lo, hi)) = f.piece_ends(x, side) {
                a = a.max(lo);
                b = b.min(hi);
            }
        }
        if a.is_nan() || b.is_nan() || a >= b {
            return out;
        }
        // Interior (Chebyshev–Gauss) points: never a panel end, where a
        // field may be singular (an edge) or jump.
        let n = WINDOW_POINTS as f64;
        for j in 0..WINDOW_POINTS {
            let t = 0.5 * (1.0 - (std::f64::consts::PI * (j as f64 + 0.5) / n).cos());
            out.push((a + (b - a) * t, side));
        }
        out
    }

    /// A quantity `q(fields, y, side)` at `x`: its last-level value, and as
    /// estimate the largest level difference over [`LevelFields::window`].
    pub fn windowed<F>(&self, x: f64, side: Approach, q: F) -> Result<Valued, PlanError>
    where
        F: Fn(&Fields<'a>, f64, Approach) -> Result<f64, PlanError>,
    {
        let value = q(&self.last, x, side)?;
        let Some(prev) = &self.previous else {
            return Ok(Valued {
                value,
                error: f64::INFINITY,
            });
        };
        let mut error = 0.0f64;
        for (i, (y, s)) in self.window(x, side).into_iter().enumerate() {
            let last = if i == 0 { value } else { q(&self.last, y, s)? };
            error = error.max(finite_or_inf((q(prev, y, s)? - last).abs()));
        }
        if let Some(sh) = &self.shifted {
            // Measured: the change at x when the scalars move by their
            // estimate (a point within it of a moving end changes side).
            error += finite_or_inf((q(sh, x, side)? - value).abs());
        } else if let Some(end) = self.moving_end(x, side) {
            // The field next to the end, on x's side (not at it: a
            // singular term may be unbounded there).
            let near = end.0 + 1e-3 * (x - end.0);
            if near != end.0 {
                let fb = q(&self.last, near, side)?;
                error += LevelFields::shift_term(x, end, value, fb);
            }
        }
        Ok(Valued { value, error })
    }

    /// Unknown `u` at `x` from `side`, with its estimate (the largest level
    /// difference over the window around `x`).
    /// The estimate is bounded as the ladder bounded the unknown's: at
    /// least its rounding floor, the difference times its safety factor
    /// ([`crate::plan::split_solve::UnknownEstimate`]).
    pub fn value(&self, u: usize, x: f64, side: Approach) -> Result<Valued, PlanError> {
        let v = self.windowed(x, side, |f, y, s| f.value(u, y, s))?;
        let (factor, floor) = self.bounds.get(u).copied().unwrap_or((1.0, 0.0));
        Ok(Valued {
            value: v.value,
            error: finite_or_inf(factor * v.error).max(floor),
        })
    }
}

fn finite_or_inf(e: f64) -> f64 {
    if e.is_nan() { f64::INFINITY } else { e }
}

impl<'a> Fields<'a> {
    /// The value of slot `i` of this level (the unknown scalars first,
    /// then the real parameters), e.g. the level's own `c`.
    pub fn slot(&self, i: usize) -> Option<f64> {
        self.d.vars.get(i).copied()
    }

    /// The smallest panel of this level's bases that contains `x`
    /// (approached from `side`), as `(a, b)`.
    pub fn panel(&self, x: f64, side: Approach) -> Option<(f64, f64)> {
        self.panel_shape(x, side).map(|(a, b, _)| (a, b))
    }

    /// The smallest panel containing `x` (from `side`), as in
    /// [`Fields::panel`], with its number of nodes: `(a, b, n)`. Two
    /// levels with the same shape there have the same discretisation at
    /// `x`, so their difference there holds only what other panels changed.
    pub fn panel_shape(&self, x: f64, side: Approach) -> Option<(f64, f64, usize)> {
        self.d
            .bases
            .iter()
            .flatten()
            .chain(self.d.terms.iter().map(|t| &t.basis))
            .filter_map(|b| {
                b.panels
                    .iter()
                    .find(|p| match side {
                        Approach::Below => x > p.a && x <= p.b,
                        Approach::Above => x >= p.a && x < p.b,
                    })
                    .map(|p| (p.a, p.b, p.nodes.len()))
            })
            .min_by(|u, v| (u.1 - u.0).total_cmp(&(v.1 - v.0)))
    }

    /// The subinterval ends (equation and relation interval ends, singular
    /// points) of this level that depend on an unknown scalar: those that
    /// move when the scalars' slots move.
    pub fn scalar_ends(&self) -> Vec<f64> {
        let c = &self.problem.contact;
        let ns = c.scalars.len();
        let vars = &self.d.vars;
        let mut moved = vars.clone();
        for v in moved.iter_mut().take(ns) {
            *v = *v * (1.0 + 1e-6) + 1e-9;
        }
        let mut out = Vec::new();
        let mut check = |a: f64, b: f64| {
            if a != b && a.is_finite() {
                out.push(a);
            }
        };
        for d in c.equation_domains.iter().flatten() {
            let ((lo, hi), (lo2, hi2)) = (d.eval(vars), d.eval(&moved));
            check(lo, lo2);
            check(hi, hi2);
        }
        for r in &c.relations {
            let ((lo, hi), (lo2, hi2)) = (r.domain.eval(vars), r.domain.eval(&moved));
            check(lo, lo2);
            check(hi, hi2);
        }
        for s in &c.singulars {
            check(s.at.eval(vars, 0.0), s.at.eval(&moved, 0.0));
        }
        out.sort_by(f64::total_cmp);
        out.dedup();
        out
    }

    /// The ends of the subinterval `x` lies on, approached from `side`.
    pub fn piece_ends(&self, x: f64, side: Approach) -> Option<(f64, f64)> {
        let k = self.piece(x, side).ok()?;
        Some((self.d.breaks[k], self.d.breaks[k + 1]))
    }

    /// Prepares evaluation of `d`, a discretisation of `problem`.
    pub fn new(problem: &'a SplitProblem, d: &'a Discrete) -> Result<Fields<'a>, PlanError> {
        let ctx = || PlanError::numeric("field evaluation");
        let asms = d
            .bases
            .iter()
            .map(|b| b.as_ref().map(Assembler::new).transpose())
            .collect::<Result<Vec<_>, _>>()
            .map_err(ctx())?;
        let term_asms = d
            .terms
            .iter()
            .map(|t| Assembler::new(&t.basis))
            .collect::<Result<Vec<_>, _>>()
            .map_err(ctx())?;
        let mid = d
            .mid
            .as_ref()
            .map(Assembler::new)
            .transpose()
            .map_err(ctx())?;
        Ok(Fields {
            problem,
            d,
            asms,
            term_asms,
            mid,
        })
    }

    /// The weight of unknown `u`'s basis at `x` (1 where it has none).
    pub fn weight_at(&self, u: usize, x: f64) -> f64 {
        match self.d.bases.get(u).and_then(Option::as_ref) {
            Some(b) => b.weight_at(x),
            None => 1.0,
        }
    }

    /// Index of the unknown called `name`.
    pub fn unknown_index(&self, name: &str) -> Option<usize> {
        self.problem.sys.unknowns.iter().position(|u| u == name)
    }

    /// The subinterval `x` lies on, approached from `side`.
    fn piece(&self, x: f64, side: Approach) -> Result<usize, PlanError> {
        let b = &self.d.breaks;
        let (lo, hi) = (b[0], b[b.len() - 1]);
        if !(x >= lo && x <= hi) {
            return Err(invalid(format!(
                "x = {x} is outside the unknowns' interval [{lo}, {hi}]"
            )));
        }
        let k = match side {
            Approach::Below => b.partition_point(|&z| z < x),
            Approach::Above => b.partition_point(|&z| z <= x),
        };
        Ok(k.saturating_sub(1).min(b.len() - 2))
    }

    fn unknown(&self, u: usize) -> Result<(), PlanError> {
        if u < self.problem.sys.unknowns.len() {
            Ok(())
        } else {
            Err(invalid(format!("no unknown #{u}")))
        }
    }

    /// Unknown `u` at `x` approached from `side`, with its exact singular
    /// terms (unbounded at a term's own point unless its coefficient is
    /// zero: use [`Fields::regular_value`] there).
    pub fn value(&self, u: usize, x: f64, side: Approach) -> Result<f64, PlanError> {
        self.value_with(u, x, side, true)
    }

    /// Unknown `u` at `x` from `side` without its exact singular terms
    /// (the bounded part, e.g. the one-sided limit at a singular point).
    pub fn regular_value(&self, u: usize, x: f64, side: Approach) -> Result<f64, PlanError> {
        self.value_with(u, x, side, false)
    }

    fn value_with(&self, u: usize, x: f64, side: Approach, terms: bool) -> Result<f64, PlanError> {
        self.unknown(u)?;
        let k = self.piece(x, side)?;
        if self.d.is_zero(u, k) {
            return Ok(0.0);
        }
        if let Some((factor, other)) = self.d.relation(u, k) {
            if self.d.relation(other, k).is_some() {
                return Err(invalid(format!(
                    "{} is substituted by an unknown that is not free",
                    self.problem.sys.unknowns[u]
                )));
            }
            return Ok(factor * self.value_with(other, x, side, terms)?);
        }
        let mut v = match &self.d.bases[u] {
            Some(b) => eval_side(b, self.d.coefficients_of(u), x, side),
            None => 0.0,
        };
        if terms {
            for (i, t) in self.d.terms.iter().enumerate() {
                if t.unknown != u {
                    continue;
                }
                let (s0, s1) = t.basis.support();
                let on = match side {
                    Approach::Below => x > s0 && x <= s1,
                    Approach::Above => x >= s0 && x < s1,
                };
                if on {
                    v += self.d.term_coefficient(i) * eval_side(&t.basis, &t.phi, x, side);
                }
            }
        }
        Ok(v)
    }

    /// Whether equation `e` is imposed at `x` (its declared interval, with
    /// its open and closed ends; everywhere when it has none).
    #[cfg(any(test, feature = "internals"))]
    pub fn imposed(&self, e: usize, x: f64) -> bool {
        match self
            .problem
            .contact
            .equation_domains
            .get(e)
            .and_then(Option::as_ref)
        {
            Some(dom) => {
                let (lo, hi) = dom.eval(&self.d.vars);
                (x > lo || (dom.lo_closed && x == lo)) && (x < hi || (dom.hi_closed && x == hi))
            }
            None => e < self.problem.sys.equations.len(),
        }
    }

    /// The residual `lhs − rhs` of equation `e` at each point of `xs`,
    /// imposed there or not: every operator of the equation applied by
    /// product integration to every part of its unknown (free basis,
    /// substituted pieces, exact singular terms). At the point of a
    /// singular term an operator that reaches it from the term's side is
    /// unbounded; such points give non-finite values.
    pub fn residuals(&self, e: usize, xs: &[f64]) -> Result<Vec<f64>, PlanError> {
        let eq = self
            .problem
            .sys
            .equations
            .get(e)
            .ok_or_else(|| invalid(format!("no equation #{e}")))?;
        let mut r: Vec<f64> = xs.iter().map(|&x| -(eq.rhs)(x)).collect();
        let add = |r: &mut Vec<f64>,
                   asm: &Assembler,
                   (e, j, op): (usize, usize, Option<&Operator>),
                   window: (f64, f64),
                   coef: &[f64],
                   factor: f64|
         -> Result<(), PlanError> {
            let mut m = match op {
                Some(op) => asm
                    .matrix_on(op, xs, window)
                    .map_err(PlanError::numeric("residual"))?,
                None => DMatrix::zeros(xs.len(), asm.basis().dim()),
            };
            if let Some(p) =
                self.problem
                    .products((e, j), asm, xs, window, self.mid.as_ref(), false)?
            {
                m += p;
            }
            let v = m * DVector::from_column_slice(coef);
            for (ri, vi) in r.iter_mut().zip(v.iter()) {
                *ri += factor * vi;
            }
            Ok(())
        };
        let b = &self.d.breaks;
        for j in 0..self.problem.sys.unknowns.len() {
            let op = self.problem.operator_in(self.d, e, j);
            if op.is_none() && !self.problem.has_products_in(e, j) {
                continue;
            }
            let op = (e, j, op);
            if let (Some(asm), Some(basis)) = (&self.asms[j], &self.d.bases[j]) {
                add(
                    &mut r,
                    asm,
                    op,
                    basis.support(),
                    self.d.coefficients_of(j),
                    1.0,
                )?;
            }
            for k in 0..b.len() - 1 {
                if let Some((factor, other)) = self.d.relation(j, k) {
                    let asm = self.asms[other].as_ref().ok_or_else(|| {
                        invalid(format!(
                            "{} is substituted by an unknown that is nowhere free",
                            self.problem.sys.unknowns[j]
                        ))
                    })?;
                    add(
                        &mut r,
                        asm,
                        op,
                        (b[k], b[k + 1]),
                        self.d.coefficients_of(other),
                        factor,
                    )?;
                }
            }
            for (i, t) in self.d.terms.iter().enumerate() {
                if t.unknown == j {
                    add(
                        &mut r,
                        &self.term_asms[i],
                        op,
                        t.basis.support(),
                        &t.phi,
                        self.d.term_coefficient(i),
                    )?;
                }
            }
        }
        Ok(r)
    }

    /// The residual of equation `e` at one point (see [`Fields::residuals`]).
    pub fn residual(&self, e: usize, x: f64) -> Result<f64, PlanError> {
        Ok(self.residuals(e, &[x])?[0])
    }

    /// The residual of equation `e` interpolated on the level's mesh panels
    /// that tile `[lo, hi]` (same nodes per panel as the unknowns' bases,
    /// unweighted): the natural way to carry the residual of an equation on
    /// a subinterval where it is not imposed into further integrals.
    pub fn residual_field(
        &self,
        e: usize,
        (lo, hi): (f64, f64),
    ) -> Result<ResidualField, PlanError> {
        let mut panels: Vec<(f64, f64, usize)> = Vec::new();
        for basis in self
            .d
            .bases
            .iter()
            .flatten()
            .chain(self.d.terms.iter().map(|t| &t.basis))
        {
            for p in basis.panels.iter().filter(|p| p.a >= lo && p.b <= hi) {
                panels.push((p.a, p.b, p.nodes.len()));
            }
        }
        panels.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.total_cmp(&y.1)));
        panels.dedup_by(|x, y| x.0 == y.0 && x.1 == y.1);
        let tiles = panels.first().is_some_and(|p| p.0 == lo)
            && panels.last().is_some_and(|p| p.1 == hi)
            && panels.windows(2).all(|w| w[0].1 == w[1].0);
        if !tiles {
            return Err(invalid(format!(
                "[{lo}, {hi}] is not a union of the mesh's panels"
            )));
        }
        let mut breaks = vec![lo];
        breaks.extend(panels.iter().map(|p| p.1));
        let counts: Vec<usize> = panels.iter().map(|p| p.2).collect();
        let ctx = || PlanError::numeric("residual field");
        let mesh = Mesh::from_breaks(breaks).map_err(ctx())?;
        let basis = PanelBasis::new(&mesh, &counts, vec![]).map_err(ctx())?;
        let values = self.residuals(e, &basis.nodes())?;
        Ok(ResidualField {
            basis,
            values,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::{SplitOptions, solve_split_fields};

    /// The manufactured split problem (`examples/hertz_split_mms.lmx`):
    /// p = x, q = 4x³ on [0, 1/2), q = μp = x on [1/2, 1]; E2 is imposed
    /// on the stick zone only, and on the slip zone its residual is exactly
    /// `x² − 1/4` (the file extends its right side by `−(x² − 1/4)` there).
    #[test]
    fn manufactured_fields_and_the_residual_where_an_equation_is_not_imposed() {
        let src = include_str!("../../examples/hertz_split_mms.lmx");
        let prog = crate::lang::parse_program(src, "hertz_split_mms.lmx").expect("valid");
        let s = solve_split_fields(&prog, &SplitOptions::default()).expect("solves");
        let c = s.report.scalars[0].value;
        assert!((c - 0.5).abs() <= 1e-10);
        let f = Fields::new(&s.problem, &s.discrete).expect("fields");
        let (p, q) = (
            f.unknown_index("p").expect("p"),
            f.unknown_index("q").expect("q"),
        );
        let mut worst = 0.0f64;
        for i in 1..60 {
            let x = (f64::from(i) + 0.3) / 61.0;
            let q_exact = if x < c { 4.0 * x * x * x } else { x };
            let r1 = f.residual(0, x).expect("E1");
            let r2 = f.residual(1, x).expect("E2");
            let r2_exact = if x < c { 0.0 } else { x * x - 0.25 };
            assert!(f.imposed(0, x));
            assert_eq!(f.imposed(1, x), x < c);
            for err in [
                f.value(p, x, Approach::Above).expect("p") - x,
                f.value(q, x, Approach::Below).expect("q") - q_exact,
                r1,
                r2 - r2_exact,
            ] {
                worst = worst.max(err.abs());
            }
        }
        // One-sided limits at c: the stick shear 4c³ = 1/2 below, μp = c above.
        let below = f.regular_value(q, c, Approach::Below).expect("q(c-)");
        let above = f.value(q, c, Approach::Above).expect("q(c+)");
        worst = worst.max((below - 0.5).abs()).max((above - c).abs());
        // The residual field on the slip zone interpolates x² − 1/4.
        let rf = f.residual_field(1, (c, 1.0)).expect("field");
        assert_eq!(rf.basis.support(), (c, 1.0));
        for x in [0.55, 0.7, 0.95] {
            worst = worst.max((rf.eval(x) - (x * x - 0.25)).abs());
        }
        eprintln!("largest error {worst:.1e}");
        assert!(worst <= 1e-9, "largest error {worst:e}");
        // Outside the interval: an error, not a number.
        assert!(f.value(p, 1.5, Approach::Below).is_err());
        // Measured 2.3e-13 (the exact solution is polynomial).
        // An interval that is not a union of panels is refused.
        assert!(f.residual_field(1, (0.3, 0.7)).is_err());
    }

    /// The estimates of [`LevelFields`] on the manufactured problem: `c`
    /// is the one end that moves with the scalar, every window lies in the
    /// point's panel and subinterval, and every estimate bounds the true
    /// error of the exact polynomial solution.
    #[test]
    fn level_fields_estimates_on_the_manufactured_problem() {
        let src = include_str!("../../examples/hertz_split_mms.lmx");
        let prog = crate::lang::parse_program(src, "hertz_split_mms.lmx").expect("valid");
        let s = solve_split_fields(&prog, &SplitOptions::default()).expect("solves");
        let c = s.report.scalars[0].value;
        let lf = LevelFields::new(&s).expect("fields");
        assert!(lf.previous.is_some());
        assert_eq!(lf.last.scalar_ends(), vec![c]);
        assert_eq!(lf.scalar_error, s.report.scalars[0].error);
        let (p, q) = (
            lf.last.unknown_index("p").expect("p"),
            lf.last.unknown_index("q").expect("q"),
        );
        let mut checked = 0;
        for i in 1..60 {
            let x = (f64::from(i) + 0.3) / 61.0;
            assert_eq!(lf.moving_end(x, Approach::Above).map(|e| e.0), Some(c));
            let w = lf.window(x, Approach::Above);
            assert_eq!(w[0].0, x);
            let (lo, hi) = lf.last.piece_ends(x, Approach::Above).expect("piece");
            assert!(w.iter().all(|&(y, _)| y >= lo && y <= hi), "{w:?}");
            assert_eq!(w.len(), 1 + WINDOW_POINTS);
            let q_exact = if x < c { 4.0 * x * x * x } else { x };
            for (u, exact) in [(p, x), (q, q_exact)] {
                let v = lf.value(u, x, Approach::Above).expect("value");
                assert!(v.error.is_finite());
                assert!(
                    (v.value - exact).abs() <= v.error,
                    "x = {x}: {v:?} vs {exact}"
                );
                checked += 1;
            }
        }
        assert_eq!(checked, 118);
        // The shift term: zero at a flat field, δ-proportional elsewhere,
        // and bounded by the jump itself within δ of the end.
        assert_eq!(LevelFields::shift_term(0.7, (0.5, 1e-10), 3.0, 3.0), 0.0);
        let t = LevelFields::shift_term(0.7, (0.5, 1e-10), 3.0, 1.0);
        assert!((t - 2.0 * 2.0 * 1e-10 / 0.2).abs() < 1e-22);
        assert_eq!(LevelFields::shift_term(0.5, (0.5, 1e-10), 3.0, 1.0), 4.0);
    }
}
