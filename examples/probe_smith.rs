use lambdamat::algebra::{
    matrix::Matrix,
    qx::{QPoly, QxRing},
    rational::{Rationals, qi},
    ring::Ring,
    upoly::UPolyRing,
};
fn main() {
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .map(|s| s.parse().unwrap())
        .collect();
    let (n, d) = (args[0], args[1]);
    let mut seed: u64 = 12345;
    let mut rnd = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % 19) as i64 - 9
    };
    let r0 = UPolyRing::new(Rationals, "x");
    let data: Vec<_> = (0..n * n)
        .map(|_| QPoly::from_upoly(&r0.trim((0..=d).map(|_| qi(rnd())).collect())))
        .collect();
    let a = Matrix::new(QxRing::new("x"), n, n, data);
    let t0 = std::time::Instant::now();
    let dd = lambdamat::algebra::smith::smith_form(&a);
    println!(
        "D only {:?} {:?}",
        t0.elapsed(),
        dd.diagonal().iter().map(|f| f.degree()).collect::<Vec<_>>()
    );
    if args.len() > 2 {
        return;
    }
    let t = std::time::Instant::now();
    let (s, alg) = lambdamat::algebra::smith::modes::decompose_qx(&a);
    println!("{alg}");
    let t1 = t.elapsed();
    let c = s.certify(&a);
    let t2 = t.elapsed();
    let t3 = std::time::Instant::now();
    let maxlen =
        s.u.format_rows()
            .iter()
            .flatten()
            .map(|x| x.len())
            .max()
            .unwrap();
    let vlen =
        s.v.format_rows()
            .iter()
            .flatten()
            .map(|x| x.len())
            .max()
            .unwrap();
    println!(
        "smith {:?} certify {:?} format {:?} verified {} inv {:?} maxU {} maxV {}",
        t1,
        t2 - t1,
        t3.elapsed(),
        c.verified(),
        s.invariant_factors()
            .iter()
            .map(|f| f.degree())
            .collect::<Vec<_>>(),
        maxlen,
        vlen
    );
    let _ = a.ring.name();
}
#[allow(dead_code)]
fn d_only() {}
