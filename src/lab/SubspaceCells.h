#pragma once
// Exact free-space cells of an axis-aligned affine subspace of a BoxSpace: the boxes that meet
// the subspace cut it into a grid (their faces' coordinates on each free axis); grid cells are
// wholly free or wholly blocked, and free cells that share a face form one FSC. A subspace
// with no free axis is a point, with one FSC or none.
#include <cstdint>
#include <optional>
#include <vector>

#include "lab/BoxSpace.h"

namespace mms::lab {

/// Fixes the coordinates not in `freeAxes`, at `point`'s values; the free ones vary in (0, 1).
struct AxisSubspace {
  std::vector<int> freeAxes;  // increasing
  Point point;                // full dimension; values on free axes are ignored

  bool fixes(int axis) const;
};

/// The subspace both lie in: fixed where either is fixed. None when both fix an axis at
/// different values (parallel and apart).
std::optional<AxisSubspace> intersect(const AxisSubspace& a, const AxisSubspace& b);

class SubspaceCells {
 public:
  /// Throws std::length_error when the grid would exceed `maxCells`.
  SubspaceCells(const BoxSpace& space, AxisSubspace subspace, size_t maxCells = 4'000'000);

  const AxisSubspace& subspace() const { return subspace_; }
  size_t components() const { return representatives_.size(); }
  /// The FSC holding x (a free point of the subspace, full dimension), or -1 when x is blocked
  /// or outside the cube. On a grid line, the cell above it.
  int locate(const Point& x) const;
  /// A free point (a cell centre) of each FSC, in FSC order.
  const std::vector<Point>& representatives() const { return representatives_; }
  size_t cellCount() const { return labels_.size(); }
  /// Per free axis, the grid's coordinates: 0, the box faces strictly inside, 1.
  const std::vector<std::vector<double>>& breaks() const { return breaks_; }

 private:
  // The grid on the free axes (breaks_, stride_) from the faces of the boxes that meet the
  // subspace; its number of cells.
  size_t makeGrid(const std::vector<const Box*>& meeting, size_t maxCells);
  std::vector<char> blockedCells(const std::vector<const Box*>& meeting, size_t cells) const;
  void labelComponents(const std::vector<char>& blocked);

  AxisSubspace subspace_;
  std::vector<std::vector<double>> breaks_;  // per free axis: 0, the faces inside, 1
  std::vector<size_t> stride_;
  std::vector<int32_t> labels_;  // per grid cell: its FSC, or -1 when blocked
  std::vector<Point> representatives_;
};

}  // namespace mms::lab
