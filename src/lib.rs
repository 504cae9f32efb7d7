//! lambdamat turns systems of linear operator equations into exact algebra
//! and then into numerical solvers.
//!
//! The crate is split along the pipeline; each folder is
//! one stage and may only depend on the stages before it:
//!
//! * `lang`: text → spanned AST → validated, lowered objects (the only
//!   place that knows about source positions and names);
//! * `algebra`: exact rationals, polynomials, rational functions, matrices
//!   over a ring object and the certified Smith normal form (never `f64`);
//! * `system`: the span-free lowered program shared by algebra and numerics;
//! * `numeric`: f64 numerics (nalgebra): quadrature, graded meshes,
//!   product integration of Abel kernels, operator matrices, solves;
//! * `plan`: a language system → numerical plan (kernels compiled to
//!   closures, discretisation, coupled/ordered/commutative solves);
//! * `hertz`: the flagship Hertz contact problem with finite friction,
//!   built on `numeric`;
//! * `reduce`: one equation for one unknown of an operator system (the
//!   commutative eliminant, its expansion into iterated integrals, the
//!   ordered elimination), built from `algebra` and `system`;
//! * `codegen`: a language system → a standalone Rust solver module
//!   (kernels as Rust functions, solved through `plan` and `numeric`);
//! * `report`: the one report of a numerical solve (every file, one
//!   entry `report::solve`) and its text, JSON, CSV and SVG;
//! * [`standalone`]: the `main` of generated solvers (no command-line
//!   crates: they build with `default-features = false`);
//! * `api` (with or without the feature `cli`): the small entry point —
//!   `Problem` with its methods `smith`, `reduce`, `codegen` and `solve`,
//!   their values and one `Error` — re-exported here; the CLI and the
//!   Python package are its clients;
//! * `cli` (feature `cli`): the `lambdamat` command line (clap, miette's
//!   fancy output, plotters, indicatif), run by `cli_main`.
//!
//! The public surface is `api` (its names re-exported here) and
//! [`standalone`], which generated solvers build against. The other modules
//! are public only with the feature `internals`: unstable internals for the
//! project's own tests, benches and probes; not part of the API.

// Every public item is documented; the internals, public only for the
// project's own tests with the feature `internals`, are not API.
#![cfg_attr(not(feature = "internals"), warn(missing_docs))]
// Without the command line (`default-features = false`, the build generated
// solvers and the Python package depend on) and without `internals`, only
// `api` and `standalone` are public: the parts of the pipeline only the
// command line uses are compiled but unreachable, so their dead code (and
// the imports only that code uses) are expected there. The
// default build and the `internals` build keep the dead-code lint.
#![cfg_attr(
    not(any(feature = "cli", feature = "internals")),
    allow(dead_code, unused_imports)
)]

/// Declares internal modules: public with the feature `internals` (the
/// project's own tests, benches and probes), crate-private otherwise.
macro_rules! internal {
    ($($(#[$attr:meta])* $name:ident;)*) => {$(
        $(#[$attr])*
        #[cfg(feature = "internals")]
        pub mod $name;
        $(#[$attr])*
        #[cfg(not(feature = "internals"))]
        pub(crate) mod $name;
    )*};
}

internal! {
    algebra;
    #[cfg(feature = "cli")]
    cli;
    codegen;
    error;
    hertz;
    lang;
    numeric;
    plan;
    reduce;
    report;
    system;
}

pub mod api;
pub mod standalone;

/// Runs the `lambdamat` command line on the process's arguments and
/// returns its exit code. Public because the binary (`src/main.rs`) is a
/// crate of its own; it is the binary's whole `main`.
#[cfg(feature = "cli")]
pub fn cli_main() -> i32 {
    cli::main()
}

pub use api::{
    Error, ErrorKind, Field, Location, Method, Problem, RationalFunction, Reduction, SmithForm,
    SmithOptions, Solution, SolveOptions,
};

/// The README's Rust blocks, run as doc tests (`cargo test --doc`).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
