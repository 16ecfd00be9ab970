//! The sketch's face of its parameters: define and change them, bind dimensions to
//! expressions of them, and re-solve what reads them.

use crate::constraints::Constraint;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::{ConstraintId, EntityId};
use crate::session::solve::SketchReport;
use crate::sketch::Sketch;

use crate::sketch::parameters::{apply, at_path, mentions, Binding, Parameter, Parameters};

/// What changing a parameter touched: the constraints that read it (their dimensions
/// re-evaluated, their expressions recompiled) and the entities whose components re-solve.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ParameterChange {
    /// Constraints whose dimension or rows read the parameter.
    pub constraints: Vec<ConstraintId>,
    /// Their entities (marked for the next solve).
    pub entities: Vec<EntityId>,
}

/// A parameter name: a name of the expression language, not one of its functions or
/// constants.
fn check_name(name: &str) -> Result<()> {
    let mut chars = name.chars();
    let ok = chars
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !ok || camber_expr::is_reserved(name) {
        return Err(Error::Expression(camber_expr::Error::Scope {
            column: 1,
            message: format!(
                "`{name}` cannot name a parameter (a letter or _, then letters, digits or _; not a function or constant of the language)"
            ),
        }));
    }
    Ok(())
}

/// # Parameters
impl Sketch {
    /// The sketch's parameters and the bindings of its dimensions.
    pub fn parameters(&self) -> &Parameters {
        &self.parameters
    }

    /// The value of parameter `name`.
    pub fn parameter(&self, name: &str) -> Option<f64> {
        self.parameters.get(name).map(|p| p.value)
    }

    /// The constraints that read parameter `name`: a dimension bound to an expression of it,
    /// or an expression constraint whose rows name it.
    pub fn parameter_readers(&self, name: &str) -> Vec<ConstraintId> {
        self.constraints()
            .filter(|(id, c)| {
                self.parameters.binding_reads(*id, name)
                    || matches!(c, Constraint::Expression(e)
                        if e.rows.iter().any(|r| mentions(r, name)))
            })
            .map(|(id, _)| id)
            .collect()
    }

    /// Defines parameter `name` or changes its value, without solving: every dimension bound
    /// to an expression of it is re-evaluated, every expression constraint reading it is
    /// checked again, and their entities are marked so that the next [`Sketch::solve`]
    /// re-solves exactly their components.
    ///
    /// ```
    /// use camber_sketch::constraints::Distance;
    /// use camber_sketch::{PointRef, Sketch};
    /// use nalgebra::Point2;
    /// let mut s = Sketch::new();
    /// let (a, b) = (s.add_point(Point2::new(0.0, 0.0))?, s.add_point(Point2::new(1.0, 0.0))?);
    /// s.define_parameter("chord", 3.0)?;
    /// let d = s.add_constraint(Distance { a: PointRef::Point(a), b: PointRef::Point(b), distance: 1.0 })?;
    /// s.bind_dimension(d, "distance", "chord / 2")?;
    /// s.solve()?;
    /// let gap = |s: &Sketch| (s.point(PointRef::Point(b)).unwrap() - s.point(PointRef::Point(a)).unwrap()).norm();
    /// assert!((gap(&s) - 1.5).abs() < 1e-10);
    /// s.set_parameter("chord", 5.0)?;
    /// assert!((gap(&s) - 2.5).abs() < 1e-10);
    /// assert!(s.define_parameter("chord", f64::NAN).is_err());
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    ///
    /// # Errors
    /// A name that is not one ([`Error::Expression`]), a non-finite value
    /// ([`Error::NonFinite`]), or what a reader refuses at the new value (a distance that is
    /// no longer positive, say); nothing changes then.
    pub fn define_parameter(&mut self, name: &str, value: f64) -> Result<ParameterChange> {
        check_name(name)?;
        if !value.is_finite() {
            return Err(Error::NonFinite {
                what: "parameter",
                index: 0,
                value,
            });
        }
        let before = self.parameters.clone();
        self.parameters
            .values
            .insert(name.to_owned(), Parameter { value });
        match self.reapply(name) {
            Ok(change) => Ok(change),
            Err(e) => {
                self.parameters = before;
                Err(e)
            }
        }
    }

    /// Re-evaluates and re-checks the readers of `name` against the current parameters and
    /// commits them; on an error nothing is committed.
    fn reapply(&mut self, name: &str) -> Result<ParameterChange> {
        let readers = self.parameter_readers(name);
        let mut replaced: Vec<(ConstraintId, Constraint)> = Vec::new();
        for id in &readers {
            let c = self.constraint(*id)?;
            let bindings = self.parameters.bindings(*id);
            let updated = if bindings.is_empty() {
                c.clone()
            } else {
                apply(c, bindings, &self.parameters)?
            };
            updated.compile(self)?;
            replaced.push((*id, updated));
        }
        let mut change = ParameterChange {
            constraints: readers,
            entities: Vec::new(),
        };
        for (id, c) in replaced {
            for e in c.entities() {
                if !change.entities.contains(&e) {
                    change.entities.push(e);
                }
            }
            // Only values changed (a dimension's number, the constants an expression's tape
            // folds): the readers' components keep their prepared problems and plans.
            self.replace_constraint_value(id, c);
        }
        Ok(change)
    }

    /// Sets parameter `name` and re-solves the components that read it (and any other
    /// component edited since the last solve). A failed solve leaves the sketch as it was,
    /// the parameter included.
    ///
    /// # Errors
    /// As [`Sketch::define_parameter`] and [`Sketch::solve`].
    pub fn set_parameter(&mut self, name: &str, value: f64) -> Result<SketchReport> {
        let before = self.clone();
        self.define_parameter(name, value)?;
        match self.solve() {
            Ok(report) => Ok(report),
            Err(e) => {
                *self = before;
                Err(e)
            }
        }
    }

    /// Removes a parameter nothing reads.
    ///
    /// # Errors
    /// [`Error::Expression`] naming a reader, or an unknown parameter.
    pub fn remove_parameter(&mut self, name: &str) -> Result<f64> {
        if let Some(id) = self.parameter_readers(name).first() {
            return Err(Error::Expression(camber_expr::Error::Scope {
                column: 1,
                message: format!("the parameter `{name}` is read by {id}"),
            }));
        }
        self.parameters
            .values
            .remove(name)
            .map(|p| p.value)
            .ok_or_else(|| {
                Error::Expression(camber_expr::Error::UnknownName {
                    column: 1,
                    name: name.to_owned(),
                })
            })
    }

    /// Writes the number at `path` of a constraint's file form (`"distance"`,
    /// `"target.at[0]"`, `"radius"`) as the expression `text` of the parameters: the
    /// constraint takes its value now and follows the parameters from then on, and a saved
    /// file holds the text.
    ///
    /// # Errors
    /// [`Error::UnknownConstraint`]; [`Error::Expression`] for a text the language refuses or
    /// a path that is not a number of the form; the constraint's own errors at the new value.
    /// Nothing changes then.
    pub fn bind_dimension(&mut self, id: ConstraintId, path: &str, text: &str) -> Result<()> {
        let c = self.constraint(id)?;
        let mut bindings: Vec<Binding> = self
            .parameters
            .bindings(id)
            .iter()
            .filter(|b| b.path != path)
            .cloned()
            .collect();
        let body = c.save().map_err(|e| {
            Error::Expression(camber_expr::Error::Scope {
                column: 1,
                message: e.to_string(),
            })
        })?;
        let mut value: serde_json::Value = serde_json::from_str(&body).map_err(|e| {
            Error::Expression(camber_expr::Error::Scope {
                column: 1,
                message: e.to_string(),
            })
        })?;
        if !at_path(&mut value, path).is_some_and(|v| v.is_number()) {
            return Err(Error::Expression(camber_expr::Error::Scope {
                column: 1,
                message: format!("`{path}` is not a number of a {} constraint", c.tag()),
            }));
        }
        bindings.push(Binding {
            path: path.to_owned(),
            text: text.to_owned(),
        });
        let updated = apply(c, &bindings, &self.parameters)?;
        updated.compile(self)?;
        self.replace_constraint_value(id, updated);
        self.parameters.bindings.insert(id, bindings);
        Ok(())
    }

    /// Writes a dimension's value (the field [`Constraint::value_field`] names: the
    /// `distance` of a distance, the `radius` of a radius, …) as the expression `text` of the
    /// parameters, as [`Sketch::bind_dimension`] does at that path.
    ///
    /// ```
    /// use camber_sketch::constraints::Radius;
    /// use camber_sketch::Sketch;
    /// let mut s = Sketch::new();
    /// let c = s.add_circle(nalgebra::Point2::new(0.0, 0.0), 1.0)?;
    /// let r = s.add_constraint(Radius { circle: c, radius: 1.0 })?;
    /// s.define_parameter("chord", 3.0)?;
    /// s.bind_value(r, "chord / 4")?;
    /// assert_eq!(s.constraint(r)?.value(), Some(0.75));
    /// s.unbind_value(r)?;
    /// s.set_value(r, 2.0)?; // no longer follows `chord`
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::UnknownConstraint`]; [`Error::NoValue`] for a kind without a value; as
    /// [`Sketch::bind_dimension`]. Nothing changes then.
    pub fn bind_value(&mut self, id: ConstraintId, text: &str) -> Result<()> {
        let field = self.value_field_of(id)?;
        self.bind_dimension(id, field, text)
    }

    /// Drops the expression a dimension's value follows, if any: the value keeps its current
    /// number and no longer changes with the parameters ([`Sketch::set_value`] may set it).
    ///
    /// # Errors
    /// [`Error::UnknownConstraint`]; [`Error::NoValue`] for a kind without a value.
    pub fn unbind_value(&mut self, id: ConstraintId) -> Result<()> {
        let field = self.value_field_of(id)?;
        let kept: Vec<Binding> = self
            .parameters
            .bindings(id)
            .iter()
            .filter(|b| b.path != field)
            .cloned()
            .collect();
        self.set_bindings(id, kept);
        Ok(())
    }

    /// The field holding a constraint's value, or [`Error::NoValue`].
    fn value_field_of(&self, id: ConstraintId) -> Result<&'static str> {
        let c = self.constraint(id)?;
        c.value_field().ok_or(Error::NoValue {
            constraint: id,
            kind: c.kind_name(),
        })
    }

    /// Stores the bindings read from a file for a constraint just added.
    pub(crate) fn set_bindings(&mut self, id: ConstraintId, bindings: Vec<Binding>) {
        if bindings.is_empty() {
            self.parameters.bindings.remove(&id);
        } else {
            self.parameters.bindings.insert(id, bindings);
        }
    }
}
