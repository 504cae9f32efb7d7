//! An unknown on an interval that ends at an unknown scalar,
//! `unknown p on [0, a]` with `scalar a in (0, 2)`, read as what it means
//! for the solver: the unknown on the fixed interval that holds every value
//! of the scalar, `[0, 2]`, and zero beyond the scalar,
//! `relation p = 0 on [a, 2]`. An equation written without a domain then
//! holds where the unknown lives, `on [0, a)`. This module owns only that
//! rewrite of the syntax tree, made before validation; a scalar whose range
//! has no finite end on that side is left alone, and validation refuses it
//! at its line and column.

use num_rational::BigRational;

use super::ast::{Expr, ExprKind, File, Ident, Interval, Statement, Stmt};

/// Rewrites every unknowns' interval with an end that is a scalar's name.
pub(super) fn rewrite(file: &mut File) {
    let ranges: Vec<(String, Interval)> = file
        .statements
        .iter()
        .filter_map(|s| match &s.kind {
            Stmt::Scalar { name, range, .. } => Some((name.name.clone(), range.clone())),
            _ => None,
        })
        .collect();
    let range_of = |e: &Expr| match &e.kind {
        ExprKind::Name(id) => ranges
            .iter()
            .find(|(n, _)| *n == id.name)
            .map(|(_, r)| r.clone()),
        _ => None,
    };
    let mut relations = Vec::new();
    let mut lives_on: Vec<Interval> = Vec::new();
    for st in &mut file.statements {
        let Stmt::Unknown(names, Some(iv)) = &mut st.kind else {
            continue;
        };
        let written = iv.clone();
        let mut changed = false;
        if let Some(r) = range_of(&iv.hi).filter(|r| !super::validate_contact::is_inf(&r.hi)) {
            // [lo, a] → [lo, hi of a's range], zero on [a, hi].
            let end = r.hi.clone();
            for n in names.iter() {
                relations.push(zero(n, iv.hi.clone(), end.clone(), st.span, written.span));
            }
            iv.hi = end;
            iv.hi_closed = true;
            changed = true;
        }
        if let Some(r) = range_of(&iv.lo).filter(|r| !super::validate_contact::is_inf(&r.lo)) {
            // [a, hi] → [lo of a's range, hi], zero on [lo, a].
            let start = r.lo.clone();
            for n in names.iter() {
                relations.push(zero(n, start.clone(), iv.lo.clone(), st.span, written.span));
            }
            iv.lo = start;
            iv.lo_closed = true;
            changed = true;
        }
        if changed {
            lives_on.push(Interval {
                lo_closed: true,
                hi_closed: false,
                ..written
            });
        }
    }
    if lives_on.is_empty() {
        return;
    }
    // Equations without a domain hold where the unknowns live, when they
    // all live on the same written interval.
    let same = lives_on.iter().all(|i| same_ends(i, &lives_on[0]));
    let unknown_statements = file
        .statements
        .iter()
        .filter(|s| matches!(s.kind, Stmt::Unknown(..)))
        .count();
    let all_rewritten = unknown_statements == lives_on.len();
    if same && all_rewritten {
        for st in &mut file.statements {
            if let Stmt::Equation { domain, .. } = &mut st.kind
                && domain.is_none()
            {
                *domain = Some(lives_on[0].clone());
            }
        }
    }
    file.statements.extend(relations);
}

/// `relation u = 0 on [lo, hi]`, placed at the unknown's declaration.
fn zero(u: &Ident, lo: Expr, hi: Expr, at: super::ast::Span, iv: super::ast::Span) -> Statement {
    Statement {
        kind: Stmt::Relation {
            unknown: u.clone(),
            value: Expr {
                kind: ExprKind::Number(BigRational::from_integer(0.into())),
                span: iv,
            },
            domain: Interval {
                lo,
                hi,
                lo_closed: true,
                hi_closed: true,
                span: iv,
            },
        },
        span: at,
    }
}

/// Whether two intervals have the same ends as written.
fn same_ends(a: &Interval, b: &Interval) -> bool {
    a.lo.kind == b.lo.kind && a.hi.kind == b.hi.kind
}
