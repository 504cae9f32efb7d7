//! The input of the split-domain solver: the compiled operator system
//! (operators, right sides, outputs) with the split-domain declarations
//! as numbers and functions — every interval end, relation factor,
//! singular point, weight exponent, singular term, condition value and
//! real parameter a function of the slot values (scalars, then real
//! parameters) and `x`. It is built two ways, exactly as
//! [`CompiledSystem`] is: from a lowered [`Program`]
//! ([`SplitInput::from_program`], expressions evaluated by
//! [`RExpr::eval`]) or by code `lambdamat codegen` wrote (the same
//! expressions as Rust functions performing the same floating-point
//! operations). [`super::split::SplitProblem`] is made from it in both
//! cases. This file owns that data and its construction from a program;
//! it must not discretise or solve.
use std::sync::Arc;

use super::compiled::CompiledSystem;
use super::error::PlanError;
use crate::system::Program;
use crate::system::OperatorDef;
use crate::system::contact::{Contact, EndSite, Interval, RExpr, Scalar, SingularKind};

/// A real function of the slot values and `x`.
pub type SlotFn = Arc<dyn Fn(&[f64], f64) -> f64 + Send + Sync>;

/// A real quantity of a split-domain problem: a function of the slot
/// values `v` (scalars, then real parameters) and of `x` (constants
/// ignore both).
#[derive(Clone)]
pub struct RealFn(pub SlotFn);

impl RealFn {
    /// Wraps a function.
    pub fn new(f: impl Fn(&[f64], f64) -> f64 + Send + Sync + 'static) -> RealFn {
        RealFn(Arc::new(f))
    }

    /// Evaluates an expression of the language (the in-process path).
    pub fn from_expr(e: &RExpr) -> RealFn {
        let e = e.clone();
        RealFn::new(move |v, x| e.eval(v, x))
    }

    /// The value for slot values `vars` at `x`.
    pub fn eval(&self, vars: &[f64], x: f64) -> f64 {
        (self.0)(vars, x)
    }
}

/// An interval whose ends are functions of the slot values.
#[derive(Clone)]
pub struct SplitInterval {
    /// Left end.
    pub lo: RealFn,
    /// Right end.
    pub hi: RealFn,
    /// Whether the left end belongs to the interval (`[`).
    pub lo_closed: bool,
    /// Whether the right end belongs to the interval (`]`).
    pub hi_closed: bool,
}

impl SplitInterval {
    /// The ends for slot values `vars`.
    pub fn eval(&self, vars: &[f64]) -> (f64, f64) {
        (self.lo.eval(vars, 0.0), self.hi.eval(vars, 0.0))
    }

    fn from_interval(i: &Interval) -> SplitInterval {
        SplitInterval {
            lo: RealFn::from_expr(&i.lo),
            hi: RealFn::from_expr(&i.hi),
            lo_closed: i.lo_closed,
            hi_closed: i.hi_closed,
        }
    }
}

/// `unknown = coeff · other` on `domain`.
#[derive(Clone)]
pub struct SplitRelation {
    /// Index of the unknown that is substituted.
    pub unknown: usize,
    /// The factor.
    pub coeff: RealFn,
    /// Index of the unknown it is expressed by.
    pub other: usize,
    /// Where it holds.
    pub domain: SplitInterval,
}

/// One term of a side of a [`SplitInequality`]: `coeff · unknown`, or
/// the constant `coeff` when `unknown` is `None`.
#[derive(Clone)]
pub struct SplitLinTerm {
    /// The factor.
    pub coeff: RealFn,
    /// The unknown it multiplies, if any.
    pub unknown: Option<usize>,
}

/// `Σ lhs ≤ Σ rhs` (`|Σ lhs| ≤ Σ rhs` when `abs`) on `domain`.
#[derive(Clone)]
pub struct SplitInequality {
    /// Whether the smaller side is in `abs(…)`.
    pub abs: bool,
    /// The smaller side.
    pub lhs: Vec<SplitLinTerm>,
    /// The larger side.
    pub rhs: Vec<SplitLinTerm>,
    /// Where it must hold.
    pub domain: SplitInterval,
    /// Its source text, for messages.
    pub text: String,
}

/// What is declared singular about an unknown at a point.
#[derive(Clone)]
pub enum SplitKind {
    /// The weight `|x - P|^e` is factored out.
    Weight {
        /// The exponent `e`.
        exponent: RealFn,
    },
    /// A logarithmic end `ln|x - P|`: graded toward, no weight factored
    /// out, the value at the point left out of the reported grid.
    Log,
    /// An exact singular term `B·g(x)` with a free coefficient `B`.
    Term {
        /// Index of the coefficient.
        coefficient: usize,
        /// `g(x)`.
        func: RealFn,
    },
}

/// `singular u at P± ~ …`.
#[derive(Clone)]
pub struct SplitSingular {
    /// Index of the unknown.
    pub unknown: usize,
    /// The point.
    pub at: RealFn,
    /// `-1` below the point, `1` above, `0` not said.
    pub side: i8,
    /// The behaviour.
    pub kind: SplitKind,
}

/// `condition coefficient = value`.
#[derive(Clone)]
pub struct SplitCondition {
    /// Index of the coefficient.
    pub coefficient: usize,
    /// Its required value.
    pub value: RealFn,
}

/// An integration limit that is a function of the slot values
/// (`int(x..a)`): the operator system holds the unknowns' interval end
/// there. For an operator, `site`'s term indexes the compiled
/// [`crate::numeric::Operator`]'s terms (`numeric_site`); for an output
/// or side condition, its compiled terms.
#[derive(Clone)]
pub struct SplitEnd {
    /// The integral it belongs to.
    pub site: EndSite,
    /// The upper limit (`true`) or the lower one.
    pub upper: bool,
    /// Its value.
    pub value: RealFn,
}

/// The split-domain declarations as numbers and functions (the numeric
/// counterpart of `Contact`, field for field).
#[derive(Clone, Default)]
pub struct SplitContact {
    /// Unknown scalars (slots `0..scalars.len()`).
    pub scalars: Vec<Scalar>,
    /// Real parameters in definition order, each a function of the slots
    /// before it (slot `scalars.len() + i`).
    pub reals: Vec<RealFn>,
    /// Per unknown, the interval it lives on, if declared.
    pub unknown_domains: Vec<Option<SplitInterval>>,
    /// Per equation, where it holds (everywhere when `None`).
    pub equation_domains: Vec<Option<SplitInterval>>,
    /// Per equation, its right side when it uses an unknown scalar (then
    /// it replaces the operator system's); empty when none does.
    pub rhs: Vec<Option<RealFn>>,
    /// Relations.
    pub relations: Vec<SplitRelation>,
    /// Inequalities the solution must keep.
    pub inequalities: Vec<SplitInequality>,
    /// Declared singular behaviour.
    pub singulars: Vec<SplitSingular>,
    /// Names of the coefficients of exact singular terms.
    pub coefficients: Vec<String>,
    /// Conditions fixing the scalars.
    pub conditions: Vec<SplitCondition>,
    /// Per scalar, its declared asymptotic estimate, a function of the
    /// slots (the scalar's own slot unused); `split_end.rs` uses it only
    /// where the solver cannot place the root.
    pub estimates: Vec<Option<RealFn>>,
    /// Integration limits that use a scalar.
    pub ends: Vec<SplitEnd>,
}

impl SplitContact {
    /// The numeric form of `c` (expressions evaluated by `RExpr::eval`).
    pub fn from_contact(c: &Contact) -> SplitContact {
        let interval = |i: &Option<Interval>| i.as_ref().map(SplitInterval::from_interval);
        SplitContact {
            scalars: c.scalars.clone(),
            reals: c
                .reals
                .iter()
                .map(|r| RealFn::from_expr(&r.value))
                .collect(),
            unknown_domains: c.unknown_domains.iter().map(interval).collect(),
            equation_domains: c.equation_domains.iter().map(interval).collect(),
            rhs: c
                .rhs
                .iter()
                .map(|e| e.as_ref().map(RealFn::from_expr))
                .collect(),
            relations: c
                .relations
                .iter()
                .map(|r| SplitRelation {
                    unknown: r.unknown,
                    coeff: RealFn::from_expr(&r.coeff),
                    other: r.other,
                    domain: SplitInterval::from_interval(&r.domain),
                })
                .collect(),
            inequalities: c
                .inequalities
                .iter()
                .map(|q| {
                    let side = |t: &[crate::system::contact::LinTerm]| {
                        t.iter()
                            .map(|t| SplitLinTerm {
                                coeff: RealFn::from_expr(&t.coeff),
                                unknown: t.unknown,
                            })
                            .collect()
                    };
                    SplitInequality {
                        abs: q.abs,
                        lhs: side(&q.lhs),
                        rhs: side(&q.rhs),
                        domain: SplitInterval::from_interval(&q.domain),
                        text: q.text.clone(),
                    }
                })
                .collect(),
            singulars: c
                .singulars
                .iter()
                .map(|s| SplitSingular {
                    unknown: s.unknown,
                    at: RealFn::from_expr(&s.at),
                    side: s.side,
                    kind: match &s.kind {
                        SingularKind::Weight { exponent } => SplitKind::Weight {
                            exponent: RealFn::from_expr(exponent),
                        },
                        SingularKind::Log => SplitKind::Log,
                        SingularKind::Term { coefficient, func } => SplitKind::Term {
                            coefficient: *coefficient,
                            func: RealFn::from_expr(func),
                        },
                    },
                })
                .collect(),
            coefficients: c.coefficients.clone(),
            conditions: c
                .conditions
                .iter()
                .map(|k| SplitCondition {
                    coefficient: k.coefficient,
                    value: RealFn::from_expr(&k.value),
                })
                .collect(),
            estimates: c
                .estimates
                .iter()
                .map(|e| e.as_ref().map(RealFn::from_expr))
                .collect(),
            ends: c
                .ends
                .iter()
                .map(|e| SplitEnd {
                    site: e.site,
                    upper: e.upper,
                    value: RealFn::from_expr(&e.value),
                })
                .collect(),
        }
    }

    /// The slot values for the scalar values `scalars`: the scalars, then
    /// every real parameter evaluated in order (as `Contact::values`).
    pub fn values(&self, scalars: &[f64]) -> Vec<f64> {
        let mut v: Vec<f64> = scalars.to_vec();
        v.resize(self.scalars.len(), f64::NAN);
        for r in &self.reals {
            let x = r.eval(&v, 0.0);
            v.push(x);
        }
        v
    }
}

/// Everything the split-domain solver needs.
#[derive(Clone)]
pub struct SplitInput {
    /// The operator system without its split-domain declarations.
    pub sys: CompiledSystem,
    /// The split-domain declarations.
    pub contact: SplitContact,
}

impl SplitInput {
    /// Compiles `prog` (a file with split-domain declarations): its
    /// operator system as if it had none, and its declarations.
    pub fn from_program(prog: &Program) -> Result<SplitInput, PlanError> {
        SplitInput::for_target(prog, None)
    }

    /// [`SplitInput::from_program`] with the eliminations' target unknown
    /// named (`None`: the file's `solve for`, else the first unknown).
    pub fn for_target(prog: &Program, target: Option<&str>) -> Result<SplitInput, PlanError> {
        let mut contact = SplitContact::from_contact(&prog.contact);
        for e in &mut contact.ends {
            e.site = numeric_site(prog, e.site)?;
        }
        Ok(SplitInput {
            sys: CompiledSystem::from_program(&plain(prog), target)?,
            contact,
        })
    }
}

/// `site` of a [`crate::system::contact::MovingEnd`] of `prog` with an
/// operator's term counted among the compiled operator's terms (a
/// definition's term may compile to none, or to two: the `ln|c|` part of
/// a logarithmic kernel is a term of its own); outputs' and conditions'
/// sites are unchanged.
pub fn numeric_site(prog: &Program, site: EndSite) -> Result<EndSite, PlanError> {
    let EndSite::Operator { symbol, term } = site else {
        return Ok(site);
    };
    let def = prog
        .operator(symbol)
        .ok_or_else(|| PlanError::Invalid(format!("operator #{symbol} has no definition")))?;
    let domain = prog
        .contact
        .unknown_domains
        .iter()
        .flatten()
        .next()
        .map(|d| d.eval(&[]))
        .ok_or_else(|| {
            PlanError::Invalid("an integration limit with a scalar needs the unknowns' interval".into())
        })?;
    let name = prog.symbols.get(symbol).cloned().unwrap_or_default();
    let before = OperatorDef {
        symbol,
        terms: def.terms[..term.min(def.terms.len())].to_vec(),
    };
    let term = super::operators::plan_operator(&before, &name, domain)?.len();
    Ok(EndSite::Operator { symbol, term })
}

/// `prog` without its split-domain declarations: the operator system the
/// split solver discretises on every subinterval (what `codegen` writes
/// as `system()`).
pub fn plain(prog: &Program) -> Program {
    let mut p = prog.clone();
    let c = &prog.contact;
    p.contact = Contact::default();
    // A declared interval without scalars is the operator system's own
    // (`unknown f on [0, 2]` when no limit reaches 2).
    if c.scalars.is_empty() {
        p.contact.unknown_domains = c.unknown_domains.clone();
        p.contact.reals = c.reals.clone();
    }
    p
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::system::contact::{RBin, RealParam};
    use num_rational::BigRational;

    #[test]
    fn slot_values_match_the_expressions() {
        let c = Contact {
            scalars: vec![Scalar {
                name: "c".into(),
                range: (0.0, 1.0),
            }],
            reals: vec![RealParam {
                name: "a".into(),
                value: RExpr::Bin(
                    RBin::Pow,
                    Box::new(RExpr::Var(0)),
                    Box::new(RExpr::Const(BigRational::new(1.into(), 3.into()))),
                ),
            }],
            ..Contact::default()
        };
        let n = SplitContact::from_contact(&c);
        for s in [0.1, 0.5, 0.9] {
            let a = c.values(&[s]);
            let b = n.values(&[s]);
            assert_eq!(a.len(), b.len());
            for (x, y) in a.iter().zip(&b) {
                assert_eq!(x.to_bits(), y.to_bits());
            }
        }
    }
}
