//! Times `Problem::solve` from Rust, the reference for the Python
//! package's overhead (`python/tests/timing.py` times the same solves):
//! `cargo run --release --example api_timing -- N [CASE]`. Prints the median
//! CPU time of the process over N solves of each case, in milliseconds
//! (CPU time, so that a busy machine changes the ratio little).
use lambdamat::{Problem, SolveOptions};

/// CPU time of this process, in milliseconds.
fn cpu_ms() -> f64 {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `ts` is a valid timespec for clock_gettime to write.
    unsafe { libc::clock_gettime(libc::CLOCK_PROCESS_CPUTIME_ID, &mut ts) };
    ts.tv_sec as f64 * 1e3 + ts.tv_nsec as f64 * 1e-6
}

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
    // An optional second argument runs only the case of that label.
    let only = std::env::args().nth(2);
    for (label, path, set, tol) in cases {
        if only.as_deref().is_some_and(|o| o != label) {
            continue;
        }
        let p = Problem::from_file(path)?;
        let opts = SolveOptions {
            set,
            tol,
            ..SolveOptions::default()
        };
        let times: Vec<f64> = (0..n)
            .map(|_| {
                let t = cpu_ms();
                let s = p.solve(&opts);
                let dt = cpu_ms() - t;
                assert!(s.is_ok_and(|s| s.converged));
                dt
            })
            .collect();
        println!("{label} {:.3}", median(times));
    }
    Ok(())
}
