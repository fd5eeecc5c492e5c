// Property at scale: on random scenes (mms scenario random), every path a planner reports as
// found is certified by the continuous checker (what `mms check` runs), no planner throws, and
// every run ends near its time limit. 300 scenes per CI run (30 under the sanitizers); a
// nightly-style run takes more: MMS_PROPERTY_SCENES=5000 build/mms_tests --gtest_filter='*Random*'
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "Support.h"
#include "baselines/OmplPlanner.h"
#include "check/PathChecker.h"
#include "io/SceneIO.h"
#include "planner/OneRobotPlanner.h"
#include "planner/TwoRobotPlanner.h"
#include "scenarios/RandomScene.h"

namespace mms {
namespace {

using test::kSanitized;

constexpr int kShards = 10;

int scenesToCheck() {
  if (const char* env = std::getenv("MMS_PROPERTY_SCENES")) return std::max(1, std::atoi(env));
  return kSanitized ? 30 : 300;
}

struct PlanRun {
  bool found = false;
  std::vector<Config> waypoints;
  double seconds = 0;
};

PlanRun planMms(const Scene& scene, uint64_t seed, double limit) {
  Stopwatch clock;
  PlanRun run;
  if (scene.robots.size() == 1) {
    OneRobotSettings s;
    s.seed = seed;
    OneRobotPlanner planner(scene, 0, s);
    const OneRobotResult r =
        planner.solve(scene.robots[0].start, scene.robots[0].goal, Termination(limit));
    run.found = r.status == PlanStatus::Found;
    run.waypoints = r.waypoints;
  } else {
    TwoRobotSettings s;
    s.seed = seed;
    TwoRobotPlanner planner(scene, s);
    const TwoRobotResult r = planner.solve(Termination(limit));
    run.found = r.status == PlanStatus::Found;
    run.waypoints = r.waypoints;
  }
  run.seconds = clock.seconds();
  return run;
}

PlanRun planOmpl(const Scene& scene, uint64_t seed, double limit) {
  OmplSettings s;
  s.planner = "rrtconnect";
  s.seed = seed;
  Stopwatch clock;
  const OmplResult r = planWithOmpl(scene, s, Termination(limit));
  return {r.status == PlanStatus::Found, r.waypoints, clock.seconds()};
}

class RandomScenes : public testing::TestWithParam<int> {};

// Each shard takes every kShards-th scene, so ctest runs the shards in parallel.
TEST_P(RandomScenes, EveryReportedPathIsCertifiedAndRunsEndInTime) {
  const double limit = kSanitized ? 2.0 : 0.25;
  // The planners check their limit between manifolds and certify a found path before
  // returning: one manifold plus one certification may overrun it. The overrun itself is
  // measured by scripts/time-limits.sh; here only a run that ignores its limit fails.
  const double allowed = 2 * limit + 0.5;
  int found = 0, omplFound = 0, omplRuns = 0;
  for (int seed = 1 + GetParam(); seed <= scenesToCheck(); seed += kShards) {
    SCOPED_TRACE("mms scenario random --seed " + std::to_string(seed));
    const Scene scene = randomScene({uint64_t(seed)});
    ASSERT_NO_THROW(parseScene(sceneToJson(scene), "random")) << "generator made an invalid scene";
    const CollisionChecker checker(scene);
    // Ends near its limit; a path reported found passes the checker. Counts found paths.
    const auto judge = [&](const PlanRun& run, int& foundCount) {
      EXPECT_LT(run.seconds, allowed);
      if (!run.found) return;
      ++foundCount;
      const PathCheckResult c = checkPath(scene, checker, run.waypoints);
      EXPECT_TRUE(c.ok) << "segment " << c.segment << " at " << c.parameter << ": " << c.reason;
    };
    PlanRun mms;
    ASSERT_NO_THROW(mms = planMms(scene, seed, limit));
    judge(mms, found);
    if (seed / kShards % 5 == 0) {  // OMPL on every fifth scene: failing runs take the whole limit
      ++omplRuns;
      PlanRun ompl;
      ASSERT_NO_THROW(ompl = planOmpl(scene, seed, limit));
      judge(ompl, omplFound);
    }
  }
  std::printf("shard %d: MMS found %d paths, RRT-Connect %d of %d (all certified)\n", GetParam(),
              found, omplFound, omplRuns);
}

INSTANTIATE_TEST_SUITE_P(Shards, RandomScenes, testing::Range(0, kShards));

TEST(ScenarioRandom, SameSeedSameSceneAndOptionsAreChecked) {
  test::TempDir dir;
  const std::string a = dir.path("a.json"), b = dir.path("b.json"), c = dir.path("c.json");
  const std::string args = " --seed 17 --robots 2 --obstacles 200 -o ";
  ASSERT_EQ(test::runMms("scenario random" + args + test::quote(a)).code, 0);
  ASSERT_EQ(test::runMms("scenario random" + args + test::quote(b)).code, 0);
  EXPECT_EQ(test::readFile(a), test::readFile(b));
  ASSERT_EQ(test::runMms("scenario random --seed 18 -o " + test::quote(c)).code, 0);
  EXPECT_NE(test::readFile(a), test::readFile(c));
  const Scene scene = loadScene(a);  // valid, with what was asked for
  EXPECT_EQ(scene.robots.size(), 2u);
  EXPECT_EQ(scene.obstacles.size(), 200u);
  EXPECT_EQ(test::runMms("validate " + test::quote(a)).code, 0);
  const test::Outcome bad = test::runMms("scenario random --robots 3 -o " + test::quote(c));
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--robots"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace mms
