use lambdamat::algebra::smith::modes::{SmithOptions, smith_report};
use lambdamat::algebra::{matrix::Matrix, mpoly::MPoly, polyring::PolyRing, rational::qi};
fn main() {
    let mut seed: u64 = 99;
    let mut rnd = |m: u64| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed % m
    };
    for case in 0..12 {
        let nv = 3;
        let n = 3;
        let names: Vec<String> = (1..=nv).map(|i| format!("s{i}")).collect();
        let data: Vec<MPoly> = (0..n * n)
            .map(|_| {
                let k = rnd(4) as usize;
                MPoly::from_terms(
                    nv,
                    (0..k).map(|_| {
                        (
                            (0..nv).map(|_| rnd(2) as u32).collect(),
                            qi(rnd(7) as i64 - 3),
                        )
                    }),
                )
            })
            .collect();
        let a = Matrix::new(PolyRing::new(names), n, n, data);
        let t = std::time::Instant::now();
        let r1 = smith_report("A", &a, &SmithOptions::default()).unwrap();
        let t1 = t.elapsed();
        let t = std::time::Instant::now();
        let r2 = smith_report(
            "A",
            &a,
            &SmithOptions {
                principal: Some(2),
                latex: false,
            },
        )
        .unwrap();
        let t2 = t.elapsed();
        println!(
            "case {case}: divisors {t1:?} principal {t2:?} inv {:?} / {:?}",
            r1.invariant_factors,
            r2.invariant_factors
                .iter()
                .map(|s| s.len())
                .collect::<Vec<_>>()
        );
    }
}
