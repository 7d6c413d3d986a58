// A jittered triangular lattice on a triangle's plane, for the mesher's initial sample
// (initial_sample.h). Random candidates at 4 per spacing² leave holes between the points chosen
// from them (random sequential adsorption stops short of covering: ~0.6 points per spacing²
// where a cover needs ~0.7), and each hole costs one insertion of step 2(b) into the finished
// triangulation with its restricted-facet update, ~3x a point of the batch. A triangular lattice
// of step a whose points are moved by at most j leaves no point of the plane farther than
// a/√3 + j from it, and keeps its points at least a - 2j apart; with a = 1.45 spacing and
// j = 0.12 spacing that is 0.957 spacing and 1.21 spacing: a cover in which no point rejects
// another, at 0.55 points per spacing². The jitter (a fixed function of the lattice index and
// the plane) keeps four points from being co-circular, which would make flat cells in the
// triangulation. It is computed with std::sin and std::cos: the same points on every run of a
// build, not necessarily bit for bit across C libraries.
//
// The lattice depends only on the plane (its frame is a function of the unit normal, its origin
// the plane's point nearest the coordinate origin), so coplanar triangles that share an edge get
// the same lattice, without a seam between them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <delpsc/kernel/large_array.h>
#include <delpsc/kernel/point.h>

namespace delpsc::refine {

/// Lattice step and jitter radius as multiples of the spacing (see the file comment).
inline constexpr double kLatticeStep = 1.45;
inline constexpr double kLatticeJitter = 0.12;
/// Largest angle, in degrees, between a triangle's normal and its cluster's lattice plane
/// (PolygonDomain::surface_candidates): the cover radius grows by 1 / cos of it, 0.957 to 1.06
/// spacings at 25° (a few holes where a cluster is steepest, left to refinement), while curved
/// models of small triangles get a lattice at all (insertions left to step 2 halved on fandisk,
/// the elephant and the sphere against clusters of coplanar triangles only).
inline constexpr double kClusterAngle = 25;

/// A lattice's plane: unit normal (largest component positive), axes u and v, origin (the
/// plane's point nearest the coordinate origin) and the key of its jitter (from the plane's
/// offset). Not valid for a zero normal or a step that is not positive and finite.
struct LatticeFrame {
  Vec3 normal = Vec3::Zero(), u = Vec3::Zero(), v = Vec3::Zero(), origin = Vec3::Zero();
  std::uint64_t key = 0;
  bool valid = false;
};

/// The frame of the plane through `point` with normal `normal`, for lattices of step `step`.
LatticeFrame lattice_frame(const Vec3& normal, const Vec3& point, double step);

/// The points of `frame`'s jittered lattice whose projection on its plane falls in the
/// projection of triangle (a, b, c), mapped to the triangle by their barycentric coordinates.
/// For a triangle of the plane, its lattice points; for a nearby triangle at a small angle to it
/// (a cluster of a curved surface), points on the triangle that are at least as far apart as in
/// the plane (projection only shortens) and cover it as the plane's cover radius over the cosine
/// of the angle. Nothing for a triangle seen edge-on, or an invalid frame, step or jitter.
/// `work`, if given, is a budget of rows and lattice sites to try, charged as they are: false
/// (and a partial output) when it would run out, for a caller that must bound its time (a
/// needle triangle 10^8 steps long costs 10^8 sites for no point). Cost O(1 + area / step² +
/// perimeter / step).
bool jittered_lattice(const LatticeFrame& frame, const Vec3& a, const Vec3& b, const Vec3& c, double step,
                      double jitter, kernel::LargeVector<Vec3>& out, std::size_t* work = nullptr);

/// Appends to `out` the points of the jittered lattice of step `step` and jitter radius `jitter`
/// on the plane of triangle (a, b, c) that lie in the closed triangle, as a + u (b - a) + v (c - a)
/// (on the triangle up to rounding). Nothing for a degenerate triangle, a step that is not
/// positive and finite, a jitter not in [0, step/2), or a triangle more than 2^50 steps from the
/// origin. Cost O(1 + area / step² + perimeter / step).
void jittered_lattice(const Vec3& a, const Vec3& b, const Vec3& c, double step, double jitter,
                      kernel::LargeVector<Vec3>& out);

}  // namespace delpsc::refine
