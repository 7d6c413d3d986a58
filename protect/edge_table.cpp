// Step 2 of build_complex: the unique undirected edges and their incident triangles.
//
// Half-edges are bucketed by their smaller vertex (a counting sort, O(T + V)) and each bucket,
// a handful of entries on a mesh, is sorted by the larger vertex: O(T) overall in practice,
// versus O(T log T) for one global sort, which matters at a million triangles.
#include <algorithm>

#include "complex_build.h"

namespace delpsc::protect::detail {

kernel::LargeVector<std::uint32_t> offsets_from_counts(std::span<const std::uint32_t> counts) {
  kernel::LargeVector<std::uint32_t> offsets(counts.size() + 1, 0);
  for (std::size_t i = 0; i < counts.size(); ++i) offsets[i + 1] = offsets[i] + counts[i];
  return offsets;
}

void build_edge_table(Complex& complex) {
  const auto& tris = complex.triangles;
  const auto n_vertices = complex.vertices.size();
  const auto n_half = static_cast<std::uint32_t>(3 * tris.size());

  kernel::LargeVector<std::uint32_t> counts(n_vertices, 0);
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) ++counts[std::min(t[(k + 1) % 3], t[(k + 2) % 3])];
  const kernel::LargeVector<std::uint32_t> start = offsets_from_counts(counts);
  // (larger vertex, half-edge 3 t + k), bucketed by the smaller vertex
  kernel::LargeVector<std::pair<std::uint32_t, std::uint32_t>> half(n_half);
  {
    kernel::LargeVector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::uint32_t t = 0; t < tris.size(); ++t)
      for (std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t a = tris[t][(k + 1) % 3], b = tris[t][(k + 2) % 3];
        half[fill[std::min(a, b)]++] = {std::max(a, b), 3 * t + k};
      }
  }

  complex.edges.clear();
  complex.edge_triangle_offsets.assign(1, 0);
  complex.edge_triangles.clear();
  complex.edges.reserve(n_half / 2 + 1);
  complex.edge_triangles.reserve(n_half);
  complex.triangle_edges.assign(tris.size(), {kNoIndex, kNoIndex, kNoIndex});
  for (std::uint32_t u = 0; u < n_vertices; ++u) {
    const auto first = half.begin() + start[u], last = half.begin() + start[u + 1];
    std::sort(first, last);
    for (auto it = first; it != last; ++it) {
      if (it == first || it->first != (it - 1)->first) {
        if (!complex.edges.empty()) complex.edge_triangle_offsets.push_back(static_cast<std::uint32_t>(complex.edge_triangles.size()));
        complex.edges.push_back({u, it->first});
      }
      const auto e = static_cast<std::uint32_t>(complex.edges.size() - 1);
      complex.triangle_edges[it->second / 3][it->second % 3] = e;
      complex.edge_triangles.push_back(it->second / 3);
    }
  }
  if (!complex.edges.empty()) complex.edge_triangle_offsets.push_back(static_cast<std::uint32_t>(complex.edge_triangles.size()));
}

std::uint32_t find_edge(const Complex& complex, std::uint32_t u, std::uint32_t v) {
  const std::array<std::uint32_t, 2> key = {std::min(u, v), std::max(u, v)};
  const auto it = std::lower_bound(complex.edges.begin(), complex.edges.end(), key);
  if (it == complex.edges.end() || *it != key) return kNoIndex;
  return static_cast<std::uint32_t>(it - complex.edges.begin());
}

}  // namespace delpsc::protect::detail
