// Index tables of a tetrahedron's vertex slots and the packed keys the triangulation hashes.
// Internal to delaunay/.
#pragma once

#include <array>
#include <cstdint>

namespace delpsc::delaunay::detail {

/// kFacetSlots[i]: the slots of the facet opposite slot i, ordered so that the facet followed by
/// vertex i has the orientation of the cell: orient3d(v[f0], v[f1], v[f2], v[i]) has the sign of
/// orient3d(v0, v1, v2, v3). Two cells sharing a facet list it in opposite cyclic orders.
inline constexpr int kFacetSlots[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};

/// For a cell with apex slot i and a facet j != i (which contains slot i): the two other slots
/// (k, l) of that facet such that (i, k, l) is a cyclic rotation of kFacetSlots[j].
inline constexpr std::array<std::array<std::array<int, 2>, 4>, 4> kEdgeAfterApex = [] {
  std::array<std::array<std::array<int, 2>, 4>, 4> t{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      if (j == i) continue;
      for (int r = 0; r < 3; ++r)
        if (kFacetSlots[j][r] == i) t[i][j] = {kFacetSlots[j][(r + 1) % 3], kFacetSlots[j][(r + 2) % 3]};
    }
  return t;
}();

/// For apex slot i: its three inner facets j != i with their edge slots (k, l) as in
/// kEdgeAfterApex, flattened: kInnerFacets[i][t] = {j, k, l}.
inline constexpr std::array<std::array<std::array<int, 3>, 3>, 4> kInnerFacets = [] {
  std::array<std::array<std::array<int, 3>, 3>, 4> t{};
  for (int i = 0; i < 4; ++i) {
    int n = 0;
    for (int j = 0; j < 4; ++j)
      if (j != i) t[i][n++] = {j, kEdgeAfterApex[i][j][0], kEdgeAfterApex[i][j][1]};
  }
  return t;
}();

/// Neighbour link: neighbour cell << 2 | index of the shared facet in the neighbour.
inline constexpr std::uint32_t make_link(std::uint32_t cell, int facet) {
  return (cell << 2) | static_cast<std::uint32_t>(facet);
}

/// Key of the directed edge a -> b.
inline constexpr std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t{a} << 32) | b;
}

/// Vertex numbers in facet keys have 21 bits; this one stands for the infinite vertex.
inline constexpr std::uint32_t kFacetKeyMask = (1u << 21) - 1;

/// Key of an oriented triangle (a, b, c): equal for its three cyclic rotations, different for
/// the opposite orientation. Precondition: a, b, c <= kFacetKeyMask.
inline constexpr std::uint64_t facet_key(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  // Rotate the smallest number to the front.
  if (b < a && b < c) {
    const std::uint32_t t = a;
    a = b;
    b = c;
    c = t;
  } else if (c < a && c < b) {
    const std::uint32_t t = c;
    c = b;
    b = a;
    a = t;
  }
  return (std::uint64_t{a} << 42) | (std::uint64_t{b} << 21) | c;
}

}  // namespace delpsc::delaunay::detail
