// check_skeleton (refine/skeleton_check.h) on input models given as their own meshes (every
// patch's triangles labelled, every curve's edges): the per-patch figures cut open along slits
// equal the complex's (the box with a fin: its bottom patch is a disk with an interior slit, an
// annulus once cut; the sample part's top face carries the fin), the uncut ones differ exactly
// there, and a broken patch is reported as not a manifold.
#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <string>

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

TEST_CASE("skeleton check: a stop ends it undecided; a stop that never says so changes nothing") {
  // 41 x 41 vertices a face: the fan loop polls after every 1,024 vertices of a patch.
  const refine::PolygonDomain domain(io::make_cube(40));
  const io::SurfaceMesh mesh = protect::to_surface_mesh(domain.complex());
  const refine::SkeletonReport whole = refine::check_skeleton(mesh, domain, tolerance(domain));
  REQUIRE(whole.ok());
  int calls = 0;
  const refine::SkeletonReport polled =
      refine::check_skeleton(mesh, domain, tolerance(domain), [&calls] { return ++calls, false; });
  CHECK(polled.ok());
  CHECK_FALSE(polled.stopped);
  CHECK(polled.patches.size() == whole.patches.size());
  CHECK(calls >= 6);  // at least once in each face's fans
  // Stopped in the first patch's fans (after the 12 curves' polls): undecided, not ok, though
  // no problem was found.
  calls = 0;
  const refine::SkeletonReport cut =
      refine::check_skeleton(mesh, domain, tolerance(domain), [&calls] { return ++calls > 12; });
  CHECK(cut.stopped);
  CHECK_FALSE(cut.ok());
  CHECK(cut.problems.empty());
  CHECK(cut.patches.empty());
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

namespace {

bool mentions(const refine::SkeletonReport& report, const std::string& what) {
  return std::any_of(report.problems.begin(), report.problems.end(),
                     [&](const std::string& p) { return p.find(what) != std::string::npos; });
}

// A vertex of the mesh inside a patch (on no feature edge) and the triangles around it.
std::pair<std::uint32_t, std::vector<std::size_t>> interior_vertex(const io::SurfaceMesh& mesh) {
  std::vector<bool> on_curve(mesh.vertices.size(), false);
  for (const auto& e : mesh.edges) on_curve[e[0]] = on_curve[e[1]] = true;
  for (std::uint32_t v = 0; v < mesh.vertices.size(); ++v) {
    if (on_curve[v]) continue;
    std::vector<std::size_t> fan;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      if (std::count(mesh.triangles[t].begin(), mesh.triangles[t].end(), v)) fan.push_back(t);
    if (fan.size() >= 4) return {v, fan};
  }
  return {0, {}};
}

void erase_triangles(io::SurfaceMesh& mesh, std::vector<std::size_t> which) {
  std::sort(which.rbegin(), which.rend());
  for (const std::size_t t : which) {
    mesh.triangles.erase(mesh.triangles.begin() + static_cast<std::ptrdiff_t>(t));
    mesh.triangle_patch.erase(mesh.triangle_patch.begin() + static_cast<std::ptrdiff_t>(t));
  }
}

}  // namespace

TEST_CASE("skeleton check: holes, pinched fans and vertices off the model are reported") {
  const refine::PolygonDomain domain(io::make_cube(6));
  const io::SurfaceMesh original = protect::to_surface_mesh(domain.complex());
  REQUIRE(refine::check_skeleton(original, domain, tolerance(domain)).ok());
  const auto [v, fan] = interior_vertex(original);
  REQUIRE(fan.size() >= 4);
  const auto patch = static_cast<std::uint32_t>(original.triangle_patch[fan[0]]);

  SUBCASE("a hole: a boundary that is no curve, one more loop") {
    // A triangle with no vertex on a curve, so the hole's boundary does not touch the patch's.
    std::vector<bool> on_curve(original.vertices.size(), false);
    for (const auto& e : original.edges) on_curve[e[0]] = on_curve[e[1]] = true;
    const auto inner = std::find_if(fan.begin(), fan.end(), [&](std::size_t t) {
      const auto& c = original.triangles[t];
      return !on_curve[c[0]] && !on_curve[c[1]] && !on_curve[c[2]];
    });
    REQUIRE(inner != fan.end());
    io::SurfaceMesh mesh = original;
    erase_triangles(mesh, {*inner});
    const auto report = refine::check_skeleton(mesh, domain, tolerance(domain));
    CHECK(mentions(report, "is not on a boundary curve"));
    CHECK(report.patches[patch].boundary_loops == 2);
    CHECK(report.patches[patch].manifold);  // still a surface, with a hole
  }
  SUBCASE("a pinched fan: the triangles around a vertex are two disks") {
    io::SurfaceMesh mesh = original;
    // Two triangles of the fan sharing no edge: what is left around v is two paths.
    std::size_t second = 0;
    for (std::size_t i = 1; i < fan.size() && second == 0; ++i) {
      int shared = 0;
      for (const auto a : original.triangles[fan[0]])
        shared += static_cast<int>(std::count(original.triangles[fan[i]].begin(), original.triangles[fan[i]].end(), a));
      if (shared == 1) second = i;  // only v in common
    }
    REQUIRE(second != 0);
    erase_triangles(mesh, {fan[0], fan[second]});
    const auto report = refine::check_skeleton(mesh, domain, tolerance(domain));
    CHECK(mentions(report, "the triangles around vertex " + std::to_string(v) + " are not one disk"));
    CHECK_FALSE(report.patches[patch].manifold);
  }
  SUBCASE("a vertex off the model") {
    io::SurfaceMesh mesh = original;
    mesh.vertices[v] += Vec3(0.01, 0.02, 0.03);
    const auto report = refine::check_skeleton(mesh, domain, tolerance(domain));
    CHECK(mentions(report, "vertex " + std::to_string(v) + " is off the domain"));
  }
  SUBCASE("a vertex just off the model: the tolerance decides, near the closest-point search's bound and beyond it") {
    // The search for a vertex's closest point is bounded by twice the tolerance; a vertex is off
    // the domain beyond the tolerance, whether the bounded search finds a point or none.
    const auto& t = original.triangles[fan[0]];
    const Vec3 normal = (original.vertices[t[1]] - original.vertices[t[0]])
                            .cross(original.vertices[t[2]] - original.vertices[t[0]])
                            .normalized();
    const double tol = tolerance(domain);
    for (const double times : {0.5, 1.5, 3.0, 1e3}) {
      CAPTURE(times);
      io::SurfaceMesh mesh = original;
      mesh.vertices[v] += times * tol * normal;
      const auto report = refine::check_skeleton(mesh, domain, tol);
      CHECK(mentions(report, "vertex " + std::to_string(v) + " is off the domain") == (times > 1));
      CHECK(report.ok() == (times < 1));
    }
  }
  SUBCASE("a patch's triangle labelled with another patch") {
    io::SurfaceMesh mesh = original;
    mesh.triangle_patch[fan[0]] = static_cast<std::int32_t>((patch + 1) % domain.patch_count());
    const auto report = refine::check_skeleton(mesh, domain, tolerance(domain));
    CHECK(mentions(report, "lies on patch " + std::to_string(patch)));
    CHECK(mentions(report, "is not on a boundary curve"));
  }
}

TEST_CASE("skeleton check: a corner on no curve lies on each of its patches, and on no other") {
  // Two spheres touching at a vertex, and a third apart: the contact vertex is a corner of the
  // first two patches; its closest point names only one of them, which made the other's
  // triangles around it "lie on" the wrong patch.
  io::TriangleSoup soup = io::make_touching_spheres(4);
  const io::TriangleSoup third = io::make_sphere(4);
  const auto first = static_cast<std::uint32_t>(soup.vertices.size());
  for (const Vec3& v : third.vertices) soup.vertices.push_back(v + Vec3(5, 0, 0));
  for (const auto& t : third.triangles) soup.triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
  const refine::PolygonDomain domain(soup);
  REQUIRE(domain.patch_count() == 3);
  REQUIRE(domain.corner_count() == 1);
  REQUIRE(domain.curve_count() == 0);
  io::SurfaceMesh mesh = protect::to_surface_mesh(domain.complex());
  REQUIRE(mesh.corners.size() == 1);
  const refine::SkeletonReport good = refine::check_skeleton(mesh, domain, tolerance(domain));
  CHECK_MESSAGE(good.ok(), (good.problems.empty() ? std::string() : good.problems.front()));
  // A triangle of the third sphere moved onto the contact vertex: that patch does not hold it.
  const std::uint32_t contact = mesh.corners[0];
  const auto t = static_cast<std::size_t>(
      std::find(mesh.triangle_patch.begin(), mesh.triangle_patch.end(), mesh.triangle_patch.back()) -
      mesh.triangle_patch.begin());
  mesh.triangles[t][0] = contact;
  const refine::SkeletonReport bad = refine::check_skeleton(mesh, domain, tolerance(domain));
  CHECK_FALSE(bad.ok());
  bool named = false;
  for (const std::string& p : bad.problems) named |= p.find("(corner 0) is not on it") != std::string::npos;
  CHECK(named);
}

TEST_CASE("skeleton check: labels out of range, and curve or corner vertices off the complex") {
  const refine::PolygonDomain domain(io::make_cube(2));
  const io::SurfaceMesh good = protect::to_surface_mesh(domain.complex());
  REQUIRE(refine::check_skeleton(good, domain, tolerance(domain)).ok());
  REQUIRE(!good.edges.empty());
  REQUIRE(!good.corners.empty());
  const auto problems_of = [&](const io::SurfaceMesh& mesh) {
    const refine::SkeletonReport report = refine::check_skeleton(mesh, domain, tolerance(domain));
    std::string text;
    for (const std::string& p : report.problems) text += p + "\n";
    return text;
  };
  // A triangle far off the cube labelled with no patch: it belonged to no Skl²|σ and passed.
  for (const std::int32_t label : {999, -1}) {
    CAPTURE(label);
    io::SurfaceMesh mesh = good;
    const auto n = static_cast<std::uint32_t>(mesh.vertices.size());
    mesh.vertices.push_back(Vec3(5, 5, 5));
    mesh.triangles.push_back({0, 1, n});
    mesh.triangle_patch.push_back(label);
    CHECK(problems_of(mesh).find("not a patch of the domain") != std::string::npos);
  }
  {
    io::SurfaceMesh mesh = good;
    mesh.triangle_patch.pop_back();
    CHECK(problems_of(mesh).find("patch labels for") != std::string::npos);
  }
  {
    io::SurfaceMesh mesh = good;
    mesh.edge_curve[0] = static_cast<std::int32_t>(domain.curve_count());
    CHECK(problems_of(mesh).find("not a curve of the domain") != std::string::npos);
  }
  {
    io::SurfaceMesh mesh = good;
    mesh.triangles[0][1] = static_cast<std::uint32_t>(mesh.vertices.size());
    CHECK(problems_of(mesh).find("vertex index out of range") != std::string::npos);
  }
  {
    // An edge given to a curve it does not lie on (the cube's curves are its 12 edges, and no
    // two share both ends).
    io::SurfaceMesh mesh = good;
    const std::int32_t other = (mesh.edge_curve[0] + 1) % static_cast<std::int32_t>(domain.curve_count());
    mesh.edge_curve[0] = other;
    CHECK(problems_of(mesh).find("off that curve") != std::string::npos);
  }
  {
    // A corner vertex that is no corner: the centre of triangle 0, added as a vertex.
    io::SurfaceMesh mesh = good;
    const auto& t = mesh.triangles[0];
    mesh.vertices.push_back((mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3);
    mesh.corners.push_back(static_cast<std::uint32_t>(mesh.vertices.size() - 1));
    CHECK(problems_of(mesh).find("at no corner") != std::string::npos);
  }
}

TEST_CASE("skeleton check: a pinched patch is one disk per fan at its corner") {
  const io::TriangleSoup soup = io::make_pinched_sheet(4);
  const refine::PolygonDomain domain(soup);
  REQUIRE(domain.complex().pinches.size() == 1);
  const io::SurfaceMesh input = protect::to_surface_mesh(domain.complex());
  const refine::SkeletonReport report = refine::check_skeleton(input, domain, tolerance(domain));
  CHECK(report.ok());
  REQUIRE(report.patches.size() == 1);
  CHECK(report.patches[0].manifold);
  CHECK(report.patches[0].cut_euler == domain.complex().patches[0].euler_characteristic);
  CHECK(report.patches[0].cut_boundary_loops == domain.complex().patches[0].boundary_loops);
  // One hole filled again: the triangles around the pinch are one disk, not the two fans the
  // domain has there.
  const io::TriangleSoup whole = io::make_square_sheet(4);
  io::SurfaceMesh filled = input;
  for (const auto& t : whole.triangles)
    if (std::find(soup.triangles.begin(), soup.triangles.end(), t) == soup.triangles.end()) {
      filled.triangles.push_back(t);
      filled.triangle_patch.push_back(0);
      break;
    }
  REQUIRE(filled.triangles.size() == input.triangles.size() + 1);
  const std::uint32_t pinch = domain.complex().pinches[0][0];
  const auto broken = refine::check_skeleton(filled, domain, tolerance(domain));
  CHECK(mentions(broken, "the triangles around vertex " + std::to_string(pinch) + " are not one disk per fan"));
  CHECK_FALSE(broken.patches[0].manifold);
}
