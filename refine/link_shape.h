// The shape of a vertex's link in one umbrella (disk_condition.h, D1/D2 of Dey & Levine 2009,
// §3): the edges opposite p of the restricted triangles of Umb_σ(p), as a graph on their
// endpoints. Umb_σ(p) is a 2-disk iff this graph is one simple path (p on the disk's boundary)
// or one simple cycle (p inside): connected, no vertex of degree above 2. Purely combinatorial.
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include <delpsc/delaunay/regular_triangulation.h>

namespace delpsc::refine {

struct LinkShape {
  bool simple = false;        ///< connected with every degree <= 2: a simple path or cycle
  std::size_t vertices = 0;   ///< distinct endpoints (meaningful when simple: a cycle iff == edges)
};

/// The shape of the graph with these edges (each two distinct vertices, no edge twice).
/// O(k) expected for k edges; small links (the common case) by linear scans without allocation.
LinkShape link_shape(std::span<const std::array<delaunay::PointId, 2>> link);

/// Up to kSmallLink edges: fixed arrays, O(k^2). link_shape's choice for such links.
inline constexpr std::size_t kSmallLink = 16;
LinkShape link_shape_small(std::span<const std::array<delaunay::PointId, 2>> link);
/// Any size: endpoints numbered through a hash map, degrees, union-find; O(k) expected,
/// memory kept between calls (per thread). `vertices` counts the endpoints seen before a
/// third edge at one vertex ended the test, when it did.
LinkShape link_shape_large(std::span<const std::array<delaunay::PointId, 2>> link);

}  // namespace delpsc::refine
