#include <cstdio>
#include <filesystem>

#include "Commands.h"
#include "baselines/OmplPlanner.h"
#include "planner/MmsPlanner.h"
#include "planner/TwoRobotPlanner.h"
#include "render/SvgRenderer.h"
#include "scene/Errors.h"
#include "scene/Json.h"
#include "scene/SceneIO.h"
#include "util/AtomicFile.h"
#include "util/Interrupt.h"
#include "util/Parallel.h"

namespace mms::cli {

namespace {

void printStats(const MmsStats& s) {
  std::printf(
      "  manifolds: %zu slices (%zu cells), %zu lines (%zu arcs); graph %zu nodes, %zu edges; %zu "
      "rounds\n",
      s.manifolds.slices, s.manifolds.sliceCells, s.manifolds.lines, s.manifolds.lineArcs,
      s.graphNodes, s.graphEdges, s.rounds);
  std::printf(
      "  time: %.3f s total = slices %.3f + lines %.3f + connect %.3f + search %.3f + motion %.3f "
      "+ shortcut %.3f + certify %.3f\n",
      s.totalSeconds, s.manifolds.sliceSeconds, s.manifolds.lineSeconds, s.manifolds.connectSeconds,
      s.searchSeconds, s.motionSeconds, s.shortcutSeconds, s.certifySeconds);
  if (s.rejectedPaths)
    std::printf("  %zu candidate motions failed certification\n", s.rejectedPaths);
  if (s.pathManifolds)
    std::printf("  the path uses %zu of the %zu manifolds built\n", s.pathManifolds,
                s.manifolds.slices + s.manifolds.lines);
}

struct Query {
  Pose start, goal;
};

// mms-queries/1: {"format": "mms-queries/1", "queries": [{"start": [x,y,t], "goal": [x,y,t]}]}
std::vector<Query> loadQueries(const std::string& file, const Scene& scene) {
  using json_in::Node;
  const auto doc = json_in::parseFile(file);
  const Node root(doc, file, "");
  root.allowOnly({"format", "queries"});
  if (root["format"].string() != "mms-queries/1")
    root["format"].fail("unsupported format '" + root["format"].string() +
                        "' (expected mms-queries/1)");
  const Node qs = root["queries"];
  const size_t n = qs.arraySize(1, 100000);
  const CollisionChecker checker(scene);
  std::vector<Query> out;
  for (size_t i = 0; i < n; ++i) {
    qs[i].allowOnly({"start", "goal"});
    Query q;
    Pose* ends[2] = {&q.start, &q.goal};
    const char* names[2] = {"start", "goal"};
    for (int e = 0; e < 2; ++e) {
      const Node p = qs[i][names[e]];
      p.arraySize(3, 3);
      *ends[e] = {p[size_t(0)].number(json_in::kMaxCoordinate),
                  p[size_t(1)].number(json_in::kMaxCoordinate),
                  p[size_t(2)].number(json_in::kMaxAngle)};
      const Contact c = checker.robotContact(0, *ends[e]);
      if (c.kind != Contact::Kind::None)
        p.fail("robot '" + scene.robots[0].name + "' collides with " + c.describe(scene));
      if (scene.robots[0].motion == Motion::Translate &&
          ends[e]->theta != scene.robots[0].start.theta)
        p.fail("a translate robot keeps its angle " + std::to_string(scene.robots[0].start.theta));
    }
    out.push_back(q);
  }
  return out;
}

// "out.json" -> "out.3.json" for query 3.
std::string numbered(const std::string& path, size_t i) {
  const std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + "." + std::to_string(i) + p.extension().string()))
      .string();
}

}  // namespace

namespace {

void printFound(const std::string& label, const Path& path, const PathCheckResult& c) {
  std::printf(
      "%s: path found and certified: %zu waypoints, translation %.4g, rotation %.4g rad, min "
      "clearance %.3g\n",
      label.c_str(), path.waypoints.size(), c.translation, c.rotation, c.minClearance);
}

void printNotFound(const std::string& label, double timeLimit, MmsResult::Status status) {
  std::printf("%s: no path found within %.3g s (%s)\n", label.c_str(), timeLimit,
              status == MmsResult::Status::Cancelled ? "interrupted" : "time limit");
}

void writeStats(const PlanArgs& a, const nlohmann::json& j) {
  if (!a.statsJson.empty()) writeFileAtomically(a.statsJson, j.dump(1) + "\n");
}

nlohmann::json runSummary(const PlanArgs& a, const char* status, double seconds) {
  return {{"scene", a.scene}, {"planner", a.planner}, {"seed", a.seed},
          {"status", status}, {"seconds", seconds},   {"time_limit", a.timeLimit}};
}

void addPath(nlohmann::json& j, const PathCheckResult& c, size_t waypoints) {
  j["path"] = {{"waypoints", waypoints},
               {"translation", c.translation},
               {"rotation", c.rotation},
               {"min_clearance", c.minClearance}};
}

int planOmpl(const PlanArgs& a, const Scene& scene) {
  if (!a.queries.empty())
    throw InputError(a.queries + ": (file): --queries is for the mms planner");
  OmplSettings s;
  s.planner = a.planner;
  s.seed = a.seed;
  s.resolution = a.resolution;
  s.range = a.range;
  s.neighbours = a.neighbours;
  s.segmentFactor = a.segmentFactor;
  s.simplify = a.simplify;
#if !defined(__SANITIZE_ADDRESS__)
  s.keepUntilExit = true;  // under ASan, free everything so leaks stay visible
#endif
  const OmplResult r = planWithOmpl(scene, s, Termination(a.timeLimit, sigintFlag()));
  if (interruptRequested()) throw Interrupted();
  const char* status = r.status == OmplResult::Status::Found         ? "found"
                       : r.status == OmplResult::Status::Uncertified ? "uncertified"
                                                                     : "not_found";
  nlohmann::json j = runSummary(a, status, r.seconds);
  j["graph_states"] = r.states;
  j["parameters"] = {{"resolution", s.resolution},
                     {"range", s.range},
                     {"k", s.neighbours},
                     {"segment_factor", s.segmentFactor},
                     {"simplify", s.simplify}};
  if (r.status == OmplResult::Status::Uncertified) {
    std::printf(
        "%s: %s returned a path in %.3f s that fails the continuous check: segment %zu at s = "
        "%.4g: %s "
        "(counted as a failure)\n",
        a.scene.c_str(), a.planner.c_str(), r.seconds, r.certificate.segment,
        r.certificate.parameter, r.certificate.reason.c_str());
    j["rejection"] = r.certificate.reason;
    writeStats(a, j);
    return 1;
  }
  if (r.status == OmplResult::Status::NotFound) {
    if (r.states)
      std::printf("%s: %s found no path within %.3g s (%zu states)\n", a.scene.c_str(),
                  a.planner.c_str(), a.timeLimit, r.states);
    else
      std::printf("%s: %s found no path within %.3g s\n", a.scene.c_str(), a.planner.c_str(),
                  a.timeLimit);
    writeStats(a, j);
    return 1;
  }
  Path path;
  path.waypoints = r.waypoints;
  path.extra = {
      {"planner", a.planner}, {"seed", a.seed}, {"statistics", {{"graph_states", r.states}}}};
  if (!a.output.empty()) savePath(path, scene, a.output);
  if (!a.svg.empty()) writeFileAtomically(a.svg, renderSvg(scene, &path));
  addPath(j, r.certificate, path.waypoints.size());
  writeStats(a, j);
  std::printf(
      "%s: %s found a path in %.3f s, certified: %zu waypoints, translation %.4g, rotation %.4g "
      "rad, min "
      "clearance %.3g; %zu states\n",
      a.scene.c_str(), a.planner.c_str(), r.seconds, path.waypoints.size(),
      r.certificate.translation, r.certificate.rotation, r.certificate.minClearance, r.states);
  return 0;
}

void printTwoRobotStats(const TwoRobotStats& s) {
  const SubspaceStats& m = s.manifolds;
  std::printf(
      "  manifolds: %zu subspaces (%zu + %zu fixings), %zu slices (%zu at narrow arcs; %zu "
      "cells), %zu lines (%zu arcs); graph %zu nodes, %zu edges (%zu between subspaces); %zu "
      "rounds\n",
      s.subspaces, s.fixings[0], s.fixings[1], m.slices, m.localSlices, m.sliceCells, m.lines,
      m.lineArcs, s.graphNodes, s.graphEdges, s.crossEdges, s.rounds);
  std::printf(
      "  time: %.3f s total = base slices %.3f + overlays %.3f + lines %.3f + connect %.3f + "
      "cross %.3f + search %.3f + motion %.3f + shortcut %.3f + certify %.3f\n",
      s.totalSeconds, s.baseSliceSeconds, m.sliceSeconds, m.lineSeconds, m.connectSeconds,
      s.crossSeconds, s.searchSeconds, s.motionSeconds, s.shortcutSeconds, s.certifySeconds);
  if (s.rejectedPaths)
    std::printf("  %zu candidate motions failed certification\n", s.rejectedPaths);
  if (s.pathManifolds)
    std::printf("  the path uses %zu of the %zu manifolds built, in %zu of the %zu subspaces\n",
                s.pathManifolds, m.slices + m.lines, s.pathSubspaces, s.subspaces);
}

int planTwo(const PlanArgs& a, const Scene& scene) {
  if (a.saveRoadmap)
    throw InputError(a.scene +
                     ": (--save-roadmap): one-robot scenes only (a two-robot roadmap "
                     "lives in subspaces of a 6-D space)");
  if (!a.queries.empty())
    throw InputError(a.queries + ": (file): --queries is for one-robot scenes; " + a.scene +
                     " has two robots");
  TwoRobotSettings settings;
  settings.seed = a.seed;
  settings.threads = a.threads ? a.threads : hardwareThreads();
  if (a.nTheta) settings.nTheta = a.nTheta;
  if (a.nLines) settings.nLines = a.nLines;
  if (a.nFixings) settings.nFixings = a.nFixings;
  if (a.expandShare >= 0) settings.expandShare = a.expandShare;
  TwoRobotPlanner planner(scene, settings);
  Stopwatch clock;
  auto progress = [&](const TwoRobotStats& s) {
    if (a.quiet || clock.seconds() < 1.0) return;
    std::fprintf(stderr,
                 "mms plan: %.1f s, round %zu: %zu subspaces, %zu slices, %zu lines, graph %zu "
                 "nodes / %zu edges\n",
                 clock.seconds(), s.rounds, s.subspaces, s.manifolds.slices, s.manifolds.lines,
                 s.graphNodes, s.graphEdges);
  };
  const TwoRobotResult res = planner.solve(Termination(a.timeLimit, sigintFlag()), progress);
  if (interruptRequested()) throw Interrupted();
  nlohmann::json j = runSummary(a, res.status == MmsResult::Status::Found ? "found" : "not_found",
                                res.stats.totalSeconds);
  const TwoRobotStats& ts = res.stats;
  j["graph_nodes"] = ts.graphNodes;
  j["graph_edges"] = ts.graphEdges;
  const nlohmann::json parameters = {{"n_theta", settings.nTheta},
                                     {"n_lines", settings.nLines},
                                     {"n_fixings", settings.nFixings},
                                     {"expand_share", settings.expandShare}};
  j["parameters"] = parameters;
  j["manifolds"] = {{"subspaces", ts.subspaces},          {"slices", ts.manifolds.slices},
                    {"lines", ts.manifolds.lines},        {"path_cells", ts.pathCells},
                    {"path_manifolds", ts.pathManifolds}, {"path_subspaces", ts.pathSubspaces}};
  j["phases"] = {{"base_slices", ts.baseSliceSeconds}, {"overlays", ts.manifolds.sliceSeconds},
                 {"lines", ts.manifolds.lineSeconds},  {"connect", ts.manifolds.connectSeconds},
                 {"cross", ts.crossSeconds},           {"search", ts.searchSeconds},
                 {"motion", ts.motionSeconds},         {"shortcut", ts.shortcutSeconds},
                 {"certify", ts.certifySeconds}};
  if (res.status == MmsResult::Status::Found) addPath(j, res.certificate, res.waypoints.size());
  writeStats(a, j);
  if (res.status != MmsResult::Status::Found) {
    printNotFound(a.scene, a.timeLimit, res.status);
    printTwoRobotStats(res.stats);
    return 1;
  }
  Path path;
  path.waypoints = res.waypoints;
  const TwoRobotStats& st = res.stats;
  path.extra = {{"planner", "mms"},
                {"seed", a.seed},
                {"parameters", parameters},
                {"statistics",
                 {{"subspaces", st.subspaces},
                  {"slices", st.manifolds.slices},
                  {"lines", st.manifolds.lines},
                  {"graph_nodes", st.graphNodes},
                  {"graph_edges", st.graphEdges},
                  {"path_cells", st.pathCells}}}};
  if (!a.output.empty()) savePath(path, scene, a.output);
  if (!a.svg.empty()) writeFileAtomically(a.svg, renderSvg(scene, &path));
  printFound(a.scene, path, res.certificate);
  printTwoRobotStats(st);
  return 0;
}

}  // namespace

int plan(const PlanArgs& a) {
  const Scene scene = readScene(a.scene, a.quiet);
  if (a.planner != "mms") return planOmpl(a, scene);
  if (scene.robots.size() == 2) return planTwo(a, scene);
  if (scene.robots.size() != 1)
    throw InputError(a.scene + ": robots: " + std::to_string(scene.robots.size()) +
                     " robots; mms plan handles scenes with one or two robots");
  std::vector<Query> queries{{scene.robots[0].start, scene.robots[0].goal}};
  if (!a.queries.empty()) queries = loadQueries(a.queries, scene);

  MmsSettings settings;
  settings.seed = a.seed;
  settings.threads = a.threads ? a.threads : hardwareThreads();
  if (a.nTheta) settings.nTheta = a.nTheta;
  if (a.nLines) settings.nLines = a.nLines;
  MmsPlanner planner(scene, 0, settings);
  int exitCode = 0;
  nlohmann::json summaries = nlohmann::json::array();
  for (size_t qi = 0; qi < queries.size(); ++qi) {
    const Query& q = queries[qi];
    Scene queryScene = scene;
    queryScene.robots[0].start = q.start;
    queryScene.robots[0].goal = q.goal;
    const std::string label =
        a.queries.empty() ? a.scene : a.queries + " query " + std::to_string(qi);
    Stopwatch clock;
    auto progress = [&](const MmsStats& s) {
      if (a.quiet || clock.seconds() < 1.0) return;
      std::fprintf(
          stderr,
          "mms plan: %.1f s, round %zu: %zu slices, %zu lines, graph %zu nodes / %zu edges\n",
          clock.seconds(), s.rounds, s.manifolds.slices, s.manifolds.lines, s.graphNodes,
          s.graphEdges);
    };
    const MmsResult res =
        planner.solve(q.start, q.goal, Termination(a.timeLimit, sigintFlag()), progress);
    if (interruptRequested()) throw Interrupted();
    nlohmann::json j = runSummary(a, res.status == MmsResult::Status::Found ? "found" : "not_found",
                                  res.stats.totalSeconds);
    const MmsStats& ms = res.stats;
    j["graph_nodes"] = ms.graphNodes;
    j["graph_edges"] = ms.graphEdges;
    j["parameters"] = {{"n_theta", settings.nTheta}, {"n_lines", settings.nLines}};
    j["manifolds"] = {{"slices", ms.manifolds.slices},
                      {"lines", ms.manifolds.lines},
                      {"path_cells", ms.pathCells},
                      {"path_manifolds", ms.pathManifolds}};
    j["phases"] = {{"slices", ms.manifolds.sliceSeconds},
                   {"lines", ms.manifolds.lineSeconds},
                   {"connect", ms.manifolds.connectSeconds},
                   {"search", ms.searchSeconds},
                   {"motion", ms.motionSeconds},
                   {"shortcut", ms.shortcutSeconds},
                   {"certify", ms.certifySeconds}};
    if (res.status == MmsResult::Status::Found) addPath(j, res.certificate, res.waypoints.size());
    summaries.push_back(j);
    if (res.status != MmsResult::Status::Found) {
      printNotFound(label, a.timeLimit, res.status);
      printStats(res.stats);
      exitCode = 1;
      continue;
    }
    Path path;
    path.waypoints = res.waypoints;
    const MmsStats& st = res.stats;
    path.extra = {{"planner", "mms"},
                  {"seed", a.seed},
                  {"statistics",
                   {{"slices", st.manifolds.slices},
                    {"lines", st.manifolds.lines},
                    {"slice_cells", st.manifolds.sliceCells},
                    {"line_arcs", st.manifolds.lineArcs},
                    {"graph_nodes", st.graphNodes},
                    {"graph_edges", st.graphEdges},
                    {"path_cells", st.pathCells}}}};
    if (a.saveRoadmap) {
      // The viewer's overlay: the free-space cells the path uses, and every line's point.
      nlohmann::json cells = nlohmann::json::array(), points = nlohmann::json::array();
      for (const ConnectivityGraph::Node& n : res.cells)
        if (n.kind == ConnectivityGraph::Kind::SliceCell) {
          nlohmann::json rings = nlohmann::json::array();
          for (const Ring& r : planner.slices()[n.manifold].cell(n.cell))
            rings.push_back(ringToJson(r));
          cells.push_back(rings);
        }
      for (const Line& l : planner.lines()) points.push_back({l.point().x, l.point().y});
      path.extra["roadmap"] = {{"cells", cells}, {"points", points}};
    }
    const bool many = queries.size() > 1;
    if (!a.output.empty()) savePath(path, queryScene, many ? numbered(a.output, qi) : a.output);
    if (!a.svg.empty()) {
      SvgOptions o;
      if (a.svgRoadmap) {
        for (const Line& l : planner.lines()) o.markers.push_back(l.point());
        for (const ConnectivityGraph::Node& n : res.cells)
          if (n.kind == ConnectivityGraph::Kind::SliceCell)
            o.regions.push_back(planner.slices()[n.manifold].cell(n.cell));
      }
      writeFileAtomically(many ? numbered(a.svg, qi) : a.svg, renderSvg(queryScene, &path, o));
    }
    printFound(label, path, res.certificate);
    printStats(st);
  }
  writeStats(a, summaries.size() == 1 ? summaries[0] : summaries);
  return exitCode;
}

}  // namespace mms::cli
