#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include <delpsc/delaunay/spatial_sort.h>

#include "support/generators.h"

using namespace delpsc;
using delpsc::delaunay::brio_order;
using delpsc::delaunay::hilbert_sort;

namespace {

double path_length(const std::vector<WeightedPoint>& pts, const std::vector<std::uint32_t>& order) {
  double total = 0;
  for (std::size_t i = 1; i < order.size(); ++i) total += (pts[order[i]].point() - pts[order[i - 1]].point()).norm();
  return total;
}

bool is_permutation_of_range(std::vector<std::uint32_t> order, std::size_t n) {
  if (order.size() != n) return false;
  std::sort(order.begin(), order.end());
  for (std::size_t i = 0; i < n; ++i)
    if (order[i] != i) return false;
  return true;
}

// Sorts the k^3 unit grid (given in reverse order) on a 2^bits grid and requires every step of
// the resulting order to join face neighbours.
void check_unit_steps(int k, int bits) {
  CAPTURE(k);
  CAPTURE(bits);
  const auto pts = test::grid_points(k, k, k);
  std::vector<std::uint32_t> order(pts.size());
  std::iota(order.begin(), order.end(), 0u);
  std::reverse(order.begin(), order.end());
  hilbert_sort(pts, order, bits);
  CHECK(is_permutation_of_range(order, pts.size()));
  for (std::size_t i = 1; i < order.size(); ++i) {
    const double d = (pts[order[i]].point() - pts[order[i - 1]].point()).norm();
    REQUIRE(d == 1.0);
  }
}

}  // namespace

TEST_CASE("hilbert_sort visits a full grid by unit steps") {
  // On the 2^b grid with one point per curve cell, a Hilbert curve moves to a face neighbour at
  // every step: a strong check of the key computation (a Morton order would jump).
  for (int bits = 1; bits <= 4; ++bits) check_unit_steps(1 << bits, bits);
}

TEST_CASE("hilbert_sort keeps the coarse curve's order at fine grids, up to 21 bits") {
  // A k^3 grid of points sorted on a 2^bits grid: each point falls in its own cell of the
  // coarse k^3 grid, and a Hilbert key's top bits are the coarse curve's key, so the order
  // still moves by unit steps. Checks the key's top levels at widths the full grids above
  // (at most 4 bits) do not reach; every level is checked by the next test.
  for (const int k : {2, 4, 8})
    for (const int bits : {6, 10, 16, 21}) check_unit_steps(k, bits);
}

namespace {

// Skilling's transform written plainly, with branches, as a reference: the position along the
// Hilbert curve of cell x (each coordinate below 2^bits).
std::uint64_t reference_hilbert_key(std::array<std::uint32_t, 3> x, int bits) {
  const std::uint32_t top = 1u << (bits - 1);
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    const std::uint32_t p = q - 1;
    for (int i = 0; i < 3; ++i) {
      if (x[i] & q) {
        x[0] ^= p;
      } else {
        const std::uint32_t t = (x[0] ^ x[i]) & p;
        x[0] ^= t;
        x[i] ^= t;
      }
    }
  }
  x[1] ^= x[0];
  x[2] ^= x[1];
  std::uint32_t t = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1)
    if (x[2] & q) t ^= q - 1;
  for (auto& xi : x) xi ^= t;
  std::uint64_t key = 0;
  for (int b = bits - 1; b >= 0; --b)
    for (int i = 0; i < 3; ++i) key = (key << 1) | ((x[i] >> b) & 1u);
  return key;
}

}  // namespace

TEST_CASE("hilbert_sort orders random cells as the plain Hilbert key does, every level") {
  // Points at integer coordinates in [0, 2^bits) plus one at 2^bits in every coordinate: the
  // sort's grid is then the integer grid itself (that last point clamped into the top cell),
  // and its order must be a stable sort by the reference key - which depends on every level
  // of every coordinate, unlike the grids above.
  test::Rng rng(21);
  for (int bits = 1; bits <= 21; ++bits) {
    CAPTURE(bits);
    const std::int64_t cells = std::int64_t{1} << bits;
    std::vector<WeightedPoint> pts;
    std::vector<std::array<std::uint32_t, 3>> cell;
    for (int i = 0; i < 3000; ++i) {
      const std::array<std::int64_t, 3> c{rng.integer(0, cells - 1), rng.integer(0, cells - 1), rng.integer(0, cells - 1)};
      pts.push_back(WeightedPoint::from(Vec3(double(c[0]), double(c[1]), double(c[2]))));
      cell.push_back({std::uint32_t(c[0]), std::uint32_t(c[1]), std::uint32_t(c[2])});
    }
    pts.push_back(WeightedPoint::from(Vec3(0, 0, 0)));
    cell.push_back({0, 0, 0});
    pts.push_back(WeightedPoint::from(Vec3(double(cells), double(cells), double(cells))));
    const auto top = std::uint32_t(cells - 1);
    cell.push_back({top, top, top});
    std::vector<std::uint32_t> order(pts.size()), expected(pts.size());
    std::iota(order.begin(), order.end(), 0u);
    std::iota(expected.begin(), expected.end(), 0u);
    std::stable_sort(expected.begin(), expected.end(), [&](std::uint32_t a, std::uint32_t b) {
      return reference_hilbert_key(cell[a], bits) < reference_hilbert_key(cell[b], bits);
    });
    hilbert_sort(pts, order, bits);
    CHECK(order == expected);
  }
}

TEST_CASE("brio_order is a deterministic permutation with local rounds") {
  test::Rng rng(7);
  for (const std::size_t n : {0u, 1u, 2u, 63u, 64u, 65u, 1000u, 20000u}) {
    const auto pts = test::uniform_points(rng, n, 0, 1);
    std::vector<std::uint32_t> a, b;
    brio_order(pts, a);
    brio_order(pts, b);
    CHECK(is_permutation_of_range(a, n));
    CHECK(a == b);
    if (n >= 1000) {
      std::vector<std::uint32_t> identity(n);
      std::iota(identity.begin(), identity.end(), 0u);
      // Each round is a curve through a random sample: the whole path is far shorter than a
      // random order's (~n * 0.66 for the unit cube).
      CHECK(path_length(pts, a) < 0.2 * path_length(pts, identity));
    }
  }
  // Another seed gives another order.
  const auto pts = test::uniform_points(rng, 5000, 0, 1);
  std::vector<std::uint32_t> a, b;
  brio_order(pts, a, 1);
  brio_order(pts, b, 2);
  CHECK(a != b);
}

TEST_CASE("hilbert_sort handles flat and coincident sets") {
  std::vector<WeightedPoint> same(100, WeightedPoint{1, 2, 3, 0});
  std::vector<std::uint32_t> order(100);
  std::iota(order.begin(), order.end(), 0u);
  hilbert_sort(same, order);
  CHECK(is_permutation_of_range(order, 100));
  auto flat = test::grid_points(16, 16, 1);
  order.resize(flat.size());
  std::iota(order.begin(), order.end(), 0u);
  std::reverse(order.begin(), order.end());
  const double row_by_row = path_length(flat, order);
  hilbert_sort(flat, order, 4);
  CHECK(is_permutation_of_range(order, flat.size()));
  // A 3D curve restricted to a slice is not continuous, but stays local.
  CHECK(path_length(flat, order) < 1.5 * row_by_row);
}
