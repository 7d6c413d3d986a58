#include "initial_sample.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace delpsc::refine {

namespace {

// A hash grid of weighted points with open addressing: one chain per occupied cell. Every
// interaction the selection tests reaches at most one cell size (see select_separated_points),
// so the 27 cells around a point hold everything that can reject it.
class PointGrid {
 public:
  PointGrid(const Vec3& origin, double cell, std::size_t expected) : origin_(origin), inverse_(1 / cell) {
    std::size_t capacity = 64;
    while (capacity < 2 * expected) capacity *= 2;
    slots_.assign(capacity, Slot{});
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

  void add(const WeightedPoint& w) {
    Slot& slot = find(pack(cell_of(w.point())));
    if (slot.head == kEmpty) {
      slot.key = pack(cell_of(w.point()));
      ++occupied_;
    }
    points_.push_back(w);
    next_.push_back(slot.head);
    slot.head = static_cast<std::uint32_t>(points_.size() - 1);
    if (occupied_ * 2 > slots_.size()) grow();
  }

  /// Whether some point of the grid has power distance to x at most `limit`.
  bool any_within(const Vec3& x, double limit) const {
    const auto c = cell_of(x);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const Slot& slot = find_const(pack({c[0] + dx, c[1] + dy, c[2] + dz}));
          for (std::uint32_t i = slot.head; i != kEmpty; i = next_[i]) {
            const WeightedPoint& w = points_[i];
            if ((w.point() - x).squaredNorm() - w.w <= limit) return true;
          }
        }
    return false;
  }

 private:
  static constexpr std::uint32_t kEmpty = 0xffffffffu;
  struct Slot {
    std::uint64_t key = 0;
    std::uint32_t head = kEmpty;
  };

  std::size_t home(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9e3779b97f4a7c15ull) >> 20) & (slots_.size() - 1);
  }
  Slot& find(std::uint64_t key) {
    std::size_t i = home(key);
    while (slots_[i].head != kEmpty && slots_[i].key != key) i = (i + 1) & (slots_.size() - 1);
    return slots_[i];
  }
  const Slot& find_const(std::uint64_t key) const {
    std::size_t i = home(key);
    while (slots_[i].head != kEmpty && slots_[i].key != key) i = (i + 1) & (slots_.size() - 1);
    return slots_[i];
  }
  void grow() {
    std::vector<Slot> old(2 * slots_.size());
    old.swap(slots_);
    for (const Slot& s : old)
      if (s.head != kEmpty) find(s.key) = s;
  }

  Vec3 origin_;
  double inverse_;
  std::vector<Slot> slots_;
  std::size_t occupied_ = 0;
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
  PointGrid grid(box.lo, cell, balls.size() + fixed.size() + order.size() / 4);
  for (const WeightedPoint& b : balls) grid.add(b);
  for (const Vec3& p : fixed) grid.add(WeightedPoint::from(p));
  // Cell order (then index): neighbouring candidates are tested one after another, which keeps
  // the grid's chains in cache and packs the chosen points like a scan line.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
  keyed.reserve(order.size());
  for (const std::uint32_t i : order) keyed.emplace_back(PointGrid::pack(grid.cell_of(candidates[i])), i);
  std::sort(keyed.begin(), keyed.end());
  const double limit = spacing * spacing;
  for (const auto& [key, i] : keyed) {
    if (grid.any_within(candidates[i], limit)) continue;
    grid.add(WeightedPoint::from(candidates[i]));
    chosen.push_back(i);
  }
  return chosen;
}

}  // namespace delpsc::refine
