#include "render/HtmlViewer.h"

#include "io/SceneIO.h"
#include "render/Palette.h"
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
// The picture fills the window, as large as fits beside the controls, and follows it when it
// is resized (the drawing is scaled, not redrawn).
function fit() {
  const below = document.body.scrollHeight - cv.offsetHeight;
  const k = Math.max(0.1, Math.min(window.innerWidth / W, (window.innerHeight - below) / H));
  cv.style.width = Math.floor(W * k) + 'px'; cv.style.height = Math.floor(H * k) + 'px';
}
window.addEventListener('resize', fit);
window.addEventListener('load', fit);
const g = cv.getContext('2d');
const px = p => [PAD + (p[0] - B[0]) * S, PAD + (B[3] - p[1]) * S];
const COLOURS = D.colours;
const way = D.waypoints || [];
const radius = D.robots.map(r => Math.max(...r.shape.map(v => Math.hypot(v[0], v[1]))));
// Cumulative durations: a segment takes as long as its fastest-moving robot point needs.
const cum = [0];
for (let i = 1; i < way.length; ++i) {
  let d = 0;
  D.robots.forEach((r, k) => {
    const a = way[i - 1], b = way[i], o = 3 * k;
    d = Math.max(d, Math.hypot(b[o] - a[o], b[o + 1] - a[o + 1]) + radius[k] * Math.abs(b[o + 2] - a[o + 2]));
  });
  cum.push(cum[i - 1] + d);
}
const total = cum[cum.length - 1] || 0;
function configAt(f) {
  if (way.length === 0) return null;
  if (way.length === 1 || total === 0) return way[0];
  const t = Math.min(Math.max(f, 0), 1) * total;
  let i = 1;
  while (i < way.length - 1 && cum[i] < t) ++i;
  const seg = cum[i] - cum[i - 1], s = seg > 0 ? (t - cum[i - 1]) / seg : 1;
  return way[i - 1].map((v, c) => v + s * (way[i][c] - v));
}
function ring(pts) {
  g.beginPath();
  pts.forEach((p, i) => { const q = px(p); i ? g.lineTo(q[0], q[1]) : g.moveTo(q[0], q[1]); });
  g.closePath();
}
function placed(r, pose) {
  const c = Math.cos(pose[2]), s = Math.sin(pose[2]);
  return r.shape.map(v => [pose[0] + c * v[0] - s * v[1], pose[1] + s * v[0] + c * v[1]]);
}
const ui = {
  slider: document.getElementById('time'), play: document.getElementById('play'),
  speed: document.getElementById('speed'), traces: document.getElementById('traces'),
  roadmap: document.getElementById('roadmap'), label: document.getElementById('label')
};
if (!D.roadmap) { ui.roadmap.disabled = true; ui.roadmap.parentElement.title = 'the path file holds no roadmap (mms plan --save-roadmap)'; }
function draw() {
  const f = ui.slider.value / 1000;
  g.fillStyle = '#ffffff'; g.fillRect(0, 0, W, H);
  g.strokeStyle = '#333333'; g.lineWidth = 1;
  const c0 = px([B[0], B[3]]), c1 = px([B[2], B[1]]);
  g.strokeRect(c0[0], c0[1], c1[0] - c0[0], c1[1] - c0[1]);
  if (D.roadmap && ui.roadmap.checked) {
    g.fillStyle = 'rgba(46, 125, 50, 0.15)';
    (D.roadmap.cells || []).forEach(cell => {
      g.beginPath();
      cell.forEach(r => r.forEach((p, i) => { const q = px(p); i ? g.lineTo(q[0], q[1]) : g.moveTo(q[0], q[1]); }));
      g.fill('evenodd');
    });
    g.fillStyle = 'rgba(0, 0, 0, 0.35)';
    (D.roadmap.points || []).forEach(p => { const q = px(p); g.fillRect(q[0] - 1, q[1] - 1, 2, 2); });
  }
  g.fillStyle = '#3f6fb5';
  D.obstacles.forEach(o => { ring(o); g.fill(); });
  D.robots.forEach((r, k) => {
    g.lineWidth = 1.5;
    g.strokeStyle = '#2e7d32'; ring(placed(r, r.start)); g.stroke();
    g.strokeStyle = '#c62828'; ring(placed(r, r.goal)); g.stroke();
  });
  if (way.length && ui.traces.checked) {
    D.robots.forEach((r, k) => {
      g.strokeStyle = COLOURS[k % COLOURS.length]; g.lineWidth = 1; g.setLineDash([4, 3]);
      g.beginPath();
      way.forEach((q, i) => { const p = px([q[3 * k], q[3 * k + 1]]); i ? g.lineTo(p[0], p[1]) : g.moveTo(p[0], p[1]); });
      g.stroke(); g.setLineDash([]);
    });
  }
  const q = configAt(f);
  if (q) D.robots.forEach((r, k) => {
    g.fillStyle = COLOURS[k % COLOURS.length];
    ring(placed(r, [q[3 * k], q[3 * k + 1], q[3 * k + 2]])); g.fill();
  });
  ui.label.textContent = way.length ? 't = ' + f.toFixed(3) + ' of the motion' : 'no path';
}
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
ui.traces.onchange = draw; ui.roadmap.onchange = draw;
function fromHash() {
  const h = new URLSearchParams(location.hash.slice(1));
  if (h.has('t')) { ui.slider.value = Math.round(1000 * Number(h.get('t'))); playing = false; }
  if (h.has('roadmap')) ui.roadmap.checked = h.get('roadmap') === '1';
  if (h.has('traces')) ui.traces.checked = h.get('traces') === '1';
  draw();
}
window.addEventListener('hashchange', fromHash);
fromHash();
)JS";

}  // namespace

Vec2 viewerPixel(const Scene& scene, Vec2 p) {
  const Box& b = scene.bounds;
  const double s = (kViewerCanvasWidth - 2 * kViewerPad) / b.width();
  return {kViewerPad + (p.x - b.xmin) * s, kViewerPad + (b.ymax - p.y) * s};
}

std::string renderHtmlViewer(const Scene& scene, const Path* path) {
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
  for (size_t at = 0; (at = data.find("</", at)) != std::string::npos; at += 3)
    data.replace(at, 2, "<\\/");
  const std::string title = scene.name.empty() ? "mms scene" : scene.name;
  std::string html;
  html += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>";
  html += escapeMarkup(title) + " - mms view</title>\n";
  html +=
      "<style>body{margin:0;font:13px sans-serif;color:#222}canvas{display:block}"
      "#controls{padding:8px 10px;display:flex;gap:12px;align-items:center;flex-wrap:wrap}"
      "#time{width:340px}</style>\n</head>\n<body>\n<canvas id=\"view\"></canvas>\n"
      "<div id=\"controls\"><button id=\"play\">Play</button>"
      "<input id=\"time\" type=\"range\" min=\"0\" max=\"1000\" value=\"0\" "
      "aria-label=\"time\"><span id=\"label\"></span>"
      "<label>speed <select id=\"speed\"><option value=\"0.25\">0.25x</option>"
      "<option value=\"0.5\">0.5x</option><option value=\"1\" selected>1x</option>"
      "<option value=\"2\">2x</option><option value=\"4\">4x</option></select></label>"
      "<label><input id=\"traces\" type=\"checkbox\" checked> traces</label>"
      "<label><input id=\"roadmap\" type=\"checkbox\"> free-space cells and lines</label>"
      "</div>\n<p style=\"padding:0 10px\">";
  html += escapeMarkup(title) +
          ": obstacles blue, robots green at the start and red at the goal (outlines). "
          "Link to a moment with #t=0.5.</p>\n";
  if (scene.robots.size() >= 2) {
    html += "<p id=\"legend\" style=\"padding:0 10px\">";
    for (size_t i = 0; i < scene.robots.size(); ++i)
      html +=
          std::string("<span style=\"display:inline-block;margin-right:14px\">") +
          "<span style=\"display:inline-block;width:12px;height:12px;background:" + robotColour(i) +
          ";margin-right:5px\"></span>" + escapeMarkup(scene.robots[i].name) + "</span>";
    html += "</p>\n";
  }
  html += "<script id=\"mms-data\" type=\"application/json\">" + data + "</script>\n";
  html += "<script>" + std::string(kScript) + "</script>\n</body>\n</html>\n";
  return html;
}

}  // namespace mms
