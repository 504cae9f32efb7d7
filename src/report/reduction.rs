//! A reduction as text, LaTeX or one JSON object: the printer behind
//! [`crate::api::Reduction`], the `reduce` command and the `solve for` part
//! of `run`, and the per-subinterval reductions of a split-domain program.
//! Formatting only; the algebra and the expansion are done in
//! [`crate::reduce`].

use super::smith::{checks, matrix};
use crate::error::CliError;
use crate::algebra::print::latex_name;
use crate::reduce::expand::{sum_latex, sum_text};
use crate::reduce::{Reduction, StepsForm, reduce};
use serde_json::{Value, json};
use std::fmt::Write as _;

/// The reduction of every subinterval of a split-domain program for
/// unknown `u` (where it is free; else the first free unknown there). A
/// subinterval where no equation holds (only substitutions such as
/// `p = 0 on [a, 2]`) has nothing to reduce and is left out.
pub fn split_reductions(
    p: &crate::system::Program,
    u: usize,
) -> Result<Vec<(crate::reduce::split::Piece, Reduction)>, CliError> {
    let target = &p.unknowns[u];
    let pieces = crate::reduce::split::pieces(p).map_err(|e| CliError::Invalid(e.to_string()))?;
    pieces
        .into_iter()
        .filter(|piece| !piece.program.equations.is_empty())
        .map(|piece| {
            let v = piece
                .program
                .unknowns
                .iter()
                .position(|n| n == target)
                .unwrap_or(0);
            let r = reduce(&piece.program, v)?;
            Ok((piece, r))
        })
        .collect()
}

const MODEL_NOTE: &str = "the substitution holds on this piece only; operators integrating beyond it see the other pieces' unknowns, so the single equation is a model there (the seed's (2.4)); `solve` keeps the pieces coupled";

/// The JSON object `{"pieces": [...]}` of [`split_reductions`].
pub fn split_json(list: &[(crate::reduce::split::Piece, Reduction)]) -> Value {
    let pieces: Vec<Value> = list
        .iter()
        .map(|(piece, r)| {
            json!({
                "interval": piece.label,
                "substituted": piece.substituted,
                "note": if piece.substituted.is_empty() { Value::Null } else { json!(MODEL_NOTE) },
                "reduction": to_json(r),
            })
        })
        .collect();
    json!({ "pieces": pieces })
}

/// Text (or LaTeX) of [`split_reductions`].
pub fn split_text(list: &[(crate::reduce::split::Piece, Reduction)], as_latex: bool) -> String {
    let mut s = String::new();
    for (i, (piece, r)) in list.iter().enumerate() {
        let subst = if piece.substituted.is_empty() {
            String::new()
        } else {
            format!(" with {} substituted", piece.substituted.join(", "))
        };
        if as_latex {
            let _ = writeln!(s, "% on {}{subst}", piece.label);
            s.push_str(&latex(r));
            continue;
        }
        if i > 0 {
            s.push('\n');
        }
        let q = &piece.program;
        let _ = writeln!(
            s,
            "━━ on {}{subst}: {} equation(s) in {} ━━",
            piece.label,
            q.equations.len(),
            q.unknowns.join(", ")
        );
        if !piece.substituted.is_empty() {
            let _ = writeln!(s, "note: on {}, {MODEL_NOTE}", piece.label);
        }
        s.push_str(&text(r));
    }
    s
}

/// The JSON object of a reduction. Every formula in it is in the
/// language's syntax and parses back with [`crate::lang::formula`] (ring
/// elements) or the language's expression grammar (right sides `value`),
/// except the display strings `eliminant.text` (with `op[value]`
/// applications) and `expanded` (iterated integrals), which are prose.
pub fn to_json(r: &Reduction) -> Value {
    let rhs: Vec<Value> = r
        .rhs
        .iter()
        .map(|t| json!({"operator": t.operator, "equation": t.equation, "value": t.value}))
        .collect();
    let (ordered, ordered_inverses, ordered_pivots) = match &r.ordered {
        Ok(o) => (
            Value::String(o.lmx.clone()),
            json!(o.inverses_lmx),
            json!(o.pivots),
        ),
        Err(e) => (Value::Null, json!([]), json!([e])),
    };
    let ordered_steps = match &r.ordered_steps {
        Ok(st) => steps_json(st),
        Err(e) => json!({"not_available": e}),
    };
    let expanded = match &r.expanded {
        Ok(x) => json!({"lhs": sum_text(&x.lhs), "rhs": sum_text(&x.rhs)}),
        Err(e) => json!({"not_expanded": e}),
    };
    let eliminant = match &r.eliminant_refused {
        Some(why) => json!({"not_expanded": why}),
        None => json!({
            "lhs": r.lhs,
            "rhs": rhs,
            "text": r.eliminant_text(),
            "lhs_ordered": r.lhs_ordered_lmx,
            "removed_factor": r.removed_factor,
            "dropped": r.dropped.iter().zip(&r.dropped_lmx).map(|((_, u), c)| json!({"operator": c, "unknown": u})).collect::<Vec<_>>(),
        }),
    };
    json!({
        "unknown": r.unknown,
        "lambda_matrix": r.lambda_matrix,
        "invariant_factors": r.invariant_factors,
        "eliminant": eliminant,
        "expanded": expanded,
        "ordered": ordered,
        "ordered_inverses": ordered_inverses,
        "ordered_pivots": ordered_pivots,
        "ordered_steps": ordered_steps,
        "commuted_pairs": r.commuted_pairs.iter().map(|c| c.pair.clone()).collect::<Vec<_>>(),
        "notes": r.notes,
    })
}

/// The steps form as JSON: every formula in the language's syntax over
/// `symbols` (operators, `g1..gn`, intermediates), so it parses back with
/// [`crate::lang::formula::parse_ncexpr`].
fn steps_json(st: &StepsForm) -> Value {
    let steps: Vec<Value> = st
        .steps
        .iter()
        .map(|s| {
            let updates: Vec<Value> = s
                .updates
                .iter()
                .map(|u| {
                    json!({
                        "name": u.name,
                        "equation": u.equation,
                        "unknown": u.unknown,
                        "value": u.value.lmx,
                        "vanishes": u.vanishes,
                    })
                })
                .collect();
            json!({
                "equation": s.equation,
                "unknown": s.unknown,
                "pivot": s.pivot.lmx,
                "inverse": s.inverse.lmx,
                "updates": updates,
            })
        })
        .collect();
    json!({
        "symbols": st.symbols,
        "steps": steps,
        "result": {"equation": st.equation, "lhs": st.lhs.lmx, "rhs": st.rhs.lmx},
        "inverses": st.inverses.iter().map(|i| i.lmx.clone()).collect::<Vec<_>>(),
    })
}

/// The steps form as text lines (indented by two spaces).
fn steps_text(st: &StepsForm, out: &mut String) {
    let _ = writeln!(
        out,
        "  as steps (nothing expanded; gj is the right side of equation j; each update is named, Sk for a coefficient, Rk for a right side):"
    );
    for (i, s) in st.steps.iter().enumerate() {
        let inv = if s.constant {
            format!("{} (a number)", s.inverse.text)
        } else {
            s.inverse.text.clone()
        };
        let _ = writeln!(
            out,
            "  step {}: {} from equation {}, pivot {}, inverse {}",
            i + 1,
            s.unknown,
            s.equation,
            s.pivot.text,
            inv
        );
        for u in &s.updates {
            let on = match &u.unknown {
                Some(x) => format!("coefficient of {x}"),
                None => "right side".to_string(),
            };
            let zero = if u.vanishes { " = 0" } else { "" };
            let _ = writeln!(
                out,
                "    {} = {}{zero}    [equation {}, {on}]",
                u.name, u.value.text, u.equation
            );
        }
    }
    let _ = writeln!(
        out,
        "  result, equation {}: {}    where {}",
        st.equation,
        st.result.text,
        right_sides(st)
    );
    if st.inverses.is_empty() {
        let _ = writeln!(out, "  requires no inverse");
    } else {
        let inv: Vec<&str> = st.inverses.iter().map(|i| i.text.as_str()).collect();
        let _ = writeln!(out, "  inverses required: {}", inv.join(", "));
    }
}

/// `g1 = 1, g2 = 0` for the right sides of the equations.
fn right_sides(st: &StepsForm) -> String {
    st.right_sides
        .iter()
        .map(|(g, v)| format!("{g} = {v}"))
        .collect::<Vec<_>>()
        .join(", ")
}

fn pair_list(r: &Reduction) -> String {
    r.commuted_pairs
        .iter()
        .map(|c| format!("({}, {})", c.pair[0], c.pair[1]))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The text report.
pub fn text(r: &Reduction) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "Reduction for {}", r.unknown);
    let _ = writeln!(
        out,
        "\nλ-matrix over {} (rows: equations; columns: {}):",
        r.ring,
        r.unknowns.join(", ")
    );
    out.push_str(&matrix("A", &r.lambda_matrix));
    if r.invariant_factors.is_empty() {
        let _ = writeln!(out, "invariant factors: not computed (too many minors)");
    } else {
        let _ = writeln!(
            out,
            "invariant factors over {} (determinantal divisors): {}",
            r.ring,
            r.invariant_factors.join(", ")
        );
        out.push_str(&checks(&r.smith_checks));
    }

    let _ = writeln!(
        out,
        "\nEliminant (commutative: the symbols are treated as commuting):"
    );
    if let Some(why) = &r.eliminant_refused {
        let _ = writeln!(out, "  {why}");
    } else {
        eliminant_text(r, &mut out);
    }
    ordered_text(r, &mut out);
    out
}

fn eliminant_text(r: &Reduction, out: &mut String) {
    let _ = writeln!(out, "  {}", r.eliminant_text());
    let _ = writeln!(
        out,
        "  derived as {} (Ej: equation j); in the derivation's order the operator on {} is {}",
        r.derivation_text(),
        r.unknown,
        r.lhs_ordered
    );
    match &r.removed_factor {
        Some(h) => {
            let _ = writeln!(
                out,
                "  det(A) = {}; removed the common factor {h} of the whole relation",
                r.det
            );
        }
        None => {
            let _ = writeln!(
                out,
                "  det(A) = {}; the relation has no common factor",
                r.det
            );
        }
    }
    for (c, u) in &r.dropped {
        let _ = writeln!(
            out,
            "  dropped: ({c}) {u}, which is zero only if the operators commute"
        );
    }

    let params: Vec<String> = r.params.iter().map(|(n, v)| format!("{n} = {v}")).collect();
    let _ = writeln!(
        out,
        "\nExpanded (iterated integrals{}):",
        if params.is_empty() {
            String::new()
        } else {
            format!("; substituted {}", params.join(", "))
        }
    );
    match &r.expanded {
        Ok(x) => {
            for (i, t) in x.lhs.iter().enumerate() {
                let sign = match (i, t.coeff < num_traits::Zero::zero()) {
                    (_, true) => "-",
                    (0, false) => " ",
                    (_, false) => "+",
                };
                let _ = writeln!(out, "    {sign} {}    [{}]", t.body_text(), t.source);
            }
            if x.rhs.is_empty() {
                let _ = writeln!(out, "  = 0");
            }
            for (i, t) in x.rhs.iter().enumerate() {
                let neg = t.coeff < num_traits::Zero::zero();
                let lead = match (i, neg) {
                    (0, true) => "  = -",
                    (0, false) => "  =  ",
                    (_, true) => "    -",
                    (_, false) => "    +",
                };
                let _ = writeln!(out, "{lead} {}    [{}]", t.body_text(), t.source);
            }
        }
        Err(e) => {
            let _ = writeln!(out, "  not expanded: {e}");
        }
    }
}

fn ordered_text(r: &Reduction, out: &mut String) {
    let _ = writeln!(
        out,
        "\nOrdered elimination (no symbol commuted; exact for non-commuting operators):"
    );
    match &r.ordered {
        Ok(o) => {
            let gs: Vec<String> = o
                .right_sides
                .iter()
                .map(|(g, v)| format!("{g} = {v}"))
                .collect();
            let _ = writeln!(out, "  {}    where {}", o.text, gs.join(", "));
            let _ = writeln!(out, "  pivots: {}", o.pivots.join("; "));
            if o.inverses.is_empty() {
                let _ = writeln!(out, "  requires no inverse");
            } else {
                let _ = writeln!(out, "  inverses required: {}", o.inverses.join(", "));
            }
            let _ = writeln!(
                out,
                "  commuting every symbol turns it into Cramer's rule: {}",
                if o.agrees_with_cramer { "yes" } else { "NO" }
            );
        }
        Err(e) => {
            let _ = writeln!(out, "  Schur form not available: {e}");
            if let Ok(st) = &r.ordered_steps {
                steps_text(st, out);
            }
        }
    }

    if r.eliminant_refused.is_some() {
        let _ = writeln!(
            out,
            "\nCommuted pairs: not computed (the eliminant was not expanded)"
        );
    } else if r.commuted_pairs.is_empty() {
        let _ = writeln!(
            out,
            "\nCommuted pairs: none (the eliminant holds for non-commuting operators)"
        );
    } else {
        let _ = writeln!(
            out,
            "\nCommuted pairs (the eliminant is exact only if these commute): {}",
            pair_list(r)
        );
        for c in &r.commuted_pairs {
            let _ = writeln!(
                out,
                "  {} {} ≠ {} {} in general: needed to drop the terms in {}",
                c.pair[0],
                c.pair[1],
                c.pair[1],
                c.pair[0],
                c.on.join(", ")
            );
        }
    }
    for n in &r.notes {
        let _ = writeln!(out, "note: {n}");
    }
}

/// The LaTeX report (formulas with `%` comments).
pub fn latex(r: &Reduction) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "% Reduction for {}", r.unknown);
    let body: Vec<String> = r
        .lambda_matrix_latex
        .iter()
        .map(|x| x.join(" & "))
        .collect();
    let _ = writeln!(
        out,
        "\\[ A = \\begin{{pmatrix}} {} \\end{{pmatrix}} \\]",
        body.join(" \\\\ ")
    );
    if !r.invariant_factors_latex.is_empty() {
        let _ = writeln!(out, "% invariant factors over {}", r.ring);
        let _ = writeln!(
            out,
            "\\[ {} \\]",
            r.invariant_factors_latex.join(",\\quad ")
        );
    }
    match &r.eliminant_refused {
        Some(why) => {
            let _ = writeln!(out, "% eliminant (commutative): {why}");
        }
        None => {
            let _ = writeln!(out, "% eliminant (commutative)");
            let _ = writeln!(out, "\\[ {} \\]", r.eliminant_latex());
        }
    }
    match &r.expanded {
        Ok(x) => {
            let _ = writeln!(out, "% expanded");
            let _ = writeln!(
                out,
                "\\begin{{multline*}}\n{}\n\\\\ = {}\n\\end{{multline*}}",
                sum_latex(&x.lhs),
                sum_latex(&x.rhs)
            );
        }
        Err(e) => {
            let _ = writeln!(out, "% not expanded: {e}");
        }
    }
    match &r.ordered {
        Ok(o) => {
            let _ = writeln!(out, "% ordered elimination (exact)");
            let _ = writeln!(out, "\\[ {} \\]", o.latex);
        }
        Err(e) => {
            let _ = writeln!(out, "% ordered elimination, Schur form not available: {e}");
            if let Ok(st) = &r.ordered_steps {
                let _ = writeln!(
                    out,
                    "% ordered elimination as steps (g_j: right side of equation j; S_k, R_k: named updates)"
                );
                let mut lines = Vec::new();
                for (i, s) in st.steps.iter().enumerate() {
                    lines.push(format!(
                        "&\\text{{step {}: {} from equation {}, pivot }} {} && \\text{{inverse }} {}",
                        i + 1,
                        s.unknown,
                        s.equation,
                        s.pivot.latex,
                        s.inverse.latex
                    ));
                    for u in &s.updates {
                        lines.push(format!("{} &= {}", latex_name(&u.name), u.value.latex));
                    }
                }
                lines.push(format!("&\\text{{result: }} {}", st.result.latex));
                let _ = writeln!(
                    out,
                    "\\begin{{align*}}\n{}\n\\end{{align*}}",
                    lines.join(" \\\\\n")
                );
            }
        }
    }
    let _ = writeln!(
        out,
        "% commuted pairs: {}",
        if r.commuted_pairs.is_empty() {
            "none".to_string()
        } else {
            pair_list(r)
        }
    );
    out
}
