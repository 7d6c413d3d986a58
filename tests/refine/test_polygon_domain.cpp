// The Domain of a polygon mesh: intersections reported once per patch per crossing where a
// segment passes exactly through mesh vertices, mesh edges, feature curves and corners; coplanar
// overlaps; rays; generic segments against brute force; the curve and patch queries.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <set>

#include <delpsc/io/shapes.h>
#include <delpsc/kernel/constructions.h>
#include <delpsc/refine/polygon_domain.h>

using namespace delpsc;
using refine::PolygonDomain;
using refine::SurfaceHit;

namespace {

std::vector<SurfaceHit> hits_of(const PolygonDomain& d, const Vec3& a, const Vec3& b) {
  std::vector<SurfaceHit> out;
  d.intersect_segment(a, b, out);
  return out;
}

std::set<std::uint32_t> patches_of(const std::vector<SurfaceHit>& hits) {
  std::set<std::uint32_t> p;
  for (const auto& h : hits) p.insert(h.patch);
  return p;
}

// The patch of the cube [0,1]^3 on the face where coordinate `axis` equals `side`.
std::uint32_t face_patch(const PolygonDomain& d, int axis, double side) {
  Vec3 p = Vec3::Constant(0.5);
  p[axis] = side;
  return d.closest_point(p)->patch;
}

}  // namespace

TEST_CASE("segments through cube face vertices and edges: one hit per patch") {
  const PolygonDomain d(io::make_cube(4));
  REQUIRE(d.patch_count() == 6);
  const std::uint32_t bottom = face_patch(d, 2, 0), top = face_patch(d, 2, 1);
  REQUIRE(bottom != top);
  // Vertical segments at x, y multiples of 1/8 inside the cube: through grid vertices (which
  // have up to 6 triangles), grid edges (2 triangles) and triangle interiors.
  for (int i = 1; i < 8; ++i)
    for (int j = 1; j < 8; ++j) {
      const double x = i / 8.0, y = j / 8.0;
      const auto hits = hits_of(d, Vec3(x, y, -1), Vec3(x, y, 2));
      REQUIRE(hits.size() == 2);
      CHECK(hits[0].patch == bottom);
      CHECK(hits[1].patch == top);
      CHECK(hits[0].point == Vec3(x, y, 0));
      CHECK(hits[1].point == Vec3(x, y, 1));
      CHECK(hits[0].t == doctest::Approx(1.0 / 3));
      CHECK_FALSE(hits[0].coplanar);
    }
}

TEST_CASE("through a feature curve and through a corner: once for each patch there") {
  const PolygonDomain d(io::make_cube(4));
  // Across the edge y = z = 0 at x = 0.5 (a grid vertex of both faces), through the solid and
  // out across the edge y = z = 1.
  auto hits = hits_of(d, Vec3(0.5, -1, -1), Vec3(0.5, 2, 2));
  REQUIRE(hits.size() == 4);
  CHECK(patches_of({hits.begin(), hits.begin() + 2}) == std::set{face_patch(d, 1, 0), face_patch(d, 2, 0)});
  CHECK(patches_of({hits.begin() + 2, hits.end()}) == std::set{face_patch(d, 1, 1), face_patch(d, 2, 1)});
  CHECK(hits[0].point == Vec3(0.5, 0, 0));
  // Along the main diagonal through two corners: three patches at each.
  hits = hits_of(d, Vec3(-1, -1, -1), Vec3(2, 2, 2));
  REQUIRE(hits.size() == 6);
  CHECK(patches_of({hits.begin(), hits.begin() + 3}).size() == 3);
  CHECK(patches_of({hits.begin() + 3, hits.end()}).size() == 3);
  for (int k = 0; k < 3; ++k) CHECK(hits[k].point == Vec3(0, 0, 0));
  // Through a point of an edge that is no grid vertex (x = 0.3): each face reports it once.
  hits = hits_of(d, Vec3(0.3, -1, -0.5), Vec3(0.3, 0.6, 0.3));
  REQUIRE(hits.size() == 2);
  CHECK(hits[0].patch != hits[1].patch);
  CHECK(hits[0].t == doctest::Approx(0.625));
}

TEST_CASE("a segment lying in a face: the overlap's two ends, flagged coplanar") {
  const PolygonDomain d(io::make_cube(4));
  const auto hits = hits_of(d, Vec3(-1, 0.3, 0), Vec3(2, 0.3, 0));
  const std::uint32_t bottom = face_patch(d, 2, 0);
  std::vector<SurfaceHit> in_plane;
  for (const auto& h : hits)
    if (h.patch == bottom) in_plane.push_back(h);
  REQUIRE(in_plane.size() == 2);
  CHECK(in_plane[0].coplanar);
  CHECK(in_plane[1].coplanar);
  CHECK(in_plane[0].t == doctest::Approx(1.0 / 3));
  CHECK(in_plane[1].t == doctest::Approx(2.0 / 3));
  CHECK((in_plane[1].point - Vec3(1, 0.3, 0)).norm() < 1e-15);
  // The side faces x = 0 and x = 1 are crossed at their bottom edges.
  CHECK(hits.size() == 4);
  CHECK(patches_of(hits) == std::set{bottom, face_patch(d, 0, 0), face_patch(d, 0, 1)});
}

TEST_CASE("the fin's attachment: the bottom patch on both sides is still one crossing") {
  const PolygonDomain d(io::make_box_with_fin(4));
  // Through (1, 0, 0.5), on the attachment curve, into the box.
  const auto hits = hits_of(d, Vec3(0.5, -0.5, 0.5), Vec3(1.5, 0.5, 0.5));
  REQUIRE(hits.size() == 2);
  CHECK(hits[0].patch != hits[1].patch);
  CHECK(hits[0].point == Vec3(1, 0, 0.5));
  CHECK(hits[1].point == Vec3(1, 0, 0.5));
}

TEST_CASE("rays: from inside a closed surface, one hit") {
  const PolygonDomain cube(io::make_cube(4));
  std::vector<SurfaceHit> out;
  cube.intersect_ray(Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 1), out);  // onto a face's grid vertex
  REQUIRE(out.size() == 1);
  CHECK(out[0].point == Vec3(0.5, 0.5, 1));
  CHECK(out[0].t == doctest::Approx(0.5));
  cube.intersect_ray(Vec3(0.5, 0.5, 0.5), Vec3(1, 1, 1), out);  // onto a corner
  CHECK(out.size() == 3);
  const PolygonDomain sphere(io::make_sphere(6));
  std::mt19937_64 rng(11);
  std::normal_distribution<double> g;
  for (int q = 0; q < 200; ++q) {
    sphere.intersect_ray(Vec3(0.1, -0.2, 0.05), Vec3(g(rng), g(rng), g(rng)), out);
    CHECK(out.size() == 1);
  }
}

TEST_CASE("generic segments: as many hits as triangles met, parity of the crossings") {
  const PolygonDomain d(io::make_torus(1, 0.4, 24, 12));
  const auto& c = d.complex();
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  std::size_t total = 0;
  for (int q = 0; q < 300; ++q) {
    const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    const auto hits = hits_of(d, a, b);
    std::size_t brute = 0;
    for (const auto& t : c.triangles)
      if (kernel::intersect_segment_triangle(a, b, c.vertices[t[0]], c.vertices[t[1]], c.vertices[t[2]])) ++brute;
    CHECK(hits.size() == brute);  // random segments meet no mesh edge or vertex
    CHECK(std::is_sorted(hits.begin(), hits.end(), [](const SurfaceHit& x, const SurfaceHit& y) { return x.t < y.t; }));
    total += hits.size();
  }
  CHECK(total > 100);
  // Segments from far outside ending exactly at a mesh vertex: the vertex, shared by six
  // triangles, is one hit.
  for (std::uint32_t v = 0; v < c.vertices.size(); v += 7) {
    const Vec3 target = c.vertices[v];
    const auto hits = hits_of(d, Vec3(5, 4, 3), target);
    REQUIRE_FALSE(hits.empty());
    CHECK(hits.back().point == target);
    CHECK(hits.back().t == 1);
    CHECK(std::count_if(hits.begin(), hits.end(), [&](const SurfaceHit& h) { return h.t == 1; }) == 1);
  }
}

TEST_CASE("curve, corner and patch queries agree with the complex") {
  const PolygonDomain d(io::make_capped_cylinder(1, 2, 32, 4, 2));
  CHECK(d.corner_count() == 2);
  CHECK(d.curve_count() == 2);
  CHECK(d.patch_count() == 3);
  const auto box = d.bounding_box();
  CHECK(box.lo.z() == 0);
  CHECK(box.hi.z() == 2);
  CHECK(box.hi.x() == 1);
  for (std::uint32_t k = 0; k < d.curve_count(); ++k) {
    CHECK(d.curve_closed(k));
    CHECK(d.curve_start_corner(k) == d.curve_end_corner(k));
    CHECK(d.curve_point(k, 0) == d.corner_point(d.curve_start_corner(k)));
    CHECK(d.curve_patches(k).size() == 2);
    const auto seg = d.curve_segment_in_ball(k, 1.0, 0.5);
    const auto want = d.complex().segment_in_ball(k, 1.0, 0.5);
    CHECK(seg.s0 == want.s0);
    CHECK(seg.s1 == want.s1);
    CHECK(d.curve_distance(k, 0.5, 0.25) == doctest::Approx(d.curve_length(k) - 0.25));
  }
  for (std::uint32_t p = 0; p < d.patch_count(); ++p) {
    const Vec3 x = d.patch_interior_point(p);
    const auto closest = d.closest_point(x);
    REQUIRE(closest);
    CHECK(closest->patch == p);
    CHECK(closest->squared_distance < 1e-24);
  }
  const PolygonDomain torus(io::make_torus());
  CHECK(torus.patch_curves(0).empty());
}
