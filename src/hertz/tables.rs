//! The published values the Hertz front is compared with, written once:
//! Spence's (1975) stick radii and the seed paper's Table 1 and Table 2
//! rows (`lambdamat hertz table` prints them beside ours; the tests check
//! our values against them). Owns these constants only.

/// Spence's published `(ν, μ, c)` triples (the seed's Table 1, column c1).
/// Four digits: agreement to about 1e-3 in `μ` is what can be expected.
pub const SPENCE: [(f64, f64, f64); 7] = [
    (0.0, 0.2063, 0.24),
    (0.0, 0.2986, 0.50),
    (0.0, 0.4013, 0.70),
    (0.0, 0.4862, 0.80),
    (0.25, 0.1387, 0.30),
    (0.25, 0.1801, 0.50),
    (0.25, 0.2843, 0.80),
];

/// Spence's `c` for `(ν, μ)`, when he published one.
pub fn spence_c(nu: f64, mu: f64) -> Option<f64> {
    SPENCE
        .iter()
        .find(|&&(n, m, _)| n == nu && m == mu)
        .map(|&(_, _, c)| c)
}

/// The seed's Table 1 rows: `(μ, ν, c2, c3)` (c2, c3: Gauthier et al.
/// as printed in the seed); c1 is [`spence_c`].
pub const SEED_TABLE1: [(f64, f64, f64, f64); 14] = [
    (0.1387, 0.0, 0.0750, 0.0913),
    (0.1387, 0.25, 0.3083, 0.3028),
    (0.1801, 0.0, 0.1750, 0.2041),
    (0.1801, 0.25, 0.5083, 0.5083),
    (0.2063, 0.0, 0.2417, 0.2739),
    (0.2063, 0.25, 0.6083, 0.6124),
    (0.2843, 0.0, 0.4750, 0.4743),
    (0.2843, 0.25, 0.8083, 0.8010),
    (0.2986, 0.0, 0.5083, 0.5083),
    (0.2986, 0.25, 0.8250, 0.8317),
    (0.4013, 0.0, 0.7083, 0.7072),
    (0.4013, 0.25, 0.9250, 0.9265),
    (0.4862, 0.0, 0.8083, 0.8010),
    (0.4862, 0.25, 0.9750, 0.9618),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_spence_row_is_a_seed_row() {
        let found = SPENCE
            .iter()
            .filter(|&&(nu, mu, _)| SEED_TABLE1.iter().any(|r| r.0 == mu && r.1 == nu))
            .count();
        assert_eq!(found, SPENCE.len());
        assert_eq!(spence_c(0.25, 0.1801), Some(0.5));
        assert_eq!(spence_c(0.0, 0.1801), None);
    }
}
