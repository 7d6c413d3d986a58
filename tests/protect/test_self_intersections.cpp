// protect/self_intersections.h: which pairs of input triangles meet other than in a shared vertex
// or edge. Hand-made pairs for every case of the exact test (no, one, two, three shared
// vertices; crossing, touching, coplanar overlap, folds), symmetry under swapping and rotating
// the triangles, and whole models: the generated shapes (including the non-manifold book and
// fin, where sheets meet along a shared edge and must not be flagged), the sample part, the
// libcgal-demo models when present, and a model with one crossing pushed into it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <delpsc/io/read_model.h>
#include <delpsc/io/sample_part.h>
#include <delpsc/io/shapes.h>
#include <delpsc/kernel/aabb_tree.h>
#include <delpsc/kernel/constructions.h>
#include <delpsc/kernel/predicates.h>
#include <delpsc/protect/certified_fans.h>
#include <delpsc/protect/self_intersections.h>

#include "support/cgal_demo_data.h"

using namespace delpsc;
using protect::triangles_intersect_improperly;

namespace {

using Tri = std::array<Vec3, 3>;
using Ids = std::array<std::uint32_t, 3>;

// For an improper pair: improper_contact_point gives a point of both triangles (up to rounding)
// that is no shared vertex and, for two shared vertices, not on their edge.
void check_contact_point(const Tri& a, const Ids& ia, const Tri& b, const Ids& ib) {
  const std::optional<Vec3> p = protect::improper_contact_point(a, ia, b, ib);
  REQUIRE(p.has_value());
  const auto distance = [&](const Tri& t) { return (kernel::closest_point_on_triangle(*p, t[0], t[1], t[2]).point - *p).norm(); };
  CHECK(distance(a) <= 1e-12);
  CHECK(distance(b) <= 1e-12);
  std::vector<Vec3> shared;
  for (int i = 0; i < 3; ++i)
    if (std::find(ib.begin(), ib.end(), ia[i]) != ib.end()) shared.push_back(a[i]);
  if (shared.size() == 3) return;  // the same triangle twice: any point of it
  for (const Vec3& v : shared) CHECK((*p - v).norm() > 1e-9);
  if (shared.size() == 2) {
    const Vec3 d = shared[1] - shared[0];
    const double s = std::clamp((*p - shared[0]).dot(d) / d.squaredNorm(), 0.0, 1.0);
    CHECK((shared[0] + s * d - *p).norm() > 1e-9);
  }
}

// The answer for (a, b), checked to be the same for (b, a) and for every rotation of the
// corners of either triangle (the test must not depend on the order it is given things in);
// when they meet improperly, the contact point is checked for each order too.
bool improper(const Tri& a, const Ids& ia, const Tri& b, const Ids& ib) {
  const bool answer = triangles_intersect_improperly(a, ia, b, ib);
  for (int r = 0; r < 3; ++r) {
    const Tri ar{a[r], a[(r + 1) % 3], a[(r + 2) % 3]};
    const Ids iar{ia[r], ia[(r + 1) % 3], ia[(r + 2) % 3]};
    for (int s = 0; s < 3; ++s) {
      const Tri bs{b[s], b[(s + 1) % 3], b[(s + 2) % 3]};
      const Ids ibs{ib[s], ib[(s + 1) % 3], ib[(s + 2) % 3]};
      CHECK(triangles_intersect_improperly(ar, iar, bs, ibs) == answer);
      CHECK(triangles_intersect_improperly(bs, ibs, ar, iar) == answer);
      if (answer) {
        check_contact_point(ar, iar, bs, ibs);
        check_contact_point(bs, ibs, ar, iar);
      }
    }
  }
  return answer;
}

const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);

// The smallest (vertex, triangle) pair, vertex no corner of the triangle, at a distance in
// (0, tolerance): every used vertex against every triangle, in order.
std::optional<std::array<std::uint32_t, 2>> brute_near_contact(const protect::Complex& complex, double tolerance) {
  for (std::uint32_t v = 0; v < complex.vertices.size(); ++v)
    for (std::uint32_t t = 0; t < complex.triangles.size(); ++t) {
      const auto& tri = complex.triangles[t];
      if (tri[0] == v || tri[1] == v || tri[2] == v) continue;
      const Vec3& p = complex.vertices[v];
      const double d2 = (p - kernel::closest_point_on_triangle(p, complex.vertices[tri[0]], complex.vertices[tri[1]],
                                                               complex.vertices[tri[2]]).point).squaredNorm();
      const bool on = d2 == 0 && kernel::intersect_segment_triangle(p, p, complex.vertices[tri[0]], complex.vertices[tri[1]],
                                                                   complex.vertices[tri[2]]);
      if (d2 < tolerance * tolerance && !on) return std::array<std::uint32_t, 2>{v, t};
    }
  return std::nullopt;
}

// Every pair of triangles that meets improperly, tested one by one, in order.
std::vector<std::array<std::uint32_t, 2>> brute_crossings(const protect::Complex& complex) {
  const auto corners = [&](std::uint32_t k) {
    const auto& tri = complex.triangles[k];
    return Tri{complex.vertices[tri[0]], complex.vertices[tri[1]], complex.vertices[tri[2]]};
  };
  std::vector<std::array<std::uint32_t, 2>> pairs;
  for (std::uint32_t s = 0; s < complex.triangles.size(); ++s)
    for (std::uint32_t t = s + 1; t < complex.triangles.size(); ++t)
      if (triangles_intersect_improperly(corners(s), complex.triangles[s], corners(t), complex.triangles[t]))
        pairs.push_back({s, t});
  return pairs;
}

// A closed cylinder of radius 1 and height 1, n points on each rim (the lower rim's first is
// vertex 0, the upper's vertex n, above it), whose caps are fanned from those two points, as an
// STL exporter triangulates a polygon; the side's triangles first, or the caps'.
io::TriangleSoup rim_fanned_cylinder(int n, bool caps_first = false) {
  io::TriangleSoup soup;
  for (const double height : {0.0, 1.0})
    for (int i = 0; i < n; ++i)
      soup.vertices.push_back(Vec3(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n), height));
  const auto high = static_cast<std::uint32_t>(n);
  const auto side = [&] {
    for (std::uint32_t i = 0; i < high; ++i) {
      const std::uint32_t j = (i + 1) % high;
      soup.triangles.push_back({i, j, high + j});
      soup.triangles.push_back({i, high + j, high + i});
    }
  };
  if (!caps_first) side();
  for (std::uint32_t i = 1; i + 1 < high; ++i) {
    soup.triangles.push_back({0, i + 1, i});
    soup.triangles.push_back({high, high + i, high + i + 1});
  }
  if (caps_first) side();
  return soup;
}

std::size_t self_intersections(const io::TriangleSoup& soup) {
  return protect::find_self_intersections(protect::build_complex(soup)).size();
}

}  // namespace

TEST_CASE("no shared vertex") {
  const Tri a{o, x, y};
  // Crossing: b pierces a's interior.
  CHECK(improper(a, {0, 1, 2}, {Vec3(0.2, 0.2, -1), Vec3(0.3, 0.3, 1), Vec3(0.9, 0.1, 1)}, {3, 4, 5}));
  // Apart, above a.
  CHECK_FALSE(improper(a, {0, 1, 2}, {Vec3(0, 0, 0.1), Vec3(1, 0, 0.1), Vec3(0, 1, 0.2)}, {3, 4, 5}));
  // Touching: a vertex of b on a's interior, b otherwise above a.
  CHECK(improper(a, {0, 1, 2}, {Vec3(0.25, 0.25, 0), Vec3(1, 1, 1), Vec3(0, 1, 1)}, {3, 4, 5}));
  // Touching: a vertex of b on a's edge (a T-junction that was not welded).
  CHECK(improper(a, {0, 1, 2}, {Vec3(0.5, 0, 0), Vec3(0.5, -1, 0), Vec3(1, -1, 0)}, {3, 4, 5}));
  // Just apart from that edge (the exact test sees 2^-40).
  CHECK_FALSE(improper(a, {0, 1, 2}, {Vec3(0.5, -0x1p-40, 0), Vec3(0.5, -1, 0), Vec3(1, -1, 0)}, {3, 4, 5}));
  // Coplanar, b inside a: no edges cross; b's edges lie in a.
  CHECK(improper(a, {0, 1, 2}, {Vec3(0.1, 0.1, 0), Vec3(0.3, 0.1, 0), Vec3(0.1, 0.3, 0)}, {3, 4, 5}));
  // Coplanar and disjoint.
  CHECK_FALSE(improper(a, {0, 1, 2}, {Vec3(1, 1, 0), Vec3(2, 1, 0), Vec3(1, 2, 0)}, {3, 4, 5}));
}

TEST_CASE("one shared vertex") {
  const Tri a{o, x, y};
  // A fan neighbour across nothing: b hangs below a, meeting it only at o.
  CHECK_FALSE(improper(a, {0, 1, 2}, {o, Vec3(-1, 0, -1), Vec3(0, -1, -1)}, {0, 3, 4}));
  // b stands on o and cuts through a: its opposite edge pierces a's interior.
  CHECK(improper(a, {0, 1, 2}, {o, Vec3(0.3, 0.3, 1), Vec3(0.3, 0.3, -1)}, {0, 3, 4}));
  // b leans on a along a line from o: the segment from o to (0.2, 0.2, 0) lies in both, and b's
  // opposite edge crosses a's plane outside a - only a's opposite edge meets b.
  CHECK(improper(a, {0, 1, 2}, {o, Vec3(0.4, 0.4, 1), Vec3(0.4, 0.4, -1)}, {0, 3, 4}));
  CHECK(improper(a, {0, 1, 2}, {o, Vec3(5, 5, 1), Vec3(5, 5, -1)}, {0, 3, 4}));
  // Coplanar, sectors at o overlapping.
  CHECK(improper(a, {0, 1, 2}, {o, Vec3(1, 0.5, 0), Vec3(2, 3, 0)}, {0, 3, 4}));
  // Coplanar, sectors at o apart (b in the opposite quadrant).
  CHECK_FALSE(improper(a, {0, 1, 2}, {o, Vec3(-1, 0, 0), Vec3(0, -1, 0)}, {0, 3, 4}));
  // Coplanar, b's edge along a's edge o-x but longer: they share the segment o-x.
  CHECK(improper(a, {0, 1, 2}, {o, Vec3(2, 0, 0), Vec3(2, -1, 0)}, {0, 3, 4}));
  // Not coplanar, an edge of b along a's edge o-x, shorter: they share a segment from o.
  CHECK(improper(a, {0, 1, 2}, {o, Vec3(0.5, 0, 0), Vec3(0.5, 0, 1)}, {0, 3, 4}));
}

TEST_CASE("a shared edge") {
  const Tri a{o, x, y};
  CHECK_FALSE(improper(a, {0, 1, 2}, {x, o, Vec3(0, -1, 0)}, {1, 0, 3}));  // flat, either side
  CHECK_FALSE(improper(a, {0, 1, 2}, {x, o, z}, {1, 0, 3}));               // a dihedral angle
  CHECK_FALSE(improper(a, {0, 1, 2}, {x, o, Vec3(0.5, 1, 1e-30)}, {1, 0, 3}));  // nearly folded
  CHECK(improper(a, {0, 1, 2}, {x, o, Vec3(0.5, 1, 0)}, {1, 0, 3}));        // folded onto a
  CHECK(improper(a, {0, 1, 2}, {o, x, y}, {0, 1, 2}));                       // the same triangle
}

TEST_CASE("clean models have none, the non-manifold ones included") {
  CHECK(self_intersections(io::make_cube(4)) == 0);
  CHECK(self_intersections(io::make_torus()) == 0);
  CHECK(self_intersections(io::make_book(4)) == 0);
  CHECK(self_intersections(io::make_box_with_fin()) == 0);
  CHECK(self_intersections(io::make_wedge(1)) == 0);
  CHECK(self_intersections(io::make_crossed_ridges(0.001)) == 0);
  CHECK(self_intersections(io::make_sample_part()) == 0);
  for (const char* name : {"fandisk", "part", "anchor", "joint", "elephant"}) {
    CAPTURE(name);
    if (const auto soup = test::cgal_demo_soup(name)) CHECK(self_intersections(*soup) == 0);
  }
}

TEST_CASE("a cube with a sheet through it: every crossing pair found, and the cap respected") {
  io::TriangleSoup soup = io::make_cube(4);  // the unit cube, 4 x 4 squares a face
  // A square sheet at height 0.3 sticking out of the cube on every side: it crosses the four
  // side faces, each along a line through 4 squares (8 triangles), and the 2 sheet triangles
  // meet each of them.
  const auto base = static_cast<std::uint32_t>(soup.vertices.size());
  for (const Vec3& p : {Vec3(-1, -1, 0.3), Vec3(2, -1, 0.3), Vec3(2, 2, 0.3), Vec3(-1, 2, 0.3)}) soup.vertices.push_back(p);
  soup.triangles.push_back({base, base + 1, base + 2});
  soup.triangles.push_back({base, base + 2, base + 3});
  const protect::Complex complex = protect::build_complex(soup);
  const auto pairs = protect::find_self_intersections(complex, 1000);
  CHECK(pairs.size() >= 32);
  for (const auto& [s, t] : pairs) {
    CHECK(s < t);
    CHECK(t >= complex.triangles.size() - 2);  // every pair involves the sheet
  }
  // Sorted, and a cap keeps the smallest pairs: what a scan in (first, second) order would stop at.
  CHECK(std::is_sorted(pairs.begin(), pairs.end()));
  const auto capped = protect::find_self_intersections(complex, 5);
  REQUIRE(capped.size() == 5);
  CHECK(std::equal(capped.begin(), capped.end(), pairs.begin()));
}

TEST_CASE("crossing pairs first found: real crossings, as many as the smallest up to the cap") {
  io::TriangleSoup soup = io::make_cube(4);
  const auto base = static_cast<std::uint32_t>(soup.vertices.size());
  for (const Vec3& p : {Vec3(-1, -1, 0.3), Vec3(2, -1, 0.3), Vec3(2, 2, 0.3), Vec3(-1, 2, 0.3)}) soup.vertices.push_back(p);
  soup.triangles.push_back({base, base + 1, base + 2});
  soup.triangles.push_back({base, base + 2, base + 3});
  const protect::Complex complex = protect::build_complex(soup);
  const kernel::AabbTree tree(complex.vertices, complex.triangles);
  const auto all = protect::find_self_intersections(complex, 1000);
  REQUIRE(all.size() >= 32);
  for (const std::size_t cap : {std::size_t{1}, std::size_t{5}, all.size(), all.size() + 7}) {
    CAPTURE(cap);
    const protect::InputDefects any =
        protect::find_input_defects(complex, tree, cap, 0, {}, protect::CrossingPairs::first_found);
    CHECK_FALSE(any.stopped);
    CHECK(any.crossing.size() == std::min(cap, all.size()));
    CHECK(std::is_sorted(any.crossing.begin(), any.crossing.end()));
    for (const auto& pair : any.crossing) CHECK(std::binary_search(all.begin(), all.end(), pair));
  }
  // A triangle listed 20,000 times: 2*10^8 pairs of copies, every one crossing; the first found
  // end the search, long before a `stop` that answers true from its 257th question (~10^6
  // box-overlapping pairs; the smallest pairs would need them all).
  io::TriangleSoup repeated;
  repeated.vertices = {o, x, y, z};
  repeated.triangles = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  repeated.triangles.insert(repeated.triangles.end(), 20000, {0, 2, 1});
  const protect::Complex copies = protect::build_complex(repeated);
  std::size_t asked = 0;
  const protect::InputDefects first = protect::find_input_defects(
      copies, kernel::AabbTree(copies.vertices, copies.triangles), 100, 0, [&] { return ++asked > 256; },
      protect::CrossingPairs::first_found);
  CHECK_FALSE(first.stopped);
  CHECK(first.crossing.size() == 100);
  for (const auto& [s, t] : first.crossing) CHECK((s >= 3 && t >= 3));  // copies of the base
}

TEST_CASE("a vertex off a triangle's edge by less than a rounding is a near contact, not a touch") {
  // From a sheet whose triangle was split at a point computed as a + (b - a) / 4 on an edge of
  // non-dyadic ends (a T-junction an exporter's rounding broke): P lies 1.5e-17 off the line AB,
  // so its computed distance to the triangle (A, B, C) is 0 while the exact test finds no contact.
  // It was let through as touching and Protect then ran 10 s towards a million balls.
  const Vec3 A(0.16666666666666666, 1, 0), B(0, 0.8333333333333334, 0), P(0.125, 0.9583333333333334, 0);
  REQUIRE_FALSE(kernel::collinear(A.data(), B.data(), P.data()));
  // C on the side of AB away from P, the second triangle's other corners on P's side.
  const int side = kernel::orient2d(A.data(), B.data(), P.data(), 0, 1);
  REQUIRE(side != 0);
  const Vec3 away = side > 0 ? Vec3(0, 1, 0) : Vec3(0.5, 0.5, 0), toward = side > 0 ? Vec3(0.5, 0.5, 0) : Vec3(0, 1.2, 0);
  REQUIRE(kernel::orient2d(A.data(), B.data(), away.data(), 0, 1) == -side);
  REQUIRE(kernel::orient2d(A.data(), B.data(), toward.data(), 0, 1) == side);
  io::TriangleSoup soup;
  soup.vertices = {A, B, away, P, toward, toward + Vec3(0.01, 0.03, 0)};
  soup.triangles = {{0, 1, 2}, {3, 4, 5}};
  const protect::Complex complex = protect::build_complex(soup);
  CHECK((kernel::closest_point_on_triangle(P, A, B, away).point - P).squaredNorm() == 0);
  CHECK(protect::find_self_intersections(complex).empty());
  const auto near = protect::find_near_contact(complex, 1e-9);
  REQUIRE(near);
  CHECK((*near == std::array<std::uint32_t, 2>{3, 0}));
}

TEST_CASE("near contacts: the smallest (vertex, triangle) pair within the tolerance, as brute force finds it") {
  // Random small triangles in the unit cube (they also cross: find_input_defects reports both
  // kinds from one descent, each as its own function does). Brute force: every used vertex
  // against every triangle it is no corner of, in order, with the same closest-point distance.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1), small(-0.04, 0.04);
  io::TriangleSoup soup;
  for (int i = 0; i < 1000; ++i) {
    const Vec3 c(u(rng), u(rng), u(rng));
    const auto base = static_cast<std::uint32_t>(soup.vertices.size());
    for (int k = 0; k < 3; ++k) soup.vertices.push_back(c + Vec3(small(rng), small(rng), small(rng)));
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  const protect::Complex complex = protect::build_complex(soup);
  const kernel::AabbTree tree(complex.vertices, complex.triangles);
  for (const double tolerance : {2e-3, 1e-2, 3e-2}) {
    CAPTURE(tolerance);
    const auto want = brute_near_contact(complex, tolerance);
    REQUIRE(want);  // each tolerance finds some: the test means something
    CHECK(protect::find_near_contact(complex, tree, tolerance) == want);
    const protect::InputDefects both = protect::find_input_defects(complex, tree, 50, tolerance);
    CHECK(both.near_contact == want);
    CHECK(both.crossing == protect::find_self_intersections(complex, 50));
    CHECK(!both.crossing.empty());
  }
  CHECK_FALSE(protect::find_near_contact(complex, tree, 0));
  CHECK_FALSE(protect::find_near_contact(complex, tree, std::numeric_limits<double>::quiet_NaN()));
  // A clean closed surface has none at the commands' tolerance.
  const protect::Complex torus = protect::build_complex(io::make_torus(1, 0.3, 64, 32));
  CHECK_FALSE(protect::find_near_contact(torus, 1e-9 * 2.6));
}

// Fans around one vertex skip the pair test when their angular sectors, seen along an axis, are
// certified disjoint (a CAD cylinder's cap fanned from 20,000 rim points took 50 s, a cone's side
// 24 s): the pairs found must still be exactly the brute force's - for flat fans and for cones,
// pleated fans and saddles (certified), for fans that wind twice around their centre or have a
// sector folded back over others (crossings), and for stars no axis sees as one fan (two cones
// apex to apex, two half discs at right angles).
TEST_CASE("fans around a vertex: the same crossing pairs as testing every pair") {
  const auto fan = [](int n, const std::function<Vec3(int)>& rim, bool closed) {
    io::TriangleSoup soup;
    soup.vertices.push_back(Vec3::Zero());
    for (int i = 0; i < n; ++i) soup.vertices.push_back(rim(i));
    for (int i = 0; i < (closed ? n : n - 1); ++i)
      soup.triangles.push_back({0, static_cast<std::uint32_t>(1 + i), static_cast<std::uint32_t>(1 + (i + 1) % n)});
    return soup;
  };
  const auto circle = [](double turns, int n, double r0, double r1) {
    return [=](int i) -> Vec3 {
      const double a = 2 * M_PI * turns * i / n, r = i < n / 2 ? r0 : r1;
      return Vec3(r * std::cos(a), r * std::sin(a), 0);
    };
  };
  struct Case {
    const char* name;
    io::TriangleSoup soup;
    bool crossing;
  };
  std::vector<Case> cases;
  cases.push_back({"a disc fanned from its centre", fan(64, circle(1, 64, 1, 1), true), false});
  cases.push_back({"a convex polygon fanned from a corner", fan(40, circle(0.9, 40, 1, 1), false), false});
  cases.push_back({"a fan winding twice", fan(64, circle(2, 64, 1, 0.5), true), true});
  cases.push_back({"a fan with a sector folded back",
                   fan(40, [&](int i) -> Vec3 { return i == 20 ? Vec3(std::cos(0.3), std::sin(0.3), 0) : circle(0.9, 40, 1, 1)(i); },
                       false),
                   true});
  const auto lifted = [&](double turns, int n, const std::function<double(int)>& height) {
    return [=](int i) -> Vec3 { return circle(turns, n, 1, 1)(i) + Vec3(0, 0, height(i)); };
  };
  cases.push_back({"a cone (not flat)", fan(64, lifted(1, 64, [](int) { return -1.0; }), true), false});
  cases.push_back({"a steep cone", fan(64, lifted(1, 64, [](int) { return 40.0; }), true), false});
  cases.push_back({"a pleated fan", fan(64, lifted(1, 64, [](int i) { return i % 2 ? 0.7 : -0.7; }), true), false});
  cases.push_back({"a monkey saddle", fan(60, lifted(1, 60, [](int i) { return std::sin(6 * M_PI * i / 60); }), true), false});
  cases.push_back({"a cone winding twice", fan(64, [&](int i) -> Vec3 { return circle(2, 64, 1, 0.5)(i) + Vec3(0, 0, -1); }, true), true});
  cases.push_back({"a cone with a sector folded back",
                   fan(40, [&](int i) -> Vec3 {
                         return (i == 20 ? Vec3(std::cos(0.3), std::sin(0.3), 0) : circle(0.9, 40, 1, 1)(i)) + Vec3(0, 0, -1);
                       }, false),
                   true});
  {
    // Two cones sharing their apex, one up and one down: the apex's star covers every direction
    // twice, and the sheets meet only there.
    io::TriangleSoup soup = fan(32, lifted(1, 32, [](int) { return 1.0; }), true);
    const auto base = static_cast<std::uint32_t>(soup.vertices.size());
    for (int i = 0; i < 32; ++i) soup.vertices.push_back(lifted(1, 32, [](int) { return -1.0; })(i) * 0.8);
    for (std::uint32_t i = 0; i < 32; ++i) soup.triangles.push_back({0, base + i, base + (i + 1) % 32});
    cases.push_back({"two cones apex to apex", soup, false});
  }
  {
    // Two half discs fanned from one centre, at right angles along a shared diameter: from any
    // axis some triangle is seen edge on or two sectors overlap.
    io::TriangleSoup soup;
    soup.vertices.push_back(Vec3::Zero());
    for (int i = 0; i <= 16; ++i) soup.vertices.push_back(Vec3(std::cos(M_PI * i / 16), std::sin(M_PI * i / 16), 0));
    for (int i = 1; i < 16; ++i) soup.vertices.push_back(Vec3(std::cos(M_PI * i / 16), 0, std::sin(M_PI * i / 16)));
    for (std::uint32_t i = 1; i <= 16; ++i) soup.triangles.push_back({0, i, i + 1});
    const auto z = [](std::uint32_t i) { return i == 0 ? 1u : i == 16 ? 17u : 17 + i; };  // the second half's rim
    for (std::uint32_t i = 0; i < 16; ++i) soup.triangles.push_back({0, z(i + 1), z(i)});
    cases.push_back({"two half discs at right angles", soup, false});
  }
  for (const Case& c : cases) {
    CAPTURE(c.name);
    const protect::Complex complex = protect::build_complex(c.soup);
    const auto brute = brute_crossings(complex);
    CHECK(brute.empty() == !c.crossing);
    CHECK(protect::find_self_intersections(complex, 100000) == brute);
  }
}

// The certificate is what spares the pairs: on a cone's side of 3,000 triangles (4.5 million
// pairs, all boxes overlapping, a poll of `stop` every 4,096 of them), shallow or steep, and on
// a flat disc of as many, its triangles oriented alike or every other one turned over, the
// descent asks almost never; nor does the search across fans on a cone with its base fanned
// from the centre (9 million pairs across the two). Without the certificate for cones it asked
// ~1,100 times; with only the normals' sum turned to agree for an axis, the steep cone did; with
// only their sum as given, the square disc did (its normals, exact integers, sum to zero);
// without the search by angle, or with one that does not stop, the cone on its base did.
TEST_CASE("fans around a vertex: a certified fan's pairs are not visited") {
  const int n = 3000;
  const auto on_circle = [](int i) { return Vec3(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n), 0); };
  const auto on_square = [](int i) {  // 750 unit steps a side, anticlockwise from (-375, -375)
    const int side = i / 750, step = i % 750 - 375;
    const double along[4][2] = {{double(step), -375}, {375, double(step)}, {-double(step), 375}, {-375, -double(step)}};
    return Vec3(along[side][0], along[side][1], 0);
  };
  struct Case {
    const char* name;
    double height;
    std::function<Vec3(int)> rim;
    bool turned, base;  // base: closed by a disc fanned from the rim's centre
    bool base_from_rim = false;  // ... from the rim's first point instead (an STL export's)
  };
  for (const Case& c : {Case{"a flat disc", 0, on_circle, false, false}, Case{"a disc turned every other", 0, on_circle, true, false},
                        Case{"a square disc turned every other", 0, on_square, true, false},
                        Case{"a shallow cone", 1, on_circle, false, false}, Case{"a steep cone", -3, on_circle, false, false},
                        Case{"a cone on a base fanned from its centre", 1, on_circle, false, true},
                        Case{"a cone on a base fanned from a rim point", 1, on_circle, false, true, true},
                        Case{"a shallow cone on a base fanned from a rim point", 0.05, on_circle, false, true, true},
                        Case{"a cone under 1 degree on a base fanned from a rim point", 0.005, on_circle, false, true, true}}) {
    const std::string name = c.name;
    CAPTURE(name);
    io::TriangleSoup soup;
    soup.vertices.push_back(Vec3(0, 0, c.height));
    for (int i = 0; i < n; ++i) soup.vertices.push_back(c.rim(i));
    for (int i = 0; i < n; ++i) {
      const auto a = static_cast<std::uint32_t>(1 + i), b = static_cast<std::uint32_t>(1 + (i + 1) % n);
      soup.triangles.push_back(c.turned && i % 2 ? std::array<std::uint32_t, 3>{0, b, a} : std::array<std::uint32_t, 3>{0, a, b});
    }
    if (c.base && c.base_from_rim) {
      // The corner's star is no fan (its two side triangles cover the chords' angles); its
      // chords alone are (certified_fans.h), else their n²/2 coplanar pairs are all visited.
      for (int i = 1; i + 1 < n; ++i)
        soup.triangles.push_back({1, static_cast<std::uint32_t>(2 + i), static_cast<std::uint32_t>(1 + i)});
    } else if (c.base) {
      soup.vertices.push_back(Vec3::Zero());
      for (int i = 0; i < n; ++i)
        soup.triangles.push_back({static_cast<std::uint32_t>(n + 1), static_cast<std::uint32_t>(1 + (i + 1) % n),
                                  static_cast<std::uint32_t>(1 + i)});
    }
    const protect::Complex complex = protect::build_complex(soup);
    const kernel::AabbTree tree(complex.vertices, complex.triangles);
    int polls = 0;
    const protect::InputDefects found = protect::find_input_defects(complex, tree, 100, 1e-9, [&] { return ++polls < 0; });
    CHECK(found.crossing.empty());
    CHECK_FALSE(found.near_contact);
    CHECK_FALSE(found.stopped);
    CHECK(polls <= 8);
  }
}

// Pairs across two fans are left out of the descent too and searched by angle about one fan's
// axis: the crossing pairs and the near contact must still be brute force's - for a cone on a
// base fanned from its centre and a double cone (none), a base whose centre is pushed out
// through the cone's side, a cone whose side pierces a disc around the disc's own axis, a cone
// lying on its side across a disc, two discs 1e-4 apart (near contacts only), and fans touching
// a disc where only a full search finds every pair: through its centre in a plane of its axis,
// with an edge through its centre, lying on one of its edges (the sector before the one the
// shadow starts in).
TEST_CASE("fans around a vertex: pairs across two fans, as brute force finds them") {
  const auto ring = [](io::TriangleSoup& soup, int n, const Vec3& centre, double radius, double turn) {
    const auto first = static_cast<std::uint32_t>(soup.vertices.size());
    for (int i = 0; i < n; ++i) {
      const double a = 2 * M_PI * (i + turn) / n;
      soup.vertices.push_back(centre + radius * Vec3(std::cos(a), std::sin(a), 0));
    }
    return first;
  };
  // Triangles from vertex `apex` to the ring starting at `first`, closed, in the ring's order or
  // against it.
  const auto fan_to = [](io::TriangleSoup& soup, std::uint32_t apex, std::uint32_t first, int n, bool reverse) {
    for (int i = 0; i < n; ++i) {
      const std::uint32_t a = first + static_cast<std::uint32_t>(i), b = first + static_cast<std::uint32_t>((i + 1) % n);
      soup.triangles.push_back(reverse ? std::array<std::uint32_t, 3>{apex, b, a} : std::array<std::uint32_t, 3>{apex, a, b});
    }
  };
  const auto point = [](io::TriangleSoup& soup, const Vec3& p) {
    soup.vertices.push_back(p);
    return static_cast<std::uint32_t>(soup.vertices.size() - 1);
  };
  struct Case {
    const char* name;
    io::TriangleSoup soup;
    bool crossing;
  };
  std::vector<Case> cases;
  const int n = 40;
  for (const bool pushed : {false, true}) {
    io::TriangleSoup soup;
    const std::uint32_t rim = ring(soup, n, Vec3::Zero(), 1, 0);
    fan_to(soup, point(soup, Vec3(0, 0, 1)), rim, n, false);
    fan_to(soup, point(soup, pushed ? Vec3(0.9, 0, 0.5) : Vec3::Zero()), rim, n, true);
    cases.push_back({pushed ? "a base whose centre is pushed out through the side" : "a cone on a base fanned from its centre",
                     soup, pushed});
  }
  {
    io::TriangleSoup soup;
    const std::uint32_t rim = ring(soup, n, Vec3::Zero(), 1, 0);
    fan_to(soup, point(soup, Vec3(0, 0, 1)), rim, n, false);
    fan_to(soup, point(soup, Vec3(0, 0, -0.7)), rim, n, true);
    cases.push_back({"a double cone", soup, false});
  }
  {
    io::TriangleSoup soup;
    fan_to(soup, point(soup, Vec3::Zero()), ring(soup, n, Vec3::Zero(), 1, 0), n, false);
    fan_to(soup, point(soup, Vec3(0.3, 0, -1)), ring(soup, 24, Vec3(0.3, 0, 1), 0.5, 0.5), 24, false);
    cases.push_back({"a cone piercing a disc around its axis", soup, true});
  }
  {
    io::TriangleSoup soup;
    fan_to(soup, point(soup, Vec3::Zero()), ring(soup, n, Vec3::Zero(), 1, 0), n, false);
    // A cone along x: apex at (-0.8, 0, 0.2), rim a circle of radius 0.4 in the plane x = 0.6.
    const std::uint32_t apex = point(soup, Vec3(-0.8, 0, 0.2));
    const auto first = static_cast<std::uint32_t>(soup.vertices.size());
    for (int i = 0; i < 20; ++i)
      soup.vertices.push_back(Vec3(0.6, 0.4 * std::cos(2 * M_PI * i / 20), 0.2 + 0.4 * std::sin(2 * M_PI * i / 20)));
    fan_to(soup, apex, first, 20, false);
    cases.push_back({"a cone lying across a disc", soup, true});
  }
  {
    io::TriangleSoup soup;
    fan_to(soup, point(soup, Vec3::Zero()), ring(soup, n, Vec3::Zero(), 1, 0), n, false);
    fan_to(soup, point(soup, Vec3(0.01, 0, 1e-4)), ring(soup, n, Vec3(0, 0, 1e-4), 1, 0.37), n, false);
    cases.push_back({"two discs 1e-4 apart", soup, false});
  }
  // A flat fan B around `centre` whose rim runs from `from` to `to` (one edge of B) and back
  // through `via`, 17 more rim points: every triangle of B but the first lies beyond that edge.
  const auto polygon_fan = [&](io::TriangleSoup& soup, const Vec3& centre, const Vec3& from, const Vec3& to, const Vec3& via) {
    const std::uint32_t c = point(soup, centre), first = point(soup, from);
    point(soup, to);
    for (int i = 1; i <= 17; ++i) {  // along to -> via -> from, a quadratic Bezier arc
      const double t = i / 18.0;
      point(soup, (1 - t) * (1 - t) * to + 2 * t * (1 - t) * via + t * t * from);
    }
    fan_to(soup, c, first, 19, false);
  };
  {
    // A fan of the disc's axis plane, its edge from (-0.5, 0, -0.5) to (0.5, 0, -0.5) under the
    // disc's centre and its centre above it: it meets every disc triangle in the disc's centre
    // (inside it), crossing those along x; its triangles' planes hold the disc's axis.
    io::TriangleSoup soup;
    fan_to(soup, point(soup, Vec3::Zero()), ring(soup, n, Vec3::Zero(), 1, 0), n, false);
    polygon_fan(soup, Vec3(0, 0, 0.2), Vec3(-0.5, 0, -0.5), Vec3(0.5, 0, -0.5), Vec3(0, 0, 2.5));
    cases.push_back({"a fan in the disc's axis plane through its centre", soup, true});
  }
  {
    // A fan whose edge from (-1, 0, 0.5) to (1, 0, -0.5) passes through the disc's centre, its
    // shadow's edge through the axis: it meets every disc triangle there.
    io::TriangleSoup soup;
    fan_to(soup, point(soup, Vec3::Zero()), ring(soup, n, Vec3::Zero(), 1, 0), n, false);
    polygon_fan(soup, Vec3(0, 0.6, 0.3), Vec3(-1, 0, 0.5), Vec3(1, 0, -0.5), Vec3(0, 2.5, 1));
    cases.push_back({"a fan whose edge crosses the disc's centre", soup, true});
  }
  {
    // The same with the fan's centre (2, 0, 0) in the disc's plane, so that the disc's axis
    // cannot be turned through it: the edge's shadow crosses the disc's axis, its other corners
    // off it.
    io::TriangleSoup soup;
    fan_to(soup, point(soup, Vec3::Zero()), ring(soup, n, Vec3::Zero(), 1, 0), n, false);
    polygon_fan(soup, Vec3(2, 0, 0), Vec3(-1, 0.5, 0.5), Vec3(1, -0.5, -0.5), Vec3(5, 0, 0));
    cases.push_back({"a fan whose edge crosses the disc's centre, its own centre in the disc's plane", soup, true});
  }
  for (const double side : {0.2, -0.2}) {
    // A fan lying on the disc's edge from its centre to (1, 0, 0) along (0.2, 0, 0)-(0.8, 0, 0),
    // rising to one side: it overlaps the two disc triangles on either side of that edge.
    io::TriangleSoup soup;
    fan_to(soup, point(soup, Vec3::Zero()), ring(soup, n, Vec3::Zero(), 1, 0), n, false);
    polygon_fan(soup, Vec3(0.5, side, 0.3), Vec3(0.8, 0, 0), Vec3(0.2, 0, 0), Vec3(0.5, 4 * side, 1.5));
    cases.push_back({side > 0 ? "a fan on a disc edge, rising to one side" : "a fan on a disc edge, rising to the other",
                     soup, true});
  }
  // A flat disc fanned from a rim point (the first fan: its centre is vertex 0) against fans on
  // one side of its plane, touching it in their rim edge (a cone over it: none), in one vertex
  // (an apex inside a disc triangle, on a disc edge) or along an edge across many sectors.
  const auto corner_disc = [&](io::TriangleSoup& soup) {
    const std::uint32_t rim = ring(soup, n, Vec3::Zero(), 1, 0);
    for (int i = 1; i + 1 < n; ++i)
      soup.triangles.push_back({rim, rim + static_cast<std::uint32_t>(i) + 1, rim + static_cast<std::uint32_t>(i)});
    return rim;
  };
  {
    io::TriangleSoup soup;
    const std::uint32_t rim = corner_disc(soup);
    fan_to(soup, point(soup, Vec3(0, 0, 1)), rim, n, false);
    cases.push_back({"a cone on a disc fanned from a rim point", soup, false});
  }
  for (const Vec3& apex : {Vec3(0.3, 0.2, 0), Vec3(0.5, 0, 0), Vec3(-0.2, -0.1, 0)}) {
    io::TriangleSoup soup;
    corner_disc(soup);
    fan_to(soup, point(soup, apex), ring(soup, 24, Vec3(0, 0, 1), 0.5, 0.5), 24, false);
    cases.push_back({"a cone standing on its apex on a disc fanned from a rim point", soup, true});
  }
  {
    io::TriangleSoup soup;
    corner_disc(soup);
    polygon_fan(soup, Vec3(0, 0.1, 0.4), Vec3(-0.5, 0.3, 0), Vec3(0.6, -0.2, 0), Vec3(0.1, 0.1, 2));
    cases.push_back({"a fan standing on an edge across a disc fanned from a rim point", soup, true});
  }
  // A closed cylinder whose caps are fanned from rim points one above the other (an STL
  // export's): about the axis turned through the upper corner, the side triangles at the lower
  // one have no sector and are tested one by one (fan_about's left_out). Then the same with a
  // triangle at the lower corner rising through the upper cap (sharing only the upper corner
  // with the cap's triangles, which it crosses): left out of the turned fan, and a member of
  // neither certified part.
  for (const bool rising : {false, true}) {
    io::TriangleSoup soup = rim_fanned_cylinder(n);
    if (rising) soup.triangles.push_back({0, static_cast<std::uint32_t>(n), point(soup, Vec3(0.2, 0.1, 1.3))});
    cases.push_back({rising ? "caps fanned from rim points, a triangle at the lower corner rising through the upper cap"
                            : "a cylinder whose caps are fanned from rim points one above the other",
                     soup, rising});
  }
  {
    // A fin at the lower corner whose edge runs up through the upper corner and on: it meets
    // every triangle there. It is a member of the lower corner's fan and left out of it about
    // the axis turned through the upper corner.
    io::TriangleSoup soup = rim_fanned_cylinder(n);
    soup.triangles.push_back({0, point(soup, Vec3(1, 0, 2)), point(soup, Vec3(1.5, 0.2, 0.5))});
    cases.push_back({"caps fanned from rim points, a fin at the lower corner through the upper one", soup, true});
  }
  {
    // A cone whose apex is on the vertical through the lower corner, above the cylinder, and
    // whose side cuts the side triangles at that corner: about the axis turned through the apex
    // they are left out, and only testing them one by one finds those crossings.
    io::TriangleSoup soup = rim_fanned_cylinder(n);
    fan_to(soup, point(soup, Vec3(1, 0, 2)), ring(soup, 24, Vec3(1, 0.07, 0.5), 0.3, 0.5), 24, false);
    cases.push_back({"caps fanned from rim points, a cone from above the lower corner through its side", soup, true});
  }
  {
    // The caps' triangles first, so that they own the rims' vertices (each vertex's near contacts
    // are sought from its first triangle), and a small triangle of no fan outside the side, 5e-6
    // from a rim point: a near contact only the chord owning that point can report. (At 160 rim
    // points the chords' boxes hold enough of the side for the caps to be searched whole.)
    io::TriangleSoup soup = rim_fanned_cylinder(160, true);
    const Vec3 rim = soup.vertices[5], out = Vec3(rim.x(), rim.y(), 0).normalized(), along(-rim.y(), rim.x(), 0);
    const Vec3 at = rim + 5e-6 * out;
    soup.triangles.push_back({point(soup, at - 0.01 * along - 0.01 * z), point(soup, at + 0.01 * along - 0.01 * z),
                              point(soup, at + 0.01 * z)});
    cases.push_back({"caps fanned from rim points listed first, a triangle hovering beside a rim point", soup, false});
  }
  {
    // A cone standing on the upper cap, its rim through the upper corner: its two triangles at
    // that corner cross the cap's chords there, sharing only the corner with them, and are no
    // members of the corner's certified part (the chords) but of the apex's fan.
    io::TriangleSoup soup = rim_fanned_cylinder(n);
    const std::uint32_t apex = point(soup, Vec3(0.6, 0, 1.6));
    std::vector<std::uint32_t> rim{static_cast<std::uint32_t>(n)};  // the upper corner, (1, 0, 1)
    for (int k = 1; k < 24; ++k)
      rim.push_back(point(soup, Vec3(0.6 + 0.4 * std::cos(2 * M_PI * k / 24), 0.4 * std::sin(2 * M_PI * k / 24), 1)));
    for (std::size_t k = 0; k < rim.size(); ++k) soup.triangles.push_back({apex, rim[k], rim[(k + 1) % rim.size()]});
    cases.push_back({"caps fanned from rim points, a cone standing on the upper cap through its corner", soup, true});
  }
  {
    io::TriangleSoup soup;
    corner_disc(soup);
    fan_to(soup, point(soup, Vec3(0.2, 0.1, -0.5)), ring(soup, 24, Vec3(0, 0, 0.5), 0.5, 0.5), 24, false);
    cases.push_back({"a cone through a disc fanned from a rim point", soup, true});
  }
  for (const Case& c : cases) {
    const std::string name = c.name;
    CAPTURE(name);
    const protect::Complex complex = protect::build_complex(c.soup);
    const kernel::AabbTree tree(complex.vertices, complex.triangles);
    const auto brute = brute_crossings(complex);
    CHECK(brute.empty() == !c.crossing);
    for (const double tolerance : {0.0, 1e-5, 1e-3}) {
      CAPTURE(tolerance);
      const protect::InputDefects found = protect::find_input_defects(complex, tree, 100000, tolerance);
      CHECK(found.crossing == brute);
      if (tolerance > 0) CHECK(found.near_contact == brute_near_contact(complex, tolerance));
    }
    CHECK(protect::find_self_intersections(complex, 7) ==
          std::vector<std::array<std::uint32_t, 2>>(brute.begin(), brute.begin() + std::min<std::size_t>(7, brute.size())));
  }
}

// The axis and second-plane points a fan is certified about are constructed in floating point
// and handed to the predicates, which are exact only for coordinates 0 or of magnitude in
// [2^-140, 2^140]: a point outside is refused (the fan is then not certified about it), one
// inside accepted.
TEST_CASE("fans around a vertex: axis points outside the predicates' exact range are refused") {
  io::TriangleSoup soup;
  soup.vertices.push_back(Vec3::Zero());
  const int n = 32;
  for (int i = 0; i < n; ++i) soup.vertices.push_back(Vec3(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n), 0));
  for (int i = 0; i < n; ++i)
    soup.triangles.push_back({0, static_cast<std::uint32_t>(1 + i), static_cast<std::uint32_t>(1 + (i + 1) % n)});
  const protect::Complex complex = protect::build_complex(soup);
  std::vector<std::uint32_t> fan_at;
  const std::vector<protect::detail::Fan> fans = protect::detail::certify_fans(complex, 16, fan_at);
  REQUIRE(fans.size() == 1);
  CHECK(fan_at[0] == 0);
  CHECK(protect::detail::fan_about(complex, fans[0], Vec3(0, 0, 1)).has_value());
  CHECK(protect::detail::fan_about(complex, fans[0], Vec3(0, 0x1p-141, 1)).has_value() == false);
  CHECK(protect::detail::fan_about(complex, fans[0], Vec3(0, 0, 0x1p141)).has_value() == false);
  CHECK(protect::detail::fan_about(complex, fans[0], Vec3(0, 0, std::numeric_limits<double>::quiet_NaN())).has_value() == false);
  CHECK(protect::detail::fan_about(complex, fans[0], Vec3(0x1p-140, 0, 0x1p140)).has_value());
}

// A cap fanned from a rim point: its corner's star is no fan when the side's triangles there
// cover the chords' angles (a cone's base), and the chords alone are certified; about an axis
// turned through the other cap's corner (a cylinder's), the triangles whose planes hold it are
// left out of the turned fan and handed back, and the rest is that fan.
TEST_CASE("fans around a vertex: a cap fanned from a rim point, certified in part and turned") {
  const int n = 40;
  {
    io::TriangleSoup soup = rim_fanned_cylinder(n);  // its lower rim and cap, and a cone over them
    soup.vertices.resize(n);
    soup.vertices.push_back(Vec3(0, 0, 1));
    soup.triangles.clear();
    for (int i = 0; i < n; ++i)
      soup.triangles.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>((i + 1) % n), static_cast<std::uint32_t>(n)});
    for (std::uint32_t i = 1; i + 1 < static_cast<std::uint32_t>(n); ++i) soup.triangles.push_back({0, i + 1, i});
    const protect::Complex complex = protect::build_complex(soup);
    std::vector<std::uint32_t> fan_at;
    const std::vector<protect::detail::Fan> fans = protect::detail::certify_fans(complex, 16, fan_at);
    REQUIRE(fan_at[0] != protect::detail::kNoFan);
    const protect::detail::Fan& corner = fans[fan_at[0]];
    CHECK(corner.sectors.size() == static_cast<std::size_t>(n - 2));
    for (const auto& sector : corner.sectors) CHECK(sector.triangle >= static_cast<std::uint32_t>(n));  // chords only
    CHECK(fan_at[n] != protect::detail::kNoFan);  // the apex: its whole star
    CHECK(fans[fan_at[n]].sectors.size() == static_cast<std::size_t>(n));
  }
  const protect::Complex complex = protect::build_complex(rim_fanned_cylinder(n));
  std::vector<std::uint32_t> fan_at;
  const std::vector<protect::detail::Fan> fans = protect::detail::certify_fans(complex, 16, fan_at);
  REQUIRE(fan_at[0] != protect::detail::kNoFan);
  const protect::detail::Fan& lower = fans[fan_at[0]];
  const Vec3& above = complex.vertices[n];
  std::vector<std::uint32_t> left_out{12345};  // cleared first
  const std::optional<protect::detail::Fan> turned = protect::detail::fan_about(complex, lower, above, &left_out);
  REQUIRE(turned.has_value());
  std::vector<std::uint32_t> before, after(left_out);
  for (const auto& sector : lower.sectors) before.push_back(sector.triangle);
  for (const auto& sector : turned->sectors) after.push_back(sector.triangle);
  std::sort(before.begin(), before.end());
  std::sort(after.begin(), after.end());
  CHECK(after == before);
  for (const std::uint32_t t : left_out) {
    const auto& tri = complex.triangles[t];
    CHECK(kernel::orient3d(complex.vertices[0], above, complex.vertices[tri[0] == 0 ? tri[1] : tri[0]],
                           complex.vertices[tri[2] == 0 ? tri[1] : tri[2]]) == 0);
  }
  // The lower corner's whole star is certified (about an axis tilted by the side's triangles),
  // and its three side triangles hold the vertical through both corners.
  CHECK(left_out.size() == 3);
  CHECK_FALSE(protect::detail::fan_about(complex, lower, above).has_value());
  // No turned fan (a point outside the predicates' range): nothing is handed back either.
  CHECK_FALSE(protect::detail::fan_about(complex, lower, Vec3(1, 0, 1e300), &left_out).has_value());
  CHECK(left_out.empty());
  // At 3,000 rim points the chords' long boxes hold much of the side: the caps are searched
  // whole by angle, where the descent made ~n²/4 pairs of a chord and a side triangle (the stop
  // is asked every 4,096 of them: ~550 times).
  for (const bool caps_first : {false, true}) {
    CAPTURE(caps_first);
    const protect::Complex big = protect::build_complex(rim_fanned_cylinder(3000, caps_first));
    const kernel::AabbTree tree(big.vertices, big.triangles);
    int polls = 0;
    const protect::InputDefects found = protect::find_input_defects(big, tree, 100, 1e-9, [&] { return ++polls < 0; });
    CHECK(found.crossing.empty());
    CHECK_FALSE(found.near_contact);
    CHECK(polls <= 40);  // 22 and 23 when written
  }
}

// A certified fan's own pairs are left out of the descent (d²/2 of them): its near contacts are
// then found by a query per vertex instead, and must still be brute force's - a rim vertex next
// to a sector it is no corner of, one close to the centre - with the fan beside other triangles
// (a wall standing on the disc's rim, and a sheet crossing the disc) that are paired as before.
TEST_CASE("fans around a vertex: near contacts and crossings inside and beside them, as brute force finds them") {
  const int n = 48;
  const auto disc = [n](const std::function<Vec3(int)>& rim) {
    io::TriangleSoup soup;
    soup.vertices.push_back(Vec3::Zero());
    for (int i = 0; i < n; ++i) soup.vertices.push_back(rim(i));
    for (int i = 0; i < n; ++i)
      soup.triangles.push_back({0, static_cast<std::uint32_t>(1 + i), static_cast<std::uint32_t>(1 + (i + 1) % n)});
    return soup;
  };
  const auto at = [](double angle, double radius) { return Vec3(radius * std::cos(angle), radius * std::sin(angle), 0); };
  const double step = 2 * M_PI / n;
  struct Case {
    const char* name;
    io::TriangleSoup soup;
  };
  std::vector<Case> cases;
  cases.push_back({"a plain disc", disc([&](int i) { return at(i * step, 1); })});
  // Vertex 11 just past the direction of vertex 10, farther out: vertex 10 lies 1e-4 from the
  // edge from the centre to vertex 11, a side of a triangle it is no corner of.
  cases.push_back({"a thin sector", disc([&](int i) { return i == 10 ? at(10 * step, 1) : i == 11 ? at(10 * step + 1e-4, 2) : at(i * step, 1); })});
  cases.push_back({"a rim vertex by the centre", disc([&](int i) { return at(i * step, i == 7 ? 3e-4 : 1.0); })});
  for (Case& c : cases) {
    // A wall on the rim between vertices 30 and 31 (sharing that edge), and a sheet through the
    // disc far from both: paired with the fan's triangles as before.
    const auto base = static_cast<std::uint32_t>(c.soup.vertices.size());
    c.soup.vertices.push_back(c.soup.vertices[31] + Vec3(0, 0, 1));
    c.soup.triangles.push_back({31, 32, base});
    c.soup.vertices.push_back(Vec3(-0.3, -0.5, -0.5));
    c.soup.vertices.push_back(Vec3(-0.3, -0.4, 0.5));
    c.soup.vertices.push_back(Vec3(-0.4, -0.6, 0.5));
    c.soup.triangles.push_back({base + 1, base + 2, base + 3});
  }
  for (const Case& c : cases) {
    CAPTURE(c.name);
    const protect::Complex complex = protect::build_complex(c.soup);
    const kernel::AabbTree tree(complex.vertices, complex.triangles);
    const auto brute = brute_crossings(complex);
    CHECK(!brute.empty());  // the sheet crosses the disc
    for (const double tolerance : {1e-5, 1e-3, 1e-2}) {
      CAPTURE(tolerance);
      const protect::InputDefects found = protect::find_input_defects(complex, tree, 100000, tolerance);
      CHECK(found.crossing == brute);
      CHECK(found.near_contact == brute_near_contact(complex, tolerance));
    }
  }
  // The cases mean something: the thin sector and the vertex by the centre are near contacts at
  // 1e-3 and not at 1e-5, the plain disc has none.
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const protect::Complex complex = protect::build_complex(cases[k].soup);
    CHECK(brute_near_contact(complex, 1e-3).has_value() == (k > 0));
    CHECK_FALSE(brute_near_contact(complex, 1e-5));
  }
}
