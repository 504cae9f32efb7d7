//! The stick radius `c` and the compliance factor `P*` of the Hertz problem
//! with finite friction against `μ`, through the language and its general
//! split-domain solver (`examples/hertz.lmx`, `plan::solve_split`): the
//! table of `docs/hertz_curves.md`, the sweep of the (ν, μ) plane and the
//! picture `docs/hertz_c_map.svg`. Owns only this driving and formatting;
//! every number comes from the library.
//!
//! ```text
//! cargo run --release --example hertz_curves -- table > docs/hertz_curves.md
//! cargo run --release --example hertz_curves -- sweep [n_nu] [n_mu]
//! cargo run --release --example hertz_curves -- svg docs/hertz_c_map.svg
//! cargo run --release --example hertz_curves -- point NU MU [TOL]
//! cargo run --release --example hertz_curves -- probe NU MU LEVEL C0 C1 N
//! ```
//!
//! `probe` prints the discrete condition `B(c)` on one refinement level at
//! `N` log-spaced stick radii (how its noise at small `c` was measured).
use std::time::Instant;

use lambdamat::lang::parse_program_with;
use lambdamat::lang::parser::parse_exact;
use lambdamat::plan::{SplitOptions, SplitReport, solve_split};

/// One solved point: `c`, `P*` with their estimates, and the wall time.
struct Point {
    c: f64,
    ce: f64,
    p: f64,
    pe: f64,
    converged: bool,
    secs: f64,
    /// At an end answer: the distance from the end within which the root
    /// lies (c bounded, not resolved), with the end.
    bounded: Option<(f64, f64)>,
}

/// The shortest decimal that reads back as `x` (Rust's `Display` for
/// `f64` never uses an exponent), exact for `--set`.
fn decimal(x: f64) -> String {
    x.to_string()
}

fn solve(src: &str, nu: f64, mu: f64, tol: f64) -> Result<Point, String> {
    let sets = [("nu", nu), ("mu", mu)]
        .iter()
        .map(|(n, v)| {
            parse_exact(&decimal(*v))
                .map(|q| (n.to_string(), q))
                .ok_or_else(|| format!("cannot read {v}"))
        })
        .collect::<Result<Vec<_>, String>>()?;
    let prog =
        parse_program_with(src, "examples/hertz.lmx", &sets).map_err(|e| format!("{e:?}"))?;
    let opts = SplitOptions {
        tol,
        ..SplitOptions::default()
    };
    let t = Instant::now();
    let r: SplitReport = solve_split(&prog, &opts).map_err(|e| e.to_string())?;
    let secs = t.elapsed().as_secs_f64();
    let get = |l: &[lambdamat::plan::split_solve::Estimate], n: &str| {
        l.iter()
            .find(|e| e.name == n)
            .map(|e| (e.value, e.error))
            .ok_or_else(|| format!("no {n}"))
    };
    let (c, ce) = get(&r.scalars, "c")?;
    let (p, pe) = get(&r.outputs, "P")?;
    Ok(Point {
        c,
        ce,
        p,
        pe,
        converged: r.converged,
        secs,
        bounded: r.end_answer.as_ref().map(|e| (e.end_value, e.distance)),
    })
}

/// `x` with ten significant digits.
fn ten_digits(x: f64) -> String {
    if x.abs() >= 1e-3 {
        let d = 9 - x.abs().log10().floor() as i32;
        format!("{x:.*}", d.max(0) as usize)
    } else {
        format!("{x:.9e}")
    }
}

/// A refusal for a table cell: the limit it names, else its last clause.
fn short(e: &str) -> String {
    if e.contains("closer to the end 1") {
        return "refused: 1 − c below about 1e-12 (the slip annulus is thinner than the solver resolves)"
            .into();
    }
    if e.contains("closer than") {
        return "refused: no admissible root resolved (c below 1e-10, the μ → 0 limit)".into();
    }
    let s: String = e.replace('|', "/");
    let n = s.chars().count();
    s.chars().skip(n.saturating_sub(160)).collect()
}

/// c against log10 μ, one line per ν.
fn plot(path: &str, curves: &[(f64, Vec<(f64, f64)>)]) -> Result<(), Box<dyn std::error::Error>> {
    use plotters::prelude::*;
    let root = SVGBackend::new(path, (900, 560)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "Stick radius c/a of the Hertz problem with friction (split solver, tol 1e-10)",
            ("sans-serif", 20),
        )
        .margin(16)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(-2f64..2f64, 0f64..1f64)?;
    chart
        .configure_mesh()
        .x_desc("friction coefficient μ (log scale)")
        .y_desc("c / a")
        .x_label_formatter(&|v| format!("{}", 10f64.powf(*v)))
        .draw()?;
    let colors = [
        BLUE,
        RED,
        GREEN,
        MAGENTA,
        CYAN,
        BLACK,
        RGBColor(200, 120, 0),
    ];
    for (i, (nu, pts)) in curves.iter().enumerate() {
        let color = colors[i % colors.len()];
        chart
            .draw_series(LineSeries::new(pts.clone(), color.stroke_width(2)))?
            .label(format!("ν = {nu}"))
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
            });
        chart.draw_series(
            pts.iter()
                .map(|&(x, y)| Circle::new((x, y), 2, color.filled())),
        )?;
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}

fn logspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| {
            let t = if n == 1 {
                0.0
            } else {
                i as f64 / (n - 1) as f64
            };
            (a.ln() + t * (b.ln() - a.ln())).exp()
        })
        .collect()
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let src = match std::fs::read_to_string("examples/hertz.lmx") {
        Ok(s) => s,
        Err(e) => {
            eprintln!("run from the repository root: {e}");
            std::process::exit(2);
        }
    };
    let mode = args.first().map(String::as_str).unwrap_or("sweep");
    let arg = |i: usize, d: f64| -> f64 { args.get(i).and_then(|s| s.parse().ok()).unwrap_or(d) };
    match mode {
        "point" => {
            let (nu, mu) = (arg(1, 0.0), arg(2, 0.3));
            let tol = arg(3, 1e-10);
            match solve(&src, nu, mu, tol) {
                Ok(p) => println!(
                    "nu={nu} mu={mu}: c = {:.15e} ± {:.1e}, 1-c = {:.6e}, P* = {:.15} ± {:.1e}, converged {}, {:.3} s",
                    p.c,
                    p.ce,
                    1.0 - p.c,
                    p.p,
                    p.pe,
                    p.converged,
                    p.secs
                ),
                Err(e) => println!("nu={nu} mu={mu}: refused: {e}"),
            }
        }
        "probe" => {
            // The condition B(c) on one level over a range of c.
            let (nu, mu, k) = (arg(1, 0.0), arg(2, 0.3), arg(3, 0.0) as usize);
            let (c0, c1, n) = (arg(4, 1e-9), arg(5, 1e-7), arg(6, 11.0) as usize);
            let sets = [("nu", nu), ("mu", mu)]
                .iter()
                .filter_map(|(n, v)| parse_exact(&decimal(*v)).map(|q| (n.to_string(), q)))
                .collect::<Vec<_>>();
            let Ok(prog) = parse_program_with(&src, "examples/hertz.lmx", &sets) else {
                std::process::exit(2);
            };
            let Ok(problem) = lambdamat::plan::split::SplitProblem::new(&prog) else {
                std::process::exit(2);
            };
            let lvl = lambdamat::plan::split::SplitLevel::level(k);
            for c in logspace(c0, c1, n) {
                match problem.discretise(&[c], &lvl) {
                    Ok(d) => println!(
                        "c = {c:.6e}: B = {:.6e}, dim {}, cond {:.2e}",
                        d.residuals[0],
                        d.solution.len(),
                        d.cond
                    ),
                    Err(e) => println!("c = {c:.6e}: {e}"),
                }
            }
        }
        "sweep" => {
            let nn = arg(1, 15.0) as usize;
            let nm = arg(2, 21.0) as usize;
            let tol = arg(3, 1e-10);
            let nus: Vec<f64> = (0..nn)
                .map(|i| -0.9 + 1.4 * i as f64 / (nn - 1).max(1) as f64)
                .collect();
            let mus = logspace(0.01, 100.0, nm);
            let (mut ok, mut total) = (0, 0);
            let mut worst_err = (0.0f64, 0.0, 0.0);
            let mut worst_time = (0.0f64, 0.0, 0.0);
            for &nu in &nus {
                for &mu in &mus {
                    total += 1;
                    match solve(&src, nu, mu, tol) {
                        Ok(p) => {
                            let e = p.ce.max(p.pe);
                            println!(
                                "{nu:8.4} {mu:10.4e} c={:.12e} ±{:.1e} 1-c={:.3e} P={:.12} ±{:.1e} {} {:.3}s",
                                p.c,
                                p.ce,
                                1.0 - p.c,
                                p.p,
                                p.pe,
                                if p.converged { "ok" } else { "NOT CONVERGED" },
                                p.secs
                            );
                            if p.converged {
                                ok += 1;
                            }
                            if e > worst_err.0 {
                                worst_err = (e, nu, mu);
                            }
                            if p.secs > worst_time.0 {
                                worst_time = (p.secs, nu, mu);
                            }
                        }
                        Err(e) => println!("{nu:8.4} {mu:10.4e} refused: {e}"),
                    }
                }
            }
            println!(
                "solved {ok} of {total}; worst estimate {:.1e} at (nu, mu) = ({}, {}); worst time {:.3} s at ({}, {})",
                worst_err.0, worst_err.1, worst_err.2, worst_time.0, worst_time.1, worst_time.2
            );
        }
        "table" => {
            let tol = arg(1, 1e-10);
            let nus = [-0.5, 0.0, 0.1, 0.2, 0.25, 0.3, 0.4, 0.45];
            let mus = [0.05, 0.1, 0.2, 0.3, 0.5, 1.0, 2.0, 5.0, 10.0, 100.0];
            println!("# c and P* of the Hertz problem with friction against μ\n");
            println!(
                "Generated by `cargo run --release --example hertz_curves -- table` \
                 (the split-domain solver on `examples/hertz.lmx`, tol {tol:e}). \
                 Each value is followed by its error estimate (distance between the \
                 last two refinement levels plus the root tolerance); it is absolute, \
                 so a small c (the μ → 0 end) is known to the relative accuracy \
                 estimate/c. A c marked bounded lies closer to an end than the \
                 solver resolves (an end answer, `src/plan/split_end.rs`): it is \
                 the middle of that gap, and P*'s estimate includes its variation \
                 over the gap. A refusal is printed with the limit it names. The \
                 limits are explained in `docs/hertz_asymptotics.md`.\n"
            );
            for nu in nus {
                println!("## ν = {nu}\n");
                println!("| μ | c | ± | P* | ± |");
                println!("|---|---|---|---|---|");
                for mu in mus {
                    match solve(&src, nu, mu, tol) {
                        Ok(p) if p.converged => println!(
                            "| {mu} | {}{} | {:.1e} | {:.12} | {:.1e} |",
                            ten_digits(p.c),
                            p.bounded.map_or(String::new(), |(end, d)| if end == 1.0 {
                                format!(" (bounded: 1 − c < {d:.1e})")
                            } else {
                                format!(" (bounded: c < {d:.2e})")
                            }),
                            p.ce,
                            p.p,
                            p.pe
                        ),
                        Ok(p) => println!(
                            "| {mu} | not converged: {} | {:.1e} | {:.12} | {:.1e} |",
                            ten_digits(p.c),
                            p.ce,
                            p.p,
                            p.pe
                        ),
                        Err(e) => println!("| {mu} | {} | | | |", short(&e)),
                    }
                }
                println!();
            }
            println!("## Literature beside it (ν = 0 and ν = 0.25)\n");
            println!(
                "| ν | μ | c/a, Spence (seed Table 1) | c/a, this solver | ± | Kalker's CONTACT |"
            );
            println!("|---|---|---|---|---|---|");
            for (nu, mu, spence, contact) in [
                (0.0, 0.2063, "0.24", ""),
                (
                    0.0,
                    0.2986,
                    "0.50",
                    "about 0.494 (its discretised validation run, as quoted in issue 13; not re-run here)",
                ),
                (0.0, 0.4013, "0.70", ""),
                (0.0, 0.4862, "0.80", ""),
                (0.25, 0.1387, "0.30", ""),
                (0.25, 0.1801, "0.50", ""),
                (0.25, 0.2843, "0.80", ""),
            ] {
                match solve(&src, nu, mu, tol) {
                    Ok(p) => println!(
                        "| {nu} | {mu} | {spence} | {} | {:.1e} | {contact} |",
                        ten_digits(p.c),
                        p.ce
                    ),
                    Err(e) => println!(
                        "| {nu} | {mu} | {spence} | refused: {} | | {contact} |",
                        short(&e)
                    ),
                }
            }
        }
        "svg" => {
            let path = args
                .get(1)
                .cloned()
                .unwrap_or("docs/hertz_c_map.svg".into());
            let n = arg(2, 17.0) as usize;
            let nus = [-0.9, -0.5, 0.0, 0.25, 0.4, 0.45, 0.49];
            let mus = logspace(0.01, 100.0, n);
            let mut curves = Vec::new();
            for nu in nus {
                let pts: Vec<(f64, f64)> = mus
                    .iter()
                    .filter_map(|&mu| match solve(&src, nu, mu, 1e-10) {
                        Ok(p) if p.converged => Some((mu.log10(), p.c)),
                        _ => None,
                    })
                    .collect();
                eprintln!("ν = {nu}: {} of {} points", pts.len(), mus.len());
                curves.push((nu, pts));
            }
            if let Err(e) = plot(&path, &curves) {
                eprintln!("plot: {e}");
                std::process::exit(1);
            }
        }
        other => {
            eprintln!("unknown mode {other}: table, sweep, svg or point");
            std::process::exit(2);
        }
    }
}
