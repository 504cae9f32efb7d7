//! The reduction of the seed's stick-zone system (`examples/hertz_stick.lmx`)
//! checked against the paper's (3.3) term by term: limits, and the composed
//! kernel at sample points, with the third term's sign as derived in
//! docs/hertz.md (real roots: `-γ² ∫_0^x x/√(x²-t²) ∫_0^t s p(s)/√(t²-s²)`).

use lambdamat::reduce::expand::{Argument, Bound, ExpandedTerm, Layer};
use lambdamat::reduce::{choose_unknown, reduce};
use num_rational::BigRational;
use num_traits::ToPrimitive;

fn seed() -> lambdamat::reduce::Reduction {
    let src = std::fs::read_to_string("examples/hertz_stick.lmx").expect("example exists");
    let p = lambdamat::lang::parse_program(&src, "hertz_stick.lmx").expect("valid");
    let u = choose_unknown(&p, Some("p")).expect("p exists");
    reduce(&p, u).expect("reduces")
}

/// (lower, upper) of each integral layer.
fn limits(t: &ExpandedTerm) -> Vec<(Bound, Bound)> {
    t.layers
        .iter()
        .map(|l| match l {
            Layer::Integral { lower, upper, .. } => (lower.clone(), upper.clone()),
            Layer::Multiply { .. } => panic!("no multiplication layers in the seed"),
        })
        .collect()
}

/// The composed kernel of a two-level term at (x, t, s).
fn kernel(term: &ExpandedTerm, x: f64, t: f64, s: f64) -> f64 {
    let pts = [x, t, s];
    let mut v = term.coeff.to_f64().expect("finite");
    for l in &term.layers {
        if let Layer::Integral {
            kernel: Some(k),
            outer,
            inner,
            ..
        } = l
        {
            v *= k.eval(pts[*outer], pts[*inner]);
        }
    }
    v
}

fn c(n: i64) -> Bound {
    Bound::Const(BigRational::from_integer(n.into()))
}

#[test]
fn expanded_form_matches_3_3_with_the_derived_sign() {
    let r = seed();
    let x = r
        .expanded
        .as_ref()
        .expect("every symbol is a defined operator");
    assert_eq!(x.lhs.len(), 3, "(3.3) has three terms on the left");
    let g2 = 1.0_f64 / 9.0; // γ = 1/3 for ν = 1/4
    let v = Bound::Var;
    // First term: ∫_x^1 ∫_t^1 -x s / √((t²-x²)(s²-t²)) p(s) ds dt.
    assert_eq!(limits(&x.lhs[0]), vec![(v(0), c(1)), (v(1), c(1))]);
    // Second: +γ² ∫_0^1 ∫_0^t s/√(t²-s²) p(s) ds dt.
    assert_eq!(limits(&x.lhs[1]), vec![(c(0), c(1)), (c(0), v(1))]);
    // Third: -γ² ∫_0^x ∫_0^t x s/(√(x²-t²) √(t²-s²)) p(s) ds dt.
    assert_eq!(limits(&x.lhs[2]), vec![(c(0), v(0)), (c(0), v(1))]);
    for &(x0, t0, s0) in &[
        (0.2_f64, 0.5_f64, 0.9_f64),
        (0.1, 0.3, 0.35),
        (0.6, 0.7, 0.95),
    ] {
        let want = -x0 * s0 / ((t0 * t0 - x0 * x0) * (s0 * s0 - t0 * t0)).sqrt();
        assert!((kernel(&x.lhs[0], x0, t0, s0) - want).abs() < 1e-12);
    }
    for &(x0, t0, s0) in &[
        (0.9_f64, 0.5_f64, 0.2_f64),
        (0.4, 0.35, 0.1),
        (0.95, 0.7, 0.6),
    ] {
        let want_b = g2 * s0 / (t0 * t0 - s0 * s0).sqrt();
        assert!((kernel(&x.lhs[1], x0, t0, s0) - want_b).abs() < 1e-12);
        let want_c = -g2 * x0 * s0 / ((x0 * x0 - t0 * t0).sqrt() * (t0 * t0 - s0 * s0).sqrt());
        let got = kernel(&x.lhs[2], x0, t0, s0);
        assert!(
            (got - want_c).abs() < 1e-12,
            "third term: {got} vs {want_c}"
        );
        assert!(
            got < 0.0,
            "the third term's sign is negative with real roots"
        );
    }
    for t in &x.lhs {
        assert_eq!(t.argument, Argument::Unknown("p".into()));
        assert_eq!(t.depth, 2);
    }
}

#[test]
fn right_side_is_k4_of_one() {
    // κ4[1] = -∫_x^1 x/√(t²-x²) dt (= x ln x - x ln(1+√(1-x²))); κ2[0] = 0.
    let r = seed();
    let x = r.expanded.as_ref().expect("expanded");
    assert_eq!(x.rhs.len(), 1);
    let t = &x.rhs[0];
    assert_eq!(limits(t), vec![(Bound::Var(0), c(1))]);
    assert_eq!(t.argument, Argument::Value(None));
    let Layer::Integral {
        kernel: Some(k), ..
    } = &t.layers[0]
    else {
        panic!("an integral with a kernel")
    };
    let (x0, t0) = (0.3_f64, 0.8_f64);
    let got = t.coeff.to_f64().expect("finite") * k.eval(x0, t0);
    assert!((got + x0 / (t0 * t0 - x0 * x0).sqrt()).abs() < 1e-12);
}

#[test]
fn the_defect_pair_is_k2_k4_and_nothing_else() {
    let r = seed();
    let pairs: Vec<[String; 2]> = r.commuted_pairs.iter().map(|c| c.pair.clone()).collect();
    assert_eq!(pairs, vec![["k2".to_string(), "k4".to_string()]]);
    assert_eq!(r.commuted_pairs[0].on, vec!["q".to_string()]);
    assert_eq!(r.lhs_ordered, "k4 k1 - k2 k3");
    assert_eq!(
        r.dropped,
        vec![("-k2 k4 + k4 k2".to_string(), "q".to_string())]
    );
}
