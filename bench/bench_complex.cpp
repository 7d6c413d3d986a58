// Building the piecewise smooth complex of a large mesh, building the AABB tree, and the
// segment queries the mesher makes (Voronoi edges: short segments near the surface).
#include <benchmark/benchmark.h>

#include <map>
#include <random>

#include <delpsc/io/shapes.h>
#include <delpsc/kernel/aabb_tree.h>
#include <delpsc/protect/complex.h>
#include <delpsc/protect/self_intersections.h>
#include <delpsc/refine/polygon_domain.h>

using namespace delpsc;

namespace {

// A torus with 2 nu nv triangles (no features) and a box with n x n quads per face (features
// on 12 edges): two ends of the work the feature step does.
const io::TriangleSoup& torus_soup(int nu, int nv) {
  static std::map<std::pair<int, int>, io::TriangleSoup> cache;
  auto& s = cache[{nu, nv}];
  if (s.triangles.empty()) s = io::make_torus(1, 0.3, nu, nv);
  return s;
}

void BM_BuildComplexTorus(benchmark::State& state) {
  const auto nu = static_cast<int>(state.range(0));
  const auto& soup = torus_soup(nu, nu / 2);
  for (auto _ : state) benchmark::DoNotOptimize(protect::build_complex(soup));
  state.counters["triangles"] = static_cast<double>(soup.triangles.size());
  state.counters["tri/s"] = benchmark::Counter(static_cast<double>(soup.triangles.size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_BuildComplexTorus)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_BuildComplexCube(benchmark::State& state) {
  const auto soup = io::make_cube(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(protect::build_complex(soup));
  state.counters["triangles"] = static_cast<double>(soup.triangles.size());
}
BENCHMARK(BM_BuildComplexCube)->Arg(290)->Unit(benchmark::kMillisecond);

// An open sheet (a boundary of 4n edges): the cost of looking for T-junctions along it.
void BM_BuildComplexSheet(benchmark::State& state) {
  const auto soup = io::make_square_sheet(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(protect::build_complex(soup));
  state.counters["triangles"] = static_cast<double>(soup.triangles.size());
}
BENCHMARK(BM_BuildComplexSheet)->Arg(700)->Unit(benchmark::kMillisecond);

void BM_BuildAabbTree(benchmark::State& state) {
  const auto nu = static_cast<int>(state.range(0));
  const auto& soup = torus_soup(nu, nu / 2);
  for (auto _ : state) benchmark::DoNotOptimize(kernel::AabbTree(soup.vertices, soup.triangles));
  state.counters["triangles"] = static_cast<double>(soup.triangles.size());
}
BENCHMARK(BM_BuildAabbTree)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

// The input checks every command that meshes runs (protect/self_intersections.h) on a clean
// surface, where nothing is found and every box-overlapping pair is decided: the tree, then one
// descent of it for the exact pair tests and the near-contact search (find_input_defects, as
// the commands do). Against BM_BuildComplexTorus: what the checks add to reading a model.
void BM_InputChecksTorus(benchmark::State& state) {
  const auto nu = static_cast<int>(state.range(0));
  const protect::Complex complex = protect::build_complex(torus_soup(nu, nu / 2));
  for (auto _ : state) {
    const kernel::AabbTree tree(complex.vertices, complex.triangles);
    benchmark::DoNotOptimize(protect::find_input_defects(complex, tree, 100, 1e-9 * 2.6));
  }
  state.counters["triangles"] = static_cast<double>(complex.triangles.size());
  state.counters["tri/s"] = benchmark::Counter(static_cast<double>(complex.triangles.size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_InputChecksTorus)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

// The two checks of BM_InputChecksTorus apart, with the tree built once outside the loop.
void BM_SelfIntersectionsTorus(benchmark::State& state) {
  const auto nu = static_cast<int>(state.range(0));
  const protect::Complex complex = protect::build_complex(torus_soup(nu, nu / 2));
  const kernel::AabbTree tree(complex.vertices, complex.triangles);
  for (auto _ : state) benchmark::DoNotOptimize(protect::find_self_intersections(complex, tree, 100));
}
BENCHMARK(BM_SelfIntersectionsTorus)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
void BM_NearContactTorus(benchmark::State& state) {
  const auto nu = static_cast<int>(state.range(0));
  const protect::Complex complex = protect::build_complex(torus_soup(nu, nu / 2));
  const kernel::AabbTree tree(complex.vertices, complex.triangles);
  for (auto _ : state) benchmark::DoNotOptimize(protect::find_near_contact(complex, tree, 1e-9 * 2.6));
}
BENCHMARK(BM_NearContactTorus)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

// Segments of length `len` (relative to the torus's tube radius 0.3) centred on random points of
// random triangles, in random directions: the shape of Voronoi edges dual to restricted
// triangles (generic: they do not pass exactly through mesh vertices, which would send every
// test to the exact arithmetic).
void segment_queries(benchmark::State& state, bool through_domain) {
  const auto nu = static_cast<int>(state.range(0));
  const double len = 0.3 * static_cast<double>(state.range(1)) / 100;
  const auto& soup = torus_soup(nu, nu / 2);
  const refine::PolygonDomain domain(soup);
  std::mt19937_64 rng(1);
  std::normal_distribution<double> g;
  std::vector<std::pair<Vec3, Vec3>> segments(4096);
  for (auto& [a, b] : segments) {
    const auto& t = soup.triangles[rng() % soup.triangles.size()];
    std::uniform_real_distribution<double> u(0, 1);
    double x = u(rng), y = u(rng);
    if (x + y > 1) x = 1 - x, y = 1 - y;
    const Vec3 c = soup.vertices[t[0]] + x * (soup.vertices[t[1]] - soup.vertices[t[0]]) +
                   y * (soup.vertices[t[2]] - soup.vertices[t[0]]);
    const Vec3 d = Vec3(g(rng), g(rng), g(rng)).normalized() * (len / 2);
    a = c - d;
    b = c + d;
  }
  std::vector<kernel::TriangleIntersection> raw;
  std::vector<refine::SurfaceHit> hits;
  std::size_t i = 0, found = 0;
  for (auto _ : state) {
    const auto& [a, b] = segments[i++ % segments.size()];
    if (through_domain) {
      domain.intersect_segment(a, b, hits);
      found += hits.size();
    } else {
      raw.clear();
      domain.tree().intersect_segment(a, b, raw);
      found += raw.size();
    }
  }
  state.counters["hits/query"] = static_cast<double>(found) / static_cast<double>(state.iterations());
  state.counters["triangles"] = static_cast<double>(soup.triangles.size());
}

void BM_AabbSegmentQuery(benchmark::State& state) { segment_queries(state, false); }
void BM_DomainIntersectSegment(benchmark::State& state) { segment_queries(state, true); }
// Args: torus resolution nu, segment length in percent of the tube radius. {100, 400} is the
// mesher's case without a proven cover: 10^4 triangles, segments a third of the model's diagonal
// (the dual edges' average on fandisk), which visit many inner nodes of a tree that fits in
// cache; {100, 10} the first examination's short windows on such a tree; {300, 10} and
// {1000, 10} short segments in trees of 9 * 10^4 and 10^6 triangles, out of cache.
BENCHMARK(BM_AabbSegmentQuery)->Args({100, 10})->Args({300, 10})->Args({1000, 10})->Args({1000, 100})->Args({100, 400})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DomainIntersectSegment)->Args({1000, 10})->Args({1000, 100})->Args({100, 400})->Unit(benchmark::kMicrosecond);

void BM_SegmentInBall(benchmark::State& state) {
  const auto c = protect::build_complex(io::make_capped_cylinder(1, 1, static_cast<int>(state.range(0)), 2, 2));
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(0, 1);
  double sum = 0;
  for (auto _ : state) {
    const auto seg = c.segment_in_ball(0, u(rng) * c.curves[0].length, 0.05);
    sum += seg.s1 - seg.s0;
  }
  benchmark::DoNotOptimize(sum);
}
BENCHMARK(BM_SegmentInBall)->Arg(1000)->Arg(100000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
