// Run summaries (mms-run/1) and the public API's path files: what a planner's result becomes on
// disk, and reads back as.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "Support.h"
#include "io/RunSummary.h"
#include "mms/Errors.h"
#include "mms/Io.h"
#include "mms/Planner.h"

using namespace mms;
using namespace mms::test;

TEST(RunSummary, WritesAndReadsBackEveryField) {
  PlanResult r;
  r.status = PlanStatus::Found;
  r.waypoints = {{0, 0, 0}, {1, 2, 3}};
  r.certificate.translation = 2.5;
  r.certificate.rotation = 3;
  r.certificate.minClearance = 0.125;
  r.parameters = {{"n_theta", 16}, {"expand_share", 0.5}};
  r.stats.seconds = 0.75;
  r.stats.rounds = 2;
  r.stats.graphNodes = 10;
  r.stats.graphEdges = 20;
  r.stats.manifoldsBuilt = 30;
  r.stats.manifoldsUsed = 4;
  r.stats.pathCells = 5;
  r.stats.rejectedPaths = 1;
  r.stats.counts = {{"slices", 7}};
  r.stats.phases = {{"search", 0.25}};
  const RunSummary back = runSummaryFromJson(
      nlohmann::json::parse(toJson(summarize("s.json", "mms", 9, 60, r)).dump()));
  EXPECT_EQ(back.scene, "s.json");
  EXPECT_EQ(back.planner, "mms");
  EXPECT_EQ(back.seed, 9u);
  EXPECT_EQ(back.timeLimit, 60);
  EXPECT_EQ(back.status, PlanStatus::Found);
  EXPECT_EQ(back.parameters, r.parameters);
  EXPECT_EQ(back.waypoints, 2u);
  EXPECT_EQ(back.certificate.translation, 2.5);
  EXPECT_EQ(back.certificate.minClearance, 0.125);
  EXPECT_EQ(back.stats.seconds, 0.75);
  EXPECT_EQ(back.stats.rounds, 2u);
  EXPECT_EQ(back.stats.graphEdges, 20u);
  EXPECT_EQ(back.stats.manifoldsBuilt, 30u);
  EXPECT_EQ(back.stats.manifoldsUsed, 4u);
  EXPECT_EQ(back.stats.rejectedPaths, 1u);
  EXPECT_EQ(back.stats.counts, r.stats.counts);
  EXPECT_EQ(back.stats.phases, r.stats.phases);
  EXPECT_THROW(runSummaryFromJson(nlohmann::json{{"format", "other"}}), std::runtime_error);
  EXPECT_THROW(runSummaryFromJson(nlohmann::json("mms-run/1")), std::runtime_error);
}

// The public API's files: a result written as a path file reads back to the same waypoints,
// with the planner's parameters and statistics, and `mms check` certifies it.
TEST(PublicApi, PathFilesRoundTripAndCertify) {
  TempDir dir;
  const std::string sceneFile = scenario("one-robot/bar-slot.json");
  std::vector<std::string> notes;
  const Scene s = readSceneFile(sceneFile, &notes);
  EXPECT_TRUE(notes.empty());
  const PlanResult r = makePlanner(kDefaultPlanner, s)->solve(Termination(planSeconds(20)));
  ASSERT_TRUE(r.found());
  const std::string file = dir.path("p.json");
  writePathFile(s, r, kDefaultPlanner, 1, file);
  EXPECT_EQ(readPathFile(file, s), r.waypoints);
  const nlohmann::json j = nlohmann::json::parse(readFile(file));
  EXPECT_EQ(j["planner"], kDefaultPlanner);
  // The portfolio's winner names itself, with its parameters.
  if (j["statistics"]["solved_by"] == "mms") {
    EXPECT_EQ(j["parameters"]["n_theta"], 16);
  } else {
    EXPECT_EQ(j["statistics"]["solved_by"], "rrtconnect");
    EXPECT_EQ(j["parameters"]["simplify"], false);
  }
  EXPECT_EQ(j["statistics"]["graph_nodes"], r.stats.graphNodes);
  EXPECT_FALSE(j["statistics"].contains("seconds"));  // same seed, same file
  EXPECT_EQ(runMms("check " + quote(sceneFile) + " " + quote(file)).code, 0);
  EXPECT_THROW(readPathFile(dir.file("bad.json", "{}"), s), InputError);
  EXPECT_THROW(readSceneFile(dir.file("bad-scene.json", "[1]")), InputError);
}
