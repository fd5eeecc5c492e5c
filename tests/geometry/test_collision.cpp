// The floating-point collision checker against CGAL's exact predicates, and the exact
// geometry helpers.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <thread>
#include <vector>

#include "Support.h"
#include "geometry/CollisionChecker.h"
#include "geometry/Exact.h"
#include "geometry/PolygonOps.h"
#include "io/SceneIO.h"
#include "scenarios/Generators.h"
#include "util/Random.h"

using namespace mms;

namespace {

// Exact reference: the placed ring lies inside the bounds and its interior meets no
// obstacle's interior. Obstacles whose boxes miss the ring's box cannot meet it (box tests in
// doubles are exact).
bool exactFree(const Scene& s, const Ring& placed) {
  const Box box = boundingBox(placed);
  if (!s.bounds.contains(box)) return false;
  for (const Ring& o : s.obstacles)
    if (box.overlaps(boundingBox(o)) && exact::interiorsIntersect(placed, o)) return false;
  return true;
}

Scene benchmarkScene(uint64_t seed) {
  RandomPolygonsSettings st;
  st.seed = seed;
  st.obstacles = 20;
  st.obstacleVertices = 8;
  st.robotVertices = 10;
  // Validate through the loader so the generator's output is a legal scene.
  return parseScene(sceneToJson(randomPolygonsScene(st)), "generated");
}

// The brute-force reference for distances: every edge of a against every edge of b.
double nearestEdgePair(const Ring& a, const Ring& b) {
  double nearest = std::numeric_limits<double>::infinity();
  for (size_t u = 0; u < a.size(); ++u)
    for (size_t v = 0; v < b.size(); ++v)
      nearest = std::min(nearest, segmentSegmentDistance(a[u], a[(u + 1) % a.size()], b[v],
                                                         b[(v + 1) % b.size()]));
  return nearest;
}

// Two random star-shaped 9-gons in an empty room.
Scene twoStarRobots(Random& rng) {
  Scene s;
  s.bounds = {-10, -10, 10, 10};
  for (int k = 0; k < 2; ++k) {
    Robot r;
    r.name = "r" + std::to_string(k);
    r.shape = randomStarPolygon(rng, {0, 0}, 0.5, 2.0, 9);
    s.robots.push_back(r);
  }
  return s;
}

}  // namespace

TEST(CollisionChecker, AgreesWithExactPredicatesOnRandomPlacements) {
  const Scene s = benchmarkScene(7);
  const CollisionChecker checker(s);
  const Ring& shrunk = checker.shrunkShape(0);
  const ShrinkResult deeper = shrinkRing(s.robots[0].shape, 2 * s.tolerance());
  ASSERT_FALSE(deeper.error);
  Random rng(11);
  const Box& b = s.bounds;
  int free = 0, blocked = 0, vsShrunk = 0, vsShape = 0, unexplained = 0;
  const int n = 10000;
  for (int i = 0; i < n; ++i) {
    const Pose p{rng.uniform(b.xmin, b.xmax), rng.uniform(b.ymin, b.ymax),
                 rng.uniform(-M_PI, M_PI)};
    const bool fast = checker.robotFree(0, p);
    (fast ? free : blocked)++;
    // Same definition, exact arithmetic: the shrunk shape's interior.
    if (fast != exactFree(s, placedRing(shrunk, p))) ++vsShrunk;
    // The true shape: disagreement only inside the tolerance band.
    if (fast != exactFree(s, placedRing(s.robots[0].shape, p))) {
      ++vsShape;
      if (!exactFree(s, placedRing(deeper.ring, p))) ++unexplained;
    }
  }
  std::printf(
      "[ info ] %d placements: %d free, %d blocked; %d differ from the exact answer for the "
      "unshrunk shape (all within the tolerance band)\n",
      n, free, blocked, vsShape);
  EXPECT_EQ(vsShrunk, 0);
  EXPECT_EQ(unexplained, 0);
  EXPECT_LE(vsShape, 2);  // uniform placements essentially never land within 1e-6 of contact
  // The sample must exercise both answers.
  EXPECT_GT(free, n / 10);
  EXPECT_GT(blocked, n / 10);
}

// The point test before robotFree: it may only say "blocked" where robotFree does; where the
// free space is narrow (a bend, a keyhole) it must say so for most blocked poses, or it only
// adds work. A robot whose reference point lies outside its shape gets no answer from it.
TEST(CollisionChecker, ReferenceBlockedOnlyWhereTheRobotIsBlocked) {
  Scene away = benchmarkScene(7);
  for (Vec2& v : away.robots[0].shape) v.x += 5;  // the frame's origin far outside the shape
  struct Case {
    const char* name;
    Scene scene;
    double share;  // of the blocked poses the test must catch; 0: none
  };
  const std::vector<Case> cases = {{"bend", bendScene(3), 0.5},
                                   {"keyhole", keyholeScene(2), 0.5},
                                   {"swallow", swallowScene(5), 0.1},
                                   {"discs", discsSwapScene(4), 0.1},
                                   {"random polygons", benchmarkScene(7), 0.1},
                                   {"origin outside", away, 0}};
  for (const Case& c : cases) {
    const CollisionChecker checker(c.scene);
    Random rng(13);
    const Box& b = c.scene.bounds;
    int blocked = 0, caught = 0;
    for (int i = 0; i < 20000; ++i) {
      const Pose p{rng.uniform(b.xmin, b.xmax), rng.uniform(b.ymin, b.ymax),
                   rng.uniform(-M_PI, M_PI)};
      const bool free = checker.robotFree(0, p), early = checker.referenceBlocked(0, p);
      ASSERT_FALSE(free && early) << c.name << " at " << p.x << ", " << p.y << ", " << p.theta;
      blocked += !free;
      caught += early;
    }
    std::printf("[ info ] %s: %d of %d blocked poses caught by the point test\n", c.name, caught,
                blocked);
    EXPECT_GT(blocked, 1000) << c.name;
    if (c.share > 0)
      EXPECT_GT(caught, c.share * blocked) << c.name;
    else
      EXPECT_EQ(caught, 0) << c.name;
  }
}

TEST(CollisionChecker, TreatsNearContactsAsTouching) {
  // Placements within ~1e-12 of contact (found by bisection with the exact predicate) are
  // tolerance-close: the checker must call them free on both sides of the contact.
  const Scene s = benchmarkScene(3);
  const CollisionChecker checker(s);
  const Ring& shape = s.robots[0].shape;
  Random rng(5);
  const Box& b = s.bounds;
  int contacts = 0;
  // 45 exact bisection steps a contact: under the sanitizers (29 s for 300) 150 are enough.
  const int wanted = test::kSanitized ? 150 : 300;
  for (int attempt = 0; attempt < 4000 && contacts < wanted; ++attempt) {
    const Pose a{rng.uniform(b.xmin, b.xmax), rng.uniform(b.ymin, b.ymax),
                 rng.uniform(-M_PI, M_PI)};
    const Pose c{a.x + rng.uniform(-3, 3), a.y + rng.uniform(-3, 3),
                 a.theta + rng.uniform(-0.5, 0.5)};
    if (!exactFree(s, placedRing(shape, a)) || exactFree(s, placedRing(shape, c))) continue;
    double lo = 0, hi = 1;
    auto at = [&](double t) {
      return Pose{a.x + t * (c.x - a.x), a.y + t * (c.y - a.y), a.theta + t * (c.theta - a.theta)};
    };
    for (int k = 0; k < 45; ++k) {
      const double mid = 0.5 * (lo + hi);
      (exactFree(s, placedRing(shape, at(mid))) ? lo : hi) = mid;
    }
    ++contacts;
    EXPECT_TRUE(checker.robotFree(0, at(lo))) << "free side of contact " << contacts;
    EXPECT_TRUE(checker.robotFree(0, at(hi))) << "touching side of contact " << contacts;
    // Well past the tolerance it must collide: move 100 tolerances further along, which
    // penetrates unless the segment grazes (then the exact answer says so too).
    const double step = 100 * s.tolerance() / std::hypot(c.x - a.x, c.y - a.y);
    const Pose deep = at(std::min(1.0, hi + step));
    if (!exactFree(s, placedRing(checker.shrunkShape(0), deep))) {
      EXPECT_FALSE(checker.robotFree(0, deep)) << "deep side of contact " << contacts;
    }
  }
  std::printf("[ info ] %d near-contact placements checked\n", contacts);
  EXPECT_GE(contacts, 100);
}

TEST(CollisionChecker, RobotPairsAgreeWithExactPredicates) {
  Random rng(21);
  const Scene s = twoStarRobots(rng);
  const CollisionChecker checker(s);
  int overlaps = 0, mismatches = 0;
  for (int i = 0; i < 5000; ++i) {
    const Pose p{rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-M_PI, M_PI)};
    const Pose q{rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-M_PI, M_PI)};
    const bool disjoint = checker.robotsDisjoint(0, p, 1, q);
    const bool exactOverlap = exact::interiorsIntersect(placedRing(checker.shrunkShape(0), p),
                                                        placedRing(checker.shrunkShape(1), q));
    overlaps += exactOverlap;
    mismatches += (disjoint == exactOverlap);
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(overlaps, 500);
  EXPECT_LT(overlaps, 4500);
}

// The distance between two robots against every pair of their edges; with a bound it is the
// distance when below the bound and the bound otherwise (the certifier's shortcut for far
// robots).
TEST(CollisionChecker, RobotsDistanceIsTheNearestEdgePairOrTheBound) {
  Random rng(23);
  const Scene s = twoStarRobots(rng);
  const CollisionChecker checker(s);
  int apart = 0, bounded = 0;
  for (int i = 0; i < 3000; ++i) {
    const Pose p{rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-M_PI, M_PI)};
    const Pose q{rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-M_PI, M_PI)};
    const Ring a = placedRing(checker.shrunkShape(0), p), b = placedRing(checker.shrunkShape(1), q);
    double nearest = nearestEdgePair(a, b);
    if (ringsIntersect(a, boundingBox(a), b, boundingBox(b))) nearest = 0;
    const double d = checker.robotsDistance(0, p, 1, q);
    ASSERT_NEAR(d, nearest, 1e-12) << "placement " << i;
    apart += d > 0;
    const double bound = rng.uniform(0, 2 * d + 0.1);
    const double withBound = checker.robotsDistance(0, p, 1, q, bound);
    bounded += d >= bound;
    EXPECT_EQ(withBound, d < bound ? d : bound) << "placement " << i;
  }
  EXPECT_GT(apart, 1000);
  EXPECT_GT(bounded, 500);
}

// Each thread keeps robots' last placements for the checkers it used last: checkers of
// different shapes in turn (more than it keeps), the same pose again, and a new checker in the
// place of a destroyed one must each see their own shapes.
TEST(CollisionChecker, CheckersInTurnEachPlaceTheirOwnShapes) {
  Random rng(31);
  std::vector<Scene> scenes;
  for (int k = 0; k < 3; ++k) scenes.push_back(twoStarRobots(rng));
  std::vector<CollisionChecker> checkers(scenes.begin(), scenes.end());
  std::optional<CollisionChecker> reused;
  for (int i = 0; i < 600; ++i) {
    const Pose p{rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-M_PI, M_PI)};
    const Pose q{rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-M_PI, M_PI)};
    const size_t k = size_t(i) % 3;
    reused.emplace(scenes[(k + 1) % 3]);  // the same storage, other shapes
    for (const CollisionChecker* c : {&checkers[k], &*reused, &checkers[k]}) {
      const Ring a = placedRing(c->shrunkShape(0), p), b = placedRing(c->shrunkShape(1), q);
      const double nearest =
          ringsIntersect(a, boundingBox(a), b, boundingBox(b)) ? 0 : nearestEdgePair(a, b);
      ASSERT_NEAR(c->robotsDistance(0, p, 1, q), nearest, 1e-12) << "placement " << i;
      ASSERT_EQ(c->robotsDisjoint(0, p, 1, q), nearest > 0) << "placement " << i;
    }
  }
}

// A robot's clearance against every pair of robot and obstacle edges and the bounds' sides;
// with a bound it is the clearance when below the bound and the bound otherwise, naming the
// same nearest obstacle (the certifier's shortcut for far obstacles).
TEST(CollisionChecker, ClearanceIsTheNearestEdgePairOrTheBound) {
  const Scene s = benchmarkScene(7);
  const CollisionChecker checker(s);
  Random rng(29);
  const Box& b = s.bounds;
  int free = 0, bounded = 0, obstacleNearest = 0;
  for (int i = 0; i < 4000; ++i) {
    const Pose p{rng.uniform(b.xmin, b.xmax), rng.uniform(b.ymin, b.ymax),
                 rng.uniform(-M_PI, M_PI)};
    if (!checker.robotFree(0, p)) continue;
    ++free;
    const Ring a = placedRing(checker.shrunkShape(0), p);
    double nearest = std::numeric_limits<double>::infinity();
    for (const Vec2 v : a)
      nearest = std::min({nearest, v.x - b.xmin, b.xmax - v.x, v.y - b.ymin, b.ymax - v.y});
    for (const Ring& o : s.obstacles) nearest = std::min(nearest, nearestEdgePair(a, o));
    const CollisionChecker::Clearance c = checker.robotClearance(0, p);
    ASSERT_NEAR(c.distance, std::max(0.0, nearest), 1e-12) << "placement " << i;
    obstacleNearest += c.nearest.kind == Contact::Kind::Obstacle;
    const double bound = rng.uniform(0, 2 * c.distance + 0.1);
    const CollisionChecker::Clearance withBound = checker.robotClearance(0, p, bound);
    if (c.distance < bound) {
      EXPECT_EQ(withBound.distance, c.distance) << "placement " << i;
      EXPECT_EQ(withBound.nearest.kind, c.nearest.kind) << "placement " << i;
      EXPECT_EQ(withBound.nearest.index, c.nearest.index) << "placement " << i;
    } else {
      ++bounded;
      EXPECT_EQ(withBound.distance, bound) << "placement " << i;
    }
  }
  EXPECT_GT(free, 500);
  EXPECT_GT(bounded, 100);
  EXPECT_GT(obstacleNearest, 100);
}

TEST(CollisionChecker, ExactContactsAreFreeAndPenetrationIsNot) {
  Scene s;
  s.bounds = {0, 0, 10, 10};
  s.obstacles = {{{4, 4}, {6, 4}, {6, 6}, {4, 6}}};
  Robot r;
  r.name = "sq";
  r.shape = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  s.robots = {r};
  const CollisionChecker c(s);
  const double t = s.tolerance();
  EXPECT_TRUE(c.robotFree(0, {3, 5, 0}));            // edge on edge
  EXPECT_TRUE(c.robotFree(0, {3, 3, 0}));            // corner on corner
  EXPECT_TRUE(c.robotFree(0, {1, 1, 0}));            // touching two sides of the bounds
  EXPECT_TRUE(c.robotFree(0, {3 + 0.5 * t, 5, 0}));  // within tolerance
  EXPECT_FALSE(c.robotFree(0, {3 + 3 * t, 5, 0}));
  EXPECT_FALSE(c.robotFree(0, {1 - 3 * t, 5, 0}));  // leaves the bounds
  EXPECT_FALSE(c.robotFree(0, {5, 5, 0.3}));        // inside the obstacle entirely
  EXPECT_EQ(c.robotContact(0, {5, 5, 0}).kind, Contact::Kind::Obstacle);
  EXPECT_EQ(c.robotContact(0, {0.5, 5, 0}).kind, Contact::Kind::Bounds);
  // A diamond whose tip touches the obstacle's edge.
  const double d = std::sqrt(2.0);
  EXPECT_TRUE(c.robotFree(0, {4 - d, 5, M_PI / 4}));
  EXPECT_FALSE(c.robotFree(0, {4 - d + 3 * t, 5, M_PI / 4}));
  // Clearance of the real shape = clearance of the shrunk one minus about the tolerance.
  EXPECT_NEAR(c.robotClearance(0, {2, 5, 0}).distance, 1 + t, 1e-9);
}

TEST(CollisionChecker, ObstacleInsideRobotCollides) {
  Scene s;
  s.bounds = {0, 0, 10, 10};
  s.obstacles = {{{4.9, 4.9}, {5.1, 4.9}, {5.1, 5.1}, {4.9, 5.1}}};
  Robot r;
  r.name = "big";
  r.shape = {{-2, -2}, {2, -2}, {2, 2}, {-2, 2}};
  s.robots = {r};
  const CollisionChecker c(s);
  EXPECT_FALSE(c.robotFree(0, {5, 5, 0.2}));
  EXPECT_EQ(c.robotClearance(0, {5, 5, 0.2}).distance, 0.0);
}

// The inscribed disc lies inside its ring (checked on points of its circle) and is near the
// largest one, against a fine grid of centres (brute force), on random star-shaped polygons,
// convex and not, and a thin L.
TEST(InscribedDisc, LiesInsideAndIsNearTheLargest) {
  Random rng(7);
  std::vector<Ring> rings{{{0, 0}, {4, 0}, {4, 0.5}, {0.5, 0.5}, {0.5, 3}, {0, 3}}};
  for (int k = 0; k < 40; ++k) {
    Ring r;
    const int n = 3 + int(rng.below(10));
    for (int i = 0; i < n; ++i) {
      const double a = 2 * M_PI * (i + 0.8 * rng.uniform()) / n, d = rng.uniform(0.3, 2.0);
      r.push_back({d * std::cos(a) + 5, d * std::sin(a) - 3});
    }
    rings.push_back(r);
  }
  for (const Ring& r : rings) {
    const Disc disc = inscribedDisc(r);
    ASSERT_GT(disc.radius, 0);
    for (int i = 0; i < 64; ++i) {
      const double a = 2 * M_PI * i / 64;
      EXPECT_TRUE(
          insideRing(r, disc.center + 0.999 * disc.radius * Vec2{std::cos(a), std::sin(a)}));
    }
    double best = 0;
    const Box b = boundingBox(r);
    for (int i = 0; i <= 300; ++i)
      for (int j = 0; j <= 300; ++j) {
        const Vec2 p{b.xmin + b.width() * i / 300, b.ymin + b.height() * j / 300};
        if (!insideRing(r, p)) continue;
        double d = 1e9;
        for (size_t e = 0, f = r.size() - 1; e < r.size(); f = e++)
          d = std::min(d, pointSegmentDistance(p, r[f], r[e]));
        best = std::max(best, d);
      }
    EXPECT_GT(disc.radius, 0.9 * best);
  }
}

TEST(ShrinkForContacts, RejectsFeaturesBelowTheTolerance) {
  const Ring sliver = {{0, 0}, {10, 0}, {10, 1e-7}, {0, 2e-7}};
  EXPECT_TRUE(shrinkForContacts(sliver, 1e-6).error.has_value());
  const Ring ok = {{0, 0}, {10, 0}, {10, 1}, {0, 1}};
  const ShrunkShape s = shrinkForContacts(ok, 1e-3);
  ASSERT_FALSE(s.error);
  EXPECT_NEAR(s.ring[0].x, 1e-3, 1e-12);
  EXPECT_NEAR(s.ring[2].y, 1 - 1e-3, 1e-12);
}

TEST(Exact, RationalAnglesAreCloseAndRotationsExact) {
  Random rng(2);
  const exact::Polygon sq = exact::toExact(Ring{{3, 0}, {3, 1}, {-2, 1.5}});
  for (int i = 0; i < 200; ++i) {
    const double theta = i < 4 ? std::array{M_PI, -M_PI, M_PI_2, 0.0}[i] : rng.uniform(-7, 7);
    const exact::RationalAngle a = exact::rationalAngleNear(theta);
    EXPECT_NEAR(std::remainder(a.radians() - theta, 2 * M_PI), 0.0, 1e-6) << theta;
    const auto [c, s] = a.cosSin();
    EXPECT_TRUE(c * c + s * s == 1);  // exact, not approximately
    const exact::Polygon r = exact::rotated(sq, a);
    for (size_t k = 0; k < sq.size(); ++k)
      EXPECT_TRUE(CGAL::squared_distance(r[k], exact::Point(0, 0)) ==
                  CGAL::squared_distance(sq[k], exact::Point(0, 0)));
  }
  // A half turn is expressible exactly (tan(pi/2) is not).
  const exact::RationalAngle half = exact::rationalAngleNear(M_PI);
  EXPECT_TRUE(half.half);
  EXPECT_TRUE(exact::rotated(sq, half)[0] == exact::Point(-3, 0));
}

TEST(Exact, InteriorPredicateIgnoresTouching) {
  const Ring a = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_FALSE(exact::interiorsIntersect(a, {{1, 0}, {2, 0}, {2, 1}, {1, 1}}));  // shared edge
  EXPECT_FALSE(exact::interiorsIntersect(a, {{1, 1}, {2, 1}, {2, 2}, {1, 2}}));  // shared corner
  EXPECT_TRUE(exact::interiorsIntersect(a, {{0.5, 0.5}, {2, 0.5}, {2, 2}, {0.5, 2}}));
  EXPECT_TRUE(exact::interiorsIntersect(a, {{0.2, 0.2}, {0.8, 0.2}, {0.5, 0.8}}));  // contained
}

// Two polygons' distance: 0 exactly when their interiors meet (CGAL's exact predicate), one
// inside the other included; otherwise the nearest pair of edges, or the bound when that is
// nearer. Random star polygons at random offsets and scales, small ones often inside large.
TEST(RingDistance, IsTheNearestEdgePairOrZeroWhereTheyMeet) {
  Random rng(41);
  int meet = 0, inside = 0, apart = 0, bounded = 0;
  for (int i = 0; i < 3000; ++i) {
    const Ring a = randomStarPolygon(rng, {0, 0}, 0.5, 2.0, 3 + int(rng.below(10)));
    const double scale = rng.below(3) == 0 ? 0.1 : 1.0;
    const Vec2 at{rng.uniform(-4, 4), rng.uniform(-4, 4)};
    const Ring b = randomStarPolygon(rng, at, 0.5 * scale, 2.0 * scale, 3 + int(rng.below(10)));
    const Box boxA = boundingBox(a), boxB = boundingBox(b);
    const double nearest = nearestEdgePair(a, b);
    const double bound =
        rng.below(4) == 0 ? rng.uniform(0, 2) : std::numeric_limits<double>::infinity();
    const double d = ringDistance(a, boxA, b, boxB, bound);
    if (exact::interiorsIntersect(a, b)) {
      ++meet;
      inside += nearest > 0;
      ASSERT_EQ(d, 0.0) << "pair " << i;
      ASSERT_EQ(ringDistance(b, boxB, a, boxA, bound), 0.0) << "pair " << i;
    } else if (nearest > 1e-9) {
      ++apart;
      if (nearest >= bound) {  // reported as the bound, squared and back
        ++bounded;
        ASSERT_DOUBLE_EQ(d, bound) << "pair " << i;
      } else {
        ASSERT_NEAR(d, nearest, 1e-12) << "pair " << i;  // edges taken the other way round
      }
    }
  }
  EXPECT_GT(meet, 300);
  EXPECT_GT(inside, 30);  // one inside the other, no edges crossing
  EXPECT_GT(apart, 300);
  EXPECT_GT(bounded, 30);
}

// Work is counted per thread: each robot test or distance once, another thread's not at all,
// so that a budget read on one thread is the same whatever runs beside it.
TEST(CollisionChecker, CountsItsWorkOnTheCallingThread) {
  Random rng(3);
  const Scene s = twoStarRobots(rng);
  const CollisionChecker checker(s);
  const Pose a{0, 0, 0}, b{50, 50, 0};
  const size_t start = CollisionChecker::workOnThisThread();
  checker.robotFree(0, a);
  checker.robotClearance(0, a);
  checker.robotsDisjoint(0, a, 1, b);
  checker.robotsDistance(0, a, 1, b);
  EXPECT_EQ(CollisionChecker::workOnThisThread() - start, 4u);
  std::thread([&] {
    for (int k = 0; k < 100; ++k) checker.robotFree(0, a);
  }).join();
  EXPECT_EQ(CollisionChecker::workOnThisThread() - start, 4u);
}
