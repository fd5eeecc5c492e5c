#pragma once
// MMS for k >= 3 robots: recursive MMS (Salzman, Hemmer, Halperin, Section II) with every robot
// but one held. A *tuple* places all k robots; in the subspace (i, tuple) robot i moves among the
// obstacles and the others, held where the tuple puts them: a 3-D C-space approximated by exact
// slices and lines, as one robot's. Two subspaces (i, t) and (j, t) of one tuple meet at t
// itself, so a tuple joins the subspaces of all its robots.
//
// With two robots, any fixing of one meets any fixing of the other (the pair of their poses);
// with three or more, two tuples share a subspace only where they agree on all robots but one,
// which independent random tuples never do. So tuples grow from cells already reached, as RRT
// and EST grow trees over exact cells: a point p in a reached cell of subspace (i, t) makes the
// tuple t' (t with robot i at p), reached too, and a subspace of t' for another robot carries
// the growth on. Start and goal are two such trees; they meet when a tuple agrees with the
// other side's on all robots but one. To make that happen, each new subspace is also tried
// greedily: if its robot can reach its pose on the other side (its goal, for a tuple reached
// from the start), it is put there and the next robot is tried in turn, until all are there
// (the tuple joins the other side's subspaces) or one cannot move. A robot that must make way
// (wait in a niche while the others pass) is what the random growth provides.
//
// Probabilistic completeness, informally: every reached cell keeps a positive chance of
// producing tuples anywhere in it, the angle sets double every round (as with two robots), and
// the lines of each subspace are uniform, so the reachable tuples' subspaces cover any
// robust path's neighbourhood with probability going to 1; each step is exact, and every path
// returned is certified.
#include <algorithm>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "planner/HeldRobotPlanner.h"

namespace mms {

struct KRobotSettings : HeldRobotSettings {
  // More angles than two robots' (TwoRobotSettings): runs that needed more tuples waited for
  // the angles. The 2k root subspaces' growing lines cost more than they found here
  // (docs/planner.md).
  KRobotSettings() {
    nTheta = 16;
    growRootLines = false;
  }
  size_t nTuples = 8;  // tuples grown in the first round; doubles every round, with the angles
  // Share of growth points drawn near a vertex of their cell (a robot tucked into a corner, out
  // of the others' way); the rest uniform in the cell.
  double cornerShare = 0.5;
  // A growth point is the first of up to this many (each in a cell drawn anew) at which its
  // robot cuts no passage of any other robot at its start angle (one overlay per robot), else
  // the last.
  size_t screenCandidates = 16;
};

struct KRobotStats : HeldRobotStats {
  size_t tuples = 0, greedyMoves = 0;
};

using KRobotResult = HeldRobotResult<KRobotStats>;

/// The hold policy for k robots: tuples grown from reached cells, and greedy moves to the
/// other side.
class KRobotPlanner : public HeldRobotPlanner {
 public:
  explicit KRobotPlanner(const Scene& scene, KRobotSettings settings = {});
  ~KRobotPlanner() override;

  KRobotResult solve(const Termination& stop,
                     const std::function<void(const KRobotStats&)>& progress = {});

 private:
  using Tuple = std::vector<Placement>;

  // The hold policy (HeldRobotPlanner)
  bool placeEnds(const Termination& stop) override;
  void endsPlaced(const Termination& stop) override;
  bool growing() override;
  bool roundComplete() override { return grown_ >= grownAtRoundStart_ + target_; }
  double roundShare() override {
    return target_ == 0 ? 1 : std::min(1.0, double(grown_ - grownAtRoundStart_) / double(target_));
  }
  void growStep(const Termination& stop) override;
  void nextTargets(bool fixingsGrow) override;

  size_t subspaceFor(size_t moving, const Tuple& t, const Termination& stop);
  std::vector<std::pair<size_t, Pose>> heldBy(size_t moving, const Tuple& t) const;
  long existing(size_t moving, const Tuple& t) const;
  void join(const Tuple& t);
  std::optional<std::pair<size_t, Placement>> growthPoint();
  void towardsOtherSide(Tuple t, bool fromStart, const Termination& stop);
  bool anyReached();

  KRobotSettings hold_;
  KRobotStats stats_;
  std::vector<Tuple> tuples_;  // tuples_[i]: the tuple subspaces_[i] was made for
  Tuple start_, goal_;
  size_t grown_ = 0;  // growth steps taken (a step may fail to draw a point)
  size_t grownAtRoundStart_ = 0;
  size_t target_ = 0;  // growth steps this round
};

}  // namespace mms
