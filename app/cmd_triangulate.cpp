// `delpsc triangulate`: the regular triangulation of a point set, checked from outside (issue 3).
#include <chrono>
#include <delpsc/delaunay/regular_triangulation.h>
#include <delpsc/io/error.h>
#include <delpsc/io/point_generators.h>
#include <delpsc/io/point_set.h>
#include <random>
#include <stdexcept>

#include "command.h"
#include "size_limits.h"

namespace delpsc::app {

namespace {

struct TriangulateOptions {
  std::string input;
  std::string generate;
  bool check = false;
  std::size_t remove = 0;
  std::uint64_t seed = 1;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::vector<WeightedPoint> load(const TriangulateOptions& o) {
  try {
    if (!o.generate.empty()) {
      reject_points_beyond_memory(io::parse_generator(o.generate).count);  // before making them
      return io::generate_points(o.generate, o.seed);
    }
    std::vector<WeightedPoint> points = io::read_point_set(o.input);
    reject_points_beyond_memory(points.size());
    return points;
  } catch (const io::Error& e) {
    throw Failure{kBadInput, e.what()};
  } catch (const std::invalid_argument& e) {
    throw Failure{kBadInput, e.what()};
  }
}

int run(const TriangulateOptions& o, const GlobalOptions& g) {
  const std::vector<WeightedPoint> points = load(o);
  if (points.empty()) throw Failure{kBadInput, (o.input.empty() ? o.generate : o.input) + ": no points"};
  if (!g.quiet && g.verbosity > 0) std::fprintf(stderr, "delpsc: %zu points read\n", points.size());

  delaunay::RegularTriangulation dt;
  const auto t0 = std::chrono::steady_clock::now();
  dt.insert(points);
  const double insert_seconds = seconds_since(t0);

  report("points", points.size());
  report("dimension", static_cast<long long>(dt.dimension()));
  // Below four affinely independent points there is no tetrahedron: vertices, cells and the
  // rest are 0 by definition, which a bare report would leave to be guessed.
  if (dt.dimension() < 3 && !g.quiet)
    std::fprintf(stderr,
                 "delpsc: warning: the points span only dimension %d (all on a plane, a line or one spot): no "
                 "tetrahedra, so no vertices\n",
                 dt.dimension());
  report("vertices", dt.number_of_vertices());
  report("hidden", dt.number_of_hidden());
  report("finite_cells", dt.number_of_finite_cells());
  report("seconds", insert_seconds);
  report("bytes_per_vertex",
         dt.number_of_vertices() ? double(dt.memory_bytes()) / double(dt.number_of_vertices()) : 0.0);
  bool all_valid = true;
  if (o.check) {
    std::string why;
    const bool valid = dt.is_valid(&why);
    report("valid", valid);
    if (!valid) std::fprintf(stderr, "delpsc: triangulation invalid: %s\n", why.c_str());
    all_valid = valid;
  }
  if (o.remove > 0) {
    // K distinct random vertices, chosen before any is removed so the choice does not depend on
    // the removal order.
    std::vector<delaunay::PointId> vertices;
    for (delaunay::PointId id = 0; id < dt.number_of_points(); ++id)
      if (dt.status(id) == delaunay::PointStatus::vertex) vertices.push_back(id);
    if (o.remove > vertices.size())
      throw Failure{kBadInput, "--remove " + std::to_string(o.remove) + ": the triangulation has only " +
                                   std::to_string(vertices.size()) + " vertices"};
    std::mt19937_64 rng(o.seed);
    const std::size_t k = o.remove;
    for (std::size_t i = 0; i < k; ++i) std::swap(vertices[i], vertices[i + rng() % (vertices.size() - i)]);
    std::size_t removed = 0;
    std::string first_refusal, refusal;
    const auto t1 = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < k; ++i) {
      if (dt.remove(vertices[i], nullptr, &refusal))
        ++removed;
      else if (first_refusal.empty())
        first_refusal = refusal;
    }
    const double remove_seconds = seconds_since(t1);
    // Removal refuses to leave fewer than four affinely independent vertices: fewer than K
    // removed is said, not only counted (--remove 999 of 1,000 removed 996, exit 0, silently).
    if (removed < k && !g.quiet)
      std::fprintf(stderr, "delpsc: warning: --remove %zu: %zu of them removed; the first refused: %s\n", k, removed,
                   first_refusal.c_str());
    report("removed", removed);
    report("remove_refused", k - removed);
    report("remove_seconds", remove_seconds);
    report("remove_microseconds_per_vertex", removed ? 1e6 * remove_seconds / double(removed) : 0.0);
    report("vertices_after_remove", dt.number_of_vertices());
    report("finite_cells_after_remove", dt.number_of_finite_cells());
    if (o.check) {
      std::string why;
      const bool valid = dt.is_valid(&why);
      report("valid_after_remove", valid);
      if (!valid) std::fprintf(stderr, "delpsc: invalid after removal: %s\n", why.c_str());
      all_valid = all_valid && valid;
    }
  }
  return all_valid ? kOk : kCheckFailed;
}

}  // namespace

Runner register_triangulate(CLI::App& app) {
  auto o = std::make_shared<TriangulateOptions>();
  app.add_option("POINTS", o->input,
                 "Point set: *.bin (records of 4 little-endian doubles x y z w) or text "
                 "lines 'x y z [w]'");
  app.add_option("--generate", o->generate,
                 "Instead of a file, generate KIND:N points (uniform, weighted, sphere, grid)");
  app.add_flag("--check", o->check, "Check every invariant of the triangulation (exact)");
  app.add_option("--remove", o->remove, "Then remove K random vertices and time it")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--seed", o->seed, "Seed for --generate and --remove");
  app.footer(
      "Prints key=value lines: points, dimension, vertices, hidden, finite_cells, seconds "
      "(insertion, spatial sort included), bytes_per_vertex, valid (--check), removed, "
      "remove_refused (removals refused: they would leave fewer than four affinely independent vertices), "
      "remove_seconds, valid_after_remove (--remove).\n\n"
      "Examples:\n  delpsc triangulate cloud.bin --check\n"
      "  delpsc triangulate --generate uniform:1000000 --remove 10000 --check");
  return [o](const GlobalOptions& g) {
    if (o->input.empty() == o->generate.empty())
      throw Failure{kBadInput, "triangulate: give exactly one of POINTS or --generate KIND:N"};
    return run(*o, g);
  };
}

}  // namespace delpsc::app
