// MMS for many robots, one at a time: grids and discs among triangles solved with certified
// paths that reach every goal, robots that block each other left to the k-robot MMS, the same
// path for the same seed, and the generators of those scenes.
#include <gtest/gtest.h>

#include <cmath>

#include "Support.h"
#include "check/PathChecker.h"
#include "io/SceneIO.h"
#include "mms/Errors.h"
#include "planner/OrderedPlanner.h"
#include "scenarios/Catalog.h"
#include "scenarios/Generators.h"

using namespace mms;
using namespace mms::test;

namespace {

OrderedResult plan(const Scene& s, uint64_t seed = 1) {
  OrderedSettings st;
  st.seed = seed;
  return OrderedPlanner(s, st).solve(Termination(planSeconds(60)));
}

// Found, every waypoint of the path placing each robot somewhere free (all pairs, no sweep),
// certified by a checker of its own, from the start to the goal.
void expectSolved(const Scene& s, const OrderedResult& r) {
  ASSERT_EQ(r.status, PlanStatus::Found) << s.name;
  ASSERT_FALSE(r.waypoints.empty());
  EXPECT_EQ(r.waypoints.front(), startConfig(s)) << s.name;
  // At the goal; a robot that turned may arrive a whole turn further round, the same placement.
  const Config& end = r.waypoints.back();
  const Config goal = goalConfig(s);
  for (size_t i = 0; i < s.robots.size(); ++i) {
    EXPECT_EQ(end[3 * i], goal[3 * i]) << s.name;
    EXPECT_EQ(end[3 * i + 1], goal[3 * i + 1]) << s.name;
    EXPECT_NEAR(std::remainder(end[3 * i + 2] - goal[3 * i + 2], 2 * M_PI), 0, 1e-12) << s.name;
  }
  const CollisionChecker checker(s);
  EXPECT_TRUE(checkPath(s, checker, r.waypoints).ok) << s.name;
  for (const Config& q : r.waypoints)
    for (size_t i = 0; i < s.robots.size(); ++i)
      for (size_t j = i + 1; j < s.robots.size(); ++j)
        ASSERT_TRUE(checker.robotsDisjoint(i, poseOf(q, i), j, poseOf(q, j))) << s.name;
}

}  // namespace

TEST(Ordered, DenseAndSparseGridsGoToTheirOtherGrid) {
  for (uint64_t seed = 1; seed <= size_t(seedsToRun(3)); ++seed)
    for (double spacing : {3.0, 10.0}) {
      const Scene s = discGridScene(seed, 30, spacing);
      ASSERT_EQ(s.robots.size(), 30u);
      expectSolved(s, plan(s));
    }
}

TEST(Ordered, DiscsAmongTrianglesAreSolvedOneAtATime) {
  for (uint64_t seed = 1; seed <= size_t(seedsToRun(3)); ++seed) {
    const Scene s = discTrianglesScene(seed, 20);
    const OrderedResult r = plan(s);
    expectSolved(s, r);
    EXPECT_EQ(r.stats.moves, 20u) << "every disc on its own: no joint planning needed";
    EXPECT_EQ(r.stats.jointRobots, 0u);
  }
}

// Discs round a block each go to the next one's place: nobody can go first, and the k-robot MMS
// plans them together.
TEST(Ordered, RobotsThatBlockEachOtherArePlannedTogether) {
  const Scene s = discsSwapScene(1);
  const OrderedResult r = plan(s);
  expectSolved(s, r);
  EXPECT_EQ(r.stats.jointRobots, s.robots.size());
}

TEST(Ordered, SameSeedSamePath) {
  const Scene s = discTrianglesScene(4, 20);
  const OrderedResult a = plan(s, 3), b = plan(s, 3);
  ASSERT_EQ(a.status, PlanStatus::Found);
  EXPECT_EQ(a.waypoints, b.waypoints);
}

TEST(ManyDiscScenes, SameSeedSameSceneValidAndSized) {
  for (const char* name : {"disc-grid", "disc-triangles"})
    for (int robots : {1, 20, 100}) {
      ScenarioRequest r;
      r.name = name;
      r.seed = 7;
      r.robots = robots;
      const Scene a = makeScenario(r), b = makeScenario(r);  // makeScenario validates them
      EXPECT_EQ(a.robots.size(), size_t(robots)) << name;
      for (const Robot& robot : a.robots) EXPECT_EQ(robot.disc, 1) << name << ": exact discs";
      EXPECT_EQ(sceneToJson(a), sceneToJson(b)) << name;
      r.seed = 8;
      EXPECT_NE(sceneToJson(makeScenario(r)), sceneToJson(a)) << name;
    }
  ScenarioRequest bad;
  bad.name = "disc-grid";
  bad.spacing = 1.5;  // discs would overlap
  EXPECT_THROW(makeScenario(bad, "--"), InputError);
}

// Touching discs packed in a walled box with a few empty cells: nobody can go alone, so the
// pebble graph shuffles them, one moving at a time, every move a certified translation.
TEST(Ordered, TouchingDiscsInABoxShuffleOnThePebbleGraph) {
  for (uint64_t seed = 1; seed <= size_t(seedsToRun(3)); ++seed) {
    const Scene s = discBoxScene(seed, 16);
    ASSERT_EQ(s.robots.size(), 16u);
    const OrderedResult r = plan(s, seed);
    expectSolved(s, r);
    EXPECT_GT(r.stats.pebbles.moves, 0u) << s.name;
    EXPECT_GT(r.stats.pebbles.vertices, 16u) << "placements beyond the starts and goals";
    EXPECT_EQ(r.stats.jointRobots, 0u);
    // A shuffle moves one robot per step (what its edges were certified for).
    size_t single = 0;
    for (size_t k = 1; k < r.waypoints.size(); ++k) {
      size_t moved = 0;
      for (size_t i = 0; i < s.robots.size(); ++i)
        moved += poseOf(r.waypoints[k], i).x != poseOf(r.waypoints[k - 1], i).x ||
                 poseOf(r.waypoints[k], i).y != poseOf(r.waypoints[k - 1], i).y;
      single += moved == 1;
    }
    EXPECT_GE(single, r.stats.pebbles.moves) << s.name;
  }
}

TEST(Ordered, ThePebbleGraphNeedsOneShapeThatTranslates) {
  Scene s = discBoxScene(2, 6);
  EXPECT_TRUE(pebbleApplies(s, startConfig(s)));
  s.robots[3].disc = 0.4;
  EXPECT_FALSE(pebbleApplies(s, startConfig(s))) << "two radii";
  s = discBoxScene(2, 6);
  s.robots[0].motion = Motion::Rigid;
  EXPECT_FALSE(pebbleApplies(s, startConfig(s)));
  s = discBoxScene(2, 1);
  EXPECT_FALSE(pebbleApplies(s, startConfig(s))) << "one robot";
}

// The box generator: the same scene for the same seed, valid, discs touching each other and the
// walls, starts and goals on cells.
TEST(Ordered, DiscBoxScenesAreReproducibleAndPacked) {
  for (uint64_t seed : {1, 7}) {
    const Scene a = discBoxScene(seed, 29), b = discBoxScene(seed, 29);
    EXPECT_EQ(sceneToJson(a), sceneToJson(b));
    EXPECT_NO_THROW(parseScene(sceneToJson(a), "box"));
    ASSERT_EQ(a.robots.size(), 29u);
    const CollisionChecker checker(a);
    size_t touching = 0;
    for (size_t i = 0; i < a.robots.size(); ++i) {
      EXPECT_EQ(a.robots[i].disc, 0.5);
      for (size_t j = i + 1; j < a.robots.size(); ++j)
        touching +=
            std::fabs(checker.robotsDistance(i, a.robots[i].start, j, a.robots[j].start)) < 1e-4;
    }
    EXPECT_GT(touching, 20u) << "packed: many neighbours touch";
  }
  EXPECT_NE(sceneToJson(discBoxScene(1, 29)), sceneToJson(discBoxScene(2, 29)));
}

// Carts in a warehouse park lengthwise in the aisles and crosswise in the cross-aisles: a cart
// that changes its angle turns where there is room, alone among the standing carts (one-robot
// MMS), one after another.
TEST(Ordered, CartsInAWarehouseTurnOneAtATime) {
  for (uint64_t seed : {1, 2}) {
    const Scene s = warehouseScene(seed, 20);
    ASSERT_EQ(s.robots.size(), 20u);
    EXPECT_EQ(sceneToJson(s), sceneToJson(warehouseScene(seed, 20))) << "same seed, same scene";
    EXPECT_NO_THROW(parseScene(sceneToJson(s), "warehouse"));
    size_t turning = 0;
    for (const Robot& r : s.robots)
      turning += std::fabs(std::remainder(r.goal.theta - r.start.theta, 2 * M_PI)) > 0.1;
    EXPECT_GT(turning, 5u) << "most carts turn";
    if (size_t(seed) > size_t(seedsToRun(2))) continue;
    const OrderedResult r = plan(s, seed);
    expectSolved(s, r);
    EXPECT_GT(r.stats.turnMoves, 5u) << s.name;
  }
}
