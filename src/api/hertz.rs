//! The library's entry to the flagship Hertz contact problem with finite
//! friction: one solve ([`hertz_report`], and [`hertz`] for its file's
//! [`Solution`]), the seed paper's tables ([`hertz_table`]) and a ν × μ
//! grid ([`hertz_sweep`]), each returning a value with its printers. Every
//! `lambdamat hertz …` command prints what these return, and the Python
//! package's `lambdamat.hertz` calls [`hertz`]. The solves go through the
//! `hertz` front (the language files `examples/hertz*.lmx` and the general
//! split-domain solver); this module owns the reports and their text, JSON
//! and CSV, not the computation.

use std::fmt::Write as _;

use rayon::prelude::*;

use super::{Error, Given, Solution, invalid};
use crate::hertz::front::{DEFAULT_MAX_LEVEL, HertzResult, Limit, Refusal};
use crate::hertz::seed::seed_literal;
use crate::hertz::tables::{SEED_TABLE1, spence_c};
use crate::plan::SplitOptions;
use crate::plan::error::RangeEnd;

/// Options of [`hertz_report`].
///
/// ```
/// let o = lambdamat::api::HertzOptions::default();
/// assert_eq!(o.tol, 1e-10);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct HertzOptions {
    /// Refine until the error estimate is below this (finite, > 0).
    pub tol: f64,
    /// The memory budget in bytes (default: half the free memory).
    pub max_memory: Option<u64>,
    /// Points of the output grid the file's report samples its unknowns
    /// on ([`Hertz::into_solution`]); the front's own values and printers
    /// do not use it. At least 2.
    pub grid: usize,
}

impl Default for HertzOptions {
    fn default() -> HertzOptions {
        HertzOptions {
            tol: 1e-10,
            max_memory: None,
            grid: crate::report::SolveSettings::default().grid,
        }
    }
}

/// Refuses a tolerance that is not a finite number > 0 (invalid input).
pub(crate) fn check_tol(tol: f64) -> Result<(), Error> {
    if tol > 0.0 && tol.is_finite() {
        Ok(())
    } else {
        Err(invalid(format!(
            "--tol {tol}: the tolerance must be a finite number > 0, e.g. 1e-10"
        )))
    }
}

/// The front's options at tolerance `tol` (the ladder of `lambdamat solve`).
fn options(tol: f64) -> SplitOptions {
    SplitOptions {
        tol,
        max_level: DEFAULT_MAX_LEVEL,
        field_tol: crate::plan::split_solve::default_field_tol(tol),
        ..SplitOptions::default()
    }
}

/// A solved Hertz problem: the stick radius c and friction coefficient μ
/// (one given, one found), the edge exponent, the compliance by two
/// formulas, the physical checks and their estimates, read off the
/// solution of the language file; what `lambdamat hertz --nu … --mu …`
/// prints ([`Hertz::text`], [`Hertz::to_json`]).
///
/// ```
/// use lambdamat::api::{Given, HertzOptions, hertz_report};
/// let h = hertz_report(0.25, Given::Mu(0.1801), &HertzOptions { tol: 1e-8, ..HertzOptions::default() })?;
/// assert!(h.converged());
/// assert!((h.c() - 0.4956467).abs() < 1e-6);
/// assert!(h.text().contains("given μ = 0.1801  →  c = 0.49564"));
/// # Ok::<(), lambdamat::Error>(())
/// ```
pub struct Hertz {
    result: HertzResult,
    given: Given,
}

impl std::fmt::Debug for Hertz {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Hertz")
            .field("given", &self.given)
            .field("nu", &self.nu())
            .field("c", &self.c())
            .field("mu", &self.mu())
            .field("error_estimate", &self.error_estimate())
            .field("converged", &self.converged())
            .finish_non_exhaustive()
    }
}

/// Why [`hertz_report`] gave no result: its [`Error`] and, for a refusal at
/// one of the physical limits the solver does not resolve, the JSON
/// `lambdamat hertz --json` prints for it (the error and the limit's
/// asymptotic values, for information).
///
/// ```
/// use lambdamat::api::{Given, HertzOptions, hertz_report};
/// let r = hertz_report(0.25, Given::C(1.5), &HertzOptions::default()).unwrap_err();
/// assert_eq!(r.error().exit_code(), 2); // c lies in (0, 1]
/// let e: lambdamat::Error = r.into();
/// assert!(!e.to_string().is_empty());
/// ```
#[derive(Debug)]
pub struct HertzRefusal {
    error: Error,
    json: Option<String>,
}

impl HertzRefusal {
    /// The error (its text states the limit, when there is one).
    ///
    /// ```
    /// use lambdamat::api::{Given, HertzOptions, hertz_report};
    /// let r = hertz_report(0.25, Given::Mu(-1.0), &HertzOptions::default()).unwrap_err();
    /// assert_eq!(r.error().kind(), lambdamat::ErrorKind::InvalidInput);
    /// ```
    pub fn error(&self) -> &Error {
        &self.error
    }

    /// The JSON object of a refusal at a physical limit (`None` for any
    /// other failure).
    ///
    /// ```
    /// use lambdamat::api::{Given, HertzOptions, hertz_report};
    /// // ν = −0.9, μ = 0.01 puts c near 1e-25, in the small-friction limit.
    /// let opts = HertzOptions { tol: 1e-11, ..HertzOptions::default() };
    /// let r = hertz_report(-0.9, Given::Mu(0.01), &opts).unwrap_err();
    /// assert!(r.limit_json().unwrap().contains("small"));
    /// ```
    pub fn limit_json(&self) -> Option<&str> {
        self.json.as_deref()
    }
}

impl From<HertzRefusal> for Error {
    fn from(r: HertzRefusal) -> Error {
        r.error
    }
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

/// Solves the Hertz contact problem for Poisson's ratio `nu` (−1 < ν ≤ 1/2)
/// and the given stick radius c or friction coefficient μ: the files
/// `examples/hertz.lmx` (μ given), `hertz_given_c.lmx` (c given) or
/// `hertz_frictionless.lmx` (no shear: μ = 0 or ν = 1/2), with the
/// parameters set as `--set` sets them. A parameter outside its physical
/// range is invalid input; a point in a physical limit the solver does not
/// resolve is refused (computation failed) with the limit's asymptotic
/// values. A result that did not reach the tolerance is `Ok` with
/// [`Hertz::converged`] false.
///
/// ```
/// use lambdamat::api::{Given, HertzOptions, hertz_report};
/// let bad = hertz_report(0.7, Given::Mu(0.1), &HertzOptions::default()).unwrap_err();
/// assert_eq!(bad.error().exit_code(), 2);
/// ```
pub fn hertz_report(nu: f64, given: Given, opts: &HertzOptions) -> Result<Hertz, HertzRefusal> {
    let refuse = |error: Error| HertzRefusal { error, json: None };
    check_tol(opts.tol).map_err(refuse)?;
    // -0 is 0 (and is shown so).
    let nu = nu + 0.0;
    let given = match given {
        Given::C(c) => Given::C(c + 0.0),
        Given::Mu(m) => Given::Mu(m + 0.0),
    };
    let grid = opts.grid.max(2);
    crate::hertz::front::solve_sampled(nu, given, &options(opts.tol), opts.max_memory, grid)
        .map(|result| Hertz { result, given })
        .map_err(|Refusal { error, limit }| {
            let json = limit.map(|limit| {
                let (c, mu) = match given {
                    Given::C(c) => (Some(c), None),
                    Given::Mu(m) => (None, Some(m)),
                };
                serde_json::to_string_pretty(&RefusalJson {
                    nu,
                    c,
                    mu,
                    error: error.to_string(),
                    limit: Some(limit),
                })
                .unwrap_or_default()
            });
            HertzRefusal {
                error: error.into(),
                json,
            }
        })
}

/// The Hertz problem as [`hertz_report`] solves it, returned as the report
/// of its language file's solve: the same [`Solution`] `lambdamat solve
/// examples/hertz.lmx --set nu=… --set mu=…` gives, after the front's
/// refusals and checks. A refusal is its [`Error`].
///
/// ```
/// use lambdamat::api::{hertz, Given};
/// let s = hertz(0.25, Given::Mu(0.1801), 1e-8)?;
/// assert!(s.converged);
/// assert!((s.scalars["c"] - 0.4956467).abs() < 1e-6);
/// # Ok::<(), lambdamat::Error>(())
/// ```
pub fn hertz(nu: f64, given: Given, tol: f64) -> Result<Solution, Error> {
    let opts = HertzOptions {
        tol,
        ..HertzOptions::default()
    };
    Ok(hertz_report(nu, given, &opts)?.into_solution())
}

impl Hertz {
    /// Poisson's ratio.
    ///
    /// ```
    /// use lambdamat::api::{Given, HertzOptions, hertz_report};
    /// let h = hertz_report(0.25, Given::Mu(0.1801), &HertzOptions { tol: 1e-7, ..HertzOptions::default() })?;
    /// assert_eq!(h.nu(), 0.25);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn nu(&self) -> f64 {
        self.result.nu
    }

    /// The stick radius (given or found; 0 without friction, 1 at ν = 1/2).
    ///
    /// ```
    /// use lambdamat::api::{Given, HertzOptions, hertz_report};
    /// let h = hertz_report(0.25, Given::Mu(0.1801), &HertzOptions { tol: 1e-7, ..HertzOptions::default() })?;
    /// assert!((h.c() - 0.4956467).abs() < 1e-6);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn c(&self) -> f64 {
        self.result.c
    }

    /// The friction coefficient (given or found).
    ///
    /// ```
    /// use lambdamat::api::{Given, HertzOptions, hertz_report};
    /// let h = hertz_report(0.25, Given::Mu(0.1801), &HertzOptions { tol: 1e-7, ..HertzOptions::default() })?;
    /// assert_eq!(h.mu(), 0.1801);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn mu(&self) -> f64 {
        self.result.mu
    }

    /// The compliance `P* = (π/2) ∫ x p dx`.
    ///
    /// ```
    /// use lambdamat::api::{Given, HertzOptions, hertz_report};
    /// let h = hertz_report(0.25, Given::Mu(0.1801), &HertzOptions { tol: 1e-7, ..HertzOptions::default() })?;
    /// // Friction stiffens the contact a little: P* lies between 1 (no friction)
    /// // and artanh(γ)/γ (full stick).
    /// assert!(h.compliance() > 1.0 && h.compliance() < 1.1);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn compliance(&self) -> f64 {
        self.result.compliance
    }

    /// The largest absolute estimate of the found scalar and the outputs.
    ///
    /// ```
    /// use lambdamat::api::{Given, HertzOptions, hertz_report};
    /// let h = hertz_report(0.25, Given::Mu(0.1801), &HertzOptions { tol: 1e-7, ..HertzOptions::default() })?;
    /// assert!(h.error_estimate() <= h.tol());
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn error_estimate(&self) -> f64 {
        self.result.error_estimate
    }

    /// Whether every estimate reached the tolerance.
    ///
    /// ```
    /// use lambdamat::api::{Given, HertzOptions, hertz_report};
    /// let h = hertz_report(0.25, Given::Mu(0.1801), &HertzOptions { tol: 1e-7, ..HertzOptions::default() })?;
    /// assert!(h.converged());
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn converged(&self) -> bool {
        self.result.converged
    }

    /// The requested tolerance.
    ///
    /// ```
    /// use lambdamat::api::{Given, HertzOptions, hertz_report};
    /// let h = hertz_report(0.25, Given::Mu(0.1801), &HertzOptions { tol: 1e-7, ..HertzOptions::default() })?;
    /// assert_eq!(h.tol(), 1e-7);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn tol(&self) -> f64 {
        self.result.tol
    }

    /// The front's result, for the command line's plot.
    pub(crate) fn result(&self) -> &HertzResult {
        &self.result
    }

    /// The report of the language file's solve (see [`hertz`]).
    ///
    /// ```
    /// use lambdamat::api::{Given, HertzOptions, hertz_report};
    /// let h = hertz_report(0.25, Given::Mu(0.1801), &HertzOptions { tol: 1e-7, ..HertzOptions::default() })?;
    /// let (c, s) = (h.c(), h.into_solution());
    /// assert_eq!(s.scalars["c"], c);
    /// assert!(s.unknowns.contains_key("p"));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn into_solution(self) -> Solution {
        self.result.into_file_report()
    }

    /// The JSON `lambdamat hertz --json` prints.
    ///
    /// ```
    /// use lambdamat::api::{Given, HertzOptions, hertz_report};
    /// let h = hertz_report(0.25, Given::Mu(0.1801), &HertzOptions { tol: 1e-7, ..HertzOptions::default() })?;
    /// let v: serde_json::Value = serde_json::from_str(&h.to_json()).unwrap();
    /// assert_eq!(v["nu"], 0.25);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(&self.result).unwrap_or_default()
    }

    /// `x, p, q, mu_p, u` on a fine grid, each field followed by its error
    /// estimate (`*_err`), as CSV: what `lambdamat hertz --csv FILE` writes.
    ///
    /// ```
    /// use lambdamat::api::{Given, HertzOptions, hertz_report};
    /// let h = hertz_report(0.25, Given::Mu(0.1801), &HertzOptions { tol: 1e-7, ..HertzOptions::default() })?;
    /// let csv = h.profile_csv()?;
    /// assert!(csv.starts_with("x,p,p_err,q,"));
    /// assert!(csv.lines().count() > 100);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn profile_csv(&self) -> Result<String, Error> {
        let samples = self.result.profile(400)?;
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

    /// The text `lambdamat hertz` prints.
    ///
    /// ```
    /// use lambdamat::api::{Given, HertzOptions, hertz_report};
    /// let h = hertz_report(0.25, Given::Mu(0.1801), &HertzOptions { tol: 1e-7, ..HertzOptions::default() })?;
    /// assert!(h.text().contains("c = 0.49564"));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn text(&self) -> String {
        text(&self.result, matches!(self.given, Given::C(_)))
    }
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

/// How the solves of a table or sweep ended.
///
/// ```
/// let s = lambdamat::api::hertz_sweep(&[0.25], &[0.1801], 1e-7, &|| {})?;
/// let t = s.tally();
/// assert_eq!((t.total, t.failed, t.not_converged), (1, 0, 0));
/// # Ok::<(), lambdamat::Error>(())
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Tally {
    /// How many solves there were.
    pub total: usize,
    /// How many failed (no value).
    pub failed: usize,
    /// How many gave a value that did not reach the tolerance.
    pub not_converged: usize,
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

/// The seed paper's Tables 1 and 2 beside lambdamat's values: what
/// `lambdamat hertz table` prints ([`HertzTable::markdown`],
/// [`HertzTable::csv`]). A failed solve is a cell with its error.
///
/// ```no_run
/// let t = lambdamat::api::hertz_table(None, 1e-8)?;
/// print!("{}", t.markdown());
/// # Ok::<(), lambdamat::Error>(())
/// ```
#[derive(Debug)]
pub struct HertzTable {
    which: Option<u8>,
    rows1: Vec<Vec<String>>,
    rows2: Vec<Vec<String>>,
    tally: Tally,
}

const HEAD1: [&str; 10] = [
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
const HEAD2: [&str; 6] = ["ν", "c", "seed μ", "our μ(c)", "our P*", "error est."];

/// Computes the seed paper's Table 1 (`which == Some(1)`), Table 2
/// (`Some(2)`) or both (`None`) at tolerance `tol`, solving in parallel.
///
/// ```no_run
/// let t = lambdamat::api::hertz_table(Some(2), 1e-8)?;
/// print!("{}", t.markdown());
/// assert_eq!(t.tally().failed, 0);
/// # Ok::<(), lambdamat::Error>(())
/// ```
pub fn hertz_table(which: Option<u8>, tol: f64) -> Result<HertzTable, Error> {
    check_tol(tol)?;
    if which.is_some_and(|w| !(1..=2).contains(&w)) {
        return Err(invalid(format!(
            "--table {}: the seed paper has tables 1 and 2",
            which.unwrap_or_default()
        )));
    }
    let opts = options(tol);
    let solve = |nu, given| crate::hertz::front::solve(nu, given, &opts);
    let show1 = which != Some(2);
    let show2 = which != Some(1);
    let tally = std::sync::Mutex::new(Tally::default());
    let count = |r: &Result<HertzResult, crate::plan::PlanError>| {
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
            let by_mu = solve(nu, Given::Mu(mu));
            let by_c = c1.map(|c| solve(nu, Given::C(c)));
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
    let rows2: Vec<Vec<String>> = TABLE2_NU
        .iter()
        .flat_map(|&nu| TABLE2_PAIRS.iter().map(move |&(c, mu)| (nu, c, mu)))
        .collect::<Vec<_>>()
        .par_iter()
        .filter(|_| show2)
        .map(|&(nu, c, mu)| {
            let r = solve(nu, Given::C(c));
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
    Ok(HertzTable {
        which,
        rows1,
        rows2,
        tally: tally.into_inner().unwrap_or_default(),
    })
}

impl HertzTable {
    /// How the solves ended.
    ///
    /// ```no_run
    /// let t = lambdamat::api::hertz_table(Some(2), 1e-8)?;
    /// assert_eq!(t.tally().failed, 0);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn tally(&self) -> Tally {
        self.tally
    }

    /// The table as CSV: Table 2 if only it was computed, else Table 1
    /// (what `lambdamat hertz table --csv` prints).
    ///
    /// ```no_run
    /// let t = lambdamat::api::hertz_table(Some(2), 1e-8)?;
    /// assert!(t.csv().starts_with("ν,c,seed μ"));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn csv(&self) -> String {
        if self.which == Some(2) {
            csv_rows(&HEAD2, &self.rows2)
        } else {
            csv_rows(&HEAD1, &self.rows1)
        }
    }

    /// The computed tables as Markdown with their notes (what `lambdamat
    /// hertz table` prints).
    ///
    /// ```no_run
    /// let t = lambdamat::api::hertz_table(Some(1), 1e-8)?;
    /// assert!(t.markdown().contains("seed c1 (Spence)"));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn markdown(&self) -> String {
        let mut w = String::new();
        if self.which != Some(2) {
            let _ = writeln!(
                w,
                "Table 1 of the seed paper (c for given μ; ν = 0 and 0.25) beside lambdamat\n"
            );
            md_rows(&mut w, &HEAD1, &self.rows1);
            let _ = writeln!(
                w,
                "\nc1: Spence (1975); c2, c3: Gauthier et al. (LCP), as printed in the seed. Ours: the exact stick/slip problem of\n\
             docs/hertz.md; the error estimate is the change between the last two refinement levels. The last column runs the\n\
             seed's own algorithm (eq. 2.4 on [c,1], eq. 3.3 on [0,c)) at our c with the same numerics, levels 0..4.\n"
            );
        }
        if self.which != Some(1) {
            let _ = writeln!(
                w,
                "Table 2 of the seed paper (the same (c, μ) pairs for every ν) beside lambdamat\n"
            );
            md_rows(&mut w, &HEAD2, &self.rows2);
            let _ = writeln!(
                w,
                "\nThe seed uses ν = 0 pairs (c, μ) for every ν; in the exact problem μ(c) depends on ν, as the fourth column shows."
            );
        }
        w
    }
}

fn md_rows(w: &mut String, head: &[&str], rows: &[Vec<String>]) {
    let _ = writeln!(w, "| {} |", head.join(" | "));
    let _ = writeln!(w, "|{}", "---|".repeat(head.len()));
    for r in rows {
        let _ = writeln!(w, "| {} |", r.join(" | "));
    }
}

fn csv_field(s: &str) -> String {
    if s.contains(',') || s.contains('"') {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

fn csv_rows(head: &[&str], rows: &[Vec<String>]) -> String {
    let line = |cells: &mut dyn Iterator<Item = String>| cells.collect::<Vec<_>>().join(",") + "\n";
    let mut w = line(&mut head.iter().map(|h| csv_field(h)));
    for r in rows {
        w.push_str(&line(&mut r.iter().map(|h| csv_field(h))));
    }
    w
}

/// The most points a sweep solves (ν count × μ count).
///
/// ```
/// let nus = vec![0.25; 1000];
/// let mus = vec![0.5; 101];
/// assert!(1000 * 101 > lambdamat::api::MAX_SWEEP_POINTS);
/// let e = lambdamat::api::hertz_sweep(&nus, &mus, 1e-8, &|| {}).unwrap_err();
/// assert_eq!(e.exit_code(), 2);
/// ```
pub const MAX_SWEEP_POINTS: usize = 100_000;

#[derive(Debug, serde::Serialize)]
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

/// The Hertz problem solved on a ν × μ grid: one row per point, ν-major,
/// a failed point being a row with its error; what `lambdamat hertz
/// sweep` prints ([`HertzSweep::csv`], [`HertzSweep::jsonl`],
/// [`HertzSweep::summary`]).
///
/// ```
/// let s = lambdamat::api::hertz_sweep(&[0.0, 0.25], &[0.5], 1e-7, &|| {})?;
/// assert_eq!(s.tally().total, 2);
/// # Ok::<(), lambdamat::Error>(())
/// ```
#[derive(Debug)]
pub struct HertzSweep {
    rows: Vec<SweepRow>,
    tally: Tally,
}

/// Solves every point of `nus × mus` (μ given) in parallel at tolerance
/// `tol`, calling `on_point` after each (for a progress bar). More than
/// [`MAX_SWEEP_POINTS`] points, or an invalid tolerance, is invalid
/// input; a point that fails is a row with its error and never stops the
/// sweep.
///
/// ```no_run
/// let s = lambdamat::api::hertz_sweep(&[0.25], &[0.1, 1.0], 1e-8, &|| {})?;
/// print!("{}", s.csv());
/// eprintln!("{}", s.summary());
/// # Ok::<(), lambdamat::Error>(())
/// ```
pub fn hertz_sweep(
    nus: &[f64],
    mus: &[f64],
    tol: f64,
    on_point: &(dyn Fn() + Sync),
) -> Result<HertzSweep, Error> {
    check_tol(tol)?;
    let points = nus.len().saturating_mul(mus.len());
    if points > MAX_SWEEP_POINTS {
        return Err(invalid(format!(
            "the sweep has {} × {} = {points} points; the limit is {MAX_SWEEP_POINTS}",
            nus.len(),
            mus.len()
        )));
    }
    let grid: Vec<(f64, f64)> = nus
        .iter()
        .flat_map(|&n| mus.iter().map(move |&m| (n, m)))
        .collect();
    let opts = options(tol);
    let tally = std::sync::Mutex::new(Tally::default());
    let rows: Vec<SweepRow> = grid
        .par_iter()
        .map(|&(nu, mu)| {
            let r = crate::hertz::front::solve_with_limit(nu, Given::Mu(mu), &opts);
            on_point();
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
    Ok(HertzSweep {
        rows,
        tally: tally.into_inner().unwrap_or_default(),
    })
}

impl HertzSweep {
    /// How the solves ended.
    ///
    /// ```
    /// let s = lambdamat::api::hertz_sweep(&[0.25], &[0.1801, 1.0], 1e-7, &|| {})?;
    /// assert_eq!(s.tally(), lambdamat::api::Tally { total: 2, failed: 0, not_converged: 0 });
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn tally(&self) -> Tally {
        self.tally
    }

    /// One JSON object per row, one per line (`--jsonl`).
    ///
    /// ```
    /// let s = lambdamat::api::hertz_sweep(&[0.25], &[0.1801, 1.0], 1e-7, &|| {})?;
    /// assert_eq!(s.jsonl().lines().count(), 2);
    /// let row: serde_json::Value = serde_json::from_str(s.jsonl().lines().next().unwrap()).unwrap();
    /// assert_eq!(row["mu"], 0.1801);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn jsonl(&self) -> String {
        let mut text = String::new();
        for r in &self.rows {
            let _ = writeln!(text, "{}", serde_json::to_string(r).unwrap_or_default());
        }
        text
    }

    /// The rows as CSV with a header line (the default output).
    ///
    /// ```
    /// let s = lambdamat::api::hertz_sweep(&[0.25], &[0.1801, 1.0], 1e-7, &|| {})?;
    /// assert_eq!(s.csv().lines().count(), 3);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn csv(&self) -> String {
        let mut text = String::from(
            "nu,mu,c,alpha,compliance,compliance_via_shear,error_estimate,stick_ok,slip_ok,error,limit,c_asymptotic_low,c_asymptotic_high,compliance_asymptotic,end_answer\n",
        );
        let f = |v: Option<f64>| v.map_or(String::new(), |x| format!("{x:.15e}"));
        let b = |v: Option<bool>| v.map_or(String::new(), |x| x.to_string());
        for r in &self.rows {
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
        text
    }

    /// The sweep's summary line: counts, then the physical checks over the
    /// solved points (stick, slip, 0 < c < 1 or c = 1 at ν = 1/2; c
    /// non-decreasing in μ at each ν, whatever order the μ range was given
    /// in). The command line prints it on standard error.
    ///
    /// ```
    /// let s = lambdamat::api::hertz_sweep(&[0.25], &[0.1801, 1.0], 1e-7, &|| {})?;
    /// assert!(s.summary().contains("2"));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn summary(&self) -> String {
        let rows = &self.rows;
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
}
