#include "link_shape.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include <delpsc/delaunay/small_map.h>

namespace delpsc::refine {

using delaunay::PointId;

// Large links: each endpoint numbered on first sight through a hash map (the triangulation's
// SmallMap, cleared in O(1)), degrees counted on the way (a third edge at a vertex ends the
// test), then connectivity by union-find; O(k) expected for k edges. A vertex with a large umbrella (a big ball next to many small
// ones, or the crowd at a fold) is re-checked after every insertion nearby: sorting its link's
// vertices each time, as this did before, took a third of meshing hand.off at 0.5%
// (BENCHMARKS.md, "Session 30").
LinkShape link_shape_large(std::span<const std::array<PointId, 2>> link) {
  thread_local delaunay::detail::SmallMap number;  // endpoint -> its number
  thread_local std::vector<std::uint32_t> degree, parent, ends;
  number.reset(2 * link.size());
  degree.clear();
  ends.resize(2 * link.size());
  for (std::size_t e = 0; e < link.size(); ++e)
    for (int k = 0; k < 2; ++k) {
      const PointId v = link[e][k];
      std::uint32_t i;
      if (const std::uint32_t* known = number.find(v)) {
        i = *known;
      } else {
        i = static_cast<std::uint32_t>(degree.size());
        number.insert(v, i);
        degree.push_back(0);
      }
      if (++degree[i] > 2) return {false, degree.size()};
      ends[2 * e + k] = i;
    }
  const std::size_t n = degree.size();
  // Connected with degrees <= 2 needs n <= k + 1 (a path); more vertices cannot be connected.
  if (n > link.size() + 1) return {false, n};
  parent.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) parent[i] = i;
  const auto root = [&](std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::size_t components = n;
  for (std::size_t e = 0; e < link.size(); ++e) {
    const std::uint32_t ra = root(ends[2 * e]), rb = root(ends[2 * e + 1]);
    if (ra != rb) {
      parent[ra] = rb;
      --components;
    }
  }
  return {components == 1, n};
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
  return link.size() <= kSmallLink ? link_shape_small(link) : link_shape_large(link);
}

}  // namespace delpsc::refine
