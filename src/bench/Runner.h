#pragma once
// mms bench as a library: runs every (scene, planner, seed) in its own `mms plan` process under
// a time and memory limit, appends each result to DIR/runs.jsonl as it finishes (a second call
// resumes), and writes the reports (DIR/report.md, results.csv, ompl/*.log, tightness.svg).
#include <atomic>
#include <string>
#include <vector>

namespace mms {

struct BenchSettings {
  std::vector<std::string> scenes;    // scene files, any format mms reads
  std::vector<std::string> planners;  // registry names
  std::vector<std::string> params;    // "PLANNER=ARGS": extra `mms plan` options for one planner
  std::string output;                 // the results folder
  std::string sweepPacman;            // "0,0.5,0.9": generated Pacman scenes added
  std::string executable;             // the mms binary whose `plan` runs each job
  uint64_t runs = 12;                 // seeds 1..runs
  double timeLimit = 60, memoryMb = 4096;
  size_t shardIndex = 1, shardCount = 1;  // run only the shardIndex-th of shardCount parts
  size_t jobs = 1;                        // cores to fill
  bool stopDecided = false;  // skip a group's seeds once its median is decided as unsolved
  std::string command;       // the command line, logged in DIR/commands.txt and report.md
};

struct BenchOutcome {
  size_t finished = 0, skipped = 0, notRun = 0;  // run now, recorded before, skipped as decided
  bool interrupted = false;                      // by `cancel` or a run's Ctrl-C
  std::string runsFile;
};

/// Runs the benchmark until every run is recorded or `cancel` is set; throws InputError on bad
/// settings (one line naming the option).
BenchOutcome runBenchmark(const BenchSettings& settings, const std::atomic<bool>* cancel);

/// Rewrites the reports from every runs*.jsonl in `dir`.
void writeBenchReports(const std::string& dir);

/// Merges the runs of several folders (shards) into `output`, with reports; returns the count.
size_t mergeBenchmarks(const std::vector<std::string>& dirs, const std::string& output);

/// "a,b,,c" -> {"a", "b", "c"}: the items of a separated list, empty ones dropped.
std::vector<std::string> split(const std::string& s, char sep);

}  // namespace mms
