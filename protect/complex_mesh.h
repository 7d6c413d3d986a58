// The complex as a labelled surface mesh, for writing (`delpsc features -o OUT.vtu|OUT.mesh`) and
// viewing: its triangles with their patch ids, its feature edges with their curve ids, its
// corners. The vertices are the complex's (the soup's, unused ones included), so indices match.
#pragma once

#include <delpsc/io/surface_mesh.h>

#include "complex.h"

namespace delpsc::protect {

/// O(V + T) time and memory. Edges follow the curves in order, each along its polyline.
io::SurfaceMesh to_surface_mesh(const Complex& complex);

}  // namespace delpsc::protect
