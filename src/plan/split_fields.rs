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
//! accessors, never their internals.
use nalgebra::DVector;

use super::error::PlanError;
use super::split::{Discrete, SplitProblem};
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
    /// The equation (index in source order).
    pub equation: usize,
    /// The unweighted basis on the panels of the interval.
    pub basis: PanelBasis,
    /// The residual at the basis nodes (its coefficients).
    pub values: Vec<f64>,
}

impl ResidualField {
    /// The interpolated residual at `x` (zero outside the interval).
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

impl<'a> Fields<'a> {
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
        Ok(Fields {
            problem,
            d,
            asms,
            term_asms,
        })
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
                   op: &Operator,
                   window: (f64, f64),
                   coef: &[f64],
                   factor: f64|
         -> Result<(), PlanError> {
            let m = asm
                .matrix_on(op, xs, window)
                .map_err(PlanError::numeric("residual"))?;
            let v = m * DVector::from_column_slice(coef);
            for (ri, vi) in r.iter_mut().zip(v.iter()) {
                *ri += factor * vi;
            }
            Ok(())
        };
        let b = &self.d.breaks;
        for j in 0..self.problem.sys.unknowns.len() {
            let Some(op) = self.problem.operator(e, j) else {
                continue;
            };
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
            equation: e,
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
}
