// Each middle stage of the exact power test, wherever it decides, must agree with exact
// expansion arithmetic; and on the inputs each stage exists for, it must decide.
#include <doctest/doctest.h>

#include <cmath>
#include <delpsc/kernel/power_test_stages.h>
#include <random>

using namespace delpsc::kernel::detail;

namespace {

struct Case {
  double p[5][4];
  const double* pts[4];
  Case() {
    for (int i = 0; i < 4; ++i) pts[i] = p[i];
  }
};

// Integer points in [-range, range]^3 with integer weights; range near the stage's 2^20 limit
// makes some differences exceed it, which must send the input on, not give a wrong answer.
Case integer_case(std::mt19937_64& rng, long range, long wrange) {
  Case c;
  std::uniform_int_distribution<long> coord(-range, range), weight(0, wrange);
  for (auto& p : c.p) {
    for (int k = 0; k < 3; ++k) p[k] = double(coord(rng));
    p[3] = double(weight(rng));
  }
  return c;
}

// Points rounded onto the unit sphere: the double filter fails on nearly all of these.
Case sphere_case(std::mt19937_64& rng) {
  Case c;
  std::normal_distribution<double> g;
  for (auto& p : c.p) {
    double v[3] = {g(rng), g(rng), g(rng)};
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; ++k) p[k] = v[k] / n;
    p[3] = 0;
  }
  return c;
}

}  // namespace

TEST_CASE("integer stage: exact on small integers, declines beyond its limits") {
  std::mt19937_64 rng(3);
  int decided = 0, zeros = 0;
  for (int it = 0; it < 100000; ++it) {
    const long range = (it % 3 == 0) ? 2 : (it % 3 == 1) ? 1000 : (1L << 20);
    Case c = integer_case(rng, range, it % 2 ? 3 : (1L << 40));
    const bool weighted = it % 4 != 0;
    const int v = power_test_integer(c.pts, c.p[4], weighted);
    if (v == 2) continue;
    ++decided;
    zeros += v == 0;
    REQUIRE(v == power_test_expansion(c.pts, c.p[4], weighted));
  }
  CHECK(decided > 50000);
  CHECK(zeros > 1000);
  // Non-integers are declined.
  Case c = integer_case(rng, 5, 0);
  c.p[2][1] += 0.5;
  CHECK(power_test_integer(c.pts, c.p[4], false) == 2);
}

TEST_CASE("double-double stage agrees with exact arithmetic and decides near-cospherical input") {
  std::mt19937_64 rng(4);
  int decided = 0;
  const int n = 100000;
  for (int it = 0; it < n; ++it) {
    Case c = sphere_case(rng);
    const int v = power_test_double_double(c.pts, c.p[4], false);
    if (v == 2) continue;
    ++decided;
    REQUIRE(v == power_test_expansion(c.pts, c.p[4], false));
  }
  CHECK(decided > n * 99 / 100);
  // Exactly degenerate input (lattice points on a sphere, scaled so differences are inexact) is
  // never decided by a floating-point stage.
  const double s = 0.1;
  Case e;
  const double lattice[5][3] = {{3, 4, 0}, {0, 3, 4}, {4, 0, 3}, {-3, 0, 4}, {0, -4, -3}};
  for (int i = 0; i < 5; ++i) {
    for (int k = 0; k < 3; ++k) e.p[i][k] = lattice[i][k] * s + 0.3;
    e.p[i][3] = 0;
  }
  const int exact = power_test_expansion(e.pts, e.p[4], false);
  const int v = power_test_double_double(e.pts, e.p[4], false);
  CHECK((v == 2 || v == exact));
}
