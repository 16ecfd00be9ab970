// camber edit: the sketcher. Drawing tools with snapping and inferred constraints, selection
// (click, Shift+click, Shift+drag box), constraints applied to a selection, dimensions typed
// on the picture, the constraint list, parameters, fillets, save-as and export. It holds no
// solver of its own: everything it adds or changes is a request to the library's routes
// (create, delete, dimension, parameter, fillet), and it draws what the state answers. It
// uses editor.js's globals (state, entities, glyphs, view, toScreen, toModel, api, takeState,
// element, layers, canvas, showMessage, setStatus) and is called back by it after every
// redraw (sketcherRedraw) and every new state (sketcherPanel).
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

// ---- drawing tools ---------------------------------------------------------------------------

/** Chooses a tool; `quiet` leaves the status line alone (at start, editor.js's own line stays). */
function setTool(name, quiet) {
  tool = name;
  drawing = name === "select" ? null : { pts: [], cursor: null };
  for (const b of document.querySelectorAll("#tools button")) b.classList.toggle("active", b.dataset.tool === name);
  canvas.classList.toggle("drawing", name !== "select");
  hintBox.hidden = true;
  if (!quiet) setStatus(TOOLS[name].help);
  drawOverlay();
}

/** How many clicks a tool takes (Infinity: until Enter, a double-click, or closing). */
const CLICKS = { point: 1, line: 2, circle: 2, arc: 3, ellipse: 3, polyline: Infinity, bezier: Infinity, bspline: Infinity };

function drawClick(ev) {
  const xy = canvasXY(ev);
  const own = tool === "polyline" && drawing.pts.length >= 3 ? [drawing.pts[0].at] : null;
  const snap = snapAt(xy, own);
  if (snap.own === 0) {
    drawing.closed = true;
    finishDrawing();
    return;
  }
  drawing.pts.push({ at: snap.at, snap });
  if (drawing.pts.length >= CLICKS[tool]) finishDrawing();
  else drawOverlay();
}

/** The entities and constraints of the shape drawn, with fresh ids. */
function shapeOf(kind, pts, closed) {
  const ents = [];
  const cons = [];
  const snapTo = (snap, ref) => snapConstraints(snap, ref).forEach((c) => cons.push(c));
  if (kind === "point") {
    ents.push({ kind: "point", at: pts[0].at });
    snapTo(pts[0].snap, { point: "#0" });
  } else if (kind === "line" || kind === "polyline") {
    for (let k = 0; k + 1 < pts.length; k++) {
      ents.push({ kind: "line", from: pts[k].at, to: pts[k + 1].at });
      const line = `#${ents.length - 1}`;
      if (k === 0) snapTo(pts[0].snap, { control: [line, 0] });
      else cons.push({ kind: "coincident", a: { control: [`#${ents.length - 2}`, 1] }, b: { control: [line, 0] } });
      snapTo(pts[k + 1].snap, { control: [line, 1] });
      lineInferences(line, pts[k], pts[k + 1], k === 0 ? pts[0].snap : null).forEach((c) => cons.push(c));
    }
    if (closed && ents.length >= 2) {
      ents.push({ kind: "line", from: pts[pts.length - 1].at, to: pts[0].at });
      const line = `#${ents.length - 1}`;
      cons.push({ kind: "coincident", a: { control: [`#${ents.length - 2}`, 1] }, b: { control: [line, 0] } });
      cons.push({ kind: "coincident", a: { control: [line, 1] }, b: { control: ["#0", 0] } });
      lineInferences(line, pts[pts.length - 1], pts[0], null).forEach((c) => cons.push(c));
    }
  } else if (kind === "circle") {
    ents.push({ kind: "circle", center: pts[0].at, radius: round(dist(pts[0].at, pts[1].at)) });
    snapTo(pts[0].snap, { control: ["#0", 0] });
  } else if (kind === "arc") {
    const [c, a, b] = pts.map((p) => p.at);
    const a0 = Math.atan2(a[1] - c[1], a[0] - c[0]);
    let a1 = Math.atan2(b[1] - c[1], b[0] - c[0]);
    if (a1 <= a0) a1 += 2 * Math.PI;
    ents.push({ kind: "arc", center: c, radius: round(dist(c, a)), start_angle: round(a0), end_angle: round(a1) });
    snapTo(pts[0].snap, { control: ["#0", 0] });
    snapTo(pts[1].snap, { control: ["#0", 1] });
    snapTo(pts[2].snap, { control: ["#0", 2] });
  } else if (kind === "ellipse") {
    const [c, v, q] = pts.map((p) => p.at);
    const u = sub(v, c);
    const a = norm(u);
    const b = a > 0 ? Math.abs(cross(u, sub(q, c))) / a : 0;
    ents.push({ kind: "ellipse", center: c, semi_axis_a: round(a), semi_axis_b: round(b), rotation: round(Math.atan2(u[1], u[0])) });
    snapTo(pts[0].snap, { control: ["#0", 0] });
  } else if (kind === "bezier" || kind === "bspline") {
    const cps = pts.map((p) => p.at);
    if (kind === "bezier") ents.push({ kind: "bezier", control_points: cps });
    else {
      const p = Math.min(3, cps.length - 1);
      const inner = cps.length - p - 1;
      const knots = [...Array(p + 1).fill(0), ...Array.from({ length: inner }, (_, k) => round((k + 1) / (inner + 1))), ...Array(p + 1).fill(1)];
      ents.push({ kind: "bspline", degree: p, knots, control_points: cps });
    }
    snapTo(pts[0].snap, { control: ["#0", 0] });
    snapTo(pts[pts.length - 1].snap, { control: ["#0", cps.length - 1] });
  }
  return { ents, cons };
}

/** Replaces the placeholders "#k" (the k-th new entity) by ids from the state's next id. */
function withIds(shape) {
  const ids = nextIds(shape.ents.length + shape.cons.length);
  const fill = (v) => {
    if (typeof v === "string" && /^#\d+$/.test(v)) return ids[Number(v.slice(1))];
    if (Array.isArray(v)) return v.map(fill);
    if (v && typeof v === "object") return Object.fromEntries(Object.entries(v).map(([k, x]) => [k, fill(x)]));
    return v;
  };
  return {
    entities: shape.ents.map((e, k) => ({ id: ids[k], ...e })),
    constraints: shape.cons.map((c, k) => ({ id: ids[shape.ents.length + k], ...fill(c) })),
  };
}

function minimumPoints(kind) {
  return { polyline: 2, bezier: 2, bspline: 2 }[kind] ?? CLICKS[kind];
}

async function finishDrawing() {
  if (!drawing) return;
  hintBox.hidden = true;
  const { pts, closed } = drawing;
  drawing = { pts: [], cursor: drawing.cursor };
  drawOverlay();
  if (pts.length < minimumPoints(tool)) return;
  const degenerate = pts.some((p, k) => k > 0 && dist(p.at, pts[k - 1].at) === 0);
  if (degenerate && tool !== "point") {
    showMessage("two clicks at the same place: nothing drawn", "error");
    return;
  }
  await create(withIds(shapeOf(tool, pts, closed)));
}

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

// ---- constraints from a selection -------------------------------------------------------------

const ROUND = ["circle", "arc"];
const CURVES = ["bezier", "bspline", "nurbs", "hermite"];

/** The point a selected item names: {ref, at}. */
function pointOf(item) {
  const e = entities.get(item.entity);
  return { ref: pointRef(item.entity, item.index), at: e.points[item.index] };
}

/** The line's direction, from its first point to its second. */
const lineDir = (e) => sub(e.points[1], e.points[0]);

/**
 * The constraints that fit the selection: [{label, key, make}] where make() gives the
 * constraints' file forms (without ids), dimensions at their current value so that adding
 * one does not move anything.
 */
function applicable() {
  const points = selection.filter((s) => s.type === "point").map(pointOf);
  const chosen = selection.filter((s) => s.type === "entity").map((s) => entities.get(s.id)).filter(Boolean);
  // A point entity selected counts as a point.
  for (const e of chosen.filter((e) => e.kind === "point")) points.push({ ref: { point: e.id }, at: e.points[0] });
  const ents = chosen.filter((e) => e.kind !== "point");
  const lines = ents.filter((e) => e.kind === "line");
  const rounds = ents.filter((e) => ROUND.includes(e.kind));
  const curves = ents.filter((e) => CURVES.includes(e.kind));
  const out = [];
  const add = (label, key, make) => out.push({ label, key, make });
  const only = (np, nl, nr, nc) => points.length === np && lines.length === nl && rounds.length === nr && curves.length === nc && ents.length === nl + nr + nc;
  if (only(1, 0, 0, 0)) add("Fix point", "F", () => [{ kind: "fixed", target: { point: points[0].ref } }]);
  if (only(2, 0, 0, 0)) {
    const [a, b] = points;
    const d = sub(b.at, a.at);
    add("Coincident", "C", () => [{ kind: "coincident", a: a.ref, b: b.ref }]);
    add("Horizontal", "H", () => [{ kind: "horizontal", of: { a: a.ref, b: b.ref } }]);
    add("Vertical", "V", () => [{ kind: "vertical", of: { a: a.ref, b: b.ref } }]);
    add("Distance", "D", () => [{ kind: "distance", a: a.ref, b: b.ref, distance: round(norm(d)) }]);
    add("Horizontal distance", "X", () => [{ kind: "horizontal_distance", of: { a: a.ref, b: b.ref }, distance: round(d[0]) }]);
    add("Vertical distance", "Y", () => [{ kind: "vertical_distance", of: { a: a.ref, b: b.ref }, distance: round(d[1]) }]);
  }
  if (only(0, 1, 0, 0)) {
    const l = lines[0];
    add("Horizontal", "H", () => [{ kind: "horizontal", of: { line: l.id } }]);
    add("Vertical", "V", () => [{ kind: "vertical", of: { line: l.id } }]);
    add("Length", "D", () => [{ kind: "distance", a: { control: [l.id, 0] }, b: { control: [l.id, 1] }, distance: round(norm(lineDir(l))) }]);
  }
  if (only(0, 2, 0, 0)) {
    const [l, m] = lines;
    const angle = Math.atan2(cross(lineDir(l), lineDir(m)), dot(lineDir(l), lineDir(m)));
    add("Parallel", "P", () => [{ kind: "parallel", first: l.id, second: m.id }]);
    add("Perpendicular", "T", () => [{ kind: "perpendicular", first: l.id, second: m.id }]);
    add("Equal length", "E", () => [{ kind: "equal_length", first: { line: l.id }, second: { line: m.id } }]);
    add("Angle", "A", () => [{ kind: "angle", first: l.id, second: m.id, angle: round(angle) }]);
    add("Fillet (radius 10% of the shorter)", "R", null);
  }
  if (only(1, 1, 0, 0)) {
    const [p, l] = [points[0], lines[0]];
    const side = cross(lineDir(l), sub(p.at, l.points[0])) >= 0 ? "left" : "right";
    const distance = Math.abs(cross(lineDir(l), sub(p.at, l.points[0]))) / (norm(lineDir(l)) || 1);
    add("On line", "O", () => [{ kind: "point_on_line", point: p.ref, line: l.id }]);
    add("Midpoint", "M", () => [{ kind: "midpoint", point: p.ref, of: { line: l.id } }]);
    add("Distance to line", "D", () => [{ kind: "point_line_distance", point: p.ref, line: l.id, distance: round(distance), side }]);
  }
  if (only(1, 0, 1, 0)) {
    const [p, c] = [points[0], rounds[0]];
    add(c.kind === "arc" ? "On arc" : "On circle", "O", () => [c.kind === "arc" ? { kind: "point_on_arc", point: p.ref, arc: c.id } : { kind: "point_on_circle", point: p.ref, circle: c.id }]);
  }
  if (only(0, 0, 1, 0)) {
    const c = rounds[0];
    const r = c.kind === "circle" ? c.radius : dist(c.points[0], c.points[1]);
    add("Radius", "R", () => [{ kind: "radius", circle: c.id, radius: round(r) }]);
  }
  if (only(0, 0, 2, 0)) {
    const [c, d] = rounds;
    add("Equal radius", "E", () => [{ kind: "equal_radius", first: c.id, second: d.id }]);
    add("Concentric", "O", () => [{ kind: "concentric", first: c.id, second: d.id }]);
  }
  if (only(0, 1, 1, 0) && rounds[0].kind === "arc") {
    const [l, a] = [lines[0], rounds[0]];
    const side = cross(lineDir(l), sub(a.points[0], l.points[0])) >= 0 ? "left" : "right";
    add("Tangent", "T", () => [{ kind: "arc_touches_line", arc: a.id, line: l.id, side }]);
  }
  if (only(0, 0, 0, 2)) {
    const [c, d] = curves;
    add("G1 join (end to start)", "G", () => [{ kind: "g1_join_free", first: c.id, second: d.id }]);
    add("G2 join (end to start)", "K", () => [{ kind: "g2_join", first: c.id, second: d.id }]);
  }
  if (ents.length > 0 && points.length === 0) {
    add(ents.length === 1 ? "Fix" : "Fix each", "F", () => ents.map((e) => ({ kind: "fixed", target: { entity: e.id } })));
  }
  return out;
}

async function apply(choice) {
  if (!choice) return;
  if (choice.make === null) return fillet();
  const made = choice.make();
  const ids = nextIds(made.length);
  if (await create({ constraints: made.map((c, k) => ({ id: ids[k], ...c })) })) select(null);
}

async function fillet() {
  const lines = selection.filter((s) => s.type === "entity").map((s) => entities.get(s.id));
  const shorter = Math.min(...lines.map((l) => norm(lineDir(l))));
  const r = await api("POST", "/api/fillet", { first: lines[0].id, second: lines[1].id, radius: round(0.1 * shorter) });
  if (r.ok) {
    takeState(r.data, true);
    showMessage(state.report.summary, "info");
    select(null);
  } else showMessage(r.data.error, "error");
}

async function deleteSelection() {
  const ents = new Set();
  const cons = new Set();
  for (const s of selection) {
    if (s.type === "entity") ents.add(s.id);
    else if (s.type === "constraint") cons.add(s.id);
    else if (entities.get(s.entity)?.kind === "point") ents.add(s.entity);
  }
  if (!ents.size && !cons.size) {
    showMessage("select entities or constraints to delete (a curve's control point cannot be deleted alone)", "error");
    return;
  }
  const r = await api("POST", "/api/delete", { entities: [...ents], constraints: [...cons] });
  if (r.ok) {
    selection = [];
    takeState(r.data, true);
    showMessage(state.report.summary, "info");
  } else showMessage(r.data.error, "error");
}

// ---- dimensions ------------------------------------------------------------------------------

const ANGLES = ["angle", "arc_angle"];

function valueText(c) {
  if (ANGLES.includes(c.kind)) return `${((c.value * 180) / Math.PI).toPrecision(5).replace(/\.?0+$/, "")}°`;
  const v = Number(c.value.toPrecision(6));
  return c.kind === "radius" ? `R ${v}` : `${v}`;
}

/** Canvas positions of the drawn dimension labels, by constraint id. */
const labelAt = new Map();

function drawDimensions() {
  dimensionLayer.replaceChildren();
  labelAt.clear();
  if (!state) return;
  // Thinned: a label closer than 24 px to one already drawn is left out (zoom in to see it).
  const taken = new Set();
  for (const c of state.constraints) {
    if (typeof c.value !== "number") continue;
    const list = glyphs.get(c.id);
    if (!list || !list.length) continue;
    // Between the two points a distance marks, else beside the first glyph.
    const anchor = list.length >= 2 && c.kind.endsWith("distance")
      ? [(list[0].at[0] + list[1].at[0]) / 2, (list[0].at[1] + list[1].at[1]) / 2]
      : list[0].at;
    const [x, y] = toScreen(anchor);
    const cell = `${Math.round(x / 24)},${Math.round(y / 24)}`;
    if (taken.has(cell)) continue;
    taken.add(cell);
    const bad = c.status === "conflicting" ? " conflict" : "";
    const sel = selection.some((s) => s.type === "constraint" && s.id === c.id) ? " selected" : "";
    const t = element("text", { class: `dimension${bad}${sel}`, x: x + 8, y: y + 16, "data-dimension": c.id }, dimensionLayer);
    t.textContent = c.expression ? `${valueText(c)} = ${c.expression}` : valueText(c);
    labelAt.set(c.id, [x + 8, y + 16]);
  }
}

/** The dimension whose label is under canvas position `xy`, or null. */
function dimensionAt(xy) {
  for (const el of dimensionLayer.children) {
    const b = el.getBBox();
    if (xy[0] >= b.x - 3 && xy[0] <= b.x + b.width + 3 && xy[1] >= b.y - 3 && xy[1] <= b.y + b.height + 3) {
      return Number(el.dataset.dimension);
    }
  }
  return null;
}

function editDimension(id) {
  const c = state.constraints.find((x) => x.id === id);
  if (!c || typeof c.value !== "number") return;
  const at = labelAt.get(id) ?? [40, 40];
  dimInput.hidden = false;
  dimInput.style.left = `${at[0]}px`;
  dimInput.style.top = `${at[1] - 18}px`;
  dimInput.value = c.expression ?? (ANGLES.includes(c.kind) ? String(Number(((c.value * 180) / Math.PI).toPrecision(10))) : String(c.value));
  dimInput.dataset.constraint = id;
  dimInput.title = ANGLES.includes(c.kind)
    ? "a number in degrees, or an expression of the parameters in radians; Enter sets it, Esc leaves it"
    : "a number, or an expression of the parameters (chord / 2); Enter sets it, Esc leaves it";
  dimInput.focus();
  dimInput.select();
}

async function setDimension(id, text) {
  const c = state.constraints.find((x) => x.id === id);
  let value = text.trim();
  const number = Number(value);
  if (value !== "" && Number.isFinite(number)) value = ANGLES.includes(c.kind) ? (number * Math.PI) / 180 : number;
  const r = await api("POST", "/api/dimension", { constraint: id, value });
  if (r.ok) {
    takeState(r.data, true);
    showMessage(state.report.summary, "info");
  } else showMessage(r.data.error, "error");
  return r.ok;
}

dimInput.addEventListener("keydown", async (ev) => {
  ev.stopPropagation();
  if (ev.key === "Escape") dimInput.hidden = true;
  else if (ev.key === "Enter") {
    const id = Number(dimInput.dataset.constraint);
    if (await setDimension(id, dimInput.value)) dimInput.hidden = true;
  }
});
dimInput.addEventListener("blur", () => {
  dimInput.hidden = true;
});

// ---- the overlay: what is drawn, selected, and flagged ----------------------------------------

function polyline(points, cls) {
  return element("polyline", { class: cls, points: points.map((p) => toScreen(p).map((v) => v.toFixed(2)).join(",")).join(" ") }, overlayLayer);
}

function drawOverlay() {
  overlayLayer.replaceChildren();
  if (!state) return;
  // Over-constrained and conflicting geometry: the entities their constraints read.
  const flagged = new Map();
  for (const c of state.constraints) {
    if (c.status === "conflicting") c.entities.forEach((e) => flagged.set(e, "conflict"));
    else if (c.status === "redundant") c.entities.forEach((e) => flagged.has(e) || flagged.set(e, "redundant"));
  }
  if (flagged.size <= 2000) {
    for (const [id, how] of flagged) {
      const e = entities.get(id);
      if (e && e.kind !== "point") polyline(outlineOf(e), `flag ${how}`);
    }
  }
  // The selection: entities thick, points ringed, a constraint's entities and glyphs.
  for (const s of selection) {
    if (s.type === "entity") {
      const e = entities.get(s.id);
      if (!e) continue;
      if (e.kind === "point") element("circle", { class: "picked", cx: toScreen(e.points[0])[0], cy: toScreen(e.points[0])[1], r: 9 }, overlayLayer);
      else polyline(outlineOf(e), "picked");
    } else if (s.type === "point") {
      const e = entities.get(s.entity);
      if (!e) continue;
      const [cx, cy] = toScreen(e.points[s.index]);
      element("circle", { class: "picked", cx, cy, r: 9 }, overlayLayer);
    } else {
      const c = state.constraints.find((x) => x.id === s.id);
      for (const id of c ? c.entities : []) {
        const e = entities.get(id);
        if (e && e.kind !== "point") polyline(outlineOf(e), "picked constraint");
        else if (e) element("circle", { class: "picked constraint", cx: toScreen(e.points[0])[0], cy: toScreen(e.points[0])[1], r: 9 }, overlayLayer);
      }
      for (const g of glyphs.get(s.id) ?? []) {
        const [cx, cy] = toScreen(g.at);
        element("circle", { class: "picked glyph-pick", cx, cy, r: 12 }, overlayLayer);
      }
    }
  }
  // The shape being drawn, to the cursor, with what would be inferred.
  if (drawing && drawing.cursor) {
    const pts = [...drawing.pts.map((p) => p.at), drawing.cursor.at];
    if (tool === "circle" && pts.length === 2) {
      const [cx, cy] = toScreen(pts[0]);
      element("circle", { class: "rubber", cx, cy, r: dist(pts[0], pts[1]) * view.k }, overlayLayer);
    } else if (tool === "arc" && pts.length >= 2) {
      const [cx, cy] = toScreen(pts[0]);
      element("circle", { class: "rubber faint", cx, cy, r: dist(pts[0], pts[1]) * view.k }, overlayLayer);
      polyline(pts.slice(0, 2), "rubber faint");
      if (pts.length === 3) polyline([pts[0], pts[2]], "rubber faint");
    } else if (pts.length >= 2) {
      polyline(pts, "rubber");
    }
    for (const p of pts) {
      const [cx, cy] = toScreen(p);
      element("circle", { class: "rubber-point", cx, cy, r: 3.5 }, overlayLayer);
    }
  }
  for (const w of shapeWarnings) {
    const [cx, cy] = toScreen(w.at);
    element("circle", { class: "shape-warning", cx, cy, r: 7 }, overlayLayer);
  }
  if (box) {
    const [a, b] = [box.from, box.to];
    element("rect", { class: "box", x: Math.min(a[0], b[0]), y: Math.min(a[1], b[1]), width: Math.abs(a[0] - b[0]), height: Math.abs(a[1] - b[1]) }, overlayLayer);
  }
}

/** What the cursor would infer now, for the hint beside it. */
function inferredHint() {
  const c = drawing.cursor;
  const words = [];
  if (c.label) words.push(c.label);
  const last = drawing.pts[drawing.pts.length - 1];
  if (last && ["line", "polyline"].includes(tool)) {
    lineInferences("#", last, c, drawing.pts.length === 1 ? drawing.pts[0].snap : null).forEach((x) => words.push(x.kind === "arc_tangent_to_line" ? "tangent" : x.kind));
  }
  return words.join(", ");
}

// ---- curvature combs and shape warnings --------------------------------------------------------

async function fetchCombs() {
  if (!combs.on) return;
  if (combs.busy) {
    combs.again = true;
    return;
  }
  combs.busy = true;
  const r = await api("GET", "/api/combs");
  combs.busy = false;
  if (r.ok) combs.list = r.data.combs;
  drawCombs();
  if (combs.again) {
    combs.again = false;
    fetchCombs();
  }
}

function drawCombs() {
  combLayer.replaceChildren();
  if (!combs.on) return;
  for (const c of combs.list) {
    const teeth = c.teeth.map(([p, t]) => [toScreen(p), toScreen(t)]);
    const d = teeth.map(([p, t]) => `M${p[0].toFixed(1)},${p[1].toFixed(1)}L${t[0].toFixed(1)},${t[1].toFixed(1)}`).join("");
    element("path", { class: "comb", d }, combLayer);
    element("polyline", { class: "comb envelope", points: teeth.map(([, t]) => `${t[0].toFixed(1)},${t[1].toFixed(1)}`).join(" ") }, combLayer);
  }
}

function toggleCombs() {
  combs.on = !combs.on;
  document.getElementById("combs").classList.toggle("active", combs.on);
  if (combs.on) fetchCombs();
  else drawCombs();
}

function showShapeWarnings() {
  shapeNote.hidden = shapeWarnings.length === 0;
  shapeNote.textContent = shapeWarnings.length
    ? `⚠ ${shapeWarnings.slice(0, 3).map((w) => w.message).join("; ")}${shapeWarnings.length > 3 ? ` (and ${shapeWarnings.length - 3} more)` : ""}`
    : "";
}

// ---- the panel -------------------------------------------------------------------------------

function renderSelection() {
  const div = document.getElementById("selection");
  div.replaceChildren();
  const p = document.createElement("p");
  p.className = "muted";
  p.textContent = selection.length
    ? selection.map((s) => (s.type === "point" ? `point ${s.index} of ${s.entity}` : s.type === "entity" ? `entity ${s.id} (${entities.get(s.id)?.kind})` : `constraint ${s.id}`)).join(", ")
    : "nothing selected: click a point, a curve or a glyph (Shift adds, Shift+drag boxes)";
  div.appendChild(p);
  const buttons = document.createElement("div");
  buttons.className = "buttons";
  for (const choice of applicable()) {
    const b = document.createElement("button");
    b.type = "button";
    b.textContent = choice.label;
    b.title = `Shift+${choice.key}`;
    b.dataset.constrain = choice.key;
    b.addEventListener("click", () => apply(choice));
    buttons.appendChild(b);
  }
  if (selection.length) {
    const b = document.createElement("button");
    b.type = "button";
    b.textContent = "Delete";
    b.title = "Delete or Backspace";
    b.id = "delete";
    b.addEventListener("click", deleteSelection);
    buttons.appendChild(b);
  }
  div.appendChild(buttons);
}

function renderConstraints() {
  const div = document.getElementById("constraints");
  div.replaceChildren();
  const list = state.constraints;
  const attention = list.filter((c) => c.status !== "ok" || (c.residual ?? 0) > 1e-9);
  const selected = new Set(selection.filter((s) => s.type === "constraint").map((s) => s.id));
  const shown = list.length > LIST_LIMIT ? list.filter((c) => c.status !== "ok" || (c.residual ?? 0) > 1e-9 || selected.has(c.id)) : list;
  const summary = document.createElement("p");
  summary.className = "muted";
  summary.textContent = `${list.length} constraint(s), ${attention.length} needing attention${shown.length < list.length ? `; ${list.length - shown.length} satisfied ones not listed` : ""}`;
  div.appendChild(summary);
  const table = document.createElement("table");
  table.className = "constraints";
  for (const c of shown.slice(0, LIST_LIMIT)) {
    const row = table.insertRow();
    row.dataset.constraint = c.id;
    if (selected.has(c.id)) row.className = "selected";
    const residual = c.residual === null ? "–" : c.residual === 0 ? "0" : c.residual.toExponential(1);
    const bad = c.status !== "ok" || (c.residual ?? 0) > 1e-9;
    row.insertCell().textContent = c.id;
    row.insertCell().textContent = c.name;
    const v = row.insertCell();
    if (typeof c.value === "number") {
      const input = document.createElement("input");
      input.value = c.expression ?? (ANGLES.includes(c.kind) ? String(Number(((c.value * 180) / Math.PI).toPrecision(10))) : String(c.value));
      input.size = 8;
      input.title = ANGLES.includes(c.kind) ? "degrees, or an expression in radians" : "a number or an expression of the parameters";
      input.addEventListener("keydown", (ev) => ev.stopPropagation());
      input.addEventListener("change", () => setDimension(c.id, input.value));
      v.appendChild(input);
    }
    const r = row.insertCell();
    r.textContent = residual;
    const s = row.insertCell();
    s.textContent = c.status === "ok" ? "" : c.status.replace("_", " ");
    if (bad) row.classList.add("bad");
    row.addEventListener("click", (ev) => {
      if (ev.target.tagName !== "INPUT") select({ type: "constraint", id: c.id }, ev.shiftKey);
    });
  }
  div.appendChild(table);
}

function renderParameters() {
  const div = document.getElementById("parameters");
  div.replaceChildren();
  for (const p of state.parameters) {
    const row = document.createElement("p");
    const label = document.createElement("label");
    label.textContent = `${p.name} `;
    const input = document.createElement("input");
    input.value = p.value;
    input.size = 10;
    input.dataset.parameter = p.name;
    input.title = `read by ${p.readers.length ? p.readers.join(", ") : "nothing yet"}`;
    input.addEventListener("keydown", (ev) => ev.stopPropagation());
    input.addEventListener("change", () => setParameter(p.name, input.value));
    label.appendChild(input);
    row.appendChild(label);
    div.appendChild(row);
  }
}

async function setParameter(name, text) {
  const value = Number(text);
  if (!name.trim() || text.trim() === "" || !Number.isFinite(value)) {
    showMessage("a parameter needs a name and a finite number", "error");
    return false;
  }
  const r = await api("POST", "/api/parameter", { name: name.trim(), value });
  if (r.ok) {
    takeState(r.data, true);
    showMessage(state.report.summary, "info");
  } else showMessage(r.data.error, "error");
  return r.ok;
}

document.getElementById("parameter-add").addEventListener("submit", async (ev) => {
  ev.preventDefault();
  const name = document.getElementById("parameter-name");
  const value = document.getElementById("parameter-value");
  if (await setParameter(name.value, value.value)) {
    name.value = "";
    value.value = "";
  }
});
for (const input of document.querySelectorAll("#parameter-add input")) input.addEventListener("keydown", (ev) => ev.stopPropagation());

// ---- save as, export -------------------------------------------------------------------------

async function saveAs() {
  const current = (state?.output ?? "sketch.json").split(/[\\/]/).pop();
  const name = window.prompt("Save as (a file name beside the current file):", current);
  if (!name) return;
  let r = await api("POST", "/api/save-as", { file: name });
  if (r.status === 409 && window.confirm(`${r.data.error}\nReplace it?`)) r = await api("POST", "/api/save-as", { file: name, overwrite: true });
  if (r.ok) {
    takeState(r.data.state, true);
    showMessage(`saved ${r.data.saved} (${r.data.bytes} bytes)`, "info");
  } else showMessage(r.data.error, "error");
}

async function download(format) {
  const response = await fetch(`/api/export.${format}`);
  if (!response.ok) {
    showMessage(`export failed: ${response.status}`, "error");
    return;
  }
  const blob = await response.blob();
  const a = document.createElement("a");
  a.href = URL.createObjectURL(blob);
  a.download = `${(state?.output ?? "sketch.json").split(/[\\/]/).pop().replace(/\.json$/i, "")}.${format}`;
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

document.getElementById("save-as").addEventListener("click", saveAs);
document.getElementById("combs").addEventListener("click", toggleCombs);
document.getElementById("export-svg").addEventListener("click", () => download("svg"));
document.getElementById("export-dxf").addEventListener("click", () => download("dxf"));

// ---- pointer and keys (capture phase: before editor.js's drag and pan) --------------------------

canvas.addEventListener("pointerdown", (ev) => {
  if (ev.button !== 0) return;
  const xy = canvasXY(ev);
  if (tool !== "select") {
    ev.stopImmediatePropagation();
    ev.preventDefault();
    drawClick(ev);
    return;
  }
  // A handle under the pointer is dragged (editor.js), even where a label lies over it.
  const label = nearestHandle(xy) ? null : dimensionAt(xy);
  if (label !== null) {
    ev.stopImmediatePropagation();
    ev.preventDefault();
    select({ type: "constraint", id: label }, ev.shiftKey);
    editDimension(label);
    return;
  }
  press = { xy, shift: ev.shiftKey };
  if (ev.shiftKey && !nearestHandle(xy)) {
    ev.stopImmediatePropagation();
    ev.preventDefault();
    box = { from: xy, to: xy, pointerId: ev.pointerId };
    canvas.setPointerCapture(ev.pointerId);
  }
}, true);

canvas.addEventListener("pointermove", (ev) => {
  const xy = canvasXY(ev);
  if (box) {
    box.to = xy;
    drawOverlay();
  } else if (drawing) {
    const own = tool === "polyline" && drawing.pts.length >= 3 ? [drawing.pts[0].at] : null;
    drawing.cursor = snapAt(xy, own);
    drawOverlay();
    const hint = inferredHint();
    hintBox.hidden = !hint;
    hintBox.textContent = hint;
    hintBox.style.left = `${xy[0] + 14}px`;
    hintBox.style.top = `${xy[1] + 14}px`;
  }
}, true);

window.addEventListener("pointerup", (ev) => {
  if (box) {
    const b = box;
    box = null;
    press = null;
    if (dist(b.from, b.to) > 3) boxSelect(b.from, b.to, true);
    else select(itemAt(canvasXY(ev)), true); // a Shift+click
    return;
  }
  if (!press || tool !== "select") return;
  const xy = canvasXY(ev);
  const moved = dist(xy, press.xy);
  const shift = press.shift;
  press = null;
  if (moved > 3) return;
  // A click: select what is under it (a drag that did not move committed nothing).
  select(itemAt(xy), shift);
}, true);

canvas.addEventListener("dblclick", (ev) => {
  if (tool !== "select" && drawing && drawing.pts.length) {
    ev.preventDefault();
    // The double-click's second click added the last point twice.
    const pts = drawing.pts;
    if (pts.length >= 2 && dist(pts[pts.length - 1].at, pts[pts.length - 2].at) === 0) pts.pop();
    finishDrawing();
    return;
  }
  const id = dimensionAt(canvasXY(ev));
  if (id !== null) editDimension(id);
});

window.addEventListener("keydown", (ev) => {
  if (ev.target instanceof HTMLInputElement) return;
  if (ev.ctrlKey || ev.metaKey || ev.altKey) return;
  if (ev.key === "Escape" && tool !== "select") {
    ev.stopImmediatePropagation();
    if (drawing && drawing.pts.length && ["polyline", "bezier", "bspline"].includes(tool)) finishDrawing();
    else setTool("select");
    return;
  }
  if (ev.key === "Enter" && drawing) {
    ev.stopImmediatePropagation();
    finishDrawing();
    return;
  }
  if ((ev.key === "Delete" || ev.key === "Backspace") && selection.length) {
    ev.stopImmediatePropagation();
    ev.preventDefault();
    deleteSelection();
    return;
  }
  if (ev.shiftKey && ev.key.length === 1) {
    const choice = applicable().find((c) => c.key === ev.key.toUpperCase());
    if (choice) {
      ev.stopImmediatePropagation();
      apply(choice);
    }
    return;
  }
  if (ev.key === "k") {
    ev.stopImmediatePropagation();
    toggleCombs();
    return;
  }
  const name = Object.keys(TOOLS).find((t) => TOOLS[t].key === ev.key);
  if (name) {
    ev.stopImmediatePropagation();
    setTool(name);
  }
}, true);

// ---- the toolbar, and the hooks editor.js calls ----------------------------------------------

for (const [name, t] of Object.entries(TOOLS)) {
  const b = document.createElement("button");
  b.type = "button";
  b.dataset.tool = name;
  b.textContent = t.label;
  b.title = `${t.help} (${t.key.toUpperCase()})`;
  b.addEventListener("click", () => setTool(name));
  document.getElementById("tools").appendChild(b);
}

/**
 * After every redraw (a zoom, a pan, a drag move, a new state): labels, overlay, combs. A drag
 * move's answer (`scene`, with its `update_us`) carries the shape warnings of what it moved.
 */
function sketcherRedraw(scene) {
  if (scene && scene.update_us !== undefined) {
    const moved = new Set(scene.entities.map((e) => e.id));
    shapeWarnings = shapeWarnings.filter((w) => !moved.has(w.entity)).concat(scene.warnings ?? []);
    showShapeWarnings();
    fetchCombs();
  }
  drawDimensions();
  drawOverlay();
  drawCombs();
}

/** After every new state: the selection pruned, the panels. */
function sketcherPanel() {
  if (!state) return;
  pruneSelection();
  shapeWarnings = state.warnings ?? [];
  showShapeWarnings();
  fetchCombs();
  renderSelection();
  renderConstraints();
  renderParameters();
  sketcherRedraw();
}

setTool("select", true);
if (state) sketcherPanel();
