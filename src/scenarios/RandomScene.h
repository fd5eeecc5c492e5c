#pragma once
// Random scenes for property tests (`mms scenario random`): varied sizes, shapes and counts,
// and on purpose the degenerate cases exact geometry must survive: on grid scenes, rectangles
// whose edges touch each other and the bounds, collinear and overlapping edges, and gaps exactly
// as wide as a robot. Start and goal are free; whether a path exists is not known.
#include <cstdint>

#include "mms/Scene.h"

namespace mms {

struct RandomSceneSettings {
  uint64_t seed = 1;
  int robots = 0;      // 1 or 2; 0: drawn from the seed
  int obstacles = -1;  // how many; -1: drawn from the seed (0 to 30)
};

/// Same settings, same scene. Always valid (the loader accepts it).
Scene randomScene(const RandomSceneSettings& settings);

}  // namespace mms
