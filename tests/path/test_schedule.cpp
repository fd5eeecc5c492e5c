// Robots moving at once (path/Schedule.h): a path's moves started as soon as the moves whose
// swept regions they may meet are done, against an independent reference (the collision checker
// at dense poses of the schedule), each robot's own motion unchanged; and the fleet's measures
// (check/PathChecker.h) against hand-computed ones.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "Support.h"
#include "check/PathChecker.h"
#include "mms/Planner.h"
#include "path/Schedule.h"
#include "scenarios/Generators.h"

using namespace mms;

namespace {

Robot disc(const std::string& name, double radius, Pose start, Pose goal) {
  Robot r;
  r.name = name;
  r.disc = radius;
  r.shape = {{-radius, -radius}, {radius, -radius}, {radius, radius}, {-radius, radius}};
  r.start = start;
  r.goal = goal;
  r.motion = Motion::Translate;
  return r;
}

// A robot's cost along the path, and the poses where it starts, stops or bends.
double robotCost(const CollisionChecker& checker, const std::vector<Config>& w, size_t robot) {
  double c = 0;
  for (size_t k = 1; k < w.size(); ++k)
    c += poseCost(checker, robot, poseOf(w[k - 1], robot), poseOf(w[k], robot));
  return c;
}

// Every segment of the schedule, at 64 poses each: the collision checker finds every robot
// free and every pair apart. Independent of the certifier, which the schedule also passes.
void expectFreeAtDensePoses(const Scene& s, const CollisionChecker& checker,
                            const std::vector<Config>& w) {
  for (size_t k = 1; k < w.size(); ++k)
    for (int j = 0; j <= 64; ++j) {
      const Config q = lerp(w[k - 1], w[k], j / 64.0);
      ASSERT_TRUE(checker.isFree(q)) << s.name << ": segment " << k << " at " << j / 64.0;
    }
}

}  // namespace

// Two discs far apart, moved one after the other: at once, the makespan the longer move.
TEST(Schedule, RobotsFarApartMoveAtOnce) {
  Scene s;
  s.name = "apart";
  s.bounds = {0, 0, 20, 20};
  s.robots = {disc("a", 1, {2, 2, 0}, {2, 8, 0}), disc("b", 1, {15, 2, 0}, {15, 6, 0})};
  const CollisionChecker checker(s);
  const std::vector<Config> sequential = {
      {2, 2, 0, 15, 2, 0}, {2, 8, 0, 15, 2, 0}, {2, 8, 0, 15, 6, 0}};
  ScheduleStats st;
  const std::vector<Config> w = concurrentSchedule(s, checker, sequential, &st);
  EXPECT_DOUBLE_EQ(st.makespanBefore, 10);
  EXPECT_DOUBLE_EQ(st.makespanAfter, 6);
  ASSERT_TRUE(checkPath(s, checker, w).ok);
  PathCheckResult m;
  measureFleet(s, checker, w, m);
  EXPECT_DOUBLE_EQ(m.makespan, 6);
  EXPECT_DOUBLE_EQ(m.makespanBound, 6);
  EXPECT_DOUBLE_EQ(m.distance, 10);
  EXPECT_DOUBLE_EQ(m.distanceBound, 10);
  // Both move for 4, then a alone for 2.
  EXPECT_NEAR(m.movingAtOnce, (4 * 2 + 2) / 6.0, 1e-12);
  measureFleet(s, checker, sequential, m);
  EXPECT_DOUBLE_EQ(m.makespan, 10);
  EXPECT_DOUBLE_EQ(m.movingAtOnce, 1);
}

// Disc b goes to where a stood, half a radius behind it, after a left: b follows a down the
// corridor, at once but never before a has gone on, and never closer than the certifier allows.
TEST(Schedule, ARobotFollowsTheOneAheadOfIt) {
  Scene s;
  s.name = "follow";
  s.bounds = {0, 0, 40, 4};
  s.robots = {disc("a", 1, {4.5, 2, 0}, {32.5, 2, 0}), disc("b", 1, {2, 2, 0}, {30, 2, 0})};
  const CollisionChecker checker(s);
  const std::vector<Config> sequential = {
      {4.5, 2, 0, 2, 2, 0}, {32.5, 2, 0, 2, 2, 0}, {32.5, 2, 0, 30, 2, 0}};
  ScheduleStats st;
  const std::vector<Config> w = concurrentSchedule(s, checker, sequential, &st);
  EXPECT_LT(st.makespanAfter, 0.6 * st.makespanBefore);
  EXPECT_GT(st.makespanAfter, 28);  // b waits for a to get ahead
  ASSERT_TRUE(checkPath(s, checker, w).ok);
  expectFreeAtDensePoses(s, checker, w);
  EXPECT_NEAR(robotCost(checker, w, 0), 28, 1e-9);
  EXPECT_NEAR(robotCost(checker, w, 1), 28, 1e-9);
}

// Two discs whose ways cross: the second sets off at once but reaches the crossing only once the
// first has passed it.
TEST(Schedule, CrossingWaysTakeTurnsAtTheCrossing) {
  Scene s;
  s.name = "cross";
  s.bounds = {0, 0, 20, 20};
  s.robots = {disc("a", 1, {2, 10, 0}, {18, 10, 0}), disc("b", 1, {10, 2, 0}, {10, 18, 0})};
  const CollisionChecker checker(s);
  const std::vector<Config> sequential = {
      {2, 10, 0, 10, 2, 0}, {18, 10, 0, 10, 2, 0}, {18, 10, 0, 10, 18, 0}};
  ScheduleStats st;
  const std::vector<Config> w = concurrentSchedule(s, checker, sequential, &st);
  EXPECT_LT(st.makespanAfter, st.makespanBefore);
  EXPECT_GT(st.makespanAfter, 16);  // not both at full speed: they would meet at (10, 10)
  ASSERT_TRUE(checkPath(s, checker, w).ok);
  expectFreeAtDensePoses(s, checker, w);
}

// Fleets planned one robot at a time (mms from 8 robots, the schedule off), then scheduled:
// every result certified and free at dense poses, each robot's own distance as planned, and the
// makespan no longer (on fresh-looking seeds of three families).
TEST(Schedule, FleetsPlannedOneAtATimeMoveAtOnce) {
  const std::vector<Scene> scenes = {discGridScene(3, 40, 5), discTrianglesScene(4, 20),
                                     discBoxScene(5, 12), warehouseScene(6, 10)};
  for (const Scene& s : scenes) {
    PlannerParams p;
    p.values = {{"concurrent", 0}};
    const PlanResult r = makePlanner("mms", s, p)->solve(Termination(test::planSeconds(60)));
    ASSERT_EQ(r.status, PlanStatus::Found) << s.name;
    const CollisionChecker checker(s);
    ScheduleStats st;
    const std::vector<Config> w = concurrentSchedule(s, checker, r.waypoints, &st);
    const PathCheckResult c = checkPath(s, checker, w);
    ASSERT_TRUE(c.ok) << s.name << ": " << c.reason;
    expectFreeAtDensePoses(s, checker, w);
    for (size_t i = 0; i < s.robots.size(); ++i)
      EXPECT_NEAR(robotCost(checker, w, i), robotCost(checker, r.waypoints, i), 1e-6)
          << s.name << " robot " << i;
    PathCheckResult before, after;
    measureFleet(s, checker, r.waypoints, before);
    measureFleet(s, checker, w, after);
    EXPECT_LE(after.makespan, before.makespan + 1e-9) << s.name;
    EXPECT_GT(after.movingAtOnce, 1) << s.name;
  }
}

// The default command moves robots at once and says how far from the bounds it is; the run's
// summary keeps the measures; --concurrent 0 keeps the robots' moves in turn.
TEST(Schedule, PlanReportsTheFleetsMeasures) {
  test::TempDir dir;
  const std::string scene = dir.path("grid.json"), stats = dir.path("s.json");
  ASSERT_EQ(
      test::runMms("scenario disc-grid --robots 30 --spacing 6 --seed 2 -o " + test::quote(scene))
          .code,
      0);
  auto ratio = [&](const std::string& options) {
    const test::Outcome r = test::runMms("plan " + test::quote(scene) + " --stats-json " +
                                         test::quote(stats) + options);
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("fleet: makespan"), std::string::npos) << r.out;
    const nlohmann::json path = nlohmann::json::parse(test::readFile(stats))["path"];
    EXPECT_GT(path["makespan_bound"].get<double>(), 0);
    EXPECT_GE(path["distance"].get<double>(), path["distance_bound"].get<double>() - 1e-9);
    return path["makespan"].get<double>() / path["makespan_bound"].get<double>();
  };
  const double atOnce = ratio(""), inTurn = ratio(" --concurrent 0");
  EXPECT_LT(atOnce, 0.5 * inTurn);
  EXPECT_GE(atOnce, 1 - 1e-9);
}
