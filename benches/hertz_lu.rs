//! A Hertz point's cost in LU factorisations: every (ν, μ) point of the
//! issue's grid is solved by the front at tol 1e-10, and its time is
//! divided by the time of one dense LU of a 501 × 501 matrix (the blocked
//! `getrf`-order factorisation the solver itself uses) measured in the
//! same run, and by one LU of the point's finest size. Prints a table per
//! point and the median and worst ratios; wall and CPU time both, since
//! assembly runs on every core. The LU reference is timed again before
//! every point, and the median of all those timings is the unit, so a
//! drift of the machine's speed during the run moves both sides. Run:
//! `cargo bench --bench hertz_lu` (`HERTZ_LU_QUICK=1`: three ν and three
//! μ only; `HERTZ_LU_NU=-0.9,0 HERTZ_LU_MU=0.1`: these points only).
use std::time::Instant;

use lambdamat::hertz::front::{Given, solve};
use lambdamat::numeric::lu::DenseLu;
use lambdamat::plan::SplitOptions;
use nalgebra::DMatrix;

/// CPU seconds of this process so far (user + system).
fn cpu_seconds() -> f64 {
    let mut u = std::mem::MaybeUninit::<libc::rusage>::uninit();
    // SAFETY: getrusage writes the whole struct for RUSAGE_SELF.
    let u = unsafe {
        libc::getrusage(libc::RUSAGE_SELF, u.as_mut_ptr());
        u.assume_init()
    };
    let t = |v: libc::timeval| v.tv_sec as f64 + v.tv_usec as f64 * 1e-6;
    t(u.ru_utime) + t(u.ru_stime)
}

/// Wall and CPU seconds of `f`.
fn timed<T>(f: impl FnOnce() -> T) -> (T, f64, f64) {
    let (w, c) = (Instant::now(), cpu_seconds());
    let out = f();
    (out, w.elapsed().as_secs_f64(), cpu_seconds() - c)
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// A well-conditioned (diagonally dominant) seeded random `n × n` matrix.
fn reference_matrix(n: usize) -> DMatrix<f64> {
    let mut state = 0x5eed_u64 ^ n as u64;
    let mut next = move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    DMatrix::from_fn(n, n, |i, j| next() + if i == j { n as f64 } else { 0.0 })
}

/// Median wall and CPU seconds of an LU of [`reference_matrix`]`(n)` (7
/// factorisations; the copies are made outside the clock).
fn lu_seconds(n: usize) -> (f64, f64) {
    let a = reference_matrix(n);
    let (mut w, mut c) = (Vec::new(), Vec::new());
    for _ in 0..7 {
        let m = a.clone();
        let (lu, tw, tc) = timed(|| DenseLu::new(m));
        assert_eq!(
            lu.expect("a diagonally dominant matrix factorises").size(),
            n
        );
        w.push(tw);
        c.push(tc);
    }
    (median(w), median(c))
}

fn main() {
    // `cargo bench` passes `--bench`; a filter or `--list` from a harness
    // run over every target has nothing to select here.
    if std::env::args().any(|a| a == "--list") {
        return;
    }
    let list = |var: &str, quick: &[f64], full: &[f64]| -> Vec<f64> {
        match std::env::var(var) {
            Ok(v) => v
                .split(',')
                .map(|x| x.trim().parse().expect("a comma-separated list of numbers"))
                .collect(),
            Err(_) if std::env::var_os("HERTZ_LU_QUICK").is_some() => quick.to_vec(),
            Err(_) => full.to_vec(),
        }
    };
    let nus = list(
        "HERTZ_LU_NU",
        &[-0.5, 0.0, 0.3],
        &[-0.9, -0.5, 0.0, 0.1, 0.25, 0.3, 0.4],
    );
    let mus = list(
        "HERTZ_LU_MU",
        &[0.1, 1.0, 10.0],
        &[0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0],
    );
    let opts = SplitOptions::default();
    let reference = reference_matrix(501);
    let lu_once = || {
        let m = reference.clone();
        let (lu, w, c) = timed(|| DenseLu::new(m));
        assert!(lu.is_ok(), "a diagonally dominant matrix factorises");
        (w, c)
    };
    let (mut ref_w, mut ref_c) = (Vec::new(), Vec::new());
    for _ in 0..7 {
        let (w, c) = lu_once();
        ref_w.push(w);
        ref_c.push(c);
    }
    let mut finest_lu = std::collections::BTreeMap::new();
    let mut rows = Vec::new();
    for &nu in &nus {
        for &mu in &mus {
            let (w, c) = lu_once();
            ref_w.push(w);
            ref_c.push(c);
            let (r, w, c) = timed(|| solve(nu, Given::Mu(mu), &opts));
            let r = match r {
                Ok(r) => r,
                Err(e) => {
                    println!("{nu:>5} {mu:>5} failed: {e}");
                    continue;
                }
            };
            let n = r.unknowns;
            let (fw, _) = *finest_lu.entry(n).or_insert_with(|| lu_seconds(n));
            rows.push((nu, mu, r.c, r.levels, n, r.converged, w, c, fw));
        }
    }
    let (lu_w, lu_c) = (median(ref_w), median(ref_c));
    println!(
        "LU 501×501 (median of {} timings through the run): wall {:.2} ms, CPU {:.2} ms",
        7 + nus.len() * mus.len(),
        lu_w * 1e3,
        lu_c * 1e3
    );
    println!(
        "{:>5} {:>5} {:>9} {:>7} {:>6} {:>6} {:>8} {:>8} {:>8} {:>10}",
        "nu", "mu", "c", "levels", "size", "exit", "wall s", "LU501 w", "LU501 c", "LU finest"
    );
    let (mut by_wall, mut by_cpu, mut by_finest) = (Vec::new(), Vec::new(), Vec::new());
    for (nu, mu, c_stick, levels, n, converged, w, c, fw) in rows {
        let (rw, rc, rf) = (w / lu_w, c / lu_c, w / fw);
        println!(
            "{nu:>5} {mu:>5} {c_stick:>9.6} {levels:>7} {n:>6} {:>6} {w:>8.3} {rw:>8.1} {rc:>8.1} {rf:>10.1}",
            if converged { 0 } else { 4 },
        );
        by_wall.push(rw);
        by_cpu.push(rc);
        by_finest.push(rf);
    }
    let worst = |v: &[f64]| v.iter().copied().fold(0.0, f64::max);
    println!(
        "points {}; LU-501 equivalents (wall): median {:.1}, worst {:.1}; (CPU): median {:.1}, worst {:.1}; LUs of the finest size (wall): median {:.1}, worst {:.1}",
        by_wall.len(),
        median(by_wall.clone()),
        worst(&by_wall),
        median(by_cpu.clone()),
        worst(&by_cpu),
        median(by_finest.clone()),
        worst(&by_finest)
    );
}
