// Near-planar clusters of a polygon mesh's triangles, for the initial sample's lattice
// (surface_lattice.h, PolygonDomain::surface_candidates): one lattice plane serves a whole
// cluster, so a curved surface made of triangles far smaller than the spacing still gets a
// lattice, and coplanar triangles share one without seams.
#pragma once

#include <cstdint>
#include <vector>

#include <delpsc/kernel/large_array.h>

#include <delpsc/protect/complex.h>

namespace delpsc::refine {

/// Per triangle of a complex: its cluster, which of its edges bound the cluster, and its
/// distance to the cluster's boundary; per cluster its seed triangle.
struct TriangleClusters {
  kernel::LargeVector<std::uint32_t> cluster_of;     ///< per triangle
  kernel::LargeVector<std::uint32_t> seed;           ///< per cluster: the triangle it was grown from
  kernel::LargeVector<std::uint8_t> boundary_edges;  ///< per triangle, bit k: edge k (opposite vertex k)
  /// Per triangle: 0 with a boundary edge, else the shortest path through the centroids of its
  /// cluster's triangles to one that has; exact up to `horizon`, larger (up to HUGE_VAL) beyond.
  /// A horizon that is infinite or NaN means none: exact everywhere.
  kernel::LargeVector<double> distance;
};

/// Clusters grown from seeds in triangle order across edges that are no feature, while a
/// triangle's normal stays within `max_angle_degrees` of the seed's (signed: a sheet folding back
/// never joins, nor does a neighbour of opposite orientation). An edge bounds its cluster when it
/// is a feature or the triangle across it is in another cluster. The distances by Dial's bucket
/// variant of Dijkstra's algorithm: O(T + B) for B buckets (65 for a finite horizon) plus the
/// re-filings of triangles first reached by a longer path within one bucket's width (few on a
/// mesh, where edge lengths vary smoothly).
TriangleClusters cluster_triangles(const protect::Complex& complex, double max_angle_degrees, double horizon);

}  // namespace delpsc::refine
