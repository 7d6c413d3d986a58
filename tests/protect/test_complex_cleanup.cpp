// Zero-area triangles, welding, bad orientation, user polylines, sheets meeting at a vertex and
// bad input: the complex must keep the topology of the surface the soup describes.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>

#include <delpsc/io/shapes.h>
#include <delpsc/kernel/predicates.h>
#include <delpsc/protect/complex.h>

#include "support/complex_checks.h"
#include "support/problem_lines.h"

using namespace delpsc;
using protect::build_complex;
using protect::Complex;
using protect::ComplexOptions;
using Topologies = std::vector<std::pair<int, int>>;

namespace {

struct Shared {
  std::uint32_t t1, t2, a, b;  // t1 runs a -> b, t2 runs b -> a
};

bool runs(const std::array<std::uint32_t, 3>& t, std::uint32_t u, std::uint32_t v) {
  for (int k = 0; k < 3; ++k)
    if (t[k] == u && t[(k + 1) % 3] == v) return true;
  return false;
}

// The first pair of triangles sharing an edge for which `accept(a, b)` holds.
template <class Accept>
std::optional<Shared> find_shared_edge(const io::TriangleSoup& s, Accept accept) {
  for (std::uint32_t t1 = 0; t1 < s.triangles.size(); ++t1)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = s.triangles[t1][k], b = s.triangles[t1][(k + 1) % 3];
      if (!accept(s.vertices[a], s.vertices[b])) continue;
      for (std::uint32_t t2 = 0; t2 < s.triangles.size(); ++t2)
        if (t2 != t1 && runs(s.triangles[t2], b, a)) return Shared{t1, t2, a, b};
    }
  return std::nullopt;
}

// Puts a zero-area cap between t1 and t2 along their edge a-b: t2 is split at the edge's
// midpoint c into two triangles, and the cap (b, a, c) fills the gap, a T-junction as mesh
// repair tools and STL exporters leave them. Returns the cap's index. With an `offset`, c is
// moved off the edge by it: a cap of non-zero area.
std::uint32_t insert_cap(io::TriangleSoup& s, const Shared& e, const Vec3& offset = Vec3::Zero()) {
  const auto c = static_cast<std::uint32_t>(s.vertices.size());
  s.vertices.push_back((s.vertices[e.a] + s.vertices[e.b]) / 2 + offset);  // exact on the dyadic grids used
  auto& t2 = s.triangles[e.t2];
  std::uint32_t y = 0;
  for (auto v : t2)
    if (v != e.a && v != e.b) y = v;
  t2 = {e.b, c, y};
  s.triangles.push_back({c, e.a, y});
  s.triangles.push_back({e.b, e.a, c});
  return static_cast<std::uint32_t>(s.triangles.size() - 1);
}

// Splits t2 (which runs b -> a) at the given points of the edge a-b, listed from a towards b,
// with no cap: a T-junction of each point against t1's edge a-b. Returns their indices.
std::vector<std::uint32_t> split_without_cap(io::TriangleSoup& s, const Shared& e, const std::vector<double>& at) {
  std::vector<std::uint32_t> points;
  for (const double f : at) {
    points.push_back(static_cast<std::uint32_t>(s.vertices.size()));
    s.vertices.push_back(s.vertices[e.a] + f * (s.vertices[e.b] - s.vertices[e.a]));  // exact: dyadic
  }
  std::uint32_t y = 0;
  for (auto v : s.triangles[e.t2])
    if (v != e.a && v != e.b) y = v;
  // From b back to a, as t2 runs.
  std::vector<std::uint32_t> path{e.b};
  for (auto it = points.rbegin(); it != points.rend(); ++it) path.push_back(*it);
  path.push_back(e.a);
  s.triangles[e.t2] = {path[0], path[1], y};
  for (std::size_t i = 1; i + 1 < path.size(); ++i) s.triangles.push_back({path[i], path[i + 1], y});
  return points;
}

void check_same_complex(const Complex& got, const Complex& want) {
  CHECK(got.corner_count() == want.corner_count());
  CHECK(got.curve_count() == want.curve_count());
  CHECK(got.closed_curve_count() == want.closed_curve_count());
  CHECK(got.patch_count() == want.patch_count());
  CHECK(test::patch_topologies(got) == test::patch_topologies(want));
  const auto problems = test::complex_problems(got);
  CHECK_MESSAGE(problems.empty(), test::problem_lines(problems));
}

}  // namespace

TEST_CASE("a zero-area cap inside a flat sheet is healed, not turned into a hole") {
  io::TriangleSoup s = io::make_square_sheet(4);
  const Complex before = build_complex(s);
  // An interior grid edge (not on the boundary y = 0 or x = 0 lines).
  const auto e = find_shared_edge(s, [](const Vec3& a, const Vec3& b) { return a.y() == 0.5 && b.y() == 0.5; });
  REQUIRE(e);
  const std::uint32_t cap = insert_cap(s, *e);
  const Complex after = build_complex(s);
  check_same_complex(after, before);
  CHECK(after.cleanup.zero_area_triangles == std::vector<std::uint32_t>{cap});
  CHECK(after.cleanup.split_triangles == 1);
  CHECK(after.cleanup.dropped_caps == 0);
  CHECK(after.triangles.size() == s.triangles.size());  // one cap out, one split triangle in
}

TEST_CASE("a flat cap (height 1e-7 of its edge, out of the sheet) is healed like a zero-area one") {
  for (const double height : {1e-7, 1e-4}) {
    CAPTURE(height);
    io::TriangleSoup s = io::make_square_sheet(4);
    const Complex before = build_complex(s);
    const auto e = find_shared_edge(s, [](const Vec3& a, const Vec3& b) { return a.y() == 0.5 && b.y() == 0.5; });
    REQUIRE(e);
    const double length = (s.vertices[e->a] - s.vertices[e->b]).norm();
    // Standing up out of the plane, the cap's normal is nearly perpendicular to the sheet's: kept,
    // its three edges are sharp and make curves the sheet does not have.
    const std::uint32_t cap = insert_cap(s, *e, Vec3(0, 0, height * length));
    const Complex after = build_complex(s);
    CHECK(after.cleanup.zero_area_triangles.empty());
    if (height < 1e-5) {
      check_same_complex(after, before);
      CHECK(after.cleanup.flat_caps == std::vector<std::uint32_t>{cap});
      CHECK(after.cleanup.split_triangles == 1);
      CHECK(after.triangles.size() == s.triangles.size());
    } else {
      CHECK(after.cleanup.flat_caps.empty());
      CHECK(after.curve_count() > before.curve_count());
    }
  }
}

TEST_CASE("a zero-area cap, or a T-junction without one, along a cube edge keeps the edge one curve") {
  for (const bool with_cap : {true, false}) {
    CAPTURE(with_cap);
    io::TriangleSoup s = io::make_cube(2);
    const Complex before = build_complex(s);
    // An edge of the cube: both ends on the line y = 0, z = 0.
    const auto e = find_shared_edge(s, [](const Vec3& a, const Vec3& b) {
      return a.y() == 0 && a.z() == 0 && b.y() == 0 && b.z() == 0;
    });
    REQUIRE(e);
    if (with_cap)
      insert_cap(s, *e);
    else
      split_without_cap(s, *e, {0.5});
    const Complex after = build_complex(s);
    check_same_complex(after, before);
    CHECK(after.cleanup.split_triangles == 1);
    CHECK(after.cleanup.t_junctions == (with_cap ? 0 : 1));
    // The new midpoint (the last vertex either way) lies inside a cube edge's curve, not at a corner.
    const auto mid = static_cast<std::uint32_t>(s.vertices.size() - 1);
    CHECK(after.vertex_corner[mid] == protect::kNoIndex);
    int through = 0;
    for (std::uint32_t k = 0; k < after.curve_count(); ++k) through += after.parameter_of_vertex(k, mid) ? 1 : 0;
    CHECK(through == 1);
  }
}

TEST_CASE("caps on the boundary leave the boundary where it was") {
  const io::TriangleSoup sheet = io::make_square_sheet(4);
  const Complex before = build_complex(sheet);
  // A boundary edge a -> b of triangle t (on y = 0) and its midpoint c.
  std::uint32_t t = 0, a = 0, b = 0, x = 0;
  for (t = 0; t < sheet.triangles.size(); ++t) {
    bool found = false;
    for (int k = 0; k < 3 && !found; ++k) {
      a = sheet.triangles[t][k];
      b = sheet.triangles[t][(k + 1) % 3];
      x = sheet.triangles[t][(k + 2) % 3];
      found = sheet.vertices[a].y() == 0 && sheet.vertices[b].y() == 0;
    }
    if (found) break;
  }
  REQUIRE(t < sheet.triangles.size());
  const auto c = static_cast<std::uint32_t>(sheet.vertices.size());
  const Vec3 mid = (sheet.vertices[a] + sheet.vertices[b]) / 2;

  SUBCASE("cap outside, on the long edge: t is split at c, c joins the boundary") {
    io::TriangleSoup s = sheet;
    s.vertices.push_back(mid);
    s.triangles.push_back({b, a, c});
    const Complex after = build_complex(s);
    check_same_complex(after, before);
    CHECK(after.cleanup.zero_area_triangles.size() == 1);
    CHECK(after.cleanup.split_triangles == 1);
  }
  SUBCASE("cap outside, on the short edges: its long edge is free, it is simply removed") {
    io::TriangleSoup s = sheet;
    s.vertices.push_back(mid);
    s.triangles[t] = {a, c, x};
    s.triangles.push_back({c, b, x});
    s.triangles.push_back({c, a, b});
    const Complex after = build_complex(s);
    check_same_complex(after, before);
    CHECK(after.cleanup.zero_area_triangles.size() == 1);
    CHECK(after.cleanup.split_triangles == 0);
    CHECK(after.cleanup.dropped_caps == 0);
  }
}

TEST_CASE("T-junctions without a cap are healed: the complex of the mesh without them") {
  for (const std::vector<double>& at : {std::vector<double>{0.5}, std::vector<double>{0.25, 0.75}}) {
    CAPTURE(at.size());
    io::TriangleSoup s = io::make_square_sheet(4);
    const Complex before = build_complex(s);
    CHECK(before.cleanup.t_junctions == 0);  // a straight boundary's collinear vertices are none
    const auto e = find_shared_edge(s, [](const Vec3& a, const Vec3& b) { return a.y() == 0.5 && b.y() == 0.5; });
    REQUIRE(e);
    const std::size_t t1_source = e->t1;
    split_without_cap(s, *e, at);
    const Complex after = build_complex(s);
    check_same_complex(after, before);
    CHECK(after.cleanup.t_junctions == 1);
    CHECK(after.cleanup.split_triangles == at.size());
    CHECK(after.cleanup.zero_area_triangles.empty());
    CHECK(after.triangles.size() == s.triangles.size() + at.size());  // t1 became a fan of 1 + k
    CHECK(std::count(after.triangle_source.begin(), after.triangle_source.end(), t1_source) ==
          static_cast<long>(1 + at.size()));
    for (const auto& t : after.triangles) {  // the sheet's orientation (+z) kept by the fan
      const Vec3 n = (after.vertices[t[1]] - after.vertices[t[0]]).cross(after.vertices[t[2]] - after.vertices[t[0]]);
      CHECK(n.z() > 0);
    }
  }
}

void check_faces_up(const Complex& c) {  // the sheet's orientation (+z) kept by the fans
  for (const auto& t : c.triangles) {
    const Vec3 n = (c.vertices[t[1]] - c.vertices[t[0]]).cross(c.vertices[t[2]] - c.vertices[t[0]]);
    CHECK(n.z() > 0);
  }
}

TEST_CASE("a vertex off an edge by rounding is a T-junction; one farther off is none") {
  io::TriangleSoup s = io::make_square_sheet(4);
  const Complex before = build_complex(s);
  const auto e = find_shared_edge(s, [](const Vec3& a, const Vec3& b) { return a.y() == 0.5 && b.y() == 0.5; });
  REQUIRE(e);
  const std::uint32_t mid = split_without_cap(s, *e, {0.5}).front();
  SUBCASE("2^-40 off (into t1): healed, the surface moved by that much") {
    s.vertices[mid].y() += 0x1p-40;
    const Complex after = build_complex(s);
    check_same_complex(after, before);
    CHECK(after.cleanup.t_junctions == 1);
    CHECK(after.cleanup.near_t_junctions == 1);
    CHECK(after.cleanup.t_junction_gap == doctest::Approx(0x1p-40).epsilon(1e-6).scale(0));
    check_faces_up(after);
  }
  SUBCASE("1e-3 off, an angle of 0.9 degrees at the vertex: a crack left as it is") {
    s.vertices[mid].y() += 1e-3;
    const Complex after = build_complex(s);
    CHECK(after.cleanup.t_junctions == 0);
    CHECK(after.cleanup.t_junction_gap == 0);
    SUBCASE("unless the file had the model 1000 away, where six digits round off 1e-3") {
      protect::ComplexOptions options;
      options.file_offset = {1000, 0, 0};
      const Complex far = build_complex(s, options);
      check_same_complex(far, before);
      CHECK(far.cleanup.near_t_junctions == 1);
      CHECK(far.cleanup.t_junction_gap == doctest::Approx(1e-3).epsilon(1e-6).scale(0));
    }
  }
}

TEST_CASE("a crack split at different points on its two sides is zipped") {
  io::TriangleSoup s = io::make_square_sheet(4);
  const Complex before = build_complex(s);
  const auto e = find_shared_edge(s, [](const Vec3& a, const Vec3& b) { return a.y() == 0.5 && b.y() == 0.5; });
  REQUIRE(e);
  // t2 split at the middle, t1 at the quarters: each side's vertices lie on the other's edges.
  const std::uint32_t mid = split_without_cap(s, *e, {0.5}).front();
  const std::vector<std::uint32_t> quarters = split_without_cap(s, Shared{e->t2, e->t1, e->b, e->a}, {0.25, 0.75});
  SUBCASE("exactly on the line") {
    const Complex after = build_complex(s);
    check_same_complex(after, before);
    CHECK(after.cleanup.t_junctions == 3);  // the middle on t1's, each quarter on one of t2's
    CHECK(after.cleanup.near_t_junctions == 0);
    CHECK(after.cleanup.split_triangles == 3);
    check_faces_up(after);
  }
  SUBCASE("each off it by rounding, to either side") {
    s.vertices[mid].y() -= 0x1p-44;
    s.vertices[quarters[0]].y() += 0x1p-45;
    s.vertices[quarters[1]].y() -= 0x1p-43;
    const Complex after = build_complex(s);
    check_same_complex(after, before);
    CHECK(after.cleanup.t_junctions == 3);
    CHECK(after.cleanup.near_t_junctions == 3);
    // The farthest: the second quarter, 3/4 of 2^-43 off the line of t2's edge from the middle
    // (itself 2^-44 off) to the end.
    CHECK(after.cleanup.t_junction_gap == doctest::Approx(0x1p-43 - 0x1p-45).epsilon(1e-6).scale(0));
    check_faces_up(after);
  }
  SUBCASE("one vertex of the crack far off the line: nothing is zipped") {
    s.vertices[quarters[1]].y() += 1e-3;
    const Complex after = build_complex(s);
    CHECK(after.cleanup.t_junctions == 0);
    CHECK(after.cleanup.split_triangles == 0);
  }
}

TEST_CASE("triangles between two boundary paths leaving a vertex together are no crack") {
  // Flatness 8e-4 (below kCrackRadians, above the flat caps'): a's two boundary edges at p and
  // b run together, but the triangle itself fills the gap.
  const Vec3 p(0, 0, 0), a(0.5, 2e-4, 0), b(1, 0, 0), q(1.5, -1e-4, 0);
  SUBCASE("one nearly flat triangle") {
    io::TriangleSoup s;
    s.vertices = {p, a, b};
    s.triangles = {{0, 2, 1}};
    const Complex after = build_complex(s);
    CHECK(after.cleanup.t_junctions == 0);
    REQUIRE(after.triangles.size() == 1);
    CHECK(after.triangles[0] == std::array<std::uint32_t, 3>{0, 2, 1});
  }
  SUBCASE("a lens of two: each side's vertex opposite the other side's edge") {
    io::TriangleSoup s;
    s.vertices = {p, a, b, q};
    s.triangles = {{0, 2, 1}, {1, 2, 3}};
    const Complex after = build_complex(s);
    CHECK(after.cleanup.t_junctions == 0);
    CHECK(after.triangles.size() == 2);
  }
}

TEST_CASE("triangles with a repeated vertex, and repeated vertices, change nothing") {
  io::TriangleSoup s = io::make_cube(3);
  const Complex before = build_complex(s);
  s.triangles.push_back({0, 0, 5});
  s.triangles.push_back({7, 7, 7});
  // A second copy of vertex 0, used by one triangle in place of the original.
  s.vertices.push_back(s.vertices[0]);
  const auto copy = static_cast<std::uint32_t>(s.vertices.size() - 1);
  for (auto& tri : s.triangles) {
    const auto it = std::find(tri.begin(), tri.end(), 0u);
    if (it != tri.end() && tri[0] != tri[1]) {
      *it = copy;
      break;
    }
  }
  const Complex after = build_complex(s);
  check_same_complex(after, before);
  CHECK(after.cleanup.zero_area_triangles.size() == 2);
  CHECK(after.cleanup.welded_vertices == 1);
}

TEST_CASE("triangles listed more than once are counted, through welded vertices and either winding") {
  io::TriangleSoup s = io::make_cube(3);
  CHECK(build_complex(s).cleanup.duplicate_triangles == 0);
  CHECK(build_complex(s).cleanup.first_duplicate[0] == protect::kNoIndex);
  const auto n = static_cast<std::uint32_t>(s.triangles.size());
  const auto t5 = s.triangles[5], t9 = s.triangles[9];
  s.triangles.push_back({t5[2], t5[1], t5[0]});  // n: triangle 5 again, reversed
  s.triangles.push_back(t9);                     // n + 1, n + 2: triangle 9 twice more
  s.triangles.push_back({t9[1], t9[2], t9[0]});
  // n + 3: triangle 9 once more through a copy of one of its vertices (welded).
  s.vertices.push_back(s.vertices[t9[0]]);
  s.triangles.push_back({static_cast<std::uint32_t>(s.vertices.size() - 1), t9[1], t9[2]});
  const Complex c = build_complex(s);
  CHECK(c.cleanup.duplicate_triangles == 4);  // one repeat of 5, three of 9
  const auto [first, again] = c.cleanup.first_duplicate;
  CHECK(((first == 5 && again == n) || (first == 9 && again >= n + 1 && again <= n + 3)));
}

TEST_CASE("inconsistently oriented triangles make no false features") {
  io::TriangleSoup s = io::make_square_sheet(6);
  for (std::size_t t = 0; t < s.triangles.size(); t += 3) std::swap(s.triangles[t][0], s.triangles[t][1]);
  const Complex c = build_complex(s);
  CHECK(c.patch_count() == 1);
  CHECK(c.curve_count() == 4);
  CHECK(test::patch_topologies(c) == Topologies{{1, 1}});
}

TEST_CASE("a patch touching itself only at a vertex is a pinch") {
  // Around the sheet's centre vertex 12, two triangles that share no edge are dropped, with a
  // triangle left between them on either side: its triangles form two fans, still one patch.
  CHECK(build_complex(io::make_square_sheet(4)).pinches.empty());
  const io::TriangleSoup s = io::make_pinched_sheet(4);
  REQUIRE(s.triangles.size() == 30);
  const Complex pinched = build_complex(s);
  CHECK(pinched.patch_count() == 1);
  REQUIRE(pinched.pinches.size() == 1);
  CHECK(pinched.pinches[0] == std::array<std::uint32_t, 2>{12, 0});
  // Four hole sides leave the corner at 12; each fan is a wedge between two of them, which the
  // mesher follows fan by fan (none unsupported).
  CHECK(pinched.unsupported_pinches.empty());
  const std::uint32_t corner = pinched.vertex_corner[12];
  REQUIRE(corner != protect::kNoIndex);
  const auto fans = pinched.corner_pinch_fans(corner, 0);
  REQUIRE(fans.size() == 2);
  for (const auto& fan : fans) {
    CHECK(fan[0] != protect::kNoIndex);
    CHECK(fan[1] != protect::kNoIndex);
    CHECK(fan[0] != fan[1]);
    for (const std::uint32_t c : fan)  // curves of the holes' sides, leaving the pinch
      CHECK((pinched.curves[c].start_corner == corner || pinched.curves[c].end_corner == corner));
  }
  CHECK(pinched.corner_pinch_fans(corner, 1).empty());  // no such patch
  for (std::uint32_t k = 0; k < pinched.corner_count(); ++k)
    if (k != corner) CHECK(pinched.corner_pinch_fans(k, 0).empty());
}

TEST_CASE("a torus pinched to a point: two closed fans, a pinch the mesher refuses") {
  // Its ring at angle 0 welded into one vertex (the triangles it flattens are dropped): two cones
  // of the one patch meet at their tips there, with no curve. Such closed fans are unsupported.
  io::TriangleSoup s = io::make_torus(1, 0.3, 32, 16);
  for (auto& v : s.vertices)
    if (v.y() == 0 && v.x() > 0) v = Vec3(1, 0, 0);
  const Complex c = build_complex(s);
  CHECK(c.patch_count() == 1);
  REQUIRE(c.pinches.size() == 1);
  REQUIRE(c.unsupported_pinches.size() == 1);
  CHECK(c.unsupported_pinches[0] == c.pinches[0]);
  const std::uint32_t corner = c.vertex_corner[c.pinches[0][0]];
  REQUIRE(corner != protect::kNoIndex);  // two sheets meet there (kCornerSheets)
  CHECK(c.corner_pinch_fans(corner, 0).empty());
}

TEST_CASE("user polylines split patches or cut slits") {
  // make_square_sheet(4) numbers its grid vertices j * 5 + i.
  const io::TriangleSoup s = io::make_square_sheet(4);
  ComplexOptions across;
  across.feature_polylines = {{10, 11, 12, 13, 14}};  // y = 0.5, from x = 0 to x = 1
  const Complex split = build_complex(s, across);
  CHECK(split.corner_count() == 6);
  CHECK(split.curve_count() == 7);
  CHECK(split.patch_count() == 2);
  CHECK(test::patch_topologies(split) == Topologies{{1, 1}, {1, 1}});
  CHECK(test::complex_problems(split).empty());

  ComplexOptions slit;
  slit.feature_polylines = {{11, 12, 13}};  // inside the sheet: a slit
  const Complex cut = build_complex(s, slit);
  CHECK(cut.corner_count() == 6);
  CHECK(cut.curve_count() == 5);
  CHECK(cut.patch_count() == 1);
  CHECK(test::patch_topologies(cut) == Topologies{{0, 2}});  // a disc with a slit: an annulus
  CHECK(test::complex_problems(cut).empty());
  CHECK(cut.pinches.empty());  // both sides of a slit share its edges: one fan of the patch

  ComplexOptions loop;
  loop.feature_polylines = {{6, 7, 8, 13, 18, 17, 16, 11, 6}};  // a closed square inside
  const Complex ring = build_complex(s, loop);
  CHECK(ring.corner_count() == 8);  // the sheet's 4 and the inner square's 4 (90° turns)
  CHECK(ring.patch_count() == 2);
  CHECK(test::patch_topologies(ring) == Topologies{{0, 2}, {1, 1}});
  CHECK(test::complex_problems(ring).empty());

  ComplexOptions bad;
  bad.feature_polylines = {{0, 12}};
  CHECK_THROWS_AS(build_complex(s, bad), std::invalid_argument);
}

TEST_CASE("two spheres touching at one vertex meet at a corner") {
  io::TriangleSoup a = io::make_sphere(4);  // (1, 0, 0) is the centre of a cube face: a vertex
  io::TriangleSoup b = a;
  for (auto& p : b.vertices) p.x() += 2;  // (-1, 0, 0) moves onto (1, 0, 0)
  const auto offset = static_cast<std::uint32_t>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (auto t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const Complex c = build_complex(a);
  CHECK(c.cleanup.welded_vertices == 1);
  REQUIRE(c.corner_count() == 1);
  CHECK(c.corner_flags[0] == protect::kCornerSheets);
  CHECK(c.vertices[c.corner_vertex[0]] == Vec3(1, 0, 0));
  CHECK(c.curve_count() == 0);
  CHECK(c.patch_count() == 2);
  CHECK(c.corner_patch_ids(0).size() == 2);
  CHECK(test::patch_topologies(c) == Topologies{{2, 0}, {2, 0}});
}

TEST_CASE("bad input is refused with std::invalid_argument") {
  io::TriangleSoup s = io::make_cube(1);
  ComplexOptions o;
  o.feature_angle_degrees = 200;
  CHECK_THROWS_AS(build_complex(s, o), std::invalid_argument);
  s.triangles.push_back({0, 1, 99});
  CHECK_THROWS_AS(build_complex(s), std::invalid_argument);
  s = io::make_cube(1);
  s.vertices[3].x() = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(build_complex(s), std::invalid_argument);
  const Complex empty = build_complex(io::TriangleSoup{});
  CHECK(empty.patch_count() == 0);
  CHECK(empty.curve_count() == 0);
}

TEST_CASE("random soups with every kind of defect build a consistent complex") {
  // Few vertices on a small integer grid, many random triangles: repeated vertices, exactly
  // collinear triples (caps), duplicated and oppositely oriented triangles, edges with many
  // triangles, vertices where sheets touch.
  std::mt19937_64 rng(2024);
  for (int round = 0; round < 200; ++round) {
    io::TriangleSoup s;
    const int n = 4 + static_cast<int>(rng() % 12);
    for (int v = 0; v < n; ++v)
      s.vertices.emplace_back(static_cast<double>(rng() % 3), static_cast<double>(rng() % 3), static_cast<double>(rng() % 2));
    const int m = 1 + static_cast<int>(rng() % 30);
    for (int t = 0; t < m; ++t)
      s.triangles.push_back({static_cast<std::uint32_t>(rng() % n), static_cast<std::uint32_t>(rng() % n),
                             static_cast<std::uint32_t>(rng() % n)});
    protect::ComplexOptions o;
    o.corner_angle_degrees = static_cast<double>(rng() % 200);
    const Complex c = build_complex(s, o);
    const auto problems = test::complex_problems(c);
    CHECK_MESSAGE(problems.empty(), test::problem_lines(problems));
    CHECK(c.triangles.size() + c.cleanup.zero_area_triangles.size() == s.triangles.size() + c.cleanup.split_triangles);
    for (const auto& t : c.triangles)
      CHECK_FALSE(kernel::collinear(c.vertices[t[0]].data(), c.vertices[t[1]].data(), c.vertices[t[2]].data()));
  }
}
