//! The operator system of a file, ready for the numerics: operators as
//! [`Operator`]s with their kernels compiled, right sides and output
//! weights as closures, the ordered operators of the equations as exact
//! [`NcPoly`]s (products in the order written), the target unknown and the
//! unknowns' interval. It is the plain part of a
//! [`super::SplitInput`] (which adds breakpoints, scalars, relations and
//! singular terms), and it can be built two ways: from a parsed [`Program`]
//! ([`CompiledSystem::from_program`], kernels compiled to closures) or by
//! code that `lambdamat codegen` wrote (kernels as Rust functions). This
//! file owns that data, its construction from a program and its
//! consistency check; it must not discretise or solve.
use std::sync::Arc;

use num_rational::BigRational;

use crate::system::{Directive, FunctionalTerm, Limit, NcPoly, Program, Term};

use super::compile::{compile_x, constant_value, rational};
use super::error::PlanError;
use super::operators::build_operator;
use crate::algebra::derivation::Derivation;
use crate::algebra::matrix::Matrix;
use crate::algebra::polyring::PolyRing;
use crate::numeric::Operator;

/// A compiled function of `x`.
pub type Fn1 = Arc<dyn Fn(f64) -> f64 + Send + Sync>;

/// One equation `Σ_j lhs[j] u_j = rhs`.
#[derive(Clone)]
pub struct CompiledEquation {
    /// The ordered operator applied to each unknown (words in the order
    /// written, the last symbol of a word applied first).
    pub lhs: Vec<NcPoly>,
    /// The right side.
    pub rhs: Fn1,
    /// The right side as written (for error messages).
    pub rhs_text: String,
}

/// One term of an output functional, in the order written.
#[derive(Clone)]
pub enum OutputTerm {
    /// A constant.
    Constant(f64),
    /// `coeff · ∫_lower^upper weight(x) u(x) dx`.
    Integral {
        /// The constant factor.
        coeff: f64,
        /// Lower limit.
        lower: f64,
        /// Upper limit.
        upper: f64,
        /// The weight.
        weight: Fn1,
        /// Index of the unknown.
        unknown: usize,
    },
    /// `coeff · u(at)`.
    Point {
        /// The constant factor.
        coeff: f64,
        /// The point.
        at: f64,
        /// Index of the unknown.
        unknown: usize,
    },
}

impl OutputTerm {
    /// The unknown the term uses, if any.
    pub fn unknown(&self) -> Option<usize> {
        match self {
            OutputTerm::Constant(_) => None,
            OutputTerm::Integral { unknown, .. } | OutputTerm::Point { unknown, .. } => {
                Some(*unknown)
            }
        }
    }
}

/// A side condition `Σ terms = value`: one extra row of the discrete
/// system.
#[derive(Clone)]
pub struct CompiledCondition {
    /// The terms of the functional (constants included).
    pub terms: Vec<OutputTerm>,
    /// The required value.
    pub value: f64,
    /// The condition as written (for messages).
    pub text: String,
}

/// A named output functional.
#[derive(Clone)]
pub struct CompiledOutput {
    /// Its name.
    pub name: String,
    /// Its terms, summed in order.
    pub terms: Vec<OutputTerm>,
}

/// The operator system of a file (the plain part of a [`super::SplitInput`]).
#[derive(Clone)]
pub struct CompiledSystem {
    /// Operator symbol names (the letters of the `NcPoly` words).
    pub symbols: Vec<String>,
    /// The operator of each symbol the equations use (`None` otherwise).
    pub operators: Vec<Option<Operator>>,
    /// Unknown names.
    pub unknowns: Vec<String>,
    /// One equation per unknown.
    pub equations: Vec<CompiledEquation>,
    /// Output functionals.
    pub outputs: Vec<CompiledOutput>,
    /// Side conditions (extra rows; solved with the equations by least
    /// squares).
    pub conditions: Vec<CompiledCondition>,
    /// The unknown the eliminations solve for.
    pub target: usize,
    /// The principal symbol (`principal k4`), preferred as pivot by the
    /// ordered elimination.
    pub principal: Option<usize>,
    /// The ordered elimination's pivot sequence, (equation, unknown)
    /// 0-based, as `lambdamat codegen` embedded it in a generated solver;
    /// `None` when the system was compiled in process. When set,
    /// [`CompiledSystem::derivation`] refuses a derivation with other
    /// pivots, so a generated solver runs exactly the derivation its
    /// header prints.
    pub derived_pivots: Option<Vec<(usize, usize)>>,
    /// The unknowns' interval.
    pub domain: (f64, f64),
    /// Constant limits strictly inside the interval (meshes are graded there).
    pub interior: Vec<f64>,
    /// Narrow features of the kernels (in `t`) and right sides (in `x`),
    /// as `(point, width)` (`super::features`): meshes are graded there
    /// down to the width.
    pub features: Vec<(f64, f64)>,
}

impl CompiledSystem {
    /// Compiles `prog`: kernels to closures, the interval from the
    /// constant limits, the target from `target` (an unknown's name), else
    /// the file's `solve for`, else the first unknown.
    pub fn from_program(prog: &Program, target: Option<&str>) -> Result<CompiledSystem, PlanError> {
        if prog.contact.is_split() {
            return Err(PlanError::Invalid(
                "this file has split-domain declarations (on-intervals, relations, scalars, singular terms, conditions): `lambdamat solve` and `codegen` handle it with the split-domain solver (`plan::SplitInput`)".into(),
            ));
        }
        square(prog.equations.len(), prog.unknowns.len())?;
        let target = match target {
            Some(name) => prog
                .unknowns
                .iter()
                .position(|u| u == name)
                .ok_or_else(|| {
                    PlanError::Invalid(format!(
                        "{name} is not an unknown of the file (unknowns: {})",
                        prog.unknowns.join(", ")
                    ))
                })?,
            None => prog
                .directives
                .iter()
                .find_map(|d| match d {
                    Directive::Solve { unknown } => Some(*unknown),
                    _ => None,
                })
                .unwrap_or(0),
        };
        let used = |s: usize| {
            prog.equations
                .iter()
                .any(|eq| eq.lhs.iter().any(|p| p.contains_var(s)))
        };
        if let Some(s) = (0..prog.symbols.len()).find(|&s| used(s) && prog.operator(s).is_none()) {
            return Err(no_definition(&prog.symbols[s]));
        }
        let (domain, interior) = interval(prog)?;
        let mut operators: Vec<Option<Operator>> = vec![None; prog.symbols.len()];
        for d in prog.operators.iter().filter(|d| used(d.symbol)) {
            let name = &prog.symbols[d.symbol];
            operators[d.symbol] = Some(build_operator(d, name, domain)?);
        }
        let mut features = Vec::new();
        {
            use super::features::{Var, features as of};
            for d in prog.operators.iter().filter(|d| used(d.symbol)) {
                for t in &d.terms {
                    if let crate::system::Term::Integral { kernel, .. } = t {
                        features.extend(of(kernel, Var::T, domain));
                    }
                }
            }
            for eq in &prog.equations {
                features.extend(of(&eq.rhs, Var::X, domain));
            }
        }
        let features: Vec<(f64, f64)> = features.iter().map(|f| (f.at, f.width)).collect();
        let equations = prog
            .equations
            .iter()
            .map(|eq| CompiledEquation {
                lhs: eq.lhs.clone(),
                rhs: compile_x(&eq.rhs),
                rhs_text: eq.rhs_text(),
            })
            .collect();
        let outputs = prog
            .outputs
            .iter()
            .map(|o| CompiledOutput {
                name: o.name.clone(),
                terms: compile_terms(&o.terms),
            })
            .collect();
        let conditions = prog
            .side_conditions
            .iter()
            .enumerate()
            .map(|(k, c)| CompiledCondition {
                terms: compile_terms(&c.terms),
                value: constant_value(&c.value).unwrap_or(f64::NAN),
                text: format!("side condition {} (= {})", k + 1, c.value),
            })
            .collect();
        let sys = CompiledSystem {
            symbols: prog.symbols.clone(),
            operators,
            unknowns: prog.unknowns.clone(),
            equations,
            outputs,
            conditions,
            target,
            principal: prog.principal,
            derived_pivots: None,
            domain,
            interior,
            features,
        };
        sys.check()?;
        Ok(sys)
    }

    /// Checks that the parts fit together: one equation per unknown, one
    /// polynomial per unknown over the declared symbols, an operator for
    /// every symbol used, a valid target, interval and output unknowns.
    pub fn check(&self) -> Result<(), PlanError> {
        let n = self.unknowns.len();
        let invalid = |s: String| Err(PlanError::Invalid(s));
        square(self.equations.len(), n)?;
        if self.operators.len() != self.symbols.len() {
            return invalid(format!(
                "{} operators for {} symbols",
                self.operators.len(),
                self.symbols.len()
            ));
        }
        for (i, eq) in self.equations.iter().enumerate() {
            if eq.lhs.len() != n {
                return invalid(format!(
                    "equation {} has {} operator polynomials for {n} unknowns",
                    i + 1,
                    eq.lhs.len()
                ));
            }
            for p in &eq.lhs {
                if let Some(s) = p.symbols().into_iter().find(|&s| s >= self.symbols.len()) {
                    return invalid(format!(
                        "equation {}: symbol #{s} of {} symbols",
                        i + 1,
                        self.symbols.len()
                    ));
                }
                for (s, name) in self.symbols.iter().enumerate() {
                    if p.contains_var(s) && self.operators[s].is_none() {
                        return Err(no_definition(name));
                    }
                }
            }
        }
        if self.target >= n {
            return invalid(format!("target unknown #{} of {n}", self.target));
        }
        let (lo, hi) = self.domain;
        if !(lo.is_finite() && hi.is_finite() && lo < hi) {
            return invalid(format!("the interval [{lo}, {hi}] is empty or not finite"));
        }
        let named = self.outputs.iter().map(|o| (&o.terms, o.name.as_str()));
        let conds = self.conditions.iter().map(|c| (&c.terms, c.text.as_str()));
        for (terms, name) in named.chain(conds) {
            for t in terms.iter() {
                if let Some(u) = t.unknown()
                    && u >= n
                {
                    return invalid(format!("{name} uses unknown #{u}"));
                }
                if let OutputTerm::Point { at, unknown, .. } = t
                    && !(*at >= lo && *at <= hi)
                {
                    return invalid(format!(
                        "{name}: the point value {}({at}) is outside the unknowns' interval [{lo}, {hi}]",
                        self.unknowns[*unknown]
                    ));
                }
            }
        }
        for c in &self.conditions {
            if !c.value.is_finite() {
                return invalid(format!(
                    "side condition {}: its value is not finite",
                    c.text
                ));
            }
        }
        Ok(())
    }
}

impl CompiledSystem {
    /// The one `Derivation` of this system for its target: the same
    /// value `lambdamat reduce` prints for the same file, since both come
    /// from `Derivation::new` on the same ordered words, target and
    /// principal symbol. With [`CompiledSystem::derived_pivots`] set (a
    /// generated solver), a derivation whose pivots differ from the
    /// embedded ones is refused ([`PlanError::Invalid`]: the solver was
    /// generated by a lambdamat that derives differently; regenerate it).
    pub fn derivation(&self) -> Result<Derivation, PlanError> {
        let nvars = self.symbols.len();
        let n = self.unknowns.len();
        let words: Vec<Vec<NcPoly>> = self.equations.iter().map(|e| e.lhs.clone()).collect();
        let image = Matrix::new(
            PolyRing::new(self.symbols.clone()),
            self.equations.len(),
            n,
            words
                .iter()
                .flat_map(|r| r.iter().map(|w| w.commutative_image(nvars)))
                .collect(),
        );
        let d = Derivation::new(&image, &words, self.target, self.principal)
            .map_err(|e| PlanError::Singular(format!("no derivation: {e}")))?;
        if let Some(embedded) = &self.derived_pivots
            && *embedded != d.pivot_order()
        {
            let show = |p: &[(usize, usize)]| {
                p.iter()
                    .map(|&(e, u)| {
                        let name = self.unknowns.get(u).map_or("?", String::as_str);
                        format!("{name} from equation {}", e + 1)
                    })
                    .collect::<Vec<_>>()
                    .join("; ")
            };
            return Err(PlanError::Invalid(format!(
                "this solver embeds the ordered elimination [{}], but this lambdamat derives [{}]; regenerate it with `lambdamat codegen`",
                show(embedded),
                show(&d.pivot_order())
            )));
        }
        Ok(d)
    }
}

/// The compiled terms of a functional.
fn compile_terms(terms: &[FunctionalTerm]) -> Vec<OutputTerm> {
    terms
        .iter()
        .map(|t| match t {
            FunctionalTerm::Constant(e) => {
                OutputTerm::Constant(constant_value(e).unwrap_or(f64::NAN))
            }
            FunctionalTerm::Integral {
                coeff,
                lower,
                upper,
                weight,
                unknown,
            } => OutputTerm::Integral {
                coeff: constant_value(coeff).unwrap_or(f64::NAN),
                lower: rational(lower),
                upper: rational(upper),
                weight: compile_x(weight),
                unknown: *unknown,
            },
            FunctionalTerm::Point { coeff, at, unknown } => OutputTerm::Point {
                coeff: constant_value(coeff).unwrap_or(f64::NAN),
                at: rational(at),
                unknown: *unknown,
            },
        })
        .collect()
}

/// One equation per unknown, and at least one.
fn square(equations: usize, unknowns: usize) -> Result<(), PlanError> {
    if unknowns == 0 {
        return Err(PlanError::Invalid(
            "there is no operator system to solve: declare the unknowns (`unknown p`) and give one `equation` per unknown"
                .into(),
        ));
    }
    if equations != unknowns {
        return Err(PlanError::Invalid(format!(
            "the solver needs as many equations as unknowns ({equations} equations, {unknowns} unknowns)"
        )));
    }
    Ok(())
}

/// The error for a symbol the equations use that has no operator.
fn no_definition(name: &str) -> PlanError {
    PlanError::Unsupported {
        operator: name.to_string(),
        reason: "declared with `var`: it has no definition to discretise".into(),
    }
}

/// The unknowns' interval: the hull of all constant limits of operators
/// and outputs (`[0, c]` if `c` is the only one), and the limits strictly
/// inside it.
fn interval(prog: &Program) -> Result<((f64, f64), Vec<f64>), PlanError> {
    let mut limits = Vec::new();
    for d in &prog.operators {
        for t in &d.terms {
            if let Term::Integral { lower, upper, .. } = t {
                for l in [lower, upper] {
                    if let Limit::Const(c) = l {
                        limits.push(rational(c));
                    }
                }
            }
        }
    }
    let functionals = prog.outputs.iter().map(|o| &o.terms);
    for terms in functionals.chain(prog.side_conditions.iter().map(|c| &c.terms)) {
        for t in terms {
            if let FunctionalTerm::Integral { lower, upper, .. } = t {
                limits.extend([rational(lower), rational(upper)]);
            }
        }
    }
    if let Some((lo, hi)) = declared_interval(prog)? {
        if let Some(z) = limits.iter().find(|&&z| !(z >= lo && z <= hi)) {
            return Err(PlanError::Invalid(format!(
                "the integration limit {z} is outside the unknowns' declared interval [{lo}, {hi}]"
            )));
        }
        let mut interior: Vec<f64> = limits.into_iter().filter(|&z| z > lo && z < hi).collect();
        interior.sort_by(f64::total_cmp);
        interior.dedup();
        return Ok(((lo, hi), interior));
    }
    if limits.iter().all(|&c| Some(c) == limits.first().copied()) {
        limits.push(0.0);
    }
    let lo = limits.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = limits.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if !(lo.is_finite() && hi.is_finite() && lo < hi) {
        return Err(PlanError::Invalid(
            "cannot tell the unknowns' interval: no integral has a nonzero constant limit; state it, e.g. `unknown p on [0, 1]`".into(),
        ));
    }
    let mut interior: Vec<f64> = limits.into_iter().filter(|&z| z > lo && z < hi).collect();
    interior.sort_by(f64::total_cmp);
    interior.dedup();
    Ok(((lo, hi), interior))
}

/// The interval stated by `unknown p, q on [a, b]`, if any: every
/// unknown that states one must state the same, with finite ends.
fn declared_interval(prog: &Program) -> Result<Option<(f64, f64)>, PlanError> {
    let c = &prog.contact;
    let Some(first) = c.unknown_domains.iter().flatten().next() else {
        return Ok(None);
    };
    if c.unknown_domains.iter().flatten().any(|d| d != first) {
        return Err(PlanError::Invalid(
            "the unknowns are declared on different intervals; a system on one interval needs one (`unknown p, q on [0, 1]`)".into(),
        ));
    }
    let vars = c.values(&vec![f64::NAN; c.scalars.len()]);
    let (lo, hi) = first.eval(&vars);
    if !(lo.is_finite() && hi.is_finite() && lo < hi) {
        return Err(PlanError::Invalid(format!(
            "the unknowns' declared interval [{lo}, {hi}] must have finite ends, the left below the right"
        )));
    }
    Ok(Some((lo, hi)))
}

/// An ordered operator from its terms: each term is a word (symbol
/// indices, applied right to left: `&[1, 0]` is `s1 s0`, `s0` first) and
/// an exact rational coefficient written `"p"` or `"p/q"` (the form
/// `lambdamat codegen` writes).
///
/// ```
/// use lambdamat::plan::compiled::words;
/// let p = words(&[(&[1, 0], "1"), (&[0, 1], "-1/3")]).unwrap();
/// assert_eq!(p.to_string_with(&["a", "b"]), "-1/3*a b + b a");
/// ```
pub fn words(terms: &[(&[usize], &str)]) -> Result<NcPoly, PlanError> {
    let mut out = Vec::with_capacity(terms.len());
    for (w, c) in terms {
        let q: BigRational = c
            .parse()
            .map_err(|_| PlanError::Invalid(format!("{c} is not a rational number")))?;
        out.push((w.to_vec(), q));
    }
    Ok(NcPoly::from_terms(out))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn program(src: &str) -> Program {
        crate::lang::parse_program(src, "t.lmx").expect("parses")
    }

    #[test]
    fn interval_and_target_from_the_file() {
        let p = program(
            "operator a = int(x..1) t dt\noperator b = int(0..1/2) x*t dt\nunknown u, v\n\
             equation a u + v = 1\nequation b v = x\nsolve for v\n",
        );
        let s = CompiledSystem::from_program(&p, None).unwrap();
        assert_eq!(s.domain, (0.0, 1.0));
        assert_eq!(s.interior, vec![0.5]);
        assert_eq!(s.target, 1);
        assert_eq!(
            CompiledSystem::from_program(&p, Some("u")).unwrap().target,
            0
        );
        let e = CompiledSystem::from_program(&p, Some("w")).err().unwrap();
        assert!(e.to_string().contains("w is not an unknown"), "{e}");
    }

    #[test]
    fn check_names_the_misfit() {
        let p = program("operator a = int(x..1) t dt\nunknown u\nequation a u = 1\n");
        let mut s = CompiledSystem::from_program(&p, None).unwrap();
        s.operators[0] = None;
        assert!(s.check().unwrap_err().to_string().contains("`var`"));
        let mut s = CompiledSystem::from_program(&p, None).unwrap();
        s.domain = (1.0, 1.0);
        assert!(s.check().unwrap_err().to_string().contains("empty"));
        assert!(words(&[(&[0], "1/0")]).is_err());
        assert!(words(&[(&[0], "x")]).is_err());
        let mut s = CompiledSystem::from_program(&p, None).unwrap();
        s.equations[0].lhs[0] = words(&[(&[1], "1")]).unwrap();
        assert!(s.check().unwrap_err().to_string().contains("symbol #1"));
    }

    #[test]
    fn declared_interval_and_side_conditions() {
        // A pure Volterra file: the interval comes from `unknown … on`.
        let p = program("operator a = int(0..x) dt\nunknown u on [0, 3/2]\nequation u + a u = 1\n");
        let s = CompiledSystem::from_program(&p, None).unwrap();
        assert_eq!(s.domain, (0.0, 1.5));
        // Without it, the file says nothing about the interval.
        let p = program("operator a = int(0..x) dt\nunknown u\nequation u + a u = 1\n");
        let e = CompiledSystem::from_program(&p, None).err().unwrap();
        assert!(e.to_string().contains("interval"), "{e}");
        // A limit outside the declared interval is refused.
        let p = program("operator a = int(0..2) dt\nunknown u on [0, 1]\nequation u + a u = 1\n");
        let e = CompiledSystem::from_program(&p, None).err().unwrap();
        assert!(e.to_string().contains("outside"), "{e}");
        // A side condition's limits count for the interval; its constant
        // terms stay terms, its value is the right side.
        let p = program(
            "operator a = int(0..x) dt\nunknown u\nequation a u = x\ncondition 1 + int(0..2) u(x) dx - u(1) = 3\n",
        );
        let s = CompiledSystem::from_program(&p, None).unwrap();
        assert_eq!(s.domain, (0.0, 2.0));
        assert_eq!(s.conditions.len(), 1);
        assert_eq!(s.conditions[0].value, 3.0);
        assert!(matches!(
            s.conditions[0].terms.as_slice(),
            [
                OutputTerm::Constant(c),
                OutputTerm::Integral { .. },
                OutputTerm::Point { coeff, at, unknown: 0 }
            ] if *c == 1.0 && *coeff == -1.0 && *at == 1.0
        ));
        // A point value outside the interval is refused.
        let p = program(
            "operator a = int(0..1) dt\nunknown u\nequation u + a u = x\noutput P = u(2)\n",
        );
        let e = CompiledSystem::from_program(&p, None).err().unwrap();
        assert!(e.to_string().contains("outside"), "{e}");
    }
}
