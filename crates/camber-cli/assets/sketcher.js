// camber edit: the sketcher's model, the first of its three scripts (the server joins them, in
// this order, as /sketcher.js: this file, then
// sketcher-tools.js: drawing, constraints from a selection, pointer and keys; then
// sketcher-view.js: labels, overlay, combs, panels, and the hooks editor.js calls). Here: its
// state, picking (points, curves, glyphs), snapping and inferred constraints, the selection,
// and the one request that adds to the sketch. The sketcher holds no solver of its own:
// everything it adds or changes is a request to the library's routes (create, delete,
// dimension, parameter, fillet), and it draws what the state answers. It uses editor.js's
// globals (state, entities, glyphs, view, toScreen, toModel, api, takeState, element, layers,
// canvas, showMessage, setStatus, pickHandle).
"use strict";

const overlayLayer = element("g", { id: "layer-overlay" }, canvas);
const dimensionLayer = element("g", { id: "layer-dimensions" }, canvas);
const combLayer = element("g", { id: "layer-combs" }, canvas);
const shapeNote = document.getElementById("shape-warning");
const hintBox = document.getElementById("hint");
const dimInput = document.getElementById("dim-input");

/** Pick radius for points, glyphs and labels, in screen pixels. */
const PICK_PX = 10;
/** Pick radius for curves, in screen pixels. */
const CURVE_PX = 6;
/** Within this angle of the axes a drawn line is inferred horizontal or vertical. */
const AXIS_DEG = 3;
/** Within this angle of an arc's end tangent a line drawn from that end is inferred tangent. */
const TANGENT_DEG = 5;
/** Above this many constraints the list shows only those that need attention. */
const LIST_LIMIT = 300;

const TOOLS = {
  select: { key: "v", label: "Select", help: "select: click, Shift+click, Shift+drag a box; drag points" },
  point: { key: "p", label: "Point", help: "point: click" },
  line: { key: "l", label: "Line", help: "line: click the start, click the end" },
  polyline: { key: "y", label: "Polyline", help: "polyline: click each corner; click the first point to close, Enter or double-click to end" },
  circle: { key: "o", label: "Circle", help: "circle: click the centre, click a point of the rim" },
  arc: { key: "a", label: "Arc", help: "arc: click the centre, the start, the end (counter-clockwise)" },
  ellipse: { key: "e", label: "Ellipse", help: "ellipse: click the centre, the end of one axis, a point giving the other" },
  bezier: { key: "b", label: "Bézier", help: "Bézier: click each control point; Enter or double-click to end" },
  bspline: { key: "n", label: "B-spline", help: "B-spline (cubic, clamped): click each control point; Enter or double-click to end" },
};

let tool = "select";
/** The shape being drawn: its clicked points ({at, snap}) and the cursor's snap. */
let drawing = null;
/** Selected items: {type: "point", entity, index} | {type: "entity", id} | {type: "constraint", id}. */
let selection = [];
/** A press in select mode: where, whether Shift was down; a box selection in progress. */
let press = null;
let box = null;
/** Curvature combs: shown or not, the last ones fetched, a fetch on its way or due. */
const combs = { on: false, list: [], busy: false, again: false };
/** The cusps and self-crossings of the geometry drawn (the state's, or the last move's). */
let shapeWarnings = [];

// ---- small helpers ---------------------------------------------------------------------------

const sub = (a, b) => [a[0] - b[0], a[1] - b[1]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1];
const cross = (a, b) => a[0] * b[1] - a[1] * b[0];
const norm = (a) => Math.hypot(a[0], a[1]);
const dist = (a, b) => norm(sub(a, b));
const round = (v) => Number(v.toPrecision(12));
const pt = (p) => [round(p[0]), round(p[1])];

function canvasXY(ev) {
  const r = canvas.getBoundingClientRect();
  return [ev.clientX - r.left, ev.clientY - r.top];
}

/** A point of the sketch as the file names it. */
function pointRef(entity, index) {
  const e = entities.get(entity);
  return e && e.kind === "point" ? { point: entity } : { control: [entity, index] };
}

/**
 * The handle at canvas position `xy`: the one editor.js's picking would grab (the nearest
 * within its pick radius, or the one chosen with the cycle key), as {entity, index, at}, or null.
 */
function nearestHandle(xy) {
  const r = canvas.getBoundingClientRect();
  const h = pickHandle(r.left + xy[0], r.top + xy[1]);
  const e = h && entities.get(h.entity);
  return e ? { entity: h.entity, index: h.index, at: e.points[h.index] } : null;
}

/** Distance in pixels from canvas position `xy` to the segment a–b (screen points). */
function segmentDistance(xy, a, b) {
  const ab = sub(b, a);
  const t = Math.max(0, Math.min(1, dot(sub(xy, a), ab) / (dot(ab, ab) || 1)));
  return dist(xy, [a[0] + t * ab[0], a[1] + t * ab[1]]);
}

/** The polyline an entity is drawn with, in model coordinates (a circle sampled). */
function outlineOf(e) {
  if (e.kind === "line") return e.points;
  if (e.kind === "circle") {
    const [c, r] = [e.points[0], e.radius];
    return Array.from({ length: 65 }, (_, k) => [c[0] + r * Math.cos((k * Math.PI) / 32), c[1] + r * Math.sin((k * Math.PI) / 32)]);
  }
  return e.samples ?? [];
}

/** The entity whose outline passes nearest `xy` within the curve pick radius: {id, d, k, n}. */
function nearestEntity(xy) {
  let best = null;
  for (const e of entities.values()) {
    if (e.kind === "point") continue;
    const line = outlineOf(e).map(toScreen);
    for (let k = 0; k + 1 < line.length; k++) {
      const d = segmentDistance(xy, line[k], line[k + 1]);
      if (d <= CURVE_PX && (!best || d < best.d)) best = { id: e.id, d, k, n: line.length };
    }
  }
  return best;
}

/**
 * The constraint whose glyph is drawn nearest `xy`, within 8 pixels: among the letters
 * (`marks`, drawn beside their anchor) or among the other shapes (rings, arrows, triangles,
 * drawn on the geometry).
 */
function nearestGlyph(xy, marks) {
  let best = null;
  for (const [c, list] of glyphs) {
    for (const g of list) {
      if ((g.shape === "mark") !== marks) continue;
      // Where the glyph is drawn: a mark's letter up and right of its anchor (editor.js).
      const s = toScreen(g.at);
      const drawn = g.shape === "mark" ? [s[0] + 10, s[1] - 10] : s;
      const d = dist(drawn, xy);
      if (d <= 8 && (!best || d < best.d)) best = { id: c, d };
    }
  }
  return best;
}

function nextIds(n) {
  const first = state.next_id;
  return Array.from({ length: n }, (_, k) => first + k);
}

/** Grid step in model units: a power of ten with cells of at least 20 pixels. */
function gridStep() {
  return Math.pow(10, Math.ceil(Math.log10(20 / view.k)));
}

/**
 * Where a click at canvas position `xy` lands: on a handle (coincident), on an entity (on it),
 * on the grid, or free. `own` are points of the shape being drawn that it may close onto.
 */
function snapAt(xy, own) {
  if (own) {
    for (let k = 0; k < own.length; k++) {
      if (dist(toScreen(own[k]), xy) <= PICK_PX) return { at: own[k], own: k, label: "close" };
    }
  }
  const h = nearestHandle(xy);
  if (h) return { at: h.at, ref: pointRef(h.entity, h.index), entity: h.entity, index: h.index, label: "coincident" };
  const on = nearestEntity(xy);
  const m = toModel(xy[0] + canvas.getBoundingClientRect().left, xy[1] + canvas.getBoundingClientRect().top);
  if (on) {
    const e = entities.get(on.id);
    const kinds = { line: "point_on_line", circle: "point_on_circle", arc: "point_on_arc", ellipse: "point_on_ellipse", elliptic_arc: "point_on_ellipse", bezier: "point_on_curve" };
    if (kinds[e.kind]) {
      return { at: pt(m), onEntity: on.id, onKind: kinds[e.kind], u: e.kind === "bezier" ? on.k / (on.n - 1) : null, label: `on ${e.kind} ${e.id}` };
    }
  }
  const step = gridStep();
  const g = [Math.round(m[0] / step) * step, Math.round(m[1] / step) * step];
  if (dist(toScreen(g), xy) <= 6) return { at: pt(g), label: "grid" };
  return { at: pt(m), label: null };
}

/** The constraints tying a new point `ref` to where it snapped. */
function snapConstraints(snap, ref) {
  if (snap.ref) return [{ kind: "coincident", a: ref, b: snap.ref }];
  if (snap.onKind === "point_on_line") return [{ kind: "point_on_line", point: ref, line: snap.onEntity }];
  if (snap.onKind === "point_on_circle") return [{ kind: "point_on_circle", point: ref, circle: snap.onEntity }];
  if (snap.onKind === "point_on_arc") return [{ kind: "point_on_arc", point: ref, arc: snap.onEntity }];
  if (snap.onKind === "point_on_ellipse") return [{ kind: "point_on_ellipse", point: ref, ellipse: snap.onEntity }];
  if (snap.onKind === "point_on_curve") return [{ kind: "point_on_curve", point: ref, curve: snap.onEntity, u: { free: snap.u } }];
  return [];
}

/** Horizontal, vertical or tangent constraints a line from a to b infers. */
function lineInferences(line, a, b, startSnap) {
  const d = sub(b.at, a.at);
  const out = [];
  const angle = (Math.atan2(Math.abs(d[1]), Math.abs(d[0])) * 180) / Math.PI;
  if (norm(d) > 0 && angle <= AXIS_DEG) out.push({ kind: "horizontal", of: { line } });
  else if (norm(d) > 0 && angle >= 90 - AXIS_DEG) out.push({ kind: "vertical", of: { line } });
  // Drawn from an arc's end along its tangent: tangent to the arc there.
  if (startSnap && startSnap.ref && (startSnap.index === 1 || startSnap.index === 2)) {
    const arc = entities.get(startSnap.entity);
    if (arc && arc.kind === "arc") {
      const r = sub(startSnap.at, arc.points[0]);
      const t = [-r[1], r[0]];
      if (norm(t) > 0 && norm(d) > 0 && Math.abs(cross(t, d)) / (norm(t) * norm(d)) <= Math.sin((TANGENT_DEG * Math.PI) / 180)) {
        out.push({ kind: "arc_tangent_to_line", arc: arc.id, end: startSnap.index === 1 ? "start" : "end", line, sense: dot(t, d) > 0 ? "agree" : "oppose" });
      }
    }
  }
  return out;
}

// ---- adding to the sketch --------------------------------------------------------------------

/** Sends entities and constraints to the sketch; shows the answer. */
async function create(body) {
  const r = await api("POST", "/api/create", body);
  if (r.ok) {
    takeState(r.data, true);
    showMessage(state.report ? state.report.summary : "added", state.report && state.report.summary.includes("failed") ? "error" : "info");
  } else {
    showMessage(r.data.error, "error");
  }
  return r.ok;
}

// ---- selection -------------------------------------------------------------------------------

const key = (item) => (item.type === "point" ? `p${item.entity}:${item.index}` : item.type === "entity" ? `e${item.id}` : `c${item.id}`);

function select(item, add) {
  if (!add) selection = item ? [item] : [];
  else if (item) {
    const k = key(item);
    const at = selection.findIndex((s) => key(s) === k);
    if (at >= 0) selection.splice(at, 1);
    else selection.push(item);
  }
  drawOverlay();
  renderSelection();
}

function itemAt(xy) {
  const h = nearestHandle(xy);
  if (h) {
    const e = entities.get(h.entity);
    return e.kind === "point" ? { type: "entity", id: h.entity } : { type: "point", entity: h.entity, index: h.index };
  }
  const label = dimensionAt(xy);
  if (label !== null) return { type: "constraint", id: label };
  // A letter lies beside the geometry; a ring or an arrow lies on it, and the geometry under
  // the pointer wins over it (the ring's edge, off the curve, still picks the constraint).
  const mark = nearestGlyph(xy, true);
  if (mark) return { type: "constraint", id: mark.id };
  const on = nearestEntity(xy);
  if (on) return { type: "entity", id: on.id };
  const g = nearestGlyph(xy, false);
  if (g) return { type: "constraint", id: g.id };
  return null;
}

function boxSelect(a, b, add) {
  const lo = [Math.min(a[0], b[0]), Math.min(a[1], b[1])];
  const hi = [Math.max(a[0], b[0]), Math.max(a[1], b[1])];
  const inside = (p) => {
    const s = toScreen(p);
    return s[0] >= lo[0] && s[0] <= hi[0] && s[1] >= lo[1] && s[1] <= hi[1];
  };
  if (!add) selection = [];
  for (const e of entities.values()) {
    const shape = e.kind === "point" ? e.points : outlineOf(e);
    if (shape.length && shape.every(inside) && e.points.every(inside)) {
      if (!selection.some((s) => s.type === "entity" && s.id === e.id)) selection.push({ type: "entity", id: e.id });
    }
  }
  drawOverlay();
  renderSelection();
}

/** Drops selected items the state no longer has. */
function pruneSelection() {
  const held = new Set((state?.constraints ?? []).map((c) => c.id));
  selection = selection.filter((s) => (s.type === "constraint" ? held.has(s.id) : entities.has(s.type === "point" ? s.entity : s.id)));
}

