// Routes inside one free cell: every point of a route inside the cell (an independent
// even-odd test, sampled along each segment), the pulled route no longer than the route
// through midpoints and no shorter than the shortest way worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "GeometryReference.h"
#include "manifolds/CellRoute.h"

using namespace mms;

namespace {

double length(const std::vector<Vec2>& route) {
  double sum = 0;
  for (size_t k = 1; k < route.size(); ++k) sum += norm(route[k] - route[k - 1]);
  return sum;
}

// Whether 40 points along each segment lie strictly inside the cell.
bool insideAlong(const std::vector<Ring>& cell, const std::vector<Vec2>& route) {
  for (size_t k = 1; k < route.size(); ++k)
    for (int i = 0; i <= 40; ++i) {
      const double t = i / 40.0;
      double margin = 0;
      if (!test::insideCells({cell}, (1 - t) * route[k - 1] + t * route[k], margin) ||
          margin < 1e-9)
        return false;
    }
  return true;
}

std::optional<std::vector<Vec2>> route(const std::vector<Ring>& cell, Vec2 a, Vec2 b,
                                       RouteShape shape) {
  return routeInCell(
      cell,
      [&](Vec2 p) {
        double margin = 0;
        return test::insideCells({cell}, p, margin) && margin > 0;
      },
      a, b, shape);
}

}  // namespace

TEST(CellRoute, APulledRouteTurnsTheCornerOfAnLShortlyAndStaysInside) {
  const std::vector<Ring> corridor{{{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 4}, {0, 4}}};
  const Vec2 a{3.5, 0.5}, b{0.5, 3.5};
  const auto pulled = route(corridor, a, b, RouteShape::Pulled);
  const auto midpoints = route(corridor, a, b, RouteShape::Midpoints);
  ASSERT_TRUE(pulled && midpoints);
  EXPECT_TRUE(pulled->front() == a && pulled->back() == b);
  EXPECT_TRUE(insideAlong(corridor, *pulled));
  EXPECT_TRUE(insideAlong(corridor, *midpoints));
  const double shortest = 2 * std::hypot(2.5, 0.5);  // round the inner corner (1, 1)
  EXPECT_GE(length(*pulled), shortest - 1e-9);
  EXPECT_LE(length(*pulled), 1.15 * shortest);
  EXPECT_LE(length(*pulled), length(*midpoints) + 1e-9);
}

TEST(CellRoute, APulledRouteGoesRoundAHoleTheShortWay) {
  // A room with a block in it, the block's ring turning the other way (a hole).
  const std::vector<Ring> room{{{0, 0}, {6, 0}, {6, 6}, {0, 6}}, {{2, 1}, {2, 5}, {4, 5}, {4, 1}}};
  const Vec2 a{1, 3}, b{5, 3};
  const auto pulled = route(room, a, b, RouteShape::Pulled);
  const auto midpoints = route(room, a, b, RouteShape::Midpoints);
  ASSERT_TRUE(pulled && midpoints);
  EXPECT_TRUE(insideAlong(room, *pulled));
  const double shortest = 2 * std::hypot(1, 2) + 2;  // over or under the block
  EXPECT_GE(length(*pulled), shortest - 1e-9);
  EXPECT_LE(length(*pulled), 1.25 * shortest);
  EXPECT_LE(length(*pulled), length(*midpoints) + 1e-9);
  // Into the block: no route.
  EXPECT_FALSE(route(room, a, {3, 3}, RouteShape::Pulled).has_value());
}

TEST(CellRoute, WherePointsSeeEachOtherThePulledRouteIsStraight) {
  const std::vector<Ring> square{{{0, 0}, {5, 0}, {5, 5}, {0, 5}}};
  const auto pulled = route(square, {0.5, 4}, {4.5, 1}, RouteShape::Pulled);
  ASSERT_TRUE(pulled.has_value());
  ASSERT_EQ(pulled->size(), 2u);
  EXPECT_NEAR(length(*pulled), 5, 1e-12);
}
