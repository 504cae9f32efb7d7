//! The split-domain part of a lowered program (contact problems): where
//! unknowns live and equations hold, relations substituted on
//! subintervals, unknown scalars with their ranges, real parameters
//! (expressions of parameters and scalars that are not exact rationals),
//! declared singular behaviour of unknowns at points and the conditions
//! that fix the scalars. Data and evaluation only; built by `lang::lower`,
//! solved by `plan::contact`. It must not discretise anything.
use num_rational::BigRational;
use num_traits::ToPrimitive;

/// A real expression of the real parameters, the scalars and `x`.
#[derive(Clone, Debug, PartialEq)]
pub enum RExpr {
    /// An exact constant (rational parameters are substituted).
    Const(BigRational),
    /// π.
    Pi,
    /// The variable `x`.
    X,
    /// Slot `i` of the value vector ([`Contact::slots`]).
    Var(usize),
    /// `-a`
    Neg(Box<RExpr>),
    /// A binary operation.
    Bin(RBin, Box<RExpr>, Box<RExpr>),
    /// `f(a)`.
    Call(RFunc, Box<RExpr>),
}

/// Binary operations of [`RExpr`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RBin {
    /// `+`
    Add,
    /// `-`
    Sub,
    /// `*`
    Mul,
    /// `/`
    Div,
    /// `^` (real power)
    Pow,
}

/// Elementary functions of `RExpr`: the same functions as in kernels.
pub use super::expr::Func as RFunc;

/// `a^b` as `RExpr::eval` computes it: `powi` for small integer `b`,
/// else `powf` (code that `lambdamat codegen` writes calls it too).
pub fn real_pow(a: f64, b: f64) -> f64 {
    if b.fract() == 0.0 && b.abs() <= 64.0 {
        a.powi(b as i32)
    } else {
        a.powf(b)
    }
}

impl RExpr {
    /// The value for slot values `vars` at `x` (IEEE semantics).
    ///
    /// ```
    /// use lambdamat::system::contact::{RExpr, RFunc};
    /// let e = RExpr::Call(RFunc::Acot, Box::new(RExpr::Var(0)));
    /// assert!((e.eval(&[1.0], 0.0) - std::f64::consts::FRAC_PI_4).abs() < 1e-16);
    /// ```
    pub fn eval(&self, vars: &[f64], x: f64) -> f64 {
        match self {
            RExpr::Const(q) => q.to_f64().unwrap_or(f64::NAN),
            RExpr::Pi => std::f64::consts::PI,
            RExpr::X => x,
            RExpr::Var(i) => vars.get(*i).copied().unwrap_or(f64::NAN),
            RExpr::Neg(a) => -a.eval(vars, x),
            RExpr::Bin(op, a, b) => {
                let (a, b) = (a.eval(vars, x), b.eval(vars, x));
                match op {
                    RBin::Add => a + b,
                    RBin::Sub => a - b,
                    RBin::Mul => a * b,
                    RBin::Div => a / b,
                    RBin::Pow => real_pow(a, b),
                }
            }
            RExpr::Call(f, a) => f.apply(a.eval(vars, x)),
        }
    }

    /// Source text, with slot names `slots` (fully parenthesised where
    /// precedence is not obvious).
    ///
    /// ```
    /// use lambdamat::system::contact::{RBin, RExpr};
    /// let e = RExpr::Bin(RBin::Mul, Box::new(RExpr::Var(0)), Box::new(RExpr::X));
    /// assert_eq!(e.to_text(&["mu".to_string()]), "mu*x");
    /// ```
    pub fn to_text(&self, slots: &[String]) -> String {
        let atom = |e: &RExpr| match e {
            RExpr::Bin(..) | RExpr::Neg(_) => format!("({})", e.to_text(slots)),
            RExpr::Const(q) if !q.is_integer() || q < &BigRational::from_integer(0.into()) => {
                format!("({})", e.to_text(slots))
            }
            _ => e.to_text(slots),
        };
        match self {
            RExpr::Const(q) => q.to_string(),
            RExpr::Pi => "pi".into(),
            RExpr::X => "x".into(),
            RExpr::Var(i) => slots.get(*i).cloned().unwrap_or_else(|| format!("#{i}")),
            RExpr::Neg(a) => format!("-{}", atom(a)),
            RExpr::Bin(op, a, b) => {
                let sym = match op {
                    RBin::Add => " + ",
                    RBin::Sub => " - ",
                    RBin::Mul => "*",
                    RBin::Div => "/",
                    RBin::Pow => "^",
                };
                match op {
                    RBin::Add => format!("{}{sym}{}", a.to_text(slots), b.to_text(slots)),
                    RBin::Sub => format!("{}{sym}{}", a.to_text(slots), atom(b)),
                    _ => format!("{}{sym}{}", atom(a), atom(b)),
                }
            }
            RExpr::Call(f, a) => {
                let name = f.name();
                format!("{name}({})", a.to_text(slots))
            }
        }
    }

    /// Whether `x` occurs.
    pub fn uses_x(&self) -> bool {
        match self {
            RExpr::X => true,
            RExpr::Const(_) | RExpr::Pi | RExpr::Var(_) => false,
            RExpr::Neg(a) | RExpr::Call(_, a) => a.uses_x(),
            RExpr::Bin(_, a, b) => a.uses_x() || b.uses_x(),
        }
    }

    /// Whether a slot (a scalar or a real parameter) occurs.
    pub fn uses_slots(&self) -> bool {
        match self {
            RExpr::Var(_) => true,
            RExpr::Const(_) | RExpr::Pi | RExpr::X => false,
            RExpr::Neg(a) | RExpr::Call(_, a) => a.uses_slots(),
            RExpr::Bin(_, a, b) => a.uses_slots() || b.uses_slots(),
        }
    }
}

/// An interval with expression ends.
#[derive(Clone, Debug, PartialEq)]
pub struct Interval {
    /// Left end.
    pub lo: RExpr,
    /// Right end.
    pub hi: RExpr,
    /// `[` (true) or `(`.
    pub lo_closed: bool,
    /// `]` (true) or `)`.
    pub hi_closed: bool,
}

impl Interval {
    /// The ends for slot values `vars`.
    pub fn eval(&self, vars: &[f64]) -> (f64, f64) {
        (self.lo.eval(vars, 0.0), self.hi.eval(vars, 0.0))
    }
}

/// `unknown = coeff · other` on `domain` (`unknown = 0` is stored with
/// `coeff` 0 and `other` the unknown itself).
#[derive(Clone, Debug, PartialEq)]
pub struct Relation {
    /// Index of the unknown that is substituted.
    pub unknown: usize,
    /// The constant factor.
    pub coeff: RExpr,
    /// Index of the unknown it is expressed by.
    pub other: usize,
    /// Where it holds.
    pub domain: Interval,
}

/// One term of a side of an [`Inequality`]: `coeff · unknown`, or the
/// constant `coeff` when `unknown` is `None`.
#[derive(Clone, Debug, PartialEq)]
pub struct LinTerm {
    /// The factor (a real expression of the slots).
    pub coeff: RExpr,
    /// The unknown it multiplies, if any.
    pub unknown: Option<usize>,
}

/// `lhs <= rhs` (or `|lhs| <= rhs` when `abs`) on `domain`: a bound the
/// solution must keep (e.g. Coulomb's `|q| ≤ μp` where the surfaces
/// stick). `>=` is stored with its sides swapped.
#[derive(Clone, Debug, PartialEq)]
pub struct Inequality {
    /// Whether the smaller side is `abs(lhs)`.
    pub abs: bool,
    /// The smaller side.
    pub lhs: Vec<LinTerm>,
    /// The larger side.
    pub rhs: Vec<LinTerm>,
    /// Where it must hold.
    pub domain: Interval,
    /// Its source text (for messages).
    pub text: String,
}

impl Inequality {
    /// Source text `abs(q) <= (mu)*p` without its interval, with unknown
    /// names `unknowns` and slot names `slots`.
    pub fn to_text(&self, unknowns: &[String], slots: &[String]) -> String {
        let side = |terms: &[LinTerm]| -> String {
            if terms.is_empty() {
                return "0".into();
            }
            terms
                .iter()
                .map(|t| {
                    let k = t.coeff.to_text(slots);
                    match t.unknown {
                        Some(u) => {
                            let name = unknowns.get(u).map_or("?", String::as_str);
                            match k.as_str() {
                                "1" => name.to_string(),
                                "-1" => format!("-{name}"),
                                _ => format!("({k})*{name}"),
                            }
                        }
                        None if k.chars().all(|c| c.is_ascii_digit()) => k,
                        None => format!("({k})"),
                    }
                })
                .collect::<Vec<_>>()
                .join(" + ")
        };
        let small = side(&self.lhs);
        let small = if self.abs {
            format!("abs({small})")
        } else {
            small
        };
        format!("{small} <= {}", side(&self.rhs))
    }
}

/// An unknown scalar.
#[derive(Clone, Debug, PartialEq)]
pub struct Scalar {
    /// Its name.
    pub name: String,
    /// The range searched (ends may be infinite).
    pub range: (f64, f64),
}

/// What is declared singular about an unknown at a point.
#[derive(Clone, Debug, PartialEq)]
pub enum SingularKind {
    /// `(P - x)^e` or `(x - P)^e`: the weight `|x - P|^e` is factored out.
    Weight {
        /// The exponent `e`.
        exponent: RExpr,
    },
    /// `ln|x - P|` (`ln(x)`, `log(1 - x)`, …): a logarithmic end. The
    /// mesh is graded toward `P` as toward any declared point; no weight
    /// is factored out, and the unknown's value at `P` is not reported.
    Log,
    /// `B * g(x)`: an exact singular term with a free coefficient.
    Term {
        /// Index of the coefficient in [`Contact::coefficients`].
        coefficient: usize,
        /// `g(x)`.
        func: RExpr,
    },
}

/// `singular u at P± ~ …`.
#[derive(Clone, Debug, PartialEq)]
pub struct Singular {
    /// Index of the unknown.
    pub unknown: usize,
    /// The point.
    pub at: RExpr,
    /// `-1` below the point, `1` above, `0` not said.
    pub side: i8,
    /// The behaviour.
    pub kind: SingularKind,
}

/// `condition coefficient = value`.
#[derive(Clone, Debug, PartialEq)]
pub struct Condition {
    /// Index of the coefficient.
    pub coefficient: usize,
    /// Its required value.
    pub value: RExpr,
}

/// A real parameter: a value computed numerically from other parameters
/// and the scalars.
#[derive(Clone, Debug, PartialEq)]
pub struct RealParam {
    /// Its name.
    pub name: String,
    /// Its definition.
    pub value: RExpr,
}

/// The split-domain declarations of a program (all empty for an ordinary
/// system on one interval).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Contact {
    /// Unknown scalars; slot `i` of the value vector for `i < scalars.len()`.
    pub scalars: Vec<Scalar>,
    /// Real parameters in definition order; slot `scalars.len() + i`.
    pub reals: Vec<RealParam>,
    /// Per unknown, the interval it lives on, if declared.
    pub unknown_domains: Vec<Option<Interval>>,
    /// Per equation, where it holds (everywhere when `None`).
    pub equation_domains: Vec<Option<Interval>>,
    /// Per equation, its right side when it uses an unknown scalar (a
    /// function of the slots and `x`; the operator system holds 0 there);
    /// empty when no right side does.
    pub rhs: Vec<Option<RExpr>>,
    /// Relations.
    pub relations: Vec<Relation>,
    /// Inequalities the solution must keep.
    pub inequalities: Vec<Inequality>,
    /// Declared singular behaviour.
    pub singulars: Vec<Singular>,
    /// Names of the coefficients of exact singular terms.
    pub coefficients: Vec<String>,
    /// Conditions fixing the scalars.
    pub conditions: Vec<Condition>,
    /// Per scalar, its declared asymptotic estimate (`scalar c in (0, 1) ~
    /// e`), a function of the real parameters; the solver uses it only
    /// where it cannot place the root itself.
    pub estimates: Vec<Option<RExpr>>,
    /// Integration limits that use an unknown scalar (`int(x..a)` in an
    /// operator, `int(0..a)` in an output or side condition): the
    /// operator system holds the unknowns' interval end there, and the
    /// split solver integrates to the limit's value at the scalars.
    pub ends: Vec<MovingEnd>,
}

/// Where a `MovingEnd` (a scalar integration limit) sits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EndSite {
    /// Term `term` of the definition of operator symbol `symbol`.
    Operator {
        /// Index into `Program::symbols`.
        symbol: usize,
        /// Index into the definition's terms.
        term: usize,
    },
    /// Term `term` of output `output`.
    Output {
        /// Index into `Program::outputs`.
        output: usize,
        /// Index into its terms.
        term: usize,
    },
    /// Term `term` of side condition `condition`.
    Condition {
        /// Index into `Program::side_conditions`.
        condition: usize,
        /// Index into its terms.
        term: usize,
    },
}

/// An integration limit that is a function of the slots.
#[derive(Clone, Debug, PartialEq)]
pub struct MovingEnd {
    /// The integral it belongs to.
    pub site: EndSite,
    /// The upper limit (`true`) or the lower one.
    pub upper: bool,
    /// Its value.
    pub value: RExpr,
}

impl Contact {
    /// Whether the program uses any split-domain feature.
    pub fn is_split(&self) -> bool {
        !(self.scalars.is_empty()
            && self.relations.is_empty()
            && self.inequalities.is_empty()
            && self.singulars.is_empty()
            && self.conditions.is_empty()
            && self.ends.is_empty()
            && self.equation_domains.iter().all(Option::is_none))
    }

    /// Names of the value slots: scalars, then real parameters.
    pub fn slots(&self) -> Vec<String> {
        self.scalars
            .iter()
            .map(|s| s.name.clone())
            .chain(self.reals.iter().map(|r| r.name.clone()))
            .collect()
    }

    /// The slot values for the scalar values `scalars`: the scalars, then
    /// every real parameter evaluated in order.
    pub fn values(&self, scalars: &[f64]) -> Vec<f64> {
        let mut v: Vec<f64> = scalars.to_vec();
        v.resize(self.scalars.len(), f64::NAN);
        for r in &self.reals {
            let x = r.value.eval(&v, 0.0);
            v.push(x);
        }
        v
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn acot_branch_and_reals_in_order() {
        let acot = |v: f64| {
            RExpr::Call(
                RFunc::Acot,
                Box::new(RExpr::Const(BigRational::from_float(v).unwrap_or_default())),
            )
            .eval(&[], 0.0)
        };
        assert!((acot(0.0) - std::f64::consts::FRAC_PI_2).abs() < 1e-16);
        assert!((acot(-1.0) - 0.75 * std::f64::consts::PI).abs() < 1e-15);
        let c = Contact {
            scalars: vec![Scalar {
                name: "mu".into(),
                range: (0.0, f64::INFINITY),
            }],
            reals: vec![RealParam {
                name: "a".into(),
                value: RExpr::Bin(RBin::Mul, Box::new(RExpr::Var(0)), Box::new(RExpr::Pi)),
            }],
            ..Contact::default()
        };
        assert_eq!(c.slots(), ["mu", "a"]);
        let v = c.values(&[2.0]);
        assert!((v[1] - 2.0 * std::f64::consts::PI).abs() < 1e-15);
    }
}
