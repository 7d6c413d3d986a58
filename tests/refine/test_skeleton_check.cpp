// check_skeleton (refine/skeleton_check.h) on input models given as their own meshes (every
// patch's triangles labelled, every curve's edges): the per-patch figures cut open along slits
// equal the complex's (the box with a fin: its bottom patch is a disk with an interior slit, an
// annulus once cut; the sample part's top face carries the fin), the uncut ones differ exactly
// there, and a broken patch is reported as not a manifold.
#include <doctest/doctest.h>

#include <algorithm>
#include <map>

#include <delpsc/io/sample_part.h>
#include <delpsc/io/shapes.h>
#include <delpsc/protect/complex_mesh.h>
#include <delpsc/refine/polygon_domain.h>
#include <delpsc/refine/skeleton_check.h>

using namespace delpsc;

namespace {

double tolerance(const refine::Domain& d) {
  const kernel::Box3 b = d.bounding_box();
  return 1e-9 * (b.hi - b.lo).norm();
}

// Patches with a slit in the input complex: the uncut figures differ from the cut ones.
std::size_t check_against_complex(const io::TriangleSoup& soup) {
  const refine::PolygonDomain domain(soup);
  const io::SurfaceMesh mesh = protect::to_surface_mesh(domain.complex());
  const refine::SkeletonReport report = refine::check_skeleton(mesh, domain, tolerance(domain));
  CHECK(report.ok());
  REQUIRE(report.patches.size() == domain.complex().patches.size());
  std::size_t slit_patches = 0;
  for (const auto& p : report.patches) {
    CHECK(p.manifold);
    CHECK(p.cut_euler == domain.complex().patches[p.patch].euler_characteristic);
    CHECK(p.cut_boundary_loops == domain.complex().patches[p.patch].boundary_loops);
    if (p.cut_euler != p.euler) {
      ++slit_patches;
      // One interior slit arc: one Euler less, one loop more.
      CHECK(p.cut_euler == p.euler - 1);
      CHECK(p.cut_boundary_loops == p.boundary_loops + 1);
    }
  }
  return slit_patches;
}

}  // namespace

TEST_CASE("skeleton check: cut-open topology equals the complex's, slits included") {
  CHECK(check_against_complex(io::make_cube(3)) == 0);
  CHECK(check_against_complex(io::make_capped_cylinder(1, 2, 16, 3, 2)) == 0);
  CHECK(check_against_complex(io::make_box_with_fin(4)) == 1);
  CHECK(check_against_complex(io::make_sample_part(32)) == 1);
}

TEST_CASE("skeleton check: a patch with an edge in three triangles is not a manifold") {
  const refine::PolygonDomain domain(io::make_cube(2));
  io::SurfaceMesh mesh = protect::to_surface_mesh(domain.complex());
  // A third triangle on an interior edge of the patch of triangle 0 (an edge in two of its
  // triangles), through a new vertex on the patch.
  const std::int32_t patch = mesh.triangle_patch[0];
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
    if (mesh.triangle_patch[i] == patch)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = mesh.triangles[i][k], b = mesh.triangles[i][(k + 1) % 3];
        ++uses[{std::min(a, b), std::max(a, b)}];
      }
  const auto interior = std::find_if(uses.begin(), uses.end(), [](const auto& u) { return u.second == 2; });
  REQUIRE(interior != uses.end());
  const auto [a, b] = interior->first;
  const auto& t = mesh.triangles[0];
  mesh.vertices.push_back((mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3);
  mesh.triangles.push_back({a, b, static_cast<std::uint32_t>(mesh.vertices.size() - 1)});
  mesh.triangle_patch.push_back(patch);
  const refine::SkeletonReport report = refine::check_skeleton(mesh, domain, tolerance(domain));
  CHECK(!report.ok());
  for (const auto& p : report.patches) CHECK(p.manifold == (p.patch != static_cast<std::uint32_t>(patch)));
}
