// mms bench: statistics, reports in the formats other tools read, runs recorded incrementally,
// shards and merging, limits.
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "Support.h"
#include "bench/Report.h"

using namespace mms;
using namespace mms::test;

namespace {

RunRecord run(const std::string& planner, uint64_t seed, const std::string& status,
              double seconds) {
  RunRecord r;
  r.scene = "s";
  r.planner = planner;
  r.seed = seed;
  r.status = status;
  r.seconds = seconds;
  r.timeLimit = 60;
  r.translation = 10;
  return r;
}

size_t lines(const std::string& text) { return size_t(std::count(text.begin(), text.end(), '\n')); }

}  // namespace

TEST(BenchReport, TrimmedMeanMedianAndFailures) {
  std::vector<RunRecord> runs;
  const double times[] = {1, 2, 3, 4, 100};
  for (uint64_t i = 0; i < 5; ++i) runs.push_back(run("a", i + 1, "found", times[i]));
  runs.push_back(run("b", 1, "found", 5));
  runs.push_back(run("b", 2, "not_found", 60));
  runs.push_back(run("b", 3, "uncertified", 7));
  const std::vector<Summary> s = summarize(runs);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_DOUBLE_EQ(s[0].meanTrimmed, 3.0);  // 2, 3, 4: without the fastest and the slowest
  EXPECT_DOUBLE_EQ(s[0].stdevTrimmed, 1.0);
  EXPECT_DOUBLE_EQ(s[0].median, 3.0);
  EXPECT_EQ(s[1].solved, 1u);
  EXPECT_EQ(s[1].uncertified, 1u);
  EXPECT_FALSE(s[1].medianSolved);  // two of three unsolved: the median is a failure
  const std::string md = markdownReport(s, "");
  EXPECT_NE(md.find("| s | a | defaults | 5/5 | 0 | 3 ± 1 | 3 |"), std::string::npos) << md;
  EXPECT_NE(md.find("1/3 (1 uncertified)"), std::string::npos);
  EXPECT_NE(md.find("> 60"), std::string::npos);
  EXPECT_EQ(lines(csvReport(runs)), runs.size() + 1);
}

// Fleets are measured as their community does: the makespan and the sum of distances against
// their lower bounds, and the robots moving at once, medians of the solved runs, for scenes of
// two robots or more; the CSV carries each run's.
TEST(BenchReport, FleetsReportMakespanAndDistanceAgainstTheirBounds) {
  std::vector<RunRecord> runs;
  const double makespan[] = {20, 30, 40}, distance[] = {110, 120, 130}, moving[] = {2, 3, 4};
  for (uint64_t i = 0; i < 3; ++i) {
    RunRecord r = run("mms", i + 1, "found", 1);
    r.scene = "grid";
    r.robots = 10;
    r.makespan = makespan[i], r.makespanBound = 10;
    r.distance = distance[i], r.distanceBound = 100;
    r.movingAtOnce = moving[i];
    runs.push_back(r);
  }
  RunRecord unsolved = runs.back();
  unsolved.status = "not_found", unsolved.seed = 4, unsolved.makespan = 1e9;
  runs.push_back(unsolved);
  RunRecord alone = run("mms", 1, "found", 1);
  alone.robots = 1;
  alone.makespan = alone.makespanBound = alone.distance = alone.distanceBound = 5;
  runs.push_back(alone);
  const std::string md = fleetReport(summarize(runs));
  EXPECT_NE(md.find("| grid | mms | 10 | 3 | 1.2 | 3 |"), std::string::npos) << md;
  EXPECT_EQ(md.find("| s |"), std::string::npos) << "one robot is no fleet: " << md;
  EXPECT_EQ(fleetReport(summarize({alone})), "");
  const std::string csv = csvReport(runs);
  EXPECT_NE(csv.find(",makespan,makespan_bound,distance,distance_bound,moving_at_once\n"),
            std::string::npos);
  EXPECT_NE(csv.find(",20,10,110,100,2\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",,,,,\n"), std::string::npos) << "no measures for a run without a path";
  EXPECT_EQ(RunRecord::fromJson(runs[0].toJson()).makespanBound, 10);
}

// A crashed run (a signal, exit 3) is not a timeout: the table counts it in a column of its
// own, the rankings say so, and a line under the table names each crashed run.
TEST(BenchReport, CrashesHaveAColumnAndALineNamingTheRuns) {
  std::vector<RunRecord> runs{run("a", 1, "crashed", 0.2), run("a", 2, "not_found", 3),
                              run("b", 1, "found", 1), run("b", 2, "found", 1)};
  runs[0].detail = "signal 6";
  const std::vector<Summary> s = summarize(runs);
  EXPECT_EQ(s[0].crashed, 1u);
  EXPECT_EQ(s[1].crashed, 0u);
  const std::string md = markdownReport(s, "");
  EXPECT_NE(md.find("| s | a | defaults | 0/2 | **1** |"), std::string::npos) << md;
  EXPECT_NE(md.find("| s | b | defaults | 2/2 | 0 |"), std::string::npos) << md;
  EXPECT_NE(rankingReport(s).find("> 60 s, 0/2, 1 crashed"), std::string::npos) << rankingReport(s);
  EXPECT_EQ(crashReport(runs), "**Crashed runs** (bugs, not timeouts): s a seed 1: signal 6.\n");
  EXPECT_EQ(crashReport({runs[1], runs[2]}), "");
}

TEST(BenchReport, OneRunHasNoDeviationAndUncertifiedRunsNoPathMeasures) {
  std::vector<RunRecord> runs{run("a", 1, "found", 0.00803), run("b", 1, "found", 1),
                              run("b", 2, "found", 3),       run("c", 1, "uncertified", 2),
                              run("d", 1, "found", 1),       run("d", 2, "found", 2),
                              run("d", 3, "found", 5)};
  runs[0].rotation = 1.5;
  const std::string md = markdownReport(summarize(runs), "");
  EXPECT_NE(md.find("| 0.00803 (one run) | 0.00803 | 10 | 1.5 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 2 ± 1.4 (two runs) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 2 (the middle of three) |"), std::string::npos) << md;
  EXPECT_EQ(md.find("± 0 "), std::string::npos) << md;
  const std::string csv = csvReport(runs);
  // No tightness (the scene has none), no translation or rotation for the uncertified run.
  EXPECT_NE(csv.find("s,,c,\"\",1,uncertified,2,0,0,,,0,,,,,,\n"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("-1"), std::string::npos) << csv;
}

TEST(BenchReport, AFoundRunPastItsLimitIsAFailure) {
  RunRecord r = run("a", 1, "found", 9);
  r.timeLimit = 10;
  r.wallSeconds = 10.19;  // within 2 %
  EXPECT_FALSE(r.failIfOverLimit());
  EXPECT_TRUE(r.solved());
  r.wallSeconds = 11.7;
  EXPECT_TRUE(r.failIfOverLimit());
  EXPECT_EQ(r.status, "over_limit");
  EXPECT_FALSE(r.solved());
  RunRecord quick = run("a", 1, "found", 0.01);
  quick.timeLimit = 0.05;
  quick.wallSeconds = 0.099;  // 50 ms past a short limit is allowed
  EXPECT_FALSE(quick.failIfOverLimit());
  quick.wallSeconds = 0.11;
  EXPECT_TRUE(quick.failIfOverLimit());
}

TEST(BenchReport, SpeedupAgainstTheBestOtherPlanner) {
  std::vector<RunRecord> runs;
  auto add = [&](const std::string& scene, const std::string& planner, double seconds,
                 const std::string& status) {
    RunRecord r = run(planner, runs.size() + 1, status, seconds);
    r.scene = scene;
    r.manifoldsBuilt = 100;
    r.manifoldsUsed = 10;
    runs.push_back(r);
  };
  for (int i = 0; i < 3; ++i) {
    add("open", "mms", 0.5, "found");
    add("open", "auto", 0.008, "found");  // ours, never the "other" even when fastest
    add("open", "rrtconnect", 0.01, "found");
    add("open", "prm", 2, "found");
    add("tight", "mms", 2, "found");
    add("tight", "prm", 60, "not_found");
    add("tight", "rrtconnect", 60, "not_found");
  }
  add("tight", "rrtconnect", 30, "found");  // one of four: the median stays past the limit
  const std::string md = speedupReport(summarize(runs));
  // Slower than RRT-Connect on the open scene: a ratio below one, against the best planner.
  EXPECT_NE(md.find("| open | mms | 0.5 s, 3/3 | rrtconnect: 0.01 s, 3/3 | 0.02× | 10 / 100 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| open | auto | 0.008 s, 3/3 | rrtconnect: 0.01 s, 3/3 | 1.25× |"),
            std::string::npos)
      << md;
  // Nothing else reached its median: a lower bound, and RRT-Connect (one run solved) is best.
  EXPECT_NE(md.find("| tight | mms | 2 s, 3/3 | rrtconnect: > 60 s, 1/4 | > 30× |"),
            std::string::npos)
      << md;
  EXPECT_EQ(md.find("| tight | auto"), std::string::npos) << md;  // auto did not run there
}

// Every planner ranked per scene, ours or not; without MMS there is no comparison table, not
// an empty one.
TEST(BenchReport, EveryPlannerIsRankedAndNoTableIsEmpty) {
  std::vector<RunRecord> runs;
  for (uint64_t i = 1; i <= 3; ++i) {
    runs.push_back(run("prm", i, "found", 0.4));
    runs.push_back(run("rrtconnect", i, "found", 0.1));
    runs.push_back(run("kpiece", i, "not_found", 60));
  }
  const std::vector<Summary> s = summarize(runs);
  EXPECT_EQ(speedupReport(s), "");
  const std::string md = rankingReport(s);
  EXPECT_NE(md.find("| s | 1 | rrtconnect | 0.1 s, 3/3 | 1× |"), std::string::npos) << md;
  EXPECT_NE(md.find("|  | 2 | prm | 0.4 s, 3/3 | 4× |"), std::string::npos) << md;
  EXPECT_NE(md.find("|  | 3 | kpiece | > 60 s, 0/3 | > 600× |"), std::string::npos) << md;
}

// The pictures Planner Arena shows: the times per run as boxes, the share solved as bars, for
// every scene and planner.
TEST(BenchReport, BoxPlotAndSuccessChartRender) {
  std::vector<RunRecord> runs;
  for (const std::string scene : {"open", "tight"})
    for (uint64_t i = 1; i <= 4; ++i) {
      RunRecord r = run("mms", i, "found", 0.01 * double(i));
      r.scene = scene;
      runs.push_back(r);
      r.planner = "prm";
      r.status = scene == "tight" && i > 1 ? "not_found" : "found";
      r.seconds = r.status == "found" ? 0.5 : 60;
      runs.push_back(r);
    }
  TempDir dir;
  const std::string times = dir.file("times.svg", timesPlot(runs));
  const std::string success = dir.file("success.svg", successPlot(summarize(runs)));
  for (const std::string& svg : {times, success})
    EXPECT_EQ(runCommand("rsvg-convert " + quote(svg) + " -o " + quote(svg + ".png")).code, 0);
  const std::string t = readFile(times);
  EXPECT_EQ(std::count(t.begin(), t.end(), '\n') > 10, true);
  // Four boxes (two scenes, two planners) drawn as rectangles with a white fill.
  size_t boxes = 0;
  for (size_t at = 0; (at = t.find("fill=\"white\" stroke=", at)) != std::string::npos; ++at)
    ++boxes;
  EXPECT_EQ(boxes, 4u) << t;
  EXPECT_NE(t.find("3/4 ✗"), std::string::npos) << "the unsolved runs counted";
  const std::string b = readFile(success);
  EXPECT_NE(b.find(">1/4<"), std::string::npos) << b;
  EXPECT_NE(b.find(">4/4<"), std::string::npos) << b;
}

TEST(BenchReport, OmplLogIsReadByOmplBenchmarkStatistics) {
  TempDir dir;
  std::vector<RunRecord> runs;
  for (uint64_t i = 1; i <= 3; ++i) runs.push_back(run("mms", i, "found", 0.1 * i));
  runs.push_back(run("prm", 1, "not_found", 60));
  const auto logs = omplLogs(runs, "host");
  ASSERT_EQ(logs.size(), 1u);
  const std::string log = dir.file("s.log", logs[0].second);
  const Outcome r =
      runCommand("ompl_benchmark_statistics " + quote(log) + " -d " + quote(dir.path("b.db")));
  ASSERT_EQ(r.code, 0)
      << "ompl_benchmark_statistics (Debian package ompl-demos, installed by scripts/setup.sh): "
      << r.out << r.err;
  EXPECT_NE(r.out.find("Parsing data for mms"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Parsing data for prm"), std::string::npos);
  // When the runs began, not "unknown".
  runs[0].startedAt = 1.8e9;
  EXPECT_NE(omplLogs(runs, "host")[0].second.find("\nStarting at 2027-01-15 08:00:00 UTC\n"),
            std::string::npos);
}

TEST(BenchReport, TightnessPlotRenders) {
  std::vector<RunRecord> runs;
  for (double t : {0.0, 0.5, 0.9})
    for (uint64_t i = 1; i <= 3; ++i) {
      RunRecord r = run("mms", i, "found", 1 + t + 0.1 * i);
      r.scene = "pacman-" + std::to_string(t);
      r.tightness = t;
      runs.push_back(r);
      r.planner = "prm";
      r.status = t > 0.6 ? "not_found" : "found";
      runs.push_back(r);
    }
  TempDir dir;
  const std::string svg = dir.file("t.svg", tightnessPlot(summarize(runs), "t"));
  EXPECT_EQ(runCommand("rsvg-convert " + quote(svg) + " -o " + quote(dir.path("t.png"))).code, 0);
  EXPECT_NE(readFile(svg).find("3/3"), std::string::npos);  // the unsolved runs are shown
}

TEST(BenchCommand, RecordsRunsResumesShardsAndMerges) {
  TempDir dir;
  const std::string scene = quote(scenario("translating/cup.json"));
  const std::string common = scene + " --planners mms,prm-bridge --runs 2 --time-limit 10";
  Outcome r = runMms("bench " + common + " -o " + quote(dir.path("all")));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(readFile(dir.path("all/runs.jsonl"))), 4u);
  for (const char* f : {"all/report.md", "all/results.csv", "all/ompl/cup.log"})
    EXPECT_TRUE(std::filesystem::exists(dir.path(f))) << f;
  EXPECT_NE(r.err.find("[4/4]"), std::string::npos);  // progress
  // Rerun: nothing left to do.
  r = runMms("bench " + common + " -o " + quote(dir.path("all")));
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("0 runs (4 already recorded)"), std::string::npos) << r.out;
  // ... and says so as it starts, with when they were measured.
  EXPECT_NE(r.err.find("resuming " + dir.path("all/runs.jsonl") +
                       ": 4 of 4 runs recorded already, the newest started 20"),
            std::string::npos)
      << r.err;
  // The report says what was measured and how to measure it again.
  const std::string report = readFile(dir.path("all/report.md"));
  EXPECT_NE(report.find("limits per run: 10 s, 4096 MB"), std::string::npos) << report;
  EXPECT_NE(report.find("mms 0."), std::string::npos) << report;
  EXPECT_NE(report.find(" bench " + scenario("translating/cup.json")), std::string::npos) << report;
  EXPECT_NE(readFile(dir.path("all/runs.jsonl")).find("\"version\":\"0."), std::string::npos);
  // Resuming with another limit would mix two benchmarks in one table: refused, nothing run.
  for (const std::string other : {"--time-limit 0.05", "--time-limit 10 --memory-limit 2048"}) {
    r = runMms("bench " + scene + " --planners mms,prm-bridge --runs 2 " + other + " -o " +
               quote(dir.path("all")));
    EXPECT_EQ(r.code, 2) << other;
    EXPECT_NE(r.err.find("runs.jsonl: (resume): its runs were made with --"), std::string::npos)
        << r.err;
    EXPECT_EQ(lines(r.err), 1u) << r.err;
  }
  EXPECT_EQ(lines(readFile(dir.path("all/runs.jsonl"))), 4u);
  // Two shards cover the run list disjointly; merged they hold every run once.
  for (const char* k : {"1", "2"})
    ASSERT_EQ(runMms("bench " + common + " --shard " + k + "/2 -o " +
                     quote(dir.path(std::string("s") + k)))
                  .code,
              0);
  const size_t a = lines(readFile(dir.path("s1/runs-1-of-2.jsonl"))),
               b = lines(readFile(dir.path("s2/runs-2-of-2.jsonl")));
  EXPECT_EQ(a + b, 4u);
  EXPECT_GT(a, 0u);
  r = runMms("bench-merge " + quote(dir.path("s1")) + " " + quote(dir.path("s2")) + " -o " +
             quote(dir.path("m")));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lines(readFile(dir.path("m/runs.jsonl"))), 4u);
}

TEST(BenchCommand, StopDecidedRecordsTheSeedsItSkips) {
  TempDir dir;
  // No path exists in the sealed ring: every run fails, so after 2 of 4 failures (seeds 1 and 2,
  // one run at a time) PRM's median is decided and seeds 3 and 4 are not run.
  const std::string cmd = "bench " + quote(scenario("one-robot/sealed-ring.json")) +
                          " --planners prm --runs 4 --time-limit 0.3 --stop-decided "
                          "--memory-limit 0 -o " +  // 0: sanitizer builds reserve terabytes
                          quote(dir.path("b"));
  Outcome r = runMms(cmd);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("2 not run"), std::string::npos) << r.out;
  std::map<uint64_t, std::string> status;
  std::istringstream in(readFile(dir.path("b/runs.jsonl")));
  for (std::string line; std::getline(in, line);) {
    const nlohmann::json j = nlohmann::json::parse(line);
    status[j["seed"].get<uint64_t>()] = j["status"];
  }
  const std::map<uint64_t, std::string> expected{
      {1, "not_found"}, {2, "not_found"}, {3, "not_run"}, {4, "not_run"}};
  EXPECT_EQ(status, expected);
  EXPECT_NE(readFile(dir.path("b/report.md")).find("0/4 (2 not run: median decided)"),
            std::string::npos);
  // The OMPL log holds only the runs that ran.
  EXPECT_NE(readFile(dir.path("b/ompl/sealed-ring.log")).find("\n2 runs\n"), std::string::npos);
  r = runMms(cmd);  // resumed: nothing left
  EXPECT_NE(r.out.find("0 runs (4 already recorded)"), std::string::npos) << r.out;
}

TEST(BenchCommand, ARunWithTwoThreadsHasTheCoresToItself) {
  TempDir dir;
  const Outcome r =
      runMms("bench " + quote(scenario("translating/cup.json")) + " " +
             quote(scenario("one-robot/bar-slot.json")) +
             " --planners mms,rrtconnect --param \"mms=--threads 2\" --runs 3 --time-limit 10 "
             "--jobs 2 -o " +
             quote(dir.path("b")));
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<RunRecord> runs = readRuns(dir.path("b/runs.jsonl"));
  ASSERT_EQ(runs.size(), 12u);
  size_t twoThreads = 0;
  for (const RunRecord& a : runs) {
    EXPECT_EQ(a.cores, a.planner == "mms" ? 2u : 1u);
    EXPECT_GT(a.startedAt, 0);
    if (a.cores < 2) continue;
    ++twoThreads;
    for (const RunRecord& b : runs) {
      if (&a == &b) continue;
      const bool overlap =
          a.startedAt < b.startedAt + b.wallSeconds && b.startedAt < a.startedAt + a.wallSeconds;
      EXPECT_FALSE(overlap) << a.scene << " mms seed " << a.seed << " overlaps " << b.planner
                            << " seed " << b.seed;
    }
  }
  EXPECT_EQ(twoThreads, 6u);
}

TEST(BenchCommand, MemoryLimitIsEnforcedAndRecorded) {
  TempDir dir;
  // Two robots among 3000 obstacles: the exact geometry alone is far past 100 MB within seconds.
  const std::string scene = dir.path("crowded.json");
  ASSERT_EQ(runMms("scenario random --seed 4 --robots 2 --obstacles 3000 -o " + quote(scene)).code,
            0);
  const Outcome r = runMms("bench " + quote(scene) +
                           " --planners mms --runs 1 --time-limit 20 --memory-limit 100 -o " +
                           quote(dir.path("b")));
  EXPECT_EQ(r.code, 0) << r.err;
  const nlohmann::json rec = nlohmann::json::parse(readFile(dir.path("b/runs.jsonl")));
  EXPECT_EQ(rec["status"], "crashed") << rec.dump();
  EXPECT_EQ(rec["memory_limit_mb"], 100.0);
  EXPECT_LT(rec["wall_seconds"].get<double>(), 20.0);  // stopped by memory, not by time
}

TEST(BenchCommand, BadOptionsExitTwo) {
  TempDir dir;
  const std::string scene = quote(scenario("translating/cup.json"));
  for (const std::string& opts :
       {std::string("--shard 3/2"), std::string("--planners mms,astar"), std::string("--param prm"),
        std::string("--sweep-pacman 1.5"), std::string("--param \"mms=--threads many\""),
        std::string("--param \"prm=--n-theta 4\""), std::string("--param \"astar=--k 4\"")}) {
    const Outcome r = runMms("bench " + scene + " " + opts + " -o " + quote(dir.path("x")));
    EXPECT_EQ(r.code, 2) << opts;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << opts << ": " << r.err;
  }
}

// By default a small set: the portfolio, MMS and the four OMPL planners the benchmarks compare
// against; what is about to run, and for how long at most, is said before the first run.
TEST(BenchCommand, DefaultPlannersAndTheTimeItMayTake) {
  TempDir dir;
  const Outcome r = runMms("bench " + quote(scenario("translating/cup.json")) +
                           " --runs 1 --time-limit 0.5 -o " + quote(dir.path("b")));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.rfind("mms bench: 6 runs to make (1 scene(s) x 6 planner(s) x 1 seed(s)): at "
                        "most 3 s at 0.5 s each, 1 at a time",
                        0),
            0u)
      << r.err;
  std::set<std::string> planners;
  std::istringstream runs(readFile(dir.path("b/runs.jsonl")));
  for (std::string line; std::getline(runs, line);)
    planners.insert(nlohmann::json::parse(line)["planner"].get<std::string>());
  EXPECT_EQ(planners,
            (std::set<std::string>{"auto", "mms", "prm", "prm-bridge", "rrtconnect", "kpiece"}));
  const std::string report = readFile(dir.path("b/report.md"));
  EXPECT_NE(report.find("![time per run](times.svg)"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir.path("b/times.svg")));
  EXPECT_TRUE(std::filesystem::exists(dir.path("b/success.svg")));
}

// Runs are kept by scene name: two files that name one scene would share their runs (the second
// was never planned, "1 already recorded"). The clash is refused naming both files, and so is a
// file given twice; nothing is written.
TEST(BenchRunner, TwoScenesOfOneNameAreRefusedNamingBothFiles) {
  const TempDir dir;
  std::filesystem::create_directories(dir.path("dupA"));
  std::filesystem::create_directories(dir.path("dupB"));
  const std::string scene = readFile(scenario("one-robot/bar-slot.json"));
  const std::string a = dir.file("dupA/s.json", scene), b = dir.file("dupB/s.json", scene);
  const Outcome clash = runMms("bench " + quote(a) + " " + quote(b) +
                               " --planners mms --runs 1 -o " + quote(dir.path("out")));
  EXPECT_EQ(clash.code, 2) << clash.err;
  EXPECT_EQ(lines(clash.err), 1u) << clash.err;
  EXPECT_NE(clash.err.find(a), std::string::npos) << clash.err;
  EXPECT_NE(clash.err.find(b), std::string::npos) << clash.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path("out/runs.jsonl")));
  const Outcome twice = runMms("bench " + quote(a) + " " + quote(a) +
                               " --planners mms --runs 1 -o " + quote(dir.path("out")));
  EXPECT_EQ(twice.code, 2);
  EXPECT_NE(twice.err.find("given twice"), std::string::npos) << twice.err;
}
