// The shape of an output mesh's triangles in a few figures, for the final report of `delpsc mesh`
// (JSON "quality") and for tests: the extreme angles, the radius-edge ratio and a histogram of
// the smallest angles. DelPSC itself bounds no angle (§4: the disk condition and the size λ drive
// refinement); these figures say what a run produced.
#pragma once

#include <array>
#include <cstddef>

#include <delpsc/io/surface_mesh.h>

namespace delpsc::refine {

struct QualitySummary {
  std::size_t triangles = 0;
  double min_angle_degrees = 180;  ///< smallest interior angle (180 without triangles)
  double max_angle_degrees = 0;    ///< largest interior angle (0 without triangles)
  /// Circumradius over shortest edge, R / l_min = 1 / (2 sin θ_min) by the law of sines:
  /// 1/√3 ≈ 0.577 for an equilateral triangle, 1 for θ_min = 30°, infinite for a degenerate one.
  double max_radius_edge_ratio = 0;
  double mean_radius_edge_ratio = 0;  ///< over the triangles (infinite if one is degenerate)
  /// Triangles whose smallest angle is in [10k, 10k + 10) degrees, k = 0..5 (60 falls in k = 5).
  std::array<std::size_t, 6> min_angle_histogram{};
};

/// The figures of every triangle of `mesh` (indices must be valid). O(T).
QualitySummary summarize_quality(const io::SurfaceMesh& mesh);

}  // namespace delpsc::refine
