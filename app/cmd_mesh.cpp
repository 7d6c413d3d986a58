// `delpsc mesh`: the DelPSC mesh of a polygon model - Protect (step 1), Mesh2Complex (step 2),
// ∪ Skl^i (step 3) - written by extension (issue 6).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <utility>

#include <delpsc/io/mesh_writer.h>
#include <delpsc/io/output_file.h>
#include <delpsc/io/preview_svg.h>
#include <delpsc/protect/balls.h>
#include <delpsc/protect/complex.h>
#include <delpsc/protect/protect.h>
#include <delpsc/refine/approximation_error.h>
#include <delpsc/refine/mesh_quality.h>
#include <delpsc/refine/mesher.h>
#include <delpsc/refine/polygon_domain.h>
#include <delpsc/refine/protected_balls.h>
#include <delpsc/refine/quality_summary.h>
#include <delpsc/refine/skeleton_check.h>

#include "command.h"
#include "crowding_warning.h"
#include "input_defects.h"
#include "mesh_report.h"
#include "model_input.h"
#include "output_paths.h"
#include "progress.h"
#include "size_limits.h"
#include "size_option.h"
#include "stl_precision.h"
#include "time_limit.h"

namespace delpsc::app {

namespace {

struct MeshCommandOptions {
  std::string input;
  std::string output;
  std::string size = "2%";
  double angle = 60;
  double corner_angle = 60;
  std::optional<std::size_t> max_vertices;  // unset: automatic_vertex_cap; 0: no limit
  std::string facet_distance;  // empty: off
  std::string edge_size;       // empty: the size
  double facet_angle = 0;
  std::string balls_path;
  std::string preview;
  bool check = false;
  bool progress = false;  ///< --progress: progress lines in a log too (stderr not a terminal)
  bool no_initial_sample = false;
  bool no_distances = false;
  double max_seconds = 0;  // 0: no limit
};

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// A vertex where the disk condition fails, kept for the closing message after the mesher is gone.
struct FailingVertex {
  refine::PointId id;
  Vec3 position;
  refine::DiskVerdict verdict;
};

std::vector<FailingVertex> failing_vertices_of(const refine::Mesher& mesher) {
  std::vector<FailingVertex> out;
  for (const auto& [p, verdict] : mesher.failing_vertices())
    out.push_back({p, in_file_frame(mesher.triangulation().point(p).point()), verdict});
  return out;
}

/// The vertices failing the disk condition, one line each on stderr (all with -v, else the first
/// few): where they are and which of D1-D4 fails on which patch.
void list_failing(const std::vector<FailingVertex>& failing, const GlobalOptions& g) {
  const std::size_t shown = g.verbosity > 0 ? failing.size() : std::min<std::size_t>(failing.size(), 20);
  for (std::size_t i = 0; i < shown; ++i) {
    const FailingVertex& f = failing[i];
    std::fprintf(stderr, "delpsc: disk condition %s fails at vertex %u (%.17g %.17g %.17g)", refine::to_string(f.verdict.failure),
                 f.id, f.position.x(), f.position.y(), f.position.z());
    if (f.verdict.patch != refine::kNoElement) std::fprintf(stderr, " on patch %u", f.verdict.patch);
    std::fprintf(stderr, "\n");
  }
  if (shown < failing.size()) std::fprintf(stderr, "delpsc: ... and %zu more (-v lists all)\n", failing.size() - shown);
}

int run(const MeshCommandOptions& o, const GlobalOptions& g) {
  if (o.output.empty() || !io::mesh_format_from_path(o.output))
    throw Failure{kBadInput, "-o " + o.output + ": unknown output format (use .mesh, .vtu, .off, .obj, .ply or .stl)"};
  check_output_path(o.output, "-o");
  if (!o.preview.empty()) check_preview_path(o.preview);
  if (!o.balls_path.empty()) check_output_path(o.balls_path, "--balls");
  const TimeLimit time_limit(o.max_seconds);
  ProgressLine progress(progress_wanted(g.quiet, o.progress));
  PhaseTimes phases;
  progress.phase("read");
  const auto t_read = Clock::now();
  const io::ReadResult model = load_model(o.input, g, &time_limit);
  phases.emplace_back("read", seconds_since(t_read));
  progress.phase("features");
  const auto t0 = Clock::now();
  // The domain's tree serves the input checks too (a second tree was ~5% of meshing fandisk at 2%).
  protect::Complex complex = load_complex(model, o.input, o.angle, o.corner_angle, g);
  reject_duplicate_triangles(complex, o.input);
  const refine::PolygonDomain domain(std::move(complex));
  progress.phase("input check");
  reject_self_intersections(domain.complex(), domain.tree(), o.input, &time_limit);
  reject_empty_complex(domain.complex(), model, o.input, "mesh");
  reject_pinched_patches(domain.complex(), model.soup, complex_options(o.angle, o.corner_angle), o.input, &time_limit);
  if (!g.quiet) {
    if (const std::string fold = fold_warning(domain.complex(), sharpest_fold(domain.complex()), o.input); !fold.empty())
      std::fprintf(stderr, "delpsc: warning: %s\n", fold.c_str());
    if (const std::string unmarked = unmarked_sharp_edge_warning(domain.complex(), o.angle, o.input); !unmarked.empty())
      std::fprintf(stderr, "delpsc: warning: %s\n", unmarked.c_str());
  }
  const kernel::Box3 box = domain.bounding_box();
  const double lambda = parse_size(o.size, (box.hi - box.lo).norm());
  // CGAL's edge_size: the largest protecting ball radius, λ unless given (Protect(D, λ) of the
  // paper uses one λ for both; the balls need only be at most the facets' size for step 2, and
  // smaller ones just cost vertices along the curves).
  const double edge_size = o.edge_size.empty() ? lambda : parse_size(o.edge_size, (box.hi - box.lo).norm(), "--edge-size");
  const std::string& edge_text = o.edge_size.empty() ? o.size : o.edge_size;
  reject_edge_size(edge_size, lambda, edge_text, o.size);
  reject_size_for_balls(domain.complex(), edge_size, protect::ProtectOptions{}.max_balls, edge_text,
                        o.edge_size.empty() ? "--size" : "--edge-size");
  const double expected = expected_vertices(domain.complex(), lambda, edge_size);
  if (!o.max_vertices) reject_size_for_vertices(expected, o.size);

  phases.emplace_back("features", seconds_since(t0));
  time_limit.check_before(o.input, "protection");
  progress.phase("protect");
  const auto t_protect = Clock::now();
  // One floor for every ball of the run, Protect's and RefineBall's (protect::options_for_size).
  const protect::ProtectOptions ball_options = protect::options_for_size(edge_size, (box.hi - box.lo).norm());
  protect::ProtectOptions protect_options = ball_options;
  protect_options.stop = time_limit.poll();
  // Every ball centre is a vertex of the mesh: balls past the vertex cap cannot lead to a mesh
  // within it, so Protect stops there instead of at its own cap (a 1 x 1e-6 x 1 box at 2% took
  // 18 s and 2.2 GB to reach 5,000,000 balls; --max-vertices 1000 now ends it at once).
  const std::size_t vertex_cap = o.max_vertices.value_or(automatic_vertex_cap(expected));  // 0: none
  const bool balls_capped_by_vertices = vertex_cap > 0 && vertex_cap < protect_options.max_balls;
  if (balls_capped_by_vertices) protect_options.max_balls = vertex_cap;
  std::optional<protect::BallSet> ball_set;
  const auto protect_curves = [&] {
    try {
      ball_set.emplace(protect::protect(domain.complex(), edge_size, protect_options));
    } catch (const protect::ProtectionStopped& e) {
      throw Failure{kCheckFailed, o.input + ": " + time_limit.stopped() + ": " + e.what() + "; nothing written"};
    } catch (const protect::ProtectionError& e) {
      if (e.too_many_balls() && balls_capped_by_vertices && o.max_vertices)
        throw Failure{kCheckFailed, o.input + ": protection stopped at --max-vertices " + std::to_string(vertex_cap) +
                                        ": the protecting balls alone would be more vertices (every ball centre is "
                                        "one); nothing written"};
      const std::string cap = e.too_many_balls() && balls_capped_by_vertices
                                  ? "the balls would be more than the automatic vertex cap allows (every ball "
                                    "centre is a vertex of the mesh; --max-vertices sets the cap): "
                                  : "";
      const std::string defect = input_defect_near(domain.complex(), e.where(), edge_size);
      throw Failure{kBadInput, o.input + ": " + cap + e.what() + (defect.empty() ? "" : "; " + defect)};
    }
  };
  protect_curves();
  const double seconds_protect = seconds_since(t_protect);
  phases.emplace_back("protect", seconds_protect);

  const auto t_refine = Clock::now();
  refine::MesherOptions options;
  options.facet_size = lambda;
  if (!o.facet_distance.empty()) {
    options.facet_distance = parse_size(o.facet_distance, (box.hi - box.lo).norm(), "--facet-distance");
    reject_facet_distance(options.facet_distance, lambda, o.facet_distance, o.max_vertices.has_value());
  }
  options.facet_angle = o.facet_angle;
  options.initial_sample = !o.no_initial_sample;
  options.max_vertices = vertex_cap;
  options.stop = time_limit.poll();
  if (progress.enabled()) options.progress = [&progress](std::size_t vertices) { progress.vertices(vertices); };
  progress.phase("refine");
  std::optional<refine::ProtectedBalls> balls;
  std::optional<refine::Mesher> meshing;
  try {
    for (;;) {
      balls.emplace(*ball_set, ball_options);
      meshing.emplace(domain, *balls, options);
      try {
        meshing->run();
        break;
      } catch (const protect::ProtectionError& e) {
        // The initial sample let within half its spacing of the balls spares most step-2 repairs
        // along curves, but on a few hard models it moves where refinement meets the balls'
        // floor (initial_sample.h, kBallClearance): once, start again from Protect's balls with
        // the sample a full spacing from them (the retry's time counts as refinement's).
        if (!options.initial_sample || options.sample_ball_clearance >= 1) throw;
        time_limit.check_before(o.input, "retrying refinement after it reached the balls' floor");
        if (!g.quiet)
          std::fprintf(stderr,
                       "delpsc: refinement reached the balls' floor (%s); retrying with the initial sample a full "
                       "spacing from the balls\n",
                       e.what());
        options.sample_ball_clearance = 1;
        meshing.reset();
        balls.reset();
        protect_curves();
      }
    }
  } catch (const protect::ProtectionError& e) {
    // Refinement shrinks protecting balls where the disk condition fails near a curve; shrinking
    // past protect's safety cap means the complex cannot be meshed at any size, e.g. part.off at
    // --angle 100, whose 90° creases are then no curves. It ended as an 'internal error', exit 1.
    // A defect of the input within λ of that ball is named (input_defects.h).
    const std::string defect = input_defect_near(domain.complex(), e.where(), lambda);
    char generic[320];
    std::snprintf(generic, sizeof generic,
                  "the surface may fold sharply at edges that are no feature curves at --angle %g (a smaller angle "
                  "makes them curves), a curve turn sharply at a vertex that is no corner at --corner-angle %g (a "
                  "smaller angle makes it one), or the surface nearly touch itself",
                  o.angle, o.corner_angle);
    throw Failure{kBadInput, o.input + ": refinement needed protecting balls smaller than the model allows (" +
                                 e.what() + "); " + (defect.empty() ? std::string(generic) : defect)};
  }
  const double seconds_refine = seconds_since(t_refine);
  phases.emplace_back("refine", seconds_refine);
  io::SurfaceMesh mesh = meshing->output();
  const double seconds = seconds_since(t0);
  const std::vector<FailingVertex> failing_vertices = failing_vertices_of(*meshing);
  const std::size_t failing = failing_vertices.size();
  const refine::MesherStats stats = meshing->stats();
  // The triangulation and the restricted facets are most of the memory meshing holds (fandisk at
  // 0.1%: 630 of 730 MB), and nothing below needs them: freed before the checks and the
  // approximation allocate theirs, the peak is the larger of the two instead of their sum
  // (1.06 GB -> 0.73 GB there).
  meshing.reset();
  balls.reset();
  // G1 and the per-patch topology are checked on every run (for the report); --check only
  // makes a failure change the exit code. Vertices are domain points computed in doubles: a
  // tolerance of a few ulps of the diagonal.
  progress.phase("check", mesh.vertices.size());
  const auto t_check = Clock::now();
  // Cut short at twice --max-seconds (TimeLimit::grace): on fans of thin triangles the checks
  // and the distances took four times refinement's time.
  const refine::SkeletonReport check =
      refine::check_skeleton(mesh, domain, 1e-9 * (box.hi - box.lo).norm(), time_limit.grace());
  const refine::QualitySummary quality = refine::summarize_quality(mesh);
  phases.emplace_back("check", seconds_since(t_check));
  // Issue 6: the distances to the input, sampled at spacing λ/2 (coarser only for a run stopped
  // far short of its size: approximation_spacing) - lower bounds at most the spacing below the
  // true ones, in practice within a few percent (refine/approximation_error.h).
  // --no-distances skips it: on the CGAL demo models at 1% it takes two fifths to four fifths of
  // refinement's time (BENCHMARKS.md, session 36).
  refine::ApproximationError approximation;
  double seconds_approximation = 0;
  if (!o.no_distances) {
    progress.phase("approximation", mesh.vertices.size());
    const auto t_approximation = Clock::now();
    refine::ApproximationOptions approximation_options;
    approximation_options.sample_spacing = approximation_spacing(lambda, expected, mesh.vertices.size(),
                                                                 stats.stopped_on_request ? 1 : 8);
    approximation_options.stop = time_limit.grace();
    approximation = refine::measure_approximation(mesh, domain, approximation_options);
    seconds_approximation = seconds_since(t_approximation);
    phases.emplace_back("approximation", seconds_approximation);
  }
  const bool measured = !o.no_distances && !approximation.stopped;
  const bool cut_short = check.stopped || approximation.stopped;
  progress.clear();

  report("vertices", mesh.vertices.size());
  report("triangles", mesh.triangles.size());
  // Clamped where llround would overflow (sizes of 1e-9 of the diagonal and below).
  report("vertices_expected", static_cast<std::size_t>(std::llround(std::min(expected, 1e18))));
  report("patches", std::size_t{domain.patch_count()});
  report("curves", std::size_t{domain.curve_count()});
  report("corners", std::size_t{domain.corner_count()});
  report("lambda", lambda);
  report("edge_size", edge_size);
  report("balls", ball_set->size());
  report("ball_refinements", stats.ball_refinements);
  // Points of a selection a stop cut short were never all inserted: none counts.
  report("initial_sample", stats.initialised ? stats.sampled : 0);
  report("sample_ball_clearance", options.sample_ball_clearance);
  report("seconds_protect", seconds_protect);
  report("seconds_refine", seconds_refine);
  report("seconds", seconds);
  // Before the initial points are all examined nothing is known of it (an empty mesh).
  report("disk_condition", !stats.initialised ? std::string("unchecked")
                           : failing == 0               ? std::string("ok")
                                                        : std::to_string(failing));
  {
    const refine::MesherStats& s = stats;
    report("stopped", std::string(s.stopped_on_request        ? "max-seconds"
                                  : s.stopped_at_max_vertices ? "max-vertices"
                                  : s.stuck                   ? "stuck"
                                  : cut_short                 ? "max-seconds"
                                                              : "no"));
  }
  report("min_angle", refine::min_triangle_angle_degrees(mesh));
  // A measurement or a check cut short says so instead of giving figures it did not finish.
  const auto report_distance = [&](const char* key, double d) {
    if (measured)
      report(key, approximation.relative(d));
    else
      report(key, "unmeasured");
  };
  report_distance("hausdorff", approximation.hausdorff());
  report_distance("hausdorff_out_in", approximation.output_to_input.distance);
  report_distance("hausdorff_in_out", approximation.input_to_output.distance);
  report_distance("feature_distance", approximation.feature_distance());
  if (o.no_distances)
    report("hausdorff_spacing", "unmeasured");
  else
    report("hausdorff_spacing", approximation.relative(approximation.sample_spacing));
  report("seconds_approximation", seconds_approximation);
  report_quality(quality);
  if (check.stopped) {
    report("patches_manifold", std::string("unchecked"));
    report("patches_topology_ok", std::string("unchecked"));
  } else {
    report_topology(compare_topology(check, domain.complex()), g);
  }
  report_complex_topology(refine::complex_topology(mesh.triangles), refine::complex_topology(domain.complex()),
                          g);
  {
    std::vector<refine::DiskFailure> kinds;
    for (const FailingVertex& f : failing_vertices) kinds.push_back(f.verdict.failure);
    report_disk_failures(kinds);
  }
  if (!g.quiet)
    if (const std::string crowded = crowding_warning(mesh, domain.complex(), lambda, expected, o.size); !crowded.empty())
      std::fprintf(stderr, "delpsc: warning: %s: %s\n", o.input.c_str(), crowded.c_str());
  bool g1 = true;
  if (o.check && check.stopped) {
    g1 = false;
    report("g1", std::string("unchecked"));
  } else if (o.check) {
    g1 = check.ok();
    report("g1", g1);
    const std::size_t shown = g.verbosity > 0 ? check.problems.size() : std::min<std::size_t>(check.problems.size(), 20);
    for (std::size_t i = 0; i < shown; ++i) std::fprintf(stderr, "delpsc: G1: %s\n", check.problems[i].c_str());
    if (shown < check.problems.size())
      std::fprintf(stderr, "delpsc: G1: ... and %zu more problems (-v lists all)\n", check.problems.size() - shown);
  }
  if (g.verbosity > 0) {
    const refine::MesherStats& s = stats;
    std::fprintf(stderr,
                 "delpsc: insertions disk=%zu d34=%zu empty_cell=%zu size=%zu distance=%zu angle=%zu pieces=%zu "
                 "(global choices %zu), "
                 "refused_inside_ball=%zu swallowed=%zu rejected_inaccurate=%zu seeds=%zu sampled=%zu, "
                 "first examination: facets queried=%zu spared by the sample's cover=%zu\n",
                 s.insertions_disk, s.insertions_d34, s.insertions_empty_cell, s.insertions_size, s.insertions_distance,
                 s.insertions_angle, s.insertions_pieces, s.global_choices,
                 s.refused_inside_ball, s.swallowed,
                 s.rejected_inaccurate, s.seeds, s.sampled, s.first_queries, s.cover_skipped);
  }

  // The mesh reached is written even when refinement stopped early: it shows where it failed.
  progress.phase("output", mesh.vertices.size());
  const auto t_output = Clock::now();
  try {
    // Last use of the coordinates: the checks and distances above ran in the moved frame, where
    // the mesh was made; the file gets the input's frame (rounded to its precision).
    move_to_file_frame(mesh.vertices);
    refuse_stl_that_collapses(o.output, mesh);
    io::write_mesh(o.output, mesh);
    if (!o.preview.empty()) {
      io::PreviewOptions preview;
      char title[256];
      std::snprintf(title, sizeof title, "%s: %zu vertices, %zu triangles, %u patches (λ = %s), min angle %.1f°",
                    o.input.c_str(), mesh.vertices.size(), mesh.triangles.size(), domain.patch_count(), o.size.c_str(),
                    quality.min_angle_degrees);
      preview.title = title;
      preview.outline_triangles = true;
      io::write_preview_svg(o.preview, mesh, preview);
    }
  } catch (const io::Error& e) {
    throw Failure{kBadInput, e.what()};
  }
  if (!o.balls_path.empty()) {
    try {
      io::write_output_file(o.balls_path, protect::balls_to_text(*ball_set, model_offset()));
    } catch (const io::Error& e) {
      throw Failure{kBadInput, e.what()};
    }
  }
  phases.emplace_back("output", seconds_since(t_output));
  progress.clear();
  report_phases(phases);
  if (cut_short)
    std::fprintf(stderr, "delpsc: %s: %s %s; the mesh (%zu vertices) is in %s\n", o.input.c_str(),
                 time_limit.grace_ended().c_str(),
                 check.stopped ? approximation.stopped
                                     ? "while checking the mesh (G1 and the patches' topology unchecked, the distances unmeasured)"
                                     : "while checking the mesh (G1 and the patches' topology unchecked)"
                               : "while measuring the distances to the input (unmeasured)",
                 mesh.vertices.size(), o.output.c_str());
  const refine::MesherStats& s = stats;
  if (s.stopped_at_max_vertices || s.stopped_on_request || s.stuck || failing != 0) {
    const std::string why =
        s.stopped_on_request ? time_limit.stopped() + (s.initialised ? "" : ", before the initial points were all inserted and examined")
        : s.message.empty()  ? "ended with the disk condition failing"
                             : s.message;
    std::fprintf(stderr, "delpsc: %s: refinement %s; the mesh reached (%zu vertices) is in %s\n", o.input.c_str(),
                 why.c_str(), mesh.vertices.size(), o.output.c_str());
    if (s.stopped_at_max_vertices && !o.max_vertices)
      std::fprintf(stderr,
                   "delpsc: %zu vertices is the automatic cap for this model at --size %s (50 times what the size "
                   "alone needs, within [2e6, 2e7] and what 80%% of the memory this process may use holds): a thin feature or a crossing of the model may stop refinement from ending; "
                   "--max-vertices N raises the cap, --max-vertices 0 removes it\n",
                   options.max_vertices, o.size.c_str());
    list_failing(failing_vertices, g);
    return kCheckFailed;
  }
  return g1 && !cut_short ? kOk : kCheckFailed;
}

}  // namespace

Runner register_mesh(CLI::App& app) {
  auto o = std::make_shared<MeshCommandOptions>();
  add_model_input(app, o->input);
  app.add_option("-o,--output", o->output,
                 "The mesh: .mesh (Medit, patch and curve labels), .vtu (ParaView), .off, .obj, .ply or .stl")
      ->required();
  app.add_option("--size", o->size,
                 "λ: the largest restricted-facet size (CGAL's facet_size) and, unless --edge-size is given, the "
                 "largest protecting ball radius; a length or a percentage of the bounding-box diagonal (default 2%)");
  app.add_option("--edge-size", o->edge_size,
                 "The largest protecting ball radius along the feature curves (CGAL's edge_size), a length or a "
                 "percentage of the diagonal (default: --size), at least 1/64 of it; smaller gives finer curves, "
                 "larger coarser ones");
  add_feature_angles(app, o->angle, o->corner_angle);
  app.add_option("--facet-distance", o->facet_distance,
                 "Largest distance between a triangle's circumcentre and the surface point it stands for (CGAL's "
                 "facet_distance), a length or a percentage of the diagonal (default: off)");
  app.add_option("--facet-angle", o->facet_angle,
                 "Smallest angle, in degrees, of triangles away from the features (vertices all off the protecting "
                 "balls); at most 30, the largest bound for which refinement is known to end (default: off)")
      ->check(range_not_nan(0.0, refine::kMaxFacetAngleDegrees));
  app.add_option("--max-vertices", o->max_vertices,
                 "Stop refining at this many vertices; the mesh reached is still written, exit code 1 (nothing when the "
                 "protecting balls alone, each centre a vertex, would be more: Protect stops there) (default: 50 times "
                 "the vertices the size alone needs, within two and twenty million and what 80% of memory holds at "
                 "1.4 KB each; a size needing more than ten million, or more than memory holds, is refused unless "
                 "this is given; 0: no limit)")
      ->transform(count_in_any_notation())
      ->check(CLI::Range(0.0, 1e15));  // a negative or overflowing count wrapped to "unlimited"
  add_max_seconds_option(app, o->max_seconds,
                         "the mesh reached is still written, as with --max-vertices (nothing when the limit comes "
                         "before Protect has ended; an empty mesh until the initial points are all inserted and "
                         "examined); the checks and the report after the stop take time in proportion to that mesh, and are "
                         "cut short at twice the limit (G1 and the patches' topology then unchecked, the distances "
                         "unmeasured)");
  app.add_flag("--check", o->check,
               "Check guarantee G1 on the output: each patch's triangles a 2-manifold bounded by its "
               "curves' edges, every vertex on the model; exit 1 if it fails");
  app.add_flag("--progress", o->progress,
               "Show progress also when stderr is no terminal (a batch job's log): a line when each phase starts "
               "and every 10 s while refining - the phase, vertices, their rate and the time so far (on a terminal "
               "one line redrawn in place, without this flag; -q: none)");
  app.add_flag("--no-distances", o->no_distances,
               "Do not measure the distances between the mesh and the input (hausdorff..., feature_distance and "
               "hausdorff_spacing are then 'unmeasured'): on the CGAL demo models at 1% the measurement takes two "
               "fifths to four fifths of refinement's time");
  app.add_flag("--no-initial-sample", o->no_initial_sample,
               "Start refinement from the protecting balls alone, as the paper does, instead of also from a "
               "sample of the surface whose points are farther than the size apart (2-3 times as slow, ~20% more "
               "vertices)");
  app.add_option("--balls", o->balls_path, "Write the final protecting balls as text (the format of `delpsc protect`)");
  app.add_option("--preview", o->preview,
                 "Draw the mesh to an SVG picture: triangles coloured by patch and shaded, feature curves and "
                 "corners dark");
  app.footer(
      "Prints key=value lines: vertices, triangles, vertices_expected (what the size alone needs on the model's area; "
      "a run above 8 times it warns, unless -q, where its vertices crowd and what the input has there), patches, "
      "curves, corners, "
      "lambda, edge_size, balls, "
      "ball_refinements, initial_sample (the points refinement started from besides the balls; 0 with "
      "--no-initial-sample), seconds_protect, seconds_refine, seconds (total, I/O excluded), "
      "disk_condition (ok, or the number of vertices where it fails; unchecked when a cap stopped the run "
      "before its first mesh), stopped (no; max-vertices or max-seconds when "
      "a cap ended refinement or twice --max-seconds the checks; stuck when a failure had no step to address it), min_angle, max_angle (degrees), "
      "hausdorff, hausdorff_out_in, hausdorff_in_out (the sampled distance between output and input surfaces, both ways "
      "and each way), feature_distance (the same between each input curve and the output's edges of that curve), "
      "hausdorff_spacing (the sample spacing, λ/2: each figure is at most that below the true one; all five relative "
      "to the bounding-box diagonal; unmeasured with --no-distances or when twice --max-seconds cut the measurement "
      "short), seconds_approximation, "
      "radius_edge_ratio (the largest circumradius / shortest edge), patches_manifold, patches_topology_ok (each "
      "patch's Euler characteristic and boundary loops those of the input; -v lists them), topology_ok (the whole "
      "output's components, Euler characteristic, boundary loops, non-manifold curves and sheets those of the input), "
      "g1 (--check; unchecked, like patches_manifold and patches_topology_ok, when twice --max-seconds cut the check short). "
      "--report FILE.json writes them as JSON with phase times, the angle histogram and the per-patch and whole topology.\n"
      "Exit code 1 when refinement or the checks stopped early (--max-vertices, --max-seconds), the disk condition fails "
      "somewhere or G1 fails (--check): the mesh reached is written anyway and the failing vertices are listed on stderr.\n\n"
      "Examples:\n  delpsc mesh fandisk.off --size 1% -o fandisk.mesh\n"
      "  delpsc mesh samples/part.off -o part.mesh --report part.json --preview part.svg\n"
      "  delpsc mesh part.stl --size 2% --facet-distance 0.1% --facet-angle 25 -o part.vtu");
  return [o](const GlobalOptions& g) { return run(*o, g); };
}

}  // namespace delpsc::app
