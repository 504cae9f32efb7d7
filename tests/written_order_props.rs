//! Property test of issue 9: random small systems of two unknowns whose
//! operators mix Volterra, Fredholm and Abel integrals and products of
//! them in either order. `coupled` (one block system) and `ordered` (the
//! derivation's Schur elimination) must agree to 1e-9 wherever both
//! converge. Seeds are fixed so every run sees the same cases.

use lambdamat::lang::parse_program;
use lambdamat::plan::Method;
use lambdamat::report::{Report, SolveSettings, solve};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed, TestRunner};
use std::cell::Cell;

const OPERATORS: &str = "operator V = int(0..x) (1 + t) dt\n\
     operator F = int(0..1) (x*t - 1/2) dt\n\
     operator A = int(0..x) t/sqrt(x^2 - t^2) dt\n";
const NAMES: [&str; 3] = ["V", "F", "A"];

/// One term `c*W` of an entry: a coefficient in [-1/2, 1/2] and a word of
/// one or two symbols (products in the order generated).
fn term() -> impl Strategy<Value = String> {
    (-4i32..=4, proptest::collection::vec(0usize..3, 1..=2)).prop_map(|(c, w)| {
        let word: Vec<&str> = w.iter().map(|&s| NAMES[s]).collect();
        format!("{c}/8*{}", word.join("*"))
    })
}

/// The text of a system `u + Σ terms = rhs` for two unknowns.
fn system() -> impl Strategy<Value = String> {
    proptest::collection::vec(proptest::collection::vec(term(), 1..=2), 4).prop_map(|e| {
        let entry = |k: usize| e[k].join(" + ");
        format!(
            "{OPERATORS}unknown p, q\n\
             equation p + ({}) p + ({}) q = 1 + x\n\
             equation q + ({}) p + ({}) q = x^2\n\
             solve for p\noutput P = int(0..1) p(x) dx\n",
            entry(0),
            entry(1),
            entry(2),
            entry(3)
        )
    })
}

fn values(r: &Report, name: &str) -> Vec<f64> {
    r.unknowns
        .get(name)
        .map(|u| u.values.clone())
        .unwrap_or_default()
}

#[test]
fn coupled_and_ordered_agree_on_random_operator_systems() {
    let mut runner = TestRunner::new(Config {
        cases: 16,
        rng_seed: RngSeed::Fixed(0x5eed_0009),
        ..Config::default()
    });
    let compared = Cell::new(0usize);
    runner
        .run(&system(), |src| {
            let prog = parse_program(&src, "random.lmx").expect("valid system");
            let run = |method| {
                solve(
                    &prog,
                    &SolveSettings {
                        method: Some(method),
                        max_level: 5,
                        ..SolveSettings::default()
                    },
                )
            };
            let (Ok(c), Ok(o)) = (run(Method::Coupled), run(Method::Ordered)) else {
                return Ok(());
            };
            if !(c.converged && o.converged) {
                return Ok(());
            }
            compared.set(compared.get() + 1);
            for name in ["p", "q"] {
                let (a, b) = (values(&c, name), values(&o, name));
                prop_assert_eq!(a.len(), b.len());
                let scale = a.iter().fold(1.0f64, |m, v| m.max(v.abs()));
                let diff = a
                    .iter()
                    .zip(&b)
                    .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
                prop_assert!(
                    diff <= 1e-9 * scale,
                    "{}: {} differs by {:e}\n{}",
                    name,
                    name,
                    diff,
                    src
                );
            }
            Ok(())
        })
        .expect("coupled and ordered agree");
    assert!(
        compared.get() >= 8,
        "only {} of 16 random systems converged with both methods",
        compared.get()
    );
}
