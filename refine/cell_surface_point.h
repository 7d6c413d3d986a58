// A surface point inside the power cell of a ball whose umbrella is empty, for step 2(a) of
// DelPSC (Dey & Levine 2009, §3).
//
// A ball vertex p on a curve fails D1 with no restricted triangle at all when the patches cross
// its power cell without meeting one of the cell's Voronoi edges: the surface piece in the cell
// is bounded by a loop on one facet (a long thin cell reaching out of the model, or a thin slab
// between two larger balls). Refining p's ball (the mesher's answer while p has no facet, d1 = -1
// against d2 = r_p) makes the same configuration one scale down: on libcgal-demo's dino.off the
// middle ball of a 0.0047-long crease between two corner balls of 0.0016 was refined four times
// in a row to the balls' floor, at 2%, 1% and 0.5% alike. A point of the surface in the cell
// cuts it instead.
//
// The point: on the segments from p's centre to the orthocentres (Voronoi vertices) of p's finite
// cells - inside the convex cell when the centre is - the domain hits on the patches `wanted`
// accepts, at power distance at least min_power from p, that are in p's power cell (exact:
// kernel::compare_power_distance with every neighbour of p), the one of largest power distance.
// When no hit qualifies, the same choice among the domain's closest points to those orthocentres:
// an unweighted point on a needle narrower than the spacing around it (a cone of 1° on a sheet
// at 0.5%) has the needle's side wrapped round it inside its cell, and every segment from it
// leaves the needle at once; the mesher then fell back on the paper's global choice and refined
// the sheet the cone stood on to 120,000 points in a minute without reaching the point. A
// surface point nearest to a Voronoi vertex of p is no farther from it than p.
// When none of those qualifies either, the farthest point of the wanted patches in the cell
// itself: the patches' triangles near the cell (Domain::triangles_in_box) clipped to its sides,
// the largest power distance taken at a corner of what is left, moved a millionth of the way to
// its polygon's centre against rounding. A needle standing in the cell of the ball at its tip (a
// cone of 8° on a sheet at 2%) is met by no segment from the tip, and the needle's points
// nearest to the Voronoi vertices lie just outside the cell: refining the ball instead made the
// same cell one scale down, to the balls' floor.
// Such a point is admissible (§2.1): p is its power-nearest vertex and it lies outside p's ball,
// hence outside every ball; and its power distance to every point of the triangulation is at
// least min_power, which bounds the insertions from below as the packing argument of §3 needs.
// Cost: one segment query per cell around p and one exact comparison per neighbour and hit;
// when none qualifies, one closest-point query per cell more; when none of those does, a box
// query and the clipping of each triangle met by p's neighbours' sides (O(k n m) for k triangles,
// n neighbours and clipped polygons of m corners), in rounded arithmetic: only the exact
// comparisons decide what is returned. A patch touching the cell only along an edge or at a
// point (a clipped polygon of fewer than three corners) is passed over.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>

#include <delpsc/delaunay/regular_triangulation.h>

#include "domain.h"

namespace delpsc::refine {

/// The hit described above, or nullopt (p not a vertex, no such hit).
std::optional<SurfaceHit> surface_point_in_cell(const delaunay::RegularTriangulation& dt, const Domain& domain,
                                                delaunay::PointId p, double min_power,
                                                const std::function<bool(std::uint32_t patch)>& wanted);

}  // namespace delpsc::refine
