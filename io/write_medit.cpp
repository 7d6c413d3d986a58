// Medit .mesh (INRIA, Frey 2001; the format of Gmsh, MMG, CGAL's output_to_medit): keyword
// sections, 1-based indices, an integer reference after every entity. The reference carries the
// complex's labels: patch id on triangles, curve id on edges, so a viewer can colour by face.
#include "mesh_formats.h"

namespace delpsc::io::detail {

void format_medit(const SurfaceMesh& mesh, std::string& out) {
  out += "MeshVersionFormatted 2\nDimension 3\n";  // version 2: double-precision coordinates
  out += "Vertices\n";
  append_number(out, std::int64_t(mesh.vertices.size()));
  out += '\n';
  for (const Vec3& p : mesh.vertices) {
    for (int k = 0; k < 3; ++k) {
      append_number(out, p[k]);
      out += ' ';
    }
    out += "0\n";
  }
  const auto index = [&](std::uint32_t v) { append_number(out, std::int64_t{v} + 1); };
  if (!mesh.triangles.empty()) {
    out += "Triangles\n";
    append_number(out, std::int64_t(mesh.triangles.size()));
    out += '\n';
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      for (const std::uint32_t v : mesh.triangles[t]) {
        index(v);
        out += ' ';
      }
      append_number(out, mesh.triangle_patch.empty() ? 0 : mesh.triangle_patch[t]);
      out += '\n';
    }
  }
  if (!mesh.edges.empty()) {
    out += "Edges\n";
    append_number(out, std::int64_t(mesh.edges.size()));
    out += '\n';
    for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
      for (const std::uint32_t v : mesh.edges[e]) {
        index(v);
        out += ' ';
      }
      append_number(out, mesh.edge_curve.empty() ? 0 : mesh.edge_curve[e]);
      out += '\n';
    }
  }
  if (!mesh.corners.empty()) {
    out += "Corners\n";
    append_number(out, std::int64_t(mesh.corners.size()));
    out += '\n';
    for (const std::uint32_t v : mesh.corners) {
      index(v);
      out += '\n';
    }
  }
  out += "End\n";
}

}  // namespace delpsc::io::detail
