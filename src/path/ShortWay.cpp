#include "path/ShortWay.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "geometry/SpinPlace.h"
#include "manifolds/Pivot.h"

namespace mms::detail {

// A stretch in which a robot turns more than half a circle in all, turned the other way
// round. The rest of the path is the same motion shifted by a full turn, so only the stretch
// needs certifying. Turns split across waypoints and across moves at a fixed angle (an MMS
// path turns on lines and moves in slices) count as one: each window from the start of one
// run of turning segments to the end of another is a candidate, the largest saving first.
void ShortWay::turnShortWay(std::vector<Config>& w) {
  for (size_t i = 0; i < scene_.robots.size(); ++i)
    while (rigid(i) && !done() && rewindOnce(w, i)) ++s_.accepted;
}

std::vector<ShortWay::Run> ShortWay::turningRuns(const std::vector<Config>& w, size_t c) {
  std::vector<Run> runs;
  for (size_t k = 0; k + 1 < w.size(); ++k) {
    if (w[k + 1][c] == w[k][c]) continue;
    if (!runs.empty() && runs.back().second == k)
      runs.back().second = k + 1;
    else
      runs.emplace_back(k, k + 1);
  }
  return runs;
}

std::vector<ShortWay::Rewind> ShortWay::rewinds(const std::vector<Config>& w,
                                                const std::vector<Run>& runs, size_t c) {
  std::vector<double> turned{0};  // rotation up to each waypoint
  for (size_t k = 1; k < w.size(); ++k)
    turned.push_back(turned.back() + std::fabs(w[k][c] - w[k - 1][c]));
  std::vector<Rewind> out;
  for (size_t p = 0; p < runs.size(); ++p)
    for (size_t q = p; q < runs.size(); ++q) {
      const size_t from = runs[p].first, to = runs[q].second;
      const double net = w[to][c] - w[from][c], turns = -std::round(net / (2 * M_PI));
      const double saving = turned[to] - turned[from] - std::fabs(net + 2 * M_PI * turns);
      // Without a full turn to take back, only turning back and forth is saved.
      if (turns != 0 || saving >= kMinSaving) out.push_back({p, q, turns, saving});
    }
  std::stable_sort(out.begin(), out.end(), [](const Rewind& a, const Rewind& b) {
    return a.saving > b.saving + 1e-9 || (a.saving > b.saving - 1e-9 && a.q - a.p < b.q - b.p);
  });
  return out;
}

// The first candidate that certifies, taken; whether there was one. Where the runs' turns
// do not certify where they were made, a second pass moves a run whose turn changed to the
// nearest place where the robot spins in place (SpinPlace.h).
bool ShortWay::rewindOnce(std::vector<Config>& w, size_t robot) {
  const size_t c = 3 * robot + 2;
  const std::vector<Run> runs = turningRuns(w, c);
  const std::vector<double> cum = cumulativeCost(w);
  const std::vector<Rewind> candidates = rewinds(w, runs, c);
  spinPlaces_.clear();
  const bool taken = routing_ ? routedSpin(w, robot, runs, cum, candidates)
                              : rewindPass(w, robot, runs, cum, candidates, false) ||
                                    rewindPass(w, robot, runs, cum, candidates, true) ||
                                    holdThroughTurn(w, robot, cum);
  changed();
  return taken;
}

bool ShortWay::rewindPass(std::vector<Config>& w, size_t robot, const std::vector<Run>& runs,
                          const std::vector<double>& cum, const std::vector<Rewind>& candidates,
                          bool spin) {
  const size_t c = 3 * robot + 2;
  size_t tries = 0, considered = 0;
  for (const Rewind& r : candidates) {
    if (spin && r.turns == 0) continue;
    const size_t from = runs[r.p].first, to = runs[r.q].second;
    for (const Carrier& carrier : carriersOf(r, spin)) {
      if (!spin && (tries++ == kRewindTries || done())) return false;
      if (spin && (considered++ == kSpinCarriers || spinPlaces_.size() > kSpinPlaces)) return false;
      std::vector<Config> stretch(w.begin() + long(from), w.begin() + long(to) + 1);
      double before = 0, after = 0;
      for (size_t k = 1; k < stretch.size(); ++k) {
        stretch[k][c] = rewound(w, cum, runs, carrier, r, from + k, c);
        before += std::fabs(w[from + k][c] - w[from + k - 1][c]);
        after += std::fabs(stretch[k][c] - stretch[k - 1][c]);
      }
      if (after > before - 1e-6) continue;  // this carrier turns as much or more
      for (const auto& [moved, mirror] : spunRuns(carrier, spin)) {
        if (spin && (tries++ == kSpinTries || done())) return false;
        std::vector<Config> candidate =
            spin ? spunStretch(w, stretch, runs, moved, mirror, from, robot) : stretch;
        if (spin && pathCost(checker_, candidate) >= cum[to] - cum[from]) continue;
        // A rewound window changes the robot's angle alone; a spun one may insert poses.
        if (!certified(candidate, spin ? kEveryRobot : robot)) continue;
        takeWindow(w, from, to, candidate, c, r.turns);
        return true;
      }
    }
  }
  return false;
}

// A sampler's robot turns at every waypoint: one run, the whole path, which may wind a full
// turn more than the short way from its start angle to its goal's and not turn the other way
// as a whole where the clutter needs its angles. A stretch inside it that turns a full turn
// (the other way from what is to be taken out) can lose it instead, the robot all but holding
// its angle through the stretch (its turn scaled to what is left, as the rewinds' Scaled
// carrier does): those that save a full turn first, the shortest of them first (the least of
// the path changed), then those that save less. On open clutter's fresh seeds this took the
// needless full turn out of 22 of 26 first paths that had one, against 18 without it.
bool ShortWay::holdThroughTurn(std::vector<Config>& w, size_t robot,
                               const std::vector<double>& cum) {
  const size_t c = 3 * robot + 2;
  const Robot& r = scene_.robots[robot];
  const double shortest = std::remainder(r.goal.theta - r.start.theta, 2 * M_PI);
  const double extra = std::round((w.back()[c] - w.front()[c] - shortest) / (2 * M_PI));
  if (extra == 0) return false;
  struct Window {
    size_t from, to;
    double turns, saving, cost;
    size_t order;  // as found: the last tie-break
  };
  auto better = [](const Window& a, const Window& b) {
    return std::tie(b.saving, a.cost, a.order) < std::tie(a.saving, b.cost, b.order);
  };
  // Only the tries' worth of best windows is kept as they are found, and a window spans at
  // most kHoldSpan waypoints: a long path has a great many.
  std::vector<Window> windows;
  for (size_t i = 0; i + 1 < w.size(); ++i)
    for (size_t j = i + 1; j < std::min(w.size(), i + kHoldSpan + 1); ++j) {
      const double net = w[j][c] - w[i][c], turns = -std::round(net / (2 * M_PI));
      const double saving = std::fabs(net) - std::fabs(net + 2 * M_PI * turns);
      if (turns * extra >= 0 || std::fabs(turns) > std::fabs(extra) || saving <= kMinSaving)
        continue;
      windows.push_back(
          {i, j, turns, std::min(saving, 2 * M_PI), cum[j] - cum[i], i * w.size() + j});
      if (windows.size() == 2 * kRewindTries) {
        std::nth_element(windows.begin(), windows.begin() + kRewindTries, windows.end(), better);
        windows.resize(kRewindTries);
      }
    }
  std::sort(windows.begin(), windows.end(), better);
  size_t tries = 0;
  for (const Window& h : windows) {
    if (tries++ == kRewindTries || done()) return false;
    std::vector<Config> stretch(w.begin() + long(h.from), w.begin() + long(h.to) + 1);
    const double a = w[h.from][c], net = w[h.to][c] - a, target = net + 2 * M_PI * h.turns;
    for (size_t k = 1; k < stretch.size(); ++k)
      stretch[k][c] = a + target * (w[h.from + k][c] - a) / net;
    if (!certified(stretch, robot)) continue;
    takeWindow(w, h.from, h.to, stretch, c, h.turns);
    return true;
  }
  return false;
}

// Waypoints from..to replaced by a window turned the other way round: the rest of the path
// is the same motion, its angle (coordinate c) shifted by the full turns the window undid.
void ShortWay::takeWindow(std::vector<Config>& w, size_t from, size_t to,
                          const std::vector<Config>& window, size_t c, double turns) {
  for (size_t k = to + 1; k < w.size(); ++k) w[k][c] += 2 * M_PI * turns;
  w.erase(w.begin() + long(from), w.begin() + long(to) + 1);
  w.insert(w.begin() + long(from), window.begin(), window.end());
}

// A third pass, for the windows that save the most: the window's net turn made about the
// robot's spinning centre at a clear place near where it turned, the robot routed there at
// its angle before the window and on from there at its angle after it, through exact slices
// (HeldRoutes): a key that went down a slot bit last goes down bit first. The places are
// climbed to from where the window turned most, in that order: a sampler's key may turn most
// outside, where it cannot be routed on at its new angle.
bool ShortWay::routedSpin(std::vector<Config>& w, size_t robot, const std::vector<Run>& runs,
                          const std::vector<double>& cum, const std::vector<Rewind>& candidates) {
  if (!routes_.routes()) return false;
  const size_t c = 3 * robot + 2;
  size_t tried = 0;
  for (const Rewind& r : candidates) {
    if (r.saving < kRouteSaving || tried++ == kRouteWindows || done()) return false;
    const size_t from = runs[r.p].first, to = runs[r.q].second;
    for (const Vec2 at : placesToSpin(w, from, to, robot)) {
      // No route is shorter than straight to the place and on: the slices are not built
      // for a detour that would cost more than the window does.
      const SpinEnds ends = spinEnds(w, from, to, robot, r.turns, at);
      if (leastRoutedCost(ends, robot) >= cum[to] - cum[from]) continue;
      std::vector<Config> candidate = routedStretch(w[from], ends, robot, at);
      if (candidate.empty() || pathCost(checker_, candidate) >= cum[to] - cum[from] ||
          !certified(candidate))
        continue;
      takeWindow(w, from, to, candidate, c, r.turns);
      return true;
    }
  }
  return false;
}

ShortWay::SpinEnds ShortWay::spinEnds(const std::vector<Config>& w, size_t from, size_t to,
                                      size_t robot, double turns, Vec2 at) {
  SpinEnds e{poseOf(w[from], robot), {}, {}, poseOf(w[to], robot)};
  e.a = poseWithPointAt(spinCentre(robot), at, e.first.theta);
  e.b = poseWithPointAt(spinCentre(robot), at, e.last.theta + 2 * M_PI * turns);
  return e;
}

// What routedStretch costs at least: straight to the place, the turn, straight on at the
// turned angle (the window ends there; the rest of the path is shifted by the full turns).
double ShortWay::leastRoutedCost(const SpinEnds& e, size_t robot) const {
  return poseCost(checker_, robot, e.first, e.a) + poseCost(checker_, robot, e.a, e.b) +
         std::hypot(e.last.x - e.b.x, e.last.y - e.b.y);
}

// The clearest place climbed to from the robot's spinning centre halfway along segment k.
Vec2 ShortWay::clearPlaceNear(const std::vector<Config>& w, size_t k, size_t robot) {
  const double radius = checker_.radius(robot);
  const Vec2 centre = Transform(poseOf(lerp(w[k], w[k + 1], 0.5), robot))(spinCentre(robot));
  return clearestNear(scene_, centre, 0.25 * radius, 2 * radius);
}

// Distinct clear places climbed to from the segments of w[from..to] that turn most.
std::vector<Vec2> ShortWay::placesToSpin(const std::vector<Config>& w, size_t from, size_t to,
                                         size_t robot) {
  const size_t c = 3 * robot + 2;
  std::vector<size_t> segments;
  for (size_t k = from; k < to; ++k)
    if (w[k + 1][c] != w[k][c]) segments.push_back(k);
  std::stable_sort(segments.begin(), segments.end(), [&](size_t a, size_t b) {
    return std::fabs(w[a + 1][c] - w[a][c]) > std::fabs(w[b + 1][c] - w[b][c]);
  });
  const double radius = checker_.radius(robot);
  std::vector<Vec2> places;
  for (size_t i = 0; i < segments.size() && places.size() < kRoutePlaces && i < kRouteClimbs; ++i) {
    const Vec2 at = clearPlaceNear(w, segments[i], robot);
    // Where the robot cannot spin whole, a quarter's sweep may still fit, but the routes
    // would cost two slices on the chance: the bends' and doors' places are too small.
    if (wallDistance(scene_, at) < spinRadius(robot)) continue;
    const bool known = std::any_of(places.begin(), places.end(), [&](Vec2 q) {
      return std::hypot(q.x - at.x, q.y - at.y) < 0.05 * radius;
    });
    if (!known) places.push_back(at);
  }
  return places;
}

// A window from `start` made as: routed at its angle to `ends.a`, turned there about the
// spinning centre at `at` to `ends.b`, routed on at that angle to `ends.last`. Empty where a
// route is not found.
std::vector<Config> ShortWay::routedStretch(const Config& start, const SpinEnds& ends, size_t robot,
                                            Vec2 at) {
  const Pose &first = ends.first, &last = ends.last, &a = ends.a, &b = ends.b;
  const auto before = routes_.route(first.theta, {first.x, first.y}, {a.x, a.y}, stop_);
  const auto after =
      before ? routes_.route(b.theta, {b.x, b.y}, {last.x, last.y}, stop_) : std::nullopt;
  if (!after) return {};
  std::vector<Config> out{start};
  auto along = [&](const std::vector<Vec2>& route, double theta) {
    for (size_t k = 1; k < route.size(); ++k) {
      out.push_back(start);
      setPose(out.back(), robot, {route[k].x, route[k].y, theta});
    }
  };
  along(*before, first.theta);
  Config spun = out.back();
  setPose(spun, robot, b);
  const std::vector<Config> turn =
      turnAbout(out.back(), spun, robot, spinCentre(robot), at, kSpinStep);
  out.insert(out.end(), turn.begin(), turn.end());
  out.push_back(spun);
  along(*after, b.theta);
  return out;
}

// The carriers of a window: in the second pass only those whose runs turn the other way.
std::vector<ShortWay::Carrier> ShortWay::carriersOf(const Rewind& r, bool spin) {
  std::vector<Carrier> carriers;
  if (r.turns != 0) {
    if (!spin) carriers.push_back({Carrier::Scaled});
    for (size_t p = r.p; p <= r.q && r.q > r.p; ++p)
      for (size_t q = p; q <= r.q; ++q) carriers.push_back({Carrier::Runs, p, q});
  }
  for (size_t p = r.p; p <= r.q; ++p) carriers.push_back({Carrier::Only, p, p});
  if (!spin) carriers.push_back({Carrier::Spread});
  return carriers;
}

// Which of a carrier's runs are moved to where the robot spins: none in the first pass; in
// the second, both of two (the later first, so that the earlier's waypoints keep their
// places), or either; each with the drift in angle outside the turn kept or mirrored.
std::vector<std::pair<std::vector<size_t>, bool>> ShortWay::spunRuns(const Carrier& carrier,
                                                                     bool spin) {
  if (!spin) return {{{}, false}};
  std::vector<std::vector<size_t>> moved{{carrier.first}};
  if (carrier.kind == Carrier::Runs && carrier.second != carrier.first)
    moved = {{carrier.second, carrier.first}, {carrier.first}, {carrier.second}};
  std::vector<std::pair<std::vector<size_t>, bool>> out;
  for (const bool mirror : {false, true})
    for (const auto& m : moved) out.emplace_back(m, mirror);
  return out;
}

// The rewound stretch with each of `moved` (runs) turned about the robot's spinning centre
// held at the clearest place near where the run turned most. Only the run's waypoints whose
// centre lies in that place's empty circle make the turn; the others drift in angle as they
// did, or the other way (`mirror`): a key turned half round in a slot fits it tilted the
// other way, as its mirror image.
std::vector<Config> ShortWay::spunStretch(const std::vector<Config>& w, std::vector<Config> stretch,
                                          const std::vector<Run>& runs,
                                          const std::vector<size_t>& moved, bool mirror,
                                          size_t from, size_t robot) {
  const size_t c = 3 * robot + 2;
  const Vec2 centre = spinCentre(robot);
  auto centreAt = [&](const Config& q) { return Transform(poseOf(q, robot))(centre); };
  size_t end = from + stretch.size() - 1;  // an earlier run's turn ends before a later's
  for (const size_t run : moved) {
    const auto [first, last] = runs[run];
    size_t most = first;
    for (size_t k = first; k < last; ++k)
      if (std::fabs(w[k + 1][c] - w[k][c]) > std::fabs(w[most + 1][c] - w[most][c])) most = k;
    auto [place, fresh] = spinPlaces_.try_emplace(most);
    if (fresh) place->second = clearPlaceNear(w, most, robot);
    const Vec2 at = place->second;
    const double room = wallDistance(scene_, at);
    auto inside = [&](size_t k) {
      const Vec2 p = centreAt(w[k]);
      return std::hypot(p.x - at.x, p.y - at.y) <= room;
    };
    // From the last waypoint before the robot's centre enters that place to the first after
    // it leaves (within the stretch).
    size_t i = most, j = std::min(most + 1, end);
    while (i > from && inside(i - 1)) --i;
    while (j < end && inside(j + 1)) ++j;
    if (i > from) --i;
    if (j < end) ++j;
    if (j <= i) continue;
    // The rest of the run turns as it did, offset to the run's new ends.
    const double begin = stretch[first - from][c];
    const double finish = last <= end ? stretch[last - from][c] : stretch[end - from][c];
    const double sign = mirror ? -1 : 1;
    for (size_t k = first; k <= i; ++k)
      stretch[k - from][c] = begin + sign * (w[k][c] - w[first][c]);
    for (size_t k = j; k <= std::min(last, end); ++k)
      stretch[k - from][c] = finish - sign * (w[std::min(last, end)][c] - w[k][c]);
    const std::vector<Config> turn =
        turnAbout(stretch[i - from], stretch[j - from], robot, centre, at, kSpinStep);
    stretch.erase(stretch.begin() + long(i - from) + 1, stretch.begin() + long(j - from));
    stretch.insert(stretch.begin() + long(i - from) + 1, turn.begin(), turn.end());
    end = i;
  }
  return stretch;
}

// The robot's smallest enclosing circle (its frame), about whose centre it sweeps least.
const Disc& ShortWay::spinCircle(size_t robot) {
  if (spinCircles_.empty())
    for (const Robot& r : scene_.robots) spinCircles_.push_back(smallestCircle(r.shape));
  return spinCircles_[robot];
}

// The robot's new angle at waypoint `at` (c: its angle coordinate).
double ShortWay::rewound(const std::vector<Config>& w, const std::vector<double>& cum,
                         const std::vector<Run>& runs, const Carrier& carrier, const Rewind& r,
                         size_t at, size_t c) {
  const size_t from = runs[r.p].first, to = runs[r.q].second;
  const double a = w[from][c], net = w[to][c] - a, target = net + 2 * M_PI * r.turns;
  if (carrier.kind == Carrier::Scaled) return a + target * (w[at][c] - a) / net;
  if (carrier.kind == Carrier::Spread)
    return a + target * (cum[at] - cum[from]) / (cum[to] - cum[from]);
  // How far through a run the robot is at `at`: by its cost, or by its turn.
  auto through = [&](size_t run, bool byTurn) {
    const auto [first, last] = runs[run];
    if (at <= first) return 0.0;
    if (at >= last) return 1.0;
    const double own = w[last][c] - w[first][c];
    return byTurn && own != 0 ? (w[at][c] - w[first][c]) / own
                              : (cum[at] - cum[first]) / (cum[last] - cum[first]);
  };
  // The whole net turn in one run: by cost, which never turns back.
  if (carrier.kind == Carrier::Only) return a + target * through(carrier.first, false);
  // Full turns added where the robot turned (by cost where a run turns back to its start).
  const double added = carrier.first == carrier.second
                           ? through(carrier.first, true)
                           : 0.5 * (through(carrier.first, true) + through(carrier.second, true));
  return w[at][c] + 2 * M_PI * r.turns * added;
}

}  // namespace mms::detail
