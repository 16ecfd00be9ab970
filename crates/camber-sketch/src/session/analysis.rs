//! The DOF analysis of a sketch, component by component: free unknowns, rank, DOF, and the
//! constraints that are redundant or conflicting (camber_solve's analysis on each component's
//! problem, dense for small components and sparse for large ones, with the coincidences merged
//! into one unknown named redundant when they repeat; a constraint is never both).

use camber_solve::DofAnalysis;

pub use crate::component::problem::{EntityFreedom, ParameterFreedom};
use crate::component::Component;
use crate::ground::errors::Result;
use crate::sketch::Sketch;

/// The DOF analysis of one component at the current state.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ComponentAnalysis {
    /// The component.
    pub component: Component,
    /// Free unknowns, rank, DOF, redundant and conflicting constraints.
    pub analysis: DofAnalysis,
    /// The entities with something still free (points that can move, radii that can change),
    /// in id order; an entity of the component not listed is fully determined.
    pub freedom: Vec<EntityFreedom>,
    /// The free parameters of constraints (contact parameters) that can still change: the
    /// contacts that can slide along their curve.
    pub free_parameters: Vec<ParameterFreedom>,
}

impl ComponentAnalysis {
    /// Whether every point and radius of `entity` is determined by the constraints.
    pub fn is_determined(&self, entity: crate::ground::ids::EntityId) -> bool {
        self.component.entities.contains(&entity)
            && !self.freedom.iter().any(|f| f.entity == entity)
    }
}

/// # Analysis
impl Sketch {
    /// The DOF analysis of every component (components without constraints included: their
    /// DOF is their number of unknowns).
    ///
    /// # Errors
    /// Errors of building the problems.
    pub fn analyze(&self) -> Result<Vec<ComponentAnalysis>> {
        let mut out = Vec::new();
        // The options depend on the largest coordinate of the whole sketch: worked out once,
        // not once per component (which made a sketch of many components quadratic).
        let options = self.solve_options();
        for comp in self.components() {
            let cp = self.build_component(&comp)?;
            let mut analysis = cp.problem().analyze(&options)?;
            cp.name_merged_redundant(&mut analysis.redundant);
            let conflicting = &analysis.conflicting;
            analysis.redundant.retain(|c| !conflicting.contains(c));
            let mut freedom = cp.freedom(&analysis.rows.free_columns)?;
            freedom.sort_by_key(|f| f.entity);
            let free_parameters = cp.parameter_freedom(&analysis.rows.free_columns)?;
            out.push(ComponentAnalysis {
                component: comp,
                analysis,
                freedom,
                free_parameters,
            });
        }
        Ok(out)
    }
}
