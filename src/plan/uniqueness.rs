//! Equations with more than one solution, recognised from their operators
//! before any discretisation (issue 27). One equation for one unknown,
//! without a side condition, whose operator is a first-kind integral over
//! the unknown's whole interval `[a, b]` with constant kernel factors:
//!
//! * `α ∫_a^b ln|x - t| f(t) dt + β ∫_a^b f(t) dt` maps the equilibrium
//!   density `1/√((t - a)(b - t))` to `π (α ln((b - a)/4) + β)`, a
//!   constant; when it vanishes (the logarithmic capacity `(b - a)/4` is
//!   1 for `β = 0`) the operator has a null space, so the equation has
//!   infinitely many solutions or none: infinitely many when the right
//!   side `g` has `∫ g(x)/√((x - a)(b - x)) dx = 0`. It is refused
//!   ([`PlanError::Singular`]), saying which: asking for a side condition,
//!   or for a right side satisfying that condition.
//! * `γ PV∫_a^b f(t)/(t - x) dt` (the airfoil equation) annihilates the
//!   same density: the solutions unbounded at both ends form a
//!   one-parameter family, and the two classes bounded at one end have
//!   one solution each. The solver's weight selects one; the answer
//!   says so in a warning (containing "unique") naming how to select
//!   another.
//!
//! * A system of second-kind equations on one interval (every operator a
//!   combination of multipliers and smooth integrals over the whole
//!   interval, the multiplier part invertible at every point): `M + K`
//!   with `K` compact, whose singular values gather at those of `M`, so
//!   its Nyström matrices at 48 and 96 Gauss–Legendre points (exact to
//!   rounding for analytic kernels) have a smallest singular value at
//!   rounding level only when the operator has a null function. Then the
//!   problem is refused ([`PlanError::Singular`]), naming the null
//!   function by its values and whether the right side admits solutions
//!   (is orthogonal to the adjoint's null function): a side condition
//!   selects one of many, or the right side must change.
//!   A discrete solver need not see this: in a weighted trial space the
//!   null function is only approximated, so its singular value falls
//!   with the level no faster than the approximation error.
//!
//! Anything else is left to the numerics: a first-kind operator other
//! than the two above, and either of the two inside a system (e.g. the
//! capacity-1 logarithmic kernel in a diagonal block of a triangular
//! system); an integral over part of the interval (Volterra and Abel
//! terms); a singular or peaked kernel; any side condition; split-domain
//! files beyond [`check_split`]. There the only guard is the solver's
//! discrete check (`numeric::solve::null_direction`: a smallest singular
//! value below 1e-10 of the largest while the next is not), which sees a
//! null function only when the trial space represents it to rounding.
use super::compiled::CompiledSystem;
use super::error::PlanError;
use super::split_input::SplitInput;
use crate::numeric::operator::{Limits, Operator, Singularity, Term};
use crate::numeric::solve::{NULL_NEXT, NULL_SMALLEST};
use nalgebra::DMatrix;

/// What the operators say about uniqueness.
#[derive(Debug, Clone, PartialEq)]
pub enum Uniqueness {
    /// Nothing is known against it.
    Unknown,
    /// More than one solution; the solver's choice is described by the
    /// warning.
    Chosen(String),
}

/// The relative size below which two kernel values, or a capacity
/// defect, are equal.
const EQUAL: f64 = 1e-12;

/// Checks `sys` (see the module documentation): an error for a singular
/// logarithmic equation, [`Uniqueness::Chosen`] for a Cauchy equation
/// without a side condition.
pub fn check(sys: &CompiledSystem) -> Result<Uniqueness, PlanError> {
    if !sys.conditions.is_empty() {
        return Ok(Uniqueness::Unknown);
    }
    second_kind_null(sys)?;
    if sys.unknowns.len() != 1 || sys.equations.len() != 1 {
        return Ok(Uniqueness::Unknown);
    }
    let (a, b) = sys.domain;
    let Some(poly) = sys.equations[0].lhs.first() else {
        return Ok(Uniqueness::Unknown);
    };
    let (mut log, mut smooth, mut cauchy) = (0.0, 0.0, 0.0);
    for (word, coeff) in poly.terms() {
        let [symbol] = word.as_slice() else {
            return Ok(Uniqueness::Unknown);
        };
        let Some(Some(op)) = sys.operators.get(*symbol) else {
            return Ok(Uniqueness::Unknown);
        };
        let c: f64 = num_traits::ToPrimitive::to_f64(coeff).unwrap_or(f64::NAN);
        for (k, term) in &op.terms {
            let Term::Integral {
                limits: Limits::Fixed { a: lo, b: hi },
                singularity,
                kernel,
            } = term
            else {
                return Ok(Uniqueness::Unknown);
            };
            if (*lo, *hi) != (a, b) {
                return Ok(Uniqueness::Unknown);
            }
            let Some(value) = constant(kernel.as_ref(), a, b) else {
                return Ok(Uniqueness::Unknown);
            };
            let v = c * k * value;
            match singularity {
                Singularity::Log => log += v,
                Singularity::Smooth => smooth += v,
                Singularity::Cauchy => cauchy += v,
                _ => return Ok(Uniqueness::Unknown),
            }
        }
    }
    let name = &sys.unknowns[0];
    let minus = |v: f64| {
        if v < 0.0 {
            format!("x + {}", -v)
        } else {
            format!("x - {v}")
        }
    };
    let density = format!("1/sqrt(({})*({b} - x))", minus(a));
    let cond = format!("condition int({a}..{b}) {name}(t) dt = C");
    if cauchy != 0.0 && log == 0.0 && smooth == 0.0 {
        return Ok(Uniqueness::Chosen(format!(
            "the solution is not unique: the Cauchy (airfoil) equation for {name} on [{a}, {b}] without a side condition has a one-parameter family of solutions unbounded at both ends (any multiple of {density} can be added) and one solution in each class bounded at one end; the answer is the one in the class of {name}'s weight shown; to select one of the family add a side condition such as `{cond}`"
        )));
    }
    if log != 0.0 && cauchy == 0.0 {
        let cap = (b - a) / 4.0;
        let mean = log * cap.ln() + smooth;
        let scale = log.abs() * (1.0 + cap.ln().abs()) + smooth.abs();
        if mean.abs() <= EQUAL * scale {
            let why = if smooth == 0.0 {
                format!("[{a}, {b}] has logarithmic capacity (b - a)/4 = 1")
            } else {
                format!(
                    "the kernel's constant part cancels ln((b - a)/4) = {} of [{a}, {b}]",
                    cap.ln()
                )
            };
            let head =
                format!("the logarithmic kernel's operator maps {density} to 0, because {why}");
            let weighted = format!("∫ g(x)/sqrt(({})*({b} - x)) dx", minus(a));
            return Err(PlanError::Singular(match log_solvable(sys, a, b) {
                Solvable::Yes => format!(
                    "the problem has more than one solution: {head}, so any multiple of it can be added to a solution (the right side g satisfies the solvability condition {weighted} = 0); a side condition such as `{cond}` can select one"
                ),
                Solvable::No(v) => format!(
                    "the problem has no solution: {head}, and the operator's range is the right sides g with {weighted} = 0, but here it is {v:.6e}; a side condition cannot help: the right side must be changed to satisfy that condition"
                ),
                Solvable::Unknown => format!(
                    "the problem has more than one solution or none: {head}; if the right side g satisfies {weighted} = 0 any multiple of that function can be added to a solution and a side condition such as `{cond}` can select one, otherwise there is no solution and the right side must be changed (the integral could not be evaluated reliably)"
                ),
            }));
        }
    }
    Ok(Uniqueness::Unknown)
}

/// [`check`] for the split-domain solver's input: only a file without
/// split-domain declarations is one equation on one interval.
pub fn check_split(input: &SplitInput) -> Result<Uniqueness, PlanError> {
    let c = &input.contact;
    let plain = c.scalars.is_empty()
        && c.relations.is_empty()
        && c.inequalities.is_empty()
        && c.singulars.is_empty()
        && c.coefficients.is_empty()
        && c.conditions.is_empty()
        && c.equation_domains.iter().all(Option::is_none);
    if plain {
        check(&input.sys)
    } else {
        Ok(Uniqueness::Unknown)
    }
}

/// Gauss–Legendre sizes of the two Nyström matrices of [`second_kind_null`].
const NYSTROM: [usize; 2] = [48, 96];
/// Largest Nyström block matrix decomposed (unknowns times nodes): six
/// unknowns at 96 points. A larger system (a chain of 40 smooth
/// equations would need 3840 rows) is left to the solver's own null
/// probe, which is bounded likewise.
const NYSTROM_MAX: usize = 576;
/// The next singular value (above the solver's `NULL_NEXT` of the largest)
/// must agree at both sizes to this relative difference; the smallest
/// must be below `NULL_SMALLEST` of the largest at both.
const NEXT_AGREE: f64 = 1e-6;
/// The multiplier part is invertible when its smallest singular value at
/// every node is above this fraction of its largest anywhere.
const SECOND_KIND: f64 = 1e-3;

/// One operator symbol sampled at Nyström nodes `x` with weights `w`: the
/// multiplier part at each node and the matrix `m(x_i) δ_ij + Σ c k(x_i, x_j) w_j`.
struct Sampled {
    mult: Vec<f64>,
    matrix: DMatrix<f64>,
}

fn sample(op: &Operator, a: f64, b: f64, x: &[f64], w: &[f64]) -> Option<Sampled> {
    let n = x.len();
    let mut mult = vec![0.0; n];
    let mut matrix = DMatrix::<f64>::zeros(n, n);
    for (c, term) in &op.terms {
        match term {
            Term::Multiply(m) => {
                for (i, xi) in x.iter().enumerate() {
                    mult[i] += c * m(*xi);
                }
            }
            Term::Integral {
                limits: Limits::Fixed { a: lo, b: hi },
                singularity: Singularity::Smooth,
                kernel,
            } => {
                let sign = if (*lo, *hi) == (a, b) {
                    1.0
                } else if (*lo, *hi) == (b, a) {
                    -1.0
                } else {
                    return None;
                };
                for (i, xi) in x.iter().enumerate() {
                    for (j, (tj, wj)) in x.iter().zip(w).enumerate() {
                        matrix[(i, j)] += sign * c * kernel(*xi, *tj) * wj;
                    }
                }
            }
            _ => return None,
        }
    }
    for (i, m) in mult.iter().enumerate() {
        matrix[(i, i)] += m;
    }
    (mult.iter().all(|v| v.is_finite()) && matrix.iter().all(|v| v.is_finite()))
        .then_some(Sampled { mult, matrix })
}

/// The Nyström discretisation of `sys` at `n` Gauss–Legendre points: the
/// nodes and weights, the block matrix symmetrised to `W^{1/2} A W^{-1/2}`
/// (its singular values approximate the operator's on L²), and the
/// smallest singular value of the multiplier part over its largest.
/// `None` when an operator is not of the second-kind class.
/// Nyström nodes, weights, the symmetrised matrix and the multiplier
/// part's smallest-over-largest singular value.
type Nystrom = (Vec<f64>, Vec<f64>, DMatrix<f64>, f64);

fn nystrom(sys: &CompiledSystem, n: usize) -> Option<Nystrom> {
    let (a, b) = sys.domain;
    let nu = sys.unknowns.len();
    if nu == 0
        || nu * n > NYSTROM_MAX
        || sys.equations.len() != nu
        || a.partial_cmp(&b) != Some(std::cmp::Ordering::Less)
    {
        return None;
    }
    let (x, w) = crate::numeric::gauss::gauss_legendre(n).ok()?.mapped(a, b);
    let mut sampled = Vec::with_capacity(sys.operators.len());
    for op in &sys.operators {
        sampled.push(match op {
            Some(op) => Some(sample(op, a, b, &x, &w)?),
            None => None,
        });
    }
    let mut big = DMatrix::<f64>::zeros(nu * n, nu * n);
    // The multiplier part at each node, an nu×nu matrix.
    let mut parts = vec![DMatrix::<f64>::zeros(nu, nu); n];
    for (i, eq) in sys.equations.iter().enumerate() {
        for (j, poly) in eq.lhs.iter().enumerate() {
            for (word, coeff) in poly.terms() {
                let c: f64 = num_traits::ToPrimitive::to_f64(coeff)?;
                let mut m = DMatrix::<f64>::identity(n, n);
                let mut mult = vec![1.0; n];
                for s in word {
                    let op = sampled.get(*s)?.as_ref()?;
                    m *= &op.matrix;
                    for (v, o) in mult.iter_mut().zip(&op.mult) {
                        *v *= o;
                    }
                }
                let mut block = big.view_mut((i * n, j * n), (n, n));
                block += m * c;
                for (p, v) in parts.iter_mut().zip(&mult) {
                    p[(i, j)] += c * v;
                }
            }
        }
    }
    let root: Vec<f64> = w.iter().map(|v| v.sqrt()).collect();
    for r in 0..nu * n {
        for c in 0..nu * n {
            big[(r, c)] *= root[r % n] / root[c % n];
        }
    }
    let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
    for p in &parts {
        let sv = p.singular_values();
        lo = lo.min(sv.min());
        hi = hi.max(sv.max());
    }
    let ratio = if hi > 0.0 { lo / hi } else { 0.0 };
    big.iter()
        .all(|v| v.is_finite())
        .then_some((x, w, big, ratio))
}

/// Refuses a second-kind system whose operator has a null function (see
/// the module documentation); passes everything else.
fn second_kind_null(sys: &CompiledSystem) -> Result<(), PlanError> {
    let mut found = Vec::new();
    for n in NYSTROM {
        let Some((x, w, a, part)) = nystrom(sys, n) else {
            return Ok(());
        };
        if part.is_nan() || part < SECOND_KIND {
            return Ok(());
        }
        let svd = a.clone().svd(true, true);
        let sv = &svd.singular_values;
        let (k, smallest) = sv.argmin();
        let largest = sv.max();
        if !(largest > 0.0 && smallest < NULL_SMALLEST * largest) {
            return Ok(());
        }
        let next = sv
            .iter()
            .enumerate()
            .filter(|(i, _)| *i != k)
            .map(|(_, v)| *v)
            .fold(f64::INFINITY, f64::min);
        // The rest of the spectrum must be resolved: one isolated value at
        // rounding level, not a cluster (`p + 1e20·∫(x + t) p` is
        // invertible, its small singular values all near 1e-20 of the largest).
        if next.is_nan() || next <= NULL_NEXT * largest {
            return Ok(());
        }
        let (Some(u), Some(vt)) = (&svd.u, &svd.v_t) else {
            return Ok(());
        };
        found.push((
            x,
            w,
            smallest / largest,
            next / largest,
            vt.row(k).transpose(),
            u.column(k).into_owned(),
        ));
    }
    // ... and the same at both sizes (the discretisation converged).
    let nexts: Vec<f64> = found.iter().map(|f| f.3).collect();
    if nexts
        .iter()
        .any(|v| (v - nexts[0]).abs() > NEXT_AGREE * nexts[0])
    {
        return Ok(());
    }
    let Some((x, w, smallest, next, right, left)) = found.pop() else {
        return Ok(());
    };
    let coarse = found.first().map_or(smallest, |f| f.2);
    let n = x.len();
    let root: Vec<f64> = w.iter().map(|v| v.sqrt()).collect();
    let (a, b) = sys.domain;
    // The null function at five points of each unknown's interval, by
    // barycentric interpolation at the Legendre nodes.
    let at = [a, a + 0.25 * (b - a), 0.5 * (a + b), a + 0.75 * (b - a), b];
    let mut values = Vec::new();
    for j in 0..sys.unknowns.len() {
        let u: Vec<f64> = (0..n).map(|i| right[j * n + i] / root[i]).collect();
        values.push(at.map(|p| barycentric(&x, &w, &u, a, b, p)));
    }
    let top = values
        .iter()
        .flatten()
        .copied()
        .fold(0.0f64, |m, v| if v.abs() > m.abs() { v } else { m });
    let shown: Vec<String> = sys
        .unknowns
        .iter()
        .zip(&values)
        .flat_map(|(name, vs)| {
            at.iter()
                .zip(vs)
                .map(move |(p, v)| format!("{name}({p}) = {:.4}", v / top))
        })
        .collect();
    // Solutions exist only when the right side is orthogonal to the
    // adjoint's null function (the left singular vector, W^{1/2}-weighted).
    let (mut dot, mut gnorm, mut ynorm) = (0.0, 0.0, 0.0);
    for (i, eq) in sys.equations.iter().enumerate() {
        for r in 0..n {
            let g = (eq.rhs)(x[r]) * root[r];
            let y = left[i * n + r];
            dot += g * y;
            gnorm += g * g;
            ynorm += y * y;
        }
    }
    let scale = (gnorm * ynorm).sqrt();
    let what = format!(
        "the operator has a null direction (its Nyström discretisations at {} and {n} points have smallest singular value {coarse:.1e} and {smallest:.1e} of the largest, the next {next:.1e}), proportional to {}",
        NYSTROM[0],
        shown.join(", ")
    );
    Err(PlanError::Singular(if !scale.is_finite() {
        format!(
            "the problem has more than one solution or none: {what}; if the right side is orthogonal to the adjoint's null function any multiple of that direction can be added to a solution and a side condition (`condition …`) can select one, otherwise there is no solution and the right side must be changed (the right side could not be evaluated at every node)"
        )
    } else if dot.abs() <= 1e-8 * scale {
        format!(
            "the problem has more than one solution: {what}; the right side is orthogonal to the adjoint's null function (the solvability condition), so any multiple of that direction can be added to a solution; a side condition (`condition …`) can select one"
        )
    } else {
        format!(
            "the problem has no solution: {what}; the right side is not orthogonal to the adjoint's null function (its component along it is {:.1e} of its size), so no function solves the equation; a side condition cannot help: the right side must be changed to be orthogonal to that function",
            dot.abs() / scale
        )
    }))
}

/// Whether the right side lies in an operator's range.
enum Solvable {
    Yes,
    /// No; the value of the solvability functional.
    No(f64),
    /// The functional could not be evaluated reliably.
    Unknown,
}

/// The logarithmic operator of [`check`] with its null function
/// `w = 1/√((x - a)(b - x))` (symmetric kernel: `w` spans the adjoint's
/// null space too) maps onto the right sides `g` with `∫_a^b g w dx = 0`
/// (the Chebyshev coefficient of `T_0` of `g`, the only one the operator
/// does not reach). The integral by Gauss–Chebyshev rules at 64 and 128
/// points, `π/n Σ g(x_k)`: zero when both are below `1e-10` of
/// `π/n Σ |g(x_k)|`, nonzero when they agree to `1e-6` and are above
/// `1e-8` of it; otherwise unknown (e.g. a right side with a feature too
/// narrow for 128 points).
fn log_solvable(sys: &CompiledSystem, a: f64, b: f64) -> Solvable {
    let rhs = &sys.equations[0].rhs;
    let rule = |n: usize| {
        let (mut sum, mut abs) = (0.0, 0.0);
        for k in 0..n {
            let theta = std::f64::consts::PI * (2 * k + 1) as f64 / (2 * n) as f64;
            let g = rhs(0.5 * (a + b) + 0.5 * (b - a) * theta.cos());
            sum += g;
            abs += g.abs();
        }
        let h = std::f64::consts::PI / n as f64;
        (sum * h, abs * h)
    };
    let ((coarse, _), (fine, scale)) = (rule(64), rule(128));
    if !(coarse.is_finite() && fine.is_finite() && scale.is_finite()) {
        Solvable::Unknown
    } else if coarse.abs() <= 1e-10 * scale && fine.abs() <= 1e-10 * scale {
        Solvable::Yes
    } else if fine.abs() > 1e-8 * scale && (coarse - fine).abs() <= 1e-6 * fine.abs() {
        Solvable::No(fine)
    } else {
        Solvable::Unknown
    }
}

/// The polynomial through `(x_i, u_i)` at `p`, `x` the Gauss–Legendre
/// nodes on `[a, b]` with weights `w` (barycentric weights
/// `(-1)^i √((1 - s_i²) w_i)`).
fn barycentric(x: &[f64], w: &[f64], u: &[f64], a: f64, b: f64, p: f64) -> f64 {
    let (mut num, mut den) = (0.0, 0.0);
    for (i, ((xi, wi), ui)) in x.iter().zip(w).zip(u).enumerate() {
        let s = (2.0 * xi - a - b) / (b - a);
        let lam = if i % 2 == 0 { 1.0 } else { -1.0 } * ((1.0 - s * s) * wi).sqrt();
        let d = p - xi;
        if d == 0.0 {
            return *ui;
        }
        num += lam / d * ui;
        den += lam / d;
    }
    num / den
}

/// The kernel factor's value if it is the same (relative to its size) at
/// sample points of `[a, b]²`.
fn constant(kernel: &(dyn Fn(f64, f64) -> f64 + Send + Sync), a: f64, b: f64) -> Option<f64> {
    let at = |s: f64| a + (b - a) * s;
    let first = kernel(at(0.5), at(0.5));
    let same = [0.13, 0.5, 0.91].iter().all(|&s| {
        [0.07, 0.62, 0.95].iter().all(|&r| {
            let v = kernel(at(s), at(r));
            (v - first).abs() <= EQUAL * first.abs()
        })
    });
    (first.is_finite() && same).then_some(first)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check_src(src: &str) -> Result<Uniqueness, PlanError> {
        let prog = crate::lang::parse_program(src, "u.lmx").expect("parses");
        check(&CompiledSystem::from_program(&prog, None).expect("compiles"))
    }

    #[test]
    fn capacity_one_log_equations_are_refused_saying_whether_a_solution_exists() {
        // Right sides with ∫ g/√((x - a)(b - x)) = 0: infinitely many
        // solutions, a side condition selects one.
        for src in [
            "operator k = 1/pi*int(0..4) ln(abs(x - t)) dt\nunknown f on [0, 4]\nequation k f = x - 2\n",
            "operator k = int(-1..1) ln(abs(2*x - 2*t)) dt\nunknown f on [-1, 1]\nequation k f = x\n",
        ] {
            let e = check_src(src).expect_err(src).to_string();
            assert!(
                e.starts_with("the problem has more than one solution:"),
                "{e}"
            );
            assert!(
                e.contains("condition int(") && e.contains("can select one"),
                "{e}"
            );
            assert!(!e.contains("no solution"), "{e}");
        }
        // ∫ 1/√(1 - x²) = π ≠ 0: no solution, and no side condition helps.
        for src in [
            "operator k = int(-1..1) ln(abs(2*x - 2*t)) dt\nunknown f on [-1, 1]\nequation k f = 1\n",
            "operator k = int(-1..1) ln(abs(x - t)) dt + ln(2)*int(-1..1) dt\nunknown f on [-1, 1]\nequation k f = 1\n",
            "operator k = int(-2..2) ln(abs(x - t)) dt\nunknown f on [-2, 2]\nequation k f = x^2\n",
        ] {
            let e = check_src(src).expect_err(src);
            assert!(!e.is_input_error(), "{e}");
            let e = e.to_string();
            assert!(e.starts_with("the problem has no solution:"), "{e}");
            assert!(
                e.contains("cannot help") && !e.contains("can select one"),
                "{e}"
            );
        }
    }

    #[test]
    fn other_log_equations_and_side_conditions_pass() {
        for src in [
            "operator k = int(-1..1) ln(abs(x - t)) dt\nunknown f\nequation k f = 1\n",
            "operator k = int(0..4) ln(abs(x - t)) dt\nunknown f on [0, 4]\nequation k f = x - 2\ncondition int(0..4) f(t) dt = 1\n",
            "operator k = int(0..4) x*ln(abs(x - t)) dt\nunknown f on [0, 4]\nequation k f = x - 2\n",
            "operator k = id + int(0..4) ln(abs(x - t)) dt\nunknown f on [0, 4]\nequation k f = x - 2\n",
        ] {
            assert_eq!(check_src(src).expect(src), Uniqueness::Unknown, "{src}");
        }
    }

    #[test]
    fn cauchy_equations_without_a_side_condition_state_the_choice() {
        let src =
            "operator h = 1/pi*pv int(-1..1) 1/(t - x) dt\nunknown f\nequation h f = exp(x)\n";
        let Uniqueness::Chosen(w) = check_src(src).expect("checks") else {
            panic!("not flagged");
        };
        assert!(w.contains("not unique") && w.contains("condition int(-1..1) f(t) dt"));
        let with = format!("{src}condition int(-1..1) f(t) dt = 1\n");
        assert_eq!(check_src(&with).expect("checks"), Uniqueness::Unknown);
    }

    #[test]
    fn second_kind_null_functions_are_found_and_ill_conditioning_is_not_one() {
        // The right side decides between many solutions and none: ∫ e^x·1
        // ≠ 0, while x - 2e^x/(e² - 1) is orthogonal to e^x.
        let rank_one =
            "operator k = id - int(0..1) 2*exp(x)*exp(t)/(exp(2) - 1) dt\nunknown f on [0, 1]\n";
        let e = check_src(&format!("{rank_one}equation k f = 1\n"))
            .expect_err("no solution")
            .to_string();
        assert!(e.starts_with("the problem has no solution:"), "{e}");
        assert!(
            e.contains("cannot help") && !e.contains("can select one"),
            "{e}"
        );
        let e = check_src(&format!(
            "{rank_one}equation k f = x - 2*exp(x)/(exp(2) - 1)\n"
        ))
        .expect_err("many solutions")
        .to_string();
        assert!(
            e.starts_with("the problem has more than one solution:"),
            "{e}"
        );
        assert!(
            e.contains("can select one") && !e.contains("no solution"),
            "{e}"
        );
        for src in [
            "operator k = id - int(0..1) 3*x*t dt\nunknown f on [0, 1]\nequation k*k f = x\n",
            "operator k = int(0..1) 3*x*t dt\nunknown f on [0, 1]\nunknown g on [0, 1]\nequation f - k g = 1\nequation g - f = 0\n",
        ] {
            let e = check_src(src).expect_err(src);
            assert!(e.to_string().contains("null direction"), "{e}");
        }
        for src in [
            "operator k = id - int(0..1) 2*(1 - 1/10^6)*exp(x)*exp(t)/(exp(2) - 1) dt\nunknown f on [0, 1]\nequation k f = 1\n",
            "operator k = id + int(0..1) exp(-(x - t)^2) dt\nunknown f on [0, 1]\nequation k f = 1\n",
            "operator k = int(0..1) 100000000000000000000*(x + t) dt\nunknown p\nequation p + k p = 1\n",
            "operator k = id - int(0..1) 2*exp(x)*exp(t)/(exp(2) - 1) dt\nunknown f on [0, 1]\nequation k f = 1\ncondition int(0..1) f(t) dt = 1\n",
        ] {
            assert_eq!(check_src(src).expect(src), Uniqueness::Unknown, "{src}");
        }
    }
}
