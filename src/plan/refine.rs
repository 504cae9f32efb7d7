//! The refinement ladder for a language system: checks its shape, finds
//! the unknowns' interval (the hull of all constant integration limits of
//! operators and outputs; `[0, c]` if `c` is the only one), builds the operators, chooses each unknown's
//! edge weight, then solves on [`LevelSpec::level`] 1, 2, … until two
//! successive answers (unknowns on a fixed grid and outputs) agree to
//! `tol`; the distance of the last two levels is the error estimate
//! carried by the answer. It also evaluates the output functionals and
//! measures the commutator defects. Owns this control logic; it must not
//! print (the CLI does) or assemble (`discrete.rs` does).
//!
//! **Edge weights.** Unknowns hit by an Abel operator `∫_x^b` with `b` the
//! right end of the interval may have an inverse-square-root edge
//! singularity there (the frictionless punch: `p = (2/π)/√(1-x²)`), which
//! polynomials cannot approximate. The solver tries two trial spaces, plain
//! piecewise polynomials and, for those unknowns, polynomials times
//! `(b-t)^(-1/2)`, on levels 1 and 2, and keeps the one whose two levels
//! agree better (a heuristic: the file needs no annotation, and the choice
//! is reported).
use nalgebra::DVector;
use serde::Serialize;

use crate::numeric::solve::DEFAULT_MAX_COND;
use crate::numeric::{Assembler, Factor, Limits, Operator, Singularity};
use crate::system::{FunctionalTerm, Limit, Program, Term};

use super::compile::{compile_x, constant_value, rational};
use super::discrete::{Discretisation, LevelSpec};
use super::error::PlanError;
use super::methods::{LevelSolution, Method, commuted_pairs, defect, solve_level};
use super::operators::build_operator;

/// Defects above this are reported as warnings.
pub const DEFECT_WARNING: f64 = 1e-8;

/// What to solve and how accurately.
#[derive(Debug, Clone, Copy)]
pub struct SolveOptions {
    /// The method.
    pub method: Method,
    /// Stop when two successive levels agree to this (relative to the
    /// size of the answer, at least 1).
    pub tol: f64,
    /// Highest level tried.
    pub max_level: usize,
    /// Condition limit for every factorisation.
    pub max_cond: f64,
    /// Number of points of the output grid.
    pub grid: usize,
}

impl Default for SolveOptions {
    fn default() -> SolveOptions {
        SolveOptions {
            method: Method::Ordered,
            tol: 1e-10,
            max_level: 7,
            max_cond: DEFAULT_MAX_COND,
            grid: 101,
        }
    }
}

/// An unknown on the output grid.
#[derive(Debug, Clone, Serialize)]
pub struct UnknownValues {
    /// Its name.
    pub name: String,
    /// Grid points (a singular end of a weighted unknown is left out).
    pub x: Vec<f64>,
    /// Values at the grid points.
    pub values: Vec<f64>,
    /// Its weight, e.g. `(1 - x)^(-1/2)`, or `1`.
    pub weight: String,
}

/// A measured commutator defect.
#[derive(Debug, Clone, Serialize)]
pub struct Defect {
    /// The two symbols.
    pub pair: [String; 2],
    /// `‖KaKb f - KbKa f‖/‖KaKb f‖` for `f = 1 + x` (None if `KaKb f = 0`).
    pub defect: Option<f64>,
}

/// A solved system.
#[derive(Debug, Clone, Serialize)]
pub struct SolveReport {
    /// The method used.
    pub method: String,
    /// Whether the answer is of a model (commutative) rather than the system.
    pub model: bool,
    /// The unknown solved for by the eliminations.
    pub target: String,
    /// Computed unknowns on the output grid.
    pub unknowns: Vec<UnknownValues>,
    /// Outputs (None if they need an unknown the method does not compute).
    pub outputs: Vec<(String, Option<f64>)>,
    /// Distance between the last two levels.
    pub error_estimate: f64,
    /// Whether that distance is within the tolerance.
    pub converged: bool,
    /// The final level.
    pub level: usize,
    /// Coefficients per unknown on the final level.
    pub dim: usize,
    /// Largest condition estimate on the final level.
    pub cond: f64,
    /// Measured defects of the commuted pairs.
    pub commutator_defects: Vec<Defect>,
    /// Warnings (large defects, no convergence, model).
    pub warnings: Vec<String>,
    /// The interval of the unknowns.
    pub domain: (f64, f64),
}

/// Everything prepared once: operators, interval, candidate weights.
struct Setup {
    ops: Vec<Option<(String, Operator)>>,
    domain: (f64, f64),
    interior: Vec<f64>,
    candidates: Vec<Vec<Vec<Factor>>>,
    target: usize,
}

fn setup(prog: &Program) -> Result<Setup, PlanError> {
    let n = prog.unknowns.len();
    if n == 0 || prog.equations.len() != n {
        return Err(PlanError::Invalid(format!(
            "the solver needs as many equations as unknowns ({} equations, {} unknowns)",
            prog.equations.len(),
            n
        )));
    }
    // The interval: the hull of all constant limits.
    let mut limits = Vec::new();
    for d in &prog.operators {
        for t in &d.terms {
            if let Term::Integral { lower, upper, .. } = t {
                for l in [lower, upper] {
                    if let Limit::Const(c) = l {
                        limits.push(rational(c));
                    }
                }
            }
        }
    }
    for o in &prog.outputs {
        for t in &o.terms {
            if let FunctionalTerm::Integral { lower, upper, .. } = t {
                limits.extend([rational(lower), rational(upper)]);
            }
        }
    }
    // With a single constant limit `c` (e.g. only `int(x..1)`), the
    // interval runs from 0 to `c`.
    if limits.iter().all(|&c| Some(c) == limits.first().copied()) {
        limits.push(0.0);
    }
    let lo = limits.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = limits.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if !(lo.is_finite() && hi.is_finite() && lo < hi) {
        return Err(PlanError::Invalid(
            "cannot tell the unknowns' interval: no integral has a nonzero constant limit".into(),
        ));
    }
    let mut interior: Vec<f64> = limits.into_iter().filter(|&z| z > lo && z < hi).collect();
    interior.sort_by(f64::total_cmp);
    interior.dedup();
    // Operators of the symbols the equations use; those must be defined.
    let used = |s: usize| {
        prog.equations
            .iter()
            .any(|eq| eq.lhs.iter().any(|p| p.contains_var(s)))
    };
    let mut ops: Vec<Option<(String, Operator)>> = vec![None; prog.symbols.len()];
    for d in prog.operators.iter().filter(|d| used(d.symbol)) {
        let name = prog.symbols[d.symbol].clone();
        ops[d.symbol] = Some((name.clone(), build_operator(d, &name, (lo, hi))?));
    }
    for eq in &prog.equations {
        for p in &eq.lhs {
            for (s, name) in prog.symbols.iter().enumerate() {
                if p.contains_var(s) && ops[s].is_none() {
                    return Err(PlanError::Unsupported {
                        operator: name.clone(),
                        reason: "declared with `var`: it has no definition to discretise".into(),
                    });
                }
            }
        }
    }
    // Unknowns hit by an Abel integral reaching the right end.
    let reaches_hi = |s: usize| {
        ops[s].as_ref().is_some_and(|(_, op)| {
            op.terms.iter().any(|(_, t)| {
                matches!(t, crate::numeric::operator::Term::Integral {
                    limits: Limits::Upper { b } | Limits::Fixed { b, .. },
                    singularity: Singularity::AbelSqrt,
                    ..
                } if *b == hi)
            })
        })
    };
    let edge: Vec<bool> = (0..n)
        .map(|j| {
            prog.equations.iter().any(|eq| {
                (0..prog.symbols.len()).any(|s| eq.lhs[j].contains_var(s) && reaches_hi(s))
            })
        })
        .collect();
    let plain = vec![Vec::new(); n];
    let mut candidates = vec![plain];
    if edge.iter().any(|&e| e) {
        candidates.push(
            edge.iter()
                .map(|&e| {
                    if e {
                        vec![Factor {
                            at: hi,
                            exponent: -0.5,
                        }]
                    } else {
                        Vec::new()
                    }
                })
                .collect(),
        );
    }
    let target = prog
        .directives
        .iter()
        .find_map(|d| match d {
            crate::system::Directive::Solve { unknown } => Some(*unknown),
            _ => None,
        })
        .unwrap_or(0);
    Ok(Setup {
        ops,
        domain: (lo, hi),
        interior,
        candidates,
        target,
    })
}

/// One solved level with its unknowns on the grid and its outputs.
struct Solved {
    disc: Discretisation,
    sol: LevelSolution,
    /// `u_j / W_j` on the grid (None if not computed).
    phi: Vec<Option<Vec<f64>>>,
    outputs: Vec<Option<f64>>,
}

fn grid(domain: (f64, f64), n: usize) -> Vec<f64> {
    let n = n.max(2);
    (0..n)
        .map(|k| domain.0 + (domain.1 - domain.0) * k as f64 / (n - 1) as f64)
        .collect()
}

fn solve_one(
    prog: &Program,
    s: &Setup,
    weights: &[Vec<Factor>],
    level: usize,
    opts: &SolveOptions,
) -> Result<Solved, PlanError> {
    let mut disc = Discretisation::new(
        s.domain,
        &s.interior,
        LevelSpec::level(level),
        s.ops.clone(),
        weights,
    )?;
    let sol = solve_level(&mut disc, prog, opts.method, s.target, opts.max_cond)?;
    let xs = grid(s.domain, opts.grid);
    let phi = sol
        .coefs
        .iter()
        .enumerate()
        .map(|(j, c)| {
            c.as_ref().map(|c| {
                let b = &disc.bases[j];
                xs.iter()
                    .map(|&x| {
                        let w = b.weight_at(x);
                        if w.is_finite() && w != 0.0 {
                            b.eval(c.as_slice(), x) / w
                        } else {
                            f64::NAN
                        }
                    })
                    .collect()
            })
        })
        .collect();
    let outputs = outputs(prog, &disc, &sol)?;
    Ok(Solved {
        disc,
        sol,
        phi,
        outputs,
    })
}

fn outputs(
    prog: &Program,
    disc: &Discretisation,
    sol: &LevelSolution,
) -> Result<Vec<Option<f64>>, PlanError> {
    let mut out = Vec::new();
    'outer: for o in &prog.outputs {
        let mut v = 0.0;
        for t in &o.terms {
            match t {
                FunctionalTerm::Constant(e) => v += constant_value(e).unwrap_or(f64::NAN),
                FunctionalTerm::Integral {
                    coeff,
                    lower,
                    upper,
                    weight,
                    unknown,
                } => {
                    let Some(c) = &sol.coefs[*unknown] else {
                        out.push(None);
                        continue 'outer;
                    };
                    let asm = Assembler::new(&disc.bases[*unknown])
                        .map_err(PlanError::numeric("output functional"))?;
                    let w = compile_x(weight);
                    let row = asm
                        .functional(move |x| w(x), rational(lower), rational(upper))
                        .map_err(PlanError::numeric(format!("output {}", o.name)))?;
                    let k = constant_value(coeff).unwrap_or(f64::NAN);
                    v += k * DVector::from_vec(row).dot(c);
                }
            }
        }
        out.push(Some(v));
    }
    Ok(out)
}

/// Relative distance between two levels (unknowns on the grid, outputs).
fn distance(a: &Solved, b: &Solved) -> f64 {
    let mut d: f64 = 0.0;
    for (pa, pb) in a.phi.iter().zip(&b.phi) {
        if let (Some(pa), Some(pb)) = (pa, pb) {
            let scale = pb
                .iter()
                .filter(|v| v.is_finite())
                .fold(1.0f64, |m, v| m.max(v.abs()));
            for (x, y) in pa.iter().zip(pb) {
                if x.is_finite() && y.is_finite() {
                    d = d.max((x - y).abs() / scale);
                } else if x.is_finite() != y.is_finite() {
                    d = f64::INFINITY;
                }
            }
        }
    }
    for (x, y) in a.outputs.iter().zip(&b.outputs) {
        if let (Some(x), Some(y)) = (x, y) {
            d = d.max((x - y).abs() / y.abs().max(1.0));
        }
    }
    d
}

/// Solves `prog` by `opts.method`, refining until two levels agree.
pub fn solve_program(prog: &Program, opts: &SolveOptions) -> Result<SolveReport, PlanError> {
    if !(opts.tol > 0.0 && opts.tol.is_finite()) {
        return Err(PlanError::Invalid(format!(
            "tolerance {} must be positive",
            opts.tol
        )));
    }
    let s = setup(prog)?;
    let max_level = opts.max_level.max(2);
    // Levels 1 and 2 for every candidate weight; keep the best.
    let mut best: Option<(f64, usize, Solved, Solved)> = None;
    let mut first_err = None;
    for (ci, w) in s.candidates.iter().enumerate() {
        let pair = solve_one(prog, &s, w, 1, opts)
            .and_then(|a| solve_one(prog, &s, w, 2, opts).map(|b| (a, b)));
        match pair {
            Ok((a, b)) => {
                let d = distance(&a, &b);
                if best.as_ref().is_none_or(|x| d < x.0) {
                    best = Some((d, ci, a, b));
                }
            }
            Err(e) => {
                first_err.get_or_insert(e);
            }
        }
    }
    let Some((mut est, ci, _, mut last)) = best else {
        return Err(first_err.unwrap_or(PlanError::Invalid("nothing to solve".into())));
    };
    let weights = &s.candidates[ci];
    let mut level = 2;
    while est > opts.tol && level < max_level {
        let next = solve_one(prog, &s, weights, level + 1, opts)?;
        let d = distance(&last, &next);
        if d > est && est < 1e-8 {
            // Rounding noise has overtaken the discretisation error: the
            // previous answer, with its estimate, is the best there is.
            break;
        }
        level += 1;
        est = d;
        last = next;
    }
    report(prog, &s, weights, last, est, level, opts)
}

fn report(
    prog: &Program,
    s: &Setup,
    weights: &[Vec<Factor>],
    mut last: Solved,
    est: f64,
    level: usize,
    opts: &SolveOptions,
) -> Result<SolveReport, PlanError> {
    let xs = grid(s.domain, opts.grid);
    let mut unknowns = Vec::new();
    for (j, c) in last.sol.coefs.iter().enumerate() {
        let Some(c) = c else { continue };
        let b = &last.disc.bases[j];
        let (mut x, mut values) = (Vec::new(), Vec::new());
        for &t in &xs {
            let w = b.weight_at(t);
            if w.is_finite() {
                x.push(t);
                values.push(b.eval(c.as_slice(), t));
            }
        }
        let weight = match weights[j].as_slice() {
            [] => "1".to_string(),
            fs => fs
                .iter()
                .map(|f| format!("({} - x)^({})", f.at, f.exponent))
                .collect::<Vec<_>>()
                .join("*"),
        };
        unknowns.push(UnknownValues {
            name: prog.unknowns[j].clone(),
            x,
            values,
            weight,
        });
    }
    let mut warnings = Vec::new();
    let mut defects = Vec::new();
    for (a, b) in commuted_pairs(prog, opts.method, s.target) {
        let d = defect(&mut last.disc, a, b)?;
        let (na, nb) = (&prog.symbols[a], &prog.symbols[b]);
        if let Some(v) = d
            && v > DEFECT_WARNING
        {
            warnings.push(format!(
                "{na} and {nb} do not commute: ‖{na}{nb} f - {nb}{na} f‖/‖{na}{nb} f‖ = {v:.3e} for f = 1 + x; an elimination that commutes them is a model, not the system"
            ));
        }
        defects.push(Defect {
            pair: [na.clone(), nb.clone()],
            defect: d,
        });
    }
    let model = opts.method == Method::Commutative;
    if model {
        warnings.push(format!(
            "the commutative method solves the seed's single equation det(A) {0} = Σ adj(A)_{0}j g_j, a model that treats the operators as commuting symbols; compare with --method ordered",
            prog.unknowns[s.target]
        ));
    }
    let converged = est <= opts.tol;
    if !converged {
        warnings.push(format!(
            "refinement stopped at level {level} before two answers agreed to {:.1e} (estimate {est:.1e})",
            opts.tol
        ));
    }
    Ok(SolveReport {
        method: opts.method.name().to_string(),
        model,
        target: prog.unknowns[s.target].clone(),
        unknowns,
        outputs: prog
            .outputs
            .iter()
            .map(|o| o.name.clone())
            .zip(last.outputs.iter().copied())
            .collect(),
        error_estimate: est,
        converged,
        level,
        dim: last.disc.dim(),
        cond: last.sol.cond,
        commutator_defects: defects,
        warnings,
        domain: s.domain,
    })
}
