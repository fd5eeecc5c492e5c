#include <cstdio>

#include "Commands.h"
#include "planner/MmsPlanner.h"
#include "render/SvgRenderer.h"
#include "scene/Errors.h"
#include "scene/SceneIO.h"
#include "util/AtomicFile.h"

namespace mms::cli {

namespace {

void printStats(std::FILE* out, const MmsStats& s) {
  std::fprintf(out,
               "  manifolds: %zu slices (%zu cells), %zu lines (%zu arcs); graph %zu nodes, %zu edges; "
               "%zu rounds\n",
               s.slices, s.sliceCells, s.lines, s.lineArcs, s.graphNodes, s.graphEdges, s.rounds);
  std::fprintf(out,
               "  time: %.3f s total = slices %.3f + lines %.3f + connect %.3f + search %.3f + "
               "motion %.3f + shortcut/certify %.3f\n",
               s.totalSeconds, s.sliceSeconds, s.lineSeconds, s.connectSeconds, s.searchSeconds,
               s.motionSeconds, s.certifySeconds);
}

}  // namespace

int plan(const PlanArgs& a) {
  const Scene scene = loadScene(a.scene);
  if (scene.robots.size() != 1)
    throw InputError(a.scene + ": robots: " + std::to_string(scene.robots.size()) +
                     " robots; this version of mms plan handles scenes with one robot");
  MmsSettings settings;
  settings.seed = a.seed;
  settings.nTheta = a.nTheta;
  settings.nLines = a.nLines;
  MmsPlanner planner(scene, 0, settings);
  const Termination stop(a.timeLimit);
  Stopwatch clock;
  auto progress = [&](const MmsStats& s) {
    if (a.quiet || clock.seconds() < 1.0) return;
    std::fprintf(stderr, "mms plan: %.1f s, round %zu: %zu slices, %zu lines, graph %zu nodes / %zu edges\n",
                 clock.seconds(), s.rounds, planner.slices().size(), planner.lines().size(), s.graphNodes, s.graphEdges);
  };
  const Robot& r = scene.robots[0];
  const MmsResult res = planner.solve(r.start, r.goal, stop, progress);
  if (res.status != MmsResult::Status::Found) {
    std::printf("%s: no path found within %.3g s (%s)\n", a.scene.c_str(), a.timeLimit,
                res.status == MmsResult::Status::Cancelled ? "interrupted" : "time limit");
    printStats(stdout, res.stats);
    if (res.stats.rejectedPaths)
      std::printf("  %zu candidate motions failed certification\n", res.stats.rejectedPaths);
    return 1;
  }
  Path path;
  path.waypoints = res.waypoints;
  path.extra = {{"planner", "mms"},
                {"seed", a.seed},
                {"statistics",
                 {{"slices", res.stats.slices},
                  {"lines", res.stats.lines},
                  {"slice_cells", res.stats.sliceCells},
                  {"line_arcs", res.stats.lineArcs},
                  {"graph_nodes", res.stats.graphNodes},
                  {"graph_edges", res.stats.graphEdges},
                  {"path_cells", res.stats.pathCells}}}};
  if (!a.output.empty()) savePath(path, scene, a.output);
  if (!a.svg.empty()) writeFileAtomically(a.svg, renderSvg(scene, &path));
  std::printf("%s: path found and certified: %zu waypoints, translation %.4g, rotation %.4g rad, "
              "min clearance %.3g\n",
              a.scene.c_str(), path.waypoints.size(), res.certificate.translation, res.certificate.rotation,
              res.certificate.minClearance);
  printStats(stdout, res.stats);
  return 0;
}

}  // namespace mms::cli
