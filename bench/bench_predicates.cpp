// Cost of the exact predicates (issue 2): the filtered path on random inputs, the exact path on
// degenerate inputs, each next to a plain double evaluation of the same formula (no filter, not
// robust) on the same inputs, so that "filtered / plain" is a ratio measured within one run.
//
// Reading the output: one benchmark iteration makes kCallsPerIteration = 1000 predicate calls
// and time is reported in microseconds, so the Time column reads directly as nanoseconds per
// call (items_per_second gives the same figure as a rate).
//
// Inputs: each workload is a pool of at most a few thousand (weighted) points and 2^16 index
// tuples into it, walked in order and cyclically. The pool stays in L2 and the tuples stream
// sequentially, so the figures measure arithmetic and branches, not memory bandwidth; 2^16
// distinct random tuples are too many for the branch predictor to learn the outcomes.
// Results are summed into a sink passed to benchmark::DoNotOptimize after every batch, so no call
// can be removed.
//
// Workload names:
//   random           uniform in [0,1)^3 (full double precision), weights uniform in [0, 0.01)
//   *_int            exactly degenerate, integer coordinates: differences are exact, expansions
//                    stay short (the cheap exact path)
//   coplanar_real, collinear_real
//                    exactly degenerate with non-integer coordinates whose differences are not
//                    representable (points on the plane x + y = 1, Sterbenz makes y = 1 - x exact)
//   near_*           points (and weights) rounded from an exact sphere/plane/line: the filter
//                    fails, the exact sign is non-zero and every expansion is full length (the
//                    expensive path, e.g. points sampled on a sphere)
//
// Filter statistics: with -DDELPSC_STATISTICS=ON, each benchmark first makes one untimed pass
// over its 2^16 tuples and reports, for every predicate counter that moved, the percentage of
// calls that needed the exact path (counters "exact%_<predicate>").
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <delpsc/kernel/predicates.h>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

using delpsc::WeightedPoint;
namespace k = delpsc::kernel;

constexpr int kCallsPerIteration = 1000;
constexpr std::size_t kSets = std::size_t{1} << 16;  // a power of two: the walk wraps by masking
constexpr std::size_t kPool = 4096;

// ---------------------------------------------------------------------------------------------
// Plain double evaluations: the filters' formulas, term for term, without the error bound.
// ---------------------------------------------------------------------------------------------
namespace plain {

inline int sign_of(double v) { return (v > 0) - (v < 0); }

inline int orient3d(const double* p, const double* q, const double* r, const double* s) {
  const double ax = q[0] - p[0], ay = q[1] - p[1], az = q[2] - p[2];
  const double bx = r[0] - p[0], by = r[1] - p[1], bz = r[2] - p[2];
  const double cx = s[0] - p[0], cy = s[1] - p[1], cz = s[2] - p[2];
  return sign_of(ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx));
}

inline int orient2d(const double* p, const double* q, const double* r, int i, int j) {
  return sign_of((q[i] - p[i]) * (r[j] - p[j]) - (q[j] - p[j]) * (r[i] - p[i]));
}

inline int coplanar_orientation(const double* p, const double* q, const double* r) {
  if (const int o = orient2d(p, q, r, 0, 1); o != 0) return o;
  if (const int o = orient2d(p, q, r, 1, 2); o != 0) return o;
  return orient2d(p, q, r, 0, 2);
}

template <bool Weighted>
inline int power_test(const double* p, const double* q, const double* r, const double* s,
                      const double* t) {
  const double dpx = p[0] - t[0], dpy = p[1] - t[1], dpz = p[2] - t[2];
  const double dqx = q[0] - t[0], dqy = q[1] - t[1], dqz = q[2] - t[2];
  const double drx = r[0] - t[0], dry = r[1] - t[1], drz = r[2] - t[2];
  const double dsx = s[0] - t[0], dsy = s[1] - t[1], dsz = s[2] - t[2];
  double lp = dpx * dpx + dpy * dpy + dpz * dpz;
  double lq = dqx * dqx + dqy * dqy + dqz * dqz;
  double lr = drx * drx + dry * dry + drz * drz;
  double ls = dsx * dsx + dsy * dsy + dsz * dsz;
  if constexpr (Weighted) {
    lp += t[3] - p[3];
    lq += t[3] - q[3];
    lr += t[3] - r[3];
    ls += t[3] - s[3];
  }
  const double pq = dpx * dqy - dqx * dpy;
  const double pr = dpx * dry - drx * dpy;
  const double ps = dpx * dsy - dsx * dpy;
  const double qr = dqx * dry - drx * dqy;
  const double qs = dqx * dsy - dsx * dqy;
  const double rs = drx * dsy - dsx * dry;
  const double pqr = dpz * qr - dqz * pr + drz * pq;
  const double pqs = dpz * qs - dqz * ps + dsz * pq;
  const double prs = dpz * rs - drz * ps + dsz * pr;
  const double qrs = dqz * rs - drz * qs + dsz * qr;
  return -sign_of((ls * pqr - lr * pqs) + (lq * prs - lp * qrs));
}

// The library's 4-point test: first projection (xy, xz, yz) with a non-zero lifted determinant,
// times the orientation of p, q, r in it.
inline int planar_power_test(const double* p, const double* q, const double* r, const double* t) {
  static constexpr int kAxes[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  const double* pts[3] = {p, q, r};
  for (const auto& ax : kAxes) {
    double da[3], db[3], lift[3];
    for (int i = 0; i < 3; ++i) {
      const double d[3] = {pts[i][0] - t[0], pts[i][1] - t[1], pts[i][2] - t[2]};
      lift[i] = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + (t[3] - pts[i][3]);
      da[i] = d[ax[0]];
      db[i] = d[ax[1]];
    }
    const double det = lift[0] * (da[1] * db[2] - da[2] * db[1]) -
                       lift[1] * (da[0] * db[2] - da[2] * db[0]) +
                       lift[2] * (da[0] * db[1] - da[1] * db[0]);
    if (det != 0) return sign_of(det) * orient2d(p, q, r, ax[0], ax[1]);
  }
  return 0;
}

inline int linear_power_test(const double* p, const double* q, const double* t) {
  for (int a = 0; a < 3; ++a) {
    if (p[a] == q[a]) continue;
    double lp = t[3] - p[3], lq = t[3] - q[3];
    for (int c = 0; c < 3; ++c) {
      lp += (p[c] - t[c]) * (p[c] - t[c]);
      lq += (q[c] - t[c]) * (q[c] - t[c]);
    }
    const int cmp = p[a] < q[a] ? -1 : 1;
    return cmp * sign_of((p[a] - t[a]) * lq - (q[a] - t[a]) * lp);
  }
  return 0;
}

inline int power_distance_sign(const double* x, const double* c) {
  const double dx = x[0] - c[0], dy = x[1] - c[1], dz = x[2] - c[2];
  return sign_of(dx * dx + dy * dy + dz * dz - c[3]);
}

}  // namespace plain

// ---------------------------------------------------------------------------------------------
// Workloads: a pool of weighted points and kSets tuples of indices into it.
// ---------------------------------------------------------------------------------------------

struct Workload {
  std::vector<WeightedPoint> pool;
  std::vector<std::uint32_t> sets;  // arity indices per tuple, kSets tuples
  int arity = 0;
};

using Rng = std::mt19937_64;

double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
long integer(Rng& rng, long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(rng); }

// Which extra condition a tuple must meet (the predicates' preconditions).
enum class Tuple {
  any,             // distinct indices
  positive,        // first four positively oriented (swap the first two if needed), never flat
  non_collinear,   // first three not collinear (planar power test)
  distinct_first,  // first two differ in position (linear power test)
};

// kSets tuples of distinct pool indices meeting `rule`. Deterministic (fixed seed).
std::vector<std::uint32_t> make_tuples(const std::vector<WeightedPoint>& pool, int arity,
                                       Tuple rule, std::uint64_t seed) {
  Rng rng(seed);
  std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(pool.size() - 1));
  std::vector<std::uint32_t> sets;
  sets.reserve(kSets * static_cast<std::size_t>(arity));
  std::uint32_t t[5] = {};
  while (sets.size() < kSets * static_cast<std::size_t>(arity)) {
    bool distinct = true;
    for (int i = 0; i < arity; ++i) {
      t[i] = pick(rng);
      for (int j = 0; j < i; ++j) distinct = distinct && t[i] != t[j];
    }
    if (!distinct) continue;
    const double* p[5] = {};
    for (int i = 0; i < arity; ++i) p[i] = pool[t[i]].data();
    if (rule == Tuple::positive) {
      const int o = k::orient3d(p[0], p[1], p[2], p[3]);
      if (o == 0) continue;
      if (o < 0) std::swap(t[0], t[1]);
    } else if (rule == Tuple::non_collinear) {
      if (k::collinear(p[0], p[1], p[2])) continue;
    } else if (rule == Tuple::distinct_first) {
      if (k::compare_xyz(p[0], p[1]) == 0) continue;
    }
    sets.insert(sets.end(), t, t + arity);
  }
  return sets;
}

// ---- pools ------------------------------------------------------------------------------------

// Uniform in [0,1)^3, full precision; weights uniform in [0, max_weight).
std::vector<WeightedPoint> random_cube(double max_weight, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<WeightedPoint> pool(kPool);
  for (auto& p : pool) p = {uniform(rng, 0, 1), uniform(rng, 0, 1), uniform(rng, 0, 1),
                            uniform(rng, 0, max_weight)};
  return pool;
}

// Weights making every point exactly orthogonal to the sphere (c, W): w = |p - c|^2 - W.
// Exact when p, c and W are integers (all the *_int pools); rounded otherwise (near_* pools).
void orthogonal_weights(std::vector<WeightedPoint>& pool, const double* c, double W) {
  for (auto& p : pool) {
    const double dx = p.x - c[0], dy = p.y - c[1], dz = p.z - c[2];
    p.w = dx * dx + dy * dy + dz * dz - W;
  }
}

// Integer points of the tilted plane z = 2x - 3y + 7 (never an axis plane: no coordinate column
// of differences vanishes, so the filters' zero-column shortcuts do not apply).
std::vector<WeightedPoint> integer_plane(std::uint64_t seed) {
  Rng rng(seed);
  std::vector<WeightedPoint> pool(kPool);
  for (auto& p : pool) {
    const long x = integer(rng, -1024, 1024), y = integer(rng, -1024, 1024);
    p = {double(x), double(y), double(2 * x - 3 * y + 7), 0};
  }
  const double c[3] = {5, -3, 40};  // off the plane: every weight is >= its squared distance 14
  orthogonal_weights(pool, c, 10);
  return pool;
}

// Points on the plane x + y = 1 with x in [0.5, 1): y = 1 - x is exact (Sterbenz), z is a full
// precision double, so the points are exactly coplanar but their differences are not doubles.
std::vector<WeightedPoint> real_plane(std::uint64_t seed) {
  Rng rng(seed);
  std::vector<WeightedPoint> pool(kPool);
  for (auto& p : pool) {
    const double x = uniform(rng, 0.5, 1);
    p = {x, 1 - x, uniform(rng, 0, 1), uniform(rng, 0, 0.01)};
  }
  return pool;
}

// Dyadic points (multiples of 2^-20) exactly on the tilted plane z = x/4 + y/2 + 1/8: generic
// coplanar inputs for the planar power test's filter path. Weights uniform in [0, 0.01).
std::vector<WeightedPoint> dyadic_plane(std::uint64_t seed) {
  Rng rng(seed);
  std::vector<WeightedPoint> pool(kPool);
  for (auto& p : pool) {
    const double x = std::ldexp(double(integer(rng, 0, (1 << 20) - 1)), -20);
    const double y = std::ldexp(double(integer(rng, 0, (1 << 20) - 1)), -20);
    p = {x, y, 0.25 * x + 0.5 * y + 0.125, uniform(rng, 0, 0.01)};
  }
  return pool;
}

// Full-precision points rounded onto the plane z = 0.3 x + 0.7 y + 0.1, weights rounded from
// orthogonality to a sphere: the planar power test's expensive path (orient3d's too).
std::vector<WeightedPoint> near_plane(std::uint64_t seed) {
  Rng rng(seed);
  std::vector<WeightedPoint> pool(kPool);
  for (auto& p : pool) {
    const double x = uniform(rng, 0, 1), y = uniform(rng, 0, 1);
    p = {x, y, 0.3 * x + 0.7 * y + 0.1, 0};
  }
  const double c[3] = {0.41, 0.53, 0.2};
  orthogonal_weights(pool, c, 0.01);
  return pool;
}

// Integer points on the line a + k d; weights exactly orthogonal to one sphere.
std::vector<WeightedPoint> integer_line(std::uint64_t seed) {
  Rng rng(seed);
  std::vector<WeightedPoint> pool(kPool);
  for (auto& p : pool) {
    const long s = integer(rng, -1000, 1000);
    p = {double(11 + 3 * s), double(13 - 5 * s), double(-17 + 7 * s), 0};
  }
  const double c[3] = {2, 9, -4};  // off the line, squared distance > 10
  orthogonal_weights(pool, c, 10);
  return pool;
}

// Points (x, 1 - x, 1 - x), x in [0.5, 1): exactly collinear, inexact differences, and no axis
// projection is degenerate by a constant coordinate.
std::vector<WeightedPoint> real_line(std::uint64_t seed) {
  Rng rng(seed);
  std::vector<WeightedPoint> pool(kPool);
  for (auto& p : pool) {
    const double x = uniform(rng, 0.5, 1);
    p = {x, 1 - x, 1 - x, uniform(rng, 0, 0.01)};
  }
  return pool;
}

// Full-precision points rounded onto a line, weights rounded from orthogonality to a sphere.
std::vector<WeightedPoint> near_line(std::uint64_t seed) {
  Rng rng(seed);
  std::vector<WeightedPoint> pool(kPool);
  for (auto& p : pool) {
    const double s = uniform(rng, 0, 1);
    p = {0.1 + 0.3 * s, 0.2 + 0.7 * s, 0.9 - 0.6 * s, 0};
  }
  const double c[3] = {0.5, 0.3, 0.4};
  orthogonal_weights(pool, c, 0.01);
  return pool;
}

// Integer points in [-1024, 1024]^3 with weights exactly orthogonal to one sphere: the 5-point
// power test is exactly 0 on every tuple, with short expansions.
std::vector<WeightedPoint> integer_orthogonal(std::uint64_t seed) {
  Rng rng(seed);
  std::vector<WeightedPoint> pool(kPool);
  for (auto& p : pool)
    p = {double(integer(rng, -1024, 1024)), double(integer(rng, -1024, 1024)),
         double(integer(rng, -1024, 1024)), 0};
  const double c[3] = {3, -7, 11};
  orthogonal_weights(pool, c, 10);  // w may be negative within distance sqrt(10) of c; harmless
  return pool;
}

// Full-precision points in [0,1)^3 with weights rounded from orthogonality to one sphere.
std::vector<WeightedPoint> near_orthogonal(std::uint64_t seed) {
  auto pool = random_cube(0, seed);
  const double c[3] = {0.47, 0.52, 0.61};
  orthogonal_weights(pool, c, 0.01);
  return pool;
}

// All integer points of the sphere |p|^2 = 30030 (r3(30030) is in the thousands), translated by
// an integer vector: exactly cospherical with exact differences.
std::vector<WeightedPoint> integer_sphere() {
  constexpr long n = 30030, r = 174;  // 173^2 < 30030 < 174^2
  std::vector<WeightedPoint> pool;
  for (long x = -r; x <= r; ++x)
    for (long y = -r; y <= r; ++y) {
      const long zz = n - x * x - y * y;
      if (zz < 0) continue;
      const long z = std::lround(std::sqrt(double(zz)));
      if (z * z != zz) continue;
      pool.push_back({double(x + 17), double(y - 5), double(z + 3), 0});
      if (z != 0) pool.push_back({double(x + 17), double(y - 5), double(-z + 3), 0});
    }
  return pool;
}

// Unit vectors (normalised Gaussian samples) rounded to doubles: nearly cospherical, inexact
// differences; insphere's expensive path.
std::vector<WeightedPoint> near_sphere(std::uint64_t seed) {
  Rng rng(seed);
  std::normal_distribution<double> gauss;
  std::vector<WeightedPoint> pool(kPool);
  for (auto& p : pool) {
    const double x = gauss(rng), y = gauss(rng), z = gauss(rng);
    const double len = std::sqrt(x * x + y * y + z * z);
    p = {x / len, y / len, z / len, 0};
  }
  return pool;
}

// Pairs (x, c) for power_distance_sign: pool entries 2i and 2i+1, tuples pick random pairs.
Workload pairs(std::vector<WeightedPoint> pool, std::uint64_t seed) {
  Rng rng(seed);
  std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(pool.size() / 2 - 1));
  Workload w;
  w.arity = 2;
  w.sets.reserve(2 * kSets);
  for (std::size_t i = 0; i < kSets; ++i) {
    const std::uint32_t j = pick(rng);
    w.sets.push_back(2 * j);
    w.sets.push_back(2 * j + 1);
  }
  w.pool = std::move(pool);
  return w;
}

// Random pairs: x in [0,1)^3, c in [0,1)^3 with weight in [0, 0.25) (radius up to 0.5, so both
// signs occur often).
Workload random_pairs() { return pairs(random_cube(0.25, 21), 22); }

// Pairs with w_c = |x - c|^2 exactly (integers) or rounded (full precision).
Workload distance_pairs(bool exact) {
  Rng rng(23);
  std::vector<WeightedPoint> pool(kPool);
  for (std::size_t i = 0; i < kPool; i += 2) {
    WeightedPoint& x = pool[i];
    WeightedPoint& c = pool[i + 1];
    for (double* v : {&x.x, &x.y, &x.z, &c.x, &c.y, &c.z})
      *v = exact ? double(integer(rng, -1024, 1024)) : uniform(rng, 0, 1);
    const double dx = x.x - c.x, dy = x.y - c.y, dz = x.z - c.z;
    c.w = dx * dx + dy * dy + dz * dz;
  }
  return pairs(std::move(pool), 24);
}

Workload tuples(std::vector<WeightedPoint> pool, int arity, Tuple rule, std::uint64_t seed) {
  Workload w;
  w.sets = make_tuples(pool, arity, rule, seed);
  w.pool = std::move(pool);
  w.arity = arity;
  return w;
}

// ---------------------------------------------------------------------------------------------
// Running
// ---------------------------------------------------------------------------------------------

template <class F, std::size_t... I>
inline int call(const F& f, const WeightedPoint* pool, const std::uint32_t* t,
                std::index_sequence<I...>) {
  return f(pool[t[I]].data()...);
}

const char* predicate_name(int i) {
  static constexpr const char* kNames[] = {"orient3d",      "orient2d",      "insphere",
                                           "power_test_3d", "power_test_2d", "power_test_1d",
                                           "power_distance"};
  return kNames[i];
}

// With DELPSC_STATISTICS: one untimed pass over all tuples, reporting the exact-path percentage
// of every predicate counter that moved.
template <int Arity, class F>
void report_filter_failures(benchmark::State& state, const Workload& w, const F& f) {
  if (!k::statistics_enabled()) return;
  k::reset_predicate_statistics();
  int sink = 0;
  for (std::size_t i = 0; i < kSets; ++i)
    sink += call(f, w.pool.data(), &w.sets[i * Arity], std::make_index_sequence<Arity>());
  benchmark::DoNotOptimize(sink);
  const auto stats = k::predicate_statistics();
  for (int i = 0; i < static_cast<int>(k::Predicate::count); ++i) {
    if (stats[i].calls == 0) continue;
    state.counters[std::string("exact%_") + predicate_name(i)] =
        100.0 * double(stats[i].filter_failures) / double(stats[i].calls);
    state.counters[std::string("calls/set_") + predicate_name(i)] =
        double(stats[i].calls) / double(kSets);
  }
}

template <int Arity, class F>
void run(benchmark::State& state, const Workload& w, const F& f) {
  report_filter_failures<Arity>(state, w, f);
  const WeightedPoint* pool = w.pool.data();
  const std::uint32_t* sets = w.sets.data();
  std::size_t next = 0;
  int sink = 0;
  for (auto _ : state) {
    for (int c = 0; c < kCallsPerIteration; ++c) {
      sink += call(f, pool, sets + next * Arity, std::make_index_sequence<Arity>());
      next = (next + 1) & (kSets - 1);
    }
    benchmark::DoNotOptimize(sink);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * kCallsPerIteration);
}

// Workloads are built on first use (and kept), so filtering benchmarks by name stays fast.
using Maker = std::function<Workload()>;
std::function<const Workload&()> lazy(Maker make) {
  auto cell = std::make_shared<std::unique_ptr<Workload>>();
  return [cell, make]() -> const Workload& {
    if (!*cell) *cell = std::make_unique<Workload>(make());
    return **cell;
  };
}

// Registers "<predicate>/<input>/filtered" and ".../plain" on the same workload.
template <int Arity, class Filtered, class Plain>
void add(const std::string& predicate, const std::string& input,
         const std::function<const Workload&()>& workload, Filtered filtered, Plain plainf) {
  benchmark::RegisterBenchmark((predicate + "/" + input + "/filtered").c_str(),
                               [workload, filtered](benchmark::State& st) {
                                 run<Arity>(st, workload(), filtered);
                               })
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark((predicate + "/" + input + "/plain").c_str(),
                               [workload, plainf](benchmark::State& st) {
                                 run<Arity>(st, workload(), plainf);
                               })
      ->Unit(benchmark::kMicrosecond);
}

using P = const double*;

void register_all() {
  // Pools shared by several predicates (seeds differ per arity so tuples differ).
  const auto cube4 = lazy([] { return tuples(random_cube(0.01, 1), 4, Tuple::any, 2); });
  const auto cube5 = lazy([] { return tuples(random_cube(0.01, 1), 5, Tuple::any, 3); });
  const auto cube5_pos = lazy([] { return tuples(random_cube(0.01, 1), 5, Tuple::positive, 4); });
  const auto cube3 = lazy([] { return tuples(random_cube(0.01, 1), 3, Tuple::any, 5); });

  const auto orient3d = [](P p, P q, P r, P s) { return k::orient3d(p, q, r, s); };
  const auto orient3d_plain = [](P p, P q, P r, P s) { return plain::orient3d(p, q, r, s); };
  add<4>("orient3d", "random", cube4, orient3d, orient3d_plain);
  add<4>("orient3d", "coplanar_int",
         lazy([] { return tuples(integer_plane(6), 4, Tuple::any, 7); }), orient3d, orient3d_plain);
  add<4>("orient3d", "coplanar_real",
         lazy([] { return tuples(real_plane(8), 4, Tuple::any, 9); }), orient3d, orient3d_plain);
  add<4>("orient3d", "near_plane", lazy([] { return tuples(near_plane(10), 4, Tuple::any, 11); }),
         orient3d, orient3d_plain);

  const auto orient2d = [](P p, P q, P r) { return k::orient2d(p, q, r, 0, 1); };
  const auto orient2d_plain = [](P p, P q, P r) { return plain::orient2d(p, q, r, 0, 1); };
  add<3>("orient2d_xy", "random", cube3, orient2d, orient2d_plain);
  const auto coplanar = [](P p, P q, P r) { return k::coplanar_orientation(p, q, r); };
  const auto coplanar_plain = [](P p, P q, P r) { return plain::coplanar_orientation(p, q, r); };
  add<3>("coplanar_orientation", "random", cube3, coplanar, coplanar_plain);
  add<3>("coplanar_orientation", "collinear_int",
         lazy([] { return tuples(integer_line(12), 3, Tuple::distinct_first, 13); }), coplanar,
         coplanar_plain);
  add<3>("coplanar_orientation", "collinear_real",
         lazy([] { return tuples(real_line(14), 3, Tuple::distinct_first, 15); }), coplanar,
         coplanar_plain);

  const auto insphere = [](P p, P q, P r, P s, P t) { return k::insphere(p, q, r, s, t); };
  const auto insphere_plain = [](P p, P q, P r, P s, P t) {
    return plain::power_test<false>(p, q, r, s, t);
  };
  const auto sphere_int = lazy([] { return tuples(integer_sphere(), 5, Tuple::positive, 16); });
  add<5>("insphere", "random", cube5, insphere, insphere_plain);
  add<5>("insphere", "cospherical_int", sphere_int, insphere, insphere_plain);
  add<5>("insphere", "coplanar_real", lazy([] { return tuples(real_plane(8), 5, Tuple::any, 17); }),
         insphere, insphere_plain);
  add<5>("insphere", "near_sphere",
         lazy([] { return tuples(near_sphere(18), 5, Tuple::positive, 19); }), insphere,
         insphere_plain);

  const auto power5 = [](P p, P q, P r, P s, P t) { return k::power_test(p, q, r, s, t); };
  const auto power5_plain = [](P p, P q, P r, P s, P t) {
    return plain::power_test<true>(p, q, r, s, t);
  };
  const auto orthogonal_int =
      lazy([] { return tuples(integer_orthogonal(25), 5, Tuple::positive, 26); });
  add<5>("power_test5", "random", cube5, power5, power5_plain);
  add<5>("power_test5", "orthogonal_int", orthogonal_int, power5, power5_plain);
  add<5>("power_test5", "coplanar_real",
         lazy([] { return tuples(real_plane(8), 5, Tuple::any, 27); }), power5, power5_plain);
  add<5>("power_test5", "near_orthogonal",
         lazy([] { return tuples(near_orthogonal(28), 5, Tuple::positive, 29); }), power5,
         power5_plain);

  const auto power4 = [](P p, P q, P r, P t) { return k::power_test(p, q, r, t); };
  const auto power4_plain = [](P p, P q, P r, P t) { return plain::planar_power_test(p, q, r, t); };
  add<4>("power_test4", "random_plane",
         lazy([] { return tuples(dyadic_plane(30), 4, Tuple::non_collinear, 31); }), power4,
         power4_plain);
  add<4>("power_test4", "orthogonal_int",
         lazy([] { return tuples(integer_plane(6), 4, Tuple::non_collinear, 32); }), power4,
         power4_plain);
  add<4>("power_test4", "near_orthogonal",
         lazy([] { return tuples(near_plane(10), 4, Tuple::non_collinear, 33); }), power4,
         power4_plain);

  const auto power3 = [](P p, P q, P t) { return k::power_test(p, q, t); };
  const auto power3_plain = [](P p, P q, P t) { return plain::linear_power_test(p, q, t); };
  add<3>("power_test3", "random_line",
         lazy([] {
           // Dyadic points exactly on a line, random weights: the filter path.
           Rng rng(34);
           std::vector<WeightedPoint> pool(kPool);
           for (auto& p : pool) {
             const double s = std::ldexp(double(integer(rng, 0, (1 << 20) - 1)), -20);
             p = {0.125 + 0.25 * s, 0.5 - 0.5 * s, 0.75 * s, uniform(rng, 0, 0.01)};
           }
           return tuples(std::move(pool), 3, Tuple::distinct_first, 35);
         }),
         power3, power3_plain);
  add<3>("power_test3", "orthogonal_int",
         lazy([] { return tuples(integer_line(12), 3, Tuple::distinct_first, 36); }), power3,
         power3_plain);
  add<3>("power_test3", "near_orthogonal",
         lazy([] { return tuples(near_line(37), 3, Tuple::distinct_first, 38); }), power3,
         power3_plain);

  const auto distance = [](P x, P c) { return k::power_distance_sign(x, c); };
  const auto distance_plain = [](P x, P c) { return plain::power_distance_sign(x, c); };
  add<2>("power_distance_sign", "random", lazy(random_pairs), distance, distance_plain);
  add<2>("power_distance_sign", "on_sphere_int", lazy([] { return distance_pairs(true); }),
         distance, distance_plain);
  add<2>("power_distance_sign", "near_sphere", lazy([] { return distance_pairs(false); }),
         distance, distance_plain);

  // Perturbed tests: the plain column is the unperturbed plain determinant on the same tuples.
  const auto power5_perturbed = [](P p, P q, P r, P s, P t) {
    return k::power_test_perturbed(p, q, r, s, t);
  };
  add<5>("power_test_perturbed", "random", cube5_pos, power5_perturbed, power5_plain);
  add<5>("power_test_perturbed", "orthogonal_int", orthogonal_int, power5_perturbed,
         power5_plain);
  const auto insphere_perturbed = [](P p, P q, P r, P s, P t) {
    return k::insphere_perturbed(p, q, r, s, t);
  };
  add<5>("insphere_perturbed", "random", cube5_pos, insphere_perturbed, insphere_plain);
  add<5>("insphere_perturbed", "cospherical_int", sphere_int, insphere_perturbed, insphere_plain);
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
