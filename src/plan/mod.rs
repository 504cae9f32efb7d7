//! Solving a system written in the language: the bridge from the lowered
//! [`crate::system::Program`] to the numeric layer. It owns compiling kernel
//! expressions to closures, mapping operator definitions to
//! [`crate::numeric::Operator`]s, discretising operator polynomials on a
//! mesh split at the file's breakpoints, the three solution methods and the
//! refinement ladder: one solver for every file. It must not
//! parse, must not do quadrature itself (that is [`crate::numeric`]'s job)
//! and must not print anything (that is [`crate::cli`]'s job).
//!
//! * [`error`]: [`PlanError`] (unsupported input vs failed numerics);
//! * [`compile`]: expression trees → closures, Abel-factor recognition;
//! * [`compiled`]: the compiled system (what the solver solves; built from a
//!   program or by code `lambdamat codegen` wrote);
//! * [`operators`]: operator definitions → numeric operators;
//! * [`method`]: the methods a user chooses and the ordered block
//!   elimination they share;
//! * [`split`]: one discretisation level of a problem (a file on one
//!   interval is a split problem with no breakpoints and no scalars);
//! * [`split_input`]: its input (built from a program or by generated code);
//! * [`split_solve`]: its scalar root solve and refinement ladder;
//! * [`split_methods`]: its `ordered` (and `commutative`) methods;
//! * [`split_scalars`]: the joint root solve of several scalars;
//! * [`split_ends`]: the ladder's end check (grading undeclared singular
//!   ends when they matter);
//! * [`split_weights`]: its automatic end weights (per unknown, from the
//!   equations and unknowns only);
//! * [`split_fields`]: the unknowns and equation residuals of a solved
//!   split-domain problem at any point;
//! * [`uniqueness`]: equations with more than one solution, recognised
//!   from their operators.

pub mod compile;
pub mod compiled;
pub mod error;
pub mod features;
pub mod method;
pub mod operators;
pub mod split;
pub mod split_end;
pub mod split_ends;
pub mod split_fields;
pub mod split_input;
pub mod split_methods;
pub mod split_scalars;
pub mod split_solve;
pub mod split_weights;
pub mod uniqueness;

pub use compiled::CompiledSystem;
pub use error::PlanError;
pub use method::Method;
pub use split_input::SplitInput;
pub use split_solve::{SplitOptions, SplitReport, SplitSolution};
#[cfg(feature = "internals")]
pub use split_solve::{solve_split, solve_split_fields, solve_split_input, solve_split_input_fields};

/// One factor of a weight as reports print it, for a point `at` and an
/// exponent `e`: the distance to the point is written as the user would
/// (`x`, `x + 2`, `x - 1/2` as `x - 0.5`), as `|…|` on a split domain where
/// the weight holds on both sides of its point, else oriented so that it is
/// positive on the interval: `x^(0.5)`, `(x + 2)^(-0.5)`, `(1 - x)^(-0.5)`.
pub fn weight_factor_text(at: f64, e: f64, side: WeightSide) -> String {
    let shifted = if at == 0.0 {
        "x".to_string()
    } else if at < 0.0 {
        format!("x + {}", -at)
    } else {
        format!("x - {at}")
    };
    match side {
        WeightSide::Both if at == 0.0 => format!("|x|^({e})"),
        WeightSide::Both => format!("|{shifted}|^({e})"),
        WeightSide::Above if at == 0.0 => format!("x^({e})"),
        WeightSide::Above => format!("({shifted})^({e})"),
        WeightSide::Below if at == 0.0 => format!("(-x)^({e})"),
        WeightSide::Below if at < 0.0 => format!("(-{} - x)^({e})", -at),
        WeightSide::Below => format!("({at} - x)^({e})"),
    }
}

/// Where a weight factor's unknown lies relative to its point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WeightSide {
    /// On both sides (a split domain): the factor is `|x - at|^e`.
    Both,
    /// Above the point (`at` is the interval's left end).
    Above,
    /// Below the point (`at` is the interval's right end).
    Below,
}

#[cfg(test)]
mod weight_text_tests {
    use super::{WeightSide::*, weight_factor_text as w};

    #[test]
    fn weight_factors_read_as_written() {
        assert_eq!(w(0.0, 0.5, Above), "x^(0.5)");
        assert_eq!(w(-2.0, -0.5, Above), "(x + 2)^(-0.5)");
        assert_eq!(w(0.25, -0.5, Above), "(x - 0.25)^(-0.5)");
        assert_eq!(w(1.0, -0.5, Below), "(1 - x)^(-0.5)");
        assert_eq!(w(-1.0, 0.5, Below), "(-1 - x)^(0.5)");
        assert_eq!(w(0.0, 0.5, Below), "(-x)^(0.5)");
        assert_eq!(w(0.0, -0.25, Both), "|x|^(-0.25)");
        assert_eq!(w(-1.0, -0.5, Both), "|x + 1|^(-0.5)");
        assert_eq!(w(1.0, -0.5, Both), "|x - 1|^(-0.5)");
    }
}
