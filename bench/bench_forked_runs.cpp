// One model meshed end to end in a fresh forked child per run, as the CGAL comparison does
// (bench/cgal/bench_mesh_vs_cgal.cpp), without CGAL: read, complex, Protect, Mesher::run and
// output(). Prints each run's CPU time (user and system, measured in the child) and minor page
// faults, then the medians. A fresh child pays for every page it touches, which a warm loop in
// one process hides; scripts/ab-runs.sh alternates two builds of this binary to compare them.
//   build/bin/bench_forked_runs MODEL SIZE_PERCENT [RUNS]
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <delpsc/io/read_model.h>

#include "mesh_pipeline.h"

using namespace delpsc;

namespace {

struct Usage {
  double user = 0, system = 0;
  long faults = 0;
};

Usage usage_now() {
  rusage r{};
  getrusage(RUSAGE_SELF, &r);
  return {static_cast<double>(r.ru_utime.tv_sec) + 1e-6 * static_cast<double>(r.ru_utime.tv_usec),
          static_cast<double>(r.ru_stime.tv_sec) + 1e-6 * static_cast<double>(r.ru_stime.tv_usec), r.ru_minflt};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s MODEL SIZE_PERCENT [RUNS]\n", argv[0]);
    return 2;
  }
  const std::string path = argv[1];
  char* end = nullptr;
  const double percent = std::strtod(argv[2], &end);
  // A size of 0 or garbage (atof's 0) would ask the mesher for nothing it can finish.
  if (end == argv[2] || *end != '\0' || !(percent > 0 && percent <= 100)) {
    std::fprintf(stderr, "%s: SIZE_PERCENT must be a number in (0, 100], got '%s'\n", argv[0], argv[2]);
    return 2;
  }
  const int runs = argc > 3 ? std::max(1, std::atoi(argv[3])) : 5;
  std::vector<double> total, system;
  for (int run = 0; run < runs; ++run) {
    int pipe_ends[2];
    if (pipe(pipe_ends) != 0) return 1;
    const pid_t child = fork();
    if (child < 0) return 1;
    if (child == 0) {
      close(pipe_ends[0]);
      const Usage before = usage_now();
      std::size_t vertices = 0;
      try {
        vertices = bench::mesh_end_to_end(io::read_model(path).soup, percent / 100);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        _exit(1);
      }
      const Usage after = usage_now();
      const double figures[4] = {after.user - before.user, after.system - before.system,
                                 static_cast<double>(after.faults - before.faults), static_cast<double>(vertices)};
      const bool written = write(pipe_ends[1], figures, sizeof figures) == static_cast<ssize_t>(sizeof figures);
      _exit(written ? 0 : 1);
    }
    close(pipe_ends[1]);
    double figures[4] = {};
    const bool read_all = read(pipe_ends[0], figures, sizeof figures) == static_cast<ssize_t>(sizeof figures);
    close(pipe_ends[0]);
    int status = 0;
    waitpid(child, &status, 0);
    if (!read_all || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      std::fprintf(stderr, "run %d failed\n", run + 1);
      return 1;
    }
    std::printf("run %d: vertices=%.0f user=%.4f s system=%.4f s faults=%.0f\n", run + 1, figures[3], figures[0],
                figures[1], figures[2]);
    total.push_back(figures[0] + figures[1]);
    system.push_back(figures[1]);
  }
  std::printf("median cpu=%.4f s system=%.4f s over %d runs\n", median(total), median(system), runs);
  return 0;
}
