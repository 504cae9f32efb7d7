//! A manufactured 3×3 system through the language path: the Hertz
//! operators coupled with a smooth operator and the identity. Exact
//! solution `p = 1, q = x, r = x²`. The ordered block elimination (which
//! pivots on the unknowns' own equations) and the coupled solve must both
//! recover it; the commutative model must at least be computed from the
//! algebra's det/adj (det here is `k1 k4 - k2 k3`).
use lambdamat::plan::Method;
use lambdamat::report::{SolveSettings, solve};

const SRC: &str = "param gamma = 1/3
operator k1 = int(x..1) t/sqrt(t^2 - x^2) dt
operator k2 = -gamma*int(0..1) dt + gamma*int(0..x) x/sqrt(x^2 - t^2) dt
operator k3 = gamma*int(0..x) t/sqrt(x^2 - t^2) dt
operator k4 = -int(x..1) x/sqrt(t^2 - x^2) dt
operator s = int(0..1) x*t dt
unknown p, q, r
equation k1 p + k2 q = sqrt(1 - x^2) + gamma*(x^2 - 1/2)
equation k3 p + k4 q = gamma*x - x*sqrt(1 - x^2)
equation s p + r = x/2 + x^2
output R = int(0..1) r(x) dx
";

#[test]
fn three_unknowns_ordered_and_coupled() {
    let prog = lambdamat::lang::parse_program(SRC, "three.lmx").expect("parses");
    let exact: [fn(f64) -> f64; 3] = [|_| 1.0, |x| x, |x| x * x];
    for method in [Method::Ordered, Method::Coupled] {
        let settings = SolveSettings {
            method: Some(method),
            ..SolveSettings::default()
        };
        let r = solve(&prog, &settings).expect("solves");
        assert!(r.converged, "{method}: {:?}", r.error_estimates);
        assert_eq!(r.unknowns.len(), 3);
        for ((name, u), f) in r.unknowns.iter().zip(exact) {
            let e =
                u.x.iter()
                    .zip(&u.values)
                    .map(|(x, v)| (v - f(*x)).abs())
                    .fold(0.0, f64::max);
            eprintln!("{method}: {name} max error {e:.1e}");
            assert!(e <= 1e-10, "{method}: {name} error {e:e}");
            assert!(
                e <= u.error_estimate.max(1e-14),
                "{method}: {name} estimate"
            );
        }
        let big_r = r.outputs["R"];
        assert!((big_r - 1.0 / 3.0).abs() <= 1e-10, "R = {big_r}");
    }
    let settings = SolveSettings {
        method: Some(Method::Commutative),
        max_level: 3,
        ..SolveSettings::default()
    };
    let m = solve(&prog, &settings).expect("the model is computed");
    assert_eq!(m.extra["model"], true);
    let defects = m.extra["commutator_defects"].as_array().expect("defects");
    assert!(
        defects
            .iter()
            .any(|d| d["pair"] == serde_json::json!(["k2", "k4"])),
        "{defects:?}"
    );
    assert!(
        m.warnings
            .iter()
            .any(|w| w.contains("k2 and k4 do not commute")),
        "{:?}",
        m.warnings
    );
}
