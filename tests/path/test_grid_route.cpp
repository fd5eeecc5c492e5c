// Routes of a robot held at an angle found on a grid with the collision checker: each segment
// certified free and free at densely sampled poses (an independent test), between the asked
// ends; none where the two ends are apart at that angle, where the passage is narrower than
// the grid sees, or once the search is out of tests or stopped.
#include <gtest/gtest.h>

#include <cmath>

#include "Support.h"
#include "check/PathChecker.h"
#include "geometry/CollisionChecker.h"
#include "path/GridRoute.h"

using namespace mms;

namespace {

Scene walled(double gap) { return test::slottedBarScene(gap); }

bool freeAlong(const CollisionChecker& checker, const std::vector<Vec2>& route, double theta) {
  for (size_t k = 1; k < route.size(); ++k) {
    if (!motionFree(checker, {route[k - 1].x, route[k - 1].y, theta},
                    {route[k].x, route[k].y, theta}))
      return false;
    for (int i = 0; i <= 100; ++i) {
      const double t = i / 100.0;
      const Config q{route[k - 1].x + t * (route[k].x - route[k - 1].x),
                     route[k - 1].y + t * (route[k].y - route[k - 1].y), theta};
      if (!checker.isFree(q)) return false;
    }
  }
  return true;
}

const Termination forever(60);

}  // namespace

TEST(GridRoute, ARouteThroughAWideGapIsCertifiedAndPulledTight) {
  const Scene s = walled(1.0);
  const CollisionChecker checker(s);
  const auto route = gridRoute(checker, s.bounds, 0, {2, 1}, {8, 5}, {0.1, 4000}, forever);
  ASSERT_TRUE(route.has_value());
  ASSERT_GE(route->size(), 3u);  // not straight: through the gap
  EXPECT_EQ(route->front().x, 2);
  EXPECT_EQ(route->front().y, 1);
  EXPECT_EQ(route->back().x, 8);
  EXPECT_EQ(route->back().y, 5);
  EXPECT_TRUE(freeAlong(checker, *route, 0));
  // Pulled tight: a handful of corners, not the walk's hundred-odd cells, and not much longer
  // than the way over the gap's two edges.
  EXPECT_LE(route->size(), 8u);
  double length = 0;
  for (size_t k = 1; k < route->size(); ++k)
    length += std::hypot((*route)[k].x - (*route)[k - 1].x, (*route)[k].y - (*route)[k - 1].y);
  // The shortest way: to the gap's lower corner as the bar's end reaches the wall, across to
  // its upper one as the other end leaves it, and on.
  const double viaGap = std::hypot(3.8 - 2, 2.6 - 1) + std::hypot(6.2 - 3.8, 3.4 - 2.6) +
                        std::hypot(8 - 6.2, 5 - 3.4);
  EXPECT_LT(length, 1.1 * viaGap);
}

TEST(GridRoute, NothingWhereTheEndsAreApartAtThatAngle) {
  const Scene s = walled(1.0);
  const CollisionChecker checker(s);
  // Upright the bar (2 long) cannot pass a gap 1 wide.
  EXPECT_FALSE(gridRoute(checker, s.bounds, M_PI / 2, {2, 3}, {8, 3}, {0.1, 100000}, forever));
  // An end the robot does not fit at, or outside the bounds.
  EXPECT_FALSE(gridRoute(checker, s.bounds, 0, {5, 1}, {8, 5}, {0.1, 4000}, forever));
  EXPECT_FALSE(gridRoute(checker, s.bounds, 0, {-1, 3}, {8, 5}, {0.1, 4000}, forever));
}

TEST(GridRoute, APassageNarrowerThanTheGridSeesIsLeftToTheSlices) {
  // The gap is 0.22 for a bar 0.2 thick: its centre must lie within 0.01 of the gap's middle,
  // which no centre of a grid of 0.25 does (nor does a finer grid's here, by construction: 3 is
  // a cell's edge, not its centre).
  const Scene s = walled(0.22);
  const CollisionChecker checker(s);
  EXPECT_FALSE(gridRoute(checker, s.bounds, 0, {2, 3}, {8, 3}, {0.25, 100000}, forever));
  EXPECT_FALSE(gridRoute(checker, s.bounds, 0, {2, 3}, {8, 3}, {0.1, 100000}, forever));
}

TEST(GridRoute, TheSearchIsBoundedByItsTestsAndByStop) {
  const Scene s = walled(1.0);
  const CollisionChecker checker(s);
  EXPECT_TRUE(gridRoute(checker, s.bounds, 0, {2, 1}, {8, 5}, {0.1, 4000}, forever));
  EXPECT_FALSE(gridRoute(checker, s.bounds, 0, {2, 1}, {8, 5}, {0.1, 20}, forever));
  EXPECT_FALSE(gridRoute(checker, s.bounds, 0, {2, 1}, {8, 5}, {0.1, 4000}, Termination(0)));
  EXPECT_FALSE(gridRoute(checker, s.bounds, 0, {2, 1}, {8, 5}, {0, 4000}, forever));
}

TEST(GridRoute, AVastSceneGetsLargerCellsNotMoreMemory) {
  // Cells of 0.01 over a square of 10 000 would be a million million; the grid is capped at
  // 65 536 cells, made larger, and the open way is found (straight, once pulled tight).
  Scene s = walled(1.0);
  s.bounds = {0, 0, 10000, 10000};
  s.obstacles.clear();
  const CollisionChecker checker(s);
  const auto route = gridRoute(checker, s.bounds, 0.3, {20, 20}, {9000, 7000}, {0.01}, forever);
  ASSERT_TRUE(route.has_value());
  EXPECT_EQ(route->size(), 2u);
  EXPECT_TRUE(freeAlong(checker, *route, 0.3));
}
