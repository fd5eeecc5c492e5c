// The default planner "auto": MMS and RRT-Connect race; the first certified path wins, the
// statistics name the winner, and the winner alone with the same seed gives the same path.
#include <gtest/gtest.h>
#include <pthread.h>
#include <sched.h>

#include <atomic>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "Support.h"
#include "io/SceneIO.h"
#include "mms/Planner.h"
#include "scenarios/Generators.h"

namespace mms {
namespace {

using test::quote;
using test::runMms;

nlohmann::json readJson(const std::string& path) {
  return nlohmann::json::parse(test::readFile(path));
}

// Each scene is won by whichever member is faster there; either way the winner named in the
// path file, run alone with the same seed, returns the same waypoints.
TEST(Portfolio, TheWinnerIsNamedAndRunAloneGivesTheSamePath) {
  test::TempDir dir;
  std::set<std::string> winners;
  for (const std::string scene : {"two-robots/random-polygons.json", "one-robot/bar-slot.json",
                                  "two-robots/pacman-0.9.json"}) {
    const std::string file = quote(test::scenario(scene)), raced = dir.path("raced.json"),
                      alone = dir.path("alone.json");
    const test::Outcome r =
        runMms("plan " + file + " -q --seed 3 --time-limit 60 -o " + quote(raced));
    ASSERT_EQ(r.code, 0) << scene << r.err;
    const nlohmann::json path = readJson(raced);
    EXPECT_EQ(path["planner"], "auto");
    const std::string winner = path["statistics"]["solved_by"];
    ASSERT_TRUE(winner == "mms" || winner == "rrtconnect") << winner;
    EXPECT_NE(r.out.find("auto (" + winner + ") found a path"), std::string::npos) << r.out;
    winners.insert(winner);
    // The portfolio optimises the winner's path as the winner alone does when asked; the
    // sampler certifies its motions as it goes, and takes shorter ones among several robots.
    const bool several = scene.rfind("two-robots/", 0) == 0;
    const std::string alsoAsked =
        winner == "rrtconnect"
            ? std::string(" --certified-motions --free-samples --lean-angles 0.5") +
                  (several ? " --range-share 0.1" : "")
            : "";
    EXPECT_EQ(path["parameters"].value("certified_motions", false), !alsoAsked.empty());
    EXPECT_EQ(path["parameters"].value("free_samples", false), !alsoAsked.empty());
    EXPECT_EQ(path["parameters"].value("lean_angles", 0.0), alsoAsked.empty() ? 0 : 0.5);
    EXPECT_EQ(path["parameters"].value("range_share", 0.0),
              !alsoAsked.empty() && several ? 0.1 : 0);
    ASSERT_EQ(runMms("plan " + file + " -q --seed 3 --time-limit 60 --optimize 1 --planner " +
                     winner + alsoAsked + " -o " + quote(alone))
                  .code,
              0);
    const nlohmann::json own = readJson(alone);
    EXPECT_EQ(path["waypoints"], own["waypoints"]) << scene << " won by " << winner;
    // One type per parameter, whichever planner wrote it: a switch is true or false.
    for (const auto& [key, value] : own["parameters"].items()) {
      ASSERT_TRUE(path["parameters"].contains(key)) << key;
      EXPECT_EQ(path["parameters"][key].type_name(), std::string(value.type_name())) << key;
    }
    if (winner == "rrtconnect") {
      EXPECT_TRUE(path["parameters"]["simplify"].is_boolean());
    }
    EXPECT_EQ(runMms("check " + file + " " + quote(raced)).code, 0);
  }
  // Random polygons fall to RRT-Connect in milliseconds, the Pacman at 0.9 to MMS: both
  // members win somewhere (a loaded machine could flip a close race, but not these).
  if (!test::kSanitized) {
    EXPECT_EQ(winners.size(), 2u);
  }
}

// Three robots: MMS alone and the portfolio both return paths that certify.
TEST(Portfolio, ThreeRobotsArePlannedByMmsAloneAndByTheRace) {
  test::TempDir dir;
  nlohmann::json scene = {{"format", "mms-scene/1"},
                          {"name", "three-squares"},
                          {"bounds", {-10, -10, 10, 10}},
                          {"obstacles", nlohmann::json::array()},
                          {"robots", nlohmann::json::array()}};
  const nlohmann::json square = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  for (int i = 0; i < 3; ++i)
    scene["robots"].push_back({{"name", std::string(1, char('a' + i))},
                               {"motion", "rigid"},
                               {"shape", square},
                               {"start", {-6.0, -5.0 + 5 * i, 0.0}},
                               {"goal", {6.0, 5.0 - 5 * i, 1.0}}});
  const std::string file = dir.file("three.json", scene.dump()), out = dir.path("p.json");
  const std::string alone = dir.path("mms.json");
  const test::Outcome m =
      runMms("plan " + quote(file) + " -q --planner mms --time-limit 30 -o " + quote(alone));
  ASSERT_EQ(m.code, 0) << m.out << m.err;
  EXPECT_EQ(runMms("check " + quote(file) + " " + quote(alone)).code, 0);
  const test::Outcome r = runMms("plan " + quote(file) + " -q --time-limit 30 -o " + quote(out));
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const std::string by = readJson(out)["statistics"]["solved_by"];
  EXPECT_TRUE(by == "rrtconnect" || by == "mms") << by;
  EXPECT_EQ(runMms("check " + quote(file) + " " + quote(out)).code, 0);
}

// While they race, the sampler's thread keeps its core and MMS's gets the others; the caller's
// thread has all its cores back when solve() returns, whoever won. The bar's slot takes
// RRT-Connect longer than the head start, so MMS does start.
TEST(Portfolio, TheCallersCoresAreItsOwnAgainAfterTheRace) {
  cpu_set_t before;
  ASSERT_EQ(pthread_getaffinity_np(pthread_self(), sizeof before, &before), 0);
  const Scene scene = loadScene(test::scenario("one-robot/bar-slot.json"));
  for (const uint64_t seed : {1, 2, 3}) {
    PlannerParams params;
    params.seed = seed;
    const PlanResult r = makePlanner("auto", scene, params)->solve(Termination(60));
    ASSERT_EQ(r.status, PlanStatus::Found);
    cpu_set_t after;
    ASSERT_EQ(pthread_getaffinity_np(pthread_self(), sizeof after, &after), 0);
    EXPECT_TRUE(CPU_EQUAL(&before, &after))
        << "seed " << seed << ": " << CPU_COUNT(&after) << " cores of " << CPU_COUNT(&before);
  }
}

// Where neither member finds a path both stop at the limit: the run ends "not found" on time.
TEST(Portfolio, BothMembersStopAtTheLimit) {
  const Scene scene = loadScene(test::scenario("one-robot/zigzag-slot.json"));
  const auto planner = makePlanner("auto", scene);
  const Stopwatch clock;
  const PlanResult r = planner->solve(Termination(1.0));
  EXPECT_EQ(r.status, PlanStatus::NotFound);
  EXPECT_TRUE(r.stats.solvedBy.empty());
  EXPECT_LT(clock.seconds(), test::kSanitized ? 20.0 : 3.0);
}

// Plain RRT-Connect's path on this generated clutter (seed 1) clips an obstacle between its
// checked poses, and the certifier refuses it. The race's sampler certifies each motion as it
// adds it: its path is accepted, and the race returns a certified path whoever wins.
TEST(Portfolio, TheSamplersPathsAreCertifiedAsTheyGrow) {
  const Scene scene = openClutterScene(100);
  EXPECT_EQ(makePlanner("rrtconnect", scene)->solve(Termination(10)).status,
            PlanStatus::Uncertified);
  PlannerParams certified;
  certified.values = {{"certified-motions", 1}};
  EXPECT_EQ(makePlanner("rrtconnect", scene, certified)->solve(Termination(10)).status,
            PlanStatus::Found);
  for (int race = 0; race < test::seedsToRun(3); ++race) {
    const PlanResult r = makePlanner("auto", scene)->solve(Termination(60));
    ASSERT_EQ(r.status, PlanStatus::Found) << "race " << race;
  }
}

// Discs nearly filling a round room: MMS begins seven rounds before its path, while the sampler
// needs some 45 000 iterations, far past the budget of 2000 but within it doubled for each of
// MMS's rounds after its first. The sampler's path is taken, and the same one each time.
TEST(Portfolio, TheSamplersAllowanceDoublesWithMmsRounds) {
  const Scene scene = roundRoomScene(3);
  PlannerParams seeded;
  seeded.seed = 3;
  std::vector<std::vector<Config>> paths;
  for (int run = 0; run < 2; ++run) {
    const PlanResult r = makePlanner("auto", scene, seeded)->solve(Termination(60));
    ASSERT_EQ(r.status, PlanStatus::Found) << "run " << run;
    EXPECT_EQ(r.stats.solvedBy, "rrtconnect");
    size_t iterations = 0;
    for (const auto& [name, value] : r.stats.counts)
      if (name == "iterations") iterations = size_t(value);
    EXPECT_GT(iterations, 2000u);
    paths.push_back(r.waypoints);
  }
  EXPECT_EQ(paths[0], paths[1]);
}

// A picture of the roadmap is of MMS's cells and lines. On a bend the sampler usually wins the
// race, and its path has neither: with the picture asked for, MMS runs alone, and says so.
TEST(Portfolio, ARoadmapPictureIsMmsAlone) {
  test::TempDir dir;
  const std::string scene = dir.path("bend.json"), svg = dir.path("bend.svg"),
                    path = dir.path("bend.path.json");
  ASSERT_EQ(runMms("scenario bend --seed 1 -o " + quote(scene)).code, 0);
  const test::Outcome r = runMms("plan " + quote(scene) + " -q --svg-roadmap --save-roadmap -o " +
                                 quote(path) + " --svg " + quote(svg));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("auto (mms) found a path"), std::string::npos) << r.out;
  EXPECT_EQ(readJson(path)["statistics"]["solved_by"], "mms");
  EXPECT_NE(test::readFile(svg).find("id=\"cells\""), std::string::npos);
}

// A budget of 0 runs MMS alone: on a bend, which the sampler takes at the default budget, the
// path is MMS's, the one `--planner mms` gives with the same seed.
TEST(Portfolio, ABudgetOfZeroIsMmsAlone) {
  test::TempDir dir;
  const std::string scene = dir.path("bend.json"), zero = dir.path("zero.json"),
                    byDefault = dir.path("default.json"), mms = dir.path("mms.json");
  ASSERT_EQ(runMms("scenario bend --seed 1 -o " + quote(scene)).code, 0);
  const std::string plan = "plan " + quote(scene) + " -q --seed 2 --time-limit 60 -o ";
  ASSERT_EQ(runMms(plan + quote(byDefault)).code, 0);
  EXPECT_EQ(readJson(byDefault)["statistics"]["solved_by"], "rrtconnect");
  const test::Outcome r = runMms(plan + quote(zero) + " --sampler-iterations 0");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("auto (mms) found a path"), std::string::npos) << r.out;
  EXPECT_EQ(readJson(zero)["statistics"]["solved_by"], "mms");
  ASSERT_EQ(runMms(plan + quote(mms) + " --planner mms").code, 0);
  EXPECT_EQ(readJson(zero)["waypoints"], readJson(mms)["waypoints"]);
}

// Where the sampler wins after MMS has started, solve() returns without waiting for MMS to
// stop. Nothing of the caller's may be used after that: the cancel flag is freed as soon as
// solve() returns (AddressSanitizer reports a later read), and progress reports after the
// return are counted (none). The same planner then answers again, waiting for the last MMS.
TEST(Portfolio, NothingOfTheCallersIsUsedOnceSolveReturns) {
  // The portfolio's RRT-Connect: 11 ms here, past the head start; MMS alone eight times as
  // long.
  const Scene scene = openClutterScene(20);
  const auto planner = makePlanner("auto", scene);
  std::atomic<bool> returned{false};
  std::atomic<int> late{0};
  const Planner::Progress progress = [&](const PlanStatistics&) {
    if (returned) ++late;
  };
  int samplerWins = 0;
  for (int race = 0; race < 4; ++race) {
    returned = false;
    auto cancel = std::make_unique<std::atomic<bool>>(false);
    const PlanResult r = planner->solve(Termination(60, cancel.get()), progress);
    returned = true;
    cancel.reset();
    ASSERT_EQ(r.status, PlanStatus::Found) << "race " << race;
    samplerWins += r.stats.solvedBy == "rrtconnect";
  }
  planner->finishBackgroundWork();
  EXPECT_EQ(late.load(), 0);
  if (!test::kSanitized) {
    EXPECT_GE(samplerWins, 1);
  }
}

}  // namespace
}  // namespace mms
