// Slice and line free-space cells against an independent reference: the collision checker
// sampled inside, just inside and just outside every cell.
#include <CGAL/convex_hull_2.h>
#include <gtest/gtest.h>

#include <cmath>

#include "GeometryReference.h"
#include "Support.h"
#include "geometry/CollisionChecker.h"
#include "geometry/PolygonOps.h"
#include "io/SceneIO.h"
#include "manifolds/Line.h"
#include "manifolds/Slice.h"
#include "scenarios/Generators.h"

using namespace mms;

namespace {
PoseTest freeTest(const CollisionChecker& c) {
  return [&c](const Pose& q) { return c.robotFree(0, q); };
}
}  // namespace
using namespace mms::test;

namespace {

Scene randomScene(uint64_t seed) {
  RandomPolygonsSettings st;
  st.seed = seed;
  st.obstacles = 12;
  st.obstacleVertices = 7;
  st.robotVertices = 8;
  st.extent = 20;
  return parseScene(sceneToJson(randomPolygonsScene(st)), "generated");
}

// Robot 0 of `s`, turned by `turn` (its shape `turned`), held still at a random place.
MovedShape heldAtRandom(const Scene& s, double turn, const Ring& turned, Random& rng) {
  const Vec2 offset{rng.uniform(s.bounds.xmin, s.bounds.xmax),
                    rng.uniform(s.bounds.ymin, s.bounds.ymax)};
  return {0, turn, turned, offset};
}

// Points on, just inside and just outside every edge and vertex of `slice`'s cells.
void addEdgeProbes(const Slice& slice, std::vector<Vec2>& points) {
  for (size_t c = 0; c < slice.fscCount(); ++c)
    for (const Ring& r : slice.cell(c))
      for (size_t i = 0; i < r.size(); ++i) {
        const Vec2 a = r[i], e = r[(i + 1) % r.size()] - a;
        const Vec2 normal = (1 / norm(e)) * Vec2{-e.y, e.x};
        for (const double t : {0.0, 0.5})
          for (const double off : {0.0, 1e-13, -1e-13, 1e-10, -1e-10, 1e-8, -1e-8, 1e-4, -1e-4})
            points.push_back(a + t * e + off * normal);
      }
}

}  // namespace

// Every robot and obstacle replaced by its convex hull: slices then sum convex pairs directly.
Scene convexScene(uint64_t seed) {
  Scene s = randomScene(seed);
  for (Ring& o : s.obstacles) o = exact::convexHull(o);
  for (Robot& r : s.robots) r.shape = exact::convexHull(r.shape);
  return s;
}

void expectSlicesMatchChecker(const Scene& s, uint64_t seed) {
  const CollisionChecker checker(s);
  const SliceWorld world(s, 0);
  Random rng(seed * 7 + 1);
  const double eps = 1e-4 * std::max(s.bounds.width(), s.bounds.height());  // 100 tolerances
  size_t inside = 0, outside = 0;
  for (int k = 0; k < 4; ++k) {
    const Slice slice(world, exact::rationalAngleNear(rng.uniform(-M_PI, M_PI), 30));
    const double theta = slice.theta();
    ASSERT_GT(slice.fscCount(), 0u);
    // Uniform points: a point in a cell is a free placement.
    for (int i = 0; i < 2000; ++i) {
      const Vec2 p{rng.uniform(s.bounds.xmin, s.bounds.xmax),
                   rng.uniform(s.bounds.ymin, s.bounds.ymax)};
      if (slice.locate(p) >= 0) {
        ++inside;
        EXPECT_TRUE(checker.robotFree(0, {p.x, p.y, theta})) << p.x << "," << p.y;
      }
    }
    // Boundary edges: a step inside is in the cell and free; a step outside is forbidden
    // (unless it lands in another cell, which only happens where two cells nearly touch).
    for (size_t c = 0; c < slice.fscCount(); ++c)
      for (const Ring& ring : slice.cell(c))
        for (size_t j = 0, jp = ring.size() - 1; j < ring.size(); jp = j++) {
          const Vec2 a = ring[jp], b = ring[j], e = b - a;
          const double len = norm(e);
          if (len < 10 * eps) continue;
          const Vec2 out = (1.0 / len) * Vec2{e.y, -e.x};  // the cell lies to the left
          const Vec2 m = 0.5 * (a + b);
          const Vec2 pin = m - eps * out, pout = m + eps * out;
          EXPECT_EQ(slice.locate(pin), int(c));
          EXPECT_TRUE(checker.robotFree(0, {pin.x, pin.y, theta}));
          if (slice.locate(pout) < 0) {
            ++outside;
            EXPECT_FALSE(checker.robotFree(0, {pout.x, pout.y, theta})) << "edge of cell " << c;
          }
        }
  }
  EXPECT_GT(inside, 500u);
  EXPECT_GT(outside, 100u);
}

class SliceVsChecker : public ::testing::TestWithParam<uint64_t> {};

TEST_P(SliceVsChecker, CellsAreFreeAndTheirOutsideIsNot) {
  expectSlicesMatchChecker(randomScene(GetParam()), GetParam());
}

TEST_P(SliceVsChecker, ConvexSumsToo) {
  expectSlicesMatchChecker(convexScene(GetParam()), GetParam());
}

// An overlay subtracts a held shape's sum, computed once per (shape, angle) and translated; a
// slice built with the placed shape as one more obstacle is the reference.
TEST_P(SliceVsChecker, OverlaysMatchSlicesWithTheHeldShapeAsObstacle) {
  for (const bool convex : {false, true}) {
    const Scene s = convex ? convexScene(GetParam()) : randomScene(GetParam());
    const SliceWorld world(s, 0);
    Random rng(GetParam() * 11 + 3);
    const exact::RationalAngle angle = exact::rationalAngleNear(rng.uniform(-M_PI, M_PI), 30);
    const Slice base(world, angle);
    const double turn = rng.uniform(-M_PI, M_PI);
    const Ring turned = placedRing(s.robots[0].shape, {0, 0, turn});
    for (int k = 0; k < 3; ++k) {
      const MovedShape held = heldAtRandom(s, turn, turned, rng);
      const Slice overlay(base, {held});
      const SliceWorld withHeld(s, 0, {held.placed()});
      const Slice reference(withHeld, angle);
      EXPECT_EQ(overlay.fscCount(), reference.fscCount()) << "convex " << convex << ", k " << k;
      size_t agree = 0, inside = 0;
      for (int i = 0; i < 3000; ++i) {
        const Vec2 p{rng.uniform(s.bounds.xmin, s.bounds.xmax),
                     rng.uniform(s.bounds.ymin, s.bounds.ymax)};
        const int a = overlay.locate(p), b = reference.locate(p);
        agree += (a < 0) == (b < 0);
        inside += a >= 0;
      }
      EXPECT_EQ(agree, 3000u) << "convex " << convex << ", k " << k;
      EXPECT_GT(inside, 100u);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, SliceVsChecker, ::testing::Values(1, 2, 3));

// A base slice keeps the sums of the last 32 convex held shapes it met (a convex pair's sum is
// cheap to redo) and every non-convex one. Overlays built again after 40 other angles pushed
// their sums out agree with the first ones (cells and every located point), and with a slice
// that has the held shape as an obstacle.
TEST(Slice, OverlaysAgreeWhetherTheirSumWasKeptOrRedone) {
  for (const bool convex : {true, false}) {
    const Scene s = convex ? convexScene(5) : randomScene(5);
    const SliceWorld world(s, 0);
    Random rng(17);
    const exact::RationalAngle angle = exact::rationalAngleNear(0.3, 30);
    const Slice base(world, angle);
    std::vector<MovedShape> held;
    for (int k = 0; k < 40; ++k) {
      const double turn = -M_PI + 2 * M_PI * k / 40;
      held.push_back(heldAtRandom(s, turn, placedRing(s.robots[0].shape, {0, 0, turn}), rng));
    }
    std::vector<Slice> first;
    for (const MovedShape& h : held) first.emplace_back(base, std::vector<MovedShape>{h});
    std::vector<Vec2> points;
    for (int i = 0; i < 1000; ++i)
      points.push_back(
          {rng.uniform(s.bounds.xmin, s.bounds.xmax), rng.uniform(s.bounds.ymin, s.bounds.ymax)});
    // Newest first: of a convex pair's sums the base keeps only the last 32, so held[39..8]
    // come from the kept ring and held[7..0] are redone (in order they would all be redone).
    for (size_t k = held.size(); k-- > 0;) {
      const Slice again(base, std::vector<MovedShape>{held[k]});
      ASSERT_EQ(again.fscCount(), first[k].fscCount()) << "convex " << convex << ", k " << k;
      for (const Vec2 p : points)
        ASSERT_EQ(again.locate(p), first[k].locate(p)) << "convex " << convex << ", k " << k;
      if (k % 10 != 0) continue;
      const SliceWorld withHeld(s, 0, {held[k].placed()});
      const Slice reference(withHeld, angle);
      EXPECT_EQ(again.fscCount(), reference.fscCount()) << "convex " << convex << ", k " << k;
      for (const Vec2 p : points)
        EXPECT_EQ(again.locate(p) < 0, reference.locate(p) < 0)
            << "convex " << convex << ", k " << k;
    }
  }
}

// The merge of two convex polygons' edges against the convex hull of all n * m vertex sums
// (CGAL's exact hull), vertex for vertex: random hulls; squares and hexagons, whose edges are
// parallel and antiparallel; collinear and repeated vertices; clockwise input; a segment.
TEST(ConvexMinkowskiSum, IsTheHullOfAllVertexSums) {
  using exact::Point;
  using exact::Polygon;
  auto hullOfSums = [](const Polygon& a, const Polygon& b) {
    std::vector<Point> sums, hull;
    for (const Point& p : a.vertices())
      for (const Point& q : b.vertices()) sums.push_back(p + (q - CGAL::ORIGIN));
    CGAL::convex_hull_2(sums.begin(), sums.end(), std::back_inserter(hull));
    return hull;
  };
  auto sameCycle = [](const std::vector<Point>& got, const std::vector<Point>& want) {
    if (got.size() != want.size() || want.empty()) return false;
    for (size_t s = 0; s < want.size(); ++s) {
      bool all = true;
      for (size_t i = 0; i < want.size() && all; ++i) all = got[i] == want[(i + s) % want.size()];
      if (all) return true;
    }
    return false;
  };
  auto polygon = [](const Ring& r) { return exact::toExact(r); };
  std::vector<Polygon> shapes;
  Random rng(8);
  for (int k = 0; k < 12; ++k) {
    std::vector<Vec2> pts;
    const int n = 3 + int(rng.uniform(0, 12));
    for (int i = 0; i < n; ++i) pts.push_back({rng.uniform(-3, 3), rng.uniform(-2, 2)});
    shapes.push_back(polygon(exact::convexHull(pts)));
  }
  shapes.push_back(polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}));                   // square
  shapes.push_back(polygon({{0, 0}, {2, 0}, {3, 1}, {2, 2}, {0, 2}, {-1, 1}}));  // hexagon
  // Collinear and repeated vertices, the first one on an edge.
  shapes.push_back(polygon({{1, 0}, {2, 0}, {2, 0}, {2, 1}, {2, 2}, {0, 2}, {0, 0}}));
  Polygon clockwise = polygon({{0, 0}, {4, 1}, {1, 3}});
  clockwise.reverse_orientation();
  shapes.push_back(clockwise);
  size_t compared = 0;
  for (const Polygon& a : shapes)
    for (const Polygon& b : shapes) {
      const Polygon sum = exact::convexMinkowskiSum(a, b);
      const std::vector<Point> got(sum.vertices_begin(), sum.vertices_end());
      EXPECT_TRUE(sameCycle(got, hullOfSums(a, b))) << "pair " << compared;
      EXPECT_TRUE(sum.is_convex() && sum.is_counterclockwise_oriented());
      ++compared;
    }
  EXPECT_EQ(compared, shapes.size() * shapes.size());
  // No area, no sum: the caller falls back on CGAL's general Minkowski sum.
  EXPECT_TRUE(exact::convexMinkowskiSum(polygon({{0, 0}, {1, 1}, {2, 2}}), shapes[0]).is_empty());
}

TEST(Slice, TooLargeRobotHasNoCells) {
  Scene s = loadScene(scenario("one-robot/bar-slot.json"));
  s.bounds = {-2.9, -10, 2.9, 10};  // the 6-long bar fits only upright
  s.obstacles.clear();
  const SliceWorld world(s, 0);
  const Slice none(world, exact::rationalAngleNear(0.0));
  EXPECT_EQ(none.fscCount(), 0u);
  EXPECT_EQ(none.locate({0, 0}), -1);  // no arrangement at all: answered without one
  EXPECT_EQ(Slice(world, exact::rationalAngleNear(M_PI / 2)).fscCount(), 1u);
}

TEST(Slice, PointLocationStrategiesAgree) {
  const Scene s = randomScene(4);
  const SliceWorld world(s, 0);
  const auto angle = exact::rationalAngleNear(0.7, 30);
  const Slice walk(world, angle, PointLocation::Walk), trap(world, angle, PointLocation::Trapezoid),
      land(world, angle, PointLocation::Landmarks), autoPl(world, angle, PointLocation::Auto);
  Random rng(3);
  for (int i = 0; i < 3000; ++i) {
    const Vec2 p{rng.uniform(-20, 20), rng.uniform(-20, 20)};
    const int w = walk.locate(p);
    EXPECT_EQ(trap.locate(p), w);
    EXPECT_EQ(land.locate(p), w);
    EXPECT_EQ(autoPl.locate(p), w) << "query " << i;  // switches strategy after 600 queries
  }
}

// Auto locates in doubles first; that must give CGAL's exact answer everywhere, most of all
// at points on, just inside and just outside the cells' edges and vertices, and in cells with
// holes nested in other cells (the M parts' pockets).
TEST(Slice, LocationInDoublesAgreesWithExactLocationNearEdges) {
  std::vector<std::pair<Scene, double>> cases;
  for (uint64_t seed : {4, 9, 13}) cases.push_back({randomScene(seed), 0.3 * double(seed)});
  Scene parts = loadScene(scenario("assembly/assembly-2-m-parts.json"));
  // The other M part held at its start: the slice then has cells inside the pocket.
  parts.obstacles.push_back(placedRing(parts.robots[1].shape, parts.robots[1].start));
  cases.push_back({parts, parts.robots[0].start.theta});
  // A slice among 20 obstacles: one cell with a hole per obstacle group, past the vertex count
  // a scan may cover, so only the rings whose boxes hold a point are scanned.
  cases.push_back({loadScene(scenario("two-robots/random-polygons.json")), 1.0});
  size_t nearEdge = 0;
  for (const auto& [scene, theta] : cases) {
    const SliceWorld world(scene, 0);
    const auto angle = exact::rationalAngleNear(theta, 30);
    const Slice exactPl(world, angle, PointLocation::Walk), autoPl(world, angle);
    ASSERT_GT(exactPl.fscCount(), 0u);
    std::vector<Vec2> points;
    Random rng(5);
    const Box& b = scene.bounds;
    for (int i = 0; i < 2000; ++i)
      points.push_back({rng.uniform(b.xmin, b.xmax), rng.uniform(b.ymin, b.ymax)});
    const size_t firstProbe = points.size();
    addEdgeProbes(exactPl, points);
    for (size_t i = 0; i < points.size(); ++i) {
      const Vec2 p = points[i];
      const int expected = exactPl.locate(p);
      ASSERT_EQ(autoPl.locate(p), expected) << "(" << p.x << ", " << p.y << ")";
      nearEdge += i >= firstProbe && expected >= 0;
    }
  }
  EXPECT_GT(nearEdge, 1000u);  // the edge probes did land inside cells, not only outside
}

// An overlay located in doubles first drops its exact arrangement and rebuilds it for the
// first query near an edge: every answer must be the one of an overlay that kept it (Walk),
// cell for cell, on random points and on points on, just inside and just outside the edges.
TEST(Slice, OverlaysRebuildTheirArrangementForExactQueries) {
  size_t nearEdge = 0;
  for (uint64_t seed : {2, 5, 11}) {
    const Scene s = randomScene(seed);
    const SliceWorld world(s, 0);
    Random rng(seed + 40);
    const auto angle = exact::rationalAngleNear(rng.uniform(-M_PI, M_PI), 30);
    const Slice base(world, angle);
    const double turn = rng.uniform(-M_PI, M_PI);
    const Ring turned = placedRing(s.robots[0].shape, {0, 0, turn});
    for (int k = 0; k < 3; ++k) {
      const MovedShape held = heldAtRandom(s, turn, turned, rng);
      const Slice kept(base, {held}, PointLocation::Walk), dropped(base, {held});
      ASSERT_EQ(dropped.fscCount(), kept.fscCount());
      std::vector<Vec2> points;
      for (int i = 0; i < 500; ++i)
        points.push_back(
            {rng.uniform(s.bounds.xmin, s.bounds.xmax), rng.uniform(s.bounds.ymin, s.bounds.ymax)});
      for (size_t c = 0; c < kept.fscCount(); ++c) ASSERT_EQ(dropped.cell(c), kept.cell(c));
      const size_t firstProbe = points.size();
      addEdgeProbes(kept, points);
      for (size_t i = 0; i < points.size(); ++i) {
        const Vec2 p = points[i];
        const int expected = kept.locate(p);
        ASSERT_EQ(dropped.locate(p), expected)
            << "seed " << seed << " (" << p.x << ", " << p.y << ")";
        nearEdge += i >= firstProbe && expected >= 0;
      }
    }
  }
  EXPECT_GT(nearEdge, 500u);
}

class LineVsChecker : public ::testing::TestWithParam<uint64_t> {};

TEST_P(LineVsChecker, ArcsMatchSampledAngles) {
  const Scene s = randomScene(GetParam());
  const CollisionChecker checker(s);
  const LineWorld world(s, 0);
  Random rng(GetParam() + 100);
  size_t lines = 0, mismatches = 0, samples = 0, partial = 0;
  for (int k = 0; k < 300; ++k) {
    const Vec2 p{rng.uniform(s.bounds.xmin, s.bounds.xmax),
                 rng.uniform(s.bounds.ymin, s.bounds.ymax)};
    const Line line(world, freeTest(checker), p);
    const std::vector<double> critical = criticalAngles(world, p);
    ++lines;
    for (const Arc& a : line.arcs()) partial += !a.full();
    for (int i = 0; i < 200; ++i) {
      const double t = rng.uniform(-M_PI, M_PI);
      bool nearCritical = false;
      for (double c : critical) nearCritical |= std::fabs(std::remainder(t - c, 2 * M_PI)) < 1e-9;
      if (nearCritical) continue;
      ++samples;
      const bool inArc = line.arcContaining(t) >= 0, free = checker.robotFree(0, {p.x, p.y, t});
      // An arc never holds a colliding angle. Outside the arcs the checker may still call a
      // placement free when its overlap is within the contact tolerance; the true shape must
      // then overlap.
      if (inArc && !free) ++mismatches;
      if (!inArc && free && !trueShapeOverlaps(s, {p.x, p.y, t})) ++mismatches;
    }
    // Just inside each partial arc's ends is free; just outside, the true (unshrunk) shape
    // overlaps something (unless another arc starts right there).
    for (const Arc& a : line.arcs()) {
      if (a.full() || a.hi - a.lo < 1e-3) continue;
      EXPECT_TRUE(checker.robotFree(0, {p.x, p.y, a.lo + 1e-4}));
      EXPECT_TRUE(checker.robotFree(0, {p.x, p.y, a.hi - 1e-4}));
      for (double t : {a.lo - 1e-4, a.hi + 1e-4}) {
        if (line.arcContaining(t) < 0) {
          EXPECT_TRUE(trueShapeOverlaps(s, {p.x, p.y, t}));
        }
      }
    }
  }
  EXPECT_EQ(mismatches, 0u) << "of " << samples << " sampled angles on " << lines << " lines";
  EXPECT_GT(partial, 50u);  // the sample must include lines with real constraints
}

INSTANTIATE_TEST_SUITE_P(Seeds, LineVsChecker, ::testing::Values(1, 2, 3));

namespace {
// A one-vertex-deep probe: a thin triangle robot whose tip at (1, 0) sweeps the unit circle
// around p = (0, 0), and a wall whose lower side lies at height h.
struct Probe {
  Scene s;
  explicit Probe(double h) {
    s.bounds = {-5, -5, 5, 5};
    s.obstacles = {{{-4, h}, {4, h}, {4, h + 1}, {-4, h + 1}}};
    Robot r;
    r.name = "probe";
    r.shape = {{-0.2, -0.05}, {1, 0}, {-0.2, 0.05}};
    s.robots = {r};
  }
};
}  // namespace

TEST(Line, ExactTangencyNeitherLosesNorSplitsTheArc) {
  Probe probe(1.0);  // the tip's circle touches the wall at theta = pi/2 exactly
  const CollisionChecker checker(probe.s);
  const LineWorld world(probe.s, 0);
  LineStats stats;
  const Line line(world, freeTest(checker), {0, 0}, &stats);
  ASSERT_EQ(line.arcs().size(), 1u);
  EXPECT_TRUE(line.arcs()[0].full());
  EXPECT_GE(stats.exactFallbacks, 1u);  // the discriminant was decided exactly
}

TEST(Line, ShallowAndDeepDips) {
  // Dipping 1e-9 (below the tolerance): still one full arc. Dipping 0.01: the arc opens.
  {
    Probe probe(1.0 - 1e-9);
    const CollisionChecker checker(probe.s);
    const Line line(LineWorld(probe.s, 0), freeTest(checker), {0, 0});
    ASSERT_EQ(line.arcs().size(), 1u);
    EXPECT_TRUE(line.arcs()[0].full());
  }
  {
    Probe probe(0.99);
    const CollisionChecker checker(probe.s);
    const Line line(LineWorld(probe.s, 0), freeTest(checker), {0, 0});
    ASSERT_EQ(line.arcs().size(), 1u);
    EXPECT_FALSE(line.arcs()[0].full());
    EXPECT_FALSE(line.arcs()[0].contains(M_PI / 2));
    EXPECT_TRUE(line.arcs()[0].contains(-M_PI / 2));
    EXPECT_TRUE(line.arcs()[0].contains(M_PI));  // wraps through +-pi
    EXPECT_NEAR(line.arcs()[0].hi - line.arcs()[0].lo, 2 * M_PI - 2 * std::acos(0.99), 1e-3);
  }
}
