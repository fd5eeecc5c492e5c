#pragma once
// Seeded randomness with the same stream on every platform: std::mt19937_64's output is fixed
// by the standard, but the std distributions are not, so we map its bits ourselves.
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "mms/Geometry.h"

namespace mms {

class Random {
 public:
  explicit Random(uint64_t seed) : engine_(seed) {}
  /// Uniform in [0, 1).
  double uniform() { return double(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform in the box: x drawn first, then y.
  Vec2 uniformIn(const Box& b) {
    const double x = uniform(b.xmin, b.xmax);
    return {x, uniform(b.ymin, b.ymax)};
  }
  /// Uniform integer in [0, n).
  uint64_t below(uint64_t n) { return uint64_t(uniform() * double(n)) % n; }
  uint64_t bits() { return engine_(); }
  /// `count` of 0 .. n-1 in random order, none twice: the first `count` of a shuffle
  /// (Fisher-Yates from the back).
  std::vector<size_t> sample(size_t n, size_t count) {
    std::vector<size_t> out(n);
    for (size_t i = 0; i < n; ++i) out[i] = i;
    for (size_t i = n; i > 1; --i) std::swap(out[i - 1], out[below(i)]);
    out.resize(count);
    return out;
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace mms
