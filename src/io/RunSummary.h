#pragma once
// One run of one planner as JSON: what `mms plan --stats-json` writes, what path files carry as
// "statistics", and what `mms bench` reads back from each child run. Written and read here only,
// so the keys are typed once (docs/formats.md, "Run summaries").
#include <nlohmann/json.hpp>
#include <string>

#include "mms/Planner.h"

namespace mms {

inline constexpr const char* kRunFormat = "mms-run/1";

/// Without timings, the statistics of a seed are the same on every run (path files).
nlohmann::json toJson(const PlanStatistics& s, bool timings = true);
PlanStatistics statisticsFromJson(const nlohmann::json& j);

/// The parameters in force as files show them: whole numbers, flags (true, false) and named
/// choices ("length") as such, by the planner's declarations (PlanResult::parameterSpecs).
nlohmann::json parametersJson(const PlanResult& result);

/// What a path file keeps of the run besides the waypoints: planner, seed, parameters,
/// statistics.
nlohmann::json pathExtra(const PlanResult& result, const std::string& planner, uint64_t seed);

struct RunSummary {
  std::string scene, planner;
  uint64_t seed = 1;
  double timeLimit = 0;
  PlanStatus status = PlanStatus::NotFound;
  nlohmann::json parameters;  // as parametersJson writes them
  PlanStatistics stats;
  size_t waypoints = 0;         // of the path, when found
  PathCheckResult certificate;  // translation, rotation, clearance when found; reason when not
};

RunSummary summarize(const std::string& scene, const std::string& planner, uint64_t seed,
                     double timeLimit, const PlanResult& result);
nlohmann::json toJson(const RunSummary& r);
/// Throws std::runtime_error on a document that is not a run summary.
RunSummary runSummaryFromJson(const nlohmann::json& j);

}  // namespace mms
