//! The unknowns of a [`Report`] as an SVG plot (plotters): one line per
//! unknown against x.
use plotters::prelude::*;

use super::Report;

impl Report {
    /// The unknowns drawn as an SVG document (the caller writes it);
    /// an error names why nothing could be drawn.
    pub fn svg(&self) -> Result<String, String> {
        let err = |e: String| format!("cannot plot: {e}");
        let mut out = String::new();
        let finite = |v: &f64| v.is_finite();
        let ys: Vec<f64> = self
            .unknowns
            .values()
            .flat_map(|u| u.values.iter().copied().filter(finite))
            .collect();
        let xs: Vec<f64> = self
            .unknowns
            .values()
            .flat_map(|u| u.x.iter().copied().filter(finite))
            .collect();
        let range = |v: &[f64]| {
            v.iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
                    (a.min(v), b.max(v))
                })
        };
        let (mut y0, mut y1) = range(&ys);
        let (x0, x1) = range(&xs);
        if !(y0.is_finite() && y1.is_finite() && x0 < x1) {
            return Err(err("no unknowns with finite values".into()));
        }
        if y1 - y0 < 1e-12 {
            y0 -= 0.5;
            y1 += 0.5;
        }
        let pad = 0.05 * (y1 - y0);
        {
            let root = SVGBackend::with_string(&mut out, (800, 500)).into_drawing_area();
            root.fill(&WHITE).map_err(|e| err(e.to_string()))?;
            let mut chart = ChartBuilder::on(&root)
                .caption(
                    format!("lambdamat solve ({})", self.method),
                    ("sans-serif", 20),
                )
                .margin(10)
                .x_label_area_size(30)
                .y_label_area_size(50)
                .build_cartesian_2d(x0..x1, (y0 - pad)..(y1 + pad))
                .map_err(|e| err(e.to_string()))?;
            chart
                .configure_mesh()
                .x_desc("x")
                .draw()
                .map_err(|e| err(e.to_string()))?;
            for (k, (name, u)) in self.unknowns.iter().enumerate() {
                let color = Palette99::pick(k).to_rgba();
                let pts: Vec<(f64, f64)> =
                    u.x.iter()
                        .copied()
                        .zip(u.values.iter().copied())
                        .filter(|(_, v)| v.is_finite())
                        .collect();
                chart
                    .draw_series(LineSeries::new(pts, color))
                    .map_err(|e| err(e.to_string()))?
                    .label(name.clone())
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color));
            }
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .draw()
                .map_err(|e| err(e.to_string()))?;
            root.present().map_err(|e| err(e.to_string()))?;
        }
        Ok(out)
    }
}
