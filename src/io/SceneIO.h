#pragma once
// Scene files, format "mms-scene/1" (docs/formats.md). Loading validates everything and
// throws InputError with one line "FILE: LOCATION: PROBLEM" on the first problem found.
#include <nlohmann/json.hpp>
#include <string>

#include "mms/Scene.h"

namespace mms {

inline constexpr const char* kSceneFormat = "mms-scene/1";
/// Limits of the format, far above what planning takes, so that a runaway file (a million
/// robots) is refused at once with one line instead of filling memory.
inline constexpr size_t kMaxRobots = 100000;
inline constexpr size_t kMaxObstacles = 100000;

Scene loadScene(const std::string& file);
/// `source` names the document in messages (normally its file name).
Scene parseScene(const nlohmann::json& doc, const std::string& source);

nlohmann::json sceneToJson(const Scene& scene);
/// [[x, y], ...], as scene files write polygons.
nlohmann::json ringToJson(const Ring& ring);
/// Writes the scene atomically (no partial file on failure).
void saveScene(const Scene& scene, const std::string& file);

}  // namespace mms
