#pragma once
// The broad phase for many robots: which pairs of robots can come near each other at all. Each
// robot lies within a disc about its reference point (its radius), so two robots whose discs are
// a gap g apart are at least g apart. A sweep over the discs sorted by their left edge finds the
// pairs closer than a reach in O(k log k + pairs) instead of testing all k(k-1)/2 pairs, which
// for 500 robots is 125 000 ring tests per configuration.
//
// Pairs come out sorted (i < j, lexicographic), as the all-pairs loops visit them, so that
// callers report the same first contact with and without it.
#include <cstddef>
#include <utility>
#include <vector>

#include "mms/Geometry.h"

namespace mms {

class DiscSweep {
 public:
  using Pair = std::pair<size_t, size_t>;

  /// Pairs i < j whose discs' gap |c_i - c_j| - r_i - r_j is below `reach` and that `keep(i, j,
  /// gap)` accepts (a caller's finer, per-pair reach), sorted.
  template <class Keep>
  const std::vector<Pair>& near(const std::vector<Vec2>& centres, const std::vector<double>& radii,
                                double reach, const Keep& keep) {
    const size_t k = centres.size();
    order_.resize(k);
    for (size_t i = 0; i < k; ++i) order_[i] = i;
    std::sort(order_.begin(), order_.end(), [&](size_t a, size_t b) {
      const double la = centres[a].x - radii[a], lb = centres[b].x - radii[b];
      return la < lb || (la == lb && a < b);
    });
    pairs_.clear();
    for (size_t a = 0; a < k; ++a) {
      const size_t i = order_[a];
      const double right = centres[i].x + radii[i] + reach;
      for (size_t b = a + 1; b < k; ++b) {
        const size_t j = order_[b];
        if (centres[j].x - radii[j] > right) break;  // sorted: the rest lie further right
        const double gap = norm(centres[i] - centres[j]) - radii[i] - radii[j];
        if (gap < reach && keep(std::min(i, j), std::max(i, j), gap))
          pairs_.emplace_back(std::min(i, j), std::max(i, j));
      }
    }
    std::sort(pairs_.begin(), pairs_.end());
    return pairs_;
  }

 private:
  std::vector<size_t> order_;
  std::vector<Pair> pairs_;
};

}  // namespace mms
