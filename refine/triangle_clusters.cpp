#include "triangle_clusters.h"

#include <array>
#include <cmath>
#include <functional>
#include <queue>
#include <utility>

namespace delpsc::refine {

TriangleClusters cluster_triangles(const protect::Complex& complex, double max_angle_degrees, double horizon) {
  const double min_cos = std::cos(max_angle_degrees * 3.141592653589793 / 180);
  const std::size_t n = complex.triangles.size();
  constexpr std::uint32_t kNone = 0xffffffffu;
  std::vector<Vec3> normal(n), centroid(n);
  for (std::size_t t = 0; t < n; ++t) {
    const auto& tri = complex.triangles[t];
    const Vec3 &a = complex.vertices[tri[0]], &b = complex.vertices[tri[1]], &c = complex.vertices[tri[2]];
    normal[t] = (b - a).cross(c - a).normalized();
    centroid[t] = (a + b + c) / 3;
  }
  // The triangle across edge k of t, if the edge is no feature (exactly two triangles), looked
  // up once: the three passes below read it again and again.
  std::vector<std::array<std::uint32_t, 3>> neighbour(n, {kNone, kNone, kNone});
  for (std::uint32_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t e = complex.triangle_edges[t][k];
      if (complex.edge_feature[e] != 0) continue;
      for (std::uint32_t q = complex.edge_triangle_offsets[e]; q < complex.edge_triangle_offsets[e + 1]; ++q)
        if (complex.edge_triangles[q] != t) neighbour[t][k] = complex.edge_triangles[q];
    }
  TriangleClusters out;
  out.cluster_of.assign(n, kNone);
  out.boundary_edges.assign(n, 0);
  std::vector<std::uint32_t> queue;
  for (std::uint32_t s = 0; s < n; ++s) {
    if (out.cluster_of[s] != kNone) continue;
    const auto id = static_cast<std::uint32_t>(out.seed.size());
    out.seed.push_back(s);
    out.cluster_of[s] = id;
    queue.assign(1, s);
    while (!queue.empty()) {
      const std::uint32_t t = queue.back();
      queue.pop_back();
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t u = neighbour[t][k];
        if (u == kNone || out.cluster_of[u] != kNone || !(normal[u].dot(normal[s]) >= min_cos)) continue;
        out.cluster_of[u] = id;
        queue.push_back(u);
      }
    }
  }
  // Distances to the boundary: Dijkstra from the triangles that have a boundary edge.
  out.distance.assign(n, HUGE_VAL);
  using Entry = std::pair<double, std::uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
  for (std::uint32_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = neighbour[t][k];
      if (u == kNone || out.cluster_of[u] != out.cluster_of[t]) {
        out.boundary_edges[t] |= static_cast<std::uint8_t>(1u << k);
        if (out.distance[t] != 0) heap.emplace(out.distance[t] = 0, t);
      }
    }
  while (!heap.empty()) {
    const auto [d, t] = heap.top();
    heap.pop();
    if (d > out.distance[t] || d > horizon) continue;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = neighbour[t][k];
      if (u == kNone || out.cluster_of[u] != out.cluster_of[t]) continue;
      const double du = d + (centroid[u] - centroid[t]).norm();
      if (du < out.distance[u]) heap.emplace(out.distance[u] = du, u);
    }
  }
  return out;
}

}  // namespace delpsc::refine
