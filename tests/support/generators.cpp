#include "support/generators.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace delpsc::test {

namespace {

// Error-free transformations (Knuth's TwoSum, and the fma residual of a product): they tell
// whether one rounded operation was exact, which is all the generators need to build exactly
// degenerate sets in doubles.
bool exact_sum(double a, double b, double& s) {
  s = a + b;
  const double bv = s - a;
  const double av = s - bv;
  return std::isfinite(s) && (a - av) + (b - bv) == 0;
}
bool exact_square(double a, double& s) {
  s = a * a;
  return std::isfinite(s) && std::fma(a, a, -s) == 0 && (s == 0 || std::isnormal(s));
}

bool magnitude_in(double x, int min_exp, int max_exp) {
  if (x == 0) return true;
  const double m = std::fabs(x);
  return std::isfinite(m) && m >= std::ldexp(1.0, min_exp) && m <= std::ldexp(1.0, max_exp);
}

// Binary exponent e of |x| in [2^e, 2^(e+1)); x != 0.
int exponent_of(double x) { return std::ilogb(x); }

int floor_div(int a, int b) { return a / b - (a % b != 0 && (a < 0) != (b < 0) ? 1 : 0); }
int ceil_div(int a, int b) { return -floor_div(-a, b); }

}  // namespace

bool coordinate_in_range(double x) {
  return magnitude_in(x, kMinCoordinateExp, kMaxCoordinateExp);
}
bool weight_in_range(double w) { return magnitude_in(w, kMinWeightExp, kMaxWeightExp); }
bool in_range(const WeightedPoint& p) {
  return coordinate_in_range(p.x) && coordinate_in_range(p.y) && coordinate_in_range(p.z) &&
         weight_in_range(p.w);
}

// ---- Rng -------------------------------------------------------------------------------------

double Rng::uniform(double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(engine_);
}

std::int64_t Rng::integer(std::int64_t lo, std::int64_t hi) {
  return std::uniform_int_distribution<std::int64_t>(lo, hi)(engine_);
}

bool Rng::chance(double p) { return std::bernoulli_distribution(p)(engine_); }

double Rng::log_uniform(int min_exp, int max_exp) {
  const int e = static_cast<int>(integer(min_exp, max_exp));
  // 53 random bits with the top one set: a uniformly random mantissa in [1, 2).
  const std::uint64_t bits = (engine_() >> 11) | (std::uint64_t{1} << 52);
  return sign() * std::ldexp(static_cast<double>(bits), e - 52);
}

// ---- building blocks -------------------------------------------------------------------------

std::vector<WeightedPoint> uniform_points(Rng& rng, std::size_t n, double lo, double hi,
                                          double wlo, double whi) {
  std::vector<WeightedPoint> out(n);
  for (auto& p : out) {
    p.x = rng.uniform(lo, hi);
    p.y = rng.uniform(lo, hi);
    p.z = rng.uniform(lo, hi);
    p.w = wlo < whi ? rng.uniform(wlo, whi) : wlo;
  }
  return out;
}

std::vector<WeightedPoint> mixed_scale_points(Rng& rng, std::size_t n, bool weighted,
                                              double zero_chance) {
  auto coordinate = [&] {
    return rng.chance(zero_chance) ? 0.0 : rng.log_uniform(kMinCoordinateExp, kMaxCoordinateExp - 1);
  };
  std::vector<WeightedPoint> out(n);
  for (auto& p : out) {
    p.x = coordinate();
    p.y = coordinate();
    p.z = coordinate();
    p.w = weighted && !rng.chance(zero_chance) ? rng.log_uniform(kMinWeightExp, kMaxWeightExp - 1)
                                               : 0.0;
  }
  return out;
}

std::vector<WeightedPoint> lattice_sphere_points(std::int64_t r2) {
  std::vector<WeightedPoint> out;
  const auto r = static_cast<std::int64_t>(std::sqrt(static_cast<double>(r2))) + 1;
  for (std::int64_t x = -r; x <= r; ++x) {
    for (std::int64_t y = -r; y <= r; ++y) {
      const std::int64_t rest = r2 - x * x - y * y;
      if (rest < 0) continue;
      auto z = static_cast<std::int64_t>(std::sqrt(static_cast<double>(rest)));
      while (z * z > rest) --z;
      while ((z + 1) * (z + 1) <= rest) ++z;
      if (z * z != rest) continue;
      const auto fx = static_cast<double>(x), fy = static_cast<double>(y);
      out.push_back({fx, fy, -static_cast<double>(z), 0});
      if (z != 0) out.push_back({fx, fy, static_cast<double>(z), 0});
    }
  }
  return out;
}

std::vector<WeightedPoint> grid_points(int nx, int ny, int nz, double spacing,
                                       const double* origin) {
  std::vector<WeightedPoint> out;
  const double o[3] = {origin ? origin[0] : 0, origin ? origin[1] : 0, origin ? origin[2] : 0};
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k)
        out.push_back({o[0] + i * spacing, o[1] + j * spacing, o[2] + k * spacing, 0});
  return out;
}

WeightedPoint IntegerPlane::at(std::int64_t u, std::int64_t v) const {
  double c3[3];
  const int iu = axis == 0 ? 1 : 0;
  const int iv = axis == 2 ? 1 : 2;
  c3[iu] = static_cast<double>(u);
  c3[iv] = static_cast<double>(v);
  c3[axis] = static_cast<double>(a * u + b * v + c);
  return {c3[0], c3[1], c3[2], 0};
}

IntegerPlane IntegerPlane::random(Rng& rng, std::int64_t max_slope, std::int64_t max_offset) {
  IntegerPlane p;
  p.axis = static_cast<int>(rng.integer(0, 2));
  p.a = rng.integer(-max_slope, max_slope);
  p.b = rng.integer(-max_slope, max_slope);
  p.c = rng.integer(-max_offset, max_offset);
  return p;
}

std::vector<WeightedPoint> coplanar_points(Rng& rng, std::size_t n, const IntegerPlane& plane,
                                           std::int64_t bound) {
  std::vector<WeightedPoint> out(n);
  for (auto& p : out) p = plane.at(rng.integer(-bound, bound), rng.integer(-bound, bound));
  return out;
}

std::vector<WeightedPoint> collinear_points(Rng& rng, std::size_t n, const double* origin,
                                            const double* direction, std::int64_t kmax,
                                            bool distinct) {
  std::vector<std::int64_t> ks;
  while (ks.size() < n) {
    const std::int64_t k = rng.integer(-kmax, kmax);
    if (distinct && std::find(ks.begin(), ks.end(), k) != ks.end()) continue;
    ks.push_back(k);
  }
  std::vector<WeightedPoint> out;
  for (const std::int64_t k : ks) {
    const auto fk = static_cast<double>(k);
    out.push_back({origin[0] + fk * direction[0], origin[1] + fk * direction[1],
                   origin[2] + fk * direction[2], 0});
  }
  return out;
}

WeightedPoint random_integer_vector(Rng& rng, std::int64_t bound) {
  WeightedPoint v;
  do {
    v = {static_cast<double>(rng.integer(-bound, bound)),
         static_cast<double>(rng.integer(-bound, bound)),
         static_cast<double>(rng.integer(-bound, bound)), 0};
  } while (v.x == 0 && v.y == 0 && v.z == 0);
  return v;
}

std::vector<WeightedPoint> sample_distinct(Rng& rng, const std::vector<WeightedPoint>& pool,
                                           std::size_t k) {
  // Partial Fisher-Yates on indices: O(k) draws.
  std::vector<std::size_t> idx(pool.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
  std::vector<WeightedPoint> out;
  for (std::size_t i = 0; i < k; ++i) {
    const std::size_t j = i + rng.index(idx.size() - i);
    std::swap(idx[i], idx[j]);
    out.push_back(pool[idx[i]]);
  }
  return out;
}

// ---- weights ---------------------------------------------------------------------------------

std::optional<double> orthogonal_weight(const WeightedPoint& p, const double* center, double r2) {
  const double* x = p.data();
  double sum = 0;
  for (int k = 0; k < 3; ++k) {
    double d = 0, d2 = 0, s = 0;
    if (!exact_sum(x[k], -center[k], d) || !exact_square(d, d2) || !exact_sum(sum, d2, s))
      return std::nullopt;
    sum = s;
  }
  double w = 0;
  if (!exact_sum(sum, -r2, w)) return std::nullopt;
  return w;
}

bool set_orthogonal_weights(std::vector<WeightedPoint>& points, const double* center, double r2) {
  for (auto& p : points) {
    const auto w = orthogonal_weight(p, center, r2);
    if (!w) return false;
    p.w = *w;
  }
  return true;
}

void set_weights(std::vector<WeightedPoint>& points, double w) {
  for (auto& p : points) p.w = w;
}

// ---- moving a little, scaling ----------------------------------------------------------------

double nudge(double x, int ulps, int min_exp) {
  if (ulps == 0) return x;
  const double smallest = std::ldexp(1.0, min_exp);
  if (x == 0) return std::copysign(smallest, static_cast<double>(ulps));
  const double toward = ulps > 0 ? INFINITY : -INFINITY;
  double y = x;
  for (int i = 0; i < std::abs(ulps); ++i) y = std::nextafter(y, toward);
  // Moving toward zero below the smallest allowed magnitude would leave the range: move away
  // from zero instead.
  if (std::fabs(y) < smallest) return nudge(x, -ulps, min_exp);
  return y;
}

void nudge_randomly(Rng& rng, std::vector<WeightedPoint>& points, int moves, int max_ulps,
                    unsigned axes_mask) {
  std::vector<int> axes;
  for (int k = 0; k < 4; ++k)
    if (axes_mask & (1u << k)) axes.push_back(k);
  if (axes.empty() || points.empty()) return;
  for (int m = 0; m < moves; ++m) {
    WeightedPoint& p = points[rng.index(points.size())];
    const int k = axes[rng.index(axes.size())];
    const int ulps = static_cast<int>(rng.integer(1, max_ulps)) * rng.sign();
    p.data()[k] = nudge(p.data()[k], ulps, k == 3 ? kMinWeightExp : kMinCoordinateExp);
  }
}

std::pair<int, int> scale_bounds(const std::vector<WeightedPoint>& points) {
  // 2^k |x| must stay in [2^-140, 2^140] and 2^2k |w| in [2^-280, 2^280].
  int kmin = -100000, kmax = 100000;
  auto constrain = [&](double v, int min_exp, int max_exp, int degree) {
    if (v == 0) return;
    const int e = exponent_of(v);  // |v| in [2^e, 2^(e+1))
    const bool power_of_two = std::fabs(v) == std::ldexp(1.0, e);
    // degree*k + e >= min_exp, and |v| 2^(degree*k) <= 2^max_exp.
    kmin = std::max(kmin, ceil_div(min_exp - e, degree));
    kmax = std::min(kmax, floor_div(power_of_two ? max_exp - e : max_exp - e - 1, degree));
  };
  for (const auto& p : points) {
    constrain(p.x, kMinCoordinateExp, kMaxCoordinateExp, 1);
    constrain(p.y, kMinCoordinateExp, kMaxCoordinateExp, 1);
    constrain(p.z, kMinCoordinateExp, kMaxCoordinateExp, 1);
    constrain(p.w, kMinWeightExp, kMaxWeightExp, 2);
  }
  return {kmin, kmax};
}

void scale_pow2(std::vector<WeightedPoint>& points, int k) {
  for (auto& p : points) {
    p.x = std::ldexp(p.x, k);
    p.y = std::ldexp(p.y, k);
    p.z = std::ldexp(p.z, k);
    p.w = std::ldexp(p.w, 2 * k);
  }
}

void scale_randomly(Rng& rng, std::vector<WeightedPoint>& points) {
  const auto [kmin, kmax] = scale_bounds(points);
  if (kmin > kmax) return;
  scale_pow2(points, static_cast<int>(rng.integer(kmin, kmax)));
}

bool translate_exactly(std::vector<WeightedPoint>& points, const WeightedPoint& offset) {
  std::vector<WeightedPoint> moved = points;
  for (auto& p : moved) {
    for (int k = 0; k < 3; ++k) {
      double s = 0;
      if (!exact_sum(p.data()[k], offset.data()[k], s) || !coordinate_in_range(s)) return false;
      p.data()[k] = s;
    }
  }
  points = std::move(moved);
  return true;
}

std::vector<WeightedPoint> unit_cube_edge_balls(double spacing, double radius) {
  std::vector<WeightedPoint> balls;
  for (int axis = 0; axis < 3; ++axis)
    for (int corner = 0; corner < 4; ++corner)
      for (double t = 0; t <= 1 + 1e-9; t += spacing) {
        Vec3 c;
        c[axis] = t;
        c[(axis + 1) % 3] = corner & 1;
        c[(axis + 2) % 3] = corner >> 1;
        balls.push_back(WeightedPoint::from(c, radius * radius));
      }
  return balls;
}

}  // namespace delpsc::test
