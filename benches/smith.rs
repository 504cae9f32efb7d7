//! Criterion benchmarks of the Smith engine: the peer matrices of
//! `../shared/bench/smith_peers.py` (random over Q[x], transforms and
//! certificate included) and the seed λ-matrix in its two multivariate
//! modes, and the issue-15 group (`smith_scale`: modular gcd, the modular
//! Q[x] path, the principal 4×4 that used to stall). Ratios against PARI/GP and SymPy are measured by `benches/peers.sh`.

use criterion::{Criterion, criterion_group, criterion_main};
use lambdamat::algebra::matrix::Matrix;
use lambdamat::algebra::modgcd;
use lambdamat::algebra::mpoly::MPoly;
use lambdamat::algebra::polyring::PolyRing;
use lambdamat::algebra::rational::Q;
use lambdamat::algebra::smith::modes::{SmithOptions, smith_report};
use lambdamat::lang::parse_program;
use std::hint::black_box;
use std::time::Duration;

fn first_matrix(path: &str) -> Matrix<PolyRing> {
    let src = std::fs::read_to_string(path).expect("bench data");
    let p = parse_program(&src, path).expect("valid bench data");
    let m = &p.matrices[0];
    Matrix::new(
        PolyRing::new(p.symbols.clone()),
        m.rows,
        m.cols,
        m.entries.clone(),
    )
}

fn peers(c: &mut Criterion) {
    let mut g = c.benchmark_group("smith_qx");
    g.sample_size(10);
    for case in ["10_2_1", "8_4_1", "12_3_1"] {
        let a = first_matrix(&format!("benches/data/peers_{case}.lmx"));
        g.bench_function(case, |b| {
            b.iter(|| {
                smith_report("A", black_box(&a), &SmithOptions::default()).expect("certified")
            })
        });
    }
    g.finish();
}

fn seed(c: &mut Criterion) {
    let a = first_matrix("examples/seed_lambda.lmx");
    let mut g = c.benchmark_group("smith_seed");
    g.bench_function("determinantal_divisors", |b| {
        b.iter(|| smith_report("A", black_box(&a), &SmithOptions::default()).expect("certified"))
    });
    let opts = SmithOptions {
        principal: Some(3),
        ..SmithOptions::default()
    };
    g.bench_function("principal_k4", |b| {
        b.iter(|| smith_report("A", black_box(&a), &opts).expect("certified"))
    });
    g.finish();
}

/// The algorithms of issue 15: Brown's modular gcd, the modular inverse
/// over Q[x], and the two inputs that used to stall.
fn scale(c: &mut Criterion) {
    let mut g = c.benchmark_group("smith_scale");
    g.sample_size(10);
    let a = first_matrix("benches/data/issue15_principal_k2.lmx");
    let opts = SmithOptions {
        principal: Some(1),
        ..SmithOptions::default()
    };
    g.bench_function("principal_k2_4x4", |b| {
        b.iter(|| smith_report("A", black_box(&a), &opts).expect("certified"))
    });
    let a = first_matrix("benches/data/peers_2_150_1.lmx");
    g.bench_function("qx_2x2_deg150", |b| {
        b.iter(|| smith_report("A", black_box(&a), &SmithOptions::default()).expect("certified"))
    });
    // gcd of (g·p, g·q) in three symbols with g, p, q dense of degree 3.
    let n = 3;
    let v: Vec<MPoly> = (0..n).map(|i| MPoly::var(i, n)).collect();
    let one = MPoly::one(n);
    let dense = |s: i64| {
        let mut acc = MPoly::zero(n);
        for (k, x) in v.iter().enumerate() {
            let c = MPoly::constant(Q::from_integer((s + k as i64).into()), n);
            acc = acc + &c * &x.pow(3) + x * &v[(k + 1) % n] + one.clone();
        }
        acc
    };
    let (gg, p, q) = (dense(2), dense(5), dense(-7));
    let (x, y) = (&gg * &p, &gg * &q);
    g.bench_function("brown_gcd_3vars", |b| {
        b.iter(|| modgcd::mpoly_gcd(black_box(&x), black_box(&y)).expect("gcd"))
    });
    g.finish();
}

/// The large one-symbol shapes of issue 15: a 200×200 constant matrix
/// (det/adj mod primes, U = I/det, V = adj, certified), a 200×200 diagonal
/// and a 50×50 of degree 1 (invariant factors certified without
/// transforms); B·diag·C with two (12×12) and three (16×16 with
/// transforms, 32×32 without) non-trivial factors; a 2×2 of degree 500
/// (Bezout route, against PARI's 3.0 s) and a 64×64 of degree 1 (D only).
fn large(c: &mut Criterion) {
    let mut g = c.benchmark_group("smith_large");
    g.sample_size(10);
    for case in [
        "const_200",
        "diag_200",
        "qx_50x50_deg1",
        "bdc_12",
        "bdc3_16",
        "bdc3_32",
        "qx_2x2_deg500",
        "qx_64x64_deg1",
    ] {
        let a = first_matrix(&format!("benches/data/issue15_{case}.lmx"));
        g.bench_function(case, |b| {
            b.iter(|| {
                smith_report("A", black_box(&a), &SmithOptions::default()).expect("certified")
            })
        });
    }
    g.finish();
}

/// The small end of issue 15's grid (n ≤ 12, one symbol, with transforms
/// and certificate): dense 8×8 and 12×12 of degree 1 (the nonsingular path,
/// certified from degrees) and an 8×8 B·diag(1, …, x − 1, (x − 1)(x + 2),
/// (x − 1)(x + 2)x)·C (the trailing Hermite route).
fn small(c: &mut Criterion) {
    let mut g = c.benchmark_group("smith_small");
    g.sample_size(20);
    for case in ["dense_8_1", "dense_12_1", "bdc3_8_1"] {
        let a = first_matrix(&format!("benches/data/small_{case}.lmx"));
        g.bench_function(case, |b| {
            b.iter(|| {
                smith_report("A", black_box(&a), &SmithOptions::default()).expect("certified")
            })
        });
    }
    g.finish();
}

/// Process CPU time (`CLOCK_PROCESS_CPUTIME_ID`): on a shared machine
/// the wall time of a millisecond-long call measures the load, not the
/// code.
fn process_cpu() -> Duration {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `t` is a valid, writable timespec for the call's duration.
    let rc = unsafe { libc::clock_gettime(libc::CLOCK_PROCESS_CPUTIME_ID, &mut t) };
    assert_eq!(rc, 0, "clock_gettime(CLOCK_PROCESS_CPUTIME_ID)");
    Duration::new(t.tv_sec as u64, t.tv_nsec as u32)
}

/// Process CPU time of `iters` certified Smith reports of `a`.
fn cpu_time_of(iters: u64, a: &Matrix<PolyRing>) -> Duration {
    let t0 = process_cpu();
    for _ in 0..iters {
        black_box(smith_report("A", black_box(a), &SmithOptions::default()).expect("certified"));
    }
    process_cpu() - t0
}

/// Issue 15's goal at the small end, in CPU time: `smith_report` from the
/// parsed matrix to the certified report (transforms, certificate and
/// printed rows included; parsing and process start excluded) on the
/// grid's dense 8×8 of degree 1, 2, 3 and 12×12 of degree 1
/// (`benches/peers_grid.py`'s `build("dense", n, d, 1)`). Criterion's
/// "time" here is process CPU time per call. PARI's `matsnf(M,3)` on the
/// same matrices took 6.8, 32, 121 and 126 ms (its own timer, in-process),
/// so 10× PARI means ≤ 0.68, 3.2, 12 and 12.6 ms.
/// `cargo bench --bench smith -- smith_small_cpu`.
fn small_cpu(c: &mut Criterion) {
    let mut g = c.benchmark_group("smith_small_cpu");
    g.sample_size(20);
    for case in ["dense_8_1", "dense_8_2", "dense_8_3", "dense_12_1"] {
        let a = first_matrix(&format!("benches/data/small_{case}.lmx"));
        g.bench_function(case, |b| b.iter_custom(|iters| cpu_time_of(iters, &a)));
    }
    g.finish();
}

/// The trailing Hermite route at 8×8 (issue 15's B·diag(chain)·C grid,
/// `benches/peers_grid.py build`, seed 1): two factors (x − 1,
/// (x − 1)(x + 2)) and three (…, (x − 1)(x + 2)x), B of degree 1–3, with
/// transforms and the certificate, as `lambdamat smith` runs them.
/// Criterion's "time" here is process CPU time per call, as in
/// `smith_small_cpu`. `cargo bench --bench smith -- smith_trailing_8`.
fn trailing(c: &mut Criterion) {
    let mut g = c.benchmark_group("smith_trailing_8");
    g.sample_size(20);
    for shape in ["bdc2", "bdc3"] {
        for d in 1..=3 {
            let case = format!("{shape}_8_{d}");
            let a = first_matrix(&format!("benches/data/trailing_{case}.lmx"));
            g.bench_function(&case, |b| b.iter_custom(|iters| cpu_time_of(iters, &a)));
        }
    }
    g.finish();
}

/// Issue 29's stall families over Q[x] (`benches/stall_families.py`
/// writes them; `benches/data/issue29_*.lmx`), those answered within a few
/// seconds: the non-square diagonals (monomial route), the rank-deficient
/// and rectangular inputs (unit-factor rank certificate), the sparse ones
/// (Hermite certificate with the local pivots moved last) and the 2×2 with
/// one huge coefficient (D alone from the adjugate), and the 4×4 of
/// 45-digit rationals (integer Hermite route on up to 4 096 word primes,
/// with U and V; product-tree CRT), the 6×6 of 60-digit rationals (D alone:
/// U's rows would need more primes than that). Criterion's "time" is
/// process CPU time per call. `cargo bench --bench smith -- smith_stall`.
fn stall(c: &mut Criterion) {
    let mut g = c.benchmark_group("smith_stall");
    g.sample_size(10);
    for case in [
        "diag_39x40",
        "diag_40x41",
        "rankdef_12_d2",
        "rankdef_16_d1",
        "rect_13x10_d2",
        "rect_16x19_d2",
        "sparse_sing_17",
        "sparse_24_e24",
        "bigc_2_d50",
        "bigq_4_d2",
        "bigq_6_d2",
    ] {
        let a = first_matrix(&format!("benches/data/issue29_{case}.lmx"));
        g.bench_function(case, |b| b.iter_custom(|iters| cpu_time_of(iters, &a)));
    }
    g.finish();
}

criterion_group!(
    benches, peers, seed, scale, large, small, small_cpu, trailing, stall
);
criterion_main!(benches);
