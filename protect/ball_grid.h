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
// Insert and erase are O(kTiers) expected; a query costs O(levels * (27 + candidates)), the
// candidates within about 2 * reach of c per axis.
//
// Storage is flat: one open-addressing table of cells (linear probing) whose slots hold the head
// of a doubly linked chain through per-(ball, tier) arrays. A std::unordered_map of
// std::vector per cell cost two allocations per cell and tier, six cells a ball: at 1.65 million
// balls (fandisk at 0.0003%) freeing them alone took 1.3 s, and the map's lookups were a
// quarter of Protect's time at 0.02%. A slot keeps the cell key's 64-bit hash, not the key: two
// cells whose hashes agreed would share one chain, which only adds candidates (callers test
// the distance; erase unlinks from whatever chain holds the ball). A cell emptied by erase
// keeps its slot until the table next grows, which rebuilds it from the non-empty cells.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

#include <delpsc/kernel/large_array.h>
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
  static constexpr std::uint32_t kNone = 0xffffffffu;
  static constexpr std::size_t kNotFound = static_cast<std::size_t>(-1);
  struct Key {
    int level, tier;
    std::int64_t x, y, z;
    friend bool operator==(const Key&, const Key&) = default;
  };
  struct Slot {
    std::uint64_t hash = 0;      // of the cell's key
    std::uint32_t head = kNone;  // the cell's first ball (kNone: an emptied cell)
    std::uint32_t used = 0;      // 1: the slot holds a cell
  };
  static std::uint64_t hash(const Key& k);
  static int level_of(double r);
  static double cell_size(int level, int tier);
  static std::int64_t cell_coordinate(double x, double cell);
  static Key key_of(const Vec3& c, int level, int tier);
  void grow(std::uint32_t id);
  /// The non-empty cell of hash `h`, or kNotFound.
  std::size_t find(std::uint64_t h) const;
  /// The slot of hash `h`, claimed if absent (the table may be rebuilt first).
  std::size_t find_or_add(std::uint64_t h);
  void rebuild_table(std::size_t capacity);

  // From the huge-page pool (kernel/large_array.h): a table of 10^4-10^5 slots in a fresh
  // std::vector faulted in its pages on every Protect run (+20-30% at 2,000-3,000 balls).
  kernel::LargeVector<Slot> slots_;                   // a power of two in size, or empty
  std::size_t used_ = 0;                              // slots holding a key
  kernel::LargeVector<std::uint32_t> next_, prev_;    // [kTiers id + t]: id's neighbours in its tier-t cell
  std::map<int, std::vector<std::uint32_t>> levels_;  // level -> ids, for the widest queries
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
          const std::size_t slot = find(hash(Key{level, tier, x, y, z}));
          if (slot == kNotFound) continue;
          for (std::uint32_t id = slots_[slot].head; id != kNone; id = next_[std::size_t(id) * kTiers + tier]) f(id);
        }
  }
}

}  // namespace delpsc::protect::detail
