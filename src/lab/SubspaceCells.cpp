#include "lab/SubspaceCells.h"

#include <algorithm>
#include <boost/pending/disjoint_sets.hpp>
#include <stdexcept>

namespace mms::lab {

namespace {

// Steps a grid index through the box [lo, hi) (first axis fastest, as flat indices run);
// false once it has wrapped around.
bool nextIndex(std::vector<size_t>& idx, const std::vector<size_t>& lo,
               const std::vector<size_t>& hi) {
  for (size_t j = 0; j < idx.size(); ++j) {
    if (++idx[j] < hi[j]) return true;
    idx[j] = lo[j];
  }
  return false;
}

}  // namespace

bool AxisSubspace::fixes(int axis) const {
  return !std::binary_search(freeAxes.begin(), freeAxes.end(), axis);
}

std::optional<AxisSubspace> intersect(const AxisSubspace& a, const AxisSubspace& b) {
  AxisSubspace r{{}, a.point};
  for (size_t i = 0; i < a.point.size(); ++i) {
    int axis = int(i);
    bool fa = a.fixes(axis), fb = b.fixes(axis);
    if (fa && fb && a.point[i] != b.point[i]) return std::nullopt;
    if (!fa && !fb)
      r.freeAxes.push_back(axis);
    else
      r.point[i] = fa ? a.point[i] : b.point[i];
  }
  return r;
}

SubspaceCells::SubspaceCells(const BoxSpace& space, AxisSubspace subspace, size_t maxCells)
    : subspace_(std::move(subspace)) {
  const int d = space.dim();
  for (int i = 0; i < d; ++i)
    if (subspace_.fixes(i) && !(subspace_.point[i] > 0 && subspace_.point[i] < 1)) {
      return;  // outside the open cube: nothing free
    }
  // The boxes that meet the subspace, and the grid their faces induce on the free axes.
  std::vector<const Box*> meeting;
  for (const Box& b : space.obstacles()) {
    bool meets = true;
    for (int i = 0; i < d && meets; ++i)
      if (subspace_.fixes(i))
        meets = b.lo[i] <= subspace_.point[i] && subspace_.point[i] <= b.hi[i];
    if (meets) meeting.push_back(&b);
  }
  const size_t cells = makeGrid(meeting, maxCells);
  labelComponents(blockedCells(meeting, cells));
}

size_t SubspaceCells::makeGrid(const std::vector<const Box*>& meeting, size_t maxCells) {
  const size_t k = subspace_.freeAxes.size();
  breaks_.resize(k);
  size_t cells = 1;
  for (size_t j = 0; j < k; ++j) {
    int axis = subspace_.freeAxes[j];
    std::vector<double>& br = breaks_[j];
    br = {0.0, 1.0};
    for (const Box* b : meeting)
      for (double v : {b->lo[axis], b->hi[axis]})
        if (v > 0 && v < 1) br.push_back(v);
    std::sort(br.begin(), br.end());
    br.erase(std::unique(br.begin(), br.end()), br.end());
    cells *= br.size() - 1;
    if (cells > maxCells) throw std::length_error("subspace grid too fine");
  }
  stride_.assign(k, 1);
  for (size_t j = 1; j < k; ++j) stride_[j] = stride_[j - 1] * (breaks_[j - 1].size() - 1);
  return cells;
}

// A box covers a contiguous index range per axis: the cells inside it are blocked.
std::vector<char> SubspaceCells::blockedCells(const std::vector<const Box*>& meeting,
                                              size_t cells) const {
  const size_t k = subspace_.freeAxes.size();
  std::vector<char> blocked(cells, 0);
  std::vector<size_t> lo(k), hi(k), idx(k);
  for (const Box* b : meeting) {
    for (size_t j = 0; j < k; ++j) {
      const std::vector<double>& br = breaks_[j];
      int axis = subspace_.freeAxes[j];
      lo[j] = std::lower_bound(br.begin(), br.end(), b->lo[axis]) - br.begin();
      hi[j] = std::lower_bound(br.begin(), br.end(), b->hi[axis]) - br.begin();
      // Box faces outside (0, 1) clamp to the cube.
      lo[j] = std::min(lo[j], br.size() - 1);
      hi[j] = std::min(hi[j], br.size() - 1);
      if (b->lo[axis] <= 0) lo[j] = 0;
      if (b->hi[axis] >= 1) hi[j] = br.size() - 1;
    }
    bool empty = false;
    for (size_t j = 0; j < k; ++j) empty = empty || lo[j] >= hi[j];
    if (empty) continue;
    idx = lo;
    do {
      size_t flat = 0;
      for (size_t j = 0; j < k; ++j) flat += idx[j] * stride_[j];
      blocked[flat] = 1;
    } while (nextIndex(idx, lo, hi));
  }
  return blocked;
}

// Free cells sharing a face are one FSC; each FSC's representative is its first cell's centre.
void SubspaceCells::labelComponents(const std::vector<char>& blocked) {
  const size_t k = subspace_.freeAxes.size(), cells = blocked.size();
  std::vector<size_t> idx(k, 0), zero(k, 0), count(k);
  for (size_t j = 0; j < k; ++j) count[j] = breaks_[j].size() - 1;
  std::vector<size_t> rank(cells), parent(cells);
  boost::disjoint_sets<size_t*, size_t*> sets(rank.data(), parent.data());
  for (size_t c = 0; c < cells; ++c) sets.make_set(c);
  for (size_t c = 0; c < cells; ++c) {
    if (!blocked[c])
      for (size_t j = 0; j < k; ++j)
        if (idx[j] > 0 && !blocked[c - stride_[j]]) sets.union_set(c, c - stride_[j]);
    nextIndex(idx, zero, count);
  }
  labels_.assign(cells, -1);
  std::vector<int32_t> labelOfRoot(cells, -1);
  std::fill(idx.begin(), idx.end(), 0);
  for (size_t c = 0; c < cells; ++c) {
    if (!blocked[c]) {
      size_t root = sets.find_set(c);
      if (labelOfRoot[root] < 0) {
        labelOfRoot[root] = int32_t(representatives_.size());
        Point p = subspace_.point;
        for (size_t j = 0; j < k; ++j)
          p[subspace_.freeAxes[j]] = 0.5 * (breaks_[j][idx[j]] + breaks_[j][idx[j] + 1]);
        representatives_.push_back(std::move(p));
      }
      labels_[c] = labelOfRoot[root];
    }
    nextIndex(idx, zero, count);
  }
}

int SubspaceCells::locate(const Point& x) const {
  if (labels_.empty()) return -1;
  size_t flat = 0;
  for (size_t j = 0; j < breaks_.size(); ++j) {
    double v = x[subspace_.freeAxes[j]];
    if (!(v > 0 && v < 1)) return -1;
    const std::vector<double>& br = breaks_[j];
    size_t cell = std::upper_bound(br.begin(), br.end(), v) - br.begin() - 1;
    flat += cell * stride_[j];
  }
  return labels_[flat];
}

}  // namespace mms::lab
