#include "Commands.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "check/PathChecker.h"
#include "io/AnyScene.h"
#include "io/Discopygal.h"
#include "io/PathIO.h"
#include "io/RecordIO.h"
#include "io/SceneIO.h"
#include "io/Trajectories.h"
#include "mms/Errors.h"
#include "render/HtmlViewer.h"
#include "render/SvgRenderer.h"
#include "util/AtomicFile.h"
#include "util/MemoryLimit.h"
#include "util/Number.h"

namespace mms::cli {

namespace {
const char* motionName(Motion m) { return m == Motion::Rigid ? "rigid" : "translate"; }

std::string pose(const Pose& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%g, %g, %g)", p.x, p.y, p.theta);
  return buf;
}
// --bounds XMIN,YMIN,XMAX,YMAX.
Box parseBounds(const std::string& text) {
  std::vector<double> v;
  std::istringstream in(text);
  in.imbue(std::locale::classic());
  for (std::string part; std::getline(in, part, ',');) {
    const std::optional<double> x = wholeNumber(part);
    if (!x || !std::isfinite(*x))
      throw InputError("--bounds: '" + part + "' is not a number (expected XMIN,YMIN,XMAX,YMAX)");
    v.push_back(*x);
  }
  if (v.size() != 4 || v[0] >= v[2] || v[1] >= v[3])
    throw InputError("--bounds: '" + text +
                     "' is not XMIN,YMIN,XMAX,YMAX with XMIN < XMAX and YMIN < YMAX");
  return {v[0], v[1], v[2], v[3]};
}
}  // namespace

static void printNotes(const ImportNotes& notes, bool quiet) {
  for (const std::string& w : notes.mistakes) std::fprintf(stderr, "mms: note: %s\n", w.c_str());
  if (!quiet)
    for (const std::string& w : notes.warnings) std::fprintf(stderr, "mms: note: %s\n", w.c_str());
}

Scene readScene(const std::string& file, bool quiet) {
  ImportNotes notes;
  Scene s = [&] {
    ReadingFile reading(file);
    return loadAnyScene(file, notes);
  }();
  printNotes(notes, quiet);
  return s;
}

int validate(const ValidateArgs& a) {
  const Scene s = readScene(a.scene, a.quiet);
  if (a.quiet) return 0;
  size_t vertices = 0;
  for (size_t i = 0; i < s.obstacles.size(); ++i)
    vertices += s.obstacleDisc(i) ? 0 : s.obstacles[i].size();
  std::printf("%s: valid %s scene%s%s\n", a.scene.c_str(), kSceneFormat, s.name.empty() ? "" : " '",
              s.name.empty() ? "" : (s.name + "'").c_str());
  std::printf("  bounds [%g, %g] x [%g, %g], %zu obstacles (%zu vertices), contact tolerance %g\n",
              s.bounds.xmin, s.bounds.xmax, s.bounds.ymin, s.bounds.ymax, s.obstacles.size(),
              vertices, s.tolerance());
  for (const Robot& r : s.robots) {
    char shape[64];
    if (r.disc > 0)
      std::snprintf(shape, sizeof shape, "disc of radius %g", r.disc);
    else
      std::snprintf(shape, sizeof shape, "%zu vertices", r.shape.size());
    std::printf("  robot '%s': %s, %s, start %s, goal %s\n", r.name.c_str(), shape,
                motionName(r.motion), pose(r.start).c_str(), pose(r.goal).c_str());
  }
  return 0;
}

std::string fleetLine(const Scene& scene, const PathCheckResult& c) {
  if (scene.robots.size() < 2 || !c.ok) return "";
  char line[256];
  std::snprintf(line, sizeof line,
                "  fleet: makespan %.4g (%.2fx its bound %.4g), sum of distances %.4g (%.2fx its "
                "bound %.4g), %.3g robots moving at once\n",
                c.makespan, c.makespanBound > 0 ? c.makespan / c.makespanBound : 1, c.makespanBound,
                c.distance, c.distanceBound > 0 ? c.distance / c.distanceBound : 1, c.distanceBound,
                c.movingAtOnce);
  return line;
}

int check(const CheckArgs& a) {
  const Scene scene = readScene(a.scene, true);
  const Path path = loadPath(a.path, scene);
  const CollisionChecker checker(scene);
  PathCheckSettings settings;
  settings.maxEvaluations = a.maxEvaluations;
  PathCheckResult r = checkPath(scene, checker, path.waypoints, settings);
  if (r.ok) measureFleet(scene, checker, path.waypoints, r);
  const size_t segments = path.waypoints.size() - 1;
  if (!r.ok && r.reason.find("waypoint puts") != std::string::npos) {  // an end, not a motion
    std::printf("%s: rejected: %s\n", a.path.c_str(), r.reason.c_str());
    return 1;
  }
  if (!r.ok) {
    std::printf("%s: rejected: segment %zu (waypoint %zu to %zu) at s = %.6g: %s\n", a.path.c_str(),
                r.segment, r.segment, std::min(r.segment + 1, segments), r.parameter,
                r.reason.c_str());
    return 1;
  }
  std::printf("%s: certified collision-free (%zu waypoints, %zu segments, %zu poses checked)\n",
              a.path.c_str(), path.waypoints.size(), segments, r.evaluations);
  std::printf("  min clearance %.6g (0 = touching within the tolerance %g)\n", r.minClearance,
              checker.tolerance());
  std::printf("  length: translation %.6g, rotation %.6g rad (summed over robots)\n", r.translation,
              r.rotation);
  std::printf("%s", fleetLine(scene, r).c_str());
  return 0;
}

int render(const RenderArgs& a) {
  const Scene scene = readScene(a.scene, true);
  Path path;
  if (!a.path.empty()) path = loadPath(a.path, scene);
  SvgOptions o;
  o.widthPx = a.width;
  o.ghosts = a.ghosts;
  o.animate = !a.noAnimation;
  writeFileAtomically(a.output, renderSvg(scene, a.path.empty() ? nullptr : &path, o));
  std::printf("%s: written\n", a.output.c_str());
  return 0;
}

int view(const ViewArgs& a) {
  const Scene scene = readScene(a.scene, true);
  Path path;
  if (!a.path.empty()) {
    path = loadPath(a.path, scene);
    // The viewer plays the path as given; one that is not a collision-free motion from the
    // scene's start to its goal is said to be so, as `mms check` would say.
    const PathCheckResult c = checkPath(scene, CollisionChecker(scene), path.waypoints);
    if (!c.ok)
      std::fprintf(stderr, "%s: warning: not certified (%s); the viewer shows it as given\n",
                   a.path.c_str(), c.reason.c_str());
  }
  std::optional<RecordFile> record;
  if (!a.record.empty()) record = loadRecord(a.record, scene.robots.size());
  writeFileAtomically(a.output, renderHtmlViewer(scene, a.path.empty() ? nullptr : &path,
                                                 record ? &*record : nullptr));
  std::printf("%s: written (open it in a browser; #t=0.5 shows the motion half-way)\n",
              a.output.c_str());
  return 0;
}

int scenario(const ScenarioArgs& a) {
  const Scene s = makeScenario(a, "--");
  saveScene(s, a.output);
  std::printf("%s: written (%s)\n", a.output.c_str(), s.name.c_str());
  return 0;
}

int importScene(const ImportArgs& a) {
  checkWritable(a.output, "-o");
  ImportNotes notes;
  Scene s = loadAnyScene(a.input, notes);
  if (!a.bounds.empty()) {
    s.bounds = parseBounds(a.bounds);
    // Validated again in the new bounds: a robot or obstacle outside them is named.
    s = parseScene(sceneToJson(s), a.input + " (with --bounds " + a.bounds + ")");
  }
  // Bounds given: the note on the bounds made up goes.
  if (!a.bounds.empty())
    std::erase_if(notes.warnings, [](const std::string& w) { return w.rfind("bounds:", 0) == 0; });
  printNotes(notes, a.quiet);
  saveScene(s, a.output);
  if (!a.quiet) {
    size_t vertices = 0;
    for (const Ring& o : s.obstacles) vertices += o.size();
    std::printf("%s: written (%zu obstacles, %zu vertices; %zu robot(s))\n", a.output.c_str(),
                s.obstacles.size(), vertices, s.robots.size());
  }
  return 0;
}

int exportScene(const ExportArgs& a) {
  const Scene scene = readScene(a.scene, true);
  ImportNotes notes;
  std::string text;
  if (a.to == "discopygal") {
    if (!a.path.empty())
      throw InputError(a.path + ": (PATH): --to discopygal writes the scene only");
    // discopygal's polygon robots only translate: a robot that must turn would lose the
    // motions its scene is about, unless the user says so.
    for (size_t i = 0; i < scene.robots.size() && !a.force; ++i)
      if (scene.robots[i].motion == Motion::Rigid && !(scene.robots[i].disc > 0))
        throw InputError(a.scene + ": robots[" + std::to_string(i) + "] ('" + scene.robots[i].name +
                         "'): rotates, and discopygal's polygon robots only translate (--force "
                         "writes it translating at its start angle)");
    text = discopygalJson(scene, notes);
  } else if (a.to == "trajectories") {
    if (a.path.empty()) throw InputError(a.scene + ": (PATH): --to trajectories needs a path file");
    text = trajectoriesCsv(scene, loadPath(a.path, scene).waypoints);
  } else {
    if (a.path.empty()) throw InputError(a.scene + ": (PATH): --to ompl-path needs a path file");
    if (scene.robots.size() != 1 || scene.robots[0].motion != Motion::Rigid)
      throw InputError(a.scene + ": robots: OMPL.app's .path holds one rigid robot (x y theta)");
    text = omplPathText(loadPath(a.path, scene).waypoints);
  }
  writeFileAtomically(a.output, text);
  if (!a.quiet) {
    printNotes(notes, false);
    std::printf("%s: written (%s)\n", a.output.c_str(), a.to.c_str());
  }
  return 0;
}

}  // namespace mms::cli

namespace mms::cli {

const Stopwatch& processClock() {
  static const Stopwatch clock;
  return clock;
}

}  // namespace mms::cli
