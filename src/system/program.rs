//! The lowered program: symbol table, principal symbol, matrices of
//! polynomials and directives, all indexed, all span-free. This file defines
//! data only; building it is `lang::lower`'s job and printing it back as
//! source is `lang::pretty`'s.

use crate::algebra::mpoly::MPoly;

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
}
