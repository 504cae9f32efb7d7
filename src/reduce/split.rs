//! The subintervals of a split-domain program, each as an ordinary
//! [`Program`] that [`super::reduce`] can reduce: the equations that hold
//! there, with every relation `u = κ·v` of the subinterval substituted
//! (column `u` of the λ-matrix added to column `v` times `κ`, then
//! removed). A factor `κ` that is an exact rational scales the column; a
//! scalar or real parameter becomes a new commuting symbol of the
//! λ-matrix (so the slip-zone matrix is over `Q(μ)[k1..k4]` when μ is an
//! unknown scalar). The order of the breakpoints is decided at a
//! representative value of every scalar (the middle of its range); the
//! labels keep the written ends. It must not print or solve anything.
use num_rational::BigRational;

use crate::algebra::mpoly::MPoly;
use crate::algebra::ncpoly::NcPoly;
use crate::system::contact::{Interval, RExpr};
use crate::system::{Equation, Expr, FunctionalTerm, Program};

/// One subinterval and its system.
#[derive(Clone, Debug)]
pub struct Piece {
    /// The subinterval as written, e.g. `[c, 1]`.
    pub label: String,
    /// The substitutions made, e.g. `q = mu*p`.
    pub substituted: Vec<String>,
    /// The system holding there (no split-domain declarations left).
    pub program: Program,
}

/// Why the pieces could not be formed.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct PieceError(pub String);

/// The subintervals of `p`, left to right.
pub fn pieces(p: &Program) -> Result<Vec<Piece>, PieceError> {
    let c = &p.contact;
    let slots = c.slots();
    let reps: Vec<f64> = c
        .scalars
        .iter()
        .map(|s| {
            if s.range.1.is_finite() {
                0.5 * (s.range.0 + s.range.1)
            } else {
                s.range.0 + 1.0
            }
        })
        .collect();
    let vars = c.values(&reps);
    // Every written end with its value.
    let mut ends: Vec<(f64, String)> = Vec::new();
    let mut push = |e: &RExpr| ends.push((e.eval(&vars, 0.0), e.to_text(&slots)));
    for d in c
        .equation_domains
        .iter()
        .flatten()
        .chain(c.relations.iter().map(|r| &r.domain))
    {
        push(&d.lo);
        push(&d.hi);
    }
    for d in c.unknown_domains.iter().flatten() {
        push(&d.lo);
        push(&d.hi);
    }
    ends.sort_by(|a, b| a.0.total_cmp(&b.0));
    ends.dedup_by(|a, b| a.0 == b.0);
    if ends.iter().any(|e| !e.0.is_finite()) {
        return Err(PieceError("an interval end cannot be evaluated".into()));
    }
    let holds = |d: &Interval, m: f64| {
        let (lo, hi) = d.eval(&vars);
        lo < m && m < hi
    };
    let mut out = Vec::new();
    for w in ends.windows(2) {
        let (a, b) = (&w[0], &w[1]);
        let m = 0.5 * (a.0 + b.0);
        let eqs: Vec<usize> = (0..p.equations.len())
            .filter(|&e| {
                c.equation_domains
                    .get(e)
                    .and_then(Option::as_ref)
                    .is_none_or(|d| holds(d, m))
            })
            .collect();
        let closed = |d: Option<&Interval>, left: bool| {
            d.is_some_and(|d| if left { d.lo_closed } else { d.hi_closed })
        };
        // Brackets from the equation or relation that has this end.
        let find = |left: bool| {
            c.equation_domains
                .iter()
                .flatten()
                .chain(c.relations.iter().map(|r| &r.domain))
                .find(|d| {
                    let (lo, hi) = d.eval(&vars);
                    if left {
                        lo == a.0 && holds(d, m)
                    } else {
                        hi == b.0 && holds(d, m)
                    }
                })
        };
        let label = format!(
            "{}{}, {}{}",
            if closed(find(true), true) { "[" } else { "(" },
            a.1,
            b.1,
            if closed(find(false), false) { "]" } else { ")" }
        );
        let mut program = p.clone();
        program.contact = Default::default();
        program.equations = eqs.iter().map(|&e| p.equations[e].clone()).collect();
        let mut substituted = Vec::new();
        let mut removed = vec![false; p.unknowns.len()];
        // What each unknown is on this piece: itself, or a factor times
        // another (for the side conditions, printed in the piece's terms).
        let mut through: Vec<(Option<BigRational>, usize)> =
            (0..p.unknowns.len()).map(|u| (None, u)).collect();
        for r in c.relations.iter().filter(|r| holds(&r.domain, m)) {
            let factor = match &r.coeff {
                RExpr::Const(q) => Factor::Exact(q.clone()),
                RExpr::Var(s) => Factor::Symbol(slots[*s].clone()),
                other => {
                    return Err(PieceError(format!(
                        "the relation factor {} is neither a constant nor a parameter: it cannot enter the λ-matrix",
                        other.to_text(&slots)
                    )));
                }
            };
            let sym = match &factor {
                Factor::Symbol(name) => Some(add_symbol(&mut program, name)),
                Factor::Exact(_) => None,
            };
            for eq in &mut program.equations {
                let col = eq.lhs[r.unknown].clone();
                // k (κ v): the factor is applied first, so it is written last.
                let scaled = match (&factor, sym) {
                    (Factor::Exact(q), _) => col.scale(q),
                    (_, Some(s)) => &col * &NcPoly::var(s),
                    _ => col,
                };
                eq.lhs[r.other] = &eq.lhs[r.other] + &scaled;
                eq.lhs[r.unknown] = NcPoly::zero();
            }
            removed[r.unknown] = true;
            through[r.unknown] = match &factor {
                Factor::Exact(q) => (Some(q.clone()), r.other),
                Factor::Symbol(_) => (None, usize::MAX),
            };
            substituted.push(format!(
                "{} = {}*{}",
                p.unknowns[r.unknown],
                r.coeff.to_text(&slots),
                p.unknowns[r.other]
            ));
        }
        let keep: Vec<usize> = (0..p.unknowns.len()).filter(|&u| !removed[u]).collect();
        program.unknowns = keep.iter().map(|&u| p.unknowns[u].clone()).collect();
        program.equations = program
            .equations
            .into_iter()
            .map(|eq| Equation {
                lhs: keep.iter().map(|&u| eq.lhs[u].clone()).collect(),
                rhs: eq.rhs,
                written: eq.written,
            })
            .collect();
        // Side conditions over the piece's unknowns: a substituted unknown
        // replaced by its relation (a condition through a relation with a
        // parameter's factor is left out of the piece).
        let index = |u: usize| keep.iter().position(|&k| k == u);
        program.side_conditions = p
            .side_conditions
            .iter()
            .filter_map(|sc| {
                let mut sc = sc.clone();
                for t in &mut sc.terms {
                    let (FunctionalTerm::Integral { coeff, unknown, .. }
                    | FunctionalTerm::Point { coeff, unknown, .. }) = t
                    else {
                        continue;
                    };
                    let (f, other) = through.get(*unknown).cloned()?;
                    if let Some(f) = f {
                        *coeff = Expr::Mul(Box::new(Expr::Const(f)), Box::new(coeff.clone()));
                    }
                    *unknown = index(other)?;
                }
                Some(sc)
            })
            .collect();
        program.directives.clear();
        program.outputs.clear();
        out.push(Piece {
            label,
            substituted,
            program,
        });
    }
    Ok(out)
}

enum Factor {
    Exact(BigRational),
    Symbol(String),
}

/// Adds a commuting symbol (if new) and widens the matrices' polynomials
/// (operator words need no widening).
fn add_symbol(p: &mut Program, name: &str) -> usize {
    if let Some(i) = p.symbols.iter().position(|s| s == name) {
        return i;
    }
    p.symbols.push(name.to_string());
    let n = p.symbols.len();
    let widen = |m: &MPoly| {
        MPoly::from_terms(
            n,
            m.terms().iter().map(|(mono, c)| {
                let mut mono = mono.clone();
                mono.resize(n, 0);
                (mono, c.clone())
            }),
        )
    };
    for m in &mut p.matrices {
        for e in &mut m.entries {
            *e = widen(e);
        }
    }
    n - 1
}
