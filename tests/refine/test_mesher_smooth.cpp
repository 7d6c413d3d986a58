// The mesher on closed smooth surfaces without features (no balls): the sphere and the torus.
// G1 (each patch's Skl² a closed 2-manifold with every vertex on the patch) and, at these sizes,
// G2 (the Euler characteristic of the input patch); the disk condition holds at every vertex.
#include <doctest/doctest.h>

#include <delpsc/io/shapes.h>
#include <delpsc/refine/mesher.h>
#include <delpsc/refine/polygon_domain.h>
#include <delpsc/refine/skeleton_check.h>

#include "support/mesher_checks.h"

using namespace delpsc;

namespace {

double diagonal(const refine::Domain& d) {
  const kernel::Box3 b = d.bounding_box();
  return (b.hi - b.lo).norm();
}

void check_smooth(const io::TriangleSoup& soup, double size_fraction, int expected_euler) {
  refine::PolygonDomain domain(soup);
  REQUIRE(domain.curve_count() == 0);
  refine::NoBalls balls;
  refine::MesherOptions options;
  options.facet_size = size_fraction * diagonal(domain);
  options.max_vertices = 20000;
  refine::Mesher mesher(domain, balls, options);
  test::run_mesher_and_check(mesher);
  CHECK(mesher.triangulation().is_valid());
  const io::SurfaceMesh mesh = mesher.output();
  const refine::SkeletonReport report = test::check_g1(mesh, domain);
  REQUIRE(report.patches.size() == 1);
  CHECK(report.patches[0].euler == expected_euler);
  CHECK(report.patches[0].boundary_loops == 0);
  // Every restricted facet is no larger than λ at the end (step 2b).
  mesher.restricted_facets().for_each(
      [&](std::uint32_t, const refine::RestrictedFacet& r) { CHECK(r.size <= options.facet_size); });
  MESSAGE("vertices=" << mesh.vertices.size() << " triangles=" << mesh.triangles.size());
}

}  // namespace

TEST_CASE("sphere: closed 2-manifold of Euler characteristic 2") {
  check_smooth(io::make_sphere(8), 0.1, 2);
  check_smooth(io::make_sphere(8), 0.04, 2);
}

TEST_CASE("torus: closed 2-manifold of Euler characteristic 0") {
  check_smooth(io::make_torus(1, 0.35, 32, 16), 0.04, 0);
}

TEST_CASE("facet_size must be positive") {
  refine::PolygonDomain domain(io::make_sphere(4));
  refine::NoBalls balls;
  CHECK_THROWS_AS(refine::Mesher(domain, balls, refine::MesherOptions{}), std::invalid_argument);
}
