//! The exact Abel identities of hertz.md reproduced by the numeric layer's
//! operator matrices at many points (polynomial arguments are represented
//! exactly by the basis, so only the product integration is tested).
use lambdamat::numeric::{Assembler, Mesh, Operator, PanelBasis};

const GAMMA: f64 = 0.5;

fn kappa(i: usize) -> Operator {
    match i {
        1 => Operator::abel_upper(1.0, |_x, t| t),
        2 => {
            Operator::smooth(0.0, 1.0, |_, _| 1.0).scaled(-GAMMA)
                + Operator::abel_lower(0.0, |x, _t| x).scaled(GAMMA)
        }
        3 => Operator::abel_lower(0.0, |_x, t| t).scaled(GAMMA),
        _ => Operator::abel_upper(1.0, |x, _t| x).scaled(-1.0),
    }
}

fn points() -> Vec<f64> {
    let mut x: Vec<f64> = (1..400).map(|i| i as f64 / 400.0).collect();
    x.extend([1e-6, 1e-3, 0.123456789, 0.999, 0.999999]);
    x
}

fn max_error(
    op: &Operator,
    f: impl Fn(f64) -> f64,
    exact: impl Fn(f64) -> f64,
    basis: &PanelBasis,
) -> f64 {
    let asm = Assembler::new(basis).unwrap();
    let xs = points();
    let a = asm.matrix(op, &xs).unwrap();
    let c = nalgebra::DVector::from_vec(basis.interpolate(f));
    let v = a * c;
    xs.iter()
        .zip(v.iter())
        .map(|(x, v)| (v - exact(*x)).abs())
        .fold(0.0, f64::max)
}

fn bases() -> Vec<PanelBasis> {
    vec![
        PanelBasis::new(&Mesh::uniform(0.0, 1.0, 1).unwrap(), &[3], vec![]).unwrap(),
        PanelBasis::new(&Mesh::uniform(0.0, 1.0, 7).unwrap(), &[4; 7], vec![]).unwrap(),
        PanelBasis::new(
            &Mesh::from_breaks(vec![0.0, 0.01, 0.5, 0.9, 0.999, 1.0]).unwrap(),
            &[2, 5, 3, 8, 2],
            vec![],
        )
        .unwrap(),
    ]
}

#[test]
fn kappa1_of_one() {
    for b in bases() {
        let e = max_error(&kappa(1), |_| 1.0, |x| (1.0 - x * x).sqrt(), &b);
        eprintln!("κ1[1] max error {e:.2e}");
        assert!(e <= 1e-13, "κ1[1]: {e:e}");
    }
}

#[test]
fn kappa4_of_one() {
    for b in bases() {
        let e = max_error(
            &kappa(4),
            |_| 1.0,
            |x| x * x.ln() - x * (1.0 + (1.0 - x * x).sqrt()).ln(),
            &b,
        );
        eprintln!("κ4[1] max error {e:.2e}");
        assert!(e <= 1e-13, "κ4[1]: {e:e}");
    }
}

#[test]
fn kappa3_of_one() {
    for b in bases() {
        let e = max_error(&kappa(3), |_| 1.0, |x| GAMMA * x, &b);
        eprintln!("κ3[1] max error {e:.2e}");
        assert!(e <= 1e-13, "κ3[1]: {e:e}");
    }
}

#[test]
fn kappa4_of_x() {
    for b in bases() {
        let e = max_error(&kappa(4), |t| t, |x| -x * (1.0 - x * x).sqrt(), &b);
        eprintln!("κ4[x] max error {e:.2e}");
        assert!(e <= 1e-13, "κ4[x]: {e:e}");
    }
}

#[test]
fn kappa2_of_x() {
    for b in bases() {
        let e = max_error(&kappa(2), |t| t, |x| GAMMA * (x * x - 0.5), &b);
        eprintln!("κ2[x] max error {e:.2e}");
        assert!(e <= 1e-13, "κ2[x]: {e:e}");
    }
}
