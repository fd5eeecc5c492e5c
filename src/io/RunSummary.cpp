#include "io/RunSummary.h"

#include <iterator>
#include <stdexcept>
#include <type_traits>

namespace mms {

namespace {

constexpr PlanStatus kStatuses[] = {PlanStatus::Found, PlanStatus::NotFound,
                                    PlanStatus::Uncertified, PlanStatus::Cancelled};
constexpr const char* kStatusNames[] = {"found", "not_found", "uncertified", "cancelled"};

PlanStatus statusFrom(const std::string& s) {
  for (size_t i = 0; i < std::size(kStatuses); ++i)
    if (s == kStatusNames[i]) return kStatuses[i];
  throw std::runtime_error("unknown status '" + s + "'");
}

// The scalar statistics, each named once for writing and reading.
template <class Stats, class F>
void scalars(Stats& s, F&& field) {
  field("seconds", s.seconds);
  field("rounds", s.rounds);
  field("graph_nodes", s.graphNodes);
  field("graph_edges", s.graphEdges);
  field("manifolds_built", s.manifoldsBuilt);
  field("manifolds_used", s.manifoldsUsed);
  field("path_cells", s.pathCells);
  field("rejected_paths", s.rejectedPaths);
}

}  // namespace

const char* toString(PlanStatus status) { return kStatusNames[size_t(status)]; }

nlohmann::json toJson(const PlanStatistics& s, bool timings) {
  nlohmann::json j = {{"counts", nlohmann::json::object()}};
  scalars(s, [&](const char* name, const auto& v) { j[name] = v; });
  for (const auto& [name, n] : s.counts) j["counts"][name] = n;
  if (s.rounds > 0) j["round_share"] = s.roundShare;
  if (!s.solvedBy.empty()) j["solved_by"] = s.solvedBy;
  if (!s.noPath.empty()) j["no_path"] = s.noPath;
  if (!timings) {
    j.erase("seconds");
    return j;
  }
  j["phases"] = nlohmann::json::object();
  for (const auto& [name, t] : s.phases) j["phases"][name] = t;
  return j;
}

PlanStatistics statisticsFromJson(const nlohmann::json& j) {
  PlanStatistics s;
  scalars(s, [&](const char* name, auto& v) { v = j.at(name).get<std::decay_t<decltype(v)>>(); });
  for (const auto& [name, n] : j.at("counts").items()) s.counts.emplace_back(name, n.get<size_t>());
  for (const auto& [name, t] : j.at("phases").items()) s.phases.emplace_back(name, t.get<double>());
  s.roundShare = j.value("round_share", 0.0);
  s.solvedBy = j.value("solved_by", "");
  s.noPath = j.value("no_path", "");
  return s;
}

nlohmann::json parametersJson(const PlanResult& result) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [key, v] : result.parameters) {
    j[key] = v;
    for (const ParamSpec& spec : result.parameterSpecs) {
      if (spec.key() != key) continue;
      if (!spec.choices.empty() && v >= 0 && size_t(v) < spec.choices.size())
        j[key] = spec.choices[size_t(v)];
      else if (spec.type == ParamSpec::Type::Flag)
        j[key] = v != 0;
      else if (spec.type == ParamSpec::Type::Integer)
        j[key] = static_cast<long long>(v);
    }
  }
  return j;
}

nlohmann::json pathExtra(const PlanResult& result, const std::string& planner, uint64_t seed) {
  return {{"planner", planner},
          {"seed", seed},
          {"parameters", parametersJson(result)},
          {"statistics", toJson(result.stats, /*timings=*/false)}};
}

RunSummary summarize(const std::string& scene, const std::string& planner, uint64_t seed,
                     double timeLimit, const PlanResult& result) {
  RunSummary r;
  r.scene = scene;
  r.planner = planner;
  r.seed = seed;
  r.timeLimit = timeLimit;
  r.status = result.status;
  r.parameters = parametersJson(result);
  r.stats = result.stats;
  r.waypoints = result.waypoints.size();
  r.certificate = result.certificate;
  return r;
}

nlohmann::json toJson(const RunSummary& r) {
  nlohmann::json j = {{"format", kRunFormat},         {"scene", r.scene},
                      {"planner", r.planner},         {"seed", r.seed},
                      {"time_limit", r.timeLimit},    {"status", toString(r.status)},
                      {"seconds", r.stats.seconds},   {"parameters", r.parameters},
                      {"statistics", toJson(r.stats)}};
  if (r.status == PlanStatus::Found) {
    const PathCheckResult& c = r.certificate;
    j["path"] = {{"waypoints", r.waypoints},        {"translation", c.translation},
                 {"rotation", c.rotation},          {"min_clearance", c.minClearance},
                 {"makespan", c.makespan},          {"makespan_bound", c.makespanBound},
                 {"distance", c.distance},          {"distance_bound", c.distanceBound},
                 {"moving_at_once", c.movingAtOnce}};
  }
  if (r.status == PlanStatus::Uncertified) j["rejection"] = r.certificate.reason;
  return j;
}

RunSummary runSummaryFromJson(const nlohmann::json& j) {
  if (!j.is_object() || j.value("format", "") != kRunFormat)
    throw std::runtime_error(std::string("not an ") + kRunFormat + " document");
  RunSummary r;
  r.scene = j.at("scene").get<std::string>();
  r.planner = j.at("planner").get<std::string>();
  r.seed = j.at("seed").get<uint64_t>();
  r.timeLimit = j.at("time_limit").get<double>();
  r.status = statusFrom(j.at("status").get<std::string>());
  r.parameters = j.at("parameters");
  if (!r.parameters.is_object()) throw std::runtime_error("parameters: not an object");
  r.stats = statisticsFromJson(j.at("statistics"));
  if (j.contains("path")) {
    const auto& p = j["path"];
    r.waypoints = p.at("waypoints").get<size_t>();
    r.certificate.ok = true;
    r.certificate.translation = p.at("translation").get<double>();
    r.certificate.rotation = p.at("rotation").get<double>();
    r.certificate.minClearance = p.at("min_clearance").get<double>();
    // Runs recorded before fleets were measured have none of these.
    r.certificate.makespan = p.value("makespan", 0.0);
    r.certificate.makespanBound = p.value("makespan_bound", 0.0);
    r.certificate.distance = p.value("distance", 0.0);
    r.certificate.distanceBound = p.value("distance_bound", 0.0);
    r.certificate.movingAtOnce = p.value("moving_at_once", 0.0);
  }
  r.certificate.reason = j.value("rejection", "");
  return r;
}

}  // namespace mms
