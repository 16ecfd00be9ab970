//! Plain descriptions of constraints and of failed solves, naming each constraint by its id
//! and kind ("constraint 4 (G1 join)"): the words the CLI, the editor and the Python package
//! show a user, where [`Error`]'s own message knows only the ids.

use camber_solve::ConstraintId;

use crate::ground::errors::Error;
use crate::ground::ids::{ARC_ROW, DRAG_CONSTRAINT};
use crate::sketch::Sketch;

/// Constraints named one by one in a "not solved" message (the rest are counted).
const NOT_SOLVED_LISTED: usize = 20;

/// # Descriptions
impl Sketch {
    /// "constraint 4 (G1 join)", "the drag target" for a drag's own pin, or "constraint 4" when
    /// the id is not in the sketch.
    ///
    /// ```
    /// use camber_sketch::constraints::Fixed;
    /// use camber_sketch::{ConstraintId, PointRef, Sketch};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let p = s.add_point(Point2::new(0.0, 0.0))?;
    /// let c = s.add_constraint(Fixed::point(PointRef::Point(p)))?;
    /// assert_eq!(s.describe_constraint(c), format!("constraint {} (fixed)", c.0));
    /// assert_eq!(s.describe_constraint(ConstraintId(99)), "constraint 99");
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    pub fn describe_constraint(&self, id: ConstraintId) -> String {
        if id == DRAG_CONSTRAINT {
            return "the drag target".to_owned();
        }
        if id == ARC_ROW {
            return "an arc's own row (its end on its circle)".to_owned();
        }
        match self.constraint(id) {
            Ok(c) => format!("{id} ({})", c.kind_name()),
            Err(_) => id.to_string(),
        }
    }

    /// A comma-separated list of [`Sketch::describe_constraint`], or "none".
    pub fn describe_constraints(&self, ids: &[ConstraintId]) -> String {
        if ids.is_empty() {
            "none".to_owned()
        } else {
            ids.iter()
                .map(|&id| self.describe_constraint(id))
                .collect::<Vec<_>>()
                .join(", ")
        }
    }

    /// An error of this sketch in plain words: conflicts, redundancies, unsatisfied and
    /// unsolved constraints named by id and kind (the largest residuals first, at most twenty
    /// named); any other error in its own words.
    pub fn describe_error(&self, e: &Error) -> String {
        match e {
            Error::Conflicting { constraints } => format!(
                "conflicting constraints: {}",
                self.describe_constraints(constraints)
            ),
            Error::Redundant { constraints } => format!(
                "redundant constraints: {}",
                self.describe_constraints(constraints)
            ),
            Error::NotSatisfied { failed } => format!(
                "constraints not satisfied: {}",
                failed
                    .iter()
                    .map(|(id, g)| format!("{} (|g| = {g:.3e})", self.describe_constraint(*id)))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            Error::OrientationFlipped { constraint, dot } => format!(
                "{} would flip its tangent orientation (signed dot {dot:.3e})",
                self.describe_constraint(*constraint)
            ),
            Error::Solve(camber_solve::Error::NotSolved {
                tried, residuals, ..
            }) => {
                // Every constraint left above 1e-9, largest first, by id and kind.
                let mut above: Vec<_> = residuals
                    .iter()
                    .filter(|r| r.max_abs > 1e-9 || r.max_abs.is_nan())
                    .collect();
                above.sort_by(|a, b| b.max_abs.total_cmp(&a.max_abs));
                let mut named: Vec<String> = above
                    .iter()
                    .take(NOT_SOLVED_LISTED)
                    .map(|r| {
                        format!(
                            "{} |g| = {:.3e}",
                            self.describe_constraint(r.constraint),
                            r.max_abs
                        )
                    })
                    .collect();
                if above.len() > NOT_SOLVED_LISTED {
                    named.push(format!("and {} more", above.len() - NOT_SOLVED_LISTED));
                }
                format!(
                    "not solved (nothing proves a conflict): {tried}; residual per constraint: {}",
                    if named.is_empty() {
                        "none above 1e-9".to_owned()
                    } else {
                        named.join(", ")
                    }
                )
            }
            other => other.to_string(),
        }
    }
}
