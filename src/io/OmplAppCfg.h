#pragma once
// The [problem] section of an OMPL.app .cfg file: which meshes, where the robot starts and ends,
// the volume. Apart from the meshes' conversion (exact geometry), so that the fuzz target for
// this reader builds without it.
#include <optional>
#include <string>

#include "mms/Geometry.h"
#include "mms/Scene.h"

namespace mms {

struct OmplAppProblem {
  std::string name;                  // "" when the file gives none
  std::string robotMesh, worldMesh;  // as written, relative to the .cfg's folder
  Pose start, goal;
  Box volume;
  std::optional<std::string> control;    // a control-based problem's system, planned geometrically
  std::optional<std::string> objective;  // OMPL's optimization objective ("length", ...)
};

/// Throws InputError ("SOURCE: [problem] KEY: PROBLEM") on a missing section, key or number.
OmplAppProblem parseOmplAppProblem(const std::string& text, const std::string& source);
OmplAppProblem readOmplAppProblem(const std::string& cfgFile);

}  // namespace mms
