// The oracle checked on its own, against values computed by hand, before it judges the kernel.
// Each case is also replayed after scaling by 2^k (weights by 2^2k) for extreme k, which
// exercises the oracle's conversion of doubles to integers.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "support/generators.h"
#include "support/oracle.h"

namespace oracle = delpsc::test::oracle;
using delpsc::WeightedPoint;
using delpsc::test::scale_pow2;

namespace {

WeightedPoint P(double x, double y, double z, double w = 0) { return {x, y, z, w}; }

// Runs check(points) on the points as given and scaled by 2^k for a few k in range.
template <class Check>
void at_every_scale(std::vector<WeightedPoint> pts, Check check) {
  for (const int k : {0, -130, -77, 1, 63, 120}) {
    std::vector<WeightedPoint> s = pts;
    scale_pow2(s, k);
    CAPTURE(k);
    check(s);
  }
}

}  // namespace

TEST_CASE("oracle orient3d, orient2d and coplanar orientations on hand-made cases") {
  at_every_scale({P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(0, 0, 1), P(3, 7, 0), P(2, 5, 0)},
                 [](const std::vector<WeightedPoint>& p) {
                   const double *o = p[0].data(), *x = p[1].data(), *y = p[2].data(),
                                *z = p[3].data(), *a = p[4].data(), *b = p[5].data();
                   CHECK(oracle::orient3d(o, x, y, z) == 1);  // det I = 1
                   CHECK(oracle::orient3d(x, o, y, z) == -1);
                   CHECK(oracle::orient3d(o, x, y, a) == 0);  // a in the plane z = 0
                   CHECK(oracle::orient2d(o, x, y, 0, 1) == 1);
                   CHECK(oracle::orient2d(o, x, y, 1, 0) == -1);
                   CHECK(oracle::orient2d(o, x, z, 0, 1) == 0);  // z projects onto o
                   // (3,7)-(0,0) x (2,5)-(0,0) = 15 - 14 = 1.
                   CHECK(oracle::orient2d(o, a, b, 0, 1) == 1);
                   CHECK(oracle::coplanar_orientation(o, x, y) == 1);
                   CHECK(oracle::coplanar_orientation(o, y, x) == -1);
                   // Plane x = 0: xy collinear, yz decides: (0,0),(1,0),(0,1) -> +1.
                   CHECK(oracle::coplanar_orientation(o, y, z) == 1);
                   // Plane y = 0: xy and yz collinear, xz decides: (0,0),(1,0),(0,1) -> +1.
                   CHECK(oracle::coplanar_orientation(o, x, z) == 1);
                   CHECK(oracle::coplanar_orientation(o, z, x) == -1);
                   CHECK(oracle::coplanar_orientation(o, x, a) == 1);
                   CHECK_FALSE(oracle::collinear(o, x, y));
                 });
  at_every_scale({P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(5, -1, 0), P(7, 0, 0), P(3, 2, 0),
                  P(2, 4, 6)},
                 [](const std::vector<WeightedPoint>& p) {
                   const double *o = p[0].data(), *x = p[1].data(), *y = p[2].data();
                   CHECK(oracle::coplanar_orientation(o, x, y, p[3].data()) == -1);
                   CHECK(oracle::coplanar_orientation(o, x, y, p[4].data()) == 0);
                   CHECK(oracle::coplanar_orientation(o, x, y, p[5].data()) == 1);
                   CHECK(oracle::collinear(o, x, p[4].data()));
                   CHECK(oracle::collinear(o, p[6].data(), p[6].data()));
                   CHECK(oracle::compare_xyz(o, x) == -1);
                   CHECK(oracle::compare_xyz(p[4].data(), p[3].data()) == 1);
                   CHECK(oracle::compare_xyz(y, y) == 0);
                 });
}

TEST_CASE("oracle orient3d is exact across magnitudes") {
  // det[(1,0,0); (0,1,0); (2^60, 2^60, 2^-100)] = 2^-100 > 0: huge and tiny in one determinant.
  const double o[3] = {0, 0, 0}, x[3] = {1, 0, 0}, y[3] = {0, 1, 0};
  const double s[3] = {0x1p60, 0x1p60, 0x1p-100}, t[3] = {0x1p60, 0x1p60, -0x1p-100};
  CHECK(oracle::orient3d(o, x, y, s) == 1);
  CHECK(oracle::orient3d(o, x, y, t) == -1);
  // 0.1 is not dyadic-simple, but the translated determinant is still (0.1)^3 exactly in binary.
  const double a[3] = {0.1, 0, 0}, b[3] = {0, 0.1, 0}, c[3] = {0, 0, 0.1};
  CHECK(oracle::orient3d(o, a, b, c) == 1);
}

TEST_CASE("oracle insphere and 5-point power test on hand-made cases") {
  // Unit tetrahedron O, X, Y, Z (positively oriented): circumcentre (1/2,1/2,1/2), r^2 = 3/4.
  at_every_scale({P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(0, 0, 1), P(0.25, 0.25, 0.25),
                  P(3, 3, 3), P(1, 1, 1), P(0, 1, 1)},
                 [](const std::vector<WeightedPoint>& p) {
                   const double *o = p[0].data(), *x = p[1].data(), *y = p[2].data(),
                                *z = p[3].data();
                   CHECK(oracle::insphere(o, x, y, z, p[4].data()) == 1);   // inside
                   CHECK(oracle::insphere(o, x, y, z, p[5].data()) == -1);  // outside
                   CHECK(oracle::insphere(o, x, y, z, p[6].data()) == 0);   // on it
                   CHECK(oracle::insphere(x, o, y, z, p[4].data()) == -1);  // orientation flips
                   CHECK(oracle::insphere(o, x, y, z, p[7].data()) == 0);
                 });
  // Weights 1 on O, X, Y, Z keep the centre and make the orthosphere's squared radius
  // 3/4 - 1 = -1/4; (1,1,1) with weight w has power product 3/4 + 1/4 - w with it.
  at_every_scale({P(0, 0, 0, 1), P(1, 0, 0, 1), P(0, 1, 0, 1), P(0, 0, 1, 1), P(1, 1, 1, 0),
                  P(1, 1, 1, 1), P(1, 1, 1, 2)},
                 [](const std::vector<WeightedPoint>& p) {
                   const double *a = p[0].data(), *b = p[1].data(), *c = p[2].data(),
                                *d = p[3].data();
                   CHECK(oracle::power_test(a, b, c, d, p[4].data()) == -1);
                   CHECK(oracle::power_test(a, b, c, d, p[5].data()) == 0);
                   CHECK(oracle::power_test(a, b, c, d, p[6].data()) == 1);
                   CHECK(oracle::power_test(b, a, c, d, p[6].data()) == -1);
                 });
}

TEST_CASE("oracle lower-dimensional power tests on hand-made cases") {
  // Circle through (0,0), (2,0), (0,2): centre (1,1), r^2 = 2, in the planes z = 0, x = 0, y = 0
  // (the xy, yz and xz projections decide). (3,3) with weight w: power 8 - 2 - w.
  for (const int plane : {2, 0, 1}) {
    auto in_plane = [plane](double u, double v, double w) {
      double c[3] = {0, 0, 0};
      const int iu = plane == 0 ? 1 : 0, iv = plane == 2 ? 1 : 2;
      c[iu] = u;
      c[iv] = v;
      return P(c[0], c[1], c[2], w);
    };
    CAPTURE(plane);
    at_every_scale({in_plane(0, 0, 0), in_plane(2, 0, 0), in_plane(0, 2, 0), in_plane(1, 1, 0),
                    in_plane(3, 3, 0), in_plane(2, 2, 0), in_plane(3, 3, 6), in_plane(3, 3, 7)},
                   [](const std::vector<WeightedPoint>& p) {
                     const double *a = p[0].data(), *b = p[1].data(), *c = p[2].data();
                     CHECK(oracle::power_test(a, b, c, p[3].data()) == 1);
                     CHECK(oracle::power_test(a, c, b, p[3].data()) == 1);  // no orientation
                     CHECK(oracle::power_test(a, b, c, p[4].data()) == -1);
                     CHECK(oracle::power_test(a, b, c, p[5].data()) == 0);
                     CHECK(oracle::power_test(a, b, c, p[6].data()) == 0);
                     CHECK(oracle::power_test(a, b, c, p[7].data()) == 1);
                   });
  }
  // Segment (0,0,0)-(2,0,0): centre 1, r^2 = 1; t = 3 with weight w: power 4 - 1 - w.
  for (const int axis : {0, 1, 2}) {
    auto on_axis = [axis](double s, double w) {
      double c[3] = {0, 0, 0};
      c[axis] = s;
      return P(c[0], c[1], c[2], w);
    };
    CAPTURE(axis);
    at_every_scale({on_axis(0, 0), on_axis(2, 0), on_axis(1, 0), on_axis(3, 3), on_axis(3, 4),
                    on_axis(3, 2)},
                   [](const std::vector<WeightedPoint>& p) {
                     const double *a = p[0].data(), *b = p[1].data();
                     CHECK(oracle::power_test(a, b, p[2].data()) == 1);
                     CHECK(oracle::power_test(b, a, p[2].data()) == 1);
                     CHECK(oracle::power_test(a, b, p[3].data()) == 0);
                     CHECK(oracle::power_test(a, b, p[4].data()) == 1);
                     CHECK(oracle::power_test(a, b, p[5].data()) == -1);
                   });
  }
  at_every_scale({P(1, 2, 3, 5), P(1, 2, 3, 7), P(1, 2, 3, 5)},
                 [](const std::vector<WeightedPoint>& p) {
                   CHECK(oracle::power_test(p[0].data(), p[1].data()) == 1);
                   CHECK(oracle::power_test(p[1].data(), p[0].data()) == -1);
                   CHECK(oracle::power_test(p[0].data(), p[2].data()) == 0);
                 });
}

TEST_CASE("oracle power distances on hand-made cases") {
  at_every_scale({P(3, 4, 0), P(0, 0, 0, 25), P(0, 0, 0, 24), P(0, 0, 0, 26)},
                 [](const std::vector<WeightedPoint>& p) {
                   CHECK(oracle::power_distance_sign(p[0].data(), p[1].data()) == 0);
                   CHECK(oracle::power_distance_sign(p[0].data(), p[2].data()) == 1);
                   CHECK(oracle::power_distance_sign(p[0].data(), p[3].data()) == -1);
                 });
  // pow(0, (1,0,0; 0)) = 1, pow(0, (0,2,0; 3)) = 1, pow(0, (0,2,0; 2)) = 2.
  at_every_scale({P(0, 0, 0), P(1, 0, 0, 0), P(0, 2, 0, 3), P(0, 2, 0, 2)},
                 [](const std::vector<WeightedPoint>& p) {
                   CHECK(oracle::compare_power_distance(p[0].data(), p[1].data(), p[2].data()) == 0);
                   CHECK(oracle::compare_power_distance(p[0].data(), p[1].data(), p[3].data()) == -1);
                   CHECK(oracle::compare_power_distance(p[0].data(), p[3].data(), p[1].data()) == 1);
                 });
}

TEST_CASE("perturbed oracle on hand-expanded determinants") {
  SUBCASE("segment, t strictly between p and q") {
    // Ranks p 0, t 1, q 2 -> eps^3, eps^2, eps^1 on the lifts. Rows [x, |x|^2 - w + eps^e, 1]:
    // p [0, eps^3, 1], q [2, 4 + eps, 1], t [1, 2 + eps^2, 1] (w_t = -1);
    // det = -eps + 2 eps^2 - eps^3: first coefficient -1 (eps^1), times sign(p_x - q_x) = -1.
    const double p[4] = {0, 0, 0, 0}, q[4] = {2, 0, 0, 0}, t[4] = {1, 0, 0, -1};
    REQUIRE(oracle::power_test(p, q, t) == 0);
    const auto r = oracle::power_segment_side_perturbed(p, q, t);
    CHECK(r.sign == 1);
    CHECK(r.eps_power == 1);
    CHECK(oracle::power_segment_side_perturbed(q, p, t).sign == 1);
    // t beyond q, on the boundary (power 4 - 1 - 3 = 0): t is the largest point, its own term
    // is -(q_x - p_x) eps = -2 eps, times sign(p_x - q_x): outside.
    const double beyond[4] = {3, 0, 0, 3};
    REQUIRE(oracle::power_test(p, q, beyond) == 0);
    CHECK(oracle::power_segment_side_perturbed(p, q, beyond).sign == -1);
    CHECK(oracle::power_segment_side_perturbed(p, q, beyond).eps_power == 1);
  }
  SUBCASE("insphere: the largest point's term, then a deeper one when it vanishes") {
    const double o[3] = {0, 0, 0}, x[3] = {1, 0, 0}, y[3] = {0, 1, 0}, z[3] = {0, 0, 1};
    const double t1[3] = {1, 1, 1}, t2[3] = {0, 1, 1};
    REQUIRE(oracle::insphere(o, x, y, z, t1) == 0);
    REQUIRE(oracle::insphere(o, x, y, z, t2) == 0);
    // t1 is the largest: its cofactor is orient3d(o,x,y,z) = 1 in -det: outside, eps^1.
    CHECK(oracle::insphere_perturbed(o, x, y, z, t1).sign == -1);
    CHECK(oracle::insphere_perturbed(o, x, y, z, t1).eps_power == 1);
    // Order o < z < y < t2 < x: x is the largest, but its cofactor (o, y, z, t2 all in the plane
    // x = 0) vanishes; t2 comes next: outside, at eps^2.
    CHECK(oracle::insphere_perturbed(o, x, y, z, t2).sign == -1);
    CHECK(oracle::insphere_perturbed(o, x, y, z, t2).eps_power == 2);
  }
  SUBCASE("circle: the largest point r decides, t on the side of r") {
    // p (0,0) < t (0,2) < q (2,0) < r (2,2), concyclic. r's cofactor is orient(p, q, t) = +1,
    // times orient(p, q, r) = +1: conflict.
    const double p[4] = {0, 0, 0, 0}, q[4] = {2, 0, 0, 0}, r[4] = {2, 2, 0, 0}, t[4] = {0, 2, 0, 0};
    REQUIRE(oracle::power_test(p, q, r, t) == 0);
    const auto s = oracle::power_circle_side_perturbed(p, q, r, t);
    CHECK(s.sign == 1);
    CHECK(s.eps_power == 1);
    CHECK(oracle::power_circle_side_perturbed(q, p, r, t).sign == 1);  // any orientation
    // t largest: outside.
    const double p2[4] = {0, 0, 0, 0}, r2[4] = {0, 2, 0, 0}, t2[4] = {2, 2, 0, 0};
    CHECK(oracle::power_circle_side_perturbed(p2, q, r2, t2).sign == -1);
  }
}

TEST_CASE("perturbed oracles reduce to the plain oracles when these are not zero") {
  delpsc::test::Rng rng(7);
  int checked = 0;
  for (int n = 0; n < 2000; ++n) {
    auto pts = delpsc::test::uniform_points(rng, 5, -1, 1, -0.5, 0.5);
    const double *p = pts[0].data(), *q = pts[1].data(), *r = pts[2].data(), *s = pts[3].data(),
                 *t = pts[4].data();
    const int plain = oracle::power_test(p, q, r, s, t);
    const auto pert = oracle::power_test_perturbed(p, q, r, s, t);
    CHECK(pert.eps_power == 0);
    CHECK(pert.sign == plain);
    CHECK(oracle::insphere_perturbed(p, q, r, s, t).sign == oracle::insphere(p, q, r, s, t));
    // Planar and linear versions on the points projected to z = 0 and to the x-axis.
    WeightedPoint a = pts[0], b = pts[1], c = pts[2], d = pts[3];
    a.z = b.z = c.z = d.z = 0;
    CHECK(oracle::power_circle_side_perturbed(a.data(), b.data(), c.data(), d.data()).sign ==
          oracle::power_test(a.data(), b.data(), c.data(), d.data()));
    a.y = b.y = c.y = 0;
    CHECK(oracle::power_segment_side_perturbed(a.data(), b.data(), c.data()).sign ==
          oracle::power_test(a.data(), b.data(), c.data()));
    ++checked;
  }
  CHECK(checked == 2000);
}
