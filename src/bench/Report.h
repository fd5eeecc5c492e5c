#pragma once
// Benchmark results: one record per run (a line of runs.jsonl), and the reports made from them:
// a Markdown table in the style of the paper's Table 1, CSV, OMPL benchmark logs (readable by
// ompl_benchmark_statistics and Planner Arena), and time-versus-tightness plots like its Fig. 5.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace mms {

struct RunRecord {
  std::string scene;  // scene name (from the file)
  std::string sceneFile;
  double tightness = -1;  // for swept scenes (Pacman), else -1
  size_t robots = 0;      // in the scene (0 in records of older versions)
  std::string planner;
  std::string parameters;  // as given to mms plan, e.g. "--k 10"
  uint64_t seed = 0;
  std::string status;  // found, not_found, uncertified, crashed, killed, not_run (--stop-decided)
  double seconds = 0;  // planning time as the planner measured it
  double wallSeconds = 0;  // the whole process
  double startedAt = 0;    // Unix time the process started (0: unknown)
  size_t cores = 1;        // cores the scheduler reserved for it
  double peakMemoryMb = 0;
  double timeLimit = 0, memoryLimitMb = 0;
  double translation = 0, rotation = 0;
  // Two robots or more, as fleets are measured (PathCheckResult): makespan and sum of distances
  // with their lower bounds, and robots moving at once (0 in records of older versions).
  double makespan = 0, makespanBound = 0, distance = 0, distanceBound = 0, movingAtOnce = 0;
  size_t graphSize = 0;  // graph nodes (mms) or planner states (OMPL)
  // mms: manifolds (slices + lines) built, and those the solution lies on (an oracle's count)
  size_t manifoldsBuilt = 0, manifoldsUsed = 0;
  std::string detail;    // why a run failed, when known
  std::string solvedBy;  // the portfolio's member that found the path (auto), else ""
  std::string version;   // mms's version that ran it ("" in records of older versions)

  bool solved() const { return status == "found"; }
  /// A found run whose process took longer than the limit allows (the limit plus 2 % or
  /// 50 ms, whichever is more) is a failure: status "over_limit". Returns whether it was.
  bool failIfOverLimit();
  nlohmann::json toJson() const;
  static RunRecord fromJson(const nlohmann::json& j);
};

/// Statistics of one planner on one scene.
struct Summary {
  std::string scene, planner, parameters;
  double tightness = -1, timeLimit = 0;
  size_t runs = 0, solved = 0, uncertified = 0;
  size_t notRun = 0;   // skipped once the median was decided as unsolved; counted as unsolved
  size_t crashed = 0;  // a signal other than the time limit's kill, or an internal error (exit 3)
  double meanTrimmed = 0,
         stdevTrimmed = 0;  // over solved runs, without the fastest and slowest (paper's protocol)
  double median = 0;        // over all runs, an unsolved run counting as infinite
  bool medianSolved = false;
  double medianLength = 0, medianRotation = 0, medianGraph = 0, peakMemoryMb = 0;
  double medianBuilt = 0, medianUsed = 0;  // manifolds, over solved runs (mms)
  size_t robots = 0;
  // Over solved runs of two robots or more: makespan and sum of distances against their bounds,
  // and robots moving at once.
  double medianMakespanRatio = 0, medianDistanceRatio = 0, medianMovingAtOnce = 0;
};

std::vector<Summary> summarize(const std::vector<RunRecord>& runs);

std::string markdownReport(const std::vector<Summary>& summaries, const std::string& heading);
/// A line naming every crashed run (scene, planner, seed, what happened), "" when none did: a
/// crash is a bug, not a slow run, and must not read as a timeout.
std::string crashReport(const std::vector<RunRecord>& runs);
/// Per scene: MMS and the portfolio "auto" (each the best of its configurations) against the
/// best other planner by median,
/// with the speed-up (a lower bound where that planner's median is past the time limit) and
/// how many manifolds MMS built against those its path uses; "" when either side did not run.
std::string speedupReport(const std::vector<Summary>& summaries);
/// Per scene of two robots or more and planner: the makespan and sum of distances against their
/// lower bounds and the robots moving at once, medians of the solved runs; "" without such a
/// scene.
std::string fleetReport(const std::vector<Summary>& summaries);
/// Per scene, every planner ranked by median time (unsolved last), then by runs solved, with
/// its time against the best one's.
std::string rankingReport(const std::vector<Summary>& summaries);
/// SVG box plot of the solved runs' times (log scale) per scene and planner, the unsolved runs
/// counted under each box.
std::string timesPlot(const std::vector<RunRecord>& runs);
/// SVG bar chart of the share of runs solved per scene and planner.
std::string successPlot(const std::vector<Summary>& summaries);
std::string csvReport(const std::vector<RunRecord>& runs);
/// One OMPL benchmark log per scene: scene name -> log text.
std::vector<std::pair<std::string, std::string>> omplLogs(const std::vector<RunRecord>& runs,
                                                          const std::string& host);
/// SVG plot of mean planning time (log scale) against tightness with one-stdev error bars per
/// planner; unsolved runs are drawn as such at the top.
std::string tightnessPlot(const std::vector<Summary>& summaries, const std::string& title);

/// SVG plot of the median planning time (`memory`: the median peak memory) of solved runs against
/// the number of robots, per scene family (the scene's name without its seed and robot count)
/// and planner; "" unless some family has scenes of two robot counts or more.
std::string robotsPlot(const std::vector<RunRecord>& runs, bool memory);

/// "2026-11-27 07:30:00 UTC" for seconds since the epoch (a run's start); "unknown" for none.
std::string dateText(double epochSeconds);

std::vector<RunRecord> readRuns(const std::string& jsonlFile);

}  // namespace mms
