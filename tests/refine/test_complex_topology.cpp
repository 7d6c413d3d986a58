// complex_topology (refine/complex_topology.h) on complexes whose figures are known by hand: a
// triangle, a tetrahedron (also with a triangle turned over: orientability does not depend on the
// orientation given), a Möbius strip against an annulus, two tetrahedra pinched at a vertex, a
// book of three triangles, the generated box with a fin and the torus; and topology_differences
// naming exactly the figures that differ; and sort_edge_records, which both grouping steps use,
// against std::sort.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <delpsc/io/shapes.h>
#include <delpsc/protect/complex.h>
#include <delpsc/refine/complex_topology.h>
#include <delpsc/refine/edge_record_sort.h>

#include "support/generators.h"

using namespace delpsc;
using Triangles = std::vector<std::array<std::uint32_t, 3>>;

namespace {

// A strip of n quads around a loop: top vertices 0..n-1, bottom n..2n-1. With a twist the last
// quad glues top to bottom (a Möbius strip), without it an annulus.
Triangles strip(std::uint32_t n, bool twist) {
  Triangles out;
  for (std::uint32_t i = 0; i < n; ++i) {
    const bool last = i + 1 == n;
    const std::uint32_t t0 = i, b0 = n + i;
    std::uint32_t t1 = (i + 1) % n, b1 = n + (i + 1) % n;
    if (last && twist) std::swap(t1, b1);
    out.push_back({t0, b0, b1});
    out.push_back({t0, b1, t1});
  }
  return out;
}

const Triangles tetrahedron{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};

refine::ComplexTopology of_model(const io::TriangleSoup& soup) {
  return refine::complex_topology(protect::build_complex(soup).triangles);
}

}  // namespace

TEST_CASE("one triangle: a disk with one boundary loop") {
  const Triangles one{{4, 7, 9}};  // unused indices below and between are not vertices
  const refine::ComplexTopology t = refine::complex_topology(one);
  CHECK(t.vertices == 3);
  CHECK(t.edges == 3);
  CHECK(t.triangles == 1);
  CHECK(t.components == 1);
  CHECK(t.euler == 1);
  CHECK(t.boundary_loops == 1);
  CHECK(t.singular_curves == 0);
  CHECK(t.sheets == 1);
  CHECK(t.non_orientable_sheets == 0);
}

TEST_CASE("tetrahedron: a sphere, orientable however its triangles are given") {
  refine::ComplexTopology t = refine::complex_topology(tetrahedron);
  CHECK(t.euler == 2);
  CHECK(t.boundary_loops == 0);
  CHECK(t.sheets == 1);
  CHECK(t.non_orientable_sheets == 0);
  Triangles turned = tetrahedron;
  std::swap(turned[2][0], turned[2][1]);
  t = refine::complex_topology(turned);
  CHECK(t.euler == 2);
  CHECK(t.non_orientable_sheets == 0);
}

TEST_CASE("Möbius strip against annulus: same Euler characteristic, told apart") {
  const refine::ComplexTopology annulus = refine::complex_topology(strip(5, false));
  const refine::ComplexTopology moebius = refine::complex_topology(strip(5, true));
  CHECK(annulus.euler == 0);
  CHECK(moebius.euler == 0);
  CHECK(annulus.boundary_loops == 2);
  CHECK(moebius.boundary_loops == 1);
  CHECK(annulus.non_orientable_sheets == 0);
  CHECK(moebius.non_orientable_sheets == 1);
  const std::vector<std::string> d = refine::topology_differences(moebius, annulus);
  REQUIRE(d.size() == 2);
  CHECK(d[0].find("boundary loops") == 0);
  CHECK(d[1].find("non-orientable sheets") == 0);
}

TEST_CASE("two tetrahedra pinched at a vertex: one component, two sheets") {
  Triangles two = tetrahedron;
  for (auto t : tetrahedron) {
    for (auto& v : t) v = v == 0 ? 0 : v + 3;
    two.push_back(t);
  }
  const refine::ComplexTopology t = refine::complex_topology(two);
  CHECK(t.components == 1);
  CHECK(t.euler == 3);  // two spheres (2 + 2) glued at one point (- 1)
  CHECK(t.sheets == 2);
  CHECK(t.singular_curves == 0);
  // Pulled apart (the second copy on its own vertex) the figures differ.
  Triangles apart = two;
  for (std::size_t i = 4; i < apart.size(); ++i)
    for (auto& v : apart[i])
      if (v == 0) v = 100;
  const std::vector<std::string> d = refine::topology_differences(refine::complex_topology(apart), t);
  REQUIRE(d.size() == 2);
  CHECK(d[0] == "components: output 2, input 1");
  CHECK(d[1] == "Euler characteristic: output 4, input 3");
}

TEST_CASE("book of three triangles on one spine") {
  const Triangles book{{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const refine::ComplexTopology t = refine::complex_topology(book);
  CHECK(t.edges == 7);
  CHECK(t.euler == 1);
  CHECK(t.singular_curves == 1);
  CHECK(t.sheets == 3);
  CHECK(t.boundary_loops == 1);  // the six outer edges meet at the spine's ends
}

TEST_CASE("generated models") {
  const refine::ComplexTopology fin = of_model(io::make_box_with_fin(4));
  CHECK(fin.components == 1);
  CHECK(fin.euler == 2);  // a sphere (2) with a disk glued along an arc (+ 1 - 1)
  CHECK(fin.boundary_loops == 1);
  CHECK(fin.singular_curves == 1);
  CHECK(fin.sheets == 2);
  const refine::ComplexTopology torus = of_model(io::make_torus(1, 0.35, 16, 8));
  CHECK(torus.euler == 0);
  CHECK(torus.boundary_loops == 0);
  const refine::ComplexTopology sphere = of_model(io::make_sphere(4));
  CHECK(refine::topology_differences(sphere, sphere).empty());
  const std::vector<std::string> d = refine::topology_differences(torus, sphere);
  REQUIRE(d.size() == 1);
  CHECK(d[0] == "Euler characteristic: output 0, input 2");
}

namespace {

// A Möbius strip in space: n quads around a circle of radius 1, the strip's width turning by a
// half turn (strip() with coordinates).
io::TriangleSoup moebius_soup(std::uint32_t n) {
  io::TriangleSoup soup;
  const double pi = 3.14159265358979323846;
  for (int side : {1, -1})
    for (std::uint32_t i = 0; i < n; ++i) {
      const double u = 2 * pi * i / n, w = 0.2 * side;
      soup.vertices.push_back(
          {(1 + w * std::cos(u / 2)) * std::cos(u), (1 + w * std::cos(u / 2)) * std::sin(u), w * std::sin(u / 2)});
    }
  for (const auto& t : strip(n, true)) soup.triangles.push_back(t);
  return soup;
}

}  // namespace

TEST_CASE("read off a complex's edge table: the same figures as from its triangles") {
  const std::vector<io::TriangleSoup> soups = {
      io::make_box_with_fin(4), io::make_torus(1, 0.35, 16, 8), io::make_sphere(4), io::make_book(4, 3),
      io::make_touching_spheres(4), io::make_square_sheet(3), io::make_cone_on_sheet(10, 24, 4),
      io::make_capped_cylinder(), moebius_soup(12)};
  for (std::size_t i = 0; i < soups.size(); ++i) {
    CAPTURE(i);
    const protect::Complex complex = protect::build_complex(soups[i]);
    const refine::ComplexTopology a = refine::complex_topology(complex), b = refine::complex_topology(complex.triangles);
    CHECK(a.vertices == b.vertices);
    CHECK(a.edges == b.edges);
    CHECK(a.triangles == b.triangles);
    CHECK(a.components == b.components);
    CHECK(a.euler == b.euler);
    CHECK(a.boundary_loops == b.boundary_loops);
    CHECK(a.singular_curves == b.singular_curves);
    CHECK(a.sheets == b.sheets);
    CHECK(a.non_orientable_sheets == b.non_orientable_sheets);
  }
  // Not a vacuous comparison: the Möbius strip is told from an annulus by the complex's figures.
  const refine::ComplexTopology moebius = refine::complex_topology(protect::build_complex(moebius_soup(12)));
  CHECK(moebius.non_orientable_sheets == 1);
  CHECK(moebius.boundary_loops == 1);
  CHECK(refine::complex_topology(protect::build_complex(io::make_book(4, 3))).singular_curves == 1);
  CHECK(refine::complex_topology(protect::Complex{}).triangles == 0);
}

TEST_CASE("a triangle repeating a vertex is refused") {
  const Triangles bad{{0, 1, 1}};
  CHECK_THROWS_AS(refine::complex_topology(bad), std::invalid_argument);
}

TEST_CASE("sort_edge_records orders as std::sort with the same total order") {
  struct Record {
    std::uint32_t lo, hi, triangle;
  };
  const auto less = [](const Record& x, const Record& y) {
    return x.lo != y.lo ? x.lo < y.lo : x.hi != y.hi ? x.hi < y.hi : x.triangle < y.triangle;
  };
  delpsc::test::Rng rng(3);
  for (const std::uint32_t vertices : {1u, 7u, 1000u}) {
    std::vector<Record> records;
    for (std::uint32_t t = 0; t < 5000; ++t) {
      const auto a = static_cast<std::uint32_t>(rng.integer(0, vertices - 1));
      const auto b = static_cast<std::uint32_t>(rng.integer(0, vertices - 1));
      records.push_back({std::min(a, b), std::max(a, b), t});
    }
    std::vector<Record> expected = records;
    std::sort(expected.begin(), expected.end(), less);
    refine::sort_edge_records(records, vertices, less);
    REQUIRE(records.size() == expected.size());
    bool same = true;
    for (std::size_t i = 0; i < records.size(); ++i)
      same = same && records[i].lo == expected[i].lo && records[i].hi == expected[i].hi &&
             records[i].triangle == expected[i].triangle;
    CHECK(same);
  }
  std::vector<Record> none;
  refine::sort_edge_records(none, 0, less);
  CHECK(none.empty());
}
