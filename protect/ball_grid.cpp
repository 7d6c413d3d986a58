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

std::size_t BallGrid::KeyHash::operator()(const Key& k) const {
  std::uint64_t h = mix(std::uint64_t(std::int64_t(k.level) * kTiers + k.tier));
  h = mix(h ^ std::uint64_t(k.x));
  h = mix(h ^ std::uint64_t(k.y));
  return static_cast<std::size_t>(mix(h ^ std::uint64_t(k.z)));
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
    cell_slot_.resize(n * kTiers);
  }
}

void BallGrid::insert(std::uint32_t id, const Vec3& c, double r) {
  assert(r > 0);
  grow(id);
  const int level = level_of(r);
  for (int t = 0; t < kTiers; ++t) {
    auto& cell = cells_[key_of(c, level, t)];
    cell_slot_[std::size_t(id) * kTiers + t] = static_cast<std::uint32_t>(cell.size());
    cell.push_back(id);
  }
  auto& list = levels_[level];
  level_slot_[id] = static_cast<std::uint32_t>(list.size());
  list.push_back(id);
}

void BallGrid::erase(std::uint32_t id, const Vec3& c, double r) {
  const int level = level_of(r);
  for (int t = 0; t < kTiers; ++t) {
    const auto it = cells_.find(key_of(c, level, t));
    assert(it != cells_.end());
    auto& cell = it->second;
    const std::uint32_t at = cell_slot_[std::size_t(id) * kTiers + t];
    assert(at < cell.size() && cell[at] == id);
    const std::uint32_t moved = cell.back();
    cell[at] = moved;
    cell_slot_[std::size_t(moved) * kTiers + t] = at;
    cell.pop_back();
    if (cell.empty()) cells_.erase(it);
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
