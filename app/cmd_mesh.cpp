// `delpsc mesh`: the DelPSC mesh of a polygon model - Protect (step 1), Mesh2Complex (step 2),
// ∪ Skl^i (step 3) - written by extension (issue 6).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <optional>
#include <stdexcept>

#include <delpsc/io/mesh_writer.h>
#include <delpsc/protect/balls.h>
#include <delpsc/protect/complex.h>
#include <delpsc/protect/protect.h>
#include <delpsc/refine/mesh_quality.h>
#include <delpsc/refine/mesher.h>
#include <delpsc/refine/polygon_domain.h>
#include <delpsc/refine/protected_balls.h>
#include <delpsc/refine/skeleton_check.h>

#include "command.h"
#include "model_input.h"
#include "size_option.h"

namespace delpsc::app {

namespace {

struct MeshCommandOptions {
  std::string input;
  std::string output;
  std::string size = "2%";
  double angle = 60;
  double corner_angle = 60;
  std::size_t max_vertices = 0;
  std::string facet_distance;  // empty: off
  double facet_angle = 0;
  std::string balls_path;
  bool check = false;
};

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// The vertices failing the disk condition, one line each on stderr (all with -v, else the first
/// few): where they are and which of D1-D4 fails on which patch.
void list_failing(const refine::Mesher& mesher, const GlobalOptions& g) {
  const auto failing = mesher.failing_vertices();
  const std::size_t shown = g.verbosity > 0 ? failing.size() : std::min<std::size_t>(failing.size(), 20);
  for (std::size_t i = 0; i < shown; ++i) {
    const auto& [p, verdict] = failing[i];
    const Vec3 x = mesher.triangulation().point(p).point();
    std::fprintf(stderr, "delpsc: disk condition %s fails at vertex %u (%.17g %.17g %.17g)", refine::to_string(verdict.failure),
                 p, x.x(), x.y(), x.z());
    if (verdict.patch != refine::kNoElement) std::fprintf(stderr, " on patch %u", verdict.patch);
    std::fprintf(stderr, "\n");
  }
  if (shown < failing.size()) std::fprintf(stderr, "delpsc: ... and %zu more (-v lists all)\n", failing.size() - shown);
}

int run(const MeshCommandOptions& o, const GlobalOptions& g) {
  if (o.output.empty() || !io::mesh_format_from_path(o.output))
    throw Failure{kBadInput, "-o " + o.output + ": unknown output format (use .mesh, .vtu, .off, .obj, .ply or .stl)"};
  const io::ReadResult model = load_model(o.input, g);
  const auto t0 = Clock::now();
  protect::Complex complex = load_complex(model, o.input, o.angle, o.corner_angle);
  if (complex.triangles.empty())
    throw Failure{kBadInput, o.input + ": no triangle of non-zero area: nothing to mesh"};
  const refine::PolygonDomain domain(std::move(complex));
  const kernel::Box3 box = domain.bounding_box();
  const double lambda = parse_size(o.size, (box.hi - box.lo).norm());

  const auto t_protect = Clock::now();
  std::optional<protect::BallSet> ball_set;
  try {
    ball_set.emplace(protect::protect(domain.complex(), lambda));
  } catch (const protect::ProtectionError& e) {
    throw Failure{kBadInput, o.input + ": " + e.what()};
  }
  const double seconds_protect = seconds_since(t_protect);

  const auto t_refine = Clock::now();
  refine::ProtectedBalls balls(*ball_set);
  refine::MesherOptions options;
  options.facet_size = lambda;
  if (!o.facet_distance.empty())
    options.facet_distance = parse_size(o.facet_distance, (box.hi - box.lo).norm(), "--facet-distance");
  options.facet_angle = o.facet_angle;
  options.max_vertices = o.max_vertices;
  if (!g.quiet && isatty(STDERR_FILENO))
    options.progress = [](std::size_t vertices) { std::fprintf(stderr, "\rdelpsc: refining, %zu vertices", vertices); };
  refine::Mesher mesher(domain, balls, options);
  mesher.run();
  if (options.progress) std::fprintf(stderr, "\r\033[K");
  const double seconds_refine = seconds_since(t_refine);
  const io::SurfaceMesh mesh = mesher.output();
  const double seconds = seconds_since(t0);
  const std::size_t failing = mesher.failing_vertices().size();

  report("vertices", mesh.vertices.size());
  report("triangles", mesh.triangles.size());
  report("patches", std::size_t{domain.patch_count()});
  report("curves", std::size_t{domain.curve_count()});
  report("corners", std::size_t{domain.corner_count()});
  report("lambda", lambda);
  report("balls", ball_set->size());
  report("ball_refinements", mesher.stats().ball_refinements);
  report("seconds_protect", seconds_protect);
  report("seconds_refine", seconds_refine);
  report("seconds", seconds);
  report("disk_condition", failing == 0 ? std::string("ok") : std::to_string(failing));
  report("min_angle", refine::min_triangle_angle_degrees(mesh));
  bool g1 = true;
  if (o.check) {
    // Vertices are domain points computed in doubles: a tolerance of a few ulps of the diagonal.
    const refine::SkeletonReport check = refine::check_skeleton(mesh, domain, 1e-9 * (box.hi - box.lo).norm());
    g1 = check.ok();
    report("g1", g1);
    const std::size_t shown = g.verbosity > 0 ? check.problems.size() : std::min<std::size_t>(check.problems.size(), 20);
    for (std::size_t i = 0; i < shown; ++i) std::fprintf(stderr, "delpsc: G1: %s\n", check.problems[i].c_str());
    if (shown < check.problems.size())
      std::fprintf(stderr, "delpsc: G1: ... and %zu more problems (-v lists all)\n", check.problems.size() - shown);
  }
  if (g.verbosity > 0) {
    const refine::MesherStats& s = mesher.stats();
    std::fprintf(stderr,
                 "delpsc: insertions disk=%zu d34=%zu size=%zu distance=%zu angle=%zu, refused_inside_ball=%zu "
                 "swallowed=%zu rejected_inaccurate=%zu seeds=%zu\n",
                 s.insertions_disk, s.insertions_d34, s.insertions_size, s.insertions_distance, s.insertions_angle,
                 s.refused_inside_ball, s.swallowed,
                 s.rejected_inaccurate, s.seeds);
  }

  // The mesh reached is written even when refinement stopped early: it shows where it failed.
  try {
    io::write_mesh(o.output, mesh);
  } catch (const io::Error& e) {
    throw Failure{kBadInput, e.what()};
  }
  if (!o.balls_path.empty()) {
    std::ofstream out(o.balls_path, std::ios::binary);
    out << protect::balls_to_text(*ball_set);
    out.close();
    if (!out) throw Failure{kBadInput, o.balls_path + ": cannot write"};
  }
  const refine::MesherStats& s = mesher.stats();
  if (s.stopped_at_max_vertices || s.stuck || failing != 0) {
    std::fprintf(stderr, "delpsc: %s: refinement %s; the mesh reached (%zu vertices) is in %s\n", o.input.c_str(),
                 s.message.empty() ? "ended with the disk condition failing" : s.message.c_str(), mesh.vertices.size(),
                 o.output.c_str());
    list_failing(mesher, g);
    return kCheckFailed;
  }
  return g1 ? kOk : kCheckFailed;
}

}  // namespace

Runner register_mesh(CLI::App& app) {
  auto o = std::make_shared<MeshCommandOptions>();
  app.add_option("IN", o->input, "Polygon model: OFF, OBJ, STL (ASCII or binary) or PLY")->required();
  app.add_option("-o,--output", o->output,
                 "The mesh: .mesh (Medit, patch and curve labels), .vtu (ParaView), .off, .obj, .ply or .stl")
      ->required();
  app.add_option("--size", o->size,
                 "λ: the largest ball radius and restricted-facet size, a length or a percentage of the "
                 "bounding-box diagonal (default 2%)");
  app.add_option("--angle", o->angle,
                 "Feature angle in degrees: an edge whose face normals differ by more is sharp")
      ->check(CLI::Range(0.0, 180.0));
  app.add_option("--corner-angle", o->corner_angle,
                 "A curve turning by more than this many degrees at a vertex gets a corner there")
      ->check(CLI::Range(0.0, 180.0));
  app.add_option("--facet-distance", o->facet_distance,
                 "Largest distance between a triangle's circumcentre and the surface point it stands for (CGAL's "
                 "facet_distance), a length or a percentage of the diagonal (default: off)");
  app.add_option("--facet-angle", o->facet_angle,
                 "Smallest angle, in degrees, of triangles away from the features (vertices all off the protecting "
                 "balls); at most 30, the largest bound for which refinement is known to end (default: off)")
      ->check(CLI::Range(0.0, refine::kMaxFacetAngleDegrees));
  app.add_option("--max-vertices", o->max_vertices,
                 "Stop refining at this many vertices; the mesh reached is still written, exit code 1");
  app.add_flag("--check", o->check,
               "Check guarantee G1 on the output: each patch's triangles a 2-manifold bounded by its "
               "curves' edges, every vertex on the model; exit 1 if it fails");
  app.add_option("--balls", o->balls_path, "Write the final protecting balls as text (the format of `delpsc protect`)");
  app.footer(
      "Prints key=value lines: vertices, triangles, patches, curves, corners, lambda, balls, "
      "ball_refinements, seconds_protect, seconds_refine, seconds (total, I/O excluded), "
      "disk_condition (ok, or the number of vertices where it fails), min_angle (degrees), g1 (--check).\n"
      "Exit code 1 when refinement stopped early (--max-vertices), the disk condition fails "
      "somewhere or G1 fails (--check): the mesh reached is written anyway and the failing vertices are listed on stderr.\n\n"
      "Examples:\n  delpsc mesh fandisk.off --size 1% -o fandisk.mesh\n"
      "  delpsc mesh part.stl --size 2% --facet-distance 0.1% --facet-angle 25 -o part.vtu");
  return [o](const GlobalOptions& g) { return run(*o, g); };
}

}  // namespace delpsc::app
