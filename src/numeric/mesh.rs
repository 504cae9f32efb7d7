//! Panel meshes on an interval, graded geometrically toward chosen points
//! from chosen sides (the hp-style meshes that resolve endpoint and
//! stick/slip singularities). Owns breakpoints and the "layer" of every
//! panel (its distance, in grading layers, from the nearest graded point);
//! it must not know about polynomial degrees, kernels or operators.
use super::error::NumericError;

/// From which side(s) of a point the mesh is graded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// Panels shrink toward the point from below (`t < at`).
    Left,
    /// Panels shrink toward the point from above (`t > at`).
    Right,
    /// Both sides.
    Both,
}

/// One point toward which panels shrink geometrically.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grading {
    /// The point (becomes a breakpoint).
    pub at: f64,
    /// Side(s) graded.
    pub side: Side,
    /// Number of geometric layers (panels) on each graded side.
    pub layers: usize,
}

/// The smallest panel [`Mesh::graded_to_scale`] puts beside a graded point
/// `z`, relative to `|z|`: `1e3` ulps. A position near 1 is known only to
/// `ulp(1) ≈ 1.1e-16`, so finer panels would have nodes that merge with
/// the point. Where the grading toward `z` reaches this floor, further
/// levels cannot shrink the panels beside `z`.
pub const GRADING_FLOOR: f64 = 1e3 * f64::EPSILON;

/// Sorted breakpoints `lo = b_0 < … < b_P = hi` and, per panel, its layer
/// index (0 = touching a graded point; larger = farther away).
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    /// Breakpoints, strictly increasing.
    pub breaks: Vec<f64>,
    /// Layer index of each panel (`breaks.len() - 1` entries).
    pub levels: Vec<usize>,
}

impl Mesh {
    /// A mesh from explicit breakpoints (all panels at layer 0).
    pub fn from_breaks(breaks: Vec<f64>) -> Result<Mesh, NumericError> {
        check_breaks(&breaks)?;
        let levels = vec![0; breaks.len() - 1];
        Ok(Mesh { breaks, levels })
    }

    /// `n` equal panels on `[lo, hi]`.
    #[cfg(any(test, feature = "internals"))]
    pub fn uniform(lo: f64, hi: f64, n: usize) -> Result<Mesh, NumericError> {
        if n == 0 {
            return Err(NumericError::InvalidMesh("zero panels".into()));
        }
        let breaks = (0..=n)
            .map(|i| {
                if i == n {
                    hi
                } else {
                    lo + (hi - lo) * i as f64 / n as f64
                }
            })
            .collect();
        Mesh::from_breaks(breaks)
    }

    /// A mesh on `[lo, hi]` graded geometrically with ratio `sigma ∈ (0,1)`
    /// toward every point of `gradings` (each becomes a breakpoint; the same
    /// point may be listed once per side with different layer counts).
    /// Between two consecutive special points, a side that is graded gets
    /// `layers` panels of sizes `∝ σ^k`; two graded sides meet in the middle; an
    /// interval with no graded side becomes one panel. Layer indices count
    /// outward from the graded point.
    ///
    /// ```
    /// use lambdamat::numeric::mesh::{Grading, Mesh, Side};
    /// let m = Mesh::graded(0.0, 1.0, &[Grading { at: 1.0, side: Side::Left, layers: 4 }], 0.2).unwrap();
    /// assert_eq!(m.breaks.len(), 5);
    /// assert!((m.breaks[3] - 0.992).abs() < 1e-15);
    /// ```
    pub fn graded(
        lo: f64,
        hi: f64,
        gradings: &[Grading],
        sigma: f64,
    ) -> Result<Mesh, NumericError> {
        Mesh::graded_impl(lo, hi, gradings, sigma, false)
    }

    /// [`Mesh::graded`], with the layers of every graded side counted from
    /// the point's own length scale: when the nearest other special point
    /// (or end of `[lo, hi]`) is at distance `d` and the graded side spans
    /// `h > d`, the side gets `⌊log(h/d)/log(1/σ)⌋` extra layers, so its
    /// panels shrink to the scale `d` before the requested `layers` start.
    /// Two points close together (a stick radius `c → 0` beside `0`, or
    /// `c → 1` beside an edge singularity at `1`) are then resolved with a
    /// number of panels that grows like `log(1/d)`, not with panels larger
    /// than the gap.
    ///
    /// ```
    /// use lambdamat::numeric::mesh::{Grading, Mesh, Side};
    /// let g = [Grading { at: 1e-6, side: Side::Both, layers: 2 }];
    /// let m = Mesh::graded_to_scale(0.0, 1.0, &g, 0.25).unwrap();
    /// // The right side spans 1 - 1e-6 and sees 0 at 1e-6: 9 extra layers,
    /// // and one panel more where its inner layers (anchored at 1e-6) meet
    /// // its outer ones (anchored at 1).
    /// assert_eq!(m.panels(), 2 + 2 + 9 + 1);
    /// assert!(m.breaks[3] - 1e-6 < 1e-6);
    /// ```
    pub fn graded_to_scale(
        lo: f64,
        hi: f64,
        gradings: &[Grading],
        sigma: f64,
    ) -> Result<Mesh, NumericError> {
        Mesh::graded_impl(lo, hi, gradings, sigma, true)
    }

    fn graded_impl(
        lo: f64,
        hi: f64,
        gradings: &[Grading],
        sigma: f64,
        to_scale: bool,
    ) -> Result<Mesh, NumericError> {
        if lo.partial_cmp(&hi) != Some(std::cmp::Ordering::Less)
            || !lo.is_finite()
            || !hi.is_finite()
        {
            return Err(NumericError::InvalidMesh(format!(
                "bad interval [{lo}, {hi}]"
            )));
        }
        if !(sigma > 0.0 && sigma < 1.0) {
            return Err(NumericError::InvalidMesh(format!(
                "grading ratio {sigma} not in (0,1)"
            )));
        }
        // Special points with the layer counts of their left and right sides.
        let mut pts: Vec<(f64, usize, usize)> = vec![(lo, 0, 0), (hi, 0, 0)];
        for g in gradings {
            if !(g.at >= lo && g.at <= hi) {
                return Err(NumericError::InvalidMesh(format!(
                    "grading point {} outside [{lo}, {hi}]",
                    g.at
                )));
            }
            let (l, r) = match g.side {
                Side::Left => (g.layers, 0),
                Side::Right => (0, g.layers),
                Side::Both => (g.layers, g.layers),
            };
            if let Some(p) = pts.iter_mut().find(|p| p.0 == g.at) {
                p.1 = p.1.max(l);
                p.2 = p.2.max(r);
            } else {
                pts.push((g.at, l, r));
            }
        }
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        // Distance from each special point to its nearest neighbour.
        let gap: Vec<f64> = (0..pts.len())
            .map(|i| {
                let l = if i > 0 {
                    pts[i].0 - pts[i - 1].0
                } else {
                    f64::INFINITY
                };
                let r = pts.get(i + 1).map_or(f64::INFINITY, |p| p.0 - pts[i].0);
                l.min(r)
            })
            .collect();
        let extra = |span: f64, d: f64| -> usize {
            if to_scale && d > 0.0 && span > d {
                ((span / d).ln() / (1.0 / sigma).ln()).floor() as usize
            } else {
                0
            }
        };
        // With scaled layers, the smallest panel stays above `FLOOR·|z|`
        // (`z` the graded point): finer panels beside a point near 1 would
        // be a few ulps wide and their nodes would merge with the point.
        const FLOOR: f64 = GRADING_FLOOR;
        let cap = |layers: usize, span: f64, z: f64| -> usize {
            if !to_scale || z == 0.0 || span <= 0.0 {
                return layers;
            }
            let most = 1.0 + (span / (FLOOR * z.abs())).ln() / (1.0 / sigma).ln();
            if most.is_finite() && most >= 1.0 {
                layers.min(most.floor() as usize)
            } else {
                layers.min(1)
            }
        };
        // The distances from a graded point `z` of its side's breaks,
        // outermost (`span`) first. With extra layers (`d`, the gap, well
        // below `span`), the inner layers are anchored at the gap: their
        // breaks are `s·σ^k` with `s = d·σ^(-J)`, `J` half the extra
        // layers, the same multiples of `d` whatever `d` is; the outer ones
        // are `span·σ^k` as without extra layers, down to `2s`. Anchored at
        // the span alone, the panels near the point sit at a multiple of
        // `d` that cycles through a factor `1/σ` as `d` varies, and a
        // discrete quantity that depends on it (the Hertz condition `B(c)`
        // far from its root, whose field is singular at `c`) follows that
        // cycle: a staircase in `d` (issue 13). Anchored at the gap alone,
        // the outer panels cycle instead, and the outputs (integrals over
        // the whole interval) follow them. Half-way in scale, the two
        // panels whose ratio varies (between `1/√σ` and `1/σ`, never
        // coarser than the grading) sit where the fields vary smoothly on
        // both scales.
        let side = |layers: usize, span: f64, d: f64, z: f64| -> Vec<f64> {
            let ex = extra(span, d);
            let j = ex / 2;
            let s = d * (1.0 / sigma).powi(j as i32);
            let full = d * (1.0 / sigma).powi(ex as i32);
            let n = cap(layers + ex, full, z);
            // Not anchored: few extra layers, or layers cut by the floor
            // (the panels beside a point within ~1e-12 of 1 are then set by
            // rounding, not by the gap).
            if ex < 2 || n < layers + ex {
                let n = cap(layers + ex, span, z);
                return (0..n).map(|k| span * sigma.powi(k as i32)).collect();
            }
            let mut r: Vec<f64> = (0..ex - j).map(|k| span * sigma.powi(k as i32)).collect();
            // The outer layers end at `x ∈ [s/σ, s/σ²)`; two panels of one
            // ratio `√(x/s)` between 1/σ and 1/√σ join them to `s`.
            if let Some(&x) = r.last() {
                r.push((x * s).sqrt());
            }
            let inner = n.saturating_sub(ex - j).max(1);
            r.extend((0..inner).map(|k| s * sigma.powi(k as i32)));
            r
        };
        let mut breaks = vec![lo];
        let mut levels = Vec::new();
        for (i, w) in pts.windows(2).enumerate() {
            let (a, _, la) = w[0];
            let (b, lb, _) = w[1];
            let (ga, gb) = (la > 0, lb > 0);
            let mid = match (ga, gb) {
                (true, true) => 0.5 * (a + b),
                (true, false) => b,
                _ => a,
            };
            let la = if ga {
                side(la, mid - a, gap[i], a)
            } else {
                vec![]
            };
            let lb = if gb {
                side(lb, b - mid, gap[i + 1], b)
            } else {
                vec![]
            };
            if ga {
                // Panels [a + r_k, a + r_{k-1}], r_0 = mid - a.
                let n = la.len();
                for (k, r) in la.iter().enumerate().rev() {
                    breaks.push(a + r);
                    levels.push(n - 1 - k);
                }
                if !gb {
                    continue;
                }
            }
            if gb {
                // Panels [b - r_{k-1}, b - r_k], the last ending at b.
                let n = lb.len();
                for (k, r) in lb.iter().enumerate().skip(1) {
                    breaks.push(b - r);
                    levels.push(n - k);
                }
                breaks.push(b);
                levels.push(0);
            } else if !ga {
                breaks.push(b);
                levels.push(1);
            }
        }
        check_breaks(&breaks)?;
        Ok(Mesh { breaks, levels })
    }

    /// Number of panels.
    pub fn panels(&self) -> usize {
        self.breaks.len() - 1
    }

    /// Panel `k` as `(left, right)`.
    pub fn panel(&self, k: usize) -> (f64, f64) {
        (self.breaks[k], self.breaks[k + 1])
    }
}

fn check_breaks(b: &[f64]) -> Result<(), NumericError> {
    if b.len() < 2 {
        return Err(NumericError::InvalidMesh(
            "fewer than two breakpoints".into(),
        ));
    }
    for w in b.windows(2) {
        if w[0].partial_cmp(&w[1]) != Some(std::cmp::Ordering::Less)
            || !w[0].is_finite()
            || !w[1].is_finite()
        {
            return Err(NumericError::InvalidMesh(format!(
                "breakpoints not strictly increasing: {} then {}",
                w[0], w[1]
            )));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn graded_both_sides_of_interior_point() {
        let g = [Grading {
            at: 0.5,
            side: Side::Both,
            layers: 3,
        }];
        let m = Mesh::graded(0.0, 1.0, &g, 0.5).unwrap();
        assert_eq!(m.breaks, vec![0.0, 0.25, 0.375, 0.5, 0.625, 0.75, 1.0]);
        assert_eq!(m.levels, vec![2, 1, 0, 0, 1, 2]);
    }

    #[test]
    fn graded_meeting_in_the_middle() {
        let g = [
            Grading {
                at: 0.0,
                side: Side::Right,
                layers: 2,
            },
            Grading {
                at: 1.0,
                side: Side::Left,
                layers: 2,
            },
        ];
        let m = Mesh::graded(0.0, 1.0, &g, 0.5).unwrap();
        assert_eq!(m.breaks, vec![0.0, 0.25, 0.5, 0.75, 1.0]);
        assert_eq!(m.levels, vec![0, 1, 1, 0]);
    }

    #[test]
    fn sides_may_have_different_layer_counts() {
        let g = [
            Grading {
                at: 0.5,
                side: Side::Left,
                layers: 1,
            },
            Grading {
                at: 0.5,
                side: Side::Right,
                layers: 2,
            },
        ];
        let m = Mesh::graded(0.0, 1.0, &g, 0.5).unwrap();
        assert_eq!(m.breaks, vec![0.0, 0.5, 0.75, 1.0]);
        assert_eq!(m.levels, vec![0, 0, 1]);
    }

    #[test]
    fn scaled_layers_follow_the_gap_and_keep_panels_above_the_floor() {
        // A point 1e-8 from 0: the side toward 1 gets ⌊log4(0.5e8)⌋ = 12
        // extra layers, and its first panel is on the scale of the gap.
        let g = [
            Grading {
                at: 1e-8,
                side: Side::Both,
                layers: 4,
            },
            Grading {
                at: 1.0,
                side: Side::Left,
                layers: 4,
            },
        ];
        let plain = Mesh::graded(0.0, 1.0, &g, 0.25).unwrap();
        let scaled = Mesh::graded_to_scale(0.0, 1.0, &g, 0.25).unwrap();
        assert!(
            (12..=13).contains(&(scaled.panels() - plain.panels())),
            "{} panels more",
            scaled.panels() - plain.panels()
        );
        let i = scaled.breaks.iter().position(|&z| z == 1e-8).unwrap();
        let first = scaled.breaks[i + 1] - 1e-8;
        assert!(first < 1e-8 && first > 1e-10, "{first}");
        // A point 1e-10 below 1: no panel narrower than ~1e3 ulps of 1.
        let g = [
            Grading {
                at: 1.0 - 1e-10,
                side: Side::Both,
                layers: 20,
            },
            Grading {
                at: 1.0,
                side: Side::Left,
                layers: 20,
            },
        ];
        let m = Mesh::graded_to_scale(0.0, 1.0, &g, 0.25).unwrap();
        let narrowest = m.breaks.windows(2).map(|w| w[1] - w[0]).fold(1.0, f64::min);
        assert!(narrowest >= 0.2e3 * f64::EPSILON, "{narrowest}");
    }

    /// The breaks of `graded_to_scale` beside a point `c` near 0, in units
    /// of `c`: those within `s = c·σ^(-J)` are the same numbers whatever
    /// `c` is (the inner layers are anchored at the gap), so a discretised
    /// quantity at `c` varies smoothly with `c`. Anchored at the span, they
    /// cycled through a factor 4 as `c` varied, and the Hertz condition
    /// `B(c)` followed as a staircase (issue 13: 0.26–0.38 at ν = −0.9,
    /// μ = 0.01, now 0.35–0.42 and monotone). The outermost breaks stay
    /// the span's multiples, as without extra layers.
    #[test]
    fn inner_layers_are_anchored_at_the_gap_and_outer_ones_at_the_span() {
        let near = |c: f64| -> (Vec<f64>, Vec<f64>) {
            let g = [
                Grading {
                    at: c,
                    side: Side::Both,
                    layers: 6,
                },
                Grading {
                    at: 1.0,
                    side: Side::Left,
                    layers: 6,
                },
            ];
            let m = Mesh::graded_to_scale(0.0, 1.0, &g, 0.25).unwrap();
            let i = m.breaks.iter().position(|&z| z == c).unwrap();
            let inner = m.breaks[i + 1..i + 9].iter().map(|z| (z - c) / c).collect();
            let mid = 0.5 * (1.0 + c);
            let j = m.breaks.iter().position(|&z| z == mid).unwrap();
            let outer = m.breaks[j - 2..=j].to_vec();
            (inner, outer)
        };
        let (first, _) = near(1e-9);
        for c in [1.3e-9, 2.1e-9, 3.7e-9, 1e-8, 5e-7, 2e-4] {
            let (inner, outer) = near(c);
            for (a, b) in inner.iter().zip(&first) {
                assert!((a - b).abs() <= 1e-6 * b, "c = {c}: {a} against {b}");
            }
            let span = 0.5 * (1.0 - c);
            for (k, z) in outer.iter().rev().enumerate() {
                let want = c + span * 0.25f64.powi(k as i32);
                assert!((z - want).abs() <= 1e-15, "c = {c}: {z} against {want}");
            }
        }
        // The layers are still counted to the scale: 9 for 1e-9 and 1e-8
        // (4 layers between them), within one panel for the remainder.
        let count = |c: f64| {
            let g = [Grading {
                at: c,
                side: Side::Right,
                layers: 6,
            }];
            Mesh::graded_to_scale(0.0, 1.0, &g, 0.25).unwrap().panels()
        };
        let d = count(1e-9) as i64 - count(4f64.powi(2) * 1e-9) as i64;
        assert_eq!(d, 2);
    }

    #[test]
    fn bad_meshes_are_rejected() {
        assert!(Mesh::from_breaks(vec![0.0, 0.0]).is_err());
        assert!(Mesh::graded(0.0, 1.0, &[], 1.5).is_err());
        let g = [Grading {
            at: 2.0,
            side: Side::Both,
            layers: 2,
        }];
        assert!(Mesh::graded(0.0, 1.0, &g, 0.3).is_err());
        assert!(Mesh::uniform(0.0, 1.0, 0).is_err());
    }
}
