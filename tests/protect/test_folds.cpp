// protect::sharpest_fold_near and narrowest_corner_near (protect/folds.h): a wedge's apex edge
// and apex corner are found with its angle, whatever the triangles' orientation; flat and
// right-angled edges and a cube's corners are neither; the radius and the angle bound are
// respected.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

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

TEST_CASE("folds off the curves: a cube's edges once a feature angle above 90 degrees leaves them out") {
  const Vec3 centre(0.5, 0.5, 0.5);
  // At the default angle every cube edge is on a curve: off them only the faces' flat edges.
  const protect::Complex marked = protect::build_complex(io::make_cube(4));
  CHECK(protect::sharpest_fold_near(marked, centre, 10, 91));
  CHECK_FALSE(protect::sharpest_fold_near(marked, centre, 10, 179, protect::FoldEdges::off_curves));
  CHECK(protect::sharpest_fold_near(marked, centre, 10, 181, protect::FoldEdges::off_curves)->dihedral_degrees ==
        doctest::Approx(180));
  // At 120 degrees none is a curve: the right angles are found off the curves.
  protect::ComplexOptions wide;
  wide.feature_angle_degrees = 120;
  const protect::Complex unmarked = protect::build_complex(io::make_cube(4), wide);
  REQUIRE(unmarked.curves.empty());
  const auto edge = protect::sharpest_fold_near(unmarked, centre, 10, 119, protect::FoldEdges::off_curves);
  REQUIRE(edge);
  CHECK(edge->dihedral_degrees == doctest::Approx(90));
  // The flat edges inside the faces are off the curves too, but no sharper than 180 degrees.
  CHECK_FALSE(protect::sharpest_fold_near(unmarked, centre, 10, 89, protect::FoldEdges::off_curves));
  // A wedge at 120 degrees: its 2 degree apex is still a curve (normals 178 degrees apart), its
  // right-angled edges are not, and those are what off_curves finds.
  const protect::Complex wedge = protect::build_complex(io::make_wedge(2, 0.1), wide);
  const auto sharp = protect::sharpest_fold_near(wedge, Vec3::Zero(), HUGE_VAL, 119, protect::FoldEdges::off_curves);
  REQUIRE(sharp);
  CHECK(sharp->dihedral_degrees > 80);
  CHECK(protect::sharpest_fold_near(wedge, Vec3::Zero(), HUGE_VAL, 15)->dihedral_degrees == doctest::Approx(2).epsilon(1e-6));
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

TEST_CASE("a curve coming back near itself: a hairpin's boundary, named at its gap; none on a cube") {
  const protect::Complex hairpin = protect::build_complex(io::make_hairpin_sheet(0.03, 4));
  REQUIRE(hairpin.curves.size() == 4);
  // The curves along y = 0 and y = 1 run out along z = 0 and back along z = 0.03; from a point
  // on the lower branch the upper one is 0.03 away, the curve between them about 2 long.
  std::size_t returning = 0;
  for (std::uint32_t c = 0; c < hairpin.curves.size(); ++c) {
    if (hairpin.curves[c].length < 1.5) continue;  // the straight ends at x = 0
    ++returning;
    const double s = 0.25;  // a point at x = 0.25 on one branch
    const auto back = protect::curve_returning_near(hairpin, c, s);
    REQUIRE(back.has_value());
    CHECK(back->curve == c);
    CHECK(back->distance == doctest::Approx(0.03).epsilon(1e-9));
    // Near the bend the curve's own neighbourhood is no return: nothing closer than the gap.
    const auto at_bend = protect::curve_returning_near(hairpin, c, hairpin.curves[c].length / 2);
    CHECK((!at_bend || at_bend->distance >= 0.03 * (1 - 1e-9)));
  }
  CHECK(returning == 2);
  const protect::Complex cube = protect::build_complex(io::make_cube(2));
  for (std::uint32_t c = 0; c < cube.curves.size(); ++c)
    CHECK_FALSE(protect::curve_returning_near(cube, c, cube.curves[c].length / 3).has_value());
}

TEST_CASE("the patch nearest a curve among those it does not bound: a cube's edge, half an edge away") {
  // From the middle of an edge, the faces it bounds are at distance 0 and left out; the two faces
  // through its ends are half an edge away, the other two a whole edge.
  const protect::Complex cube = protect::build_complex(io::make_cube(2));
  REQUIRE(cube.curves.size() == 12);
  for (std::uint32_t c = 0; c < cube.curves.size(); ++c) {
    const Vec3 middle = cube.point_at(c, cube.curves[c].length / 2);
    const auto bounded = cube.curve_patch_ids(c);
    const auto near = protect::nearest_patch_except(cube, middle, bounded);
    REQUIRE(near.has_value());
    CHECK(near->distance == doctest::Approx(cube.curves[c].length / 2).epsilon(1e-12));
    CHECK(std::find(bounded.begin(), bounded.end(), near->patch) == bounded.end());
  }
}
