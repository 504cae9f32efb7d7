//! Times the phases of a Smith decomposition over Q[x] on a random n×n
//! matrix of degree d (integer coefficients in [-9, 9], like
//! `smith_peers.py`): D alone by elimination, the full decomposition (the
//! nonsingular path when it applies), the certificate, and printing.
//!
//! `cargo run --release --example smith_phases -- 10 2`
use lambdamat::algebra::{
    matrix::Matrix,
    qx::{QPoly, QxRing},
    rational::{Rationals, qi},
    smith::{modes::decompose_qx, smith_form},
    upoly::UPolyRing,
};
use std::time::Instant;

fn main() {
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|s| s.parse().ok())
        .collect();
    let (n, d) = match args.as_slice() {
        [n, d, ..] => (*n, *d),
        _ => (10, 2),
    };
    let mut seed: u64 = 12345;
    let mut rnd = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % 19) as i64 - 9
    };
    let r0 = UPolyRing::new(Rationals, "x");
    let data: Vec<QPoly> = (0..n * n)
        .map(|_| QPoly::from_upoly(&r0.trim((0..=d).map(|_| qi(rnd())).collect())))
        .collect();
    let a = Matrix::new(QxRing::new("x"), n, n, data);
    let t = Instant::now();
    let dd = smith_form(&a);
    println!("D alone by elimination: {:?}", t.elapsed());
    let t = Instant::now();
    let (s, alg) = decompose_qx(&a);
    println!("U, D, V ({alg}): {:?}", t.elapsed());
    let t = Instant::now();
    let c = s.certify(&a);
    println!("certificate: {:?}, verified {}", t.elapsed(), c.verified());
    let t = Instant::now();
    let widest = [&s.u, &s.v]
        .iter()
        .flat_map(|m| m.format_rows().into_iter().flatten())
        .map(|e| e.len())
        .max()
        .unwrap_or(0);
    println!(
        "printing U and V: {:?} (widest entry {widest} characters)",
        t.elapsed()
    );
    assert_eq!(dd.diagonal(), s.d.diagonal(), "both paths give the same D");
}
