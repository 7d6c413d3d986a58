// refine/cell_surface_point.h on the configuration that empties a ball's umbrella: a thin tube
// (a cylinder of radius 0.05) crossing a ball's power cell that two points along the tube squeeze
// into a slab, |z - 1| < 0.0167, reaching far sideways. The tube's band in the slab meets no
// Voronoi edge of the cell (no restricted facet); the point found is the tube's far side, in the
// cell, outside the ball, and the power-nearest vertex of it is the ball.
#include <doctest/doctest.h>

#include <cmath>

#include <delpsc/delaunay/regular_triangulation.h>
#include <delpsc/io/shapes.h>
#include <delpsc/refine/cell_surface_point.h>
#include <delpsc/refine/polygon_domain.h>

using namespace delpsc;

namespace {

struct SlabCell {
  refine::PolygonDomain tube{io::make_capped_cylinder(0.05, 2, 24, 8, 4)};
  delaunay::RegularTriangulation dt;
  std::vector<WeightedPoint> points;
  std::vector<delaunay::PointId> ids;  // of points, in order (the batch is sorted)

  SlabCell() {
    points.push_back({0.05, 0, 1, 0.01 * 0.01});  // the ball, r = 0.01, on the tube's side
    points.push_back({0.05, 0, 1.03, 0});         // the slab's two walls
    points.push_back({0.05, 0, 0.97, 0});
    for (int k = 0; k < 8; ++k)  // a far frame
      points.push_back({k & 1 ? 10.0 : -10.0, k & 2 ? 10.0 : -10.0, k & 4 ? 11.0 : -9.0, 0});
    dt.insert(points, &ids);
  }
  delaunay::PointId ball() const { return ids[0]; }
};

}  // namespace

TEST_CASE("a point of the tube's far side in the slab cell of a ball") {
  SlabCell s;
  REQUIRE(s.dt.status(s.ball()) == delaunay::PointStatus::vertex);
  const double r2 = s.points[0].w;
  const auto hit = refine::surface_point_in_cell(s.dt, s.tube, s.ball(), 1.25 * r2, [](std::uint32_t) { return true; });
  REQUIRE(hit);
  CHECK(hit->point.x() < -0.04);  // across the tube, ~0.1 from the ball's centre
  CHECK(std::abs(hit->point.z() - 1) < 0.0167);
  CHECK(std::hypot(hit->point.x(), hit->point.y()) == doctest::Approx(0.05).epsilon(0.02));  // on the tube
  // Outside the ball by at least 1.5 radii, and power-nearest to it among all points.
  const double to_ball = (hit->point - s.points[0].point()).squaredNorm() - r2;
  CHECK(to_ball >= 1.25 * r2);
  for (std::size_t i = 1; i < s.points.size(); ++i)
    CHECK((hit->point - s.points[i].point()).squaredNorm() - s.points[i].w > to_ball);
}

TEST_CASE("no point: nothing far enough out, or no patch wanted") {
  SlabCell s;
  const auto any = [](std::uint32_t) { return true; };
  CHECK_FALSE(refine::surface_point_in_cell(s.dt, s.tube, s.ball(), 1.0, any));  // 1.0 > the tube's 0.1²
  CHECK_FALSE(refine::surface_point_in_cell(s.dt, s.tube, s.ball(), 0, [](std::uint32_t) { return false; }));
}
