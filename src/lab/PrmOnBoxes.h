#pragma once
// OMPL's PRM (Kavraki et al. 1996) on a BoxSpace, grown one milestone at a time until start
// and goal are in one roadmap component: the point-sample baseline for the lab. Samples are
// drawn from a per-trial seed (not OMPL's process-wide one), and motions are checked exactly
// against the boxes, so a trial's result depends on its seed only.
#include <cstdint>
#include <optional>

#include "lab/BoxSpace.h"

namespace mms::lab {

struct PrmSettings {
  size_t maxMilestones = 5000;
  unsigned neighbours = 10;  // OMPL's default k
  uint64_t seed = 1;
};

struct PrmResult {
  std::optional<size_t> milestones;  // free samples added before start and goal connected
  double seconds = 0;
};

PrmResult solvePrmOnBoxes(const BoxSpace& space, const Point& start, const Point& goal,
                          const PrmSettings& settings);

}  // namespace mms::lab
