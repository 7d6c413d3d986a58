// Issue 6's acceptance on the generated models at 4% and 1% of the diagonal: termination with
// the disk condition, G1, G2 per patch and for the whole output (tests/support/acceptance.h).
// Non-manifold complexes (book, fin, the sample part's fin), open surfaces with boundary
// (square and disc sheets), closed smooth surfaces without features (sphere, torus), rotated
// copies (no axis-aligned plane). The small angles, thin gaps and short curves are in
// test_accept_hard.cpp, 0.5% in test_accept_generated_fine.cpp (separate executables, so ctest
// runs them in parallel).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include <delpsc/io/sample_part.h>
#include <delpsc/io/shapes.h>

#include "support/acceptance.h"

using namespace delpsc;
using test::check_acceptance;

namespace {

// The boxes as one model: vertices at the same position merged, and a triangle given twice (a
// face two boxes share) kept once, as the first box winds it.
io::TriangleSoup joined_boxes(const std::vector<io::TriangleSoup>& boxes) {
  io::TriangleSoup out;
  std::map<std::array<double, 3>, std::uint32_t> index;
  std::set<std::array<std::uint32_t, 3>> seen;
  for (const io::TriangleSoup& box : boxes)
    for (const auto& t : box.triangles) {
      std::array<std::uint32_t, 3> u{};
      for (int k = 0; k < 3; ++k) {
        const Vec3& p = box.vertices[t[k]];
        const auto [it, added] = index.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, out.vertices.size());
        if (added) out.vertices.push_back(p);
        u[k] = it->second;
      }
      std::array<std::uint32_t, 3> key = u;
      std::sort(key.begin(), key.end());
      if (seen.insert(key).second) out.triangles.push_back(u);
    }
  return out;
}

}  // namespace

TEST_CASE("closed models with features: cube, capped cylinder, sample part") {
  for (const double size : {0.04, 0.01}) {
    check_acceptance("cube", io::make_cube(4), size);
    check_acceptance("capped cylinder", io::make_capped_cylinder(1, 2, 24, 8, 4), size);
    check_acceptance("sample part", io::make_sample_part(), size);
  }
}

TEST_CASE("non-manifold complexes: book of three sheets, box with a fin") {
  for (const double size : {0.04, 0.01}) {
    check_acceptance("book", io::make_book(3, 4), size);
    check_acceptance("box with fin", io::make_box_with_fin(4), size);
  }
}

// Closed shells meeting along non-manifold edges: no component of the output is closed by
// itself, so orient_triangles cannot turn it outward by its volume; the input's winding decides
// (the probe of session 28 found both cubes inside out at 10%, and half a shell each way).
TEST_CASE("closed shells meeting at edges: two cubes sharing an edge, a box with an inner wall") {
  const io::TriangleSoup cubes = joined_boxes({io::make_box(Vec3(0, 0, 0), Vec3(1, 1, 1), {4, 4, 4}),
                                               io::make_box(Vec3(1, 1, 0), Vec3(2, 2, 1), {4, 4, 4})});
  const io::TriangleSoup wall = joined_boxes({io::make_box(Vec3(0, 0, 0), Vec3(1, 1, 1), {4, 4, 4}),
                                              io::make_box(Vec3(1, 0, 0), Vec3(2, 1, 1), {4, 4, 4})});
  for (const double size : {0.1, 0.04, 0.01}) {
    check_acceptance("two cubes sharing an edge", cubes, size);
    check_acceptance("box with an inner wall", wall, size);
  }
}

TEST_CASE("open surfaces with boundary: square and disc sheets, either way up") {
  for (const double size : {0.04, 0.01})
    for (const bool reversed : {false, true}) {
      io::TriangleSoup square = io::make_square_sheet(4), disc = io::make_disc_sheet(24, 4);
      if (reversed)
        for (io::TriangleSoup* s : {&square, &disc})
          for (auto& t : s->triangles) std::swap(t[1], t[2]);
      CAPTURE(reversed);
      check_acceptance("square sheet", square, size);
      check_acceptance("disc sheet", disc, size);
    }
}

TEST_CASE("closed smooth surfaces without features: sphere, torus") {
  for (const double size : {0.04, 0.01}) {
    check_acceptance("sphere", io::make_sphere(8), size);
    check_acceptance("torus", io::make_torus(1, 0.35, 32, 16), size);
  }
}

TEST_CASE("rotated cube, book and fin") {
  for (const double size : {0.04, 0.01}) {
    check_acceptance("rotated cube", test::rotated_model(io::make_cube(4)), size);
    check_acceptance("rotated book", test::rotated_model(io::make_book(3, 4)), size);
    check_acceptance("rotated fin", test::rotated_model(io::make_box_with_fin(4)), size);
  }
}
