#pragma once
// Query files, format "mms-queries/1" (docs/formats.md): several start and goal poses of a
// one-robot scene, answered on one roadmap by `mms plan --queries`.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "mms/Scene.h"

namespace mms {

inline constexpr const char* kQueriesFormat = "mms-queries/1";

struct Query {
  Pose start, goal;
};

/// Reads and validates the queries for robot 0 of `scene` (free poses; a translating robot
/// keeps its angle). Throws InputError ("FILE: FIELD: PROBLEM") on the first problem.
std::vector<Query> loadQueries(const std::string& file, const Scene& scene);
std::vector<Query> parseQueries(const nlohmann::json& doc, const std::string& source,
                                const Scene& scene);

}  // namespace mms
