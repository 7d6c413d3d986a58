#include "point_generators.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace delpsc::io {

namespace {

// [0,1) from the top 53 bits: std::uniform_real_distribution's output is implementation-defined.
double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

// Standard normal by Box-Muller on our own uniforms, for the same reason.
double normal(std::mt19937_64& rng) {
  const double u1 = 1.0 - unit(rng), u2 = unit(rng);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
}

}  // namespace

std::vector<WeightedPoint> uniform_points(std::size_t n, std::uint64_t seed) {
  return weighted_points(n, 0.0, seed);
}

std::vector<WeightedPoint> weighted_points(std::size_t n, double max_weight, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<WeightedPoint> pts(n);
  for (auto& p : pts) {
    p.x = unit(rng);
    p.y = unit(rng);
    p.z = unit(rng);
    p.w = max_weight > 0 ? max_weight * unit(rng) : 0.0;
  }
  return pts;
}

std::vector<WeightedPoint> sphere_points(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<WeightedPoint> pts(n);
  for (auto& p : pts) {
    double v[3], len2 = 0;
    do {
      for (double& c : v) c = normal(rng);
      len2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    } while (len2 < 1e-12);
    const double inv = 1.0 / std::sqrt(len2);
    p = {v[0] * inv, v[1] * inv, v[2] * inv, 0.0};
  }
  return pts;
}

std::vector<WeightedPoint> grid_points(std::size_t k, std::uint64_t seed) {
  std::vector<WeightedPoint> pts;
  pts.reserve(k * k * k);
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = 0; j < k; ++j)
      for (std::size_t l = 0; l < k; ++l)
        pts.push_back({double(i), double(j), double(l), 0.0});
  std::mt19937_64 rng(seed);
  for (std::size_t i = pts.size(); i > 1; --i) std::swap(pts[i - 1], pts[rng() % i]);
  return pts;
}

GeneratorSpec parse_generator(const std::string& spec) {
  const auto colon = spec.find(':');
  if (colon == std::string::npos)
    throw std::invalid_argument("generator '" + spec + "': expected KIND:N, e.g. uniform:100000");
  const std::string kind = spec.substr(0, colon);
  std::size_t n = 0;
  try {
    std::size_t used = 0;
    const long long v = std::stoll(spec.substr(colon + 1), &used);
    if (used != spec.size() - colon - 1 || v <= 0) throw std::invalid_argument("count");
    n = static_cast<std::size_t>(v);
  } catch (const std::exception&) {
    throw std::invalid_argument("generator '" + spec + "': N must be a positive whole number");
  }
  if (n > 200'000'000)
    throw std::invalid_argument("generator '" + spec + "': N is larger than 2e8 points");
  if (kind != "uniform" && kind != "weighted" && kind != "sphere" && kind != "grid")
    throw std::invalid_argument("generator '" + spec + "': unknown kind (uniform, weighted, sphere, grid)");
  return {kind, n};
}

std::vector<WeightedPoint> generate_points(const std::string& spec, std::uint64_t seed) {
  const auto [kind, n] = parse_generator(spec);
  if (kind == "uniform") return uniform_points(n, seed);
  if (kind == "weighted") {
    const double r = 0.1 * std::cbrt(1.0 / static_cast<double>(n));
    return weighted_points(n, r * r, seed);
  }
  if (kind == "grid") {
    auto k = static_cast<std::size_t>(std::cbrt(static_cast<double>(n)) + 1e-9);
    while ((k + 1) * (k + 1) * (k + 1) <= n) ++k;
    return grid_points(std::max<std::size_t>(k, 1), seed);
  }
  return sphere_points(n, seed);  // kind == "sphere" (parse_generator accepts no other)
}

}  // namespace delpsc::io
