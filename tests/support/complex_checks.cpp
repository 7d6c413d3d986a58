#include "support/complex_checks.h"

#include <algorithm>
#include <map>

namespace delpsc::test {

using protect::kNoIndex;

namespace {

std::uint32_t edge_index(const protect::Complex& c, std::uint32_t u, std::uint32_t v) {
  const std::array<std::uint32_t, 2> key = {std::min(u, v), std::max(u, v)};
  const auto it = std::lower_bound(c.edges.begin(), c.edges.end(), key);
  return it != c.edges.end() && *it == key ? static_cast<std::uint32_t>(it - c.edges.begin()) : kNoIndex;
}

}  // namespace

std::vector<std::string> complex_problems(const protect::Complex& c) {
  std::vector<std::string> problems;
  auto fail = [&](std::string what) { problems.push_back(std::move(what)); };
  const auto n_edges = static_cast<std::uint32_t>(c.edges.size());

  std::vector<int> edge_uses(n_edges, 0);
  for (std::uint32_t k = 0; k < c.curves.size(); ++k) {
    const auto& curve = c.curves[k];
    const std::string name = "curve " + std::to_string(k) + ": ";
    if (curve.start_corner >= c.corner_count() || curve.end_corner >= c.corner_count()) {
      fail(name + "end corner out of range");
      continue;
    }
    const auto poly = c.curve_polyline(k);
    const auto s = c.curve_parameters(k);
    if (poly.size() < 2) fail(name + "fewer than 2 vertices");
    if (c.corner_vertex[curve.start_corner] != poly.front()) fail(name + "start corner is not its first vertex");
    if (c.corner_vertex[curve.end_corner] != poly.back()) fail(name + "end corner is not its last vertex");
    if (curve.closed != (curve.start_corner == curve.end_corner)) fail(name + "closed flag wrong");
    if (s.front() != 0 || s.back() != curve.length) fail(name + "arc length does not run from 0 to length");
    for (std::size_t i = 0; i + 1 < poly.size(); ++i) {
      if (!(s[i + 1] > s[i])) fail(name + "arc length not increasing");
      if (i > 0 && c.vertex_corner[poly[i]] != kNoIndex) fail(name + "inner vertex is a corner");
      const std::uint32_t e = edge_index(c, poly[i], poly[i + 1]);
      if (e == kNoIndex || c.edge_feature[e] == 0) {
        fail(name + "consecutive vertices not joined by a feature edge");
        continue;
      }
      if (c.edge_curve[e] != k) fail(name + "edge labelled with another curve");
      ++edge_uses[e];
      // Curve patches = patches of this edge's triangles.
      std::vector<std::uint32_t> here;
      for (auto t : c.edge_triangle_ids(e)) here.push_back(c.triangle_patch[t]);
      std::sort(here.begin(), here.end());
      const auto listed = c.curve_patch_ids(k);
      if (!std::equal(here.begin(), here.end(), listed.begin(), listed.end()))
        fail(name + "patch list differs from the triangles at edge " + std::to_string(e));
    }
  }
  for (std::uint32_t e = 0; e < n_edges; ++e)
    if ((c.edge_feature[e] != 0) != (edge_uses[e] == 1))
      fail("edge " + std::to_string(e) + ": feature edge on " + std::to_string(edge_uses[e]) + " curves");

  std::vector<std::uint32_t> degree(c.vertices.size(), 0);
  for (std::uint32_t e = 0; e < n_edges; ++e)
    if (c.edge_feature[e] != 0) {
      ++degree[c.edges[e][0]];
      ++degree[c.edges[e][1]];
    }
  for (std::uint32_t k = 0; k < c.corner_count(); ++k) {
    if (c.vertex_corner[c.corner_vertex[k]] != k) fail("corner " + std::to_string(k) + ": vertex_corner disagrees");
    if (c.corner_curve_ids(k).size() != degree[c.corner_vertex[k]])
      fail("corner " + std::to_string(k) + ": curve ends differ from the feature degree");
  }

  for (std::uint32_t p = 0; p < c.patch_count(); ++p)
    for (auto t : c.patch_triangle_ids(p))
      if (c.triangle_patch[t] != p) fail("patch " + std::to_string(p) + " lists a triangle of another patch");
  if (c.patch_triangles.size() != c.triangles.size()) fail("patch triangle lists do not cover the triangles");

  // Boundary half-edges per (patch, curve) versus the multiplicities listed by the patches:
  // for every feature edge, the patches of its triangles with their counts must equal the
  // patches that list its curve, with their multiplicities.
  std::vector<std::map<std::uint32_t, std::uint32_t>> listed(c.curve_count());
  for (std::uint32_t p = 0; p < c.patch_count(); ++p)
    for (auto k : c.patch_curve_ids(p)) {
      if (k >= c.curve_count()) {
        fail("patch " + std::to_string(p) + " lists curve " + std::to_string(k) + " out of range");
        continue;
      }
      ++listed[k][p];
    }
  for (std::uint32_t e = 0; e < n_edges; ++e) {
    if (c.edge_feature[e] == 0 || c.edge_curve[e] >= c.curve_count()) continue;
    std::map<std::uint32_t, std::uint32_t> here;
    for (auto t : c.edge_triangle_ids(e)) ++here[c.triangle_patch[t]];
    if (here != listed[c.edge_curve[e]])
      fail("edge " + std::to_string(e) + ": its triangles' patches differ from the patches listing curve " +
           std::to_string(c.edge_curve[e]));
  }
  return problems;
}

std::vector<std::pair<int, int>> patch_topologies(const protect::Complex& c) {
  std::vector<std::pair<int, int>> t;
  for (const auto& p : c.patches) t.push_back({p.euler_characteristic, static_cast<int>(p.boundary_loops)});
  std::sort(t.begin(), t.end());
  return t;
}

std::size_t non_manifold_curves(const protect::Complex& c) {
  std::size_t n = 0;
  for (std::uint32_t k = 0; k < c.curve_count(); ++k) n += c.curve_patch_ids(k).size() >= 3 ? 1 : 0;
  return n;
}

}  // namespace delpsc::test
