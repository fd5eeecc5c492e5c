#pragma once
// What the optimiser's passes share (path/Optimize.h): the certification of a candidate stretch
// (poses probed first, then the continuous checker), the work budget that makes the same seed
// give the same path, and the path's cumulative cost. Internal to path/.
#include <limits>
#include <vector>

#include "check/PathChecker.h"
#include "path/Optimize.h"

namespace mms::detail {

/// All robots' cost from a to b.
double segmentCost(const CollisionChecker& checker, const Config& a, const Config& b);

class OptimizerCore {
 protected:
  OptimizerCore(const Scene& scene, const CollisionChecker& checker, Random& rng,
                const OptimizeSettings& settings, const Termination& stop, OptimizeStats& stats);

  bool rigid(size_t robot) const { return scene_.robots[robot].motion != Motion::Translate; }

  // Out of work: the attempts' evaluations are spent, or the time limit struck.
  bool done() const { return s_.evaluations * workPerEvaluation_ >= limit_ || stop_(); }

  /// The certifier on a stretch; its minClearance is measured only when asked.
  PathCheckResult check(const std::vector<Config>& stretch, bool measureClearance = false);
  static constexpr size_t kEveryRobot = size_t(-1);
  /// Whether the stretch is probed free and then certified. `moved`: the only robot whose
  /// motion differs from the certified path's (the others follow it), so that the probes test
  /// that robot alone, against the obstacles and the others.
  bool certified(const std::vector<Config>& stretch, size_t moved = kEveryRobot);
  const std::vector<double>& cumulativeCost(const std::vector<Config>& w);
  void changed() { ++version_; }

  const Scene& scene_;
  const CollisionChecker& checker_;
  Random& rng_;
  const OptimizeSettings& settings_;
  const Termination& stop_;
  OptimizeStats& s_;
  size_t limit_ = 0;  // work at which the current step ends
  size_t workPerEvaluation_ =
      scene_.robots.size() + scene_.robots.size() * (scene_.robots.size() - 1) / 2;

 private:
  bool probedFree(const std::vector<Config>& stretch, size_t moved);
  bool freeAt(const Config& q, size_t moved);

  static constexpr size_t kProbeLevels = 3;  // of poses tested before a candidate is certified
  size_t probeLevels_ = kProbeLevels;
  std::vector<double> probeCost_;  // probedFree's, per segment
  Config probe_;                   // probedFree's pose
  double probeSpacing_ = 0;
  PathCheckSettings quick_, measured_;  // without and with the clearance measured
  std::vector<double> cum_;             // cumulativeCost's, for the path at `cumVersion_`
  size_t version_ = 0, cumVersion_ = size_t(-1);
};

}  // namespace mms::detail
