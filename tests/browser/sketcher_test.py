#!/usr/bin/env python3
"""The editor as a sketcher, end to end in a real browser.

Starts `camber edit --new` on an empty file, and with real mouse and key events in headless
Chromium (Python playwright driving the system's /usr/bin/chromium; no browser is downloaded):
draws a rectangle with the polyline tool (the corners snap to the grid, the sides are inferred
horizontal and vertical, the last click closes it on the first corner), rounds its four corners
with fillets, fixes a corner, dimensions two sides until the analysis reports no freedom left
(DOF 0 in the panel), types a new width into the dimension's label on the picture, deletes a
constraint from the list and adds it back from a selection, undoes and redoes, saves with
Ctrl+S, reloads the page and restarts the editor on the saved file, and finds the same sketch.
Every step is checked through the editor's HTTP API (the constraints hold: every residual is
below tolerance; the geometry is what was typed). Last, the bundled blade section, which does
not hold as shipped, opens solved with the report shown. Screenshots of each step go to
target/browser/sketcher_*.png.

Usage: sketcher_test.py [CAMBER_BINARY]   (default: target/release/camber)
With CAMBER_ASSETS_FROM_SOURCE=1 the page's files are served from crates/camber-cli/assets
instead of the ones built into the binary (to try a change of the page without a rebuild).
Any failed step raises, prints `sketcher test FAILED: …` and exits with 1.
"""

import math
import re
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

from playwright.sync_api import sync_playwright

sys.path.insert(0, str(Path(__file__).resolve().parent))
from editor_test import CHROMIUM, ROOT, SHOTS, Editor, Failure, check  # noqa: E402

BLADE = ROOT / "examples" / "sketches" / "blade_section.json"
TOLERANCE = 1e-9


def from_source(path):
    """A route handler answering with the file at `path`."""
    return lambda route, *_: route.fulfill(path=str(path))


def shot(page, name):
    page.screenshot(path=str(SHOTS / f"sketcher_{name}.png"))


def at(page, x, y):
    """The page position of model point (x, y)."""
    return page.evaluate(
        """([x, y]) => { const r = canvas.getBoundingClientRect(); const s = toScreen([x, y]);
                         return [r.left + s[0], r.top + s[1]]; }""",
        [x, y],
    )


def click(page, x, y, shift=False):
    px, py = at(page, x, y)
    if shift:
        page.keyboard.down("Shift")
    page.mouse.click(px, py)
    if shift:
        page.keyboard.up("Shift")


def settle(page):
    """Waits until no request of the page is on its way (the page's state is the server's)."""
    page.wait_for_load_state("networkidle")
    page.wait_for_timeout(50)


def kinds(state):
    out = {}
    for c in state["constraints"]:
        out[c["kind"]] = out.get(c["kind"], 0) + 1
    return out


def dof(state):
    return sum(c["analysis"]["dof"] for c in state["components"])


def check_holds(state, step):
    for c in state["constraints"]:
        r = c["residual"]
        check(r is None or r < TOLERANCE, f"{step}: constraint {c['id']} ({c['name']}) has residual {r}")
        check(c["status"] == "ok", f"{step}: constraint {c['id']} is {c['status']}")


def lines(state):
    return {e["id"]: e["points"] for e in state["scene"]["entities"] if e["kind"] == "line"}


def length(p):
    return math.dist(p[0], p[1])


def side(state, horizontal, lowest):
    """The id of the bottom/top (horizontal) or left/right (vertical) side."""
    axis = 1 if horizontal else 0
    level = [(i, p) for i, p in lines(state).items() if abs(p[0][axis] - p[1][axis]) < 1e-9]
    level.sort(key=lambda ip: ip[1][0][axis])
    return (level[0] if lowest else level[-1])[0]


def mid(state, line):
    p = lines(state)[line]
    return ((p[0][0] + p[1][0]) / 2, (p[0][1] + p[1][1]) / 2)


def constrain(page, label):
    if page.locator("#selection button", has_text=label).count() == 0:
        shot(page, "failed")
        raise Failure(f"no {label!r} for the selection: {page.locator('#selection').inner_text()!r}")
    page.locator("#selection button", has_text=label).first.click()
    settle(page)


def panel_dof(page):
    return page.locator("#components").inner_text()


def main():
    binary = Path(sys.argv[1] if len(sys.argv) > 1 else ROOT / "target" / "release" / "camber")
    check(binary.exists(), f"{binary} does not exist (build it first)")
    check(Path(CHROMIUM).exists(), f"{CHROMIUM} does not exist (apt-get install chromium)")
    SHOTS.mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp(prefix="camber-sketcher-"))
    drawn = work / "drawn.json"
    started = time.monotonic()
    editor = Editor(binary, drawn, "--new")
    errors = []
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=CHROMIUM, headless=True, args=["--no-sandbox"])
            page = browser.new_page(viewport={"width": 1300, "height": 850})
            if os.environ.get("CAMBER_ASSETS_FROM_SOURCE") == "1":
                assets = ROOT / "crates" / "camber-cli" / "assets"
                for name in ("editor.js", "editor.css"):
                    page.route(f"**/{name}", from_source(assets / name))
                joined = "\n".join((assets / n).read_text() for n in ("sketcher.js", "sketcher-tools.js", "sketcher-view.js"))
                page.route("**/sketcher.js", lambda route, *_: route.fulfill(body=joined, content_type="text/javascript"))
            page.on("pageerror", lambda e: errors.append(f"page error: {e}"))
            page.on("console", lambda m: errors.append(f"console {m.type}: {m.text}") if m.type == "error" else None)
            page.goto(editor.url)
            page.wait_for_selector("#tools button[data-tool=polyline]")
            settle(page)

            # 1. A rectangle drawn with the polyline tool: four clicks on grid points, the fifth
            # on the first corner closes it. Sides are inferred level and plumb, corners joined.
            page.keyboard.press("y")
            corners = [(-0.6, -0.4), (0.6, -0.4), (0.6, 0.4), (-0.6, 0.4)]
            for x, y in corners:
                px, py = at(page, x, y)
                page.mouse.move(px, py)
                click(page, x, y)
            click(page, *corners[0])
            settle(page)
            state = editor.state()
            check(len(lines(state)) == 4, f"four sides drawn: {lines(state)}")
            check(
                kinds(state) == {"coincident": 4, "horizontal": 2, "vertical": 2},
                f"inferred constraints: {kinds(state)}",
            )
            check_holds(state, "the drawn rectangle")
            bottom = side(state, True, True)
            check(abs(length(lines(state)[bottom]) - 1.2) < 1e-9, f"snapped to the grid: {lines(state)[bottom]}")
            page.keyboard.press("Escape")
            shot(page, "1_rectangle")

            # 2. Its corners rounded: select two sides (click, Shift+click), Fillet.
            ids = {
                "bottom": side(state, True, True),
                "right": side(state, False, False),
                "top": side(state, True, False),
                "left": side(state, False, True),
            }
            for a, b in [("bottom", "right"), ("right", "top"), ("top", "left"), ("left", "bottom")]:
                state = editor.state()
                click(page, *mid(state, ids[a]))
                click(page, *mid(state, ids[b]), shift=True)
                constrain(page, "Fillet")
            state = editor.state()
            arcs = [e for e in state["scene"]["entities"] if e["kind"] == "arc"]
            check(len(arcs) == 4, f"four fillet arcs: {kinds(state)}")
            check_holds(state, "the rounded rectangle")
            check(dof(state) == 4, f"a rounded rectangle on its own has 4 DOF, the analysis says {dof(state)}")
            shot(page, "2_rounded")

            # 3. Fully constrained: a corner fixed (click a side's end, Fix point), the bottom
            # and left sides dimensioned at their length (select the side, Length).
            b = lines(state)[ids["bottom"]]
            start = min(b, key=lambda q: q[0])
            click(page, *start)
            constrain(page, "Fix point")
            for name in ("bottom", "left"):
                click(page, *mid(editor.state(), ids[name]))
                constrain(page, "Length")
            state = editor.state()
            check_holds(state, "the constrained rectangle")
            check(dof(state) == 0, f"DOF after fixing and dimensioning: {dof(state)}")
            check(re.search(r"DOF\s*0 \(", panel_dof(page)), f"the panel shows DOF 0: {panel_dof(page)!r}")
            shot(page, "3_constrained")

            # 4. The width typed into its label on the picture: the bottom side becomes 1.5
            # long, everything still holds.
            width = next(c for c in state["constraints"] if c["kind"] == "distance" and ids["bottom"] in c["entities"])
            label = page.locator(f"#layer-dimensions text[data-dimension='{width['id']}']")
            check(label.count() == 1, "the width's label is drawn")
            label.click()
            page.wait_for_selector("#dim-input:not([hidden])")
            page.fill("#dim-input", "1.5")
            page.press("#dim-input", "Enter")
            settle(page)
            state = editor.state()
            check_holds(state, "after the width edit")
            check(abs(length(lines(state)[ids["bottom"]]) - 1.5) < 1e-9, f"the bottom side is 1.5 long: {lines(state)[ids['bottom']]}")
            check(dof(state) == 0, "still no freedom")
            shot(page, "4_dimension")
            saved_geometry = lines(state)

            # 5. A constraint deleted from the list (click its row, Delete) and added back from a
            # selection (the side, Shift+H).
            level = next(c for c in state["constraints"] if c["kind"] == "horizontal" and ids["top"] in c["entities"])
            page.locator(f"#constraints tr[data-constraint='{level['id']}']").click()
            page.keyboard.press("Delete")
            settle(page)
            state = editor.state()
            check(all(c["id"] != level["id"] for c in state["constraints"]), "the constraint is deleted")
            check(dof(state) == 1, f"one DOF freed: {dof(state)}")
            shot(page, "5_deleted")
            click(page, *mid(state, ids["top"]))
            page.keyboard.press("Shift+H")
            settle(page)
            state = editor.state()
            check(kinds(state).get("horizontal") == 2, f"horizontal again: {kinds(state)}")
            check(dof(state) == 0, f"no freedom again: {dof(state)}")
            check_holds(state, "after re-adding")
            shot(page, "6_readded")

            # 6. Undo takes the re-added constraint back, redo replays it.
            page.click("#undo")
            settle(page)
            check(dof(editor.state()) == 1, "undo took the constraint back")
            page.keyboard.press("Control+Shift+Z")
            settle(page)
            state = editor.state()
            check(dof(state) == 0 and kinds(state).get("horizontal") == 2, "redo replayed it")

            # 7. Saved, reloaded, restarted on the saved file: the same sketch.
            page.keyboard.press("Control+s")
            settle(page)
            check(drawn.exists(), "Ctrl+S wrote the file")
            check(not editor.state()["unsaved"], "nothing unsaved after saving")
            page.reload()
            settle(page)
            check(page.locator("#layer-dimensions text").count() >= 6, "labels drawn after a reload (4 radii, 2 lengths)")
            before = editor.state()
            editor.stop()
            editor = Editor(binary, drawn, solve=True)
            page.goto(editor.url)
            settle(page)
            after = editor.state()
            check(after["constraints"] == before["constraints"], "the saved file holds the same constraints")
            check(after["scene"]["entities"] == before["scene"]["entities"], "the saved file holds the same geometry")
            check(lines(after) == saved_geometry, "the geometry typed is the geometry saved")
            check(after["report"] is None, "a solved file opens untouched")
            shot(page, "7_reloaded")
            editor.stop()

            # 8. A sketch that does not hold as shipped opens solved, the report shown.
            blade = work / "blade.json"
            shutil.copy(BLADE, blade)
            editor = Editor(binary, blade, solve=True)
            page.goto(editor.url)
            settle(page)
            state = editor.state()
            check(state["report"] and state["report"]["summary"].startswith("solved on opening"), f"report: {state['report']}")
            check(all(c["residual"] < TOLERANCE for c in state["components"]), "every component solved")
            check("solved on opening" in page.locator("#report").inner_text(), "the page shows the report")
            shot(page, "8_opened_solved")
            browser.close()
        check(not errors, f"the page logged errors: {errors}")
    finally:
        editor.stop()
        shutil.rmtree(work, ignore_errors=True)
    print(f"sketcher test passed in {time.monotonic() - started:.1f} s; screenshots in {SHOTS}")


if __name__ == "__main__":
    try:
        main()
    except Failure as e:
        print(f"sketcher test FAILED: {e}", file=sys.stderr)
        sys.exit(1)
