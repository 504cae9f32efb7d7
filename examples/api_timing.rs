//! Times `Problem::solve` from Rust, the reference for the Python
//! package's overhead (`python/tests/timing.py` times the same solves):
//! `cargo run --release --example api_timing -- N`. Prints the median
//! wall time of N solves of each case, in milliseconds.
use lambdamat::{Problem, SolveOptions};
use std::time::Instant;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() -> Result<(), lambdamat::Error> {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(21);
    let cases = [
        ("mms", "examples/mms.lmx", vec![], 1e-10),
        (
            "hertz",
            "examples/hertz.lmx",
            vec![
                ("nu".to_string(), "0.3".to_string()),
                ("mu".to_string(), "0.5".to_string()),
            ],
            1e-8,
        ),
    ];
    for (label, path, set, tol) in cases {
        let p = Problem::from_file(path)?;
        let opts = SolveOptions {
            set,
            tol,
            ..SolveOptions::default()
        };
        let times: Vec<f64> = (0..n)
            .map(|_| {
                let t = Instant::now();
                let s = p.solve(&opts);
                let dt = t.elapsed().as_secs_f64() * 1e3;
                assert!(s.is_ok_and(|s| s.converged));
                dt
            })
            .collect();
        println!("{label} {:.3}", median(times));
    }
    Ok(())
}
