// The planner seam: the registry, declared parameters, one result type, run summaries, and the
// round loop every MMS planner runs.
#include <gtest/gtest.h>

#include <set>

#include "Support.h"
#include "io/RunSummary.h"
#include "io/SceneIO.h"
#include "mms/Errors.h"
#include "mms/Io.h"
#include "mms/Planner.h"
#include "planner/Rounds.h"
#include "scenarios/Generators.h"

using namespace mms;
using namespace mms::test;

TEST(Registry, NamesAreUniqueAndSharedParametersAgree) {
  std::set<std::string> names;
  std::map<std::string, ParamSpec> byName;
  ASSERT_FALSE(planners().empty());
  EXPECT_EQ(planners().front().name, kDefaultPlanner);
  for (const PlannerInfo& p : planners()) {
    EXPECT_TRUE(names.insert(p.name).second) << p.name;
    EXPECT_EQ(findPlanner(p.name), &p);
    EXPECT_FALSE(p.summary.empty()) << p.name;
    EXPECT_TRUE(p.make) << p.name;
    for (const ParamSpec& s : p.params) {
      EXPECT_EQ(s.problem(s.value), "") << p.name << " --" << s.name << ": default out of range";
      EXPECT_FALSE(s.help.empty()) << s.name;
      // One option on the command line serves every planner that declares the name.
      const auto [it, fresh] = byName.emplace(s.name, s);
      if (!fresh) {
        EXPECT_EQ(int(it->second.type), int(s.type)) << s.name;
        EXPECT_EQ(it->second.min, s.min) << s.name;
        EXPECT_EQ(it->second.max, s.max) << s.name;
      }
    }
  }
  EXPECT_EQ(findPlanner("astar"), nullptr);
}

TEST(Registry, ParametersAreCheckedAgainstTheDeclarations) {
  const Scene s = loadScene(scenario("one-robot/bar-slot.json"));
  auto refusal = [&](const std::string& planner, const std::string& name, double v) {
    PlannerParams p;
    p.values[name] = v;
    try {
      makePlanner(planner, s, p, "bar-slot.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(refusal("prm", "n-theta", 4).find("--n-theta: not a parameter of planner prm"),
            std::string::npos);
  EXPECT_NE(refusal("mms", "n-theta", 0).find("--n-theta: 0 is not in [1,"), std::string::npos);
  EXPECT_NE(refusal("mms", "n-lines", 2.5).find("not an integer"), std::string::npos);
  EXPECT_NE(refusal("rrtconnect", "k", 5).find("its parameters: --resolution, --range"),
            std::string::npos);
  EXPECT_EQ(refusal("mms", "n-theta", 8), "");
  EXPECT_EQ(refusal("prm", "k", 5), "");
  EXPECT_THROW(makePlanner("astar", s), InputError);
}

TEST(Registry, MmsTakesAnyNumberOfRobotsAndRefusesNoneWithOneLine) {
  const Scene three = nicheThreeScene(1);
  EXPECT_NO_THROW(makePlanner("mms", three, {}, "three.json"));
  Scene none = three;
  none.robots.clear();
  try {
    makePlanner("mms", none, {}, "none.json");
    FAIL() << "no robots accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("none.json: robots: none", 0), 0u) << e.what();
  }
}

// Every planner behind the seam returns a path that certifies on its own, and says which
// parameters it used.
TEST(Registry, PlannersSolveThroughTheSeamAndTheirPathsCertify) {
  const Scene s = loadScene(scenario("one-robot/bar-slot.json"));
  for (const char* name : {"mms", "rrtconnect", "prm-bridge"}) {
    // OMPL's PRMs grow their roadmap in a thread for as long as the search takes, so a loaded
    // machine changes their path, and a path their discrete motion check passed may fail the
    // continuous one: reported Uncertified, as it must be. Up to three seeds for one Found.
    size_t found = 0;
    for (uint64_t seed = 3; seed <= 5 && found == 0; ++seed) {
      PlannerParams params;
      params.seed = seed;
      const auto planner = makePlanner(name, s, params);
      const PlanResult r = planner->solve(Termination(planSeconds(20)));
      EXPECT_GT(r.stats.seconds, 0) << name;
      EXPECT_GT(r.stats.graphNodes, 0u) << name;
      if (std::string(name) != "mms") {
        for (const ParamSpec& spec : findPlanner(name)->params)
          EXPECT_EQ(r.parameters.count(spec.key()), 1u) << spec.key();
      }
      if (r.status == PlanStatus::Uncertified && std::string(name) != "mms") {
        EXPECT_FALSE(r.certificate.ok) << name;
        continue;
      }
      ASSERT_EQ(r.status, PlanStatus::Found) << name;
      EXPECT_TRUE(r.certificate.ok) << name;
      EXPECT_TRUE(certify(s, r.waypoints).ok) << name;
      ++found;
    }
    EXPECT_EQ(found, 1u) << name;
  }
  const PlanResult m = makePlanner("mms", s)->solve(Termination(planSeconds(20)));
  EXPECT_EQ(m.parameters.at("n_theta"), 16);
  EXPECT_GT(m.stats.manifoldsBuilt, m.stats.manifoldsUsed);
  EXPECT_FALSE(m.stats.phases.empty());
}

TEST(Registry, OneRobotMmsAnswersANewQueryOnItsRoadmap) {
  const Scene s = loadScene(scenario("one-robot/bar-slot.json"));
  const auto planner = makePlanner("mms", s);
  ASSERT_TRUE(planner->solve(Termination(planSeconds(20))).found());
  Scene back = s;
  std::swap(back.robots[0].start, back.robots[0].goal);
  ASSERT_TRUE(planner->setQuery(startConfig(back), goalConfig(back)));
  const PlanResult r = planner->solve(Termination(planSeconds(20)));
  ASSERT_TRUE(r.found());
  EXPECT_TRUE(certify(back, r.waypoints).ok);
  EXPECT_FALSE(makePlanner("rrtconnect", s)->setQuery(startConfig(back), goalConfig(back)));
}

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

namespace {

struct LoopStats {
  size_t rounds = 0, rejectedPaths = 0;
  double searchSeconds = 0, motionSeconds = 0, certifySeconds = 0;
};

// A manifold of `cells` cells that meets nothing: the loop's graph needs nodes, not geometry.
class Cells final : public Manifold {
 public:
  explicit Cells(size_t cells) : cells_(cells) {}
  const ManifoldFamily& family() const override { return kFamily; }
  size_t cellCount() const override { return cells_; }
  long locate(const Config&) const override { return -1; }
  std::optional<std::vector<Config>> motion(size_t, const Config&, const Config&) const override {
    return std::nullopt;
  }

 private:
  static constexpr ManifoldFamily kFamily{"cells"};
  size_t cells_;
};

Roadmap roadmapOfCells(size_t cells) {
  Roadmap r;
  r.add(std::make_unique<Cells>(cells), 0, 0);
  return r;
}

}  // namespace

// A chain of cells 0 - 1 - ... - 5 that grows one edge per manifold: the search runs as soon
// as 0 and 5 connect; a refused candidate completes the round before the next search; a
// complete round doubles the target.
TEST(Rounds, SearchEarlyCompleteTheRoundAfterARefusalThenDouble) {
  Roadmap g = roadmapOfCells(6);
  size_t built = 0, target = 2, searches = 0, refusals = 0;
  std::vector<size_t> builtAtSearch;
  RoundHooks h;
  h.growing = [&] { return built < target; };
  h.complete = [&] { return built >= target; };
  h.grow = [&] {
    if (built < 5) g.addEdge(built, built + 1);
    ++built;
  };
  h.motion = [&](const std::vector<size_t>& nodes) {
    CertifiedMotion m;
    builtAtSearch.push_back(built);
    m.ok = ++searches > 1;  // the first candidate is refused
    m.waypoints = {Config(nodes.size(), 0.0)};
    return m;
  };
  h.refused = [&] { ++refusals; };
  h.next = [&] {
    target *= 2;
    return true;
  };
  LoopStats stats;
  const RoundsOutcome o = runRounds(h, g, 0, 5, Termination(10), stats);
  ASSERT_EQ(o.end, RoundsOutcome::End::Found);
  EXPECT_EQ(o.nodes, (std::vector<size_t>{0, 1, 2, 3, 4, 5}));
  // Rounds of 2, 4, 8: connected after 5 manifolds (round 3), refused, the round completed to
  // 8, then searched again.
  EXPECT_EQ(builtAtSearch, (std::vector<size_t>{5, 8}));
  EXPECT_EQ(stats.rounds, 3u);
  EXPECT_EQ(stats.rejectedPaths, 1u);
  EXPECT_EQ(refusals, 1u);
}

TEST(Rounds, GiveUpAndStop) {
  const Roadmap g = roadmapOfCells(2);
  size_t built = 0, target = 1, rounds = 0;
  RoundHooks h;
  h.growing = [&] { return built < target; };
  h.complete = [&] { return built >= target; };
  h.grow = [&] { ++built; };
  h.motion = [](const std::vector<size_t>&) { return CertifiedMotion{}; };
  h.next = [&] {
    target *= 2;
    return ++rounds < 3;  // a budget of rounds
  };
  LoopStats stats;
  EXPECT_EQ(runRounds(h, g, 0, 1, Termination(10), stats).end, RoundsOutcome::End::NotFound);
  EXPECT_EQ(stats.rounds, 3u);
  EXPECT_EQ(built, 4u);
  std::atomic<bool> cancel{true};
  h.next = [] { return true; };
  EXPECT_EQ(runRounds(h, g, 0, 1, Termination(10, &cancel), stats).end,
            RoundsOutcome::End::Cancelled);
}

TEST(Registry, PlanOptionsComeFromTheDeclarations) {
  TempDir dir;
  const std::string scene = quote(scenario("one-robot/bar-slot.json"));
  const Outcome wrong = runMms("plan " + scene + " --planner prm --n-theta 4");
  EXPECT_EQ(wrong.code, 2);
  EXPECT_EQ(wrong.err,
            "--n-theta: not a parameter of planner prm (its parameters: "
            "--resolution, --k, --simplify, --certified-motions, --free-samples, --optimize, "
            "--objective, --restarts)\n");
  const Outcome text = runMms("plan " + scene + " --n-theta many");
  EXPECT_EQ(text.code, 2);
  EXPECT_NE(text.err.find("--n-theta: 'many' is not a number"), std::string::npos) << text.err;
  // Every declared parameter is an option of mms plan, with its range in --help.
  const Outcome help = runMms("plan --help");
  for (const PlannerInfo& p : planners())
    for (const ParamSpec& s : p.params)
      EXPECT_NE(help.out.find("--" + s.name), std::string::npos) << s.name;
  const std::string stats = dir.path("s.json");
  ASSERT_EQ(
      runMms("plan " + scene + " --planner mms -q --n-lines 64 --stats-json " + quote(stats)).code,
      0);
  const RunSummary s = runSummaryFromJson(nlohmann::json::parse(readFile(stats)));
  EXPECT_EQ(s.status, PlanStatus::Found);
  EXPECT_EQ(s.parameters.at("n_lines"), 64);
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
    EXPECT_EQ(j["parameters"]["simplify"], 0);
  }
  EXPECT_EQ(j["statistics"]["graph_nodes"], r.stats.graphNodes);
  EXPECT_FALSE(j["statistics"].contains("seconds"));  // same seed, same file
  EXPECT_EQ(runMms("check " + quote(sceneFile) + " " + quote(file)).code, 0);
  EXPECT_THROW(readPathFile(dir.file("bad.json", "{}"), s), InputError);
  EXPECT_THROW(readSceneFile(dir.file("bad-scene.json", "[1]")), InputError);
}

// A run cut short leaves a two-robot planner's base slices and start and goal subspaces part
// built; solved again, the planner gives the path a fresh one gives (it used to report "not
// found" at once, in the portfolio's races too, which end MMS wherever it is).
TEST(Registry, TwoRobotMmsSolvedAgainAfterACutGivesAFreshRunsPath) {
  const Scene scene = openClutterScene(6);
  ASSERT_EQ(scene.robots.size(), 2u);
  const PlanResult fresh = makePlanner("mms", scene)->solve(Termination(planSeconds(30)));
  ASSERT_EQ(fresh.status, PlanStatus::Found);
  const std::vector<double> cuts =
      kSanitized ? std::vector<double>{0.05} : std::vector<double>{0.001, 0.004, 0.01, 0.03};
  for (const double cut : cuts) {
    const auto planner = makePlanner("mms", scene);
    planner->solve(Termination(cut));
    const PlanResult again = planner->solve(Termination(planSeconds(30)));
    ASSERT_EQ(again.status, PlanStatus::Found) << "cut at " << cut << " s";
    EXPECT_EQ(again.waypoints, fresh.waypoints) << "cut at " << cut << " s";
  }
}
