#include "path/OptimizerCore.h"

#include <algorithm>
#include <cmath>

namespace mms::detail {

// One robot's cost from pose a to pose b.
double segmentCost(const CollisionChecker& checker, const Config& a, const Config& b) {
  double c = 0;
  for (size_t i = 0; 3 * i < a.size(); ++i) {
    const Pose p = poseOf(a, i), q = poseOf(b, i);
    // Robots that stay put add exactly 0: among hundreds moved one at a time most do.
    if (p.x == q.x && p.y == q.y && p.theta == q.theta) continue;
    c += poseCost(checker, i, p, q);
  }
  return c;
}

OptimizerCore::OptimizerCore(const Scene& scene, const CollisionChecker& checker, Random& rng,
                             const OptimizeSettings& settings, const Termination& stop,
                             OptimizeStats& stats)
    : scene_(scene), checker_(checker), rng_(rng), settings_(settings), stop_(stop), s_(stats) {
  // A candidate stretch is short; one that needs more evaluations slides along contacts and
  // is not worth the time.
  quick_.maxEvaluations = settings.candidateEvaluations;
  quick_.measureClearance = false;  // (only the clearance objective reads it)
  measured_.maxEvaluations = settings.candidateEvaluations;
  // Robots that are all discs are certified at once per segment (a swept stadium): the middle
  // pose alone, as a probe, then costs less than more of them.
  double r = std::numeric_limits<double>::infinity();
  bool discs = true;
  for (size_t i = 0; i < scene_.robots.size(); ++i) {
    r = std::min(r, checker_.radius(i));
    discs = discs && checker_.disc(i) > 0;
  }
  probeLevels_ = discs ? 1 : kProbeLevels;
  probeSpacing_ = 0.5 * r;
}

PathCheckResult OptimizerCore::check(const std::vector<Config>& stretch, bool measureClearance) {
  const PathCheckResult r =
      checkMotion(scene_, checker_, stretch, measureClearance ? measured_ : quick_);
  s_.evaluations += r.evaluations;
  return r;
}

// Most candidates cut through an obstacle, and the certifier, which advances from the start,
// takes fifty evaluations and more to reach it: poses along each segment, tested first coarse
// to fine, refuse most of them at a few (the certifier would refuse them too, at that pose).
bool OptimizerCore::certified(const std::vector<Config>& stretch, size_t moved) {
  ++s_.checked;
  return probedFree(stretch, moved) && check(stretch).ok;
}

// The other robots are where the certified path has them, clear of the obstacles and of each
// other: only the moved robot's tests can fail.
bool OptimizerCore::freeAt(const Config& q, size_t moved) {
  if (moved == kEveryRobot) return checker_.isFree(q);
  const Pose p = poseOf(q, moved);
  if (!checker_.robotFree(moved, p)) return false;
  for (size_t j = 0; j < scene_.robots.size(); ++j)
    if (j != moved && !checker_.robotsDisjoint(moved, p, j, poseOf(q, j))) return false;
  return true;
}

// Poses at 1/2 of every segment, then 1/4 and 3/4, and so on: halving the spacing each level
// while it is longer (in cost, how far the robots' points move) than half the smallest robot's
// radius, up to kProbeLevels levels (7 poses a segment; the middle alone for discs).
bool OptimizerCore::probedFree(const std::vector<Config>& stretch, size_t moved) {
  for (size_t level = 1; level <= probeLevels_; ++level) {
    const size_t parts = size_t(1) << level;
    if (level == 2) {  // the segments' costs, once finer poses may be tested
      probeCost_.clear();
      for (size_t k = 1; k < stretch.size(); ++k)
        probeCost_.push_back(segmentCost(checker_, stretch[k - 1], stretch[k]));
    }
    bool finer = false;
    // Segments from the middle out: a robot straightened over the stretch strays furthest from
    // its certified way mid-stretch, where most refused candidates first collide (the same
    // candidates are refused in any order).
    const size_t n = stretch.size() - 1, middle = (n + 1) / 2;
    for (size_t i = 0, visited = 0; visited < n; ++i) {
      const size_t k = i % 2 ? middle - (i + 1) / 2 : middle + i / 2;  // (wraps past 0: skipped)
      if (k < 1 || k > n) continue;
      ++visited;
      if (level > 1 && 2 * probeCost_[k - 1] < double(parts) * probeSpacing_) continue;
      finer = true;
      for (size_t j = 1; j < parts; j += 2) {
        s_.evaluations += 1;
        lerp(stretch[k - 1], stretch[k], double(j) / double(parts), probe_);
        if (!freeAt(probe_, moved)) return false;
      }
    }
    if (!finer) break;
  }
  return true;
}

// The cost of the path up to each waypoint, kept until the path changes (`changed`): with
// hundreds of robots and a waypoint per move it costs as much as a copy of the path.
const std::vector<double>& OptimizerCore::cumulativeCost(const std::vector<Config>& w) {
  if (cumVersion_ == version_ && cum_.size() == w.size()) return cum_;
  cum_.assign(1, 0.0);
  for (size_t k = 1; k < w.size(); ++k)
    cum_.push_back(cum_.back() + segmentCost(checker_, w[k - 1], w[k]));
  cumVersion_ = version_;
  return cum_;
}

}  // namespace mms::detail
