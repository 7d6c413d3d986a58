// Quality figures of an output mesh, for reports (`delpsc mesh`) and tests.
#pragma once

#include <delpsc/io/surface_mesh.h>

namespace delpsc::refine {

/// The smallest interior angle of triangle abc, in radians (0 if it is degenerate). O(1).
double triangle_min_angle(const Vec3& a, const Vec3& b, const Vec3& c);

/// The smallest interior angle, in degrees, over the mesh's triangles (180 for a mesh without
/// triangles; 0 if one is degenerate). O(T).
double min_triangle_angle_degrees(const io::SurfaceMesh& mesh);

}  // namespace delpsc::refine
