// What Mesher::output() promises about orientation (refine/mesher.h), checked on a mesh
// independently of refine/triangle_orientation.h: two triangles sharing an edge that no third
// triangle uses traverse it in opposite directions, and each closed component (every edge in
// exactly two triangles) encloses a positive volume, i.e. faces outward. Meant for outputs of
// orientable inputs (a non-orientable sheet cannot pass). Cost O(T log T).
#pragma once

#include <string>
#include <vector>

#include <delpsc/io/surface_mesh.h>

namespace delpsc::test {

/// Problems found, in words (at most `max_problems`); empty when the orientation is as promised.
std::vector<std::string> orientation_problems(const io::SurfaceMesh& mesh, std::size_t max_problems = 20);

}  // namespace delpsc::test
