// Geometric meaning of the predicates' signs on hand-made configurations, and the exact path on
// inputs the filter cannot decide. (The million-input comparison with GMP is tests/oracle.)
#include <doctest/doctest.h>

#include <cmath>
#include <delpsc/kernel/predicates.h>

using namespace delpsc;
using namespace delpsc::kernel;

namespace {
const double O[4] = {0, 0, 0, 0}, X[4] = {1, 0, 0, 0}, Y[4] = {0, 1, 0, 0}, Z[4] = {0, 0, 1, 0};
}

TEST_CASE("orient3d sign follows the right-hand rule and flips with a swap") {
  const double above[3] = {0.2, 0.2, 5}, below[3] = {0.2, 0.2, -5}, in[3] = {0.3, 0.3, 0};
  CHECK(orient3d(O, X, Y, Z) == 1);
  CHECK(orient3d(X, O, Y, Z) == -1);
  CHECK(orient3d(O, X, Y, above) == 1);
  CHECK(orient3d(O, X, Y, below) == -1);
  CHECK(orient3d(O, X, Y, in) == 0);
}

TEST_CASE("orient3d is exact where doubles round to the wrong sign") {
  // d lies a few ulps off the plane through a, b, c; the naive determinant misjudges many of
  // these, the predicate must agree with the sign of the offset.
  const double a[3] = {0.1, 0.1, 0.1}, b[3] = {0.7, 0.3, 0.1}, c[3] = {0.2, 0.9, 0.1};
  for (int k = -4; k <= 4; ++k) {
    double d[3] = {0.33, 0.47, 0.1};
    for (int s = 0; s < std::abs(k); ++s) d[2] = std::nextafter(d[2], k > 0 ? 1.0 : -1.0);
    CHECK(orient3d(a, b, c, d) == (k > 0) - (k < 0));
  }
}

TEST_CASE("insphere: inside is positive for a positively oriented tetrahedron") {
  const double centre[3] = {0.25, 0.25, 0.25}, far[3] = {3, 3, 3}, on[3] = {1, 1, 1};
  REQUIRE(orient3d(O, X, Y, Z) == 1);
  CHECK(insphere(O, X, Y, Z, centre) == 1);
  CHECK(insphere(O, X, Y, Z, far) == -1);
  CHECK(insphere(O, X, Y, Z, on) == 0);  // (1,1,1) is on the sphere through O, X, Y, Z
  CHECK(insphere(X, O, Y, Z, centre) == -1);
}

TEST_CASE("power_test: a heavy point is in conflict, zero weights agree with insphere") {
  const double t_far[4] = {3, 3, 3, 0}, t_heavy[4] = {3, 3, 3, 100}, on[4] = {1, 1, 1, 0};
  CHECK(power_test(O, X, Y, Z, t_far) == -1);
  CHECK(power_test(O, X, Y, Z, t_heavy) == 1);
  CHECK(power_test(O, X, Y, Z, on) == insphere(O, X, Y, Z, on));
  // Raising the four weights by 1 keeps the centre and lowers the orthosphere's squared radius
  // from 3/4 to -1/4: (1,1,1) now has power product 3/4 + 1/4 > 0 with it, no conflict; a point
  // of weight 1 there is exactly orthogonal to it, one of weight 2 is in conflict.
  const double a[4] = {0, 0, 0, 1}, b[4] = {1, 0, 0, 1}, c[4] = {0, 1, 0, 1}, d[4] = {0, 0, 1, 1};
  const double orthogonal[4] = {1, 1, 1, 1}, heavy[4] = {1, 1, 1, 2};
  CHECK(power_test(a, b, c, d, on) == -1);
  CHECK(power_test(a, b, c, d, orthogonal) == 0);
  CHECK(power_test(a, b, c, d, heavy) == 1);
}

TEST_CASE("lower-dimensional power tests do not depend on the order of the defining points") {
  const double p[4] = {0, 0, 0, 0}, q[4] = {2, 0, 0, 0}, r[4] = {0, 2, 0, 0};
  const double inside[4] = {0.5, 0.5, 0, 0}, outside[4] = {5, 5, 0, 0};
  CHECK(power_test(p, q, r, inside) == 1);
  CHECK(power_test(q, p, r, inside) == 1);
  CHECK(power_test(p, q, r, outside) == -1);
  const double mid[4] = {1, 0, 0, 0}, beyond[4] = {7, 0, 0, 0};
  CHECK(power_test(p, q, mid) == 1);
  CHECK(power_test(q, p, mid) == 1);
  CHECK(power_test(p, q, beyond) == -1);
  const double light[4] = {0, 0, 0, 1}, heavy[4] = {0, 0, 0, 2};
  CHECK(power_test(light, heavy) == 1);
  CHECK(power_test(heavy, light) == -1);
  CHECK(power_test(light, light) == 0);
}

TEST_CASE("coplanar orientation falls back to other projections for vertical planes") {
  const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 0, 1}, d[3] = {1, 0, 1};
  CHECK(coplanar_orientation(a, b, c) != 0);
  CHECK(coplanar_orientation(a, b, c, d) == 1);
  const double e[3] = {0.5, 0, -1};
  CHECK(coplanar_orientation(a, b, c, e) == -1);
  CHECK(collinear(a, b, b));
  const double f[3] = {3, 0, 0};
  CHECK(collinear(a, b, f));
}

TEST_CASE("power distance predicates") {
  const double ball[4] = {0, 0, 0, 4};  // radius 2
  const double in[3] = {1, 1, 1}, out[3] = {2, 2, 0}, on[3] = {0, 2, 0};
  CHECK(power_distance_sign(in, ball) == -1);
  CHECK(power_distance_sign(out, ball) == 1);
  CHECK(power_distance_sign(on, ball) == 0);
  const double other[4] = {4, 0, 0, 0};
  const double x[3] = {2, 0, 0};
  CHECK(compare_power_distance(x, ball, other) == -1);  // 4-4=0 vs 4
  CHECK(compare_power_distance(x, other, ball) == 1);
}

TEST_CASE("perturbed tests never return zero and break cospherical ties") {
  const double on[4] = {1, 1, 1, 0};
  const int s = power_test_perturbed(O, X, Y, Z, on);
  CHECK((s == 1 || s == -1));
  CHECK(insphere_perturbed(O, X, Y, Z, on) == s);
  // Same five points, two of the sphere points swapped and the orientation restored: same answer.
  CHECK(power_test_perturbed(O, X, Z, Y, on) != 0);
  // p, q of weight 1: orthosphere centre (1,0,0), squared radius 0.
  const double p[4] = {0, 0, 0, 1}, q[4] = {2, 0, 0, 1}, mid[4] = {1, 0, 0, 0};  // orthogonal
  REQUIRE(power_test(p, q, mid) == 0);
  CHECK(power_segment_side_perturbed(p, q, mid) == 1);
  const double beyond[4] = {3, 0, 0, 4};  // also orthogonal: (3-1)^2 - 4 - 0 = 0
  REQUIRE(power_test(p, q, beyond) == 0);
  CHECK(power_segment_side_perturbed(p, q, beyond) == -1);
}
