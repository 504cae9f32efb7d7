//! lambdamat turns systems of linear operator equations into exact algebra
//! and then into numerical solvers.
//!
//! The crate is split along the pipeline; each folder is
//! one stage and may only depend on the stages before it:
//!
//! * [`lang`]: text → spanned AST → validated, lowered objects (the only
//!   place that knows about source positions and names);
//! * [`algebra`]: exact rationals, polynomials, rational functions, matrices
//!   over a ring object and the certified Smith normal form (never `f64`);
//! * [`system`]: the span-free lowered program shared by algebra and numerics;
//! * [`numeric`]: f64 numerics (nalgebra): quadrature, graded meshes,
//!   product integration of Abel kernels, operator matrices, solves;
//! * [`plan`]: a language system → numerical plan (kernels compiled to
//!   closures, discretisation, coupled/ordered/commutative solves);
//! * [`hertz`]: the flagship Hertz contact problem with finite friction,
//!   built on [`numeric`];
//! * [`reduce`]: one equation for one unknown of an operator system (the
//!   commutative eliminant, its expansion into iterated integrals, the
//!   ordered elimination), built from [`algebra`] and [`system`];
//! * [`codegen`]: a language system → a standalone Rust solver module
//!   (kernels as Rust functions, solved through [`plan`] and [`numeric`]);
//! * [`report`]: the one report of a numerical solve (every file, one
//!   entry [`report::solve`]) and its text, JSON, CSV and SVG;
//! * [`api`]: the small entry point — [`Problem`] with its methods
//!   `smith`, `reduce`, `codegen` and `solve`, their values and one
//!   [`Error`] — re-exported here; the CLI and the Python package are its
//!   clients;
//! * [`cli`]: the `lambdamat` command line and its text/LaTeX/JSON reports.
pub mod algebra;
pub mod api;
pub mod cli;
pub mod codegen;
pub mod hertz;
pub mod lang;
pub mod numeric;
pub mod plan;
pub mod reduce;
pub mod report;
pub mod system;

pub use api::{
    Error, ErrorKind, Field, Location, Method, Problem, Reduction, SmithForm, SmithOptions,
    Solution, SolveOptions,
};
