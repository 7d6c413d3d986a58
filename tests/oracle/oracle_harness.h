// Driver of the million-input comparisons of the kernel's predicates with the GMP oracle.
//
// A predicate is tested on families of inputs, grouped in four categories: uniform random,
// exactly degenerate, a few ulps from degenerate, and multi-scale (whole configurations scaled
// by 2^k, and magnitudes mixed inside one configuration). Each family states how often the exact
// answer must be 0, and the driver CHECKs it, so that a family that silently stopped producing the
// case it is named after (e.g. a "cospherical" generator whose points are no longer exactly
// cospherical) fails the test instead of testing only easy inputs. Every input is also checked
// to lie in the documented range of the predicates.
//
// Set DELPSC_ORACLE_SCALE (e.g. 0.05) to run fewer inputs while developing, or more (e.g. 10)
// to search harder; the default is the full count (at least one million inputs per predicate).
// DELPSC_ORACLE_SEED changes every family's random stream (default 0: the fixed CI inputs).
#pragma once

#include <doctest/doctest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include <delpsc/kernel/predicates.h>

#include "support/generators.h"

namespace delpsc::test {

/// One input: up to five weighted points (plain predicates ignore the weight) and, for orient2d,
/// a pair of axes.
struct Case {
  std::array<WeightedPoint, 5> pts{};
  int n = 0;
  int i = 0, j = 1;
  const double* operator[](int k) const { return pts[static_cast<std::size_t>(k)].data(); }
  void set(const std::vector<WeightedPoint>& v) {
    n = static_cast<int>(v.size());
    for (std::size_t k = 0; k < v.size() && k < pts.size(); ++k) pts[k] = v[k];
  }
};

/// Bounds on the fraction of inputs of a family whose exact answer is 0.
struct ZeroRate {
  double min = 0, max = 1;
};
inline constexpr ZeroRate kDegenerate{0.9, 1.0};    ///< exactly degenerate by construction
inline constexpr ZeroRate kNearDegenerate{0, 0.5};  ///< non-zero most of the time
inline constexpr ZeroRate kGeneric{0, 0.01};        ///< random: essentially never 0
inline constexpr ZeroRate kAnyRate{0, 1};           ///< mixtures (the family says why)

struct Family {
  const char* category;  ///< "uniform", "degenerate", "near-degenerate", "multi-scale"
  const char* name;
  long cases;  ///< before DELPSC_ORACLE_SCALE
  ZeroRate expect;
  /// Fills the case; returns false to reject a draw that misses the predicate's precondition.
  std::function<bool(Rng&, Case&)> make;
};

/// DELPSC_ORACLE_SCALE, default 1.
inline double oracle_scale() {
  const char* s = std::getenv("DELPSC_ORACLE_SCALE");
  const double v = s ? std::atof(s) : 1.0;
  return v > 0 ? v : 1.0;
}

/// DELPSC_ORACLE_SEED, default 0.
inline std::uint64_t oracle_seed() {
  const char* s = std::getenv("DELPSC_ORACLE_SEED");
  return s ? std::strtoull(s, nullptr, 10) : 0;
}

inline long scaled_count(long n) {
  return std::max(1L, std::lround(static_cast<double>(n) * oracle_scale()));
}

inline void print_case(const Case& c) {
  for (int k = 0; k < c.n; ++k)
    std::printf("    {%a, %a, %a, %a}\n", c[k][0], c[k][1], c[k][2], c[k][3]);
  std::printf("    axes (%d, %d)\n", c.i, c.j);
}

/// Compares ours(c) with exact(c) on every family; prints one summary line per family.
/// Returns the number of inputs compared.
template <class Ours, class Exact>
long run_families(const char* predicate, std::uint64_t seed, const std::vector<Family>& families,
                  Ours ours, Exact exact) {
  long total = 0;
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t f = 0; f < families.size(); ++f) {
    const Family& fam = families[f];
    Rng rng((seed * 1000003u + f) ^ (oracle_seed() * 0x9E3779B97F4A7C15u));
    const long want = scaled_count(fam.cases);
    long made = 0, draws = 0, zeros = 0, mismatches = 0, out_of_range = 0;
    Case c;
    kernel::reset_predicate_statistics();
    while (made < want && draws < 50 * want) {
      ++draws;
      c = Case{};
      if (!fam.make(rng, c)) continue;
      ++made;
      for (int k = 0; k < c.n; ++k)
        if (!in_range(c.pts[static_cast<std::size_t>(k)])) ++out_of_range;
      const int e = exact(c);
      const int o = ours(c);
      if (e == 0) ++zeros;
      if (o != e) {
        if (++mismatches <= 5) {
          std::printf("MISMATCH %s [%s / %s] input %ld: ours %d, exact %d\n", predicate,
                      fam.category, fam.name, made, o, e);
          print_case(c);
        }
      }
    }
    const double rate = made ? static_cast<double>(zeros) / static_cast<double>(made) : 0;
    std::printf("%-26s %-16s %-44s %8ld  zero %6.2f%%", predicate, fam.category, fam.name, made,
                100 * rate);
    if (kernel::statistics_enabled()) {
      // A DELPSC_STATISTICS build also shows how often the filters gave up (all predicates the
      // tested one calls), i.e. how much of the family reaches the exact arithmetic.
      std::uint64_t calls = 0, failures = 0;
      for (const auto& s : kernel::predicate_statistics()) {
        calls += s.calls;
        failures += s.filter_failures;
      }
      std::printf("  exact path %6.2f%% of %llu calls",
                  calls ? 100.0 * static_cast<double>(failures) / static_cast<double>(calls) : 0.0,
                  static_cast<unsigned long long>(calls));
    }
    std::printf("\n");
    INFO(predicate << " / " << fam.category << " / " << fam.name);
    CHECK(made == want);  // the generator is not rejecting nearly everything
    CHECK(out_of_range == 0);
    CHECK(mismatches == 0);
    CHECK(rate >= fam.expect.min);
    CHECK(rate <= fam.expect.max);
    total += made;
  }
  const double secs =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%-26s total %ld inputs, %.1f s\n", predicate, total, secs);
  std::fflush(stdout);
  return total;
}

/// The per-predicate minimum the issue asks for, scaled like the families.
inline long required_total() { return scaled_count(1'000'000); }

}  // namespace delpsc::test
