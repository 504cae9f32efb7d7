//! The refinement ladder for a compiled system ([`CompiledSystem`]):
//! checks it, chooses each unknown's edge weight, then solves on [`LevelSpec::level`] 1, 2, … until two
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
//! agree better on the unknowns (a heuristic: the file needs no
//! annotation, and the choice is reported). The choice is made per
//! unknown, from the equations and the unknowns only: the requested
//! outputs never enter it (`choose_weights`).
use serde::Serialize;

use crate::numeric::budget;
use crate::numeric::solve::DEFAULT_MAX_COND;
use crate::numeric::{Factor, Limits, Operator, Singularity};
#[cfg(feature = "internals")]
use crate::system::Program;

use super::compiled::CompiledSystem;
use super::discrete::BasisId;
use super::discrete::{Discretisation, LevelSpec};
use super::error::PlanError;
use super::methods::{
    LevelSolution, Method, commuted_pairs, defect, defect_on, functional_rows, solve_level,
};
use crate::algebra::derivation::Derivation;

pub use crate::numeric::solve::rounding_floor;

/// Longest panel, in peak widths, for systems with peaked kernels.
const PEAK_PANELS: f64 = 1.0;

/// Narrower features than this fraction of the interval (or of their
/// position) are refused: the panels graded toward them would be a few
/// hundred rounding units wide.
const FEATURE_FLOOR: f64 = 1e-11;

pub use super::split_methods::DEFECT_WARNING;

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
    /// Memory budget in bytes (`None`: the default of
    /// [`crate::numeric::budget`]). A level that would not fit is not
    /// built: the ladder stops at the last level that did (marked not
    /// converged), or refuses with the size it would have needed.
    pub max_memory: Option<u64>,
}

impl Default for SolveOptions {
    fn default() -> SolveOptions {
        SolveOptions {
            method: Method::Ordered,
            tol: 1e-10,
            max_level: 7,
            max_cond: DEFAULT_MAX_COND,
            grid: 101,
            max_memory: None,
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
    /// The largest absolute error estimate of its values on the grid:
    /// the ladder's estimate (relative to the largest `|u/weight|`, at
    /// least 1) times that scale times `|weight(x)|`.
    pub error_estimate: f64,
}

/// A measured commutator defect.
#[derive(Debug, Clone, Serialize)]
pub struct Defect {
    /// The two symbols.
    pub pair: [String; 2],
    /// `‖KaKb f - KbKa f‖/‖KaKb f‖` for `f = 1 + x` (None if `KaKb f = 0`).
    pub defect: Option<f64>,
    /// The same for `f` = the system's solution for the target unknown
    /// (for the commutative model: the ordered elimination's solution on the
    /// same level); None if it could not be computed or `KaKb f = 0`.
    pub defect_on_solution: Option<f64>,
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
    /// Distance between the last two levels, relative to each quantity's
    /// size (at least 1): every quantity `v` is within
    /// `error_estimate·max(1, |v|)` (for an unknown, `|v|` is its largest
    /// `|u/weight|`).
    pub error_estimate: f64,
    /// The absolute error estimate of each output (`error_estimate ·
    /// max(1, |value|)`), in the order of `outputs`; `None` where the
    /// output is.
    pub output_errors: Vec<Option<f64>>,
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
    /// Set when the equation has more than one solution and the answer is
    /// the one the chosen weight selects: the warning saying so
    /// (`uniqueness.rs`).
    pub uniqueness: Option<String>,
    /// The pivots `ordered` executed on the final level, as (equation
    /// numbered from 1, unknown): the derivation's unless a warning says
    /// otherwise (empty for the other methods).
    pub pivots: Vec<(usize, String)>,
    /// The interval of the unknowns.
    pub domain: (f64, f64),
}

/// Everything prepared once: operators, interval, candidate weights.
struct Setup {
    /// The system has Hertz-type kernels `|t²-x²|^(-1/2)`.
    hertz: bool,
    /// The smallest width of a peaked kernel (infinite if none).
    peak: f64,
    ops: Vec<Option<(String, Operator)>>,
    domain: (f64, f64),
    /// Interior breakpoints, and whether the mesh is graded toward each
    /// (the constant limits and narrow features are).
    interior: Vec<(f64, bool)>,
    candidates: Vec<Vec<Vec<Factor>>>,
    target: usize,
    derivation: Option<Derivation>,
}

fn setup(sys: &CompiledSystem, derivation: Option<Derivation>) -> Result<Setup, PlanError> {
    sys.check()?;
    let n = sys.unknowns.len();
    let hi = sys.domain.1;
    let ops: Vec<Option<(String, Operator)>> = sys
        .operators
        .iter()
        .zip(&sys.symbols)
        .map(|(op, name)| op.as_ref().map(|op| (name.clone(), op.clone())))
        .collect();
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
            sys.equations.iter().any(|eq| {
                (0..sys.symbols.len()).any(|s| eq.lhs[j].contains_var(s) && reaches_hi(s))
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
    // Kernels other than the Hertz family: solutions may have power
    // behaviour at either end or both, `(t - lo)^a (hi - t)^b` for every
    // unknown, with the exponents of square-root edges and, for a kernel
    // `|x - t|^(-β)`, the Abel exponent `β - 1`.
    let mut hertz = false;
    let mut peak = f64::INFINITY;
    let mut exps = vec![-0.5, 0.5];
    for (_, op) in ops.iter().flatten() {
        for (_, t) in &op.terms {
            if let crate::numeric::operator::Term::Integral { singularity, .. } = t {
                match *singularity {
                    Singularity::AbelSqrt => hertz = true,
                    Singularity::Peaked { width } => peak = peak.min(width),
                    Singularity::Power { beta } if !exps.contains(&(beta - 1.0)) => {
                        exps.push(beta - 1.0)
                    }
                    _ => {}
                }
            }
        }
    }
    if !hertz {
        let lo = sys.domain.0;
        let mut ends: Vec<(f64, f64)> = Vec::new();
        for &a in std::iter::once(&0.0).chain(&exps) {
            for &b in std::iter::once(&0.0).chain(&exps) {
                if (a, b) != (0.0, 0.0) {
                    ends.push((a, b));
                }
            }
        }
        for (a, b) in ends {
            let mut w = Vec::new();
            if a != 0.0 {
                w.push(Factor {
                    at: lo,
                    exponent: a,
                });
            }
            if b != 0.0 {
                w.push(Factor {
                    at: hi,
                    exponent: b,
                });
            }
            let cand = vec![w; n];
            if !candidates.contains(&cand) {
                candidates.push(cand);
            }
        }
    }
    let mut interior: Vec<(f64, bool)> = sys.interior.iter().map(|&z| (z, true)).collect();
    let (lo, len) = (sys.domain.0, sys.domain.1 - sys.domain.0);
    for &(at, width) in &sys.features {
        if width > 0.0 && width < FEATURE_FLOOR * len.max(at.abs()) {
            return Err(PlanError::Numeric {
                context: "resolving a narrow feature".into(),
                source: crate::numeric::NumericError::InvalidMesh(format!(
                    "the formulas have a feature of width {width:.1e} at {at} (a narrow peak or a pole beside the interval), narrower than the solver resolves ({FEATURE_FLOOR:.0e} of the interval)"
                )),
            });
        }
        // The point itself, graded; breakpoints at `at ± 2^k·width`
        // (k = 0, 1, …) across the interval: panels no wider than the
        // feature beside it and no wider than their distance from it
        // beyond (a Lorentzian's tail varies on that scale), refined in
        // degree from level to level.
        if at > lo && at < sys.domain.1 {
            interior.push((at, true));
        }
        let mut d = width;
        while width > 0.0 && d < len {
            for z in [at - d, at + d] {
                if z > lo && z < sys.domain.1 {
                    interior.push((z, false));
                }
            }
            d *= 2.0;
        }
    }
    Ok(Setup {
        hertz,
        peak,
        ops,
        domain: sys.domain,
        interior,
        candidates,
        target: sys.target,
        derivation,
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

/// The mesh and degrees of `level` for the system prepared in `s`.
fn level_spec(s: &Setup, level: usize) -> LevelSpec {
    let mut spec = LevelSpec::level(level);
    if !s.hertz {
        // Other kernels are not even in x: grade toward both ends.
        spec.layers_lo = spec.layers;
    }
    // Solutions of equations with peaked kernels vary on the peak's scale.
    let len = s.domain.1 - s.domain.0;
    spec.max_panel = spec.max_panel.min(PEAK_PANELS * s.peak / len);
    spec
}

/// Checks that `level` fits the memory budget beside the level the ladder
/// still holds: the operator matrices (one per symbol and basis, bases of
/// the unknowns and `mid`) and three copies of the coupled matrix (`u²`
/// blocks: assembled, factorised, and a product's temporary), for this
/// level and the one before.
fn fits(sys: &CompiledSystem, s: &Setup, level: usize, budget: u64) -> Result<(), PlanError> {
    let u = sys.unknowns.len() as f64;
    let symbols = s.ops.iter().flatten().count() as f64;
    let matrices = symbols * (u + 1.0) + 3.0 * u * u;
    let dim = super::discrete::level_dim(s.domain, &s.interior, level_spec(s, level))?;
    let held = if level > 1 {
        super::discrete::level_dim(s.domain, &s.interior, level_spec(s, level - 1))?
    } else {
        0.0
    };
    let needed = budget::dense_bytes(dim, matrices) + budget::dense_bytes(held, matrices);
    budget::check(
        || format!("level {level} ({dim:.0} coefficients per unknown)"),
        needed,
        budget,
    )
    .map_err(PlanError::OverBudget)
}

fn solve_one(
    sys: &CompiledSystem,
    s: &Setup,
    weights: &[Vec<Factor>],
    level: usize,
    opts: &SolveOptions,
) -> Result<Solved, PlanError> {
    let spec = level_spec(s, level);
    let mut disc = Discretisation::new(s.domain, &s.interior, spec, s.ops.clone(), weights)?;
    let sol = solve_level(
        &mut disc,
        sys,
        opts.method,
        s.derivation.as_ref(),
        opts.max_cond,
    )?;
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
    let outputs = outputs(sys, &disc, &sol)?;
    Ok(Solved {
        disc,
        sol,
        phi,
        outputs,
    })
}

fn outputs(
    sys: &CompiledSystem,
    disc: &Discretisation,
    sol: &LevelSolution,
) -> Result<Vec<Option<f64>>, PlanError> {
    let mut out = Vec::new();
    'outer: for o in &sys.outputs {
        let (rows, constant) = functional_rows(disc, &o.terms, &format!("output {}", o.name))?;
        let mut v = constant;
        for (row, c) in rows.iter().zip(&sol.coefs) {
            match (row, c) {
                (Some(row), Some(c)) => v += row.dot(c),
                (Some(_), None) => {
                    out.push(None);
                    continue 'outer;
                }
                (None, _) => {}
            }
        }
        out.push(Some(v));
    }
    Ok(out)
}

/// Per unknown, the distance of two levels on the grid relative to the
/// unknown's scale (its largest `|u/weight|`, at least 1); `None` where a
/// level does not compute it.
fn unknown_distances(a: &Solved, b: &Solved) -> Vec<Option<f64>> {
    a.phi
        .iter()
        .zip(&b.phi)
        .map(|(pa, pb)| {
            let (pa, pb) = (pa.as_ref()?, pb.as_ref()?);
            let scale = pb
                .iter()
                .filter(|v| v.is_finite())
                .fold(1.0f64, |m, v| m.max(v.abs()));
            let mut d: f64 = 0.0;
            for (x, y) in pa.iter().zip(pb) {
                if x.is_finite() && y.is_finite() {
                    d = d.max((x - y).abs() / scale);
                } else if x.is_finite() != y.is_finite() {
                    d = f64::INFINITY;
                }
            }
            Some(d)
        })
        .collect()
}

/// Relative distance between two levels (unknowns on the grid, outputs).
fn distance(a: &Solved, b: &Solved) -> f64 {
    let mut d = unknown_distances(a, b)
        .into_iter()
        .flatten()
        .fold(0.0f64, f64::max);
    for (x, y) in a.outputs.iter().zip(&b.outputs) {
        if let (Some(x), Some(y)) = (x, y) {
            d = d.max((x - y).abs() / y.abs().max(1.0));
        }
    }
    d
}

/// A trial space tried on levels 1 and 2: its weights, the distance of
/// the two levels per unknown and the score it is ranked by (the largest
/// of those distances and the least-squares residual).
struct Trial {
    weights: Vec<Vec<Factor>>,
    per_unknown: Vec<Option<f64>>,
    score: f64,
    levels: (Solved, Solved),
}

fn trial(
    sys: &CompiledSystem,
    s: &Setup,
    weights: &[Vec<Factor>],
    opts: &SolveOptions,
) -> Result<Trial, PlanError> {
    let a = solve_one(sys, s, weights, 1, opts)?;
    let b = solve_one(sys, s, weights, 2, opts)?;
    let per_unknown = unknown_distances(&a, &b);
    let score = per_unknown
        .iter()
        .flatten()
        .fold(b.sol.residual, |m, &d| m.max(d));
    Ok(Trial {
        weights: weights.to_vec(),
        per_unknown,
        score,
        levels: (a, b),
    })
}

/// The end weights, chosen from the equations and the unknowns only
/// (never from the requested outputs, so that asking for one more output
/// cannot change the trial space): every candidate of [`Setup`] (one
/// weight for every unknown) on levels 1 and 2, then the combination that
/// gives each unknown the candidate weight whose two levels agree best on
/// that unknown; the trial whose largest per-unknown distance (or
/// least-squares residual) is smallest is kept, the earliest on a tie.
///
/// A trial refused for a null direction of its discretised operator
/// (`NumericError::NullSpace`) is not merely a weight that does not fit:
/// in that class the problem has more than one solution or none. The
/// refusal is kept ([`Chosen::null`]): it is the error when no weight
/// succeeds, and [`solve_derived`] reports it when the chosen weight's
/// answer does not converge, or states that the answer is not unique
/// when it does (a weight can exclude a null function legitimately, as
/// the airfoil equation's classes bounded at one end do).
fn choose_weights(
    sys: &CompiledSystem,
    s: &Setup,
    opts: &SolveOptions,
) -> Result<Chosen, PlanError> {
    let mut best: Option<Trial> = None;
    let mut first_err = None;
    let mut null: Option<(Vec<Vec<Factor>>, PlanError)> = None;
    // Per unknown: the smallest distance met and the weight giving it.
    let mut per: Vec<Option<(f64, Vec<Factor>)>> = vec![None; sys.unknowns.len()];
    let mut tried: Vec<Vec<Vec<Factor>>> = Vec::new();
    for w in &s.candidates {
        tried.push(w.clone());
        match trial(sys, s, w, opts) {
            Ok(t) => {
                for (j, d) in t.per_unknown.iter().enumerate() {
                    if let Some(d) = *d
                        && per[j].as_ref().is_none_or(|p| d < p.0)
                    {
                        per[j] = Some((d, w[j].clone()));
                    }
                }
                if best.as_ref().is_none_or(|b| t.score < b.score) {
                    best = Some(t);
                }
            }
            Err(e) if is_null_direction(&e) => {
                null.get_or_insert((w.clone(), e));
            }
            Err(e) => {
                first_err.get_or_insert(e);
            }
        }
    }
    let Some(mut best) = best else {
        return Err(match null {
            Some((w, e)) => in_class(e, &weights_text(sys, s, &w), ""),
            None => first_err.unwrap_or(PlanError::Invalid("nothing to solve".into())),
        });
    };
    // Unknowns no trial computed keep the best trial's weight.
    let combo: Vec<Vec<Factor>> = per
        .into_iter()
        .enumerate()
        .map(|(j, p)| p.map_or_else(|| best.weights[j].clone(), |p| p.1))
        .collect();
    if !tried.contains(&combo)
        && let Ok(t) = trial(sys, s, &combo, opts)
        && t.score < best.score
    {
        best = t;
    }
    let null = null.map(|(w, e)| (weights_text(sys, s, &w), e));
    Ok(Chosen { trial: best, null })
}

/// [`choose_weights`]'s answer: the trial kept, and the first null-direction
/// refusal met under another weight (that weight's text and the error).
struct Chosen {
    trial: Trial,
    null: Option<(String, PlanError)>,
}

use super::split_solve::is_null_direction;
use super::split_weights::in_class;

/// The singular values of a null-direction refusal, in words.
fn null_numbers(e: &PlanError) -> String {
    match e {
        PlanError::Numeric {
            source: crate::numeric::NumericError::NullSpace { smallest, next, .. },
            ..
        } => format!("smallest singular value {smallest:.1e} of the largest, the next {next:.1e}"),
        e => e.to_string(),
    }
}


/// A weight as the report prints it, e.g. `x^(0.5)*(4 - x)^(-0.5)`
/// or `1`.
fn weight_text(fs: &[Factor], hi: f64) -> String {
    match fs {
        [] => "1".to_string(),
        fs => fs
            .iter()
            .map(|f| {
                let side = if f.at >= hi {
                    super::WeightSide::Below
                } else {
                    super::WeightSide::Above
                };
                super::weight_factor_text(f.at, f.exponent, side)
            })
            .collect::<Vec<_>>()
            .join("*"),
    }
}

/// The weights of all unknowns: one text when they agree, else
/// `name: weight` for each.
fn weights_text(sys: &CompiledSystem, s: &Setup, weights: &[Vec<Factor>]) -> String {
    if weights.iter().all(|w| *w == weights[0]) {
        weights
            .first()
            .map_or_else(|| "1".into(), |w| weight_text(w, s.domain.1))
    } else {
        sys.unknowns
            .iter()
            .zip(weights)
            .map(|(n, w)| format!("{n}: {}", weight_text(w, s.domain.1)))
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// Solves `prog` by `opts.method`, refining until two levels agree: the
/// program is compiled ([`CompiledSystem::from_program`]) and solved by
/// [`solve_system`].
#[cfg(feature = "internals")]
pub fn solve_program(prog: &Program, opts: &SolveOptions) -> Result<SolveReport, PlanError> {
    solve_system(&CompiledSystem::from_program(prog, None)?, opts)
}

/// Solves a compiled system by `opts.method`, refining until two levels
/// agree. This is the entry point of solvers written by `lambdamat
/// codegen`.
pub fn solve_system(sys: &CompiledSystem, opts: &SolveOptions) -> Result<SolveReport, PlanError> {
    let derivation = match sys.derivation() {
        Ok(d) => Some(d),
        // A generated solver whose embedded derivation differs.
        Err(e @ PlanError::Invalid(_)) => return Err(e),
        Err(_) => None,
    };
    solve_derived(sys, derivation, opts)
}

/// [`solve_system`] executing a derivation already built for `sys` (by
/// [`CompiledSystem::derivation`] or [`crate::reduce::derive`] on the same
/// file and target); `None` when the system has none (`det(A) = 0` over
/// Q\[symbols\]: `coupled` and `ordered` still solve, the commutative model
/// refuses).
pub fn solve_derived(
    sys: &CompiledSystem,
    derivation: Option<Derivation>,
    opts: &SolveOptions,
) -> Result<SolveReport, PlanError> {
    if !(opts.tol > 0.0 && opts.tol.is_finite()) {
        return Err(PlanError::Invalid(format!(
            "tolerance {} must be positive",
            opts.tol
        )));
    }
    let choice = super::uniqueness::check(sys)?;
    let s = setup(sys, derivation)?;
    let max_level = opts.max_level.max(2);
    let budget = opts.max_memory.unwrap_or_else(budget::default_budget);
    fits(sys, &s, 2, budget)?;
    let Chosen {
        trial: chosen,
        null,
    } = choose_weights(sys, &s, opts)?;
    let weights = &chosen.weights;
    let (first, mut last) = chosen.levels;
    let mut est = distance(&first, &last).max(last.sol.residual);
    let mut level = 2;
    let mut prev: Option<f64> = None;
    let mut bound = est;
    let mut over = None;
    while bound > opts.tol && level < max_level {
        if let Err(PlanError::OverBudget(e)) = fits(sys, &s, level + 1, budget) {
            over = Some(e);
            break;
        }
        let next = solve_one(sys, &s, weights, level + 1, opts)?;
        let d = distance(&last, &next);
        if d > est && est < 1e-8 {
            // Rounding noise has overtaken the discretisation error: the
            // previous answer, with its estimate, is the best there is.
            break;
        }
        level += 1;
        prev = Some(est);
        est = d;
        bound = honest(est, prev).max(next.sol.residual);
        last = next;
    }
    // With side conditions, equations and conditions that contradict each
    // other leave a least-squares residual: the answer is no better.
    let est = honest(est, prev)
        .max(rounding_floor(last.sol.cond))
        .max(last.sol.residual);
    let mut r = report(sys, &s, weights, last, est, level, opts)?;
    if let Some(e) = over
        && !r.converged
    {
        r.warnings.push(format!(
            "stopped at level {level}, the last within the memory budget: {e}"
        ));
    }
    if let super::uniqueness::Uniqueness::Chosen(w) = choice {
        r.uniqueness = Some(w);
    }
    if let Some((other, e)) = null {
        let here = weights_text(sys, &s, weights);
        if !r.converged {
            // The chosen space only approximates what the other represents:
            // its answer drifts with the level (exit 4 without a cause).
            return Err(in_class(
                e,
                &other,
                &format!(
                    " (in the trial space of weight {here} the refinement did not reach the tolerance)"
                ),
            ));
        }
        if r.uniqueness.is_none() {
            r.uniqueness = Some(format!(
                "the solution is not unique across trial spaces: in the trial space of weight {other} the discretised operator has a null direction ({}), so in that class the problem has more than one solution or none; the answer is the one in the class of the weight {here} shown, where the operator is invertible; a side condition (`condition …`) can select another",
                null_numbers(&e)
            ));
        }
    }
    Ok(r)
}

/// The error estimate of the last level from the distances `d` (last two
/// levels) and `prev` (the two before): `d` bounds the error of the
/// previous level; the last level's error is about `d·r/(1-r)` when the
/// distances fall geometrically with ratio `r = d/prev`, which exceeds `d`
/// when convergence is slow (`r > 1/2`). Rounding-level distances are
/// taken as they are.
fn honest(d: f64, prev: Option<f64>) -> f64 {
    match prev {
        Some(p) if p > 0.0 && d > 1e-13 => {
            let r = d / p;
            if r < 1.0 {
                d * (r / (1.0 - r)).max(1.0)
            } else {
                d
            }
        }
        _ => d,
    }
}

fn report(
    sys: &CompiledSystem,
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
        // The scale the ladder's distance was relative to (`distance`).
        let scale = last.phi[j].as_ref().map_or(1.0, |phi| {
            phi.iter()
                .filter(|v| v.is_finite())
                .fold(1.0f64, |m, v| m.max(v.abs()))
        });
        let (mut x, mut values) = (Vec::new(), Vec::new());
        let mut error_estimate = 0.0f64;
        for &t in &xs {
            let w = b.weight_at(t);
            if w.is_finite() {
                x.push(t);
                values.push(b.eval(c.as_slice(), t));
                error_estimate = error_estimate.max(est * scale * w.abs());
            }
        }
        let weight = weight_text(&weights[j], s.domain.1);
        unknowns.push(UnknownValues {
            name: sys.unknowns[j].clone(),
            x,
            values,
            weight,
            error_estimate,
        });
    }
    let mut warnings = Vec::new();
    let mut defects = Vec::new();
    for w in &last.sol.warnings {
        if !warnings.contains(w) {
            warnings.push(w.clone());
        }
    }
    let pairs = commuted_pairs(opts.method, s.derivation.as_ref());
    // The defects are also measured on the system's own solution for the
    // target: the method's, or for the commutative model (whose answer is
    // not the system's) the ordered elimination's on the same level.
    let solution = if pairs.is_empty() {
        None
    } else if opts.method == Method::Commutative {
        solve_level(
            &mut last.disc,
            sys,
            Method::Ordered,
            s.derivation.as_ref(),
            opts.max_cond,
        )
        .ok()
        .and_then(|l| l.coefs[s.target].clone())
    } else {
        last.sol.coefs[s.target].clone()
    };
    for (a, b) in pairs {
        let d = defect(&mut last.disc, a, b)?;
        let on_solution = match &solution {
            Some(c) => defect_on(&mut last.disc, a, b, BasisId::Unknown(s.target), c)?,
            None => None,
        };
        let (na, nb) = (&sys.symbols[a], &sys.symbols[b]);
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
            defect_on_solution: on_solution,
        });
    }
    let model = opts.method == Method::Commutative;
    if model {
        warnings.push(format!(
            "the commutative method solves the seed's single equation (det(A)/h) {0} = Σ_j c_j g_j (the eliminant of `lambdamat reduce`), a model that treats the operators as commuting symbols; compare with --method ordered",
            sys.unknowns[s.target]
        ));
    }
    let converged = est <= opts.tol;
    if !converged {
        warnings.push(format!(
            "refinement stopped at level {level} before every estimate was within {:.1e}·max(1, |value|)",
            opts.tol
        ));
    }
    Ok(SolveReport {
        method: if sys.conditions.is_empty() {
            opts.method.name().to_string()
        } else {
            format!(
                "least squares (equations and {} side condition{})",
                sys.conditions.len(),
                if sys.conditions.len() == 1 { "" } else { "s" }
            )
        },
        model,
        target: sys.unknowns[s.target].clone(),
        unknowns,
        outputs: sys
            .outputs
            .iter()
            .map(|o| o.name.clone())
            .zip(last.outputs.iter().copied())
            .collect(),
        error_estimate: est,
        output_errors: last
            .outputs
            .iter()
            .map(|v| v.map(|v| est * v.abs().max(1.0)))
            .collect(),
        converged,
        level,
        dim: last.disc.dim(),
        cond: last.sol.cond,
        commutator_defects: defects,
        warnings,
        uniqueness: None,
        pivots: last
            .sol
            .pivots
            .iter()
            .map(|&(e, u)| (e + 1, sys.unknowns[u].clone()))
            .collect(),
        domain: s.domain,
    })
}
