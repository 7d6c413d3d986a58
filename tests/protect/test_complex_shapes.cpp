// The complex of every generated model (io/shapes.h): counts of corners, curves, closed curves,
// patches and boundary-free patches, each patch's Euler characteristic and boundary loops, and
// the incidences checked against the mesh (support/complex_checks.h). The expected numbers are
// the topology of the shapes, derived by hand in io/shapes.h, not read off the program.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include <delpsc/io/shapes.h>
#include <delpsc/protect/complex.h>
#include <delpsc/protect/complex_mesh.h>

#include "support/complex_checks.h"
#include "support/problem_lines.h"

using namespace delpsc;
using protect::build_complex;
using protect::Complex;
using protect::ComplexOptions;
using Topologies = std::vector<std::pair<int, int>>;

namespace {

struct Counts {
  std::size_t corners, curves, closed, patches, without_boundary;
};

void check_counts(const Complex& c, const Counts& want) {
  CHECK(c.corner_count() == want.corners);
  CHECK(c.curve_count() == want.curves);
  CHECK(c.closed_curve_count() == want.closed);
  CHECK(c.patch_count() == want.patches);
  CHECK(c.patches_without_boundary() == want.without_boundary);
  const auto problems = test::complex_problems(c);
  CHECK_MESSAGE(problems.empty(), test::problem_lines(problems));
  CHECK(c.cleanup.zero_area_triangles.empty());
}

Topologies disks(int n) { return Topologies(n, {1, 1}); }

ComplexOptions without_turn_corners() {
  ComplexOptions o;
  o.corner_angle_degrees = 180;
  return o;
}

}  // namespace

TEST_CASE("cube: 8 corners of degree 3, 12 curves, 6 disks") {
  for (int n : {1, 4}) {
    const Complex c = build_complex(io::make_cube(n));
    check_counts(c, {8, 12, 0, 6, 0});
    CHECK(test::patch_topologies(c) == disks(6));
    for (std::uint32_t k = 0; k < c.corner_count(); ++k) {
      CHECK(c.corner_curve_ids(k).size() == 3);
      CHECK(c.corner_patch_ids(k).size() == 3);
      CHECK(c.corner_flags[k] == protect::kCornerDegree);
    }
    for (std::uint32_t k = 0; k < c.curve_count(); ++k) {
      CHECK(c.curves[k].length == doctest::Approx(1.0));
      CHECK(c.curve_patch_ids(k).size() == 2);
    }
    for (std::uint32_t p = 0; p < c.patch_count(); ++p) {
      CHECK(c.patch_curve_ids(p).size() == 4);
      CHECK(c.patch_corner_ids(p).size() == 4);
    }
  }
}

TEST_CASE("capped cylinder: 2 closed curves, an annulus and two disks") {
  const Complex c = build_complex(io::make_capped_cylinder(1, 2, 24, 6, 3));
  check_counts(c, {2, 2, 2, 3, 0});
  CHECK(test::patch_topologies(c) == Topologies{{0, 2}, {1, 1}, {1, 1}});
  for (std::uint32_t k = 0; k < c.corner_count(); ++k) CHECK(c.corner_flags[k] == protect::kCornerLoop);
  // A regular 24-gon inscribed in the unit circle.
  for (const auto& curve : c.curves) CHECK(curve.length == doctest::Approx(48 * std::sin(std::numbers::pi / 24)));
}

TEST_CASE("a cone's tip is a corner below a half-angle of 30 degrees (kCornerApex)") {
  for (const double half : {10.0, 20.0, 40.0}) {
    CAPTURE(half);
    const Complex c = build_complex(io::make_cone(half, 24, 4));
    const bool tip = half < 30;  // the angles at the tip sum to 360 sin(half)
    check_counts(c, {tip ? 2u : 1u, 1, 1, 2, 0});  // the base circle: one closed curve
    std::size_t apex = 0;
    for (std::uint32_t k = 0; k < c.corner_count(); ++k)
      if (c.corner_flags[k] == protect::kCornerApex) {
        ++apex;
        CHECK(c.vertices[c.corner_vertex[k]].norm() == 0);  // at the tip
        CHECK(c.corner_curve_ids(k).empty());
        CHECK(c.corner_patch_ids(k).size() == 1);
      }
    CHECK(apex == (tip ? 1u : 0u));
  }
  // A smooth closed surface's vertices sum to nearly 360 degrees: none.
  CHECK(build_complex(io::make_sphere(8)).corner_count() == 0);
}

TEST_CASE("book of three sheets: one non-manifold spine") {
  const Complex c = build_complex(io::make_book(3, 4));
  check_counts(c, {8, 10, 0, 3, 0});
  CHECK(test::patch_topologies(c) == disks(3));
  CHECK(test::non_manifold_curves(c) == 1);
  // Without turning corners only the spine's ends remain: the spine and one free boundary per
  // sheet running from the top of the spine round to its bottom.
  const Complex plain = build_complex(io::make_book(3, 4), without_turn_corners());
  check_counts(plain, {2, 4, 0, 3, 0});
  CHECK(test::non_manifold_curves(plain) == 1);
}

TEST_CASE("open sheets: one patch bounded by one loop") {
  const Complex square = build_complex(io::make_square_sheet(5));
  check_counts(square, {4, 4, 0, 1, 0});  // its corners turn by 90°
  CHECK(test::patch_topologies(square) == disks(1));
  const Complex loop = build_complex(io::make_square_sheet(5), without_turn_corners());
  check_counts(loop, {1, 1, 1, 1, 0});
  CHECK(loop.curves[0].length == doctest::Approx(4.0));
  CHECK(loop.corner_vertex[0] == *std::min_element(loop.curve_vertices.begin(), loop.curve_vertices.end()));
  const Complex disc = build_complex(io::make_disc_sheet(32, 3));
  check_counts(disc, {1, 1, 1, 1, 0});
  CHECK(test::patch_topologies(disc) == disks(1));
}

TEST_CASE("torus and sphere: one patch, no curve, no boundary") {
  const Complex torus = build_complex(io::make_torus(1, 0.3, 24, 12));
  check_counts(torus, {0, 0, 0, 1, 1});
  CHECK(test::patch_topologies(torus) == Topologies{{0, 0}});
  const Complex sphere = build_complex(io::make_sphere(4));
  check_counts(sphere, {0, 0, 0, 1, 1});
  CHECK(test::patch_topologies(sphere) == Topologies{{2, 0}});
}

TEST_CASE("box with an internal fin: the bottom patch is slit") {
  for (const auto& options : {ComplexOptions{}, without_turn_corners()}) {
    const Complex c = build_complex(io::make_box_with_fin(4), options);
    // The fin's attachment ends stay corners without the turning rule: the patches along the
    // attachment (bottom twice, fin) differ from those along the fin's free edge (fin).
    const std::size_t corners = options.corner_angle_degrees < 180 ? 12 : 10;
    const std::size_t curves = options.corner_angle_degrees < 180 ? 16 : 14;
    check_counts(c, {corners, curves, 0, 7, 0});
    CHECK(test::patch_topologies(c) == Topologies{{0, 2}, {1, 1}, {1, 1}, {1, 1}, {1, 1}, {1, 1}, {1, 1}});
    CHECK(test::non_manifold_curves(c) == 1);
    // The attachment curve lists its patches as {bottom, bottom, fin}; the bottom patch lists it twice.
    for (std::uint32_t k = 0; k < c.curve_count(); ++k) {
      const auto patches = c.curve_patch_ids(k);
      if (patches.size() != 3) continue;
      CHECK(patches[0] == patches[1]);
      const auto bottom = c.patch_curve_ids(patches[0]);
      CHECK(std::count(bottom.begin(), bottom.end(), k) == 2);
      CHECK(c.curves[k].length == doctest::Approx(0.5));
    }
  }
}

TEST_CASE("wedge with a 10 degree dihedral angle") {
  const Complex c = build_complex(io::make_wedge(10, 0.1));
  check_counts(c, {6, 9, 0, 5, 0});
  CHECK(test::patch_topologies(c) == disks(5));
  // Half the total curve length: the apex edge, two legs' vertical edges, two triangular caps.
  double total = 0;
  for (const auto& curve : c.curves) total += curve.length;
  CHECK(total == doctest::Approx(3 * 0.5 + 2 * (2 + 2 * std::sin(5 * std::numbers::pi / 180))));
}

TEST_CASE("crossed ridges: two cubes whose ridges pass within 1% of the diagonal") {
  const Complex c = build_complex(io::make_crossed_ridges(0.01, 3));
  check_counts(c, {16, 24, 0, 12, 0});
  CHECK(test::patch_topologies(c) == disks(12));
  // The closest points of curves of the two cubes are the crossing ridges' middles.
  double closest = 1e9;
  const auto half = c.vertices.size() / 2;  // second cube's vertices come after the first's
  for (std::uint32_t a = 0; a < c.curve_count(); ++a)
    for (std::uint32_t b = 0; b < c.curve_count(); ++b) {
      if (c.curve_polyline(a)[0] >= half || c.curve_polyline(b)[0] < half) continue;
      for (double s = 0; s <= c.curves[a].length; s += c.curves[a].length / 60)
        closest = std::min(closest, (c.point_at(b, c.closest_parameter(b, c.point_at(a, s))) - c.point_at(a, s)).norm());
    }
  CHECK(closest == doctest::Approx(0.01 * std::sqrt(3.0)).epsilon(1e-6));
}

TEST_CASE("a very short curve survives as its own curve") {
  const double cut = 1e-3;
  const Complex c = build_complex(io::make_short_curve_prism(cut, 0.1));
  check_counts(c, {8, 12, 0, 6, 0});
  CHECK(test::patch_topologies(c) == disks(6));
  double shortest = 1e9;
  for (const auto& curve : c.curves) shortest = std::min(shortest, curve.length);
  CHECK(shortest == doctest::Approx(2 * cut * std::tan(15 * std::numbers::pi / 180)));
}

TEST_CASE("the feature angle decides which edges are features") {
  // A cylinder with 8 sides: neighbouring side faces make 45° between normals.
  const auto soup = io::make_capped_cylinder(1, 1, 8, 2, 2);
  check_counts(build_complex(soup), {2, 2, 2, 3, 0});
  ComplexOptions sharp;
  sharp.feature_angle_degrees = 40;
  // Now the 8 vertical edges are features too: 16 rim corners of degree 3, 8 + 16 curves,
  // 8 side faces + 2 caps.
  const Complex c = build_complex(soup, sharp);
  check_counts(c, {16, 24, 0, 10, 0});
  CHECK(test::patch_topologies(c) == disks(10));
  ComplexOptions nothing;
  nothing.feature_angle_degrees = 180;
  check_counts(build_complex(soup, nothing), {0, 0, 0, 1, 1});
}

TEST_CASE("generators refuse parameters that would not give the documented model") {
  CHECK_THROWS_AS(io::make_cube(0), std::invalid_argument);
  CHECK_THROWS_AS(io::make_capped_cylinder(1, 1, 6), std::invalid_argument);
  CHECK_THROWS_AS(io::make_torus(1, 2), std::invalid_argument);
  CHECK_THROWS_AS(io::make_wedge(70), std::invalid_argument);
}

TEST_CASE("the complex as a labelled surface mesh") {
  const Complex c = build_complex(io::make_box_with_fin(4));
  const io::SurfaceMesh m = protect::to_surface_mesh(c);
  CHECK(m.triangles.size() == c.triangles.size());
  CHECK(m.triangle_patch.size() == m.triangles.size());
  CHECK(m.corners.size() == c.corner_count());
  std::size_t feature_edges = 0;
  for (auto f : c.edge_feature) feature_edges += f != 0 ? 1 : 0;
  CHECK(m.edges.size() == feature_edges);
  std::set<std::int32_t> curves(m.edge_curve.begin(), m.edge_curve.end());
  CHECK(curves.size() == c.curve_count());
  std::set<std::int32_t> patches(m.triangle_patch.begin(), m.triangle_patch.end());
  CHECK(patches.size() == c.patch_count());
}
