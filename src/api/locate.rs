//! Points errors found after lowering back at the source: the numerics see
//! the span-free [`crate::system::Program`], so an unsupported kernel or a
//! right side that is not finite is named there by operator name or
//! equation index. This module finds the matching expression in the spanned
//! AST (through [`crate::lang`]'s public parser) and turns the error into a
//! [`LangErrors`], which renders line and column. It only looks things up;
//! it decides nothing about what is wrong.

use crate::lang::ast::{Expr, ExprKind, File, Span, Stmt};
use crate::lang::{ErrorKind, LangError, LangErrors};
use crate::plan::PlanError;

/// `e` as a located source error, if it names a place in `text`.
pub fn locate_plan_error(e: &PlanError, text: &str, filename: &str) -> Option<LangErrors> {
    let text = crate::lang::strip_bom(text);
    let file = crate::lang::parse_ast(text, filename).ok()?;
    let err = match e {
        PlanError::Unsupported { operator, reason } => {
            let (span, label) = operator_place(&file, operator, reason)?;
            LangError::new(
                ErrorKind::Unsupported,
                format!("operator {operator}: {reason}"),
                span,
                label,
            )
        }
        PlanError::RightSide { equation, reason } => {
            let rhs = file
                .statements
                .iter()
                .filter_map(|s| match &s.kind {
                    Stmt::Equation { rhs, .. } => Some(rhs),
                    _ => None,
                })
                .nth(*equation)?;
            LangError::new(
                ErrorKind::Unsupported,
                reason.clone(),
                rhs.span,
                "this right side",
            )
        }
        _ => return None,
    };
    Some(LangErrors::new(filename, text, vec![err]))
}

/// Where operator `name`'s problem is: its only integral's kernel (for a
/// kernel error), else its whole definition; the `var` declaration for a
/// symbol without definition.
fn operator_place(file: &File, name: &str, reason: &str) -> Option<(Span, &'static str)> {
    for s in &file.statements {
        match &s.kind {
            Stmt::Operator { name: n, body } if n.name == name => {
                if reason.starts_with("kernel") || reason.contains(" kernel ") {
                    let mut kernels = Vec::new();
                    integrals(body, &mut kernels);
                    if let [one] = kernels.as_slice() {
                        return Some((*one, "this kernel"));
                    }
                }
                return Some((body.span, "this definition"));
            }
            Stmt::Var(names) => {
                if let Some(n) = names.iter().find(|n| n.name == name) {
                    return Some((n.span, "declared here without a definition"));
                }
            }
            _ => {}
        }
    }
    None
}

/// The spans of the integrands (or whole integrals, when the integrand is
/// left out) of every integral in `e`.
fn integrals(e: &Expr, out: &mut Vec<Span>) {
    match &e.kind {
        ExprKind::Integral { integrand, .. } => {
            out.push(integrand.as_ref().map_or(e.span, |k| k.span));
        }
        ExprKind::Neg(a) | ExprKind::Call(_, a) => integrals(a, out),
        ExprKind::Binary(_, a, b) => {
            integrals(a, out);
            integrals(b, out);
        }
        ExprKind::Number(_) | ExprKind::Name(_) | ExprKind::Pi | ExprKind::Identity => {}
    }
}

/// Reads a source file, mapping I/O errors to invalid input; text that is
/// not UTF-8 is reported with the byte offset, line and column of the
/// first bad byte.
pub fn read_source(path: &std::path::Path) -> Result<(String, String), crate::error::CliError> {
    let name = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| crate::error::CliError::Io {
        path: name.clone(),
        source: e,
    })?;
    let text = String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let bytes = e.as_bytes();
        let good = String::from_utf8_lossy(&bytes[..at]);
        let line = good.matches('\n').count() + 1;
        let col = good.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
        crate::error::CliError::Invalid(format!(
            "{name}:{line}:{col}: not UTF-8 text: byte 0x{:02x} at byte offset {at}",
            bytes.get(at).copied().unwrap_or(0)
        ))
    })?;
    Ok((text, name))
}

/// A plan error pointed at its place in the source when it has one (a
/// language error), else kept as a plan error.
pub(crate) fn located(e: crate::plan::PlanError, text: &str, name: &str) -> crate::error::CliError {
    match locate_plan_error(&e, text, name) {
        Some(errs) => crate::error::CliError::Lang(Box::new(errs)),
        None => crate::error::CliError::Plan(e),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_kernel_error_points_at_the_kernel() {
        let text = "operator k = 2*id + int(0..1) 1/(t - x) dt\nunknown p\nequation k p = 1\n";
        let e = PlanError::Unsupported {
            operator: "k".into(),
            reason: "kernel 1/(t - x): singular on the diagonal".into(),
        };
        let errs = locate_plan_error(&e, text, "a.lmx").expect("located");
        let span = errs.errors()[0].span;
        assert_eq!(&text[span.start..span.end], "1/(t - x)");
        assert_eq!(errs.line_col(span), (1, 31));
    }

    #[test]
    fn a_right_side_error_points_at_the_right_side() {
        let text = "operator k = int(0..1) dt\nunknown p, q\nequation k p + q = 1\nequation p - q = sqrt(-1)\n";
        let e = PlanError::RightSide {
            equation: 1,
            reason: "right side of equation 2 = sqrt(-1) is not finite at x = 0.5".into(),
        };
        let errs = locate_plan_error(&e, text, "a.lmx").expect("located");
        let span = errs.errors()[0].span;
        assert_eq!(&text[span.start..span.end], "sqrt(-1)");
        assert_eq!(errs.line_col(span), (4, 18));
        assert!(errs.render().contains("a.lmx:4:18"));
    }

    #[test]
    fn errors_without_a_place_are_left_alone() {
        let e = PlanError::Invalid("the system is not square".into());
        assert!(locate_plan_error(&e, "unknown p\n", "a.lmx").is_none());
    }
}
