#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <utility>

#include <delpsc/io/shapes.h>
#include <delpsc/io/surface_mesh.h>
#include <delpsc/refine/triangle_orientation.h>

#include "support/orientation_check.h"

using namespace delpsc;

namespace {

using Triangles = kernel::LargeVector<std::array<std::uint32_t, 3>>;

// How many times each directed edge is used: a consistent orientation uses each edge shared by
// two triangles once in each direction.
std::size_t edges_used_twice_the_same_way(const Triangles& triangles) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  std::size_t bad = 0;
  for (const auto& [edge, uses] : directed) bad += uses > 1;
  return bad;
}

double signed_volume(std::span<const Vec3> v, const Triangles& triangles) {
  double volume = 0;
  for (const auto& t : triangles) volume += v[t[0]].dot(v[t[1]].cross(v[t[2]]));
  return volume / 6;
}

void flip_some(Triangles& triangles, unsigned seed) {
  std::mt19937 rng(seed);
  for (auto& t : triangles)
    if (rng() & 1u) std::swap(t[1], t[2]);
}

}  // namespace

TEST_CASE("orient_triangles: a closed surface comes out consistent and outward") {
  for (const auto& soup : {io::make_cube(3, 2.0), io::make_sphere(6), io::make_torus(1, 0.3, 16, 8)}) {
    for (unsigned seed = 1; seed <= 3; ++seed) {
      Triangles triangles = soup.triangles;
      flip_some(triangles, seed);
      REQUIRE(edges_used_twice_the_same_way(triangles) > 0);
      CHECK(refine::orient_triangles(soup.vertices, triangles) == 0);
      CHECK(edges_used_twice_the_same_way(triangles) == 0);
      CHECK(signed_volume(soup.vertices, triangles) > 0);
    }
    // All turned inside out: turned back.
    Triangles inverted = soup.triangles;
    for (auto& t : inverted) std::swap(t[1], t[2]);
    refine::orient_triangles(soup.vertices, inverted);
    CHECK(signed_volume(soup.vertices, inverted) > 0);
  }
}

TEST_CASE("orient_triangles: open and non-manifold sets, and a Moebius strip") {
  // An open sheet: consistent, whichever way.
  const io::TriangleSoup sheet = io::make_square_sheet(5);
  Triangles triangles = sheet.triangles;
  flip_some(triangles, 7);
  CHECK(refine::orient_triangles(sheet.vertices, triangles) == 0);
  CHECK(edges_used_twice_the_same_way(triangles) == 0);
  // Three sheets on one edge: that edge joins nothing, each sheet is consistent by itself.
  const io::TriangleSoup book = io::make_book(3, 4);
  triangles = book.triangles;
  flip_some(triangles, 9);
  CHECK(refine::orient_triangles(book.vertices, triangles) == 0);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) ++uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  for (const auto& [edge, n] : uses)
    if (n == 2) CHECK(directed[edge] == 1);  // both directions once
  // A Moebius strip: 12 quads around a loop with a half twist; one non-orientable component.
  std::vector<Vec3> v;
  const int m = 12;
  for (int i = 0; i < m; ++i) {
    const double a = 2 * M_PI * i / m, twist = a / 2;
    const Vec3 centre(std::cos(a), std::sin(a), 0), radial(std::cos(a), std::sin(a), 0), up(0, 0, 1);
    const Vec3 w = std::cos(twist) * radial + std::sin(twist) * up;
    v.push_back(centre - 0.2 * w);
    v.push_back(centre + 0.2 * w);
  }
  Triangles strip;
  for (int i = 0; i < m; ++i) {
    const std::uint32_t a0 = 2 * i, a1 = 2 * i + 1;
    // The last quad joins the first column the other way round: the half twist.
    const bool last = i == m - 1;
    const std::uint32_t b0 = last ? 1 : 2 * (i + 1), b1 = last ? 0 : 2 * (i + 1) + 1;
    strip.push_back({a0, b0, b1});
    strip.push_back({a0, b1, a1});
  }
  CHECK(refine::orient_triangles(v, strip) == 1);
}

TEST_CASE("orient_triangles: nested closed surfaces - a cavity faces into itself, a solid in it outward") {
  // Three concentric cubes (sizes 3, 2, 1, centred alike) and a fourth beside them: the middle
  // one bounds the cavity of the outer, the inner is a solid in that cavity, the fourth its own
  // solid. Signed volume by nesting depth: +, -, +, +.
  io::SurfaceMesh mesh;
  const auto add = [&](double size, const Vec3& centre) {
    const io::TriangleSoup c = io::make_cube(2, size);
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    for (const Vec3& v : c.vertices) mesh.vertices.push_back(v - Vec3::Constant(size / 2) + centre);
    for (const auto& t : c.triangles) mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  };
  add(3, Vec3::Zero());
  add(2, Vec3::Zero());
  add(1, Vec3::Zero());
  add(1, Vec3(5, 0, 0));
  const std::size_t per_cube = mesh.triangles.size() / 4;
  const auto volume_of = [&](std::size_t cube) {
    Triangles part(mesh.triangles.begin() + static_cast<std::ptrdiff_t>(cube * per_cube),
                   mesh.triangles.begin() + static_cast<std::ptrdiff_t>((cube + 1) * per_cube));
    return signed_volume(mesh.vertices, part);
  };
  for (unsigned seed = 1; seed <= 3; ++seed) {
    CAPTURE(seed);
    flip_some(mesh.triangles, seed);
    CHECK(refine::orient_triangles(mesh.vertices, mesh.triangles) == 0);
    CHECK(edges_used_twice_the_same_way(mesh.triangles) == 0);
    CHECK(volume_of(0) == doctest::Approx(27));
    CHECK(volume_of(1) == doctest::Approx(-8));
    CHECK(volume_of(2) == doctest::Approx(1));
    CHECK(volume_of(3) == doctest::Approx(1));
    CHECK(test::orientation_problems(mesh).empty());
  }
  // The tests' checker, independently: the cavity turned outward is reported.
  io::SurfaceMesh wrong = mesh;
  for (std::size_t t = per_cube; t < 2 * per_cube; ++t) std::swap(wrong.triangles[t][1], wrong.triangles[t][2]);
  const auto problems = test::orientation_problems(wrong);
  REQUIRE(problems.size() == 1);
  CHECK(problems[0].find("bounds a cavity") != std::string::npos);
}

TEST_CASE("orient_triangles: a cavity touching its container at a vertex still faces into itself") {
  // The cube [0, 3]^3 and, inside it, a tetrahedron with one corner at the cube's corner at the
  // origin (the same vertex) and the others strictly inside: the two meet at that vertex only.
  // The tetrahedron's first triangle starts there: a test point at that vertex would lie on the
  // cube (winding number 1/8) and the cavity would be missed.
  io::SurfaceMesh mesh;
  const io::TriangleSoup outer = io::make_cube(2, 3);
  mesh.vertices.assign(outer.vertices.begin(), outer.vertices.end());
  mesh.triangles.assign(outer.triangles.begin(), outer.triangles.end());
  const auto shared =
      static_cast<std::uint32_t>(std::find(mesh.vertices.begin(), mesh.vertices.end(), Vec3::Zero()) - mesh.vertices.begin());
  REQUIRE(shared < mesh.vertices.size());
  const auto a = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.push_back(Vec3(0.5, 0.5, 0.2));
  mesh.vertices.push_back(Vec3(0.5, 0.2, 0.5));
  mesh.vertices.push_back(Vec3(0.2, 0.5, 0.5));
  const std::size_t outer_count = mesh.triangles.size();
  for (const std::array<std::uint32_t, 3>& t : {std::array<std::uint32_t, 3>{shared, a, a + 1},
                                                {shared, a + 1, a + 2}, {shared, a + 2, a}, {a, a + 2, a + 1}})
    mesh.triangles.push_back(t);
  CHECK(refine::orient_triangles(mesh.vertices, mesh.triangles) == 0);
  const Triangles outer_part(mesh.triangles.begin(), mesh.triangles.begin() + static_cast<std::ptrdiff_t>(outer_count));
  const Triangles inner_part(mesh.triangles.begin() + static_cast<std::ptrdiff_t>(outer_count), mesh.triangles.end());
  CHECK(signed_volume(mesh.vertices, outer_part) == doctest::Approx(27));
  CHECK(signed_volume(mesh.vertices, inner_part) == doctest::Approx(-0.018));
  CHECK(test::orientation_problems(mesh).empty());
}

TEST_CASE("the tests' own orientation check reports a flipped triangle and an inward closed surface") {
  io::SurfaceMesh cube = io::surface_mesh_from(io::make_cube(3));
  CHECK(refine::orient_triangles(cube.vertices, cube.triangles) == 0);
  CHECK(test::orientation_problems(cube).empty());
  io::SurfaceMesh one = cube;
  std::swap(one.triangles[5][1], one.triangles[5][2]);
  const auto flipped = test::orientation_problems(one);
  CHECK(flipped.size() == 3);  // each of its three edges
  io::SurfaceMesh inward = cube;
  for (auto& t : inward.triangles) std::swap(t[1], t[2]);
  const auto turned = test::orientation_problems(inward);
  REQUIRE(turned.size() == 1);
  CHECK(turned[0].find("faces inward") != std::string::npos);
  // An open sheet has no inside: only consistency is asked of it, in either direction.
  io::SurfaceMesh sheet = io::surface_mesh_from(io::make_square_sheet(3));
  CHECK(test::orientation_problems(sheet).empty());
  for (auto& t : sheet.triangles) std::swap(t[1], t[2]);
  CHECK(test::orientation_problems(sheet).empty());
}

TEST_CASE("an open component takes the orientation its votes prefer; a closed one stays outward") {
  io::SurfaceMesh sheet = io::surface_mesh_from(io::make_square_sheet(6));  // in the plane z = 0
  const auto facing_z = [&](double sign) {
    return [&sheet, sign](std::uint32_t t) {
      const auto& v = sheet.triangles[t];
      const Vec3 n = (sheet.vertices[v[1]] - sheet.vertices[v[0]]).cross(sheet.vertices[v[2]] - sheet.vertices[v[0]]);
      return sign * n.z() > 0 ? 1 : -1;
    };
  };
  const auto all_facing = [&](double sign) {
    return std::all_of(sheet.triangles.begin(), sheet.triangles.end(), [&](const auto& v) {
      const Vec3 n = (sheet.vertices[v[1]] - sheet.vertices[v[0]]).cross(sheet.vertices[v[2]] - sheet.vertices[v[0]]);
      return sign * n.z() > 0;
    });
  };
  for (const double sign : {1.0, -1.0}) {
    CAPTURE(sign);
    CHECK(refine::orient_triangles(sheet.vertices, sheet.triangles, facing_z(sign)) == 0);
    CHECK(all_facing(sign));
  }
  // A closed cube ignores the votes: outward whatever they say.
  io::SurfaceMesh cube = io::surface_mesh_from(io::make_cube(3));
  for (auto& t : cube.triangles) std::swap(t[1], t[2]);
  CHECK(refine::orient_triangles(cube.vertices, cube.triangles, [](std::uint32_t) { return -1; }) == 0);
  CHECK(test::orientation_problems(cube).empty());
}
