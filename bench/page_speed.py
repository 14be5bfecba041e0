#!/usr/bin/env python3
"""How fast a clip's page (`linkage render --out clip.html`) opens and plays in headless Chromium.

    bench/page_speed.py LINKAGE [--mechanism four-bar] [--runs 5] [--work DIR]

Renders the mechanism's 10 s clip as a page, opens it RUNS times from file:// in one
browser and reports, per run and as the median:
  - first frame: ms from the start of the page's navigation (the browser's own clock,
    performance.now()) until its first frame is on the canvas (issue 28's goal: under 1 s);
  - playing: frames painted per second while it plays the whole clip at speed 1, as a
    fraction of the clip's own rate (the goal: 1, every frame on time).
  - painting: ms to paint one frame (show(k), then one pixel read back, which makes the
    browser rasterize it), median and largest over every frame of the clip in turn.
All are measured inside the page, so Selenium's own overhead is not in them. The machine's
load average is printed with them: the machines are shared, and a figure means little
without it. Needs Debian's chromium, chromium-driver and python3-selenium.
"""
import argparse
import os
import pathlib
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service

PLAY = """
const done = arguments[0], page = window.linkagePage;
const painted = page.paints, started = performance.now();
document.getElementById('play').click();
const wait = () => {
  if (page.playing) { setTimeout(wait, 50); return; }
  done([page.paints - painted, (performance.now() - started) / 1000]);
};
setTimeout(wait, 50);
"""

PAINT = """
const page = window.linkagePage, ctx = document.getElementById('clip').getContext('2d');
page.show(0);
const times = [];
for (let k = 1; k < page.count; ++k) {
  const started = performance.now();
  page.show(k);
  ctx.getImageData(0, 0, 1, 1);
  times.push(performance.now() - started);
}
times.sort((a, b) => a - b);
return [times[times.length >> 1], times[times.length - 1]];
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("linkage")
    parser.add_argument("--mechanism", default="four-bar")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--work", default=None, help="folder for the page (default: a temporary one)")
    args = parser.parse_args()
    work = pathlib.Path(args.work or tempfile.mkdtemp(prefix="page-speed-"))
    work.mkdir(parents=True, exist_ok=True)
    page = work / (args.mechanism + ".html")
    subprocess.run([args.linkage, "render", "--mechanism", args.mechanism, "--out", str(page), "--quiet"], check=True)

    options = Options()
    for flag in ("--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking",
                 "--window-size=1400,1100", "--force-device-scale-factor=1"):
        options.add_argument(flag)
    options.add_argument("--user-data-dir=" + tempfile.mkdtemp(dir=work))
    options.binary_location = shutil.which("chromium")
    driver = webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=options)
    first, rates, paints_ms = [], [], []
    try:
        for run in range(args.runs):
            driver.get(page.as_uri())
            for _ in range(1000):
                if driver.execute_script("return !!(window.linkagePage && window.linkagePage.ready)"):
                    break
                time.sleep(0.01)
            else:
                sys.exit(f"{page.name}: the page did not draw its first frame in 10 s")
            ready = driver.execute_script("return window.linkagePage.readyAt")
            count, fps = driver.execute_script("return [window.linkagePage.count, window.linkagePage.fps]")
            driver.set_script_timeout(120)
            paints, seconds = driver.execute_async_script(PLAY)
            rate = paints / seconds / fps
            median, largest = driver.execute_script(PAINT)
            first.append(ready)
            rates.append(rate)
            paints_ms.append(median)
            print(f"run {run + 1}: first frame {ready:.0f} ms; played {paints} of {count} frames in {seconds:.2f} s: "
                  f"{paints / seconds:.1f} frames/s, {rate:.2f} of the clip's {fps:g} fps; a frame painted in "
                  f"{median:.1f} ms (median; largest {largest:.1f}) (load average {os.getloadavg()[0]:.1f})")
    finally:
        driver.quit()
    print(f"{args.mechanism}, {page.stat().st_size} bytes: median first frame {statistics.median(first):.0f} ms; "
          f"median playing rate {statistics.median(rates):.2f} of the clip's; median paint "
          f"{statistics.median(paints_ms):.1f} ms a frame")


if __name__ == "__main__":
    main()
