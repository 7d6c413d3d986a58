#include "edges_by_curve.h"

namespace delpsc::refine {

EdgesByCurve group_edges_by_curve(const io::SurfaceMesh& output, std::uint32_t curve_count) {
  EdgesByCurve g;
  g.offsets.assign(curve_count + 1, 0);
  const auto curve_of = [&](std::size_t e) -> std::int64_t {
    if (output.edge_curve.empty()) return -1;
    const std::int32_t c = output.edge_curve[e];
    return c >= 0 && static_cast<std::uint32_t>(c) < curve_count ? c : -1;
  };
  for (std::size_t e = 0; e < output.edges.size(); ++e) {
    const std::int64_t c = curve_of(e);
    if (c >= 0) {
      ++g.offsets[static_cast<std::size_t>(c) + 1];
    } else if (g.unlabelled++ == 0) {
      g.first_unlabelled = output.vertices[output.edges[e][0]];
    }
  }
  for (std::uint32_t c = 0; c < curve_count; ++c) g.offsets[c + 1] += g.offsets[c];
  g.segments.resize(g.offsets[curve_count]);
  std::vector<std::size_t> next(g.offsets.begin(), g.offsets.end() - 1);
  for (std::size_t e = 0; e < output.edges.size(); ++e) {
    const std::int64_t c = curve_of(e);
    if (c < 0) continue;
    const auto [u, v] = output.edges[e];
    g.segments[next[static_cast<std::size_t>(c)]++] = {u, v, v};
  }
  return g;
}

}  // namespace delpsc::refine
