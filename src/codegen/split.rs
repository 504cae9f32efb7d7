//! Code generation for split-domain (contact) files: the operator system
//! without its split-domain declarations is written as for a one-interval
//! file (`system()`), and every interval end, relation factor, singular
//! point, weight exponent, singular term, condition value and real
//! parameter becomes a Rust function of the slot values `v` (scalars, then
//! real parameters) and `x`; `input()` puts them into a
//! [`crate::plan::SplitInput`] field for field as
//! [`crate::plan::SplitInput::from_program`] does, and `main()` solves it
//! through [`crate::plan::solve_split_input`] and prints the report of
//! `lambdamat solve`. The printed expressions perform the floating-point
//! operations of [`RExpr::eval`] in the same order (the same library
//! calls for powers and functions), so the generated solver agrees with
//! the in-process one bit for bit. Owns the layout of these parts only.
use std::collections::HashMap;
use std::fmt::Write;

use num_traits::ToPrimitive;

use super::rust::literal;
use super::{Names, Provenance, imports, struct_lit, vec_expr};
use crate::plan::{CompiledSystem, PlanError};
use crate::plan::split_input::{numeric_site, plain};
use crate::system::Program;
use crate::system::contact::{Contact, EndSite, Interval, RBin, RExpr, RFunc, SingularKind};

/// Rust source of a solver for the split-domain file `prog`.
pub fn split_solver_source(
    prog: &Program,
    target: Option<&str>,
    from: &Provenance,
) -> Result<String, PlanError> {
    let (sys, system) = super::system_code(&plain(prog), target)?;
    let mut fns = Fns::new(&prog.contact);
    let sites = prog
        .contact
        .ends
        .iter()
        .map(|e| numeric_site(prog, e.site))
        .collect::<Result<Vec<_>, _>>()?;
    let contact = contact_lit(&prog.contact, &sites, &mut fns);
    let mut code = system;
    code.push_str(&fns.code);
    code.push_str(
        "\n/// The split-domain problem, ready for `lambdamat::standalone::split_solver_main`.\n\
         pub fn input() -> Result<SplitInput, PlanError> {\n",
    );
    let _ = writeln!(code, "    let contact = {};", indent(&contact, 4));
    code.push_str("    let sys = system()?;\n    Ok(SplitInput { sys, contact })\n}\n");
    let mut out = String::new();
    header(&mut out, prog, &sys, from);
    out.push_str(&imports(&code));
    out.push_str(&code);
    out.push_str(
        "\n/// Solves the problem and prints the report of `lambdamat solve`; takes\n\
         /// `[--method coupled|ordered|commutative] [--tol T] [--max-level N] [--json]`\n\
         /// `[--csv FILE]` (see `--help`). It needs lambdamat without its command line:\n\
         /// `lambdamat = { path = \"…\", default-features = false }`.\n\
         pub fn main() {\n    \
         std::process::exit(lambdamat::standalone::split_solver_main(input));\n}\n",
    );
    Ok(out)
}

fn header(out: &mut String, prog: &Program, sys: &CompiledSystem, from: &Provenance) {
    super::provenance_lines(out, from);
    if !prog.contact.is_split() {
        out.push_str(
            "//!\n\
             //! Kernels, multipliers, right sides and output weights are the Rust\n\
             //! functions below; `system()` collects them, `input()` makes them a\n\
             //! problem without breakpoints, and `main()` solves it through\n\
             //! lambdamat's solver (`lambdamat::standalone::split_solver_main`):\n\
             //! assembly, refinement to the tolerance, and the error estimates.\n",
        );
        super::one_interval_derivation(out, prog, sys);
        super::source_block(out, prog, "system");
        return;
    }
    out.push_str(
        "//!\n\
         //! A split-domain (contact) problem. Kernels, right sides and output\n\
         //! weights are Rust functions of `x` (and `t`); interval ends, relation\n\
         //! factors, singular points, exponents and terms, condition values and\n\
         //! real parameters are Rust functions of the slot values `v` (the unknown\n\
         //! scalars, then the real parameters) and `x`. `input()` collects them and\n\
         //! `main()` solves through lambdamat's split-domain solver\n\
         //! (`lambdamat::standalone::split_solver_main`): the scalars' root solve,\n\
         //! refinement to the tolerance, and the error estimates. Parameters are\n\
         //! those of the regenerating command (`--set` there).\n",
    );
    let slots = prog.contact.slots();
    if !slots.is_empty() {
        let _ = writeln!(out, "//! Slots: {}.", slots.join(", "));
    }
    derivations(out, prog);
    super::source_block(out, prog, "problem");
}

/// The single equations `lambdamat reduce` derives on every subinterval,
/// for the reader (the solver keeps the subintervals coupled).
fn derivations(out: &mut String, prog: &Program) {
    let target = prog
        .directives
        .iter()
        .find_map(|d| match d {
            crate::system::Directive::Solve { unknown } => Some(*unknown),
            _ => None,
        })
        .unwrap_or(0);
    let Ok(pieces) = crate::reduce::split::pieces(prog) else {
        return;
    };
    let name = prog.unknowns.get(target).cloned().unwrap_or_default();
    let _ = writeln!(
        out,
        "//!\n//! Derived equations per subinterval (`lambdamat reduce`; a model where a\n\
         //! relation is substituted: the solver keeps the subintervals coupled):"
    );
    for piece in pieces {
        let q = &piece.program;
        let v = q.unknowns.iter().position(|n| *n == name).unwrap_or(0);
        let subst = if piece.substituted.is_empty() {
            String::new()
        } else {
            format!(" with {} substituted", piece.substituted.join(", "))
        };
        let _ = writeln!(out, "//! - on {}{subst}:", piece.label);
        match crate::reduce::reduce(q, v) {
            Ok(r) => {
                if let Ok(o) = &r.ordered {
                    let _ = writeln!(out, "//!   ordered elimination: `{}`", o.text);
                }
                if r.eliminant_refused.is_none() {
                    let _ = writeln!(out, "//!   commutative eliminant: `{}`", r.eliminant_text());
                }
            }
            Err(e) => {
                let _ = writeln!(out, "//!   {e}");
            }
        }
    }
}

/// The functions of the slot values written so far (one per distinct
/// body).
struct Fns {
    code: String,
    names: Names,
    by_body: HashMap<String, String>,
    slots: Vec<String>,
}

impl Fns {
    fn new(c: &Contact) -> Fns {
        let mut names = Names::default();
        // Names the one-interval part uses.
        for taken in ["system", "input", "main"] {
            names.fresh(taken);
        }
        Fns {
            code: String::new(),
            names,
            by_body: HashMap::new(),
            slots: c.slots(),
        }
    }

    /// `RealFn::new(f)` for a function `f` computing `e`.
    fn real(&mut self, role: &str, what: &str, e: &RExpr) -> String {
        let body = expr(e, Prec::Top);
        if let Some(f) = self.by_body.get(&body) {
            return format!("RealFn::new({f})");
        }
        // Constants and plain slots are shared under their own names; the
        // names never collide with the one-interval part's (`kernel_…`,
        // `rhs_…`, `weight_…`, `multiplier_…`).
        let text = e.to_text(&self.slots);
        let (role, what) = match e {
            RExpr::Var(i) => (
                format!("slot_{}", self.slots.get(*i).map_or("", String::as_str)),
                "Slot value".to_string(),
            ),
            _ if !(role.starts_with("real_")
                || role.starts_with("estimate_")
                || uses_var(e)
                || e.uses_x()) =>
            {
                (
                    format!("const_{}", text.replace('-', "minus_")),
                    "A constant".to_string(),
                )
            }
            _ => (role.to_string(), what.to_string()),
        };
        let f = self.names.fresh(&role);
        let uses_v = uses_var(e);
        let v = if uses_v { "v" } else { "_v" };
        let x = if e.uses_x() { "x" } else { "_x" };
        let _ = writeln!(self.code, "\n/// {what}: `{}`.", text.replace('`', "'"));
        let _ = writeln!(self.code, "fn {f}({v}: &[f64], {x}: f64) -> f64 {{");
        let one = format!("    {body}");
        if one.len() <= 100 {
            let _ = writeln!(self.code, "{one}");
        } else {
            // rustfmt breaks long expressions; keep them on a binding per
            // operand instead.
            let _ = writeln!(self.code, "    {}", broken(e));
        }
        self.code.push_str("}\n");
        self.by_body.insert(body, f.clone());
        format!("RealFn::new({f})")
    }

    fn interval(&mut self, role: &str, what: &str, i: &Interval) -> String {
        let lo = self.real(&format!("{role}_lo"), &format!("{what}, left end"), &i.lo);
        let hi = self.real(&format!("{role}_hi"), &format!("{what}, right end"), &i.hi);
        lit(
            "SplitInterval",
            &[
                ("lo", lo),
                ("hi", hi),
                ("lo_closed", i.lo_closed.to_string()),
                ("hi_closed", i.hi_closed.to_string()),
            ],
        )
    }
}

/// The `SplitContact { … }` literal for `c` (functions written to `fns`;
/// `sites`: the sites of `c.ends` as the solver counts them).
fn contact_lit(c: &Contact, sites: &[EndSite], fns: &mut Fns) -> String {
    let scalars: Vec<String> = c
        .scalars
        .iter()
        .map(|s| {
            lit(
                "Scalar",
                &[
                    ("name", format!("{:?}.into()", s.name)),
                    (
                        "range",
                        format!("({}, {})", literal(s.range.0), literal(s.range.1)),
                    ),
                ],
            )
        })
        .collect();
    let reals: Vec<String> = c
        .reals
        .iter()
        .map(|r| {
            fns.real(
                &format!("real_{}", r.name),
                &format!("Real parameter `{}`", r.name),
                &r.value,
            )
        })
        .collect();
    let mut domain = |list: &[Option<Interval>], role: &str, what: &str| -> Vec<String> {
        list.iter()
            .enumerate()
            .map(|(i, d)| match d {
                Some(d) => {
                    let lit = fns.interval(
                        &format!("{role}_{}", i + 1),
                        &format!("{what} {}", i + 1),
                        d,
                    );
                    format!("Some({lit})")
                }
                None => "None".into(),
            })
            .collect()
    };
    let unknown_domains = domain(&c.unknown_domains, "unknown", "Interval of unknown");
    let equation_domains = domain(&c.equation_domains, "equation", "Where equation");
    let rhs: Vec<String> = c
        .rhs
        .iter()
        .enumerate()
        .map(|(i, e)| match e {
            Some(e) => {
                let f = fns.real(
                    &format!("equation_{}_rhs", i + 1),
                    &format!(
                        "Right side of equation {} (it uses a scalar): `{}`",
                        i + 1,
                        e.to_text(&c.slots())
                    ),
                    e,
                );
                format!("Some({f})")
            }
            None => "None".into(),
        })
        .collect();
    let relations: Vec<String> = c
        .relations
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let role = format!("relation_{}", i + 1);
            let what = format!("Relation {}", i + 1);
            let coeff = fns.real(
                &format!("{role}_coeff"),
                &format!("{what}, factor"),
                &r.coeff,
            );
            let domain = fns.interval(&role, &what, &r.domain);
            lit(
                "SplitRelation",
                &[
                    ("unknown", r.unknown.to_string()),
                    ("coeff", coeff),
                    ("other", r.other.to_string()),
                    ("domain", domain),
                ],
            )
        })
        .collect();
    let inequalities: Vec<String> = c
        .inequalities
        .iter()
        .enumerate()
        .map(|(i, q)| {
            let role = format!("inequality_{}", i + 1);
            let what = format!("Inequality {}", i + 1);
            let mut side = |terms: &[crate::system::contact::LinTerm], name: &str| {
                let items: Vec<String> = terms
                    .iter()
                    .enumerate()
                    .map(|(j, t)| {
                        let coeff = fns.real(
                            &format!("{role}_{name}_{}", j + 1),
                            &format!("{what}, {name} side, factor {}", j + 1),
                            &t.coeff,
                        );
                        lit(
                            "SplitLinTerm",
                            &[("coeff", coeff), ("unknown", format!("{:?}", t.unknown))],
                        )
                    })
                    .collect();
                list(&items)
            };
            let lhs = side(&q.lhs, "smaller");
            let rhs = side(&q.rhs, "larger");
            let domain = fns.interval(&role, &what, &q.domain);
            lit(
                "SplitInequality",
                &[
                    ("abs", q.abs.to_string()),
                    ("lhs", lhs),
                    ("rhs", rhs),
                    ("domain", domain),
                    ("text", format!("{:?}.into()", q.text)),
                ],
            )
        })
        .collect();
    let singulars: Vec<String> = c
        .singulars
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let role = format!("singular_{}", i + 1);
            let what = format!("Singular declaration {}", i + 1);
            let at = fns.real(&format!("{role}_at"), &format!("{what}, point"), &s.at);
            let kind = match &s.kind {
                SingularKind::Weight { exponent } => {
                    let f = fns.real(
                        &format!("{role}_exponent"),
                        &format!("{what}, weight exponent"),
                        exponent,
                    );
                    lit("SplitKind::Weight", &[("exponent", f)])
                }
                SingularKind::Log => "SplitKind::Log".to_string(),
                SingularKind::Term { coefficient, func } => {
                    let f = fns.real(
                        &format!("{role}_term"),
                        &format!("{what}, singular term"),
                        func,
                    );
                    lit(
                        "SplitKind::Term",
                        &[("coefficient", coefficient.to_string()), ("func", f)],
                    )
                }
            };
            lit(
                "SplitSingular",
                &[
                    ("unknown", s.unknown.to_string()),
                    ("at", at),
                    ("side", s.side.to_string()),
                    ("kind", kind),
                ],
            )
        })
        .collect();
    let coefficients: Vec<String> = c
        .coefficients
        .iter()
        .map(|n| format!("{n:?}.into()"))
        .collect();
    let conditions: Vec<String> = c
        .conditions
        .iter()
        .enumerate()
        .map(|(i, k)| {
            let f = fns.real(
                &format!("condition_{}_value", i + 1),
                &format!("Condition {}, required value", i + 1),
                &k.value,
            );
            lit(
                "SplitCondition",
                &[("coefficient", k.coefficient.to_string()), ("value", f)],
            )
        })
        .collect();
    let estimates: Vec<String> = c
        .estimates
        .iter()
        .zip(&c.scalars)
        .map(|(e, s)| match e {
            Some(e) => {
                let f = fns.real(
                    &format!("estimate_{}", s.name),
                    &format!("Asymptotic estimate of the scalar `{}`", s.name),
                    e,
                );
                format!("Some({f})")
            }
            None => "None".into(),
        })
        .collect();
    let ends: Vec<String> = c
        .ends
        .iter()
        .zip(sites)
        .enumerate()
        .map(|(i, (e, site))| {
            let f = fns.real(
                &format!("end_{}", i + 1),
                &format!("Integration limit or point-value position {} (it uses a scalar)", i + 1),
                &e.value,
            );
            let site = match *site {
                EndSite::Operator { symbol, term } => {
                    format!("EndSite::Operator {{ symbol: {symbol}, term: {term} }}")
                }
                EndSite::Output { output, term } => {
                    format!("EndSite::Output {{ output: {output}, term: {term} }}")
                }
                EndSite::Condition { condition, term } => {
                    format!("EndSite::Condition {{ condition: {condition}, term: {term} }}")
                }
            };
            lit(
                "SplitEnd",
                &[("site", site), ("upper", e.upper.to_string()), ("value", f)],
            )
        })
        .collect();
    let fields = [
        ("scalars", list(&scalars)),
        ("reals", list(&reals)),
        ("unknown_domains", list(&unknown_domains)),
        ("equation_domains", list(&equation_domains)),
        ("rhs", list(&rhs)),
        ("relations", list(&relations)),
        ("inequalities", list(&inequalities)),
        ("singulars", list(&singulars)),
        ("coefficients", list(&coefficients)),
        ("conditions", list(&conditions)),
        ("estimates", list(&estimates)),
        ("ends", list(&ends)),
    ];
    lit("SplitContact", &fields)
}

/// A struct literal at indentation 0 (fields at 4), laid out as rustfmt
/// lays it out; multi-line field values are indented to fit.
fn lit(name: &str, fields: &[(&str, String)]) -> String {
    let fields: Vec<(&str, String)> = fields.iter().map(|(k, v)| (*k, indent(v, 4))).collect();
    struct_lit(name, &fields, 0)
}

/// `vec![…]` at indentation 0, laid out as rustfmt lays it out: one line
/// if it fits, a single multi-line item hugging the brackets, else one
/// item per line.
fn list(items: &[String]) -> String {
    match items {
        [one] if one.contains('\n') => format!("vec![{one}]"),
        _ if items.iter().any(|i| i.contains('\n')) => {
            let mut s = "vec![\n".to_string();
            for it in items {
                let _ = writeln!(s, "    {},", indent(it, 4));
            }
            s.push(']');
            s
        }
        _ => vec_expr(items, 0),
    }
}

/// `text` with every line after the first indented by `n` more spaces.
fn indent(text: &str, n: usize) -> String {
    let pad = " ".repeat(n);
    text.lines()
        .enumerate()
        .map(|(i, l)| {
            if i == 0 || l.is_empty() {
                l.to_string()
            } else {
                format!("{pad}{l}")
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
}

fn uses_var(e: &RExpr) -> bool {
    match e {
        RExpr::Var(_) => true,
        RExpr::Const(_) | RExpr::Pi | RExpr::X => false,
        RExpr::Neg(a) | RExpr::Call(_, a) => uses_var(a),
        RExpr::Bin(_, a, b) => uses_var(a) || uses_var(b),
    }
}

/// Binding strength of a printed expression.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Prec {
    Top,
    Sum,
    Product,
    Unary,
    Atom,
}

fn prec_of(e: &RExpr) -> Prec {
    match e {
        RExpr::Const(q) if q.to_f64().is_some_and(|v| v.is_sign_negative()) => Prec::Unary,
        RExpr::Const(_) | RExpr::Pi | RExpr::X | RExpr::Var(_) | RExpr::Call(..) => Prec::Atom,
        RExpr::Bin(RBin::Pow, ..) => Prec::Atom,
        RExpr::Neg(_) => Prec::Unary,
        RExpr::Bin(RBin::Add | RBin::Sub, ..) => Prec::Sum,
        RExpr::Bin(RBin::Mul | RBin::Div, ..) => Prec::Product,
    }
}

/// `e` as a Rust expression that computes what [`RExpr::eval`] computes,
/// parenthesised for a context that binds `ctx`-tightly.
fn expr(e: &RExpr, ctx: Prec) -> String {
    let text = match e {
        RExpr::Const(q) => literal(q.to_f64().unwrap_or(f64::NAN)),
        RExpr::Pi => "std::f64::consts::PI".into(),
        RExpr::X => "x".into(),
        RExpr::Var(i) => format!("v[{i}]"),
        // `-(…)` for anything that is not an atom (never `--a`).
        RExpr::Neg(a) => format!("-{}", expr(a, Prec::Atom)),
        RExpr::Bin(RBin::Pow, a, b) => {
            format!("real_pow({}, {})", expr(a, Prec::Top), expr(b, Prec::Top))
        }
        RExpr::Bin(op, a, b) => {
            let (p, sym) = match op {
                RBin::Add => (Prec::Sum, "+"),
                RBin::Sub => (Prec::Sum, "-"),
                RBin::Mul => (Prec::Product, "*"),
                _ => (Prec::Product, "/"),
            };
            // Left-associative: the right operand needs parentheses at the
            // same strength; a negative operand always gets them.
            let left = if prec_of(a) == Prec::Unary {
                expr(a, Prec::Atom)
            } else {
                expr(a, p)
            };
            let right = expr(
                b,
                if p == Prec::Sum {
                    Prec::Product
                } else {
                    Prec::Unary
                },
            );
            let right = if prec_of(b) == Prec::Unary && !right.starts_with('(') {
                format!("({right})")
            } else {
                right
            };
            format!("{left} {sym} {right}")
        }
        RExpr::Call(f, a) => format!("RFunc::{}.apply({})", func_name(*f), expr(a, Prec::Top)),
    };
    if prec_of(e) < ctx {
        format!("({text})")
    } else {
        text
    }
}

/// The variant's name, as the generated code spells `RFunc::Name`.
fn func_name(f: RFunc) -> String {
    format!("{f:?}")
}

/// A long expression as `let` bindings of its operands and a final line
/// (each short enough for one line).
fn broken(e: &RExpr) -> String {
    let mut lets = Vec::new();
    let last = bind(e, &mut lets);
    let mut s = String::new();
    for (k, l) in lets.iter().enumerate() {
        let _ = write!(s, "let e{k} = {l};\n    ");
    }
    s.push_str(&last);
    s
}

/// Binds the operands of `e` that do not fit on a line; returns the
/// expression over the bindings.
fn bind(e: &RExpr, lets: &mut Vec<String>) -> String {
    let whole = expr(e, Prec::Top);
    if whole.len() <= 80 {
        return whole;
    }
    let named = |sub: &RExpr, lets: &mut Vec<String>| {
        let t = bind(sub, lets);
        lets.push(t);
        format!("e{}", lets.len() - 1)
    };
    match e {
        RExpr::Neg(a) => format!("-{}", named(a, lets)),
        RExpr::Call(f, a) => format!("RFunc::{}.apply({})", func_name(*f), named(a, lets)),
        RExpr::Bin(op, a, b) => {
            let (l, r) = (named(a, lets), named(b, lets));
            match op {
                RBin::Add => format!("{l} + {r}"),
                RBin::Sub => format!("{l} - {r}"),
                RBin::Mul => format!("{l} * {r}"),
                RBin::Div => format!("{l} / {r}"),
                RBin::Pow => format!("real_pow({l}, {r})"),
            }
        }
        _ => whole,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    fn c(n: i64, d: i64) -> RExpr {
        RExpr::Const(BigRational::new(n.into(), d.into()))
    }

    fn b(op: RBin, a: RExpr, bb: RExpr) -> RExpr {
        RExpr::Bin(op, Box::new(a), Box::new(bb))
    }

    #[test]
    fn precedence_keeps_the_evaluation_order() {
        let x = || RExpr::X;
        assert_eq!(
            expr(&b(RBin::Sub, x(), b(RBin::Sub, x(), c(1, 1))), Prec::Top),
            "x - (x - 1.0)"
        );
        assert_eq!(
            expr(&b(RBin::Sub, b(RBin::Sub, x(), c(1, 1)), x()), Prec::Top),
            "x - 1.0 - x"
        );
        assert_eq!(expr(&b(RBin::Mul, x(), c(-1, 2)), Prec::Top), "x * (-0.5)");
        assert_eq!(
            expr(&b(RBin::Div, x(), b(RBin::Mul, x(), x())), Prec::Top),
            "x / (x * x)"
        );
        assert_eq!(expr(&RExpr::Neg(Box::new(c(-1, 1))), Prec::Top), "-(-1.0)");
        assert_eq!(
            expr(
                &RExpr::Call(RFunc::Acot, Box::new(b(RBin::Add, x(), RExpr::Var(2)))),
                Prec::Top
            ),
            "RFunc::Acot.apply(x + v[2])"
        );
    }

    #[test]
    fn long_expressions_are_bound_operand_by_operand() {
        // sqrt(x + 1/3 + … ) with many terms: too long for one line.
        let mut e = RExpr::X;
        for k in 1..12 {
            e = b(
                RBin::Add,
                e,
                b(RBin::Mul, c(1, 3 + k), RExpr::Var(k as usize)),
            );
        }
        let e = RExpr::Call(RFunc::Sqrt, Box::new(e));
        assert!(expr(&e, Prec::Top).len() > 100);
        let text = broken(&e);
        let lines: Vec<&str> = text.lines().collect();
        assert!(lines.len() > 1, "{text}");
        for l in &lines {
            assert!(l.len() <= 96, "{l}");
        }
        // Every binding is used once, after it is made, and the last line
        // is the expression over them.
        let last = lines.last().copied().unwrap_or_default();
        assert!(
            last.trim_start().starts_with("RFunc::Sqrt.apply(e"),
            "{last}"
        );
        let n = lines.len() - 1;
        for k in 0..n {
            let name = format!("e{k}");
            let uses = text
                .match_indices(&name)
                .filter(|(i, _)| {
                    !text[i + name.len()..].starts_with(|ch: char| ch.is_ascii_digit())
                })
                .count();
            assert_eq!(uses, 2, "{name} in\n{text}");
        }
    }
}
