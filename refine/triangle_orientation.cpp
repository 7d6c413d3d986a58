#include "triangle_orientation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include <delpsc/kernel/aabb_tree.h>
#include <delpsc/kernel/large_array.h>

namespace delpsc::refine {

namespace {

/// A closed orientable component: its triangles closed_triangles[first, end), its box, and a
/// point on it (a triangle's centroid: two components may share a vertex, never a triangle's
/// interior, so the point lies off every other component).
struct ClosedComponent {
  std::size_t first = 0, end = 0;
  kernel::Box3 box;
  Vec3 probe = Vec3::Zero();
};

/// The winding number of the closed triangle set `ts` (outward) around p: the sum of the solid
/// angles its triangles subtend at p over 4π (Van Oosterom and Strackee's formula), near 1
/// inside and 0 outside. p lies off the set. O(|ts|).
double winding_number(const Vec3& p, std::span<const Vec3> vertices, std::span<const std::array<std::uint32_t, 3>> triangles,
                      std::span<const std::uint32_t> ts) {
  double sum = 0;
  for (const std::uint32_t t : ts) {
    const Vec3 a = vertices[triangles[t][0]] - p, b = vertices[triangles[t][1]] - p, c = vertices[triangles[t][2]] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double det = a.dot(b.cross(c));
    const double den = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    sum += 2 * std::atan2(det, den);
  }
  return sum / (4 * std::numbers::pi);
}

/// Each closed component was turned to a positive volume, outward as if it bounded a solid of
/// its own. One inside an odd number of others bounds a cavity of the solid they make (a
/// hollow ball's inner sphere), whose outside is the cavity: it is turned to face into it. The
/// components meet at most at vertices, so whether one lies inside another is the winding number
/// of a point inside one of its triangles; only the components whose box holds that point are
/// asked. Cost: the triangles of every component whose box holds another's point, once per such
/// point (quadratic only for many components inside one large one, left as is).
void turn_cavities(std::span<const Vec3> vertices, std::span<std::array<std::uint32_t, 3>> triangles,
                   const std::vector<ClosedComponent>& components, const kernel::LargeVector<std::uint32_t>& members) {
  if (components.size() < 2) return;
  std::vector<std::uint8_t> reverse(components.size(), 0);
  for (std::size_t i = 0; i < components.size(); ++i) {
    int depth = 0;
    for (std::size_t j = 0; j < components.size(); ++j) {
      if (j == i || !components[j].box.contains(components[i].probe)) continue;
      const std::span<const std::uint32_t> ts(members.data() + components[j].first, components[j].end - components[j].first);
      depth += std::abs(winding_number(components[i].probe, vertices, triangles, ts)) > 0.5;
    }
    reverse[i] = static_cast<std::uint8_t>(depth % 2);
  }
  for (std::size_t i = 0; i < components.size(); ++i)
    if (reverse[i])
      for (std::size_t k = components[i].first; k < components[i].end; ++k)
        std::swap(triangles[members[k]][1], triangles[members[k]][2]);
}

}  // namespace

std::size_t orient_triangles(std::span<const Vec3> vertices, std::span<std::array<std::uint32_t, 3>> triangles,
                             const std::function<int(std::uint32_t)>& prefer) {
  const std::size_t n = triangles.size();
  constexpr std::uint32_t kNone = 0xffffffffu;
  // Each vertex's triangles (flat, by vertex), each with the two other vertices in the
  // triangle's cyclic order after this one and this one's place in the triangle.
  struct Around {
    std::uint32_t triangle, next, after;  // (v, next, after) is the triangle's cyclic order
    std::uint32_t place;                  // v == triangles[triangle][place]
  };
  kernel::LargeVector<std::uint32_t> first(vertices.size() + 1, 0);
  for (const auto& t : triangles)
    for (const std::uint32_t v : t) ++first[v + 1];
  for (std::size_t v = 0; v < vertices.size(); ++v) first[v + 1] += first[v];
  kernel::LargeVector<Around> around(3 * n);
  {
    kernel::LargeVector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::uint32_t t = 0; t < n; ++t)
      for (std::uint32_t k = 0; k < 3; ++k)
        around[fill[triangles[t][k]]++] = {t, triangles[t][(k + 1) % 3], triangles[t][(k + 2) % 3], k};
  }
  // Across edge k of t (from vertex k to k + 1): the other triangle if exactly two use the edge,
  // and whether the two traverse it in opposite directions (consistently oriented as given).
  // `open` marks triangles with an edge that is not used by exactly two triangles. Each edge
  // {a, x} is settled once, at its smaller end a, from a's list alone: its users there, grouped
  // by x (the search of a's list per edge and triangle side it replaces was 5.8% of meshing the
  // cube at 0.5%).
  kernel::LargeVector<std::array<std::uint32_t, 3>> next(n, {kNone, kNone, kNone});
  kernel::LargeVector<std::uint8_t> opposite(n, 0);  // bit k: across edge k, opposite directions
  kernel::LargeVector<char> open(n, 0);
  struct Use {
    std::uint32_t other_end, triangle;
    std::uint8_t edge;      // the edge's index in the triangle
    bool outgoing;          // the triangle goes from a to other_end
  };
  std::vector<Use> uses;
  for (std::uint32_t a = 0; a < vertices.size(); ++a) {
    uses.clear();
    for (std::uint32_t i = first[a]; i < first[a + 1]; ++i) {
      const Around& x = around[i];
      if (x.next > a) uses.push_back({x.next, x.triangle, static_cast<std::uint8_t>(x.place), true});
      if (x.after > a) uses.push_back({x.after, x.triangle, static_cast<std::uint8_t>((x.place + 2) % 3), false});
    }
    std::sort(uses.begin(), uses.end(), [](const Use& p, const Use& q) { return p.other_end < q.other_end; });
    for (std::size_t i = 0; i < uses.size();) {
      std::size_t j = i + 1;
      while (j < uses.size() && uses[j].other_end == uses[i].other_end) ++j;
      if (j - i == 2) {
        const Use &u = uses[i], &w = uses[i + 1];
        next[u.triangle][u.edge] = w.triangle;
        next[w.triangle][w.edge] = u.triangle;
        if (u.outgoing != w.outgoing) {
          opposite[u.triangle] |= static_cast<std::uint8_t>(1u << u.edge);
          opposite[w.triangle] |= static_cast<std::uint8_t>(1u << w.edge);
        }
      } else {
        for (std::size_t k = i; k < j; ++k) open[uses[k].triangle] = 1;
      }
      i = j;
    }
  }
  // Breadth-first search per component, deciding which triangles to flip: u keeps t's decision
  // when they already agree across their edge, and takes the other one when they do not.
  kernel::LargeVector<std::int8_t> flip(n, -1);  // -1: not reached yet
  std::size_t bad = 0;
  kernel::LargeVector<std::uint32_t> component, queue;
  // The closed orientable components, turned outward one by one below; a second pass turns
  // those nested inside an odd number of others (cavities) to face into them.
  std::vector<ClosedComponent> closed_components;
  kernel::LargeVector<std::uint32_t> closed_triangles;
  for (std::uint32_t start = 0; start < n; ++start) {
    if (flip[start] >= 0) continue;
    component.clear();
    queue.assign(1, start);
    flip[start] = 0;
    bool closed = true, orientable = true;
    while (!queue.empty()) {
      const std::uint32_t t = queue.back();
      queue.pop_back();
      component.push_back(t);
      closed &= !open[t];
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t u = next[t][k];
        if (u == kNone) continue;
        const auto wanted = static_cast<std::int8_t>((opposite[t] >> k & 1u) ? flip[t] : 1 - flip[t]);
        if (flip[u] < 0) {
          flip[u] = wanted;
          queue.push_back(u);
        } else if (flip[u] != wanted) {
          orientable = false;
        }
      }
    }
    if (!orientable) ++bad;
    for (const std::uint32_t t : component)
      if (flip[t] == 1) std::swap(triangles[t][1], triangles[t][2]);
    bool reverse = false;
    if (closed && orientable) {
      double volume = 0;
      for (const std::uint32_t t : component) {
        const Vec3& p = vertices[triangles[t][0]];
        volume += p.dot(vertices[triangles[t][1]].cross(vertices[triangles[t][2]]));
      }
      reverse = volume < 0;
    } else if (orientable && prefer) {
      // Votes from triangles spread over the component (the search's order is spatially coherent).
      const std::size_t step = std::max<std::size_t>(1, component.size() / kOrientationVotes);
      long votes = 0;
      for (std::size_t i = 0; i < component.size(); i += step) {
        const int vote = prefer(component[i]);
        votes += vote > 0 ? 1 : vote < 0 ? -1 : 0;
      }
      reverse = votes < 0;
    }
    if (reverse)
      for (const std::uint32_t t : component) std::swap(triangles[t][1], triangles[t][2]);
    if (closed && orientable) {
      ClosedComponent c;
      c.first = closed_triangles.size();
      closed_triangles.insert(closed_triangles.end(), component.begin(), component.end());
      c.end = closed_triangles.size();
      for (const std::uint32_t t : component)
        for (const std::uint32_t v : triangles[t]) c.box.extend(vertices[v]);
      const auto& seed = triangles[component.front()];
      c.probe = (vertices[seed[0]] + vertices[seed[1]] + vertices[seed[2]]) / 3;
      closed_components.push_back(c);
    }
  }
  turn_cavities(vertices, triangles, closed_components, closed_triangles);
  return bad;
}

}  // namespace delpsc::refine
