//! The split solver's pointwise estimates of the unknowns bound their true
//! errors on manufactured problems whose exact unknowns are known
//! (`examples/hertz_split_mms.lmx`: p = x, q = 4x³ on [0, 1/2) and
//! q = μp = x on [1/2, 1]), on every level the ladder reports from, and
//! a method the split solver does not run is refused.
use lambdamat::lang::parse_program;
use lambdamat::plan::split_fields::LevelFields;
use lambdamat::plan::{Method, PlanError, SplitOptions, solve_split_fields};

fn exact(u: &str, x: f64) -> f64 {
    match u {
        "p" => x,
        _ if x < 0.5 => 4.0 * x * x * x,
        _ => x,
    }
}

#[test]
fn pointwise_estimates_bound_the_errors_of_the_manufactured_fields() {
    let text = std::fs::read_to_string("examples/hertz_split_mms.lmx").expect("example");
    let prog = parse_program(&text, "examples/hertz_split_mms.lmx").expect("parses");
    let mut compared = 0;
    for max_level in [3, 4, 6] {
        let opts = SplitOptions {
            max_level,
            ..SplitOptions::default()
        };
        let s = solve_split_fields(&prog, &opts).expect("solves");
        let lf = LevelFields::new(&s).expect("fields");
        for (u, name) in s.problem.sys.unknowns.iter().enumerate() {
            let g = lf.on_grid(u, 101, true).expect("grid");
            let worst = g.errors.iter().fold(0.0f64, |m, &e| m.max(e));
            let est = s.report.unknowns.iter().find(|e| &e.name == name);
            assert!(
                est.is_some_and(|e| e.error == worst),
                "{name}: the report's estimate is the grid's largest"
            );
            for ((x, v), e) in g.x.iter().zip(&g.values).zip(&g.errors) {
                let err = (v - exact(name, *x)).abs();
                assert!(
                    err <= *e,
                    "level cap {max_level}, {name}({x}): error {err:.2e} > estimate {e:.2e}"
                );
                compared += usize::from(e.is_finite());
            }
        }
    }
    // Finite estimates only count: an infinite one bounds anything.
    assert!(compared >= 500, "only {compared} finite estimates compared");
}

#[test]
fn a_method_the_split_solver_does_not_run_is_refused() {
    let text = std::fs::read_to_string("examples/hertz_split_mms.lmx").expect("example");
    let prog = parse_program(&text, "examples/hertz_split_mms.lmx").expect("parses");
    for method in [Method::Ordered, Method::Commutative] {
        let opts = SplitOptions {
            method,
            ..SplitOptions::default()
        };
        match solve_split_fields(&prog, &opts) {
            Err(PlanError::Invalid(m)) => assert!(m.contains(method.name()), "{m}"),
            other => panic!(
                "{method}: expected a refusal, got {:?}",
                other.map(|s| s.report)
            ),
        }
    }
}
