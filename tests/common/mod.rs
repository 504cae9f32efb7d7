//! Helpers shared by the test files (`mod common;` in each): language
//! helpers here, CLI helpers in [`cli`].
#![allow(dead_code)]

pub mod cli;
pub mod sweep;

/// Spence's published (ν, μ, c) triples: the library's one copy.
#[allow(unused_imports)]
pub use lambdamat::hertz::tables::SPENCE;

use lambdamat::lang::{ErrorKind, LangErrors, Program, parse_program};

/// Parses `src`, panicking with the rendered errors if it is invalid.
pub fn ok(src: &str) -> Program {
    match parse_program(src, "t.lmx") {
        Ok(p) => p,
        Err(e) => panic!("unexpected errors:\n{}", e.render()),
    }
}

/// The errors of `src`, panicking if it is valid.
pub fn errs(src: &str) -> LangErrors {
    match parse_program(src, "t.lmx") {
        Ok(p) => panic!("expected errors, got {p:?}"),
        Err(e) => e,
    }
}

/// (kind, message, line, column) of every error.
pub fn summary(src: &str) -> Vec<(ErrorKind, String, usize, usize)> {
    let e = errs(src);
    e.errors()
        .iter()
        .map(|x| {
            let (l, c) = e.line_col(x.span);
            (x.kind, x.message.clone(), l, c)
        })
        .collect()
}

/// The single error of `src`: kind, message and line:column.
pub fn single(src: &str) -> (ErrorKind, String, usize, usize) {
    let mut all = summary(src);
    assert_eq!(all.len(), 1, "{all:?}");
    all.remove(0)
}
