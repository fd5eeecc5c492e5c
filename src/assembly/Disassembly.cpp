#include "assembly/Disassembly.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "check/PathChecker.h"
#include "io/PathIO.h"
#include "manifolds/CellSampling.h"
#include "planner/OneRobotPlanner.h"
#include "planner/TwoRobotPlanner.h"

namespace mms {

namespace {

Box obstaclesBox(const Scene& scene) {
  Box b = boundingBox(scene.obstacles.at(0));
  for (const Ring& o : scene.obstacles) {
    const Box c = boundingBox(o);
    b = {std::min(b.xmin, c.xmin), std::min(b.ymin, c.ymin), std::max(b.xmax, c.xmax),
         std::max(b.ymax, c.ymax)};
  }
  return b;
}

bool samePose(const Pose& a, const Pose& b) {
  return a.x == b.x && a.y == b.y && a.theta == b.theta;
}

}  // namespace

DisassemblyPlanner::DisassemblyPlanner(const Scene& scene, DisassemblySettings settings)
    : scene_(scene), settings_(settings), attemptSeed_(settings.seed) {
  if (scene_.obstacles.empty())
    throw std::invalid_argument("the scene has no obstacles: there is no static part");
  box_ = obstaclesBox(scene_);
  for (const Robot& r : scene_.robots) pose_.push_back(r.start);
  done_.assign(scene_.robots.size(), false);
}

// The problem of one step: the moving parts as robots from where they are, every other part
// (still inside or parked outside) as an obstacle where it is.
Scene DisassemblyPlanner::stepScene(const std::vector<size_t>& moving) const {
  Scene s;
  s.name = scene_.name.empty() ? "step" : scene_.name + "-step";
  s.bounds = scene_.bounds;
  s.obstacles = scene_.obstacles;
  for (size_t i = 0; i < scene_.robots.size(); ++i)
    if (std::find(moving.begin(), moving.end(), i) == moving.end())
      s.obstacles.push_back(placedRing(scene_.robots[i].shape, pose_[i]));
  for (const size_t i : moving) {
    Robot r = scene_.robots[i];
    r.start = r.goal = pose_[i];
    s.robots.push_back(std::move(r));
  }
  return s;
}

// Where robot `robot` of a step may go to leave the static part's box, given the step's
// obstacles only (the other moving part is ignored): points of the exact free space at its
// angle that lie outside the box. A translating part can reach only those in its start's cell;
// a rigid one may turn on its way, so any will do, those in its start's cell first. Then
// farthest from the box first, so parked parts stay out of the way of the later ones.
std::vector<Pose> DisassemblyPlanner::targetsFor(const Scene& step, const CollisionChecker& checker,
                                                 size_t robot, size_t count) const {
  const Scene contact = withContactShapes(step, checker);
  const SliceWorld world(contact, robot);
  const Pose start = step.robots[robot].start;
  const bool rigid = step.robots[robot].motion == Motion::Rigid;
  const Slice free(world, exact::rationalAngleNear(start.theta, 30));
  const int startCell = free.locate({start.x, start.y});
  if (startCell < 0) return {};
  const Ring boxRing = {{box_.xmin, box_.ymin},
                        {box_.xmax, box_.ymin},
                        {box_.xmax, box_.ymax},
                        {box_.xmin, box_.ymax}};
  const Slice outside(free, {MovedShape{0, 0, boxRing, {0, 0}}});  // the box as one more obstacle
  Random rng(attemptSeed_);
  struct Found {
    bool startCell;
    double distance;
    Pose pose;
  };
  std::vector<Found> found;
  for (size_t c = 0; c < outside.fscCount(); ++c)
    for (int k = 0; k < 8; ++k) {
      const auto p = samplePointInCell(outside, c, rng, 32);
      if (!p) continue;
      const bool inStartCell = free.locate(*p) == startCell;
      if (!inStartCell && !rigid) continue;
      const Pose q{p->x, p->y, start.theta};
      found.push_back(
          {inStartCell, boundingBox(placedRing(step.robots[robot].shape, q)).distance(box_), q});
    }
  std::sort(found.begin(), found.end(), [](const Found& a, const Found& b) {
    return a.startCell != b.startCell ? a.startCell : a.distance > b.distance;
  });
  std::vector<Pose> out;
  for (size_t i = 0; i < found.size() && out.size() < count; ++i) out.push_back(found[i].pose);
  return out;
}

void DisassemblyPlanner::record(DisassemblyStep step, DisassemblyResult& out) {
  const Config& last = step.waypoints.back();
  for (size_t k = 1; k < step.waypoints.size(); ++k) {
    Config q = path_.back();
    for (size_t m = 0; m < step.parts.size(); ++m) {
      const Pose p = poseOf(step.waypoints[k], m);
      q[3 * step.parts[m]] = p.x, q[3 * step.parts[m] + 1] = p.y,
            q[3 * step.parts[m] + 2] = p.theta;
    }
    path_.push_back(std::move(q));
  }
  for (size_t m = 0; m < step.parts.size(); ++m) pose_[step.parts[m]] = poseOf(last, m);
  for (const size_t i : step.removed) done_[i] = true;
  out.steps.push_back(std::move(step));
}

DisassemblyPlanner::Attempt DisassemblyPlanner::trySingle(size_t part, size_t rounds,
                                                          const Termination& stop,
                                                          DisassemblyResult& out) {
  Stopwatch watch;
  Scene step = stepScene({part});
  const Robot& original = scene_.robots[part];
  const bool rigid = original.motion == Motion::Rigid;
  Pose goal = original.goal;
  if (samePose(original.start, original.goal)) {
    const auto targets = targetsFor(step, CollisionChecker(step), 0, 1);
    if (targets.empty()) {
      reasons_.push_back(original.name + (rigid ? ": no free place outside the static part's box "
                                                  "within the bounds at its angle"
                                                : ": cannot leave alone (its exact free space)"));
      return Attempt::Never;
    }
    goal = targets.front();
  }
  step.robots[0].goal = goal;
  ++out.attempts;
  OneRobotSettings settings;
  settings.seed = attemptSeed_++;
  settings.maxRounds = rounds;
  OneRobotPlanner planner(step, 0, settings);
  const OneRobotResult r = planner.solve(pose_[part], goal, stop);
  if (r.status == PlanStatus::Found) {
    record({{part}, {part}, std::move(step), r.waypoints, watch.seconds()}, out);
    return Attempt::Step;
  }
  // A translating part's free space is one slice: no path is a proof.
  if (!rigid || !r.stats.noPath.empty()) {
    reasons_.push_back(original.name + ": cannot leave alone (" +
                       (rigid ? r.stats.noPath : std::string("its exact free space")) + ")");
    return Attempt::Never;
  }
  singleRounds_ = std::max(singleRounds_, rounds);
  return Attempt::NotYet;
}

// Parts a and b move together; `returning` is -1 (both leave) or the index (0: a, 1: b) of a
// helper that makes room and goes back to where it was.
DisassemblyPlanner::Attempt DisassemblyPlanner::tryPair(size_t a, size_t b, int returning,
                                                        size_t rounds, const Termination& stop,
                                                        DisassemblyResult& out) {
  Stopwatch watch;
  Scene step = stepScene({a, b});
  const CollisionChecker checker(step);
  std::vector<std::vector<Pose>> goals(2);
  for (size_t m = 0; m < 2; ++m) {
    const Robot& original = scene_.robots[m == 0 ? a : b];
    if (int(m) == returning)
      goals[m] = {step.robots[m].start};
    else if (!samePose(original.start, original.goal))
      goals[m] = {original.goal};
    else
      goals[m] = targetsFor(step, checker, m, 6);
    if (goals[m].empty()) return Attempt::Never;  // it cannot leave even with the other one gone
  }
  bool paired = false;
  for (size_t i = 0; i < goals[0].size() && !paired; ++i)
    for (size_t j = 0; j < goals[1].size() && !paired; ++j)
      if (checker.robotsDisjoint(0, goals[0][i], 1, goals[1][j])) {
        step.robots[0].goal = goals[0][i];
        step.robots[1].goal = goals[1][j];
        paired = true;
      }
  if (!paired || stop()) return Attempt::NotYet;
  ++out.attempts;
  TwoRobotSettings settings;
  settings.seed = attemptSeed_++;
  settings.maxRounds = rounds;
  TwoRobotPlanner planner(step, settings);
  const TwoRobotResult r = planner.solve(Termination(stop.secondsLeft(), stop.cancelFlag()));
  pairRounds_ = std::max(pairRounds_, rounds);
  if (r.status != PlanStatus::Found) return Attempt::NotYet;
  std::vector<size_t> removed;
  if (returning != 0) removed.push_back(a);
  if (returning != 1) removed.push_back(b);
  record({{a, b}, removed, std::move(step), r.waypoints, watch.seconds()}, out);
  return Attempt::Step;
}

// Each part alone, then (three hands) each pair, at the budgets of pass `pass`. A part whose
// attempt alone proved it cannot leave is not tried alone again until a step moves another.
DisassemblyPlanner::Attempt DisassemblyPlanner::tryPass(const std::vector<size_t>& left,
                                                        size_t pass, const Termination& stop,
                                                        DisassemblyResult& out) {
  bool more = false;  // whether a later pass, with larger budgets, could find a step
  for (const size_t p : left) {
    if (neverAlone_[p] || stop()) continue;
    const Attempt a = trySingle(p, settings_.firstSingleRounds + pass, stop, out);
    if (a == Attempt::Step) return a;
    if (a == Attempt::Never) neverAlone_[p] = true;
    more = more || a == Attempt::NotYet;
  }
  if (!settings_.pairs) return more ? Attempt::NotYet : Attempt::Never;
  for (size_t i = 0; i < left.size(); ++i)
    for (size_t j = i + 1; j < left.size(); ++j)
      for (const int returning : {-1, 0, 1}) {
        if (stop()) return Attempt::NotYet;
        const Attempt a =
            tryPair(left[i], left[j], returning, settings_.firstPairRounds + pass, stop, out);
        if (a == Attempt::Step) return a;
        more = more || a == Attempt::NotYet;
      }
  return more ? Attempt::NotYet : Attempt::Never;
}

// "A: cannot leave alone (its exact free space)" where that was proved; otherwise what was
// tried and for how long.
std::string DisassemblyPlanner::whyStuck(const std::vector<size_t>& left, size_t passes,
                                         bool proved, const DisassemblyResult& out,
                                         const Termination& stop) const {
  std::string proofs;
  for (const std::string& r : reasons_) proofs += (proofs.empty() ? "" : "; ") + r;
  if (proved)
    return proofs + (settings_.pairs && left.size() >= 2
                         ? "; no two can leave together either, each alone having no place to go"
                         : (left.size() >= 2 ? "; pairs not tried (one part at a time)" : ""));
  char text[256];
  std::snprintf(text, sizeof text, "no step found in %.3g s%s: %zu passes, %zu planner runs",
                out.seconds, stop.cancelled() ? "" : " (the time limit)", passes, out.attempts);
  std::string why = text;
  if (singleRounds_)
    why += ", a rigid part alone up to " + std::to_string(singleRounds_) +
           " rounds of the one-robot MMS";
  if (pairRounds_)
    why += ", two together up to " + std::to_string(pairRounds_) + " rounds of the two-robot MMS";
  return why + (proofs.empty() ? "" : "; " + proofs);
}

DisassemblyResult DisassemblyPlanner::solve(
    const Termination& stop, const std::function<void(size_t, const DisassemblyStep&)>& progress) {
  Stopwatch clock;
  DisassemblyResult out;
  path_ = {startConfig(scene_)};
  while (!stop()) {
    std::vector<size_t> left;
    for (size_t i = 0; i < done_.size(); ++i)
      if (!done_[i]) left.push_back(i);
    if (left.empty()) break;
    // Passes under budgets that double every pass, so a hard part or pair is not given up
    // early, until a step, the limit or a proof that no pass can find one.
    neverAlone_.assign(scene_.robots.size(), false);
    singleRounds_ = pairRounds_ = 0;
    Attempt a = Attempt::NotYet;
    size_t passes = 0;
    reasons_.clear();
    while (a == Attempt::NotYet && !stop()) a = tryPass(left, passes++, stop, out);
    if (a != Attempt::Step) {
      out.stuck = left;
      out.seconds = clock.seconds();
      out.stuckBecause = whyStuck(left, passes, a == Attempt::Never, out, stop);
      break;
    }
    if (progress) progress(out.steps.size() - 1, out.steps.back());
  }
  if (out.stuck.empty())
    for (size_t i = 0; i < done_.size(); ++i)
      if (!done_[i]) out.stuck.push_back(i);
  out.finalScene = scene_;
  for (size_t i = 0; i < pose_.size(); ++i) out.finalScene.robots[i].goal = pose_[i];
  out.path = path_;
  // Each step was certified in its own scene; the whole motion is certified once more.
  const CollisionChecker checker(out.finalScene);
  if (const auto c = checkPath(out.finalScene, checker, out.path); !c.ok)
    throw std::logic_error("the combined disassembly path failed certification: " + c.reason);
  out.seconds = clock.seconds();
  return out;
}

}  // namespace mms
