// camber edit: the page's script. It holds no geometry of its own: it draws the entities and
// glyphs the server computes (GET /api/state, POST /api/drag/move) and sends the pointer's
// positions back. Requests of one drag go out one at a time; while one is on its way, only the
// latest pointer position is kept, so a slow answer never builds a queue.
"use strict";

const SVG_NS = "http://www.w3.org/2000/svg";
const canvas = document.getElementById("canvas");
const layers = {
  polygons: document.getElementById("layer-polygons"),
  curves: document.getElementById("layer-curves"),
  glyphs: document.getElementById("layer-glyphs"),
  points: document.getElementById("layer-points"),
};
const statusLine = document.getElementById("status");
const coordsLine = document.getElementById("coords");
const message = document.getElementById("message");

/** The last full state from the server. */
let state = null;
/** Entities by id, as the server last sent them. */
const entities = new Map();
/** Glyph lists by constraint id. */
const glyphs = new Map();
/** Model-to-screen view: the model point at the canvas centre and pixels per model unit. */
const view = { x: 0, y: 0, k: 1 };
/** The drag in progress: the point, the request on its way, the next target, how to end. */
let drag = null;
/** A background pan in progress. */
let pan = null;

// ---- requests ------------------------------------------------------------------------------

async function api(method, path, body) {
  const options = { method, headers: {} };
  if (method === "POST") {
    options.headers["Content-Type"] = "application/json";
    options.body = JSON.stringify(body ?? {});
  }
  let response;
  try {
    response = await fetch(path, options);
  } catch (e) {
    return { ok: false, status: 0, data: { error: `the editor is not reachable (${e.message})` } };
  }
  let data;
  try {
    data = await response.json();
  } catch {
    data = { error: `${response.status} ${response.statusText}` };
  }
  return { ok: response.ok, status: response.status, data };
}

// ---- coordinates ---------------------------------------------------------------------------

/**
 * The canvas size, measured once per task and kept until the next microtask checkpoint: asking
 * the browser at every point of a redraw forced a layout after each element added (5 s of a
 * 1,000-segment chain's first draw went there).
 */
let sizeNow = null;
function size() {
  if (!sizeNow) {
    const r = canvas.getBoundingClientRect();
    sizeNow = { w: r.width || 1, h: r.height || 1 };
    queueMicrotask(() => { sizeNow = null; });
  }
  return sizeNow;
}

function toScreen(p) {
  const { w, h } = size();
  return [w / 2 + (p[0] - view.x) * view.k, h / 2 - (p[1] - view.y) * view.k];
}

function toModel(clientX, clientY) {
  const r = canvas.getBoundingClientRect();
  const { w, h } = size();
  return [view.x + (clientX - r.left - w / 2) / view.k, view.y - (clientY - r.top - h / 2) / view.k];
}

/** Sets the view to show everything (fit() also redraws). */
function fitView() {
  pickGrid = null;
  let lo = [Infinity, Infinity];
  let hi = [-Infinity, -Infinity];
  const grow = (p, r = 0) => {
    lo = [Math.min(lo[0], p[0] - r), Math.min(lo[1], p[1] - r)];
    hi = [Math.max(hi[0], p[0] + r), Math.max(hi[1], p[1] + r)];
  };
  for (const e of entities.values()) {
    e.points.forEach((p) => grow(p, e.radius ?? 0));
    (e.samples ?? []).forEach((p) => grow(p));
  }
  // Glyphs too: a target ring away from its curve (a conflicting target) must be in view.
  for (const list of glyphs.values()) list.forEach((g) => grow(g.at));
  if (!(lo[0] <= hi[0])) {
    lo = [-1, -1];
    hi = [1, 1];
  }
  const { w, h } = size();
  const span = Math.max(hi[0] - lo[0], hi[1] - lo[1], 1e-9);
  view.x = (lo[0] + hi[0]) / 2;
  view.y = (lo[1] + hi[1]) / 2;
  view.k = 0.9 * Math.min(w / Math.max(hi[0] - lo[0], span * 1e-3), h / Math.max(hi[1] - lo[1], span * 1e-3));
}

function fit() {
  fitView();
  redrawAll();
}

// ---- drawing -------------------------------------------------------------------------------

function element(tag, attrs, parent) {
  const el = document.createElementNS(SVG_NS, tag);
  for (const [k, v] of Object.entries(attrs)) el.setAttribute(k, v);
  if (parent) parent.appendChild(el);
  return el;
}

/** A polyline's points attribute in screen pixels (one string built in a loop: this runs for
 * every sample of every curve at each redraw). */
function pointsAttr(list) {
  const { w, h } = size();
  const [cx, cy, k] = [w / 2 - view.x * view.k, h / 2 + view.y * view.k, view.k];
  let out = "";
  for (const p of list) {
    out += `${out ? " " : ""}${(cx + p[0] * k).toFixed(2)},${(cy - p[1] * k).toFixed(2)}`;
  }
  return out;
}

/** The elements of each entity in each layer, by entity id, so an update replaces only them. */
const drawn = new Map();

/**
 * What of entity `id` can still move, from its component's DOF analysis: the indices of its
 * free points and whether its radius is free; `null` when the component was not analysed.
 */
function freedomOf(id) {
  if (freedomIndex.state !== state) {
    // Built once per state: looking each entity up in the component lists made a redraw
    // quadratic in the entities of a component.
    const byEntity = new Map();
    for (const comp of state?.components ?? []) {
      const free = new Map((comp.analysis?.free ?? []).map((f) => [f.entity, f]));
      for (const e of comp.entities) byEntity.set(e, comp.analysis ? free.get(e) ?? false : null);
    }
    freedomIndex.state = state;
    freedomIndex.byEntity = byEntity;
  }
  const f = freedomIndex.byEntity.get(id);
  if (f === undefined || f === null) return null;
  return { points: new Set(f ? f.points : []), radius: !!(f && f.scalars.length) };
}
const freedomIndex = { state: undefined, byEntity: new Map() };

// ---- density: what a redraw leaves out where the drawing is denser than the screen shows ----

/**
 * Screen cells already holding a drawn handle or glyph. A handle whose cell (HANDLE_CELL px)
 * already shows another handle lies under it and is not drawn; a constraint glyph whose cell
 * (GLYPH_CELL px) already shows another constraint's glyph of the same shape is left out until
 * zooming in (conflicting constraints always draw). Small sketches are not thinned (see
 * THIN_HANDLES_ABOVE, THIN_GLYPHS_ABOVE). Nothing is lost for picking: pickHandle works on every
 * handle, drawn or not. Claims are kept per entity or constraint, so a partial redraw (a drag
 * update) releases and retakes only its own cells.
 */
class Density {
  constructor(cell) {
    this.cell = cell;
    this.owner = new Map();
    this.claims = new Map();
  }
  clear() {
    this.owner.clear();
    this.claims.clear();
  }
  release(group) {
    for (const k of this.claims.get(group) ?? []) {
      if (this.owner.get(k)?.group === group) this.owner.delete(k);
    }
    this.claims.delete(group);
  }
  /**
   * Claims the cell of (x, y) among things of one `kind` (a glyph shape: a ring and an arrow on
   * one spot both show) for `token` of `group`; false when another token holds it.
   */
  take(group, token, x, y, force, kind = "") {
    const k = `${kind}${Math.floor(x / this.cell)},${Math.floor(y / this.cell)}`;
    const o = this.owner.get(k);
    if (o && !(o.group === group && o.token === token) && !force) return false;
    this.owner.set(k, { group, token });
    if (!this.claims.has(group)) this.claims.set(group, []);
    this.claims.get(group).push(k);
    return true;
  }
}
const HANDLE_CELL = 3;
/**
 * Handles are thinned only in sketches with more than this many: below it every handle is drawn
 * (coincident ones too, as the joints of a small sketch), which costs nothing.
 */
const THIN_HANDLES_ABOVE = 500;
let thinHandles = false;
/** Glyphs are thinned only in sketches with more constraints carrying glyphs than this (the
 * limit `camber render` thins above too). */
const THIN_GLYPHS_ABOVE = 200;
let thinGlyphs = false;
const GLYPH_CELL = 24;
const handleDensity = new Density(HANDLE_CELL);
const glyphDensity = new Density(GLYPH_CELL);
/** Whether (x, y) lies on the canvas or within `margin` px of it. */
function onCanvas(x, y, margin) {
  const { w, h } = size();
  return x >= -margin && y >= -margin && x <= w + margin && y <= h + margin;
}

function drawEntity(e) {
  const old = drawn.get(e.id);
  if (old) old.forEach((el) => el.remove());
  const els = [];
  // Fully determined entities and points are drawn in the "determined" colour.
  const freedom = freedomOf(e.id);
  const determined = freedom !== null && freedom.points.size === 0 && !freedom.radius;
  const curveClass = determined ? "curve determined" : "curve";
  const curveLike = ["bezier", "bspline", "nurbs", "hermite", "composite"].includes(e.kind);
  if (curveLike) {
    // Hermite and composite curves send their polygon (nodes and tangent handles) apart.
    els.push(element("polyline", { class: "polygon", points: pointsAttr(e.polygon ?? e.points) }, layers.polygons));
    els.push(element("polyline", { class: curveClass, points: pointsAttr(e.samples ?? []) }, layers.curves));
  } else if (["arc", "ellipse", "elliptic_arc"].includes(e.kind)) {
    // Round entities come as samples along them (an ellipse closed, its last sample its first).
    els.push(element("polyline", { class: curveClass, points: pointsAttr(e.samples ?? []) }, layers.curves));
  } else if (e.kind === "line") {
    els.push(element("polyline", { class: curveClass, points: pointsAttr(e.points) }, layers.curves));
  } else if (e.kind === "circle") {
    const [cx, cy] = toScreen(e.points[0]);
    els.push(element("circle", { class: curveClass, cx, cy, r: e.radius * view.k }, layers.curves));
  }
  // Handles off the canvas or under another drawn handle are not drawn (see Density); the
  // one dragged always is. Their titles are made on demand (pointerover).
  handleDensity.release(e.id);
  pickGrid = null;
  e.points.forEach((p, index) => {
    const [cx, cy] = toScreen(p);
    const active = drag && drag.entity === e.id && drag.index === index;
    if (!active && !(onCanvas(cx, cy, 8) && (!thinHandles || handleDensity.take(e.id, index, cx, cy)))) return;
    const fixed = freedom !== null && !freedom.points.has(index);
    const cls = `handle${e.kind === "point" ? " point" : ""}${active ? " active" : ""}${fixed ? " determined" : ""}`;
    const el = element("circle", { class: cls, cx, cy, r: e.kind === "point" ? 5 : 4.5 }, layers.points);
    el.dataset.entity = e.id;
    el.dataset.index = index;
    els.push(el);
  });
  drawn.set(e.id, els);
}

/** The words for point `index` of entity `id`: kind, index, position. */
function handleText(id, index) {
  const e = entities.get(id);
  const p = e?.points[index];
  if (!p) return `entity ${id} point ${index}`;
  return `entity ${id} (${e.kind}), point ${index}: (${p[0].toPrecision(6)}, ${p[1].toPrecision(6)})`;
}

// Titles on demand: a constraint's glyphs get their tooltip when the pointer first comes over
// them, not one <title> per group at every redraw. Handles have none: the status line names
// the handle a press would grab (showPick), which where handles overlap is not always the one
// drawn on top.
canvas.addEventListener("pointerover", (ev) => {
  const el = ev.target.closest?.("g[data-constraint]");
  if (!el || el.querySelector(":scope > title")) return;
  element("title", {}, el).textContent = `constraint ${el.dataset.constraint}`;
});

/** A constraint's residual as a label shows it: |g| in two digits, "?" when unknown. */
function residualText(r) {
  if (typeof r !== "number") return "|g| ?";
  return r === 0 ? "|g| 0" : `|g| ${r.toExponential(1)}`;
}

/** The elements of each constraint's glyphs, by constraint id. */
const drawnGlyphs = new Map();

function drawGlyphs(constraint, list) {
  drawnGlyphs.get(constraint)?.remove();
  drawnGlyphs.delete(constraint);
  glyphDensity.release(constraint);
  // A glyph off the canvas, or in a cell another constraint's glyph already shows, is left
  // out (see Density); conflicting ones always draw.
  const shown = list.filter((glyph) => {
    const [x, y] = toScreen(glyph.at);
    return onCanvas(x, y, 30) && (!thinGlyphs || glyphDensity.take(constraint, constraint, x, y, glyph.conflicting, glyph.shape));
  });
  if (shown.length === 0) return;
  const g = element("g", { "data-constraint": constraint }, layers.glyphs);
  for (const glyph of shown) {
    const red = glyph.conflicting ? " conflict" : "";
    const [x, y] = toScreen(glyph.at);
    if (glyph.shape === "arrow") {
      const n = Math.hypot(glyph.dir[0], glyph.dir[1]);
      if (!(n > 0)) continue;
      const [dx, dy] = [glyph.dir[0] / n, -glyph.dir[1] / n];
      const len = 22;
      const [bx, by] = [x + dx * len, y + dy * len];
      const [sx, sy] = [-dy * 4, dx * 4];
      element("line", { class: `glyph${red}`, x1: x, y1: y, x2: bx, y2: by }, g);
      const back = [bx - dx * 7, by - dy * 7];
      element("polyline", {
        class: `glyph${red}`,
        points: `${back[0] + sx},${back[1] + sy} ${bx},${by} ${back[0] - sx},${back[1] - sy}`,
      }, g);
    } else if (glyph.shape === "fixed") {
      element("polygon", { class: `glyph solid${red}`, points: `${x},${y} ${x - 6},${y + 10} ${x + 6},${y + 10}` }, g);
    } else if (glyph.shape === "mark") {
      const label = element("text", { class: `glyph-mark${red}`, x: x + 6, y: y - 6 }, g);
      label.textContent = glyph.text;
    } else {
      element("circle", { class: `glyph${red}`, cx: x, cy: y, r: 8 }, g);
    }
    if (glyph.label !== undefined) {
      // An expression constraint: its name and its residual at the geometry drawn.
      const text = element("text", { class: `glyph-label${red}`, x: x + 6, y: y + 14, "data-constraint": constraint }, g);
      text.textContent = `${glyph.label}: ${residualText(glyph.residual)}`;
    }
  }
  drawnGlyphs.set(constraint, g);
}

/** What the last redraw drew and how long it took (the chain test reads it). */
const drawStats = { ms: 0, handles: 0, handlesDrawn: 0, constraints: 0, constraintsDrawn: 0 };
/** The line saying what a dense drawing leaves out (made here, so the page needs no slot). */
const densityLine = document.createElement("div");
densityLine.id = "density";
densityLine.hidden = true;
canvas.parentElement.appendChild(densityLine);

function redrawAll() {
  const t0 = performance.now();
  handleDensity.clear();
  glyphDensity.clear();
  let handles = 0;
  for (const e of entities.values()) handles += e.points.length;
  thinHandles = handles > THIN_HANDLES_ABOVE;
  thinGlyphs = glyphs.size > THIN_GLYPHS_ABOVE;
  for (const e of entities.values()) drawEntity(e);
  for (const [c, list] of glyphs) drawGlyphs(c, list);
  Object.assign(drawStats, {
    ms: performance.now() - t0,
    handles,
    handlesDrawn: layers.points.childElementCount,
    constraints: glyphs.size,
    constraintsDrawn: layers.glyphs.childElementCount,
  });
  const thinned = drawStats.handlesDrawn < handles || drawStats.constraintsDrawn < glyphs.size;
  densityLine.hidden = !thinned;
  densityLine.textContent = thinned
    ? `drawn: ${drawStats.handlesDrawn} of ${handles} handles, glyphs of ${drawStats.constraintsDrawn} of ` +
      `${glyphs.size} constraints (the rest lie off the canvas or under others: zoom in); every handle can be picked`
    : "";
  showPick();
  if (typeof sketcherRedraw === "function") sketcherRedraw();
}

/** Redraws at the next frame, once however many times it is asked (pan, zoom, resize). */
let redrawPending = false;
function requestRedraw() {
  pickGrid = null;
  if (redrawPending) return;
  redrawPending = true;
  requestAnimationFrame(() => {
    redrawPending = false;
    redrawAll();
  });
}

/**
 * Puts entities and glyphs from an answer in place; `full` replaces everything. With `draw`
 * false (a full scene that a fit redraws next) nothing is drawn yet.
 */
function takeScene(scene, full, draw = true) {
  if (full) {
    for (const els of drawn.values()) els.forEach((el) => el.remove());
    for (const g of drawnGlyphs.values()) g.remove();
    drawn.clear();
    drawnGlyphs.clear();
    entities.clear();
    glyphs.clear();
  }
  const touched = new Set();
  for (const g of scene.glyphs) {
    if (!touched.has(g.constraint)) {
      touched.add(g.constraint);
      glyphs.set(g.constraint, []);
    }
    glyphs.get(g.constraint).push(g);
  }
  for (const e of scene.entities) {
    entities.set(e.id, e);
    if (draw && !full) drawEntity(e);
  }
  pickGrid = null;
  if (!draw) return;
  if (full) redrawAll();
  else {
    for (const c of touched) drawGlyphs(c, glyphs.get(c));
    if (typeof sketcherRedraw === "function") sketcherRedraw(scene);
  }
}

// ---- the side panel ------------------------------------------------------------------------

function showMessage(text, kind) {
  message.hidden = !text;
  message.textContent = text ?? "";
  message.className = `message ${kind ?? "info"}`;
}

function setStatus(text, error) {
  statusLine.textContent = text;
  statusLine.className = error ? "error" : "";
  // The pointer's handle is named again at its next move, over this line, which comes back
  // when the pointer leaves the handles.
  if (hovered) hovered = { status: text, error };
}

const ids = (list) => (list.length > 6 ? `${list.slice(0, 3).join(", ")}, …, ${list[list.length - 1]}` : list.join(", "));
/**
 * Runs of consecutive ids that share a text, as "first–last: text" (or "id: text" alone); a
 * component of 1,000 chain segments lists its free points in three runs instead of 1,000
 * entries. `items` are [id, text] in id order.
 */
function runs(items, format) {
  const out = [];
  for (const [id, text] of items) {
    const last = out[out.length - 1];
    if (last && last.text === text && id === last.to + 1) last.to = id;
    else out.push({ from: id, to: id, text });
  }
  return out.map((r) => format(r.from === r.to ? `${r.from}` : `${r.from}–${r.to}`, r.text));
}
/** At most PANEL_ITEMS entries of a panel line; the whole list goes in its tooltip. */
const PANEL_ITEMS = 12;
function capped(parts, sep) {
  const all = parts.join(sep);
  if (parts.length <= PANEL_ITEMS) return [all, null];
  return [`${parts.slice(0, PANEL_ITEMS).join(sep)}${sep}… (${parts.length - PANEL_ITEMS} more: hover for all)`, all];
}
const namedParts = (refs) => runs(refs.map((c) => [c.id, c.kind]), (r, kind) => `${r} (${kind})`);
const named = (refs) => capped(namedParts(refs), ", ")[0];
const sci = (v) => (v === 0 ? "0" : v.toExponential(2));

/** A block of lines: a bold title, then (label, text, bad, tooltip) rows. */
function block(title, rows) {
  const div = document.createElement("div");
  div.className = "block";
  const h = document.createElement("p");
  h.className = "title";
  h.textContent = title;
  div.appendChild(h);
  for (const [label, text, bad, tooltip] of rows) {
    const p = document.createElement("p");
    const l = document.createElement("span");
    l.className = "label";
    l.textContent = `${label} `;
    const t = document.createElement("span");
    t.textContent = text;
    if (bad) t.className = "bad";
    if (tooltip) t.title = tooltip;
    p.append(l, t);
    div.appendChild(p);
  }
  return div;
}

function renderPanel() {
  const file = document.getElementById("file");
  file.textContent = state.output === state.file ? state.file : `${state.file} → saves to ${state.output}`;
  if (state.unsaved) {
    const mark = document.createElement("span");
    mark.className = "unsaved";
    mark.textContent = " (unsaved changes)";
    file.appendChild(mark);
  }
  document.getElementById("undo").disabled = !state.can_undo;
  document.getElementById("redo").disabled = !state.can_redo;
  const report = document.getElementById("report");
  report.replaceChildren();
  if (state.report) {
    const p = document.createElement("p");
    p.textContent = state.report.summary;
    report.appendChild(p);
    for (const c of state.report.components) {
      report.appendChild(block(`entities ${ids(c.entities)}`, [
        ["solver", c.solver],
        ["why", c.reason],
        ["DOF", c.dof ?? "–"],
        ["residual", sci(c.residual), c.residual > 1e-9],
        ["time", `${c.time_ms.toFixed(3)} ms`],
      ]));
    }
  } else {
    report.innerHTML = '<p class="muted">none yet</p>';
  }
  const comps = document.getElementById("components");
  comps.replaceChildren();
  state.components.forEach((c, k) => {
    const a = c.analysis;
    // While this component is dragged, the residual before the drag would be stale: each move
    // answer carries the residual of the geometry it draws, shown here until the next one.
    const dragged = drag && drag.started && c.entities.includes(drag.entity);
    const now = dragged ? drag.residual : c;
    const unsolved = now !== null && now.residual > 1e-9;
    const residual = now === null
      ? "updated at the first move"
      : `${sci(now.residual)}${now.worst && unsolved ? ` at ${now.worst.id} (${now.worst.kind})` : ""}${dragged ? " (now)" : ""}`;
    // Long lists are summarised: runs of ids, at most PANEL_ITEMS of them, the rest in the
    // line's tooltip (the page stays readable on a 1,000-segment chain).
    const list = (refs) => capped(namedParts(refs), ", ");
    const [free, freeAll] = a ? freeText(a.free, a.free_parameters) : ["–", null];
    const [redundant, redundantAll] = a ? list(a.redundant) : ["–", null];
    const [partly, partlyAll] = a ? list(a.partly_redundant) : ["", null];
    const [conflicting, conflictingAll] = a ? list(a.conflicting) : ["–", null];
    const count = c.entities.length > 6 ? ` (${c.entities.length} entities, ${c.constraints.length} constraints)` : "";
    comps.appendChild(block(`${k + 1}. entities ${ids(c.entities)}${count}${c.nonlinear ? " (nonlinear)" : ""}`, [
      ["DOF", a ? `${a.dof} (${a.free_unknowns} free unknowns, rank ${a.rank})` : "not analysed"],
      ["free", free, false, freeAll],
      ["residual", residual, unsolved],
      ["redundant", redundant || "none", false, redundantAll],
      ...(partly ? [["partly redundant", partly, false, partlyAll]] : []),
      ["conflicting", conflicting || "none", a && a.conflicting.length > 0, conflictingAll],
    ]));
  });
}

// What can still move: "3: points 1, 2; 5: radius; constraint 8: parameter 0" (runs of
// entities that can move the same points as "1–998: points 0, 1, 2, 3"), or "nothing (fully
// constrained)"; with the whole text when it had to be cut (see capped).
function freeText(free, parameters) {
  if ((!free || free.length === 0) && (!parameters || parameters.length === 0)) {
    return ["nothing (fully constrained)", null];
  }
  const entityParts = runs(free.map((f) => {
    const parts = [];
    if (f.points.length) parts.push(`point${f.points.length > 1 ? "s" : ""} ${f.points.join(", ")}`);
    if (f.scalars.length) parts.push("radius");
    return [f.entity, parts.join(", ")];
  }), (r, text) => `${r}: ${text}`);
  const parameterParts = (parameters ?? []).map((p) => `constraint ${p.constraint}: parameter ${p.parameter}`);
  return capped(entityParts.concat(parameterParts), "; ");
}

function takeState(s, keepView) {
  state = s;
  // A new sketch is drawn once: at the fitted view when it is to be fitted.
  takeScene(s.scene, true, false);
  if (!keepView) fitView();
  redrawAll();
  renderPanel();
  if (typeof sketcherPanel === "function") sketcherPanel();
}

// ---- dragging ------------------------------------------------------------------------------

async function startDrag(entity, index, pointerId, at) {
  drag = { entity, index, pointerId, started: false, busy: true, next: at, end: null, updates: 0, residual: null, saveAfter: false };
  canvas.setPointerCapture(pointerId);
  drawEntity(entities.get(entity));
  let r = await api("POST", "/api/drag/start", { entity, index });
  if (r.status === 409) {
    // A drag left open (a lost pointer release): end it, then start again.
    await api("POST", "/api/drag/end");
    r = await api("POST", "/api/drag/start", { entity, index });
  }
  if (!r.ok) {
    setStatus(r.data.error, true);
    const old = drag;
    drag = null;
    drawEntity(entities.get(old.entity));
    return;
  }
  drag.started = true;
  drag.busy = false;
  renderPanel();
  setStatus(`dragging point ${index} of entity ${entity} (${r.data.linear ? "linear path, cached factorization" : "nonlinear path, Newton"})`);
  pump();
}

/** Sends the next request of the drag, if none is on its way. */
async function pump() {
  if (!drag || !drag.started || drag.busy) return;
  const d = drag;
  if (d.next) {
    const to = d.next;
    d.next = null;
    d.busy = true;
    const t0 = performance.now();
    const r = await api("POST", "/api/drag/move", { to });
    const ms = performance.now() - t0;
    d.busy = false;
    if (r.ok) {
      d.updates += 1;
      takeScene(r.data, false);
      d.residual = { residual: r.data.residual, worst: r.data.worst };
      renderPanel();
      setStatus(`update ${r.data.update_us.toFixed(1)} µs in the solver, ${r.data.handler_us.toFixed(0)} µs in the handler, ${ms.toFixed(1)} ms round trip`);
    } else {
      setStatus(r.data.error, true);
    }
    pump();
  } else if (d.end) {
    d.busy = true;
    const r = await api("POST", d.end === "cancel" ? "/api/drag/cancel" : "/api/drag/end");
    drag = null;
    if (r.ok) {
      takeState(r.data, true);
      if (d.end === "cancel") setStatus("drag cancelled");
      else if (!statusLine.classList.contains("error")) setStatus(state.report ? state.report.summary : "drag ended");
    } else {
      setStatus(r.data.error, true);
      await reload(true);
    }
    if (d.saveAfter) await save();
  }
}

function finishDrag(how) {
  if (!drag) return;
  drag.end = drag.end ?? how;
  if (how === "cancel") drag.next = null;
  pump();
}

// ---- picking -------------------------------------------------------------------------------

/** How far from the pointer a handle may lie to be picked, in screen pixels. */
const PICK_RADIUS = 8;
/**
 * Every handle's screen position in buckets of PICK_RADIUS px ("i,j" → [{entity, index, x,
 * y}]), built on the first pick after a redraw (drawEntity drops it), so a pick looks at 9
 * buckets instead of every handle.
 */
let pickGrid = null;
/** The handle chosen with the cycle key (C) among several under the pointer, or null. */
let picked = null;
/** The last pointer position over the canvas (client coordinates), for the cycle key. */
let pointerAt = null;

function pickIndex() {
  if (pickGrid) return pickGrid;
  pickGrid = new Map();
  for (const e of entities.values()) {
    e.points.forEach((p, index) => {
      const [x, y] = toScreen(p);
      if (!Number.isFinite(x) || !Number.isFinite(y)) return;
      const k = `${Math.floor(x / PICK_RADIUS)},${Math.floor(y / PICK_RADIUS)}`;
      if (!pickGrid.has(k)) pickGrid.set(k, []);
      pickGrid.get(k).push({ entity: e.id, index, x, y });
    });
  }
  return pickGrid;
}

/**
 * The handles within PICK_RADIUS px of the pointer at (clientX, clientY), nearest first (on a
 * tie, by entity id, then point index): [{entity, index, distance}].
 */
function handlesNear(clientX, clientY) {
  const r = canvas.getBoundingClientRect();
  const [x, y] = [clientX - r.left, clientY - r.top];
  const [i, j] = [Math.floor(x / PICK_RADIUS), Math.floor(y / PICK_RADIUS)];
  const grid = pickIndex();
  const out = [];
  for (let di = -1; di <= 1; di++) {
    for (let dj = -1; dj <= 1; dj++) {
      for (const h of grid.get(`${i + di},${j + dj}`) ?? []) {
        const distance = Math.hypot(h.x - x, h.y - y);
        if (distance <= PICK_RADIUS) out.push({ entity: h.entity, index: h.index, distance });
      }
    }
  }
  return out.sort((a, b) => a.distance - b.distance || a.entity - b.entity || a.index - b.index);
}

/**
 * The handle a press at (clientX, clientY) grabs, {entity, index}, or null: the one chosen
 * with the cycle key while it is still under the pointer, else the nearest within PICK_RADIUS
 * px. (The topmost SVG element is not used: where handles overlap it is another one.)
 */
function pickHandle(clientX, clientY) {
  const near = handlesNear(clientX, clientY);
  const chosen = picked && near.find((h) => h.entity === picked.entity && h.index === picked.index);
  const h = chosen ?? near[0];
  return h ? { entity: h.entity, index: h.index } : null;
}

/** The ring around the handle a press would grab (drawn above the handles). */
const pickLayer = element("g", { id: "layer-pick" }, canvas);
const pickMark = element("circle", { class: "pick-mark", r: 7.5 }, pickLayer);
pickMark.style.display = "none";
/** The handle the ring marks, and the status line to put back when the pointer leaves it. */
let hovered = null;

/** Marks the handle a press at the last pointer position would grab, and names it. */
function showPick() {
  const near = pointerAt && !drag && !pan ? handlesNear(pointerAt[0], pointerAt[1]) : [];
  const h = pointerAt && near.length ? pickHandle(pointerAt[0], pointerAt[1]) : null;
  if (!h) {
    pickMark.style.display = "none";
    if (hovered) {
      setStatus(hovered.status, hovered.error);
      hovered = null;
    }
    return;
  }
  const [x, y] = toScreen(entities.get(h.entity).points[h.index]);
  pickMark.setAttribute("cx", x);
  pickMark.setAttribute("cy", y);
  pickMark.style.display = "";
  if (!hovered) hovered = { status: statusLine.textContent, error: statusLine.classList.contains("error") };
  const k = near.findIndex((n) => n.entity === h.entity && n.index === h.index);
  const more = near.length > 1 ? `; C for the next of the ${near.length}` : "";
  statusLine.textContent = `entity ${h.entity} point ${h.index} (${k + 1} of ${near.length} here): ${handleText(h.entity, h.index)}${more}`;
  statusLine.className = "";
}

/** Whether a key goes to a text field (where C is a letter, not the cycle key). */
const typing = (ev) => ev.target instanceof HTMLInputElement || ev.target instanceof HTMLTextAreaElement || ev.target.isContentEditable;

/** The cycle key: the next of the handles under the pointer becomes the one a press grabs. */
function cyclePick(step) {
  if (!pointerAt || drag) return;
  const near = handlesNear(pointerAt[0], pointerAt[1]);
  if (near.length === 0) {
    picked = null;
    setStatus(`no handle within ${PICK_RADIUS} px of the pointer`);
    return;
  }
  const now = pickHandle(pointerAt[0], pointerAt[1]);
  const k = near.findIndex((n) => n.entity === now.entity && n.index === now.index);
  const next = near[(k + step + near.length) % near.length];
  picked = { entity: next.entity, index: next.index };
  showPick();
}

// ---- pointer and keys ----------------------------------------------------------------------

canvas.addEventListener("pointerdown", (ev) => {
  if (ev.button !== 0 || drag) return;
  pointerAt = [ev.clientX, ev.clientY];
  const h = pickHandle(ev.clientX, ev.clientY);
  if (h) {
    ev.preventDefault();
    picked = null;
    pickMark.style.display = "none";
    hovered = null;
    startDrag(h.entity, h.index, ev.pointerId, null);
  } else {
    pan = { x: ev.clientX, y: ev.clientY, vx: view.x, vy: view.y };
    canvas.setPointerCapture(ev.pointerId);
    canvas.classList.add("panning");
  }
});

canvas.addEventListener("pointermove", (ev) => {
  const m = toModel(ev.clientX, ev.clientY);
  coordsLine.textContent = `x ${m[0].toPrecision(6)}  y ${m[1].toPrecision(6)}`;
  pointerAt = [ev.clientX, ev.clientY];
  if (drag && ev.pointerId === drag.pointerId && !drag.end) {
    drag.next = m;
    pump();
  } else if (pan) {
    view.x = pan.vx - (ev.clientX - pan.x) / view.k;
    view.y = pan.vy + (ev.clientY - pan.y) / view.k;
    requestRedraw();
  } else {
    // A handle chosen with the cycle key stays chosen while it is under the pointer.
    if (picked && !handlesNear(ev.clientX, ev.clientY).some((h) => h.entity === picked.entity && h.index === picked.index)) {
      picked = null;
    }
    showPick();
  }
});
canvas.addEventListener("pointerleave", () => {
  if (drag || pan) return;
  pointerAt = null;
  picked = null;
  showPick();
});

function release(ev) {
  if (drag && ev.pointerId === drag.pointerId) finishDrag("end");
  if (pan) {
    pan = null;
    canvas.classList.remove("panning");
  }
}
canvas.addEventListener("pointerup", release);
canvas.addEventListener("pointercancel", release);

canvas.addEventListener("wheel", (ev) => {
  ev.preventDefault();
  const before = toModel(ev.clientX, ev.clientY);
  view.k *= Math.exp(-ev.deltaY * 0.0015);
  const after = toModel(ev.clientX, ev.clientY);
  view.x += before[0] - after[0];
  view.y += before[1] - after[1];
  pointerAt = [ev.clientX, ev.clientY];
  requestRedraw();
}, { passive: false });

window.addEventListener("keydown", (ev) => {
  if (ev.key === "Escape") finishDrag("cancel");
  else if ((ev.ctrlKey || ev.metaKey) && (ev.key === "y" || (ev.shiftKey && ev.key.toLowerCase() === "z"))) {
    ev.preventDefault();
    action("/api/redo");
  }
  else if ((ev.ctrlKey || ev.metaKey) && ev.key === "z") { ev.preventDefault(); action("/api/undo"); }
  else if ((ev.ctrlKey || ev.metaKey) && ev.key === "s") { ev.preventDefault(); save(); }
  else if (!ev.ctrlKey && !ev.metaKey && ev.key === "f") fit();
  else if (!ev.ctrlKey && !ev.metaKey && ev.key === "s") action("/api/solve");
  else if (!ev.ctrlKey && !ev.metaKey && !ev.altKey && (ev.key === "c" || ev.key === "C") && !typing(ev)) {
    cyclePick(ev.shiftKey ? -1 : 1);
  }
});

window.addEventListener("resize", requestRedraw);
window.addEventListener("beforeunload", (ev) => {
  if (state && state.unsaved) {
    ev.preventDefault();
    ev.returnValue = "";
  }
});

// ---- buttons -------------------------------------------------------------------------------

async function action(path) {
  if (drag) return;
  const r = await api("POST", path);
  if (r.ok) {
    takeState(r.data, true);
    showMessage(state.report ? state.report.summary : "done", "info");
    setStatus("ready");
  } else {
    showMessage(r.data.error, "error");
  }
}

async function save() {
  // A save asked for during a drag (Ctrl+S right after the mouse is released, before the
  // drag's end is answered) runs once the drag has ended, on the geometry it leaves.
  if (drag) {
    drag.saveAfter = true;
    return;
  }
  const r = await api("POST", "/api/save");
  if (r.ok) {
    takeState(r.data.state, true);
    showMessage(`saved ${r.data.saved} (${r.data.bytes} bytes)`, "info");
  } else {
    showMessage(r.data.error, "error");
  }
}

document.getElementById("solve").addEventListener("click", () => action("/api/solve"));
document.getElementById("undo").addEventListener("click", () => action("/api/undo"));
document.getElementById("redo").addEventListener("click", () => action("/api/redo"));
document.getElementById("save").addEventListener("click", save);
document.getElementById("fit").addEventListener("click", fit);

/**
 * The page's first load, in ms since navigation started (performance.now()): the state
 * answered and parsed, drawn (script done), and the first frame with the drawing painted.
 */
const loadTimes = { state: null, drawn: null, painted: null };

async function reload(keepView) {
  const r = await api("GET", "/api/state");
  if (r.ok) {
    const first = loadTimes.state === null;
    if (first) loadTimes.state = performance.now();
    takeState(r.data, keepView);
    if (first) {
      loadTimes.drawn = performance.now();
      // A task queued from the next animation frame runs after that frame is painted.
      requestAnimationFrame(() => setTimeout(() => { loadTimes.painted = performance.now(); }, 0));
    }
    if (!keepView) setStatus("ready: drag a point");
  } else {
    setStatus(r.data.error, true);
  }
}

reload(false);
