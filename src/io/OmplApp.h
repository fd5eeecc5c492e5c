#pragma once
// OMPL.app planar problems (.cfg + COLLADA meshes) as mms scenes: the [problem] section names
// the robot and world meshes, start, goal and the volume; each mesh becomes exact polygons,
// the union of its triangles projected on the X/Z plane (CGAL).
#include <string>
#include <vector>

#include "mms/Scene.h"

namespace mms {

struct ImportNotes {
  std::vector<std::string> warnings;  // what was dropped or changed, one line each
  /// What looks like a mistake in the input (angles in degrees): shown even where a quiet
  /// command shows no warnings.
  std::vector<std::string> mistakes;
};

/// Throws InputError ("FILE: FIELD: PROBLEM") on anything it cannot read or convert. The
/// scene is validated as if loaded from a file.
Scene importOmplApp(const std::string& cfgFile, ImportNotes& notes);

/// Writes a path as OMPL.app's .path text: one "x y theta" line per state (one rigid robot),
/// describing the same motion. OMPL turns the short way between states and keeps angles in
/// [-pi, pi), so angles are written there and a segment turning pi or more is split into
/// equal parts that each turn less.
std::string omplPathText(const std::vector<Config>& waypoints);

/// The waypoints omplPathText writes: `waypoints` with long turns split, angles unchanged.
std::vector<Config> splitLongTurns(const std::vector<Config>& waypoints);

}  // namespace mms
