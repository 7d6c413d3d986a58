#include "unused_vertices.h"

#include <vector>

namespace delpsc::io {

UnusedVertices drop_unused_vertices(TriangleSoup& soup) {
  UnusedVertices dropped;
  const std::size_t n = soup.vertices.size();
  std::vector<std::uint8_t> used(n, 0);
  for (const auto& t : soup.triangles)
    for (const std::uint32_t v : t) used[v] = 1;
  // Kept vertices move down in place: vertex v goes to kept <= v, read before it is written.
  std::vector<std::uint32_t> renumber(n);
  std::uint32_t kept = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (used[v]) {
      renumber[v] = kept;
      soup.vertices[kept++] = soup.vertices[v];
    } else if (dropped.count++ == 0) {
      dropped.first = static_cast<std::uint32_t>(v);
      dropped.first_point = soup.vertices[v];
    }
  }
  if (dropped.count == 0) return dropped;
  soup.vertices.resize(kept);
  for (auto& t : soup.triangles)
    for (std::uint32_t& v : t) v = renumber[v];
  return dropped;
}

}  // namespace delpsc::io
