// The mesher on models with corners and curves, protected by protect::protect: G1 per patch
// (a 2-manifold whose boundary is exactly the chain of ball centres along its boundary curves,
// every vertex on the domain), the disk condition everywhere at the end, and at these sizes the
// input patch's Euler characteristic and boundary loop count (G2 per patch).
#include <doctest/doctest.h>

#include <algorithm>

#include <delpsc/io/shapes.h>
#include <delpsc/refine/mesher.h>
#include <delpsc/refine/polygon_domain.h>
#include <delpsc/refine/protected_balls.h>
#include <delpsc/refine/skeleton_check.h>

using namespace delpsc;

namespace {

struct Outcome {
  refine::SkeletonReport report;
  refine::MesherStats stats;
  std::size_t vertices = 0;
};

Outcome mesh_model(const io::TriangleSoup& soup, double size_fraction) {
  refine::PolygonDomain domain(soup);
  const kernel::Box3 box = domain.bounding_box();
  const double diag = (box.hi - box.lo).norm();
  const double lambda = size_fraction * diag;
  protect::BallSet set = protect::protect(domain.complex(), lambda);
  refine::ProtectedBalls balls(set);
  refine::MesherOptions options;
  options.facet_size = lambda;
  options.max_vertices = 30000;
  refine::Mesher mesher(domain, balls, options);
  mesher.run();
  INFO("message: " << mesher.stats().message);
  CHECK_FALSE(mesher.stats().stuck);
  CHECK_FALSE(mesher.stats().stopped_at_max_vertices);
  CHECK(mesher.failing_vertices().empty());
  Outcome out;
  const io::SurfaceMesh mesh = mesher.output();
  out.report = refine::check_skeleton(mesh, domain, 1e-9 * diag);
  for (const auto& p : out.report.problems) INFO(p);
  CHECK(out.report.ok());
  // G2 per patch at this size: the input patch's topology. Skipped for a patch on both sides of
  // a curve (a slit): the complex counts its cut surface, Skl² is not cut along the slit.
  for (const auto& p : out.report.patches) {
    const auto curves = domain.patch_curves(p.patch);
    bool slit = false;
    for (const auto c : curves) slit |= std::count(curves.begin(), curves.end(), c) > 1;
    if (slit) continue;
    CHECK(p.euler == domain.complex().patches[p.patch].euler_characteristic);
    CHECK(p.boundary_loops == domain.complex().patches[p.patch].boundary_loops);
  }
  CHECK(mesh.corners.size() == domain.corner_count());
  out.stats = mesher.stats();
  out.vertices = mesh.vertices.size();
  MESSAGE("vertices=" << out.vertices << " triangles=" << mesh.triangles.size()
                      << " ball_refinements=" << out.stats.ball_refinements);
  return out;
}

}  // namespace

TEST_CASE("cube") {
  mesh_model(io::make_cube(4), 0.1);
  mesh_model(io::make_cube(4), 0.04);
}

TEST_CASE("open square sheet") { mesh_model(io::make_square_sheet(4), 0.04); }

TEST_CASE("capped cylinder") { mesh_model(io::make_capped_cylinder(1, 2, 24, 8, 4), 0.04); }

TEST_CASE("coarse sizes force ball refinements") {
  mesh_model(io::make_cube(4), 0.3);
  mesh_model(io::make_capped_cylinder(1, 2, 24, 8, 4), 0.3);
}

TEST_CASE("book of three sheets (non-manifold spine)") { mesh_model(io::make_book(3, 4), 0.04); }
TEST_CASE("box with a fin (slit)") { mesh_model(io::make_box_with_fin(4), 0.04); }
// Not yet: the wedge with a 10° edge does not terminate below 30,000 vertices at 4% (D1/D2
// failures near the sharp edge keep refining); see issue 6.
TEST_CASE("disc sheet") { mesh_model(io::make_disc_sheet(24, 4), 0.04); }
