// summarize_quality (refine/quality_summary.h) on triangles whose angles and circumradii are
// known in closed form, and the radius-edge ratio against the circumradius computed directly
// (R = abc / 4·area) on random triangles.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>

#include <delpsc/refine/quality_summary.h>

using namespace delpsc;

TEST_CASE("quality of known triangles") {
  io::SurfaceMesh mesh;
  refine::QualitySummary q = refine::summarize_quality(mesh);
  CHECK(q.triangles == 0);
  CHECK(q.min_angle_degrees == 180);
  CHECK(q.max_radius_edge_ratio == 0);

  // Equilateral: 60°, R / l = 1/√3, in the last bin.
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0}};
  mesh.triangles = {{0, 1, 2}};
  q = refine::summarize_quality(mesh);
  CHECK(q.min_angle_degrees == doctest::Approx(60).epsilon(1e-12));
  CHECK(q.max_angle_degrees == doctest::Approx(60).epsilon(1e-12));
  CHECK(q.max_radius_edge_ratio == doctest::Approx(1 / std::sqrt(3.0)).epsilon(1e-12));
  CHECK(q.min_angle_histogram[5] == 1);

  // Add a right isosceles triangle out of the plane: 45° and 90°, R = hypotenuse / 2 = √2 / 2
  // over the leg 1.
  mesh.vertices.push_back({0, 0, 1});
  mesh.vertices.push_back({0, 1, 1});
  mesh.vertices.push_back({0, 0, 2});
  mesh.triangles.push_back({3, 4, 5});
  q = refine::summarize_quality(mesh);
  CHECK(q.triangles == 2);
  CHECK(q.min_angle_degrees == doctest::Approx(45).epsilon(1e-12));
  CHECK(q.max_angle_degrees == doctest::Approx(90).epsilon(1e-12));
  CHECK(q.max_radius_edge_ratio == doctest::Approx(std::sqrt(2.0) / 2).epsilon(1e-12));
  CHECK(q.mean_radius_edge_ratio == doctest::Approx((std::sqrt(2.0) / 2 + 1 / std::sqrt(3.0)) / 2).epsilon(1e-12));
  CHECK(q.min_angle_histogram[4] == 1);
  CHECK(q.min_angle_histogram[5] == 1);

  // A degenerate (collinear) triangle: angles 0 and 180, an infinite ratio.
  mesh.vertices.push_back({5, 0, 0});
  mesh.vertices.push_back({6, 0, 0});
  mesh.vertices.push_back({7, 0, 0});
  mesh.triangles.push_back({6, 7, 8});
  q = refine::summarize_quality(mesh);
  CHECK(q.min_angle_degrees == 0);
  CHECK(q.max_angle_degrees == doctest::Approx(180));
  CHECK(q.max_radius_edge_ratio == std::numeric_limits<double>::infinity());
  CHECK(q.min_angle_histogram[0] == 1);
}

TEST_CASE("radius-edge ratio agrees with the circumradius computed from the side lengths") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    io::SurfaceMesh mesh;
    for (int k = 0; k < 3; ++k) mesh.vertices.push_back({coord(rng), coord(rng), coord(rng)});
    mesh.triangles = {{0, 1, 2}};
    const Vec3 &a = mesh.vertices[0], &b = mesh.vertices[1], &c = mesh.vertices[2];
    const double ab = (b - a).norm(), bc = (c - b).norm(), ca = (a - c).norm();
    const double area = (b - a).cross(c - a).norm() / 2;
    const double circumradius = ab * bc * ca / (4 * area);
    const refine::QualitySummary q = refine::summarize_quality(mesh);
    CHECK(q.max_radius_edge_ratio == doctest::Approx(circumradius / std::min({ab, bc, ca})).epsilon(1e-9));
    std::size_t binned = 0;
    for (const auto n : q.min_angle_histogram) binned += n;
    CHECK(binned == 1);
  }
}
