//! `lambdamat hertz`: the flagship Hertz contact problem with finite
//! friction. One solve from (ν, c) or (ν, μ) with text/JSON/CSV/SVG output,
//! `hertz table` (the seed paper's Tables 1 and 2 beside our values and the
//! seed's literal algorithm) and `hertz sweep` (a ν × μ grid in parallel).
//! A client of the library's Hertz entry ([`crate::api::hertz_report`],
//! [`crate::api::hertz_table`], [`crate::api::hertz_sweep`]): this file
//! reads the flags, prints what those return and turns their outcome into
//! the exit code.

use super::error::CliError;
use super::help_with_examples;
use super::output::{check_writable, write_file};
use crate::api::{Given, HertzOptions, MAX_SWEEP_POINTS, Tally};
use clap::{Args, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};
use std::io::Write;
use std::path::PathBuf;

/// Arguments of `lambdamat hertz`.
#[derive(Args, Debug)]
#[command(args_conflicts_with_subcommands = true)]
pub struct HertzArgs {
    #[command(subcommand)]
    sub: Option<HertzSub>,
    /// Poisson's ratio ν, -1 < ν ≤ 1/2 (a stable isotropic solid).
    #[arg(long, allow_hyphen_values = true)]
    nu: Option<f64>,
    /// Stick radius c in (0, 1): find μ.
    #[arg(long, conflicts_with = "mu", allow_hyphen_values = true)]
    c: Option<f64>,
    /// Friction coefficient μ ≥ 0: find c.
    #[arg(long, allow_hyphen_values = true)]
    mu: Option<f64>,
    /// Target accuracy (finite, > 0): refine until successive levels agree to this.
    #[arg(long, default_value = "1e-10", allow_hyphen_values = true)]
    tol: f64,
    /// Memory budget, e.g. 2G or 500M (default: half the free memory, and of `ulimit -v`).
    #[arg(long, value_name = "SIZE", value_parser = crate::numeric::budget::parse_size)]
    max_memory: Option<u64>,
    /// Print one JSON object instead of text.
    #[arg(long)]
    json: bool,
    /// Write x, p, q, mu_p, u on a fine grid to this CSV file, each with its error estimate.
    #[arg(long, value_name = "FILE")]
    csv: Option<PathBuf>,
    /// Draw p, q, μp and u against x (c marked) into this SVG file.
    #[arg(long, value_name = "FILE.svg")]
    plot: Option<PathBuf>,
}

#[derive(Subcommand, Debug)]
enum HertzSub {
    /// The seed paper's Tables 1 and 2 beside our values (Markdown, or CSV with --csv).
    #[command(after_help = help_with_examples!(
        "  lambdamat hertz table --table 2\n  lambdamat hertz table --csv --tol 1e-8"
    ))]
    Table {
        /// Print one table as CSV instead of Markdown (table 1 unless --table 2).
        #[arg(long)]
        csv: bool,
        /// Only this table (1 or 2); Markdown shows both by default.
        #[arg(long, value_parser = clap::value_parser!(u8).range(1..=2))]
        table: Option<u8>,
        /// Target accuracy of our solves (finite, > 0).
        #[arg(long, default_value = "1e-10", allow_hyphen_values = true)]
        tol: f64,
    },
    /// Solve on a ν × μ grid in parallel; CSV (default) or JSON lines.
    #[command(after_help = help_with_examples!(
        "  lambdamat hertz sweep --nu 0:0.5:3 --mu 0.1:1:4\n  lambdamat hertz sweep --nu 0.25:0.25:1 --mu log:0.01:100:5 --jsonl -o /tmp/sweep.jsonl"
    ))]
    Sweep {
        /// ν range as START:END:COUNT within (-1, 1/2], e.g. -0.9:0.5:15 (END may be below START).
        #[arg(long, value_name = "START:END:COUNT", allow_hyphen_values = true)]
        nu: String,
        /// μ range as START:END:COUNT with μ ≥ 0, e.g. 0.1:1:10, or log:START:END:COUNT for
        /// log spacing (START, END > 0), e.g. log:0.01:100:13 (0.01, 0.0215…, 0.0464…, 0.1, …, 100).
        #[arg(long, value_name = "START:END:COUNT", allow_hyphen_values = true)]
        mu: String,
        /// Target accuracy of each solve (finite, > 0).
        #[arg(long, default_value = "1e-10", allow_hyphen_values = true)]
        tol: f64,
        /// Print JSON lines instead of CSV.
        #[arg(long)]
        jsonl: bool,
        /// Write to this file instead of standard output.
        #[arg(long, short, value_name = "FILE")]
        out: Option<PathBuf>,
    },
}

/// Refuses a tolerance that is not a finite number > 0.
fn check_tol(tol: f64) -> Result<(), CliError> {
    Ok(crate::api::check_tol(tol)?)
}

/// Refuses `--set`: `hertz` takes its parameters as flags (`--nu`,
/// `--mu`, `--c`); the language file behind it takes `--set` through
/// `lambdamat solve examples/hertz.lmx`.
fn refuse_set() -> Result<(), CliError> {
    match super::overrides().first() {
        None => Ok(()),
        Some((name, value)) => {
            let flag = match name.as_str() {
                "nu" | "mu" | "c" => format!("--{name} {value}"),
                _ => "--nu, --mu or --c".to_string(),
            };
            Err(CliError::Invalid(format!(
                "--set {name}: `lambdamat hertz` takes no --set; give its parameters as {flag} (or run `lambdamat solve examples/hertz.lmx --set {name}={value}`)"
            )))
        }
    }
}

/// `lambdamat hertz …`.
pub fn hertz_command(a: &HertzArgs, w: &mut dyn Write) -> Result<(), CliError> {
    refuse_set()?;
    match &a.sub {
        Some(HertzSub::Table {
            csv,
            table: which,
            tol,
        }) => return table(*csv, *which, *tol, w),
        Some(HertzSub::Sweep {
            nu,
            mu,
            tol,
            jsonl,
            out,
        }) => return sweep(nu, mu, *tol, *jsonl, out.as_ref(), w),
        None => {}
    }
    let nu = a.nu.ok_or_else(|| {
        CliError::Usage(
            "hertz needs --nu N and one of --c C or --mu M (or a subcommand: table, sweep)".into(),
        )
    })?;
    check_tol(a.tol)?;
    let given = match (a.c, a.mu) {
        (Some(c), None) => Given::C(c),
        (None, Some(mu)) => Given::Mu(mu),
        _ => {
            return Err(CliError::Usage(
                "give exactly one of --c C or --mu M".into(),
            ));
        }
    };
    for path in [&a.csv, &a.plot].into_iter().flatten() {
        check_writable(path, &[])?;
    }
    let opts = HertzOptions {
        tol: a.tol,
        max_memory: a.max_memory,
        // The report's own grid is not printed: its ends only.
        grid: 2,
    };
    let s = match crate::api::hertz_report(nu, given, &opts) {
        Ok(s) => s,
        Err(refusal) => {
            // With --json a refusal at a physical limit is still one JSON
            // object (the error and the limit's asymptotic values); the
            // exit status is the error's (3).
            if a.json
                && let Some(json) = refusal.limit_json()
            {
                writeln!(w, "{json}")?;
            }
            return Err(crate::api::Error::from(refusal).into());
        }
    };
    if let Some(path) = &a.csv {
        write_file(path, s.profile_csv()?.as_bytes(), &[], "")?;
    }
    if let Some(path) = &a.plot {
        write_file(path, super::plot::hertz_svg(s.result())?.as_bytes(), &[], "")?;
    }
    if a.json {
        writeln!(w, "{}", s.to_json())?;
    } else {
        write!(w, "{}", s.text())?;
    }
    if !s.converged() {
        return Err(CliError::NotConverged(format!(
            "tolerance {:.0e} not reached; the error estimate {:.1e} is the honest one",
            s.tol(),
            s.error_estimate()
        )));
    }
    Ok(())
}

/// The exit status of a table or sweep: some solve failed (3), else some
/// did not converge (4).
fn status(t: Tally, what: &'static str) -> Result<(), CliError> {
    if t.failed > 0 {
        Err(CliError::RowsFailed {
            failed: t.failed,
            total: t.total,
            what,
        })
    } else if t.not_converged > 0 {
        Err(CliError::NotConverged(format!(
            "{} of {} {what} did not reach the tolerance",
            t.not_converged, t.total
        )))
    } else {
        Ok(())
    }
}

fn table(csv: bool, which: Option<u8>, tol: f64, w: &mut dyn Write) -> Result<(), CliError> {
    check_tol(tol)?;
    // CSV is one table per output; Markdown shows both unless one is asked for.
    let which = if csv { Some(which.unwrap_or(1)) } else { which };
    let t = crate::api::hertz_table(which, tol)?;
    if csv {
        w.write_all(t.csv().as_bytes())?;
    } else {
        w.write_all(t.markdown().as_bytes())?;
    }
    status(t.tally(), "solves")
}


/// Parses `START:END:COUNT` into `COUNT` evenly spaced values (END may be
/// below START), or `log:START:END:COUNT` into `COUNT` values evenly
/// spaced in the logarithm (START and END > 0). The inner values are
/// rounded to 12 significant digits (a linear range: 12 digits of its
/// larger end), so log:0.01:100:5 is 0.01, 0.1, 1, 10, 100 and
/// -0.9:0.5:15 is -0.9, -0.8, …, 0, …, 0.5. Each value must lie
/// inside `domain` (a description and a test). Checked before any work.
pub fn parse_range(
    flag: &str,
    s: &str,
    domain: (&str, fn(f64) -> bool),
) -> Result<Vec<f64>, CliError> {
    let bad = || {
        CliError::Usage(format!(
            "--{flag} {s}: expected START:END:COUNT (e.g. 0:0.45:10) or log:START:END:COUNT (e.g. log:0.01:100:13)"
        ))
    };
    let (log, body) = match s.trim().strip_prefix("log:") {
        Some(rest) => (true, rest),
        None => (false, s),
    };
    let parts: Vec<&str> = body.split(':').collect();
    let [a, b, n] = parts.as_slice() else {
        return Err(bad());
    };
    let (a, b): (f64, f64) = (
        a.trim().parse().map_err(|_| bad())?,
        b.trim().parse().map_err(|_| bad())?,
    );
    let n: usize = n.trim().parse().map_err(|_| bad())?;
    if n == 0 || n > MAX_SWEEP_POINTS {
        return Err(CliError::Invalid(format!(
            "--{flag} {s}: COUNT must be between 1 and {MAX_SWEEP_POINTS}"
        )));
    }
    let (what, inside) = domain;
    for v in [a, b] {
        if !inside(v) {
            return Err(CliError::Invalid(format!(
                "--{flag} {s}: {v} is outside {what}"
            )));
        }
        if log && !(v > 0.0 && v.is_finite()) {
            return Err(CliError::Invalid(format!(
                "--{flag} {s}: {v} is not > 0; a log range needs START and END > 0"
            )));
        }
    }
    let (a, b) = (a + 0.0, b + 0.0);
    Ok(if n == 1 {
        vec![a]
    } else {
        (0..n)
            .map(|k| {
                let s = k as f64 / (n - 1) as f64;
                if k == 0 {
                    a
                } else if k == n - 1 {
                    b
                } else if log {
                    // 12 significant digits: 10^k comes out as 10^k.
                    let v = (a.ln() * (1.0 - s) + b.ln() * s).exp();
                    format!("{v:.11e}").parse().unwrap_or(v)
                } else {
                    // 12 digits of the range's scale: -0.9:0.5:15 gives
                    // -0.8, …, 0, …, 0.1 (not 5.6e-17 or 0.10000000000000003).
                    let v = a * (1.0 - s) + b * s;
                    let scale = a.abs().max(b.abs());
                    // (f64 arithmetic: a zero scale gives +∞, clamped.)
                    let digits = (11.0 - scale.log10().floor()).clamp(0.0, 400.0) as usize;
                    format!("{v:.digits$}")
                        .parse::<f64>()
                        .map_or(v, |r| r + 0.0)
                }
            })
            .collect()
    })
}

fn sweep(
    nu: &str,
    mu: &str,
    tol: f64,
    jsonl: bool,
    out: Option<&PathBuf>,
    w: &mut dyn Write,
) -> Result<(), CliError> {
    check_tol(tol)?;
    if let Some(p) = out {
        check_writable(p, &[])?;
    }
    let nus = parse_range(
        "nu",
        nu,
        (
            "(-1, 1/2] (a stable isotropic solid has -1 < ν ≤ 1/2)",
            |v| v > -1.0 && v <= 0.5,
        ),
    )?;
    let mus = parse_range("mu", mu, ("μ ≥ 0 (finite)", |v| v >= 0.0 && v.is_finite()))?;
    let bar = ProgressBar::new(nus.len().saturating_mul(mus.len()) as u64);
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} solves, {elapsed} elapsed, eta {eta}")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let s = crate::api::hertz_sweep(&nus, &mus, tol, &|| bar.inc(1));
    bar.finish_and_clear();
    let s = s?;
    let text = if jsonl { s.jsonl() } else { s.csv() };
    match out {
        Some(p) => write_file(p, text.as_bytes(), &[], "")?,
        None => w.write_all(text.as_bytes())?,
    }
    super::output::note(&s.summary());
    status(s.tally(), "solves")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn positive(v: f64) -> bool {
        v >= 0.0 && v.is_finite()
    }

    #[test]
    fn log_ranges_are_geometric_with_exact_decades() {
        let v = parse_range("mu", "log:0.01:100:13", ("μ ≥ 0", positive)).unwrap();
        assert_eq!(v.len(), 13);
        assert_eq!(
            (v[0], v[3], v[6], v[9], v[12]),
            (0.01, 0.1, 1.0, 10.0, 100.0)
        );
        // Equal ratios 10^(1/3) to the 12 rounded digits.
        for w in v.windows(2) {
            assert!((w[1] / w[0] - 10f64.powf(1.0 / 3.0)).abs() < 1e-10, "{w:?}");
        }
        // Descending works too, and one point is START.
        let d = parse_range("mu", "log:100:1:3", ("μ ≥ 0", positive)).unwrap();
        assert_eq!(d, vec![100.0, 10.0, 1.0]);
        assert_eq!(
            parse_range("mu", "log:0.5:7:1", ("μ ≥ 0", positive)).unwrap(),
            vec![0.5]
        );
    }

    #[test]
    fn bad_ranges_are_refused() {
        let r = |s: &str| parse_range("mu", s, ("μ ≥ 0", positive));
        assert!(matches!(r("log:0:1:3"), Err(CliError::Invalid(_))));
        assert!(matches!(r("log:1:inf:3"), Err(CliError::Invalid(_))));
        assert!(matches!(r("log:1:2"), Err(CliError::Usage(_))));
        assert!(matches!(r("log:1:2:0"), Err(CliError::Invalid(_))));
        assert!(matches!(r("0:1:3"), Ok(v) if v == vec![0.0, 0.5, 1.0]));
        assert!(matches!(r("0:0:3"), Ok(v) if v == vec![0.0; 3]));
        assert!(matches!(r("1e-300:2e-300:3"), Ok(v) if v.len() == 3 && v[1] > 0.0));
        let nu = |s: &str| parse_range("nu", s, ("(-1, 1/2]", |v| v > -1.0 && v <= 0.5));
        assert!(
            matches!(nu("-0.9:0.5:15"), Ok(v) if v.len() == 15 && v[0] == -0.9 && v[1] == -0.8 && v[9] == 0.0 && v[10] == 0.1 && v[14] == 0.5)
        );
        assert!(matches!(nu("-1:0.5:3"), Err(CliError::Invalid(_))));
    }
}
