// The mesher end to end (Protect's balls made once outside the timing, then Mesher::run and
// output, CPU time) at λ = 0.5% of the diagonal, started from the initial sample (the default)
// and from the balls alone (the paper's start, MesherOptions::initial_sample = false); and the
// initial sample's own parts: the domain's candidates and their selection; the whole pipeline
// at 2% (pipeline/), where the costs per input triangle weigh; the output's orientation
// (orient/); the input checks `delpsc mesh` runs before meshing (input_checks/: the tree,
// crossing triangles, near contacts; also on a cylinder with fanned caps), which the pipeline
// leaves out; the G1 check it runs after (skeleton_check/) and the distances to the input
// (distances/, on a cylinder with fanned caps). Generated models and, when fetched by scripts/get-cgal-data.sh, the libcgal-demo
// models.
//   cmake --build build --target bench_mesher && build/bin/bench_mesher
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <delpsc/io/read_model.h>
#include <delpsc/io/sample_part.h>
#include <delpsc/io/shapes.h>
#include <delpsc/protect/complex.h>
#include <delpsc/protect/protect.h>
#include <delpsc/protect/self_intersections.h>
#include <delpsc/refine/approximation_error.h>
#include <delpsc/refine/initial_sample.h>
#include <delpsc/refine/mesher.h>
#include <delpsc/refine/polygon_domain.h>
#include <delpsc/refine/protected_balls.h>
#include <delpsc/refine/skeleton_check.h>
#include <delpsc/refine/triangle_orientation.h>

#include "mesh_pipeline.h"

using namespace delpsc;

namespace {

struct Model {
  std::string name;
  std::function<io::TriangleSoup()> make;  ///< reads the file, for the libcgal-demo models
  std::shared_ptr<const refine::PolygonDomain> domain;
  std::shared_ptr<const protect::BallSet> balls;
  double lambda = 0;
};

// Its domain, and Protect's balls at λ = 0.5% of the diagonal.
Model model_of(const std::string& name, const std::function<io::TriangleSoup()>& make) {
  Model m{name, make, std::make_shared<const refine::PolygonDomain>(make()), nullptr, 0};
  m.lambda = 0.005 * m.domain->bounding_box().diagonal();
  m.balls = std::make_shared<const protect::BallSet>(protect::protect(m.domain->complex(), m.lambda));
  return m;
}

// A closed cylinder (radius 1, height 1) of n rim points whose caps are fans of n triangles
// around their centres (tests/app/lib.sh's write_fan_cylinder), as CAD exports tessellate them,
// or, `from_rim`, of n - 2 triangles from the rims' first points (as STL exporters do).
io::TriangleSoup fan_cylinder(std::uint32_t n, bool from_rim = false) {
  io::TriangleSoup soup;
  for (const double z : {0.0, 1.0})
    for (std::uint32_t i = 0; i < n; ++i)
      soup.vertices.emplace_back(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n), z);
  soup.vertices.emplace_back(0, 0, 0);
  soup.vertices.emplace_back(0, 0, 1);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    soup.triangles.push_back({i, j, n + j});
    soup.triangles.push_back({i, n + j, n + i});
    if (!from_rim) {
      soup.triangles.push_back({2 * n, j, i});
      soup.triangles.push_back({2 * n + 1, n + i, n + j});
    } else if (i >= 1 && i + 1 < n) {
      soup.triangles.push_back({0, i + 1, i});
      soup.triangles.push_back({n, n + i, n + i + 1});
    }
  }
  return soup;
}

std::vector<Model> models() {
  std::vector<std::pair<std::string, std::function<io::TriangleSoup()>>> makers = {
      {"sphere", [] { return io::make_sphere(16); }},
      {"sample_part", [] { return io::make_sample_part(); }},
  };
  const auto data = std::filesystem::path(__FILE__).parent_path() / "../data/cgal-demo";
  for (const char* name : {"fandisk", "part", "anchor", "joint", "cube", "elephant", "sphere"}) {
    const auto path = data / (std::string(name) + ".off");
    if (std::filesystem::exists(path))
      makers.emplace_back(std::string("cgal_") + name, [path] { return io::read_model(path.string()).soup; });
  }
  std::vector<Model> out;
  for (auto& [name, make] : makers) out.push_back(model_of(name, make));
  return out;
}

void mesh(benchmark::State& state, const Model& m, bool initial_sample) {
  std::size_t vertices = 0;
  refine::MesherStats stats;
  for (auto _ : state) {
    protect::BallSet set = *m.balls;  // RefineBall changes it
    refine::ProtectedBalls balls(set);
    refine::MesherOptions options;
    options.facet_size = m.lambda;
    options.initial_sample = initial_sample;
    refine::Mesher mesher(*m.domain, balls, options);
    mesher.run();
    const io::SurfaceMesh out = mesher.output();
    vertices = out.vertices.size();
    stats = mesher.stats();
    benchmark::DoNotOptimize(out);
  }
  state.counters["vertices"] = static_cast<double>(vertices);
  state.counters["sampled"] = static_cast<double>(stats.sampled);
  state.counters["insertions"] = static_cast<double>(stats.insertions_size + stats.insertions_disk + stats.insertions_d34);
  // Output vertices per second of CPU time (shown with a k or M prefix).
  state.counters["vertices_per_s"] =
      benchmark::Counter(static_cast<double>(vertices), benchmark::Counter::kIsIterationInvariantRate);
}

void initial_sample(benchmark::State& state, const Model& m) {
  std::vector<WeightedPoint> balls;
  for (const protect::BallId id : m.balls->live_ids()) balls.push_back((*m.balls)[id].weighted_point());
  std::size_t chosen = 0, candidates = 0;
  for (auto _ : state) {
    kernel::LargeVector<Vec3> points;
    kernel::LargeVector<std::uint32_t> patches;
    const refine::CandidateParts parts = m.domain->surface_candidates(m.lambda, 0xffffffffu, points, patches);
    candidates = points.size();
    chosen = refine::select_sample(points, parts, balls, {}, m.lambda).size();
  }
  state.counters["candidates"] = static_cast<double>(candidates);
  state.counters["chosen"] = static_cast<double>(chosen);
}

// The candidates alone (clusters, lattice, random points near the clusters' boundaries, net) at
// a coarser size: their cost per triangle is fixed, so it shows where the mesh is small.
void candidates(benchmark::State& state, const Model& m, double scale) {
  std::size_t count = 0;
  refine::CandidateParts parts;
  for (auto _ : state) {
    kernel::LargeVector<Vec3> points;
    kernel::LargeVector<std::uint32_t> patches;
    parts = m.domain->surface_candidates(scale * m.lambda, 0xffffffffu, points, patches);
    count = points.size();
    benchmark::DoNotOptimize(points);
  }
  state.counters["candidates"] = static_cast<double>(count);
  state.counters["lattice"] = static_cast<double>(parts.lattice);
  state.counters["net"] = static_cast<double>(parts.net);
}

// Everything `delpsc mesh --size 2%` times, as the comparison with CGAL does (bench/cgal): the
// model read again (libcgal-demo models; the generated ones are made again), the complex, the
// AABB tree, Protect, Mesh2Complex and the output; the mesher's destruction too, since the loop
// ends each iteration there. At coarse sizes these fixed costs are a quarter of fandisk's time.
void pipeline(benchmark::State& state, const Model& m, double relative) {
  std::size_t vertices = 0;
  for (auto _ : state) vertices = bench::mesh_end_to_end(m.make(), relative);
  state.counters["vertices"] = static_cast<double>(vertices);
  state.counters["vertices_per_s"] =
      benchmark::Counter(static_cast<double>(vertices), benchmark::Counter::kIsIterationInvariantRate);
}

// The model's mesh at 0.5%, made before a timing that works on it.
io::SurfaceMesh mesh_of(const Model& m) {
  protect::BallSet set = *m.balls;
  refine::ProtectedBalls balls(set);
  refine::MesherOptions options;
  options.facet_size = m.lambda;
  refine::Mesher mesher(*m.domain, balls, options);
  mesher.run();
  return mesher.output();
}

// orient_triangles on the mesh's own output at 0.5% (meshed once, before the timing), as
// Mesher::output() calls it: the triangles copied and oriented again each iteration (the copy is
// a few percent of it).
void orient(benchmark::State& state, const Model& m) {
  const io::SurfaceMesh mesh = mesh_of(m);
  for (auto _ : state) {
    kernel::LargeVector<std::array<std::uint32_t, 3>> triangles = mesh.triangles;
    benchmark::DoNotOptimize(refine::orient_triangles(mesh.vertices, triangles));
    benchmark::DoNotOptimize(triangles);
  }
  state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
}

// What app/model_input.h's reject_self_intersections does on a clean model: one tree, then both
// checks in one descent of it (nothing is found, so every box-overlapping pair is decided). The
// tolerance is the command's, 1e-9 of the diagonal.
void input_checks(benchmark::State& state, const Model& m) {
  const protect::Complex& complex = m.domain->complex();
  const double tolerance = 1e-9 * m.domain->bounding_box().diagonal();
  for (auto _ : state) {
    const kernel::AabbTree tree(complex.vertices, complex.triangles);
    benchmark::DoNotOptimize(protect::find_input_defects(complex, tree, 100, tolerance));
  }
  state.counters["triangles"] = static_cast<double>(complex.triangles.size());
}

// The G1 and per-patch topology check `delpsc mesh` runs on every output (for its report), on
// the mesh at 0.5%, with the command's tolerance.
void skeleton_check(benchmark::State& state, const Model& m) {
  const io::SurfaceMesh mesh = mesh_of(m);
  const double tolerance = 1e-9 * m.domain->bounding_box().diagonal();
  for (auto _ : state) benchmark::DoNotOptimize(refine::check_skeleton(mesh, *m.domain, tolerance));
  state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
}

// The tree and find_input_defects on `soup`'s complex, as the commands run them.
void input_checks_of(benchmark::State& state, const io::TriangleSoup& soup) {
  const refine::PolygonDomain domain(protect::build_complex(soup));
  const protect::Complex& complex = domain.complex();
  const double tolerance = 1e-9 * domain.bounding_box().diagonal();
  for (auto _ : state) {
    const kernel::AabbTree tree(complex.vertices, complex.triangles);
    benchmark::DoNotOptimize(protect::find_input_defects(complex, tree, 100, tolerance));
  }
  state.counters["triangles"] = static_cast<double>(complex.triangles.size());
}

// input_checks on a closed cylinder whose caps are fans of `rim` triangles around their centres
// (tests/app/lib.sh's write_fan_cylinder): rim²/2 box-overlapping pairs in each cap, which a
// certified flat fan spares (protect/self_intersections.h).
void input_checks_fan_cylinder(benchmark::State& state) {
  input_checks_of(state, fan_cylinder(static_cast<std::uint32_t>(state.range(0))));
}

// The same with the caps fanned from rim points one above the other: the chords' boxes are long
// and overlap many side triangles' (what is left of the quadratic cost there), and the search
// across the two fans turns the lower one's axis through the upper corner.
void input_checks_rim_fan_cylinder(benchmark::State& state) {
  input_checks_of(state, fan_cylinder(static_cast<std::uint32_t>(state.range(0)), true));
}

// The distances `delpsc mesh` reports (measure_approximation, sample spacing λ/2 as the command
// uses), on the mesh at 0.5% made before the timing; wall time, since it runs on two threads.
void distances(benchmark::State& state, const Model& m) {
  const io::SurfaceMesh mesh = mesh_of(m);
  refine::ApproximationOptions options;
  options.sample_spacing = m.lambda / 2;
  for (auto _ : state) benchmark::DoNotOptimize(refine::measure_approximation(mesh, *m.domain, options));
  state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
}

// input_checks on the side of a cone of `rim` triangles around its apex, open (second argument
// 0) or on a base fanned from its centre (1) or from its first rim point (2): rim²/2
// box-overlapping pairs in the side, which a fan certified along the cone's axis spares, and
// rim² across side and base, which the search by angle across fans spares; the base fanned from
// a rim point is a fan of its chords without the side's two triangles there.
void input_checks_cone(benchmark::State& state) {
  const auto n = static_cast<std::uint32_t>(state.range(0));
  io::TriangleSoup soup;
  for (std::uint32_t i = 0; i < n; ++i) soup.vertices.emplace_back(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n), 0);
  soup.vertices.emplace_back(0, 0, 1);
  soup.vertices.emplace_back(0, 0, 0);
  for (std::uint32_t i = 0; i < n; ++i) {
    soup.triangles.push_back({n, i, (i + 1) % n});
    if (state.range(1) == 1) soup.triangles.push_back({n + 1, (i + 1) % n, i});
    if (state.range(1) == 2 && i + 2 < n) soup.triangles.push_back({0, i + 2, i + 1});
  }
  input_checks_of(state, soup);
}

const int registered = [] {
  benchmark::RegisterBenchmark("input_checks/fan_cylinder", input_checks_fan_cylinder)
      ->Arg(5000)
      ->Arg(20000)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("input_checks/cone", input_checks_cone)
      ->Args({5000, 0})
      ->Args({20000, 0})
      ->Args({5000, 1})
      ->Args({20000, 1})
      ->Args({5000, 2})
      ->Args({20000, 2})
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("input_checks/rim_fan_cylinder", input_checks_rim_fan_cylinder)
      ->Arg(5000)
      ->Arg(20000)
      ->Unit(benchmark::kMillisecond);
  // Fans of thin triangles: refinement's segment queries, the G1 check's closest points and the
  // distances all search them by angle (refine/closest_point_index.h, PolygonDomain).
  for (const std::uint32_t n : {5000u, 20000u}) {
    const Model m = model_of("fan_cylinder_" + std::to_string(n), [n] { return fan_cylinder(n); });
    benchmark::RegisterBenchmark(("mesh/" + m.name + "/sample").c_str(), mesh, m, true)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("skeleton_check/" + m.name).c_str(), skeleton_check, m)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("distances/" + m.name).c_str(), distances, m)->UseRealTime()->Unit(benchmark::kMillisecond);
  }
  for (const Model& m : models()) {
    benchmark::RegisterBenchmark(("mesh/" + m.name + "/sample").c_str(), mesh, m, true)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("mesh/" + m.name + "/paper").c_str(), mesh, m, false)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("initial_sample/" + m.name).c_str(), initial_sample, m)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("candidates/" + m.name + "/2%").c_str(), candidates, m, 4.0)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("pipeline/" + m.name + "/2%").c_str(), pipeline, m, 0.02)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("orient/" + m.name).c_str(), orient, m)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("input_checks/" + m.name).c_str(), input_checks, m)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("skeleton_check/" + m.name).c_str(), skeleton_check, m)->Unit(benchmark::kMillisecond);
  }
  return 0;
}();

}  // namespace

BENCHMARK_MAIN();
