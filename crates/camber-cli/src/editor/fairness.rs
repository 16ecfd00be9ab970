//! What the editor tells a designer about the shape of the curves: curvature combs on request
//! (`GET /api/combs`), and warnings when a curve has a cusp or crosses itself (with each state
//! and each drag move, for the curves they draw).
//!
//! A cusp is where the speed |C′(u)| nearly vanishes: at the samples of [`SAMPLES_PER_PIECE`]
//! per piece, a speed below [`CUSP_RATIO`] times the curve's mean speed. A self-crossing is
//! found on the drawn polyline (the same samples): two segments that are not neighbours and
//! cross. Segments are bucketed in a grid of cells about one segment long, so a curve of n
//! samples costs about n segment tests, not n².

use std::collections::HashMap;

use anyhow::Result;
use camber_geom::ParametricCurve;
use camber_sketch::{Entity, EntityId};
use serde::Serialize;

use crate::draw::{sample_parameters, Comb, SAMPLES_PER_PIECE, TEETH_PER_PIECE};

/// A speed below this fraction of the curve's mean speed is a cusp.
pub const CUSP_RATIO: f64 = 1e-3;

/// The longest polyline checked for crossings, in samples (a larger curve is left unchecked:
/// the test is for the curves a designer drags, and bounded per request: segments much longer
/// than the mean are tested against all others, at most n²/8 tests, 3·10⁷ here).
pub const MAX_CHECKED_SAMPLES: usize = 1 << 14;

/// The most samples a drag move checks (over the curves it moved): a larger move (a long
/// chain dragged whole) is checked when the drag ends, so that the move answers stay fast.
pub const MAX_MOVE_SAMPLES: usize = 4096;

/// One warning about a curve's shape.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ShapeWarning {
    /// The entity.
    pub entity: u64,
    /// `cusp` or `self_crossing`.
    pub kind: &'static str,
    /// Where, in model coordinates.
    pub at: [f64; 2],
    /// One sentence for the page.
    pub message: String,
}

/// The cusps and self-crossings of one entity (none for entities that are not free-form
/// curves).
///
/// # Errors
/// A curve that cannot be evaluated (not for an entity the sketch accepted).
pub fn warnings(id: EntityId, e: &Entity, samples: &[[f64; 2]]) -> Result<Vec<ShapeWarning>> {
    let Some(curve) = e.as_curve() else {
        return Ok(Vec::new());
    };
    let mut out = Vec::new();
    if let Some(at) = cusp(curve)? {
        out.push(ShapeWarning {
            entity: id.0,
            kind: "cusp",
            at,
            message: format!(
                "entity {} has a cusp near ({:.4}, {:.4}): its tangent vanishes there",
                id.0, at[0], at[1]
            ),
        });
    }
    if samples.len() <= MAX_CHECKED_SAMPLES {
        if let Some(at) = self_crossing(samples) {
            out.push(ShapeWarning {
                entity: id.0,
                kind: "self_crossing",
                at,
                message: format!(
                    "entity {} crosses itself near ({:.4}, {:.4})",
                    id.0, at[0], at[1]
                ),
            });
        }
    }
    Ok(out)
}

/// The point of least speed when it is below [`CUSP_RATIO`] of the mean speed.
fn cusp(curve: &dyn ParametricCurve<f64, 2>) -> Result<Option<[f64; 2]>> {
    let mut least = (f64::INFINITY, 0.0);
    let mut sum = 0.0;
    let params = sample_parameters(curve, SAMPLES_PER_PIECE);
    for &u in &params {
        let speed = curve.derivative(u)?.norm();
        sum += speed;
        if speed < least.0 {
            least = (speed, u);
        }
    }
    let mean = sum / params.len().max(1) as f64;
    // A curve of zero (or not finite) mean speed is a point: nothing to warn of.
    if !mean.is_finite() || mean <= 0.0 || least.0 >= CUSP_RATIO * mean {
        return Ok(None);
    }
    let p = curve.point(least.1)?;
    Ok(Some([p.x, p.y]))
}

/// Where a polyline first crosses itself (two segments that share no end), if it does.
pub fn self_crossing(points: &[[f64; 2]]) -> Option<[f64; 2]> {
    let n = points.len();
    if n < 4 {
        return None;
    }
    let length: f64 = points.windows(2).map(|w| dist(w[0], w[1])).sum();
    if !length.is_finite() || length <= 0.0 {
        return None;
    }
    let cell = length / (n - 1) as f64;
    let key = |v: f64| (v / cell).floor() as i64;
    let mut grid: HashMap<(i64, i64), Vec<usize>> = HashMap::new();
    for k in 0..n - 1 {
        let (a, b) = (points[k], points[k + 1]);
        let (x0, x1) = (key(a[0].min(b[0])), key(a[0].max(b[0])));
        let (y0, y1) = (key(a[1].min(b[1])), key(a[1].max(b[1])));
        // A segment is about one cell long; a longer one (a straight run) covers its box.
        if (x1 - x0 + 1).saturating_mul(y1 - y0 + 1) > 64 {
            for (j, w) in points.windows(2).enumerate() {
                if j + 1 < k || j > k + 1 {
                    if let Some(p) = crossing(a, b, w[0], w[1]) {
                        return Some(p);
                    }
                }
            }
            continue;
        }
        for x in x0..=x1 {
            for y in y0..=y1 {
                let bucket = grid.entry((x, y)).or_default();
                for &j in bucket.iter() {
                    if j + 1 < k {
                        if let Some(p) = crossing(points[j], points[j + 1], a, b) {
                            return Some(p);
                        }
                    }
                }
                bucket.push(k);
            }
        }
    }
    // A closed curve's last segment meets its first at the shared end: not a crossing.
    None
}

fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// The crossing point of segments a–b and c–d when they cross at interior points.
fn crossing(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> Option<[f64; 2]> {
    let r = [b[0] - a[0], b[1] - a[1]];
    let s = [d[0] - c[0], d[1] - c[1]];
    let den = r[0] * s[1] - r[1] * s[0];
    if den == 0.0 {
        return None;
    }
    let q = [c[0] - a[0], c[1] - a[1]];
    let t = (q[0] * s[1] - q[1] * s[0]) / den;
    let u = (q[0] * r[1] - q[1] * r[0]) / den;
    let inside = |v: f64| v > 1e-12 && v < 1.0 - 1e-12;
    (inside(t) && inside(u)).then(|| [a[0] + t * r[0], a[1] + t * r[1]])
}

/// The warnings of every entity a scene draws, from the samples it drew.
///
/// # Errors
/// A curve that cannot be evaluated (not for an entity the sketch accepted).
pub fn scene_warnings(
    view: &crate::scene::View,
    scene: &super::wire::SceneJson,
) -> Result<Vec<ShapeWarning>> {
    let mut out = Vec::new();
    for drawn in &scene.entities {
        let id = EntityId(drawn.id);
        if let Ok(e) = view.entity(id) {
            out.extend(warnings(id, e, &drawn.samples)?);
        }
    }
    Ok(out)
}

/// One curve's comb for `GET /api/combs`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CombJson {
    /// The entity.
    pub entity: u64,
    /// (curve point, tooth tip) pairs; the tips joined are the envelope.
    pub teeth: Vec<[[f64; 2]; 2]>,
}

/// The curvature combs of every free-form curve, the longest tooth a tenth of the sketch's
/// size (the largest side of the box of all entities' points) on each curve.
///
/// # Errors
/// A curve that cannot be evaluated (not for an entity the sketch accepted).
pub fn combs(entities: &[(EntityId, &Entity)]) -> Result<Vec<CombJson>> {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for (_, e) in entities {
        for p in e.points() {
            lo = [lo[0].min(p.x), lo[1].min(p.y)];
            hi = [hi[0].max(p.x), hi[1].max(p.y)];
        }
    }
    let size = (hi[0] - lo[0]).max(hi[1] - lo[1]);
    let tooth = if size.is_finite() && size > 0.0 {
        0.1 * size
    } else {
        1.0
    };
    let mut out = Vec::new();
    for (id, e) in entities {
        if let Some(curve) = e.as_curve() {
            let id = *id;
            let comb = Comb::of(curve, TEETH_PER_PIECE, tooth)?;
            out.push(CombJson {
                entity: id.0,
                teeth: comb
                    .teeth
                    .iter()
                    .map(|(p, t)| [[p.x, p.y], [t.x, t.y]])
                    .collect(),
            });
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use camber_geom::BezierCurve2;
    use nalgebra::Point2;

    fn bezier(points: &[[f64; 2]]) -> Entity {
        Entity::Bezier(
            BezierCurve2::try_new(points.iter().map(|p| Point2::new(p[0], p[1])).collect())
                .unwrap(),
        )
    }

    #[test]
    fn a_figure_eight_polyline_crosses_itself_where_its_diagonals_meet() {
        // The bow tie (0,0) → (1,1) → (1,0) → (0,1): its diagonals cross at (½, ½).
        let at = self_crossing(&[[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]]).unwrap();
        assert!((at[0] - 0.5).abs() < 1e-15 && (at[1] - 0.5).abs() < 1e-15);
        // A square's outline closes on its start without crossing.
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]];
        assert_eq!(self_crossing(&square), None);
        // A long straight run crossed by a short segment far from it in the list.
        let mut long = vec![[0.0, 0.0], [100.0, 0.0]];
        long.extend((0..50).map(|k| [100.0 - f64::from(k), 1.0 + f64::from(k % 2)]));
        long.push([50.0, 5.0]);
        long.push([50.0, -5.0]);
        let at = self_crossing(&long).unwrap();
        assert!(
            (at[0] - 50.0).abs() < 1e-12 && at[1].abs() < 1e-12,
            "{at:?}"
        );
    }

    #[test]
    fn a_cubic_with_a_loop_and_one_with_a_cusp_are_named() {
        // Control polygon crossing itself: the cubic (0,0), (3,2), (-1,2), (2,0) loops.
        let looped = bezier(&[[0.0, 0.0], [3.0, 2.0], [-1.0, 2.0], [2.0, 0.0]]);
        let samples = crate::editor::wire::outline(&looped).unwrap();
        let w = warnings(EntityId(3), &looped, &samples).unwrap();
        assert_eq!(
            w.iter().map(|w| w.kind).collect::<Vec<_>>(),
            ["self_crossing"]
        );
        // (0,0), (2,2), (0,2), (2,0): C′(½) = 0, a cusp at (1, 1.5).
        let cusped = bezier(&[[0.0, 0.0], [2.0, 2.0], [0.0, 2.0], [2.0, 0.0]]);
        let samples = crate::editor::wire::outline(&cusped).unwrap();
        let w = warnings(EntityId(4), &cusped, &samples).unwrap();
        assert_eq!(w[0].kind, "cusp");
        assert!((w[0].at[0] - 1.0).abs() < 1e-12 && (w[0].at[1] - 1.5).abs() < 1e-12);
        // A fair arch has neither.
        let fair = bezier(&[[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]]);
        let samples = crate::editor::wire::outline(&fair).unwrap();
        assert!(warnings(EntityId(5), &fair, &samples).unwrap().is_empty());
    }

    #[test]
    fn combs_point_away_from_the_centre_with_the_tooth_asked() {
        let arch = bezier(&[[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]]);
        let list = [(EntityId(0), &arch)];
        let combs = combs(&list).unwrap();
        assert_eq!(combs.len(), 1);
        let teeth = &combs[0].teeth;
        assert_eq!(teeth.len(), TEETH_PER_PIECE + 1);
        // The arch bends down (its centre of curvature below it): teeth point up, the longest
        // (at the apex, most curved) a tenth of the sketch's size 2.
        let longest = teeth
            .iter()
            .map(|[p, t]| (t[1] - p[1], dist(*p, *t)))
            .fold((0.0, 0.0), |m: (f64, f64), x| if x.1 > m.1 { x } else { m });
        assert!(
            longest.0 > 0.0 && (longest.1 - 0.2).abs() < 1e-12,
            "{longest:?}"
        );
    }
}
