//! SVG plots (plotters): the Hertz fields p, q, μp and u against x with the
//! stick radius c marked. Only drawing; the values come from
//! [`crate::hertz::front::HertzResult::profile`].

use super::error::CliError;
use crate::hertz::front::{HertzResult, Sample};
use plotters::prelude::*;

/// A curve: legend, colour, stroke width and the field it draws.
type Series = (&'static str, RGBColor, u32, fn(&Sample) -> f64);

fn plot_err(e: impl std::fmt::Display) -> CliError {
    CliError::Numeric(format!("cannot draw the plot: {e}"))
}

/// The fields of `s` drawn as an SVG document (the caller writes it).
pub fn hertz_svg(s: &HertzResult) -> Result<String, CliError> {
    let mut out = String::new();
    draw(s, &mut out)?;
    Ok(out)
}

fn draw(s: &HertzResult, out: &mut String) -> Result<(), CliError> {
    let samples = s.profile(400)?;
    // p ~ (1-x)^(-α) at the edge: scale the axis to the field away from it.
    let shown: Vec<_> = samples.iter().filter(|p| p.x <= 0.97).collect();
    let (mut lo, mut hi) = (0.0f64, 0.0f64);
    for p in &shown {
        for v in [p.p, p.q, p.mu_p, p.u] {
            if v.is_finite() {
                lo = lo.min(v);
                hi = hi.max(v);
            }
        }
    }
    let pad = 0.08 * (hi - lo).max(1e-12);
    let (lo, hi) = (lo - pad, hi + pad);
    let root = SVGBackend::with_string(out, (900, 560)).into_drawing_area();
    root.fill(&WHITE).map_err(plot_err)?;
    // The fields' own estimates, at most this over the plotted range.
    let worst = shown
        .iter()
        .flat_map(|p| [p.p_err, p.q_err, p.mu_p_err, p.u_err])
        .fold(0.0f64, f64::max);
    let title = format!(
        "Hertz contact: ν = {}, μ = {:.6}, c = {:.6}; fields ± {:.0e} or better",
        s.nu, s.mu, s.c, worst
    );
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 22))
        .margin(16)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(0f64..1f64, lo..hi)
        .map_err(plot_err)?;
    chart
        .configure_mesh()
        .x_desc("x (radius / contact radius)")
        .y_desc("stress, slip")
        .draw()
        .map_err(plot_err)?;
    // μp before q: in the slip zone q = μp and q is drawn on top.
    let series: [Series; 4] = [
        ("p (normal stress)", BLUE, 2, |p| p.p),
        ("μp", GREEN, 4, |p| p.mu_p),
        ("q (shear stress; = μp for x > c)", RED, 2, |p| p.q),
        ("u (slip)", MAGENTA, 2, |p| p.u),
    ];
    for (name, color, width, f) in series {
        // Points beyond the axis (the edge singularity of p) are left out.
        let pts: Vec<(f64, f64)> = samples
            .iter()
            .map(|p| (p.x, f(p)))
            .filter(|(_, y)| y.is_finite() && *y >= lo && *y <= hi)
            .collect();
        chart
            .draw_series(LineSeries::new(pts, color.stroke_width(width)))
            .map_err(plot_err)?
            .label(name)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(width))
            });
    }
    let marker = ShapeStyle::from(&BLACK).stroke_width(1);
    let dashes = (0..40).map(|k| {
        let y0 = lo + (hi - lo) * k as f64 / 40.0;
        PathElement::new(vec![(s.c, y0), (s.c, y0 + 0.5 * (hi - lo) / 40.0)], marker)
    });
    chart
        .draw_series(dashes)
        .map_err(plot_err)?
        .label(format!("c = {:.4} (stick | slip)", s.c))
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], marker));
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(plot_err)?;
    root.present().map_err(plot_err)?;
    Ok(())
}
