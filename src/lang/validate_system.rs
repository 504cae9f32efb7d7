//! Meaning checks for the operator-system part of a file (operators,
//! equations, outputs, `solve for`), as more methods of the validator in
//! `validate.rs`: which variables a kernel, multiplier, right side or output
//! may use, linearity in the unknowns, operator definitions built only from
//! `id` and integrals, a square system. Like `validate.rs` it collects every
//! error with its span, never panics and builds nothing.

use num_traits::Zero;

use super::ast::{BinOp, Expr, ExprKind, File, Ident, IntVar, LhsTerm, Stmt};
use super::error::{ErrorKind, LangError};
use super::scope::{Entry, Scope, Sort};
use super::validate::{MAX_DEGREE, PolyCtx, Validator, division_by_zero};
use crate::system::Func;

/// Where a real-valued expression appears; decides which variables it may
/// use and how errors are worded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Place {
    /// The integrand of an operator's integral: `x` and `t`.
    Kernel,
    /// A function of x multiplying an operator term: `x` only.
    Multiplier,
    /// The right side of an equation: `x` only.
    Rhs,
    /// The weight in an output's integral: only the integration variable.
    Weight(IntVar),
    /// A constant factor or term of an output: no variable.
    OutputConst,
}

impl Place {
    fn allows(self, var: IntVar) -> bool {
        match self {
            Place::Kernel => true,
            Place::Multiplier | Place::Rhs => var == IntVar::X,
            Place::Weight(v) => v == var,
            Place::OutputConst => false,
        }
    }

    fn what(self) -> &'static str {
        match self {
            Place::Kernel => "a kernel",
            Place::Multiplier => "a multiplier of an operator",
            Place::Rhs => "the right side of an equation",
            Place::Weight(_) => "an output's integrand",
            Place::OutputConst => "an output outside its integrals",
        }
    }

    fn variables(self) -> &'static str {
        match self {
            Place::Kernel => "x, t, ",
            Place::Multiplier | Place::Rhs | Place::Weight(IntVar::X) => "x, ",
            Place::Weight(IntVar::T) => "t, ",
            Place::OutputConst => "",
        }
    }
}

/// The variable a name stands for in a real-valued expression, if any.
fn variable(name: &str) -> Option<IntVar> {
    match name {
        "x" => Some(IntVar::X),
        "t" => Some(IntVar::T),
        _ => None,
    }
}

fn var_name(v: IntVar) -> &'static str {
    match v {
        IntVar::X => "x",
        IntVar::T => "t",
    }
}

/// How an equation term splits: the operator product (if any) and the
/// unknown it is applied to (if one can be found where it must be).
pub(crate) fn split_term(term: &LhsTerm) -> (Option<&Expr>, Option<&Ident>) {
    if let Some(u) = &term.unknown {
        return (Some(&term.product), Some(u));
    }
    match &term.product.kind {
        ExprKind::Name(id) => (None, Some(id)),
        ExprKind::Binary(BinOp::Mul, a, b) => match &b.kind {
            ExprKind::Name(id) => (Some(a), Some(id)),
            _ => (Some(&term.product), None),
        },
        _ => (Some(&term.product), None),
    }
}

/// Whether `e` contains an operator piece (`id` or an integral).
pub(crate) fn contains_operator(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Identity | ExprKind::Integral { .. } => true,
        ExprKind::Neg(a) | ExprKind::Call(_, a) => contains_operator(a),
        ExprKind::Binary(_, a, b) => contains_operator(a) || contains_operator(b),
        _ => false,
    }
}

impl Validator {
    fn is_unknown(&self, name: &str) -> bool {
        matches!(
            self.scope.get(name),
            Some(Entry {
                sort: Sort::Unknown(_),
                ..
            })
        )
    }

    /// The first unknown mentioned anywhere in `e` (as a name or a call).
    fn first_unknown<'e>(&self, e: &'e Expr) -> Option<&'e Ident> {
        match &e.kind {
            ExprKind::Name(id) if self.is_unknown(&id.name) => Some(id),
            ExprKind::Call(f, a) => {
                if self.is_unknown(&f.name) {
                    Some(f)
                } else {
                    self.first_unknown(a)
                }
            }
            ExprKind::Neg(a) => self.first_unknown(a),
            ExprKind::Binary(_, a, b) => self.first_unknown(a).or_else(|| self.first_unknown(b)),
            _ => None,
        }
    }

    /// Counts the unknowns mentioned in `e`.
    fn count_unknowns(&self, e: &Expr) -> usize {
        match &e.kind {
            ExprKind::Name(id) => usize::from(self.is_unknown(&id.name)),
            ExprKind::Call(f, a) => usize::from(self.is_unknown(&f.name)) + self.count_unknowns(a),
            ExprKind::Neg(a) => self.count_unknowns(a),
            ExprKind::Binary(_, a, b) => self.count_unknowns(a) + self.count_unknowns(b),
            ExprKind::Integral {
                lower,
                upper,
                integrand,
                ..
            } => {
                self.count_unknowns(lower)
                    + self.count_unknowns(upper)
                    + integrand.as_ref().map_or(0, |i| self.count_unknowns(i))
            }
            _ => 0,
        }
    }

    /// `x` and `t` cannot name parameters, unknowns, operators or outputs.
    pub(super) fn not_reserved(&mut self, id: &Ident, what: &str) {
        if let Some(v) = variable(&id.name) {
            let role = match v {
                IntVar::X => "the output variable of kernels and right sides",
                IntVar::T => "the integration variable of kernels",
            };
            self.err(
                LangError::new(
                    ErrorKind::BadVariable,
                    format!("`{}` is {role} and cannot name {what}", id.name),
                    id.span,
                    "reserved variable",
                )
                .with_help("choose another name"),
            );
        }
    }

    /// Checks a real-valued expression used at `place`.
    pub(super) fn func(&mut self, e: &Expr, place: Place) {
        match &e.kind {
            ExprKind::Number(_) | ExprKind::Pi => {}
            ExprKind::Name(id) => self.func_name(id, place),
            ExprKind::Identity | ExprKind::Integral { .. } => {
                let what = if matches!(e.kind, ExprKind::Identity) {
                    "the identity `id`"
                } else {
                    "an integral"
                };
                self.err(LangError::new(
                    ErrorKind::WrongSort,
                    format!("{what} cannot appear inside {}", place.what()),
                    e.span,
                    "not allowed here",
                ));
            }
            ExprKind::Call(f, arg) => {
                if Func::from_name(&f.name).is_some() {
                    self.func(arg, place);
                } else if self.is_unknown(&f.name) {
                    self.unknown_misplaced(f, place);
                } else {
                    self.err(
                        LangError::new(
                            ErrorKind::Undeclared,
                            format!("unknown function `{}`", f.name),
                            f.span,
                            "not a function",
                        )
                        .with_help(format!("the functions are {}", function_list())),
                    );
                }
            }
            ExprKind::Neg(a) => self.func(a, place),
            ExprKind::Binary(op, a, b) => {
                self.func(a, place);
                let before = self.errors.len();
                self.func(b, place);
                if *op == BinOp::Div && self.errors.len() == before {
                    self.nonzero_divisor(b);
                }
            }
        }
    }

    /// Reports a divisor that is a rational constant equal to zero.
    fn nonzero_divisor(&mut self, b: &Expr) {
        if self.scope.is_rational_const(b)
            && let Some(v) = self.constant(b)
            && v.is_zero()
        {
            self.err(division_by_zero(b.span));
        }
    }

    fn func_name(&mut self, id: &Ident, place: Place) {
        if let Some(v) = variable(&id.name) {
            if !place.allows(v) {
                let msg = match place {
                    Place::Weight(w) => format!(
                        "this integral runs over {0} (`d{0}`), so `{1}` cannot appear in it",
                        var_name(w),
                        id.name
                    ),
                    Place::OutputConst => format!(
                        "an output is a number: `{}` may only appear inside an integral",
                        id.name
                    ),
                    _ => format!(
                        "`{}` is the integration variable and may only appear inside `int(…) … dt`",
                        id.name
                    ),
                };
                self.err(LangError::new(
                    ErrorKind::BadVariable,
                    msg,
                    id.span,
                    format!("`{}` not available here", id.name),
                ));
            }
            return;
        }
        match self.scope.get(&id.name) {
            Some(Entry {
                sort: Sort::Param(i),
                ..
            }) => {
                // A real parameter that uses a scalar may stand in a
                // right side (the split solver evaluates it per scalar).
                let allowed = (self.scope.real_def(i).is_some()
                    && matches!(place, Place::Rhs | Place::Weight(_) | Place::OutputConst))
                    || place == Place::Rhs;
                if self.scope.is_real_param(i) && !allowed {
                    self.err(
                        LangError::new(
                            ErrorKind::WrongSort,
                            format!(
                                "`{}` is a real (not exactly rational) parameter; it cannot appear inside {} yet",
                                id.name,
                                place.what()
                            ),
                            id.span,
                            "real parameter",
                        )
                        .with_help("kernels and multipliers take exact parameters; real ones (that use no scalar) may stand in right sides and outputs too"),
                    );
                }
            }
            Some(Entry {
                sort: Sort::Unknown(_),
                ..
            }) => self.unknown_misplaced(id, place),
            // An unknown scalar may stand in a right side.
            Some(Entry {
                sort: Sort::Scalar(_),
                ..
            }) if place == Place::Rhs => {}
            Some(en) => self.err(
                LangError::new(
                    ErrorKind::WrongSort,
                    format!(
                        "`{}` is {}; it cannot appear inside {}",
                        id.name,
                        en.sort.word(),
                        place.what()
                    ),
                    id.span,
                    format!("{} here", en.sort.word()),
                )
                .with_related(en.span, "declared here"),
            ),
            None => self.err(
                LangError::new(
                    ErrorKind::Undeclared,
                    format!("undeclared name `{}`", id.name),
                    id.span,
                    "not declared",
                )
                .with_help(format!(
                    "{} may use {}parameters, numbers, pi and the functions {}",
                    place.what(),
                    place.variables(),
                    function_list()
                )),
            ),
        }
    }

    fn unknown_misplaced(&mut self, id: &Ident, place: Place) {
        let (msg, help) = match place {
            Place::Kernel => (
                format!("the unknown `{}` cannot appear inside a kernel", id.name),
                "a kernel describes the operator; the operator is applied to unknowns in equations, e.g. `k1 p`",
            ),
            Place::Rhs => (
                format!("the unknown `{}` cannot appear on the right side", id.name),
                "move every term with an unknown to the left side",
            ),
            Place::Multiplier => (
                format!(
                    "the unknown `{}` cannot appear in an operator definition",
                    id.name
                ),
                "operators are applied to unknowns in equations, e.g. `k1 p`",
            ),
            Place::Weight(_) | Place::OutputConst => (
                format!("the unknown `{}` is used non-linearly", id.name),
                "an output must be linear in the unknowns, e.g. `int(0..1) x*p(x) dx`",
            ),
        };
        self.err(
            LangError::new(
                ErrorKind::NonLinear,
                msg,
                id.span,
                "unknown not allowed here",
            )
            .with_help(help),
        );
    }

    /// An operator's integration limit: `x`, an exact constant or a real
    /// expression of the scalars.
    fn op_limit(&mut self, e: &Expr) {
        if let ExprKind::Name(id) = &e.kind
            && id.name == "x"
        {
            return;
        }
        if self.mentions_variable(e) {
            self.err(
                LangError::new(
                    ErrorKind::BadVariable,
                    "an integration limit must be `x` or a constant",
                    e.span,
                    "not `x` or a constant",
                )
                .with_help("write e.g. `x..1`, `0..x` or `0..1`"),
            );
            return;
        }
        if !self.moving_limit(e) {
            self.constant(e);
        }
    }

    /// An integration limit that uses an unknown scalar (`int(x..a)`,
    /// `int(0..a) … dx`): a real expression, remembered so that the file
    /// is checked to declare the unknowns' interval. `false` when `e`
    /// uses no scalar (then it must be an exact constant).
    fn moving_limit(&mut self, e: &Expr) -> bool {
        if !self.uses_scalar(e) {
            return false;
        }
        if self.real_expr(e, false) {
            self.moving_limits.push(e.span);
        }
        true
    }

    /// An output's integration limit: an exact constant or a real
    /// expression of the scalars.
    fn output_limit(&mut self, e: &Expr) {
        if self.mentions_variable(e) {
            self.err(LangError::new(
                ErrorKind::BadVariable,
                "the limits of an output's integral must be constants",
                e.span,
                "not a constant",
            ));
            return;
        }
        if !self.moving_limit(e) {
            self.constant(e);
        }
    }

    fn mentions_variable(&self, e: &Expr) -> bool {
        match &e.kind {
            ExprKind::Name(id) => variable(&id.name).is_some(),
            ExprKind::Neg(a) | ExprKind::Call(_, a) => self.mentions_variable(a),
            ExprKind::Binary(_, a, b) => self.mentions_variable(a) || self.mentions_variable(b),
            _ => false,
        }
    }

    /// Checks an operator definition: a linear combination of `id` and
    /// integrals over t, with functions of x as factors.
    pub(super) fn operator_body(&mut self, e: &Expr) {
        match &e.kind {
            ExprKind::Identity => {}
            ExprKind::Integral {
                lower,
                upper,
                integrand,
                var,
                var_span,
                ..
            } => {
                if *var == IntVar::X {
                    self.err(
                        LangError::new(
                            ErrorKind::BadVariable,
                            "an operator integrates over t: close the integral with `dt`",
                            *var_span,
                            "should be `dt`",
                        )
                        .with_help("x is the output variable, t the integration variable"),
                    );
                }
                self.op_limit(lower);
                self.op_limit(upper);
                if let Some(k) = integrand {
                    self.func(k, Place::Kernel);
                }
            }
            ExprKind::Neg(a) => self.operator_body(a),
            ExprKind::Binary(BinOp::Add | BinOp::Sub, a, b) => {
                for side in [a, b] {
                    if contains_operator(side) {
                        self.operator_body(side);
                    } else {
                        self.err(
                            LangError::new(
                                ErrorKind::WrongSort,
                                "this is a function, not an operator term",
                                side.span,
                                "not an operator",
                            )
                            .with_help(
                                "to add a multiple of the identity write e.g. `2*id` or `x*id`",
                            ),
                        );
                    }
                }
            }
            ExprKind::Binary(BinOp::Mul, a, b) => {
                match (contains_operator(a), contains_operator(b)) {
                    (true, true) => self.err(
                        LangError::new(
                            ErrorKind::NonLinear,
                            "a product of two operators cannot be defined directly",
                            e.span,
                            "operator times operator",
                        )
                        .with_help(
                            "define each operator and multiply them in an equation, e.g. `k1*k2 p`",
                        ),
                    ),
                    (true, false) => {
                        self.operator_body(a);
                        self.func(b, Place::Multiplier);
                    }
                    (false, true) => {
                        self.func(a, Place::Multiplier);
                        self.operator_body(b);
                    }
                    (false, false) => self.not_an_operator(e),
                }
            }
            ExprKind::Binary(BinOp::Div, a, b) => {
                if contains_operator(b) {
                    self.err(LangError::new(
                        ErrorKind::WrongSort,
                        "cannot divide by an operator",
                        b.span,
                        "an operator",
                    ));
                } else if contains_operator(a) {
                    self.operator_body(a);
                    let before = self.errors.len();
                    self.func(b, Place::Multiplier);
                    if self.errors.len() == before {
                        self.nonzero_divisor(b);
                    }
                } else {
                    self.not_an_operator(e);
                }
            }
            ExprKind::Binary(BinOp::Pow, _, _) if contains_operator(e) => self.err(
                LangError::new(
                    ErrorKind::WrongSort,
                    "powers of operators cannot be defined directly",
                    e.span,
                    "operator power",
                )
                .with_help("use a power in an equation instead, e.g. `k1^2 p`"),
            ),
            ExprKind::Name(id)
                if matches!(
                    self.scope.get(&id.name),
                    Some(Entry {
                        sort: Sort::Symbol(_),
                        ..
                    })
                ) =>
            {
                self.err(
                    LangError::new(
                        ErrorKind::WrongSort,
                        format!(
                            "an operator definition cannot refer to another operator (`{}`)",
                            id.name
                        ),
                        id.span,
                        "an operator symbol",
                    )
                    .with_help("combine operators in the equations instead, e.g. `(k1 + k2) p`"),
                )
            }
            _ => self.not_an_operator(e),
        }
    }

    fn not_an_operator(&mut self, e: &Expr) {
        self.err(
            LangError::new(
                ErrorKind::WrongSort,
                "an operator must be built from `id` and integrals `int(a..b) … dt`",
                e.span,
                "not an operator",
            )
            .with_help("e.g. `int(x..1) t/sqrt(t^2 - x^2) dt`, `2*id` or `x^2*id`"),
        );
    }

    /// Checks one equation.
    pub(super) fn equation(&mut self, lhs: &[LhsTerm], rhs: &Expr) {
        for term in lhs {
            self.lhs_term(term);
        }
        self.func(rhs, Place::Rhs);
    }

    fn lhs_term(&mut self, term: &LhsTerm) {
        let (product, unknown) = split_term(term);
        let explicit = term.unknown.is_some();
        let Some(u) = unknown else {
            self.no_unknown(term);
            return;
        };
        match self.scope.get(&u.name) {
            Some(Entry {
                sort: Sort::Unknown(_),
                ..
            }) => {}
            Some(en) if explicit => self.err(
                LangError::new(
                    ErrorKind::WrongSort,
                    format!("`{}` is {}, not an unknown", u.name, en.sort.word()),
                    u.span,
                    "not an unknown",
                )
                .with_related(en.span, "declared here"),
            ),
            Some(_) => {
                self.no_unknown(term);
                return;
            }
            None if !explicit && variable(&u.name).is_some() => {
                self.no_unknown(term);
                return;
            }
            None => self.err(
                LangError::new(
                    ErrorKind::Undeclared,
                    format!("undeclared unknown `{}`", u.name),
                    u.span,
                    "not declared",
                )
                .with_help(format!("declare it with `unknown {}`", u.name)),
            ),
        }
        if let Some(p) = product {
            let size = self.poly(p, PolyCtx::Operator);
            if size.degree > MAX_DEGREE {
                self.err(LangError::new(
                    ErrorKind::BadExponent,
                    format!(
                        "this operator product can reach degree {}, more than the limit {MAX_DEGREE}",
                        size.degree
                    ),
                    p.span,
                    "degree too high",
                ));
            }
        }
    }

    /// Reports a term without an unknown in last place: either the unknown
    /// is elsewhere in it, or there is none.
    fn no_unknown(&mut self, term: &LhsTerm) {
        match self.first_unknown(&term.product) {
            Some(id) => self.err(
                LangError::new(
                    ErrorKind::NonLinear,
                    format!(
                        "the unknown `{}` must come last in its term, after the operators applied to it",
                        id.name
                    ),
                    id.span,
                    "not last",
                )
                .with_help("write e.g. `k1*k2 p` or `k1*k2*p`"),
            ),
            None => self.err(
                LangError::new(
                    ErrorKind::NonLinear,
                    "this term applies no operator to an unknown",
                    term.span,
                    "no unknown",
                )
                .with_help("write e.g. `k1 p` (operator k1 applied to the unknown p)"),
            ),
        }
    }

    /// `solve for p`: `p` must be an unknown.
    pub(super) fn solve_target(&mut self, id: &Ident) {
        self.unknown_ref(id);
    }

    /// A name that must refer to an unknown (`solve for p`, relations,
    /// singular declarations).
    pub(super) fn unknown_ref(&mut self, id: &Ident) {
        match self.scope.get(&id.name) {
            Some(Entry {
                sort: Sort::Unknown(_),
                ..
            }) => {}
            Some(en) => self.err(
                LangError::new(
                    ErrorKind::WrongSort,
                    format!("`{}` is {}, not an unknown", id.name, en.sort.word()),
                    id.span,
                    "not an unknown",
                )
                .with_related(en.span, "declared here"),
            ),
            None => self.err(
                LangError::new(
                    ErrorKind::Undeclared,
                    format!("undeclared unknown `{}`", id.name),
                    id.span,
                    "not declared",
                )
                .with_help(format!("declare it with `unknown {}`", id.name)),
            ),
        }
    }

    /// Checks an output: constants plus constant multiples of integrals of
    /// a weight times one unknown.
    pub(super) fn output_body(&mut self, e: &Expr) {
        match &e.kind {
            ExprKind::Integral {
                lower,
                upper,
                integrand,
                var,
                ..
            } => {
                self.output_limit(lower);
                self.output_limit(upper);
                match integrand {
                    Some(i) => self.output_integrand(i, *var),
                    None => self.err(
                        LangError::new(
                            ErrorKind::NonLinear,
                            "this integral has no unknown in its integrand",
                            e.span,
                            "no unknown",
                        )
                        .with_help("write e.g. `int(0..1) x*p(x) dx`"),
                    ),
                }
            }
            ExprKind::Call(f, arg) if self.is_unknown(&f.name) => {
                if self.mentions_variable(arg) {
                    self.err(
                        LangError::new(
                            ErrorKind::BadVariable,
                            format!(
                                "a point value `{}(…)` in an output or condition must be taken at a constant",
                                f.name
                            ),
                            arg.span,
                            "not a constant",
                        )
                        .with_help(format!(
                            "write e.g. `{0}(1/2)`, or integrate: `int(0..1) {0}(x) dx`",
                            f.name
                        )),
                    );
                } else if !self.moving_limit(arg) {
                    self.constant(arg);
                }
            }
            ExprKind::Neg(a) => self.output_body(a),
            ExprKind::Binary(BinOp::Add | BinOp::Sub, a, b) => {
                for side in [a, b] {
                    self.output_part(side);
                }
            }
            ExprKind::Binary(op @ (BinOp::Mul | BinOp::Div), a, b) => {
                match (
                    contains_functional(a, &self.scope),
                    contains_functional(b, &self.scope),
                ) {
                    (true, true) => self.err(LangError::new(
                        ErrorKind::NonLinear,
                        "a product or quotient of two integrals is not linear in the unknowns",
                        e.span,
                        "not linear",
                    )),
                    (false, true) if *op == BinOp::Div => self.err(LangError::new(
                        ErrorKind::NonLinear,
                        "dividing by an integral is not linear in the unknowns",
                        b.span,
                        "not linear",
                    )),
                    (true, false) => {
                        self.output_body(a);
                        self.func(b, Place::OutputConst);
                        if *op == BinOp::Div {
                            self.nonzero_divisor(b);
                        }
                    }
                    (false, true) => {
                        self.func(a, Place::OutputConst);
                        self.output_body(b);
                    }
                    (false, false) => self.func(e, Place::OutputConst),
                }
            }
            _ => self.func(e, Place::OutputConst),
        }
    }

    /// The value of a side condition: a constant.
    pub(super) fn side_value(&mut self, e: &Expr) {
        if contains_functional(e, &self.scope) {
            self.err(
                LangError::new(
                    ErrorKind::NonLinear,
                    "the right side of a side condition must be a constant",
                    e.span,
                    "uses an unknown",
                )
                .with_help("move every term with an unknown to the left: `condition int(-1..1) f(t) dt - f(0) = 1`"),
            );
        } else {
            self.func(e, Place::OutputConst);
        }
    }

    fn output_part(&mut self, e: &Expr) {
        if contains_functional(e, &self.scope) {
            self.output_body(e);
        } else {
            self.func(e, Place::OutputConst);
        }
    }

    fn output_integrand(&mut self, e: &Expr, var: IntVar) {
        match &e.kind {
            ExprKind::Binary(BinOp::Add | BinOp::Sub, a, b) => {
                self.output_integrand(a, var);
                self.output_integrand(b, var);
            }
            ExprKind::Neg(a) => self.output_integrand(a, var),
            _ => match self.count_unknowns(e) {
                0 => self.err(
                    LangError::new(
                        ErrorKind::NonLinear,
                        "this part of the integrand contains no unknown",
                        e.span,
                        "no unknown",
                    )
                    .with_help("an output must be linear in the unknowns; put constants outside the integral"),
                ),
                1 => self.weighted_unknown(e, var),
                _ => self.err(LangError::new(
                    ErrorKind::NonLinear,
                    "unknowns are multiplied together: an output must be linear in the unknowns",
                    e.span,
                    "not linear",
                )),
            },
        }
    }

    /// A product containing exactly one unknown, evaluated at `var`.
    fn weighted_unknown(&mut self, e: &Expr, var: IntVar) {
        match &e.kind {
            ExprKind::Call(f, arg) if self.is_unknown(&f.name) => {
                let ok = matches!(&arg.kind, ExprKind::Name(id) if variable(&id.name) == Some(var));
                if !ok {
                    self.err(
                        LangError::new(
                            ErrorKind::BadVariable,
                            format!(
                                "`{}` must be evaluated at the integration variable `{}`",
                                f.name,
                                var_name(var)
                            ),
                            arg.span,
                            format!("should be `{}`", var_name(var)),
                        )
                        .with_help(format!(
                            "write `{}({})`",
                            f.name,
                            var_name(var)
                        )),
                    );
                }
            }
            ExprKind::Name(id) if self.is_unknown(&id.name) => self.err(LangError::new(
                ErrorKind::NonLinear,
                format!(
                    "write the unknown as a function: `{}({})`",
                    id.name,
                    var_name(var)
                ),
                id.span,
                "missing argument",
            )),
            ExprKind::Neg(a) => self.weighted_unknown(a, var),
            ExprKind::Binary(BinOp::Mul, a, b) => {
                if self.count_unknowns(a) == 1 {
                    self.weighted_unknown(a, var);
                    self.func(b, Place::Weight(var));
                } else {
                    self.func(a, Place::Weight(var));
                    self.weighted_unknown(b, var);
                }
            }
            ExprKind::Binary(BinOp::Div, a, b) if self.count_unknowns(a) == 1 => {
                self.weighted_unknown(a, var);
                let before = self.errors.len();
                self.func(b, Place::Weight(var));
                if self.errors.len() == before {
                    self.nonzero_divisor(b);
                }
            }
            _ => {
                if let Some(id) = self.first_unknown(e) {
                    let id = id.clone();
                    self.unknown_misplaced(&id, Place::Weight(var));
                }
            }
        }
    }

    /// The system must have as many equations as unknowns.
    pub(super) fn square(&mut self, file: &File) {
        let equations: Vec<_> = file
            .statements
            .iter()
            .filter(|s| matches!(s.kind, Stmt::Equation { .. }))
            .collect();
        let unknowns = self.scope.unknowns.len();
        if equations.len() == unknowns {
            return;
        }
        let first_unknown_decl = file
            .statements
            .iter()
            .find(|s| matches!(s.kind, Stmt::Unknown(..)));
        let at = first_unknown_decl
            .or(equations.first().copied())
            .map(|s| s.span);
        let Some(at) = at else { return };
        let mut e = LangError::new(
            ErrorKind::NotSquare,
            format!(
                "the system is not square: {} equation{} for {} unknown{}",
                equations.len(),
                if equations.len() == 1 { "" } else { "s" },
                unknowns,
                if unknowns == 1 { "" } else { "s" }
            ),
            at,
            format!("{unknowns} unknown{}", if unknowns == 1 { "" } else { "s" }),
        )
        .with_help("write exactly one equation per unknown");
        for extra in equations.iter().skip(unknowns) {
            e = e.with_related(extra.span, "extra equation");
        }
        self.err(e);
    }
}

/// Whether `e` contains an integral.
/// The function names, for messages: `sqrt, ln, …, tanh`.
pub(super) fn function_list() -> String {
    crate::system::expr::FUNCS
        .iter()
        .map(|f| f.name())
        .collect::<Vec<_>>()
        .join(", ")
}

/// Whether `condition lhs = …` is a side condition of the unknowns
/// (`condition int(-1..1) f(t) dt = 1`, `condition p(0) = 0`) rather than
/// one fixing a singular coefficient of a split problem (`condition B = 0`).
pub(crate) fn is_side_condition(lhs: &Expr, scope: &Scope) -> bool {
    contains_functional(lhs, scope)
}

/// Whether `e` contains a term of a functional: an integral or a point
/// value `p(c)` of an unknown.
pub(super) fn contains_functional(e: &Expr, scope: &Scope) -> bool {
    match &e.kind {
        ExprKind::Integral { .. } => true,
        ExprKind::Call(f, _)
            if matches!(
                scope.get(&f.name),
                Some(Entry {
                    sort: Sort::Unknown(_),
                    ..
                })
            ) =>
        {
            true
        }
        ExprKind::Neg(a) | ExprKind::Call(_, a) => contains_functional(a, scope),
        ExprKind::Binary(_, a, b) => contains_functional(a, scope) || contains_functional(b, scope),
        _ => false,
    }
}
