#include "bench/Report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "mms/Errors.h"
#include "mms/mms.h"
#include "render/Plot.h"

namespace mms {

nlohmann::json RunRecord::toJson() const {
  return {{"scene", scene},
          {"scene_file", sceneFile},
          {"tightness", tightness},
          {"robots", robots},
          {"planner", planner},
          {"parameters", parameters},
          {"seed", seed},
          {"status", status},
          {"seconds", seconds},
          {"wall_seconds", wallSeconds},
          {"started_at", startedAt},
          {"cores", cores},
          {"peak_memory_mb", peakMemoryMb},
          {"time_limit", timeLimit},
          {"memory_limit_mb", memoryLimitMb},
          {"translation", translation},
          {"rotation", rotation},
          {"makespan", makespan},
          {"makespan_bound", makespanBound},
          {"distance", distance},
          {"distance_bound", distanceBound},
          {"moving_at_once", movingAtOnce},
          {"graph_size", graphSize},
          {"manifolds_built", manifoldsBuilt},
          {"manifolds_used", manifoldsUsed},
          {"detail", detail},
          {"solved_by", solvedBy},
          {"version", version}};
}

RunRecord RunRecord::fromJson(const nlohmann::json& j) {
  RunRecord r;
  r.scene = j.at("scene");
  r.sceneFile = j.value("scene_file", "");
  r.tightness = j.value("tightness", -1.0);
  r.robots = j.value("robots", size_t(0));
  r.planner = j.at("planner");
  r.parameters = j.value("parameters", "");
  r.seed = j.at("seed");
  r.status = j.at("status");
  r.seconds = j.value("seconds", 0.0);
  r.wallSeconds = j.value("wall_seconds", 0.0);
  r.startedAt = j.value("started_at", 0.0);
  r.cores = j.value("cores", size_t(1));
  r.peakMemoryMb = j.value("peak_memory_mb", 0.0);
  r.timeLimit = j.value("time_limit", 0.0);
  r.memoryLimitMb = j.value("memory_limit_mb", 0.0);
  r.translation = j.value("translation", 0.0);
  r.rotation = j.value("rotation", 0.0);
  r.makespan = j.value("makespan", 0.0);
  r.makespanBound = j.value("makespan_bound", 0.0);
  r.distance = j.value("distance", 0.0);
  r.distanceBound = j.value("distance_bound", 0.0);
  r.movingAtOnce = j.value("moving_at_once", 0.0);
  r.graphSize = j.value("graph_size", size_t(0));
  r.manifoldsBuilt = j.value("manifolds_built", size_t(0));
  r.manifoldsUsed = j.value("manifolds_used", size_t(0));
  r.solvedBy = j.value("solved_by", "");
  r.detail = j.value("detail", "");
  r.version = j.value("version", "");
  return r;
}

std::vector<RunRecord> readRuns(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file + ": (file): cannot open for reading");
  std::vector<RunRecord> runs;
  std::string line;
  for (size_t n = 1; std::getline(in, line); ++n) {
    if (line.empty()) continue;
    try {
      runs.push_back(RunRecord::fromJson(nlohmann::json::parse(line)));
    } catch (const std::exception& e) {
      throw InputError(file + ": line " + std::to_string(n) + ": not a run record: " + e.what());
    }
  }
  return runs;
}

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

}  // namespace

std::string dateText(double epochSeconds) {
  std::tm utc{};
  char buf[32];
  const bool plausible = std::isfinite(epochSeconds) && epochSeconds > 0 && epochSeconds < 1e15;
  const std::time_t t = plausible ? std::time_t(epochSeconds) : 0;
  if (!plausible || !gmtime_r(&t, &utc) ||
      !std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S UTC", &utc))
    return "unknown";
  return buf;
}

bool RunRecord::failIfOverLimit() {
  if (!solved() || timeLimit <= 0) return false;
  const double allowed = timeLimit + std::max(0.05, 0.02 * timeLimit);
  if (wallSeconds <= allowed) return false;
  status = "over_limit";
  detail = "found a path, but the run took " + fmt("%.3f", wallSeconds) + " s of a " +
           fmt("%g", timeLimit) + " s limit";
  return true;
}

std::vector<Summary> summarize(const std::vector<RunRecord>& runs) {
  std::map<std::tuple<std::string, std::string, std::string>, std::vector<const RunRecord*>> groups;
  std::vector<std::tuple<std::string, std::string, std::string>> order;
  for (const RunRecord& r : runs) {
    auto key = std::make_tuple(r.scene, r.planner, r.parameters);
    if (!groups.count(key)) order.push_back(key);
    groups[key].push_back(&r);
  }
  std::vector<Summary> out;
  for (const auto& key : order) {
    const auto& g = groups[key];
    Summary s;
    std::tie(s.scene, s.planner, s.parameters) = key;
    s.tightness = g.front()->tightness;
    s.timeLimit = g.front()->timeLimit;
    s.runs = g.size();
    s.robots = g.front()->robots;
    std::vector<double> solvedTimes, all, lengths, rotations, graphs, built, used;
    std::vector<double> makespans, distances, moving;  // fleets: against their bounds
    for (const RunRecord* r : g) {
      s.uncertified += r->status == "uncertified";
      s.crashed += r->status == "crashed";
      if (r->status == "not_run") {
        ++s.notRun;
        all.push_back(std::numeric_limits<double>::infinity());
        continue;
      }
      s.peakMemoryMb = std::max(s.peakMemoryMb, r->peakMemoryMb);
      graphs.push_back(double(r->graphSize));
      if (r->solved()) {
        ++s.solved;
        solvedTimes.push_back(r->seconds);
        all.push_back(r->seconds);
        lengths.push_back(r->translation);
        rotations.push_back(r->rotation);
        built.push_back(double(r->manifoldsBuilt));
        used.push_back(double(r->manifoldsUsed));
        if (r->robots >= 2 && r->makespanBound > 0 && r->distanceBound > 0) {
          makespans.push_back(r->makespan / r->makespanBound);
          distances.push_back(r->distance / r->distanceBound);
          moving.push_back(r->movingAtOnce);
        }
      } else {
        all.push_back(std::numeric_limits<double>::infinity());
      }
    }
    std::sort(solvedTimes.begin(), solvedTimes.end());
    // The paper's protocol: mean and stdev without the fastest and the slowest run.
    std::vector<double> trimmed = solvedTimes;
    if (trimmed.size() >= 3) trimmed = std::vector<double>(trimmed.begin() + 1, trimmed.end() - 1);
    if (!trimmed.empty()) {
      double sum = 0;
      for (double t : trimmed) sum += t;
      s.meanTrimmed = sum / trimmed.size();
      double var = 0;
      for (double t : trimmed) var += (t - s.meanTrimmed) * (t - s.meanTrimmed);
      s.stdevTrimmed = trimmed.size() > 1 ? std::sqrt(var / (trimmed.size() - 1)) : 0;
    }
    std::sort(all.begin(), all.end());
    s.median = median(all);
    s.medianSolved = std::isfinite(s.median);
    s.medianLength = median(lengths);
    s.medianRotation = median(rotations);
    s.medianGraph = median(graphs);
    s.medianBuilt = median(built);
    s.medianUsed = median(used);
    s.medianMakespanRatio = median(makespans);
    s.medianDistanceRatio = median(distances);
    s.medianMovingAtOnce = median(moving);
    out.push_back(s);
  }
  return out;
}

std::string markdownReport(const std::vector<Summary>& summaries, const std::string& heading) {
  std::ostringstream md;
  if (!heading.empty()) md << heading << "\n\n";
  md << "| scene | planner | parameters | solved | crashed | mean ± stdev [s] (no min/max) | "
        "median [s] | path length | rotation [rad] | graph size | peak memory [MB] |\n";
  md << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Summary& s : summaries) {
    md << "| " << s.scene << " | " << s.planner << " | "
       << (s.parameters.empty() ? "defaults" : s.parameters) << " | " << s.solved << "/" << s.runs;
    if (s.uncertified) md << " (" << s.uncertified << " uncertified)";
    if (s.notRun) md << " (" << s.notRun << " not run: median decided)";
    md << " | " << (s.crashed ? "**" + std::to_string(s.crashed) + "**" : "0") << " | ";
    // Fewer than three solved runs are not trimmed, and one run has no deviation; of three,
    // trimming leaves the middle one.
    if (s.solved == 1)
      md << fmt("%.3g", s.meanTrimmed) << " (one run)";
    else if (s.solved == 3)
      md << fmt("%.3g", s.meanTrimmed) << " (the middle of three)";
    else if (s.solved == 2)
      md << fmt("%.3g", s.meanTrimmed) << " ± " << fmt("%.2g", s.stdevTrimmed) << " (two runs)";
    else if (s.solved)
      md << fmt("%.3g", s.meanTrimmed) << " ± " << fmt("%.2g", s.stdevTrimmed);
    else
      md << "–";
    md << " | " << (s.medianSolved ? fmt("%.3g", s.median) : "> " + fmt("%g", s.timeLimit)) << " | "
       << (s.solved ? fmt("%.3g", s.medianLength) : "–") << " | "
       << (s.solved ? fmt("%.3g", s.medianRotation) : "–") << " | " << fmt("%.0f", s.medianGraph)
       << " | " << fmt("%.0f", s.peakMemoryMb) << " |\n";
  }
  return md.str();
}

std::string crashReport(const std::vector<RunRecord>& runs) {
  std::string line;
  for (const RunRecord& r : runs) {
    if (r.status != "crashed") continue;
    line += (line.empty() ? "" : "; ") + r.scene + " " + r.planner +
            (r.parameters.empty() ? "" : " (" + r.parameters + ")") + " seed " +
            std::to_string(r.seed) + (r.detail.empty() ? "" : ": " + r.detail);
  }
  return line.empty() ? "" : "**Crashed runs** (bugs, not timeouts): " + line + ".\n";
}

namespace {
// The better of two summaries of one scene: lower median, then more runs solved.
bool better(const Summary& a, const Summary& b) {
  if (a.median != b.median) return a.median < b.median;
  return a.solved > b.solved;
}
std::string medianText(const Summary& s) {
  return (s.medianSolved ? fmt("%.3g s", s.median) : "> " + fmt("%g s", s.timeLimit)) + ", " +
         std::to_string(s.solved) + "/" + std::to_string(s.runs) +
         (s.notRun ? " (" + std::to_string(s.notRun) + " not run)" : "") +
         (s.crashed ? ", " + std::to_string(s.crashed) + " crashed" : "");
}
std::string label(const Summary& s) {
  return s.planner + (s.parameters.empty() ? "" : " (" + s.parameters + ")");
}
}  // namespace

std::string fleetReport(const std::vector<Summary>& summaries) {
  std::ostringstream md;
  for (const Summary& s : summaries) {
    if (s.robots < 2 || s.medianMakespanRatio == 0) continue;
    if (md.tellp() == 0)
      md << "| scene | planner | robots | makespan / its bound | sum of distances / its bound | "
            "robots moving at once |\n|---|---|---|---|---|---|\n";
    md << "| " << s.scene << " | " << label(s) << " | " << s.robots << " | "
       << fmt("%.3g", s.medianMakespanRatio) << " | " << fmt("%.3g", s.medianDistanceRatio) << " | "
       << fmt("%.3g", s.medianMovingAtOnce) << " |\n";
  }
  return md.str();
}

std::string speedupReport(const std::vector<Summary>& summaries) {
  std::vector<std::string> scenes;
  // Ours: MMS alone (mms, mms-ordered, mms-joint: the best of them) and the portfolio (which
  // races MMS with a sampler: never an "other").
  const std::string ours[] = {"mms", "auto"};
  std::map<std::string, const Summary*> best[3];  // per scene: mms, auto, the best other
  for (const Summary& s : summaries) {
    if (std::none_of(std::begin(best), std::end(best),
                     [&](const auto& b) { return b.count(s.scene); }))
      scenes.push_back(s.scene);
    const bool mmsFamily = s.planner.rfind("mms", 0) == 0;
    const size_t k =
        mmsFamily ? 0 : size_t(std::find(std::begin(ours), std::end(ours), s.planner) - ours);
    auto& b = best[k];
    if (!b.count(s.scene) || better(s, *b[s.scene])) b[s.scene] = &s;
  }
  std::ostringstream md;
  const bool rows = std::any_of(scenes.begin(), scenes.end(), [&](const std::string& scene) {
    return best[2].count(scene) && (best[0].count(scene) || best[1].count(scene));
  });
  if (!rows) return "";  // no MMS, or no other planner: nothing to compare
  md << "| scene | planner | median, solved | best other planner by median | speed-up | MMS "
        "manifolds used / built (median) |\n|---|---|---|---|---|---|\n";
  for (const std::string& scene : scenes)
    for (size_t k = 0; k < 2; ++k) {
      if (!best[k].count(scene) || !best[2].count(scene)) continue;
      const Summary& m = *best[k][scene];
      const Summary& o = *best[2][scene];
      std::string speedup = "–";
      if (m.medianSolved && o.medianSolved)
        speedup = fmt("%.3g×", o.median / m.median);
      else if (m.medianSolved)
        speedup = "> " + fmt("%.3g×", o.timeLimit / m.median) +
                  (o.solved == 0 ? " (no run of any other planner solved)" : "");
      md << "| " << scene << " | " << label(m) << " | " << medianText(m) << " | " << label(o)
         << ": " << medianText(o) << " | " << speedup << " | "
         << (m.solved ? fmt("%.0f", m.medianUsed) + " / " + fmt("%.0f", m.medianBuilt) : "–")
         << " |\n";
    }
  return md.str();
}

std::string rankingReport(const std::vector<Summary>& summaries) {
  std::vector<std::string> scenes;
  for (const Summary& s : summaries)
    if (std::find(scenes.begin(), scenes.end(), s.scene) == scenes.end()) scenes.push_back(s.scene);
  std::ostringstream md;
  md << "| scene | rank | planner | median, solved | against the first |\n|---|---|---|---|---|\n";
  for (const std::string& scene : scenes) {
    std::vector<const Summary*> ranked;
    for (const Summary& s : summaries)
      if (s.scene == scene) ranked.push_back(&s);
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const Summary* a, const Summary* b) { return better(*a, *b); });
    const Summary& first = *ranked.front();
    for (size_t k = 0; k < ranked.size(); ++k) {
      const Summary& s = *ranked[k];
      std::string ratio = "–";
      if (k == 0)
        ratio = "1×";
      else if (s.medianSolved && first.medianSolved)
        ratio = fmt("%.3g×", s.median / first.median);
      else if (first.medianSolved)
        ratio = "> " + fmt("%.3g×", s.timeLimit / first.median);
      md << "| " << (k ? "" : scene) << " | " << k + 1 << " | " << label(s) << " | "
         << medianText(s) << " | " << ratio << " |\n";
    }
  }
  return md.str();
}

namespace {
// Planners in the order they first appear, each with its colour.
std::vector<std::string> plannerOrder(const std::vector<std::string>& labels) {
  std::vector<std::string> out;
  for (const std::string& l : labels)
    if (std::find(out.begin(), out.end(), l) == out.end()) out.push_back(l);
  return out;
}
}  // namespace

std::string timesPlot(const std::vector<RunRecord>& runs) {
  std::vector<std::string> labels;
  for (const RunRecord& r : runs)
    labels.push_back(r.parameters.empty() ? r.planner : r.planner + " " + r.parameters);
  const std::vector<std::string> planners = plannerOrder(labels);
  std::vector<Category> cs;
  double limit = 0;
  std::vector<std::string> scenes;
  for (const RunRecord& r : runs)
    if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
  for (const std::string& scene : scenes)
    for (size_t p = 0; p < planners.size(); ++p) {
      Category c{scene, planners[p], seriesColour(p), {}};
      size_t unsolved = 0, total = 0;
      for (size_t i = 0; i < runs.size(); ++i) {
        if (runs[i].scene != scene || labels[i] != planners[p] || runs[i].status == "not_run")
          continue;
        ++total;
        limit = std::max(limit, runs[i].timeLimit);
        if (runs[i].solved())
          c.values.push_back(runs[i].seconds);
        else
          ++unsolved;
      }
      if (total == 0) continue;
      if (unsolved) c.note = std::to_string(unsolved) + "/" + std::to_string(total) + " ✗";
      cs.push_back(std::move(c));
    }
  PlotSpec spec;
  spec.title = "Time to a certified path per run";
  spec.yLabel = "seconds (log scale)";
  spec.logY = true;
  spec.width = std::max(640.0, 220 + 28.0 * double(cs.size()));
  spec.footnote = "Boxes: quartiles and median of the solved runs; n/m ✗: n of m runs unsolved";
  if (limit > 0) spec.rules.push_back({limit, "time limit"});
  return boxPlot(spec, cs);
}

std::string successPlot(const std::vector<Summary>& summaries) {
  std::vector<std::string> labels;
  for (const Summary& s : summaries) labels.push_back(label(s));
  const std::vector<std::string> planners = plannerOrder(labels);
  std::vector<Category> cs;
  for (const std::string& scene : plannerOrder([&] {
         std::vector<std::string> v;
         for (const Summary& s : summaries) v.push_back(s.scene);
         return v;
       }()))
    for (size_t p = 0; p < planners.size(); ++p)
      for (const Summary& s : summaries)
        if (s.scene == scene && label(s) == planners[p]) {
          const size_t ran = s.runs - s.notRun;
          const double share = ran ? double(s.solved) / double(ran) : 0;
          cs.push_back({scene,
                        planners[p],
                        seriesColour(p),
                        {100 * share},
                        std::to_string(s.solved) + "/" + std::to_string(ran)});
        }
  PlotSpec spec;
  spec.title = "Runs solved";
  spec.yLabel = "solved [%]";
  spec.width = std::max(640.0, 220 + 28.0 * double(cs.size()));
  spec.rules.push_back({100, ""});
  return barChart(spec, cs);
}

std::string csvReport(const std::vector<RunRecord>& runs) {
  std::ostringstream csv;
  csv << "scene,tightness,planner,parameters,seed,status,seconds,wall_seconds,peak_memory_mb,"
         "translation,rotation,"
         "graph_size,solved_by,makespan,makespan_bound,distance,distance_bound,moving_at_once\n";
  // Fields that do not apply are empty: no tightness for a scene without one, no path
  // measures for a run without a certified path.
  auto fleet = [](const RunRecord& r) { return r.solved() && r.robots >= 2 && r.makespan > 0; };
  auto field = [](bool applies, double v) {
    std::ostringstream s;
    if (applies) s << v;
    return s.str();
  };
  for (const RunRecord& r : runs)
    csv << r.scene << "," << field(r.tightness >= 0, r.tightness) << "," << r.planner << ",\""
        << r.parameters << "\"," << r.seed << "," << r.status << "," << r.seconds << ","
        << r.wallSeconds << "," << r.peakMemoryMb << "," << field(r.solved(), r.translation) << ","
        << field(r.solved(), r.rotation) << "," << r.graphSize << "," << r.solvedBy << ","
        << field(fleet(r), r.makespan) << "," << field(fleet(r), r.makespanBound) << ","
        << field(fleet(r), r.distance) << "," << field(fleet(r), r.distanceBound) << ","
        << field(fleet(r), r.movingAtOnce) << "\n";
  return csv.str();
}

std::vector<std::pair<std::string, std::string>> omplLogs(const std::vector<RunRecord>& runs,
                                                          const std::string& host) {
  std::vector<std::string> scenes;
  for (const RunRecord& r : runs)
    if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string& scene : scenes) {
    std::vector<std::pair<std::string, std::vector<const RunRecord*>>> planners;
    double total = 0, limit = 0, memory = 0;
    double first = std::numeric_limits<double>::infinity();  // when its first run started
    for (const RunRecord& r : runs) {
      if (r.scene != scene || r.status == "not_run") continue;
      if (r.startedAt > 0) first = std::min(first, r.startedAt);
      const std::string name = r.parameters.empty() ? r.planner : r.planner + " " + r.parameters;
      auto it = std::find_if(planners.begin(), planners.end(),
                             [&](const auto& p) { return p.first == name; });
      if (it == planners.end()) planners.push_back({name, {}}), it = planners.end() - 1;
      it->second.push_back(&r);
      total += r.wallSeconds;
      limit = std::max(limit, r.timeLimit);
      memory = std::max(memory, r.memoryLimitMb);
    }
    std::ostringstream log;
    size_t maxRuns = 0;
    for (const auto& p : planners) maxRuns = std::max(maxRuns, p.second.size());
    log << "MMS version " << version() << "\nExperiment " << scene << "\nRunning on " << host
        << "\nStarting at " << dateText(first) << "\n"
        << "<<<|\nmms bench on scene " << scene << "\n|>>>\n<<<|\n|>>>\n"
        << "1 is the random seed\n"
        << limit << " seconds per run\n"
        << memory << " MB per run\n"
        << maxRuns << " runs per planner\n"
        << total << " seconds spent to collect the data\n"
        << "1 enum type\nstatus|Exact solution|Timeout|Uncertified solution|Crash\n"
        << planners.size() << " planners\n";
    for (const auto& [name, rs] : planners) {
      std::string id = name;
      std::replace(id.begin(), id.end(), ' ', '_');
      log << id << "\n0 common properties\n7 properties for each run\n"
          << "time REAL\nmemory REAL\nsolved BOOLEAN\nstatus ENUM\nsolution_length "
             "REAL\ngraph_states INTEGER\n"
          << "seed INTEGER\n"
          << rs.size() << " runs\n";
      for (const RunRecord* r : rs) {
        const int status = r->solved()                  ? 0
                           : r->status == "uncertified" ? 2
                           : r->status == "not_found"   ? 1
                                                        : 3;
        log << (r->solved() ? r->seconds : r->timeLimit) << "; " << r->peakMemoryMb << "; "
            << (r->solved() ? 1 : 0) << "; " << status << "; ";
        if (r->solved()) log << r->translation;
        log << "; " << r->graphSize << "; " << r->seed << "; \n";
      }
      log << ".\n";
    }
    out.push_back({scene, log.str()});
  }
  return out;
}

std::string tightnessPlot(const std::vector<Summary>& summaries, const std::string& title) {
  PlotSpec spec;
  spec.title = title;
  spec.xLabel = "tightness";
  spec.yLabel = "planning time [s] (mean ± 1 stdev, log scale)";
  spec.logY = true;
  spec.width = 760;
  spec.footnote = "× n/m: n of m runs unsolved";
  double limit = 0;
  std::vector<std::string> planners;
  for (const Summary& s : summaries) {
    if (s.tightness < 0) continue;
    limit = std::max(limit, s.timeLimit);
    if (std::find(planners.begin(), planners.end(), s.planner) == planners.end())
      planners.push_back(s.planner);
  }
  if (limit > 0) spec.rules.push_back({limit, "time limit"});
  std::vector<Series> series;
  for (size_t pi = 0; pi < planners.size(); ++pi) {
    std::vector<const Summary*> pts;
    for (const Summary& s : summaries)
      if (s.planner == planners[pi] && s.tightness >= 0) pts.push_back(&s);
    std::sort(pts.begin(), pts.end(), [](auto a, auto b) { return a->tightness < b->tightness; });
    Series solved{planners[pi], seriesColour(pi), {}};
    Series failed{"", seriesColour(pi), {}};
    failed.line = false;
    failed.cross = true;
    for (const Summary* s : pts) {
      if (s->solved) {
        solved.points.push_back({s->tightness, s->meanTrimmed});
        // On a log axis a stdev larger than the mean has no lower end: stop at half the mean.
        solved.bars.push_back({std::max(0.5 * s->meanTrimmed, s->meanTrimmed - s->stdevTrimmed),
                               s->meanTrimmed + s->stdevTrimmed});
      }
      if (s->solved < s->runs) {  // unsolved runs: a cross at the time limit with the count
        failed.points.push_back({s->tightness, limit});
        failed.labels.push_back(std::to_string(s->runs - s->solved) + "/" +
                                std::to_string(s->runs));
      }
    }
    series.push_back(std::move(solved));
    series.push_back(std::move(failed));
  }
  return linePlot(spec, series);
}

namespace {
// "disc-grid-500-101" with 500 robots: "disc-grid" (the seed, then the count, dropped).
std::string familyOf(const RunRecord& r) {
  std::string name = r.scene;
  auto dropNumber = [&](const std::string& number) {
    const size_t dash = name.rfind('-');
    if (dash == std::string::npos || dash + 1 >= name.size()) return;
    const std::string tail = name.substr(dash + 1);
    const bool digits =
        std::all_of(tail.begin(), tail.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (digits && (number.empty() || tail == number)) name.erase(dash);
  };
  dropNumber("");
  dropNumber(std::to_string(r.robots));
  return name;
}
}  // namespace

std::string robotsPlot(const std::vector<RunRecord>& runs, bool memory) {
  // (family, planner) -> robots -> the solved runs' values
  std::map<std::pair<std::string, std::string>, std::map<size_t, std::vector<double>>> values;
  std::map<std::string, std::set<size_t>> counts;
  for (const RunRecord& r : runs) {
    if (r.robots == 0) continue;
    counts[familyOf(r)].insert(r.robots);
    if (r.solved())
      values[{familyOf(r), r.planner}][r.robots].push_back(memory ? r.peakMemoryMb : r.seconds);
  }
  std::vector<Series> series;
  for (const auto& [key, byCount] : values) {
    if (counts[key.first].size() < 2) continue;
    Series s{key.first + " (" + key.second + ")", seriesColour(series.size()), {}};
    for (auto [robots, v] : byCount) {
      std::sort(v.begin(), v.end());
      const double median =
          v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
      s.points.push_back({double(robots), median});
      s.labels.push_back(std::to_string(v.size()) + " solved");
    }
    series.push_back(std::move(s));
  }
  if (series.empty()) return "";
  PlotSpec spec;
  spec.title = memory ? "Peak memory against the number of robots"
                      : "Planning time against the number of robots";
  spec.xLabel = "robots (log scale)";
  spec.yLabel = memory ? "peak memory [MB] (median of solved runs, log scale)"
                       : "time to the first certified path [s] (median of solved runs, log scale)";
  spec.logX = spec.logY = true;
  spec.width = 760;
  return linePlot(spec, series);
}

}  // namespace mms
