// What Mesher::output() promises about orientation (refine/mesher.h), checked on a mesh
// independently of refine/triangle_orientation.h: two triangles sharing an edge that no third
// triangle uses traverse it in opposite directions, and each closed component (every edge in
// exactly two triangles) encloses a positive volume, i.e. faces outward - unless it lies inside
// an odd number of other closed components (a ray's crossings), where it bounds a cavity and
// faces into it (a negative volume). Meant for outputs of
// orientable inputs (a non-orientable sheet cannot pass). Cost O(T log T).
#pragma once

#include <string>
#include <vector>

#include <delpsc/io/surface_mesh.h>
#include <delpsc/refine/domain.h>

namespace delpsc::test {

/// Problems found, in words (at most `max_problems`); empty when the orientation is as promised.
std::vector<std::string> orientation_problems(const io::SurfaceMesh& mesh, std::size_t max_problems = 20);

/// Patches of the output facing against the input: each triangle compares its normal with that
/// of the input triangle nearest its centroid (Domain::closest_point), when that lies on the
/// triangle's own patch; a patch whose triangles disagree more often than they agree is
/// reported. For inputs wound consistently and outward where closed (the generated and
/// libcgal-demo models). One closest-point query per triangle.
std::vector<std::string> patches_against_input(const io::SurfaceMesh& mesh, const refine::Domain& domain);

}  // namespace delpsc::test
