#include "link_shape.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include <delpsc/delaunay/small_map.h>

namespace delpsc::refine {

using delaunay::PointId;

// Large links: each endpoint numbered on first sight through a hash map (the triangulation's
// SmallMap, cleared in O(1)), degrees counted on the way (a third edge at a vertex ends the
// test), then connectivity by union-find; O(k) expected for k edges. A vertex with a large umbrella (a big ball next to many small
// ones, or the crowd at a fold) is re-checked after every insertion nearby: sorting its link's
// vertices each time, as this did before, took a third of meshing hand.off at 0.5%
// (BENCHMARKS.md, "Session 30").
LinkShape link_shape_large(std::span<const std::array<PointId, 2>> link) {
  thread_local delaunay::detail::SmallMap number;  // endpoint -> its number
  thread_local std::vector<std::uint32_t> degree, parent, ends;
  number.reset(2 * link.size());
  degree.clear();
  ends.resize(2 * link.size());
  for (std::size_t e = 0; e < link.size(); ++e)
    for (int k = 0; k < 2; ++k) {
      const PointId v = link[e][k];
      std::uint32_t i;
      if (const std::uint32_t* known = number.find(v)) {
        i = *known;
      } else {
        i = static_cast<std::uint32_t>(degree.size());
        number.insert(v, i);
        degree.push_back(0);
      }
      if (++degree[i] > 2) return {false, degree.size()};
      ends[2 * e + k] = i;
    }
  const std::size_t n = degree.size();
  // Connected with degrees <= 2 needs n <= k + 1 (a path); more vertices cannot be connected.
  if (n > link.size() + 1) return {false, n};
  parent.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) parent[i] = i;
  const auto root = [&](std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::size_t components = n;
  for (std::size_t e = 0; e < link.size(); ++e) {
    const std::uint32_t ra = root(ends[2 * e]), rb = root(ends[2 * e + 1]);
    if (ra != rb) {
      parent[ra] = rb;
      --components;
    }
  }
  return {components == 1, n};
}

// The common case, an umbrella of a few triangles (a surface vertex has ~6): the same answer
// from fixed arrays and linear scans, without sorting or allocation. The disk check runs ~8
// times per output vertex and the general version cost ~9% of meshing.
LinkShape link_shape_small(std::span<const std::array<PointId, 2>> link) {
  std::array<PointId, 2 * kSmallLink> verts;
  std::array<std::uint8_t, 2 * kSmallLink> degree{}, label;
  std::size_t n = 0;
  std::array<std::array<std::uint8_t, 2>, kSmallLink> ends;
  for (std::size_t e = 0; e < link.size(); ++e)
    for (int k = 0; k < 2; ++k) {
      std::size_t i = 0;
      while (i < n && verts[i] != link[e][k]) ++i;
      if (i == n) {
        verts[n] = link[e][k];
        label[n] = static_cast<std::uint8_t>(n);
        ++n;
      }
      if (++degree[i] > 2) return {false, n};
      ends[e][k] = static_cast<std::uint8_t>(i);
    }
  // Connectivity: relabel to the smallest label until stable (at most k passes over k edges).
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t e = 0; e < link.size(); ++e) {
      std::uint8_t& a = label[ends[e][0]];
      std::uint8_t& b = label[ends[e][1]];
      if (a == b) continue;
      a = b = std::min(a, b);
      changed = true;
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (label[i] != 0) return {false, n};
  return {true, n};
}

LinkShape link_shape(std::span<const std::array<PointId, 2>> link) {
  return link.size() <= kSmallLink ? link_shape_small(link) : link_shape_large(link);
}

bool link_pieces(std::span<const std::array<PointId, 2>> link, std::vector<LinkPiece>& pieces) {
  pieces.clear();
  std::vector<PointId> verts;
  for (const auto& e : link) verts.insert(verts.end(), e.begin(), e.end());
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  const auto index = [&](PointId v) {
    return static_cast<std::uint32_t>(std::lower_bound(verts.begin(), verts.end(), v) - verts.begin());
  };
  std::vector<std::uint32_t> degree(verts.size(), 0), parent(verts.size());
  for (std::uint32_t i = 0; i < parent.size(); ++i) parent[i] = i;
  const auto root = [&](std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& e : link) {
    const std::uint32_t a = index(e[0]), b = index(e[1]);
    if (++degree[a] > 2 || ++degree[b] > 2) return false;
    parent[root(a)] = root(b);
  }
  // Per component: its vertices, its edges, and its degree-1 vertices (a path's ends).
  std::vector<std::uint32_t> piece_of(verts.size(), 0xffffffffu), vertex_count, edge_count, ends_seen;
  for (std::uint32_t i = 0; i < verts.size(); ++i) {
    const std::uint32_t r = root(i);
    if (piece_of[r] == 0xffffffffu) {
      piece_of[r] = static_cast<std::uint32_t>(pieces.size());
      pieces.emplace_back();
      vertex_count.push_back(0);
      edge_count.push_back(0);
      ends_seen.push_back(0);
    }
    const std::uint32_t k = piece_of[r];
    // Degrees <= 2 and connected: a path has exactly two ends, a cycle none.
    if (degree[i] == 1) pieces[k].ends[ends_seen[k]++] = verts[i];
    ++vertex_count[k];
  }
  for (const auto& e : link) ++edge_count[piece_of[root(index(e[0]))]];
  for (std::size_t k = 0; k < pieces.size(); ++k) pieces[k].cycle = edge_count[k] == vertex_count[k];
  return true;
}

bool pieces_match_fans(std::span<const LinkPiece> pieces, std::span<const std::array<std::uint32_t, 2>> fans,
                       const std::function<bool(PointId, std::uint32_t)>& on_curve) {
  if (pieces.size() != fans.size()) return false;
  constexpr std::uint32_t kClosed = 0xffffffffu;
  std::vector<std::uint8_t> used(fans.size(), 0);
  const auto fits = [&](const LinkPiece& p, const std::array<std::uint32_t, 2>& f) {
    if (p.cycle || f[0] == kClosed) return p.cycle && f[0] == kClosed;
    return (on_curve(p.ends[0], f[0]) && on_curve(p.ends[1], f[1])) || (on_curve(p.ends[0], f[1]) && on_curve(p.ends[1], f[0]));
  };
  // Piece i onwards to the unused fans; depth-first (fans are a handful).
  const std::function<bool(std::size_t)> assign = [&](std::size_t i) {
    if (i == pieces.size()) return true;
    for (std::size_t f = 0; f < fans.size(); ++f) {
      if (used[f] || !fits(pieces[i], fans[f])) continue;
      used[f] = 1;
      if (assign(i + 1)) return true;
      used[f] = 0;
    }
    return false;
  };
  return assign(0);
}

}  // namespace delpsc::refine
