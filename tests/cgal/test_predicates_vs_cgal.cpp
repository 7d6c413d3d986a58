// Our predicates against CGAL's on the same inputs: same signs, same perturbation. This pins our
// sign conventions to CGAL's, which the cell-for-cell triangulation cross-check relies on.
// Built only with -DDELPSC_WITH_CGAL=ON; CGAL is never a dependency of the library.
#include <doctest/doctest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>

#include <array>
#include <delpsc/kernel/predicates.h>
#include <random>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using WP = K::Weighted_point_3;
using P = K::Point_3;
using W4 = std::array<double, 4>;

// Exposes the perturbed tests CGAL keeps protected inside Regular_triangulation_3.
struct ExposedRT : CGAL::Regular_triangulation_3<K> {
  using CGAL::Regular_triangulation_3<K>::side_of_oriented_power_sphere;
  using CGAL::Regular_triangulation_3<K>::side_of_bounded_power_circle;
  using CGAL::Regular_triangulation_3<K>::side_of_bounded_power_segment;
};

WP to_cgal(const W4& p) { return WP(P(p[0], p[1], p[2]), p[3]); }

// Small integer coordinates and weights: ties everywhere, so the perturbation is exercised.
struct Draw {
  std::mt19937_64 rng{12345};
  W4 grid(int range, int wrange) {
    std::uniform_int_distribution<int> c(-range, range), w(0, wrange);
    return {double(c(rng)), double(c(rng)), double(c(rng)), double(w(rng))};
  }
  W4 planar(int range, int wrange) {  // on the plane z = x + 2y
    W4 p = grid(range, wrange);
    p[2] = p[0] + 2 * p[1];
    return p;
  }
  W4 linear(int range, int wrange) {  // on the line (t, 2t, -t), |direction|^2 = 6
    std::uniform_int_distribution<int> c(-range, range), w(0, wrange);
    const double t = c(rng);
    return {t, 2 * t, -t, 6.0 * w(rng)};  // weights in multiples of 6 make ties possible
  }
  W4 uniform() {
    std::uniform_real_distribution<double> c(-1, 1), w(0, 0.1);
    return {c(rng), c(rng), c(rng), w(rng)};
  }
};

}  // namespace

TEST_CASE("orient3d, 5-point power test and its perturbation agree with CGAL") {
  Draw d;
  ExposedRT rt;
  int ties = 0;
  for (int it = 0; it < 200000; ++it) {
    std::array<W4, 5> p;
    for (auto& x : p) x = (it % 3 == 0) ? d.uniform() : d.grid(1 + it % 2, 2);
    const int o = delpsc::kernel::orient3d(p[0].data(), p[1].data(), p[2].data(), p[3].data());
    REQUIRE(o == int(CGAL::orientation(to_cgal(p[0]).point(), to_cgal(p[1]).point(),
                                       to_cgal(p[2]).point(), to_cgal(p[3]).point())));
    const int s = delpsc::kernel::power_test(p[0].data(), p[1].data(), p[2].data(), p[3].data(),
                                             p[4].data());
    REQUIRE(s == int(K().power_side_of_oriented_power_sphere_3_object()(
                     to_cgal(p[0]), to_cgal(p[1]), to_cgal(p[2]), to_cgal(p[3]), to_cgal(p[4]))));
    if (o <= 0) continue;
    bool distinct = true;
    for (int i = 0; i < 4; ++i)
      distinct = distinct && delpsc::kernel::compare_xyz(p[i].data(), p[4].data()) != 0;
    if (!distinct) continue;
    ties += s == 0;
    const int ps = delpsc::kernel::power_test_perturbed(p[0].data(), p[1].data(), p[2].data(),
                                                        p[3].data(), p[4].data());
    REQUIRE(ps == int(rt.side_of_oriented_power_sphere(to_cgal(p[0]), to_cgal(p[1]),
                                                       to_cgal(p[2]), to_cgal(p[3]),
                                                       to_cgal(p[4]), true)));
  }
  CHECK(ties > 1000);  // the tie-break really was exercised
}

TEST_CASE("planar predicates and their perturbation agree with CGAL") {
  Draw d;
  ExposedRT rt;
  int ties = 0;
  for (int it = 0; it < 200000; ++it) {
    std::array<W4, 4> p;
    for (auto& x : p) x = d.planar(2, 2);
    P a = to_cgal(p[0]).point(), b = to_cgal(p[1]).point(), c = to_cgal(p[2]).point(),
      e = to_cgal(p[3]).point();
    const int co = delpsc::kernel::coplanar_orientation(p[0].data(), p[1].data(), p[2].data());
    REQUIRE(co == int(CGAL::coplanar_orientation(a, b, c)));
    if (co == 0) continue;
    REQUIRE(delpsc::kernel::coplanar_orientation(p[0].data(), p[1].data(), p[2].data(),
                                                 p[3].data()) ==
            int(CGAL::coplanar_orientation(a, b, c, e)));
    const int s =
        delpsc::kernel::power_test(p[0].data(), p[1].data(), p[2].data(), p[3].data());
    REQUIRE(s == int(K().power_side_of_oriented_power_sphere_3_object()(
                     to_cgal(p[0]), to_cgal(p[1]), to_cgal(p[2]), to_cgal(p[3]))));
    bool distinct = true;
    for (int i = 0; i < 3; ++i)
      distinct = distinct && delpsc::kernel::compare_xyz(p[i].data(), p[3].data()) != 0;
    if (!distinct) continue;
    ties += s == 0;
    REQUIRE(delpsc::kernel::power_circle_side_perturbed(p[0].data(), p[1].data(), p[2].data(),
                                                        p[3].data()) ==
            int(rt.side_of_bounded_power_circle(to_cgal(p[0]), to_cgal(p[1]), to_cgal(p[2]),
                                                to_cgal(p[3]), true)));
  }
  CHECK(ties > 1000);
}

TEST_CASE("linear predicates and their perturbation agree with CGAL") {
  Draw d;
  ExposedRT rt;
  int ties = 0;
  for (int it = 0; it < 100000; ++it) {
    std::array<W4, 3> p;
    for (auto& x : p) x = d.linear(3, 3);
    if (delpsc::kernel::compare_xyz(p[0].data(), p[1].data()) == 0) continue;
    const int s = delpsc::kernel::power_test(p[0].data(), p[1].data(), p[2].data());
    REQUIRE(s == int(K().power_side_of_oriented_power_sphere_3_object()(
                     to_cgal(p[0]), to_cgal(p[1]), to_cgal(p[2]))));
    if (delpsc::kernel::compare_xyz(p[0].data(), p[2].data()) == 0 ||
        delpsc::kernel::compare_xyz(p[1].data(), p[2].data()) == 0)
      continue;
    ties += s == 0;
    REQUIRE(delpsc::kernel::power_segment_side_perturbed(p[0].data(), p[1].data(), p[2].data()) ==
            int(rt.side_of_bounded_power_segment(to_cgal(p[0]), to_cgal(p[1]), to_cgal(p[2]),
                                                 true)));
  }
  CHECK(ties > 1000);
}
