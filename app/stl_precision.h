// An .stl output refused when its single-precision coordinates would collapse triangles.
#pragma once

#include <cstdio>
#include <string>

#include <delpsc/io/mesh_writer.h>
#include <delpsc/io/surface_mesh.h>

#include "command.h"

namespace delpsc::app {

/// Throws Failure (kBadInput) when `mesh`, to be written to `path` as .stl, has triangles that
/// rounding to float collapses (io::triangles_collapsed_in_float), naming the count and the
/// formats that keep doubles; call before writing. A warning was not enough: under -q nothing
/// was said, and fandisk moved to 1e9 came out as 2,342 triangles on one vertex with exit 0.
/// O(triangles), and nothing for other formats.
inline void refuse_stl_that_collapses(const std::string& path, const io::SurfaceMesh& mesh) {
  if (io::mesh_format_from_path(path) != io::MeshFormat::stl) return;
  const std::size_t collapsed = io::triangles_collapsed_in_float(mesh);
  if (collapsed == 0) return;
  char text[512];
  std::snprintf(text, sizeof text,
                "%s: STL stores coordinates as single-precision floats, and %zu of the %zu triangles would have no "
                "area once rounded to them (the model lies far from the origin for its size, or its triangles are "
                "very small); nothing written: use .off, .obj, .ply or .mesh, which keep every digit",
                path.c_str(), collapsed, mesh.triangles.size());
  throw Failure{kBadInput, text};
}

}  // namespace delpsc::app
