#include "check/PathChecker.h"
#include "io/AnyScene.h"
#include "io/PathIO.h"
#include "io/RunSummary.h"
#include "mms/Io.h"

namespace mms {

Scene readSceneFile(const std::string& file, std::vector<std::string>* notes) {
  ImportNotes n;
  Scene s = loadAnyScene(file, n);
  if (notes) {
    notes->insert(notes->end(), n.mistakes.begin(), n.mistakes.end());
    notes->insert(notes->end(), n.warnings.begin(), n.warnings.end());
  }
  return s;
}

void writePathFile(const Scene& scene, const PlanResult& result, const std::string& planner,
                   uint64_t seed, const std::string& file) {
  Path path;
  path.waypoints = result.waypoints;
  path.extra = pathExtra(result, planner, seed);
  savePath(path, scene, file);
}

std::vector<Config> readPathFile(const std::string& file, const Scene& scene) {
  return loadPath(file, scene).waypoints;
}

PathCheckResult certify(const Scene& scene, const std::vector<Config>& waypoints) {
  const CollisionChecker checker(scene);
  PathCheckResult c = checkPath(scene, checker, waypoints);
  if (c.ok) measureFleet(scene, checker, waypoints, c);
  return c;
}

}  // namespace mms
