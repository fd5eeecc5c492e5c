// The continuous path checker: certifies motions, not just poses.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>
#include <utility>

#include "Support.h"
#include "check/PathChecker.h"
#include "io/PathIO.h"
#include "io/SceneIO.h"
#include "scenarios/Generators.h"

using namespace mms;
using namespace mms::test;
using nlohmann::json;

namespace {

Path pathOf(std::vector<Config> w) {
  Path p;
  p.waypoints = std::move(w);
  return p;
}

PathCheckResult check(const Scene& s, const Path& p, size_t budget = 20'000'000) {
  const CollisionChecker c(s);
  PathCheckSettings st;
  st.maxEvaluations = budget;
  return checkPath(s, c, p.waypoints, st);
}

const double kHalfPi = M_PI / 2;

// A straight motion of every robot: from anywhere in the bounds to up to `share` of their size
// away, turning up to `share` of two full turns either way.
std::pair<Config, Config> randomMotion(const Scene& s, std::mt19937_64& rng, double share) {
  const Box& b = s.bounds;
  std::uniform_real_distribution<double> x(b.xmin, b.xmax), y(b.ymin, b.ymax), turn(-M_PI, M_PI),
      step(-share, share);
  Config a(s.dof()), e(s.dof());
  for (size_t i = 0; i < s.robots.size(); ++i) {
    a[3 * i] = x(rng), a[3 * i + 1] = y(rng), a[3 * i + 2] = turn(rng);
    e[3 * i] = a[3 * i] + step(rng) * b.width();
    e[3 * i + 1] = a[3 * i + 1] + step(rng) * b.height();
    e[3 * i + 2] = a[3 * i + 2] + 2 * step(rng) * M_PI;
  }
  return {a, e};
}

}  // namespace

class BarSlot : public ::testing::Test {
 protected:
  Scene s = loadScene(scenario("one-robot/bar-slot.json"));
};

TEST_F(BarSlot, HandMadePathIsCertified) {
  const PathCheckResult r = check(s, loadPath(scenario("one-robot/bar-slot.path.json"), s));
  EXPECT_TRUE(r.ok) << r.reason;
  EXPECT_NEAR(r.minClearance, 0.2, 1e-3);  // the slot leaves 0.2 on each side of the bar
  EXPECT_NEAR(r.translation, 12, 1e-12);
  EXPECT_NEAR(r.rotation, M_PI, 1e-12);
}

TEST_F(BarSlot, PathFreeAtEveryWaypointButThroughTheWallIsRejected) {
  // Both waypoints are free; the straight motion between them crosses the wall.
  const Path p = pathOf({{-6, 0, kHalfPi}, {6, 0, kHalfPi}});
  const CollisionChecker c(s);
  ASSERT_TRUE(c.isFree(p.waypoints[0]));
  ASSERT_TRUE(c.isFree(p.waypoints[1]));
  const PathCheckResult r = check(s, p);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.segment, 0u);
  // First contact: the bar's right side (x + 0.4) reaches the wall (x = -1) at x = -1.4.
  EXPECT_NEAR(r.parameter, (-1.4 + 6) / 12, 1e-4);
  EXPECT_NE(r.reason.find("robot 'bar' hits obstacles["), std::string::npos) << r.reason;
}

TEST_F(BarSlot, RotationSweepingThroughTheWallIsRejected) {
  // At (-3.5, 0) the bar fits both flat (its tip in the slot) and upright, but turning
  // between the two swings the tip into the upper wall.
  const Path p =
      pathOf({{-6, 0, kHalfPi}, {-3.5, 0, kHalfPi}, {-3.5, 0, 0}, {6, 0, 0}, {6, 0, kHalfPi}});
  const CollisionChecker c(s);
  for (const Config& q : p.waypoints) ASSERT_TRUE(c.isFree(q));
  const PathCheckResult r = check(s, p);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.segment, 1u);
  EXPECT_GT(r.parameter, 0.5);  // near the flat end of the turn
  EXPECT_NE(r.reason.find("hits obstacles[1]"), std::string::npos) << r.reason;
}

TEST_F(BarSlot, EndsMustMatchStartAndGoal) {
  PathCheckResult r =
      check(s, pathOf({{-5.9, 0, kHalfPi}, {-6, 0, 0}, {6, 0, 0}, {6, 0, kHalfPi}}));
  EXPECT_FALSE(r.ok);
  EXPECT_NE(
      r.reason.find("puts robot 'bar' at (-5.9, 0, 1.5708), not at its start (-6, 0, 1.5708)"),
      std::string::npos)
      << r.reason;
  r = check(s, pathOf({{-6, 0, kHalfPi}, {-6, 0, 0}, {6, 0, 0}}));
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.reason.find("not at its goal (6, 0, 1.5708)"), std::string::npos) << r.reason;
  // Angles count modulo 2 pi: arriving upside down is arriving.
  r = check(s, pathOf({{-6, 0, kHalfPi}, {-6, 0, 0}, {6, 0, 0}, {6, 0, kHalfPi - 2 * M_PI}}));
  EXPECT_TRUE(r.ok) << r.reason;
}

TEST_F(BarSlot, EvaluationBudgetIsHonoured) {
  const PathCheckResult r = check(s, loadPath(scenario("one-robot/bar-slot.path.json"), s), 10);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.reason.find("could not certify within 10"), std::string::npos);
  EXPECT_LE(r.evaluations, 11u);
}

class TouchingScene : public ::testing::Test {
 protected:
  Scene s;
  void SetUp() override {
    s.name = "contact";
    s.bounds = {0, 0, 10, 10};
    s.obstacles = {{{4, 0}, {6, 0}, {6, 4}, {4, 4}}};
    Robot r;
    r.name = "sq";
    r.shape = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    r.start = {3, 1.5, 0};  // touching the obstacle's left side
    r.goal = {3, 1.52, 0};
    s.robots = {r};
  }
};

TEST_F(TouchingScene, ShortSlideAlongAContactIsCertified) {
  const PathCheckResult r = check(s, pathOf({{3, 1.5, 0}, {3, 1.52, 0}}));
  EXPECT_TRUE(r.ok) << r.reason;
  EXPECT_NEAR(r.minClearance, 0.0, 1e-12);
  EXPECT_GT(r.evaluations, 100u);  // pieces shrink to the tolerance along the contact
}

TEST_F(TouchingScene, SlideThatPenetratesBeyondTheToleranceIsRejected) {
  const double in = 3 * s.tolerance();
  s.robots[0].start.x = s.robots[0].goal.x = 3 - 0.1;
  const PathCheckResult r = check(s, pathOf({{2.9, 1.5, 0}, {3 + in, 1.51, 0}, {2.9, 1.52, 0}}));
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.segment, 0u);
  EXPECT_NE(r.reason.find("hits obstacles[0]"), std::string::npos) << r.reason;
}

TEST_F(TouchingScene, TranslateOnlyRobotMayNotTurn) {
  s.robots[0].motion = Motion::Translate;
  s.robots[0].start = {2, 6, 0};
  s.robots[0].goal = {8, 6, 0};
  PathCheckResult r = check(s, pathOf({{2, 6, 0}, {5, 6, 0.1}, {8, 6, 0}}));
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.reason.find("only translates"), std::string::npos) << r.reason;
  r = check(s, pathOf({{2, 6, 0}, {5, 6, 0}, {8, 6, 0}}));
  EXPECT_TRUE(r.ok) << r.reason;
}

TEST_F(TouchingScene, SingleWaypointPathWhenStartIsGoal) {
  s.robots[0].goal = s.robots[0].start;
  EXPECT_TRUE(check(s, pathOf({{3, 1.5, 0}})).ok);
}

TEST(TwoRobots, RobotsPassingThroughEachOtherAreRejected) {
  const Scene s = loadScene(scenario("two-robots/niche-swap.json"));
  // Straight swap along the corridor: each waypoint is free, the middle is not.
  const PathCheckResult r =
      check(s, pathOf({{1, 0.65, 0, 11, 0.65, 0}, {11, 0.65, 0, 1, 0.65, 0}}));
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.reason.find("robot 'left' hits robot 'right'"), std::string::npos) << r.reason;
  EXPECT_NEAR(r.parameter, 0.45, 0.01);  // they meet when 10 - 20 s = 1 (their width)
}

// ---- one motion at a time, as the sampling planners ask ----

// motionFree is the certifier's test of one segment: on random motions of two robots among
// clutter (free, hitting obstacles, hitting each other, turning into walls) it agrees with
// checkMotion's verdict every time.
TEST(MotionFree, AgreesWithTheCertifierOnRandomMotions) {
  for (const Scene& s : {randomPolygonsTwoRobots(4), openClutterScene(3)}) {
    const CollisionChecker c(s);
    std::mt19937_64 rng(7);
    int free = 0, refused = 0;
    for (int n = 0; n < 400; ++n) {
      const auto [a, e] = randomMotion(s, rng, 0.15);
      if (!c.isFree(a)) continue;
      const bool certified = checkMotion(s, c, {a, e}).ok;
      ASSERT_EQ(motionFree(c, a, e), certified) << s.name << " motion " << n;
      ++(certified ? free : refused);
    }
    EXPECT_GE(free, 20) << s.name;
    EXPECT_GE(refused, 20) << s.name;
  }
}

// The certifier skips what an evaluation proves clear on either side of its pose: an independent
// reference (the collision checker at 2000 poses along each motion) finds every certified motion,
// and every certified prefix, free; whether the clearance is measured changes no verdict.
TEST(MotionFree, CertifiedMotionsAreFreeAtEveryPoseAlongThem) {
  for (const Scene& s : {randomPolygonsTwoRobots(4), openClutterScene(3), openClutterScene(5)}) {
    const CollisionChecker c(s);
    std::mt19937_64 rng(11);
    PathCheckSettings unmeasured;
    unmeasured.measureClearance = false;
    int certified = 0, prefixes = 0;
    for (int n = 0; n < 300; ++n) {
      const auto [a, e] = randomMotion(s, rng, 0.1);
      if (!c.isFree(a)) continue;
      const PathCheckResult r = checkMotion(s, c, {a, e});
      ASSERT_EQ(checkMotion(s, c, {a, e}, unmeasured).ok, r.ok) << s.name << " motion " << n;
      const double t = r.ok ? 1.0 : certifiedPrefix(c, a, e);
      for (int k = 0; k <= 2000; ++k)
        ASSERT_TRUE(c.isFree(lerp(a, e, t * k / 2000.0)))
            << s.name << " motion " << n << " at " << t * k / 2000.0;
      certified += r.ok;
      prefixes += !r.ok && t > 0;
    }
    EXPECT_GE(certified, 20) << s.name;
    EXPECT_GE(prefixes, 20) << s.name;
  }
}

// Straight through the wall: the motion is certified up to just before the bar's first contact
// (x = -1.4, at 4.6 / 12 of it), to a pose at least the tolerance away from the wall, from which
// another motion can be certified (the way back).
TEST_F(BarSlot, CertifiedPrefixEndsAtTheFirstContact) {
  const CollisionChecker c(s);
  const Config a{-6, 0, kHalfPi}, e{6, 0, kHalfPi};
  EXPECT_FALSE(motionFree(c, a, e));
  const double t = certifiedPrefix(c, a, e), contact = 4.6 / 12;
  EXPECT_LT(t, contact);
  EXPECT_GT(t, contact - 1e-3);
  const Config reached{-6 + 12 * t, 0, kHalfPi};
  EXPECT_GE(c.robotClearance(0, poseOf(reached, 0)).distance, c.tolerance());
  EXPECT_TRUE(checkMotion(s, c, {a, reached, a}).ok);
  // A free motion is certified whole; a turn into the wall is refused.
  EXPECT_EQ(certifiedPrefix(c, a, Config{-3.5, 0, kHalfPi}), 1.0);
  EXPECT_TRUE(motionFree(c, a, Config{-3.5, 0, kHalfPi}));
  EXPECT_FALSE(motionFree(c, Config{-3.5, 0, kHalfPi}, Config{-3.5, 0, 0}));
  EXPECT_LT(certifiedPrefix(c, Config{-3.5, 0, kHalfPi}, Config{-3.5, 0, 0}), 1.0);
}

// ---- the CLI on the bundled scenarios, with corrupted variants ----

struct Bundled {
  const char* scene;
  const char* path;
};

void PrintTo(const Bundled& b, std::ostream* os) { *os << b.scene; }

class BundledPaths : public ::testing::TestWithParam<Bundled> {};

TEST_P(BundledPaths, AcceptedAndCorruptionsRejected) {
  const std::string scene = scenario(GetParam().scene), path = scenario(GetParam().path);
  Outcome r = runMms("check " + quote(scene) + " " + quote(path));
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("certified collision-free"), std::string::npos);
  EXPECT_NE(r.out.find("min clearance"), std::string::npos);
  EXPECT_NE(r.out.find("length"), std::string::npos);

  const json good = json::parse(readFile(path));
  const size_t n = good["waypoints"].size();
  ASSERT_GE(n, 3u);
  TempDir dir;
  auto rejected = [&](const json& bad, const std::string& expect) {
    const Outcome rr =
        runMms("check " + quote(scene) + " " + quote(dir.file("bad.json", bad.dump())));
    EXPECT_EQ(rr.code, 1) << bad.dump() << "\n" << rr.out << rr.err;
    EXPECT_NE(rr.out.find(expect.rfind(", not at", 0) == 0 ? "rejected: the last waypoint"
                                                           : "rejected: segment "),
              std::string::npos)
        << rr.out;
    EXPECT_NE(rr.out.find(expect), std::string::npos) << rr.out;
  };
  // Shortcut: straight from start to goal.
  json bad = good;
  bad["waypoints"] = {good["waypoints"][0], good["waypoints"][n - 1]};
  rejected(bad, "hits");
  // A middle waypoint dragged into the first obstacle (every robot's reference point).
  bad = good;
  const Scene s = loadScene(scene);
  for (size_t i = 0; i < s.robots.size(); ++i) {
    bad["waypoints"][1][3 * i] = s.obstacles[0][0].x;
    bad["waypoints"][1][3 * i + 1] = s.obstacles[0][0].y;
  }
  rejected(bad, "hits");
  // Stops short of the goal.
  bad = good;
  bad["waypoints"].erase(n - 1);
  rejected(bad, ", not at its goal (");
}

INSTANTIATE_TEST_SUITE_P(
    Scenarios, BundledPaths,
    ::testing::Values(Bundled{"one-robot/bar-slot.json", "one-robot/bar-slot.path.json"},
                      Bundled{"two-robots/niche-swap.json", "two-robots/niche-swap.path.json"},
                      Bundled{"translating/cup.json", "translating/cup.path.json"}),
    [](const auto& info) { return std::to_string(info.index); });
