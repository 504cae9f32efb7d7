//! Probes the discrete free-boundary condition `B(c)` of the Hertz file at
//! small stick radii (issue 13, the "staircase" at μ = 0.01): per `c`, `B`
//! on one level, the system size, the mesh beside `c` (the first panel
//! right of `c` relative to `c`) and the fields `p`, `q` just beside `c`.
//! Owns only this driving and printing; every number comes from the
//! library.
//!
//! ```text
//! cargo run --release --example smallc_probe -- NU MU LEVEL C0 C1 N
//! ```
use lambdamat::hertz::front::{GIVEN_MU, program};
use lambdamat::plan::SplitInput;
use lambdamat::plan::split::{SplitLevel, SplitProblem};

fn main() {
    if let Err(e) = run() {
        eprintln!("smallc_probe: {e}");
        std::process::exit(2);
    }
}

fn run() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let num = |i: usize| -> Result<f64, String> {
        args.get(i)
            .and_then(|s| s.parse().ok())
            .ok_or_else(|| "usage: smallc_probe NU MU LEVEL C0 C1 N [fields]".to_string())
    };
    let (nu, mu, k) = (num(0)?, num(1)?, num(2)? as usize);
    let (c0, c1, n) = (num(3)?, num(4)?, num(5)? as usize);
    let fields = args.get(6).is_some_and(|s| s == "fields");
    let prog = program(GIVEN_MU, &[("nu", nu), ("mu", mu)]).map_err(|e| e.to_string())?;
    let input = SplitInput::from_program(&prog).map_err(|e| e.to_string())?;
    let pb = SplitProblem::from_input(input).map_err(|e| e.to_string())?;
    let lvl = SplitLevel::level(k);
    for i in 0..n {
        let f = if n > 1 {
            i as f64 / (n - 1) as f64
        } else {
            0.0
        };
        let c = c0 * (c1 / c0).powf(f);
        let d = pb.discretise(&[c], &lvl).map_err(|e| e.to_string())?;
        let b = pb.coefficient(&d, 0).ok_or("no coefficient B")?;
        let pbasis = d.bases[0].as_ref().ok_or("no basis for p")?;
        let right = pbasis
            .panels
            .iter()
            .find(|p| p.a >= c)
            .map_or(f64::NAN, |p| (p.b - p.a) / c);
        let layers = pbasis
            .panels
            .iter()
            .filter(|p| p.a >= c && p.b <= 0.5 * (1.0 + c))
            .count();
        println!(
            "c = {c:.6e}: B = {b:.9e}, dim {}, cond {:.2e}, first slip panel/c {right:.3e}, slip panels to mid {layers}",
            d.solution.len(),
            d.cond
        );
        if fields {
            for e in [1e-1, 1e-2, 1e-3, 1e-4, 1e-5] {
                let xp = c * (1.0 + e);
                let xm = c * (1.0 - e);
                println!(
                    "   x/c-1 = ±{e:.0e}: p(c+) {:.9e} p(c-) {:.9e} q(c-) {:.9e}",
                    pb.value(&d, 0, xp),
                    pb.value(&d, 0, xm),
                    pb.value(&d, 1, xm)
                );
            }
            for e in [1e-6, 1e-4, 1e-2, 0.5, 1.0, 2.0, 10.0, 100.0] {
                let x = c * e;
                if x < 1.0 {
                    println!(
                        "   x/c = {e:.0e}: p {:.9e} q {:.9e}",
                        pb.value(&d, 0, x),
                        pb.value(&d, 1, x)
                    );
                }
            }
        }
    }
    Ok(())
}
