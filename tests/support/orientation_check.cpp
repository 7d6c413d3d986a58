#include "orientation_check.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <tuple>

namespace delpsc::test {

std::vector<std::string> orientation_problems(const io::SurfaceMesh& mesh, std::size_t max_problems) {
  std::vector<std::string> problems;
  const auto problem = [&](const std::string& what) {
    if (problems.size() < max_problems) problems.push_back(what);
  };
  const auto n = static_cast<std::uint32_t>(mesh.triangles.size());
  struct Use {
    std::uint32_t lo, hi, triangle;
    bool forward;  // the triangle goes from lo to hi
  };
  std::vector<Use> uses;
  uses.reserve(3 * std::size_t{n});
  for (std::uint32_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      uses.push_back({std::min(a, b), std::max(a, b), t, a < b});
    }
  std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) {
    return std::tie(x.lo, x.hi, x.triangle) < std::tie(y.lo, y.hi, y.triangle);
  });
  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  const auto root = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<char> open(n, 0);  // some edge of the triangle is not in exactly two triangles
  for (std::size_t b = 0; b < uses.size();) {
    std::size_t e = b + 1;
    while (e < uses.size() && uses[e].lo == uses[b].lo && uses[e].hi == uses[b].hi) ++e;
    if (e - b == 2) {
      if (uses[b].forward == uses[b + 1].forward)
        problem("triangles " + std::to_string(uses[b].triangle) + " and " + std::to_string(uses[b + 1].triangle) +
                " traverse their edge " + std::to_string(uses[b].lo) + "-" + std::to_string(uses[b].hi) +
                " the same way");
      parent[root(uses[b].triangle)] = root(uses[b + 1].triangle);
    } else {
      for (std::size_t j = b; j < e; ++j) open[uses[j].triangle] = 1;
    }
    b = e;
  }
  // Six times the signed volume of each component, and whether it is closed.
  std::vector<double> volume(n, 0);
  std::vector<char> closed(n, 1);
  for (std::uint32_t t = 0; t < n; ++t) {
    const auto& v = mesh.triangles[t];
    const std::uint32_t r = root(t);
    volume[r] += mesh.vertices[v[0]].dot(mesh.vertices[v[1]].cross(mesh.vertices[v[2]]));
    if (open[t]) closed[r] = 0;
  }
  // A closed component inside an odd number of others bounds a cavity and faces into it
  // (negative volume): the parity of a ray's crossings, from a point inside one of its
  // triangles, with the other closed components (a ray cast, not the library's winding
  // numbers), among those whose box holds that point.
  std::vector<std::uint32_t> closed_roots;
  for (std::uint32_t t = 0; t < n; ++t)
    if (root(t) == t && closed[t]) closed_roots.push_back(t);
  std::vector<std::vector<std::uint32_t>> members(closed_roots.size());
  std::vector<kernel::Box3> boxes(closed_roots.size());
  for (std::uint32_t t = 0; t < n; ++t) {
    const auto it = std::lower_bound(closed_roots.begin(), closed_roots.end(), root(t));
    if (it == closed_roots.end() || *it != root(t)) continue;
    const auto c = static_cast<std::size_t>(it - closed_roots.begin());
    members[c].push_back(t);
    for (const std::uint32_t v : mesh.triangles[t]) boxes[c].extend(mesh.vertices[v]);
  }
  const Vec3 direction = Vec3(0.5773, 0.5779, 0.5768).normalized();
  const auto crossings = [&](const Vec3& p, const std::vector<std::uint32_t>& ts) {
    int count = 0;
    for (const std::uint32_t t : ts) {  // Moller and Trumbore, in doubles: a test's estimate
      const Vec3 &a = mesh.vertices[mesh.triangles[t][0]], &b = mesh.vertices[mesh.triangles[t][1]],
                 &c = mesh.vertices[mesh.triangles[t][2]];
      const Vec3 e1 = b - a, e2 = c - a, h = direction.cross(e2);
      const double det = e1.dot(h);
      if (det == 0) continue;
      const Vec3 s = p - a;
      const double u = s.dot(h) / det;
      if (u < 0 || u > 1) continue;
      const Vec3 q = s.cross(e1);
      const double w = direction.dot(q) / det;
      if (w < 0 || u + w > 1) continue;
      count += e2.dot(q) / det > 0;
    }
    return count;
  };
  for (std::size_t i = 0; i < closed_roots.size(); ++i) {
    // A triangle's centroid: components may share a vertex, which would lie on the other one.
    const auto& seed = mesh.triangles[closed_roots[i]];
    const Vec3 p = (mesh.vertices[seed[0]] + mesh.vertices[seed[1]] + mesh.vertices[seed[2]]) / 3;
    int depth = 0;
    for (std::size_t j = 0; j < closed_roots.size(); ++j)
      if (j != i && boxes[j].contains(p)) depth += crossings(p, members[j]) % 2;
    const double v = volume[closed_roots[i]];
    if (depth % 2 == 0 && !(v > 0))
      problem("the closed component of triangle " + std::to_string(closed_roots[i]) + " faces inward (signed volume " +
              std::to_string(v / 6) + ")");
    if (depth % 2 == 1 && !(v < 0))
      problem("the closed component of triangle " + std::to_string(closed_roots[i]) +
              " bounds a cavity but faces away from it (signed volume " + std::to_string(v / 6) + ")");
  }
  return problems;
}

std::vector<std::string> patches_against_input(const io::SurfaceMesh& mesh, const refine::Domain& domain) {
  std::vector<long> agree(domain.patch_count(), 0), disagree(domain.patch_count(), 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t];
    const Vec3 &a = mesh.vertices[v[0]], &b = mesh.vertices[v[1]], &c = mesh.vertices[v[2]];
    const auto near = domain.closest_point((a + b + c) / 3);
    const auto patch = static_cast<std::uint32_t>(mesh.triangle_patch[t]);
    if (!near || near->patch != patch || patch >= agree.size()) continue;
    const double d = (b - a).cross(c - a).dot(near->normal);
    if (d > 0) ++agree[patch];
    if (d < 0) ++disagree[patch];
  }
  std::vector<std::string> problems;
  for (std::size_t p = 0; p < agree.size(); ++p)
    if (disagree[p] >= agree[p] && disagree[p] > 0)
      problems.push_back("patch " + std::to_string(p) + " faces against the input: " + std::to_string(disagree[p]) +
                         " of its triangles disagree with the input's, " + std::to_string(agree[p]) + " agree");
  return problems;
}

}  // namespace delpsc::test
