//! `camber edit`: the interactive editor. One sketch is kept in memory; a single page draws it
//! and drags its points through HTTP calls that this module answers.
//!
//! [`EditorState::handle`] takes a request as method, path and body and returns a
//! [`Response`]; it knows nothing of sockets, so tests drive it directly. The server loop
//! ([`server`]) only reads requests, checks where they come from, and writes the answers.
//!
//! The drag loop: `POST /api/drag/start` opens a [`camber_sketch::DragSession`] on the
//! point; each `POST /api/drag/move` runs `DragSession::update` and answers with the entities
//! that moved (control points and curve samples, drawn by [`crate::scene`] like `camber
//! render`) and the glyphs of the constraints reading them; `POST /api/drag/end` commits the
//! session to the sketch, which then is analysed again. An update the solver refuses answers
//! 422 with the reason, and the session keeps its last valid geometry; the sketch changes only
//! at the end of a drag, a solve or an undo, and never to an invalid state.
//!
//! ```
//! use camber_cli::editor::EditorState;
//! let text = r#"{"version": 1,
//!   "entities": [{"id": 0, "kind": "bezier", "control_points": [[0, 0], [1, 1], [2, 0]]}],
//!   "constraints": [{"id": 1, "kind": "fixed", "target": {"point": {"start": 0}}}]}"#;
//! let sketch = camber_cli::sketch_file::parse(text)?;
//! let mut editor = EditorState::new(sketch, "curve.json".into(), None)?;
//! assert_eq!(editor.handle("POST", "/api/drag/start", br#"{"entity": 0, "index": 2}"#).status, 200);
//! let moved = editor.handle("POST", "/api/drag/move", br#"{"to": [2, 1]}"#);
//! assert_eq!(moved.status, 200, "{}", moved.text());
//! assert_eq!(editor.handle("POST", "/api/drag/end", b"").status, 200);
//! let end = editor.sketch().point(camber_sketch::PointRef::Control(camber_sketch::EntityId(0), 2))?;
//! assert!((end.y - 1.0).abs() < 1e-12);
//! assert_eq!(editor.handle("POST", "/api/drag/move", br#"{"to": [2, 1]}"#).status, 409);
//! # Ok::<(), anyhow::Error>(())
//! ```

mod authoring;
pub mod fairness;
pub mod server;
pub mod wire;

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use anyhow::{anyhow, Result};
use camber_sketch::{ConstraintId, DragSession, Entity, EntityId, PointRef, Sketch};
use nalgebra::Point2;
use serde::de::DeserializeOwned;
use serde::Serialize;

use crate::scene::View;
use crate::sketch_file::{self, describe_error};
use wire::{
    AnalysisJson, ComponentJson, ComponentReportJson, ConstraintRef, ConstraintResidualJson,
    DragMove, DragStart, DraggedJson, ErrorJson, MoveJson, ParameterJson, ReportJson, SavedJson,
    SceneJson, StateJson,
};

/// The page, its script and its style sheet, built into the binary.
const PAGE: &str = include_str!("../../assets/editor.html");
const SCRIPT: &str = include_str!("../../assets/editor.js");
/// The sketcher's three scripts (its model, its tools, its view), served joined in that order
/// as `/sketcher.js`: one request instead of three while the page loads.
const SKETCHER: &str = concat!(
    include_str!("../../assets/sketcher.js"),
    "\n",
    include_str!("../../assets/sketcher-tools.js"),
    "\n",
    include_str!("../../assets/sketcher-view.js"),
);
const STYLE: &str = include_str!("../../assets/editor.css");

/// How many earlier states undo keeps.
pub const UNDO_DEPTH: usize = 100;

/// An HTTP answer: status, content type, body.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Response {
    /// The status code.
    pub status: u16,
    /// The `Content-Type` header.
    pub content_type: &'static str,
    /// The body.
    pub body: Vec<u8>,
}

impl Response {
    /// A JSON answer.
    pub fn json<T: Serialize>(status: u16, value: &T) -> Self {
        match serde_json::to_vec(value) {
            Ok(body) => Self {
                status,
                content_type: "application/json",
                body,
            },
            Err(e) => Self::error(500, &format!("cannot write the answer as JSON: {e}")),
        }
    }

    /// An error answer, `{"error": message}`.
    pub fn error(status: u16, message: &str) -> Self {
        let body = serde_json::to_vec(&ErrorJson {
            error: message.to_owned(),
        })
        .unwrap_or_else(|_| b"{\"error\":\"error\"}".to_vec());
        Self {
            status,
            content_type: "application/json",
            body,
        }
    }

    fn asset(content_type: &'static str, text: &'static str) -> Self {
        Self {
            status: 200,
            content_type,
            body: text.as_bytes().to_vec(),
        }
    }

    /// The body as text (lossy), for messages and tests.
    pub fn text(&self) -> String {
        String::from_utf8_lossy(&self.body).into_owned()
    }
}

/// A failed request: the status and the plain message the page shows.
#[derive(Debug)]
struct Failure(u16, String);

impl Failure {
    fn new(status: u16, message: impl Into<String>) -> Self {
        Self(status, crate::tidy_numbers(&message.into()))
    }
}

impl From<anyhow::Error> for Failure {
    fn from(e: anyhow::Error) -> Self {
        Self(500, crate::tidy_numbers(&format!("{e:#}")))
    }
}

type Answer = std::result::Result<Response, Failure>;

/// A drag in progress: the session, and the geometry it shows now.
#[derive(Debug)]
struct Drag {
    session: DragSession,
    entity: EntityId,
    index: usize,
    linear: bool,
    /// The entities of the dragged component at the session's current state.
    current: BTreeMap<EntityId, Entity>,
    updates: usize,
    refused: usize,
    update_time: Duration,
}

/// A constraint with its residual (the largest |row| it owns).
type ConstraintResidual = (ConstraintId, f64);

impl Drag {
    /// Each constraint's residual in the dragged component at the session's current state, and
    /// the largest non-zero one with its constraint (on a tie the smaller constraint id).
    fn live_residuals(
        &self,
    ) -> camber_sketch::Result<(Vec<ConstraintResidual>, Option<ConstraintResidual>)> {
        let residuals = self.session.residuals()?;
        let worst = worst_of(&residuals);
        Ok((residuals, worst))
    }
}

/// The largest non-zero residual with its constraint (on a tie the smaller constraint id).
fn worst_of(residuals: &[ConstraintResidual]) -> Option<ConstraintResidual> {
    residuals.iter().filter(|(_, r)| *r > 0.0).fold(
        None,
        |best: Option<ConstraintResidual>, (id, r)| match best {
            Some((_, b)) if b >= *r => best,
            _ => Some((*id, *r)),
        },
    )
}

/// The largest entity or constraint id the editor accepts: 2^53 − 1, the largest integer a
/// JavaScript number holds exactly (a larger id would be rounded by the page and name another
/// entity or none).
pub const MAX_EDITOR_ID: u64 = (1 << 53) - 1;

/// How far a drag target may lie from the centre of the sketch, in multiples of its scale:
/// the drag session refuses farther targets itself (one rule for every surface).
pub use camber_sketch::drag::MAX_DRAG_REACH;

/// The editor: the sketch, the drag in progress, the undo and redo histories and the last
/// report.
#[derive(Debug)]
pub struct EditorState {
    sketch: Sketch,
    file: PathBuf,
    output: PathBuf,
    /// A number per distinct state: new for every change, restored by undo.
    version: u64,
    next_version: u64,
    saved_version: u64,
    undo: Vec<(Sketch, u64)>,
    /// The states undo left, newest last; a new change clears it.
    redo: Vec<(Sketch, u64)>,
    drag: Option<Drag>,
    components: Vec<ComponentJson>,
    conflicting: BTreeSet<ConstraintId>,
    /// Each constraint's residual (max |g| over its rows) at the committed geometry.
    residuals: BTreeMap<ConstraintId, f64>,
    report: Option<ReportJson>,
}

impl EditorState {
    /// Loads a sketch file; `output` is where saving writes (the file itself by default).
    ///
    /// # Errors
    /// The file cannot be read or is not a valid sketch (the message starts with its name).
    pub fn load(file: &Path, output: Option<PathBuf>) -> Result<Self> {
        let sketch = sketch_file::load(file)?;
        Self::new(sketch, file.to_path_buf(), output)
    }

    /// An editor on a sketch that came from `file`.
    ///
    /// # Errors
    /// An id above [`MAX_EDITOR_ID`] (the page could not address it); the analysis of the
    /// sketch fails (it names the constraints).
    pub fn new(sketch: Sketch, file: PathBuf, output: Option<PathBuf>) -> Result<Self> {
        let ids = sketch
            .entities()
            .map(|(id, _)| ("entity", id.0))
            .chain(sketch.constraints().map(|(id, _)| ("constraint", id.0)));
        for (what, id) in ids {
            if id > MAX_EDITOR_ID {
                anyhow::bail!(
                    "{}: {what} id {id} is above {MAX_EDITOR_ID} (2^53 - 1), the largest id the \
                     editor's page can address exactly; renumber the sketch to edit it",
                    file.display()
                );
            }
        }
        let mut state = Self {
            sketch,
            output: output.unwrap_or_else(|| file.clone()),
            file,
            version: 0,
            next_version: 1,
            saved_version: 0,
            undo: Vec::new(),
            redo: Vec::new(),
            drag: None,
            components: Vec::new(),
            conflicting: BTreeSet::new(),
            residuals: BTreeMap::new(),
            report: None,
        };
        state.analyse()?;
        Ok(state)
    }

    /// The sketch as committed (a drag in progress is not in it until it ends).
    pub fn sketch(&self) -> &Sketch {
        &self.sketch
    }

    /// Answers one request. `path` may carry a query string, which is ignored.
    ///
    /// | request | answer |
    /// | --- | --- |
    /// | `GET /`, `/editor.js`, `/sketcher.js`, `/editor.css` | the page |
    /// | `GET /api/state` | [`StateJson`] |
    /// | `GET /api/combs` | the curvature combs of the curves drawn |
    /// | `GET /api/export.svg`, `/api/export.dxf` | the sketch as SVG (as `camber render`) or DXF (as `camber export`) |
    /// | `POST /api/drag/start` [`DragStart`] | [`DraggedJson`] |
    /// | `POST /api/drag/move` [`DragMove`] | [`MoveJson`]; 422 when the solver refuses |
    /// | `POST /api/drag/end`, `/api/drag/cancel` | [`StateJson`] |
    /// | `POST /api/solve`, `/api/undo`, `/api/redo` | [`StateJson`] |
    /// | `POST /api/save` | [`SavedJson`] |
    /// | `POST /api/save-as` [`wire::SaveAsRequest`] | [`SavedJson`] |
    /// | `POST /api/create` [`wire::CreateRequest`] | [`StateJson`] |
    /// | `POST /api/delete` [`wire::DeleteRequest`] | [`StateJson`] |
    /// | `POST /api/dimension` [`wire::DimensionRequest`] | [`StateJson`]; 422 when the re-solve fails |
    /// | `POST /api/parameter` [`wire::ParameterRequest`] | [`StateJson`]; 422 when the re-solve fails |
    /// | `POST /api/fillet` [`wire::FilletRequest`] | [`StateJson`]; 422 when the corner cannot be rounded |
    ///
    /// Errors answer `{"error": "…"}`: 400 for a malformed body, 404 for an unknown path,
    /// entity or point, 405 for a wrong method, 409 for an action that does not fit the state
    /// (moving without a drag, saving during one, nothing to undo), 422 when the solver refuses
    /// (the sketch and the drag keep their last valid geometry), 500 when writing fails.
    pub fn handle(&mut self, method: &str, path: &str, body: &[u8]) -> Response {
        let path = path.split(['?', '#']).next().unwrap_or_default();
        let answer = match (method, path) {
            ("GET" | "HEAD", "/" | "/index.html") => {
                Ok(Response::asset("text/html; charset=utf-8", PAGE))
            }
            ("GET" | "HEAD", "/editor.js") => {
                Ok(Response::asset("text/javascript; charset=utf-8", SCRIPT))
            }
            ("GET" | "HEAD", "/sketcher.js") => {
                Ok(Response::asset("text/javascript; charset=utf-8", SKETCHER))
            }
            ("GET" | "HEAD", "/editor.css") => {
                Ok(Response::asset("text/css; charset=utf-8", STYLE))
            }
            ("GET" | "HEAD", "/api/state") => self.state_answer(),
            ("GET" | "HEAD", "/api/combs") => self.combs(),
            ("GET" | "HEAD", "/api/export.svg") => self.export("svg"),
            ("GET" | "HEAD", "/api/export.dxf") => self.export("dxf"),
            ("POST", "/api/drag/start") => self.drag_start(body),
            ("POST", "/api/drag/move") => self.drag_move(body),
            ("POST", "/api/drag/end") => self.drag_end(),
            ("POST", "/api/drag/cancel") => self.drag_cancel(),
            ("POST", "/api/solve") => self.solve(),
            ("POST", "/api/undo") => self.undo(),
            ("POST", "/api/redo") => self.redo(),
            ("POST", "/api/save") => self.save(),
            ("POST", "/api/save-as") => self.save_as(body),
            ("POST", "/api/create") => self.create(body),
            ("POST", "/api/delete") => self.delete(body),
            ("POST", "/api/dimension") => self.dimension(body),
            ("POST", "/api/parameter") => self.parameter(body),
            ("POST", "/api/fillet") => self.fillet(body),
            (_, p) if ROUTES.contains(&p) => {
                Err(Failure::new(405, format!("{method} is not allowed on {p}")))
            }
            (_, p) => Err(Failure::new(404, format!("no such page: {p}"))),
        };
        answer.unwrap_or_else(|Failure(status, message)| Response::error(status, &message))
    }

    /// The whole state as the page shows it.
    ///
    /// # Errors
    /// Evaluation failures while drawing (not for a sketch the library accepted).
    pub fn state(&self) -> Result<StateJson> {
        let mut components = self.components.clone();
        let mut residuals = self.residuals.clone();
        // During a drag the dragged component's residuals are the session's, as in the move
        // answers: the geometry drawn is the session's, not the committed sketch's.
        if let Some(d) = &self.drag {
            let (live, worst) = d
                .live_residuals()
                .map_err(|e| anyhow!("residuals failed: {}", describe_error(&self.sketch, &e)))?;
            residuals.extend(live);
            if let Some(c) = components
                .iter_mut()
                .find(|c| c.entities.contains(&d.entity.0))
            {
                c.residual = worst.map_or(0.0, |w| w.1);
                c.worst = worst.map(|(id, _)| ConstraintRef::of(&self.sketch, id));
            }
        }
        let no_overrides = BTreeMap::new();
        let view = View::with_overrides(
            &self.sketch,
            self.drag.as_ref().map_or(&no_overrides, |d| &d.current),
        );
        let scene = SceneJson::of(&view, &self.conflicting, &residuals, |_| true)?;
        let warnings = fairness::scene_warnings(&view, &scene)?;
        Ok(StateJson {
            file: self.file.display().to_string(),
            output: self.output.display().to_string(),
            unsaved: self.version != self.saved_version,
            can_undo: !self.undo.is_empty(),
            can_redo: !self.redo.is_empty(),
            dragging: self.drag.as_ref().map(|d| DraggedJson {
                entity: d.entity.0,
                index: d.index,
                linear: d.linear,
            }),
            scene,
            warnings,
            constraints: self.constraint_list(&components, &residuals),
            parameters: self
                .sketch
                .parameters()
                .iter()
                .map(|(name, p)| ParameterJson {
                    name: name.to_owned(),
                    value: p.value,
                    readers: self
                        .sketch
                        .parameter_readers(name)
                        .iter()
                        .map(|c| c.0)
                        .collect(),
                })
                .collect(),
            next_id: self
                .sketch
                .entities()
                .map(|(id, _)| id.0)
                .chain(self.sketch.constraints().map(|(id, _)| id.0))
                .max()
                .map_or(0, |m| m + 1),
            components,
            report: self.report.clone(),
        })
    }

    fn state_answer(&self) -> Answer {
        Ok(Response::json(200, &self.state()?))
    }

    fn no_drag(&self, action: &str) -> std::result::Result<(), Failure> {
        match &self.drag {
            Some(d) => Err(Failure::new(
                409,
                format!(
                    "cannot {action} during a drag (point {} of entity {}): end or cancel it first",
                    d.index, d.entity.0
                ),
            )),
            None => Ok(()),
        }
    }

    fn drag_start(&mut self, body: &[u8]) -> Answer {
        let req: DragStart = parse(body)?;
        self.no_drag("start another drag")?;
        let id = EntityId(req.entity);
        let e = self
            .sketch
            .entity(id)
            .map_err(|_| Failure::new(404, format!("entity {} does not exist", req.entity)))?;
        let count = e.points().len();
        if req.index >= count {
            return Err(Failure::new(
                404,
                format!(
                    "entity {} has {count} point(s), index {} does not exist",
                    req.entity, req.index
                ),
            ));
        }
        let point = match e {
            Entity::Point(_) => PointRef::Point(id),
            _ => PointRef::Control(id, req.index),
        };
        let comp = self
            .sketch
            .component_of(id)
            .map_err(|e| Failure::new(500, describe_error(&self.sketch, &e)))?;
        let session = self
            .sketch
            .drag(point)
            .map_err(|e| Failure::new(422, describe_error(&self.sketch, &e)))?;
        if session.freedom() == camber_sketch::drag::Freedom::Determined {
            return Err(Failure::new(
                422,
                format!(
                    "point {} of entity {} cannot be dragged: it is fixed or determined by the constraints",
                    req.index, req.entity
                ),
            ));
        }
        let mut current = BTreeMap::new();
        for c in &comp.entities {
            if let Ok(e) = self.sketch.entity(*c) {
                current.insert(*c, e.clone());
            }
        }
        let linear = !self
            .components
            .iter()
            .any(|c| c.nonlinear && c.entities.contains(&id.0));
        let dragged = DraggedJson {
            entity: id.0,
            index: req.index,
            linear,
        };
        self.drag = Some(Drag {
            session,
            entity: id,
            index: req.index,
            linear,
            current,
            updates: 0,
            refused: 0,
            update_time: Duration::ZERO,
        });
        Ok(Response::json(200, &dragged))
    }

    fn drag_move(&mut self, body: &[u8]) -> Answer {
        let start = Instant::now();
        let req: DragMove = parse(body)?;
        let Some(drag) = self.drag.as_mut() else {
            return Err(Failure::new(409, "no drag in progress: start one first"));
        };
        let to = Point2::new(req.to[0], req.to[1]);
        // A tangent block of a Hermite or composite curve is grabbed at its handle N ± t/3:
        // the block's target is the tangent that puts the handle at `to`.
        let target = match drag.current.get(&drag.entity) {
            Some(e) => e.block_for_handle(drag.index, to),
            None => to,
        };
        let t = Instant::now();
        let result = drag.session.update(target).map(|_| ());
        let update_time = t.elapsed();
        drag.update_time += update_time;
        let update = match result {
            Ok(()) => drag.session.last_update().clone(),
            Err(e) => {
                drag.refused += 1;
                return Err(Failure::new(
                    422,
                    format!("move refused: {}", describe_error(&self.sketch, &e)),
                ));
            }
        };
        drag.updates += 1;
        // Only the entities the update moved are read from the session; the residuals come
        // with the update.
        let mut moved = Vec::with_capacity(update.moved.len());
        for id in &update.moved {
            let e = drag
                .session
                .entity(*id)
                .map_err(|err| Failure::new(500, describe_error(&self.sketch, &err)))?;
            moved.push((*id, e));
        }
        let changed: BTreeSet<EntityId> = update.moved.iter().copied().collect();
        drag.current.extend(moved);
        let view = View::with_overrides(&self.sketch, &drag.current);
        let residuals = update.residuals;
        let scene = SceneJson::of(
            &view,
            &self.conflicting,
            &residuals.iter().copied().collect(),
            |id| changed.contains(&id),
        )?;
        let worst = worst_of(&residuals);
        let moved_samples: usize = scene.entities.iter().map(|e| e.samples.len()).sum();
        let warnings = if moved_samples <= fairness::MAX_MOVE_SAMPLES {
            fairness::scene_warnings(&view, &scene)?
        } else {
            Vec::new()
        };
        Ok(Response::json(
            200,
            &MoveJson {
                scene,
                warnings,
                residual: worst.map_or(0.0, |w| w.1),
                worst: worst.map(|(id, _)| ConstraintRef::of(&self.sketch, id)),
                constraint_residuals: residuals
                    .iter()
                    .map(|(id, r)| ConstraintResidualJson {
                        id: id.0,
                        residual: *r,
                    })
                    .collect(),
                update_us: update_time.as_secs_f64() * 1e6,
                handler_us: start.elapsed().as_secs_f64() * 1e6,
            },
        ))
    }

    fn drag_end(&mut self) -> Answer {
        let Some(drag) = self.drag.take() else {
            return Err(Failure::new(409, "no drag in progress"));
        };
        if drag.updates == 0 {
            return self.state_answer();
        }
        let before = self.sketch.clone();
        let (entity, index, linear) = (drag.entity, drag.index, drag.linear);
        let (updates, refused, time) = (drag.updates, drag.refused, drag.update_time);
        drag.session
            .finish(&mut self.sketch)
            .map_err(|e| Failure::new(422, describe_error(&self.sketch, &e)))?;
        self.committed(before)?;
        let comp = self
            .components
            .iter()
            .find(|c| c.entities.contains(&entity.0));
        let path = if linear {
            "drag: linear minimum norm (cached factorization)"
        } else {
            "drag: Newton minimum norm (warm-started)"
        };
        let tries = updates + refused;
        let mean_us = time.as_secs_f64() * 1e6 / tries as f64;
        self.report = Some(ReportJson {
            action: "drag",
            summary: format!(
                "dragged point {index} of entity {}: {updates} update(s), {refused} refused, \
                 {mean_us:.1} µs per update",
                entity.0
            ),
            components: comp
                .map(|c| ComponentReportJson {
                    entities: c.entities.clone(),
                    solver: path.to_owned(),
                    reason: format!("{updates} update(s), {refused} refused"),
                    dof: c.analysis.as_ref().map(|a| a.dof),
                    residual: c.residual,
                    time_ms: time.as_secs_f64() * 1e3,
                })
                .into_iter()
                .collect(),
        });
        self.state_answer()
    }

    fn drag_cancel(&mut self) -> Answer {
        if self.drag.take().is_none() {
            return Err(Failure::new(409, "no drag in progress"));
        }
        self.state_answer()
    }

    fn solve(&mut self) -> Answer {
        self.no_drag("solve")?;
        let before = self.sketch.clone();
        let report = self.sketch.solve_all().map_err(|e| {
            Failure::new(
                422,
                format!("solve failed: {}", describe_error(&before, &e)),
            )
        })?;
        self.committed(before)?;
        let components = component_reports(&report);
        self.report = Some(ReportJson {
            action: "solve",
            summary: format!("solved {} component(s)", components.len()),
            components,
        });
        self.state_answer()
    }

    fn undo(&mut self) -> Answer {
        self.no_drag("undo")?;
        let Some(earlier) = self.undo.pop() else {
            return Err(Failure::new(409, "nothing to undo"));
        };
        let now = self.restore(earlier)?;
        self.redo.push(now);
        self.state_answer()
    }

    fn redo(&mut self) -> Answer {
        self.no_drag("redo")?;
        let Some(later) = self.redo.pop() else {
            return Err(Failure::new(409, "nothing to redo"));
        };
        let now = self.restore(later)?;
        self.undo.push(now);
        self.state_answer()
    }

    /// Makes `(sketch, version)` the current state (an undo or a redo), returning the state it
    /// replaces.
    fn restore(&mut self, (sketch, version): (Sketch, u64)) -> Result<(Sketch, u64)> {
        let now = (
            std::mem::replace(&mut self.sketch, sketch),
            std::mem::replace(&mut self.version, version),
        );
        self.report = None;
        self.analyse()?;
        Ok(now)
    }

    fn save(&mut self) -> Answer {
        self.no_drag("save")?;
        let text = camber_sketch::file::to_json(&self.sketch)
            .map_err(|e| Failure::new(422, format!("cannot save: {e}")))?;
        crate::output::write_all(&[], &[(self.output.clone(), text.clone())])
            .map_err(|e| Failure::new(500, format!("{e:#}")))?;
        self.saved_version = self.version;
        Ok(Response::json(
            200,
            &SavedJson {
                saved: self.output.display().to_string(),
                bytes: text.len(),
                state: self.state()?,
            },
        ))
    }

    /// After a change of the sketch: remember the state before it, give the new one a
    /// version, analyse again.
    fn committed(&mut self, before: Sketch) -> Result<()> {
        if self.undo.len() == UNDO_DEPTH {
            self.undo.remove(0);
        }
        self.undo.push((before, self.version));
        self.redo.clear();
        self.version = self.next_version;
        self.next_version += 1;
        self.analyse()
    }

    /// Recomputes the components, their DOF analysis and their residuals.
    fn analyse(&mut self) -> Result<()> {
        let analysis = analyse(&self.sketch)?;
        self.components = analysis.components;
        self.conflicting = analysis.conflicting;
        self.residuals = analysis.residuals;
        Ok(())
    }
}

/// One report line per component a solve touched.
fn component_reports(report: &camber_sketch::SketchReport) -> Vec<ComponentReportJson> {
    report
        .components
        .iter()
        .map(|c| {
            let r = &c.report;
            ComponentReportJson {
                entities: c.component.entities.iter().map(|e| e.0).collect(),
                solver: crate::sketch_file::solver_name(r.solver).to_owned(),
                reason: r.reason.clone(),
                dof: Some(r.dof),
                residual: r.residuals.iter().fold(0.0_f64, |m, g| m.max(g.max_abs)),
                time_ms: r.elapsed.as_secs_f64() * 1e3,
            }
        })
        .collect()
}

/// Every path the editor answers, for telling 405 from 404.
const ROUTES: [&str; 23] = [
    "/",
    "/index.html",
    "/editor.js",
    "/sketcher.js",
    "/editor.css",
    "/api/state",
    "/api/drag/start",
    "/api/drag/move",
    "/api/drag/end",
    "/api/drag/cancel",
    "/api/solve",
    "/api/undo",
    "/api/redo",
    "/api/save",
    "/api/save-as",
    "/api/create",
    "/api/delete",
    "/api/dimension",
    "/api/parameter",
    "/api/fillet",
    "/api/export.svg",
    "/api/export.dxf",
    "/api/combs",
];

/// Parses a JSON request body; a malformed one is a 400 with serde's reason.
fn parse<T: DeserializeOwned>(body: &[u8]) -> std::result::Result<T, Failure> {
    serde_json::from_slice(body).map_err(|e| Failure::new(400, format!("bad request body: {e}")))
}

/// What [`analyse`] finds in a sketch.
#[derive(Debug, Clone, PartialEq)]
pub struct Analysis {
    /// The components with their analysis and largest residual now.
    pub components: Vec<ComponentJson>,
    /// Every constraint the analysis names conflicting.
    pub conflicting: BTreeSet<ConstraintId>,
    /// Each constraint's residual now: max |g| over its rows (constraints with no rows, such
    /// as bindings, are absent).
    pub residuals: BTreeMap<ConstraintId, f64>,
}

/// The components of a sketch with their analysis (sparse for large components) and their
/// largest residual now, every constraint the analysis names conflicting, and each
/// constraint's residual.
///
/// # Errors
/// Building a component's problem fails (the message names the constraint).
pub fn analyse(sketch: &Sketch) -> Result<Analysis> {
    let failed =
        |e: camber_sketch::Error| anyhow!("analysis failed: {}", describe_error(sketch, &e));
    let mut analyses: BTreeMap<EntityId, AnalysisJson> = BTreeMap::new();
    let mut conflicting = BTreeSet::new();
    for a in sketch.analyze().map_err(failed)? {
        let d = &a.analysis;
        conflicting.extend(d.conflicting.iter().copied());
        if let Some(first) = a.component.entities.first() {
            analyses.insert(
                *first,
                AnalysisJson {
                    free_unknowns: d.free_unknowns,
                    rank: d.rank,
                    dof: d.dof,
                    redundant: ConstraintRef::list(sketch, &d.redundant),
                    partly_redundant: ConstraintRef::list(sketch, &d.partly_redundant),
                    conflicting: ConstraintRef::list(sketch, &d.conflicting),
                    free: a.freedom.clone(),
                    free_parameters: a.free_parameters.clone(),
                },
            );
        }
    }
    let mut out = Vec::new();
    let mut residuals: BTreeMap<ConstraintId, f64> = BTreeMap::new();
    for comp in sketch.components() {
        let Some(first) = comp.entities.first().copied() else {
            continue;
        };
        let cp = sketch.component_problem(first).map_err(failed)?;
        let lin = cp
            .problem()
            .linearize()
            .map_err(|e| failed(camber_sketch::Error::from(e)))?;
        for (owner, g) in lin.row_owner.iter().zip(&lin.g) {
            let r = residuals.entry(*owner).or_insert(0.0);
            *r = r.max(g.abs());
        }
        let worst = lin
            .g
            .iter()
            .enumerate()
            .fold(None, |best: Option<(usize, f64)>, (i, g)| match best {
                Some((_, b)) if b >= g.abs() => best,
                _ if g.abs() > 0.0 => Some((i, g.abs())),
                _ => best,
            });
        out.push(ComponentJson {
            entities: comp.entities.iter().map(|e| e.0).collect(),
            constraints: comp.constraints.iter().map(|c| c.0).collect(),
            nonlinear: !lin.affine,
            analysis: analyses.remove(&first),
            residual: worst.map_or(0.0, |w| w.1),
            worst: worst
                .and_then(|(i, _)| lin.row_owner.get(i))
                .map(|id| ConstraintRef::of(sketch, *id)),
        });
    }
    Ok(Analysis {
        components: out,
        conflicting,
        residuals,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn saving_replaces_the_file_whole_and_leaves_no_temporary() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("s.json");
        std::fs::write(&path, "old").unwrap();
        crate::output::write_all(&[], &[(path.clone(), "new text".into())]).unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "new text");
        let names: Vec<_> = std::fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(names, ["s.json"]);
        // A missing folder fails plainly, naming the file, and creates nothing.
        let missing = dir.path().join("no/such/s.json");
        let e = crate::output::write_all(&[], &[(missing, "x".into())])
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("cannot write") && e.contains("no such file or directory"),
            "{e}"
        );
    }

    #[test]
    fn unsaved_follows_the_versions_through_undo() {
        let text = r#"{"version": 1,
          "entities": [{"id": 0, "kind": "bezier", "control_points": [[0, 0], [1, 1], [2, 0]]}],
          "constraints": [{"id": 1, "kind": "fixed", "target": {"point": {"start": 0}}}]}"#;
        let sketch = crate::sketch_file::parse(text).unwrap();
        let mut ed = EditorState::new(sketch, "s.json".into(), None).unwrap();
        let unsaved = |ed: &EditorState| ed.state().unwrap().unsaved;
        assert!(!unsaved(&ed));
        assert_eq!(ed.handle("POST", "/api/solve", b"{}").status, 200);
        assert!(unsaved(&ed));
        assert_eq!(ed.handle("POST", "/api/undo", b"{}").status, 200);
        assert!(!unsaved(&ed), "back at the loaded state");
        // A new change after an undo gets a new version, never an old one.
        assert_eq!(ed.handle("POST", "/api/solve", b"{}").status, 200);
        assert!(unsaved(&ed));
        assert_eq!(ed.version, 2);
    }

    #[test]
    fn redo_replays_what_undo_took_back_until_a_new_change() {
        let text = r#"{"version": 1,
          "entities": [{"id": 0, "kind": "line", "from": [0, 0], "to": [1, 0.5]}],
          "constraints": [{"id": 1, "kind": "horizontal", "of": {"line": 0}}]}"#;
        let sketch = crate::sketch_file::parse(text).unwrap();
        let mut ed = EditorState::new(sketch, "s.json".into(), None).unwrap();
        let end_y = |ed: &EditorState| {
            ed.sketch()
                .point(camber_sketch::PointRef::End(camber_sketch::EntityId(0)))
                .unwrap()
                .y
        };
        assert_eq!(ed.handle("POST", "/api/redo", b"{}").status, 409);
        assert_eq!(ed.handle("POST", "/api/solve", b"{}").status, 200);
        let solved = end_y(&ed);
        assert!(
            (solved - 0.5).abs() > 1e-3,
            "the solve moved the end: {solved}"
        );
        assert_eq!(ed.handle("POST", "/api/undo", b"{}").status, 200);
        let state = ed.state().unwrap();
        assert!(state.can_redo && !state.can_undo && !state.unsaved);
        assert!((end_y(&ed) - 0.5).abs() < 1e-15);
        assert_eq!(ed.handle("POST", "/api/redo", b"{}").status, 200);
        let state = ed.state().unwrap();
        assert!(!state.can_redo && state.can_undo && state.unsaved);
        assert_eq!(
            end_y(&ed).to_bits(),
            solved.to_bits(),
            "redo restores the solved geometry exactly"
        );
        assert_eq!(ed.version, 1, "redo restores the version too");
        // Undo, then a new change: the undone state cannot be redone any more.
        assert_eq!(ed.handle("POST", "/api/undo", b"{}").status, 200);
        assert_eq!(ed.handle("POST", "/api/solve", b"{}").status, 200);
        assert!(!ed.state().unwrap().can_redo);
        assert_eq!(ed.handle("POST", "/api/redo", b"{}").status, 409);
        assert_eq!(ed.handle("GET", "/api/redo", b"").status, 405);
    }
}
