// A set of occupied grid cells that admits at most one point per cell, for thinning a point set
// while bounding what is lost: every refused point lies within `separation` of an admitted one.
// PolygonDomain thins the initial sample's net with it where the net is out of all proportion to
// the other candidates (fans of needles, initial_sample.h's kNetExcess).
//
// Cells are cubes of side separation / sqrt(3) (shrunk by a relative 1e-9 for the rounding of a
// point's cell index), so two points of one cell are within `separation`. Points that are not
// finite, or so far out that their cell index leaves 2^62, are always admitted (never thinned).
//
// Units: lengths of the coordinates; separation > 0 and finite, else every point is admitted.
// Cost: O(1) expected per point (open addressing on a 64-bit mix of the cell), memory O(cells
// occupied).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>

#include <delpsc/kernel/large_array.h>
#include <delpsc/kernel/point.h>

namespace delpsc::refine {

class ThinningGrid {
 public:
  explicit ThinningGrid(double separation);

  /// True when p's cell held no admitted point (p is then admitted and its cell occupied), or p
  /// is never thinned (see the file comment); false when p lies within `separation` of a point
  /// admitted before.
  bool admit(const Vec3& p);

  /// Cells occupied so far.
  std::size_t occupied() const { return count_; }

 private:
  // A cell's integer coordinates; x = kFree marks an empty slot (cell indices stay below 2^62).
  struct Cell {
    std::int64_t x, y, z;
  };
  static constexpr std::int64_t kFree = std::numeric_limits<std::int64_t>::min();
  void grow();
  // Whether `cell` was free in the table (it is occupied after the call).
  bool occupy(const Cell& cell);

  double inverse_side_ = 0;  // 0: admit everything
  // Open addressing, a power of two in size, at most half full; on huge pages where they are
  // advised (a fan's net occupies ~10^5 cells: 24 bytes each, the table twice that).
  kernel::LargeVector<Cell> table_;
  std::size_t count_ = 0;
};

}  // namespace delpsc::refine
