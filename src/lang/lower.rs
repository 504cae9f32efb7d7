//! Validated AST → span-free [`Program`]: the only place that maps names to
//! indices for the algebra and builds the [`MPoly`] entries of matrices and
//! the ordered [`NcPoly`] operators of equations (products kept in the
//! order written). It trusts the
//! validator (every name resolved, every divisor a nonzero constant, every
//! exponent a small literal) but still never panics: anything unexpected
//! becomes an internal error. It must not check user errors itself.

use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

use super::ast::{BinOp, Expr, ExprKind, File, Ident, IntVar, Sign, Stmt};
use super::error::{ErrorKind, LangError};
use super::scope::{Entry, Scope, Sort};
use super::validate::Validated;
use super::lower_contact::{moving_ends, moving_marker, uses_scalar};
use super::validate_system::{
    contains_functional, contains_operator, is_side_condition, split_term,
};
use crate::algebra::mpoly::MPoly;
use crate::algebra::ncpoly::NcPoly;
use crate::system::contact::EndSite;
use crate::system::expr::{Expr as SExpr, Func};
use crate::system::{
    Directive, Equation, FunctionalTerm, Limit, MatrixDef, OperatorDef, Output, Param, Program,
    SideCondition, Term,
};

fn internal(e: &Expr) -> LangError {
    LangError::new(
        ErrorKind::WrongSort,
        "internal error: an expression passed validation but cannot be lowered",
        e.span,
        "here",
    )
}

fn internal_name(id: &Ident) -> LangError {
    LangError::new(
        ErrorKind::WrongSort,
        format!(
            "internal error: `{}` passed validation but cannot be resolved",
            id.name
        ),
        id.span,
        "here",
    )
}

/// Builds the program of a validated file.
pub fn lower(file: &File, v: &Validated) -> Result<Program, LangError> {
    let scope = &v.scope;
    let n = scope.symbols.len();
    let mut program = Program {
        symbols: scope.symbols.clone(),
        principal: None,
        matrices: Vec::new(),
        directives: Vec::new(),
        params: scope
            .params
            .iter()
            .enumerate()
            .filter(|(i, _)| !scope.is_real_param(*i))
            .map(|(_, (name, v))| Param {
                name: name.clone(),
                value: v.clone().unwrap_or_else(BigRational::zero),
            })
            .collect(),
        unknowns: scope.unknowns.clone(),
        operators: Vec::new(),
        equations: Vec::new(),
        outputs: Vec::new(),
        side_conditions: Vec::new(),
        contact: super::lower_contact::lower_contact(file, scope)?,
    };
    let unknown_index = |id: &Ident| match scope.get(&id.name) {
        Some(Entry {
            sort: Sort::Unknown(i),
            ..
        }) => Ok(i),
        _ => Err(internal_name(id)),
    };
    let matrix_index = |id: &Ident| match scope.get(&id.name) {
        Some(Entry {
            sort: Sort::Matrix(i),
            ..
        }) => Ok(i),
        _ => Err(internal_name(id)),
    };
    for st in &file.statements {
        match &st.kind {
            Stmt::Principal(id) => match scope.get(&id.name) {
                Some(Entry {
                    sort: Sort::Symbol(i),
                    ..
                }) => program.principal = Some(i),
                _ => return Err(internal_name(id)),
            },
            Stmt::Matrix { name, rows, .. } => {
                let cols = rows.first().map_or(0, |r| r.entries.len());
                let mut entries = Vec::with_capacity(rows.len() * cols);
                for row in rows {
                    for e in &row.entries {
                        entries.push(poly(e, scope, n)?);
                    }
                }
                program.matrices.push(MatrixDef {
                    name: name.name.clone(),
                    rows: rows.len(),
                    cols,
                    entries,
                });
            }
            Stmt::Smith(id) => program.directives.push(Directive::Smith {
                matrix: matrix_index(id)?,
            }),
            Stmt::CheckSmith { a, u, d, v } => program.directives.push(Directive::CheckSmith {
                matrix: matrix_index(a)?,
                u: matrix_index(u)?,
                d: matrix_index(d)?,
                v: matrix_index(v)?,
            }),
            Stmt::Solve(id) => program.directives.push(Directive::Solve {
                unknown: unknown_index(id)?,
            }),
            Stmt::Operator { name, body } => {
                let symbol = match scope.get(&name.name) {
                    Some(Entry {
                        sort: Sort::Symbol(i),
                        ..
                    }) => i,
                    _ => return Err(internal_name(name)),
                };
                let mut terms: Vec<Term> = operator_terms(body, scope)?
                    .into_iter()
                    .map(|(factor, atom)| atom.into_term(factor))
                    .collect();
                moving_ends(
                    body,
                    scope,
                    &mut program.contact,
                    operator_limits(symbol, &mut terms),
                )?;
                program.operators.push(OperatorDef { symbol, terms });
            }
            Stmt::Equation { lhs, rhs, .. } => {
                let mut row = vec![NcPoly::zero(); scope.unknowns.len()];
                for term in lhs {
                    let (product, unknown) = split_term(term);
                    let u = unknown.ok_or_else(|| internal(&term.product))?;
                    let j = unknown_index(u)?;
                    let mut c = match product {
                        Some(p) => ncpoly(p, scope, n)?,
                        None => NcPoly::constant(BigRational::one()),
                    };
                    if term.sign == Sign::Minus {
                        c = c.scale(&-BigRational::one());
                    }
                    let slot = row.get_mut(j).ok_or_else(|| internal_name(u))?;
                    *slot = &*slot + &c;
                }
                // A right side with a scalar is the split solver's
                // (`Contact::rhs`, printed from there); the operator system
                // holds 0 there.
                let j = program.equations.len();
                let (rhs, written) = match program.contact.rhs.get(j) {
                    Some(Some(e)) => (
                        SExpr::Const(BigRational::zero()),
                        Some(e.to_text(&program.contact.slots())),
                    ),
                    _ => (fexpr(rhs, scope)?, None),
                };
                program.equations.push(Equation {
                    lhs: row,
                    rhs,
                    written,
                });
            }
            Stmt::Output { name, body } => {
                let mut terms = output_terms(body, scope)?;
                let output = program.outputs.len();
                moving_ends(
                    body,
                    scope,
                    &mut program.contact,
                    functional_limits(|term| EndSite::Output { output, term }, &mut terms),
                )?;
                finite_functional(&terms, &format!("output {}", name.name), body)?;
                program.outputs.push(Output {
                    name: name.name.clone(),
                    terms,
                })
            }
            Stmt::Condition { lhs, rhs } if is_side_condition(lhs, scope) => {
                let mut terms = output_terms(lhs, scope)?;
                let condition = program.side_conditions.len();
                moving_ends(
                    lhs,
                    scope,
                    &mut program.contact,
                    functional_limits(|term| EndSite::Condition { condition, term }, &mut terms),
                )?;
                finite_functional(&terms, "this condition", lhs)?;
                let value = fexpr(rhs, scope)?;
                finite_constant(&value, "the condition's value", rhs)?;
                program.side_conditions.push(SideCondition { terms, value })
            }
            Stmt::Var(_)
            | Stmt::Param { .. }
            | Stmt::Unknown(..)
            | Stmt::Relation { .. }
            | Stmt::Inequality { .. }
            | Stmt::Scalar { .. }
            | Stmt::Singular { .. }
            | Stmt::Condition { .. } => {}
        }
    }
    program.operators.sort_by_key(|o| o.symbol);
    Ok(program)
}

/// `a * b`, folding rational constants and factors of one.
fn smul(a: SExpr, b: SExpr) -> SExpr {
    match (a, b) {
        (SExpr::Const(x), SExpr::Const(y)) => SExpr::Const(x * y),
        (SExpr::Const(x), b) if x.is_one() => b,
        (a, SExpr::Const(y)) if y.is_one() => a,
        (SExpr::Const(x), b) if (-&x).is_one() => sneg(b),
        (a, SExpr::Const(y)) if (-&y).is_one() => sneg(a),
        (a, b) => SExpr::Mul(Box::new(a), Box::new(b)),
    }
}

/// `a / b`, folding rational constants and divisors of one.
fn sdiv(a: SExpr, b: SExpr) -> SExpr {
    match (a, b) {
        (SExpr::Const(x), SExpr::Const(y)) if !y.is_zero() => SExpr::Const(x / y),
        (a, SExpr::Const(y)) if y.is_one() => a,
        (a, b) => SExpr::Div(Box::new(a), Box::new(b)),
    }
}

/// `-a`, folding rational constants.
fn sneg(a: SExpr) -> SExpr {
    match a {
        SExpr::Const(x) => SExpr::Const(-x),
        a => SExpr::Neg(Box::new(a)),
    }
}

/// A real expression tree, with parameters substituted and rational
/// subexpressions folded.
pub(crate) fn fexpr(e: &Expr, scope: &Scope) -> Result<SExpr, LangError> {
    if scope.is_rational_const(e) {
        return constant(e, scope)
            .map(SExpr::Const)
            .ok_or_else(|| internal(e));
    }
    let b = |x: &Expr| fexpr(x, scope).map(Box::new);
    Ok(match &e.kind {
        ExprKind::Name(id) if id.name == "x" => SExpr::X,
        ExprKind::Name(id) if id.name == "t" => SExpr::T,
        // A real parameter stands for its definition.
        ExprKind::Name(id) => match scope.get(&id.name) {
            Some(Entry {
                sort: Sort::Param(i),
                ..
            }) => fexpr(scope.real_def(i).ok_or_else(|| internal(e))?, scope)?,
            _ => return Err(internal(e)),
        },
        ExprKind::Pi => SExpr::Pi,
        ExprKind::Neg(a) => SExpr::Neg(b(a)?),
        ExprKind::Binary(op, x, y) => {
            let (x, y) = (b(x)?, b(y)?);
            match op {
                BinOp::Add => SExpr::Add(x, y),
                BinOp::Sub => SExpr::Sub(x, y),
                BinOp::Mul => SExpr::Mul(x, y),
                BinOp::Div => SExpr::Div(x, y),
                BinOp::Pow => SExpr::Pow(x, y),
            }
        }
        ExprKind::Call(f, a) => {
            SExpr::Call(Func::from_name(&f.name).ok_or_else(|| internal(e))?, b(a)?)
        }
        _ => return Err(internal(e)),
    })
}

/// One operator piece before its factor is folded in.
enum Atom {
    Identity,
    Integral {
        lower: Limit,
        upper: Limit,
        kernel: SExpr,
        pv: bool,
    },
}

impl Atom {
    fn into_term(self, factor: SExpr) -> Term {
        match self {
            Atom::Identity => match factor {
                SExpr::Const(c) if c.is_one() => Term::Identity,
                SExpr::Const(c) => Term::Scalar(c),
                f => Term::Multiply(f),
            },
            Atom::Integral {
                lower,
                upper,
                kernel,
                pv,
            } => Term::Integral {
                lower,
                upper,
                kernel: smul(factor, kernel),
                pv,
            },
        }
    }
}

fn limit(e: &Expr, scope: &Scope) -> Result<Limit, LangError> {
    match &e.kind {
        ExprKind::Name(id) if id.name == "x" => Ok(Limit::X),
        _ => output_limit(e, scope)
            .map(Limit::Const)
            .ok_or_else(|| internal(e)),
    }
}

/// A constant integration limit, or the marker of one that uses a scalar
/// (`lower_contact::moving_ends` replaces it).
fn output_limit(e: &Expr, scope: &Scope) -> Option<BigRational> {
    if uses_scalar(e, scope) {
        Some(moving_marker(e))
    } else {
        constant(e, scope)
    }
}

/// The constant limits of `terms` (operator terms), with their sites.
fn operator_limits(
    symbol: usize,
    terms: &mut [Term],
) -> impl Iterator<Item = (EndSite, &mut BigRational, bool)> {
    terms.iter_mut().enumerate().flat_map(move |(term, t)| {
        let mut v = Vec::new();
        if let Term::Integral { lower, upper, .. } = t {
            for (l, up) in [(lower, false), (upper, true)] {
                if let Limit::Const(q) = l {
                    v.push((EndSite::Operator { symbol, term }, q, up));
                }
            }
        }
        v
    })
}

/// The limits of `terms` (a functional's), with their sites.
fn functional_limits(
    site: impl Fn(usize) -> EndSite,
    terms: &mut [FunctionalTerm],
) -> impl Iterator<Item = (EndSite, &mut BigRational, bool)> {
    terms.iter_mut().enumerate().flat_map(move |(i, t)| {
        let mut v = Vec::new();
        match t {
            FunctionalTerm::Integral { lower, upper, .. } => {
                v.push((site(i), lower, false));
                v.push((site(i), upper, true));
            }
            // A point value's position moves as an upper limit does.
            FunctionalTerm::Point { at, .. } => v.push((site(i), at, true)),
            FunctionalTerm::Constant(_) => {}
        }
        v
    })
}

/// An operator body as a list of (factor, piece).
fn operator_terms(e: &Expr, scope: &Scope) -> Result<Vec<(SExpr, Atom)>, LangError> {
    let one = || SExpr::Const(BigRational::one());
    Ok(match &e.kind {
        ExprKind::Identity => vec![(one(), Atom::Identity)],
        ExprKind::Integral {
            lower,
            upper,
            integrand,
            pv,
            ..
        } => vec![(
            one(),
            Atom::Integral {
                pv: *pv,
                lower: limit(lower, scope)?,
                upper: limit(upper, scope)?,
                kernel: match integrand {
                    Some(k) => fexpr(k, scope)?,
                    None => one(),
                },
            },
        )],
        ExprKind::Neg(a) => operator_terms(a, scope)?
            .into_iter()
            .map(|(f, t)| (sneg(f), t))
            .collect(),
        ExprKind::Binary(BinOp::Add, a, b) => {
            let mut v = operator_terms(a, scope)?;
            v.extend(operator_terms(b, scope)?);
            v
        }
        ExprKind::Binary(BinOp::Sub, a, b) => {
            let mut v = operator_terms(a, scope)?;
            v.extend(
                operator_terms(b, scope)?
                    .into_iter()
                    .map(|(f, t)| (sneg(f), t)),
            );
            v
        }
        ExprKind::Binary(BinOp::Mul, a, b) => {
            if contains_operator(a) {
                let g = fexpr(b, scope)?;
                operator_terms(a, scope)?
                    .into_iter()
                    .map(|(f, t)| (smul(f, g.clone()), t))
                    .collect()
            } else {
                let g = fexpr(a, scope)?;
                operator_terms(b, scope)?
                    .into_iter()
                    .map(|(f, t)| (smul(g.clone(), f), t))
                    .collect()
            }
        }
        ExprKind::Binary(BinOp::Div, a, b) => {
            let g = fexpr(b, scope)?;
            operator_terms(a, scope)?
                .into_iter()
                .map(|(f, t)| (sdiv(f, g.clone()), t))
                .collect()
        }
        _ => return Err(internal(e)),
    })
}

/// Replaces `t` by `x` (output weights are stored in `x`).
fn t_to_x(e: SExpr) -> SExpr {
    let b = |x: Box<SExpr>| Box::new(t_to_x(*x));
    match e {
        SExpr::T => SExpr::X,
        SExpr::Neg(a) => SExpr::Neg(b(a)),
        SExpr::Add(x, y) => SExpr::Add(b(x), b(y)),
        SExpr::Sub(x, y) => SExpr::Sub(b(x), b(y)),
        SExpr::Mul(x, y) => SExpr::Mul(b(x), b(y)),
        SExpr::Div(x, y) => SExpr::Div(b(x), b(y)),
        SExpr::Pow(x, y) => SExpr::Pow(b(x), b(y)),
        SExpr::Call(f, a) => SExpr::Call(f, b(a)),
        other => other,
    }
}

fn negate_term(t: FunctionalTerm) -> FunctionalTerm {
    scale_term(t, sneg)
}

fn scale_term(t: FunctionalTerm, f: impl Fn(SExpr) -> SExpr) -> FunctionalTerm {
    match t {
        FunctionalTerm::Constant(c) => FunctionalTerm::Constant(f(c)),
        FunctionalTerm::Integral {
            coeff,
            lower,
            upper,
            weight,
            unknown,
        } => FunctionalTerm::Integral {
            coeff: f(coeff),
            lower,
            upper,
            weight,
            unknown,
        },
        FunctionalTerm::Point { coeff, at, unknown } => FunctionalTerm::Point {
            coeff: f(coeff),
            at,
            unknown,
        },
    }
}

/// Refuses a functional (an output or a side condition's left side)
/// whose constants or weights are not finite doubles: `10^400`,
/// `exp(1000)` or `pi^1000` would print NaN or infinity, so they are
/// refused at `at` instead of computed.
fn finite_functional(terms: &[FunctionalTerm], what: &str, at: &Expr) -> Result<(), LangError> {
    for t in terms {
        match t {
            FunctionalTerm::Constant(c) | FunctionalTerm::Point { coeff: c, .. } => {
                finite_constant(c, &format!("the constant factor {c} of {what}"), at)?
            }
            FunctionalTerm::Integral {
                coeff,
                lower,
                upper,
                weight,
                ..
            } => {
                finite_constant(coeff, &format!("the constant factor {coeff} of {what}"), at)?;
                let (a, b) = (
                    lower.to_f64().unwrap_or(f64::NAN),
                    upper.to_f64().unwrap_or(f64::NAN),
                );
                // Interior points only: an integrable end singularity of the
                // weight is allowed.
                for f in [0.013, 0.25, 0.5, 0.75, 0.987] {
                    let x = a + f * (b - a);
                    let v = weight.eval(x, x);
                    if !v.is_finite() {
                        return Err(not_finite(
                            format!(
                                "the weight {weight} of {what} is {v} at x = {x} (as a double): the output cannot be computed"
                            ),
                            at,
                        ));
                    }
                }
            }
        }
    }
    Ok(())
}

/// Refuses a constant that is not a finite double, or a nonzero exact
/// constant that rounds to zero.
fn finite_constant(c: &SExpr, what: &str, at: &Expr) -> Result<(), LangError> {
    let v = c.eval(0.0, 0.0);
    let underflow = matches!(c, SExpr::Const(q) if !q.is_zero()) && v == 0.0;
    if v.is_finite() && !underflow {
        return Ok(());
    }
    let why = if underflow {
        "is below the smallest double and would be taken as 0".to_string()
    } else {
        format!("evaluates to {v} in double precision (some part of it overflows 1.8e308)")
    };
    Err(not_finite(
        format!(
            "{what} {why}: it is refused rather than printed as NaN; rescale it so every part stays within the range of doubles"
        ),
        at,
    ))
}

fn not_finite(message: String, at: &Expr) -> LangError {
    LangError::new(
        ErrorKind::Unsupported,
        message,
        at.span,
        "not a finite number",
    )
}

/// An output body as a list of terms (every `+`, `-` at the top splits).
fn output_terms(e: &Expr, scope: &Scope) -> Result<Vec<FunctionalTerm>, LangError> {
    Ok(match &e.kind {
        ExprKind::Integral {
            lower,
            upper,
            integrand,
            var,
            ..
        } => {
            let lo = output_limit(lower, scope).ok_or_else(|| internal(lower))?;
            let hi = output_limit(upper, scope).ok_or_else(|| internal(upper))?;
            let integrand = integrand.as_ref().ok_or_else(|| internal(e))?;
            weighted(integrand, scope)?
                .into_iter()
                .map(|(w, u)| FunctionalTerm::Integral {
                    coeff: SExpr::Const(BigRational::one()),
                    lower: lo.clone(),
                    upper: hi.clone(),
                    weight: if *var == IntVar::T { t_to_x(w) } else { w },
                    unknown: u,
                })
                .collect()
        }
        ExprKind::Call(f, arg)
            if matches!(
                scope.get(&f.name),
                Some(Entry {
                    sort: Sort::Unknown(_),
                    ..
                })
            ) =>
        {
            let Some(Entry {
                sort: Sort::Unknown(u),
                ..
            }) = scope.get(&f.name)
            else {
                return Err(internal(e));
            };
            vec![FunctionalTerm::Point {
                coeff: SExpr::Const(BigRational::one()),
                at: output_limit(arg, scope).ok_or_else(|| internal(arg))?,
                unknown: u,
            }]
        }
        ExprKind::Neg(a) => output_terms(a, scope)?
            .into_iter()
            .map(negate_term)
            .collect(),
        ExprKind::Binary(BinOp::Add, a, b) => {
            let mut v = output_terms(a, scope)?;
            v.extend(output_terms(b, scope)?);
            v
        }
        ExprKind::Binary(BinOp::Sub, a, b) => {
            let mut v = output_terms(a, scope)?;
            v.extend(output_terms(b, scope)?.into_iter().map(negate_term));
            v
        }
        ExprKind::Binary(BinOp::Mul | BinOp::Div, _, _) if !contains_functional(e, scope) => {
            vec![FunctionalTerm::Constant(fexpr(e, scope)?)]
        }
        ExprKind::Binary(BinOp::Mul, a, b) => {
            if contains_functional(a, scope) {
                let g = fexpr(b, scope)?;
                output_terms(a, scope)?
                    .into_iter()
                    .map(|t| scale_term(t, |c| smul(c, g.clone())))
                    .collect()
            } else {
                let g = fexpr(a, scope)?;
                output_terms(b, scope)?
                    .into_iter()
                    .map(|t| scale_term(t, |c| smul(g.clone(), c)))
                    .collect()
            }
        }
        ExprKind::Binary(BinOp::Div, a, b) => {
            let g = fexpr(b, scope)?;
            output_terms(a, scope)?
                .into_iter()
                .map(|t| scale_term(t, |c| sdiv(c, g.clone())))
                .collect()
        }
        _ if !contains_functional(e, scope) => vec![FunctionalTerm::Constant(fexpr(e, scope)?)],
        _ => return Err(internal(e)),
    })
}

/// An output integrand as a sum of (weight, unknown index).
fn weighted(e: &Expr, scope: &Scope) -> Result<Vec<(SExpr, usize)>, LangError> {
    let unknown = |id: &Ident| match scope.get(&id.name) {
        Some(Entry {
            sort: Sort::Unknown(i),
            ..
        }) => Some(i),
        _ => None,
    };
    let has_unknown = |x: &Expr| mentions_unknown(x, scope);
    Ok(match &e.kind {
        ExprKind::Call(f, _) => match unknown(f) {
            Some(i) => vec![(SExpr::Const(BigRational::one()), i)],
            None => return Err(internal(e)),
        },
        ExprKind::Neg(a) => weighted(a, scope)?
            .into_iter()
            .map(|(w, u)| (sneg(w), u))
            .collect(),
        ExprKind::Binary(BinOp::Add, a, b) => {
            let mut v = weighted(a, scope)?;
            v.extend(weighted(b, scope)?);
            v
        }
        ExprKind::Binary(BinOp::Sub, a, b) => {
            let mut v = weighted(a, scope)?;
            v.extend(weighted(b, scope)?.into_iter().map(|(w, u)| (sneg(w), u)));
            v
        }
        ExprKind::Binary(BinOp::Mul, a, b) => {
            if has_unknown(a) {
                let g = fexpr(b, scope)?;
                weighted(a, scope)?
                    .into_iter()
                    .map(|(w, u)| (smul(w, g.clone()), u))
                    .collect()
            } else {
                let g = fexpr(a, scope)?;
                weighted(b, scope)?
                    .into_iter()
                    .map(|(w, u)| (smul(g.clone(), w), u))
                    .collect()
            }
        }
        ExprKind::Binary(BinOp::Div, a, b) => {
            let g = fexpr(b, scope)?;
            weighted(a, scope)?
                .into_iter()
                .map(|(w, u)| (sdiv(w, g.clone()), u))
                .collect()
        }
        _ => return Err(internal(e)),
    })
}

fn mentions_unknown(e: &Expr, scope: &Scope) -> bool {
    let is_unknown = |name: &str| scope.is_unknown(name);
    match &e.kind {
        ExprKind::Name(id) => is_unknown(&id.name),
        ExprKind::Call(f, a) => is_unknown(&f.name) || mentions_unknown(a, scope),
        ExprKind::Neg(a) => mentions_unknown(a, scope),
        ExprKind::Binary(_, a, b) => mentions_unknown(a, scope) || mentions_unknown(b, scope),
        _ => false,
    }
}

/// The polynomial an expression denotes, over the `n` symbols of `scope`.
pub(crate) fn poly(e: &Expr, scope: &Scope, n: usize) -> Result<MPoly, LangError> {
    Ok(match &e.kind {
        ExprKind::Number(q) => MPoly::constant(q.clone(), n),
        ExprKind::Name(id) => match scope.get(&id.name) {
            Some(Entry {
                sort: Sort::Symbol(i),
                ..
            }) if i < n => MPoly::var(i, n),
            Some(Entry {
                sort: Sort::Param(i),
                ..
            }) => MPoly::constant(scope.param_value(i).cloned().ok_or_else(|| internal(e))?, n),
            _ => return Err(internal(e)),
        },
        ExprKind::Neg(a) => -poly(a, scope, n)?,
        ExprKind::Binary(op, a, b) => match op {
            BinOp::Add => poly(a, scope, n)? + poly(b, scope, n)?,
            BinOp::Sub => poly(a, scope, n)? - poly(b, scope, n)?,
            BinOp::Mul => poly(a, scope, n)? * poly(b, scope, n)?,
            BinOp::Div => {
                let c = constant(b, scope).ok_or_else(|| internal(b))?;
                if c.is_zero() {
                    return Err(internal(b));
                }
                poly(a, scope, n)?.scale(&c.recip())
            }
            BinOp::Pow => {
                let k = match &b.kind {
                    ExprKind::Number(q) if q.is_integer() => q.to_integer().to_u32(),
                    _ => None,
                }
                .ok_or_else(|| internal(b))?;
                poly(a, scope, n)?.pow(k)
            }
        },
        _ => return Err(internal(e)),
    })
}

/// The ordered operator an expression denotes: products keep the order
/// written (`k2*k1` is the word `k2 k1`), powers repeat the factor.
pub(crate) fn ncpoly(e: &Expr, scope: &Scope, n: usize) -> Result<NcPoly, LangError> {
    Ok(match &e.kind {
        ExprKind::Number(q) => NcPoly::constant(q.clone()),
        ExprKind::Name(id) => match scope.get(&id.name) {
            Some(Entry {
                sort: Sort::Symbol(i),
                ..
            }) if i < n => NcPoly::var(i),
            Some(Entry {
                sort: Sort::Param(i),
                ..
            }) => NcPoly::constant(scope.param_value(i).cloned().ok_or_else(|| internal(e))?),
            _ => return Err(internal(e)),
        },
        ExprKind::Neg(a) => ncpoly(a, scope, n)?.scale(&-BigRational::one()),
        ExprKind::Binary(op, a, b) => match op {
            BinOp::Add => &ncpoly(a, scope, n)? + &ncpoly(b, scope, n)?,
            BinOp::Sub => &ncpoly(a, scope, n)? - &ncpoly(b, scope, n)?,
            BinOp::Mul => &ncpoly(a, scope, n)? * &ncpoly(b, scope, n)?,
            BinOp::Div => {
                let c = constant(b, scope).ok_or_else(|| internal(b))?;
                if c.is_zero() {
                    return Err(internal(b));
                }
                ncpoly(a, scope, n)?.scale(&c.recip())
            }
            BinOp::Pow => {
                let k = match &b.kind {
                    ExprKind::Number(q) if q.is_integer() => q.to_integer().to_u32(),
                    _ => None,
                }
                .ok_or_else(|| internal(b))?;
                ncpoly(a, scope, n)?.pow(k)
            }
        },
        _ => return Err(internal(e)),
    })
}

/// The exact value of a validated constant expression.
pub(crate) fn constant(e: &Expr, scope: &Scope) -> Option<BigRational> {
    match &e.kind {
        ExprKind::Number(q) => Some(q.clone()),
        ExprKind::Name(id) => match scope.get(&id.name) {
            Some(Entry {
                sort: Sort::Param(i),
                ..
            }) => scope.param_value(i).cloned(),
            _ => None,
        },
        ExprKind::Neg(a) => constant(a, scope).map(|q| -q),
        ExprKind::Binary(op, a, b) => {
            let x = constant(a, scope)?;
            match op {
                BinOp::Add => Some(x + constant(b, scope)?),
                BinOp::Sub => Some(x - constant(b, scope)?),
                BinOp::Mul => Some(x * constant(b, scope)?),
                BinOp::Div => {
                    let y = constant(b, scope)?;
                    (!y.is_zero()).then(|| x / y)
                }
                BinOp::Pow => {
                    // Any constant integer exponent folds, however it is
                    // written (`2^(-24)` and `2^(-12*2)` lower alike, so
                    // the printed program reads back as the same program).
                    let e = constant(b, scope)?;
                    if !e.is_integer() {
                        return None;
                    }
                    let neg = e.is_negative();
                    let k = e.abs().to_integer().to_u32()?;
                    if k > super::validate::MAX_EXPONENT {
                        return None;
                    }
                    let mut acc = BigRational::one();
                    for _ in 0..k {
                        acc *= &x;
                    }
                    if neg {
                        if acc.is_zero() {
                            return None;
                        }
                        acc = acc.recip();
                    }
                    Some(acc)
                }
            }
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigInt;

    fn c(n: i64) -> SExpr {
        SExpr::Const(BigRational::from_integer(BigInt::from(n)))
    }

    #[test]
    fn folding_helpers() {
        assert_eq!(smul(c(2), c(3)), c(6));
        assert_eq!(smul(c(1), SExpr::X), SExpr::X);
        assert_eq!(smul(SExpr::X, c(1)), SExpr::X);
        assert_eq!(smul(c(-1), SExpr::X), SExpr::Neg(Box::new(SExpr::X)));
        assert_eq!(
            sdiv(c(3), c(6)),
            SExpr::Const(BigRational::new(1.into(), 2.into()))
        );
        assert_eq!(sdiv(SExpr::X, c(1)), SExpr::X);
        assert_eq!(sneg(c(4)), c(-4));
        // Division by zero is never folded (validation rejects it earlier).
        assert_eq!(sdiv(c(1), c(0)), SExpr::Div(Box::new(c(1)), Box::new(c(0))));
    }

    #[test]
    fn t_becomes_x_in_output_weights() {
        let w = SExpr::Mul(
            Box::new(SExpr::T),
            Box::new(SExpr::Call(Func::Sqrt, Box::new(SExpr::T))),
        );
        let x = t_to_x(w);
        assert!(!x.uses_t() && x.uses_x());
    }
}
