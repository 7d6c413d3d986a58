#include "triangle_orientation.h"

#include <algorithm>
#include <utility>

namespace delpsc::refine {

std::size_t orient_triangles(const std::vector<Vec3>& vertices, std::vector<std::array<std::uint32_t, 3>>& triangles) {
  const std::size_t n = triangles.size();
  constexpr std::uint32_t kNone = 0xffffffffu;
  // Each vertex's triangles (flat, by vertex), then each triangle's neighbours across its edges
  // used by exactly two triangles: a scan of the first end's few triangles per edge, instead of
  // sorting all 3T edge uses (and a heap-allocated list per triangle).
  std::vector<std::uint32_t> first(vertices.size() + 1, 0), around(3 * n);
  for (const auto& t : triangles)
    for (const std::uint32_t v : t) ++first[v + 1];
  for (std::size_t v = 0; v < vertices.size(); ++v) first[v + 1] += first[v];
  {
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::uint32_t t = 0; t < n; ++t)
      for (const std::uint32_t v : triangles[t]) around[fill[v]++] = t;
  }
  // `open` marks triangles with an edge that is not used by exactly two triangles.
  std::vector<std::array<std::uint32_t, 3>> next(n, {kNone, kNone, kNone});
  std::vector<char> open(n, 0);
  for (std::uint32_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      std::uint32_t other = kNone, users = 1;
      for (std::uint32_t i = first[a]; i < first[a + 1]; ++i) {
        const std::uint32_t u = around[i];
        if (u == t || std::find(triangles[u].begin(), triangles[u].end(), b) == triangles[u].end()) continue;
        other = u;
        ++users;
      }
      if (users == 2)
        next[t][k] = other;
      else
        open[t] = 1;
    }
  auto has_directed = [&](std::uint32_t t, std::uint32_t a, std::uint32_t b) {
    const auto& v = triangles[t];
    for (int k = 0; k < 3; ++k)
      if (v[k] == a && v[(k + 1) % 3] == b) return true;
    return false;
  };
  std::vector<char> seen(n, 0);
  std::size_t bad = 0;
  std::vector<std::uint32_t> component, queue;
  for (std::uint32_t start = 0; start < n; ++start) {
    if (seen[start]) continue;
    component.clear();
    queue.assign(1, start);
    seen[start] = 1;
    bool closed = true, orientable = true;
    while (!queue.empty()) {
      const std::uint32_t t = queue.back();
      queue.pop_back();
      component.push_back(t);
      closed &= !open[t];
      for (const std::uint32_t u : next[t]) {
        if (u == kNone) continue;
        // The shared edge (a, b) as t traverses it; u must traverse it as (b, a).
        std::uint32_t a = 0, b = 0;
        for (int k = 0; k < 3; ++k) {
          const std::uint32_t x = triangles[t][k], y = triangles[t][(k + 1) % 3];
          if (std::find(triangles[u].begin(), triangles[u].end(), x) != triangles[u].end() &&
              std::find(triangles[u].begin(), triangles[u].end(), y) != triangles[u].end()) {
            a = x;
            b = y;
          }
        }
        const bool agrees = has_directed(u, b, a);
        if (!seen[u]) {
          if (!agrees) std::swap(triangles[u][1], triangles[u][2]);
          seen[u] = 1;
          queue.push_back(u);
        } else if (!agrees) {
          orientable = false;
        }
      }
    }
    if (!orientable) ++bad;
    if (closed && orientable) {
      double volume = 0;
      for (const std::uint32_t t : component) {
        const Vec3& p = vertices[triangles[t][0]];
        volume += p.dot(vertices[triangles[t][1]].cross(vertices[triangles[t][2]]));
      }
      if (volume < 0)
        for (const std::uint32_t t : component) std::swap(triangles[t][1], triangles[t][2]);
    }
  }
  return bad;
}

}  // namespace delpsc::refine
