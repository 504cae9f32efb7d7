//! Exact algebra: everything here is exact (BigRational coefficients) and
//! never touches `f64`, names or source spans.
//!
//! * [`ring`]: the capability ladder `Ring → GcdDomain → EuclideanDomain`,
//!   `Field`, implemented by ring *objects* stored beside the data;
//! * [`rational`]: the field Q;
//! * [`mpoly`]: sparse multivariate polynomials over Q in commuting symbols;
//! * [`gcd`]: multivariate gcd (modular first, primitive PRS as fallback);
//! * [`kronecker`]: integer polynomial products by Kronecker substitution;
//! * [`decimal`]: decimal text of big naturals (for printing);
//! * [`modular`]: word-size prime fields, Z_p\[x\], Chinese remainders;
//! * [`crt`]: Chinese remaindering over many word primes by a product tree;
//! * [`modgcd`]: Brown's modular multivariate gcd and the modular Q\[x\] gcd;
//! * [`ratfunc`]: the field Q(s1..sn) of reduced rational functions;
//! * [`upoly`]: dense univariate polynomials over any field object (Q\[x\],
//!   Q(others)\[λ\]);
//! * [`mod@print`]: the one printer (text, LaTeX, the language's syntax) on a
//!   print tree that every ring builds;
//! * [`matrix`]: `Matrix<R>` over a ring object, Bareiss determinant,
//!   adjugate, rank, minors;
//! * [`smith`]: the three honest Smith modes and their certificates;
//! * [`ncpoly`]: non-commutative polynomials (ordered words) and trace
//!   normal forms;
//! * [`eliminate`]: the commutative eliminant of one unknown, its commuted
//!   pairs and its Smith cross-check;
//! * [`ordered`]: the ordered elimination by Schur complements with
//!   explicit inverses;
//! * [`derivation`]: the one [`derivation::Derivation`] per target that
//!   every command consumes (size bound, eliminant, ordered elimination,
//!   commuted pairs).

pub mod crt;
pub mod decimal;
pub mod derivation;
pub mod eliminate;
pub mod gcd;
pub mod intgcd;
pub mod kronecker;
pub mod matrix;
pub mod modgcd;
pub mod modular;
pub mod mpoly;
pub mod ncpoly;
pub mod ordered;
pub mod polyring;
pub mod print;
pub mod qx;
pub mod ratfunc;
pub mod rational;
pub mod ring;
pub mod smith;
pub mod upoly;
