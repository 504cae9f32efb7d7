//! The front end: source text → pest parse tree → spanned AST → validated
//! program → lowered algebraic objects. This is the only layer that knows
//! about source positions (line:column) and user-facing names; it hands the
//! algebra plain polynomials indexed by a symbol table and must not do any
//! algebra beyond building those polynomials.
//!
//! * `grammar/lambdamat.pest`: the syntax, the single reference;
//! * [`parser`]: text → spanned [`ast`] (pest + a Pratt parser);
//! * [`validate`]: every meaning error at once, each with a span;
//! * [`diagnostics`]: [`LangErrors`], the only place that formats line:column;
//! * [`lower`]: validated AST → span-free [`Program`];
//! * [`pretty`]: [`Program`] → source text that parses back to it.

pub mod ast;
pub mod diagnostics;
pub mod error;
pub mod keywords;
pub mod lower;
pub mod parser;
pub mod pretty;
pub mod scope;
pub mod validate;
pub mod validate_system;

pub use crate::system::{Directive, MatrixDef, Program};
pub use diagnostics::LangErrors;
pub use error::{ErrorKind, LangError};

/// Parses, validates and lowers a whole file.
///
/// On failure, returns the syntax error, or every validation error, each
/// with its position in `filename`.
///
/// ```
/// let src = "var x\nmatrix A = [x, 1/2; 0.25, (x+1)^2]\nsmith A\n";
/// let p = lambdamat::lang::parse_program(src, "a.lmx").expect("valid");
/// assert_eq!(p.symbols, ["x"]);
/// assert_eq!((p.matrices[0].rows, p.matrices[0].cols), (2, 2));
/// assert_eq!(p.matrices[0].entries[3].to_string_with(&p.symbols), "x^2 + 2*x + 1");
///
/// let err = lambdamat::lang::parse_program("var x\nmatrix A = [y]", "a.lmx").unwrap_err();
/// assert!(err.render().contains("a.lmx:2:13"));
/// ```
pub fn parse_program(src: &str, filename: &str) -> Result<Program, LangErrors> {
    let file = parser::parse_file(src).map_err(|e| LangErrors::new(filename, src, vec![e]))?;
    let checked = validate::validate(&file).map_err(|errs| LangErrors::new(filename, src, errs))?;
    lower::lower(&file, &checked).map_err(|e| LangErrors::new(filename, src, vec![e]))
}

/// Parses `src` into its spanned AST (syntax only, no validation).
pub fn parse_ast(src: &str, filename: &str) -> Result<ast::File, LangErrors> {
    parser::parse_file(src).map_err(|e| LangErrors::new(filename, src, vec![e]))
}
