#pragma once
// Files in and out, for programs that embed mms: scenes in any format mms reads, path files,
// and certification of a motion. Formats: docs/formats.md.
#include <string>
#include <vector>

#include "mms/Certificate.h"
#include "mms/Planner.h"
#include "mms/Scene.h"

namespace mms {

/// A scene file: mms-scene/1 JSON, an OMPL.app .cfg problem or a discopygal JSON scene. What a
/// conversion changed is appended to `notes` (one line each) when given. Throws InputError
/// ("FILE: FIELD: PROBLEM") on anything it cannot read.
Scene readSceneFile(const std::string& file, std::vector<std::string>* notes = nullptr);

/// Writes a planner's certified path as an mms-path/1 file (atomically: no partial file), with
/// the planner's name, seed, parameters and statistics.
void writePathFile(const Scene& scene, const PlanResult& result, const std::string& planner,
                   uint64_t seed, const std::string& file);

/// Reads an mms-path/1 file for `scene`; throws InputError on any problem.
std::vector<Config> readPathFile(const std::string& file, const Scene& scene);

/// Certifies waypoints as a continuous collision-free motion from the scene's start to its goal.
PathCheckResult certify(const Scene& scene, const std::vector<Config>& waypoints);

}  // namespace mms
