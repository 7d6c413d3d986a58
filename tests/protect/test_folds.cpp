// protect::sharpest_fold_near and narrowest_corner_near (protect/folds.h): a wedge's apex edge
// and apex corner are found with its angle, whatever the triangles' orientation; flat and
// right-angled edges and a cube's corners are neither; the radius and the angle bound are
// respected.
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

TEST_CASE("narrow corners: a wedge's apex, where its legs leave at the wedge's angle; none on a cube") {
  for (const double angle : {2.0, 5.0, 10.0}) {
    CAPTURE(angle);
    const protect::Complex wedge = protect::build_complex(io::make_wedge(angle, 0.1));
    // The apex corners (0, 0, 0) and (0, 0, 1/2): each cap's two legs leave them `angle` apart.
    const auto narrow = protect::narrowest_corner_near(wedge, Vec3::Zero(), 0.01, 15);
    REQUIRE(narrow);
    CHECK(wedge.vertices[wedge.corner_vertex[narrow->corner]].norm() < 1e-12);
    CHECK(narrow->curves[0] != narrow->curves[1]);
    CHECK(narrow->angle_degrees == doctest::Approx(angle).epsilon(1e-6));
    // The nearest curve not through the apex: a leg of the other cap, 1/2 above.
    REQUIRE(narrow->nearest_curve != protect::kNoIndex);
    CHECK(narrow->nearest_curve != narrow->curves[0]);
    CHECK(narrow->nearest_curve != narrow->curves[1]);
    CHECK(narrow->clearance == doctest::Approx(0.5));
    CHECK_FALSE(protect::narrowest_corner_near(wedge, Vec3::Zero(), 0.01, angle / 2));
    // The radius is respected: the far corners of the wedge (legs of length 1) are 60°+ wide.
    CHECK_FALSE(protect::narrowest_corner_near(wedge, Vec3(1, 0, 0), 0.1, 15));
  }
  const protect::Complex cube = protect::build_complex(io::make_cube(4));
  CHECK_FALSE(protect::narrowest_corner_near(cube, Vec3(0.5, 0.5, 0.5), 10, 89));
  const auto right = protect::narrowest_corner_near(cube, Vec3(0.5, 0.5, 0.5), 10, 91);
  REQUIRE(right);
  CHECK(right->angle_degrees == doctest::Approx(90));
}
