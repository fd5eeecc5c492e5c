// Degenerate geometry: obstacles touching each other and the bounds, collinear and overlapping
// edges, duplicated obstacles (coincident critical angles), a start touching an obstacle, a gap
// exactly as wide as the robot, hundreds of obstacles, scenes in any unit. Cells and arcs are
// checked against the collision checker; planned paths against the continuous path checker.
//
// Decision for zero clearance (docs/robustness.md): contacts up to the scene's tolerance count
// as touching, so a gap exactly the robot's width is passable. A translating robot passes it
// (its free space is exact); for a rigid robot the passage is a set of angles of measure ~0 that
// sampling finds only by luck: it may report "no path", never an uncertified one.
#include <gtest/gtest.h>

#include <cmath>

#include "GeometryReference.h"
#include "Support.h"
#include "check/PathChecker.h"
#include "geometry/CollisionChecker.h"
#include "geometry/PolygonOps.h"
#include "io/SceneIO.h"
#include "manifolds/Line.h"
#include "manifolds/Slice.h"
#include "mms/Planner.h"
#include "planner/OneRobotPlanner.h"
#include "scenarios/RandomScene.h"

namespace mms {
namespace {

// Validated like a file: the loader must accept every scene here.
using test::rect;
using test::trueShapeOverlaps;

Scene load(const Scene& s) { return parseScene(sceneToJson(s), s.name); }

// Rectangles sharing edges (collinear), one overlapping two others, some flush with the
// bounds, one duplicated, two sharing only a corner; a wall with a gap of exactly `gap`.
Scene touchingScene(double gap, Motion motion) {
  Scene s;
  s.name = "touching";
  s.bounds = {0, 0, 10, 10};
  s.obstacles = {rect(0, 0, 3, 2),
                 rect(3, 0, 6, 2),
                 rect(5, 0, 8, 1),
                 rect(8, 1, 10, 2),
                 rect(8, 1, 10, 2),
                 rect(0, 4, 5 - gap / 2, 5),
                 rect(5 + gap / 2, 4, 10, 5),
                 rect(1, 7, 2, 8),
                 rect(2, 8, 3, 9)};
  Robot r;
  r.name = "square";
  r.motion = motion;
  r.shape = rect(-0.5, -0.5, 0.5, 0.5);
  r.start = {5, 2.5, 0};  // touches the top of rect(3, 0, 6, 2) (y = 2) exactly
  r.goal = {5, 9.5, 0};   // touches the upper bound
  s.robots = {r};
  return load(s);
}

// Random points: in a cell means free for the checker; outside every cell means the true shape
// touches or overlaps something. Returns how many points fell in cells.
size_t checkSlice(const Scene& s, double theta, int points) {
  const CollisionChecker checker(s);
  const SliceWorld world(s, 0);
  const Slice slice(world, exact::rationalAngleNear(theta, 30));
  Random rng(7);
  size_t in = 0;
  for (int i = 0; i < points; ++i) {
    const Vec2 p{rng.uniform(s.bounds.xmin, s.bounds.xmax),
                 rng.uniform(s.bounds.ymin, s.bounds.ymax)};
    const Pose q{p.x, p.y, slice.theta()};
    if (slice.locate(p) >= 0) {
      ++in;
      EXPECT_TRUE(checker.robotFree(0, q)) << p.x << ", " << p.y;
    } else {
      EXPECT_TRUE(trueShapeOverlaps(s, q)) << p.x << ", " << p.y;
    }
  }
  return in;
}

TEST(Degenerate, SlicesAmongTouchingCollinearAndDuplicatedObstaclesMatchTheChecker) {
  const Scene s = touchingScene(1.0, Motion::Rigid);
  for (double theta : {0.0, M_PI / 2, 0.3, -2.0}) EXPECT_GT(checkSlice(s, theta, 4000), 100u);
}

TEST(Degenerate, LinesWithCoincidentCriticalAnglesMatchTheChecker) {
  // Duplicated obstacles and obstacles sharing corners give the same critical angle twice.
  const Scene s = touchingScene(1.0, Motion::Rigid);
  const CollisionChecker checker(s);
  const LineWorld world(s, 0);
  Random rng(3);
  size_t samples = 0;
  for (const Vec2 p : {Vec2{9, 3}, Vec2{2.5, 8.5}, Vec2{5, 3}, Vec2{5, 4.5}, Vec2{1.5, 3}}) {
    const Line line(
        world, [&](const Pose& q) { return checker.robotFree(0, q); }, p);
    const std::vector<double> critical = criticalAngles(world, p);
    for (int i = 0; i < 2000; ++i) {
      const double t = rng.uniform(-M_PI, M_PI);
      bool nearCritical = false;
      for (double c : critical) nearCritical |= std::fabs(std::remainder(t - c, 2 * M_PI)) < 1e-9;
      if (nearCritical) continue;
      ++samples;
      const Pose q{p.x, p.y, t};
      if (line.arcContaining(t) >= 0) {
        EXPECT_TRUE(checker.robotFree(0, q)) << p.x << ", " << p.y << " at " << t;
      } else if (checker.robotFree(0, q)) {
        EXPECT_TRUE(trueShapeOverlaps(s, q)) << p.x << ", " << p.y << " at " << t;
      }
    }
  }
  EXPECT_GT(samples, 9000u);
}

OneRobotResult plan(const Scene& s, double seconds) {
  OneRobotPlanner planner(s, 0, {});
  return planner.solve(s.robots[0].start, s.robots[0].goal, Termination(seconds));
}

TEST(Degenerate, TranslatingRobotPassesAGapExactlyItsWidthTouchingBothSides) {
  const Scene s = touchingScene(1.0, Motion::Translate);
  const OneRobotResult r = plan(s, test::planSeconds(10));
  ASSERT_EQ(r.status, PlanStatus::Found);
  const CollisionChecker checker(s);
  const PathCheckResult c = checkPath(s, checker, r.waypoints);
  EXPECT_TRUE(c.ok) << c.reason;
  EXPECT_LT(c.minClearance, s.tolerance());  // it touches: zero clearance, certified
}

TEST(Degenerate, GapNarrowerThanTheRobotByTenTolerancesHasNoPath) {
  const Scene probe = touchingScene(1.0, Motion::Translate);
  const Scene s = touchingScene(1.0 - 10 * probe.tolerance(), Motion::Translate);
  EXPECT_EQ(plan(s, test::planSeconds(10)).status, PlanStatus::NotFound);
}

TEST(Degenerate, RigidRobotAtAnExactFitGapNeverReturnsAnUncertifiedPath) {
  const Scene s = touchingScene(1.0, Motion::Rigid);
  const OneRobotResult r = plan(s, test::planSeconds(2));
  if (r.status == PlanStatus::Found) {
    EXPECT_TRUE(r.certificate.ok);
    const CollisionChecker checker(s);
    EXPECT_TRUE(checkPath(s, checker, r.waypoints).ok);
  } else {
    EXPECT_EQ(r.status, PlanStatus::NotFound);
  }
}

// The planner among 500 obstacles: this scene has no path found in 30 s, so the run goes to its
// limit; 1 s builds 8 slices among the 500 obstacles and 512 lines, which is what is exercised
// here (under the sanitizers, 10 s: a slice takes up to 60 times as long there).
TEST(Degenerate, HundredsOfObstacles) {
  const Scene s = load(randomScene({11, 1, 500}));
  ASSERT_EQ(s.obstacles.size(), 500u);
  checkSlice(s, 0.7, test::kSanitized ? 300 : 2000);
  const OneRobotResult r = plan(s, test::planSeconds(1));
  EXPECT_GT(r.stats.manifolds.slices, 0u);
  if (r.status == PlanStatus::Found) {
    const CollisionChecker checker(s);
    EXPECT_TRUE(checkPath(s, checker, r.waypoints).ok);
  }
}

// The same scene in other units: every length times `k`, angles kept.
Scene scaled(const Scene& s, double k) {
  Scene out = s;
  out.bounds = {k * s.bounds.xmin, k * s.bounds.ymin, k * s.bounds.xmax, k * s.bounds.ymax};
  for (Ring& o : out.obstacles)
    for (Vec2& v : o) v = k * v;
  for (Robot& r : out.robots) {
    for (Vec2& v : r.shape) v = k * v;
    r.start = {k * r.start.x, k * r.start.y, r.start.theta};
    r.goal = {k * r.goal.x, k * r.goal.y, r.goal.theta};
  }
  return load(out);
}

// A scene drawn in millimetres or in kilometres is the same problem: the contact tolerance and
// the motion-check resolution are fractions of the bounds, and exact geometry has no unit. A
// user's scene in micrometres or in metres of a 1 km site must plan as the bundled one does.
TEST(Degenerate, AnySceneUnitPlansTheSame) {
  for (const char* file : {"one-robot/bar-slot.json", "two-robots/niche-swap.json"}) {
    const Scene base = loadScene(test::scenario(file));
    for (const double k : {1e-3, 1e3}) {
      const Scene s = scaled(base, k);
      const CollisionChecker checker(s);
      for (const char* planner : {"mms", "auto"}) {
        PlannerParams params;
        params.seed = 1;
        const PlanResult r =
            makePlanner(planner, s, params)->solve(Termination(test::planSeconds(10)));
        ASSERT_TRUE(r.found()) << file << " x" << k << " " << planner;
        const PathCheckResult c = checkPath(s, checker, r.waypoints);
        EXPECT_TRUE(c.ok) << file << " x" << k << " " << planner << ": " << c.reason;
        // The path stays inside the scaled bounds, so its length is of the scene's size.
        EXPECT_LT(c.translation, 100 * k * base.bounds.width()) << file << " x" << k;
      }
    }
  }
}

}  // namespace
}  // namespace mms

// Cancellation widens a lazy number's interval to ~1e-8 around 1/3; CGAL's to_double accepts
// intervals up to 1e-5 wide and would return its middle. Cells in doubles must be closer than
// the 1e-9 margins of point location in doubles.
TEST(Degenerate, ExactToDoubleIsTheNearestDoubleEvenAfterCancellation) {
  const mms::exact::FT third = mms::exact::FT(1) / mms::exact::FT(3);
  const mms::exact::FT big(1e8);
  const mms::exact::FT x = (third + big) - big;
  const std::pair<double, double> interval = CGAL::to_interval(x);
  ASSERT_GT(interval.second - interval.first, 1e-12);  // the case this test is about
  const mms::Vec2 v = mms::exact::toDouble(mms::exact::Point(x, x));
  EXPECT_NEAR(v.x, 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(v.y, 1.0 / 3.0, 1e-12);
}
