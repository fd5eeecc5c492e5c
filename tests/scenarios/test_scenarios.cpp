// Scene generators: valid scenes, same seed same scene, and the property each family stands
// for, checked with the collision and path checkers (not with the planner it benchmarks).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <set>

#include "Support.h"
#include "check/PathChecker.h"
#include "geometry/CollisionChecker.h"
#include "io/SceneIO.h"
#include "mms/Planner.h"
#include "scenarios/Generators.h"

using namespace mms;

namespace {
Vec2 inFrame(const Pose& frame, const Pose& p) {  // p's position in frame's coordinates
  const double c = std::cos(frame.theta), s = std::sin(frame.theta);
  return {c * (p.x - frame.x) + s * (p.y - frame.y), -s * (p.x - frame.x) + c * (p.y - frame.y)};
}
// The part slides in the pocket to the midpoint of its start and goal holds; the pair, as one
// rigid body, translates to the chamber's centre, turns there in steps of a quarter degree (the
// part's chord between steps strays from its arc by ~1e-5 part sizes, far less than the play),
// translates to the goal; the part slides to its goal hold. Both holds lie in the pocket's
// play, a rectangle of positions at one angle, so the slides are free.
std::vector<Config> turnTogether(const Scene& s) {
  const Pose g = s.robots[0].start, goal = s.robots[0].goal;
  const Vec2 a = inFrame(g, s.robots[1].start), b = inFrame(goal, s.robots[1].goal);
  const Vec2 mid{(a.x + b.x) / 2, (a.y + b.y) / 2};
  const double turn = std::remainder(goal.theta - g.theta, 2 * M_PI) > 0 ? M_PI : -M_PI;
  auto pair = [&](double x, double y, double theta, Vec2 hold) {
    const double c = std::cos(theta), sn = std::sin(theta);
    return Config{x, y, theta, x + c * hold.x - sn * hold.y, y + sn * hold.x + c * hold.y, theta};
  };
  std::vector<Config> w{pair(g.x, g.y, g.theta, a), pair(g.x, g.y, g.theta, mid),
                        pair(0, 0, g.theta, mid)};
  for (int i = 1; i <= 720; ++i) w.push_back(pair(0, 0, g.theta + turn * i / 720, mid));
  w.push_back(pair(goal.x, goal.y, g.theta + turn, mid));
  w.push_back(pair(goal.x, goal.y, g.theta + turn, b));
  return w;
}
}  // namespace

TEST(ScenarioCarryTurn, EverySeedIsSolvedByTurningThePairTogether) {
  size_t regrips = 0;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE(seed);
    const Scene s = carryTurnScene(seed);
    ASSERT_NO_THROW(parseScene(sceneToJson(s), "carry-turn"));
    const CollisionChecker checker(s);
    const PathCheckResult r = checkPath(s, checker, turnTogether(s));
    EXPECT_TRUE(r.ok) << r.reason;
    // Narrow: the gripper cannot turn a quarter in place where it starts, either way (the
    // corridor is narrower than its diagonal), and both robots end turned half round.
    for (const double way : {1.0, -1.0}) {
      bool blocked = false;
      for (int i = 1; i <= 90 && !blocked; ++i) {
        Pose q = s.robots[0].start;
        q.theta += way * M_PI / 2 * i / 90;
        blocked = !checker.robotFree(0, q);
      }
      EXPECT_TRUE(blocked);
    }
    for (const Robot& r : s.robots)
      EXPECT_NEAR(std::abs(std::remainder(r.goal.theta - r.start.theta, 2 * M_PI)), M_PI, 1e-9);
    const Vec2 a = inFrame(s.robots[0].start, s.robots[1].start),
               b = inFrame(s.robots[0].goal, s.robots[1].goal);
    regrips += std::hypot(a.x - b.x, a.y - b.y) > 1e-6;
  }
  EXPECT_GE(regrips, 8u);  // the holds differ: the part changes its place in the pocket
}

TEST(ScenarioCarryTurn, SameSeedSameSceneOtherSeedsOtherScenes) {
  EXPECT_EQ(sceneToJson(carryTurnScene(4)), sceneToJson(carryTurnScene(4)));
  EXPECT_NE(sceneToJson(carryTurnScene(4)), sceneToJson(carryTurnScene(5)));
}

// The extent of a robot's shape along x (axis 0) or y (axis 1): [lo, hi].
std::pair<double, double> shapeExtent(const Ring& r, int axis) {
  double lo = INFINITY, hi = -INFINITY;
  for (const Vec2 v : r) {
    const double c = axis == 0 ? v.x : v.y;
    lo = std::min(lo, c), hi = std::max(hi, c);
  }
  return {lo, hi};
}

// Robot 0 waits in the niche while robot 1 passes below it: certified on seeds 1-10. Side by
// side the two do not fit the corridor, so the niche is needed; the niche fits the larger robot
// with a play of 0.04-0.1 of the robots' size (or the play asked for).
TEST(ScenarioNicheSwap, EverySeedIsSolvedThroughATightNiche) {
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    for (const double play : {-1.0, 0.5}) {
      SCOPED_TRACE(std::to_string(seed) + " play " + std::to_string(play));
      const Scene s = nicheSwapScene(seed, play);
      ASSERT_NO_THROW(parseScene(sceneToJson(s), "niche-swap"));
      const CollisionChecker checker(s);
      // The niche: the gap in the corridor's upper wall (obstacles 0 and 1 flank it).
      const double left = s.obstacles[0][1].x, right = s.obstacles[1][0].x;
      const double top = s.obstacles[2][0].y, corridor = s.obstacles[0][0].y;
      double widest = 0, tallest = 0;
      for (const Robot& rb : s.robots) {
        const auto [xlo, xhi] = shapeExtent(rb.shape, 0);
        const auto [ylo, yhi] = shapeExtent(rb.shape, 1);
        widest = std::max(widest, xhi - xlo), tallest = std::max(tallest, yhi - ylo);
      }
      const double spareX = right - left - widest, spareY = top - corridor - tallest;
      EXPECT_NEAR(spareX, spareY, 1e-9);
      if (play < 0) {
        EXPECT_GE(spareX, 0.04 - 1e-9);
        EXPECT_LE(spareX, 0.1 + 1e-9);
      } else {
        EXPECT_NEAR(spareX, play, 1e-9);
      }
      // Robot 0 centred in the niche.
      const auto [xlo, xhi] = shapeExtent(s.robots[0].shape, 0);
      const auto [ylo, yhi] = shapeExtent(s.robots[0].shape, 1);
      const double nx = (left + right) / 2 - (xlo + xhi) / 2;
      const double ny = (corridor + top) / 2 - (ylo + yhi) / 2;
      const Pose a0 = s.robots[0].start, a1 = s.robots[0].goal;
      const Pose b0 = s.robots[1].start, b1 = s.robots[1].goal;
      const std::vector<Config> w{{a0.x, a0.y, 0, b0.x, b0.y, 0}, {nx, a0.y, 0, b0.x, b0.y, 0},
                                  {nx, ny, 0, b0.x, b0.y, 0},     {nx, ny, 0, b1.x, b1.y, 0},
                                  {nx, a0.y, 0, b1.x, b1.y, 0},   {a1.x, a1.y, 0, b1.x, b1.y, 0}};
      const PathCheckResult r = checkPath(s, checker, w);
      EXPECT_TRUE(r.ok) << r.reason;
      // At their angle the two robots' heights add up to more than the corridor's width: they
      // cannot pass side by side.
      double height = 0;
      for (const Robot& rb : s.robots) {
        const auto [lo, hi] = shapeExtent(rb.shape, 1);
        height += hi - lo;
      }
      EXPECT_LT(corridor, height);
    }
  }
  EXPECT_NE(sceneToJson(nicheSwapScene(4)), sceneToJson(nicheSwapScene(5)));
  EXPECT_EQ(sceneToJson(nicheSwapScene(4)), sceneToJson(nicheSwapScene(4)));
}

// Three robots: the oncoming robot steps into the niche, the two others pass below it to the
// corridor's right end, and it goes on to the left end: a constructed 9-D path, certified on
// seeds 1-10. No two fit the corridor side by side and none can turn in it, and both ends are
// dead ends, so the niche is needed.
TEST(ScenarioNicheThree, EverySeedIsSolvedWithOneRobotWaitingInTheNiche) {
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE(seed);
    const Scene s = nicheThreeScene(seed);
    ASSERT_NO_THROW(parseScene(sceneToJson(s), "niche-three"));
    ASSERT_EQ(s.robots.size(), 3u);
    const CollisionChecker checker(s);
    const double width = s.obstacles[0][0].y;  // the corridor's ceiling
    const double nx0 = s.obstacles[0][1].x, nx1 = s.obstacles[1][0].x;
    const double nicheTop = s.obstacles[2][0].y;
    std::vector<double> q;
    for (const Robot& r : s.robots) q.insert(q.end(), {r.start.x, r.start.y, r.start.theta});
    std::vector<Config> w{q};
    auto move = [&](size_t robot, double x, double y) {
      q[3 * robot] = x, q[3 * robot + 1] = y;
      w.push_back(q);
    };
    const double mid = (nx0 + nx1) / 2;
    move(2, mid, width / 2);
    move(2, mid, (width + nicheTop) / 2);
    for (const size_t r : {1, 0}) move(r, s.robots[r].goal.x, s.robots[r].goal.y);
    move(2, mid, width / 2);
    move(2, s.robots[2].goal.x, s.robots[2].goal.y);
    const PathCheckResult res = checkPath(s, checker, w);
    EXPECT_TRUE(res.ok) << res.reason;
    EXPECT_EQ(w.back(), goalConfig(s));
    // Side by side, any two are taller than the corridor; turned, any is longer than it is wide.
    for (size_t i = 0; i < 3; ++i) {
      const auto [xlo, xhi] = shapeExtent(s.robots[i].shape, 0);
      const auto [ylo, yhi] = shapeExtent(s.robots[i].shape, 1);
      EXPECT_LT(width, std::hypot(xhi - xlo, yhi - ylo));
      EXPECT_LT(yhi - ylo, width);
      for (size_t j = i + 1; j < 3; ++j) {
        const auto [jlo, jhi] = shapeExtent(s.robots[j].shape, 1);
        EXPECT_LT(width, (yhi - ylo) + (jhi - jlo));
      }
    }
    // Robot 2 comes the other way: it starts right of the others and ends left of them.
    EXPECT_GT(s.robots[2].start.x, s.robots[1].start.x);
    EXPECT_LT(s.robots[2].goal.x, s.robots[1].goal.x);
  }
  EXPECT_NE(sceneToJson(nicheThreeScene(4)), sceneToJson(nicheThreeScene(5)));
  EXPECT_EQ(sceneToJson(nicheThreeScene(4)), sceneToJson(nicheThreeScene(4)));
}

// `mms scenario ... --translate NAME`: the named robot only translates and the scene is named
// apart; a robot that is not there, or one that turns from start to goal, is refused (exit 2,
// one line naming the option and the robot).
TEST(ScenarioTranslate, NamedRobotsOnlyTranslateAndTurningOnesAreRefused) {
  test::TempDir dir;
  const std::string file = dir.path("n.json");
  const test::Outcome ok =
      test::runMms("scenario niche-three --seed 3 --translate oncoming -o " + test::quote(file));
  ASSERT_EQ(ok.code, 0) << ok.err;
  const Scene s = loadScene(file);
  EXPECT_EQ(s.name, "niche-three-oncoming-translates-3");  // the family, then the seed
  const Scene plain = nicheThreeScene(3);
  for (size_t r = 0; r < 3; ++r) {
    EXPECT_EQ(s.robots[r].motion, r == 2 ? Motion::Translate : Motion::Rigid) << r;
    EXPECT_EQ(s.robots[r].start.x, plain.robots[r].start.x) << r;
    EXPECT_EQ(s.robots[r].goal.x, plain.robots[r].goal.x) << r;
  }
  const test::Outcome unknown =
      test::runMms("scenario niche-three --translate nobody -o " + test::quote(file));
  EXPECT_EQ(unknown.code, 2);
  EXPECT_EQ(unknown.err,
            "--translate: no robot 'nobody' in niche-three-1 (robots: first, second, "
            "oncoming)\n");
  // Named twice: translated once, named once. A trailing number that is not the seed stays.
  ASSERT_EQ(test::runMms("scenario pacman --translate square,square -o " + test::quote(file)).code,
            0);
  EXPECT_EQ(loadScene(file).name, "pacman-0-square-translates");
  // A robot that translates already would give a scene named as the plain one: refused.
  const test::Outcome already =
      test::runMms("scenario discs-swap --translate disc-0 -o " + test::quote(file));
  EXPECT_EQ(already.code, 2);
  EXPECT_EQ(already.err, "--translate: robot 'disc-0' of discs-swap-1 translates already\n");
  const test::Outcome turning =
      test::runMms("scenario carry-turn --translate part -o " + test::quote(file));
  EXPECT_EQ(turning.code, 2);
  EXPECT_NE(turning.err.find("--translate: robot 'part' of carry-turn-1 turns from start to goal"),
            std::string::npos)
      << turning.err;
  EXPECT_EQ(std::count(turning.err.begin(), turning.err.end(), '\n'), 1);
}

// Discs: valid scenes of translating discs, free and apart at start and goal; round the block
// each goes to where another starts; the same seed gives the same scene.
TEST(ScenarioDiscs, SwapAndRoomScenesAreValidAndDeterministic) {
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE(seed);
    for (const Scene& s : {discsSwapScene(seed), discsRoomScene(seed), discsRoomScene(seed, 16)}) {
      ASSERT_NO_THROW(parseScene(sceneToJson(s), s.name));
      const CollisionChecker checker(s);
      for (size_t i = 0; i < s.robots.size(); ++i) {
        EXPECT_EQ(s.robots[i].motion, Motion::Translate);
        EXPECT_TRUE(checker.robotFree(i, s.robots[i].start));
        EXPECT_TRUE(checker.robotFree(i, s.robots[i].goal));
        for (size_t j = i + 1; j < s.robots.size(); ++j) {
          EXPECT_TRUE(checker.robotsDisjoint(i, s.robots[i].start, j, s.robots[j].start));
          EXPECT_TRUE(checker.robotsDisjoint(i, s.robots[i].goal, j, s.robots[j].goal));
        }
      }
    }
    const Scene swap = discsSwapScene(seed);
    ASSERT_GE(swap.robots.size(), 4u);
    ASSERT_LE(swap.robots.size(), 5u);
    for (const Robot& r : swap.robots) {
      size_t starts = 0;
      for (const Robot& o : swap.robots)
        starts += std::hypot(o.start.x - r.goal.x, o.start.y - r.goal.y) < 1e-9;
      EXPECT_EQ(starts, 1u);
    }
    EXPECT_EQ(discsRoomScene(seed).robots.size(), 10u);
    EXPECT_EQ(discsRoomScene(seed, 16).robots.size(), 16u);
  }
  EXPECT_EQ(sceneToJson(discsSwapScene(3)), sceneToJson(discsSwapScene(3)));
  EXPECT_NE(sceneToJson(discsSwapScene(3)), sceneToJson(discsSwapScene(4)));
  EXPECT_EQ(sceneToJson(discsRoomScene(3)), sceneToJson(discsRoomScene(3)));
}

// A round room: valid, its discs each going to where another starts, and the way its generator
// promises (all turning round the middle together, in steps of half a degree) certified by the
// path checker; --robots sets the count, smaller discs for more.
TEST(ScenarioDiscs, RoundRoomDiscsCrossByTurningTogether) {
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    for (const size_t count : {size_t(0), size_t(2), size_t(8)}) {
      SCOPED_TRACE(std::to_string(seed) + " " + std::to_string(count));
      const Scene s = roundRoomScene(seed, count);
      ASSERT_NO_THROW(parseScene(sceneToJson(s), s.name));
      const size_t n = s.robots.size();
      if (count) {
        EXPECT_EQ(n, count);
      } else {
        EXPECT_TRUE(n >= 3 && n <= 5) << n;
      }
      const double a0 = std::atan2(s.robots[0].start.y, s.robots[0].start.x);
      const double a1 = std::atan2(s.robots[0].goal.y, s.robots[0].goal.x);
      const double turn = std::remainder(a1 - a0, 2 * M_PI) < 0
                              ? std::remainder(a1 - a0, 2 * M_PI) + 2 * M_PI
                              : std::remainder(a1 - a0, 2 * M_PI);
      const int steps = int(std::ceil(turn / (M_PI / 360)));
      std::vector<Config> way;
      for (int k = 0; k <= steps; ++k) {
        const double c = std::cos(turn * k / steps), sn = std::sin(turn * k / steps);
        Config q;
        for (const Robot& r : s.robots)
          q.insert(q.end(), {c * r.start.x - sn * r.start.y, sn * r.start.x + c * r.start.y, 0});
        way.push_back(q);
      }
      for (size_t i = 0; i < n; ++i) {
        EXPECT_NEAR(way.back()[3 * i], s.robots[i].goal.x, 1e-9);
        EXPECT_NEAR(way.back()[3 * i + 1], s.robots[i].goal.y, 1e-9);
      }
      const PathCheckResult c = checkPath(s, CollisionChecker(s), way);
      EXPECT_TRUE(c.ok) << c.reason;
    }
  }
  EXPECT_EQ(sceneToJson(roundRoomScene(3)), sceneToJson(roundRoomScene(3)));
  EXPECT_NE(sceneToJson(roundRoomScene(3)), sceneToJson(roundRoomScene(4)));
  EXPECT_EQ(test::runMms("scenario round-room --robots 1 -o /dev/null").code, 2);
}

// Doors: lined up with the door (angle 0) the robot slides through each wall, and turns in the
// rooms' middles: a constructed path, certified on seeds 1-10. Across (a quarter turn) it does
// not fit a door: it must line up.
TEST(ScenarioDoors, EverySeedIsSolvedByLiningUpWithEachDoor) {
  std::set<size_t> wallCounts;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE(seed);
    const Scene s = doorsScene(seed);
    ASSERT_NO_THROW(parseScene(sceneToJson(s), "doors"));
    const CollisionChecker checker(s);
    const Pose start = s.robots[0].start, goal = s.robots[0].goal;
    const double roomMiddleY = (s.bounds.ymin + s.bounds.ymax) / 2;
    std::vector<Config> w{{start.x, start.y, start.theta}, {start.x, start.y, 0}};
    // Obstacles come in pairs per wall: below the door, then above it.
    ASSERT_EQ(s.obstacles.size() % 2, 0u);
    wallCounts.insert(s.obstacles.size() / 2);
    double x = start.x;
    for (size_t k = 0; k < s.obstacles.size(); k += 2) {
      double below = -INFINITY, above = INFINITY, wallRight = -INFINITY;
      for (const Vec2 v : s.obstacles[k])
        below = std::max(below, v.y), wallRight = std::max(wallRight, v.x);
      for (const Vec2 v : s.obstacles[k + 1]) above = std::min(above, v.y);
      const double doorY = (below + above) / 2;
      const double next =
          k + 2 < s.obstacles.size() ? (wallRight + s.obstacles[k + 2][0].x) / 2 : goal.x;
      w.push_back({x, doorY, 0});
      w.push_back({next, doorY, 0});
      // Across, the robot does not fit the door.
      EXPECT_FALSE(checker.robotFree(0, {wallRight - 0.1, doorY, M_PI / 2}));
      x = next;
    }
    w.push_back({goal.x, roomMiddleY, 0});
    w.push_back({goal.x, goal.y, goal.theta});
    const PathCheckResult r = checkPath(s, checker, w);
    EXPECT_TRUE(r.ok) << r.reason << " at segment " << r.segment;
  }
  EXPECT_EQ(wallCounts, (std::set<size_t>{1, 2, 3}));
  EXPECT_NE(sceneToJson(doorsScene(4)), sceneToJson(doorsScene(5)));
}

// A bend: the plank cannot turn a quarter in place where it starts or ends, yet a path exists
// (found by MMS and certified by the independent path checker).
TEST(ScenarioBend, EverySeedIsATightCornerWithAPath) {
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE(seed);
    const Scene s = bendScene(seed);
    ASSERT_NO_THROW(parseScene(sceneToJson(s), "bend"));
    const CollisionChecker checker(s);
    for (const Pose end : {s.robots[0].start, s.robots[0].goal}) {
      ASSERT_TRUE(checker.robotFree(0, end));
      bool blocked = false;  // a quarter turn in place
      for (int i = 1; i <= 90 && !blocked; ++i)
        blocked = !checker.robotFree(0, {end.x, end.y, end.theta + M_PI / 2 * i / 90});
      EXPECT_TRUE(blocked);
    }
    const std::unique_ptr<Planner> planner = makePlanner("mms", s, {seed, {}});
    const PlanResult r = planner->solve(Termination(test::planSeconds(30)));
    ASSERT_EQ(r.status, PlanStatus::Found);
    EXPECT_TRUE(checkPath(s, checker, r.waypoints).ok);
  }
  EXPECT_NE(sceneToJson(bendScene(4)), sceneToJson(bendScene(5)));
}

// Open clutter: one or two robots, 20-30 obstacles, free starts and goals; open enough that
// both MMS and RRT-Connect find certified paths on every seed.
TEST(ScenarioOpenClutter, FreeEndsAndPathsOnEverySeed) {
  std::set<size_t> robotCounts;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE(seed);
    const Scene s = openClutterScene(seed);
    ASSERT_NO_THROW(parseScene(sceneToJson(s), "open-clutter"));
    EXPECT_GE(s.obstacles.size(), 20u);
    EXPECT_LE(s.obstacles.size(), 30u);
    robotCounts.insert(s.robots.size());
    const CollisionChecker checker(s);
    EXPECT_TRUE(checker.isFree(startConfig(s)));
    EXPECT_TRUE(checker.isFree(goalConfig(s)));
    // Seeds 1 (one robot) and 2 (two) under the sanitizers, where MMS takes seconds on each.
    if (test::kSanitized && seed > 2) continue;
    for (const char* name : {"mms", "rrtconnect"}) {
      const PlanResult r =
          makePlanner(name, s, {seed, {}})->solve(Termination(test::planSeconds(30)));
      EXPECT_EQ(r.status, PlanStatus::Found) << name;
    }
  }
  EXPECT_EQ(robotCounts, (std::set<size_t>{1, 2}));
}

// A key through a keyhole: a quarter turn from start to goal, a path on every seed (found by
// MMS, certified by the independent checker); the same seed gives the same scene, and a slack
// given changes the chamber alone (the key, its poses and the walls' number stay).
TEST(ScenarioKeyhole, EverySeedIsAQuarterTurnWithAPath) {
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE(seed);
    const Scene s = keyholeScene(seed);
    ASSERT_NO_THROW(parseScene(sceneToJson(s), "keyhole"));
    const Robot& key = s.robots.at(0);
    EXPECT_NEAR(std::abs(std::remainder(key.goal.theta - key.start.theta, 2 * M_PI)), M_PI / 2,
                1e-9);
    const CollisionChecker checker(s);
    const std::unique_ptr<Planner> planner = makePlanner("mms", s, {seed, {}});
    const PlanResult r = planner->solve(Termination(test::planSeconds(30)));
    ASSERT_EQ(r.status, PlanStatus::Found);
    EXPECT_TRUE(checkPath(s, checker, r.waypoints).ok);
  }
  EXPECT_EQ(sceneToJson(keyholeScene(4)), sceneToJson(keyholeScene(4)));
  EXPECT_NE(sceneToJson(keyholeScene(4)), sceneToJson(keyholeScene(5)));
  const Scene tight = keyholeScene(4, 0.03), loose = keyholeScene(4, 0.12);
  EXPECT_EQ(tight.robots.at(0).shape, loose.robots.at(0).shape);
  EXPECT_EQ(tight.robots.at(0).start.theta, loose.robots.at(0).start.theta);
  EXPECT_EQ(tight.obstacles.size(), loose.obstacles.size());
  EXPECT_NE(sceneToJson(tight), sceneToJson(loose));
}

// Swallow and turn: on every seed the generator's way through (the U takes the fixed part into
// its mouth and turns half round about it) is certified by the path checker, while the same half
// turn about the U's reference point is not free: the turning centre is elsewhere. A slack given
// changes the bay (and where the corridors begin) alone; even at 0.001 the turn is free.
TEST(ScenarioSwallow, EverySeedTurnsHalfRoundAboutThePartAndNotAboutItsReferencePoint) {
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    SCOPED_TRACE(seed);
    const Scene s = swallowScene(seed);
    ASSERT_NO_THROW(parseScene(sceneToJson(s), "swallow"));
    ASSERT_EQ(s.robots.size(), 1u);
    const Robot& u = s.robots[0];
    EXPECT_NEAR(std::abs(std::remainder(u.goal.theta - u.start.theta, 2 * M_PI)), M_PI, 1e-9);
    const CollisionChecker checker(s);
    const std::vector<Config> w = swallowWitness(s);
    const PathCheckResult c = checkPath(s, checker, w);
    EXPECT_TRUE(c.ok) << c.reason;
    // Where the U holds the part, half a turn about its own reference point hits the walls.
    Config turned = w[1];
    turned[2] = w.back()[2];
    EXPECT_FALSE(checkPath(s, checker, {w[1], turned}).ok);
  }
  EXPECT_EQ(sceneToJson(swallowScene(4)), sceneToJson(swallowScene(4)));
  EXPECT_NE(sceneToJson(swallowScene(4)), sceneToJson(swallowScene(5)));
  const Scene tight = swallowScene(4, 0.03), loose = swallowScene(4, 0.12);
  EXPECT_EQ(tight.robots[0].shape, loose.robots[0].shape);
  EXPECT_EQ(tight.robots[0].goal.theta, loose.robots[0].goal.theta);
  EXPECT_EQ(tight.obstacles.back(), loose.obstacles.back());  // the part
  EXPECT_NE(sceneToJson(tight), sceneToJson(loose));
  const Scene tightest = swallowScene(4, 0.001);
  EXPECT_TRUE(checkPath(tightest, CollisionChecker(tightest), swallowWitness(tightest)).ok);
}

// The two-robot swallow is the swallow with its part a robot: the same U, bay and part, the part
// waiting at the bay's centre while the U turns about it, then leaving the other way.
TEST(ScenarioSwallow, TwoRobotsTheUTurnsAboutThePartWhichThenLeaves) {
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    SCOPED_TRACE(seed);
    const Scene one = swallowScene(seed), s = swallowScene(seed, -1, true);
    ASSERT_NO_THROW(parseScene(sceneToJson(s), "swallow-two"));
    ASSERT_EQ(s.robots.size(), 2u);
    EXPECT_EQ(s.obstacles.size() + 1, one.obstacles.size());  // the part moved to the robots
    EXPECT_EQ(s.robots[0].shape, one.robots[0].shape);
    const Robot& part = s.robots[1];
    const Ring placed = placedRing(part.shape, part.start), fixed = one.obstacles.back();
    ASSERT_EQ(placed.size(), fixed.size());
    for (size_t i = 0; i < placed.size(); ++i) {
      EXPECT_NEAR(placed[i].x, fixed[i].x, 1e-9);
      EXPECT_NEAR(placed[i].y, fixed[i].y, 1e-9);
    }
    // The U's witness with the part held still, then the part's straight way to its goal.
    std::vector<Config> w;
    for (const Config& u : swallowWitness(s))
      w.push_back({u[0], u[1], u[2], part.start.x, part.start.y, part.start.theta});
    Config last = w.back();
    last[3] = part.goal.x, last[4] = part.goal.y, last[5] = part.goal.theta;
    w.push_back(last);
    const PathCheckResult c = checkPath(s, CollisionChecker(s), w);
    EXPECT_TRUE(c.ok) << c.reason;
    // The part cannot leave first: the U stands in the corridor it leaves by.
    Config first = w.front();
    first[3] = part.goal.x, first[4] = part.goal.y;
    EXPECT_FALSE(checkPath(s, CollisionChecker(s), {w.front(), first}).ok);
  }
}

// Settings a family does not take are refused, not silently ignored.
TEST(ScenarioCatalog, SettingsAFamilyDoesNotTakeAreRefused) {
  const test::Outcome tight = test::runMms("scenario keyhole --tightness 0.5 -o /dev/null");
  EXPECT_EQ(tight.code, 2);
  EXPECT_NE(tight.err.find("--tightness: scenario keyhole does not take it"), std::string::npos)
      << tight.err;
  EXPECT_EQ(test::runMms("scenario pacman --robots 3 -o /dev/null").code, 2);
  EXPECT_EQ(test::runMms("scenario bend --slack 0.1 -o /dev/null").code, 2);
  EXPECT_EQ(test::runMms("scenario open-clutter --spacing 3 -o /dev/null").code, 2);
  EXPECT_EQ(test::runMms("scenario swallow-two --slack 0.05 -o /dev/null").code, 0);
  EXPECT_EQ(test::runMms("scenario disc-grid --robots 30 --spacing 3 -o /dev/null").code, 0);
}

// Carry-turn's play can be asked for (down to a tight grip): the scene's seed draws the rest.
TEST(ScenarioCarryTurn, PlayGivenChangesTheGripAlone) {
  const Scene tight = carryTurnScene(3, 0.03), seeded = carryTurnScene(3);
  EXPECT_EQ(tight.robots.at(1).shape, seeded.robots.at(1).shape);  // the part
  EXPECT_NE(tight.robots.at(0).shape, seeded.robots.at(0).shape);  // the gripper's pocket
  const CollisionChecker checker(tight);
  EXPECT_TRUE(checkPath(tight, checker, turnTogether(tight)).ok);
}
