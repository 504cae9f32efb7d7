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
//! * [`lower`]: validated AST → span-free [`Program`].

pub mod ast;
pub mod diagnostics;
pub mod error;
pub mod keywords;
pub mod parser;

pub use diagnostics::LangErrors;
pub use error::{ErrorKind, LangError};

/// Parses `src` into its spanned AST (syntax only, no validation).
pub fn parse_ast(src: &str, filename: &str) -> Result<ast::File, LangErrors> {
    parser::parse_file(src).map_err(|e| LangErrors::new(filename, src, vec![e]))
}
