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

function size() {
  const r = canvas.getBoundingClientRect();
  return { w: r.width || 1, h: r.height || 1 };
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

function fit() {
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
  redrawAll();
}

// ---- drawing -------------------------------------------------------------------------------

function element(tag, attrs, parent) {
  const el = document.createElementNS(SVG_NS, tag);
  for (const [k, v] of Object.entries(attrs)) el.setAttribute(k, v);
  if (parent) parent.appendChild(el);
  return el;
}

const pointsAttr = (list) => list.map((p) => toScreen(p).map((v) => v.toFixed(2)).join(",")).join(" ");

/** The elements of each entity in each layer, by entity id, so an update replaces only them. */
const drawn = new Map();

/**
 * What of entity `id` can still move, from its component's DOF analysis: the indices of its
 * free points and whether its radius is free; `null` when the component was not analysed.
 */
function freedomOf(id) {
  const c = state?.components?.find((comp) => comp.entities.includes(id));
  if (!c || !c.analysis) return null;
  const f = c.analysis.free.find((x) => x.entity === id);
  return { points: new Set(f ? f.points : []), radius: !!(f && f.scalars.length) };
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
  e.points.forEach((p, index) => {
    const [cx, cy] = toScreen(p);
    const active = drag && drag.entity === e.id && drag.index === index;
    const fixed = freedom !== null && !freedom.points.has(index);
    const cls = `handle${e.kind === "point" ? " point" : ""}${active ? " active" : ""}${fixed ? " determined" : ""}`;
    const el = element("circle", { class: cls, cx, cy, r: e.kind === "point" ? 5 : 4.5 }, layers.points);
    el.dataset.entity = e.id;
    el.dataset.index = index;
    const title = element("title", {}, el);
    title.textContent = `entity ${e.id} (${e.kind}), point ${index}: (${p[0].toPrecision(6)}, ${p[1].toPrecision(6)})`;
    els.push(el);
  });
  drawn.set(e.id, els);
}

/** A constraint's residual as a label shows it: |g| in two digits, "?" when unknown. */
function residualText(r) {
  if (typeof r !== "number") return "|g| ?";
  return r === 0 ? "|g| 0" : `|g| ${r.toExponential(1)}`;
}

/** The elements of each constraint's glyphs, by constraint id. */
const drawnGlyphs = new Map();

function drawGlyphs(constraint, list) {
  drawnGlyphs.get(constraint)?.remove();
  const g = element("g", {}, layers.glyphs);
  for (const glyph of list) {
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
  const title = element("title", {}, g);
  title.textContent = `constraint ${constraint}`;
  drawnGlyphs.set(constraint, g);
}

function redrawAll() {
  for (const e of entities.values()) drawEntity(e);
  for (const [c, list] of glyphs) drawGlyphs(c, list);
  if (typeof sketcherRedraw === "function") sketcherRedraw();
}

/** Puts entities and glyphs from an answer in place; `full` replaces everything. */
function takeScene(scene, full) {
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
    drawEntity(e);
  }
  for (const c of touched) drawGlyphs(c, glyphs.get(c));
  if (typeof sketcherRedraw === "function") sketcherRedraw(scene);
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
}

const ids = (list) => (list.length > 6 ? `${list.slice(0, 3).join(", ")}, …, ${list[list.length - 1]}` : list.join(", "));
const named = (refs) => refs.map((c) => `${c.id} (${c.kind})`).join(", ");
const sci = (v) => (v === 0 ? "0" : v.toExponential(2));

/** A block of lines: a bold title, then (label, text, bad) rows. */
function block(title, rows) {
  const div = document.createElement("div");
  div.className = "block";
  const h = document.createElement("p");
  h.className = "title";
  h.textContent = title;
  div.appendChild(h);
  for (const [label, text, bad] of rows) {
    const p = document.createElement("p");
    const l = document.createElement("span");
    l.className = "label";
    l.textContent = `${label} `;
    const t = document.createElement("span");
    t.textContent = text;
    if (bad) t.className = "bad";
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
    comps.appendChild(block(`${k + 1}. entities ${ids(c.entities)}${c.nonlinear ? " (nonlinear)" : ""}`, [
      ["DOF", a ? `${a.dof} (${a.free_unknowns} free unknowns, rank ${a.rank})` : "not analysed"],
      ["free", a ? freeText(a.free, a.free_parameters) : "–"],
      ["residual", residual, unsolved],
      ["redundant", a ? named(a.redundant) || "none" : "–"],
      ...(a && a.partly_redundant.length ? [["partly redundant", named(a.partly_redundant)]] : []),
      ["conflicting", a ? named(a.conflicting) || "none" : "–", a && a.conflicting.length > 0],
    ]));
  });
}

// What can still move: "3: points 1, 2; 5: radius; constraint 8: parameter 0", or "nothing
// (fully constrained)".
function freeText(free, parameters) {
  if ((!free || free.length === 0) && (!parameters || parameters.length === 0)) {
    return "nothing (fully constrained)";
  }
  return free
    .map((f) => {
      const parts = [];
      if (f.points.length) parts.push(`point${f.points.length > 1 ? "s" : ""} ${f.points.join(", ")}`);
      if (f.scalars.length) parts.push("radius");
      return `${f.entity}: ${parts.join(", ")}`;
    })
    .concat((parameters ?? []).map((p) => `constraint ${p.constraint}: parameter ${p.parameter}`))
    .join("; ");
}

function takeState(s, keepView) {
  state = s;
  takeScene(s.scene, true);
  if (!keepView) fit();
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

// ---- pointer and keys ----------------------------------------------------------------------

canvas.addEventListener("pointerdown", (ev) => {
  if (ev.button !== 0 || drag) return;
  const t = ev.target;
  if (t.dataset && t.dataset.entity !== undefined) {
    ev.preventDefault();
    startDrag(Number(t.dataset.entity), Number(t.dataset.index), ev.pointerId, null);
  } else {
    pan = { x: ev.clientX, y: ev.clientY, vx: view.x, vy: view.y };
    canvas.setPointerCapture(ev.pointerId);
    canvas.classList.add("panning");
  }
});

canvas.addEventListener("pointermove", (ev) => {
  const m = toModel(ev.clientX, ev.clientY);
  coordsLine.textContent = `x ${m[0].toPrecision(6)}  y ${m[1].toPrecision(6)}`;
  if (drag && ev.pointerId === drag.pointerId && !drag.end) {
    drag.next = m;
    pump();
  } else if (pan) {
    view.x = pan.vx - (ev.clientX - pan.x) / view.k;
    view.y = pan.vy + (ev.clientY - pan.y) / view.k;
    redrawAll();
  }
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
  redrawAll();
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
});

window.addEventListener("resize", redrawAll);
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

async function reload(keepView) {
  const r = await api("GET", "/api/state");
  if (r.ok) {
    takeState(r.data, keepView);
    if (!keepView) setStatus("ready: drag a point");
  } else {
    setStatus(r.data.error, true);
  }
}

reload(false);
