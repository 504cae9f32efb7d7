//! Program → source text: prints a lowered [`Program`] in the concrete
//! syntax of `grammar/lambdamat.pest`, so that parsing the text again gives
//! the same program (parameters appear already substituted, constants
//! folded, operator bodies as flat sums of terms). It owns the layout of the
//! printed file only; it must not validate, simplify or do algebra.

use std::fmt::Write;

use num_traits::One;

use crate::algebra::print::{Node, PrintOptions, print};
use crate::system::contact::{Contact, EndSite};

use crate::system::{
    Directive, Expr, FunctionalTerm, Limit, MatrixDef, OperatorDef, Program, SideCondition, Term,
};

/// An interval in source syntax.
fn interval(d: &crate::system::contact::Interval, slots: &[String]) -> String {
    format!(
        "{}{}, {}{}",
        if d.lo_closed { "[" } else { "(" },
        d.lo.to_text(slots),
        d.hi.to_text(slots),
        if d.hi_closed { "]" } else { ")" }
    )
}

/// Relations, singular declarations and conditions.
fn contact(program: &Program, slots: &[String], out: &mut String) {
    use crate::system::contact::SingularKind;
    let c = &program.contact;
    let unknown = |i: usize| program.unknowns.get(i).map_or("?", String::as_str);
    for r in &c.relations {
        let zero = matches!(&r.coeff, crate::system::contact::RExpr::Const(q) if num_traits::Zero::is_zero(q));
        let value = if zero && r.other == r.unknown {
            "0".to_string()
        } else {
            format!("({})*{}", r.coeff.to_text(slots), unknown(r.other))
        };
        let _ = writeln!(
            out,
            "relation {} = {value} on {}",
            unknown(r.unknown),
            interval(&r.domain, slots)
        );
    }
    for q in &c.inequalities {
        let _ = writeln!(
            out,
            "inequality {} on {}",
            q.to_text(&program.unknowns, slots),
            interval(&q.domain, slots)
        );
    }
    for s in &c.singulars {
        let at = s.at.to_text(slots);
        let side = match s.side {
            -1 => "-",
            1 => "+",
            _ => "",
        };
        let body = match &s.kind {
            SingularKind::Weight { exponent } => {
                format!("({at} - x)^({})", exponent.to_text(slots))
            }
            SingularKind::Log => format!("ln(abs(x - ({at})))"),
            SingularKind::Term { coefficient, func } => format!(
                "{}*({})",
                c.coefficients.get(*coefficient).map_or("?", String::as_str),
                func.to_text(slots)
            ),
        };
        let _ = writeln!(
            out,
            "singular {} at ({at}){side} ~ {body}",
            unknown(s.unknown)
        );
    }
    for k in &c.conditions {
        let _ = writeln!(
            out,
            "condition {} = {}",
            c.coefficients
                .get(k.coefficient)
                .map_or("?", String::as_str),
            k.value.to_text(slots)
        );
    }
}

/// Prints `program` as lambdamat source.
///
/// ```
/// use lambdamat::lang::{parse_program, pretty::pretty};
/// let src = "var k1, k2\nunknown p\nequation (k1 + k2) p = x\n";
/// let p = parse_program(src, "a.lmx").expect("valid");
/// let text = pretty(&p);
/// assert_eq!(parse_program(&text, "b.lmx").expect("valid again"), p);
/// ```
pub fn pretty(program: &Program) -> String {
    let mut out = String::new();
    let names = &program.symbols;
    for p in &program.params {
        let _ = writeln!(out, "param {} = {}", p.name, Expr::Const(p.value.clone()));
    }
    let c = &program.contact;
    let slots = c.slots();
    // A scalar whose estimate uses a real parameter is declared after the
    // real parameters (which may use scalars, but not that estimate).
    let scalar_line = |i: usize, s: &crate::system::contact::Scalar| {
        let end = |v: f64| {
            if v.is_infinite() {
                "inf".to_string()
            } else {
                format!("{v}")
            }
        };
        let estimate = match c.estimates.get(i).and_then(Option::as_ref) {
            Some(e) => format!(" ~ {}", e.to_text(&slots)),
            None => String::new(),
        };
        format!(
            "scalar {} in ({}, {}){estimate}",
            s.name,
            end(s.range.0),
            end(s.range.1)
        )
    };
    let late = |i: usize| {
        c.estimates
            .get(i)
            .and_then(Option::as_ref)
            .is_some_and(crate::system::contact::RExpr::uses_slots)
    };
    for (i, s) in c.scalars.iter().enumerate() {
        if !late(i) {
            let _ = writeln!(out, "{}", scalar_line(i, s));
        }
    }
    for r in &c.reals {
        let _ = writeln!(out, "param {} = {}", r.name, r.value.to_text(&slots));
    }
    for (i, s) in c.scalars.iter().enumerate() {
        if late(i) {
            let _ = writeln!(out, "{}", scalar_line(i, s));
        }
    }
    for (i, name) in names.iter().enumerate() {
        match program.operator(i) {
            Some(def) => {
                let _ = writeln!(out, "operator {name} = {}", operator_body(def, c, &slots));
            }
            None => {
                let _ = writeln!(out, "var {name}");
            }
        }
    }
    if let Some(name) = program.principal.and_then(|i| names.get(i)) {
        let _ = writeln!(out, "principal {name}");
    }
    for m in &program.matrices {
        let _ = writeln!(out, "matrix {} = {}", m.name, matrix(m, names));
    }
    if !program.unknowns.is_empty() {
        let domain = match c.unknown_domains.first() {
            Some(Some(d)) if c.unknown_domains.iter().all(|o| o.as_ref() == Some(d)) => {
                format!(" on {}", interval(d, &slots))
            }
            _ => String::new(),
        };
        let _ = writeln!(out, "unknown {}{domain}", program.unknowns.join(", "));
    }
    for (i, eq) in program.equations.iter().enumerate() {
        let terms: Vec<(bool, Node)> = eq
            .lhs
            .iter()
            .zip(&program.unknowns)
            .filter(|(c, _)| !c.is_zero())
            .map(|(c, u)| {
                let (neg, op) = c.to_node(names).split_sign();
                let term = match op {
                    Node::Num(v) if v.is_one() => Node::sym(u),
                    op => Node::Apply(Box::new(op), Box::new(Node::sym(u))),
                };
                (neg, term)
            })
            .collect();
        let lhs = if terms.is_empty() {
            let first = program.unknowns.first().map_or("p", String::as_str);
            format!("0 {first}")
        } else {
            print(&Node::Terms(terms), PrintOptions::LMX)
        };
        let domain = match c.equation_domains.get(i) {
            Some(Some(d)) => format!(" on {}", interval(d, &slots)),
            _ => String::new(),
        };
        let _ = writeln!(out, "equation {lhs} = {}{domain}", eq.rhs);
    }
    contact(program, &slots, &mut out);
    for (output, o) in program.outputs.iter().enumerate() {
        let terms: Vec<String> = o
            .terms
            .iter()
            .enumerate()
            .map(|(term, t)| {
                let site = EndSite::Output { output, term };
                let ends = [false, true].map(|up| moving(c, &slots, site, up));
                functional_term(t, &program.unknowns, &ends)
            })
            .collect();
        let body = if terms.is_empty() {
            "0".to_string()
        } else {
            terms.join(" + ")
        };
        let _ = writeln!(out, "output {} = {body}", o.name);
    }
    for (condition, sc) in program.side_conditions.iter().enumerate() {
        let terms: Vec<String> = sc
            .terms
            .iter()
            .enumerate()
            .map(|(term, t)| {
                let site = EndSite::Condition { condition, term };
                let ends = [false, true].map(|up| moving(c, &slots, site, up));
                functional_term(t, &program.unknowns, &ends)
            })
            .collect();
        let _ = writeln!(out, "condition {} = {}", terms.join(" + "), sc.value);
    }
    let matrix_name = |i: usize| program.matrices.get(i).map_or("?", |m| m.name.as_str());
    for d in &program.directives {
        let _ = match d {
            Directive::Smith { matrix } => writeln!(out, "smith {}", matrix_name(*matrix)),
            Directive::CheckSmith { matrix, u, d, v } => writeln!(
                out,
                "check smith {} with {}, {}, {}",
                matrix_name(*matrix),
                matrix_name(*u),
                matrix_name(*d),
                matrix_name(*v)
            ),
            Directive::Solve { unknown } => writeln!(
                out,
                "solve for {}",
                program.unknowns.get(*unknown).map_or("?", String::as_str)
            ),
        };
    }
    out
}

fn matrix(m: &MatrixDef, names: &[String]) -> String {
    if m.rows == 0 || m.cols == 0 {
        return "[]".to_string();
    }
    let rows: Vec<String> = m
        .entries
        .chunks(m.cols)
        .map(|row| {
            row.iter()
                .map(|e| print(&e.to_node(names), PrintOptions::LMX))
                .collect::<Vec<_>>()
                .join(", ")
        })
        .collect();
    format!("[{}]", rows.join("; "))
}

fn limit(l: &Limit) -> String {
    match l {
        Limit::X => "x".to_string(),
        Limit::Const(q) => Expr::Const(q.clone()).to_string(),
    }
}

/// The source of a limit that uses a scalar (`Contact::ends`) at `site`.
fn moving(c: &Contact, slots: &[String], site: EndSite, upper: bool) -> Option<String> {
    c.ends
        .iter()
        .find(|e| e.site == site && e.upper == upper)
        .map(|e| e.value.to_text(slots))
}

fn operator_body(def: &OperatorDef, c: &Contact, slots: &[String]) -> String {
    if def.terms.is_empty() {
        return "0*id".to_string();
    }
    let at = |term: usize, l: &Limit, upper: bool| {
        let site = EndSite::Operator {
            symbol: def.symbol,
            term,
        };
        moving(c, slots, site, upper).unwrap_or_else(|| limit(l))
    };
    def.terms
        .iter()
        .enumerate()
        .map(|(i, t)| match t {
            Term::Integral {
                lower,
                upper,
                kernel,
                pv,
            } => format!(
                "{}int({}..{}) {kernel} dt",
                if *pv { "pv " } else { "" },
                at(i, lower, false),
                at(i, upper, true)
            ),
            Term::Multiply(f) => format!("{}*id", factor(f)),
            Term::Identity => "id".to_string(),
            Term::Scalar(c) => format!("{}*id", factor(&Expr::Const(c.clone()))),
        })
        .collect::<Vec<_>>()
        .join(" + ")
}

/// A side condition as source: `condition int(-1..1) f(x) dx = 1`.
pub fn side_condition(c: &SideCondition, unknowns: &[String]) -> String {
    let terms: Vec<String> = c
        .terms
        .iter()
        .map(|t| functional_term(t, unknowns, &[None, None]))
        .collect();
    format!("condition {} = {}", terms.join(" + "), c.value)
}

/// A functional's term as source; `ends`: the lower and upper limit's
/// source when it uses a scalar.
fn functional_term(t: &FunctionalTerm, unknowns: &[String], ends: &[Option<String>; 2]) -> String {
    let end = |i: usize, q: &num_rational::BigRational| {
        ends[i]
            .clone()
            .unwrap_or_else(|| Expr::Const(q.clone()).to_string())
    };
    match t {
        FunctionalTerm::Point { coeff, at, unknown } => {
            let name = unknowns.get(*unknown).map_or("?", String::as_str);
            let point = format!("{name}({})", end(1, at));
            if coeff.as_const().is_some_and(|c| c.is_one()) {
                point
            } else {
                format!("{}*{point}", factor(coeff))
            }
        }
        FunctionalTerm::Constant(c) => format!("({c})"),
        FunctionalTerm::Integral {
            coeff,
            lower,
            upper,
            weight,
            unknown,
        } if coeff.as_const().is_some_and(|c| c.is_one()) => format!(
            "int({}..{}) {}{}(x) dx",
            end(0, lower),
            end(1, upper),
            weight_prefix(weight),
            unknowns.get(*unknown).map_or("?", String::as_str)
        ),
        FunctionalTerm::Integral {
            coeff,
            lower,
            upper,
            weight,
            unknown,
        } => format!(
            "{}*int({}..{}) {}{}(x) dx",
            factor(coeff),
            end(0, lower),
            end(1, upper),
            weight_prefix(weight),
            unknowns.get(*unknown).map_or("?", String::as_str)
        ),
    }
}

/// `e` as the left factor of a product, parenthesised when needed.
fn factor(e: &Expr) -> String {
    if e.prec() < 2 {
        format!("({e})")
    } else {
        e.to_string()
    }
}

/// The weight in front of `u(x)`: nothing for 1, else `w*`.
fn weight_prefix(w: &Expr) -> String {
    if w.as_const().is_some_and(|c| c.is_one()) {
        String::new()
    } else {
        format!("{}*", factor(w))
    }
}
