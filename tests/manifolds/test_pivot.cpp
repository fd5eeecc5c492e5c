// Turns about a pivot: a robot's pocket and an obstacle's smallest circle, pivot lines' arcs
// against the collision checker sampled along the turn, and the swallow's U, which turns half
// round about the part in its mouth and not about its reference point.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/CollisionChecker.h"
#include "geometry/PolygonOps.h"
#include "manifolds/Pivot.h"
#include "scenarios/Generators.h"

namespace mms {
namespace {

// The robot's free placements turning about `pivot` placed at `at`, sampled: whether each
// sample's angle lies on an arc exactly when the checker finds the placement free (away from
// the arcs' ends by a sampling step).
void expectArcsMatchTheChecker(const Scene& s, const PivotLineManifold& line) {
  const CollisionChecker checker(s);
  constexpr int kSamples = 2000;
  const double step = 2 * M_PI / kSamples;
  for (int i = 0; i < kSamples; ++i) {
    const double theta = -M_PI + step * (i + 0.5);
    bool nearEnd = false;
    for (const Arc& a : line.line().arcs())
      nearEnd = nearEnd || (!a.full() && (std::abs(std::remainder(theta - a.lo, 2 * M_PI)) < step ||
                                          std::abs(std::remainder(theta - a.hi, 2 * M_PI)) < step));
    if (nearEnd) continue;
    const Config q = line.at(theta);
    EXPECT_EQ(line.locate(q) >= 0, checker.isFree(q)) << "theta " << theta;
  }
}

TEST(Pivot, APocketsDiscIsTheDeepestNearestTheReferencePoint) {
  // A U open towards +x, its reference point the middle of its back: its mouth holds a disc of
  // radius 0.6 anywhere along it; the one against the back is the one nearest the reference.
  const Ring u{{0, -1}, {3, -1}, {3, -0.6}, {0.4, -0.6}, {0.4, 0.6}, {3, 0.6}, {3, 1}, {0, 1}};
  const auto pocket = pocketDisc(u);
  ASSERT_TRUE(pocket);
  EXPECT_NEAR(pocket->radius, 0.6, 0.03);
  EXPECT_NEAR(pocket->center.x, 1.0, 0.03);  // 0.4 + 0.6
  EXPECT_NEAR(pocket->center.y, 0, 0.03);
  // A convex robot has none; the smallest circle of a square is about its centre.
  EXPECT_FALSE(pocketDisc({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}));
  const Disc c = smallestCircle({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  EXPECT_NEAR(c.center.x, 1, 1e-12);
  EXPECT_NEAR(c.center.y, 1, 1e-12);
  EXPECT_NEAR(c.radius, std::sqrt(2.0), 1e-12);
}

// The swallow's U about its pocket placed at the part's smallest circle's centre: the arcs
// match the checker, and the arc the U starts its turn on spans half a turn or more (the
// generator built the bay for a turn about the part's centre; bars and Ls have theirs there).
TEST(Pivot, TheSwallowsUTurnsHalfRoundAboutThePartInItsMouth) {
  size_t halfTurns = 0;
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    SCOPED_TRACE(seed);
    const Scene s = swallowScene(seed);
    const Robot& u = s.robots[0];
    const auto pocket = pocketDisc(u.shape);
    ASSERT_TRUE(pocket);
    const Disc part = smallestCircle(s.obstacles.back());
    EXPECT_LE(part.radius, pocket->radius);
    const CollisionChecker checker(s);
    const PoseTest free = [&](const Pose& p) { return checker.robotFree(0, p); };
    const PivotLineManifold line(pivotWorld(s, pocket->center), free, pocket->center, part.center);
    expectArcsMatchTheChecker(s, line);
    const long arc = line.locate(line.at(u.start.theta));
    if (arc < 0) continue;
    const Arc& a = line.line().arcs()[size_t(arc)];
    halfTurns += a.hi - a.lo >= M_PI;
  }
  EXPECT_GE(halfTurns, 6u);
}

}  // namespace
}  // namespace mms
