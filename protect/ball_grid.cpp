// The hierarchical hash grid of protect/ball_grid.h.
#include "ball_grid.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <delpsc/kernel/bits.h>

namespace delpsc::protect::detail {

namespace {

// splitmix64 finaliser: cell keys are small consecutive integers, which std::hash would map to
// themselves and cluster in the buckets.
std::uint64_t mix(std::uint64_t x) { return kernel::mix64(x + 0x9e3779b97f4a7c15ull); }

}  // namespace

std::uint64_t BallGrid::hash(const Key& k) {
  std::uint64_t h = mix(std::uint64_t(std::int64_t(k.level) * kTiers + k.tier));
  h = mix(h ^ std::uint64_t(k.x));
  h = mix(h ^ std::uint64_t(k.y));
  return mix(h ^ std::uint64_t(k.z));
}

std::size_t BallGrid::find(std::uint64_t h) const {
  if (slots_.empty()) return kNotFound;
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t i = h & mask;; i = (i + 1) & mask) {
    const Slot& s = slots_[i];
    if (!s.used) return kNotFound;
    if (s.hash == h) return s.head == kNone ? kNotFound : i;
  }
}

std::size_t BallGrid::find_or_add(std::uint64_t h) {
  // At most half the slots hold a key, so probes stay short; a rebuild drops emptied cells.
  if (2 * (used_ + 1) > slots_.size()) {
    std::size_t live = 0;
    for (const Slot& s : slots_) live += s.used && s.head != kNone;
    std::size_t capacity = 64;
    while (capacity < 4 * (live + 1)) capacity *= 2;
    rebuild_table(capacity);
  }
  const std::size_t mask = slots_.size() - 1;
  std::size_t i = h & mask;
  for (; slots_[i].used; i = (i + 1) & mask)
    if (slots_[i].hash == h) return i;
  slots_[i].used = 1;
  slots_[i].hash = h;
  slots_[i].head = kNone;
  ++used_;
  return i;
}

void BallGrid::rebuild_table(std::size_t capacity) {
  kernel::LargeVector<Slot> old(capacity);
  old.swap(slots_);
  used_ = 0;
  const std::size_t mask = capacity - 1;
  for (const Slot& s : old) {
    if (!s.used || s.head == kNone) continue;
    std::size_t i = s.hash & mask;
    while (slots_[i].used) i = (i + 1) & mask;
    slots_[i] = s;
    ++used_;
  }
}

int BallGrid::level_of(double r) { return std::ilogb(r); }

double BallGrid::cell_size(int level, int tier) { return std::ldexp(1.0, level + 1 + 2 * tier); }

std::int64_t BallGrid::cell_coordinate(double x, double cell) {
  // Clamped far inside the int64 range: a query box that wide falls back to the level's list.
  const double q = std::clamp(std::floor(x / cell), -0x1p60, 0x1p60);
  return static_cast<std::int64_t>(q);
}

BallGrid::Key BallGrid::key_of(const Vec3& c, int level, int tier) {
  const double cell = cell_size(level, tier);
  return {level, tier, cell_coordinate(c.x(), cell), cell_coordinate(c.y(), cell), cell_coordinate(c.z(), cell)};
}

void BallGrid::grow(std::uint32_t id) {
  if (id >= level_slot_.size()) {
    const std::size_t n = std::max<std::size_t>(std::size_t(id) + 1, 2 * level_slot_.size());
    level_slot_.resize(n);
    next_.resize(n * kTiers);
    prev_.resize(n * kTiers);
  }
}

void BallGrid::insert(std::uint32_t id, const Vec3& c, double r) {
  assert(r > 0);
  grow(id);
  const int level = level_of(r);
  for (int t = 0; t < kTiers; ++t) {
    Slot& cell = slots_[find_or_add(hash(key_of(c, level, t)))];
    const std::size_t k = std::size_t(id) * kTiers + t;
    next_[k] = cell.head;
    prev_[k] = kNone;
    if (cell.head != kNone) prev_[std::size_t(cell.head) * kTiers + t] = id;
    cell.head = id;
  }
  auto& list = levels_[level];
  level_slot_[id] = static_cast<std::uint32_t>(list.size());
  list.push_back(id);
}

void BallGrid::erase(std::uint32_t id, const Vec3& c, double r) {
  const int level = level_of(r);
  for (int t = 0; t < kTiers; ++t) {
    const std::size_t k = std::size_t(id) * kTiers + t;
    const std::uint32_t before = prev_[k], after = next_[k];
    if (before == kNone) {
      const std::size_t slot = find(hash(key_of(c, level, t)));
      assert(slot != kNotFound && slots_[slot].head == id);
      slots_[slot].head = after;  // an emptied cell keeps its slot until the next rebuild
    } else {
      next_[std::size_t(before) * kTiers + t] = after;
    }
    if (after != kNone) prev_[std::size_t(after) * kTiers + t] = before;
  }
  const auto list = levels_.find(level);
  const std::uint32_t at = level_slot_[id];
  assert(at < list->second.size() && list->second[at] == id);
  const std::uint32_t moved = list->second.back();
  list->second[at] = moved;
  level_slot_[moved] = at;
  list->second.pop_back();
  if (list->second.empty()) levels_.erase(list);
}

}  // namespace delpsc::protect::detail
