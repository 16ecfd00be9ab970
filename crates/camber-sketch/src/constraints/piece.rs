//! Pieces: what a constraint compiles to, and what the component builder reads.
//!
//! A constraint kind ([`crate::constraints`]) validates itself against the sketch's entities
//! and writes its contribution as pieces: bindings (fixed entities and points, eliminated
//! tangents), constant-coefficient combinations of entity points (affine rows), and general
//! residuals over slots (points, radii, free parameters) with an optional check of the solved
//! state. The builder ([`crate::component::problem`]) turns pieces into blocks, bindings and residuals of
//! one component's [`camber_solve::Problem`]; it knows pieces, not kinds.

use std::sync::Arc;

use camber_solve::{BlockId, ConstraintId, DynResidual};
use smallvec::SmallVec;

use crate::constraints::check::SolvedCheck;
use crate::ground::ids::EntityId;

/// A combination Σ c·P over points of several entities: (entity, point index, coefficient).
pub(crate) type ETerms = SmallVec<[(EntityId, usize, f64); 8]>;

/// A block read by a general residual.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Slot {
    /// Point `index` of an entity (two unknowns x, y).
    Point(EntityId, usize),
    /// The scalar block of an entity (one unknown): a circle's radius, an ellipse's or an
    /// elliptic arc's semi-axis b.
    Radius(EntityId),
    /// A new free parameter of the constraint, starting at `start`, bounded to [lo, hi]; a
    /// successful solve stores it back into the constraint (the k-th such slot of a
    /// constraint is its k-th free parameter).
    Free {
        /// Starting value.
        start: f64,
        /// Lower bound (may be −∞).
        lo: f64,
        /// Upper bound (may be +∞).
        hi: f64,
    },
    /// The k-th free parameter of another constraint (a contact parameter, say).
    FreeOf(ConstraintId, usize),
    /// A block of the problem already built (a contact parameter read by a clearance row).
    Existing(BlockId),
}

/// One piece of a compiled constraint.
#[derive(Debug, Clone)]
pub(crate) enum Piece {
    /// Every block of the entity is fixed.
    FixEntity(EntityId),
    /// One point block is fixed.
    FixPoint(EntityId, usize),
    /// Σ c·P − target = 0 (two rows).
    Combination {
        name: &'static str,
        terms: ETerms,
        target: [f64; 2],
    },
    /// cross(Σ c·P, d) = 0 (one row), with the orientation check Σ c·P · `orient` > 0.
    Cross {
        name: &'static str,
        terms: ETerms,
        direction: [f64; 2],
        orient: Option<[f64; 2]>,
    },
    /// Point on a line and tangent along it (two rows), tangent · `orient` > 0.
    Line {
        point: ETerms,
        tangent: ETerms,
        origin: [f64; 2],
        direction: [f64; 2],
        orient: [f64; 2],
    },
    /// A residual over slots, with the check its solved state must pass (which receives the
    /// solved values of the constraint's free parameters).
    General {
        residual: Arc<dyn DynResidual>,
        slots: Vec<Slot>,
        check: Option<Arc<dyn SolvedCheck>>,
    },
    /// P_target = P_base + t·direction with t > 0 a new unknown (P_target = t·direction when
    /// there is no base: a Hermite or composite end tangent, which is itself an unknown block);
    /// `fallback` is the row form used when the target cannot be eliminated.
    Eliminate {
        curve: EntityId,
        target: usize,
        base: Option<usize>,
        direction: [f64; 2],
        fallback: Box<Piece>,
    },
}

/// The pieces of one constraint (most kinds write one to three). A `Vec`, not an inline
/// array: a piece is a few hundred bytes, and the builder moves every constraint's list around
/// (an inline list of three made each move a kilobyte copy and the component's list of lists
/// one large allocation).
pub(crate) type Pieces = Vec<Piece>;

/// The basis of a curve entity and the slots of all its control points, in order.
///
/// # Errors
/// [`crate::ground::errors::Error::UnknownEntity`]; [`crate::ground::errors::Error::WrongEntityKind`] for a non-curve.
pub(crate) fn curve_slots(
    lookup: &dyn crate::ground::lookup::EntityLookup,
    id: EntityId,
) -> crate::ground::errors::Result<(crate::ground::curve_eval::CurveBasis, Vec<Slot>)> {
    let e = lookup.lookup(id)?;
    let basis = crate::ground::curve_eval::CurveBasis::of(e).ok_or(
        crate::ground::errors::Error::WrongEntityKind {
            entity: id,
            expected: "curve",
            found: e.kind_name(),
        },
    )?;
    let slots = (0..e.points().len()).map(|j| Slot::Point(id, j)).collect();
    Ok((basis, slots))
}

/// The pieces of a constraint that may be relaxed (a priority above 0), every binding written
/// as rows instead: a fixed point becomes P − P_now = 0, a fixed circle's radius r − r_now = 0,
/// an eliminated tangent its row form. A binding cannot give way; rows can.
///
/// # Errors
/// [`crate::ground::errors::Error::UnknownEntity`] for an entity the sketch does not hold.
pub(crate) fn as_rows(
    lookup: &dyn crate::ground::lookup::EntityLookup,
    pieces: Pieces,
) -> crate::ground::errors::Result<Pieces> {
    let mut out = Pieces::new();
    let fixed_point = |e: EntityId, j: usize, at: nalgebra::Point2<f64>| {
        let mut terms = ETerms::new();
        terms.push((e, j, 1.0));
        Piece::Combination {
            name: "fixed",
            terms,
            target: [at.x, at.y],
        }
    };
    for piece in pieces {
        match piece {
            Piece::FixPoint(e, j) => {
                let at = lookup.lookup(e)?.points()[j];
                out.push(fixed_point(e, j, at));
            }
            Piece::FixEntity(e) => {
                let entity = lookup.lookup(e)?;
                for (j, at) in entity.points().iter().enumerate() {
                    out.push(fixed_point(e, j, *at));
                }
                // The scalar block (a circle's radius, an ellipse's b) held by a row.
                for value in entity.scalars() {
                    out.push(Piece::General {
                        residual: Arc::new(crate::residuals::affine::RadiusValue::new(value)),
                        slots: vec![Slot::Radius(e)],
                        check: None,
                    });
                }
            }
            Piece::Eliminate { fallback, .. } => out.push(*fallback),
            other => out.push(other),
        }
    }
    Ok(out)
}
