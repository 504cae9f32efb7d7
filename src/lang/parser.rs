//! Source text → spanned AST ([`super::ast::File`]). Owns the pest parser generated
//! from `grammar/lambdamat.pest`, the Pratt parser that gives expressions
//! their precedence, and the translation of pest's failures into a
//! [`LangError`] that speaks about tokens in human words (never pest rule
//! names). It resolves no names and checks no meaning: that is the
//! validator's job. Positions stay byte spans; line:column is formatted only
//! by `diagnostics.rs`.

use std::collections::BTreeSet;
use std::sync::LazyLock;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};
use pest::Parser;
use pest::error::{ErrorVariant, InputLocation};
use pest::iterators::Pair;
use pest::pratt_parser::{Assoc, Op, PrattParser};

use super::ast::{
    BinOp, Expr, ExprKind, File, Ident, IntVar, Interval, LhsTerm, MatrixRow, Sign, Span,
    Statement, Stmt,
};
use super::error::{ErrorKind, LangError};
use super::keywords::{KEYWORDS, is_keyword};

/// The pest parser for the lambdamat grammar.
#[derive(pest_derive::Parser)]
#[grammar = "../grammar/lambdamat.pest"]
struct LmxParser;

/// Deepest bracket nesting accepted (protects the recursive-descent parser).
pub const MAX_NESTING: usize = 500;
/// Deepest expression tree accepted (protects every recursive pass); a sum
/// of n terms is n levels deep.
pub const MAX_DEPTH: usize = 20_000;
/// Most chained unary minus or `^` operators in one expression (these make
/// the Pratt parser recurse).
const MAX_RECURSIVE_OPS: usize = 5_000;

static PRATT: LazyLock<PrattParser<Rule>> = LazyLock::new(|| {
    PrattParser::new()
        .op(Op::infix(Rule::add, Assoc::Left) | Op::infix(Rule::sub, Assoc::Left))
        .op(Op::infix(Rule::mul, Assoc::Left) | Op::infix(Rule::div, Assoc::Left))
        .op(Op::prefix(Rule::neg))
        .op(Op::infix(Rule::pow, Assoc::Right))
});

/// Parses a whole file into its spanned AST, or returns the first syntax
/// error (a parser cannot usefully go on after one).
pub fn parse_file(src: &str) -> Result<File, LangError> {
    check_nesting(src)?;
    let mut pairs = match LmxParser::parse(Rule::program, src) {
        Ok(pairs) => pairs,
        Err(_) => {
            // Parse again with pest's token tracking on, which names the
            // expected punctuation. It is a process-wide switch that is only
            // ever turned on, so the second parse always has it; it costs
            // about twice the parsing time, so valid files do without it.
            pest::set_error_detail(true);
            return Err(match LmxParser::parse(Rule::program, src) {
                Err(e) => syntax_error(&e, src),
                Ok(_) => internal(Span::default(), "the parser changed its mind"),
            });
        }
    };
    let program = pairs
        .next()
        .ok_or_else(|| LangError::new(ErrorKind::Syntax, "empty parse", Span::default(), ""))?;
    let mut statements = Vec::new();
    for pair in program.into_inner() {
        if pair.as_rule() == Rule::EOI {
            break;
        }
        statements.push(statement(pair)?);
    }
    Ok(File { statements })
}

/// Parses one expression on its own (the `formula` rule): the syntax of a
/// printed formula, before any meaning is given to its names.
pub fn parse_formula(src: &str) -> Result<Expr, LangError> {
    check_nesting(src)?;
    let mut pairs = match LmxParser::parse(Rule::formula, src) {
        Ok(pairs) => pairs,
        Err(_) => {
            pest::set_error_detail(true);
            return Err(match LmxParser::parse(Rule::formula, src) {
                Err(e) => syntax_error(&e, src),
                Ok(_) => internal(Span::default(), "the parser changed its mind"),
            });
        }
    };
    let formula = pairs
        .next()
        .ok_or_else(|| internal(Span::default(), "empty formula"))?;
    let inner = formula
        .into_inner()
        .find(|p| p.as_rule() == Rule::expr)
        .ok_or_else(|| internal(Span::default(), "no expression"))?;
    expr(inner)
}

fn span_of(pair: &Pair<'_, Rule>) -> Span {
    let s = pair.as_span();
    Span::new(s.start(), s.end())
}

fn ident(pair: &Pair<'_, Rule>) -> Ident {
    Ident {
        name: pair.as_str().to_string(),
        span: span_of(pair),
    }
}

fn internal(span: Span, what: &str) -> LangError {
    LangError::new(
        ErrorKind::Syntax,
        format!("internal parser error: {what}"),
        span,
        "here",
    )
}

/// Takes the next inner pair or reports an internal error at `span`.
fn next<'i>(
    it: &mut impl Iterator<Item = Pair<'i, Rule>>,
    span: Span,
) -> Result<Pair<'i, Rule>, LangError> {
    it.next()
        .ok_or_else(|| internal(span, "missing part of a statement"))
}

/// The `name` children of a pair, as identifiers.
fn names(pair: Pair<'_, Rule>) -> Vec<Ident> {
    pair.into_inner()
        .filter(|p| p.as_rule() == Rule::name)
        .map(|p| ident(&p))
        .collect()
}

fn statement(pair: Pair<'_, Rule>) -> Result<Statement, LangError> {
    let span = span_of(&pair);
    let rule = pair.as_rule();
    let kind = match rule {
        Rule::var_decl => Stmt::Var(names(pair)),
        Rule::unknown_decl => {
            let mut domain = None;
            let mut ids = Vec::new();
            for p in pair.into_inner() {
                match p.as_rule() {
                    Rule::name => ids.push(ident(&p)),
                    Rule::domain => domain = Some(interval_of_domain(p, span)?),
                    _ => {}
                }
            }
            Stmt::Unknown(ids, domain)
        }
        Rule::relation_def => {
            let mut it = pair.into_inner().skip(1);
            let unknown = ident(&next(&mut it, span)?);
            let value = expr(next(&mut it, span)?)?;
            let domain = interval_of_domain(next(&mut it, span)?, span)?;
            Stmt::Relation {
                unknown,
                value,
                domain,
            }
        }
        Rule::inequality_def => {
            let mut it = pair.into_inner().skip(1);
            let lhs = expr(next(&mut it, span)?)?;
            let ge = next(&mut it, span)?.as_rule() == Rule::ge;
            let rhs = expr(next(&mut it, span)?)?;
            let domain = interval_of_domain(next(&mut it, span)?, span)?;
            Stmt::Inequality {
                lhs,
                ge,
                rhs,
                domain,
            }
        }
        Rule::scalar_decl => {
            let mut it = pair.into_inner().skip(1);
            let name = ident(&next(&mut it, span)?);
            let _kw_in = next(&mut it, span)?;
            let range = interval(next(&mut it, span)?, span)?;
            let estimate = it.next().map(expr).transpose()?;
            Stmt::Scalar {
                name,
                range,
                estimate,
            }
        }
        Rule::singular_decl => {
            let mut it = pair.into_inner().skip(1);
            let unknown = ident(&next(&mut it, span)?);
            let _kw_at = next(&mut it, span)?;
            let at = expr(next(&mut it, span)?)?;
            let mut p = next(&mut it, span)?;
            let mut side = 0;
            if p.as_rule() == Rule::side {
                side = if p.as_str() == "-" { -1 } else { 1 };
                p = next(&mut it, span)?;
            }
            let body = expr(p)?;
            Stmt::Singular {
                unknown,
                at,
                side,
                body,
            }
        }
        Rule::condition_def => {
            let mut it = pair.into_inner().skip(1);
            let lhs = expr(next(&mut it, span)?)?;
            let rhs = expr(next(&mut it, span)?)?;
            Stmt::Condition { lhs, rhs }
        }
        Rule::principal_decl | Rule::smith_cmd | Rule::solve_cmd => {
            let id = names(pair)
                .into_iter()
                .next()
                .ok_or_else(|| internal(span, "missing name"))?;
            match rule {
                Rule::principal_decl => Stmt::Principal(id),
                Rule::smith_cmd => Stmt::Smith(id),
                _ => Stmt::Solve(id),
            }
        }
        Rule::check_cmd => {
            let mut n = names(pair).into_iter();
            let mut take = || n.next().ok_or_else(|| internal(span, "missing name"));
            Stmt::CheckSmith {
                a: take()?,
                u: take()?,
                d: take()?,
                v: take()?,
            }
        }
        Rule::matrix_def => {
            let mut it = pair.into_inner().filter(|p| p.as_rule() != Rule::kw_matrix);
            let name = ident(&next(&mut it, span)?);
            let lit = next(&mut it, span)?;
            let lit_span = span_of(&lit);
            let mut rows = Vec::new();
            for row in lit.into_inner() {
                let row_span = span_of(&row);
                let entries = row.into_inner().map(expr).collect::<Result<Vec<_>, _>>()?;
                rows.push(MatrixRow {
                    entries,
                    span: row_span,
                });
            }
            Stmt::Matrix {
                name,
                rows,
                lit_span,
            }
        }
        Rule::param_def | Rule::operator_def | Rule::output_def => {
            let mut it = pair.into_inner().skip(1);
            let name = ident(&next(&mut it, span)?);
            let body = expr(next(&mut it, span)?)?;
            match rule {
                Rule::param_def => Stmt::Param { name, value: body },
                Rule::operator_def => Stmt::Operator { name, body },
                _ => Stmt::Output { name, body },
            }
        }
        Rule::equation => {
            let mut it = pair.into_inner().skip(1);
            let lhs = equation_lhs(next(&mut it, span)?)?;
            let rhs = expr(next(&mut it, span)?)?;
            let domain = match it.next() {
                Some(d) => Some(interval_of_domain(d, span)?),
                None => None,
            };
            Stmt::Equation { lhs, rhs, domain }
        }
        _ => return Err(internal(span, "unexpected statement")),
    };
    Ok(Statement { kind, span })
}

/// The interval of a `domain` pair (`on [a, b)`).
fn interval_of_domain(pair: Pair<'_, Rule>, span: Span) -> Result<Interval, LangError> {
    let mut it = pair.into_inner().skip(1);
    interval(next(&mut it, span)?, span)
}

/// An `interval` pair.
fn interval(pair: Pair<'_, Rule>, span: Span) -> Result<Interval, LangError> {
    let ispan = span_of(&pair);
    let mut it = pair.into_inner();
    let lo_closed = next(&mut it, span)?.as_rule() == Rule::lclosed;
    let lo = expr(next(&mut it, span)?)?;
    let hi = expr(next(&mut it, span)?)?;
    let hi_closed = next(&mut it, span)?.as_rule() == Rule::rclosed;
    Ok(Interval {
        lo,
        hi,
        lo_closed,
        hi_closed,
        span: ispan,
    })
}

fn equation_lhs(pair: Pair<'_, Rule>) -> Result<Vec<LhsTerm>, LangError> {
    let mut terms = Vec::new();
    let mut sign = Sign::Plus;
    for p in pair.into_inner() {
        match p.as_rule() {
            Rule::add => sign = Sign::Plus,
            Rule::sub => sign = Sign::Minus,
            _ => {
                let span = span_of(&p);
                let mut product = None;
                let mut unknown = None;
                let mut negated = false;
                for q in p.into_inner() {
                    match q.as_rule() {
                        Rule::neg => negated = true,
                        Rule::product => product = Some(expr(q)?),
                        Rule::name => unknown = Some(ident(&q)),
                        _ => return Err(internal(span, "unexpected part of a term")),
                    }
                }
                let product = product.ok_or_else(|| internal(span, "missing product"))?;
                let term_sign = match (sign, negated) {
                    (Sign::Plus, false) | (Sign::Minus, true) => Sign::Plus,
                    _ => Sign::Minus,
                };
                terms.push(LhsTerm {
                    sign: term_sign,
                    product,
                    unknown,
                    span,
                });
                sign = Sign::Plus;
            }
        }
    }
    Ok(terms)
}

/// An expression under construction with the depth of its tree.
struct Built {
    expr: Expr,
    depth: usize,
}

fn too_deep(span: Span) -> LangError {
    LangError::new(
        ErrorKind::TooDeep,
        format!("expression is nested too deeply (the limit is {MAX_DEPTH} levels)"),
        span,
        "too deeply nested",
    )
    .with_help("split it into smaller pieces")
}

fn node(kind: ExprKind, span: Span, depth: usize) -> Result<Built, LangError> {
    if depth > MAX_DEPTH {
        return Err(too_deep(span));
    }
    Ok(Built {
        expr: Expr { kind, span },
        depth,
    })
}

/// Builds an expression from an `expr` or `product` pair.
fn expr(pair: Pair<'_, Rule>) -> Result<Expr, LangError> {
    Ok(build(pair)?.expr)
}

fn build(pair: Pair<'_, Rule>) -> Result<Built, LangError> {
    let span = span_of(&pair);
    let recursive = pair
        .clone()
        .into_inner()
        .filter(|p| matches!(p.as_rule(), Rule::neg | Rule::pow))
        .count();
    if recursive > MAX_RECURSIVE_OPS {
        return Err(too_deep(span));
    }
    PRATT
        .map_primary(primary)
        .map_prefix(|op, rhs| {
            let rhs = rhs?;
            let span = span_of(&op).to(rhs.expr.span);
            node(ExprKind::Neg(Box::new(rhs.expr)), span, rhs.depth + 1)
        })
        .map_infix(|lhs, op, rhs| {
            let (lhs, rhs) = (lhs?, rhs?);
            let bin = match op.as_rule() {
                Rule::add => BinOp::Add,
                Rule::sub => BinOp::Sub,
                Rule::mul => BinOp::Mul,
                Rule::div => BinOp::Div,
                _ => BinOp::Pow,
            };
            let span = lhs.expr.span.to(rhs.expr.span);
            let depth = lhs.depth.max(rhs.depth) + 1;
            node(
                ExprKind::Binary(bin, Box::new(lhs.expr), Box::new(rhs.expr)),
                span,
                depth,
            )
        })
        .parse(pair.into_inner())
}

/// A call `f(a)`; `beta(a, b)` is written out as its definition
/// `gamma(a)*gamma(b)/gamma(a + b)` (so every later pass sees functions of
/// one argument), and any other name with two or more arguments is refused.
fn call(f: Ident, mut args: Vec<Built>, span: Span) -> Result<Built, LangError> {
    let depth = args.iter().map(|a| a.depth).max().unwrap_or(0) + 3;
    match (f.name.as_str(), args.len()) {
        (name @ "beta", n) if n != 2 => Err(wrong_arity(name, "two arguments", n, span)),
        (_, 1) => {
            let a = args
                .pop()
                .ok_or_else(|| internal(span, "a call without argument"))?;
            node(ExprKind::Call(f, Box::new(a.expr)), span, depth)
        }
        ("beta", 2) => {
            let b = args
                .pop()
                .ok_or_else(|| internal(span, "beta's argument"))?
                .expr;
            let a = args
                .pop()
                .ok_or_else(|| internal(span, "beta's argument"))?
                .expr;
            let name = |f: &Ident| Ident {
                name: "gamma".into(),
                span: f.span,
            };
            let g = |e: Expr| Expr {
                span: e.span,
                kind: ExprKind::Call(name(&f), Box::new(e)),
            };
            let bin = |op, x: Expr, y: Expr| Expr {
                span,
                kind: ExprKind::Binary(op, Box::new(x), Box::new(y)),
            };
            let sum = bin(BinOp::Add, a.clone(), b.clone());
            let num = bin(BinOp::Mul, g(a), g(b));
            node(bin(BinOp::Div, num, g(sum)).kind, span, depth)
        }
        (name, n) => Err(wrong_arity(name, "one argument", n, span)),
    }
}

fn wrong_arity(name: &str, want: &str, n: usize, span: Span) -> LangError {
    LangError::new(
        ErrorKind::WrongSort,
        format!("`{name}` takes {want}, not {n}"),
        span,
        "wrong number of arguments",
    )
    .with_help(
        "`beta(a, b)` takes two arguments; every other function and an unknown's value take one",
    )
}

fn primary(pair: Pair<'_, Rule>) -> Result<Built, LangError> {
    let span = span_of(&pair);
    match pair.as_rule() {
        Rule::number => node(
            ExprKind::Number(parse_number(pair.as_str(), span)?),
            span,
            1,
        ),
        Rule::pi => node(ExprKind::Pi, span, 1),
        Rule::identity => node(ExprKind::Identity, span, 1),
        Rule::name_ref => node(ExprKind::Name(ident(&pair)), span, 1),
        Rule::paren => {
            let inner = build(next(&mut pair.into_inner(), span)?)?;
            node(inner.expr.kind, span, inner.depth)
        }
        Rule::call => {
            let mut it = pair.into_inner();
            let f = ident(&next(&mut it, span)?);
            let args = it.map(build).collect::<Result<Vec<_>, _>>()?;
            call(f, args, span)
        }
        Rule::integral => {
            let mut it = pair.into_inner().peekable();
            let pv = it.peek().is_some_and(|p| p.as_rule() == Rule::kw_pv);
            let mut it = it.skip(if pv { 2 } else { 1 });
            let lower = build(next(&mut it, span)?)?;
            let upper = build(next(&mut it, span)?)?;
            let mut integrand = None;
            let mut var = None;
            for p in it {
                match p.as_rule() {
                    Rule::expr => integrand = Some(build(p)?),
                    Rule::differential => {
                        let v = if p.as_str() == "dx" {
                            IntVar::X
                        } else {
                            IntVar::T
                        };
                        var = Some((v, span_of(&p)));
                    }
                    _ => return Err(internal(span, "unexpected part of an integral")),
                }
            }
            let (var, var_span) = var.ok_or_else(|| internal(span, "missing differential"))?;
            let depth = 1 + lower
                .depth
                .max(upper.depth)
                .max(integrand.as_ref().map_or(0, |b| b.depth));
            node(
                ExprKind::Integral {
                    lower: Box::new(lower.expr),
                    upper: Box::new(upper.expr),
                    integrand: integrand.map(|b| Box::new(b.expr)),
                    var,
                    var_span,
                    pv,
                },
                span,
                depth,
            )
        }
        _ => Err(internal(span, "unexpected operand")),
    }
}

/// An integer or exact decimal literal as a rational (`0.25` → 1/4).
/// An exact number as written on a command line: an optional `-`, then an
/// integer, an exact decimal (`0.1801` is 1801/10000) or a fraction `a/b`.
///
/// ```
/// use lambdamat::lang::parser::parse_exact;
/// assert_eq!(parse_exact("0.25").unwrap().to_string(), "1/4");
/// assert_eq!(parse_exact("-3/6").unwrap().to_string(), "-1/2");
/// assert!(parse_exact("1e-3").is_none());
/// ```
pub fn parse_exact(text: &str) -> Option<BigRational> {
    let text = text.trim();
    let (neg, body) = match text.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, text),
    };
    let decimal = |t: &str| -> Option<BigRational> {
        let (i, f) = t.split_once('.').unwrap_or((t, ""));
        if i.is_empty()
            || !i.bytes().all(|b| b.is_ascii_digit())
            || !f.bytes().all(|b| b.is_ascii_digit())
            || (t.contains('.') && f.is_empty())
        {
            return None;
        }
        parse_number(t, Span::default()).ok()
    };
    let v = match body.split_once('/') {
        Some((a, b)) => {
            let d = decimal(b.trim())?;
            if d.is_zero() {
                return None;
            }
            decimal(a.trim())? / d
        }
        None => decimal(body)?,
    };
    Some(if neg { -v } else { v })
}

fn parse_number(text: &str, span: Span) -> Result<BigRational, LangError> {
    // Most literals are small integers: no digit string, no gcd.
    if text.len() <= 18
        && let Ok(v) = text.parse::<u64>()
    {
        return Ok(BigRational::from_integer(BigInt::from(v)));
    }
    let (int_part, frac_part) = text.split_once('.').unwrap_or((text, ""));
    let digits = format!("{int_part}{frac_part}");
    let numer = BigInt::parse_bytes(digits.as_bytes(), 10)
        .ok_or_else(|| internal(span, "malformed number"))?;
    let mut denom = BigInt::one();
    for _ in 0..frac_part.len() {
        denom *= 10;
    }
    if denom.is_zero() {
        return Err(internal(span, "malformed number"));
    }
    Ok(BigRational::new(numer, denom))
}

/// Rejects bracket nesting deeper than [`MAX_NESTING`] before pest recurses
/// into it.
fn check_nesting(src: &str) -> Result<(), LangError> {
    let mut depth = 0usize;
    let mut in_comment = false;
    for (i, c) in src.char_indices() {
        match c {
            '\n' => in_comment = false,
            _ if in_comment => {}
            '#' => in_comment = true,
            '(' | '[' => {
                depth += 1;
                if depth > MAX_NESTING {
                    return Err(LangError::new(
                        ErrorKind::TooDeep,
                        format!(
                            "brackets are nested too deeply (the limit is {MAX_NESTING} levels)"
                        ),
                        Span::new(i, i + 1),
                        "too deeply nested",
                    ));
                }
            }
            ')' | ']' => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    Ok(())
}

/// What a rule that pest expected means to a user, if anything.
fn describe_rule(rule: Rule) -> Option<&'static str> {
    Some(match rule {
        Rule::EOI => "the end of the file",
        // At the start of a file pest names the whole program: a statement.
        Rule::program => STATEMENT,
        Rule::kw_var
        | Rule::kw_principal
        | Rule::kw_matrix
        | Rule::kw_smith
        | Rule::kw_check
        | Rule::kw_param
        | Rule::kw_unknown
        | Rule::kw_operator
        | Rule::kw_equation
        | Rule::kw_solve
        | Rule::kw_output
        | Rule::kw_relation
        | Rule::kw_scalar
        | Rule::kw_singular
        | Rule::kw_condition
        | Rule::kw_inequality => STATEMENT,
        Rule::le | Rule::ge => "`<=` or `>=`",
        Rule::kw_on => "`on`",
        Rule::kw_in => "`in`",
        Rule::kw_at => "`at`",
        Rule::domain => "`on [a, b]`",
        Rule::interval | Rule::lclosed | Rule::lopen => "an interval such as `[0, c)`",
        Rule::rclosed | Rule::ropen => "`]` or `)` to close the interval",
        Rule::side => "`-`, `+` or `~`",
        Rule::kw_with => "`with`",
        Rule::kw_for => "`for`",
        Rule::name => "a name",
        Rule::lhs | Rule::lhs_term => "a term such as `k1 p`",
        Rule::var_decl
        | Rule::principal_decl
        | Rule::matrix_def
        | Rule::smith_cmd
        | Rule::check_cmd
        | Rule::param_def
        | Rule::unknown_decl
        | Rule::operator_def
        | Rule::equation
        | Rule::solve_cmd
        | Rule::output_def
        | Rule::relation_def
        | Rule::scalar_decl
        | Rule::singular_decl
        | Rule::condition_def
        | Rule::inequality_def => STATEMENT,
        Rule::number
        | Rule::paren
        | Rule::integral
        | Rule::kw_int
        | Rule::call
        | Rule::ident
        | Rule::pi
        | Rule::identity
        | Rule::name_ref
        | Rule::neg
        | Rule::expr
        | Rule::product => "an expression",
        Rule::add | Rule::sub | Rule::mul | Rule::div | Rule::pow => {
            "an operator (`+`, `-`, `*`, `/`, `^`)"
        }
        Rule::matrix_lit => "`[`",
        Rule::matrix_row => "a matrix entry",
        Rule::differential => "`dt`/`dx` to close the integral",
        _ => return None,
    })
}

const STATEMENT: &str = "a statement (`var`, `principal`, `matrix`, `smith`, `check`, `param`, `unknown`, `operator`, `equation`, `relation`, `inequality`, `scalar`, `singular`, `condition`, `solve` or `output`)";

/// What is written at byte `pos`, in words.
fn found_at(src: &str, pos: usize) -> (String, Option<String>, usize) {
    let rest = src.get(pos..).unwrap_or("");
    let Some(c) = rest.chars().next() else {
        return ("the end of the file".to_string(), None, 0);
    };
    if c.is_alphabetic() || c == '_' {
        let word: String = rest
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        let len = word.len();
        if is_keyword(&word) {
            return (format!("the keyword `{word}`"), Some(word), len);
        }
        return (format!("`{word}`"), None, len);
    }
    if c.is_ascii_digit() {
        let num: String = rest
            .chars()
            .take_while(|c| c.is_ascii_digit() || *c == '.')
            .collect();
        let len = num.len();
        return (format!("the number `{num}`"), None, len);
    }
    (format!("`{c}`"), None, c.len_utf8())
}

fn join_or(items: &[String]) -> String {
    match items {
        [] => "something else".to_string(),
        [one] => one.clone(),
        [init @ .., last] => format!("{} or {last}", init.join(", ")),
    }
}

/// Translates a pest failure into one error in human words.
fn syntax_error(e: &pest::error::Error<Rule>, src: &str) -> LangError {
    let pos = match e.location {
        InputLocation::Pos(p) => p,
        InputLocation::Span((s, _)) => s,
    };
    if let ErrorVariant::CustomError { message } = &e.variant {
        // pest reports its own call or stack limits this way.
        return LangError::new(
            ErrorKind::TooDeep,
            format!("the input is nested too deeply to parse ({message})"),
            Span::new(pos, pos),
            "here",
        );
    }
    let mut expected: Vec<String> = Vec::new();
    let mut push = |s: String| {
        if !expected.contains(&s) {
            expected.push(s);
        }
    };
    if let ErrorVariant::ParsingError { positives, .. } = &e.variant {
        for r in positives {
            if let Some(d) = describe_rule(*r) {
                push(d.to_string());
            }
        }
    }
    if let Some(att) = e.parse_attempts().filter(|a| a.max_position == pos) {
        let tokens: BTreeSet<String> = att
            .expected_tokens()
            .into_iter()
            .map(|t| t.to_string())
            .filter(|token| {
                !token.is_empty()
                    && token.chars().all(|c| !c.is_alphanumeric() && c != '_')
                    && !matches!(token.as_str(), "#" | "\n" | " " | "\t" | "\r")
                    && !token.chars().any(char::is_whitespace)
            })
            .map(|token| format!("`{token}`"))
            .collect();
        for t in tokens {
            push(t);
        }
    }
    // The end of the file is always acceptable between statements; saying
    // so adds nothing. Tokens already covered by a phrase are dropped.
    if expected.len() > 1 {
        expected.retain(|s| s != "the end of the file");
    }
    let has = |e: &[String], what: &str| e.iter().any(|s| s.starts_with(what));
    let covered: Vec<&str> = [
        (
            has(&expected, "an operator"),
            &["`+`", "`-`", "`*`", "`/`", "`^`"][..],
        ),
        (has(&expected, "an expression"), &["`(`", "`-`"][..]),
        (has(&expected, "a term"), &["`(`", "`-`"][..]),
        (true, &["`.`"][..]),
    ]
    .into_iter()
    .filter(|(on, _)| *on)
    .flat_map(|(_, toks)| toks.iter().copied())
    .collect();
    expected.retain(|s| !covered.contains(&s.as_str()));
    let (found, keyword, len) = found_at(src, pos);
    let span = Span::new(pos, pos + len);
    let help = |word: &str| {
        format!(
            "`{word}` is reserved; choose another name. The reserved words are {}",
            KEYWORDS.join(", ")
        )
    };
    if let Some(word) = &keyword {
        if expected.iter().any(|s| s == "a name") {
            return LangError::new(
                ErrorKind::KeywordAsName,
                format!("`{word}` is a reserved keyword and cannot be used as a name"),
                span,
                "reserved keyword",
            )
            .with_help(help(word));
        }
        if expected.iter().any(|s| s == "an expression") {
            return LangError::new(
                ErrorKind::KeywordAsName,
                format!(
                    "expected an expression, found the keyword `{word}` (keywords cannot be used as names)"
                ),
                span,
                "reserved keyword",
            )
            .with_help(help(word));
        }
    }
    let what = join_or(&expected);
    let short: Vec<String> = expected
        .iter()
        .map(|s| {
            if s == STATEMENT {
                "a statement".to_string()
            } else if s.starts_with("an operator") {
                "an operator".to_string()
            } else {
                s.clone()
            }
        })
        .collect();
    LangError::new(
        ErrorKind::Syntax,
        format!("expected {what}, found {found}"),
        span,
        format!("expected {}", join_or(&short)),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(BigInt::from(n), BigInt::from(d))
    }

    /// Prints a tree fully parenthesised, to check precedence.
    fn show(e: &Expr) -> String {
        match &e.kind {
            ExprKind::Number(v) => v.to_string(),
            ExprKind::Name(id) => id.name.clone(),
            ExprKind::Neg(a) => format!("(-{})", show(a)),
            ExprKind::Binary(op, a, b) => format!("({} {} {})", show(a), op.symbol(), show(b)),
            other => format!("{other:?}"),
        }
    }

    fn entry(src: &str) -> String {
        let file = parse_file(&format!("matrix A = [{src}]")).expect("parses");
        match &file.statements[0].kind {
            Stmt::Matrix { rows, .. } => show(&rows[0].entries[0]),
            _ => String::new(),
        }
    }

    #[test]
    fn decimals_are_exact() {
        let s = Span::default();
        assert_eq!(parse_number("0.25", s).ok(), Some(q(1, 4)));
        assert_eq!(parse_number("12", s).ok(), Some(q(12, 1)));
        assert_eq!(parse_number("1.50", s).ok(), Some(q(3, 2)));
        assert_eq!(parse_number("007", s).ok(), Some(q(7, 1)));
        assert_eq!(parse_number("0", s).ok(), Some(q(0, 1)));
        let big = "123456789012345678901234567890";
        assert_eq!(
            parse_number(big, s).ok().map(|v| v.to_string()),
            Some(big.to_string())
        );
    }

    #[test]
    fn precedence_and_associativity() {
        assert_eq!(entry("a + b * c"), "(a + (b * c))");
        assert_eq!(entry("a - b - c"), "((a - b) - c)");
        assert_eq!(entry("a / b / c"), "((a / b) / c)");
        assert_eq!(entry("a ^ b ^ c"), "(a ^ (b ^ c))");
        assert_eq!(entry("-a ^ 2"), "(-(a ^ 2))");
        assert_eq!(entry("-a * b"), "((-a) * b)");
        assert_eq!(entry("a ^ -b"), "(a ^ (-b))");
        assert_eq!(entry("(a + b) * c"), "((a + b) * c)");
    }

    #[test]
    fn spans_cover_the_written_text() {
        let src = "matrix A = [ (x + 1) * y ]";
        let file = parse_file(src).expect("parses");
        let Stmt::Matrix { rows, .. } = &file.statements[0].kind else {
            panic!("not a matrix")
        };
        let e = &rows[0].entries[0];
        assert_eq!(&src[e.span.start..e.span.end], "(x + 1) * y");
    }
}
