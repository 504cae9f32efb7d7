//! Diagnostic (issue 13, the edges ν → 1/2 and ν → −1): the outputs of
//! `examples/hertz.lmx` with the stick radius held fixed (the problem the
//! end answers of `plan::split_end` evaluate), at `1 − c = w` for a list
//! of `w`, on the given refinement levels, with the discrete condition `B`.
//!
//! `cargo run --release --example edges_probe -- NU MU LEVELS W...`
//! (`LEVELS` like `0,2,4`).
use lambdamat::lang::parse_program_with;
use lambdamat::lang::parser::parse_exact;
use lambdamat::plan::split::{SplitLevel, SplitProblem};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.len() < 4 {
        eprintln!("usage: edges_probe NU MU LEVELS W...");
        std::process::exit(2);
    }
    let src = include_str!("../examples/hertz.lmx");
    let sets: Vec<_> = [("nu", &args[0]), ("mu", &args[1])]
        .iter()
        .filter_map(|(n, v)| parse_exact(v).map(|q| (n.to_string(), q)))
        .collect();
    let Ok(prog) = parse_program_with(src, "examples/hertz.lmx", &sets) else {
        std::process::exit(2);
    };
    let Ok(problem) = SplitProblem::new(&prog) else {
        std::process::exit(2);
    };
    let levels: Vec<usize> = args[2].split(',').filter_map(|s| s.parse().ok()).collect();
    for w in args[3..].iter().filter_map(|s| s.parse::<f64>().ok()) {
        for &k in &levels {
            let lvl = SplitLevel::level(k);
            let c = 1.0 - w;
            match problem.discretise(&[c], &lvl) {
                Ok(d) => {
                    let o: Vec<String> = (0..2)
                        .map(|i| {
                            problem
                                .output(&d, i)
                                .map_or("err".into(), |v| format!("{v:.16}"))
                        })
                        .collect();
                    println!(
                        "w={w:.3e} level {k}: B={:+.6e} P={} P_shear={} dim {} cond {:.1e}",
                        d.residuals[0],
                        o[0],
                        o[1],
                        SplitProblem::size(&d),
                        d.cond
                    );
                }
                Err(e) => println!("w={w:.3e} level {k}: {e}"),
            }
        }
    }
}
