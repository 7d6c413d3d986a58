// An output mesh's feature edges grouped by the curve label they carry, for the checks that
// look at one curve at a time (the G1 check's ends on their curve, skeleton_check.h; the
// distances between each input curve and its edges, approximation_error.h).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <delpsc/io/surface_mesh.h>

namespace delpsc::refine {

/// The edges labelled with curve c are segments[offsets[c] .. offsets[c + 1]), in mesh order,
/// each stored as (u, v, v): the degenerate triangle an AABB tree takes for a segment.
struct EdgesByCurve {
  std::vector<std::size_t> offsets;
  std::vector<std::array<std::uint32_t, 3>> segments;
  std::size_t unlabelled = 0;            ///< edges with no label, or one outside [0, curve_count)
  Vec3 first_unlabelled = Vec3::Zero();  ///< the first such edge's first vertex
};

/// Counting sort by label; O(edges + curve_count). Precondition: every edge's vertices index
/// mesh.vertices (first_unlabelled reads one).
EdgesByCurve group_edges_by_curve(const io::SurfaceMesh& mesh, std::uint32_t curve_count);

}  // namespace delpsc::refine
