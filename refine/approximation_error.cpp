#include "approximation_error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <atomic>
#include <functional>
#include <future>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

#include <delpsc/kernel/aabb_tree.h>
#include <delpsc/kernel/constructions.h>

#include "edge_record_sort.h"
#include "edges_by_curve.h"
#include "triangle_samples.h"

namespace delpsc::refine {

namespace {

using Triangle = std::array<std::uint32_t, 3>;
/// Thrown by FarthestSample::sample when ApproximationOptions::stop says so; caught at the top.
struct Stopped {};
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr std::uint32_t kNone = 0xffffffffu;

/// For each triangle and each of its edges k (opposite corner k), a triangle across that edge:
/// the other one of a manifold edge, the next one around a non-manifold edge (they form a
/// cycle), kNone on the boundary. O(T log T).
kernel::LargeVector<std::array<std::uint32_t, 3>> edge_neighbours(std::span<const Triangle> triangles) {
  struct HalfEdge {
    std::uint32_t lo, hi, triangle, edge;
  };
  kernel::LargeVector<HalfEdge> half;
  half.reserve(3 * triangles.size());
  std::uint32_t vertex_bound = 0;
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t u = triangles[t][(k + 1) % 3], v = triangles[t][(k + 2) % 3];
      if (u != v) half.push_back({std::min(u, v), std::max(u, v), t, k});
      vertex_bound = std::max({vertex_bound, u + 1, v + 1});
    }
  sort_edge_records(half, vertex_bound, [](const HalfEdge& x, const HalfEdge& y) {
    return x.lo != y.lo ? x.lo < y.lo : x.hi != y.hi ? x.hi < y.hi : x.triangle < y.triangle;
  });
  kernel::LargeVector<std::array<std::uint32_t, 3>> out(triangles.size(), {kNone, kNone, kNone});
  for (std::size_t i = 0; i < half.size();) {
    std::size_t j = i;
    while (j < half.size() && half[j].lo == half[i].lo && half[j].hi == half[i].hi) ++j;
    for (std::size_t k = i; j - i > 1 && k < j; ++k)
      if (half[k].triangle != half[k + 1 < j ? k + 1 : i].triangle)  // not a segment's own edge twice
        out[half[k].triangle][half[k].edge] = half[k + 1 < j ? k + 1 : i].triangle;
    i = j;
  }
  return out;
}

/// edge_neighbours(complex.triangles) read off the complex's own edge table instead of sorting
/// every half-edge again: the same triangles (an edge's triangles are listed in increasing order
/// there, as edge_neighbours sorts them), in O(T) and without its two 16-byte records per
/// half-edge (96 MB and ~0.1 s on a 1M-triangle input meshed coarsely, the run's peak).
kernel::LargeVector<std::array<std::uint32_t, 3>> complex_neighbours(const protect::Complex& complex) {
  kernel::LargeVector<std::array<std::uint32_t, 3>> out(complex.triangles.size(), {kNone, kNone, kNone});
  for (std::uint32_t t = 0; t < complex.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const auto around = complex.edge_triangle_ids(complex.triangle_edges[t][k]);
      if (around.size() < 2) continue;
      const auto at = std::find(around.begin(), around.end(), t);
      out[t][k] = at + 1 == around.end() ? around.front() : *(at + 1);
    }
  return out;
}

/// The largest distance from samples to a set of triangles `to` (indices into `vertices`; `tree`
/// is built over them). Most samples cannot raise the maximum, and showing it needs no tree
/// query: starting from the triangle that settled the previous sample (samples come in spatially
/// coherent order, a triangle's or a segment's at a time), a greedy walk across the edge or
/// vertex holding the closest point, as in point location, usually reaches a triangle no
/// farther than the largest distance so far within a step or two. Only the samples the walk does
/// not settle are queried, and the result is the one querying every sample would give (up to the
/// rounding of the distances compared). On the CGAL demo models meshed at λ = 1% and sampled at
/// h = λ/2 this leaves one query in 10 to 150 samples (fandisk, joint, the elephant).
class FarthestSample {
 public:
  using Neighbours = kernel::LargeVector<std::array<std::uint32_t, 3>>;
  /// The closest point of `to` to a point: a tree's, or a ClosestPointIndex's over the input.
  using Closest = std::function<std::optional<kernel::ClosestTriangle>(const Vec3&)>;
  /// `stop`: ApproximationOptions::stop, or empty.
  FarthestSample(std::span<const Vec3> vertices, std::span<const Triangle> to, Closest closest,
                 const std::function<bool()>& stop)
      : vertices_(vertices), to_(to), closest_(std::move(closest)), own_neighbours_(edge_neighbours(to)),
        neighbours_(own_neighbours_), stop_(stop) {}
  /// With `to`'s edge_neighbours made once for several samplers (they must outlive this one).
  FarthestSample(std::span<const Vec3> vertices, std::span<const Triangle> to, Closest closest,
                 const Neighbours& neighbours, const std::function<bool()>& stop)
      : vertices_(vertices), to_(to), closest_(std::move(closest)), neighbours_(neighbours), stop_(stop) {}
  // A copy's neighbours_ would point into the original's own table.
  FarthestSample(const FarthestSample&) = delete;
  FarthestSample& operator=(const FarthestSample&) = delete;

  /// Throws Stopped when the stop says so (asked every 4,096 samples).
  void sample(const Vec3& p) {
    if ((result_.samples & 4095) == 4095 && stop_ && stop_()) throw Stopped{};
    if (result_.samples++ > 0 && walk(p)) return;
    const auto closest = closest_(p);
    const double distance = closest ? std::sqrt(closest->squared_distance) : kInfinity;
    if (closest) current_ = closest->triangle;
    if (result_.samples == 1 || distance > result_.distance) {
      result_.distance = distance;
      result_.where = p;
      largest_squared_ = distance * distance;
    }
  }

  const OneSidedDistance& result() const { return result_; }

 private:
  /// The walk goes on only while it gets closer, so it is short wherever triangles are not much
  /// smaller than the sample spacing. Across thin triangles (a fan's, a finely tessellated
  /// cylinder's side strips) a sample is many triangles from the previous one; beyond a few steps
  /// the query is cheaper: fans are searched by angle (closest_point_index.h) and the tree of the
  /// rest gets their bound. Session 30 had 64 steps, when the tree alone was slow near fans;
  /// with the index, 4 steps measure the cylinder of caps fanned from 20,000 rim points at 0.5%
  /// in 1.3 s instead of 2.4 s, and the CGAL demo models as fast as before (BENCHMARKS.md,
  /// "Session 33").
  static constexpr int kWalkSteps = 4;
  struct Near {
    double squared_distance;
    kernel::TriangleFeature feature;
  };

  Near closest_on(const Vec3& p, std::uint32_t t) const {
    const Triangle& c = to_[t];
    const auto q = kernel::closest_point_on_triangle(p, vertices_[c[0]], vertices_[c[1]], vertices_[c[2]]);
    return {(q.point - p).squaredNorm(), q.feature};
  }

  /// True if the walk from the current triangle finds one within the largest distance of p.
  bool walk(const Vec3& p) {
    if (current_ == kNone) return false;
    std::uint32_t t = current_;
    Near here = closest_on(p, t);
    for (int step = 0;; ++step) {
      if (here.squared_distance <= largest_squared_) {
        current_ = t;
        return true;
      }
      if (step == kWalkSteps || here.feature.kind == kernel::FeatureKind::face) return false;
      // Across the edge holding the closest point, or either edge at the vertex holding it.
      const int k = here.feature.index;
      const std::array<int, 2> edges = here.feature.kind == kernel::FeatureKind::edge
                                           ? std::array<int, 2>{k, -1}
                                           : std::array<int, 2>{(k + 1) % 3, (k + 2) % 3};
      std::uint32_t next = kNone;
      Near best = here;
      for (const int e : edges) {
        if (e < 0 || neighbours_[t][e] == kNone) continue;
        const Near c = closest_on(p, neighbours_[t][e]);
        if (c.squared_distance < best.squared_distance) {
          best = c;
          next = neighbours_[t][e];
        }
      }
      if (next == kNone) return false;  // a local minimum that is not close enough
      t = next;
      here = best;
    }
  }

  std::span<const Vec3> vertices_;
  std::span<const Triangle> to_;
  Closest closest_;
  Neighbours own_neighbours_;
  std::span<const std::array<std::uint32_t, 3>> neighbours_;
  std::function<bool()> stop_;
  std::uint32_t current_ = kNone;
  OneSidedDistance result_;
  double largest_squared_ = 0;  // result_.distance squared
};

/// The surface samples of the header: per triangle its corners not sampled yet (so each vertex
/// once), then triangle_samples. Only the triangles from index `first` on; the corners of those
/// before count as sampled, so that splitting the triangles between threads samples every vertex
/// once all the same.
void sample_surface(std::span<const Vec3> vertices, std::span<const Triangle> triangles, double h, FarthestSample& to,
                    std::size_t first = 0) {
  std::vector<std::uint8_t> sampled(vertices.size(), 0);
  for (const Triangle& t : triangles.first(first))
    for (const std::uint32_t v : t) sampled[v] = 1;
  kernel::LargeVector<Vec3> inside;
  for (const Triangle& t : triangles.subspan(first)) {
    for (const std::uint32_t v : t)
      if (!sampled[v]) {
        sampled[v] = 1;
        to.sample(vertices[v]);
      }
    inside.clear();
    triangle_samples(vertices[t[0]], vertices[t[1]], vertices[t[2]], h, inside);
    for (const Vec3& p : inside) to.sample(p);
  }
}

/// The curve samples of the header for segments stored as (u, v, v): both ends and each segment
/// cut into pieces of length <= h.
void sample_polyline(std::span<const Vec3> vertices, std::span<const Triangle> segments, double h, FarthestSample& to) {
  for (const Triangle& s : segments) {
    const Vec3 &a = vertices[s[0]], &b = vertices[s[1]];
    const std::size_t n = sample_pieces((b - a).norm(), h);
    for (std::size_t k = 0; k <= n; ++k) to.sample(a + (static_cast<double>(k) / static_cast<double>(n)) * (b - a));
  }
}

void keep_larger(OneSidedDistance& total, const OneSidedDistance& d) {
  if (d.samples == 0) return;
  if (total.samples == 0 || d.distance > total.distance) {
    total.distance = d.distance;
    total.where = d.where;
  }
  total.samples += d.samples;
}

void validate(const io::SurfaceMesh& output) {
  const std::size_t nv = output.vertices.size();
  for (std::size_t v = 0; v < nv; ++v)
    if (!output.vertices[v].allFinite())
      throw std::invalid_argument("measure_approximation: vertex " + std::to_string(v) + " is not finite");
  for (const auto& t : output.triangles)
    for (const std::uint32_t v : t)
      if (v >= nv) throw std::invalid_argument("measure_approximation: triangle vertex " + std::to_string(v) + " out of range");
  for (const auto& e : output.edges)
    for (const std::uint32_t v : e)
      if (v >= nv) throw std::invalid_argument("measure_approximation: edge vertex " + std::to_string(v) + " out of range");
  if (!output.edge_curve.empty() && output.edge_curve.size() != output.edges.size())
    throw std::invalid_argument("measure_approximation: edge_curve has " + std::to_string(output.edge_curve.size()) +
                                " labels for " + std::to_string(output.edges.size()) + " edges");
}

/// The sampling of measure_approximation (both surfaces, then curve by curve) into `e`; throws
/// Stopped when `stop` says so.
void measure_surfaces_and_curves(const io::SurfaceMesh& output, const PolygonDomain& input, double h,
                                 const std::function<bool()>& stop, ApproximationError& e) {
  const protect::Complex& complex = input.complex();
  // Both directions only read const trees (queries are thread-safe), so they run on two threads:
  // the measurement costs a third of the refinement's time at λ/2 spacing, and users wait for
  // it. Input to output is the dearer (its queries search the output's many triangles: 0.53 s
  // against 0.09 s on joint at 0.5%), so its first half of the input triangles gets the second
  // thread and this one does the rest. Each vertex is still sampled once.
  // The output's tree and its triangles' neighbours, which only the samplers towards the output
  // need, are made once on the second thread, while this one samples the output towards the
  // input: building the tree (27 ms for the cube's 90,000 output triangles at 0.5%) no longer
  // holds both threads up.
  std::optional<kernel::AabbTree> output_tree;
  FarthestSample::Neighbours output_neighbours;
  std::promise<void> output_side_made;
  std::shared_future<void> output_side_ready = output_side_made.get_future().share();
  const auto on_output = [&](const Vec3& p) { return output_tree->closest_point(p); };
  const std::span<const Triangle> input_triangles(complex.triangles);
  const std::size_t half = input_triangles.size() / 2;
  auto first_half_to_output = std::async(std::launch::async, [&] {
    try {
      output_tree.emplace(output.vertices, output.triangles);
      output_neighbours = edge_neighbours(output.triangles);
      output_side_made.set_value();
    } catch (...) {
      output_side_made.set_exception(std::current_exception());
      throw;
    }
    FarthestSample to_output(output.vertices, output.triangles, on_output, output_neighbours, stop);
    sample_surface(complex.vertices, input_triangles.first(half), h, to_output);  // corners first seen here
    return to_output.result();
  });
  // The input may have fans of thin triangles, where its tree is slow: searched by angle there.
  const ClosestPointIndex& input_index = input.closest_point_index();
  const FarthestSample::Neighbours input_neighbours = complex_neighbours(complex);
  FarthestSample to_input(complex.vertices, complex.triangles, [&](const Vec3& p) { return input_index.closest_point(p); },
                          input_neighbours, stop);
  sample_surface(output.vertices, output.triangles, h, to_input);
  e.output_to_input = to_input.result();
  output_side_ready.get();
  FarthestSample to_output(output.vertices, output.triangles, on_output, output_neighbours, stop);
  sample_surface(complex.vertices, input_triangles, h, to_output, half);
  e.input_to_output = to_output.result();
  keep_larger(e.input_to_output, first_half_to_output.get());

  const auto curve_count = static_cast<std::uint32_t>(complex.curve_count());
  const EdgesByCurve edges = group_edges_by_curve(output, curve_count);
  std::vector<Triangle> input_segments;
  for (std::uint32_t c = 0; c < curve_count; ++c) {
    // Also here: each curve's samplers count their own samples, and short curves never reach a
    // poll of theirs.
    if (stop && stop()) throw Stopped{};
    const auto polyline = complex.curve_polyline(c);
    input_segments.clear();
    for (std::size_t i = 0; i + 1 < polyline.size(); ++i) input_segments.push_back({polyline[i], polyline[i + 1], polyline[i + 1]});
    const std::span<const Triangle> output_segments(edges.segments.data() + edges.offsets[c], edges.offsets[c + 1] - edges.offsets[c]);
    const kernel::AabbTree input_curve(complex.vertices, input_segments);
    const kernel::AabbTree output_curve(output.vertices, output_segments);

    CurveApproximation& a = e.curves.emplace_back();
    a.curve = c;
    a.output_edges = output_segments.size();
    FarthestSample to_output_curve(output.vertices, output_segments,
                                   [&](const Vec3& p) { return output_curve.closest_point(p); }, stop);
    sample_polyline(complex.vertices, input_segments, h, to_output_curve);
    a.input_to_output = to_output_curve.result();
    FarthestSample to_input_curve(complex.vertices, input_segments,
                                  [&](const Vec3& p) { return input_curve.closest_point(p); }, stop);
    sample_polyline(output.vertices, output_segments, h, to_input_curve);
    a.output_to_input = to_input_curve.result();
    keep_larger(e.feature_input_to_output, a.input_to_output);
    keep_larger(e.feature_output_to_input, a.output_to_input);
  }
  e.unlabelled_edges = edges.unlabelled;
  if (edges.unlabelled > 0) {
    // An edge of no input curve is at no finite distance from "its" curve.
    e.feature_output_to_input.distance = kInfinity;
    e.feature_output_to_input.where = edges.first_unlabelled;
  }
}

}  // namespace

double ApproximationError::hausdorff() const { return std::max(output_to_input.distance, input_to_output.distance); }

double ApproximationError::feature_distance() const {
  return std::max(feature_input_to_output.distance, feature_output_to_input.distance);
}

ApproximationError measure_approximation(const io::SurfaceMesh& output, const PolygonDomain& input,
                                         const ApproximationOptions& options) {
  const double h = options.sample_spacing;
  if (!(h > 0) || !std::isfinite(h))
    throw std::invalid_argument("measure_approximation: sample spacing must be positive and finite, not " + std::to_string(h));
  validate(output);

  ApproximationError e;
  const kernel::Box3 box = input.bounding_box();
  e.diagonal = box.empty() ? 0 : box.diagonal();
  e.sample_spacing = h;

  // Once the caller's stop has said true it stays true for both threads (a stop that answers
  // true once must not leave the other thread measuring to the end).
  std::atomic<bool> cut{false};
  const std::function<bool()> stop =
      options.stop ? std::function<bool()>([&cut, &options] {
        if (cut.load(std::memory_order_relaxed)) return true;
        if (!options.stop()) return false;
        cut.store(true, std::memory_order_relaxed);
        return true;
      })
                   : std::function<bool()>{};
  try {
    measure_surfaces_and_curves(output, input, h, stop, e);
  } catch (const Stopped&) {
    e.stopped = true;
  }
  return e;
}

}  // namespace delpsc::refine
