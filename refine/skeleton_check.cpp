#include "skeleton_check.h"

#include <algorithm>
#include <map>
#include <set>
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
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      if (mesh.triangle_patch[t] != static_cast<std::int32_t>(sigma)) continue;
      ++ps.triangles;
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
      if (k > 2) problem(sigma, "edge in " + std::to_string(k) + " triangles");
      if (k == 1) boundary.push_back(e);
    }
    ps.boundary_loops = components(boundary);
    // Each vertex's fan: a path or a cycle (connected, degrees <= 2).
    for (const auto& [v, edges] : link) {
      std::map<std::uint32_t, int> degree;
      for (const auto& [a, b] : edges) ++degree[a], ++degree[b];
      const bool ok = components(edges) == 1 &&
                      std::all_of(degree.begin(), degree.end(), [](const auto& d) { return d.second <= 2; });
      if (!ok) problem(sigma, "the triangles around vertex " + std::to_string(v) + " are not one disk");
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
    report.patches.push_back(ps);
  }
  return report;
}

}  // namespace delpsc::refine
