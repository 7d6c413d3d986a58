// CGAL's Regular_triangulation_3 and Delaunay_triangulation_3 (Epick, range insertion, which
// spatially sorts) on exactly the point sets bench_triangulation uses, so the two binaries can
// be run back to back and compared as ratios. Built only with -DDELPSC_WITH_CGAL=ON.
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <benchmark/benchmark.h>

#include <delpsc/io/point_generators.h>
#include <string>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Regular = CGAL::Regular_triangulation_3<K>;
using Delaunay = CGAL::Delaunay_triangulation_3<K>;

void run_regular(benchmark::State& state, const std::string& spec) {
  const auto pts = delpsc::io::generate_points(spec, 1);
  std::vector<K::Weighted_point_3> wp;
  wp.reserve(pts.size());
  for (const auto& p : pts) wp.emplace_back(K::Point_3(p.x, p.y, p.z), p.w);
  for (auto _ : state) {
    Regular rt(wp.begin(), wp.end());
    benchmark::DoNotOptimize(rt.number_of_finite_cells());
    state.counters["vertices"] = double(rt.number_of_vertices());
    state.counters["hidden"] = double(pts.size() - rt.number_of_vertices());
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(pts.size()));
}

void run_delaunay(benchmark::State& state, const std::string& spec) {
  const auto pts = delpsc::io::generate_points(spec, 1);
  std::vector<K::Point_3> p3;
  p3.reserve(pts.size());
  for (const auto& p : pts) p3.emplace_back(p.x, p.y, p.z);
  for (auto _ : state) {
    Delaunay dt(p3.begin(), p3.end());
    benchmark::DoNotOptimize(dt.number_of_finite_cells());
    state.counters["vertices"] = double(dt.number_of_vertices());
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(pts.size()));
}

// The workloads of issue 3: 1e5 and 1e6 uniform points, unweighted and weighted, a cospherical
// set and an integer grid. Names match bench_triangulation's.
const char* kSpecs[] = {"uniform:100000", "uniform:1000000", "weighted:100000",
                        "weighted:1000000", "sphere:100000",  "grid:103823"};

int register_all() {
  for (const char* spec : kSpecs) {
    benchmark::RegisterBenchmark((std::string("cgal_regular/") + spec).c_str(), run_regular, spec)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
    benchmark::RegisterBenchmark((std::string("cgal_delaunay/") + spec).c_str(), run_delaunay, spec)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
  }
  return 0;
}
const int registered = register_all();

}  // namespace

BENCHMARK_MAIN();
