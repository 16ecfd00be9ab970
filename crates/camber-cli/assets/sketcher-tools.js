// camber edit: the sketcher's tools (after sketcher.js): drawing shapes click by click, the
// constraints that fit a selection, deleting, and the pointer and keys, which listen in the
// capture phase so that they run before editor.js's drag and pan.
"use strict";

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

// ---- the toolbar ------------------------------------------------------------------------------

for (const [name, t] of Object.entries(TOOLS)) {
  const b = document.createElement("button");
  b.type = "button";
  b.dataset.tool = name;
  b.textContent = t.label;
  b.title = `${t.help} (${t.key.toUpperCase()})`;
  b.addEventListener("click", () => setTool(name));
  document.getElementById("tools").appendChild(b);
}
