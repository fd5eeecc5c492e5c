#pragma once
// The anytime round loop of every MMS planner: grow manifolds until the round's targets are
// met or start and goal connect (the graph keeps a union-find, so the search can run early),
// search the connectivity graph, and turn the graph path into a certified motion. A candidate
// the checker refuses sends the loop back to complete the round; a complete round without a
// certified motion doubles the targets (Salzman, Hemmer, Halperin, Algorithm 1, with the
// search run as soon as start and goal connect). The planners supply what differs as hooks.
#include <functional>
#include <vector>

#include "graph/Roadmap.h"
#include "mms/Planner.h"
#include "mms/Termination.h"
#include "path/Motion.h"

namespace mms {

struct RoundHooks {
  std::function<void()> begin = [] {};  // before each stretch of growth
  std::function<bool()> growing;        // whether growth goes on in this stretch
  std::function<void()> grow;           // builds the next manifolds
  std::function<bool()> complete;       // the round's targets are met
  std::function<double()> share;        // how much of them (0 to 1)
  std::function<CertifiedMotion(const std::vector<size_t>& nodes)> motion;
  std::function<void()> refused = [] {};  // after the checker refused a candidate
  std::function<void()> report = [] {};   // after each search
  std::function<bool()> next;             // doubles the targets for the next round; false: give up
};

struct RoundsOutcome {
  enum class End { Found, NotFound, Cancelled } end = End::NotFound;
  std::vector<size_t> nodes;  // the graph path of the certified motion
  CertifiedMotion motion;     // the last candidate (certified when Found)
};

/// `Stats` holds the counters every MMS planner reports: rounds, roundShare, rejectedPaths and
/// the seconds of search, motion and certify. After each step of growth the round's share of
/// its targets met goes to `stop`'s watcher (the default planner's allowance grows with it).
template <class Stats>
RoundsOutcome runRounds(const RoundHooks& h, Roadmap& roadmap, size_t from, size_t to,
                        const Termination& stop, Stats& stats) {
  RoundsOutcome out;
  // After a candidate the checker refused, the round is completed before the next search.
  bool searchEarly = true;
  auto noteShare = [&] {
    stats.roundShare = h.share();
    stop.noteGrowth(stats.roundShare);
  };
  auto beginRound = [&] {
    roadmap.beginRound(uint32_t(++stats.rounds));
    stats.roundShare = 0;
    stop.noteRound(stats.rounds);
  };
  beginRound();
  while (true) {
    try {
      h.begin();
      while (h.growing() && !stop() && !(searchEarly && roadmap.graph().connected(from, to))) {
        h.grow();
        noteShare();
      }
      noteShare();
    } catch (const Stopped&) {
      // The limit struck inside a manifold: it is dropped, the search runs on the rest. No
      // round follows, so manifolds cut short never get out of step with the others.
    }
    Stopwatch search;
    const auto nodes = roadmap.path(from, to, [&] { return stop(); });
    stats.searchSeconds += search.seconds();
    roadmap.noteSearch(from, to);
    if (nodes) {
      out.motion = h.motion(*nodes);
      stats.motionSeconds += out.motion.buildSeconds;
      stats.certifySeconds += out.motion.certifySeconds;
      if (out.motion.ok) {
        out.nodes = *nodes;
        roadmap.notePath(out.nodes);
        out.end = RoundsOutcome::End::Found;
        return out;
      }
      if (!stop()) {  // refused by the certifier, not cut short by the limit
        ++stats.rejectedPaths;
        h.refused();
      }
    }
    h.report();
    if (stop()) {
      out.end = stop.cancelled() ? RoundsOutcome::End::Cancelled : RoundsOutcome::End::NotFound;
      return out;
    }
    if (searchEarly && !h.complete()) {
      searchEarly = false;  // a refused candidate ended the round early: complete it
      continue;
    }
    if (!h.next()) return out;
    searchEarly = true;
    beginRound();
  }
}

/// The angle count a rigid robot of a multi-robot planner reaches before its fixings grow too
/// (anglesFirst); the --n-fixings help reads it from here.
inline constexpr size_t kAnglesBeforeFixingsGrow = 16;

/// Whether the next round of a planner for two robots or more grows only the robots' angle
/// sets, keeping its holds: while a rigid robot has fewer than kAnglesBeforeFixingsGrow sequence
/// angles (counted per robot in `angles`, `translates` marking those with none). A subspace
/// costs an overlay per angle, so few angles make cheap rounds, while a passage that needs an
/// angle neither the start's nor the goal's is met only as the sets grow (docs/planner.md).
template <class Counts, class Flags>
bool anglesFirst(const Counts& angles, const Flags& translates) {
  for (size_t r = 0; r < angles.size(); ++r)
    if (!translates[r] && angles[r] < kAnglesBeforeFixingsGrow) return true;
  return false;
}

/// A planner's result as it ends (found or not, cut short or not): the graph's size and the
/// run's seconds in its statistics, and the status.
template <class Result, class Stats>
Result finishedRun(Result r, PlanStatus status, const Roadmap& roadmap, Stats& stats,
                   const Stopwatch& clock) {
  stats.graphNodes = roadmap.nodeCount();
  stats.graphEdges = roadmap.edgeCount();
  stats.totalSeconds = clock.seconds();
  r.status = status;
  r.stats = stats;
  return r;
}

/// A finished run of rounds in a planner's result: the last candidate's certificate; when
/// found, the graph path's size and footprint in `stats` and the certified waypoints. Returns
/// the run's status.
template <class Stats>
PlanStatus recordOutcome(RoundsOutcome& o, const Roadmap& roadmap, Stats& stats,
                         std::vector<Config>& waypoints, PathCheckResult& certificate) {
  certificate = o.motion.certificate;
  if (o.end == RoundsOutcome::End::Found) {
    stats.pathCells = o.nodes.size();
    const auto used = roadmap.footprint(o.nodes);
    stats.pathManifolds = used.manifolds;
    stats.pathSubspaces = used.groups;
    waypoints = std::move(o.motion.waypoints);
    return PlanStatus::Found;
  }
  return o.end == RoundsOutcome::End::Cancelled ? PlanStatus::Cancelled : PlanStatus::NotFound;
}

}  // namespace mms
