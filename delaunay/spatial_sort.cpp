// BRIO rounds + Hilbert order; see spatial_sort.h.
#include "spatial_sort.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include <delpsc/kernel/bits.h>

namespace delpsc::delaunay {
namespace {

/// Spreads the low 21 bits of v to every third bit of the result (bit b to bit 3b).
std::uint64_t spread_by_three(std::uint32_t v) {
  std::uint64_t x = v & 0x1fffffu;
  x = (x | x << 32) & 0x001f00000000ffffull;
  x = (x | x << 16) & 0x001f0000ff0000ffull;
  x = (x | x << 8) & 0x100f00f00f00f00full;
  x = (x | x << 4) & 0x10c30c30c30c30c3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}

/// Position along the Hilbert curve of the grid cell (x[0], x[1], x[2]), each < 2^bits.
/// Skilling's method: turn the axes into the "transposed" Hilbert index by undoing the curve's
/// rotations and reflections level by level, Gray-encode, then interleave the bits (most
/// significant level first). Written without data-dependent branches: the bits tested are
/// coin tosses, and as branches they were mispredicted about 30 times a key (hilbert_sort was
/// 3.4% of meshing the cube at 0.456%).
std::uint64_t hilbert_key(std::array<std::uint32_t, 3> cell, int bits) {
  std::uint32_t x0 = cell[0], x1 = cell[1], x2 = cell[2];  // scalars: kept in registers
  const std::uint32_t top = 1u << (bits - 1);
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    const std::uint32_t p = q - 1;
    // Bit q of x_i set: invert the low bits of x_0; clear: exchange the low bits of x_0 and
    // x_i (for x_0 itself the exchange is a no-op).
    x0 ^= p & (0u - ((x0 & q) != 0));
    for (std::uint32_t* xi : {&x1, &x2}) {
      const std::uint32_t set = 0u - ((*xi & q) != 0);
      const std::uint32_t t = (x0 ^ *xi) & p & ~set;
      x0 ^= (p & set) | t;
      *xi ^= t;
    }
  }
  x1 ^= x0;
  x2 ^= x1;
  std::uint32_t t = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1) t ^= (q - 1) & (0u - ((x2 & q) != 0));
  x0 ^= t;
  x1 ^= t;
  x2 ^= t;
  // Bit b of x_0, x_1, x_2 goes to bit 3b + 2, 3b + 1, 3b of the key.
  return spread_by_three(x0) << 2 | spread_by_three(x1) << 1 | spread_by_three(x2);
}

/// splitmix64: a tiny, well-mixed deterministic generator for the shuffle.
std::uint64_t next_random(std::uint64_t& state) { return kernel::mix64(state += 0x9e3779b97f4a7c15ull); }

}  // namespace

void hilbert_sort(std::span<const WeightedPoint> points, std::span<std::uint32_t> indices, int bits) {
  if (indices.size() < 2) return;
  bits = std::clamp(bits, 1, 21);
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::numeric_limits<double>::infinity();
    hi[k] = -lo[k];
  }
  for (const std::uint32_t i : indices) {
    const double* p = points[i].data();
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  // One scale for all axes keeps the curve's cells cubes (a flat set stays well ordered).
  const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  const double cells = std::ldexp(1.0, bits);
  const double scale = extent > 0 ? cells / extent : 0;
  const auto max_cell = static_cast<std::uint32_t>(cells - 1);

  kernel::KeyedIndices items(indices.size());
  for (std::size_t j = 0; j < indices.size(); ++j) {
    const double* p = points[indices[j]].data();
    std::array<std::uint32_t, 3> cell;
    for (int k = 0; k < 3; ++k) {
      const double c = (p[k] - lo[k]) * scale;  // in [0, 2^bits]; clamp the top edge
      cell[k] = std::min(static_cast<std::uint32_t>(c), max_cell);
    }
    items[j] = {hilbert_key(cell, bits), indices[j]};
  }
  kernel::radix_sort_by_key(items, 3 * bits);
  for (std::size_t j = 0; j < indices.size(); ++j) indices[j] = items[j].second;
}

void brio_order(std::span<const WeightedPoint> points, std::vector<std::uint32_t>& order,
                std::uint64_t seed, std::size_t small_round) {
  const std::size_t n = points.size();
  order.resize(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(i);
  // Fisher–Yates shuffle: each round is then a random sample of the batch.
  std::uint64_t state = seed;
  for (std::size_t i = n; i > 1; --i) {
    const std::size_t j = next_random(state) % i;
    std::swap(order[i - 1], order[j]);
  }
  // Rounds [b_k, b_{k-1}) with b_0 = n, b_k = b_{k-1} / 8, down to small_round points.
  std::size_t end = n;
  while (end > 0) {
    std::size_t begin = end / 8;
    if (begin < small_round) begin = 0;
    // A grid fine enough for the round even when its points lie on a surface, as the mesher's
    // sample does: 2^(2 bits) >= 8 n, at least 2^4 per axis. Sized for points filling the volume
    // (2^(3 bits) >= 8 n), a surface sample shared each occupied cell among several points in no
    // particular order, and the walks from one insertion to the next took 18 steps on fandisk's
    // and the elephant's samples, 6 on the cube's; now 5-6 and 3 (meshing fandisk -8 to -11%,
    // anchor -7%, the elephant -5%). For points filling the volume the finer grid is within
    // +-3% (bench_triangulation uniform).
    int bits = 4;
    while (bits < 21 && (std::size_t{1} << (2 * bits)) < 8 * (end - begin)) ++bits;
    hilbert_sort(points, std::span<std::uint32_t>(order.data() + begin, end - begin), bits);
    end = begin;
  }
}

}  // namespace delpsc::delaunay
