#pragma once
// A roadmap as a record of the planning (mms/Record.h): its manifolds in the order built, with
// their time and round stamps, the subspaces they lie in, the searches and the path's manifolds.
#include <string>
#include <utility>
#include <vector>

#include "graph/Roadmap.h"
#include "mms/Record.h"

namespace mms {

/// Appends `roadmap` to `out` (its subspaces, manifolds, growth and searches). Past the budget
/// every k-th manifold is kept, the path's manifolds always.
void appendRoadmap(const Roadmap& roadmap, const RecordBudget& budget, PlanRecord& out);

/// How many of each kind were stamped by each of kGrowthSamples evenly spaced times:
/// `stamps` are (kind, time), in any order; `kinds` name the kinds.
inline constexpr size_t kGrowthSamples = 256;
RecordGrowth growthOf(std::vector<std::pair<uint32_t, float>> stamps,
                      const std::vector<std::string>& kinds);

}  // namespace mms
