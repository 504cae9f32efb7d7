//! The `smith` command: picks the matrices to decompose, resolves the
//! principal symbol, asks [`crate::algebra::smith::modes`] for certified
//! reports and prints them. Also runs `check smith` directives for `run`.

use super::error::CliError;
use super::{OutputArgs, SmithArgs, read_source};
use crate::report::smith as render;
use crate::algebra::matrix::Matrix;
use crate::algebra::polyring::PolyRing;
use crate::algebra::smith::modes::{
    CheckReport, PhaseHook, SmithOptions, SmithReport, check_decomposition, smith_report,
};
use crate::api::Problem;
use crate::lang::{MatrixDef, Program};
use std::io::Write;

/// A matrix definition as a matrix over Q\[symbols\].
pub fn to_matrix(symbols: &[String], m: &MatrixDef) -> Matrix<PolyRing> {
    Matrix::new(
        PolyRing::new(symbols.to_vec()),
        m.rows,
        m.cols,
        m.entries.clone(),
    )
}

/// Reads the file at `path` and validates it with the command line's
/// `--set` overrides: a [`crate::api::Problem`].
pub fn load_problem(path: &std::path::Path) -> Result<Problem, CliError> {
    let (text, name) = read_source(path)?;
    Problem::with_sets(text, name, super::overrides().to_vec()).map_err(crate::api::Error::into_cli)
}

/// Resolves `--principal` against the file's symbols (the flag wins).
pub fn principal(p: &Program, flag: Option<&str>) -> Result<Option<usize>, CliError> {
    crate::api::principal_of(p, flag).map_err(crate::api::Error::into_cli)
}

/// The Smith report of matrix number `idx`.
pub fn report(
    p: &Program,
    idx: usize,
    principal: Option<usize>,
    latex: bool,
) -> Result<SmithReport, CliError> {
    let m = &p.matrices[idx];
    report_of(&m.name, &to_matrix(&p.symbols, m), principal, latex)
}

/// The Smith report of `a` (named `name`), with a spinner naming the
/// phases on a terminal.
fn report_of(
    name: &str,
    a: &Matrix<PolyRing>,
    principal: Option<usize>,
    latex: bool,
) -> Result<SmithReport, CliError> {
    let spinner = std::io::IsTerminal::is_terminal(&std::io::stderr()).then(|| {
        let bar = indicatif::ProgressBar::new_spinner();
        bar.set_style(
            indicatif::ProgressStyle::with_template("{spinner} {prefix}: {msg} ({elapsed})")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_spinner()),
        );
        bar.set_prefix(format!("smith {name}"));
        bar.enable_steady_tick(std::time::Duration::from_millis(200));
        bar
    });
    let timings = timings_enabled();
    let hook = spinner.clone().map(|bar| {
        std::sync::Arc::new(move |phase: &str| {
            if timings {
                timing(phase);
            }
            bar.set_message(phase.to_string())
        }) as std::sync::Arc<dyn Fn(&str) + Send + Sync>
    });
    let hook = hook.or_else(|| {
        timings.then(|| {
            std::sync::Arc::new(|phase: &str| timing(phase))
                as std::sync::Arc<dyn Fn(&str) + Send + Sync>
        })
    });
    let opts = SmithOptions {
        principal,
        latex,
        progress: PhaseHook(hook),
    };
    let r = smith_report(name, a, &opts);
    if let Some(bar) = spinner {
        bar.finish_and_clear();
    }
    Ok(r?)
}

/// Whether `LAMBDAMAT_TIMINGS` asks for phase timings on stderr (a
/// debugging aid for the speed work on small inputs; off by default).
fn timings_enabled() -> bool {
    std::env::var_os("LAMBDAMAT_TIMINGS").is_some_and(|v| !v.is_empty() && v != "0")
}

/// Prints `[timings] <CPU ms> <wall ms> <what starts now>` to stderr: the
/// main thread's CPU time from `/proc/thread-self/schedstat` (nanoseconds;
/// `-` where unavailable) and the wall time since the first call.
fn timing(what: &str) {
    static START: std::sync::OnceLock<std::time::Instant> = std::sync::OnceLock::new();
    let t0 = START.get_or_init(std::time::Instant::now);
    let cpu = std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<f64>().ok())
        .map_or_else(|| "-".to_string(), |ns| format!("{:.3}", ns / 1e6));
    super::output::note(&format!(
        "[timings] cpu {cpu:>9} ms  wall {:9.3} ms  {what}",
        t0.elapsed().as_secs_f64() * 1e3
    ));
}

/// The report of a `check smith A with U, D, V` directive.
pub fn check(p: &Program, ids: [usize; 4], principal: Option<usize>) -> CheckReport {
    let mats: Vec<Matrix<PolyRing>> = ids
        .iter()
        .map(|&i| to_matrix(&p.symbols, &p.matrices[i]))
        .collect();
    let names = ids.map(|i| p.matrices[i].name.clone());
    check_decomposition(names, [&mats[0], &mats[1], &mats[2], &mats[3]], principal)
}

/// Prints one Smith report in the requested form.
pub fn print_report(r: &SmithReport, out: &OutputArgs, w: &mut dyn Write) -> Result<(), CliError> {
    if out.latex {
        write!(w, "{}", render::smith_latex(r))?;
    } else {
        write!(w, "{}", render::smith_text(r))?;
    }
    Ok(())
}

/// `lambdamat smith FILE`: the matrices [`Problem::smith`] would choose
/// (every one the file asks for, or the λ-matrix of its operator system).
pub fn smith_command(a: &SmithArgs, w: &mut dyn Write) -> Result<(), CliError> {
    let timings = timings_enabled();
    if timings {
        timing("parsing and lowering");
    }
    let (text, name) = read_source(&a.file)?;
    let problem = Problem::with_sets(text, name, super::overrides().to_vec())
        .map_err(crate::api::Error::into_cli)?;
    let opts = crate::api::SmithOptions {
        principal: a.principal.clone(),
        matrix: a.matrix.clone(),
    };
    let targets = problem
        .smith_targets(&opts)
        .map_err(crate::api::Error::into_cli)?;
    let principal = problem
        .principal(&opts)
        .map_err(crate::api::Error::into_cli)?;
    let reports = targets
        .iter()
        .map(|(name, m)| report_of(name, m, principal, a.out.latex))
        .collect::<Result<Vec<_>, _>>()?;
    if timings {
        timing("printing");
    }
    let done = || {
        if timings {
            timing("done");
        }
    };
    if a.out.json {
        let v = if reports.len() == 1 {
            serde_json::to_value(&reports[0])
        } else {
            serde_json::to_value(&reports)
        }
        .map_err(|e| CliError::Invalid(e.to_string()))?;
        super::output::write_json(w, &v)?;
        done();
        return Ok(());
    }
    for (k, r) in reports.iter().enumerate() {
        if k > 0 {
            writeln!(w, "\n{}\n", "─".repeat(60))?;
        }
        print_report(r, &a.out, w)?;
    }
    done();
    Ok(())
}
