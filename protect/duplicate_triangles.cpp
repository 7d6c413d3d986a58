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
  // Two repeats share all three edges; each is seen at one of them only, the first of its
  // triangle's edges in the table, among the triangles there with the same third vertex.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> third;  // (vertex off the edge, triangle)
  for (std::uint32_t e = 0; e < complex.edges.size(); ++e) {
    const auto faces = complex.edge_triangle_ids(e);
    if (faces.size() < 2) continue;
    third.clear();
    for (const std::uint32_t t : faces) {
      const auto& te = complex.triangle_edges[t];
      if (std::min({te[0], te[1], te[2]}) != e) continue;
      const auto& v = complex.triangles[t];
      third.emplace_back(v[0] ^ v[1] ^ v[2] ^ complex.edges[e][0] ^ complex.edges[e][1], t);
    }
    if (third.size() < 2) continue;
    std::sort(third.begin(), third.end());
    for (std::size_t i = 1; i < third.size(); ++i) {
      if (third[i].first != third[i - 1].first) continue;
      if (report.duplicate_triangles++ == 0)
        report.first_duplicate = {complex.triangle_source[third[i - 1].second], complex.triangle_source[third[i].second]};
    }
  }
}

}  // namespace delpsc::protect::detail
