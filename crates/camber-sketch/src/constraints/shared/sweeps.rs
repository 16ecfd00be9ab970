//! The sweep of a circular or elliptic arc read from its blocks, generically over the scalar,
//! and the arc lengths that integrate over it: what `arc_angle` and `arc_length` constrain on
//! arcs.
//!
//! A circular arc's blocks are [C, S, E] and its sweep is the counter-clockwise angle from
//! S − C to E − C, φ ∈ (0, 2π). An elliptic arc's blocks are [C, V, b, S, E] (V the a-axis
//! vertex, a = |V − C|, b a scalar block); a point P of it has the parametric angle θ with
//! (cos θ, sin θ) = (x′/a, y′/b), x′ = (P − C)·u, y′ = (P − C)·v in the frame u = (V − C)/a,
//! v = rot₉₀(u), and its sweep is the counter-clockwise angle Δ ∈ (0, 2π) from θ_S to θ_E.
//! Both are atan2 of a cross and a dot product folded into (0, 2π): smooth in the blocks
//! except where the sweep passes through a whole turn, which a solve refuses anyway
//! (`Error::ArcTurnedInsideOut`).
//!
//! Lengths: a circular arc is r·φ long (r = |S − C|), an elliptic arc
//! Δ·∫₀¹ √(a²·sin²θ(t) + b²·cos²θ(t)) dt with θ(t) = θ_S + t·Δ, integrated by the composite
//! 8-point Gauss–Legendre rule of `arc_length`, the number of pieces chosen once on the arc as
//! it is (doubling until two rules agree to [`RULE_TOLERANCE`] relative).

use camber_solve::scalar::{cst, re};
use camber_solve::{Residual, Scalar};

use super::angles::angle_of;
use crate::constraints::arc_length::{composite_rule, MAX_SUBINTERVALS, RULE_TOLERANCE};
use crate::constraints::piece::Slot;
use crate::constraints::Compiler;
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::residuals::curve::{cross, dot, sub};

/// The counter-clockwise angle from direction `s` to direction `e`, in [0, 2π) (NaN when
/// either vanishes).
pub(crate) fn ccw_angle<T: Scalar>(s: [T; 2], e: [T; 2]) -> T {
    let phi = angle_of(cross(s, e), dot(s, e));
    if re(phi) < 0.0 {
        phi + cst::<T>(std::f64::consts::TAU)
    } else {
        phi
    }
}

/// (cos θ, sin θ) of the parametric angle θ of the point `p` − C of an ellipse with a-axis
/// `w` = V − C, semi-axes `a` = |w| and `b`, times the positive factor a²·b:
/// (b·(p·w), a·(w × p)).
pub(crate) fn parametric_direction<T: Scalar>(w: [T; 2], p: [T; 2], a: T, b: T) -> [T; 2] {
    [b * dot(p, w), a * cross(w, p)]
}

/// Which arc a sweep is read from, and so the layout of its blocks.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum SweptArc {
    /// A circular arc: blocks [C, S, E].
    Circular,
    /// An elliptic arc: blocks [C, V, b, S, E].
    Elliptic,
}

impl SweptArc {
    /// The kind of the arc `id` of `cx`.
    ///
    /// # Errors
    /// Unknown id; [`Error::WrongEntityKind`] for anything but a circular or elliptic arc.
    pub(crate) fn of(cx: &Compiler<'_>, id: EntityId) -> Result<SweptArc> {
        let e = cx.entity(id)?;
        Self::from_entity(e).ok_or_else(|| Error::WrongEntityKind {
            entity: id,
            expected: "arc or elliptic arc",
            found: e.kind_name(),
        })
    }

    /// The layout of a circular or elliptic arc; `None` for any other entity.
    pub(crate) fn from_entity(e: &Entity) -> Option<SweptArc> {
        match e {
            Entity::Arc(_) => Some(SweptArc::Circular),
            Entity::EllipticArc { .. } => Some(SweptArc::Elliptic),
            _ => None,
        }
    }

    /// The slots of the arc `id` its sweep reads, in the layout of the module documentation.
    pub(crate) fn slots(self, id: EntityId) -> Vec<Slot> {
        match self {
            SweptArc::Circular => vec![Slot::Point(id, 0), Slot::Point(id, 1), Slot::Point(id, 2)],
            SweptArc::Elliptic => vec![
                Slot::Point(id, 0),
                Slot::Point(id, 1),
                Slot::Radius(id),
                Slot::Point(id, 2),
                Slot::Point(id, 3),
            ],
        }
    }

    /// The sizes of those blocks.
    pub(crate) fn block_sizes(self) -> Vec<usize> {
        match self {
            SweptArc::Circular => vec![2, 2, 2],
            SweptArc::Elliptic => vec![2, 2, 1, 2, 2],
        }
    }

    /// The sweep φ (circular) or Δ (elliptic) in radians, from the blocks.
    pub(crate) fn sweep<T: Scalar>(self, x: &[&[T]]) -> T {
        match self {
            SweptArc::Circular => ccw_angle(sub(x[1], x[0]), sub(x[2], x[0])),
            SweptArc::Elliptic => {
                let (w, b) = (sub(x[1], x[0]), x[2][0]);
                let a = dot(w, w).sqrt();
                let s = parametric_direction(w, sub(x[3], x[0]), a, b);
                let e = parametric_direction(w, sub(x[4], x[0]), a, b);
                ccw_angle(s, e)
            }
        }
    }
}

/// The length of an arc minus L (one row in length units): r·φ for a circular arc, the
/// quadrature of the module documentation for an elliptic one.
///
/// ```
/// use camber_sketch::constraints::arc_length::ArcLengthOfArc;
/// use camber_solve::Residual;
/// // A quarter of the unit circle about (0, 0) from (1, 0) to (0, 1) is π/2 long.
/// let quarter = ArcLengthOfArc::circular(0.0);
/// let mut g = [f64::NAN];
/// quarter.eval(&[&[0.0, 0.0], &[1.0, 0.0], &[0.0, 1.0]], &mut g);
/// assert!((g[0] - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct ArcLengthOfArc {
    arc: SweptArc,
    /// (t, weight) of the rule on [0, 1], for an elliptic arc.
    nodes: Vec<(f64, f64)>,
    length: f64,
}

impl ArcLengthOfArc {
    /// The row of a circular arc `length` long.
    pub fn circular(length: f64) -> Self {
        Self {
            arc: SweptArc::Circular,
            nodes: Vec::new(),
            length,
        }
    }

    /// The row of an elliptic arc `length` long, with the rule chosen on its blocks `blocks`
    /// as they are ([C, V, b, S, E], f64).
    pub fn elliptic(blocks: &[&[f64]], length: f64) -> Self {
        let mut row = Self {
            arc: SweptArc::Elliptic,
            nodes: composite_rule(&[0.0, 1.0], 1),
            length,
        };
        let mut previous = row.length_of(blocks);
        let mut pieces = 2;
        while pieces <= MAX_SUBINTERVALS {
            let nodes = composite_rule(&[0.0, 1.0], pieces);
            let next = Self { nodes, ..row };
            let value = next.length_of(blocks);
            row = next;
            let settled = (value - previous).abs() <= RULE_TOLERANCE * value.abs();
            previous = value;
            if settled {
                break;
            }
            pieces *= 2;
        }
        row
    }

    /// The number of quadrature nodes (0 for a circular arc, which needs none).
    pub fn nodes(&self) -> usize {
        self.nodes.len()
    }

    /// The arc's length from its blocks (f64), for reports and tests.
    pub fn length_of(&self, blocks: &[&[f64]]) -> f64 {
        self.arc_length(blocks)
    }

    fn arc_length<T: Scalar>(&self, x: &[&[T]]) -> T {
        let sweep = self.arc.sweep(x);
        match self.arc {
            SweptArc::Circular => {
                let r = sub(x[1], x[0]);
                dot(r, r).sqrt() * sweep
            }
            SweptArc::Elliptic => {
                let (w, b) = (sub(x[1], x[0]), x[2][0]);
                let a = dot(w, w).sqrt();
                let s = parametric_direction(w, sub(x[3], x[0]), a, b);
                let start = angle_of(s[1], s[0]);
                let mut sum = T::zero();
                for (t, weight) in &self.nodes {
                    let theta = start + sweep * cst::<T>(*t);
                    let (sin, cos) = (a * theta.sin(), b * theta.cos());
                    sum += cst::<T>(*weight) * (sin * sin + cos * cos).sqrt();
                }
                sweep * sum
            }
        }
    }
}

impl Residual for ArcLengthOfArc {
    fn name(&self) -> &str {
        "arc length"
    }
    fn dim(&self) -> usize {
        1
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(self.arc.block_sizes())
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        out[0] = self.arc_length(x) - cst::<T>(self.length);
    }
}
