#include "acceptance.h"

#include <doctest/doctest.h>

#include <Eigen/Geometry>

#include <delpsc/io/read_model.h>
#include <delpsc/protect/complex_mesh.h>
#include <delpsc/protect/protect.h>
#include <delpsc/refine/complex_topology.h>
#include <delpsc/refine/mesher.h>
#include <delpsc/refine/polygon_domain.h>
#include <delpsc/refine/protected_balls.h>

#include "cgal_demo_data.h"
#include "mesher_checks.h"
#include "orientation_check.h"
#include "problem_lines.h"

namespace delpsc::test {

AcceptanceRun check_acceptance(const std::string& name, const io::TriangleSoup& soup, double size_fraction,
                               std::size_t max_vertices, ExtraCriteria criteria) {
  CAPTURE(name);
  CAPTURE(size_fraction);
  CAPTURE(criteria.facet_distance_of_lambda);
  CAPTURE(criteria.facet_angle_degrees);
  const refine::PolygonDomain domain(soup);
  const kernel::Box3 box = domain.bounding_box();
  const double lambda = size_fraction * (box.hi - box.lo).norm();
  const protect::ProtectOptions ball_options = protect::options_for_size(lambda, (box.hi - box.lo).norm());
  protect::BallSet set = protect::protect(domain.complex(), lambda, ball_options);  // as delpsc mesh
  refine::ProtectedBalls balls(set, ball_options);
  refine::MesherOptions options;
  options.facet_size = lambda;
  options.max_vertices = max_vertices;
  options.facet_distance = criteria.facet_distance_of_lambda * lambda;
  options.facet_angle = criteria.facet_angle_degrees;
  refine::Mesher mesher(domain, balls, options);
  run_mesher_and_check(mesher, &set);
  const io::SurfaceMesh mesh = mesher.output();
  const refine::SkeletonReport report = check_g1(mesh, domain);
  // G2 per patch: protect::Patch counts the input patch cut open along its slits, and so do the
  // cut_* figures of the output's patch.
  REQUIRE(report.patches.size() == domain.complex().patches.size());
  for (const refine::PatchSkeleton& p : report.patches) {
    CAPTURE(p.patch);
    CHECK(p.cut_euler == domain.complex().patches[p.patch].euler_characteristic);
    CHECK(p.cut_boundary_loops == domain.complex().patches[p.patch].boundary_loops);
  }
  // G2 for the whole output, against the cleaned input triangles the mesher meshed.
  const refine::ComplexTopology out = refine::complex_topology(mesh.triangles);
  const refine::ComplexTopology in = refine::complex_topology(domain.complex().triangles);
  for (const std::string& d : refine::topology_differences(out, in)) FAIL_CHECK(d);
  CHECK(mesh.corners.size() == domain.corner_count());
  // Consistently oriented, outward where closed (Mesher::output()); G1 does not look at it.
  const std::vector<std::string> orientation = orientation_problems(mesh);
  CHECK_MESSAGE(orientation.empty(), problem_lines(orientation));
  // ...and as the input is where a component has no inside of its own, when the input itself is
  // wound consistently and outward where closed (boeing.off, welded, is not).
  if (orientation_problems(protect::to_surface_mesh(domain.complex()), 1).empty()) {
    const std::vector<std::string> against = patches_against_input(mesh, domain);
    CHECK_MESSAGE(against.empty(), problem_lines(against));
  }
  MESSAGE(name << " at " << size_fraction * 100 << "%: vertices=" << mesh.vertices.size()
               << " ball_refinements=" << mesher.stats().ball_refinements);
  return {mesh.vertices.size(), mesher.stats().ball_refinements};
}

io::TriangleSoup rotated_model(io::TriangleSoup soup) {
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(1.1, Vec3::UnitZ()) * Eigen::AngleAxisd(0.7, Vec3::UnitY()) *
                             Eigen::AngleAxisd(0.3, Vec3::UnitX()))
                                .toRotationMatrix();
  for (Vec3& v : soup.vertices) v = r * v;
  return soup;
}

io::TriangleSoup cgal_demo_model(const std::string& name) { return cgal_demo_soup(name).value_or(io::TriangleSoup{}); }

}  // namespace delpsc::test
