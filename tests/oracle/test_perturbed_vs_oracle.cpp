// The perturbed predicates against an independent oracle of the symbolic perturbation
// (support/oracle.h): the lifted determinant with weights w_i - eps^(n - rank_i), expanded as a
// polynomial in eps with GMP, signed by its first non-zero coefficient. Inputs are exactly
// degenerate (cospherical; cospherical and coplanar, where the first perturbation terms vanish
// too), their neighbours, scaled copies, and a few generic ones. The perturbed predicates must
// never return 0; the oracle never does on valid input, so a 0 shows up as a mismatch.
//
// Each family also states how often the perturbation must have decided (eps power >= 1) and
// how often a deeper term than the first was needed (eps power >= 2), so that the test cannot
// drift into checking only the unperturbed sign or only the easy first term.
#include <doctest/doctest.h>

#include <array>

#include <delpsc/kernel/predicates.h>

#include "oracle_families.h"
#include "support/oracle.h"

namespace kernel = delpsc::kernel;
namespace oracle = delpsc::test::oracle;
using namespace delpsc::test;
using namespace delpsc::test::configs;
using delpsc::WeightedPoint;

namespace {

struct PerturbedFamily {
  Family family;
  double min_perturbed;  ///< fraction of inputs decided by an eps term (power >= 1)
  double min_deep;       ///< fraction needing a deeper term (power >= 2)
};

// Runs each family separately to keep a histogram of the eps power that decided.
template <class Ours, class Exact>
void run_perturbed(const char* predicate, std::uint64_t seed,
                   const std::vector<PerturbedFamily>& families, Ours ours, Exact exact) {
  long total = 0;
  for (std::size_t f = 0; f < families.size(); ++f) {
    std::array<long, 7> hist{};
    long zeros_ours = 0;
    const PerturbedFamily& pf = families[f];
    total += run_families(
        predicate, seed * 100 + f, {pf.family},
        [&](const Case& c) {
          const int o = ours(c);
          if (o == 0) ++zeros_ours;
          return o;
        },
        [&](const Case& c) {
          const oracle::PerturbedSign s = exact(c);
          ++hist[static_cast<std::size_t>(std::clamp(s.eps_power, -1, 5) + 1)];
          return s.sign;
        });
    long n = 0;
    for (const long h : hist) n += h;
    const double perturbed = static_cast<double>(n - hist[0] - hist[1]) / static_cast<double>(n);
    const double deep = static_cast<double>(n - hist[0] - hist[1] - hist[2]) / static_cast<double>(n);
    std::printf("%26s decided by eps^0: %ld, eps^1: %ld, eps^2: %ld, eps^3: %ld, eps^4: %ld, "
                "eps^5: %ld\n",
                "", hist[1], hist[2], hist[3], hist[4], hist[5], hist[6]);
    INFO(predicate << " / " << pf.family.name);
    CHECK(hist[0] == 0);  // the oracle found every coefficient zero: a violated precondition
    CHECK(zeros_ours == 0);
    CHECK(perturbed >= pf.min_perturbed);
    CHECK(deep >= pf.min_deep);
  }
  CHECK(total > 0);
}

// Precondition of the 5-point version: orient3d(p,q,r,s) > 0 (swap p, q when negative; reject
// when 0) and t at a position different from p, q, r, s.
bool valid_5(Case& c) {
  if (c.n != 5) return false;
  for (int k = 0; k < 4; ++k)
    if (oracle::compare_xyz(c[k], c[4]) == 0) return false;
  const int o = oracle::orient3d(c[0], c[1], c[2], c[3]);
  if (o == 0) return false;
  if (o < 0) std::swap(c.pts[0], c.pts[1]);
  return true;
}

template <class Gen>
auto valid5(Gen gen) {
  return [gen](Rng& rng, Case& c) { return gen(rng, c) && valid_5(c); };
}

// Coplanar p, q, r, t; p, q, r not collinear; t at another position. When `oriented`,
// coplanar_orientation(p, q, r) > 0 too (swap p, q).
bool valid_4(Case& c, bool oriented) {
  if (c.n != 4 || oracle::collinear(c[0], c[1], c[2])) return false;
  for (int k = 0; k < 3; ++k)
    if (oracle::compare_xyz(c[k], c[3]) == 0) return false;
  if (oriented && oracle::coplanar_orientation(c[0], c[1], c[2]) < 0) std::swap(c.pts[0], c.pts[1]);
  return true;
}

template <class Gen>
auto valid4(Gen gen, bool oriented) {
  return [gen, oriented](Rng& rng, Case& c) { return gen(rng, c) && valid_4(c, oriented); };
}

// Collinear, pairwise distinct positions.
template <class Gen>
auto valid3(Gen gen) {
  return [gen](Rng& rng, Case& c) {
    return gen(rng, c) && c.n == 3 && oracle::compare_xyz(c[0], c[1]) != 0 &&
           oracle::compare_xyz(c[0], c[2]) != 0 && oracle::compare_xyz(c[1], c[2]) != 0;
  };
}

bool orthogonal_integer_5(Rng& rng, Points& p) {
  p.assign(5, WeightedPoint{});
  for (auto& q : p) q = random_integer_vector(rng, 1 << 16);
  return orthogonal_to_random_sphere(rng, p);
}

// Points of a small grid orthogonal to one sphere: cospherical in the weighted sense with many
// coplanar (and collinear) subsets, the case where several perturbation terms vanish.
bool orthogonal_grid(Rng& rng, Points& p, std::size_t k, int side, bool planar) {
  static const Points g3 = grid_points(3, 3, 3), g4 = grid_points(4, 4, 4), p3 = grid_points(3, 3, 1),
                      p4 = grid_points(4, 4, 1);
  const Points& g = planar ? (side == 3 ? p3 : p4) : (side == 3 ? g3 : g4);
  p = sample_distinct(rng, g, k);
  if (planar) {
    const int a = static_cast<int>(rng.integer(0, 2));
    for (auto& q : p) std::swap(q.data()[2], q.data()[a]);
  }
  return orthogonal_to_random_sphere(rng, p);
}

// Lattice points of one of the smallest spheres (r^2 = 3: cube corners; 9; 11; ...), equal
// weights: cospherical with many coplanar quadruples.
Points small_sphere(Rng& rng, std::size_t k) {
  const auto& spheres = lattice_spheres();
  const Points* s = nullptr;
  do s = &spheres[rng.index(4)];
  while (s->size() < k);
  Points p = sample_distinct(rng, *s, k);
  set_weights(p, static_cast<double>(rng.integer(-100, 100)));
  return p;
}

}  // namespace

TEST_CASE("power_test_perturbed (5 points) agrees with the eps-polynomial oracle") {
  auto orthogonal = maybe(orthogonal_integer_5);
  auto grid3 = maybe([](Rng& rng, Points& p) { return orthogonal_grid(rng, p, 5, 3, false); });
  auto grid4 = maybe([](Rng& rng, Points& p) { return orthogonal_grid(rng, p, 5, 4, false); });
  auto sphere = always([](Rng& rng) { return small_sphere(rng, 5); });
  auto concyclic4 = always([](Rng& rng) {
    Points p = concyclic(rng, 4);
    p.push_back(random_integer_vector(rng, 64));
    return p;
  });
  const std::vector<PerturbedFamily> families = {
      {{"uniform", "generic points and weights", 20'000, ZeroRate{0, 0},
        valid5(always([](Rng& rng) { return uniform_points(rng, 5, -1, 1, -0.5, 0.5); }))},
       0, 0},
      {{"degenerate", "integer points orthogonal to one sphere", 60'000, ZeroRate{0, 0},
        valid5(orthogonal)},
       0.99, 0},
      {{"degenerate", "grid {0..2}^3 orthogonal (coplanar subsets)", 60'000, ZeroRate{0, 0},
        valid5(grid3)},
       0.99, 0.05},
      {{"degenerate", "grid {0..3}^3 orthogonal (coplanar subsets)", 40'000, ZeroRate{0, 0},
        valid5(grid4)},
       0.99, 0.02},
      {{"degenerate", "small lattice spheres, equal weights", 40'000, ZeroRate{0, 0},
        valid5(sphere)},
       0.99, 0.05},
      {{"degenerate", "4 concyclic + any, equal weights 0", 20'000, ZeroRate{0, 0},
        valid5(shuffled(concyclic4))},
       0.99, 0},
      {{"near-degenerate", "orthogonal, weights moved", 20'000, ZeroRate{0, 0},
        valid5(nudged(orthogonal, 0b1000))},
       0, 0},
      {{"multi-scale", "grid orthogonal x 2^k", 30'000, ZeroRate{0, 0}, valid5(scaled(grid3))},
       0.99, 0.05},
      {{"multi-scale", "grid orthogonal, at the range's ends", 10'000, ZeroRate{0, 0},
        valid5(scaled_to_extreme(grid3))},
       0.99, 0.05},
      {{"multi-scale", "per-point scales, orthogonal", 20'000, ZeroRate{0, 0},
        valid5(always([](Rng& rng) { return mixed_scale_orthogonal(rng, 5); }))},
       0.99, 0},
      {{"multi-scale", "per-point scales, plane + 1, orthogonal", 20'000, ZeroRate{0, 0},
        valid5(shuffled(always([](Rng& rng) {
          const int a = static_cast<int>(rng.integer(0, 2));
          Points p = mixed_scale_orthogonal(rng, 4, 1u << a);
          p.push_back(mixed_scale_orthogonal(rng, 1)[0]);
          return p;
        })))},
       0.99, 0.05},
  };
  run_perturbed(
      "power_test_perturbed(5)", 41, families,
      [](const Case& c) { return kernel::power_test_perturbed(c[0], c[1], c[2], c[3], c[4]); },
      [](const Case& c) { return oracle::power_test_perturbed(c[0], c[1], c[2], c[3], c[4]); });
}

TEST_CASE("insphere_perturbed agrees with the eps-polynomial oracle") {
  auto small = always([](Rng& rng) { return small_sphere(rng, 5); });
  auto any_sphere = always([](Rng& rng) { return cospherical(rng, 5); });
  const std::vector<PerturbedFamily> families = {
      {{"uniform", "generic points", 20'000, ZeroRate{0, 0},
        valid5(always([](Rng& rng) { return uniform_points(rng, 5, -1, 1); }))},
       0, 0},
      {{"degenerate", "small lattice spheres (coplanar subsets)", 80'000, ZeroRate{0, 0},
        valid5(small)},
       0.99, 0.05},
      {{"degenerate", "lattice spheres, translated", 60'000, ZeroRate{0, 0}, valid5(any_sphere)},
       0.99, 0},
      {{"degenerate", "4 concyclic + any", 20'000, ZeroRate{0, 0},
        valid5(shuffled(always([](Rng& rng) {
          Points p = concyclic(rng, 4);
          p.push_back(random_integer_vector(rng, 64));
          return p;
        })))},
       0.99, 0},
      {{"multi-scale", "small lattice spheres x 2^k", 40'000, ZeroRate{0, 0}, valid5(scaled(small))},
       0.99, 0.05},
  };
  run_perturbed(
      "insphere_perturbed", 42, families,
      [](const Case& c) { return kernel::insphere_perturbed(c[0], c[1], c[2], c[3], c[4]); },
      [](const Case& c) { return oracle::insphere_perturbed(c[0], c[1], c[2], c[3], c[4]); });
}

namespace {

std::vector<PerturbedFamily> planar_families(bool oriented) {
  auto tilted = maybe([](Rng& rng, Points& p) {
    p = coplanar_points(rng, 4, IntegerPlane::random(rng, 3, 1 << 20), 1 << 16);
    return orthogonal_to_random_sphere(rng, p);
  });
  auto grid3 = maybe([](Rng& rng, Points& p) { return orthogonal_grid(rng, p, 4, 3, true); });
  auto grid4 = maybe([](Rng& rng, Points& p) { return orthogonal_grid(rng, p, 4, 4, true); });
  auto concyclic_equal = always([](Rng& rng) {
    Points p = concyclic(rng, 4);
    set_weights(p, static_cast<double>(rng.integer(-100, 100)));
    return p;
  });
  // Two points on a line through the others: collinear triples inside the circle test.
  auto vertical_grid = maybe([](Rng& rng, Points& p) {
    static const Points g = grid_points(3, 1, 3);  // plane y = 0: xy and yz degenerate
    p = sample_distinct(rng, g, 4);
    if (rng.chance(0.5))
      for (auto& q : p) std::swap(q.x, q.y);  // plane x = 0: xy degenerate, yz decides
    return orthogonal_to_random_sphere(rng, p);
  });
  return {
      {{"uniform", "generic points in z = c", 20'000, ZeroRate{0, 0},
        valid4(always([](Rng& rng) {
                 Points p = uniform_points(rng, 4, -1, 1, -0.5, 0.5);
                 for (auto& q : p) q.z = 0.5;
                 return p;
               }),
               oriented)},
       0, 0},
      {{"degenerate", "integer plane orthogonal to one sphere", 50'000, ZeroRate{0, 0},
        valid4(tilted, oriented)},
       0.99, 0},
      {{"degenerate", "grid {0..2}^2 orthogonal (collinear triples)", 50'000, ZeroRate{0, 0},
        valid4(grid3, oriented)},
       0.99, 0.05},
      {{"degenerate", "grid {0..3}^2 orthogonal", 30'000, ZeroRate{0, 0}, valid4(grid4, oriented)},
       0.99, 0.02},
      {{"degenerate", "grid in x = 0 or y = 0 (later projections)", 30'000, ZeroRate{0, 0},
        valid4(vertical_grid, oriented)},
       0.99, 0.05},
      {{"degenerate", "concyclic lattice points, equal weights", 30'000, ZeroRate{0, 0},
        valid4(concyclic_equal, oriented)},
       0.99, 0},
      {{"multi-scale", "grid orthogonal x 2^k", 20'000, ZeroRate{0, 0}, valid4(scaled(grid3), oriented)},
       0.99, 0.05},
      {{"multi-scale", "per-point scales, plane x_a = 0, orthogonal", 20'000, ZeroRate{0, 0},
        valid4(always([](Rng& rng) {
                 return mixed_scale_orthogonal(rng, 4, 1u << rng.integer(0, 2));
               }),
               oriented)},
       0.99, 0},
  };
}

}  // namespace

TEST_CASE("power_test_perturbed (4 coplanar points) agrees with the eps-polynomial oracle") {
  run_perturbed(
      "power_test_perturbed(4)", 43, planar_families(true),
      [](const Case& c) { return kernel::power_test_perturbed(c[0], c[1], c[2], c[3]); },
      [](const Case& c) { return oracle::power_circle_side_perturbed(c[0], c[1], c[2], c[3]); });
}

TEST_CASE("power_circle_side_perturbed agrees with the eps-polynomial oracle") {
  run_perturbed(
      "power_circle_side_perturbed", 44, planar_families(false),
      [](const Case& c) { return kernel::power_circle_side_perturbed(c[0], c[1], c[2], c[3]); },
      [](const Case& c) { return oracle::power_circle_side_perturbed(c[0], c[1], c[2], c[3]); });
}

TEST_CASE("power_segment_side_perturbed agrees with the eps-polynomial oracle") {
  auto line = maybe([](Rng& rng, Points& p) {
    p = integer_collinear(rng, 3);
    return orthogonal_to_random_sphere(rng, p);
  });
  auto short_line = maybe([](Rng& rng, Points& p) {
    const WeightedPoint o = random_integer_vector(rng, 8), d = random_direction(rng);
    p = collinear_points(rng, 3, o.data(), d.data(), 3);
    return orthogonal_to_random_sphere(rng, p);
  });
  const std::vector<PerturbedFamily> families = {
      {{"uniform", "generic, on an axis-parallel line", 20'000, ZeroRate{0, 0},
        valid3(always([](Rng& rng) {
          Points p = uniform_points(rng, 3, -1, 1, -0.5, 0.5);
          p[1].y = p[2].y = p[0].y;
          p[1].z = p[2].z = p[0].z;
          return p;
        }))},
       0, 0},
      {{"degenerate", "integer line orthogonal to one sphere", 60'000, ZeroRate{0, 0}, valid3(line)},
       0.99, 0},
      {{"degenerate", "short integer line orthogonal", 40'000, ZeroRate{0, 0}, valid3(short_line)},
       0.99, 0},
      {{"multi-scale", "integer line orthogonal x 2^k", 20'000, ZeroRate{0, 0}, valid3(scaled(line))},
       0.99, 0},
      {{"multi-scale", "per-point scales on an axis, orthogonal", 20'000, ZeroRate{0, 0},
        valid3(always([](Rng& rng) {
          const int a = static_cast<int>(rng.integer(0, 2));
          return mixed_scale_orthogonal(rng, 3, 0b111u & ~(1u << a));
        }))},
       0.99, 0},
  };
  run_perturbed(
      "power_segment_side_perturbed", 45, families,
      [](const Case& c) { return kernel::power_segment_side_perturbed(c[0], c[1], c[2]); },
      [](const Case& c) { return oracle::power_segment_side_perturbed(c[0], c[1], c[2]); });
}
