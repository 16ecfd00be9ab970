//! `ellipse_touches_line`: an ellipse or an elliptic arc (centre C, a-axis vertex V, semi-axis
//! b) touches the infinite line of a line entity (A, B) somewhere in its interior, lying on a
//! recorded side of A→B. With d = B − A, the unit normal n̂ = rot₉₀(d)/|d| and the ellipse's
//! frame u = (V − C)/a, v = rot₉₀(u), the ellipse reaches
//!
//! h = √(a²·(n̂·u)² + b²·(n̂·v)²)
//!
//! from its centre towards n̂ (its support function), so it touches the line when the signed
//! distance of the centre equals h on its side. One row in length units,
//!
//! cross(d, C − A)/|d| − s·h = 0 (s = +1 for `left`, −1 for `right`),
//!
//! written over the blocks as h·|d| = √(cross(d, w)² + b²·(w·d)²/(w·w)), w = V − C: no frame,
//! no angle, smooth wherever a > 0 and b > 0. The ellipse cannot cross to the other side
//! without h going through zero. The contact is the support point
//! F = C − s·(a²·(n̂·u)·u + b²·(n̂·v)·v)/h; on an elliptic arc its parametric angle must lie
//! within the sweep after every solve (to the solve's tolerance over the smaller semi-axis),
//! else the solve fails with [`Error::ContactOffArc`] naming the constraint and the arc, and the
//! sketch is left as it was. For an elliptic arc's end on a line, `elliptic_arc_tangent_to_line`
//! is the kind. File form:
//! `{"kind": "ellipse_touches_line", "ellipse": 1, "line": 0, "side": "left"}`.

use std::sync::Arc;

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use nalgebra::{Point2, Vector2};
use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::{self, Glyph};
use super::shared::arc_span::outside_elliptic_sweep;
use super::shared::ellipses::ellipse_kind;
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::check::{SolvedCheck, SolvedState};
use crate::constraints::piece::Slot;
use crate::ground::ellipse_blocks::ellipse_of_blocks;
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::LineSide;
use crate::residuals::curve::{cross, dot, sub};

/// The ellipse touches the line in its interior, on a recorded side (one row, and on an
/// elliptic arc the contact checked within the sweep after the solve).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EllipseTouchesLine {
    /// The ellipse or elliptic arc.
    pub ellipse: EntityId,
    /// The line entity (its ends may be unknowns).
    pub line: EntityId,
    /// The side of A→B the ellipse (and its centre) lies on.
    pub side: LineSide,
}

/// g of the module documentation over the blocks [C, V, b, A, B].
///
/// ```
/// use camber_sketch::constraints::ellipse_touches_line::EllipseLineContact;
/// use camber_sketch::LineSide;
/// use camber_solve::Residual;
/// let mut g = [f64::NAN];
/// // Centre (0, 1), a = 2 along x, b = 1, above the x axis run left to right: it touches.
/// let x: [&[f64]; 5] = [&[0.0, 1.0], &[2.0, 1.0], &[1.0], &[-1.0, 0.0], &[3.0, 0.0]];
/// EllipseLineContact::new(LineSide::Left).eval(&x, &mut g);
/// assert!(g[0].abs() < 1e-15);
/// // Turned a quarter (the a-axis vertical) it reaches 2 below its centre: 1 − 2.
/// let x: [&[f64]; 5] = [&[0.0, 1.0], &[0.0, 3.0], &[1.0], &[-1.0, 0.0], &[3.0, 0.0]];
/// EllipseLineContact::new(LineSide::Left).eval(&x, &mut g);
/// assert!((g[0] + 1.0).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipseLineContact {
    side: LineSide,
}

impl EllipseLineContact {
    /// The row for an ellipse on `side` of the line.
    pub fn new(side: LineSide) -> Self {
        Self { side }
    }
}

/// ±1 for the side.
fn side_sign(side: LineSide) -> f64 {
    match side {
        LineSide::Left => 1.0,
        LineSide::Right => -1.0,
    }
}

impl Residual for EllipseLineContact {
    fn name(&self) -> &str {
        EllipseTouchesLine::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(vec![2, 2, 1, 2, 2])
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let (w, b) = (sub(x[1], x[0]), x[2][0]);
        let d = sub(x[4], x[3]);
        let d_len = dot(d, d).sqrt();
        let across = cross(d, w);
        let along = dot(w, d);
        let reach = (across * across + b * b * along * along / dot(w, w)).sqrt();
        let distance = cross(d, sub(x[0], x[3]));
        out[0] = (distance - cst::<T>(side_sign(self.side)) * reach) / d_len;
    }
}

impl EllipseTouchesLine {
    /// The contact point, the line's direction and, for an elliptic arc, the arc; in the
    /// state `at` gives.
    #[allow(clippy::type_complexity)] // Three named results read plainer than a struct here.
    fn contact<'e>(
        &self,
        at: impl Fn(EntityId) -> Result<&'e Entity>,
    ) -> Result<(Point2<f64>, Vector2<f64>, Option<camber_geom::EllipticArc<f64>>)> {
        let e = at(self.ellipse)?;
        let is_arc = ellipse_kind(e, self.ellipse)?;
        let (points, semi_axis_b) = match e {
            Entity::Ellipse {
                points,
                semi_axis_b,
            } => (*points, *semi_axis_b),
            Entity::EllipticArc {
                points,
                semi_axis_b,
            } => ([points[0], points[1]], *semi_axis_b),
            _ => return Err(Error::UnknownEntity { entity: self.ellipse }),
        };
        let ellipse = ellipse_of_blocks(&points, semi_axis_b).map_err(|reason| {
            Error::InvalidEllipse {
                entity: self.ellipse,
                reason,
            }
        })?;
        let Entity::Line([a, b]) = at(self.line)? else {
            return Err(Error::WrongEntityKind {
                entity: self.line,
                expected: "line",
                found: at(self.line)?.kind_name(),
            });
        };
        let d = b - a;
        let n = Vector2::new(-d.y, d.x) / d.norm();
        let (u, v) = ellipse.axes();
        let (ra, rb) = (ellipse.semi_axis_a(), ellipse.semi_axis_b());
        let (nu, nv) = (n.dot(&u), n.dot(&v));
        let h = (ra * ra * nu * nu + rb * rb * nv * nv).sqrt();
        let s = side_sign(self.side);
        let f = ellipse.center() - (u * (ra * ra * nu) + v * (rb * rb * nv)) * (s / h);
        Ok((f, d, if is_arc { e.as_elliptic_arc() } else { None }))
    }
}

impl ConstraintKind for EllipseTouchesLine {
    const TAG: &'static str = "ellipse_touches_line";
    const LABEL: &'static str = "ellipse touches line";

    fn entities(&self, out: &mut Entities) {
        out.add(self.ellipse);
        out.add(self.line);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        ellipse_kind(cx.entity(self.ellipse)?, self.ellipse)?;
        distinct(self.ellipse, self.line)?;
        cx.line(self.line)?;
        let slots = vec![
            Slot::Point(self.ellipse, 0),
            Slot::Point(self.ellipse, 1),
            Slot::Radius(self.ellipse),
            Slot::Point(self.line, 0),
            Slot::Point(self.line, 1),
        ];
        cx.residual(
            EllipseLineContact::new(self.side),
            slots,
            Some(Arc::new(*self)),
        );
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        let (f, d, _) = self.contact(|id| at.lookup(id))?;
        Ok(vec![Glyph::Arrow(f, d), glyph::line_arrow(at, self.line)?])
    }
}

impl SolvedCheck for EllipseTouchesLine {
    fn verify(&self, state: &SolvedState<'_>) -> Result<()> {
        let (f, _, arc) = self.contact(|id| state.entity(id))?;
        let Some(arc) = arc else {
            return Ok(());
        };
        let angle = arc.ellipse().angle_of(&f);
        match outside_elliptic_sweep(&arc, angle, state.penetration) {
            None => Ok(()),
            Some(outside) => Err(Error::ContactOffArc {
                constraint: state.owner,
                arc: self.ellipse,
                outside,
            }),
        }
    }
}
