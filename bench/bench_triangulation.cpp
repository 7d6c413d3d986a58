// Insertion throughput, removal cost and memory of delaunay::RegularTriangulation on the
// workloads of issue 3. bench/cgal/bench_triangulation_cgal runs CGAL on the same point sets
// under the same names; run both in one go and quote ratios (see BENCHMARKS.md).
#include <benchmark/benchmark.h>

#include <delpsc/delaunay/regular_triangulation.h>
#include <delpsc/delaunay/spatial_sort.h>
#include <delpsc/io/point_generators.h>
#include <random>
#include <string>
#include <vector>

namespace {

using delpsc::delaunay::PointId;
using delpsc::delaunay::PointStatus;
using delpsc::delaunay::RegularTriangulation;

void run_insert(benchmark::State& state, const std::string& spec) {
  const auto pts = delpsc::io::generate_points(spec, 1);
  for (auto _ : state) {
    RegularTriangulation dt;
    dt.insert(pts);
    benchmark::DoNotOptimize(dt.number_of_finite_cells());
    state.counters["vertices"] = double(dt.number_of_vertices());
    state.counters["hidden"] = double(dt.number_of_hidden());
    state.counters["bytes_per_vertex"] = double(dt.memory_bytes()) / double(dt.number_of_vertices());
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(pts.size()));
}

// Removes 10^4 random vertices of a triangulation of `spec`; the time is per removed vertex.
void run_remove(benchmark::State& state, const std::string& spec) {
  const auto pts = delpsc::io::generate_points(spec, 1);
  constexpr std::size_t kRemovals = 10000;
  for (auto _ : state) {
    state.PauseTiming();
    RegularTriangulation dt;
    dt.insert(pts);
    std::vector<PointId> victims;
    for (PointId id = 0; id < dt.number_of_points(); ++id)
      if (dt.status(id) == PointStatus::vertex) victims.push_back(id);
    std::mt19937_64 rng(2);
    for (std::size_t i = 0; i < kRemovals; ++i)
      std::swap(victims[i], victims[i + rng() % (victims.size() - i)]);
    state.ResumeTiming();
    std::size_t removed = 0;
    for (std::size_t i = 0; i < kRemovals; ++i) removed += dt.remove(victims[i]);
    benchmark::DoNotOptimize(removed);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(kRemovals));
}

// The insertion order alone (delaunay::brio_order: shuffle, rounds, Hilbert sort of each), which
// every batch insertion computes first.
void run_brio_order(benchmark::State& state, const std::string& spec) {
  const auto pts = delpsc::io::generate_points(spec, 1);
  std::vector<std::uint32_t> order;
  for (auto _ : state) {
    delpsc::delaunay::brio_order(pts, order);
    benchmark::DoNotOptimize(order.data());
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(pts.size()));
}

const char* kSpecs[] = {"uniform:100000", "uniform:1000000", "weighted:100000",
                        "weighted:1000000", "sphere:100000",  "grid:103823"};

int register_all() {
  for (const char* spec : kSpecs)
    benchmark::RegisterBenchmark((std::string("delpsc_regular/") + spec).c_str(), run_insert, spec)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
  for (const char* spec : {"uniform:100000", "weighted:100000"})
    benchmark::RegisterBenchmark((std::string("delpsc_remove/") + spec).c_str(), run_remove, spec)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
  for (const char* spec : {"uniform:100000", "sphere:100000"})
    benchmark::RegisterBenchmark((std::string("delpsc_brio_order/") + spec).c_str(), run_brio_order, spec)
        ->Unit(benchmark::kMillisecond);
  return 0;
}
const int registered = register_all();

}  // namespace

BENCHMARK_MAIN();
