//! The Hertz contact problem with finite friction (docs/hertz.md), a
//! client of the general solver.
//!
//! * [`front`]: what `lambdamat hertz` runs: the language files
//!   `src/hertz/hertz*.lmx` (user copies in `examples/`) through the one
//!   solve entry [`crate::report`], and the fields, slip and checks read off
//!   their solution. This is the one numerical implementation behind the
//!   command line.
//! * [`seed`]: the seed paper's literal algorithm (a different model), on
//!   its own small discretisation, for the `hertz table` comparison column;
//! * [`tables`]: the published values compared with (Spence's, the seed's
//!   tables), written once;
//! * [`error`]: the seed's error enum.
//!
//! The hand-written solver that preceded the language is kept as the
//! tests' independent oracle (`tests/common/hertz_oracle/`).
//!
//! ```no_run
//! use lambdamat::hertz::front::{Given, solve};
//! use lambdamat::plan::SplitOptions;
//! let s = solve(0.25, Given::Mu(0.1801), &SplitOptions::default()).unwrap();
//! println!("c = {}", s.c);
//! ```
pub mod error;
pub mod front;
pub mod seed;
pub mod tables;

#[cfg(feature = "internals")]
pub use error::HertzError;
