#include "analysis/figures/replay_html.hpp"
#include "analysis/figures/html_escape.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string_view>

#include "analysis/figures/canvas.hpp"
#include "analysis/figures/figures.hpp"
#include "analysis/figures/map_view.hpp"
#include "analysis/figures/robot_palette.hpp"
#include "analysis/records/measure.hpp"

namespace covsim {

namespace {

// A JSON string that is safe inside <script>: "</script>" cannot end it early.
std::string script_string(const std::string& s) {
  std::string out = nlohmann::json(s).dump();
  for (std::size_t at = out.find("</"); at != std::string::npos; at = out.find("</", at + 3))
    out.replace(at, 2, "<\\/");
  return out;
}

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
std::string data_literal(const RunFiles& run, std::size_t max_frames,
                         std::optional<std::uint32_t> planner_robot) {
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
  fmt::format_to(std::back_inserter(out),
                 "],\"lo\":[{},{}],\"hi\":[{},{}],\"robots\":{},\"radius\":{},", b.lo.x, b.lo.y,
                 b.hi.x, b.hi.y, n, run.scenario.coverage.radius);
  fmt::format_to(std::back_inserter(out), "\"title\":{},\"cost_unit\":{},\"colours\":[",
                 script_string(scenario_name(run.scenario.source)), script_string(kCostUnit));
  // Each robot's colour, and the first three for the key's path (however many robots).
  for (std::size_t i = 0; i < n; ++i)
    fmt::format_to(std::back_inserter(out), "{}\"{}\"", i > 0 ? "," : "",
                   colour_hex(robot_colour(i)));
  fmt::format_to(std::back_inserter(out), "],\"key_colours\":[\"{}\",\"{}\",\"{}\"]",
                 colour_hex(robot_colour(0)), colour_hex(robot_colour(1)),
                 colour_hex(robot_colour(2)));
  // Robots that mapped Ω: the map's cells and when they became known (-1: never), shaded
  // while not yet known.
  fmt::format_to(std::back_inserter(out), ",\"map\":{{\"size\":{},\"cells\":[", run.known.size);
  for (std::size_t k = 0; k < run.known.cells.size(); ++k) {
    const KnownCell& c = run.known.cells[k];
    fmt::format_to(std::back_inserter(out), "{}{},{},{}", k > 0 ? "," : "", c.centre.x, c.centre.y,
                   std::isinf(c.since) ? -1.0 : c.since);
  }
  out += "]}";
  // Planners with maps of their own: walls as [t, robot (-1: shared), x0, y0, x1, y1] and
  // ways as [t, robot, [x, y, ...]], in time order.
  const PlannerMapRecord& pm = run.planner_maps;
  fmt::format_to(std::back_inserter(out), ",\"planner\":{{\"robot\":{},\"walls\":[",
                 planner_robot && !pm.empty() ? static_cast<long>(*planner_robot) : -1L);
  for (std::size_t k = 0; k < pm.walls.size(); ++k) {
    const auto& w = pm.walls[k];
    fmt::format_to(std::back_inserter(out), "{}{:.7g},{},{:.7g},{:.7g},{:.7g},{:.7g}",
                   k > 0 ? "," : "", w.t, w.robot ? static_cast<long>(*w.robot) : -1L, w.a.x, w.a.y,
                   w.b.x, w.b.y);
  }
  out += "],\"ways\":[";
  for (std::size_t k = 0; k < pm.ways.size(); ++k) {
    const auto& w = pm.ways[k];
    fmt::format_to(std::back_inserter(out), "{}[{:.7g},{},[", k > 0 ? "," : "", w.t, w.robot);
    for (std::size_t j = 0; j < w.points.size(); ++j)
      fmt::format_to(std::back_inserter(out), "{}{:.7g},{:.7g}", j > 0 ? "," : "", w.points[j].x,
                     w.points[j].y);
    out += "]]";
  }
  out += "]}";
  out += ",\"times\":[";
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

constexpr std::string_view kPage = R"HTML(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>@TITLE@ — covsim replay</title>
<style>
* { box-sizing: border-box; }
html, body { margin: 0; }
body { font-family: "DejaVu Sans", sans-serif; font-size: 13px; color: #222; padding: 8px 12px; }
header { display: flex; align-items: baseline; gap: 14px; flex-wrap: wrap; }
h1 { font-size: 18px; margin: 0 0 6px 0; font-weight: 600; }
#controls { display: flex; gap: 8px; align-items: center; margin: 0 0 8px 0; }
#slider { flex: 1; min-width: 120px; }
#time { min-width: 16em; font-variant-numeric: tabular-nums; }
main { display: flex; gap: 14px; align-items: flex-start; }
#side { flex: 1 1 0; min-width: 0; }
canvas { display: block; }
#view, #cost, #key { border: 1px solid #ccc; }
aside > * { margin: 0 0 10px 0; }
.hint { color: #666; font-size: 12px; }
#status { font-size: 11px; color: #666; white-space: pre-wrap; }
@media (max-width: 860px) { main { flex-direction: column; } #side { width: 100%; } }
</style></head><body>
<header><h1 id="title">@TITLE@</h1><span class="hint" id="subtitle"></span></header>
<div id="controls"><button id="back" title="step back (←)">◀</button>
<button id="play" title="play or pause (space)">play</button>
<button id="forward" title="step forward (→)">▶</button>
<label>speed <select id="speed"><option>0.25</option><option>0.5</option><option selected>1</option>
<option>2</option><option>4</option><option>8</option></select>×</label>
<input id="slider" type="range" min="0" value="0"><span id="time"></span>
<label id="plannerBox" hidden>planner map of <select id="plannerRobot"><option value="-1">no robot</option></select></label>
<button id="png" title="download the frame as PNG">frame as PNG</button></div>
<main id="main"><div id="mapBox"><canvas id="view"></canvas></div>
<aside id="side"><canvas id="cost"></canvas><canvas id="key"></canvas>
<div class="hint" id="hint">keys: space play/pause, ← → step, Home/End first/last frame. The cost plot's
line marks the frame's time; the address ends in #t=SECONDS, which opens the page at that time.</div>
<pre id="status"></pre></aside></main>
<script>
"use strict";
const D = @DATA@;
const errors = [];
window.addEventListener("error", e => { errors.push(String(e.message)); report(); });
const $ = id => document.getElementById(id);
const slider = $("slider"), canvas = $("view"), ctx = canvas.getContext("2d");
const costCanvas = $("cost"), cctx = costCanvas.getContext("2d");
const keyCanvas = $("key"), kctx = keyCanvas.getContext("2d");
const statusBox = $("status"), timeLabel = $("time");
const INK = "#222222", OBSTACLE = "#4a4a4a", CELLS = "#1f5fbf", PROJECTED = "#ffd21f", UNKNOWN = "rgba(107, 122, 153, 0.45)";
const PLANNER_WALL = "#d95f02";
// Planners with maps of their own: a menu of the robots whose map can be shown.
const plannerMaps = D.planner.walls.length > 0 || D.planner.ways.length > 0;
const plannerRobot = $("plannerRobot");
if (plannerMaps) {
  for (let i = 0; i < D.robots; i++) { const o = document.createElement("option"); o.value = String(i); o.textContent = "robot " + i; plannerRobot.appendChild(o); }
  plannerRobot.value = String(D.planner.robot);
  $("plannerBox").hidden = false;
}
let drawnPlannerWalls = 0, drawnPlannerWay = 0;
const FONT = "12px 'DejaVu Sans', sans-serif";
$("subtitle").textContent = D.robots + (D.robots === 1 ? " robot, " : " robots, ") + D.frames.length + " frames to t = " +
  D.times[D.times.length - 1].toFixed(1) + " s";
slider.max = String(D.frames.length - 1);
const dpr = window.devicePixelRatio || 1;
// The map shows Ω's box padded by 3%, as the figures do, with room for its axes around it.
const spanX = D.hi[0] - D.lo[0], spanY = D.hi[1] - D.lo[1];
const box = { lo: [D.lo[0] - 0.03 * spanX, D.lo[1] - 0.03 * spanY],
              hi: [D.hi[0] + 0.03 * spanX, D.hi[1] + 0.03 * spanY] };
const room = { l: 54, r: 12, t: 10, b: 42 };
let W = 0, H = 0, scale = 1;
const X = x => room.l + (x - box.lo[0]) * scale, Y = y => room.t + (box.hi[1] - y) * scale;
function sized(c, w, h) {
  c.style.width = w + "px"; c.style.height = h + "px";
  c.width = Math.round(w * dpr); c.height = Math.round(h * dpr);
  c.getContext("2d").setTransform(dpr, 0, 0, dpr, 0, 0);
}
// The map takes the window's height and leaves the side panel at least 300 px (on a narrow
// window the panel goes under it); the panel takes the rest of the width, and its cost plot
// the height the key and the hint leave beside the map, so nothing needs scrolling.
const SIDE_LEAST = 300, GAP = 14;
function layout() {
  const main = $("main").getBoundingClientRect(), narrow = window.innerWidth <= 860;
  const maxW = Math.max(240, (narrow ? main.width : main.width - GAP - SIDE_LEAST) - 2);
  const maxH = Math.max(240, window.innerHeight - main.top - GAP);
  const bw = box.hi[0] - box.lo[0], bh = box.hi[1] - box.lo[1];
  scale = Math.min((maxW - room.l - room.r) / bw, (maxH - room.t - room.b) / bh);
  W = Math.round(bw * scale + room.l + room.r); H = Math.round(bh * scale + room.t + room.b);
  sized(canvas, W, H);
  const side = Math.floor(narrow ? main.width : main.width - W - 2 - GAP) - 2;
  sized(keyCanvas, side, keyHeight(side));
  drawKey(side);
  // Beside the map: the height the key, the hint and their margins leave.
  const hint = $("hint").getBoundingClientRect().height;
  const rest = narrow ? 0.6 * side : H - keyHeight(side) - hint - 3 * 10 - 6;
  sized(costCanvas, side, Math.round(Math.max(170, Math.min(0.8 * side, rest))));
}
let densityImage = null;
if (D.density) {
  densityImage = new Image();
  densityImage.onload = () => { draw(shownFrame < 0 ? 0 : shownFrame); drawKey(keyWidth); };
  densityImage.src = D.density.png;
}
let drawnCells = 0, drawnRobots = 0, shownFrame = -1, cursorTime = NaN, keyWidth = 0;
function robot(f, i) { const a = D.frames[f], k = 8 * i; return a.slice(k, k + 8); }
// Ticks of 1, 2 or 5 times a power of ten, about n over [lo, hi].
function tickStep(range, n) {
  const raw = range / n, p = Math.pow(10, Math.floor(Math.log10(raw)));
  for (const m of [1, 2, 5]) if (m * p >= raw) return m * p;
  return 10 * p;
}
function ticks(lo, hi, n) {
  const s = tickStep(hi - lo, n), out = [], digits = Math.max(0, -Math.floor(Math.log10(s) + 1e-9));
  for (let v = Math.ceil(lo / s - 1e-9) * s; v <= hi + 1e-9 * s; v += s)
    out.push([v, (Math.abs(v) < 1e-9 * s ? 0 : v).toFixed(digits)]);
  return out;
}
// The Voronoi cell of generator i: the bounding box cut by the bisector half-planes.
function cell(gens, i) {
  const m = 0.05 * Math.max(spanX, spanY);
  let poly = [[D.lo[0] - m, D.lo[1] - m], [D.hi[0] + m, D.lo[1] - m], [D.hi[0] + m, D.hi[1] + m], [D.lo[0] - m, D.hi[1] + m]];
  const g = gens[i];
  for (let j = 0; j < gens.length && poly.length > 0; j++) {
    const q = gens[j];
    if (j === i || (q[0] === g[0] && q[1] === g[1])) continue;
    const n = [q[0] - g[0], q[1] - g[1]], c = (n[0] * (q[0] + g[0]) + n[1] * (q[1] + g[1])) / 2;
    const out = [];
    for (let k = 0; k < poly.length; k++) {
      const a = poly[k], b = poly[(k + 1) % poly.length];
      const da = n[0] * a[0] + n[1] * a[1] - c, db = n[0] * b[0] + n[1] * b[1] - c;
      if (da <= 0) out.push(a);
      if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
        const t = da / (da - db); out.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
      }
    }
    poly = out;
  }
  return poly;
}
function path(g, points, close) {
  points.forEach((p, k) => k === 0 ? g.moveTo(X(p[0]), Y(p[1])) : g.lineTo(X(p[0]), Y(p[1])));
  if (close) g.closePath();
}
function omega(g) { g.beginPath(); D.rings.forEach(r => path(g, r, true)); }
// The marks, as the figures draw them; the key draws the same ones.
function cross(g, x, y, h) {
  g.beginPath(); g.moveTo(x - h, y - h); g.lineTo(x + h, y + h); g.moveTo(x - h, y + h); g.lineTo(x + h, y - h); g.stroke();
}
const mark = {
  path(g, x0, y, x1, colour) { g.strokeStyle = colour; g.lineWidth = 1.8; g.setLineDash([]); g.beginPath(); g.moveTo(x0, y); g.lineTo(x1, y); g.stroke(); },
  start(g, x, y, colour) { g.beginPath(); g.arc(x, y, 4.5, 0, 2 * Math.PI); g.fillStyle = "#fff"; g.fill(); g.strokeStyle = colour; g.lineWidth = 1.5; g.stroke(); },
  robot(g, x, y, colour) { g.beginPath(); g.arc(x, y, 5.5, 0, 2 * Math.PI); g.fillStyle = colour; g.fill(); g.strokeStyle = "#fff"; g.lineWidth = 1.2; g.stroke(); },
  // A body to scale (radius in px), translucent with a solid rim; the mark when it is smaller.
  body(g, x, y, r, colour) {
    if (r <= 5.5) { mark.robot(g, x, y, colour); return; }
    g.beginPath(); g.arc(x, y, r, 0, 2 * Math.PI); g.globalAlpha = 0.35; g.fillStyle = colour; g.fill();
    g.globalAlpha = 1; g.strokeStyle = colour; g.lineWidth = 1.6; g.stroke();
    g.beginPath(); g.arc(x, y, 2.2, 0, 2 * Math.PI); g.fill();
  },
  generator(g, x, y, colour) { g.fillStyle = colour; g.fillRect(x - 3, y - 3, 6, 6); g.strokeStyle = "#fff"; g.lineWidth = 0.8; g.strokeRect(x - 3, y - 3, 6, 6); },
  target(g, x, y) { g.strokeStyle = INK; g.lineWidth = 1.5; cross(g, x, y, 4.5); },
  projected(g, x, y) { g.strokeStyle = "#000"; g.lineWidth = 4; cross(g, x, y, 6.5); g.strokeStyle = PROJECTED; g.lineWidth = 2; cross(g, x, y, 6.5); },
  cells(g, x0, y, x1) { g.strokeStyle = CELLS; g.lineWidth = 1.3; g.beginPath(); g.moveTo(x0, y); g.lineTo(x1, y); g.stroke(); },
  plannerWall(g, x0, y0, x1, y1) { g.strokeStyle = PLANNER_WALL; g.lineWidth = 1.8; g.setLineDash([]); g.beginPath(); g.moveTo(x0, y0); g.lineTo(x1, y1); g.stroke(); },
  plannerWay(g, points, colour) { g.strokeStyle = colour; g.lineWidth = 1.4; g.setLineDash([4, 3]); g.beginPath(); points.forEach((p, k) => k === 0 ? g.moveTo(p[0], p[1]) : g.lineTo(p[0], p[1])); g.stroke(); g.setLineDash([]); },
};
const keyRows = [
  ["robot path (colour per robot)", (g, x, y) => [0, 1, 2].forEach(k => mark.path(g, x - 11 + 8 * k, y, x - 5 + 8 * k, D.key_colours[k]))],
  ["start", (g, x, y) => mark.start(g, x, y, D.key_colours[0])],
  ["robot (ID)", (g, x, y) => mark.robot(g, x, y, D.key_colours[0])],
  ["virtual generator", (g, x, y) => mark.generator(g, x, y, D.key_colours[0])],
  ["virtual target", (g, x, y) => mark.target(g, x, y)],
  ["projected target", (g, x, y) => mark.projected(g, x, y)],
  ["virtual partition", (g, x, y) => mark.cells(g, x - 11, y, x + 11)],
  ["obstacle", (g, x, y) => { g.fillStyle = OBSTACLE; g.fillRect(x - 10, y - 6, 20, 12); }],
  ...(plannerMaps ? [["walls the planner's map held", (g, x, y) => mark.plannerWall(g, x - 11, y, x + 11, y)],
                     ["the planner's way ahead", (g, x, y) => mark.plannerWay(g, [[x - 11, y], [x + 11, y]], D.key_colours[0])]] : []),
  [D.density ? "density φ (darker: higher)" : "uniform density φ", (g, x, y) => {
    if (densityImage && densityImage.complete && densityImage.naturalWidth > 0) g.drawImage(densityImage, x - 10, y - 6, 20, 12);
    else { g.fillStyle = "#fff"; g.fillRect(x - 10, y - 6, 20, 12); }
    g.strokeStyle = INK; g.lineWidth = 0.8; g.strokeRect(x - 10, y - 6, 20, 12);
  }],
];
const keyColumns = w => (w >= 380 ? 2 : 1), keyRow = 21;
function keyHeight(w) { return Math.ceil(keyRows.length / keyColumns(w)) * keyRow + 10; }
function drawKey(w) {
  keyWidth = w;
  const n = keyColumns(w), colW = (w - 8) / n;
  kctx.fillStyle = "#fff"; kctx.fillRect(0, 0, w, keyHeight(w));
  kctx.font = FONT; kctx.textBaseline = "middle";
  keyRows.forEach(([label, symbol], k) => {
    const x = 6 + colW * (k % n), y = 5 + keyRow * (Math.floor(k / n) + 0.5);
    symbol(kctx, x + 14, y);
    kctx.fillStyle = INK; kctx.fillText(label, x + 32, y);
  });
}
// Ticks and labels in metres around the map, and a scale bar in its bottom left corner.
function drawAxes() {
  const x0 = X(box.lo[0]), x1 = X(box.hi[0]), y0 = Y(box.hi[1]), y1 = Y(box.lo[1]);
  ctx.strokeStyle = INK; ctx.fillStyle = INK; ctx.lineWidth = 1; ctx.setLineDash([]);
  ctx.strokeRect(x0, y0, x1 - x0, y1 - y0);
  ctx.font = FONT; ctx.textAlign = "center"; ctx.textBaseline = "top";
  ticks(box.lo[0], box.hi[0], 8).forEach(([v, s]) => {
    ctx.beginPath(); ctx.moveTo(X(v), y1); ctx.lineTo(X(v), y1 + 4); ctx.stroke(); ctx.fillText(s, X(v), y1 + 6);
  });
  ctx.fillText("x [m]", (x0 + x1) / 2, y1 + 22);
  ctx.textAlign = "right"; ctx.textBaseline = "middle";
  ticks(box.lo[1], box.hi[1], 6).forEach(([v, s]) => {
    ctx.beginPath(); ctx.moveTo(x0, Y(v)); ctx.lineTo(x0 - 4, Y(v)); ctx.stroke(); ctx.fillText(s, x0 - 6, Y(v));
  });
  ctx.save(); ctx.translate(12, (y0 + y1) / 2); ctx.rotate(-Math.PI / 2);
  ctx.textAlign = "center"; ctx.fillText("y [m]", 0, 0); ctx.restore();
  const len = tickStep(spanX, 5), sx = x0 + 12, sy = y1 - 12, ex = sx + len * scale;
  ctx.fillStyle = "rgba(255,255,255,0.85)"; ctx.fillRect(sx - 5, sy - 19, ex - sx + 10, 25);
  ctx.strokeStyle = "#000"; ctx.lineWidth = 2; ctx.beginPath(); ctx.moveTo(sx, sy); ctx.lineTo(ex, sy); ctx.stroke();
  ctx.lineWidth = 1; ctx.beginPath(); ctx.moveTo(sx, sy - 4); ctx.lineTo(sx, sy + 4); ctx.moveTo(ex, sy - 4); ctx.lineTo(ex, sy + 4); ctx.stroke();
  ctx.fillStyle = "#000"; ctx.textAlign = "center"; ctx.textBaseline = "bottom";
  ctx.fillText(String(len) + " m", (sx + ex) / 2, sy - 4);
}
// H of the real (solid) and virtual (dashed) generators over time, a line at the frame's time.
function drawCost(t) {
  const w = parseFloat(costCanvas.style.width), h = parseFloat(costCanvas.style.height);
  const l = 62, r = 12, top = 12, b = 38;
  cctx.fillStyle = "#fff"; cctx.fillRect(0, 0, w, h);
  cctx.font = FONT; cctx.fillStyle = INK; cctx.strokeStyle = INK; cctx.lineWidth = 1; cctx.setLineDash([]);
  if (D.cost.length === 0) return;
  const t1 = Math.max(D.cost[D.cost.length - 1][0], 1e-9);
  let hmax = 0; D.cost.forEach(c => { hmax = Math.max(hmax, c[1], c[2]); });
  hmax = hmax > 0 ? hmax : 1;
  const yt = ticks(0, hmax, 4), ytop = Math.max(hmax, yt[yt.length - 1][0]);
  const cx = x => l + (w - l - r) * x / t1, cy = y => h - b - (h - top - b) * y / ytop;
  cctx.strokeRect(l, top, w - l - r, h - top - b);
  cctx.textAlign = "right"; cctx.textBaseline = "middle";
  yt.forEach(([v, s]) => { cctx.beginPath(); cctx.moveTo(l - 4, cy(v)); cctx.lineTo(l, cy(v)); cctx.stroke(); cctx.fillText(s, l - 6, cy(v)); });
  cctx.textAlign = "center"; cctx.textBaseline = "top";
  ticks(0, t1, 5).forEach(([v, s]) => { cctx.beginPath(); cctx.moveTo(cx(v), h - b); cctx.lineTo(cx(v), h - b + 4); cctx.stroke(); cctx.fillText(s, cx(v), h - b + 6); });
  cctx.fillText("time [s]", l + (w - l - r) / 2, h - b + 21);
  cctx.save(); cctx.translate(11, top + (h - top - b) / 2); cctx.rotate(-Math.PI / 2);
  cctx.textBaseline = "middle"; cctx.fillText("cost H [" + D.cost_unit + "]", 0, 0); cctx.restore();
  const series = [[1, "#d62728", [], "H real"], [2, "#1f5fbf", [6, 4], "H virtual"]];
  series.forEach(([k, colour, dash]) => {
    cctx.strokeStyle = colour; cctx.setLineDash(dash); cctx.lineWidth = 1.6; cctx.beginPath();
    D.cost.forEach((c, i) => i === 0 ? cctx.moveTo(cx(c[0]), cy(c[k])) : cctx.lineTo(cx(c[0]), cy(c[k])));
    cctx.stroke();
  });
  cctx.textAlign = "left"; cctx.textBaseline = "middle";
  series.forEach(([k, colour, dash, label], n) => {
    const x = w - r - 100, y = top + 12 + 16 * n;
    cctx.strokeStyle = colour; cctx.setLineDash(dash); cctx.lineWidth = 1.6;
    cctx.beginPath(); cctx.moveTo(x, y); cctx.lineTo(x + 24, y); cctx.stroke();
    cctx.fillStyle = INK; cctx.fillText(label, x + 30, y);
  });
  cctx.setLineDash([]); cctx.strokeStyle = "#000"; cctx.lineWidth = 1; cctx.beginPath();
  cctx.moveTo(cx(t), top); cctx.lineTo(cx(t), h - b); cctx.stroke();
  cursorTime = t;
}
function draw(f) {
  ctx.fillStyle = "#fff"; ctx.fillRect(0, 0, W, H);
  const x0 = X(box.lo[0]), x1 = X(box.hi[0]), y0 = Y(box.hi[1]), y1 = Y(box.lo[1]);
  ctx.save(); ctx.beginPath(); ctx.rect(x0, y0, x1 - x0, y1 - y0); ctx.clip();
  ctx.fillStyle = OBSTACLE; ctx.fillRect(x0, y0, x1 - x0, y1 - y0);
  omega(ctx); ctx.fillStyle = "#fff"; ctx.fill("evenodd");
  ctx.save(); omega(ctx); ctx.clip("evenodd");
  if (densityImage && densityImage.complete && densityImage.naturalWidth > 0)
    ctx.drawImage(densityImage, X(D.density.lo[0]), Y(D.density.hi[1]),
                  X(D.density.hi[0]) - X(D.density.lo[0]), Y(D.density.lo[1]) - Y(D.density.hi[1]));
  // What the maps did not hold yet at this frame's time.
  ctx.fillStyle = UNKNOWN;
  const half = D.map.size / 2, mc = D.map.cells;
  for (let k = 0; k < mc.length; k += 3)
    if (mc[k + 2] < 0 || mc[k + 2] > D.times[f])
      ctx.fillRect(X(mc[k] - half), Y(mc[k + 1] + half), X(mc[k] + half) - X(mc[k] - half), Y(mc[k + 1] - half) - Y(mc[k + 1] + half));
  const gens = [];
  for (let i = 0; i < D.robots; i++) { const r = robot(f, i); gens.push([r[2], r[3]]); }
  ctx.strokeStyle = CELLS; ctx.lineWidth = 1.3; ctx.setLineDash([]); drawnCells = 0;
  for (let i = 0; i < D.robots; i++) { const c = cell(gens, i); if (c.length >= 3) { ctx.beginPath(); path(ctx, c, true); ctx.stroke(); drawnCells++; } }
  ctx.restore();
  omega(ctx); ctx.strokeStyle = "#000"; ctx.lineWidth = 1; ctx.stroke();
  ctx.restore();
  // Trails above the obstacles, as in the figures: a walk along a wall lies on ∂Ω.
  drawnRobots = 0;
  for (let i = 0; i < D.robots; i++) {
    const trail = [];
    for (let k = 0; k <= f; k++) { const r = robot(k, i); trail.push([r[0], r[1]]); }
    ctx.strokeStyle = D.colours[i]; ctx.globalAlpha = 0.85; ctx.lineWidth = 1.6; ctx.setLineDash([]);
    ctx.beginPath(); path(ctx, trail, false); ctx.stroke(); ctx.globalAlpha = 1;
    const s = robot(0, i);
    mark.start(ctx, X(s[0]), Y(s[1]), D.colours[i]);
  }
  // The chosen robot's planner: the walls its map held by now and the way it had ahead.
  drawnPlannerWalls = 0; drawnPlannerWay = 0;
  const sel = plannerMaps ? Number(plannerRobot.value) : -1;
  if (sel >= 0) {
    const w = D.planner.walls, now = D.times[f];
    for (let k = 0; k < w.length && w[k] <= now; k += 6)
      if (w[k + 1] === -1 || w[k + 1] === sel) { mark.plannerWall(ctx, X(w[k + 2]), Y(w[k + 3]), X(w[k + 4]), Y(w[k + 5])); drawnPlannerWalls++; }
    let way = null;
    for (const [t, r, pts] of D.planner.ways) { if (t > now) break; if (r === sel) way = pts; }
    if (way && way.length >= 4) {
      const pts = [];
      for (let k = 0; k < way.length; k += 2) pts.push([X(way[k]), Y(way[k + 1])]);
      mark.plannerWay(ctx, pts, D.colours[sel]); drawnPlannerWay = pts.length - 1;
    }
  }
  ctx.font = FONT; ctx.textAlign = "left"; ctx.textBaseline = "alphabetic";
  for (let i = 0; i < D.robots; i++) {
    const r = robot(f, i);
    mark.target(ctx, X(r[4]), Y(r[5]));
    mark.generator(ctx, X(r[2]), Y(r[3]), D.colours[i]);
    if (r[6] !== r[4] || r[7] !== r[5]) mark.projected(ctx, X(r[6]), Y(r[7]));
    mark.body(ctx, X(r[0]), Y(r[1]), D.radius * scale, D.colours[i]);
    ctx.fillStyle = INK; ctx.fillText(String(i), X(r[0]) + 7, Y(r[1]) - 7);
    drawnRobots++;
  }
  drawAxes();
  shownFrame = f;
  slider.value = String(f);
  drawCost(D.times[f]);
  timeLabel.textContent = "t = " + D.times[f].toFixed(1) + " s (frame " + (f + 1) + " of " + D.frames.length + ")";
}
// The frame whose time is nearest t.
function frameAt(t) {
  let lo = 0, hi = D.times.length - 1;
  while (lo < hi) { const mid = (lo + hi) >> 1; if (D.times[mid] < t) lo = mid + 1; else hi = mid; }
  if (lo > 0 && Math.abs(D.times[lo - 1] - t) <= Math.abs(D.times[lo] - t)) lo--;
  return lo;
}
function hashTime() {
  const m = /^#(?:.*&)?t=([-+0-9.eE]+)/.exec(location.hash), t = m ? Number(m[1]) : NaN;
  return Number.isFinite(t) ? t : null;
}
// The address says the frame's time (not while playing: browsers limit how often a page may
// rewrite its address).
function remember() {
  const hash = "#t=" + D.times[shownFrame];
  if (location.hash === hash) return;
  try { history.replaceState(null, "", hash); } catch (e) { location.replace(hash); }
}
function show(f) { draw(Math.max(0, Math.min(D.frames.length - 1, f))); remember(); }
function report(extra) {
  statusBox.textContent = errors.length > 0 ? "errors: " + errors.join("; ")
    : "selftest ok: frame " + shownFrame + " of " + D.frames.length + ", t=" + D.times[shownFrame] +
      ", robots " + drawnRobots + ", cells " + drawnCells + ", cost cursor t=" + cursorTime +
      (plannerMaps ? ", planner map of robot " + plannerRobot.value + ": walls " + drawnPlannerWalls + ", way legs " + drawnPlannerWay : "") + (extra || "");
}
const step = d => { stop(); show(shownFrame + d); };
slider.addEventListener("input", () => show(Number(slider.value)));
plannerRobot.addEventListener("change", () => { draw(shownFrame); report(); });
let timer = null, budget = 0;
function stop() {
  if (timer) { clearInterval(timer); timer = null; remember(); }
  $("play").textContent = "play";
}
function play() {
  if (timer) { stop(); return; }
  if (shownFrame >= D.frames.length - 1) draw(0);
  $("play").textContent = "pause";
  // 25 frames per second at speed 1; other speeds skip or hold frames.
  timer = setInterval(() => {
    budget += Number($("speed").value);
    const n = Math.floor(budget); budget -= n;
    if (n === 0) return;
    const f = Math.min(D.frames.length - 1, shownFrame + n);
    draw(f);
    if (f >= D.frames.length - 1) stop();
  }, 40);
}
$("play").addEventListener("click", play);
$("back").addEventListener("click", () => step(-1));
$("forward").addEventListener("click", () => step(1));
document.addEventListener("keydown", e => {
  if (e.target && e.target.tagName === "SELECT") return;
  if (e.key === " ") { play(); e.preventDefault(); }
  else if (e.key === "ArrowRight") { step(1); e.preventDefault(); }
  else if (e.key === "ArrowLeft") { step(-1); e.preventDefault(); }
  else if (e.key === "Home") { stop(); show(0); }
  else if (e.key === "End") { stop(); show(D.frames.length - 1); }
});
window.addEventListener("hashchange", () => { const t = hashTime(); if (t !== null) { stop(); draw(frameAt(t)); } });
window.addEventListener("resize", () => { layout(); draw(shownFrame); });
$("png").addEventListener("click", () => {
  const a = document.createElement("a");
  a.href = canvas.toDataURL("image/png");
  a.download = D.title + "-t" + D.times[shownFrame] + ".png";
  a.click();
});
layout();
draw(hashTime() === null ? 0 : frameAt(hashTime()));
if (location.search.indexOf("selftest") >= 0) {
  // Opened at the address's time, if it gave one.
  const opened = ", opened t=" + D.times[shownFrame] +
    (plannerMaps ? ", planner walls at open " + drawnPlannerWalls : "");
  slider.value = String(Math.floor((D.frames.length - 1) / 2));
  slider.dispatchEvent(new Event("input"));
  // The keys step one frame and back; the PNG of the frame is a PNG.
  const at = shownFrame;
  document.dispatchEvent(new KeyboardEvent("keydown", { key: "ArrowRight" }));
  const forward = shownFrame;
  document.dispatchEvent(new KeyboardEvent("keydown", { key: "ArrowLeft" }));
  const keys = forward === at + 1 && shownFrame === at ? ", keys ok" : ", keys failed";
  const png = canvas.toDataURL("image/png").startsWith("data:image/png") ? ", png ok" : ", png failed";
  // Each robot's colour as drawn: the pixel at its centre.
  const seen = new Set(), hex = v => v.toString(16).padStart(2, "0");
  for (let i = 0; i < D.robots; i++) {
    const r = robot(shownFrame, i), p = ctx.getImageData(Math.round(X(r[0]) * dpr), Math.round(Y(r[1]) * dpr), 1, 1).data;
    seen.add("#" + hex(p[0]) + hex(p[1]) + hex(p[2]));
  }
  // Where the cost plot and the map lie in the window.
  const rect = e => { const b = e.getBoundingClientRect(); return Math.round(b.left) + "," + Math.round(b.top) + "," + Math.round(b.right) + "," + Math.round(b.bottom); };
  const inView = e => { const b = e.getBoundingClientRect(); return b.left >= 0 && b.top >= 0 && b.right <= window.innerWidth && b.bottom <= window.innerHeight; };
  report(opened + keys + png + ", url " + location.hash + ", robot colours " + seen.size + " of " + D.robots + " (" + [...seen].join(" ") + ")" +
    ", window " + window.innerWidth + "x" + window.innerHeight +
    ", cost plot " + (inView(costCanvas) ? "in view" : "out of view") + " at " + rect(costCanvas) +
    ", map " + (inView(canvas) ? "in view" : "out of view") + " at " + rect(canvas) + ", title " + document.title);
  // A new address (as a user types or follows one) moves to its time; the page's own
  // listener runs first.
  window.addEventListener("hashchange", () => {
    statusBox.textContent += ", address t=5 showed t=" + D.times[shownFrame];
  }, { once: true });
  location.hash = "#t=5";
}
</script></body></html>
)HTML";

}  // namespace

std::string replay_html(const RunFiles& run, std::size_t max_frames,
                        std::optional<std::uint32_t> planner_robot) {
  // The page's text with its placeholders filled in (placeholders, so that the page's script
  // keeps its braces): the title where it shows, the data where the script reads them.
  const std::string title = html_escape(scenario_name(run.scenario.source));
  const std::string data = data_literal(run, std::max<std::size_t>(max_frames, 2), planner_robot);
  std::string out;
  for (std::size_t at = 0; at < kPage.size();) {
    const std::size_t next = kPage.find('@', at);
    if (next == std::string_view::npos) {
      out += kPage.substr(at);
      break;
    }
    out += kPage.substr(at, next - at);
    if (kPage.substr(next, 7) == "@TITLE@") {
      out += title;
      at = next + 7;
    } else if (kPage.substr(next, 6) == "@DATA@") {
      out += data;
      at = next + 6;
    } else {
      out += '@';
      at = next + 1;
    }
  }
  return out;
}

}  // namespace covsim
