#pragma once
// Path files, format "mms-path/1" (docs/formats.md): waypoints of all robots' configurations,
// linearly interpolated (angles are not wrapped).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "mms/Scene.h"

namespace mms {

inline constexpr const char* kPathFormat = "mms-path/1";
inline constexpr size_t kMaxWaypoints = 10'000'000;

struct Path {
  std::vector<Config> waypoints;
  /// Keys a planner adds (planner, seed, statistics ...); written back unchanged.
  nlohmann::json extra = nlohmann::json::object();
};

/// Loads a path and checks its shape against the scene (robot names, coordinates per
/// waypoint). Throws InputError on any problem.
Path loadPath(const std::string& file, const Scene& scene);
Path parsePath(const nlohmann::json& doc, const std::string& source, const Scene& scene);

/// Reads OMPL.app's .path text (PathGeometric::printAsMatrix): one line per state, "x y theta"
/// per robot (or "x y" for a robot that only translates). OMPL interpolates angles the short
/// way; the waypoints are unwrapped to say the same. Throws InputError ("FILE: line N: ...").
std::vector<Config> parseOmplPath(const std::string& text, const std::string& source,
                                  const Scene& scene);

nlohmann::json pathToJson(const Path& path, const Scene& scene);
void savePath(const Path& path, const Scene& scene, const std::string& file);

}  // namespace mms
