#include "path/Optimize.h"

#include <algorithm>
#include <cmath>

#include "path/ShortWay.h"

namespace mms {

using detail::segmentCost;

namespace {

// Which coordinates of a robot a partial shortcut straightens.
enum class Part { Translation, Rotation, Both };

class Optimizer final : detail::ShortWay {
 public:
  Optimizer(const Scene& scene, const CollisionChecker& checker, Random& rng,
            const OptimizeSettings& settings, const Termination& stop, OptimizeStats& stats)
      : ShortWay(scene, checker, rng, settings, stop, stats) {}

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
    s_.gridRoutes = routes_.gridRoutes();
    if (settings_.objective == PathObjective::Clearance) {
      limit_ = s_.evaluations * workPerEvaluation_ + settings_.maxWork;  // a budget of its own
      pushAwayFromContacts(w);
    }
  }

 private:
  // Rounds of shortcuts until they stop paying: the first rounds take most of what there is,
  // and on an easy scene the rest would cost more than the planning did. Short rounds end the
  // work soon after it stops paying; two weak rounds in a row, not one, because a short round
  // on a tight path often takes nothing by chance while the next takes much. They also end
  // once they have made the tests they may (settings.roundsWork): counted, not timed.
  void shortcutRounds(std::vector<Config>& w) {
    // The cumulative cost, which the next attempt reads too, instead of pathCost again.
    double cost = cumulativeCost(w).back();
    size_t weak = 0;
    const size_t start = CollisionChecker::workOnThisThread();
    const auto spent = [&] {
      return settings_.roundsWork > 0 &&
             s_.roundsWork + (CollisionChecker::workOnThisThread() - start) >= settings_.roundsWork;
    };
    for (size_t round = 0; round < settings_.rounds && !done() && !spent(); ++round) {
      const size_t before = s_.accepted;
      for (size_t a = 0; a < settings_.attempts && !done() && !spent() && w.size() >= 2; ++a)
        shortcut(w, /*partial=*/rng_.below(3) != 0);
      dropStraightWaypoints(w);
      changed();
      if (s_.accepted > before) turnShortWay(w);  // shortcuts may have joined turns
      const double now = cumulativeCost(w).back();
      ++s_.rounds;
      const bool paid = s_.accepted > before && cost - now >= settings_.minGain * cost;
      weak = paid ? 0 : weak + 1;
      if (weak == kWeakRounds) break;
      cost = now;
    }
    s_.roundsWork += CollisionChecker::workOnThisThread() - start;
  }

  // A point of the path at arc parameter `s` (cumulative cost): waypoint `k`, or when none is
  // there, `q` on the segment that ends at waypoint `k`.
  struct At {
    size_t k;
    bool inserted;
    Config q;
  };
  // Into `out`, whose pose keeps its storage from one attempt to the next.
  static void at(const std::vector<Config>& w, const std::vector<double>& cum, double s, At& out) {
    size_t j = size_t(std::upper_bound(cum.begin(), cum.end(), s) - cum.begin());
    j = std::clamp<size_t>(j, 1, w.size() - 1);  // s lies on segment (j - 1, j)
    const double length = cum[j] - cum[j - 1];
    const double t = length > 0 ? (s - cum[j - 1]) / length : 0;
    out.inserted = t > 1e-9 && t < 1 - 1e-9;
    out.k = t <= 1e-9 ? j - 1 : j;
    if (out.inserted)
      lerp(w[j - 1], w[j], t, out.q);
    else
      out.q = w[out.k];
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
    Stretch& st = stretch_;
    at(w, cum, s1, st.from);
    at(w, cum, s2, st.to);
    st.begin = st.from.inserted ? st.from.k : st.from.k + 1;
    st.end = st.to.k;  // the waypoints strictly between the two points: [begin, end)
    if (st.end + 1 <= st.begin) return;  // both points are one waypoint
    st.oldCost = stretchCost(w, st);
    st.aimed = st.to.q;
    if (!partial) {
      for (size_t r = 0; r < scene_.robots.size(); ++r) aimEnd(w, st, r);
      const double newCost = segmentCost(checker_, st.from.q, st.aimed);
      if (newCost >= st.oldCost - settings_.minStep * total) return;
      candidate_.resize(2);
      candidate_[0] = st.from.q;
      candidate_[1] = st.aimed;
      if (!certified(candidate_)) return;
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
    std::vector<Pose>&before = before_, &after = after_;
    before.assign(1, a);
    after.assign(1, a);
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
    // Assigned, not built: each pose keeps its storage from one attempt to the next.
    std::vector<Config>& stretch = candidate_;
    stretch.resize(st.end - st.begin + 2);
    stretch.front() = st.from.q;
    for (size_t k = st.begin; k < st.end; ++k) {
      stretch[k - st.begin + 1] = w[k];
      setPose(stretch[k - st.begin + 1], robot, after[k - st.begin + 1]);
    }
    stretch.back() = st.aimed;
    if (!certified(stretch, robot)) return false;
    for (size_t k = st.begin; k < st.end; ++k) w[k] = stretch[k - st.begin + 1];
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
    const PathCheckResult r = check({q}, /*measureClearance=*/true);
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
      const PathCheckResult now = check(after, /*measureClearance=*/true);
      if (!now.ok || clearanceAt(q) <= clearanceAt(w[k]) ||
          now.minClearance < check(before, /*measureClearance=*/true).minClearance) {
        step[k] *= 0.7;
        continue;
      }
      w[k] = q;
      changed();
      ++s_.accepted;
    }
  }

  static constexpr size_t kWeakRounds = 2;  // rounds in a row that do not pay, to stop
  // An attempt's scratch, kept between attempts: thousands of attempts allocated a pose each.
  Stretch stretch_;
  std::vector<Config> candidate_;
  std::vector<Pose> before_, after_;
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
