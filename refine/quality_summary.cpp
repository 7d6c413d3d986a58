#include "quality_summary.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace delpsc::refine {

QualitySummary summarize_quality(const io::SurfaceMesh& mesh) {
  QualitySummary q;
  q.triangles = mesh.triangles.size();
  double smallest = std::numbers::pi, largest = 0, ratio_sum = 0;
  for (const auto& t : mesh.triangles) {
    double lo = std::numbers::pi, hi = 0;
    for (int i = 0; i < 3; ++i) {
      const Vec3& apex = mesh.vertices[t[i]];
      const Vec3 u = mesh.vertices[t[(i + 1) % 3]] - apex, v = mesh.vertices[t[(i + 2) % 3]] - apex;
      const double angle = std::atan2(u.cross(v).norm(), u.dot(v));  // accurate near 0 and π
      lo = std::min(lo, angle), hi = std::max(hi, angle);
    }
    smallest = std::min(smallest, lo), largest = std::max(largest, hi);
    const double ratio = lo > 0 ? 1 / (2 * std::sin(lo)) : std::numeric_limits<double>::infinity();
    q.max_radius_edge_ratio = std::max(q.max_radius_edge_ratio, ratio);
    ratio_sum += ratio;
    const auto bin = static_cast<std::size_t>(std::clamp(lo * 180 / std::numbers::pi / 10, 0.0, 5.0));
    ++q.min_angle_histogram[bin];
  }
  q.min_angle_degrees = smallest * 180 / std::numbers::pi;
  q.max_angle_degrees = largest * 180 / std::numbers::pi;
  if (q.triangles > 0) q.mean_radius_edge_ratio = ratio_sum / static_cast<double>(q.triangles);
  return q;
}

}  // namespace delpsc::refine
