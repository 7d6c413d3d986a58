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

// Conservative test whether the line piece {a + t d, t in [0, t_max]} meets the closed box.
// Slab method (Kay & Kajiya) with inv_d = 1 / d precomputed per query; the parameters
// t = (lo_i - a_i) * inv_d_i carry three roundings (d_i = b_i - a_i, its reciprocal, and the
// subtraction and product - the product and subtraction each one, the reciprocal of a rounded
// d_i one more), so each differs from the exact parameter (lo_i - a_i) / (b_i - a_i) by at most
// 4 eps |t| (1 + O(eps)). Widening every entry parameter by 8 eps |t| downwards and every exit
// parameter by 8 eps |t| upwards makes the computed interval contain the exact one: the test may
// accept a box the exact piece misses by a hair (harmless: the exact triangle test follows),
// never reject one it meets. Axes with d_i == 0 are decided exactly; a NaN from 0 * inf (d_i so
// small that its reciprocal overflows, a_i on the slab's plane) is ignored by max/min, which
// only widens the interval. (Cf. Ize, "Robust BVH ray traversal", JCGT 2(2), 2013, which widens
// by 2 gamma_3 the same way.)
bool segment_may_hit_box(const Vec3& a, const Vec3& d, const Vec3& inv_d, double t_max, const Box3& box) {
  double t_lo = 0, t_hi = t_max;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0) {
      if (a[i] < box.lo[i] || a[i] > box.hi[i]) return false;
      continue;
    }
    double t0 = (box.lo[i] - a[i]) * inv_d[i];
    double t1 = (box.hi[i] - a[i]) * inv_d[i];
    if (t0 > t1) std::swap(t0, t1);
    t0 -= 8 * kEps * std::abs(t0);
    t1 += 8 * kEps * std::abs(t1);
    t_lo = std::max(t_lo, t0);
    t_hi = std::min(t_hi, t1);
    if (t_lo > t_hi) return false;
  }
  return true;
}

// Single-precision bounds that contain [lo, hi]: each double rounded to a float, moved one float
// further out when the rounding went inwards.
void store_box(const Box3& b, std::array<float, 3>& lo, std::array<float, 3>& hi) {
  for (int i = 0; i < 3; ++i) {
    float l = static_cast<float>(b.lo[i]), h = static_cast<float>(b.hi[i]);
    if (static_cast<double>(l) > b.lo[i]) l = std::nextafter(l, -std::numeric_limits<float>::infinity());
    if (static_cast<double>(h) < b.hi[i]) h = std::nextafter(h, std::numeric_limits<float>::infinity());
    lo[i] = l;
    hi[i] = h;
  }
}

// Depth: at most kSahDepth SAH levels, then median splits (below 32 for any 32-bit triangle
// count): under 57, so 64 is ample.
constexpr int kStackSize = 64;
static_assert(AabbTree::kSahDepth + 33 <= kStackSize, "the traversal stack must hold the deepest tree");

}  // namespace

AabbTree::AabbTree(std::span<const Vec3> vertices,
                   std::span<const std::array<std::uint32_t, 3>> triangles) {
  const auto n = static_cast<std::uint32_t>(triangles.size());
  if (n == 0) return;
  std::vector<BuildItem> items(n);
  for (std::uint32_t t = 0; t < n; ++t) {
    const auto& tri = triangles[t];
    const Vec3 c = (vertices[tri[0]] + vertices[tri[1]] + vertices[tri[2]]) / 3.0;
    items[t] = {{static_cast<float>(c.x()), static_cast<float>(c.y()), static_cast<float>(c.z())}, t};
  }
  nodes_.reserve(2 * (n / kLeafSize) + 2);
  // Leaves copy their triangles' corners as they are made, so the corner array ends up in leaf
  // order and a leaf reads one contiguous block.
  corners_.reserve(n);
  triangle_ids_.reserve(n);
  bounds_ = build_node(items, 0, n, 0, vertices, triangles);
}

std::uint32_t AabbTree::sah_split(std::vector<BuildItem>& items, std::uint32_t begin, std::uint32_t end, int axis,
                                  float lo, float hi, int depth, std::span<const Vec3> vertices,
                                  std::span<const std::array<std::uint32_t, 3>> triangles) {
  if (depth >= kSahDepth || !(hi > lo)) return begin;
  const double scale = kSahBins / (double(hi) - double(lo));
  auto bin_of = [&](const BuildItem& item) {
    return std::min(kSahBins - 1, static_cast<int>((double(item.centroid[axis]) - double(lo)) * scale));
  };
  std::array<Box3, kSahBins> bin_box;
  std::array<std::uint32_t, kSahBins> bin_count{};
  for (std::uint32_t k = begin; k < end; ++k) {
    const int b = bin_of(items[k]);
    const auto& tri = triangles[items[k].id];
    for (const std::uint32_t v : tri) bin_box[b].extend(vertices[v]);
    ++bin_count[b];
  }
  // Cost of cutting after bin i: area(left) * n(left) + area(right) * n(right) (half areas).
  auto half_area = [](const Box3& b) {
    const Vec3 d = b.hi - b.lo;
    return d.x() * d.y() + d.y() * d.z() + d.z() * d.x();
  };
  std::array<double, kSahBins> left_cost{};
  Box3 acc;
  std::uint32_t n = 0;
  for (int i = 0; i + 1 < kSahBins; ++i) {
    acc.extend(bin_box[i]);
    n += bin_count[i];
    left_cost[i] = n == 0 ? -1 : half_area(acc) * n;
  }
  acc = Box3();
  n = 0;
  int best = -1;
  double best_cost = std::numeric_limits<double>::infinity();
  for (int i = kSahBins - 1; i > 0; --i) {
    acc.extend(bin_box[i]);
    n += bin_count[i];
    if (n == 0 || left_cost[i - 1] < 0) continue;
    const double cost = left_cost[i - 1] + half_area(acc) * n;
    if (cost < best_cost) best_cost = cost, best = i - 1;
  }
  if (best < 0) return begin;
  const auto cut = std::partition(items.begin() + begin, items.begin() + end,
                                  [&](const BuildItem& item) { return bin_of(item) <= best; });
  return static_cast<std::uint32_t>(cut - items.begin());
}

Box3 AabbTree::build_node(std::vector<BuildItem>& items, std::uint32_t begin, std::uint32_t end, int depth,
                          std::span<const Vec3> vertices, std::span<const std::array<std::uint32_t, 3>> triangles) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back({});
  if (end - begin <= kLeafSize) {
    Box3 box;
    nodes_[index].first_or_right = static_cast<std::uint32_t>(corners_.size());
    nodes_[index].count = end - begin;
    for (std::uint32_t k = begin; k < end; ++k) {
      const auto& tri = triangles[items[k].id];
      corners_.push_back({vertices[tri[0]], vertices[tri[1]], vertices[tri[2]]});
      triangle_ids_.push_back(items[k].id);
      box.extend(triangle_box(corners_.back()));
    }
    store_box(box, nodes_[index].lo, nodes_[index].hi);
    return box;
  }
  // Split on the longest axis of the centroids' box by the binned surface area heuristic (Wald,
  // "On fast construction of SAH-based bounding volume hierarchies", 2007): CAD meshes mix long
  // thin triangles with tiny ones, and the mesher's dual edges are long (a third of the diagonal
  // on average on fandisk), so a split that keeps boxes small pays on every query. Below
  // kSahDepth, or when every centroid falls in one bin, the median split: the depth stays below
  // kSahDepth + 32 < kStackSize whatever the input.
  std::array<float, 3> lo = items[begin].centroid, hi = lo;
  for (std::uint32_t k = begin + 1; k < end; ++k)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], items[k].centroid[i]);
      hi[i] = std::max(hi[i], items[k].centroid[i]);
    }
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (hi[i] - lo[i] > hi[axis] - lo[axis]) axis = i;
  std::uint32_t mid = sah_split(items, begin, end, axis, lo[axis], hi[axis], depth, vertices, triangles);
  if (mid == begin || mid == end) {
    mid = begin + (end - begin) / 2;
    std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
                     [axis](const BuildItem& p, const BuildItem& q) { return p.centroid[axis] < q.centroid[axis]; });
  }
  // Boxes bottom-up: O(1) per inner node instead of a pass over its triangles.
  Box3 box = build_node(items, begin, mid, depth + 1, vertices, triangles);
  const auto right = static_cast<std::uint32_t>(nodes_.size());
  box.extend(build_node(items, mid, end, depth + 1, vertices, triangles));
  store_box(box, nodes_[index].lo, nodes_[index].hi);
  nodes_[index].first_or_right = right;
  nodes_[index].count = 0;
  return box;
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
  const Vec3 inv_d = d.cwiseInverse();
  const double t_max = is_ray ? std::numeric_limits<double>::infinity() : 1.0;
  // The segment's own box first: six exact comparisons (a node's box contains its triangles', so
  // this never rejects a node the segment meets) spare most nodes the slab test's products,
  // widening and branches. The mesher's dual-edge queries, the main user: ~5% less meshing time.
  Box3 reach;
  if (is_ray) {
    reach.lo = Vec3::Constant(-std::numeric_limits<double>::infinity());
    reach.hi = Vec3::Constant(std::numeric_limits<double>::infinity());
  } else {
    reach.extend(a);
    reach.extend(b);
  }
  const auto may_hit = [&](std::uint32_t i) {
    const Box3 box = nodes_[i].box();
    return reach.overlaps(box) && segment_may_hit_box(a, d, inv_d, t_max, box);
  };
  if (!may_hit(0)) return;
  // A node is pushed only once its box passed: the children are tested at the parent, the left
  // one (the next node in memory) while the parent's line is still in cache.
  std::array<std::uint32_t, kStackSize> stack;
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (node.count == 0) {
      const auto self = static_cast<std::uint32_t>(&node - nodes_.data());
      if (may_hit(node.first_or_right)) stack[top++] = node.first_or_right;
      if (may_hit(self + 1)) stack[top++] = self + 1;
      continue;
    }
    for (std::uint32_t slot = node.first_or_right; slot < node.first_or_right + node.count; ++slot) {
      const auto& t = corners_[slot];
      // The triangle's own box first: a few flops that spare most exact tests in the leaf.
      if (!segment_may_hit_box(a, d, inv_d, t_max, triangle_box(t))) continue;
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
  // Depth first, nearer child first, pruned by the box distance. Boxes contain their triangles,
  // and the box distance is a lower bound up to rounding (a relative few eps), so a pruned box
  // could hide a triangle at most a few ulps closer than the best: harmless.
  std::array<std::pair<std::uint32_t, double>, kStackSize> stack;
  int top = 0;
  stack[top++] = {0, nodes_[0].box().squared_distance(p)};
  while (top > 0) {
    const auto [i, box_distance] = stack[--top];
    if (box_distance > best.squared_distance) continue;
    const Node& node = nodes_[i];
    if (node.count == 0) {
      const std::uint32_t left = i + 1, right = node.first_or_right;
      const double dl = nodes_[left].box().squared_distance(p);
      const double dr = nodes_[right].box().squared_distance(p);
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
    if (!node.box().overlaps(box)) continue;
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
