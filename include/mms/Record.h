#pragma once
// A record of the planning: what a planner built and when, for pictures of how it grew (`mms
// plan --record`, format mms-record/1 in docs/formats.md; `mms view --record`; `result.record`
// in Python). MMS records its manifolds (slices with their free-space cells, lines with their
// free arcs, pivot lines, compound manifolds), the subspaces they lie in and how start's and
// goal's components grew; OMPL's planners their tree or graph. Plain data, as every public
// header.
//
// Bounded: past a budget, every k-th manifold or state is kept (spread over the whole run), and
// how many of each were built by when is kept from them all (RecordGrowth).
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "mms/Geometry.h"
#include "mms/Scene.h"

namespace mms {

/// Where the robots not moving in a subspace stand.
struct RecordSubspace {
  size_t moving = 0;                          // the robot that moves (a compound's carrier)
  long attached = -1;                         // a compound: the robot carried along, else -1
  std::vector<std::pair<size_t, Pose>> held;  // the robots held, and where
};

/// One manifold as it was built.
struct RecordManifold {
  size_t index = 0;       // its place in the order built (PlanRecord::manifolds may skip some)
  std::string family;     // "slice", "line", "pivot-line", "compound-slice", "compound-line"
  float at = 0;           // seconds since the planning began
  uint32_t round = 0;     // 0: before the first round (ends, base slices), then 1, 2, ...
  uint32_t subspace = 0;  // index into PlanRecord::subspaces
  size_t cells = 0;       // its free-space cells (a line's: its free arcs)
  size_t vertices = 0;    // a slice: its cells' vertices
  /// When one of its cells joined the start's (0) and the goal's (1) component, as seen at the
  /// searches; -1: never.
  std::array<float, 2> reached{-1, -1};
  bool onPath = false;  // a cell of it lies on the path found
  double theta = 0;     // a slice: the moving robot's angle
  Vec2 point;           // a line: the moving robot's reference point; a pivot line: the pivot
  std::vector<std::vector<Ring>> regions;       // a slice: each cell, outer ring then holes
  std::vector<std::pair<double, double>> arcs;  // a line: its free arcs [lo, hi]
};

/// How much was built by when: the count of each kind (a manifold family, or a sampler's
/// "states") at evenly spaced times up to the last stamp. Kept from every stamp, thinned or not.
struct RecordGrowth {
  std::vector<float> at;
  std::vector<std::pair<std::string, std::vector<size_t>>> counts;  // by kind, one per time
};

/// The graph after each search.
struct RecordSearch {
  float at = 0;
  uint32_t round = 0;
  size_t manifolds = 0, nodes = 0, edges = 0;
  bool connected = false;  // start and goal in one component
};

/// A sampler's tree or roadmap (OMPL's PlannerData): every robot's configuration per state,
/// with the time its first motion was found free.
struct RecordTree {
  std::vector<Config> states;
  std::vector<float> at;
  std::vector<std::array<uint32_t, 2>> edges;
  size_t totalStates = 0, totalEdges = 0;  // before thinning
};

struct PlanRecord {
  std::string planner;  // the registry name of the planner recorded (a portfolio's winner)
  size_t robots = 0;
  double seconds = 0;        // the planning the record covers
  double recordSeconds = 0;  // of which, assembling the record
  std::vector<RecordSubspace> subspaces;
  std::vector<RecordManifold> manifolds;  // in the order built; past the budget, those kept
  RecordGrowth growth;
  std::vector<RecordSearch> searches;
  RecordTree tree;
};

/// How much of the planning a record keeps: past these, every k-th manifold or state, so that
/// a file stays under about 50 MB however long the run.
struct RecordBudget {
  /// Bytes of manifolds in the file, as estimated per manifold: 130 for its stamps and counts,
  /// 18 per vertex of its cells, 20 per arc; and 40 per robot held in each subspace.
  size_t bytes = 40'000'000;
  size_t numbers = 1'000'000;  // a sampler's states, 3 numbers per robot each (about 9 bytes)
};

}  // namespace mms
