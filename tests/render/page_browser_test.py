#!/usr/bin/env python3
"""`linkage render --out clip.html` driven in headless Chromium (issue 28).

Makes pages of the four-bar, the homework (two-blocks), every shipped mechanism (short)
and a mechanism titled with a script tag, opens each from file:// in one browser, and
checks: no console errors; the canvas scrubbed to t = 3 s is the clip's frame at 3 s as
Cairo draws it, to the tolerance below; hiding the joint forces changes exactly the
pixels of their layers; the keys step and play; the pointer on a panel's curve reads
`linkage simulate`'s value there; the CSV download is simulate's table at the frame
times; the title shows as text and runs nothing; the panel of the case's worked equations
is well-formed XML with MathML the browser draws, sits beside the canvas on a wide window
without changing its size, and hides. With --stills DIR, also writes the screenshots
docs/stills/page-four-bar-t0.png and -t3.png (on a window 1900 px wide).

    page_browser_test.py LINKAGE SOURCE_DIR WORK_DIR [--stills DIR]
"""
import base64
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ElementTree

try:
    from selenium import webdriver
    from selenium.common.exceptions import NoAlertPresentException
    from selenium.webdriver.chrome.options import Options
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
except ImportError:
    webdriver = None

SKIP = 77  # ctest's SKIP_RETURN_CODE

LINKAGE, SOURCE, WORK = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
STILLS = pathlib.Path(sys.argv[sys.argv.index("--stills") + 1]) if "--stills" in sys.argv else None
XSS_TITLE = "</script><script>alert(1)</script>"
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def linkage(*args):
    subprocess.run([LINKAGE, *args, "--quiet"], check=True)


def browser():
    options = Options()
    # Chromium's own connections are refused on a closed network: none are started.
    for flag in ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync",
                 "--window-size=1400,1100", "--force-device-scale-factor=1"):
        options.add_argument(flag)
    options.add_argument("--user-data-dir=" + tempfile.mkdtemp(dir=WORK))
    options.binary_location = shutil.which("chromium")
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=options)


def open_page(driver, page):
    driver.get(page.as_uri())
    for _ in range(500):
        if driver.execute_script("return !!(window.linkagePage && window.linkagePage.ready)"):
            return True
        time.sleep(0.02)
    return False


def settle(driver):
    """Waits until the frame last asked for is on the canvas."""
    for _ in range(500):
        if driver.execute_script("const p = window.linkagePage; return p.completed === p.requested"):
            return
        time.sleep(0.01)
    raise RuntimeError("the page did not draw the frame asked for")


def errors(driver):
    return [entry["message"] for entry in driver.get_log("browser") if entry["level"] == "SEVERE"]


# The canvas's pixels against a PNG's (data: URLs both; the canvas's is lossless), drawn
# `shift` pixels to the right: figures only. Run in a blank tab: the page's own policy
# allows no image, as it needs none.
COMPARE = """
const [canvasPng, png, shift, done] = arguments;
const load = (src) => new Promise((resolve, reject) => {
  const img = new Image(); img.onload = () => resolve(img); img.onerror = reject; img.src = src;
});
const pixels = (img, dx) => {
  const c = document.createElement('canvas');
  c.width = img.width; c.height = img.height;
  const ctx = c.getContext('2d');
  ctx.drawImage(img, dx, 0);
  return ctx.getImageData(0, 0, img.width, img.height).data;
};
Promise.all([load(canvasPng), load(png)]).then(([canvas, img]) => {
  if (img.width !== canvas.width || img.height !== canvas.height) { done({size: [img.width, img.height]}); return; }
  const mine = pixels(canvas, 0), theirs = pixels(img, shift);
  let over32 = 0, over96 = 0, sum = 0;
  for (let i = 0; i < mine.length; i += 4) {
    let d = 0;
    for (let c = 0; c < 3; ++c) d = Math.max(d, Math.abs(mine[i + c] - theirs[i + c]));
    sum += d; if (d > 32) ++over32; if (d > 96) ++over96;
  }
  const n = mine.length / 4;
  done({pixels: n, mean: sum / n, over32: over32 / n, over96: over96 / n});
}, (e) => done({error: String(e)}));
"""


def compare_canvas(driver, png, shift):
    """The page's canvas against the PNG file `png` shifted right by `shift` pixels."""
    canvas = driver.execute_script("return document.getElementById('clip').toDataURL('image/png')")
    page = driver.current_window_handle
    driver.switch_to.new_window("tab")
    try:
        return driver.execute_async_script(COMPARE, canvas, png_url(png), shift)
    finally:
        driver.close()
        driver.switch_to.window(page)


# The pixels that change when an element is hidden, against where its layers paint.
TOGGLE = """
const [element, done] = arguments;
const page = window.linkagePage, canvas = document.getElementById('clip');
const grab = () => canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
const settle = async () => { while (page.completed !== page.requested) await new Promise(r => setTimeout(r, 10)); };
(async () => {
  await settle();
  const before = grab();
  page.setShown(element, false);
  await settle();
  const after = grab();
  const alone = await page.layersAlone(page.frame, element);
  page.setShown(element, true);
  await settle();
  const w = canvas.width, h = canvas.height;
  // Where the element's layers put any ink, grown by a pixel (antialiasing reaches it).
  const ink = new Uint8Array(w * h);
  for (let y = 0; y < h; ++y) for (let x = 0; x < w; ++x) {
    if (alone[4 * (y * w + x) + 3] === 0) continue;
    for (let dy = -1; dy <= 1; ++dy) for (let dx = -1; dx <= 1; ++dx) {
      const X = x + dx, Y = y + dy;
      if (X >= 0 && Y >= 0 && X < w && Y < h) ink[Y * w + X] = 1;
    }
  }
  // And the picture with them is their layers painted over the picture without them.
  let changed = 0, outside = 0, inked = 0, unlike = 0;
  for (let p = 0; p < w * h; ++p) {
    let d = 0, e = 0;
    const a = alone[4 * p + 3] / 255;
    for (let c = 0; c < 3; ++c) {
      d = Math.max(d, Math.abs(before[4 * p + c] - after[4 * p + c]));
      const over = a * alone[4 * p + c] + (1 - a) * after[4 * p + c];
      e = Math.max(e, Math.abs(before[4 * p + c] - over));
    }
    if (d > 0) { ++changed; if (!ink[p]) ++outside; }
    if (a > 0) { ++inked; if (e > 8) ++unlike; }
  }
  done({changed, outside, inked, unlike});
})();
"""


def equations_html(page):
    """The equations panel's HTML as the page file holds it: <div id="equations-body">...</div>."""
    text = page.read_text()
    start = text.find('<div id="equations-body">')
    return text[start:text.find("</details>", start)] if start >= 0 else None


# The panel's figures: its math, whether it is open, and where it and the canvas are.
PANEL = """
const rect = (e) => { const r = e.getBoundingClientRect(); return [r.left, r.top, r.width, r.height]; };
const panel = document.getElementById('equations'), maths = [...panel.querySelectorAll('math')];
const drawn = maths.filter((m) => { const r = m.getBoundingClientRect(); return m.checkVisibility() && r.width > 0 && r.height > 0; });
const body = document.getElementById('equations-body'), display = panel.querySelector('math[display=block]');
return {open: panel.open, maths: maths.length, drawn: drawn.length, merror: panel.querySelectorAll('merror').length,
        panel: rect(panel), body: rect(body), body_visible: body.checkVisibility(),
        canvas: rect(document.getElementById('clip')), display: display ? rect(display) : null};
"""


def save_still(driver, name):
    """A screenshot for docs/stills on a window wide enough for the equations beside the clip,
    the panel scrolled to the clip's case."""
    driver.set_window_size(1900, 1150)
    driver.execute_script("""
        const body = document.getElementById('equations-body');
        const heading = [...body.querySelectorAll('h2')].find((h) => h.textContent.startsWith('Case'));
        if (heading) body.scrollTop = heading.offsetTop - body.offsetTop;""")
    time.sleep(0.2)
    driver.save_screenshot(str(STILLS / name))
    driver.set_window_size(1400, 1100)
    time.sleep(0.2)


def simulated(*args):
    """`linkage simulate`'s table: its header's names and rows of numbers."""
    out = subprocess.run([LINKAGE, "simulate", *args], check=True, capture_output=True, text=True).stdout
    lines = out.strip().split("\n")
    return lines[0].split(","), [[float(v) for v in line.split(",")] for line in lines[1:]]


def check_panel_and_csv(driver, page, downloads):
    """The panel's values under the cursor and the CSV download, against `linkage simulate`."""
    check(open_page(driver, page), "the four-bar's page with a panel opens")
    names, rows = simulated("--mechanism", str(SOURCE / "mechanisms/four-bar.toml"), "--duration", "4", "--every",
                            "1", "--columns", "t,2.theta,B.force_x")
    at3 = rows[3]
    plots = driver.execute_script("return window.linkagePage.plots()")
    check(len(plots) == 2, f"two plots, one per unit (rad, N): {len(plots)}")
    for plot, value, unit in zip(plots, at3[1:], ("rad", "N")):
        m = plot["time"]
        x = m["from"] + (3.0 - m["min"]) / (m["max"] - m["min"]) * (m["to"] - m["from"])
        v = plot["value"]
        y = v["from"] + (value - v["min"]) / (v["max"] - v["min"]) * (v["to"] - v["from"])
        text = driver.execute_script("return window.linkagePage.plotAt(arguments[0], arguments[1])", x, y) or ""
        expected = f"{float(f'{value:.4g}'):g}"
        check(text.endswith(f" = {expected} {unit} at t = 3.000 s"),
              f"the cursor on the {unit} plot at t = 3 s reads simulate's value {value:.6g} {unit}: '{text}'")
    # A real pointer on the first plot: the box under it says what plotAt says of that pixel
    # (offsets from the canvas's centre, border included; it is drawn at its own size here).
    canvas = driver.find_element(By.ID, "clip")
    left, top, width, height = plots[0]["area"]
    px, py = round(left + width / 2), round(top + height / 2)
    border = driver.execute_script("return arguments[0].clientLeft", canvas)
    ActionChains(driver).move_to_element_with_offset(canvas, px + border - canvas.size["width"] // 2,
                                                     py + border - canvas.size["height"] // 2).perform()
    shown = driver.find_element(By.ID, "hover")
    # (The pointer lands within a pixel of where it was sent: the browser rounds.)
    said = [driver.execute_script("return window.linkagePage.plotAt(arguments[0], arguments[1])", px + d, py)
            for d in (-1, -0.5, 0, 0.5, 1)]
    check(shown.is_displayed() and shown.text in said,
          f"the pointer on a plot shows its value: '{shown.text}' (at that pixel: {said[2]})")
    # The CSV the page offers: the motion's poses at the frame times, as simulate writes them.
    driver.execute_cdp_cmd("Page.setDownloadBehavior", {"behavior": "allow", "downloadPath": str(downloads)})
    driver.find_element(By.ID, "csv").click()
    saved = downloads / "four-bar-panel.csv"
    for _ in range(500):
        if saved.exists() and saved.stat().st_size > 0:
            break
        time.sleep(0.02)
    check(saved.exists(), "Download CSV saves four-bar-panel.csv")
    if saved.exists():
        lines = saved.read_text().strip().split("\n")
        header, table = lines[0].split(","), [[float(v) for v in line.split(",")] for line in lines[1:]]
        poses = simulated("--mechanism", str(SOURCE / "mechanisms/four-bar.toml"), "--duration", "4", "--every", "1")
        check(header == poses[0], f"the CSV's columns are simulate's: {header}")
        check(len(table) == 120, f"a row per frame: 120 for 4 s at 30 fps ({len(table)})")
        # Frames 0, 30, ..., 90 are t = 0, 1, 2, 3 s: simulate's rows there, to the integrator's tolerance.
        worst = max(abs(a - b) for k in range(4) for a, b in zip(table[30 * k], poses[1][k]))
        check(worst < 1e-7, f"the CSV's rows at t = 0, 1, 2, 3 s are simulate's (largest difference {worst:.2g})")
    check(errors(driver) == [], "no console errors on the page with a panel")


def png_url(path):
    return "data:image/png;base64," + base64.b64encode(path.read_bytes()).decode()


def main():
    if webdriver is None or not shutil.which("chromium") or not shutil.which("chromedriver"):
        print("skipped: no Chromium, chromedriver or Selenium; ./scripts/install-deps --tests installs "
              "chromium chromium-driver python3-selenium (Debian's python3)")
        # CI installs them (scripts/test): there a missing browser is a failure, not a skip.
        return 1 if os.environ.get("CI") else SKIP
    shutil.rmtree(WORK, ignore_errors=True)
    WORK.mkdir(parents=True)
    four_bar = WORK / "four-bar.html"
    linkage("render", "--mechanism", str(SOURCE / "mechanisms/four-bar.toml"), "--out", str(four_bar))
    # The clip's own frames as Cairo draws them into the MP4. (A still --at 3 is not one of
    # them: its camera fits the motion up to 3 s, the clip's the whole 10 s.)
    frames = WORK / "frames"
    linkage("render", "--mechanism", str(SOURCE / "mechanisms/four-bar.toml"), "--frames", str(frames))
    still = frames / "frame_00090.png"
    homework = WORK / "two-blocks.html"
    linkage("render", "--mechanism", str(SOURCE / "mechanisms/two-blocks.toml"), "--duration", "2", "--out",
            str(homework))
    hostile = WORK / "hostile.toml"
    text = (SOURCE / "mechanisms/four-bar.toml").read_text()
    hostile.write_text(text.replace('title = "Four-bar linkage: a Grashof crank-rocker"',
                                    "title = " + json.dumps(XSS_TITLE), 1))
    hostile_page = WORK / "hostile.html"
    linkage("render", "--mechanism", str(hostile), "--duration", "1", "--out", str(hostile_page))
    # Every shipped mechanism's page, short and small: it opens, draws, logs no error.
    shipped = []
    for toml in sorted((SOURCE / "mechanisms").glob("*.toml")):
        shipped.append(WORK / ("shipped-" + toml.stem + ".html"))
        linkage("render", "--mechanism", str(toml), "--duration", "0.2", "--size", "320x180", "--out",
                str(shipped[-1]))
    with_panel = WORK / "four-bar-panel.html"
    linkage("render", "--mechanism", str(SOURCE / "mechanisms/four-bar.toml"), "--duration", "4", "--panel",
            "2.theta,B.force_x", "--out", str(with_panel))
    size = four_bar.stat().st_size
    check(size < 2_000_000, f"the four-bar's 10 s page, equations included, is under 2 MB ({size} bytes)")
    # The equations as the page holds them: well-formed XML, MathML and no unknown command.
    panel = equations_html(four_bar)
    try:
        tree = ElementTree.fromstring(panel) if panel else None
    except ElementTree.ParseError as e:
        tree = None
        print("     ", e)
    check(tree is not None, "the four-bar's equations panel is well-formed XML")
    if tree is not None:
        maths = tree.findall(".//math")
        check(len(maths) > 10 and not tree.findall(".//merror"),
              f"its math is MathML, no command left unknown ({len(maths)} <math> elements)")
        check("Case 3" in "".join(tree.itertext()), "they are the worked solution of the clip's case (3)")

    driver = browser()
    try:
        started = time.monotonic()
        check(open_page(driver, four_bar), "the four-bar's page opens and draws its first frame")
        print(f"     (first frame after {time.monotonic() - started:.2f} s; not a check)")
        check(errors(driver) == [], "no console errors opening the four-bar's page")
        page = driver.execute_script("const p = window.linkagePage; return {count: p.count, toggles: p.toggles}")
        check(page["count"] == 300, f"300 frames for 10 s at 30 fps ({page['count']})")
        if STILLS:
            STILLS.mkdir(parents=True, exist_ok=True)
            save_still(driver, "page-four-bar-t0.png")

        # Scrubbing: the slider moved to frame 90 (t = 3 s) as a hand would.
        slider = driver.find_element(By.ID, "slider")
        driver.execute_script("arguments[0].value = 90; arguments[0].dispatchEvent(new Event('input'))", slider)
        settle(driver)
        check(driver.execute_script("return window.linkagePage.time") == 3.0, "the slider's frame 90 is t = 3 s")
        # Chromium's rasterizer against Cairo's: the same paths, their antialiased edges
        # rounded differently; Cairo's labels placed to a quarter pixel (render/text.cpp) and
        # its HUD and legend glyphs hinted. Measured: 0.05% of pixels differ by more than 96
        # of 255, mean difference 0.6. The next frame (0.033 s later) differs in 2.4%, the frame
        # a pixel aside (checked below) in more than 0.2%: so under 0.2% tells the frame and its place.
        same = compare_canvas(driver, still, 0)
        print("     canvas at 3 s against Cairo's frame 90:", same)
        check(same.get("pixels") == 1280 * 720, "the canvas has the clip's size")
        check(same.get("over96", 1) < 0.002 and same.get("mean", 255) < 1.0,
              "the canvas at t = 3 s is Cairo's frame 90 (under 0.2% of pixels differ by more than 96)")
        aside = compare_canvas(driver, still, 1)
        print("     against Cairo's frame 90 a pixel to the right:", aside)
        check(aside.get("over96", 0) > 0.002, "a pixel aside is not the frame (over 0.2% differ by more than 96)")
        driver.execute_script("window.linkagePage.show(91)")
        settle(driver)
        later = compare_canvas(driver, still, 0)
        print("     a frame later against Cairo's frame 90:", later)
        check(later.get("over96", 0) > 0.01, "a frame later is not frame 90 (over 1% of pixels differ by more than 96)")

        # Hiding the joint forces changes the pixels of their arrows and labels, no others.
        driver.execute_script("window.linkagePage.show(90)")
        settle(driver)
        toggled = driver.execute_async_script(TOGGLE, "pin-force")
        print("     hiding pin-force:", toggled)
        check(toggled["changed"] > 1000, "hiding the joint forces changes the picture")
        check(toggled["outside"] == 0, "hiding the joint forces changes no pixel outside their layers")
        check(toggled["unlike"] <= 0.01 * toggled["inked"],
              "the picture is the joint forces' layers over the picture without them (99% within 8 of 255)")

        # The keyboard: arrows step a frame, space plays and pauses.
        body = driver.find_element(By.TAG_NAME, "body")
        body.send_keys(Keys.ARROW_RIGHT)
        settle(driver)
        check(driver.execute_script("return window.linkagePage.drawn") == 91, "-> steps to frame 91")
        body.send_keys(Keys.ARROW_LEFT)
        body.send_keys(Keys.ARROW_LEFT)
        settle(driver)
        check(driver.execute_script("return window.linkagePage.drawn") == 89, "<- <- steps back to frame 89")
        # At a quarter speed, so a busy machine's slow keys cannot let it play to the end
        # (where it stops, and space would start it again from the beginning).
        driver.execute_script("const s = document.getElementById('speed'); s.value = '0.25';"
                              "s.dispatchEvent(new Event('change'))")
        body.send_keys(Keys.SPACE)
        check(driver.execute_script("return window.linkagePage.playing"), "space plays")
        for _ in range(500):
            if driver.execute_script("return window.linkagePage.frame") > 89:
                break
            time.sleep(0.02)
        body.send_keys(Keys.SPACE)
        settle(driver)
        frame = driver.execute_script("return window.linkagePage.frame")
        check(not driver.execute_script("return window.linkagePage.playing") and frame > 89,
              f"space pauses, after playing on (frame {frame})")

        # The value under the cursor: the first arrow's middle names it with its unit.
        hover = driver.execute_script(
            "const p = window.linkagePage, a = p.arrows(p.frame)[0];"
            "return [p.arrowAt((a.a[0] + a.b[0]) / 2, (a.a[1] + a.b[1]) / 2), a.value]")
        check(hover[0] is not None and hover[0].endswith(hover[1]) and hover[1].endswith(" N"),
              f"an arrow's value with its unit under the cursor ({hover[0]})")
        check(errors(driver) == [], "no console errors using the four-bar's page")

        # The equations: below the canvas in this window, drawn, hidden and shown by their summary.
        shown = driver.execute_script(PANEL)
        print("     equations panel:", shown)
        check(shown["open"] and shown["maths"] > 10 and shown["drawn"] == shown["maths"] and shown["merror"] == 0,
              "the equations panel starts open and the browser draws each <math> with a size")
        check(shown["display"] is not None and shown["display"][3] > 40,
              "a display equation (the first: the moments of inertia) is taller than a few lines")
        check(shown["panel"][1] >= shown["canvas"][1] + shown["canvas"][3], "on a narrow window it is below the canvas")
        check(shown["body"][3] <= driver.execute_script("return window.innerHeight"),
              "it scrolls on its own (no taller than the window)")
        driver.find_element(By.CSS_SELECTOR, "#equations > summary").click()
        hidden = driver.execute_script(PANEL)
        print("     hidden:", hidden)
        check(not hidden["open"] and hidden["drawn"] == 0 and not hidden["body_visible"],
              "clicking its summary hides the equations")
        check(hidden["canvas"] == shown["canvas"], "the canvas keeps its place and size")
        driver.find_element(By.CSS_SELECTOR, "#equations > summary").click()
        check(driver.execute_script(PANEL)["open"], "a second click shows them again")
        # A window wide enough for both: the panel beside the canvas, the canvas its own size.
        driver.set_window_size(1900, 1100)
        time.sleep(0.2)
        wide = driver.execute_script(PANEL)
        print("     on a wide window:", wide)
        check(wide["panel"][0] >= wide["canvas"][0] + wide["canvas"][2] and wide["panel"][1] < wide["canvas"][1] + 50,
              "on a wide window the panel is beside the canvas")
        check(wide["canvas"][2] == shown["canvas"][2] == 1282, "the canvas is its own size (1280 px and its border)")
        driver.set_window_size(1400, 1100)
        time.sleep(0.2)
        check(errors(driver) == [], "no console errors (nor styles refused) with the equations panel")
        if STILLS:  # at the speed a page opens with, as a reader first sees it
            driver.execute_script("const s = document.getElementById('speed'); s.value = '1';"
                                  "s.dispatchEvent(new Event('change')); window.linkagePage.show(90)")
            settle(driver)
            save_still(driver, "page-four-bar-t3.png")

        downloads = WORK / "downloads"
        downloads.mkdir()
        check_panel_and_csv(driver, with_panel, downloads)

        check(open_page(driver, homework), "the homework's page opens")
        check(errors(driver) == [], "no console errors on the homework's page")
        check(driver.execute_script("return window.linkagePage.count") == 60, "the homework's 2 s: 60 frames")

        for page in shipped:
            opened = open_page(driver, page)
            if opened:
                driver.execute_script("window.linkagePage.show(window.linkagePage.count - 1)")
                settle(driver)
            check(opened and driver.execute_script("return window.linkagePage.drawn") == 5 and errors(driver) == [],
                  f"{page.name}: opens, draws its last frame (the 6th: 0.2 s at 30 fps), no console errors")
            figures = driver.execute_script(PANEL) if opened else {}
            check(figures.get("maths", 0) > 5 and figures.get("drawn") == figures.get("maths") and
                  figures.get("merror") == 0, f"{page.name}: its equations drawn, no command unknown")

        check(open_page(driver, hostile_page), "the page of a mechanism titled with a script opens")
        try:
            driver.switch_to.alert
            check(False, "no alert from a title")
        except NoAlertPresentException:
            check(True, "no alert from a title")
        check(driver.find_element(By.ID, "title").text == XSS_TITLE, "the title shows as text")
        check(driver.title == XSS_TITLE, "the document's title is the text")
        check(XSS_TITLE in driver.find_element(By.CSS_SELECTOR, "#equations-body h1").text,
              "the worked solution's heading shows the title as text too")
        check(errors(driver) == [], "no console errors (nor refused scripts) on that page")
    finally:
        driver.quit()
    if failures:
        print(f"{len(failures)} check(s) failed")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
