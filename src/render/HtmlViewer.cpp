#include "render/HtmlViewer.h"

#include "io/SceneIO.h"
#include "render/Palette.h"
#include "render/RecordLayer.h"
#include "util/Markup.h"

namespace mms {

namespace {

// The player. Kept in one string: the page must carry everything it needs.
const char* kScript = R"JS(
const D = JSON.parse(document.getElementById('mms-data').textContent);
const W = D.canvasWidth, PAD = D.pad, B = D.bounds;
const S = (W - 2 * PAD) / (B[2] - B[0]);
const H = Math.round((B[3] - B[1]) * S + 2 * PAD);
const cv = document.getElementById('view');
cv.width = W; cv.height = H;
// The picture fills the window above the sliders (the motion's, its caption, and the
// planning's with a record), beside the 3-D view when that is open, and follows the window when it is resized
// (the drawing is scaled, not redrawn); what else the page holds (the legend, the phases)
// scrolls below. #fit=0 keeps the drawing at its own size (pixel checks, screenshots of a
// given scale).
function fit() {
  if (new URLSearchParams(location.hash.slice(1)).get('fit') === '0') {
    cv.style.width = W + 'px'; cv.style.height = H + 'px'; return;
  }
  const bars = ['controls', 'caption', 'record'].map(id => document.getElementById(id))
      .reduce((a, e) => a + (e ? e.offsetHeight : 0), 0);
  const beside = typeof cspaceBeside === 'function' ? cspaceBeside() : 0;
  const k = Math.max(0.1, Math.min((window.innerWidth - beside) / W, (window.innerHeight - bars - 4) / H));
  cv.style.width = Math.floor(W * k) + 'px'; cv.style.height = Math.floor(H * k) + 'px';
}
window.addEventListener('resize', fit);
window.addEventListener('load', fit);
const g = cv.getContext('2d');
const px = p => [PAD + (p[0] - B[0]) * S, PAD + (B[3] - p[1]) * S];
const COLOURS = D.colours;
const way = D.waypoints || [];
const N = D.robots.length;
// Exact discs carry a radius instead of a shape (mms-scene/1), obstacles likewise.
const radius = D.robots.map(r => r.disc || Math.max(...r.shape.map(v => Math.hypot(v[0], v[1]))));
// Cumulative durations: a segment takes as long as its fastest-moving robot point needs.
const cum = [0];
for (let i = 1; i < way.length; ++i) {
  let d = 0;
  for (let k = 0; k < N; ++k) {
    const a = way[i - 1], b = way[i], o = 3 * k;
    const turn = D.robots[k].disc ? 0 : radius[k] * Math.abs(b[o + 2] - a[o + 2]);
    d = Math.max(d, Math.hypot(b[o] - a[o], b[o + 1] - a[o + 1]) + turn);
  }
  cum.push(cum[i - 1] + d);
}
const total = cum[cum.length - 1] || 0;
function configAt(f) {
  if (way.length === 0) return null;
  if (way.length === 1 || total === 0) return way[0];
  const t = Math.min(Math.max(f, 0), 1) * total;
  let lo = 1, hi = way.length - 1;  // the first segment ending at or after t
  while (lo < hi) { const m = (lo + hi) >> 1; if (cum[m] < t) lo = m + 1; else hi = m; }
  const i = lo, seg = cum[i] - cum[i - 1], s = seg > 0 ? (t - cum[i - 1]) / seg : 1;
  return way[i - 1].map((v, c) => v + s * (way[i][c] - v));
}
// Each robot's trace: only where it starts, stops or bends (hundreds of robots moving in turn).
const traces = D.robots.map((r, k) => {
  const pts = [];
  way.forEach(q => {
    const p = [q[3 * k], q[3 * k + 1]], n = pts.length;
    if (n && pts[n - 1][0] === p[0] && pts[n - 1][1] === p[1]) return;
    if (n >= 2) {
      const a = pts[n - 2], b = pts[n - 1];
      if (Math.abs((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])) < 1e-12) { pts[n - 1] = p; return; }
    }
    pts.push(p);
  });
  return pts;
});
function line(ctx, pts) {
  ctx.beginPath();
  pts.forEach((p, i) => { const q = px(p); i ? ctx.lineTo(q[0], q[1]) : ctx.moveTo(q[0], q[1]); });
}
function ring(ctx, pts) { line(ctx, pts); ctx.closePath(); }
function disc(ctx, c, r) {
  const q = px(c);
  ctx.beginPath(); ctx.arc(q[0], q[1], r * S, 0, 2 * Math.PI);
}
function robotPath(ctx, k, pose) {
  const r = D.robots[k];
  if (r.disc) return disc(ctx, pose, r.disc);
  const c = Math.cos(pose[2]), s = Math.sin(pose[2]);
  ring(ctx, r.shape.map(v => [pose[0] + c * v[0] - s * v[1], pose[1] + s * v[0] + c * v[1]]));
}
const ui = {
  slider: document.getElementById('time'), play: document.getElementById('play'),
  speed: document.getElementById('speed'), traces: document.getElementById('traces'),
  roadmap: document.getElementById('roadmap'), label: document.getElementById('label'),
  find: document.getElementById('find')
};
if (!D.roadmap) { ui.roadmap.disabled = true; ui.roadmap.parentElement.title = 'the path file holds no roadmap (mms plan --save-roadmap)'; }
// The robot picked out (by name, or under the pointer in the legend or the picture), -1: none.
let picked = -1, named = -1;
const byName = new Map(D.robots.map((r, k) => [r.name, k]));
// What does not move is drawn once, into a second canvas, and copied per frame.
const still = document.createElement('canvas');
still.width = W; still.height = H;
function drawStill() {
  const s = still.getContext('2d');
  s.fillStyle = '#ffffff'; s.fillRect(0, 0, W, H);
  s.strokeStyle = '#333333'; s.lineWidth = 1;
  const c0 = px([B[0], B[3]]), c1 = px([B[2], B[1]]);
  s.strokeRect(c0[0], c0[1], c1[0] - c0[0], c1[1] - c0[1]);
  if (D.roadmap && ui.roadmap.checked) {
    s.fillStyle = 'rgba(46, 125, 50, 0.15)';
    (D.roadmap.cells || []).forEach(cell => {
      s.beginPath();
      cell.forEach(r => r.forEach((p, i) => { const q = px(p); i ? s.lineTo(q[0], q[1]) : s.moveTo(q[0], q[1]); }));
      s.fill('evenodd');
    });
    s.fillStyle = 'rgba(0, 0, 0, 0.35)';
    (D.roadmap.points || []).forEach(p => { const q = px(p); s.fillRect(q[0] - 1, q[1] - 1, 2, 2); });
  }
  if (typeof drawRecord === 'function') drawRecord(s);
  s.fillStyle = '#3f6fb5';
  D.obstacles.forEach(o => { o.radius !== undefined ? disc(s, o.center, o.radius) : ring(s, o); s.fill(); });
  for (let k = 0; k < N; ++k) {
    const r = D.robots[k];
    s.globalAlpha = picked < 0 || picked === k ? 1 : 0.25;
    s.lineWidth = picked === k ? 3 : 1.5;
    s.strokeStyle = '#2e7d32'; robotPath(s, k, r.start); s.stroke();
    s.strokeStyle = '#c62828'; robotPath(s, k, r.goal); s.stroke();
    if (way.length && ui.traces.checked) {
      s.strokeStyle = COLOURS[k % COLOURS.length]; s.lineWidth = picked === k ? 2.5 : 1;
      s.setLineDash([4, 3]);
      line(s, traces[k]); s.stroke(); s.setLineDash([]);
    }
  }
  s.globalAlpha = 1;
}
function draw() {
  const f = ui.slider.value / 1000;
  // A record's layer may follow the motion (the slice nearest the robot's angle now).
  if (typeof recordMoment === 'function' && recordMoment(f)) drawStill();
  g.drawImage(still, 0, 0);
  const q = configAt(f);
  if (q) for (let k = 0; k < N; ++k) {
    g.globalAlpha = picked < 0 || picked === k ? 1 : 0.25;
    g.fillStyle = COLOURS[k % COLOURS.length];
    robotPath(g, k, [q[3 * k], q[3 * k + 1], q[3 * k + 2]]); g.fill();
    if (picked === k) { g.strokeStyle = '#000000'; g.lineWidth = 2.5; g.stroke(); }
  }
  g.globalAlpha = 1;
  ui.label.textContent = (way.length ? 't = ' + f.toFixed(3) + ' of the motion' : 'no path') +
      (picked >= 0 ? ' · ' + D.robots[picked].name : '');
}
function pick(k) { if (k !== picked) { picked = k; drawStill(); draw(); } }
document.querySelectorAll('[data-robot]').forEach(e => {
  e.addEventListener('mouseenter', () => pick(Number(e.dataset.robot)));
  e.addEventListener('mouseleave', () => pick(named));
});
if (ui.find) ui.find.addEventListener('input', () => {
  named = byName.has(ui.find.value) ? byName.get(ui.find.value) : -1; pick(named);
});
// The robot under the pointer, where it is at this moment.
cv.addEventListener('mousemove', ev => {
  const q = configAt(ui.slider.value / 1000); if (!q) return;
  const k2 = cv.width / cv.clientWidth, x = ev.offsetX * k2, y = ev.offsetY * k2;
  let best = named, bestD = Infinity;
  for (let k = 0; k < N; ++k) {
    const c = px([q[3 * k], q[3 * k + 1]]), d = Math.hypot(c[0] - x, c[1] - y);
    if (d <= radius[k] * S && d < bestD) { best = k; bestD = d; }
  }
  pick(best);
});
cv.addEventListener('mouseleave', () => pick(named));
let playing = false, last = 0;
function frame(ts) {
  if (!playing) return;
  const dt = last ? (ts - last) / 1000 : 0; last = ts;
  const seconds = 6 / Number(ui.speed.value);  // a whole motion in 6 s at 1x
  let v = Number(ui.slider.value) + 1000 * dt / seconds;
  if (v >= 1000) { v = 1000; playing = false; ui.play.textContent = 'Play'; }
  ui.slider.value = v; draw();
  if (playing) requestAnimationFrame(frame);
}
ui.play.onclick = () => {
  playing = !playing; ui.play.textContent = playing ? 'Pause' : 'Play';
  if (playing) { if (Number(ui.slider.value) >= 1000) ui.slider.value = 0; last = 0; requestAnimationFrame(frame); }
};
ui.slider.oninput = () => { playing = false; ui.play.textContent = 'Play'; draw(); };
ui.traces.onchange = () => { drawStill(); draw(); };
ui.roadmap.onchange = ui.traces.onchange;
function fromHash() {
  const h = new URLSearchParams(location.hash.slice(1));
  if (h.has('t')) { ui.slider.value = Math.round(1000 * Number(h.get('t'))); playing = false; }
  if (h.has('roadmap')) ui.roadmap.checked = h.get('roadmap') === '1';
  if (h.has('traces')) ui.traces.checked = h.get('traces') === '1';
  if (h.has('robot')) {
    named = byName.has(h.get('robot')) ? byName.get(h.get('robot')) : -1;
    if (ui.find) ui.find.value = h.get('robot');
  }
  picked = named;
  drawStill(); draw();
  if (h.has('bench')) benchFrames(Math.max(1, Number(h.get('bench')) || 100));
}
// #bench=N: N frames drawn through the motion, each read back so that it is rasterised, and
// the mean time a frame took put on the page (data-frame-ms of the body, and the label).
function benchFrames(n) {
  const t0 = performance.now();
  for (let i = 0; i < n; ++i) {
    ui.slider.value = Math.round(1000 * i / n); draw(); g.getImageData(0, 0, 1, 1);
  }
  const ms = (performance.now() - t0) / n;
  document.body.dataset.frameMs = ms.toFixed(3);
  ui.label.textContent = 'a frame in ' + ms.toFixed(2) + ' ms';
}
window.addEventListener('hashchange', fromHash);
fromHash();
)JS";

// Each robot's colour and name; hovering one picks it out in the picture, and so does typing its
// name. Beyond a screenful of names the legend is folded.
std::string legend(const Scene& scene) {
  const size_t n = scene.robots.size();
  std::string html = "<div id=\"legend\" style=\"padding:0 10px\">";
  html += "<label>robot <input id=\"find\" list=\"robot-names\" placeholder=\"name\"></label>";
  html += "<datalist id=\"robot-names\">";
  for (const Robot& r : scene.robots) html += "<option value=\"" + escapeMarkup(r.name) + "\">";
  html += "</datalist>";
  const bool fold = n > kViewerLegendUnfolded;
  html += fold ? "<details><summary>" + std::to_string(n) + " robots</summary>" : "<p>";
  for (size_t i = 0; i < n; ++i) {
    html += "<span data-robot=\"";
    html += std::to_string(i) + "\" style=\"display:inline-block;margin-right:14px\">";
    html += "<span style=\"display:inline-block;width:12px;height:12px;background:";
    html += std::string(robotColour(i)) + ";margin-right:5px\"></span>" +
            escapeMarkup(scene.robots[i].name);
    html += "</span>";
  }
  html += fold ? "</details>" : "</p>";
  return html + "</div>\n";
}

}  // namespace

Vec2 viewerPixel(const Scene& scene, Vec2 p) {
  const Box& b = scene.bounds;
  const double s = (kViewerCanvasWidth - 2 * kViewerPad) / b.width();
  return {kViewerPad + (p.x - b.xmin) * s, kViewerPad + (b.ymax - p.y) * s};
}

std::string renderHtmlViewer(const Scene& scene, const Path* path, const RecordFile* record) {
  // The scene as its file holds it (bounds, obstacles, robots' shape, start and goal).
  nlohmann::json d = sceneToJson(scene);
  d["canvasWidth"] = kViewerCanvasWidth;
  d["pad"] = kViewerPad;
  d["colours"] = nlohmann::json::array();
  for (size_t i = 0; i < scene.robots.size(); ++i) d["colours"].push_back(robotColour(i));
  if (path) {
    d["waypoints"] = path->waypoints;
    if (path->extra.contains("roadmap")) d["roadmap"] = path->extra["roadmap"];
  }
  // Inside <script>, "</" would end the element: JSON allows escaping the slash.
  std::string data = d.dump();
  if (record) {  // spliced in as text: a record's JSON tree would take ten times its size
    data.pop_back();
    data += ",\"record\":" + recordText(record->record, record->stats) + "}";
  }
  for (size_t at = 0; (at = data.find("</", at)) != std::string::npos; at += 3)
    data.replace(at, 2, "<\\/");
  const std::string title = scene.name.empty() ? "mms scene" : scene.name;
  std::string html;
  html += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>";
  html += escapeMarkup(title) + " - mms view</title>\n";
  html +=
      "<style>body{margin:0;font:13px sans-serif;color:#222}canvas{display:block}"
      "#controls{padding:8px 10px;display:flex;gap:12px;align-items:center;flex-wrap:wrap}"
      "#time{width:340px}#stage{display:flex;flex-wrap:wrap;align-items:flex-start;gap:4px}"
      "</style>\n</head>\n<body>\n<div id=\"stage\"><canvas id=\"view\"></canvas>" +
      (record ? cspaceStage(*record) : std::string()) +
      "</div>\n"
      "<div id=\"controls\"><button id=\"play\">Play</button>"
      "<input id=\"time\" type=\"range\" min=\"0\" max=\"1000\" value=\"0\" "
      "aria-label=\"time\"><span id=\"label\"></span>"
      "<label>speed <select id=\"speed\"><option value=\"0.25\">0.25x</option>"
      "<option value=\"0.5\">0.5x</option><option value=\"1\" selected>1x</option>"
      "<option value=\"2\">2x</option><option value=\"4\">4x</option></select></label>"
      "<label><input id=\"traces\" type=\"checkbox\" checked> traces</label>"
      "<label><input id=\"roadmap\" type=\"checkbox\"> free-space cells and lines</label>"
      "</div>\n<p id=\"caption\" style=\"padding:0 10px\">";
  html += escapeMarkup(title) +
          ": obstacles blue, robots green at the start and red at the goal (outlines). "
          "Link to a moment with #t=0.5, to a robot with #robot=NAME.</p>\n";
  if (record) html += recordControls(*record);
  if (scene.robots.size() >= 2) html += legend(scene);
  html += "<script id=\"mms-data\" type=\"application/json\">" + data + "</script>\n";
  html += "<script>" + std::string(kScript) + "</script>\n";
  if (record)
    html += "<script>" + std::string(recordScript()) + "</script>\n" + cspaceScripts(*record);
  html += "</body>\n</html>\n";
  return html;
}

}  // namespace mms
