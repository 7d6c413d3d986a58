// A jittered triangular lattice on a triangle's plane, for the mesher's initial sample
// (initial_sample.h). Random candidates at 4 per spacing² leave holes between the points chosen
// from them (random sequential adsorption stops short of covering: ~0.6 points per spacing²
// where a cover needs ~0.7), and each hole costs one insertion of step 2(b) into the finished
// triangulation with its restricted-facet update, ~3x a point of the batch. A triangular lattice
// of step a whose points are moved by at most j leaves no point of the plane farther than
// a/√3 + j from it, and keeps its points at least a - 2j apart; with a = 1.4 spacing and
// j = 0.15 spacing that is 0.96 spacing and 1.1 spacing: a cover in which no point rejects
// another, at 0.59 points per spacing². The jitter (a fixed function of the lattice index and the plane) keeps
// four points from being co-circular, which would make flat cells in the triangulation.
//
// The lattice depends only on the plane (its frame is a function of the unit normal, its origin
// the plane's point nearest the coordinate origin), so coplanar triangles that share an edge get
// the same lattice, without a seam between them.
#pragma once

#include <cstddef>
#include <vector>

#include <delpsc/kernel/point.h>

namespace delpsc::refine {

/// Lattice step and jitter radius as multiples of the spacing (see the file comment).
inline constexpr double kLatticeStep = 1.45;
inline constexpr double kLatticeJitter = 0.12;

/// Appends to `out` the points of the jittered lattice of step `step` and jitter radius `jitter`
/// on the plane of triangle (a, b, c) that lie in the closed triangle, as a + u (b - a) + v (c - a)
/// (on the triangle up to rounding). Nothing for a degenerate triangle, a step that is not
/// positive and finite, a jitter not in [0, step/2), or a triangle more than 2^50 steps from the
/// origin. Cost O(1 + area / step² + perimeter / step).
void jittered_lattice(const Vec3& a, const Vec3& b, const Vec3& c, double step, double jitter,
                      std::vector<Vec3>& out);

}  // namespace delpsc::refine
