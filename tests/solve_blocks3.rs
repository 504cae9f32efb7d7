//! A manufactured 3×3 system through the language path: the Hertz
//! operators coupled with a smooth operator and the identity. Exact
//! solution `p = 1, q = x, r = x²`. The ordered block elimination (which
//! pivots on the unknowns' own equations) and the coupled solve must both
//! recover it; the commutative model must at least be computed from the
//! algebra's det/adj (det here is `k1 k4 - k2 k3`).
use lambdamat::plan::{Method, SolveOptions, solve_program};

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
        let opts = SolveOptions {
            method,
            ..SolveOptions::default()
        };
        let r = solve_program(&prog, &opts).expect("solves");
        assert_eq!(r.unknowns.len(), 3);
        for (u, f) in r.unknowns.iter().zip(exact) {
            let e =
                u.x.iter()
                    .zip(&u.values)
                    .map(|(x, v)| (v - f(*x)).abs())
                    .fold(0.0, f64::max);
            eprintln!("{method}: {} max error {e:.1e}", u.name);
            assert!(e <= 1e-10, "{method}: {} error {e:e}", u.name);
        }
        let big_r = r.outputs[0].1.expect("R");
        assert!((big_r - 1.0 / 3.0).abs() <= 1e-10, "R = {big_r}");
    }
    let opts = SolveOptions {
        method: Method::Commutative,
        max_level: 3,
        ..SolveOptions::default()
    };
    let m = solve_program(&prog, &opts).expect("the model is computed");
    assert!(m.model);
    assert_eq!(m.unknowns.len(), 1);
    assert!(m.commutator_defects.iter().any(|d| d.pair == ["k2", "k4"]));
}
