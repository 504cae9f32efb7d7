//! The `lambdamat` command line (clap) and report formatting (text, LaTeX,
//! JSON). It owns exit codes (0 ok, 1 usage, 2 invalid input, 3 numerical
//! failure) and never does algebra or parsing itself: it calls [`crate::lang`]
//! and [`crate::algebra`] and prints what they return.

/// Entry point used by the binary; returns the process exit code.
pub fn main() -> i32 {
    0
}
