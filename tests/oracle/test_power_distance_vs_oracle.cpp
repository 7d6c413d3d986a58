// power_distance_sign and compare_power_distance against the GMP oracle, at least one million
// inputs each (tests/oracle/oracle_harness.h). Case layout: point 0 is the unweighted x, points
// 1 (and 2) the weighted ones.
#include <doctest/doctest.h>

#include <delpsc/kernel/predicates.h>

#include "oracle_families.h"
#include "support/oracle.h"

namespace kernel = delpsc::kernel;
namespace oracle = delpsc::test::oracle;
using namespace delpsc::test;
using namespace delpsc::test::configs;
using delpsc::WeightedPoint;

namespace {

WeightedPoint dyadic_point(Rng& rng) {
  WeightedPoint p;
  for (int a = 0; a < 3; ++a) p.data()[a] = std::ldexp(static_cast<double>(rng.integer(-4096, 4096)), -10);
  return p;
}

// x and c with w_c = |x - c|^2 - r2 exact: x on the sphere (c, w_c) when r2 = 0.
bool on_sphere(Rng& rng, Points& p, bool dyadic) {
  p.assign(2, WeightedPoint{});
  p[0] = dyadic ? dyadic_point(rng) : random_integer_vector(rng, 1 << 20);
  p[1] = dyadic ? dyadic_point(rng) : random_integer_vector(rng, 1 << 20);
  const auto w = orthogonal_weight(p[1], p[0].data(), 0);
  if (!w) return false;
  p[1].w = *w;
  p[0].w = 0;
  maybe_translate(rng, p);
  return true;
}

// x = c + s with s a lattice point of a sphere of squared radius R^2 = w_c.
bool on_lattice_sphere(Rng& rng, Points& p) {
  const auto& spheres = lattice_spheres();
  const Points& s = spheres[rng.index(spheres.size())];
  const WeightedPoint d = s[rng.index(s.size())];
  const WeightedPoint c = random_integer_vector(rng, 1 << 30);
  p = {{c.x + d.x, c.y + d.y, c.z + d.z, 0}, {c.x, c.y, c.z, d.x * d.x + d.y * d.y + d.z * d.z}};
  return true;
}

// A point c of magnitude ~2^ec and x = c + 2^ex v with ex up to 40 below ec; w_c = |x - c|^2.
// All exact; the magnitudes in one input differ by up to 2^40 (coordinates) and 2^80 (weight
// against squared coordinates).
Points offset_pair(Rng& rng, int& ex) {
  const int ec = static_cast<int>(rng.integer(-90, 120));
  ex = ec - static_cast<int>(rng.integer(0, 40));
  const WeightedPoint u = random_integer_vector(rng, 255), v = random_integer_vector(rng, 255);
  WeightedPoint c{std::ldexp(u.x, ec), std::ldexp(u.y, ec), std::ldexp(u.z, ec), 0};
  WeightedPoint x{c.x + std::ldexp(v.x, ex), c.y + std::ldexp(v.y, ex), c.z + std::ldexp(v.z, ex), 0};
  c.w = std::ldexp(v.x * v.x + v.y * v.y + v.z * v.z, 2 * ex);
  return {x, c};
}

// x, p, q with w_p = |x - p|^2 - K and w_q = |x - q|^2 - K: equal power distances K.
bool equal_powers(Rng& rng, Points& p, bool dyadic) {
  p.assign(3, WeightedPoint{});
  for (auto& q : p) q = dyadic ? dyadic_point(rng) : random_integer_vector(rng, 1 << 16);
  const double k = dyadic ? std::ldexp(static_cast<double>(rng.integer(-(1 << 20), 1 << 20)), -12)
                          : static_cast<double>(rng.integer(-(1 << 20), 1 << 20));
  for (int i = 1; i < 3; ++i) {
    const auto w = orthogonal_weight(p[i], p[0].data(), k);
    if (!w) return false;
    p[i].w = *w;
  }
  maybe_translate(rng, p);
  return true;
}

// Equal weights; q is p reflected through a coordinate plane through x or with two of its
// offsets from x swapped, so |x - p| = |x - q|.
bool mirrored(Rng& rng, Points& p) {
  const WeightedPoint x = random_integer_vector(rng, 1 << 20);
  const WeightedPoint d = random_integer_vector(rng, 1 << 16);
  WeightedPoint e = d;
  if (rng.chance(0.5)) {
    e.data()[rng.integer(0, 2)] *= -1;
  } else {
    const int a = static_cast<int>(rng.integer(0, 2));
    std::swap(e.data()[a], e.data()[(a + 1) % 3]);
  }
  const double w = static_cast<double>(rng.integer(-(1 << 20), 1 << 20));
  p = {x, {x.x + d.x, x.y + d.y, x.z + d.z, w}, {x.x + e.x, x.y + e.y, x.z + e.z, w}};
  maybe_translate(rng, p);
  return true;
}

}  // namespace

TEST_CASE("power_distance_sign agrees with the exact oracle") {
  auto integer = maybe([](Rng& rng, Points& p) { return on_sphere(rng, p, false); });
  auto mixed_offset = always([](Rng& rng) {
    int ex = 0;
    return offset_pair(rng, ex);
  });
  const std::vector<Family> families = {
      {"uniform", "x, c in [-1,1]^3, w in [0,1]", 275'000, kGeneric,
       always([](Rng& rng) {
         Points p = uniform_points(rng, 2, -1, 1, 0, 1);
         p[0].w = 0;
         return p;
       })},
      {"degenerate", "integers, w = |x - c|^2", 150'000, kDegenerate, integer},
      {"degenerate", "lattice sphere around c, w = R^2", 50'000, kDegenerate,
       maybe(on_lattice_sphere)},
      {"degenerate", "dyadic, w = |x - c|^2", 50'000, kDegenerate,
       maybe([](Rng& rng, Points& p) { return on_sphere(rng, p, true); })},
      {"near-degenerate", "w moved 1-4 ulps", 100'000, kNearDegenerate, nudged(integer, 0b1000, 1)},
      {"near-degenerate", "coordinates moved 1-4 ulps", 100'000, kNearDegenerate,
       nudged(integer, 0b0111)},
      {"multi-scale", "on the sphere, x 2^k", 75'000, kDegenerate, scaled(integer)},
      {"multi-scale", "moved, x 2^k", 75'000, kNearDegenerate, scaled(nudged(integer, 0b1111))},
      {"multi-scale", "mixed magnitudes", 50'000, kGeneric,
       always([](Rng& rng) {
         Points p = mixed_scale_points(rng, 2, true);
         p[0].w = 0;
         return p;
       })},
      {"multi-scale", "|c| ~ 2^ec, |x - c| ~ 2^(ec-40..ec), on it", 50'000, kDegenerate,
       mixed_offset},
      {"multi-scale", "moved, at the range's ends", 25'000, kNearDegenerate,
       scaled_to_extreme(nudged(integer, 0b1111))},
      {"multi-scale", "|c| ~ 2^ec, |x - c| ~ 2^(ec-40..ec), moved", 25'000, kNearDegenerate,
       nudged(mixed_offset, 0b1111)},
  };
  const long n = run_families(
      "power_distance_sign", 31, families,
      [](const Case& c) { return kernel::power_distance_sign(c[0], c[1]); },
      [](const Case& c) { return oracle::power_distance_sign(c[0], c[1]); });
  CHECK(n >= required_total());
}

TEST_CASE("compare_power_distance agrees with the exact oracle") {
  auto integer = maybe([](Rng& rng, Points& p) { return equal_powers(rng, p, false); });
  // x ~ 2^ec, p and q at offsets 2^ex, 2^ex' below it with w = |offset|^2: both powers are 0.
  auto mixed_equal = always([](Rng& rng) {
    int ex = 0;
    Points a = offset_pair(rng, ex);  // a[0] = c + offset, a[1] = c with w = |offset|^2
    const WeightedPoint c = a[1];
    const WeightedPoint v = random_integer_vector(rng, 255);
    const int ey = ex + static_cast<int>(rng.integer(0, 10));  // c's bits and both offsets fit 53
    WeightedPoint q{c.x + std::ldexp(v.x, ey), c.y + std::ldexp(v.y, ey), c.z + std::ldexp(v.z, ey),
                    std::ldexp(v.x * v.x + v.y * v.y + v.z * v.z, 2 * ey)};
    // x = c, p = a[0] with w = |offset|^2, q likewise.
    WeightedPoint x = c;
    x.w = 0;
    WeightedPoint p = a[0];
    p.w = c.w;
    return Points{x, p, q};
  });
  const std::vector<Family> families = {
      {"uniform", "x, p, q in [-1,1]^3, w in [0,1]", 275'000, kGeneric,
       always([](Rng& rng) {
         Points p = uniform_points(rng, 3, -1, 1, 0, 1);
         p[0].w = 0;
         return p;
       })},
      {"degenerate", "integers, equal powers", 150'000, kDegenerate, integer},
      {"degenerate", "equal weights, q mirrors p about x", 50'000, kDegenerate, maybe(mirrored)},
      {"degenerate", "dyadic, equal powers", 50'000, kDegenerate,
       maybe([](Rng& rng, Points& p) { return equal_powers(rng, p, true); })},
      {"near-degenerate", "equal powers, weights moved", 100'000, kNearDegenerate,
       nudged(integer, 0b1000, 1)},
      {"near-degenerate", "equal powers, coordinates moved", 100'000, kNearDegenerate,
       nudged(integer, 0b0111)},
      {"multi-scale", "equal powers x 2^k", 75'000, kDegenerate, scaled(integer)},
      {"multi-scale", "equal powers moved, x 2^k", 75'000, kNearDegenerate,
       scaled(nudged(integer, 0b1111))},
      {"multi-scale", "mixed magnitudes", 50'000, kGeneric,
       always([](Rng& rng) {
         Points p = mixed_scale_points(rng, 3, true);
         p[0].w = 0;
         return p;
       })},
      {"multi-scale", "|x| ~ 2^ec, offsets 2^(ec-40..ec+10), equal powers", 50'000, kDegenerate,
       mixed_equal},
      {"multi-scale", "equal powers moved, at the range's ends", 25'000, kNearDegenerate,
       scaled_to_extreme(nudged(integer, 0b1111))},
      {"multi-scale", "|x| ~ 2^ec, offsets, equal powers, moved", 25'000, kNearDegenerate,
       nudged(mixed_equal, 0b1111)},
  };
  const long n = run_families(
      "compare_power_distance", 32, families,
      [](const Case& c) { return kernel::compare_power_distance(c[0], c[1], c[2]); },
      [](const Case& c) { return oracle::compare_power_distance(c[0], c[1], c[2]); });
  CHECK(n >= required_total());
}
