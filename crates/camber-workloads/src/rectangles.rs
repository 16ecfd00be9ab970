//! W5 and W5b (WORKLOADS.md): classic sketches of lines, points, coincidences, horizontals,
//! verticals, point–point distances and one fixed point, which every classic sketch solver can
//! run. Every line is a segment with its own two end points; lines meet only through
//! coincidences.
//!
//! - **W5**: N independent rectangles on a grid (c = ⌈√N⌉ columns, pitch 2): corners
//!   A = (2·col, 2·row), B = A + (w, 0), C = A + (w, h), D = A + (0, h), lines bottom A→B, right
//!   B→C, top C→D, left D→A; corners coincident, bottom and top horizontal, right and left
//!   vertical, |bottom| = w, |left| = h, bottom.start fixed: 16 unknowns and 16 rows each.
//! - **W5b**: one ladder of N cells: rung R₀ then per cell k the rails B_k, T_k and the rung
//!   R_{k+1}; rails horizontal, rungs vertical, |B_k| = w(k), |R₀| = H = 1, R₀.start fixed.
//!
//! Widths and heights cycle: w(k) = 1.0 + 0.2·(k mod 3), h(k) = 0.6 + 0.2·(k mod 4). The start
//! moves every coordinate of every point but the fixed one by an offset in [−0.1, 0.1) from a
//! 64-bit LCG (state ← 6364136223846793005·state + 1442695040888963407, seed 12345,
//! u = (state >> 11)/2⁵³, offset = 0.1·(2u − 1); x then y per point, line l's points 2l and
//! 2l + 1 in line order; the fixed point's two draws are discarded).

use camber_sketch::constraints::{Coincident, Distance, Fixed, Horizontal, Vertical};
use camber_sketch::{EntityId, PointRef, Result, Sketch};
use nalgebra::{Point2, Vector2};

/// The constraints of a W5 or W5b sketch, as plain geometry the validity check recomputes.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Rectangles {
    /// Every line, in the order the start perturbation reads them.
    pub lines: Vec<EntityId>,
    /// Coincident point pairs.
    pub coincident: Vec<(PointRef, PointRef)>,
    /// Horizontal lines.
    pub horizontal: Vec<EntityId>,
    /// Vertical lines.
    pub vertical: Vec<EntityId>,
    /// Lines with their prescribed lengths (distance between their two ends).
    pub lengths: Vec<(EntityId, f64)>,
    /// The fixed points and where they stay.
    pub fixed: Vec<(PointRef, Point2<f64>)>,
}

/// w(k) = 1.0 + 0.2·(k mod 3).
fn width(k: usize) -> f64 {
    1.0 + 0.2 * (k % 3) as f64
}

/// h(k) = 0.6 + 0.2·(k mod 4).
fn height(k: usize) -> f64 {
    0.6 + 0.2 * (k % 4) as f64
}

/// The start perturbation's generator (see the module documentation), also W8's radius
/// factors.
pub(crate) struct Lcg(pub(crate) u64);

impl Lcg {
    /// The next u = (state >> 11)/2⁵³ in [0, 1).
    pub(crate) fn unit(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    /// The next offset in [−0.1, 0.1).
    fn offset(&mut self) -> f64 {
        0.1 * (2.0 * self.unit() - 1.0)
    }
}

impl Rectangles {
    /// Adds the lines from their design end points, perturbed as the module documentation says;
    /// the start points of the lines in `fixed` (indices) keep their design position and are
    /// fixed.
    fn add_lines(
        &mut self,
        s: &mut Sketch,
        design: &[[Point2<f64>; 2]],
        fixed: &[usize],
    ) -> Result<()> {
        let mut rng = Lcg(12_345);
        for (l, ends) in design.iter().enumerate() {
            let mut moved = *ends;
            for (e, p) in moved.iter_mut().enumerate() {
                let (dx, dy) = (rng.offset(), rng.offset());
                if !(e == 0 && fixed.binary_search(&l).is_ok()) {
                    *p += Vector2::new(dx, dy);
                }
            }
            self.lines.push(s.add_line(moved[0], moved[1])?);
        }
        for &l in fixed {
            let at = PointRef::Start(self.lines[l]);
            s.add_constraint(Fixed::point(at))?;
            self.fixed.push((at, design[l][0]));
        }
        Ok(())
    }

    fn coincide(&mut self, s: &mut Sketch, a: PointRef, b: PointRef) -> Result<()> {
        s.add_constraint(Coincident { a, b })?;
        self.coincident.push((a, b));
        Ok(())
    }

    fn level(&mut self, s: &mut Sketch, line: EntityId) -> Result<()> {
        s.add_constraint(Horizontal::line(line))?;
        self.horizontal.push(line);
        Ok(())
    }

    fn plumb(&mut self, s: &mut Sketch, line: EntityId) -> Result<()> {
        s.add_constraint(Vertical::line(line))?;
        self.vertical.push(line);
        Ok(())
    }

    fn length(&mut self, s: &mut Sketch, line: EntityId, length: f64) -> Result<()> {
        s.add_constraint(Distance {
            a: PointRef::Start(line),
            b: PointRef::End(line),
            distance: length,
        })?;
        self.lengths.push((line, length));
        Ok(())
    }
}

/// W5: `n` independent rectangles (see the module documentation). Returns the sketch (dirty,
/// perturbed) and its constraints.
///
/// ```
/// let (mut s, r) = camber_workloads::w5(4)?;
/// assert_eq!(s.components().len(), 4);
/// assert!(!camber_workloads::w5_valid(&s, &r, 1e-6)); // the start is perturbed
/// s.solve()?;
/// assert!(camber_workloads::w5_valid(&s, &r, 1e-6));
/// # Ok::<(), camber_sketch::Error>(())
/// ```
///
/// # Errors
/// None in practice.
pub fn w5(n: usize) -> Result<(Sketch, Rectangles)> {
    w5_at(n, Vector2::zeros())
}

/// W5 moved by `origin`: the same rectangles, constraints and perturbation with every design
/// point shifted (issue 17: the same sketch far from the origin must solve alike).
///
/// ```
/// use nalgebra::Vector2;
/// let (mut s, r) = camber_workloads::w5_at(1, Vector2::new(1e6, -1e6))?;
/// s.solve()?;
/// assert!(camber_workloads::w5_valid(&s, &r, 1e-6));
/// # Ok::<(), camber_sketch::Error>(())
/// ```
///
/// # Errors
/// None in practice.
pub fn w5_at(n: usize, origin: Vector2<f64>) -> Result<(Sketch, Rectangles)> {
    let columns = (n as f64).sqrt().ceil().max(1.0) as usize;
    let mut design = Vec::with_capacity(4 * n);
    for k in 0..n {
        let (col, row) = (k % columns, k / columns);
        let a = Point2::new(2.0 * col as f64, 2.0 * row as f64) + origin;
        let (w, h) = (width(k), height(k));
        let (b, c, d) = (
            a + Vector2::new(w, 0.0),
            a + Vector2::new(w, h),
            a + Vector2::new(0.0, h),
        );
        design.extend([[a, b], [b, c], [c, d], [d, a]]);
    }
    let mut s = Sketch::new();
    let mut r = Rectangles::default();
    let bottoms: Vec<usize> = (0..n).map(|k| 4 * k).collect();
    r.add_lines(&mut s, &design, &bottoms)?;
    for k in 0..n {
        let l = &r.lines[4 * k..4 * k + 4];
        let [bottom, right, top, left] = [l[0], l[1], l[2], l[3]];
        r.coincide(&mut s, PointRef::End(bottom), PointRef::Start(right))?;
        r.coincide(&mut s, PointRef::End(right), PointRef::Start(top))?;
        r.coincide(&mut s, PointRef::End(top), PointRef::Start(left))?;
        r.coincide(&mut s, PointRef::End(left), PointRef::Start(bottom))?;
        r.level(&mut s, bottom)?;
        r.level(&mut s, top)?;
        r.plumb(&mut s, right)?;
        r.plumb(&mut s, left)?;
        r.length(&mut s, bottom, width(k))?;
        r.length(&mut s, left, height(k))?;
    }
    Ok((s, r))
}

/// W5b: one ladder of `n` cells (see the module documentation). Returns the sketch (dirty,
/// perturbed) and its constraints.
///
/// ```
/// let (mut s, r) = camber_workloads::w5b(3)?;
/// assert_eq!(s.components().len(), 1);
/// s.solve()?;
/// assert!(camber_workloads::w5_valid(&s, &r, 1e-6));
/// # Ok::<(), camber_sketch::Error>(())
/// ```
///
/// # Errors
/// None in practice.
pub fn w5b(n: usize) -> Result<(Sketch, Rectangles)> {
    let h = 1.0;
    let mut x = vec![0.0];
    for k in 0..n {
        x.push(x[k] + width(k));
    }
    // Line order: R₀, then per cell B_k, T_k, R_{k+1}.
    let mut design = vec![[Point2::new(0.0, 0.0), Point2::new(0.0, h)]];
    for k in 0..n {
        design.push([Point2::new(x[k], 0.0), Point2::new(x[k + 1], 0.0)]);
        design.push([Point2::new(x[k], h), Point2::new(x[k + 1], h)]);
        design.push([Point2::new(x[k + 1], 0.0), Point2::new(x[k + 1], h)]);
    }
    let mut s = Sketch::new();
    let mut r = Rectangles::default();
    r.add_lines(&mut s, &design, &[0])?;
    let rung = |r: &Rectangles, k: usize| if k == 0 { r.lines[0] } else { r.lines[3 * k] };
    r.plumb(&mut s, r.lines[0])?;
    r.length(&mut s, r.lines[0], h)?;
    for k in 0..n {
        let (bottom, top, next) = (r.lines[3 * k + 1], r.lines[3 * k + 2], r.lines[3 * k + 3]);
        let this = rung(&r, k);
        r.coincide(&mut s, PointRef::Start(bottom), PointRef::Start(this))?;
        r.coincide(&mut s, PointRef::Start(top), PointRef::End(this))?;
        r.coincide(&mut s, PointRef::End(bottom), PointRef::Start(next))?;
        r.coincide(&mut s, PointRef::End(top), PointRef::End(next))?;
        r.level(&mut s, bottom)?;
        r.level(&mut s, top)?;
        r.plumb(&mut s, next)?;
        r.length(&mut s, bottom, width(k))?;
    }
    Ok((s, r))
}

/// The W5/W5b validity check, recomputed from the solved coordinates: every coincidence gap,
/// |Δy| of every horizontal, |Δx| of every vertical, every length error and every fixed point's
/// offset at most `tol`. A mirrored solution meets every constraint and counts as valid.
pub fn w5_valid(s: &Sketch, r: &Rectangles, tol: f64) -> bool {
    let p = |q: PointRef| s.point(q).ok();
    let ends = |l: EntityId| Some((p(PointRef::Start(l))?, p(PointRef::End(l))?));
    r.coincident
        .iter()
        .all(|(a, b)| matches!((p(*a), p(*b)), (Some(u), Some(v)) if (u - v).norm() <= tol))
        && r.horizontal
            .iter()
            .all(|l| ends(*l).is_some_and(|(a, b)| (b.y - a.y).abs() <= tol))
        && r.vertical
            .iter()
            .all(|l| ends(*l).is_some_and(|(a, b)| (b.x - a.x).abs() <= tol))
        && r.lengths
            .iter()
            .all(|(l, d)| ends(*l).is_some_and(|(a, b)| ((b - a).norm() - d).abs() <= tol))
        && r.fixed
            .iter()
            .all(|(q, at)| p(*q).is_some_and(|v| (v - at).norm() <= tol))
}
