// The closest point of a triangle set to a point, where the set has fans of thin triangles
// around a vertex (the caps of a finely tessellated CAD cylinder, the side of a cone): there every
// triangle's bounding box holds the fan's centre, so near it an AABB tree's best-first search
// finds no box to prune and tries most of the fan's triangles (a closed cylinder of 20,000 rim
// points meshed at 0.5%: 12.6 s of distance measurement for 3.2 s of refinement).
//
// A fan's triangles are searched by angle instead. Seen along an axis through the centre c, a
// triangle (c, u, v) lies in the wedge of half-planes from the axis between u's and v's
// directions (its points are convex combinations of c, u and v, and projecting along the axis
// keeps that), so a point p at distance ρ from the axis and angular distance Δ from the wedge is
// at least ρ sin(min(Δ, π/2)) from the triangle, whatever the fan's shape. With the triangles
// sorted by angle, a query tries those around p's direction first and stops on each side at
// the angle where that bound reaches the closest distance found. The other triangles stay in an
// AABB tree. The bound is exact geometry evaluated in doubles, with a margin of 1e-9 rad on every
// angle (the rounding of the projections is ~1e-16 of their length; a direction within 1e-6 of
// the axis makes its triangle one that every query tries): the answer is the distance the tree
// over all triangles gives, up to the rounding of closest_point_on_triangle, though among
// triangles at equal distance it may name another one.
//
// Which fans: every vertex of at least kMinFanDegree triangles, most triangles first, each
// triangle in the first such fan it is part of; the axis is the sum of the triangles' unit
// normals as given or turned to agree with the first one, whichever gives the narrower wedges
// (the first suits a consistently oriented cone, the second a flat fan whatever its
// orientation); a vertex whose wedges overlap more than twice around keeps its triangles in the
// tree. Without fans the index is the tree over all triangles, unchanged.
//
// Cost: building O(T) plus O(d log d) per fan of d triangles and a tree over the rest; a query
// O(log T) in the tree, plus per fan whose box is nearer than the best distance so far O(log d +
// k) for k triangles within the angular bound - O(d) only for points nearer the axis than the
// surface is. Queries are const and thread-safe.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <delpsc/kernel/aabb_tree.h>
#include <delpsc/kernel/point.h>

namespace delpsc::refine {

class ClosestPointIndex {
 public:
  using Triangle = std::array<std::uint32_t, 3>;
  /// Fans of fewer triangles stay in the tree: the tree's visits near their centre are few.
  static constexpr std::size_t kMinFanDegree = 64;

  /// `all`: the tree over all of `triangles`, used as it is when there is no fan. The three must
  /// outlive the index. Preconditions as for kernel::AabbTree.
  ClosestPointIndex(std::span<const Vec3> vertices, std::span<const Triangle> triangles, const kernel::AabbTree& all);

  /// As kernel::AabbTree::closest_point over all the triangles (see the file comment), with its
  /// `below_squared` bound: only a triangle at squared distance below it counts.
  std::optional<kernel::ClosestTriangle> closest_point(const Vec3& p, double below_squared = HUGE_VAL) const;

  /// The fans searched by angle, and their triangles, for tests and statistics.
  std::size_t fan_count() const { return fans_.size(); }
  std::size_t fan_triangles() const;

 private:
  struct Entry {
    double start;  ///< the wedge's first direction, radians in [0, 2π), less the margin
    double width;  ///< its angle with the margin on both sides, at most π + 2 margins
    std::uint32_t triangle;
  };
  struct Fan {
    Vec3 centre, axis, e1, e2;  ///< e1, e2, axis: an orthonormal frame
    kernel::Box3 box;
    std::vector<Entry> entries;         ///< sorted by start
    double widest = 0;                  ///< the largest width
    std::vector<std::uint32_t> always;  ///< triangles with a direction near the axis: always tried
  };

  /// Makes the fan of `centre` from `members` (triangles with that vertex) about the better of
  /// the two axes; nullopt when its wedges overlap more than twice around either way.
  std::optional<Fan> make_fan(std::uint32_t centre, std::span<const std::uint32_t> members) const;
  std::optional<Fan> fan_about(std::uint32_t centre, std::span<const std::uint32_t> members, const Vec3& axis) const;
  /// Where p is seen from a fan: its distance from the axis, its angle, and the first entry
  /// starting after that angle.
  struct Aim {
    double rho, alpha;
    std::size_t first_after;
  };
  Aim aim(const Fan& fan, const Vec3& p) const;
  /// Lowers `best` (squared distance) by the fan's always-tried triangles and the two wedges at
  /// p's direction.
  void probe(const Fan& fan, const Aim& at, const Vec3& p, kernel::ClosestTriangle& best) const;
  /// Lowers `best` to p's closest point on the fan's wedges (after probe), if nearer.
  void search_fan(const Fan& fan, const Aim& at, const Vec3& p, kernel::ClosestTriangle& best) const;
  void try_triangle(std::uint32_t t, const Vec3& p, kernel::ClosestTriangle& best) const;

  std::span<const Vec3> vertices_;
  std::span<const Triangle> triangles_;
  const kernel::AabbTree* all_;
  std::vector<Fan> fans_;
  std::vector<Triangle> rest_triangles_;  ///< the triangles of no fan, and their ids
  std::vector<std::uint32_t> rest_ids_;
  kernel::AabbTree rest_;
};

}  // namespace delpsc::refine
