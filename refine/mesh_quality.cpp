#include "mesh_quality.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace delpsc::refine {

double min_triangle_angle_degrees(const io::SurfaceMesh& mesh) {
  double smallest = std::numbers::pi;
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      const Vec3& apex = mesh.vertices[t[i]];
      const Vec3 u = mesh.vertices[t[(i + 1) % 3]] - apex, v = mesh.vertices[t[(i + 2) % 3]] - apex;
      // atan2(|u x v|, u.v) stays accurate for angles near 0 and π, unlike acos.
      smallest = std::min(smallest, std::atan2(u.cross(v).norm(), u.dot(v)));
    }
  return smallest * 180 / std::numbers::pi;
}

}  // namespace delpsc::refine
