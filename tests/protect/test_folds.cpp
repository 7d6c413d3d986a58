// protect::sharpest_fold_near (protect/folds.h): the edge of a wedge is found with its angle,
// whatever the triangles' orientation; flat and right-angled edges are no folds; the radius
// and the angle bound are respected.
#include <doctest/doctest.h>

#include <algorithm>

#include <delpsc/io/shapes.h>
#include <delpsc/protect/folds.h>

using namespace delpsc;

TEST_CASE("folds: a wedge's apex edges, not the cube's") {
  for (const double angle : {2.0, 5.0, 10.0}) {
    CAPTURE(angle);
    const protect::Complex wedge = protect::build_complex(io::make_wedge(angle, 0.1));
    // Anywhere near the model: the sharpest edge is on the apex line, at the wedge's angle.
    Vec3 centre = Vec3::Zero();
    for (const Vec3& v : wedge.vertices) centre += v / static_cast<double>(wedge.vertices.size());
    const auto fold = protect::sharpest_fold_near(wedge, centre, 100, 15);
    REQUIRE(fold);
    CHECK(fold->dihedral_degrees == doctest::Approx(angle).epsilon(1e-6));
    // Below the bound asked for, there is none; far from the model, none either.
    CHECK_FALSE(protect::sharpest_fold_near(wedge, centre, 100, angle / 2));
    CHECK_FALSE(protect::sharpest_fold_near(wedge, centre + Vec3(1000, 0, 0), 1, 15));
  }
  const protect::Complex cube = protect::build_complex(io::make_cube(4));
  CHECK_FALSE(protect::sharpest_fold_near(cube, Vec3(0.5, 0.5, 0.5), 10, 89));
  const auto right = protect::sharpest_fold_near(cube, Vec3(0.5, 0.5, 0.5), 10, 91);
  REQUIRE(right);
  CHECK(right->dihedral_degrees == doctest::Approx(90));

  // Orientation does not matter: the same wedge with every triangle flipped.
  io::TriangleSoup flipped = io::make_wedge(5, 0.1);
  for (auto& t : flipped.triangles) std::swap(t[1], t[2]);
  const protect::Complex f = protect::build_complex(flipped);
  const auto fold = protect::sharpest_fold_near(f, f.vertices.front(), 100, 15);
  REQUIRE(fold);
  CHECK(fold->dihedral_degrees == doctest::Approx(5).epsilon(1e-6));
}
