#include "lab/BoxSpace.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "util/Random.h"

namespace mms::lab {

BoxSpace::BoxSpace(int dim, std::vector<Box> obstacles, std::string name)
    : dim_(dim), obstacles_(std::move(obstacles)), name_(std::move(name)) {
  if (dim < 1 || dim > 12) throw std::invalid_argument("dimension must be 1 to 12");
  for (const Box& b : obstacles_) {
    if (int(b.lo.size()) != dim || int(b.hi.size()) != dim)
      throw std::invalid_argument("box of the wrong dimension");
    for (int i = 0; i < dim; ++i)
      if (!(b.lo[i] < b.hi[i])) throw std::invalid_argument("box with an empty extent");
  }
}

bool BoxSpace::isFree(const double* x) const {
  for (int i = 0; i < dim_; ++i)
    if (!(x[i] > 0 && x[i] < 1)) return false;
  for (const Box& b : obstacles_) {
    bool inside = true;
    for (int i = 0; i < dim_ && inside; ++i) inside = b.lo[i] <= x[i] && x[i] <= b.hi[i];
    if (inside) return false;
  }
  return true;
}

namespace {

// The parameter interval [t0, t1] of x + t u (t in [0, cap]) inside the closed box; false when
// the ray misses it. Slab method, exact up to the one division per axis.
bool rayHits(const Box& b, const double* x, const double* u, int d, double cap, double& t0) {
  double lo = 0, hi = cap;
  for (int i = 0; i < d; ++i) {
    if (u[i] == 0) {
      if (x[i] < b.lo[i] || x[i] > b.hi[i]) return false;
      continue;
    }
    double a = (b.lo[i] - x[i]) / u[i], c = (b.hi[i] - x[i]) / u[i];
    if (a > c) std::swap(a, c);
    lo = std::max(lo, a);
    hi = std::min(hi, c);
    if (lo > hi) return false;
  }
  t0 = lo;
  return true;
}

}  // namespace

bool BoxSpace::segmentFree(const double* a, const double* b) const {
  if (!isFree(a) || !isFree(b)) return false;  // the cube is convex: the ends decide it
  std::vector<double> u(dim_);
  for (int i = 0; i < dim_; ++i) u[i] = b[i] - a[i];
  double t;
  for (const Box& box : obstacles_)
    if (rayHits(box, a, u.data(), dim_, 1.0, t)) return false;
  return true;
}

double BoxSpace::rayFree(const double* x, const double* u, double cap, bool cube) const {
  double best = cap;
  for (const Box& b : obstacles_) {
    bool inside = true;
    for (int i = 0; i < dim_ && inside; ++i) inside = b.lo[i] <= x[i] && x[i] <= b.hi[i];
    if (inside) return 0;
  }
  if (cube && !isFree(x)) return 0;
  for (int i = 0; cube && i < dim_; ++i) {  // the cube's faces
    if (u[i] > 0) best = std::min(best, (1 - x[i]) / u[i]);
    if (u[i] < 0) best = std::min(best, -x[i] / u[i]);
  }
  double t;
  for (const Box& b : obstacles_)
    if (rayHits(b, x, u, dim_, best, t)) best = std::min(best, t);
  return best;
}

BoxSpace wallWithHole(int dim, double rho, int clutter, unsigned long long seed) {
  if (dim < 2) throw std::invalid_argument("the wall needs two dimensions at least");
  if (!(rho > 0 && rho < 0.19)) throw std::invalid_argument("rho must be in (0, 0.19)");
  std::vector<Box> boxes;
  // The wall, minus the hole: per other axis, the slab below and the slab above the hole.
  for (int axis = 1; axis < dim; ++axis)
    for (int side = 0; side < 2; ++side) {
      Box b{std::vector<double>(dim, 0.0), std::vector<double>(dim, 1.0)};
      b.lo[0] = 0.45;
      b.hi[0] = 0.55;
      // Earlier axes are already covered outside the hole: restrict them to it, so the
      // boxes tile the wall without overlaps (not needed, but cheaper to decompose).
      for (int j = 1; j < axis; ++j) {
        b.lo[j] = 0.5 - rho;
        b.hi[j] = 0.5 + rho;
      }
      if (side == 0)
        b.hi[axis] = 0.5 - rho;
      else
        b.lo[axis] = 0.5 + rho;
      boxes.push_back(b);
    }
  // The path's three legs (start to the hole's mouth, through it, on to the goal) as boxes,
  // grown by 2 rho: clutter stays out of them.
  const double m = 2 * rho;
  std::vector<Box> keepOut;
  for (auto [x0, x1, y0, y1] :
       {std::array<double, 4>{0.2, 0.45, 0.3, 0.5}, std::array<double, 4>{0.45, 0.55, 0.5, 0.5},
        std::array<double, 4>{0.55, 0.8, 0.3, 0.5}}) {
    Box k{std::vector<double>(dim, y0 - m), std::vector<double>(dim, y1 + m)};
    k.lo[0] = x0 - m;
    k.hi[0] = x1 + m;
    keepOut.push_back(k);
  }
  Random random(seed);
  for (int placed = 0, tries = 0; placed < clutter && tries < 100000; ++tries) {
    Box b{std::vector<double>(dim), std::vector<double>(dim)};
    for (int i = 0; i < dim; ++i) {
      double side = random.uniform(0.05, 0.3), lo = random.uniform(0, 1 - side);
      b.lo[i] = lo;
      b.hi[i] = lo + side;
    }
    bool blocks = false;
    for (const Box& k : keepOut) {
      bool meets = true;
      for (int i = 0; i < dim && meets; ++i) meets = b.hi[i] > k.lo[i] && b.lo[i] < k.hi[i];
      blocks = blocks || meets;
    }
    if (blocks) continue;
    boxes.push_back(b);
    ++placed;
  }
  return BoxSpace(dim, std::move(boxes), "wall with a hole, d = " + std::to_string(dim));
}

Point wallStart(int dim) {
  Point p(dim, 0.3);
  p[0] = 0.2;
  return p;
}

Point wallGoal(int dim) {
  Point p(dim, 0.3);
  p[0] = 0.8;
  return p;
}

namespace {

Box wallPart(double y0, double y1, double z0, double z1) {
  return Box{{0.35, y0, z0}, {0.65, y1, z1}};
}

}  // namespace

BoxSpace flume(double eps) {
  if (!(eps > 0 && eps < 0.5)) throw std::invalid_argument("eps must be in (0, 0.5)");
  double h = eps * eps / 2;
  return BoxSpace(3, {wallPart(0, 0.5 - h, 0, 1), wallPart(0.5 + h, 1, 0, 1)}, "flume");
}

BoxSpace tunnel(double eps) {
  if (!(eps > 0 && eps < 0.5)) throw std::invalid_argument("eps must be in (0, 0.5)");
  double h = eps / 2;
  return BoxSpace(3,
                  {wallPart(0, 0.5 - h, 0, 1), wallPart(0.5 + h, 1, 0, 1),
                   wallPart(0.5 - h, 0.5 + h, 0, 0.5 - h), wallPart(0.5 - h, 0.5 + h, 0.5 + h, 1)},
                  "tunnel");
}

Point passageStart() { return {0.1, 0.2, 0.3}; }
Point passageGoal() { return {0.9, 0.8, 0.7}; }

}  // namespace mms::lab
