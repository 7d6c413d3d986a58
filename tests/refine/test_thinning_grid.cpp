// ThinningGrid: each refused point lies within the separation of a point admitted before it, one
// point per cell is admitted, and what cannot be placed in a cell is never thinned.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <delpsc/refine/thinning_grid.h>

using namespace delpsc;

TEST_CASE("thinning grid: every refused point is within the separation of an admitted one") {
  std::mt19937 rng(11);
  for (const double separation : {0.05, 0.3, 1e-7}) {
    CAPTURE(separation);
    // Points in a box of ~40 separations a side, many of them close together.
    std::uniform_real_distribution<double> coordinate(-20 * separation, 20 * separation);
    refine::ThinningGrid grid(separation);
    std::vector<Vec3> admitted;
    std::size_t refused = 0;
    for (int k = 0; k < 6000; ++k) {
      const Vec3 p(coordinate(rng), coordinate(rng), 1e3 * separation + coordinate(rng));
      if (grid.admit(p)) {
        admitted.push_back(p);
        continue;
      }
      ++refused;
      double nearest = HUGE_VAL;
      for (const Vec3& q : admitted) nearest = std::min(nearest, (q - p).norm());
      CHECK(nearest <= separation);
    }
    CHECK(grid.occupied() == admitted.size());
    // ~64,000 cells in the box for 6,000 points: most admitted, but not all.
    CHECK(refused > 0);
    CHECK(admitted.size() > 3000);
  }
}

TEST_CASE("thinning grid: one point per cell, and points it cannot place are always admitted") {
  refine::ThinningGrid grid(1.0);
  CHECK(grid.admit({0.1, 0.1, 0.1}));
  CHECK_FALSE(grid.admit({0.1, 0.1, 0.1}));       // the same point again
  CHECK_FALSE(grid.admit({0.11, 0.12, 0.13}));    // the same cell (side 1/sqrt(3))
  CHECK(grid.admit({-0.1, 0.1, 0.1}));            // across x = 0
  CHECK(grid.admit({0.1, 0.1, 0.7}));             // the next cell up
  CHECK(grid.occupied() == 3);
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  for (const Vec3& odd : {Vec3(inf, 0, 0), Vec3(0, nan, 0), Vec3(1e300, 0, 0)}) {
    CHECK(grid.admit(odd));
    CHECK(grid.admit(odd));  // never thinned
  }
  CHECK(grid.occupied() == 3);
  // Many cells: the table grows and still tells each cell apart (points near the middles of every
  // other cell along a row far from the first ones, then each moved by 1e-3 inside its cell).
  const double side = 1 / std::sqrt(3.0), middle = 100.5 * side;
  for (int i = 0; i < 5000; ++i) CHECK(grid.admit({(2 * i + 40.5) * side, middle, middle}));
  for (int i = 0; i < 5000; ++i) CHECK_FALSE(grid.admit({(2 * i + 40.5) * side + 1e-3, middle - 1e-3, middle}));
  CHECK(grid.occupied() == 5003);
  // No positive finite separation: nothing is thinned.
  for (const double bad : {0.0, -1.0, inf, nan}) {
    refine::ThinningGrid all(bad);
    CHECK(all.admit({0, 0, 0}));
    CHECK(all.admit({0, 0, 0}));
    CHECK(all.occupied() == 0);
  }
}
