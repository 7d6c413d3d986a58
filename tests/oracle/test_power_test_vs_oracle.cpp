// insphere and the 5-point power_test against the GMP oracle, at least one million inputs each
// (tests/oracle/oracle_harness.h).
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

// Four concyclic lattice points (a degenerate circle makes every fifth point "on the sphere":
// the lifted rows of the four span only a plane) plus any fifth point.
Points concyclic_plus_one(Rng& rng) {
  Points p = concyclic(rng, 4);
  p.push_back(random_integer_vector(rng, 1 << 20));
  return p;
}

// Four concyclic lattice points scaled by 2^k1, a fifth point of unrelated magnitude.
Points concyclic_plus_one_mixed(Rng& rng) {
  Points p = concyclic(rng, 4);
  scale_randomly(rng, p);
  WeightedPoint t;
  for (int a = 0; a < 3; ++a) t.data()[a] = mixed_coordinate(rng);
  p.push_back(t);
  return p;
}

// Random integer points weighted to be orthogonal to one random sphere: the power test is 0.
bool orthogonal_integer(Rng& rng, Points& p) {
  p.assign(5, WeightedPoint{});
  for (auto& q : p) q = random_integer_vector(rng, 1 << 16);
  if (!orthogonal_to_random_sphere(rng, p)) return false;
  maybe_translate(rng, p);
  return true;
}

// Dyadic points (12-bit fractions) orthogonal to a sphere with a dyadic centre.
bool orthogonal_dyadic(Rng& rng, Points& p) {
  p.assign(5, WeightedPoint{});
  for (auto& q : p)
    for (int a = 0; a < 3; ++a) q.data()[a] = std::ldexp(static_cast<double>(rng.integer(-4096, 4096)), -10);
  const double c[3] = {std::ldexp(static_cast<double>(rng.integer(-256, 256)), -4),
                       std::ldexp(static_cast<double>(rng.integer(-256, 256)), -4),
                       std::ldexp(static_cast<double>(rng.integer(-256, 256)), -4)};
  const double r2 = std::ldexp(static_cast<double>(rng.integer(0, 1 << 16)), -8);
  return set_orthogonal_weights(p, c, r2);
}

// Points of the grid {0..3}^3 orthogonal to one sphere: cospherical in the weighted sense with
// many coplanar and collinear subsets.
bool orthogonal_grid(Rng& rng, Points& p) {
  p = grid(rng, 5);
  return orthogonal_to_random_sphere(rng, p);
}

// Five lattice points of one sphere, all with the same weight.
Points cospherical_equal_weights(Rng& rng) {
  Points p = cospherical(rng, 5);
  set_weights(p, rng.chance(0.5) ? static_cast<double>(rng.integer(-(1 << 20), 1 << 20))
                                 : rng.uniform(-100, 100));
  return p;
}

}  // namespace

TEST_CASE("insphere agrees with the exact oracle") {
  auto sphere = always([](Rng& rng) { return cospherical(rng, 5); });
  const std::vector<Family> families = {
      {"uniform", "5 points in [-1,1]^3", 250'000, kGeneric,
       always([](Rng& rng) { return uniform_points(rng, 5, -1, 1); })},
      {"uniform", "5 points in [2^20, 2^20+1]^3", 50'000, kGeneric,
       always([](Rng& rng) { return uniform_points(rng, 5, 0x1p20, 0x1p20 + 1); })},
      {"degenerate", "5 lattice points of one sphere", 150'000, kDegenerate, sphere},
      {"degenerate", "4 concyclic lattice points + any", 50'000, kDegenerate,
       shuffled(always(concyclic_plus_one))},
      {"degenerate", "grid {0..3}^3", 50'000, ZeroRate{0.05, 0.9},
       always([](Rng& rng) { return grid(rng, 5); })},
      {"near-degenerate", "lattice sphere, 1-3 coords moved 1-4 ulps", 150'000, kNearDegenerate,
       nudged(sphere, 0b0111)},
      {"near-degenerate", "4 concyclic + any, moved", 50'000, kNearDegenerate,
       nudged(shuffled(always(concyclic_plus_one)), 0b0111)},
      {"multi-scale", "lattice sphere x 2^k", 75'000, kDegenerate, scaled(sphere)},
      {"multi-scale", "lattice sphere moved, x 2^k", 75'000, kNearDegenerate,
       scaled(nudged(sphere, 0b0111))},
      {"multi-scale", "mixed magnitudes 2^-140..2^140", 50'000, kGeneric,
       always([](Rng& rng) { return mixed_scale_points(rng, 5, false); })},
      {"multi-scale", "4 concyclic x 2^k + a point of any magnitude", 50'000, kDegenerate,
       shuffled(always(concyclic_plus_one_mixed))},
      {"multi-scale", "lattice sphere moved, at the range's ends", 25'000, kNearDegenerate,
       scaled_to_extreme(nudged(sphere, 0b0111))},
      // Two equal rows make the determinant 0; about 4% of the draws are 5 distinct points.
      {"degenerate", "repeated points (5 draws from 5)", 25'000, ZeroRate{0.9, 1},
       with_repeats(sphere, 5)},
  };
  const long n = run_families(
      "insphere", 11, families,
      [](const Case& c) { return kernel::insphere(c[0], c[1], c[2], c[3], c[4]); },
      [](const Case& c) { return oracle::insphere(c[0], c[1], c[2], c[3], c[4]); });
  CHECK(n >= required_total());
}

TEST_CASE("power_test (5 points) agrees with the exact oracle") {
  auto orthogonal = maybe(orthogonal_integer);
  auto equal = always(cospherical_equal_weights);
  const std::vector<Family> families = {
      {"uniform", "points in [-1,1]^3, weights in [-1/2,1/2]", 200'000, kGeneric,
       always([](Rng& rng) { return uniform_points(rng, 5, -1, 1, -0.5, 0.5); })},
      {"uniform", "points in [-1,1]^3, weights in [-4,4]", 50'000, kGeneric,
       always([](Rng& rng) { return uniform_points(rng, 5, -1, 1, -4, 4); })},
      {"degenerate", "integer points orthogonal to one sphere", 150'000, kDegenerate, orthogonal},
      {"degenerate", "lattice sphere, equal weights", 50'000, kDegenerate, equal},
      {"degenerate", "grid orthogonal to one sphere", 50'000, kDegenerate, maybe(orthogonal_grid)},
      {"degenerate", "dyadic points orthogonal to one sphere", 50'000, kDegenerate,
       maybe(orthogonal_dyadic)},
      {"near-degenerate", "orthogonal, 1-3 coords moved 1-4 ulps", 100'000, kNearDegenerate,
       nudged(orthogonal, 0b0111)},
      {"near-degenerate", "orthogonal, 1-3 weights moved 1-4 ulps", 75'000, kNearDegenerate,
       nudged(orthogonal, 0b1000)},
      {"near-degenerate", "lattice sphere equal weights, moved", 25'000, kNearDegenerate,
       nudged(equal, 0b1111)},
      {"multi-scale", "orthogonal x 2^k (weights x 2^2k)", 75'000, kDegenerate, scaled(orthogonal)},
      {"multi-scale", "orthogonal moved, x 2^k", 75'000, kNearDegenerate,
       scaled(nudged(orthogonal, 0b1111))},
      {"multi-scale", "mixed magnitudes, weights 2^-280..2^280", 50'000, kGeneric,
       always([](Rng& rng) { return mixed_scale_points(rng, 5, true); })},
      {"multi-scale", "per-point scales 2^+-120, orthogonal", 50'000, kDegenerate,
       always([](Rng& rng) { return mixed_scale_orthogonal(rng, 5); })},
      {"multi-scale", "orthogonal moved, at the range's ends", 25'000, kNearDegenerate,
       scaled_to_extreme(nudged(orthogonal, 0b1111))},
      // Repeated points with different weights are not degenerate: any zero rate.
      {"degenerate", "repeated points (5 draws from 5)", 25'000, kAnyRate,
       with_repeats(orthogonal, 5)},
      {"multi-scale", "per-point scales, orthogonal, moved", 25'000, kNearDegenerate,
       nudged(always([](Rng& rng) { return mixed_scale_orthogonal(rng, 5); }), 0b1111)},
  };
  const long n = run_families(
      "power_test(5)", 12, families,
      [](const Case& c) { return kernel::power_test(c[0], c[1], c[2], c[3], c[4]); },
      [](const Case& c) { return oracle::power_test(c[0], c[1], c[2], c[3], c[4]); });
  CHECK(n >= required_total());
}
