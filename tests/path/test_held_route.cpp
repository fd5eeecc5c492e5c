// Routes of a robot held at an angle, from the grid where it finds them and through the exact
// free space where it does not: every point and every segment of a route free by the collision
// checker (sampled densely), none between places the walls part, and a route that needs the
// angle it was asked at.
#include <gtest/gtest.h>

#include <cmath>

#include "Support.h"
#include "geometry/CollisionChecker.h"
#include "path/HeldRoute.h"

using namespace mms;

namespace {

Scene slotted(double slot = 0.4) { return test::slottedBarScene(slot); }

// Whether the robot at `theta` is free at every point of the route and at 50 points along each
// of its segments.
bool freeAlong(const Scene& s, const std::vector<Vec2>& route, double theta) {
  const CollisionChecker checker(s);
  for (size_t k = 1; k < route.size(); ++k)
    for (int i = 0; i <= 50; ++i) {
      const double t = i / 50.0;
      const Vec2 p{route[k - 1].x + t * (route[k].x - route[k - 1].x),
                   route[k - 1].y + t * (route[k].y - route[k - 1].y)};
      if (!checker.isFree(Config{p.x, p.y, theta})) return false;
    }
  return true;
}

}  // namespace

TEST(HeldRoute, ARouteThroughTheSlotIsFreeAtItsAngle) {
  const Scene s = slotted();
  const CollisionChecker checker(s);
  HeldRoutes routes(s, checker, 4);
  const Termination forever(60);
  const auto across = routes.route(0, {2, 1}, {8, 5}, forever);
  ASSERT_TRUE(across.has_value());
  EXPECT_GE(across->size(), 3u);  // not straight: through the slot
  EXPECT_DOUBLE_EQ(across->front().x, 2);
  EXPECT_DOUBLE_EQ(across->back().y, 5);
  EXPECT_TRUE(freeAlong(s, *across, 0));
  // A slot twice the bar's width: the grid finds the way, no slice is built.
  EXPECT_EQ(routes.gridRoutes(), 1u);
  EXPECT_EQ(routes.slicesBuilt(), 0u);
  // Upright the bar cannot pass the slot: the grid finds no way and the slice shows the two
  // sides are different cells.
  EXPECT_FALSE(routes.route(M_PI / 2, {2, 3}, {8, 3}, forever).has_value());
  EXPECT_EQ(routes.slicesBuilt(), 1u);
  // On one side it can go anywhere free upright.
  const auto upright = routes.route(M_PI / 2, {1, 1.5}, {3.5, 4.5}, forever);
  ASSERT_TRUE(upright.has_value());
  EXPECT_TRUE(freeAlong(s, *upright, M_PI / 2));
  EXPECT_TRUE(routes.route(2 * M_PI, {2, 1}, {8, 5}, forever).has_value());
}

TEST(HeldRoute, ASlotTheGridMissesIsRoutedThroughTheSlice) {
  // The bar's centre must pass within 0.01 of the slot's middle, between the grid's centres.
  const Scene s = slotted(0.22);
  const CollisionChecker checker(s);
  HeldRoutes routes(s, checker, 4);
  const Termination forever(60);
  const auto across = routes.route(0, {2, 1}, {8, 5}, forever);
  ASSERT_TRUE(across.has_value());
  EXPECT_TRUE(freeAlong(s, *across, 0));
  EXPECT_EQ(routes.gridRoutes(), 0u);
  EXPECT_EQ(routes.slicesBuilt(), 1u);
  // An angle a whole turn away is the same slice.
  EXPECT_TRUE(routes.route(2 * M_PI, {2, 1}, {8, 5}, forever).has_value());
  EXPECT_EQ(routes.slicesBuilt(), 1u);
}

TEST(HeldRoute, NoRouteFromAPlaceTheRobotDoesNotFit) {
  const Scene s = slotted();
  const CollisionChecker checker(s);
  HeldRoutes routes(s, checker, 4);
  const Termination forever(60);
  EXPECT_FALSE(routes.route(0, {5, 1}, {8, 5}, forever).has_value());    // in the wall
  EXPECT_FALSE(routes.route(0, {0.5, 3}, {8, 5}, forever).has_value());  // through the bounds
}

TEST(HeldRoute, SlicesAreBoundedAndAnEndedRunRoutesNothing) {
  const Scene s = slotted(0.22);
  const CollisionChecker checker(s);
  HeldRoutes routes(s, checker, 1);
  const Termination forever(60);
  EXPECT_TRUE(routes.route(0, {2, 1}, {8, 5}, forever).has_value());
  EXPECT_FALSE(routes.route(M_PI, {2, 1}, {8, 5}, forever).has_value());  // spent
  // Where the grid finds the way, spent slices do not matter.
  EXPECT_TRUE(routes.route(M_PI / 2, {1, 1.5}, {3.5, 4.5}, forever).has_value());
  HeldRoutes fresh(s, checker, 4);
  EXPECT_FALSE(fresh.route(0, {2, 1}, {8, 5}, Termination(0)).has_value());
  // Two robots: nothing is routed (their slices would hold the other robot).
  Scene two = s;
  two.robots.push_back(s.robots[0]);
  two.robots[1].name = "other";
  two.robots[1].start = two.robots[1].goal = {8, 1, 0};
  EXPECT_FALSE(HeldRoutes(two, CollisionChecker(two), 4).routes());
}
