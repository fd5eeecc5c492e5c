#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/PolygonOps.h"
#include "mms/Errors.h"
#include "registry/Adapters.h"
#include "util/Number.h"
#include "util/Suggest.h"

namespace mms {

bool afterFirstPath(const std::string& phase) {
  return phase == "optimize" || phase == "simplify" || phase == "restarts" || phase == "schedule";
}

double paramValue(const PlannerParams& params, const ParamSpec& spec) {
  const auto it = params.values.find(spec.name);
  return it == params.values.end() ? spec.value : it->second;
}

namespace {

// `scene` with its discs' stand-ins made with `sides` sides (robots and obstacles alike).
Scene withDiscSides(const Scene& scene, int sides) {
  Scene s = scene;
  for (Robot& r : s.robots)
    if (r.disc > 0) r.shape = discStandIn({{0, 0}, r.disc}, sides);
  for (size_t i = 0; i < s.obstacles.size(); ++i)
    if (const Disc* d = s.obstacleDisc(i)) s.obstacles[i] = discStandIn(*d, sides);
  return s;
}

}  // namespace

PlannerInfo withDiscStandIns(PlannerInfo info) {
  const ParamSpec sides{
      "disc-sides",
      ParamSpec::Type::Integer,
      0,
      256,
      0,
      "Sides of the polygons MMS plans on in place of exact discs (each around its disc, so a "
      "passage narrower than its disc by less than what they add, 1/cos(pi/sides) - 1 of the "
      "radius, is missed: 2 % at 16, 0.5 % at 32); slices of many discs cost about sides^1.8; "
      "paths are certified on the exact discs whatever the sides. 8 to 256, or 0: " +
          std::to_string(kFewDiscSides) + " below " + std::to_string(kOrderedFrom) + " robots, " +
          std::to_string(kManyDiscSides) + " from there (default 0)"};
  info.params.push_back(sides);
  info.make = [make = info.make, sides](const Scene& scene, const PlannerParams& params,
                                        const std::string& source) {
    int n = int(paramValue(params, sides));
    if (n != 0 && n < 8)
      throw InputError("--disc-sides: " + std::to_string(n) + " is neither 0 nor in [8, 256]");
    if (n == 0) n = scene.robots.size() < kOrderedFrom ? kFewDiscSides : kManyDiscSides;
    return scene.hasDiscs() ? make(withDiscSides(scene, n), params, source)
                            : make(scene, params, source);
  };
  return info;
}

const std::vector<PlannerInfo>& planners() {
  static const std::vector<PlannerInfo> all = [] {
    // MMS's paths are optimised by default; OMPL's planners keep OMPL's own simplifier
    // (--simplify), so that they are the baselines OMPL's users know. MMS's planners plan on
    // polygons in place of discs; OMPL's only ask the collision checker, which takes discs.
    std::vector<PlannerInfo> v{withDiscStandIns(withPathOptimization(portfolioPlannerInfo(), true)),
                               withDiscStandIns(withPathOptimization(mmsPlannerInfo(), true)),
                               withDiscStandIns(withPathOptimization(orderedPlannerInfo(), true)),
                               withDiscStandIns(withPathOptimization(jointPlannerInfo(), true))};
    for (PlannerInfo& i : omplPlannerInfos())
      v.push_back(withPathOptimization(std::move(i), false));
    return v;
  }();
  return all;
}

const PlannerInfo* findPlanner(const std::string& name) {
  for (const PlannerInfo& p : planners())
    if (p.name == name) return &p;
  return nullptr;
}

namespace {
// "a, b, c", each name after `prefix`.
std::string listed(const std::vector<std::string>& names, const std::string& prefix) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + prefix + n;
  return out;
}
}  // namespace

std::unique_ptr<Planner> makePlanner(const std::string& name, const Scene& scene,
                                     const PlannerParams& params, const std::string& source) {
  const PlannerInfo* info = findPlanner(name);
  if (!info) {
    std::vector<std::string> names;
    for (const PlannerInfo& p : planners()) names.push_back(p.name);
    throw InputError("--planner: unknown planner '" + name + "' (known: " + listed(names, "") +
                     ")" + didYouMean(name, names));
  }
  for (const auto& [given, value] : params.values) {
    const ParamSpec* spec = nullptr;
    for (const ParamSpec& s : info->params)
      if (s.name == given) spec = &s;
    if (!spec) {
      std::vector<std::string> names;
      for (const ParamSpec& s : info->params) names.push_back(s.name);
      throw InputError(
          "--" + given + ": not a parameter of planner " + name +
          (names.empty() ? " (it has none)" : " (its parameters: " + listed(names, "--") + ")") +
          didYouMean(given, names));
    }
    if (const std::string why = spec->problem(value); !why.empty())
      throw InputError("--" + given + ": " + why);
  }
  return info->make(scene, params, source);
}

}  // namespace mms
