#include "analysis/replay_html.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>

#include "analysis/xml_escape.hpp"

namespace covsim {

namespace {

void append_point(std::string& out, Vec2 p) {
  fmt::format_to(std::back_inserter(out), "[{:.7g},{:.7g}]", p.x, p.y);
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
  out += "]}";
  return out;
}

constexpr const char* kPage = R"HTML(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>covsim replay</title>
<style>
body {{ font-family: sans-serif; margin: 12px; }}
#controls {{ display: flex; gap: 10px; align-items: center; margin: 8px 0; }}
#slider {{ flex: 1; }}
canvas {{ border: 1px solid #ccc; }}
.key span {{ margin-right: 14px; }}
</style></head><body>
<div id="title"></div>
<div id="controls"><button id="play">play</button><input id="slider" type="range" min="0" value="0">
<span id="time"></span></div>
<canvas id="view" width="800" height="600"></canvas>
<div class="key"><span style="color:#1f3f8f">● robot (path so far)</span><span style="color:#2a8a3a">● virtual generator</span>
<span style="color:#c02020">× virtual target</span><span style="color:#c89000">+ real target</span>
<span style="color:#4060c0">— Voronoi cells of the generators</span></div>
<pre id="status"></pre>
<script>
"use strict";
const D = {data};
const errors = [];
window.addEventListener("error", e => {{ errors.push(String(e.message)); report(); }});
const slider = document.getElementById("slider"), canvas = document.getElementById("view");
const ctx = canvas.getContext("2d"), timeLabel = document.getElementById("time");
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
let drawnCells = 0, drawnRobots = 0, shownFrame = -1;
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
function draw(f) {{
  ctx.fillStyle = "#222"; ctx.fillRect(0, 0, W, H);
  path(D.rings[0], true); ctx.fillStyle = "#fff4c8"; ctx.fill();
  const gens = [];
  for (let i = 0; i < D.robots; i++) {{ const r = robot(f, i); gens.push([r[2], r[3]]); }}
  ctx.save(); path(D.rings[0], true); ctx.clip();
  ctx.strokeStyle = "#4060c0"; ctx.lineWidth = 1.2; drawnCells = 0;
  for (let i = 0; i < D.robots; i++) {{ const c = cell(gens, i); if (c.length >= 3) {{ path(c, true); ctx.stroke(); drawnCells++; }} }}
  ctx.restore();
  for (let h = 1; h < D.rings.length; h++) {{ path(D.rings[h], true); ctx.fillStyle = "#222"; ctx.fill(); }}
  drawnRobots = 0;
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
    drawnRobots++;
  }}
  shownFrame = f;
  timeLabel.textContent = "t = " + D.times[f].toFixed(1) + " s (frame " + (f + 1) + " of " + D.frames.length + ")";
}}
function report() {{
  statusBox.textContent = errors.length > 0 ? "errors: " + errors.join("; ")
    : "selftest ok: frame " + shownFrame + " of " + D.frames.length + ", t=" + D.times[shownFrame] +
      ", robots " + drawnRobots + ", cells " + drawnCells;
}}
slider.addEventListener("input", () => draw(Number(slider.value)));
let timer = null;
document.getElementById("play").addEventListener("click", () => {{
  if (timer) {{ clearInterval(timer); timer = null; return; }}
  if (Number(slider.value) >= D.frames.length - 1) slider.value = "0";
  timer = setInterval(() => {{
    const f = Number(slider.value) + 1;
    if (f >= D.frames.length) {{ clearInterval(timer); timer = null; return; }}
    slider.value = String(f); draw(f);
  }}, 40);
}});
draw(0);
if (location.search.indexOf("selftest") >= 0) {{
  slider.value = String(Math.floor((D.frames.length - 1) / 2));
  slider.dispatchEvent(new Event("input"));
  report();
}}
</script></body></html>
)HTML";

}  // namespace

std::string replay_html(const RunFiles& run, std::size_t max_frames) {
  return fmt::format(kPage,
                     fmt::arg("data", data_literal(run, std::max<std::size_t>(max_frames, 2))));
}

}  // namespace covsim
