//! `arc_curvature_to_curve`: at one end P of a circular or an elliptic arc, a free-form
//! curve's signed curvature at one end of its domain matches the arc's — the curvature half of
//! a G2 join, with `coincident` (position) and `arc_tangent_to_curve` /
//! `elliptic_arc_tangent_to_curve` (tangent) making the rest.
//!
//! Travelled counter-clockwise an arc turns left with curvature 1/ρ, ρ its radius of
//! curvature at P: ρ = r = |P − C| on a circular arc, and on an elliptic arc, with x′, y′ the
//! frame coordinates of P − C and a = |V − C|,
//!
//! ρ = (a²·y′²/b² + b²·x′²/a²)^{3/2} / (a·b).
//!
//! The curve's curvature at its end is κ = (C′ × C″)/|C′|³. When the arc's travel agrees with
//! C′ there (σ = +1) the two turn alike and κ = 1/ρ; when it opposes it (σ = −1) the curve runs
//! the arc backwards and κ = −1/ρ. One row, free of scale,
//!
//! g = σ·κ·ρ − 1 = 0,
//!
//! whose gradient vanishes only with the curve's tangent (a cusp). The row reads only the
//! control points of the curve's end span (the basis is fixed at the domain end, up to the
//! second derivative). File form: `{"kind": "arc_curvature_to_curve", "arc": 1, "end": "end",
//! "curve": 2, "curve_end": "start", "sense": "agree"}`.

use camber_solve::scalar::cst;
use camber_solve::{Residual, Scalar};
use serde::{Deserialize, Serialize};

use super::compiler::distinct;
use super::glyph::{self, Glyph};
use super::shared::arc_ends::{domain_end, ArcEnd};
use super::shared::ellipses::end_block;
use super::shared::sweeps::SweptArc;
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::piece::Slot;
use crate::ground::curve_eval::CurveBasis;
use crate::ground::errors::Result;
use crate::ground::ids::EntityId;
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::Sense;
use crate::residuals::curve::{cross, curvature, dot, sub};

/// A curve's curvature at one of its ends matches an arc's at one of its ends (one row).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ArcCurvatureToCurve {
    /// The circular or elliptic arc.
    pub arc: EntityId,
    /// Which end of the arc.
    pub end: ArcEnd,
    /// The curve (Bézier, B-spline, NURBS, Hermite or composite).
    pub curve: EntityId,
    /// Which end of the curve's domain.
    pub curve_end: ArcEnd,
    /// Whether the arc's counter-clockwise travel agrees with the curve's C′ there or opposes it.
    #[serde(default)]
    pub sense: Sense,
}

/// g of the module documentation over the arc's blocks ([C, P] for a circular arc,
/// [C, V, b, P] for an elliptic one) and the curve's end control points.
///
/// ```
/// use camber_sketch::constraints::arc_curvature_to_curve::CurvatureMatch;
/// use camber_sketch::curve_eval::CurveBasis;
/// use camber_sketch::Entity;
/// use camber_geom::BezierCurve2;
/// use camber_solve::Residual;
/// use nalgebra::Point2;
/// // A cubic ending at (1, 0) heading +y, with P₂ = (1, −h) and P₁ = (1 − 1.5h², ·), has
/// // curvature 2(1 − x₁)/(3h²) = 1 there: that of the unit circle about (0, 0) travelled
/// // counter-clockwise from (1, 0).
/// let h = 0.4;
/// let pts = [(0.0, -1.0), (1.0 - 1.5 * h * h, -0.7), (1.0, -h), (1.0, 0.0)];
/// let cubic = BezierCurve2::try_new(pts.iter().map(|p| Point2::new(p.0, p.1)).collect())?;
/// let full = CurveBasis::of(&Entity::Bezier(cubic)).expect("a Bézier has a basis");
/// let (basis, used) = full.at(1.0, 2);
/// let row = CurvatureMatch::circular(basis, 1.0, 1.0);
/// let ends: Vec<[f64; 2]> = used.iter().map(|j| [pts[*j].0, pts[*j].1]).collect();
/// let mut blocks: Vec<&[f64]> = vec![&[0.0, 0.0], &[1.0, 0.0]];
/// blocks.extend(ends.iter().map(|p| &p[..]));
/// let mut g = [f64::NAN];
/// row.eval(&blocks, &mut g);
/// assert!(g[0].abs() < 1e-14);
/// # Ok::<(), camber_geom::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct CurvatureMatch {
    arc: SweptArc,
    basis: CurveBasis,
    u: f64,
    sense: f64,
}

impl CurvatureMatch {
    /// The row for a circular arc, the curve's `basis` fixed at its end `u` (order 2), and the
    /// sense's sign `sense` (±1).
    pub fn circular(basis: CurveBasis, u: f64, sense: f64) -> Self {
        Self {
            arc: SweptArc::Circular,
            basis,
            u,
            sense,
        }
    }

    /// The row for an elliptic arc, otherwise as [`CurvatureMatch::circular`].
    pub fn elliptic(basis: CurveBasis, u: f64, sense: f64) -> Self {
        Self {
            arc: SweptArc::Elliptic,
            ..Self::circular(basis, u, sense)
        }
    }

    /// The number of arc blocks in front of the curve's.
    fn arc_blocks(&self) -> usize {
        match self.arc {
            SweptArc::Circular => 2,
            SweptArc::Elliptic => 4,
        }
    }
}

/// The arc's radius of curvature at its end, from its blocks.
fn radius_of_curvature<T: Scalar>(arc: SweptArc, x: &[&[T]]) -> T {
    match arc {
        SweptArc::Circular => {
            let r = sub(x[1], x[0]);
            dot(r, r).sqrt()
        }
        SweptArc::Elliptic => {
            let (w, b, p) = (sub(x[1], x[0]), x[2][0], sub(x[3], x[0]));
            let a2 = dot(w, w);
            // a·x′ = p·w and a·y′ = w × p.
            let (xa, ya) = (dot(p, w), cross(w, p));
            let q = ya * ya / (b * b) + b * b * xa * xa / (a2 * a2);
            q * q.sqrt() / (a2.sqrt() * b)
        }
    }
}

impl Residual for CurvatureMatch {
    fn name(&self) -> &str {
        ArcCurvatureToCurve::LABEL
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        let mut sizes = match self.arc {
            SweptArc::Circular => vec![2, 2],
            SweptArc::Elliptic => vec![2, 2, 1, 2],
        };
        sizes.extend(std::iter::repeat_n(2, self.basis.count()));
        Some(sizes)
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        let k = self.arc_blocks();
        let kappa = curvature(self.basis.eval2(&x[k..], cst(self.u)));
        out[0] = cst::<T>(self.sense) * kappa * radius_of_curvature(self.arc, x) - T::one();
    }
}

impl ConstraintKind for ArcCurvatureToCurve {
    const TAG: &'static str = "arc_curvature_to_curve";
    const LABEL: &'static str = "arc curvature to curve";

    fn entities(&self, out: &mut Entities) {
        out.add(self.arc);
        out.add(self.curve);
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let arc = SweptArc::of(cx, self.arc)?;
        distinct(self.arc, self.curve)?;
        let (full, _) = cx.curve_basis(self.curve)?;
        let u = domain_end(full.domain(), self.curve_end);
        let (basis, points) = full.at(u, 2);
        let mut slots = match arc {
            SweptArc::Circular => vec![Slot::Point(self.arc, 0), Slot::Point(self.arc, self.end.block())],
            SweptArc::Elliptic => vec![
                Slot::Point(self.arc, 0),
                Slot::Point(self.arc, 1),
                Slot::Radius(self.arc),
                Slot::Point(self.arc, end_block(self.end)),
            ],
        };
        slots.extend(points.iter().map(|j| Slot::Point(self.curve, *j)));
        let sense = self.sense.sign();
        let row = match arc {
            SweptArc::Circular => CurvatureMatch::circular(basis, u, sense),
            SweptArc::Elliptic => CurvatureMatch::elliptic(basis, u, sense),
        };
        cx.residual(row, slots, None);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        let u = glyph::domain_end(at, self.curve, self.curve_end == ArcEnd::End)?;
        let p = glyph::curve_point(at, self.curve, u)?;
        Ok(vec![Glyph::Mark(p, "κ")])
    }
}
