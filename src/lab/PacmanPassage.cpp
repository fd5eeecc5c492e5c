#include "lab/PacmanPassage.h"

#include <cmath>
#include <numeric>

#include "geometry/CollisionChecker.h"
#include "mms/Termination.h"
#include "planner/TwoRobotPlanner.h"
#include "scenarios/Generators.h"
#include "util/Random.h"

namespace mms::lab {

namespace {

double norm(const Point& v) {
  return std::sqrt(std::inner_product(v.begin(), v.end(), v.begin(), 0.0));
}

// How far a ray runs free, marched in 32 steps and the first blocked step bisected: thin
// obstacles between steps are missed, so the radii are estimates from above at that resolution.
RayFunction marchingRay(const std::function<bool(const Point&)>& free) {
  return [free](const Point& x, const Point& u, double cap) {
    if (!free(x)) return 0.0;
    const int steps = 32;
    double h = cap / steps, lo = 0, hi = -1;
    Point p(6);
    for (int i = 1; i <= steps; ++i) {
      double t = h * i;
      for (int a = 0; a < 6; ++a) p[a] = x[a] + t * u[a];
      if (!free(p)) {
        hi = t;
        break;
      }
      lo = t;
    }
    if (hi < 0) return cap;
    for (int i = 0; i < 10; ++i) {
      double t = 0.5 * (lo + hi);
      for (int a = 0; a < 6; ++a) p[a] = x[a] + t * u[a];
      (free(p) ? lo : hi) = t;
    }
    return lo;
  };
}

}  // namespace

PacmanPassage measurePacmanPassage(double tightness, const PacmanPassageSettings& settings) {
  const Scene scene = pacmanScene(tightness);
  PacmanPassage out;
  TwoRobotSettings ts;
  ts.seed = settings.seed;
  TwoRobotPlanner planner(scene, ts);
  TwoRobotResult res = planner.solve(Termination(settings.timeLimit));
  out.planSeconds = res.stats.totalSeconds;
  if (res.status != PlanStatus::Found) return out;
  out.found = true;

  const CollisionChecker checker(scene);
  const double r0 = checker.radius(0), r1 = checker.radius(1);
  auto toMetric = [&](const Config& q) {
    return Point{q[0], q[1], q[2] * r0, q[3], q[4], q[5] * r1};
  };
  auto toConfig = [&](const Point& p) {
    return Config{p[0], p[1], p[2] / r0, p[3], p[4], p[5] / r1};
  };
  auto free = [&](const Point& p) { return checker.isFree(toConfig(p)); };
  DiskSearch disk = settings.disk;
  disk.seed = settings.seed;
  disk.cap = settings.cap > 0 ? settings.cap : 0.5 * std::max(r0, r1);
  const RayFunction ray = marchingRay(free);

  // The path in metric coordinates, sampled evenly by length.
  std::vector<Point> way;
  for (const Config& q : res.waypoints) way.push_back(toMetric(q));
  std::vector<double> along{0};
  for (size_t i = 1; i < way.size(); ++i) {
    Point d(6);
    for (int a = 0; a < 6; ++a) d[a] = way[i][a] - way[i - 1][a];
    along.push_back(along.back() + norm(d));
  }
  DiskSearch scan = disk;
  scan.directions = std::max<size_t>(8, disk.directions / 4);
  double worst = INFINITY;
  Point at, tangent(6, 0.0);
  for (size_t s = 0; s < settings.pathSamples; ++s) {
    double len = along.back() * (s + 0.5) / double(settings.pathSamples);
    size_t i = std::upper_bound(along.begin(), along.end(), len) - along.begin();
    i = std::min(std::max<size_t>(i, 1), way.size() - 1);
    double seg = along[i] - along[i - 1], t = seg > 0 ? (len - along[i - 1]) / seg : 0;
    Point p(6), dir(6);
    for (int a = 0; a < 6; ++a) {
      p[a] = way[i - 1][a] + t * (way[i][a] - way[i - 1][a]);
      dir[a] = way[i][a] - way[i - 1][a];
    }
    double c = diskRadius(6, 6, p, ray, scan);
    if (c < worst) worst = c, at = p, tangent = dir;
  }
  if (double n = norm(tangent); n > 0)
    for (double& v : tangent) v /= n;

  // Climb to the widest point of the cross-section near it.
  Random random(settings.seed * 7919 + 17);
  Point best = at;
  double bestC = worst, step = settings.climbRadius / 4;
  for (size_t i = 0; i < settings.climbSteps; ++i) {
    Point d(6);
    for (double& v : d) v = random.uniform(-1, 1);
    double dot = std::inner_product(d.begin(), d.end(), tangent.begin(), 0.0);
    for (int a = 0; a < 6; ++a) d[a] -= dot * tangent[a];
    double n = norm(d);
    if (n == 0) continue;
    Point p(6);
    for (int a = 0; a < 6; ++a) p[a] = best[a] + step * d[a] / n;
    Point off(6);
    for (int a = 0; a < 6; ++a) off[a] = p[a] - at[a];
    double c = norm(off) <= settings.climbRadius ? diskRadius(6, 6, p, ray, scan) : -1;
    if (c > bestC)
      bestC = c, best = p;
    else
      step *= 0.85;
  }
  out.tightest = toConfig(best);
  for (int k = 6; k >= 1; --k) out.sequence.push_back(diskRadius(6, k, best, ray, disk));
  makeMonotone(out.sequence);
  return out;
}

}  // namespace mms::lab
