#!/usr/bin/python3
"""Opens rodshape's 3D pages (plan.html, validation.html) in headless Chromium and checks what a
person would see: no console error, a 3D view that is not blank (the view's part of a screenshot
at the slider's end has many colours), the slider's end showing the final shape (window.rodshape.state() against the
plan's last step in plan.json), the picture changing with the time, and the page's own helpers
(interpolation, the colour ramp). Debian: chromium, chromium-driver, python3-selenium.

Usage: /usr/bin/python3 tests/figures/check_pages.py [--screenshot PAGE=PNG] DIR_OR_PAGE...
Each DIR is searched for plan.html and validation.html. Exit status 0 when every page passes.
Run by .ci/run (step 3b) on the bundled examples' outputs.
"""

import argparse
import base64
import json
import math
import os
import sys
import time

from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service

# Counts the distinct colours of a screenshot inside a rectangle, in the browser (no PIL needed).
COUNT_COLOURS = """
const [png, rect, done] = arguments;
const image = new Image();
image.onload = () => {
  const canvas = document.createElement('canvas');
  canvas.width = image.width; canvas.height = image.height;
  const ctx = canvas.getContext('2d');
  ctx.drawImage(image, 0, 0);
  const x = Math.max(0, Math.floor(rect.x)), y = Math.max(0, Math.floor(rect.y));
  const w = Math.min(image.width - x, Math.floor(rect.width));
  const h = Math.min(image.height - y, Math.floor(rect.height));
  const pixels = ctx.getImageData(x, y, w, h).data;
  const seen = new Set();
  let hash = 0;
  for (let i = 0; i < pixels.length; i += 4) {
    const c = (pixels[i] << 16) | (pixels[i + 1] << 8) | pixels[i + 2];
    seen.add(c);
    hash = (hash * 31 + c) | 0;
  }
  done({colours: seen.size, hash: hash, width: w, height: h});
};
image.onerror = () => done({colours: 0, hash: 0, width: 0, height: 0});
image.src = 'data:image/png;base64,' + png;
"""

# The page's own helpers, checked on small made-up data.
HELPER_CHECKS = """
const h = window.rodshape.helpers;
const errors = [];
const keys = [{t: 0, shape: [[0,0,0],[1,0,0]], step: 0}, {t: 2, shape: [[0,0,0],[1,0,2]], step: 1},
              {t: 4, shape: [[0,0,0],[1,0,4]], step: 2}];
const mid = h.shapeAt(keys, 1);
if (Math.abs(mid.shape[1][2] - 1) > 1e-12 || mid.step !== 0) errors.push('shapeAt(1): ' + JSON.stringify(mid));
const end = h.shapeAt(keys, 9);
if (end.shape[1][2] !== 4 || end.step !== 2) errors.push('shapeAt(end): ' + JSON.stringify(end));
const start = h.shapeAt(keys, -1);
if (start.shape[1][2] !== 0 || start.step !== 0) errors.push('shapeAt(start): ' + JSON.stringify(start));
if (h.segmentAt([0, 1, 2, 3], 2.5) !== 2) errors.push('segmentAt');
const mixed = h.mixShapes([[0,0,0],[2,0,0]], [[0,0,0],[1,0,0],[2,0,2]], 0.5);
if (mixed.length !== 3 || Math.abs(mixed[2][2] - 1) > 1e-12) errors.push('mixShapes: ' + JSON.stringify(mixed));
const arm = {t: [0, 1], frames: [[[0,0,0],[0,0,1]], [[0,0,0],[1,0,1]]]};
const a = h.armAt(arm, 0.25);
if (Math.abs(a[1][0] - 0.25) > 1e-12) errors.push('armAt: ' + JSON.stringify(a));
if (h.armAt(null, 1) !== null) errors.push('armAt(null)');
if (h.stepColour(0, 5) !== 0x0d0887 || h.stepColour(4, 5) !== 0xf08232) errors.push('stepColour');
return errors;
"""


def find_pages(arguments):
    pages = []
    for argument in arguments:
        if os.path.isdir(argument):
            for name in ("plan.html", "validation.html"):
                path = os.path.join(argument, name)
                if os.path.isfile(path):
                    pages.append(path)
        else:
            pages.append(argument)
    return pages


def browser():
    options = Options()
    for flag in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=1100,680",
                 "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--disable-gpu-sandbox",
                 "--hide-scrollbars", "--force-device-scale-factor=1"):
        options.add_argument(flag)
    options.binary_location = "/usr/bin/chromium"
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)


def max_node_distance(a, b):
    if len(a) != len(b):
        return math.inf
    return max(math.dist(p, q) for p, q in zip(a, b))


def final_shape_from_plan_json(page):
    """The last step's nodes as plan.json has them (or None when it has none)."""
    path = os.path.join(os.path.dirname(page), "plan.json")
    if not os.path.isfile(path):
        return None
    with open(path, encoding="utf-8") as f:
        plan = json.load(f)
    steps = plan.get("steps") or []
    if not steps:
        return None
    configuration = steps[-1].get("configuration") or {}
    return configuration.get("p")


def check_page(driver, page, screenshot=None):
    failures = []
    driver.get("file://" + os.path.abspath(page))
    deadline = time.time() + 10
    while time.time() < deadline:
        if driver.execute_script("return Boolean(window.rodshape && window.rodshape.state().ready)"):
            break
        time.sleep(0.05)
    else:
        failures.append("window.rodshape never became ready")
        failures += ["console: " + e.get("message", "") for e in driver.get_log("browser")
                     if e.get("level") == "SEVERE"]
        return failures, {}
    data = driver.execute_script("return window.rodshape.data")
    view = driver.execute_script(
        "const r = document.querySelector('#rs-view canvas').getBoundingClientRect();"
        "return {x: r.x, y: r.y, width: r.width, height: r.height};")

    def picture():
        png = driver.get_screenshot_as_base64()
        return driver.execute_async_script(COUNT_COLOURS, png, view), png

    # The picture at t = 0 as the canvas holds it (cheap: no screenshot), to compare with the end.
    canvas_hash = ("const c = document.querySelector('#rs-view canvas').toDataURL('image/png');"
                   "let h = 0; for (let i = 0; i < c.length; i += 7) h = (h * 31 + c.charCodeAt(i)) | 0;"
                   "return h;")
    driver.execute_script("window.rodshape.setTime(0)")
    start_hash = driver.execute_script(canvas_hash)
    state = driver.execute_script("return window.rodshape.state()")
    if max_node_distance(state["shape"], data["initial"]) > 1e-12:
        failures.append("at t = 0 the rod is not the initial shape")
    driver.execute_script("window.rodshape.setTime(window.rodshape.state().duration)")
    end, png = picture()
    end_hash = driver.execute_script(canvas_hash)
    state = driver.execute_script("return window.rodshape.state()")
    if data["steps"]:
        final = data["steps"][-1]["shape"]
        if max_node_distance(state["shape"], final) > 1e-12:
            failures.append("at the slider's end the rod is not the last step's shape")
        if state["step"] != data["steps"][-1]["index"]:
            failures.append(f"at the end the page says step {state['step']}, not {data['steps'][-1]['index']}")
        from_json = final_shape_from_plan_json(page)
        if from_json is not None:
            tip_error = math.dist(state["tip"], from_json[-1])
            if tip_error > 2e-6:
                failures.append(f"the final tip is {tip_error:.3g} m from plan.json's")
        if start_hash == end_hash:
            failures.append("the picture at the end is the picture at t = 0")
    if data["arm"] and not state["arm"]:
        failures.append("the plan has an arm but the page shows none")
    if data["arm"] and data["arm"]["frames"]:
        driver.execute_script("window.rodshape.setTime(0)")
        first = driver.execute_script("return window.rodshape.state().arm")
        if max_node_distance(first, state["arm"]) < 1e-6 and len(data["arm"]["frames"]) > 1:
            failures.append("the arm does not move")
    if data["validation"]:
        runs = data["validation"]["runs"]
        if not runs or len(runs[0]["plant_final"]) < 2:
            failures.append("the validation page has no plant's rod")
        if len(runs) > 1 and not driver.execute_script("return Boolean(document.getElementById('rs-run'))"):
            failures.append("no run selector for several runs")
    # Not blank: a rendered scene has many colours (shading, lines, antialiasing).
    if end["colours"] < 40:
        failures.append(f"the 3D view looks blank: {end['colours']} colours in its screenshot")
    failures += driver.execute_script(HELPER_CHECKS)
    errors = [entry for entry in driver.get_log("browser") if entry.get("level") == "SEVERE"]
    for entry in errors:
        failures.append("console: " + entry.get("message", ""))
    if screenshot:
        with open(screenshot, "wb") as f:
            f.write(base64.b64decode(png))
    return failures, {"colours": end["colours"], "bytes": os.path.getsize(page)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("paths", nargs="+", help="output directories or pages")
    parser.add_argument("--screenshot", action="append", default=[], metavar="PAGE=PNG",
                        help="save the screenshot at the slider's end of PAGE (a path ending as "
                        "given) to PNG")
    args = parser.parse_args()
    shots = dict(item.split("=", 1) for item in args.screenshot)
    pages = find_pages(args.paths)
    if not pages:
        print("check_pages: no page found", file=sys.stderr)
        return 1
    started = time.time()
    driver = browser()
    failed = 0
    try:
        for page in pages:
            shot = next((png for suffix, png in shots.items() if os.path.abspath(page).endswith(suffix)), None)
            failures, facts = check_page(driver, page, shot)
            status = "ok" if not failures else "FAILED"
            detail = f"{facts.get('bytes', 0) / 1e6:.2f} MB, {facts.get('colours', 0)} colours" if facts else ""
            print(f"{status:6} {page} ({detail})")
            for failure in failures:
                print(f"       {failure}")
            failed += bool(failures)
    finally:
        driver.quit()
    print(f"check_pages: {len(pages) - failed} of {len(pages)} pages pass ({time.time() - started:.1f} s)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
