// `delpsc info`: what a model is made of and what is wrong with it, before meshing.
#include <delpsc/kernel/aabb_tree.h>
#include <delpsc/protect/complex.h>
#include <delpsc/protect/folds.h>
#include <delpsc/protect/self_intersections.h>
#include <charconv>
#include <limits>
#include <stdexcept>

#include "command.h"
#include "input_defects.h"
#include "model_input.h"
#include "time_limit.h"

namespace delpsc::app {

namespace {

struct InfoOptions {
  std::string input;
  double angle = 60;
  double max_seconds = 0;  // 0: no limit
};

int run(const InfoOptions& o, const GlobalOptions& g) {
  const TimeLimit time_limit(o.max_seconds);
  const io::ReadResult model = load_model(o.input, g, &time_limit);
  const auto& soup = model.soup;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& v : soup.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const protect::Complex complex =
      load_complex(model, o.input, o.angle, protect::ComplexOptions{}.corner_angle_degrees, g);
  std::size_t boundary = 0, non_manifold = 0;
  for (std::size_t e = 0; e < complex.edges.size(); ++e) {
    boundary += (complex.edge_feature[e] & protect::kBoundaryEdge) != 0;
    non_manifold += (complex.edge_feature[e] & protect::kNonManifoldEdge) != 0;
  }
  // Shortest round-trip digits: a model far from the origin (1e9 + its size of 1) keeps its extent.
  std::string box;
  for (const Vec3& corner : {in_file_frame(lo), in_file_frame(hi)})
    for (int k = 0; k < 3; ++k) {
      char digits[32];
      const auto end = std::to_chars(digits, digits + sizeof digits, corner[k]).ptr;
      box += (box.empty() ? "" : " ") + std::string(digits, end);
    }
  report("format", model.report.format);
  report("vertices", soup.vertices.size());
  report("triangles", soup.triangles.size());
  report("merged_vertices", model.report.merged_vertices);
  report("unused_vertices", model.report.unused_vertices);  // dropped, with a warning (load_model)
  report("zero_area_triangles", model.report.degenerate_triangles.size());
  report("t_junctions", complex.cleanup.t_junctions);  // healed (complex.h)
  report("near_t_junctions", complex.cleanup.near_t_junctions);
  report("t_junction_gap", complex.cleanup.t_junction_gap);
  report("boundary_edges", boundary);
  report("non_manifold_edges", non_manifold);
  report("bbox", box);
  report("diagonal", (hi - lo).norm());
  report("corners", complex.corner_count());
  report("curves", complex.curve_count());
  report("patches", complex.patch_count());
  report("pinched_vertices", complex.pinches.size());  // a patch touching itself there: meshed fan by fan
  const auto& unsupported = complex.unsupported_pinches;
  report("unsupported_pinches", unsupported.size());  // those mesh refuses (no corner, or odd fans)
  // With unsupported pinches: the feature angle nearest --angle without one (mesh's refusal names
  // it), or none. --max-seconds may end that search: "unknown" then, not "none".
  bool pinch_search_stopped = false;
  const std::optional<double> free_angle =
      unsupported.empty()
          ? std::nullopt
          : pinch_free_angle(model.soup, complex_options(o.angle, protect::ComplexOptions{}.corner_angle_degrees),
                             time_limit.poll(), &pinch_search_stopped);
  // A string in every case, so that the JSON report's type does not depend on the model.
  char angle[32] = "-";
  if (free_angle)
    std::snprintf(angle, sizeof angle, "%g", *free_angle);
  else if (pinch_search_stopped)
    std::snprintf(angle, sizeof angle, "unknown");
  else if (!unsupported.empty())
    std::snprintf(angle, sizeof angle, "none");
  report("pinch_free_angle", std::string(angle));
  report("duplicate_triangles", complex.cleanup.duplicate_triangles);  // repeats: mesh refuses
  // The one step whose time is not linear in the model (pairs of overlapping boxes: a cone's side
  // of d triangles against a base triangulated in one strip of thin triangles makes ~d²/4 of
  // them; a fan's own pairs, flat or a cone's, are settled at once, and pairs across two fans by
  // angle), hence the only one --max-seconds polls.
  const protect::InputDefects defects =
      protect::find_input_defects(complex, kernel::AabbTree(complex.vertices, complex.triangles),
                                  kSelfIntersectionsCounted, 0, time_limit.poll(),
                                  protect::CrossingPairs::first_found);  // only counted here
  const std::size_t crossing = defects.crossing.size();
  report("self_intersections", crossing);  // pairs of triangles, at most kSelfIntersectionsCounted
  // The sharpest edge between two triangles (input_defects.h).
  const auto sharpest = sharpest_fold(complex);
  report("sharpest_fold_degrees", sharpest ? sharpest->dihedral_degrees : 180.0);
  // Every warning line this command prints (or would print without -q): the reader's, then
  // load_model's and load_complex's own (unused vertices, zero-area triangles, T-junctions, flat caps), then
  // the four below. Counting the reader's alone said 0 beside two printed lines.
  const std::string fold = fold_warning(complex, sharpest, o.input);
  const std::string unmarked = unmarked_sharp_edge_warning(complex, o.angle, o.input);
  report("warnings", model.report.warnings.size() + (model.report.unused_vertices > 0) +
                         !model.report.degenerate_triangles.empty() + !complex.cleanup.flat_caps.empty() + (complex.cleanup.t_junctions > 0) +
                         !fold.empty() + !unmarked.empty() + (crossing > 0) + !unsupported.empty());
  if (!fold.empty() && !g.quiet) std::fprintf(stderr, "delpsc: warning: %s\n", fold.c_str());
  if (!unmarked.empty() && !g.quiet) std::fprintf(stderr, "delpsc: warning: %s\n", unmarked.c_str());
  if (crossing > 0 && !g.quiet)
    std::fprintf(stderr,
                 "delpsc: warning: %s: %s%zu pair(s) of triangles cross or overlap; `delpsc mesh` refuses such a model\n",
                 o.input.c_str(), crossing == kSelfIntersectionsCounted ? "at least " : "", crossing);
  if (!unsupported.empty() && !g.quiet)
    std::fprintf(stderr,
                 "delpsc: warning: %s: at %zu vertex(es) a patch touches itself only at the vertex, not at a corner "
                 "whose fans are wedges of %g degrees or more between two feature curves (at --angle %g); `delpsc "
                 "mesh` refuses such a model; %s\n",
                 o.input.c_str(), unsupported.size(), protect::kNarrowestPinchWedgeDegrees, o.angle,
                 pinch_advice(free_angle, pinch_search_stopped).c_str());
  report("stopped", defects.stopped ? "max-seconds" : "no");
  if (defects.stopped)
    throw Failure{kCheckFailed, o.input + ": " + time_limit.stopped() +
                                    " while checking the model for self-intersections: self_intersections counts "
                                    "only the pairs found before"};
  return kOk;
}

}  // namespace

Runner register_info(CLI::App& app) {
  auto o = std::make_shared<InfoOptions>();
  add_model_input(app, o->input);
  app.add_option("--angle", o->angle, "Feature angle in degrees for the complex counts")
      ->check(range_not_nan(0.0, 180.0));
  add_max_seconds_option(app, o->max_seconds,
                         "the check for self-intersections, the one step that can take long (thousands of "
                         "triangles whose boxes all overlap, as around a cone's apex), ends there with the "
                         "pairs found so far");
  app.footer(
      "Prints key=value lines: format, vertices (those some triangle uses), triangles, merged_vertices, "
      "unused_vertices (used by no triangle: dropped), "
      "zero_area_triangles, t_junctions (edges with vertices of the other side of a crack on them - exactly, or off by rounding: with the edge's ends an angle within 1e-3 rad of 180 degrees - and no triangle between, healed by splitting the edge's triangle at them), near_t_junctions (those with vertices off the edge), t_junction_gap (the largest distance of such a vertex from its edge: how far healing moves the surface), boundary_edges, non_manifold_edges, bbox, diagonal, corners, curves, "
      "patches, pinched_vertices (where a patch touches itself only at a vertex; mesh keeps each fan there a disk of its own), unsupported_pinches (those at no corner, or with a fan that is no wedge of 10 degrees or more between two curves, which mesh refuses), pinch_free_angle (with unsupported pinches, the feature angle of 15, 30, ..., 150 nearest --angle at which there are none, none, or unknown when --max-seconds ended the search; - without), duplicate_triangles (triangles that repeat another's three vertices, which mesh refuses), self_intersections (pairs of triangles that cross or overlap other than along a shared edge or vertex, at most 100 counted), sharpest_fold_degrees (the smallest angle between the two triangles of an edge: 180 flat, 0 folded shut; below 15 a warning says where), warnings, stopped (no, or max-seconds when --max-seconds ended the check for self-intersections: exit code 1).\n\nExample:\n  delpsc info part.stl");
  return [o](const GlobalOptions& g) { return run(*o, g); };
}

}  // namespace delpsc::app
