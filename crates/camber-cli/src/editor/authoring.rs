//! The editor's authoring requests: add and delete entities and constraints, set a dimension
//! or a parameter, save under another name, solve a sketch as it opens, and the constraint
//! list of the state. Each goes through the library's API
//! ([`camber_sketch::file::add_from_values`], [`Sketch::remove_constraint`],
//! [`Sketch::remove_entity`], [`Sketch::set_value`], [`Sketch::bind_value`],
//! [`Sketch::set_parameter`], [`Sketch::solve`]); a refused request leaves the sketch as it
//! was, and an accepted one is one step of undo.

use std::collections::{BTreeMap, BTreeSet};

use anyhow::Result;
use camber_sketch::{ConstraintId, EntityId, Sketch};

use super::wire::{
    ComponentJson, ConstraintJson, CreateRequest, DeleteRequest, DimensionRequest, DimensionValue,
    FilletRequest, ParameterRequest, ReportJson, SaveAsRequest,
};
use super::{component_reports, parse, Answer, EditorState, Failure, MAX_EDITOR_ID};
use crate::sketch_file::describe_error;

/// The longest file name `POST /api/save-as` takes, in bytes.
const MAX_FILE_NAME: usize = 255;

impl EditorState {
    /// `POST /api/create`: adds what the page drew, with the constraints it inferred or the
    /// user applied, then solves (unless asked not to). A solve that fails keeps the addition
    /// with the geometry as it was and says why: the analysis then names the conflicting
    /// constraints, and undo takes the addition back.
    pub(super) fn create(&mut self, body: &[u8]) -> Answer {
        let req: CreateRequest = parse(body)?;
        self.no_drag("add to the sketch")?;
        if req.entities.is_empty() && req.constraints.is_empty() {
            return Err(Failure::new(
                400,
                "nothing to add: no entities, no constraints",
            ));
        }
        for (what, list) in [("entity", &req.entities), ("constraint", &req.constraints)] {
            for v in list {
                if let Some(id) = v.get("id").and_then(serde_json::Value::as_u64) {
                    if id > MAX_EDITOR_ID {
                        return Err(Failure::new(
                            400,
                            format!("{what} id {id} is above {MAX_EDITOR_ID} (2^53 - 1), the largest id the page can address"),
                        ));
                    }
                }
            }
        }
        let (n_entities, n_constraints) = (req.entities.len(), req.constraints.len());
        let before = self.sketch.clone();
        camber_sketch::file::add_from_values(&mut self.sketch, req.entities, req.constraints)
            .map_err(|e| {
                let status = match e {
                    camber_sketch::file::FileError::Shape { .. }
                    | camber_sketch::file::FileError::Syntax { .. } => 400,
                    _ => 422,
                };
                Failure::new(status, format!("cannot add: {e}"))
            })?;
        let added = format!(
            "added {n_entities} entit{} and {n_constraints} constraint{}",
            if n_entities == 1 { "y" } else { "ies" },
            if n_constraints == 1 { "" } else { "s" }
        );
        let (summary, components) = if req.solve {
            match self.sketch.solve() {
                Ok(report) => (format!("{added}; solved"), component_reports(&report)),
                Err(e) => (
                    format!(
                        "{added}; the solve failed, the geometry is as it was: {}",
                        describe_error(&self.sketch, &e)
                    ),
                    Vec::new(),
                ),
            }
        } else {
            (added, Vec::new())
        };
        self.committed(before)?;
        self.report = Some(ReportJson {
            action: "create",
            summary,
            components,
        });
        self.state_answer()
    }

    /// `POST /api/delete`: removes entities and constraints, with every constraint that reads
    /// a removed entity or the free parameters of a removed constraint. Nothing is solved:
    /// what stays was satisfied and still is.
    pub(super) fn delete(&mut self, body: &[u8]) -> Answer {
        let req: DeleteRequest = parse(body)?;
        self.no_drag("delete")?;
        if req.entities.is_empty() && req.constraints.is_empty() {
            return Err(Failure::new(
                400,
                "nothing to delete: no entities, no constraints",
            ));
        }
        let entities: BTreeSet<EntityId> = req.entities.iter().copied().map(EntityId).collect();
        for e in &entities {
            if self.sketch.entity(*e).is_err() {
                return Err(Failure::new(404, format!("entity {} does not exist", e.0)));
            }
        }
        for c in &req.constraints {
            if self.sketch.constraint(ConstraintId(*c)).is_err() {
                return Err(Failure::new(404, format!("constraint {c} does not exist")));
            }
        }
        // The constraints asked for, then those reading a removed entity, by increasing id.
        let mut work: Vec<ConstraintId> = self
            .sketch
            .constraints()
            .filter(|(_, c)| c.entities().iter().any(|e| entities.contains(e)))
            .map(|(id, _)| id)
            .collect();
        work.reverse();
        work.extend(req.constraints.iter().rev().copied().map(ConstraintId));
        let before = self.sketch.clone();
        let mut removed = BTreeSet::new();
        // Each constraint is removed once; one that others read waits for them, so the loop
        // ends after at most twice as many steps as there are constraints.
        let mut budget = 2 * self.sketch.constraints().count() + work.len() + 1;
        while let Some(id) = work.pop() {
            budget = budget.saturating_sub(1);
            if budget == 0 {
                self.sketch = before;
                return Err(Failure::new(
                    500,
                    "deleting did not finish: constraints reading each other",
                ));
            }
            if removed.contains(&id) {
                continue;
            }
            match self.sketch.remove_constraint(id) {
                Ok(_) => {
                    removed.insert(id);
                }
                Err(camber_sketch::Error::ConstraintInUse { by, .. }) => {
                    work.push(id);
                    work.push(by);
                }
                Err(e) => {
                    let message = describe_error(&before, &e);
                    self.sketch = before;
                    return Err(Failure::new(422, format!("cannot delete: {message}")));
                }
            }
        }
        for e in &entities {
            if let Err(err) = self.sketch.remove_entity(*e) {
                let message = describe_error(&before, &err);
                self.sketch = before;
                return Err(Failure::new(422, format!("cannot delete: {message}")));
            }
        }
        let asked: BTreeSet<ConstraintId> =
            req.constraints.iter().copied().map(ConstraintId).collect();
        let with = removed.difference(&asked).count();
        let summary = format!(
            "deleted {} entit{} and {} constraint{}{}",
            entities.len(),
            if entities.len() == 1 { "y" } else { "ies" },
            removed.len(),
            if removed.len() == 1 { "" } else { "s" },
            if with > 0 {
                format!(" ({with} of them read what was deleted)")
            } else {
                String::new()
            }
        );
        self.committed(before)?;
        self.report = Some(ReportJson {
            action: "delete",
            summary,
            components: Vec::new(),
        });
        self.state_answer()
    }

    /// `POST /api/dimension`: sets a dimension to a number (dropping an expression it
    /// followed) or to an expression of the parameters, and re-solves. When the sketch cannot
    /// take the value, nothing changes and the answer says why.
    pub(super) fn dimension(&mut self, body: &[u8]) -> Answer {
        let req: DimensionRequest = parse(body)?;
        self.no_drag("set a dimension")?;
        let id = ConstraintId(req.constraint);
        let c = self
            .sketch
            .constraint(id)
            .map_err(|_| Failure::new(404, format!("constraint {} does not exist", id.0)))?;
        let (kind, old) = (c.kind_name(), c.value());
        let Some(old) = old else {
            return Err(Failure::new(
                422,
                format!("constraint {} ({kind}) has no value to set", id.0),
            ));
        };
        let number = match &req.value {
            DimensionValue::Number(v) => Some(*v),
            DimensionValue::Text(t) => t.trim().parse::<f64>().ok(),
        };
        let typed = match (&req.value, number) {
            (_, Some(v)) => format!("{v}"),
            (DimensionValue::Text(t), None) => t.trim().to_owned(),
            (DimensionValue::Number(v), None) => format!("{v}"),
        };
        let before = self.sketch.clone();
        let set = match (number, &req.value) {
            (Some(v), _) => self
                .sketch
                .unbind_value(id)
                .and_then(|()| self.sketch.set_value(id, v)),
            (None, DimensionValue::Text(t)) => self.sketch.bind_value(id, t.trim()),
            (None, DimensionValue::Number(_)) => unreachable!("a number is always read"),
        };
        let refused = |sketch: &mut Sketch, before: Sketch, e: &camber_sketch::Error| {
            let message = describe_error(&before, e);
            *sketch = before;
            Failure::new(
                422,
                format!(
                    "constraint {} ({kind}) cannot be {typed}: {message}; it stays {old}",
                    id.0
                ),
            )
        };
        if let Err(e) = set {
            return Err(refused(&mut self.sketch, before, &e));
        }
        match self.sketch.solve() {
            Ok(report) => {
                let value = self.sketch.constraint(id).ok().and_then(|c| c.value());
                self.committed(before)?;
                self.report = Some(ReportJson {
                    action: "dimension",
                    summary: format!(
                        "constraint {} ({kind}) = {typed}{}; solved",
                        id.0,
                        match value {
                            Some(v) if number.is_none() => format!(" = {v}"),
                            _ => String::new(),
                        }
                    ),
                    components: component_reports(&report),
                });
                self.state_answer()
            }
            Err(e) => Err(refused(&mut self.sketch, before, &e)),
        }
    }

    /// `POST /api/parameter`: defines or changes a named parameter and re-solves the
    /// components that read it ([`Sketch::set_parameter`], which leaves the sketch as it was
    /// when the solve fails).
    pub(super) fn parameter(&mut self, body: &[u8]) -> Answer {
        let req: ParameterRequest = parse(body)?;
        self.no_drag("set a parameter")?;
        let before = self.sketch.clone();
        let old = self.sketch.parameter(&req.name);
        let report = self
            .sketch
            .set_parameter(&req.name, req.value)
            .map_err(|e| {
                Failure::new(
                    422,
                    format!(
                        "parameter {} cannot be {}: {}{}",
                        req.name,
                        req.value,
                        describe_error(&before, &e),
                        old.map_or(String::new(), |v| format!("; it stays {v}"))
                    ),
                )
            })?;
        self.committed(before)?;
        self.report = Some(ReportJson {
            action: "parameter",
            summary: format!("{} = {}; solved", req.name, req.value),
            components: component_reports(&report),
        });
        self.state_answer()
    }

    /// `POST /api/fillet`: rounds a corner with a tangent arc of the given radius, trimming
    /// the two entities to its ends (the arc, its tangencies and its radius dimension are
    /// added, the corner's coincidence removed).
    pub(super) fn fillet(&mut self, body: &[u8]) -> Answer {
        let req: FilletRequest = parse(body)?;
        self.no_drag("round a corner")?;
        for id in [req.first, req.second] {
            if self.sketch.entity(EntityId(id)).is_err() {
                return Err(Failure::new(404, format!("entity {id} does not exist")));
            }
        }
        let before = self.sketch.clone();
        let fillet = self
            .sketch
            .fillet(EntityId(req.first), EntityId(req.second), req.radius)
            .map_err(|e| {
                Failure::new(
                    422,
                    format!(
                        "cannot round the corner of {} and {}: {}",
                        req.first,
                        req.second,
                        describe_error(&before, &e)
                    ),
                )
            })?;
        self.committed(before)?;
        self.report = Some(ReportJson {
            action: "fillet",
            summary: format!(
                "rounded the corner of {} and {} with arc {} (radius {})",
                req.first, req.second, fillet.arc.0, req.radius
            ),
            components: Vec::new(),
        });
        self.state_answer()
    }

    /// `POST /api/save-as`: writes the sketch to another file of the output's folder, which
    /// becomes where "Save" writes. The name is a file name only (no folder, no `..`), ends in
    /// `.json`, and replaces an existing file only when asked.
    pub(super) fn save_as(&mut self, body: &[u8]) -> Answer {
        let req: SaveAsRequest = parse(body)?;
        self.no_drag("save")?;
        let name = req.file.trim();
        let bad = |why: &str| Failure::new(400, format!("cannot save as {name:?}: {why}"));
        if name.is_empty() || name.len() > MAX_FILE_NAME {
            return Err(bad(&format!(
                "a file name is 1 to {MAX_FILE_NAME} bytes long"
            )));
        }
        if name.contains(['/', '\\', '\0', ':']) || name.starts_with('.') {
            return Err(bad(
                "give a file name only: no folder, no leading dot (it is saved beside the current file)",
            ));
        }
        if !name.to_ascii_lowercase().ends_with(".json") {
            return Err(bad("a sketch file name ends in .json"));
        }
        let folder = self
            .output
            .parent()
            .map(std::path::Path::to_path_buf)
            .unwrap_or_default();
        let path = folder.join(name);
        if path.exists() && !req.overwrite {
            return Err(Failure::new(
                409,
                format!(
                    "{} exists: ask to overwrite it, or choose another name",
                    path.display()
                ),
            ));
        }
        let previous = std::mem::replace(&mut self.output, path);
        let saved = self.save();
        if saved.is_err() {
            self.output = previous;
        }
        saved
    }

    /// `GET /api/export.svg` and `GET /api/export.dxf`: the sketch as `camber render` draws
    /// it, or its geometry as `camber export` writes it (text DXF); during a drag, the sketch
    /// as committed.
    pub(super) fn export(&self, format: &str) -> Answer {
        match format {
            "svg" => {
                let svg = crate::commands::render::picture(&self.sketch, false)?;
                Ok(super::Response {
                    status: 200,
                    content_type: "image/svg+xml",
                    body: svg.into_bytes(),
                })
            }
            _ => {
                let bytes =
                    camber_interop::dxf::write(&self.sketch, camber_interop::dxf::Form::Text)
                        .map_err(|e| Failure::new(422, format!("cannot export as DXF: {e}")))?;
                Ok(super::Response {
                    status: 200,
                    content_type: "application/dxf",
                    body: bytes,
                })
            }
        }
    }

    /// `GET /api/combs`: the curvature combs of every free-form curve at the geometry drawn
    /// (during a drag, the drag's).
    pub(super) fn combs(&self) -> Answer {
        let no_overrides = BTreeMap::new();
        let view = crate::scene::View::with_overrides(
            &self.sketch,
            self.drag.as_ref().map_or(&no_overrides, |d| &d.current),
        );
        let entities: Vec<_> = view.entities().collect();
        let combs = super::fairness::combs(&entities)?;
        Ok(super::Response::json(
            200,
            &serde_json::json!({ "combs": combs }),
        ))
    }

    /// Solves a sketch just opened when a constraint does not hold, so that the page shows it
    /// solved; undo goes back to the geometry of the file. A sketch that does not solve stays
    /// as it is, and the report says why.
    ///
    /// # Errors
    /// The analysis after the solve fails (not for a sketch the library accepted).
    pub fn solve_on_open(&mut self) -> Result<()> {
        let tolerance = self.sketch.solve_options().tolerance;
        let unsolved = self
            .components
            .iter()
            .filter(|c| c.residual > tolerance)
            .count();
        if unsolved == 0 {
            return Ok(());
        }
        let before = self.sketch.clone();
        match self.sketch.solve_all() {
            Ok(report) => {
                self.committed(before)?;
                self.report = Some(ReportJson {
                    action: "solve",
                    summary: format!(
                        "solved on opening ({unsolved} component(s) did not hold as loaded; undo shows the file as it is)"
                    ),
                    components: component_reports(&report),
                });
            }
            Err(e) => {
                self.report = Some(ReportJson {
                    action: "solve",
                    summary: format!(
                        "opened unsolved: the solve failed: {}",
                        describe_error(&self.sketch, &e)
                    ),
                    components: Vec::new(),
                });
            }
        }
        Ok(())
    }

    /// Every constraint with its residual (`residuals`, at the geometry drawn), its status
    /// from the components' analysis, and its value and expression.
    pub(super) fn constraint_list(
        &self,
        components: &[ComponentJson],
        residuals: &BTreeMap<ConstraintId, f64>,
    ) -> Vec<ConstraintJson> {
        let mut status: BTreeMap<u64, &'static str> = BTreeMap::new();
        for c in components {
            match &c.analysis {
                None => {
                    for id in &c.constraints {
                        status.insert(*id, "unanalysed");
                    }
                }
                Some(a) => {
                    for (list, word) in [
                        (&a.redundant, "redundant"),
                        (&a.partly_redundant, "partly_redundant"),
                        (&a.conflicting, "conflicting"),
                    ] {
                        for r in list {
                            status.insert(r.id, word);
                        }
                    }
                }
            }
        }
        self.sketch
            .constraints()
            .map(|(id, c)| ConstraintJson {
                id: id.0,
                kind: c.tag(),
                name: c.kind_name(),
                entities: c.entities().iter().map(|e| e.0).collect(),
                residual: residuals.get(&id).copied(),
                status: status.get(&id.0).copied().unwrap_or("ok"),
                value: c.value(),
                expression: c.value_field().and_then(|field| {
                    self.sketch
                        .parameters()
                        .bindings(id)
                        .iter()
                        .find(|b| b.path == field)
                        .map(|b| b.text.clone())
                }),
            })
            .collect()
    }
}
