#include "thinning_grid.h"

#include <cmath>

#include <delpsc/kernel/bits.h>

namespace delpsc::refine {

namespace {

std::uint64_t cell_hash(std::int64_t x, std::int64_t y, std::int64_t z) {
  const auto u = [](std::int64_t v) { return static_cast<std::uint64_t>(v); };
  return kernel::mix64(u(x) ^ kernel::mix64(u(y) ^ kernel::mix64(u(z))));
}

}  // namespace

ThinningGrid::ThinningGrid(double separation) {
  // The cell's diagonal is its side times sqrt(3): at most `separation`, with room for rounding.
  if (separation > 0 && std::isfinite(separation)) inverse_side_ = std::sqrt(3.0) / (separation * (1 - 1e-9));
}

bool ThinningGrid::admit(const Vec3& p) {
  if (inverse_side_ == 0 || !p.allFinite()) return true;
  Cell cell{};
  std::int64_t* const index[3] = {&cell.x, &cell.y, &cell.z};
  for (int i = 0; i < 3; ++i) {
    // floor(p / side) in doubles: a point moved across a cell's face by the rounding of the
    // product is still within the margin the side leaves (a relative 1e-9 of it).
    const double k = std::floor(p[i] * inverse_side_);
    if (!(std::abs(k) < 0x1p62)) return true;
    *index[i] = static_cast<std::int64_t>(k);
  }
  return occupy(cell);
}

bool ThinningGrid::occupy(const Cell& cell) {
  if (2 * (count_ + 1) > table_.size()) grow();
  const std::size_t mask = table_.size() - 1;
  for (std::size_t i = cell_hash(cell.x, cell.y, cell.z) & mask;; i = (i + 1) & mask) {
    Cell& slot = table_[i];
    if (slot.x == kFree) {
      slot = cell;
      ++count_;
      return true;
    }
    if (slot.x == cell.x && slot.y == cell.y && slot.z == cell.z) return false;
  }
}

void ThinningGrid::grow() {
  kernel::LargeVector<Cell> old(table_.empty() ? 64 : 2 * table_.size(), Cell{kFree, 0, 0});
  old.swap(table_);
  count_ = 0;
  for (const Cell& c : old)
    if (c.x != kFree) occupy(c);
}

}  // namespace delpsc::refine
