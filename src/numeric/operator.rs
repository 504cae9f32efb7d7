//! Linear operators as data: linear combinations of integral terms of Abel
//! type (`∫_x^b`, `∫_a^x`, `∫_a^b` with kernel `a(x,t)|t²-x²|^{-1/2}`),
//! power, logarithmic, Cauchy principal-value and sharply peaked kernels
//! (`a(x,t)|x-t|^{-β}`, `a(x,t)ln|x-t|`, `PV a(x,t)/(t-x)`), smooth integral terms (`∫_a^b a(x,t) f(t) dt`) and multiplication by a
//! function of `x` (the identity is multiplication by 1). Kernels are
//! closures compiled once by the caller (for example from the language's
//! kernel expressions) and shared by `Arc`. This file owns the description
//! only; discretisation lives in `assemble.rs`.
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};
use std::sync::Arc;

/// A smooth kernel factor `a(x, t)`.
pub type Kernel = Arc<dyn Fn(f64, f64) -> f64 + Send + Sync>;
/// A multiplier `m(x)`.
pub type Multiplier = Arc<dyn Fn(f64) -> f64 + Send + Sync>;

/// The integration range of an integral term as a function of `x`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Limits {
    /// `∫_x^b`, oriented: for `x > b` it is `-∫_b^x`.
    Upper {
        /// Upper end.
        b: f64,
    },
    /// `∫_a^x`, oriented: for `x < a` it is `-∫_x^a`.
    Lower {
        /// Lower end.
        a: f64,
    },
    /// `∫_a^b`, independent of `x`.
    Fixed {
        /// Lower end.
        a: f64,
        /// Upper end.
        b: f64,
    },
}

impl Limits {
    /// The limits `(from, to)` at `x` as written: the integral is
    /// `∫_from^to`, which is `-∫_to^from` when `from > to`.
    pub fn at(&self, x: f64) -> (f64, f64) {
        match *self {
            Limits::Upper { b } => (x, b),
            Limits::Lower { a } => (a, x),
            Limits::Fixed { a, b } => (a, b),
        }
    }

    /// The range `[lo, hi]` (`lo ≤ hi`) at `x` and the orientation: the
    /// integral is `sign · ∫_lo^hi`.
    pub fn range_at(&self, x: f64) -> (f64, f64, f64) {
        let (from, to) = self.at(x);
        if from <= to {
            (from, to, 1.0)
        } else {
            (to, from, -1.0)
        }
    }
}

/// The singular factor of an integral term's kernel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Singularity {
    /// Kernel `a(x,t) |t² - x²|^{-1/2}` (the Hertz family).
    AbelSqrt,
    /// Kernel `a(x,t)` (smooth).
    Smooth,
    /// Kernel `a(x,t) |x - t|^{-β}`, `0 < β < 1` (Abel of order `1 - β`
    /// when the range is one-sided).
    Power {
        /// The exponent `β`.
        beta: f64,
    },
    /// Kernel `a(x,t) ln|x - t|`.
    Log,
    /// Kernel `a(x,t)/(t - x)`, integrated as a Cauchy principal value.
    Cauchy,
    /// A smooth kernel `a(x,t)` sharply peaked at `t = x`: its nearest
    /// complex singularities are `width` away from the real axis.
    Peaked {
        /// That distance.
        width: f64,
    },
}

impl Singularity {
    /// `S(x, t)` for `t ≠ x` (1 for smooth and peaked kernels).
    pub fn value(&self, x: f64, t: f64) -> f64 {
        self.value_from(t - x, t + x)
    }

    /// `S(x, t)` from the differences `t - x` and `t + x` (for callers that
    /// know them more accurately than `t`: see
    /// `super::product::composite_rule_offsets`).
    pub fn value_from(&self, t_minus_x: f64, t_plus_x: f64) -> f64 {
        match *self {
            Singularity::AbelSqrt => 1.0 / (t_minus_x.abs() * t_plus_x.abs()).sqrt(),
            Singularity::Smooth | Singularity::Peaked { .. } => 1.0,
            Singularity::Power { beta } => super::basis::pow_fast(t_minus_x.abs(), -beta),
            Singularity::Log => t_minus_x.abs().ln(),
            Singularity::Cauchy => 1.0 / t_minus_x,
        }
    }
}

/// One term of an [`Operator`].
#[derive(Clone)]
pub enum Term {
    /// `f ↦ ∫_{limits(x)} a(x,t) S(x,t) f(t) dt`.
    Integral {
        /// Integration range.
        limits: Limits,
        /// The singular factor `S`.
        singularity: Singularity,
        /// The smooth factor `a`.
        kernel: Kernel,
    },
    /// `f ↦ m(x) f(x)`.
    Multiply(Multiplier),
}

impl fmt::Debug for Term {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Term::Integral {
                limits,
                singularity,
                ..
            } => {
                write!(f, "Integral({limits:?}, {singularity:?}, <kernel>)")
            }
            Term::Multiply(_) => write!(f, "Multiply(<m>)"),
        }
    }
}

/// A linear combination `Σ c_k T_k` of terms.
///
/// ```
/// use lambdamat::numeric::operator::Operator;
/// // κ1 f(x) = ∫_x^1 t f(t)/√(t²-x²) dt
/// let k1 = Operator::abel_upper(1.0, |_x, t| t);
/// assert_eq!(k1.terms.len(), 1);
/// ```
#[derive(Clone, Debug, Default)]
pub struct Operator {
    /// Coefficients and terms.
    pub terms: Vec<(f64, Term)>,
}

impl Operator {
    /// The zero operator.
    pub fn zero() -> Operator {
        Operator::default()
    }

    /// The identity.
    pub fn identity() -> Operator {
        Operator::multiply(|_| 1.0)
    }

    /// Multiplication by `m(x)`.
    pub fn multiply(m: impl Fn(f64) -> f64 + Send + Sync + 'static) -> Operator {
        Operator {
            terms: vec![(1.0, Term::Multiply(Arc::new(m)))],
        }
    }

    /// A single integral term.
    pub fn integral(
        limits: Limits,
        singularity: Singularity,
        kernel: impl Fn(f64, f64) -> f64 + Send + Sync + 'static,
    ) -> Operator {
        Operator::integral_shared(limits, singularity, Arc::new(kernel))
    }

    /// [`Operator::integral`] with a kernel already behind an `Arc` (a
    /// compiled one): used as it is, not wrapped in a further closure
    /// (assembly calls it once per quadrature node).
    pub fn integral_shared(limits: Limits, singularity: Singularity, kernel: Kernel) -> Operator {
        Operator {
            terms: vec![(
                1.0,
                Term::Integral {
                    limits,
                    singularity,
                    kernel,
                },
            )],
        }
    }

    /// `∫_x^b a(x,t) f(t) / √(t²-x²) dt`.
    pub fn abel_upper(b: f64, a: impl Fn(f64, f64) -> f64 + Send + Sync + 'static) -> Operator {
        Operator::integral(Limits::Upper { b }, Singularity::AbelSqrt, a)
    }

    /// `∫_a^x k(x,t) f(t) / √(x²-t²) dt`.
    pub fn abel_lower(a: f64, k: impl Fn(f64, f64) -> f64 + Send + Sync + 'static) -> Operator {
        Operator::integral(Limits::Lower { a }, Singularity::AbelSqrt, k)
    }

    /// `∫_a^b k(x,t) f(t) / √|t²-x²| dt`.
    pub fn abel_fixed(
        a: f64,
        b: f64,
        k: impl Fn(f64, f64) -> f64 + Send + Sync + 'static,
    ) -> Operator {
        Operator::integral(Limits::Fixed { a, b }, Singularity::AbelSqrt, k)
    }

    /// `∫_a^b k(x,t) f(t) dt` with smooth `k`.
    pub fn smooth(a: f64, b: f64, k: impl Fn(f64, f64) -> f64 + Send + Sync + 'static) -> Operator {
        Operator::integral(Limits::Fixed { a, b }, Singularity::Smooth, k)
    }

    /// `c · self`.
    pub fn scaled(mut self, c: f64) -> Operator {
        self.terms.iter_mut().for_each(|t| t.0 *= c);
        self
    }
}

impl Add for Operator {
    type Output = Operator;
    fn add(mut self, rhs: Operator) -> Operator {
        self.terms.extend(rhs.terms);
        self
    }
}

impl Sub for Operator {
    type Output = Operator;
    fn sub(self, rhs: Operator) -> Operator {
        self + rhs.scaled(-1.0)
    }
}

impl Neg for Operator {
    type Output = Operator;
    fn neg(self) -> Operator {
        self.scaled(-1.0)
    }
}

impl Mul<Operator> for f64 {
    type Output = Operator;
    fn mul(self, rhs: Operator) -> Operator {
        rhs.scaled(self)
    }
}
