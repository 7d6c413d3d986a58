#include "triangle_clusters.h"

#include <array>
#include <cmath>
#include <utility>

namespace delpsc::refine {

TriangleClusters cluster_triangles(const protect::Complex& complex, double max_angle_degrees, double horizon) {
  const double min_cos = std::cos(max_angle_degrees * 3.141592653589793 / 180);
  const std::size_t n = complex.triangles.size();
  constexpr std::uint32_t kNone = 0xffffffffu;
  kernel::LargeVector<Vec3> normal(n), centroid(n);
  for (std::size_t t = 0; t < n; ++t) {
    const auto& tri = complex.triangles[t];
    const Vec3 &a = complex.vertices[tri[0]], &b = complex.vertices[tri[1]], &c = complex.vertices[tri[2]];
    normal[t] = (b - a).cross(c - a).normalized();
    centroid[t] = (a + b + c) / 3;
  }
  // The triangle across edge k of t, if the edge is no feature (exactly two triangles), looked
  // up once: the three passes below read it again and again.
  kernel::LargeVector<std::array<std::uint32_t, 3>> neighbour(n, {kNone, kNone, kNone});
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
  kernel::LargeVector<std::uint32_t> queue;
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
  // Distances to the boundary along centroid paths, up to the horizon: Dijkstra with the heap
  // replaced by buckets of equal width (Dial), horizon / 64 wide. An entry may come out of its
  // bucket before a shorter path to it is seen; the shorter path then files it again and its
  // neighbours are relaxed again, so the distances are the shortest ones all the same (up to the
  // rounding of equally long paths). On fandisk's 13,000 triangles at 2% the binary heap was a
  // fifth of choosing the sample's candidates. Without a horizon (infinite or NaN) the buckets
  // are a few mean centroid steps wide, at most 4,096 of them, the last taking all that is
  // farther (still exact: a bucket is only ever read after all earlier ones).
  out.distance.assign(n, HUGE_VAL);
  const bool bounded = horizon < HUGE_VAL;  // false for NaN too
  const double limit = bounded ? horizon : HUGE_VAL;
  double width = bounded && horizon > 0 ? horizon / 64 : HUGE_VAL;
  std::size_t last_bucket = 64;
  if (!bounded) {
    double steps = 0, count = 0;
    for (std::uint32_t t = 0; t < n; ++t)
      for (int k = 0; k < 3; ++k)
        if (const std::uint32_t u = neighbour[t][k]; u != kNone && u > t) {
          steps += (centroid[u] - centroid[t]).norm();
          count += 1;
        }
    if (count > 0 && steps > 0) width = 4 * steps / count;
    last_bucket = 4096;
  }
  std::vector<kernel::LargeVector<std::pair<double, std::uint32_t>>> buckets(1);
  const auto file = [&](double d, std::uint32_t t) {
    const double b = std::floor(d / width);  // NaN (0 / 0, a width that underflowed): the last
    const std::size_t i = b < static_cast<double>(last_bucket) ? static_cast<std::size_t>(b) : last_bucket;
    if (buckets.size() <= i) buckets.resize(i + 1);
    buckets[i].emplace_back(d, t);
  };
  for (std::uint32_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = neighbour[t][k];
      if (u == kNone || out.cluster_of[u] != out.cluster_of[t]) {
        out.boundary_edges[t] |= static_cast<std::uint8_t>(1u << k);
        if (out.distance[t] != 0) file(out.distance[t] = 0, t);
      }
    }
  // By index: filing may add buckets (and grow the one being read).
  for (std::size_t b = 0; b < buckets.size(); ++b)
    for (std::size_t i = 0; i < buckets[b].size(); ++i) {
      const auto [d, t] = buckets[b][i];  // a copy: filing may move the bucket's storage
      if (d > out.distance[t]) continue;  // a shorter path filed it again
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t u = neighbour[t][k];
        if (u == kNone || out.cluster_of[u] != out.cluster_of[t]) continue;
        // Beyond the horizon distances may stay larger (HUGE_VAL): no entry is made for them.
        const double du = d + (centroid[u] - centroid[t]).norm();
        if (du < out.distance[u] && du <= limit) file(out.distance[u] = du, u);
      }
    }
  return out;
}

}  // namespace delpsc::refine
