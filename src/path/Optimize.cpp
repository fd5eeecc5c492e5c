#include "path/Optimize.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "check/PathChecker.h"
#include "geometry/SpinPlace.h"
#include "manifolds/Pivot.h"
#include "path/HeldRoute.h"

namespace mms {

namespace {

// One robot's cost from pose a to pose b.
double poseCost(const CollisionChecker& checker, size_t robot, const Pose& a, const Pose& b) {
  return std::hypot(b.x - a.x, b.y - a.y) + checker.radius(robot) * std::fabs(b.theta - a.theta);
}

double segmentCost(const CollisionChecker& checker, const Config& a, const Config& b) {
  double c = 0;
  for (size_t i = 0; 3 * i < a.size(); ++i) {
    const Pose p = poseOf(a, i), q = poseOf(b, i);
    // Robots that stay put add exactly 0: among hundreds moved one at a time most do, and
    // hypot is a call into libm.
    if (p.x == q.x && p.y == q.y && p.theta == q.theta) continue;
    c += poseCost(checker, i, p, q);
  }
  return c;
}

// Which coordinates of a robot a partial shortcut straightens.
enum class Part { Translation, Rotation, Both };

class Optimizer {
 public:
  Optimizer(const Scene& scene, const CollisionChecker& checker, Random& rng,
            const OptimizeSettings& settings, const Termination& stop, OptimizeStats& stats)
      : scene_(scene), checker_(checker), rng_(rng), settings_(settings), stop_(stop), s_(stats) {
    // A candidate stretch is short; one that needs more evaluations slides along contacts and
    // is not worth the time.
    quick_.maxEvaluations = settings.candidateEvaluations;
  }

  void run(std::vector<Config>& w) {
    limit_ = settings_.maxWork;
    turnShortWay(w);
    shortcutRounds(w);
    // Turns made the short way only along a new route, tried once the shortcuts have taken
    // what they could (most of a wandering sampler's back and forth): each costs exact slices.
    // A route taken runs through the midpoints of a triangulation, which more shortcuts
    // straighten.
    const size_t before = s_.accepted;
    routing_ = true;
    turnShortWay(w);
    routing_ = false;
    if (s_.accepted > before) shortcutRounds(w);
    s_.slices = routes_.slicesBuilt();
    if (settings_.objective == PathObjective::Clearance) {
      limit_ = s_.evaluations * workPerEvaluation_ + settings_.maxWork;  // a budget of its own
      pushAwayFromContacts(w);
    }
  }

 private:
  // Rounds of shortcuts until they stop paying: the first rounds take most of what there is,
  // and on an easy scene the rest would cost more than the planning did. Short rounds end the
  // work soon after it stops paying; two weak rounds in a row, not one, because a short round
  // on a tight path often takes nothing by chance while the next takes much.
  void shortcutRounds(std::vector<Config>& w) {
    double cost = pathCost(checker_, w);
    size_t weak = 0;
    for (size_t round = 0; round < settings_.rounds && !done(); ++round) {
      const size_t before = s_.accepted;
      for (size_t a = 0; a < settings_.attempts && !done() && w.size() >= 2; ++a)
        shortcut(w, /*partial=*/rng_.below(3) != 0);
      dropStraightWaypoints(w);
      changed();
      if (s_.accepted > before) turnShortWay(w);  // shortcuts may have joined turns
      const double now = pathCost(checker_, w);
      ++s_.rounds;
      const bool paid = s_.accepted > before && cost - now >= settings_.minGain * cost;
      weak = paid ? 0 : weak + 1;
      if (weak == kWeakRounds) break;
      cost = now;
    }
  }

  bool rigid(size_t robot) const { return scene_.robots[robot].motion != Motion::Translate; }

  // Out of work: the attempts' evaluations are spent, or the time limit struck.
  bool done() const { return s_.evaluations * workPerEvaluation_ >= limit_ || stop_(); }

  PathCheckResult check(const std::vector<Config>& stretch) {
    const PathCheckResult r = checkMotion(scene_, checker_, stretch, quick_);
    s_.evaluations += r.evaluations;
    return r;
  }

  // Most candidates cut through an obstacle, and the certifier, which advances from the start,
  // takes fifty evaluations and more to reach it: poses along each segment, tested first coarse
  // to fine, refuse most of them at a few (the certifier would refuse them too, at that pose).
  bool certified(const std::vector<Config>& stretch) {
    ++s_.checked;
    return probedFree(stretch) && check(stretch).ok;
  }

  // Poses at 1/2 of every segment, then 1/4 and 3/4, and so on: halving the spacing each level
  // while it is longer (in cost, how far the robots' points move) than half the smallest robot's
  // radius, up to kProbeLevels levels (7 poses a segment).
  bool probedFree(const std::vector<Config>& stretch) {
    probeCost_.clear();
    for (size_t k = 1; k < stretch.size(); ++k)
      probeCost_.push_back(segmentCost(checker_, stretch[k - 1], stretch[k]));
    for (size_t level = 1; level <= kProbeLevels; ++level) {
      const size_t parts = size_t(1) << level;
      bool finer = false;
      for (size_t k = 1; k < stretch.size(); ++k) {
        if (level > 1 && 2 * probeCost_[k - 1] < double(parts) * probeSpacing_) continue;
        finer = true;
        for (size_t j = 1; j < parts; j += 2) {
          s_.evaluations += 1;
          if (!checker_.isFree(lerp(stretch[k - 1], stretch[k], double(j) / double(parts))))
            return false;
        }
      }
      if (!finer) break;
    }
    return true;
  }

  // A stretch in which a robot turns more than half a circle in all, turned the other way
  // round. The rest of the path is the same motion shifted by a full turn, so only the stretch
  // needs certifying. Turns split across waypoints and across moves at a fixed angle (an MMS
  // path turns on lines and moves in slices) count as one: each window from the start of one
  // run of turning segments to the end of another is a candidate, the largest saving first.
  void turnShortWay(std::vector<Config>& w) {
    for (size_t i = 0; i < scene_.robots.size(); ++i)
      while (rigid(i) && !done() && rewindOnce(w, i)) ++s_.accepted;
  }

  using Run = std::pair<size_t, size_t>;  // waypoints at the ends of a run of turning segments

  struct Rewind {
    size_t p, q;    // the window's first and last runs
    double turns;   // full turns added at the window's end and after
    double saving;  // rotation saved
  };

  static std::vector<Run> turningRuns(const std::vector<Config>& w, size_t c) {
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

  static std::vector<Rewind> rewinds(const std::vector<Config>& w, const std::vector<Run>& runs,
                                     size_t c) {
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

  // The first candidate that certifies, taken; whether there was one. Where the runs' turns
  // do not certify where they were made, a second pass moves a run whose turn changed to the
  // nearest place where the robot spins in place (SpinPlace.h).
  bool rewindOnce(std::vector<Config>& w, size_t robot) {
    const size_t c = 3 * robot + 2;
    const std::vector<Run> runs = turningRuns(w, c);
    const std::vector<double> cum = cumulativeCost(w);
    const std::vector<Rewind> candidates = rewinds(w, runs, c);
    spinPlaces_.clear();
    const bool taken = routing_ ? routedSpin(w, robot, runs, cum, candidates)
                                : rewindPass(w, robot, runs, cum, candidates, false) ||
                                      rewindPass(w, robot, runs, cum, candidates, true);
    changed();
    return taken;
  }

  bool rewindPass(std::vector<Config>& w, size_t robot, const std::vector<Run>& runs,
                  const std::vector<double>& cum, const std::vector<Rewind>& candidates,
                  bool spin) {
    const size_t c = 3 * robot + 2;
    size_t tries = 0, considered = 0;
    for (const Rewind& r : candidates) {
      if (spin && r.turns == 0) continue;
      const size_t from = runs[r.p].first, to = runs[r.q].second;
      for (const Carrier& carrier : carriersOf(r, spin)) {
        if (!spin && (tries++ == kRewindTries || done())) return false;
        if (spin && (considered++ == kSpinCarriers || spinPlaces_.size() > kSpinPlaces))
          return false;
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
          if (!certified(candidate)) continue;
          takeWindow(w, from, to, candidate, c, r.turns);
          return true;
        }
      }
    }
    return false;
  }

  // Waypoints from..to replaced by a window turned the other way round: the rest of the path
  // is the same motion, its angle (coordinate c) shifted by the full turns the window undid.
  static void takeWindow(std::vector<Config>& w, size_t from, size_t to,
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
  bool routedSpin(std::vector<Config>& w, size_t robot, const std::vector<Run>& runs,
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

  // A routed window's poses: its ends, and the robot spinning at `at` before and after the
  // turn (b at the end's angle plus `turns` full turns).
  struct SpinEnds {
    Pose first, a, b, last;
  };
  SpinEnds spinEnds(const std::vector<Config>& w, size_t from, size_t to, size_t robot,
                    double turns, Vec2 at) {
    SpinEnds e{poseOf(w[from], robot), {}, {}, poseOf(w[to], robot)};
    e.a = poseWithPointAt(spinCentre(robot), at, e.first.theta);
    e.b = poseWithPointAt(spinCentre(robot), at, e.last.theta + 2 * M_PI * turns);
    return e;
  }

  // What routedStretch costs at least: straight to the place, the turn, straight on.
  double leastRoutedCost(const SpinEnds& e, size_t robot) const {
    return poseCost(checker_, robot, e.first, e.a) + poseCost(checker_, robot, e.a, e.b) +
           poseCost(checker_, robot, e.b, e.last);
  }

  // The clearest place climbed to from the robot's spinning centre halfway along segment k.
  Vec2 clearPlaceNear(const std::vector<Config>& w, size_t k, size_t robot) {
    const double radius = checker_.radius(robot);
    const Vec2 centre = Transform(poseOf(lerp(w[k], w[k + 1], 0.5), robot))(spinCentre(robot));
    return clearestNear(scene_, centre, 0.25 * radius, 2 * radius);
  }

  // Distinct clear places climbed to from the segments of w[from..to] that turn most.
  std::vector<Vec2> placesToSpin(const std::vector<Config>& w, size_t from, size_t to,
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
    for (size_t i = 0; i < segments.size() && places.size() < kRoutePlaces && i < kRouteClimbs;
         ++i) {
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
  std::vector<Config> routedStretch(const Config& start, const SpinEnds& ends, size_t robot,
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
  static std::vector<Carrier> carriersOf(const Rewind& r, bool spin) {
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
  static std::vector<std::pair<std::vector<size_t>, bool>> spunRuns(const Carrier& carrier,
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
  std::vector<Config> spunStretch(const std::vector<Config>& w, std::vector<Config> stretch,
                                  const std::vector<Run>& runs, const std::vector<size_t>& moved,
                                  bool mirror, size_t from, size_t robot) {
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
  const Disc& spinCircle(size_t robot) {
    if (spinCircles_.empty())
      for (const Robot& r : scene_.robots) spinCircles_.push_back(smallestCircle(r.shape));
    return spinCircles_[robot];
  }
  Vec2 spinCentre(size_t robot) { return spinCircle(robot).center; }
  double spinRadius(size_t robot) { return spinCircle(robot).radius; }

  // The robot's new angle at waypoint `at` (c: its angle coordinate).
  static double rewound(const std::vector<Config>& w, const std::vector<double>& cum,
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

  // The cost of the path up to each waypoint, kept until the path changes (`changed`): with
  // hundreds of robots and a waypoint per move it costs as much as a copy of the path.
  const std::vector<double>& cumulativeCost(const std::vector<Config>& w) {
    if (cumVersion_ == version_ && cum_.size() == w.size()) return cum_;
    cum_.assign(1, 0.0);
    for (size_t k = 1; k < w.size(); ++k)
      cum_.push_back(cum_.back() + segmentCost(checker_, w[k - 1], w[k]));
    cumVersion_ = version_;
    return cum_;
  }
  void changed() { ++version_; }

  // A point of the path at arc parameter `s` (cumulative cost): waypoint `k`, or when none is
  // there, `q` on the segment that ends at waypoint `k`.
  struct At {
    size_t k;
    bool inserted;
    Config q;
  };
  static At at(const std::vector<Config>& w, const std::vector<double>& cum, double s) {
    size_t j = size_t(std::upper_bound(cum.begin(), cum.end(), s) - cum.begin());
    j = std::clamp<size_t>(j, 1, w.size() - 1);  // s lies on segment (j - 1, j)
    const double length = cum[j] - cum[j - 1];
    const double t = length > 0 ? (s - cum[j - 1]) / length : 0;
    if (t <= 1e-9) return {j - 1, false, w[j - 1]};
    if (t >= 1 - 1e-9) return {j, false, w[j]};
    return {j, true, lerp(w[j - 1], w[j], t)};
  }

  // One attempt: two random points of the path, joined straight (all of every robot when
  // not `partial`) or in one robot's translation, rotation or both. Only a candidate that is
  // shorter (by settings.minStep of the path) is built and certified, and only the stretch it
  // replaces: an attempt costs what its stretch does, not a copy of the path.
  void shortcut(std::vector<Config>& w, bool partial) {
    const std::vector<double>& cum = cumulativeCost(w);
    const double total = cum.back();
    if (total <= 0) return;
    double s1 = rng_.uniform(0, total), s2 = rng_.uniform(0, total);
    if (s1 > s2) std::swap(s1, s2);
    // From the start and to the end now and then: a detour next to either (a slice's cell
    // entered a hair off the start) is otherwise almost never cut.
    if (rng_.below(8) == 0) s1 = 0;
    if (rng_.below(8) == 0) s2 = total;  // to the end, whose angle may change by a full turn
    if (s2 - s1 < 1e-9 * total) return;
    Stretch st{at(w, cum, s1), at(w, cum, s2), 0, 0, 0, {}};
    st.begin = st.from.inserted ? st.from.k : st.from.k + 1;
    st.end = st.to.k;  // the waypoints strictly between the two points: [begin, end)
    if (st.end + 1 <= st.begin) return;  // both points are one waypoint
    st.oldCost = stretchCost(w, st);
    st.aimed = st.to.q;
    if (!partial) {
      for (size_t r = 0; r < scene_.robots.size(); ++r) aimEnd(w, st, r);
      const double newCost = segmentCost(checker_, st.from.q, st.aimed);
      if (newCost >= st.oldCost - settings_.minStep * total) return;
      if (!certified({st.from.q, st.aimed})) return;
      w.erase(w.begin() + long(st.begin), w.begin() + long(st.end));
    } else if (!partialShortcut(w, st, total)) {
      return;
    }
    // The first waypoint after those between is `to`, or follows it when `to` is new.
    const size_t after = partial ? st.end : st.begin;
    if (st.to.inserted)
      w.insert(w.begin() + long(after), st.aimed);
    else
      w[after] = st.aimed;
    if (st.from.inserted) w.insert(w.begin() + long(st.begin), st.from.q);
    changed();
    ++s_.accepted;
  }

  // A shortcut's two points and the waypoints between them.
  struct Stretch {
    At from, to;
    size_t begin = 0, end = 0;  // the waypoints between, [begin, end)
    double oldCost = 0;
    Config aimed;  // `to`, its goal angles aimed (aimEnd)
  };

  // The stretch's cost from its first point to its last, through the waypoints between.
  double stretchCost(const std::vector<Config>& w, const Stretch& st) {
    if (st.begin == st.end) return segmentCost(checker_, st.from.q, st.to.q);
    const std::vector<double>& cum = cumulativeCost(w);
    return segmentCost(checker_, st.from.q, w[st.begin]) + cum[st.end - 1] - cum[st.begin] +
           segmentCost(checker_, w[st.end - 1], st.to.q);
  }

  // The goal's angle counts modulo a full turn (as the certifier takes it): a stretch to the
  // end may end there at the turn nearest to where it begins.
  void aimEnd(const std::vector<Config>& w, Stretch& st, size_t robot) const {
    if (st.to.inserted || st.to.k + 1 < w.size() || !rigid(robot)) return;
    double& end = st.aimed[3 * robot + 2];
    end += 2 * M_PI * std::round((st.from.q[3 * robot + 2] - end) / (2 * M_PI));
  }

  // One robot's translation, rotation or both straightened over the stretch, everything else
  // keeping its timing; taken into `w`'s waypoints between when it is shorter and certified.
  bool partialShortcut(std::vector<Config>& w, Stretch& st, double total) {
    if (st.end < st.begin + 1) return false;
    const size_t robot = rng_.below(scene_.robots.size());
    Part part = Part(rng_.below(3));
    if (!rigid(robot)) part = Part::Translation;
    if (part != Part::Translation) aimEnd(w, st, robot);
    // The robot's own poses along the stretch, before and after: the others' cost is the same.
    const Pose a = poseOf(st.from.q, robot), b = poseOf(st.aimed, robot);
    std::vector<Pose> before{a}, after{a};
    const std::vector<double>& cum = cumulativeCost(w);
    const double lead = segmentCost(checker_, st.from.q, w[st.begin]);
    for (size_t k = st.begin; k < st.end; ++k) {
      before.push_back(poseOf(w[k], robot));
      const double t = (lead + cum[k] - cum[st.begin]) / st.oldCost;
      Pose p = before.back();
      if (part != Part::Rotation) p.x = a.x + t * (b.x - a.x), p.y = a.y + t * (b.y - a.y);
      if (part != Part::Translation) p.theta = a.theta + t * (b.theta - a.theta);
      after.push_back(p);
    }
    before.push_back(poseOf(st.to.q, robot));
    after.push_back(b);
    if (robotCost(after, robot) >= robotCost(before, robot) - settings_.minStep * total)
      return false;
    std::vector<Config> stretch{st.from.q};
    stretch.reserve(st.end - st.begin + 2);
    for (size_t k = st.begin; k < st.end; ++k) {
      stretch.push_back(w[k]);
      setPose(stretch.back(), robot, after[k - st.begin + 1]);
    }
    stretch.push_back(st.aimed);
    if (!certified(stretch)) return false;
    for (size_t k = st.begin; k < st.end; ++k) w[k] = std::move(stretch[k - st.begin + 1]);
    return true;
  }

  // One robot's cost along its poses.
  double robotCost(const std::vector<Pose>& poses, size_t robot) const {
    double c = 0;
    for (size_t k = 1; k < poses.size(); ++k)
      c += poseCost(checker_, robot, poses[k - 1], poses[k]);
    return c;
  }

  // A waypoint on the straight segment between its neighbours, at one common fraction for
  // every coordinate, changes nothing about the motion.
  static void dropStraightWaypoints(std::vector<Config>& w) {
    for (size_t k = 1; k + 1 < w.size();) {
      const Config &a = w[k - 1], &q = w[k], &b = w[k + 1];
      double t = -1, scale = 0;
      size_t widest = 0;
      for (size_t c = 0; c < a.size(); ++c)
        if (std::fabs(b[c] - a[c]) > scale) scale = std::fabs(b[c] - a[c]), widest = c;
      bool straight = true;
      if (scale == 0) {
        straight = q == a;
      } else {
        t = (q[widest] - a[widest]) / (b[widest] - a[widest]);
        straight = t >= 0 && t <= 1;
        for (size_t c = 0; c < a.size() && straight; ++c)
          straight = std::fabs(a[c] + t * (b[c] - a[c]) - q[c]) <= 1e-12 * (1 + std::fabs(q[c]));
      }
      if (straight)
        w.erase(w.begin() + long(k));
      else
        ++k;
    }
  }

  double clearanceAt(const Config& q) {
    const PathCheckResult r = check({q});
    return r.ok ? r.minClearance : -1;
  }

  // Moves single waypoints away from contacts: a move is taken when its two segments stay
  // certified, their smallest clearance does not fall, and the waypoint's own clearance rises.
  void pushAwayFromContacts(std::vector<Config>& w) {
    if (w.size() < 3) return;
    const size_t attempts =
        settings_.clearanceAttempts ? settings_.clearanceAttempts : 50 * (w.size() - 2);
    std::vector<double> step(w.size(), 0);
    for (size_t k = 1; k + 1 < w.size(); ++k)
      step[k] = 0.25 * std::min(segmentCost(checker_, w[k - 1], w[k]),
                                segmentCost(checker_, w[k], w[k + 1]));
    for (size_t a = 0; a < attempts && !done(); ++a) {
      const size_t k = 1 + rng_.below(w.size() - 2);
      if (step[k] <= checker_.tolerance()) continue;
      const size_t robot = rng_.below(scene_.robots.size());
      Config q = w[k];
      const double angle = rng_.uniform(0, 2 * M_PI), r = step[k] * rng_.uniform();
      q[3 * robot] += r * std::cos(angle);
      q[3 * robot + 1] += r * std::sin(angle);
      if (rigid(robot))
        q[3 * robot + 2] += rng_.uniform(-1, 1) * step[k] / std::max(1.0, checker_.radius(robot));
      const std::vector<Config> before{w[k - 1], w[k], w[k + 1]}, after{w[k - 1], q, w[k + 1]};
      ++s_.checked;
      const PathCheckResult now = check(after);
      if (!now.ok || clearanceAt(q) <= clearanceAt(w[k]) ||
          now.minClearance < check(before).minClearance) {
        step[k] *= 0.7;
        continue;
      }
      w[k] = q;
      changed();
      ++s_.accepted;
    }
  }

  const Scene& scene_;
  const CollisionChecker& checker_;
  Random& rng_;
  const OptimizeSettings& settings_;
  const Termination& stop_;
  OptimizeStats& s_;
  static constexpr size_t kProbeLevels = 3;  // of poses tested before a candidate is certified
  std::vector<double> probeCost_;            // probedFree's, per segment
  // Robots that are all discs are certified at once per segment (a swept stadium): the middle
  // pose alone, as a probe, then costs less than more of them.
  double probeSpacing_ = [this] {
    double r = std::numeric_limits<double>::infinity();
    bool discs = true;
    for (size_t i = 0; i < scene_.robots.size(); ++i) {
      r = std::min(r, checker_.radius(i));
      discs = discs && checker_.disc(i) > 0;
    }
    return discs ? std::numeric_limits<double>::infinity() : 0.5 * r;
  }();
  static constexpr size_t kWeakRounds = 2;     // rounds in a row that do not pay, to stop
  static constexpr size_t kRewindTries = 32;   // certifications per robot and change
  static constexpr size_t kSpinTries = 24;     // the same, for turns moved to spin in place
  static constexpr size_t kSpinCarriers = 64;  // and carriers built for them (each a stretch)
  static constexpr size_t kSpinPlaces = 4;     // and places where the robot could spin, climbed to
  static constexpr double kSpinStep = 0.05;    // radians between a moved turn's waypoints
  std::vector<Disc> spinCircles_;
  std::map<size_t, Vec2> spinPlaces_;          // per segment where a run turned most, in one rewind
  static constexpr double kMinSaving = 0.05;   // radians of back and forth worth a try
  static constexpr double kRouteSaving = 1.0;  // and worth routing the robot anew for
  static constexpr size_t kRouteWindows = 2;   // windows routed per rewind
  static constexpr size_t kRoutePlaces = 3;    // places to spin tried per window
  static constexpr size_t kRouteClimbs = 12;   // climbs to find them
  HeldRoutes routes_{scene_, 8};               // slices at most, per optimisation
  bool routing_ = false;                       // whether rewinds may route (the last pass)
  PathCheckSettings quick_;
  std::vector<double> cum_;  // cumulativeCost's, for the path at `cumVersion_`
  size_t version_ = 0, cumVersion_ = size_t(-1);
  size_t limit_ = 0;  // work at which the current step ends
  size_t workPerEvaluation_ =
      scene_.robots.size() + scene_.robots.size() * (scene_.robots.size() - 1) / 2;
};

}  // namespace

double pathCost(const CollisionChecker& checker, const std::vector<Config>& w) {
  double c = 0;
  for (size_t k = 1; k < w.size(); ++k) c += segmentCost(checker, w[k - 1], w[k]);
  return c;
}

OptimizeStats optimizePath(const Scene& scene, const CollisionChecker& checker, Random& rng,
                           const OptimizeSettings& settings, const Termination& stop,
                           std::vector<Config>& waypoints) {
  Stopwatch watch;
  OptimizeStats s;
  s.costBefore = pathCost(checker, waypoints);
  Optimizer(scene, checker, rng, settings, stop, s).run(waypoints);
  s.costAfter = pathCost(checker, waypoints);
  s.seconds = watch.seconds();
  return s;
}

double minimumRotation(const Scene& scene) {
  double r = 0;
  for (const Robot& robot : scene.robots)
    if (robot.motion != Motion::Translate)
      r += std::fabs(std::remainder(robot.goal.theta - robot.start.theta, 2 * M_PI));
  return r;
}

}  // namespace mms
