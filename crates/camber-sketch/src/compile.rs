//! Compiling a constraint into linear pieces over entity points: the step shared by
//! validation (a constraint is accepted when it compiles) and by problem building.
//!
//! A piece refers to points as (entity, point index, coefficient) terms; [`crate::build`] maps
//! them to parameter blocks of a component's problem.

use nalgebra::Vector2;
use smallvec::SmallVec;

use crate::constraint::{Constraint, FixTarget, TangentForm, Target};
use crate::entity::{combine, Entity, Terms};
use crate::errors::{Error, Result};
use crate::ids::{EntityId, PointRef};

/// A combination Σ c·P over points of several entities: (entity, point index, coefficient).
pub(crate) type ETerms = SmallVec<[(EntityId, usize, f64); 8]>;

/// One linear piece of a compiled constraint.
#[derive(Debug, Clone)]
pub(crate) enum Piece {
    /// Every block of the entity is fixed.
    FixEntity(EntityId),
    /// One point block is fixed.
    FixPoint(EntityId, usize),
    /// Σ c·P − target = 0 (two rows). `fixed` marks a `Fixed` constraint in row form.
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
    /// A user residual reading one block per point.
    Custom {
        residual: std::sync::Arc<dyn camber_solve::DynResidual>,
        points: Vec<(EntityId, usize)>,
    },
    /// A nonlinear residual over slots (points, radii, new contact parameters), with the check
    /// its solved value must pass.
    General {
        name: &'static str,
        residual: std::sync::Arc<dyn camber_solve::DynResidual>,
        slots: Vec<crate::general::Slot>,
        check: Option<crate::general::Check>,
    },
    /// P_target = P_base + t·direction with t > 0 a new unknown; `fallback` is the row form
    /// used when the target cannot be eliminated.
    Eliminate {
        curve: EntityId,
        target: usize,
        base: usize,
        direction: [f64; 2],
        fallback: Box<Piece>,
    },
}

/// Looks up an entity.
pub(crate) trait EntityLookup {
    /// The entity with that id.
    fn lookup(&self, id: EntityId) -> Result<&Entity>;
    /// The weight of the entity's point `index` in the minimum-norm metric (1 unless set).
    fn weight(&self, _id: EntityId, _index: usize) -> f64 {
        1.0
    }
}

fn with_entity(id: EntityId, terms: &Terms, sign: f64, out: &mut ETerms) {
    for (j, c) in terms {
        out.push((id, *j, sign * c));
    }
}

/// A finite, non-zero direction as an array.
pub(crate) fn check_direction(what: &'static str, v: &Vector2<f64>) -> Result<[f64; 2]> {
    crate::entity::check_finite2(what, 0, [v.x, v.y])?;
    if v.x.abs() <= 0.0 && v.y.abs() <= 0.0 {
        return Err(Error::ZeroDirection {
            what,
            x: v.x,
            y: v.y,
        });
    }
    Ok([v.x, v.y])
}

fn check_u(u: f64) -> Result<()> {
    if u.is_finite() {
        Ok(())
    } else {
        Err(Error::NonFinite {
            what: "parameter",
            index: 0,
            value: u,
        })
    }
}

fn point_terms(lookup: &impl EntityLookup, r: PointRef, sign: f64, out: &mut ETerms) -> Result<()> {
    let e = lookup.lookup(r.entity())?;
    let t = e.resolve(r)?;
    with_entity(r.entity(), &t, sign, out);
    Ok(())
}

fn curve_terms(
    lookup: &impl EntityLookup,
    curve: EntityId,
    u: f64,
    order: usize,
) -> Result<ETerms> {
    check_u(u)?;
    let t = lookup.lookup(curve)?.coefficients(curve, u, order)?;
    let mut out = ETerms::new();
    with_entity(curve, &t, 1.0, &mut out);
    Ok(out)
}

fn domain(lookup: &impl EntityLookup, curve: EntityId) -> Result<(f64, f64)> {
    let e = lookup.lookup(curve)?;
    e.domain().ok_or(Error::WrongEntityKind {
        entity: curve,
        expected: "curve",
        found: e.kind_name(),
    })
}

/// The current value of a combination (for `Fixed` in row form).
fn current(lookup: &impl EntityLookup, terms: &ETerms) -> Result<[f64; 2]> {
    let mut s = [0.0; 2];
    for (e, j, c) in terms {
        let v = combine(lookup.lookup(*e)?.points(), &[(*j, *c)]);
        s[0] += v[0];
        s[1] += v[1];
    }
    Ok(s)
}

/// Compiles a constraint against the current entities, validating every id, index, parameter
/// and number on the way.
pub(crate) fn compile(lookup: &impl EntityLookup, c: &Constraint) -> Result<SmallVec<[Piece; 3]>> {
    let mut out: SmallVec<[Piece; 3]> = SmallVec::new();
    let name = c.kind_name();
    match c {
        Constraint::Fixed(FixTarget::Entity(e)) => {
            lookup.lookup(*e)?;
            out.push(Piece::FixEntity(*e));
        }
        Constraint::Fixed(FixTarget::Point(r)) => {
            let t = lookup.lookup(r.entity())?.resolve(*r)?;
            match t.as_slice() {
                [(j, c)] if (c - 1.0).abs() <= 0.0 => out.push(Piece::FixPoint(r.entity(), *j)),
                _ => {
                    let mut terms = ETerms::new();
                    with_entity(r.entity(), &t, 1.0, &mut terms);
                    let target = current(lookup, &terms)?;
                    out.push(Piece::Combination {
                        name,
                        terms,
                        target,
                    });
                }
            }
        }
        Constraint::Coincident(a, b) => {
            let mut terms = ETerms::new();
            point_terms(lookup, *a, 1.0, &mut terms)?;
            point_terms(lookup, *b, -1.0, &mut terms)?;
            out.push(Piece::Combination {
                name,
                terms,
                target: [0.0; 2],
            });
        }
        Constraint::PointAtParameter { curve, u, target } => {
            let mut terms = curve_terms(lookup, *curve, *u, 0)?;
            let target = match target {
                Target::At(p) => {
                    crate::entity::check_point("target", 0, p)?;
                    [p.x, p.y]
                }
                Target::Point(r) => {
                    point_terms(lookup, *r, -1.0, &mut terms)?;
                    [0.0; 2]
                }
            };
            out.push(Piece::Combination {
                name,
                terms,
                target,
            });
        }
        Constraint::TangentVectorAt { curve, u, vector } => {
            let terms = curve_terms(lookup, *curve, *u, 1)?;
            crate::entity::check_finite2("tangent vector", 0, [vector.x, vector.y])?;
            out.push(Piece::Combination {
                name,
                terms,
                target: [vector.x, vector.y],
            });
        }
        Constraint::DirectionalTangentAt {
            curve,
            u,
            direction,
            sense,
        } => {
            let d = check_direction("tangent", direction)?;
            out.push(Piece::Cross {
                name,
                terms: curve_terms(lookup, *curve, *u, 1)?,
                direction: d,
                orient: Some([sense.sign() * d[0], sense.sign() * d[1]]),
            });
        }
        Constraint::StartTangent {
            curve,
            direction,
            sense,
            form,
        }
        | Constraint::EndTangent {
            curve,
            direction,
            sense,
            form,
        } => {
            let at_end = matches!(c, Constraint::EndTangent { .. });
            let d = check_direction("tangent", direction)?;
            let (a, b) = domain(lookup, *curve)?;
            let u = if at_end { b } else { a };
            let orient = [sense.sign() * d[0], sense.sign() * d[1]];
            let row = Piece::Cross {
                name,
                terms: curve_terms(lookup, *curve, u, 1)?,
                direction: d,
                orient: Some(orient),
            };
            match form {
                TangentForm::Row => out.push(row),
                TangentForm::Elimination => {
                    let e = lookup.lookup(*curve)?;
                    if !e.is_clamped(at_end) {
                        return Err(Error::NotClampedEnd {
                            entity: *curve,
                            end: if at_end { "end" } else { "start" },
                        });
                    }
                    let n = e.points().len();
                    // Start: P₁ = P₀ + t·s·T. End: Pₙ₋₁ = Pₙ − t·s·T.
                    let (target, base, direction) = if at_end {
                        (n - 2, n - 1, [-orient[0], -orient[1]])
                    } else {
                        (1, 0, orient)
                    };
                    out.push(Piece::Eliminate {
                        curve: *curve,
                        target,
                        base,
                        direction,
                        fallback: Box::new(row),
                    });
                }
            }
        }
        Constraint::TangentToLineAt {
            curve,
            u,
            point,
            direction,
            sense,
        } => {
            let d = check_direction("line", direction)?;
            crate::entity::check_point("line point", 0, point)?;
            out.push(Piece::Line {
                point: curve_terms(lookup, *curve, *u, 0)?,
                tangent: curve_terms(lookup, *curve, *u, 1)?,
                origin: [point.x, point.y],
                direction: d,
                orient: [sense.sign() * d[0], sense.sign() * d[1]],
            });
        }
        Constraint::G1Join {
            first,
            second,
            direction,
        } => {
            let d = check_direction("joint", direction)?;
            let (_, b) = domain(lookup, *first)?;
            let (a, _) = domain(lookup, *second)?;
            let mut joint = ETerms::new();
            point_terms(lookup, PointRef::End(*first), 1.0, &mut joint)?;
            point_terms(lookup, PointRef::Start(*second), -1.0, &mut joint)?;
            out.push(Piece::Combination {
                name,
                terms: joint,
                target: [0.0; 2],
            });
            for (curve, u) in [(*first, b), (*second, a)] {
                out.push(Piece::Cross {
                    name,
                    terms: curve_terms(lookup, curve, u, 1)?,
                    direction: d,
                    orient: Some(d),
                });
            }
        }
        Constraint::Custom(custom) => {
            let mut points = Vec::with_capacity(custom.points.len());
            for r in &custom.points {
                let e = lookup.lookup(r.entity())?;
                match e.resolve(*r)?.as_slice() {
                    [(j, c)] if (c - 1.0).abs() <= 0.0 => points.push((r.entity(), *j)),
                    _ => {
                        return Err(Error::WrongEntityKind {
                            entity: r.entity(),
                            expected: "a single point block for a custom constraint",
                            found: e.kind_name(),
                        })
                    }
                }
            }
            out.push(Piece::Custom {
                residual: custom.residual.clone(),
                points,
            });
        }
        other => {
            crate::general::compile_general(lookup, other, &mut out)?;
        }
    }
    Ok(out)
}
