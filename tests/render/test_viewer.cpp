// The HTML viewer (mms view): the roadmap a path file keeps reaches the page, and a real
// headless Chromium draws the robot where the slider says.
#include <gtest/gtest.h>
#include <png.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

#include "GeometryReference.h"
#include "Support.h"
#include "geometry/PolygonOps.h"
#include "io/PathIO.h"
#include "io/RecordIO.h"
#include "io/SceneIO.h"
#include "render/HtmlViewer.h"
#include "render/Palette.h"
#include "scenarios/Generators.h"
#include "util/Random.h"

namespace mms {
namespace {

using test::quote;
using test::runMms;
using test::TempDir;

// Headless Chromium screenshots are read back as pixels.
struct Rgb {
  int r, g, b;
};

std::vector<Rgb> readPng(const std::string& file, int& w, int& h) {
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&img, file.c_str())) return {};
  img.format = PNG_FORMAT_RGB;
  std::vector<unsigned char> buf(PNG_IMAGE_SIZE(img));
  if (!png_image_finish_read(&img, nullptr, buf.data(), 0, nullptr)) return {};
  w = int(img.width), h = int(img.height);
  std::vector<Rgb> px(size_t(w) * size_t(h));
  for (size_t i = 0; i < px.size(); ++i) px[i] = {buf[3 * i], buf[3 * i + 1], buf[3 * i + 2]};
  return px;
}

// Headless Chromium draws every page these tests look at.
bool chromiumInstalled() { return test::runCommand("command -v chromium").code == 0; }

TEST(View, SavedRoadmapReachesThePathFileAndThePage) {
  TempDir dir;
  const std::string scene = test::scenario("one-robot/bar-slot.json");
  const std::string path = dir.path("p.json"), html = dir.path("v.html");
  auto plan = runMms("plan " + quote(scene) + " --planner mms -q --save-roadmap -o " + quote(path));
  ASSERT_EQ(plan.code, 0) << plan.err;
  const nlohmann::json saved = nlohmann::json::parse(test::readFile(path));
  ASSERT_TRUE(saved.contains("roadmap"));
  EXPECT_GT(saved["roadmap"]["cells"].size(), 0u);
  EXPECT_GT(saved["roadmap"]["points"].size(), 0u);
  // Every cell ring is a polygon of [x, y] points.
  for (const auto& cell : saved["roadmap"]["cells"])
    for (const auto& ring : cell) {
      EXPECT_GE(ring.size(), 3u);
      for (const auto& p : ring) EXPECT_EQ(p.size(), 2u);
    }
  ASSERT_EQ(runMms("view " + quote(scene) + " " + quote(path) + " -o " + quote(html)).code, 0);
  EXPECT_NE(test::readFile(html).find("\"roadmap\":{\"cells\""), std::string::npos);
  auto two = runMms("plan " + quote(test::scenario("two-robots/niche-swap.json")) +
                    " -q --save-roadmap -o " + quote(dir.path("two.json")));
  EXPECT_EQ(two.code, 2) << "one-robot scenes only";
  EXPECT_NE(two.err.find("--save-roadmap"), std::string::npos) << two.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path("two.json")));
}

// The viewer shows a path as given, and says when it is not a certified motion of the scene
// (here: it begins away from the robot's start).
TEST(View, AnUncertifiedPathIsShownWithAWarning) {
  TempDir dir;
  const std::string scene = test::scenario("one-robot/bar-slot.json");
  const std::string path = dir.path("p.json"), moved = dir.path("moved.json"),
                    html = dir.path("v.html");
  ASSERT_EQ(runMms("plan " + quote(scene) + " --planner mms -q -o " + quote(path)).code, 0);
  auto good = runMms("view " + quote(scene) + " " + quote(path) + " -o " + quote(html));
  ASSERT_EQ(good.code, 0) << good.err;
  EXPECT_EQ(good.err.find("warning"), std::string::npos) << good.err;
  nlohmann::json j = nlohmann::json::parse(test::readFile(path));
  j["waypoints"][0][0] = j["waypoints"][0][0].get<double>() + 0.5;
  dir.file("moved.json", j.dump());
  auto bad = runMms("view " + quote(scene) + " " + quote(moved) + " -o " + quote(html));
  EXPECT_EQ(bad.code, 0) << bad.err;
  EXPECT_NE(bad.err.find("moved.json: warning: not certified ("), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("not at its start"), std::string::npos) << bad.err;
  EXPECT_EQ(test::readFile(html).rfind("<!DOCTYPE html>", 0), 0u);
}

// The viewer page of the scene and path, written by `mms view` into `dir`.
std::string viewPage(const Scene& s, const Path& p, TempDir& dir) {
  const std::string sceneFile = dir.path("s.json"), pathFile = dir.path("p.json");
  saveScene(s, sceneFile);
  savePath(p, s, pathFile);
  const std::string html = dir.path("v.html");
  auto v = runMms("view " + quote(sceneFile) + " " + quote(pathFile) + " -o " + quote(html));
  EXPECT_EQ(v.code, 0) << v.err;
  return html;
}

// A headless browser's picture of the page at `hash`; empty on failure.
std::vector<Rgb> screenshot(TempDir& dir, const std::string& html, const std::string& hash,
                            const std::string& size, int& w, int& h) {
  const std::string png = dir.path("shot.png");
  auto c = test::runCommand(
      "chromium --headless --no-sandbox --disable-gpu --hide-scrollbars "
      "--force-device-scale-factor=1 --window-size=" +
      size + " --virtual-time-budget=3000 --user-data-dir=" + quote(dir.path("profile")) +
      " --screenshot=" + quote(png) + " " + quote("file://" + html + "#" + hash));
  EXPECT_EQ(c.code, 0) << c.err;
  return c.code == 0 ? readPng(png, w, h) : std::vector<Rgb>{};
}

TEST(View, HeadlessBrowserDrawsTheRobotWhereTheSliderSays) {
  ASSERT_TRUE(chromiumInstalled()) << "chromium is not installed: scripts/setup.sh installs it";
  TempDir dir;
  // A square robot translating from left to right across an empty room, then turning.
  Scene s;
  s.name = "viewer test";
  s.bounds = {0, 0, 20, 10};
  s.obstacles.push_back({{9, 8}, {11, 8}, {11, 10}, {9, 10}});
  Robot r;
  r.name = "box";
  r.shape = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  r.start = {3, 3, 0};
  r.goal = {17, 3, 0};
  s.robots.push_back(r);
  Path p;
  p.waypoints = {{3, 3, 0}, {17, 3, 0}};
  const std::string html = viewPage(s, p, dir);
  const std::string page = test::readFile(html);
  for (const char* external : {"http://", "https://", " src=", " href=", "import("})
    EXPECT_EQ(page.find(external), std::string::npos)
        << "the page must be self-contained: " << external;

  const Rgb robot{0xe8, 0x71, 0x0a};
  auto isRobot = [&](const std::vector<Rgb>& px, int w, Vec2 at) {
    const Rgb c = px[size_t(std::lround(at.y)) * size_t(w) + size_t(std::lround(at.x))];
    return std::abs(c.r - robot.r) < 24 && std::abs(c.g - robot.g) < 24 &&
           std::abs(c.b - robot.b) < 24;
  };
  for (double t : {0.0, 0.5, 1.0}) {
    int w = 0, h = 0;
    const auto px = screenshot(dir, html, "t=" + std::to_string(t), "820,500", w, h);
    ASSERT_FALSE(px.empty()) << "unreadable screenshot";
    const Vec2 expected = viewerPixel(s, {3 + 14 * t, 3});
    ASSERT_LT(expected.y, h);
    EXPECT_TRUE(isRobot(px, w, expected)) << "robot at t = " << t;
    // Where it is not: 4 units left and right of it, unless that is where it is.
    for (double dx : {-4.0, 4.0}) {
      const double x = 3 + 14 * t + dx;
      if (x > 0 && x < 20) {
        EXPECT_FALSE(isRobot(px, w, viewerPixel(s, {x, 3}))) << t << dx;
      }
    }
  }
}

// Thirty exact discs: the legend folds, and a robot named in the link is drawn in full while
// the others fade.
TEST(View, ARobotNamedInTheLinkStandsOutAmongMany) {
  ASSERT_TRUE(chromiumInstalled()) << "chromium is not installed: scripts/setup.sh installs it";
  TempDir dir;
  Scene s;
  s.name = "many discs";
  s.bounds = {0, 0, 20, 12};
  for (int i = 0; i < 30; ++i) {
    Robot r;
    r.name = "disc-" + std::to_string(i);
    r.disc = 0.5;
    r.shape = discStandIn({{0, 0}, 0.5});
    r.motion = Motion::Translate;
    r.start = {1.5 + 2 * (i % 6), 1.5 + 2 * (i / 6), 0};
    r.goal = {r.start.x + 1, r.start.y, 0};
    s.robots.push_back(r);
  }
  Path p;
  p.waypoints = {startConfig(s), goalConfig(s)};
  const std::string html = viewPage(s, p, dir);
  const std::string page = test::readFile(html);
  EXPECT_NE(page.find("<details><summary>30 robots</summary>"), std::string::npos);
  EXPECT_NE(page.find("data-robot=\"29\""), std::string::npos);

  int w = 0, h = 0;
  const auto px = screenshot(dir, html, "t=0&traces=0&robot=disc-7", "820,900", w, h);
  ASSERT_FALSE(px.empty());
  auto colourAt = [&](size_t robot) {
    const Vec2 at = viewerPixel(s, {s.robots[robot].start.x, s.robots[robot].start.y});
    return px[size_t(std::lround(at.y)) * size_t(w) + size_t(std::lround(at.x))];
  };
  auto hex = [](const std::string& c, int at) {
    return std::stoi(c.substr(1 + 2 * at, 2), nullptr, 16);
  };
  auto near = [&](Rgb got, const std::string& want, double alpha) {
    // `want` at `alpha` over white.
    const int rgb[3] = {got.r, got.g, got.b};
    for (int k = 0; k < 3; ++k)
      if (std::abs(rgb[k] - (alpha * hex(want, k) + (1 - alpha) * 255)) > 24) return false;
    return true;
  };
  EXPECT_TRUE(near(colourAt(7), robotColour(7), 1)) << "the robot named stands out";
  for (size_t other : {3u, 20u}) {
    EXPECT_TRUE(near(colourAt(other), robotColour(other), 0.25)) << "robot " << other << " fades";
  }
}

// #bench=N draws N frames and puts the mean time of one on the page, for measuring playback
// (the time itself is the benchmark's to judge, not a test's).
TEST(View, TheFrameMeterPutsATimeOnThePage) {
  ASSERT_TRUE(chromiumInstalled()) << "chromium is not installed: scripts/setup.sh installs it";
  TempDir dir;
  const Scene s = discGridScene(1, 40, 10);
  Path p;
  p.waypoints = {startConfig(s), goalConfig(s)};
  const std::string html = viewPage(s, p, dir);
  auto c = test::runCommand("chromium --headless --no-sandbox --disable-gpu --user-data-dir=" +
                            quote(dir.path("profile")) + " --dump-dom " +
                            quote("file://" + html + "#bench=20"));
  ASSERT_EQ(c.code, 0) << c.err;
  const size_t at = c.out.find("data-frame-ms=\"");
  ASSERT_NE(at, std::string::npos) << c.out.substr(0, 400);
  const double ms = std::stod(c.out.substr(at + 15));
  EXPECT_GT(ms, 0);
  EXPECT_NE(c.out.find("a frame in "), std::string::npos);
}

// A planning record's page (mms plan --record, mms view --record) in `dir`, with the record.
std::string recordPage(const Scene& s, const std::string& planner, TempDir& dir,
                       RecordFile& record) {
  const std::string sceneFile = dir.path("s.json"), pathFile = dir.path("p.json"),
                    recordFile = dir.path("r.json"), html = dir.path("v.html");
  saveScene(s, sceneFile);
  auto plan = runMms("plan " + quote(sceneFile) + " --planner " + planner + " -q -o " +
                     quote(pathFile) + " --record " + quote(recordFile));
  EXPECT_EQ(plan.code, 0) << plan.err;
  auto v = runMms("view " + quote(sceneFile) + " " + quote(pathFile) + " --record " +
                  quote(recordFile) + " -o " + quote(html));
  EXPECT_EQ(v.code, 0) << v.err;
  record = loadRecord(recordFile, s.robots.size());
  return html;
}

bool white(Rgb c) { return c.r > 245 && c.g > 245 && c.b > 245; }

// Any pixel within one of `at` not white.
bool drawnNear(const std::vector<Rgb>& px, int w, int h, Vec2 at) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int x = int(std::lround(at.x)) + dx, y = int(std::lround(at.y)) + dy;
      if (x >= 0 && y >= 0 && x < w && y < h && !white(px[size_t(y) * size_t(w) + size_t(x)]))
        return true;
    }
  return false;
}

// A point well inside a cell of a slice, away from where the robot stands at the start
// and the goal; the slice's stamp in `at`.
std::optional<Vec2> pointInASlice(const Scene& s, const PlanRecord& r, double& at) {
  const double scale = (kViewerCanvasWidth - 2 * kViewerPad) / s.bounds.width();
  const double reach = radius(s.robots[0].shape) + 4 / scale;
  Random rng(3);
  for (const RecordManifold& m : r.manifolds) {
    if (m.family != "slice") continue;
    for (int i = 0; i < 2000; ++i) {
      const Vec2 p{rng.uniform(s.bounds.xmin, s.bounds.xmax),
                   rng.uniform(s.bounds.ymin, s.bounds.ymax)};
      double margin;
      const bool in = test::insideCells(m.regions, p, margin);
      const Pose a = s.robots[0].start, b = s.robots[0].goal;
      if (in && margin > 4 / scale && std::hypot(p.x - a.x, p.y - a.y) > reach &&
          std::hypot(p.x - b.x, p.y - b.y) > reach) {
        at = m.at;
        return p;
      }
    }
  }
  return std::nullopt;
}

// The record's slider: a slice's cell is drawn from the moment the slice was built, not before.
TEST(View, ARecordShowsEachSliceFromTheMomentItWasBuilt) {
  ASSERT_TRUE(chromiumInstalled()) << "chromium is not installed: scripts/setup.sh installs it";
  TempDir dir;
  const Scene s = keyholeScene(2);
  RecordFile record;
  const std::string html = recordPage(s, "mms", dir, record);
  double at = 0;
  const auto p = pointInASlice(s, record.record, at);
  ASSERT_TRUE(p) << "no slice cell away from the robot";
  double length = record.record.seconds;
  for (const RecordManifold& m : record.record.manifolds) length = std::max(length, double(m.at));
  const Vec2 q = viewerPixel(s, *p);
  for (const auto& [rt, shown] : {std::pair{0.0, false}, {0.5 * at / length, false}, {1.0, true}}) {
    int w = 0, h = 0;
    const auto px =
        screenshot(dir, html, "fit=0&t=0&traces=0&layers=cells&angle=all&rt=" + std::to_string(rt),
                   "820,900", w, h);
    ASSERT_FALSE(px.empty());
    ASSERT_LT(q.y, h);
    const Rgb c = px[size_t(std::lround(q.y)) * size_t(w) + size_t(std::lround(q.x))];
    EXPECT_EQ(!white(c), shown) << "planning at " << rt << " of the run, pixel " << c.r << ","
                                << c.g << "," << c.b;
  }
}

// A sampler's record: its tree's edges appear as the slider passes the time they were found.
TEST(View, ARecordShowsASamplersTreeAsItGrew) {
  ASSERT_TRUE(chromiumInstalled()) << "chromium is not installed: scripts/setup.sh installs it";
  TempDir dir;
  const Scene s = keyholeScene(1, 0.3);
  RecordFile record;
  const std::string html = recordPage(s, "rrtconnect", dir, record);
  const RecordTree& t = record.record.tree;
  ASSERT_GT(t.edges.size(), 5u);
  int w = 0, h = 0, w1 = 0, h1 = 0;
  const auto before = screenshot(dir, html, "fit=0&t=0&traces=0&layers=tree&rt=0", "820,900", w, h);
  const auto after =
      screenshot(dir, html, "fit=0&t=0&traces=0&layers=tree&rt=1", "820,900", w1, h1);
  ASSERT_FALSE(before.empty() || after.empty());
  size_t checked = 0;
  for (const auto& e : t.edges) {
    const Config &a = t.states[e[0]], &b = t.states[e[1]];
    const Vec2 pa = viewerPixel(s, {a[0], a[1]}), pb = viewerPixel(s, {b[0], b[1]});
    if (std::hypot(pa.x - pb.x, pa.y - pb.y) < 6) continue;  // too short to tell from its ends
    const Vec2 mid = viewerPixel(s, {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2});
    if (mid.y >= h || drawnNear(before, w, h, mid)) continue;  // an obstacle or a robot there
    ++checked;
    EXPECT_TRUE(drawnNear(after, w, h, mid)) << "edge " << e[0] << "-" << e[1];
    if (checked == 20) break;
  }
  EXPECT_GT(checked, 3u);
}

// The page as a headless Chromium leaves it (window 1200 x 900), after its scripts ran.
std::string pageDom(TempDir& dir, const std::string& html, const std::string& hash) {
  auto c = test::runCommand(
      "chromium --headless --no-sandbox --disable-gpu --window-size=1200,900 "
      "--virtual-time-budget=5000 --user-data-dir=" +
      quote(dir.path("profile")) + " --dump-dom " + quote("file://" + html + "#" + hash));
  EXPECT_EQ(c.code, 0) << c.err;
  return c.out;
}

// The first number after `key` in `text`, or -1.
double numberAfter(const std::string& text, const std::string& key) {
  const size_t at = text.find(key);
  return at == std::string::npos ? -1 : std::stod(text.substr(at + key.size()));
}

// The slice angle of the record nearest `theta`, round the circle.
double nearestSliceAngle(const PlanRecord& r, double theta) {
  double best = 0, apart = 1e9;
  for (const RecordManifold& m : r.manifolds) {
    if (m.family != "slice") continue;
    const double d = std::abs(std::remainder(m.theta - theta, 2 * M_PI));
    if (d < apart) best = m.theta, apart = d;
  }
  return best;
}

// A record's page in a window of 1200 x 900: the scene's picture keeps most of the window's
// height, with the 3-D view open beside it too (it once shrank to a thumbnail of 80 x 47 px);
// one robot's slices are by default the one nearest its angle at the motion's moment (every
// angle stacked into one wash hid the scene); #angle=X picks the slice nearest X rad (it once
// took X as an index); the growth chart has its axes.
TEST(View, ARecordPageKeepsTheSceneLargeAndShowsTheSliceAtTheRobotsAngle) {
  ASSERT_TRUE(chromiumInstalled()) << "chromium is not installed: scripts/setup.sh installs it";
  TempDir dir;
  const Scene s = keyholeScene(2);
  RecordFile record;
  const std::string html = recordPage(s, "mms", dir, record);
  for (const char* hash : {"", "cspace=1"}) {
    const std::string dom = pageDom(dir, html, hash);
    const size_t view = dom.find("<canvas id=\"view\"");
    ASSERT_NE(view, std::string::npos) << dom.substr(0, 400);
    const double width = numberAfter(dom.substr(view), "width: "),
                 height = numberAfter(dom.substr(view), "height: ");
    EXPECT_GE(height, 600) << hash;
    if (std::string(hash).empty()) continue;
    // The 3-D view beside it, both within the window.
    const size_t cspace = dom.find("<div id=\"cspace\" style=\"display: block;\"><canvas");
    ASSERT_NE(cspace, std::string::npos) << dom.substr(0, 2000);
    EXPECT_LE(width + numberAfter(dom.substr(cspace), "width=\""), 1200);
  }
  auto label = [&](const std::string& hash) {
    const std::string dom = pageDom(dir, html, hash);
    const size_t at = dom.find("<p id=\"rlabel\"");
    return at == std::string::npos ? dom : dom.substr(at, dom.find("</p>", at) - at);
  };
  char want[96];
  for (const auto& [t, theta] :
       {std::pair{0, s.robots[0].start.theta}, {1, s.robots[0].goal.theta}}) {
    std::snprintf(want, sizeof want,
                  "cells of the slice at %.3f rad, nearest the robot's angle now",
                  nearestSliceAngle(record.record, theta));
    EXPECT_NE(label("t=" + std::to_string(t)).find(want), std::string::npos) << "t = " << t;
  }
  std::snprintf(want, sizeof want, "cells of the slice at %.3f rad ·",
                nearestSliceAngle(record.record, 0));
  EXPECT_NE(label("angle=0").find(std::string(want).substr(0, std::string(want).size() - 3)),
            std::string::npos);
  EXPECT_EQ(label("angle=0").find("nearest the robot"), std::string::npos);
  EXPECT_EQ(label("angle=all").find("cells of the slice"), std::string::npos);
  size_t built = 0;
  for (const auto& [kind, counts] : record.record.growth.counts) built += counts.back();
  const std::string dom = pageDom(dir, html, "");
  EXPECT_NE(dom.find("data-axes=\"0 to " + std::to_string(built) + " over 0 to "),
            std::string::npos)
      << dom.substr(dom.find("rgrowth"), 300);
}

// One robot's C-space in 3-D (three.js from Debian's libjs-three): what the record held at the
// slider's moment, counted by the page and drawn by WebGL (its pixels read back).
TEST(View, ARecordsThreeDimensionalViewGrowsWithThePlanning) {
  ASSERT_TRUE(chromiumInstalled()) << "chromium is not installed: scripts/setup.sh installs it";
  TempDir dir;
  const Scene s = keyholeScene(1);
  RecordFile record;
  const std::string html = recordPage(s, "mms", dir, record);
  ASSERT_NE(test::readFile(html).find("OrbitControls"), std::string::npos)
      << "libjs-three is not installed: scripts/setup.sh installs it";
  auto page = [&](const std::string& hash) { return pageDom(dir, html, hash); };
  auto attribute = [](const std::string& dom, const std::string& name) {
    const size_t at = dom.find(name + "=\"");
    return at == std::string::npos
               ? std::string("(none)")
               : dom.substr(at + name.size() + 2,
                            dom.find('"', at + name.size() + 2) - at - name.size() - 2);
  };
  size_t slices = 0, arcs = 0;
  for (const RecordManifold& m : record.record.manifolds) {
    slices += m.family == "slice";
    arcs += m.arcs.size();
  }
  const std::string start = page("cspace=1&ink=1&rt=0"), end = page("cspace=1&ink=1&rt=1");
  EXPECT_EQ(attribute(start, "data-cspace"), "0 slices, 0 arcs");
  EXPECT_EQ(attribute(end, "data-cspace"),
            std::to_string(slices) + " slices, " + std::to_string(arcs) + " arcs");
  const double before = std::stod(attribute(start, "data-cspace-ink")),
               after = std::stod(attribute(end, "data-cspace-ink"));
  EXPECT_GT(before, 0) << "the frame, the obstacles and the path";
  EXPECT_GT(after, before + 500) << "the slices, arcs and path add to them";
}

}  // namespace
}  // namespace mms
