//! A mutation fuzzer that keeps running: it takes the example files and the
//! grammar's tokens, applies seeded random edits (insert, delete, replace,
//! splice, duplicate, huge numbers, deep brackets, stray bytes), and runs
//! every result through the library's whole pipeline with small limits:
//! parse → validate → lower, then the Smith form of small matrices, the
//! reduction for each unknown, code generation and a short numerical solve.
//! Each input must end in `Ok` or an error, never a panic; the time of each
//! input is measured and the slowest is reported.
//!
//! * CI runs a short seeded slice (`fuzz_slice`, a few seconds);
//! * the long run is a documented command (docs/history.md, "Fuzzing"):
//!   `LAMBDAMAT_FUZZ_CASES=1000000 cargo test --release --test fuzz -- --ignored --nocapture --test-threads 1`
//!   with `LAMBDAMAT_FUZZ_SEED` to start elsewhere; it fails on a panic or
//!   on an input slower than `LAMBDAMAT_FUZZ_MAX_SECS` (default 10) and
//!   writes such inputs to `target/tmp/fuzz-findings/`;
//!   `LAMBDAMAT_FUZZ_REPLAY=FILE` runs one such input again and times it.
//!   Times are the process's CPU time on Linux (`/proc/self/stat`, 10 ms
//!   ticks; run it with `--test-threads 1`), wall-clock elsewhere: under `nice` on a loaded machine
//!   an input can take minutes of wall-clock time only waiting for a core.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::time::{Duration, Instant};

use lambdamat::codegen::{Provenance, solver_source};
use lambdamat::lang::{Program, parse_program};
use lambdamat::report::{SolveSettings, solve};

/// The seed corpus: every example and test input of the language.
const CORPUS: &[&str] = &[
    include_str!("../examples/generic3.lmx"),
    include_str!("../examples/hertz_manufactured.lmx"),
    include_str!("../examples/hertz_stick.lmx"),
    include_str!("../examples/matrix_qx.lmx"),
    include_str!("../examples/mms.lmx"),
    include_str!("../examples/punch.lmx"),
    include_str!("../examples/seed_lambda.lmx"),
    include_str!("../examples/singular.lmx"),
    include_str!("data/codegen_terms.lmx"),
    include_str!("data/peers_3x3.lmx"),
];

/// Tokens of the grammar (keywords come from the language itself) and a
/// few troublemakers.
const TOKENS: &[&str] = &[
    "x",
    "t",
    "p",
    "q",
    "k1",
    "k2",
    "A",
    "U",
    "D",
    "V",
    "0",
    "1",
    "2",
    "0.5",
    "1/3",
    "(",
    ")",
    "[",
    "]",
    ",",
    ";",
    "+",
    "-",
    "*",
    "/",
    "^",
    "=",
    "..",
    "#",
    "\n",
    " ",
    "int(0..1)",
    "int(x..1)",
    "int(0..x)",
    " dt",
    " dx",
    "sqrt(",
    "ln(",
    "abs(",
    "exp(",
    "pi",
    "id",
    "t^2 - x^2",
    "x - t",
    "1/(t - x)",
    "^2",
    "^40",
    "^1000",
    "κ",
    "\u{feff}",
    "\u{0}",
    "é",
    "999999999999999999999999",
    "0.000000000000000001",
];

/// SplitMix64: small, seeded, reproducible.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
    fn pick<'a>(&mut self, xs: &[&'a str]) -> &'a str {
        xs[self.below(xs.len())]
    }
}

fn token(rng: &mut Rng) -> String {
    let kw = lambdamat::lang::keywords::KEYWORDS;
    match rng.below(10) {
        0..=2 => format!(" {} ", rng.pick(kw)),
        3 => "9".repeat(1 + rng.below(200)),
        4 => "(".repeat(1 + rng.below(40)),
        _ => rng.pick(TOKENS).to_string(),
    }
}

/// One random edit of `src` (on character boundaries).
fn mutate(src: &str, rng: &mut Rng) -> String {
    let chars: Vec<char> = src.chars().collect();
    let n = chars.len();
    let at = rng.below(n + 1);
    let len = 1 + rng.below(12);
    let end = (at + len).min(n);
    let s = |a: usize, b: usize| chars[a..b].iter().collect::<String>();
    match rng.below(8) {
        0 => format!("{}{}{}", s(0, at), token(rng), s(at, n)),
        1 => format!("{}{}", s(0, at), s(end, n)),
        2 => format!("{}{}{}", s(0, at), token(rng), s(end, n)),
        3 => {
            // Splice a piece of another corpus file.
            let other: Vec<char> = rng.pick(CORPUS).chars().collect();
            let a = rng.below(other.len() + 1);
            let b = (a + rng.below(80)).min(other.len());
            format!(
                "{}{}{}",
                s(0, at),
                other[a..b].iter().collect::<String>(),
                s(at, n)
            )
        }
        4 => {
            // Duplicate a line.
            let lines: Vec<&str> = src.lines().collect();
            if lines.is_empty() {
                return src.to_string();
            }
            let i = rng.below(lines.len());
            let mut out: Vec<&str> = lines.clone();
            out.insert(rng.below(lines.len() + 1), lines[i]);
            out.join("\n")
        }
        5 => {
            // Drop a line.
            let mut lines: Vec<&str> = src.lines().collect();
            if !lines.is_empty() {
                let i = rng.below(lines.len());
                lines.remove(i);
            }
            lines.join("\n")
        }
        6 => {
            // Replace a digit run or a name by another.
            let mut out = s(0, at);
            out.push_str(rng.pick(&["0", "1", "2", "1/2", "x", "t", "p", "-1", "1000000"]));
            out.push_str(&s(end, n));
            out
        }
        _ => format!(
            "{}{}{}",
            s(0, at),
            char::from_u32(rng.next() as u32 % 0x3000).unwrap_or('?'),
            s(at, n)
        ),
    }
}

/// CPU time used by this process so far (user + system, all threads: the
/// front end parses on a worker thread; from `/proc/self/stat`, in clock
/// ticks of 10 ms), or `None` where that file does not exist. Waiting for
/// a core on a loaded machine does not count, unlike wall-clock time. The
/// long run uses one test thread, so the difference is the input's own.
fn process_cpu_time() -> Option<Duration> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // Fields after the command name (which is in parentheses): state is
    // field 3, utime field 14, stime field 15.
    let rest = &stat[stat.rfind(')')? + 2..];
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks: u64 = f.get(11)?.parse::<u64>().ok()? + f.get(12)?.parse::<u64>().ok()?;
    Some(Duration::from_millis(ticks * 10))
}

/// Time spent since `wall`/`cpu` were taken: CPU time where the system
/// gives it, else wall-clock time.
fn spent(wall: Instant, cpu: Option<Duration>) -> Duration {
    match (cpu, process_cpu_time()) {
        (Some(a), Some(b)) => b.saturating_sub(a),
        _ => wall.elapsed(),
    }
}

/// The whole pipeline with small limits; errors are fine, panics are not.
fn pipeline(p: &Program) {
    // Smith forms of small matrices only: the algebra's cost grows fast
    // with size and degree, and this fuzzer looks for crashes.
    for (i, m) in p.matrices.iter().enumerate() {
        let small = m.rows <= 3
            && m.cols <= 3
            && p.symbols.len() <= 4
            && m.entries.iter().all(|e| e.total_degree().unwrap_or(0) <= 4);
        if small {
            let _ = lambdamat::cli::smith::report(p, i, p.principal, false);
        }
    }
    let small_system = p.unknowns.len() <= 3 && p.symbols.len() <= 5;
    if !small_system {
        return;
    }
    for u in 0..p.unknowns.len() {
        let _ = lambdamat::reduce::reduce(p, u);
    }
    let from = Provenance {
        source: "fuzz.lmx".into(),
        command: "fuzz".into(),
    };
    let _ = solver_source(p, None, &from);
    let settings = SolveSettings {
        max_level: 2,
        tol: 1e-3,
        ..SolveSettings::default()
    };
    let _ = solve(p, &settings);
}

/// What one fuzz run found.
#[derive(Default)]
struct Findings {
    cases: usize,
    valid: usize,
    panics: Vec<String>,
    slow: Vec<(Duration, String)>,
    slowest: (Duration, String),
}

fn fuzz(seed: u64, cases: usize, max: Duration) -> Findings {
    let mut rng = Rng(seed);
    let mut f = Findings::default();
    for _ in 0..cases {
        let mut src = rng.pick(CORPUS).to_string();
        for _ in 0..1 + rng.below(4) {
            src = mutate(&src, &mut rng);
        }
        let (start, cpu) = (Instant::now(), process_cpu_time());
        let result = catch_unwind(AssertUnwindSafe(|| {
            match parse_program(&src, "fuzz.lmx") {
                Ok(p) => {
                    pipeline(&p);
                    true
                }
                Err(e) => {
                    // Errors must render (with a position).
                    assert!(!e.is_empty() && e.render().contains("fuzz.lmx:"));
                    false
                }
            }
        }));
        let took = spent(start, cpu);
        f.cases += 1;
        match result {
            Ok(true) => f.valid += 1,
            Ok(false) => {}
            Err(_) => f.panics.push(src.clone()),
        }
        if took > f.slowest.0 {
            f.slowest = (took, src.clone());
        }
        if took > max {
            f.slow.push((took, src));
        }
    }
    f
}

fn report(f: &Findings) -> String {
    format!(
        "fuzz: {} inputs ({} valid files), {} panics, {} over the time limit; slowest {:.3} s (CPU):\n{}",
        f.cases,
        f.valid,
        f.panics.len(),
        f.slow.len(),
        f.slowest.0.as_secs_f64(),
        f.slowest.1.chars().take(600).collect::<String>()
    )
}

/// The seeded slice CI runs on every test run.
#[test]
fn fuzz_slice() {
    let f = fuzz(12, 300, Duration::MAX);
    eprintln!("{}", report(&f));
    assert!(
        f.panics.is_empty(),
        "panics on:\n{}",
        f.panics.join("\n-----\n")
    );
    // The mutations must keep a fair share of files valid, or the pipeline
    // behind the parser is not being exercised.
    assert!(
        f.valid * 10 >= f.cases,
        "only {} of {} valid",
        f.valid,
        f.cases
    );
}

/// The long run: `LAMBDAMAT_FUZZ_CASES=1000000 cargo test --release --test
/// fuzz -- --ignored --nocapture`.
#[test]
#[ignore = "long: run on demand (see the module docs)"]
fn fuzz_long() {
    let env = |k: &str, d: u64| {
        std::env::var(k)
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(d)
    };
    // Replay one finding: `LAMBDAMAT_FUZZ_REPLAY=path/to/input.lmx`.
    if let Ok(path) = std::env::var("LAMBDAMAT_FUZZ_REPLAY") {
        let src = std::fs::read_to_string(&path).expect("replay file");
        let (start, cpu) = (Instant::now(), process_cpu_time());
        let ok = parse_program(&src, "fuzz.lmx")
            .map(|p| pipeline(&p))
            .is_ok();
        eprintln!(
            "replay {path}: valid {ok}, {:.3} s wall, {:.2} s CPU",
            start.elapsed().as_secs_f64(),
            spent(start, cpu).as_secs_f64()
        );
        return;
    }
    let cases = env("LAMBDAMAT_FUZZ_CASES", 100_000) as usize;
    let seed = env("LAMBDAMAT_FUZZ_SEED", 1);
    let max = Duration::from_secs(env("LAMBDAMAT_FUZZ_MAX_SECS", 10));
    // In chunks, so that progress shows and findings are kept as they come.
    let chunk = 10_000.min(cases.max(1));
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("fuzz-findings");
    let mut total = Findings::default();
    let mut done = 0;
    let mut k = 0u64;
    while done < cases {
        let n = chunk.min(cases - done);
        let f = fuzz(seed.wrapping_mul(1_000_003).wrapping_add(k), n, max);
        for (i, src) in f.panics.iter().enumerate() {
            let _ = std::fs::create_dir_all(&dir);
            let _ = std::fs::write(dir.join(format!("panic-{k}-{i}.lmx")), src);
        }
        for (i, (_, src)) in f.slow.iter().enumerate() {
            let _ = std::fs::create_dir_all(&dir);
            let _ = std::fs::write(dir.join(format!("slow-{k}-{i}.lmx")), src);
        }
        total.cases += f.cases;
        total.valid += f.valid;
        total.panics.extend(f.panics);
        total.slow.extend(f.slow);
        if f.slowest.0 > total.slowest.0 {
            total.slowest = f.slowest;
        }
        done += n;
        k += 1;
        eprintln!("{}", report(&total).lines().next().unwrap_or(""));
    }
    eprintln!("{}", report(&total));
    assert!(total.panics.is_empty(), "panics: see {}", dir.display());
    assert!(total.slow.is_empty(), "slow inputs: see {}", dir.display());
}
