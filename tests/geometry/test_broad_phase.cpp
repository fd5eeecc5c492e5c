// The broad phase for many robots against all pairs: the same first contact, and the certifier
// with it sound and complete against dense sampling with every pair tested.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>

#include "check/PathChecker.h"
#include "geometry/BroadPhase.h"
#include "geometry/CollisionChecker.h"
#include "util/Random.h"

namespace mms {
namespace {

Ring polygonAround(double r, int sides, double phase) {
  Ring ring;
  for (int i = 0; i < sides; ++i) {
    const double a = phase + 2 * M_PI * i / sides;
    ring.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return ring;
}

// k robots of mixed sizes (some not centred on their reference point) scattered in a box small
// enough that some overlap.
Scene crowd(size_t k, uint64_t seed, double side) {
  Random rng(seed);
  Scene s;
  s.bounds = {0, 0, side, side};
  s.obstacles = {{{10, 10}, {14, 10}, {12, 13}}};
  for (size_t i = 0; i < k; ++i) {
    Ring shape = polygonAround(rng.uniform(0.3, 1.5), 3 + int(rng.below(6)), rng.uniform(0, 1));
    if (i % 3 == 0)
      for (Vec2& v : shape) v = v + Vec2{0.8, 0};  // reference point off the shape's middle
    const Pose p{rng.uniform(2, side - 2), rng.uniform(2, side - 2), rng.uniform(-3, 3)};
    Robot r{"r", shape, p, p, Motion::Rigid};
    r.name += std::to_string(i);
    s.robots.push_back(std::move(r));
  }
  return s;
}

Config randomConfig(const Scene& s, Random& rng) {
  Config q;
  for (size_t i = 0; i < s.robots.size(); ++i)
    for (double v :
         {rng.uniform(2, s.bounds.xmax - 2), rng.uniform(2, s.bounds.ymax - 2), rng.uniform(-3, 3)})
      q.push_back(v);
  return q;
}

// A configuration the checker finds free, of up to 201 drawn; none when all collide.
std::optional<Config> freeConfig(const Scene& s, const CollisionChecker& c, Random& rng) {
  Config q = randomConfig(s, rng);
  for (int attempt = 0; attempt < 200 && !c.isFree(q); ++attempt) q = randomConfig(s, rng);
  if (!c.isFree(q)) return std::nullopt;
  return q;
}

// Every pair, in order: the reference the broad phase must agree with.
std::optional<std::pair<size_t, size_t>> firstOverlapAllPairs(const CollisionChecker& c,
                                                              const Config& q) {
  for (size_t i = 0; i < c.robotCount(); ++i)
    for (size_t j = i + 1; j < c.robotCount(); ++j)
      if (!c.robotsDisjoint(i, poseOf(q, i), j, poseOf(q, j))) return std::pair(i, j);
  return std::nullopt;
}

bool freeAllPairs(const CollisionChecker& c, const Config& q) {
  for (size_t i = 0; i < c.robotCount(); ++i)
    if (!c.robotFree(i, poseOf(q, i))) return false;
  return !firstOverlapAllPairs(c, q);
}

TEST(BroadPhase, SweepFindsExactlyThePairsWhoseDiscsComeWithinReach) {
  Random rng(7);
  std::vector<Vec2> centres;
  std::vector<double> radii;
  for (int i = 0; i < 300; ++i) {
    centres.push_back({rng.uniform(0, 100), rng.uniform(0, 100)});
    radii.push_back(rng.uniform(0.1, 3));
  }
  DiscSweep sweep;
  for (double reach : {0.0, 0.5, 4.0}) {
    std::vector<DiscSweep::Pair> expected;
    for (size_t i = 0; i < centres.size(); ++i)
      for (size_t j = i + 1; j < centres.size(); ++j)
        if (norm(centres[i] - centres[j]) - radii[i] - radii[j] < reach)
          expected.emplace_back(i, j);
    EXPECT_EQ(sweep.near(centres, radii, reach, [](size_t, size_t, double) { return true; }),
              expected)
        << "reach " << reach;
  }
}

TEST(BroadPhase, FirstContactAmongManyRobotsIsThatOfAllPairs) {
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    const Scene s = crowd(60, seed, 60);
    const CollisionChecker c(s);
    ASSERT_GT(c.robotCount(), CollisionChecker::kAllPairsUpTo);
    Random rng(seed * 31);
    size_t overlapping = 0;
    for (int t = 0; t < 20; ++t) {
      const Config q = randomConfig(s, rng);
      const auto contact = c.firstContact(q);
      bool robotsClear = true;
      for (size_t i = 0; i < s.robots.size() && robotsClear; ++i)
        robotsClear = c.robotFree(i, poseOf(q, i));
      if (!robotsClear) continue;  // an obstacle or the bounds come first
      const auto expected = firstOverlapAllPairs(c, q);
      overlapping += expected.has_value();
      ASSERT_EQ(contact.has_value(), expected.has_value()) << "seed " << seed;
      if (expected) {
        EXPECT_EQ(contact->first, expected->first);
        EXPECT_EQ(contact->second.index, expected->second);
      }
    }
    EXPECT_GT(overlapping, 0u) << "the crowd never overlaps: the test tests nothing";
  }
}

// Robots move one at a time or all at once; the certifier (with the broad phase) must refuse
// every motion that dense sampling with all pairs finds in collision, and accept only motions
// that sampling finds free.
TEST(BroadPhase, CertifierAmongManyRobotsAgreesWithDenseSamplingOfAllPairs) {
  size_t refused = 0, accepted = 0;
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    const Scene s = crowd(40, seed, 90);
    const CollisionChecker c(s);
    Random rng(seed * 17);
    const std::optional<Config> drawn = freeConfig(s, c, rng);
    if (!drawn) continue;
    const Config& a = *drawn;
    for (int t = 0; t < 6; ++t) {
      Config b = a;
      const bool all = t % 2 == 0;
      for (size_t i = 0; i < s.robots.size(); ++i)
        if (all || i == size_t(t)) {
          b[3 * i] += rng.uniform(-12, 12);
          b[3 * i + 1] += rng.uniform(-12, 12);
          b[3 * i + 2] += rng.uniform(-1, 1);
        }
      bool sampledFree = true;
      for (int k = 0; k <= 400 && sampledFree; ++k) {
        Config q = a;
        for (size_t x = 0; x < q.size(); ++x) q[x] += (b[x] - a[x]) * k / 400.0;
        sampledFree = freeAllPairs(c, q);
      }
      const bool certified = checkMotion(s, c, {a, b}).ok;
      if (certified) {
        EXPECT_TRUE(sampledFree) << "seed " << seed << " motion " << t;
      }
      if (!sampledFree) {
        EXPECT_FALSE(certified) << "seed " << seed << " motion " << t;
      }
      EXPECT_EQ(motionFree(c, a, b), certified) << "seed " << seed << " motion " << t;
      (certified ? accepted : refused)++;
    }
  }
  EXPECT_GT(accepted, 3u);
  EXPECT_GT(refused, 3u);
}

}  // namespace
}  // namespace mms

namespace mms {
namespace {

// The certifier checks robots that stay put once, where a segment does not start where the last
// one ended: a path of one-at-a-time moves gets the answer and smallest clearance of its
// segments certified one by one (each with that check).
TEST(BroadPhase, APathCertifiesAsItsSegmentsDoOneByOne) {
  size_t refused = 0;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    const Scene s = crowd(30, seed, 70);
    const CollisionChecker c(s);
    Random rng(seed * 5);
    const std::optional<Config> q = freeConfig(s, c, rng);
    if (!q) continue;
    std::vector<Config> path{*q};
    for (int m = 0; m < 12; ++m) {
      Config next = path.back();
      const size_t r = rng.below(s.robots.size());
      next[3 * r] += rng.uniform(-6, 6);
      next[3 * r + 1] += rng.uniform(-6, 6);
      path.push_back(next);
    }
    const PathCheckResult whole = checkMotion(s, c, path);
    bool ok = true;
    double least = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k + 1 < path.size() && ok; ++k) {
      const PathCheckResult one = checkMotion(s, c, {path[k], path[k + 1]});
      ok = one.ok;
      least = std::min(least, one.minClearance);
      if (!ok) {
        EXPECT_EQ(whole.segment, k) << "seed " << seed;
      }
    }
    EXPECT_EQ(whole.ok, ok) << "seed " << seed;
    if (ok) {
      EXPECT_DOUBLE_EQ(whole.minClearance, least) << "seed " << seed;
    }
    refused += !ok;
  }
  EXPECT_GT(refused, 0u);
}

}  // namespace
}  // namespace mms
