//! One front-end error as data: its kind, a message in human words, the span
//! it points at, a label for the caret, optional help and secondary spans.
//! This module only describes errors; turning spans into line:column and
//! rendering them is `diagnostics.rs`'s job alone.

use super::ast::Span;

/// What went wrong, for programs (tests, the CLI) that need to tell errors
/// apart without reading the message.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ErrorKind {
    /// The text does not follow the grammar.
    Syntax,
    /// A keyword was written where a name is expected.
    KeywordAsName,
    /// A name that is not declared anywhere.
    Undeclared,
    /// A name declared twice.
    Duplicate,
    /// Division by an expression that is zero.
    DivisionByZero,
    /// Division by something that is not a constant (the entry would not be a
    /// polynomial).
    NonPolynomial,
    /// An exponent that is not a non-negative integer literal.
    BadExponent,
    /// Rows of a matrix with different numbers of entries.
    RaggedRows,
    /// `smith`/`check` names something that is not a matrix.
    UnknownMatrix,
    /// `check smith A with U, D, V` with shapes that cannot give U·A·V = D.
    Shape,
    /// `principal` names something that is not a declared symbol, or is
    /// given twice.
    BadPrincipal,
    /// A name of the wrong sort in this place (e.g. an unknown where a
    /// constant is needed, or a function that does not exist).
    WrongSort,
    /// A variable (`x`, `t`) used where it is not available.
    BadVariable,
    /// An unknown used non-linearly, or not applied as the last factor.
    NonLinear,
    /// The number of equations differs from the number of unknowns.
    NotSquare,
    /// An expression nested too deeply to be processed safely.
    TooDeep,
    /// A kernel, multiplier or right side that the numerics cannot use
    /// (found when the system is solved, pointed at in the source).
    Unsupported,
}

/// One error with everything needed to render it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LangError {
    /// What went wrong.
    pub kind: ErrorKind,
    /// One sentence in human words.
    pub message: String,
    /// The place the caret points at.
    pub span: Span,
    /// Text printed next to the caret.
    pub label: String,
    /// A hint on how to fix it.
    pub help: Option<String>,
    /// Other places worth showing (e.g. the first definition of a duplicate).
    pub related: Vec<(Span, String)>,
}

impl LangError {
    /// An error of `kind` with `message`, pointing at `span` with `label`.
    pub fn new(
        kind: ErrorKind,
        message: impl Into<String>,
        span: Span,
        label: impl Into<String>,
    ) -> LangError {
        LangError {
            kind,
            message: message.into(),
            span,
            label: label.into(),
            help: None,
            related: Vec::new(),
        }
    }

    /// Adds a help line.
    pub fn with_help(mut self, help: impl Into<String>) -> LangError {
        self.help = Some(help.into());
        self
    }

    /// Adds a secondary span with its own label.
    pub fn with_related(mut self, span: Span, label: impl Into<String>) -> LangError {
        self.related.push((span, label.into()));
        self
    }
}
