#include "check/PathChecker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "geometry/BroadPhase.h"
#include "mms/Termination.h"

namespace mms {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Piece {
  double s0, s1;
  bool certified = false;  // by the evaluation of a larger piece (certifiedPrefix)
};

/// How far from a piece's middle its evaluation certified the motion although it did not certify
/// the whole piece: an item (a robot against the bounds, an obstacle or another robot) at
/// `distance` keeps clear while |s - mid| < distance / rate, which is half * distance / bound
/// since its bound over the piece is half * rate. A hair less, for the rounding of the poses.
class Reach {
 public:
  explicit Reach(double half) : reach_(half) {}
  void see(double distance, double bound, double half) {
    if (distance <= bound && bound > 0)
      reach_ = std::min(reach_, std::max(0.0, kShare * half * distance / bound));
  }
  double operator()() const { return reach_; }

 private:
  static constexpr double kShare = 1 - 1e-6;
  double reach_;
};

/// What is left of a piece to certify once an evaluation at its middle certified `reach` on
/// either side: pushed onto `pieces` right first, so that a stack visits them left to right.
/// Each is at most half the piece, so pieces shrink as fast as halving them would.
/// `keepCertified`: the certified stretch too, between them, as a piece marked certified.
void pushRest(std::vector<Piece>& pieces, const Piece& p, double mid, double reach,
              bool keepCertified = false) {
  if (mid + reach < p.s1) pieces.push_back({mid + reach, p.s1});
  if (keepCertified)
    pieces.push_back({std::max(p.s0, mid - reach), std::min(p.s1, mid + reach), true});
  if (mid - reach > p.s0) pieces.push_back({p.s0, mid - reach});
}

std::string num(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

bool samePose(const Pose& a, const Pose& b, double posTol, double angTol) {
  return std::fabs(a.x - b.x) <= posTol && std::fabs(a.y - b.y) <= posTol &&
         std::fabs(std::remainder(a.theta - b.theta, 2 * M_PI)) <= angTol;
}

/// One straight motion from a to b as the certifier sees it: how far any point of each robot can
/// move per unit of the parameter s (|dp| + radius * |dtheta|), the poses along it, and the
/// evaluation at a piece's middle. The path certifier and a sampler's motion test share it and
/// differ only in what they do with each distance.
class StraightMotion {
 public:
  /// Kept between motions: no allocation once the robots' count has been seen.
  void reset(const CollisionChecker& checker, const Config& a, const Config& b) {
    checker_ = &checker;
    a_ = &a;
    b_ = &b;
    k_ = checker.robotCount();
    rate_.assign(k_, 0.0);
    moving_.clear();
    if (k_ > CollisionChecker::kAllPairsUpTo) {  // the broad phase's discs
      radii_.resize(k_);
      for (size_t i = 0; i < k_; ++i) radii_[i] = checker.radius(i);
    }
    translation_ = rotation_ = maxRate_ = 0;
    minRate_ = kInf;
    discsOnly_ = true;
    for (size_t i = 0; i < k_; ++i) {
      const double dp = std::hypot(b[3 * i] - a[3 * i], b[3 * i + 1] - a[3 * i + 1]);
      const double dt = std::fabs(b[3 * i + 2] - a[3 * i + 2]);
      translation_ += dp;
      rotation_ += dt;
      // A disc turning about its centre covers the same points.
      rate_[i] = dp + (checker.disc(i) > 0 ? 0 : checker.radius(i) * dt);
      if (rate_[i] > 0) moving_.push_back(i);
      if (rate_[i] > 0 && checker.disc(i) == 0) discsOnly_ = false;
      maxRate_ = std::max(maxRate_, rate_[i]);
      if (rate_[i] > 0) minRate_ = std::min(minRate_, rate_[i]);
    }
  }
  double translation() const { return translation_; }
  double rotation() const { return rotation_; }
  double maxRate() const { return maxRate_; }
  /// Over a piece [mid - half, mid + half] certified with half * minRate() at least d, every
  /// moving robot keeps a clearance above d at mid.
  double minRate() const { return minRate_; }
  /// The summed rates: a bound on how far all points move over the whole motion.
  double length() const {
    double l = 0;
    for (double v : rate_) l += v;
    return l;
  }

  /// At parameter s, each robot's clearance and each pair's distance that matters over
  /// [s - half, s + half] (the moving robots, or those that stay put), against the bound half *
  /// their rates: `visit(distance, bound, robot, other)` for each, until it returns false.
  /// `cutoff(bound)` is the distance past which an exact one changes nothing to the caller.
  template <class Cutoff, class Visit>
  void evaluate(double s, double half, bool movingOnly, const Cutoff& cutoff,
                const Visit& visit) const {
    const CollisionChecker& checker = *checker_;
    for (size_t i = 0; i < k_; ++i) {
      if (movingOnly != (rate_[i] > 0)) continue;
      const double bound = half * rate_[i];
      const auto c = checker.robotClearance(i, pose(i, s), cutoff(bound));
      if (!visit(c.distance, bound, i, c.nearest)) return;
    }
    auto pair = [&](size_t i, size_t j) {
      const double bound = half * (rate_[i] + rate_[j]);
      const double d = checker.robotsDistance(i, pose(i, s), j, pose(j, s), cutoff(bound));
      return visit(d, bound, i, Contact{Contact::Kind::Robot, j});
    };
    auto counts = [&](size_t i, size_t j) { return movingOnly == (rate_[i] > 0 || rate_[j] > 0); };
    if (k_ <= CollisionChecker::kAllPairsUpTo) {
      for (size_t i = 0; i < k_; ++i)
        for (size_t j = i + 1; j < k_; ++j)
          if (counts(i, j) && !pair(i, j)) return;
      return;
    }
    // Many robots: only pairs whose discs come within their cutoff can change the answer (a
    // pair further apart would be reported at the cutoff, which the caller ignores).
    centres_.resize(k_);
    for (size_t i = 0; i < k_; ++i) {
      const Pose p = pose(i, s);
      centres_[i] = {p.x, p.y};
    }
    if (movingOnly && moving_.size() * 8 < k_) {
      // A few robots move (one at a time, as many-robot planners move them): each against all,
      // which costs less than sorting them all per evaluation.
      near_.clear();
      for (size_t i : moving_)
        for (size_t j = 0; j < k_; ++j) {
          if (j == i || (rate_[j] > 0 && j < i)) continue;  // a pair of movers once
          const size_t a = std::min(i, j), b = std::max(i, j);
          const double gap = norm(centres_[a] - centres_[b]) - radii_[a] - radii_[b];
          if (gap < cutoff(half * (rate_[a] + rate_[b]))) near_.emplace_back(a, b);
        }
      std::sort(near_.begin(), near_.end());
      for (const auto& [i, j] : near_)
        if (!pair(i, j)) return;
      return;
    }
    const double reach = cutoff(2 * half * maxRate_);
    const auto& near = sweep_.near(centres_, radii_, reach, [&](size_t i, size_t j, double gap) {
      return counts(i, j) && gap < cutoff(half * (rate_[i] + rate_[j]));
    });
    for (const auto& [i, j] : near)
      if (!pair(i, j)) return;
  }

 public:
  /// Every moving robot is a disc: a translating disc sweeps a stadium, and sweep() tests the
  /// whole motion at once, exactly, instead of piece by piece (which along a contact needs
  /// pieces as short as the tolerance).
  bool discsOnly() const { return discsOnly_; }
  /// The least distance over the whole motion of each moving disc to the bounds and obstacles
  /// and to every other robot (a pair of moving discs once): `visit(distance, robot, contact)`
  /// until it returns false.
  template <class Visit>
  void sweep(const Visit& visit) const {
    const CollisionChecker& checker = *checker_;
    const Config &a = *a_, &b = *b_;
    auto from = [&](size_t i) { return Vec2{a[3 * i], a[3 * i + 1]}; };
    auto to = [&](size_t i) { return Vec2{b[3 * i], b[3 * i + 1]}; };
    for (size_t i : moving_) {
      const auto c = checker.sweptDiscClearance(i, from(i), to(i));
      if (!visit(c.distance, i, c.nearest)) return;
      for (size_t j = 0; j < k_; ++j) {
        if (j == i || (rate_[j] > 0 && j < i)) continue;  // a pair of movers once
        const double d =
            checker.sweptDiscDistance(i, from(i), to(i), j, from(j), to(j), poseOf(a, j));
        if (!visit(d, i, Contact{Contact::Kind::Robot, j})) return;
      }
    }
  }

 private:
  Pose pose(size_t i, double s) const {
    const Config &a = *a_, &b = *b_;
    auto lerp = [&](size_t c) { return a[c] + s * (b[c] - a[c]); };
    return {lerp(3 * i), lerp(3 * i + 1), lerp(3 * i + 2)};
  }

  const CollisionChecker* checker_ = nullptr;
  const Config *a_ = nullptr, *b_ = nullptr;
  size_t k_ = 0;
  std::vector<double> rate_, radii_;
  std::vector<size_t> moving_;         // robots whose rate is positive
  mutable std::vector<Vec2> centres_;  // scratch of the broad phase, kept between evaluations
  mutable std::vector<DiscSweep::Pair> near_;
  mutable DiscSweep sweep_;
  double translation_ = 0, rotation_ = 0, maxRate_ = 0, minRate_ = kInf;
  bool discsOnly_ = false;
};

class Certifier {
 public:
  Certifier(const Scene& scene, const CollisionChecker& checker, const PathCheckSettings& settings,
            PathCheckResult& result)
      : scene_(scene), checker_(checker), settings_(settings), r_(result) {}

  // Certifies the motion from a to b; on failure fills the result and returns false.
  bool segment(size_t index, const Config& a, const Config& b) {
    index_ = index;
    motion_.reset(checker_, a, b);
    r_.translation += motion_.translation();
    r_.rotation += motion_.rotation();
    // Robots that stay put are checked once; pieces then only test the moving ones. Where the
    // segment starts at the end of the one certified before, they were: each of them and each
    // pair of them either stood as they stand now at that segment's start, or moved, and every
    // robot and pair with a moving robot was certified over that segment up to its end. Among
    // hundreds of robots moving one at a time this check was most of the work.
    const bool continues = certifiedEnd_ == &a || (certifiedEnd_ && *certifiedEnd_ == a);
    if (!continues && evaluate(0.0, /*movingOnly=*/false, 0.0) == Status::Collision)
      return fail(0.0, budgetExceeded_ ? budgetWhy_ : why());
    if (motion_.discsOnly() && sweptFree()) {
      certifiedEnd_ = &b;
      return true;
    }
    // (A swept disc that hits something: the pieces below find where it first does.)
    // Pieces are visited left to right; after a collision only what lies before it is
    // searched further, so the reported parameter is the first failure along the segment.
    double failAt = -1;
    std::string failWhy;
    std::vector<Piece>& stack = stack_;  // kept between segments: no allocation per segment
    stack.assign(1, {0.0, 1.0});
    while (!stack.empty()) {
      const Piece p = stack.back();
      stack.pop_back();
      if (failAt >= 0 && p.s0 >= failAt) continue;
      const double half = 0.5 * (p.s1 - p.s0);
      const double mid = p.s0 + half;
      const Status st = evaluate(mid, /*movingOnly=*/true, half);
      if (budgetExceeded_) return fail(mid, budgetWhy_);
      if (st == Status::Certified) continue;
      if (st == Status::Collision) {
        failAt = mid;
        failWhy = why();
        stack.push_back({p.s0, mid});
        continue;
      }
      if (half * motion_.maxRate() < 0.25 * checker_.tolerance()) {
        failAt = mid;
        failWhy =
            why() + " (clearance below the contact tolerance " + num(checker_.tolerance()) + ")";
        continue;
      }
      pushRest(stack, p, mid, reach_);
    }
    if (failAt >= 0) return fail(failAt, failWhy);
    certifiedEnd_ = &b;
    return true;
  }

 private:
  bool fail(double s, const std::string& why) {
    r_.ok = false;
    r_.segment = index_;
    r_.parameter = s;
    r_.reason = why;
    return false;
  }

  enum class Status { Certified, Uncertified, Collision };

  // The whole motion of moving discs at once (one evaluation).
  bool sweptFree() {
    ++r_.evaluations;
    bool hit = false;
    motion_.sweep([&](double distance, size_t, const Contact&) {
      r_.minClearance = std::min(r_.minClearance, std::max(0.0, distance - checker_.tolerance()));
      hit = distance <= 0;
      return !hit;
    });
    return !hit;
  }

  // Checks the pose at parameter s: Collision when a robot hits something there, Uncertified
  // when some clearance does not exceed the displacement bound over +-half (hit_ says which).
  Status evaluate(double s, bool movingOnly, double half) {
    // A planner's time limit reaches the certifier (a no-op outside a planner's StopScope).
    if ((r_.evaluations & 1023) == 1023) checkpoint();
    if (++r_.evaluations > settings_.maxEvaluations) {
      budgetExceeded_ = true;
      budgetWhy_ = "could not certify within " + std::to_string(settings_.maxEvaluations) +
                   " clearance evaluations (the path runs along contacts)";
      return Status::Collision;
    }
    Status st = Status::Certified;
    Reach reach(half);
    // What is hit is recorded, not described: most evaluations are certified or subdivided,
    // and a message per evaluation cost more than the clearance (the text is made on failure).
    // Every distance is seen: the report's smallest clearance is over all of them.
    auto note = [&](double distance, double bound, size_t robot, const Contact& other) {
      r_.minClearance = std::min(r_.minClearance, std::max(0.0, distance - checker_.tolerance()));
      reach.see(distance, bound, half);
      if (st == Status::Collision || distance > bound) return true;
      st = distance <= 0 ? Status::Collision : Status::Uncertified;
      hit_ = {robot, other};
      return true;
    };
    // Beyond both the displacement bound and the smallest clearance so far (or the bound alone,
    // when no clearance is measured), the exact distance changes nothing: a distance just past
    // them stands in for it, and far obstacles and robots cost a box test per edge.
    auto enough = [&](double bound) {
      if (!settings_.measureClearance) return std::nextafter(bound, kInf);
      return std::nextafter(std::max(bound, r_.minClearance + checker_.tolerance()), kInf);
    };
    motion_.evaluate(s, half, movingOnly, enough, note);
    reach_ = reach();
    return st;
  }

  // "robot 'a' hits obstacle 3" for the last evaluation that was not certified.
  std::string why() const {
    return "robot '" + scene_.robots[hit_.robot].name + "' hits " + hit_.other.describe(scene_);
  }

  const Scene& scene_;
  const CollisionChecker& checker_;
  const PathCheckSettings& settings_;
  PathCheckResult& r_;
  size_t index_ = 0;
  StraightMotion motion_;
  std::vector<Piece> stack_;
  double reach_ = 0;  // what the last evaluation certified on either side of its pose
  bool budgetExceeded_ = false;
  std::string budgetWhy_;
  struct Hit {
    size_t robot = 0;
    Contact other;
  } hit_;
  const Config* certifiedEnd_ = nullptr;  // the end of the last segment certified
};

}  // namespace

PathCheckResult checkPath(const Scene& scene, const CollisionChecker& checker,
                          const std::vector<Config>& waypoints, const PathCheckSettings& settings) {
  PathCheckResult r;
  r.minClearance = std::numeric_limits<double>::infinity();
  const size_t k = scene.robots.size();
  const auto& w = waypoints;
  auto fail = [&](size_t segment, double s, std::string why) {
    r.ok = false;
    r.segment = segment;
    r.parameter = s;
    r.reason = std::move(why);
    return r;
  };
  if (w.empty()) return fail(0, 0, "the path has no waypoints");

  // Ends: positions within the tolerance, angles equal modulo 2 pi (displacing no point of
  // the robot by more than the tolerance).
  const Config start = startConfig(scene), goal = goalConfig(scene);
  for (size_t i = 0; i < k; ++i) {
    const double posTol = checker.tolerance();
    const double angTol = checker.tolerance() / std::max(1.0, checker.radius(i));
    const std::string who = "robot '" + scene.robots[i].name + "'";
    auto text = [](const Pose& p) {
      // Appended piece by piece: GCC 12 warns (-Wrestrict) on "(" + std::string&&.
      std::string t("(");
      t += num(p.x);
      t += ", ";
      t += num(p.y);
      t += ", ";
      t += num(p.theta);
      return t += ")";
    };
    if (!samePose(poseOf(w.front(), i), poseOf(start, i), posTol, angTol))
      return fail(0, 0,
                  "the first waypoint puts " + who + " at " + text(poseOf(w.front(), i)) +
                      ", not at its start " + text(poseOf(start, i)));
    if (!samePose(poseOf(w.back(), i), poseOf(goal, i), posTol, angTol))
      return fail(w.size() - 1, 1,
                  "the last waypoint puts " + who + " at " + text(poseOf(w.back(), i)) +
                      ", not at its goal " + text(poseOf(goal, i)));
    if (scene.robots[i].motion == Motion::Translate)
      for (size_t j = 0; j < w.size(); ++j)
        if (w[j][3 * i + 2] != scene.robots[i].start.theta)
          return fail(j == 0 ? 0 : j - 1, j == 0 ? 0 : 1,
                      who + " only translates but has angle " + num(w[j][3 * i + 2]) +
                          " at waypoint " + std::to_string(j));
  }

  const PathCheckResult motion = checkMotion(scene, checker, w, settings);
  return motion;
}

PathCheckResult checkMotion(const Scene& scene, const CollisionChecker& checker,
                            const std::vector<Config>& w, const PathCheckSettings& settings) {
  PathCheckResult r;
  r.minClearance = std::numeric_limits<double>::infinity();
  if (w.empty()) {
    r.reason = "the path has no waypoints";
    return r;
  }
  Certifier certifier(scene, checker, settings, r);
  if (w.size() == 1 && !certifier.segment(0, w[0], w[0])) return r;
  for (size_t j = 0; j + 1 < w.size(); ++j)
    if (!certifier.segment(j, w[j], w[j + 1])) return r;
  r.ok = true;
  return r;
}

namespace {

/// One straight motion tested piece by piece as the certifier does, without its report: what
/// a sampling planner asks of every motion it adds.
class MotionTest {
 public:
  MotionTest(const CollisionChecker& checker, const Config& a, const Config& b)
      : checker_(checker), motion_(reused()) {
    motion_.reset(checker, a, b);
    // A motion that grazes a contact would need pieces as short as the tolerance: it is
    // refused after about as many evaluations as pieces a quarter of the tolerance long.
    budget_ = 1000 + size_t(std::min(1e6, 4 * motion_.length() / checker.tolerance()));
  }
  MotionTest(const MotionTest&) = delete;
  MotionTest& operator=(const MotionTest&) = delete;

  /// Collision: a robot hits something at the piece's middle. Refused: the piece is as short as
  /// the tolerance allows and still not certified, or the evaluations ran out.
  enum class Status { Collision, Refused, Uncertified, Certified };
  double minRate() const { return motion_.minRate(); }
  bool discsOnly() const { return motion_.discsOnly(); }
  /// The moving discs' whole motion, exactly (discsOnly()).
  bool sweptFree() const {
    bool hit = false;
    motion_.sweep([&](double distance, size_t, const Contact&) { return !(hit = distance <= 0); });
    return !hit;
  }
  /// Robots that stay put, at s = 0 (free of contact).
  bool stillOnesFree() { return evaluate(0.0, 0.0, false) != Status::Collision; }
  /// How far on either side of the last piece's middle its evaluation certified the motion.
  double reach() const { return reach_; }
  /// The moving robots over [mid - half, mid + half].
  Status piece(double mid, double half) {
    if (++evaluations_ > budget_) return Status::Refused;
    const Status st = evaluate(mid, half, true);
    if (st == Status::Uncertified && half * motion_.maxRate() < 0.25 * checker_.tolerance())
      return Status::Refused;
    return st;
  }

 private:
  /// One per thread, reset per motion: a sampler tests thousands of motions a second.
  static StraightMotion& reused() {
    thread_local StraightMotion motion;
    return motion;
  }
  /// Stops at the first contact; only whether a distance is within its bound matters.
  Status evaluate(double s, double half, bool movingOnly) {
    Status st = Status::Certified;
    Reach reach(half);
    auto justPast = [](double bound) { return std::nextafter(bound, kInf); };
    motion_.evaluate(s, half, movingOnly, justPast,
                     [&](double distance, double bound, size_t, const Contact&) {
                       if (distance <= 0) {
                         st = Status::Collision;
                         return false;
                       }
                       reach.see(distance, bound, half);
                       if (distance <= bound) st = Status::Uncertified;
                       return true;
                     });
    reach_ = reach();
    return st;
  }

  const CollisionChecker& checker_;
  StraightMotion& motion_;
  size_t budget_ = 0, evaluations_ = 0;
  double reach_ = 0;
};

}  // namespace

bool motionFree(const CollisionChecker& checker, const Config& a, const Config& b,
                bool stillOnesFree) {
  MotionTest test(checker, a, b);
  if (!stillOnesFree) {
    // Where a motion ends is where a tree's extension usually collides: a collision test there
    // (cheaper than a clearance) refuses most motions at once, as OMPL's discrete validator
    // does.
    if (!checker.isFree(b)) return false;
    if (!test.stillOnesFree()) return false;
  }
  if (test.discsOnly()) return test.sweptFree();
  // Breadth first: a motion that hits something is refused after a few evaluations.
  thread_local std::vector<Piece> queue;
  queue.assign(1, {0.0, 1.0});
  for (size_t head = 0; head < queue.size(); ++head) {
    const Piece p = queue[head];
    const double half = 0.5 * (p.s1 - p.s0), mid = p.s0 + half;
    const MotionTest::Status st = test.piece(mid, half);
    if (st == MotionTest::Status::Collision || st == MotionTest::Status::Refused) return false;
    if (st == MotionTest::Status::Uncertified) pushRest(queue, p, mid, test.reach());
  }
  return true;
}

double certifiedPrefix(const CollisionChecker& checker, const Config& a, const Config& b) {
  MotionTest test(checker, a, b);
  if (!test.stillOnesFree()) return 0;
  // Depth first, left to right: the certified pieces join up from 0. After a collision only
  // what lies before it is searched further. Where the certified beginning ends a robot may
  // all but touch something, and a motion from there could not be certified again (pieces
  // would need to be shorter than the tolerance): the answer is the furthest point of the last
  // certified piece at which every moving robot keeps the tolerance's clearance.
  thread_local std::vector<Piece> stack;
  stack.assign(1, {0.0, 1.0});
  double collision = 2, clear = 0;
  while (!stack.empty()) {
    const Piece p = stack.back();
    stack.pop_back();
    if (p.s0 >= collision) continue;
    const double half = 0.5 * (p.s1 - p.s0), mid = p.s0 + half;
    const MotionTest::Status st =
        p.certified ? MotionTest::Status::Certified : test.piece(mid, half);
    if (st == MotionTest::Status::Refused) return clear;
    if (st == MotionTest::Status::Certified) {
      if (p.s1 == 1) return 1;
      // Each moving robot is more than half * its rate away from anything at mid, and loses at
      // most its rate per unit of s: twice the tolerance short of the piece's end it keeps twice
      // the tolerance.
      const double tol = checker.tolerance(), rate = test.minRate();
      if (half * rate >= tol) clear = mid + std::max(0.0, half - 2 * tol / rate);
    } else if (st == MotionTest::Status::Collision) {
      collision = mid;
      stack.push_back({p.s0, mid});
    } else {
      // What the evaluation certified about its pose is visited in its turn, as a piece of its
      // own: its middle may be the answer.
      pushRest(stack, p, mid, test.reach(), /*keepCertified=*/true);
    }
  }
  return clear;
}

void measureFleet(const Scene& scene, const CollisionChecker& checker,
                  const std::vector<Config>& waypoints, PathCheckResult& r) {
  const size_t robots = scene.robots.size();
  std::vector<double> own(robots, 0);  // each robot's cost
  double makespan = 0, moving = 0;
  for (size_t k = 0; k + 1 < waypoints.size(); ++k) {
    double segment = 0;
    size_t movers = 0;
    for (size_t i = 0; i < robots; ++i) {
      const Pose p = poseOf(waypoints[k], i), q = poseOf(waypoints[k + 1], i);
      if (p.x == q.x && p.y == q.y && p.theta == q.theta) continue;
      const double c = poseCost(checker, i, p, q);
      own[i] += c;
      segment = std::max(segment, c);
      ++movers;
    }
    makespan += segment;
    moving += segment * double(movers);
  }
  r.makespan = makespan;
  r.distance = r.makespanBound = r.distanceBound = 0;
  for (size_t i = 0; i < robots; ++i) {
    r.distance += own[i];
    const Robot& robot = scene.robots[i];
    Pose goal = robot.goal;
    // The turn the short way (the certifier takes the goal's angle modulo a full turn).
    goal.theta =
        robot.motion == Motion::Translate
            ? robot.start.theta
            : robot.start.theta + std::remainder(robot.goal.theta - robot.start.theta, 2 * M_PI);
    const double least = poseCost(checker, i, robot.start, goal);
    r.distanceBound += least;
    r.makespanBound = std::max(r.makespanBound, least);
  }
  r.movingAtOnce = makespan > 0 ? moving / makespan : 0;
}

}  // namespace mms
