#include "planner/TwoRobotPlanner.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>
#include <utility>

#include "geometry/PolygonOps.h"

namespace mms {

TwoRobotPlanner::TwoRobotPlanner(const Scene& scene, TwoRobotSettings settings)
    : HeldRobotPlanner(scene, settings, stats_),
      hold_(settings),
      sampler_(std::make_unique<MixedFixings>(settings.expandShare, settings.connectShare,
                                              settings.connectSteps, settings.cornerShare,
                                              settings.cornerCandidates)),
      target_(settings.nFixings) {}

TwoRobotPlanner::~TwoRobotPlanner() = default;

TwoRobotResult TwoRobotPlanner::solve(const Termination& stop,
                                      const std::function<void(const TwoRobotStats&)>& progress) {
  return solveReporting(stop, progress, stats_);
}

// Each robot held at its start and at its goal; robot 0 moves from the subspace holding robot 1
// at its start (index 1) to the one holding it at its goal (index 3).
bool TwoRobotPlanner::placeEnds(const Termination& stop) {
  std::array<Fixing, 2> start, goal;
  for (size_t r = 0; r < 2; ++r) {
    start[r] = {endPlacement(r, true), r, -1};
    goal[r] = {endPlacement(r, false), r, -1};
  }
  for (const Fixing& f : {start[0], start[1], goal[0], goal[1]}) addFixing(f, stop);
  fixingsAtRoundStart_ = stats_.fixings;
  const long from = nodeFor(*subspaces_[1], start[0]), to = nodeFor(*subspaces_[3], goal[0]);
  if (from < 0 || to < 0) return false;
  from_ = from;
  to_ = to;
  return true;
}

// The robots take turns, so both families grow before start and goal connect.
bool TwoRobotPlanner::wants(size_t r) const {
  return !exhausted_[r] && stats_.fixings[r] < target_ + 2;
}

bool TwoRobotPlanner::roundComplete() {
  return stats_.fixings[0] >= target_ + 2 && stats_.fixings[1] >= target_ + 2;
}

// Each robot's share of its fixings to add this round, in the mean.
double TwoRobotPlanner::roundShare() {
  double share = 0;
  for (size_t r = 0; r < 2; ++r) {
    const size_t from = fixingsAtRoundStart_[r], to = target_ + 2;
    share += to <= from ? 1 : std::min(1.0, double(stats_.fixings[r] - from) / double(to - from));
  }
  return share / 2;
}

void TwoRobotPlanner::growStep(const Termination& stop) {
  for (size_t r = 0; r < 2 && !stop(); ++r) {
    if (!wants(r)) continue;
    if (!sampler_->grow(r, *this, stop)) exhausted_[r] = true;
    sliceNarrowArcsIfDisconnected();
  }
}

void TwoRobotPlanner::nextTargets(bool fixingsGrow) {
  fixingsAtRoundStart_ = stats_.fixings;
  if (fixingsGrow) target_ *= 2;
}

void TwoRobotPlanner::roundGrown(const Termination& stop) {
  for (auto& c : compounds_) addCompoundLines(*c, c->lineCount(), stop);
}

void TwoRobotPlanner::anglesAdded(size_t robot, size_t firstAngle, const Termination& stop) {
  for (auto& c : compounds_)
    if (robot == c->frame().carrier)
      for (size_t k = firstAngle; k < base_[robot].size() && !stop(); ++k)
        c->addSlice(base_[robot][k], *worlds_[c->frame().attached]);
}

// A new subspace in which the other robot moves, joined to the subspaces of the other family
// at the pair of their held poses.
size_t TwoRobotPlanner::addFixing(const Fixing& held, const Termination& stop) {
  fixings_.push_back(held);
  ++stats_.fixings[held.robot];
  auto join = [&](Subspace& sub) {
    for (const size_t j : crossCandidates(held)) {
      // Both fixings are free among the obstacles; the pair meets where the robots are disjoint.
      if (!checker_.robotsDisjoint(held.robot, held.pose, fixings_[j].robot, fixings_[j].pose))
        continue;
      const long here = nodeFor(sub, fixings_[j], true);
      if (here < 0) continue;
      const long there = nodeFor(*subspaces_[j], held, true);
      if (there < 0) continue;
      roadmap_.addEdge(size_t(here), size_t(there));
      ++stats_.crossEdges;
    }
  };
  return addSubspace(1 - held.robot, {{held.robot, held.pose}}, stop, join);
}

namespace {
bool sameRelativePose(const CompoundFrame& f, const CompoundFrame& g) {
  return std::hypot(f.offset.x - g.offset.x, f.offset.y - g.offset.y) <=
             1e-9 * (1 + std::hypot(f.offset.x, f.offset.y)) &&
         std::abs(std::remainder(f.dtheta - g.dtheta, 2 * M_PI)) <= 1e-9;
}
}  // namespace

// A pair that starts and ends close together (a part held in a gripper, a robot pushing
// another) moves as one rigid body: one compound subspace per relative pose of its start and
// goal (one if they agree). Each has lines at robot 0's start and goal positions; they meet the
// start and goal arcs at the start and goal configurations themselves. Where the relative
// poses differ, robot 1 changes its hold in the subspaces holding robot 0 at its start or goal:
// a line there at robot 1's position in the other relative pose meets the other compound. Pairs
// apart at either end build none: they pay nothing.
void TwoRobotPlanner::addCompound(const Termination& stop) {
  if (!hold_.coupled || translates_[0] || translates_[1]) return;
  const Robot &a = scene_.robots[0], &b = scene_.robots[1];
  const double reach = 0.25 * std::min(radius(a.shape), radius(b.shape));
  if (checker_.robotsDistance(0, a.start, 1, b.start) > reach ||
      checker_.robotsDistance(0, a.goal, 1, b.goal) > reach)
    return;
  std::vector<CompoundFrame> frames{CompoundFrame::between(a.start, b.start)};
  if (const CompoundFrame g = CompoundFrame::between(a.goal, b.goal);
      !sameRelativePose(frames[0], g))
    frames.push_back(g);
  for (const CompoundFrame& f : frames) {
    if (stop()) return;
    compounds_.push_back(std::make_unique<CompoundSubspace>(
        CompoundSubspace::kFirstGroup + uint32_t(compounds_.size()), contactScene_, checker_, f,
        roadmap_, stats_.compound));
    CompoundSubspace& c = *compounds_.back();
    for (const Slice& base : base_[0]) c.addSlice(base, *worlds_[1]);
    // Subspaces 0 and 2 hold robot 0 at its start and goal; 1 and 3 robot 1.
    for (const auto& [carrier, held, end] :
         {std::tuple{a.start, size_t(0), from_}, std::tuple{a.goal, size_t(2), to_}}) {
      const uint32_t line = c.addLine({carrier.x, carrier.y});
      roadmap_.join(line, roadmap_.graph().node(size_t(end)).manifold);
      const Pose other = f.attachedPose(carrier);
      const Pose own = held == 0 ? b.start : b.goal;
      if (std::hypot(other.x - own.x, other.y - own.y) >
          1e-9 * (1 + std::abs(own.x) + std::abs(own.y))) {
        const size_t l = subspaces_[held]->addLine({other.x, other.y});
        roadmap_.join(subspaces_[held]->lineId(l), line);
      }
    }
    addCompoundLines(c, settings_.nLines, stop);
  }
}

// Half the compound's lines in its slices' cells drawn uniformly among the cells (the compound
// turns where its cells are small: a chamber just larger than the pair), half as a subspace's.
void TwoRobotPlanner::addCompoundLines(CompoundSubspace& c, size_t count, const Termination& stop) {
  for (size_t i = 0; i < count && !stop(); ++i) {
    std::optional<Vec2> p;
    if (rng_.uniform() < 0.5) p = c.pointInCell(rng_);
    c.addLine(p ? *p : linePoint(c.frame().carrier));
  }
}

}  // namespace mms
