//! The manufactured coupled system, the frictionless punch, a convergence
//! sequence and the refusal of singular systems, all through the public
//! numeric layer.
use lambdamat::numeric::elimination::{
    apply_to_values, commutator_defect_on, product, solve_blocks,
};
use lambdamat::numeric::solve::{CheckedLu, solve};
use lambdamat::numeric::{Assembler, Factor, Mesh, NumericError, Operator, PanelBasis};
use nalgebra::{DMatrix, DVector};
use std::f64::consts::{FRAC_PI_2, PI};

// The 2×2 recipes, written here from the library's building blocks
// (`solve_blocks`, `product`, `CheckedLu`): the library's own methods are
// `plan::methods`, which work on any square system.

/// The blocks and right sides of a 2×2 system.
struct System2<'a> {
    k11: &'a DMatrix<f64>,
    k12: &'a DMatrix<f64>,
    k21: &'a DMatrix<f64>,
    k22: &'a DMatrix<f64>,
    g1: &'a DVector<f64>,
    g2: &'a DVector<f64>,
}

/// Coefficients of `p` and `q` (empty `q` for the commutative model).
struct Solution2 {
    p: DVector<f64>,
    q: DVector<f64>,
}

fn solve_coupled(s: &System2, max_cond: f64) -> Result<Solution2, NumericError> {
    let (mut x, _) = solve_blocks(
        &[vec![s.k11, s.k12], vec![s.k21, s.k22]],
        &[s.g1, s.g2],
        max_cond,
    )?;
    let q = x.pop().expect("two unknowns");
    let p = x.pop().expect("two unknowns");
    Ok(Solution2 { p, q })
}

/// `(K11 - K12 K22⁻¹ K21) p = g1 - K12 K22⁻¹ g2`, then `q = K22⁻¹ (g2 - K21 p)`.
fn solve_ordered(s: &System2, max_cond: f64) -> Result<Solution2, NumericError> {
    let l22 = CheckedLu::new(s.k22, max_cond)?;
    let y = l22.solve_matrix(s.k21)?;
    let schur = s.k11 - s.k12 * y;
    let rhs = s.g1 - s.k12 * l22.solve(s.g2)?;
    let p = CheckedLu::new(&schur, max_cond)?.solve(&rhs)?;
    let q = l22.solve(&(s.g2 - s.k21 * &p))?;
    Ok(Solution2 { p, q })
}

/// The seed's model `(K22K11 - K12K21) p = K22 g1 - K12 g2` through `mid`.
fn solve_commutative(
    s: &System2,
    mid: &PanelBasis,
    max_cond: f64,
) -> Result<Solution2, NumericError> {
    let lhs = product(s.k22, mid, s.k11)? - product(s.k12, mid, s.k21)?;
    let rhs = apply_to_values(s.k22, mid, s.g1)? - apply_to_values(s.k12, mid, s.g2)?;
    let p = CheckedLu::new(&lhs, max_cond)?.solve(&rhs)?;
    Ok(Solution2 {
        p,
        q: DVector::zeros(0),
    })
}

fn commutator_defect(
    ka: &DMatrix<f64>,
    kb: &DMatrix<f64>,
    mid: &PanelBasis,
    f: &DVector<f64>,
) -> Result<f64, NumericError> {
    commutator_defect_on(ka, kb, ka, kb, mid, f)
}

fn kappa(i: usize, g: f64) -> Operator {
    match i {
        1 => Operator::abel_upper(1.0, |_x, t| t),
        2 => {
            Operator::smooth(0.0, 1.0, |_, _| 1.0).scaled(-g)
                + Operator::abel_lower(0.0, |x, _t| x).scaled(g)
        }
        3 => Operator::abel_lower(0.0, |_x, t| t).scaled(g),
        _ => Operator::abel_upper(1.0, |x, _t| x).scaled(-1.0),
    }
}

struct Mms {
    basis: PanelBasis,
    k: Vec<DMatrix<f64>>,
    g1: DVector<f64>,
    g2: DVector<f64>,
}

fn mms(g: f64, panels: usize, nodes: usize) -> Mms {
    let basis = PanelBasis::new(
        &Mesh::uniform(0.0, 1.0, panels).unwrap(),
        &vec![nodes; panels],
        vec![],
    )
    .unwrap();
    let asm = Assembler::new(&basis).unwrap();
    let x = basis.nodes();
    let k = (1..=4)
        .map(|i| asm.matrix(&kappa(i, g), &x).unwrap())
        .collect();
    let g1 = DVector::from_iterator(
        x.len(),
        x.iter().map(|x| (1.0 - x * x).sqrt() + g * (x * x - 0.5)),
    );
    let g2 = DVector::from_iterator(x.len(), x.iter().map(|x| g * x - x * (1.0 - x * x).sqrt()));
    Mms { basis, k, g1, g2 }
}

fn max_dev(v: &DVector<f64>, f: impl Fn(usize) -> f64) -> f64 {
    v.iter()
        .enumerate()
        .map(|(i, v)| (v - f(i)).abs())
        .fold(0.0, f64::max)
}

#[test]
fn manufactured_system_coupled_ordered_and_commutative() {
    for (g, panels, nodes) in [(0.5, 4, 8), (1.0 / 3.0, 6, 6)] {
        let m = mms(g, panels, nodes);
        let x = m.basis.nodes();
        let s = System2 {
            k11: &m.k[0],
            k12: &m.k[1],
            k21: &m.k[2],
            k22: &m.k[3],
            g1: &m.g1,
            g2: &m.g2,
        };
        let c = solve_coupled(&s, 1e13).unwrap();
        assert!(max_dev(&c.p, |_| 1.0) <= 1e-10, "coupled p");
        assert!(max_dev(&c.q, |i| x[i]) <= 1e-10, "coupled q");
        let (b, _) = solve_blocks(
            &[vec![&m.k[0], &m.k[1]], vec![&m.k[2], &m.k[3]]],
            &[&m.g1, &m.g2],
            1e13,
        )
        .unwrap();
        assert!((&b[0] - &c.p).amax() < 1e-14 && (&b[1] - &c.q).amax() < 1e-14);
        let o = solve_ordered(&s, 1e13).unwrap();
        assert!(max_dev(&o.p, |_| 1.0) <= 1e-10, "ordered p");
        assert!(max_dev(&o.q, |i| x[i]) <= 1e-10, "ordered q");
        // The commutative model is visibly wrong ...
        let w = solve_commutative(&s, &m.basis, 1e13).unwrap();
        let err = max_dev(&w.p, |_| 1.0);
        eprintln!(
            "γ={g:.4}: coupled p {:.1e} q {:.1e}; ordered p {:.1e} q {:.1e}; commutative p error {err:.2e}",
            max_dev(&c.p, |_| 1.0),
            max_dev(&c.q, |i| x[i]),
            max_dev(&o.p, |_| 1.0),
            max_dev(&o.q, |i| x[i])
        );
        assert!(err > 0.5, "commutative model error {err}");
        // ... because κ4 and κ2 do not commute: O(1) defect.
        let f = DVector::from_vec(m.basis.interpolate(|t| t));
        let d = commutator_defect(&m.k[3], &m.k[1], &m.basis, &f).unwrap();
        eprintln!("γ={g:.4}: defect ‖K4K2 f - K2K4 f‖/‖K4K2 f‖ = {d:.3} (f = x)");
        assert!(d > 0.5, "defect {d}");
    }
}

fn punch(panels: usize, nodes: usize) -> (f64, f64) {
    let w = vec![Factor {
        at: 1.0,
        exponent: -0.5,
    }];
    let basis = PanelBasis::new(
        &Mesh::uniform(0.0, 1.0, panels).unwrap(),
        &vec![nodes; panels],
        w,
    )
    .unwrap();
    let asm = Assembler::new(&basis).unwrap();
    let x = basis.nodes();
    let a = asm.matrix(&kappa(1, 0.0), &x).unwrap();
    let p = solve(&a, &DVector::from_element(x.len(), 1.0)).unwrap();
    let pstar = FRAC_PI_2 * DVector::from_vec(asm.functional(|t| t, 0.0, 1.0).unwrap()).dot(&p);
    let exact = |t: f64| 2.0 / PI / (1.0 - t * t).sqrt();
    let err = (0..2000)
        .map(|i| {
            let t = i as f64 / 2000.0;
            ((basis.eval(p.as_slice(), t) - exact(t)) / exact(t)).abs()
        })
        .fold(0.0, f64::max);
    (err, (pstar - 1.0).abs())
}

#[test]
fn frictionless_punch() {
    let (err, dp) = punch(3, 12);
    eprintln!("punch: relative error of p {err:.1e}, |P* - 1| = {dp:.1e}");
    assert!(err <= 1e-12, "relative error of p {err:e}");
    assert!(dp <= 1e-12, "P* - 1 = {dp:e}");
}

#[test]
fn punch_converges_under_refinement() {
    let errs: Vec<(f64, f64)> = [2, 3, 4, 6, 8].iter().map(|&n| punch(1, n)).collect();
    eprintln!("punch (p error, P* error) for 2,3,4,6,8 nodes: {errs:?}");
    for w in errs.windows(2) {
        assert!(w[1].0 < 0.5 * w[0].0, "p errors do not decrease: {errs:?}");
        assert!(w[1].1 < 0.5 * w[0].1, "P* errors do not decrease: {errs:?}");
    }
}

#[test]
fn singular_systems_are_errors() {
    // The zero operator, and κ1 collocated twice at the same points.
    let basis = PanelBasis::new(&Mesh::uniform(0.0, 1.0, 2).unwrap(), &[4, 4], vec![]).unwrap();
    let asm = Assembler::new(&basis).unwrap();
    let x = basis.nodes();
    let z = asm.matrix(&Operator::zero(), &x).unwrap();
    assert!(matches!(
        CheckedLu::new(&z, 1e13),
        Err(NumericError::Singular(_))
    ));
    let mut pts = x.clone();
    pts[1] = pts[0];
    let a = asm.matrix(&kappa(1, 0.0), &pts).unwrap();
    assert!(CheckedLu::new(&a, 1e13).is_err());
    // Commutative model of a system whose blocks make K4K1 - K2K3 = 0.
    let k1 = asm.matrix(&kappa(1, 0.0), &x).unwrap();
    let g = DVector::from_element(x.len(), 1.0);
    let s = System2 {
        k11: &k1,
        k12: &k1,
        k21: &k1,
        k22: &k1,
        g1: &g,
        g2: &g,
    };
    assert!(solve_coupled(&s, 1e13).is_err());
    assert!(solve_commutative(&s, &basis, 1e13).is_err());
}

#[test]
fn manufactured_case_converges_with_piecewise_constants() {
    // With one node per panel q = x is not in the trial space, so the
    // coupled solve has a genuine discretisation error; it must fall as the
    // panels are halved.
    let mut errs = Vec::new();
    for panels in [4, 8, 16, 32, 64] {
        let m = mms(0.5, panels, 1);
        let x = m.basis.nodes();
        let s = System2 {
            k11: &m.k[0],
            k12: &m.k[1],
            k21: &m.k[2],
            k22: &m.k[3],
            g1: &m.g1,
            g2: &m.g2,
        };
        let c = solve_coupled(&s, 1e13).unwrap();
        errs.push(max_dev(&c.p, |_| 1.0).max(max_dev(&c.q, |i| x[i])));
    }
    eprintln!("piecewise-constant manufactured errors (4..64 panels): {errs:?}");
    for w in errs.windows(2) {
        assert!(w[1] < 0.8 * w[0], "errors do not fall: {errs:?}");
    }
}
