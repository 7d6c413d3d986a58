// Internal to protect/: the spatial index of BallSet (balls.h) — which balls may meet a query ball.
//
// Balls differ in radius by orders of magnitude (a small angle or a short curve next to balls of
// size λ), so one uniform grid would be either too fine for the big balls or too coarse for the
// small ones. This is a hierarchical hash grid: a ball of radius r in [2^k, 2^(k+1)) lives at
// level k. A ball of level k that meets B(c, R) has its centre within reach = R + 2^(k+1) of c,
// so per level the query visits the cells of the box c +- reach. So that a big query does not
// visit a huge number of small cells, each level is gridded at kTiers resolutions, cell sides
// 2^(k+1) * 4^t, t = 0 .. kTiers-1, every ball in the one cell of each tier holding its centre;
// the query uses the finest tier whose box has at most 27 cells (3 per axis), or the level's
// list when even the coarsest box would hold more cells than the level has balls.
// Insert and erase are O(kTiers) expected (swap-remove with stored slots); a query costs
// O(levels * (27 + candidates)), the candidates within about 2 * reach of c per axis.
#pragma once

#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>

#include <delpsc/kernel/point.h>

namespace delpsc::protect::detail {

class BallGrid {
 public:
  /// Adds ball `id` (any uint32 value, used as an index: keep ids dense) of centre c and radius
  /// r > 0. Each id at most once at a time.
  void insert(std::uint32_t id, const Vec3& c, double r);
  /// Removes ball `id`, inserted earlier with the same c and r.
  void erase(std::uint32_t id, const Vec3& c, double r);
  /// Calls f(id) for every ball whose centre is within R + 2^(level+1) of c (per axis, at
  /// least): a superset of the balls meeting B(c, R); the caller tests the distance.
  template <class F>
  void for_each_candidate(const Vec3& c, double R, F&& f) const;

 private:
  static constexpr int kTiers = 6;  // cell sides up to 4^5 = 1024 times the finest
  struct Key {
    int level, tier;
    std::int64_t x, y, z;
    friend bool operator==(const Key&, const Key&) = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const;
  };
  static int level_of(double r);
  static double cell_size(int level, int tier);
  static std::int64_t cell_coordinate(double x, double cell);
  static Key key_of(const Vec3& c, int level, int tier);
  void grow(std::uint32_t id);

  std::unordered_map<Key, std::vector<std::uint32_t>, KeyHash> cells_;
  std::map<int, std::vector<std::uint32_t>> levels_;  // level -> ids, for the widest queries
  std::vector<std::uint32_t> cell_slot_;              // position of id in its cell of tier t: [kTiers id + t]
  std::vector<std::uint32_t> level_slot_;             // position of id in its level's list
};

template <class F>
void BallGrid::for_each_candidate(const Vec3& c, double R, F&& f) const {
  for (const auto& [level, ids] : levels_) {
    const double reach = R + cell_size(level, 0);
    int tier = 0;
    std::int64_t lo[3], hi[3];
    double cells = 0;
    for (; tier < kTiers; ++tier) {
      const double cell = cell_size(level, tier);
      cells = 1;
      for (int a = 0; a < 3; ++a) {
        lo[a] = cell_coordinate(c[a] - reach, cell);
        hi[a] = cell_coordinate(c[a] + reach, cell);
        cells *= double(hi[a] - lo[a] + 1);
      }
      if (cells <= 27) break;
    }
    if (tier == kTiers) --tier;
    if (cells >= double(ids.size())) {
      for (const std::uint32_t id : ids) f(id);
      continue;
    }
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
          const auto it = cells_.find(Key{level, tier, x, y, z});
          if (it == cells_.end()) continue;
          for (const std::uint32_t id : it->second) f(id);
        }
  }
}

}  // namespace delpsc::protect::detail
