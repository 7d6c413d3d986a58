// Step 7 of build_complex: the fans of a patch at each vertex where it is pinched, so that the
// mesher can ask of Umb_σ(p) at that corner one disk per fan instead of one disk (D1/D2 of
// DelPSC, §3, read per fan: the patch there is a 2-manifold with boundary whose boundary points
// at the pinch are identified, and each fan is a wedge of it).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "complex_build.h"

namespace delpsc::protect {

std::span<const std::array<std::uint32_t, 2>> Complex::corner_pinch_fans(std::uint32_t k, std::uint32_t patch) const {
  if (pinches.empty() || k >= corner_vertex.size()) return {};
  const std::array<std::uint32_t, 2> key{corner_vertex[k], patch};
  const auto it = std::lower_bound(pinches.begin(), pinches.end(), key);
  if (it == pinches.end() || *it != key) return {};
  const auto i = static_cast<std::size_t>(it - pinches.begin());
  return {pinch_fans.data() + pinch_fan_offsets[i], pinch_fans.data() + pinch_fan_offsets[i + 1]};
}

namespace detail {

namespace {

// The angle at v between edges e and f, in degrees (rounded arithmetic: a threshold, not a
// combinatorial decision).
double wedge_degrees(const Complex& complex, std::uint32_t v, std::uint32_t e, std::uint32_t f) {
  const auto away = [&](std::uint32_t edge) {
    const std::uint32_t w = complex.edges[edge][0] == v ? complex.edges[edge][1] : complex.edges[edge][0];
    return Vec3(complex.vertices[w] - complex.vertices[v]);
  };
  const Vec3 a = away(e), b = away(f);
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / std::numbers::pi;
}

}  // namespace

void describe_pinch_fans(Complex& complex) {
  complex.pinch_fan_offsets.assign(1, 0);
  complex.pinch_fans.clear();
  complex.unsupported_pinches.clear();
  if (complex.pinches.empty()) return;
  // The triangles of each pinch's patch at its vertex: (pinch, triangle), grouped by pinch.
  kernel::LargeVector<std::uint8_t> pinched(complex.vertices.size(), 0);
  for (const auto& [v, patch] : complex.pinches) pinched[v] = 1;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> members;
  for (std::uint32_t t = 0; t < complex.triangles.size(); ++t)
    for (const std::uint32_t v : complex.triangles[t]) {
      if (!pinched[v]) continue;
      const std::array<std::uint32_t, 2> key{v, complex.triangle_patch[t]};
      const auto it = std::lower_bound(complex.pinches.begin(), complex.pinches.end(), key);
      if (it != complex.pinches.end() && *it == key)
        members.emplace_back(static_cast<std::uint32_t>(it - complex.pinches.begin()), t);
    }
  std::sort(members.begin(), members.end());
  std::vector<std::pair<std::uint32_t, std::uint32_t>> sides;  // (edge at the vertex, local triangle)
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ends;   // (fan root, boundary edge)
  std::vector<std::uint32_t> roots;                             // the fans along one edge
  for (std::size_t i = 0, first = 0; i < complex.pinches.size(); ++i) {
    std::size_t end = first;
    while (end < members.size() && members[end].first == i) ++end;
    const std::uint32_t v = complex.pinches[i][0];
    // Fans: the triangles joined through their edges at v (any edge: a slit's two sides and a
    // crease inside the patch are one fan, as in find_pinches).
    sides.clear();
    for (std::size_t m = first; m < end; ++m)
      for (const std::uint32_t e : complex.triangle_edges[members[m].second])
        if (complex.edges[e][0] == v || complex.edges[e][1] == v) sides.emplace_back(e, static_cast<std::uint32_t>(m - first));
    std::sort(sides.begin(), sides.end());
    UnionFind fans(end - first);
    for (std::size_t s = 1; s < sides.size(); ++s)
      if (sides[s].first == sides[s - 1].first) fans.unite(sides[s].second, sides[s - 1].second);
    // A fan's boundary at v: its edges at v in exactly one of its triangles. An edge in more
    // than two of them (a non-manifold edge inside the fan) makes the fan no wedge: its umbrella
    // could never be one path, and the pinch is unsupported.
    bool manifold_fans = true;
    ends.clear();
    for (std::size_t s = 0; s < sides.size();) {
      std::size_t r = s;
      while (r < sides.size() && sides[r].first == sides[s].first) ++r;
      roots.clear();
      for (std::size_t q = s; q < r; ++q) roots.push_back(fans.find(sides[q].second));
      std::sort(roots.begin(), roots.end());
      for (std::size_t q = 0; q < roots.size(); ++q) {
        const bool alone = (q == 0 || roots[q - 1] != roots[q]) && (q + 1 == roots.size() || roots[q + 1] != roots[q]);
        if (alone) ends.emplace_back(roots[q], sides[s].first);
        manifold_fans &= q < 2 || roots[q - 2] != roots[q];
      }
      s = r;
    }
    std::sort(ends.begin(), ends.end());
    bool supported = complex.vertex_corner[v] != kNoIndex && manifold_fans;
    const std::size_t fans_first = complex.pinch_fans.size();
    for (std::uint32_t local = 0; local < end - first; ++local) {
      if (fans.find(local) != local) continue;
      const auto lo = std::lower_bound(ends.begin(), ends.end(), std::pair{local, 0u});
      std::size_t count = 0;
      for (auto it = lo; it != ends.end() && it->first == local; ++it) ++count;
      // A closed fan (count 0) is left unsupported: cones of one patch meeting at their tips (a
      // torus pinched to a point) had restricted triangles across the tip joining the cones'
      // umbrellas into one at every scale, the corner ball refined to the floor on half the
      // probes.
      if (count == 2 && complex.edge_curve[lo[0].second] != kNoIndex && complex.edge_curve[lo[1].second] != kNoIndex &&
          wedge_degrees(complex, v, lo[0].second, lo[1].second) >= kNarrowestPinchWedgeDegrees) {
        complex.pinch_fans.push_back({complex.edge_curve[lo[0].second], complex.edge_curve[lo[1].second]});
      } else {
        supported = false;
      }
    }
    if (!supported) {
      complex.pinch_fans.resize(fans_first);
      complex.unsupported_pinches.push_back(complex.pinches[i]);
    }
    complex.pinch_fan_offsets.push_back(static_cast<std::uint32_t>(complex.pinch_fans.size()));
    first = end;
  }
}

}  // namespace detail
}  // namespace delpsc::protect
