// An axis-aligned bounding-box tree over a set of triangles: which triangles a segment or a ray
// meets (with the exact classification of constructions.h), the closest point of the set to a
// point, and the triangles whose boxes overlap a box.
//
// Layout (flat arrays, no pointers): the nodes live in one vector in depth-first order, the left
// child of node i is node i + 1 and the right child's index is stored; a leaf holds a contiguous
// range of at most kLeafSize triangles of the tree's own copy of the triangle corners, stored in
// leaf order next to their original ids. Segment and ray queries walk a copy of the same tree
// with two levels collapsed into one, four boxes per node tested together (WideNode). The tree
// therefore does not refer to the caller's arrays after construction. Built top-down along the
// longest axis of the triangle centroids' box, each cut chosen by the binned surface area
// heuristic (kSahBins bins) down to depth kSahDepth and at the median (nth_element) below it or
// when SAH cannot cut, so the depth is at most
// kSahDepth + ceil(log2(n / kLeafSize)) + 1 whatever the input.
//
// Robustness: box tests are floating point but conservative (see SlabQuery in the .cpp: every
// slab parameter is widened beyond its proven rounding error, infinities and NaN included), so
// a triangle is never skipped because of a box test; whether a segment meets a triangle, and
// through which feature (vertex, edge or interior), is then decided exactly by
// kernel::intersect_segment_triangle. A segment through an edge shared by two triangles is
// reported by both, with kind edge. Before that exact test, certified floating-point filters
// (the triangle's plane; for thin triangles, planes through their edges) skip triangles the
// segment provably misses; they never change an answer.
//
// Cost: building O(n log n) time, about 200 bytes per triangle (350 for a thin one). A segment
// query costs O(log n + k) box tests for k reported triangles on well-spread input (more for
// long segments through dense regions: it visits every leaf whose box the segment meets; in a
// fan of thin triangles around a point most boxes near the point overlap, and the edge planes
// spare those leaves' exact tests but not the visits). Queries are const and thread-safe; they
// append to caller-provided vectors so loops need not allocate.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "constructions.h"
#include "large_array.h"
#include "point.h"

namespace delpsc::kernel {

/// A closed axis-aligned box [lo, hi]. Default-constructed empty (lo = +inf, hi = -inf).
struct Box3 {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::infinity());

  bool empty() const { return !(lo.x() <= hi.x() && lo.y() <= hi.y() && lo.z() <= hi.z()); }
  void extend(const Vec3& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void extend(const Box3& b) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
  /// Length of the diagonal hi - lo (0 for a point, undefined for an empty box).
  double diagonal() const { return (hi - lo).norm(); }
  /// True iff the closed boxes share a point. Exact.
  bool overlaps(const Box3& b) const {
    return lo.x() <= b.hi.x() && b.lo.x() <= hi.x() && lo.y() <= b.hi.y() && b.lo.y() <= hi.y() &&
           lo.z() <= b.hi.z() && b.lo.z() <= hi.z();
  }
  /// True iff p lies in the closed box. Exact.
  bool contains(const Vec3& p) const {
    return lo.x() <= p.x() && p.x() <= hi.x() && lo.y() <= p.y() && p.y() <= hi.y() &&
           lo.z() <= p.z() && p.z() <= hi.z();
  }
  /// Squared Euclidean distance from p to the box (0 inside), in floating point.
  double squared_distance(const Vec3& p) const {
    const Vec3 d = (lo - p).cwiseMax(p - hi).cwiseMax(0.0);
    return d.squaredNorm();
  }
};

/// One triangle met by a segment or ray query.
struct TriangleIntersection {
  std::uint32_t triangle = 0;  ///< index into the triangle array given to the tree
  TriangleHit hit;             ///< exact classification and the double point (constructions.h)
};

/// Result of a closest-point query.
struct ClosestTriangle {
  std::uint32_t triangle = 0;  ///< index into the triangle array given to the tree
  Vec3 point = Vec3::Zero();   ///< closest point of that triangle
  double squared_distance = 0;
};

class AabbTree {
 public:
  /// Maximum number of triangles per leaf.
  static constexpr std::uint32_t kLeafSize = 4;
  /// Bins of the surface area heuristic, and the depth from which only median splits are made.
  static constexpr int kSahBins = 16;
  static constexpr int kSahDepth = 24;

  AabbTree() = default;

  /// Builds the tree over `triangles` (vertex indices into `vertices`). Preconditions: every
  /// index < vertices.size(), coordinates finite, fewer than 2^32 triangles. Degenerate
  /// (collinear) triangles are allowed; queries never report them. O(n log n).
  /// `edge_planes` false leaves out the thin triangles' edge planes (the filters in front of the
  /// exact tests; the answers are the same either way, which the tests check by comparing).
  AabbTree(std::span<const Vec3> vertices, std::span<const std::array<std::uint32_t, 3>> triangles,
           bool edge_planes = true);

  std::size_t size() const { return triangle_ids_.size(); }
  bool empty() const { return triangle_ids_.empty(); }
  /// Box of all triangles, exact (empty box when the tree is empty).
  Box3 bounds() const { return bounds_; }
  /// Number of nodes and the depth (root alone = 1), for tests and statistics.
  std::size_t node_count() const { return nodes_.size(); }
  int depth() const;

  /// Appends to `out` every triangle the closed segment [a, b] meets (contact != none, not
  /// degenerate), in no particular order. `out` is not cleared.
  void intersect_segment(const Vec3& a, const Vec3& b, std::vector<TriangleIntersection>& out) const;

  /// Appends to `out` every triangle met by the ray {origin + t direction, t >= 0}; the ray is
  /// represented exactly as in kernel::intersect_ray_triangle (through ray_through_point), so
  /// all triangles see the same ray. Precondition: direction != 0.
  void intersect_ray(const Vec3& origin, const Vec3& direction,
                     std::vector<TriangleIntersection>& out) const;

  /// The closest point of all triangles to p; nullopt iff the tree is empty. Among triangles at
  /// equal distance, one of them. Best-first descent with pruning: O(log n) on typical input.
  /// With a finite `below_squared`, only a triangle at squared distance below it counts
  /// (nullopt when there is none): a bound from elsewhere that prunes from the start.
  std::optional<ClosestTriangle> closest_point(const Vec3& p,
                                               double below_squared = std::numeric_limits<double>::infinity()) const;

  /// Appends the ids of the triangles whose bounding boxes overlap `box` (closed boxes): a
  /// superset of the triangles that meet the box, exact for the box test itself.
  void triangles_in_box(const Box3& box, std::vector<std::uint32_t>& out) const;

  /// Calls f(a, b) once for every unordered pair of distinct triangles (ids, in no particular
  /// order) whose closed bounding boxes, each grown by `margin` on every side (a negative or NaN
  /// margin counts as 0), overlap -
  /// with margin 0 the same pairs as triangles_in_box with each triangle's box, found by one
  /// simultaneous descent of the tree against itself (each pair of overlapping nodes visited
  /// once) instead of a query per triangle. A positive margin also pairs triangles up to about
  /// 2 margin apart per axis (the growth is rounded to nearest: give it slack). O(n log n + k)
  /// for k pairs on typical input; a margin as large as the model pairs every two triangles.
  /// `group`, if not empty (one entry per triangle id), leaves out every pair of triangles of the
  /// same group (any value but kNoGroup), whole subtrees at a time: a caller that has settled a
  /// group's own pairs otherwise (a fan of d triangles around a vertex, flat or a cone's side:
  /// d²/2 pairs whose boxes all overlap) does not pay for enumerating them. A triangle of group
  /// kLeaveOut is paired with none (its caller searches all its pairs otherwise); other groups
  /// are below it.
  static constexpr std::uint32_t kNoGroup = 0xffffffffu;
  static constexpr std::uint32_t kLeaveOut = kNoGroup - 2;
  void for_each_overlapping_pair(const std::function<void(std::uint32_t, std::uint32_t)>& f, double margin = 0,
                                 std::span<const std::uint32_t> group = {}) const;

 private:
  /// A node's box in single precision, rounded outwards (so it contains the exact box): 32-byte
  /// nodes instead of 56 halve the memory a query walks through, which is what a query on a
  /// large tree mostly pays for (cache misses on the way down).
  struct Node {
    std::array<float, 6> bounds{};  ///< lo x, y, z then hi x, y, z
    /// Leaf: first triangle slot; inner node: index of the right child (left is this + 1).
    std::uint32_t first_or_right = 0;
    std::uint32_t count = 0;  ///< triangles in a leaf, 0 for an inner node
    Box3 box() const {
      Box3 b;
      b.lo = Vec3(bounds[0], bounds[1], bounds[2]);
      b.hi = Vec3(bounds[3], bounds[4], bounds[5]);
      return b;
    }
  };

  /// Centroids in single precision: they only steer the split (any split is correct), and
  /// 16-byte items halve the memory nth_element moves while building.
  struct BuildItem {
    std::array<float, 3> centroid;
    std::uint32_t id;
  };
  /// Builds the subtree over items[begin, end) at `depth` (root 0) and returns its exact box.
  Box3 build_node(LargeVector<BuildItem>& items, std::uint32_t begin, std::uint32_t end, int depth,
                  std::span<const Vec3> vertices, std::span<const std::array<std::uint32_t, 3>> triangles);
  /// Partitions items[begin, end) at the binned-SAH cut along `axis` (centroids in [lo, hi]) and
  /// returns the first item of the right part; begin when no SAH split applies.
  static std::uint32_t sah_split(LargeVector<BuildItem>& items, std::uint32_t begin, std::uint32_t end, int axis,
                                 float lo, float hi, int depth, std::span<const Vec3> vertices,
                                 std::span<const std::array<std::uint32_t, 3>> triangles);
  struct Plane;
  static Plane plane_filter(const std::array<Vec3, 3>& t);
  void intersect_line(const Vec3& a, const Vec3& b, bool is_ray, const Vec3& ray_direction,
                      std::vector<TriangleIntersection>& out) const;

  /// Up to four nodes of the binary tree side by side (a node's children, and where those are
  /// inner nodes the larger one's children in its place, in left-to-right order), their boxes in
  /// single precision by axis: segment and ray queries test four boxes at once and descend half
  /// as many levels (intersect_line). Unused lanes have NaN bounds, which no test passes.
  struct WideNode {
    std::array<float, 4> lo_x, lo_y, lo_z, hi_x, hi_y, hi_z;
    std::array<std::uint32_t, 4> child;  ///< a wide node's index (count 0) or a leaf's first slot
    std::array<std::uint32_t, 4> count;  ///< a leaf's triangles, 0 for an inner lane
  };
  /// Appends the wide node over binary node `node`'s children (or over `node` itself when it is
  /// a leaf, for a tree of one leaf) and, depth first, those below; returns its index.
  std::uint32_t build_wide(std::uint32_t node);

  LargeVector<Node> nodes_;
  LargeVector<WideNode> wide_;  ///< wide_[0] is the root's
  Box3 bounds_;
  /// A triangle's plane as a floating-point filter (plane_filter in the .cpp): normal, offset,
  /// and the error bound's factor and constant.
  struct Plane {
    Vec3 normal = Vec3::Zero();
    double offset = 0, error_factor = 0, error_constant = 0;
  };
  /// Planes through each edge of a thin triangle, across it, oriented so that the triangle lies
  /// on their positive side (edge_planes in the .cpp); an edge whose plane cannot be certified
  /// has an infinite error and rejects nothing.
  using EdgePlanes = std::array<Plane, 3>;
  static constexpr std::uint32_t kNoEdgePlanes = 0xffffffffu;
  static EdgePlanes edge_planes(const std::array<Vec3, 3>& t);
  /// Whether t's smallest height is below 1/16 of its longest edge (degenerate ones included).
  static bool thin(const std::array<Vec3, 3>& t);
  /// One triangle in leaf order: its corners and plane side by side, read together by a query,
  /// and for a thin triangle the index of its edge planes.
  struct Slot {
    std::array<Vec3, 3> corners;
    Plane plane;
    std::uint32_t edge_planes = kNoEdgePlanes;
  };
  LargeVector<Slot> slots_;
  /// Thin triangles' boxes are much larger than they are, and in a fan of them around a point
  /// most boxes near the point overlap: a segment or a point there meets hundreds of boxes of
  /// triangles it is far from. Their edge planes reject those cheaply (intersect_line,
  /// closest_point). Only for triangles whose smallest height is below 1/16 of their longest
  /// edge: on fatter ones the box is tight enough.
  LargeVector<EdgePlanes> edge_planes_;
  LargeVector<std::uint32_t> triangle_ids_;     // original id of each slot
};

}  // namespace delpsc::kernel
