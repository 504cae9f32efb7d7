//! Measures the refinement ladder of the split solver on the Hertz file at
//! a fixed stick radius: per level of `SplitLevel::level` (optionally
//! varied), the errors of the outputs P and P_shear and of the condition
//! coefficient B against a finer discretisation at the same `(ν, μ, c)`,
//! and `dc ≈ −ΔB/(dB/dc)`, the error of c that ΔB implies. It found the
//! parity effect of the degree cap at c → 1 (issue 13's hand-over note:
//! with one node more per level the error of P alternates in size
//! between levels, so the honest estimate needed extra levels; the
//! default ladder now steps the cap by two, so `nmax2` and `layers3` are
//! the default and `nmax+1` shows the old parity).
//!
//! ```text
//! cargo run --release --example ladder_probe -- NU MU C [VARIANT]
//! ```
//! `C` should be the converged stick radius of `(ν, μ)` (for example from
//! `lambdamat hertz --nu NU --mu MU --tol 1e-13`). `VARIANT` is a
//! comma-separated list of changes to every level: `nmax+1`, `nmax-1`
//! (the degree cap), `layers+1`, `layers-1`, `nmax2` (cap `7 + 2k`),
//! `layers3` (`6 + 3k` layers, at most 20).
use lambdamat::hertz::front::{GIVEN_MU, program};
use lambdamat::plan::SplitInput;
use lambdamat::plan::split::{SplitLevel, SplitProblem};

fn main() {
    if let Err(e) = run() {
        eprintln!("ladder_probe: {e}");
        std::process::exit(2);
    }
}

fn run() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let num = |i: usize| -> Result<f64, String> {
        args.get(i)
            .and_then(|s| s.parse().ok())
            .ok_or_else(|| "usage: ladder_probe NU MU C [VARIANT]".to_string())
    };
    let (nu, mu, c) = (num(0)?, num(1)?, num(2)?);
    let variant = args.get(3).cloned().unwrap_or_default();
    let prog = program(GIVEN_MU, &[("nu", nu), ("mu", mu)]).map_err(|e| e.to_string())?;
    let input = SplitInput::from_program(&prog).map_err(|e| e.to_string())?;
    let pb = SplitProblem::from_input(input).map_err(|e| e.to_string())?;
    let eval = |l: &SplitLevel, c: f64| -> Result<(f64, f64, f64, usize), String> {
        let d = pb.discretise(&[c], l).map_err(|e| e.to_string())?;
        let p = pb.output(&d, 0).map_err(|e| e.to_string())?;
        let ps = pb.output(&d, 1).map_err(|e| e.to_string())?;
        let b = pb.coefficient(&d, 0).ok_or("no coefficient B")?;
        Ok((p, ps, b, d.solution.len()))
    };
    let fine = SplitLevel {
        layers: 22,
        n_max: 25,
        ..SplitLevel::level(11)
    };
    let (p0, ps0, b0, _) = eval(&fine, c)?;
    let step = 1e-9 * (1.0 - c).min(c);
    let (_, _, b1, _) = eval(&fine, c + step)?;
    let dbdc = (b1 - b0) / step;
    println!("reference: P {p0:.16} P_shear {ps0:.16} B {b0:e} dB/dc {dbdc:e}");
    for k in 0..9 {
        let mut l = SplitLevel::level(k);
        for v in variant.split(',').filter(|v| !v.is_empty()) {
            match v {
                "nmax+1" => l.n_max += 1,
                "nmax-1" => l.n_max -= 1,
                "layers+1" => l.layers += 1,
                "layers-1" => l.layers -= 1,
                "nmax2" => l.n_max = 7 + 2 * k,
                "layers3" => l.layers = (6 + 3 * k).min(20),
                _ => return Err(format!("unknown variant {v}")),
            }
        }
        let (p, ps, b, n) = eval(&l, c)?;
        println!(
            "level {k} ({n:4} unknowns): P {:+.2e}  P_shear {:+.2e}  B {:+.2e}  c {:+.2e}",
            p - p0,
            ps - ps0,
            b - b0,
            -(b - b0) / dbdc
        );
    }
    Ok(())
}
