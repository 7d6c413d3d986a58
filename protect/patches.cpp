// Steps 4 and 6 of build_complex: patches as components across non-feature edges, the fans of
// triangles around each vertex, the incidences between corners, curves and patches, and the
// topology of each patch cut open along its features.
#include <algorithm>
#include <utility>
#include <vector>

#include "complex_build.h"

namespace delpsc::protect::detail {

namespace {

// Complex::pinches. The fans of one patch around a vertex are its wedges (joined across
// smooth edges, whose two triangles share a patch) joined again across the feature edges
// between two triangles of the same patch (a slit's sides, a crease inside a patch): a
// union-find over the wedges, about one per vertex, instead of a third one over all triangle
// corners (that cost ~20% of build_complex on a 1M-triangle cube, bench_complex).
// `wedge_vertex`, `wedge_patch`: each wedge's vertex and patch.
template <class CornerAt>
void find_pinches(Complex& complex, const VertexFans& fans, const kernel::LargeVector<std::uint32_t>& wedge_vertex,
                  const kernel::LargeVector<std::uint32_t>& wedge_patch, CornerAt corner_at) {
  // A vertex with one wedge has one fan: with no vertex of more, nothing to find.
  kernel::LargeVector<std::uint8_t> fan_count(complex.vertices.size(), 0);  // saturates at 2
  bool several = false;
  for (const std::uint32_t v : wedge_vertex) {
    several |= fan_count[v] > 0;
    fan_count[v] = static_cast<std::uint8_t>(fan_count[v] < 2 ? fan_count[v] + 1 : 2);
  }
  complex.pinches.clear();
  if (!several) return;
  UnionFind patch_fans(fans.wedge_count);
  // Each triangle along a feature edge joins the first one of its patch there. Grouped by a sort
  // of (patch, triangle), not by comparing every two: an edge of k triangles each in a patch of
  // its own cost k²/2 comparisons (a PLY polygon listing 30,000 indices of four vertices, split
  // into a fan on a few edges, took 2 s here, and 30 million ran for hours).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> by_patch;  // (patch, triangle)
  for (std::uint32_t e = 0; e < complex.edges.size(); ++e) {
    if (complex.edge_feature[e] == 0) continue;
    const auto faces = complex.edge_triangle_ids(e);
    if (faces.size() == 2) {  // most feature edges (a crease): no list, no sort
      if (complex.triangle_patch[faces[0]] == complex.triangle_patch[faces[1]])
        for (const std::uint32_t v : complex.edges[e])
          patch_fans.unite(fans.corner_wedge[corner_at(faces[0], v)], fans.corner_wedge[corner_at(faces[1], v)]);
      continue;
    }
    by_patch.clear();
    for (const std::uint32_t t : faces) by_patch.emplace_back(complex.triangle_patch[t], t);
    std::sort(by_patch.begin(), by_patch.end());
    for (const std::uint32_t v : complex.edges[e])
      for (std::size_t i = 1, first = 0; i < by_patch.size(); ++i) {
        if (by_patch[i].first != by_patch[first].first) {
          first = i;
          continue;
        }
        patch_fans.unite(fans.corner_wedge[corner_at(by_patch[first].second, v)],
                         fans.corner_wedge[corner_at(by_patch[i].second, v)]);
      }
  }
  // Two roots at one vertex with the same patch: a pinch. Only the roots at vertices with more
  // than one wedge are collected and sorted.
  kernel::LargeVector<std::array<std::uint32_t, 2>> fan_roots;  // (vertex, patch), one per fan
  for (std::uint32_t w = 0; w < fans.wedge_count; ++w)
    if (fan_count[wedge_vertex[w]] > 1 && patch_fans.find(w) == w) fan_roots.push_back({wedge_vertex[w], wedge_patch[w]});
  std::sort(fan_roots.begin(), fan_roots.end());
  for (std::size_t i = 1; i < fan_roots.size(); ++i)
    if (fan_roots[i] == fan_roots[i - 1] && (complex.pinches.empty() || complex.pinches.back() != fan_roots[i]))
      complex.pinches.push_back(fan_roots[i]);
}

}  // namespace

VertexFans find_patches(Complex& complex) {
  const auto n_tris = static_cast<std::uint32_t>(complex.triangles.size());

  // Components across non-feature edges (a non-feature edge has exactly two triangles), by
  // depth-first search from the smallest unlabelled triangle, so ids follow triangle order.
  complex.triangle_patch.assign(n_tris, kNoIndex);
  std::uint32_t patch_count = 0;
  kernel::LargeVector<std::uint32_t> stack;
  for (std::uint32_t seed = 0; seed < n_tris; ++seed) {
    if (complex.triangle_patch[seed] != kNoIndex) continue;
    complex.triangle_patch[seed] = patch_count;
    stack.push_back(seed);
    while (!stack.empty()) {
      const std::uint32_t t = stack.back();
      stack.pop_back();
      for (const std::uint32_t e : complex.triangle_edges[t]) {
        if (complex.edge_feature[e] != 0) continue;
        for (const std::uint32_t n : complex.edge_triangle_ids(e))
          if (complex.triangle_patch[n] == kNoIndex) {
            complex.triangle_patch[n] = patch_count;
            stack.push_back(n);
          }
      }
    }
    ++patch_count;
  }
  complex.patches.assign(patch_count, Patch{});
  kernel::LargeVector<std::uint32_t> counts(patch_count, 0);
  for (const auto p : complex.triangle_patch) ++counts[p];
  complex.patch_triangle_offsets = offsets_from_counts(counts);
  complex.patch_triangles.resize(n_tris);
  {
    kernel::LargeVector<std::uint32_t> fill(complex.patch_triangle_offsets.begin(), complex.patch_triangle_offsets.end() - 1);
    for (std::uint32_t t = 0; t < n_tris; ++t) complex.patch_triangles[fill[complex.triangle_patch[t]]++] = t;
  }

  // Fans around each vertex, with one union-find over all triangle corners (t, k), index
  // 3 t + k: the corners of the triangles along an edge are joined at each end of the edge -
  // along any edge for sheets, along a non-feature edge for wedges. A set never leaves its
  // vertex, and a set's representative is its smallest corner.
  const auto n_corners = 3 * static_cast<std::size_t>(n_tris);
  UnionFind sheets(n_corners), wedges(n_corners);
  auto corner_at = [&](std::uint32_t t, std::uint32_t v) {
    const auto& tri = complex.triangles[t];
    return 3 * t + (tri[0] == v ? 0u : tri[1] == v ? 1u : 2u);
  };
  for (std::uint32_t e = 0; e < complex.edges.size(); ++e) {
    const auto faces = complex.edge_triangle_ids(e);
    const bool smooth = complex.edge_feature[e] == 0;
    for (const std::uint32_t v : complex.edges[e]) {
      const std::uint32_t first = corner_at(faces[0], v);
      for (std::size_t i = 1; i < faces.size(); ++i) {
        const std::uint32_t other = corner_at(faces[i], v);
        sheets.unite(first, other);
        if (smooth) wedges.unite(first, other);
      }
    }
  }
  VertexFans fans;
  fans.vertex_sheets.assign(complex.vertices.size(), 0);
  fans.corner_wedge.assign(n_corners, kNoIndex);
  kernel::LargeVector<std::uint32_t> wedge_vertex, wedge_patch;
  wedge_vertex.reserve(complex.vertices.size());
  wedge_patch.reserve(complex.vertices.size());
  for (std::uint32_t c = 0; c < n_corners; ++c) {
    if (sheets.find(c) == c) ++fans.vertex_sheets[complex.triangles[c / 3][c % 3]];
    const std::uint32_t root = wedges.find(c);
    // Roots are the smallest corner of their set, so they are numbered before their members.
    if (root == c) {
      fans.corner_wedge[c] = fans.wedge_count++;
      wedge_vertex.push_back(complex.triangles[c / 3][c % 3]);
      wedge_patch.push_back(complex.triangle_patch[c / 3]);
    } else {
      fans.corner_wedge[c] = fans.corner_wedge[root];
    }
  }
  find_pinches(complex, fans, wedge_vertex, wedge_patch, corner_at);
  return fans;
}

void link_incidences(Complex& complex, const VertexFans& fans) {
  const auto n_patches = static_cast<std::uint32_t>(complex.patches.size());
  const auto n_curves = static_cast<std::uint32_t>(complex.curves.size());
  const auto n_corners = static_cast<std::uint32_t>(complex.corner_vertex.size());

  // Curves -> patches: the patches of the triangles on the curve's first edge. (Corners are
  // placed wherever these change along a polyline, so any edge of the curve gives the same.)
  complex.curve_patch_offsets.assign(1, 0);
  complex.curve_patches.clear();
  kernel::LargeVector<std::pair<std::uint32_t, std::uint32_t>> patch_curve;  // (patch, curve)
  for (std::uint32_t c = 0; c < n_curves; ++c) {
    const auto poly = complex.curve_polyline(c);
    const std::uint32_t e = find_edge(complex, poly[0], poly[1]);
    const auto begin = complex.curve_patches.size();
    for (const auto t : complex.edge_triangle_ids(e)) complex.curve_patches.push_back(complex.triangle_patch[t]);
    std::sort(complex.curve_patches.begin() + static_cast<std::ptrdiff_t>(begin), complex.curve_patches.end());
    for (auto i = begin; i < complex.curve_patches.size(); ++i) patch_curve.push_back({complex.curve_patches[i], c});
    complex.curve_patch_offsets.push_back(static_cast<std::uint32_t>(complex.curve_patches.size()));
  }
  std::sort(patch_curve.begin(), patch_curve.end());
  {
    kernel::LargeVector<std::uint32_t> counts(n_patches, 0);
    for (const auto& pc : patch_curve) ++counts[pc.first];
    complex.patch_curve_offsets = offsets_from_counts(counts);
    complex.patch_curves.clear();
    for (const auto& pc : patch_curve) complex.patch_curves.push_back(pc.second);
  }

  // Corners -> curves, once per curve end, in curve order.
  {
    kernel::LargeVector<std::uint32_t> counts(n_corners, 0);
    for (const auto& curve : complex.curves) {
      ++counts[curve.start_corner];
      ++counts[curve.end_corner];
    }
    complex.corner_curve_offsets = offsets_from_counts(counts);
    complex.corner_curves.assign(complex.corner_curve_offsets.back(), kNoIndex);
    kernel::LargeVector<std::uint32_t> fill(complex.corner_curve_offsets.begin(), complex.corner_curve_offsets.end() - 1);
    for (std::uint32_t c = 0; c < n_curves; ++c) {
      complex.corner_curves[fill[complex.curves[c].start_corner]++] = c;
      complex.corner_curves[fill[complex.curves[c].end_corner]++] = c;
    }
  }

  // Corners <-> patches: the patches of the triangles at the corner's vertex.
  kernel::LargeVector<std::pair<std::uint32_t, std::uint32_t>> corner_patch;
  for (std::uint32_t t = 0; t < complex.triangles.size(); ++t)
    for (const auto v : complex.triangles[t])
      if (complex.vertex_corner[v] != kNoIndex) corner_patch.push_back({complex.vertex_corner[v], complex.triangle_patch[t]});
  std::sort(corner_patch.begin(), corner_patch.end());
  corner_patch.erase(std::unique(corner_patch.begin(), corner_patch.end()), corner_patch.end());
  {
    kernel::LargeVector<std::uint32_t> counts(n_corners, 0), pcounts(n_patches, 0);
    for (const auto& kp : corner_patch) {
      ++counts[kp.first];
      ++pcounts[kp.second];
    }
    complex.corner_patch_offsets = offsets_from_counts(counts);
    complex.corner_patches.clear();
    for (const auto& kp : corner_patch) complex.corner_patches.push_back(kp.second);
    complex.patch_corner_offsets = offsets_from_counts(pcounts);
    complex.patch_corners.assign(complex.patch_corner_offsets.back(), kNoIndex);
    kernel::LargeVector<std::uint32_t> fill(complex.patch_corner_offsets.begin(), complex.patch_corner_offsets.end() - 1);
    for (const auto& kp : corner_patch) complex.patch_corners[fill[kp.second]++] = kp.first;  // corner order
  }

  // Topology of each patch cut open along its features. Its vertices are the wedges, its edges
  // the non-feature edges (two triangles of the patch) plus one copy of a feature edge per
  // incident triangle of the patch (a boundary edge of the cut surface), its faces the
  // triangles. Boundary loops are the components of the graph of boundary edges on wedges: on
  // the cut surface every boundary wedge has exactly two boundary edges, so components are
  // cycles.
  kernel::LargeVector<std::int64_t> chi(n_patches, 0);
  kernel::LargeVector<std::uint32_t> wedge_patch(fans.wedge_count, kNoIndex);
  for (std::uint32_t t = 0; t < complex.triangles.size(); ++t) {
    const std::uint32_t p = complex.triangle_patch[t];
    ++chi[p];  // F
    for (std::uint32_t k = 0; k < 3; ++k) wedge_patch[fans.corner_wedge[3 * t + k]] = p;
  }
  for (const auto p : wedge_patch) ++chi[p];  // V
  UnionFind loops(fans.wedge_count);
  kernel::LargeVector<char> on_boundary(fans.wedge_count, 0);
  for (std::uint32_t e = 0; e < complex.edges.size(); ++e) {
    const auto faces = complex.edge_triangle_ids(e);
    if (complex.edge_feature[e] == 0) {
      --chi[complex.triangle_patch[faces[0]]];  // E (interior edge)
      continue;
    }
    for (const auto t : faces) {
      --chi[complex.triangle_patch[t]];  // E (one boundary copy per side)
      std::uint32_t w[2], n = 0;
      for (std::uint32_t k = 0; k < 3; ++k)
        if (complex.triangles[t][k] == complex.edges[e][0] || complex.triangles[t][k] == complex.edges[e][1])
          w[n++] = fans.corner_wedge[3 * t + k];
      loops.unite(w[0], w[1]);
      on_boundary[w[0]] = on_boundary[w[1]] = 1;
    }
  }
  for (std::uint32_t w = 0; w < fans.wedge_count; ++w)
    if (on_boundary[w] && loops.find(w) == w) ++complex.patches[wedge_patch[w]].boundary_loops;
  for (std::uint32_t p = 0; p < n_patches; ++p) complex.patches[p].euler_characteristic = static_cast<int>(chi[p]);
}

}  // namespace delpsc::protect::detail
