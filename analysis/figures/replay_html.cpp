#include "analysis/figures/replay_html.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>

#include "analysis/figures/canvas.hpp"
#include "analysis/figures/map_view.hpp"
#include "analysis/figures/xml_escape.hpp"

namespace covsim {

namespace {

void append_point(std::string& out, Vec2 p) {
  fmt::format_to(std::back_inserter(out), "[{:.7g},{:.7g}]", p.x, p.y);
}

std::string base64(const std::string& bytes) {
  static constexpr char kDigits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::uint32_t acc = 0;
  int bits = 0;
  for (unsigned char c : bytes) {
    acc = (acc << 8) | c;
    bits += 8;
    while (bits >= 6) {
      bits -= 6;
      out += kDigits[(acc >> bits) & 63];
    }
  }
  if (bits > 0) out += kDigits[(acc << (6 - bits)) & 63];
  while (out.size() % 4 != 0)
    out += '=';
  return out;
}

// The density over Ω's box as a PNG data URI in quotes (the same colour map as the
// figures), or null for a uniform density.
std::string density_png(const Scenario& scenario) {
  if (scenario.density->is_uniform()) return "null";
  const Box& b = scenario.environment->bounds();
  const double w = 400, h = std::clamp(400 * b.size().y / b.size().x, 40.0, 1200.0);
  Canvas c(FigureFile{FigureFormat::png, 400}, w, h);
  const MapView view(scenario, {0, 0}, {w, h});
  c.image(view.density_image(), view.to_px({b.lo.x, b.hi.y}), view.to_px({b.hi.x, b.lo.y}));
  return fmt::format("{{\"png\":\"data:image/png;base64,{}\",\"lo\":[{},{}],\"hi\":[{},{}]}}",
                     base64(c.finish()), view.axes().data.lo.x, view.axes().data.lo.y,
                     view.axes().data.hi.x, view.axes().data.hi.y);
}

// The data as a JavaScript object literal: rings, bounds, and frames of
// [x, y, vx, vy, tx, ty, rx, ry] per robot.
std::string data_literal(const RunFiles& run, std::size_t max_frames) {
  const Environment& env = *run.scenario.environment;
  const std::size_t n = run.outcome.robots.size();
  // Group rows into frames by time (rows come in time order).
  std::vector<double> times;
  std::vector<std::vector<TrajectoryRow>> frames;
  std::vector<TrajectoryRow> state(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 s = run.scenario.robot_positions[i];
    state[i] = TrajectoryRow{0.0, static_cast<std::uint32_t>(i), s, s, s, s};
  }
  for (std::size_t k = 0; k < run.trajectory.size();) {
    const double t = run.trajectory[k].t;
    for (; k < run.trajectory.size() && run.trajectory[k].t == t; ++k)
      state[run.trajectory[k].robot] = run.trajectory[k];
    times.push_back(t);
    frames.push_back(state);
  }
  std::string out = "{\"rings\":[";
  for (std::size_t r = 0; r < env.rings().size(); ++r) {
    out += r > 0 ? ",[" : "[";
    for (std::size_t v = 0; v < env.rings()[r].size(); ++v) {
      if (v > 0) out += ",";
      append_point(out, env.rings()[r][v]);
    }
    out += "]";
  }
  const Box& b = env.bounds();
  fmt::format_to(std::back_inserter(out), "],\"lo\":[{},{}],\"hi\":[{},{}],\"robots\":{},", b.lo.x,
                 b.lo.y, b.hi.x, b.hi.y, n);
  fmt::format_to(std::back_inserter(out), "\"title\":\"{}\",\"times\":[",
                 xml_escape(run.scenario.source));
  const std::size_t stride =
      frames.size() <= max_frames ? 1 : (frames.size() + max_frames - 2) / (max_frames - 1);
  std::vector<std::size_t> keep;
  for (std::size_t f = 0; f < frames.size(); f += stride)
    keep.push_back(f);
  if (!frames.empty() && keep.back() != frames.size() - 1) keep.push_back(frames.size() - 1);
  for (std::size_t i = 0; i < keep.size(); ++i)
    fmt::format_to(std::back_inserter(out), "{}{:.7g}", i > 0 ? "," : "", times[keep[i]]);
  out += "],\"frames\":[";
  for (std::size_t i = 0; i < keep.size(); ++i) {
    out += i > 0 ? ",[" : "[";
    const auto& fr = frames[keep[i]];
    for (std::size_t r = 0; r < n; ++r) {
      const TrajectoryRow& s = fr[r];
      fmt::format_to(std::back_inserter(out),
                     "{}{:.7g},{:.7g},{:.7g},{:.7g},{:.7g},{:.7g},{:.7g},{:.7g}", r > 0 ? "," : "",
                     s.position.x, s.position.y, s.virtual_generator.x, s.virtual_generator.y,
                     s.virtual_target.x, s.virtual_target.y, s.real_target.x, s.real_target.y);
    }
    out += "]";
  }
  // The cost series, for the plot under the map.
  out += "],\"cost\":[";
  for (std::size_t i = 0; i < run.samples.size(); ++i)
    fmt::format_to(std::back_inserter(out), "{}[{:.7g},{:.7g},{:.7g}]", i > 0 ? "," : "",
                   run.samples[i].t, run.samples[i].cost_real, run.samples[i].cost_virtual);
  out += "],\"density\":";
  out += density_png(run.scenario);
  out += "}";
  return out;
}

constexpr const char* kPage = R"HTML(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>covsim replay</title>
<style>
body {{ font-family: sans-serif; margin: 12px; }}
#controls {{ display: flex; gap: 8px; align-items: center; margin: 8px 0; }}
#slider {{ flex: 1; }}
canvas {{ border: 1px solid #ccc; display: block; }}
.key span {{ margin-right: 14px; }}
.hint {{ color: #666; font-size: 12px; }}
</style></head><body>
<div id="title"></div>
<div id="controls"><button id="back" title="step back (←)">◀</button>
<button id="play" title="play or pause (space)">play</button>
<button id="forward" title="step forward (→)">▶</button>
<label>speed <select id="speed"><option>0.25</option><option>0.5</option><option selected>1</option>
<option>2</option><option>4</option><option>8</option></select>×</label>
<input id="slider" type="range" min="0" value="0"><span id="time"></span>
<button id="png" title="download the frame as PNG">frame as PNG</button></div>
<canvas id="view" width="800" height="600"></canvas>
<canvas id="cost" width="800" height="170"></canvas>
<div class="key"><span style="color:#1f3f8f">● robot (ID; path so far)</span><span style="color:#2a8a3a">● virtual generator</span>
<span style="color:#c02020">× virtual target</span><span style="color:#c89000">+ real target</span>
<span style="color:#4060c0">— Voronoi cells of the generators</span><span id="densityKey"></span></div>
<div class="hint">keys: space play/pause, ← → step, Home/End first/last frame; the cost plot's line marks the frame's time</div>
<pre id="status"></pre>
<script>
"use strict";
const D = {data};
const errors = [];
window.addEventListener("error", e => {{ errors.push(String(e.message)); report(); }});
const slider = document.getElementById("slider"), canvas = document.getElementById("view");
const ctx = canvas.getContext("2d"), timeLabel = document.getElementById("time");
const costCanvas = document.getElementById("cost"), cctx = costCanvas.getContext("2d");
const statusBox = document.getElementById("status");
document.getElementById("title").textContent = D.title + " — " + D.robots + " robots";
slider.max = String(D.frames.length - 1);
// The canvas takes Ω's aspect ratio (within limits); the drawing is centred in it.
const pad = 20, W = canvas.width, spanX = D.hi[0] - D.lo[0], spanY = D.hi[1] - D.lo[1];
canvas.height = Math.max(300, Math.min(800, Math.round((W - 2 * pad) * spanY / spanX + 2 * pad)));
const H = canvas.height;
const scale = Math.min((W - 2 * pad) / spanX, (H - 2 * pad) / spanY);
const ox = (W - spanX * scale) / 2, oy = (H - spanY * scale) / 2;
const X = x => ox + (x - D.lo[0]) * scale, Y = y => H - oy - (y - D.lo[1]) * scale;
let densityImage = null;
if (D.density) {{
  densityImage = new Image();
  densityImage.onload = () => draw(shownFrame < 0 ? 0 : shownFrame);
  densityImage.src = D.density.png;
  document.getElementById("densityKey").textContent = "shading: density φ (darker: higher)";
}}
let drawnCells = 0, drawnRobots = 0, shownFrame = -1, cursorTime = NaN;
function robot(f, i) {{ const a = D.frames[f], k = 8 * i; return a.slice(k, k + 8); }}
// The Voronoi cell of generator i: the bounding box cut by the bisector half-planes.
function cell(gens, i) {{
  const m = 0.05 * Math.max(D.hi[0] - D.lo[0], D.hi[1] - D.lo[1]);
  let poly = [[D.lo[0] - m, D.lo[1] - m], [D.hi[0] + m, D.lo[1] - m], [D.hi[0] + m, D.hi[1] + m], [D.lo[0] - m, D.hi[1] + m]];
  const g = gens[i];
  for (let j = 0; j < gens.length && poly.length > 0; j++) {{
    const q = gens[j];
    if (j === i || (q[0] === g[0] && q[1] === g[1])) continue;
    const n = [q[0] - g[0], q[1] - g[1]], c = (n[0] * (q[0] + g[0]) + n[1] * (q[1] + g[1])) / 2;
    const out = [];
    for (let k = 0; k < poly.length; k++) {{
      const a = poly[k], b = poly[(k + 1) % poly.length];
      const da = n[0] * a[0] + n[1] * a[1] - c, db = n[0] * b[0] + n[1] * b[1] - c;
      if (da <= 0) out.push(a);
      if ((da < 0 && db > 0) || (da > 0 && db < 0)) {{
        const t = da / (da - db); out.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
      }}
    }}
    poly = out;
  }}
  return poly;
}}
function path(points, close) {{
  ctx.beginPath();
  points.forEach((p, k) => k === 0 ? ctx.moveTo(X(p[0]), Y(p[1])) : ctx.lineTo(X(p[0]), Y(p[1])));
  if (close) ctx.closePath();
}}
// H of the real (solid) and virtual (dashed) generators over time, a line at the frame's time.
function drawCost(t) {{
  const w = costCanvas.width, h = costCanvas.height, l = 60, r = 10, top = 10, b = 26;
  cctx.fillStyle = "#fff"; cctx.fillRect(0, 0, w, h);
  if (D.cost.length === 0) return;
  const t1 = Math.max(D.cost[D.cost.length - 1][0], 1e-9);
  let hmax = 0; D.cost.forEach(c => {{ hmax = Math.max(hmax, c[1], c[2]); }});
  hmax = hmax > 0 ? hmax : 1;
  const cx = x => l + (w - l - r) * x / t1, cy = y => h - b - (h - top - b) * y / hmax;
  cctx.strokeStyle = "#000"; cctx.lineWidth = 1; cctx.strokeRect(l, top, w - l - r, h - top - b);
  cctx.fillStyle = "#222"; cctx.font = "11px sans-serif";
  cctx.fillText("0", l - 12, h - b + 4); cctx.fillText(hmax.toPrecision(3), 4, top + 8);
  cctx.fillText("time [s]", w / 2 - 20, h - 6); cctx.fillText(t1.toFixed(1), w - r - 30, h - b + 14);
  cctx.fillText("cost H", 4, h / 2);
  [[1, "#d62728", []], [2, "#1f5fbf", [6, 4]]].forEach(([k, colour, dash]) => {{
    cctx.strokeStyle = colour; cctx.setLineDash(dash); cctx.lineWidth = 1.5; cctx.beginPath();
    D.cost.forEach((c, i) => i === 0 ? cctx.moveTo(cx(c[0]), cy(c[k])) : cctx.lineTo(cx(c[0]), cy(c[k])));
    cctx.stroke();
  }});
  cctx.setLineDash([]); cctx.strokeStyle = "#000"; cctx.lineWidth = 1; cctx.beginPath();
  cctx.moveTo(cx(t), top); cctx.lineTo(cx(t), h - b); cctx.stroke();
  cursorTime = t;
}}
function draw(f) {{
  ctx.fillStyle = "#444"; ctx.fillRect(0, 0, W, H);
  path(D.rings[0], true); ctx.fillStyle = "#fff"; ctx.fill();
  if (densityImage && densityImage.complete && densityImage.naturalWidth > 0) {{
    ctx.save(); path(D.rings[0], true); ctx.clip();
    ctx.drawImage(densityImage, X(D.density.lo[0]), Y(D.density.hi[1]),
                  X(D.density.hi[0]) - X(D.density.lo[0]), Y(D.density.lo[1]) - Y(D.density.hi[1]));
    ctx.restore();
  }}
  const gens = [];
  for (let i = 0; i < D.robots; i++) {{ const r = robot(f, i); gens.push([r[2], r[3]]); }}
  ctx.save(); path(D.rings[0], true); ctx.clip();
  ctx.strokeStyle = "#4060c0"; ctx.lineWidth = 1.2; drawnCells = 0;
  for (let i = 0; i < D.robots; i++) {{ const c = cell(gens, i); if (c.length >= 3) {{ path(c, true); ctx.stroke(); drawnCells++; }} }}
  ctx.restore();
  for (let h = 1; h < D.rings.length; h++) {{ path(D.rings[h], true); ctx.fillStyle = "#444"; ctx.fill(); }}
  drawnRobots = 0;
  ctx.font = "11px sans-serif";
  for (let i = 0; i < D.robots; i++) {{
    const trail = [];
    for (let k = 0; k <= f; k++) {{ const r = robot(k, i); trail.push([r[0], r[1]]); }}
    ctx.strokeStyle = "rgba(31,63,143,0.5)"; ctx.lineWidth = 1; path(trail, false); ctx.stroke();
    const r = robot(f, i);
    ctx.strokeStyle = "#c02020"; ctx.lineWidth = 1.5; ctx.beginPath();
    ctx.moveTo(X(r[4]) - 5, Y(r[5]) - 5); ctx.lineTo(X(r[4]) + 5, Y(r[5]) + 5);
    ctx.moveTo(X(r[4]) - 5, Y(r[5]) + 5); ctx.lineTo(X(r[4]) + 5, Y(r[5]) - 5); ctx.stroke();
    ctx.strokeStyle = "#c89000"; ctx.beginPath();
    ctx.moveTo(X(r[6]) - 6, Y(r[7])); ctx.lineTo(X(r[6]) + 6, Y(r[7]));
    ctx.moveTo(X(r[6]), Y(r[7]) - 6); ctx.lineTo(X(r[6]), Y(r[7]) + 6); ctx.stroke();
    ctx.fillStyle = "#2a8a3a"; ctx.beginPath(); ctx.arc(X(r[2]), Y(r[3]), 3.5, 0, 2 * Math.PI); ctx.fill();
    ctx.fillStyle = "#1f3f8f"; ctx.beginPath(); ctx.arc(X(r[0]), Y(r[1]), 5, 0, 2 * Math.PI); ctx.fill();
    ctx.fillStyle = "#111"; ctx.fillText(String(i), X(r[0]) + 6, Y(r[1]) - 6);
    drawnRobots++;
  }}
  shownFrame = f;
  slider.value = String(f);
  drawCost(D.times[f]);
  timeLabel.textContent = "t = " + D.times[f].toFixed(1) + " s (frame " + (f + 1) + " of " + D.frames.length + ")";
}}
function report(extra) {{
  statusBox.textContent = errors.length > 0 ? "errors: " + errors.join("; ")
    : "selftest ok: frame " + shownFrame + " of " + D.frames.length + ", t=" + D.times[shownFrame] +
      ", robots " + drawnRobots + ", cells " + drawnCells + ", cost cursor t=" + cursorTime + (extra || "");
}}
const step = d => {{ stop(); draw(Math.max(0, Math.min(D.frames.length - 1, shownFrame + d))); }};
slider.addEventListener("input", () => draw(Number(slider.value)));
let timer = null, budget = 0;
function stop() {{ if (timer) {{ clearInterval(timer); timer = null; }} document.getElementById("play").textContent = "play"; }}
function play() {{
  if (timer) {{ stop(); return; }}
  if (shownFrame >= D.frames.length - 1) draw(0);
  document.getElementById("play").textContent = "pause";
  // 25 frames per second at speed 1; other speeds skip or hold frames.
  timer = setInterval(() => {{
    budget += Number(document.getElementById("speed").value);
    const n = Math.floor(budget); budget -= n;
    if (n === 0) return;
    const f = Math.min(D.frames.length - 1, shownFrame + n);
    draw(f);
    if (f >= D.frames.length - 1) stop();
  }}, 40);
}}
document.getElementById("play").addEventListener("click", play);
document.getElementById("back").addEventListener("click", () => step(-1));
document.getElementById("forward").addEventListener("click", () => step(1));
document.addEventListener("keydown", e => {{
  if (e.target && e.target.tagName === "SELECT") return;
  if (e.key === " ") {{ play(); e.preventDefault(); }}
  else if (e.key === "ArrowRight") {{ step(1); e.preventDefault(); }}
  else if (e.key === "ArrowLeft") {{ step(-1); e.preventDefault(); }}
  else if (e.key === "Home") {{ stop(); draw(0); }}
  else if (e.key === "End") {{ stop(); draw(D.frames.length - 1); }}
}});
document.getElementById("png").addEventListener("click", () => {{
  const a = document.createElement("a");
  a.href = canvas.toDataURL("image/png");
  a.download = D.title.replace(/^.*[\\/]/, "").replace(/\.json$/, "") + "-frame-" + shownFrame + ".png";
  a.click();
}});
draw(0);
if (location.search.indexOf("selftest") >= 0) {{
  slider.value = String(Math.floor((D.frames.length - 1) / 2));
  slider.dispatchEvent(new Event("input"));
  // The keys step one frame and back; the PNG of the frame is a PNG.
  const at = shownFrame;
  document.dispatchEvent(new KeyboardEvent("keydown", {{ key: "ArrowRight" }}));
  const forward = shownFrame;
  document.dispatchEvent(new KeyboardEvent("keydown", {{ key: "ArrowLeft" }}));
  const keys = forward === at + 1 && shownFrame === at ? ", keys ok" : ", keys failed";
  const png = canvas.toDataURL("image/png").startsWith("data:image/png") ? ", png ok" : ", png failed";
  report(keys + png);
}}
</script></body></html>
)HTML";

}  // namespace

std::string replay_html(const RunFiles& run, std::size_t max_frames) {
  return fmt::format(kPage,
                     fmt::arg("data", data_literal(run, std::max<std::size_t>(max_frames, 2))));
}

}  // namespace covsim
