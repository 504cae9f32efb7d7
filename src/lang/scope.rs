//! The name table of one file: which names are declared, as what sort of
//! thing, where, and with which index in the lowered program. Built by the
//! validator, read by the lowering. It owns no checks and formats no
//! messages beyond the word for a sort.

use std::collections::HashMap;

use num_rational::BigRational;
use num_traits::Signed;

use super::ast::{BinOp, Expr, ExprKind, Span};

/// What a declared name stands for, with its index in the lowered program.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sort {
    /// A polynomial symbol (`var`, or an operator symbol): index into
    /// `Program::symbols`.
    Symbol(usize),
    /// A matrix: index into `Program::matrices`.
    Matrix(usize),
    /// A parameter: index into [`Scope::params`].
    Param(usize),
    /// An unknown function: index into the unknowns.
    Unknown(usize),
    /// An output functional.
    Output(usize),
    /// An unknown scalar: index into [`Scope::scalars`].
    Scalar(usize),
    /// The coefficient of an exact singular term: index into
    /// [`Scope::coefficients`].
    Coefficient(usize),
}

impl Sort {
    /// The sort in words, with an article: "a matrix".
    pub fn word(self) -> &'static str {
        match self {
            Sort::Symbol(_) => "a symbol",
            Sort::Matrix(_) => "a matrix",
            Sort::Param(_) => "a parameter",
            Sort::Unknown(_) => "an unknown",
            Sort::Output(_) => "an output",
            Sort::Scalar(_) => "an unknown scalar",
            Sort::Coefficient(_) => "a singular coefficient",
        }
    }
}

/// One declared name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Entry {
    /// What it is.
    pub sort: Sort,
    /// Where it was declared.
    pub span: Span,
}

/// Every declared name of a file.
#[derive(Clone, Debug, Default)]
pub struct Scope {
    names: HashMap<String, Entry>,
    /// Polynomial symbols in order.
    pub symbols: Vec<String>,
    /// Matrix names in order.
    pub matrices: Vec<String>,
    /// Parameters in order, with their value once computed (`None` while
    /// not yet computed or when its definition has an error).
    pub params: Vec<(String, Option<BigRational>)>,
    /// Unknowns in order.
    pub unknowns: Vec<String>,
    /// Outputs in order.
    pub outputs: Vec<String>,
    /// `real_params[i]`: parameter `i` is real (not an exact rational).
    pub real_params: Vec<bool>,
    /// `real_defs[i]`: the definition of real parameter `i` when it uses
    /// no scalar (such a parameter may stand in right sides and outputs,
    /// where it is replaced by its definition).
    pub real_defs: Vec<Option<Expr>>,
    /// Unknown scalars in order.
    pub scalars: Vec<String>,
    /// Singular coefficients in order.
    pub coefficients: Vec<String>,
}

impl Scope {
    /// The entry for `name`, if declared.
    pub fn get(&self, name: &str) -> Option<Entry> {
        self.names.get(name).copied()
    }

    /// Whether `name` is declared as an unknown function.
    pub fn is_unknown(&self, name: &str) -> bool {
        matches!(
            self.get(name),
            Some(Entry {
                sort: Sort::Unknown(_),
                ..
            })
        )
    }

    /// Declares `name`; if it is already declared, returns the earlier entry
    /// and changes nothing.
    pub fn declare(
        &mut self,
        name: &str,
        span: Span,
        make: impl FnOnce(&mut Scope) -> Sort,
    ) -> Result<Sort, Entry> {
        if let Some(e) = self.names.get(name) {
            return Err(*e);
        }
        let sort = make(self);
        self.names.insert(name.to_string(), Entry { sort, span });
        Ok(sort)
    }

    /// Declares a polynomial symbol.
    pub fn declare_symbol(&mut self, name: &str, span: Span) -> Result<Sort, Entry> {
        self.declare(name, span, |s| {
            s.symbols.push(name.to_string());
            Sort::Symbol(s.symbols.len() - 1)
        })
    }

    /// Declares a matrix.
    pub fn declare_matrix(&mut self, name: &str, span: Span) -> Result<Sort, Entry> {
        self.declare(name, span, |s| {
            s.matrices.push(name.to_string());
            Sort::Matrix(s.matrices.len() - 1)
        })
    }

    /// Declares a parameter (its value comes later).
    pub fn declare_param(&mut self, name: &str, span: Span) -> Result<Sort, Entry> {
        self.declare(name, span, |s| {
            s.params.push((name.to_string(), None));
            Sort::Param(s.params.len() - 1)
        })
    }

    /// Declares an unknown.
    pub fn declare_unknown(&mut self, name: &str, span: Span) -> Result<Sort, Entry> {
        self.declare(name, span, |s| {
            s.unknowns.push(name.to_string());
            Sort::Unknown(s.unknowns.len() - 1)
        })
    }

    /// Declares an output.
    pub fn declare_output(&mut self, name: &str, span: Span) -> Result<Sort, Entry> {
        self.declare(name, span, |s| {
            s.outputs.push(name.to_string());
            Sort::Output(s.outputs.len() - 1)
        })
    }

    /// Declares an unknown scalar.
    pub fn declare_scalar(&mut self, name: &str, span: Span) -> Result<Sort, Entry> {
        self.declare(name, span, |s| {
            s.scalars.push(name.to_string());
            Sort::Scalar(s.scalars.len() - 1)
        })
    }

    /// Declares a singular coefficient.
    pub fn declare_coefficient(&mut self, name: &str, span: Span) -> Result<Sort, Entry> {
        self.declare(name, span, |s| {
            s.coefficients.push(name.to_string());
            Sort::Coefficient(s.coefficients.len() - 1)
        })
    }

    /// Whether parameter `i` is real (not an exact rational).
    pub fn is_real_param(&self, i: usize) -> bool {
        self.real_params.get(i).copied().unwrap_or(false)
    }

    /// The definition of real parameter `i`, if it uses no scalar.
    pub fn real_def(&self, i: usize) -> Option<&Expr> {
        self.real_defs.get(i).and_then(Option::as_ref)
    }

    /// The value of parameter `i`, if known.
    pub fn param_value(&self, i: usize) -> Option<&BigRational> {
        self.params.get(i).and_then(|(_, v)| v.as_ref())
    }
}

impl Scope {
    /// Whether `e` is an exact rational constant: numbers and parameters
    /// combined by `+ - * /` and integer-literal powers. Such expressions
    /// are folded to one number when lowered.
    pub fn is_rational_const(&self, e: &Expr) -> bool {
        match &e.kind {
            ExprKind::Number(_) => true,
            ExprKind::Name(id) => matches!(
                self.get(&id.name),
                Some(Entry {
                    sort: Sort::Param(i),
                    ..
                }) if !self.is_real_param(i)
            ),
            ExprKind::Neg(a) => self.is_rational_const(a),
            ExprKind::Binary(BinOp::Pow, a, b) => {
                // Any constant integer exponent within the limit, however
                // written (`2^(-24)` or `2^(-12*2)`), as `lower::constant`
                // folds it: the printed program then reads back the same.
                self.is_rational_const(a)
                    && self.is_rational_const(b)
                    && super::lower::constant(b, self).is_some_and(|q| {
                        q.is_integer()
                            && q.abs().to_integer()
                                <= num_bigint::BigInt::from(super::validate::MAX_EXPONENT)
                    })
            }
            ExprKind::Binary(_, a, b) => self.is_rational_const(a) && self.is_rational_const(b),
            _ => false,
        }
    }
}
