// Step 2b of build_complex: triangles listed more than once (the same three vertices once the
// vertices are welded). Two such triangles overlap everywhere, which DelPSC's input may not do
// (§1.1); a polygon listing millions of indices of a few vertices, split into a fan, is one
// triangle repeated millions of times, and every later step that meets each pair of overlapping
// triangles (the self-intersection check: a box per triangle, all of them equal) would take
// years over it. Counted here in O(T log d) from the edge table instead, so that the commands
// refuse such a model at once, naming a repeat.
#include <algorithm>
#include <utility>
#include <vector>

#include "complex_build.h"

namespace delpsc::protect::detail {

void find_duplicate_triangles(Complex& complex) {
  CleanupReport& report = complex.cleanup;
  report.duplicate_triangles = 0;
  report.first_duplicate = {kNoIndex, kNoIndex};
  // Two triangles of an edge with the same vertex off it are repeats: they share all three
  // edges, so each pair is counted at one of them only, the first of the triangles' edges.
  const auto off = [&](std::uint32_t t, std::uint32_t e) {
    const auto& v = complex.triangles[t];
    return v[0] ^ v[1] ^ v[2] ^ complex.edges[e][0] ^ complex.edges[e][1];
  };
  const auto repeat_at = [&](std::uint32_t t, std::uint32_t again, std::uint32_t e) {
    const auto& te = complex.triangle_edges[t];
    if (std::min({te[0], te[1], te[2]}) != e) return;
    if (report.duplicate_triangles++ == 0)
      report.first_duplicate = {complex.triangle_source[t], complex.triangle_source[again]};
  };
  std::vector<std::pair<std::uint32_t, std::uint32_t>> by_off;  // (vertex off the edge, triangle)
  for (std::uint32_t e = 0; e < complex.edges.size(); ++e) {
    const auto faces = complex.edge_triangle_ids(e);
    if (faces.size() < 2) continue;
    if (faces.size() == 2) {  // nearly every edge: no list, no sort (build_complex +5% with them)
      if (off(faces[0], e) == off(faces[1], e)) repeat_at(faces[0], faces[1], e);
      continue;
    }
    by_off.clear();
    for (const std::uint32_t t : faces) by_off.emplace_back(off(t, e), t);
    std::sort(by_off.begin(), by_off.end());
    for (std::size_t i = 1; i < by_off.size(); ++i)
      if (by_off[i].first == by_off[i - 1].first) repeat_at(by_off[i - 1].second, by_off[i].second, e);
  }
}

}  // namespace delpsc::protect::detail
