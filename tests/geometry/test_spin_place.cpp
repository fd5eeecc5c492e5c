// Where a robot spins in place: the clearest point near a start (against brute force over a
// grid), and the turn about a robot's point held there (its poses against the transform).
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/SpinPlace.h"

using namespace mms;

namespace {

// A room with a post off centre: the clearest points lie away from the post.
Scene roomWithPost() {
  Scene s;
  s.bounds = {0, 0, 6, 4};
  s.obstacles = {{{3.5, 1.5}, {4.0, 1.5}, {4.0, 2.0}, {3.5, 2.0}}};
  return s;
}

}  // namespace

TEST(SpinPlace, TheWallDistanceIsTheNearestEdgeOfObstaclesAndBounds) {
  const Scene s = roomWithPost();
  EXPECT_NEAR(wallDistance(s, {1, 2}), 1.0, 1e-12);     // the left wall
  EXPECT_NEAR(wallDistance(s, {3, 1.75}), 0.5, 1e-12);  // the post's left side
  EXPECT_NEAR(wallDistance(s, {3.25, 1.25}), std::hypot(0.25, 0.25), 1e-12);  // its corner
}

TEST(SpinPlace, TheClimbEndsAtALocalMaximumOfTheWallDistance) {
  const Scene s = roomWithPost();
  for (const Vec2 start : {Vec2{1, 1}, Vec2{2.5, 3}, Vec2{5, 0.5}, Vec2{3, 1.7}}) {
    const Vec2 p = clearestNear(s, start, 0.5, 10);
    const double d = wallDistance(s, p);
    EXPECT_GT(d, wallDistance(s, start) - 1e-12);
    // No point of a fine grid around it is clearer by more than the search's last step allows.
    for (int i = -20; i <= 20; ++i)
      for (int j = -20; j <= 20; ++j)
        EXPECT_LE(wallDistance(s, {p.x + 0.005 * i, p.y + 0.005 * j}), d + 1e-3)
            << start.x << "," << start.y;
  }
  // In a room without obstacles, the centre.
  Scene empty = roomWithPost();
  empty.obstacles.clear();
  empty.bounds = {0, 0, 4, 4};
  const Vec2 c = clearestNear(empty, {0.7, 3.1}, 0.5, 10);
  EXPECT_NEAR(c.x, 2, 1e-3);
  EXPECT_NEAR(c.y, 2, 1e-3);
}

TEST(SpinPlace, TheTurnHoldsTheRobotsPointWhereItSpinsInStepsOfAtMostTheGivenAngle) {
  const Config a{1, 1, 0.3, 7, 7, 0}, b{2, 1, 2.0, 8, 7, 1};  // robot 0 turns; robot 1 goes on
  const Vec2 centre{0.6, 0.1}, at{3, 2};
  const std::vector<Config> w = turnAbout(a, b, 0, centre, at, 0.05);
  ASSERT_GE(w.size(), 4u);
  // Along the heading, then across to the spin: the first pose is on a's heading line.
  const double cross = (w[0][0] - a[0]) * std::sin(a[2]) - (w[0][1] - a[1]) * std::cos(a[2]);
  EXPECT_NEAR(cross, 0, 1e-12);
  EXPECT_EQ(w[0][2], a[2]);
  EXPECT_EQ(w.back()[2], b[2]);
  for (size_t k = 1; k + 1 < w.size(); ++k) {
    const Vec2 held = Transform(Pose{w[k][0], w[k][1], w[k][2]})(centre);
    EXPECT_NEAR(held.x, at.x, 1e-12);
    EXPECT_NEAR(held.y, at.y, 1e-12);
    if (k > 1) {
      EXPECT_GT(w[k][2], w[k - 1][2]);
      EXPECT_LE(w[k][2] - w[k - 1][2], 0.05 + 1e-12);
    }
  }
  EXPECT_NEAR(w[1][2], a[2], 1e-12);
  EXPECT_NEAR(w[w.size() - 2][2], b[2], 1e-12);
  // The other robot moves evenly from a to b.
  for (size_t k = 0; k < w.size(); ++k)
    EXPECT_NEAR(w[k][3], 7 + double(k + 1) / double(w.size() + 1), 1e-12);
}
