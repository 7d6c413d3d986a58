// The symbolic perturbation is one consistent scheme (Devillers & Teillaud 2011):
//  - the perturbed 5-point power test is the sign of ONE alternating function of the five
//    points: with S(a,b,c,d,e) = power_test_perturbed(a,b,c,d,e) when orient3d(a,b,c,d) > 0 and
//    -power_test_perturbed(b,a,c,d,e) when < 0, S(pi x) = sign(pi) S(x) for all 120
//    permutations; likewise the planar version (24 permutations) and the segment version (6);
//    so the answer never depends on the order in which the points are given beyond that sign;
//  - the perturbed predicates never return 0 and agree with the plain ones when these are not 0;
//  - realizing the perturbation with an actual small number (w_i - delta^(n - rank_i), delta a
//    power of two small enough for the first non-zero term to dominate, all exact in doubles) and
//    running the plain exact predicate gives the same answer: a GMP-free check of the scheme.
// Inputs are exactly degenerate sets (cospherical, cospherical and coplanar, concyclic, points
// orthogonal to one sphere on grids and lines) where the perturbation decides.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <vector>

#include <delpsc/kernel/predicates.h>

#include "support/generators.h"

using namespace delpsc;
using namespace delpsc::kernel;
using namespace delpsc::test;
using Points = std::vector<WeightedPoint>;

namespace {

// Sign of a permutation given as an index array, by counting inversions.
template <std::size_t N>
int permutation_sign(const std::array<int, N>& perm) {
  int inversions = 0;
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = i + 1; j < N; ++j) inversions += perm[i] > perm[j];
  return inversions % 2 ? -1 : 1;
}

// S of the text above for five weighted points; 0 when a, b, c, d are coplanar (undefined).
int alternating_5(const double* a, const double* b, const double* c, const double* d,
                  const double* e, bool weighted) {
  auto test = [weighted](const double* p, const double* q, const double* r, const double* s,
                         const double* t) {
    return weighted ? power_test_perturbed(p, q, r, s, t) : insphere_perturbed(p, q, r, s, t);
  };
  const int o = orient3d(a, b, c, d);
  if (o > 0) return test(a, b, c, d, e);
  if (o < 0) return -test(b, a, c, d, e);
  return 0;
}

// Planar: 0 when a, b, c are collinear (undefined).
int alternating_4(const double* a, const double* b, const double* c, const double* d) {
  const int o = coplanar_orientation(a, b, c);
  if (o > 0) return power_test_perturbed(a, b, c, d);
  if (o < 0) return -power_test_perturbed(b, a, c, d);
  return 0;
}

// Segment: power_segment_side_perturbed(a, b, c) is the first non-zero coefficient of the
// lifted 3x3 determinant times sign(a - b) on the first axis where they differ, which is
// compare_xyz(a, b); removing that factor leaves the alternating determinant.
int alternating_3(const double* a, const double* b, const double* c) {
  return power_segment_side_perturbed(a, b, c) * compare_xyz(a, b);
}

// Checks S(pi x) sign(pi) = constant over all permutations pi where S is defined; returns how
// many permutations were defined. S must never be 0 where the preconditions hold.
template <std::size_t N, class S>
int check_alternating(const Points& x, S s) {
  std::array<int, N> perm;
  std::iota(perm.begin(), perm.end(), 0);
  int reference = 0, defined = 0;
  do {
    std::array<const double*, N> p;
    for (std::size_t i = 0; i < N; ++i) p[i] = x[static_cast<std::size_t>(perm[i])].data();
    const int v = s(p);
    if (v == 2) continue;  // undefined for this order (degenerate leading simplex)
    CHECK(v != 0);
    const int normalized = v * permutation_sign(perm);
    if (reference == 0) reference = normalized;
    CHECK(normalized == reference);
    ++defined;
  } while (std::next_permutation(perm.begin(), perm.end()));
  return defined;
}

bool distinct_positions(const Points& p) {
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      if (compare_xyz(p[i].data(), p[j].data()) == 0) return false;
  return true;
}

// ---- degenerate configurations ----------------------------------------------------------------

const std::vector<Points>& small_lattice_spheres() {
  static const std::vector<Points> s = {lattice_sphere_points(2), lattice_sphere_points(3),
                                        lattice_sphere_points(5), lattice_sphere_points(9),
                                        lattice_sphere_points(11), lattice_sphere_points(25)};
  return s;
}

// k points from a small grid or lattice sphere, weighted to be orthogonal to a small random
// sphere (or, for lattice spheres, with equal weights): the weighted test is 0 and many subsets
// are coplanar or collinear, so several perturbation terms vanish.
Points degenerate_3d(Rng& rng, std::size_t k, bool weighted) {
  static const Points g3 = grid_points(3, 3, 3);
  Points p;
  if (!weighted || rng.chance(0.5)) {
    const auto& spheres = small_lattice_spheres();
    const Points* s = nullptr;
    do s = &spheres[rng.index(spheres.size())];
    while (s->size() < k);
    p = sample_distinct(rng, *s, k);
    set_weights(p, weighted ? static_cast<double>(rng.integer(-3, 3)) : 0.0);
  } else {
    p = sample_distinct(rng, g3, k);
    const WeightedPoint c = random_integer_vector(rng, 2);
    REQUIRE(set_orthogonal_weights(p, c.data(), static_cast<double>(rng.integer(0, 4))));
  }
  return p;
}

// Four coplanar points of a small grid in a coordinate plane (or in the plane x = y), orthogonal
// to a small random sphere.
Points degenerate_planar(Rng& rng) {
  static const Points g = grid_points(3, 3, 1);
  Points p = sample_distinct(rng, g, 4);
  const int mode = static_cast<int>(rng.integer(0, 3));
  for (auto& q : p) {
    if (mode == 1) std::swap(q.y, q.z);                 // plane y = 0
    if (mode == 2) std::swap(q.x, q.z);                 // plane x = 0
    if (mode == 3) q = {q.x, q.x, q.y, 0};              // plane y = x
  }
  const WeightedPoint c = random_integer_vector(rng, 2);
  REQUIRE(set_orthogonal_weights(p, c.data(), static_cast<double>(rng.integer(0, 4))));
  return p;
}

// Three collinear points of a short integer line, orthogonal to a small random sphere.
Points degenerate_linear(Rng& rng) {
  const WeightedPoint o = random_integer_vector(rng, 2);
  WeightedPoint d = random_integer_vector(rng, 1);
  Points p = collinear_points(rng, 3, o.data(), d.data(), 3);
  const WeightedPoint c = random_integer_vector(rng, 2);
  REQUIRE(set_orthogonal_weights(p, c.data(), static_cast<double>(rng.integer(0, 4))));
  return p;
}

// ---- realizing the perturbation ---------------------------------------------------------------

// w - d when exact (checked with Knuth's TwoSum), NaN otherwise.
double exact_difference(double w, double d) {
  const double s = w - d;
  const double bv = s - w;
  const double av = s - bv;
  return (w - av) + (-d - bv) == 0 ? s : NAN;
}

// Lexicographic ranks of the points (distinct positions).
std::vector<int> ranks(const Points& p) {
  std::vector<int> r(p.size(), 0);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < p.size(); ++j) r[i] += compare_xyz(p[j].data(), p[i].data()) < 0;
  return r;
}

// The points with weights w_i - delta^(n - rank_i), delta = 2^-m; false if one is not exact.
bool realize(const Points& p, int m, Points& out) {
  const auto r = ranks(p);
  const int n = static_cast<int>(p.size());
  out = p;
  for (std::size_t i = 0; i < p.size(); ++i) {
    out[i].w = exact_difference(p[i].w, std::ldexp(1.0, -m * (n - r[i])));
    if (std::isnan(out[i].w)) return false;
  }
  return true;
}

// Smallest m with 2^m > 2 B: then delta = 2^-m makes the first non-zero (integer) coefficient of
// the perturbed determinant outweigh all later ones, each at most B in magnitude.
int delta_exponent(double bound) { return static_cast<int>(std::ceil(std::log2(2 * bound))) + 1; }

double max_difference(const Points& p) {
  double m = 0;
  for (const auto& a : p)
    for (const auto& b : p)
      for (int k = 0; k < 3; ++k) m = std::max(m, std::fabs(a.data()[k] - b.data()[k]));
  return m;
}

}  // namespace

TEST_CASE("5-point perturbed power test is one alternating function of the five points") {
  Rng rng(2024);
  for (const bool weighted : {true, false}) {
    CAPTURE(weighted);
    int sets = 0, orders = 0;
    for (int n = 0; n < 3000; ++n) {
      const Points x = degenerate_3d(rng, 5, weighted);
      REQUIRE(distinct_positions(x));
      const int defined = check_alternating<5>(x, [weighted](const std::array<const double*, 5>& p) {
        const int s = alternating_5(p[0], p[1], p[2], p[3], p[4], weighted);
        return s == 0 && orient3d(p[0], p[1], p[2], p[3]) == 0 ? 2 : s;
      });
      orders += defined;
      sets += defined > 0;
    }
    MESSAGE("weighted " << weighted << ": " << sets << " sets, " << orders << " defined orders");
    CHECK(sets > 2500);
  }
}

TEST_CASE("planar perturbed power test is one alternating function of the four points") {
  Rng rng(2025);
  int sets = 0;
  for (int n = 0; n < 5000; ++n) {
    const Points x = degenerate_planar(rng);
    REQUIRE(distinct_positions(x));
    const int defined = check_alternating<4>(x, [](const std::array<const double*, 4>& p) {
      const int s = alternating_4(p[0], p[1], p[2], p[3]);
      return s == 0 && collinear(p[0], p[1], p[2]) ? 2 : s;
    });
    sets += defined > 0;
    // power_circle_side_perturbed: "inside the circle of p, q, r" does not depend on their order
    // and equals power_test_perturbed when they are positively oriented.
    const double *a = x[0].data(), *b = x[1].data(), *c = x[2].data(), *t = x[3].data();
    if (collinear(a, b, c)) continue;
    const int side = power_circle_side_perturbed(a, b, c, t);
    CHECK(side != 0);
    CHECK(power_circle_side_perturbed(b, a, c, t) == side);
    CHECK(power_circle_side_perturbed(c, b, a, t) == side);
    CHECK(power_circle_side_perturbed(b, c, a, t) == side);
    CHECK(power_circle_side_perturbed(c, a, b, t) == side);
    CHECK(power_circle_side_perturbed(a, c, b, t) == side);
    if (coplanar_orientation(a, b, c) > 0) CHECK(power_test_perturbed(a, b, c, t) == side);
  }
  CHECK(sets > 4000);
}

TEST_CASE("segment perturbed power test is one alternating function of the three points") {
  Rng rng(2026);
  for (int n = 0; n < 5000; ++n) {
    const Points x = degenerate_linear(rng);
    REQUIRE(distinct_positions(x));
    check_alternating<3>(x, [](const std::array<const double*, 3>& p) {
      return alternating_3(p[0], p[1], p[2]);
    });
    CHECK(power_segment_side_perturbed(x[0].data(), x[1].data(), x[2].data()) ==
          power_segment_side_perturbed(x[1].data(), x[0].data(), x[2].data()));
  }
}

TEST_CASE("perturbed predicates agree with the plain ones away from degeneracy") {
  Rng rng(2027);
  for (int n = 0; n < 20000; ++n) {
    Points p = uniform_points(rng, 5, -1, 1, -0.5, 0.5);
    if (orient3d(p[0].data(), p[1].data(), p[2].data(), p[3].data()) < 0) std::swap(p[0], p[1]);
    const double *a = p[0].data(), *b = p[1].data(), *c = p[2].data(), *d = p[3].data(),
                 *e = p[4].data();
    const int plain = power_test(a, b, c, d, e);
    if (plain != 0) CHECK(power_test_perturbed(a, b, c, d, e) == plain);
    const int plain_sphere = insphere(a, b, c, d, e);
    if (plain_sphere != 0) CHECK(insphere_perturbed(a, b, c, d, e) == plain_sphere);
    for (auto& q : p) q.z = 0.25;  // planar
    const int plain_circle = power_test(a, b, c, d);
    if (plain_circle != 0) CHECK(power_circle_side_perturbed(a, b, c, d) == plain_circle);
    for (auto& q : p) q.y = -0.5;  // linear
    const int plain_segment = power_test(a, b, c);
    if (plain_segment != 0) CHECK(power_segment_side_perturbed(a, b, c) == plain_segment);
  }
}

TEST_CASE("realizing the perturbation with a small delta gives the perturbed answers") {
  Rng rng(2028);
  int realized = 0, decided_by_perturbation = 0;
  for (int n = 0; n < 20000; ++n) {
    const int kind = n % 4;
    Points x, real;
    int got = 0, plain = 0;
    if (kind <= 1) {  // 5 points, weighted or not
      const bool weighted = kind == 0;
      x = degenerate_3d(rng, 5, weighted);
      const int o = orient3d(x[0].data(), x[1].data(), x[2].data(), x[3].data());
      if (o == 0) continue;
      if (o < 0) std::swap(x[0], x[1]);
      // Coefficients of eps are orient3d of four of the points: at most 6 M^3.
      const double m = max_difference(x);
      if (!realize(x, delta_exponent(6 * m * m * m), real)) continue;
      const double *a = x[0].data(), *b = x[1].data(), *c = x[2].data(), *d = x[3].data(),
                   *e = x[4].data();
      got = weighted ? power_test_perturbed(a, b, c, d, e) : insphere_perturbed(a, b, c, d, e);
      plain = weighted ? power_test(a, b, c, d, e) : insphere(a, b, c, d, e);
      const int truth = power_test(real[0].data(), real[1].data(), real[2].data(), real[3].data(),
                                   real[4].data());
      CHECK(got == truth);
    } else if (kind == 2) {  // planar: coefficients are orient2d, at most 2 M^2
      x = degenerate_planar(rng);
      if (collinear(x[0].data(), x[1].data(), x[2].data())) continue;
      const double m = max_difference(x);
      if (!realize(x, delta_exponent(2 * m * m), real)) continue;
      got = power_circle_side_perturbed(x[0].data(), x[1].data(), x[2].data(), x[3].data());
      plain = power_test(x[0].data(), x[1].data(), x[2].data(), x[3].data());
      CHECK(got == power_test(real[0].data(), real[1].data(), real[2].data(), real[3].data()));
    } else {  // linear: coefficients are differences, at most M
      x = degenerate_linear(rng);
      if (!realize(x, delta_exponent(max_difference(x)), real)) continue;
      got = power_segment_side_perturbed(x[0].data(), x[1].data(), x[2].data());
      plain = power_test(x[0].data(), x[1].data(), x[2].data());
      CHECK(got == power_test(real[0].data(), real[1].data(), real[2].data()));
    }
    ++realized;
    decided_by_perturbation += plain == 0;
  }
  MESSAGE(realized << " realized, " << decided_by_perturbation << " decided by the perturbation");
  CHECK(realized > 15000);
  CHECK(decided_by_perturbation > 10000);
}
