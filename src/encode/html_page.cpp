#include "encode/html_page.hpp"

#include <string_view>

#include "core/atomic_file.hpp"
#include "core/markup_escape.hpp"
#include "core/sha256.hpp"
#include "encode/gzip.hpp"

namespace linkage {
namespace {

constexpr std::string_view kStyle = R"(
body { font-family: "DejaVu Sans", sans-serif; margin: 1em; color: #222; background: #fafafa; }
h1 { font-size: 1.3em; margin: 0 0 0.5em; }
#stage { position: relative; display: inline-block; max-width: 100%; }
#clip { display: block; max-width: 100%; height: auto; border: 1px solid #ccc; }
#hover { position: absolute; pointer-events: none; background: #fff; border: 1px solid #888; padding: 2px 6px;
         font-size: 0.9em; white-space: nowrap; }
#controls { display: flex; flex-wrap: wrap; align-items: center; gap: 0.5em; margin: 0.5em 0; }
#slider { flex: 1 1 20em; }
#time { font-variant-numeric: tabular-nums; min-width: 8em; }
#layers label { margin-right: 1em; white-space: nowrap; }
#status { color: #555; font-size: 0.9em; }
)";

// The worked equations beside the player, below it when the window is too narrow for both;
// the player keeps its size, the panel scrolls on its own. MathML Core draws the math: the
// classes of latex_mathml align the columns of aligned (right, left, ...) and space rows
// (Chromium aligns a cell by -webkit-right/-webkit-left or justify-items, not by right/left).
constexpr std::string_view kEquationsStyle = R"(
#view { display: flex; flex-wrap: wrap; align-items: flex-start; gap: 0 1em; }
#player { flex: 0 1 auto; max-width: 100%; min-width: 0; }
#equations { flex: 1 1 26em; min-width: 0; max-width: 100%; border: 1px solid #ccc; background: #fff; }
#equations > summary { cursor: pointer; padding: 0.3em 0.6em; font-weight: bold; }
#equations-body { max-height: calc(100vh - 4em); overflow: auto; padding: 0 0.8em; font-size: 0.9em; }
#equations-body h1 { font-size: 1.15em; }
#equations-body h2 { font-size: 1.05em; margin-top: 1.2em; }
#equations-body table { border-collapse: collapse; }
#equations-body th, #equations-body td { padding: 0.1em 0.5em; border-bottom: 1px solid #eee; }
math { font-family: "Latin Modern Math", "STIX Two Math", "Cambria Math", math; font-size: 1.1em; }
math[display="block"] { margin: 0.6em 0; overflow-x: auto; overflow-y: hidden; padding-bottom: 2px; }
mtable.aligned > mtr > mtd { padding: 0.15em 0; }
mtable.aligned > mtr > mtd:nth-child(odd) { text-align: right; text-align: -webkit-right; justify-items: end; }
mtable.aligned > mtr > mtd:nth-child(even) { text-align: left; text-align: -webkit-left; justify-items: start; }
mtable.aligned > mtr > mtd:nth-child(2n+3) { padding-left: 2em; }
mtable > mtr.gap > mtd { padding-top: 1.2ex; }
)";

// The player: opens the data, paints frame k's shown layers (Cairo's drawing operations)
// onto the canvas in the painter's order, and drives the controls. Nothing here reaches
// the network.
constexpr std::string_view kScript = R"js(
"use strict";
(async function () {
  const $ = (id) => document.getElementById(id);
  const status = $("status");
  const page = { ready: false, frame: 0, time: 0, drawn: -1, requested: 0, completed: 0, playing: false, rate: 1,
                 paints: 0, readyAt: 0 };
  window.linkagePage = page;
  let data;
  try {
    const raw = atob($("linkage-data").textContent.replace(/\s+/g, ""));
    const bytes = new Uint8Array(raw.length);
    for (let i = 0; i < raw.length; ++i) bytes[i] = raw.charCodeAt(i);
    const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("gzip"));
    data = JSON.parse(await new Response(stream).text());
  } catch (e) {
    status.textContent = "This browser cannot open the clip (it needs DecompressionStream: Chrome 80, " +
      "Firefox 113, Safari 16.4 or later): " + e;
    return;
  }
  const canvas = $("clip"), ctx = canvas.getContext("2d"), slider = $("slider"), hover = $("hover");
  canvas.width = data.width;
  canvas.height = data.height;
  const count = data.frames.length;
  const shown = new Set(data.toggles);
  slider.max = String(count - 1);

  // The painter of Cairo's drawing operations (encode/canvas_ops.hpp): paths and glyphs
  // as Path2D, styles as the canvas's state. Each distinct drawing of a layer is made into
  // Path2Ds once, when first drawn; the last few are kept.
  const expand = (d) => d.replace(/@(\d+)/g, (_, i) => data.paths[Number(i)]);
  const glyphs = [];
  const glyph = (i) => glyphs[i] || (glyphs[i] = new Path2D(expand(data.glyphs[i])));
  const styles = data.styles.map((s) => {
    if (s.gradient === undefined) return s;
    const g = data.gradients[s.gradient], fill = ctx.createLinearGradient(...g.line);
    for (const [offset, colour] of g.stops) fill.addColorStop(offset, colour);
    return Object.assign({}, s, { fill });
  });
  const solid = [];
  function made(ops) {
    return ops.map((op) => {
      switch (op[0]) {
        case "p": return ["p", styles[op[1]], new Path2D(expand(op[2])), op[3]];
        case "g": return ["g", styles[op[1]], op[2]];
        default: return ["c", new Path2D(expand(op[1])), op[2], made(op[3])];
      }
    });
  }
  function paint(c, ops) {  // onto a context whose transform is the identity
    for (const op of ops) {
      const s = op[1];
      if (op[0] === "g") {
        c.fillStyle = s.fill;
        const run = op[2];
        for (let i = 0; i < run.length; i += 3) {
          c.setTransform(1, 0, 0, 1, run[i + 1], run[i + 2]);
          c.fill(glyph(run[i]), s.rule || "nonzero");
        }
        c.setTransform(1, 0, 0, 1, 0, 0);
      } else if (op[0] === "c") {
        c.save();
        c.clip(op[1], op[2]);
        paint(c, op[3]);
        c.restore();
      } else {
        if (op[3]) c.setTransform(...op[3]);
        if (s.fill) {
          c.fillStyle = s.fill;
          c.fill(op[2], s.rule || "nonzero");
        }
        if (s.stroke) {
          c.strokeStyle = s.stroke;
          c.lineWidth = s.width;
          c.lineCap = s.cap;
          c.lineJoin = s.join;
          c.miterLimit = s.miter;
          c.setLineDash(s.dash || solid);
          c.lineDashOffset = s.offset || 0;
          c.stroke(op[2]);
        }
        if (op[3]) c.setTransform(1, 0, 0, 1, 0, 0);
      }
    }
  }
  function cached(cache, size, key, make) {
    let entry = cache.get(key);
    if (entry) cache.delete(key);  // kept as the newest
    else entry = make();
    cache.set(key, entry);
    while (cache.size > size) cache.delete(cache.keys().next().value);
    return entry;
  }
  const drawings = new Map();
  const drawing = (i) => cached(drawings, 64, i, () => made(data.drawings[i]));
  // A layer the same in several frames (a fixed grid, the title, the legend) is painted
  // once, into a bitmap, with the lasting layers next to it; each frame paints only its
  // own. A frame is drawn as its runs of lasting and of own layers, in the painter's order.
  const uses = new Map();
  for (const row of data.frames) for (const i of row) if (i >= 0) uses.set(i, (uses.get(i) || 0) + 1);
  const lasting = (i) => uses.get(i) > 1;
  const bitmaps = new Map();
  function bitmap(run) {
    return cached(bitmaps, 8, run.drawings.join(","), () => {
      const b = document.createElement("canvas");
      b.width = data.width;
      b.height = data.height;
      const c = b.getContext("2d");
      for (const i of run.drawings) paint(c, drawing(i));
      return b;
    });
  }
  const visible = (layer) => data.layers[layer].needs.every((e) => shown.has(e));
  function runsOf(k) {
    const runs = [];
    data.frames[k].forEach((i, layer) => {
      if (i < 0 || !visible(layer)) return;
      const last = runs[runs.length - 1];
      if (last && last.lasting === lasting(i)) last.drawings.push(i);
      else runs.push({ lasting: lasting(i), drawings: [i] });
    });
    return runs;
  }
  function draw(k) {
    ++page.requested;
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    for (const run of runsOf(k)) {
      if (run.lasting) ctx.drawImage(bitmap(run), 0, 0);
      else for (const i of run.drawings) paint(ctx, drawing(i));
    }
    page.drawn = k;
    page.completed = page.requested;
    ++page.paints;
    return Promise.resolve();
  }
  function show(k) {
    k = Math.max(0, Math.min(count - 1, Math.round(k)));
    page.frame = k;
    page.time = data.times[k];
    slider.value = String(k);
    $("time").textContent = "t = " + data.times[k].toFixed(3) + " s";
    hover.hidden = true;
    return draw(k);
  }

  // Playing: the frames at the clip's rate times the chosen speed, from where it is.
  let started = 0, from = 0;
  function tick() {
    if (!page.playing) return;
    // performance.now(), not the callback's time: that is the frame's start, which can come
    // before play() was pressed.
    const k = from + Math.max(0, Math.floor((performance.now() - started) / 1000 * data.fps * page.rate));
    if (k >= count - 1) {
      show(count - 1);
      pause();
      return;
    }
    if (k !== page.frame) show(k);
    requestAnimationFrame(tick);
  }
  function play() {
    if (page.frame >= count - 1) show(0);
    page.playing = true;
    from = page.frame;
    started = performance.now();
    $("play").textContent = "Pause";
    requestAnimationFrame(tick);
  }
  function pause() {
    page.playing = false;
    $("play").textContent = "Play";
  }
  const toggle = () => (page.playing ? pause() : play());
  function step(by) {
    pause();
    return show(page.frame + by);
  }
  $("play").addEventListener("click", toggle);
  $("back").addEventListener("click", () => step(-1));
  $("next").addEventListener("click", () => step(1));
  slider.addEventListener("input", () => { pause(); show(Number(slider.value)); });
  $("speed").addEventListener("change", () => {
    page.rate = Number($("speed").value);
    if (page.playing) { from = page.frame; started = performance.now(); }
  });
  document.addEventListener("keydown", (event) => {
    if (event.target instanceof HTMLSelectElement) return;
    if (event.key === "ArrowLeft") step(-1);
    else if (event.key === "ArrowRight") step(1);
    else if (event.key === " ") toggle();
    else return;
    event.preventDefault();
  });

  // A checkbox per element drawn somewhere in the clip.
  for (const name of data.toggles) {
    const label = document.createElement("label"), box = document.createElement("input");
    box.type = "checkbox";
    box.checked = true;
    box.dataset.element = name;
    box.addEventListener("change", () => {
      if (box.checked) shown.add(name); else shown.delete(name);
      draw(page.frame);
    });
    label.append(box, " " + name);
    $("layers").append(label);
  }
  page.setShown = (name, on) => {
    const box = [...document.querySelectorAll("#layers input")].find((b) => b.dataset.element === name);
    if (!box) return false;
    if (box.checked !== on) box.click();
    return true;
  };

  // The arrow under the cursor (within 6 px of its shaft), nearest first.
  function distance(p, a, b) {
    const dx = b[0] - a[0], dy = b[1] - a[1], len = dx * dx + dy * dy;
    const s = len > 0 ? Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len)) : 0;
    return Math.hypot(p[0] - a[0] - s * dx, p[1] - a[1] - s * dy);
  }
  function arrowAt(x, y) {
    let best = null, nearest = 6;
    for (const arrow of data.arrows[page.frame]) {
      if (!visible(arrow.layer)) continue;
      const d = distance([x, y], arrow.a, arrow.b);
      if (d <= nearest) { nearest = d; best = arrow; }
    }
    return best && (best.kind + (best.label ? " " + best.label : "") + ": " + best.value);
  }
  // The panel's curve under the cursor: the sample nearest the cursor's time, the curve
  // nearest its height.
  const panel = data.panel;
  function fromPixel(m, p) {
    const f = (p - m.from) / (m.to - m.from);
    return m.log ? m.min * Math.pow(m.max / m.min, f) : m.min + f * (m.max - m.min);
  }
  function toPixel(m, v) {
    const f = m.log ? Math.log(v / m.min) / Math.log(m.max / m.min) : (v - m.min) / (m.max - m.min);
    return m.from + f * (m.to - m.from);
  }
  function nearestSample(t) {
    let lo = 0, hi = panel.t.length - 1;
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (panel.t[mid] <= t) lo = mid; else hi = mid;
    }
    return Math.abs(panel.t[hi] - t) < Math.abs(t - panel.t[lo]) ? hi : lo;
  }
  function plotAt(x, y) {
    if (!panel) return null;
    for (const plot of panel.plots) {
      const [left, top, width, height] = plot.area;
      if (x < left || x > left + width || y < top || y > top + height) continue;
      const i = nearestSample(fromPixel(plot.time, x));
      let best = null, nearest = 0;
      for (const c of plot.curves) {
        const v = panel.curves[c].values[i];
        if (v === null) continue;
        const d = Math.abs(toPixel(plot.value, v) - y);
        if (!best || d < nearest) { nearest = d; best = panel.curves[c]; }
      }
      if (!best) return null;
      return best.label + " = " + String(Number(best.values[i].toPrecision(4))) + (best.unit ? " " + best.unit : "") +
        " at t = " + panel.t[i].toFixed(3) + " s";
    }
    return null;
  }
  canvas.addEventListener("mousemove", (event) => {
    // The canvas's own pixels: inside its border, scaled as the window shows it.
    const box = canvas.getBoundingClientRect();
    const x = (event.clientX - box.left - canvas.clientLeft) * canvas.width / canvas.clientWidth;
    const y = (event.clientY - box.top - canvas.clientTop) * canvas.height / canvas.clientHeight;
    const text = arrowAt(x, y) || plotAt(x, y);
    hover.hidden = !text;
    if (!text) return;
    hover.textContent = text;
    hover.style.left = (event.clientX - box.left + 12) + "px";
    hover.style.top = (event.clientY - box.top + 12) + "px";
  });
  canvas.addEventListener("mouseleave", () => { hover.hidden = true; });

  // For tests: the pixels of frame k's layers that need `element`, drawn alone.
  page.layersAlone = async (k, element) => {
    const needs = (layer) => data.layers[layer].needs;
    const alone = document.createElement("canvas");
    alone.width = data.width;
    alone.height = data.height;
    const c = alone.getContext("2d");
    data.frames[k].forEach((i, layer) => {
      if (i >= 0 && needs(layer).includes(element) && needs(layer).every((e) => e === element || shown.has(e)))
        paint(c, drawing(i));
    });
    return c.getImageData(0, 0, data.width, data.height).data;
  };
  // The motion's table (t and each body's pose, as `linkage simulate` writes it), saved by
  // the browser from the page's own data.
  $("csv").addEventListener("click", () => {
    const url = URL.createObjectURL(new Blob([data.csv], { type: "text/csv" }));
    const link = document.createElement("a");
    link.href = url;
    link.download = data.csvName;
    document.body.append(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(url), 10000);
  });
  page.csv = () => data.csv;
  page.plotAt = plotAt;
  page.plots = () => (panel ? panel.plots : []);
  page.count = count;
  page.fps = data.fps;
  page.times = data.times;
  page.arrows = (k) => data.arrows[k];
  page.arrowAt = arrowAt;
  page.show = show;
  page.toggles = data.toggles;
  status.textContent = count + " frames at " + data.fps + " fps. Keys: \u2190 \u2192 step a frame, space plays " +
    "or pauses; the cursor on an arrow" +
    (panel ? " or a plot" : "") + " shows its value.";
  await show(0);
  page.readyAt = performance.now();  // ms from the start of the page's navigation: its first frame
  page.ready = true;
})();
)js";

std::string csp_hash(std::string_view text) {
  const std::array<std::uint8_t, 32> digest = sha256(text);
  return "'sha256-" + base64(std::string_view(reinterpret_cast<const char*>(digest.data()), digest.size())) + "'";
}

}  // namespace

std::string html_page(const PageText& text, const std::string& data) {
  // Nothing from the network: only this page's own script and style (by their hashes), and
  // its empty icon (data:), which keeps the browser from asking a server for one.
  const std::string policy = "default-src 'none'; script-src " + csp_hash(kScript) + "; style-src " + csp_hash(kStyle) +
                             " " + csp_hash(kEquationsStyle) + "; img-src data:; base-uri 'none'; form-action 'none'";
  const std::string title = escape_markup(text.title.empty() ? std::string("linkage clip") : text.title);
  std::string page;
  page += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  page.append("<meta http-equiv=\"Content-Security-Policy\" content=\"").append(policy).append("\">\n");
  page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  page += "<link rel=\"icon\" href=\"data:,\">\n";
  page.append("<title>").append(title).append("</title>\n<style>").append(kStyle).append("</style>\n");
  page.append("<style>").append(kEquationsStyle).append("</style>\n</head>\n<body>\n");
  page.append("<h1 id=\"title\">").append(title).append("</h1>\n");
  page += "<div id=\"view\">\n<div id=\"player\">\n";
  page +=
      "<div id=\"stage\"><canvas id=\"clip\" width=\"1\" height=\"1\"></canvas><div id=\"hover\" hidden></div></div>\n";
  page += "<div id=\"controls\">\n<button id=\"play\" type=\"button\">Play</button>\n";
  page += "<button id=\"back\" type=\"button\" title=\"One frame back (left arrow key)\">&#9664;</button>\n";
  page += "<button id=\"next\" type=\"button\" title=\"One frame on (right arrow key)\">&#9654;</button>\n";
  page += "<input id=\"slider\" type=\"range\" min=\"0\" max=\"0\" step=\"1\" value=\"0\" aria-label=\"Time\">\n";
  page += "<output id=\"time\">t = 0.000 s</output>\n<label>Speed <select id=\"speed\">";
  for (const char* rate : {"0.25", "0.5", "1", "2", "4"})
    page += std::string("<option value=\"") + rate + "\"" + (std::string_view(rate) == "1" ? " selected" : "") + ">" +
            rate + "x</option>";
  page += "</select></label>\n";
  page +=
      "<button id=\"csv\" type=\"button\" title=\"The motion's table: t and each body's x, y, theta\">"
      "Download CSV</button>\n</div>\n<fieldset id=\"layers\"><legend>Show</legend></fieldset>\n";
  page += "<p id=\"status\">Opening the clip&hellip;</p>\n";
  page += "</div>\n";
  if (!text.equations.empty())  // the report's HTML, escaped by its renderer
    page.append("<details id=\"equations\" open><summary>Equations</summary><div id=\"equations-body\">\n")
        .append(text.equations)
        .append("</div></details>\n");
  page += "</div>\n";
  // Base64 holds no markup: the data cannot end the element early.
  page += "<script id=\"linkage-data\" type=\"application/octet-stream\">\n";
  const std::string packed = base64(gzip(data));
  for (std::size_t i = 0; i < packed.size(); i += 120) page.append(packed, i, 120).append("\n");
  page.append("</script>\n<script>").append(kScript).append("</script>\n</body>\n</html>\n");
  return page;
}

void write_html_page(const PageText& text, const std::string& data, const std::filesystem::path& target,
                     const std::string& setting) {
  write_file_atomically(target, html_page(text, data), setting);
}

}  // namespace linkage
