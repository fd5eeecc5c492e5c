// Translating parts and three-handed disassembly (issue 6): the 4-D recursion on interlocked
// parts, `mms assemble` on the paper's two assembly scenarios, the exact one-part decision
// against a brute-force flood fill with the collision checker, and the files it writes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <queue>
#include <set>

#include "Support.h"
#include "assembly/Disassembly.h"
#include "graph/ConnectivityGraph.h"
#include "io/PathIO.h"
#include "io/SceneIO.h"
#include "manifolds/CellSampling.h"
#include "planner/TwoRobotPlanner.h"
#include "scenarios/Generators.h"

using namespace mms;
using namespace mms::test;

namespace {

Box partBox(const Scene& s, size_t robot, const Pose& p) {
  return boundingBox(placedRing(s.robots[robot].shape, p));
}

Box obstaclesBox(const Scene& s) {
  Box b = boundingBox(s.obstacles[0]);
  for (const Ring& o : s.obstacles) {
    const Box c = boundingBox(o);
    b = {std::min(b.xmin, c.xmin), std::min(b.ymin, c.ymin), std::max(b.xmax, c.xmax),
         std::max(b.ymax, c.ymax)};
  }
  return b;
}

// Moves between consecutive waypoints that change which robot moves.
int alternations(const std::vector<Config>& w) {
  int switches = 0, last = -1;
  for (size_t j = 1; j < w.size(); ++j) {
    const int moving = (w[j][0] != w[j - 1][0] || w[j][1] != w[j - 1][1]) ? 0 : 1;
    if (last >= 0 && moving != last) ++switches;
    last = moving;
  }
  return switches;
}

}  // namespace

TEST(ConnectivityGraph, IncrementalComponentsAgreeWithSearch) {
  ConnectivityGraph g;
  Random rng(5);
  for (int i = 0; i < 200; ++i) g.addNode({0, 0});
  for (int e = 0; e < 150; ++e) g.addEdge(rng.below(200), rng.below(200));
  for (int q = 0; q < 500; ++q) {
    const size_t a = rng.below(200), b = rng.below(200);
    EXPECT_EQ(g.connected(a, b), g.path(a, b).has_value()) << a << " " << b;
  }
}

TEST(CellSampling, PointsLieInTheirCell) {
  const Scene s = assemblyTwoScene(0.05, true);
  const SliceWorld world(s, 0);
  const Slice slice(world, exact::rationalAngleNear(0, 30));
  Random rng(3);
  ASSERT_GT(slice.fscCount(), 0u);
  int near = 0, towards = 0;
  for (size_t c = 0; c < slice.fscCount(); ++c)
    for (int k = 0; k < 50; ++k) {
      if (const auto p = samplePointNearVertex(slice, c, rng)) {
        EXPECT_EQ(slice.locate(*p), int(c));
        ++near;
      }
      const Vec2 target{rng.uniform(-4.5, 11.5), rng.uniform(-6, 7)};
      if (const auto p = pointTowards(slice, c, target, rng)) {
        EXPECT_EQ(slice.locate(*p), int(c));
        if (slice.locate(target) == int(c)) {
          EXPECT_EQ(p->x, target.x);
        }
        ++towards;
      }
    }
  EXPECT_GT(near, 0);
  EXPECT_GT(towards, 0);
}

// Round discs held side by side make cells whose boundary runs straight through some vertices
// (edges split where overlaid curves crossed): no corner there, and a point "near" such a vertex
// lies on the boundary, where no route in the cell can start. Points near vertices keep off the
// boundary.
TEST(CellSampling, PointsNearVerticesKeepOffTheBoundary) {
  auto distance = [](Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 d = b - a;
    const double len2 = d.x * d.x + d.y * d.y;
    const double t =
        len2 > 0 ? std::clamp(((p.x - a.x) * d.x + (p.y - a.y) * d.y) / len2, 0.0, 1.0) : 0;
    return std::hypot(p.x - a.x - t * d.x, p.y - a.y - t * d.y);
  };
  double nearest = INFINITY;
  int drawn = 0;
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    const Scene s = discsSwapScene(seed);
    const SliceWorld world(s, 0);
    const Slice base(world, exact::rationalAngleNear(0, 30));
    std::vector<MovedShape> held;
    for (size_t r = 1; r < s.robots.size(); ++r)
      held.push_back({r, 0, s.robots[r].shape, {s.robots[r].start.x, s.robots[r].start.y}});
    const Slice slice(base, held);
    Random rng(seed);
    for (size_t c = 0; c < slice.fscCount(); ++c)
      for (int k = 0; k < 400; ++k)
        if (const auto p = samplePointNearVertex(slice, c, rng)) {
          ++drawn;
          for (const Ring& r : slice.cell(c))
            for (size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
              nearest = std::min(nearest, distance(*p, r[j], r[i]));
        }
  }
  EXPECT_GT(drawn, 1000);
  EXPECT_GT(nearest, 1e-9);
}

TEST(Scenarios, AssemblyFilesMatchTheGeneratorAndValidate) {
  TempDir dir;
  for (const auto& [args, file] :
       {std::pair{"assembly-1", "assembly-1.json"}, std::pair{"assembly-2", "assembly-2.json"},
        std::pair{"assembly-2 --m-parts-only", "assembly-2-m-parts.json"}}) {
    const std::string out = dir.path(file);
    ASSERT_EQ(runMms(std::string("scenario ") + args + " -o " + quote(out)).code, 0) << args;
    EXPECT_EQ(readFile(out), readFile(scenario(std::string("assembly/") + file))) << file;
  }
  for (const char* slack : {"0.001", "0.15"})
    for (const char* name : {"assembly-1", "assembly-2"})
      EXPECT_EQ(runMms(std::string("scenario ") + name + " --slack " + slack + " -o " +
                       quote(dir.path("s.json")))
                    .code,
                0)
          << name << " " << slack;
  EXPECT_EQ(runMms("scenario assembly-1 --slack 0.5 -o " + quote(dir.path("x.json"))).code, 2);
}

// Neither hooked part of assembly 1 can leave while the other stays put: the exact one-part
// decision (one slice) against a flood fill over a grid of placements, each tested by the
// collision checker, that must stay inside the static part's box.
TEST(Assembly, OnePartAloneIsStuckExactlyAndByFloodFill) {
  const Scene s = assemblyOneScene(0.05);
  DisassemblySettings one;
  one.pairs = false;
  const DisassemblyResult r = DisassemblyPlanner(s, one).solve(Termination(planSeconds(20)));
  EXPECT_TRUE(r.steps.empty());
  EXPECT_EQ(r.stuck, (std::vector<size_t>{0, 1}));
  // Decided, not given up: each part's exact free space is the proof.
  EXPECT_EQ(r.stuckBecause,
            "A: cannot leave alone (its exact free space); B: cannot leave alone (its exact free "
            "space); pairs not tried (one part at a time)");
  const CollisionChecker checker(s);
  const Box box = obstaclesBox(s);
  for (size_t moving = 0; moving < 2; ++moving) {
    const size_t held = 1 - moving;
    const double h = 0.01;
    const Pose start = s.robots[moving].start;
    std::set<std::pair<int, int>> seen{{0, 0}};
    std::queue<std::pair<int, int>> todo;
    todo.push({0, 0});
    while (!todo.empty() && seen.size() < 100000) {
      const auto [i, j] = todo.front();
      todo.pop();
      const Pose p{start.x + i * h, start.y + j * h, start.theta};
      EXPECT_TRUE(partBox(s, moving, p).distance(box) == 0) << "escaped at " << i << "," << j;
      for (const auto& [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const std::pair<int, int> n{i + di, j + dj};
        const Pose q{start.x + n.first * h, start.y + n.second * h, start.theta};
        if (seen.count(n) || !checker.robotFree(moving, q) ||
            !checker.robotsDisjoint(moving, q, held, s.robots[held].start))
          continue;
        seen.insert(n);
        todo.push(n);
      }
    }
    EXPECT_LT(seen.size(), 200u) << "part " << moving << " should only rattle in place";
    EXPECT_GT(seen.size(), 4u);
  }
}

// Together they climb out of the shaft in alternation: every move gains at most twice the
// slack on the other part, so the certified path needs many turns.
TEST(Assembly, HookedPartsClimbOutInAlternation) {
  const Scene s = loadScene(scenario("assembly/assembly-1.json"));
  const CollisionChecker checker(s);
  for (int seed = 1; seed <= seedsToRun(3); ++seed) {
    TwoRobotSettings st;
    st.seed = uint64_t(seed);
    const TwoRobotResult r = TwoRobotPlanner(s, st).solve(Termination(planSeconds(60)));
    ASSERT_EQ(r.status, PlanStatus::Found) << "seed " << seed;
    EXPECT_TRUE(checkPath(s, checker, r.waypoints).ok);
    // The climb is 2.2 and each turn gains at most 2 * 0.05.
    EXPECT_GE(alternations(r.waypoints), 21) << "seed " << seed;
  }
}

TEST(Assembly, MixedRigidAndTranslatingRobots) {
  Scene s = loadScene(scenario("two-robots/pacman-0.5.json"));
  s.robots[1].motion = Motion::Translate;  // the square: both ends have angle 0
  const CollisionChecker checker(s);
  TwoRobotSettings st;
  const TwoRobotResult r = TwoRobotPlanner(s, st).solve(Termination(planSeconds(60)));
  ASSERT_EQ(r.status, PlanStatus::Found);
  EXPECT_TRUE(checkPath(s, checker, r.waypoints).ok);
  for (const Config& q : r.waypoints) EXPECT_EQ(q[5], 0.0);
}

// A rigid part that must turn to leave gets the rigid planner: the bar stands upright in a box
// whose one opening is a slot in its side, so it turns level on its way out.
TEST(Assembly, ARigidPartTurnsOnItsWayOut) {
  const Scene s = loadScene(scenario("assembly/turn-out.json"));
  const DisassemblyResult r = DisassemblyPlanner(s).solve(Termination(planSeconds(60)));
  ASSERT_TRUE(r.complete()) << r.stuckBecause;
  ASSERT_EQ(r.steps.size(), 1u);
  const CollisionChecker checker(r.finalScene);
  EXPECT_TRUE(checkPath(r.finalScene, checker, r.path).ok);
  EXPECT_GT(partBox(s, 0, poseOf(r.path.back(), 0)).distance(obstaclesBox(s)), 0);
  // Through the slot (0.6 high, 0.5 long) the bar of 3 x 0.3 lies within 30 degrees of level.
  bool level = false;
  for (const Config& q : r.path)
    if (std::abs(std::sin(q[2])) < 0.5 && q[0] > 2 && q[0] < 2.5) level = true;
  EXPECT_TRUE(level);
}

// A rigid part that cannot leave is tried with budgets that double pass by pass until the
// time limit, and the result says what was tried: here the upright bar's box is too narrow
// for it to turn level (1.5 wide for a bar of 3).
TEST(Assembly, AStuckRigidPartIsTriedUntilTheLimitAndSaysWhatWasTried) {
  Scene s = loadScene(scenario("assembly/turn-out.json"));
  s.obstacles[0][5] = {0.5, -2.0}, s.obstacles[0][6] = {0.5, 2.0};  // the box's inner left wall
  s.robots[0].start.x = s.robots[0].goal.x = 1.25;
  const double limit = 1.5;
  const DisassemblyResult r = DisassemblyPlanner(s).solve(Termination(limit));
  EXPECT_EQ(r.stuck, std::vector<size_t>{0});
  EXPECT_GE(r.seconds, limit * 0.9);
  EXPECT_GE(r.attempts, 2u) << r.stuckBecause;
  EXPECT_NE(r.stuckBecause.find("(the time limit)"), std::string::npos) << r.stuckBecause;
  EXPECT_NE(r.stuckBecause.find("rounds of the one-robot MMS"), std::string::npos)
      << r.stuckBecause;
}

// Assembly 2 with mms assemble: the triangles leave first (the one under the wide M needs it
// lifted: two hands), then the wide M ducks into the bottom-left pocket so the tall one can
// pass; the whole motion is certified by mms check, and the same seed writes the same files.
TEST(Assembly, AssembleCommandRemovesEveryPartOfAssemblyTwo) {
  TempDir dir;
  const std::string scene = quote(scenario("assembly/assembly-2.json"));
  const std::string out = dir.path("out"), svg = dir.path("a.svg");
  const std::string limit = " --time-limit " + std::to_string(planSeconds(60));
  const Outcome r =
      runMms("assemble " + scene + limit + " -q -o " + quote(out) + " --svg " + quote(svg));
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("every part removed"), std::string::npos) << r.out;
  const Outcome whole = runMms("check " + quote(out + "/disassembly.scene.json") + " " +
                               quote(out + "/disassembly.path.json"));
  EXPECT_EQ(whole.code, 0) << whole.out;
  const auto summary = nlohmann::json::parse(readFile(out + "/disassembly.json"));
  EXPECT_TRUE(summary["complete"].get<bool>());
  const size_t steps = summary["steps"].size();
  ASSERT_GE(steps, 3u);
  for (size_t k = 1; k <= steps; ++k) {
    const std::string stem = out + "/step-" + std::to_string(k);
    EXPECT_EQ(
        runMms("check " + quote(stem + ".scene.json") + " " + quote(stem + ".path.json")).code, 0)
        << "step " << k;
  }
  // The tall M leaves only after the wide M has been in the pocket (below the corridor).
  const Scene s = loadScene(out + "/disassembly.scene.json");
  const Path p = loadPath(out + "/disassembly.path.json", s);
  const Box box = obstaclesBox(s);
  bool ducked = false, tallOutAfterDuck = false;
  for (const Config& q : p.waypoints) {
    if (q[3 * 3 + 1] < -1.0 && partBox(s, 3, poseOf(q, 3)).distance(box) == 0) ducked = true;
    if (partBox(s, 4, poseOf(q, 4)).distance(box) > 0) {
      tallOutAfterDuck = ducked;
      break;
    }
  }
  EXPECT_TRUE(tallOutAfterDuck);
  for (size_t i = 0; i < s.robots.size(); ++i)
    EXPECT_GT(partBox(s, i, s.robots[i].goal).distance(box), 0) << s.robots[i].name;
  EXPECT_NE(readFile(svg).find("animateTransform"), std::string::npos);
  if (kSanitized) return;  // a second run costs minutes there; the Release build checks it
  const std::string again = dir.path("again");
  ASSERT_EQ(runMms("assemble " + scene + limit + " -q -o " + quote(again)).code, 0);
  EXPECT_EQ(readFile(again + "/disassembly.path.json"), readFile(out + "/disassembly.path.json"));
}

TEST(Assembly, StuckPartsAreNamedAndBadInputRejected) {
  TempDir dir;
  const std::string a1 = quote(scenario("assembly/assembly-1.json"));
  const Outcome stuck = runMms("assemble " + a1 + " --no-pairs -q -o " + quote(dir.path("o")));
  EXPECT_EQ(stuck.code, 1);
  EXPECT_NE(stuck.out.find("stuck: A, B"), std::string::npos) << stuck.out;
  const std::string noStatic =
      dir.file("empty.json",
               R"({"format": "mms-scene/1", "bounds": [0, 0, 10, 10], "obstacles": [],
          "robots": [{"shape": [[0,0],[1,0],[0,1]], "start": [5,5,0], "goal": [5,5,0],
                      "motion": "translate"}]})");
  const Outcome bad = runMms("assemble " + quote(noStatic) + " -o " + quote(dir.path("p")));
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("empty.json: obstacles:"), std::string::npos) << bad.err;
  const std::string file = dir.file("plain", "x");
  const Outcome notDir = runMms("assemble " + a1 + " -o " + quote(file));
  EXPECT_EQ(notDir.code, 2);
  EXPECT_NE(notDir.err.find("(output)"), std::string::npos) << notDir.err;
}

TEST(Assembly, ExpandShareIsAnOptionOfPlanAndIsRecorded) {
  TempDir dir;
  const std::string scene = quote(scenario("translating/cup.json")), stats = dir.path("s.json");
  ASSERT_EQ(
      runMms("plan " + scene + " -q --planner mms --expand-share 0 --stats-json " + quote(stats))
          .code,
      0);
  EXPECT_EQ(nlohmann::json::parse(readFile(stats))["parameters"]["expand_share"], 0.0);
  const Outcome bad = runMms("plan " + scene + " --expand-share 1.5");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--expand-share"), std::string::npos) << bad.err;
}
