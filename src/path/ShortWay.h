#pragma once
// The optimiser's turn passes (path/Optimize.h, "turn the short way"): where a rigid robot turns
// more than half a circle in all over a stretch, the stretch turned the other way round, its
// new turn put where the robot turned, moved to a clear place where the robot spins whole, or
// made there with the robot routed anew through exact slices (HeldRoute.h). Internal to path/.
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "path/HeldRoute.h"
#include "path/OptimizerCore.h"

namespace mms::detail {

class ShortWay : protected OptimizerCore {
 protected:
  using OptimizerCore::OptimizerCore;

  /// Each rigid robot's stretches turned the short way while one certifies.
  void turnShortWay(std::vector<Config>& w);

  HeldRoutes routes_{scene_, checker_, 8};  // slices at most, per optimisation
  bool routing_ = false;                    // whether rewinds may route (the last pass)

 private:
  using Run = std::pair<size_t, size_t>;  // waypoints at the ends of a run of turning segments

  struct Rewind {
    size_t p, q;    // the window's first and last runs
    double turns;   // full turns added at the window's end and after
    double saving;  // rotation saved
  };

  static std::vector<Run> turningRuns(const std::vector<Config>& w, size_t c);

  static std::vector<Rewind> rewinds(const std::vector<Config>& w, const std::vector<Run>& runs,
                                     size_t c);

  // Where a window's new turn goes. All its runs scaled to it, or spread evenly over the
  // window's cost; or the full turns added in one run (that run turns the other way round), or
  // half in each of two (between them the robot is held half a turn round: a key that turned a
  // quarter the long way in its chamber, left through a slot with its bit first and turned half
  // round outside, turns a quarter the other way and leaves bit last); or the whole net turn
  // made in one run, the robot holding its angle through the others (what removes turning back
  // and forth across runs, which a window without a full turn to take back is tried for).
  struct Carrier {
    enum Kind { Scaled, Spread, Runs, Only } kind;
    size_t first = 0, second = 0;  // runs, for Runs (second == first: one run) and Only
  };

  bool rewindOnce(std::vector<Config>& w, size_t robot);

  bool rewindPass(std::vector<Config>& w, size_t robot, const std::vector<Run>& runs,
                  const std::vector<double>& cum, const std::vector<Rewind>& candidates, bool spin);

  bool holdThroughTurn(std::vector<Config>& w, size_t robot, const std::vector<double>& cum);

  static void takeWindow(std::vector<Config>& w, size_t from, size_t to,
                         const std::vector<Config>& window, size_t c, double turns);

  bool routedSpin(std::vector<Config>& w, size_t robot, const std::vector<Run>& runs,
                  const std::vector<double>& cum, const std::vector<Rewind>& candidates);

  // A routed window's poses: its ends, and the robot spinning at `at` before and after the
  // turn (b at the end's angle plus `turns` full turns).
  struct SpinEnds {
    Pose first, a, b, last;
  };

  SpinEnds spinEnds(const std::vector<Config>& w, size_t from, size_t to, size_t robot,
                    double turns, Vec2 at);

  double leastRoutedCost(const SpinEnds& e, size_t robot) const;

  Vec2 clearPlaceNear(const std::vector<Config>& w, size_t k, size_t robot);

  std::vector<Vec2> placesToSpin(const std::vector<Config>& w, size_t from, size_t to,
                                 size_t robot);

  std::vector<Config> routedStretch(const Config& start, const SpinEnds& ends, size_t robot,
                                    Vec2 at);

  static std::vector<Carrier> carriersOf(const Rewind& r, bool spin);

  static std::vector<std::pair<std::vector<size_t>, bool>> spunRuns(const Carrier& carrier,
                                                                    bool spin);

  std::vector<Config> spunStretch(const std::vector<Config>& w, std::vector<Config> stretch,
                                  const std::vector<Run>& runs, const std::vector<size_t>& moved,
                                  bool mirror, size_t from, size_t robot);

  const Disc& spinCircle(size_t robot);

  Vec2 spinCentre(size_t robot) { return spinCircle(robot).center; }

  double spinRadius(size_t robot) { return spinCircle(robot).radius; }

  static double rewound(const std::vector<Config>& w, const std::vector<double>& cum,
                        const std::vector<Run>& runs, const Carrier& carrier, const Rewind& r,
                        size_t at, size_t c);

  static constexpr size_t kRewindTries = 32;   // certifications per robot and change
  static constexpr size_t kHoldSpan = 512;     // waypoints a full turn held through spans at most
  static constexpr size_t kSpinTries = 24;     // the same, for turns moved to spin in place
  static constexpr size_t kSpinCarriers = 64;  // and carriers built for them (each a stretch)
  static constexpr size_t kSpinPlaces = 4;     // and places where the robot could spin, climbed to
  static constexpr double kSpinStep = 0.05;    // radians between a moved turn's waypoints
  static constexpr double kMinSaving = 0.05;   // radians of back and forth worth a try
  // Worth routing the robot anew for: half a turn (a quarter turn made the long way round
  // saves that). From 1 rad, on open clutter's and the doors' tuning seeds the routes cost the
  // optimiser 1.2x its time in the mean and left the 90th percentile of rotation as it was.
  static constexpr double kRouteSaving = M_PI - 1e-6;
  static constexpr size_t kRouteWindows = 2;  // windows routed per rewind
  static constexpr size_t kRoutePlaces = 3;   // places to spin tried per window
  static constexpr size_t kRouteClimbs = 12;  // climbs to find them
  std::vector<Disc> spinCircles_;
  std::map<size_t, Vec2> spinPlaces_;  // per segment where a run turned most, in one rewind
};

}  // namespace mms::detail
