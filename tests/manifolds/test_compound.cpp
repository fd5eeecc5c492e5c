// Coupled motion: compound slices and lines (two robots in one relative pose moving as one)
// against the collision checker sampled at random (an independent reference), their meeting
// with the one-robot families at the start configuration, and the two-robot planner carrying
// and turning a part with them.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "Support.h"
#include "check/PathChecker.h"
#include "geometry/CollisionChecker.h"
#include "manifolds/Compound.h"
#include "mms/Planner.h"
#include "planner/TwoRobotPlanner.h"
#include "scenarios/Generators.h"
#include "util/Random.h"

using namespace mms;
using namespace mms::test;

namespace {

CompoundFrame startFrame(const Scene& s) {
  return CompoundFrame::between(s.robots[0].start, s.robots[1].start);
}

Vec2 uniformPoint(const Box& b, Random& rng) {
  return {rng.uniform(b.xmin, b.xmax), rng.uniform(b.ymin, b.ymax)};
}

// The pair at carrier pose g: free by the checker, and with clearance to spare.
struct PairStatus {
  bool free = false, clear = false;
};
PairStatus pairAt(const CollisionChecker& checker, const CompoundFrame& f, const Pose& g) {
  const Pose a = f.attachedPose(g);
  PairStatus s;
  s.free = checker.robotFree(0, g) && checker.robotFree(1, a) && checker.robotsDisjoint(0, g, 1, a);
  s.clear = s.free && checker.robotClearance(0, g).distance > 1e-3 &&
            checker.robotClearance(1, a).distance > 1e-3;
  return s;
}

}  // namespace

TEST(Compound, SliceCellsAreWhereBothRobotsAreFree) {
  const Scene s = carryTurnScene(2);
  const CollisionChecker checker(s);
  const CompoundFrame f = startFrame(s);
  const SliceWorld carrier(s, 0), attached(s, 1);
  Random rng(5);
  size_t inside = 0, outside = 0;
  for (const double theta : {s.robots[0].start.theta, s.robots[0].start.theta + 0.7, 2.0}) {
    const auto angle = exact::rationalAngleNear(theta, 30);
    const Slice base(carrier, angle);
    const Slice other(attached, exact::rationalAngleNear(angle.radians() + f.dtheta, 30));
    const Slice compound(base, other, f.offset);
    for (int i = 0; i < 3000; ++i) {
      const Vec2 p = uniformPoint(s.bounds, rng);
      const PairStatus pair = pairAt(checker, f, {p.x, p.y, compound.theta()});
      const bool located = compound.locate(p) >= 0;
      if (located) {
        EXPECT_TRUE(pair.free) << p.x << " " << p.y << " " << theta;
      }
      if (pair.clear) {
        EXPECT_TRUE(located) << p.x << " " << p.y << " " << theta;
      }
      (located ? inside : outside) += 1;
    }
  }
  EXPECT_GT(inside, 50u);
  EXPECT_GT(outside, 50u);
}

TEST(Compound, LineArcsAreWhereThePairTurnsFree) {
  const Scene s = carryTurnScene(3);
  const CollisionChecker checker(s);
  const CompoundFrame f = startFrame(s);
  const LineWorld world(compoundShapes(s, f), s.obstacles, s.bounds);
  Random rng(9);
  size_t onArcs = 0, lines = 0;
  for (int k = 0; k < 300; ++k) {
    // Pivots where the pair is free at some angle: the lines' arcs are then not empty.
    Vec2 p = uniformPoint(s.bounds, rng);
    for (int tries = 0;
         tries < 500 && !pairAt(checker, f, {p.x, p.y, rng.uniform(-M_PI, M_PI)}).free; ++tries)
      p = uniformPoint(s.bounds, rng);
    const Line line(
        world, [&](const Pose& q) { return pairAt(checker, f, q).free; }, p);
    lines += !line.arcs().empty();
    for (int i = 0; i < 60; ++i) {
      const double theta = rng.uniform(-M_PI, M_PI);
      const PairStatus pair = pairAt(checker, f, {p.x, p.y, theta});
      const bool onArc = line.arcContaining(theta) >= 0;
      if (onArc) {
        EXPECT_TRUE(pair.free) << p.x << " " << p.y << " " << theta;
      }
      if (pair.clear) {
        EXPECT_TRUE(onArc) << p.x << " " << p.y << " " << theta;
      }
      onArcs += onArc;
    }
  }
  EXPECT_GT(lines, 100u);
  EXPECT_GT(onArcs, 500u);
}

// A compound line at the carrier's start meets the one-robot line there (the part held at its
// start) at the start configuration itself.
TEST(Compound, MeetsTheOneRobotFamiliesAtTheStart) {
  const Scene s = carryTurnScene(4);
  const CollisionChecker checker(s);
  CompoundFrame f = startFrame(s);
  const Pose a = s.robots[0].start, b = s.robots[1].start;
  const HeldFrame held{0, 2, 0, {{1, b}}};
  std::vector<Line> compoundLines, lines;
  compoundLines.emplace_back(
      LineWorld(compoundShapes(s, f), s.obstacles, s.bounds),
      [&](const Pose& q) { return pairAt(checker, f, q).free; }, Vec2{a.x, a.y});
  lines.emplace_back(
      LineWorld(s, 0, {}), [&](const Pose& q) { return checker.robotFree(0, q); }, Vec2{a.x, a.y});
  const CompoundLineManifold compound(f, compoundLines, 0);
  const LineManifold line(held, lines, 0);
  const auto q = meetingPoint(compound, line);
  ASSERT_TRUE(q);
  const Config start{a.x, a.y, a.theta, b.x, b.y, b.theta};
  for (size_t i = 0; i < 6; ++i) EXPECT_NEAR((*q)[i], start[i], 1e-12) << i;
  EXPECT_GE(compound.locate(*q), 0);
  EXPECT_GE(line.locate(*q), 0);
  EXPECT_EQ(meetingPoint(line, compound), q);
  // Held elsewhere, the part is not where the compound puts it: no meeting.
  const HeldFrame elsewhere{1, 2, 0, {{1, {b.x + 0.5, b.y, b.theta}}}};
  const LineManifold off(elsewhere, lines, 0);
  EXPECT_FALSE(meetingPoint(compound, off));
}

// The gripper and its part turn together: certified, on seeds of the generator.
TEST(Compound, TwoRobotPlannerCarriesAndTurns) {
  for (uint64_t seed : {1, 5, 8}) {
    SCOPED_TRACE(seed);
    const Scene s = carryTurnScene(seed);
    TwoRobotSettings st;
    st.seed = 1;
    TwoRobotPlanner planner(s, st);
    const TwoRobotResult r = planner.solve(Termination(planSeconds(20)));
    ASSERT_EQ(r.status, PlanStatus::Found);
    EXPECT_GT(r.stats.compound.lines, 0u);
    const CollisionChecker checker(s);
    EXPECT_TRUE(checkPath(s, checker, r.waypoints).ok);
  }
}

// The statistics keep the compound subspaces apart (their own phases and counts), and the
// phases still account for the run's time.
TEST(Compound, StatisticsShowTheCompoundPhases) {
  const Scene s = carryTurnScene(2);
  const PlanResult r = makePlanner("mms", s)->solve(Termination(planSeconds(20)));
  ASSERT_EQ(r.status, PlanStatus::Found);
  std::map<std::string, double> phases(r.stats.phases.begin(), r.stats.phases.end());
  EXPECT_GT(phases["compound_slices"], 0);
  EXPECT_GT(phases["compound_lines"], 0);
  EXPECT_GT(phases["overlays"], 0);
  double sum = 0;
  for (const auto& [name, seconds] : r.stats.phases)
    if (!afterFirstPath(name)) sum += seconds;
  EXPECT_LE(sum, r.stats.seconds * 1.001);
  EXPECT_GE(sum, 0.9 * r.stats.seconds);
  std::map<std::string, size_t> counts(r.stats.counts.begin(), r.stats.counts.end());
  EXPECT_GT(counts["compound_slices"], 0u);
  EXPECT_GT(counts["slices"], counts["compound_slices"]);  // slices counts every kind
}
