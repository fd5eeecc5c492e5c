// Foreign formats: OMPL.app problems (the real ones from ../shared when present, and small
// COLLADA files written here), discopygal scenes, OMPL.app .path export.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "Support.h"
#include "check/PathChecker.h"
#include "geometry/PolygonOps.h"
#include "io/AnyScene.h"
#include "io/Collada.h"
#include "io/Discopygal.h"
#include "io/OmplApp.h"
#include "io/OmplAppCfg.h"
#include "io/PathIO.h"
#include "io/SceneIO.h"
#include "mms/Errors.h"

namespace mms {
namespace {

using test::quote;
using test::runMms;
using test::TempDir;

const std::string kOmplApp = test::sourceDir() + "/../shared/data/omplapp-2d";

// A COLLADA square [0,2]x[0,1] in the X/Z plane, extruded along Y (top, bottom and side faces),
// under a node that scales by 10 and translates by (5, 0, -3).
const char* kSquareDae = R"(<?xml version="1.0"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
 <library_geometries><geometry id="g"><mesh>
  <source id="pos"><float_array id="pa" count="24">0 0 0  0.2 0 0  0.2 0 0.1  0 0 0.1  0 1 0  0.2 1 0  0.2 1 0.1  0 1 0.1</float_array>
   <technique_common><accessor source="#pa" count="8" stride="3"/></technique_common></source>
  <vertices id="v"><input semantic="POSITION" source="#pos"/></vertices>
  <triangles count="6"><input semantic="VERTEX" source="#v" offset="0"/>
   <p>0 1 2  0 2 3  4 5 6  4 6 7  0 1 5  0 5 4</p></triangles>
 </mesh></geometry></library_geometries>
 <library_visual_scenes><visual_scene id="s"><node><node>
  <matrix>10 0 0 5  0 10 0 0  0 0 10 -3  0 0 0 1</matrix>
  <instance_geometry url="#g"/></node></node></visual_scene></library_visual_scenes>
 <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>)";

std::string cfgText(const std::string& robot, const std::string& world, bool withGoal = true) {
  return "[problem]\nname = Square\nrobot = " + robot + "\nworld = " + world +
         "\nstart.x = -5\nstart.y = 0\nstart.theta = 0\n" +
         (withGoal ? "goal.x = -5\ngoal.y = 5\ngoal.theta = 1.5\n" : "") +
         "volume.min.x = -10\nvolume.min.y = -10\nvolume.max.x = 10\nvolume.max.y = 10\n"
         "[planner]\naps=\naps=\n";
}

TEST(Import, ColladaMeshBecomesTheExactUnionOfItsTriangles) {
  TempDir dir;
  dir.file("square.dae", kSquareDae);
  const std::string cfg = dir.file("square.cfg", cfgText("square.dae", "square.dae"));
  ImportNotes notes;
  const Scene s = importOmplApp(cfg, notes);
  ASSERT_EQ(s.obstacles.size(), 1u);
  // x = 10 * X + 5 in [5, 7], y = 10 * Z - 3 in [-3, -2]: four corners, nothing else.
  const Ring& o = s.obstacles[0];
  ASSERT_EQ(o.size(), 4u);
  for (Vec2 v : o) {
    EXPECT_TRUE(v.x == 5 || v.x == 7) << v.x;
    EXPECT_TRUE(v.y == -3 || v.y == -2) << v.y;
  }
  // The robot is centred on its vertices' mean (OMPL.app's reference point): (6, -2.5).
  for (Vec2 v : s.robots[0].shape) {
    EXPECT_DOUBLE_EQ(std::abs(v.x), 1.0);
    EXPECT_DOUBLE_EQ(std::abs(v.y), 0.5);
  }
  EXPECT_EQ(s.robots[0].goal.theta, 1.5);
  bool sideFaces = false;
  for (const std::string& w : notes.warnings) sideFaces |= w.find("zero-area") != std::string::npos;
  EXPECT_TRUE(sideFaces) << "the side faces are dropped, with a note";
}

TEST(Import, BadOmplAppInputIsOneLineNamingFileAndField) {
  TempDir dir;
  dir.file("square.dae", kSquareDae);
  dir.file("broken.dae", "<COLLADA><library_geometries>");
  struct Case {
    std::string cfg, expect;
  } cases[] = {
      {cfgText("square.dae", "square.dae", false), "goal.x: missing"},
      {cfgText("square.dae", "nothere.dae"), "no such mesh file in " +
                                                 std::filesystem::canonical(dir.path("")).string() +
                                                 " (meshes are looked for beside the .cfg file)"},
      {cfgText("square.dae", "broken.dae"), "broken.dae: (XML"},
      {"[other]\nx = 1\n", "[problem]: no such section"},
      {cfgText("square.dae", "square.dae") + "", ""},
  };
  for (const Case& c : cases) {
    const std::string cfg = dir.file("p.cfg", c.cfg);
    auto r = runMms("import " + quote(cfg) + " -o " + quote(dir.path("out.json")));
    if (c.expect.empty()) {
      EXPECT_EQ(r.code, 0) << r.err;
      continue;
    }
    EXPECT_EQ(r.code, 2) << c.expect;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

// OMPL.app's objective has no place in a scene: the import says what becomes of it.
TEST(Import, OmplAppObjectiveIsNotDroppedSilently) {
  TempDir dir;
  dir.file("square.dae", kSquareDae);
  std::string cfg = cfgText("square.dae", "square.dae");
  cfg.insert(cfg.find("start.x"), "objective = length\nobjective.threshold = 0.0\n");
  auto r = runMms("import " + quote(dir.file("p.cfg", cfg)) + " -o " + quote(dir.path("o.json")));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("objective = length is what mms plan optimises by default"),
            std::string::npos)
      << r.err;
  cfg.replace(cfg.find("= length"), 8, "= maximize_min_clearance");
  r = runMms("import " + quote(dir.file("q.cfg", cfg)) + " -o " + quote(dir.path("o.json")));
  EXPECT_NE(r.err.find("objective = maximize_min_clearance is not one mms optimises"),
            std::string::npos)
      << r.err;
}

// The real problems: present in the project's workspace, absent from a user's clone.
std::vector<std::string> omplAppProblems() {
  std::vector<std::string> cfgs;
  if (!std::filesystem::is_directory(kOmplApp)) return cfgs;
  for (const auto& e : std::filesystem::directory_iterator(kOmplApp))
    if (e.path().extension() == ".cfg") cfgs.push_back(e.path().string());
  std::sort(cfgs.begin(), cfgs.end());
  return cfgs;
}

TEST(Import, EveryOmplAppProblemImportsAndItsOwnSolutionsAreFree) {
  const auto cfgs = omplAppProblems();
  if (cfgs.empty())
    GTEST_SKIP() << "OMPL.app's problems are not here (" << kOmplApp
                 << " is absent: they are third-party data kept outside the repository)";
  ASSERT_GE(cfgs.size(), 7u);
  size_t certified = 0;
  for (const std::string& cfg : cfgs) {
    ImportNotes notes;
    const Scene s = importOmplApp(cfg, notes);  // validated inside
    EXPECT_EQ(s.robots.size(), 1u) << cfg;
    EXPECT_GT(s.obstacles.size(), 0u) << cfg;
    // OMPL.app's own solution paths (x y theta per line) are an independent reference for the
    // conversion: where OMPL.app checked them at a fine resolution, every state must be free
    // here too, and most paths certify as continuous motions.
    const std::string pathFile = cfg.substr(0, cfg.size() - 4) + ".path";
    if (!std::filesystem::exists(pathFile) ||
        notes.warnings.end() !=
            std::find_if(notes.warnings.begin(), notes.warnings.end(), [](const std::string& w) {
              return w.find("convex hull") != std::string::npos;
            }))
      continue;
    std::ifstream in(pathFile);
    Path p;
    for (std::string line; std::getline(in, line);) {
      std::istringstream l(line);
      Config q(3);
      if (l >> q[0] >> q[1] >> q[2]) p.waypoints.push_back(q);
    }
    ASSERT_GT(p.waypoints.size(), 2u) << pathFile;
    const CollisionChecker checker(s);
    for (const Config& q : p.waypoints) EXPECT_TRUE(checker.isFree(q)) << pathFile;
    Scene query = s;
    query.robots[0].start = {p.waypoints.front()[0], p.waypoints.front()[1],
                             p.waypoints.front()[2]};
    query.robots[0].goal = {p.waypoints.back()[0], p.waypoints.back()[1], p.waypoints.back()[2]};
    certified += checkPath(query, CollisionChecker(query), p.waypoints).ok;
  }
  EXPECT_GE(certified, 3u) << "BugTrap, Maze and RandomPolygons' solutions certify";
}

TEST(Import, EveryOmplAppProblemIsPlannedWithACertifiedPath) {
  const auto cfgs = omplAppProblems();
  if (cfgs.empty())
    GTEST_SKIP() << "OMPL.app's problems are not here (" << kOmplApp << " is absent)";
  TempDir dir;
  for (const std::string& cfg : cfgs) {
    const std::string out = dir.path("p.json");
    auto r = runMms("plan " + quote(cfg) + " -q --seed 1 --time-limit " +
                    std::to_string(test::planSeconds(60)) + " -o " + quote(out));
    ASSERT_EQ(r.code, 0) << cfg << ": " << r.err;
    auto c = runMms("check " + quote(cfg) + " " + quote(out));
    EXPECT_EQ(c.code, 0) << cfg << ": " << c.out << c.err;
    if (test::kSanitized) break;  // one problem suffices where everything runs 20x slower
  }
}

std::string discopygalScene() {
  return R"({"__class__": "Scene",
    "obstacles": [
      {"__class__": "ObstaclePolygon", "poly": [[-1, -1], [1, -1], [1, 1], [-1, 1], [-1, 1]], "data": {}},
      {"__class__": "ObstacleDisc", "location": [4, 4], "radius": 1.5, "data": {}}],
    "robots": [
      {"__class__": "RobotPolygon", "poly": [[0, 0], [1, 0], [0, 1]], "start": [-6, -6], "end": [6, -6], "data": {"name": "tri"}},
      {"__class__": "RobotDisc", "radius": 0.5, "start": [-6, 6], "end": [6, 6], "data": {}},
      {"__class__": "RobotRod", "length": 2, "start": [[-7, 0], 1.57], "end": [[5, 0], 0], "data": {}}],
    "metadata": {"version": "1.1.1", "solvers": "", "details": ""}})";
}

// discopygal's discs are exact discs in mms, not polygons: no note, and they go back as discs.
// Discs that touch at the start (radius 0.5 at spacing 1, as in multi-agent benchmarks) load.
TEST(Import, DiscRobotsAndDiscObstaclesStayDiscsBothWays) {
  std::string robots;
  for (int i = 0; i < 12; ++i)
    robots += std::string(i ? "," : "") +
              R"({"__class__": "RobotDisc", "radius": 0.5, "start": [)" + std::to_string(i) +
              R"(, 0], "end": [)" + std::to_string(i) + R"(, 5], "data": {}})";
  TempDir dir;
  const std::string file = dir.file(
      "discs.json",
      R"({"__class__": "Scene", "obstacles": [{"__class__": "ObstacleDisc", "location": [5.5, 2.5], "radius": 0.75, "data": {}}], "robots": [)" +
          robots + "]}");
  ImportNotes notes;
  const Scene s = importDiscopygal(file, notes);
  for (const std::string& w : notes.warnings) EXPECT_EQ(w.find("-gon"), std::string::npos) << w;
  ASSERT_EQ(s.robots.size(), 12u);
  for (const Robot& r : s.robots) EXPECT_EQ(r.disc, 0.5);
  ASSERT_NE(s.obstacleDisc(0), nullptr);
  EXPECT_EQ(s.obstacleDisc(0)->radius, 0.75);

  ImportNotes exportNotes;
  const nlohmann::json out = nlohmann::json::parse(discopygalJson(s, exportNotes));
  EXPECT_EQ(out["obstacles"][0]["__class__"], "ObstacleDisc");
  EXPECT_EQ(out["robots"][3]["__class__"], "RobotDisc");
  EXPECT_EQ(out["robots"][3]["radius"], 0.5);
  ImportNotes again;
  const Scene t = importDiscopygal(dir.file("back.json", out.dump()), again);
  ASSERT_EQ(t.robots.size(), 12u);
  EXPECT_EQ(t.robots[11].disc, 0.5);
  EXPECT_EQ(t.robots[11].goal.y, 5);
  ASSERT_NE(t.obstacleDisc(0), nullptr);
  EXPECT_EQ(t.obstacleDisc(0)->center.x, 5.5);
}

TEST(Import, DiscopygalScenesConvertConservatively) {
  TempDir dir;
  const std::string file = dir.file("d.json", discopygalScene());
  ImportNotes notes;
  const Scene s = importDiscopygal(file, notes);
  ImportNotes detected;
  EXPECT_EQ(sceneToJson(loadAnyScene(file, detected)), sceneToJson(s))
      << "any scene reader recognises discopygal by content";
  ASSERT_EQ(s.obstacles.size(), 2u);
  EXPECT_EQ(s.obstacles[0].size(), 4u) << "the repeated vertex dropped";
  // The disc's polygon contains the disc: every edge is at least the radius from the centre.
  auto inradius = [](const Ring& r, Vec2 c) {
    double d = INFINITY;
    for (size_t i = 0; i < r.size(); ++i) {
      Vec2 a = r[i], b = r[(i + 1) % r.size()];
      double len = std::hypot(b.x - a.x, b.y - a.y);
      d = std::min(d, std::abs((b.x - a.x) * (a.y - c.y) - (a.x - c.x) * (b.y - a.y)) / len);
    }
    return d;
  };
  EXPECT_GE(inradius(s.obstacles[1], {4, 4}), 1.5 * (1 - 1e-12)) << "the disc's stand-in";
  ASSERT_NE(s.obstacleDisc(1), nullptr);
  EXPECT_EQ(s.obstacleDisc(1)->radius, 1.5);
  EXPECT_EQ(s.obstacleDisc(0), nullptr);
  ASSERT_EQ(s.robots.size(), 3u);
  EXPECT_EQ(s.robots[0].name, "tri");
  EXPECT_EQ(s.robots[0].motion, Motion::Translate);
  EXPECT_EQ(s.robots[1].motion, Motion::Translate);
  EXPECT_GE(inradius(s.robots[1].shape, {0, 0}), 0.5 * (1 - 1e-12));
  EXPECT_EQ(s.robots[1].disc, 0.5);
  // The rod: rigid, from its first end (the reference point) along theta, inside the rectangle.
  const Robot& rod = s.robots[2];
  EXPECT_EQ(rod.motion, Motion::Rigid);
  EXPECT_EQ(rod.start.theta, 1.57);
  EXPECT_TRUE(insideRing(rod.shape, {1.0, 0.0})) << "the rod's middle";
  double xmin = INFINITY, xmax = -INFINITY;
  for (Vec2 v : rod.shape) xmin = std::min(xmin, v.x), xmax = std::max(xmax, v.x);
  EXPECT_EQ(xmin, 0);
  EXPECT_EQ(xmax, 2);

  // The command refuses the rod, which rotates, unless told to write it translating; then it
  // writes the same document as the library. It refuses a path.
  const std::string viaCli = dir.path("cli.json");
  auto refused = runMms("export " + quote(file) + " --to discopygal -q -o " + quote(viaCli));
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.err.find("robots[2] ('" + rod.name + "'): rotates"), std::string::npos)
      << refused.err;
  EXPECT_FALSE(std::filesystem::exists(viaCli));
  auto ex = runMms("export " + quote(file) + " --to discopygal --force -q -o " + quote(viaCli));
  ASSERT_EQ(ex.code, 0) << ex.err;
  ImportNotes cliNotes;
  EXPECT_EQ(test::readFile(viaCli), discopygalJson(s, cliNotes));
  auto withPath = runMms("export " + quote(file) + " " + quote(file) + " --to discopygal -o " +
                         quote(dir.path("never.json")));
  EXPECT_EQ(withPath.code, 2);
  EXPECT_FALSE(std::filesystem::exists(dir.path("never.json")));

  // Export and import again: the obstacles, the bounds (written as four walls, read back as
  // the bounds, so that round trips do not grow them) and the robots' ends survive.
  ImportNotes exportNotes;
  const std::string back = dir.file("back.json", discopygalJson(s, exportNotes));
  ImportNotes again;
  const Scene t = importDiscopygal(back, again);
  EXPECT_EQ(t.obstacles.size(), s.obstacles.size());
  EXPECT_EQ(t.bounds.xmin, s.bounds.xmin);
  EXPECT_EQ(t.bounds.ymin, s.bounds.ymin);
  EXPECT_EQ(t.bounds.xmax, s.bounds.xmax);
  EXPECT_EQ(t.bounds.ymax, s.bounds.ymax);
  ImportNotes twice;
  const Scene u = importDiscopygal(dir.file("twice.json", discopygalJson(t, twice)), twice);
  EXPECT_EQ(u.bounds.xmax - u.bounds.xmin, s.bounds.xmax - s.bounds.xmin) << "no growth";
  ASSERT_EQ(t.robots.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(t.robots[i].start.x, s.robots[i].start.x);
    EXPECT_EQ(t.robots[i].goal.y, s.robots[i].goal.y);
  }
}

TEST(Import, BadDiscopygalInputIsOneLineNamingTheField) {
  TempDir dir;
  struct Case {
    std::string text, expect;
  } cases[] = {
      {R"({"__class__": "Scene", "obstacles": [], "robots": [{"__class__": "RobotBlob", "data": {}}], "metadata": {}})",
       "robots[0].__class__: unknown robot class 'RobotBlob'"},
      {R"({"__class__": "Scene", "obstacles": [{"__class__": "ObstacleDisc", "location": [0, 0], "radius": -1, "data": {}}], "robots": [], "metadata": {}})",
       "obstacles[0].radius: must be positive"},
      {R"({"__class__": "Scene", "obstacles": [], "metadata": {}})", "robots"},
  };
  for (const Case& c : cases) {
    const std::string f = dir.file("bad.json", c.text);
    auto r = runMms("import " + quote(f) + " -o " + quote(dir.path("o.json")));
    EXPECT_EQ(r.code, 2) << c.text;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.path("o.json")));
  }
}

TEST(Import, OmplPathExportHasOneStatePerLine) {
  TempDir dir;
  const std::string scene = test::scenario("one-robot/bar-slot.json");
  const std::string path = test::scenario("one-robot/bar-slot.path.json");
  const std::string out = dir.path("bar.path");
  auto r =
      runMms("export " + quote(scene) + " " + quote(path) + " --to ompl-path -o " + quote(out));
  ASSERT_EQ(r.code, 0) << r.err;
  const Path p = loadPath(path, loadScene(scene));
  std::istringstream in(test::readFile(out));
  size_t lines = 0;
  for (std::string line; std::getline(in, line); ++lines) {
    std::istringstream l(line);
    Config q(3);
    ASSERT_TRUE(l >> q[0] >> q[1] >> q[2]) << line;
    EXPECT_EQ(q, p.waypoints[lines]);
  }
  EXPECT_EQ(lines, p.waypoints.size());
  auto two = runMms("export " + quote(test::scenario("two-robots/niche-swap.json")) + " " +
                    quote(test::scenario("two-robots/niche-swap.path.json")) +
                    " --to ompl-path -o " + quote(dir.path("x.path")));
  EXPECT_EQ(two.code, 2) << "one rigid robot only";
}

// OMPL turns the short way between states and keeps angles in [-pi, pi): an exported path
// must say the same motion there. Random paths with turns of up to three full circles.
TEST(Import, OmplPathExportDescribesTheSameMotion) {
  Scene s;
  s.bounds = {-10, -10, 10, 10};
  s.robots.push_back({"r", test::rect(-0.5, -0.1, 0.5, 0.1), {0, 0, 0}, {0, 0, 0}, Motion::Rigid});
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> at(-9, 9), turn(-6 * M_PI, 6 * M_PI);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Config> w(2 + rng() % 6, Config(3));
    double theta = turn(rng);
    for (Config& q : w) {
      q = {at(rng), at(rng), theta};
      theta += trial % 4 == 0 ? std::round(turn(rng) / M_PI) * M_PI : turn(rng);  // exact pi too
    }
    const std::string text = omplPathText(w);
    const std::vector<Config> back = parseOmplPath(text, "p.path", s);
    const std::vector<Config> split = splitLongTurns(w);
    ASSERT_EQ(back.size(), split.size()) << text;
    // The same waypoints, every angle moved by one whole number of turns: the same motion.
    const double offset = back[0][2] - split[0][2];
    EXPECT_NEAR(std::remainder(offset, 2 * M_PI), 0, 1e-9);
    for (size_t k = 0; k < back.size(); ++k) {
      EXPECT_NEAR(back[k][0], split[k][0], 1e-9);
      EXPECT_NEAR(back[k][1], split[k][1], 1e-9);
      EXPECT_NEAR(back[k][2] - split[k][2], offset, 1e-9) << "state " << k << " of\n" << text;
    }
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
      std::istringstream l(line);
      double x, y, theta;
      ASSERT_TRUE(l >> x >> y >> theta) << line;
      EXPECT_TRUE(theta >= -M_PI && theta < M_PI) << line;
    }
    // The split path is the original: every waypoint kept in order, the others on its segments.
    size_t kept = 0;
    for (const Config& q : split)
      if (kept < w.size() && q == w[kept]) ++kept;
    EXPECT_EQ(kept, w.size());
  }
  std::istringstream lines(omplPathText({{0, 0, 0}, {0, 0, 4}}));
  size_t n = 0;
  for (std::string line; std::getline(lines, line); ++n) {
    std::istringstream l(line);
    double x, y, theta;
    ASSERT_TRUE(l >> x >> y >> theta);
    EXPECT_GE(theta, -M_PI);
    EXPECT_LT(theta, M_PI);
  }
  EXPECT_EQ(n, 3u) << "a turn of 4 rad in two parts";
}

// Every bundled one-robot scene with a path: exported, read back, certified again.
TEST(Import, EveryBundledOneRobotPathSurvivesTheOmplPathRoundTrip) {
  TempDir dir;
  for (const std::string name : {"bar-slot", "corridor-corner", "bug-trap", "maze"}) {
    const std::string scene = quote(test::scenario("one-robot/" + name + ".json")),
                      json = dir.path(name + ".json"), text = dir.path(name + ".path");
    const auto plan = runMms("plan " + scene + " --planner mms -q --time-limit " +
                             std::to_string(test::planSeconds(30)) + " -o " + quote(json));
    ASSERT_EQ(plan.code, 0) << name << ": " << plan.err;
    const auto out =
        runMms("export " + scene + " " + quote(json) + " --to ompl-path -q -o " + quote(text));
    ASSERT_EQ(out.code, 0) << name << ": " << out.err;
    const auto c = runMms("check " + scene + " " + quote(text));
    EXPECT_EQ(c.code, 0) << name << ": " << c.out << c.err;
  }
  // A certified turn the long way (0 to 4 rad in open space) is certified after the trip too,
  // and turns the same way: its rotation stays 4 rad.
  const std::string open = dir.file("open.json",
                                    R"({"format": "mms-scene/1", "bounds": [-10, -10, 10, 10],
          "obstacles": [[[3, -1], [4, -1], [4, 1], [3, 1]]],
          "robots": [{"name": "bar", "shape": [[-1, -0.1], [1, -0.1], [1, 0.1], [-1, 0.1]],
                      "start": [0, 0, 0], "goal": [0, 0, 4]}]})");
  const std::string turn = dir.file(
      "turn.json",
      R"({"format": "mms-path/1", "robots": ["bar"], "waypoints": [[0, 0, 0], [0, 0, 4]]})");
  ASSERT_EQ(runMms("check " + quote(open) + " " + quote(turn)).code, 0);
  ASSERT_EQ(runMms("export " + quote(open) + " " + quote(turn) + " --to ompl-path -q -o " +
                   quote(dir.path("turn.path")))
                .code,
            0);
  const auto c = runMms("check " + quote(open) + " " + quote(dir.path("turn.path")));
  EXPECT_EQ(c.code, 0) << c.out << c.err;
  EXPECT_NE(c.out.find("rotation 4 rad"), std::string::npos) << c.out;
}

// OMPL.app's .path files are read where mms reads paths: angles unwrapped as OMPL interpolates
// them (the short way), bad lines named; what mms exports reads back and certifies.
TEST(Import, OmplPathFilesAreReadUnwrappedAndCheckedLineByLine) {
  const Scene s = loadScene(test::scenario("one-robot/bar-slot.json"));
  const std::vector<Config> w = parseOmplPath("1 2 3.1\n\n1 2 -3.1\n1 2.5 3.0\n", "p.path", s);
  ASSERT_EQ(w.size(), 3u);
  EXPECT_NEAR(w[1][2], 3.1 + (2 * M_PI - 6.2), 1e-12);  // across pi, not back round
  EXPECT_NEAR(w[2][2], w[1][2] + std::remainder(3.0 - w[1][2], 2 * M_PI), 1e-12);
  auto error = [&](const std::string& text) {
    try {
      parseOmplPath(text, "p.path", s);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error("1 2 3\n1 x 3\n"), "p.path: line 2: 'x' is not a number");
  EXPECT_EQ(error("1 2 3 4\n"),
            "p.path: line 1: expected 3 numbers (x y theta per robot, x y for one that "
            "translates), found 4");
  EXPECT_NE(error("\n \n").find("no waypoints"), std::string::npos);

  TempDir dir;
  const std::string scene = quote(test::scenario("one-robot/bar-slot.json")),
                    json = dir.path("p.json"), text = dir.path("p.path");
  ASSERT_EQ(runMms("plan " + scene + " -q -o " + quote(json)).code, 0);
  ASSERT_EQ(
      runMms("export " + scene + " " + quote(json) + " --to ompl-path -q -o " + quote(text)).code,
      0);
  const auto c = runMms("check " + scene + " " + quote(text));
  EXPECT_EQ(c.code, 0) << c.out << c.err;
  // A path mms wrote (JSON) under the name FILE.path reads as JSON.
  const std::string named = dir.path("mine.path");
  ASSERT_EQ(runMms("plan " + scene + " -q -o " + quote(named)).code, 0);
  const auto mine = runMms("check " + scene + " " + quote(named));
  EXPECT_EQ(mine.code, 0) << mine.out << mine.err;
  const auto bad = runMms("check " + scene + " " + quote(dir.file("bad.path", "0 0 0\n1 1\n")));
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("bad.path: line 2: expected 3 numbers"), std::string::npos) << bad.err;
  const auto cfgs = omplAppProblems();
  if (cfgs.empty()) {
    std::printf("OMPL.app's problems are absent (%s): their .path files not read\n",
                kOmplApp.c_str());
    return;
  }
  const auto maze = runMms("check " + quote(kOmplApp + "/Maze_planar.cfg") + " " +
                           quote(kOmplApp + "/Maze_planar.path"));
  EXPECT_EQ(maze.code, 0) << maze.out << maze.err;
}

// discopygal scenes have no bounds: the import invents a box unless told one.
TEST(Import, DiscopygalBoundsCanBeGiven) {
  TempDir dir;
  const std::string file = dir.file("d.json", discopygalScene()), out = dir.path("out.json");
  auto r = runMms("import " + quote(file) + " --bounds -20,-10,20,10 -o " + quote(out));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("bounds: none in discopygal"), std::string::npos) << r.err;
  const Scene s = loadScene(out);
  EXPECT_EQ(s.bounds.xmin, -20);
  EXPECT_EQ(s.bounds.ymin, -10);
  EXPECT_EQ(s.bounds.xmax, 20);
  EXPECT_EQ(s.bounds.ymax, 10);
  // Too small for the robots: named, one line, nothing written.
  const std::string small = dir.path("small.json");
  r = runMms("import " + quote(file) + " --bounds -3,-3,3,3 -o " + quote(small));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("(with --bounds -3,-3,3,3): robots[0].start: robot 'tri' is not inside"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(small));
  for (const std::string bad : {"1,2,3", "0,0,a,1", "5,0,1,1"}) {
    r = runMms("import " + quote(file) + " --bounds " + bad + " -o " + quote(small));
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_NE(r.err.find("--bounds: '"), std::string::npos) << r.err;
  }
}

// Found by fuzzing the readers: each was an exception other than InputError or a stack overflow.
TEST(Import, FuzzedReadersFailWithOneLine) {
  auto error = [](auto&& read) {
    try {
      read();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // The INI reader read the section's name on past "]" (here a NUL): no [problem] section.
  EXPECT_EQ(error([] { parseOmplAppProblem(std::string("[problem]\0x\n[a]\n", 15), "f.cfg"); }),
            "f.cfg: [problem]: no such section");
  // A <vertices> whose POSITION input is itself.
  const std::string loop = R"(<COLLADA><library_geometries><geometry id="g"><mesh>
    <vertices id="v"><input semantic="POSITION" source="#v"/></vertices>
    <triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 0 0</p></triangles>
    </mesh></geometry></library_geometries><library_visual_scenes><visual_scene id="s"><node>
    <instance_geometry url="#g"/></node></visual_scene></library_visual_scenes></COLLADA>)";
  EXPECT_NE(error([&] { parseColladaPlanar(loop, "f.dae"); }).find("refer to each other in a loop"),
            std::string::npos);
  // A vertex index too large for an integer.
  std::string huge = kSquareDae;
  huge.replace(huge.find("<p>0 1 2"), 8, "<p>1e92 1 2");
  EXPECT_NE(error([&] { parseColladaPlanar(huge, "f.dae"); }).find("vertex index"),
            std::string::npos);
  // Elements nested 200 000 deep.
  std::string deep = "<COLLADA>";
  for (int i = 0; i < 200000; ++i) deep += "<a>";
  for (int i = 0; i < 200000; ++i) deep += "</a>";
  deep += "</COLLADA>";
  EXPECT_EQ(error([&] { parseColladaPlanar(deep, "f.dae"); }),
            "f.dae: <library_visual_scenes>: no visual scene");
}

// discopygal plans in the open plane: a disc that must walk round a wall spanning everything
// else is not walled in by the bounds the import makes, and the bounds are said once.
TEST(Import, DiscopygalBoundsLetEveryRobotPassRoundEverything) {
  TempDir dir;
  const std::string scene = R"({"__class__": "Scene",
    "obstacles": [{"__class__": "ObstaclePolygon", "poly": [[0, 4], [10, 4], [10, 6], [0, 6]]}],
    "robots": [{"__class__": "RobotDisc", "radius": 1, "start": [5, 2], "end": [5, 8]},
               {"__class__": "RobotDisc", "radius": 1, "start": [2, 1.5], "end": [8, 8.5]}]})";
  const std::string file = dir.file("wall.json", scene), out = dir.path("out.json");
  auto r = runMms("import " + quote(file) + " -o " + quote(out));
  ASSERT_EQ(r.code, 0) << r.err;
  size_t said = 0;
  for (size_t at = r.err.find("bounds:"); at != std::string::npos;
       at = r.err.find("bounds:", at + 1))
    ++said;
  EXPECT_EQ(said, 1u) << r.err;
  const std::string note = r.err;
  const Scene s = loadScene(out);
  // Round the wall's end: a corridor at least a diameter (2) wide beyond x = 10 and x = 0.
  EXPECT_GE(s.bounds.xmax - 10, 2.0);
  EXPECT_LE(s.bounds.xmin, -2.0);
  const std::string path = dir.path("path.json");
  r = runMms("plan " + quote(out) + " --planner mms --seed 1 --time-limit 30 -o " + quote(path));
  EXPECT_EQ(r.code, 0) << r.err << r.out;
  EXPECT_TRUE(std::filesystem::exists(path));
  // The note and mms import --help say the same growth.
  const std::string growth = "largest robot's diameter and 10 % more";
  EXPECT_NE(note.find(growth), std::string::npos) << note;
  const auto help = runMms("import --help");
  std::string flat;  // the help wraps its lines
  for (const char c : help.out)
    if (c != '\n' && !(c == ' ' && !flat.empty() && flat.back() == ' ')) flat += c;
  EXPECT_NE(flat.find(growth), std::string::npos) << help.out;
}

}  // namespace
}  // namespace mms
