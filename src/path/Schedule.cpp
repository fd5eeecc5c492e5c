#include "path/Schedule.h"

#include <algorithm>
#include <cmath>

#include "check/PathChecker.h"
#include "geometry/PolygonOps.h"

namespace mms {

namespace {

bool samePose(const Pose& a, const Pose& b) {
  return a.x == b.x && a.y == b.y && a.theta == b.theta;
}

Pose between(const Pose& a, const Pose& b, double s) {
  return {a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), a.theta + s * (b.theta - a.theta)};
}

// A piece of a segment of the path, from fraction s0 to s1 of it, and the robots it moves.
struct Action {
  size_t segment = 0;  // from waypoint `segment` to the next
  double s0 = 0, s1 = 1;
  std::vector<size_t> robots;  // those that move in it
  double duration = 0;         // its slowest robot's cost
  double start = 0;            // when it begins in the schedule
};

// The segments that move a robot, in the path's order, each cut into pieces along which its
// slowest robot moves at most its own diameter: a robot that follows another through a
// corridor then waits only for the piece ahead of it, not for the other's whole segment.
std::vector<Action> actionsOf(const CollisionChecker& checker, const std::vector<Config>& w) {
  std::vector<Action> out;
  const size_t robots = w.empty() ? 0 : w[0].size() / 3;
  for (size_t k = 0; k + 1 < w.size(); ++k) {
    Action a;
    a.segment = k;
    double piece = 0;  // the largest moving robot's diameter
    for (size_t i = 0; i < robots; ++i) {
      const Pose p = poseOf(w[k], i), q = poseOf(w[k + 1], i);
      if (samePose(p, q)) continue;
      a.robots.push_back(i);
      a.duration = std::max(a.duration, poseCost(checker, i, p, q));
      piece = std::max(piece, 2 * checker.radius(i));
    }
    if (a.robots.empty()) continue;
    const size_t pieces =
        piece > 0 ? size_t(std::clamp(std::ceil(a.duration / piece), 1.0, 1e4)) : 1;
    const double whole = a.duration;
    for (size_t p = 0; p < pieces; ++p) {
      a.s0 = double(p) / double(pieces);
      a.s1 = p + 1 == pieces ? 1.0 : double(p + 1) / double(pieces);
      a.duration = whole * (a.s1 - a.s0);
      out.push_back(a);
    }
  }
  return out;
}

Pose poseAt(const std::vector<Config>& w, const Action& a, size_t robot, double s) {
  return between(poseOf(w[a.segment], robot), poseOf(w[a.segment + 1], robot), s);
}

// One robot's part of an action: its reference point's segment, and the robot's radius about
// it. Its box bounds the capsule.
struct Sweep {
  size_t action;
  Vec2 from, to;
  double radius;
  Box box;
};

std::vector<Sweep> sweepsOf(const CollisionChecker& checker, const std::vector<Config>& w,
                            const std::vector<Action>& actions) {
  std::vector<Sweep> out;
  for (size_t a = 0; a < actions.size(); ++a)
    for (const size_t i : actions[a].robots) {
      const Pose p = poseAt(w, actions[a], i, actions[a].s0),
                 q = poseAt(w, actions[a], i, actions[a].s1);
      const double r = checker.radius(i);
      out.push_back({a,
                     {p.x, p.y},
                     {q.x, q.y},
                     r,
                     {std::min(p.x, q.x) - r, std::min(p.y, q.y) - r, std::max(p.x, q.x) + r,
                      std::max(p.y, q.y) + r}});
    }
  return out;
}

// Of the actions of one robot that an action waits for, the last suffices: the robot's own come
// before it. So an action waits for at most one per robot (a robot turning on the spot in many
// short segments would otherwise make every pair of them a dependency).
void keepTheLastOfEachRobot(const std::vector<Action>& actions, size_t robots,
                            std::vector<std::vector<size_t>>& waitsFor) {
  std::vector<long> lastOf(robots, -1);
  for (auto& v : waitsFor) {
    for (const size_t e : v)
      for (const size_t i : actions[e].robots) lastOf[i] = std::max(lastOf[i], long(e));
    std::vector<size_t> kept;
    for (const size_t e : v)
      for (const size_t i : actions[e].robots)
        if (lastOf[i] == long(e)) kept.push_back(e);
    for (const size_t e : v)
      for (const size_t i : actions[e].robots) lastOf[i] = -1;
    std::sort(kept.begin(), kept.end());
    kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
    v = std::move(kept);
  }
}

// For each action, the earlier actions it waits for: those that share a robot (the last such
// one suffices, its own are before it) and those whose sweeps may meet its own. A sweep along
// x finds the pairs whose boxes overlap.
std::vector<std::vector<size_t>> dependencies(const CollisionChecker& checker,
                                              const std::vector<Config>& w,
                                              const std::vector<Action>& actions) {
  std::vector<std::vector<size_t>> waitsFor(actions.size());
  const size_t robots = w[0].size() / 3;
  std::vector<long> last(robots, -1);
  for (size_t a = 0; a < actions.size(); ++a)
    for (const size_t i : actions[a].robots) {
      if (last[i] >= 0) waitsFor[a].push_back(size_t(last[i]));
      last[i] = long(a);
    }
  std::vector<Sweep> sweeps = sweepsOf(checker, w, actions);
  std::sort(sweeps.begin(), sweeps.end(),
            [](const Sweep& s, const Sweep& t) { return s.box.xmin < t.box.xmin; });
  std::vector<size_t> open;  // sweeps whose box may still overlap the next ones in x
  for (size_t k = 0; k < sweeps.size(); ++k) {
    const Sweep& s = sweeps[k];
    std::erase_if(open, [&](size_t j) { return sweeps[j].box.xmax < s.box.xmin; });
    for (const size_t j : open) {
      const Sweep& t = sweeps[j];
      if (t.action == s.action || t.box.ymin > s.box.ymax || s.box.ymin > t.box.ymax) continue;
      if (segmentSegmentDistance(s.from, s.to, t.from, t.to) > s.radius + t.radius) continue;
      waitsFor[std::max(s.action, t.action)].push_back(std::min(s.action, t.action));
    }
    open.push_back(k);
  }
  keepTheLastOfEachRobot(actions, robots, waitsFor);
  return waitsFor;
}

// Every robot's pose at time t of the schedule: within its action, or where its last one left
// it. `next[i]`: robot i's first action not yet over at t (advanced as t grows).
Config posesAt(double t, const std::vector<Config>& w, const std::vector<Action>& actions,
               const std::vector<std::vector<size_t>>& byRobot, std::vector<size_t>& next) {
  Config q = w.front();
  for (size_t i = 0; i < byRobot.size(); ++i) {
    const std::vector<size_t>& mine = byRobot[i];
    size_t& n = next[i];
    while (n < mine.size() && actions[mine[n]].start + actions[mine[n]].duration <= t) ++n;
    if (n > 0) setPose(q, i, poseAt(w, actions[mine[n - 1]], i, actions[mine[n - 1]].s1));
    if (n == mine.size()) continue;
    const Action& a = actions[mine[n]];
    if (t <= a.start) continue;  // waits where its last action left it
    setPose(q, i, poseAt(w, a, i, a.s0 + (a.s1 - a.s0) * (t - a.start) / a.duration));
  }
  return q;
}

// Whether every robot moves through `mid` (at time tm) at one velocity from `a` (ta) to `b`
// (tb): then the waypoint says nothing the segment from a to b does not.
bool passedThrough(const Config& a, double ta, const Config& mid, double tm, const Config& b,
                   double tb) {
  const double s = (tm - ta) / (tb - ta);
  for (size_t c = 0; c < mid.size(); ++c) {
    const double expected = a[c] + s * (b[c] - a[c]);
    if (std::abs(mid[c] - expected) > 1e-9 * (1 + std::abs(mid[c]))) return false;
  }
  return true;
}

}  // namespace

std::vector<Config> concurrentSchedule(const Scene& scene, const CollisionChecker& checker,
                                       const std::vector<Config>& waypoints, ScheduleStats* stats) {
  if (waypoints.size() < 2) return waypoints;
  std::vector<Action> actions = actionsOf(checker, waypoints);
  if (actions.empty()) return waypoints;
  const std::vector<std::vector<size_t>> waitsFor = dependencies(checker, waypoints, actions);
  // The path's order is a topological one: every action waits only for earlier ones.
  std::vector<double> times{0};
  double before = 0;
  for (size_t a = 0; a < actions.size(); ++a) {
    for (const size_t b : waitsFor[a])
      actions[a].start = std::max(actions[a].start, actions[b].start + actions[b].duration);
    times.push_back(actions[a].start);
    times.push_back(actions[a].start + actions[a].duration);
    before += actions[a].duration;
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  std::vector<std::vector<size_t>> byRobot(scene.robots.size());
  for (size_t a = 0; a < actions.size(); ++a)
    for (const size_t i : actions[a].robots) byRobot[i].push_back(a);
  // The poses at every time an action starts or ends, but where every robot moves on at one
  // velocity: a waypoint only where some robot starts, stops or changes its way.
  std::vector<size_t> next(scene.robots.size(), 0);
  std::vector<Config> out{waypoints.front()};
  std::vector<double> at{0};
  for (size_t k = 1; k < times.size(); ++k) {
    Config q = k + 1 == times.size() ? waypoints.back()  // exactly the end, whatever the rounding
                                     : posesAt(times[k], waypoints, actions, byRobot, next);
    if (out.size() >= 2 &&
        passedThrough(out[out.size() - 2], at[at.size() - 2], out.back(), at.back(), q, times[k]))
      out.back() = std::move(q), at.back() = times[k];
    else
      out.push_back(std::move(q)), at.push_back(times[k]);
  }
  if (stats) {
    stats->actions = actions.size();
    stats->dependencies = 0;
    for (const auto& v : waitsFor) stats->dependencies += v.size();
    stats->makespanBefore = before;
    stats->makespanAfter = times.back();
  }
  return out;
}

}  // namespace mms
