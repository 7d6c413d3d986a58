// Reading a model for a subcommand: io errors become a bad-input exit with the reader's message,
// and the reader's warnings go to stderr unless -q.
#pragma once

#include <delpsc/io/error.h>
#include <delpsc/io/model_frame.h>
#include <delpsc/io/read_model.h>
#include <delpsc/io/unused_vertices.h>
#include <delpsc/kernel/aabb_tree.h>
#include <delpsc/protect/complex.h>
#include <delpsc/protect/self_intersections.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "command.h"
#include "file_frame.h"
#include "time_limit.h"

namespace delpsc::app {

/// Reads the model, drops the vertices no triangle uses (a warning says how many) and moves it
/// next to the origin when it lies far from it (exactly; see io/model_frame.h and model_offset()).
/// A pipe without data (a FIFO nobody writes to) is waited on, with a line on stderr after a
/// second unless -q, until `limit` (--max-seconds, if any) passes: exit code 1, nothing written.
inline io::ReadResult load_model(const std::string& path, const GlobalOptions& g, const TimeLimit* limit = nullptr) {
  io::ReadResult result;
  io::PipeWait wait;
  if (limit) wait.stop = limit->poll();
  if (!g.quiet)
    wait.waiting = [&] {
      std::fprintf(stderr, "delpsc: waiting for data on %s, a pipe without a writer or data so far%s\n", path.c_str(),
                   limit && limit->active() ? " (until --max-seconds)" : " (--max-seconds caps the wait)");
    };
  try {
    result = io::read_model(path, wait);
  } catch (const io::ReadStopped& e) {
    throw Failure{kCheckFailed, std::string(e.what()) + ": " + limit->stopped() + " while reading; nothing written"};
  } catch (const io::Error& e) {
    throw Failure{kBadInput, e.what()};
  }
  // Before anything takes the model's box (io/unused_vertices.h).
  const io::UnusedVertices unused = io::drop_unused_vertices(result.soup);
  result.report.unused_vertices = unused.count;
  model_offset() = io::move_near_origin(result.soup.vertices);
  if (!g.quiet) {
    if (unused.count > 0)
      std::fprintf(stderr, "delpsc: warning: %s: %zu vertex(es) used by no triangle ignored (the first at (%.6g, %.6g, %.6g))\n",
                   path.c_str(), unused.count, unused.first_point.x(), unused.first_point.y(), unused.first_point.z());
    for (const auto& w : result.report.warnings)
      std::fprintf(stderr, "delpsc: warning: %s\n", w.c_str());
    if (!result.report.degenerate_triangles.empty())
      std::fprintf(stderr, "delpsc: warning: %s: %zu zero-area triangle(s) kept out of the complex\n",
                   path.c_str(), result.report.degenerate_triangles.size());
  }
  return result;
}

/// The piecewise smooth complex of a model read by load_model, with the feature and corner
/// angles of the command line; a bad user polyline or similar becomes a bad-input exit naming
/// the file. Flat caps healed on the way (protect::CleanupReport) are a warning unless -q: the
/// surface meshed differs from the file's by their heights.
inline protect::ComplexOptions complex_options(double feature_angle, double corner_angle) {
  protect::ComplexOptions options;
  options.feature_angle_degrees = feature_angle;
  options.corner_angle_degrees = corner_angle;
  const Vec3 offset = model_offset();  // set by load_model
  options.file_offset = {offset.x(), offset.y(), offset.z()};
  return options;
}

inline protect::Complex load_complex(const io::ReadResult& model, const std::string& path, double feature_angle,
                                     double corner_angle, const GlobalOptions& g) {
  const protect::ComplexOptions options = complex_options(feature_angle, corner_angle);
  protect::Complex complex;
  try {
    complex = protect::build_complex(model.soup, options);
  } catch (const std::invalid_argument& e) {
    throw Failure{kBadInput, path + ": " + e.what()};
  }
  if (!g.quiet && complex.cleanup.t_junctions > 0) {
    std::fprintf(stderr,
                 "delpsc: warning: %s: %zu T-junction(s) healed: vertices lying on another triangle's edge, "
                 "with no triangle between; that triangle is split at them (the surface is unchanged",
                 path.c_str(), complex.cleanup.t_junctions);
    if (complex.cleanup.near_t_junctions > 0)
      std::fprintf(stderr, " but at %zu of them, whose vertices the file rounded off the edge: there it moves by up to %g",
                   complex.cleanup.near_t_junctions, complex.cleanup.t_junction_gap);
    std::fprintf(stderr, ")\n");
  }
  if (!g.quiet && !complex.cleanup.flat_caps.empty())
    std::fprintf(stderr,
                 "delpsc: warning: %s: %zu nearly flat triangle(s) (an angle within 1e-4 rad of 180 degrees; the "
                 "first is triangle %u, counted after splitting polygons) split away like zero-area ones\n",
                 path.c_str(), complex.cleanup.flat_caps.size(), complex.cleanup.flat_caps.front());
  return complex;
}

/// A bad-input exit when no triangle of the model is left to `verb` (mesh, protect): all have
/// zero area, or an angle so near 180° (protect::CleanupReport::flat_caps) that they were set
/// aside with them. The message counts both: a needle of height 1e-7 on a base of 1 has an area,
/// and "no triangle of non-zero area" alone sent its user looking for the wrong defect.
inline void reject_empty_complex(const protect::Complex& complex, const io::ReadResult& model, const std::string& path,
                                 const char* verb) {
  if (!complex.triangles.empty()) return;
  const std::size_t flat = complex.cleanup.flat_caps.size();
  std::string why = "no triangle of non-zero area";
  if (flat > 0)
    why = "no triangle left: of the model's " + std::to_string(model.soup.triangles.size()) + ", " +
          std::to_string(flat) + " have an angle within 1e-4 rad of 180 degrees (nearly flat) and " +
          std::to_string(complex.cleanup.zero_area_triangles.size()) + " zero area, and all are set aside";
  throw Failure{kBadInput, path + ": " + why + ": nothing to " + verb};
}

/// At most this many self-intersecting pairs are looked for (info reports ">= this" as this).
inline constexpr std::size_t kSelfIntersectionsCounted = 100;

/// Closer than this fraction of the bounding-box diagonal, a vertex and a triangle not incident to
/// it count as touching (protect's smallest ball is 1e-10 of the diagonal).
inline constexpr double kNearContactFraction = 1e-9;

/// A bad-input exit when a vertex comes within kNearContactFraction of the diagonal of a triangle
/// it is no corner of (protect::find_near_contact): refinement would have to sample at that
/// scale, and ran for minutes towards the vertex cap on a tetrahedron 1e-15 thick.
inline void reject_near_contact(const protect::Complex& complex, const std::array<std::uint32_t, 2>& pair,
                                double tolerance, const std::string& path) {
  const Vec3 p = in_file_frame(complex.vertices[pair[0]]);
  char message[512];
  std::snprintf(message, sizeof message,
                "%s: the model nearly touches itself: vertex %u (%.9g, %.9g, %.9g) lies within %.3g (%g of the "
                "diagonal) of triangle %u, not one of its own (counted after splitting polygons); DelPSC would have "
                "to sample the surface at that scale - weld or separate them",
                path.c_str(), pair[0], p.x(), p.y(), p.z(), tolerance, kNearContactFraction,
                complex.triangle_source[pair[1]]);
  throw Failure{kBadInput, message};
}

/// A bad-input exit when the complex lists a triangle more than once (protect::CleanupReport::
/// duplicate_triangles): the copies overlap everywhere, a self-intersection said at once and by
/// name. Before the domain's fans and the search for crossings, which meet every pair of a
/// triangle's copies (a polygon of millions of repeated indices: minutes to years).
inline void reject_duplicate_triangles(const protect::Complex& complex, const std::string& path) {
  const std::size_t repeats = complex.cleanup.duplicate_triangles;
  if (repeats == 0) return;
  const auto [s, t] = complex.cleanup.first_duplicate;
  char message[512];
  std::snprintf(message, sizeof message,
                "%s: the model lists a triangle more than once: triangles %u and %u (counted after splitting "
                "polygons into triangles) have the same three vertices, and %zu repeat(s) in all; DelPSC needs "
                "surfaces that meet only along shared edges and vertices - remove the repeats",
                path.c_str(), s, t, repeats);
  throw Failure{kBadInput, message};
}

/// A bad-input exit when two triangles of the complex cross or overlap other than along a shared
/// edge or vertex (protect/self_intersections.h): such a model is no piecewise smooth complex
/// (§1.1), the disk condition can never hold along the crossing, and refinement would run until
/// it hit a cap or ran out of memory. The message names the first pair and where it is. Then the
/// near contacts (reject_near_contact), found in the same descent of `tree`. `limit`, if given,
/// can stop the search (--max-seconds): the command then ends with exit code 1, nothing written.
inline void reject_self_intersections(const protect::Complex& complex, const kernel::AabbTree& tree,
                                      const std::string& path, const TimeLimit* limit = nullptr) {
  reject_duplicate_triangles(complex, path);
  kernel::Box3 box;
  for (const Vec3& p : complex.vertices) box.extend(p);
  const double tolerance = kNearContactFraction * (box.hi - box.lo).norm();
  const protect::InputDefects defects = protect::find_input_defects(
      complex, tree, kSelfIntersectionsCounted, tolerance, limit ? limit->poll() : std::function<bool()>{});
  if (defects.stopped)
    throw Failure{kCheckFailed, path + ": " + limit->stopped() +
                                    " while checking the model for self-intersections; nothing written"};
  const auto& pairs = defects.crossing;
  if (pairs.empty()) {
    if (defects.near_contact) reject_near_contact(complex, *defects.near_contact, tolerance, path);
    return;
  }
  const auto [s, t] = pairs.front();
  const auto corners = [&](std::uint32_t k) {
    const auto& tri = complex.triangles[k];
    return std::array<Vec3, 3>{complex.vertices[tri[0]], complex.vertices[tri[1]], complex.vertices[tri[2]]};
  };
  // Where they meet (a centroid of a CAD triangle may be far from it), else s's centroid.
  const std::array<Vec3, 3> cs = corners(s);
  Vec3 c = protect::improper_contact_point(cs, complex.triangles[s], corners(t), complex.triangles[t])
               .value_or((cs[0] + cs[1] + cs[2]) / 3);
  c = in_file_frame(c);
  char message[512];
  std::snprintf(message, sizeof message,
                "%s: the model intersects itself: triangles %u and %u (counted after splitting polygons into "
                "triangles) cross or overlap near (%.6g, %.6g, %.6g), and %s%zu pair(s) in all; DelPSC needs "
                "surfaces that meet only along shared edges and vertices - repair the model "
                "(`delpsc info` counts the pairs)",
                path.c_str(), complex.triangle_source[s], complex.triangle_source[t], c.x(), c.y(), c.z(),
                pairs.size() == kSelfIntersectionsCounted ? "at least " : "", pairs.size());
  throw Failure{kBadInput, message};
}

/// The same with a tree of its own (one tree for both checks); `delpsc mesh` passes its domain's.
inline void reject_self_intersections(const protect::Complex& complex, const std::string& path,
                                      const TimeLimit* limit = nullptr) {
  reject_self_intersections(complex, kernel::AabbTree(complex.vertices, complex.triangles), path, limit);
}

/// The feature angles pinch_free_angle tries, in degrees.
inline constexpr std::array<double, 10> kPinchFreeAngles = {15, 30, 45, 60, 75, 90, 105, 120, 135, 150};

/// When a model's complex at `options` has pinches the mesher refuses (unsupported_pinches):
/// the feature angle of kPinchFreeAngles nearest options.feature_angle_degrees (the larger of
/// two as near: fewer curves) at which it has none, or nullopt. A pinch whose fans the curves
/// of another angle turn into wedges goes there (a torus of six sides pinched to a point, two
/// cones of one patch at 60 degrees, has its sides' edges as curves at 45, each fan a wedge
/// between two); one in the geometry (a needle fan between two holes) at none. One
/// build_complex per angle tried (a few ms on a model of 10^4 triangles), only on the way to a
/// refusal; `stop` (--max-seconds) is asked before each, and when it ends the search *stopped
/// (if given) is set: nullopt then means "not found in time", not "none".
inline std::optional<double> pinch_free_angle(const io::TriangleSoup& soup, protect::ComplexOptions options,
                                              const std::function<bool()>& stop = {}, bool* stopped = nullptr) {
  if (stopped) *stopped = false;
  std::array<double, kPinchFreeAngles.size()> order = kPinchFreeAngles;
  const double given = options.feature_angle_degrees;
  std::sort(order.begin(), order.end(), [given](double a, double b) {
    return std::pair(std::abs(a - given), -a) < std::pair(std::abs(b - given), -b);
  });
  for (const double angle : order) {
    if (angle == given) continue;
    if (stop && stop()) {
      if (stopped) *stopped = true;
      return std::nullopt;
    }
    options.feature_angle_degrees = angle;
    try {
      if (protect::build_complex(soup, options).unsupported_pinches.empty()) return angle;
    } catch (const std::invalid_argument&) {
      return std::nullopt;  // the model itself is bad; the complex at the given angle said so first
    }
  }
  return std::nullopt;
}

/// What to do about unsupported pinches, given pinch_free_angle's answer and whether it stopped.
inline std::string pinch_advice(std::optional<double> free_angle, bool stopped) {
  char advice[200];
  if (stopped)
    std::snprintf(advice, sizeof advice, "--max-seconds ended the search for a feature angle without them");
  else if (free_angle)
    std::snprintf(advice, sizeof advice, "at --angle %g the feature curves divide the model without such a pinch", *free_angle);
  else
    std::snprintf(advice, sizeof advice, "no --angle from %g to %g degrees removes them: separate the sheets or divide the patch there",
                  kPinchFreeAngles.front(), kPinchFreeAngles.back());
  return advice;
}

/// A bad-input exit when a patch touches itself only at a vertex in a way the mesher does not
/// follow fan by fan (protect::Complex::unsupported_pinches: the vertex is no corner, or a fan is
/// not a wedge of kNarrowestPinchWedgeDegrees or more between two curves there): refinement
/// there shrank the balls around the vertex to the floor, or ran for minutes at a needle fan.
/// Pinches at corners between wedges (libcgal-demo's elephant-with-holes.off has 60) are
/// meshed, one disk per fan.
/// The message ends with pinch_advice: `options` are the complex's, `soup` the model it was
/// built from (see pinch_free_angle).
inline void reject_pinched_patches(const protect::Complex& complex, const io::TriangleSoup& soup,
                                   const protect::ComplexOptions& options, const std::string& path,
                                   const TimeLimit* limit = nullptr) {
  const auto& pinches = complex.unsupported_pinches;
  if (pinches.empty()) return;
  const auto [v, patch] = pinches.front();
  const Vec3 p = in_file_frame(complex.vertices[v]);
  bool stopped = false;
  const std::optional<double> free_angle =
      pinch_free_angle(soup, options, limit ? limit->poll() : std::function<bool()>{}, &stopped);
  const std::string advice = pinch_advice(free_angle, stopped);
  char message[1000];
  std::snprintf(message, sizeof message,
                "%s: patch %u touches itself only at the vertex (%.9g, %.9g, %.9g)%s: two fans of its triangles "
                "meet there without sharing an edge, and the mesher follows a pinch only at a corner whose fans are "
                "wedges of %g degrees or more between two feature curves; %s; `delpsc info` counts them",
                path.c_str(), patch, p.x(), p.y(), p.z(),
                pinches.size() > 1 ? (", and at " + std::to_string(pinches.size() - 1) + " more").c_str() : "",
                protect::kNarrowestPinchWedgeDegrees, advice.c_str());
  throw Failure{kBadInput, message};
}

}  // namespace delpsc::app
