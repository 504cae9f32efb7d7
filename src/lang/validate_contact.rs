//! Meaning checks of the split-domain statements (contact problems):
//! intervals after `on`, `relation`, `scalar`, `singular`, `condition`, and
//! real parameters (values such as `acot(gamma*mu)/pi` that are not exact
//! rationals). Every error carries a span; nothing here builds the lowered
//! program (that is `lower_contact.rs`) or touches the operator part.
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use super::ast::{BinOp, Expr, ExprKind, Ident, Interval};
use super::error::{ErrorKind, LangError};
use super::scope::{Entry, Scope, Sort};
use super::validate::Validator;
use crate::system::contact::RFunc;

/// Whether `e` is the name `inf`.
pub(super) fn is_inf(e: &Expr) -> bool {
    matches!(&e.kind, ExprKind::Name(id) if id.name == "inf")
}

/// `B*g(x)` (a product or quotient whose leftmost factor is the name `B`):
/// the name and `g`, the expression with `B` replaced by 1.
pub(super) fn coefficient_term(e: &Expr) -> Option<(Ident, Expr)> {
    fn leftmost(e: &Expr) -> Option<&Ident> {
        match &e.kind {
            ExprKind::Binary(BinOp::Mul | BinOp::Div, a, _) => match &a.kind {
                ExprKind::Name(id) if id.name != "x" => Some(id),
                _ => leftmost(a),
            },
            _ => None,
        }
    }
    fn replace(e: &Expr, id: &Ident) -> Expr {
        match &e.kind {
            ExprKind::Binary(op @ (BinOp::Mul | BinOp::Div), a, b) => {
                let a = match &a.kind {
                    ExprKind::Name(n) if n == id => Expr {
                        kind: ExprKind::Number(num_traits::One::one()),
                        span: a.span,
                    },
                    _ => replace(a, id),
                };
                Expr {
                    kind: ExprKind::Binary(*op, Box::new(a), b.clone()),
                    span: e.span,
                }
            }
            _ => e.clone(),
        }
    }
    let id = leftmost(e)?.clone();
    let g = replace(e, &id);
    Some((id, g))
}

/// `B*g(x) + D*h(x) - …`: the terms of a sum of coefficient terms (a
/// single term is a sum of one), each a name and its function, a
/// subtracted term's function negated; `None` unless every summand is a
/// coefficient term.
pub(super) fn coefficient_terms(e: &Expr) -> Option<Vec<(Ident, Expr)>> {
    match &e.kind {
        ExprKind::Binary(op @ (BinOp::Add | BinOp::Sub), a, b) => {
            let mut terms = coefficient_terms(a)?;
            let (id, g) = coefficient_term(b)?;
            let g = if *op == BinOp::Sub {
                Expr {
                    span: g.span,
                    kind: ExprKind::Neg(Box::new(g)),
                }
            } else {
                g
            };
            terms.push((id, g));
            Some(terms)
        }
        _ => coefficient_term(e).map(|t| vec![t]),
    }
}

/// Whether `x` occurs in `e`.
fn uses_x(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Name(id) => id.name == "x",
        ExprKind::Neg(a) | ExprKind::Call(_, a) => uses_x(a),
        ExprKind::Binary(_, a, b) => uses_x(a) || uses_x(b),
        _ => false,
    }
}

/// Whether `e` calls `ln` (or `log`, its spelling in a singular
/// declaration).
fn uses_ln(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Call(f, a) => f.name == "ln" || f.name == "log" || uses_ln(a),
        ExprKind::Neg(a) => uses_ln(a),
        ExprKind::Binary(_, a, b) => uses_ln(a) || uses_ln(b),
        _ => false,
    }
}

fn node(kind: ExprKind, span: super::ast::Span) -> Expr {
    Expr { kind, span }
}

fn number(q: BigRational, span: super::ast::Span) -> Expr {
    node(ExprKind::Number(q), span)
}

/// `e` as `a·x + b` with an exact `a` (terms free of `x` make up `b`, in
/// source form); `None` when `e` is not of that shape.
fn linear_x(e: &Expr, scope: &Scope) -> Option<(BigRational, Option<Expr>)> {
    let bin = |op, a: Expr, b: Expr| node(ExprKind::Binary(op, Box::new(a), Box::new(b)), e.span);
    if !uses_x(e) {
        return Some((BigRational::zero(), Some(e.clone())));
    }
    match &e.kind {
        ExprKind::Name(_) => Some((BigRational::one(), None)),
        ExprKind::Neg(a) => {
            let (k, c) = linear_x(a, scope)?;
            Some((-k, c.map(|c| node(ExprKind::Neg(Box::new(c)), e.span))))
        }
        ExprKind::Binary(op @ (BinOp::Add | BinOp::Sub), a, b) => {
            let (ka, ca) = linear_x(a, scope)?;
            let (kb, cb) = linear_x(b, scope)?;
            let k = if *op == BinOp::Add { ka + kb } else { ka - kb };
            let c = match (ca, cb) {
                (Some(ca), Some(cb)) => Some(bin(*op, ca, cb)),
                (Some(ca), None) => Some(ca),
                (None, Some(cb)) if *op == BinOp::Add => Some(cb),
                (None, Some(cb)) => Some(node(ExprKind::Neg(Box::new(cb)), e.span)),
                (None, None) => None,
            };
            Some((k, c))
        }
        ExprKind::Binary(BinOp::Mul, a, b) => {
            let (f, l) = if uses_x(a) { (b, a) } else { (a, b) };
            let q = super::lower::constant(f, scope)?;
            let (k, c) = linear_x(l, scope)?;
            Some((k * &q, c.map(|c| bin(BinOp::Mul, number(q, e.span), c))))
        }
        ExprKind::Binary(BinOp::Div, a, b) => {
            let q = super::lower::constant(b, scope).filter(|q| !q.is_zero())?;
            let (k, c) = linear_x(a, scope)?;
            Some((k / &q, c.map(|c| bin(BinOp::Div, c, number(q, e.span)))))
        }
        _ => None,
    }
}

/// A weight `|x − P|^e` however it is written: a power, square root or
/// reciprocal of an expression linear in `x` (`(1 - x)^(-alpha)`,
/// `(x - (-1))^(-1/2)`, `(1 + x)^(-1/2)`, `1/sqrt(1 + x)`,
/// `abs(2*x - 2)^(-1/3)`), possibly times a constant (a weight's constant
/// factor is immaterial: the smooth factor takes it). Returns the point
/// `P` and the exponent `e`, both in source form.
pub(super) fn weight_form(e: &Expr, scope: &Scope) -> Option<(Expr, Expr)> {
    let span = e.span;
    let half = || number(BigRational::new(1.into(), 2.into()), span);
    let base = |b: &Expr| -> Option<Expr> {
        let b = match &b.kind {
            ExprKind::Call(f, a) if f.name == "abs" => a,
            _ => b,
        };
        let (k, c) = linear_x(b, scope)?;
        if k.is_zero() {
            return None;
        }
        // a·x + c = a·(x − P) with P = −c/a.
        Some(match c {
            None => number(BigRational::zero(), span),
            Some(c) => node(
                ExprKind::Neg(Box::new(node(
                    ExprKind::Binary(BinOp::Div, Box::new(c), Box::new(number(k, span))),
                    span,
                ))),
                span,
            ),
        })
    };
    let times =
        |a: Expr, b: Expr| node(ExprKind::Binary(BinOp::Mul, Box::new(a), Box::new(b)), span);
    match &e.kind {
        ExprKind::Binary(BinOp::Pow, b, exp) if !uses_x(exp) => match &b.kind {
            ExprKind::Call(f, a) if f.name == "sqrt" => {
                Some((base(a)?, times(half(), (**exp).clone())))
            }
            _ => Some((base(b)?, (**exp).clone())),
        },
        ExprKind::Call(f, a) if f.name == "sqrt" => Some((base(a)?, half())),
        ExprKind::Binary(BinOp::Div, k, w) if !uses_x(k) => {
            let (p, exp) = weight_form(w, scope)?;
            Some((p, node(ExprKind::Neg(Box::new(exp)), span)))
        }
        ExprKind::Binary(BinOp::Mul, k, w) | ExprKind::Binary(BinOp::Mul, w, k) if !uses_x(k) => {
            weight_form(w, scope)
        }
        ExprKind::Binary(BinOp::Div, w, k) if !uses_x(k) => weight_form(w, scope),
        _ => None,
    }
}

/// A logarithmic singular behaviour: `ln(L)` or `log(L)` with `L` linear
/// in `x` (or its absolute value, square root or power), possibly negated
/// or times a constant (`ln(x)`, `-ln(1 - x)`, `ln(abs(x - P))/2`): the
/// point `P` where `L` vanishes.
pub(super) fn log_form(e: &Expr, scope: &Scope) -> Option<Expr> {
    match &e.kind {
        ExprKind::Call(f, a) if f.name == "ln" || f.name == "log" => {
            let one = number(BigRational::one(), e.span);
            let power = node(ExprKind::Binary(BinOp::Pow, a.clone(), Box::new(one)), e.span);
            weight_form(&power, scope).map(|(point, _)| point)
        }
        ExprKind::Neg(a) => log_form(a, scope),
        ExprKind::Binary(BinOp::Mul, k, w) | ExprKind::Binary(BinOp::Mul, w, k) if !uses_x(k) => {
            log_form(w, scope)
        }
        ExprKind::Binary(BinOp::Div, w, k) if !uses_x(k) => log_form(w, scope),
        _ => None,
    }
}

/// A relation's right side `k * v`, `v * k` or `v`: the factor (if any) and
/// the unknown `v`.
pub(super) fn relation_form(
    e: &Expr,
    is_unknown: impl Fn(&str) -> bool,
) -> Option<(Option<&Expr>, &Ident)> {
    match &e.kind {
        ExprKind::Name(id) if is_unknown(&id.name) => Some((None, id)),
        ExprKind::Binary(BinOp::Mul, a, b) => match (&a.kind, &b.kind) {
            (_, ExprKind::Name(id)) if is_unknown(&id.name) => Some((Some(a), id)),
            (ExprKind::Name(id), _) if is_unknown(&id.name) => Some((Some(b), id)),
            _ => None,
        },
        _ => None,
    }
}

/// One side of an inequality as terms `(factor, unknown)` (the factor
/// `None` for 1, the unknown `None` for a constant term), each with its
/// sign; `None` when it is not such a sum.
pub(super) fn linear_side<'e>(
    e: &'e Expr,
    is_unknown: &impl Fn(&str) -> bool,
    negate: bool,
    out: &mut Vec<(bool, Option<&'e Expr>, Option<&'e Ident>)>,
) -> Option<()> {
    let mentions = |e: &Expr| mentions_unknown(e, is_unknown);
    match &e.kind {
        ExprKind::Neg(a) => linear_side(a, is_unknown, !negate, out),
        ExprKind::Binary(op @ (BinOp::Add | BinOp::Sub), a, b) => {
            linear_side(a, is_unknown, negate, out)?;
            linear_side(b, is_unknown, negate ^ (*op == BinOp::Sub), out)
        }
        _ if !mentions(e) => {
            out.push((negate, Some(e), None));
            Some(())
        }
        _ => {
            let (k, u) = relation_form(e, is_unknown)?;
            if k.is_some_and(mentions) {
                return None;
            }
            out.push((negate, k, Some(u)));
            Some(())
        }
    }
}

fn mentions_unknown(e: &Expr, is_unknown: &impl Fn(&str) -> bool) -> bool {
    match &e.kind {
        ExprKind::Name(id) => is_unknown(&id.name),
        ExprKind::Call(f, a) => is_unknown(&f.name) || mentions_unknown(a, is_unknown),
        ExprKind::Neg(a) => mentions_unknown(a, is_unknown),
        ExprKind::Binary(_, a, b) => {
            mentions_unknown(a, is_unknown) || mentions_unknown(b, is_unknown)
        }
        _ => false,
    }
}

/// An inequality `lhs <= rhs` (`>=` swapped) as `(abs, smaller, larger)`:
/// the smaller side without its `abs(…)` if it has one.
pub(super) fn inequality_sides<'e>(
    lhs: &'e Expr,
    ge: bool,
    rhs: &'e Expr,
) -> (bool, &'e Expr, &'e Expr) {
    let (small, large) = if ge { (rhs, lhs) } else { (lhs, rhs) };
    match &small.kind {
        ExprKind::Call(f, a) if f.name == "abs" => (true, a, large),
        _ => (false, small, large),
    }
}

fn wrong(e: &Expr, msg: impl Into<String>, label: &str, help: &str) -> LangError {
    LangError::new(ErrorKind::WrongSort, msg, e.span, label).with_help(help)
}

impl Validator {
    /// Whether `e` is a real constant (numbers, `pi`, parameters defined
    /// so far, scalars, `the functions, `+ - * / ^`; and `x`
    /// when `allow_x`), reporting every error.
    pub(super) fn real_expr(&mut self, e: &Expr, allow_x: bool) -> bool {
        match &e.kind {
            ExprKind::Number(_) | ExprKind::Pi => true,
            ExprKind::Name(id) if id.name == "x" && allow_x => true,
            ExprKind::Name(id) => match self.scope.get(&id.name) {
                Some(Entry {
                    sort: Sort::Param(i),
                    ..
                }) => {
                    let known = self.scope.param_value(i).is_some() || self.scope.is_real_param(i);
                    if !known && !self.param_processed(i) {
                        self.err(LangError::new(
                            ErrorKind::Undeclared,
                            format!("parameter `{}` is used before its definition", id.name),
                            id.span,
                            "not yet defined",
                        ));
                    }
                    known
                }
                Some(Entry {
                    sort: Sort::Scalar(_),
                    ..
                }) => true,
                Some(en) => {
                    self.err(
                        LangError::new(
                            ErrorKind::WrongSort,
                            format!(
                                "`{}` is {}, but a number is needed here",
                                id.name,
                                en.sort.word()
                            ),
                            id.span,
                            "not a number",
                        )
                        .with_related(en.span, "declared here"),
                    );
                    false
                }
                None => {
                    self.err(
                        LangError::new(
                            ErrorKind::Undeclared,
                            format!("undeclared name `{}`", id.name),
                            id.span,
                            "not declared",
                        )
                        .with_help("declare it with `param` or `scalar`"),
                    );
                    false
                }
            },
            ExprKind::Neg(a) => self.real_expr(a, allow_x),
            ExprKind::Binary(BinOp::Pow, _, b) if matches!(&b.kind, ExprKind::Number(q) if q.abs() > num_rational::BigRational::from_integer(super::validate::MAX_EXPONENT.into())) =>
            {
                self.err(LangError::new(
                    ErrorKind::BadExponent,
                    format!(
                        "exponent is too large (the limit is {})",
                        super::validate::MAX_EXPONENT
                    ),
                    b.span,
                    "too large",
                ));
                false
            }
            ExprKind::Binary(_, a, b) => {
                let l = self.real_expr(a, allow_x);
                self.real_expr(b, allow_x) && l
            }
            ExprKind::Call(f, a) => {
                let ok = RFunc::from_name(&f.name).is_some();
                if !ok {
                    self.err(
                        LangError::new(
                            ErrorKind::WrongSort,
                            format!("unknown function `{}`", f.name),
                            f.span,
                            "not a function",
                        )
                        .with_help(format!(
                            "functions: {}",
                            super::validate_system::function_list()
                        )),
                    );
                }
                self.real_expr(a, allow_x) && ok
            }
            ExprKind::Identity | ExprKind::Integral { .. } => {
                self.err(wrong(
                    e,
                    "an operator cannot appear in a number",
                    "not a number",
                    "use numbers, parameters, scalars and elementary functions",
                ));
                false
            }
        }
    }

    /// Whether `e` uses an unknown scalar, directly or through a real
    /// parameter defined with one.
    pub(super) fn uses_scalar(&self, e: &Expr) -> bool {
        match &e.kind {
            ExprKind::Name(id) => match self.scope.get(&id.name) {
                Some(Entry {
                    sort: Sort::Scalar(_),
                    ..
                }) => true,
                Some(Entry {
                    sort: Sort::Param(i),
                    ..
                }) => self.scope.is_real_param(i) && self.scope.real_def(i).is_none(),
                _ => false,
            },
            ExprKind::Neg(a) | ExprKind::Call(_, a) => self.uses_scalar(a),
            ExprKind::Binary(_, a, b) => self.uses_scalar(a) || self.uses_scalar(b),
            _ => false,
        }
    }

    /// Whether `e` can only be real, not exactly rational: it uses `pi`, a
    /// function, a power that is not an integer literal, a real parameter
    /// or a scalar. (Other failures of exact evaluation, such as a division
    /// by zero, stay errors.)
    pub(super) fn needs_real(&self, e: &Expr) -> bool {
        match &e.kind {
            ExprKind::Pi | ExprKind::Call(..) => true,
            ExprKind::Number(_) | ExprKind::Identity | ExprKind::Integral { .. } => false,
            ExprKind::Name(id) => match self.scope.get(&id.name) {
                Some(Entry {
                    sort: Sort::Param(i),
                    ..
                }) => self.scope.is_real_param(i),
                Some(Entry {
                    sort: Sort::Scalar(_),
                    ..
                }) => true,
                _ => false,
            },
            ExprKind::Neg(a) => self.needs_real(a),
            ExprKind::Binary(BinOp::Pow, a, b) => {
                let lit = match &b.kind {
                    ExprKind::Neg(inner) => inner.as_ref(),
                    _ => b.as_ref(),
                };
                !matches!(&lit.kind, ExprKind::Number(q) if q.is_integer()) || self.needs_real(a)
            }
            ExprKind::Binary(_, a, b) => self.needs_real(a) || self.needs_real(b),
        }
    }

    /// Checks an interval whose ends are real constants.
    pub(super) fn interval(&mut self, i: &Interval) {
        self.real_expr(&i.lo, false);
        self.real_expr(&i.hi, false);
    }

    /// Refuses an unknowns' interval with an end that uses an unknown
    /// scalar: the unknowns live on a fixed interval.
    pub(super) fn fixed_interval(&mut self, i: &Interval) {
        for end in [&i.lo, &i.hi] {
            if self.uses_scalar(end) {
                self.err(
                    LangError::new(
                        ErrorKind::Unsupported,
                        "an unknown's interval cannot end at an unknown scalar: the unknowns live on a fixed interval",
                        end.span,
                        "uses an unknown scalar",
                    )
                    .with_help("declare the unknown on a fixed interval that holds every value of the scalar, and say what it is beyond the scalar: `unknown p on [0, 2]`, `relation p = 0 on [a, 2]` (examples/contact/sphere_indentation.lmx)"),
                );
            }
        }
    }

    /// Checks a scalar's range: constants, `inf` allowed as the right end.
    pub(super) fn scalar_range(&mut self, i: &Interval) {
        if is_inf(&i.lo) {
            self.err(wrong(
                &i.lo,
                "the range of a scalar must have a finite left end",
                "infinite",
                "write e.g. `scalar mu in (0, inf)`",
            ));
        } else {
            self.constant(&i.lo);
        }
        if !is_inf(&i.hi) {
            self.constant(&i.hi);
        }
    }

    /// A scalar's asymptotic estimate: a real expression of the
    /// parameters (not of `x` or of any scalar: it estimates one).
    pub(super) fn scalar_estimate(&mut self, e: &Expr) {
        if !self.real_expr(e, false) {
            return;
        }
        fn scalar_name<'a>(v: &Validator, e: &'a Expr) -> Option<&'a Ident> {
            match &e.kind {
                ExprKind::Name(id) => matches!(
                    v.scope.get(&id.name),
                    Some(Entry {
                        sort: Sort::Scalar(_),
                        ..
                    })
                )
                .then_some(id),
                ExprKind::Neg(a) | ExprKind::Call(_, a) => scalar_name(v, a),
                ExprKind::Binary(_, a, b) => scalar_name(v, a).or_else(|| scalar_name(v, b)),
                _ => None,
            }
        }
        if let Some(id) = scalar_name(self, e) {
            self.err(
                LangError::new(
                    ErrorKind::WrongSort,
                    format!(
                        "a scalar's estimate cannot use the scalar `{}`: it is a value of the parameters",
                        id.name
                    ),
                    id.span,
                    "a scalar",
                )
                .with_help("write it with numbers, parameters and elementary functions, e.g. `scalar c in (0, 1) ~ 4*exp(-1/mu)`"),
            );
        }
    }

    /// `relation u = k * v on I`.
    pub(super) fn relation(&mut self, unknown: &Ident, value: &Expr, domain: &Interval) {
        self.unknown_ref(unknown);
        let scope = &self.scope;
        let is_unknown = |n: &str| scope.is_unknown(n);
        match relation_form(value, is_unknown) {
            Some((factor, other)) => {
                if other.name == unknown.name {
                    self.err(wrong(
                        value,
                        "a relation must express an unknown by another one",
                        "same unknown",
                        "write e.g. `relation q = mu*p on [c, 1]`",
                    ));
                }
                if let Some(k) = factor {
                    self.real_expr(k, false);
                }
            }
            None if super::lower::constant(value, &self.scope).is_some_and(|q| q.is_zero()) => {}
            None => self.err(wrong(
                value,
                "the right side of a relation must be 0 or a constant times an unknown",
                "not `0` or `k * unknown`",
                "write e.g. `relation p = 0 on [a, 2]` or `relation q = mu*p on [c, 1]`",
            )),
        }
        self.interval(domain);
    }

    /// `inequality lhs <= rhs on domain` (or `>=`).
    pub(super) fn inequality(&mut self, lhs: &Expr, ge: bool, rhs: &Expr, domain: &Interval) {
        let (_, small, large) = inequality_sides(lhs, ge, rhs);
        for side in [small, large] {
            let scope = &self.scope;
            let is_unknown = |n: &str| scope.is_unknown(n);
            let mut terms = Vec::new();
            if linear_side(side, &is_unknown, false, &mut terms).is_none() {
                self.err(wrong(
                    side,
                    "each side of an inequality must be a sum of constant multiples of unknowns and constants (the smaller side may be wrapped in `abs(…)`)",
                    "not understood",
                    "write e.g. `inequality abs(q) <= mu*p on [0, c)` or `inequality p >= 0 on [0, a]`",
                ));
                continue;
            }
            for (_, k, u) in terms {
                if let Some(u) = u {
                    self.unknown_ref(u);
                }
                if let Some(k) = k {
                    self.real_expr(k, false);
                }
            }
        }
        self.interval(domain);
    }

    /// `singular u at P± ~ body`.
    pub(super) fn singular(&mut self, unknown: &Ident, at: &Expr, body: &Expr) {
        self.unknown_ref(unknown);
        self.real_expr(at, false);
        if let Some(terms) = coefficient_terms(body) {
            let new = |id: &Ident| {
                matches!(
                    self.scope.get(&id.name),
                    Some(Entry {
                        sort: Sort::Coefficient(_),
                        span
                    }) if span == id.span
                )
            };
            if terms.iter().all(|(id, _)| new(id)) {
                for (_, g) in &terms {
                    self.real_expr(g, true);
                }
                return;
            }
            if terms.len() > 1 {
                if let Some((id, _)) = terms.iter().find(|(id, _)| !new(id)) {
                    self.err(wrong(
                        &Expr {
                            kind: ExprKind::Name(id.clone()),
                            span: id.span,
                        },
                        "each term of a sum of singular terms needs its own new coefficient name (`A*g(x) + B*h(x)`)",
                        "not a new coefficient",
                        "e.g. `singular p at 1- ~ A/sqrt(1 - x) + B*(1 - x)^(-1/4)`",
                    ));
                }
                return;
            }
        }
        if let Some(point) = log_form(body, &self.scope) {
            if self.real_expr(&point, false) {
                self.same_point(body, &point, at, "logarithm", "`singular p at 0 ~ ln(x)`");
            }
            return;
        }
        match weight_form(body, &self.scope) {
            Some((point, exp)) => {
                let ok = self.real_expr(&point, false);
                self.real_expr(&exp, false);
                if ok {
                    self.same_point(body, &point, at, "weight", "`singular f at -1 ~ (1 + x)^(-1/2)`");
                }
            }
            None if uses_ln(body) => self.err(
                LangError::new(
                    ErrorKind::Unsupported,
                    "logarithmic singular behaviour must be the logarithm of an expression linear in x that vanishes at the declared point: `ln(x - P)`, `ln(P - x)`, `ln(abs(x - P))` or `log(…)`, alone or times a constant",
                    body.span,
                    "not such a logarithm",
                )
                .with_help("e.g. `singular p at 0 ~ ln(x)`; a logarithm times a power is not supported: declare the power as a weight, or leave the end undeclared (the solver grades the mesh toward the ends of the unknowns' interval and toward every breakpoint)"),
            ),
            None => self.err(wrong(
                body,
                "singular behaviour must be a weight `|x - P|^e` (a power, square root or reciprocal of an expression linear in x, such as `(1 - x)^(-alpha)` or `1/sqrt(1 + x)`) or a term `B*g(x)` with a new coefficient name `B`",
                "not understood",
                "e.g. `singular p at 1 ~ (1 - x)^(-alpha)` or `singular q at c- ~ B*x/sqrt(c^2 - x^2)`",
            )),
        }
    }

    /// Refuses a weight or logarithm (`what`) in `body` singular at
    /// `point` other than the declared `at`, when both are exact.
    fn same_point(&mut self, body: &Expr, point: &Expr, at: &Expr, what: &str, example: &str) {
        let exact = |e: &Expr| super::lower::constant(e, &self.scope);
        if let (Some(p), Some(a)) = (exact(point), exact(at))
            && p != a
        {
            self.err(wrong(
                body,
                format!("this {what} is singular at x = {p}, not at the declared point {a}"),
                "another point",
                &format!("write the {what} of the point after `at`, e.g. {example}"),
            ));
        }
    }

    /// The first point value `u(arg)` in `e` whose position uses a scalar.
    fn moving_point<'e>(&self, e: &'e Expr) -> Option<&'e Expr> {
        match &e.kind {
            ExprKind::Call(f, a) if self.scope.is_unknown(&f.name) => {
                self.uses_scalar(a).then_some(&**a)
            }
            ExprKind::Neg(a) | ExprKind::Call(_, a) => self.moving_point(a),
            ExprKind::Binary(_, a, b) => self.moving_point(a).or_else(|| self.moving_point(b)),
            _ => None,
        }
    }

    /// `condition B = value`, or a side condition `functional = value`
    /// (an output's body, linear in the unknowns, fixed to a constant).
    pub(super) fn condition(&mut self, lhs: &Expr, rhs: &Expr) {
        if super::validate_system::is_side_condition(lhs, &self.scope) {
            self.output_body(lhs);
            self.side_value(rhs);
            if let Some(arg) = self.moving_point(lhs) {
                self.err(
                    LangError::new(
                        ErrorKind::Unsupported,
                        "a condition cannot take a point value at a position that uses an unknown scalar (not supported: the joint root solve does not follow such a condition from level to level)",
                        arg.span,
                        "moves with a scalar",
                    )
                    .with_help("take the point value at a constant (`p(1/2)`), or state the condition as an integral (`int(0..a) …`); outputs may take point values at scalars (`output p_mid = p(a/2)`)"),
                );
            }
            return;
        }
        let ok = matches!(&lhs.kind, ExprKind::Name(id) if matches!(
            self.scope.get(&id.name),
            Some(Entry { sort: Sort::Coefficient(_), .. })
        ));
        if !ok {
            self.err(wrong(
                lhs,
                "a condition must set the coefficient of a singular term",
                "not a singular coefficient",
                "declare `singular q at c- ~ B*g(x)` and write `condition B = 0`, or state a side condition on the unknowns: `condition int(-1..1) f(t) dt = 1`",
            ));
        }
        self.real_expr(rhs, false);
    }
}
