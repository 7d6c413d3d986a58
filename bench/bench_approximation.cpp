// refine::measure_approximation (issue 6) on meshes made by the mesher at λ = 1% of the diagonal:
// generated models and, when fetched by scripts/get-cgal-data.sh, the libcgal-demo models; sample
// spacing λ/2 (what `delpsc mesh` uses) and λ/8. Each model is meshed once outside the timing; its
// refinement CPU time is the counter refine_ms, to read the measurement's cost against. Also
// refine::check_skeleton on the same meshes: the other check `delpsc mesh` runs on every output.
//   cmake --build build --target bench_approximation && build/bin/bench_approximation
#include <benchmark/benchmark.h>

#include <ctime>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <delpsc/io/read_model.h>
#include <delpsc/io/shapes.h>
#include <delpsc/protect/protect.h>
#include <delpsc/refine/approximation_error.h>
#include <delpsc/refine/mesher.h>
#include <delpsc/refine/polygon_domain.h>
#include <delpsc/refine/protected_balls.h>
#include <delpsc/refine/skeleton_check.h>

using namespace delpsc;

namespace {

struct Meshed {
  std::string name;
  std::shared_ptr<const refine::PolygonDomain> domain;
  io::SurfaceMesh mesh;
  double lambda = 0;
  double refine_ms = 0;  // CPU time of Mesher::run
};

Meshed mesh_model(const std::string& name, const io::TriangleSoup& soup) {
  Meshed m{name, std::make_shared<const refine::PolygonDomain>(soup), {}, 0, 0};
  m.lambda = 0.01 * m.domain->bounding_box().diagonal();
  protect::BallSet set = protect::protect(m.domain->complex(), m.lambda);
  refine::ProtectedBalls balls(set);
  refine::MesherOptions options;
  options.facet_size = m.lambda;
  refine::Mesher mesher(*m.domain, balls, options);
  const std::clock_t start = std::clock();
  mesher.run();
  m.refine_ms = 1e3 * static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  m.mesh = mesher.output();
  return m;
}

std::vector<Meshed> models() {
  std::vector<std::pair<std::string, std::function<io::TriangleSoup()>>> makers = {
      {"sphere", [] { return io::make_sphere(16); }},
      {"capped_cylinder", [] { return io::make_capped_cylinder(); }},
  };
  const auto data = std::filesystem::path(__FILE__).parent_path() / "../data/cgal-demo";
  for (const char* name : {"fandisk", "part", "anchor", "joint"}) {
    const auto path = data / (std::string(name) + ".off");
    if (std::filesystem::exists(path)) makers.emplace_back(name, [path] { return io::read_model(path.string()).soup; });
  }
  std::vector<Meshed> out;
  for (auto& [name, make] : makers) out.push_back(mesh_model(name, make()));
  return out;
}

void measure(benchmark::State& state, const Meshed& m, double spacing_in_lambdas) {
  refine::ApproximationOptions options;
  options.sample_spacing = spacing_in_lambdas * m.lambda;
  refine::ApproximationError e;
  for (auto _ : state) {
    e = refine::measure_approximation(m.mesh, *m.domain, options);
    benchmark::DoNotOptimize(e);
  }
  state.counters["triangles"] = static_cast<double>(m.mesh.triangles.size());
  state.counters["samples"] = static_cast<double>(e.output_to_input.samples + e.input_to_output.samples);
  state.counters["hausdorff"] = e.relative(e.hausdorff());
  state.counters["refine_ms"] = m.refine_ms;
}

void check(benchmark::State& state, const Meshed& m) {
  const double tolerance = 1e-9 * m.domain->bounding_box().diagonal();  // as delpsc mesh
  for (auto _ : state) benchmark::DoNotOptimize(refine::check_skeleton(m.mesh, *m.domain, tolerance));
  state.counters["triangles"] = static_cast<double>(m.mesh.triangles.size());
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<Meshed> all = models();
  for (const Meshed& m : all)
    for (const auto& [label, spacing] : {std::pair{"h=lambda/2", 0.5}, std::pair{"h=lambda/8", 0.125}})
      benchmark::RegisterBenchmark(("measure_approximation/" + m.name + "/" + label).c_str(), measure, m, spacing)
          ->Unit(benchmark::kMillisecond);
  for (const Meshed& m : all)
    benchmark::RegisterBenchmark(("check_skeleton/" + m.name).c_str(), check, m)->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
