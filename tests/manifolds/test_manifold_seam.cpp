// The manifold seam: meeting points of the one-robot families against the collision checker
// (an independent reference), the motion inside a cell certified by the path checker, and a
// family defined here, outside the library, that the roadmap, the search and the path stage
// take without an edit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "check/PathChecker.h"
#include "geometry/CollisionChecker.h"
#include "graph/Roadmap.h"
#include "manifolds/OneRobot.h"
#include "path/Motion.h"
#include "scenarios/Generators.h"
#include "util/Random.h"

using namespace mms;

namespace {

Scene clutter(uint64_t seed) {
  RandomPolygonsSettings st;
  st.seed = seed;
  st.obstacles = 10;
  st.extent = 20;
  return randomPolygonsScene(st);
}

Vec2 uniformPoint(const Box& b, Random& rng) {
  return {rng.uniform(b.xmin, b.xmax), rng.uniform(b.ymin, b.ymax)};
}

// One robot among clutter: slices at random angles and lines at random points of one frame.
struct OneFrame {
  OneFrame(uint64_t sceneSeed, int sliceCount, int lineCount, uint64_t seed)
      : scene(clutter(sceneSeed)), checker(scene), sliceWorld(scene, 0), lineWorld(scene, 0) {
    Random rng(seed);
    for (int k = 0; k < sliceCount; ++k)
      slices.emplace_back(sliceWorld, exact::rationalAngleNear(rng.uniform(-M_PI, M_PI), 30));
    for (int l = 0; l < lineCount; ++l)
      lines.emplace_back(
          lineWorld, [&](const Pose& q) { return checker.robotFree(0, q); },
          uniformPoint(scene.bounds, rng));
  }
  Scene scene;
  CollisionChecker checker;
  SliceWorld sliceWorld;
  LineWorld lineWorld;
  HeldFrame frame{0, 1, 0, {}};
  std::vector<Slice> slices;
  std::vector<Line> lines;
};

}  // namespace

// In one frame a slice and a line meet at (line point, slice angle); the cells that hold it
// are free there by the collision checker, and the roadmap joins exactly those.
TEST(ManifoldSeam, SliceAndLineOfOneFrameMeetAtLinePointAndSliceAngle) {
  const OneFrame f(3, 4, 60, 7);
  const CollisionChecker& checker = f.checker;
  const HeldFrame& frame = f.frame;
  const std::vector<Slice>& slices = f.slices;
  const std::vector<Line>& lines = f.lines;
  Roadmap roadmap;
  std::vector<uint32_t> sliceIds, lineIds;
  for (size_t k = 0; k < slices.size(); ++k)
    sliceIds.push_back(roadmap.add(std::make_unique<SliceManifold>(frame, slices, k), 0, k));
  for (size_t l = 0; l < lines.size(); ++l)
    lineIds.push_back(roadmap.add(std::make_unique<LineManifold>(frame, lines, l), 0, l));
  size_t joined = 0;
  for (size_t l = 0; l < lines.size(); ++l)
    for (size_t k = 0; k < slices.size(); ++k) {
      const auto q = meetingPoint(roadmap.manifold(lineIds[l]), roadmap.manifold(sliceIds[k]));
      ASSERT_TRUE(q);
      EXPECT_EQ((*q)[0], lines[l].point().x);
      EXPECT_EQ((*q)[1], lines[l].point().y);
      EXPECT_EQ((*q)[2], slices[k].theta());
      const bool inBoth =
          slices[k].locate(lines[l].point()) >= 0 && lines[l].arcContaining(slices[k].theta()) >= 0;
      if (inBoth) {
        EXPECT_TRUE(checker.robotFree(0, poseOf(*q, 0)));
      }
      const size_t before = roadmap.edgeCount();
      EXPECT_EQ(roadmap.join(lineIds[l], sliceIds[k]), inBoth);
      EXPECT_EQ(roadmap.edgeCount() - before, inBoth ? 1u : 0u);
      joined += inBoth;
    }
  EXPECT_GT(joined, 10u);  // the scene leaves room: the check above was exercised
  // Two slices, or two lines, of one frame share no single point.
  EXPECT_FALSE(meetingPoint(roadmap.manifold(sliceIds[0]), roadmap.manifold(sliceIds[1])));
  EXPECT_FALSE(meetingPoint(roadmap.manifold(lineIds[0]), roadmap.manifold(lineIds[1])));
}

// A weave stores no edge, yet decides connectivity and finds fewest-cells paths exactly as
// the same joins stored one by one (the reference: join() of every line-slice pair).
TEST(ManifoldSeam, AWeaveConnectsAndSearchesAsStoredEdgesDo) {
  const OneFrame f(4, 6, 80, 11);
  const HeldFrame& frame = f.frame;
  const std::vector<Slice>& slices = f.slices;
  const std::vector<Line>& lines = f.lines;
  Random rng(11);
  Roadmap stored, woven;
  const uint32_t w = woven.addWeave();
  std::vector<uint32_t> sliceIds, lineIds;
  // Interleaved as a planner adds them: each new manifold meets those already on the other side.
  for (size_t l = 0; l < lines.size(); ++l) {
    if (l % 14 == 0 && l / 14 < slices.size()) {
      const size_t k = l / 14;
      sliceIds.push_back(stored.add(std::make_unique<SliceManifold>(frame, slices, k), 0, k));
      ASSERT_EQ(woven.add(std::make_unique<SliceManifold>(frame, slices, k), 0, k),
                sliceIds.back());
      woven.weave(w, 1, sliceIds.back());
    }
    lineIds.push_back(stored.add(std::make_unique<LineManifold>(frame, lines, l), 0, l));
    ASSERT_EQ(woven.add(std::make_unique<LineManifold>(frame, lines, l), 0, l), lineIds.back());
    woven.weave(w, 0, lineIds.back());
  }
  for (const uint32_t line : lineIds)
    for (const uint32_t slice : sliceIds) stored.join(line, slice);
  ASSERT_EQ(stored.nodeCount(), woven.nodeCount());
  size_t storedEdges = 0;
  for (size_t v = 0; v < woven.nodeCount(); ++v) {
    EXPECT_TRUE(woven.graph().neighbours(v).empty());
    storedEdges += stored.graph().neighbours(v).size();
  }
  ASSERT_GT(storedEdges, 200u);
  size_t paths = 0;
  for (int q = 0; q < 300; ++q) {
    const size_t a = rng.below(stored.nodeCount()), b = rng.below(stored.nodeCount());
    ASSERT_EQ(woven.graph().connected(a, b), stored.graph().connected(a, b)) << a << " " << b;
    const auto ps = stored.graph().path(a, b), pw = woven.path(a, b);
    ASSERT_EQ(ps.has_value(), pw.has_value());
    if (!ps) continue;
    ++paths;
    EXPECT_EQ(ps->size(), pw->size());             // both fewest cells
    for (size_t i = 0; i + 1 < pw->size(); ++i) {  // each step is a stored edge
      const auto& n = stored.graph().neighbours((*pw)[i]);
      EXPECT_NE(std::find(n.begin(), n.end(), uint32_t((*pw)[i + 1])), n.end());
    }
  }
  EXPECT_GT(paths, 30u);
  // A search that is told to stop gives up (when it has weave edges to compute).
  for (size_t v = 1; v < woven.nodeCount(); ++v)
    if (woven.graph().connected(0, v)) {
      EXPECT_FALSE(woven.path(0, v, [] { return true; }));
      break;
    }
}

// Across frames (recursive MMS): each robot where the other frame holds it, if that lies on
// the manifold it moves on; otherwise they do not meet.
TEST(ManifoldSeam, ManifoldsOfTwoFramesMeetWhereEachHoldsTheOther) {
  const Scene scene = randomPolygonsTwoRobots(2);
  const SliceWorld world0(scene, 0), world1(scene, 1);
  const exact::RationalAngle a0 = exact::rationalAngleNear(0.3, 30),
                             a1 = exact::rationalAngleNear(-1.2, 30);
  std::vector<Slice> s0, s1;
  s0.emplace_back(world0, a0);
  s0.emplace_back(world0, exact::rationalAngleNear(2.0, 30));
  s1.emplace_back(world1, a1);
  const Pose p0{1.5, 2.5, a0.radians()}, p1{-3, 4, a1.radians()};
  const HeldFrame moves0{0, 2, 0, {{1, p1}}}, moves1{1, 2, 1, {{0, p0}}};
  const SliceManifold m0(moves0, s0, 0), m0other(moves0, s0, 1), m1(moves1, s1, 0);
  const auto q = meetingPoint(m0, m1);
  ASSERT_TRUE(q);
  EXPECT_EQ(*q, (Config{p0.x, p0.y, p0.theta, p1.x, p1.y, p1.theta}));
  EXPECT_EQ(meetingPoint(m1, m0), q);       // the table serves either order
  EXPECT_FALSE(meetingPoint(m0other, m1));  // robot 0 is held at another angle than 2.0
  // Two frames in which the same robot moves hold the other robot apart: disjoint.
  const HeldFrame alsoMoves0{2, 2, 0, {{1, p1}}};
  const SliceManifold m0b(alsoMoves0, s0, 0);
  EXPECT_FALSE(meetingPoint(m0, m0b));
}

// A slice cell's motion and a line arc's motion, between random points of one cell, pass the
// continuous path checker and end where asked.
TEST(ManifoldSeam, MotionsInsideCellsAreCertified) {
  const Scene scene = clutter(5);
  const CollisionChecker checker(scene);
  const SliceWorld sliceWorld(scene, 0);
  const LineWorld lineWorld(scene, 0);
  const HeldFrame frame{0, 1, 0, {}};
  Random rng(11);
  std::vector<Slice> slices;
  slices.emplace_back(sliceWorld, exact::rationalAngleNear(0.7, 30));
  const SliceManifold slice(frame, slices, 0);
  size_t routes = 0;
  for (int attempt = 0; attempt < 400 && routes < 20; ++attempt) {
    const Vec2 a = uniformPoint(scene.bounds, rng), b = uniformPoint(scene.bounds, rng);
    const Config qa{a.x, a.y, slices[0].theta()}, qb{b.x, b.y, slices[0].theta()};
    const long ca = slice.locate(qa);
    if (ca < 0 || slice.locate(qb) != ca) continue;
    const auto moved = slice.motion(size_t(ca), qa, qb);
    ASSERT_TRUE(moved);
    std::vector<Config> w{qa};
    w.insert(w.end(), moved->begin(), moved->end());
    EXPECT_EQ(w.back(), qb);
    EXPECT_TRUE(checkMotion(scene, checker, w).ok);
    ++routes;
  }
  EXPECT_GE(routes, 5u);
  std::vector<Line> lines;
  size_t turns = 0;
  for (int attempt = 0; attempt < 200 && turns < 20; ++attempt) {
    lines.emplace_back(
        lineWorld, [&](const Pose& q) { return checker.robotFree(0, q); },
        uniformPoint(scene.bounds, rng));
    const LineManifold line(frame, lines, lines.size() - 1);
    const Vec2 p = lines.back().point();
    for (size_t c = 0; c < line.cellCount(); ++c) {
      const Arc& arc = lines.back().arcs()[c];
      const double span = arc.full() ? 2 * M_PI : arc.hi - arc.lo;
      const Config from{p.x, p.y, arc.lo + 0.1 * span}, to{p.x, p.y, arc.lo + 0.9 * span};
      const auto moved = line.motion(c, from, to);
      ASSERT_TRUE(moved);
      ASSERT_EQ(moved->size(), 1u);
      EXPECT_NEAR(std::remainder(moved->back()[2] - to[2], 2 * M_PI), 0, 1e-12);
      EXPECT_TRUE(checkMotion(scene, checker, {from, moved->back()}).ok);
      ++turns;
    }
  }
  EXPECT_GE(turns, 5u);
}

namespace {
// A family defined outside the library: a single configuration (a 0-D manifold, one cell).
// It meets a line of the one-robot frame when its position is the line's point.
class PointManifold final : public Manifold {
 public:
  static const ManifoldFamily kFamily;
  explicit PointManifold(Config q) : q_(std::move(q)) {}
  const Config& point() const { return q_; }
  const ManifoldFamily& family() const override { return kFamily; }
  size_t cellCount() const override { return 1; }
  long locate(const Config& q) const override { return q == q_ ? 0 : -1; }
  std::optional<std::vector<Config>> motion(size_t, const Config& from,
                                            const Config& to) const override {
    auto here = [&](const Config& q) {  // angles arrive unwound by whole turns
      return q[0] == q_[0] && q[1] == q_[1] &&
             std::abs(std::remainder(q[2] - q_[2], 2 * M_PI)) < 1e-9;
    };
    if (!here(from) || !here(to)) return std::nullopt;
    return std::vector<Config>{};
  }

 private:
  Config q_;
};
const ManifoldFamily PointManifold::kFamily{"point"};

bool meetPointLine(const Manifold& point, const Manifold& line, Config& at) {
  const Config& q = static_cast<const PointManifold&>(point).point();
  const Vec2 p = static_cast<const LineManifold&>(line).line().point();
  if (q[0] != p.x || q[1] != p.y) return false;
  at = q;
  return true;
}
}  // namespace

// One class and one row in the table: the roadmap joins the new family's cells to lines, the
// search finds a path through them, and the path stage moves through them, unchanged.
TEST(ManifoldSeam, ANewFamilyNeedsOneClassAndOneRow) {
  addMeetRule({&PointManifold::kFamily, &LineManifold::kFamily, meetPointLine});
  Scene scene = clutter(9);
  const CollisionChecker checker(scene);
  const LineWorld lineWorld(scene, 0);
  const HeldFrame frame{0, 1, 0, {}};
  const Pose start = scene.robots[0].start;
  std::vector<Line> lines;
  lines.emplace_back(
      lineWorld, [&](const Pose& q) { return checker.robotFree(0, q); }, Vec2{start.x, start.y});
  const long arc = lines[0].arcContaining(start.theta);
  ASSERT_GE(arc, 0);
  const Arc& a = lines[0].arcs()[size_t(arc)];
  // A waypoint on the start's arc, a little further round: the point family's one cell.
  const double turn = a.full() ? 1.0 : 0.5 * (a.unwrap(start.theta) - a.lo);
  const Config mid{start.x, start.y, start.theta - turn};
  ASSERT_GE(lines[0].arcContaining(mid[2]), 0);
  Roadmap roadmap;
  const uint32_t line = roadmap.add(std::make_unique<LineManifold>(frame, lines, 0), 0, 0);
  const uint32_t point = roadmap.add(std::make_unique<PointManifold>(mid), 1, 0);
  ASSERT_TRUE(roadmap.join(point, line));
  const size_t from = roadmap.node(line, size_t(arc)), to = roadmap.node(point, 0);
  const auto cells = roadmap.graph().path(from, to);
  ASSERT_TRUE(cells);
  EXPECT_EQ(roadmap.footprint(*cells).manifolds, 2u);
  EXPECT_EQ(roadmap.footprint(*cells).groups, 2u);
  const Config q0{start.x, start.y, start.theta};
  const auto w = graphPathMotion(roadmap, *cells, q0, mid);
  ASSERT_TRUE(w);
  EXPECT_EQ(w->front(), q0);
  EXPECT_NEAR(std::remainder(w->back()[2] - mid[2], 2 * M_PI), 0, 1e-12);
  EXPECT_TRUE(checkMotion(scene, checker, *w).ok);
  // A point off every line meets none.
  const PointManifold elsewhere(Config{start.x + 1, start.y, start.theta});
  EXPECT_FALSE(meetingPoint(elsewhere, roadmap.manifold(line)));
}
