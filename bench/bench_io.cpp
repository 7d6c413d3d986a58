// Reading models: a finely tessellated torus of about a million triangles (1000 x 500 quads,
// 500k vertices), written once per format to $TMPDIR, then read back by io::read_model. The
// file is in the page cache after the first iteration, so this measures parsing, vertex merging
// and the zero-area check, not the disk. Counters: triangles per second and the file size.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>

#include <delpsc/io/mesh_writer.h>
#include <delpsc/io/read_model.h>
#include <delpsc/io/shapes.h>

using namespace delpsc;

namespace {

constexpr int kAround = 1000, kTube = 500;  // 2 * 1000 * 500 = 1M triangles

/// The model file for `extension`, written on first use and removed at exit.
const std::string& model_file(const std::string& extension) {
  static const io::SurfaceMesh mesh = io::surface_mesh_from(io::make_torus(1, 0.3, kAround, kTube));
  static std::map<std::string, std::string> paths;
  auto it = paths.find(extension);
  if (it == paths.end()) {
    const char* dir = std::getenv("TMPDIR");
    const std::string path = std::string(dir ? dir : "/tmp") + "/delpsc_bench_io_torus" + extension;
    io::write_mesh(path, mesh);
    it = paths.emplace(extension, path).first;
    static const struct Cleanup {
      ~Cleanup() {
        for (const auto& [ext, p] : paths) std::remove(p.c_str());
      }
    } cleanup;
  }
  return it->second;
}

void BM_read_model(benchmark::State& state, const std::string& extension) {
  const std::string& path = model_file(extension);
  std::size_t triangles = 0;
  for (auto _ : state) {
    const io::ReadResult r = io::read_model(path);
    triangles = r.soup.triangles.size();
    benchmark::DoNotOptimize(r.soup.vertices.data());
  }
  state.counters["triangles"] = static_cast<double>(triangles);
  state.counters["MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
  state.counters["tri/s"] = benchmark::Counter(static_cast<double>(triangles),
                                               benchmark::Counter::kIsIterationInvariantRate);
}

void BM_write_mesh(benchmark::State& state, const std::string& extension) {
  const io::SurfaceMesh mesh = io::surface_mesh_from(io::make_torus(1, 0.3, kAround, kTube));
  const char* dir = std::getenv("TMPDIR");
  const std::string path = std::string(dir ? dir : "/tmp") + "/delpsc_bench_io_write" + extension;
  for (auto _ : state) io::write_mesh(path, mesh);
  std::remove(path.c_str());
  state.counters["tri/s"] = benchmark::Counter(static_cast<double>(mesh.triangles.size()),
                                               benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

BENCHMARK_CAPTURE(BM_read_model, stl_binary, std::string(".stl"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_read_model, ply_binary, std::string(".ply"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_read_model, off, std::string(".off"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_read_model, obj, std::string(".obj"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_write_mesh, stl_binary, std::string(".stl"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_write_mesh, ply_binary, std::string(".ply"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_write_mesh, off, std::string(".off"))->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
