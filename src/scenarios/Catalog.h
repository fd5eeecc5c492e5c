#pragma once
// Every scene generator by name, with its settings checked: what `mms scenario` writes and what
// the Python module's mms.scenario() returns.
#include <cstdint>
#include <string>
#include <vector>

#include "mms/Scene.h"

namespace mms {

struct ScenarioRequest {
  std::string name;
  double tightness = 0;  // pacman: 0 = the base scene, towards 1 = the square exactly fits
  uint64_t seed = 1;     // random-polygons, random and the generated families
  double slack = 0.05;   // assembly-1/2; niche-swap, carry-turn, keyhole, swallow when given
  bool slackGiven = false;
  bool mPartsOnly = false;         // assembly-2
  int robots = 0, obstacles = -1;  // random: 0 / -1 = drawn from the seed; discs-room: robots
  double spacing = 0;              // disc-grid: centres apart, in radii (0: from the seed)
  // Robots (by name) that only translate; each must keep its angle from start to goal. The scene
  // is named apart ("niche-three-oncoming-translates-3"), so a benchmark keeps both variants.
  std::vector<std::string> translate;
};

/// A family of scenes: its name, what it is, and the settings it takes besides --seed.
struct ScenarioInfo {
  std::string name;
  std::vector<std::string> settings;  // "tightness", "slack", "robots", "obstacles", ...
  std::string summary;                // for mms scenario --help
  bool seeded = true;                 // whether its scene depends on the seed
};

/// Every family, in the order of the docs.
const std::vector<ScenarioInfo>& scenarios();

/// pacman, viking-helmet, random-polygons, assembly-1, ... (scenarios()' names).
const std::vector<std::string>& scenarioNames();

/// The scene; throws InputError ("PREFIX" "SETTING: PROBLEM", e.g. "--slack: ...") on an unknown
/// name or a setting out of range for that generator.
Scene makeScenario(const ScenarioRequest& request, const std::string& settingPrefix = "");

}  // namespace mms
