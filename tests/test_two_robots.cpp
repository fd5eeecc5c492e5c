// Recursive MMS for two robots: the paper's scenarios solved with certified paths that move one
// robot at a time; bundled scenario files in sync with their generator.
#include <gtest/gtest.h>

#include "Support.h"
#include "io/SceneIO.h"
#include "planner/TwoRobotPlanner.h"
#include "scenarios/Generators.h"

using namespace mms;
using namespace mms::test;

namespace {

TwoRobotResult plan(const Scene& s, uint64_t seed) {
  TwoRobotSettings st;
  st.seed = seed;
  TwoRobotPlanner planner(s, st);
  return planner.solve(Termination(planSeconds(60)));
}

std::string label(const std::string& file) {
  std::string n = file.substr(file.find('/') + 1);
  n = n.substr(0, n.rfind('.'));
  for (char& c : n)
    if (c == '-' || c == '.') c = '_';
  return n;
}

}  // namespace

struct TwoRobotCase {
  const char* scene;
  int seeds;
};
void PrintTo(const TwoRobotCase& c, std::ostream* os) { *os << c.scene; }

class TwoRobotScene : public ::testing::TestWithParam<TwoRobotCase> {};

TEST_P(TwoRobotScene, SolvedWithCertifiedPathsMovingOneRobotAtATime) {
  const Scene s = loadScene(scenario(GetParam().scene));
  const CollisionChecker checker(s);
  for (int seed = 1; seed <= seedsToRun(GetParam().seeds); ++seed) {
    const TwoRobotResult r = plan(s, uint64_t(seed));
    ASSERT_EQ(r.status, PlanStatus::Found) << GetParam().scene << " seed " << seed;
    const PathCheckResult c = checkPath(s, checker, r.waypoints);
    EXPECT_TRUE(c.ok) << c.reason;
    for (size_t j = 1; j < r.waypoints.size(); ++j) {
      int moving = 0;
      for (size_t robot = 0; robot < 2; ++robot)
        for (size_t k = 3 * robot; k < 3 * robot + 3; ++k)
          if (r.waypoints[j][k] != r.waypoints[j - 1][k]) {
            ++moving;
            break;
          }
      EXPECT_LE(moving, 1) << "segment " << j - 1;
    }
    EXPECT_GT(r.stats.crossEdges, 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(Paper, TwoRobotScene,
                         ::testing::Values(TwoRobotCase{"two-robots/viking-helmet.json", 3},
                                           TwoRobotCase{"two-robots/pacman-0.json", 2},
                                           TwoRobotCase{"two-robots/pacman-0.5.json", 2},
                                           TwoRobotCase{"two-robots/pacman-0.9.json", 2},
                                           TwoRobotCase{"two-robots/random-polygons.json", 1},
                                           TwoRobotCase{"two-robots/niche-swap.json", 2},
                                           TwoRobotCase{"translating/cup.json", 2}),
                         [](const auto& info) { return label(info.param.scene); });

// Both robots' start and goal angles are among their slices, and the search runs once start
// and goal connect: on the base Pacman scene the first round's fixings are not all drawn.
TEST(TwoRobots, StartAndGoalAnglesSlicedAndEarlyStop) {
  const Scene s = loadScene(scenario("two-robots/pacman-0.json"));
  const TwoRobotSettings defaults;
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    const TwoRobotResult r = plan(s, seed);
    ASSERT_EQ(r.status, PlanStatus::Found);
    EXPECT_LT(r.stats.subspaces, 2 * (defaults.nFixings + 2)) << "seed " << seed;
    // Every subspace of a rigid robot has its n_theta (+1 for robot 1) angles, plus its start
    // angle (start and goal angles coincide in this scene).
    EXPECT_EQ(
        r.stats.manifolds.slices - r.stats.manifolds.localSlices,
        r.stats.fixings[1] * (defaults.nTheta + 1) + r.stats.fixings[0] * (defaults.nTheta + 2));
    EXPECT_LE(r.stats.pathSubspaces, r.stats.subspaces);
  }
}

// At tightness 0.98 the Pacman must turn round to within a fraction of a degree for the square
// to pass through its mouth. Slices at the middles of narrow line arcs open that passage within
// two rounds; the evenly spread angles alone do not (they found it in round 5 before).
TEST(TwoRobots, NarrowArcSlicesOpenTheTightestPacman) {
  const Scene s = pacmanScene(0.98);
  const CollisionChecker checker(s);
  for (uint64_t seed : {1, 4}) {
    for (const size_t narrow : {size_t(8), size_t(0)}) {
      TwoRobotSettings st;
      st.seed = seed;
      st.maxRounds = 2;
      st.narrowSlices = narrow;
      const TwoRobotResult r = TwoRobotPlanner(s, st).solve(Termination(planSeconds(60)));
      if (narrow == 0) {
        EXPECT_EQ(r.status, PlanStatus::NotFound) << "seed " << seed;
        continue;
      }
      ASSERT_EQ(r.status, PlanStatus::Found) << "seed " << seed;
      EXPECT_TRUE(checkPath(s, checker, r.waypoints).ok);
    }
  }
}

// Narrow-arc slices are built only when start and goal do not connect without them: among the
// random polygons the four start and goal subspaces connect them (seeds 1-3), so the first search
// runs before any is built; the tightest Pacman (above) needs them and builds them.
TEST(TwoRobots, NarrowArcSlicesWaitUntilStartAndGoalFailToConnect) {
  const Scene s = loadScene(scenario("two-robots/random-polygons.json"));
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    const TwoRobotResult r = plan(s, seed);
    ASSERT_EQ(r.status, PlanStatus::Found) << "seed " << seed;
    EXPECT_EQ(r.stats.subspaces, 4u) << "seed " << seed;
    EXPECT_EQ(r.stats.manifolds.localSlices, 0u) << "seed " << seed;
  }
  const TwoRobotResult tight = plan(pacmanScene(0.98), 1);
  ASSERT_EQ(tight.status, PlanStatus::Found);
  EXPECT_GT(tight.stats.manifolds.localSlices, 0u);
}

// In a tight niche (play 0.04-0.1 of the robots' size) most corners of the corridor hold a
// robot across the other's way; screened corner fixings (the first of 16 that cuts no passage of
// the other robot) find the niche with a fraction of the work the unscreened ones need, and
// every path is certified. Work counted in overlays (the slices built and the poses screened).
TEST(TwoRobots, CornerFixingsThatLeaveTheOtherRoomFindATightNicheSooner) {
  size_t slices[2] = {0, 0};  // 16 candidates, 1
  for (uint64_t seed : {1, 2, 3, 4, 6}) {
    const Scene s = nicheSwapScene(seed);
    const CollisionChecker checker(s);
    for (const size_t candidates : {size_t(16), size_t(1)}) {
      TwoRobotSettings st;
      st.seed = 1;
      st.cornerCandidates = candidates;
      const TwoRobotResult r = TwoRobotPlanner(s, st).solve(Termination(planSeconds(60)));
      ASSERT_EQ(r.status, PlanStatus::Found) << "seed " << seed << ", " << candidates;
      EXPECT_TRUE(checkPath(s, checker, r.waypoints).ok);
      slices[candidates == 1] += r.stats.manifolds.slices + r.stats.screenedPoses;
    }
  }
  EXPECT_LT(2 * slices[0], slices[1]) << slices[0] << " vs " << slices[1];
}

TEST(TwoRobots, SameSeedSamePath) {
  const Scene s = loadScene(scenario("two-robots/pacman-0.5.json"));
  const TwoRobotResult a = plan(s, 3), b = plan(s, 3);
  ASSERT_EQ(a.status, PlanStatus::Found);
  EXPECT_EQ(a.waypoints, b.waypoints);
}

TEST(TwoRobots, PlanCommandWritesACertifiedPath) {
  TempDir dir;
  const std::string scene = quote(scenario("two-robots/viking-helmet.json"));
  const Outcome r = runMms("plan " + scene + " -q -o " + quote(dir.path("p.json")) + " --svg " +
                           quote(dir.path("p.svg")));
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("subspaces"), std::string::npos);
  EXPECT_EQ(runMms("check " + scene + " " + quote(dir.path("p.json"))).code, 0);
  EXPECT_NE(readFile(dir.path("p.svg")).find("animateTransform"), std::string::npos);
}

TEST(Scenarios, BundledFilesMatchTheGenerator) {
  TempDir dir;
  struct Gen {
    const char* args;
    const char* file;
  };
  for (const Gen& g : {Gen{"pacman --tightness 0", "pacman-0.json"},
                       Gen{"pacman --tightness 0.5", "pacman-0.5.json"},
                       Gen{"pacman --tightness 0.8", "pacman-0.8.json"},
                       Gen{"pacman --tightness 0.9", "pacman-0.9.json"},
                       Gen{"viking-helmet", "viking-helmet.json"},
                       Gen{"random-polygons --seed 1", "random-polygons.json"}}) {
    const std::string out = dir.path(g.file);
    ASSERT_EQ(runMms(std::string("scenario ") + g.args + " -o " + quote(out)).code, 0) << g.args;
    EXPECT_EQ(readFile(out), readFile(scenario(std::string("two-robots/") + g.file))) << g.file;
  }
}

TEST(Scenarios, PacmanSquareGrowsWithTightnessAndBadValuesAreRejected) {
  TempDir dir;
  auto side = [&](const char* t) {
    const std::string f = dir.path(std::string("p") + t + ".json");
    EXPECT_EQ(runMms(std::string("scenario pacman --tightness ") + t + " -o " + quote(f)).code, 0);
    const Ring sq = loadScene(f).robots[1].shape;
    return sq[1].x - sq[0].x;
  };
  EXPECT_NEAR(side("0"), 0.8, 1e-12);
  EXPECT_NEAR(side("0.5"), 1.2, 1e-12);
  EXPECT_LT(side("0.99"), 1.6);
  const Outcome bad = runMms("scenario pacman --tightness 1.5 -o " + quote(dir.path("x.json")));
  EXPECT_EQ(bad.code, 2);
  EXPECT_FALSE(std::filesystem::exists(dir.path("x.json")));
}
