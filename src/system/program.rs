//! The lowered program: symbol table, principal symbol, matrices of
//! polynomials, parameters, the operator system (unknowns, operator table,
//! equations as rows of operator words in the order written, with right
//! sides, outputs) and directives, all indexed, all span-free. An
//! equation's operators are elements of the free algebra over the symbols
//! ([`NcPoly`]: `k2*k1` ≠ `k1*k2`); the λ-matrix over commuting symbols is
//! their image ([`Program::lambda_matrix`]). This file defines data only;
//! building it is `lang::lower`'s job and printing it back as source is
//! `lang::pretty`'s.

use num_rational::BigRational;

use super::contact::Contact;
use super::expr::Expr;
use super::operator::OperatorDef;
use crate::algebra::mpoly::MPoly;
use crate::algebra::ncpoly::NcPoly;

/// Everything a file says, ready for the algebra and the numerics.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    /// The polynomial symbols in declaration order; an [`MPoly`] in this
    /// program has `symbols.len()` variables and variable `i` is
    /// `symbols[i]`.
    pub symbols: Vec<String>,
    /// Index into `symbols` of the principal symbol (`principal k4`).
    pub principal: Option<usize>,
    /// The matrices, in definition order.
    pub matrices: Vec<MatrixDef>,
    /// What the file asks to be done, in source order.
    pub directives: Vec<Directive>,
    /// The parameters with their exact values, in definition order (already
    /// substituted everywhere; kept for reports).
    pub params: Vec<Param>,
    /// The unknown functions of x, in declaration order.
    pub unknowns: Vec<String>,
    /// Definitions of operator symbols (symbols declared with `var` have
    /// none: they are purely algebraic).
    pub operators: Vec<OperatorDef>,
    /// The equations in source order; equation `i` is row `i` of the
    /// ordered matrix ([`Program::ordered_matrix`]) and of its commutative
    /// image, the λ-matrix.
    pub equations: Vec<Equation>,
    /// Output functionals, in definition order.
    pub outputs: Vec<Output>,
    /// Side conditions `functional = value` (`condition int(-1..1) f(t) dt
    /// = 1`): extra rows of the one-interval system, in definition order.
    pub side_conditions: Vec<SideCondition>,
    /// Split domains, relations, scalars and singular behaviour (contact
    /// problems); empty for a system on one interval.
    pub contact: Contact,
}

impl Program {
    /// The λ-matrix of the operator system: one row per equation, one
    /// column per unknown, each entry the commutative image of the
    /// equation's ordered operator (what Smith forms and the commutative
    /// eliminant work on).
    pub fn lambda_matrix(&self) -> MatrixDef {
        let n = self.symbols.len();
        MatrixDef {
            name: "A".to_string(),
            rows: self.equations.len(),
            cols: self.unknowns.len(),
            entries: self
                .equations
                .iter()
                .flat_map(|e| e.lhs.iter().map(|w| w.commutative_image(n)))
                .collect(),
        }
    }

    /// The ordered operators of the system, row by row (equation `i`,
    /// unknown `j`): products in the order written.
    pub fn ordered_matrix(&self) -> Vec<Vec<NcPoly>> {
        self.equations.iter().map(|e| e.lhs.clone()).collect()
    }

    /// The definition of symbol `i`, if it is a defined operator.
    pub fn operator(&self, symbol: usize) -> Option<&OperatorDef> {
        self.operators.iter().find(|o| o.symbol == symbol)
    }
}

/// A named exact constant.
#[derive(Clone, Debug, PartialEq)]
pub struct Param {
    /// Its name.
    pub name: String,
    /// Its value.
    pub value: BigRational,
}

/// One equation `Σ_j lhs[j] u_j = rhs`.
#[derive(Clone, Debug, PartialEq)]
pub struct Equation {
    /// The operator applied to each unknown (one per unknown, zero where
    /// the unknown does not occur), as a polynomial in non-commuting
    /// symbols: every product keeps the order written (`k2*k1 p` is the
    /// word `k2 k1`, `k1` applied first), and terms of one unknown are
    /// summed (`k2*k1 p - k1*k2 p` is the commutator, not zero).
    pub lhs: Vec<NcPoly>,
    /// The right side, a function of `x`.
    pub rhs: Expr,
    /// The right side as the split solver runs it, when it uses an unknown
    /// scalar (`delta - x^2`): `rhs` holds 0 there for the operator
    /// algebra, and every printer shows this text instead.
    pub written: Option<String>,
}

impl Equation {
    /// The right side as printed: [`Equation::written`] when set, else
    /// `rhs`.
    pub fn rhs_text(&self) -> String {
        self.written.clone().unwrap_or_else(|| self.rhs.to_string())
    }
}

/// A number computed from the solution: a sum of terms.
#[derive(Clone, Debug, PartialEq)]
pub struct Output {
    /// Its name.
    pub name: String,
    /// The terms whose sum is the output.
    pub terms: Vec<FunctionalTerm>,
}

/// A side condition: a linear functional of the unknowns (the same terms
/// as an output) equal to a constant.
#[derive(Clone, Debug, PartialEq)]
pub struct SideCondition {
    /// The terms whose sum is fixed (constants included).
    pub terms: Vec<FunctionalTerm>,
    /// The required value (a constant; may involve `pi`).
    pub value: Expr,
}

/// One term of an output functional.
#[derive(Clone, Debug, PartialEq)]
pub enum FunctionalTerm {
    /// A constant (may involve `pi`; never `x` or `t`).
    Constant(Expr),
    /// `coeff · ∫_lower^upper weight(x) u(x) dx`.
    Integral {
        /// A constant factor (never `x` or `t`).
        coeff: Expr,
        /// Lower limit.
        lower: BigRational,
        /// Upper limit.
        upper: BigRational,
        /// The weight, a function of the integration variable, written `x`.
        weight: Expr,
        /// Index into `Program::unknowns`.
        unknown: usize,
    },
    /// `coeff · u(at)`: a point value.
    Point {
        /// A constant factor (never `x` or `t`).
        coeff: Expr,
        /// The point.
        at: BigRational,
        /// Index into `Program::unknowns`.
        unknown: usize,
    },
}

/// A named matrix of polynomials.
#[derive(Clone, Debug, PartialEq)]
pub struct MatrixDef {
    /// Its name.
    pub name: String,
    /// Number of rows.
    pub rows: usize,
    /// Number of columns.
    pub cols: usize,
    /// `rows * cols` entries, row-major.
    pub entries: Vec<MPoly>,
}

impl MatrixDef {
    /// The entry in row `i`, column `j` (0-based), if inside the matrix.
    pub fn get(&self, i: usize, j: usize) -> Option<&MPoly> {
        if i < self.rows && j < self.cols {
            self.entries.get(i * self.cols + j)
        } else {
            None
        }
    }
}

/// A request made by the file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Directive {
    /// `smith A`: the Smith form of `matrices[matrix]`.
    Smith {
        /// Index into `Program::matrices`.
        matrix: usize,
    },
    /// `check smith A with U, D, V`: check a user-supplied decomposition.
    CheckSmith {
        /// The matrix A.
        matrix: usize,
        /// The left transform U.
        u: usize,
        /// The claimed diagonal form D.
        d: usize,
        /// The right transform V.
        v: usize,
    },
    /// `solve for p`: eliminate for and solve for this unknown.
    Solve {
        /// Index into `Program::unknowns`.
        unknown: usize,
    },
}
