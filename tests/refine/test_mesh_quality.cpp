// min_triangle_angle_degrees on triangles whose angles are known in closed form.
#include <doctest/doctest.h>

#include <cmath>

#include <delpsc/refine/mesh_quality.h>

using namespace delpsc;

TEST_CASE("smallest angle of known triangles") {
  io::SurfaceMesh mesh;
  CHECK(refine::min_triangle_angle_degrees(mesh) == 180);
  // Equilateral: 60.
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0}};
  mesh.triangles = {{0, 1, 2}};
  CHECK(refine::min_triangle_angle_degrees(mesh) == doctest::Approx(60).epsilon(1e-12));
  // Add a right triangle with legs 1 and tan(10°), tilted out of the plane: 10.
  const double t = std::tan(10 * std::acos(-1.0) / 180);
  mesh.vertices.push_back({0, 0, 1});
  mesh.vertices.push_back({0, 1, 1});
  mesh.vertices.push_back({0, 1, 1 + t});
  mesh.triangles.push_back({3, 4, 5});
  CHECK(refine::min_triangle_angle_degrees(mesh) == doctest::Approx(10).epsilon(1e-12));
  // A needle of angle 1e-9 rad, where acos would lose it: atan2 keeps it.
  mesh.vertices.push_back({0, 0, 5});
  mesh.vertices.push_back({1, 0, 5});
  mesh.vertices.push_back({1, 1e-9, 5});
  mesh.triangles.push_back({6, 7, 8});
  CHECK(refine::min_triangle_angle_degrees(mesh) == doctest::Approx(1e-9 * 180 / std::acos(-1.0)).epsilon(1e-6));
}
