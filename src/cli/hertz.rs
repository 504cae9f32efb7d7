//! `lambdamat hertz`: the flagship Hertz contact problem with finite
//! friction. One solve from (ν, c) or (ν, μ) with text/JSON/CSV/SVG output,
//! `hertz table` (the seed paper's Tables 1 and 2 beside our values and the
//! seed's literal algorithm) and `hertz sweep` (a ν × μ grid in parallel).
//! Every solve goes through [`crate::hertz::front`] (the language files
//! `examples/hertz*.lmx` and the general split-domain solver); this file
//! only formats. The hand-written solver is not called here.

use super::error::CliError;
use super::help_with_examples;
use super::output::{check_writable, write_file};
use crate::hertz::front::{
    DEFAULT_MAX_LEVEL, Given, HertzResult, Limit, Refusal, solve, solve_with_limit,
};
use crate::hertz::seed::seed_literal;
use crate::hertz::tables::{SEED_TABLE1, spence_c};
use crate::plan::error::RangeEnd;
use crate::plan::{PlanError, SplitOptions};
use clap::{Args, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use std::fmt::Write as _;
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

/// The front's options at tolerance `tol` (the ladder of `lambdamat solve`).
fn options(tol: f64) -> SplitOptions {
    SplitOptions {
        tol,
        max_level: DEFAULT_MAX_LEVEL,
        ..SplitOptions::default()
    }
}

fn solve_given_c(nu: f64, c: f64, opts: &SplitOptions) -> Result<HertzResult, PlanError> {
    solve(nu, Given::C(c), opts)
}

fn solve_given_mu(nu: f64, mu: f64, opts: &SplitOptions) -> Result<HertzResult, PlanError> {
    solve(nu, Given::Mu(mu), opts)
}

/// Refuses a tolerance that is not a finite number > 0.
fn check_tol(tol: f64) -> Result<(), CliError> {
    if tol > 0.0 && tol.is_finite() {
        Ok(())
    } else {
        Err(CliError::Invalid(format!(
            "--tol {tol}: the tolerance must be a finite number > 0, e.g. 1e-10"
        )))
    }
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
    // -0 is 0 (and is shown so).
    let (nu, c, mu) = (nu + 0.0, a.c.map(|c| c + 0.0), a.mu.map(|m| m + 0.0));
    let opts = options(a.tol);
    let given = match (c, mu) {
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
    let s = match crate::hertz::front::solve_within(nu, given, &opts, a.max_memory) {
        Ok(s) => s,
        Err(Refusal { error, limit }) => {
            // With --json a refusal at a physical limit is still one JSON
            // object (the error and the limit's asymptotic values); the
            // exit status is the error's (3).
            if a.json && limit.is_some() {
                super::output::write_json(
                    w,
                    &RefusalJson {
                        nu,
                        c,
                        mu,
                        error: error.to_string(),
                        limit,
                    },
                )?;
            }
            return Err(error.into());
        }
    };
    if let Some(path) = &a.csv {
        write_file(path, profile_csv(&s)?.as_bytes(), &[], "")?;
    }
    if let Some(path) = &a.plot {
        write_file(path, super::plot::hertz_svg(&s)?.as_bytes(), &[], "")?;
    }
    if a.json {
        super::output::write_json(w, &s)?;
    } else {
        write!(w, "{}", text(&s, a.c.is_some()))?;
    }
    if !s.converged {
        return Err(CliError::NotConverged(format!(
            "tolerance {:.0e} not reached; the error estimate {:.1e} is the honest one",
            s.tol, s.error_estimate
        )));
    }
    Ok(())
}

/// The asymptotic values of the limit an end answer lies in, as one line
/// of information (not refined to the tolerance).
fn limit_info(l: &Limit) -> String {
    match *l {
        Limit::SmallFriction {
            exponent,
            compliance_asymptotic,
            ..
        } => format!(
            "small-friction limit (information, not refined): c = C₀·exp(−a/μ)·(1 + O(μ)), a = {exponent:.4} (derived) gives c ≈ {} (the range is the measured O(μ) term); P* = 1 + γμ(1−2/π) + γ²Jμ² + O(μ³) = {compliance_asymptotic:.15} + O(μ³) (derived)",
            l.c_asymptotic_text()
        ),
        Limit::ThinSlip {
            compliance_infinity,
            compliance_full_stick,
            ..
        } => format!(
            "near-full stick (information, not refined): as μ → ∞ a slip annulus 1 − c∞ = δ₀(1 − δ₀/2 + O(δ₀²)) = {} remains, δ₀ = 8·exp(−π/(2ε₀)) (derived), and P* → P*ₛ(1 − δ₀/2) = {compliance_infinity:.16} ≤ artanh(γ)/γ = {compliance_full_stick:.16} (full stick)",
            l.one_minus_c_infinity_text()
        ),
        Limit::BeyondLargeFriction { .. } => String::new(),
    }
}

/// A given value as the user would write it: `0.01`, but `1e-9` rather
/// than nine zeros (f64's `Display` never uses an exponent).
fn shown(x: f64) -> String {
    if x != 0.0 && (x.abs() < 1e-4 || x.abs() >= 1e16) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

fn ok(b: bool) -> &'static str {
    if b { "ok" } else { "VIOLATED" }
}

fn text(s: &HertzResult, given_c: bool) -> String {
    let mut o = String::new();
    let _ = writeln!(
        o,
        "Hertz contact with finite friction: ν = {}, γ = (1-2ν)/(2-2ν) = {:.15}",
        s.nu, s.gamma
    );
    // The found scalar's own estimate (none in the limits without shear,
    // where c = 0 or 1 is not computed).
    let pm = |name: &str| {
        s.error_estimates
            .get(name)
            .map_or(String::new(), |e| format!(" ± {e:.1e}"))
    };
    match (&s.end_answer, given_c) {
        (Some(e), _) => {
            let (name, given, value) = if given_c {
                ("μ", format!("c = {}", shown(s.c)), s.mu)
            } else {
                ("c", format!("μ = {}", shown(s.mu)), s.c)
            };
            // Near the upper end (c → 1 near full stick) the gap is
            // stated as the distance from the end, which is what is known.
            let (rel, reported) = match e.end {
                RangeEnd::Lower => ("<", format!("{value:.4e}")),
                RangeEnd::Upper => (
                    ">",
                    format!(
                        "{value:.16}, i.e. {} − {:.2e}",
                        e.end_value,
                        e.end_value - value
                    ),
                ),
            };
            let _ = writeln!(
                o,
                "  given {given}  →  {name} {rel} {}, bounded, not resolved: the root of the free-boundary condition lies within {:.1e} of the end {} (reported as {reported}{})",
                end_point(e),
                e.distance,
                e.end_value,
                pm(e.scalar.as_str())
            );
            if let Some(line) = crate::report::text::estimate_line(e) {
                let _ = writeln!(o, "  {line}");
            }
            if let Some(l) = &s.limit {
                let _ = writeln!(o, "  {}", limit_info(l));
            }
        }
        (None, true) => {
            let _ = writeln!(o, "  given c = {}  →  μ = {:.13}{}", s.c, s.mu, pm("mu"));
        }
        (None, false) => {
            let _ = writeln!(
                o,
                "  given μ = {}  →  c = {:.13}{}",
                shown(s.mu),
                s.c,
                pm("c")
            );
        }
    }
    let _ = writeln!(o, "  edge exponent α = arccot(γμ)/π = {:.15}", s.alpha);
    let _ = writeln!(
        o,
        "  compliance P* = (π/2)∫x p dx       = {:.15}",
        s.compliance
    );
    let _ = writeln!(
        o,
        "  P* = 1 + γ∫q(1-√(1-t²))dt          = {:.15}",
        s.compliance_via_shear
    );
    let _ = writeln!(
        o,
        "  difference of the two formulas     = {:.1e}",
        s.compliance_difference
    );
    let _ = writeln!(
        o,
        "  error estimate {:.1e} (successive refinement levels: {}, {} unknowns; tolerance {:.0e} {})",
        s.error_estimate,
        s.levels,
        s.unknowns,
        s.tol,
        if s.converged {
            "reached"
        } else {
            "NOT reached"
        }
    );
    // At an end answer the zone beside the end lies inside the gap.
    let gap = "not checked (inside the unresolved gap)";
    let (stick, slip) = match s.end_answer.as_ref().map(|e| e.end) {
        Some(RangeEnd::Lower) => (gap, ok(s.slip_ok)),
        Some(RangeEnd::Upper) => (ok(s.stick_ok), gap),
        None => (ok(s.stick_ok), ok(s.slip_ok)),
    };
    let _ = writeln!(
        o,
        "  checks: stick q < μp on [0,c): {stick}; slip u < 0 on (c,1]: {slip}"
    );
    // Pointwise values carry their own estimates (the two levels' values,
    // each at its own c); none in the limits without shear.
    let fe = |name: &str| {
        s.field_error_estimates
            .get(name)
            .map_or(String::new(), |e| format!(" ± {e:.1e}"))
    };
    if let Some(e) = &s.end_answer {
        let _ = writeln!(
            o,
            "          at c: not checked (c is bounded, not resolved); the outputs are those at {} = {}, each with its variation over the gap to the end in its estimate ({})",
            e.scalar,
            end_point(e),
            e.variations
                .iter()
                .filter(|v| v.name == "P" || v.name == "P_shear")
                .map(|v| format!("{} ± {:.1e}", v.name, v.bound))
                .collect::<Vec<_>>()
                .join(", ")
        );
    } else if let Some(u) = &s.unrefined_at_c {
        let _ = writeln!(
            o,
            "          at c: not checked: {}; the last level there gives shear jump q(c⁻) - μp(c) = {:.1e}, E2 residual at c (÷c) = {:.1e}",
            u.describe(),
            s.shear_jump_at_c,
            s.residual_c
        );
    } else {
        let _ = writeln!(
            o,
            "          shear jump q(c⁻) - μp(c) = {:.1e}{}, E2 residual at c (÷c) = {:.1e}{}",
            s.shear_jump_at_c,
            fe("shear_jump_at_c"),
            s.residual_c,
            fe("residual_c")
        );
    }
    let _ = writeln!(o, "  solved through the language: {}", s.command);
    o
}

/// `x, p, q, mu_p, u` on a fine grid, each field followed by its error
/// estimate (`*_err`, see [`crate::plan::split_fields::LevelFields`]), as
/// CSV.
fn profile_csv(s: &HertzResult) -> Result<String, CliError> {
    let samples = s.profile(400)?;
    let mut out = String::from("x,p,p_err,q,q_err,mu_p,mu_p_err,u,u_err\n");
    for p in samples {
        let _ = writeln!(
            out,
            "{:.16e},{:.16e},{:.2e},{:.16e},{:.2e},{:.16e},{:.2e},{:.16e},{:.2e}",
            p.x, p.p, p.p_err, p.q, p.q_err, p.mu_p, p.mu_p_err, p.u, p.u_err
        );
    }
    Ok(out)
}

/// The seed's Table 2: (c, μ) pairs used for every ν.
const TABLE2_PAIRS: [(f64, f64); 3] = [(0.24, 0.2063), (0.5, 0.2986), (0.7, 0.4013)];
const TABLE2_NU: [f64; 4] = [0.0, 0.125, 0.25, 0.375];

fn fmt_opt(v: Option<f64>, digits: usize) -> String {
    v.map_or("-".to_string(), |x| format!("{x:.digits$}"))
}

fn seed_cell(nu: f64, mu: f64, c: f64, tol: f64) -> String {
    match seed_literal(nu, mu, c, 4, tol) {
        Ok(r) => {
            let seq: Vec<String> = r
                .levels
                .iter()
                .map(|l| {
                    l.compliance
                        .map_or("refused".to_string(), |p| format!("{p:.4}"))
                })
                .collect();
            if r.converged {
                fmt_opt(r.compliance, 6)
            } else {
                format!("no convergence: {}", seq.join(" → "))
            }
        }
        Err(e) => format!("refused: {e}"),
    }
}

/// How the rows of a table or sweep ended.
#[derive(Default)]
struct Tally {
    total: usize,
    failed: usize,
    not_converged: usize,
}

impl Tally {
    fn add<T>(&mut self, r: &Result<HertzResult, T>) {
        self.total += 1;
        match r {
            Ok(s) if !s.converged => self.not_converged += 1,
            Ok(_) => {}
            Err(_) => self.failed += 1,
        }
    }

    /// The exit status: some row failed (3), else some did not converge (4).
    fn status(&self, what: &'static str) -> Result<(), CliError> {
        if self.failed > 0 {
            Err(CliError::RowsFailed {
                failed: self.failed,
                total: self.total,
                what,
            })
        } else if self.not_converged > 0 {
            Err(CliError::NotConverged(format!(
                "{} of {} {what} did not reach the tolerance",
                self.not_converged, self.total
            )))
        } else {
            Ok(())
        }
    }
}

fn table(csv: bool, which: Option<u8>, tol: f64, w: &mut dyn Write) -> Result<(), CliError> {
    check_tol(tol)?;
    let opts = options(tol);
    // CSV is one table per output; Markdown shows both unless one is asked for.
    let which = if csv { Some(which.unwrap_or(1)) } else { which };
    let show1 = which != Some(2);
    let show2 = which != Some(1);
    let tally = std::sync::Mutex::new(Tally::default());
    let count = |r: &Result<HertzResult, PlanError>| {
        if let Ok(mut t) = tally.lock() {
            t.add(r);
        }
    };
    // Table 1: our c for the published μ; our μ for Spence's c1.
    let rows1: Vec<Vec<String>> = SEED_TABLE1
        .par_iter()
        .filter(|_| show1)
        .map(|&(mu, nu, c2, c3)| {
            let c1 = spence_c(nu, mu);
            let by_mu = solve_given_mu(nu, mu, &opts);
            let by_c = c1.map(|c| solve_given_c(nu, c, &opts));
            count(&by_mu);
            if let Some(r) = &by_c {
                count(r);
            }
            let (c_ours, pstar, est) = match &by_mu {
                Ok(s) => (
                    format!("{:.6}", s.c),
                    format!("{:.10}", s.compliance),
                    format!("{:.0e}", s.error_estimate),
                ),
                Err(e) => (format!("error: {e}"), "-".into(), "-".into()),
            };
            let mu_c1 = match &by_c {
                Some(Ok(s)) => format!("{:.6} ({:+.1e})", s.mu, s.mu - mu),
                Some(Err(e)) => format!("error: {e}"),
                None => "-".into(),
            };
            let seed = match &by_mu {
                Ok(s) => seed_cell(nu, mu, s.c, tol),
                Err(_) => "-".into(),
            };
            vec![
                format!("{mu}"),
                format!("{nu}"),
                fmt_opt(c1, 4),
                format!("{c2:.4}"),
                format!("{c3:.4}"),
                c_ours,
                mu_c1,
                pstar,
                est,
                seed,
            ]
        })
        .collect();
    let head1 = [
        "μ",
        "ν",
        "seed c1 (Spence)",
        "seed c2",
        "seed c3",
        "our c(μ)",
        "our μ(c1) (ours − μ)",
        "our P*",
        "error est.",
        "seed's literal algorithm: P*",
    ];
    let rows2: Vec<Vec<String>> = TABLE2_NU
        .iter()
        .flat_map(|&nu| TABLE2_PAIRS.iter().map(move |&(c, mu)| (nu, c, mu)))
        .collect::<Vec<_>>()
        .par_iter()
        .filter(|_| show2)
        .map(|&(nu, c, mu)| {
            let r = solve_given_c(nu, c, &opts);
            count(&r);
            (nu, c, mu, r)
        })
        .map(|(nu, c, mu, r)| match r {
            Ok(s) => vec![
                format!("{nu}"),
                format!("{c}"),
                format!("{mu}"),
                format!("{:.6}", s.mu),
                format!("{:.10}", s.compliance),
                format!("{:.0e}", s.error_estimate),
            ],
            Err(e) => vec![
                format!("{nu}"),
                format!("{c}"),
                format!("{mu}"),
                format!("error: {e}"),
                "-".into(),
                "-".into(),
            ],
        })
        .collect();
    let head2 = ["ν", "c", "seed μ", "our μ(c)", "our P*", "error est."];
    let tally = tally.into_inner().unwrap_or_default();
    if csv {
        if show1 {
            write_csv_rows(w, &head1, &rows1)?;
        } else {
            write_csv_rows(w, &head2, &rows2)?;
        }
        return tally.status("solves");
    }
    if show1 {
        writeln!(
            w,
            "Table 1 of the seed paper (c for given μ; ν = 0 and 0.25) beside lambdamat\n"
        )?;
        write_md(w, &head1, &rows1)?;
        writeln!(
            w,
            "\nc1: Spence (1975); c2, c3: Gauthier et al. (LCP), as printed in the seed. Ours: the exact stick/slip problem of\n\
         docs/hertz.md; the error estimate is the change between the last two refinement levels. The last column runs the\n\
         seed's own algorithm (eq. 2.4 on [c,1], eq. 3.3 on [0,c)) at our c with the same numerics, levels 0..4.\n"
        )?;
    }
    if show2 {
        writeln!(
            w,
            "Table 2 of the seed paper (the same (c, μ) pairs for every ν) beside lambdamat\n"
        )?;
        write_md(w, &head2, &rows2)?;
        writeln!(
            w,
            "\nThe seed uses ν = 0 pairs (c, μ) for every ν; in the exact problem μ(c) depends on ν, as the fourth column shows."
        )?;
    }
    tally.status("solves")
}

fn write_md(w: &mut dyn Write, head: &[&str], rows: &[Vec<String>]) -> Result<(), CliError> {
    writeln!(w, "| {} |", head.join(" | "))?;
    writeln!(w, "|{}", "---|".repeat(head.len()))?;
    for r in rows {
        writeln!(w, "| {} |", r.join(" | "))?;
    }
    Ok(())
}

fn csv_field(s: &str) -> String {
    if s.contains(',') || s.contains('"') {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

fn write_csv_rows(w: &mut dyn Write, head: &[&str], rows: &[Vec<String>]) -> Result<(), CliError> {
    writeln!(
        w,
        "{}",
        head.iter()
            .map(|h| csv_field(h))
            .collect::<Vec<_>>()
            .join(",")
    )?;
    for r in rows {
        writeln!(
            w,
            "{}",
            r.iter().map(|h| csv_field(h)).collect::<Vec<_>>().join(",")
        )?;
    }
    Ok(())
}

/// The most points a sweep solves (ν count × μ count): checked before
/// anything is allocated.
pub const MAX_SWEEP_POINTS: usize = 100_000;

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

/// `--json` output of a refusal at a physical limit.
#[derive(serde::Serialize)]
struct RefusalJson {
    nu: f64,
    c: Option<f64>,
    mu: Option<f64>,
    error: String,
    limit: Option<Limit>,
}

#[derive(serde::Serialize)]
struct SweepRow {
    nu: f64,
    mu: f64,
    c: Option<f64>,
    alpha: Option<f64>,
    compliance: Option<f64>,
    compliance_via_shear: Option<f64>,
    error_estimate: Option<f64>,
    stick_ok: Option<bool>,
    slip_ok: Option<bool>,
    error: Option<String>,
    /// The physical limit of a refusal or of an end answer, with its
    /// asymptotic values.
    limit: Option<Limit>,
    /// At an end answer: `c < δ` or `c > 1 − δ` (bounded, not resolved).
    end_answer: Option<String>,
}

/// The resolved point of an end answer: `1.0262e-10` near the lower end,
/// `1 − 9.334e-13` near the upper one (where `{:.4e}` of the point itself
/// would print `1.0000e0`).
fn end_point(e: &crate::plan::split_end::EndAnswer) -> String {
    match e.end {
        RangeEnd::Lower => format!("{:.4e}", e.at),
        RangeEnd::Upper => format!("{} − {:.4e}", e.end_value, e.distance),
    }
}

/// `c < 1.03e-10, bounded` (or `c > 1 − …`) for an end answer.
fn bounded(s: &HertzResult) -> Option<String> {
    s.end_answer.as_ref().map(|e| match e.end {
        RangeEnd::Lower => format!(
            "{} < {:.3e}, bounded, not resolved (the root lies within {:.1e} of {})",
            e.scalar, e.at, e.distance, e.end_value
        ),
        RangeEnd::Upper => format!(
            "{} > {} − {:.3e}, bounded, not resolved (the root lies within {:.1e} of {})",
            e.scalar, e.end_value, e.distance, e.distance, e.end_value
        ),
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
    let points = nus.len().saturating_mul(mus.len());
    if points > MAX_SWEEP_POINTS {
        return Err(CliError::Invalid(format!(
            "the sweep has {} × {} = {points} points; the limit is {MAX_SWEEP_POINTS}",
            nus.len(),
            mus.len()
        )));
    }
    let grid: Vec<(f64, f64)> = nus
        .iter()
        .flat_map(|&n| mus.iter().map(move |&m| (n, m)))
        .collect();
    let bar = ProgressBar::new(grid.len() as u64);
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} solves, {elapsed} elapsed, eta {eta}")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let opts = options(tol);
    let tally = std::sync::Mutex::new(Tally::default());
    let rows: Vec<SweepRow> = grid
        .par_iter()
        .map(|&(nu, mu)| {
            let r = solve_with_limit(nu, Given::Mu(mu), &opts);
            bar.inc(1);
            if let Ok(mut t) = tally.lock() {
                t.add(&r);
            }
            match r {
                Ok(s) => SweepRow {
                    nu,
                    mu,
                    c: Some(s.c),
                    alpha: Some(s.alpha),
                    compliance: Some(s.compliance),
                    compliance_via_shear: Some(s.compliance_via_shear),
                    error_estimate: Some(s.error_estimate),
                    stick_ok: Some(s.stick_ok),
                    slip_ok: Some(s.slip_ok),
                    // An answer above the tolerance is shown, and said so.
                    error: (!s.converged).then(|| {
                        format!(
                            "not converged: the error estimate {:.1e} is above the tolerance {tol:.0e}",
                            s.error_estimate
                        )
                    }),
                    limit: s.limit,
                    end_answer: bounded(&s),
                },
                Err(Refusal { error: e, limit }) => SweepRow {
                    nu,
                    mu,
                    c: None,
                    alpha: None,
                    compliance: None,
                    compliance_via_shear: None,
                    error_estimate: None,
                    stick_ok: None,
                    slip_ok: None,
                    error: Some(e.to_string()),
                    limit,
                    end_answer: None,
                },
            }
        })
        .collect();
    bar.finish_and_clear();
    let mut text = String::new();
    if jsonl {
        for r in &rows {
            let _ = writeln!(
                text,
                "{}",
                serde_json::to_string(r).map_err(|e| CliError::Invalid(e.to_string()))?
            );
        }
    } else {
        text.push_str(
            "nu,mu,c,alpha,compliance,compliance_via_shear,error_estimate,stick_ok,slip_ok,error,limit,c_asymptotic_low,c_asymptotic_high,compliance_asymptotic,end_answer\n",
        );
        let f = |v: Option<f64>| v.map_or(String::new(), |x| format!("{x:.15e}"));
        let b = |v: Option<bool>| v.map_or(String::new(), |x| x.to_string());
        for r in &rows {
            let (c_lo, c_hi, p_asym) = match r.limit {
                Some(Limit::SmallFriction {
                    c_asymptotic: (lo, hi),
                    compliance_asymptotic,
                    ..
                }) => (Some(lo), Some(hi), Some(compliance_asymptotic)),
                _ => (None, None, None),
            };
            let _ = writeln!(
                text,
                "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
                r.nu,
                r.mu,
                f(r.c),
                f(r.alpha),
                f(r.compliance),
                f(r.compliance_via_shear),
                f(r.error_estimate),
                b(r.stick_ok),
                b(r.slip_ok),
                r.error.as_deref().map(csv_field).unwrap_or_default(),
                r.limit.map(|l| l.kind()).unwrap_or_default(),
                f(c_lo),
                f(c_hi),
                f(p_asym),
                r.end_answer.as_deref().map(csv_field).unwrap_or_default(),
            );
        }
    }
    match out {
        Some(p) => write_file(p, text.as_bytes(), &[], "")?,
        None => w.write_all(text.as_bytes())?,
    }
    super::output::note(&sweep_summary(&rows));
    tally.into_inner().unwrap_or_default().status("solves")
}

/// The sweep's summary line: counts, then the physical checks over the
/// solved points (stick, slip, 0 < c < 1 or c = 1 at ν = 1/2; c non-decreasing in μ at each ν,
/// whatever order the μ range was given in).
fn sweep_summary(rows: &[SweepRow]) -> String {
    let solved: Vec<&SweepRow> = rows.iter().filter(|r| r.c.is_some()).collect();
    let failed = rows.len() - solved.len();
    // Solved but above the tolerance (their `error` column says so).
    let unconverged = solved.iter().filter(|r| r.error.is_some()).count();
    let refused = |k: &str| {
        rows.iter()
            .filter(|r| r.c.is_none() && r.limit.is_some_and(|l| l.kind() == k))
            .count()
    };
    let (small, thin) = (refused("small_friction"), refused("thin_slip"));
    let at_end = |k: &str| {
        solved
            .iter()
            .filter(|r| r.end_answer.is_some() && r.limit.is_some_and(|l| l.kind() == k))
            .count()
    };
    let ends = solved.iter().filter(|r| r.end_answer.is_some()).count();
    let mut head = format!(
        "sweep: {} solves, {failed} failed ({small} in the small-friction limit, c < 1e-10; \
         {thin} near full stick, 1 − c < 1e-12; {} other); {ends} answered at an end of c's range, c bounded, not resolved \
         ({} with c < 1e-10 in the small-friction limit, {} with 1 − c < 1e-12 near full stick)",
        rows.len(),
        failed - small - thin,
        at_end("small_friction"),
        at_end("thin_slip"),
    );
    if unconverged > 0 {
        head.push_str(&format!(
            "; {unconverged} of the solved points did not reach the tolerance (their error column says so)"
        ));
    }
    if solved.is_empty() {
        return format!("{head}; no point solved, so no physical check");
    }
    let phys = solved.iter().filter(|r| r.mu > 0.0).all(|r| {
        r.stick_ok == Some(true)
            && r.slip_ok == Some(true)
            // ν = 1/2 (γ = 0) sticks everywhere: c = 1 exactly.
            && r.c.is_some_and(|c| c > 0.0 && (c < 1.0 || r.nu == 0.5))
    });
    let mut by_nu: Vec<(f64, f64, f64)> = solved
        .iter()
        .filter_map(|r| r.c.map(|c| (r.nu, r.mu, c)))
        .collect();
    by_nu.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    let monotone = by_nu
        .windows(2)
        .all(|p| p[0].0 != p[1].0 || p[1].2 >= p[0].2);
    format!(
        "{head}; physical checks on the {} solved points (stick, slip, 0 < c < 1, c = 1 at ν = 1/2): {}; c non-decreasing in μ: {}",
        solved.len(),
        if phys { "all hold" } else { "SOME FAIL" },
        if monotone { "yes" } else { "NO" }
    )
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
