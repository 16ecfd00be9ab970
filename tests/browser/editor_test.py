#!/usr/bin/env python3
"""The editor in a real browser, end to end (issue 11).

Starts `camber edit` on a copy of the bundled blade section, opens the page in headless
Chromium (Python playwright driving the system's /usr/bin/chromium; no browser is downloaded),
checks that the side panel's residual follows a drag before the mouse is released,
drags a control point with real mouse events, and checks through the editor's HTTP API that
every constraint still holds (the editor's own residuals, and the G1 joins and fixed points
recomputed here from the points), after solving the blade with the Solve button (it is not
solved as shipped). Then it undoes with the Undo button, redoes with Ctrl+Shift+Z and undoes
again with Ctrl+Z, drags again, saves
with Ctrl+S, reloads the page, restarts the editor on the saved file, and checks that a
request from a foreign Origin is refused and changes nothing. Last, on the parametric
diffuser, it checks that expression constraints are drawn with their name and residual, and
that the residual follows a solve; on the rounded plate, that an arc end drags with its
tangencies kept; on the blade with arcs, that the elliptic leading edge is drawn and its vertex
drags with both joints closed and tangent. Screenshots go to target/browser/.

Usage: editor_test.py [CAMBER_BINARY]   (default: target/release/camber)
Any failed step raises, prints `browser test FAILED: …` and exits with 1.
"""

import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request
from pathlib import Path

from playwright.sync_api import sync_playwright

ROOT = Path(__file__).resolve().parents[2]
BLADE = ROOT / "examples" / "sketches" / "blade_section.json"
PARAMETRIC = ROOT / "examples" / "sketches" / "diffuser_parametric.json"
PLATE = ROOT / "examples" / "sketches" / "rounded_plate.json"
BLADE_ARCS = ROOT / "examples" / "sketches" / "blade_arcs.json"
CHROMIUM = os.environ.get("CHROMIUM", "/usr/bin/chromium")
SHOTS = ROOT / "target" / "browser"

# The editor's tolerance is 1e-10 on residual rows; the joins recomputed here from rounded
# decimal points get a little more.
RESIDUAL_TOLERANCE = 1e-9


class Failure(Exception):
    """A step of the test that did not do what it should."""


def check(condition, message):
    if not condition:
        raise Failure(message)


class Editor:
    """A running `camber edit` process and its URL."""

    def __init__(self, binary, sketch, *options, solve=False):
        # --no-solve unless asked: these steps start from the files' own geometry (the blade's
        # trailing-edge join is open as shipped, and the first drag must close it).
        self.process = subprocess.Popen(
            [str(binary), "edit", str(sketch), "--port", "0", *options, *([] if solve else ["--no-solve"])],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        line = self.process.stdout.readline()
        check(" at http://" in line, f"camber edit did not print its address: {line!r}")
        self.url = line.split(" at ", 1)[1].split(" ", 1)[0]
        self.host = self.url.removeprefix("http://").rstrip("/")

    def request(self, method, path, body=None, headers=None):
        """(status, JSON answer) of one request; no Origin header unless given."""
        data = None if body is None else json.dumps(body).encode()
        req = urllib.request.Request(self.url.rstrip("/") + path, data=data, method=method)
        if method == "POST":
            req.add_header("Content-Type", "application/json")
            if data is None:
                req.data = b"{}"
        for k, v in (headers or {}).items():
            req.add_header(k, v)
        try:
            with urllib.request.urlopen(req, timeout=30) as r:
                return r.status, json.loads(r.read())
        except urllib.error.HTTPError as e:
            return e.code, json.loads(e.read())

    def state(self):
        status, s = self.request("GET", "/api/state")
        check(status == 200, f"GET /api/state answered {status}: {s}")
        return s

    def stop(self):
        self.process.terminate()
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()


def points(state):
    return {e["id"]: e["points"] for e in state["scene"]["entities"]}


def check_constraints(state, sketch_file, original):
    """Every constraint of the blade holds: the editor's residual per component, and each
    constraint recomputed here from the points the API returns."""
    for c in state["components"]:
        check(
            c["residual"] <= RESIDUAL_TOLERANCE,
            f"component {c['entities']} has residual {c['residual']} (worst {c['worst']})",
        )
    pts = points(state)
    for c in json.loads(sketch_file.read_text())["constraints"]:
        if c["kind"] == "g1_join":
            first, second = pts[c["first"]], pts[c["second"]]
            end, start = first[-1], second[0]
            gap = math.dist(end, start)
            check(gap <= RESIDUAL_TOLERANCE, f"g1_join {c['id']}: the ends are {gap} apart")
            d = c["direction"]
            dn = math.hypot(*d)
            for name, (a, b) in (("first", (first[-2], first[-1])), ("second", (second[0], second[1]))):
                t = (b[0] - a[0], b[1] - a[1])
                tn = math.hypot(*t)
                cross = (t[0] * d[1] - t[1] * d[0]) / (tn * dn)
                dot = (t[0] * d[0] + t[1] * d[1]) / (tn * dn)
                check(abs(cross) <= RESIDUAL_TOLERANCE, f"g1_join {c['id']}: {name} tangent off by {cross}")
                check(dot > 0, f"g1_join {c['id']}: {name} tangent points against the joint")
        elif c["kind"] == "fixed":
            target = c["target"]["point"]
            (where, entity), = target.items()
            index = 0 if where == "start" else -1
            now, was = pts[entity][index], original[entity][index]
            check(now == was, f"fixed {c['id']}: the {where} of {entity} moved from {was} to {now}")
        else:
            raise Failure(f"the test does not know constraint kind {c['kind']}")


def panel_residuals(page):
    """The text of every component's residual line in the side panel."""
    return page.evaluate(
        """() => [...document.querySelectorAll('#components p')]
            .filter((p) => p.querySelector('.label')?.textContent.startsWith('residual'))
            .map((p) => p.lastChild.textContent)"""
    )


def handle(page, entity, index):
    return page.locator(f'#layer-points circle[data-entity="{entity}"][data-index="{index}"]')


def drag(page, editor, entity, index, dx, dy):
    """Drags a handle by (dx, dy) pixels with real mouse events; returns the state after."""
    # The page redraws its handles when a state arrives (the element is replaced), so the box
    # is read again until a drawn handle answers.
    box = None
    deadline = time.monotonic() + 5
    while box is None and time.monotonic() < deadline:
        box = handle(page, entity, index).bounding_box()
        if box is None:
            page.wait_for_timeout(50)
    check(box is not None, f"no handle for point {index} of entity {entity}")
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    for k in range(1, 11):
        page.mouse.move(x + dx * k / 10, y + dy * k / 10)
        page.wait_for_timeout(30)
    page.mouse.up()
    # The page ends the drag after its last move is answered.
    deadline = time.monotonic() + 20
    while time.monotonic() < deadline:
        s = editor.state()
        if s["dragging"] is None and s["report"] and s["report"]["action"] == "drag":
            return s
        page.wait_for_timeout(50)
    raise Failure("the drag did not end within 20 s")


def labels(page):
    """{constraint id: text} of the expression labels the page draws."""
    return page.evaluate(
        """() => Object.fromEntries([...document.querySelectorAll('#layer-glyphs text.glyph-label')]
            .map((t) => [t.dataset.constraint, t.textContent]))"""
    )


def check_expression_labels(editor):
    """The page writes each expression constraint's name and residual beside its mark, and the
    residual follows a solve."""
    errors = []
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, headless=True, args=["--no-sandbox"])
        page = browser.new_page(viewport={"width": 1200, "height": 800})
        page.on("pageerror", lambda e: errors.append(f"page error: {e}"))
        page.goto(editor.url)
        page.wait_for_selector("#layer-glyphs text.glyph-label")
        shown = labels(page)
        expected = {"2": "leading circle", "4": "middle circle", "6": "trailing circle"}
        check(set(shown) == set(expected), f"expression labels drawn: {shown}")
        for cid, name in expected.items():
            check(shown[cid].startswith(f"{name}: |g| "), f"label of constraint {cid}: {shown[cid]!r}")
        check(shown["4"] == "middle circle: |g| 1.0e-2", f"the unsolved middle circle: {shown['4']!r}")
        page.screenshot(path=str(SHOTS / "editor_expressions.png"))
        page.click("#solve")
        deadline = time.monotonic() + 20
        while labels(page).get("4") == shown["4"] and time.monotonic() < deadline:
            page.wait_for_timeout(50)
        solved = labels(page)["4"]
        residual = solved.split("|g| ", 1)[1]
        check(residual == "0" or float(residual) <= RESIDUAL_TOLERANCE, f"the solved middle circle: {solved!r}")
        browser.close()
    check(not errors, f"the page reported errors: {errors}")


def point_of(pts, ref):
    """The point a file's point reference names, from the editor's points per entity: a line's
    start and end are its points 0 and 1, an arc's its points 1 and 2 (0 is the centre)."""
    (where, target), = ref.items()
    if where == "control":
        return pts[target[0]][target[1]]
    if where == "point":
        return pts[target][0]
    arc = len(pts[target]) == 3
    return pts[target][(1 if where == "start" else 2) if arc else (0 if where == "start" else -1)]


def check_arc_constraints(state, sketch_file, original):
    """Every constraint of the rounded plate holds, recomputed from the editor's points: the
    joins, each fillet arc's radius, its tangency to its line at its end with the sense drawn,
    the horizontals and verticals, the fixed corner."""
    for c in state["components"]:
        check(c["residual"] <= RESIDUAL_TOLERANCE, f"component {c['entities']}: residual {c['residual']}")
    pts = points(state)
    for c in json.loads(sketch_file.read_text())["constraints"]:
        kind = c["kind"]
        if kind == "coincident":
            gap = math.dist(point_of(pts, c["a"]), point_of(pts, c["b"]))
            check(gap <= RESIDUAL_TOLERANCE, f"coincident {c['id']}: {gap} apart")
        elif kind == "radius":
            centre, start, end = pts[c["circle"]]
            for p in (start, end):
                check(abs(math.dist(centre, p) - c["radius"]) <= RESIDUAL_TOLERANCE, f"radius {c['id']}: {math.dist(centre, p)}")
        elif kind == "arc_tangent_to_line":
            centre, start, end = pts[c["arc"]]
            p = start if c["end"] == "start" else end
            a, b = pts[c["line"]]
            d = (b[0] - a[0], b[1] - a[1])
            r = (p[0] - centre[0], p[1] - centre[1])
            along = (r[0] * d[0] + r[1] * d[1]) / math.hypot(*d)
            check(abs(along) <= RESIDUAL_TOLERANCE, f"arc_tangent_to_line {c['id']}: the radius is {along} off the normal")
            travel = -r[1] * d[0] + r[0] * d[1]
            check((travel > 0) == (c["sense"] == "agree"), f"arc_tangent_to_line {c['id']}: the arc turned against its sense")
        elif kind in ("horizontal", "vertical"):
            a, b = pts[c["of"]["line"]]
            k = 1 if kind == "horizontal" else 0
            check(abs(a[k] - b[k]) <= RESIDUAL_TOLERANCE, f"{kind} {c['id']}: {a} to {b}")
        elif kind == "fixed":
            ref = c["target"]["point"]
            check(point_of(pts, ref) == point_of(original, ref), f"fixed {c['id']} moved")
        else:
            raise Failure(f"the test does not know constraint kind {kind}")


def check_arc_drag(binary, work):
    """The editor draws the rounded plate's fillet arcs, and dragging the end of a corner arc
    with the mouse stretches the plate with every join, radius and tangency kept."""
    plate = work / "rounded_plate.json"
    shutil.copy(PLATE, plate)
    editor = Editor(binary, plate)
    errors = []
    try:
        original = points(editor.state())
        arcs = [e["id"] for e in json.loads(plate.read_text())["entities"] if e["kind"] == "arc"]
        check(len(arcs) == 4, f"the plate has 4 arcs: {arcs}")
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=CHROMIUM, headless=True, args=["--no-sandbox"])
            page = browser.new_page(viewport={"width": 1200, "height": 800})
            page.on("pageerror", lambda e: errors.append(f"page error: {e}"))
            page.goto(editor.url)
            page.wait_for_selector("#layer-points circle[data-entity]")
            for arc in arcs:
                check(handle(page, arc, 2).count() == 1, f"no handle for the end of arc {arc}")
            # The top-right arc: its end joins the top line; the bottom-left corner is fixed.
            corner = arcs[1]
            after = drag(page, editor, corner, 2, 40, -30)
            moved = points(after)
            check(moved[corner][2] != original[corner][2], f"the arc end did not move: {moved[corner][2]}")
            check_arc_constraints(after, plate, original)
            width = moved[1][0][0] - moved[3][0][0]
            check(abs(width - 2.0) > 1e-3, f"the drag did not stretch the plate: width {width}")
            page.screenshot(path=str(SHOTS / "editor_arcs.png"))
            browser.close()
    finally:
        editor.stop()
    check(not errors, f"the page reported errors: {errors}")


def ellipse_travel(centre, vertex, b, p):
    """The counter-clockwise tangent of the ellipse of centre, a-axis vertex and semi-axis b
    at its point p: −(a/b)·y′·u + (b/a)·x′·v in its frame u, v."""
    ux, uy = vertex[0] - centre[0], vertex[1] - centre[1]
    a = math.hypot(ux, uy)
    ux, uy = ux / a, uy / a
    dx, dy = p[0] - centre[0], p[1] - centre[1]
    x, y = dx * ux + dy * uy, -dx * uy + dy * ux
    tx, ty = -(a / b) * y, (b / a) * x
    return (tx * ux - ty * uy, tx * uy + ty * ux)


def check_elliptic_joints(state):
    """The blade with arcs after a drag: the elliptic leading edge (entity 1; points centre,
    vertex, start, end) still ends on both sides (Béziers 0 and 2) with its travel along their
    end tangents, against them (the file's `oppose`), both ends on one ellipse."""
    for c in state["components"]:
        check(c["residual"] <= RESIDUAL_TOLERANCE, f"component {c['entities']}: residual {c['residual']}")
    pts = points(state)
    centre, vertex, start, end = pts[1]
    a = math.dist(centre, vertex)
    ux, uy = (vertex[0] - centre[0]) / a, (vertex[1] - centre[1]) / a

    def frame(p):
        dx, dy = p[0] - centre[0], p[1] - centre[1]
        return dx * ux + dy * uy, -dx * uy + dy * ux

    xs, ys = frame(start)
    b = abs(ys) / math.sqrt(1.0 - (xs / a) ** 2)
    xe, ye = frame(end)
    on = (xe / a) ** 2 + (ye / b) ** 2 - 1.0
    check(abs(on) <= 1e-8, f"the elliptic arc's ends are on different ellipses ({on})")
    side0, side2 = pts[0], pts[2]
    for name, p, q, t_side in (
        ("end", end, side0[-1], (side0[-1][0] - side0[-2][0], side0[-1][1] - side0[-2][1])),
        ("start", start, side2[0], (side2[1][0] - side2[0][0], side2[1][1] - side2[0][1])),
    ):
        check(math.dist(p, q) <= RESIDUAL_TOLERANCE, f"the leading edge's {name} left its side: {math.dist(p, q)}")
        t = ellipse_travel(centre, vertex, b, p)
        n = math.hypot(*t) * math.hypot(*t_side)
        sin = (t[0] * t_side[1] - t[1] * t_side[0]) / n
        check(abs(sin) <= 1e-8, f"the leading edge's {name} is not tangent to its side (sin {sin})")
        check(t[0] * t_side[0] + t[1] * t_side[1] < 0, f"the leading edge's {name} turned against its sense")


def check_ellipse_drag(binary, work):
    """The editor draws the blade's elliptic leading edge and circular trailing edge along
    themselves, and dragging the leading edge's a-axis vertex with the mouse keeps it joined
    and tangent to both sides."""
    blade = work / "blade_arcs.json"
    shutil.copy(BLADE_ARCS, blade)
    editor = Editor(binary, blade)
    errors = []
    try:
        status, answer = editor.request("POST", "/api/solve")
        check(status == 200, f"solving the blade with arcs answered {status}: {answer}")
        before = points(editor.state())
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=CHROMIUM, headless=True, args=["--no-sandbox"])
            page = browser.new_page(viewport={"width": 1200, "height": 800})
            page.on("pageerror", lambda e: errors.append(f"page error: {e}"))
            page.goto(editor.url)
            page.wait_for_selector("#layer-points circle[data-entity]")
            # Two sides, the elliptic and the circular edge: four outlines.
            drawn = page.locator("#layer-curves polyline").count()
            check(drawn == 4, f"the page draws {drawn} outlines for 2 sides and 2 arcs")
            after = drag(page, editor, 1, 1, -8, 5)
            check(points(after)[1][1] != before[1][1], "the leading edge's vertex did not move")
            check_elliptic_joints(after)
            page.screenshot(path=str(SHOTS / "editor_ellipse.png"))
            browser.close()
    finally:
        editor.stop()
    check(not errors, f"the page reported errors: {errors}")


def main():
    binary = Path(sys.argv[1] if len(sys.argv) > 1 else ROOT / "target" / "release" / "camber")
    check(binary.exists(), f"{binary} does not exist (build it first)")
    check(Path(CHROMIUM).exists(), f"{CHROMIUM} does not exist (apt-get install chromium)")
    SHOTS.mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp(prefix="camber-browser-"))
    sketch = work / "blade_section.json"
    shutil.copy(BLADE, sketch)
    started = time.monotonic()
    editor = Editor(binary, sketch)
    errors = []
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=CHROMIUM, headless=True, args=["--no-sandbox"])
            page = browser.new_page(viewport={"width": 1200, "height": 800})
            page.on("pageerror", lambda e: errors.append(f"page error: {e}"))
            page.on("console", lambda m: errors.append(f"console {m.type}: {m.text}") if m.type == "error" else None)

            # 1. The page loads and draws every control point.
            page.goto(editor.url)
            page.wait_for_selector("#layer-points circle[data-entity]")
            loaded = points(editor.state())
            drawn = page.locator("#layer-points circle[data-entity]").count()
            expected = sum(len(v) for v in loaded.values())
            check(drawn == expected, f"the page draws {drawn} handles, the sketch has {expected} points")

            # 1b. The points the DOF analysis leaves no freedom are drawn as determined.
            determined = 0
            for comp in editor.state()["components"]:
                analysis = comp["analysis"]
                free = {f["entity"]: set(f["points"]) for f in analysis["free"]}
                for e in comp["entities"]:
                    determined += sum(1 for k in range(len(loaded[e])) if k not in free.get(e, set()))
            shown = page.locator("#layer-points circle.determined").count()
            check(determined > 0, "the blade has fixed points, so some handles are determined")
            check(shown == determined, f"{shown} handles drawn as determined, the analysis says {determined}")

            # 1c. During a drag the panel shows the residual of the geometry being drawn, not the
            # number from before the drag: the blade is not solved as shipped (its trailing-edge
            # join is open), and the first move closes it. Escape then cancels the drag.
            stale = panel_residuals(page)
            check(len(stale) == 1 and "e-" in stale[0], f"the panel's residual before the drag: {stale}")
            check(float(stale[0].split()[0]) > 1e-6, f"the blade should start unsolved: {stale}")
            box = handle(page, 0, 2).bounding_box()
            check(box is not None, "no handle for point 2 of entity 0")
            x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
            page.mouse.move(x, y)
            page.mouse.down()
            live = stale
            deadline = time.monotonic() + 10
            k = 0
            # The panel first says "updated at the first move" (the drag has started, its first
            # answer is on the way), then the live figure.
            while not (live and live[0].endswith("(now)")) and time.monotonic() < deadline:
                k += 1
                page.mouse.move(x + 2 * k, y - k)
                page.wait_for_timeout(50)
                live = panel_residuals(page)
            check(editor.state()["dragging"] is not None, "the drag ended before the mouse was released")
            check(live != stale and live[0].endswith("(now)"), f"the panel kept {stale} during the drag: {live}")
            check(float(live[0].split()[0]) <= RESIDUAL_TOLERANCE, f"the residual during the drag: {live}")
            page.keyboard.press("Escape")
            page.mouse.up()
            deadline = time.monotonic() + 10
            while editor.state()["dragging"] is not None and time.monotonic() < deadline:
                page.wait_for_timeout(50)
            cancelled = editor.state()
            check(cancelled["dragging"] is None and not cancelled["report"], f"Escape did not cancel: {cancelled['report']}")
            check(points(cancelled) == loaded, "a cancelled drag changed the sketch")

            # 2. The bundled blade is not solved as shipped: Solve (the button) solves it, and
            # the fixed points stay where the file has them.
            page.click("#solve")
            deadline = time.monotonic() + 20
            while not editor.state()["report"] and time.monotonic() < deadline:
                page.wait_for_timeout(50)
            solved = editor.state()
            check(solved["report"] and solved["report"]["action"] == "solve", f"Solve did not report: {solved['report']}")
            check_constraints(solved, sketch, loaded)
            original = points(solved)

            # 3. Drag control point 2 of the suction side with the mouse; the constraints hold.
            after = drag(page, editor, 0, 2, 60, -45)
            moved = points(after)
            check(moved[0][2] != original[0][2], f"the dragged point did not move: {moved[0][2]}")
            check(after["unsaved"] and after["can_undo"], f"after the drag: unsaved {after['unsaved']}, can_undo {after['can_undo']}")
            check_constraints(after, sketch, original)
            page.screenshot(path=str(SHOTS / "editor_after_drag.png"))

            # 4. Undo (the button): every point is back, exactly.
            page.click("#undo")
            page.wait_for_function("() => !document.getElementById('message').hidden")
            undone = editor.state()
            check(points(undone) == original, "undo did not restore the original points")
            check(undone["can_undo"], "undo of the drag also undid the solve")
            check(undone["can_redo"], "after an undo there is nothing to redo")

            # 4b. Redo (Ctrl+Shift+Z) brings the drag back exactly; Ctrl+Z takes it back again.
            page.keyboard.press("Control+Shift+Z")
            deadline = time.monotonic() + 10
            while editor.state()["can_redo"] and time.monotonic() < deadline:
                page.wait_for_timeout(50)
            redone = editor.state()
            check(points(redone) == moved, "redo did not restore the dragged points")
            check(redone["unsaved"] and not redone["can_redo"], f"after redo: {redone['unsaved']}, {redone['can_redo']}")
            check(not page.is_disabled("#undo") and page.is_disabled("#redo"), "the buttons do not follow redo")
            page.keyboard.press("Control+z")
            deadline = time.monotonic() + 10
            while not editor.state()["can_redo"] and time.monotonic() < deadline:
                page.wait_for_timeout(50)
            check(points(editor.state()) == original, "undo after redo did not restore the original points")

            # 5. Drag again and save with Ctrl+S; the file on disk holds the dragged geometry.
            after = drag(page, editor, 2, 3, -50, 40)
            check_constraints(after, sketch, original)
            page.keyboard.press("Control+s")
            deadline = time.monotonic() + 10
            while editor.state()["unsaved"] and time.monotonic() < deadline:
                page.wait_for_timeout(50)
            saved_state = editor.state()
            check(not saved_state["unsaved"], "Ctrl+S did not save")
            saved = json.loads(sketch.read_text())
            on_disk = {e["id"]: e["control_points"] for e in saved["entities"]}
            check(on_disk == points(saved_state), "the saved file differs from the editor's sketch")
            check(on_disk != original, "the saved file still holds the original geometry")

            # 6. Reload the page: it draws the saved geometry.
            page.reload()
            page.wait_for_selector("#layer-points circle[data-entity]")
            page.wait_for_function("() => document.getElementById('status').textContent.startsWith('ready')")
            shown = page.evaluate("() => state.scene.entities.map((e) => [e.id, e.points])")
            check({k: v for k, v in shown} == on_disk, "the reloaded page shows other points than the file")

            # 7. A request from another site is refused and changes nothing.
            before = editor.state()
            for path, body in (("/api/drag/start", {"entity": 0, "index": 2}), ("/api/solve", None), ("/api/save", None)):
                status, answer = editor.request("POST", path, body, {"Origin": "https://attacker.example"})
                check(status == 403, f"POST {path} from a foreign Origin answered {status}: {answer}")
            # The same request from the page's own origin goes through (the sketch is solved, so
            # nothing moves).
            status, answer = editor.request("POST", "/api/solve", None, {"Origin": f"http://{editor.host}"})
            check(status == 200, f"POST /api/solve from the page's own Origin answered {status}: {answer}")
            check(points(editor.state()) == points(before), "a refused request changed the sketch")

            page.screenshot(path=str(SHOTS / "editor.png"))
            browser.close()
        check(not errors, f"the page reported errors: {errors}")

        # 8. The saved file opens again in a new editor with the same geometry.
        editor.stop()
        editor = Editor(binary, sketch)
        check(points(editor.state()) == on_disk, "the restarted editor shows other geometry than the saved file")
        check_constraints(editor.state(), sketch, original)

        # 9. Expression constraints are drawn with their name and their residual now: the
        # parametric diffuser with its middle circle's radius parameter off by 0.01, then solved.
        editor.stop()
        diffuser = work / "diffuser_parametric.json"
        diffuser.write_text(PARAMETRIC.read_text().replace('"r3":0.07', '"r3":0.08'))
        editor = Editor(binary, diffuser)
        check_expression_labels(editor)

        # 10. Arcs: the rounded plate's fillets are drawn and an arc end drags with every
        # tangency kept.
        editor.stop()
        check_arc_drag(binary, work)

        # 11. Ellipses: the blade's elliptic leading edge is drawn along itself and its vertex
        # drags with both joints kept.
        check_ellipse_drag(binary, work)
    finally:
        editor.stop()
        shutil.rmtree(work, ignore_errors=True)
    print(f"browser test passed in {time.monotonic() - started:.1f} s; screenshots in {SHOTS}")


if __name__ == "__main__":
    try:
        main()
    except Exception as e:  # every failure, including playwright's timeouts, fails loudly
        print(f"browser test FAILED: {type(e).__name__}: {e}", file=sys.stderr)
        sys.exit(1)
