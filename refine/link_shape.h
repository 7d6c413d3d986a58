// The shape of a vertex's link in one umbrella (disk_condition.h, D1/D2 of Dey & Levine 2009,
// §3): the edges opposite p of the restricted triangles of Umb_σ(p), as a graph on their
// endpoints. Umb_σ(p) is a 2-disk iff this graph is one simple path (p on the disk's boundary)
// or one simple cycle (p inside): connected, no vertex of degree above 2. Purely combinatorial.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

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

// ---- links at a pinch ------------------------------------------------------------------------
// Where a patch touches itself at a corner (Domain::corner_pinch_fans) its umbrella there is
// not one disk but one per fan of the input: the link must be as many simple pieces, a cycle for
// each closed fan and a path for each open one, each path running between the two curves that
// bound its fan.

/// One connected piece of a link: a simple path between `ends`, or a simple cycle.
struct LinkPiece {
  bool cycle = false;
  std::array<delaunay::PointId, 2> ends{};  ///< a path's two ends (unset for a cycle)
};

/// The pieces of the link, when no vertex has degree above 2 (false otherwise, `pieces` then
/// unspecified). O(k log k) for k edges: for the few umbrellas at pinches.
bool link_pieces(std::span<const std::array<delaunay::PointId, 2>> link, std::vector<LinkPiece>& pieces);

/// Whether the pieces are the fans one to one: as many, cycles for the closed fans (both curves
/// 0xffffffff), and paths for the open ones whose two ends lie on the fan's two curves
/// (`on_curve(end, curve)`), in either order. Exhaustive over the assignments (a handful of fans).
bool pieces_match_fans(std::span<const LinkPiece> pieces, std::span<const std::array<std::uint32_t, 2>> fans,
                       const std::function<bool(delaunay::PointId, std::uint32_t)>& on_curve);

}  // namespace delpsc::refine
