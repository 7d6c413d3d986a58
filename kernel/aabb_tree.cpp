#include "aabb_tree.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace delpsc::kernel {

namespace {

Box3 triangle_box(const std::array<Vec3, 3>& t) {
  Box3 b;
  b.extend(t[0]);
  b.extend(t[1]);
  b.extend(t[2]);
  return b;
}

// Conservative test whether the line piece {a + t d, t in [0, t_max]} (d = b - a) meets a closed
// box, given as {lo_x, lo_y, lo_z, hi_x, hi_y, hi_z}. Slab method (Kay & Kajiya) without branches:
// per query, the reciprocal r_i = fl(1 / fl(d_i)) is scaled once by (1 - 2^-49) for the entry
// parameter and by (1 + 2^-49) for the exit parameter, and the sign of d_i picks per axis which
// bound is entered first, so a box costs six subtractions, six products, min and max.
//
// Why it never rejects a box the exact piece meets. Take an axis with d_i != 0, near = the bound
// entered first, t = (near - a_i) / d_i exact. The computed factors carry five roundings,
// fl(b_i - a_i), the reciprocal, the scaling, fl(near - a_i) and the final product, each relative
// at most u = 2^-53 as long as nothing overflows or underflows (ensured by the guard in the
// constructor: 2^-1000 <= |d_i| <= 2^1000, |a_i| <= 2^1000 and the tree's coordinates at most
// 2^1000; other axes get NaN factors, which impose no constraint; a float node bound rounded out
// to +-inf gives a parameter of +-inf on the side where the box is unbounded). The product before its last rounding is thus
// t (1 - 2^-49) (1 + theta) with |theta| <= (1 + u)^3 / (1 - u) - 1 < 5u, of the sign of t and
// no larger in magnitude (16u > 5u + O(u^2)); likewise the exit product is at least the exact
// exit parameter in magnitude. Entry parameters below 0 and exit parameters above t_max do not
// matter (the interval starts at [0, t_max]), and a negative exit parameter is exactly
// negative, so: if the exact piece meets the box at some t* in [0, t_max], every unrounded
// entry product is <= t* <= every unrounded exit product, and rounding, being monotone
// (overflow included), keeps max(0, entries) <= fl(t*) <= min(t_max, exits). An axis with
// d_i == 0 (r_i = +-inf) contributes -inf or NaN entries and +inf or NaN exits when a_i is in the
// slab; max and min below drop NaN operands (std::max(x, NaN) == x), so such an axis imposes
// no constraint - the caller's test of the segment's own box decides it exactly. (Cf. Ize,
// "Robust BVH ray traversal", JCGT 2(2), 2013, which widens by 2 gamma_3 the same way.)
class SlabQuery {
 public:
  /// `tree_tame`: every coordinate of the tree's triangles is at most 2^1000 in magnitude.
  SlabQuery(const Vec3& a, const Vec3& b, double t_max, bool tree_tame) : t_max_(t_max) {
    for (int i = 0; i < 3; ++i) {
      a_[i] = a[i];
      const double d = b[i] - a[i];
      const double r = 1 / d;
      const double m = std::abs(d);
      const bool tame = tree_tame && std::abs(a[i]) <= 0x1p1000 && (m == 0 || (m >= 0x1p-1000 && m <= 0x1p1000));
      entry_scale_[i] = tame ? r * (1 - 0x1p-49) : std::numeric_limits<double>::quiet_NaN();
      exit_scale_[i] = tame ? r * (1 + 0x1p-49) : std::numeric_limits<double>::quiet_NaN();
      // The sign bit, not d < 0: d == -0 gives r == -inf, which needs the hi bound first.
      entry_[i] = std::signbit(d) ? i + 3 : i;
      exit_[i] = std::signbit(d) ? i : i + 3;
    }
  }

  template <class T>
  bool may_hit(const std::array<T, 6>& box) const {
    double t_lo = 0, t_hi = t_max_;
    for (int i = 0; i < 3; ++i) {
      t_lo = std::max(t_lo, (static_cast<double>(box[entry_[i]]) - a_[i]) * entry_scale_[i]);
      t_hi = std::min(t_hi, (static_cast<double>(box[exit_[i]]) - a_[i]) * exit_scale_[i]);
    }
    return t_lo <= t_hi;
  }

 private:
  std::array<double, 3> a_, entry_scale_, exit_scale_;
  std::array<int, 3> entry_, exit_;
  double t_max_;
};

// The next float below f, for f > -inf: one step of the bit pattern, away from zero for a
// negative f (std::nextafter is a library call).
float float_below(float f) {
  if (f == 0) return -std::numeric_limits<float>::denorm_min();
  const auto u = std::bit_cast<std::uint32_t>(f);
  return std::bit_cast<float>(f > 0 ? u - 1 : u + 1);
}
float float_above(float f) { return -float_below(-f); }

// Single-precision bounds that contain [lo, hi]: each double rounded to a float, moved one float
// further out when the rounding went inwards (never from -inf down or +inf up: those compare
// below or above every double).
void store_box(const Box3& b, std::array<float, 6>& bounds) {
  for (int i = 0; i < 3; ++i) {
    float l = static_cast<float>(b.lo[i]), h = static_cast<float>(b.hi[i]);
    if (static_cast<double>(l) > b.lo[i]) l = float_below(l);
    if (static_cast<double>(h) < b.hi[i]) h = float_above(h);
    bounds[i] = l;
    bounds[i + 3] = h;
  }
}

// Depth: at most kSahDepth SAH levels, then median splits (below 32 for any 32-bit triangle
// count): under 57, so 64 is ample.
constexpr int kStackSize = 64;
static_assert(AabbTree::kSahDepth + 33 <= kStackSize, "the traversal stack must hold the deepest tree");

}  // namespace

// A floating-point filter for "the segment stays strictly on one side of the triangle's plane",
// which spares most leaf triangles the box and exact tests. With u = q - p, v = r - p, the exact
// side of x is the sign of V(x) = (u x v) . (x - p); the filter evaluates s(x) = fl(n . x) - d
// with n = fl(u x v), d = fl(n . p). Each component of n is off by at most 8 eps U V (U, V the
// largest components of u, v: two products of rounded differences, then a subtraction), so
// |n - u x v|_1 <= 24 eps U V; the two dot products and the subtraction add at most
// 7 eps |n|_1 (|x| + |p|) (infinity norms). Hence |s(x) - V(x)| <= eps (7 |n|_1 + 24 U V)
// (|x| + |p|), and the filter uses 64 eps (|n|_1 + 4 U V) (|x| + |p|), over twice that, plus an
// absolute 2^-1000 for results near the subnormal range. When both ends have |s| above the bound
// and the same sign, V has that sign at both ends, so the segment misses the plane and the
// triangle. A degenerate triangle (V = 0 everywhere) never passes; a triangle with tiny or huge
// coordinates (U V outside [2^-900, 2^900]) gets an infinite bound, i.e. no filter; and the
// filter acts only when both values of s are finite, since an overflow in n . x or in the offset
// n . p (possible within those limits, e.g. |p| ~ 2^300 with U V ~ 2^900) leaves an infinity in
// s with a finite bound. Only the caller's exact test decides a hit.
AabbTree::Plane AabbTree::plane_filter(const std::array<Vec3, 3>& t) {
  Plane plane;
  const Vec3 u = t[1] - t[0], v = t[2] - t[0];
  plane.normal = u.cross(v);
  plane.offset = plane.normal.dot(t[0]);
  const double uv = u.cwiseAbs().maxCoeff() * v.cwiseAbs().maxCoeff();
  const double factor = 64 * 0x1p-53 * (plane.normal.cwiseAbs().sum() + 4 * uv);
  const bool tame = uv >= 0x1p-900 && uv <= 0x1p900 && t[0].cwiseAbs().maxCoeff() <= 0x1p300;
  plane.error_factor = tame ? factor : std::numeric_limits<double>::infinity();
  plane.error_constant = tame ? factor * t[0].cwiseAbs().maxCoeff() + 0x1p-1000 : std::numeric_limits<double>::infinity();
  return plane;
}

// A plane through each edge pq of t and the point r = p + |q - p| n / |n| off t along its normal
// n: the plane contains the line pq and not t's third corner s, so t lies in the closed half-space
// on s's side, and a segment with both ends certified strictly on the other side (plane_filter's
// bound, which holds for any three points) misses t. The plane is oriented so that s is on its
// positive side, where plane_filter's bound certifies it; an edge where that fails (t degenerate
// or r rounded onto p) gets an infinite bound and rejects nothing. Any r off the line would do:
// this one keeps the plane's normal well conditioned.
AabbTree::EdgePlanes AabbTree::edge_planes(const std::array<Vec3, 3>& t) {
  EdgePlanes planes;
  const Vec3 n = (t[1] - t[0]).cross(t[2] - t[0]);
  for (int k = 0; k < 3; ++k) {
    const Vec3 &p = t[(k + 1) % 3], &q = t[(k + 2) % 3], &s = t[k];
    Plane& plane = planes[k];
    plane = plane_filter({p, q, p + ((q - p).norm() / n.norm()) * n});
    const double value = plane.normal.dot(s) - plane.offset;
    const double error = plane.error_factor * s.cwiseAbs().maxCoeff() + plane.error_constant;
    if (!std::isfinite(value) || !(std::abs(value) > error)) {
      plane.error_factor = plane.error_constant = std::numeric_limits<double>::infinity();
    } else if (value < 0) {
      plane.normal = -plane.normal;  // exact, and the bound is the same
      plane.offset = -plane.offset;
    }
  }
  return planes;
}

bool AabbTree::thin(const std::array<Vec3, 3>& t) {
  // height = 2 area / longest edge < longest / 16, squared: |n|² 64 < longest⁴ (n = 2 area).
  const double longest = std::max({(t[1] - t[0]).squaredNorm(), (t[2] - t[1]).squaredNorm(), (t[0] - t[2]).squaredNorm()});
  return 64 * (t[1] - t[0]).cross(t[2] - t[0]).squaredNorm() < longest * longest;
}

AabbTree::AabbTree(std::span<const Vec3> vertices, std::span<const std::array<std::uint32_t, 3>> triangles,
                   bool with_edge_planes) {
  const auto n = static_cast<std::uint32_t>(triangles.size());
  if (n == 0) return;
  LargeVector<BuildItem> items(n);
  for (std::uint32_t t = 0; t < n; ++t) {
    const auto& tri = triangles[t];
    const Vec3 c = (vertices[tri[0]] + vertices[tri[1]] + vertices[tri[2]]) / 3.0;
    items[t] = {{static_cast<float>(c.x()), static_cast<float>(c.y()), static_cast<float>(c.z())}, t};
  }
  nodes_.reserve(2 * (n / kLeafSize) + 2);
  // Leaves copy their triangles' corners as they are made, so the corner array ends up in leaf
  // order and a leaf reads one contiguous block.
  slots_.reserve(n);
  triangle_ids_.reserve(n);
  bounds_ = build_node(items, 0, n, 0, vertices, triangles);
  for (Slot& slot : slots_) {
    slot.plane = plane_filter(slot.corners);
    if (with_edge_planes && thin(slot.corners)) {
      slot.edge_planes = static_cast<std::uint32_t>(edge_planes_.size());
      edge_planes_.push_back(edge_planes(slot.corners));
    }
  }
  wide_.reserve(nodes_.size() / 2 + 1);
  build_wide(0);
}

std::uint32_t AabbTree::build_wide(std::uint32_t node) {
  std::array<std::uint32_t, 4> lanes{};
  int k = 0;
  if (nodes_[node].count > 0) {
    lanes[k++] = node;
  } else {
    lanes[k++] = node + 1;
    lanes[k++] = nodes_[node].first_or_right;
  }
  // Open the inner lane of largest box (half area) until four lanes: its children take its place,
  // so the lanes stay in the binary tree's left-to-right order.
  const auto half_area = [](const std::array<float, 6>& b) {
    const double dx = double(b[3]) - b[0], dy = double(b[4]) - b[1], dz = double(b[5]) - b[2];
    return dx * dy + dy * dz + dz * dx;
  };
  while (k < 4) {
    int best = -1;
    double best_area = -1;
    for (int i = 0; i < k; ++i)
      if (nodes_[lanes[i]].count == 0 && half_area(nodes_[lanes[i]].bounds) > best_area)
        best = i, best_area = half_area(nodes_[lanes[i]].bounds);
    if (best < 0) break;
    const std::uint32_t opened = lanes[best];
    for (int i = k; i > best + 1; --i) lanes[i] = lanes[i - 1];
    lanes[best] = opened + 1;
    lanes[best + 1] = nodes_[opened].first_or_right;
    ++k;
  }
  const auto index = static_cast<std::uint32_t>(wide_.size());
  WideNode wide;
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  for (auto* axis : {&wide.lo_x, &wide.lo_y, &wide.lo_z, &wide.hi_x, &wide.hi_y, &wide.hi_z}) axis->fill(kNaN);
  wide.child.fill(0);
  wide.count.fill(0);
  for (int i = 0; i < k; ++i) {
    const Node& n = nodes_[lanes[i]];
    wide.lo_x[i] = n.bounds[0], wide.lo_y[i] = n.bounds[1], wide.lo_z[i] = n.bounds[2];
    wide.hi_x[i] = n.bounds[3], wide.hi_y[i] = n.bounds[4], wide.hi_z[i] = n.bounds[5];
    wide.child[i] = n.first_or_right;
    wide.count[i] = n.count;
  }
  wide_.push_back(wide);
  for (int i = 0; i < k; ++i)
    if (nodes_[lanes[i]].count == 0) {
      const std::uint32_t child = build_wide(lanes[i]);
      wide_[index].child[i] = child;
    }
  return index;
}

std::uint32_t AabbTree::sah_split(LargeVector<BuildItem>& items, std::uint32_t begin, std::uint32_t end, int axis,
                                  float lo, float hi, int depth, std::span<const Vec3> vertices,
                                  std::span<const std::array<std::uint32_t, 3>> triangles) {
  // Centroids beyond the float range are infinite: no SAH cut then (a median split follows),
  // rather than bins indexed by a converted NaN or infinity.
  if (depth >= kSahDepth || !(hi > lo) || !std::isfinite(hi) || !std::isfinite(lo)) return begin;
  const double scale = kSahBins / (double(hi) - double(lo));
  auto bin_of = [&](const BuildItem& item) {
    const double x = (double(item.centroid[axis]) - double(lo)) * scale;  // in [0, kSahBins]
    return x < kSahBins - 1 ? static_cast<int>(x) : kSahBins - 1;
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

Box3 AabbTree::build_node(LargeVector<BuildItem>& items, std::uint32_t begin, std::uint32_t end, int depth,
                          std::span<const Vec3> vertices, std::span<const std::array<std::uint32_t, 3>> triangles) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back({});
  if (end - begin <= kLeafSize) {
    Box3 box;
    nodes_[index].first_or_right = static_cast<std::uint32_t>(slots_.size());
    nodes_[index].count = end - begin;
    for (std::uint32_t k = begin; k < end; ++k) {
      const auto& tri = triangles[items[k].id];
      slots_.push_back({{vertices[tri[0]], vertices[tri[1]], vertices[tri[2]]}, {}});
      triangle_ids_.push_back(items[k].id);
      box.extend(triangle_box(slots_.back().corners));
    }
    store_box(box, nodes_[index].bounds);
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
  store_box(box, nodes_[index].bounds);
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
  const SlabQuery slab(a, b, is_ray ? std::numeric_limits<double>::infinity() : 1.0,
                       bounds_.lo.cwiseAbs().maxCoeff() <= 0x1p1000 && bounds_.hi.cwiseAbs().maxCoeff() <= 0x1p1000);
  // The piece's own box first: six exact comparisons (a node's box contains its triangles', so
  // this never rejects a node the piece meets) that spare most nodes the slab test, and decide
  // the axes along which the piece does not move. A ray's box is unbounded only on the side its
  // direction points to (the sign of b_i - a_i is exact).
  Box3 reach;
  for (int i = 0; i < 3; ++i) {
    const double inf = std::numeric_limits<double>::infinity();
    reach.lo[i] = is_ray ? (b[i] < a[i] ? -inf : a[i]) : std::min(a[i], b[i]);
    reach.hi[i] = is_ray ? (b[i] > a[i] ? inf : a[i]) : std::max(a[i], b[i]);
  }
  const double a_size = a.cwiseAbs().maxCoeff(), b_size = b.cwiseAbs().maxCoeff();  // for plane_filter
  // The reach in single precision, compared with the nodes' float bounds float to float (six
  // float comparisons a node instead of six conversions to double first). Rounding to nearest
  // is enough here: it is monotone, and a node's bounds are rounded outwards, so where the exact
  // boxes overlap, node lo <= reach hi gives float(node lo) <= nearest(node lo) <= nearest(reach
  // hi), and likewise on the other side; no node the piece meets is rejected.
  std::array<float, 6> reach_f;
  for (int i = 0; i < 3; ++i) {
    reach_f[i] = static_cast<float>(reach.lo[i]);
    reach_f[i + 3] = static_cast<float>(reach.hi[i]);
  }
  // Four lanes at a time: the six float comparisons of each lane's box with the reach, lane by
  // lane in one vector; then the slab test for the lanes that pass. (Skipping the slab test at
  // inner nodes for short pieces saved 1-3% of meshing's instructions on the small trees of the
  // CGAL demo models, but on a tree of 10^6 triangles out of cache each extra node visited is a
  // cache miss: short queries 40% slower, BENCHMARKS.md, session 22.)
  using Floats = float __attribute__((vector_size(16)));
  const auto load = [](const std::array<float, 4>& v) {
    Floats f;
    std::memcpy(&f, v.data(), sizeof f);
    return f;
  };
  const auto splat = [](float x) { return Floats{x, x, x, x}; };
  const Floats rlx = splat(reach_f[0]), rly = splat(reach_f[1]), rlz = splat(reach_f[2]);
  const Floats rhx = splat(reach_f[3]), rhy = splat(reach_f[4]), rhz = splat(reach_f[5]);
  // Depth first, lanes left to right (pushed in reverse): the leaves come in the binary tree's
  // order, so the hits do too. Each wide node popped pushes at most four entries, and the wide
  // tree is no deeper than the binary one (below kStackSize): 3 kStackSize + 1 entries suffice.
  struct Entry {
    std::uint32_t index, count;  // count 0: a wide node; else a leaf's first slot and triangles
  };
  std::array<Entry, 4 * kStackSize> stack;
  int top = 0;
  stack[top++] = {0, 0};
  while (top > 0) {
    const Entry entry = stack[--top];
    if (entry.count == 0) {
      const WideNode& w = wide_[entry.index];
      const auto pass = (load(w.lo_x) <= rhx) & (rlx <= load(w.hi_x)) & (load(w.lo_y) <= rhy) &
                        (rly <= load(w.hi_y)) & (load(w.lo_z) <= rhz) & (rlz <= load(w.hi_z));
      int lanes[4], passed = 0;
      for (int i = 0; i < 4; ++i) {
        if (pass[i] == 0) continue;
        if (!slab.may_hit(std::array<float, 6>{w.lo_x[i], w.lo_y[i], w.lo_z[i], w.hi_x[i], w.hi_y[i], w.hi_z[i]}))
          continue;
        lanes[passed++] = i;
      }
      for (int j = passed - 1; j >= 0; --j) stack[top++] = {w.child[lanes[j]], w.count[lanes[j]]};
      continue;
    }
    for (std::uint32_t slot = entry.index; slot < entry.index + entry.count; ++slot) {
      if (!is_ray) {
        // Both ends strictly on one side of the plane: no hit (plane_filter). Cheaper than the
        // box, and it rejects what boxes cannot: big triangles whose box holds the segment.
        const Plane& plane = slots_[slot].plane;
        const double sa = plane.normal.dot(a) - plane.offset, sb = plane.normal.dot(b) - plane.offset;
        const double ea = plane.error_factor * a_size + plane.error_constant;
        const double eb = plane.error_factor * b_size + plane.error_constant;
        // Finite values only: an overflow anywhere (n . x, or the offset n . p) leaves an
        // infinity or NaN in s, outside the error analysis.
        if (std::isfinite(sa) && std::isfinite(sb) && ((sa > ea && sb > eb) || (sa < -ea && sb < -eb))) continue;
      }
      const auto& t = slots_[slot].corners;
      // The triangle's own box first: a few flops that spare most exact tests in the leaf.
      const Box3 box = triangle_box(t);
      if (!slab.may_hit(std::array<double, 6>{box.lo.x(), box.lo.y(), box.lo.z(), box.hi.x(), box.hi.y(), box.hi.z()}))
        continue;
      // A thin triangle's box says little: both ends beyond one of its edge planes (edge_planes).
      if (!is_ray && slots_[slot].edge_planes != kNoEdgePlanes) {
        const auto beyond = [&](const Plane& e) {
          const double sa = e.normal.dot(a) - e.offset, sb = e.normal.dot(b) - e.offset;
          return std::isfinite(sa) && std::isfinite(sb) && sa < -(e.error_factor * a_size + e.error_constant) &&
                 sb < -(e.error_factor * b_size + e.error_constant);
        };
        const EdgePlanes& edges = edge_planes_[slots_[slot].edge_planes];
        if (beyond(edges[0]) || beyond(edges[1]) || beyond(edges[2])) continue;
      }
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

std::optional<ClosestTriangle> AabbTree::closest_point(const Vec3& p, double below_squared) const {
  if (nodes_.empty()) return std::nullopt;
  ClosestTriangle best;
  // A caller's bound prunes like a best already found; only a triangle nearer replaces it.
  best.squared_distance = below_squared;
  bool found = false;
  const double p_size = p.cwiseAbs().maxCoeff();  // for the edge planes' bound
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
      const auto& t = slots_[slot].corners;
      // A thin triangle beyond one of its edge planes by more than the best distance cannot be
      // closer: the plane separates p from it. The separation is certified (plane_filter's bound
      // taken off: the exact plane's value is at least -v - error) and the factor covers the
      // rounding of |n| and of the distances compared, so a skipped triangle would not have
      // replaced the best: the answer is the one without the skip, ties included.
      if (slots_[slot].edge_planes != kNoEdgePlanes && best.squared_distance < HUGE_VAL) {
        // Both squares kept in the normal range (an edge of ~1e-77 has |n|² below it, whose
        // rounding the factor would not cover).
        const auto farther = [&](const Plane& e) {
          const double margin = -(e.normal.dot(p) - e.offset) - (e.error_factor * p_size + e.error_constant);
          const double n2 = e.normal.squaredNorm();
          return margin >= 0x1p-450 && n2 >= 0x1p-900 && margin * margin > best.squared_distance * n2 * (1 + 0x1p-20);
        };
        const EdgePlanes& edges = edge_planes_[slots_[slot].edge_planes];
        if (farther(edges[0]) || farther(edges[1]) || farther(edges[2])) continue;
      }
      const ClosestOnTriangle c = closest_point_on_triangle(p, t[0], t[1], t[2]);
      const double d2 = (c.point - p).squaredNorm();
      if (d2 < best.squared_distance) {
        best = {triangle_ids_[slot], c.point, d2};
        found = true;
      }
    }
  }
  // Without a bound a non-empty tree always answers, even when every distance overflowed or p
  // is NaN (the triangle then is 0, the distance infinite): callers over segments rely on it.
  if (!found && below_squared < std::numeric_limits<double>::infinity()) return std::nullopt;
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
      if (triangle_box(slots_[slot].corners).overlaps(box)) out.push_back(triangle_ids_[slot]);
  }
}

void AabbTree::for_each_overlapping_pair(const std::function<void(std::uint32_t, std::uint32_t)>& f,
                                         double margin, std::span<const std::uint32_t> group) const {
  if (nodes_.empty()) return;
  // Each node's group when all its triangles share one (kNoGroup or kMixed otherwise), children
  // before parents: a child's index is above its parent's.
  constexpr std::uint32_t kMixed = kNoGroup - 1;
  const bool grouped = !group.empty();
  if (grouped && group.size() < triangle_ids_.size())
    throw std::invalid_argument("AabbTree::for_each_overlapping_pair: fewer groups than triangles");
  std::vector<std::uint32_t> node_group(grouped ? nodes_.size() : 0);
  for (std::size_t i = node_group.size(); i-- > 0;) {
    const Node& n = nodes_[i];
    std::uint32_t g;
    if (n.count > 0) {
      g = group[triangle_ids_[n.first_or_right]];
      for (std::uint32_t s = 1; s < n.count; ++s)
        if (group[triangle_ids_[n.first_or_right + s]] != g) g = kMixed;
    } else {
      g = node_group[i + 1] == node_group[n.first_or_right] ? node_group[i + 1] : kMixed;
    }
    node_group[i] = g;
  }
  const auto one_group = [&](std::uint32_t i, std::uint32_t j) {
    return grouped && ((node_group[i] < kMixed && node_group[i] == node_group[j]) || node_group[i] == kLeaveOut ||
                       node_group[j] == kLeaveOut);
  };
  const auto report = [&](std::uint32_t a, std::uint32_t b) {
    if (!grouped || ((group[a] == kNoGroup || group[a] != group[b]) && group[a] != kLeaveOut && group[b] != kLeaveOut))
      f(a, b);
  };
  // A negative or NaN margin would shrink or void every box and drop pairs that overlap.
  if (!(margin > 0)) margin = 0;
  // Two boxes each grown by the margin overlap iff one overlaps the other grown by twice it.
  const Vec3 grow = Vec3::Constant(margin), grow2 = Vec3::Constant(2 * margin);
  const auto node_box = [&](std::uint32_t i) {
    Box3 b = nodes_[i].box();
    b.lo -= grow2;
    b.hi += grow2;
    return b;
  };
  const auto is_leaf = [&](std::uint32_t i) { return nodes_[i].count > 0; };
  const auto children = [&](std::uint32_t i) { return std::array<std::uint32_t, 2>{i + 1, nodes_[i].first_or_right}; };
  // Pairs of nodes whose boxes overlap (a node paired with itself stands for the pairs inside it).
  std::vector<std::array<std::uint32_t, 2>> stack = {{0, 0}};
  // Each triangle's box once, in slot order: a leaf meets ~10 others, and recomputing its boxes
  // from the corners at each meeting was a seventh of the check on a million triangles.
  std::vector<Box3> slot_box(slots_.size());
  for (std::size_t s = 0; s < slots_.size(); ++s) {
    slot_box[s] = triangle_box(slots_[s].corners);
    slot_box[s].lo -= grow;
    slot_box[s].hi += grow;
  }
  const Box3* const boxes_of = slot_box.data();
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    if (one_group(i, j)) continue;
    const Node &a = nodes_[i], &b = nodes_[j];
    if (i == j) {
      if (is_leaf(i)) {
        const Box3* boxes = boxes_of + a.first_or_right;
        for (std::uint32_t s = 0; s < a.count; ++s)
          for (std::uint32_t t = s + 1; t < a.count; ++t)
            if (boxes[s].overlaps(boxes[t])) report(triangle_ids_[a.first_or_right + s], triangle_ids_[a.first_or_right + t]);
        continue;
      }
      const auto [l, r] = children(i);
      stack.push_back({l, l});
      stack.push_back({r, r});
      if (nodes_[l].box().overlaps(node_box(r))) stack.push_back({l, r});
      continue;
    }
    if (is_leaf(i) && is_leaf(j)) {
      const Box3* boxes_a = boxes_of + a.first_or_right;
      const Box3* boxes_b = boxes_of + b.first_or_right;
      for (std::uint32_t s = 0; s < a.count; ++s)
        for (std::uint32_t t = 0; t < b.count; ++t)
          if (boxes_a[s].overlaps(boxes_b[t])) report(triangle_ids_[a.first_or_right + s], triangle_ids_[b.first_or_right + t]);
      continue;
    }
    // Descend the inner node (the larger one when both are): its children against the other.
    const bool split_a = is_leaf(j) || (!is_leaf(i) && a.box().diagonal() >= b.box().diagonal());
    const std::uint32_t split = split_a ? i : j, other = split_a ? j : i;
    const Box3 other_box = node_box(other);
    for (const std::uint32_t c : children(split))
      if (nodes_[c].box().overlaps(other_box)) stack.push_back({c, other});
  }
}

}  // namespace delpsc::kernel
