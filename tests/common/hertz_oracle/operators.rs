//! The four operators κ1..κ4 of the seed's (2.6) as data of the numeric
//! layer, for a given `γ`. Owns nothing but their definitions; it must not
//! discretise or solve.
use lambdamat::numeric::Operator;

/// `γ = (1-2ν)/(2-2ν)`.
pub fn gamma_of_nu(nu: f64) -> f64 {
    (1.0 - 2.0 * nu) / (2.0 - 2.0 * nu)
}

/// The edge exponent `α = arccot(γμ)/π ∈ (0, 1/2]`.
pub fn edge_exponent(gamma: f64, mu: f64) -> f64 {
    let gm = gamma * mu;
    if gm <= 0.0 {
        0.5
    } else {
        (1.0 / gm).atan() / std::f64::consts::PI
    }
}

/// `κ1 f(x) = ∫_x^1 t f(t)/√(t²-x²) dt`.
pub fn kappa1() -> Operator {
    Operator::abel_upper(1.0, |_x, t| t)
}

/// `κ2 f(x) = -γ ∫_0^1 f(t) dt + γ ∫_0^x x f(t)/√(x²-t²) dt`.
pub fn kappa2(gamma: f64) -> Operator {
    Operator::smooth(0.0, 1.0, |_, _| 1.0).scaled(-gamma)
        + Operator::abel_lower(0.0, |x, _t| x).scaled(gamma)
}

/// `κ3 f(x) = γ ∫_0^x t f(t)/√(x²-t²) dt`.
pub fn kappa3(gamma: f64) -> Operator {
    Operator::abel_lower(0.0, |_x, t| t).scaled(gamma)
}

/// `κ4 f(x) = -∫_x^1 x f(t)/√(t²-x²) dt`.
pub fn kappa4() -> Operator {
    Operator::abel_upper(1.0, |x, _t| x).scaled(-1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gamma_and_alpha() {
        assert_eq!(gamma_of_nu(0.0), 0.5);
        assert!((gamma_of_nu(0.25) - 1.0 / 3.0).abs() < 1e-16);
        assert_eq!(edge_exponent(0.5, 0.0), 0.5);
        // arccot(1) = π/4.
        assert!((edge_exponent(0.5, 2.0) - 0.25).abs() < 1e-16);
        assert!(edge_exponent(0.5, 1e6) < 1e-6);
    }
}
