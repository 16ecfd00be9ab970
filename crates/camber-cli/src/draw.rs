//! Geometry to pictures: sampled curves, control polygons, primitives and curvature combs,
//! drawn with the [`crate::svg`] writer. Each drawing is computed first (so the picture's box
//! can be taken from all of them) and then added to an [`Svg`].

use anyhow::Result;
use camber_geom::queries::signed_curvature_from_derivatives;
use camber_geom::{Circle, Line, ParametricCurve};
use nalgebra::{Point2, Vector2};

use crate::svg::{BBox, Style, Svg};

/// Samples per breakpoint piece for curve polylines.
pub const SAMPLES_PER_PIECE: usize = 32;

/// Samples per breakpoint piece for curvature combs.
pub const TEETH_PER_PIECE: usize = 12;

/// Points of `curve` at `per_piece` + 1 equally spaced parameters on each breakpoint piece
/// (shared ends written once), so corners at knots are kept.
pub fn sample_curve(
    curve: &dyn ParametricCurve<f64, 2>,
    per_piece: usize,
) -> Result<Vec<Point2<f64>>> {
    sample_parameters(curve, per_piece)
        .into_iter()
        .map(|u| finite(u, "point", curve.point(u)?.coords))
        .map(|p| p.map(Point2::from))
        .collect()
}

/// `v` when both its coordinates are finite; otherwise an error naming `what` and `u`, so a
/// curve whose numbers overflow f64 is refused instead of drawn with NaN coordinates.
fn finite(u: f64, what: &str, v: Vector2<f64>) -> Result<Vector2<f64>> {
    if v.x.is_finite() && v.y.is_finite() {
        Ok(v)
    } else {
        anyhow::bail!(
            "at u = {u}: the {what} is not finite in f64 (the curve's numbers are too large or \
             too unevenly weighted to draw)"
        )
    }
}

/// The parameters used by [`sample_curve`], increasing, ends included.
pub fn sample_parameters(curve: &dyn ParametricCurve<f64, 2>, per_piece: usize) -> Vec<f64> {
    let per_piece = per_piece.max(1);
    let breaks = curve.breakpoints();
    let mut us = Vec::with_capacity(breaks.len().saturating_sub(1) * per_piece + 1);
    for pair in breaks.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        for i in 0..per_piece {
            us.push(a + (b - a) * i as f64 / per_piece as f64);
        }
    }
    if let Some(&last) = breaks.last() {
        us.push(last);
    }
    us
}

/// A curvature comb: one tooth per sample, from the curve point along the normal on the convex
/// side, with length proportional to |κ|; the tips joined form the envelope.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Comb {
    /// (curve point, tooth tip) pairs.
    pub teeth: Vec<(Point2<f64>, Point2<f64>)>,
}

impl Comb {
    /// The comb of `curve` with its longest tooth `max_length` model units long. Samples where
    /// the speed is zero (curvature undefined) get no tooth.
    pub fn of(
        curve: &dyn ParametricCurve<f64, 2>,
        per_piece: usize,
        max_length: f64,
    ) -> Result<Self> {
        let mut raw = Vec::new();
        for u in sample_parameters(curve, per_piece) {
            let [p, d1, d2] = curve.second_order(u)?;
            let (d1, d2) = (
                finite(u, "first derivative", d1)?,
                finite(u, "second derivative", d2)?,
            );
            if let Some(k) = signed_curvature_from_derivatives(&d1, &d2) {
                let n = Vector2::new(-d1.y, d1.x) / d1.norm();
                raw.push((Point2::from(p), n, k));
            }
        }
        let k_max = raw.iter().fold(0.0_f64, |m, &(_, _, k)| m.max(k.abs()));
        let scale = if k_max > 0.0 { max_length / k_max } else { 0.0 };
        let teeth = raw
            .into_iter()
            .map(|(p, n, k)| (p, p - n * (k * scale)))
            .collect();
        Ok(Self { teeth })
    }

    /// Every point of the comb, for the picture's box.
    pub fn points(&self) -> impl Iterator<Item = Point2<f64>> + '_ {
        self.teeth.iter().flat_map(|&(a, b)| [a, b])
    }

    /// Draws the teeth and the envelope in a light colour.
    pub fn draw(&self, svg: &mut Svg) {
        let tooth = Style::stroke("#9b59b6", 0.6);
        for &(a, b) in &self.teeth {
            svg.line(a, b, &tooth);
        }
        let tips: Vec<_> = self.teeth.iter().map(|t| t.1).collect();
        svg.polyline(&tips, &Style::stroke("#9b59b6", 1.0));
    }
}

/// Draws a sampled curve as one polyline.
pub fn draw_curve(svg: &mut Svg, samples: &[Point2<f64>], colour: &str) {
    svg.polyline(samples, &Style::stroke(colour, 2.0));
}

/// Draws a control polygon: dashed grey legs and a small dot per control point.
pub fn draw_control_polygon(svg: &mut Svg, points: &[Point2<f64>]) {
    svg.polyline(points, &Style::stroke("#7f8c8d", 0.8).with_dashes());
    for &p in points {
        svg.dot(p, 3.0, "#7f8c8d");
    }
}

/// Draws a point as a dot.
pub fn draw_point(svg: &mut Svg, p: Point2<f64>, colour: &str) {
    svg.dot(p, 4.0, colour);
}

/// Draws the part of an infinite line inside `bbox` grown by half its larger side (so it
/// crosses the picture), or nothing for an empty box.
pub fn draw_line(svg: &mut Svg, line: &Line<f64>, bbox: &BBox, colour: &str) {
    if bbox.is_empty() {
        return;
    }
    let (w, h) = bbox.size();
    let reach = (w.hypot(h)).max(1.0);
    let c = Point2::from((bbox.min.coords + bbox.max.coords) / 2.0);
    let d = line.unit_direction();
    // The foot of the centre on the line, then both ways along the direction.
    let foot = line.project(&c);
    svg.line(
        foot - d * reach,
        foot + d * reach,
        &Style::stroke(colour, 1.0),
    );
}

/// The points that bound a circular arc: its ends and the points of its circle at 0°, 90°,
/// 180° and 270° that lie within its sweep.
pub fn arc_extremes(arc: &camber_geom::CircularArc<f64>) -> impl Iterator<Item = Point2<f64>> + '_ {
    let quarters = (0..4)
        .map(|k| f64::from(k) * std::f64::consts::FRAC_PI_2)
        .filter(|a| arc.contains_angle(*a, 0.0))
        .map(|a| arc.point_at_angle(a));
    [arc.start_point(), arc.end_point()]
        .into_iter()
        .chain(quarters)
}

/// Draws a circle outline.
pub fn draw_circle(svg: &mut Svg, circle: &Circle<f64>, colour: &str) {
    svg.circle(
        *circle.center(),
        circle.radius(),
        &Style::stroke(colour, 1.5),
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use camber_geom::{BSplineCurve2, KnotVector};

    fn two_piece_spline() -> BSplineCurve2<f64> {
        let knots = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]).unwrap();
        let pts = vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 1.0),
            Point2::new(2.0, 1.0),
            Point2::new(3.0, 0.0),
        ];
        BSplineCurve2::try_new(2, knots, pts).unwrap()
    }

    #[test]
    fn samples_hit_every_breakpoint() {
        let c = two_piece_spline();
        let us = sample_parameters(&c, 4);
        assert_eq!(us.len(), 9);
        assert!((us[4] - 0.5).abs() < 1e-15 && (us[8] - 1.0).abs() < 1e-15);
        assert_eq!(sample_curve(&c, 4).unwrap().len(), 9);
    }

    #[test]
    fn comb_teeth_point_away_from_the_centre_of_curvature() {
        // The arch bends right (clockwise), so the centre is below and the teeth point up.
        let c = two_piece_spline();
        let comb = Comb::of(&c, 4, 1.0).unwrap();
        assert_eq!(comb.teeth.len(), 9);
        let longest = comb
            .teeth
            .iter()
            .map(|(a, b)| (b - a).norm())
            .fold(0.0, f64::max);
        assert!((longest - 1.0).abs() < 1e-12);
        assert!(comb.teeth.iter().all(|(a, b)| b.y >= a.y - 1e-12));
    }
}
