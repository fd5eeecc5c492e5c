#pragma once
// A cheap proof that a generated scene has a solution, so that a generator can redraw the
// scenes it cannot vouch for instead of handing planners a problem that has no answer.
#include <optional>
#include <vector>

#include "mms/Scene.h"

namespace mms {

/// A path that solves `scene`, found on a grid of poses, or nothing. The robots move one at a
/// time (scene order, then the reverse order), the others parked at their starts or goals; each
/// steps between neighbouring poses of a grid over (x, y, theta) with `cellsAcross` cells over
/// the bounds' longer side and angle steps that move no point of the robot further than a cell
/// (a robot that only translates keeps its angle).
/// A pose is used only if the robot's clearance there exceeds half a step, which bounds how far
/// any of its points moves to the nearer end of a step: every step is free as a continuous
/// motion. Nothing means only that the grid found no way (a passage may be narrower than a
/// cell). Meant for scenes of a few dozen obstacles: a robot may visit every grid pose.
std::optional<std::vector<Config>> gridWitness(const Scene& scene, int cellsAcross = 256);

}  // namespace mms
