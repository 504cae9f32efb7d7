//! Measures the pointwise error estimates of the Hertz front's fields
//! (p, q, μp, u at the profile points, and the shear jump and E2 residual
//! at c) against a much finer solve of the same file, and optionally the
//! hand-written oracle (`src/hertz/`, tight tolerance).
//!
//! ```text
//! cargo run --release --example field_errors -- NU mu|c VALUE [TOL] [REF_TOL] [REF_LEVEL]
//! ```
//! Prints, per field, the largest true error, the largest estimate, the
//! largest ratio true/estimate and how many points have true > estimate.
use lambdamat::hertz::front::{Given, Sample, profile_points, solve};
#[path = "../tests/common/hertz_oracle/mod.rs"]
mod hertz_oracle;
use hertz_oracle::{HertzOptions, solve_given_c, solve_given_mu};
use lambdamat::plan::SplitOptions;

/// A field of a sample and its estimate.
type Field = fn(&Sample) -> (f64, f64);

fn main() {
    if let Err(e) = run() {
        eprintln!("field_errors: {e}");
        std::process::exit(3);
    }
}

fn run() -> Result<(), String> {
    let a: Vec<String> = std::env::args().skip(1).collect();
    let num = |i: usize, d: f64| a.get(i).and_then(|s| s.parse().ok()).unwrap_or(d);
    let nu = num(0, 0.25);
    let value = num(2, 0.1801);
    let given = if a.get(1).map(String::as_str) == Some("c") {
        Given::C(value)
    } else {
        Given::Mu(value)
    };
    let tol = num(3, 1e-10);
    let ref_tol = num(4, 1e-13);
    let ref_level = num(5, 10.0) as usize;
    let t0 = std::time::Instant::now();
    let s = solve(
        nu,
        given,
        &SplitOptions {
            tol,
            max_level: 7,
            ..SplitOptions::default()
        },
    )
    .map_err(|e| e.to_string())?;
    let t_solve = t0.elapsed().as_secs_f64();
    let r = solve(
        nu,
        given,
        &SplitOptions {
            tol: ref_tol,
            max_level: ref_level,
            ..SplitOptions::default()
        },
    );
    let r = r.map_err(|e| format!("reference: {e}"))?;
    println!(
        "ν = {nu}, {given:?}: c = {:.15} ± {:.1e} ({} levels), reference c = {:.15} ± {:.1e} ({} levels, converged {})",
        s.c, s.error_estimate, s.levels, r.c, r.error_estimate, r.levels, r.converged
    );
    let c = s.c;
    let xs = profile_points(c, 200);
    let t1 = std::time::Instant::now();
    let ours = s.sample(&xs).map_err(|e| e.to_string())?;
    let t_sample = t1.elapsed().as_secs_f64();
    let refs = r.sample(&xs).map_err(|e| e.to_string())?;
    println!(
        "solve {t_solve:.3} s wall, sampling {} points {t_sample:.3} s wall",
        xs.len()
    );
    let fields: [(&str, Field); 4] = [
        ("p", |s| (s.p, s.p_err)),
        ("q", |s| (s.q, s.q_err)),
        ("mu_p", |s| (s.mu_p, s.mu_p_err)),
        ("u", |s| (s.u, s.u_err)),
    ];
    println!("field  max|true|   max est    max true/est  violations  (worst-ratio point)");
    for (name, get) in fields {
        let (mut t_max, mut e_max, mut ratio, mut viol, mut at) = (0.0f64, 0.0f64, 0.0f64, 0, 0.0);
        for (o, f) in ours.iter().zip(&refs) {
            // The reference's own uncertainty is added to the truth's
            // tolerance: a "violation" must exceed it.
            let (v, e) = get(o);
            let (tv, te) = get(f);
            let t = (v - tv).abs();
            t_max = t_max.max(t);
            e_max = e_max.max(e);
            let rr = if t == 0.0 { 0.0 } else { t / e };
            if rr > ratio {
                ratio = rr;
                at = o.x;
            }
            if t > e + te {
                viol += 1;
            }
            if a.iter().any(|x| x == "--points") && t > 0.5 * e {
                println!(
                    "  {name} x {:.12}  value {v:.6e}  true {t:.2e}  est {e:.2e}  ref est {te:.1e}",
                    o.x
                );
            }
        }
        println!("{name:5}  {t_max:9.2e}  {e_max:9.2e}  {ratio:12.3e}  {viol:10}  x = {at:.6}");
    }
    let fe = &s.field_error_estimates;
    println!(
        "shear jump at c: {:.3e} ± {:.1e} (reference {:.3e}); E2 residual at c ÷ c: {:.3e} ± {:.1e} (reference {:.3e})",
        s.shear_jump_at_c,
        fe["shear_jump_at_c"],
        r.shear_jump_at_c,
        s.residual_c,
        fe["residual_c"],
        r.residual_c
    );
    if a.iter().any(|x| x == "--oracle") {
        let o = HertzOptions {
            tol: 1e-12,
            max_level: 10,
        };
        let os = match given {
            Given::Mu(mu) => solve_given_mu(nu, mu, &o),
            Given::C(c) => solve_given_c(nu, c, &o),
        };
        let os = match os {
            Ok(os) => os,
            Err(e) => {
                println!("oracle refused: {e}");
                return Ok(());
            }
        };
        let xs: Vec<f64> = xs.into_iter().filter(|&x| x <= 0.99).collect();
        let ours = s.sample(&xs).map_err(|e| e.to_string())?;
        let theirs = os.sample(&xs).map_err(|e| e.to_string())?;
        let (mut worst, mut viol) = (0.0f64, 0);
        for (a, b) in ours.iter().zip(&theirs) {
            for (v, e, t) in [
                (a.p, a.p_err, b.p),
                (a.q, a.q_err, b.q),
                (a.u, a.u_err, b.u),
            ] {
                worst = worst.max((v - t).abs() / e.max(1e-300));
                if (v - t).abs() > e {
                    viol += 1;
                }
            }
        }
        println!(
            "oracle (tol 1e-12, x ≤ 0.99): c {:.15}, largest true/est {worst:.3e}, violations {viol}",
            os.c
        );
    }
    Ok(())
}
