// Issue 6's acceptance on the generated models at 4% and 1% of the diagonal: termination with
// the disk condition, G1, G2 per patch and for the whole output (tests/support/acceptance.h).
// Non-manifold complexes (book, fin, the sample part's fin), open surfaces with boundary
// (square and disc sheets), closed smooth surfaces without features (sphere, torus), rotated
// copies (no axis-aligned plane). The small angles, thin gaps and short curves are in
// test_accept_hard.cpp, 0.5% in test_accept_generated_fine.cpp (separate executables, so ctest
// runs them in parallel).
#include <doctest/doctest.h>

#include <delpsc/io/sample_part.h>
#include <delpsc/io/shapes.h>

#include "support/acceptance.h"

using namespace delpsc;
using test::check_acceptance;

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

TEST_CASE("open surfaces with boundary: square and disc sheets") {
  for (const double size : {0.04, 0.01}) {
    check_acceptance("square sheet", io::make_square_sheet(4), size);
    check_acceptance("disc sheet", io::make_disc_sheet(24, 4), size);
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
