//! Program → source text: prints a lowered [`Program`] in the concrete
//! syntax of `grammar/lambdamat.pest`, so that parsing the text again gives
//! the same program (parameters appear already substituted, constants
//! folded, operator bodies as flat sums of terms). It owns the layout of the
//! printed file only; it must not validate, simplify or do algebra.

use std::fmt::Write;

use num_traits::One;

use crate::algebra::print::{Node, PrintOptions, print};

use crate::system::{
    Directive, Expr, FunctionalTerm, Limit, MatrixDef, OperatorDef, Program, Term,
};

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
    for (i, name) in names.iter().enumerate() {
        match program.operator(i) {
            Some(def) => {
                let _ = writeln!(out, "operator {name} = {}", operator_body(def));
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
        let _ = writeln!(out, "unknown {}", program.unknowns.join(", "));
    }
    for eq in &program.equations {
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
        let _ = writeln!(out, "equation {lhs} = {}", eq.rhs);
    }
    for o in &program.outputs {
        let terms: Vec<String> = o
            .terms
            .iter()
            .map(|t| functional_term(t, &program.unknowns))
            .collect();
        let body = if terms.is_empty() {
            "0".to_string()
        } else {
            terms.join(" + ")
        };
        let _ = writeln!(out, "output {} = {body}", o.name);
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

fn operator_body(def: &OperatorDef) -> String {
    if def.terms.is_empty() {
        return "0*id".to_string();
    }
    def.terms
        .iter()
        .map(|t| match t {
            Term::Integral {
                lower,
                upper,
                kernel,
            } => format!("int({}..{}) {kernel} dt", limit(lower), limit(upper)),
            Term::Multiply(f) => format!("{}*id", factor(f)),
            Term::Identity => "id".to_string(),
            Term::Scalar(c) => format!("{}*id", factor(&Expr::Const(c.clone()))),
        })
        .collect::<Vec<_>>()
        .join(" + ")
}

fn functional_term(t: &FunctionalTerm, unknowns: &[String]) -> String {
    match t {
        FunctionalTerm::Constant(c) => format!("({c})"),
        FunctionalTerm::Integral {
            coeff,
            lower,
            upper,
            weight,
            unknown,
        } if coeff.as_const().is_some_and(|c| c.is_one()) => format!(
            "int({}..{}) {}{}(x) dx",
            Expr::Const(lower.clone()),
            Expr::Const(upper.clone()),
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
            Expr::Const(lower.clone()),
            Expr::Const(upper.clone()),
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
