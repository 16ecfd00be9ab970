// camber edit: what the sketcher shows (after sketcher.js and sketcher-tools.js): dimension
// labels and their editor, the overlay (selection, flags, the shape being drawn), curvature
// combs and shape warnings, the Selection, Constraints and Parameters panels, save-as and
// export, and the two hooks editor.js calls after every redraw and every new state.
"use strict";

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

// ---- the hooks editor.js calls ----------------------------------------------------------------

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
