#include "aabb_tree.h"

#include <algorithm>
#include <cmath>

namespace delpsc::kernel {

namespace {

constexpr double kEps = 0x1p-53;  // unit roundoff of double

Box3 triangle_box(const std::array<Vec3, 3>& t) {
  Box3 b;
  b.extend(t[0]);
  b.extend(t[1]);
  b.extend(t[2]);
  return b;
}

// Conservative test whether the line piece {a + t (b - a), t in [0, t_max]} meets the closed box.
// Slab method (Kay & Kajiya); the parameters t = (lo_i - a_i) / (b_i - a_i) are computed with
// three roundings (the two subtractions and the division), so each differs from the exact
// parameter by at most 3 eps |t| (1 + O(eps)). Widening every entry parameter by 8 eps |t|
// downwards and every exit parameter by 8 eps |t| upwards makes the computed interval contain the
// exact one: the test may accept a box the exact piece misses by a hair (harmless: the exact
// triangle test follows), never reject one it meets. Axes with b_i == a_i are decided exactly.
// (Cf. Ize, "Robust BVH ray traversal", JCGT 2(2), 2013, which widens by 2 gamma_3 the same way.)
bool segment_may_hit_box(const Vec3& a, const Vec3& d, double t_max, const Box3& box) {
  double t_lo = 0, t_hi = t_max;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0) {
      if (a[i] < box.lo[i] || a[i] > box.hi[i]) return false;
      continue;
    }
    double t0 = (box.lo[i] - a[i]) / d[i];
    double t1 = (box.hi[i] - a[i]) / d[i];
    if (t0 > t1) std::swap(t0, t1);
    t0 -= 8 * kEps * std::abs(t0);
    t1 += 8 * kEps * std::abs(t1);
    t_lo = std::max(t_lo, t0);
    t_hi = std::min(t_hi, t1);
    if (t_lo > t_hi) return false;
  }
  return true;
}

// Depth of a median-split tree is below 40 for any 32-bit triangle count; 64 is ample.
constexpr int kStackSize = 64;

}  // namespace

AabbTree::AabbTree(std::span<const Vec3> vertices,
                   std::span<const std::array<std::uint32_t, 3>> triangles) {
  const auto n = static_cast<std::uint32_t>(triangles.size());
  if (n == 0) return;
  std::vector<std::array<Vec3, 3>> corners(n);
  std::vector<Vec3> centroids(n);
  std::vector<std::uint32_t> order(n);
  for (std::uint32_t t = 0; t < n; ++t) {
    const auto& tri = triangles[t];
    corners[t] = {vertices[tri[0]], vertices[tri[1]], vertices[tri[2]]};
    centroids[t] = (corners[t][0] + corners[t][1] + corners[t][2]) / 3.0;
    order[t] = t;
  }
  nodes_.reserve(2 * (n / kLeafSize) + 2);
  build_node(order, centroids, 0, n, corners);
  // Store the triangles in leaf order so a leaf reads one contiguous block.
  corners_.resize(n);
  triangle_ids_ = order;
  for (std::uint32_t slot = 0; slot < n; ++slot) corners_[slot] = corners[order[slot]];
}

std::uint32_t AabbTree::build_node(std::vector<std::uint32_t>& order, std::vector<Vec3>& centroids,
                                   std::uint32_t begin, std::uint32_t end,
                                   std::span<const std::array<Vec3, 3>> corners) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back({});
  Box3 box, centroid_box;
  for (std::uint32_t k = begin; k < end; ++k) {
    box.extend(triangle_box(corners[order[k]]));
    centroid_box.extend(centroids[order[k]]);
  }
  nodes_[index].box = box;
  if (end - begin <= kLeafSize) {
    nodes_[index].first_or_right = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  // Median split on the longest axis of the centroids' box: balanced whatever the distribution
  // (an SAH split gives faster queries on very uneven meshes; the input meshes here are fairly
  // uniform and the balanced depth bound keeps the traversal stack fixed-size).
  int axis = 0;
  const Vec3 extent = centroid_box.hi - centroid_box.lo;
  if (extent.y() > extent[axis]) axis = 1;
  if (extent.z() > extent[axis]) axis = 2;
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                   [&](std::uint32_t p, std::uint32_t q) { return centroids[p][axis] < centroids[q][axis]; });
  build_node(order, centroids, begin, mid, corners);
  const std::uint32_t right = build_node(order, centroids, mid, end, corners);
  nodes_[index].first_or_right = right;
  nodes_[index].count = 0;
  return index;
}

int AabbTree::depth() const {
  if (nodes_.empty()) return 0;
  int best = 0;
  std::array<std::pair<std::uint32_t, int>, kStackSize> stack;
  int top = 0;
  stack[top++] = {0, 1};
  while (top > 0) {
    const auto [i, d] = stack[--top];
    best = std::max(best, d);
    if (nodes_[i].count == 0) {
      stack[top++] = {i + 1, d + 1};
      stack[top++] = {nodes_[i].first_or_right, d + 1};
    }
  }
  return best;
}

void AabbTree::intersect_line(const Vec3& a, const Vec3& b, bool is_ray, const Vec3& ray_direction,
                              std::vector<TriangleIntersection>& out) const {
  if (nodes_.empty()) return;
  const Vec3 d = b - a;
  const double t_max = is_ray ? std::numeric_limits<double>::infinity() : 1.0;
  std::array<std::uint32_t, kStackSize> stack;
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!segment_may_hit_box(a, d, t_max, node.box)) continue;
    if (node.count == 0) {
      const auto self = static_cast<std::uint32_t>(&node - nodes_.data());
      stack[top++] = node.first_or_right;
      stack[top++] = self + 1;
      continue;
    }
    for (std::uint32_t slot = node.first_or_right; slot < node.first_or_right + node.count; ++slot) {
      const auto& t = corners_[slot];
      const TriangleHit hit = is_ray ? intersect_ray_triangle(a, ray_direction, t[0], t[1], t[2])
                                     : intersect_segment_triangle(a, b, t[0], t[1], t[2]);
      if (hit) out.push_back({triangle_ids_[slot], hit});
    }
  }
}

void AabbTree::intersect_segment(const Vec3& a, const Vec3& b,
                                 std::vector<TriangleIntersection>& out) const {
  intersect_line(a, b, false, Vec3::Zero(), out);
}

void AabbTree::intersect_ray(const Vec3& origin, const Vec3& direction,
                             std::vector<TriangleIntersection>& out) const {
  // The triangle test sees the ray as the half-line from origin through q; the box test uses the
  // same two points (its widening covers the rounding of q - origin), so both agree on the ray.
  intersect_line(origin, ray_through_point(origin, direction), true, direction, out);
}

std::optional<ClosestTriangle> AabbTree::closest_point(const Vec3& p) const {
  if (nodes_.empty()) return std::nullopt;
  ClosestTriangle best;
  best.squared_distance = std::numeric_limits<double>::infinity();
  // Depth first, nearer child first, pruned by the box distance. Boxes are exact bounds of their
  // triangles, and the box distance is a lower bound up to rounding (a relative few eps), so a
  // pruned box could hide a triangle at most a few ulps closer than the best: harmless.
  std::array<std::pair<std::uint32_t, double>, kStackSize> stack;
  int top = 0;
  stack[top++] = {0, nodes_[0].box.squared_distance(p)};
  while (top > 0) {
    const auto [i, box_distance] = stack[--top];
    if (box_distance > best.squared_distance) continue;
    const Node& node = nodes_[i];
    if (node.count == 0) {
      const std::uint32_t left = i + 1, right = node.first_or_right;
      const double dl = nodes_[left].box.squared_distance(p);
      const double dr = nodes_[right].box.squared_distance(p);
      // Push the farther first so the nearer is explored first.
      if (dl <= dr) {
        stack[top++] = {right, dr};
        stack[top++] = {left, dl};
      } else {
        stack[top++] = {left, dl};
        stack[top++] = {right, dr};
      }
      continue;
    }
    for (std::uint32_t slot = node.first_or_right; slot < node.first_or_right + node.count; ++slot) {
      const auto& t = corners_[slot];
      const ClosestOnTriangle c = closest_point_on_triangle(p, t[0], t[1], t[2]);
      const double d2 = (c.point - p).squaredNorm();
      if (d2 < best.squared_distance) best = {triangle_ids_[slot], c.point, d2};
    }
  }
  return best;
}

void AabbTree::triangles_in_box(const Box3& box, std::vector<std::uint32_t>& out) const {
  if (nodes_.empty()) return;
  std::array<std::uint32_t, kStackSize> stack;
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const std::uint32_t i = stack[--top];
    const Node& node = nodes_[i];
    if (!node.box.overlaps(box)) continue;
    if (node.count == 0) {
      stack[top++] = node.first_or_right;
      stack[top++] = i + 1;
      continue;
    }
    for (std::uint32_t slot = node.first_or_right; slot < node.first_or_right + node.count; ++slot)
      if (triangle_box(corners_[slot]).overlaps(box)) out.push_back(triangle_ids_[slot]);
  }
}

}  // namespace delpsc::kernel
