// How far an output mesh is from the input it approximates, measured by sampling (issue 6): the
// two one-sided distances between the surfaces (their maximum is the Hausdorff distance), and
// the same between each input feature curve and the output's feature edges labelled with it.
// DelPSC guarantees the topology of the output (G1, G2) and, through the size λ, closeness to the
// input (§3: every restricted triangle lies in its surface Delaunay ball, centred on the surface,
// of power radius size(t, σ) ≤ λ); these figures say how close a run actually got.
//
// Sampling, with spacing h (ApproximationOptions::sample_spacing):
//   - a surface: every vertex used by a triangle once, and in each triangle rows of points
//     parallel to its longest edge, at most (sqrt(3) / 2) h apart, each row cut into pieces of
//     length <= h (triangle_samples). Every point of the surface is within h of a sample, and a
//     needle triangle gets ~area / h² samples, not (longest edge / h)²;
//   - a curve (polyline): every polyline vertex, and each segment cut into ceil(length / h)
//     equal pieces.
// The distance from each sample to the other side is exact up to the rounding of
// kernel::closest_point_on_triangle (a few ulps). Because the distance to a set is 1-Lipschitz,
// the sampled largest distance d_s of A to B brackets the true one-sided distance d:
//   d_s <= d <= d_s + h,
// so every figure here is a lower bound of the true value that converges as h -> 0, with the gap
// at most h (in practice far less: on the CGAL demo models at λ = 1%, h = λ/2 gives the
// Hausdorff distance within 2% of its value at h = λ/64). Of the order of A / h² samples for a
// surface of area A (more where triangles are small next to h), L / h for a curve of length L.
//
// Cost: O(T log T) for an AABB tree over the output triangles and the edge adjacency of both
// triangle sets, then a few closest-point-on-triangle computations per sample: a sample is
// settled by walking from the previous sample's closest triangle across edges while that gets
// closer, and the tree (kernel/aabb_tree.h; for the input PolygonDomain's ClosestPointIndex,
// which searches fans of thin triangles by angle) is queried only when the walk finds no
// triangle within the largest distance so far (one sample in 10 to 150).
// Curves use one small tree each over their segments, a segment stored as the degenerate
// triangle (u, v, v), whose closest point the tree computes on its edges. Measured on fandisk at
// λ = 1% with h = λ/2: 0.06 s of CPU, 15% of the refinement's (BENCHMARKS.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include <delpsc/io/surface_mesh.h>
#include <delpsc/kernel/point.h>

#include "polygon_domain.h"

namespace delpsc::refine {

struct ApproximationOptions {
  /// h: the largest distance between neighbouring samples (absolute length, > 0 and finite).
  double sample_spacing = 0;
  /// Polled every 4,096 samples of each sampler and once per curve, from both threads at once
  /// (it must be thread-safe); true ends the measurement early, with ApproximationError::stopped
  /// set. Empty: never.
  std::function<bool()> stop;
};

/// The largest distance found from the samples of one set to another set.
struct OneSidedDistance {
  /// Absolute length; +infinity when the first set has samples and the second is empty.
  double distance = 0;
  Vec3 where = Vec3::Zero();  ///< a sample realising it
  std::size_t samples = 0;
};

/// One input feature curve against the output's feature edges labelled with its id.
struct CurveApproximation {
  std::uint32_t curve = 0;
  std::size_t output_edges = 0;  ///< 0: the output lost the curve (its distances are infinite)
  OneSidedDistance input_to_output;  ///< samples of the input polyline to those edges
  OneSidedDistance output_to_input;  ///< samples of those edges to the input polyline
};

struct ApproximationError {
  double diagonal = 0;        ///< of the input's bounding box, the unit of the relative figures
  double sample_spacing = 0;  ///< h, absolute
  OneSidedDistance output_to_input;  ///< output triangles to input triangles
  OneSidedDistance input_to_output;  ///< input triangles to output triangles
  /// One per input curve, in curve order.
  std::vector<CurveApproximation> curves;
  /// Output feature edges whose curve label is not an input curve, or all of them when the
  /// output has edges but no labels: they make feature_output_to_input infinite.
  std::size_t unlabelled_edges = 0;
  OneSidedDistance feature_input_to_output;  ///< the largest over the curves
  OneSidedDistance feature_output_to_input;  ///< the largest over the curves (see unlabelled_edges)

  /// The (sampled) Hausdorff distance, max of both ways, absolute.
  double hausdorff() const;
  /// The Hausdorff distance between the input's curves and the output's feature edges, curve by
  /// curve (each input curve against the edges of the same curve), max of both ways, absolute.
  double feature_distance() const;
  /// A stop (ApproximationOptions::stop) cut the measurement short: the figures are over the
  /// samples taken until then, lower bounds that are not the measurement described above.
  bool stopped = false;
  /// d / diagonal (d itself when the diagonal is 0).
  double relative(double d) const { return diagonal > 0 ? d / diagonal : d; }
};

/// Measures `output` against the polygon mesh of `input` (see the file comment). Output labels
/// are the input complex's ids (as the mesher writes them). Throws std::invalid_argument if h is
/// not positive and finite, a vertex of `output` is not finite, an index is out of range, or edge_curve has neither
/// 0 nor one entry per edge. Both surfaces empty gives 0; one empty gives an infinite distance
/// from the other. Runs the output-to-input direction on a second thread (std::async).
ApproximationError measure_approximation(const io::SurfaceMesh& output, const PolygonDomain& input,
                                         const ApproximationOptions& options);

}  // namespace delpsc::refine
