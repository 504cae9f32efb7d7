//! Measures the split solver's ladder on one file (a one-interval file is
//! fed to the split solver as `tests/split_field_bounds.rs` does): levels,
//! whether it converged, and every scalar's, output's, coefficient's and
//! unknown's estimate; the unknowns drive the ladder
//! (`SplitOptions::fields_converge`) unless `LM_NO_FIELDS` is set
//! (`LM_FIELD_TOL` sets `field_tol`, default the larger of `TOL` and
//! `1e-6`); with `LM_WHERE` set, the grid points
//! of the largest estimates; for a file with a closed form, the true
//! errors on the grid.
//!
//! ```text
//! cargo run --release --example unknowns_ladder -- FILE [TOL [MAX_LEVEL]]
//! ```
use lambdamat::lang::parse_program;
use lambdamat::plan::{SplitOptions, solve_split_fields};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some(path) = args.first() else {
        eprintln!("usage: unknowns_ladder FILE [TOL [MAX_LEVEL]]");
        std::process::exit(1);
    };
    let mut opts = SplitOptions {
        fields_converge: std::env::var_os("LM_NO_FIELDS").is_none(),
        ..SplitOptions::default()
    };
    if let Some(t) = args.get(1).and_then(|s| s.parse().ok()) {
        opts.tol = t;
        opts.field_tol = lambdamat::plan::split_solve::default_field_tol(t);
    }
    if let Some(m) = args.get(2).and_then(|s| s.parse().ok()) {
        opts.max_level = m;
    }
    if let Some(t) = std::env::var("LM_FIELD_TOL")
        .ok()
        .and_then(|s| s.parse().ok())
    {
        opts.field_tol = t;
    }
    let text = std::fs::read_to_string(path).expect("file");
    let prog = parse_program(&text, path).expect("parses");
    let t = std::time::Instant::now();
    let s = match solve_split_fields(&prog, &opts) {
        Ok(s) => s,
        Err(e) => {
            println!("{path}: error {e}");
            std::process::exit(3);
        }
    };
    let r = &s.report;
    println!(
        "{path}: levels {} converged {} est {:.2e} cond {:.2e} dim {} wall {:.2}s",
        r.levels,
        r.converged,
        r.error_estimate,
        r.cond,
        r.dim,
        t.elapsed().as_secs_f64()
    );
    for e in r.scalars.iter().chain(&r.outputs).chain(&r.coefficients) {
        println!("  {} = {:.12e} ± {:.2e}", e.name, e.value, e.error);
    }
    for u in &r.unknowns {
        println!(
            "  field {}: size {:.3e} est {:.2e} factor {:.2} floor {:.2e} left out {:?}",
            u.name,
            u.size,
            u.error,
            u.factor,
            u.floor,
            u.left_out.iter().map(|l| l.x).collect::<Vec<_>>()
        );
    }
    if std::env::var_os("LM_WHERE").is_some() {
        let lf = lambdamat::plan::split_fields::LevelFields::new(&s).expect("fields");
        for (u, name) in s.problem.sys.unknowns.iter().enumerate() {
            let g = lf.on_grid(u, opts.grid, true).expect("grid");
            let mut idx: Vec<usize> = (0..g.x.len()).collect();
            idx.sort_by(|&a, &b| g.errors[b].total_cmp(&g.errors[a]));
            for &i in idx.iter().take(6) {
                println!(
                    "    {name}({:.4}) = {:.6e} ± {:.2e}",
                    g.x[i], g.values[i], g.errors[i]
                );
            }
            println!("    {name}: {} points kept", g.x.len());
        }
    }
    if let Some(exact) = closed_form(path) {
        let lf = lambdamat::plan::split_fields::LevelFields::new(&s).expect("fields");
        let ek = f64::EPSILON * r.cond;
        for (u, name) in s.problem.sys.unknowns.iter().enumerate() {
            let g = lf.on_grid(u, opts.grid, true).expect("grid");
            let (mut worst, mut at, mut ratio) = (0.0f64, 0.0, 0.0f64);
            for ((x, v), e) in g.x.iter().zip(&g.values).zip(&g.errors) {
                let err = (v - exact(name, *x)).abs();
                if err > worst {
                    (worst, at) = (err, *x);
                }
                ratio = ratio.max(err / e);
            }
            println!(
                "    true {name}: max error {worst:.2e} at {at:.3}, /(eps kappa max(1,size)) {:.2}, error/estimate {ratio:.3}",
                worst / (ek * g.size.max(1.0))
            );
        }
    }
    std::process::exit(if r.converged { 0 } else { 4 });
}

type Exact = Box<dyn Fn(&str, f64) -> f64>;

/// The closed forms of the files that have one.
fn closed_form(path: &str) -> Option<Exact> {
    use std::f64::consts::PI;
    let f: Exact = if path.ends_with("hertz_split_mms.lmx") {
        Box::new(|u, x| match u {
            "p" => x,
            _ if x < 0.5 => 4.0 * x * x * x,
            _ => x,
        })
    } else if path.ends_with("punch_torsion.lmx") {
        // The normal problem is the flat punch's; the shear has no
        // closed form at every point.
        Box::new(|u, x| {
            if u == "p" {
                2.0 / PI / (1.0 - x * x).sqrt()
            } else {
                f64::NAN
            }
        })
    } else if path.ends_with("flat_punch.lmx") {
        Box::new(|_, x| 2.0 / 3.0 / PI / (1.0 - x * x).sqrt())
    } else if path.ends_with("sphere_indentation.lmx") {
        let a = 0.5f64.sqrt();
        Box::new(move |_, x| {
            if x < a {
                4.0 / PI * (a * a - x * x).sqrt()
            } else {
                0.0
            }
        })
    } else if path.ends_with("contact/mms.lmx") || path == "examples/mms.lmx" {
        Box::new(|u, x| if u == "p" { 1.0 } else { x })
    } else if path.ends_with("cattaneo_mindlin_shift.lmx") {
        let c = 0.5f64.sqrt();
        Box::new(move |u, x| {
            let p = 4.0 / PI * (1.0 - x * x).max(0.0).sqrt();
            if u == "p" {
                p
            } else {
                0.5 * (p - if x < c {
                    4.0 / PI * (c * c - x * x).sqrt()
                } else {
                    0.0
                })
            }
        })
    } else if path.ends_with("cone.lmx") {
        let a = 2.0 / PI;
        Box::new(move |_, x| if x < a { (a / x).acosh() } else { 0.0 })
    } else {
        return None;
    };
    Some(f)
}
