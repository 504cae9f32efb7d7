//! Diagnostic (issue 13, ν = 0.4 at large μ): over the sweep's grid
//! (`hertz sweep --nu -0.9:0.5:15 --mu log:0.01:100:13`), the values at c
//! whose continuum value is 0 (the shear jump q(c⁻) − μp(c) and E2's
//! residual at c) against their estimates, and whether the panels beside
//! c were refined on the last two levels (`UnrefinedAtC`).
//!
//! `cargo run --release --example nearone_probe [tol]`
use lambdamat::hertz::front::{Given, solve_with_limit};
use lambdamat::plan::SplitOptions;

fn main() {
    let tol: f64 = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1e-10);
    let opts = SplitOptions {
        tol,
        ..SplitOptions::default()
    };
    let (mut bad, mut flagged, mut solved) = (0, 0, 0);
    for i in 0..15 {
        let nu = -0.9 + 0.1 * i as f64;
        let nu = (nu * 10.0).round() / 10.0;
        for j in 0..13 {
            let mu = 10f64.powf(-2.0 + 4.0 * j as f64 / 12.0);
            let mu = format!("{mu:.3}").parse::<f64>().unwrap_or(mu);
            let t = std::time::Instant::now();
            match solve_with_limit(nu, Given::Mu(mu), &opts) {
                Ok(s) => {
                    solved += 1;
                    let ej = s.field_error_estimates.get("shear_jump_at_c").copied();
                    let er = s.field_error_estimates.get("residual_c").copied();
                    let over = |v: f64, e: Option<f64>| e.is_some_and(|e| v.abs() > e);
                    let flag = s.unrefined_at_c.is_some();
                    flagged += usize::from(flag);
                    let b = over(s.shear_jump_at_c, ej) || over(s.residual_c, er);
                    bad += usize::from(b);
                    println!(
                        "{nu:5} {mu:8.4} c={:.13} jump={:+.2e}±{:.1e} R={:+.2e}±{:.1e} {}{} {:.2}s",
                        s.c,
                        s.shear_jump_at_c,
                        ej.unwrap_or(f64::NAN),
                        s.residual_c,
                        er.unwrap_or(f64::NAN),
                        if flag { "UNREFINED " } else { "" },
                        if b { "VALUE>EST" } else { "" },
                        t.elapsed().as_secs_f64()
                    );
                }
                Err(r) => {
                    let e = r.error.to_string();
                    println!("{nu:5} {mu:8.4} refused: {}", &e[..e.len().min(200)]);
                }
            }
        }
    }
    println!("solved {solved}, unrefined at c {flagged}, |value| > estimate at c {bad}");
}
