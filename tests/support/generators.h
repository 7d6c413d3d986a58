// Point-set generators for tests: uniform random sets, exactly degenerate sets (coplanar,
// collinear, cospherical, grids, weights orthogonal to one sphere, equal weights), sets a few ulps
// away from degenerate, and sets spanning many orders of magnitude.
//
// Everything is a WeightedPoint (w = 0 for plain points), so the same set feeds both the plain
// and the weighted predicates. "Exactly degenerate" means degenerate in the doubles themselves:
// the constructions use integers (exact below 2^53), powers of two and error-free checks, never a
// rounded formula. Everything is deterministic given the Rng seed.
//
// Range: the predicates are exact for coordinates 0 or |x| in [2^-140, 2^140] and weights 0 or
// |w| in [2^-280, 2^280] (kernel/predicates.h). Generators that take magnitudes stay inside it;
// in_range() checks a point, and scale_bounds() tells how far a set may be scaled by 2^k.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include <delpsc/kernel/point.h>

namespace delpsc::test {

// ---- range of the exact predicates ----------------------------------------------------------

inline constexpr int kMinCoordinateExp = -140;  ///< smallest allowed |coordinate| is 2^-140
inline constexpr int kMaxCoordinateExp = 140;   ///< largest allowed |coordinate| is 2^140
inline constexpr int kMinWeightExp = -280;
inline constexpr int kMaxWeightExp = 280;

bool coordinate_in_range(double x);
bool weight_in_range(double w);
/// Coordinates and weight of p all in range.
bool in_range(const WeightedPoint& p);

// ---- random numbers -------------------------------------------------------------------------

/// A seeded 64-bit Mersenne twister with the few draws the generators need.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi);
  /// Uniform integer in [lo, hi] (inclusive).
  std::int64_t integer(std::int64_t lo, std::int64_t hi);
  /// True with probability p.
  bool chance(double p);
  /// -1 or +1.
  int sign() { return chance(0.5) ? 1 : -1; }
  /// A double of random sign whose magnitude has a uniformly random binary exponent in
  /// [min_exp, max_exp] and a full random 53-bit mantissa: |x| in [2^min_exp, 2^(max_exp+1)).
  double log_uniform(int min_exp, int max_exp);
  /// Index in [0, n).
  std::size_t index(std::size_t n) { return static_cast<std::size_t>(integer(0, static_cast<std::int64_t>(n) - 1)); }
  std::mt19937_64& engine() { return engine_; }

 private:
  std::mt19937_64 engine_;
};

// ---- building blocks ------------------------------------------------------------------------

/// n points uniform in the cube [lo, hi)^3, weights uniform in [wlo, whi) (0 when wlo == whi == 0).
std::vector<WeightedPoint> uniform_points(Rng& rng, std::size_t n, double lo, double hi,
                                          double wlo = 0, double whi = 0);

/// n points whose every coordinate is, independently, 0 with probability zero_chance or else
/// log-uniform over the whole coordinate range; weights likewise over the weight range when
/// weighted. Magnitudes inside one set then differ by up to 2^280.
std::vector<WeightedPoint> mixed_scale_points(Rng& rng, std::size_t n, bool weighted,
                                              double zero_chance = 0.1);

/// All integer points (x, y, z) with x^2 + y^2 + z^2 = r2, in lexicographic order. O(r2) time.
std::vector<WeightedPoint> lattice_sphere_points(std::int64_t r2);

/// The regular grid {0..nx-1} x {0..ny-1} x {0..nz-1} times spacing, offset by origin.
std::vector<WeightedPoint> grid_points(int nx, int ny, int nz, double spacing = 1,
                                       const double* origin = nullptr);

/// An integer plane: coordinate `axis` equals a*u + b*v + c, where (u, v) are the two other
/// coordinates in increasing axis order. axis = 2, a = b = 0 is the plane z = c.
struct IntegerPlane {
  int axis = 2;
  std::int64_t a = 0, b = 0, c = 0;
  /// The point of the plane with free coordinates (u, v); exact while |a u + b v + c| < 2^53.
  WeightedPoint at(std::int64_t u, std::int64_t v) const;
  /// A random plane with |a|, |b| <= max_slope, |c| <= max_offset, random axis.
  static IntegerPlane random(Rng& rng, std::int64_t max_slope, std::int64_t max_offset);
};

/// n random points of `plane` with free coordinates in [-bound, bound].
std::vector<WeightedPoint> coplanar_points(Rng& rng, std::size_t n, const IntegerPlane& plane,
                                           std::int64_t bound);

/// n points origin + k * direction with random integers k in [-kmax, kmax] (distinct when
/// distinct = true and 2*kmax+1 >= n). Exact while the coordinates stay integers below 2^53.
std::vector<WeightedPoint> collinear_points(Rng& rng, std::size_t n, const double* origin,
                                            const double* direction, std::int64_t kmax,
                                            bool distinct = true);

/// A random integer vector with coordinates in [-bound, bound], not all zero.
WeightedPoint random_integer_vector(Rng& rng, std::int64_t bound);

/// k distinct elements of pool (k <= pool.size()), in random order.
std::vector<WeightedPoint> sample_distinct(Rng& rng, const std::vector<WeightedPoint>& pool,
                                           std::size_t k);

/// Balls along the twelve edges of the unit cube [0, 1]³, as protection puts them: of radius
/// `radius` (weight radius²), one every `spacing` from each edge's start (`spacing` > 0).
std::vector<WeightedPoint> unit_cube_edge_balls(double spacing, double radius);

// ---- weights --------------------------------------------------------------------------------

/// |p - center|^2 - r2 when every step of its evaluation in doubles is exact (checked with
/// error-free transformations), nullopt otherwise. Giving each point this weight makes the
/// point orthogonal to the sphere (center, r2): all such points have one common orthosphere,
/// so every power test among them is exactly zero.
std::optional<double> orthogonal_weight(const WeightedPoint& p, const double* center, double r2);

/// Sets every weight to orthogonal_weight(p, center, r2); false (and the set unchanged in part)
/// if one of them is not exact.
bool set_orthogonal_weights(std::vector<WeightedPoint>& points, const double* center, double r2);

/// Sets every weight to w.
void set_weights(std::vector<WeightedPoint>& points, double w);

// ---- moving a little, scaling by powers of two ----------------------------------------------

/// x moved by `ulps` steps of std::nextafter (toward +inf if ulps > 0). To stay in the
/// predicates' range, a zero moves to +-2^min_exp instead of into the subnormals, and a move
/// toward zero that would pass below 2^min_exp goes the other way.
double nudge(double x, int ulps, int min_exp = kMinCoordinateExp);

/// Moves `moves` randomly chosen coordinates (or weights, if weights = true and chosen) of the
/// set by 1..max_ulps ulps in a random direction. Only the listed coordinate axes are touched
/// (axes_mask bit k = coordinate k may move; bit 3 = the weight may move).
void nudge_randomly(Rng& rng, std::vector<WeightedPoint>& points, int moves, int max_ulps,
                    unsigned axes_mask = 0b0111);

/// Interval [kmin, kmax] of the k such that multiplying every coordinate by 2^k and every weight
/// by 2^(2k) keeps the set in range (empty interval, kmin > kmax, if none).
std::pair<int, int> scale_bounds(const std::vector<WeightedPoint>& points);

/// Coordinates times 2^k, weights times 2^(2k): exact, and every power test and orientation keeps
/// its sign (the polynomials are homogeneous with weights of degree 2).
void scale_pow2(std::vector<WeightedPoint>& points, int k);

/// scale_pow2 by a k drawn uniformly from scale_bounds(points) (no-op if that is empty).
void scale_randomly(Rng& rng, std::vector<WeightedPoint>& points);

/// Adds offset (x, y, z; its weight is ignored) to every point if every sum is exact (checked
/// with an error-free transformation) and in range; returns false and leaves the points
/// unchanged otherwise. Weights are kept: translating the orthosphere's centre with the points
/// keeps every power test.
bool translate_exactly(std::vector<WeightedPoint>& points, const WeightedPoint& offset);

}  // namespace delpsc::test
