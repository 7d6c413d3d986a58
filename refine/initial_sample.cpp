#include "initial_sample.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace delpsc::refine {

namespace {

// A hash grid of weighted points with open addressing, one chain per occupied cell, sized once
// for every point it will hold (it never rehashes, so slot positions stay valid). Every
// interaction the selection tests reaches at most one cell size (see select_separated_points),
// so the 27 cells around a point hold everything that can reject it.
class PointGrid {
 public:
  static constexpr std::uint32_t kEmpty = 0xffffffffu;

  PointGrid(const Vec3& origin, double cell, std::size_t points) : origin_(origin), inverse_(1 / cell) {
    std::size_t capacity = 64;
    while (capacity < 2 * points) capacity *= 2;
    slots_.assign(capacity, Slot{});
    points_.reserve(points);
    next_.reserve(points);
  }

  std::array<std::int64_t, 3> cell_of(const Vec3& p) const {
    return {static_cast<std::int64_t>(std::floor((p.x() - origin_.x()) * inverse_)),
            static_cast<std::int64_t>(std::floor((p.y() - origin_.y()) * inverse_)),
            static_cast<std::int64_t>(std::floor((p.z() - origin_.z()) * inverse_))};
  }
  /// 21 bits per axis, x major (offset so that cells just below the origin's pack too; cells
  /// farther out alias, which only lengthens a chain: every test is by distance).
  static std::uint64_t pack(const std::array<std::int64_t, 3>& c) {
    const auto u = [](std::int64_t v) { return static_cast<std::uint64_t>(v + (1 << 20)) & 0x1fffff; };
    return u(c[0]) << 42 | u(c[1]) << 21 | u(c[2]);
  }

  /// The slot of a cell: where its chain is, or the empty slot where it would start.
  std::size_t slot_of(std::uint64_t key) const {
    std::size_t i = static_cast<std::size_t>((key * 0x9e3779b97f4a7c15ull) >> 20) & (slots_.size() - 1);
    while (slots_[i].head != kEmpty && slots_[i].key != key) i = (i + 1) & (slots_.size() - 1);
    return i;
  }
  /// Adds w to the cell `key` whose slot_of is `slot` (no add in between).
  void add_at(std::size_t slot, std::uint64_t key, const WeightedPoint& w) {
    Slot& s = slots_[slot];
    s.key = key;
    points_.push_back(w);
    next_.push_back(s.head);
    s.head = static_cast<std::uint32_t>(points_.size() - 1);
  }
  void add(const WeightedPoint& w) {
    const std::uint64_t key = pack(cell_of(w.point()));
    add_at(slot_of(key), key, w);
  }

  /// Whether a point in the chain of `slot` has power distance to x at most `limit`.
  bool chain_within(std::size_t slot, const Vec3& x, double limit) const {
    for (std::uint32_t i = slots_[slot].head; i != kEmpty; i = next_[i]) {
      const WeightedPoint& w = points_[i];
      if ((w.point() - x).squaredNorm() - w.w <= limit) return true;
    }
    return false;
  }

 private:
  struct Slot {
    std::uint64_t key = 0;
    std::uint32_t head = kEmpty;
  };

  Vec3 origin_;
  double inverse_;
  std::vector<Slot> slots_;
  std::vector<WeightedPoint> points_;
  std::vector<std::uint32_t> next_;
};

}  // namespace

std::vector<std::uint32_t> select_separated_points(std::span<const Vec3> candidates,
                                                   std::span<const WeightedPoint> balls,
                                                   std::span<const Vec3> fixed, double spacing) {
  std::vector<std::uint32_t> chosen;
  if (!(spacing > 0) || !std::isfinite(spacing) || candidates.empty()) return chosen;
  // A ball B(c, r) rejects x when |x - c|² - r² <= spacing², so within sqrt(spacing² + r²);
  // a point within spacing: one cell of that size around x's reaches them all.
  double largest_weight = 0;
  for (const WeightedPoint& b : balls) largest_weight = std::max(largest_weight, b.w);
  const double cell = std::sqrt(spacing * spacing + largest_weight);
  kernel::Box3 box;
  std::vector<std::uint32_t> order;
  order.reserve(candidates.size());
  for (std::uint32_t i = 0; i < candidates.size(); ++i)
    if (candidates[i].allFinite()) {
      box.extend(candidates[i]);
      order.push_back(i);
    }
  if (order.empty() || !std::isfinite(cell) || (box.hi - box.lo).maxCoeff() / cell > double{1 << 19}) return chosen;
  PointGrid grid(box.lo, cell, balls.size() + fixed.size() + order.size());
  for (const WeightedPoint& b : balls) grid.add(b);
  for (const Vec3& p : fixed) grid.add(WeightedPoint::from(p));
  // Cell order (then index): the candidates of a cell are tested one after another against the
  // same 27 chains, found once per cell, and the chosen points pack like a scan line.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
  keyed.reserve(order.size());
  for (const std::uint32_t i : order) keyed.emplace_back(PointGrid::pack(grid.cell_of(candidates[i])), i);
  std::sort(keyed.begin(), keyed.end());
  const double limit = spacing * spacing;
  std::array<std::size_t, 27> around{};  // around[0]: the cell itself, tested first
  std::uint64_t current = 0;
  for (std::size_t k = 0; k < keyed.size(); ++k) {
    const auto [key, i] = keyed[k];
    if (k == 0 || key != current) {
      current = key;
      const auto c = grid.cell_of(candidates[i]);
      around[0] = grid.slot_of(key);
      std::size_t n = 1;
      for (std::int64_t dx = -1; dx <= 1; ++dx)
        for (std::int64_t dy = -1; dy <= 1; ++dy)
          for (std::int64_t dz = -1; dz <= 1; ++dz)
            if (dx != 0 || dy != 0 || dz != 0) around[n++] = grid.slot_of(PointGrid::pack({c[0] + dx, c[1] + dy, c[2] + dz}));
    }
    // A neighbour cell without points keeps the empty slot found above; only this cell gains
    // points meanwhile, and should it claim that slot its chain is merely tested twice.
    const Vec3& x = candidates[i];
    if (std::any_of(around.begin(), around.end(), [&](std::size_t slot) { return grid.chain_within(slot, x, limit); }))
      continue;
    grid.add_at(around[0], key, WeightedPoint::from(x));
    chosen.push_back(i);
  }
  return chosen;
}

}  // namespace delpsc::refine
