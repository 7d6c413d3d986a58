#include "mesh_quality.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace delpsc::refine {

double triangle_min_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3* p[3] = {&a, &b, &c};
  double smallest = std::numbers::pi;
  for (int i = 0; i < 3; ++i) {
    const Vec3 u = *p[(i + 1) % 3] - *p[i], v = *p[(i + 2) % 3] - *p[i];
    // atan2(|u x v|, u.v) stays accurate for angles near 0 and π, unlike acos.
    smallest = std::min(smallest, std::atan2(u.cross(v).norm(), u.dot(v)));
  }
  return smallest;
}

double min_triangle_angle_degrees(const io::SurfaceMesh& mesh) {
  double smallest = std::numbers::pi;
  for (const auto& t : mesh.triangles)
    smallest = std::min(smallest, triangle_min_angle(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]));
  return smallest * 180 / std::numbers::pi;
}

}  // namespace delpsc::refine
