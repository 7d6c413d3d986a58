// Guarantee G1 of DelPSC (Dey & Levine 2009, §3-4) checked on an output mesh: for each patch σ,
// Skl²|σ (the triangles labelled σ) is a 2-manifold - every edge in one or two of its triangles,
// the triangles around each vertex one disk (a fan whose link is a path or a cycle; at a corner
// where σ touches itself, Domain::corner_pinch_fans, one disk per fan of the input, each open one
// between the feature edges of its two curves) - whose
// boundary is exactly the chain of ball centres along σ's boundary curves (the mesh's feature
// edges of the curves bounding σ once; a curve with σ on both sides, a slit, must be interior),
// with every vertex on the domain near σ. Also per patch the Euler characteristic and the number
// of boundary loops (for G2 against the input's). Before that, the mesh itself: one patch label
// per triangle and one curve label per edge, each naming a patch or curve of the domain, every
// index a vertex (otherwise nothing else is checked); each feature edge's ends on its curve and
// each corner vertex at a corner of the domain.
//
// Independent of the mesher's data structures: it reads only the SurfaceMesh and the Domain.
// Cost O(T log T) plus one closest-point query per vertex, plus, per curve of K polyline
// segments, O(K) once and O(log K) per feature-edge end on it (Domain::curve_closest_parameters;
// O(K) per end for a Domain without a batch answer), and O(C) per corner vertex for C corners.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <delpsc/io/surface_mesh.h>

#include "domain.h"

namespace delpsc::refine {

struct PatchSkeleton {
  std::uint32_t patch = 0;
  std::size_t vertices = 0, edges = 0, triangles = 0;
  int euler = 0;                   ///< V - E + F of Skl²|σ
  std::size_t boundary_loops = 0;  ///< connected components of its boundary edges
  /// Every edge in at most two of its triangles and the triangles around each vertex one disk
  /// (the 2-manifold part of G1, without the boundary and the distance to the domain).
  bool manifold = true;
  /// The same two figures for Skl²|σ cut open along its slits (curves with σ on both sides),
  /// the way protect::Patch counts the input's patches: equal to euler and boundary_loops when
  /// σ has no slit, and then G2 makes them the input's. An interior slit arc makes the cut
  /// surface's Euler characteristic one less and adds one boundary loop.
  int cut_euler = 0;
  std::size_t cut_boundary_loops = 0;
};

struct SkeletonReport {
  std::vector<PatchSkeleton> patches;  ///< one per patch of the domain
  std::vector<std::string> problems;   ///< empty iff G1 holds (when not stopped)
  /// The check's stop said true before it ended: `patches` is incomplete and G1 undecided.
  bool stopped = false;
  bool ok() const { return problems.empty() && !stopped; }
};

/// `tolerance`: largest distance accepted between a vertex and the domain (absolute). `stop`
/// (may be empty) is polled every 1,024 vertices of a patch and once per curve; true ends the
/// check with SkeletonReport::stopped set.
SkeletonReport check_skeleton(const io::SurfaceMesh& mesh, const Domain& domain, double tolerance,
                              const std::function<bool()>& stop = {});

}  // namespace delpsc::refine
