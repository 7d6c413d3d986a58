// Protect(D, λ) per model and λ (issue 5): the generated test models and, when fetched by
// scripts/get-cgal-data.sh, the libcgal-demo models; λ = 4%, 1% and 0.25% of the bounding-box
// diagonal. The complex is built once outside the timing. Also RefineBall as the mesher calls it
// (the largest ball, again and again) and the spatial index query.
//   cmake --build build --target bench_protect && build/bin/bench_protect
#include <benchmark/benchmark.h>

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <delpsc/io/read_model.h>
#include <delpsc/io/shapes.h>
#include <delpsc/protect/protect.h>

using namespace delpsc;

namespace {

struct Model {
  std::string name;
  std::shared_ptr<const protect::Complex> complex;
};

std::vector<Model> models() {
  std::vector<std::pair<std::string, std::function<io::TriangleSoup()>>> makers = {
      {"cube", [] { return io::make_cube(8); }},
      {"book", [] { return io::make_book(3, 8); }},
      {"box_with_fin", [] { return io::make_box_with_fin(8); }},
      {"capped_cylinder", [] { return io::make_capped_cylinder(); }},
      {"wedge_10deg", [] { return io::make_wedge(10, 0.05); }},
      {"crossed_ridges_1pc", [] { return io::make_crossed_ridges(0.01, 8); }},
      {"short_curve_1e-3", [] { return io::make_short_curve_prism(1e-3, 0.05); }},
  };
  const auto data = std::filesystem::path(__FILE__).parent_path() / "../data/cgal-demo";
  for (const char* name : {"fandisk", "part", "anchor", "joint", "elephant"}) {
    const auto path = data / (std::string(name) + ".off");
    if (std::filesystem::exists(path))
      makers.emplace_back(name, [path] { return io::read_model(path.string()).soup; });
  }
  std::vector<Model> out;
  for (auto& [name, make] : makers)
    out.push_back({name, std::make_shared<const protect::Complex>(protect::build_complex(make()))});
  return out;
}

void protect_model(benchmark::State& state, const Model& model, double fraction) {
  const double lambda = fraction * protect::BallSet(*model.complex).diagonal();
  std::size_t balls = 0;
  for (auto _ : state) {
    const protect::BallSet set = protect::protect(*model.complex, lambda);
    balls = set.size();
    benchmark::DoNotOptimize(balls);
  }
  state.counters["balls"] = static_cast<double>(balls);
  state.counters["curves"] = static_cast<double>(model.complex->curve_count());
}

// 50 refinements of the largest ball after protecting at 4%; time per refine_ball call.
void refine_largest(benchmark::State& state, const Model& model) {
  const double lambda = 0.04 * protect::BallSet(*model.complex).diagonal();
  std::size_t calls = 0, added = 0;
  for (auto _ : state) {
    state.PauseTiming();
    protect::BallSet set = protect::protect(*model.complex, lambda);
    state.ResumeTiming();
    for (int i = 0; i < 50; ++i) added += protect::refine_ball(set, set.largest()).added.size();
    calls += 50;
  }
  state.counters["us/call"] = benchmark::Counter(static_cast<double>(calls), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["added/call"] = static_cast<double>(added) / static_cast<double>(calls);
}

// balls_meeting(id) for every live ball of a protection at 0.25%: the query Separate and the
// checker make.
void balls_meeting(benchmark::State& state, const Model& model) {
  const protect::BallSet set = protect::protect(*model.complex, 0.0025 * protect::BallSet(*model.complex).diagonal());
  const std::vector<protect::BallId> ids = set.live_ids();
  std::size_t i = 0, found = 0;
  for (auto _ : state) found += set.balls_meeting(ids[i++ % ids.size()]).size();
  benchmark::DoNotOptimize(found);
  state.counters["balls"] = static_cast<double>(ids.size());
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<Model> all = models();
  for (const Model& m : all) {
    for (const auto& [label, fraction] : {std::pair{"4%", 0.04}, std::pair{"1%", 0.01}, std::pair{"0.25%", 0.0025}})
      benchmark::RegisterBenchmark(("protect/" + m.name + "/" + label).c_str(), protect_model, m, fraction)
          ->Unit(benchmark::kMillisecond);
  }
  for (const Model& m : all)
    if (m.name == "cube" || m.name == "wedge_10deg" || m.name == "fandisk")
      benchmark::RegisterBenchmark(("refine_largest/" + m.name).c_str(), refine_largest, m)->Unit(benchmark::kMillisecond);
  for (const Model& m : all)
    if (m.name == "short_curve_1e-3" || m.name == "fandisk")
      benchmark::RegisterBenchmark(("balls_meeting/" + m.name).c_str(), balls_meeting, m);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
