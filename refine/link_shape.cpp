#include "link_shape.h"

#include <algorithm>
#include <vector>

namespace delpsc::refine {

using delaunay::PointId;

// The link graph's vertices sorted, degrees, and connectivity by union-find, so that a
// vertex with a large umbrella (a big ball next to many small ones) costs O(k log k), not
// O(k^2): it is re-checked after every insertion nearby.
LinkShape link_shape_sorted(std::span<const std::array<PointId, 2>> link) {
  thread_local std::vector<PointId> verts;
  thread_local std::vector<int> degree;
  thread_local std::vector<std::size_t> parent;
  verts.clear();
  for (const auto& e : link) verts.insert(verts.end(), e.begin(), e.end());
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  auto index = [&](PointId v) {
    return static_cast<std::size_t>(std::lower_bound(verts.begin(), verts.end(), v) - verts.begin());
  };
  degree.assign(verts.size(), 0);
  parent.resize(verts.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
  auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::size_t components = verts.size();
  for (const auto& e : link) {
    const std::size_t a = index(e[0]), b = index(e[1]);
    ++degree[a];
    ++degree[b];
    const std::size_t ra = root(a), rb = root(b);
    if (ra != rb) {
      parent[ra] = rb;
      --components;
    }
  }
  const bool low_degree = std::all_of(degree.begin(), degree.end(), [](int d) { return d <= 2; });
  return {low_degree && components == 1, verts.size()};
}

// The common case, an umbrella of a few triangles (a surface vertex has ~6): the same answer
// from fixed arrays and linear scans, without sorting or allocation. The disk check runs ~8
// times per output vertex and the general version cost ~9% of meshing.
LinkShape link_shape_small(std::span<const std::array<PointId, 2>> link) {
  std::array<PointId, 2 * kSmallLink> verts;
  std::array<std::uint8_t, 2 * kSmallLink> degree{}, label;
  std::size_t n = 0;
  std::array<std::array<std::uint8_t, 2>, kSmallLink> ends;
  for (std::size_t e = 0; e < link.size(); ++e)
    for (int k = 0; k < 2; ++k) {
      std::size_t i = 0;
      while (i < n && verts[i] != link[e][k]) ++i;
      if (i == n) {
        verts[n] = link[e][k];
        label[n] = static_cast<std::uint8_t>(n);
        ++n;
      }
      if (++degree[i] > 2) return {false, n};
      ends[e][k] = static_cast<std::uint8_t>(i);
    }
  // Connectivity: relabel to the smallest label until stable (at most k passes over k edges).
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t e = 0; e < link.size(); ++e) {
      std::uint8_t& a = label[ends[e][0]];
      std::uint8_t& b = label[ends[e][1]];
      if (a == b) continue;
      a = b = std::min(a, b);
      changed = true;
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (label[i] != 0) return {false, n};
  return {true, n};
}

LinkShape link_shape(std::span<const std::array<PointId, 2>> link) {
  return link.size() <= kSmallLink ? link_shape_small(link) : link_shape_sorted(link);
}

}  // namespace delpsc::refine
