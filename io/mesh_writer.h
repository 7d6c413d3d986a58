// Writing surface meshes, the format chosen by the file extension (case-insensitive):
//   .off .obj          text, triangles only; coordinates in shortest round-trip form (exact)
//   .ply               binary little-endian PLY, double coordinates, triangles only (exact)
//   .stl               binary STL, triangles only; coordinates rounded to float (the format's
//                      precision), facet normals computed from the vertices
//   .mesh              Medit (MeshVersionFormatted 2, doubles): Vertices, Triangles with the
//                      patch id as reference, Edges with the curve id, Corners; 1-based indices
//   .vtu               ParaView XML UnstructuredGrid, ASCII: triangles, edges and corners as cells
//                      (VTK_TRIANGLE, VTK_LINE, VTK_VERTEX) with cell data "patch" (-1 off
//                      triangles), "curve" (-1 off edges) and "dimension" (2, 1, 0)
// Missing labels (empty triangle_patch / edge_curve) are written as 0 in Medit and -1 in VTU.
// Cost: O(size of the mesh); the file is assembled in memory and written at once.
#pragma once

#include <optional>
#include <string>

#include "surface_mesh.h"

namespace delpsc::io {

enum class MeshFormat { off, obj, ply, stl, medit, vtu };

/// The format named by the extension of `path`, or nullopt.
std::optional<MeshFormat> mesh_format_from_path(const std::string& path);

/// Writes `mesh` to `path` in the format of its extension. Throws io::Error on an unknown
/// extension, a mesh violating the SurfaceMesh invariants, or a failed write.
void write_mesh(const std::string& path, const SurfaceMesh& mesh);

/// The file contents write_mesh would produce (tests and in-memory users).
std::string format_mesh(const SurfaceMesh& mesh, MeshFormat format);

/// How many triangles of `mesh` have no area once their corners are rounded to float, as .stl
/// stores them: two corners rounded to one point, or the three on a line. Far from the origin
/// float's 24 bits run out (a mesh 1e6 away with triangles of 1e-2), and a caller can say so
/// instead of writing a file with holes in it. O(triangles).
std::size_t triangles_collapsed_in_float(const SurfaceMesh& mesh);

}  // namespace delpsc::io
