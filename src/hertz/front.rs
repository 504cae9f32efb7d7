//! The Hertz problem as a front over the language: `lambdamat hertz` (one
//! solve, `table`, `sweep`) runs the files `examples/hertz.lmx` (given ν,
//! μ → c), `examples/hertz_given_c.lmx` (given ν, c → μ) and, in the two
//! limits without shear (μ = 0, ν = 1/2), `examples/hertz_frictionless.lmx`,
//! embedded with `include_str!` and with the parameters set exactly as
//! `--set` sets them (the shortest decimal of the number, read as an exact
//! rational), through the one solve entry of [`crate::report`] (the
//! general split-domain solver and its report). So `lambdamat hertz --nu 0.25 --mu
//! 0.1801` and `lambdamat solve examples/hertz.lmx --set nu=0.25 --set
//! mu=0.1801` are one computation. The fields, the slip (from E2's residual
//! on the slip zone, docs/hertz.md) and the checks are read off the
//! solution with [`crate::plan::split_fields`]. Owns the Hertz-specific
//! reading of those files (which scalar is c or μ, which equation is E2,
//! the checks); it must not discretise or solve anything itself, and it
//! must not call the hand-written solver of this module's siblings (that
//! is the tests' independent oracle).
use std::collections::BTreeMap;
use std::f64::consts::{FRAC_2_PI, PI};

use serde::Serialize;

use crate::lang::parse_program_with;
use crate::lang::parser::parse_exact;
use crate::numeric::mesh::GRADING_FLOOR;
use crate::numeric::{Assembler, NumericError, Operator};
use crate::plan::error::{EndReason, RangeEnd};
use crate::plan::split_fields::{Approach, Fields, LevelFields, ResidualField, Valued};
use crate::plan::{PlanError, SplitInput, SplitOptions, SplitSolution};
use crate::report::{SolveSettings, solve_split_solution};
use crate::system::Program;

/// A language file the front runs: the path of its user copy (for
/// messages and the equivalent `lambdamat solve` command) and its text,
/// embedded from the copy beside this file (`src/hertz/*.lmx`;
/// `tests/split_hertz.rs` checks that the copies in `examples/` are
/// identical, so editing an example cannot silently change the product).
pub type Source = (&'static str, &'static str);

/// Given (ν, μ), find the stick radius c.
pub const GIVEN_MU: Source = ("examples/hertz.lmx", include_str!("hertz.lmx"));
/// Given (ν, c), find the friction coefficient μ.
pub const GIVEN_C: Source = (
    "examples/hertz_given_c.lmx",
    include_str!("hertz_given_c.lmx"),
);
/// The limits without shear stress (μ = 0, or ν = 1/2).
pub const NO_SHEAR: Source = (
    "examples/hertz_frictionless.lmx",
    include_str!("hertz_frictionless.lmx"),
);

/// The highest refinement level tried by default: `lambdamat solve`'s
/// default `--max-level`, so the two commands climb the same ladder.
pub const DEFAULT_MAX_LEVEL: usize = 8;

/// Which of c and μ is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Given {
    /// The stick radius c ∈ (0, 1): find μ.
    C(f64),
    /// The friction coefficient μ ≥ 0: find c.
    Mu(f64),
}

/// `p`, `q`, `μp` and `u` at one point, each with its error estimate
/// (`*_err`: the distance between the last two refinement levels' values
/// at this point, [`crate::plan::split_fields::LevelFields`]; infinite
/// after a single level).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Sample {
    /// Radius.
    pub x: f64,
    /// Normal stress.
    pub p: f64,
    /// Its estimate.
    pub p_err: f64,
    /// Shear stress.
    pub q: f64,
    /// Its estimate.
    pub q_err: f64,
    /// `μ p`.
    pub mu_p: f64,
    /// Its estimate.
    pub mu_p_err: f64,
    /// Slip (zero in the stick zone).
    pub u: f64,
    /// Its estimate.
    pub u_err: f64,
}

/// A solved Hertz problem, read off the language file's solution.
#[derive(Serialize)]
pub struct HertzResult {
    /// Poisson's ratio.
    pub nu: f64,
    /// `γ = (1-2ν)/(2-2ν)` (the file's parameter `gamma`).
    pub gamma: f64,
    /// Friction coefficient (given, or the scalar `mu` of the file).
    pub mu: f64,
    /// Stick radius (given, the scalar `c`; 0 without friction, 1 for ν = 1/2).
    pub c: f64,
    /// Edge exponent `α = arccot(γμ)/π` (the file's `alpha`).
    pub alpha: f64,
    /// `P* = (π/2) ∫ x p dx` (output `P`).
    pub compliance: f64,
    /// `P* = 1 + γ ∫ q (1 - √(1-t²)) dt` (output `P_shear`).
    pub compliance_via_shear: f64,
    /// `compliance - compliance_via_shear`.
    pub compliance_difference: f64,
    /// The largest absolute estimate of the scalar and the outputs (from
    /// the report of [`crate::report::solve`]).
    pub error_estimate: f64,
    /// Whether every estimate met `tol·max(1, |value|)` (the report's rule).
    pub converged: bool,
    /// The requested tolerance.
    pub tol: f64,
    /// `q < μp` on the sampled stick zone `[0, c)`.
    pub stick_ok: bool,
    /// `u < 0` on the sampled slip zone `(c, 1]` (`u = 0` when γ = 0, where
    /// E2's residual vanishes identically).
    pub slip_ok: bool,
    /// `R(c)`: E2's residual at `x = c` divided by `c` (the bounded-shear
    /// condition of docs/hertz.md; zero at the free boundary).
    pub residual_c: f64,
    /// `q(c⁻) - μ p(c)` (regular part of the stick shear): continuity of
    /// the shear at the stick/slip point.
    pub shear_jump_at_c: f64,
    /// Estimates of the pointwise values above (`residual_c`,
    /// `shear_jump_at_c`): the distance between the last two levels' values,
    /// each level at its own c.
    pub field_error_estimates: BTreeMap<String, f64>,
    /// Number of unknowns of the final discretisation.
    pub unknowns: usize,
    /// Number of refinement levels used.
    pub levels: usize,
    /// Condition estimate of the final system.
    pub condition: f64,
    /// The language file that was solved.
    pub file: &'static str,
    /// The same computation from the command line.
    pub command: String,
    /// Each scalar's, output's and singular coefficient's own estimate.
    pub error_estimates: BTreeMap<String, f64>,
    /// Set when the found scalar was not resolved but bounded: its root
    /// lies within `distance` of an end of its range (`c < 1e-10`, say),
    /// `c` (or `μ`) is the middle of that gap with half of it as its
    /// estimate, and the outputs include their variation over the gap
    /// (`crate::plan::split_end`). The checks at `c` (shear jump, E2
    /// residual) are not made then.
    pub end_answer: Option<crate::plan::split_end::EndAnswer>,
    /// At an end answer, the physical limit it lies in and its asymptotic
    /// values (information only).
    pub limit: Option<Limit>,
    /// Set when the panels beside `c` are the same on the last two levels
    /// (the grading toward `c` stopped at the mesh floor): the values at
    /// `c` (`residual_c`, `shear_jump_at_c`) are then not refined, their
    /// estimates are infinite and the shear-jump check is not made
    /// ([`UnrefinedAtC`]).
    pub unrefined_at_c: Option<UnrefinedAtC>,
    /// The report of the language file's solve: what `lambdamat solve`
    /// prints for the file and the parameters of [`HertzResult::command`].
    #[serde(skip)]
    file_report: crate::report::Report,
    #[serde(skip)]
    solution: SplitSolution,
    /// The stick radius of the discretisation the fields are read from
    /// (`c` itself, except at an end answer: the resolved point).
    #[serde(skip)]
    c_fields: f64,
    #[serde(skip)]
    slip: Option<ResidualField>,
    #[serde(skip)]
    pq: (usize, usize),
    #[serde(skip)]
    found: Found,
}

/// Which of μ and c the file's scalar is (its first slot).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Found {
    /// The stick radius (given μ).
    C,
    /// The friction coefficient (given c).
    Mu,
    /// No scalar (no shear).
    Nothing,
}

impl Found {
    /// `(μ, c)` of a level whose first slot is `scalar`, the other one
    /// being the given `(mu, c)`.
    fn mu_c(self, scalar: Option<f64>, mu: f64, c: f64) -> (f64, f64) {
        match self {
            Found::C => (mu, scalar.unwrap_or(c)),
            Found::Mu => (scalar.unwrap_or(mu), c),
            Found::Nothing => (mu, c),
        }
    }
}

/// Why the fields at `c` are not refined: the panel touching `c` from
/// below or from above has the same width on the last two levels (each
/// level at its own `c`), with the same node count or at the mesh floor
/// (see `same_shape`). Every level puts the same number of nodes on a
/// panel touching a graded point, so the discretisation at `c` itself did
/// not change, and the two levels' values there agree whatever their
/// error: their difference is no estimate. This happens when the grading
/// toward `c` reaches the mesh floor (`Mesh::graded_to_scale`: panels of
/// at least `1e3` ulps of `c`, since a position near 1 is known only to
/// `ulp(1) ≈ 1.1e-16`), i.e. when `c` is close to 1. Measured at ν = 0.4
/// (1 − c = 1.8e-12 at μ = 46.4, 2.9e-11 at μ = 4.64): the slip annulus is
/// 8 to 130 floor panels wide, and the shear jump is −13 % and −10 % of
/// `μp(c)` with level differences of 1e-8 relative; a floor ten times
/// lower moved it by 30 % (μ = 4.64), while c and P* moved by 4e-15 and
/// 3e-16. Also at (0.3, 100) and (0.4, 1), where the jump was −159 ± 0.04
/// and −0.013 ± 8.8e-7 (the lower floor: −266 and −0.0076).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct UnrefinedAtC {
    /// Width of the panel touching `c` from below (last level).
    pub panel_below: f64,
    /// Width of the panel touching `c` from above (last level).
    pub panel_above: f64,
    /// `1 − c` (the width of the slip zone).
    pub one_minus_c: f64,
    /// The last level's `(q(c⁻) − μp(c))/(μp(c))`: the continuum value is
    /// 0, so this is the local error at c relative to the stress there.
    pub jump_relative: f64,
}

impl UnrefinedAtC {
    /// The report's sentence.
    pub fn describe(&self) -> String {
        format!(
            "the panels beside c ({:.1e} below, {:.1e} above; 1 − c = {:.1e}) are the same on the last two levels (the grading toward c is at the mesh floor of 1e3 ulps), so the fields at c are not refined and carry no estimate; their continuum values are 0, and the last level's shear jump is {:.1e} of μp(c)",
            self.panel_below, self.panel_above, self.one_minus_c, self.jump_relative
        )
    }
}

/// [`UnrefinedAtC`] of `lf` when the panels touching each level's own `c`
/// (`own_c`) have the same widths, to 1e-9 relative, on the last two
/// levels, from either side; `None` when they changed or with one level.
fn unrefined_at_c<'a, F>(lf: &LevelFields<'a>, own_c: F, jump_relative: f64) -> Option<UnrefinedAtC>
where
    F: Fn(&Fields<'a>) -> f64,
{
    let prev = lf.previous.as_ref()?;
    let shape = |f: &Fields<'a>, side: Approach| {
        let c = own_c(f);
        f.panel_shape(c, side).map(|(a, b, n)| (b - a, n))
    };
    let below = shape(&lf.last, Approach::Below)?;
    let above = shape(&lf.last, Approach::Above)?;
    let c = own_c(&lf.last);
    let unchanged = |w: (f64, usize), side| shape(prev, side).is_some_and(|v| same_shape(w, v, c));
    (unchanged(below, Approach::Below) || unchanged(above, Approach::Above)).then(|| UnrefinedAtC {
        panel_below: below.0,
        panel_above: above.0,
        one_minus_c: 1.0 - own_c(&lf.last),
        jump_relative,
    })
}

/// Given μ, a root `c` whose fields at `c` are not refined is refused
/// when `1 − c` plus c's estimate is below half of `1 − c∞(ν)`, the
/// derived width of the slip annulus as μ → ∞ (docs/hertz_asymptotics.md):
/// c grows with μ toward `c∞`, so no finite μ has such a root, and the
/// next roots of the condition (`δₙ = δ₀·exp(−nπ/ε₀)`, the spurious ones)
/// lie a factor `exp(−π/ε₀) ≤ 3e-5` (ν ≥ −0.9) below the physical one.
fn beyond_c_infinity(
    nu: f64,
    given: Given,
    gamma: f64,
    c: f64,
    scalars: &[crate::plan::split_solve::Estimate],
    u: &UnrefinedAtC,
) -> Result<Option<PlanError>, PlanError> {
    if !(matches!(given, Given::Mu(_)) && nu > -1.0 && nu < 0.5 && c > 0.5) {
        return Ok(None);
    }
    let (one_minus_c_inf, _) = large_friction_asymptotics(gamma);
    let c_err = scalars
        .iter()
        .find(|e| e.name == "c")
        .map(|e| e.error)
        .ok_or_else(|| invalid("the Hertz file has no `c`".into()))?;
    Ok((1.0 - c + c_err < 0.5 * one_minus_c_inf).then(|| {
        no_convergence(format!(
            "the root 1 − c = {:.3e} ± {c_err:.1e} lies below half of 1 − c∞(ν) = {one_minus_c_inf:.3e}, which no finite μ reaches, so it is not the physical free boundary; {}",
            1.0 - c,
            u.describe()
        ))
    }))
}

/// Two panels `(width, nodes)` of two levels beside the graded point `c`
/// are the same discretisation at `c`: widths equal to 1e-9 (each level's
/// panels sit at its own c, which moves the ends by rounding), and either
/// the same node count or a width at the mesh floor
/// ([`GRADING_FLOOR`]`·c`, within the factor `1/σ ≤ 8` of one grading
/// layer). At the floor the panel cannot shrink on any level, and more
/// nodes on it do not resolve a structure at c below its width: near full
/// stick the shear at c has a layer of width about `e^(−πγμ)(1 − c)`
/// (docs/hertz_asymptotics.md, step L3). Measured at ν = 0.4, μ = 1e4,
/// tol 1e-12 (1 − c = 1.5e-12): the panel below c is 2.27e-13 wide on
/// both levels with 3 and then 4 nodes, and the shear jump stays at
/// −10 % of μp(c) with a level difference of 0.7 %.
fn same_shape(a: (f64, usize), b: (f64, usize), c: f64) -> bool {
    let width = a.0.abs().max(b.0.abs());
    let at_floor = width <= 8.0 * GRADING_FLOOR * c.abs();
    (a.1 == b.1 || at_floor) && (a.0 - b.0).abs() <= 1e-9 * width
}

fn invalid(s: String) -> PlanError {
    PlanError::Invalid(s)
}

fn no_convergence(s: String) -> PlanError {
    PlanError::Numeric {
        context: "Hertz problem".into(),
        source: NumericError::NoConvergence(s),
    }
}

/// The distance `1 − c` below which the split solver does not place a
/// root (it scans to `e^(−27.7) ≈ 9.3e-13` relative of the upper end).
pub const RESOLVED: f64 = 1e-12;

/// The stick radius below which the split solver does not place a root:
/// it scans to `1e-10` of the lower end (below `c ≈ 1e-9` its discrete
/// condition carries rounding noise of about `4e-16/c`, and below about
/// `1e-10` that noise breaks the Coulomb bound beside `c`;
/// docs/hertz_asymptotics.md).
pub const RESOLVED_STICK: f64 = 1e-10;

/// The small-μ stick radius derived in docs/hertz_asymptotics.md:
/// `(a, C₀)` of `c = C₀·exp(−a/μ)·(1 + O(μ))`, `a = −ln(1−γ²)/γ`,
/// `C₀ = 4(1−γ²)^(1−2 ln 2)`.
pub fn small_friction_asymptotics(gamma: f64) -> (f64, f64) {
    let g2 = gamma * gamma;
    (
        -(1.0 - g2).ln() / gamma,
        4.0 * (1.0 - g2).powf(1.0 - 2.0 * std::f64::consts::LN_2),
    )
}

/// The measured range of the `O(μ)` correction of the small-μ stick
/// radius, as a multiple of `γμ`: `ln(c/(C₀e^(−a/μ)))/(γμ)` lies in
/// `[−1.32, −1.0]` for ν ∈ [−0.9, 0.4] (docs/hertz_asymptotics.md); the
/// range given is that with a margin.
pub const SMALL_FRICTION_CORRECTION: (f64, f64) = (-1.5, -0.9);

/// `J` of the `μ²` term `γ²J` of the small-μ compliance,
/// `J = −(2/π)∫_0^1 (−1 + (2/π)xK(x))(K(x) − E(x))/x dx` with the complete
/// elliptic integrals of modulus x (derived in docs/hertz_asymptotics.md,
/// evaluated by mpmath in docs/hertz_asymptotics_checks.py, part j).
pub const SMALL_FRICTION_COMPLIANCE_J: f64 = -0.024_395_310_845_086_8;

/// A refusal of [`solve_with_limit`]: the error (exit 3 for a numerical
/// refusal, 2 for bad input) and, when the refusal is one of the physical
/// limits, which one.
#[derive(Debug)]
pub struct Refusal {
    /// The error, whose text states the limit when there is one.
    pub error: PlanError,
    /// The physical limit the point lies in, if the refusal is one.
    pub limit: Option<Limit>,
}

/// A physical limit of the Hertz problem that the split solver refuses to
/// resolve, with its asymptotic values (information only: none of them is
/// a solution refined to the tolerance).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Limit {
    /// μ → 0: the stick radius is below [`RESOLVED_STICK`], or below about
    /// `1e-9` where the shear-jump check refuses the noisy stick shear.
    /// `c = C₀·exp(−a/μ)·(1 + O(μ))` with `a = −ln(1−γ²)/γ` and
    /// `C₀ = 4(1−γ²)^(1−2 ln 2)`, and
    /// `P* = 1 + γμ(1−2/π) + γ²Jμ² + O(μ³)` with
    /// [`SMALL_FRICTION_COMPLIANCE_J`] (all derived).
    SmallFriction {
        /// `a = −ln(1−γ²)/γ`.
        exponent: f64,
        /// `C₀·exp(−a/μ + kγμ)` for `k` at the ends of
        /// [`SMALL_FRICTION_CORRECTION`] (the measured `O(μ)` term).
        c_asymptotic: (f64, f64),
        /// Their `log₁₀`, finite where the values underflow (`−2.4988e8`
        /// at ν = 0, μ = 1e-9).
        log10_c_asymptotic: (f64, f64),
        /// `1 + γμ(1−2/π) + γ²Jμ²` (remainder O(μ³), measured about
        /// `−0.08γ³μ³`).
        compliance_asymptotic: f64,
        /// The μ at which `C₀·exp(−a/μ)` reaches [`RESOLVED_STICK`].
        mu_resolved: f64,
    },
    /// `1 − c` is below [`RESOLVED`]: near-full stick (ν close to 1/2 or
    /// large μ). As μ → ∞, `1 − c → 1 − c∞(ν) = δ₀(1 − δ₀/2 + O(δ₀²))`
    /// with `δ₀ = 8·exp(−π/(2ε₀))`, `ε₀ = artanh(γ)/π`, and
    /// `ln((1 − c)/(1 − c∞)) = (1/(2μ) + O(μ⁻²))/ε₀`; `P* → P*ₛ(1 − δ₀/2)`
    /// below the full-stick `P*ₛ = artanh(γ)/γ` (docs/hertz_asymptotics.md).
    ThinSlip {
        /// `δ₀(1 − δ₀/2)`, see [`large_friction_asymptotics`] (0 when it
        /// underflows, as for ν ≥ 0.4967; subnormal from ν ≈ 0.4966; see the next field).
        one_minus_c_infinity: f64,
        /// `log₁₀` of `1 − c∞`, finite where the value itself underflows
        /// (`−1073.6` at ν = 0.499).
        log10_one_minus_c_infinity: f64,
        /// `P*ₛ(1 − δ₀/2)`, the compliance as μ → ∞.
        compliance_infinity: f64,
        /// The full-stick compliance `artanh(γ)/γ`, an upper bound of P*.
        compliance_full_stick: f64,
    },
    /// A given stick radius beyond `c∞(ν)`, the limit of c as μ → ∞: no
    /// finite μ has it.
    BeyondLargeFriction {
        /// `c∞(ν) = 1 − δ₀(1 − δ₀/2)`, as in [`Limit::ThinSlip`].
        c_infinity: f64,
    },
}

/// `γ = (1−2ν)/(2−2ν)`.
fn gamma_of(nu: f64) -> f64 {
    (1.0 - 2.0 * nu) / (2.0 - 2.0 * nu)
}

/// The large-μ limit derived in docs/hertz_asymptotics.md (steps L1–L5):
/// `(1 − c∞, ε₀)` with `ε₀ = artanh(γ)/π` and
/// `1 − c∞ = δ₀(1 − δ₀/2) + O(δ₀³)`, `δ₀ = 8·exp(−π/(2ε₀))` (`δ₀` derived;
/// the `−δ₀/2` derived up to one assumption and measured).
pub fn large_friction_asymptotics(gamma: f64) -> (f64, f64) {
    let eps0 = gamma.atanh() / PI;
    let d0 = 8.0 * (-PI / (2.0 * eps0)).exp();
    (d0 * (1.0 - d0 / 2.0), eps0)
}

impl Limit {
    /// The small-friction limit at `(γ, μ)` with its derived asymptotics
    /// (docs/hertz_asymptotics.md): c to O(μ), P* to O(μ³).
    fn small_friction(gamma: f64, mu: f64) -> Limit {
        let (a, c0) = small_friction_asymptotics(gamma);
        let (klo, khi) = SMALL_FRICTION_CORRECTION;
        let ln_c_at = |k: f64| c0.ln() - a / mu + k * gamma * mu;
        let c_at = |k: f64| ln_c_at(k).exp();
        let log10_c_at = |k: f64| ln_c_at(k) / std::f64::consts::LN_10;
        Limit::SmallFriction {
            exponent: a,
            c_asymptotic: (c_at(klo), c_at(khi)),
            log10_c_asymptotic: (log10_c_at(klo), log10_c_at(khi)),
            compliance_asymptotic: 1.0
                + gamma * mu * (1.0 - FRAC_2_PI)
                + gamma * gamma * SMALL_FRICTION_COMPLIANCE_J * mu * mu,
            mu_resolved: a / (c0 / RESOLVED_STICK).ln(),
        }
    }

    /// The near-full-stick limit at `γ` with its derived values as μ → ∞.
    fn thin_slip(gamma: f64) -> Limit {
        let (one_minus_c_infinity, eps0) = large_friction_asymptotics(gamma);
        let full_stick = gamma.atanh() / gamma;
        // ln δ₀ = ln 8 − π/(2ε₀); the factor (1 − δ₀/2) is 1 wherever δ₀
        // underflows.
        let log10_one_minus_c_infinity = if one_minus_c_infinity > 0.0 {
            one_minus_c_infinity.log10()
        } else {
            (8.0f64.ln() - PI / (2.0 * eps0)) / std::f64::consts::LN_10
        };
        Limit::ThinSlip {
            one_minus_c_infinity,
            log10_one_minus_c_infinity,
            compliance_infinity: full_stick * (1.0 - one_minus_c_infinity / 2.0),
            compliance_full_stick: full_stick,
        }
    }

    /// `1 − c∞` of [`Limit::ThinSlip`] as text: `4.081e-7`, or `1e-1073.6`
    /// where it is below the smallest double (empty for the other limits).
    /// The small-friction limit's range of c as text: `4.56e-25–4.58e-25`,
    /// or powers of ten where the values underflow (`1e-249883840.2–…`).
    pub fn c_asymptotic_text(&self) -> String {
        match *self {
            Limit::SmallFriction {
                c_asymptotic: (lo, hi),
                log10_c_asymptotic: (llo, lhi),
                ..
            } => {
                if lo >= f64::MIN_POSITIVE {
                    format!("{lo:.2e}–{hi:.2e}")
                } else {
                    format!("1e{llo:.1}–1e{lhi:.1}")
                }
            }
            _ => String::new(),
        }
    }

    pub fn one_minus_c_infinity_text(&self) -> String {
        match *self {
            Limit::ThinSlip {
                one_minus_c_infinity,
                log10_one_minus_c_infinity,
                ..
            } => {
                if one_minus_c_infinity >= f64::MIN_POSITIVE {
                    format!("{one_minus_c_infinity:.3e}")
                } else {
                    format!("1e{log10_one_minus_c_infinity:.1}")
                }
            }
            _ => String::new(),
        }
    }

    /// The limit a refusal of `(nu, given)` lies in, if any: only the
    /// split solver's structured "root at an end" refusals
    /// ([`PlanError::RootAtEnd`]) and the front's own spurious-root refusal
    /// are read, never bad input and never the message text.
    ///
    /// - Given μ, the stick radius c: no sign change with the condition
    ///   smallest toward `c = 1` is thin slip; any other refusal at an end
    ///   (toward 0, or all roots rejected, or noise near an end) and the
    ///   spurious free boundary are small friction when the asymptotic
    ///   `c ≈ C·exp(−a/μ)` is at most `1e-8` (the noisy zone starts near
    ///   `1e-9`, the scan stops at `1e-10`).
    /// - Given c, the friction μ: no sign change over `μ ∈ (1e-10, 1e12)`
    ///   toward `∞`, or with the condition levelling off at a non-zero
    ///   value toward `μ → 0` (measured: ν = 0.3, c = 1 − 1e-8 and ν = −0.9,
    ///   c = 0.99 level off at both ends), means no μ has that c: c is
    ///   beyond `c∞(ν)`.
    fn classify(nu: f64, given: Given, failure: &Failure) -> Option<Limit> {
        if !(nu > -1.0 && nu < 0.5) {
            return None;
        }
        let gamma = gamma_of(nu);
        let at_end = match failure {
            Failure::Plan(PlanError::RootAtEnd(r)) => Some(r.as_ref()),
            Failure::Spurious(_) => None,
            Failure::ThinSlip(_) => return Some(Limit::thin_slip(gamma)),
            Failure::Plan(_) => return None,
        };
        let no_sign_change =
            at_end.is_some_and(|r| matches!(r.reason, EndReason::NoSignChange { .. }));
        match given {
            Given::Mu(mu) if mu > 0.0 && mu.is_finite() => {
                if no_sign_change && at_end.is_some_and(|r| r.end == RangeEnd::Upper) {
                    return Some(Limit::thin_slip(gamma));
                }
                // The O(μ) range of the small-μ stick radius is measured
                // for small μ only: at large μ its factor exp(kγμ) would
                // put any c below 1e-8, so the leading term must be there
                // too (before, ν = 0.4, μ = 1e4 at tol 1e-12, a refusal at
                // 1 − c = 1.5e-12, was named small friction).
                let small = Limit::small_friction(gamma, mu);
                let (a, c0) = small_friction_asymptotics(gamma);
                match small {
                    Limit::SmallFriction {
                        c_asymptotic: (_, c_hi),
                        ..
                    } if c_hi.max(c0 * (-a / mu).exp()) <= 1e-8 => Some(small),
                    _ => None,
                }
            }
            Given::C(_) => {
                let r = at_end.filter(|_| no_sign_change)?;
                (r.end == RangeEnd::Upper || r.levels_off(RangeEnd::Lower, 1e-6)).then(|| {
                    Limit::BeyondLargeFriction {
                        c_infinity: 1.0 - large_friction_asymptotics(gamma).0,
                    }
                })
            }
            _ => None,
        }
    }

    /// The physical limit an end answer of `(nu, given)` at `end` lies
    /// in, with its asymptotic values (information beside the answer).
    pub fn at_end(nu: f64, given: Given, end: RangeEnd) -> Option<Limit> {
        if !(nu > -1.0 && nu < 0.5) {
            return None;
        }
        let gamma = gamma_of(nu);
        match (given, end) {
            (Given::Mu(mu), RangeEnd::Lower) if mu > 0.0 => Some(Limit::small_friction(gamma, mu)),
            (Given::Mu(_), RangeEnd::Upper) => Some(Limit::thin_slip(gamma)),
            _ => None,
        }
    }

    /// The name used in the sweep's `limit` column.
    pub fn kind(&self) -> &'static str {
        match self {
            Limit::SmallFriction { .. } => "small_friction",
            Limit::ThinSlip { .. } => "thin_slip",
            Limit::BeyondLargeFriction { .. } => "beyond_large_friction",
        }
    }

    /// The refusal's text: the physical limit, its asymptotic values, and
    /// the solver's own words.
    pub fn message(&self, nu: f64, given: Given, err: &PlanError) -> String {
        let gamma = gamma_of(nu);
        let nu = nu + 0.0;
        let head = match *self {
            Limit::SmallFriction {
                exponent,
                compliance_asymptotic,
                mu_resolved,
                ..
            } => {
                let mu = match given {
                    Given::Mu(m) => m,
                    Given::C(_) => f64::NAN,
                };
                format!(
                    "the stick radius is too small for the solver (it scans to {RESOLVED_STICK:.0e}; below about 1e-9 its condition and the stick shear beside c carry rounding noise of about 4e-16/c and up to 5e-14/c, and the shear-jump check refuses): \
                     (ν, μ) = ({nu}, {mu}) is in the small-friction limit, where \
                     c = C₀·exp(−a/μ)·(1 + O(μ)) with a = −ln(1−γ²)/γ = {exponent:.4} and C₀ = 4(1−γ²)^(1−2 ln 2) (derived), \
                     so c ≈ {} (the range is the measured O(μ) term; c reaches {RESOLVED_STICK:.0e} near μ ≈ {mu_resolved:.3}); \
                     P* = 1 + γμ(1−2/π) + γ²Jμ² + O(μ³) = {compliance_asymptotic:.15} + O(μ³) (derived, J = −0.0243953; the O(μ³) remainder is measured at about −0.08γ³μ³). \
                     These asymptotic values are not refined to the tolerance, so no answer is given \
                     (docs/hertz_asymptotics.md)",
                    self.c_asymptotic_text()
                )
            }
            Limit::ThinSlip {
                compliance_infinity,
                compliance_full_stick,
                ..
            } => {
                let width = self.one_minus_c_infinity_text();
                let eps0 = gamma.atanh() / PI;
                let rate = match given {
                    Given::Mu(m) => format!(
                        "; at μ = {m}, ln((1 − c)/(1 − c∞)) = (1/(2μ) + O(μ⁻²))/ε₀ ≈ {:.4} to first order \
                         (the 1/2 computed, not proved; the O(μ⁻²) term is about 0.25/(γμ²), measured)",
                        1.0 / (2.0 * eps0 * m)
                    ),
                    Given::C(_) => String::new(),
                };
                format!(
                    "1 − c is below {RESOLVED:.0e}, which the solver does not resolve: near-full stick \
                     (ν = {nu}, γ = {gamma:.4}, ε₀ = artanh(γ)/π = {eps0:.5}); as μ → ∞ a slip annulus of width \
                     1 − c∞(ν) = δ₀(1 − δ₀/2 + O(δ₀²)) = {width} remains, δ₀ = 8·exp(−π/(2ε₀)) \
                     (derived){rate}, and P* → P*ₛ(1 − δ₀/2) = {compliance_infinity:.16}, below the \
                     full-stick P*ₛ = artanh(γ)/γ = {compliance_full_stick:.16} by {:.3e}. These asymptotic \
                     values are not refined to the tolerance, so no answer is given (docs/hertz_asymptotics.md)",
                    compliance_full_stick - compliance_infinity
                )
            }
            Limit::BeyondLargeFriction { c_infinity } => {
                let c = match given {
                    Given::C(c) => c,
                    Given::Mu(_) => f64::NAN,
                };
                // How far below c∞ the given c is, and the μ the derived
                // rate c∞ − c ≈ (1 − c∞)/(2ε₀μ) gives it: μ grows like
                // 1/(c∞ − c), so an error of c∞ moves μ by μ/(c∞ − c) per
                // unit. The O(δ₀³) term of 1 − c∞ (coefficient measured
                // ≈ 0.19) bounds how well the formula places c∞.
                let (one_minus, eps0) = large_friction_asymptotics(gamma);
                let d0 = 8.0 * (-PI / (2.0 * eps0)).exp();
                let formula_err = 0.2 * d0.powi(3);
                let gap = c_infinity - c;
                let near = if gap > 5.0 * formula_err {
                    let mu = one_minus / (2.0 * eps0 * gap);
                    format!(
                        "; here c∞ − c = {gap:.2e}, where the rate c∞ − c ≈ (1 − c∞)/(2ε₀μ) puts μ near \
                         {mu:.2e}: μ grows like 1/(c∞ − c), so each 1e-14 of error in the computed stick \
                         radius moves μ by {:.1e}, and the scan runs on the coarsest level, whose own \
                         limit of c may lie below the given c",
                        mu * 1e-14 / gap
                    )
                } else {
                    format!(
                        "; c lies beyond c∞(ν) or within five times the formula's O(δ₀³) uncertainty \
                         ({formula_err:.0e}) of it, where μ, if there is one, is not placed"
                    )
                };
                format!(
                    "no μ the solver reaches (up to about 1e12, scanned on its first level) gives c = {c} \
                     at ν = {nu}: as μ → ∞ the stick radius tends to c∞(ν) < 1 (a slip annulus remains; \
                     1 − c∞ = δ₀(1 − δ₀/2 + O(δ₀²)), δ₀ = 8·exp(−π/(2ε₀)), ε₀ = artanh(γ)/π (derived), so \
                     c∞ = {c_infinity:.12} to about {formula_err:.0e}){near} (docs/hertz_asymptotics.md)"
                )
            }
        };
        format!("{head}. The solver: {err}")
    }
}

/// `x` as `--set` reads it: its shortest decimal, as an exact rational.
fn exact(name: &str, x: f64) -> Result<(String, num_rational::BigRational), PlanError> {
    let text = format!("{x}");
    parse_exact(&text)
        .map(|v| (name.to_string(), v))
        .ok_or_else(|| invalid(format!("{name} = {x} is not a finite number")))
}

/// The embedded file `src` with the parameters `sets` (exact decimals).
pub fn program(src: Source, sets: &[(&str, f64)]) -> Result<Program, PlanError> {
    let sets = sets
        .iter()
        .map(|&(n, v)| exact(n, v))
        .collect::<Result<Vec<_>, _>>()?;
    parse_program_with(src.1, src.0, &sets).map_err(|e| invalid(e.to_string()))
}

/// Parameter settings `(name, value)` for [`program`].
pub(crate) type Sets = Vec<(&'static str, f64)>;

/// Which file runs for `(ν, given)` and with which parameters, after the
/// physical ranges are checked (bad input is [`PlanError::Invalid`]).
pub(crate) fn plan(nu: f64, given: Given) -> Result<(Source, Sets), PlanError> {
    if !(nu > -1.0 && nu <= 0.5) {
        return Err(invalid(format!(
            "Poisson's ratio ν = {nu} is outside (-1, 1/2]: a stable isotropic solid has -1 < ν ≤ 1/2"
        )));
    }
    let nu = nu + 0.0;
    match given {
        Given::C(c) => {
            if !(c > 0.0 && c < 1.0) {
                return Err(invalid(format!("stick radius c = {c} not in (0,1)")));
            }
            if nu == 0.5 {
                return Err(invalid(
                    "ν = 1/2 decouples normal and shear stress: the stick zone is the whole contact (c = 1) for every μ".into(),
                ));
            }
            Ok((GIVEN_C, vec![("nu", nu), ("c", c)]))
        }
        Given::Mu(mu) => {
            if mu == f64::INFINITY {
                return Err(invalid(infinite_friction(nu)));
            }
            if !(mu >= 0.0 && mu.is_finite()) {
                return Err(invalid(format!("friction μ = {mu} must be finite and ≥ 0")));
            }
            if mu == 0.0 || nu == 0.5 {
                Ok((NO_SHEAR, vec![("nu", nu)]))
            } else {
                Ok((GIVEN_MU, vec![("nu", nu), ("mu", mu + 0.0)]))
            }
        }
    }
}

/// The bad-input text for `μ = ∞` at a valid `ν`. The problem is posed
/// for finite μ: its slip-zone law `q = μp` has no μ = ∞ form (there `p`
/// vanishes and `q` is left free), so μ = ∞ is only the limit μ → ∞,
/// derived in docs/hertz_asymptotics.md. The text gives that limit and a
/// finite μ that reaches it: `ln((1 − c)/(1 − c∞)) = (1/(2μ) + O(μ⁻²))/ε₀`
/// puts `c` within `1e-15` of `c∞` for μ ≥ 1e15 at every ν (`c∞ − c ≈
/// (1 − c∞)/(2ε₀μ)`, and `(1 − c∞)/(2ε₀) = 4e^(−π/(2ε₀))/ε₀` grows with
/// ε₀ up to `0.081` as ν → −1), and `P*` approaches `P*∞` at a similar
/// rate (measured: `0.15/ε₀` times `P*ₛ(1 − c∞)/μ`, below `3e-17` there).
fn infinite_friction(nu: f64) -> String {
    let head = "friction μ = inf: the problem is posed for a finite μ (its slip law q = μp has no μ = ∞ form), \
                so μ = ∞ is only the limit μ → ∞";
    let gamma = gamma_of(nu);
    if nu >= 0.5 {
        return format!(
            "{head}; at ν = 1/2 there is no shear and c = 1, P* = 1 for every μ: use --mu 1"
        );
    }
    let limit = Limit::thin_slip(gamma);
    let Limit::ThinSlip {
        compliance_infinity,
        compliance_full_stick,
        ..
    } = limit
    else {
        return head.to_string();
    };
    format!(
        "{head}, derived in docs/hertz_asymptotics.md: at ν = {nu} the stick radius tends to c∞ with \
         1 − c∞ = δ₀(1 − δ₀/2 + O(δ₀²)) = {}, δ₀ = 8·exp(−π/(2ε₀)), ε₀ = artanh(γ)/π = {:.5}, and \
         P* → P*ₛ(1 − δ₀/2) = {compliance_infinity:.12} (full stick P*ₛ = artanh(γ)/γ = {compliance_full_stick:.12}); \
         since ln((1 − c)/(1 − c∞)) = (1/(2μ) + O(μ⁻²))/ε₀, a finite μ of 1e15 or more is within 1e-15 of that limit: \
         use e.g. --mu 1e15",
        limit.one_minus_c_infinity_text(),
        gamma.atanh() / PI
    )
}

/// A parameter of `prog` (an exact one, or a real one evaluated at the
/// solution's slots).
fn param(prog: &Program, s: &SplitSolution, name: &str) -> Result<f64, PlanError> {
    if let Some(p) = prog.params.iter().find(|p| p.name == name) {
        return Ok(crate::plan::compile::rational(&p.value));
    }
    let slots = prog.contact.slots();
    slots
        .iter()
        .position(|n| n == name)
        .and_then(|i| s.discrete.vars.get(i).copied())
        .ok_or_else(|| invalid(format!("the Hertz file has no parameter `{name}`")))
}

/// The value of `name` in one of the report's maps.
fn value_of(map: &BTreeMap<String, f64>, name: &str) -> Result<f64, PlanError> {
    map.get(name)
        .copied()
        .ok_or_else(|| invalid(format!("the Hertz file has no `{name}`")))
}

/// Solves the Hertz problem for Poisson's ratio `nu` and the given c or
/// μ through the language files, with the tolerance and ladder of `opts`.
///
/// ```no_run
/// use lambdamat::hertz::front::{solve, Given};
/// use lambdamat::plan::SplitOptions;
/// let s = solve(0.25, Given::Mu(0.1801), &SplitOptions::default()).unwrap();
/// println!("c = {} ± {}", s.c, s.error_estimate);
/// ```
pub fn solve(nu: f64, given: Given, opts: &SplitOptions) -> Result<HertzResult, PlanError> {
    solve_with_limit(nu, given, opts).map_err(|r| r.error)
}

/// [`solve`], but a refusal at one of the physical limits the solver does
/// not resolve (see [`Limit`]) comes back as a [`Refusal`] whose error
/// states the limit and its asymptotic values (for information: they are
/// not refined to the tolerance, so the refusal stays a failure, exit 3).
pub fn solve_with_limit(
    nu: f64,
    given: Given,
    opts: &SplitOptions,
) -> Result<HertzResult, Refusal> {
    solve_within(nu, given, opts, None)
}

/// [`solve_with_limit`] within a memory budget of `max_memory` bytes
/// (`None`: the default of [`crate::numeric::budget`]).
pub fn solve_within(
    nu: f64,
    given: Given,
    opts: &SplitOptions,
    max_memory: Option<u64>,
) -> Result<HertzResult, Refusal> {
    solve_sampled(nu, given, opts, max_memory, 2)
}

/// [`solve_within`] with the report's unknowns sampled on `grid` points
/// (see [`HertzResult::solution`]). The front samples the fields at its
/// own points, so the command line asks for 2 (the ends only: sampling
/// 101 points per unknown made `lambdamat hertz` about 1.4 times
/// slower); the library's `api::hertz` asks for the grid of
/// `lambdamat solve`, whose report it returns.
pub(crate) fn solve_sampled(
    nu: f64,
    given: Given,
    opts: &SplitOptions,
    max_memory: Option<u64>,
    grid: usize,
) -> Result<HertzResult, Refusal> {
    if let Some(refusal) = extreme_given_c(nu, given) {
        return Err(refusal);
    }
    solve_inner(nu, given, opts, max_memory, grid).map_err(|failure| {
        let limit = Limit::classify(nu, given, &failure);
        let error = match failure {
            Failure::Plan(e) | Failure::Spurious(e) | Failure::ThinSlip(e) => e,
        };
        match limit {
            Some(limit) => Refusal {
                error: no_convergence(limit.message(nu, given, &error)),
                limit: Some(limit),
            },
            None => Refusal { error, limit: None },
        }
    })
}

/// The smallest given stick radius solved: below it the scan in μ and
/// the mesh grading toward c cost far more than a normal point (measured
/// at ν = 0.25: c = 1e-4 in 0.9 s, 1e-6 in 4.9 s, 1e-8 over 40 s, 1e-10
/// 27 s and 1.1 GB, and subnormal c overflowed the mesh builder).
pub const SMALLEST_GIVEN_C: f64 = 1e-6;

/// A refusal, before any solving, of a given stick radius the front does
/// not resolve: below [`SMALLEST_GIVEN_C`] (with the small-friction
/// asymptotic μ for information), beyond the large-friction limit `c∞(ν)`
/// (no finite μ has it), or closer to 1 than the split solver places a
/// root. In the user's terms, exit 3.
fn extreme_given_c(nu: f64, given: Given) -> Option<Refusal> {
    let Given::C(c) = given else { return None };
    if !(nu > -1.0 && nu < 0.5 && c > 0.0 && c < 1.0) {
        return None;
    }
    let gamma = gamma_of(nu);
    if c < SMALLEST_GIVEN_C {
        // c ≈ C₀·exp(−a/μ) as μ → 0 (docs/hertz_asymptotics.md).
        let (a, c0) = small_friction_asymptotics(gamma);
        let mu = a / (c0.ln() - c.ln());
        return Some(Refusal {
            error: no_convergence(format!(
                "the stick radius c = {c:e} is below {SMALLEST_GIVEN_C:e}, the smallest this front resolves within the time and memory of a normal point: \
                 as μ → 0 the stick radius is c ≈ {c0:.4}·exp(−{a:.4}/μ), which puts μ near {mu:.4e} (an asymptotic value, not refined to the tolerance; docs/hertz_asymptotics.md)"
            )),
            limit: None,
        });
    }
    let (one_minus_c_infinity, _) = large_friction_asymptotics(gamma);
    let c_infinity = 1.0 - one_minus_c_infinity;
    if c > c_infinity || 1.0 - c < 1e-10 {
        let limit = Limit::BeyondLargeFriction { c_infinity };
        let why = if c > c_infinity {
            format!(
                "the stick radius c = {c} is beyond c∞(ν) = {c_infinity} at ν = {nu}, the limit of c as μ → ∞: no finite friction coefficient gives it"
            )
        } else {
            format!(
                "the stick radius c = {c} is within 1e-10 of 1, closer than the split solver resolves (c∞(ν = {nu}) = {c_infinity}, the limit of c as μ → ∞)"
            )
        };
        return Some(Refusal {
            error: no_convergence(why),
            limit: (c > c_infinity).then_some(limit),
        });
    }
    None
}

/// Why [`solve_inner`] gave no result: the split solver's (or the input's)
/// error, or the front's own refusal of a spurious free boundary (a root
/// of the condition at which the shear still jumps).
enum Failure {
    Plan(PlanError),
    Spurious(PlanError),
    /// A root beyond the derived limit `c∞(ν)` where the fields at c are
    /// not refined: near-full stick ([`Limit::ThinSlip`]).
    ThinSlip(PlanError),
}

impl From<PlanError> for Failure {
    fn from(e: PlanError) -> Failure {
        Failure::Plan(e)
    }
}

fn solve_inner(
    nu: f64,
    given: Given,
    opts: &SplitOptions,
    budget: Option<u64>,
    grid: usize,
) -> Result<HertzResult, Failure> {
    if !(opts.tol > 0.0 && opts.tol.is_finite()) {
        return Err(invalid(format!(
            "--tol {}: the tolerance must be a finite number > 0, e.g. 1e-10",
            opts.tol
        ))
        .into());
    }
    let (src, sets) = plan(nu, given)?;
    let prog = program(src, &sets)?;
    let mut command = format!("lambdamat solve {}", src.0);
    for (n, v) in &sets {
        command.push_str(&format!(" --set {n}={v}"));
    }
    if opts.tol != 1e-10 {
        command.push_str(&format!(" --tol {:e}", opts.tol));
    }
    // The one solve entry and its report (as `lambdamat solve` runs it),
    // its unknowns on `grid` points (see `solve_sampled`).
    let settings = SolveSettings {
        tol: opts.tol,
        max_level: opts.max_level,
        // The unknowns' tolerance of `opts` (infinite: out of convergence).
        field_tol: Some(if opts.fields_converge {
            opts.field_tol
        } else {
            f64::INFINITY
        }),
        grid,
        max_memory: budget,
        ..SolveSettings::default()
    };
    let (report, solution) = solve_split_solution(SplitInput::from_program(&prog)?, &settings)?;
    let nu = nu + 0.0;
    let gamma = param(&prog, &solution, "gamma")?;
    let (mu, c) = match given {
        Given::C(c) => (value_of(&report.scalars, "mu")?, c),
        Given::Mu(mu) if src == GIVEN_MU => (mu + 0.0, value_of(&report.scalars, "c")?),
        // No shear: the whole contact slips (μ = 0) or sticks (ν = 1/2).
        Given::Mu(mu) => (mu + 0.0, if mu == 0.0 { 0.0 } else { 1.0 }),
    };
    let alpha = param(&prog, &solution, "alpha")?;
    let compliance = value_of(&report.outputs, "P")?;
    let compliance_via_shear = value_of(&report.outputs, "P_shear")?;
    // The numbers' own estimates (the unknowns' are read pointwise below).
    let error_estimates: BTreeMap<String, f64> = report
        .error_estimates
        .iter()
        .filter(|(k, _)| !report.unknowns.contains_key(*k))
        .map(|(k, v)| (k.clone(), *v))
        .collect();
    let error_estimate = report
        .scalars
        .keys()
        .chain(report.outputs.keys())
        .filter_map(|k| report.estimate(k))
        .fold(0.0, f64::max);
    let r = &solution.report;
    let (converged, tol, unknowns, levels, condition) =
        (report.converged, report.tol, r.dim, report.levels, r.cond);
    // Each level's (μ, c): the scalar of the file is the one not given.
    // (the first slot; none without shear).
    let found = match given {
        Given::C(_) => Found::Mu,
        Given::Mu(_) if src == GIVEN_MU => Found::C,
        Given::Mu(_) => Found::Nothing,
    };
    let end_answer = r.end_answer.clone();
    // The fields are those of the discretisation at the resolved point.
    let c_reported = c;
    let c = match (&end_answer, found) {
        (Some(e), Found::C) => e.at,
        _ => c,
    };
    let level_mu_c = |scalar: Option<f64>| found.mu_c(scalar, mu, c);
    let (slip, pq, residual_c, shear_jump_at_c, unrefined_at_c) = {
        let lf = LevelFields::new(&solution)?;
        let f = &lf.last;
        let (Some(p), Some(q)) = (f.unknown_index("p"), f.unknown_index("q")) else {
            return Err(invalid("the Hertz file must have unknowns p and q".into()).into());
        };
        // E2 (κ3 p + κ4 q = 0 on the stick zone) is the file's second equation.
        let e2 = 1;
        let slip = slip_field(f, c)?;
        let (mut residual_c, mut jump) = (Valued::ZERO, Valued::ZERO);
        let mut unrefined = None;
        if c > 0.0 && c < 1.0 && end_answer.is_none() {
            // Each level at its own c, as its scalars are compared.
            let own_c = |f: &Fields| level_mu_c(f.slot(0)).1;
            residual_c = lf.estimate(|f| {
                let c = own_c(f);
                Ok(f.residual(e2, c)? / c)
            })?;
            jump = lf.estimate(|f| {
                let c = own_c(f);
                Ok(f.regular_value(q, c, Approach::Below)? - f.value(q, c, Approach::Above)?)
            })?;
            let mu_p = mu * f.value(p, c, Approach::Above)?;
            // The residual is a sum of terms of the size of the stresses at
            // c, each rounded: a floor of 64 ulps of that size (measured:
            // the levels' values scatter by up to 4e-15 at c ≈ 0.5).
            let stresses = f
                .value(p, c, Approach::Above)?
                .abs()
                .max(mu_p.abs())
                .max(1.0);
            residual_c.error = residual_c.error.max(64.0 * f64::EPSILON * stresses / c);
            unrefined = unrefined_at_c(&lf, own_c, jump.value / mu_p);
            if let Some(u) = &unrefined {
                // The two levels are the same discretisation at c: their
                // difference there is no estimate (see `UnrefinedAtC`).
                residual_c.error = f64::INFINITY;
                jump.error = f64::INFINITY;
                if let Some(e) = beyond_c_infinity(nu, given, gamma, c, &r.scalars, u)? {
                    return Err(Failure::ThinSlip(e));
                }
            }
            // A root of the bounded-shear condition whose shear still jumps
            // at c is not the physical free boundary (measured at ν = 0:
            // c ≲ 4e-4, μ ≲ 0.065, where the condition degenerated before
            // the mesh reached the scale c). The jump must exceed 10 % of
            // μp(c) by more than its own estimate: below c ≈ 1e-9 the stick
            // shear beside c carries the small-c rounding noise, and the
            // jump is then of the size of its estimate (measured at ν = 0.1,
            // μ = 0.02154, c = 4.50e-10: 5.3e-3 ± 6.9e-3 against
            // μp(c) = 1.7e-2; docs/hertz_asymptotics.md). Where the fields
            // at c are not refined, the jump is not checked near c = 1
            // (the root is checked against c∞ above, and the split solver
            // took the lowest root that keeps the Coulomb bound); below
            // c = 1/2 it is checked without an estimate.
            let excess = if unrefined.is_some() {
                (c <= 0.5).then_some(jump.value.abs())
            } else {
                Some(jump.value.abs() - jump.error)
            };
            if jump.value.is_nan() || excess.is_some_and(|x| x > 0.1 * mu_p.abs()) {
                // Near 1, c as 1 − (1 − c): `1.0000e0` said nothing.
                let at = if c > 0.5 {
                    format!("1 − {:.4e}", 1.0 - c)
                } else {
                    format!("{c:.4e}")
                };
                return Err(Failure::Spurious(no_convergence(format!(
                    "spurious free boundary at c = {at}, μ = {mu:.4e}: q(c⁻) - μp(c) = {:.3e} ± {:.1e} (μp(c) = {:.3e}); \
                     c this close to 0 or 1 is outside the solver's reliable range",
                    jump.value,
                    jump.error,
                    mu_p.abs()
                ))));
            }
        }
        (slip, (p, q), residual_c, jump, unrefined)
    };
    // Without a free boundary (no shear: c = 0 or 1) both are zero by
    // definition, not computed, and carry no estimate.
    let field_error_estimates = if c > 0.0 && c < 1.0 && end_answer.is_none() {
        [
            ("residual_c".to_string(), residual_c.error),
            ("shear_jump_at_c".to_string(), shear_jump_at_c.error),
        ]
        .into_iter()
        .collect()
    } else {
        BTreeMap::new()
    };
    let limit = end_answer
        .as_ref()
        .and_then(|e| Limit::at_end(nu, given, e.end));
    let mut s = HertzResult {
        nu,
        gamma,
        mu,
        c: c_reported,
        alpha,
        compliance,
        compliance_via_shear,
        compliance_difference: compliance - compliance_via_shear,
        error_estimate,
        converged,
        tol,
        stick_ok: false,
        slip_ok: false,
        residual_c: residual_c.value,
        shear_jump_at_c: shear_jump_at_c.value,
        field_error_estimates,
        unknowns,
        levels,
        condition,
        file: src.0,
        command,
        error_estimates,
        end_answer,
        limit,
        unrefined_at_c,
        file_report: report,
        solution,
        c_fields: c,
        slip,
        pq,
        found,
    };
    let samples = s.sample_last(&profile_points(c, 200))?;
    // A point closer to c than c's own uncertainty is in neither zone: at
    // x = c + 6e-16 the slip is a rounding-level ±1e-19.
    // At an end answer the fields are those at the resolved point `c`,
    // the gap's far side: the zone between `c` and the end (the stick zone
    // at `c → 0`, the slip zone at `c → 1`) is inside the unresolved gap
    // and is not checked.
    let gap = s
        .end_answer
        .as_ref()
        .map_or(0.0, |e| (e.at - e.end_value).abs());
    let blur = [error_estimate, gap]
        .into_iter()
        .filter(|e| e.is_finite())
        .fold(0.0, f64::max);
    s.stick_ok = samples
        .iter()
        .filter(|v| v.x < c - blur)
        .all(|v| v.q < v.mu_p);
    // With γ = 0 (ν = 1/2) E2's residual κ3 p + κ4 q vanishes identically
    // (κ3 = 0, q = 0): no slip at all, which is not a violation.
    s.slip_ok = samples
        .iter()
        .filter(|v| v.x > c + blur)
        .all(|v| v.u < 0.0 || (gamma == 0.0 && v.u == 0.0));
    Ok(s)
}

impl HertzResult {
    /// The report of the language file's solve (`lambdamat solve` on
    /// [`HertzResult::command`]'s file and parameters), its unknowns on
    /// the grid the solve was asked for.
    pub(crate) fn into_file_report(self) -> crate::report::Report {
        self.file_report
    }

    /// The evaluator of the solution's fields.
    pub fn fields(&self) -> Result<Fields<'_>, PlanError> {
        Fields::new(&self.solution.problem, &self.solution.discrete)
    }

    /// The split solver's report (scalars, outputs, coefficients).
    #[cfg(feature = "internals")]
    pub fn report(&self) -> &crate::plan::SplitReport {
        &self.solution.report
    }

    /// Normal stress `p(x)`, `x ∈ [0, 1)`.
    #[cfg(feature = "internals")]
    pub fn p(&self, x: f64) -> Result<f64, PlanError> {
        self.fields()?.value(self.pq.0, x, Approach::Above)
    }

    /// Shear stress `q(x)` (with its singular part on the stick zone, zero
    /// up to the root tolerance; at `c` itself the slip side, `μp(c)`).
    #[cfg(feature = "internals")]
    pub fn q(&self, x: f64) -> Result<f64, PlanError> {
        self.fields()?.value(self.pq.1, x, Approach::Above)
    }

    /// `p, q, μp, u` at the points `xs` (each in `[0, 1)`) on the last
    /// level only (no estimates: `*_err` are NaN); for the checks.
    fn sample_last(&self, xs: &[f64]) -> Result<Vec<Sample>, PlanError> {
        check_points(xs)?;
        let f = self.fields()?;
        let u = slip_at(&self.slip, self.c_fields, xs)?;
        xs.iter()
            .zip(u)
            .map(|(&x, u)| {
                let p = f.value(self.pq.0, x, Approach::Above)?;
                Ok(Sample {
                    x,
                    p,
                    p_err: f64::NAN,
                    q: f.value(self.pq.1, x, Approach::Above)?,
                    q_err: f64::NAN,
                    mu_p: self.mu * p,
                    mu_p_err: f64::NAN,
                    u,
                    u_err: f64::NAN,
                })
            })
            .collect()
    }

    /// `p, q, μp, u` at the points `xs` (each in `[0, 1)`), each with its
    /// estimate ([`LevelFields`]): the largest distance to the previous
    /// level's value over a window around the point (that level at its own
    /// c and μ), plus what c's own estimate makes uncertain near c
    /// ([`LevelFields::shift_term`]).
    pub fn sample(&self, xs: &[f64]) -> Result<Vec<Sample>, PlanError> {
        check_points(xs)?;
        let lf = LevelFields::new(&self.solution)?;
        let own = |f: &Fields| self.found.mu_c(f.slot(0), self.mu, self.c_fields);
        let windows: Vec<Vec<(f64, Approach)>> =
            xs.iter().map(|&x| lf.window(x, Approach::Above)).collect();
        // The slip of each level at every window point at once (one
        // assembly row per point), each level at its own c.
        let flat: Vec<f64> = windows.iter().flatten().map(|w| w.0).collect();
        let u_last = slip_at(&self.slip, self.c_fields, &flat)?;
        let other = |f: &Option<Fields>, pts: &[f64]| -> Result<Option<Vec<f64>>, PlanError> {
            match f {
                Some(f) => {
                    let c = own(f).1;
                    Ok(Some(slip_at(&slip_field(f, c)?, c, pts)?))
                }
                None => Ok(None),
            }
        };
        let u_prev = other(&lf.previous, &flat)?;
        let frozen = |x: f64| {
            let shape = |f: &Fields| {
                f.panel_shape(x, Approach::Above)
                    .map(|(a, b, n)| (b - a, n))
            };
            match (&lf.previous, shape(&lf.last)) {
                (Some(prev), Some(last)) => shape(prev).is_some_and(|v| same_shape(last, v, x)),
                _ => false,
            }
        };
        let mut at = 0;
        xs.iter()
            .zip(&windows)
            .map(|(&x, w)| {
                let p = lf.value(self.pq.0, x, Approach::Above)?;
                let q = lf.value(self.pq.1, x, Approach::Above)?;
                let mu_p = lf.windowed(x, Approach::Above, |f, y, s| {
                    Ok(own(f).0 * f.value(self.pq.0, y, s)?)
                })?;
                let range = at..at + w.len();
                at += w.len();
                let finite = |d: f64| if d.is_nan() { f64::INFINITY } else { d };
                let mut u_err = match &u_prev {
                    Some(up) => range
                        .clone()
                        .fold(0.0f64, |m, j| m.max(finite((u_last[j] - up[j]).abs()))),
                    None => f64::INFINITY,
                };
                // u vanishes at c (continuously): its shift term uses u(c) = 0.
                if let Some(end) = lf.moving_end(x, Approach::Above) {
                    u_err += LevelFields::shift_term(x, end, u_last[range.start], 0.0);
                }
                // Where the panel holding x is the same on both levels (the
                // grading toward c or 1 stopped, see `UnrefinedAtC`), their
                // difference at x is no estimate.
                let no = |e: f64| if frozen(x) { f64::INFINITY } else { e };
                Ok(Sample {
                    x,
                    p: p.value,
                    p_err: no(p.error),
                    q: q.value,
                    q_err: no(q.error),
                    mu_p: mu_p.value,
                    mu_p_err: no(mu_p.error),
                    u: u_last[range.start],
                    u_err: no(u_err),
                })
            })
            .collect()
    }

    /// [`HertzResult::sample`] on `n` equal steps of `[0,1)` plus points
    /// clustered toward `c` from both sides and toward 1, sorted.
    pub fn profile(&self, n: usize) -> Result<Vec<Sample>, PlanError> {
        self.sample(&profile_points(self.c_fields, n))
    }

    /// The largest absolute residuals of E1 on `xs ∩ (0,1)` and of E2 on
    /// `xs ∩ (0,c)`, at points that need not be collocation nodes.
    #[cfg(feature = "internals")]
    pub fn residuals(&self, xs: &[f64]) -> Result<(f64, f64), PlanError> {
        let f = self.fields()?;
        let worst = |e: usize, pts: Vec<f64>| -> Result<f64, PlanError> {
            Ok(f.residuals(e, &pts)?
                .into_iter()
                .fold(0.0f64, |m, r| m.max(r.abs())))
        };
        let inner: Vec<f64> = xs.iter().copied().filter(|&x| x > 0.0 && x < 1.0).collect();
        let stick: Vec<f64> = inner
            .iter()
            .copied()
            .filter(|&x| x < self.c_fields)
            .collect();
        Ok((worst(0, inner)?, worst(1, stick)?))
    }
}

/// Refuses sample points outside `[0, 1)`.
fn check_points(xs: &[f64]) -> Result<(), PlanError> {
    match xs.iter().find(|x| !(0.0..1.0).contains(*x)) {
        Some(x) => Err(invalid(format!("sample point {x} not in [0,1)"))),
        None => Ok(()),
    }
}

/// E2's residual interpolated on the slip zone `[c, 1]` of one level
/// (`None` when there is no slip zone). E2 (κ3 p + κ4 q = 0 on the stick
/// zone) is the file's second equation.
fn slip_field(f: &Fields, c: f64) -> Result<Option<ResidualField>, PlanError> {
    if c < 1.0 {
        Ok(Some(f.residual_field(1, (c, 1.0))?))
    } else {
        Ok(None)
    }
}

/// Slip `u(x) = -(2/(πx)) ∫_c^x s r(s)/√(x²-s²) ds` on `(c, 1]` with `r`
/// E2's residual on the slip zone (`slip`, of a level whose stick radius
/// is `c`); zero in the stick zone.
fn slip_at(slip: &Option<ResidualField>, c: f64, xs: &[f64]) -> Result<Vec<f64>, PlanError> {
    let Some(r) = slip else {
        return Ok(vec![0.0; xs.len()]);
    };
    let op = Operator::abel_lower(c, |_x, s| s);
    let asm = Assembler::new(&r.basis).map_err(PlanError::numeric("slip"))?;
    xs.iter()
        .map(|&x| {
            if x <= c {
                return Ok(0.0);
            }
            let mut row = vec![0.0; r.basis.dim()];
            asm.row_into(&op, x.min(1.0), r.basis.support(), &mut row)
                .map_err(PlanError::numeric("slip"))?;
            let v: f64 = row.iter().zip(&r.values).map(|(a, b)| a * b).sum();
            Ok(-FRAC_2_PI / x * v)
        })
        .collect()
}

/// `n` equal steps of `[0,1)` plus points geometrically clustered toward
/// `c` (both sides, when `0 < c < 1`) and toward 1, sorted.
pub fn profile_points(c: f64, n: usize) -> Vec<f64> {
    let mut xs: Vec<f64> = (0..n.max(2)).map(|i| i as f64 / n.max(2) as f64).collect();
    for k in 1..=8i32 {
        let d = 10f64.powi(-k / 2 - 1) * if k % 2 == 0 { 1.0 } else { 0.3 };
        xs.push(1.0 - d);
        if c > 0.0 && c < 1.0 {
            xs.push(c - d * c);
            xs.push(c + d * (1.0 - c));
        }
    }
    xs.retain(|x| (0.0..1.0).contains(x));
    xs.sort_by(|a, b| a.total_cmp(b));
    xs.dedup();
    xs
}

/// The exact frictionless pressure `(2/π)/√(1-x²)`.
#[cfg(feature = "internals")]
pub fn frictionless_pressure(x: f64) -> f64 {
    2.0 / PI / (1.0 - x * x).sqrt()
}
