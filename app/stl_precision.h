// A warning when an .stl output loses triangles to its single-precision coordinates.
#pragma once

#include <cstdio>
#include <string>

#include <delpsc/io/mesh_writer.h>
#include <delpsc/io/surface_mesh.h>

#include "command.h"

namespace delpsc::app {

/// Unless -q: warns on stderr when `mesh`, written to `path` as .stl, has triangles that rounding
/// to float collapses (io::triangles_collapsed_in_float), naming the count and the formats that
/// keep doubles. The cube moved 1e6 from the origin and meshed at 10% lost 14 triangles that way
/// without a word. O(triangles), and nothing for other formats.
inline void warn_if_stl_collapses(const std::string& path, const io::SurfaceMesh& mesh, const GlobalOptions& g) {
  if (g.quiet || io::mesh_format_from_path(path) != io::MeshFormat::stl) return;
  const std::size_t collapsed = io::triangles_collapsed_in_float(mesh);
  if (collapsed == 0) return;
  std::fprintf(stderr,
               "delpsc: warning: %s: STL stores coordinates as single-precision floats, and %zu of the %zu triangles "
               "have no area once rounded to them (the model lies far from the origin for its size, or its triangles "
               "are very small); .off, .obj, .ply and .mesh keep every digit\n",
               path.c_str(), collapsed, mesh.triangles.size());
}

}  // namespace delpsc::app
