// Step 2b of build_complex: T-junctions healed. A vertex lying exactly on another triangle's
// edge, with no zero-area cap between them (the caps are step 1's), leaves a crack of zero
// width: the long edge and the short edges along it are each in one triangle only, so they would
// be boundary curves on top of each other, and the two sides touch along the segment (which the
// commands refuse as a self-intersection). Meshes whose faces were tessellated apart have them.
// The triangle of the long edge is split at the vertices on it into a fan from its opposite
// vertex: exactly the same surface (they lie on the edge, decided exactly), now glued along the
// short edges.
#include <algorithm>
#include <utility>
#include <vector>

#include <delpsc/kernel/predicates.h>

#include "complex_build.h"

namespace delpsc::protect::detail {

namespace {

// Whether n lies strictly between `from` and `to` on the segment from p to q (from and to on it,
// in that order from p). Exact: collinearity by orient predicates, order along the axis where p
// and q differ most (collinear distinct points differ there).
bool strictly_between(const Vec3& p, const Vec3& q, const Vec3& from, const Vec3& to, const Vec3& n) {
  if (!kernel::collinear(p.data(), q.data(), n.data())) return false;
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(q[i] - p[i]) > std::abs(q[axis] - p[axis])) axis = i;
  return q[axis] > p[axis] ? from[axis] < n[axis] && n[axis] < to[axis] : to[axis] < n[axis] && n[axis] < from[axis];
}

}  // namespace

std::size_t heal_t_junctions(Complex& complex) {
  constexpr int kMaxRounds = 8;
  constexpr std::size_t kMaxChain = 1024;  // vertices on one edge
  std::size_t healed = 0;
  for (int round = 0; round < kMaxRounds; ++round) {
    // Boundary edges (one triangle), and at each of their vertices the boundary edges there,
    // as (vertex, edge) sorted by vertex: closed models have none and pay one pass.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> at_vertex;
    for (std::uint32_t e = 0; e < complex.edges.size(); ++e)
      if (complex.edge_triangle_offsets[e + 1] - complex.edge_triangle_offsets[e] == 1)
        for (const std::uint32_t v : complex.edges[e]) at_vertex.emplace_back(v, e);
    if (at_vertex.empty()) break;
    std::sort(at_vertex.begin(), at_vertex.end());
    const auto boundary_at = [&](std::uint32_t v) {
      return std::equal_range(at_vertex.begin(), at_vertex.end(), std::pair{v, 0u},
                              [](const auto& x, const auto& y) { return x.first < y.first; });
    };
    std::vector<char> used(complex.edges.size(), 0);     // a boundary edge matched this round
    std::vector<char> split(complex.triangles.size(), 0);  // a triangle split this round
    std::size_t healed_now = 0;
    std::vector<std::uint32_t> chain, chain_edges;
    for (const auto& [unused_vertex, e] : at_vertex) {
      (void)unused_vertex;
      if (used[e]) continue;
      const std::uint32_t t = complex.edge_triangles[complex.edge_triangle_offsets[e]];
      if (split[t]) continue;
      int k = 0;
      while (complex.triangle_edges[t][k] != e) ++k;
      const auto tri = complex.triangles[t];
      const std::uint32_t x = tri[k], p = tri[(k + 1) % 3], q = tri[(k + 2) % 3];
      const Vec3 &pp = complex.vertices[p], &qq = complex.vertices[q];
      // The boundary path from p to q through vertices strictly between them, each step
      // nearer q: the other side of the crack.
      chain.clear();
      chain_edges.clear();
      std::uint32_t at = p;
      bool reached = false;
      while (!reached && chain.size() < kMaxChain) {
        std::uint32_t next = kNoIndex, next_edge = kNoIndex;
        const auto [first, last] = boundary_at(at);
        for (auto it = first; it != last; ++it) {
          const std::uint32_t f = it->second;
          if (f == e || used[f]) continue;
          const std::uint32_t n = complex.edges[f][0] == at ? complex.edges[f][1] : complex.edges[f][0];
          if (n == q && !chain.empty()) {
            next = q, next_edge = f;
            break;
          }
          if (n != q && strictly_between(pp, qq, complex.vertices[at], qq, complex.vertices[n]) &&
              (next == kNoIndex || strictly_between(pp, qq, complex.vertices[at], complex.vertices[next], complex.vertices[n])))
            next = n, next_edge = f;  // the nearest to `at` of those between
        }
        if (next == kNoIndex) break;
        chain_edges.push_back(next_edge);
        reached = next == q;
        if (!reached) chain.push_back(next);
        at = next;
      }
      if (!reached) continue;
      // The fan from x over p, chain..., q, in t's orientation (x, p, q).
      used[e] = 1;
      for (const std::uint32_t f : chain_edges) used[f] = 1;
      split[t] = 1;
      complex.triangles[t] = {x, p, chain.front()};
      for (std::size_t i = 0; i < chain.size(); ++i) {
        complex.triangles.push_back({x, chain[i], i + 1 < chain.size() ? chain[i + 1] : q});
        complex.triangle_source.push_back(complex.triangle_source[t]);
      }
      complex.cleanup.split_triangles += chain.size();
      ++healed_now;
    }
    if (healed_now == 0) break;
    healed += healed_now;
    build_edge_table(complex);
  }
  return healed;
}

}  // namespace delpsc::protect::detail
