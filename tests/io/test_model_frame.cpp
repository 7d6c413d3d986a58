#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <delpsc/io/model_frame.h>

using namespace delpsc;

namespace {

/// Random points in a box of the given size whose lower corner is `corner`, with full-precision
/// coordinates (every bit of the double used), as a model read from a file has.
std::vector<Vec3> points_at(const Vec3& corner, double size, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, size);
  std::vector<Vec3> points;
  for (int i = 0; i < 500; ++i) points.push_back(corner + Vec3(u(rng), u(rng), u(rng)));
  return points;
}

}  // namespace

TEST_CASE("a model far from the origin moves next to it exactly, and back") {
  for (const Vec3& corner : {Vec3(1e9, 2e9, -3e9), Vec3(5e6, 3.2e5, 1.7e7), Vec3(-4e12, -1e3, 7e15)}) {
    const std::vector<Vec3> original = points_at(corner, 1.5, 7);
    std::vector<Vec3> moved = original;
    const Vec3 offset = io::move_near_origin(moved);
    CAPTURE(corner);
    CHECK(offset.allFinite());
    for (int k = 0; k < 3; ++k) CHECK(std::fabs(offset[k] - corner[k]) <= 1.5 + 1e-6 * std::fabs(corner[k]));
    // Exact: every difference of two moved points is the difference of the originals, and the
    // offset added back restores each coordinate bit for bit.
    for (std::size_t i = 0; i < moved.size(); ++i) {
      CHECK(moved[i].cwiseAbs().maxCoeff() <= 1.5 + 4e-16 * corner.cwiseAbs().maxCoeff() + 1e-9);  // ulps of corner
      CHECK((moved[i] + offset) == original[i]);
      CHECK((moved[i] - moved[0]) == (original[i] - original[0]));
    }
    std::vector<Vec3> back = moved;
    io::move_by(back, offset);
    CHECK(back == original);
  }
}

TEST_CASE("a model near the origin, or whose axis cannot move exactly, stays where it is") {
  // Straddling the origin; near it (a corner 10 sizes away, below the 16 of kFarFromOriginRatio);
  // far on one axis only.
  std::vector<Vec3> straddling = points_at(Vec3(-0.5, -0.5, -0.5), 1, 1);
  const std::vector<Vec3> straddling_before = straddling;
  CHECK(io::move_near_origin(straddling) == Vec3::Zero());
  CHECK(straddling == straddling_before);

  std::vector<Vec3> near = points_at(Vec3(10, 10, 10), 1, 2);
  CHECK(io::move_near_origin(near) == Vec3::Zero());

  std::vector<Vec3> one_axis = points_at(Vec3(0, 1e8, 0), 1, 3);
  const Vec3 offset = io::move_near_origin(one_axis);
  CHECK(offset.x() == 0);
  CHECK(offset.z() == 0);
  CHECK(offset.y() >= 1e8);
  CHECK(offset.y() <= 1e8 + 1);

  // An axis as long as its distance from the origin: subtracting its bound could round (3e8 - 1e8
  // is not within a factor of two), and it is no farther than the model's size, so it stays.
  std::vector<Vec3> wide{Vec3(1e8, 0, 0), Vec3(3e8, 1, 1)};
  CHECK(io::move_near_origin(wide) == Vec3::Zero());
  CHECK(wide[1] == Vec3(3e8, 1, 1));
}

TEST_CASE("an empty or non-finite point set is left alone") {
  std::vector<Vec3> none;
  CHECK(io::move_near_origin(none) == Vec3::Zero());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Vec3> bad{Vec3(1e9, 1e9, 1e9), Vec3(nan, 1e9, 1e9)};
  CHECK(io::move_near_origin(bad) == Vec3::Zero());
  CHECK(bad[0] == Vec3(1e9, 1e9, 1e9));
}
