#include "triangle_orientation.h"

#include <algorithm>
#include <utility>

namespace delpsc::refine {

std::size_t orient_triangles(const std::vector<Vec3>& vertices, std::vector<std::array<std::uint32_t, 3>>& triangles) {
  const std::size_t n = triangles.size();
  // Undirected edges as (min, max, triangle), sorted so the triangles of an edge are adjacent.
  struct EdgeUse {
    std::uint32_t a, b, t;
  };
  std::vector<EdgeUse> uses;
  uses.reserve(3 * n);
  for (std::uint32_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      uses.push_back({std::min(a, b), std::max(a, b), t});
    }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.t < y.t;
  });
  // Neighbour pairs across manifold edges; `open` marks triangles with a non-2-manifold edge.
  std::vector<std::vector<std::uint32_t>> next(n);
  std::vector<char> open(n, 0);
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].a == uses[i].a && uses[j].b == uses[i].b) ++j;
    if (j - i == 2) {
      next[uses[i].t].push_back(uses[i + 1].t);
      next[uses[i + 1].t].push_back(uses[i].t);
    } else {
      for (std::size_t k = i; k < j; ++k) open[uses[k].t] = 1;
    }
    i = j;
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
