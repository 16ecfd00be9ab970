#!/usr/bin/env python3
"""The editor on a large sketch, in a real browser: the 1,000-segment W3 chain (issue: "loads in
5.6 s as a solid green band with a wall of text; aiming at entity 500 dragged entity 505").

Writes the chain with `camber bench --only W3 --sizes 1000 --write-sketch` (nothing large is
committed), starts `camber edit` on it, opens the page in headless Chromium (Python playwright
driving the system's /usr/bin/chromium; no browser is downloaded) and checks:

1. the page opens in under 1 s: measured in the page, from navigation start (performance.now()
   is 0 there) to the first frame painted after the state was received and drawn (the page's
   `loadTimes.painted`). The page is opened three times, each in a new tab of one browser, and
   the fastest open is asserted (CI runs on a loaded 2-core machine, where one open can take
   twice another); every open's figures (state received, its request, the draw, the paint,
   elements drawn) are printed. The panel lists the component's free points in runs, not per
   entity, and no handle carries its own <title>;
2. zoomed in where the chain's handles overlap (several within the 8 px pick radius), aiming at
   point 1 of entity 500 picks exactly that point (the status line names it, and the drag's
   start request asks for it), and dragging it keeps every constraint (the editor's residuals
   and the G1 joins, chords and fixed ends recomputed here from the points the API returns);
3. zoomed further onto the joint of entities 500 and 501 (two handles on one spot), the pointer
   names "1 of 2", the cycle key C chooses the other one, and the next drag grabs it.

Screenshots of each step go to target/browser/chain_*.png.

Usage: chain_test.py [CAMBER_BINARY]   (default: target/release/camber)
Any failed step raises, prints `browser test FAILED: …` and exits with 1.
"""

import json
import math
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from playwright.sync_api import sync_playwright

sys.path.insert(0, str(Path(__file__).resolve().parent))
from editor_test import CHROMIUM, ROOT, SHOTS, Editor, Failure, check, points  # noqa: E402

SEGMENTS = 1000
# The first full draw must be on screen within this many ms of navigation start.
OPEN_LIMIT_MS = 1000
# The chain is solved before the drags; each drag keeps its constraints to this.
TOLERANCE = 1e-8


def write_chain(binary, path):
    out = subprocess.run(
        [str(binary), "bench", "--only", "W3", "--sizes", str(SEGMENTS), "--write-sketch", str(path)],
        capture_output=True,
        text=True,
        timeout=60,
    )
    check(out.returncode == 0, f"camber bench --write-sketch failed: {out.stderr}")
    return json.loads(path.read_text())


def check_chain(state, sketch, original):
    """Every constraint of the chain holds: the editor's residuals, and the G1 joins, the chord
    lengths and the fixed ends recomputed from the points the API returns."""
    for c in state["components"]:
        check(c["residual"] <= TOLERANCE, f"component residual {c['residual']} (worst {c['worst']})")
    pts = points(state)
    for c in sketch["constraints"]:
        if c["kind"] == "g1_join_free":
            a, b = pts[c["first"]], pts[c["second"]]
            gap = math.dist(a[-1], b[0])
            check(gap <= TOLERANCE, f"g1_join_free {c['id']}: the ends are {gap} apart")
            ta = (a[-1][0] - a[-2][0], a[-1][1] - a[-2][1])
            tb = (b[1][0] - b[0][0], b[1][1] - b[0][1])
            sin = (ta[0] * tb[1] - ta[1] * tb[0]) / (math.hypot(*ta) * math.hypot(*tb))
            check(abs(sin) <= TOLERANCE, f"g1_join_free {c['id']}: tangents off by sin {sin}")
            check(ta[0] * tb[0] + ta[1] * tb[1] > 0, f"g1_join_free {c['id']}: tangents opposed")
        elif c["kind"] == "distance":
            (wa, ea), = c["a"].items()
            (wb, eb), = c["b"].items()
            check((wa, wb) == ("start", "end") and ea == eb, f"distance {c['id']}: not a chord: {c}")
            chord = math.dist(pts[ea][0], pts[ea][-1])
            check(abs(chord - c["distance"]) <= TOLERANCE, f"distance {c['id']}: chord {chord}, wants {c['distance']}")
        elif c["kind"] == "fixed":
            entity, index = c["target"]["point"]["control"]
            now, was = pts[entity][index], original[entity][index]
            check(math.dist(now, was) == 0, f"fixed {c['id']}: point {index} of {entity} moved from {was} to {now}")
        else:
            raise Failure(f"the test does not know constraint kind {c['kind']}")


def open_figures(page):
    """What the page measured of its first load (ms since navigation start) and drew."""
    return page.evaluate(
        """() => { const e = performance.getEntriesByName(location.origin + '/api/state')[0];
          return {...loadTimes, request: e.responseEnd - e.requestStart, bytes: e.decodedBodySize,
                  draw: drawStats.ms, handles: drawStats.handles, handlesDrawn: drawStats.handlesDrawn,
                  constraints: drawStats.constraints, constraintsDrawn: drawStats.constraintsDrawn,
                  elements: document.getElementsByTagName('*').length,
                  titles: document.getElementsByTagName('title').length,
                  panel: document.getElementById('components').textContent}; }"""
    )


def client_xy(page, entity, index):
    """Where point `index` of `entity` is on the page now (client pixels)."""
    return page.evaluate(
        """([e, i]) => { const [x, y] = toScreen(entities.get(e).points[i]);
                         const r = canvas.getBoundingClientRect(); return [x + r.left, y + r.top]; }""",
        [entity, index],
    )


def zoom_at(page, entity, index, pixels_per_unit):
    """Wheel-zooms about the point until the view shows about `pixels_per_unit`."""
    for _ in range(60):
        k = page.evaluate("() => view.k")
        if k >= pixels_per_unit:
            break
        x, y = client_xy(page, entity, index)
        page.mouse.move(x, y)
        page.mouse.wheel(0, -120)
        page.wait_for_function("() => !redrawPending")
    return page.evaluate("() => view.k")


def status(page):
    return page.locator("#status").text_content()


def wait_status(page, prefix):
    try:
        page.wait_for_function(
            "(p) => document.getElementById('status').textContent.startsWith(p)", arg=prefix, timeout=5000
        )
    except Exception as e:
        raise Failure(f"the status line does not start with {prefix!r}: {status(page)!r}") from e


def drag_from(page, editor, x, y, dx, dy):
    """Presses at (x, y), moves by (dx, dy) in ten steps and releases; the state after."""
    page.mouse.move(x, y)
    page.mouse.down()
    for k in range(1, 11):
        page.mouse.move(x + dx * k / 10, y + dy * k / 10)
        page.wait_for_timeout(40)
    page.mouse.up()
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:
        s = editor.state()
        if s["dragging"] is None and s["report"] and s["report"]["action"] == "drag":
            return s
        page.wait_for_timeout(50)
    s = editor.state()
    raise Failure(
        f"the drag did not end within 30 s: status {status(page)!r}, dragging {s['dragging']}, "
        f"report {(s['report'] or {}).get('summary')!r}"
    )


def main():
    binary = Path(sys.argv[1] if len(sys.argv) > 1 else ROOT / "target" / "release" / "camber")
    check(binary.exists(), f"{binary} does not exist (build it first)")
    check(Path(CHROMIUM).exists(), f"{CHROMIUM} does not exist (apt-get install chromium)")
    SHOTS.mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp(prefix="camber-chain-"))
    path = work / "chain.json"
    sketch = write_chain(binary, path)
    file_points = {e["id"]: e["control_points"] for e in sketch["entities"]}
    check(len(file_points) == SEGMENTS, f"the chain has {len(file_points)} segments")
    started = time.monotonic()
    editor = Editor(binary, path)
    errors = []
    starts = []
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=CHROMIUM, headless=True, args=["--no-sandbox"])

            def new_page():
                page = browser.new_page(viewport={"width": 1200, "height": 800})
                page.on("pageerror", lambda e: errors.append(f"page error: {e}"))
                page.on("console", lambda m: errors.append(f"console {m.type}: {m.text}") if m.type == "error" else None)
                page.on(
                    "request",
                    lambda r: starts.append(json.loads(r.post_data)) if r.url.endswith("/api/drag/start") else None,
                )
                return page

            page = new_page()

            # 1. The chain opens in under 1 s, measured in the page from navigation start to the
            # first painted frame of the full drawing: the fastest of three opens.
            opens = []
            for attempt in range(3):
                if attempt:
                    page.close()
                    page = new_page()
                page.goto(editor.url)
                page.wait_for_function("() => loadTimes.painted !== null", timeout=30000)
                t = open_figures(page)
                opens.append(t["painted"])
                print(
                    f"chain of {SEGMENTS}, open {attempt + 1}: state received {t['state']:.0f} ms after navigation "
                    f"start (request {t['request']:.0f} ms, {t['bytes'] / 1e6:.2f} MB), drawn at {t['drawn']:.0f} ms "
                    f"(redraw {t['draw']:.0f} ms), painted at {t['painted']:.0f} ms; {t['elements']} elements, "
                    f"{t['handlesDrawn']} of {t['handles']} handles and {t['constraintsDrawn']} of "
                    f"{t['constraints']} constraints' glyphs drawn"
                )
            page.screenshot(path=str(SHOTS / "chain_open.png"))
            check(min(opens) < OPEN_LIMIT_MS, f"the chain took {min(opens):.0f} ms to open at best (limit {OPEN_LIMIT_MS})")
            check(t["handles"] == 4 * SEGMENTS, f"the page knows {t['handles']} handles")
            check(t["titles"] == 1, f"{t['titles'] - 1} <title> elements besides the page's own")
            check("1–998: points 0, 1, 2, 3" in t["panel"], f"the panel's free points are not in runs: {t['panel'][:300]}")
            check(len(t["panel"]) < 1000, f"the panel has {len(t['panel'])} characters")


            # The chain is not solved as generated (its last point was moved): Solve (S) first.
            page.keyboard.press("s")
            deadline = time.monotonic() + 60
            while not editor.state()["report"] and time.monotonic() < deadline:
                page.wait_for_timeout(100)
            solved = editor.state()
            check_chain(solved, sketch, file_points)

            # 2. Zoom in on entity 500 until its neighbours' handles lie within the pick radius,
            # and aim at its point 1: exactly that point is picked and dragged.
            k = zoom_at(page, 500, 1, 3.0)
            x, y = client_xy(page, 500, 1)
            page.mouse.move(x, y)
            near = page.evaluate("([x, y]) => handlesNear(x, y).length", [x, y])
            topmost = page.evaluate(
                "([x, y]) => { const el = document.elementFromPoint(x, y); return el && el.dataset.entity !== undefined ? [Number(el.dataset.entity), Number(el.dataset.index)] : null; }",
                [x, y],
            )
            print(f"zoomed to {k:.2f} px per unit: {near} handles within the pick radius of point 1 of entity 500; the topmost element there is {topmost}")
            check(near >= 3, f"only {near} handles near point 1 of entity 500 at {k} px per unit: not an overlap")
            check(page.evaluate("([x, y]) => pickHandle(x, y)", [x, y]) == {"entity": 500, "index": 1}, "pickHandle")
            wait_status(page, f"entity 500 point 1 (1 of {near} here)")
            page.screenshot(path=str(SHOTS / "chain_aim.png"))
            before = points(solved)
            target = page.evaluate("([x, y]) => toModel(x, y - 24)", [x, y])
            after = drag_from(page, editor, x, y, 0, -24)
            check(starts[-1] == {"entity": 500, "index": 1}, f"the drag grabbed {starts[-1]}, not point 1 of entity 500")
            moved = points(after)[500][1]
            check(math.dist(moved, before[500][1]) > 1e-3, f"point 1 of entity 500 did not move: {moved}")
            print(f"dragged point 1 of entity 500 from {before[500][1]} to {moved} (aimed at {target})")
            check_chain(after, sketch, file_points)
            page.screenshot(path=str(SHOTS / "chain_after_drag.png"))

            # 3. Zoom onto the joint of entities 500 and 501: two handles on one spot. The
            # pointer names the first; C chooses the other, and the next drag grabs it.
            k = zoom_at(page, 500, 3, 40.0)
            x, y = client_xy(page, 500, 3)
            page.mouse.move(x + 1, y + 1)
            wait_status(page, "entity 500 point 3 (1 of 2 here)")
            page.keyboard.press("c")
            wait_status(page, "entity 501 point 0 (2 of 2 here)")
            check(page.evaluate("([x, y]) => pickHandle(x, y)", [x + 1, y + 1]) == {"entity": 501, "index": 0}, "pickHandle after C")
            page.screenshot(path=str(SHOTS / "chain_cycled.png"))
            before = points(after)
            after = drag_from(page, editor, x + 1, y + 1, 12, -8)
            check(starts[-1] == {"entity": 501, "index": 0}, f"after C the drag grabbed {starts[-1]}, not point 0 of entity 501")
            joint = points(after)[501][0]
            check(math.dist(joint, before[501][0]) > 1e-3, f"the joint did not move: {joint}")
            print(f"at {k:.1f} px per unit, C chose point 0 of entity 501; dragged the joint from {before[501][0]} to {joint}")
            check_chain(after, sketch, file_points)
            page.screenshot(path=str(SHOTS / "chain_joint_dragged.png"))
            browser.close()
        check(not errors, f"the page reported errors: {errors}")
    finally:
        editor.stop()
        shutil.rmtree(work, ignore_errors=True)
    print(f"chain browser test passed in {time.monotonic() - started:.1f} s; screenshots in {SHOTS}")


if __name__ == "__main__":
    try:
        main()
    except Exception as e:  # every failure, including playwright's timeouts, fails loudly
        print(f"browser test FAILED: {type(e).__name__}: {e}", file=sys.stderr)
        sys.exit(1)
