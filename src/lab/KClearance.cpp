#include "lab/KClearance.h"

#include <Eigen/Dense>
#include <algorithm>
#include <boost/pending/disjoint_sets.hpp>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "lab/SubspaceCells.h"
#include "util/Random.h"

namespace mms::lab {

namespace {

using Frame = std::vector<Point>;  // k orthonormal vectors of R^d

double gaussian(Random& r) {
  // Box-Muller from our platform-independent uniforms.
  double u = std::max(r.uniform(), 1e-300), v = r.uniform();
  return std::sqrt(-2 * std::log(u)) * std::cos(2 * M_PI * v);
}

bool orthonormalize(Frame& f) {
  for (size_t i = 0; i < f.size(); ++i) {
    for (size_t j = 0; j < i; ++j) {
      double dot = std::inner_product(f[i].begin(), f[i].end(), f[j].begin(), 0.0);
      for (size_t a = 0; a < f[i].size(); ++a) f[i][a] -= dot * f[j][a];
    }
    double n = std::sqrt(std::inner_product(f[i].begin(), f[i].end(), f[i].begin(), 0.0));
    if (n < 1e-12) return false;
    for (double& v : f[i]) v /= n;
  }
  return true;
}

// Unit directions of R^k, the same for every frame: +-1 for k = 1, a regular polygon for
// k = 2, Gaussian samples for k >= 3.
std::vector<Point> diskDirections(int k, size_t n, uint64_t seed) {
  std::vector<Point> dirs;
  if (k == 1) return {{1.0}, {-1.0}};
  if (k == 2) {
    for (size_t i = 0; i < n; ++i) {
      double a = 2 * M_PI * double(i) / double(n);
      dirs.push_back({std::cos(a), std::sin(a)});
    }
    return dirs;
  }
  Random r(seed ^ 0x9e3779b97f4a7c15ULL);
  // Axis directions first: the coordinate planes of box spaces are where disks fit best.
  for (int i = 0; i < k; ++i)
    for (double s : {1.0, -1.0}) {
      Point p(k, 0.0);
      p[i] = s;
      dirs.push_back(p);
    }
  while (dirs.size() < n * size_t(k - 1)) {
    Point p(k);
    for (double& v : p) v = gaussian(r);
    double len = std::sqrt(std::inner_product(p.begin(), p.end(), p.begin(), 0.0));
    if (len < 1e-9) continue;
    for (double& v : p) v /= len;
    dirs.push_back(p);
  }
  return dirs;
}

double frameRadius(const Point& x, const Frame& f, const std::vector<Point>& dirs,
                   const RayFunction& ray, double cap) {
  const size_t d = x.size();
  Point u(d);
  double r = cap;
  for (const Point& w : dirs) {
    std::fill(u.begin(), u.end(), 0.0);
    for (size_t i = 0; i < f.size(); ++i)
      for (size_t a = 0; a < d; ++a) u[a] += w[i] * f[i][a];
    r = std::min(r, ray(x, u, r));
    if (r <= 0) return 0;
  }
  return r;
}

}  // namespace

double diskRadius(int d, int k, const Point& x, const RayFunction& ray, const DiskSearch& s) {
  if (k < 1 || k > d || int(x.size()) != d) throw std::invalid_argument("bad disk dimension");
  const std::vector<Point> dirs = diskDirections(k, s.directions, s.seed);
  Random r(s.seed + 977 * uint64_t(k));
  Frame best;
  double bestRadius = -1;
  auto consider = [&](Frame f) {
    if (!orthonormalize(f)) return false;
    double radius = frameRadius(x, f, dirs, ray, s.cap);
    if (radius <= bestRadius) return false;
    bestRadius = radius;
    best = std::move(f);
    return true;
  };
  // Coordinate frames: every k-subset of the axes.
  std::vector<int> pick(d, 0);
  std::fill(pick.end() - k, pick.end(), 1);
  do {
    Frame f;
    for (int a = 0; a < d; ++a)
      if (pick[a]) {
        Point e(d, 0.0);
        e[a] = 1;
        f.push_back(e);
      }
    consider(std::move(f));
  } while (std::next_permutation(pick.begin(), pick.end()));
  if (k == d) return bestRadius;  // a ball: orientation does not matter
  auto randomFrame = [&] {
    Frame f(k, Point(d));
    for (Point& v : f)
      for (double& c : v) c = gaussian(r);
    return f;
  };
  // The principal frame: the free space reaches far along the passage's own directions, so
  // the top eigenvectors of sum(len(u)^2 u u^T) over random directions u span them even when
  // they are no coordinate directions (two robots moving together).
  {
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(d, d);
    for (size_t i = 0; i < s.directions * size_t(d); ++i) {
      Frame f = randomFrame();
      f.resize(1);
      if (!orthonormalize(f)) continue;
      double len = ray(x, f[0], s.cap);
      Eigen::Map<const Eigen::VectorXd> u(f[0].data(), d);
      m += len * len * u * u.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(m);
    Frame f;
    for (int i = d - 1; i >= d - k; --i) {  // eigenvalues increase
      Eigen::VectorXd v = eig.eigenvectors().col(i);
      f.emplace_back(v.data(), v.data() + d);
    }
    consider(std::move(f));
  }
  for (size_t i = 0; i < s.randomFrames; ++i) consider(randomFrame());
  double step = 0.5;
  for (size_t i = 0; i < s.refineSteps; ++i) {
    Frame f = best;
    for (Point& v : f)
      for (double& c : v) c += step * gaussian(r);
    if (!consider(std::move(f))) step *= 0.8;
  }
  return std::max(0.0, bestRadius);
}

std::vector<double> kClearanceSequence(const BoxSpace& space, const Point& start, const Point& goal,
                                       int split, const DiskSearch& s) {
  const int d = space.dim();
  if (split < 1) throw std::invalid_argument("split must be positive");
  // The arrangement grid of all boxes, each interval split evenly.
  AxisSubspace whole{{}, Point(d, 0.5)};
  for (int i = 0; i < d; ++i) whole.freeAxes.push_back(i);
  SubspaceCells arrangement(space, whole);
  std::vector<std::vector<double>> centres(d);
  for (int i = 0; i < d; ++i) {
    const std::vector<double>& br = arrangement.breaks()[i];
    for (size_t j = 0; j + 1 < br.size(); ++j)
      for (int t = 0; t < split; ++t)
        centres[i].push_back(br[j] + (br[j + 1] - br[j]) * (t + 0.5) / split);
  }
  std::vector<size_t> stride(d, 1);
  size_t n = centres[0].size();
  for (int i = 1; i < d; ++i) {
    stride[i] = stride[i - 1] * centres[i - 1].size();
    n *= centres[i].size();
  }
  if (n > 2'000'000) throw std::length_error("k-clearance grid too fine");
  auto pointOf = [&](size_t flat) {
    Point p(d);
    for (int i = 0; i < d; ++i) p[i] = centres[i][(flat / stride[i]) % centres[i].size()];
    return p;
  };
  auto nearest = [&](const Point& q) {
    size_t flat = 0;
    for (int i = 0; i < d; ++i) {
      const std::vector<double>& c = centres[i];
      size_t j = std::min_element(
                     c.begin(), c.end(),
                     [&](double a, double b) { return std::abs(a - q[i]) < std::abs(b - q[i]); }) -
                 c.begin();
      flat += j * stride[i];
    }
    return flat;
  };
  const size_t from = nearest(start), to = nearest(goal);
  // The cube is where samples come from, not a wall of the passage: rays pass through its
  // faces, so the bottleneck is the passage's and not the start's distance to the boundary.
  RayFunction ray = [&space](const Point& x, const Point& u, double cap) {
    return space.rayFree(x.data(), u.data(), cap, false);
  };

  std::vector<double> sequence;
  for (int k = d; k >= 1; --k) {
    std::vector<double> value(n, -1);
    for (size_t c = 0; c < n; ++c) {
      Point p = pointOf(c);
      if (space.isFree(p)) value[c] = diskRadius(d, k, p, ray, s);
    }
    // Maximin path: add points from the widest down until start and goal connect.
    std::vector<size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return value[a] > value[b]; });
    std::vector<size_t> rank(n), parent(n);
    boost::disjoint_sets<size_t*, size_t*> sets(rank.data(), parent.data());
    std::vector<char> added(n, 0);
    double bottleneck = 0;
    for (size_t c : order) {
      if (value[c] < 0) break;
      sets.make_set(c);
      added[c] = 1;
      for (int i = 0; i < d; ++i) {
        size_t coord = (c / stride[i]) % centres[i].size();
        if (coord > 0 && added[c - stride[i]]) sets.union_set(c, c - stride[i]);
        if (coord + 1 < centres[i].size() && added[c + stride[i]]) sets.union_set(c, c + stride[i]);
      }
      if (added[from] && added[to] && sets.find_set(from) == sets.find_set(to)) {
        bottleneck = value[c];
        break;
      }
    }
    sequence.push_back(bottleneck);
  }
  makeMonotone(sequence);
  return sequence;
}

void makeMonotone(std::vector<double>& sequence) {
  for (size_t i = 1; i < sequence.size(); ++i) sequence[i] = std::max(sequence[i], sequence[i - 1]);
}

int passageDimension(const std::vector<double>& sequence, double factor) {
  const int d = int(sequence.size());
  for (int k = d - 1; k >= 1; --k)
    if (sequence[d - k] >= factor * sequence[0]) return k;
  return 0;
}

}  // namespace mms::lab
