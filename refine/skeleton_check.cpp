#include "skeleton_check.h"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>
#include <utility>

namespace delpsc::refine {

namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;
Edge edge(std::uint32_t a, std::uint32_t b) { return a < b ? Edge{a, b} : Edge{b, a}; }

// Components of a graph given by edges (union-find over the vertex ids met).
std::size_t components(const std::vector<Edge>& edges) {
  std::map<std::uint32_t, std::uint32_t> parent;
  auto find = [&](std::uint32_t x) {
    parent.emplace(x, x);
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& [a, b] : edges) parent[find(a)] = find(b);
  std::set<std::uint32_t> roots;
  for (const auto& [x, p] : parent) roots.insert(find(x));
  return roots.size();
}

// Union-find over dense ids with path halving.
std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// The Euler characteristic and boundary loops of the triangles `tris` cut open along the edges
// in `slit`. Each triangle corner is a copy of its vertex; two triangles sharing an edge that is
// not a slit glue their corners at its two ends. The cut surface's vertices are the glued
// classes of corners, its edges those of the triangles with each slit edge counted once per
// triangle, its boundary the edges of one triangle (original boundary and both sides of slits).
std::pair<int, std::size_t> cut_open_topology(const io::SurfaceMesh& mesh, const std::vector<std::size_t>& tris,
                                              const std::set<Edge>& slit) {
  const auto corner = [](std::size_t local, int k) { return static_cast<std::uint32_t>(3 * local + k); };
  std::map<Edge, std::vector<std::pair<std::size_t, int>>> uses;  // edge -> (local triangle, corner of its first end)
  for (std::size_t i = 0; i < tris.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const auto& v = mesh.triangles[tris[i]];
      uses[edge(v[k], v[(k + 1) % 3])].emplace_back(i, k);
    }
  std::vector<std::uint32_t> parent(3 * tris.size());
  for (std::uint32_t c = 0; c < parent.size(); ++c) parent[c] = c;
  // The corner of local triangle i at mesh vertex x.
  const auto corner_at = [&](std::size_t i, std::uint32_t x) {
    const auto& v = mesh.triangles[tris[i]];
    return corner(i, v[0] == x ? 0 : v[1] == x ? 1 : 2);
  };
  std::size_t edges = 0;
  std::vector<Edge> boundary;  // between corner classes, filled after gluing
  for (const auto& [e, list] : uses) {
    const bool cut = list.size() == 1 || slit.count(e);
    edges += cut ? list.size() : 1;
    if (cut) continue;
    for (std::size_t j = 1; j < list.size(); ++j)
      for (const std::uint32_t x : {e.first, e.second})
        parent[find_root(parent, corner_at(list[0].first, x))] = find_root(parent, corner_at(list[j].first, x));
  }
  std::set<std::uint32_t> vertices;
  for (std::uint32_t c = 0; c < parent.size(); ++c) vertices.insert(find_root(parent, c));
  for (const auto& [e, list] : uses)
    if (list.size() == 1 || slit.count(e))
      for (const auto& [i, k] : list)
        boundary.push_back(edge(find_root(parent, corner_at(i, e.first)), find_root(parent, corner_at(i, e.second))));
  const int euler = static_cast<int>(vertices.size()) - static_cast<int>(edges) + static_cast<int>(tris.size());
  return {euler, components(boundary)};
}

}  // namespace

SkeletonReport check_skeleton(const io::SurfaceMesh& mesh, const Domain& domain, double tolerance) {
  SkeletonReport report;
  auto problem = [&](std::uint32_t patch, const std::string& what) {
    if (report.problems.size() < 50) report.problems.push_back("patch " + std::to_string(patch) + ": " + what);
  };
  std::set<std::uint32_t> on_curve;  // vertices of feature edges
  for (const auto& e : mesh.edges) on_curve.insert(e[0]), on_curve.insert(e[1]);
  for (std::uint32_t sigma = 0; sigma < domain.patch_count(); ++sigma) {
    PatchSkeleton ps;
    ps.patch = sigma;
    std::map<Edge, int> edge_count;
    std::map<std::uint32_t, std::vector<Edge>> link;  // vertex -> edges opposite it
    std::vector<std::size_t> tris;                     // the triangles of σ
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      if (mesh.triangle_patch[t] != static_cast<std::int32_t>(sigma)) continue;
      ++ps.triangles;
      tris.push_back(t);
      const auto& v = mesh.triangles[t];
      for (int k = 0; k < 3; ++k) {
        ++edge_count[edge(v[k], v[(k + 1) % 3])];
        link[v[k]].push_back(edge(v[(k + 1) % 3], v[(k + 2) % 3]));
      }
    }
    ps.vertices = link.size();
    ps.edges = edge_count.size();
    ps.euler = static_cast<int>(ps.vertices) - static_cast<int>(ps.edges) + static_cast<int>(ps.triangles);
    if (ps.triangles == 0) problem(sigma, "no triangle");
    std::vector<Edge> boundary;
    for (const auto& [e, k] : edge_count) {
      if (k > 2) problem(sigma, "edge in " + std::to_string(k) + " triangles"), ps.manifold = false;
      if (k == 1) boundary.push_back(e);
    }
    ps.boundary_loops = components(boundary);
    // Each vertex's fan: a path or a cycle (connected, degrees <= 2).
    for (const auto& [v, edges] : link) {
      std::map<std::uint32_t, int> degree;
      for (const auto& [a, b] : edges) ++degree[a], ++degree[b];
      const bool ok = components(edges) == 1 &&
                      std::all_of(degree.begin(), degree.end(), [](const auto& d) { return d.second <= 2; });
      if (!ok) problem(sigma, "the triangles around vertex " + std::to_string(v) + " are not one disk"), ps.manifold = false;
      const auto close = domain.closest_point(mesh.vertices[v]);
      if (!close || close->squared_distance > tolerance * tolerance)
        problem(sigma, "vertex " + std::to_string(v) + " is off the domain");
      else if (!on_curve.count(v) && close->patch != sigma)
        problem(sigma, "vertex " + std::to_string(v) + " lies on patch " + std::to_string(close->patch));
    }
    // The boundary must be the feature edges of the curves bounding σ once.
    const auto curves = domain.patch_curves(sigma);
    std::set<Edge> expected, slit;
    for (std::size_t i = 0; i < mesh.edges.size(); ++i) {
      const auto c = static_cast<std::uint32_t>(mesh.edge_curve[i]);
      const auto k = std::count(curves.begin(), curves.end(), c);
      if (k == 1) expected.insert(edge(mesh.edges[i][0], mesh.edges[i][1]));
      if (k >= 2) slit.insert(edge(mesh.edges[i][0], mesh.edges[i][1]));
    }
    const std::set<Edge> found(boundary.begin(), boundary.end());
    for (const Edge& e : found)
      if (!expected.count(e)) problem(sigma, "boundary edge " + std::to_string(e.first) + "-" + std::to_string(e.second) + " is not on a boundary curve");
    for (const Edge& e : expected)
      if (!found.count(e)) problem(sigma, "curve edge " + std::to_string(e.first) + "-" + std::to_string(e.second) + " is not on the boundary");
    for (const Edge& e : slit)
      if (edge_count[e] != 2) problem(sigma, "slit edge not between two triangles");
    std::tie(ps.cut_euler, ps.cut_boundary_loops) = cut_open_topology(mesh, tris, slit);
    report.patches.push_back(ps);
  }
  return report;
}

}  // namespace delpsc::refine
