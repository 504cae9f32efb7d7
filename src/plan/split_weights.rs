//! Automatic end weights of the split-domain solver: before the ladder,
//! each unknown's behaviour at the ends of the unknowns' interval that no
//! `singular` declaration names is chosen among plain piecewise
//! polynomials and polynomials times `(x - a)^α (b - x)^β`, with α and β
//! from `{0, -1/2, 1/2}` and, for every kernel `|x - t|^(-γ)` of the file,
//! the Abel exponent `γ - 1`. The choice is a weight per unknown made from the
//! equations and the unknowns only, never from the requested outputs:
//! every candidate (one weight for every unknown) is solved on levels 0
//! and 1, each unknown `u` is compared on a grid as `u/weight` relative to
//! its largest value (at least 1), then the combination giving each
//! unknown the candidate whose two levels agree best on it is tried too,
//! and the trial whose largest per-unknown distance (or least-squares
//! residual) is smallest is kept, the plain one on a tie. A chosen weight
//! is installed as the declaration `singular u at end ~ |x - end|^e`
//! would be, the plain one (`e = 0`) included: the mesh is graded toward
//! every end so chosen (toward a plain one with few layers, which the end check may
//! deepen: `split.rs`'s `PLAIN_END_LAYERS`), and the report names the
//! weight. Problems with unknown scalars or relations are left as
//! declared (their ends are the end check's, `split_ends.rs`). Owns this
//! choice; the discretisation is `split.rs`'s, the ladder
//! `split_solve.rs`'s.
use super::error::PlanError;
use super::split::{Discrete, SplitLevel, SplitProblem};
use super::split_fields::{Approach, Fields};
use super::split_input::{RealFn, SplitKind, SplitSingular};
use crate::numeric::Singularity;
use crate::numeric::operator::Term;

/// Points of the grid the trial levels are compared on.
const GRID: usize = 101;

/// The exponents of one unknown's weight at the lower and upper end
/// (`0` for none).
type Ends = (f64, f64);

/// The exponents tried at an end: `∓1/2` and the Abel exponent `γ - 1` of
/// every kernel `|x - t|^(-γ)`.
fn exponents(problem: &SplitProblem) -> Vec<f64> {
    let mut exps = vec![-0.5, 0.5];
    for op in problem.sys.operators.iter().flatten() {
        for (_, t) in &op.terms {
            if let Term::Integral {
                singularity: Singularity::Power { beta },
                ..
            } = t
                && !exps.contains(&(beta - 1.0))
            {
                exps.push(beta - 1.0);
            }
        }
    }
    exps
}

/// Chooses and installs the end weights of `problem` (see the module).
/// Does nothing when it has unknown scalars or relations, or when every
/// end of every unknown is declared; when no weighted trial can be
/// solved, the problem stays as declared and the ladder reports.
pub(super) fn choose(problem: &mut SplitProblem) -> Result<(), PlanError> {
    let c = &problem.contact;
    if !c.scalars.is_empty() || !c.relations.is_empty() {
        return Ok(());
    }
    let (a, b) = problem.domain;
    if !(a.is_finite() && b.is_finite() && a < b) {
        return Ok(());
    }
    let vars = c.values(&[]);
    let nu = problem.sys.unknowns.len();
    let open: Vec<(bool, bool)> = (0..nu)
        .map(|u| {
            let declared = |z: f64| {
                c.singulars
                    .iter()
                    .any(|s| s.unknown == u && s.at.eval(&vars, 0.0) == z)
            };
            (!declared(a), !declared(b))
        })
        .collect();
    if open.iter().all(|&(l, h)| !l && !h) {
        return Ok(());
    }
    let exps = exponents(problem);
    let mut pairs: Vec<Ends> = Vec::new();
    for &l in std::iter::once(&0.0).chain(&exps) {
        for &h in std::iter::once(&0.0).chain(&exps) {
            pairs.push((l, h));
        }
    }
    let base = problem.contact.singulars.len();
    let mut tried: Vec<Vec<Ends>> = Vec::new();
    let mut best: Option<(f64, Vec<Ends>)> = None;
    let mut per: Vec<Option<(f64, Ends)>> = vec![None; nu];
    // The first trial space met with a null direction, and its numbers.
    let mut null: Option<(Vec<Ends>, String, PlanError)> = None;
    for (l, h) in pairs {
        let w: Vec<Ends> = open
            .iter()
            .map(|&(ol, oh)| (if ol { l } else { 0.0 }, if oh { h } else { 0.0 }))
            .collect();
        if tried.contains(&w) {
            continue;
        }
        tried.push(w.clone());
        let (dists, score) = match trial(problem, &w, &open, base) {
            Ok(t) => t,
            Err(e) => {
                if let Some(numbers) = null_numbers(&e) {
                    null.get_or_insert((w.clone(), numbers, e));
                }
                continue;
            }
        };
        for (u, d) in dists.iter().enumerate() {
            if let Some(d) = *d
                && per[u].is_none_or(|p| d < p.0)
            {
                per[u] = Some((d, w[u]));
            }
        }
        if best.as_ref().is_none_or(|bst| score < bst.0) {
            best = Some((score, w));
        }
    }
    let Some(mut best) = best else {
        return match null {
            Some((w, _, e)) => Err(in_class(e, &weights_text(problem, &w, &open), "")),
            None => Ok(()),
        };
    };
    let combo: Vec<Ends> = per
        .iter()
        .enumerate()
        .map(|(u, p)| p.map_or(best.1[u], |p| p.1))
        .collect();
    if !tried.contains(&combo)
        && let Ok((_, score)) = trial(problem, &combo, &open, base)
        && score < best.0
    {
        best = (score, combo);
    }
    let here = weights_text(problem, &best.1, &open);
    if let Some((w, numbers, e)) = null {
        let other = weights_text(problem, &w, &open);
        problem.weight_note = Some(format!(
            "the solution is not unique across trial spaces: in the trial space of weight {other} the discretised operator has a null direction ({numbers}), so in that class the problem has more than one solution or none; the answer is the one in the class of the weight {here} shown, where the operator is invertible; a side condition (`condition …`) can select another"
        ));
        problem.null_refusal = Some(in_class(
            e,
            &other,
            &format!(
                " (in the trial space of weight {here} the refinement did not reach the tolerance)"
            ),
        ));
    }
    problem.weight_text = Some(here);
    let base = problem.contact.singulars.len();
    install(problem, &best.1, &open);
    // The plain weights installed (in `install`'s order) are graded only
    // a little (`PLAIN_END_LAYERS`) and left to the end check.
    let mut plain = Vec::new();
    let mut i = base;
    for (&(l, h), &(ol, oh)) in best.1.iter().zip(&open) {
        for (e, o) in [(l, ol), (h, oh)] {
            if o {
                if e == 0.0 {
                    plain.push(i);
                }
                i += 1;
            }
        }
    }
    problem.set_plain_ends(plain);
    Ok(())
}

/// A null-direction refusal `e` naming the trial space it was met in
/// (`weight`) and, after it, `more`; other errors unchanged.
pub(super) fn in_class(e: PlanError, weight: &str, more: &str) -> PlanError {
    match e {
        PlanError::Numeric { context, source } => PlanError::Numeric {
            context: format!("{context}, in the trial space of weight {weight}{more}"),
            source,
        },
        e => e,
    }
}

/// The singular values of a null-direction refusal `e` in words; `None`
/// for any other error.
fn null_numbers(e: &PlanError) -> Option<String> {
    match e {
        PlanError::Numeric {
            source: crate::numeric::NumericError::NullSpace { smallest, next, .. },
            ..
        } => Some(format!(
            "smallest singular value {smallest:.1e} of the largest, the next {next:.1e}"
        )),
        _ => None,
    }
}

/// The weights `w` at the ends `open` marks as the report prints them:
/// one text when every unknown has the same, else `name: text` per
/// unknown.
fn weights_text(problem: &SplitProblem, w: &[Ends], open: &[(bool, bool)]) -> String {
    use super::{WeightSide, weight_factor_text};
    let (a, b) = problem.domain;
    let texts: Vec<String> = w
        .iter()
        .zip(open)
        .map(|(&(l, h), &(ol, oh))| {
            let mut fs = Vec::new();
            if ol && l != 0.0 {
                fs.push(weight_factor_text(a, l, WeightSide::Above));
            }
            if oh && h != 0.0 {
                fs.push(weight_factor_text(b, h, WeightSide::Below));
            }
            if fs.is_empty() {
                "1".to_string()
            } else {
                fs.join("*")
            }
        })
        .collect();
    if texts.windows(2).all(|p| p[0] == p[1]) {
        texts.into_iter().next().unwrap_or_else(|| "1".to_string())
    } else {
        problem
            .sys
            .unknowns
            .iter()
            .zip(&texts)
            .map(|(n, t)| format!("{n}: {t}"))
            .collect::<Vec<_>>()
            .join("; ")
    }
}

/// Declares the weights `w` (per unknown, the exponents at the two ends)
/// at the ends `open` marks, an exponent 0 included: every end chosen is
/// graded toward, so that each level refines the one before there
/// whatever the weight (an ungraded end keeps one panel of a few nodes on
/// the first levels of [`SplitLevel::level`], which would agree however
/// wrong they are); a plain weight then with at most
/// [`PLAIN_END_LAYERS`](super::split::PLAIN_END_LAYERS) layers (`choose`
/// marks it).
fn install(problem: &mut SplitProblem, w: &[Ends], open: &[(bool, bool)]) {
    let (a, b) = problem.domain;
    for (u, (&(l, h), &(ol, oh))) in w.iter().zip(open).enumerate() {
        for (z, e, o) in [(a, l, ol), (b, h, oh)] {
            if o {
                problem.contact.singulars.push(SplitSingular {
                    unknown: u,
                    at: RealFn::new(move |_, _| z),
                    side: 0,
                    kind: SplitKind::Weight {
                        exponent: RealFn::new(move |_, _| e),
                    },
                });
            }
        }
    }
}

/// Levels 0 and 1 with the weights `w`: per unknown the distance of
/// `u/weight` on the grid relative to its largest value (at least 1), and
/// the score (the largest of them and the least-squares residual). The
/// declarations are restored to the first `base` afterwards.
fn trial(
    problem: &mut SplitProblem,
    w: &[Ends],
    open: &[(bool, bool)],
    base: usize,
) -> Result<(Vec<Option<f64>>, f64), PlanError> {
    install(problem, w, open);
    let levels = (|| {
        let d0 = problem.discretise(&[], &SplitLevel::level(0))?;
        let d1 = problem.discretise(&[], &SplitLevel::level(1))?;
        let s0 = sample(problem, &d0, w)?;
        let s1 = sample(problem, &d1, w)?;
        Ok::<_, PlanError>((s0, s1, d1.consistency))
    })();
    problem.contact.singulars.truncate(base);
    let (s0, s1, residual) = levels?;
    let dists: Vec<Option<f64>> = s0
        .iter()
        .zip(&s1)
        .map(|(p, q)| {
            let (p, q) = (p.as_ref()?, q.as_ref()?);
            let scale = q
                .iter()
                .filter(|v| v.is_finite())
                .fold(1.0f64, |m, v| m.max(v.abs()));
            let mut d = 0.0f64;
            for (x, y) in p.iter().zip(q) {
                if x.is_finite() && y.is_finite() {
                    d = d.max((x - y).abs() / scale);
                } else if x.is_finite() != y.is_finite() {
                    d = f64::INFINITY;
                }
            }
            Some(d)
        })
        .collect();
    let score = dists.iter().flatten().fold(residual, |m, &d| m.max(d));
    if !score.is_finite() {
        return Err(PlanError::Invalid(
            "the trial space gives no finite answer".into(),
        ));
    }
    Ok((dists, score))
}

/// Per unknown with a basis, `u/weight` on the grid (not finite where the
/// weight is zero or infinite).
fn sample(
    problem: &SplitProblem,
    d: &Discrete,
    w: &[Ends],
) -> Result<Vec<Option<Vec<f64>>>, PlanError> {
    let f = Fields::new(problem, d)?;
    let (a, b) = problem.domain;
    let mut out = Vec::with_capacity(w.len());
    for (u, &(l, h)) in w.iter().enumerate() {
        if d.bases[u].is_none() {
            out.push(None);
            continue;
        }
        let mut vals = Vec::with_capacity(GRID);
        for k in 0..GRID {
            let x = a + (b - a) * k as f64 / (GRID - 1) as f64;
            let weight = (x - a).abs().powf(l) * (b - x).abs().powf(h);
            let side = if k + 1 == GRID {
                Approach::Below
            } else {
                Approach::Above
            };
            let v = f.value(u, x, side)? / weight;
            vals.push(if weight.is_finite() && weight != 0.0 {
                v
            } else {
                f64::NAN
            });
        }
        out.push(Some(vals));
    }
    Ok(out)
}
