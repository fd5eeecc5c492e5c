#include <cmath>
#include <cstdio>

#include "api/Adapters.h"
#include "mms/Errors.h"

namespace mms {

std::string ParamSpec::key() const {
  std::string k = name;
  for (char& c : k)
    if (c == '-') c = '_';
  return k;
}

std::string ParamSpec::problem(double v) const {
  if (!std::isfinite(v)) return "not a number";
  if ((type == Type::Integer || type == Type::Flag) && v != std::floor(v)) return "not an integer";
  if (v < min || v > max)
    return formatNumber(v) + " is not in [" + formatNumber(min) + ", " + formatNumber(max) + "]";
  return "";
}

std::string formatNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

double paramValue(const PlannerParams& params, const ParamSpec& spec) {
  const auto it = params.values.find(spec.name);
  return it == params.values.end() ? spec.value : it->second;
}

const std::vector<PlannerInfo>& planners() {
  static const std::vector<PlannerInfo> all = [] {
    std::vector<PlannerInfo> v{portfolioPlannerInfo(), mmsPlannerInfo()};
    for (PlannerInfo& i : omplPlannerInfos()) v.push_back(std::move(i));
    return v;
  }();
  return all;
}

const PlannerInfo* findPlanner(const std::string& name) {
  for (const PlannerInfo& p : planners())
    if (p.name == name) return &p;
  return nullptr;
}

std::unique_ptr<Planner> makePlanner(const std::string& name, const Scene& scene,
                                     const PlannerParams& params, const std::string& source) {
  const PlannerInfo* info = findPlanner(name);
  if (!info) {
    std::string known;
    for (const PlannerInfo& p : planners()) known += (known.empty() ? "" : ", ") + p.name;
    throw InputError("--planner: unknown planner '" + name + "' (known: " + known + ")");
  }
  for (const auto& [given, value] : params.values) {
    const ParamSpec* spec = nullptr;
    for (const ParamSpec& s : info->params)
      if (s.name == given) spec = &s;
    if (!spec) {
      std::string known;
      for (const ParamSpec& s : info->params) known += (known.empty() ? "--" : ", --") + s.name;
      throw InputError("--" + given + ": not a parameter of planner " + name +
                       (known.empty() ? " (it has none)" : " (its parameters: " + known + ")"));
    }
    if (const std::string why = spec->problem(value); !why.empty())
      throw InputError("--" + given + ": " + why);
  }
  return info->make(scene, params, source);
}

}  // namespace mms
