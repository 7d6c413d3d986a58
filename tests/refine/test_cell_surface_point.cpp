// refine/cell_surface_point.h on the configuration that empties a ball's umbrella: a thin tube
// (a cylinder of radius 0.05) crossing a ball's power cell that two points along the tube squeeze
// into a slab, |z - 1| < 0.0167, reaching far sideways. The tube's band in the slab meets no
// Voronoi edge of the cell (no restricted facet); the point found is the tube's far side, in the
// cell, outside the ball, and the power-nearest vertex of it is the ball. Then the same cell with
// the segments and closest points hidden: the last resort, the tube's triangles clipped to the
// cell, finds the farthest point of the tube in it.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

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

/// A domain whose segments meet nothing and which has no closest point: only the last resort of
/// surface_point_in_cell (triangles_in_box, clipped to the cell) can find the surface.
class ClipOnly final : public refine::Domain {
 public:
  explicit ClipOnly(const refine::Domain& d) : d_(d) {}
  kernel::Box3 bounding_box() const override { return d_.bounding_box(); }
  std::uint32_t corner_count() const override { return d_.corner_count(); }
  Vec3 corner_point(std::uint32_t k) const override { return d_.corner_point(k); }
  std::span<const std::uint32_t> corner_curves(std::uint32_t k) const override { return d_.corner_curves(k); }
  std::span<const std::uint32_t> corner_patches(std::uint32_t k) const override { return d_.corner_patches(k); }
  std::uint32_t curve_count() const override { return d_.curve_count(); }
  double curve_length(std::uint32_t c) const override { return d_.curve_length(c); }
  bool curve_closed(std::uint32_t c) const override { return d_.curve_closed(c); }
  std::uint32_t curve_start_corner(std::uint32_t c) const override { return d_.curve_start_corner(c); }
  std::uint32_t curve_end_corner(std::uint32_t c) const override { return d_.curve_end_corner(c); }
  Vec3 curve_point(std::uint32_t c, double s) const override { return d_.curve_point(c, s); }
  double curve_distance(std::uint32_t c, double s0, double s1) const override { return d_.curve_distance(c, s0, s1); }
  refine::CurveSegment curve_segment_in_ball(std::uint32_t c, double s, double r) const override {
    return d_.curve_segment_in_ball(c, s, r);
  }
  double curve_closest_parameter(std::uint32_t c, const Vec3& p) const override { return d_.curve_closest_parameter(c, p); }
  std::span<const std::uint32_t> curve_patches(std::uint32_t c) const override { return d_.curve_patches(c); }
  std::uint32_t patch_count() const override { return d_.patch_count(); }
  std::span<const std::uint32_t> patch_curves(std::uint32_t p) const override { return d_.patch_curves(p); }
  Vec3 patch_interior_point(std::uint32_t p) const override { return d_.patch_interior_point(p); }
  void intersect_segment(const Vec3&, const Vec3&, std::vector<refine::SurfaceHit>& out) const override { out.clear(); }
  void intersect_ray(const Vec3&, const Vec3&, std::vector<refine::SurfaceHit>& out) const override { out.clear(); }
  std::optional<refine::ClosestSurfacePoint> closest_point(const Vec3&, double) const override { return std::nullopt; }
  void triangles_in_box(const kernel::Box3& box, std::vector<refine::PatchTriangle>& out) const override {
    d_.triangles_in_box(box, out);
  }

 private:
  const refine::Domain& d_;
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

TEST_CASE("the last resort: the tube's triangles clipped to the cell give its farthest point there") {
  SlabCell s;
  const double r2 = s.points[0].w;
  const auto any = [](std::uint32_t) { return true; };
  const ClipOnly hidden(s.tube);
  const auto hit = refine::surface_point_in_cell(s.dt, hidden, s.ball(), 1.25 * r2, any);
  REQUIRE(hit);
  CHECK(std::abs(hit->point.z() - 1) < 0.0167);  // in the slab
  const double radius = std::hypot(hit->point.x(), hit->point.y());
  CHECK(radius > 0.05 * std::cos(std::numbers::pi / 24) - 1e-12);  // on the 24-sided tube
  CHECK(radius < 0.05 + 1e-12);
  const double to_ball = (hit->point - s.points[0].point()).squaredNorm() - r2;
  CHECK(to_ball >= 1.25 * r2);
  for (std::size_t i = 1; i < s.points.size(); ++i)
    CHECK((hit->point - s.points[i].point()).squaredNorm() - s.points[i].w > to_ball);
  // The farthest point of the tube in the cell: at least as far as the segments' best, and
  // across the tube from the ball.
  const auto by_segments = refine::surface_point_in_cell(s.dt, s.tube, s.ball(), 1.25 * r2, any);
  REQUIRE(by_segments);
  CHECK(to_ball >= (by_segments->point - s.points[0].point()).squaredNorm() - r2 - 1e-12);
  CHECK(hit->point.x() < -0.04);
  // Nothing when no patch is wanted, or when the cell holds nothing that far out.
  CHECK_FALSE(refine::surface_point_in_cell(s.dt, hidden, s.ball(), 0, [](std::uint32_t) { return false; }));
  CHECK_FALSE(refine::surface_point_in_cell(s.dt, hidden, s.ball(), 1.0, any));
}
