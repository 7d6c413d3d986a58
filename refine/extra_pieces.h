// Pieces of a patch's restricted triangles that are not the patch: for the mesher's closing check
// of G2 (Dey & Levine 2009, Theorem 4.3: at a fine enough λ each patch's Skl² is homeomorphic to
// the patch, so it is in one piece - a patch is a connected component of the input's triangles
// across non-feature edges, protect/complex.h). The disk condition D1-D4 is local: a closed
// piece of restricted triangles away from the rest of its patch passes it at every vertex. On a
// cone of 3° at 1% the side came out with three small closed spheres besides itself (Euler
// characteristic 8 against 2): facets whose dual edges cross the narrow side twice, between
// samples on opposite walls. Theorem 4.3 rules them out only below a λ nobody can compute; the
// mesher finds them instead and samples them until they go.
#pragma once

#include <cstdint>
#include <vector>

#include "restricted_facets.h"

namespace delpsc::refine {

/// A connected piece of one patch's restricted triangles other than its largest piece.
struct ExtraPiece {
  std::uint32_t patch = 0;
  std::vector<std::uint32_t> facets;  ///< the slots of its restricted triangles, increasing
};

/// Per patch, the connected pieces of its restricted triangles but the one with the most triangles
/// (on a tie, the one holding the lowest slot). Triangles of one patch sharing a vertex are in one
/// piece: where the disk condition holds they share an edge too (a vertex's umbrella on a patch
/// is one disk), so this is the piece of the output's Skl² for the patch. `point_count`: the
/// triangulation's number of points (the vertices asked). A union-find over the records' slots:
/// O(slots) memory, O(records + Σ d²) time for d incidences at a vertex (d ~6 on a surface).
std::vector<ExtraPiece> extra_pieces(const RestrictedFacets& facets, std::size_t point_count);

}  // namespace delpsc::refine
