//! Meaning checks on the spanned AST. The validator walks the whole file and
//! collects *every* error (undeclared or duplicate names, division by zero or
//! by a non-constant, bad exponents, ragged rows, unknown matrices, a bad
//! principal symbol, …), each with the span to point at, and builds the
//! [`Scope`] the lowering needs (including the exact values of parameters).
//! It never panics and never formats positions; it must not build
//! polynomials (that is `lower.rs`).

use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};

use super::ast::{BinOp, Expr, ExprKind, File, Ident, Span, Stmt};
use super::error::{ErrorKind, LangError};
use super::scope::{Entry, Scope, Sort};

/// Largest exponent accepted in a polynomial or a constant.
pub const MAX_EXPONENT: u32 = 1000;
/// Largest total degree an entry may reach.
pub const MAX_DEGREE: u64 = 1000;
/// Largest size, in bits, of a number an entry or constant may reach.
pub const MAX_BITS: u64 = 1 << 20;

/// The outcome of validation: the name table, ready for lowering.
#[derive(Debug)]
pub struct Validated {
    /// Every declared name with its index and, for parameters, its value.
    pub scope: Scope,
}

/// Checks `file` and returns its scope, or every error found.
pub fn validate(file: &File) -> Result<Validated, Vec<LangError>> {
    let mut v = Validator {
        scope: Scope::default(),
        errors: Vec::new(),
        processed_params: Vec::new(),
        matrix_shapes: Vec::new(),
        moving_limits: Vec::new(),
    };
    v.declarations(file);
    v.parameters(file);
    v.bodies(file);
    if v.errors.is_empty() {
        Ok(Validated { scope: v.scope })
    } else {
        v.errors.sort_by_key(|e| (e.span.start, e.span.end));
        Err(v.errors)
    }
}

/// Upper bounds on the size of a polynomial expression.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Size {
    pub(super) degree: u64,
    pub(super) bits: u64,
}

/// Where a polynomial expression appears, for the wording of errors.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum PolyCtx {
    /// A matrix entry.
    Entry,
    /// The operator product of an equation term.
    Operator,
}

pub(super) struct Validator {
    pub(super) scope: Scope,
    pub(super) errors: Vec<LangError>,
    /// `processed_params[i]`: parameter `i`'s definition has been evaluated.
    processed_params: Vec<bool>,
    /// `matrix_shapes[i]`: rows and columns (of the first row) of matrix `i`.
    matrix_shapes: Vec<(usize, usize)>,
    /// Integration limits that use an unknown scalar (they need the
    /// unknowns' interval declared).
    pub(super) moving_limits: Vec<Span>,
}

fn duplicate(what: &str, id: &Ident, first: Entry) -> LangError {
    LangError::new(
        ErrorKind::Duplicate,
        format!("`{}` is defined more than once", id.name),
        id.span,
        format!("{what} `{}` defined again here", id.name),
    )
    .with_related(
        first.span,
        format!("first defined here as {}", first.sort.word()),
    )
    .with_help("every name may be declared only once; rename one of them")
}

fn bits_of(q: &BigRational) -> u64 {
    q.numer().bits().max(q.denom().bits())
}

impl Validator {
    pub(super) fn err(&mut self, e: LangError) {
        self.errors.push(e);
    }

    /// Pass 1: every declaration, so that later references may come before
    /// or after the declaration.
    fn declarations(&mut self, file: &File) {
        for st in &file.statements {
            match &st.kind {
                Stmt::Var(names) => {
                    for id in names {
                        if let Err(first) = self.scope.declare_symbol(&id.name, id.span) {
                            self.err(duplicate("symbol", id, first));
                        }
                    }
                }
                Stmt::Matrix { name, rows, .. } => {
                    match self.scope.declare_matrix(&name.name, name.span) {
                        Ok(_) => self
                            .matrix_shapes
                            .push((rows.len(), rows.first().map_or(0, |r| r.entries.len()))),
                        Err(first) => self.err(duplicate("matrix", name, first)),
                    }
                }
                Stmt::Param { name, .. } => {
                    self.not_reserved(name, "a parameter");
                    if let Err(first) = self.scope.declare_param(&name.name, name.span) {
                        self.err(duplicate("parameter", name, first));
                    }
                }
                Stmt::Unknown(names, _) => {
                    for id in names {
                        self.not_reserved(id, "an unknown");
                        if let Err(first) = self.scope.declare_unknown(&id.name, id.span) {
                            self.err(duplicate("unknown", id, first));
                        }
                    }
                }
                Stmt::Operator { name, .. } => {
                    self.not_reserved(name, "an operator");
                    if let Err(first) = self.scope.declare_symbol(&name.name, name.span) {
                        self.err(duplicate("operator", name, first));
                    }
                }
                Stmt::Output { name, .. } => {
                    self.not_reserved(name, "an output");
                    if let Err(first) = self.scope.declare_output(&name.name, name.span) {
                        self.err(duplicate("output", name, first));
                    }
                }
                Stmt::Scalar { name, .. } => {
                    self.not_reserved(name, "a scalar");
                    if let Err(first) = self.scope.declare_scalar(&name.name, name.span) {
                        self.err(duplicate("scalar", name, first));
                    }
                }
                Stmt::Singular { body, .. } => {
                    let terms = super::validate_contact::coefficient_terms(body);
                    for (id, _) in terms.into_iter().flatten() {
                        if self.scope.get(&id.name).is_none() {
                            self.not_reserved(&id, "a coefficient");
                            let _ = self.scope.declare_coefficient(&id.name, id.span);
                        }
                    }
                }
                _ => {}
            }
        }
    }

    /// Pass 2: parameter values, in source order (a parameter may only use
    /// parameters defined before it).
    fn parameters(&mut self, file: &File) {
        for st in &file.statements {
            if let Stmt::Param { name, value } = &st.kind {
                // A value that is not an exact rational but a valid real
                // expression (functions, scalars, real parameters) makes a
                // real parameter: its errors as a rational are dropped.
                let before = self.errors.len();
                let val = self.constant(value);
                let mut real = false;
                if val.is_none() && self.errors.len() > before && self.needs_real(value) {
                    let exact_errors = self.errors.split_off(before);
                    if self.real_expr(value, false) {
                        real = true;
                    } else {
                        self.errors.truncate(before);
                        self.errors.extend(exact_errors);
                    }
                }
                if let Some(Entry {
                    sort: Sort::Param(i),
                    span,
                }) = self.scope.get(&name.name)
                {
                    // Only the first definition of a duplicated name counts.
                    if span == name.span {
                        if let Some(slot) = self.scope.params.get_mut(i) {
                            slot.1 = val;
                        }
                        if self.scope.real_params.len() <= i {
                            self.scope.real_params.resize(i + 1, false);
                        }
                        self.scope.real_params[i] = real;
                        if self.scope.real_defs.len() <= i {
                            self.scope.real_defs.resize(i + 1, None);
                        }
                        self.scope.real_defs[i] =
                            (real && !self.uses_scalar(value)).then(|| value.clone());
                        if self.processed_params.len() <= i {
                            self.processed_params.resize(i + 1, false);
                        }
                        self.processed_params[i] = true;
                    }
                }
            }
        }
    }

    /// Pass 3: everything that refers to declarations.
    fn bodies(&mut self, file: &File) {
        let mut principal: Option<Span> = None;
        for st in &file.statements {
            match &st.kind {
                Stmt::Principal(id) => {
                    if let Some(first) = principal {
                        self.err(
                            LangError::new(
                                ErrorKind::BadPrincipal,
                                "the principal symbol is given more than once",
                                id.span,
                                "second `principal`",
                            )
                            .with_related(first, "first given here"),
                        );
                    } else {
                        principal = Some(id.span);
                    }
                    match self.scope.get(&id.name) {
                        Some(Entry {
                            sort: Sort::Symbol(_),
                            ..
                        }) => {}
                        Some(e) => self.err(
                            LangError::new(
                                ErrorKind::BadPrincipal,
                                format!(
                                    "the principal symbol must be a symbol, but `{}` is {}",
                                    id.name,
                                    e.sort.word()
                                ),
                                id.span,
                                "not a symbol",
                            )
                            .with_related(e.span, "declared here"),
                        ),
                        None => self.err(
                            LangError::new(
                                ErrorKind::BadPrincipal,
                                format!("the principal symbol `{}` is not declared", id.name),
                                id.span,
                                "not declared",
                            )
                            .with_help(format!(
                                "declare it first, e.g. `var {}`{}",
                                id.name,
                                self.symbol_list()
                            )),
                        ),
                    }
                }
                Stmt::Matrix { rows, .. } => {
                    let first_len = rows.first().map(|r| r.entries.len());
                    for (i, row) in rows.iter().enumerate() {
                        if let (Some(n), Some(first)) = (first_len, rows.first())
                            && row.entries.len() != n
                        {
                            self.err(
                                LangError::new(
                                    ErrorKind::RaggedRows,
                                    format!(
                                        "row {} has {}, but row 1 has {}",
                                        i + 1,
                                        entries(row.entries.len()),
                                        entries(n)
                                    ),
                                    row.span,
                                    entries(row.entries.len()),
                                )
                                .with_related(first.span, entries(n))
                                .with_help(
                                    "every row of a matrix needs the same number of entries",
                                ),
                            );
                        }
                        for e in &row.entries {
                            let size = self.poly(e, PolyCtx::Entry);
                            if size.degree > MAX_DEGREE {
                                self.err(LangError::new(
                                    ErrorKind::BadExponent,
                                    format!(
                                        "this entry can reach degree {}, more than the limit {MAX_DEGREE}",
                                        size.degree
                                    ),
                                    e.span,
                                    "degree too high",
                                ));
                            } else if size.bits > MAX_BITS {
                                self.err(LangError::new(
                                    ErrorKind::BadExponent,
                                    "this entry has numbers too large to handle".to_string(),
                                    e.span,
                                    "numbers too large",
                                ));
                            }
                        }
                    }
                }
                Stmt::Smith(id) => {
                    self.matrix_ref(id);
                }
                Stmt::CheckSmith { a, u, d, v } => {
                    let shapes: Vec<_> = [a, u, d, v]
                        .into_iter()
                        .filter_map(|id| self.matrix_ref(id))
                        .collect();
                    if let [a_shape, u_shape, d_shape, v_shape] = shapes[..] {
                        self.check_shapes(a_shape, [(u, u_shape), (d, d_shape), (v, v_shape)]);
                    }
                }
                Stmt::Operator { body, .. } => self.operator_body(body),
                Stmt::Equation { lhs, rhs, domain } => {
                    self.equation(lhs, rhs);
                    if let Some(d) = domain {
                        self.interval(d);
                    }
                }
                Stmt::Solve(id) => self.solve_target(id),
                Stmt::Output { body, .. } => self.output_body(body),
                Stmt::Unknown(_, Some(d)) => {
                    self.interval(d);
                    self.fixed_interval(d);
                }
                Stmt::Relation {
                    unknown,
                    value,
                    domain,
                } => self.relation(unknown, value, domain),
                Stmt::Inequality {
                    lhs,
                    ge,
                    rhs,
                    domain,
                } => self.inequality(lhs, *ge, rhs, domain),
                Stmt::Scalar {
                    range, estimate, ..
                } => {
                    self.scalar_range(range);
                    if let Some(e) = estimate {
                        self.scalar_estimate(e);
                    }
                }
                Stmt::Singular {
                    unknown, at, body, ..
                } => self.singular(unknown, at, body),
                Stmt::Condition { lhs, rhs } => self.condition(lhs, rhs),
                Stmt::Var(_) | Stmt::Param { .. } | Stmt::Unknown(_, None) => {}
            }
        }
        self.moving_limits_need_an_interval(file);
        self.square(file);
    }

    /// An integration limit that uses a scalar ends an integral inside the
    /// unknowns' interval, which must then be declared with constant ends
    /// (`unknown p on [0, 2]`).
    fn moving_limits_need_an_interval(&mut self, file: &File) {
        let declared = file.statements.iter().any(|st| {
            matches!(&st.kind, Stmt::Unknown(_, Some(d))
                if !self.uses_scalar(&d.lo) && !self.uses_scalar(&d.hi))
        });
        if declared {
            return;
        }
        for span in std::mem::take(&mut self.moving_limits) {
            self.err(
                LangError::new(
                    ErrorKind::WrongSort,
                    "an integration limit that uses an unknown scalar needs the unknowns' interval declared with constant ends",
                    span,
                    "uses a scalar",
                )
                .with_help("declare e.g. `unknown p on [0, 2]`, an interval that holds every value of the limit"),
            );
        }
    }

    pub(super) fn symbol_list(&self) -> String {
        if self.scope.symbols.is_empty() {
            String::new()
        } else {
            format!("; declared symbols: {}", self.scope.symbols.join(", "))
        }
    }

    /// Checks that U, D, V have the shapes U·A·V = D needs, given A's.
    fn check_shapes(&mut self, (m, n): (usize, usize), others: [(&Ident, (usize, usize)); 3]) {
        let want = [(m, m), (m, n), (n, n)];
        let role = [
            "U multiplies A on the left",
            "D = U·A·V has the shape of A",
            "V multiplies A on the right",
        ];
        for (((id, got), want), role) in others.into_iter().zip(want).zip(role) {
            if got != want {
                self.err(
                    LangError::new(
                        ErrorKind::Shape,
                        format!(
                            "`{}` is {}×{}, but it must be {}×{}: {role} and A is {m}×{n}",
                            id.name, got.0, got.1, want.0, want.1
                        ),
                        id.span,
                        format!("{}×{}", got.0, got.1),
                    )
                    .with_help("write `check smith A with U, D, V` for U·A·V = D"),
                );
            }
        }
    }

    /// Checks that `id` names a matrix; returns its shape.
    fn matrix_ref(&mut self, id: &Ident) -> Option<(usize, usize)> {
        match self.scope.get(&id.name) {
            Some(Entry {
                sort: Sort::Matrix(i),
                ..
            }) => self.matrix_shapes.get(i).copied(),
            other => {
                let mut e = LangError::new(
                    ErrorKind::UnknownMatrix,
                    match other {
                        Some(en) => format!("`{}` is {}, not a matrix", id.name, en.sort.word()),
                        None => format!("unknown matrix `{}`", id.name),
                    },
                    id.span,
                    "not a matrix",
                );
                e = e.with_help(if self.scope.matrices.is_empty() {
                    "no matrix is defined; define one with `matrix A = [ … ]`".to_string()
                } else {
                    format!("defined matrices: {}", self.scope.matrices.join(", "))
                });
                if let Some(en) = other {
                    e = e.with_related(en.span, "declared here");
                }
                self.err(e);
                None
            }
        }
    }

    /// Checks an exponent: a non-negative integer literal, not too large.
    fn exponent(&mut self, e: &Expr) -> Option<u32> {
        let bad = |msg: String, label: &str| {
            LangError::new(ErrorKind::BadExponent, msg, e.span, label)
                .with_help("exponents must be non-negative integer literals, as in `x^2`")
        };
        match &e.kind {
            ExprKind::Number(q) if q.is_integer() => match q.to_integer().to_u32() {
                Some(n) if n <= MAX_EXPONENT => Some(n),
                _ => {
                    self.err(bad(
                        format!("exponent {q} is too large (the limit is {MAX_EXPONENT})"),
                        "too large",
                    ));
                    None
                }
            },
            ExprKind::Number(q) => {
                self.err(bad(
                    format!("fractional exponent {q}: the result would not be a polynomial"),
                    "not an integer",
                ));
                None
            }
            ExprKind::Neg(_) => {
                self.err(bad(
                    "negative exponent: the result would not be a polynomial".to_string(),
                    "negative",
                ));
                None
            }
            ExprKind::Binary(BinOp::Div, _, _) => {
                self.err(bad(
                    "fractional exponent: the result would not be a polynomial".to_string(),
                    "not an integer",
                ));
                None
            }
            _ => {
                self.err(bad(
                    "the exponent must be a non-negative integer literal".to_string(),
                    "not an integer literal",
                ));
                None
            }
        }
    }

    /// Whether `e` mentions no symbol, unknown or variable, i.e. could be a
    /// constant (undeclared names count as possible constants so that they
    /// are reported as undeclared, not as "not constant").
    fn looks_constant(&self, e: &Expr) -> bool {
        match &e.kind {
            ExprKind::Number(_) | ExprKind::Pi => true,
            ExprKind::Name(id) => matches!(
                self.scope.get(&id.name),
                None | Some(Entry {
                    sort: Sort::Param(_),
                    ..
                })
            ),
            ExprKind::Identity | ExprKind::Integral { .. } => false,
            ExprKind::Neg(a) => self.looks_constant(a),
            ExprKind::Call(_, a) => self.looks_constant(a),
            ExprKind::Binary(_, a, b) => self.looks_constant(a) && self.looks_constant(b),
        }
    }

    /// Checks a polynomial expression and bounds its size.
    pub(super) fn poly(&mut self, e: &Expr, ctx: PolyCtx) -> Size {
        match &e.kind {
            ExprKind::Number(q) => Size {
                degree: 0,
                bits: bits_of(q),
            },
            ExprKind::Name(id) => match self.scope.get(&id.name) {
                Some(Entry {
                    sort: Sort::Symbol(_),
                    ..
                }) => Size { degree: 1, bits: 1 },
                Some(Entry {
                    sort: Sort::Param(i),
                    ..
                }) => {
                    if self.scope.is_real_param(i) {
                        self.err(
                            LangError::new(
                                ErrorKind::WrongSort,
                                format!(
                                    "`{}` is a real (not exactly rational) parameter, but an exact rational is needed here",
                                    id.name
                                ),
                                id.span,
                                "real parameter",
                            )
                            .with_help("the algebra takes exact parameters only"),
                        );
                    }
                    Size {
                        degree: 0,
                        bits: self.scope.param_value(i).map_or(1, bits_of),
                    }
                }
                Some(Entry {
                    sort: Sort::Unknown(_),
                    ..
                }) if ctx == PolyCtx::Operator => {
                    self.err(
                        LangError::new(
                            ErrorKind::NonLinear,
                            format!(
                                "the unknown `{}` is used non-linearly: each term applies operators to one unknown, written last",
                                id.name
                            ),
                            id.span,
                            "unknown used as a factor",
                        )
                        .with_help("write e.g. `k1 p + k2 q`"),
                    );
                    Size::default()
                }
                None if ctx == PolyCtx::Operator && (id.name == "x" || id.name == "t") => {
                    self.err(
                        LangError::new(
                            ErrorKind::BadVariable,
                            format!(
                                "`{}` cannot appear in the operator part of an equation",
                                id.name
                            ),
                            id.span,
                            "a variable, not an operator",
                        )
                        .with_help("to multiply by a function of x, define an operator such as `operator m = x*id`"),
                    );
                    Size::default()
                }
                Some(en) => {
                    self.err(
                        LangError::new(
                            ErrorKind::WrongSort,
                            format!(
                                "`{}` is {}; {} may only use symbols and parameters",
                                id.name,
                                en.sort.word(),
                                ctx.what()
                            ),
                            id.span,
                            format!("{} here", en.sort.word()),
                        )
                        .with_related(en.span, "declared here"),
                    );
                    Size::default()
                }
                None => {
                    let (what, help) = match ctx {
                        PolyCtx::Entry => ("symbol", format!("declare it with `var {}`", id.name)),
                        PolyCtx::Operator => (
                            "operator",
                            format!(
                                "define it with `operator {0} = …` or declare it with `var {0}`",
                                id.name
                            ),
                        ),
                    };
                    self.err(
                        LangError::new(
                            ErrorKind::Undeclared,
                            format!("undeclared {what} `{}`", id.name),
                            id.span,
                            "not declared",
                        )
                        .with_help(format!("{help}{}", self.symbol_list())),
                    );
                    Size::default()
                }
            },
            ExprKind::Pi => {
                self.err(LangError::new(
                    ErrorKind::NonPolynomial,
                    format!(
                        "`pi` is not rational; {} must have rational coefficients",
                        ctx.what()
                    ),
                    e.span,
                    "not rational",
                ));
                Size::default()
            }
            ExprKind::Identity | ExprKind::Integral { .. } => {
                self.err(LangError::new(
                    ErrorKind::WrongSort,
                    format!("operators are not allowed in {}", ctx.what()),
                    e.span,
                    "an operator",
                ));
                Size::default()
            }
            ExprKind::Call(f, _) => {
                self.err(
                    LangError::new(
                        ErrorKind::NonPolynomial,
                        format!(
                            "function calls are not allowed in {}: `{}(…)` is not a polynomial",
                            ctx.what(),
                            f.name
                        ),
                        e.span,
                        "not a polynomial",
                    )
                    .with_help("entries are built from numbers, symbols, + - * ^ and division by constants"),
                );
                Size::default()
            }
            ExprKind::Neg(a) => self.poly(a, ctx),
            ExprKind::Binary(op, a, b) => match op {
                BinOp::Add | BinOp::Sub => {
                    let (x, y) = (self.poly(a, ctx), self.poly(b, ctx));
                    Size {
                        degree: x.degree.max(y.degree),
                        bits: x.bits.max(y.bits).saturating_add(1),
                    }
                }
                BinOp::Mul => {
                    let (x, y) = (self.poly(a, ctx), self.poly(b, ctx));
                    Size {
                        degree: x.degree.saturating_add(y.degree),
                        bits: x.bits.saturating_add(y.bits),
                    }
                }
                BinOp::Div => {
                    let x = self.poly(a, ctx);
                    let bits = self.divisor(b, ctx).map_or(0, |q| bits_of(&q));
                    Size {
                        degree: x.degree,
                        bits: x.bits.saturating_add(bits),
                    }
                }
                BinOp::Pow => {
                    let x = self.poly(a, ctx);
                    let n = u64::from(self.exponent(b).unwrap_or(0));
                    Size {
                        degree: x.degree.saturating_mul(n),
                        bits: x.bits.saturating_mul(n),
                    }
                }
            },
        }
    }

    /// Checks a divisor in a polynomial context: a nonzero constant.
    fn divisor(&mut self, b: &Expr, ctx: PolyCtx) -> Option<BigRational> {
        if !self.looks_constant(b) {
            // Report undeclared names inside it first; then the real problem.
            let before = self.errors.len();
            self.poly(b, ctx);
            if self.errors.len() == before {
                self.err(
                    LangError::new(
                        ErrorKind::NonPolynomial,
                        format!(
                            "division by a non-constant: {} must be polynomials",
                            ctx.what()
                        ),
                        b.span,
                        "not a constant",
                    )
                    .with_help("divide only by nonzero numbers or parameters, e.g. `x/3`"),
                );
            }
            return None;
        }
        let q = self.constant(b)?;
        if q.is_zero() {
            self.err(division_by_zero(b.span));
            return None;
        }
        Some(q)
    }

    /// Evaluates a constant expression exactly (numbers, parameters defined
    /// so far, + - * /, integer powers), reporting every error.
    pub(super) fn constant(&mut self, e: &Expr) -> Option<BigRational> {
        match &e.kind {
            ExprKind::Number(q) => Some(q.clone()),
            ExprKind::Name(id) => match self.scope.get(&id.name) {
                Some(Entry {
                    sort: Sort::Param(i),
                    ..
                }) => {
                    let v = self.scope.param_value(i).cloned();
                    if self.scope.is_real_param(i) {
                        self.err(
                            LangError::new(
                                ErrorKind::WrongSort,
                                format!(
                                    "`{}` is a real (not exactly rational) parameter, but an exact rational is needed here",
                                    id.name
                                ),
                                id.span,
                                "real parameter",
                            )
                            .with_help("real parameters may be used in relations, singular declarations, conditions, intervals and other real parameters"),
                        );
                        return None;
                    }
                    if v.is_none() && !self.param_defined_with_error(i) {
                        self.err(
                            LangError::new(
                                ErrorKind::Undeclared,
                                format!("parameter `{}` is used before its definition", id.name),
                                id.span,
                                "not yet defined",
                            )
                            .with_help("define parameters before the parameters that use them"),
                        );
                    }
                    v
                }
                Some(en) => {
                    self.err(
                        LangError::new(
                            ErrorKind::WrongSort,
                            format!(
                                "`{}` is {}, but a constant is needed here",
                                id.name,
                                en.sort.word()
                            ),
                            id.span,
                            "not a constant",
                        )
                        .with_related(en.span, "declared here"),
                    );
                    None
                }
                None => {
                    self.err(
                        LangError::new(
                            ErrorKind::Undeclared,
                            format!("undeclared parameter `{}`", id.name),
                            id.span,
                            "not declared",
                        )
                        .with_help(format!("define it with `param {} = …`", id.name)),
                    );
                    None
                }
            },
            ExprKind::Pi | ExprKind::Call(..) | ExprKind::Identity | ExprKind::Integral { .. } => {
                self.err(
                    LangError::new(
                        ErrorKind::WrongSort,
                        "a constant here must be an exact rational",
                        e.span,
                        "not an exact rational",
                    )
                    .with_help("use numbers, parameters, + - * / and integer powers"),
                );
                None
            }
            ExprKind::Neg(a) => self.constant(a).map(|q| -q),
            ExprKind::Binary(op, a, b) => {
                let x = self.constant(a);
                let y = match op {
                    BinOp::Pow => None,
                    _ => self.constant(b),
                };
                match op {
                    BinOp::Add => Some(x? + y?),
                    BinOp::Sub => Some(x? - y?),
                    BinOp::Mul => {
                        let (x, y) = (x?, y?);
                        if bits_of(&x).saturating_add(bits_of(&y)) > MAX_BITS {
                            self.err(too_large(e.span));
                            return None;
                        }
                        Some(x * y)
                    }
                    BinOp::Div => {
                        let y = y?;
                        if y.is_zero() {
                            self.err(division_by_zero(b.span));
                            return None;
                        }
                        Some(x? / y)
                    }
                    BinOp::Pow => self.constant_power(e, x, b),
                }
            }
        }
    }

    /// `base^exp` for a constant base and an integer-literal exponent
    /// (negative allowed when the base is nonzero).
    fn constant_power(
        &mut self,
        whole: &Expr,
        base: Option<BigRational>,
        exp: &Expr,
    ) -> Option<BigRational> {
        let (negative, lit) = match &exp.kind {
            ExprKind::Neg(inner) => (true, inner.as_ref()),
            _ => (false, exp),
        };
        let n = match &lit.kind {
            ExprKind::Number(q) if q.is_integer() => q.to_integer().to_u32(),
            _ => {
                self.err(
                    LangError::new(
                        ErrorKind::BadExponent,
                        "the exponent of a constant must be an integer literal",
                        exp.span,
                        "not an integer literal",
                    )
                    .with_help("write e.g. `2^3` or `2^-1`"),
                );
                return None;
            }
        };
        let Some(n) = n.filter(|n| *n <= MAX_EXPONENT) else {
            self.err(LangError::new(
                ErrorKind::BadExponent,
                format!("exponent is too large (the limit is {MAX_EXPONENT})"),
                exp.span,
                "too large",
            ));
            return None;
        };
        let base = base?;
        if bits_of(&base).saturating_mul(u64::from(n)) > MAX_BITS {
            self.err(too_large(whole.span));
            return None;
        }
        let mut acc = BigRational::one();
        for _ in 0..n {
            acc *= &base;
        }
        if negative {
            if acc.is_zero() {
                self.err(division_by_zero(whole.span));
                return None;
            }
            acc = acc.recip();
        }
        Some(acc)
    }

    /// Whether parameter `i`'s definition was already evaluated, so that a
    /// missing value means an error there, already reported.
    pub(super) fn param_processed(&self, i: usize) -> bool {
        self.param_defined_with_error(i)
    }

    /// Whether parameter `i`'s definition was already evaluated (see
    /// [`Validator::param_processed`]).
    fn param_defined_with_error(&self, i: usize) -> bool {
        self.processed_params.get(i).copied().unwrap_or(false)
    }
}

impl PolyCtx {
    fn what(self) -> &'static str {
        match self {
            PolyCtx::Entry => "matrix entries",
            PolyCtx::Operator => "operator polynomials in equations",
        }
    }
}

/// "1 entry", "3 entries".
fn entries(n: usize) -> String {
    if n == 1 {
        "1 entry".to_string()
    } else {
        format!("{n} entries")
    }
}

pub(super) fn division_by_zero(span: Span) -> LangError {
    LangError::new(
        ErrorKind::DivisionByZero,
        "division by zero",
        span,
        "this is zero",
    )
}

fn too_large(span: Span) -> LangError {
    LangError::new(
        ErrorKind::BadExponent,
        format!("number too large (more than {MAX_BITS} bits)"),
        span,
        "too large",
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lang::parser::parse_file;

    fn kinds(src: &str) -> Vec<ErrorKind> {
        let file = parse_file(src).expect("parses");
        match validate(&file) {
            Ok(_) => Vec::new(),
            Err(errs) => errs.iter().map(|e| e.kind).collect(),
        }
    }

    #[test]
    fn parameters_are_evaluated_exactly_in_order() {
        let file =
            parse_file("param a = 2^-2\nparam b = (a + 1/4)*4\nparam c = -b^3").expect("parses");
        let v = validate(&file).expect("valid");
        let vals: Vec<String> = v
            .scope
            .params
            .iter()
            .map(|(n, q)| format!("{n}={}", q.as_ref().map_or("?".into(), |q| q.to_string())))
            .collect();
        assert_eq!(vals, ["a=1/4", "b=2", "c=-8"]);
    }

    #[test]
    fn errors_do_not_cascade() {
        // `a` is broken; using it later must not add a second error.
        assert_eq!(
            kinds("param a = 1/0\nparam b = a + 1\nvar x\nmatrix M = [x/a]"),
            [ErrorKind::DivisionByZero]
        );
    }

    #[test]
    fn huge_constants_are_refused() {
        assert_eq!(
            kinds("param a = 1000^1000\nparam b = a^1000"),
            [ErrorKind::BadExponent]
        );
        assert_eq!(kinds("param a = 0^-1"), [ErrorKind::DivisionByZero]);
    }
}
