#include "io/OmplApp.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

#include "geometry/Exact.h"
#include "io/Collada.h"
#include "io/OmplAppCfg.h"
#include "io/SceneIO.h"
#include "mms/Errors.h"

namespace mms {

namespace {

struct MeshShape {
  std::vector<exact::PolygonWithHoles> polygons;
  Vec2 centre;  // OMPL.app's reference point for a robot mesh
};

// A ring whose boundary touches itself at a vertex (CGAL's union writes such pinched
// boundaries) as simple rings: split at each repeated vertex.
void splitPinched(const Ring& ring, std::vector<Ring>& out) {
  for (size_t i = 0; i < ring.size(); ++i)
    for (size_t j = i + 1; j < ring.size(); ++j)
      if (ring[i].x == ring[j].x && ring[i].y == ring[j].y) {
        Ring a(ring.begin() + long(i), ring.begin() + long(j)),
            b(ring.begin() + long(j), ring.end());
        b.insert(b.end(), ring.begin(), ring.begin() + long(i));
        splitPinched(a, out);
        splitPinched(b, out);
        return;
      }
  if (ring.size() >= 3) out.push_back(ring);
}

MeshShape meshPolygons(const std::string& mesh, const std::string& what, ImportNotes& notes) {
  if (!std::filesystem::is_regular_file(mesh)) {
    std::error_code ec;
    const std::filesystem::path folder =
        std::filesystem::absolute(std::filesystem::path(mesh).parent_path(), ec);
    throw InputError(mesh + ": (" + what + "): no such mesh file in " + folder.string() +
                     " (meshes are looked for beside the .cfg file)");
  }
  ColladaMesh m = readColladaPlanar(mesh);
  size_t degenerate = 0;
  std::vector<exact::PolygonWithHoles> polys = exact::unionOfTriangles(m.triangles, degenerate);
  const std::string name = std::filesystem::path(mesh).filename().string();
  if (degenerate)
    notes.warnings.push_back(name + ": dropped " + std::to_string(degenerate) +
                             " zero-area triangles (the extrusion's side faces)");
  if (m.lineElements)
    notes.warnings.push_back(name + ": dropped " + std::to_string(m.lineElements) +
                             " line-only pieces (no area)");
  return {polys, m.vertexMean};
}

}  // namespace

Scene importOmplApp(const std::string& cfgFile, ImportNotes& notes) {
  const OmplAppProblem problem = readOmplAppProblem(cfgFile);
  const std::filesystem::path dir = std::filesystem::path(cfgFile).parent_path();
  auto meshPath = [&](const std::string& key) {
    return (dir / (key == "robot" ? problem.robotMesh : problem.worldMesh)).string();
  };
  // A scene holds no objective: say what planning does instead of dropping it silently.
  if (problem.objective)
    notes.warnings.push_back(
        cfgFile + ": objective = " + *problem.objective +
        (*problem.objective == "length"
             ? " is what mms plan optimises by default (--optimize 1 --objective length); "
               "OMPL's thresholds are not used"
             : " is not one mms optimises (it has --objective length|clearance); ignored"));
  if (problem.control)
    notes.warnings.push_back(cfgFile + ": control = " + *problem.control +
                             " ignored: planned as a geometric (holonomic) problem");

  Scene scene;
  scene.name =
      !problem.name.empty() ? problem.name : std::filesystem::path(cfgFile).stem().string();

  const MeshShape robotMesh = meshPolygons(meshPath("robot"), "[problem] robot", notes);
  const auto& robotPolys = robotMesh.polygons;
  if (robotPolys.empty())
    throw InputError(meshPath("robot") + ": ([problem] robot): the mesh has no area");
  Robot robot;
  robot.name = std::filesystem::path(meshPath("robot")).stem().string();
  if (robotPolys.size() == 1) {
    robot.shape = robotPolys[0].outer;
    if (!robotPolys[0].holes.empty())
      notes.warnings.push_back(robot.name + ": holes of the robot filled (conservative)");
  } else {
    std::vector<Vec2> all;
    for (const auto& p : robotPolys) all.insert(all.end(), p.outer.begin(), p.outer.end());
    robot.shape = exact::convexHull(all);
    notes.warnings.push_back(robot.name + ": the mesh is " + std::to_string(robotPolys.size()) +
                             " separate pieces; planned as their convex hull (conservative: a "
                             "path for the hull is valid for the pieces)");
  }
  // OMPL.app's reference point: the mean of the mesh's vertices.
  for (Vec2& v : robot.shape) v = {v.x - robotMesh.centre.x, v.y - robotMesh.centre.y};
  robot.start = problem.start;
  robot.goal = problem.goal;
  scene.robots.push_back(robot);

  size_t split = 0;
  for (const exact::PolygonWithHoles& p :
       meshPolygons(meshPath("world"), "[problem] world", notes).polygons) {
    if (p.holes.empty()) {
      splitPinched(p.outer, scene.obstacles);
      continue;
    }
    split += 1;
    for (const Ring& piece : p.convexPieces) splitPinched(piece, scene.obstacles);
  }
  if (split)
    notes.warnings.push_back(std::to_string(split) +
                             " obstacle(s) with holes split into convex pieces (scenes hold "
                             "simple polygons)");
  scene.bounds = problem.volume;
  // Validate as a loaded file would be (one definition of a valid scene).
  return parseScene(sceneToJson(scene), cfgFile);
}

std::vector<Config> splitLongTurns(const std::vector<Config>& waypoints) {
  std::vector<Config> out;
  for (size_t k = 0; k < waypoints.size(); ++k) {
    const Config& b = waypoints[k];
    if (k > 0) {
      const Config& a = waypoints[k - 1];
      double turn = 0;
      for (size_t i = 2; i < b.size(); i += 3) turn = std::max(turn, std::abs(b[i] - a[i]));
      // Parts that turn less than pi by more than rounding: OMPL's short way is then the
      // motion's own way.
      const size_t parts = size_t(std::floor(turn / (M_PI - 1e-9))) + 1;
      for (size_t j = 1; j < parts; ++j) {
        const double t = double(j) / double(parts);
        Config q(b.size());
        for (size_t i = 0; i < q.size(); ++i) q[i] = a[i] + t * (b[i] - a[i]);
        out.push_back(std::move(q));
      }
    }
    out.push_back(b);
  }
  return out;
}

std::string omplPathText(const std::vector<Config>& waypoints) {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out << std::setprecision(17);
  for (const Config& q : splitLongTurns(waypoints)) {
    for (size_t i = 0; i < q.size(); ++i) {
      double v = q[i];
      if (i % 3 == 2) {  // into [-pi, pi), OMPL's SO(2)
        v -= 2 * M_PI * std::floor((v + M_PI) / (2 * M_PI));
        if (v >= M_PI) v -= 2 * M_PI;
      }
      out << (i ? " " : "") << v;
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace mms
