#pragma once
// Robots of one shape that only translate, shuffled one at a time between the vertices of a
// graph of placements: pebble motion on a graph (Kornhauser, Miller and Spirakis, 1984), on a
// roadmap whose every move is a certified straight motion, as in the discrete roadmaps of
// Solovey and Halperin's k-colour planner (2014).
//
// Vertices: where the robots stand, their goals, and placements one robot-width away from
// those (a square and a hexagonal step in each direction) that are free of the obstacles:
// the room that lets a packed crowd shuffle. A directed edge u -> v is a straight translation;
// its blockers are the vertices whose robot the moving robot would meet on the way, found by
// the certifier on two robots. A move is legal when no blocker of its edge is occupied, so a
// sequence of legal moves is a collision-free motion of all robots, one moving at a time.
//
// The moves are found by weighted A* over the robots' vertices (cost: length moved; heuristic:
// each robot's shortest distance in the graph to its goal, others ignored, times the weight;
// ties to the newest state). Complete on the graph, within the state budget: where the search
// ends without a solution the ordered planner goes on to the k-robot MMS. The heuristic ignores
// that robots make way for each other, so a packed crowd of dozens can exhaust the budget (the
// push-and-rotate moves of de Wilde, ter Mors and Witteveen would not; not built yet).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/CollisionChecker.h"
#include "mms/Scene.h"
#include "mms/Termination.h"

namespace mms {

struct PebbleSettings {
  uint64_t seed = 1;              // for the random walks that leave a local minimum
  double weight = 5;              // heuristic weight of the A* (1: fewest moves, slow)
  size_t legStates = 30'000;      // states of one search, restarted from its nearest state
  size_t maxStates = 10'000'000;  // states of all searches (each search's are freed)
  size_t maxVertices = 4000;
};

struct PebbleStats {
  size_t vertices = 0, edges = 0, states = 0, moves = 0;
};

/// Whether the pebble graph applies: at least two robots, all translating, one shape and angle.
bool pebbleApplies(const Scene& scene, const Config& from);

/// Waypoints from `from` (first) to the scene's goal (last), one robot moving between two
/// consecutive ones; nothing when the graph has no solution within the budget or `stop` ends.
std::optional<std::vector<Config>> pebbleMotion(const Scene& scene, const CollisionChecker& checker,
                                                const Config& from, const Termination& stop,
                                                PebbleStats& stats,
                                                const PebbleSettings& settings = {});

}  // namespace mms
