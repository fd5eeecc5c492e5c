// MMS for one robot: bundled scenes solved with certified paths, the sealed scene refused in
// time, the same seed giving the same path.
#include <gtest/gtest.h>
#include <sched.h>

#include <atomic>
#include <chrono>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>
#include <vector>

#include "Support.h"
#include "io/SceneIO.h"
#include "manifolds/Pivot.h"
#include "path/Optimize.h"
#include "planner/OneRobotPlanner.h"
#include "registry/Adapters.h"
#include "scenarios/Generators.h"

using namespace mms;
using namespace mms::test;

namespace {

OneRobotResult plan(const Scene& s, uint64_t seed, double seconds) {
  OneRobotSettings st;
  st.seed = seed;
  OneRobotPlanner planner(s, 0, st);
  return planner.solve(s.robots[0].start, s.robots[0].goal, Termination(seconds));
}

}  // namespace

class SolvableScene : public ::testing::TestWithParam<const char*> {};

TEST_P(SolvableScene, SolvedWithCertifiedPathsForSeveralSeeds) {
  const Scene s = loadScene(scenario(GetParam()));
  const CollisionChecker checker(s);
  for (uint64_t seed = 1; seed <= uint64_t(seedsToRun(4)); ++seed) {
    const OneRobotResult r = plan(s, seed, planSeconds(30));
    ASSERT_EQ(r.status, PlanStatus::Found) << GetParam() << " seed " << seed;
    // An independent check of what the planner returned.
    const PathCheckResult c = checkPath(s, checker, r.waypoints);
    EXPECT_TRUE(c.ok) << c.reason;
    EXPECT_GT(r.stats.manifolds.slices, 0u);
    EXPECT_GT(r.stats.graphEdges, 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(Bundled, SolvableScene,
                         ::testing::Values("one-robot/bar-slot.json",
                                           "one-robot/corridor-corner.json",
                                           "one-robot/bug-trap.json", "one-robot/maze.json"),
                         [](const auto& info) {
                           std::string n = info.param;
                           n = n.substr(n.find('/') + 1);
                           n = n.substr(0, n.find('.'));
                           for (char& ch : n)
                             if (ch == '-') ch = '_';
                           return n;
                         });

// The search runs once start and goal connect, not at the end of a round: on an open scene the
// first round is cut short, and the path lies on a few of the manifolds built.
TEST(Plan, SearchStopsBuildingOnceStartAndGoalConnect) {
  const Scene s = loadScene(scenario("one-robot/bar-slot.json"));
  const OneRobotSettings defaults;
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    const OneRobotResult r = plan(s, seed, planSeconds(30));
    ASSERT_EQ(r.status, PlanStatus::Found);
    EXPECT_EQ(r.stats.rounds, 1u);
    EXPECT_LT(r.stats.manifolds.lines, defaults.nLines / 2) << "seed " << seed;
    EXPECT_GE(r.stats.pathManifolds, 2u);
    EXPECT_LE(r.stats.pathManifolds, r.stats.manifolds.slices + r.stats.manifolds.lines);
  }
}

// MMS alone (the default planner's own test is below).
TEST(Plan, SameSeedSamePathFileDifferentSeedOtherwise) {
  TempDir dir;
  const std::string scene = quote(scenario("one-robot/bug-trap.json"));
  const std::string plan = "plan " + scene + " --planner mms";
  for (const char* name : {"a.json", "b.json"})
    ASSERT_EQ(runMms(plan + " --seed 5 -q -o " + quote(dir.path(name))).code, 0);
  ASSERT_EQ(runMms(plan + " --seed 6 -q -o " + quote(dir.path("c.json"))).code, 0);
  EXPECT_EQ(readFile(dir.path("a.json")), readFile(dir.path("b.json")));
  EXPECT_NE(readFile(dir.path("a.json")), readFile(dir.path("c.json")));
  // And the checker certifies the file the planner wrote.
  const Outcome c = runMms("check " + scene + " " + quote(dir.path("a.json")));
  EXPECT_EQ(c.code, 0) << c.out;
}

// A loaded machine changes how long each step takes, never which steps are taken: MMS and the
// optimiser count work, not time. Every core kept busy by twice as many spinning threads.
TEST(Plan, SamePathFileUnderLoad) {
  TempDir dir;
  const std::string keyhole = dir.path("keyhole.json"), niche = dir.path("niche.json");
  ASSERT_EQ(runMms("scenario keyhole --seed 2 -o " + quote(keyhole)).code, 0);
  ASSERT_EQ(runMms("scenario niche-swap --seed 1 -o " + quote(niche)).code, 0);
  auto planned = [&](const std::string& scene, const char* name) {
    const std::string out = dir.path(name);
    const Outcome r =
        runMms("plan " + quote(scene) + " --planner mms --seed 3 -q -o " + quote(out));
    EXPECT_EQ(r.code, 0) << scene << ": " << r.out << r.err;
    return readFile(out);
  };
  const std::string idleKeyhole = planned(keyhole, "k0.json"),
                    idleNiche = planned(niche, "n0.json");
  std::atomic<bool> stop{false};
  std::vector<std::thread> load;
  for (unsigned i = 0; i < 2 * std::max(1u, std::thread::hardware_concurrency()); ++i)
    load.emplace_back([&stop] {
      volatile double x = 1;
      while (!stop.load(std::memory_order_relaxed)) x = x * 1.0000001 + 1e-9;
    });
  const std::string busyKeyhole = planned(keyhole, "k1.json"),
                    busyNiche = planned(niche, "n1.json");
  stop = true;
  for (std::thread& t : load) t.join();
  EXPECT_EQ(busyKeyhole, idleKeyhole);
  EXPECT_EQ(busyNiche, idleNiche);
  EXPECT_FALSE(idleKeyhole.empty());
}

namespace {

nlohmann::json statisticsOf(const std::string& pathFile) {
  return nlohmann::json::parse(pathFile)["statistics"];
}

}  // namespace

// The default planner takes its sampler's path when the sampler, run alone with the same seed,
// finds one within its allowance (the budget of iterations, doubled for each round MMS alone
// grows through: the rounds it begins after its first, and the share of its last round's
// targets it met), and MMS's otherwise: on the allowance's edge, and on close races (the first
// path found had won them, and a keyhole or discs' swap went either way). The rule counts
// iterations and growth, so neither the member nor the file changes when the machine is
// loaded: planned idle, then squeezed onto one core beside two spinning threads.
TEST(Plan, DefaultPlannerSamePathFileUnderLoad) {
  TempDir dir;
  auto plan = [&](const std::string& scene, const std::string& options, const std::string& name) {
    const std::string out = dir.path(name);
    const Outcome r =
        runMms("plan " + quote(scene) + " --seed 1 -q " + options + " -o " + quote(out));
    EXPECT_EQ(r.code, 0) << scene << " " << options << ": " << r.out << r.err;
    return readFile(out);
  };
  const std::vector<std::pair<std::string, std::string>> scenes{
      {"keyhole", "1"}, {"discs-swap", "2"}, {"bend", "7"}, {"bend", "2"}};
  std::vector<std::string> files, idle;
  std::vector<size_t> alone;   // the sampler's iterations to its path, alone
  std::vector<size_t> rounds;  // the rounds MMS alone begins
  std::vector<double> share;   // of its last round's targets met
  for (const auto& [family, seed] : scenes) {
    files.push_back(dir.path(family + "-" + seed + ".json"));
    ASSERT_EQ(runMms("scenario " + family + " --seed " + seed + " -o " + quote(files.back())).code,
              0);
    // The portfolio's sampler, which among several robots (the discs) takes shorter motions.
    const std::string shorter = family == "discs-swap" ? " --range-share 0.1" : "";
    const nlohmann::json sampler = statisticsOf(
        plan(files.back(),
             "--planner rrtconnect --certified-motions --free-samples --lean-angles 0.5" + shorter,
             "sampler.json"));
    alone.push_back(sampler["counts"]["iterations"].get<size_t>());
    const nlohmann::json mms = statisticsOf(plan(files.back(), "--planner mms", "mms.json"));
    rounds.push_back(mms["rounds"].get<size_t>());
    share.push_back(mms["round_share"].get<double>());
    ASSERT_GE(rounds.back(), 1u);
    const double allowance = samplerAllowance(2000, rounds.back() - 1, share.back());
    idle.push_back(plan(files.back(), "", family + seed + "-idle.json"));
    EXPECT_EQ(statisticsOf(idle.back())["solved_by"],
              double(alone.back()) <= allowance ? "rrtconnect" : "mms")
        << files.back() << ": the sampler alone took " << alone.back() << " iterations, MMS "
        << rounds.back() << " rounds, " << share.back() << " of the last";
  }
  // The allowance's edge, exactly: the least budget that, doubled for MMS's growth, covers the
  // sampler's iterations.
  size_t edge = 1;
  while (samplerAllowance(edge, rounds.back() - 1, share.back()) < double(alone.back())) ++edge;
  EXPECT_EQ(statisticsOf(plan(files.back(), "--sampler-iterations " + std::to_string(edge),
                              "edge.json"))["solved_by"],
            "rrtconnect");
  EXPECT_EQ(statisticsOf(plan(files.back(), "--sampler-iterations " + std::to_string(edge - 1),
                              "below.json"))["solved_by"],
            "mms");

  cpu_set_t all, one;
  ASSERT_EQ(sched_getaffinity(0, sizeof all, &all), 0);
  CPU_ZERO(&one);
  CPU_SET(sched_getcpu(), &one);
  ASSERT_EQ(sched_setaffinity(0, sizeof one, &one), 0);  // the children inherit it
  std::atomic<bool> stop{false};
  std::vector<std::thread> load;
  for (int i = 0; i < 2; ++i)
    load.emplace_back([&stop] {
      volatile double x = 1;
      while (!stop.load(std::memory_order_relaxed)) x = x * 1.0000001 + 1e-9;
    });
  std::vector<std::string> busy;
  for (size_t i = 0; i < files.size(); ++i)
    busy.push_back(plan(files[i], "", std::to_string(i) + "-busy.json"));
  stop = true;
  for (std::thread& t : load) t.join();
  sched_setaffinity(0, sizeof all, &all);
  for (size_t i = 0; i < files.size(); ++i) EXPECT_EQ(busy[i], idle[i]) << files[i];
}

// Slices (one robot) and overlays (two robots) are built in parallel batches and added in
// order: the thread count must not change the roadmap, hence not the path file either.
TEST(Plan, SamePathFileWhateverTheThreadCount) {
  TempDir dir;
  const std::string random = dir.path("random.json");
  ASSERT_EQ(runMms("scenario random --seed 21 --robots 1 --obstacles 60 -o " + quote(random)).code,
            0);
  for (const std::string& scene :
       {scenario("one-robot/maze.json"), scenario("one-robot/bug-trap.json"), random,
        scenario("two-robots/pacman-0.5.json"), scenario("two-robots/viking-helmet.json")}) {
    std::string first;
    for (const char* threads : {"1", "2", "3"}) {
      const std::string out = dir.path(std::string("t") + threads + ".json");
      const Outcome r = runMms("plan " + quote(scene) + " --planner mms --seed 4 -q --threads " +
                               threads + " -o " + quote(out));
      ASSERT_EQ(r.code, 0) << scene << " --threads " << threads << ": " << r.out << r.err;
      if (first.empty())
        first = readFile(out);
      else
        EXPECT_EQ(readFile(out), first) << scene << " --threads " << threads;
    }
  }
}

TEST(Plan, UnreachableGoalEndsWithExitOneWithinTheTimeLimit) {
  TempDir dir;
  const auto t0 = std::chrono::steady_clock::now();
  const Outcome r = runMms("plan " + quote(scenario("one-robot/zigzag-slot.json")) +
                           " --time-limit 2 -o " + quote(dir.path("p.json")));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("no path found within 2 s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("slices"), std::string::npos);  // says what was built
  // ... what bounded the search, and what to try.
  EXPECT_NE(r.out.find("bounded by the time limit: most of it in "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("to try: --time-limit 4 "), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir.path("p.json")));
  EXPECT_LT(seconds, 2.0 + 3.0);  // the limit plus process start and a slow shared machine
}

TEST(Plan, TranslateOnlyRobotUsesItsExactFreeSpace) {
  Scene s;
  s.name = "translate";
  s.bounds = {0, 0, 10, 10};
  s.obstacles = {{{4, 0}, {6, 0}, {6, 8}, {4, 8}}};
  Robot r;
  r.name = "block";
  r.shape = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  r.start = {2, 2, 0.3};
  r.goal = {8, 2, 0.3};
  r.motion = Motion::Translate;
  s.robots = {r};
  const OneRobotResult found = plan(s, 1, 10);
  ASSERT_EQ(found.status, PlanStatus::Found);
  EXPECT_TRUE(found.stats.noPath.empty());
  for (const Config& q : found.waypoints) EXPECT_EQ(q[2], 0.3);
  EXPECT_EQ(found.stats.manifolds.slices, 1u);  // one exact slice, no sampling
  // Close the gap above the wall: the two sides are different cells and the answer is
  // immediate, not a time-out.
  s.obstacles = {{{4, 0}, {6, 0}, {6, 10}, {4, 10}}};
  const auto t0 = std::chrono::steady_clock::now();
  const OneRobotResult none = plan(s, 1, 30);
  EXPECT_EQ(none.status, PlanStatus::NotFound);
  EXPECT_NE(none.stats.noPath.find("robot 'block' only translates"), std::string::npos);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 10.0);
}

TEST(Plan, RoadmapAnswersASecondQueryWithoutRebuilding) {
  const Scene s = loadScene(scenario("one-robot/bug-trap.json"));
  OneRobotPlanner planner(s, 0, OneRobotSettings{});
  const Robot& r = s.robots[0];
  const OneRobotResult first = planner.solve(r.start, r.goal, Termination(30));
  ASSERT_EQ(first.status, PlanStatus::Found);
  const size_t slices = planner.slices().size();
  // The reverse query, and one to another free placement outside the trap.
  const OneRobotResult back = planner.solve(r.goal, r.start, Termination(30));
  ASSERT_EQ(back.status, PlanStatus::Found);
  const OneRobotResult other = planner.solve(r.start, {7, 6, 0}, Termination(30));
  ASSERT_EQ(other.status, PlanStatus::Found);
  EXPECT_EQ(planner.slices().size(), slices);  // answered from the existing slices
}

TEST(Plan, QueriesAreForOneRobotScenes) {
  TempDir dir;
  const Outcome r = runMms("plan " + quote(scenario("two-robots/niche-swap.json")) + " --queries " +
                           quote(dir.file("q.json", "{}")));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--queries is for one-robot scenes"), std::string::npos) << r.err;
}

TEST(Plan, QueriesFileAnswersEachQueryOnOneRoadmap) {
  TempDir dir;
  const std::string q = dir.file("q.json", R"({"format": "mms-queries/1", "queries": [
      {"start": [-2, 0, 1.5707963267948966], "goal": [7, 0, 1.5707963267948966]},
      {"start": [7, 0, 1.5707963267948966], "goal": [-7, -7, 0]}]})");
  const Outcome r = runMms("plan " + quote(scenario("one-robot/bug-trap.json")) + " -q --queries " +
                           quote(q) + " -o " + quote(dir.path("p.json")) + " --svg " +
                           quote(dir.path("p.svg")) + " --svg-roadmap");
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  for (const char* f : {"p.0.json", "p.1.json", "p.0.svg", "p.1.svg"})
    EXPECT_TRUE(std::filesystem::exists(dir.path(f))) << f;
  EXPECT_NE(readFile(dir.path("p.0.svg")).find("id=\"cells\""), std::string::npos);
  // Each answer is certified against its own query (the checker needs a scene with those ends).
  const nlohmann::json p1 = nlohmann::json::parse(readFile(dir.path("p.1.json")));
  EXPECT_EQ(p1["waypoints"].back()[0], -7);
  EXPECT_EQ(p1["waypoints"].front()[0], 7);
}

TEST(Plan, BadQueriesFileExitsTwoNamingTheField) {
  TempDir dir;
  const std::string q = dir.file("q.json", R"({"format": "mms-queries/1", "queries": [
      {"start": [-2, 0, 1.5707963267948966], "goal": [3.2, 0, 1.5707963267948966]}]})");
  const Outcome r =
      runMms("plan " + quote(scenario("one-robot/bug-trap.json")) + " --queries " + quote(q));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("q.json: queries[0].goal: robot 'bar' collides with obstacles["),
            std::string::npos)
      << r.err;
}

// A robot turning a bend needs a line where it can turn: a small region at the corridor's
// corner, next to where slice cells have vertices (placements touching two walls). Lines drawn
// near cell vertices reach it with far fewer manifolds than lines drawn anywhere in the cells
// (the same seeds, the same rounds otherwise; every path certified).
TEST(Plan, LinesNearCellVerticesTurnTheBendWithFewerManifolds) {
  std::vector<Scene> scenes;
  for (uint64_t k = 1; k <= 6; ++k) scenes.push_back(bendScene(k));
  scenes.push_back(loadScene(scenario("one-robot/corridor-corner.json")));
  size_t built[2] = {0, 0};
  for (const Scene& s : scenes) {
    const CollisionChecker checker(s);
    for (int corner = 0; corner < 2; ++corner) {
      OneRobotSettings st;
      st.cornerLineShare = corner ? 0.5 : 0.0;
      OneRobotPlanner planner(s, 0, st);
      const OneRobotResult r =
          planner.solve(s.robots[0].start, s.robots[0].goal, Termination(planSeconds(60)));
      ASSERT_EQ(r.status, PlanStatus::Found) << s.name;
      EXPECT_TRUE(checkPath(s, checker, r.waypoints).ok) << s.name;
      built[corner] += r.stats.manifolds.slices + r.stats.manifolds.lines;
    }
  }
  std::printf("manifolds built: %zu with lines near cell vertices, %zu without\n", built[1],
              built[0]);
  EXPECT_LT(2 * built[1], built[0]);
}

// A U that swallows a part and turns half round about it: with pivot lines (the U's pocket
// about the part) MMS connects in its second round, on a path through one of them; without,
// it needs the angles of four rounds to stair-step the turn.
TEST(Plan, PivotLinesTurnTheSwallowInTheSecondRound) {
  size_t with = 0, without = 0;
  for (uint64_t k = 1; k <= 4; ++k) {
    const Scene s = swallowScene(k);
    const CollisionChecker checker(s);
    for (const bool pivots : {true, false}) {
      OneRobotSettings st;
      st.pivotLines = pivots;
      OneRobotPlanner planner(s, 0, st);
      const OneRobotResult r =
          planner.solve(s.robots[0].start, s.robots[0].goal, Termination(planSeconds(60)));
      ASSERT_EQ(r.status, PlanStatus::Found) << s.name;
      EXPECT_TRUE(checkPath(s, checker, r.waypoints).ok) << s.name;
      (pivots ? with : without) += r.stats.rounds;
      if (!pivots) continue;
      EXPECT_GE(r.stats.pivotLines, 1u);
      bool used = false;
      for (const ConnectivityGraph::Node& n : r.cells)
        used |= &planner.roadmap().manifold(n.manifold).family() == &PivotLineManifold::kFamily;
      EXPECT_TRUE(used) << s.name;
    }
  }
  EXPECT_LE(with, 4 * 2u + 1);
  EXPECT_GT(without, with);
}

// A key must arrive and leave aligned with two slots and turns a quarter in a chamber barely
// larger than its turning circle. Spin places (its smallest circle's centre held where the
// clearance peaks) and slices at the start's and goal's angles give it the path a hand draws:
// along the start's angle, a quarter turn the short way in the chamber, along the goal's angle;
// in the first round and before any optimiser.
TEST(Plan, SpinPlacesTurnTheKeyTheShortWayInTheFirstRound) {
  for (uint64_t k = 1; k <= 4; ++k) {
    const Scene s = keyholeScene(k);
    const CollisionChecker checker(s);
    OneRobotPlanner planner(s, 0, OneRobotSettings{});
    const OneRobotResult r =
        planner.solve(s.robots[0].start, s.robots[0].goal, Termination(planSeconds(60)));
    ASSERT_EQ(r.status, PlanStatus::Found) << s.name;
    EXPECT_TRUE(checkPath(s, checker, r.waypoints).ok) << s.name;
    EXPECT_EQ(r.stats.rounds, 1u) << s.name;
    double rotation = 0;
    for (size_t i = 1; i < r.waypoints.size(); ++i)
      rotation += std::fabs(r.waypoints[i][2] - r.waypoints[i - 1][2]);
    EXPECT_LE(rotation, 1.05 * minimumRotation(s)) << s.name;
    EXPECT_GE(r.stats.pivotLines, 1u) << s.name;
  }
}
