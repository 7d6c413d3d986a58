// Folds of the input near a point (protect/folds.h).
#include "folds.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

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
                                       double below_degrees, FoldEdges which) {
  std::optional<Fold> best;
  for (std::uint32_t e = 0; e < complex.edges.size(); ++e) {
    const auto faces = complex.edge_triangle_ids(e);
    if (faces.size() != 2) continue;
    if (which == FoldEdges::off_curves && complex.edge_curve[e] != kNoIndex) continue;
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

std::optional<NarrowCorner> narrowest_corner_near(const Complex& complex, const Vec3& where, double radius,
                                                  double below_degrees) {
  // The corners near `where`, by vertex; then each feature edge at one of them files its unit
  // direction away from the corner.
  std::vector<std::uint32_t> corner_of(complex.vertices.size(), kNoIndex);
  for (std::uint32_t k = 0; k < complex.corner_vertex.size(); ++k)
    if ((complex.vertices[complex.corner_vertex[k]] - where).norm() <= radius) corner_of[complex.corner_vertex[k]] = k;
  struct Leaving {
    std::uint32_t corner, curve;
    Vec3 direction;
  };
  std::vector<Leaving> leaving;
  for (std::uint32_t e = 0; e < complex.edges.size(); ++e) {
    if (complex.edge_curve[e] == kNoIndex) continue;
    for (int end = 0; end < 2; ++end) {
      const std::uint32_t v = complex.edges[e][end], w = complex.edges[e][1 - end];
      if (corner_of[v] == kNoIndex) continue;
      const Vec3 d = complex.vertices[w] - complex.vertices[v];
      if (d.squaredNorm() > 0) leaving.push_back({corner_of[v], complex.edge_curve[e], d.normalized()});
    }
  }
  std::sort(leaving.begin(), leaving.end(), [](const Leaving& a, const Leaving& b) { return a.corner < b.corner; });
  std::optional<NarrowCorner> best;
  for (std::size_t i = 0; i < leaving.size(); ++i)
    for (std::size_t j = i + 1; j < leaving.size() && leaving[j].corner == leaving[i].corner; ++j) {
      const Vec3 &a = leaving[i].direction, &b = leaving[j].direction;
      const double angle = std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / std::numbers::pi;
      if (angle < below_degrees && (!best || angle < best->angle_degrees))
        best = NarrowCorner{leaving[i].corner, {leaving[i].curve, leaving[j].curve}, angle};
    }
  if (!best) return best;
  // The clearance: the nearest curve not ending at the corner.
  const auto through = complex.corner_curve_ids(best->corner);
  if (const auto near = nearest_curve_except(complex, complex.vertices[complex.corner_vertex[best->corner]],
                                             {through.begin(), through.end()})) {
    best->nearest_curve = near->curve;
    best->clearance = near->distance;
  }
  return best;
}

std::optional<NearCurve> nearest_curve_except(const Complex& complex, const Vec3& where,
                                              std::span<const std::uint32_t> excluded) {
  std::optional<NearCurve> best;
  for (std::uint32_t e = 0; e < complex.edges.size(); ++e) {
    const std::uint32_t c = complex.edge_curve[e];
    if (c == kNoIndex || std::find(excluded.begin(), excluded.end(), c) != excluded.end()) continue;
    const Vec3 &a = complex.vertices[complex.edges[e][0]], &b = complex.vertices[complex.edges[e][1]];
    const double d = (kernel::closest_point_on_segment(where, a, b).point - where).norm();
    if (d > 0 && (!best || d < best->distance)) best = NearCurve{c, d};
  }
  return best;
}

std::optional<NearPatch> nearest_patch_except(const Complex& complex, const Vec3& where,
                                              std::span<const std::uint32_t> excluded) {
  std::optional<NearPatch> best;
  for (std::uint32_t t = 0; t < complex.triangles.size(); ++t) {
    const std::uint32_t patch = complex.triangle_patch[t];
    if (std::find(excluded.begin(), excluded.end(), patch) != excluded.end()) continue;
    const auto& v = complex.triangles[t];
    const Vec3 near =
        kernel::closest_point_on_triangle(where, complex.vertices[v[0]], complex.vertices[v[1]], complex.vertices[v[2]])
            .point;
    const double d = (near - where).norm();
    if (d > 0 && (!best || d < best->distance)) best = NearPatch{patch, d};
  }
  return best;
}

std::optional<NearCurve> curve_returning_near(const Complex& complex, std::uint32_t c, double s) {
  const Vec3 where = complex.point_at(c, s);
  const auto polyline = complex.curve_polyline(c);
  const auto arc = complex.curve_parameters(c);
  const double length = complex.curves[c].length;
  const bool closed = complex.curves[c].closed;
  s = complex.wrap_parameter(c, s);
  std::optional<NearCurve> best;
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
    const auto near = kernel::closest_point_on_segment(where, complex.vertices[polyline[i]], complex.vertices[polyline[i + 1]]);
    const double d = (near.point - where).norm();
    const double at = arc[i] + near.t * (arc[i + 1] - arc[i]);
    double along = std::abs(at - s);
    if (closed) along = std::min(along, length - along);
    if (d > 0 && along > 3 * d && (!best || d < best->distance)) best = NearCurve{c, d};
  }
  return best;
}

}  // namespace delpsc::protect
