// Step 3 of build_complex: which edges are features (see complex.h).
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "complex_build.h"

namespace delpsc::protect::detail {

namespace {

// True if triangle t runs along its edge from u to v (rather than from v to u).
bool runs_from(const std::array<std::uint32_t, 3>& t, std::uint32_t u, std::uint32_t v) {
  for (int k = 0; k < 3; ++k)
    if (t[k] == u) return t[(k + 1) % 3] == v;
  return false;
}

}  // namespace

void classify_feature_edges(Complex& complex, const kernel::LargeVector<std::uint32_t>& canonical) {
  const double angle = complex.options.feature_angle_degrees;
  // Angle between normals > threshold  <=>  cosine < cos(threshold).
  const double cos_threshold = std::cos(angle * std::numbers::pi / 180);

  kernel::LargeVector<Vec3> normal(complex.triangles.size());
  for (std::size_t t = 0; t < complex.triangles.size(); ++t) {
    const auto& tri = complex.triangles[t];
    const Vec3 n = (complex.vertices[tri[1]] - complex.vertices[tri[0]])
                       .cross(complex.vertices[tri[2]] - complex.vertices[tri[0]]);
    const double len = n.norm();
    // A non-degenerate triangle so small that its normal underflows has no usable direction;
    // it then never makes a sharp edge.
    normal[t] = len > 0 && std::isfinite(len) ? Vec3(n / len) : Vec3::Zero();
  }

  complex.edge_feature.assign(complex.edges.size(), 0);
  for (std::uint32_t e = 0; e < complex.edges.size(); ++e) {
    const auto faces = complex.edge_triangle_ids(e);
    if (faces.size() == 1) {
      complex.edge_feature[e] = kBoundaryEdge;
    } else if (faces.size() >= 3) {
      complex.edge_feature[e] = kNonManifoldEdge;
    } else {
      const auto [u, v] = complex.edges[e];
      const auto &t1 = complex.triangles[faces[0]], &t2 = complex.triangles[faces[1]];
      // Two consistently oriented neighbours run along their common edge in opposite
      // directions; if the soup has them the same way, compare with one normal reversed.
      const double sign = runs_from(t1, u, v) != runs_from(t2, u, v) ? 1.0 : -1.0;
      const Vec3 &n1 = normal[faces[0]], &n2 = normal[faces[1]];
      if (n1 != Vec3::Zero() && n2 != Vec3::Zero() && sign * n1.dot(n2) < cos_threshold)
        complex.edge_feature[e] = kSharpEdge;
    }
  }

  const auto& polylines = complex.options.feature_polylines;
  for (std::size_t i = 0; i < polylines.size(); ++i) {
    const auto& chain = polylines[i];
    for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
      const std::uint32_t a = chain[k], b = chain[k + 1];
      if (a >= canonical.size() || b >= canonical.size())
        throw std::invalid_argument("build_complex: feature polyline " + std::to_string(i) + " refers to vertex " +
                                    std::to_string(std::max(a, b)) + " of " + std::to_string(canonical.size()));
      const std::uint32_t e = find_edge(complex, canonical[a], canonical[b]);
      if (e == kNoIndex)
        throw std::invalid_argument("build_complex: feature polyline " + std::to_string(i) + ": vertices " +
                                    std::to_string(a) + " and " + std::to_string(b) + " are not joined by a mesh edge");
      complex.edge_feature[e] |= kPolylineEdge;
    }
  }
}

}  // namespace delpsc::protect::detail
