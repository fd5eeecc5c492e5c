// The benchmark runner: planners x scenes x seeds, each run its own `mms plan` process under a
// time and a memory limit, results appended to runs.jsonl as they come (an interrupted benchmark
// keeps its data and resumes), reports made from all runs of a folder.
#include "bench/Runner.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include "bench/ChildExit.h"
#include "bench/Report.h"
#include "io/AnyScene.h"
#include "io/RunSummary.h"
#include "io/SceneIO.h"
#include "mms/Errors.h"
#include "mms/Planner.h"
#include "mms/mms.h"
#include "scenarios/Generators.h"
#include "util/AtomicFile.h"
#include "util/MemoryLimit.h"

namespace fs = std::filesystem;

namespace mms {

namespace {

struct Job {
  RunRecord record;
  std::vector<std::string> args;  // mms plan ...
  size_t cores = 1;
};

std::string group(const RunRecord& r) { return r.scene + "|" + r.planner + "|" + r.parameters; }
std::string key(const RunRecord& r) { return group(r) + "|" + std::to_string(r.seed); }

// Cores a run keeps busy: its --threads (0: all), so that a two-thread MMS run fills --jobs 2
// alone instead of sharing the cores with another run and reporting slower times.
size_t coresOf(const std::vector<std::string>& args, size_t jobs) {
  size_t cores = 1;
  for (size_t i = 0; i < args.size(); ++i) {
    std::string v;
    if (args[i] == "--threads" && i + 1 < args.size())
      v = args[i + 1];
    else if (args[i].rfind("--threads=", 0) == 0)
      v = args[i].substr(10);
    else
      continue;
    try {
      const long n = std::stol(v);
      cores = n <= 0 ? std::thread::hardware_concurrency() : size_t(n);
    } catch (const std::exception&) {
      throw InputError("--param: --threads '" + v + "' is not a number");
    }
  }
  return std::clamp<size_t>(cores, 1, jobs);
}

// Starts `mms plan` for a job; the child gets the memory limit and no terminal output.
pid_t start(const std::string& exe, const Job& job, double memoryMb) {
  const pid_t pid = fork();
  if (pid != 0) return pid;
  // The cap only: 0 is none (sanitizer builds reserve terabytes). The run's wall time is the
  // command's own, as a user would time it.
  capAddressSpace(memoryMb);
  const int null = open("/dev/null", O_WRONLY);
  dup2(null, 1);
  dup2(null, 2);
  std::vector<char*> argv{const_cast<char*>(exe.c_str())};
  for (const std::string& a : job.args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  execv(exe.c_str(), argv.data());
  _exit(127);
}

void fillFromStats(RunRecord& r, const std::string& statsFile) {
  std::ifstream in(statsFile);
  if (!in) return;
  try {
    const RunSummary s = runSummaryFromJson(nlohmann::json::parse(in));
    r.status = toString(s.status);
    r.seconds = s.stats.seconds;
    if (s.status == PlanStatus::Found) {
      r.translation = s.certificate.translation;
      r.rotation = s.certificate.rotation;
      r.makespan = s.certificate.makespan;
      r.makespanBound = s.certificate.makespanBound;
      r.distance = s.certificate.distance;
      r.distanceBound = s.certificate.distanceBound;
      r.movingAtOnce = s.certificate.movingAtOnce;
    }
    r.graphSize = s.stats.graphNodes;
    r.manifoldsBuilt = s.stats.manifoldsBuilt;
    r.manifoldsUsed = s.stats.manifoldsUsed;
    r.solvedBy = s.stats.solvedBy;
    r.detail = s.certificate.reason;
  } catch (const std::exception&) {
    r.detail = "unreadable statistics";
  }
}

// A planner option that the planner does not declare would fail every run of the group:
// refuse it before the first run, naming it.
void checkParam(const std::string& planner, const std::string& args) {
  const PlannerInfo* info = findPlanner(planner);
  if (!info) throw InputError("--param: unknown planner '" + planner + "'");
  for (const std::string& token : split(args, ' ')) {
    if (token.rfind("--", 0) != 0) continue;  // a value
    const std::string name = token.substr(2, token.find('=') - 2);
    const bool declared = std::any_of(info->params.begin(), info->params.end(),
                                      [&](const ParamSpec& s) { return s.name == name; });
    if (!declared)
      throw InputError("--param: " + token + " is not a parameter of planner " + planner);
  }
}

// "1 h 12 min", "3 min 20 s", "45 s".
std::string duration(double seconds) {
  const long s = long(std::ceil(seconds));
  if (s >= 3600) return std::to_string(s / 3600) + " h " + std::to_string(s % 3600 / 60) + " min";
  if (s >= 60) return std::to_string(s / 60) + " min " + std::to_string(s % 60) + " s";
  return std::to_string(s) + " s";
}

// What is about to run, and how long it may take at most: a benchmark of many planners at a
// long limit can take hours, which a user should know before starting it.
void announce(const std::vector<Job>& jobs, size_t toRun, const BenchSettings& a) {
  std::set<std::string> scenes, planners;
  for (const Job& j : jobs)
    scenes.insert(j.record.scene), planners.insert(j.record.planner + " " + j.record.parameters);
  const size_t atOnce = std::max<size_t>(1, a.jobs);
  const double worst = double(toRun) * a.timeLimit / double(atOnce);
  std::fprintf(stderr,
               "mms bench: %zu runs to make (%zu scene(s) x %zu planner(s) x %zu seed(s)%s): at "
               "most %s at %s s each, %zu at a time; most end sooner, at their path\n",
               toRun, scenes.size(), planners.size(), size_t(a.runs),
               a.shardCount > 1 ? ", this shard's part" : "", duration(worst).c_str(),
               formatNumber(a.timeLimit).c_str(), atOnce);
}

}  // namespace

void writeBenchReports(const std::string& dir) {
  std::vector<RunRecord> runs;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("runs", 0) == 0 && e.path().extension() == ".jsonl") {
      for (RunRecord& r : readRuns(e.path().string())) runs.push_back(std::move(r));
    }
  }
  // Shards may overlap after a merge; keep the first record of each run.
  std::set<std::string> seen;
  std::vector<RunRecord> unique;
  for (RunRecord& r : runs)
    if (seen.insert(key(r)).second) unique.push_back(std::move(r));
  const std::vector<Summary> summaries = summarize(unique);
  std::vector<Summary> swept, fixed;
  for (const Summary& s : summaries) (s.tightness >= 0 ? swept : fixed).push_back(s);
  std::string md = "# mms bench results\n\n" + std::to_string(unique.size()) +
                   " runs. Times are planning times as each planner measures them; mean and stdev "
                   "over solved runs "
                   "without the fastest and the slowest, median over all runs (an unsolved run "
                   "counts as infinite).\n\n";
  // What was measured, and how: enough to run it again.
  std::set<std::string> versions, limits;
  for (const RunRecord& r : unique) {
    versions.insert(r.version.empty() ? "unrecorded" : r.version);
    limits.insert(
        formatNumber(r.timeLimit) + " s, " +
        (r.memoryLimitMb > 0 ? formatNumber(r.memoryLimitMb) + " MB" : "no memory limit"));
  }
  auto joined = [](const std::set<std::string>& s) {
    std::string out;
    for (const std::string& x : s) out += (out.empty() ? "" : "; ") + x;
    return out;
  };
  md += "mms " + joined(versions) + "; limits per run: " + joined(limits) + ".\n";
  if (std::ifstream commands(dir + "/commands.txt"); commands) {
    md += "\nCommands:\n\n```\n";
    for (std::string line; std::getline(commands, line);) md += line + "\n";
    md += "```\n";
  }
  // MMS and the portfolio against the rest, where both kinds ran.
  if (const std::string ours = speedupReport(summaries); !ours.empty())
    md += "\n## MMS and the portfolio against the best other planner\n\n" + ours;
  if (const std::string fleets = fleetReport(summaries); !fleets.empty())
    md += "\n## Fleets: makespan and sum of distances against their bounds\n\n" + fleets;
  md += "\n## Every planner ranked\n\n" + rankingReport(summaries) +
        "\n![time per run](times.svg)\n\n![runs solved](success.svg)\n\n## All runs\n\n";
  md += markdownReport(fixed, "");
  if (const std::string crashes = crashReport(unique); !crashes.empty()) md += "\n" + crashes;
  writeFileAtomically(dir + "/times.svg", timesPlot(unique));
  writeFileAtomically(dir + "/success.svg", successPlot(summaries));
  const std::string byRobots = robotsPlot(unique, false);
  if (!byRobots.empty()) {
    md +=
        "\n## Against the number of robots\n\n![time against robots](robots.svg)\n\n"
        "![memory against robots](robots-memory.svg)\n";
    writeFileAtomically(dir + "/robots.svg", byRobots);
    writeFileAtomically(dir + "/robots-memory.svg", robotsPlot(unique, true));
  }
  if (!swept.empty()) {
    md += "\n## Tightness sweep\n\n" + markdownReport(swept, "") +
          "\n![time vs tightness](tightness.svg)\n";
    writeFileAtomically(dir + "/tightness.svg",
                        tightnessPlot(swept, "Pacman: planning time vs tightness"));
  }
  writeFileAtomically(dir + "/report.md", md);
  writeFileAtomically(dir + "/results.csv", csvReport(unique));
  fs::create_directories(dir + "/ompl");
  char host[256] = "unknown";
  gethostname(host, sizeof host - 1);
  for (const auto& [scene, log] : omplLogs(unique, host))
    writeFileAtomically(dir + "/ompl/" + scene + ".log", log);
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string item; std::getline(ss, item, sep);)
    if (!item.empty()) out.push_back(item);
  return out;
}

namespace {

struct SceneEntry {
  std::string file, name;
  double tightness;  // a swept Pacman's; -1 for a scene file
  size_t robots = 0;
};

// Runs are kept and resumed by scene name: two files of one name would share their runs (the
// second never planned), so the clash is refused with both files named.
void refuseNameClashes(const std::vector<SceneEntry>& scenes) {
  std::map<std::string, const SceneEntry*> byName;
  for (const SceneEntry& s : scenes) {
    const auto [it, fresh] = byName.emplace(s.name, &s);
    if (fresh) continue;
    if (fs::weakly_canonical(it->second->file) == fs::weakly_canonical(s.file))
      throw InputError(s.file + ": given twice to mms bench");
    throw InputError(s.file + ": scene '" + s.name + "' is also " + it->second->file +
                     "'s name (mms bench keeps runs by scene name): rename one");
  }
}

// Scenes: the files given, plus generated Pacman scenes for a tightness sweep.
std::vector<SceneEntry> benchScenes(const BenchSettings& a) {
  std::vector<SceneEntry> scenes;
  for (const std::string& f : a.scenes) {
    ImportNotes notes;
    const Scene scene = loadAnyScene(f, notes);
    scenes.push_back({f, scene.name, -1, scene.robots.size()});
  }
  if (!a.sweepPacman.empty()) {
    fs::create_directories(a.output + "/scenes");
    for (const std::string& t : split(a.sweepPacman, ',')) {
      double tight;
      try {
        tight = std::stod(t);
      } catch (const std::exception&) {
        throw InputError("--sweep-pacman: '" + t + "' is not a number");
      }
      if (!(tight >= 0 && tight < 1))
        throw InputError("--sweep-pacman: tightness " + t + " is not in [0, 1)");
      const Scene s = pacmanScene(tight);
      const std::string file = a.output + "/scenes/" + s.name + ".json";
      saveScene(s, file);
      scenes.push_back({file, s.name, tight, s.robots.size()});
    }
  }
  for (SceneEntry& s : scenes)
    if (s.name.empty()) s.name = fs::path(s.file).stem().string();
  refuseNameClashes(scenes);
  if (scenes.empty()) throw InputError("mms bench: no scenes (give scene files or --sweep-pacman)");
  return scenes;
}

// planner -> its extra mms plan arguments (--param), each checked against its declarations.
std::map<std::string, std::string> plannerArgs(const BenchSettings& a) {
  std::map<std::string, std::string> params;
  for (const std::string& p : a.params) {
    const size_t eq = p.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("--param: expected PLANNER=ARGS, found '" + p + "'");
    const std::string planner = p.substr(0, eq);
    checkParam(planner, p.substr(eq + 1));
    params[planner] = p.substr(eq + 1);
  }
  return params;
}

// This shard's runs, in order: scenes x planners x seeds.
std::vector<Job> planJobs(const BenchSettings& a) {
  const std::vector<SceneEntry> scenes = benchScenes(a);
  std::map<std::string, std::string> params = plannerArgs(a);
  std::vector<Job> jobs;
  size_t index = 0;
  for (const SceneEntry& s : scenes)
    for (const std::string& planner : a.planners)
      for (uint64_t seed = 1; seed <= a.runs; ++seed, ++index) {
        if (index % a.shardCount != a.shardIndex - 1) continue;
        Job j;
        j.record.scene = s.name;
        j.record.sceneFile = s.file;
        j.record.tightness = s.tightness;
        j.record.robots = s.robots;
        j.record.planner = planner;
        j.record.parameters = params.count(planner) ? params[planner] : "";
        j.record.seed = seed;
        j.record.timeLimit = a.timeLimit;
        j.record.memoryLimitMb = a.memoryMb;
        j.record.version = version();
        j.args = {"plan",
                  s.file,
                  "--planner",
                  planner,
                  "--seed",
                  std::to_string(seed),
                  "--time-limit",
                  std::to_string(a.timeLimit),
                  "-q"};
        for (const std::string& extra : split(j.record.parameters, ' ')) j.args.push_back(extra);
        // The portfolio races its sampler beside MMS's threads.
        j.cores = planner.rfind("mms", 0) == 0 ? coresOf(j.args, a.jobs)
                  : planner == "auto"          ? std::min(a.jobs, 1 + coresOf(j.args, a.jobs))
                                               : 1;
        jobs.push_back(std::move(j));
      }
  return jobs;
}

// What is recorded: the runs done, and the failures per scene, planner and parameters.
struct Ledger {
  std::set<std::string> done;
  std::map<std::string, size_t> failures;
  void count(const RunRecord& r) {
    done.insert(key(r));
    if (!r.solved()) ++failures[group(r)];
  }
};

// Takes in the runs recorded in `runsFile` and returns how many of `jobs` they are. A resumed
// benchmark must measure what the recorded runs measured: other limits or another mms are
// refused rather than mixed in one table. A folder kept from an earlier build resumes silently
// otherwise (the version need not change between builds), so what is reused is said at once.
size_t resume(const std::string& runsFile, const std::vector<Job>& jobs, Ledger& ledger) {
  if (!fs::exists(runsFile)) return 0;
  double newest = 0;  // when the newest recorded run of this benchmark started
  std::map<std::string, const Job*> planned;
  for (const Job& j : jobs) planned[key(j.record)] = &j;
  for (const RunRecord& r : readRuns(runsFile)) {
    ledger.count(r);
    const auto it = planned.find(key(r));
    if (it == planned.end()) continue;
    newest = std::max(newest, r.startedAt);
    const RunRecord& now = it->second->record;
    auto differs = [&](const std::string& what, const std::string& then, const std::string& asked) {
      throw InputError(runsFile + ": (resume): its runs were made with " + what + " " + then +
                       ", this run asks for " + asked +
                       "; use another output folder, or the same settings to resume");
    };
    if (r.timeLimit != now.timeLimit)
      differs("--time-limit", formatNumber(r.timeLimit), formatNumber(now.timeLimit));
    if (r.memoryLimitMb != now.memoryLimitMb)
      differs("--memory-limit", formatNumber(r.memoryLimitMb), formatNumber(now.memoryLimitMb));
    if (!r.version.empty() && r.version != now.version) differs("mms", r.version, now.version);
  }
  size_t reused = 0;
  for (const auto& entry : planned) reused += ledger.done.count(entry.first);
  if (reused > 0) {
    const std::string date = dateText(newest);
    const std::string when = date == "unknown" ? "" : ", the newest started " + date;
    std::fprintf(stderr,
                 "mms bench: resuming %s: %zu of %zu runs recorded already%s; give another "
                 "output folder to measure them again\n",
                 runsFile.c_str(), reused, jobs.size(), when.c_str());
  }
  return reused;
}

// Runs the jobs, each when its cores are free, and records each as it ends.
class Schedule {
 public:
  Schedule(const BenchSettings& a, const std::vector<Job>& jobs, Ledger& ledger,
           const std::string& runsFile, const std::atomic<bool>* cancel)
      : a_(a),
        jobs_(jobs),
        ledger_(ledger),
        out_(runsFile, std::ios::app),
        cancel_(cancel),
        tmp_(a.output + "/tmp"),
        grace_(std::max(5.0, 0.2 * a.timeLimit)) {
    if (!out_) throw InputError(runsFile + ": (output): cannot open for appending");
    fs::create_directories(tmp_);
  }

  BenchOutcome run(const std::string& runsFile) {
    while ((next_ < jobs_.size() || !running_.empty()) && !interrupted()) {
      startWhatFits();
      if (running_.empty()) break;
      if (!reapOne()) awaitAnExit();
    }
    BenchOutcome outcome{finished_, skipped_, notRun_, false, runsFile};
    if (interrupted()) {
      for (Running& r : running_) kill(r.pid, SIGKILL);
      for (Running& r : running_) waitpid(r.pid, nullptr, 0);
      outcome.interrupted = true;
      return outcome;
    }
    fs::remove_all(tmp_);
    return outcome;
  }

 private:
  struct Running {
    Job job;
    pid_t pid;
    std::chrono::steady_clock::time_point started;
    std::string stats;
    ChildExit exit;
  };

  // Until a run ends, or the next run's limit and grace pass (it is then killed), or soon
  // enough to see Ctrl-C.
  void awaitAnExit() const {
    double until = 0.05;
    std::vector<int> fds;
    const auto now = std::chrono::steady_clock::now();
    for (const Running& r : running_) {
      fds.push_back(r.exit.fd());
      const double elapsed = std::chrono::duration<double>(now - r.started).count();
      until = std::min(until, a_.timeLimit + grace_ - elapsed);
    }
    awaitChildExit(fds, until);
  }

  bool interrupted() const { return (cancel_ && cancel_->load()) || childInterrupted_; }

  // With --stop-decided, a group's median is decided as unsolved once this many runs failed
  // (the median of N runs, unsolved ones infinite, is infinite from ceil(N / 2) failures on).
  bool decided(const RunRecord& r) const {
    const auto it = ledger_.failures.find(group(r));
    return a_.stopDecided && it != ledger_.failures.end() && it->second >= (a_.runs + 1) / 2;
  }

  // Runs start in list order, each when its cores are free.
  void startWhatFits() {
    while (next_ < jobs_.size() && busy_ + jobs_[next_].cores <= a_.jobs) {
      Job job = jobs_[next_++];
      if (ledger_.done.count(key(job.record))) {
        ++skipped_;
        continue;
      }
      if (decided(job.record)) {
        // Recorded, so that reports count it and a resumed benchmark does not run it.
        RunRecord rec = job.record;
        rec.status = "not_run";
        rec.detail = "median decided: " + std::to_string(ledger_.failures[group(rec)]) + " of " +
                     std::to_string(a_.runs) + " runs failed";
        out_ << rec.toJson().dump() << "\n" << std::flush;
        ledger_.count(rec);
        ++notRun_;
        continue;
      }
      busy_ += job.cores;
      job.record.cores = job.cores;
      job.record.startedAt =
          std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch())
              .count();
      Running r{job, 0, std::chrono::steady_clock::now(),
                tmp_ + "/run-" + std::to_string(next_) + ".json", ChildExit()};
      fs::remove(r.stats);
      r.job.args.push_back("--stats-json");
      r.job.args.push_back(r.stats);
      r.pid = start(a_.executable, r.job, a_.memoryMb);
      r.exit = ChildExit(r.pid);
      running_.push_back(std::move(r));
    }
  }

  // Records one run that ended, if any did; a run past its limit and grace is killed.
  bool reapOne() {
    for (size_t i = 0; i < running_.size(); ++i) {
      Running& r = running_[i];
      int status = 0;
      struct rusage usage {};
      const pid_t got = wait4(r.pid, &status, WNOHANG, &usage);
      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - r.started).count();
      if (got == 0 && elapsed > a_.timeLimit + grace_) {
        kill(r.pid, SIGKILL);
        continue;  // reaped on a later pass
      }
      if (got != r.pid) continue;
      // A run ended by Ctrl-C (exit 130, or SIGINT before it installed its handler) is not a
      // result: it is left unrecorded, to run again on resume.
      if ((WIFEXITED(status) && WEXITSTATUS(status) == 130) ||
          (WIFSIGNALED(status) && WTERMSIG(status) == SIGINT))
        childInterrupted_ = true;
      else
        record(r, status, usage, elapsed);
      busy_ -= r.job.cores;
      running_.erase(running_.begin() + long(i));
      return true;
    }
    return false;
  }

  void record(const Running& r, int status, const struct rusage& usage, double elapsed) {
    RunRecord rec = r.job.record;
    rec.wallSeconds = elapsed;
    rec.peakMemoryMb = usage.ru_maxrss / 1024.0;
    rec.status = "crashed";
    if (WIFSIGNALED(status))
      rec.detail = WTERMSIG(status) == SIGKILL ? "killed after the time limit"
                                               : "signal " + std::to_string(WTERMSIG(status));
    if (WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) rec.status = "killed";
    if (WIFEXITED(status)) {
      fillFromStats(rec, r.stats);
      if (WEXITSTATUS(status) == 3)
        rec.status = "crashed", rec.detail = "internal error or out of memory";
      rec.failIfOverLimit();
    }
    out_ << rec.toJson().dump() << "\n" << std::flush;
    ledger_.count(rec);
    ++finished_;
    std::fprintf(stderr, "mms bench: [%zu/%zu] %s %s seed %llu: %s %.3f s\n",
                 finished_ + skipped_ + notRun_, jobs_.size(), rec.scene.c_str(),
                 rec.planner.c_str(), (unsigned long long)rec.seed, rec.status.c_str(),
                 rec.seconds);
    fs::remove(r.stats);
  }

  const BenchSettings& a_;
  const std::vector<Job>& jobs_;
  Ledger& ledger_;
  std::ofstream out_;
  const std::atomic<bool>* cancel_;
  const std::string tmp_;
  const double grace_;
  bool childInterrupted_ = false;  // a run ended by Ctrl-C: the terminal's, reaching it first
  std::vector<Running> running_;
  size_t next_ = 0, finished_ = 0, skipped_ = 0, notRun_ = 0, busy_ = 0;
};

}  // namespace

BenchOutcome runBenchmark(const BenchSettings& a, const std::atomic<bool>* cancel) {
  fs::create_directories(a.output);
  const std::vector<Job> jobs = planJobs(a);
  const std::string runsFile = a.output + "/" +
                               (a.shardCount > 1 ? "runs-" + std::to_string(a.shardIndex) + "-of-" +
                                                       std::to_string(a.shardCount) + ".jsonl"
                                                 : "runs.jsonl");
  Ledger ledger;
  const size_t reused = resume(runsFile, jobs, ledger);
  announce(jobs, jobs.size() - reused, a);
  if (!a.command.empty()) {
    std::ofstream log(a.output + "/commands.txt", std::ios::app);
    log << a.command << "\n";
  }
  const BenchOutcome outcome = Schedule(a, jobs, ledger, runsFile, cancel).run(runsFile);
  if (!outcome.interrupted) writeBenchReports(a.output);
  return outcome;
}

size_t mergeBenchmarks(const std::vector<std::string>& dirs, const std::string& output) {
  fs::create_directories(output);
  std::set<std::string> seen;
  std::string merged;
  size_t n = 0;
  for (const std::string& d : dirs) {
    if (!fs::is_directory(d)) throw InputError(d + ": (file): not a benchmark folder");
    for (const auto& e : fs::directory_iterator(d)) {
      const std::string name = e.path().filename().string();
      if (name.rfind("runs", 0) != 0 || e.path().extension() != ".jsonl") continue;
      for (const RunRecord& r : readRuns(e.path().string()))
        if (seen.insert(key(r)).second) merged += r.toJson().dump() + "\n", ++n;
    }
  }
  writeFileAtomically(output + "/runs.jsonl", merged);
  writeBenchReports(output);
  return n;
}

}  // namespace mms
