#include "render/RecordLayer.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>

#include "util/Markup.h"

namespace mms {

namespace {

// The record layer, run after the player's script (HtmlViewer.cpp), whose drawStill() calls
// drawRecord(context) under the obstacles. D.record is the mms-record/1 document.
const char* kRecordScript = R"JS(
const R = D.record;
const rui = {
  time: document.getElementById('rtime'), label: document.getElementById('rlabel'),
  cells: document.getElementById('lcells'), lines: document.getElementById('llines'),
  tree: document.getElementById('ltree'), path: document.getElementById('lpath'),
  sub: document.getElementById('rsub'), angle: document.getElementById('rangle'),
  robot: document.getElementById('rrobot'), growth: document.getElementById('rgrowth')
};
const isSlice = m => m.family.indexOf('slice') >= 0;
const tree = R.tree || { states: [], at: [], edges: [] };
// The planning's length: the run's seconds, or the last stamp if a stamp lies past them.
const G = R.growth, GN = G.at.length;
let RT = Math.max(R.seconds, GN ? G.at[GN - 1] : 0, 1e-9);
const angles = [];
R.manifolds.forEach(m => { if (isSlice(m) && angles.indexOf(m.theta) < 0) angles.push(m.theta); });
angles.sort((a, b) => a - b);
angles.forEach((a, i) => { const o = document.createElement('option'); o.value = i; o.textContent = a.toFixed(4) + ' rad'; rui.angle.appendChild(o); });
// The slice angle nearest `theta`, round the circle.
const turnApart = (a, b) => { const d = Math.abs(a - b) % (2 * Math.PI); return Math.min(d, 2 * Math.PI - d); };
function nearestAngle(theta) {
  let best = -1;
  angles.forEach((a, i) => { if (best < 0 || turnApart(a, theta) < turnApart(angles[best], theta)) best = i; });
  return best;
}
// One robot: by default the slice nearest its angle at the motion's moment (every angle at once
// stacks hundreds of slices into one wash).
let nearAngle = -1;
function robotAngleAt(f) { const q = configAt(f); return q ? q[2] : D.robots[0].start[2]; }
function recordMoment(f) {
  if (rui.angle.value !== 'near') return false;
  const a = nearestAngle(robotAngleAt(f));
  if (a === nearAngle) return false;
  nearAngle = a;
  return true;
}
if (D.robots.length !== 1) rui.angle.querySelector('option[value="near"]').remove();
else nearAngle = nearestAngle(robotAngleAt(ui.slider.value / 1000));
R.subspaces.forEach((s, i) => {
  const o = document.createElement('option'); o.value = i;
  const held = s.held.map(h => D.robots[h[0]].name + ' at (' + h[1].toFixed(2) + ', ' + h[2].toFixed(2) + ')').join(', ');
  o.textContent = D.robots[s.moving].name + (s.attached !== undefined ? ' carrying ' + D.robots[s.attached].name : ' moves') + (held ? '; held: ' + held : '');
  rui.sub.appendChild(o);
});
if (R.subspaces.length < 2) rui.sub.parentElement.style.display = 'none';
if (!angles.length) rui.angle.parentElement.style.display = 'none';
D.robots.forEach((r, i) => { const o = document.createElement('option'); o.value = i; o.textContent = r.name; rui.robot.appendChild(o); });
if (!tree.states.length || D.robots.length < 2) rui.robot.parentElement.style.display = 'none';
function planningTime() { return RT * rui.time.value / 1000; }
// Start's component green, goal's red, both (merged) purple, neither grey.
function componentColour(m, t, alpha) {
  const s = m.reached[0] >= 0 && m.reached[0] <= t, g = m.reached[1] >= 0 && m.reached[1] <= t;
  const c = s && g ? '106, 27, 154' : s ? '46, 125, 50' : g ? '198, 40, 40' : '110, 110, 110';
  return 'rgba(' + c + ', ' + alpha + ')';
}
// `stack`: every angle unless one is chosen (the 3-D view stacks the slices by angle).
function shown(m, t, stack) {
  if (m.at > t) return false;
  if (rui.sub.value !== 'all' && m.subspace !== Number(rui.sub.value)) return false;
  if (!isSlice(m) || rui.angle.value === 'all') return true;
  if (rui.angle.value === 'near') return stack || m.theta === angles[nearAngle];
  return m.theta === angles[Number(rui.angle.value)];
}
function flatPath(ctx, flat) {
  for (let i = 0; i < flat.length; i += 2) {
    const q = px([flat[i], flat[i + 1]]);
    i ? ctx.lineTo(q[0], q[1]) : ctx.moveTo(q[0], q[1]);
  }
  ctx.closePath();
}
function drawCells(s, t) {
  const slices = R.manifolds.filter(m => isSlice(m) && shown(m, t));
  const alpha = Math.max(0.04, Math.min(0.35, 3 / Math.max(1, slices.length)));
  slices.forEach(m => {
    s.fillStyle = componentColour(m, t, alpha);
    m.regions.forEach(cell => { s.beginPath(); cell.forEach(r => flatPath(s, r)); s.fill('evenodd'); });
    if (rui.path.checked && m.path) {
      s.strokeStyle = 'rgba(0, 0, 0, 0.8)'; s.lineWidth = 1.5;
      m.regions.forEach(cell => { s.beginPath(); cell.forEach(r => flatPath(s, r)); s.stroke(); });
    }
  });
}
function drawLines(s, t) {
  R.manifolds.forEach(m => {
    if (isSlice(m) || !shown(m, t)) return;
    const q = px(m.point), big = rui.path.checked && m.path;
    s.fillStyle = big ? '#000000' : componentColour(m, t, 0.8);
    const r = big ? 3 : 1.5;
    if (m.family === 'pivot-line') { s.beginPath(); s.arc(q[0], q[1], r + 2, 0, 2 * Math.PI); s.strokeStyle = s.fillStyle; s.lineWidth = 1; s.stroke(); }
    else s.fillRect(q[0] - r, q[1] - r, 2 * r, 2 * r);
  });
}
function drawTree(s, t) {
  const k = tree.states.length && D.robots.length > 1 ? Number(rui.robot.value) : 0, o = 3 * k;
  s.strokeStyle = 'rgba(123, 31, 162, 0.6)'; s.lineWidth = 1.5;
  s.beginPath();
  tree.edges.forEach(e => {
    if (tree.at[e[0]] > t || tree.at[e[1]] > t) return;
    const a = px([tree.states[e[0]][o], tree.states[e[0]][o + 1]]), b = px([tree.states[e[1]][o], tree.states[e[1]][o + 1]]);
    s.moveTo(a[0], a[1]); s.lineTo(b[0], b[1]);
  });
  s.stroke();
}
function drawHeld(s) {
  if (rui.sub.value === 'all') return;
  const sub = R.subspaces[Number(rui.sub.value)];
  s.strokeStyle = '#555555'; s.lineWidth = 1.5; s.setLineDash([3, 2]);
  sub.held.forEach(h => { robotPath(s, h[0], [h[1], h[2], h[3]]); s.stroke(); });
  s.setLineDash([]);
}
let cspaceShown = '';  // what the 3-D view was last built for
function drawRecord(s) {
  const t = planningTime();
  if (rui.cells.checked) drawCells(s, t);
  if (rui.lines.checked) drawLines(s, t);
  if (rui.tree.checked) drawTree(s, t);
  drawHeld(s);
  describe(t);
  // The 3-D view stacks every angle: the motion's moment does not change it.
  const key = [t, rui.cells.checked, rui.lines.checked, rui.sub.value, rui.angle.value === 'near' ? '' : rui.angle.value].join();
  if (window.buildCspace && key !== cspaceShown) { cspaceShown = key; buildCspace(t); }
}
// How many of each kind existed at t, by the growth samples (kept from every stamp).
function builtBy(t) {
  let i = -1;
  while (i + 1 < GN && G.at[i + 1] <= t) ++i;
  const n = {};
  Object.keys(G.counts).forEach(k => { n[k] = i < 0 ? 0 : G.counts[k][i]; });
  return n;
}
// What existed at t, in words, and the growth chart's marker.
function describe(t) {
  const n = builtBy(t);
  let slices = 0, lines = 0, round = 0, drawn = 0, connected = false;
  Object.keys(n).forEach(k => { if (k !== 'states') (k.indexOf('slice') >= 0 ? slices += n[k] : lines += n[k]); });
  R.manifolds.forEach(m => { if (m.at <= t) { round = Math.max(round, m.round); ++drawn; } });
  tree.at.forEach(a => { if (a <= t) ++drawn; });
  R.searches.forEach(x => { if (x.at <= t) { round = Math.max(round, x.round); if (x.connected) connected = true; } });
  let text = 'planning t = ' + t.toFixed(3) + ' s of ' + RT.toFixed(3) + ' s (' + R.planner + ')';
  if (slices + lines) text += ' · ' + slices + ' slices, ' + lines + ' lines · round ' + round + (connected ? ' · start and goal connected' : '');
  const one = rui.angle.value === 'near' ? nearAngle : rui.angle.value === 'all' ? -1 : Number(rui.angle.value);
  if (one >= 0) text += ' · cells of the slice at ' + angles[one].toFixed(3) + ' rad' + (rui.angle.value === 'near' ? ', nearest the robot\'s angle now' : '');
  if (n.states !== undefined) text += ' · ' + n.states + ' states';
  const kept = R.manifolds.length + tree.states.length, all = (tree.total_states || 0) + (GN ? Object.keys(G.counts).filter(k => k !== 'states').reduce((a, k) => a + G.counts[k][GN - 1], 0) : 0);
  if (kept < all) text += ' (' + drawn + ' of them drawn: the record keeps every k-th)';
  rui.label.textContent = text;
  drawGrowth(t);
}
// Manifolds (or a tree's states) against time, with its axes, and where the slider is.
function drawGrowth(t) {
  const c = rui.growth.getContext('2d'), w = rui.growth.width, h = rui.growth.height;
  const L = 46, R = 10, T = 16, Bm = 18, pw = w - L - R, ph = h - T - Bm;
  c.fillStyle = '#ffffff'; c.fillRect(0, 0, w, h);
  const kinds = Object.keys(G.counts), total = i => kinds.reduce((a, k) => a + G.counts[k][i], 0);
  const most = Math.max(1, GN ? total(GN - 1) : 0);
  const X = s => L + s / RT * pw, Y = n => T + ph - n / most * ph;
  c.strokeStyle = '#555555'; c.lineWidth = 1; c.beginPath();
  c.moveTo(L, T); c.lineTo(L, T + ph); c.lineTo(L + pw, T + ph); c.stroke();
  c.fillStyle = '#333333'; c.font = '11px sans-serif';
  c.textAlign = 'left'; c.fillText(kinds.length === 1 && kinds[0] === 'states' ? 'states' : 'manifolds built', L, T - 4);
  c.textAlign = 'right'; c.fillText(String(most), L - 4, T + 8); c.fillText('0', L - 4, T + ph);
  c.textAlign = 'left'; c.fillText('0 s', L, h - 4);
  c.textAlign = 'right'; c.fillText(RT.toPrecision(3) + ' s', L + pw, h - 4);
  c.strokeStyle = '#3f6fb5'; c.lineWidth = 1.5; c.beginPath();
  for (let i = 0; i < GN; ++i) i ? c.lineTo(X(G.at[i]), Y(total(i))) : c.moveTo(X(G.at[i]), Y(total(i)));
  c.stroke();
  c.strokeStyle = '#c62828'; c.beginPath(); c.moveTo(X(t), T); c.lineTo(X(t), T + ph); c.stroke();
  rui.growth.dataset.axes = '0 to ' + most + ' over 0 to ' + RT.toPrecision(3) + ' s';
}
function recordFromHash() {
  const h = new URLSearchParams(location.hash.slice(1));
  if (h.has('rt')) rui.time.value = Math.round(1000 * Math.min(1, Math.max(0, Number(h.get('rt')))));
  if (h.has('layers')) {
    const on = h.get('layers').split(',');
    ['cells', 'lines', 'tree', 'path'].forEach(l => { rui[l].checked = on.indexOf(l) >= 0; });
  }
  if (h.has('sub')) rui.sub.value = h.get('sub');
  if (h.has('angle')) {
    const a = h.get('angle');
    if (a === 'all' || (a === 'near' && D.robots.length === 1)) rui.angle.value = a;
    else if (angles.length && a !== '' && isFinite(Number(a))) rui.angle.value = nearestAngle(Number(a));
    nearAngle = -1; recordMoment(ui.slider.value / 1000);
  }
  if (h.has('rrobot')) rui.robot.value = h.get('rrobot');
  drawStill(); draw();
}
rui.angle.addEventListener('change', () => { nearAngle = -1; recordMoment(ui.slider.value / 1000); });
[rui.time, rui.cells, rui.lines, rui.tree, rui.path, rui.sub, rui.angle, rui.robot].forEach(e => {
  e.addEventListener('input', () => { drawStill(); draw(); });
  e.addEventListener('change', () => { drawStill(); draw(); });
});
window.addEventListener('hashchange', recordFromHash);
recordFromHash();
)JS";

// One robot's C-space in 3-D (three.js, inlined from Debian's libjs-three): slices' cells as
// flat shapes at their angle, lines' free arcs as vertical segments, the path as a curve; x and
// y across, theta up (-pi at the bottom, pi at the top). Rebuilt with the planning slider.
const char* kCspaceScript = R"JS(
(function () {
  const box = document.getElementById('cspace'), on = document.getElementById('lcspace');
  const note = document.getElementById('cspace-note');
  const PI = Math.PI, k = 2 / Math.max(B[2] - B[0], B[3] - B[1]);
  const cx = (B[0] + B[2]) / 2, cy = (B[1] + B[3]) / 2;
  const wrap = a => { const w = ((a + PI) % (2 * PI) + 2 * PI) % (2 * PI); return w - PI; };
  const V = (x, y, th) => new THREE.Vector3((x - cx) * k, (y - cy) * k, th / PI);
  let renderer = null, scene3, camera, group = null;
  const h = new URLSearchParams(location.hash.slice(1));
  // A square beside the scene's picture, a good part of the window's width; below it where the
  // window is too narrow for both (the page then scrolls to it).
  const side = () => Math.round(Math.min(600, Math.max(240, 0.42 * window.innerWidth)));
  const besideFits = () => window.innerWidth >= 700;
  window.cspaceBeside = () => (on.checked && besideFits() ? side() + 4 : 0);
  function resize() {
    if (!renderer) return;
    renderer.setSize(side(), side());
    renderer.render(scene3, camera);
  }
  function init() {
    try {
      renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    } catch (e) { note.textContent = '3-D view: no WebGL in this browser'; return false; }
    renderer.setSize(side(), side()); renderer.setClearColor(0xffffff);
    box.appendChild(renderer.domElement);
    scene3 = new THREE.Scene();
    // Far enough that the whole box (x, y and the angle in [-1, 1]) is in view: its bounding
    // sphere, sqrt(3), within half the field of view (20 degrees), and a margin.
    camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
    const away = new THREE.Vector3(1.6, -2.9, 1.6).normalize().multiplyScalar(1.08 * Math.sqrt(3) / Math.sin(PI / 9));
    camera.up.set(0, 0, 1); camera.position.copy(away); camera.lookAt(0, 0, 0);
    window.addEventListener('resize', resize);
    const controls = new THREE.OrbitControls(camera, renderer.domElement);
    controls.addEventListener('change', () => renderer.render(scene3, camera));
    // The frame: the bounds at -pi and pi, and the obstacles at the bottom.
    const frame = [];
    [-1, 1].forEach(z => { [[0, 1], [1, 2], [2, 3], [3, 0]].forEach(e => {
      const c = [[B[0], B[1]], [B[2], B[1]], [B[2], B[3]], [B[0], B[3]]];
      frame.push(V(c[e[0]][0], c[e[0]][1], z * PI), V(c[e[1]][0], c[e[1]][1], z * PI)); }); });
    [[B[0], B[1]], [B[2], B[1]], [B[2], B[3]], [B[0], B[3]]].forEach(c => frame.push(V(c[0], c[1], -PI), V(c[0], c[1], PI)));
    scene3.add(new THREE.LineSegments(new THREE.BufferGeometry().setFromPoints(frame), new THREE.LineBasicMaterial({ color: 0x999999 })));
    const grey = new THREE.MeshBasicMaterial({ color: 0x3f6fb5, side: THREE.DoubleSide });
    D.obstacles.forEach(o => { if (o.radius !== undefined) return;
      const m = new THREE.Mesh(new THREE.ShapeGeometry(new THREE.Shape(o.map(p => new THREE.Vector2((p[0] - cx) * k, (p[1] - cy) * k)))), grey);
      m.position.z = -1; scene3.add(m); });
    return true;
  }
  function shape(ring) { return ring.reduce((a, v, i) => { if (i % 2) a.push(new THREE.Vector2((ring[i - 1] - cx) * k, (v - cy) * k)); return a; }, []); }
  function build(t) {
    const was = box.style.display;
    box.style.display = on.checked ? 'block' : 'none';
    if (was !== box.style.display) fit();  // the scene's picture makes room, or takes it back
    if (!on.checked) return;
    if (!renderer && !init()) return;
    if (group) { scene3.remove(group); group.traverse(o => { if (o.geometry) o.geometry.dispose(); if (o.material) o.material.dispose(); }); }
    group = new THREE.Group();
    let slices = 0, arcs = 0;
    const pts = [], cols = [];
    R.manifolds.forEach(m => {
      if (!shown(m, t, true)) return;
      const c = new THREE.Color(componentColour(m, t, 1).replace('rgba', 'rgb').replace(/, [0-9.]+\)$/, ')'));
      if (isSlice(m)) {
        if (!rui.cells.checked) return;
        ++slices;
        const mat = new THREE.MeshBasicMaterial({ color: c, transparent: true, opacity: 0.35, side: THREE.DoubleSide, depthWrite: false });
        m.regions.forEach(cell => {
          const s = new THREE.Shape(shape(cell[0]));
          cell.slice(1).forEach(h => s.holes.push(new THREE.Path(shape(h))));
          const mesh = new THREE.Mesh(new THREE.ShapeGeometry(s), mat);
          mesh.position.z = wrap(m.theta) / PI; group.add(mesh);
        });
      } else if (rui.lines.checked) {
        m.arcs.forEach(a => {
          ++arcs;
          // An arc as segments within [-pi, pi): split where it wraps.
          let lo = a[0], hi = Math.min(a[1], a[0] + 2 * PI);
          while (lo < hi) {
            const from = wrap(lo), len = Math.min(hi - lo, PI - from);
            pts.push(V(m.point[0], m.point[1], from), V(m.point[0], m.point[1], from + len));
            cols.push(c.r, c.g, c.b, c.r, c.g, c.b);
            lo += Math.max(len, 1e-9);
          }
        });
      }
    });
    if (pts.length) {
      const g = new THREE.BufferGeometry().setFromPoints(pts);
      g.setAttribute('color', new THREE.Float32BufferAttribute(cols, 3));
      group.add(new THREE.LineSegments(g, new THREE.LineBasicMaterial({ vertexColors: THREE.VertexColors })));
    }
    // The path of the robot, broken where its angle wraps round.
    const path = [];
    for (let i = 1; i < way.length; ++i) {
      const a = way[i - 1], b = way[i], za = wrap(a[2]), zb = za + (b[2] - a[2]);
      if (zb >= -PI && zb < PI) path.push(V(a[0], a[1], za), V(b[0], b[1], zb));
    }
    if (path.length) group.add(new THREE.LineSegments(new THREE.BufferGeometry().setFromPoints(path), new THREE.LineBasicMaterial({ color: 0x000000 })));
    scene3.add(group);
    renderer.render(scene3, camera);
    document.body.dataset.cspace = slices + ' slices, ' + arcs + ' arcs';
    if (h.get('ink') === '1') document.body.dataset.cspaceInk = ink();
    note.textContent = 'at t: ' + slices + ' slices, ' + arcs + ' free arcs; x and y across, the angle up (-pi to pi); drag to turn, wheel to zoom';
  }
  // #ink=1: the pixels the 3-D view drew (not white), read back from WebGL, for tests.
  function ink() {
    const n2 = side(), gl = renderer.getContext(), px = new Uint8Array(n2 * n2 * 4);
    gl.readPixels(0, 0, n2, n2, gl.RGBA, gl.UNSIGNED_BYTE, px);
    let n = 0;
    for (let i = 0; i < px.length; i += 4) if (px[i] < 245 || px[i + 1] < 245 || px[i + 2] < 245) ++n;
    return n;
  }
  window.buildCspace = build;
  on.addEventListener('change', () => build(planningTime()));
  if (h.get('cspace') === '1') on.checked = true;
  build(planningTime());
})();
)JS";

}  // namespace

std::string recordControls(const RecordFile& record) {
  const bool tree = !record.record.tree.states.empty();
  const bool manifolds = !record.record.manifolds.empty();
  std::string html =
      "<div id=\"record\" style=\"padding:4px 10px;display:flex;gap:12px;align-items:center;"
      "flex-wrap:wrap\"><b>planning</b><input id=\"rtime\" type=\"range\" min=\"0\" "
      "max=\"1000\" value=\"1000\" style=\"width:340px\" aria-label=\"planning time\">";
  auto box = [](const char* id, const char* label, bool on) {
    return std::string("<label><input id=\"") + id + "\" type=\"checkbox\"" +
           (on ? " checked" : "") + "> " + label + "</label>";
  };
  html += box("lcells", "slice cells", manifolds) + box("llines", "lines", manifolds) +
          box("ltree", "tree or graph", tree) + box("lpath", "the path's manifolds", manifolds);
  html +=
      "<label>subspace <select id=\"rsub\"><option value=\"all\">all</option></select></label>"
      "<label>slices at <select id=\"rangle\"><option value=\"near\" selected>the robot's "
      "angle now</option><option value=\"all\">every angle</option></select></label>"
      "<label>tree of <select id=\"rrobot\"></select></label>";
  if (record.record.robots == 1 && manifolds)
    html +=
        "<label><input id=\"lcspace\" type=\"checkbox\"> 3-D C-space</label> <span "
        "id=\"cspace-note\"></span>";
  html +=
      "</div>\n<p id=\"rlabel\" style=\"padding:0 10px\"></p>\n<canvas id=\"rgrowth\" "
      "width=\"360\" height=\"110\" style=\"margin:0 10px\" title=\"built against "
      "time\"></canvas>\n";
  html += "<div id=\"rphases\" style=\"padding:0 10px\">" + phaseChart(record.stats) + "</div>\n";
  return html;
}

std::string cspaceStage(const RecordFile& record) {
  return record.record.robots == 1 && !record.record.manifolds.empty()
             ? "<div id=\"cspace\" style=\"display:none\"></div>"
             : "";
}

std::string phaseChart(const PlanStatistics& stats) {
  // Longest first: where the time went reads from the top.
  auto phases = stats.phases;
  std::stable_sort(phases.begin(), phases.end(),
                   [](const auto& a, const auto& b) { return a.second > b.second; });
  double total = 0;
  for (const auto& [name, s] : phases) total += s;
  std::string html = "<table style=\"border-collapse:collapse\">";
  for (const auto& [name, s] : phases) {
    const int width = total > 0 ? int(240 * s / total + 0.5) : 0;
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.3g s", s);
    html += "<tr><td style=\"padding-right:8px\">" + escapeMarkup(name) +
            "</td><td><span style=\"display:inline-block;height:10px;background:#3f6fb5;width:" +
            std::to_string(width) + "px\"></span> " + seconds + "</td></tr>";
  }
  html += "</table><p>";
  for (const auto& [name, n] : stats.counts)
    html += escapeMarkup(name) + " " + std::to_string(n) + " · ";
  return html + "</p>";
}

const char* recordScript() { return kRecordScript; }

std::string cspaceScripts(const RecordFile& record) {
  if (record.record.robots != 1 || record.record.manifolds.empty()) return "";
  const std::string dir = MMS_JAVASCRIPT_DIR "/three/";
  std::string three, orbit;
  for (const auto& [file, text] : {std::pair{dir + "three.min.js", &three},
                                   {dir + "examples/js/controls/OrbitControls.js", &orbit}}) {
    std::ifstream in(file, std::ios::binary);
    if (!in)
      return "<script>document.getElementById('cspace-note').textContent = '(needs "
             "Debian\\'s libjs-three where the page was written: scripts/setup.sh "
             "installs it)'; document.getElementById('lcspace').disabled = true;</script>\n";
    text->assign(std::istreambuf_iterator<char>(in), {});
  }
  return "<script>" + three + "</script>\n<script>" + orbit + "</script>\n<script>" +
         kCspaceScript + "</script>\n";
}

}  // namespace mms
