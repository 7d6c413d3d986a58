#include <doctest/doctest.h>

#include <cmath>
#include <delpsc/io/point_generators.h>
#include <set>
#include <stdexcept>
#include <tuple>

using namespace delpsc;

TEST_CASE("generators are deterministic per seed and respect their ranges") {
  const auto a = io::generate_points("weighted:1000", 7), b = io::generate_points("weighted:1000", 7);
  const auto c = io::generate_points("weighted:1000", 8);
  CHECK(a == b);
  CHECK(a != c);
  const double wmax = std::pow(0.1 * std::cbrt(1e-3), 2);
  for (const auto& p : a) {
    CHECK((p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1 && p.z >= 0 && p.z < 1));
    CHECK((p.w >= 0 && p.w < wmax));
  }
  for (const auto& p : io::generate_points("sphere:500", 1))
    CHECK(std::fabs(p.x * p.x + p.y * p.y + p.z * p.z - 1) < 1e-15);
}

TEST_CASE("the grid generator gives every grid point once, exactly") {
  const auto g = io::generate_points("grid:30", 3);  // side 3
  REQUIRE(g.size() == 27);
  std::set<std::tuple<double, double, double>> seen;
  for (const auto& p : g) {
    CHECK((p.x == std::floor(p.x) && p.x >= 0 && p.x <= 2));
    seen.insert({p.x, p.y, p.z});
  }
  CHECK(seen.size() == 27);
  CHECK(io::generate_points("grid:64", 1).size() == 64);
}

TEST_CASE("bad generator specifications are refused with a reason") {
  CHECK_THROWS_AS(io::generate_points("uniform", 1), std::invalid_argument);
  CHECK_THROWS_AS(io::generate_points("uniform:-3", 1), std::invalid_argument);
  CHECK_THROWS_AS(io::generate_points("uniform:12x", 1), std::invalid_argument);
  CHECK_THROWS_AS(io::generate_points("cube:10", 1), std::invalid_argument);
}
