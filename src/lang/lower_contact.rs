//! Validated split-domain statements → [`Contact`]: intervals, relations,
//! scalars, real parameters, singular declarations and conditions, with
//! names mapped to unknown indices and value slots. It trusts the
//! validator and never panics (anything unexpected is an internal error).
//! The one user error it checks is the one that needs the lowered points:
//! a second singular declaration of one unknown at one point that the
//! solver cannot combine (two exact terms at one side, or two weights or
//! logarithms), refused at the second one.
use num_traits::ToPrimitive;

use super::ast::{BinOp, Expr, ExprKind, File, Ident, Interval, Stmt};
use super::error::{ErrorKind, LangError};
use super::lower::constant;
use super::scope::{Entry, Scope, Sort};
use super::validate_contact::{
    coefficient_terms, inequality_sides, is_inf, linear_side, log_form, relation_form, weight_form,
};
use crate::system::contact::{
    Condition, Contact, EndSite, Inequality, Interval as CInterval, LinTerm, MovingEnd, RBin,
    RExpr, RFunc, RealParam, Relation, Scalar, Singular, SingularKind,
};

fn internal(span: super::ast::Span, what: &str) -> LangError {
    LangError::new(
        ErrorKind::WrongSort,
        format!("internal error: {what} passed validation but cannot be lowered"),
        span,
        "here",
    )
}

/// Slot of each real parameter (`None` for rational ones).
fn real_slots(scope: &Scope) -> Vec<Option<usize>> {
    let base = scope.scalars.len();
    let mut k = 0;
    (0..scope.params.len())
        .map(|i| {
            scope.is_real_param(i).then(|| {
                k += 1;
                base + k - 1
            })
        })
        .collect()
}

/// The [`RExpr`] of a validated real expression.
fn rexpr(e: &Expr, scope: &Scope, slots: &[Option<usize>]) -> Result<RExpr, LangError> {
    // Exact subexpressions are folded to one rational.
    if !matches!(e.kind, ExprKind::Number(_))
        && let Some(q) = constant(e, scope)
    {
        return Ok(RExpr::Const(q));
    }
    Ok(match &e.kind {
        ExprKind::Number(q) => RExpr::Const(q.clone()),
        ExprKind::Pi => RExpr::Pi,
        ExprKind::Name(id) if id.name == "x" => RExpr::X,
        ExprKind::Name(id) => match scope.get(&id.name) {
            Some(Entry {
                sort: Sort::Param(i),
                ..
            }) => match slots.get(i).copied().flatten() {
                Some(s) => RExpr::Var(s),
                None => RExpr::Const(
                    scope
                        .param_value(i)
                        .cloned()
                        .ok_or_else(|| internal(e.span, "a parameter"))?,
                ),
            },
            Some(Entry {
                sort: Sort::Scalar(i),
                ..
            }) => RExpr::Var(i),
            _ => return Err(internal(e.span, "a name")),
        },
        ExprKind::Neg(a) => RExpr::Neg(Box::new(rexpr(a, scope, slots)?)),
        ExprKind::Binary(op, a, b) => {
            let (a, b) = (rexpr(a, scope, slots)?, rexpr(b, scope, slots)?);
            match (op, &a) {
                // `1*e` (left by a coefficient `B*e` with B = 1) is `e`.
                (BinOp::Mul, RExpr::Const(q)) if num_traits::One::is_one(q) => b,
                _ => RExpr::Bin(
                    match op {
                        BinOp::Add => RBin::Add,
                        BinOp::Sub => RBin::Sub,
                        BinOp::Mul => RBin::Mul,
                        BinOp::Div => RBin::Div,
                        BinOp::Pow => RBin::Pow,
                    },
                    Box::new(a),
                    Box::new(b),
                ),
            }
        }
        ExprKind::Call(f, a) => RExpr::Call(
            RFunc::from_name(&f.name).ok_or_else(|| internal(f.span, "a function"))?,
            Box::new(rexpr(a, scope, slots)?),
        ),
        _ => return Err(internal(e.span, "an expression")),
    })
}

fn interval(i: &Interval, scope: &Scope, slots: &[Option<usize>]) -> Result<CInterval, LangError> {
    Ok(CInterval {
        lo: rexpr(&i.lo, scope, slots)?,
        hi: rexpr(&i.hi, scope, slots)?,
        lo_closed: i.lo_closed,
        hi_closed: i.hi_closed,
    })
}

fn unknown(id: &Ident, scope: &Scope) -> Result<usize, LangError> {
    match scope.get(&id.name) {
        Some(Entry {
            sort: Sort::Unknown(i),
            ..
        }) => Ok(i),
        _ => Err(internal(id.span, "an unknown")),
    }
}

fn end(e: &Expr, scope: &Scope, infinite: f64) -> Result<f64, LangError> {
    if is_inf(e) {
        return Ok(infinite);
    }
    constant(e, scope)
        .and_then(|q| q.to_f64())
        .ok_or_else(|| internal(e.span, "a range end"))
}

/// Whether `e` uses an unknown scalar, directly or through a real
/// parameter (such a right side is lowered to [`Contact::rhs`]).
pub(crate) fn uses_scalar(e: &Expr, scope: &Scope) -> bool {
    match &e.kind {
        ExprKind::Name(id) => match scope.get(&id.name) {
            Some(Entry {
                sort: Sort::Scalar(_),
                ..
            }) => true,
            Some(Entry {
                sort: Sort::Param(i),
                ..
            }) => scope.is_real_param(i) && scope.real_def(i).is_none(),
            _ => false,
        },
        ExprKind::Neg(a) | ExprKind::Call(_, a) => uses_scalar(a, scope),
        ExprKind::Binary(_, a, b) => uses_scalar(a, scope) || uses_scalar(b, scope),
        _ => false,
    }
}

/// Builds the split-domain part of a validated file.
pub fn lower_contact(file: &File, scope: &Scope) -> Result<Contact, LangError> {
    let slots = real_slots(scope);
    let mut c = Contact {
        coefficients: scope.coefficients.clone(),
        unknown_domains: vec![None; scope.unknowns.len()],
        ..Contact::default()
    };
    // The weights and logarithms declared so far: unknown, point, the
    // declaration's body and what it is.
    let mut behaviours: Vec<(usize, RExpr, super::ast::Span, &str)> = Vec::new();
    for st in &file.statements {
        match &st.kind {
            Stmt::Param { name, value } => {
                if let Some(Entry {
                    sort: Sort::Param(i),
                    span,
                }) = scope.get(&name.name)
                    && span == name.span
                    && scope.is_real_param(i)
                {
                    c.reals.push(RealParam {
                        name: name.name.clone(),
                        value: rexpr(value, scope, &slots)?,
                    });
                }
            }
            Stmt::Scalar {
                name,
                range,
                estimate,
            } => {
                c.scalars.push(Scalar {
                    name: name.name.clone(),
                    range: (
                        end(&range.lo, scope, f64::NEG_INFINITY)?,
                        end(&range.hi, scope, f64::INFINITY)?,
                    ),
                });
                c.estimates.push(match estimate {
                    Some(e) => Some(rexpr(e, scope, &slots)?),
                    None => None,
                });
            }
            Stmt::Unknown(names, Some(d)) => {
                let d = interval(d, scope, &slots)?;
                for id in names {
                    let i = unknown(id, scope)?;
                    if let Some(slot) = c.unknown_domains.get_mut(i) {
                        *slot = Some(d.clone());
                    }
                }
            }
            Stmt::Equation { domain, rhs, .. } => {
                c.equation_domains.push(match domain {
                    Some(d) => Some(interval(d, scope, &slots)?),
                    None => None,
                });
                c.rhs.push(if uses_scalar(rhs, scope) {
                    Some(rexpr(rhs, scope, &slots)?)
                } else {
                    None
                });
            }
            Stmt::Relation {
                unknown: u,
                value,
                domain,
            } => {
                let is_unknown = |n: &str| scope.is_unknown(n);
                let (coeff, other) = match relation_form(value, is_unknown) {
                    Some((factor, other)) => (
                        match factor {
                            Some(k) => rexpr(k, scope, &slots)?,
                            None => RExpr::Const(num_traits::One::one()),
                        },
                        unknown(other, scope)?,
                    ),
                    // `u = 0`: stored as `u = 0·u`.
                    None => (RExpr::Const(num_traits::Zero::zero()), unknown(u, scope)?),
                };
                c.relations.push(Relation {
                    unknown: unknown(u, scope)?,
                    coeff,
                    other,
                    domain: interval(domain, scope, &slots)?,
                });
            }
            Stmt::Inequality {
                lhs,
                ge,
                rhs,
                domain,
            } => {
                let is_unknown = |n: &str| scope.is_unknown(n);
                let (abs, small, large) = inequality_sides(lhs, *ge, rhs);
                let mut sides = Vec::new();
                for side in [small, large] {
                    let mut terms = Vec::new();
                    linear_side(side, &is_unknown, false, &mut terms)
                        .ok_or_else(|| internal(side.span, "an inequality"))?;
                    let mut lin = Vec::new();
                    for (neg, k, u) in terms {
                        let mut coeff = match k {
                            Some(k) => rexpr(k, scope, &slots)?,
                            None => RExpr::Const(num_traits::One::one()),
                        };
                        if neg {
                            coeff = RExpr::Neg(Box::new(coeff));
                        }
                        lin.push(LinTerm {
                            coeff,
                            unknown: u.map(|u| unknown(u, scope)).transpose()?,
                        });
                    }
                    sides.push(lin);
                }
                let rhs_terms = sides.pop().unwrap_or_default();
                let lhs_terms = sides.pop().unwrap_or_default();
                let mut q = Inequality {
                    abs,
                    lhs: lhs_terms,
                    rhs: rhs_terms,
                    domain: interval(domain, scope, &slots)?,
                    text: String::new(),
                };
                let names: Vec<String> = scope
                    .scalars
                    .iter()
                    .cloned()
                    .chain(
                        scope
                            .params
                            .iter()
                            .enumerate()
                            .filter(|(i, _)| scope.is_real_param(*i))
                            .map(|(_, (n, _))| n.clone()),
                    )
                    .collect();
                q.text = q.to_text(&scope.unknowns, &names);
                c.inequalities.push(q);
            }
            Stmt::Singular {
                unknown: u,
                at,
                side,
                body,
            } => {
                let coefficient = |id: &Ident| match scope.get(&id.name) {
                    Some(Entry {
                        sort: Sort::Coefficient(k),
                        span,
                    }) if span == id.span => Some(k),
                    _ => None,
                };
                // A sum of exact terms `A*g(x) + B*h(x)` is one term each:
                // one column per coefficient, fixed with the others at the
                // point (the discretisation's one-sided limit and extra
                // collocation points).
                let (u, at) = (unknown(u, scope)?, rexpr(at, scope, &slots)?);
                if let Some(terms) = coefficient_terms(body)
                    && let Some(ks) = terms
                        .iter()
                        .map(|(id, _)| coefficient(id))
                        .collect::<Option<Vec<usize>>>()
                {
                    for ((_, g), k) in terms.iter().zip(ks) {
                        c.singulars.push(Singular {
                            unknown: u,
                            at: at.clone(),
                            side: *side,
                            kind: SingularKind::Term {
                                coefficient: k,
                                func: rexpr(g, scope, &slots)?,
                            },
                        });
                    }
                    continue;
                }
                let (kind, what) = if log_form(body, scope).is_some() {
                    (SingularKind::Log, "logarithm")
                } else {
                    let (_, exp) =
                        weight_form(body, scope).ok_or_else(|| internal(body.span, "a weight"))?;
                    let exponent = rexpr(&exp, scope, &slots)?;
                    (SingularKind::Weight { exponent }, "weight")
                };
                // A weight is |x − P|^e on both sides of its point whatever
                // side is written, and a logarithm takes no weight out: two
                // of them at one point would multiply (or one would be lost)
                // where the user means a sum.
                if let Some((_, _, first, first_what)) =
                    behaviours.iter().find(|(v, p, _, _)| *v == u && *p == at)
                {
                    return Err(LangError::new(
                        ErrorKind::Unsupported,
                        format!(
                            "`{}` already has a {first_what} at this point: a weight or logarithm factors the whole unknown there, so one unknown has one of them per point",
                            scope.unknowns.get(u).map_or("this unknown", String::as_str)
                        ),
                        body.span,
                        format!("a second {what}"),
                    )
                    .with_related(*first, format!("the {first_what} declared first"))
                    .with_help("a product of powers of one point is one power with the exponents added (`(1 - x)^(-1/2)` times `(1 - x)^(1/4)` is `singular p at 1 ~ (1 - x)^(-1/4)`); a sum of singular behaviours is written as exact terms with their own coefficients on one side, `singular p at 1- ~ A/sqrt(1 - x) + B*(1 - x)^(-1/4)`"));
                }
                behaviours.push((u, at.clone(), body.span, what));
                c.singulars.push(Singular {
                    unknown: u,
                    at,
                    side: *side,
                    kind,
                });
            }
            Stmt::Condition { lhs, rhs }
                if !super::validate_system::is_side_condition(lhs, scope) =>
            {
                let k = match &lhs.kind {
                    ExprKind::Name(id) => match scope.get(&id.name) {
                        Some(Entry {
                            sort: Sort::Coefficient(k),
                            ..
                        }) => k,
                        _ => return Err(internal(lhs.span, "a condition")),
                    },
                    _ => return Err(internal(lhs.span, "a condition")),
                };
                c.conditions.push(Condition {
                    coefficient: k,
                    value: rexpr(rhs, scope, &slots)?,
                });
            }
            _ => {}
        }
    }
    if c.rhs.iter().all(Option::is_none) {
        c.rhs.clear();
    }
    if c.equation_domains.iter().all(Option::is_none) && !c.is_split() {
        c.equation_domains.clear();
    }
    Ok(c)
}

/// Where the lowering of an integral puts a limit that uses a scalar
/// until [`moving_ends`] replaces it: a rational far beyond any interval,
/// offset by the limit's position in the source, so that the limit is
/// found again whatever the lowering did to the terms around it
/// (distributed factors, signs, several unknowns in one integrand).
pub(crate) fn moving_marker(e: &Expr) -> num_rational::BigRational {
    let base = num_bigint::BigInt::from(10).pow(60);
    num_rational::BigRational::from_integer(base + num_bigint::BigInt::from(e.span.start))
}

/// The source position a [`moving_marker`] stands for, if `q` is one.
fn marker_position(q: &num_rational::BigRational) -> Option<usize> {
    let base = num_bigint::BigInt::from(10).pow(60);
    if !q.is_integer() || q.numer() < &base {
        return None;
    }
    (q.numer() - base).to_usize()
}

/// Every integration limit and point-value position in `e` that uses a
/// scalar.
fn scalar_limits<'e>(e: &'e Expr, scope: &Scope, out: &mut Vec<&'e Expr>) {
    match &e.kind {
        ExprKind::Call(f, a) if scope.is_unknown(&f.name) && uses_scalar(a, scope) => out.push(a),
        ExprKind::Integral { lower, upper, .. } => {
            for l in [lower, upper] {
                if uses_scalar(l, scope) {
                    out.push(l);
                }
            }
        }
        ExprKind::Neg(a) | ExprKind::Call(_, a) => scalar_limits(a, scope, out),
        ExprKind::Binary(_, a, b) => {
            scalar_limits(a, scope, out);
            scalar_limits(b, scope, out);
        }
        _ => {}
    }
}

/// Replaces the [`moving_marker`]s among `limits` (one per integral term
/// of a definition, output or condition `body`, with its site) by the
/// end of the unknowns' interval on their side and records each as a
/// [`MovingEnd`] of `contact`.
pub(crate) fn moving_ends<'l>(
    body: &Expr,
    scope: &Scope,
    contact: &mut Contact,
    limits: impl Iterator<Item = (EndSite, &'l mut num_rational::BigRational, bool)>,
) -> Result<(), LangError> {
    let mut found = Vec::new();
    scalar_limits(body, scope, &mut found);
    if found.is_empty() {
        return Ok(());
    }
    let slots = real_slots(scope);
    let domain = contact
        .unknown_domains
        .iter()
        .flatten()
        .next()
        .and_then(|d| match (&d.lo, &d.hi) {
            (RExpr::Const(lo), RExpr::Const(hi)) => Some((lo.clone(), hi.clone())),
            _ => None,
        })
        .ok_or_else(|| internal(body.span, "an integration limit with a scalar"))?;
    for (site, q, upper) in limits {
        let Some(at) = marker_position(q) else {
            continue;
        };
        let e = found
            .iter()
            .find(|e| e.span.start == at)
            .ok_or_else(|| internal(body.span, "an integration limit with a scalar"))?;
        contact.ends.push(MovingEnd {
            site,
            upper,
            value: rexpr(e, scope, &slots)?,
        });
        *q = if upper {
            domain.1.clone()
        } else {
            domain.0.clone()
        };
    }
    Ok(())
}
