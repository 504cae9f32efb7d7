//! The exact values the API hands out: [`RationalFunction`], one entry of a
//! Smith decomposition as a reduced fraction of polynomials with rational
//! coefficients in the file's symbols. It is read back from the one
//! printer's language syntax (`crate::lang::formula`), so the value and
//! the printed text are the same fact; it owns only that reading, access
//! to the terms and exact evaluation.

use num_rational::BigRational;
use num_traits::{One, Zero};

use crate::algebra::mpoly::MPoly;
use crate::algebra::ratfunc::RatFunc;

/// An exact rational function `numerator / denominator` of the symbols
/// [`RationalFunction::symbols`], reduced (coprime, the denominator with
/// coprime integer coefficients and a positive leading one, so equal
/// functions have equal terms). A polynomial has denominator 1.
///
/// ```
/// use lambdamat::{Problem, SmithOptions};
/// use num_rational::BigRational;
/// let p = Problem::from_source("var x\nmatrix A = [x, 1; 0, 2*x]", "m.lmx")?;
/// let f = &p.smith(&SmithOptions::default())?.exact_invariant_factors()?[1];
/// assert_eq!(f.to_string(), "x^2");
/// // terms: (exponent of each symbol, coefficient)
/// assert_eq!(f.numerator(), vec![(vec![2], BigRational::from_integer(1.into()))]);
/// let three = BigRational::from_integer(3.into());
/// assert_eq!(f.eval(&[three]), Some(BigRational::from_integer(9.into())));
/// # Ok::<(), lambdamat::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RationalFunction {
    value: RatFunc,
    symbols: Vec<String>,
    text: String,
}

/// Terms `(exponents, coefficient)` of a polynomial, one exponent per
/// symbol, in the polynomial's own (graded, descending) order.
pub type Terms = Vec<(Vec<u32>, BigRational)>;

impl RationalFunction {
    /// Reads the printed `text` in `symbols`; `None` if it is not a
    /// rational function of them (the printer never writes such text).
    pub(crate) fn read(text: &str, symbols: &[String]) -> Option<RationalFunction> {
        let value = crate::lang::formula::parse_ratfunc(text, symbols).ok()?;
        Some(RationalFunction {
            value,
            symbols: symbols.to_vec(),
            text: text.to_string(),
        })
    }

    /// The symbols, in the order of each term's exponents.
    ///
    /// ```
    /// # use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_source("var s, t\nmatrix A = [s*t]", "m.lmx")?;
    /// let f = &p.smith(&SmithOptions::default())?.exact_invariant_factors()?[0];
    /// assert_eq!(f.symbols(), ["s", "t"]);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn symbols(&self) -> &[String] {
        &self.symbols
    }

    /// The numerator's terms.
    ///
    /// ```
    /// # use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_source("var s, t\nmatrix A = [s*t + 1/2]", "m.lmx")?;
    /// let f = &p.smith(&SmithOptions::default())?.exact_invariant_factors()?[0];
    /// // monic: s*t + 1/2
    /// assert_eq!(f.numerator().len(), 2);
    /// assert_eq!(f.numerator()[0].0, vec![1, 1]);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn numerator(&self) -> Terms {
        terms(self.value.num())
    }

    /// The denominator's terms (`[([0, …], 1)]` for a polynomial).
    ///
    /// ```
    /// # use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_source("var x\nmatrix A = [x]", "m.lmx")?;
    /// let f = &p.smith(&SmithOptions::default())?.exact_invariant_factors()?[0];
    /// assert!(f.is_polynomial());
    /// assert_eq!(f.denominator(), vec![(vec![0], num_rational::BigRational::from_integer(1.into()))]);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn denominator(&self) -> Terms {
        terms(self.value.den())
    }

    /// Whether the denominator is 1.
    ///
    /// ```
    /// # use lambdamat::{Problem, SmithOptions};
    /// let p = Problem::from_source("var k1, k2\nprincipal k2\nmatrix A = [k1*k2, 1; 0, k2]", "m.lmx")?;
    /// let s = p.smith(&SmithOptions::default())?;
    /// // Over Q(k1)[k2] the factors are monic in k2: k2^2 has no denominator.
    /// assert!(s.exact_invariant_factors()?.iter().all(|f| f.is_polynomial()));
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn is_polynomial(&self) -> bool {
        self.value.is_polynomial()
    }

    /// The value at `point` (one rational per symbol), exactly; `None` when
    /// the number of values is not the number of symbols or the
    /// denominator vanishes there.
    ///
    /// ```
    /// # use lambdamat::{Problem, SmithOptions};
    /// use num_rational::BigRational as Q;
    /// let p = Problem::from_source("var x\nmatrix A = [x - 1/3]", "m.lmx")?;
    /// let f = &p.smith(&SmithOptions::default())?.exact_invariant_factors()?[0];
    /// assert_eq!(f.eval(&[Q::new(1.into(), 3.into())]), Some(Q::from_integer(0.into())));
    /// assert_eq!(f.eval(&[]), None);
    /// # Ok::<(), lambdamat::Error>(())
    /// ```
    pub fn eval(&self, point: &[BigRational]) -> Option<BigRational> {
        if point.len() != self.symbols.len() {
            return None;
        }
        let den = eval(self.value.den(), point);
        if den.is_zero() {
            return None;
        }
        Some(eval(self.value.num(), point) / den)
    }
}

/// The language syntax the one printer wrote (it parses back to `self`).
impl std::fmt::Display for RationalFunction {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.text)
    }
}

fn terms(p: &MPoly) -> Terms {
    p.terms()
        .iter()
        .map(|(m, c)| (m.clone(), c.clone()))
        .collect()
}

fn eval(p: &MPoly, point: &[BigRational]) -> BigRational {
    let mut sum = BigRational::zero();
    for (m, c) in p.terms() {
        let mut t = c.clone();
        for (x, &e) in point.iter().zip(m) {
            let mut pw = BigRational::one();
            for _ in 0..e {
                pw *= x;
            }
            t *= pw;
        }
        sum += t;
    }
    sum
}
