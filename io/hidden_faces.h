// Back-face culling for the SVG preview (preview_svg.h): which triangles a viewer can never see
// because the closed surface they belong to hides them. Dropping them halves the picture of a
// closed model (a 100,000-triangle mesh) without changing a pixel.
#pragma once

#include <vector>

#include "surface_mesh.h"

namespace delpsc::io {

/// Per triangle of `mesh`, true when it is certainly hidden in an orthographic view from
/// direction `toward_viewer` (from the model towards the eye): it lies in a closed,
/// consistently oriented component - connected through shared edges, every edge of the
/// component in exactly two of its triangles, traversed in opposite directions - and faces
/// away from the viewer, the component's outside told by the sign of its enclosed volume (so
/// inward-oriented components work too). Triangles of open or non-manifold components, like a
/// fin or a sheet, are never hidden: both of their sides can be seen. Edge-on triangles are
/// kept. Indices must be valid. O(T) expected time.
std::vector<bool> hidden_back_faces(const SurfaceMesh& mesh, const Vec3& toward_viewer);

}  // namespace delpsc::io
