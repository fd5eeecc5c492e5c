// Proofs that no path exists (planner/NoPath.h): they fire where the goal is walled in, and
// never on a scene with a path.
#include <gtest/gtest.h>

#include "Support.h"
#include "check/PathChecker.h"
#include "io/SceneIO.h"
#include "mms/Planner.h"
#include "planner/OneRobotPlanner.h"
#include "planner/NoPath.h"
#include "planner/TwoRobotPlanner.h"
#include "scenarios/Generators.h"
#include "scenarios/RandomScene.h"

using namespace mms;
using namespace mms::test;

namespace {

OneRobotResult plan(const Scene& s) {
  OneRobotPlanner planner(s, 0, OneRobotSettings{});
  return planner.solve(s.robots[0].start, s.robots[0].goal, Termination(planSeconds(2)));
}

std::string proof(const Scene& s, size_t robot) {
  const CollisionChecker checker(s);
  return noPathAlone(s, checker, robot, s.robots[robot].start, s.robots[robot].goal);
}

}  // namespace

// Soundness: every robot of every scene that has a path (the bundled ones with a solution and
// seeds of every generated family, built around a witness path) gets no proof.
TEST(NoPath, TheProofsNeverFireWhereAPathExists) {
  std::vector<Scene> scenes;
  for (const char* f :
       {"one-robot/bar-slot.json", "one-robot/bug-trap.json", "one-robot/corridor-corner.json",
        "one-robot/maze.json", "two-robots/niche-swap.json", "two-robots/pacman-0.9.json",
        "two-robots/random-polygons.json", "two-robots/viking-helmet.json",
        "assembly/assembly-1.json", "assembly/assembly-2.json", "translating/cup.json"})
    scenes.push_back(loadScene(scenario(f)));
  for (uint64_t seed = 1; seed <= 4; ++seed)
    for (Scene s :
         {carryTurnScene(seed), nicheSwapScene(seed), nicheThreeScene(seed), discsSwapScene(seed),
          discsRoomScene(seed), openClutterScene(seed), bendScene(seed), doorsScene(seed)})
      scenes.push_back(std::move(s));
  scenes.push_back(pacmanScene(0.99));
  // A way in that a disc passes and the bar cannot turn in: no path, but none to prove here.
  scenes.push_back(loadScene(scenario("one-robot/zigzag-slot.json")));
  for (const Scene& s : scenes)
    for (size_t r = 0; r < s.robots.size(); ++r)
      EXPECT_EQ(proof(s, r), "") << s.name << ", robot " << s.robots[r].name;
}

// Soundness against an independent planner: random one-robot scenes (0-30 obstacles), each
// planned by RRT-Connect, which knows nothing of the proof; wherever it finds a certified path,
// the proof must not fire. It finds a path on about 30 of the 40 (here 31; the proof fired on 2
// of the 9 others).
TEST(NoPath, TheProofsNeverFireWhereASamplerFindsAPath) {
  size_t withPath = 0;
  for (uint64_t seed = 1; seed <= uint64_t(seedsToRun(40)); ++seed) {
    const Scene s = randomScene({seed, 1, -1});
    if (!makePlanner("rrtconnect", s)->solve(Termination(planSeconds(1))).found()) continue;
    ++withPath;
    EXPECT_EQ(proof(s, 0), "") << "seed " << seed;
  }
  EXPECT_GT(withPath, size_t(seedsToRun(40)) / 2);
}

// A translating square and a slit a hair narrower than the square but wider than the square as
// the checker tests it (shrunk by the tolerance): a straight path through the slit certifies.
// The planner's own slice, built for the square shrunk by half the tolerance, puts start and
// goal apart; the proof's probe (shrunk by twice the tolerance) does not, so nothing is claimed.
TEST(NoPath, ASlitOnlyTheCheckersShapePassesIsNoProof) {
  Scene s;
  s.name = "hair-slit";
  s.bounds = {0, 0, 10, 10};
  const double delta = s.tolerance(), w = 1 - 1.5 * delta;  // between 1 - 2 delta and 1 - delta
  s.obstacles = {rect(4.5, 0, 5.5, 5 - w / 2), rect(4.5, 5 + w / 2, 5.5, 10)};
  s.robots = {{"square", rect(-0.5, -0.5, 0.5, 0.5), {2, 5, 0}, {8, 5, 0}, Motion::Translate}};
  const CollisionChecker checker(s);
  EXPECT_TRUE(checkPath(s, checker, {{2, 5, 0}, {8, 5, 0}}).ok);
  EXPECT_EQ(proof(s, 0), "");
  const OneRobotResult r = plan(s);
  EXPECT_EQ(r.status, PlanStatus::NotFound);  // the planner's slice misses the slit
  EXPECT_TRUE(r.stats.noPath.empty()) << r.stats.noPath;
}

// A roadmap answers several queries: a proof about one does not stay with the next.
TEST(NoPath, AProofBelongsToItsQuery) {
  const Scene s = loadScene(scenario("one-robot/sealed-ring.json"));
  OneRobotPlanner planner(s, 0, OneRobotSettings{});
  const Pose start = s.robots[0].start;
  const OneRobotResult walled = planner.solve(start, s.robots[0].goal, Termination(60));
  ASSERT_EQ(walled.status, PlanStatus::NotFound);
  EXPECT_FALSE(walled.stats.noPath.empty());
  const OneRobotResult open = planner.solve(start, {-5, 5, 1}, Termination(60));
  ASSERT_EQ(open.status, PlanStatus::Found);
  EXPECT_TRUE(open.stats.noPath.empty()) << open.stats.noPath;
}

// The sealed ring walls the goal in: one robot's planner proves it at the end of its second
// round instead of searching until the limit, and the command line says why.
TEST(NoPath, AWalledInGoalIsProvedAfterTheSecondRound) {
  const Scene s = loadScene(scenario("one-robot/sealed-ring.json"));
  EXPECT_NE(proof(s, 0).find("robot 'bar' cannot reach its goal: a disc of radius"),
            std::string::npos);
  OneRobotPlanner planner(s, 0, OneRobotSettings{});
  const OneRobotResult r = planner.solve(s.robots[0].start, s.robots[0].goal, Termination(60));
  EXPECT_EQ(r.status, PlanStatus::NotFound);
  EXPECT_EQ(r.stats.rounds, 2u);
  EXPECT_NE(r.stats.noPath.find("cannot reach its goal"), std::string::npos);
  const Outcome cli =
      runMms("plan " + quote(scenario("one-robot/sealed-ring.json")) + " --time-limit 60");
  EXPECT_EQ(cli.code, 1) << cli.out << cli.err;
  EXPECT_NE(cli.out.find("no path exists: robot 'bar' cannot reach its goal"), std::string::npos)
      << cli.out;
}

// Two robots: the rigid one's goal lies across a wall, which its disc cannot cross either.
TEST(NoPath, TwoRobotsEndAfterTheSecondRoundWhenARigidRobotIsWalledOff) {
  Scene s = walledOffScene(2);
  s.robots[0].motion = Motion::Rigid;
  TwoRobotSettings st;
  const TwoRobotResult r = TwoRobotPlanner(s, st).solve(Termination(planSeconds(60)));
  EXPECT_EQ(r.status, PlanStatus::NotFound);
  EXPECT_EQ(r.stats.rounds, 2u);
  EXPECT_NE(r.stats.noPath.find("robot 'a' cannot reach its goal"), std::string::npos)
      << r.stats.noPath;
}
