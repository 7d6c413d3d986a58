#include "vertex_crowding.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include <delpsc/kernel/aabb_tree.h>

namespace delpsc::refine {

VertexCrowd densest_crowd(std::span<const Vec3> vertices, double cell) {
  VertexCrowd crowd;
  if (!(cell > 0) || !std::isfinite(cell)) return crowd;
  kernel::Box3 box;
  for (const Vec3& v : vertices)
    if (v.allFinite()) box.extend(v);
  if (box.empty() || !(box.hi - box.lo).allFinite()) return crowd;  // no finite vertex, or an extent overflowing
  // 21 bits per axis pack a cube's index in 63; 2^20 cubes an axis leave a margin for rounding.
  constexpr double kMostCubes = double{1 << 20};
  cell = std::max(cell, (box.hi - box.lo).maxCoeff() / kMostCubes);
  const auto cube_of = [&](const Vec3& v) {
    std::array<std::int64_t, 3> c{};
    for (int k = 0; k < 3; ++k) c[k] = static_cast<std::int64_t>(std::floor((v[k] - box.lo[k]) / cell));
    return c;
  };
  const auto key = [](const std::array<std::int64_t, 3>& c) {
    return static_cast<std::uint64_t>(c[0]) << 42 | static_cast<std::uint64_t>(c[1]) << 21 |
           static_cast<std::uint64_t>(c[2]);
  };
  std::unordered_map<std::uint64_t, std::size_t> count;
  count.reserve(vertices.size());
  std::uint64_t fullest = 0;
  std::size_t most = 0;
  for (const Vec3& v : vertices) {
    if (!v.allFinite()) continue;
    const std::uint64_t k = key(cube_of(v));
    if (const std::size_t n = ++count[k]; n > most) most = n, fullest = k;
  }
  crowd.fullest_cube = most;
  const std::array<std::int64_t, 3> f{static_cast<std::int64_t>(fullest >> 42),
                                      static_cast<std::int64_t>(fullest >> 21 & 0x1fffff),
                                      static_cast<std::int64_t>(fullest & 0x1fffff)};
  for (const Vec3& v : vertices) {
    if (!v.allFinite()) continue;
    const auto c = cube_of(v);
    if (std::abs(c[0] - f[0]) <= 1 && std::abs(c[1] - f[1]) <= 1 && std::abs(c[2] - f[2]) <= 1) {
      ++crowd.vertices;
      crowd.centre += v;
    }
  }
  crowd.centre /= static_cast<double>(crowd.vertices);
  return crowd;
}

}  // namespace delpsc::refine
