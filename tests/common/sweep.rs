//! A timing sweep over a property test's strategy (issue 15): draws many
//! values from the strategy (the same distribution the property sees, other
//! seeds), runs each mode on each value, measures the thread's CPU time and
//! records failures (panics, uncertified results, disagreements). The
//! `#[ignore]`d `*_sweep` tests call it; they assert nothing about time and
//! fail only on a failure. Environment: `LAMBDAMAT_SWEEP_CASES` (cases per
//! strategy), `LAMBDAMAT_SWEEP_SEED`, `LAMBDAMAT_SWEEP_DIR` (where the
//! slowest inputs are written as .lmx files, and `current.lmx`, the input
//! being run, so that a hang can be found by its file),
//! `LAMBDAMAT_SWEEP_SKIP` (`name:index,…`: known hangs not to run).

use lambdamat::algebra::matrix::Matrix;
use lambdamat::algebra::ring::Ring;
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config, RngSeed, TestRunner};
use std::collections::BTreeMap;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::PathBuf;

/// The calling thread's CPU time in seconds.
pub fn thread_cpu() -> f64 {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: clock_gettime writes into the timespec we own.
    let rc = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    assert_eq!(rc, 0, "clock_gettime");
    ts.tv_sec as f64 + ts.tv_nsec as f64 * 1e-9
}

/// Cases per strategy from the environment (`default` otherwise).
pub fn cases(default: usize) -> usize {
    std::env::var("LAMBDAMAT_SWEEP_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default)
}

/// `n` values drawn from `strategy` with a fixed seed derived from `tag`
/// and `LAMBDAMAT_SWEEP_SEED`.
pub fn draw<S: Strategy>(strategy: &S, tag: u64, n: usize) -> Vec<S::Value> {
    let seed: u64 = std::env::var("LAMBDAMAT_SWEEP_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1);
    let mut runner = TestRunner::new(Config {
        rng_seed: RngSeed::Fixed(seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ tag),
        ..Config::default()
    });
    (0..n)
        .map(|_| strategy.new_tree(&mut runner).expect("value").current())
        .collect()
}

/// A matrix as a lambdamat source file (`var …`, `matrix A = […]`,
/// `smith A`), so that a case can be fed to the binary.
pub fn lmx_file<R: Ring>(names: &[String], a: &Matrix<R>) -> String {
    let rows: Vec<String> = a
        .lmx_rows()
        .iter()
        .map(|r| format!("  {}", r.join(", ")))
        .collect();
    let var = if names.is_empty() {
        String::new()
    } else {
        format!("var {}\n", names.join(", "))
    };
    format!("{var}matrix A = [\n{}\n]\nsmith A\n", rows.join(";\n"))
}

/// Cases at least this slow (CPU seconds) are printed when they finish.
pub const SLOW_SECONDS: f64 = 0.5;

struct Case {
    cpu: f64,
    index: usize,
    input: String,
}

/// Times and failures per (strategy, mode).
pub struct Sweep {
    name: String,
    dir: PathBuf,
    times: BTreeMap<String, Vec<f64>>,
    slowest: Vec<(String, Case)>,
    failures: Vec<String>,
}

impl Sweep {
    pub fn new(name: &str) -> Self {
        let dir = PathBuf::from(
            std::env::var("LAMBDAMAT_SWEEP_DIR").unwrap_or_else(|_| "/tmp/lambdamat_sweep".into()),
        );
        std::fs::create_dir_all(&dir).expect("sweep directory");
        Sweep {
            name: name.to_string(),
            dir,
            times: BTreeMap::new(),
            slowest: Vec::new(),
            failures: Vec::new(),
        }
    }

    /// Runs `f` on case `index` (source `input`) as `mode`, timing it; an
    /// `Err` or a panic is recorded as a failure.
    pub fn run(
        &mut self,
        mode: &str,
        index: usize,
        input: &str,
        f: impl FnOnce() -> Result<(), String>,
    ) {
        let key = format!("{}:{index}", self.name);
        let skip = std::env::var("LAMBDAMAT_SWEEP_SKIP").unwrap_or_default();
        if skip.split(',').any(|k| k == key) {
            println!("skipped (LAMBDAMAT_SWEEP_SKIP): {key} {mode}");
            return;
        }
        std::fs::write(
            self.dir.join("current.lmx"),
            format!("# {} {mode} case {index}\n{input}", self.name),
        )
        .expect("write current case");
        let t0 = thread_cpu();
        let out = catch_unwind(AssertUnwindSafe(f));
        let cpu = thread_cpu() - t0;
        match out {
            Ok(Ok(())) => {}
            Ok(Err(e)) => self
                .failures
                .push(format!("{mode} case {index}: {e}\n{input}")),
            Err(_) => self
                .failures
                .push(format!("{mode} case {index}: panic\n{input}")),
        }
        if cpu >= SLOW_SECONDS {
            // Shown at once: a later case may hang the sweep.
            println!(
                "slow case: {} {mode} case {index}: {cpu:.2} s\n{input}",
                self.name
            );
        }
        self.times.entry(mode.to_string()).or_default().push(cpu);
        self.slowest.push((
            mode.to_string(),
            Case {
                cpu,
                index,
                input: input.to_string(),
            },
        ));
        self.slowest
            .sort_by(|a, b| b.1.cpu.partial_cmp(&a.1.cpu).expect("finite"));
        self.slowest.truncate(5);
    }

    /// Prints the distribution per mode and the five slowest cases (their
    /// inputs are written to the sweep directory); panics on any failure.
    pub fn finish(self) {
        println!("== {} ==", self.name);
        println!(
            "{:<28} {:>6} {:>10} {:>10} {:>10} {:>10}",
            "mode", "cases", "median s", "p99 s", "max s", "total s"
        );
        for (mode, t) in &self.times {
            let mut s = t.clone();
            s.sort_by(|a, b| a.partial_cmp(b).expect("finite"));
            let q = |p: f64| s[((s.len() - 1) as f64 * p).round() as usize];
            println!(
                "{:<28} {:>6} {:>10.5} {:>10.5} {:>10.5} {:>10.3}",
                mode,
                s.len(),
                q(0.5),
                q(0.99),
                q(1.0),
                s.iter().sum::<f64>()
            );
        }
        for (k, (mode, c)) in self.slowest.iter().enumerate() {
            let file = self.dir.join(format!("{}_slow{}.lmx", self.name, k + 1));
            std::fs::write(&file, &c.input).expect("write slow case");
            println!(
                "slow {}: {mode} case {} {:.4} s -> {}",
                k + 1,
                c.index,
                c.cpu,
                file.display()
            );
        }
        for f in &self.failures {
            println!("FAILURE {f}");
        }
        assert!(self.failures.is_empty(), "{} failures", self.failures.len());
    }
}
