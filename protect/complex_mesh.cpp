#include "complex_mesh.h"

namespace delpsc::protect {

io::SurfaceMesh to_surface_mesh(const Complex& complex) {
  io::SurfaceMesh mesh;
  mesh.vertices.assign(complex.vertices.begin(), complex.vertices.end());
  mesh.triangles.assign(complex.triangles.begin(), complex.triangles.end());
  mesh.triangle_patch.assign(complex.triangle_patch.begin(), complex.triangle_patch.end());
  for (std::uint32_t c = 0; c < complex.curve_count(); ++c) {
    const auto poly = complex.curve_polyline(c);
    for (std::size_t i = 0; i + 1 < poly.size(); ++i) {
      mesh.edges.push_back({poly[i], poly[i + 1]});
      mesh.edge_curve.push_back(static_cast<std::int32_t>(c));
    }
  }
  mesh.corners.assign(complex.corner_vertex.begin(), complex.corner_vertex.end());
  return mesh;
}

}  // namespace delpsc::protect
