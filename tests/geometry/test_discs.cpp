// Exact discs: the collision checker and the certifier against polygons just inside and just
// outside each disc, which CGAL's exact predicates decide; touching discs; spinning discs.
#include <gtest/gtest.h>

#include <cmath>

#include "check/PathChecker.h"
#include "geometry/CollisionChecker.h"
#include "geometry/Exact.h"
#include "geometry/PolygonOps.h"
#include "io/SceneIO.h"
#include "util/Random.h"

using namespace mms;

namespace {

// The bracketing polygons stay within this fraction of the radius of the circle.
constexpr double kBand = 1e-3;
Ring inner(const Disc& d) { return discInscribed({d.center, d.radius * (1 - kBand)}, 256); }
Ring outer(const Disc& d) { return discStandIn({d.center, d.radius * (1 + kBand)}, 256); }

// Random triangles and discs as obstacles; robot 0 a disc, robot 1 a triangle, robot 2 a disc.
Scene mixedScene(uint64_t seed) {
  Random rng(seed);
  Scene s;
  s.bounds = {0, 0, 20, 20};
  for (int i = 0; i < 6; ++i) {
    const Vec2 c{rng.uniform(2, 18), rng.uniform(2, 18)};
    Ring t;
    for (int k = 0; k < 3; ++k) {
      const double a = 2 * M_PI * k / 3 + rng.uniform(-0.4, 0.4), r = rng.uniform(0.5, 2);
      t.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
    }
    s.obstacles.push_back(t);
    s.addObstacleDisc({{rng.uniform(2, 18), rng.uniform(2, 18)}, rng.uniform(0.3, 1.5)});
  }
  for (int i = 0; i < 3; ++i) {
    Robot r;
    r.name = "robot-" + std::to_string(i);
    if (i == 1) {
      r.shape = {{-0.8, -0.5}, {0.9, -0.3}, {0, 0.9}};
    } else {
      r.disc = rng.uniform(0.3, 1.2);
      r.shape = discStandIn({{0, 0}, r.disc});
    }
    s.robots.push_back(r);
  }
  return s;
}

// The robot as the checker holds it (shrunk by the tolerance), as bracketing polygons.
struct Bracket {
  Ring in, out;
};
Bracket placed(const Scene& s, const CollisionChecker& c, size_t robot, const Pose& p) {
  if (s.robots[robot].disc > 0) {
    const Disc d{{p.x, p.y}, c.disc(robot)};
    return {inner(d), outer(d)};
  }
  const Ring r = placedRing(c.shrunkShape(robot), p);
  return {r, r};
}
Bracket obstacle(const Scene& s, size_t i) {
  if (const Disc* d = s.obstacleDisc(i)) return {inner(*d), outer(*d)};
  return {s.obstacles[i], s.obstacles[i]};
}
bool hits(const Ring& a, const Ring& b) {
  return boundingBox(a).overlaps(boundingBox(b)) && exact::interiorsIntersect(a, b);
}

}  // namespace

TEST(Discs, CheckerAgreesWithExactPredicatesOnPolygonsAroundAndInsideTheDiscs) {
  int sureFree = 0, sureHit = 0;
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    const Scene s = mixedScene(seed);
    const CollisionChecker checker(s);
    Random rng(seed + 100);
    for (int trial = 0; trial < 300; ++trial) {
      const size_t robot = trial % 3;
      const Pose p{rng.uniform(0, 20), rng.uniform(0, 20), rng.uniform(-M_PI, M_PI)};
      const Bracket b = placed(s, checker, robot, p);
      bool outerFree = s.bounds.contains(boundingBox(b.out)), innerHits = false;
      innerHits = !s.bounds.contains(boundingBox(b.in));
      for (size_t i = 0; i < s.obstacles.size(); ++i) {
        const Bracket o = obstacle(s, i);
        outerFree = outerFree && !hits(b.out, o.out);
        innerHits = innerHits || hits(b.in, o.in);
      }
      const bool free = checker.robotFree(robot, p);
      if (outerFree) {
        EXPECT_TRUE(free) << "seed " << seed << " trial " << trial;
      }
      if (innerHits) {
        EXPECT_FALSE(free) << "seed " << seed << " trial " << trial;
      }
      sureFree += outerFree;
      sureHit += innerHits;
    }
  }
  EXPECT_GT(sureFree, 200);
  EXPECT_GT(sureHit, 200);
}

TEST(Discs, RobotPairsAndDistancesAgreeWithTheBracketingPolygons) {
  int sureFree = 0, sureHit = 0;
  const Scene s = mixedScene(7);
  const CollisionChecker checker(s);
  Random rng(8);
  for (int trial = 0; trial < 600; ++trial) {
    const size_t a = trial % 3, b = (trial / 3) % 3;
    if (a == b) continue;
    const Pose pa{rng.uniform(8, 12), rng.uniform(8, 12), rng.uniform(-M_PI, M_PI)};
    const Pose pb{rng.uniform(8, 12), rng.uniform(8, 12), rng.uniform(-M_PI, M_PI)};
    const Bracket ba = placed(s, checker, a, pa), bb = placed(s, checker, b, pb);
    const bool outerFree = !hits(ba.out, bb.out), innerHits = hits(ba.in, bb.in);
    const bool disjoint = checker.robotsDisjoint(a, pa, b, pb);
    if (outerFree) {
      EXPECT_TRUE(disjoint) << trial;
    }
    if (innerHits) {
      EXPECT_FALSE(disjoint) << trial;
    }
    sureFree += outerFree;
    sureHit += innerHits;
    // The distance lies between the outer polygons' and the inner ones'.
    const double d = checker.robotsDistance(a, pa, b, pb);
    const double dOut = ringDistance(ba.out, boundingBox(ba.out), bb.out, boundingBox(bb.out));
    const double dIn = ringDistance(ba.in, boundingBox(ba.in), bb.in, boundingBox(bb.in));
    EXPECT_GE(d, dOut - 1e-9) << trial;
    EXPECT_LE(d, dIn + 1e-9) << trial;
  }
  EXPECT_GT(sureFree, 50);
  EXPECT_GT(sureHit, 50);
}

TEST(Discs, TouchingDiscsAreFreeInEveryDirectionAndOverlapBeyondTheToleranceIsNot) {
  Scene s;
  s.bounds = {0, 0, 10, 10};
  for (int i = 0; i < 2; ++i)
    s.robots.push_back(
        {"disc-" + std::to_string(i), discStandIn({{0, 0}, 0.5}), {}, {}, Motion::Translate, 0.5});
  const CollisionChecker c(s);
  const double delta = s.tolerance();
  for (int k = 0; k < 360; k += 7) {
    const double a = k * M_PI / 180;
    const Pose p{5, 5, 0}, touch{5 + std::cos(a), 5 + std::sin(a), 0};
    const Pose deep{5 + (1 - 3 * delta) * std::cos(a), 5 + (1 - 3 * delta) * std::sin(a), 0};
    EXPECT_TRUE(c.robotsDisjoint(0, p, 1, touch)) << k;
    EXPECT_FALSE(c.robotsDisjoint(0, p, 1, deep)) << k;
  }
  EXPECT_TRUE(c.robotFree(0, {0.5, 0.5, 0})) << "touching two walls";
  EXPECT_FALSE(c.robotFree(0, {0.5 - 3 * delta, 5, 0}));
}

TEST(Discs, CertifierFollowsAContactAndRefusesAPassThrough) {
  Scene s;
  s.bounds = {0, 0, 10, 10};
  s.addObstacleDisc({{5, 5}, 1.5});
  s.robots.push_back(
      {"d", discStandIn({{0, 0}, 0.5}), {3, 5, 0}, {7, 5, 1440}, Motion::Rigid, 0.5});
  const CollisionChecker c(s);
  // Round the obstacle in contact with it: chords of 3600 steps per half turn cut in by 2e-7,
  // far less than the tolerance 1e-5; 360 steps would cut in by 2e-5.
  auto round = [](int steps) {
    std::vector<Config> around;
    for (int k = 0; k <= steps; ++k) {
      const double a = M_PI - M_PI * k / steps;
      around.push_back({5 + 2 * std::cos(a), 5 + 2 * std::sin(a), 1440.0 * k / steps});
    }
    return around;
  };
  const PathCheckResult ok = checkPath(s, c, round(3600));
  EXPECT_TRUE(ok.ok) << ok.reason << " (spinning a disc does not move it)";
  EXPECT_FALSE(checkPath(s, c, round(360)).ok);
  const PathCheckResult through = checkPath(s, c, {{3, 5, 0}, {7, 5, 1440}});
  EXPECT_FALSE(through.ok);
  // Just outside the contact, a straight line through both ends of the arc cuts the disc.
  EXPECT_FALSE(motionFree(c, {3, 5, 0}, {5, 7, 0}));
}

// Moving discs are certified by their swept stadiums, exactly, in one evaluation. Against the
// pose checker on 4000 poses along each motion: a motion certified free has every pose free,
// and a motion refused comes within the poses' spacing of a contact somewhere.
TEST(Discs, SweptDiscsAgreeWithPosesAlongTheMotion) {
  int refused = 0, certified = 0;
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    Scene s = mixedScene(seed);
    s.robots[1].motion = Motion::Translate;
    const CollisionChecker c(s);
    Random rng(seed + 50);
    for (int trial = 0; trial < 150; ++trial) {
      Config a(9), b(9);
      for (size_t i = 0; i < 3; ++i) {
        const Pose p{rng.uniform(1, 19), rng.uniform(1, 19), 0.3};
        setPose(a, i, p);
        // Robot 1 (a triangle) stands still; the discs move, sometimes one, sometimes both.
        const bool moves = i != 1 && (i == 0 || trial % 2 == 0);
        setPose(b, i, moves ? Pose{p.x + rng.uniform(-4, 4), p.y + rng.uniform(-4, 4), 0.3} : p);
      }
      if (!c.isFree(a)) continue;
      constexpr int kPoses = 4000;
      double least = INFINITY;
      bool allFree = true;
      for (int n = 0; n <= kPoses; ++n) {
        Config q(9);
        for (size_t k = 0; k < 9; ++k) q[k] = a[k] + (b[k] - a[k]) * n / kPoses;
        allFree = allFree && c.isFree(q);
        for (size_t i : {0, 2}) {
          least = std::min(least, c.robotClearance(i, poseOf(q, i)).distance);
          for (size_t j = 0; j < 3; ++j)
            if (j != i) least = std::min(least, c.robotsDistance(i, poseOf(q, i), j, poseOf(q, j)));
        }
      }
      double step = 0;
      for (size_t i = 0; i < 3; ++i)
        step = std::max(step, std::hypot(b[3 * i] - a[3 * i], b[3 * i + 1] - a[3 * i + 1]));
      step /= kPoses;
      if (motionFree(c, a, b)) {
        ++certified;
        EXPECT_TRUE(allFree) << "seed " << seed << " trial " << trial;
        EXPECT_TRUE(checkMotion(s, c, {a, b}).ok);
      } else {
        ++refused;
        EXPECT_LE(least, 2 * step + 1e-9) << "seed " << seed << " trial " << trial;
        EXPECT_FALSE(checkMotion(s, c, {a, b}).ok);
      }
    }
  }
  EXPECT_GT(certified, 20);
  EXPECT_GT(refused, 20);
}
