//! What a constraint kind compiles with: the entities it reads, checked for kind, the linear
//! maps from entity points to curve points and tangents, the slots of general residuals, and
//! the pieces it writes (`component::piece`).
//!
//! Compiling is also validation: a constraint is accepted into a sketch exactly when it
//! compiles against the sketch's entities (ids, indices, parameters inside domains, finite
//! numbers, non-zero directions, entities of the right kind).

use std::sync::Arc;

use camber_solve::DynResidual;
use nalgebra::{Point2, Vector2};

use crate::constraints::check::SolvedCheck;
use crate::constraints::piece::{curve_slots, ETerms, Piece, Pieces, Slot};
use crate::ground::curve_eval::CurveBasis;
use crate::ground::entity::{combine, Entity, Terms};
use crate::ground::errors::{Error, Result};
use crate::ground::ids::{EntityId, PointRef};
use crate::ground::lookup::EntityLookup;
use crate::ground::vocabulary::Contact;
use crate::residuals::Param;

/// The compilation of one constraint: the entities it may read, and the pieces it wrote.
///
/// A kind whose pieces depend on where the entities are now (not only on their kind, shape and
/// ids: a target read from the current points, a reference length) reads them through
/// `Compiler::current` or `Compiler::entity_values` (crate-internal), which mark the compilation as
/// reading values: a prepared component may then not be refreshed with another sketch's values
/// (`crate::session::batch`).
pub struct Compiler<'a> {
    lookup: &'a dyn EntityLookup,
    pieces: Pieces,
    reads_values: std::cell::Cell<bool>,
}

impl std::fmt::Debug for Compiler<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Compiler")
            .field("pieces", &self.pieces.len())
            .finish()
    }
}

impl<'a> Compiler<'a> {
    /// A compilation against the entities of `lookup`.
    pub(crate) fn new(lookup: &'a dyn EntityLookup) -> Self {
        Self {
            lookup,
            // Most kinds write one piece.
            pieces: Pieces::with_capacity(1),
            reads_values: std::cell::Cell::new(false),
        }
    }

    /// The pieces written, and whether they depend on the entities' current values (see the
    /// type's documentation).
    pub(crate) fn finish(self) -> (Pieces, bool) {
        (self.pieces, self.reads_values.get())
    }

    /// Writes a piece.
    pub(crate) fn push(&mut self, piece: Piece) {
        self.pieces.push(piece);
    }

    /// Writes a general residual over slots, with the check of the solved state it needs.
    pub(crate) fn residual(
        &mut self,
        residual: impl DynResidual + 'static,
        slots: Vec<Slot>,
        check: Option<Arc<dyn SolvedCheck>>,
    ) {
        self.pieces.push(Piece::General {
            residual: Arc::new(residual),
            slots,
            check,
        });
    }

    /// Writes Σ c·P − target = 0 (two affine rows).
    pub(crate) fn combination(&mut self, name: &'static str, terms: ETerms, target: [f64; 2]) {
        self.pieces.push(Piece::Combination {
            name,
            terms,
            target,
        });
    }

    /// The value of the sketch's named parameter `name`, if it has one.
    pub(crate) fn parameter(&self, name: &str) -> Option<f64> {
        self.lookup.parameter(name)
    }

    /// An entity, for its kind and shape (its current points and scalars are read through
    /// [`Compiler::entity_values`]).
    pub(crate) fn entity(&self, id: EntityId) -> Result<&'a Entity> {
        self.lookup.lookup(id)
    }

    /// An entity whose current points or scalars the pieces depend on: marks the compilation
    /// as reading values.
    pub(crate) fn entity_values(&self, id: EntityId) -> Result<&'a Entity> {
        self.reads_values.set(true);
        self.lookup.lookup(id)
    }

    /// An entity that must pass `ok`, else [`Error::WrongEntityKind`] saying `expected`.
    fn kind(
        &self,
        id: EntityId,
        expected: &'static str,
        ok: fn(&Entity) -> bool,
    ) -> Result<&'a Entity> {
        let e = self.entity(id)?;
        if ok(e) {
            Ok(e)
        } else {
            Err(Error::WrongEntityKind {
                entity: id,
                expected,
                found: e.kind_name(),
            })
        }
    }

    /// A curve entity (line, Bézier, B-spline, NURBS).
    pub(crate) fn curve(&self, id: EntityId) -> Result<&'a Entity> {
        self.kind(id, "curve", Entity::is_curve)
    }

    /// A line entity's ends.
    pub(crate) fn line(&self, id: EntityId) -> Result<[Point2<f64>; 2]> {
        match self.kind(id, "line", |e| matches!(e, Entity::Line(_)))? {
            Entity::Line(ends) => Ok(*ends),
            _ => Err(Error::UnknownEntity { entity: id }),
        }
    }

    /// A circle entity (its centre and radius).
    pub(crate) fn circle(&self, id: EntityId) -> Result<(Point2<f64>, f64)> {
        match self.kind(id, "circle", |e| matches!(e, Entity::Circle { .. }))? {
            Entity::Circle { center, radius } => Ok((*center, *radius)),
            _ => Err(Error::UnknownEntity { entity: id }),
        }
    }

    /// The parametric domain of a curve.
    pub(crate) fn domain(&self, curve: EntityId) -> Result<(f64, f64)> {
        let e = self.entity(curve)?;
        e.domain().ok_or(Error::WrongEntityKind {
            entity: curve,
            expected: "curve",
            found: e.kind_name(),
        })
    }

    /// Appends the terms of a point reference, times `sign`.
    pub(crate) fn point_terms(&self, r: PointRef, sign: f64, out: &mut ETerms) -> Result<()> {
        let t = self.entity(r.entity())?.resolve(r)?;
        with_entity(r.entity(), &t, sign, out);
        Ok(())
    }

    /// The terms of C⁽ᵏ⁾(u) of a curve, k = `order` ∈ {0, 1}.
    pub(crate) fn curve_terms(&self, curve: EntityId, u: f64, order: usize) -> Result<ETerms> {
        finite("parameter", u)?;
        let e = self.entity(curve)?;
        let t = match end_terms(e, u, order.min(1)) {
            Some(t) => t,
            None => e.coefficients(curve, u, order)?,
        };
        let mut out = ETerms::new();
        with_entity(curve, &t, 1.0, &mut out);
        Ok(out)
    }

    /// The terms of C⁽ᵏ⁾(u) of a curve for k = `order` ∈ {0, 1, 2} (the second derivative
    /// from the basis' derivatives at u, rational quotient included).
    pub(crate) fn curve_derivative_terms(
        &self,
        curve: EntityId,
        u: f64,
        order: usize,
    ) -> Result<ETerms> {
        if order <= 1 {
            return self.curve_terms(curve, u, order);
        }
        finite("parameter", u)?;
        if let Some(t) = end_terms(self.entity(curve)?, u, order) {
            let mut out = ETerms::new();
            with_entity(curve, &t, 1.0, &mut out);
            return Ok(out);
        }
        let (lo, hi) = self.domain(curve)?;
        if u < lo || u > hi {
            return Err(Error::ParameterOutsideDomain {
                entity: curve,
                value: u,
                min: lo,
                max: hi,
            });
        }
        let (full, _) = self.curve_basis(curve)?;
        let (fixed, points) = full.at(u, 2);
        let mut out = ETerms::new();
        if let Some(c) = fixed.fixed_coefficients() {
            for (j, k) in points.iter().zip(c) {
                if k[2] != 0.0 {
                    out.push((curve, *j, k[2]));
                }
            }
        }
        Ok(out)
    }

    /// The current value of a combination.
    pub(crate) fn current(&self, terms: &ETerms) -> Result<[f64; 2]> {
        self.reads_values.set(true);
        let mut s = [0.0; 2];
        for (e, j, c) in terms {
            let v = combine(self.entity(*e)?.points(), &[(*j, *c)]);
            s[0] += v[0];
            s[1] += v[1];
        }
        Ok(s)
    }

    /// The single point block a reference denotes (a point, a control point, a line end, a
    /// circle centre, or the end of a curve clamped there).
    pub(crate) fn single_block(&self, r: PointRef) -> Result<(EntityId, usize)> {
        let e = self.entity(r.entity())?;
        match e.resolve(r)?.as_slice() {
            [(j, c)] if (c - 1.0).abs() <= 0.0 => Ok((r.entity(), *j)),
            _ => Err(Error::WrongEntityKind {
                entity: r.entity(),
                expected: "a single point block (point, control point or clamped end)",
                found: e.kind_name(),
            }),
        }
    }

    /// The basis of a curve and the slots of all its control points.
    pub(crate) fn curve_basis(&self, id: EntityId) -> Result<(CurveBasis, Vec<Slot>)> {
        self.curve(id)?;
        curve_slots(self.lookup, id)
    }

    /// The parameter of a curve's start or end and the basis of C′ there, restricted to the
    /// control points it reads (two at a clamped end), with their slots: an arc joined to a
    /// curve's end reads those points only, so its derivatives never carry the rest of the
    /// curve (on the bundled blade a drag update spent 80 % of its time in Hessians over every
    /// control point of both sides).
    pub(crate) fn curve_end_contact(
        &self,
        curve: EntityId,
        at_end: bool,
    ) -> Result<(CurveBasis, Vec<Slot>, f64)> {
        let (lo, hi) = self.domain(curve)?;
        let u = if at_end { hi } else { lo };
        let (basis, slots, _) = self.curve_contact(curve, Contact::At(u))?;
        Ok((basis, slots, u))
    }

    /// The basis, slots and parameter of a contact on `curve`: at a fixed parameter, the basis
    /// restricted to it and the slots of the control points it reads; at a free one, the whole
    /// curve and a new free slot for u bounded to the domain (the last slot).
    pub(crate) fn curve_contact(
        &self,
        curve: EntityId,
        u: Contact,
    ) -> Result<(CurveBasis, Vec<Slot>, Param)> {
        let (basis, mut slots) = self.curve_basis(curve)?;
        let v = u.value();
        let (lo, hi) = basis.domain();
        finite("parameter", v)?;
        if v < lo || v > hi {
            return Err(Error::ParameterOutsideDomain {
                entity: curve,
                value: v,
                min: lo,
                max: hi,
            });
        }
        Ok(match u {
            Contact::At(_) => {
                let (basis, points) = basis.at(v, 1);
                let slots = points.iter().map(|j| Slot::Point(curve, *j)).collect();
                (basis, slots, Param::Fixed(v))
            }
            Contact::Free(_) => {
                slots.push(Slot::Free { start: v, lo, hi });
                (basis, slots, Param::Block)
            }
        })
    }
}

/// The terms of C⁽ᵏ⁾(u) in closed form when u is an end of the domain of a clamped
/// polynomial curve ([`crate::ground::curve_ends`]); `None` where the general evaluation is needed.
fn end_terms(e: &Entity, u: f64, order: usize) -> Option<Terms> {
    crate::ground::curve_ends::end_derivative(e, crate::ground::curve_ends::which_end(e, u)?, order)
}

fn with_entity(id: EntityId, terms: &Terms, sign: f64, out: &mut ETerms) {
    for (j, c) in terms {
        out.push((id, *j, sign * c));
    }
}

/// A finite number, else [`Error::NonFinite`] naming it.
pub(crate) fn finite(what: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::NonFinite {
            what,
            index: 0,
            value,
        })
    }
}

/// A finite, non-zero direction as an array.
pub(crate) fn check_direction(what: &'static str, v: &Vector2<f64>) -> Result<[f64; 2]> {
    crate::ground::entity::check_finite2(what, 0, [v.x, v.y])?;
    if v.x.abs() <= 0.0 && v.y.abs() <= 0.0 {
        return Err(Error::ZeroDirection {
            what,
            x: v.x,
            y: v.y,
        });
    }
    Ok([v.x, v.y])
}

/// A positive finite number, else [`Error::NotPositive`].
pub(crate) fn positive(what: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::NotPositive { what, value })
    }
}

/// Two different entities, else [`Error::SameEntity`].
pub(crate) fn distinct(a: EntityId, b: EntityId) -> Result<()> {
    if a == b {
        Err(Error::SameEntity { entity: a })
    } else {
        Ok(())
    }
}
