//! W5r: W5's rectangles with rounded corners (issue 29: "performance of W5-like sketches made
//! of rounded rectangles (4 lines, 4 fillet arcs) is reported beside W5").
//!
//! Rectangle k (k = 0..N−1) has W5's design corners A = (2·col, 2·row), B = A + (w, 0),
//! C = A + (w, h), D = A + (0, h) (c = ⌈√N⌉ columns, pitch 2; w(k) = 1.0 + 0.2·(k mod 3),
//! h(k) = 0.6 + 0.2·(k mod 4)), drawn as W5 draws it — lines bottom A→B, right B→C, top C→D,
//! left D→A, corners coincident — and then rounded by [`Sketch::fillet`] at its four corners
//! (bottom–right, right–top, top–left, left–bottom) with radius ρ = 0.2: each fillet trims the
//! two lines to its tangent points, replaces the corner's coincidence by two (one at each arc
//! end), and adds an `arc_tangent_to_line` at each arc end (sense as drawn) and the `radius`.
//! W5's dimensions follow, on the trimmed lines: bottom and top horizontal, right and left
//! vertical, |bottom| = w − 2ρ, |left| = h − 2ρ, and bottom.start (A + (ρ, 0)) fixed.
//!
//! Per rectangle: 4 lines (16 unknowns) and 4 arcs (3 point blocks each, 24 unknowns, less
//! each arc's own row |E − C| = |S − C|: 20 DOF), against 8 coincidences (16 rows),
//! 8 tangencies, 4 radii, 2 horizontals, 2 verticals, 2 lengths and the fixed point (2): 36
//! unknowns' worth of freedom, 36 independent rows, DOF 0.
//!
//! **Start**: the drawn, filleted sketch with every coordinate of every point of every line
//! and arc but the fixed one moved by an offset in [−δ, δ), δ = 0.02 (a tenth of the corner
//! radius), from W5's LCG (seed 12345; per rectangle: its lines in order, each end x then y,
//! then its arcs in order, each of centre, start and end x then y; the fixed point's two
//! draws are discarded).
//!
//! **Valid** at tolerance 1e-6, recomputed from the solved coordinates: W5's check of the
//! lines (coincidence gaps, horizontals, verticals, lengths, the fixed point), and for every
//! arc |E − C| − |S − C|, |radius − ρ|, at each tangency (P − C)·d/|d| and the drawn sense
//! of rot₉₀(P − C)·d, and the sweep a quarter turn (an arc turned inside out would sweep
//! three quarters).

use camber_sketch::constraints::arc_tangent_to_line::ArcEnd;
use camber_sketch::constraints::{Coincident, Constraint, Horizontal, Vertical};
use camber_sketch::{Entity, EntityId, PointRef, Result, Sense, Sketch};
use nalgebra::{Point2, Vector2};

use crate::rectangles::{Lcg, Rectangles};

/// The corner radius ρ of every W5r rectangle.
pub const W5R_RADIUS: f64 = 0.2;

/// The start perturbation's half-width δ.
const W5R_DELTA: f64 = 0.02;

/// One tangency of a fillet: the arc, which end, the line, and the sense it was drawn with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tangency {
    /// The fillet arc.
    pub arc: EntityId,
    /// The arc end that touches the line.
    pub end: ArcEnd,
    /// The line.
    pub line: EntityId,
    /// Whether the arc's counter-clockwise travel there runs along the line's B − A.
    pub sense: Sense,
}

/// The constraints of a W5r sketch, as plain geometry the validity check recomputes.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RoundedRectangles {
    /// The lines' constraints, as W5 records them (coincidences are the fillets' joins).
    pub lines: Rectangles,
    /// Every fillet arc.
    pub arcs: Vec<EntityId>,
    /// Every tangency.
    pub tangencies: Vec<Tangency>,
}

/// w(k) = 1.0 + 0.2·(k mod 3), as W5.
fn width(k: usize) -> f64 {
    1.0 + 0.2 * (k % 3) as f64
}

/// h(k) = 0.6 + 0.2·(k mod 4), as W5.
fn height(k: usize) -> f64 {
    0.6 + 0.2 * (k % 4) as f64
}

/// One rounded rectangle with its lower-left design corner at `a`, added to `s` and recorded
/// in `r`: with W5's two lengths when `dimensioned`, and its points then moved by the start
/// perturbation when a generator is given.
fn add_rounded(
    s: &mut Sketch,
    r: &mut RoundedRectangles,
    rng: Option<&mut Lcg>,
    a: Point2<f64>,
    (w, h): (f64, f64),
    dimensioned: bool,
) -> Result<()> {
    let rho = W5R_RADIUS;
    let (b, c, d) = (
        a + Vector2::new(w, 0.0),
        a + Vector2::new(w, h),
        a + Vector2::new(0.0, h),
    );
    let lines = [
        s.add_line(a, b)?,
        s.add_line(b, c)?,
        s.add_line(c, d)?,
        s.add_line(d, a)?,
    ];
    for i in 0..4 {
        s.add_constraint(Coincident {
            a: PointRef::End(lines[i]),
            b: PointRef::Start(lines[(i + 1) % 4]),
        })?;
    }
    let mut arcs = Vec::with_capacity(4);
    for i in 0..4 {
        let f = s.fillet(lines[i], lines[(i + 1) % 4], rho)?;
        arcs.push(f.arc);
        for id in &f.added {
            match s.constraint(*id)? {
                Constraint::Coincident(k) => r.lines.coincident.push((k.a, k.b)),
                Constraint::ArcTangentToLine(t) => r.tangencies.push(Tangency {
                    arc: t.arc,
                    end: t.end,
                    line: t.line,
                    sense: t.sense,
                }),
                _ => {}
            }
        }
    }
    let [bottom, right, top, left] = lines;
    for l in [bottom, top] {
        s.add_constraint(Horizontal::line(l))?;
        r.lines.horizontal.push(l);
    }
    for l in [right, left] {
        s.add_constraint(Vertical::line(l))?;
        r.lines.vertical.push(l);
    }
    let lengths = if dimensioned {
        vec![(bottom, w - 2.0 * rho), (left, h - 2.0 * rho)]
    } else {
        Vec::new()
    };
    for (l, length) in lengths {
        s.add_constraint(camber_sketch::constraints::Distance {
            a: PointRef::Start(l),
            b: PointRef::End(l),
            distance: length,
        })?;
        r.lines.lengths.push((l, length));
    }
    let fixed = PointRef::Start(bottom);
    s.add_constraint(camber_sketch::constraints::Fixed::point(fixed))?;
    r.lines.fixed.push((fixed, s.point(fixed)?));
    r.lines.lines.extend(lines);
    r.arcs.extend(arcs.iter().copied());
    let Some(rng) = rng else {
        return Ok(());
    };
    // The start: every point moved but the fixed one (its draws discarded).
    let mut offset = || W5R_DELTA * (2.0 * rng.unit() - 1.0);
    for (i, l) in lines.iter().enumerate() {
        let Entity::Line(mut ends) = s.entity(*l)?.clone() else {
            unreachable!("a line")
        };
        for (e, p) in ends.iter_mut().enumerate() {
            let (dx, dy) = (offset(), offset());
            if !(i == 0 && e == 0) {
                *p += Vector2::new(dx, dy);
            }
        }
        s.set_entity(*l, Entity::Line(ends))?;
    }
    for k in &arcs {
        let Entity::Arc(mut blocks) = s.entity(*k)?.clone() else {
            unreachable!("an arc")
        };
        for p in &mut blocks {
            *p += Vector2::new(offset(), offset());
        }
        s.set_entity(*k, Entity::Arc(blocks))?;
    }
    Ok(())
}

/// W5r: `n` independent rounded rectangles (see the module documentation). Returns the sketch
/// (perturbed) and its constraints.
///
/// ```
/// let (mut s, r) = camber_workloads::w5r(4)?;
/// assert_eq!(s.components().len(), 4);
/// assert!(!camber_workloads::w5r_valid(&s, &r, 1e-6)); // the start is perturbed
/// s.solve()?;
/// assert!(camber_workloads::w5r_valid(&s, &r, 1e-6));
/// # Ok::<(), camber_sketch::Error>(())
/// ```
///
/// # Errors
/// None in practice.
pub fn w5r(n: usize) -> Result<(Sketch, RoundedRectangles)> {
    let columns = (n as f64).sqrt().ceil().max(1.0) as usize;
    let mut s = Sketch::new();
    let mut r = RoundedRectangles::default();
    let mut rng = Lcg(12_345);
    for k in 0..n {
        let (col, row) = (k % columns, k / columns);
        let a = Point2::new(2.0 * col as f64, 2.0 * row as f64);
        add_rounded(
            &mut s,
            &mut r,
            Some(&mut rng),
            a,
            (width(k), height(k)),
            true,
        )?;
    }
    Ok((s, r))
}

/// The bundled sketch `rounded_plate.json`: one W5r rectangle (2 × 1.2 with corners rounded
/// to ρ = 0.2, as drawn, not perturbed) without its two lengths, so its width and height are
/// free (DOF 2) and a drag of a corner arc stretches it with every tangency and radius kept.
///
/// ```
/// let (mut s, r) = camber_workloads::rounded_plate()?;
/// assert!(camber_workloads::w5r_valid(&s, &r, 1e-9)); // drawn satisfied
/// let dof: usize = s.analyze()?.iter().map(|a| a.analysis.dof).sum();
/// assert_eq!(dof, 2);
/// # Ok::<(), camber_sketch::Error>(())
/// ```
///
/// # Errors
/// None in practice.
pub fn rounded_plate() -> Result<(Sketch, RoundedRectangles)> {
    let mut s = Sketch::new();
    let mut r = RoundedRectangles::default();
    add_rounded(&mut s, &mut r, None, Point2::origin(), (2.0, 1.2), false)?;
    Ok((s, r))
}

/// The W5r validity check (module documentation), recomputed from the solved coordinates
/// at tolerance `tol`.
pub fn w5r_valid(s: &Sketch, r: &RoundedRectangles, tol: f64) -> bool {
    let arc = |k: EntityId| match s.entity(k) {
        Ok(Entity::Arc(blocks)) => Some(*blocks),
        _ => None,
    };
    let arcs_hold = r.arcs.iter().all(|k| {
        let Some([c, p, e]) = arc(*k) else {
            return false;
        };
        let sweep = s
            .entity(*k)
            .ok()
            .and_then(Entity::as_arc)
            .map_or(f64::NAN, |a| a.sweep());
        ((e - c).norm() - (p - c).norm()).abs() <= tol
            && ((p - c).norm() - W5R_RADIUS).abs() <= tol
            && (sweep - std::f64::consts::FRAC_PI_2).abs() <= tol / W5R_RADIUS
    });
    let tangent = r.tangencies.iter().all(|t| {
        let (Some(blocks), Ok(Entity::Line([a, b]))) = (arc(t.arc), s.entity(t.line)) else {
            return false;
        };
        let radial = blocks[t.end.block()] - blocks[0];
        let d = b - a;
        let travel = Vector2::new(-radial.y, radial.x).dot(&d);
        let sign = if t.sense == Sense::Agree { 1.0 } else { -1.0 };
        (radial.dot(&d) / d.norm()).abs() <= tol && travel * sign > 0.0
    });
    arcs_hold && tangent && crate::w5_valid(s, &r.lines, tol)
}
