//! Gauss–Legendre and Gauss–Jacobi rules by Golub–Welsch: the nodes are the
//! eigenvalues of the symmetric Jacobi matrix of the orthogonal polynomials,
//! the weights come from the first components of its eigenvectors
//! (`nalgebra::SymmetricEigen`). This file owns the rules and their affine
//! maps; it must not know about kernels, meshes or operators.
use nalgebra::{DMatrix, SymmetricEigen};

use super::error::NumericError;
use super::gamma::ln_gamma;

/// An `n`-point Gauss rule on `[-1, 1]` for the Jacobi weight
/// `(1-s)^a (1+s)^b` (`a = b = 0`: Gauss–Legendre). Nodes ascend.
#[derive(Debug, Clone, PartialEq)]
pub struct GaussRule {
    /// Exponent of `(1-s)` (right end).
    pub a: f64,
    /// Exponent of `(1+s)` (left end).
    pub b: f64,
    /// Nodes in `(-1, 1)`, ascending.
    pub nodes: Vec<f64>,
    /// Weights, positive.
    pub weights: Vec<f64>,
}

impl GaussRule {
    /// Number of nodes.
    #[cfg(feature = "internals")]
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// True for the (never constructed) empty rule.
    #[cfg(feature = "internals")]
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// Nodes and weights for `∫_l^r f(t) (r-t)^a (t-l)^b dt ≈ Σ w_j f(t_j)`.
    pub fn mapped(&self, l: f64, r: f64) -> (Vec<f64>, Vec<f64>) {
        let half = 0.5 * (r - l);
        let scale = half.powf(1.0 + self.a + self.b);
        let t = self.nodes.iter().map(|s| l + half * (1.0 + s)).collect();
        let w = self.weights.iter().map(|w| w * scale).collect();
        (t, w)
    }
}

/// The `n`-point Gauss–Legendre rule on `[-1, 1]` (exact for degree `2n-1`).
///
/// ```
/// use lambdamat::numeric::gauss::gauss_legendre;
/// let r = gauss_legendre(5).unwrap();
/// let s: f64 = r.nodes.iter().zip(&r.weights).map(|(x, w)| w * x.powi(8)).sum();
/// assert!((s - 2.0 / 9.0).abs() < 1e-15);
/// ```
pub fn gauss_legendre(n: usize) -> Result<GaussRule, NumericError> {
    gauss_jacobi(n, 0.0, 0.0)
}

/// The `n`-point Gauss–Jacobi rule on `[-1, 1]` for the weight
/// `(1-s)^a (1+s)^b`, `a, b > -1`, by Golub–Welsch.
pub fn gauss_jacobi(n: usize, a: f64, b: f64) -> Result<GaussRule, NumericError> {
    if n == 0 {
        return Err(NumericError::InvalidRule("zero nodes".into()));
    }
    if !(a > -1.0 && b > -1.0 && a.is_finite() && b.is_finite()) {
        return Err(NumericError::InvalidRule(format!(
            "Jacobi exponents must exceed -1, got a = {a}, b = {b}"
        )));
    }
    let ab = a + b;
    // Zeroth moment ∫(1-s)^a(1+s)^b ds.
    let mu0 = if a == 0.0 {
        2f64.powf(b + 1.0) / (b + 1.0)
    } else if b == 0.0 {
        2f64.powf(a + 1.0) / (a + 1.0)
    } else if a == -0.5 && b == -0.5 {
        std::f64::consts::PI
    } else {
        ((ab + 1.0) * std::f64::consts::LN_2 + ln_gamma(a + 1.0) + ln_gamma(b + 1.0)
            - ln_gamma(ab + 2.0))
        .exp()
    };
    let mut jac = DMatrix::<f64>::zeros(n, n);
    for k in 0..n {
        let kf = k as f64;
        let diag = if k == 0 {
            (b - a) / (ab + 2.0)
        } else {
            (b * b - a * a) / ((2.0 * kf + ab) * (2.0 * kf + ab + 2.0))
        };
        jac[(k, k)] = diag;
        if k + 1 < n {
            let m = kf + 1.0; // off-diagonal β_m between rows k and k+1
            let beta2 = if m == 1.0 {
                4.0 * (1.0 + a) * (1.0 + b) / ((2.0 + ab) * (2.0 + ab) * (3.0 + ab))
            } else {
                let s = 2.0 * m + ab;
                4.0 * m * (m + a) * (m + b) * (m + ab) / (s * s * (s + 1.0) * (s - 1.0))
            };
            let beta = beta2.sqrt();
            jac[(k, k + 1)] = beta;
            jac[(k + 1, k)] = beta;
        }
    }
    let eig = SymmetricEigen::try_new(jac, f64::EPSILON, 0).ok_or(NumericError::Eigen(n))?;
    let mut pairs: Vec<(f64, f64)> = (0..n)
        .map(|i| {
            let v0 = eig.eigenvectors[(0, i)];
            (eig.eigenvalues[i], mu0 * v0 * v0)
        })
        .collect();
    pairs.sort_by(|x, y| x.0.total_cmp(&y.0));
    if pairs.iter().any(|(x, w)| !x.is_finite() || !w.is_finite()) {
        return Err(NumericError::Eigen(n));
    }
    Ok(GaussRule {
        a,
        b,
        nodes: pairs.iter().map(|p| p.0).collect(),
        weights: pairs.iter().map(|p| p.1).collect(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn integrate(r: &GaussRule, f: impl Fn(f64) -> f64) -> f64 {
        r.nodes.iter().zip(&r.weights).map(|(x, w)| w * f(*x)).sum()
    }

    #[test]
    fn legendre_is_exact_to_degree_2n_minus_1() {
        for n in 1..30 {
            let r = gauss_legendre(n).unwrap();
            for k in 0..2 * n {
                let exact = if k % 2 == 1 {
                    0.0
                } else {
                    2.0 / (k as f64 + 1.0)
                };
                let got = integrate(&r, |x| x.powi(k as i32));
                assert!(
                    (got - exact).abs() < 2e-15 * (n as f64),
                    "n={n} k={k} {got}"
                );
            }
        }
    }

    #[test]
    fn legendre_known_weights() {
        let r = gauss_legendre(2).unwrap();
        assert!((r.nodes[1] - 1.0 / 3f64.sqrt()).abs() < 4e-15);
        assert!((r.weights[0] - 1.0).abs() < 4e-15);
        let r = gauss_legendre(3).unwrap();
        assert!((r.nodes[2] - 0.6f64.sqrt()).abs() < 4e-15);
        assert!((r.weights[1] - 8.0 / 9.0).abs() < 4e-15);
        assert!((r.weights[0] - 5.0 / 9.0).abs() < 4e-15);
    }

    #[test]
    fn chebyshev_first_kind_is_jacobi_minus_half() {
        // a = b = -1/2: nodes cos((2j-1)π/(2n)), weights π/n.
        let n = 9;
        let r = gauss_jacobi(n, -0.5, -0.5).unwrap();
        for (j, (x, w)) in r.nodes.iter().zip(&r.weights).enumerate() {
            let jj = (n - j) as f64;
            let exact = ((2.0 * jj - 1.0) * std::f64::consts::PI / (2.0 * n as f64)).cos();
            assert!((x - exact).abs() < 1e-14);
            assert!((w - std::f64::consts::PI / n as f64).abs() < 1e-14);
        }
    }

    #[test]
    fn jacobi_exact_on_monomials_against_beta_moments() {
        // ∫_{-1}^{1} (1-s)^a (1+s)^b (1+s)^k ds = 2^{a+b+k+1} B(a+1, b+k+1).
        for &(a, b) in &[
            (-0.5, 0.0),
            (0.0, -0.5),
            (-0.3, -0.5),
            (0.7, -0.2),
            (-0.45, 1.5),
        ] {
            for n in [1usize, 4, 11, 20] {
                let r = gauss_jacobi(n, a, b).unwrap();
                for k in 0..2 * n {
                    let kf = k as f64;
                    let exact = ((a + b + kf + 1.0) * std::f64::consts::LN_2
                        + ln_gamma(a + 1.0)
                        + ln_gamma(b + kf + 1.0)
                        - ln_gamma(a + b + kf + 2.0))
                    .exp();
                    let got = integrate(&r, |s| (1.0 + s).powi(k as i32));
                    assert!(
                        (got - exact).abs() < 1e-13 * exact.max(1.0),
                        "a={a} b={b} n={n} k={k}: {got} vs {exact}"
                    );
                }
            }
        }
    }

    #[test]
    fn mapped_rule_handles_the_interval_scale() {
        // ∫_2^5 (5-t)^{-1/2} dt = 2√3.
        let r = gauss_jacobi(3, -0.5, 0.0).unwrap();
        let (_, w) = r.mapped(2.0, 5.0);
        let s: f64 = w.iter().sum();
        assert!((s - 2.0 * 3f64.sqrt()).abs() < 1e-14);
    }

    #[test]
    fn bad_parameters_are_errors() {
        assert!(gauss_jacobi(0, 0.0, 0.0).is_err());
        assert!(gauss_jacobi(3, -1.0, 0.0).is_err());
        assert!(gauss_jacobi(3, 0.0, f64::NAN).is_err());
    }
}
