// Scene generators: valid scenes, same seed same scene, and the property each family stands
// for, checked with the collision and path checkers (not with the planner it benchmarks).
#include <gtest/gtest.h>

#include <cmath>

#include "check/PathChecker.h"
#include "geometry/CollisionChecker.h"
#include "io/SceneIO.h"
#include "scenarios/Generators.h"

using namespace mms;

namespace {
// The pair moved as one rigid body: translated to the chamber's centre, turned there in steps
// of a quarter degree (the part's chord between steps strays from its arc by ~1e-5 part
// sizes, far less than the play), translated back.
std::vector<Config> turnTogether(const Scene& s) {
  const Pose g = s.robots[0].start, p = s.robots[1].start, goal = s.robots[0].goal;
  const double offset = std::hypot(p.x - g.x, p.y - g.y);
  const double turn = std::remainder(s.robots[1].goal.theta - p.theta, 2 * M_PI) > 0 ? M_PI : -M_PI;
  auto pair = [&](double x, double y, double theta) {
    return Config{x, y, theta, x + offset * std::cos(theta), y + offset * std::sin(theta), theta};
  };
  std::vector<Config> w{pair(g.x, g.y, g.theta), pair(0, 0, g.theta)};
  for (int i = 1; i <= 720; ++i) w.push_back(pair(0, 0, g.theta + turn * i / 720));
  w.push_back(pair(goal.x, goal.y, g.theta + turn));
  return w;
}
}  // namespace

TEST(ScenarioCarryTurn, EverySeedIsSolvedByTurningThePairTogether) {
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE(seed);
    const Scene s = carryTurnScene(seed);
    ASSERT_NO_THROW(parseScene(sceneToJson(s), "carry-turn"));
    const CollisionChecker checker(s);
    const PathCheckResult r = checkPath(s, checker, turnTogether(s));
    EXPECT_TRUE(r.ok) << r.reason;
    // Narrow: the gripper cannot turn a quarter in place where it starts, either way (the
    // corridor is narrower than its diagonal), and both robots end turned half round.
    for (const double way : {1.0, -1.0}) {
      bool blocked = false;
      for (int i = 1; i <= 90 && !blocked; ++i) {
        Pose q = s.robots[0].start;
        q.theta += way * M_PI / 2 * i / 90;
        blocked = !checker.robotFree(0, q);
      }
      EXPECT_TRUE(blocked);
    }
    for (const Robot& r : s.robots)
      EXPECT_NEAR(std::abs(std::remainder(r.goal.theta - r.start.theta, 2 * M_PI)), M_PI, 1e-9);
  }
}

TEST(ScenarioCarryTurn, SameSeedSameSceneOtherSeedsOtherScenes) {
  EXPECT_EQ(sceneToJson(carryTurnScene(4)), sceneToJson(carryTurnScene(4)));
  EXPECT_NE(sceneToJson(carryTurnScene(4)), sceneToJson(carryTurnScene(5)));
}
