// Limits inside exact geometry: one slice among a thousand obstacles takes longer than a short
// time limit, so its construction must give way to the limit (StopScope / checkpoint), and the
// planners must then end with "not found" instead of running the slice to its end.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "Support.h"
#include "geometry/Exact.h"
#include "io/SceneIO.h"
#include "manifolds/Slice.h"
#include "mms/Planner.h"
#include "mms/Termination.h"
#include "planner/OneRobotPlanner.h"
#include "planner/TwoRobotPlanner.h"
#include "scenarios/Generators.h"
#include "scenarios/RandomScene.h"
#include "util/Deferred.h"

namespace mms {
namespace {

Scene crowded(int robots, int obstacles = 1000) { return randomScene({3, robots, obstacles}); }
/// For tests that also build a whole slice: one among a thousand obstacles takes about 1 s,
/// and 40-60 s under the sanitizers, where a third of them still takes far longer than the
/// short limits the tests set.
int obstaclesForWholeSlices() { return test::kSanitized ? 300 : 1000; }

// The default planner on the zigzag slot (a bar outside a room whose one way in bends too
// tightly for it: no solution, and none that a planner can prove) for 60 s under a memory limit,
// the path file to `out`.
test::Outcome planZigzagSlot(int memoryLimitMb, const std::string& out) {
  return test::runMms("plan " + test::quote(test::scenario("one-robot/zigzag-slot.json")) +
                      " --time-limit 60 --memory-limit " + std::to_string(memoryLimitMb) +
                      " -q -o " + test::quote(out));
}

TEST(Limits, SliceConstructionStopsAtTheScopesLimit) {
  const Scene scene = crowded(1, obstaclesForWholeSlices());
  ASSERT_EQ(scene.obstacles.size(), size_t(obstaclesForWholeSlices()));
  const SliceWorld world(scene, 0);
  const auto angle = exact::rationalAngleNear(0.3, 30);
  {
    const Termination expired(0);
    const StopScope scope(expired);
    EXPECT_THROW(Slice(world, angle), Stopped);
  }
  // Outside any scope nothing stops it, and the scope was closed on the way out.
  EXPECT_EQ(StopScope::current(), nullptr);
  const Slice whole(world, angle);
  EXPECT_GT(whole.fscCount(), 0u);
}

// What a limit cuts is not freed under the limit (tens of ms among 3000 obstacles) but kept
// until no planner runs.
TEST(Limits, ASliceCutByTheLimitIsFreedOnceNoPlannerRuns) {
  const Scene scene = crowded(1);
  const SliceWorld world(scene, 0);
  freeDeferred();
  {
    const Termination soon(0.05);
    const StopScope scope(soon);
    EXPECT_THROW(Slice(world, exact::rationalAngleNear(0.3, 30)), Stopped);
  }
  EXPECT_GT(deferredCount(), 0u);
  {
    const RunningSolve running;
    freeDeferredIfIdle();
    EXPECT_GT(deferredCount(), 0u);  // a planner runs: its limit must not pay
  }
  freeDeferredIfIdle();
  EXPECT_EQ(deferredCount(), 0u);
}

// A planner asked again (another query, a restart, another thread's run) frees what earlier
// limits cut when it starts, so a long-lived planner does not keep one cut slice per run.
TEST(Limits, WhatALimitCutIsFreedWhenTheNextRunStarts) {
  const Scene scene = crowded(1);
  freeDeferred();
  const auto planner = makePlanner("mms", scene);
  EXPECT_FALSE(planner->solve(Termination(0.05)).found());
  EXPECT_GT(deferredCount(), 0u);  // the first slice among 1000 obstacles takes about 1 s
  // The flag outlives the planner: a regression then fails here, not in a dangling write.
  const auto freed = std::make_shared<bool>(false);
  freeLater(std::shared_ptr<const int>(new int(0), [freed](const int* p) {
    *freed = true;
    delete p;
  }));
  EXPECT_FALSE(planner->solve(Termination(0.05)).found());
  EXPECT_TRUE(*freed);
  EXPECT_GT(deferredCount(), 0u);  // the second run's own cut slice, freed with the planner
}

TEST(Limits, OneRobotPlannerEndsWhenTheLimitStrikesInsideASlice) {
  const Scene scene = crowded(1, obstaclesForWholeSlices());
  OneRobotPlanner planner(scene, 0, {});
  const OneRobotResult r =
      planner.solve(scene.robots[0].start, scene.robots[0].goal, Termination(0.001));
  EXPECT_EQ(r.status, PlanStatus::NotFound);
  EXPECT_EQ(planner.slices().size(), 0u);  // the slice under way was dropped
  EXPECT_EQ(StopScope::current(), nullptr);
  // The planner stays usable: a second query with time builds slices. The sanitizers slow
  // slices more than the usual tenfold margin, so their budget is set apart.
  const OneRobotResult again = planner.solve(scene.robots[0].start, scene.robots[0].goal,
                                             Termination(test::kSanitized ? 300 : 5));
  EXPECT_GT(planner.slices().size(), 0u);
  if (again.status == PlanStatus::Found) {
    EXPECT_TRUE(again.certificate.ok);
  }
}

TEST(Limits, TwoRobotPlannerBuildsNothingBeforeSolve) {
  const Scene scene = crowded(2);
  TwoRobotPlanner planner(scene);
  const TwoRobotResult r = planner.solve(Termination(0.001));
  EXPECT_EQ(r.status, PlanStatus::NotFound);
  EXPECT_EQ(r.stats.subspaces, 0u);
  // The base slices were not built before solve(): what they took lies within its time (the
  // one cut short by the limit counts).
  EXPECT_LE(r.stats.baseSliceSeconds, r.stats.totalSeconds);
}

// A run the limit ends inside a slice still accounts for its time: the phases sum to it.
// Found by trying: on this generated scene and seed, five discs' first motion slides along
// contacts, and the certifier (pieces as short as the contact tolerance) took 37 s under a 5 s
// limit. The certifier now gives way to the planner's limit, and the phases still account for
// the time.
TEST(Limits, CertifyingAMotionAlongContactsStopsAtTheLimit) {
  const Scene scene = discsSwapScene(100);
  PlannerParams params;
  params.seed = 5571691718763357052ull;
  const double limit = 1.0;
  Stopwatch watch;
  const PlanResult r = makePlanner("mms", scene, params)->solve(Termination(limit));
  const double seconds = watch.seconds();
  EXPECT_LT(seconds, test::kSanitized ? 30 : limit + 0.5);
  if (r.found()) return;  // a machine fast enough to certify it in time
  double certify = 0, sum = 0;
  for (const auto& [name, s] : r.stats.phases) {
    sum += s;
    if (name == "certify") certify = s;
  }
  // Under the sanitizers the limit may strike before the motion is certified.
  if (!test::kSanitized) {
    EXPECT_GT(certify, 0.0);
  }
  EXPECT_GE(sum, 0.8 * r.stats.seconds);
}

TEST(Limits, PhasesAccountForARunTheLimitCutShortInsideASlice) {
  const Scene scene = crowded(1);
  for (const double limit : {0.05, 0.3}) {
    const PlanResult r = makePlanner("mms", scene)->solve(Termination(limit));
    EXPECT_EQ(r.status, PlanStatus::NotFound);
    double sum = 0;
    for (const auto& [name, seconds] : r.stats.phases) sum += seconds;
    EXPECT_GE(sum, 0.8 * r.stats.seconds) << "limit " << limit;
    EXPECT_LE(sum, r.stats.seconds * 1.001) << "limit " << limit;
  }
}

TEST(Limits, MemoryLimitEndsThePlanWithOutOfMemoryAndNoFile) {
  test::TempDir dir;
  const std::string scene = dir.path("crowded.json"), out = dir.path("path.json");
  ASSERT_EQ(
      test::runMms("scenario random --seed 4 --robots 2 --obstacles 3000 -o " + test::quote(scene))
          .code,
      0);
  const test::Outcome bad =
      test::runMms("plan " + test::quote(scene) + " --memory-limit 0.5 -o " + test::quote(out));
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--memory-limit"), std::string::npos) << bad.err;
  // The sanitizers reserve terabytes of address space at start-up: a cap on it cannot work
  // there, so the capped run itself is checked in the Release build only.
  if (test::kSanitized) return;
  // Unlimited, this run grows past 150 MB within seconds (3000 obstacles, two robots).
  const test::Outcome r = test::runMms(
      "plan " + test::quote(scene) + " --memory-limit 100 --time-limit 60 -o " + test::quote(out));
  EXPECT_EQ(r.code, 3) << r.out << r.err;
  // The message ends stderr. Before it, a run slowed by a loaded machine may have reported
  // progress (a round ending after 1 s, the heartbeat after 5 s); nothing else.
  const std::string message = "mms: out of memory (see --memory-limit); no output written\n";
  ASSERT_GE(r.err.size(), message.size()) << r.err;
  EXPECT_EQ(r.err.substr(r.err.size() - message.size()), message) << r.err;
  std::istringstream before(r.err.substr(0, r.err.size() - message.size()));
  for (std::string line; std::getline(before, line);)
    EXPECT_EQ(line.rfind("mms plan: ", 0), 0u) << line;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// The roadmap's memory grows with its manifolds, not with their meetings: a whole default run
// on a scene without a solution (the zigzag slot) fits in 1 GB and ends "not found" at its time
// limit. Before weaves it took 1.4 GB on the sealed ring, which is now proved to have no path.
TEST(Limits, AFullRunOnAnUnsolvableSceneStaysUnderAGigabyte) {
  if (test::kSanitized) return;  // the sanitizers reserve terabytes: no cap on address space
  test::TempDir dir;
  const std::string out = dir.path("path.json");
  const test::Outcome r = planZigzagSlot(1024, out);
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_EQ(r.err.find("out of memory"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// The default planner for 20 s on `scene`, which has no solution, under a 768 MB cap: it ends
// "not found", not out of memory, and writes no path.
void expectNotFoundWithin768Mb(const std::string& scene, const std::string& out) {
  const test::Outcome r =
      test::runMms("plan " + test::quote(scene) + " --time-limit 20 --memory-limit 768 -q -o " +
                   test::quote(out));
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_EQ(r.err.find("out of memory"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// Two robots on a scene without a solution (the zigzag slot's bar, and a square that could reach
// its goal on its own) build overlay slices as long as they run (one robot held, the other's
// slice minus its sum): 1.6 KB a slice. 20 s under 768 MB (here: 250 MB resident, 93 k slices)
// leaves a machine twice as fast its margin; at the 20 KB a slice overlays took with their
// arrangements it would need 2 GB.
TEST(Limits, TwoRobotsOnAnUnsolvableSceneStayLean) {
  if (test::kSanitized) return;  // the sanitizers reserve terabytes: no cap on address space
  test::TempDir dir;
  const std::string scene = dir.path("s.json"), out = dir.path("path.json");
  Scene s = loadScene(test::scenario("one-robot/zigzag-slot.json"));
  s.robots.push_back({"a", test::rect(-0.4, -0.4, 0.4, 0.4), {-8, 8, 0}, {0, 8, 0}, Motion::Rigid});
  saveScene(s, scene);
  expectNotFoundWithin768Mb(scene, out);
}

// Three robots on a scene without a solution (the zigzag slot's bar, and two squares that could
// reach their goals on their own) build tuples and their overlays as long as they run. Each base
// slice keeps its non-convex held sums but only the last few convex ones: 20 s under 768 MB
// (here: about 300 MB, and 740 MB after the default 60 s; keeping every sum took 1.35 GB in 60 s
// on a three-robot niche).
TEST(Limits, ThreeRobotsOnAnUnsolvableSceneStayLean) {
  if (test::kSanitized) return;  // the sanitizers reserve terabytes: no cap on address space
  test::TempDir dir;
  const std::string scene = dir.path("s.json"), out = dir.path("path.json");
  Scene s = loadScene(test::scenario("one-robot/zigzag-slot.json"));
  const Ring square{{-0.4, -0.4}, {0.4, -0.4}, {0.4, 0.4}, {-0.4, 0.4}};
  s.robots.push_back({"a", square, {-8, 8, 0}, {0, 8, 0}, Motion::Rigid});
  s.robots.push_back({"b", square, {8, -8, 0}, {0, -8, 0}, Motion::Rigid});
  saveScene(s, scene);
  expectNotFoundWithin768Mb(scene, out);
}

// Every planner under any cap ends on its own terms: a path (0), none (1) or out of memory (3)
// with the one line and no file, never by a signal (OMPL's PRM once aborted: its roadmap
// thread was left joinable by an allocation that failed beside it).
TEST(Limits, EveryPlannerUnderAnyMemoryLimitEndsWithoutASignal) {
  if (test::kSanitized) return;  // the sanitizers reserve terabytes: no cap on address space
  test::TempDir dir;
  const std::string scene = test::quote(test::scenario("two-robots/niche-swap.json")),
                    out = dir.path("path.json");
  const std::string message = "mms: out of memory (see --memory-limit); no output written\n";
  for (const PlannerInfo& p : planners())
    for (const int mb : {16, 32, 64, 128}) {
      const std::string what = p.name + " under " + std::to_string(mb) + " MB";
      std::filesystem::remove(out);
      const test::Outcome r =
          test::runMms("plan " + scene + " -q --time-limit 1 --planner " + p.name +
                       " --memory-limit " + std::to_string(mb) + " -o " + test::quote(out));
      EXPECT_TRUE(r.code == 0 || r.code == 1 || r.code == 3) << what << ": " << r.code << r.err;
      EXPECT_EQ(std::filesystem::exists(out), r.code == 0) << what;
      if (r.code == 3) {
        EXPECT_EQ(r.err, message) << what;
      }
    }
}

// The default planner runs a second thread; where memory runs out there, the run still ends
// with the one-line message and exit 3 (glibc once aborted: the library a second thread's
// unwinding needs could no longer be loaded).
TEST(Limits, ThePortfolioRunsOutOfMemoryCleanly) {
  if (test::kSanitized) return;  // the sanitizers reserve terabytes: no cap on address space
  test::TempDir dir;
  const std::string out = dir.path("path.json");
  const test::Outcome r = planZigzagSlot(80, out);
  EXPECT_EQ(r.code, 3) << r.out << r.err;
  EXPECT_EQ(r.err, "mms: out of memory (see --memory-limit); no output written\n");
  EXPECT_FALSE(std::filesystem::exists(out));
}

// The portfolio's second thread starts after the scene and the planner took most of the cap:
// the allocator must not crash making that thread's arena (jemalloc once did, at 80 MB on 2000
// discs), whatever cap the run meets it at.
TEST(Limits, AThreadStartedNearTheCapEndsCleanly) {
  if (test::kSanitized) return;  // the sanitizers reserve terabytes: no cap on address space
  test::TempDir dir;
  const std::string scene = dir.path("grid.json"), out = dir.path("path.json");
  saveScene(discGridScene(1, 2000, 5), scene);
  for (int mb = 72; mb <= 100; mb += 4) {
    const test::Outcome r = test::runMms("plan " + test::quote(scene) + " -q --memory-limit " +
                                         std::to_string(mb) + " -o " + test::quote(out));
    EXPECT_TRUE(r.code == 0 || r.code == 3) << mb << " MB: " << r.code << r.err;
    EXPECT_EQ(std::filesystem::exists(out), r.code == 0) << mb << " MB";
    std::filesystem::remove(out);
  }
}

// A scene too large for the cap is named as such, not taken for a planner that grew: 50 000
// disc robots (a 5 MB file) cannot even be read within 40 MB.
TEST(Limits, ASceneTooLargeForTheMemoryLimitIsNamed) {
  if (test::kSanitized) return;  // the sanitizers reserve terabytes: no cap on address space
  test::TempDir dir;
  const std::string scene = dir.path("crowd.json"), out = dir.path("path.json");
  {
    std::ofstream f(scene);
    f << R"({"format": "mms-scene/1", "bounds": [0, 0, 1000, 1000], "obstacles": [], "robots": [)";
    for (int i = 0; i < 50000; ++i) {
      const double x = 1.5 + 3 * (i % 300), y = 1.5 + 3 * (i / 300);
      f << (i ? "," : "") << R"({"name": "d)" << i << R"(", "disc": 1, "start": [)" << x << ", "
        << y << R"(, 0], "goal": [)" << x << ", " << y << ", 0]}";
    }
    f << "]}";
  }
  const test::Outcome r =
      test::runMms("plan " + test::quote(scene) + " --memory-limit 40 -o " + test::quote(out));
  EXPECT_EQ(r.code, 3) << r.out << r.err;
  EXPECT_EQ(r.err, "mms: " + scene +
                       ": does not fit in --memory-limit 40 MB (out of memory while reading it); "
                       "no output written\n");
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace mms

namespace mms {

// An output that cannot be written is refused before any work: the scene is not even read
// (it does not exist either, and the message is about the output), so no plan is lost.
TEST(Limits, UnwritableOutputsAreRefusedBeforeThePlanStarts) {
  test::TempDir dir;
  const std::string missingScene = test::quote(dir.path("absent.json"));
  for (const std::string option : {"-o", "--svg", "--stats-json"}) {
    const test::Outcome r =
        test::runMms("plan " + missingScene + " " + option + " " + dir.path("no/such/out"));
    EXPECT_EQ(r.code, 2) << option;
    EXPECT_NE(r.err.find("(" + option + "): cannot write here: folder"), std::string::npos)
        << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  const test::Outcome folder = test::runMms("plan " + missingScene + " -o " + dir.path(""));
  EXPECT_EQ(folder.code, 2);
  EXPECT_NE(folder.err.find("it is a folder"), std::string::npos) << folder.err;
}

}  // namespace mms

namespace mms {

// One manifold among thousands of obstacles takes longer than the planners' progress reports
// come (between manifolds): a long silent run still says it is working, within its limit.
TEST(Limits, ALongManifoldStillShowsProgress) {
  test::TempDir dir;
  const std::string scene = dir.path("big.json");
  ASSERT_EQ(
      test::runMms("scenario random --seed 4 --robots 2 --obstacles 2000 -o " + test::quote(scene))
          .code,
      0);
  // The limit counts from the command's start (loading 2000 obstacles takes seconds under the
  // sanitizers), and a slice step that would end past it is not begun (its cost estimated from
  // the steps before, which a loaded machine inflates): with room to spare, the planner still
  // works past 5 s.
  const std::string limit = test::kSanitized ? "20" : "12";
  const test::Outcome r =
      test::runMms("plan " + test::quote(scene) + " --planner mms --time-limit " + limit + " -o " +
                   test::quote(dir.path("p.json")));
  // The line comes at the heartbeat's first wake past 5 s: 5.0 s on an idle machine, 5.1 s
  // and later under the sanitizers on a loaded one.
  EXPECT_NE(r.err.find("mms plan: 5."), std::string::npos) << r.err;
}

}  // namespace mms
