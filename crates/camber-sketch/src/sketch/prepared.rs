//! The prepared components of a sketch: every component a solve compiled and solved is kept,
//! with the policy's plan beside its problem ([`ComponentProblem`]), so that the next solve of
//! the same component after a dimension edit ([`crate::Sketch::set_value`]) re-solves on the
//! kept plan instead of compiling the component again.
//!
//! A kept problem holds the values its solve wrote back, so it is exactly the sketch's state
//! for as long as nothing but constraint values change:
//!
//! - **a dimension's new value** ([`crate::Sketch::set_value`], or a parameter the constraint
//!   reads: [`crate::Sketch::set_parameter`], a dimension bound to it, an expression whose
//!   tape folds it) keeps the prepared component: before its next solve the edited
//!   constraint's residual objects are replaced in place (same rows over the same blocks), which
//!   the plan sees as a change of values ([`camber_solve::Problem::stamps`]); a constraint whose
//!   pieces do not map one to one onto its residual blocks has its component compiled again;
//! - **anything else** that touches an entity (a moved point, an entity replaced or removed, a
//!   constraint added or removed, a priority or weight, a drag committed) drops the prepared
//!   component holding it, and new options drop them all; the next solve compiles them again.
//!
//! The prepared components of a sketch hold at most [`MAX_PREPARED_UNKNOWNS`] unknowns in all;
//! beyond that, components are solved and not kept. A copy of a sketch starts with none.

use std::collections::{BTreeSet, HashMap};

use crate::component::{Component, ComponentProblem};
use crate::ground::ids::{ConstraintId, EntityId};

/// The most unknowns the prepared components of one sketch hold in all.
pub const MAX_PREPARED_UNKNOWNS: usize = 1 << 21;

/// The prepared components of a sketch (see the module documentation).
#[derive(Debug, Default)]
pub(crate) struct Prepared {
    /// Each by its smallest entity id.
    by_first: HashMap<EntityId, ComponentProblem>,
    /// The smallest entity id of the prepared component holding each entity.
    of_entity: HashMap<EntityId, EntityId>,
    /// Constraints whose value changed since their component was prepared.
    edited: BTreeSet<ConstraintId>,
    /// Unknowns held in all.
    unknowns: usize,
}

/// A copy of a sketch starts with nothing prepared: a plan belongs to one problem.
impl Clone for Prepared {
    fn clone(&self) -> Self {
        Self::default()
    }
}

impl Prepared {
    /// Takes out the prepared problem of `comp`, if it was prepared with exactly its entities
    /// and constraints, with the constraints of it whose value changed since.
    pub(crate) fn take(
        &mut self,
        comp: &Component,
    ) -> Option<(ComponentProblem, Vec<ConstraintId>)> {
        // The component is solved now, on its prepared problem or on one built from the
        // constraints as they are: either way their edits are taken into account.
        let mut edited: Vec<ConstraintId> = comp
            .constraints
            .iter()
            .copied()
            .filter(|c| self.edited.remove(c))
            .collect();
        let first = *comp.entities.first()?;
        let cp = self.by_first.remove(&first)?;
        self.release(&cp);
        edited.extend(
            cp.component()
                .constraints
                .iter()
                .copied()
                .filter(|c| self.edited.remove(c)),
        );
        (cp.component() == comp).then_some((cp, edited))
    }

    /// Keeps a solved component's problem for the next solve, if there is room.
    pub(crate) fn keep(&mut self, cp: ComponentProblem) {
        let Some(first) = cp.component().entities.first().copied() else {
            return;
        };
        if let Some(old) = self.by_first.remove(&first) {
            self.release(&old);
        }
        let n = cp.problem().num_unknowns();
        if self.unknowns.saturating_add(n) > MAX_PREPARED_UNKNOWNS {
            return;
        }
        for e in &cp.component().entities {
            self.of_entity.insert(*e, first);
        }
        self.unknowns += n;
        self.by_first.insert(first, cp);
    }

    /// Forgets a component's problem's entities and unknowns (it left the map).
    fn release(&mut self, cp: &ComponentProblem) {
        self.unknowns = self.unknowns.saturating_sub(cp.problem().num_unknowns());
        for e in &cp.component().entities {
            self.of_entity.remove(e);
        }
    }

    /// Drops the prepared component holding `entity` (something other than a constraint's
    /// value changed there).
    pub(crate) fn forget_entity(&mut self, entity: EntityId) {
        if let Some(first) = self.of_entity.get(&entity).copied() {
            if let Some(cp) = self.by_first.remove(&first) {
                self.release(&cp);
                for c in &cp.component().constraints {
                    self.edited.remove(c);
                }
            }
        }
    }

    /// Records that a constraint's value changed: its component's residuals are replaced before
    /// its next solve.
    pub(crate) fn edit(&mut self, constraint: ConstraintId) {
        self.edited.insert(constraint);
    }

    /// Takes out every prepared component whose constraints kept their values since it was
    /// prepared (the others are dropped); nothing is left prepared.
    pub(crate) fn take_all(&mut self) -> Vec<ComponentProblem> {
        let taken = std::mem::take(self);
        taken
            .by_first
            .into_values()
            .filter(|cp| {
                !cp.component()
                    .constraints
                    .iter()
                    .any(|c| taken.edited.contains(c))
            })
            .collect()
    }

    /// Drops every prepared component.
    pub(crate) fn forget_all(&mut self) {
        *self = Self::default();
    }

    /// How many components are kept.
    #[cfg(test)]
    pub(crate) fn len(&self) -> usize {
        self.by_first.len()
    }
}

/// What a component's problem was built from, besides the entities' values: the sketch's
/// options and named parameters, the component's entities (their kinds and shapes: degree,
/// knots, NURBS weights), their point weights, its constraints' data and priorities, all as
/// they were before the solve. Another sketch whose component matches it builds the same
/// problem up to values, so it may be solved on that problem once the values are refreshed
/// ([`ComponentProblem::refresh_values`]).
#[derive(Debug, Clone)]
pub(crate) struct Signature {
    component: Component,
    options: camber_solve::Options,
    parameters: super::parameters::Parameters,
    entities: Vec<crate::ground::entity::Entity>,
    weights: Vec<((EntityId, usize), f64)>,
    constraints: Vec<(crate::constraints::Constraint, camber_solve::Priority)>,
}

impl Signature {
    /// The signature of `comp` in `sketch` as it is now.
    ///
    /// # Errors
    /// An entity or constraint of `comp` missing from `sketch`.
    pub(crate) fn of(
        sketch: &super::Sketch,
        comp: &Component,
    ) -> crate::ground::errors::Result<Self> {
        let mut entities = Vec::with_capacity(comp.entities.len());
        let mut weights = Vec::new();
        for id in &comp.entities {
            entities.push(sketch.entity(*id)?.clone());
            weights.extend(
                sketch
                    .weights
                    .range((*id, 0)..=(*id, usize::MAX))
                    .map(|(k, w)| (*k, *w)),
            );
        }
        let mut constraints = Vec::with_capacity(comp.constraints.len());
        for id in &comp.constraints {
            constraints.push((sketch.constraint(*id)?.clone(), sketch.priority(*id)));
        }
        Ok(Self {
            component: comp.clone(),
            options: sketch.options.clone(),
            parameters: sketch.parameters.clone(),
            entities,
            weights,
            constraints,
        })
    }

    /// The component it describes.
    pub(crate) fn component(&self) -> &Component {
        &self.component
    }

    /// Whether `comp` of `sketch` builds the problem this signature's component built, up to
    /// the entities' values: the same component, options, constraint data, priorities and
    /// point weights, entities of the same kinds and shapes, and the same parameters, except
    /// that the parameters named in `swept` (a sweep's table: empty for `crate::solve_many`)
    /// may hold other values and the constraints reading them other data. `Some` with the
    /// constraints of `comp` that read a swept parameter (to be compiled again and replaced in
    /// place, as after a parameter change of one sketch: `Sketch::replace_constraint_value`)
    /// when it matches; `None` otherwise.
    pub(crate) fn matches_except(
        &self,
        sketch: &super::Sketch,
        comp: &Component,
        swept: &Swept,
    ) -> Option<Vec<ConstraintId>> {
        let same_parameters = self.parameters.bindings == sketch.parameters.bindings
            && self.parameters.values.len() == sketch.parameters.values.len()
            && self
                .parameters
                .values
                .iter()
                .zip(&sketch.parameters.values)
                .all(|((n, v), (m, w))| {
                    n == m && (v == w || swept.parameters.contains(n.as_str()))
                });
        if self.component != *comp || self.options != sketch.options || !same_parameters {
            return None;
        }
        let mut edited = Vec::new();
        let same_constraints =
            comp.constraints
                .iter()
                .zip(&self.constraints)
                .all(|(id, (c, priority))| {
                    let Ok(now) = sketch.constraint(*id) else {
                        return false;
                    };
                    // A reader is compiled again even with the same data: an expression
                    // folds the parameters' values into its tape.
                    let reader = swept.readers.contains(id);
                    if reader {
                        edited.push(*id);
                    }
                    sketch.priority(*id) == *priority && (reader || now == c)
                });
        let same_entities = comp.entities.iter().zip(&self.entities).all(|(id, e)| {
            sketch.entity(*id).is_ok_and(|now| {
                e.with_points(now.points(), &now.scalars())
                    .is_ok_and(|reshaped| reshaped == *now)
            })
        });
        let mut weights = comp
            .entities
            .iter()
            .flat_map(|id| sketch.weights.range((*id, 0)..=(*id, usize::MAX)));
        let same_weights = self.weights.iter().all(|(k, w)| {
            weights
                .next()
                .is_some_and(|(k2, w2)| k == k2 && w.to_bits() == w2.to_bits())
        }) && weights.next().is_none();
        (same_constraints && same_entities && same_weights).then_some(edited)
    }
}

/// What the variants of a sweep may change against each other: the swept parameters'
/// values and the data of the constraints that read them.
#[derive(Debug, Clone, Default)]
pub(crate) struct Swept {
    /// The parameters the table sets.
    pub(crate) parameters: BTreeSet<String>,
    /// Every constraint reading one of them ([`crate::Sketch::parameter_readers`]).
    pub(crate) readers: BTreeSet<ConstraintId>,
}

#[cfg(test)]
mod tests {
    use crate::constraints::{Distance, Fixed};
    use crate::{PointRef, Sketch};
    use nalgebra::Point2;

    /// Two components, each a point held at a distance from a fixed one.
    fn two() -> (Sketch, [crate::ConstraintId; 2], [crate::EntityId; 2]) {
        let mut s = Sketch::new();
        let mut ds = [crate::ConstraintId(0); 2];
        let mut bs = [crate::EntityId(0); 2];
        for k in 0..2 {
            let y = 5.0 * f64::from(k);
            let a = s.add_point(Point2::new(0.0, y)).unwrap();
            let b = s.add_point(Point2::new(1.2, y)).unwrap();
            s.add_constraint(Fixed::point(PointRef::Point(a))).unwrap();
            ds[k as usize] = s
                .add_constraint(Distance {
                    a: PointRef::Point(a),
                    b: PointRef::Point(b),
                    distance: 1.0,
                })
                .unwrap();
            bs[k as usize] = b;
        }
        (s, ds, bs)
    }

    #[test]
    fn solved_components_are_kept_across_value_edits_and_dropped_by_other_edits() {
        let (mut s, ds, bs) = two();
        s.solve().unwrap();
        assert_eq!(s.prepared.len(), 2);
        // A value edit keeps the component; its solve takes it and keeps it again.
        s.set_value(ds[0], 2.0).unwrap();
        assert_eq!(s.prepared.len(), 2);
        s.solve().unwrap();
        assert_eq!(s.prepared.len(), 2);
        assert!((s.point(PointRef::Point(bs[0])).unwrap().x - 2.0).abs() < 1e-12);
        // A moved point drops its component only.
        s.set_point(PointRef::Point(bs[1]), Point2::new(0.5, 5.5))
            .unwrap();
        assert_eq!(s.prepared.len(), 1);
        s.solve().unwrap();
        assert_eq!(s.prepared.len(), 2);
        // A copy starts with nothing prepared, new options drop everything.
        assert_eq!(s.clone().prepared.len(), 0);
        s.set_options(s.options().clone());
        assert_eq!(s.prepared.len(), 0);
    }

    #[test]
    fn a_parameter_change_keeps_the_components_that_read_it_and_solves_as_a_fresh_build() {
        use crate::constraints::expression::{ExprArg, Expression};
        let (mut s, ds, bs) = two();
        s.define_parameter("gap", 1.0).unwrap();
        // Component 0: a dimension bound to the parameter. Component 1: an expression row
        // whose tape folds the parameter as a constant (the point's height above the fixed
        // one is half the gap).
        s.bind_dimension(ds[0], "distance", "2 * gap").unwrap();
        let fixed = match s.constraint(ds[1]).unwrap() {
            crate::Constraint::Distance(d) => d.a,
            _ => unreachable!(),
        };
        let (PointRef::Point(a1), PointRef::Point(b1)) = (fixed, PointRef::Point(bs[1])) else {
            unreachable!()
        };
        s.add_constraint(
            Expression::new("half the gap", &["Q.y - P.y = gap / 2"])
                .with_arg("P", ExprArg::Point(a1))
                .with_arg("Q", ExprArg::Point(b1)),
        )
        .unwrap();
        s.solve().unwrap();
        assert_eq!(s.prepared.len(), 2);
        for gap in [1.5, 0.25, 1.0] {
            s.define_parameter("gap", gap).unwrap();
            // Only values changed: both prepared components stay for the solve to take.
            assert_eq!(s.prepared.len(), 2, "gap {gap}");
            let mut fresh = crate::file::from_json(&crate::file::to_json(&s).unwrap()).unwrap();
            s.solve().unwrap();
            fresh.solve().unwrap();
            assert_eq!(s.prepared.len(), 2);
            let p = |s: &Sketch, e| s.point(PointRef::Point(e)).unwrap();
            assert!(((p(&s, bs[0]) - Point2::new(0.0, 0.0)).norm() - 2.0 * gap).abs() < 1e-10);
            assert!(
                (p(&s, bs[1]).y - 5.0 - gap / 2.0).abs() < 1e-10,
                "gap {gap}"
            );
            for e in bs {
                assert!((p(&s, e) - p(&fresh, e)).norm() < 1e-10, "gap {gap}");
            }
        }
    }

    #[test]
    fn a_failed_solve_keeps_nothing_of_its_components_and_the_sketch_as_it_was() {
        let (mut s, ds, _) = two();
        s.solve().unwrap();
        // A point at distance 1 from a fixed one, then also at distance 1 from a second
        // fixed point 5 away: no solution.
        let far = s.add_point(Point2::new(5.0, 0.0)).unwrap();
        s.add_constraint(Fixed::point(PointRef::Point(far)))
            .unwrap();
        let b = match s.constraint(ds[0]).unwrap() {
            crate::Constraint::Distance(d) => d.b,
            _ => unreachable!(),
        };
        s.add_constraint(Distance {
            a: PointRef::Point(far),
            b,
            distance: 1.0,
        })
        .unwrap();
        let before = crate::file::to_json(&s).unwrap();
        assert!(s.solve().is_err());
        assert_eq!(crate::file::to_json(&s).unwrap(), before);
        assert_eq!(s.prepared.len(), 1);
    }
}
