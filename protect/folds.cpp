// Folds of the input near a point (protect/folds.h).
#include "folds.h"

#include <cmath>
#include <numbers>

#include <delpsc/kernel/constructions.h>

namespace delpsc::protect {

namespace {

// Dihedral angle at edge (a, b) between the triangles whose third vertices are c and d.
double dihedral_degrees(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 axis = (b - a).normalized();
  const Vec3 u = (c - a) - (c - a).dot(axis) * axis, v = (d - a) - (d - a).dot(axis) * axis;
  return std::atan2(u.cross(v).norm(), u.dot(v)) * 180 / std::numbers::pi;
}

}  // namespace

std::optional<Fold> sharpest_fold_near(const Complex& complex, const Vec3& where, double radius,
                                       double below_degrees) {
  std::optional<Fold> best;
  for (std::uint32_t e = 0; e < complex.edges.size(); ++e) {
    const auto faces = complex.edge_triangle_ids(e);
    if (faces.size() != 2) continue;
    const Vec3 &a = complex.vertices[complex.edges[e][0]], &b = complex.vertices[complex.edges[e][1]];
    if ((kernel::closest_point_on_segment(where, a, b).point - where).norm() > radius) continue;
    Vec3 opposite[2] = {Vec3::Zero(), Vec3::Zero()};
    for (int k = 0; k < 2; ++k)
      for (const std::uint32_t v : complex.triangles[faces[k]])
        if (v != complex.edges[e][0] && v != complex.edges[e][1]) opposite[k] = complex.vertices[v];
    const double angle = dihedral_degrees(a, b, opposite[0], opposite[1]);
    if (angle < below_degrees && (!best || angle < best->dihedral_degrees)) best = Fold{e, angle};
  }
  return best;
}

}  // namespace delpsc::protect
