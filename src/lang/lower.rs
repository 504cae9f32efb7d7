//! Validated AST → span-free [`Program`]: the only place that maps names to
//! indices for the algebra and builds the [`MPoly`] entries. It trusts the
//! validator (every name resolved, every divisor a nonzero constant, every
//! exponent a small literal) but still never panics: anything unexpected
//! becomes an internal error. It must not check user errors itself.

use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};

use super::ast::{BinOp, Expr, ExprKind, File, Ident, Stmt};
use super::error::{ErrorKind, LangError};
use super::scope::{Entry, Scope, Sort};
use super::validate::Validated;
use crate::algebra::mpoly::MPoly;
use crate::system::{Directive, MatrixDef, Program};

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
            _ => {}
        }
    }
    Ok(program)
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
                    let (neg, lit) = match &b.kind {
                        ExprKind::Neg(inner) => (true, inner.as_ref()),
                        _ => (false, b.as_ref()),
                    };
                    let k = match &lit.kind {
                        ExprKind::Number(q) if q.is_integer() => q.to_integer().to_u32()?,
                        _ => return None,
                    };
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
