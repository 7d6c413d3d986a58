// refine::densest_crowd (vertex_crowding.h): a dense cluster among evenly spread points is found,
// counted and located; what has no answer (no finite vertex, a bad cell) gives an empty crowd;
// a cell too small for the extent is enlarged instead of overflowing the cube keys.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <delpsc/refine/vertex_crowding.h>

using namespace delpsc;

TEST_CASE("densest_crowd: a cluster among evenly spread points") {
  std::vector<Vec3> points;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      for (int k = 0; k < 10; ++k) points.emplace_back(i + 0.5, j + 0.5, k + 0.5);
  // 500 points within 0.1 of (3, 6, 5): the middle of a cube of side 1 (the cubes start at the
  // box's corner, 0.5), whose grid point is at its lower corner.
  const Vec3 spot(3, 6, 5);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  for (int n = 0; n < 500; ++n) points.push_back(spot + Vec3(jitter(random), jitter(random), jitter(random)));
  const refine::VertexCrowd crowd = refine::densest_crowd(points, 1.0);
  CHECK(crowd.fullest_cube == 501);  // the cluster and the cube's grid point
  CHECK(crowd.vertices == 500 + 27);  // and the 26 neighbouring cubes' grid points
  CHECK((crowd.centre - spot).norm() < 0.1);
  // A NaN vertex is skipped, not counted.
  points.emplace_back(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  CHECK(refine::densest_crowd(points, 1.0).vertices == 527);
}

TEST_CASE("densest_crowd: nothing to find") {
  CHECK(refine::densest_crowd({}, 1.0).vertices == 0);
  const std::vector<Vec3> points{{0, 0, 0}, {1, 1, 1}};
  CHECK(refine::densest_crowd(points, 0.0).vertices == 0);
  CHECK(refine::densest_crowd(points, -1.0).vertices == 0);
  CHECK(refine::densest_crowd(points, std::numeric_limits<double>::quiet_NaN()).vertices == 0);
  const std::vector<Vec3> nan{{std::numeric_limits<double>::quiet_NaN(), 0, 0}};
  CHECK(refine::densest_crowd(nan, 1.0).vertices == 0);
}

TEST_CASE("densest_crowd: a cluster at the box's far corner with a cell far below the extent") {
  // The cell becomes 2^-20 of the extent, so the cluster's cube has index 2^20 along each axis:
  // the largest the 21-bit keys hold. A wrong enlargement would overflow them and find no block.
  std::vector<Vec3> points{{0, 0, 0}, {0.5, 0.25, 0.75}};
  for (int n = 0; n < 5; ++n) points.emplace_back(1, 1, 1);
  const refine::VertexCrowd crowd = refine::densest_crowd(points, 1e-12);
  CHECK(crowd.fullest_cube == 5);
  CHECK(crowd.vertices == 5);
  CHECK((crowd.centre - Vec3(1, 1, 1)).norm() < 1e-12);
  // An extent that overflows to infinity gives no crowd rather than undefined conversions.
  const std::vector<Vec3> huge{{-1.7e308, 0, 0}, {1.7e308, 0, 0}};
  CHECK(refine::densest_crowd(huge, 1.0).vertices == 0);
}

TEST_CASE("densest_crowd: a cell far below the extent is enlarged to fit the keys") {
  // 2^40 cells an axis would not fit 21 bits: the cell grows to 2^-20 of the extent, so the two
  // points near the origin share a cube and the far one is alone.
  const std::vector<Vec3> points{{0, 0, 0}, {1e-9, 0, 0}, {1e3, 1e3, 1e3}};
  const refine::VertexCrowd crowd = refine::densest_crowd(points, 1e-9);
  CHECK(crowd.fullest_cube == 2);
  CHECK(crowd.vertices == 2);
  CHECK(crowd.centre.norm() < 1e-9);
}
