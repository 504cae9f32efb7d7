//! Temporary probe: condition and outputs at fixed scalar values near an end.
use lambdamat::lang::parse_program_with;
use lambdamat::lang::parser::parse_exact;
use lambdamat::plan::split::{SplitLevel, SplitProblem};

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let nu: f64 = a[1].parse().unwrap();
    let mu: f64 = a[2].parse().unwrap();
    let level: usize = a[3].parse().unwrap();
    let xs: Vec<f64> = a[4..].iter().map(|s| s.parse().unwrap()).collect();
    let src = include_str!("hertz.lmx");
    let sets: Vec<_> = [("nu", nu), ("mu", mu)]
        .iter()
        .map(|(n, v)| (n.to_string(), parse_exact(&v.to_string()).unwrap()))
        .collect();
    let prog = parse_program_with(src, "examples/hertz.lmx", &sets).unwrap();
    let pb = SplitProblem::new(&prog).unwrap();
    let lvl = SplitLevel::level(level);
    for x in xs {
        match pb.discretise(&[x], &lvl) {
            Ok(d) => {
                let p = pb.output(&d, 0).unwrap();
                let ps = pb.output(&d, 1).unwrap();
                println!(
                    "{x:.6e} 1-x={:.6e} B={:.6e} P={p:.17} Ps={ps:.17}",
                    1.0 - x,
                    d.residuals[0]
                );
            }
            Err(e) => println!("{x:.6e} err {e}"),
        }
    }
}
