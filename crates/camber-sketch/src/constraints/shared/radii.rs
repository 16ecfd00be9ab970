//! Round entities — circles and arcs — as the radius and centre kinds read them.
//!
//! A circle's radius is a block of its own (one unknown r); an arc's is |S − C|, a function of
//! its centre and start blocks (an arc is stored by its blocks [C, S, E], see
//! [`crate::Entity::Arc`]). [`Round`] gives the slots a residual reads for the radius and
//! [`radius_of`] evaluates it from those blocks, generically over the scalar, so one residual
//! serves circle/circle, arc/circle and arc/arc alike. The centre is point block 0 of both.

use camber_solve::Scalar;
use smallvec::SmallVec;

use crate::constraints::piece::Slot;
use crate::constraints::Compiler;
use crate::ground::entity::Entity;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::EntityId;
use crate::residuals::curve::{dot, sub};

/// A circle or an arc.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Round {
    /// A circle: its radius is a block of one.
    Circle(EntityId),
    /// An arc: its radius is |S − C| over its blocks 0 and 1.
    Arc(EntityId),
}

impl Round {
    /// The entity `id` of `cx` as a round entity.
    ///
    /// # Errors
    /// Unknown id; [`Error::WrongEntityKind`] for anything but a circle or an arc.
    pub(crate) fn of(cx: &Compiler<'_>, id: EntityId) -> Result<Round> {
        match cx.entity(id)? {
            Entity::Circle { .. } => Ok(Round::Circle(id)),
            Entity::Arc(_) => Ok(Round::Arc(id)),
            other => Err(Error::WrongEntityKind {
                entity: id,
                expected: "circle or arc",
                found: other.kind_name(),
            }),
        }
    }

    /// The entity `id` of `cx`, which must be an arc (the kinds that read an arc's ends).
    ///
    /// # Errors
    /// Those of [`Round::of`] for an entity that is not round; [`Error::WrongEntityKind`]
    /// (expected "arc") for a circle.
    pub(crate) fn arc(cx: &Compiler<'_>, id: EntityId) -> Result<Round> {
        match Round::of(cx, id)? {
            Round::Arc(_) => Ok(Round::Arc(id)),
            Round::Circle(_) => Err(Error::WrongEntityKind {
                entity: id,
                expected: "arc",
                found: "circle",
            }),
        }
    }

    /// Whether it is an arc.
    pub(crate) fn is_arc(self) -> bool {
        matches!(self, Round::Arc(_))
    }

    /// The slots its radius reads: `[r]` for a circle, `[C, S]` for an arc.
    pub(crate) fn radius_slots(self) -> SmallVec<[Slot; 2]> {
        match self {
            Round::Circle(e) => smallvec::smallvec![Slot::Radius(e)],
            Round::Arc(e) => smallvec::smallvec![Slot::Point(e, 0), Slot::Point(e, 1)],
        }
    }
}

/// The block sizes of a radius: `[1]` for a circle, `[2, 2]` for an arc.
pub(crate) fn radius_block_sizes(arc: bool, out: &mut Vec<usize>) {
    if arc {
        out.extend([2, 2]);
    } else {
        out.push(1);
    }
}

/// The radius read from the blocks at the front of `x` (r, or |S − C| from [C, S]), and how
/// many blocks it used.
pub(crate) fn radius_of<T: Scalar>(arc: bool, x: &[&[T]]) -> (T, usize) {
    if arc {
        let v = sub(x[1], x[0]);
        (dot(v, v).sqrt(), 2)
    } else {
        (x[0][0], 1)
    }
}
