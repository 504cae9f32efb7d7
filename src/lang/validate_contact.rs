//! Meaning checks of the split-domain statements (contact problems):
//! intervals after `on`, `relation`, `scalar`, `singular`, `condition`, and
//! real parameters (values such as `acot(gamma*mu)/pi` that are not exact
//! rationals). Every error carries a span; nothing here builds the lowered
//! program (that is `lower_contact.rs`) or touches the operator part.
use num_traits::Signed;

use super::ast::{BinOp, Expr, ExprKind, Ident, Interval};
use super::error::{ErrorKind, LangError};
use super::scope::{Entry, Sort};
use super::validate::Validator;
use crate::system::contact::RFunc;

/// Whether `e` is the name `x`.
pub(super) fn is_x(e: &Expr) -> bool {
    matches!(&e.kind, ExprKind::Name(id) if id.name == "x")
}

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

/// `(P - x)^e` or `(x - P)^e`: the point expression and the exponent.
pub(super) fn weight_form(e: &Expr) -> Option<(&Expr, &Expr)> {
    let ExprKind::Binary(BinOp::Pow, base, exp) = &e.kind else {
        return None;
    };
    let ExprKind::Binary(BinOp::Sub, a, b) = &base.kind else {
        return None;
    };
    match (is_x(a), is_x(b)) {
        (false, true) => Some((a, exp)),
        (true, false) => Some((b, exp)),
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
        let is_unknown = |n: &str| {
            matches!(
                scope.get(n),
                Some(Entry {
                    sort: Sort::Unknown(_),
                    ..
                })
            )
        };
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
            None => self.err(wrong(
                value,
                "the right side of a relation must be a constant times an unknown",
                "not `k * unknown`",
                "write e.g. `relation q = mu*p on [c, 1]`",
            )),
        }
        self.interval(domain);
    }

    /// `singular u at P± ~ body`.
    pub(super) fn singular(&mut self, unknown: &Ident, at: &Expr, body: &Expr) {
        self.unknown_ref(unknown);
        self.real_expr(at, false);
        if let Some((id, g)) = coefficient_term(body).as_ref()
            && matches!(
                self.scope.get(&id.name),
                Some(Entry {
                    sort: Sort::Coefficient(_),
                    span
                }) if span == id.span
            )
        {
            self.real_expr(g, true);
            return;
        }
        match weight_form(body) {
            Some((point, exp)) => {
                self.real_expr(point, false);
                self.real_expr(exp, false);
            }
            None => self.err(wrong(
                body,
                "singular behaviour must be a weight `(P - x)^e` / `(x - P)^e` or a term `B*g(x)` with a new coefficient name `B`",
                "not understood",
                "e.g. `singular p at 1 ~ (1 - x)^(-alpha)` or `singular q at c- ~ B*x/sqrt(c^2 - x^2)`",
            )),
        }
    }

    /// `condition B = value`, or a side condition `functional = value`
    /// (an output's body, linear in the unknowns, fixed to a constant).
    pub(super) fn condition(&mut self, lhs: &Expr, rhs: &Expr) {
        if super::validate_system::is_side_condition(lhs, &self.scope) {
            self.output_body(lhs);
            self.side_value(rhs);
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
