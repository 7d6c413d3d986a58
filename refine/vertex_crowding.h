// Where an output mesh's vertices crowd most, for the warning of `delpsc mesh` when a run needs
// far more vertices than its size asks for. Such runs are nearly always one spot of the input:
// libcgal-demo's hand.off at 2% makes 97,899 vertices where 1,741 cover its area, and 96% of
// them mesh one sliver triangle folded back at 2.1° onto its neighbours (two sheets 0.0003-0.003
// λ apart, which refinement must separate; BENCHMARKS.md, session 23). Naming that spot tells the
// user what to repair.
#pragma once

#include <cstddef>
#include <span>

#include <delpsc/kernel/point.h>

namespace delpsc::refine {

struct VertexCrowd {
  std::size_t vertices = 0;       ///< in the block of 3 x 3 x 3 grid cubes around the fullest cube
  Vec3 centre = Vec3::Zero();     ///< their centroid (zero when there are none)
  std::size_t fullest_cube = 0;   ///< the vertices of that cube alone
};

/// The crowd around the grid cube of side `cell` holding the most of `vertices` (cubes aligned
/// on the vertices' bounding box; of cubes with equal counts, the first to reach that count).
/// Empty result when there are no finite vertices, `cell` is not positive and finite, or the
/// box's extent overflows; a cell so small that the box spans more than 2^20 of them along an
/// axis is enlarged to fit. Expected O(n) time and memory.
VertexCrowd densest_crowd(std::span<const Vec3> vertices, double cell);

}  // namespace delpsc::refine
