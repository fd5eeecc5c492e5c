#include <cmath>
#include <stdexcept>

#include "mms/Errors.h"
#include "registry/Adapters.h"
#include "util/Number.h"
#include "util/Suggest.h"

namespace mms {

bool afterFirstPath(const std::string& phase) {
  return phase == "optimize" || phase == "simplify" || phase == "restarts";
}

double paramValue(const PlannerParams& params, const ParamSpec& spec) {
  const auto it = params.values.find(spec.name);
  return it == params.values.end() ? spec.value : it->second;
}

const std::vector<PlannerInfo>& planners() {
  static const std::vector<PlannerInfo> all = [] {
    // MMS's paths are optimised by default; OMPL's planners keep OMPL's own simplifier
    // (--simplify), so that they are the baselines OMPL's users know.
    std::vector<PlannerInfo> v{withPathOptimization(portfolioPlannerInfo(), true),
                               withPathOptimization(mmsPlannerInfo(), true),
                               withPathOptimization(orderedPlannerInfo(), true),
                               withPathOptimization(jointPlannerInfo(), true)};
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
