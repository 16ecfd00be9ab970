//! Contact by iterative displacement on the linear path: the blade-design method, kept for
//! comparison with the Newton and SLSQP solves of the same sketch.
//!
//! A tangency to a fixed circle or line is nonlinear only because the contact point is unknown.
//! Guess it, and the rest is affine: "C(s) = T" and "C′(s) is parallel to the target's tangent
//! at T" are two plus one rows linear in the control points for a fixed parameter s. Each round
//!
//! 1. measures, for every contact, the signed gap G(s) of the curve to its target (positive on
//!    the intended side) and takes the parameter s* where it is least: the closest approach
//!    when the curve misses, the point of deepest overshoot when it crosses (a contact at a
//!    given parameter keeps it);
//! 2. prescribes the move of C(s*) onto the nearest target point T (the foot of the radius or
//!    of the perpendicular) and the tangent direction of the target at T, oriented as the
//!    contact asks, and solves the component's affine constraints with these rows by the
//!    minimum-norm step from the current curve;
//! 3. stops when every gap is within tolerance at its s*, every tangent is parallel to its
//!    target's, and no curve crosses its target anywhere.
//!
//! The converged state is then handed to the sketch's own solve with the contacts as they were
//! (free parameters started at s*), which validates it, usually with no iteration left to do,
//! and stores the contact parameters. When the rounds do not converge, or a round's linear
//! system is inconsistent, the sketch's own solve (its usual selection: Newton, SLSQP within
//! its limits, least squares) solves the original sketch from its own start instead. Either
//! way the sketch changes only on success.

use camber_solve::ConstraintId;

use crate::constraints::check::ContactTarget;
use crate::constraints::{
    Constraint, DirectionalTangentAt, EndTangent, PointAtParameter, StartTangent,
};
use crate::ground::errors::{Error, Result};
use crate::ground::ids::{EntityId, PointRef};
use crate::ground::vocabulary::{Contact, FixTarget, Sense, TangentForm, Target};
use crate::session::solve::SketchReport;
use crate::session::starts::{cross, least, Shape};
use crate::sketch::Sketch;

/// Halvings of a round's move tried when its linear solve fails.
const MAX_HALVINGS: i32 = 4;

/// Limits of [`Sketch::solve_by_displacement`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DisplacementOptions {
    /// Most rounds before the sketch's own solve takes over (≥ 1).
    pub max_rounds: usize,
    /// Largest gap and tangent mismatch (length units, and sine of the angle) accepted as
    /// converged; also the penetration below which a curve does not count as crossing. The
    /// validating solve then holds every constraint to the sketch's own tolerance.
    pub tolerance: f64,
    /// Samples of the curve per round and contact for the least gap (≥ 8; refined by golden
    /// section between the best sample's neighbours).
    pub samples: usize,
}

impl Default for DisplacementOptions {
    fn default() -> Self {
        Self {
            max_rounds: 50,
            tolerance: 1e-6,
            samples: 200,
        }
    }
}

/// What [`Sketch::solve_by_displacement`] did.
#[derive(Debug, Clone, PartialEq)]
pub struct DisplacementReport {
    /// Rounds of linear solves run.
    pub rounds: usize,
    /// Whether the rounds converged (otherwise the sketch's own solve solved it from its start).
    pub converged: bool,
    /// Largest gap or tangent mismatch before the first round and after every round (length
    /// units / sine; `rounds` + 1 entries when there were contacts), for studies of the
    /// method's convergence.
    pub history: Vec<f64>,
    /// The report of the final solve: the validating solve after convergence, or the sketch's
    /// own solve from its start.
    pub report: SketchReport,
}

/// A contact the method handles: a curve tangent to a fixed circle or line.
#[derive(Debug, Clone, Copy)]
struct Contact2 {
    id: ConstraintId,
    curve: EntityId,
    target: Shape,
    /// The given parameter, or `None` for a free one.
    at: Option<f64>,
}

impl Sketch {
    /// Solves the sketch's contacts with fixed circles and lines by iterative displacement on
    /// the linear path (see the module documentation), then validates the result with the
    /// sketch's own solve, which also solves the sketch from its original start when the rounds do
    /// not converge. Every other
    /// constraint must be affine (they are solved with the rows of each round); circles and
    /// lines that are contact targets must be fixed.
    ///
    /// ```
    /// use camber_geom::BezierCurve2;
    /// use camber_sketch::constraints::{Fixed, TangentToCircle};
    /// use camber_sketch::{CircleSide, Contact, PointRef, Rotation, Sketch};
    /// use camber_sketch::displacement::DisplacementOptions;
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let arc = s.add_bezier(BezierCurve2::try_new(vec![
    ///     Point2::new(-2.0, 1.3), Point2::new(-0.7, 1.5), Point2::new(0.7, 1.5), Point2::new(2.0, 1.3),
    /// ])?)?;
    /// let circle = s.add_circle(Point2::new(0.0, 0.0), 1.0)?;
    /// s.add_constraint(Fixed::entity(circle))?;
    /// for end in [PointRef::Start(arc), PointRef::End(arc)] {
    ///     s.add_constraint(Fixed::point(end))?;
    /// }
    /// s.add_constraint(TangentToCircle {
    ///     curve: arc, circle, u: Contact::Free(0.5),
    ///     side: CircleSide::Outside, rotation: Rotation::Clockwise,
    /// })?;
    /// let report = s.solve_by_displacement(&DisplacementOptions::default())?;
    /// assert!(report.converged);
    /// // The top of the arc now touches the circle.
    /// assert!((s.curve_point(arc, 0.5)?.y - 1.0).abs() < 1e-6);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidOption`] for bad options, [`Error::TargetNotFixed`] for a contact with a
    /// circle or line that may move; the errors of the validating solve or of the sketch's own solve. Nothing
    /// changes on error.
    pub fn solve_by_displacement(
        &mut self,
        options: &DisplacementOptions,
    ) -> Result<DisplacementReport> {
        if options.max_rounds == 0
            || options.samples < 8
            || !(options.tolerance.is_finite() && options.tolerance > 0.0)
        {
            return Err(Error::InvalidOption {
                what: "displacement options",
                detail: format!(
                    "need max_rounds ≥ 1, samples ≥ 8 and a positive tolerance, got {options:?}"
                ),
            });
        }
        let contacts = self.fixed_contacts()?;
        let mut work = self.clone();
        for c in &contacts {
            work.remove_constraint(c.id)?;
        }
        let mut history = Vec::new();
        let mut params: Vec<f64> = Vec::with_capacity(contacts.len());
        let mut converged = false;
        let mut rounds = 0;
        if !contacts.is_empty() {
            while rounds < options.max_rounds {
                let (worst, rows) = work.displacement_rows(&contacts, options, &mut params)?;
                history.push(worst);
                if worst <= options.tolerance {
                    converged = true;
                    break;
                }
                rounds += 1;
                // The full move first; when its linear solve fails (typically a tangent the
                // cross-product row let reverse), a fraction of it.
                let mut next = None;
                let mut rows = rows;
                for halving in 0..=MAX_HALVINGS {
                    if halving > 0 {
                        let fraction = 0.5_f64.powi(halving);
                        rows = work
                            .displacement_rows_scaled(&contacts, options, &mut params, fraction)?
                            .1;
                    }
                    let mut round = work.clone();
                    let mut added = Vec::with_capacity(rows.len());
                    for row in rows.drain(..) {
                        added.push(round.add_constraint(row)?);
                    }
                    if round.solve().is_ok() {
                        for id in added {
                            round.remove_constraint(id)?;
                        }
                        next = Some(round);
                        break;
                    }
                }
                let Some(round) = next else {
                    break;
                };
                work = round;
            }
            if !converged {
                let (worst, _) = work.displacement_rows(&contacts, options, &mut params)?;
                converged = worst <= options.tolerance;
                history.push(worst);
            }
        }
        let mut result = self.clone();
        if converged {
            for (id, e) in work.entities() {
                for (i, p) in e.points().iter().enumerate() {
                    if result.point(PointRef::Control(id, i))? != *p {
                        result.set_point(PointRef::Control(id, i), *p)?;
                    }
                }
            }
            for (c, s) in contacts.iter().zip(&params) {
                if c.at.is_none() {
                    // The free contact parameter starts the validating solve at s*.
                    result.store_free(&[(c.id, 0, *s)]);
                    result.mark_dirty(c.curve);
                }
            }
        }
        let report = result.solve()?;
        *self = result;
        Ok(DisplacementReport {
            rounds,
            converged,
            history,
            report,
        })
    }

    /// The contacts the method handles (tangencies to fixed circles and lines), in id order.
    fn fixed_contacts(&self) -> Result<Vec<Contact2>> {
        let fixed = |id: EntityId| {
            self.constraints().any(
                |(_, c)| matches!(c, Constraint::Fixed(f) if f.target == FixTarget::Entity(id)),
            )
        };
        let not_fixed = |constraint: ConstraintId, entity: EntityId| Error::TargetNotFixed {
            constraint,
            entity,
        };
        let at = |u: &Contact| match u {
            Contact::At(v) => Some(*v),
            Contact::Free(_) => None,
        };
        let mut out = Vec::new();
        for (id, c) in self.constraints() {
            let Some(spec) = c.contact() else {
                continue;
            };
            let target_entity = match spec.target {
                ContactTarget::Circle { circle, .. } => circle,
                ContactTarget::Ellipse { ellipse, .. } => ellipse,
                ContactTarget::Line { line, .. } => line,
            };
            if !fixed(target_entity) {
                return Err(not_fixed(id, target_entity));
            }
            let target = Shape::of(&spec, self)?;
            out.push(Contact2 {
                id,
                curve: spec.curve,
                at: at(&spec.u),
                target,
            });
        }
        Ok(out)
    }

    /// One round's measurement: the worst gap, tangent mismatch or crossing over all contacts,
    /// and the rows that move each contact point onto its target (plus a push-back row where a
    /// contact at a given parameter crosses elsewhere). `params` receives every contact's s*.
    fn displacement_rows(
        &self,
        contacts: &[Contact2],
        options: &DisplacementOptions,
        params: &mut Vec<f64>,
    ) -> Result<(f64, Vec<Constraint>)> {
        self.displacement_rows_scaled(contacts, options, params, 1.0)
    }

    /// [`Sketch::displacement_rows`] asking only the fraction `fraction` ∈ (0, 1] of each move:
    /// the point goes that part of the way to the foot, the tangent turns that part of the
    /// angle.
    fn displacement_rows_scaled(
        &self,
        contacts: &[Contact2],
        options: &DisplacementOptions,
        params: &mut Vec<f64>,
        fraction: f64,
    ) -> Result<(f64, Vec<Constraint>)> {
        params.clear();
        let mut worst: f64 = 0.0;
        let mut rows = Vec::with_capacity(3 * contacts.len());
        for c in contacts {
            let e = self.entity(c.curve)?;
            let (lo, hi) = e.domain().unwrap_or((0.0, 1.0));
            let gap = |s: f64| {
                e.point_tangent(s)
                    .map_or(f64::INFINITY, |(q, _)| c.target.gap(q))
            };
            let deepest = least(gap, lo, hi, options.samples);
            let s = c.at.unwrap_or(deepest);
            params.push(s);
            let Some((q, t)) = e.point_tangent(s) else {
                return Err(Error::UnknownEntity { entity: c.curve });
            };
            let (foot, direction) = c.target.foot(q);
            let goal = q + (foot - q) * fraction;
            let unit = if t.norm() > 0.0 {
                t / t.norm()
            } else {
                direction
            };
            let turned = unit + (direction - unit) * fraction;
            let asked = if fraction < 1.0 && turned.norm() > 1e-3 {
                turned / turned.norm()
            } else {
                direction
            };
            let speed = t.norm();
            let turn = if speed > 0.0 {
                let sine = cross(t, direction) / speed;
                // A tangent against the asked orientation is as far off as it gets.
                if t.dot(&direction) > 0.0 {
                    sine.abs()
                } else {
                    1.0
                }
            } else {
                1.0
            };
            worst = worst.max(c.target.gap(q).abs()).max(turn);
            rows.push(Constraint::from(PointAtParameter {
                curve: c.curve,
                u: s,
                target: Target::At(goal),
            }));
            // At a curve's end, the paper's form: the neighbouring control point on the tangent
            // ray, P₁ = P₀ + t·T, which cannot reverse the way a cross-product row can.
            rows.push(if s <= lo && e.is_clamped(false) {
                Constraint::from(StartTangent {
                    curve: c.curve,
                    direction: asked,
                    sense: Sense::Agree,
                    form: TangentForm::Elimination,
                })
            } else if s >= hi && e.is_clamped(true) {
                Constraint::from(EndTangent {
                    curve: c.curve,
                    direction: asked,
                    sense: Sense::Agree,
                    form: TangentForm::Elimination,
                })
            } else {
                Constraint::from(DirectionalTangentAt {
                    curve: c.curve,
                    u: s,
                    direction: asked,
                    sense: Sense::Agree,
                })
            });
            let depth = gap(deepest);
            if c.at.is_some() && depth < -options.tolerance {
                worst = worst.max(-depth);
                if (deepest - s).abs() > 1e-6 * (hi - lo) {
                    let (qd, _) = e.point_tangent(deepest).unwrap_or((q, t));
                    rows.push(Constraint::from(PointAtParameter {
                        curve: c.curve,
                        u: deepest,
                        target: Target::At(qd + (c.target.foot(qd).0 - qd) * fraction),
                    }));
                }
            }
        }
        Ok((worst, rows))
    }
}
