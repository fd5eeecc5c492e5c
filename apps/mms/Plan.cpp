#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <thread>

#include "Commands.h"
#include "io/PathIO.h"
#include "io/QueriesIO.h"
#include "io/RecordIO.h"
#include "io/RunSummary.h"
#include "io/SceneIO.h"
#include "mms/Errors.h"
#include "mms/Planner.h"
#include "render/SvgRenderer.h"
#include "util/AtomicFile.h"
#include "util/Interrupt.h"

namespace mms::cli {

namespace {

// "out.json" -> "out.3.json" for query 3.
std::string numbered(const std::string& path, size_t i) {
  if (path.empty()) return path;
  const std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + "." + std::to_string(i) + p.extension().string()))
      .string();
}

}  // namespace

namespace {

std::string spaced(std::string name) {
  for (char& c : name)
    if (c == '_') c = ' ';
  return name;
}

// "16 slices, 40 slice cells, ..." from the planner's counts, in its order.
std::string countsText(const PlanStatistics& s) {
  std::string out;
  for (const auto& [name, n] : s.counts)
    out += (out.empty() ? "" : ", ") + std::to_string(n) + " " + spaced(name);
  return out;
}

// "; 3 rounds", "; 1 round", or nothing for a planner without rounds (OMPL's).
std::string roundsText(size_t rounds) {
  if (rounds == 0) return "";
  return "; " + std::to_string(rounds) + (rounds == 1 ? " round" : " rounds");
}

void printStatistics(const PlanStatistics& s, bool found) {
  std::printf("  built: %s; graph %zu nodes, %zu edges%s\n", countsText(s).c_str(), s.graphNodes,
              s.graphEdges, roundsText(s.rounds).c_str());
  std::string phases, after;
  for (const auto& [name, t] : s.phases) {
    std::string& to = afterFirstPath(name) ? after : phases;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s%s %.3f", to.empty() ? "" : " + ", spaced(name).c_str(), t);
    to += buf;
  }
  std::printf("  time: %.3f s %s= %s%s%s\n", s.seconds, found ? "to the path " : "", phases.c_str(),
              after.empty() ? "" : "; then ", after.c_str());
  if (s.rejectedPaths)
    std::printf("  %zu candidate motions failed certification\n", s.rejectedPaths);
  if (s.manifoldsUsed)
    std::printf("  the path uses %zu of the %zu manifolds built\n", s.manifoldsUsed,
                s.manifoldsBuilt);
}

// After "no path found within the limit": what bounded the search (the phase the time went
// to, and MMS's round) and what to try next.
void printUnsolvedHint(const PlanArgs& a, const Scene& scene, const PlanStatistics& s) {
  const std::pair<std::string, double>* most = nullptr;
  for (const auto& phase : s.phases)
    if (!afterFirstPath(phase.first) && (!most || phase.second > most->second)) most = &phase;
  if (most && most->second > 0)
    std::printf("  bounded by the time limit: most of it in %s (%.3g of %.3g s)%s\n",
                spaced(most->first).c_str(), most->second, s.seconds,
                s.rounds ? (", in round " + std::to_string(s.rounds)).c_str() : "");
  const bool ours = a.planner == "auto" || a.planner == "mms";
  if (ours)
    std::printf(
        "  to try: --time-limit %g (each round of MMS builds twice the manifolds of the "
        "last, so about twice the time)%s\n",
        2 * a.timeLimit,
        scene.robots.size() >= 2 ? "; --planner kpiece samples all robots at once" : "");
  else
    std::printf(
        "  to try: the default planner (MMS beside a sampler: narrow passages), or "
        "--time-limit %g\n",
        2 * a.timeLimit);
}

// "auto (mms)": the planner asked for, and the portfolio's member that found the path.
std::string plannerName(const PlanArgs& a, const PlanResult& r) {
  return r.stats.solvedBy.empty() ? a.planner : a.planner + " (" + r.stats.solvedBy + ")";
}

// Reports one query's outcome and writes its files; returns the exit code.
int report(const PlanArgs& a, const Scene& scene, const std::string& label, const PlanResult& r,
           const std::string& output, const std::string& svg) {
  if (r.status == PlanStatus::Uncertified) {
    std::printf(
        "%s: %s returned a path in %.3f s that fails the continuous check: segment %zu at s = "
        "%.4g: %s (counted as a failure)\n",
        label.c_str(), a.planner.c_str(), r.stats.seconds, r.certificate.segment,
        r.certificate.parameter, r.certificate.reason.c_str());
    return 1;
  }
  if (!r.found()) {
    // A planner that ends well before the limit has searched all it could (a translating
    // robot's one exact slice): saying "time limit" would send the user to raise it.
    const bool early =
        r.status != PlanStatus::Cancelled && processClock().seconds() < 0.9 * a.timeLimit;
    if (!r.stats.noPath.empty())
      std::printf("%s: no path exists: %s (%s, after %.3g s)\n", label.c_str(),
                  r.stats.noPath.c_str(), a.planner.c_str(), r.stats.seconds);
    else if (early)
      std::printf(
          "%s: no path found (%s ended its search after %.3g s, before the %.3g s limit%s)\n",
          label.c_str(), a.planner.c_str(), r.stats.seconds, a.timeLimit,
          scene.hasDiscs() ? "; it searched round polygons about the discs: more --disc-sides "
                             "narrow them"
                           : "");
    else
      std::printf("%s: no path found within %.3g s (%s, %s)\n", label.c_str(), a.timeLimit,
                  a.planner.c_str(),
                  r.status == PlanStatus::Cancelled ? "interrupted" : "time limit");
    printStatistics(r.stats, false);
    if (r.stats.noPath.empty() && !early && r.status != PlanStatus::Cancelled)
      printUnsolvedHint(a, scene, r.stats);
    return 1;
  }
  Path path;
  path.waypoints = r.waypoints;
  path.extra = pathExtra(r, a.planner, a.seed);
  if (a.saveRoadmap) {
    // The viewer's overlay: the free-space cells the path uses, and every line's point.
    nlohmann::json cells = nlohmann::json::array(), points = nlohmann::json::array();
    for (const std::vector<Ring>& cell : r.roadmap.cells) {
      nlohmann::json rings = nlohmann::json::array();
      for (const Ring& ring : cell) rings.push_back(ringToJson(ring));
      cells.push_back(rings);
    }
    for (const Vec2& p : r.roadmap.points) points.push_back({p.x, p.y});
    path.extra["roadmap"] = {{"cells", cells}, {"points", points}};
  }
  if (!output.empty()) savePath(path, scene, output);
  if (!svg.empty()) {
    SvgOptions o;
    if (a.svgRoadmap) {
      o.markers = r.roadmap.points;
      for (const std::vector<Ring>& cell : r.roadmap.cells) o.regions.push_back(cell);
    }
    writeFileAtomically(svg, renderSvg(scene, &path, o));
  }
  const PathCheckResult& c = r.certificate;
  std::printf(
      "%s: %s found a path in %.3f s, certified: %zu waypoints, translation %.4g, rotation %.4g "
      "rad, min clearance %.3g\n",
      label.c_str(), plannerName(a, r).c_str(), r.stats.seconds, path.waypoints.size(),
      c.translation, c.rotation, c.minClearance);
  std::printf("%s", fleetLine(scene, c).c_str());
  printStatistics(r.stats, true);
  if (output.empty()) std::printf("  no path file written: -o FILE writes one\n");
  return 0;
}

}  // namespace

namespace {

// Progress on stderr while one query runs: the planner's own reports once a second has passed
// and, since a planner reports between manifolds and one manifold among thousands of obstacles
// takes longer than a user waits in silence, a line every 5 s between them that says it works.
class ProgressLines {
 public:
  ProgressLines(bool quiet, double timeLimit) : quiet_(quiet) {
    if (quiet) return;
    heartbeat_ = std::thread([this, timeLimit] {
      std::unique_lock lock(m_);
      while (!wake_.wait_for(lock, std::chrono::seconds(1), [&] { return finished_; }))
        if (clock_.seconds() - lastReport_ >= 5)
          std::fprintf(stderr,
                       "mms plan: %.1f s, still working (building manifolds; %.0f s left)\n",
                       clock_.seconds(), std::max(0.0, timeLimit - processClock().seconds())),
              lastReport_ = clock_.seconds();
    });
  }
  ~ProgressLines() {
    if (!heartbeat_.joinable()) return;
    {
      std::lock_guard lock(m_);
      finished_ = true;
    }
    wake_.notify_all();
    heartbeat_.join();
  }
  Planner::Progress callback() {
    return [this](const PlanStatistics& s) {
      if (quiet_ || clock_.seconds() < 1.0) return;
      const std::string round = s.rounds ? ", round " + std::to_string(s.rounds) : "";
      std::fprintf(stderr, "mms plan: %.1f s%s: %s, graph %zu nodes / %zu edges\n",
                   clock_.seconds(), round.c_str(), countsText(s).c_str(), s.graphNodes,
                   s.graphEdges);
      lastReport_ = clock_.seconds();
    };
  }

 private:
  bool quiet_;
  Stopwatch clock_;
  std::atomic<double> lastReport_{0};
  std::mutex m_;
  std::condition_variable wake_;
  bool finished_ = false;
  std::thread heartbeat_;
};

// The record of a run (--record), found or not: why a planner missed a way is what it shows.
void writeRecord(const PlanArgs& a, const PlanResult& r, const std::string& file) {
  PlanRecord none;  // a planner that records nothing still gets its statistics written
  none.planner = a.planner;
  saveRecord(r.record ? *r.record : none, r.stats, file);
}

// The queries to answer: the scene's own, or those of --queries (one-robot MMS only, as is the
// roadmap's picture in the path file).
std::vector<Query> queriesOf(const PlanArgs& a, const Scene& scene, bool multiQuery) {
  const bool oneRoadmap = multiQuery && scene.robots.size() == 1;
  const std::string why =
      a.scene + " has " + std::to_string(scene.robots.size()) + " robots, planner " + a.planner;
  if (!a.queries.empty() && !oneRoadmap)
    throw InputError(a.queries +
                     ": (file): --queries is for one-robot scenes with the mms planner (" + why +
                     ")");
  if (a.saveRoadmap && !oneRoadmap)
    throw InputError(a.scene + ": (--save-roadmap): one-robot scenes with the mms planner only (" +
                     why + ")");
  std::vector<Query> queries{{Pose{}, Pose{}}};
  if (!a.queries.empty()) queries = loadQueries(a.queries, scene);
  if (queries.size() > 1)
    for (const auto& [path, option] : {std::pair{a.output, "-o"}, {a.svg, "--svg"}})
      if (path == kStandardOutput)
        throw InputError(a.queries + ": (" + option +
                         "): several queries write a file each, not one to standard output");
  return queries;
}

}  // namespace

int plan(const PlanArgs& a) {
  for (const auto& [path, option] : {std::pair{a.output, "-o"},
                                     {a.svg, "--svg"},
                                     {a.statsJson, "--stats-json"},
                                     {a.record, "--record"}})
    checkWritable(path, option);
  const Scene scene = readScene(a.scene, a.quiet);
  // An unknown planner is the registry's to name (makePlanner, below).
  const PlannerInfo* info = findPlanner(a.planner);
  const std::vector<Query> queries = queriesOf(a, scene, info && info->multiQuery);
  PlannerParams params = a.params;
  params.seed = a.seed;
  params.roadmapPicture = a.saveRoadmap || a.svgRoadmap;
  params.record = !a.record.empty();
#if !defined(__SANITIZE_ADDRESS__)
  params.exitsAfterRun = true;  // under ASan, free everything so leaks stay visible
#endif
  std::unique_ptr<Planner> planner = makePlanner(a.planner, scene, params, a.scene);
  int exitCode = 0;
  nlohmann::json summaries = nlohmann::json::array();
  for (size_t qi = 0; qi < queries.size(); ++qi) {
    Scene queryScene = scene;
    std::string label = a.scene;
    if (!a.queries.empty()) {
      queryScene.robots[0].start = queries[qi].start;
      queryScene.robots[0].goal = queries[qi].goal;
      planner->setQuery(startConfig(queryScene), goalConfig(queryScene));
      label = a.queries + " query " + std::to_string(qi);
    }
    // The limit holds for the whole command: what reading the scene and making the planner
    // took (a thousand obstacles: tens of ms) comes off the first query's time.
    const double limit =
        qi == 0 ? std::max(0.0, a.timeLimit - processClock().seconds()) : a.timeLimit;
    PlanResult r;
    {
      ProgressLines lines(a.quiet, a.timeLimit);
      r = planner->solve(Termination(limit, sigintFlag()), lines.callback());
    }
    if (interruptRequested()) throw Interrupted();
    const bool many = queries.size() > 1;
    if (params.record) writeRecord(a, r, many ? numbered(a.record, qi) : a.record);
    summaries.push_back(toJson(summarize(a.scene, a.planner, a.seed, a.timeLimit, r)));
    const int code = report(a, queryScene, label, r, many ? numbered(a.output, qi) : a.output,
                            many ? numbered(a.svg, qi) : a.svg);
    exitCode = std::max(exitCode, code);
  }
  if (!a.statsJson.empty())
    writeFileAtomically(a.statsJson,
                        (summaries.size() == 1 ? summaries[0] : summaries).dump(1) + "\n");
  // Freeing a roadmap of a million manifolds takes seconds past the limit; the process is
  // about to exit and the system takes the memory back at once.
  if (params.exitsAfterRun) {
    planner->finishBackgroundWork();  // no thread of it may run while the process exits
    (void)planner.release();
  }
  return exitCode;
}

}  // namespace mms::cli
