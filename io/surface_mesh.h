// A surface mesh with the structure of a piecewise smooth complex, the output of the mesher (and
// of `delpsc features`): triangles labelled by surface patch, edges labelled by feature curve, and
// the corner vertices. Writers (mesh_writer.h) turn it into files for viewers and other tools.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <delpsc/kernel/large_array.h>
#include <delpsc/kernel/point.h>

#include "triangle_soup.h"

namespace delpsc::io {

/// Invariants checked by the writers (io::Error otherwise): every index is < vertices.size();
/// triangle_patch is empty (no labels) or has one entry per triangle; the same for edge_curve
/// and edges. Ids are the complex's patch / curve numbers, any int32 value.
struct SurfaceMesh {
  kernel::LargeVector<Vec3> vertices;
  /// Vertex indices, counter-clockwise seen from outside.
  kernel::LargeVector<std::array<std::uint32_t, 3>> triangles;
  kernel::LargeVector<std::int32_t> triangle_patch;
  /// Feature-curve segments.
  kernel::LargeVector<std::array<std::uint32_t, 2>> edges;
  kernel::LargeVector<std::int32_t> edge_curve;
  /// Indices of the corner vertices (0-faces of the complex).
  kernel::LargeVector<std::uint32_t> corners;
};

/// The triangles of a soup as an unlabelled surface mesh (copies vertices and triangles).
inline SurfaceMesh surface_mesh_from(const TriangleSoup& soup) {
  SurfaceMesh mesh;
  mesh.vertices.assign(soup.vertices.begin(), soup.vertices.end());
  mesh.triangles.assign(soup.triangles.begin(), soup.triangles.end());
  return mesh;
}

}  // namespace delpsc::io
