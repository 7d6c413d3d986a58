#include "hidden_faces.h"

#include <cstdint>
#include <numeric>
#include <unordered_map>

namespace delpsc::io {

namespace {

// Union-find over triangle ids with path halving.
std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

struct EdgeUse {
  std::uint32_t count = 0;
  int direction_sum = 0;          // +1 per use from lower to higher vertex id, -1 otherwise
  std::uint32_t first_triangle = 0;
};

}  // namespace

std::vector<bool> hidden_back_faces(const SurfaceMesh& mesh, const Vec3& toward_viewer) {
  const std::size_t n = mesh.triangles.size();
  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  std::unordered_map<std::uint64_t, EdgeUse> edges;
  edges.reserve(3 * n / 2 + 1);
  for (std::uint32_t t = 0; t < n; ++t) {
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = tri[k], b = tri[(k + 1) % 3];
      const std::uint64_t key = a < b ? (std::uint64_t{a} << 32 | b) : (std::uint64_t{b} << 32 | a);
      auto [it, inserted] = edges.try_emplace(key, EdgeUse{0, 0, t});
      ++it->second.count;
      it->second.direction_sum += a < b ? 1 : -1;
      if (!inserted) parent[find_root(parent, t)] = find_root(parent, it->second.first_triangle);
    }
  }
  // A component is closed and oriented when each of its edges is used twice, once each way.
  std::vector<bool> closed(n, true);
  for (const auto& [key, use] : edges)
    if (use.count != 2 || use.direction_sum != 0) closed[find_root(parent, use.first_triangle)] = false;
  // Six times the signed volume of each closed component (divergence theorem): positive when
  // its triangles are counter-clockwise seen from outside.
  std::vector<double> volume(n, 0.0);
  for (std::uint32_t t = 0; t < n; ++t) {
    const auto& tri = mesh.triangles[t];
    const std::uint32_t root = find_root(parent, t);
    if (!closed[root]) continue;
    // Relative to a vertex of the component: no cancellation for a model far from the origin.
    const Vec3& o = mesh.vertices[mesh.triangles[root][0]];
    volume[root] += (mesh.vertices[tri[0]] - o).dot((mesh.vertices[tri[1]] - o).cross(mesh.vertices[tri[2]] - o));
  }
  std::vector<bool> hidden(n, false);
  for (std::uint32_t t = 0; t < n; ++t) {
    const std::uint32_t root = find_root(parent, t);
    if (!closed[root] || volume[root] == 0) continue;
    const auto& tri = mesh.triangles[t];
    const Vec3 normal = (mesh.vertices[tri[1]] - mesh.vertices[tri[0]]).cross(mesh.vertices[tri[2]] - mesh.vertices[tri[0]]);
    const double facing = normal.dot(toward_viewer);
    hidden[t] = volume[root] > 0 ? facing < 0 : facing > 0;
  }
  return hidden;
}

}  // namespace delpsc::io
