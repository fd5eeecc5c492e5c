#include "assembly/Disassembly.h"

#include <algorithm>
#include <cmath>
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
// angle that lie outside the box and in the same cell as its start, so reachable when alone.
// Best first: farthest from the box, so parked parts stay out of the way of the later ones.
std::vector<Pose> DisassemblyPlanner::targetsFor(const Scene& step, const CollisionChecker& checker,
                                                 size_t robot, size_t count) const {
  const Scene contact = withContactShapes(step, checker);
  const SliceWorld world(contact, robot);
  const Pose start = step.robots[robot].start;
  const Slice free(world, exact::rationalAngleNear(start.theta, 30));
  const int startCell = free.locate({start.x, start.y});
  if (startCell < 0) return {};
  const Ring boxRing = {{box_.xmin, box_.ymin},
                        {box_.xmax, box_.ymin},
                        {box_.xmax, box_.ymax},
                        {box_.xmin, box_.ymax}};
  const Slice outside(free, {MovedShape{0, 0, boxRing, {0, 0}}});  // the box as one more obstacle
  Random rng(attemptSeed_);
  std::vector<std::pair<double, Pose>> found;
  for (size_t c = 0; c < outside.fscCount(); ++c)
    for (int k = 0; k < 8; ++k) {
      const auto p = samplePointInCell(outside, c, rng, 32);
      if (!p || free.locate(*p) != startCell) continue;
      const Pose q{p->x, p->y, start.theta};
      found.push_back({boundingBox(placedRing(step.robots[robot].shape, q)).distance(box_), q});
    }
  std::sort(found.begin(), found.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<Pose> out;
  for (size_t i = 0; i < found.size() && out.size() < count; ++i) out.push_back(found[i].second);
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

bool DisassemblyPlanner::trySingle(size_t part, const Termination& stop, DisassemblyResult& out) {
  Stopwatch watch;
  Scene step = stepScene({part});
  const Robot& original = scene_.robots[part];
  Pose goal = original.goal;
  if (samePose(original.start, original.goal)) {
    const auto targets = targetsFor(step, CollisionChecker(step), 0, 1);
    if (targets.empty()) return false;  // exact for a translating part: it cannot leave alone
    goal = targets.front();
  }
  step.robots[0].goal = goal;
  ++out.attempts;
  OneRobotSettings settings;
  settings.seed = attemptSeed_++;
  OneRobotPlanner planner(step, 0, settings);
  const OneRobotResult r = planner.solve(pose_[part], goal, stop);
  if (r.status != PlanStatus::Found) return false;
  record({{part}, {part}, std::move(step), r.waypoints, watch.seconds()}, out);
  return true;
}

// Parts a and b move together; `returning` is -1 (both leave) or the index (0: a, 1: b) of a
// helper that makes room and goes back to where it was.
bool DisassemblyPlanner::tryPair(size_t a, size_t b, int returning, size_t rounds,
                                 const Termination& stop, DisassemblyResult& out) {
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
    if (goals[m].empty()) return false;  // it cannot leave even with the other one gone
  }
  bool paired = false;
  for (size_t i = 0; i < goals[0].size() && !paired; ++i)
    for (size_t j = 0; j < goals[1].size() && !paired; ++j)
      if (checker.robotsDisjoint(0, goals[0][i], 1, goals[1][j])) {
        step.robots[0].goal = goals[0][i];
        step.robots[1].goal = goals[1][j];
        paired = true;
      }
  if (!paired || stop()) return false;
  ++out.attempts;
  TwoRobotSettings settings;
  settings.seed = attemptSeed_++;
  settings.maxRounds = rounds;
  TwoRobotPlanner planner(step, settings);
  const TwoRobotResult r = planner.solve(Termination(stop.secondsLeft(), stop.cancelFlag()));
  if (r.status != PlanStatus::Found) return false;
  std::vector<size_t> removed;
  if (returning != 0) removed.push_back(a);
  if (returning != 1) removed.push_back(b);
  record({{a, b}, removed, std::move(step), r.waypoints, watch.seconds()}, out);
  return true;
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
    bool found = false;
    for (const size_t p : left)
      if (!stop() && trySingle(p,
                               Termination(std::min(settings_.singleSeconds, stop.secondsLeft()),
                                           stop.cancelFlag()),
                               out)) {
        found = true;
        break;
      }
    // Pairs under a budget that doubles every pass: a hard pair is not given up early.
    for (size_t rounds = settings_.firstPairRounds;
         !found && settings_.pairs && left.size() >= 2 && !stop(); ++rounds) {
      for (size_t i = 0; i < left.size() && !found; ++i)
        for (size_t j = i + 1; j < left.size() && !found; ++j)
          for (const int returning : {-1, 0, 1})
            if (!stop() && tryPair(left[i], left[j], returning, rounds, stop, out)) {
              found = true;
              break;
            }
    }
    if (!found) {
      out.stuck = left;
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
