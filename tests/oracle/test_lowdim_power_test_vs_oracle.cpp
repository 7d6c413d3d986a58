// The planar (4-point), linear (3-point) and 2-point power tests against the GMP oracle, at
// least one million inputs each (tests/oracle/oracle_harness.h). Their preconditions (coplanar
// points with p, q, r not collinear; collinear points with p != q; equal positions) hold for
// every input: they are constructed exactly, and draws that miss them are rejected.
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

int random_axis(Rng& rng) { return static_cast<int>(rng.integer(0, 2)); }

// ---- planar ----------------------------------------------------------------------------------

bool not_collinear(const Points& p) { return !oracle::collinear(p[0].data(), p[1].data(), p[2].data()); }

bool axis_plane_uniform(Rng& rng, Points& p) {
  p = uniform_points(rng, 4, -1, 1, -0.5, 0.5);
  const int a = random_axis(rng);
  const double c = rng.uniform(-1, 1);
  for (auto& q : p) q.data()[a] = c;
  return not_collinear(p);
}

bool diagonal_plane_uniform(Rng& rng, Points& p) {
  p = uniform_points(rng, 4, -1, 1, -0.5, 0.5);
  const int a = random_axis(rng), b = (a + static_cast<int>(rng.integer(1, 2))) % 3;
  const double s = rng.sign() * std::ldexp(1.0, static_cast<int>(rng.integer(-2, 2)));
  for (auto& q : p) q.data()[b] = s * q.data()[a];
  return not_collinear(p);
}

bool integer_plane_integer_weights(Rng& rng, Points& p) {
  p = integer_coplanar(rng, 4);
  for (auto& q : p) q.w = static_cast<double>(rng.integer(-(1 << 30), 1 << 30));
  return not_collinear(p);
}

bool plane_orthogonal(Rng& rng, Points& p, const IntegerPlane& plane) {
  p = coplanar_points(rng, 4, plane, 1 << 16);
  if (!not_collinear(p) || !orthogonal_to_random_sphere(rng, p)) return false;
  maybe_translate(rng, p);
  return true;
}

bool tilted_orthogonal(Rng& rng, Points& p) {
  return plane_orthogonal(rng, p, IntegerPlane::random(rng, 3, 1 << 20));
}

// A plane containing an axis direction (b = 0), so that CGAL's xy (and for y = c also xz)
// projection is degenerate and a later one decides.
bool vertical_orthogonal(Rng& rng, Points& p) {
  IntegerPlane plane = IntegerPlane::random(rng, 3, 1 << 20);
  plane.axis = static_cast<int>(rng.integer(0, 1));
  plane.b = 0;
  return plane_orthogonal(rng, p, plane);
}

bool concyclic_equal_weights(Rng& rng, Points& p) {
  p = concyclic(rng, 4);
  set_weights(p, static_cast<double>(rng.integer(-(1 << 20), 1 << 20)));
  return not_collinear(p);
}

bool grid_plane_orthogonal(Rng& rng, Points& p) {
  static const Points g = grid_points(4, 4, 1);
  p = sample_distinct(rng, g, 4);
  const int a = random_axis(rng);
  for (auto& q : p) std::swap(q.data()[2], q.data()[a]);
  return not_collinear(p) && orthogonal_to_random_sphere(rng, p);
}

// Axis plane x_a = c, orthogonal weights, then in-plane coordinates moved (stays coplanar).
bool axis_plane_orthogonal_moved(Rng& rng, Points& p) {
  IntegerPlane plane;
  plane.axis = random_axis(rng);
  plane.c = rng.integer(-(1 << 20), 1 << 20);
  if (!plane_orthogonal(rng, p, plane)) return false;
  nudge_a_little(rng, p, 0b0111u & ~(1u << plane.axis));
  return not_collinear(p);
}

bool mixed_plane_mixed_weights(Rng& rng, Points& p) {
  if (rng.chance(0.5)) {
    p = mixed_scale_axis_plane(rng, 4, random_axis(rng));
  } else {
    const int a = random_axis(rng);
    p = mixed_scale_diagonal_plane(rng, 4, a, (a + 1) % 3);
  }
  for (auto& q : p) q.w = rng.chance(0.1) ? 0.0 : rng.log_uniform(kMinWeightExp, kMaxWeightExp - 1);
  return not_collinear(p);
}

bool mixed_plane_orthogonal(Rng& rng, Points& p) {
  p = mixed_scale_orthogonal(rng, 4, 1u << random_axis(rng));
  return not_collinear(p);
}

// ---- linear ----------------------------------------------------------------------------------

bool distinct_pq(const Points& p) { return oracle::compare_xyz(p[0].data(), p[1].data()) != 0; }

// (lambda, c1, c2) with the line's axis random: lambda uniform, weights uniform.
bool axis_line_uniform(Rng& rng, Points& p) {
  p = uniform_points(rng, 3, -1, 1, -0.5, 0.5);
  const int a = random_axis(rng);
  for (int k = 0; k < 3; ++k)
    if (k != a) p[1].data()[k] = p[2].data()[k] = p[0].data()[k];
  return distinct_pq(p);
}

// lambda * dir through the origin, dir entries in {0, +-1/2, +-1, +-2} (exact products).
bool diagonal_line_uniform(Rng& rng, Points& p) {
  double dir[3];
  do {
    for (double& d : dir) d = rng.chance(0.3) ? 0.0 : rng.sign() * std::ldexp(1.0, static_cast<int>(rng.integer(-1, 1)));
  } while (dir[0] == 0 && dir[1] == 0 && dir[2] == 0);
  p.assign(3, WeightedPoint{});
  for (auto& q : p) {
    const double l = rng.uniform(-1, 1);
    for (int a = 0; a < 3; ++a) q.data()[a] = l * dir[a];
    q.w = rng.uniform(-0.5, 0.5);
  }
  return distinct_pq(p);
}

bool integer_line_integer_weights(Rng& rng, Points& p) {
  p = integer_collinear(rng, 3);
  for (auto& q : p) q.w = static_cast<double>(rng.integer(-(1 << 30), 1 << 30));
  return true;
}

bool line_orthogonal(Rng& rng, Points& p) {
  p = integer_collinear(rng, 3);
  if (!orthogonal_to_random_sphere(rng, p)) return false;
  maybe_translate(rng, p);
  return true;
}

// A line with constant x (and, half of the time, constant y): CGAL projects on y or z.
bool line_in_x_plane_orthogonal(Rng& rng, Points& p) {
  const WeightedPoint o = random_integer_vector(rng, 1 << 20);
  WeightedPoint d = random_direction(rng);
  d.x = 0;
  if (rng.chance(0.5)) d.y = 0;
  if (d.y == 0 && d.z == 0) d.z = 1;
  p = collinear_points(rng, 3, o.data(), d.data(), 1 << 12);
  if (!orthogonal_to_random_sphere(rng, p)) return false;
  maybe_translate(rng, p);
  return true;
}

// Axis-parallel integer line, orthogonal weights, then coordinates along the line moved.
bool axis_line_orthogonal_moved(Rng& rng, Points& p) {
  const WeightedPoint o = random_integer_vector(rng, 1 << 20);
  const int a = random_axis(rng);
  WeightedPoint d{0, 0, 0, 0};
  d.data()[a] = static_cast<double>(rng.integer(1, 64));
  p = collinear_points(rng, 3, o.data(), d.data(), 1 << 12);
  if (!orthogonal_to_random_sphere(rng, p)) return false;
  nudge_a_little(rng, p, 1u << a);
  return distinct_pq(p);
}

bool mixed_line_mixed_weights(Rng& rng, Points& p) {
  p = mixed_scale_line(rng, 3);
  for (auto& q : p) q.w = rng.chance(0.1) ? 0.0 : rng.log_uniform(kMinWeightExp, kMaxWeightExp - 1);
  return distinct_pq(p);
}

bool mixed_axis_orthogonal(Rng& rng, Points& p) {
  const int a = random_axis(rng);
  p = mixed_scale_orthogonal(rng, 3, 0b111u & ~(1u << a));
  return distinct_pq(p);
}

// ---- same position ---------------------------------------------------------------------------

Points same_position(Rng& rng, double w0, double w1) {
  Points p = uniform_points(rng, 1, -1, 1);
  p.push_back(p[0]);
  p[0].w = w0;
  p[1].w = w1;
  return p;
}

}  // namespace

TEST_CASE("power_test (4 coplanar points) agrees with the exact oracle") {
  auto orthogonal = maybe(tilted_orthogonal);
  auto concyclic_equal = maybe(concyclic_equal_weights);
  const std::vector<Family> families = {
      {"uniform", "plane x_a = c, uniform weights", 100'000, kGeneric, maybe(axis_plane_uniform)},
      {"uniform", "plane x_b = +-2^j x_a, uniform weights", 75'000, kGeneric,
       maybe(diagonal_plane_uniform)},
      {"uniform", "integer plane, integer weights", 75'000, kGeneric,
       maybe(integer_plane_integer_weights)},
      {"degenerate", "integer plane orthogonal to one sphere", 150'000, kDegenerate, orthogonal},
      {"degenerate", "concyclic lattice points, equal weights", 50'000, kDegenerate,
       concyclic_equal},
      {"degenerate", "plane containing an axis, orthogonal", 50'000, kDegenerate,
       maybe(vertical_orthogonal)},
      {"degenerate", "grid plane, orthogonal", 25'000, kDegenerate, maybe(grid_plane_orthogonal)},
      {"near-degenerate", "orthogonal, 1-3 weights moved", 100'000, kNearDegenerate,
       nudged(orthogonal, 0b1000)},
      {"near-degenerate", "axis plane orthogonal, in-plane coords moved", 75'000, kNearDegenerate,
       maybe(axis_plane_orthogonal_moved)},
      {"near-degenerate", "concyclic equal weights, weights moved", 25'000, kNearDegenerate,
       nudged(concyclic_equal, 0b1000)},
      {"multi-scale", "orthogonal x 2^k", 75'000, kDegenerate, scaled(orthogonal)},
      {"multi-scale", "orthogonal, weights moved, x 2^k", 75'000, kNearDegenerate,
       scaled(nudged(orthogonal, 0b1000))},
      {"multi-scale", "mixed magnitudes in a plane, mixed weights", 50'000, kGeneric,
       maybe(mixed_plane_mixed_weights)},
      {"multi-scale", "per-point scales, plane x_a = 0, orthogonal", 50'000, kDegenerate,
       maybe(mixed_plane_orthogonal)},
      {"multi-scale", "orthogonal, weights moved, at the range's ends", 25'000, kNearDegenerate,
       scaled_to_extreme(nudged(orthogonal, 0b1000))},
      {"degenerate", "t at the position of p, q or r", 25'000, kAnyRate,
       maybe([](Rng& rng, Points& p) {
         if (!tilted_orthogonal(rng, p)) return false;
         const double w = p[3].w;
         p[3] = p[rng.index(3)];
         if (rng.chance(0.5)) p[3].w = w;
         return true;
       })},
      {"multi-scale", "per-point scales, plane, weights moved", 25'000, kNearDegenerate,
       nudged(maybe(mixed_plane_orthogonal), 0b1000)},
  };
  const long n = run_families(
      "power_test(4)", 21, families,
      [](const Case& c) { return kernel::power_test(c[0], c[1], c[2], c[3]); },
      [](const Case& c) { return oracle::power_test(c[0], c[1], c[2], c[3]); });
  CHECK(n >= required_total());
}

TEST_CASE("power_test (3 collinear points) agrees with the exact oracle") {
  auto orthogonal = maybe(line_orthogonal);
  const std::vector<Family> families = {
      {"uniform", "axis-parallel line, uniform weights", 150'000, kGeneric,
       maybe(axis_line_uniform)},
      {"uniform", "line through 0, uniform weights", 75'000, kGeneric, maybe(diagonal_line_uniform)},
      {"uniform", "integer line, integer weights", 75'000, kGeneric,
       maybe(integer_line_integer_weights)},
      {"degenerate", "integer line orthogonal to one sphere", 200'000, kDegenerate, orthogonal},
      {"degenerate", "line with constant x, orthogonal", 50'000, kDegenerate,
       maybe(line_in_x_plane_orthogonal)},
      {"near-degenerate", "orthogonal, 1-3 weights moved", 100'000, kNearDegenerate,
       nudged(orthogonal, 0b1000)},
      {"near-degenerate", "axis line orthogonal, moved along it", 75'000, kNearDegenerate,
       maybe(axis_line_orthogonal_moved)},
      {"multi-scale", "orthogonal x 2^k", 75'000, kDegenerate, scaled(orthogonal)},
      {"multi-scale", "orthogonal, weights moved, x 2^k", 75'000, kNearDegenerate,
       scaled(nudged(orthogonal, 0b1000))},
      {"multi-scale", "mixed magnitudes on a line through 0, mixed weights", 50'000, kGeneric,
       maybe(mixed_line_mixed_weights)},
      {"multi-scale", "per-point scales on an axis, orthogonal", 50'000, kDegenerate,
       maybe(mixed_axis_orthogonal)},
      {"multi-scale", "orthogonal, weights moved, at the range's ends", 25'000, kNearDegenerate,
       scaled_to_extreme(nudged(orthogonal, 0b1000))},
      {"degenerate", "t at the position of p or q", 25'000, kAnyRate,
       maybe([](Rng& rng, Points& p) {
         if (!line_orthogonal(rng, p)) return false;
         const double w = p[2].w;
         p[2] = p[rng.index(2)];
         if (rng.chance(0.5)) p[2].w = w;
         return true;
       })},
      {"multi-scale", "per-point scales on an axis, weights moved", 25'000, kNearDegenerate,
       nudged(maybe(mixed_axis_orthogonal), 0b1000)},
  };
  const long n = run_families(
      "power_test(3)", 22, families,
      [](const Case& c) { return kernel::power_test(c[0], c[1], c[2]); },
      [](const Case& c) { return oracle::power_test(c[0], c[1], c[2]); });
  CHECK(n >= required_total());
}

TEST_CASE("power_test (2 points at one position) agrees with the exact oracle") {
  const std::vector<Family> families = {
      {"uniform", "uniform weights", 300'000, kGeneric,
       always([](Rng& rng) { return same_position(rng, rng.uniform(-1, 1), rng.uniform(-1, 1)); })},
      {"degenerate", "equal weights", 250'000, kDegenerate,
       always([](Rng& rng) {
         const double w = rng.uniform(-1, 1);
         return same_position(rng, w, w);
       })},
      {"near-degenerate", "equal weights, one moved 1-4 ulps", 250'000, kNearDegenerate,
       always([](Rng& rng) {
         const double w = rng.uniform(-1, 1);
         return same_position(rng, w, nudge(w, static_cast<int>(rng.integer(1, 4)) * rng.sign(), kMinWeightExp));
       })},
      {"multi-scale", "mixed magnitudes", 100'000, kGeneric,
       always([](Rng& rng) {
         return same_position(rng, rng.log_uniform(kMinWeightExp, kMaxWeightExp - 1),
                              rng.log_uniform(kMinWeightExp, kMaxWeightExp - 1));
       })},
      {"multi-scale", "equal weights of any magnitude", 100'000, kDegenerate,
       always([](Rng& rng) {
         const double w = rng.log_uniform(kMinWeightExp, kMaxWeightExp - 1);
         return same_position(rng, w, w);
       })},
  };
  const long n = run_families(
      "power_test(2)", 23, families,
      [](const Case& c) { return kernel::power_test(c[0], c[1]); },
      [](const Case& c) { return oracle::power_test(c[0], c[1]); });
  CHECK(n >= required_total());
}
