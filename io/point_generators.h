// Synthetic point sets: the demo's input, the benchmarks' workloads and the tests' stress cases.
// Deterministic for a given seed (std::mt19937_64 with explicitly computed distributions, so the
// same seed gives the same points on every platform and standard library).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <delpsc/kernel/point.h>

namespace delpsc::io {

/// n points uniform in [0,1)^3, weight 0.
std::vector<WeightedPoint> uniform_points(std::size_t n, std::uint64_t seed);

/// n points uniform in [0,1)^3 with weights uniform in [0, max_weight).
std::vector<WeightedPoint> weighted_points(std::size_t n, double max_weight, std::uint64_t seed);

/// n points on the unit sphere centred at the origin (normalised Gaussian vectors, rounded to
/// doubles, so nearly but not exactly cospherical: the filters fail often).
std::vector<WeightedPoint> sphere_points(std::size_t n, std::uint64_t seed);

/// The points of the k x k x k integer grid {0..k-1}^3 in random order (exactly degenerate:
/// coplanar and cospherical subsets everywhere), weight 0.
std::vector<WeightedPoint> grid_points(std::size_t k, std::uint64_t seed);

/// A named generator, "KIND:N" with KIND uniform | weighted | sphere | grid (N = point count;
/// for grid the side is the cube root of N rounded down). For weighted the weights are uniform in
/// [0, (0.1 N^(-1/3))^2), balls a tenth of the mean spacing. Throws std::invalid_argument with a
/// message on an unknown kind or a bad count.
std::vector<WeightedPoint> generate_points(const std::string& spec, std::uint64_t seed);

/// A generator spec taken apart, checked as generate_points checks it (same exceptions): lets a
/// caller weigh the count before any point is made.
struct GeneratorSpec {
  std::string kind;
  std::size_t count = 0;
};
GeneratorSpec parse_generator(const std::string& spec);

}  // namespace delpsc::io
